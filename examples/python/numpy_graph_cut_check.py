"""The ground-truth workflow: a small graph cut written in numpy (floating point, as a prototype would be), checked
exactly by hsx on random scenes.

The prototype minimises the BSH energy without sample-connectedness (Section 5.1): per cell a label (1 inside),
outer cells 0, per support group of coincident patches its orientations (problem.hpp's rule), its measure when on
the boundary and a weight W > (every measure together) per missing sample, so that one sample outweighs any
length. Each support's pairwise term is submodular and goes into an s-t graph the usual way (Kolmogorov-Zabih);
Edmonds-Karp over a dense numpy matrix finds the cut. hsx then grades the labelling exactly (hsx.grade) and
compares its energy with hsx's certified graph cut and with the exact optimum (hsx.extract(method="exact")):
  - the prototype's energy must equal hsx's graph cut (both are optimal without sample-connectedness), and
  - it can only be below the exact optimum when its boundary is not sample-connected; when it is, it must be equal.
A float rounding that picks a worse cut is reported as a finding, never hidden.

Usage: numpy_graph_cut_check.py [--seed S] [--count N]
"""
import argparse
import sys
from collections import deque

import numpy as np

import hsx

INF = float("inf")


def supports_of(cx):
    """Per support group: (cell_a, cell_b, allow_a_inside, allow_b_inside, samples inside a, samples inside b,
    measure as a float)."""
    out = []
    for group in cx.supports:
        patches = [cx.patches[p] for p in group]
        a, b = patches[0].inside_cell, patches[0].outside_cell
        has = {a: any(p.inside_cell == a for p in patches), b: any(p.inside_cell == b for p in patches)}
        sampled = {a: sum(len(p.samples) for p in patches if p.inside_cell == a),
                   b: sum(len(p.samples) for p in patches if p.inside_cell == b)}
        allow_a = has[a] and sampled[b] == 0  # a sampled patch may not be used reversed
        allow_b = has[b] and sampled[a] == 0
        out.append((a, b, allow_a, allow_b, sampled[a], sampled[b], float(patches[0].measure)))
    return out


def build_graph(cx):
    """Capacities of the s-t graph (nodes: cells, then source n and sink n + 1; source side = label 1)."""
    n = len(cx.cells)
    cap = np.zeros((n + 2, n + 2))
    s, t = n, n + 1
    terms = supports_of(cx)
    weight = 1.0 + sum(m for *_, m in terms)

    def unary(v, c):  # c * x_v
        if c > 0:
            cap[v, t] += c
        elif c < 0:
            cap[s, v] += -c

    for a, b, allow_a, allow_b, sa, sb, m in terms:
        A = D = weight * (sa + sb)            # same labels: the support is not on b, its samples are missing
        C = m + weight * sb if allow_a else INF   # a inside, b outside
        B = m + weight * sa if allow_b else INF   # b inside, a outside
        if C == INF:
            cap[a, b] = INF                   # x_a <= x_b
            C = A + D - B if B != INF else A
        if B == INF:
            cap[b, a] = INF                   # x_b <= x_a
            B = A + D - C
        unary(a, C - A)
        unary(b, D - C)
        cap[b, a] += B + C - A - D            # (1 - x_a) * x_b, >= 0: submodular
    for k, cell in enumerate(cx.cells):
        if cell.outer:
            cap[k, t] = INF
    return cap, s, t


def min_cut(cap, s, t):
    """Edmonds-Karp; returns the source side of a minimum cut as a bool array."""
    residual = cap.copy()
    while True:
        parent = np.full(len(cap), -1)
        parent[s] = s
        queue = deque([s])
        while queue and parent[t] < 0:
            u = queue.popleft()
            for v in np.nonzero((residual[u] > 1e-12) & (parent < 0))[0]:
                parent[v] = u
                queue.append(v)
        if parent[t] < 0:
            return parent >= 0
        path, v = [], t
        while v != s:
            path.append((parent[v], v))
            v = parent[v]
        push = min(residual[u, v] for u, v in path)
        for u, v in path:
            residual[u, v] -= push
            residual[v, u] += push


def numpy_graph_cut(cx):
    cap, s, t = build_graph(cx)
    return min_cut(cap, s, t)[: len(cx.cells)]


def check(scene):
    cx = hsx.arrange(scene)
    labels = numpy_graph_cut(cx)
    grade = hsx.grade(cx, labels, oracle="exact")       # exact energy, validity, the exact optimum
    certified_cut = hsx.extract(cx, method="graphcut")  # hsx's own graph cut, certified by a flow
    versus_cut = grade.energy.compare(certified_cut.energy)
    versus_exact = grade.versus_optimum
    ok = grade.orientation_preserving and versus_cut == hsx.Order.Equal and (
        versus_exact == hsx.Order.Equal if grade.sample_connected else versus_exact != hsx.Order.Greater)
    return cx, grade, versus_cut, versus_exact, ok


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=16)
    parser.add_argument("--count", type=int, default=12)
    args = parser.parse_args(argv)
    findings = 0
    connected = 0
    for k, scene in enumerate(hsx.random_scenes(args.seed, count=args.count, min_halfspaces=2, max_halfspaces=5,
                                                max_samples=5)):
        cx, grade, versus_cut, versus_exact, ok = check(scene)
        connected += grade.sample_connected
        findings += not ok
        print(f"scene {args.seed}/{k}: {len(cx.cells)} cells; numpy cut: {grade.energy.missing_samples} missing, "
              f"{grade.energy.measure.decimal(10)}; vs hsx graph cut {versus_cut.name}, vs exact optimum "
              f"{versus_exact.name}, sample-connected {'yes' if grade.sample_connected else 'no'}"
              f"{'' if ok else '  <-- FINDING'}")
    print(f"{args.count} scenes: {args.count - findings} agree with hsx ({connected} sample-connected, hence "
          f"proven optimal BSH shapes), {findings} findings")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
