"""Scenes: built programmatically, from dicts, JSON text and files; exact numbers; float refusal; errors."""
import json
from decimal import Decimal
from fractions import Fraction as F

import pytest

import hsx


def lens_like():
    s = hsx.Scene([hsx.Disk((0, 0), 2, "A"), hsx.Disk((2, 0), 2, "B"), hsx.HalfPlane((0, 1), F(3, 2), "C")],
                  domain=((-4, -4), (6, 5)))
    s.sample("A", at=(-2, 0))
    s.sample("B", at=(4, 0))
    s.sample("C", at=(1, "3/2"))
    return s


def test_programmatic_scene_arranges():
    c = hsx.arrange(lens_like())
    assert c.halfspaces == ["A", "B", "C"]
    assert len(c.samples) == 3
    assert c.validate() == []
    assert c.has_scene


def test_four_spellings_give_the_same_complex(scenes_dir):
    path = scenes_dir / "lens.json"
    text = path.read_text()
    from_file = hsx.arrange(path)
    from_str_path = hsx.arrange(str(path))
    from_text = hsx.arrange(text)
    from_scene = hsx.arrange(hsx.Scene.from_file(path))
    doc = json.loads(text, parse_float=str)  # decimals kept as their text: exact
    from_dict = hsx.arrange(doc)
    ids = {c.identity for c in (from_file, from_str_path, from_text, from_scene, from_dict)}
    assert len(ids) == 1
    assert from_dict.to_json() == from_file.to_json()


def test_numbers_int_fraction_string_decimal_agree():
    def radius_scene(r):
        return hsx.Scene([hsx.Disk((0, 0), r, "A")])
    texts = {hsx.arrange(radius_scene(r)).to_json() for r in (F(3, 2), "3/2", "1.5", Decimal("1.5"))}
    assert len(texts) == 1


def test_float_refused_with_the_reason():
    with pytest.raises(TypeError, match=r"radius: 0\.1 is a float.*exact_from_float=True"):
        hsx.Disk((0, 0), 0.1)
    with pytest.raises(TypeError, match=r"halfspaces\[0\]\.radius: 1\.5 is a float"):
        hsx.arrange({"format": "hsx-scene/1", "dimension": 2,
                     "halfspaces": [{"name": "A", "kind": "disk", "center": [0, 0], "radius": 1.5}]})
    with pytest.raises(TypeError, match="a bool is not a number"):
        hsx.Disk((0, 0), True)


def test_exact_from_float_is_the_binary_value():
    d = hsx.Disk((0, 0), 0.1, "A", exact_from_float=True)
    assert d.to_dict()["radius"] == "3602879701896397/36028797018963968"
    assert F(d.to_dict()["radius"]) == F(0.1) != F(1, 10)
    c = hsx.arrange(hsx.Scene([d]))
    area = c.cells[[k for k, cell in enumerate(c.cells) if cell.inside == ["A"]][0]].measure
    assert area.pi_coefficient == F(0.1) ** 2


def test_witness_points_round_trip_as_fractions():
    c = hsx.arrange(lens_like())
    for cell in c.cells:
        assert all(isinstance(x, F) for x in cell.witness)
        # the witness is strictly inside the cell: the scene's exact side tests agree with the cell's sides
        x, y = cell.witness
        inside_a = x * x + y * y < 4
        inside_c = y < F(3, 2)
        assert cell.sides["A"] == inside_a and cell.sides["C"] == inside_c
    # a witness written back as exact strings gives the same Fraction
    w = c.cells[0].witness
    assert tuple(F(hsx.exact(v)) for v in w) == w


def test_scene_json_round_trip():
    s = lens_like()
    again = hsx.Scene.from_json(s.to_json())
    assert hsx.arrange(again).identity == hsx.arrange(s).identity
    assert hsx.Scene.from_dict(s.to_dict()).to_json() == s.to_json()
    assert s.halfspace_names == ["A", "B", "C"]
    # a scene read from text keeps decimals exact when turned into a dict
    d = hsx.Scene.from_json('{"format": "hsx-scene/1", "dimension": 2, "halfspaces": '
                            '[{"name": "A", "kind": "disk", "center": [0, 0], "radius": 0.1}]}').to_dict()
    assert F(d["halfspaces"][0]["radius"]) == F(1, 10)


def test_unnamed_halfspaces_and_complement():
    s = hsx.Scene([hsx.Disk((0, 0), 1), ~hsx.Polygon([(0, 0), (3, 0), (0, 3)])])
    c = hsx.arrange(s)
    assert c.halfspaces == ["H0", "H1"]
    assert s.to_dict()["halfspaces"][1]["complement"] is True


