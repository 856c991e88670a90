#!/usr/bin/env bash
# End-to-end tests of the Halfspace CSG commands: usage: csg_cli_tests.sh PATH/TO/hsx SOURCE_DIR
# - hsx describe SCENE --csg/--shape --json: describable, terms, mixed_terms (signs, cells, witness points);
# - hsx csg SCENE --csg/--shape --json: tree, text, verified, stats, area {decimal, exact}; --separators on BSH
#   Fig. 2's non-describable shapes 5 and 6 (data/figures/fig02-{5,6}.json) makes them describable, verified;
# - exit codes of describe and csg: 0 describable / a verified tree, 3 not describable (no tree; --openscad not
#   written, with a message), 2 bad input only; separators are tried before anything is written; the lens's
#   best-first shape is separated by a supporting line of a polygon edge; a hole inside a ring of the same sign
#   vector is not separable by one line ("none of the N candidates tried separated");
# - hsx convert SCENE --csg EXPR --out S, then hsx extract S: the same area as hsx csg gives for the solid;
#   hsx convert --csgnet PROGRAM --out S, then hsx extract S: the area of the same solid written as CSG over S;
#   orientation rule: a halfspace used reversed is complemented; used both ways: a failure (exit 3);
# - hsx samples SCENE --target/--csg --json: reproduced, counts within their bounds; in 3D too, --out a 3D scene
#   that hsx extract gives the target back from; hsx check fails Sec. 3.1 on the 3D counterexamples (exit 3);
# - bad inputs exit 2 with a message naming the option (and write no output file);
# - hsx corpus csgnet FILE --limit 5 when SOURCE_DIR/../shared/data/csgnet/best_st_expressions.txt exists.
# Prints "N passed, M failed" and exits non-zero when anything failed.
set -u

HSX="${1:?usage: csg_cli_tests.sh PATH/TO/hsx SOURCE_DIR}"
SRC="${2:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}"
if [[ ! -x "$HSX" ]]; then
  echo "hsx not found at $HSX: skipped"
  exit 77
fi
FIG="$SRC/data/figures"
SCENES="$SRC/data/scenes"
TMP="$(mktemp -d "${TMPDIR:-/tmp}/hsx-csg-cli-tests.XXXXXX")"
trap 'rm -rf "$TMP"' EXIT

passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() {
  failed=$((failed + 1))
  echo "FAIL: $*" >&2
}
# check NAME COMMAND...: the command's exit status decides.
check() {
  local name="$1"
  shift
  if "$@"; then pass; else fail "$name"; fi
}
# run EXPECTED_STATUS NAME COMMAND...: runs the command (stdout to $TMP/out, stderr to $TMP/err).
run() {
  local expected="$1" name="$2"
  shift 2
  "$@" >"$TMP/out" 2>"$TMP/err"
  local status=$?
  if [[ "$status" == "$expected" ]]; then
    pass
    return 0
  fi
  fail "$name: exit $status, expected $expected; stderr: $(head -c 400 "$TMP/err")"
  return 1
}
# json FILE PYTHON-EXPRESSION: evaluates the expression with `d` bound to the document; exit 0 iff truthy.
json() {
  python3 - "$1" "$2" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
try:
    ok = eval("(" + sys.argv[2].strip() + ")")
except Exception as e:
    print("json check raised %r" % e, file=sys.stderr)
    sys.exit(1)
if not ok:
    print("json check failed: %s" % sys.argv[2], file=sys.stderr)
sys.exit(0 if ok else 1)
EOF
}
# field FILE PYTHON-EXPRESSION: prints the expression's value.
field() {
  python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2"
}
# err_names WORD...: stderr of the last run mentions every word.
err_names() {
  local w
  for w in "$@"; do
    if ! grep -qF -- "$w" "$TMP/err"; then
      fail "stderr does not name '$w': $(head -c 400 "$TMP/err")"
      return 1
    fi
  done
  pass
}

