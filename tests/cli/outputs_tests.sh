#!/usr/bin/env bash
# Outputs that never clobber what they must not, and runs that fail leave nothing (issue 10, §1 and parts of §4):
# each case names the command, the exit code it must give, a fragment of its message, and what must (not) exist
# afterwards. Usage: outputs_tests.sh HSX SOURCE_DIR
set -u
hsx="$(realpath "${1:?usage: outputs_tests.sh HSX SOURCE_DIR}")"; src="$(realpath "${2:?usage}")"
lens="$src/data/scenes/lens.json"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
cd "$work"
passed=0; failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

# expect STATUS FRAGMENT -- COMMAND...: exit status and a fragment of stderr ("" for none); 10 s at most.
expect() {
  local want="$1" fragment="$2"; shift 3
  timeout 10 "$@" >"$work/out" 2>"$work/err" </dev/null; local got=$?
  if [ "$got" -ne "$want" ]; then bad "$* exited $got, expected $want: $(head -c 300 "$work/err")"; return; fi
  if [ -n "$fragment" ] && ! grep -qF -- "$fragment" "$work/err"; then bad "$*: stderr lacks '$fragment': $(head -c 300 "$work/err")"; return; fi
  ok
}
no_leftovers() {  # no temporary files of hsx anywhere in the folder
  if ls -a "$work" | grep -q 'tmp-hsx'; then bad "temporary files left: $(ls -a "$work" | grep tmp-hsx)"; else ok; fi
}

# Devices are written in place, never replaced by a regular file.
mknod "$work/null" c 1 3
expect 0 "" -- "$hsx" arrange "$lens" -q --json "$work/null"
[ -c "$work/null" ] && ok || bad "a character device was replaced: $(stat -c %F "$work/null")"
expect 2 "No space left on device" -- "$hsx" arrange "$lens" -q --json /dev/full
[ -c /dev/full ] && ok || bad "/dev/full is no longer a device"
"$hsx" arrange "$lens" -q --json /dev/stdout >"$work/stdout.json" 2>/dev/null
grep -q '"format": "hsx-complex/1"' "$work/stdout.json" && ok || bad "--json /dev/stdout wrote nothing to standard output"
"$hsx" arrange "$lens" -q --json - >"$work/dash.json" 2>/dev/null
cmp -s "$work/stdout.json" "$work/dash.json" && ok || bad "--json - and --json /dev/stdout differ"

# A FIFO is written in place (a reader on the other side).
mkfifo "$work/fifo"
(cat "$work/fifo" >"$work/from-fifo") & reader=$!
expect 0 "" -- "$hsx" arrange "$lens" -q --json "$work/fifo"
wait $reader
[ -p "$work/fifo" ] && grep -q 'hsx-complex/1' "$work/from-fifo" && ok || bad "FIFO output"

# A symbolic link is followed: its target gets the output, the link stays a link.
echo keep >"$work/t.json"; ln -s t.json "$work/l.json"
expect 0 "" -- "$hsx" arrange "$lens" -q --json "$work/l.json"
[ -L "$work/l.json" ] && grep -q 'hsx-complex/1' "$work/t.json" && ok || bad "symlink output: link lost or target unchanged"
ln -s missing.json "$work/dangling.json"
expect 2 "link to a missing file" -- "$hsx" arrange "$lens" -q --json "$work/dangling.json"

# Outputs that cannot be written are the user's problem: exit 2 with the path and the reason.
expect 2 'cannot write --json "/nonexistent/dir/out.json": no folder' -- "$hsx" arrange "$lens" -q --json /nonexistent/dir/out.json
expect 2 '/proc/out.svg' -- "$hsx" arrange "$lens" -q --svg /proc/out.svg
mkdir "$work/adir"
expect 2 'it is a directory' -- "$hsx" arrange "$lens" -q --json "$work/adir"
expect 2 'an empty path' -- "$hsx" arrange "$lens" -q --json ''
expect 2 'already the output of --json' -- "$hsx" extract "$lens" -q --json "$work/same.json" --svg "$work/same.json"

# A failed run leaves no outputs at all: every path is checked before computing.
rm -f "$work/out.json"
expect 2 "/nonexistent/x.svg" -- "$hsx" extract "$lens" --json "$work/out.json" --svg /nonexistent/x.svg
[ ! -e "$work/out.json" ] && ok || bad "extract left out.json behind after a failed --svg"
expect 2 "/nonexistent/x.svg" -- "$hsx" describe "$lens" --csg "A & B" --json "$work/out.json" --svg /nonexistent/x.svg
[ ! -e "$work/out.json" ] && ok || bad "describe left out.json behind"
expect 2 "/nonexistent/x.scad" -- "$hsx" csg "$lens" --csg "A & B" --json "$work/out.json" --openscad /nonexistent/x.scad
[ ! -e "$work/out.json" ] && ok || bad "csg left out.json behind"
mesh="$src/data/meshes/lprism.obj"; fea="$src/data/meshes/lprism_open_corner.fea"
expect 2 "/sys/x" -- "$hsx" nhtree "$mesh" --fea "$fea" --json "$work/out.json" --conf /sys/x
[ ! -e "$work/out.json" ] && ok || bad "nhtree left out.json behind after a bad --conf"
expect 2 "/nonexistent/prefix" -- "$hsx" nhtree "$mesh" --fea "$fea" --conf "$work/out.conf" --decomposed /nonexistent/prefix
[ ! -e "$work/out.conf" ] && ok || bad "nhtree left out.conf behind after a bad --decomposed"
no_leftovers

# Options that used to be accepted or silently ignored.
expect 2 "--time-limit" -- "$hsx" extract "$lens" -q --time-limit nan
expect 2 "--time-limit" -- "$hsx" extract "$lens" -q --time-limit -1
expect 2 "--max-ties" -- "$hsx" extract "$lens" -q --max-ties -3
expect 2 "--from" -- "$hsx" corpus csgnet "$lens" --from -5
expect 2 "--limit" -- "$hsx" corpus csgnet "$lens" --limit -1

# Inputs that are not regular files: refused at once, never read (a FIFO must not block).
expect 2 "is a directory" -- "$hsx" corpus csgnet "$work/adir"
mkfifo "$work/in.fifo"
expect 2 "in.fifo" -- "$hsx" arrange "$work/in.fifo"   # no writer: read as empty, refused as invalid JSON
expect 2 "is a directory" -- "$hsx" arrange "$work/adir"

mkdir "$work/dir.obj" "$work/dir.fea"
expect 2 "dir.obj: is a directory" -- "$hsx" nhtree "$work/dir.obj" --fea "$fea"
expect 2 "dir.fea: is a directory" -- "$hsx" nhtree "$mesh" --fea "$work/dir.fea"
mkfifo "$work/pipe.obj"
expect 2 "pipe.obj: not a regular file" -- "$hsx" nhtree "$work/pipe.obj" --fea "$fea"
expect 2 "missing.obj: cannot open it: no such file" -- "$hsx" nhtree "$work/missing.obj" --fea "$fea"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
