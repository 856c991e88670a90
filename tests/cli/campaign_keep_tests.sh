#!/usr/bin/env bash
# What `hsx campaign` keeps and shows (issue 15 §1, §3; docs/campaigns.md, docs/campaigns-cluster.md):
# - --merge: shards 0/3, 1/3, 2/3 merged (given in any order) are the folder of one run of the whole range, byte
#   for byte (campaign.json, results.jsonl, summary.json, summary.svg, failures/) with the same table and exit
#   status, on a campaign with a real failure too; missing, repeated, unfinished and foreign shards, and an
#   existing output folder, exit 2 and leave no output;
# - a failing scene is minimised into failures/scene-K.min.json (fewer halfspaces, its note, `hsx check` fails it
#   the same way); the same bytes for --jobs 1 and 2; --no-minimise writes no .min.json and the same records;
# - a failing 3D scene is minimised too (fewer halfspaces, segments lowered; `hsx check` fails it the same way;
#   the same bytes when run again);
# - a scene refused while generating it is tallied under its halfspace count, not under 0 (2D and 3D);
# - summary.svg is written with summary.json, parses as XML, has a panel per check, and changes with the rates.
# Usage: campaign_keep_tests.sh HSX. Prints "N passed, M failed" and exits non-zero when anything failed.
set -u
HSX="$(realpath "${1:?usage: campaign_keep_tests.sh HSX}")"
source "$(dirname "${BASH_SOURCE[0]}")/testlib.sh"
testlib_init campaign-keep
cd "$TMP" || exit 1

same() {  # same A B WHAT: identical files or folders
  if diff -r "$1" "$2" >diff.txt 2>&1; then pass; else fail "$3: $(head -c 600 diff.txt)"; fi
}

# ---- merging shards: no failure ----
GEN=(--seed 11 --halfspaces 2..5 --samples 6 --count 30)
expect_status 0 "the whole range" "$HSX" campaign "${GEN[@]}" --out whole
cp out.txt whole.txt
for i in 0 1 2; do expect_status 0 "shard $i/3" "$HSX" campaign "${GEN[@]}" --shard $i/3 --out s$i; done
expect_status 0 "--merge" "$HSX" campaign --out merged --merge s2 s0 s1
same whole merged "the merged shards and the whole range's folder"
same whole.txt out.txt "the merged table"
grep -q "merged 3 shards" err.txt && pass || fail "--merge: no message on stderr: $(cat err.txt)"

# ---- refusals: exit 2, no output folder ----
expect_status 2 "missing shard" "$HSX" campaign --out m1 --merge s0 s1
grep -q "missing shards 2/3" err.txt && pass || fail "missing shard: $(cat err.txt)"
expect_status 2 "a shard twice" "$HSX" campaign --out m2 --merge s0 s1 s1 s2
grep -q "given twice" err.txt && pass || fail "a shard twice: $(cat err.txt)"
cp -r s1 s1cut
head -n 3 s1/results.jsonl >s1cut/results.jsonl
expect_status 2 "an unfinished shard" "$HSX" campaign --out m3 --merge s0 s1cut s2
grep -q "has 3 of its 10 scenes (7 missing, the first is scene 10): finish it with --resume" err.txt && pass ||
  fail "an unfinished shard: $(cat err.txt)"
expect_status 0 "another campaign's shard" "$HSX" campaign --seed 12 --halfspaces 2..5 --samples 6 --count 30 --shard 1/3 --out other
expect_status 2 "another campaign's shard" "$HSX" campaign --out m4 --merge s0 other s2
grep -q "is not the same campaign" err.txt && grep -q "seed" err.txt && pass || fail "another campaign: $(cat err.txt)"
expect_status 2 "not a campaign" "$HSX" campaign --out m5 --merge s0 s1 nowhere
expect_status 2 "--merge without --out" "$HSX" campaign --merge s0 s1 s2
for d in m1 m2 m3 m4 m5; do [[ ! -e $d ]] && pass || fail "a refused merge left $d"; done
expect_status 2 "an existing output" "$HSX" campaign --out s0 --merge s0 s1 s2
same whole/results.jsonl merged/results.jsonl "nothing changed by the refusals"

# ---- summary.svg ----
[[ -f whole/summary.svg ]] && pass || fail "no summary.svg"
head -c 5 whole/summary.svg | grep -q '<?xml' && pass || fail "summary.svg does not start with <?xml"
if command -v python3 >/dev/null; then
  python3 -c 'import sys, xml.etree.ElementTree as E; E.parse(sys.argv[1])' whole/summary.svg && pass ||
    fail "summary.svg is not well-formed XML"
fi
[[ "$(grep -c 'class="panel"' whole/summary.svg)" == 10 ]] && pass ||
  fail "summary.svg: $(grep -c 'class="panel"' whole/summary.svg) panels, expected 10 (9 checks, beam1 optimality)"
grep -q '</svg>' whole/summary.svg && pass || fail "summary.svg has no </svg>"
cmp -s whole/summary.svg s0/summary.svg && fail "summary.svg does not change with the rates" || pass

