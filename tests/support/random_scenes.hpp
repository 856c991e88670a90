// Random valid 2D scenes for property tests (rapidcheck): a thin adapter over the library's generator
// (geometry/random_scene.hpp, which documents what a scene contains and the degeneracies it forces), and small
// helpers to build, transform and show scenes.
//
// gen_scene: rapidcheck draws the seed (not shrunk) and hands SceneGenOptions to random_scene (RandomSceneSettings);
// it shrinks by lowering max_halfspaces towards 1 and max_samples towards 0 and by turning complements off, each
// shrink a new scene of the same seed. Draws are uniform from the first test on (the library's own integer draws;
// rapidcheck's size plays no part). Scenes are small: one arrangement takes a few milliseconds.
#pragma once

#include <hsx/geometry/arrangement2.hpp>
#include <hsx/geometry/random_scene.hpp>
#include <hsx/geometry/scene_builders.hpp>
#include <hsx/geometry/scene.hpp>

#include <rapidcheck.h>

#include <ostream>
#include <string>
#include <vector>

namespace hsx::test {

using hsx::Degeneracy;  // the forced degeneracies (geometry/random_scene.hpp)
using hsx::kDegeneracyCount;
using hsx::to_string;

/// What gen_scene asks of random_scene (RandomSceneSettings; the fields below map one to one, see there).
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

/// Random valid scene: random_scene(settings, seed, 0) with a rapidcheck-drawn seed; see the header comment.
/// Counterexamples print as hsx-scene/1 JSON (showValue below), ready to save as a file and run with `hsx arrange`.
rc::Gen<Scene2> gen_scene(const SceneGenOptions& options = {});

/// The library settings gen_scene uses for `options` (before any shrinking).
RandomSceneSettings scene_settings(const SceneGenOptions& options);

/// random_scene's settings of `hsx bench --exact`: exactly `halfspaces` halfspaces, 1 to 3 samples per halfspace.
RandomSceneSettings per_halfspace_sampled(int halfspaces);

/// A rational point strictly inside `box`, coordinates multiples of 1/denominator.
rc::Gen<PointQ2> gen_point_in(const Box2& box, int denominator = 2);

/// rational_boundary_points (geometry/random_scene.hpp).
inline std::vector<PointQ2> boundary_points(const Halfspace2& h, const Box2& box) {
  return rational_boundary_points(h, box);
}
using hsx::sample_fits;  // geometry/random_scene.hpp

/// The scene translated by `offset` (domain, halfspaces, samples), validated again.
Scene2 translated(const Scene2& scene, const PointQ2& offset);

/// The scene with halfspaces reordered: result.halfspaces[k] = scene.halfspaces[order[k]]; samples keep their
/// order and follow their halfspace. Validated again.
Scene2 permuted(const Scene2& scene, const std::vector<int>& order);

// ---- builders for hand-written scenes ----
Rational q(const std::string& text);  ///< exact rational from text ("-7/3", "0.5"); throws on bad text
PointQ2 pt(const Rational& x, const Rational& y);
using hsx::disk;  // geometry/scene_builders.hpp
using hsx::halfplane;
using hsx::polygon;
/// `at` sample on the halfspace named `on` (which must exist in `scene`).
void add_sample(Scene2& scene, const std::string& on, const PointQ2& at, bool near = false);
/// A scene with the given domain and halfspaces, validated (samples can be added with add_sample and then
/// validate_and_resolve called again).
Scene2 make_scene(const Box2& domain, std::vector<Halfspace2> halfspaces);

// ---- scenes rich in exact ties (the BSH tie-enumeration properties) ----
/// Axis-aligned rectangles on the integer grid {0..3}^2 (shared and collinear edges, T-junctions: non-generic
/// junctions), some complemented, samples inside patches; half of them hold a Fig. 6 pattern (two optimal
/// boundaries). See random_scenes.cpp.
rc::Gen<Scene2> gen_grid_scene();
/// Generic scenes (every junction a transversal crossing) with exact ties: a rectangle crossed by vertical lines
/// at integer x and maybe a horizontal one; half hold the generic Fig. 6 tie. See random_scenes.cpp.
rc::Gen<Scene2> gen_rooms_scene();

/// The scene as hsx-scene/1 JSON text (one line), for failure messages.
std::string scene_text(const Scene2& scene);

}  // namespace hsx::test

namespace hsx {
/// rapidcheck prints counterexamples with this (found by argument-dependent lookup).
void showValue(const Scene2& scene, std::ostream& os);
void showValue(const PointQ2& p, std::ostream& os);
}  // namespace hsx
