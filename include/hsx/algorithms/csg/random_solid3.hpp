// Random bounded 3D solids for surveys (hsx nhsurvey --dimension 3): a random CSG expression over a few 3D
// primitives (boxes, spheres, cylinders, planes), optionally made hollow. Exact rationals only; reproducible from
// (seed, index, settings) on every machine (kernel/random.hpp). The 3D twin of random_solid.hpp.
//
// The procedure (solid `index` of `seed`):
// 1. rng = Random(item_seed(seed, index)).
// 2. A draw: primitives = rng.in(min_primitives, max_primitives); for k = 0, 1, ...: primitive k (below) appends
//    its halfspaces; the parts are combined as random_solid.hpp's Csg step (pairs of random parts: a | b, a & b,
//    a - b, b - a by rng.in(0, 3)). With `hollow`, when primitive 0 (P0) is a box or a sphere, the result R becomes
//    (R | P0) - I for its inner primitive I (below), which lies strictly inside P0: I is a cavity of the solid
//    unless another part's boundary crosses I. The scene's domain is chosen by
//    hsx (choose_domain3: every vertex strictly inside), the scene validated and arranged (no volumes).
// 3. A draw whose solid is empty or touches the domain box is drawn again from the same rng, up to max_draws draws
//    in all; the last draw is returned whatever its status.
// Primitive k (h(a, b) = rng.in(a, b) / 2; a point is three h(-4, 4) drawn x, y, z), by kind = rng.in(0, 9):
// - 0-2, an axis box: a corner p, sizes (h(2, 8), h(2, 8), h(2, 8)); six planes "b<k>.xmin", ".xmax", ".ymin",
//   ".ymax", ".zmin", ".zmax" (outward normals the coordinate axes), intersected. Its inner primitive: a sphere
//   "i" about the box's centre of radius a third of its smallest half-size.
// - 3-5, a sphere "s<k>": centre a point, radius h(2, 6), `segments` segments. Its inner primitive: the box "i.*"
//   about the centre of half-size radius / 3.
// - 6-7, a finite cylinder "c<k>": axis a coordinate axis rng.in(0, 2), centre a point, radius h(1, 4), half
//   length h(2, 6), `segments` segments.
// - 8-9, a lone plane "p<k>": outward normal the d-th (d = rng.in(0, 12)) of the 13 directions (a, b, c) with
//   entries in {-1, 0, 1}, first non-zero entry 1, in lexicographic order, through a point.
#pragma once

#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/algorithms/csg/random_solid.hpp>  // SolidStatus
#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/geometry/scene3.hpp>

#include <cstdint>
#include <vector>

namespace hsx::csg {

/// The most primitives a random solid may have. Measured (session 28, two fuzzers busy): 64 take about 30 s and
/// 135 MB per solid; beyond about 100 the planes of the boxes alone pass what choose_domain3 accepts, and a
/// million exhausted memory while drawing.
inline constexpr int kMaxRandomPrimitives3 = 64;

struct RandomSolid3Settings {
  int min_primitives = 2;  ///< number of primitives, uniform in [min_primitives, max_primitives],
                           ///< 1 <= min <= max <= kMaxRandomPrimitives3
  int max_primitives = 4;
  int segments = 8;        ///< segments per circle of spheres and cylinders, 6 <= segments <= 64 (6: a hollow sphere's
                           ///< inner box stays inside its tessellation)
  bool hollow = false;     ///< subtract an inner primitive from primitive 0 (above)
  int max_draws = 20;      ///< empty or unbounded draws are redrawn, at most this many draws in all (>= 1)
};

struct RandomSolid3 {
  Scene3 scene;             ///< validated; domain chosen by hsx, no samples
  Arranged3 arranged;       ///< the scene's arrangement and complex (no volumes)
  std::vector<char> solid;  ///< per cell of arranged.complex, 1 inside
  ExprPtr expression;       ///< the solid's expression over the scene's halfspaces
  SolidStatus status = SolidStatus::Empty;  ///< of the returned draw
  int draws = 1;
  bool hollowed = false;    ///< an inner primitive was subtracted (hollow, and primitive 0 a box or a sphere)
};

/// Solid `index` of `seed` by the procedure above. Throws std::invalid_argument for settings out of range;
/// InputError when the arrangement outgrows `limits`. `drawn`, when not null, is set to the halfspace count of the
/// last scene drawn, also when the arrangement of that scene throws (0 when it throws before drawing).
RandomSolid3 random_solid3(const RandomSolid3Settings& settings, std::uint64_t seed, std::uint64_t index,
                           const ArrangementLimits& limits = {}, int* drawn = nullptr);

}  // namespace hsx::csg
