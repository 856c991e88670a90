"""3D: a bundled 3D scene arranged, extracted, its boundary mesh closed and its volume the CLI's."""
import collections
import json
import subprocess
from fractions import Fraction

import numpy as np
import pytest

import hsx


def test_3d_boundary_mesh_closed_and_volume_matches_cli(source_dir, hsx_program, tmp_path):
    path = source_dir / "data" / "scenes3d" / "primitives.json"
    c = hsx.load(str(path))
    r = hsx.extract(c, method="graphcut")
    v, f, patch, hs = r.boundary_mesh()
    assert v.shape[1] == 3 and f.shape[1] == 3 and len(f) > 0
    assert patch.shape == (len(f),) and hs.shape == (len(f),)
    edges = collections.Counter()
    for a, b, d in f:
        for x, y in ((a, b), (b, d), (d, a)):
            edges[(int(x), int(y))] += 1
    for (x, y), k in edges.items():
        assert edges[(y, x)] == k
    ve, fe, _, _ = r.boundary_mesh(exact=True)
    q = [[Fraction(s) for s in row] for row in ve]

    def det(a, b, d):
        return (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
                + a[2] * (b[0] * d[1] - b[1] * d[0]))

    volume = sum(det(q[a], q[b], q[d]) for a, b, d in fe) / 6
    out = tmp_path / "r.json"
    subprocess.run([hsx_program, "extract", str(path), "--method", "graphcut", "--json", str(out)],
                   capture_output=True, text=True, check=True)
    doc = json.loads(out.read_text())
    assert volume == Fraction(doc["volume"]["exact"])
    assert float(volume) == pytest.approx(float(doc["volume"]["decimal"]), rel=1e-12)

def test_2d_result_has_no_boundary_mesh(scenes_dir):
    r = hsx.extract(hsx.load(str(next(scenes_dir.glob("*.json")))), method="graphcut")
    with pytest.raises(hsx.InputError):
        r.boundary_mesh()


def test_bad_3d_input_raises():
    with pytest.raises(hsx.InputError):
        hsx.arrange('{"format": "hsx-scene/1", "dimension": 3, "halfspaces": [{"kind": "sphere"}]}')


# ---- 3D scenes built programmatically (hsx.Scene3 and the 3D builders) ----

SCENES3 = ["boxes_coincident", "cad_part", "coplanar_faces", "four_tori", "mesh_obj", "mesh_off", "mesh_ply",
           "nested_cavity", "planes", "primitives", "sphere_cavity", "spheres_flipped_torus", "tangent_planes",
           "torus_spheres"]


def _tessellation_keywords(entry):
    t = entry.get("tessellation", {})
    return {k: (Fraction(v) if k == "edge_length" else v) for k, v in t.items()}


def builder_of(entry, directory):
    """The hsx builder call for one halfspace of a bundled 3D file (numbers as Fractions, never the file's text)."""
    def p(key):
        return tuple(Fraction(x) for x in entry[key])

    kind, name, comp = entry["kind"], entry["name"], entry.get("complement", False)
    tk = _tessellation_keywords(entry)
    if kind == "plane":
        h = hsx.Plane(p("normal"), Fraction(entry["offset"]), name)
    elif kind == "box":
        h = hsx.Box(p("min"), p("max"), name)
    elif kind == "sphere":
        h = hsx.Sphere(p("center"), Fraction(entry["radius"]), name, **tk)
    elif kind == "cylinder":
        h = hsx.Cylinder(p("axis_point1"), p("axis_point2"), Fraction(entry["radius"]), name,
                         infinite=entry.get("infinite", False), **tk)
    elif kind == "cone":
        h = hsx.Cone(p("apex"), p("base_center"), Fraction(entry["radius"]), name, **tk)
    elif kind == "torus":
        h = hsx.Torus(p("center"), p("axis"), Fraction(entry["major_radius"]), Fraction(entry["minor_radius"]),
                      name, **tk)
    elif kind == "mesh":
        h = hsx.Mesh(directory / entry["file"], name)  # absolute: the scene built here has no file
    else:
        raise AssertionError(f"a kind the builders do not cover: {kind}")
    return ~h if comp else h


