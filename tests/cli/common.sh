# Shared by the CLI test scripts: source it after setting `hsx` and `src`. Gives a scratch folder `$work` (removed
# on exit, the working directory), pass/fail counting, `expect` and `finish`.
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
passed=0; failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

# expect STATUS FRAGMENT -- COMMAND...: the exit status and a fragment of stderr ("" for none); stdout in
# $work/out, stderr in $work/err; 120 s at most.
expect() {
  local want="$1" fragment="$2"; shift 3
  timeout 120 "$@" >"$work/out" 2>"$work/err" </dev/null; local got=$?
  if [ "$got" -ne "$want" ]; then bad "$* exited $got, expected $want: $(head -c 300 "$work/err")"; return 1; fi
  if [ -n "$fragment" ] && ! grep -qF -- "$fragment" "$work/err"; then
    bad "$*: stderr lacks '$fragment': $(head -c 300 "$work/err")"; return 1
  fi
  ok
}

# has FILE FRAGMENT WHAT: FILE contains FRAGMENT (fixed string).
has() { if grep -qF -- "$2" "$1"; then ok; else bad "$3: '$2' not in $1: $(head -c 300 "$1")"; fi; }

# bsh_examples FILE: sets $data to the BSH authors' examples folder, absolute (HSX_BSH_DATA, default
# ../shared/data/bsh-examples beside the source tree $src), or exits 77 (reported as skipped) when FILE, a path
# inside it, is absent.
bsh_examples() {
  data="${HSX_BSH_DATA:-$src/../shared/data/bsh-examples}"
  [ -f "$data/$1" ] || { echo "no BSH examples at $data: skipped"; exit 77; }
  data="$(realpath "$data")"
}

finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
