#!/usr/bin/env bash
# `mpirun -np 2 hsx campaign` gives the same bytes as one process: usage: mpi_campaign_tests.sh HSX MPIEXEC
# - results.jsonl, summary.json, campaign.json, the failures/ folder and the printed table are identical to a
#   single-process run, on a campaign with a real failure (scene 80 of seed 1 at 8 halfspaces fails Prop. 5.1);
# - a campaign cut short (its results.jsonl truncated, the last line torn) and resumed under mpirun equals the
#   uninterrupted one;
# - a 3D campaign (--dimension 3) gives the same folder and table under mpirun, a minimised 3D failure included;
# - a folder rank 0 refuses stops every rank with exit 2 and leaves the folder as it was;
# - hsx bench --campaign-mpi times both as processes, and their records are one thread's bytes.
# Prints "N passed, M failed" and exits non-zero when anything failed.
set -u
HSX="${1:?usage: mpi_campaign_tests.sh HSX MPIEXEC}"
MPIEXEC="${2:?usage: mpi_campaign_tests.sh HSX MPIEXEC}"
source "$(dirname "${BASH_SOURCE[0]}")/testlib.sh"
testlib_init mpi-campaign
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI runs as root
MPI=("$MPIEXEC" -np 2 --oversubscribe)

same() {  # same A B WHAT
  if diff -r "$1" "$2" >"$TMP/diff.txt" 2>&1; then pass; else fail "$3 differ: $(head -c 600 "$TMP/diff.txt")"; fi
}

# both SUFFIX STATUS ARGS...: the campaign ARGS into $TMP/one<SUFFIX> (one process) and $TMP/two<SUFFIX> (mpirun),
# both exiting STATUS, with the same folders and printed tables.
both() {
  local suffix="$1" want="$2"; shift 2
  "$HSX" "$@" --out "$TMP/one$suffix" >"$TMP/one$suffix.txt" 2>"$TMP/one$suffix.err"
  local one=$?
  "${MPI[@]}" "$HSX" "$@" --out "$TMP/two$suffix" >"$TMP/two$suffix.txt" 2>"$TMP/two$suffix.err"
  local two=$?
  [[ $one == "$want" && $two == "$want" ]] && pass ||
    fail "exit statuses $one (one process) and $two (mpirun), expected $want: $(cat "$TMP/two$suffix.err")"
  same "$TMP/one$suffix" "$TMP/two$suffix" "the campaign folders$suffix"
  same "$TMP/one$suffix.txt" "$TMP/two$suffix.txt" "the printed tables$suffix"
}

ARGS=(campaign --seed 1 --start 70 --count 16 --halfspaces 8 --checks existence,prop51,beam1,uniqueness)
both "" 3 "${ARGS[@]}"
[[ -f "$TMP/two/failures/scene-80.json" ]] && pass || fail "mpirun: scene 80 not kept in failures/ ($(ls "$TMP/two/failures" 2>&1))"
grep -q "2 MPI processes" "$TMP/two.err" && pass || fail "mpirun: the timing line does not count the processes: $(cat "$TMP/two.err")"

# A 3D campaign (--dimension 3): the same bytes under mpirun.
ARGS3=(campaign --dimension 3 --seed 4 --count 6 --primitives 1..2 --segments 6 --degeneracies 1..2 --max-cells 40
       --sample-policy intended --checks existence,uniqueness,manifold,prop61,beam2)
both 3 0 "${ARGS3[@]}"
# A failing 3D scene (seed 1, scene 543) minimised on the rank that ran it: the same .min.json under mpirun.
both 3f 3 campaign --dimension 3 --seed 1 --start 542 --count 2 --primitives 1..3 --segments 6 --sample-policy intended \
  --checks manifold
[[ -f "$TMP/two3f/failures/scene-543.min.json" ]] && pass || fail "mpirun: no minimised 3D scene ($(ls "$TMP/two3f/failures" 2>&1))"

# Cut short, then resumed under mpirun.
cp -r "$TMP/one" "$TMP/cut"
rm -rf "$TMP/cut/failures" "$TMP/cut/summary.json"
head -n 9 "$TMP/one/results.jsonl" >"$TMP/cut/results.jsonl"
sed -n 10p "$TMP/one/results.jsonl" | head -c 40 >>"$TMP/cut/results.jsonl"  # a torn last line
# failures/ of the scenes already done are kept as the first run left them
mkdir -p "$TMP/cut/failures"
for f in "$TMP/one/failures"/*; do
  k="$(basename "$f" .json)"
  k="${k#scene-}"
  head -n 9 "$TMP/one/results.jsonl" | grep -q "^{\"index\":$k," && cp "$f" "$TMP/cut/failures/"
done
"${MPI[@]}" "$HSX" "${ARGS[@]}" --out "$TMP/cut" --resume >"$TMP/cut.txt" 2>"$TMP/cut.err"
[[ $? == 3 ]] && pass || fail "mpirun --resume exited $?: $(cat "$TMP/cut.err")"
same "$TMP/one" "$TMP/cut" "the resumed campaign folder and the uninterrupted one"
grep -q "resumed" "$TMP/cut.err" && pass || fail "mpirun --resume: no resume message: $(cat "$TMP/cut.err")"

# A folder that is not a campaign's: rank 0 refuses, every rank stops, the folder is untouched.
mkdir "$TMP/foreign"
echo "mine" >"$TMP/foreign/notes.txt"
timeout 60 "${MPI[@]}" "$HSX" "${ARGS[@]}" --out "$TMP/foreign" >"$TMP/f.txt" 2>"$TMP/f.err"
status=$?
[[ $status == 2 ]] && pass || fail "mpirun into a foreign folder exited $status, expected 2: $(cat "$TMP/f.err")"
[[ "$(ls "$TMP/foreign")" == notes.txt && "$(cat "$TMP/foreign/notes.txt")" == mine ]] && pass ||
  fail "the foreign folder was changed: $(ls "$TMP/foreign")"

# hsx bench --campaign --campaign-mpi: the two process stages run in alternating rounds (two here, each run into a
# folder of its own), and their records are one thread's bytes.
"$HSX" bench --campaign --campaign-halfspaces 4 --campaign-scenes 6 --campaign-checks existence,beam1,uniqueness \
  --campaign-time-limit 0 --campaign-max-states 200 --campaign-mpi --repetitions 2 --min-time 0 \
  --json "$TMP/bench.json" >"$TMP/bench.txt" 2>&1
[[ $? == 0 ]] && pass || fail "bench --campaign-mpi failed: $(cat "$TMP/bench.txt")"
python3 - "$TMP/bench.json" <<'PY' && pass || fail "bench --campaign-mpi: $(cat "$TMP/bench.txt")"
import json, sys
row = json.load(open(sys.argv[1]))["rows"][0]
assert row["mpi same"] == "yes", row
assert float(row["mpi/thread"]) > 0, row
stages = {s["stage"]: s for s in row["stages"]}
assert stages["proc jobs 2"]["repetitions"] == 2 and stages["mpirun 2"]["repetitions"] == 2, row
PY

testlib_finish
