// Minimising a campaign's failing scene: a smaller scene on which the same checks still fail.
//
// minimise_scene reduces a scene greedily, in a fixed order, keeping a change only when the reduced scene is valid
// (validate_and_resolve accepts it), its intended shape (below) is well defined on it, and the same checks still
// fail on it (check_scene, campaign.hpp). A 2D scene:
//   1. halfspaces: try removing each halfspace, with the samples on it, from the last to the first; passes are
//      repeated until one removes nothing;
//   2. samples: try removing each sample, from the last to the first, repeated likewise;
//   3. coordinates, one pass: for each halfspace in order, each of its rational parameters in order (a halfplane's
//      normal x, y and offset, first all three divided by their common factor when they are whole numbers; a
//      disk's centre x, y and radius; a polygon's vertices, x then y), the simpler values of simpler_values() are
//      tried, simplest first, and the first that keeps the failure is kept; the samples on a halfspace whose
//      parameter changed become `near` samples of their point (snapped onto the new boundary). Then each sample's
//      point likewise (it becomes a `near` sample), then the domain rounded outward to whole numbers.
// A 3D scene (CampaignSettings::dimension 3):
//   1. primitives: the halfspaces are grouped by their name up to its first '.' (a box "b1.xmin" ... "b1.zmax" is
//      one group, as a CoincidentFaces pattern "d0.xmin" ...; every other halfspace, a sphere, a cylinder, a lone
//      plane, a PlaneOnBoxFace or ConcurrentPlanes pattern "d<j>", is a group of its own); try removing each
//      group with the samples on it, from the last group (by its first halfspace) to the first, repeated until a
//      pass removes nothing; then each halfspace of a group of several likewise (a box face alone);
//   2. samples, as in 2D;
//   3. segments, one pass: for each halfspace in order tessellated by segment count (sphere, cylinder, cone,
//      torus; Tessellation3::Mode::Segments), the counts lower_segments() gives are tried, lowest first (the surface
//      tessellated again, its samples made `near` samples of their points), and the first that keeps the failure
//      is kept.
// The domain of a 3D scene chosen by hsx is chosen again for each reduced scene; a given one is kept.
//
// "The same checks still fail": every check that failed on the original scene (catalogue or extra) fails on the
// reduced one; for a scene the library threw on (outcome Error), the reduced scene makes it throw too. Only those
// checks are computed (CampaignSettings::checks and ::extra restricted to them; each gives the result it gives in
// a full run), under the campaign's limits (a reduced scene that times out or is stopped does not fail).
//
// The intended shape (SamplePolicy::Intended: prop61 and propB1 run on it, describability and nhrep too) is part
// of the failing instance when one of those four checks failed, but it is a set of cells of the original scene,
// which a reduced scene does not have. It is then carried by sign vectors (carry_by_sign_vectors): a cell of a reduced scene is inside iff the original cells
// whose sign vectors, restricted to the halfspaces the reduced scene kept, equal the cell's sign vector are inside.
// That is well defined only when those original cells exist and agree: a reduction that merges an inside and an
// outside cell into one sign vector (removing the halfspace that told them apart), or whose cell has a sign vector
// that no original cell restricts to (a coordinate change that made a new region), has no intended shape and is
// not kept; nor is one whose carried shape loses a property of the original shape: orientation-preserving (else
// prop61 would fail on its hypothesis instead of the proposition) and no outer cell (touching the domain box)
// inside. (The 2D generator's shapes have both; a 3D CSG shape need not be orientation-preserving, and prop61 and
// propB1 then fail on their hypothesis, "the target is not orientation-preserving", which is minimised as such.) The reduced scene's record has its carried shape (SceneRecord::intended), which the kept file's
// note names. (3D intended shapes are CSG expressions evaluated on cells, always functions of sign vectors; a 2D
// drawn shape may give two cells of one sign vector different flags, and then no reduction that keeps that sign
// vector's cells is kept.)
//
// Determinism: the result depends only on (settings, scene, record) and the step budget, so a campaign's minimised
// scenes are the same bytes for any number of threads or processes, unless the campaign's time limit or
// MinimiseOptions::time_limit is reached (which depends on the machine).
#pragma once

