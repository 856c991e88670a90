// `--method exact`: the BSH shape of Definition 3.3 by branch and bound over orientation-preserving labellings,
// with every optimal labelling (ties). It works on labellings directly, so it needs neither Prop. 5.1 nor 5.2 and
// is right at non-generic junctions too; proofs/bsh.md (entry 10) has the theorem.
//
// Conventions (owned here):
// - Search space: the closed sets of the implication graph over cells ("x = 1 => y = 1" when a support between x
//   and y may lie on b only with y inside; both ways when neither orientation is allowed, problem.hpp), with outer
//   cells 0. These are exactly the orientation-preserving labellings.
// - A node is a partial assignment of cells (-1 undecided, 0, 1), closed under the implications (propagation);
//   its region is the set of orientation-preserving labellings that agree with it. Every closed partial assignment
//   has a non-empty region (set the undecided cells to 0).
// - Lower bound of a node: the minimum s-t cut of Section 5.1 (graph_cut.hpp's graph) with the decided cells tied to s
//   or t. It ignores sample-connectedness, so it bounds every labelling of the region from below. It is computed fast
//   and rigorously in integers: each support's measure is replaced by floor(lo * 2^k) for a rigorous double lower
//   enclosure lo (Problem::support_enclosures, which are finite: measures beyond the largest double are enclosed times
//   2^-Problem::enclosure_scale()) and a common scale 2^k, each sample by a weight M larger than all those integers
//   together; an exact integer max flow (Boost Boykov-Kolmogorov) of these rounded-down capacities is a lower bound on
//   the true min cut (weak duality), and its value V decodes to the EnergyBound (floor(V / M), (V mod M) / 2^k, times
//   2^enclosure_scale() when reported: a lower bound beyond the largest double is reported as the largest double). An
//   s-t path of infinite capacities means the node has no admissible labelling (checked before the flow). The cut's
//   labelling is orientation-preserving; when it is sample-connected it is a candidate for the incumbent (its energy
//   is then computed exactly).
// - Pruning: by bound, only when the bound provably exceeds the incumbent's exact energy (or provably reaches it
//   once ties are no longer wanted: not enumerated, or ExtractOptions::max_ties reached). When the fast bound
//   does not decide it but the node's candidate is exactly worse than the incumbent, the exact certified graph
//   cut (graph_cut.hpp, a proof by a feasible flow) decides it. By islands: a patch of halfspace i that may
//   still lie on b with i's orientation is "dead" when no sampled patch of i is reachable from it through such
//   patches (sharing junctions): in every completion where it is on b it is in an island. A dead patch that is
//   definite (inside cell 1, outside cell 0) prunes the node; otherwise dead patches forbid their support's
//   orientation in the node's cut and are propagated into the labels (inside 1 forces outside 1, outside 0
//   forces inside 0), repeated until nothing changes. This removes only labellings that are not
//   sample-connected, so the bound stays valid for every sample-connected labelling of the region.
// - Branching (ExtractOptions::exact_branching): with Islands (the default), on an island I of the candidate (the
//   one with the fewest children) and its frontier F (patches of I's halfspace sharing a junction with I, outside
//   it): child j has I's first j - 1 patches on b with their orientation and the j-th one's orientation excluded;
//   then child |I| + j has all of I on, F's first j - 1 patches excluded and the j-th one on. This partitions the
//   sample-connected labellings of the region, and no child keeps the candidate. A node therefore carries, besides
//   its labels, the orientations its branching excluded (forbidden in its cut, propagated like dead patches).
//   With Cells, or when the candidate has no island: on an undecided cell of the candidate's first island (else of
//   its boundary, else the first undecided cell); the child that keeps the candidate's value reuses its cut. Nodes
//   are expanded best-bound first (deterministic order: bound, then the newest node).
// - Incumbent: the empty labelling (always sample-connected), a greedy seed (the root's fast cut with every
//   island's supports kept off the boundary, repeated until sample-connected) and every sample-connected
//   candidate; all comparisons that choose it are bsh::compare. Ties are the distinct labellings whose energy equals the final
//   incumbent's (Equal, or Tie = not separated, which clears Ties::certified).
// - Limits (ExtractOptions::time_limit, max_nodes, checked before every expansion) stop the search with the
//   incumbent, optimal = false, stopped_by set, and the proven lower bound in SearchStats.
#pragma once

#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/bsh/problem.hpp>

namespace hsx::bsh {

/// The exact method: `options.method` is ignored; uses time_limit, max_nodes, exact_branching, enumerate_ties,
/// max_ties, compare, progress and cancel. The result's method is Method::Exact; `removed` is all zeros and `steps` empty (no
/// removed sets here); stats carry nodes, prunings, the lower bound and the gap. Never fails on valid input.
ExtractResult extract_exact(const Problem& problem, const ExtractOptions& options);

}  // namespace hsx::bsh
