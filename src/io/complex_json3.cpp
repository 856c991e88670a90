// hsx-complex/1, the 3D geometry section: reading it (with every check complex_json.hpp lists) and writing it.
#include "io/complex_json3.hpp"

#include <hsx/geometry/mesh3.hpp>  // triangle_normal, dot3
#include <hsx/io/json_values.hpp>

#include <algorithm>
#include <map>
#include <string>
#include <utility>

namespace hsx::complex_json_detail {
namespace {

using json = nlohmann::json;

PointQ3 read_point3(const JsonField& f) {
  if (f.size() != 3) f.fail("expected a point [x, y, z], got " + std::to_string(f.size()) + " coordinates");
  return PointQ3{f.at(std::size_t{0}).rational(), f.at(std::size_t{1}).rational(), f.at(std::size_t{2}).rational()};
}

/// A cell index or -1 (outside the domain).
int read_cell_or_outside(const JsonField& f, std::size_t cell_count) {
  const std::int64_t v = f.integer();
  if (v == -1) return -1;
  return read_index(f, cell_count, "cell");
}

/// One triangle: its fields, then the checks that need no cells (distinct vertices, non-zero area, halfspaces
/// ascending and distinct, two different sides, -1 only on the box).
ArrTriangle3 read_triangle(const JsonField& t, const Names& names, std::size_t cell_count,
                           const std::vector<PointQ3>& vertices) {
  t.check_keys({"id", "vertices", "halfspaces", "front_inside", "on_box", "front_cell", "back_cell"}, "a triangle");
  ArrTriangle3 tri;
  const JsonField vs = t.at("vertices");
  if (vs.size() != 3) vs.fail("a triangle has 3 vertices, not " + std::to_string(vs.size()));
  for (std::size_t k = 0; k < 3; ++k) tri.vertices[k] = read_index(vs.at(k), vertices.size(), "vertex");
  if (tri.vertices[0] == tri.vertices[1] || tri.vertices[1] == tri.vertices[2] || tri.vertices[0] == tri.vertices[2])
    vs.fail("repeats a vertex");
  const PointQ3& a = vertices[tri.vertices[0]];
  const PointQ3 n = triangle_normal(a, vertices[tri.vertices[1]], vertices[tri.vertices[2]]);
  tri.area2 = dot3(n, n);
  if (tri.area2 == 0) vs.fail("the three vertices are collinear (the triangle has no area)");
  const JsonField hs = t.at("halfspaces");
  const JsonField fi = t.at("front_inside");
  if (fi.size() != hs.size())
    fi.fail("has " + std::to_string(fi.size()) + " entries for " + std::to_string(hs.size()) + " halfspaces");
  for (std::size_t k = 0; k < hs.size(); ++k) {
    tri.halfspaces.push_back(names(hs.at(k)));
    if (k > 0 && tri.halfspaces[k] <= tri.halfspaces[k - 1])
      hs.at(k).fail("halfspaces must be listed once each, in the document's order");
    tri.front_inside.push_back(fi.at(k).boolean() ? 1 : 0);
  }
  tri.on_box = t.at("on_box").boolean();
  tri.front_cell = read_cell_or_outside(t.at("front_cell"), cell_count);
  tri.back_cell = read_cell_or_outside(t.at("back_cell"), cell_count);
  if (tri.front_cell == tri.back_cell) t.fail("has the same cell on both sides");
  if ((tri.front_cell < 0 || tri.back_cell < 0) && !tri.on_box)
    t.fail("has the outside of the domain on one side but is not on the box");
  if (!tri.on_box && tri.halfspaces.empty()) t.at("halfspaces").fail("a triangle off the box lies on some boundary");
  return tri;
}

/// Every cell's triangles, each oriented outward from that cell, must traverse every edge as often in one direction
/// as in the other (a closed surface, possibly of several shells).
void check_closed_cells(const JsonField& triangles, const ComplexDocument& doc) {
  std::map<std::pair<int, std::pair<int, int>>, long> balance;  // (cell, (u < v)) -> net traversals u -> v
  auto add = [&balance](int cell, int u, int v) {
    if (cell < 0) return;
    if (u < v) ++balance[{cell, {u, v}}];
    else --balance[{cell, {v, u}}];
  };
  for (const ArrTriangle3& t : doc.triangles3) {
    for (int k = 0; k < 3; ++k) {
      const int u = t.vertices[k], v = t.vertices[(k + 1) % 3];
      add(t.back_cell, u, v);   // the front normal points away from the back cell: outward for it
      add(t.front_cell, v, u);  // reversed for the front cell
    }
  }
  for (const auto& [key, net] : balance) {
    if (net != 0) {
      triangles.fail("cell " + std::to_string(key.first) + " is not closed: its triangles traverse edge (" +
                     std::to_string(key.second.first) + ", " + std::to_string(key.second.second) +
                     ") unevenly in its two directions");
    }
  }
}

/// Exact volumes from the divergence theorem: each triangle adds det(a, b, c) / 6 to its back cell and subtracts
/// it from its front cell.
std::vector<Rational> cell_volumes(const ComplexDocument& doc, std::size_t cell_count) {
  std::vector<Rational> volume(cell_count, Rational(0));
  for (const ArrTriangle3& t : doc.triangles3) {
    const PointQ3& a = doc.vertices3[t.vertices[0]];
    const PointQ3& b = doc.vertices3[t.vertices[1]];
    const PointQ3& c = doc.vertices3[t.vertices[2]];
    const Rational six_v = dot3(a, triangle_normal(PointQ3{0, 0, 0}, b, c));  // det(a, b, c)
    if (t.back_cell >= 0) volume[t.back_cell] += six_v;
    if (t.front_cell >= 0) volume[t.front_cell] -= six_v;
  }
  for (Rational& v : volume) v /= 6;
  return volume;
}

}  // namespace

Box3 read_domain3(const JsonField& f) {
  f.check_keys({"min", "max"}, "a domain");
  Box3 box{read_point3(f.at("min")), read_point3(f.at("max"))};
  if (!(box.min.x < box.max.x && box.min.y < box.max.y && box.min.z < box.max.z))
    f.fail("min must be below max in all three coordinates");
  return box;
}

void read_geometry3(const JsonField& g, const Names& names, std::size_t cell_count, ComplexDocument& doc) {
  g.check_keys({"vertices", "triangles"}, "a 3D geometry section");
  const JsonField vs = g.at("vertices");
  doc.vertices3.reserve(vs.size());
  for (std::size_t k = 0; k < vs.size(); ++k) doc.vertices3.push_back(read_point3(vs.at(k)));
  const JsonField ts = g.at("triangles");
  if (ts.size() == 0) ts.fail("a 3D arrangement has triangles (at least the domain box's)");
  doc.triangles3.reserve(ts.size());
  for (std::size_t k = 0; k < ts.size(); ++k) {
    check_id(ts.at(k), k);
    doc.triangles3.push_back(read_triangle(ts.at(k), names, cell_count, doc.vertices3));
  }
  check_closed_cells(ts, doc);
  doc.has_geometry = true;
}

std::vector<Rational> geometry3_volumes(const ComplexDocument& doc, std::size_t cell_count) {
  return cell_volumes(doc, cell_count);
}

void check_triangle_sides3(const JsonField& triangles, const ComplexDocument& doc) {
  const Complex& c = doc.complex;
  for (std::size_t k = 0; k < doc.triangles3.size(); ++k) {
    const ArrTriangle3& t = doc.triangles3[k];
    for (std::size_t e = 0; e < t.halfspaces.size(); ++e) {
      const int h = t.halfspaces[e];
      const int in = t.front_inside[e] ? t.front_cell : t.back_cell;
      const int out = t.front_inside[e] ? t.back_cell : t.front_cell;
      const std::string hname = name_of(c.halfspace_names, h);
      if (in >= 0 && !c.cells[in].inside[h])
        triangles.at(k).fail("cell " + std::to_string(in) + " is on the inside of " + hname + " here but is not inside it");
      if (out >= 0 && c.cells[out].inside[h])
        triangles.at(k).fail("cell " + std::to_string(out) + " is on the outside of " + hname + " here but is inside it");
    }
  }
}

Measure patch_area3(const JsonField& f, const Patch& patch, const ComplexDocument& doc, Budget& budget) {
  if (patch.pieces.empty()) f.fail("needs \"pieces\" (its triangles) when the document has a geometry section");
  const JsonField pieces = f.at("pieces");
  budget.spend(patch.pieces.size(), pieces);
  std::vector<int> sorted = patch.pieces;
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end()) pieces.fail("lists triangle " + std::to_string(*twice) + " twice");
  const std::string hname = name_of(doc.complex.halfspace_names, patch.halfspace);
  Measure area;
  for (std::size_t k = 0; k < patch.pieces.size(); ++k) {
    const JsonField where = pieces.at(k);
    const ArrTriangle3& t = doc.triangles3.at(static_cast<std::size_t>(patch.pieces[k]));
    const std::string tname = "triangle " + std::to_string(patch.pieces[k]);
    if (!std::binary_search(t.halfspaces.begin(), t.halfspaces.end(), patch.halfspace))
      where.fail(tname + " is not on the boundary of halfspace " + hname);
    if (std::minmax(t.front_cell, t.back_cell) != std::minmax(patch.inside_cell, patch.outside_cell)) {
      where.fail(tname + " separates cells " + std::to_string(t.front_cell) + " and " + std::to_string(t.back_cell) +
                 ", not the patch's cells");
    }
    area += Measure::sqrt_of(t.area2 / 4);
  }
  return area;
}