#include <hsx/algorithms/campaign/campaign.hpp>

#include <optional>
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

/// What minimise_scene found (`Scene`: Scene2 or Scene3).
template <class Scene>
struct Minimised {
  /// The minimised scene (resolved; its description is the original's): the original when it did not fail again
  /// (`reproduced` false) or nothing could be removed.
  Scene scene;
  /// check_scene's record of `scene` under the restricted settings (index and seed the original's; its checks are
  /// the target checks, whose witnesses are the minimised scene's; `intended` the carried intended shape).
  SceneRecord record;
  /// The checks that had to keep failing, in the record's order; {"error"} for a scene the library threw on.
  std::vector<std::string> target;
  long steps = 0;                   ///< reduced scenes checked (the original's re-check included)
  int removed_halfspaces = 0;       ///< halfspaces removed
  int removed_samples = 0;          ///< samples removed (with a halfspace or alone)
  int simplified_coordinates = 0;   ///< 2D: coordinate changes kept (parameters, sample points, the domain)
  int lowered_segments = 0;         ///< 3D: segment counts lowered
  bool reproduced = true;           ///< false: the original scene did not fail again under the restricted checks
  bool exhausted = false;           ///< the budget ran out before the order above was completed
};
using MinimiseResult = Minimised<Scene2>;
using MinimiseResult3 = Minimised<Scene3>;

/// The values tried in place of the rational q by step 3, simplest first: 0, q rounded toward zero, q rounded to
/// the nearest whole number (halves away from zero), q / 2 rounded toward zero for whole numbers, then q rounded to
/// the nearest multiple of 1/2, 1/4, ... (1/2^k with 2^k below q's denominator); only values simpler than q (a
/// smaller denominator, or the same and a smaller absolute numerator), each once.
std::vector<Rational> simpler_values(const Rational& q);

/// The segment counts tried in place of `segments` by the 3D step 3, lowest first: 3, 4, 6, 8, 12, 16, 24, 32, 48,
/// ... (2^k and 3 * 2^k), those below `segments`.
std::vector<int> lower_segments(int segments);

/// The intended shape `solid` (one flag per cell of `original`) carried to `reduced`, a complex of a reduced scene
/// whose halfspace k is the original's halfspace `origin[k]` (possibly with other coordinates or segments): a
/// reduced cell is inside iff every original cell whose sign vector (Cell::inside) restricted to `origin` equals
/// the reduced cell's is inside. std::nullopt when that is not well defined: some reduced cell's sign vector is the
/// restriction of original cells inside and outside, or of none. Throws std::invalid_argument for sizes that do not
/// match (solid, origin, the cells' sign vectors) or an origin out of range.
std::optional<std::vector<char>> carry_by_sign_vectors(const Complex& original, const std::vector<char>& solid,
                                                       const std::vector<int>& origin, const Complex& reduced);

/// Minimises `scene`, on which `record` (its check_scene or run_scene record under `settings`, record.failed())
/// says which checks failed; see the order above. Under SamplePolicy::Intended, when prop61, propB1,
/// describability or nhrep failed, record.intended is the intended shape (cells of arrange(scene)) carried to the
/// reduced scenes (the other checks do not look at it). `scene` must be resolved. Throws
/// std::invalid_argument when the record did not fail or `settings` is a 3D campaign's, and what an extra check's
/// function throws.
MinimiseResult minimise_scene(const CampaignSettings& settings, const Scene2& scene, const SceneRecord& record,
                              const MinimiseOptions& options = {});
/// The same for a 3D campaign's scene (settings.dimension 3; std::invalid_argument otherwise).
MinimiseResult3 minimise_scene(const CampaignSettings& settings, const Scene3& scene, const SceneRecord& record,
                               const MinimiseOptions& options = {});

}  // namespace hsx::campaign
