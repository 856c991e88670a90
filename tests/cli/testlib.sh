# Shared by the end-to-end test scripts (source it): a temporary folder removed at exit, pass/fail counts, and the
# closing line. Usage, after `set -u`:
#   source "$(dirname "${BASH_SOURCE[0]}")/testlib.sh"; testlib_init NAME
#   ... pass / fail "what went wrong" / expect_status STATUS "what" COMMAND... ...
#   testlib_finish          # prints "N passed, M failed" and returns non-zero when anything failed
# expect_status leaves the command's standard output in "$TMP/out.txt" and its standard error in "$TMP/err.txt".

testlib_init() {
  TMP="$(mktemp -d "${TMPDIR:-/tmp}/hsx-$1-tests.XXXXXX")"
  trap 'rm -rf "$TMP"' EXIT
  passed=0
  failed=0
}

pass() { passed=$((passed + 1)); }

fail() {
  failed=$((failed + 1))
  echo "FAIL: $*" >&2
}

expect_status() {  # STATUS WHAT COMMAND...: the command exits with STATUS
  local want="$1" what="$2"
  shift 2
  "$@" >"$TMP/out.txt" 2>"$TMP/err.txt"
  local got=$?
  if [[ $got == "$want" ]]; then pass; else fail "$what: exit $got, expected $want ($(head -c 300 "$TMP/err.txt"))"; fi
}

testlib_finish() {
  echo "$passed passed, $failed failed"
  [[ $failed == 0 ]]
}
