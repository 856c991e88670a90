#!/usr/bin/env bash
# The CSGNet corpus end to end (describability, BHC, conversion to BSH and back), on a range of lines.
# Usage: csgnet.sh HSX SOURCE_DIR FROM COUNT. Exits 77 (reported by ctest as skipped, never as passed) when the
# external corpus (../shared/data/csgnet beside the project) is not present.
set -euo pipefail
hsx="$1"; src="$2"; from="$3"; count="$4"
corpus="${HSX_CSGNET_CORPUS:-$src/../shared/data/csgnet/best_st_expressions.txt}"
if [ ! -f "$corpus" ]; then
  echo "SKIPPED: CSGNet corpus not present at $corpus"
  exit 77
fi
"$hsx" corpus csgnet "$corpus" --from "$from" --limit "$count"
