#!/usr/bin/env bash
# Runs run.sh on case files as a normal user: when started as root (as CI is), as uid and gid 65534 ("nobody"), so
# that the cases marked skip-as-root (permission checks root is not bound by) run in CI too. Started as a normal
# user, it is run.sh itself. Usage as run.sh's; exit 77 (skipped) when root cannot run the program as nobody here
# (no setpriv, or the program, data or suite out of nobody's reach).
set -u
suite="$(cd "$(dirname "$0")" && pwd)"
if [ "$(id -u)" -ne 0 ]; then exec bash "$suite/run.sh" "$@"; fi
as_nobody=(setpriv --reuid=65534 --regid=65534 --clear-groups env HOME=/tmp)
reachable='test -x "$1" && test -r "$2/scenes/lens.json" && test -r "$3/run.sh" && test -r "$4"'
if ! command -v setpriv >/dev/null || ! "${as_nobody[@]}" bash -c "$reachable" _ "$1" "$2" "$suite" "${!#}"; then
  echo "hostile as a normal user: skipped (root cannot run $1 on $2 as nobody here)"
  exit 77
fi
exec "${as_nobody[@]}" bash "$suite/run.sh" "$@"
