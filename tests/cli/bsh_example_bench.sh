#!/usr/bin/env bash
# hsx bench --bsh-example (issue 13, section 4): one repetition on figure15_a of the BSH authors' examples, end to
# end (arrangement + K = 1 beam), the certified cut beside the double cut, the complete searches and peak memory in
# one row; a folder without config.json is a skipped row; the mode excludes the others. Skipped (77) without the
# data (HSX_BSH_DATA, default ../shared/data/bsh-examples).
# Usage: bsh_example_bench.sh HSX SOURCE_DIR
set -u
hsx="$(realpath "${1:?usage: bsh_example_bench.sh HSX SOURCE_DIR}")"; src="$(realpath "${2:?usage}")"
source "$src/tests/cli/common.sh"
bsh_examples figure15_a/config.json

expect 0 "" -- "$hsx" bench --bsh-example "$data/figure15_a" "$work/absent" --repetitions 1 --min-time 0 \
  --time-limit 30 --json "$work/b.json"
has "$work/out" "K=1 e2e" "the table's stages"
has "$work/out" "skipped: no $work/absent/config.json" "a folder without config.json"
python3 - "$work/b.json" <<'PY' >"$work/check.txt"
import json, sys
b = json.load(open(sys.argv[1]))
problems = []
if b["mode"] != "bsh-examples": problems.append("mode %s" % b["mode"])
rows = b["rows"]
if len(rows) != 2 or rows[0]["input"] != "figure15_a" or "skipped" not in rows[1]: problems.append("rows %s" % rows)
r = rows[0]
names = [s["stage"] for s in r["stages"]]
if names != ["arrange", "K=1 search", "K=1 e2e", "cert. cut", "double BK", "exact", "best-first"]:
    problems.append("stages %s" % names)
if any(s["status"] != "ok" or s["repetitions"] < 1 for s in r["stages"]): problems.append("a stage was not timed")
t = {s["stage"]: s["median_s"] for s in r["stages"]}
if not t["K=1 e2e"] >= t["K=1 search"]: problems.append("end to end below the search alone")
if r["cells"] != 13 or r["patches"] != 20: problems.append("cells %s patches %s" % (r["cells"], r["patches"]))
if r["exact"] != "optimal": problems.append("exact: %s" % r["exact"])
if r["beam = opt"] != "yes": problems.append("the K = 1 beam is not optimal on figure15_a")
if r["cut cert."] != "yes": problems.append("cut not certified")
if not r["bf states"].endswith("(done)"): problems.append("best-first did not finish: %s" % r["bf states"])
if r["theirs e2e"] != "-": problems.append("authors' figures for figure15_a: %s" % r["theirs e2e"])
if not 0 < float(r["peak MB"]) < 1024: problems.append("peak memory %s MB" % r["peak MB"])
print("\n".join(problems))
PY
[ -z "$(cat "$work/check.txt")" ] && ok || bad "bench --bsh-example: $(cat "$work/check.txt")"

expect 2 "needs a positive number of seconds" -- "$hsx" bench --bsh-example "$data/figure15_a" --time-limit 0
expect 2 "exclude each other" -- "$hsx" bench --bsh-example "$data/figure15_a" --cuts
expect 2 "does not apply to --bsh-example" -- "$hsx" bench --bsh-example "$data/figure15_a" --brute-force-limit 5
finish
