// A shape's boundary as meshes and pictures (io/mesh_export.hpp's shape_faces, shape_ply/obj/off, io/svg3.hpp with
// cell_fill, io/svg.hpp's svg_grid), checked against the arrangement without the library's help: for every
// labelling of a small scene's cells, the boundary mesh is closed (every directed edge used as often as its
// reverse), turned outward (its divergence-theorem volume is the exact sum of the inside cells' volumes, and the
// inside cell is behind every face), and labelled with the patch and halfspace it lies on; the three files read
// back (hsx's own readers) to the same faces, labels and volume.
#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/geometry/mesh3.hpp>
#include <hsx/io/mesh_export.hpp>
#include <hsx/io/result_json.hpp>
#include <hsx/io/svg.hpp>
#include <hsx/io/svg3.hpp>

#include "geometry/scenes3.hpp"

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace hsx;
using namespace hsx::test3;

namespace {

/// Two boxes sharing a face, a plane through both, an octahedron touching nothing, a complemented tetrahedron:
/// cells on both sides of shared faces, a floating shell, coincident-free but with a plane crossing two meshes.
const Scene3& scene() {
  static const Scene3 s = [] {
    Scene3 s = scene_of({pt(-4, -4, -4), pt(4, 4, 4)},
                        {surface("A", box_surface(pt(-2, -2, -2), pt(0, 1, 1))),
                         surface("B", box_surface(pt(0, -2, -2), pt(2, 1, 1))), plane("P", pt(0, 0, 2), 1),
                         surface("O", octahedron(pt(1, 2, 2), 1)),
                         surface("T", tetrahedron(pt(-3, 2, -3), pt(-1, 2, -3), pt(-3, 3, -3), pt(-3, 2, -1)), true)});
    s.samples = {at_sample(3, pt(Rational(4, 3), Rational(7, 3), Rational(7, 3))),
                 at_sample(2, pt(3, 3, Rational(1, 2))), at_sample(0, pt(-2, Rational(-1, 2), Rational(-1, 2)))};
    validate_and_resolve(s);
    return s;
  }();
  return s;
}

const Arranged3& arranged() {
  static const Arranged3 a = arrange(scene());
  return a;
}

/// Every labelling with outer cells 0 (the scene's inner cells are few: all 2^k of them).
std::vector<std::vector<char>> labellings() {
  const Complex& c = arranged().complex;
  std::vector<int> inner;
  for (std::size_t k = 0; k < c.cells.size(); ++k)
    if (!c.cells[k].outer) inner.push_back(static_cast<int>(k));
  REQUIRE(inner.size() <= 12);
  std::vector<std::vector<char>> out;
  for (unsigned bits = 0; bits < (1u << inner.size()); ++bits) {
    std::vector<char> l(c.cells.size(), 0);
    for (std::size_t k = 0; k < inner.size(); ++k) l[static_cast<std::size_t>(inner[k])] = (bits >> k) & 1;
    out.push_back(l);
  }
  return out;
}

/// A labelling with a bit of everything: the first that has more than one boundary patch and a boundary face
/// on each of the boxes and the octahedron.
std::vector<char> rich_labelling() {
  for (const auto& l : labellings()) {
    std::vector<char> seen(scene().halfspaces.size(), 0);
    for (const ExportedFace& f : shape_faces(arranged(), l)) seen[static_cast<std::size_t>(f.halfspace)] = 1;
    if (seen[0] && seen[1] && seen[3]) return l;
  }
  FAIL("no labelling uses A, B and O");
  return {};
}

Rational det(const PointQ3& a, const PointQ3& b, const PointQ3& c) { return dot(a, cross(b, c)); }

/// sum det / 6 over faces given as vertex triples into `vertices`.
Rational divergence_volume(const std::vector<PointQ3>& vertices, const std::vector<std::array<int, 3>>& faces) {
  Rational v = 0;
  for (const auto& f : faces) v += det(vertices[f[0]], vertices[f[1]], vertices[f[2]]);
  return v / 6;
}

/// Closed as a 2-cycle: every directed edge is used as often as its reverse. Also counts the undirected edges
/// used more than twice (non-manifold) into *non_manifold when given.
bool closed(const std::vector<std::array<int, 3>>& faces, int* non_manifold = nullptr) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& f : faces)
    for (int k = 0; k < 3; ++k) ++directed[{f[k], f[(k + 1) % 3]}];
  int extra = 0;
  for (const auto& [edge, n] : directed) {
    const auto back = directed.find({edge.second, edge.first});
    if (back == directed.end() || back->second != n) return false;
    extra += n > 1;
  }
  if (non_manifold) *non_manifold = extra;
  return true;
}

