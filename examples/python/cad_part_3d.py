"""A 3D CAD part built in Python with exact numbers, its BSH shape, and the shape's boundary as numpy arrays.

The part is data/scenes3d/cad_part.json (after BSH Fig. 19) written with hsx's 3D builders: a cylinder between the
planes Top and Bottom, cut by a slab box and a notch (a complemented box), with two rings (tori) on the top plane.
Every number is an int or a Fraction, so the scene is exactly the file's. The script

1. arranges the scene and extracts the shape (beam search, K = 1) and the exact optimum;
2. takes the shape's boundary as arrays (Result.boundary_mesh: a closed, outward triangle mesh) and checks, in
   exact rational arithmetic, that every edge is used once in each direction and that the divergence theorem's
   volume sum(det(v0, v1, v2)) / 6 is the shape's exact volume;
3. writes the engine's picture (--svg: four orthographic views, io/svg3.hpp) and, with matplotlib, a 3D plot of
   the boundary coloured by halfspace (--png; skipped with a message without matplotlib).

Usage: cad_part_3d.py [--svg OUT.svg] [--png OUT.png]
"""
import argparse
import collections
import sys
from fractions import Fraction as F

import hsx


def cad_part():
    """data/scenes3d/cad_part.json, built with the 3D builders."""
    ring = dict(segments=16, minor_segments=8)
    scene = hsx.Scene3([
        hsx.Plane((0, 0, 1), 2, "Top"),
        hsx.Plane((0, 0, -1), 0, "Bottom"),
        hsx.Cylinder((0, 0, 0), (0, 0, 2), 2, "Cyl", segments=16),
        hsx.Box((-3, -1, -1), (3, 1, 3), "Slab"),
        ~hsx.Box((F(-1, 2), F(-5, 2), 1), (F(1, 2), F(5, 2), 3), "Notch"),
        hsx.Torus((0, F(7, 2), 2), (0, 0, 1), F(1, 2), F(1, 8), "Ring1", **ring),
        hsx.Torus((0, F(-7, 2), 2), (0, 0, 1), F(1, 2), F(1, 8), "Ring2", **ring),
    ], domain=((-4, -5, -2), (4, 5, 4)))
    for name, at in [("Bottom", (0, F(1, 2), 0)), ("Top", (1, F(1, 2), 2)), ("Top", (-1, F(1, 2), 2)),
                     ("Notch", (0, F(1, 2), 1)), ("Notch", (F(1, 2), 0, F(3, 2))), ("Notch", (F(-1, 2), 0, F(3, 2))),
                     ("Slab", (1, 1, F(1, 2))), ("Slab", (1, -1, F(1, 2)))]:
        scene.sample(name, at=at)
    for name, near in [("Cyl", (3, F(1, 5), 1)), ("Cyl", (-3, F(1, 5), 1)), ("Ring1", (0, 4, 3)),
                       ("Ring1", (0, 4, 1)), ("Ring2", (0, -4, 3)), ("Ring2", (0, -4, 1))]:
        scene.sample(name, near=near)
    return scene


def det(a, b, c):
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]))


def check_boundary(result):
    """Closedness and the exact volume of the boundary mesh; returns (edges used unevenly, volume)."""
    vertices, faces, _, _ = result.boundary_mesh(exact=True)
    q = [tuple(F(x) for x in row) for row in vertices]
    edges = collections.Counter()
    for a, b, c in faces.tolist():
        for x, y in ((a, b), (b, c), (c, a)):
            edges[(x, y)] += 1
    uneven = sum(1 for (x, y), k in edges.items() if edges[(y, x)] != k)
    volume = sum(det(q[a], q[b], q[c]) for a, b, c in faces.tolist()) / 6
    return uneven, volume


def plot(result, complex_, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    except ImportError:
        print(f"matplotlib is not installed: the plot {path} is skipped (the SVG needs nothing but hsx)")
        return
    vertices, faces, _, halfspace = result.boundary_mesh()
    colours = plt.get_cmap("tab10")
    fig = plt.figure(figsize=(7, 6))
    ax = fig.add_subplot(projection="3d")
    ax.add_collection3d(Poly3DCollection(vertices[faces], facecolors=[colours(int(h) % 10) for h in halfspace],
                                         edgecolors="k", linewidths=0.1, alpha=0.9))
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(hi - lo)
    ax.set_title(f"BSH shape of the CAD part: {len(faces)} triangles, colour = halfspace "
                 f"({', '.join(complex_.halfspaces)})", fontsize=8)
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--svg", help="write the engine's picture of the shape (four views)")
    parser.add_argument("--png", help="write a matplotlib plot of the shape's boundary")
    args = parser.parse_args(argv)

    cx = hsx.arrange(cad_part())
    print(cx)
    beam = hsx.extract(cx, method="beam")
    best = hsx.extract(cx, method="exact")
    print(f"beam: {beam.energy.missing_samples} missing, boundary area {beam.energy.measure.decimal(12)}, "
          f"volume {beam.volume.decimal(12)}; exact optimum: boundary area {best.energy.measure.decimal(12)}; "
          f"beam vs optimum: {beam.energy.compare(best.energy).name}")
    uneven, volume = check_boundary(beam)
    print(f"boundary mesh: {len(beam.boundary_mesh()[1])} triangles, {uneven} edges used unevenly, "
          f"divergence volume == exact volume: {'yes' if volume == beam.volume.rational else 'no'}")
    if args.svg:
        with open(args.svg, "w", encoding="utf-8") as f:
            f.write(beam.svg(width=1000, title="the CAD part's BSH shape"))
        print(f"wrote {args.svg}")
    if args.png:
        plot(beam, cx, args.png)
    return 0 if uneven == 0 and volume == beam.volume.rational else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
