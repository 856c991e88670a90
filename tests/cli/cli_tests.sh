#!/usr/bin/env bash
# End-to-end tests of the `hsx` program: usage: cli_tests.sh PATH/TO/hsx
# - --version and --help exit 0;
# - `hsx arrange` on every bundled scene (data/scenes/*.json) exits 0 and writes valid hsx-complex/1 JSON with
#   counts.{vertices,edges,cells,outer_cells,patches} (equal to tests/regression/expected.json) and
#   patches[].{halfspace,measure.decimal,measure.exact,samples}, and an SVG;
# - bad inputs exit 2 with a message on stderr naming the offending field, and leave no output file behind;
# - a missing scene file exits 2.
# Prints "N passed, M failed" and exits non-zero when anything failed.
set -u

HSX="${1:?usage: cli_tests.sh PATH/TO/hsx}"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
EXPECTED="$ROOT/tests/regression/expected.json"
TMP="$(mktemp -d "${TMPDIR:-/tmp}/hsx-cli-tests.XXXXXX")"
trap 'rm -rf "$TMP"' EXIT

passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() {
  failed=$((failed + 1))
  echo "FAIL: $*" >&2
}

# ---- --version, --help ----
if out="$("$HSX" --version 2>&1)"; then
  if [[ "$out" == hsx* ]]; then pass; else fail "--version printed '$out'"; fi
else
  fail "--version exited $?"
fi
if "$HSX" --help >"$TMP/help.txt" 2>&1; then
  if grep -q arrange "$TMP/help.txt"; then pass; else fail "--help does not mention the arrange command"; fi
else
  fail "--help exited non-zero"
fi
if "$HSX" arrange --help >/dev/null 2>&1; then pass; else fail "arrange --help exited non-zero"; fi

# ---- every bundled scene ----
check_complex_json() {  # file scene-name: structure and counts
  python3 - "$1" "$2" "$EXPECTED" <<'EOF'
import json, sys
path, scene, expected_path = sys.argv[1], sys.argv[2], sys.argv[3]
doc = json.load(open(path))
problems = []
if doc.get("format") != "hsx-complex/1":
    problems.append("format is %r" % doc.get("format"))
counts = doc.get("counts", {})
for key in ("vertices", "edges", "cells", "outer_cells", "patches"):
    if not isinstance(counts.get(key), int):
        problems.append("counts.%s missing or not an integer" % key)
patches = doc.get("patches")
if not isinstance(patches, list) or not patches:
    problems.append("patches missing or empty")
else:
    names = set(doc.get("halfspaces", []))
    for k, p in enumerate(patches):
        if p.get("halfspace") not in names:
            problems.append("patches[%d].halfspace %r is not a halfspace name" % (k, p.get("halfspace")))
        m = p.get("measure")
        if not isinstance(m, dict) or not isinstance(m.get("decimal"), str) or "exact" not in m:
            problems.append("patches[%d].measure lacks decimal/exact" % k)
        elif not (m["exact"] is None or isinstance(m["exact"], str)):
            problems.append("patches[%d].measure.exact is neither a string nor null" % k)
        if not isinstance(p.get("samples"), int):
            problems.append("patches[%d].samples is not an integer" % k)
    if counts.get("patches") != len(patches):
        problems.append("counts.patches %r != %d patches" % (counts.get("patches"), len(patches)))
    if counts.get("cells") != len(doc.get("cells", [])):
        problems.append("counts.cells disagrees with cells[]")
expected = json.load(open(expected_path))["scenes"].get(scene)
if expected is None:
    problems.append("no expectation for %s in tests/regression/expected.json" % scene)
else:
    for key in ("vertices", "edges", "cells", "outer_cells", "patches"):
        if counts.get(key) != expected[key]:
            problems.append("counts.%s = %r, expected %r" % (key, counts.get(key), expected[key]))
if problems:
    print("; ".join(problems))
    sys.exit(1)
EOF
}

