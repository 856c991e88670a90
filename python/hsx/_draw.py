"""Float coordinates of a 2D complex's geometry, for plotting (matplotlib, numpy): a picture, never a proof.

Read from the complex's hsx-complex/1 document (its "geometry" section, complex_json.hpp): one-root coordinates
"a + b*sqrt(c)" are evaluated in floating point, arcs are sampled. Complexes without geometry (read from a
document that has none) have nothing to draw: both functions raise ValueError; a 3D complex raises hsx.InputError
(Complex.surface_mesh gives its surfaces).
"""
from __future__ import annotations

import json
import math
import re
from fractions import Fraction
from typing import List

import numpy as np

_TERM_SPLIT = re.compile(r"\s+([+-])\s+")


def number(text: str) -> float:
    """A one-root number's text ("3/2", "1 + 2*sqrt(5)", "-1/6*sqrt(24255/4096)") as the nearest-ish float."""
    parts = _TERM_SPLIT.split(text.strip())
    total, sign = 0.0, 1.0
    for k, part in enumerate(parts):
        if k % 2 == 1:
            sign = 1.0 if part == "+" else -1.0
            continue
        term = part
        negative = term.startswith("-")
        if negative:
            term = term[1:]
        if "sqrt(" in term:
            coefficient, _, radicand = term.partition("sqrt(")
            c = float(Fraction(coefficient.rstrip("*"))) if coefficient else 1.0
            value = c * math.sqrt(float(Fraction(radicand.rstrip(")"))))
        else:
            value = float(Fraction(term))
        total += sign * (-value if negative else value)
    return total


def _geometry(complex_):
    if complex_.dimension != 2:
        from ._hsx import InputError
        raise InputError("patch_polylines and cell_outlines draw a 2D complex; a 3D complex gives its surfaces as "
                         "arrays with Complex.surface_mesh()")
    doc = json.loads(complex_.to_json())
    g = doc.get("geometry")
    if not g:
        raise ValueError("this complex has no geometry to draw (an hsx-complex/1 document without it)")
    points = [np.array([number(v["point"][0]), number(v["point"][1])]) for v in g["vertices"]]
    return doc, g, points


def _edge_points(edge, points, arc_points: int, forward: bool = True) -> np.ndarray:
    a, b = points[edge["source"]], points[edge["target"]]
    if edge["shape"] == "segment":
        xy = np.array([a, b])
    else:
        c = np.array([number(edge["center"][0]), number(edge["center"][1])])
        a0 = math.atan2(a[1] - c[1], a[0] - c[0])
        a1 = math.atan2(b[1] - c[1], b[0] - c[0])
        sweep = (a1 - a0) % (2 * math.pi) if edge["ccw"] else -((a0 - a1) % (2 * math.pi))
        if sweep == 0:
            sweep = 2 * math.pi if edge["ccw"] else -2 * math.pi  # a closed circle
        r = float(np.hypot(*(a - c)))
        t = a0 + sweep * np.linspace(0, 1, max(2, arc_points))
        xy = np.stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)], axis=1)
    return xy if forward else xy[::-1]


def patch_polylines(complex_, arc_points: int = 32) -> List[List[np.ndarray]]:
    """Per patch, its pieces (arrangement edges) as (n, 2) float arrays, in the patch's order."""
    doc, g, points = _geometry(complex_)
    edges = g["edges"]
    return [[_edge_points(edges[e], points, arc_points) for e in p.get("pieces", [])] for p in doc["patches"]]


def cell_outlines(complex_, arc_points: int = 32) -> List[List[np.ndarray]]:
    """Per cell, its boundary loops (outer boundary and holes) as closed (n, 2) float arrays."""
    doc, g, points = _geometry(complex_)
    edges = g["edges"]
    out = []
    for face in g["faces"]:
        loops = []
        for loop in face["boundary"]:
            pieces = [_edge_points(edges[e], points, arc_points, forward) for e, forward in loop]
            loops.append(np.concatenate(pieces) if pieces else np.zeros((0, 2)))
        out.append(loops)
    return out
