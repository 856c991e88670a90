// Pictures and mesh exports of 3D arrangements (io/svg3.hpp, io/mesh_export.hpp) on a fixed small scene: the SVG
// parses as XML and has one polygon per visible triangle per view, painted back to front; the PLY and the OBJ
// (read back through hsx's own read_obj) give the arrangement's triangles with their patches and halfspaces.
#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/geometry/mesh3.hpp>
#include <hsx/io/mesh_export.hpp>
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

/// Two boxes sharing a face, a plane cutting both (seen edge-on from the front and the side), an octahedron
/// above them, a complemented tetrahedron; a sample on the octahedron and one on the plane.
Scene3 picture_scene() {
  Scene3 s = scene_of(
      {pt(-4, -4, -4), pt(4, 4, 4)},
      {surface("A<&>", box_surface(pt(-2, -2, -2), pt(0, 1, 1))), surface("B", box_surface(pt(0, -2, -2), pt(2, 1, 1))),
       plane("P", pt(0, 0, 2), 1), surface("O", octahedron(pt(1, 2, 2), 1)),
       surface("T", tetrahedron(pt(-3, 2, -3), pt(-1, 2, -3), pt(-3, 3, -3), pt(-3, 2, -1)), true)});
  s.samples = {at_sample(3, pt(Rational(4, 3), Rational(7, 3), Rational(7, 3))),
               at_sample(2, pt(3, 3, Rational(1, 2)))};
  validate_and_resolve(s);
  return s;
}

const Scene3& scene() {
  static const Scene3 s = picture_scene();
  return s;
}

const Arranged3& arranged() {
  static const Arranged3 a = arrange(scene());
  return a;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

PointQ3 normal_of(const Arrangement3& arr, const std::array<int, 3>& t) {
  const auto& v = arr.vertices();
  return cross(sub(v[t[1]], v[t[0]]), sub(v[t[2]], v[t[0]]));
}

/// Triangles a view must draw, counted here without the library: not on the box, normal not orthogonal to it.
std::size_t expected_faces(const Arrangement3& arr, const PointQ3& direction) {
  std::size_t n = 0;
  for (const ArrTriangle3& t : arr.triangles()) n += !t.on_box && dot(normal_of(arr, t.vertices), direction) != 0;
  return n;
}

Rational depth(const Arrangement3& arr, int triangle, const PointQ3& direction) {
  Rational d = 0;
  for (int v : arr.triangles()[static_cast<std::size_t>(triangle)].vertices) d += dot(arr.vertices()[v], direction);
  return d;
}

/// a and b are the same triangle: the same vertices in the same cyclic order.
bool same_cycle(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int r = 0; r < 3; ++r)
    if (a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3]) return true;
  return false;
}

bool close(const Rational& read, const Rational& exact) {
  const Rational bound = (abs(exact) + 1) / Rational(Integer(1) << 50);
  return abs(read - exact) <= bound;
}

}  // namespace

TEST_CASE("3D SVG: well formed, one polygon per visible triangle per view, back to front", "[io][svg3]") {
  const Arrangement3& arr = arranged().arrangement;
  Svg3Options options;
  options.title = "two boxes & a plane";
  const std::string svg = arrangement_svg3(scene(), arranged(), options);
  CHECK(svg == arrangement_svg3(scene(), arranged(), options));  // deterministic
  std::istringstream in(svg);
  boost::property_tree::ptree tree;
  REQUIRE_NOTHROW(boost::property_tree::read_xml(in, tree));  // well formed
  const auto views = default_svg_views3();
  std::size_t view_index = 0, polygons = 0;
  for (const auto& child : tree.get_child("svg")) {
    if (child.first != "g" || child.second.get("<xmlattr>.class", "") != "view") continue;
    REQUIRE(view_index < views.size());
    const SvgView3& view = views[view_index];
    CHECK(child.second.get("<xmlattr>.data-view", "") == view.name);
    std::vector<int> order;
    for (const auto& face : child.second) {
      if (face.first == "<xmlattr>") continue;
      CHECK(face.first == "polygon");
      order.push_back(face.second.get<int>("<xmlattr>.data-triangle"));
    }
    INFO(view.name);
    CHECK(order.size() == expected_faces(arr, view.direction));
    CHECK(order.size() == svg3_visible_triangles(arr, view));
    for (std::size_t k = 1; k < order.size(); ++k)
      CHECK(depth(arr, order[k - 1], view.direction) >= depth(arr, order[k], view.direction));
    polygons += order.size();
    ++view_index;
  }
  CHECK(view_index == 4);
  CHECK(count(svg, "<polygon") == polygons);
  // The plane z = 1/2 and the boxes' horizontal faces are edge-on from the front: fewer faces there than on top.
  CHECK(expected_faces(arr, views[0].direction) < expected_faces(arr, views[3].direction));
  CHECK(count(svg, "class=\"sample\"") == 4 * scene().samples.size());
  CHECK(count(svg, "class=\"cell-id\"") == 0);
  CHECK(count(svg, "A&lt;&amp;&gt; (mesh)") == 1);  // the legend, escaped
}

