// Random bounded 2D solids for surveys and campaigns (hsx nhsurvey --random): a random CSG expression over a few
// primitives, or a random set of inner cells of their arrangement. Exact rationals only; reproducible from
// (seed, index, settings) on every machine (kernel/random.hpp).
//
// The procedure (solid `index` of `seed`; this is `hsx nhsurvey --random N --seed S`'s solid i):
// 1. rng = Random(item_seed(seed, index)).
// 2. A draw: primitives = rng.in(min_primitives, max_primitives); for k = 0, 1, ...: primitive k (below) appends
//    its halfspaces to the scene; validate_and_resolve chooses the domain (every vertex strictly inside, no samples);
//    the scene is arranged (complex/from_arrangement2.hpp).
//    - Cells: per cell in order, outer cells outside, every other cell inside iff rng.in(0, 1) == 1.
//    - Csg: while more than one part is left: i = rng.in(0, parts - 1), a = part i removed; j = rng.in(0, parts - 1),
//      b = part j; part j becomes, by rng.in(0, 3): a | b, a & b, a - b, b - a. The solid is the expression's cells.
// 3. A draw whose solid is empty or covers an outer cell (unbounded in the domain) is drawn again from the same
//    rng, up to max_draws draws in all; the last draw is returned whatever its status.
// Primitive k (coordinates below are multiples of 1/2; h(a, b) = rng.in(a, b) / 2), by kind = rng.in(0, 9):
// - 0-3, a disk "c<k>": centre (h(-6, 6), h(-6, 6)), radius h(1, 6);
// - 4-5, an axis box: x0 = h(-8, 6), y0 = h(-8, 6), x1 = x0 + h(1, 6), y1 = y0 + h(1, 6); four half-planes
//   "s<k>.xmin", ".xmax", ".ymin", ".ymax" (intersected), or with `polygons` one polygon "s<k>";
// - 6-7, a triangle: three vertices (h(-8, 8), h(-8, 8)) each, redrawn until not collinear, ordered
//   counter-clockwise (the 2nd and 3rd swapped if needed); three half-planes "t<k>.0", ".1", ".2" (edge i from
//   vertex i to i + 1, outward normal (dy, -dx)), or with `polygons` one polygon "t<k>";
// - 8-9, a lone half-plane "h<k>": outward normal the d-th (d = rng.in(0, 15)) of the 16 primitive integer
//   directions of max-norm <= 2 counter-clockwise from (1, 0), through the point (h(-6, 6), h(-6, 6)).
#pragma once

#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/geometry/scene.hpp>
#include <hsx/kernel/random.hpp>

#include <cstdint>
#include <vector>

namespace hsx::csg {

/// Whether a labelling (one flag per cell of a complex, 1 = inside) is a usable bounded solid.
enum class SolidStatus {
  Bounded,    ///< at least one cell inside, no outer cell inside
  Empty,      ///< no cell inside
  Unbounded,  ///< an outer cell (touching the domain box) inside
};
/// `solid`: one flag per cell of `complex` (std::invalid_argument otherwise).
SolidStatus solid_status(const Complex& complex, const std::vector<char>& solid);

enum class RandomSolidKind {
  Csg,    ///< a random CSG expression over the primitives
  Cells,  ///< a random set of inner cells of the primitives' arrangement
};

struct RandomSolidSettings {
  int min_primitives = 2;  ///< number of primitives, uniform in [min_primitives, max_primitives], 1 <= min <= max
  int max_primitives = 4;
  bool polygons = false;   ///< boxes and triangles as one polygon halfspace each instead of half-planes
  int max_draws = 50;      ///< empty or unbounded draws are redrawn, at most this many draws in all (>= 1)
};

struct RandomSolid {
  Scene2 scene;             ///< validated; domain chosen by hsx (domain_given false), no samples
  Arranged2 arranged;       ///< the scene's arrangement and complex
  std::vector<char> solid;  ///< per cell of arranged.complex, 1 inside
  ExprPtr expression;       ///< the solid's expression over the scene's halfspaces (Csg only; null for Cells)
  SolidStatus status = SolidStatus::Empty;  ///< of the returned draw (Bounded unless max_draws ran out)
  int draws = 1;            ///< draws made (1 when the first was bounded)
};

/// Step 2's Csg combination (the header comment), shared with random_solid3.hpp: while more than one part is left,
/// a = part rng.in(0, parts - 1) removed, b = part rng.in(0, parts - 1), which becomes a | b, a & b, a - b or b - a
/// by rng.in(0, 3). Returns the last part. `parts`: at least one (std::invalid_argument otherwise).
ExprPtr random_combination(Random& rng, std::vector<ExprPtr> parts);

/// Solid `index` of `seed` of the given kind, by the procedure in the header comment. Throws
/// std::invalid_argument for settings out of range.
RandomSolid random_solid(const RandomSolidSettings& settings, RandomSolidKind kind, std::uint64_t seed,
                         std::uint64_t index);

}  // namespace hsx::csg
