#!/usr/bin/env bash
# hsx describe and hsx csg on 3D scenes (issue 14 section 1): usage: csg3_tests.sh PATH/TO/hsx SOURCE_DIR
# - csg --json on a 3D solid has "volume" (exact), never "area"; the summary says "volume"; a 2D one keeps "area";
# - a non-describable 3D solid (data/scenes3d/split_box.json, its left half chosen by scripts/solid-by-witness):
#   describe exits 3 with the mixed term and its witness cells; describe --svg draws the solid and, over it, the
#   patches bounding the witness cells (orange inside, red outside); csg --svg draws the solid's boundary only;
# - pictures are byte-identical from run to run;
# - csg --openscad on a 3D scene: a 3D program, deterministic, one polyhedron per leaf of the tree (planes and
#   complements as documented in io/openscad.hpp), every polyhedron closed and clockwise from outside (each
#   directed edge once, its reverse once; negative divergence volume with OpenSCAD's orientation), the planes'
#   polyhedra of the exact volume of the domain box's part; --circle-segments is refused in 3D and without
#   --openscad (exit 2); when `openscad` is installed, it renders the program to STL (not required);
# - csg --separators in 3D: the split box needs one plane; the BHC objects rebuilt (docs/csg3.md): the bracket
#   (data/scenes3d/bhc_bracket.json) is describable with the tree figures docs/csg3.md reports; the rounded pocket
#   (bhc_pocket.json, its solid by the rule of docs/csg3.md) has 9 mixed terms, needs 8 edge-vertex planes, then
#   has a verified tree (27 leaves) and an OpenSCAD program with the separators; --max-separators 3 stops short
#   (exit 3); --separators on a complex is refused (exit 2);
# - convert and samples on 3D CSG solids (issue 14 section 2): the BSH scene written, complements and complemented
#   copies where the solid runs along a halfspace reversed, exact `at` samples, the domain written out, and hsx
#   extract on the written file gives the solid's cells and volume back; solids reaching the domain refused; our
#   rebuild of the BSH CAD model (data/scenes3d/cad_notched.json): 23 samples = 23 components of 88 patches.
# Prints "N passed, M failed" and exits non-zero when anything failed.
set -u
hsx="$(realpath "${1:?usage: csg3_tests.sh HSX SOURCE_DIR}")"
src="$(realpath "${2:?usage: csg3_tests.sh HSX SOURCE_DIR}")"
source "$src/tests/cli/common.sh"
S3="$src/data/scenes3d"
json() { python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if eval("(" + sys.argv[2].strip() + ")") else 1)' "$1" "$2"; }
# check WHAT FILE PYTHON-EXPRESSION (d: the JSON document)
check() { if json "$2" "$3"; then ok; else bad "$1: $3 false on $2: $(head -c 300 "$2")"; fi; }

# ---- 3: volume, not area ----
CAD="Cyl & Top & Bottom & Slab & Notch | Ring1 | Ring2"
if expect 0 "" -- "$hsx" csg "$S3/cad_part.json" --csg "$CAD" --json cad.json; then
  check "3D csg: volume key, no area" cad.json '"volume" in d and "area" not in d and d["verified"] is True'
  has out "volume 13.37161106376118529" "3D csg summary"
  if grep -q "^area" out; then bad "3D csg summary says area"; else ok; fi
fi
# The volume is the one hsx extract reports for the same cells (the CSG tree's cells are the solid's).
if expect 0 "" -- "$hsx" csg "$src/data/figures/fig02-1.json" --csg "A & B" --json f2.json; then
  check "2D csg: area key" f2.json '"area" in d and "volume" not in d'
  has out "area " "2D csg summary"
fi

# ---- 2: pictures of 3D solids, witness cells of mixed terms ----
SPLIT="$S3/split_box.json"
expect 0 "" -- "$hsx" arrange "$SPLIT" --json split_complex.json
expect 0 "" -- "$hsx" extract "$SPLIT" --json split_any.json --no-timing
expect 0 "" -- python3 "$src/scripts/solid-by-witness" split_complex.json split_any.json \
  '"B" in inside and "C" not in inside and x < 0' left.json
