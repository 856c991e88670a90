// The boundary of a 2D solid made of arrangement faces, and the exact interior angle of every corner of it: the
// geometry behind NH-Rep's 2D patch graphs (complex/boundary_from_arrangement2.hpp turns it into a
// BoundarySurface).
//
// Conventions (owned here):
// - A solid is a per-face flag vector (1 = the face belongs to the solid), indexed like Arrangement2::faces().
//   Outer faces are never solid (they touch the domain box, which is not a boundary of anything), so box edges
//   are never boundary edges; a solid with an outer face is rejected.
// - A boundary edge has the solid on exactly one side. It is oriented with the solid on its LEFT: `forward`
//   means source -> target has the solid on the left.
// - A corner pairs, at a vertex, an incoming boundary edge with an outgoing one. Where the solid is
//   non-manifold (two wedges touching at a point) a vertex has several corners: the boundary curves leaving the
//   vertex (outgoing edges, and incoming edges reversed) are sorted in exact counter-clockwise order, by tangent
//   direction, ties (tangent curves) broken by signed curvature (a curve that turns left lies counter-clockwise
//   of one that turns less); each outgoing edge o is paired with the next curve counter-clockwise from it, which
//   is always a reversed incoming edge r. The solid sector lies between o and r.
// - The interior angle is the counter-clockwise angle from o's tangent d_o to r's tangent d_r, decided exactly:
//   cross(d_o, d_r) > 0: below 180 degrees (Convex); < 0: above 180 (Concave); = 0 with dot < 0: exactly 180
//   (Smooth: a line tangent to a circle, a circle or line continuing); = 0 with dot > 0: a cusp, angle 0
//   (Convex) when r turns more to the left than o (the sector is a horn), otherwise 360 (Concave).
// - Tangents at a vertex: a segment's direction is the rational direction of its supporting line, oriented by
//   comparing its end points exactly; an arc's is the perpendicular of (vertex - center). Signed curvature: 0 for
//   a segment, +1/radius for an arc travelled counter-clockwise, -1/radius clockwise (rational). Cross and dot
//   products of one-root coordinates (possibly with different radicals) are exact Measures, whose algebraic sign
//   is decided exactly.
#pragma once

#include <hsx/geometry/arrangement2.hpp>

#include <vector>

namespace hsx {

enum class CornerAngle : char { Convex, Smooth, Concave };

/// "convex", "smooth", "concave".
const char* corner_angle_name(CornerAngle angle);

struct SolidBoundaryEdge2 {
  int edge = -1;         ///< arrangement edge index
  bool forward = false;  ///< source -> target has the solid on its left
};

struct SolidCorner2 {
  int vertex = -1;
  int in_edge = -1, out_edge = -1;  ///< arrangement edges: in_edge ends here, out_edge starts here (boundary walk)
  CornerAngle angle = CornerAngle::Convex;
  bool cusp = false;  ///< the two tangents coincide: interior angle 0 (Convex) or 360 degrees (Concave)
};

struct SolidBoundary2 {
  std::vector<SolidBoundaryEdge2> edges;  ///< every boundary edge, ascending edge index
  /// Every corner, sorted by (vertex, out_edge). Each boundary edge is the in_edge of exactly one corner and the
  /// out_edge of exactly one corner.
  std::vector<SolidCorner2> corners;
};

/// The solid's boundary edges and corners (see the header comment). Throws std::invalid_argument when
/// `solid_faces` does not have one flag per face or marks an outer face, std::runtime_error when a segment has
/// no known supporting line and irrational ends, std::logic_error when the boundary is inconsistent at a vertex
/// (cannot happen for an arrangement built by Arrangement2::build).
SolidBoundary2 solid_boundary2(const Arrangement2& arrangement, const std::vector<char>& solid_faces);

/// The point where NH-Rep's face splitting cuts an edge in two: an exact rational point strictly inside the
/// edge (rational_point_inside_edge): the midpoint of a segment with rational ends, otherwise a rational point
/// near the middle (for an arc, near the middle angle; not exactly halfway, which would need a nested radical).
/// Only pictures use it; no combinatorial decision depends on where it lies.
PointQ2 edge_split_point(const Arrangement2& arrangement, int edge);

}  // namespace hsx