TEST_CASE("3D SVG: labels and bad arguments", "[io][svg3]") {
  Svg3Options options;
  options.show_cell_ids = options.show_patch_ids = true;
  options.views = {default_svg_views3()[3]};
  const std::string svg = arrangement_svg3(scene(), arranged(), options);
  CHECK(count(svg, "class=\"cell-id\"") == arranged().complex.cells.size());
  CHECK(count(svg, "class=\"patch-id\"") == arranged().complex.patches.size());
  options.views = {{"bad", pt(0, 0, 1), pt(0, 0, 2)}};
  CHECK_THROWS_AS(arrangement_svg3(scene(), arranged(), options), std::invalid_argument);
  options.views = {{"zero", pt(0, 0, 0), pt(0, 0, 1)}};
  CHECK_THROWS_AS(arrangement_svg3(scene(), arranged(), options), std::invalid_argument);
  Scene3 other = scene();
  other.halfspaces.pop_back();
  CHECK_THROWS_AS(arrangement_svg3(other, arranged(), {}), std::invalid_argument);
}

TEST_CASE("exported faces: every non-box triangle once, turned out of its first halfspace", "[io][mesh_export]") {
  const Arranged3& a = arranged();
  const auto faces = exported_faces(a);
  std::size_t non_box = 0;
  for (const ArrTriangle3& t : a.arrangement.triangles()) non_box += !t.on_box;
  REQUIRE(faces.size() == non_box);
  for (const ExportedFace& f : faces) {
    const ArrTriangle3& t = a.arrangement.triangles()[static_cast<std::size_t>(f.triangle)];
    CHECK(f.halfspace == t.halfspaces.front());
    REQUIRE(f.patch >= 0);
    const Patch& patch = a.complex.patches[static_cast<std::size_t>(f.patch)];
    CHECK(patch.halfspace == f.halfspace);
    CHECK(std::binary_search(patch.pieces.begin(), patch.pieces.end(), f.triangle));
    const bool turned = t.front_inside.front() != 0;
    std::array<int, 3> expected = t.vertices;
    if (turned) std::swap(expected[1], expected[2]);
    CHECK(same_cycle(f.vertices, expected));
    // out of the halfspace: a point just in front of the face is outside it
    CHECK(f.front_cell == (turned ? t.back_cell : t.front_cell));
    if (f.front_cell >= 0) CHECK(a.complex.cells[static_cast<std::size_t>(f.front_cell)].inside[f.halfspace] == 0);
  }
}

TEST_CASE("PLY export reads back to the same triangles, patches and colours", "[io][mesh_export]") {
  const Arranged3& a = arranged();
  const std::string ply = arrangement_ply(scene(), a);
  CHECK(ply == arrangement_ply(scene(), a));
  std::istringstream in(ply);
  std::string line;
  long vertices = -1, faces = -1;
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream words(line);
    std::string w, kind;
    long n = 0;
    if (words >> w >> kind >> n && w == "element") (kind == "vertex" ? vertices : faces) = n;
  }
  const auto exported = exported_faces(a);
  REQUIRE(faces == static_cast<long>(exported.size()));
  std::vector<int> used;  // the arrangement vertices of the exported faces, ascending
  for (const auto& f : exported) used.insert(used.end(), f.vertices.begin(), f.vertices.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  REQUIRE(vertices == static_cast<long>(used.size()));
  for (int v : used) {
    std::string x, y, z;
    in >> x >> y >> z;
    const PointQ3& p = a.arrangement.vertices()[static_cast<std::size_t>(v)];
    CHECK((close(*parse_rational(x), p.x) && close(*parse_rational(y), p.y) && close(*parse_rational(z), p.z)));
  }
  for (const auto& f : exported) {
    int n = 0, i0 = 0, i1 = 0, i2 = 0, patch = 0, halfspace = 0, front = 0, back = 0, r = 0, g = 0, b = 0;
    in >> n >> i0 >> i1 >> i2 >> patch >> halfspace >> front >> back >> r >> g >> b;
    CHECK(n == 3);
    CHECK(same_cycle({used[i0], used[i1], used[i2]}, f.vertices));
    CHECK(patch == f.patch);
    CHECK(halfspace == f.halfspace);
    CHECK((front == f.front_cell && back == f.back_cell));
    char colour[8];
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", r, g, b);
    CHECK(std::string(colour) == svg_palette_colour(halfspace));
  }
  CHECK(static_cast<bool>(in));
}

