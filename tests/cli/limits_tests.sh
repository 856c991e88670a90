#!/usr/bin/env bash
# Limits that hold and answers that are not wrong (issue 10, §3 and §4): brute force's labelling limit and time
# limit, graph-cut limits, check's limits and its stopped/skipped checks, ties cut by a limit, result identity,
# options that do not apply. Each case: the command, its exit status, a fragment of its message.
# Usage: limits_tests.sh HSX SOURCE_DIR
set -u
hsx="$(realpath "${1:?usage: limits_tests.sh HSX SOURCE_DIR}")"; src="$(realpath "${2:?usage}")"
lens="$src/data/scenes/lens.json"; star="$src/data/scenes/star.json"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
cd "$work"
passed=0; failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }
# expect STATUS FRAGMENT -- COMMAND...: exit status and a fragment of stderr+stdout ("" for none); 60 s at most.
expect() {
  local want="$1" fragment="$2"; shift 3
  timeout 60 "$@" >"$work/out" 2>&1 </dev/null; local got=$?
  if [ "$got" -ne "$want" ]; then bad "$* exited $got, expected $want: $(head -c 400 "$work/out")"; return 1; fi
  if [ -n "$fragment" ] && ! grep -qF -- "$fragment" "$work/out"; then bad "$*: output lacks '$fragment': $(head -c 400 "$work/out")"; return 1; fi
  ok
}
# json FILE PYTHON-EXPRESSION-ON-d: a property of a JSON document.
json() {
  if python3 -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if ($2) else 1)" "$1"; then ok; else bad "$1: not ($2)"; fi
}

# K rooms side by side, each the Fig. 6 tie (two optimal boundaries of equal energy): 2^K optimal boundaries, 5^K
# orientation-preserving labellings, 2K cells (the outer rooms) whose labels are independent.
rooms() {
  python3 - "$1" "$2" <<'PY'
import json, sys
k = int(sys.argv[1]); hs = []; samples = []
for j in range(k):
    x = 10 * j
    hs.append({"name": f"R{j}", "kind": "polygon", "vertices": [[x, 0], [x + 6, 0], [x + 6, 2], [x, 2]]})
    hs.append({"name": f"L{j}", "kind": "halfplane", "normal": [1, 0], "offset": x + 2})
    hs.append({"name": f"G{j}", "kind": "halfplane", "normal": [-1, 0], "offset": -(x + 4)})
    for at in ([x, 1], [x + 6, 1], [x + 1, 2], [x + 5, 2], [x + 1, 0], [x + 5, 0], [x + 3, 2], [x + 3, 0]):
        samples.append({"on": f"R{j}", "at": at})
    samples += [{"on": f"L{j}", "at": [x + 2, 1]}, {"on": f"G{j}", "at": [x + 4, 1]}]
json.dump({"format": "hsx-scene/1", "dimension": 2, "domain": {"min": [-2, -2], "max": [10 * k, 4]},
           "halfspaces": hs, "samples": samples}, open(sys.argv[2], "w"))
PY
}
rooms 5 rooms5.json
rooms 11 rooms11.json

# Brute force: more labellings than --max-labellings is bad input (exit 2) naming the limit and the option, refused
# before enumerating when 2^k independent cells prove it, else after counting; never an internal error.
expect 2 "at least 2^7 orientation-preserving labellings" -- "$hsx" extract rooms5.json -q --method brute-force --max-labellings 100
grep -qF -- "--max-labellings" out && ok || bad "the labelling limit's message does not name --max-labellings"
expect 2 "more than 2000 orientation-preserving labellings; the limit is 2000" -- \
  "$hsx" extract rooms5.json -q --method brute-force --max-labellings 2000