def test_input_errors_carry_the_cli_messages(tmp_path):
    bad = {"format": "hsx-scene/1", "dimension": 2,
           "halfspaces": [{"name": "A", "kind": "disk", "center": [0, 0], "radius": "abc"}]}
    with pytest.raises(hsx.InputError, match=r"halfspaces\[0\]\.radius"):
        hsx.arrange(bad)
    assert issubclass(hsx.InputError, ValueError)
    f = tmp_path / "bad.json"
    f.write_text(json.dumps(bad))
    with pytest.raises(hsx.InputError, match=r"bad\.json: halfspaces\[0\]\.radius"):
        hsx.arrange(f)
    with pytest.raises(hsx.InputError, match="not on the boundary"):
        s = hsx.Scene([hsx.Disk((0, 0), 1, "A")])
        s.sample("A", at=(2, 0))
        hsx.arrange(s)
    with pytest.raises(hsx.InputError, match="self-intersecting"):
        hsx.arrange(hsx.Scene([hsx.Polygon([(0, 0), (2, 2), (2, 0), (0, 2)], "P")]))
    with pytest.raises(hsx.InputError):
        hsx.arrange("{not json")
    with pytest.raises(hsx.InputError, match="max_cells"):
        hsx.arrange(lens_like(), max_cells=-1)
    assert len(hsx.arrange(lens_like(), max_cells=0).cells) > 2  # 0: no limit, as the program's --max-cells 0
    with pytest.raises(hsx.InputError):
        hsx.arrange(lens_like(), max_cells=2)
    with pytest.raises(TypeError):
        hsx.arrange(42)
    with pytest.raises(TypeError, match="exactly one"):
        hsx.Sample("A")


def test_complex_document_input(scenes_dir):
    c = hsx.arrange(scenes_dir / "lens.json")
    again = hsx.arrange(c.to_json())  # an hsx-complex/1 document
    assert not again.has_scene
    assert again.identity == c.identity
    assert again.svg() is None and again._repr_svg_() is None
    assert hsx.extract(again, method="exact").energy.compare(hsx.extract(c, method="exact").energy) == hsx.Order.Equal


def test_random_scenes_are_reproducible():
    a = hsx.random_scene(7, 3, max_halfspaces=5, max_samples=4)
    b = hsx.random_scene(7, 3, max_halfspaces=5, max_samples=4)
    assert a.to_json() == b.to_json()
    assert isinstance(a.degeneracies, list) and all(d in hsx.DEGENERACIES for d in a.degeneracies)
    scenes = list(hsx.random_scenes(7, count=3, start=2, max_halfspaces=5))
    assert len(scenes) == 3 and scenes[1].to_json() == hsx.random_scene(7, 3, max_halfspaces=5).to_json()
    assert hsx.arrange(a).validate() == []
    with pytest.raises(TypeError, match="unknown setting"):
        hsx.random_scene(1, 0, colour="red")
    with pytest.raises(hsx.InputError, match="random_scene"):
        hsx.random_scene(1, 0, min_halfspaces=5, max_halfspaces=2)
    only = hsx.random_scene(3, 0, degeneracy_weights={d: 0 for d in hsx.DEGENERACIES})
    assert only.degeneracies == []


def test_complex_accessors(scenes_dir):
    c = hsx.load(scenes_dir / "lens.json")
    assert "14 cells" in repr(c) and c.dimension == 2 and c.source.endswith("lens.json")
    assert c.outer_cell_count == sum(cell.outer for cell in c.cells)
    cp = c.cell_patches()
    assert len(cp) == len(c.cells)
    for p in c.patches:
        assert p.index in cp[p.inside_cell] and p.index in cp[p.outside_cell]
        assert p.cells == (p.inside_cell, p.outside_cell)
        assert c.halfspaces[p.halfspace_index] == p.halfspace
        assert p.index in c.supports[p.support]
        for j in p.junctions:
            assert p.index in c.junctions[j].patches
    nb = c.patch_neighbours()
    assert all(p not in nb[p] for p in range(len(c.patches)))
    for s in c.samples:
        assert c.patches[s.patch].halfspace == s.halfspace and s.index in c.patches[s.patch].samples
    total = c.measure_of(list(range(len(c.patches))))
    assert total.compare(sum((p.measure for p in c.patches), hsx.Measure())) in (hsx.Order.Equal, hsx.Order.Less)
    with pytest.raises(hsx.InputError, match="no patch"):
        c.measure_of([10 ** 6])
    scene = json.loads(c.scene_json())
    assert scene["format"] == "hsx-scene/1" and [h["name"] for h in scene["halfspaces"]] == c.halfspaces
    assert "<svg" in hsx.Scene.from_dict(scene)._repr_svg_()
    assert hsx.Scene([hsx.Polygon([(0, 0), (1, 1), (2, 2)])])._repr_svg_() is None  # does not arrange: no picture
