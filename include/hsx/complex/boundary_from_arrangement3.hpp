// The boundary of a 3D solid (a set of cells of an arranged 3D scene) as a BoundarySurface: NH-Rep's input for 3D
// solids built from halfspaces, each boundary triangle knowing its halfspace (the 3D twin of
// boundary_from_arrangement2.hpp).
//
// Conventions (owned here; the arrangement's are geometry/arrangement3.hpp's):
// - One piece per arrangement triangle with the solid on exactly one side, in increasing triangle order; `origin` is
//   the triangle index. The solid never touches the domain box, so no piece is on the box.
// - `carrier`: among the triangle's (coincident) halfspaces, the lowest index whose inside is the solid side; if
//   none, the lowest index, with carrier_complemented = true. A patch is thus a maximal piece of one halfspace's
//   boundary on the solid's boundary: a tessellated sphere's triangles, or a box halfspace's six faces, stay one
//   patch ("natural" halfspaces are hsx's halfspaces, as in 2D).
// - Links: per arrangement edge and per solid sector around it (the radially consecutive triangles between which the
//   cells are solid), one link joining the sector's two bounding triangles, so that an edge where two solid wedges
//   touch gives two links (as a non-manifold vertex gives two corners in 2D). Links are ordered by edge, then by the
//   sector's first triangle in the edge's radial order; `origin` is the edge index; corner_a/corner_b are the edge's
//   vertex ids (a < b), corner_count the arrangement's vertex count. A piece lists its links in the order of its
//   edges v0v1, v1v2, v2v0.
// - A link is a feature link iff its two pieces differ in (carrier, carrier_complemented). `type` is the exact
//   dihedral type of the solid sector (exact orientation determinants on rational vertices): Convex below 180
//   degrees, Concave above, Smooth at exactly 180; set on every link.
// - Nesting, as in 2D: `region` is the connected component of solid cells (adjacent across triangles with the
//   solid on both sides) the piece bounds; `hole` is true when the non-solid component across the piece is not the
//   one around that part (a cavity, or the void inside a hollow part). Solid parts and void components alternate
//   outwards from the void that reaches the domain box.
#pragma once

#include <hsx/complex/boundary.hpp>
#include <hsx/complex/from_arrangement3.hpp>

#include <vector>

namespace hsx {

/// `solid_cells`: one flag per cell of arranged.complex (= per arrangement cell), 1 = in the solid; outer cells must
/// be 0. Throws std::invalid_argument for a wrong size or a solid outer cell; std::logic_error if the result fails
/// check_boundary (a bug).
BoundarySurface boundary_from_arrangement3(const Arranged3& arranged, const std::vector<char>& solid_cells);

}  // namespace hsx