expect 0 "" -- "$hsx" extract rooms5.json -q --method brute-force --max-labellings 3125 --json bf.json
json bf.json "d['optimal'] and d['ties']['count'] == 32 and d['stats']['labellings_enumerated'] == 3125"
expect 2 "--max-labellings" -- "$hsx" extract rooms5.json -q --method brute-force --max-labellings 0
# ... and honours --time-limit: 5^11 labellings take about half a minute (docs/limits.md), the limit stops it with
# the best found so far.
start=$(date +%s)
expect 0 "" -- "$hsx" extract rooms11.json -q --method brute-force --max-labellings 100000000 --time-limit 0.5 --json bf11.json
[ $(( $(date +%s) - start )) -le 20 ] && ok || bad "brute force --time-limit 0.5 took $(( $(date +%s) - start )) s"
json bf11.json "not d['optimal'] and d['stopped_by'] == 'time-limit' and not d['ties']['checked']"

# Deterministic limits: --max-graph-cuts stops the search at exactly N cuts.
expect 0 "stopped by max-graph-cuts" -- "$hsx" extract "$lens" --method best-first --max-graph-cuts 1 --json g.json
json g.json "d['stopped_by'] == 'max-graph-cuts' and d['stats']['graph_cuts'] == 1 and not d['optimal']"
expect 2 "--max-graph-cuts" -- "$hsx" extract "$lens" -q --max-graph-cuts -1
expect 0 "machine" -- "$hsx" extract --help   # --help says a time limit makes the result machine-dependent

# A limit that cuts only the tie enumeration leaves the optimum proven and says the ties are incomplete.
expect 0 "enumeration stopped by max-graph-cuts" -- "$hsx" extract rooms5.json --method best-first --max-graph-cuts 10 --json t.json
json t.json "d['optimal'] and 'stopped_by' not in d and d['ties']['capped'] and d['ties']['stopped_by'] == 'max-graph-cuts'"
expect 0 "16+" -- "$hsx" extract rooms5.json --method best-first --json t.json
json t.json "d['optimal'] and d['ties']['count'] == 16 and d['ties']['capped'] and d['ties']['stopped_by'] == 'max-ties'"

# check: Prop. 5.2 compares tie counts only as far as the cap allows (32 ties, best-first stops at 16).
expect 0 "ties 16+ (best-first stopped by max-ties) of 32" -- "$hsx" check rooms5.json --json c.json
json c.json "d['passed'] and d['checks'][1]['status'] == 'pass'"
# check has extract's limits; a check they cut short is "stopped", one they leave no room for "skipped".
# --max-states is also the exact search's node limit (the optimum of the beam, Prop. 4.1 and uniqueness checks).
expect 0 "stopped  exact stopped by max-nodes" -- "$hsx" check "$lens" --max-states 2 --json c.json
json c.json "d['passed'] and not d['complete'] and any(c['status'] == 'stopped' for c in d['checks'])"
expect 0 "best-first stopped by max-graph-cuts" -- "$hsx" check "$lens" --max-graph-cuts 1 --json c.json
json c.json "d['passed'] and not d['complete']"
# Where brute force is too large, Prop. 5.2 is checked against the exact branch and bound instead.
expect 0 "Prop. 5.2 (best-first = exact branch and bound; brute force too large) pass" -- \
  "$hsx" check rooms5.json --max-labellings 100
expect 2 "--time-limit" -- "$hsx" check "$lens" --time-limit nan
expect 2 "--max-states" -- "$hsx" check "$lens" --max-states -1
expect 0 "" -- "$hsx" check "$lens" --brute-force-limit 100000   # the old name still works