# ---- the best-first results of Fig. 2's scenes (shapes 5 and 6 have no CSG expression over A and B) ----
for k in 1 2 3 4 5 6; do
  run 0 "extract fig02-$k" "$HSX" extract "$FIG/fig02-$k.json" --method best-first --json "$TMP/r$k.json"
done

# ---- describe ----
if run 0 "describe --csg" "$HSX" describe "$FIG/fig02-1.json" --csg "A & ~B" --json "$TMP/d1.json"; then
  check "describe: describable, no mixed terms" \
    json "$TMP/d1.json" 'd["format"] == "hsx-describe/1" and d["describable"] is True and d["mixed_terms"] == [] and d["terms"] == 4'
fi
for k in 5 6; do
  if run 3 "describe fig02-$k" "$HSX" describe "$FIG/fig02-$k.json" --shape "$TMP/r$k.json" --json "$TMP/d$k.json"; then
    # One mixed term: A in, B out (the arms L and R), L inside, R outside; witness points on either side of x = 0.
    check "describe fig02-$k: one mixed term A & ~B with witnesses" json "$TMP/d$k.json" '
      d["describable"] is False and len(d["mixed_terms"]) == 1 and
      d["mixed_terms"][0]["signs"] == {"A": "in", "B": "out"} and
      len(d["mixed_terms"][0]["inside_cells"]) == 1 and len(d["mixed_terms"][0]["outside_cells"]) == 1 and
      d["mixed_terms"][0]["witness"]["inside"]["cell"] == d["mixed_terms"][0]["inside_cells"][0] and
      float(eval(d["mixed_terms"][0]["witness"]["inside"]["point"][0].replace("/", "/1./"))) < 0 and
      float(eval(d["mixed_terms"][0]["witness"]["outside"]["point"][0].replace("/", "/1./"))) > 0'
  fi
done
for k in 1 2 3 4; do
  run 0 "describe fig02-$k" "$HSX" describe "$FIG/fig02-$k.json" --shape "$TMP/r$k.json" --json "$TMP/d$k.json" &&
    check "describe fig02-$k: describable" json "$TMP/d$k.json" 'd["describable"] is True'
done

# ---- csg ----
if run 0 "csg --csg" "$HSX" csg "$FIG/fig02-1.json" --csg "A | B" --json "$TMP/c1.json"; then
  check "csg: tree, verified, stats, area" json "$TMP/c1.json" '
    d["format"] == "hsx-csg/1" and d["describable"] is True and d["verified"] is True and
    d["tree"] == {"op": "union", "args": [{"halfspace": "A"}, {"halfspace": "B"}]} and d["text"] == "A | B" and
    d["stats"]["leaves"] == 2 and d["stats"]["depth"] == 1 and d["stats"]["partitions"] == 0 and
    d["stats"]["duplicated_halfspaces"] == 0 and d["area"] == {"decimal": "24", "exact": "24"}'
fi
# A case that needs a partition: the symmetric difference of the ovals (the four arms).
if run 0 "csg xor" "$HSX" csg "$FIG/fig02-1.json" --csg "(A - B) | (B - A)" --json "$TMP/cx.json"; then
  check "csg xor: one partition, both halfspaces duplicated, area 20" json "$TMP/cx.json" '
    d["verified"] is True and d["stats"]["partitions"] == 1 and d["stats"]["duplicated_halfspaces"] == 2 and
    d["stats"]["leaves"] == 4 and d["area"]["exact"] == "20"'
fi
# The four describable shapes of Fig. 2 from their best-first results: trees verified, areas as docs/figures.md.
areas=(x 24 4 14 14 9 19)
for k in 1 2 3 4; do
  run 0 "csg fig02-$k" "$HSX" csg "$FIG/fig02-$k.json" --shape "$TMP/r$k.json" --json "$TMP/c$k.json" &&
    check "csg fig02-$k: verified, area ${areas[$k]}" \
      json "$TMP/c$k.json" "d['verified'] is True and d['area']['exact'] == '${areas[$k]}'"
