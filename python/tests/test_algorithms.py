"""extract (every method), grade, check, describe, csg, samples; agreement with the hsx program's JSON."""
import json
import subprocess
from fractions import Fraction as F

import numpy as np
import pytest

import hsx


@pytest.fixture(scope="module")
def lens(scenes_dir):
    return hsx.arrange(scenes_dir / "lens.json")


def test_every_method_gives_a_sample_connected_shape(lens):
    exact = hsx.extract(lens, method="exact")
    assert exact.optimal and exact.method == "exact"
    for method in hsx.METHODS:
        r = hsx.extract(lens, method=method)
        assert r.labelling.dtype == np.bool_ and r.labelling.shape == (len(lens.cells),)
        assert r.method == method
        assert not r.labelling[[k for k, c in enumerate(lens.cells) if c.outer]].any()
        if method != "graphcut":
            assert r.sample_connected
            assert r.energy.compare(exact.energy) in (hsx.Order.Equal, hsx.Order.Greater)
        if method in ("best-first", "brute-force"):
            assert r.optimal and r.energy.compare(exact.energy) == hsx.Order.Equal
    r = hsx.extract(lens, method="best_first")  # the Python spelling is accepted
    assert r.method == "best-first"


def test_result_fields(lens):
    r = hsx.extract(lens, method="beam", beam_width=2, record_states=True)
    missing, measure = r.energy
    assert missing == r.energy.missing_samples and isinstance(measure, hsx.Measure)
    assert r.inside_cells == [k for k in range(len(lens.cells)) if r.labelling[k]]
    assert r.area.compare(sum((lens.cells[k].measure for k in r.inside_cells), hsx.Measure())) == hsx.Order.Equal
    assert lens.measure_of(r.boundary_patches).compare(r.energy.measure) == hsx.Order.Equal
    assert r.steps[0] == [] and r.steps[-1] == r.removed_patches
    assert len(r.expanded) >= 1 and all(e.dtype == np.bool_ for e in r.expanded)
    assert set(r.stats) >= {"graph_cuts", "states_expanded", "nodes", "lower_bound", "gap", "seconds"}
    assert r.stats["graph_cuts"] >= 1
    assert r.complex.identity == lens.identity
    assert '"seconds"' in r.to_json(include_seconds=True) and '"seconds"' not in r.to_json()
    assert "<svg" in r.svg(show_removed=True, labels=True) and "<svg" in r._repr_svg_()
    assert "<svg" in lens._repr_svg_() and "c0" in lens.svg(labels=True)


def test_ties_are_reported(source_dir):
    r = hsx.extract(source_dir / "data" / "figures" / "fig06.json", method="exact")
    assert r.optimal and r.ties.checked and r.ties.count == 2 and r.ties.certified
    assert len(r.tied) == 1 and not np.array_equal(r.tied[0], r.labelling)
    other = hsx.grade(r.complex, r.tied[0])
    assert other.optimal and other.versus_optimum == hsx.Order.Equal


def test_limits_and_option_errors(lens, source_dir):
    r = hsx.extract(source_dir / "data" / "figures" / "fig10.json", method="best-first", max_states=1)
    assert not r.optimal and r.stopped_by == "max-states" and r.sample_connected
    with pytest.raises(hsx.InputError, match="unknown method"):
        hsx.extract(lens, method="fastest")
    with pytest.raises(hsx.InputError, match="beam_width"):
        hsx.extract(lens, beam_width=0)
    for bad in (-1, float("nan"), float("inf")):
        with pytest.raises(hsx.InputError, match="time_limit"):
            hsx.extract(lens, time_limit=bad)
    with pytest.raises(hsx.InputError):  # brute force refuses more labellings than allowed
        hsx.extract(lens, method="brute-force", max_labellings=2)


def test_grade(lens):
    best = hsx.extract(lens, method="exact")
    g = hsx.grade(lens, best.labelling)
    assert g.optimal and g.orientation_preserving and g.sample_connected
    assert g.missing_samples_gap == 0 and g.measure_gap.is_zero()
    assert g.optimum.optimal
    empty = hsx.grade(lens, [0] * len(lens.cells))
    assert not empty.optimal and empty.versus_optimum == hsx.Order.Greater
    assert empty.missing_samples_gap > 0
    outer = [1 if c.outer else 0 for c in lens.cells]
    bad = hsx.grade(lens, outer)
    assert not bad.orientation_preserving and bad.orientation_problem
    with pytest.raises(hsx.InputError, match="labelling: 3 entries"):
        hsx.grade(lens, [0, 1, 0])
    with pytest.raises(hsx.InputError, match="not 0 or 1"):
        hsx.grade(lens, [2] * len(lens.cells))


