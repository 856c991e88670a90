#!/usr/bin/env bash
# End-to-end tests of `hsx nhtree` on bundled inputs (data/meshes, data/scenes): usage: nhtree_tests.sh HSX ROOT
# - meshes: the cube is one max node, the L-prism puts its concave edge's two sides under a min node, and the
#   L-prism with one corner edge left unmarked needs a decomposition; .conf and JSON are written and agree;
# - 2D: trees, exact evaluation and an SVG for CSG solids on data/scenes/lens.json, and the union of two disks
#   as a min root;
# - bad input exits 2 naming the problem and leaves no output file behind.
set -u
HSX="${1:?usage: nhtree_tests.sh HSX ROOT}"
ROOT="${2:?usage: nhtree_tests.sh HSX ROOT}"
TMP="$(mktemp -d "${TMPDIR:-/tmp}/hsx-nhtree-tests.XXXXXX")"
trap 'rm -rf "$TMP"' EXIT
M="$ROOT/data/meshes"
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*" >&2; }
expect_line() {  # FILE TEXT DESCRIPTION
  if grep -qF -- "$2" "$1"; then pass; else fail "$3: '$2' not in output"; cat "$1" >&2; fi
}
run_ok() {  # OUT ARGS...
  local out="$1"; shift
  if "$HSX" nhtree "$@" >"$out" 2>"$out.err"; then pass; else fail "nhtree $* exited $?: $(cat "$out.err")"; fi
}
run_bad() {  # EXPECTED_CODE MESSAGE_PART OUTPUT_FILE ARGS...
  local code="$1" part="$2" file="$3"; shift 3
  "$HSX" nhtree "$@" >"$TMP/bad.out" 2>"$TMP/bad.err"
  local got=$?
  if [ "$got" -eq "$code" ]; then pass; else fail "nhtree $* exited $got, expected $code"; fi
  if grep -qF -- "$part" "$TMP/bad.err"; then pass; else fail "nhtree $*: stderr lacks '$part': $(cat "$TMP/bad.err")"; fi
  if [ -n "$file" ] && [ -e "$file" ]; then fail "nhtree $* left $file behind"; else pass; fi
}

# ---- meshes ----
run_ok "$TMP/cube.txt" "$M/cube.obj" --fea "$M/cube.fea" --conf "$TMP/cube.conf" --json "$TMP/cube.json"
expect_line "$TMP/cube.txt" "tree: max(0, 1, 2, 3, 4, 5)" "cube"
expect_line "$TMP/cube.txt" "12 convex" "cube curves"
if printf 'csg{\n    list = [0,1,2,3,4,5,],\n    flag_convex = 1,\n}' | cmp -s - "$TMP/cube.conf"; then pass; else fail "cube .conf: $(cat "$TMP/cube.conf")"; fi
if python3 -c "
import json,sys; d=json.load(open('$TMP/cube.json'))
assert d['format']=='hsx-nhtree/1' and d['tree']['op']=='max' and sorted(d['tree']['leaves'])==[0,1,2,3,4,5]
assert len(d['patch_graph'])==12 and all(e['type']=='convex' for e in d['patch_graph'])"; then pass; else fail "cube JSON"; fi

run_ok "$TMP/lprism.txt" "$M/lprism.obj" --fea "$M/lprism.fea"
expect_line "$TMP/lprism.txt" "1 concave" "L-prism curves"
expect_line "$TMP/lprism.txt" "min(" "L-prism min node"
expect_line "$TMP/lprism.txt" "termination): ok" "L-prism structure"

run_ok "$TMP/open.txt" "$M/lprism.obj" --fea "$M/lprism_open_corner.fea" --json "$TMP/open.json" --group
expect_line "$TMP/open.txt" "decomposed patch 0 into" "open corner decomposition"
expect_line "$TMP/open.txt" "termination): ok" "open corner structure"
expect_line "$TMP/open.txt" "groups (at most 6" "grouping"
if python3 -c "
import json; d=json.load(open('$TMP/open.json'))
dec=d['decompositions'][0]; assert dec['both_kinds_after']==dec['both_kinds_before']-1
assert any(s['outcome']=='case 1: decompose' for s in d['steps']) and 'groups' in d"; then pass; else fail "open corner JSON"; fi

