#!/usr/bin/env bash
# The hostile-input suite's runner (README.md beside it describes the case format). Runs every case of the given
# case files against the hsx program, each in a fresh temporary directory under a time and a memory bound, and
# checks its exit code, fragments of its messages, and that it left behind nothing but what the case allows.
# Usage: run.sh [--selftest] HSX DATA_DIR CASE_FILE...     (exit 0 when every case passes, 1 otherwise)
# --selftest inverts the verdict: every case must fail (selftest.cases breaks each check once, so that the runner
# is shown to catch each kind of misbehaviour).
set -u
selftest=0
suite="$(cd "$(dirname "$0")" && pwd)"
if [ "${1:-}" = --selftest ]; then selftest=1; shift; fi
hsx="$(realpath "${1:?usage: run.sh HSX DATA_DIR CASE_FILE...}")"
data="$(realpath "${2:?usage: run.sh HSX DATA_DIR CASE_FILE...}")"
shift 2
passed=0 failed=0 skipped=0 cases=0
work="$(mktemp -d)"
trap 'chmod -R u+rwx "$work" 2>/dev/null; rm -rf "$work"' EXIT

# Substitutes the placeholders @hsx, @data, @suite and @tmp in $1.
expand() {
  local s="${1//@data/$data}"
  s="${s//@suite/$suite}"
  s="${s//@hsx/$hsx}"
  printf '%s' "${s//@tmp/$tmp}"
}

# What directory $1 holds, into the associative array named $2: per entry, its type, link target, permissions, size
# and modification time. (Few processes per case: the suite's time is mostly process start-up.)
snapshot() {
  local -n into=$2
  into=()
  local path rest
  while IFS=' ' read -r path rest; do into["$path"]="$rest"; done < <(find "$1" -mindepth 1 -printf '%P %y %l %m %s %T@\n')
}

# True when file $1 contains the text $2.
contains() {
  local content=""
  IFS= read -r -d '' content <"$1"
  [[ "$content" == *"$2"* ]]
}

# A case that does not behave (with --selftest: a case that fails as it must).
fail() {
  if ((selftest)); then passed=$((passed + 1)); [ -z "${HOSTILE_SHOW:-}" ] || echo "ok $name: $*"; return; fi
  failed=$((failed + 1))
  echo "FAIL $file: $name: $*"
  [ -s "$tmp.err" ] && echo "  stderr: $(head -c 400 "$tmp.err")"
}

