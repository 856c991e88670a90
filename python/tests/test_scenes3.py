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
