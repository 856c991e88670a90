// Executable checkers of the BSH paper's propositions. Each returns pass/fail with a witness a person can read;
// a failure on valid input is a counterexample (or a bug) and is kept as data (proofs/bsh.md says how).
#pragma once

#include <hsx/algorithms/bsh/extract.hpp>

#include <functional>
#include <string>
#include <vector>

namespace hsx::bsh {

struct CheckResult {
  std::string name;       ///< e.g. "Prop. 5.2: best-first = brute force"
  /// Skipped: not run (the oracle too large, the time limit already spent, not applicable); Stopped: run but cut
  /// short by a limit, so neither a pass nor a failure (the witness says which limit and what was checked).
  enum Status { Pass, Fail, Skipped, Stopped } status = Pass;
  std::string witness;    ///< what was compared, or the counterexample
};
const char* to_string(CheckResult::Status s);

/// Prop. 5.1 for one pair: b (not sample-connected) and b' (sample-connected), both orientation-preserving. For
/// every island I of b: I ∩ b' = ∅ or some support of b adjacent to I is not on b'.
CheckResult check_prop51(const Problem& problem, const Labelling& b, const Labelling& b_prime);

/// Prop. 4.1: one sample on every patch of the orientation-preserving boundary of `labelling` makes it the unique
/// BSH boundary (checked with the exact branch and bound, bsh/exact.hpp, and its tie enumeration on a copy of the
/// complex with those samples only). `limits`: the search's limits and comparison options (its method is ignored;
/// exact reads time_limit, max_nodes, max_ties, compare and cancel); a limit that cuts the search or its tie
/// enumeration gives Stopped.
CheckResult check_prop41(const Complex& complex, const Labelling& labelling, const ExtractOptions& limits = {});

/// Section 3.1, combinatorially. 2D: every junction has an even number of boundary patch ends. 3D: exactly two
/// sheets of b meet along every junction b touches (Junction::sheets: with four, b pinches along an edge), and
/// b's link at every corner it touches is one circle (Complex::corners: two circles, b pinches at a point).
/// Sec. 3.1 proves it at generic input, so a failure marks non-generic input (the witness says whether the junction
/// is generic, Problem::non_generic_junctions); Skipped on a 3D complex without sheets and corners.
CheckResult check_manifold_parity(const Problem& problem, const Labelling& labelling);

/// The complex with its samples replaced by one sample on each patch of `labelling`'s boundary.
Complex with_one_sample_per_boundary_patch(const Complex& complex, const Labelling& labelling);

/// The checks of check_all, in the order of its results.
enum class Check {
  Existence,      ///< Sec. 4.1
  Prop52,         ///< Prop. 5.2 (best-first = brute force, or = exact)
  Prop51,         ///< Prop. 5.1 on every expanded state
  Beam,           ///< beam K=1 admissible, energy >= optimum
  Prop41Optimum,  ///< Prop. 4.1 on the optimum
  Prop41Beam,     ///< Prop. 4.1 on the beam result
  Uniqueness,     ///< Sec. 4.2
  Certificates,   ///< Eqs. 2-4
  Manifold        ///< Sec. 3.1 on the optimum
};
inline constexpr int kCheckCount = 9;

/// The limits of check_all, as extract's (ExtractOptions says which are deterministic).
struct CheckOptions {
  /// The checks to run (empty: all). check_all returns the selected ones only, in its order, and computes only
  /// what they need; a selected check gives the result it gives in a full run (each search runs whenever a
  /// selected check needs it: best-first for Prop52 and Prop51, the oracle for Prop52, the exact search for
  /// Prop51, Beam, Prop41Optimum, Uniqueness, Certificates and Manifold, the beam for Beam, Prop41Beam and
  /// Certificates), except that a time limit may run out at another point.
  std::vector<Check> only;
  long brute_force_limit = 200000;  ///< labellings the oracle may enumerate (more: Prop. 5.2 against exact)
  CompareOptions compare;
  double time_limit = 0;   ///< seconds for all checks together (0: none); checks left when it runs out are skipped
  long max_states = 0;     ///< per search: expanded states, and the exact search's nodes (max_nodes) (0: none)
  long max_graph_cuts = 0; ///< per search: graph cuts (0: none)
  /// Asked where the time limit is (ExtractOptions::cancel); true stops the running check (Stopped) and skips the
  /// rest. May be empty.
  std::function<bool()> cancel;
};

/// Every applicable checker on one complex: existence (4.1), Prop. 5.2 (best-first = brute force when the oracle
/// is small enough, else = the exact branch and bound), Prop. 5.1 on every state best-first expanded, beam K=1
/// feasibility and energy >= optimum, Prop. 4.1 on the optimum and on the beam result, uniqueness or a reported tie
/// (4.2), every graph cut certified, manifold parity. A check the limits cut short is Stopped, one they leave no
/// room for Skipped. With options.only, the selected checks only (CheckOptions::only).
/// The optimum: the checks that need only an optimum (Prop. 5.1's sample-connected reference b', the beam's
/// comparison, Prop. 4.1 on it, uniqueness with its ties, manifold parity) take the exact branch and bound's
/// (bsh/exact.hpp, ties up to 16), which is proven at any junction and far faster than best-first; Prop. 4.1 is
/// decided by exact too. Best-first (with record_states) runs only for Prop. 5.2 and Prop. 5.1, the checks about
/// best-first itself. The certificates are those of the exact search's certified cuts and the beam's cuts.
std::vector<CheckResult> check_all(const Complex& complex, const CheckOptions& options);
/// The same with only the oracle's limit and comparison options.
std::vector<CheckResult> check_all(const Complex& complex, long brute_force_limit = 200000,
                                   const CompareOptions& compare = {});

}  // namespace hsx::bsh