check "solid-by-witness: one cell" left.json 'len(d["inside_cells"]) == 1'
if expect 3 "" -- "$hsx" describe "$SPLIT" --shape left.json --json d.json --svg d.svg; then
  has out "not describable by the 2 halfspaces (4 canonical intersection terms, 1 mixed)" "describe 3D summary"
  has out "mixed term B ~C: inside cells" "describe 3D mixed term"
  check "describe 3D JSON: one mixed term, inside and outside witness cells with 3 coordinates" d.json '
    d["describable"] is False and len(d["mixed_terms"]) == 1 and
    len(d["mixed_terms"][0]["witness"]["inside"]["point"]) == 3 and
    d["mixed_terms"][0]["signs"] == {"B": "in", "C": "out"}'
  # The two cells of B & ~C have 6 patches between them (each half: 5 of B's faces and 1 of C's), each a quad
  # of 2 triangles at least: both kinds of marks are present, faces are the shape's boundary.
  has d.svg 'class="mark-inside"' "describe 3D svg: inside witness cell"
  has d.svg 'class="mark-outside"' "describe 3D svg: outside witness cell"
  has d.svg "inside cells of the 1 mixed terms (in the solid) (1 cells;" "describe 3D svg legend"
  has d.svg 'class="face"' "describe 3D svg faces"
  expect 3 "" -- "$hsx" describe "$SPLIT" --shape left.json --svg d2.svg
  if cmp -s d.svg d2.svg; then ok; else bad "describe 3D svg not deterministic"; fi
fi
if expect 3 "" -- "$hsx" csg "$SPLIT" --shape left.json --svg c.svg --json c.json; then
  has c.svg 'class="face"' "csg 3D svg faces"
  if grep -q 'class="mark-' c.svg; then bad "csg 3D svg has marks"; else ok; fi
  check "csg 3D not describable: volume 6, mixed terms" c.json \
    'd["describable"] is False and d["volume"]["exact"] == "6" and len(d["mixed_terms"]) == 1'
fi
# A describable 3D solid's describe picture: no marks (no mixed term).
if expect 0 "" -- "$hsx" describe "$S3/cad_part.json" --csg "$CAD" --svg cad.svg; then
  has cad.svg 'class="face"' "describe 3D describable svg faces"
  if grep -q 'class="mark-' cad.svg; then bad "describable solid has marks"; else ok; fi
fi

# ---- 1: OpenSCAD in 3D ----
if expect 0 "" -- "$hsx" csg "$S3/cad_part.json" --csg "$CAD" --openscad cad.scad --json cad2.json; then
  expect 0 "" -- "$hsx" csg "$S3/cad_part.json" --csg "$CAD" --openscad cad2.scad
  if cmp -s cad.scad cad2.scad; then ok; else bad "3D openscad not deterministic"; fi
  has cad.scad "// hsx CSG expression as a 3D OpenSCAD program, with hsx's tessellation made explicit." "3D header"
  has cad.scad "// domain: [-4, -5, -2] to [4, 5, 4]" "3D domain"
  has cad.scad "  // Top (plane, the domain box clipped to it)" "3D plane leaf"
  has cad.scad "difference() {  // Notch (box, complement, 8 vertices, 12 triangles, subtracted from the domain box)" \
    "3D complemented box"
  has cad.scad "translate([-4, -5, -2]) cube([8, 10, 6]);" "3D domain cube"
  has cad.scad "  // Ring1 (torus, 128 vertices, 256 triangles)" "3D torus with its tessellation's counts"
  if python3 - cad.scad cad2.json <<'PY'
import json, re, sys
text = open(sys.argv[1]).read()
tree = json.load(open(sys.argv[2]))
leaves = tree["stats"]["leaves"]
polys = re.findall(r"polyhedron\(points = (\[.*?\]), faces = (\[.*?\])\);", text)
if len(polys) != leaves:
    sys.exit("%d polyhedra for %d leaves" % (len(polys), leaves))
volumes = []
for pts, fcs in polys:
    p = json.loads(pts); f = json.loads(fcs)
    edges = {}
    for face in f:
        for i in range(len(face)):
            e = (face[i], face[(i + 1) % len(face)])
            edges[e] = edges.get(e, 0) + 1
    if any(n != 1 or edges.get((b, a)) != 1 for (a, b), n in edges.items()):
        sys.exit("a polyhedron is not closed and consistently oriented")
    v = 0.0
    for face in f:
        a = p[face[0]]
        for i in range(1, len(face) - 1):
            b, c = p[face[i]], p[face[i + 1]]
            v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                  a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    if v >= 0:
        sys.exit("a polyhedron is not clockwise from outside (volume %g)" % v)
    volumes.append(-v)