json geometry3_json(const Complex& c, const Arrangement3& geometry) {
  json vertices = json::array();
  for (const PointQ3& p : geometry.vertices())
    vertices.push_back(json::array({exact_string(p.x), exact_string(p.y), exact_string(p.z)}));
  json triangles = json::array();
  for (std::size_t k = 0; k < geometry.triangles().size(); ++k) {
    const ArrTriangle3& t = geometry.triangles()[k];
    json j = json::object();
    j["id"] = k;
    j["vertices"] = json::array({t.vertices[0], t.vertices[1], t.vertices[2]});
    json hs = json::array(), fi = json::array();
    for (std::size_t e = 0; e < t.halfspaces.size(); ++e) {
      hs.push_back(c.halfspace_names.at(static_cast<std::size_t>(t.halfspaces[e])));
      fi.push_back(t.front_inside[e] != 0);
    }
    j["halfspaces"] = std::move(hs);
    j["front_inside"] = std::move(fi);
    j["on_box"] = t.on_box;
    j["front_cell"] = t.front_cell;
    j["back_cell"] = t.back_cell;
    triangles.push_back(std::move(j));
  }
  return json{{"vertices", std::move(vertices)}, {"triangles", std::move(triangles)}};
}

json box3_json(const Box3& box) {
  auto point = [](const PointQ3& p) { return json::array({exact_string(p.x), exact_string(p.y), exact_string(p.z)}); };
  return json{{"min", point(box.min)}, {"max", point(box.max)}};
}

std::size_t edge_count3(const std::vector<ArrTriangle3>& triangles) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(triangles.size() * 3);
  for (const ArrTriangle3& t : triangles)
    for (int k = 0; k < 3; ++k) edges.push_back(std::minmax(t.vertices[k], t.vertices[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  return static_cast<std::size_t>(std::unique(edges.begin(), edges.end()) - edges.begin());
}

}  // namespace hsx::complex_json_detail
