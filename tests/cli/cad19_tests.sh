#!/usr/bin/env bash
# The BSH paper's CAD example (Fig. 19(a), Sec. 7.2; issue 14 section 2) as a CSG expression over the halfspaces of
# the BSH authors' figure19_b/config.json (data/scenes3d/figure19_b_cad.csg; docs/csg3.md):
# - the expression gives exactly the cells of the authors' shape (hsx extract on their config with their 23 samples);
# - hsx csg: describable, BHC's tree verified on every cell, 17 leaves (each halfspace once), 5 internal nodes;
# - hsx convert: Table 1's CAD column, 23 components (the lower bound) and 116 boundary patches (the upper bound),
#   with the sample count docs/csg3.md reports (26), no halfspace complemented, and hsx extract on the written scene
#   returns the solid's cells.
# Skipped (77) without the data (HSX_BSH_DATA, default ../shared/data/bsh-examples). About 30 s.
# Usage: cad19_tests.sh HSX SOURCE_DIR
set -u
hsx="$(realpath "${1:?usage: cad19_tests.sh HSX SOURCE_DIR}")"; src="$(realpath "${2:?usage}")"
source "$src/tests/cli/common.sh"
bsh_examples figure19_b/config.json
config="$data/figure19_b/config.json"
EXPR="$src/data/scenes3d/figure19_b_cad.csg"
json() { python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if eval("(" + sys.argv[2].strip() + ")") else 1)' "$1" "$2"; }
check() { if json "$2" "$3"; then ok; else bad "$1: $3 false on $2: $(head -c 300 "$2")"; fi; }
same_cells() {  # same_cells WHAT A.json B.json: the same inside_cells
  if python3 -c 'import json, sys; a, b = (json.load(open(f))["inside_cells"] for f in sys.argv[1:3]); sys.exit(a != b)' \
       "$2" "$3"; then ok; else bad "$1: $2 and $3 have different inside_cells"; fi
}

expect 0 "" -- "$hsx" extract "$config" --method beam --beam-width 1 --json theirs.json --no-timing
check "their shape: 116 boundary patches" theirs.json 'len(d["inside_cells"]) == 113 and len(d["boundary"]) == 116'
if expect 0 "" -- "$hsx" csg "$config" --csg "$EXPR" --json tree.json; then
  has out "verified on every cell: yes" "csg summary"
  check "BHC tree of the CAD model" tree.json '
    d["describable"] is True and d["verified"] is True and d["stats"]["leaves"] == 17 and
    d["stats"]["duplicated_halfspaces"] == 0 and d["stats"]["internal_nodes"] == 5 and d["stats"]["depth"] == 5 and
    d["stats"]["partitions"] == 0'
  check "the tree" tree.json \
    'd["text"] == "\"5\" | \"12\" | \"13\" | \"14\" | \"15\" | \"16\" | \"17\" & \"1\" & \"2\" & \"3\" & \"4\" & (\"6\" | \"7\" | \"10\" & \"11\" & (\"8\" | \"9\"))"'
fi
if expect 0 "" -- "$hsx" convert "$config" --csg "$EXPR" --out cad.json --json conv.json; then
  has out "wrote cad.json: 26 samples (lower bound 23, upper bound 116" "convert summary"
  check "Table 1 (CAD): components 23, patches 116; our samples 26" conv.json '
    d["lower_bound"] == 23 and d["upper_bound"] == 116 and d["samples"] == 26 and d["round_trip"] is True and
    d["complemented"] == [] and d["cells"] == 215 and d["patches"] == 586'
  same_cells "the expression's solid is the authors' shape" conv.json theirs.json
  expect 0 "" -- "$hsx" extract cad.json --method beam --beam-width 1 --json back.json --no-timing
  same_cells "hsx extract on the written scene" back.json conv.json
fi
finish