# Top (z <= 2) and Bottom (z >= 0) clip the 8 x 10 x 6 domain box to z in [-2, 2] and [0, 4]: 320 each.
if sum(1 for v in volumes if abs(v - 320) < 1e-9) != 2:
    sys.exit("the two planes' polyhedra do not have volume 320: %r" % volumes)
PY
  then ok; else bad "3D openscad polyhedra (closed, clockwise, volumes)"; fi
  if command -v openscad >/dev/null 2>&1; then
    if timeout 300 openscad -o cad.stl cad.scad >openscad.log 2>&1 && [ -s cad.stl ]; then ok
    else bad "openscad failed on the 3D program: $(tail -c 300 openscad.log)"; fi
  else
    echo "openscad not installed: the 3D program was checked for structure only"
  fi
fi
expect 2 "--circle-segments: 2D only" -- "$hsx" csg "$S3/cad_part.json" --csg "$CAD" --openscad x.scad \
  --circle-segments 12
if [ -e x.scad ]; then bad "--circle-segments in 3D wrote the program"; else ok; fi
expect 2 "--circle-segments: only with --openscad" -- "$hsx" csg "$src/data/figures/fig02-1.json" --csg "A & B" \
  --circle-segments 12

# ---- 4 and 5: separating planes, the BHC objects ----
if expect 0 "" -- "$hsx" csg "$SPLIT" --shape left.json --separators --json sep.json; then
  has out "added 1 separating plane(s)" "split box: one plane"
  has out "round 1: 1 mixed terms (2 cells)" "split box: the round's line"
  check "split box --separators JSON" sep.json '
    d["verified"] is True and len(d["separators"]) == 1 and d["separators"][0]["kind"] == "plane" and
    d["separator_stop"] == "describable" and len(d["separator_rounds"]) == 1 and
    sum(t.get("chosen", False) for t in d["separator_rounds"][0]["trials"]) == 1 and
    d["volume"]["exact"] == "6"'
fi
expect 2 "--separators: needs a scene" -- "$hsx" csg split_complex.json --csg "B & ~C" --separators

BRACKET="X0 & Y0 & Y1 & Z0 & ((X1 & Z1 & Ch1) | (U1 & Z2 & Ch2) | (G0 & G1 & Gd) | Boss) & ~H1 & ~H2 & ~H3 & ~(S0 & S1 & Sz)"
expect 0 "" -- "$hsx" describe "$S3/bhc_bracket.json" --csg "$BRACKET"
has out "describable by the 20 halfspaces (342 canonical intersection terms, 0 mixed)" "bracket describable"
if expect 0 "" -- "$hsx" csg "$S3/bhc_bracket.json" --csg "$BRACKET" --json bracket.json; then
  check "bracket tree (docs/csg3.md)" bracket.json '
    d["verified"] is True and d["stats"]["leaves"] == 29 and d["stats"]["internal_nodes"] == 21 and
    d["stats"]["depth"] == 8 and d["stats"]["duplicated_halfspaces"] == 7 and d["stats"]["partitions"] == 2 and
    d["volume"]["decimal"].startswith("316.0258775148174053")'
fi

POCKET="$S3/bhc_pocket.json"
RULE='all(h in inside for h in ("BX0","BX1","BY0","BY1","BZ0","BZ1"))
  and not (z > 2 and abs(x) < 3 and abs(y) < Fraction(5, 2)
           and (abs(x) < 2 or abs(y) < Fraction(3, 2) or bool(inside & {"P1","P2","P3","P4"})))
  and not (abs(x) > 5 and abs(y) > 4 and not (inside & {"O1","O2","O3","O4"}))'
expect 0 "" -- "$hsx" arrange "$POCKET" --json pocket_complex.json
expect 0 "" -- "$hsx" extract "$POCKET" --json pocket_any.json --no-timing
expect 0 "" -- python3 "$src/scripts/solid-by-witness" pocket_complex.json pocket_any.json "$RULE" pocket.json
has out "37 cells" "pocket solid: 37 cells"
if expect 3 "" -- "$hsx" describe "$POCKET" --shape pocket.json --json pocket_d.json --svg pocket_d.svg; then
  has out "not describable by the 19 halfspaces (132 canonical intersection terms, 9 mixed)" "pocket witnesses"
  check "pocket: 8 single-pair terms and the pocket's 4 slivers against 1 pocket cell" pocket_d.json '
    sum(len(t["inside_cells"]) == 1 and len(t["outside_cells"]) == 1 for t in d["mixed_terms"]) == 8 and
    any(len(t["inside_cells"]) == 4 and len(t["outside_cells"]) == 1 for t in d["mixed_terms"])'
  has pocket_d.svg "inside cells of the 9 mixed terms (in the solid) (12 cells;" "pocket witness picture: inside"
  has pocket_d.svg "outside cells of the mixed terms (not in the solid, same sign vectors) (9 cells;" \
    "pocket witness picture: outside"