TEST_CASE("OBJ export reads back through read_obj: exact triangles, one group per patch", "[io][mesh_export]") {
  const Arranged3& a = arranged();
  MeshExportOptions exact;
  exact.exact = true;
  const ObjText text = arrangement_obj(scene(), a, "out.mtl", exact);
  std::istringstream in(text.obj);
  const ObjMesh mesh = read_obj(in, "out.obj");
  const auto exported = exported_faces(a);
  REQUIRE(mesh.faces.size() == exported.size());
  std::vector<int> used;
  for (const auto& f : exported) used.insert(used.end(), f.vertices.begin(), f.vertices.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  REQUIRE(mesh.vertices.size() == used.size());
  for (std::size_t k = 0; k < used.size(); ++k) CHECK(mesh.vertices[k] == a.arrangement.vertices()[used[k]]);
  // Faces in file order, each under the "g patch_<k>" line before it.
  std::map<int, int> patch_of_triangle;
  for (const auto& f : exported) patch_of_triangle[f.triangle] = f.patch;
  std::istringstream lines(text.obj);
  std::string line;
  int group = -1;
  std::size_t face = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("g patch_", 0) == 0) group = std::stoi(line.substr(8));
    if (line.rfind("f ", 0) != 0) continue;
    REQUIRE(face < mesh.faces.size());
    const auto& m = mesh.faces[face++];
    const std::array<int, 3> v = {used[m[0]], used[m[1]], used[m[2]]};
    const auto match = std::find_if(exported.begin(), exported.end(),
                                    [&](const ExportedFace& f) { return same_cycle(f.vertices, v); });
    REQUIRE(match != exported.end());
    CHECK(match->patch == group);
  }
  CHECK(face == exported.size());
  CHECK(text.obj.find("mtllib out.mtl\n") != std::string::npos);
  CHECK(count(text.mtl, "newmtl halfspace_") == scene().halfspaces.size());
  // Decimal coordinates read back within double precision.
  std::istringstream decimal_in(arrangement_obj(scene(), a, "out.mtl").obj);
  const ObjMesh decimal = read_obj(decimal_in, "decimal.obj");
  REQUIRE(decimal.vertices.size() == used.size());
  for (std::size_t k = 0; k < used.size(); ++k)
    CHECK(close(decimal.vertices[k].z, a.arrangement.vertices()[used[k]].z));
  CHECK(mtl_path_for("dir/out.obj") == "dir/out.mtl");
  CHECK_THROWS_AS(arrangement_obj(scene(), a, "a\nb"), std::invalid_argument);
}

TEST_CASE("3D SVG: a shape under cell marks is grey, so that the marks are not taken for halfspaces", "[io][svg3]") {
  const Complex& c = arranged().complex;
  Svg3Options options;
  options.views = {default_svg_views3()[3]};
  options.cell_fill.assign(c.cells.size(), 0);
  for (std::size_t k = 0; k < c.cells.size(); ++k) options.cell_fill[k] = c.cells[k].outer ? 0 : 1;
  // Every "face" fill "#rrggbb" is grey (r = g = b) exactly when some cell is marked.
  auto grey_faces = [](const std::string& svg) {
    std::size_t faces = 0, grey = 0;
    for (std::size_t at = svg.find("class=\"face\""); at != std::string::npos; at = svg.find("class=\"face\"", at + 1)) {
      const std::size_t f = svg.find("fill=\"#", at) + 7;
      ++faces;
      grey += svg.compare(f, 2, svg, f + 2, 2) == 0 && svg.compare(f, 2, svg, f + 4, 2) == 0;
    }
    return std::make_pair(faces, grey);
  };
  const auto plain = grey_faces(arrangement_svg3(scene(), arranged(), options));
  REQUIRE(plain.first > 0);
  CHECK(plain.second < plain.first);
  options.cell_marks.assign(c.cells.size(), 0);
  for (std::size_t k = 0; k < c.cells.size(); ++k)
    if (!c.cells[k].outer) {
      options.cell_marks[k] = 1;
      break;
    }
  const std::string marked_svg = arrangement_svg3(scene(), arranged(), options);
  const auto marked = grey_faces(marked_svg);
  CHECK(marked.first == plain.first);
  CHECK(marked.second == marked.first);
  CHECK(count(marked_svg, "grey under the marks") == 1);
}