# regression: the bundled meshes' trees, byte for byte (data/meshes/*.tree.conf, also the .conf fuzz seeds)
for pair in cube:cube lprism:lprism lprism:lprism_open_corner hollow_cube:hollow_cube lprism_split:lprism_split; do
  obj="${pair%%:*}"; fea="${pair##*:}"
  "$HSX" nhtree "$M/$obj.obj" --fea "$M/$fea.fea" --conf "$TMP/$fea.conf" >/dev/null 2>&1
  if cmp -s "$TMP/$fea.conf" "$M/$fea.tree.conf"; then pass; else fail "$fea: tree differs from $M/$fea.tree.conf"; fi
  # and it compares equal to itself through --reference
  "$HSX" nhtree "$M/$obj.obj" --fea "$M/$fea.fea" --reference "$M/$fea.tree.conf" >"$TMP/$fea.ref.txt" 2>&1
  expect_line "$TMP/$fea.ref.txt" "same tree" "$fea --reference"
done

# face-splitting: one triangle lies on a convex and a concave edge; the decomposed mesh is a valid closed mesh
# whose own tree needs no further decomposition
run_ok "$TMP/split.txt" "$M/lprism_split.obj" --fea "$M/lprism_split.fea" --decomposed "$TMP/split.dec"
expect_line "$TMP/split.txt" "(1 piece face-split, 2 links cut)" "face-splitting"
expect_line "$TMP/split.txt" "22 triangles (1 input triangle split), 19 feature edges" "decomposed mesh"
if [ "$(wc -l <"$TMP/split.dec.face-patch.txt")" -eq 22 ]; then pass; else fail "face-patch lines"; fi
run_ok "$TMP/split2.txt" "$TMP/split.dec.obj" --fea "$TMP/split.dec.fea"
expect_line "$TMP/split2.txt" "termination): ok" "decomposed mesh re-read"
if grep -q "decomposed patch" "$TMP/split2.txt"; then fail "the decomposed mesh needed another decomposition"; else pass; fi
run_bad 2 "--decomposed" "$TMP/x.json" "$ROOT/data/scenes/lens.json" --csg A --decomposed "$TMP/x" --json "$TMP/x.json"

# a cavity: Section 5.2 unites the two shells (min root); --nest-holes intersects the cavity's tree with the outer's
"$HSX" nhtree "$M/hollow_cube.obj" --fea "$M/hollow_cube.fea" --nest-holes --conf "$TMP/hollow.nested.conf" >/dev/null 2>&1
if cmp -s "$TMP/hollow.nested.conf" "$M/hollow_cube.nested.tree.conf"; then pass; else fail "hollow cube --nest-holes tree"; fi
expect_line "$M/hollow_cube.tree.conf" "flag_convex = 0" "hollow cube: the paper's min root"
expect_line "$M/hollow_cube.nested.tree.conf" "flag_convex = 1" "hollow cube nested: a max root"
P2="$ROOT/data/counterexamples/nhrep/annulus"
run_ok "$TMP/annulus.txt" "$P2.json" --csg "$P2.csg"
expect_line "$TMP/annulus.txt" "the solid has holes" "annulus diagnosis"
run_ok "$TMP/annulus.nested.txt" "$P2.json" --csg "$P2.csg" --nest-holes
expect_line "$TMP/annulus.nested.txt" "correct on every cell; tree correct" "annulus nested"

# sharpness angle: the cube's 90-degree edges are smooth below a 91-degree threshold, sharp at exactly 90
run_ok "$TMP/cube90.txt" "$M/cube.obj" --fea "$M/cube.fea" --sharp-angle 90
expect_line "$TMP/cube90.txt" "12 convex" "cube at 90 degrees"
run_ok "$TMP/cube91.txt" "$M/cube.obj" --fea "$M/cube.fea" --sharp-angle 91
expect_line "$TMP/cube91.txt" "12 smooth" "cube at 91 degrees"