# ---- a failing scene minimised, and merged with its shards ----
FAIL=(--seed 1 --halfspaces 8 --start 79 --count 3 --checks prop51 --minimise-steps 40)
expect_status 3 "scene 80 fails" "$HSX" campaign "${FAIL[@]}" --out f1 --jobs 1
cp out.txt f1.txt
[[ "$(ls f1/failures | tr '\n' ' ')" == "scene-80.json scene-80.min.json " ]] && pass || fail "failures/: $(ls f1/failures)"
jq -r .description f1/failures/scene-80.min.json | grep -q "^hsx campaign --seed 1, scene 80 minimised (8 -> " && pass ||
  fail "the minimised note: $(jq -r .description f1/failures/scene-80.min.json | head -c 300)"
jq -r .description f1/failures/scene-80.min.json | grep -q "failed prop51: state" && pass || fail "the minimised note's witness"
h="$(jq '.halfspaces | length' f1/failures/scene-80.min.json)"
[[ $h -lt 8 ]] && pass || fail "the minimised scene has $h halfspaces"
expect_status 3 "hsx check on the minimised scene" "$HSX" check f1/failures/scene-80.min.json
grep -q "Prop. 5.1 (removable sets) .*FAIL" out.txt && pass || fail "hsx check on the minimised scene: $(head -c 600 out.txt)"
expect_status 3 "--jobs 2" "$HSX" campaign "${FAIL[@]}" --out f2 --jobs 2
same f1 f2 "--jobs 1 and 2 (minimised scene included)"
expect_status 3 "--no-minimise" "$HSX" campaign "${FAIL[@]}" --out f3 --no-minimise
[[ "$(ls f3/failures)" == scene-80.json ]] && pass || fail "--no-minimise: failures/: $(ls f3/failures)"
for f in campaign.json results.jsonl summary.json summary.svg failures/scene-80.json; do
  cmp -s f1/$f f3/$f && pass || fail "--no-minimise changed $f"
done
expect_status 0 "shard 0/2 (scenes 79, 81)" "$HSX" campaign "${FAIL[@]}" --shard 0/2 --out g0
expect_status 3 "shard 1/2 (scene 80)" "$HSX" campaign "${FAIL[@]}" --shard 1/2 --out g1
expect_status 3 "--merge with a failure" "$HSX" campaign --out gm --merge g0 g1
same f1 gm "merged shards with a minimised failure and the whole range"
same f1.txt out.txt "the merged table with a failure"

# ---- a 3D failure minimised (scene 543 of seed 1: a sphere and two cylinders pinching at a vertex) ----
GEN3=(--dimension 3 --seed 1 --start 543 --count 1 --primitives 1..3 --segments 6 --sample-policy intended --checks manifold)
expect_status 3 "a failing 3D scene" "$HSX" campaign "${GEN3[@]}" --out t1
[[ "$(ls t1/failures | tr '\n' ' ')" == "scene-543.json scene-543.min.json " ]] && pass || fail "3D failures/: $(ls t1/failures)"
jq -r .description t1/failures/scene-543.min.json | grep -q "^hsx campaign --seed 1, scene 543 minimised (3 -> 2 halfspaces, .* segment counts lowered" &&
  pass || fail "the 3D minimised note: $(jq -r .description t1/failures/scene-543.min.json | head -c 300)"
expect_status 3 "hsx check on the minimised 3D scene" "$HSX" check t1/failures/scene-543.min.json
grep -q "manifold.*FAIL .*pinches at a point" out.txt && pass || fail "hsx check on the minimised 3D scene: $(head -c 600 out.txt)"
expect_status 3 "the 3D scene again, --jobs 2" "$HSX" campaign "${GEN3[@]}" --out t2 --jobs 2
same t1 t2 "a 3D campaign's minimised failure, run twice"

# ---- a scene refused while generating it is tallied under its halfspace count (2D and 3D), not under 0 ----
expect_status 0 "refused 2D scenes" "$HSX" campaign --seed 1 --count 3 --halfspaces 4 --sample-policy intended \
  --max-cells 3 --checks existence --out r2
[[ "$(jq -c '[.outcome, .halfspaces]' r2/results.jsonl | sort -u)" == '["refused",4]' ]] && pass ||
  fail "refused 2D records: $(cut -c1-200 r2/results.jsonl)"
grep -qE '^ +4 +3 +0 +0 +3 +0 ' out.txt && pass || fail "refused 2D scenes' row: $(cat out.txt)"
expect_status 0 "refused 3D scenes" "$HSX" campaign --dimension 3 --seed 1 --count 3 --max-cells 20 --checks existence --out r3
[[ "$(jq -c 'select(.outcome != "refused" or .halfspaces < 1)' r3/results.jsonl)" == "" ]] && pass ||
  fail "refused 3D records: $(cut -c1-200 r3/results.jsonl)"
grep -qE '^ +0 ' out.txt && fail "a 0-halfspace row: $(cat out.txt)" || pass

testlib_finish