Rational inside_volume(const std::vector<char>& labelling) {
  Rational v = 0;
  for (std::size_t k = 0; k < labelling.size(); ++k)
    if (labelling[k]) v += *arranged().arrangement.cells()[k].volume;
  return v;
}

std::vector<std::array<int, 3>> triangles_of(const std::vector<ExportedFace>& faces) {
  std::vector<std::array<int, 3>> out;
  for (const ExportedFace& f : faces) out.push_back(f.vertices);
  return out;
}

/// The exported faces' arrangement vertices in ascending order (the files' vertex order).
std::vector<int> used_vertices(const std::vector<ExportedFace>& faces) {
  std::vector<int> used;
  for (const auto& f : faces) used.insert(used.end(), f.vertices.begin(), f.vertices.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  return used;
}

/// Faces of a read mesh in arrangement vertex ids.
std::vector<std::array<int, 3>> in_arrangement_ids(const ObjMesh& mesh, const std::vector<int>& used) {
  std::vector<std::array<int, 3>> out;
  for (const auto& f : mesh.faces) out.push_back({used[f[0]], used[f[1]], used[f[2]]});
  return out;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

}  // namespace

TEST_CASE("shape faces: closed, outward, on their patches, for every labelling", "[io][mesh_export][shape]") {
  const Arranged3& a = arranged();
  const Complex& c = a.complex;
  const auto& triangles = a.arrangement.triangles();
  long nonempty = 0;
  for (const auto& l : labellings()) {
    const std::vector<ExportedFace> faces = shape_faces(a, l);
    auto inside = [&](int cell) { return cell >= 0 && l[static_cast<std::size_t>(cell)]; };
    // Exactly the triangles whose two cells are labelled differently, each once.
    std::vector<int> expected, got;
    for (std::size_t t = 0; t < triangles.size(); ++t)
      if (inside(triangles[t].front_cell) != inside(triangles[t].back_cell)) expected.push_back(static_cast<int>(t));
    for (const auto& f : faces) got.push_back(f.triangle);
    std::sort(got.begin(), got.end());
    REQUIRE(got == expected);
    nonempty += !faces.empty();
    for (std::size_t k = 0; k < faces.size(); ++k) {
      const ExportedFace& f = faces[k];
      const Patch& p = c.patches.at(static_cast<std::size_t>(f.patch));
      CHECK(std::binary_search(p.pieces.begin(), p.pieces.end(), f.triangle));
      CHECK(p.halfspace == f.halfspace);
      CHECK((inside(f.back_cell) && !inside(f.front_cell)));
      CHECK(((p.inside_cell == f.back_cell && p.outside_cell == f.front_cell) ||
             (p.inside_cell == f.front_cell && p.outside_cell == f.back_cell)));
      if (k > 0) CHECK(std::make_pair(faces[k - 1].patch, faces[k - 1].triangle) < std::make_pair(f.patch, f.triangle));
    }
    const auto tri = triangles_of(faces);
    CHECK(closed(tri));
    CHECK(divergence_volume(a.arrangement.vertices(), tri) == inside_volume(l));  // outward, exactly
  }
  CHECK(nonempty > 1);
  std::vector<char> outer(c.cells.size(), 0);
  outer[static_cast<std::size_t>(std::find_if(c.cells.begin(), c.cells.end(), [](const Cell& x) { return x.outer; }) -
                                 c.cells.begin())] = 1;
  CHECK_THROWS_AS(shape_faces(a, outer), std::invalid_argument);
  CHECK_THROWS_AS(shape_faces(a, std::vector<char>(c.cells.size() + 1, 0)), std::invalid_argument);
}

TEST_CASE("shape faces: a patch whose orientation the shape has is named", "[io][mesh_export][shape]") {
  // With the tetrahedron's complement, its cell is inside T: a shape holding the tetrahedron's outside and not
  // its inside uses T's patch with T's orientation (its inside cell behind the faces).
  const Arranged3& a = arranged();
  for (const auto& l : labellings())
    for (const ExportedFace& f : shape_faces(a, l)) {
      const Patch& p = a.complex.patches[static_cast<std::size_t>(f.patch)];
      const bool oriented = l[static_cast<std::size_t>(p.inside_cell)] != 0;
      // A support group here has one patch, so the named patch has the shape's orientation or there is none.
      if (a.complex.supports[static_cast<std::size_t>(p.support)].size() == 1) CHECK(oriented == (p.inside_cell == f.back_cell));
    }
}

TEST_CASE("shape PLY reads back: faces, labels, colours, closed", "[io][mesh_export][shape]") {
  const std::vector<char> l = rich_labelling();
  const std::vector<ExportedFace> faces = shape_faces(arranged(), l);
  const std::string ply = shape_ply(scene(), arranged(), l);
  CHECK(ply == shape_ply(scene(), arranged(), l));
  CHECK(ply.find("comment hsx shape boundary: outward") != std::string::npos);
  std::istringstream mesh_in(ply);
  const ObjMesh mesh = read_ply(mesh_in, "shape.ply");
  const std::vector<int> used = used_vertices(faces);
  REQUIRE(mesh.faces.size() == faces.size());
  REQUIRE(mesh.vertices.size() == used.size());
  const auto read = in_arrangement_ids(mesh, used);
  CHECK(read == triangles_of(faces));
  CHECK(closed(mesh.faces));
  // Per-face properties after the vertex ids: patch, halfspace, front (outside) and back (inside) cell, colour.
  std::istringstream in(ply);
  std::string line;
  while (std::getline(in, line) && line != "end_header") {
  }
  for (std::size_t v = 0; v < used.size(); ++v) std::getline(in, line);
  for (const ExportedFace& f : faces) {
    int n = 0, i0 = 0, i1 = 0, i2 = 0, patch = 0, halfspace = 0, front = 0, back = 0, r = 0, g = 0, b = 0;
    in >> n >> i0 >> i1 >> i2 >> patch >> halfspace >> front >> back >> r >> g >> b;
    CHECK(patch == f.patch);
    CHECK(halfspace == f.halfspace);
    CHECK((back >= 0 && l[static_cast<std::size_t>(back)] && (front < 0 || !l[static_cast<std::size_t>(front)])));
    char colour[8];
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", r, g, b);
    CHECK(std::string(colour) == svg_palette_colour(halfspace));
  }
  CHECK(static_cast<bool>(in));
}

TEST_CASE("shape OBJ (exact) reads back: one group per patch, the exact volume", "[io][mesh_export][shape]") {
  const std::vector<char> l = rich_labelling();
  const std::vector<ExportedFace> faces = shape_faces(arranged(), l);
  MeshExportOptions exact;
  exact.exact = true;
  const ObjText text = shape_obj(scene(), arranged(), l, "shape.mtl", exact);
  std::istringstream in(text.obj);
  const ObjMesh mesh = read_obj(in, "shape.obj");
  REQUIRE(mesh.faces.size() == faces.size());
  CHECK(closed(mesh.faces));
  CHECK(divergence_volume(mesh.vertices, mesh.faces) == inside_volume(l));
  std::istringstream lines(text.obj);
  std::string line;
  int group = -1, material = -1;
  std::size_t face = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("g patch_", 0) == 0) group = std::stoi(line.substr(8));
    if (line.rfind("usemtl halfspace_", 0) == 0) material = std::stoi(line.substr(17));
    if (line.rfind("f ", 0) != 0) continue;
    REQUIRE(face < faces.size());
    CHECK(group == faces[face].patch);
    CHECK(material == faces[face].halfspace);
    ++face;
  }
  CHECK(face == faces.size());
  CHECK(count(text.mtl, "newmtl halfspace_") == scene().halfspaces.size());
  CHECK_THROWS_AS(shape_obj(scene(), arranged(), l, ""), std::invalid_argument);
}