done
# Shapes 5 and 6: not describable (exit 3, mixed terms, no tree); with --separators: describable and verified.
for k in 5 6; do
  if run 3 "csg fig02-$k" "$HSX" csg "$FIG/fig02-$k.json" --shape "$TMP/r$k.json" --json "$TMP/c$k.json"; then
    check "csg fig02-$k: not describable, mixed term, no tree" \
      json "$TMP/c$k.json" "d['describable'] is False and 'tree' not in d and len(d['mixed_terms']) == 1"
  fi
  if run 0 "csg fig02-$k --separators" "$HSX" csg "$FIG/fig02-$k.json" --shape "$TMP/r$k.json" --separators \
    --json "$TMP/cs$k.json"; then
    check "csg fig02-$k --separators: describable, verified, separators listed, area ${areas[$k]}" \
      json "$TMP/cs$k.json" "d['describable'] is True and d['verified'] is True and len(d['separators']) >= 1 and
        all(s['kind'] == 'halfplane' for s in d['separators']) and d['area']['exact'] == '${areas[$k]}' and
        any(leaf == s['name'] for s in d['separators'] for leaf in d['text'].replace('(', ' ').replace(')', ' ').split())"
  fi
done

# ---- exit codes of describe and csg, --openscad, and the separators' candidates ----
# The lens's best-first shape is not describable by A, B, C, T (one mixed term); the supporting lines of T's edges
# separate it (y = -1, T's top edge, does; so does the line through (1, -3) and (4, -1)). Before the fix: "added 0
# ... separators did not help" and exit 0; with --openscad, exit 2 without trying separators.
run 0 "extract lens best-first" "$HSX" extract "$SCENES/lens.json" --method best-first --json "$TMP/lens.json"
rm -f "$TMP/lens.scad"
if run 3 "csg lens shape: not describable, exit 3" "$HSX" csg "$SCENES/lens.json" --shape "$TMP/lens.json" \
  --json "$TMP/lensc.json"; then
  check "csg lens shape: no tree, one mixed term" json "$TMP/lensc.json" \
    "d['describable'] is False and 'tree' not in d and len(d['mixed_terms']) == 1 and 'separators' not in d"
  check "csg lens shape: stdout suggests --separators" grep -qF "(try --separators)" "$TMP/out"
fi
run 3 "describe lens shape: exit 3" "$HSX" describe "$SCENES/lens.json" --shape "$TMP/lens.json"
run 0 "describe lens A | B: exit 0" "$HSX" describe "$SCENES/lens.json" --csg "A | B"
if run 3 "csg lens shape --openscad: exit 3 (not 2)" "$HSX" csg "$SCENES/lens.json" --shape "$TMP/lens.json" \
  --openscad "$TMP/lens.scad"; then
  err_names "--openscad" "not written"
  if [[ -e "$TMP/lens.scad" ]]; then fail "--openscad written without a tree"; else pass; fi
fi
separator_on_edge_of_T() {  # separator_on_edge_of_T CSG_JSON SCENE_JSON
  python3 - "$1" "$2" <<'EOF'
import json, sys
from fractions import Fraction as F
d = json.load(open(sys.argv[1]))
scene = json.load(open(sys.argv[2]))
T = [[F(str(c)) for c in v] for h in scene["halfspaces"] if h["name"] == "T" for v in h["vertices"]]
seps = d.get("separators", [])
def on(s, p):
    n = [F(str(c)) for c in s["normal"]]
    return n[0] * p[0] + n[1] * p[1] == F(str(s["offset"]))
edge_lines = [s for s in seps if any(on(s, T[i]) and on(s, T[(i + 1) % 3]) for i in range(3))]
ok = (d["describable"] and d["verified"] and len(seps) == 1 and len(edge_lines) == 1 and
      seps[0]["name"] in d["text"].replace("(", " ").replace(")", " ").split())
if not ok: print("separators: %r, text %r" % (seps, d.get("text")), file=sys.stderr)
sys.exit(0 if ok else 1)
EOF
}
if run 0 "csg lens shape --separators: exit 0" "$HSX" csg "$SCENES/lens.json" --shape "$TMP/lens.json" --separators \
  --json "$TMP/lenss.json"; then
  check "csg lens --separators: one separator, on a supporting line of one of T's edges; verified tree using it" \
    separator_on_edge_of_T "$TMP/lenss.json" "$SCENES/lens.json"
  check "csg lens --separators: says it added one, not that separators did not help" \
    bash -c "grep -qF 'added 1 separating' '$TMP/out' && ! grep -qF 'did not help' '$TMP/out'"
