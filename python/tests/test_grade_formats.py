"""hsx.grade's labelling formats (io/labelling.hpp, as `hsx grade` reads them: the BSH authors' {"labels": [...]},
an hsx-result/1, a JSON list, a plain 0/1 list; as a dict, JSON text or a file path) and hsx.export_graphcut (the
authors' graph-cut input, equal to `hsx arrange --export bsh-graphcut`); the 3D BHC tree equal to `hsx csg`'s."""
import json
import subprocess

import pytest

import hsx


@pytest.fixture(scope="module")
def lens(scenes_dir):
    return hsx.arrange(scenes_dir / "lens.json")


def run(program, *args):
    return subprocess.run([program, *map(str, args)], capture_output=True, text=True)


def same_grade(a, b):
    return (a.optimal == b.optimal and a.orientation_preserving == b.orientation_preserving
            and a.sample_connected == b.sample_connected and a.versus_optimum == b.versus_optimum
            and a.missing_samples_gap == b.missing_samples_gap
            and hsx.compare(a.measure_gap, b.measure_gap) == hsx.Order.Equal)


def test_grade_reads_every_format(lens, tmp_path):
    best = hsx.extract(lens, method="exact")
    flags = [bool(v) for v in best.labelling]
    reference = hsx.grade(lens, best.labelling)
    assert reference.optimal
    empty = hsx.grade(lens, [0] * len(flags))
    assert not empty.optimal
    as_dict = hsx.grade(lens, {"labels": flags})
    assert same_grade(as_dict, reference)
    assert same_grade(hsx.grade(lens, {"labels": [int(f) for f in flags]}), reference)
    assert same_grade(hsx.grade(lens, json.dumps({"labels": flags})), reference)
    assert same_grade(hsx.grade(lens, json.dumps([int(f) for f in flags])), reference)
    assert same_grade(hsx.grade(lens, {"labels": [False] * len(flags)}), empty)
    plain = tmp_path / "plain.txt"
    plain.write_text(" ".join(str(int(f)) for f in flags) + "\n")
    assert same_grade(hsx.grade(lens, plain), reference)
    assert same_grade(hsx.grade(lens, str(plain)), reference)
    theirs = tmp_path / "theirs.json"
    theirs.write_text(json.dumps({"labels": [False] * len(flags)}))
    assert same_grade(hsx.grade(lens, theirs), empty)
    result = tmp_path / "result.json"
    result.write_text(best.to_json())  # an hsx-result/1 of the same complex
    assert same_grade(hsx.grade(lens, result), reference)
    assert same_grade(hsx.grade(lens, json.loads(best.to_json())), reference)


def test_grade_format_errors(lens, tmp_path, scenes_dir):
    n = len(lens.cells)
    with pytest.raises(hsx.InputError, match="labels"):
        hsx.grade(lens, {"labels": [True] * (n + 1)})
    with pytest.raises(hsx.InputError, match="labelling"):
        hsx.grade(lens, {"labels": [2] * n})
    with pytest.raises(hsx.InputError, match="no-such-file"):
        hsx.grade(lens, tmp_path / "no-such-file.txt")
    other = hsx.extract(scenes_dir / "concurrent.json", method="exact")
    with pytest.raises(hsx.InputError, match="complex_id"):
        hsx.grade(lens, other.to_json())


def test_export_graphcut_equals_the_cli(hsx_program, scenes_dir, tmp_path, lens):
    scene = scenes_dir / "lens.json"
    for scale in (1000000, 7):
        out = tmp_path / f"graph{scale}.json"
        p = run(hsx_program, "arrange", scene, "--export", "bsh-graphcut", out, "--weight-scale", scale, "-q")
        assert p.returncode == 0, p.stderr
        g = hsx.export_graphcut(lens, weight_scale=scale)
        assert g == json.loads(out.read_text())
        assert g["num_cells"] == len(lens.cells) and g["weight_scale"] == scale
        assert len(g["patches"]) == len(lens.patches)
        for k, patch in enumerate(g["patches"]):
            assert patch["adj_cell_0"] == lens.patches[k].outside_cell
            assert patch["adj_cell_1"] == lens.patches[k].inside_cell
            assert isinstance(patch["weight"], int) and patch["weight"] >= 1
    assert hsx.export_graphcut(scene) == hsx.export_graphcut(lens)  # the default scale is the CLI's
    with pytest.raises(hsx.InputError, match="weight"):
        hsx.export_graphcut(lens, weight_scale=0)


