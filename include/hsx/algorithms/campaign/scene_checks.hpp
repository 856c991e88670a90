// The campaign's checks outside bsh::check_all (campaign.hpp's catalogue names them): Props. 6.1 and B.1
// (GENERATE-SAMPLES with fallbacks disabled), K-beam optimality, Shapiro-Vossler describability against BHC, and
// NH-Rep's Theorem 4.3 with the natural-halfspace evaluation. Each takes what it needs explicitly (a complex, a
// target or solid, an optimum, limits), so a test can feed it a broken input and a caller that checks a given
// scene (not a generated one) can run it alone; campaign.cpp's run_scene gives them the scene's complex, its
// intended solid (SamplePolicy::Intended) or its optimum, and the campaign's limits.
//
// Witness conventions (each check's status and witness; never silent):
// - Props. 6.1 / B.1 are proved at generic junctions only (proofs/csg.md §5). As check_all's Prop. 5.1 / 5.2,
//   they run on every scene and report held / failed; at non-generic junctions the witness ends with
//   " [N non-generic junction(s): the proposition is not guaranteed]", so a failure there is a finding about the
//   proposition's hypothesis, not a bug. (Summary tallies them all alike; grep the witness to separate them.)
// - K-beam optimality: held "optimal: E" / "sub-optimal: E" (E the beam's energy, as check_all's beam1), failed
//   when the beam's result is not admissible or is below the optimum (a bug of the beam or of the optimum).
// - Describability vs BHC: held when they agree, "describable: ..." or "not describable: ...".
// - NH-Rep: held "tree correct: ...", "describable, tree fails: ..." or "not describable: ..." (the evaluation's
//   verdict, a rate like beam optimality); failed when a structural check of the tree (Theorem 4.3's
//   constructive part, check_tree) or of the evaluation (Claim 5.1: correct => describable) is violated, or the
//   pipeline threw.
#pragma once

#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/campaign/campaign.hpp>
#include <hsx/algorithms/csg/bhc.hpp>
#include <hsx/algorithms/nhrep/survey.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/complex/from_arrangement3.hpp>

#include <functional>
#include <string>
#include <vector>

namespace hsx::campaign {

/// The limits a check's searches run under (bsh::ExtractOptions'; 0 / empty: none).
struct CheckLimits {
  long max_states = 0;
  long max_graph_cuts = 0;
  CompareOptions compare;
  /// Asked wherever the searches ask their time limit; true stops them (the check is then Stopped). The campaign
  /// folds its time limit into it. May be empty.
  std::function<bool()> cancel;
  /// The oracle's limit for certifying best-first at non-generic junctions (ExtractOptions::certify_limit).
  long certify_limit = 200000;
};

/// " [N non-generic junction(s): the proposition is not guaranteed]" when `complex` has non-generic junctions
/// (bsh::Problem::non_generic_junctions), else "".
std::string genericity_note(const Complex& complex);

/// The optimum the checks below compare with: the exact branch and bound (bsh/exact.hpp; right at any junction,
/// as check_all's optimum), within `limits` (max_states bounds its nodes). No tie enumeration. Its `stopped_by`
/// names a limit that stopped it; `optimal` false then.
bsh::ExtractResult reference_optimum(const Complex& complex, const CheckLimits& limits);

/// Prop. 6.1 (`search` BestFirst) or Prop. B.1 (`search` Beam, K = 1) on `target`: bsh::generate_samples with
/// fallbacks disabled must reproduce it by the greedy rounds alone, in at most (patches of b) - initial + 1
/// rounds. `target`: a labelling of `complex`'s cells (one flag per cell, else std::invalid_argument); a target
/// that is not orientation-preserving fails (the propositions' hypothesis: a broken input). Stopped when a limit
/// stopped a round. `name`: the outcome's check name.
CheckOutcome check_generate_samples(const std::string& name, const Complex& complex, const bsh::Labelling& target,
                                    bsh::Method search, const CheckLimits& limits);

/// Beam search of width `beam_width` (>= 1) against `optimum` (reference_optimum's, or any proven optimum): held
/// "optimal: E" or "sub-optimal: E"; failed when the beam's result is not orientation-preserving or not
/// sample-connected, or its energy is below the optimum's (then the optimum is wrong or the beam is); stopped when
/// the beam or the optimum was stopped by a limit (or the optimum is not proven).
CheckOutcome check_beam_optimality(const std::string& name, const Complex& complex, int beam_width,
                                   const bsh::ExtractResult& optimum, const CheckLimits& limits);

/// The verdict of describability against BHC: held when BHC's describable equals Shapiro-Vossler's and, when
/// describable, BHC's tree is verified on every cell; failed otherwise. `what` names the solid in the witness
/// (e.g. "the optimum"); `cells`: the complex's cell count (for the witness).
CheckOutcome describability_outcome(const std::string& name, const csg::Describability& describability,
                                    const csg::BhcResult& bhc, const std::string& what, long cells);
/// describability() and bhc() of `solid` (one flag per cell of `complex`) on `complex`, judged by
/// describability_outcome.
CheckOutcome check_describability(const std::string& name, const Complex& complex, const std::vector<char>& solid,
                                  const std::string& what);

/// The verdict of an NH-Rep survey outcome (nhrep::survey_solid): skipped for an empty or unbounded solid (not
/// surveyed), failed when outcome.problems is not empty (the first problem in the witness), else held with the
/// evaluation's verdict as the witness's first words.
CheckOutcome nhrep_outcome(const std::string& name, const nhrep::SurveyOutcome& outcome, const std::string& what);
/// NH-Rep's pipeline (nhrep::survey_solid) on `solid` (one flag per cell of `arranged.complex`, the arrangement
/// of `scene`): on the whole-plane arrangement of the scene's halfspaces (complex/carry_solid2.hpp, the survey's
/// convention) and on the scene's own domain; judged by nhrep_outcome.
CheckOutcome check_nhrep(const std::string& name, const Scene2& scene, const Arranged2& arranged,
                         const std::vector<char>& solid, const std::string& what);

/// The same in 3D: nhrep::survey_solid3 (hsx nhsurvey --dimension 3's pipeline) on `solid` (one flag per cell of
/// `arranged.complex`, the arrangement of `scene`), on the scene's own arrangement, which holds every vertex when
/// hsx chose the domain (no whole-space carry, no own-domain run: survey_solid3 has none). Skipped when the
/// scene's domain was given (then some sign vectors of space may have no cell); judged by nhrep_outcome.
CheckOutcome check_nhrep3(const std::string& name, const Scene3& scene, const Arranged3& arranged,
                          const std::vector<char>& solid, const std::string& what);

}  // namespace hsx::campaign