fi
if run 0 "csg lens shape --separators --openscad: exit 0, written" "$HSX" csg "$SCENES/lens.json" \
  --shape "$TMP/lens.json" --separators --openscad "$TMP/lens.scad"; then
  check "--openscad written after separators" test -s "$TMP/lens.scad"
fi
# A hole (the cell in neither P nor D) inside a ring of the outer region with the same sign vector: every line that
# cuts the hole cuts the outer region too, so no single separator reduces the mixed cells.
cat >"$TMP/cring.json" <<'EOF'
{"format": "hsx-scene/1", "dimension": 2, "domain": {"min": [-5, -5], "max": [5, 5]},
 "halfspaces": [{"name": "P", "kind": "polygon", "vertices": [[3, 0.5], [3, 3], [-3, 3], [-3, -3], [3, -3], [3, -0.5],
                  [2, -0.5], [2, -2], [-2, -2], [-2, 2], [2, 2], [2, 0.5]]},
                {"name": "D", "kind": "disk", "center": [2.5, 0], "radius": 1}]}
EOF
if run 0 "arrange the C ring" "$HSX" arrange "$TMP/cring.json" --json "$TMP/cringc.json" &&
   run 0 "extract the C ring (for its complex_id)" "$HSX" extract "$TMP/cring.json" -q --json "$TMP/cringr.json"; then
  python3 - "$TMP/cringc.json" "$TMP/hole.json" "$TMP/cringr.json" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
hole = [c["id"] for c in d["cells"] if c["inside"] == [] and not c["outer"]]
json.dump({"format": "hsx-result/1", "complex_id": json.load(open(sys.argv[3]))["complex_id"], "inside_cells": hole},
          open(sys.argv[2], "w"))
EOF
  rm -f "$TMP/hole.scad"
  if run 3 "csg hole --separators --openscad: exit 3" "$HSX" csg "$TMP/cring.json" --shape "$TMP/hole.json" \
    --separators --openscad "$TMP/hole.scad" --json "$TMP/holec.json"; then
    check "csg hole --separators: 'none of the N candidates tried separated' with N > 0" \
      grep -qE "none of the [1-9][0-9]* candidates tried separated" "$TMP/out"
    check "csg hole --separators: JSON says why" json "$TMP/holec.json" \
      "d['describable'] is False and d['separators'] == [] and d['separator_stop'] == 'no-candidate-separates' and
       d['separator_candidates_tried'] > 0 and len(d['mixed_terms']) == 1"
    err_names "--openscad" "not written"
    if [[ -e "$TMP/hole.scad" ]]; then fail "--openscad written without a tree"; else pass; fi
  fi
  run 3 "csg hole --separators --max-separators 0: exit 3" "$HSX" csg "$TMP/cring.json" --shape "$TMP/hole.json" \
    --separators --max-separators 0 &&
    check "--max-separators 0: says where it stopped" grep -qF "stopped at --max-separators 0" "$TMP/out"
  run 3 "describe hole: exit 3" "$HSX" describe "$TMP/cring.json" --shape "$TMP/hole.json"
fi
# Bad input (exit 2): options that need a scene given a complex, a negative --max-separators.
if run 0 "arrange fig02-5 as a complex" "$HSX" arrange "$FIG/fig02-5.json" --json "$TMP/c5complex.json"; then
  run 3 "csg on a complex: not describable, exit 3" "$HSX" csg "$TMP/c5complex.json" --shape "$TMP/r5.json"
  run 2 "csg on a complex --separators: exit 2" "$HSX" csg "$TMP/c5complex.json" --shape "$TMP/r5.json" --separators &&
    err_names "--separators"
  run 2 "csg on a complex --openscad: exit 2" "$HSX" csg "$TMP/c5complex.json" --shape "$TMP/r5.json" \
    --openscad "$TMP/bad.scad" && err_names "--openscad"
