// Mesh -> BoundarySurface. The numbering is the identity (piece = triangle, link = edge) so that NH-Rep's patch
// numbering by lowest face index carries over unchanged.
#include "complex/boundary_from_mesh.hpp"

namespace hsx {

FeatureType mesh_edge_type(const Mesh3& mesh, int edge, const SharpnessAngle& sharpness) {
  switch (classify_edge(mesh, edge, sharpness)) {
    case EdgeShape::Convex: return FeatureType::Convex;
    case EdgeShape::Concave: return FeatureType::Concave;
    case EdgeShape::Flat: break;
  }
  return FeatureType::Smooth;
}

BoundarySurface boundary_from_mesh(const Mesh3& mesh, const FeatureEdgeList& features,
                                   const Rational& sharp_angle_degrees, std::vector<std::string>* notes) {
  const SharpnessAngle sharpness(sharp_angle_degrees);
  const std::vector<char> marked = resolve_feature_edges(mesh, features, notes);
  BoundarySurface surface;
  surface.dimension = 3;
  surface.corner_count = static_cast<int>(mesh.vertices.size());
  surface.pieces.resize(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    BoundaryPiece& piece = surface.pieces[f];
    piece.origin = static_cast<int>(f);
    piece.links.assign(mesh.face_edges[f].begin(), mesh.face_edges[f].end());
  }
  surface.links.resize(mesh.edges.size());
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const MeshEdge& edge = mesh.edges[e];
    BoundaryLink& link = surface.links[e];
    link.piece_a = edge.face_ab;
    link.piece_b = edge.face_ba;
    link.corner_a = edge.a;
    link.corner_b = edge.b;
    link.origin = static_cast<int>(e);
    link.feature = marked[e] != 0;
    link.type = mesh_edge_type(mesh, static_cast<int>(e), sharpness);
  }
  return surface;
}

BoundarySurface boundary_from_mesh(const Mesh3& mesh, const std::vector<std::pair<int, int>>& feature_edges,
                                   const Rational& sharp_angle_degrees, std::vector<std::string>* notes) {
  FeatureEdgeList list;
  list.source = "feature edges";
  list.edges = feature_edges;
  return boundary_from_mesh(mesh, list, sharp_angle_degrees, notes);
}

}  // namespace hsx
