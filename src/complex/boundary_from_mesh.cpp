// Mesh -> BoundarySurface. The numbering is the identity (piece = triangle, link = edge) so that NH-Rep's patch
// numbering by lowest face index carries over unchanged.
#include <hsx/complex/boundary_from_mesh.hpp>

#include "geometry/components.hpp"

namespace hsx {

FeatureType mesh_edge_type(const Mesh3& mesh, int edge, const SharpnessAngle& sharpness) {
  switch (classify_edge(mesh, edge, sharpness)) {
    case EdgeShape::Convex: return FeatureType::Convex;
    case EdgeShape::Concave: return FeatureType::Concave;
    case EdgeShape::Flat: break;
  }
  return FeatureType::Smooth;
}

namespace {

/// Shells (components of triangles across edges) with their exact signed volumes: a shell of positive volume is an
/// outer boundary, one of negative volume a cavity. A cavity belongs to the smallest outer shell that contains one
/// of its vertices (exact ray parity, geometry/mesh3.hpp); when none does, or the vertex lies on another shell,
/// its region stays -1 (unknown). A shell of zero volume (flat: it encloses nothing) is neither, and its region
/// stays -1 too.
void set_mesh_nesting(const Mesh3& mesh, BoundarySurface& surface) {
  const std::size_t n = mesh.faces.size();
  DisjointSets sets(n);
  for (const MeshEdge& e : mesh.edges) sets.union_set(e.face_ab, e.face_ba);
  const Components shells = components_of(sets, n);  // numbered by lowest triangle
  const std::vector<std::vector<int>> shell_faces = shells.members();
  const std::size_t count = shell_faces.size();
  std::vector<Rational> volume(count);  // six times the signed volume, per shell
  for (std::size_t f = 0; f < n; ++f) {
    const PointQ3& a = mesh.vertices[static_cast<std::size_t>(mesh.faces[f][0])];
    const PointQ3& b = mesh.vertices[static_cast<std::size_t>(mesh.faces[f][1])];
    const PointQ3& c = mesh.vertices[static_cast<std::size_t>(mesh.faces[f][2])];
    volume[static_cast<std::size_t>(shells.of[f])] +=
        a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
  }
  std::vector<int> outer_shells;
  std::vector<int> region(count, -1);
  for (std::size_t r = 0; r < count; ++r)
    if (volume[r] > 0) {
      region[r] = static_cast<int>(outer_shells.size());
      outer_shells.push_back(static_cast<int>(r));
    }
  for (std::size_t r = 0; r < count; ++r) {
    if (sgn(volume[r]) >= 0) continue;  // outer, or flat (unknown)
    const PointQ3& probe = mesh.vertices[static_cast<std::size_t>(mesh.faces[static_cast<std::size_t>(shell_faces[r].front())][0])];
    int best = -1;
    for (int o : outer_shells) {
      const std::optional<bool> inside = point_inside_faces(mesh, shell_faces[static_cast<std::size_t>(o)], probe);
      if (!inside) {  // the cavity touches that shell: nesting unknown
        best = -1;
        break;
      }
      if (*inside && (best < 0 || volume[static_cast<std::size_t>(o)] < volume[static_cast<std::size_t>(best)])) best = o;
    }
    region[r] = best < 0 ? -1 : region[static_cast<std::size_t>(best)];
  }
  for (std::size_t f = 0; f < n; ++f) {
    const std::size_t shell = static_cast<std::size_t>(shells.of[f]);
    BoundaryPiece& piece = surface.pieces[f];
    piece.hole = volume[shell] < 0;
    piece.region = region[shell];
  }
}

}  // namespace

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
  set_mesh_nesting(mesh, surface);
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
