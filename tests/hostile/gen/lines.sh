#!/usr/bin/env bash
# Writes an hsx-scene/1 scene of N half-planes in general-ish position (no samples) to standard output: a large
# input for cases that need a run that takes a while (signals) or many halfspaces. Usage: lines.sh N
n="${1:?usage: lines.sh N}"
printf '{"format": "hsx-scene/1", "dimension": 2, "domain": {"min": [-1000, -1000], "max": [1000, 1000]}, "halfspaces": ['
for ((i = 1; i <= n; i++)); do
  ((i == 1)) || printf ', '
  printf '{"name": "h%d", "kind": "halfplane", "normal": [%d, %d], "offset": %d}' "$i" $((i % 17 + 1)) $((i * 7 % 23 - 11)) $((i % 13))
done
printf '], "samples": []}\n'
