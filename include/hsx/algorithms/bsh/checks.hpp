// Executable checkers of the BSH paper's propositions. Each returns pass/fail with a witness a person can read;
// a failure on valid input is a counterexample (or a bug) and is kept as data (proofs/bsh.md says how).
#pragma once

#include <hsx/algorithms/bsh/extract.hpp>

#include <string>
#include <vector>

namespace hsx::bsh {

struct CheckResult {
  std::string name;       ///< e.g. "Prop. 5.2: best-first = brute force"
  enum Status { Pass, Fail, Skipped } status = Pass;
  std::string witness;    ///< what was compared, or the counterexample
};
const char* to_string(CheckResult::Status s);

/// Prop. 5.1 for one pair: b (not sample-connected) and b' (sample-connected), both orientation-preserving. For
/// every island I of b: I ∩ b' = ∅ or some support of b adjacent to I is not on b'.
CheckResult check_prop51(const Problem& problem, const Labelling& b, const Labelling& b_prime);

/// Prop. 4.1: one sample on every patch of the orientation-preserving boundary of `labelling` makes it the unique
/// BSH boundary (checked with best-first and tie enumeration on a copy of the complex with those samples only).
CheckResult check_prop41(const Complex& complex, const Labelling& labelling, const CompareOptions& compare = {});

/// Section 3.1 in 2D, combinatorially: every junction has an even number of boundary patch ends.
CheckResult check_manifold_parity(const Problem& problem, const Labelling& labelling);

/// The complex with its samples replaced by one sample on each patch of `labelling`'s boundary.
Complex with_one_sample_per_boundary_patch(const Complex& complex, const Labelling& labelling);

/// Every applicable checker on one complex: existence (4.1), Prop. 5.2 (best-first = brute force when the oracle
/// is small enough), Prop. 5.1 on every state best-first expanded, beam K=1 feasibility and energy >= optimum,
/// Prop. 4.1 on the optimum and on the beam result, uniqueness or a reported tie (4.2), every graph cut
/// certified, manifold parity. `brute_force_limit` bounds the oracle (larger: reported as skipped).
std::vector<CheckResult> check_all(const Complex& complex, long brute_force_limit = 200000,
                                   const CompareOptions& compare = {});

}  // namespace hsx::bsh
