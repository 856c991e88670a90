// Random valid 2D scenes with forced degeneracies, for property tests and campaigns. Exact rationals only;
// reproducible from (seed, index, settings) on every machine and standard library (kernel/random.hpp: the engine
// is std::mt19937_64, every draw is Random's exactly specified integer draw).
//
// The procedure (random_scene(settings, seed, index) runs it on rng = Random(item_seed(seed, index))). Below,
// in(a, b) is rng.in(a, b), g = 1/denominator, coord() = in(-B, B) * g with B = coordinate_bound * denominator,
// point() = (coord(), coord()) (x drawn first), positive(m) = in(1, m * denominator) * g.
// 1. Degeneracy patterns. The pool is the kinds d (in enum order) whose weight is > 0 and whose halfspace kinds
//    are allowed (see Degeneracy). If the pool is not empty and max_degeneracies > 0, count = in(min_degeneracies,
//    max_degeneracies) patterns are drawn, each by rng.weighted(weights of the pool): a slot is kind d with
//    probability weight[d] / (sum of the pool's weights).
// 2. base = in(1, max(1, max_halfspaces - C)) random halfspaces, C the patterns' summed cost (Degeneracy). Each:
//    kind = pick of the allowed kinds in the order half-plane, disk, polygon, then
//    - half-plane "L<n>": p = point(), normal (a, b) = (in(-3, 3), in(-3, 3)), (1, 0) if both are 0; line through p;
//    - disk "D<n>": centre point(), radius positive(max_radius);
//    - polygon "P<n>", by in(0, 2): 0, star-shaped around c = point(): k = in(3, 7) vertices at directions of the
//      16 primitive integer directions of max-norm <= 2 (counter-clockwise from (1, 0)): gaps g_1..g_{k-1} each
//      in(1, G) (G = 7, 6, 5, 4 for k = 3, 4, 5, >= 6), redrawn together until their sum is in [9, 15] (angular
//      gaps below pi), then the first direction's index i0 = in(0, 15); vertex j = c + (in(1, 2 * denominator) * g)
//      * direction(i0 + g_1 + ... + g_j); reversed when one_in(2); 1, an axis rectangle: a = point(), b = a + (positive(3), positive(3)), corners from a
//      counter-clockwise, rotated left by in(0, 3), reversed when one_in(2); 2, a triangle a, a + g (d0, d1),
//      a + g (d2, d3), d = 4 x in(-4, 4) redrawn until d0 d3 != d1 d2.
//    Every line "through p with normal n" flips to (-n, -n . p) when one_in(2) (the same line, the other side);
//    every new halfspace except a repeat is complemented when rng.percent(complement_percent) (drawn last).
//    <n> counts halfspaces created so far (0, 1, ...).
// 3. The patterns, in their drawn order, each applied when the scene's count + its cost <= max_halfspaces
//    (see Degeneracy for each one's draws).
// 4. While fewer than min_halfspaces: one more random halfspace (step 2).
// 5. The domain: the bounding box of the anchors (centre +- radius of disks, polygon vertices, the points lines
//    were drawn through), floor/ceil to integers, widened by in(1, 2) on the low x, low y, high x, high y sides
//    (drawn in that order); domain_given = true; validate_and_resolve.
// 6. Samples when max_samples > 0: the candidates of halfspace i are rational_boundary_points plus the midpoints of
//    the rational segment edges of the sample-free arrangement that carry i, kept when sample_fits; count =
//    in(0, max_samples) samples (nothing is drawn when there is no candidate), each a uniformly picked candidate
//    (halfspace order, then candidate order); for a
//    half-plane or a disk made `near` when rng.percent(near_percent): then the given point is p + t n (half-plane,
//    t picked from {1/2, -1, 1}) or c + t (p - c) (disk, t picked from {1/2, 2}), snapped back to p exactly.
//    validate_and_resolve again. With max_samples_per_halfspace > 0 (and max_samples = 0) instead: for each
//    halfspace i in order that has a fitting candidate, count = in(min_samples_per_halfspace,
//    max_samples_per_halfspace) samples, each a uniformly picked candidate of i, `near` as above.
// Scenes are small (a few halfspaces): one arrangement takes a few milliseconds.
#pragma once

