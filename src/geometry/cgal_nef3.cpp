// The only translation unit that instantiates CGAL's Nef polyhedra (~40 s and ~1.7 GB to compile): the cell-count
// oracle of geometry/nef3.hpp. Nothing here is shared with the arrangement (cgal_arrangement3.cpp).
#include <hsx/geometry/nef3.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_nary_union_3.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <array>
#include <stdexcept>
#include <vector>

namespace hsx {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Nef = CGAL::Nef_polyhedron_3<Kernel>;

FT to_ft(const Rational& q) {
  using Exact = Kernel::Exact_kernel::FT;
  return FT(Exact(q.get_mpq_t()));
}

Point to_point(const PointQ3& p) { return Point(to_ft(p.x), to_ft(p.y), to_ft(p.z)); }

std::array<PointQ3, 8> box_corners(const Box3& box) {
  std::array<PointQ3, 8> corners;
  for (int k = 0; k < 8; ++k)
    corners[k] = {(k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y, (k & 4) ? box.max.z : box.min.z};
  return corners;
}

Rational plane_value(const Halfspace3& h, const PointQ3& p) {
  return h.normal.x * p.x + h.normal.y * p.y + h.normal.z * p.z - h.offset;
}

/// The vertices of {x in box : normal . x <= offset}: the corners on that side and the points where the plane
/// crosses a box edge strictly between its ends. Empty when the plane does not cross the open box.
std::vector<PointQ3> clipped_polytope(const Halfspace3& h, const Box3& box) {
  const auto corners = box_corners(box);
  std::array<Rational, 8> value;
  bool below = false, above = false;
  for (int k = 0; k < 8; ++k) {
    value[k] = plane_value(h, corners[k]);
    below = below || value[k] < 0;
    above = above || value[k] > 0;
  }
  if (!below || !above) return {};
  std::vector<PointQ3> points;
  for (int k = 0; k < 8; ++k)
    if (value[k] <= 0) points.push_back(corners[k]);
  for (int k = 0; k < 8; ++k)
    for (int bit : {1, 2, 4}) {
      const int j = k | bit;
      if (j == k || (value[k] < 0) == (value[j] < 0) || value[k] == 0 || value[j] == 0) continue;
      const Rational t = value[k] / (value[k] - value[j]);  // in (0, 1): the crossing on edge k -> j
      const PointQ3& a = corners[k];
      const PointQ3& b = corners[j];
      points.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)});
    }
  return points;
}

Nef plane_boundary(const Halfspace3& h, const Box3& box) {
  const auto vertices = clipped_polytope(h, box);
  if (vertices.empty()) return Nef(Nef::EMPTY);
  std::vector<Point> points;
  points.reserve(vertices.size());
  for (const auto& v : vertices) points.push_back(to_point(v));
  Mesh hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  return Nef(hull).boundary();
}

Nef surface_boundary(const Halfspace3& h, int index) {
  Mesh mesh;
  std::vector<Mesh::Vertex_index> ids;
  ids.reserve(h.surface.vertices.size());
  for (const auto& v : h.surface.vertices) ids.push_back(mesh.add_vertex(to_point(v)));
  for (const auto& t : h.surface.triangles)
    if (mesh.add_face(ids[t[0]], ids[t[1]], ids[t[2]]) == Mesh::null_face())
      throw std::runtime_error("nef_cell_counts: halfspaces[" + std::to_string(index) + "] (\"" + h.name +
                               "\"): its triangles do not form a manifold surface");
  if (!CGAL::is_closed(mesh))
    throw std::runtime_error("nef_cell_counts: halfspaces[" + std::to_string(index) + "] (\"" + h.name +
                             "\"): its surface is not closed");
  return Nef(mesh).boundary();
}

bool on_box_plane(const Kernel::Plane_3& p, const Box3& box) {
  // a x + b y + c z + d = 0 is the plane x = m iff b = c = 0 and d = -a m (and likewise for y, z).
  const FT zero(0);
  if (p.b() == zero && p.c() == zero) return p.d() == -p.a() * to_ft(box.min.x) || p.d() == -p.a() * to_ft(box.max.x);
  if (p.a() == zero && p.c() == zero) return p.d() == -p.b() * to_ft(box.min.y) || p.d() == -p.b() * to_ft(box.max.y);
  if (p.a() == zero && p.b() == zero) return p.d() == -p.c() * to_ft(box.min.z) || p.d() == -p.c() * to_ft(box.max.z);
  return false;
}

/// Visits the objects of one shell; records whether a halffacet of it lies on the box.
struct BoxFacetFinder {
  const Box3* box = nullptr;
  bool found = false;
  void visit(Nef::Vertex_const_handle) {}
  void visit(Nef::Halfedge_const_handle) {}
  void visit(Nef::Halffacet_const_handle f) { found = found || on_box_plane(f->plane(), *box); }
  void visit(Nef::SHalfedge_const_handle) {}
  void visit(Nef::SHalfloop_const_handle) {}
  void visit(Nef::SFace_const_handle) {}
};

bool touches_box(const Nef& region, Nef::Volume_const_handle volume, const Box3& box) {
  for (auto shell = volume->shells_begin(); shell != volume->shells_end(); ++shell) {
    BoxFacetFinder finder;
    finder.box = &box;
    Nef::SFace_const_handle start = shell;
    region.visit_shell_objects(start, finder);
    if (finder.found) return true;
  }
  return false;
}

}  // namespace

NefCellCounts nef_cell_counts(const Scene3& scene) {
  const Box3& box = scene.domain;
  CGAL::Nef_nary_union_3<Nef> boundaries;
  bool any = false;
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
    const Halfspace3& h = scene.halfspaces[i];
    Nef b = h.kind == HalfspaceKind3::Plane ? plane_boundary(h, box) : surface_boundary(h, static_cast<int>(i));
    if (b.is_empty()) continue;
    boundaries.add_polyhedron(b);
    any = true;
  }
  std::vector<PointQ3> corners;
  for (const auto& c : box_corners(box)) corners.push_back(c);
  std::vector<Point> points;
  for (const auto& c : corners) points.push_back(to_point(c));
  Mesh cube;
  CGAL::convex_hull_3(points.begin(), points.end(), cube);
  Nef region = Nef(cube).interior();
  if (any) region -= boundaries.get_union();
  NefCellCounts counts;
  for (auto v = region.volumes_begin(); v != region.volumes_end(); ++v) {
    if (!v->mark()) continue;
    ++counts.cells;
    if (touches_box(region, v, box)) ++counts.outer_cells;
  }
  counts.facets = static_cast<long>(region.number_of_halffacets() / 2);
  return counts;
}

}  // namespace hsx
