#!/usr/bin/env bash
# `hsx extract` on 3D scenes (issue 13, section 1, the outputs): on every bundled 3D scene the boundary mesh written
# with --obj (exact coordinates), --ply and --off is closed (every directed edge used as often as its reverse),
# has one face per boundary triangle the result names, per-face patch and halfspace labels that agree with the
# result's boundary, and an exact divergence-theorem volume equal to the result's exact volume; the summary gives
# long closed forms as a number of terms; --svg and --states-svg draw the shape and one panel per state; --png and
# --states-png write valid, reproducible PNGs with the expected colours; bad requests exit 2 and write nothing.
# Usage: extract3_tests.sh HSX SOURCE_DIR
set -u
hsx="$(realpath "${1:?usage: extract3_tests.sh HSX SOURCE_DIR}")"; src="$(realpath "${2:?usage}")"
scenes="$src/data/scenes3d"
source "$src/tests/cli/common.sh"

# check_mesh NAME: the meshes of $work/NAME.{json,obj,ply,off} against the result; prints problems, one a line.
check_mesh() {
  python3 - "$work/$1" <<'PY'
import json, sys
from fractions import Fraction
base = sys.argv[1]
result = json.load(open(base + ".json"))
problems = []

def closed(faces, what):
    directed = {}
    for f in faces:
        for k in range(3):
            e = (f[k], f[(k + 1) % 3])
            directed[e] = directed.get(e, 0) + 1
    for (a, b), n in directed.items():
        if directed.get((b, a), 0) != n:
            problems.append("%s: edge %d-%d used %d times, reversed %d" % (what, a, b, n, directed.get((b, a), 0)))
            return

triangles = sum(item["triangles"] for item in result["boundary"])
# OBJ with exact coordinates: groups and materials per face, the exact volume.
vertices, faces, groups, materials = [], [], [], []
group = material = None
for line in open(base + ".obj"):
    w = line.split()
    if not w: continue
    if w[0] == "v": vertices.append([Fraction(x) for x in w[1:4]])
    if w[0] == "g": group = int(w[1][len("patch_"):])
    if w[0] == "usemtl": material = int(w[1][len("halfspace_"):])
    if w[0] == "f":
        faces.append([int(x) - 1 for x in w[1:4]]); groups.append(group); materials.append(material)
if len(faces) != triangles: problems.append("obj: %d faces, the result's boundary has %d triangles" % (len(faces), triangles))
closed(faces, "obj")
def det(a, b, c):
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]))
volume = sum(det(vertices[f[0]], vertices[f[1]], vertices[f[2]]) for f in faces) / 6
if volume != Fraction(result["volume"]["exact"]):
    problems.append("obj: divergence volume %s != the result's %s" % (volume, result["volume"]["exact"]))
names = {item["patch"]: item["halfspace"] for item in result["boundary"]}
per_patch = {}
for g in groups: per_patch[g] = per_patch.get(g, 0) + 1
expected = {item["patch"]: item["triangles"] for item in result["boundary"]}
if per_patch != expected: problems.append("obj: faces per patch %s, the result says %s" % (per_patch, expected))
# PLY: the same faces with patch and halfspace properties.
ply = open(base + ".ply").read().split("end_header\n")[1].splitlines()
header = open(base + ".ply").read().split("end_header\n")[0]
nv = int(header.split("element vertex ")[1].split()[0])
ply_faces = [list(map(int, l.split())) for l in ply[nv:]]
if len(ply_faces) != triangles: problems.append("ply: %d faces" % len(ply_faces))
closed([f[1:4] for f in ply_faces], "ply")
if sorted(set((f[4]) for f in ply_faces)) != sorted(expected): problems.append("ply: patches differ from the result's")
# OFF: patch ranges in comments, faces after the counts.
off = open(base + ".off").read().splitlines()
ranges = [l.split() for l in off if l.startswith("# patch ")]
counts = [l for l in off if l and not l.startswith("#")][1].split()
off_faces = [list(map(int, l.split()[1:4])) for l in off if l.startswith("3 ") and len(l.split()) == 7]
if int(counts[1]) != triangles or len(off_faces) != triangles: problems.append("off: %s faces" % counts[1])
closed(off_faces, "off")
if {int(r[2]): int(r[7]) for r in ranges} != expected: problems.append("off: patch ranges differ from the result's")
if result["volume"]["exact"].count("sqrt") or "terms" not in result["boundary_area"]:
    problems.append("json: volume not rational or boundary_area without terms")
print("\n".join(problems))
PY
}

