"""examples/python: the Fig. 10 walkthrough (with and without matplotlib) and the numpy graph-cut check; the
plotting helpers they use."""
import os
import subprocess
import sys

import numpy as np
import pytest

import hsx


def run_example(source_dir, name, *args, hide_matplotlib=False):
    script = source_dir / "examples" / "python" / name
    if hide_matplotlib:  # as on a machine without it: importing matplotlib fails
        code = ("import runpy, sys; sys.modules['matplotlib'] = None; sys.argv = sys.argv[1:]; "
                "runpy.run_path(sys.argv[0], run_name='__main__')")
        cmd = [sys.executable, "-c", code, str(script), *map(str, args)]
    else:
        cmd = [sys.executable, str(script), *map(str, args)]
    return subprocess.run(cmd, capture_output=True, text=True, env=os.environ.copy(), timeout=600)


def test_fig10_walkthrough(source_dir, tmp_path):
    p = run_example(source_dir, "fig10_beam_walkthrough.py", "--svg-prefix", tmp_path / "step", "--png",
                    tmp_path / "row.png")
    assert p.returncode == 0, p.stderr
    # the paper's Fig. 10: the graph cut, then two removals (docs/figures.md: steps [[], [23], [4, 23]])
    assert "step 0: removed patches []" in p.stdout
    assert "step 1: removed patches [23]" in p.stdout
    assert "step 2: removed patches [4, 23]" in p.stdout
    assert "sample-connected yes" in p.stdout.splitlines()[3]
    for k in range(3):
        assert "<svg" in (tmp_path / f"step{k}.svg").read_text()
    try:
        import matplotlib  # noqa: F401
        assert (tmp_path / "row.png").stat().st_size > 1000
    except ImportError:
        assert "matplotlib is not installed" in p.stdout


def test_fig10_walkthrough_without_matplotlib(source_dir, tmp_path):
    p = run_example(source_dir, "fig10_beam_walkthrough.py", "--png", tmp_path / "row.png", hide_matplotlib=True)
    assert p.returncode == 0, p.stderr
    assert "step 2: removed patches [4, 23]" in p.stdout
    assert "matplotlib is not installed" in p.stdout and "skipped" in p.stdout
    assert not (tmp_path / "row.png").exists()


def test_numpy_graph_cut_agrees_with_hsx(source_dir):
    p = run_example(source_dir, "numpy_graph_cut_check.py", "--count", "8")
    assert p.returncode == 0, p.stdout + p.stderr
    assert "8 scenes: 8 agree with hsx" in p.stdout
    assert "0 findings" in p.stdout


def test_plotting_helpers(scenes_dir):
    cx = hsx.arrange(scenes_dir / "lens.json")
    lines = cx.patch_polylines(arc_points=16)
    assert len(lines) == len(cx.patches)
    assert all(piece.shape[1] == 2 for pieces in lines for piece in pieces)
    outlines = cx.cell_outlines()
    assert len(outlines) == len(cx.cells)
    # an inner cell's witness lies inside its outer loop (even-odd test on the sampled outline)
    for k, cell in enumerate(cx.cells):
        if cell.outer:
            continue
        x, y = map(float, cell.witness)
        loop = outlines[k][0]
        xs, ys = loop[:, 0], loop[:, 1]
        crossings = ((ys > y) != (np.roll(ys, -1) > y)) & (
            x < xs + (np.roll(xs, -1) - xs) * (y - ys) / np.where(np.roll(ys, -1) == ys, 1, np.roll(ys, -1) - ys))
        inside = crossings.sum() % 2 == 1
        if len(outlines[k]) == 1:
            assert inside, k
    svg = cx.svg(fill=[False] * len(cx.cells), highlight=[0, 1], highlight_legend="two patches")
    assert "two patches" in svg
    with pytest.raises(hsx.InputError, match="highlight: no patch"):
        cx.svg(highlight=[10 ** 6])
    with pytest.raises(hsx.InputError, match="fill"):
        cx.svg(fill=[True])
    doc = hsx.arrange(cx.to_json())  # an hsx-complex/1 document: no scene to draw
    assert doc.svg() is None
    with pytest.raises(ValueError, match="no geometry"):
        doc.patch_polylines()