fi
run 2 "csg --max-separators -1: exit 2" "$HSX" csg "$FIG/fig02-5.json" --shape "$TMP/r5.json" --separators \
  --max-separators -1 && err_names "--max-separators"
check "csg --help documents the exit codes" bash -c "'$HSX' csg --help | grep -qF '3 the solid is not describable'"
check "describe --help documents the exit codes" bash -c "'$HSX' describe --help | grep -qF '3 not describable'"

# ---- convert (SCENE --csg) then extract: same area ----
for expr in "A - B" "(A - B) | (B & ~C)" "A | B"; do
  name="convert lens.json --csg '$expr'"
  run 0 "$name: csg" "$HSX" csg "$SCENES/lens.json" --csg "$expr" --json "$TMP/lc.json" || continue
  run 0 "$name" "$HSX" convert "$SCENES/lens.json" --csg "$expr" --out "$TMP/lo.json" --json "$TMP/lj.json" || continue
  check "$name: summary" json "$TMP/lj.json" '
    d["round_trip"] is True and d["lower_bound"] <= d["samples"] <= d["upper_bound"] and d["rounds"] >= 1'
  run 0 "$name: extract" "$HSX" extract "$TMP/lo.json" --json "$TMP/lr.json" || continue
  a="$(field "$TMP/lc.json" 'd["area"]')"
  b="$(field "$TMP/lr.json" 'd["area"]')"
  if [[ "$a" == "$b" ]]; then pass; else fail "$name: extract area $b, csg area $a"; fi
done
# The same with best-first as the conversion's search.
run 0 "convert --search best-first" "$HSX" convert "$FIG/fig02-1.json" --csg "(A - B) | (B - A)" --search best-first \
  --out "$TMP/xo.json" &&
  run 0 "extract converted xor" "$HSX" extract "$TMP/xo.json" --method best-first --json "$TMP/xr.json" &&
  check "converted xor: area 20" json "$TMP/xr.json" 'd["area"]["exact"] == "20"'

# ---- convert --csgnet, then extract: the area of the same solid written as CSG over the written scene ----
# c(32,32,16)s(32,40,12)- is the disk minus the square; convert complements the square's sides that the solid runs
# along reversed (its description lists them). Over the written scene the solid is c0 & (t1 | t2 | t3 | t4) with
# t = s1.side when that side was complemented, ~s1.side otherwise.
if run 0 "convert --csgnet" "$HSX" convert --csgnet "c(32,32,16)s(32,40,12)-" --out "$TMP/n.json"; then
  expr="$(python3 - "$TMP/n.json" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
hs = {h["name"]: h for h in d["halfspaces"]}
sides = [n for n in hs if n.startswith("s1.")]
assert "c0" in hs and not hs["c0"].get("complement", False) and len(sides) == 4, hs
print("c0 & (" + " | ".join(n if hs[n].get("complement", False) else "~" + n for n in sides) + ")")
EOF
)"
  if [[ -n "$expr" ]]; then pass; else fail "convert --csgnet: unexpected halfspaces in the written scene"; fi
  check "convert --csgnet: description names the complemented sides" \
    json "$TMP/n.json" '"complemented" in d["description"]'
  if run 0 "extract the csgnet conversion" "$HSX" extract "$TMP/n.json" --json "$TMP/nr.json" &&
    run 0 "csg over the written scene: $expr" "$HSX" csg "$TMP/n.json" --csg "$expr" --json "$TMP/nc.json"; then
    a="$(field "$TMP/nc.json" 'd["area"]')"
    b="$(field "$TMP/nr.json" 'd["area"]')"
    if [[ "$a" == "$b" ]]; then pass; else fail "csgnet conversion: extract area $b, CSG area $a"; fi
    check "csgnet conversion: area between disk - square bounds" \
      json "$TMP/nr.json" '0 < float(d["area"]["decimal"]) < 3.14159266 * 16 * 16'
  fi