# the benchmark of NH-Rep's stages runs and reports every mesh with its decomposition count
if "$HSX" bench --meshes "$M/cube.obj" "$M/lprism.obj" >"$TMP/bench.txt" 2>&1; then pass; else fail "bench --meshes exited $?"; fi
expect_line "$TMP/bench.txt" "cube.obj" "bench cube"
expect_line "$TMP/bench.txt" "lprism.obj" "bench lprism"

# ---- 2D ----
S="$ROOT/data/scenes/lens.json"
run_ok "$TMP/lens.txt" "$S" --csg "(A | B) & ~C" --svg "$TMP/lens.svg" --json "$TMP/lens.json"
expect_line "$TMP/lens.txt" "tree: max(0, min(1, 2))" "lens tree"
expect_line "$TMP/lens.txt" "correct on every cell; tree correct" "lens evaluation"
if grep -q "<svg" "$TMP/lens.svg" && [ "$(grep -o 'class="piece"' "$TMP/lens.svg" | wc -l)" -ge 3 ]; then pass; else fail "lens SVG"; fi
P="$ROOT/data/counterexamples/nhrep/pentagram"
run_ok "$TMP/star.txt" "$P.json" --csg "$P.csg" --json "$TMP/star.json" --svg "$TMP/star.svg"
expect_line "$TMP/star.txt" "decomposed patch 0 into 10 11 (1 piece face-split, 1 link cut)" "pentagram decomposition"
expect_line "$TMP/star.txt" "describable but the tree fails" "pentagram evaluation"
if python3 -c "
import json; d=json.load(open('$TMP/star.json'))
halves=[p for ps in d['patch_pieces'].values() for p in ps if 'split_point' in p]
assert len(halves)==2 and halves[0]['split_point']==halves[1]['split_point'], halves
assert d['evaluation']['verdict']=='describable-fails'"; then pass; else fail "pentagram JSON split point"; fi
run_ok "$TMP/union.txt" "$S" --csg "A | B"
expect_line "$TMP/union.txt" "tree: min(0, 1)" "union of two disks"

# ---- bad input ----
run_bad 2 "--fea" "$TMP/x.conf" "$M/cube.obj" --conf "$TMP/x.conf"
run_bad 2 "sharp-angle" "$TMP/x.conf" "$M/cube.obj" --fea "$M/cube.fea" --sharp-angle abc --conf "$TMP/x.conf"
run_bad 2 "180" "$TMP/x.conf" "$M/cube.obj" --fea "$M/cube.fea" --sharp-angle 180 --conf "$TMP/x.conf"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$TMP/open.obj"
printf '0\n' >"$TMP/empty.fea"
run_bad 2 "open.obj" "$TMP/x.conf" "$TMP/open.obj" --fea "$TMP/empty.fea" --conf "$TMP/x.conf"
printf '1\n0 99\n' >"$TMP/bad.fea"
run_bad 2 "bad.fea:2" "$TMP/x.json" "$M/cube.obj" --fea "$TMP/bad.fea" --json "$TMP/x.json"
run_bad 2 "empty" "$TMP/x.json" "$S" --csg "A & ~A" --json "$TMP/x.json"
run_bad 2 "" "$TMP/x.json" "$S" --json "$TMP/x.json"
run_bad 2 "bounded" "$TMP/x.json" "$S" --csg "~A" --json "$TMP/x.json"
run_bad 2 "--fea" "$TMP/x.json" "$S" --csg "A" --fea "$M/cube.fea" --json "$TMP/x.json"
printf 'csg{ list = [0,1,[2,], flag_convex = 1, }' >"$TMP/bad.conf"
run_bad 2 "bad.conf:1" "" "$M/cube.obj" --fea "$M/cube.fea" --reference "$TMP/bad.conf"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
