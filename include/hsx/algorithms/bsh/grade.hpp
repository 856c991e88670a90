// Grading a labelling computed elsewhere (a floating-point or GPU BSH implementation, a learned model, a person):
// is it a valid BSH boundary, of which energy, and how far from the exact optimum?
//
// Conventions: those of algorithms/bsh/problem.hpp (labels per cell, outer cells 0, energy as the pair
// (missing samples, boundary measure) compared lexicographically and certified).
#pragma once

#include <hsx/algorithms/bsh/extract.hpp>

#include <string>
#include <vector>

namespace hsx::bsh {

struct Grade {
  /// Def. 3.1: every outer cell is 0 and every support on the boundary is used with an orientation one of its
  /// halfspaces has (and no sampled patch reversed). When false, `orientation_problem` names the first offender.
  bool orientation_preserving = false;
  std::string orientation_problem;
  /// Def. 3.2. `islands`: the components of b ∩ b_i without a sample of i (patch ids: the witnesses).
  bool sample_connected = false;
  std::vector<Component> islands;
  Energy energy;                 ///< E(b) of the graded labelling (computed even when it is not valid)
  ExtractResult optimum;         ///< the reference: reference_optimum's result (`optimal`: proven; `method`: which)
  /// The graded energy against the optimum's: Equal (optimal), Greater (worse), Less (better: only possible when
  /// the labelling is invalid or the reference is not proven), Tie (the measures did not separate).
  Order versus_optimum = Order::Tie;
  long missing_samples_gap = 0;  ///< energy.missing_samples - optimum.energy.missing_samples
  Measure measure_gap;           ///< energy.measure - optimum.energy.measure (exact)

  /// A valid BSH boundary whose energy is proven equal to a proven optimum.
  bool optimal() const {
    return orientation_preserving && sample_connected && optimum.optimal && versus_optimum == Order::Equal;
  }
};

/// The default oracle options of `grade`: Method::BestFirst, no limits.
ExtractOptions best_first_oracle();

/// The reference optimum of `grade`: extract(problem, oracle), except where the oracle is best-first and ends
/// unproven without a limit stopping it (non-generic junctions with the oracle-backed certification too large, or
/// a graph cut whose measures did not separate: ExtractResult::optimality_note): then the exact branch and bound
/// (bsh/exact.hpp, right at any junction) under the same limits decides, and its result is returned, with
/// optimality_note saying so. When exact too is stopped by a limit, best-first's unproven result is returned (its
/// note saying that exact was stopped). Deterministic without a time limit. `oracle` as in `grade`.
ExtractResult reference_optimum(const Problem& problem, const ExtractOptions& oracle = best_first_oracle());

/// Grades `labelling` on `problem`'s complex.
/// - `labelling`: one entry per cell of the complex (1 inside, 0 outside). Throws std::invalid_argument when its
///   size is not the cell count.
/// - `oracle`: how the reference optimum is computed (reference_optimum: best-first falls back to exact where it
///   is left unproven without a limit); the default is the complete best-first search with tie enumeration. With
///   limits (max_states, max_nodes, time_limit) the reference may be unproven: Grade::optimum.optimal says.
Grade grade(const Problem& problem, const Labelling& labelling, const ExtractOptions& oracle = best_first_oracle());

}  // namespace hsx::bsh
