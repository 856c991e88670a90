#!/usr/bin/env bash
# End-to-end tests of `hsx campaign` (issue 15 §1; docs/campaigns.md):
# - --list-checks names the fifteen checks (check_all's nine, the default, and the campaign's own six);
# - --sample-policy intended with --checks all: the same bytes for --jobs 1 and 2, the intended solid recorded,
#   prop61 / propB1 run (not skipped), the beam2/beam4 optimality tables; a resume with another policy is refused;
# - a campaign's results.jsonl, summary.json and table are the same bytes for --jobs 1 and --jobs 2, one line per
#   scene in index order, the table's counts add up;
# - shards 0/2 and 1/2 together are the whole campaign, line for line; one scene alone (--start K --count 1) is
#   the whole campaign's line K;
# - a campaign killed by SIGTERM (and one with a torn last line) resumed with --resume ends with the bytes of an
#   uninterrupted run;
# - a scene on which a check fails (scene 80 of seed 1 at 8 halfspaces: Prop. 5.1) exits 3 and is kept as a scene
#   file with its note, which `hsx check` reads and fails the same way;
# - --checks keeps the named checks only; --time-limit counts timed-out scenes instead of dropping them; the
#   arrangement limits record refused scenes;
# - bad options, foreign folders and mismatched resumes exit 2 and touch nothing.
# Usage: campaign_tests.sh HSX SOURCE_DIR. Prints "N passed, M failed" and exits non-zero when anything failed.
set -u
hsx="$(realpath "${1:?usage: campaign_tests.sh HSX SOURCE_DIR}")"; src="$(realpath "${2:?usage}")"
. "$src/tests/cli/common.sh"

same() {  # same A B WHAT: byte-identical files
  if cmp -s "$1" "$2"; then ok; else bad "$3: $1 and $2 differ: $(cmp "$1" "$2" 2>&1 | head -c 200)"; fi
}
lines() { wc -l <"$1" | tr -d ' '; }

gen=(--seed 11 --halfspaces 2..6 --samples 6)

# ---- --list-checks ----
expect 0 "" -- "$hsx" campaign --list-checks
for name in existence prop52 prop51 beam1 prop41-optimum prop41-beam uniqueness certificates manifold \
    prop61 propB1 beam2 beam4 describability nhrep; do
  if grep -qE "^$name " out; then ok; else bad "--list-checks lacks $name: $(head -c 300 out)"; fi
done

# ---- determinism across jobs ----
expect 0 "" -- "$hsx" campaign "${gen[@]}" --count 40 --out j1 --jobs 1 && cp out j1.txt
expect 0 "" -- "$hsx" campaign "${gen[@]}" --count 40 --out j2 --jobs 2 && cp out j2.txt
same j1/results.jsonl j2/results.jsonl "--jobs 1 vs 2 results.jsonl"
same j1/summary.json j2/summary.json "--jobs 1 vs 2 summary.json"
same j1/campaign.json j2/campaign.json "--jobs 1 vs 2 campaign.json"
same j1.txt j2.txt "--jobs 1 vs 2 table"
if [ "$(lines j1/results.jsonl)" = 40 ]; then ok; else bad "40 scenes gave $(lines j1/results.jsonl) lines"; fi
if [ "$(jq -r .index j1/results.jsonl | tr '\n' ' ')" = "$(seq 0 39 | tr '\n' ' ')" ]; then ok; else
  bad "results.jsonl is not in index order"; fi
if [ "$(jq -c 'keys_unsorted[:3]' j1/results.jsonl | sort -u)" = '["index","seed","halfspaces"]' ]; then ok; else
  bad "a line does not start with index, seed, halfspaces"; fi
if [ "$(jq '.checks | length' j1/results.jsonl | sort -u)" = 9 ]; then ok; else bad "not every line has 9 checks"; fi
# summary.json: every check's counts add up to the scenes, by number of halfspaces too.
if jq -e '.scenes == 40 and ([.checks[] | .held + .failed + .skipped + .stopped] | unique) == [40]
          and ([.checks[] | ([.by_halfspaces[] | .held + .failed + .skipped + .stopped] | add)] | unique) == [40]
          and .format == "hsx-campaign-summary/1"' j1/summary.json >/dev/null; then ok; else
  bad "summary.json counts do not add up: $(head -c 300 j1/summary.json)"; fi