fi
expect 3 "" -- "$hsx" csg "$POCKET" --shape pocket.json --openscad never.scad
has out "(try --separators)" "pocket without separators"
has err "never.scad not written" "pocket without separators: no OpenSCAD"
if expect 0 "" -- "$hsx" csg "$POCKET" --shape pocket.json --separators --json pocket_t.json --openscad pocket.scad; then
  has out "added 8 separating plane(s)" "pocket: 8 planes"
  check "pocket: 8 edge-vertex vertical planes, verified tree of 27 leaves" pocket_t.json '
    d["verified"] is True and len(d["separators"]) == 8 and len(d["separator_rounds"]) == 8 and
    all(s["normal"][2] == 0 for s in d["separators"]) and
    all(t["origin"] == "edge-vertex" for r in d["separator_rounds"] for t in r["trials"] if t.get("chosen")) and
    [r["mixed_terms"] for r in d["separator_rounds"]] == [9, 7, 5, 3, 1, 1, 1, 1] and
    d["stats"]["leaves"] == 27 and d["stats"]["duplicated_halfspaces"] == 0 and
    d["volume"]["decimal"].startswith("418.1229349185668897")'
  has pocket.scad "  // sep7 (plane, the domain box clipped to it)" "pocket OpenSCAD has the separators"
fi
if expect 3 "" -- "$hsx" csg "$POCKET" --shape pocket.json --separators --max-separators 3 --json pocket_3.json; then
  has out "(stopped at --max-separators 3)" "pocket --max-separators 3"
  check "pocket --max-separators 3 JSON" pocket_3.json 'd["separator_stop"] == "max-separators" and len(d["separators"]) == 3'
fi
# docs/csg3.md: with 18 segments (not a multiple of 4) the blends fall short of their walls, the slivers merge with
# their neighbours (132 cells, not 164) and the same rule gives a describable solid; with 12 segments it is as 16.
for n in 12 18; do
  sed "s/\"segments\": 16/\"segments\": $n/g" "$POCKET" >pocket$n.json
  expect 0 "" -- "$hsx" arrange pocket$n.json --json pocket${n}_complex.json
  expect 0 "" -- "$hsx" extract pocket$n.json --json pocket${n}_any.json --no-timing
  expect 0 "" -- python3 "$src/scripts/solid-by-witness" pocket${n}_complex.json pocket${n}_any.json "$RULE" pocket${n}_s.json
done
check "12 segments: 164 cells" pocket12_complex.json 'len(d["cells"]) == 164'
check "18 segments: 132 cells" pocket18_complex.json 'len(d["cells"]) == 132'
expect 3 "" -- "$hsx" describe pocket12.json --shape pocket12_s.json
has out "(132 canonical intersection terms, 9 mixed)" "12 segments: 9 mixed terms"
expect 0 "" -- "$hsx" describe pocket18.json --shape pocket18_s.json
has out "(132 canonical intersection terms, 0 mixed)" "18 segments: describable"

