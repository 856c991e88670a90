// The boundary of a 2D solid (a set of cells of an arranged scene) as a BoundarySurface: NH-Rep's 2D input.
//
// Conventions (owned here; the geometry is geometry/planar_corners.hpp's):
// - One piece per boundary edge of the solid (an arrangement edge with the solid on exactly one side), in
//   increasing edge order; `origin` is the edge index. A piece lists two links: first the one at its start, then
//   the one at its end, walking the boundary with the solid on the left.
// - `carrier` is the halfspace whose boundary carries the edge: among the edge's (coincident) halfspaces, the
//   lowest index whose inside is the solid side; if none, the lowest index, with carrier_complemented = true
//   (the solid lies outside it along the piece).
// - One link per corner (planar_corners.hpp: at a non-manifold vertex, one per solid sector), in corner order
//   (vertex, then outgoing edge); piece_a is the incoming piece, piece_b the outgoing one, `origin` the vertex;
//   no corners (a 2D feature curve is a single point).
// - A link is a feature link iff its two pieces differ in (carrier, carrier_complemented): a patch is a maximal
//   piece of one halfspace's boundary on the solid's boundary, so a polygon's own corner, or a circle continuing
//   through a vertex where the arrangement split it, stays inside one patch. `type` is the exact corner type
//   (Convex below 180 degrees, cusps of 0 included; Concave above, 360-degree cusps included; Smooth at exactly
//   180), set on every link, although BoundaryLink only promises it for feature links.
// - Nesting: `region` is the connected component of solid cells (adjacent across edges) the piece bounds; `hole`
//   is true when the non-solid component across the piece is not the one around that part. Solid parts and
//   non-solid components alternate outwards from the one that reaches the domain box: each part's surrounding
//   component is the one through which a search from the box reaches it first (an island inside a hole of another
//   part is surrounded by that hole).
#pragma once

#include <hsx/complex/boundary.hpp>
#include <hsx/complex/from_arrangement2.hpp>

#include <vector>

namespace hsx {

/// `solid_cells`: one flag per cell of arranged.complex (= per arrangement face), 1 = in the solid; outer cells
/// must be 0. Throws std::invalid_argument for a wrong size or a solid outer cell; std::logic_error if the result
/// fails check_boundary (a bug).
BoundarySurface boundary_from_arrangement2(const Arranged2& arranged, const std::vector<char>& solid_cells);

}  // namespace hsx
