// Section 5.1: the BSH boundary without sample-connectedness, as a minimum s-t cut (Eqs. 2-4), computed exactly
// and certified.
//
// Graph (Fig. 8): one vertex per cell, plus s and t. Label 1 (inside) = s side.
//   s -> c  weight h_c(0) = samples on patches whose inside cell is c      (c labelled 0 misses them)
//   c -> t  weight h_c(1) = samples on patches whose outside cell is c     (c labelled 1 misses them);
//           infinite for outer cells (they are always outside)
//   a -> b  weight h_ab(1,0) = sum of the measures of the supports between a and b whose inside cell is a, each
//           counted once; infinite if any support between them forbids a=1, b=0 (reversed orientation, removed,
//           or coincident halfspaces that disagree)
// Weights are pairs (samples, measure) ordered lexicographically: that is lambda > total measure, exactly.
#pragma once

#include <hsx/algorithms/bsh/problem.hpp>

#include <functional>

namespace hsx::bsh {

struct CutResult {
  Labelling labelling;
  Energy energy;                 ///< of `labelling`, computed from the labelling itself
  /// The optimality certificate: the max flow is feasible (0 <= flow <= capacity on every edge, conserved at
  /// every cell) and its value equals `energy` - which by weak duality proves no labelling is cheaper.
  bool certified = false;
  std::string certificate_note;  ///< why not certified (a comparison that did not separate), empty if certified
  long augmentations = 0;
  /// The `stop` callback ended the max flow early: labelling and energy mean nothing (missing_samples is -1).
  bool stopped = false;
};

/// Constraints on one graph cut.
struct CutConstraints {
  std::vector<char> removed;       ///< per support: 1 = may not lie on the boundary (|p| = infinity); empty: none
  std::vector<signed char> forced; ///< per cell: -1 free, 0 or 1 fixed (used to enumerate ties); empty: none
  /// How the max flow is found: true (the default) from a flow found in doubles (Boost's Boykov-Kolmogorov): first
  /// a basic flow read off it is certified without exact capacities where double enclosures decide (proofs/bsh.md
  /// entry 3); when that fails, the double flow is decomposed into paths, each augmented exactly by its certified
  /// bottleneck, and Edmonds-Karp finishes it exactly. false: Edmonds-Karp from the zero flow, the reference tests
  /// compare with. The labelling is the same either way (and so are energy and `certified` where both certify).
  bool warm_start = true;
};

/// Minimum-energy orientation-preserving labelling under `constraints`. When the constraints admit no finite
/// labelling, `energy.missing_samples` is -1 and `certified` is false. `stop`, when set, is asked before the double
/// flow, and, when the exact max flow is needed, before each warm-start path and before every augmenting path (a
/// time limit); when it says stop, the result has `stopped` set.
CutResult graph_cut(const Problem& problem, const CutConstraints& constraints,
                    const std::function<bool()>& stop = {});

/// The cost of the s-t cut that corresponds to `labelling` in the graph above, summed edge by edge (infinite
/// when the labelling breaks a constraint). Used to check that cut cost == energy (Eqs. 2-4).
/// Returns false if infinite.
bool cut_cost(const Problem& problem, const CutConstraints& constraints, const Labelling& labelling, Energy* cost);

}  // namespace hsx::bsh