fi

# ---- the conversion's orientation rule ----
cat >"$TMP/twice.json" <<'EOF'
{"format": "hsx-scene/1", "dimension": 2, "domain": {"min": [-5, -5], "max": [5, 5]},
 "halfspaces": [{"name": "B", "kind": "disk", "center": [0, 0], "radius": 3},
                {"name": "A", "kind": "disk", "center": [0, 0], "radius": 1},
                {"name": "A2", "kind": "disk", "center": [0, 0], "radius": 1}]}
EOF
# B - A runs along A (and its copy A2) reversed: A is complemented in the BSH scene, and the ring comes back.
if run 0 "convert B - A (A given twice)" "$HSX" convert "$TMP/twice.json" --csg "B - A" --out "$TMP/to.json"; then
  check "convert B - A: A complemented" json "$TMP/to.json" '[h.get("complement", False) for h in d["halfspaces"]][:2] == [False, True]'
  run 0 "extract the ring" "$HSX" extract "$TMP/to.json" --json "$TMP/tr.json" &&
    check "ring area 8 pi" json "$TMP/tr.json" 'abs(float(d["area"]["decimal"]) - 8 * 3.14159265358979) < 1e-9'
fi
cat >"$TMP/both.json" <<'EOF'
{"format": "hsx-scene/1", "dimension": 2, "domain": {"min": [-8, -8], "max": [8, 8]},
 "halfspaces": [{"name": "L", "kind": "halfplane", "normal": [1, 0], "offset": 0},
                {"name": "D1", "kind": "disk", "center": [0, 3], "radius": 2},
                {"name": "D2", "kind": "disk", "center": [0, -3], "radius": 2}]}
EOF
# (D1 & L) | (D2 & ~L) runs along L with L's orientation on D1 and reversed on D2: L is kept and a complemented
# copy "L~" is added for the reversed part (the description says so); the solid comes back.
if run 0 "convert: a boundary used both ways" "$HSX" convert "$TMP/both.json" --csg "(D1 & L) | (D2 & ~L)" \
  --out "$TMP/bo.json"; then
  check "convert both ways: L kept, complemented copy L~ added and described" json "$TMP/bo.json" '
    [(h["name"], h.get("complement", False)) for h in d["halfspaces"]] ==
      [("L", False), ("D1", False), ("D2", False), ("L~", True)] and "complemented copy of L" in d["description"]'
  if run 0 "csg of the both-ways solid" "$HSX" csg "$TMP/both.json" --csg "(D1 & L) | (D2 & ~L)" --json "$TMP/bc.json" &&
    run 0 "extract the both-ways conversion" "$HSX" extract "$TMP/bo.json" --json "$TMP/br.json"; then
    a="$(field "$TMP/bc.json" 'd["area"]')"
    b="$(field "$TMP/br.json" 'd["area"]')"
    if [[ "$a" == "$b" ]]; then pass; else fail "both-ways conversion: extract area $b, csg area $a"; fi
    check "both-ways conversion: two half disks, area 4 pi" \
      json "$TMP/br.json" 'abs(float(d["area"]["decimal"]) - 4 * 3.14159265358979) < 1e-9'
  fi
fi

# ---- samples ----
for k in 1 5 6; do
  if run 0 "samples fig02-$k" "$HSX" samples "$FIG/fig02-$k.json" --target "$TMP/r$k.json" --json "$TMP/s$k.json"; then
    check "samples fig02-$k: reproduced, bounds" json "$TMP/s$k.json" '
      d["format"] == "hsx-samples/1" and d["reproduced"] is True and
      d["lower_bound"] <= d["samples"] <= d["upper_bound"] and d["rounds"] <= d["upper_bound"] + 1 and
      len(d["sample_patches"]) == d["samples"] and
      (d["minimum"] is None or d["lower_bound"] <= d["minimum"] <= d["samples"])'
  fi