TEST_CASE("shape OFF (exact) reads back: patch ranges, colours, the exact volume", "[io][mesh_export][shape]") {
  const std::vector<char> l = rich_labelling();
  const std::vector<ExportedFace> faces = shape_faces(arranged(), l);
  MeshExportOptions exact;
  exact.exact = true;
  const std::string off = shape_off(scene(), arranged(), l, exact);
  std::istringstream in(off);
  const ObjMesh mesh = read_off(in, "shape.off");
  REQUIRE(mesh.faces.size() == faces.size());
  CHECK(closed(mesh.faces));
  CHECK(divergence_volume(mesh.vertices, mesh.faces) == inside_volume(l));
  // The "# patch K halfspace I faces FIRST COUNT" lines cover every face once, in order, with its labels.
  std::vector<int> patch_of(faces.size(), -1), halfspace_of(faces.size(), -1);
  std::istringstream lines(off);
  std::string line;
  std::size_t next = 0;
  REQUIRE((std::getline(lines, line) && line == "OFF"));
  while (std::getline(lines, line) && line.rfind("#", 0) == 0) {
    std::istringstream w(line);
    std::string hash, key, hs, fs;
    int patch = 0, halfspace = 0;
    std::size_t first = 0, n = 0;
    if (!(w >> hash >> key) || key != "patch") continue;
    REQUIRE(static_cast<bool>(w >> patch >> hs >> halfspace >> fs >> first >> n));
    CHECK(first == next);
    for (std::size_t k = first; k < first + n && k < faces.size(); ++k) {
      patch_of[k] = patch;
      halfspace_of[k] = halfspace;
    }
    next = first + n;
  }
  CHECK(next == faces.size());
  for (std::size_t k = 0; k < faces.size(); ++k) {
    CHECK(patch_of[k] == faces[k].patch);
    CHECK(halfspace_of[k] == faces[k].halfspace);
  }
  // Face lines end with the halfspace's colour.
  std::size_t face = 0;
  std::istringstream body(off);
  while (std::getline(body, line))
    if (line.rfind("3 ", 0) == 0 && std::count(line.begin(), line.end(), ' ') == 6) {
      std::istringstream w(line);
      int n = 0, i0 = 0, i1 = 0, i2 = 0, r = 0, g = 0, b = 0;
      w >> n >> i0 >> i1 >> i2 >> r >> g >> b;
      char colour[8];
      std::snprintf(colour, sizeof colour, "#%02x%02x%02x", r, g, b);
      REQUIRE(face < faces.size());
      CHECK(std::string(colour) == svg_palette_colour(faces[face++].halfspace));
    }
  CHECK(face == faces.size());
  // Decimal coordinates: the same faces.
  std::istringstream decimal(shape_off(scene(), arranged(), l));
  CHECK(read_off(decimal, "decimal.off").faces == mesh.faces);
}