BRACKET = ("X0 & Y0 & Y1 & Z0 & ((X1 & Z1 & Ch1) | (U1 & Z2 & Ch2) | (G0 & G1 & Gd) | Boss) & ~H1 & ~H2 & ~H3 & "
           "~(S0 & S1 & Sz)")


def test_3d_csg_tree_equals_the_cli(hsx_program, source_dir, tmp_path):
    scene = source_dir / "data" / "scenes3d" / "bhc_bracket.json"
    out = tmp_path / "bracket.json"
    p = run(hsx_program, "csg", scene, "--csg", BRACKET, "--json", out)
    assert p.returncode == 0, p.stderr
    cli = json.loads(out.read_text())
    tree = hsx.csg(scene, BRACKET)
    assert tree.describable and tree.verified and cli["describable"]
    assert tree.text == cli["text"]


def test_3d_csg_prefers_planes_as_the_cli(hsx_program, tmp_path):
    # inside B, S xor P needs a partition where the sphere S and the plane P split as many faces: `hsx csg` takes
    # the plane first; plain BHC (a complex without geometry) takes S, the lower index
    scene = hsx.Scene3([hsx.Sphere((0, 0, 0), 2, "S", segments=8), hsx.Plane((0, 0, 1), 0, "P"),
                        hsx.Box((-3, -3, -3), (3, 3, 3), "B")], domain=((-4, -4, -4), (4, 4, 4)))
    path = tmp_path / "xor.json"
    path.write_text(scene.to_json())
    out = tmp_path / "xor_csg.json"
    expression = "B & (S & ~P | ~S & P)"
    p = run(hsx_program, "csg", path, "--csg", expression, "--json", out)
    assert p.returncode == 0, p.stderr
    cx = hsx.arrange(scene)
    tree = hsx.csg(cx, expression)
    assert tree.verified and tree.text == json.loads(out.read_text())["text"] == "B & (P & ~S | ~P & S)"
    assert hsx.csg(hsx.load(cx.to_json()), expression).text == "B & (S & ~P | ~S & P)"


def test_3d_separators_as_the_cli(hsx_program, source_dir, tmp_path):
    # split_box: the left half of B & ~C is not describable by B and C; one separating plane makes it describable
    scene = source_dir / "data" / "scenes3d" / "split_box.json"
    cx = hsx.arrange(scene)
    left = [c.sides["B"] and not c.sides["C"] and c.witness[0] < 0 for c in cx.cells]
    assert sum(left) == 1
    plain = hsx.csg(cx, shape=left)
    assert not plain.describable and plain.mixed and plain.separated_scene_json is None
    sep = hsx.csg(cx, shape=left, separators=True)
    assert sep.verified and sep.separated_scene_json is not None
    refined = json.loads(sep.separated_scene_json)
    assert refined["dimension"] == 3 and [h["name"] for h in refined["halfspaces"]] == ["B", "C", "sep0"]
    # the same solid for the CLI: an hsx-result/1 of this scene with the left cell inside (--shape reads inside_cells)
    document = json.loads(hsx.extract(cx).to_json())
    document["inside_cells"] = [k for k, flag in enumerate(left) if flag]
    shape = tmp_path / "left.json"
    shape.write_text(json.dumps(document))
    assert (hsx.solid(cx, shape=shape) == left).all()
    out = tmp_path / "sep.json"
    p = run(hsx_program, "csg", scene, "--shape", shape, "--separators", "--json", out)
    assert p.returncode == 0, p.stderr
    assert sep.text == json.loads(out.read_text())["text"]