done
for search in beam best-first; do
  for expr in "A | B" "A & B"; do
    if run 0 "samples --csg '$expr' --search $search" "$HSX" samples "$FIG/fig02-1.json" --csg "$expr" \
      --search "$search" --json "$TMP/sx.json" --out "$TMP/sxo.json"; then
      check "samples '$expr' ($search): reproduced" json "$TMP/sx.json" "d['reproduced'] is True and d['search'] == '$search'"
      run 0 "extract the sampled scene" "$HSX" extract "$TMP/sxo.json" --method "$search" --json "$TMP/sxr.json" &&
        check "the sampled scene gives '$expr' back" \
          json "$TMP/sxr.json" "d['area']['exact'] == ('24' if '$expr' == 'A | B' else '4')"
    fi
  done
done

# ---- samples in 3D: --target a 3D extraction, --out a 3D scene that extract reproduces; --csg in 3D ----
S3="$SRC/data/scenes3d/primitives.json"
if run 0 "extract 3D primitives" "$HSX" extract "$S3" --method best-first --json "$TMP/p3.json" &&
  run 0 "samples 3D --target" "$HSX" samples "$S3" --target "$TMP/p3.json" --json "$TMP/p3s.json" --out "$TMP/p3o.json"; then
  check "samples 3D: reproduced, bounds" json "$TMP/p3s.json" '
    d["reproduced"] is True and d["lower_bound"] <= d["samples"] <= d["upper_bound"]'
  check "samples 3D --out: a 3D scene with one 'at' sample per generated sample" json "$TMP/p3o.json" '
    d["dimension"] == 3 and all("at" in s for s in d["samples"]) and
    len(d["samples"]) == json.load(open(sys.argv[1].replace("p3o", "p3s")))["samples"]'
  run 0 "extract the sampled 3D scene" "$HSX" extract "$TMP/p3o.json" --method beam --json "$TMP/p3b.json" &&
    check "the sampled 3D scene gives the target back" python3 -c '
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
sys.exit(0 if a["inside_cells"] == b["inside_cells"] and a["complex_id"] == b["complex_id"] else 1)' \
      "$TMP/p3.json" "$TMP/p3b.json"
fi
run 0 "samples 3D --csg" "$HSX" samples "$S3" --csg "T | C" --json "$TMP/p3c.json" &&
  check "samples 3D --csg 'T | C': reproduced" json "$TMP/p3c.json" 'd["reproduced"] is True'
# 3D manifold check: the kept counterexamples fail Sec. 3.1 (exit 3), a generic scene passes.
for k in edge vertex; do
  run 3 "check manifold3-$k-pinch" "$HSX" check "$SRC/data/counterexamples/manifold3-$k-pinch.json" &&
    check "check manifold3-$k-pinch: Sec. 3.1 fails" grep -q "Sec. 3.1 .* FAIL" "$TMP/out"
done
run 0 "check 3D primitives" "$HSX" check "$S3"

# ---- bad inputs: exit 2, the message names the option, no output file ----
rm -f "$TMP/bad.json"
run 2 "describe: unknown halfspace in --csg" "$HSX" describe "$FIG/fig02-1.json" --csg "A | X" --json "$TMP/bad.json" &&
  err_names "--csg" '"X"'
run 2 "csg: unknown halfspace in --csg" "$HSX" csg "$FIG/fig02-1.json" --csg "A & (B | Q)" --json "$TMP/bad.json" &&
  err_names "--csg" '"Q"'
run 2 "describe: both --shape and --csg" "$HSX" describe "$FIG/fig02-5.json" --shape "$TMP/r5.json" --csg "A" \
  --json "$TMP/bad.json" && err_names "--shape" "--csg"