#include <hsx/geometry/arrangement2.hpp>
#include <hsx/geometry/scene.hpp>
#include <hsx/kernel/random.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace hsx {

/// The forced degeneracies random_scene can add; each adds the halfspaces it needs (its cost).
enum class Degeneracy {
  /// cost 1: halfspace i = in(0, n - 1) given again exactly (a support group of size 2)
  RepeatedHalfspace,
  /// cost 1: an existing halfspace (a picked disk when there is one, else in(0, n - 1)) again, complemented
  ComplementTwin,
  /// cost 2 (half-planes and disks): disk c = point(), r = positive(max_radius); the line through c + r u with
  /// normal m u, m = in(1, 3), u = (0, 1) when one_in(2) else a picked rational unit vector (tangent at c + r u)
  LineTangentToDisk,
  /// cost 2 (disks): disk c = point(), r1 = positive(2); disk c + (r1 + r2) u, r2 = positive(2), u a picked unit
  DisksTangentOutside,
  /// cost 2 (disks): disk c = point(), r1 = in(2, 3 denominator) g; disk c + (r1 - r2) u, r2 = in(1, r1/g - 1) g
  DisksTangentInside,
  /// cost 3 (half-planes): p = point(); 4 lines when the budget allows 4 and one_in(2) (drawn only then), else 3,
  /// through p, normal to distinct directions among the first 8 of the 16 (each picked from the remaining ones)
  ConcurrentLines,
  /// cost 2 (half-planes and polygons): a random polygon and a line through a picked vertex (normal as in step 2)
  PolygonVertexOnLine,
  /// cost 2 (polygons and disks): a random polygon and the disk of radius r = positive(2) through a picked vertex
  /// v: centre v - r u, u a picked unit vector
  PolygonVertexOnCircle,
  /// cost 2 (half-planes and polygons): a random polygon (m vertices) and the line through its edge from vertex
  /// e = in(0, m - 1) to e + 1, normal the edge direction turned counter-clockwise (then flipped as in step 2)
  HalfplaneOnPolygonEdge,
  /// cost 2 (polygons): rectangles [x0, x1] x [y0, y1] and [x1, x2] x [y2, y3]: (x0, y0) = point(),
  /// x1 = x0 + positive(2), x2 = x1 + positive(2), y1 = y0 + k1 g with k1 = in(1, 3 den), y2 = y0 + in(-2 den,
  /// k1 - 1) g, y3 = max(y2, y0) + positive(2): y2 < y1 and y0 < y3, so the edges at x = x1 overlap
  PolygonsSharingEdge,
};
inline constexpr int kDegeneracyCount = 10;
const char* to_string(Degeneracy d);
/// The number of halfspaces pattern `d` adds (ConcurrentLines: 3, or 4 when the budget allows).
int degeneracy_cost(Degeneracy d);

// The rational unit vectors "picked" above: (a, b)/5 for (5,0), (0,5), (-5,0), (0,-5), (3,4), (4,3), (-3,4),
// (-4,3), (3,-4), (4,-3), (-3,-4), (-4,-3), then (a, b)/13 for (5,12), (12,5), (-5,12), (-12,-5), (12,-5).