# Every bundled 3D scene: beam K = 1 with every output; the meshes agree with the result.
for scene in "$scenes"/*.json; do
  name="$(basename "$scene" .json)"
  expect 0 "" -- "$hsx" extract "$scene" --no-timing --json "$work/$name.json" --obj "$work/$name.obj" \
    --exact-coordinates --ply "$work/$name.ply" --off "$work/$name.off" --svg "$work/$name.svg" || continue
  for f in json obj mtl ply off svg; do [ -s "$work/$name.$f" ] && ok || bad "$name.$f not written"; done
  problems="$(check_mesh "$name")"
  [ -z "$problems" ] && ok || bad "$name: $problems"
  cp "$work/out" "$work/$name.txt"
  # The summary stays short: long closed forms are counted, not printed.
  [ "$(wc -c <"$work/$name.txt")" -lt 4000 ] && ok || bad "$name: summary of $(wc -c <"$work/$name.txt") bytes"
done
has "$work/primitives.txt" "boundary area 91.46119950097825" "primitives: the boundary area"
has "$work/primitives.txt" "(closed form: 45 terms, " "primitives: the area's closed form counted"
has "$work/primitives.txt" "volume 25.17691453746334" "primitives: the volume"
has "$work/primitives.txt" "= 124670042286368123058828862129/4951760157141521099596496896" "primitives: exact volume"

# Beam and best-first: --states-svg has one panel per state along the path, the removed patches highlighted.
for method in beam best-first; do
  expect 0 "" -- "$hsx" extract "$scenes/primitives.json" --method "$method" --json "$work/s.json" \
    --states-svg "$work/states_$method.svg" --svg "$work/shape_$method.svg" --show-removed || continue
  python3 - "$work/s.json" "$work/states_$method.svg" "$work/shape_$method.svg" <<'PY' >"$work/states.txt"
import json, sys, xml.etree.ElementTree as ET
result = json.load(open(sys.argv[1]))
ns = "{http://www.w3.org/2000/svg}"
root = ET.parse(sys.argv[2]).getroot()
panels = [c for c in root if c.tag == ns + "svg"]
problems = []
if len(panels) != len(result["steps"]): problems.append("%d panels for %d steps" % (len(panels), len(result["steps"])))
# Each patch is drawn once in <defs>; the panels refer to it with <use> (class "face" or "highlight").
xlink = "{http://www.w3.org/1999/xlink}href"
ids = [g.get("id") for d in root.iter(ns + "defs") for g in d if g.get("id")]
if len(ids) != len(set(ids)): problems.append("duplicate ids in <defs>")
for k, (panel, removed) in enumerate(zip(panels, result["steps"])):
    if any(True for _ in panel.iter(ns + "polygon")): problems.append("state %d: polygons drawn in the panel" % k)
    uses = list(panel.iter(ns + "use"))
    missing = [u.get(xlink) for u in uses if u.get(xlink, "")[1:] not in ids]
    if missing: problems.append("state %d: <use> of undefined %s" % (k, missing[:3]))
    lit = sorted({int(u.get("data-patch")) for u in uses if u.get("class") == "highlight"})
    if lit != sorted(removed): problems.append("state %d: highlighted %s, removed %s" % (k, lit, removed))
    if not any(u.get("class") == "face" for u in uses): problems.append("state %d: no face" % k)
shape = ET.parse(sys.argv[3]).getroot()
lit = sorted({int(p.get("data-patch")) for p in shape.iter(ns + "polygon") if p.get("class") == "highlight"})
if lit != sorted(result["removed_patches"]): problems.append("--show-removed: %s vs %s" % (lit, result["removed_patches"]))
faces = {int(p.get("data-patch")) for p in shape.iter(ns + "polygon") if p.get("class") == "face"}
if faces != {b["patch"] for b in result["boundary"]}: problems.append("--svg: faces of patches %s" % sorted(faces))
print("\n".join(problems))
PY
  [ -z "$(cat "$work/states.txt")" ] && ok || bad "$method states: $(cat "$work/states.txt")"
  # Size: each patch is drawn once for all the panels (one isometric view each), so the states picture stays below
  # half the single-shape --svg (four views); redrawing every triangle per panel made it larger than that.
  states_bytes=$(wc -c <"$work/states_$method.svg"); shape_bytes=$(wc -c <"$work/shape_$method.svg")
  [ $((2 * states_bytes)) -lt "$shape_bytes" ] && ok ||
    bad "$method: states picture of $states_bytes bytes against $shape_bytes for the shape"
done
# The SVG pictures render with rsvg-convert where it is installed.
if command -v rsvg-convert >/dev/null; then
  for f in states_beam shape_best-first primitives; do
    rsvg-convert "$work/$f.svg" -o "$work/$f.png" 2>"$work/err" && [ -s "$work/$f.png" ] && ok ||
      bad "rsvg-convert $f.svg: $(head -c 300 "$work/err")"
  done
else
  echo "note: rsvg-convert not installed, the pictures were not rendered"
fi

# --png and --states-png (3D): valid PNGs (signature, IHDR size), the same bytes on every run, and on a box alone
# in its domain the expected colours: white background, and at the front view's centre the box's front face in its
# halfspace's colour #1f77b4 times the light factor 0.35 + 0.65 |n . l| (n = (0, 1, 0), l along
# (-0.4, -1, 0.5): 0.35 + 0.65 / sqrt(1.41)), as io/svg3.hpp's conventions say.
cat >"$work/box.json" <<'JSON'
{"format": "hsx-scene/1", "dimension": 3, "domain": {"min": [-2, -2, -2], "max": [2, 2, 2]},
 "halfspaces": [{"name": "B", "kind": "box", "min": [-1, -1, -1], "max": [1, 1, 1]}],
 "samples": [{"on": "B", "at": [1, "1/2", "1/2"]}]}
JSON
for run in 1 2; do
  expect 0 "" -- "$hsx" extract "$work/box.json" -q --png "$work/box$run.png" --states-png "$work/box_states$run.png"
done
cmp -s "$work/box1.png" "$work/box2.png" && ok || bad "--png: two runs wrote different bytes"
cmp -s "$work/box_states1.png" "$work/box_states2.png" && ok || bad "--states-png: two runs wrote different bytes"
expect 0 "" -- "$hsx" extract "$scenes/primitives.json" -q --method best-first --show-removed \
  --png "$work/prim.png" --states-png "$work/prim_states.png" --json "$work/prim_states.json"
python3 - "$work" <<'PY' >"$work/png.txt"
import json, math, struct, sys, zlib
work = sys.argv[1]
problems = []

def decode(path):
    """(width, height, rows of RGB bytes) of an 8-bit RGB PNG, or a problem."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n": return "no PNG signature"
    pos, idat, ihdr = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if zlib.crc32(kind + body) != struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])[0]:
            return "bad CRC in " + kind.decode()
        if kind == b"IHDR": ihdr = struct.unpack(">IIBBBBB", body)
        if kind == b"IDAT": idat += body
        pos += 12 + length
    if ihdr is None or data[12:16] != b"IHDR": return "IHDR is not the first chunk"
    width, height, depth, colour = ihdr[:4]
    if (depth, colour) != (8, 2): return "not 8-bit RGB: %s" % (ihdr,)
    raw, stride, rows, prev = zlib.decompress(idat), 3 * width, [], bytearray(3 * width)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b, c = prev[i], (prev[i - 3] if i >= 3 else 0)
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, rows

def pixel(image, x, y): return tuple(image[2][y][3 * x:3 * x + 3])

box = decode(work + "/box1.png")
if isinstance(box, str): problems.append("box.png: " + box)
else:
    if box[:2] != (1000, 1000): problems.append("box.png: %dx%d, not 1000x1000" % box[:2])
    if pixel(box, 2, 2) != (255, 255, 255): problems.append("box.png: background %s" % (pixel(box, 2, 2),))
    factor = 0.35 + 0.65 / math.sqrt(1.41)
    want = tuple(round(c * factor) for c in (0x1f, 0x77, 0xb4))
    # The front view's centre: margin 16 + half of the 484 px panel across; 16 + caption 22.4 + (484 - 22.4) / 2 down.
    got = pixel(box, 258, 269)
    if any(abs(g - w) > 1 for g, w in zip(got, want)): problems.append("box.png: front face %s, want %s" % (got, want))
states = decode(work + "/box_states1.png")
if isinstance(states, str): problems.append("box_states.png: " + states)
elif states[0] != 8 + 568: problems.append("box_states.png: %d px wide for one panel" % states[0])
steps = len(json.load(open(work + "/prim_states.json"))["steps"])
prim = decode(work + "/prim_states.png")
if isinstance(prim, str): problems.append("prim_states.png: " + prim)
elif prim[0] != 8 + min(steps, 3) * 568: problems.append("prim_states.png: %d px wide for %d states" % (prim[0], steps))
print("\n".join(problems))
PY
[ -z "$(cat "$work/png.txt")" ] && ok || bad "PNG: $(cat "$work/png.txt")"
expect 2 "--png: PNG pictures need a 3D scene" -- "$hsx" extract "$src/data/scenes/lens.json" --png "$work/lens.png" \
  --json "$work/lens_png.json"
[ -e "$work/lens.png" ] || [ -e "$work/lens_png.json" ] && bad "a refused --png left files" || ok
expect 2 "--states-png" -- "$hsx" extract "$work/box.json" --method exact --states-png "$work/exact.png"
[ -e "$work/exact.png" ] && bad "a refused --states-png left its file" || ok

# 2D scenes keep their outputs; --states-svg draws 2D states too.
expect 0 "" -- "$hsx" extract "$src/data/scenes/lens.json" --states-svg "$work/lens_states.svg"
has "$work/lens_states.svg" "state 0: graph cut" "2D states"

# Bad requests: exit 2, nothing written.
expect 2 "needs a 3D scene" -- "$hsx" extract "$src/data/scenes/lens.json" --obj "$work/lens.obj" --json "$work/lens.json"
[ -e "$work/lens.obj" ] || [ -e "$work/lens.json" ] && bad "a refused --obj left files" || ok
expect 2 "--obj" -- "$hsx" extract "$scenes/planes.json" --obj -
expect 2 "--states-svg" -- "$hsx" extract "$scenes/planes.json" --method graphcut --states-svg "$work/g.svg"
[ -e "$work/g.svg" ] && bad "a refused --states-svg left its file" || ok
if ls -a "$work" | grep -q 'tmp-hsx'; then bad "temporary files left: $(ls -a "$work" | grep tmp-hsx)"; else ok; fi

finish