TEST_CASE("3D SVG: cell marks draw the patches bounding marked cells, orange and red", "[io][svg3]") {
  const Complex& c = arranged().complex;
  REQUIRE(c.cells.size() >= 3);
  Svg3Options options;
  options.views = {default_svg_views3()[3]};
  options.cell_marks.assign(c.cells.size(), 0);
  CHECK(count(arrangement_svg3(scene(), arranged(), options), "class=\"mark-") == 0);
  // Mark the first non-outer cell 1 and the outer cell 0 (it bounds the first one's outside) 2.
  int marked = -1;
  for (std::size_t k = 0; k < c.cells.size() && marked < 0; ++k)
    if (!c.cells[k].outer) marked = static_cast<int>(k);
  REQUIRE(marked >= 0);
  options.cell_marks[static_cast<std::size_t>(marked)] = 1;
  const std::string one = arrangement_svg3(scene(), arranged(), options);
  // Every triangle of every patch bounding the marked cell, seen in the view, is a mark-inside polygon; the
  // patches' triangles are at most that many.
  std::size_t triangles = 0;
  for (const Patch& p : c.patches)
    if (p.inside_cell == marked || p.outside_cell == marked) triangles += p.pieces.size();
  CHECK(count(one, "class=\"mark-inside\"") > 0);
  CHECK(count(one, "class=\"mark-inside\"") <= triangles);
  CHECK(count(one, "class=\"mark-outside\"") == 0);
  CHECK(one.find("inside cells of mixed terms (1 cells;") != std::string::npos);
  CHECK(one.find("fill=\"#f4a261\"") != std::string::npos);  // the legend's swatch
  for (std::size_t k = 0; k < c.cells.size(); ++k)
    if (static_cast<int>(k) != marked) options.cell_marks[k] = 2;
  const std::string two = arrangement_svg3(scene(), arranged(), options);
  CHECK(count(two, "class=\"mark-outside\"") > 0);
  // A patch of the marked cell takes mark 1 when that cell is its inside cell, else the other cell's mark 2.
  CHECK(count(two, "class=\"mark-inside\"") <= count(one, "class=\"mark-inside\""));
  options.cell_marks.push_back(0);
  CHECK_THROWS_AS(arrangement_svg3(scene(), arranged(), options), std::invalid_argument);
  options.cell_marks.assign(c.cells.size(), 3);
  CHECK_THROWS_AS(arrangement_svg3(scene(), arranged(), options), std::invalid_argument);
}

TEST_CASE("3D SVG: states share each patch's drawing, once per view", "[io][svg3]") {
  const Complex& c = arranged().complex;
  std::vector<char> all(c.cells.size(), 0), one(c.cells.size(), 0);
  for (std::size_t k = 0; k < c.cells.size(); ++k) all[k] = c.cells[k].outer ? 0 : 1;
  for (std::size_t k = 0; k < c.cells.size(); ++k)
    if (!c.cells[k].outer) {
      one[k] = 1;
      break;
    }
  std::vector<char> lit(c.patches.size(), 0);
  lit[0] = 1;
  Svg3Options options;
  options.views = {default_svg_views3()[3]};
  const std::vector<Svg3State> states = {{all, {}, "every cell"}, {one, lit, "one cell"}, {all, lit, "again"}};
  const std::string svg = states_svg3(scene(), arranged(), states, options, 2);
  std::istringstream in(svg);
  boost::property_tree::ptree tree;
  REQUIRE_NOTHROW(boost::property_tree::read_xml(in, tree));
  // Each patch on some boundary is defined once ("v0p<k>"), patch 0's highlight once; three panels use them.
  std::vector<char> boundary(c.patches.size(), 0);
  for (const auto* fill : {&all, &one})
    for (const ExportedFace& f : shape_faces(arranged(), *fill)) boundary[static_cast<std::size_t>(f.patch)] = 1;
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    INFO("patch " << p);
    CHECK(count(svg, "id=\"v0p" + std::to_string(p) + "\"") == std::size_t(boundary[p]));
  }
  CHECK(count(svg, "id=\"v0h0\"") == 1);
  CHECK(count(svg, "class=\"highlight\" data-patch=\"0\"") == 2);
  CHECK(count(svg, "<svg x=") == 3);
  CHECK(count(svg, "<polygon") == 0);
  CHECK(count(svg, "xlink:href=\"#v0d\"") == 3);
  // The states give the shapes and titles; bad states and options are refused.
  Svg3Options titled = options;
  titled.title = "no";
  CHECK_THROWS_AS(states_svg3(scene(), arranged(), states, titled, 2), std::invalid_argument);
  CHECK_THROWS_AS(states_svg3(scene(), arranged(), {}, options, 2), std::invalid_argument);
  CHECK_THROWS_AS(states_svg3(scene(), arranged(), states, options, 0), std::invalid_argument);
  CHECK_THROWS_AS(states_svg3(scene(), arranged(), {{{1}, {}, "short"}}, options, 1), std::invalid_argument);
}
