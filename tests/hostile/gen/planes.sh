#!/usr/bin/env bash
# Writes a 3D hsx-scene/1 scene of N planes (no samples) to standard output. Usage: planes.sh KIND N, KIND one of
#   spread  planes in general-ish position crossing the domain [-10, 10]^3 (about N^3/6 cells)
#   star    planes through the origin (about N^2 cells, one corner)
#   pencil  planes through the z axis (2N cells, one line)
kind="${1:?usage: planes.sh spread|star|pencil N}" n="${2:?usage: planes.sh spread|star|pencil N}"
printf '{"format": "hsx-scene/1", "dimension": 3, "domain": {"min": [-10, -10, -10], "max": [10, 10, 10]}, "halfspaces": ['
for ((i = 1; i <= n; i++)); do
  ((i == 1)) || printf ', '
  a=$((i * 37 % 199 - 99)) b=$((i * i * 53 % 197 - 98)) c=$((i * 101 % 193 - 96)) d=0
  case "$kind" in
    spread) d=$((i * 29 % 61 - 30)) ;;
    star) ;;
    pencil) c=0 ;;
    *) echo "planes.sh: unknown kind $kind" >&2; exit 2 ;;
  esac
  ((a != 0 || b != 0 || c != 0)) || a=1
  printf '{"name": "p%d", "kind": "plane", "normal": [%d, %d, %d], "offset": %d}' "$i" "$a" "$b" "$c" "$d"
done
printf '], "samples": []}\n'