def built_scene(path):
    doc = json.loads(path.read_text(), parse_float=str)
    domain = doc.get("domain")
    scene = hsx.Scene3([builder_of(e, path.parent) for e in doc["halfspaces"]],
                       domain=None if domain is None else (tuple(map(Fraction, domain["min"])),
                                                           tuple(map(Fraction, domain["max"]))),
                       description=doc.get("description"))
    for s in doc.get("samples", []):
        key = "at" if "at" in s else "near"
        scene.sample(s["on"], **{key: tuple(Fraction(x) for x in s[key])})
    return scene, doc


@pytest.mark.parametrize("name", SCENES3)
def test_built_scene_matches_the_file_and_the_cli(name, source_dir, hsx_program, tmp_path):
    path = source_dir / "data" / "scenes3d" / f"{name}.json"
    scene, doc = built_scene(path)
    assert isinstance(scene, hsx.Scene3) and isinstance(scene, hsx.Scene)
    assert sorted({h["kind"] for h in scene.to_dict()["halfspaces"]}) == sorted({h["kind"] for h in doc["halfspaces"]})
    c = hsx.arrange(scene)
    assert c.dimension == 3 and c.has_scene
    # the CLI on the file: the arrangement's counts and identity, the graph cut's exact volume
    arranged = tmp_path / "a.json"
    subprocess.run([hsx_program, "arrange", str(path), "--json", str(arranged)], capture_output=True, text=True,
                   check=True)
    counts = json.loads(arranged.read_text())["counts"]
    assert (len(c.cells), len(c.patches), len(c.junctions), len(c.samples), c.outer_cell_count) == (
        counts["cells"], counts["patches"], counts["junctions"], counts["samples"], counts["outer_cells"])
    assert c.identity == hsx.load(str(path)).identity
    result = tmp_path / "r.json"
    subprocess.run([hsx_program, "extract", str(path), "--method", "graphcut", "--json", str(result)],
                   capture_output=True, text=True, check=True)
    cli = json.loads(result.read_text())
    r = hsx.extract(scene, method="graphcut")
    assert r.complex.identity == cli["complex_id"]
    assert r.volume.rational == Fraction(cli["volume"]["exact"])
    assert r.volume.exact == cli["volume"]["exact"] or Fraction(r.volume.exact) == Fraction(cli["volume"]["exact"])
    assert sorted(r.inside_cells) == sorted(cli["inside_cells"])


def test_primitives_by_hand_and_round_trips(source_dir):
    F = Fraction
    s = hsx.Scene3([hsx.Torus((0, 0, 0), (0, 0, 1), 3, F(1, 2), "T", segments=24, minor_segments=8),
                    hsx.Cone((0, 0, 4), (0, 0, 1), 2, "K", segments=12),
                    hsx.Cylinder((-4, 0, 0), (4, 0, 0), 1, "C", edge_length="1/2"),
                    ~hsx.Cylinder((0, 0, 0), (0, 1, 0), 5, "I", infinite=True, segments=16)],
                   domain=((-6, -6, -6), (6, 6, 6)))
    s.sample("T", near=(3, 0, 1))
    s.sample("K", near=(0, 0, 5))
    s.sample(s.to_dict()["halfspaces"][3]["name"], near=(6, 0, 0))
    path = source_dir / "data" / "scenes3d" / "primitives.json"
    assert hsx.arrange(s).identity == hsx.load(str(path)).identity
    d = s.to_dict()
    assert d["dimension"] == 3 and d["halfspaces"][0]["minor_radius"] == "1/2"
    assert d["halfspaces"][0]["tessellation"] == {"segments": 24, "minor_segments": 8}
    assert d["halfspaces"][2]["tessellation"] == {"edge_length": "1/2"}
    assert d["halfspaces"][3]["infinite"] is True and d["halfspaces"][3]["complement"] is True
    assert hsx.arrange(d).identity == hsx.arrange(s).identity  # a dict goes through Scene.from_dict
    again = hsx.Scene.from_dict(d)
    assert isinstance(again, hsx.Scene3) and again.to_json() == s.to_json()
    from_text = hsx.Scene.from_json(s.to_json())
    assert isinstance(from_text, hsx.Scene3)
    assert hsx.arrange(from_text).identity == hsx.arrange(s).identity
    # a file read as text comes back as a dict with exact numbers (hsx's writer: every primitive's tessellation)
    f = hsx.Scene.from_file(path)
    assert isinstance(f, hsx.Scene3) and f.halfspace_names == ["T", "K", "C", "I"]
    assert hsx.arrange(hsx.Scene3.from_dict(f.to_dict())).identity == hsx.arrange(f).identity
    # unnamed halfspaces are named by position; the default tessellation is the reader's
    u = hsx.Scene3([hsx.Sphere((0, 0, 0), 1), hsx.Box((-2, -2, -2), (0, 0, 0))])
    assert hsx.arrange(u).halfspaces == ["H0", "H1"]
    assert "tessellation" not in u.to_dict()["halfspaces"][0]
    assert hsx.arrange(u).identity == hsx.arrange(hsx.Scene3(
        [hsx.Sphere((0, 0, 0), 1, "H0", segments=32), hsx.Box((-2, -2, -2), (0, 0, 0), "H1")])).identity
    assert repr(u) == "<hsx.Scene3: 2 halfspaces, 0 samples>"


