"""The beam search of the BSH paper's Fig. 10, step by step, on data/figures/fig10.json (the letter S).

Beam search with K = 1 starts from the graph cut (the least-energy orientation-preserving boundary, which need not
be sample-connected), then repeatedly removes the removable set that gives the best next graph cut, until the
boundary is sample-connected. Each state is drawn: its inside cells filled, the patches removed so far
highlighted. With matplotlib the states are a row of plots (--png); the same states are also written as the
engine's own SVG pictures (--svg-prefix), which need nothing but hsx.

Usage: fig10_beam_walkthrough.py [--scene F] [--png OUT.png] [--svg-prefix PREFIX]
"""
import argparse
import pathlib
import sys

import hsx

HERE = pathlib.Path(__file__).resolve().parent
DEFAULT_SCENE = HERE.parent.parent / "data" / "figures" / "fig10.json"


def walk(scene):
    """The complex, the beam result and its states: (removed patches, labelling, energy) per step."""
    cx = hsx.arrange(scene)
    result = hsx.extract(cx, method="beam", beam_width=1, record_states=True)
    states = []
    for removed, labelling in zip(result.steps, result.expanded):
        grade = hsx.grade(cx, labelling)  # its exact energy and whether it is sample-connected
        states.append((removed, labelling, grade))
    return cx, result, states


def report(cx, result, states):
    print(f"{cx}")
    for k, (removed, labelling, grade) in enumerate(states):
        e = grade.energy
        print(f"step {k}: removed patches {removed}, inside cells {[i for i in range(len(labelling)) if labelling[i]]}, "
              f"energy ({e.missing_samples} missing, {e.measure.decimal(8)}), "
              f"sample-connected {'yes' if grade.sample_connected else 'no'}")
    best = hsx.extract(cx, method="exact")
    print(f"beam result: {result.energy.missing_samples} missing, boundary {result.energy.measure.decimal(12)}; "
          f"the exact optimum: {best.energy.missing_samples} missing, {best.energy.measure.decimal(12)}; "
          f"beam vs optimum: {result.energy.compare(best.energy).name}")


def write_svgs(cx, states, prefix):
    for k, (removed, labelling, grade) in enumerate(states):
        path = pathlib.Path(f"{prefix}{k}.svg")
        path.write_text(cx.svg(fill=labelling, highlight=removed, highlight_legend="removed patches",
                               title=f"Fig. 10, beam K = 1, step {k}"))
        print(f"wrote {path}")


def plot(cx, states, out):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.patches import PathPatch
        from matplotlib.path import Path
    except ImportError:
        print("matplotlib is not installed (Debian: python3-matplotlib): the row of pictures is skipped; the "
              "computation above is complete")
        return
    outlines, polylines = cx.cell_outlines(), cx.patch_polylines()
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    fig, axes = plt.subplots(1, len(states), figsize=(4 * len(states), 4.4), squeeze=False)
    for ax, (k, (removed, labelling, grade)) in zip(axes[0], enumerate(states)):
        for cell, loops in enumerate(outlines):
            if labelling[cell] and loops:
                verts = [p for loop in loops for p in list(loop) + [loop[0]]]
                codes = [c for loop in loops for c in [Path.MOVETO] + [Path.LINETO] * (len(loop) - 1) + [Path.CLOSEPOLY]]
                ax.add_patch(PathPatch(Path(verts, codes), facecolor="#9ecae1", edgecolor="none"))
        for p, pieces in enumerate(polylines):
            colour = colours[cx.patches[p].halfspace_index % len(colours)]
            width = 3.5 if p in removed else 1.2
            style = ":" if p in removed else "-"
            for xy in pieces:
                ax.plot(xy[:, 0], xy[:, 1], style, color=colour, linewidth=width)
        for s in cx.samples:
            xy = polylines[s.patch][len(polylines[s.patch]) // 2]
            mid = xy[len(xy) // 2]
            ax.plot(mid[0], mid[1], "o", color="black", markersize=5)
        e = grade.energy
        ax.set_title(f"step {k}: removed {removed}\n{e.missing_samples} missing, |b| = {e.measure.decimal(5)}")
        ax.set_aspect("equal")
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    print(f"wrote {out}")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(DEFAULT_SCENE))
    parser.add_argument("--png", help="write the row of matplotlib pictures here")
    parser.add_argument("--svg-prefix", help="write each state as PREFIX<k>.svg")
    args = parser.parse_args(argv)
    cx, result, states = walk(args.scene)
    report(cx, result, states)
    if args.svg_prefix:
        write_svgs(cx, states, args.svg_prefix)
    if args.png:
        plot(cx, states, args.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