def test_check(lens):
    results = hsx.check(lens)
    assert results and all(isinstance(c, hsx.CheckResult) for c in results)
    assert {c.status for c in results} <= {"pass", "skipped"}
    assert any("5.2" in c.name for c in results)


def test_describe_csg_solid(lens):
    cells = hsx.solid(lens, csg="(A | B) & ~C")
    assert cells.dtype == np.bool_ and cells.any()
    d = hsx.describe(lens, csg="(A | B) & ~C")
    assert d.describable and bool(d) and d.mixed == [] and d.terms > 0
    t = hsx.csg(lens, csg="(A | B) & ~C")
    assert t.describable and t.verified and t.text
    assert (hsx.solid(lens, csg=t.text) == cells).all()
    assert t.stats["leaves"] >= 3
    # a solid not describable by the halfspaces: one cell of a term that has two
    r = hsx.extract(lens, method="exact")
    assert hsx.describe(lens, shape=r).describable in (True, False)
    assert (hsx.solid(lens, shape=json.loads(r.to_json())) == r.labelling).all()
    assert (hsx.solid(lens, shape=r.to_json()) == r.labelling).all()
    with pytest.raises(hsx.InputError):
        hsx.solid(lens, csg="(A | Q)")
    with pytest.raises(hsx.InputError, match="exactly one"):
        hsx.solid(lens)
    other = hsx.arrange(hsx.Scene([hsx.Disk((0, 0), 1, "A")]))
    with pytest.raises(hsx.InputError, match="complex_id"):
        hsx.solid(other, shape=r.to_json())
    with pytest.raises(hsx.InputError, match="another input"):
        hsx.solid(other, shape=r)


def test_not_describable_has_mixed_terms():
    # two overlapping disks; the solid is one of the two lens halves' union with A's crescent: cells of a term split
    s = hsx.Scene([hsx.Disk((0, 0), 2, "A"), hsx.HalfPlane((1, 0), 0, "L")])
    c = hsx.arrange(s)
    inside_a = [k for k, cell in enumerate(c.cells) if cell.sides["A"]]
    # a solid that takes one cell of A but not the other, although both share every sign? find a mixed one
    sol = np.zeros(len(c.cells), dtype=bool)
    sol[inside_a[0]] = True
    d = hsx.describe(c, shape=sol)
    assert d.describable  # each sign vector is one cell here
    ring = hsx.Scene([hsx.Disk((0, 0), 2, "A"), ~hsx.Disk((0, 0), 1, "B"), hsx.HalfPlane((0, 1), 0, "C"),
                      hsx.HalfPlane((0, -1), F(-1, 2), "D")])
    c2 = hsx.arrange(ring)
    terms = {}
    for k, cell in enumerate(c2.cells):
        terms.setdefault(tuple(sorted(cell.inside)), []).append(k)
    split = next((ks for ks in terms.values() if len(ks) > 1), None)
    if split is None:
        pytest.skip("no sign vector with two cells in this scene")
    sol = np.zeros(len(c2.cells), dtype=bool)
    sol[split[0]] = True
    d = hsx.describe(c2, shape=sol)
    assert not d.describable and d.mixed
    assert "<svg" in d._repr_svg_()
    t = hsx.csg(c2, shape=sol)
    assert not t.describable and t.text is None and t.mixed
    assert t.separated_scene_json is None
    sep = hsx.csg(c2, shape=sol, separators=True)  # separating half-planes added first, as `hsx csg --separators`
    assert sep.separated_scene_json is not None and "hsx-scene/1" in sep.separated_scene_json
    if sep.describable:
        assert sep.verified and sep.text
    else:
        assert sep.mixed
    with pytest.raises(hsx.InputError, match="max_separators"):
        hsx.csg(c2, shape=sol, separators=True, max_separators=-1)


def test_samples_generation(lens):
    s = hsx.samples(lens, csg="(A | B) & C")
    assert s.reproduced and s.lower_bound <= s.count <= s.upper_bound
    assert s.minimum is None or s.minimum <= s.count
    again = hsx.arrange(s.scene_json())
    r = hsx.extract(again, method="beam")
    assert (r.labelling == hsx.solid(lens, csg="(A | B) & C")).all()
    with pytest.raises(hsx.InputError, match="search"):
        hsx.samples(lens, csg="A", search="exact")