# ---- issue 14 section 2: convert and samples on 3D CSG solids, checked by hsx extract on the written scene ----
# convert_check NAME SCENE EXPR SAMPLES FLIPPED: hsx convert writes a BSH scene with SAMPLES samples and FLIPPED
# complemented halfspaces (a Python list); hsx extract on the written file returns exactly the solid's cells
# (convert --json inside_cells), the same volume as hsx csg's on the input, and every sample is an exact `at`.
convert_check() {
  local name="$1" scene="$2" expr="$3" samples="$4" flipped="$5"
  expect 0 "" -- "$hsx" csg "$scene" --csg "$expr" --json "$name.csg.json" || return
  expect 0 "" -- "$hsx" convert "$scene" --csg "$expr" --out "$name.bsh.json" --json "$name.conv.json" || return
  has out "hsx extract gives the solid back: yes" "$name: convert summary"
  check "$name: convert JSON" "$name.conv.json" "d['dimension'] == 3 and d['round_trip'] is True and
    d['samples'] == $samples and d['complemented'] == $flipped and len(d['sample_patches']) == $samples"
  check "$name: written scene, 3D, domain given, exact at samples only" "$name.bsh.json" "
    d['dimension'] == 3 and 'domain' in d and len(d['samples']) == $samples and
    all(set(s) == {'on', 'at'} for s in d['samples'])"
  expect 0 "" -- "$hsx" extract "$name.bsh.json" --json "$name.back.json" --no-timing || return
  expect 0 "" -- python3 -c '
import json, sys
conv, back, tree = (json.load(open(f)) for f in sys.argv[1:4])
sys.exit(0 if back["inside_cells"] == conv["inside_cells"] and back["volume"]["exact"] == conv["volume"]["exact"]
         == tree["volume"]["exact"] else 1)' "$name.conv.json" "$name.back.json" "$name.csg.json"
}
# Union, difference (C complemented), and a solid running along both B and C both ways (complemented copies).
convert_check split_union "$SPLIT" "B | C" 3 '[]'
convert_check split_minus "$SPLIT" "B - C" 4 '["C"]'
convert_check split_xor "$SPLIT" "(B - C) | (C - B)" 6 '["B~ (a complemented copy of B)", "C~ (a complemented copy of C)"]'
check "xor: the written scene has the copies, complemented" split_xor.bsh.json '
  [(h["name"], h.get("complement", False)) for h in d["halfspaces"]] ==
  [("B", False), ("C", False), ("B~", True), ("C~", True)]'
# The CAD part (a complemented box, tori, a cylinder, planes): 9 samples, its 23 cells' solid back.
convert_check cad "$S3/cad_part.json" "$CAD" 9 '[]'
check "cad: bounds" cad.conv.json 'd["lower_bound"] == 9 and d["upper_bound"] == 15 and d["cells"] == 23'
# A solid reaching the domain box is refused (exit 2, nothing written).
expect 2 "reaches the domain boundary" -- "$hsx" convert "$SPLIT" --csg "~B" --out never.json
if [ -e never.json ]; then bad "convert wrote a file on bad input"; else ok; fi
# hsx samples on a 3D CSG solid: --out is checked by extracting it back; a target needing complements is refused
# with a pointer to convert.
if expect 0 "" -- "$hsx" samples "$S3/cad_part.json" --csg "$CAD" --out cad_s.json --json cad_sj.json; then
  has out "wrote cad_s.json; hsx extract gives the target back: yes" "samples --out 3D round trip"
  check "samples 3D JSON" cad_sj.json 'd["samples"] == 9 and d["reproduced"] is True and d["round_trip"] is True'
  check "samples 3D scene: the domain written out" cad_s.json '"domain" in d and len(d["samples"]) == 9'
  expect 0 "" -- "$hsx" extract cad_s.json --json cad_s_back.json --no-timing
  expect 0 "" -- python3 -c '
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
sys.exit(0 if a["inside_cells"] == b["inside_cells"] else 1)' cad.conv.json cad_s_back.json
fi
expect 2 "(hsx convert complements such halfspaces)" -- "$hsx" samples "$SPLIT" --csg "B - C" --out never.json
if [ -e never.json ]; then bad "samples wrote a file on bad input"; else ok; fi

# Our rebuild of the BSH paper's CAD model (Fig. 19(a); data/scenes3d/cad_notched.json, docs/csg3.md): a cylinder
# and a prism, minus three notches, union six tori. BHC gives each of the 17 halfspaces once; the conversion needs
# 23 samples, the lower bound (23 components), of 88 boundary patches; extracting the written scene gives it back.
NOTCHED="(Cyl & X0 & Y0 & Top & Bottom) - (~X1 & ~Y1 & ~M1 & ~M2) - (~X1 & ~Y1 & ~U) - (~X1 & ~Y1 & ~L) | T1 | T2 | T3 | T4 | T5 | T6"
convert_check notched "$S3/cad_notched.json" "$NOTCHED" 23 '[]'
check "notched: bounds (Table 1's lower bound reached)" notched.conv.json \
  'd["lower_bound"] == 23 and d["upper_bound"] == 88 and d["rounds"] == 1 and d["cells"] == 167'
check "notched: BHC tree, each halfspace once" notched.csg.json '
  d["verified"] is True and d["stats"]["leaves"] == 17 and d["stats"]["duplicated_halfspaces"] == 0 and
  d["stats"]["internal_nodes"] == 5 and
  d["text"] == "T1 | T2 | T3 | T4 | T5 | T6 | Cyl & X0 & Y0 & Top & Bottom & (X1 | Y1 | U & L & (M1 | M2))"'

finish