def test_3d_numbers_are_exact():
    with pytest.raises(TypeError, match=r"radius: 0\.5 is a float"):
        hsx.Sphere((0, 0, 0), 0.5)
    with pytest.raises(TypeError, match=r"center\[2\]: 0\.5 is a float"):
        hsx.Sphere((0, 0, 0.5), 1)
    with pytest.raises(TypeError, match=r"tessellation\.edge_length: 0\.1 is a float"):
        hsx.Cylinder((0, 0, 0), (0, 0, 1), 1, edge_length=0.1)
    with pytest.raises(TypeError, match="a number of segments is an int"):
        hsx.Sphere((0, 0, 0), 1, segments=16.0)
    with pytest.raises(TypeError, match="a 3D point has 3 coordinates, got 2"):
        hsx.Plane((0, 1), 0)
    with pytest.raises(TypeError, match="infinite: a bool"):
        hsx.Cylinder((0, 0, 0), (0, 0, 1), 1, infinite=1)
    s = hsx.Sphere((0, 0, 0), 0.1, "S", exact_from_float=True, edge_length=0.25)
    assert Fraction(s.to_dict()["radius"]) == Fraction(0.1) != Fraction(1, 10)
    assert s.to_dict()["tessellation"] == {"edge_length": "1/4"}
    # "0.1" as a string is 1/10 exactly, as the reader reads it
    a = hsx.arrange(hsx.Scene3([hsx.Box((0, 0, 0), ("0.1", 1, 1), "B")], domain=((-1, -1, -1), (2, 2, 2))))
    inner = [c for c in a.cells if not c.outer]
    assert len(inner) == 1 and inner[0].measure.rational == Fraction(1, 10)


def test_dimensions_do_not_mix():
    with pytest.raises(TypeError, match=r"Scene3\.add: a Plane, Box.*got a 2D Disk"):
        hsx.Scene3([hsx.Disk((0, 0), 1)])
    with pytest.raises(TypeError, match=r"Scene\.add: a HalfPlane, Disk or Polygon, got a 3D Sphere"):
        hsx.Scene([hsx.Sphere((0, 0, 0), 1)])
    s = hsx.Scene3([hsx.Sphere((0, 0, 0), 1, "S")])
    with pytest.raises(TypeError, match="has 2 coordinates; a 3D scene needs 3"):
        s.sample("S", at=(1, 0))
    with pytest.raises(hsx.InputError, match="dimension: expected 3, got 2"):
        hsx.Scene3.from_dict({"format": "hsx-scene/1", "dimension": 2, "halfspaces": []})
    assert type(hsx.Scene.from_dict({"format": "hsx-scene/1", "dimension": 2, "halfspaces": []})) is hsx.Scene
    assert type(hsx.Scene.from_json('{"input": []}')) is hsx.Scene3  # a BSH authors' config.json is 3D
    assert type(hsx.Scene.from_json("{not json")) is hsx.Scene  # hsx reports it when arranged
    with pytest.raises(hsx.InputError):
        hsx.arrange(hsx.Scene.from_json("{not json"))


