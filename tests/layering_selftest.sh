#!/usr/bin/env bash
# layering.sh must be able to fail: each file in tests/layering_cases breaks one rule and must be caught, with its
# own message, while the tree itself passes. Usage: layering_selftest.sh SOURCE_DIR
set -u
root="${1:?usage: layering_selftest.sh SOURCE_DIR}"
here="$(dirname "$0")"
bad=0
for case in "$here"/layering_cases/*; do
  out="$(bash "$here/layering.sh" "$root" "$case" 2>&1)"; status=$?
  logical="$(sed -nE '1s|^// layering-path: (.*)$|\1|p' "$case")"
  if [ "$status" -eq 0 ] || ! grep -q "^$logical: " <<<"$out"; then
    echo "NOT CAUGHT: $(basename "$case") ($logical)"; echo "$out" | tail -3; bad=$((bad + 1))
  else
    echo "caught: $(basename "$case"): $(grep "^$logical: " <<<"$out" | head -1)"
  fi
done
[ "$bad" -eq 0 ] || { echo "$bad layering cases not caught"; exit 1; }