# Result identity: a result names cells of the input it came from, and only that input accepts it.
expect 0 "" -- "$hsx" extract "$lens" -q --json lensr.json
expect 0 "" -- "$hsx" extract "$star" -q --json starr.json
expect 0 "" -- "$hsx" arrange "$lens" -q --json lensc.json
expect 2 "computed from another scene or complex" -- "$hsx" describe "$lens" --shape starr.json
expect 2 "computed from another scene or complex" -- "$hsx" csg "$lens" --shape starr.json
expect 2 "computed from another scene or complex" -- "$hsx" samples "$lens" --target starr.json
expect 2 "computed from another scene or complex" -- "$hsx" nhtree "$lens" --shape starr.json
# Accepted (exit 0 describable or 3 not) by its own scene and by that scene's hsx-complex/1 document.
for input in "$lens" lensc.json; do
  timeout 60 "$hsx" describe "$input" --shape lensr.json >/dev/null 2>&1; rc=$?
  [ "$rc" -eq 0 ] || [ "$rc" -eq 3 ] && ok || bad "describe $input refuses its own result (exit $rc)"
done
python3 -c "import json; d=json.load(open('lensr.json')); del d['complex_id']; json.dump(d, open('anon.json','w'))"
expect 2 "complex_id: missing" -- "$hsx" describe "$lens" --shape anon.json
# Result-file errors name the path once.
echo '{' >broken.json
expect 2 "broken.json: line" -- "$hsx" describe "$lens" --shape broken.json
[ "$(grep -o 'broken.json' out | wc -l)" -eq 1 ] && ok || bad "the path is printed more than once: $(cat out)"
mkdir adir
expect 2 "cannot read \"adir\": it is a directory" -- "$hsx" describe "$lens" --shape adir
[ "$(grep -o 'adir' out | wc -l)" -eq 1 ] && ok || bad "the path is printed more than once: $(cat out)"

# Options that do not apply are refused, not ignored.
mesh="$src/data/meshes/lprism.obj"; fea="$src/data/meshes/lprism_open_corner.fea"
expect 2 "--csg gives a solid on a scene" -- "$hsx" nhtree "$mesh" --fea "$fea" --csg "A"
expect 2 "--shape gives a solid on a scene" -- "$hsx" nhtree "$mesh" --fea "$fea" --shape lensr.json
expect 2 "--reference" -- "$hsx" nhtree "$lens" --csg "A" --reference "$work/x.conf"
expect 2 "is a directory" -- "$hsx" nhtree "$mesh" --fea "$fea" --reference "$work/adir"
grep -q "too large" out && bad "a directory as --reference is called too large" || ok

# Vertex policy (docs/scene-format.md): a sample where two boundaries cross is refused, one on a corner of its own
# polygon that nothing else passes through lies inside one patch and is accepted.
cat >corner.json <<'JSON'
{"format": "hsx-scene/1", "dimension": 2,
 "halfspaces": [{"name": "P", "kind": "polygon", "vertices": [[0, 0], [4, 0], [4, 3]]},
                {"name": "Q", "kind": "polygon", "vertices": [[2, -1], [6, -1], [6, 1], [2, 1]]}],
 "samples": [{"on": "P", "at": [0, 0]}, {"on": "P", "at": [2, 0]}]}
JSON
expect 2 "samples[1] (on \"P\"): lies on an arrangement vertex [2, 0] where boundaries meet" -- "$hsx" arrange corner.json -q
python3 -c "import json; d=json.load(open('corner.json')); d['samples'].pop(); json.dump(d, open('corner0.json','w'))"
expect 0 "" -- "$hsx" arrange corner0.json -q

# Messages: plurals spelled right ("patches", "vertices", not "patchs", "vertexs").
python3 -c "
import json; d = json.load(open('lensc.json')); d['supports'][0] = [9999]; json.dump(d, open('badp.json', 'w'))
d = json.load(open('lensc.json')); d['junctions'][0]['vertex'] = 9999; json.dump(d, open('badv.json', 'w'))"
expect 2 "supports[0][0]: patch 9999 is out of range (there are" -- "$hsx" extract badp.json -q
grep -q " patches)" out && ok || bad "plural of patch: $(cat out)"
expect 2 "junctions[0].vertex: vertex 9999 is out of range (there are" -- "$hsx" extract badv.json -q
grep -q " vertices)" out && ok || bad "plural of vertex: $(cat out)"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