def test_3d_builder_errors_carry_the_cli_messages(tmp_path):
    with pytest.raises(hsx.InputError, match=r"halfspaces\[0\]\.radius: must be positive"):
        hsx.arrange(hsx.Scene3([hsx.Sphere((0, 0, 0), 0, "S")]))
    with pytest.raises(hsx.InputError, match=r"minor_radius: must be below major_radius"):
        hsx.arrange(hsx.Scene3([hsx.Torus((0, 0, 0), (0, 0, 1), 1, 2, "T")]))
    with pytest.raises(hsx.InputError, match=r"give \"segments\" or \"edge_length\", not both"):
        hsx.arrange(hsx.Scene3([hsx.Sphere((0, 0, 0), 1, "S", segments=8, edge_length=1)]))
    with pytest.raises(hsx.InputError, match="infinite cylinder is clipped by the domain"):
        hsx.arrange(hsx.Scene3([hsx.Cylinder((0, 0, 0), (0, 0, 1), 1, "C", infinite=True)]))
    with pytest.raises(hsx.InputError, match=r"halfspaces\[0\]\.file"):
        hsx.arrange(hsx.Scene3([hsx.Mesh(tmp_path / "missing.obj", "M")]))
    s = hsx.Scene3([hsx.Sphere((0, 0, 0), 1, "S", segments=8)])
    s.sample("S", at=(5, 5, 5))
    with pytest.raises(hsx.InputError, match=r"samples\[0\]"):
        hsx.arrange(s)


@pytest.mark.parametrize("name", ["cad_part", "nested_cavity", "mesh_ply"])
def test_built_scene_extracts_checks_grades_as_the_cli(name, source_dir, hsx_program, tmp_path):
    path = source_dir / "data" / "scenes3d" / f"{name}.json"
    scene, _ = built_scene(path)
    for method in ("exact", "beam"):
        out = tmp_path / f"{method}.json"
        subprocess.run([hsx_program, "extract", str(path), "--method", method, "--json", str(out), "--no-timing"],
                       capture_output=True, text=True, check=True)
        assert hsx.extract(scene, method=method).to_json() == out.read_text(), method
    out = tmp_path / "check.json"
    p = subprocess.run([hsx_program, "check", str(path), "--json", str(out)], capture_output=True, text=True)
    assert p.returncode in (0, 3), p.stderr
    cli = [(c["check"], c["status"], c["witness"]) for c in json.loads(out.read_text())["checks"]]
    assert cli == [(c.name, c.status, c.witness) for c in hsx.check(scene)]
    r = hsx.extract(scene, method="exact")
    g = hsx.grade(scene, r.labelling)
    assert g.optimal and g.energy.compare(r.energy) == hsx.Order.Equal


def test_3d_samples_scene_json_reproduces_the_shape(source_dir):
    c = hsx.arrange(built_scene(source_dir / "data" / "scenes3d" / "nested_cavity.json")[0])
    target = hsx.extract(c, method="exact")
    s = hsx.samples(c, target=target)
    assert s.reproduced
    text = s.scene_json()
    doc = json.loads(text)
    assert doc["dimension"] == 3 and len(doc["samples"]) == s.count
    again = hsx.extract(text, method="exact")
    assert list(again.labelling) == list(target.labelling)


# ---- 3D surfaces as numpy arrays, against the CLI's mesh files ----

def read_ply(text):
    lines = text.splitlines()
    end = lines.index("end_header")
    nv = int(next(line for line in lines if line.startswith("element vertex")).split()[2])
    nf = int(next(line for line in lines if line.startswith("element face")).split()[2])
    vertices = [[float(x) for x in line.split()] for line in lines[end + 1:end + 1 + nv]]
    faces = [[int(x) for x in line.split()] for line in lines[end + 1 + nv:end + 1 + nv + nf]]
    return vertices, faces


