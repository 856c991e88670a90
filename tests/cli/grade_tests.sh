#!/usr/bin/env bash
# `hsx grade` and `hsx arrange --export bsh-graphcut`, end to end: usage: grade_tests.sh HSX NAIVE_GRAPHCUT ROOT
# - the export is the authors' graph-cut input (num_cells, patches with their fields) for 2D and 3D scenes;
# - hsx's own optimum grades "optimal" (exit 0) in every accepted labelling format; the empty shape and a
#   reversed shape grade "suboptimal" / "invalid" (exit 3) with the witness;
# - examples/naive_graphcut (a double-precision K=1 beam on the export) is graded on every bundled 2D scene and
#   figure: its verdict and the exit status agree, it is optimal on star.json, and it fails on shared_edges.json
#   (it forbids the shared edge both ways: two coincident patches of opposite orientation), where the grade names
#   the patches it left off;
# - bad input exits 2 with a message naming the file and the problem, and leaves no --json behind.
# Prints "N passed, M failed" and exits non-zero when anything failed.
set -u

HSX="${1:?usage: grade_tests.sh HSX NAIVE_GRAPHCUT ROOT}"
NAIVE="${2:?usage: grade_tests.sh HSX NAIVE_GRAPHCUT ROOT}"
ROOT="${3:?usage: grade_tests.sh HSX NAIVE_GRAPHCUT ROOT}"
source "$(dirname "${BASH_SOURCE[0]}")/testlib.sh"
testlib_init grade

# json_field FILE EXPRESSION: prints a Python expression over the document d.
json_field() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }

# ---- the export ----
STAR="$ROOT/data/scenes/star.json"
for scene in "$STAR" "$ROOT/data/scenes3d/primitives.json"; do
  name="$(basename "$scene" .json)"
  expect_status 0 "arrange --export on $name" "$HSX" arrange "$scene" --export bsh-graphcut "$TMP/$name.graph.json" \
    --json "$TMP/$name.complex.json" -q
  problems="$(python3 - "$TMP/$name.graph.json" "$TMP/$name.complex.json" <<'EOF'
import json, sys
g, c = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
p = []
if g.get("num_cells") != c["counts"]["cells"]: p.append("num_cells %r" % g.get("num_cells"))
if len(g.get("patches", [])) != c["counts"]["patches"]: p.append("patch count")
for k, e in enumerate(g.get("patches", [])):
    for key in ("adj_cell_0", "adj_cell_1", "weight", "implicit_id", "num_samples"):
        if not isinstance(e.get(key), int) or e[key] < 0: p.append("patches[%d].%s %r" % (k, key, e.get(key)))
    if e.get("adj_cell_0") == e.get("adj_cell_1"): p.append("patches[%d]: one cell on both sides" % k)
    if not all(isinstance(q, int) and 0 <= q < len(g["patches"]) and q != k for q in e.get("adj_patches", [None])):
        p.append("patches[%d].adj_patches" % k)
if sum(e["num_samples"] for e in g["patches"]) != len(c.get("samples", [])): p.append("sample count")
print("; ".join(p[:5]))
EOF
)"
  if [[ -z "$problems" ]]; then pass; else fail "export of $name: $problems"; fi
done
expect_status 2 "--export with an unknown format" "$HSX" arrange "$STAR" --export graphcut "$TMP/x.json" -q
expect_status 2 "--export without a file" "$HSX" arrange "$STAR" --export bsh-graphcut
expect_status 2 "--weight-scale 0" "$HSX" arrange "$STAR" --export bsh-graphcut "$TMP/x.json" --weight-scale 0 -q
[[ ! -e "$TMP/x.json" ]] && pass || fail "a refused --export left $TMP/x.json behind"

# ---- hsx's optimum, in every format, grades optimal ----
expect_status 0 "extract star" "$HSX" extract "$STAR" --method best-first --json "$TMP/star.result.json" -q
expect_status 0 "grade an hsx-result/1" "$HSX" grade "$STAR" "$TMP/star.result.json" --json "$TMP/grade.json"
[[ "$(json_field "$TMP/grade.json" "d['verdict'], d['graded_format'], d['versus_optimum']")" == \
   "optimal hsx-result/1 equal" ]] && pass || fail "grade.json of the optimum: $(head -c 400 "$TMP/grade.json")"
