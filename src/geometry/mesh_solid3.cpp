// The cells of a 3D scene inside a closed mesh on its halfspaces: see mesh_solid3.hpp.
#include <hsx/geometry/mesh_solid3.hpp>
#include <hsx/geometry/text3.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <string>

namespace hsx {

namespace {

std::string face_label(const Mesh3& mesh, std::size_t f) {
  const std::string line = f < mesh.face_lines.size() ? ":" + std::to_string(mesh.face_lines[f]) : std::string();
  return mesh.source + line + ": face " + std::to_string(f);
}

/// Throws unless the domain box holds every vertex of the mesh.
void check_inside_domain(const Mesh3& mesh, const Box3& domain) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (domain.contains(mesh.vertices[v])) continue;
    const std::string line = v < mesh.vertex_lines.size() ? ":" + std::to_string(mesh.vertex_lines[v]) : std::string();
    throw InputError(mesh.source + line + ": vertex " + std::to_string(v) + " " + point_text(mesh.vertices[v]) +
                     " is outside the scene's domain " + box_text(domain));
  }
}

/// The arrangement of `scene` with the mesh as its last halfspace; the arrangement's complaints about the mesh
/// (self-intersection) are given the mesh's name.
Arrangement3 arrange_with_mesh(const Scene3& scene, const Box3& domain, const Mesh3& mesh,
                               const ArrangementLimits& limits) {
  Scene3 with = scene;
  with.samples.clear();
  with.domain = domain;
  with.domain_given = true;
  Halfspace3 h;
  h.name = mesh.source;
  h.kind = HalfspaceKind3::Mesh;
  h.surface.vertices = mesh.vertices;
  h.surface.triangles = mesh.faces;
  h.primitive.file = h.origin = mesh.source;
  with.halfspaces.push_back(std::move(h));
  const std::string label = "halfspaces[" + std::to_string(scene.halfspaces.size()) + "] (\"" + mesh.source + "\")";
  Arrangement3Options options;
  options.volumes = false;
  try {
    return Arrangement3::build(with, limits, options);
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (what.compare(0, label.size(), label) == 0) throw InputError(mesh.source + what.substr(label.size()));
    throw InputError(mesh.source + ": arranging the scene with the mesh: " + what);
  }
}

/// Whether point `p`, in the plane of face `f`, lies in the (closed) face.
bool face_holds(const Mesh3& mesh, std::size_t f, const PointQ3& p) {
  const auto& t = mesh.faces[f];
  const PointQ3& n = mesh.normals[f];
  if (dot3(n, p) != dot3(n, mesh.vertices[static_cast<std::size_t>(t[0])])) return false;
  for (int k = 0; k < 3; ++k) {
    const PointQ3& a = mesh.vertices[static_cast<std::size_t>(t[k])];
    const PointQ3& b = mesh.vertices[static_cast<std::size_t>(t[(k + 1) % 3])];
    if (sgn(dot3(triangle_normal(a, b, p), n)) < 0) return false;
  }
  return true;
}

/// A plane's exact key, the same for both orientations: (n, n . a) divided by n's first non-zero coordinate.
using PlaneKey = std::array<Rational, 4>;
PlaneKey plane_key(const PointQ3& n, const PointQ3& a) {
  const Rational first = sgn(n.x) != 0 ? n.x : sgn(n.y) != 0 ? n.y : n.z;
  return {n.x / first, n.y / first, n.z / first, dot3(n, a) / first};
}

/// Throws naming the lowest mesh face holding a triangle of `with` that carries the mesh (halfspace `m`) alone.
/// Each such triangle lies inside one mesh face (coplanar input triangles are triangulated with their edges as
/// constraints), so its centroid, strictly inside it, is strictly inside that face.
void check_on_halfspaces(const Arrangement3& with, int m, const Mesh3& mesh) {
  std::map<PlaneKey, std::vector<std::size_t>> faces_by_plane;  // a triangle is looked for in its plane's faces
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    faces_by_plane[plane_key(mesh.normals[f], mesh.vertices[static_cast<std::size_t>(mesh.faces[f][0])])].push_back(f);
  std::vector<char> off(mesh.faces.size(), 0);
  std::vector<PointQ3> witness(mesh.faces.size());
  std::vector<char> on_box(mesh.faces.size(), 0);
  for (const ArrTriangle3& t : with.triangles()) {
    if (t.halfspaces.size() != 1 || t.halfspaces.front() != m) continue;
    const PointQ3& a = with.vertices()[static_cast<std::size_t>(t.vertices[0])];
    const PointQ3& b = with.vertices()[static_cast<std::size_t>(t.vertices[1])];
    const PointQ3& d = with.vertices()[static_cast<std::size_t>(t.vertices[2])];
    const PointQ3 c{(a.x + b.x + d.x) / 3, (a.y + b.y + d.y) / 3, (a.z + b.z + d.z) / 3};
    const auto plane = faces_by_plane.find(plane_key(triangle_normal(a, b, d), a));
    const std::vector<std::size_t> none;
    const std::vector<std::size_t>& candidates = plane == faces_by_plane.end() ? none : plane->second;
    const auto holder = std::find_if(candidates.begin(), candidates.end(),
                                     [&](std::size_t f) { return face_holds(mesh, f, c); });
    if (holder == candidates.end())
      throw std::logic_error("cells_inside_mesh: a triangle of the mesh lies in none of its faces");
    const std::size_t f = *holder;
    if (!off[f]) witness[f] = c;
    off[f] = 1;
    on_box[f] = static_cast<char>(on_box[f] || t.on_box);
  }
  const auto first = std::find(off.begin(), off.end(), 1);
  if (first == off.end()) return;
  const std::size_t f = static_cast<std::size_t>(first - off.begin());
  const long count = std::count(off.begin(), off.end(), 1);
  throw InputError(face_label(mesh, f) + " does not lie on the scene's halfspaces: its point " +
                   point_text(witness[f]) + " is on no halfspace's boundary" +
                   (on_box[f] ? " (it is on the domain box, which is no halfspace)" : "") +
                   ", so the face would cut a cell" +
                   (count > 1 ? " (" + std::to_string(count) + " faces are off the halfspaces)" : ""));
}

}  // namespace

std::vector<char> cells_inside_mesh(const Scene3& scene, const Arrangement3& arrangement, const Mesh3& mesh,
                                    const ArrangementLimits& limits) {
  check_inside_domain(mesh, arrangement.domain());
  const Arrangement3 with = arrange_with_mesh(scene, arrangement.domain(), mesh, limits);
  check_on_halfspaces(with, static_cast<int>(scene.halfspaces.size()), mesh);
  // The two arrangements have the same open cells: each cell's interior point lies in a cell of `with`, whose
  // side of the mesh is the cell's.
  const auto& cells = arrangement.cells();
  const std::size_t m = scene.halfspaces.size();
  std::vector<char> inside(cells.size(), 0);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const PointLocation3 where = with.locate(cells[c].interior);
    if (where.kind != PointLocation3::Cell)
      throw std::logic_error("cells_inside_mesh: the interior point of cell " + std::to_string(c) +
                             " is in no cell of the arrangement with the mesh");
    inside[c] = with.cells()[static_cast<std::size_t>(where.index)].inside[m];
  }
  return inside;
}

}  // namespace hsx