# Runs the case collected in the variables below (reset by new_case).
run_case() {
  [ -n "$name" ] || return 0
  if ((!has_run)) || [ -z "$want_exit" ]; then fail "a case needs 'run' and 'exit'"; return; fi
  if ((skip_as_root)) && [ "$(id -u)" -eq 0 ]; then skipped=$((skipped + 1)); return; fi
  if ((needs_root)) && [ "$(id -u)" -ne 0 ]; then skipped=$((skipped + 1)); return; fi
  if ((needs_unnamed)) && ! python3 -c 'import os, sys; os.close(os.open(sys.argv[1], os.O_TMPFILE | os.O_WRONLY))' "$tmp" 2>/dev/null; then
    skipped=$((skipped + 1)); echo "skipped $file: $name: the file system of $tmp has no unnamed files (O_TMPFILE)"; return
  fi
  local line
  for line in "${setups[@]}"; do
    if ! (cd "$tmp" && eval "$(expand "$line")") >/dev/null 2>"$tmp.err"; then fail "setup failed: $line"; return; fi
  done
  local -A before=() after=()
  snapshot "$tmp" before
  local words
  eval "words=($(expand "$args"))"
  local got start=$SECONDS
  local bound=(-k 2 "$time_limit")
  [ -z "$kill_with" ] || bound=(--preserve-status -k 2 -s "${kill_with% *}" "${kill_with#* }")
  { (cd "$tmp" && ulimit -v "$memory" && { [ -z "$stack" ] || ulimit -s "$stack"; } &&
    for limit in "${ulimits[@]}"; do eval "ulimit $limit" || exit 125; done &&
    case "$stdout_to" in
      full) exec >/dev/full ;;
      closed) exec >&- ;;
      broken-pipe) exec > >(:) && wait $! ;;  # a pipe whose reader has ended (waited for: no race)
    esac &&
    exec env "${envs[@]}" timeout "${bound[@]}" "$hsx" "${words[@]}") \
    <"$stdin_from" >"$tmp.out" 2>"$tmp.err"; } 2>/dev/null  # bash's own "CPU time limit exceeded" notice
  got=$?
  ((SECONDS - start < 3)) || echo "slow: $file: $name: $((SECONDS - start)) s"
  if [ "$got" != "$want_exit" ]; then fail "exit $got, expected $want_exit"; return; fi
  local fragment
  for fragment in "${stderr_parts[@]}"; do
    contains "$tmp.err" "$(expand "$fragment")" || { fail "stderr lacks: $fragment"; return; }
  done
  for fragment in "${stdout_parts[@]}"; do
    contains "$tmp.out" "$(expand "$fragment")" || { fail "stdout lacks: $fragment"; return; }
  done
  local created
  for created in "${creates[@]}"; do
    [ -e "$tmp/$created" ] || [ -L "$tmp/$created" ] || { fail "did not create $created"; return; }
  done
  # Nothing new or changed in the directory, except the outputs the case allows (and what lies in them).
  snapshot "$tmp" after
  local path changes=""
  for path in "${!before[@]}" "${!after[@]}"; do
    [ "${before[$path]-missing}" != "${after[$path]-missing}" ] && [[ "$changes " != *" $path "* ]] || continue
    for created in "${creates[@]}"; do [[ "$path" == "$created" || "$path" == "$created"/* ]] && continue 2; done
    changes+=" $path"
  done
  [ -z "$changes" ] || { fail "left behind or changed:$changes"; return; }
  for line in "${afters[@]}"; do
    (cd "$tmp" && eval "$(expand "$line")") >/dev/null 2>&1 || { fail "after-check failed: $line"; return; }
  done
  if ((selftest)); then failed=$((failed + 1)); echo "FAIL $file: $name: passed, but every selftest case must fail"; return; fi
  passed=$((passed + 1))
  [ -z "${HOSTILE_SHOW:-}" ] || echo "ok $name: $(head -c 200 "$tmp.err")"
}

new_case() {
  run_case
  name="$1" args="" has_run=0 want_exit="" time_limit=20 memory=4000000 stack="" skip_as_root=0 needs_root=0 needs_unnamed=0 kill_with="" stdout_to="" stdin_from=/dev/null ulimits=()
  stderr_parts=() stdout_parts=() setups=() creates=() afters=() envs=()
  tmp=""
  [ -n "$name" ] || return 0
  cases=$((cases + 1))
  tmp="$work/$cases-${name//[^A-Za-z0-9_.-]/_}"
  mkdir -p "$tmp"
}

for file in "$@"; do
  name="" tmp=""
  inline=""  # the inline file being collected
  lineno=0
  while IFS= read -r line || [ -n "$line" ]; do
    lineno=$((lineno + 1))
    if [ -n "$inline" ]; then
      if [ "$line" = "end" ]; then inline=""; else printf '%s\n' "$line" >>"$tmp/$inline"; fi
      continue
    fi
    case "$line" in
      ''|'#'*) continue ;;
    esac
    key="${line%% *}"
    value=""
    [ "$key" = "$line" ] || value="${line#* }"
    if [ "$key" != case ] && [ -z "$name" ]; then echo "FAIL $file:$lineno: '$key' outside a case"; failed=$((failed + 1)); continue; fi
    case "$key" in
      case) new_case "$value" ;;
      run) args="$value" has_run=1 ;;
      exit) want_exit="$value" ;;
      stderr) stderr_parts+=("$value") ;;
      stdout) stdout_parts+=("$value") ;;
      file) inline="$value"; : >"$tmp/$inline" ;;
      bytes) printf '%b' "${value#* }" >"$tmp/${value%% *}" ;;
      setup) setups+=("$value") ;;
      creates) creates+=("$value") ;;
      after) afters+=("$value") ;;
      time) time_limit="$value" ;;
      memory) memory="$value" ;;
      stack) stack="$value" ;;
      env) envs+=("$(expand "$value")") ;;
      skip-as-root) skip_as_root=1 ;;
      needs-root) needs_root=1 ;;
      needs-unnamed-files) needs_unnamed=1 ;;
      kill) kill_with="$value" ;;
      standard-output) stdout_to="$value" ;;
      standard-input) stdin_from="$(expand "$value")" ;;
      ulimit) ulimits+=("$value") ;;
      *) echo "FAIL $file:$lineno: unknown key '$key'"; failed=$((failed + 1)) ;;
    esac
  done <"$file"
  [ -z "$inline" ] || { echo "FAIL $file: inline file $inline has no 'end'"; failed=$((failed + 1)); }
  new_case ""
done
((selftest)) && echo "hostile selftest: $passed cases failed as they must, $failed did not" ||
  echo "hostile: $passed passed, $failed failed, $skipped skipped (for root or for a normal user only, or for unnamed files)"
[ "$failed" -eq 0 ]
