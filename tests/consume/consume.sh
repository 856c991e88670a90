#!/usr/bin/env bash
# hsx as a consumer sees it. Usage: consume.sh SOURCE_DIR BUILD_DIR MODE
#   MODE install:      cmake --install BUILD_DIR into a temporary prefix, then build and run examples/ as a separate
#                      CMake project that calls find_package(hsx), on bundled data, checking their output.
#   MODE subdirectory: a separate project that add_subdirectory()s the source tree, built from scratch (the whole
#                      library: several minutes), then run.
set -euo pipefail
src="$(cd "${1:?usage}" && pwd)"; build="$(cd "${2:?usage}" && pwd)"; mode="${3:?usage}"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
generator=(); command -v ninja >/dev/null && generator=(-G Ninja)
fail() { echo "FAIL: $*"; exit 1; }

case "$mode" in
install)
  cmake --install "$build" --prefix "$work/prefix" >/dev/null
  [ -f "$work/prefix/include/hsx/hsx.hpp" ] || fail "headers not installed"
  ls "$work"/prefix/lib*/cmake/hsx/hsxConfig.cmake >/dev/null || fail "no package config installed"
  [ ! -e "$work/prefix/include/hsx/geometry/planar_points.hpp" ] || fail "a private header was installed"
  cmake -S "$src/examples" -B "$work/examples" "${generator[@]}" -DCMAKE_PREFIX_PATH="$work/prefix" \
        -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$work/examples" -j2 >/dev/null
  ex="$work/examples"

  out="$("$ex/arrange_and_extract" "$src/data/scenes/lens.json" "$work/shape.json")"
  echo "$out"
  grep -q "optimal yes" <<<"$out" || fail "arrange_and_extract: no proven optimum"
  grep -q '"format": "hsx-result/1"' "$work/shape.json" || fail "arrange_and_extract: no result document"

  # Grade: the optimum (from the CLI's complex export and its result) is OPTIMAL; the empty shape is not.
  "$build/src/hsx" arrange "$src/data/scenes/lens.json" -q --json "$work/complex.json"
  cells=$(awk '/^  "cells": \[/{on=1; next} on && /^  \]/{exit} on && /^    \{/{n++} END{print n}' "$work/complex.json")
  inside=" $(awk '/"inside_cells": \[/{on=1; next} on && /\]/{exit} on {gsub(/[ ,]/, ""); printf "%s ", $0}' \
             "$work/shape.json")"
  [ "$cells" -gt 0 ] && [ "$inside" != " " ] || fail "could not read the cells of complex.json or shape.json"
  for ((c = 0; c < cells; ++c)); do [[ "$inside" == *" $c "* ]] && printf '1 ' || printf '0 '; done >"$work/labels.txt"
  for ((c = 0; c < cells; ++c)); do printf '0 '; done >"$work/empty.txt"
  out="$("$ex/grade_labelling" "$work/complex.json" "$work/labels.txt")" || fail "grade_labelling: optimum not graded optimal"
  echo "$out"; grep -q "^OPTIMAL" <<<"$out" || fail "grade_labelling: optimum not OPTIMAL"
  set +e; out="$("$ex/grade_labelling" "$work/complex.json" "$work/empty.txt")"; status=$?; set -e
  [ "$status" -eq 3 ] && grep -q "NOT OPTIMAL" <<<"$out" || fail "grade_labelling: the empty shape graded optimal"
  echo "1 0 2" >"$work/bad.txt"
  set +e; "$ex/grade_labelling" "$work/complex.json" "$work/bad.txt" 2>"$work/err"; status=$?; set -e
  [ "$status" -eq 2 ] && grep -q "bad input" "$work/err" || fail "grade_labelling: bad labels not refused"

  out="$("$ex/csg_tree" "$src/data/scenes/lens.json" "(A | B) & ~C")" || fail "csg_tree failed"
  echo "$out"; grep -q "verified on every cell yes" <<<"$out" || fail "csg_tree: no verified tree"
  ;;
subdirectory)
  launcher=(); command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S "$src/tests/consume/subdirectory" -B "$work/sub" "${generator[@]}" "${launcher[@]}" \
        -DHSX_SOURCE_DIR="$src" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$work/sub" -j2 >"$work/build.log" 2>&1 || { tail -40 "$work/build.log"; fail "build through add_subdirectory"; }
  out="$("$work/sub/consumer" "$src/data/scenes/lens.json")"
  echo "$out"; grep -q "cells; energy" <<<"$out" || fail "consumer output"
  ;;
*) fail "unknown mode $mode" ;;
esac
echo "consume ($mode): ok"
