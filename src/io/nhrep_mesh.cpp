#include <hsx/io/nhrep_mesh.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace hsx {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

std::string coordinate(const Rational& q) { return decimal_string(q, 30); }

}  // namespace

DecomposedMesh write_decomposed_mesh(const Mesh3& mesh, const nhrep::PatchGraph& graph, const std::vector<int>& conf_id) {
  const BoundarySurface& s = graph.surface;
  if (s.dimension != 3 || s.pieces.size() < mesh.faces.size() || s.links.size() < mesh.edges.size())
    throw std::invalid_argument("write_decomposed_mesh: the patch graph was not built from this mesh");
  // Live pieces grouped by input triangle (an unsplit triangle is its own piece; a split one has sub-pieces).
  std::vector<std::vector<int>> pieces_of_face(mesh.faces.size());
  for (std::size_t p = 0; p < s.pieces.size(); ++p) {
    const BoundaryPiece& piece = s.pieces[p];
    if (piece.retired) continue;
    if (piece.origin < 0 || piece.origin >= static_cast<int>(mesh.faces.size()))
      throw std::invalid_argument("write_decomposed_mesh: piece " + std::to_string(p) + " is not on a triangle");
    pieces_of_face[at(piece.origin)].push_back(static_cast<int>(p));
  }
  DecomposedMesh out;
  std::vector<PointQ3> vertices = mesh.vertices;
  std::map<int, int> centroid_of_face;  // split input triangle -> its centroid's vertex id
  std::vector<std::array<int, 3>> faces;
  std::vector<int> face_patch;
  std::map<int, std::pair<int, int>> split_link_edge;  // new link -> (centroid, shared vertex)
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& tri = mesh.faces[f];
    const auto& pieces = pieces_of_face[f];
    if (pieces.size() == 1 && s.pieces[at(pieces.front())].split_of < 0) {
      faces.push_back(tri);
      face_patch.push_back(conf_id.at(at(graph.piece_patch.at(at(pieces.front())))));
      continue;
    }
    ++out.split_faces;
    const PointQ3& a = mesh.vertices[at(tri[0])];
    const PointQ3& b = mesh.vertices[at(tri[1])];
    const PointQ3& c = mesh.vertices[at(tri[2])];
    const Rational third(1, 3);
    const int centroid = static_cast<int>(vertices.size());
    vertices.push_back(PointQ3{(a.x + b.x + c.x) * third, (a.y + b.y + c.y) * third, (a.z + b.z + c.z) * third});
    centroid_of_face[static_cast<int>(f)] = centroid;
    for (int p : pieces) {
      const BoundaryPiece& piece = s.pieces[at(p)];
      const int e = s.links.at(at(piece.kept_link)).origin;  // the input edge this sub-triangle keeps
      if (e < 0 || e >= static_cast<int>(mesh.edges.size()))
        throw std::invalid_argument("write_decomposed_mesh: a sub-triangle keeps no input edge");
      const MeshEdge& edge = mesh.edges[at(e)];
      // the input triangle runs a->b iff it is the edge's face_ab
      if (edge.face_ab == static_cast<int>(f))
        faces.push_back({edge.a, edge.b, centroid});
      else
        faces.push_back({edge.b, edge.a, centroid});
      face_patch.push_back(conf_id.at(at(graph.piece_patch.at(at(p)))));
    }
    // the links between its sub-triangles run from the centroid to the vertex their kept edges share
    for (int p : pieces)
      for (int l : s.pieces[at(p)].links) {
        if (l < static_cast<int>(mesh.edges.size()) || split_link_edge.count(l)) continue;
        const BoundaryLink& link = s.links[at(l)];
        const MeshEdge& e1 = mesh.edges[at(s.links[at(s.pieces[at(link.piece_a)].kept_link)].origin)];
        const MeshEdge& e2 = mesh.edges[at(s.links[at(s.pieces[at(link.piece_b)].kept_link)].origin)];
        const int shared = (e1.a == e2.a || e1.a == e2.b) ? e1.a : e1.b;
        split_link_edge[l] = {centroid, shared};
      }
  }
  std::set<std::pair<int, int>> features;
  for (std::size_t l = 0; l < s.links.size(); ++l) {
    const BoundaryLink& link = s.links[l];
    if (!link.feature) continue;
    std::pair<int, int> edge;
    if (l < mesh.edges.size()) {
      edge = {mesh.edges[l].a, mesh.edges[l].b};
    } else {
      auto it = split_link_edge.find(static_cast<int>(l));
      if (it == split_link_edge.end()) continue;
      edge = it->second;
    }
    features.insert({std::min(edge.first, edge.second), std::max(edge.first, edge.second)});
  }
  out.obj = "# " + mesh.source + " after NH-Rep patch decomposition (hsx nhtree)\n";
  for (const PointQ3& v : vertices)
    out.obj += "v " + coordinate(v.x) + " " + coordinate(v.y) + " " + coordinate(v.z) + "\n";
  for (const auto& f : faces)
    out.obj += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " + std::to_string(f[2] + 1) + "\n";
  out.fea = std::to_string(features.size()) + "\n";
  for (const auto& [a, b] : features) out.fea += std::to_string(a) + " " + std::to_string(b) + "\n";
  for (int id : face_patch) out.face_patch += std::to_string(id) + "\n";
  out.faces = static_cast<int>(faces.size());
  out.feature_edges = static_cast<int>(features.size());
  return out;
}

}  // namespace hsx