# The table's "all" row of prop52 agrees with summary.json and with the lines.
held_lines="$(jq -r '.checks[] | select(.check == "prop52") | .status' j1/results.jsonl | grep -c '^held$')"
held_summary="$(jq '.checks[] | select(.check == "prop52") | .held' j1/summary.json)"
held_table="$(awk '/^prop52:/ {p = 1} p && $1 == "all" {print $3; exit}' j1.txt)"
if [ "$held_lines" = "$held_summary" ] && [ "$held_lines" = "$held_table" ]; then ok; else
  bad "prop52 held: lines $held_lines, summary.json $held_summary, table $held_table"; fi
has j1.txt "40 scenes: 40 checked" "the table's first line"
has j1.txt "beam1 optimality: the K=1 beam's energy equals the optimum" "the beam1 optimality table"
if jq -e '.beam1_optimality.optimal + .beam1_optimality.sub_optimal == (.checks[] | select(.check == "beam1") | .held)' \
  j1/summary.json >/dev/null; then ok; else bad "beam1_optimality does not count the scenes where beam1 held"; fi
optimal_lines="$(jq -r '.checks[] | select(.check == "beam1" and .status == "held") | .witness' j1/results.jsonl | grep -c '^optimal:')"
if [ "$optimal_lines" = "$(jq .beam1_optimality.optimal j1/summary.json)" ]; then ok; else
  bad "beam1_optimality.optimal is not the lines' optimal witnesses ($optimal_lines)"; fi
has err "40 scenes run in" "the throughput line on stderr"

# ---- shards and single scenes ----
expect 0 "" -- "$hsx" campaign "${gen[@]}" --count 40 --shard 0/2 --out s0 --jobs 2
expect 0 "" -- "$hsx" campaign "${gen[@]}" --count 40 --shard 1/2 --out s1
cat s0/results.jsonl s1/results.jsonl | sort -t: -k2 -n >merged.jsonl
same merged.jsonl j1/results.jsonl "shards 0/2 + 1/2 = the whole campaign"
expect 0 "merged 2 shards" -- "$hsx" campaign --out merged --merge s0 s1
same merged/results.jsonl j1/results.jsonl "--merge s0 s1 = the whole campaign's results.jsonl"
same merged/summary.json j1/summary.json "--merge s0 s1 = the whole campaign's summary.json"
if [ "$(jq -r .index s1/results.jsonl | head -3 | tr '\n' ' ')" = "1 3 5 " ]; then ok; else bad "shard 1/2 is not the odd indices"; fi
expect 0 "" -- "$hsx" campaign "${gen[@]}" --start 17 --count 1 --out one
if [ "$(cat one/results.jsonl)" = "$(sed -n 18p j1/results.jsonl)" ]; then ok; else bad "scene 17 alone differs from the campaign's"; fi

# ---- resume ----
# A torn last line: the first 13 lines and half of the 14th.
mkdir torn && cp j1/campaign.json torn/
head -n 13 j1/results.jsonl >torn/results.jsonl
sed -n 14p j1/results.jsonl | head -c 150 >>torn/results.jsonl
expect 0 "a torn last line was cut off" -- "$hsx" campaign "${gen[@]}" --count 40 --out torn --resume --jobs 2
same torn/results.jsonl j1/results.jsonl "resumed after a torn line"
same torn/summary.json j1/summary.json "resumed summary.json"
same out j1.txt "resumed table"
# A real kill: SIGTERM while it runs, then --resume.
big=(--seed 5 --halfspaces 2..6 --samples 6 --count 200)
"$hsx" campaign "${big[@]}" --out killed --jobs 2 >/dev/null 2>&1 &
pid=$!
sleep 0.7
kill -TERM "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
done_lines="$(lines killed/results.jsonl)"
[ -e killed/summary.json ] && echo "note: the campaign finished before it was killed ($done_lines lines)"
expect 0 "resumed killed" -- "$hsx" campaign "${big[@]}" --out killed --resume
expect 0 "" -- "$hsx" campaign "${big[@]}" --out whole --jobs 2
same killed/results.jsonl whole/results.jsonl "killed after $done_lines scenes and resumed"
same killed/summary.json whole/summary.json "killed and resumed: summary.json"
# Resuming a finished campaign runs nothing and writes the same summary.
expect 0 "200 of 200 scenes were done" -- "$hsx" campaign "${big[@]}" --out whole --resume
same killed/results.jsonl whole/results.jsonl "a finished campaign resumed"

# ---- selections, time limits, refusals ----
expect 0 "" -- "$hsx" campaign "${gen[@]}" --count 5 --checks manifold,existence --out sel
if [ "$(jq -c '[.checks[].check]' sel/results.jsonl | sort -u)" = '["existence","manifold"]' ]; then ok; else
  bad "--checks manifold,existence: $(head -c 300 sel/results.jsonl)"; fi