struct RandomSceneSettings {
  /// Number of halfspaces in all (patterns included), in [min_halfspaces, max_halfspaces]; 1 <= min <= max.
  int min_halfspaces = 1;
  int max_halfspaces = 6;
  /// Kinds allowed for the random halfspaces (at least one); patterns needing a kind not allowed are never drawn.
  bool halfplanes = true;
  bool disks = true;
  bool polygons = true;
  int complement_percent = 25;  ///< probability (percent, 0..100) that a new halfspace is complemented
  /// The coordinate grid: centres, line points and polygon start points are multiples of 1/denominator with
  /// |coordinate| <= coordinate_bound; polygon vertices are grid points too (up to ~6 further out); radii are
  /// multiples of 1/denominator in (0, max_radius]. Degeneracy patterns built on rational unit vectors
  /// (tangencies, points on circles) leave the grid (denominators 5 and 13). All >= 1.
  int denominator = 2;
  int coordinate_bound = 3;
  int max_radius = 3;
  /// Degeneracy patterns: their number in [min_degeneracies, max_degeneracies] (0 <= min <= max), each of kind d
  /// with probability degeneracy_weight[d] / (sum over the allowed kinds); weight 0 = never. A pattern that would
  /// exceed max_halfspaces is skipped: ask for max_halfspaces >= 1 + the patterns' cost to be sure to get them.
  int min_degeneracies = 0;
  int max_degeneracies = 2;
  std::array<int, kDegeneracyCount> degeneracy_weight = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  /// Samples: up to max_samples (0: none), each exactly on a patch (never on a vertex where boundaries meet);
  /// choosing them builds the scene's arrangement once. near_percent (0..100): probability of a `near` sample.
  int max_samples = 0;
  int near_percent = 33;
  /// Samples per halfspace instead (step 6's second form; used when max_samples_per_halfspace > 0, which needs
  /// max_samples = 0 and 0 <= min_samples_per_halfspace <= max_samples_per_halfspace): each halfspace with a
  /// fitting candidate gets in(min, max) of them (`hsx bench --exact`: 1 to 3, as issue 11's scenes).
  int min_samples_per_halfspace = 0;
  int max_samples_per_halfspace = 0;
};

struct RandomScene {
  Scene2 scene;                          ///< validated (validate_and_resolve did not throw), domain_given = true
  std::vector<Degeneracy> degeneracies;  ///< the patterns applied, in order (skipped ones are not listed)
  /// The arrangement of `scene`'s halfspaces, built under the default ArrangementLimits to choose the samples,
  /// without them (Arrangement2::with_samples places them); empty when no samples were asked for.
  std::optional<Arrangement2> arrangement;
};

/// Scene `index` of `seed`: the procedure above on Random(item_seed(seed, index)). The domain contains every
/// disk, polygon and line anchor point with a margin of at least 1 (no disk or polygon touches the box, every
/// line crosses its interior). Throws std::invalid_argument for settings out of range.
RandomScene random_scene(const RandomSceneSettings& settings, std::uint64_t seed, std::uint64_t index);
/// The same procedure drawing from `rng` (for callers composing their own streams).
RandomScene random_scene(const RandomSceneSettings& settings, Random& rng);

/// A point strictly inside `box` whose coordinates are multiples of 1/denominator (x drawn first, each by
/// in(first, last) over the multiples strictly inside); a coordinate with no such multiple is the box's midpoint.
PointQ2 random_grid_point_in(Random& rng, const Box2& box, int denominator = 2);

/// Rational points on the boundary of `h` that lie strictly inside `box` (not necessarily inside patches): line
/// points p + t d (p the line's point nearest the box centre, d along the line, t in {0, +-1/2, ..., +-3}),
/// polygon vertices, edge midpoints and edge thirds, disk points centre + radius u for the unit vectors above.
std::vector<PointQ2> rational_boundary_points(const Halfspace2& h, const Box2& box);

/// True when an `at` sample of halfspace `halfspace` at `p` would be accepted by Arrangement2::build: p lies on an
/// edge carrying the halfspace (not on the box), or on a degree-2 vertex inside one run of such edges.
bool sample_fits(const Arrangement2& arrangement, int halfspace, const PointQ2& p);

}  // namespace hsx
