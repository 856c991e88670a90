// A closed triangle mesh with feature edges as a BoundarySurface (complex/boundary.hpp): the 3D input of NH-Rep's
// patch graphs. Piece i is triangle i, link i is mesh edge i.
#pragma once

#include <hsx/complex/boundary.hpp>
#include <hsx/geometry/mesh3.hpp>

#include <string>
#include <utility>
#include <vector>

namespace hsx {

/// Builds the boundary of a validated mesh.
///
/// Inputs:
///   mesh                 a Mesh3 from build_mesh3 (closed, manifold, outward-oriented); F faces, E edges, V vertices
///   features             the .fea entries (read_fea); every entry must name a mesh edge, entries "a a" are
///                        skipped (resolve_feature_edges)
///   sharp_angle_degrees  NH-Rep's sharpness angle delta in [0, 180): an edge whose face normals make an angle
///                        below delta is Smooth; 0 (the default) keeps every non-flat edge Convex or Concave
///   notes                if given, receives what resolve_feature_edges reports (skipped or repeated entries)
/// Output, dimension 3:
///   pieces  F entries; piece f has origin f and links = mesh.face_edges[f] (its edges f0->f1, f1->f2, f2->f0)
///   links   E entries; link e joins piece_a = mesh.edges[e].face_ab and piece_b = face_ba, corner_a/corner_b = the
///           edge's vertex ids a < b, origin = e, feature = marked in `features`, type = Convex / Concave by the
///           exact dihedral sign, Smooth when flat or below the sharpness angle. The type is set on every link, not
///           only on feature links, so callers can see what an unmarked edge would be.
///   corner_count = V
///   nesting: piece.hole = its shell (component of triangles) has negative signed volume (a cavity);
///           piece.region = the index of its outer shell (outer shells numbered by lowest triangle); for a cavity,
///           that of the smallest outer shell containing it (exact ray parity), -1 when none does or it touches one
/// Throws InputError for feature entries that are out of range or not mesh edges, and for a bad angle.
BoundarySurface boundary_from_mesh(const Mesh3& mesh, const FeatureEdgeList& features,
                                   const Rational& sharp_angle_degrees = Rational(0),
                                   std::vector<std::string>* notes = nullptr);

/// The same with bare vertex pairs (0-based); messages name entries by position.
BoundarySurface boundary_from_mesh(const Mesh3& mesh, const std::vector<std::pair<int, int>>& feature_edges,
                                   const Rational& sharp_angle_degrees = Rational(0),
                                   std::vector<std::string>* notes = nullptr);

/// FeatureType of a mesh edge under a sharpness angle (the `type` boundary_from_mesh gives its link).
FeatureType mesh_edge_type(const Mesh3& mesh, int edge, const SharpnessAngle& sharpness);

}  // namespace hsx
