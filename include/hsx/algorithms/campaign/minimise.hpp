// Minimising a campaign's failing scene: a smaller scene on which the same checks still fail.
//
// minimise_scene reduces a scene greedily, in a fixed order, keeping a change only when the reduced scene is valid
// (validate_and_resolve accepts it) and the same checks still fail on it (check_scene, campaign.hpp):
//   1. halfspaces: try removing each halfspace, with the samples on it, from the last to the first; passes are
//      repeated until one removes nothing;
//   2. samples: try removing each sample, from the last to the first, repeated likewise;
//   3. coordinates, one pass: for each halfspace in order, each of its rational parameters in order (a halfplane's
//      normal x, y and offset, first all three divided by their common factor when they are whole numbers; a
//      disk's centre x, y and radius; a polygon's vertices, x then y), the simpler values of simpler_values() are
//      tried, simplest first, and the first that keeps the failure is kept; the samples on a halfspace whose
//      parameter changed become `near` samples of their point (snapped onto the new boundary). Then each sample's
//      point likewise (it becomes a `near` sample), then the domain rounded outward to whole numbers.
// "The same checks still fail": every check that failed on the original scene (catalogue or extra) fails on the
// reduced one; for a scene the library threw on (outcome Error), the reduced scene makes it throw too. Only those
// checks are computed (CampaignSettings::checks and ::extra restricted to them; each gives the result it gives in
// a full run), under the campaign's limits (a reduced scene that times out or is stopped does not fail).
//
// Determinism: the result depends only on (settings, scene, record) and the step budget, so a campaign's minimised
// scenes are the same bytes for any number of threads or processes, unless the campaign's time limit or
// MinimiseOptions::time_limit is reached (which depends on the machine).
#pragma once

#include <hsx/algorithms/campaign/campaign.hpp>

#include <string>
#include <vector>

namespace hsx::campaign {

/// The budget of a minimisation, so that a campaign never hangs on one scene.
struct MinimiseOptions {
  /// The most reduced scenes checked (each one check_scene call; candidates that validate_and_resolve refuses are
  /// not counted). 0: no limit. Deterministic.
  long max_steps = 200;
  /// Seconds for the whole minimisation, looked at between steps (0: none). Reaching it makes the result depend
  /// on the machine's speed.
  double time_limit = 0;
};

/// What minimise_scene found.
struct MinimiseResult {
  /// The minimised scene (resolved; its description is the original's): the original when it did not fail again
  /// (`reproduced` false) or nothing could be removed.
  Scene2 scene;
  /// check_scene's record of `scene` under the restricted settings (index and seed the original's; its checks are
  /// the target checks, whose witnesses are the minimised scene's).
  SceneRecord record;
  /// The checks that had to keep failing, in the record's order; {"error"} for a scene the library threw on.
  std::vector<std::string> target;
  long steps = 0;                   ///< reduced scenes checked (the original's re-check included)
  int removed_halfspaces = 0;       ///< halfspaces removed
  int removed_samples = 0;          ///< samples removed (with a halfspace or alone)
  int simplified_coordinates = 0;   ///< coordinate changes kept (parameters, sample points, the domain)
  bool reproduced = true;           ///< false: the original scene did not fail again under the restricted checks
  bool exhausted = false;           ///< the budget ran out before the order above was completed
};

/// The values tried in place of the rational q by step 3, simplest first: 0, q rounded toward zero, q rounded to
/// the nearest whole number (halves away from zero), q / 2 rounded toward zero for whole numbers, then q rounded to
/// the nearest multiple of 1/2, 1/4, ... (1/2^k with 2^k below q's denominator); only values simpler than q (a
/// smaller denominator, or the same and a smaller absolute numerator), each once.
std::vector<Rational> simpler_values(const Rational& q);

/// Minimises `scene`, on which `record` (its check_scene or run_scene record under `settings`, record.failed())
/// says which checks failed; see the order above. `scene` must be resolved. Throws std::invalid_argument when the
/// record did not fail, and what an extra check's function throws.
MinimiseResult minimise_scene(const CampaignSettings& settings, const Scene2& scene, const SceneRecord& record,
                              const MinimiseOptions& options = {});

}  // namespace hsx::campaign