def run(program, *args):
    return subprocess.run([program, *map(str, args)], capture_output=True, text=True)


@pytest.mark.parametrize("name", ["lens", "coincident", "concurrent", "tangencies", "star", "shared_edges",
                                  "box_contacts", "vertex_on_circle"])
def test_agrees_with_the_cli(hsx_program, scenes_dir, tmp_path, name):
    scene = scenes_dir / f"{name}.json"
    c = hsx.arrange(scene)
    out = tmp_path / "complex.json"
    assert run(hsx_program, "arrange", scene, "--json", out).returncode == 0
    assert out.read_text() == c.to_json()
    for method in ("exact", "beam", "graphcut"):
        res = tmp_path / f"{method}.json"
        p = run(hsx_program, "extract", scene, "--method", method, "--json", res, "--no-timing")
        assert p.returncode == 0, p.stderr
        assert res.read_text() == hsx.extract(c, method=method).to_json(), method


@pytest.mark.parametrize("name", ["lens", "concurrent", "tangencies"])
def test_check_agrees_with_the_cli(hsx_program, scenes_dir, tmp_path, name):
    scene = scenes_dir / f"{name}.json"
    out = tmp_path / "check.json"
    p = run(hsx_program, "check", scene, "--json", out)
    assert p.returncode in (0, 3), p.stderr
    cli = [(c["check"], c["status"], c["witness"]) for c in json.loads(out.read_text())["checks"]]
    assert cli == [(c.name, c.status, c.witness) for c in hsx.check(scene)]


def test_error_messages_match_the_cli(hsx_program, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "hsx-scene/1", "dimension": 2, "halfspaces": '
                   '[{"name": "A", "kind": "disk", "center": [0, 0], "radius": -1}]}')
    p = run(hsx_program, "arrange", bad)
    assert p.returncode == 2
    with pytest.raises(hsx.InputError) as e:
        hsx.arrange(bad)
    assert p.stderr.strip() == f"hsx: error: {e.value}"


def test_convert(lens):
    conv = hsx.convert(lens, csg="(A | B) & C")
    assert conv.ok and bool(conv) and conv.round_trip and conv.lower_bound <= conv.samples <= conv.upper_bound
    assert conv.dimension == 2 and conv.inside_cells is None and conv.volume is None
    back = hsx.extract(conv.scene_json(), method="beam")
    cells = hsx.solid(lens, csg="(A | B) & C")
    area = sum((lens.cells[k].measure for k in range(len(cells)) if cells[k]), hsx.Measure())
    assert back.sample_connected and back.area.compare(area) == hsx.Order.Equal
    net = hsx.convert(csgnet="c(32,32,16)s(32,40,12)-")
    assert net.ok and "hsx-scene/1" in net.scene_json()
    with pytest.raises(hsx.InputError, match="alone"):
        hsx.convert(lens, csgnet="c(32,32,16)")
    with pytest.raises(hsx.InputError):
        hsx.convert(csgnet="not a program")
    with pytest.raises(hsx.InputError, match="not a complex"):
        hsx.convert(lens.to_json(), csg="A")


def test_nhtree_agrees_with_the_cli(hsx_program, scenes_dir, tmp_path, lens):
    t = hsx.nhtree(lens, csg="(A | B) & C")
    assert t.structure_violations == [] and t.verdict and t.correct in (True, False)
    assert t.tree.startswith(("max(", "min(")) or t.tree.isdigit()
    assert "list" in t.conf and "<svg" in t._repr_svg_()
    assert any(name.lstrip("~") in lens.halfspaces for name in t.leaf_names if name)
    out = tmp_path / "nh.json"
    conf = tmp_path / "nh.conf"
    p = run(hsx_program, "nhtree", scenes_dir / "lens.json", "--csg", "(A | B) & C", "--json", out, "--conf", conf)
    assert p.returncode in (0, 3), p.stderr
    assert f"tree: {t.tree}" in p.stdout
    assert conf.read_text() == t.conf
    cli = json.loads(out.read_text())
    mine = json.loads(t.to_json())
    cli.pop("input"), mine.pop("input")
    assert mine == cli
    with pytest.raises(hsx.InputError):
        hsx.nhtree(lens, csg="A & ~A")  # an empty solid has no boundary
    with pytest.raises(hsx.InputError, match="not a complex"):
        hsx.nhtree(lens.to_json(), csg="A")
