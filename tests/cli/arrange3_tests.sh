#!/usr/bin/env bash
# `hsx arrange` on 3D input (issue 12): the counts of planes in general position (1 + n + C(n,2) + C(n,3) cells, each
# plane cut into 1 + (n-1) + C(n-1,2) patches), the same mesh read as OBJ, OFF and PLY gives the same output, the
# complex written with --json is read back and checked by `hsx arrange` with the same counts, the pictures and
# exports are written (and nothing when the run fails), bad 3D input exits 2 naming the problem.
# Usage: arrange3_tests.sh HSX SOURCE_DIR
set -u
hsx="$(realpath "${1:?usage: arrange3_tests.sh HSX SOURCE_DIR}")"; src="$(realpath "${2:?usage}")"
scenes="$src/data/scenes3d"
source "$src/tests/cli/common.sh"

# counts_of FILE: the counts line without the geometry part (cells onwards)
counts_of() { grep -o 'cells [0-9].*' "$1" | head -1; }

# Four planes in general position, all their crossings inside the box: 15 cells, 4 x 7 patches.
expect 0 "" -- "$hsx" arrange "$scenes/planes.json" --json "$work/planes.json" --svg "$work/planes.svg" \
  --ply "$work/planes.ply" --obj "$work/planes.obj" --labels
has "$work/out" "cells 15 " "planes: cells"
has "$work/out" "patches 28 " "planes: patches"
has "$work/out" "outer_cells 14 " "planes: all but C(3,3) = 1 cell touch the box"
has "$work/out" "faces " "planes: the counts name the refined triangles"
cp "$work/out" "$work/planes.txt"
for f in planes.json planes.svg planes.ply planes.obj planes.mtl; do [ -s "$work/$f" ] && ok || bad "$f not written"; done
has "$work/planes.json" '"dimension": 3' "planes: --json dimension"
has "$work/planes.ply" "ply" "planes: --ply header"
has "$work/planes.obj" "mtllib planes.mtl" "planes: --obj names its .mtl"
has "$work/planes.svg" "<svg" "planes: --svg"

# The complex written is read back and checked (volumes and areas recomputed) with the same counts.
expect 0 "" -- "$hsx" arrange "$work/planes.json"
[ "$(counts_of "$work/out")" = "$(counts_of "$work/planes.txt")" ] && ok ||
  bad "planes: counts read back '$(counts_of "$work/out")' differ from '$(counts_of "$work/planes.txt")'"
# ... and a tampered one is refused.
sed 's/"outer": true/"outer": false/' "$work/planes.json" >"$work/tampered.json"
expect 2 "outer" -- "$hsx" arrange "$work/tampered.json"

# The same tetrahedron as OBJ, OFF and PLY: the same output, apart from nothing.
expect 0 "" -- "$hsx" arrange "$scenes/mesh_obj.json"; cp "$work/out" "$work/obj.txt"
expect 0 "" -- "$hsx" arrange "$scenes/mesh_off.json"; cp "$work/out" "$work/off.txt"
expect 0 "" -- "$hsx" arrange "$scenes/mesh_ply.json"; cp "$work/out" "$work/ply.txt"
cmp -s "$work/obj.txt" "$work/off.txt" && ok || bad "OBJ and OFF give different output"
cmp -s "$work/obj.txt" "$work/ply.txt" && ok || bad "OBJ and PLY give different output"
has "$work/obj.txt" "(near, on T): moved to" "mesh: a near sample reports where it landed"

# Every bundled 3D scene arranges, twice with the same bytes (reproducible).
for scene in "$scenes"/*.json; do
  expect 0 "" -- "$hsx" arrange "$scene" --json "$work/a.json" || continue
  expect 0 "" -- "$hsx" arrange "$scene" --json "$work/b.json"
  cmp -s "$work/a.json" "$work/b.json" && ok || bad "$(basename "$scene"): two runs wrote different complexes"
done

# Bad input and bad requests: exit 2, nothing written.
expect 2 "needs a 3D scene" -- "$hsx" arrange "$src/data/scenes/lens.json" --ply "$work/lens.ply"
[ -e "$work/lens.ply" ] && bad "--ply on a 2D scene left a file" || ok
expect 2 "--obj" -- "$hsx" arrange "$scenes/planes.json" --obj -
cat >"$work/bad_radius.json" <<'JSON'
{"format": "hsx-scene/1", "dimension": 3,
 "halfspaces": [{"name": "S", "kind": "sphere", "center": [0, 0, 0], "radius": -1}]}
JSON
expect 2 "radius" -- "$hsx" arrange "$work/bad_radius.json" --json "$work/bad.json"
[ -e "$work/bad.json" ] && bad "a refused scene left its --json output" || ok
if ls -a "$work" | grep -q 'tmp-hsx'; then bad "temporary files left: $(ls -a "$work" | grep tmp-hsx)"; else ok; fi

finish