if [ "$(jq -c '[.checks[].check]' sel/summary.json)" = '["existence","manifold"]' ]; then ok; else bad "--checks: summary.json"; fi
expect 0 "" -- "$hsx" campaign "${gen[@]}" --count 6 --time-limit 0.000000001 --out late
if [ "$(jq -r .timed_out late/results.jsonl | sort -u)" = true ]; then ok; else bad "--time-limit: not every scene timed out"; fi
if [ "$(jq .timed_out late/summary.json)" = 6 ]; then ok; else bad "--time-limit: summary.json does not count 6 timed out"; fi
has out "6 timed out" "--time-limit: the table counts timed-out scenes"
if [ "$(jq '[.checks[] | .stopped + .skipped] | add' late/summary.json)" -ge 30 ]; then ok; else
  bad "--time-limit: checks cut short are not reported as stopped or skipped"; fi
expect 0 "" -- "$hsx" campaign "${gen[@]}" --count 4 --max-cells 1 --out refused
if [ "$(jq -r .outcome refused/results.jsonl | sort -u)" = refused ] &&
  [ "$(jq -r '.checks[].status' refused/results.jsonl | sort -u)" = skipped ]; then ok; else
  bad "--max-cells 1: scenes not recorded as refused with skipped checks"; fi
has out "4 refused by the arrangement limits" "--max-cells 1: the table"
# 1000 halfspaces: the generator's own arrangement (to choose samples) is refused; recorded, not an error.
expect 0 "" -- "$hsx" campaign --count 1 --halfspaces 1000 --out huge
if [ "$(jq -r .outcome huge/results.jsonl)" = refused ] && jq -r .note huge/results.jsonl | grep -q "^choosing its samples"; then
  ok; else bad "1000 halfspaces: $(head -c 300 huge/results.jsonl)"; fi

# ---- a failing scene is kept (scene 80 of seed 1 at 8 halfspaces: Prop. 5.1 fails at its non-generic junctions) ----
expect 3 "" -- "$hsx" campaign --seed 1 --halfspaces 8 --start 79 --count 3 --out fails --jobs 2
has out "hsx campaign --seed 1, scene 80: failed prop51: " "the failing scene's note on stdout"
has out "3 scenes: 3 checked, 0 refused by the arrangement limits, 0 errors; 0 timed out; 1 with a failed check" \
  "the table counts the failing scene"
if [ "$(ls fails/failures | tr "\n" " ")" = "scene-80.json scene-80.min.json " ]; then ok; else bad "failures/: $(ls fails/failures)"; fi
if [ "$(jq -r '.checks[] | select(.check == "prop51") | .status' fails/results.jsonl | tr '\n' ' ')" = "held failed held " ]; then
  ok; else bad "prop51 statuses of scenes 79..81"; fi
if jq -r .description fails/failures/scene-80.json | grep -q "^hsx campaign --seed 1, scene 80: failed prop51: state "; then ok; else
  bad "the kept scene's note: $(jq -r .description fails/failures/scene-80.json | head -c 300)"; fi
expect 3 "" -- "$hsx" check fails/failures/scene-80.json
has out "Prop. 5.1 (removable sets)                                             FAIL" "hsx check on the kept scene"
if [ "$(jq '.failed_scenes' fails/summary.json)" = 1 ] &&
  [ "$(jq '.checks[] | select(.check == "prop51") | .failed' fails/summary.json)" = 1 ]; then ok; else
  bad "summary.json does not count the failure"; fi
# Not selected, the failing check neither fails the scene nor keeps it.
expect 0 "" -- "$hsx" campaign --seed 1 --halfspaces 8 --start 80 --count 1 --checks prop52,manifold --out notsel
if [ ! -e notsel/failures ]; then ok; else bad "--checks without prop51 still kept scene 80"; fi