shopt -s nullglob
scenes=("$ROOT"/data/scenes/*.json)
if ((${#scenes[@]} == 0)); then fail "no scenes in $ROOT/data/scenes"; fi
for scene in "${scenes[@]}"; do
  name="$(basename "$scene")"
  json="$TMP/$name.complex.json"
  svg="$TMP/$name.svg"
  if "$HSX" arrange "$scene" --json "$json" --svg "$svg" >"$TMP/stdout.txt" 2>"$TMP/stderr.txt"; then
    if why="$(check_complex_json "$json" "$name")"; then pass; else fail "arrange $name: $why"; fi
    if [[ -s "$svg" ]] && grep -q "<svg" "$svg"; then pass; else fail "arrange $name: no SVG written"; fi
    if grep -q "patches" "$TMP/stdout.txt"; then pass; else fail "arrange $name: no summary on stdout"; fi
  else
    fail "arrange $name exited $? ($(head -c 300 "$TMP/stderr.txt"))"
  fi
done
# --json - writes the document to standard output.
if "$HSX" arrange "${scenes[0]}" --json - >"$TMP/stdout.json" 2>/dev/null &&
  python3 -c 'import json,sys; json.load(open(sys.argv[1]))["counts"]' "$TMP/stdout.json" 2>/dev/null; then
  pass
else
  fail "arrange --json - did not write valid JSON to stdout"
fi

# ---- bad inputs: exit 2, message naming the field, no output left behind ----
BAD="$TMP/bad"
mkdir -p "$BAD"
HDR='"format": "hsx-scene/1", "dimension": 2'
DISK='{"name": "A", "kind": "disk", "center": [0, 0], "radius": 1}'
write() { printf '%s\n' "$2" >"$BAD/$1.json"; }
write invalid_json "{$HDR, \"halfspaces\": [$DISK"
write unknown_field "{$HDR, \"colour\": \"red\", \"halfspaces\": [$DISK]}"
write unknown_halfspace_field "{$HDR, \"halfspaces\": [{\"name\": \"A\", \"kind\": \"disk\", \"center\": [0, 0], \"radius\": 1, \"radios\": 2}]}"
write duplicate_name "{$HDR, \"halfspaces\": [$DISK, {\"name\": \"A\", \"kind\": \"disk\", \"center\": [3, 0], \"radius\": 1}]}"
write zero_radius "{$HDR, \"halfspaces\": [{\"name\": \"A\", \"kind\": \"disk\", \"center\": [0, 0], \"radius\": 0}]}"
write self_intersecting "{$HDR, \"halfspaces\": [{\"name\": \"P\", \"kind\": \"polygon\", \"vertices\": [[0, 0], [2, 2], [2, 0], [0, 2]]}]}"
write sample_unknown_halfspace "{$HDR, \"halfspaces\": [$DISK], \"samples\": [{\"on\": \"B\", \"at\": [1, 0]}]}"
write sample_off_boundary "{$HDR, \"halfspaces\": [$DISK], \"samples\": [{\"on\": \"A\", \"at\": [2, 0]}]}"
write sample_on_crossing "{$HDR, \"halfspaces\": [{\"name\": \"X\", \"kind\": \"halfplane\", \"normal\": [0, 1], \"offset\": 0}, {\"name\": \"Y\", \"kind\": \"halfplane\", \"normal\": [1, 0], \"offset\": 0}], \"samples\": [{\"on\": \"X\", \"at\": [0, 0]}]}"
write empty_halfspaces "{$HDR, \"halfspaces\": []}"
write domain_misses_disk "{$HDR, \"domain\": {\"min\": [-1, -1], \"max\": [1, 1]}, \"halfspaces\": [{\"name\": \"A\", \"kind\": \"disk\", \"center\": [0, 0], \"radius\": 2}]}"
write huge_exponent_string "{$HDR, \"halfspaces\": [{\"name\": \"A\", \"kind\": \"disk\", \"center\": [0, 0], \"radius\": \"1e99999999999\"}]}"
write huge_exponent_number "{$HDR, \"halfspaces\": [{\"name\": \"H\", \"kind\": \"halfplane\", \"normal\": [0, 1], \"offset\": 1e99999999999}]}"
write not_a_number "{$HDR, \"halfspaces\": [{\"name\": \"A\", \"kind\": \"disk\", \"center\": [0, \"abc\"], \"radius\": 1}]}"
write zero_normal "{$HDR, \"halfspaces\": [{\"name\": \"H\", \"kind\": \"halfplane\", \"normal\": [0, 0], \"offset\": 1}]}"
write wrong_format "{\"format\": \"hsx-scene/9\", \"dimension\": 2, \"halfspaces\": [$DISK]}"

# case name -> text that stderr must contain (the field or the position it is about)
declare -A NEEDLE=(
  [invalid_json]="column"
  [unknown_field]="colour"
  [unknown_halfspace_field]="radios"
  [duplicate_name]="halfspaces[1].name"
  [zero_radius]="halfspaces[0].radius"
  [self_intersecting]="halfspaces[0]"
  [sample_unknown_halfspace]="samples[0].on"
  [sample_off_boundary]="samples[0]"
  [sample_on_crossing]="samples[0]"
  [empty_halfspaces]="halfspaces"
  [domain_misses_disk]="domain"
  [huge_exponent_string]="halfspaces[0].radius"
  [huge_exponent_number]="halfspaces[0].offset"
  [not_a_number]="halfspaces[0].center"
  [zero_normal]="halfspaces[0].normal"
  [wrong_format]="format"
)

for input in "$BAD"/*.json; do
  case_name="$(basename "$input" .json)"
  needle="${NEEDLE[$case_name]:-}"
  out="$TMP/out-$case_name"
  "$HSX" arrange "$input" --json "$out.json" --svg "$out.svg" >"$TMP/stdout.txt" 2>"$TMP/stderr.txt"
  rc=$?
  if ((rc != 2)); then
    fail "$case_name: exit code $rc, expected 2 (stderr: $(head -c 300 "$TMP/stderr.txt"))"
    continue
  fi
  pass
  if [[ -n "$needle" ]] && grep -qF -- "$needle" "$TMP/stderr.txt"; then
    pass
  else
    fail "$case_name: stderr does not name '$needle': $(head -c 300 "$TMP/stderr.txt")"
  fi
  if [[ -e "$out.json" || -e "$out.svg" ]]; then
    fail "$case_name: an output file was left behind"
  else
    pass
  fi
done
# Nothing else (temporary files of the atomic writes) was left in the output directory either.
leftovers="$(find "$TMP" -maxdepth 1 -name 'out-*' | head -5)"
if [[ -z "$leftovers" ]]; then pass; else fail "files left behind: $leftovers"; fi

# ---- a missing file ----
"$HSX" arrange "$TMP/does-not-exist.json" --json "$TMP/missing.json" >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -qF "does-not-exist.json" "$TMP/stderr.txt" && [[ ! -e "$TMP/missing.json" ]]; then
  pass
else
  fail "missing file: exit $rc, stderr: $(head -c 300 "$TMP/stderr.txt")"
fi
# ---- no subcommand, unknown option: usage errors exit 2 ----
"$HSX" >/dev/null 2>&1
rc=$?
if ((rc == 2)); then pass; else fail "no subcommand: exit $rc, expected 2"; fi
"$HSX" arrange "${scenes[0]}" --no-such-option >/dev/null 2>&1
rc=$?
if ((rc == 2)); then pass; else fail "unknown option: exit $rc, expected 2"; fi

# ---- extract --method exact: the oracle's energy and tie count on every bundled scene and the Prop. 5.1
# counterexample; --max-nodes stops it with a lower bound and no claim of optimality ----
for input in "${scenes[@]}" "$ROOT/data/counterexamples/prop51-concurrent-lines.json"; do
  name="$(basename "$input" .json)"
  if "$HSX" extract "$input" --method exact --json "$TMP/exact-$name.json" -q &&
    "$HSX" extract "$input" --method brute-force --json "$TMP/brute-$name.json" -q &&
    why="$(python3 - "$TMP/exact-$name.json" "$TMP/brute-$name.json" <<'EOF'
import json, sys
e, b = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
problems = []
if e["method"] != "exact" or e["optimal"] is not True or "stopped_by" in e:
    problems.append("method/optimal/stopped_by %r %r %r" % (e["method"], e["optimal"], e.get("stopped_by")))
if e["energy"]["missing_samples"] != b["energy"]["missing_samples"] or \
   e["energy"]["measure"]["decimal"] != b["energy"]["measure"]["decimal"]:
    problems.append("energy %r vs brute force %r" % (e["energy"], b["energy"]))
if e["ties"]["count"] != b["ties"]["count"]:
    problems.append("ties %r vs %r" % (e["ties"], b["ties"]))
bb = e["stats"].get("branch_and_bound", {})
for key in ("nodes", "pruned_by_bound", "pruned_by_islands", "lower_bound", "gap", "max_gap"):
    if key not in bb:
        problems.append("stats.branch_and_bound.%s missing" % key)
if bb.get("gap") != {"missing_samples": 0, "measure": 0.0}:
    problems.append("gap %r after a finished search" % bb.get("gap"))
if problems:
    print("; ".join(problems))
    sys.exit(1)
EOF
)"; then pass; else fail "extract --method exact $name: ${why:-exit non-zero}"; fi
done
if "$HSX" extract "$ROOT/data/scenes/star.json" --method exact --max-nodes 1 --json "$TMP/exact-stopped.json" \
  >"$TMP/exact-stopped.txt" 2>"$TMP/stderr.txt" &&
  python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
ok = d["optimal"] is False and d.get("stopped_by") == "max-nodes" and d["ties"]["checked"] is False and \
     d["sample_connected"] is True and "lower_bound" in d["stats"]["branch_and_bound"]
sys.exit(0 if ok else 1)' "$TMP/exact-stopped.json" && grep -q "lower bound" "$TMP/exact-stopped.txt"; then
  pass
else
  fail "extract --method exact --max-nodes 1: not reported as stopped with a lower bound"
fi
"$HSX" extract "$ROOT/data/scenes/star.json" --method exact --max-nodes -1 >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "--max-nodes" "$TMP/stderr.txt"; then pass; else fail "--max-nodes -1: exit $rc"; fi

# ---- bench: repeated measurements, medians and repetition counts in CSV and JSON ----
mkdir -p "$TMP/bench"
cp "$ROOT/data/scenes/lens.json" "$TMP/bench/"
if "$HSX" bench "$TMP/bench" --repetitions 6 --min-time 0.001 --csv "$TMP/bench.csv" --json "$TMP/bench.json" \
  >"$TMP/bench.txt" 2>"$TMP/stderr.txt"; then
  if why="$(python3 - "$TMP/bench.csv" "$TMP/bench.json" <<'EOF'
import csv, json, sys
problems = []
rows = list(csv.DictReader(open(sys.argv[1])))
stages = [r["stage"] for r in rows]
if stages != ["arrange", "graphcut", "beam", "best-first", "brute-force", "exact"]:
    problems.append("CSV stages %r" % stages)
for r in rows:
    if r["scene"] != "lens.json" or r["status"] != "ok":
        problems.append("CSV row %r" % r)
        continue
    if int(r["repetitions"]) < 6:
        problems.append("%s: %s repetitions < 6" % (r["stage"], r["repetitions"]))
    if not float(r["median_s"]) > 0:
        problems.append("%s: median %s" % (r["stage"], r["median_s"]))
    if not float(r["min_s"]) <= float(r["q1_s"]) <= float(r["median_s"]) <= float(r["q3_s"]) <= float(r["max_s"]):
        problems.append("%s: quartiles out of order" % r["stage"])
    if r["stage"] in ("beam", "best-first", "brute-force", "exact") and not float(r["ratio_to_graphcut"]) > 0:
        problems.append("%s: no ratio" % r["stage"])
doc = json.load(open(sys.argv[2]))
if doc.get("format") != "hsx-bench/1" or doc.get("min_repetitions") != 6 or doc.get("min_seconds") != 0.001:
    problems.append("JSON header %r" % {k: doc.get(k) for k in ("format", "min_repetitions", "min_seconds")})
js = doc["rows"][0]["stages"]
for s, r in zip(js, rows):
    if s["stage"] != r["stage"] or s["repetitions"] != int(r["repetitions"]) or not s["median_s"] > 0:
        problems.append("JSON stage %r disagrees with CSV %r" % (s, r))
if problems:
    print("; ".join(problems))
    sys.exit(1)
EOF
)"; then pass; else fail "bench: $why"; fi
  if grep -q "lens.json" "$TMP/bench.txt" && grep -q "median" "$TMP/bench.txt"; then pass; else fail "bench: no table"; fi
else
  fail "bench exited $? ($(head -c 300 "$TMP/stderr.txt"))"
fi
"$HSX" bench "$TMP/bench" --repetitions 0 >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "--repetitions" "$TMP/stderr.txt"; then pass; else fail "bench --repetitions 0: exit $rc"; fi
# --meshes: the same measurements on NH-Rep's stages.
if "$HSX" bench --meshes "$ROOT/data/meshes/cube.obj" --repetitions 5 --min-time 0 --json "$TMP/mesh-bench.json" \
  >/dev/null 2>"$TMP/stderr.txt" &&
  python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
st = d["rows"][0]["stages"]
assert d["mode"] == "meshes" and [s["stage"] for s in st][0] == "read"
assert all(s["repetitions"] == 5 and s["median_s"] > 0 for s in st), st
' "$TMP/mesh-bench.json"; then
  pass
else
  fail "bench --meshes: $(head -c 300 "$TMP/stderr.txt")"
fi
# --3d: the exact 3D arrangement beside Nef; a missing BSH config is a skipped row, never a failure.
if "$HSX" bench --3d --planes 4,6 --h-divisors 1 --bsh-config "$TMP/no-such/config.json" --repetitions 1 \
  --min-time 0 --json "$TMP/bench3.json" >"$TMP/bench3.txt" 2>"$TMP/stderr.txt" &&
  python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
rows = d["rows"]
assert d["mode"] == "3d" and "skipped" in rows[0], rows[0]
for r in rows[1:]:
    assert [s["stage"] for s in r["stages"]] == ["arrange", "nef"], r
    assert r["agree"] == "yes" and int(r["nef cells"]) == r["cells"] and r["cells"] > 1, r
    assert all(s["repetitions"] == 1 for s in r["stages"]), r
' "$TMP/bench3.json"; then
  pass
else
  fail "bench --3d: $(head -c 300 "$TMP/stderr.txt")"
fi
"$HSX" bench --planes 4 >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "--planes needs --3d" "$TMP/stderr.txt"; then pass; else fail "bench --planes without --3d: exit $rc"; fi
"$HSX" bench --3d "$TMP/bench" >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "does not apply to --3d" "$TMP/stderr.txt"; then pass; else fail "bench --3d DIRS: exit $rc"; fi
# ---- bench --cuts --cut-inputs: the certified cut of given 2D and 3D inputs beside the double max flows ----
if "$HSX" bench --cuts --cut-scenes 0 --cut-inputs "$ROOT/data/scenes/lens.json" "$ROOT/data/scenes3d/primitives.json" \
  --repetitions 2 --min-time 0 --json "$TMP/bench-cuts.json" >/dev/null 2>"$TMP/stderr.txt" &&
  python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
rows = d["rows"]
assert d["mode"] == "cuts" and [r["input"].split("/")[-1] for r in rows] == ["lens.json", "primitives.json"], rows
for r in rows:
    assert [s["stage"] for s in r["stages"]] == ["certified cut", "zero-flow cut", "double BK", "double EK"], r
    assert r["certified"] == "yes" and r["same cut"] == "yes" and r["cells"] > 1, r
' "$TMP/bench-cuts.json"; then
  pass
else
  fail "bench --cuts --cut-inputs: $(head -c 300 "$TMP/stderr.txt")"
fi
"$HSX" bench --cut-inputs "$ROOT/data/scenes/lens.json" >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "--cut-inputs needs --cuts" "$TMP/stderr.txt"; then pass; else fail "bench --cut-inputs without --cuts: exit $rc"; fi
"$HSX" bench --cuts --cut-scenes 0 >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "--cut-scenes" "$TMP/stderr.txt"; then pass; else fail "bench --cuts --cut-scenes 0 alone: exit $rc"; fi
# ---- bench --arrange: hsx's 2D arrangement beside CGAL's bare insertion of the same curves ----
if "$HSX" bench --arrange --arrange-halfspaces 3,6 --arrange-inputs "$ROOT/data/scenes/lens.json" --repetitions 2 \
  --min-time 0 --json "$TMP/bench-arrange.json" >/dev/null 2>"$TMP/stderr.txt" &&
  python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
rows = d["rows"]
assert d["mode"] == "arrange" and d["ratio_to"] == "bare CGAL", d
assert [r["input"].split("/")[-1] for r in rows] == ["random 3 #0", "random 6 #0", "lens.json"], rows
for r in rows:
    assert [s["stage"] for s in r["stages"]] == ["hsx arrange", "bare CGAL"], r
    assert r["same cells"] == "yes" and r["cells"] > 1 and r["stages"][0]["ratio"] > 0, r
' "$TMP/bench-arrange.json"; then
  pass
else
  fail "bench --arrange: $(head -c 300 "$TMP/stderr.txt")"
fi
"$HSX" bench --arrange-scenes 2 >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "--arrange-scenes needs --arrange" "$TMP/stderr.txt"; then pass; else fail "bench --arrange-scenes alone: exit $rc"; fi
"$HSX" bench --arrange --brute >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "exclude each other" "$TMP/stderr.txt"; then pass; else fail "bench --arrange --brute: exit $rc"; fi
# ---- bench --brute: the brute-force oracle's labellings per second ----
if "$HSX" bench --brute --brute-halfspaces 4,6 --brute-scenes 2 --repetitions 2 --min-time 0 \
  --json "$TMP/bench-brute.json" >/dev/null 2>"$TMP/stderr.txt" &&
  python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
rows = d["rows"]
assert d["mode"] == "brute-force" and [r["halfsp"] for r in rows] == [4, 4, 6, 6], rows
for r in rows:
    assert [s["stage"] for s in r["stages"]] == ["brute force"] and r["stages"][0]["status"] == "ok", r
    assert int(r["labellings"]) >= 1 and float(r["per second"]) > 0 and int(r["optima"]) >= 1, r
' "$TMP/bench-brute.json"; then
  pass
else
  fail "bench --brute: $(head -c 300 "$TMP/stderr.txt")"
fi
"$HSX" bench --brute "$ROOT/data/scenes" >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "does not apply to --brute" "$TMP/stderr.txt"; then pass; else fail "bench --brute DIRS: exit $rc"; fi
# ---- bench --exact: --method exact on random scenes, best-first beside it on the small ones, a summary per size ----
if "$HSX" bench --exact --exact-halfspaces 4,6 --exact-scenes 3 --exact-best-first-up-to 4 --time-limit 60 \
  --repetitions 1 --min-time 0 --json "$TMP/bench-exact.json" >"$TMP/bench-exact.txt" 2>"$TMP/stderr.txt" &&
  python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
rows = d["rows"]
assert d["mode"] == "exact" and [r["input"] for r in rows] == ["random %d #%d" % (h, k) for h in (4, 6) for k in range(3)], rows
for r in rows:
    assert r["exact"] == "proven" and r["samples"] >= 1 and int(r["nodes"]) >= 1, r
    small = r["input"].startswith("random 4 ")
    assert (r["stages"][1]["status"] == "ok") == small, r
    if small and r["best-first"] == "proven":
        assert r["energies"] == "same", r
' "$TMP/bench-exact.json" && grep -q "^6 halfspaces: 3 scenes, .* exact proven 3/3" "$TMP/bench-exact.txt"; then
  pass
else
  fail "bench --exact: $(head -c 300 "$TMP/stderr.txt")"
fi
"$HSX" bench --exact-scenes 2 >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "--exact-scenes needs --exact" "$TMP/stderr.txt"; then pass; else fail "bench --exact-scenes without --exact: exit $rc"; fi
# ---- bench --campaign: the campaign runner's scenes per second on 1 and 2 threads, the records compared ----
if "$HSX" bench --campaign --campaign-halfspaces 2,3 --campaign-scenes 10 --campaign-time-limit 0 --repetitions 1 \
  --min-time 0 --json "$TMP/bench-campaign.json" >/dev/null 2>"$TMP/stderr.txt" &&
  python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
rows = d["rows"]
# one row per size and check list: every check, and every check but Props. 5.2 and 5.1
assert d["mode"] == "campaign" and [r["halfsp"] for r in rows] == [2, 2, 3, 3], rows
assert [r["input"].endswith("all checks") for r in rows] == [True, False, True, False], rows
for r in rows:
    assert [s["stage"] for s in r["stages"]] == ["jobs 1", "jobs 2"], r
    assert r["same"] == "yes" and r["timed out"] == "0/0" and float(r["scenes/s"]) > 0, r
' "$TMP/bench-campaign.json"; then
  pass
else
  fail "bench --campaign: $(head -c 300 "$TMP/stderr.txt")"
fi
"$HSX" bench --campaign --campaign-scenes 0 >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "--campaign-scenes: at least 1" "$TMP/stderr.txt"; then pass; else fail "bench --campaign --campaign-scenes 0: exit $rc"; fi
"$HSX" bench --campaign --campaign-checks nosuch >/dev/null 2>"$TMP/stderr.txt"
rc=$?
if ((rc == 2)) && grep -q -- "nosuch" "$TMP/stderr.txt"; then pass; else fail "bench --campaign --campaign-checks nosuch: exit $rc"; fi
# ---- arrange/extract --labels: cell and patch ids in the picture ----
if "$HSX" arrange "$ROOT/data/scenes/lens.json" --svg "$TMP/labels.svg" --labels -q &&
  grep -q 'class="cell-id"' "$TMP/labels.svg" && grep -q 'class="patch-id"' "$TMP/labels.svg"; then
  pass
else
  fail "arrange --labels: no ids in the picture"
fi
if "$HSX" extract "$ROOT/data/scenes/lens.json" --svg "$TMP/shape.svg" --labels -q &&
  grep -q 'class="cell-id"' "$TMP/shape.svg" && grep -q 'class="boundary"' "$TMP/shape.svg"; then
  pass
else
  fail "extract --svg --labels: no ids or no boundary in the picture"
fi

echo "$passed passed, $failed failed"
((failed == 0))