cells="$(json_field "$TMP/star.graph.json" "d['num_cells']")"
json_field "$TMP/star.result.json" "' '.join('1' if c in set(d['inside_cells']) else '0' for c in range($cells))" \
  >"$TMP/star.plain.txt"
json_field "$TMP/star.result.json" "json.dumps({'labels': [c in set(d['inside_cells']) for c in range($cells)]})" \
  >"$TMP/star.labels.json"
json_field "$TMP/star.result.json" "json.dumps([int(c in set(d['inside_cells'])) for c in range($cells)])" \
  >"$TMP/star.list.json"
for f in plain.txt labels.json list.json; do
  expect_status 0 "grade the optimum as $f" "$HSX" grade "$STAR" "$TMP/star.$f" -q
  expect_status 0 "grade the optimum as $f, exact reference" "$HSX" grade "$STAR" "$TMP/star.$f" -q --method exact
done

# ---- the empty shape is worse; a shape with an outer cell inside is invalid ----
python3 -c "print(' '.join(['0'] * $cells))" >"$TMP/empty.txt"
expect_status 3 "grade the empty shape" "$HSX" grade "$STAR" "$TMP/empty.txt" --json "$TMP/empty.grade.json"
[[ "$(json_field "$TMP/empty.grade.json" "d['verdict'], d['gap']['missing_samples'] > 0 or d['gap']['measure']['decimal']")" \
   == "suboptimal True" ]] && pass || fail "empty shape: $(head -c 400 "$TMP/empty.grade.json")"
[[ "$(json_field "$TMP/empty.grade.json" "len(d['boundary_difference']['optimum_only']) > 0 and not d['boundary_difference']['theirs_only']")" \
   == True ]] && pass || fail "empty shape: the patches it leaves off are not named"
python3 -c "print(' '.join(['1'] * $cells))" >"$TMP/full.txt"
expect_status 3 "grade a shape with outer cells inside" "$HSX" grade "$STAR" "$TMP/full.txt" --json "$TMP/full.grade.json"
[[ "$(json_field "$TMP/full.grade.json" "d['verdict'], d['orientation_preserving'], bool(d['orientation_problem'])")" \
   == "invalid False True" ]] && pass || fail "full shape: $(head -c 400 "$TMP/full.grade.json")"
grep -q "verdict invalid" "$TMP/out.txt" && pass || fail "the summary of an invalid shape: $(cat "$TMP/out.txt")"