# ---- bad options and folders: exit 2, nothing touched ----
expect 2 "--count" -- "$hsx" campaign --seed 1
expect 2 "--seed" -- "$hsx" campaign --count 3 --seed -1
expect 2 "--count" -- "$hsx" campaign --count -5
expect 2 "--count: at most" -- "$hsx" campaign --count 100000001
expect 2 "--start" -- "$hsx" campaign --count 2 --start 18446744073709551615
expect 2 "--start" -- "$hsx" campaign --count 1 --start 18446744073709551616
expect 2 "--halfspaces" -- "$hsx" campaign --count 3 --halfspaces 5..2
expect 2 "--halfspaces" -- "$hsx" campaign --count 3 --halfspaces two
expect 2 "--halfspaces" -- "$hsx" campaign --count 3 --halfspaces 0..3
expect 2 "--shard" -- "$hsx" campaign --count 3 --shard 2/2
expect 2 "--shard" -- "$hsx" campaign --count 3 --shard 1
expect 2 "unknown check \"prop99\"" -- "$hsx" campaign --count 3 --checks prop52,prop99
expect 2 "--kinds" -- "$hsx" campaign --count 3 --kinds square
expect 2 "--jobs" -- "$hsx" campaign --count 3 --jobs 0
expect 2 "--resume: needs --out" -- "$hsx" campaign --count 3 --resume
expect 2 "--degeneracy-weights" -- "$hsx" campaign --count 3 --degeneracy-weights Tangles=2
expect 2 "" -- "$hsx" campaign --count 3 --time-limit -1
expect 2 "generator settings" -- "$hsx" campaign --count 3 --denominator 0
expect 2 "" -- "$hsx" campaign --count 3 --out ""
expect 2 "--out: a folder, not -" -- "$hsx" campaign --count 3 --out -
mkdir theirs && echo "their notes" >theirs/notes.txt
expect 2 "not empty and holds no campaign" -- "$hsx" campaign --count 3 --out theirs
expect 2 "not empty and holds no campaign" -- "$hsx" campaign --count 3 --out theirs --resume
if [ "$(ls theirs)" = notes.txt ] && [ "$(cat theirs/notes.txt)" = "their notes" ]; then ok; else bad "a foreign folder was touched"; fi
echo data >afile
expect 2 "is not a folder" -- "$hsx" campaign --count 3 --out afile
expect 2 "does not exist" -- "$hsx" campaign --count 3 --out no/such/folder
cp j1/results.jsonl j1.keep
expect 2 "holds a campaign already" -- "$hsx" campaign "${gen[@]}" --count 40 --out j1
expect 2 "other settings" -- "$hsx" campaign "${gen[@]}" --count 41 --out j1 --resume
expect 2 "other settings" -- "$hsx" campaign "${gen[@]}" --count 40 --checks prop52 --out j1 --resume
same j1/results.jsonl j1.keep "a refused resume left results.jsonl alone"

# ---- the intended-shape sample policy and the campaign's own checks ----
expect 0 "" -- "$hsx" campaign "${gen[@]}" --count 12 --sample-policy intended --checks all --out i1 --jobs 1 && cp out i1.txt
expect 0 "" -- "$hsx" campaign "${gen[@]}" --count 12 --sample-policy intended --checks all --out i2 --jobs 2 && cp out i2.txt
same i1/results.jsonl i2/results.jsonl "intended, --jobs 1 vs 2 results.jsonl"
same i1.txt i2.txt "intended, --jobs 1 vs 2 table"
if [ "$(jq -r .generator.sample_policy i1/campaign.json)" = intended ]; then ok; else bad "campaign.json lacks the policy"; fi
if [ "$(jq -s '[.[] | select(.intended)] | length' i1/results.jsonl)" -ge 8 ]; then ok; else
  bad "few intended solids recorded: $(head -c 300 i1/results.jsonl)"; fi
if [ "$(jq -s '[.[].checks[] | select((.check == "prop61" or .check == "propB1") and .status == "skipped")] | length' \
      i1/results.jsonl)" = 0 ]; then ok; else bad "prop61/propB1 skipped under the intended policy"; fi
if [ "$(jq -c '[.checks[].check]' i1/summary.json)" = \
     '["existence","prop52","prop51","beam1","prop41-optimum","prop41-beam","uniqueness","certificates","manifold","prop61","propB1","beam2","beam4","describability","nhrep"]' ]
then ok; else bad "--checks all: summary.json's checks $(jq -c '[.checks[].check]' i1/summary.json)"; fi
if jq -e '.beam2_optimality.optimal + .beam2_optimality.sub_optimal == 12 and (.beam4_optimality | type) == "object"' \
     i1/summary.json >/dev/null; then ok; else bad "beam2/beam4 optimality in summary.json: $(head -c 400 i1/summary.json)"; fi
if grep -q "^beam4 optimality: the K=4 beam" i1.txt; then ok; else bad "the table lacks beam4 optimality"; fi
expect 2 "other settings" -- "$hsx" campaign "${gen[@]}" --count 12 --checks all --out i1 --resume
expect 2 "--sample-policy: uniform or intended" -- "$hsx" campaign --count 3 --sample-policy shaped
# Under the default (uniform) policy prop61 is skipped with why; the default set is check_all's nine.
expect 0 "" -- "$hsx" campaign "${gen[@]}" --count 2 --checks prop61 --out u1
if grep -q '"status":"skipped","witness":"not run: no intended shape' u1/results.jsonl; then ok; else
  bad "prop61 under the uniform policy: $(head -c 300 u1/results.jsonl)"; fi
