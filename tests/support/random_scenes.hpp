// Random valid 2D scenes for property tests (rapidcheck), and small helpers to build, transform and show scenes.
//
// What gen_scene produces (every scene is validated: validate_and_resolve has been called and did not throw):
// - a few halfspaces (half-planes, disks, polygons, some complemented) with small rational data: centres, line
//   anchor points and polygon start points are multiples of 1/denominator with |x| <= coordinate_bound (polygon
//   vertices and the parts of degenerate patterns lie up to ~6 further out), radii are multiples of
//   1/denominator in (0, 3]; points on circles use Pythagorean unit vectors (denominators 5 and 13);
// - polygons are simple: star-shaped around a rational point (vertices at sorted, distinct directions, angular
//   gaps below pi, so three consecutive vertices may be collinear), axis-aligned rectangles, or triangles;
// - on purpose, degenerate configurations (see Degeneracy): a halfspace repeated exactly, a halfspace and its
//   complement, a line tangent to a disk, disks tangent from outside and from inside, three or four lines through
//   one rational point, a polygon vertex on a line or on a circle, a half-plane containing a polygon edge, two
//   polygons sharing part of an edge;
// - an explicit domain (domain_given = true) that contains every disk, polygon and line anchor point with a
//   margin of at least 1, so no disk or polygon touches the box and every line crosses the box's interior;
// - optionally `at` (and `near`) samples at exact rational boundary points (a line point, a polygon vertex or
//   edge point, a disk point centre + r*u for a rational unit vector u, the midpoint of an arrangement edge), kept
//   only when they lie inside a patch: a sample on an arrangement vertex where boundaries meet is dropped (checked
//   exactly with the arrangement of the scene without samples), so Arrangement2::build(scene) does not throw.
// Scenes are small (at most max_halfspaces halfspaces): one arrangement takes a few milliseconds.
#pragma once

#include <hsx/geometry/arrangement2.hpp>
#include <hsx/geometry/scene.hpp>

#include <rapidcheck.h>

#include <ostream>
#include <string>
#include <vector>

namespace hsx::test {

/// The forced degeneracies gen_scene can add; each adds the halfspaces it needs (cost: 1 to 4 halfspaces).
enum class Degeneracy {
  RepeatedHalfspace,        ///< an existing halfspace given again exactly (a support group of size 2)
  ComplementTwin,           ///< an existing halfspace (a disk when there is one) given again, complemented
  LineTangentToDisk,        ///< a disk and a line tangent to it (y = b + r, or along a rational unit normal)
  DisksTangentOutside,      ///< two disks touching from outside at a rational point
  DisksTangentInside,       ///< a disk inside another, touching it at a rational point
  ConcurrentLines,          ///< three or four lines through one rational point
  PolygonVertexOnLine,      ///< a polygon and a line through one of its vertices
  PolygonVertexOnCircle,    ///< a polygon and a circle through one of its vertices
  HalfplaneOnPolygonEdge,   ///< a polygon and a half-plane whose line contains one of its edges
  PolygonsSharingEdge,      ///< two rectangles side by side, sharing part of an edge
};
inline constexpr int kDegeneracyCount = 10;
const char* to_string(Degeneracy d);

struct SceneGenOptions {
  /// At most this many halfspaces in total (degeneracies included); at least 1 is always generated.
  int max_halfspaces = 6;
  bool halfplanes = true;  ///< kinds allowed for the random halfspaces (at least one must be true)
  bool disks = true;
  bool polygons = true;
  bool complements = true;  ///< some halfspaces get complement = true
  /// Degeneracies: between min_degeneracies and max_degeneracies patterns, drawn from `allowed_degeneracies`
  /// (empty: all; patterns needing a kind that is not allowed are skipped, and so are patterns that would exceed
  /// max_halfspaces: ask for max_halfspaces >= 1 + the patterns' cost to be sure to get them).
  int min_degeneracies = 0;
  int max_degeneracies = 2;
  std::vector<Degeneracy> allowed_degeneracies;
  /// Samples: up to max_samples, each on a patch (never on a vertex where boundaries meet). Choosing them builds
  /// the arrangement of the scene once, inside the generator.
  bool samples = false;
  int max_samples = 4;
  bool near_samples = true;  ///< some samples are `near` (with an exact rational snapped location)
  int coordinate_bound = 3;  ///< |coordinate| of centres, anchor points and polygon centres
  int denominator = 2;       ///< coordinates and radii are multiples of 1/denominator
};

/// Random valid scene; see the header comment. Draws are uniform from the first test on (rapidcheck's size does
/// not shrink the ranges) and shrink towards fewer halfspaces, no complement and no samples. Counterexamples print
/// as hsx-scene/1 JSON (showValue below), ready to save as a file and run with `hsx arrange`.
rc::Gen<Scene2> gen_scene(const SceneGenOptions& options = {});

/// A rational point strictly inside `box`, coordinates multiples of 1/denominator.
rc::Gen<PointQ2> gen_point_in(const Box2& box, int denominator = 2);

/// Rational points on the boundary of `h` that lie strictly inside `box` (not necessarily inside patches): line
/// points, polygon vertices and edge points, disk points centre + r*u for rational unit vectors u.
std::vector<PointQ2> boundary_points(const Halfspace2& h, const Box2& box);

/// True when an `at` sample of halfspace `halfspace` at `p` would be accepted by Arrangement2::build: p lies on an
/// edge carrying the halfspace (not on the box), or on a degree-2 vertex inside one run of such edges.
bool sample_fits(const Arrangement2& arrangement, int halfspace, const PointQ2& p);

/// The scene translated by `offset` (domain, halfspaces, samples), validated again.
Scene2 translated(const Scene2& scene, const PointQ2& offset);

/// The scene with halfspaces reordered: result.halfspaces[k] = scene.halfspaces[order[k]]; samples keep their
/// order and follow their halfspace. Validated again.
Scene2 permuted(const Scene2& scene, const std::vector<int>& order);

// ---- builders for hand-written scenes ----
Rational q(const std::string& text);  ///< exact rational from text ("-7/3", "0.5"); throws on bad text
PointQ2 pt(const Rational& x, const Rational& y);
Halfspace2 halfplane(const std::string& name, const PointQ2& normal, const Rational& offset, bool complement = false);
Halfspace2 disk(const std::string& name, const PointQ2& center, const Rational& radius, bool complement = false);
Halfspace2 polygon(const std::string& name, std::vector<PointQ2> vertices, bool complement = false);
/// `at` sample on the halfspace named `on` (which must exist in `scene`).
void add_sample(Scene2& scene, const std::string& on, const PointQ2& at, bool near = false);
/// A scene with the given domain and halfspaces, validated (samples can be added with add_sample and then
/// validate_and_resolve called again).
Scene2 make_scene(const Box2& domain, std::vector<Halfspace2> halfspaces);

/// The scene as hsx-scene/1 JSON text (one line), for failure messages.
std::string scene_text(const Scene2& scene);

}  // namespace hsx::test

namespace hsx {
/// rapidcheck prints counterexamples with this (found by argument-dependent lookup).
void showValue(const Scene2& scene, std::ostream& os);
void showValue(const PointQ2& p, std::ostream& os);
}  // namespace hsx
