// A campaign's random 3D scenes (`hsx campaign --dimension 3`): a random CSG solid of boxes, spheres, cylinders
// and planes (csg::random_solid3), degeneracy patterns added to its scene, then samples; reproducible from
// (settings, seed, index) on every machine (kernel/random.hpp's exactly specified draws), like the 2D
// random_scene (geometry/random_scene.hpp).
//
// The procedure (scene `index` of `seed`):
// 1. The solid: r = csg::random_solid3(settings.solid, seed, index, limits) (random_solid3.hpp specifies its draws,
//    from Random(item_seed(seed, index))): its scene S (a domain chosen by hsx), its CSG expression E over S's
//    halfspaces, and the solid's status (bounded, or empty / unbounded after settings.solid.max_draws draws).
// 2. A second stream rng = Random(item_seed(item_seed(seed, index), 1)) draws the rest.
// 3. Degeneracy patterns: the pool is the patterns (Degeneracy3, in enum order) with a weight > 0 whose
//    prerequisite S has (PlaneOnBoxFace and CoincidentFaces: a box face, i.e. a plane halfspace of S whose name
//    holds a '.', as random_solid3's "b<k>.xmin"; ConcurrentPlanes: none). If the pool is not empty and
//    max_degeneracies > 0, count = rng.in(min_degeneracies, max_degeneracies) patterns, each of kind
//    pool[rng.weighted(their weights)], appended to S's halfspaces (named "d<j>", j the pattern's position) after
//    S's own, so E still names S's halfspaces by their indices. Each pattern's draws, in order:
//    - PlaneOnBoxFace: a face plane F = rng.pick(the box faces, in halfspace order); a lone plane "d<j>" equal to F
//      (normal and offset), complemented when rng.one_in(2): a plane through a box face (coincident faces of the
//      same or of opposite orientation).
//    - CoincidentFaces: a face plane F as above, F = { n . x <= o } with n = +-e_a (a the axis); a new axis box
//      "d<j>" (six planes "d<j>.xmin" ... ".zmax", as random_solid3's boxes) on the other side of F: along a from
//      c to c + L when n = +e_a (c = o), from c - L to c when n = -e_a (c = -o), L = rng.in(2, 8) / 2; along the
//      other two axes, in x, y, z order, a low end rng.in(-8, 8) / 2 and a size rng.in(2, 8) / 2. Its face on F
//      coincides with the box's (opposite orientations): two primitives sharing a face plane.
//    - ConcurrentPlanes: a point v = rng.pick(the vertices of r's arrangement, in its vertex order: where boundaries
//      meet, and the tessellations' vertices), a direction d = rng.in(0, 12), the d-th of the 13 directions with
//      entries in {-1, 0, 1} and first non-zero entry 1 in lexicographic order (random_solid3's lone planes); the
//      plane "d<j>" { d . x <= d . v }: a plane through a vertex where three or more boundaries meet.
//    With patterns, the scene (domain chosen by hsx again) is validated and arranged; without, r's arrangement is
//    kept.
// 4. The intended solid I = E evaluated on the scene's complex (csg::evaluate): the added halfspaces cut its cells
//    but do not change it. When r's status is not bounded (empty, or unbounded after max_draws draws), I is the
//    empty solid.
// 5. The samples, by the policy:
//    - Intended: GENERATE-SAMPLES' initial samples for I (bsh::initial_samples: one on the central patch of each
//      connected component of b ∩ b_i), no draw;
//    - Uniform: n = rng.in(1, max_samples) (none when max_samples is 0 or the complex has no patch), then n times
//      (while patches are left) a patch rng.pick(the patches not yet drawn, in patch order).
//    Each sample is an `at` sample at the centroid of its patch's largest triangle (bsh::scene_with_samples); the
//    sampled scene is validated and arranged again, and I evaluated on it. (max_samples is not used by Intended.)
// Every arrangement is computed with Arrangement3Options volumes = false, threads = 1, within `limits`.
#pragma once

#include <hsx/algorithms/csg/random_solid3.hpp>
#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/geometry/scene3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hsx::campaign {

/// The 3D degeneracy patterns (the procedure above says what each builds).
enum class Degeneracy3 { PlaneOnBoxFace, CoincidentFaces, ConcurrentPlanes };
inline constexpr int kDegeneracy3Count = 3;
/// "PlaneOnBoxFace", "CoincidentFaces", "ConcurrentPlanes".
const char* to_string(Degeneracy3 d);
/// The inverse of to_string; std::nullopt for any other text.
std::optional<Degeneracy3> degeneracy3_from_string(const std::string& s);

/// The generator's settings (`hsx campaign --dimension 3`'s options).
struct Scene3Settings {
  /// The CSG solid: primitives in [min_primitives, max_primitives], segments per circle, hollow, max_draws.
  csg::RandomSolid3Settings solid;
  int min_degeneracies = 0, max_degeneracies = 2;  ///< patterns per scene, 0 <= min <= max
  std::array<int, kDegeneracy3Count> degeneracy_weight{{1, 1, 1}};  ///< >= 0 each
  int max_samples = 6;  ///< Uniform: up to this many samples (>= 0)
};

/// How the samples are chosen (step 5).
enum class Samples3 { Uniform, Intended };

/// A generated 3D scene.
struct CampaignScene3 {
  Scene3 scene;                       ///< validated and resolved, with its samples
  Arranged3 arranged;                 ///< arrange(scene) within the limits
  std::vector<char> intended;         ///< I, one flag per cell of arranged.complex
  std::vector<std::string> degeneracies;  ///< the patterns applied (to_string), in order
};

/// `scene` (validated and resolved) arranged as the procedure arranges it: Arrangement3Options volumes = false,
/// threads = 1, within `limits` (InputError beyond them, or for a sample the arrangement refuses).
Arranged3 arrange_campaign_scene3(const Scene3& scene, const ArrangementLimits& limits);

/// Checks the settings' ranges; throws std::invalid_argument naming the first bad one.
void validate(const Scene3Settings& settings);

/// Scene `index` of `seed` by the procedure above. Throws std::invalid_argument for settings out of range and
/// InputError when an arrangement outgrows `limits`. `generated`, when not null, is set to the scene's halfspace
/// count as far as it was made, also when it throws: step 1's scene's (random_solid3's `drawn`, also when its
/// arrangement is refused), with the patterns' after step 3 (a campaign tallies a refused scene there).
CampaignScene3 random_campaign_scene3(const Scene3Settings& settings, Samples3 samples, std::uint64_t seed,
                                      std::uint64_t index, const ArrangementLimits& limits,
                                      int* generated = nullptr);

}  // namespace hsx::campaign