run 2 "csg: neither --shape nor --csg" "$HSX" csg "$FIG/fig02-5.json" --json "$TMP/bad.json" && err_names "--shape" "--csg"
# A result computed from another scene (fig03-a: 10 cells; fig02: 6).
run 0 "extract fig03-a" "$HSX" extract "$FIG/fig03-a.json" --json "$TMP/r3a.json"
if [[ "$(field "$TMP/r3a.json" 'max(d["inside_cells"])')" -ge 6 ]]; then
  run 2 "csg: --shape from another scene" "$HSX" csg "$FIG/fig02-5.json" --shape "$TMP/r3a.json" --json "$TMP/bad.json" &&
    err_names "r3a.json" "complex_id" "another scene"
  run 2 "describe: --shape from another scene" "$HSX" describe "$FIG/fig02-5.json" --shape "$TMP/r3a.json" &&
    err_names "r3a.json" "another scene"
  run 2 "samples: --target from another scene" "$HSX" samples "$FIG/fig02-5.json" --target "$TMP/r3a.json" \
    --json "$TMP/bad.json" && err_names "r3a.json" "another scene"
else
  fail "fig03-a's result has no cell id >= 6 (test setup)"
fi
# samples spells the shape option --target: its message must say so (io/solid.hpp: SolidSource's option names).
run 2 "samples: both --target and --csg" "$HSX" samples "$FIG/fig02-5.json" --target "$TMP/r5.json" --csg "A" \
  --json "$TMP/bad.json" && err_names "--target" "--csg"
run 2 "samples: an unbounded target" "$HSX" samples "$FIG/fig02-1.json" --csg "~A" \
  --json "$TMP/bad.json" && err_names "orientation-preserving"
# The symmetric difference runs along B reversed around the centre square: no BSH shape has that boundary.
run 2 "samples: a target that is not orientation-preserving" "$HSX" samples "$FIG/fig02-1.json" \
  --csg "(A - B) | (B - A)" --json "$TMP/bad.json" && err_names "orientation-preserving"
run 2 "convert: --csgnet with a SCENE" "$HSX" convert "$FIG/fig02-1.json" --csgnet "c(32,32,16)" --out "$TMP/bad.json" &&
  err_names "--csgnet"
run 2 "convert: bad --search" "$HSX" convert "$FIG/fig02-1.json" --csg "A" --search greedy --out "$TMP/bad.json" &&
  err_names "--search"
run 2 "convert: --out missing" "$HSX" convert "$FIG/fig02-1.json" --csg "A"
run 2 "corpus: unknown kind" "$HSX" corpus shapenet /dev/null && err_names "csgnet"
if [[ -e "$TMP/bad.json" ]]; then fail "a failed command left $TMP/bad.json behind"; else pass; fi

# ---- --labels on describe and csg: cell and patch ids in the picture ----
run 0 "describe --labels" "$HSX" describe "$FIG/fig02-1.json" --csg "A" --svg "$TMP/dl.svg" --labels &&
  check "describe --labels draws ids" grep -q 'class="cell-id"' "$TMP/dl.svg"
run 0 "csg --labels" "$HSX" csg "$FIG/fig02-1.json" --csg "A" --svg "$TMP/cl.svg" --labels &&
  check "csg --labels draws ids" grep -q 'class="patch-id"' "$TMP/cl.svg"
run 0 "csg without --labels" "$HSX" csg "$FIG/fig02-1.json" --csg "A" --svg "$TMP/cn.svg" &&
  check "csg without --labels draws no ids" bash -c "! grep -q 'class=\"cell-id\"' '$TMP/cn.svg'"

# ---- corpus ----
CORPUS="$SRC/../shared/data/csgnet/best_st_expressions.txt"
if [[ -f "$CORPUS" ]]; then
  if run 0 "corpus csgnet --limit 5" "$HSX" corpus csgnet "$CORPUS" --limit 5 --json "$TMP/corpus.json"; then
    check "corpus: 5 programs, all ok" grep -qE "^5 programs.*: 5 ok" "$TMP/out"
    check "corpus json: 5 rows, ok, samples within bounds" json "$TMP/corpus.json" '
      d["format"] == "hsx-corpus/1" and len(d["programs"]) == 5 and
      all(p["ok"] and p["lower_bound"] <= p["samples"] <= p["upper_bound"] for p in d["programs"])'
  fi
else
  echo "note: $CORPUS not found: corpus test skipped"
fi

echo "$passed passed, $failed failed"
[[ "$failed" == 0 ]]