@pytest.mark.parametrize("name", ["cad_part", "mesh_obj", "boxes_coincident"])
def test_surface_mesh_is_the_cli_ply(name, source_dir, hsx_program, tmp_path):
    path = source_dir / "data" / "scenes3d" / f"{name}.json"
    c = hsx.load(str(path))
    v, f, patch, hs = c.surface_mesh()
    assert v.dtype == np.float64 and v.shape[1] == 3
    assert f.dtype == np.int64 and f.shape[1] == 3 and patch.shape == hs.shape == (len(f),)
    ply = tmp_path / "a.ply"
    cx_json = tmp_path / "a.json"
    subprocess.run([hsx_program, "arrange", str(path), "--ply", str(ply), "--json", str(cx_json)],
                   capture_output=True, text=True, check=True)
    pv, pf = read_ply(ply.read_text())
    assert v.tolist() == pv  # %.17g reads back as the same doubles
    assert f.tolist() == [row[1:4] for row in pf]
    assert patch.tolist() == [row[4] for row in pf] and hs.tolist() == [row[5] for row in pf]
    # exact vertices: the arrangement's (hsx-complex/1 geometry), those of the exported faces, ascending
    geometry = json.loads(cx_json.read_text())["geometry"]
    used = sorted({k for t in geometry["triangles"] if not t["on_box"] and t["halfspaces"] for k in t["vertices"]})
    ve, fe, pe, he = c.surface_mesh(exact=True)
    assert [tuple(map(Fraction, row)) for row in ve] == [tuple(map(Fraction, geometry["vertices"][k])) for k in used]
    assert fe.tolist() == f.tolist() and pe.tolist() == patch.tolist() and he.tolist() == hs.tolist()
    # every face lies on its halfspace's patch; every patch of the complex that is first in its group has faces
    for k in set(patch.tolist()):
        assert c.patches[k].halfspace_index == int(hs[patch == k][0])


def test_boundary_mesh_is_the_cli_off(source_dir, hsx_program, tmp_path):
    path = source_dir / "data" / "scenes3d" / "cad_part.json"
    r = hsx.extract(hsx.load(str(path)), method="beam")
    off = tmp_path / "s.off"
    subprocess.run([hsx_program, "extract", str(path), "--method", "beam", "--off", str(off),
                    "--exact-coordinates"], capture_output=True, text=True, check=True)
    lines = [line for line in off.read_text().splitlines() if not line.startswith("#")]
    nv, nf, _ = map(int, lines[1].split())
    ve, fe, patch, hs = r.boundary_mesh(exact=True)
    assert [list(map(Fraction, row)) for row in ve] == [list(map(Fraction, line.split())) for line in lines[2:2 + nv]]
    assert fe.tolist() == [list(map(int, line.split()[1:4])) for line in lines[2 + nv:2 + nv + nf]]
    ranges = [line.split() for line in off.read_text().splitlines() if line.startswith("# patch ")]
    expected_patch = []
    for _, _, k, _, _, _, _, count in ranges:
        expected_patch += [int(k)] * int(count)
    assert patch.tolist() == expected_patch
    # floats: the doubles the mesh files write (truncated toward zero, as GMP's mpq_get_d), within one ulp
    v, f, _, _ = r.boundary_mesh()
    nearest = np.array([[float(Fraction(x)) for x in row] for row in ve])
    assert np.all(np.abs(v - nearest) <= np.spacing(np.abs(nearest))) and f.tolist() == fe.tolist()
    assert np.all(np.abs(v) <= np.abs(nearest))


def test_surface_mesh_refuses_2d_and_documents(scenes_dir, hsx_program, tmp_path, source_dir):
    with pytest.raises(hsx.InputError, match="needs a 3D complex"):
        hsx.load(str(scenes_dir / "lens.json")).surface_mesh()
    doc = tmp_path / "c.json"
    subprocess.run([hsx_program, "arrange", str(source_dir / "data" / "scenes3d" / "planes.json"), "--json",
                    str(doc)], capture_output=True, text=True, check=True)
    from_document = hsx.load(str(doc))
    assert from_document.dimension == 3 and not from_document.has_scene
    with pytest.raises(hsx.InputError, match="hsx-complex/1 document carries no triangles"):
        from_document.surface_mesh()
    assert from_document.svg() is None and from_document._repr_svg_() is None
    with pytest.raises(hsx.InputError, match="Complex.surface_mesh"):
        hsx.load(str(source_dir / "data" / "scenes3d" / "planes.json")).patch_polylines()


