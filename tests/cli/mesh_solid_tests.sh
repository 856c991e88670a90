#!/usr/bin/env bash
# Solids given as closed meshes on a 3D scene's halfspaces (--mesh FILE; io/solid.hpp, geometry/mesh_solid3.hpp):
# usage: mesh_solid_tests.sh PATH/TO/hsx SOURCE_DIR
# - on data/scenes3d/mesh_solids.json, describe, csg, convert, samples and nhtree with --mesh give the documents
#   --csg gives for the expression the mesh was made for (the union data/meshes/lprism.obj = A | B, the difference
#   mesh_solid_right.off = A & ~B, the hollow data/meshes/hollow_cube.obj = O & ~I): the same cells, trees, samples
#   and NH-Rep verdicts;
# - a mesh may give a solid that is not describable (the left half of split_box.json); the boundary hsx extract
#   writes with exact coordinates is such a mesh (curved halfspaces too) and gives the extracted cells back;
# - a mesh with a face off the halfspaces (mesh_solid_cut.obj), outside the domain, open, or given with a 2D scene,
#   and two solid sources at once: exit 2, the message naming the file (and the face), no output file left behind.
# Prints "N passed, M failed" and exits non-zero when anything failed.
set -u
hsx="$(realpath "${1:?usage: mesh_solid_tests.sh HSX SOURCE_DIR}")"
src="$(realpath "${2:?usage: mesh_solid_tests.sh HSX SOURCE_DIR}")"
source "$src/tests/cli/common.sh"
S3="$src/data/scenes3d"
M="$src/data/meshes"
SCENE="$S3/mesh_solids.json"
# same WHAT A B: the two files are identical
same() { if cmp -s "$2" "$3"; then ok; else bad "$1: $2 and $3 differ: $(diff "$2" "$3" | head -c 400)"; fi; }

# ---- the same documents as --csg ----
for pair in "lprism:$M/lprism.obj:A | B" "right:$S3/mesh_solid_right.off:A & ~B" "hollow:$M/hollow_cube.obj:O & ~I"; do
  IFS=: read -r name mesh expr <<<"$pair"
  expect 0 "" -- "$hsx" describe "$SCENE" --mesh "$mesh" --json "$name.mesh.describe.json"
  expect 0 "" -- "$hsx" describe "$SCENE" --csg "$expr" --json "$name.csg.describe.json"
  same "describe --mesh $name" "$name.mesh.describe.json" "$name.csg.describe.json"
  expect 0 "" -- "$hsx" csg "$SCENE" --mesh "$mesh" --json "$name.mesh.csg.json"
  expect 0 "" -- "$hsx" csg "$SCENE" --csg "$expr" --json "$name.csg.csg.json"
  same "csg --mesh $name" "$name.mesh.csg.json" "$name.csg.csg.json"
  expect 0 "" -- "$hsx" convert "$SCENE" --mesh "$mesh" --out "$name.mesh.bsh.json" --json "$name.mesh.convert.json"
  expect 0 "" -- "$hsx" convert "$SCENE" --csg "$expr" --out "$name.csg.bsh.json" --json "$name.csg.convert.json"
  same "convert --mesh $name (summary)" "$name.mesh.convert.json" "$name.csg.convert.json"
  same "convert --mesh $name (scene)" "$name.mesh.bsh.json" "$name.csg.bsh.json"
done
expect 0 "" -- "$hsx" samples "$SCENE" --mesh "$M/lprism.obj" --json lprism.mesh.samples.json
expect 0 "" -- "$hsx" samples "$SCENE" --csg "A | B" --json lprism.csg.samples.json
same "samples --mesh" lprism.mesh.samples.json lprism.csg.samples.json
# nhtree: the same patch graph, tree, evaluation and exit status (3 when the tree fails) as with --csg.
for flag in "" "--nest-holes"; do
  "$hsx" nhtree "$SCENE" --mesh "$M/hollow_cube.obj" $flag --json nh.mesh.json >nh.mesh.out 2>&1; s1=$?
  "$hsx" nhtree "$SCENE" --csg "O & ~I" $flag --json nh.csg.json >nh.csg.out 2>&1; s2=$?
  if [ "$s1" -eq "$s2" ]; then ok; else bad "nhtree --mesh $flag exited $s1, --csg $s2"; fi
  same "nhtree --mesh $flag (JSON)" nh.mesh.json nh.csg.json
  same "nhtree --mesh $flag (text)" nh.mesh.out nh.csg.out