if [ "$(jq -c '.checks | length' j1/campaign.json)" = 9 ]; then ok; else bad "the default checks are not nine"; fi

# ---- --beam-widths: beam checks of the user's widths ----
expect 0 "" -- "$hsx" campaign "${gen[@]}" --count 6 --checks existence --beam-widths 1,8,2 --out bw --jobs 2 && cp out bw.txt
if [ "$(jq -c '[.checks[].check]' bw/results.jsonl | sort -u)" = '["existence","beam1","beam2","beam8"]' ]; then ok; else
  bad "--beam-widths 1,8,2: checks $(jq -c '[.checks[].check]' bw/results.jsonl | sort -u)"; fi
if jq -e '.beam8_optimality.optimal + .beam8_optimality.sub_optimal > 0 and (.beam1_optimality | type) == "object"' \
     bw/summary.json >/dev/null; then ok; else bad "--beam-widths: beam8_optimality in summary.json"; fi
has bw.txt "beam8 optimality: the K=8 beam" "--beam-widths: the table"
expect 0 "" -- "$hsx" campaign --list-checks && has out "beamK" "--list-checks names beamK"
expect 2 "--beam-widths" -- "$hsx" campaign --count 2 --beam-widths 0

# ---- 3D campaigns (--dimension 3: algorithms/campaign/scene3.hpp) ----
gen3=(--dimension 3 --seed 4 --primitives 1..2 --segments 6 --samples 4 --degeneracies 1..2 --max-cells 40)
expect 0 "" -- "$hsx" campaign "${gen3[@]}" --count 6 --sample-policy intended --checks all --out d1 --jobs 1 && cp out d1.txt
expect 0 "" -- "$hsx" campaign "${gen3[@]}" --count 6 --sample-policy intended --checks all --out d2 --jobs 2 && cp out d2.txt
same d1/results.jsonl d2/results.jsonl "3D, --jobs 1 vs 2 results.jsonl"
same d1/summary.json d2/summary.json "3D, --jobs 1 vs 2 summary.json"
same d1.txt d2.txt "3D, --jobs 1 vs 2 table"
if [ "$(jq .dimension d1/campaign.json)" = 3 ] && [ "$(jq .generator.segments d1/campaign.json)" = 6 ]; then ok; else
  bad "3D campaign.json: $(head -c 300 d1/campaign.json)"; fi
if [ "$(jq '.checks | length' d1/results.jsonl | sort -u)" = 15 ]; then ok; else bad "3D: not every line has 15 checks"; fi
if [ "$(jq -s '[.[] | select(.intended)] | length' d1/results.jsonl)" -ge 3 ]; then ok; else
  bad "3D: few intended solids recorded"; fi
if [ "$(jq -s '[.[] | select(.outcome == "checked")] | length' d1/results.jsonl)" -ge 3 ]; then ok; else
  bad "3D: few scenes checked"; fi
if [ -f d1/summary.svg ]; then ok; else bad "3D: no summary.svg"; fi
expect 0 "" -- "$hsx" campaign "${gen3[@]}" --count 6 --sample-policy intended --checks all --shard 1/2 --out d3
if [ "$(cat d3/results.jsonl)" = "$(sed -n '2p;4p;6p' d1/results.jsonl)" ]; then ok; else bad "3D shard 1/2 differs"; fi
expect 2 "--kinds: a 2D option" -- "$hsx" campaign --dimension 3 --count 2 --kinds disk
expect 2 "--primitives: a 3D option" -- "$hsx" campaign --count 2 --primitives 2
expect 2 "--against: a 2D option" -- "$hsx" campaign --dimension 3 --count 2 --against 'true {input} {output}'
expect 2 "--degeneracy-weights" -- "$hsx" campaign --dimension 3 --count 2 --degeneracy-weights ConcurrentLines=1
expect 2 "segments" -- "$hsx" campaign --dimension 3 --count 2 --segments 4
expect 2 "--dimension: 2 or 3" -- "$hsx" campaign --dimension 4 --count 2
expect 2 "other settings" -- "$hsx" campaign "${gen3[@]/--segments/--max-draws}" --count 6 --sample-policy intended --checks all --out d1 --resume

finish