TEST_CASE("renumber_vertices: the exports' numbering, used vertices ascending", "[io][mesh_export][shape]") {
  const Arrangement3& arr = arranged().arrangement;
  const std::vector<std::vector<ExportedFace>> face_sets = {shape_faces(arranged(), rich_labelling()),
                                                             exported_faces(arranged())};
  for (const std::vector<ExportedFace>& faces : face_sets) {
    const VertexNumbering n = renumber_vertices(arr, faces);
    REQUIRE(n.id.size() == arr.vertices().size());
    std::vector<char> touched(arr.vertices().size(), 0);
    for (const ExportedFace& f : faces)
      for (int v : f.vertices) touched[static_cast<std::size_t>(v)] = 1;
    std::vector<int> expected_used;
    for (std::size_t v = 0; v < touched.size(); ++v)
      if (touched[v]) expected_used.push_back(static_cast<int>(v));
    CHECK(n.used == expected_used);
    for (std::size_t v = 0; v < n.id.size(); ++v) CHECK((n.id[v] >= 0) == (touched[v] != 0));
    for (std::size_t k = 0; k < n.used.size(); ++k)
      CHECK(n.id[static_cast<std::size_t>(n.used[k])] == static_cast<int>(k));
  }
  // The OFF file's vertices are exactly the used ones, in this order, and its faces use these numbers.
  const std::vector<char> l = rich_labelling();
  const std::vector<ExportedFace> faces = shape_faces(arranged(), l);
  const VertexNumbering n = renumber_vertices(arr, faces);
  MeshExportOptions exact;
  exact.exact = true;
  std::istringstream in(shape_off(scene(), arranged(), l, exact));
  const ObjMesh mesh = read_off(in, "shape.off");
  REQUIRE(mesh.vertices.size() == n.used.size());
  for (std::size_t k = 0; k < n.used.size(); ++k)
    CHECK(mesh.vertices[k] == arr.vertices()[static_cast<std::size_t>(n.used[k])]);
  REQUIRE(mesh.faces.size() == faces.size());
  for (std::size_t k = 0; k < faces.size(); ++k)
    for (int j = 0; j < 3; ++j)
      CHECK(mesh.faces[k][static_cast<std::size_t>(j)] ==
            n.id[static_cast<std::size_t>(faces[k].vertices[static_cast<std::size_t>(j)])]);
  // No faces: nothing used; a vertex the arrangement does not have: refused.
  const VertexNumbering none = renumber_vertices(arr, {});
  CHECK(none.used.empty());
  CHECK(std::all_of(none.id.begin(), none.id.end(), [](int v) { return v == -1; }));
  ExportedFace bad;
  bad.vertices = {0, 1, static_cast<int>(arr.vertices().size())};
  CHECK_THROWS_AS(renumber_vertices(arr, {bad}), std::out_of_range);
}

