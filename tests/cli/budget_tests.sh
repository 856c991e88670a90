#!/usr/bin/env bash
# Limits that bound time and memory (issue 10, §2; docs/limits.md): inputs whose arrangement, side table or
# numbers would exhaust the machine are refused quickly with exit 2, a message naming the limit and the option
# that raises it, and nothing written. Each run has a time bound and an address-space cap.
# Usage: budget_tests.sh HSX SOURCE_DIR
set -u
hsx="$(realpath "${1:?usage: budget_tests.sh HSX SOURCE_DIR}")"; src="$(realpath "${2:?usage}")"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
cd "$work"
passed=0; failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

# expect STATUS FRAGMENT SECONDS MEGABYTES -- COMMAND...: exit status, a fragment of stderr, and bounds.
expect() {
  local want="$1" fragment="$2" seconds="$3" megabytes="$4"; shift 5
  (ulimit -v $((megabytes * 1024)); timeout "$seconds" "$@") >"$work/out" 2>"$work/err" </dev/null; local got=$?
  if [ "$got" -ne "$want" ]; then bad "$* exited $got, expected $want: $(head -c 300 "$work/err")"; return; fi
  if [ -n "$fragment" ] && ! grep -qF -- "$fragment" "$work/err"; then bad "$*: stderr lacks '$fragment': $(head -c 300 "$work/err")"; return; fi
  ok
}
nothing_written() { if [ -e "$1" ] || ls -a "$work" | grep -q 'tmp-hsx'; then bad "output left behind: $1"; else ok; fi; }

# scene N KIND: N half-planes, "parallel" (y <= k/N) or "random" (integer normals from a fixed LCG).
scene() {
  awk -v n="$1" -v kind="$2" 'BEGIN {
    printf "{\"format\": \"hsx-scene/1\", \"dimension\": 2, \"domain\": {\"min\": [-1000, -1000], \"max\": [1000, 1000]}, \"halfspaces\": [";
    s = 12345;
    for (i = 0; i < n; i++) {
      if (kind == "parallel") { a = 0; b = 1; c = (i - n / 2) "/" n }
      else { s = (s * 1103515245 + 12345) % 2147483648; a = s % 2001 - 1000;
             s = (s * 1103515245 + 12345) % 2147483648; b = s % 2001 - 1000; if (a == 0 && b == 0) b = 1;
             s = (s * 1103515245 + 12345) % 2147483648; c = s % 1001 - 500 }
      printf "%s{\"name\": \"h%d\", \"kind\": \"halfplane\", \"normal\": [%d, %d], \"offset\": \"%s\"}", (i ? ", " : ""), i, a, b, c
    }
    printf "], \"samples\": []}\n" }' >"$3"
}
scene 100000 parallel par100000.json
scene 3000 random rand3000.json
scene 400 parallel par400.json

# 10^5 parallel half-planes: a linear arrangement, but its side table is 10^10 entries: refused before the sweep.
expect 2 "at least 100001 cells over 100000 halfspaces" 30 2000 -- "$hsx" arrange par100000.json -q --json out.json
grep -qF -- "--max-side-table" err && ok || bad "the side-table message does not name --max-side-table"
nothing_written out.json
# 3000 random half-planes (about 4.5 million cells): refused when the sweep passes 2^27 / 3000 cells.
expect 2 "cells over 3000 halfspaces: its side table (cells x halfspaces) exceeds 134217728 entries" 60 3000 -- \
  "$hsx" arrange rand3000.json -q --json out.json
nothing_written out.json
expect 2 "over the limit of 1000 (raise it with --max-cells" 30 2000 -- "$hsx" extract rand3000.json --max-cells 1000
expect 2 "over the limit of 1000" 30 2000 -- "$hsx" check rand3000.json --max-cells 1000
expect 2 "over the limit of 1000" 30 2000 -- "$hsx" describe rand3000.json --csg h0 --max-cells 1000
# The limits can be raised (and are then what holds): 401 cells x 400 half-planes.
expect 0 "" 60 2000 -- "$hsx" arrange par400.json -q --max-side-table 160400
expect 2 "exceeds 160399 entries" 60 2000 -- "$hsx" arrange par400.json -q --max-side-table 160399
expect 2 "" 10 2000 -- "$hsx" arrange par400.json -q --max-cells -1
# Out of memory is a clean error, not an abort: GMP's allocation failures and std::bad_alloc alike.
expect 2 "out of memory" 60 200 -- "$hsx" arrange rand3000.json -q --max-cells 0 --max-side-table 0
# 8000 copies of one CSGNet circle (96 KB, within the 100,000-character limit): coincident curves are merged
# before the sweep (cubic before: 800 copies took 31 s).
program="c(32,32,16)"; for _ in $(seq 8000); do program+="c(32,32,16)+"; done
expect 0 "" 60 2000 -- "$hsx" convert --csgnet "$program" --out copies.json
# A polygon total over 200,000 vertices is refused before any simplicity test.
awk 'BEGIN { printf "{\"format\": \"hsx-scene/1\", \"dimension\": 2, \"halfspaces\": [";
  for (p = 0; p < 41; p++) { printf "%s{\"name\": \"P%d\", \"kind\": \"polygon\", \"vertices\": [", (p ? ", " : ""), p;
    for (k = 0; k < 5000; k++) { r = (k % 2) ? 1000 : 900; t = 6.283185307179586 * k / 5000;
      printf "%s[%d, %d]", (k ? ", " : ""), int(r * cos(t)) + p, int(r * sin(t)) }
    printf "]}" }
  printf "], \"samples\": []}\n" }' >polygons.json
expect 2 "all polygons together have 205000 vertices, more than the limit of 200000" 10 2000 -- "$hsx" arrange polygons.json -q

echo "budget_cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