# ---- 3D pictures ----

def test_3d_pictures_are_the_cli_svg(source_dir, hsx_program, tmp_path):
    path = source_dir / "data" / "scenes3d" / "cad_part.json"
    c = hsx.load(str(path))
    out = tmp_path / "a.svg"
    subprocess.run([hsx_program, "arrange", str(path), "--svg", str(out)], capture_output=True, text=True,
                   check=True)
    assert c.svg(width=1000, title=str(path)) == out.read_text()
    r = hsx.extract(c, method="beam")
    out = tmp_path / "r.svg"
    subprocess.run([hsx_program, "extract", str(path), "--method", "beam", "--svg", str(out), "--show-removed",
                    "--labels"], capture_output=True, text=True, check=True)
    title = f"{path} - beam" + (" (optimal)" if r.optimal else "")
    assert r.svg(show_removed=True, labels=True, width=1000, title=title) == out.read_text()
    # notebooks: Complex, Result and Scene3 draw themselves (four views; a shape only its boundary)
    for picture in (c._repr_svg_(), r._repr_svg_(), built_scene(path)[0]._repr_svg_()):
        assert picture.startswith("<?xml") and picture.count('class="view"') >= 4
    assert r._repr_svg_() != c._repr_svg_()
    assert c.svg(fill=r.labelling, width=1000) == r.svg(width=1000)
    with pytest.raises(hsx.InputError, match="width: a 3D picture needs at least 200"):
        c.svg(width=100)
    with pytest.raises(hsx.InputError, match="highlight: no patch"):
        c.svg(highlight=[len(c.patches)])


def test_cad_part_example(source_dir, tmp_path):
    """examples/python/cad_part_3d.py: the part built in Python, its shape's closed boundary and exact volume, the
    engine's SVG, and the matplotlib plot (or the message saying it is skipped)."""
    import os
    import sys
    script = source_dir / "examples" / "python" / "cad_part_3d.py"
    p = subprocess.run([sys.executable, str(script), "--svg", str(tmp_path / "s.svg"), "--png", str(tmp_path / "s.png")],
                       capture_output=True, text=True, env=os.environ.copy(), timeout=600)
    assert p.returncode == 0, p.stdout + p.stderr
    assert "0 edges used unevenly, divergence volume == exact volume: yes" in p.stdout
    assert "beam vs optimum: Equal" in p.stdout
    assert (tmp_path / "s.svg").read_text().count('class="view"') >= 4
    try:
        import matplotlib  # noqa: F401
        assert (tmp_path / "s.png").stat().st_size > 1000
    except ImportError:
        assert "matplotlib is not installed" in p.stdout and not (tmp_path / "s.png").exists()
    # the example's scene is the bundled file's
    sys.path.insert(0, str(script.parent))
    try:
        import cad_part_3d
    finally:
        sys.path.pop(0)
    assert hsx.arrange(cad_part_3d.cad_part()).identity == hsx.load(
        str(source_dir / "data" / "scenes3d" / "cad_part.json")).identity


