#!/usr/bin/env bash
# `hsx reference` on the BSH authors' nine examples (issue 13 section 2): their reference-result.grid against our
# exact arrangement of the same config.json. Checks, per example, that the patch counts are equal, that every
# block with patches is mapped onto one of our cells with no cell getting both labels, and the graph-cut defect
# figures (their charged cost equals the true area exactly when no cell pair shares several patches); on
# figure19_b the figures the issue quotes (586 patches, 221 blocks, 449.237 true area, 458.935 charged). Bad
# folders exit 2. Our K = 1 beam shape agrees with theirs on every cell of figure15_a and figure16_tori. Skipped (77) without the data (HSX_BSH_DATA, default ../shared/data/bsh-examples).
# Usage: bsh_examples_reference.sh HSX SOURCE_DIR
set -u
hsx="$(realpath "${1:?usage: bsh_examples_reference.sh HSX SOURCE_DIR}")"; src="$(realpath "${2:?usage}")"
source "$src/tests/cli/common.sh"
bsh_examples figure19_b/reference-result.grid

# field FILE JQ-EXPRESSION: a value of the JSON comparison
field() { jq -r "$2" "$1"; }
same() { if [ "$1" = "$2" ]; then ok; else bad "$3: $1, expected $2"; fi; }

for example in figure15_a figure15_b figure15_c figure15_d figure16_sphere_torus figure16_tori figure19_b figure19_c \
               figure19_d; do
  expect 0 "" -- "$hsx" reference "$data/$example" --json "$work/$example.json" || continue
  j="$work/$example.json"
  has "$work/out" "$example" "table of $example"
  same "$(field "$j" .ours.patches)" "$(field "$j" .theirs.patches)" "$example: our patches against theirs"
  same "$(field "$j" .mapping.conflicting_cells)" 0 "$example: cells with both labels"
  same "$(field "$j" .mapping.blocks_on_our_boundary)" 0 "$example: block points on our boundary"
  same "$(field "$j" .mapping.blocks_without_point)" "$(field "$j" .theirs.empty_blocks)" \
       "$example: blocks without a point (only the empty ones)"
  if [ "$(field "$j" .theirs.multi_patch_pairs_on_boundary)" = 0 ]; then
    same "$(field "$j" .theirs.graph_cut_cost.decimal)" "$(field "$j" .theirs.boundary_area.decimal)" \
         "$example: charged cost without multi-patch pairs"
  fi
done

j="$work/figure19_b.json"
if [ -f "$j" ]; then
  same "$(field "$j" .theirs.patches)" 586 "figure19_b: their patches"
  same "$(field "$j" .theirs.blocks)" 221 "figure19_b: their blocks"
  same "$(field "$j" .theirs.boundary_patches)" 116 "figure19_b: their boundary patches"
  same "$(field "$j" .theirs.multi_patch_pairs)" 24 "figure19_b: block pairs sharing several patches"
  same "$(field "$j" '.theirs.boundary_area.decimal | .[0:8]')" 449.2367 "figure19_b: their true boundary area"
  same "$(field "$j" '.theirs.graph_cut_cost.decimal | .[0:8]')" 458.9347 "figure19_b: their charged cost"
fi

# Our K = 1 beam shape against their final labelling, on two examples quick to extract: the same cells.
for example in figure15_a figure16_tori; do
  expect 0 "" -- "$hsx" extract "$data/$example/config.json" --method beam --beam-width 1 --json "$work/shape.json" ||
    continue
  expect 0 "" -- "$hsx" reference "$data/$example" --shape "$work/shape.json" --json "$work/agree.json" || continue
  same "$(field "$work/agree.json" .agreement.differing_cells)" 0 "$example: cells where our shape differs from theirs"
  same "$(field "$work/agree.json" .agreement.agreeing_cells)" "$(field "$work/agree.json" .ours.cells)" \
       "$example: cells where our shape agrees with theirs"
done
# A result of another scene is refused.
expect 2 "" -- "$hsx" reference "$data/figure15_b" --shape "$work/shape.json"

expect 2 "not a folder" -- "$hsx" reference "$work/missing"
mkdir -p "$work/broken" && cp "$data/figure15_a/config.json" "$data/figure15_a/"*.xyz "$data/figure15_a/grid_64.json" \
  "$work/broken/" && printf 'vert 1 3\n0 0\n' > "$work/broken/reference-result.grid"
expect 2 "reference-result.grid:2: section vert: expected 3 coordinates" -- "$hsx" reference "$work/broken" \
  --json "$work/broken.json"
[ ! -e "$work/broken.json" ] && ok || bad "a failed run wrote --json"
finish