TEST_CASE("shape SVG: the boundary's faces per view, missing samples ringed, removed patches on top", "[io][svg3][shape]") {
  const Arranged3& a = arranged();
  const std::vector<char> l = rich_labelling();
  Svg3Options options;
  options.cell_fill = l;
  options.highlight_patches.assign(a.complex.patches.size(), 0);
  int highlighted = -1;  // a patch off the boundary
  const std::vector<ExportedFace> faces = shape_faces(a, l);
  for (std::size_t p = 0; p < a.complex.patches.size() && highlighted < 0; ++p)
    if (std::none_of(faces.begin(), faces.end(), [&](const ExportedFace& f) { return f.patch == static_cast<int>(p); }))
      highlighted = static_cast<int>(p);
  REQUIRE(highlighted >= 0);
  options.highlight_patches[static_cast<std::size_t>(highlighted)] = 1;
  options.highlight_legend = "removed patches";
  const std::string svg = arrangement_svg3(scene(), a, options);
  std::istringstream in(svg);
  boost::property_tree::ptree tree;
  REQUIRE_NOTHROW(boost::property_tree::read_xml(in, tree));
  const auto views = default_svg_views3();
  std::size_t group = 0;
  for (const auto& child : tree.get_child("svg")) {
    if (child.first != "g" || child.second.get("<xmlattr>.class", "") != "view") continue;
    const SvgView3& view = views.at(group / 2);
    const bool highlight_group = group % 2 == 1;  // each view: the faces, then the highlighted patches
    std::size_t expected = 0;
    const auto& patch = a.complex.patches[static_cast<std::size_t>(highlighted)];
    auto seen = [&](int t) {
      const auto& v = a.arrangement.vertices();
      const auto& tri = a.arrangement.triangles()[static_cast<std::size_t>(t)].vertices;
      return dot(cross(sub(v[tri[1]], v[tri[0]]), sub(v[tri[2]], v[tri[0]])), view.direction) != 0;
    };
    if (highlight_group)
      for (int t : patch.pieces) expected += seen(t);
    else
      for (const auto& f : faces) expected += seen(f.triangle);
    std::size_t n = 0;
    for (const auto& poly : child.second) {
      if (poly.first == "<xmlattr>") continue;
      CHECK(poly.second.get("<xmlattr>.class", "") == (highlight_group ? "highlight" : "face"));
      ++n;
    }
    INFO(view.name << (highlight_group ? " highlights" : " faces"));
    CHECK(n == expected);
    ++group;
  }
  CHECK(group == 2 * views.size());
  const auto missing = svg_missing_samples(a.complex, l);
  CHECK(count(svg, "class=\"missing\"") == views.size() * static_cast<std::size_t>(std::count(missing.begin(), missing.end(), 1)));
  CHECK(count(svg, "removed patches") == 1);
  options.cell_fill.pop_back();
  CHECK_THROWS_AS(arrangement_svg3(scene(), a, options), std::invalid_argument);
}

