// A CSG expression as a 2D or 3D OpenSCAD program, so that a user can look at the tree in a tool they know.
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
//
// 3D (a Scene3): a 3D OpenSCAD program with hsx's tessellation made explicit, i.e. the solids hsx actually
// arranges, not the curved primitives they came from:
// - a box, sphere, cylinder, cone, torus or mesh halfspace is `polyhedron(points = [[x, y, z], ...], faces =
//   [[i, j, k], ...]);` of its Halfspace3::surface (geometry/tessellate3.hpp gives its vertices and triangles;
//   an infinite cylinder's surface is already clipped by the domain box): the points are the surface's vertices in
//   order, each triangle (a, b, c) is written [a, c, b], clockwise seen from outside as OpenSCAD wants (hsx's
//   triangles are counter-clockwise);
// - a plane is the domain box clipped to it, computed exactly (geometry/tessellate3.hpp's box_cut_by_plane, to the
//   opposite closed halfspace for a complemented plane), as a polyhedron of convex polygon faces (each written
//   clockwise from outside, points numbered in order of first use); `union() {}` when nothing of the box is kept;
// - a complemented surface, and a complement node, is `difference() { <domain cube>; <child> }`, the domain cube
//   being `translate([x0, y0, z0]) cube([dx, dy, dz]);`;
// - operators and constants as in 2D (full: the domain cube); coordinates to 17 significant digits.
// Each leaf line ends with a comment naming its halfspace and kind, with the vertex and triangle counts of a
// surface. There is no option: the tessellation is the scene's. Output is deterministic.
#pragma once

#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/geometry/scene.hpp>
#include <hsx/geometry/scene3.hpp>

#include <string>

namespace hsx {

struct OpenScadOptions {
  int circle_segments = 96;  ///< $fn of every circle, 3 to 100,000 (InputError otherwise)
};

/// The OpenSCAD program. `e` must refer to `scene`'s halfspaces (std::invalid_argument otherwise).
std::string to_openscad(const csg::Expr& e, const Scene2& scene, const OpenScadOptions& options = {});

/// The 3D OpenSCAD program (see the 3D conventions above). `e` must refer to `scene`'s halfspaces, and `scene` be
/// validated (validate_and_resolve: surfaces tessellated, domain set); std::invalid_argument otherwise for the
/// halfspace indices.
std::string to_openscad(const csg::Expr& e, const Scene3& scene);

}  // namespace hsx