done
has nh.mesh.out "exact evaluation with natural halfspaces" "nhtree --mesh"

# A solid that is not describable, as a mesh: split_box.json's left half (csg3_tests.sh gives it by its cell).
if expect 3 "" -- "$hsx" describe "$S3/split_box.json" --mesh "$S3/split_box_left.obj" --json left.json; then
  has out "mixed term B ~C: inside cells" "describe --mesh: the left half's mixed term"
fi
# The boundary hsx extract writes (exact coordinates) is a mesh on the scene's halfspaces, curved ones too: it gives
# the extracted cells back (a sphere with a spherical cavity, 316 triangles).
expect 0 "" -- "$hsx" extract "$S3/sphere_cavity.json" --json cavity.result.json --obj cavity.obj --exact-coordinates --no-timing
expect 0 "" -- "$hsx" describe "$S3/sphere_cavity.json" --mesh cavity.obj --json cavity.mesh.json
expect 0 "" -- "$hsx" describe "$S3/sphere_cavity.json" --shape cavity.result.json --json cavity.shape.json
same "describe --mesh (extracted boundary)" cavity.mesh.json cavity.shape.json
expect 0 "" -- "$hsx" convert "$S3/sphere_cavity.json" --mesh cavity.obj --out cavity.bsh.json --json cavity.convert.json
python3 - cavity.convert.json cavity.result.json <<'PY' && ok || bad "convert --mesh (extracted boundary): other cells"
import json, sys
conv, res = (json.load(open(p)) for p in sys.argv[1:3])
sys.exit(0 if conv["round_trip"] and len(conv["inside_cells"]) == len(res["inside_cells"]) else 1)
PY

# ---- refusals: exit 2, the file and the face named, nothing written ----
expect 2 "mesh_solid_cut.obj:21: face 10 does not lie on the scene's halfspaces" -- \
  "$hsx" csg "$SCENE" --mesh "$S3/mesh_solid_cut.obj" --json cut.json --svg cut.svg
if [ -e cut.json ] || [ -e cut.svg ]; then bad "csg --mesh (refused) left output behind"; else ok; fi
for cmd in describe nhtree; do
  expect 2 "face 10 does not lie on the scene's halfspaces" -- \
    "$hsx" $cmd "$SCENE" --mesh "$S3/mesh_solid_cut.obj" --json cut.$cmd.json
  if [ -e cut.$cmd.json ]; then bad "$cmd --mesh (refused) left output behind"; else ok; fi
done
expect 2 "face 10 does not lie on the scene's halfspaces" -- \
  "$hsx" convert "$SCENE" --mesh "$S3/mesh_solid_cut.obj" --out cut.bsh.json
if [ -e cut.bsh.json ]; then bad "convert --mesh (refused) left output behind"; else ok; fi
sed 's/^v 0 0 1$/v 0 0 5/' "$M/cube.obj" >tall.obj
expect 2 "tall.obj:6: vertex 4 [0, 0, 5] is outside the scene's domain" -- \
  "$hsx" describe "$SCENE" --mesh tall.obj --json tall.json
grep -v '^f 2 7 6$' "$M/cube.obj" >open.obj
expect 2 "open.obj" -- "$hsx" describe "$SCENE" --mesh open.obj --json open.json
if [ -e tall.json ] || [ -e open.json ]; then bad "describe --mesh (refused) left output behind"; else ok; fi
expect 2 "--mesh: a solid given as a mesh needs a 3D scene" -- \
  "$hsx" describe "$src/data/figures/fig02-1.json" --mesh "$M/cube.obj"
expect 2 "exactly one" -- "$hsx" csg "$SCENE" --mesh "$M/cube.obj" --csg "A & B"
expect 2 "a mesh (.obj) is its own solid" -- "$hsx" nhtree "$M/cube.obj" --fea "$M/cube.fea" --mesh "$M/cube.obj"
expect 2 "no such file" -- "$hsx" describe "$SCENE" --mesh missing.obj
finish
