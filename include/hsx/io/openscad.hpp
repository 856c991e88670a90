// A CSG expression as a 2D OpenSCAD program, so that a user can look at the tree in a tool they know.
//
// This is a drawing, not an exact export (the header comment of the output says so):
// - a disk is `translate([cx, cy]) circle(r = r, $fn = N);` with N = OpenScadOptions::circle_segments, i.e. a
//   regular N-gon inscribed in the circle;
// - a polygon is `polygon(points = [[x, y], ...]);` with its vertices in the given order;
// - a half-plane is the domain box clipped to it, computed exactly with rationals, then printed as a polygon
//   (a complemented half-plane is clipped to the opposite closed half-plane);
// - a complemented disk or polygon, and a complement node, is `difference() { <domain square>; <child> }`;
// - union / intersection / difference nodes are union() / intersection() / difference() with their children in
//   order; the constants are `union() {}` (empty) and the domain square (full);
// - every coordinate is a decimal rounded to 17 significant digits (decimal_string).
// Each leaf line ends with a comment naming its halfspace. Output is deterministic.
#pragma once

#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/geometry/scene.hpp>

#include <string>

namespace hsx {

struct OpenScadOptions {
  int circle_segments = 96;  ///< $fn of every circle, 3 to 100,000 (InputError otherwise)
};

/// The OpenSCAD program. `e` must refer to `scene`'s halfspaces (std::invalid_argument otherwise).
std::string to_openscad(const csg::Expr& e, const Scene2& scene, const OpenScadOptions& options = {});

}  // namespace hsx