# ---- the naive double-precision K=1 beam, graded on every bundled 2D scene and figure ----
declare -A verdicts=()
for scene in "$ROOT"/data/scenes/*.json "$ROOT"/data/figures/fig*.json; do
  name="$(basename "$scene" .json)"
  "$HSX" arrange "$scene" --export bsh-graphcut "$TMP/g.json" -q || { fail "export of $name"; continue; }
  "$NAIVE" "$TMP/g.json" "$TMP/n.json" || { fail "naive_graphcut on $name"; continue; }
  "$HSX" grade "$scene" "$TMP/n.json" -q --json "$TMP/n.grade.json" 2>"$TMP/err.txt"
  status=$?
  verdict="$(json_field "$TMP/n.grade.json" "d['verdict']" 2>/dev/null)"
  case "$verdict:$status" in
    optimal:0 | suboptimal:3 | invalid:3 | undecided:4) pass ;;
    *) fail "naive on $name: verdict '$verdict' with exit $status ($(head -c 200 "$TMP/err.txt"))" ;;
  esac
  verdicts[$name]="$verdict"
  cp "$TMP/n.json" "$TMP/naive-$name.json"
done
[[ "${verdicts[star]:-}" == optimal ]] && pass || fail "naive on star: ${verdicts[star]:-none}, expected optimal"
[[ "${verdicts[shared_edges]:-}" == suboptimal ]] && pass || fail "naive on shared_edges: ${verdicts[shared_edges]:-none}"
"$HSX" grade "$ROOT/data/scenes/shared_edges.json" "$TMP/naive-shared_edges.json" >"$TMP/out.txt" 2>&1
grep -q "optimum only R2#6 R2#7" "$TMP/out.txt" && pass || fail "shared_edges: the summary does not name the patches: $(cat "$TMP/out.txt")"
summary=""
for v in optimal suboptimal invalid undecided; do
  n=0
  for name in "${!verdicts[@]}"; do [[ "${verdicts[$name]}" == "$v" ]] && n=$((n + 1)); done
  summary+="$v $n  "
done
echo "naive_graphcut on ${#verdicts[@]} bundled scenes: $summary"

# ---- --run: the program run here, its answer graded ----
SHARED="$ROOT/data/scenes/shared_edges.json"
mkdir -p "$TMP/tmpdir"
export TMPDIR="$TMP/tmpdir"
expect_status 3 "--run naive_graphcut on shared_edges" "$HSX" grade "$SHARED" --run "'$NAIVE' {input} {output}" \
  --json "$TMP/run.json"
[[ "$(json_field "$TMP/run.json" "d['verdict'], d['run']['ran'], d['run']['exit_status'], d['graded_format']")" == \
   "suboptimal True 0 BSH graph-cut labels" ]] && pass || fail "--run: $(head -c 600 "$TMP/run.json")"
expect_status 0 "--run naive_graphcut on star" "$HSX" grade "$STAR" --run "'$NAIVE' {input} {output}" -q
expect_status 3 "--run a program that times out" "$HSX" grade "$STAR" --run "sleep 20; : {input} {output}" \
  --run-time-limit 0.5 --json "$TMP/slow.json"
[[ "$(json_field "$TMP/slow.json" "d['verdict'], d['run']['timed_out'], d['run']['seconds'] < 5")" == \
   "no answer True True" ]] && pass || fail "--run, timed out: $(head -c 600 "$TMP/slow.json")"
expect_status 3 "--run a program that fails" "$HSX" grade "$STAR" --run "echo broken >&2; exit 9 # {input} {output}"
grep -q "exit status 9" "$TMP/out.txt" && grep -q broken "$TMP/out.txt" && pass || fail "--run, failing: $(cat "$TMP/out.txt")"
expect_status 3 "--run a program reading hsx-complex/1" "$HSX" grade "$STAR" --run-input complex \
  --run "grep -q hsx-complex/1 {input} && echo 0 > {output}"
grep -q "{output}: 1 labels for $cells cells" "$TMP/out.txt" && pass || fail "--run, short output: $(cat "$TMP/out.txt")"
[[ -z "$(ls -A "$TMP/tmpdir")" ]] && pass || fail "--run left $(ls "$TMP/tmpdir") in TMPDIR"
unset TMPDIR
expect_status 2 "--run without {output}" "$HSX" grade "$STAR" --run "'$NAIVE' {input}"
expect_status 2 "--run and THEIR_RESULT" "$HSX" grade "$STAR" "$TMP/star.plain.txt" --run "'$NAIVE' {input} {output}"
expect_status 2 "neither THEIR_RESULT nor --run" "$HSX" grade "$STAR"
expect_status 2 "--run-input unknown" "$HSX" grade "$STAR" --run "'$NAIVE' {input} {output}" --run-input scene

# ---- bad input: exit 2, a message naming the file, no output ----
expect_status 2 "too few labels" "$HSX" grade "$STAR" <(echo "0 1") --json "$TMP/no.json"
grep -q "labels for $cells cells" "$TMP/err.txt" && pass || fail "too few labels: $(cat "$TMP/err.txt")"
printf '0\n1\nmaybe\n' >"$TMP/bad.txt"
expect_status 2 "a bad token" "$HSX" grade "$STAR" "$TMP/bad.txt" --json "$TMP/no.json"
grep -q "bad.txt: line 3: label 2 is \"maybe\"" "$TMP/err.txt" && pass || fail "a bad token: $(cat "$TMP/err.txt")"
expect_status 2 "a missing labelling" "$HSX" grade "$STAR" "$TMP/missing.txt" --json "$TMP/no.json"
expect_status 2 "a result of another scene" "$HSX" grade "$ROOT/data/scenes/lens.json" "$TMP/star.result.json" --json "$TMP/no.json"
grep -q "complex_id" "$TMP/err.txt" && pass || fail "a result of another scene: $(cat "$TMP/err.txt")"
expect_status 2 "an incomplete reference method" "$HSX" grade "$STAR" "$TMP/star.plain.txt" --method beam
[[ ! -e "$TMP/no.json" ]] && pass || fail "a refused grade left its --json behind"
mkdir "$TMP/dir.json"
expect_status 2 "--json into a directory" "$HSX" grade "$STAR" "$TMP/star.plain.txt" --json "$TMP/dir.json"

testlib_finish