TEST_CASE("svg_grid nests pictures in rows and columns", "[io][svg]") {
  Svg3Options small;
  small.width = 300;
  small.views = {default_svg_views3().back()};
  const std::string one = arrangement_svg3(scene(), arranged(), small);
  small.width = 400;
  const std::string two = arrangement_svg3(scene(), arranged(), small);
  const std::string grid = svg_grid({one, two, one}, 2);
  std::istringstream in(grid);
  boost::property_tree::ptree tree;
  REQUIRE_NOTHROW(boost::property_tree::read_xml(in, tree));
  std::vector<std::pair<double, double>> at;
  for (const auto& child : tree.get_child("svg"))
    if (child.first == "svg") at.emplace_back(child.second.get<double>("<xmlattr>.x"), child.second.get<double>("<xmlattr>.y"));
  REQUIRE(at.size() == 3);
  CHECK(at[0] == std::make_pair(8.0, 8.0));
  CHECK(at[1] == std::make_pair(8.0 + 300 + 8, 8.0));   // the first column is as wide as its widest picture
  CHECK(at[2].first == 8.0);
  CHECK(at[2].second > 8.0 + 300);                       // the second row below the first one's tallest picture
  CHECK(tree.get<double>("svg.<xmlattr>.width") == 8 + 300 + 8 + 400 + 8);
  CHECK(count(grid, "class=\"face\"") == 3 * count(one, "class=\"face\""));
  CHECK_THROWS_AS(svg_grid({"<g/>"}, 1), std::invalid_argument);
  CHECK_THROWS_AS(svg_grid({one}, 0), std::invalid_argument);
}

TEST_CASE("closed_form_terms counts the terms of a Measure's closed form", "[io][result]") {
  CHECK(closed_form_terms("") == 0);
  CHECK(closed_form_terms("-1/2") == 1);
  CHECK(closed_form_terms("1 - sqrt(2)") == 2);
  CHECK(closed_form_terms("4/3*pi + 1/2 + 3*sqrt(2) + sqrt(5 + 2*sqrt(6))") == 4);
  Measure m = Rational(1, 3);
  const int primes[] = {2, 3, 5, 7, 11, 13, 17};
  for (int p : primes) m += Measure::sqrt_of(Rational(p)) * Rational(-p, 7);
  REQUIRE(m.exact_string());
  CHECK(closed_form_terms(*m.exact_string()) == 8);
}