def test_3d_picture_views(source_dir, scenes_dir):
    c = hsx.load(str(source_dir / "data" / "scenes3d" / "nested_cavity.json"))
    one = c.svg(views=["isometric"], width=560)
    assert one.count('class="view"') == 1 and "isometric (along (-1, 1, -1))" in one
    assert "front (along +y)" not in one
    # a view given by its exact direction and up is the default view of the same name
    F = Fraction
    assert c.svg(views=[("top (along -z)", (0, 0, -1), (0, 1, 0))]) == c.svg(views=["top"])
    # any positive multiple of the direction and up is the same view (exact numbers of every kind)
    assert c.svg(views=[("top (along -z)", (0, 0, F(-7, 3)), ("0", "2", 0))]) == c.svg(views=["top"])
    both = c.svg(views=["front", ("mine", (1, 2, 3), (0, 0, 1))])
    assert both.count('class="view"') == 2 and "mine" in both
    r = hsx.extract(c, method="exact")
    assert r.svg(views=["side"]).count('class="view"') == 1
    with pytest.raises(hsx.InputError, match=r"views\[0\]: unknown view \"back\""):
        c.svg(views=["back"])
    with pytest.raises(hsx.InputError, match=r"views\[0\]\.direction: must not be zero"):
        c.svg(views=[("z", (0, 0, 0), (0, 1, 0))])
    with pytest.raises(hsx.InputError, match=r"views\[1\]\.up: must not be parallel"):
        c.svg(views=["top", ("z", (0, 0, 1), (0, 0, 2))])
    with pytest.raises(TypeError, match="is a float|float"):
        c.svg(views=[("z", (0, 0, 1.0), (0, 1, 0))])
    with pytest.raises(TypeError):
        c.svg(views="top")
    with pytest.raises(hsx.InputError, match="at least one view"):
        c.svg(views=[])
    with pytest.raises(hsx.InputError, match="only 3D pictures have views"):
        hsx.load(str(scenes_dir / "lens.json")).svg(views=["top"])


def test_convert_3d_matches_the_cli(source_dir, hsx_program, tmp_path):
    """hsx.convert on a 3D scene is `hsx convert SCENE3 --csg EXPR`: the same scene written, the same summary; a
    solid given as a mesh on the halfspaces (mesh=) is converted alike."""
    path = source_dir / "data" / "scenes3d" / "mesh_solids.json"
    conv = hsx.convert(str(path), csg="A | B")
    assert conv.ok and bool(conv) and conv.dimension == 3 and conv.round_trip
    assert conv.lower_bound <= conv.samples <= conv.upper_bound and len(conv.sample_patches) == conv.samples
    out, summary = tmp_path / "bsh.json", tmp_path / "summary.json"
    subprocess.run([hsx_program, "convert", str(path), "--csg", "A | B", "--out", str(out), "--json", str(summary)],
                   capture_output=True, text=True, check=True)
    assert conv.scene_json() == out.read_text()
    doc = json.loads(summary.read_text())
    assert (conv.samples, conv.sample_patches, conv.inside_cells, conv.cells, conv.patches) == (
        doc["samples"], doc["sample_patches"], doc["inside_cells"], doc["cells"], doc["patches"])
    assert conv.volume.exact == doc["volume"]["exact"] == "3"
    assert conv.flipped == doc["complemented"]
    # The written scene extracts back to a solid of the same volume.
    back = hsx.extract(conv.scene_json(), method="beam")
    assert back.sample_connected and back.volume.compare(hsx.Measure(3)) == hsx.Order.Equal
    by_mesh = hsx.convert(str(path), mesh=source_dir / "data" / "meshes" / "lprism.obj")
    assert by_mesh.scene_json() == conv.scene_json() and by_mesh.inside_cells == conv.inside_cells
    # A difference runs along B reversed: B is complemented (or copied complemented) in the BSH scene.
    diff = hsx.convert(str(path), csg="A & ~B")
    assert diff.ok and diff.flipped
    with pytest.raises(hsx.InputError, match="face 10 does not lie on the scene's halfspaces"):
        hsx.convert(str(path), mesh=source_dir / "data" / "scenes3d" / "mesh_solid_cut.obj")
    with pytest.raises(hsx.InputError, match="exactly one"):
        hsx.solid(str(path), csg="A", mesh=source_dir / "data" / "meshes" / "cube.obj")
    assert list(hsx.solid(str(path), mesh=source_dir / "data" / "meshes" / "cube.obj")) == list(
        hsx.solid(str(path), csg="A & B"))


def test_mesh_solid_needs_a_3d_scene(scenes_dir, source_dir):
    with pytest.raises(hsx.InputError, match="mesh=: a solid given as a mesh needs a 3D scene"):
        hsx.solid(str(next(scenes_dir.glob("*.json"))), mesh=source_dir / "data" / "meshes" / "cube.obj")
