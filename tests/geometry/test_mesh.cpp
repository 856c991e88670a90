// Tests of geometry/mesh3 and complex/boundary_from_mesh: exact .obj/.fea reading, validation (each kind of bad
// input rejected with its line, edge or vertex), orientation, the exact convex/concave sign, the sharpness angle
// at special angles and against a long-double oracle, invariance under translation and renumbering, and the
// shared NH-Rep models when they are present.
#include <hsx/complex/boundary_from_mesh.hpp>
#include <hsx/geometry/mesh3.hpp>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace hsx;
using Catch::Matchers::Contains;

namespace {

Rational frac(long n, long d) { return make_rational(Integer(n), Integer(d)); }

Rational q(const char* text) {
  auto r = parse_rational(text);
  REQUIRE(r.has_value());
  return *r;
}

ObjMesh obj_of(const std::string& text, const std::string& source = "test.obj") {
  std::istringstream in(text);
  return read_obj(in, source);
}

Mesh3 mesh_of(const std::string& text) { return build_mesh3(obj_of(text)); }

FeatureEdgeList fea_of(const std::string& text, const std::string& source = "test.fea") {
  std::istringstream in(text);
  return read_fea(in, source);
}

std::string data_path(const std::string& name) { return std::string(HSX_SOURCE_DIR) + "/data/meshes/" + name; }

const char* const kCube =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n";

/// The cube with every face's vertex order reversed (inward normals).
std::string reversed_faces(const std::string& obj) {
  std::istringstream in(obj);
  std::string line, out;
  while (std::getline(in, line)) {
    if (line.rfind("f ", 0) == 0) {
      std::istringstream f(line.substr(2));
      std::string a, b, c;
      f >> a >> b >> c;
      line = "f " + a + " " + c + " " + b;
    }
    out += line + "\n";
  }
  return out;
}

/// A prism over a polygon that can be fanned from its first vertex (convex, or the L), 0 <= z <= h, outward.
std::string prism_obj(const std::vector<std::pair<long, long>>& polygon, long h = 1) {
  const int n = static_cast<int>(polygon.size());
  std::string out;
  for (long z : {0L, h})
    for (const auto& [x, y] : polygon) out += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  auto f = [&](int a, int b, int c) {
    out += "f " + std::to_string(a + 1) + " " + std::to_string(b + 1) + " " + std::to_string(c + 1) + "\n";
  };
  for (int i = 1; i + 1 < n; ++i) {
    f(0, i + 1, i);          // bottom, seen from below
    f(n, n + i, n + i + 1);  // top
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    f(i, j, n + j);
    f(i, n + j, n + i);
  }
  return out;
}

int edge_of(const Mesh3& m, int u, int v) {
  const int e = m.find_edge(u, v);
  REQUIRE(e >= 0);
  return e;
}

/// Per piece, its patch (connected components across non-feature links), numbered in order of lowest piece index.
std::vector<int> patch_labels(const BoundarySurface& s) {
  std::vector<int> parent(s.pieces.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
  for (const auto& l : s.links)
    if (!l.feature) parent[find(l.piece_a)] = find(l.piece_b);
  std::map<int, int> label;
  std::vector<int> out;
  for (std::size_t i = 0; i < parent.size(); ++i)
    out.push_back(label.emplace(find(static_cast<int>(i)), static_cast<int>(label.size())).first->second);
  return out;
}

int patch_count(const BoundarySurface& s) {
  const auto labels = patch_labels(s);
  return labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
}

std::map<FeatureType, int> feature_types(const BoundarySurface& s) {
  std::map<FeatureType, int> count;
  for (const auto& l : s.links)
    if (l.feature) ++count[l.type];
  return count;
}

}  // namespace

// ------------------------------------------------------------------------------------------------------------------
// Reading

TEST_CASE("obj reader: exact numbers, index forms, ignored lines", "[mesh]") {
  const ObjMesh obj = obj_of(
      "# a tetrahedron scaled by 0.1\r\n"
      "o thing\nmtllib x.mtl\n\n"
      "v 0 0 0\n"
      "v 0.1 0 0   # trailing comment\n"
      "v 0 1e-1 0\n"
      "v\t0 0 1/10 1\n"
      "vn 0 0 1\nvt 0.5 0.5\ns off\ng group\nusemtl m\n"
      "f 1/1/1 3/2/1 2//1\n"
      "f 1/1 2 4\n"
      "f -4 -1 -2\n"  // relative: 1 4 3
      "f 2 3 4\n");
  REQUIRE(obj.vertices.size() == 4);
  CHECK(obj.vertices[1].x == frac(1, 10));
  CHECK(obj.vertices[2].y == frac(1, 10));
  CHECK(obj.vertices[3].z == frac(1, 10));
  CHECK(obj.faces[0] == std::array<int, 3>{0, 2, 1});
  CHECK(obj.faces[2] == std::array<int, 3>{0, 3, 2});
  CHECK(obj.face_lines[0] == 14);
  const Mesh3 m = build_mesh3(obj);
  CHECK(m.volume == frac(1, 6000));
  CHECK_FALSE(m.flipped);
  CHECK(m.edges.size() == 6);
  for (const auto& e : m.edges) CHECK(e.shape == EdgeShape::Convex);
}

TEST_CASE("obj reader: rational coordinates, with and without a common denominator", "[mesh]") {
  // A tetrahedron (0, a, b, c on the axes): volume a b c / 6, all edges convex. Denominators 3^k, 7^k, 11^k: with
  // k = 2 the lcm is small and the integer-scaled path runs; with k = 60 it exceeds 256 bits and plain rationals do.
  for (int k : {2, 60}) {
    INFO("k = " << k);
    Integer d3, d7, d11;
    mpz_ui_pow_ui(d3.get_mpz_t(), 3, static_cast<unsigned long>(k));
    mpz_ui_pow_ui(d7.get_mpz_t(), 7, static_cast<unsigned long>(k));
    mpz_ui_pow_ui(d11.get_mpz_t(), 11, static_cast<unsigned long>(k));
    const Rational a = make_rational(1, d3), b = make_rational(2, d7), c = make_rational(5, d11);
    const Mesh3 m = mesh_of("v 0 0 0\nv " + exact_string(a) + " 0 0\nv 0 " + exact_string(b) + " 0\nv 0 0 " +
                            exact_string(c) + "\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    CHECK(m.volume == a * b * c / 6);
    for (const auto& e : m.edges) CHECK(e.shape == EdgeShape::Convex);
    const SharpnessAngle right{Rational(90)};
    CHECK(classify_edge(m, m.find_edge(0, 1), right) == EdgeShape::Convex);  // two axis planes: exactly 90 degrees
    CHECK(classify_edge(m, m.find_edge(0, 1), SharpnessAngle(q("90.0001"))) == EdgeShape::Flat);
    CHECK(classify_edge(m, m.find_edge(1, 2), right) == EdgeShape::Convex);  // interior angle < 90: deviation > 90
  }
}

TEST_CASE("fea reader", "[mesh]") {
  const FeatureEdgeList f = fea_of("\n3\n0 1\n\n1 2\n2 0\n\n");
  REQUIRE(f.edges.size() == 3);
  CHECK(f.edges[1] == std::make_pair(1, 2));
  CHECK(f.lines[1] == 5);
  CHECK(fea_of("0\n").edges.empty());
}

// ------------------------------------------------------------------------------------------------------------------
// Good meshes

TEST_CASE("unit cube: 12 convex box edges, 6 flat diagonals", "[mesh]") {
  const Mesh3 m = build_mesh3(read_obj_file(data_path("cube.obj")));
  CHECK(m.vertices.size() == 8);
  CHECK(m.faces.size() == 12);
  CHECK(m.edges.size() == 18);
  CHECK(m.volume == 1);
  CHECK(m.shells == 1);
  CHECK_FALSE(m.flipped);
  const FeatureEdgeList fea = read_fea_file(data_path("cube.fea"));
  const std::vector<char> marked = resolve_feature_edges(m, fea);
  int convex = 0, flat = 0;
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    const EdgeShape s = m.edges[e].shape;
    CHECK((s == EdgeShape::Convex) == (marked[e] != 0));  // the marked box edges are exactly the convex ones
    convex += s == EdgeShape::Convex;
    flat += s == EdgeShape::Flat;
  }
  CHECK(convex == 12);
  CHECK(flat == 6);

  const BoundarySurface b = boundary_from_mesh(m, fea);
  CHECK(check_boundary(b).empty());
  CHECK(b.dimension == 3);
  CHECK(b.corner_count == 8);
  CHECK(b.pieces.size() == 12);
  CHECK(b.links.size() == 18);
  CHECK(feature_types(b) == std::map<FeatureType, int>{{FeatureType::Convex, 12}});
  CHECK(patch_count(b) == 6);
  for (std::size_t f = 0; f < b.pieces.size(); ++f) {
    CHECK(b.pieces[f].origin == static_cast<int>(f));
    REQUIRE(b.pieces[f].links.size() == 3);
    for (int k = 0; k < 3; ++k) {  // link k of piece f is the edge f[k] -> f[k+1]
      const BoundaryLink& l = b.links[static_cast<std::size_t>(b.pieces[f].links[static_cast<std::size_t>(k)])];
      const int u = m.faces[f][static_cast<std::size_t>(k)], v = m.faces[f][static_cast<std::size_t>((k + 1) % 3)];
      CHECK(std::min(u, v) == l.corner_a);
      CHECK(std::max(u, v) == l.corner_b);
      CHECK((l.piece_a == static_cast<int>(f) || l.piece_b == static_cast<int>(f)));
    }
  }
}

TEST_CASE("L-shaped prism: one concave edge", "[mesh]") {
  const Mesh3 m = build_mesh3(read_obj_file(data_path("lprism.obj")));
  CHECK(m.volume == 3);
  CHECK(m.faces.size() == 20);
  const BoundarySurface b = boundary_from_mesh(m, read_fea_file(data_path("lprism.fea")));
  CHECK(check_boundary(b).empty());
  CHECK(feature_types(b) == std::map<FeatureType, int>{{FeatureType::Convex, 17}, {FeatureType::Concave, 1}});
  const int concave = edge_of(m, 3, 9);  // the vertical edge at (1, 1)
  CHECK(m.edges[static_cast<std::size_t>(concave)].shape == EdgeShape::Concave);
  CHECK(b.links[static_cast<std::size_t>(concave)].type == FeatureType::Concave);
  CHECK(patch_count(b) == 8);
  // Without features the whole prism is one patch.
  CHECK(patch_count(boundary_from_mesh(m, std::vector<std::pair<int, int>>{})) == 1);
}

TEST_CASE("inward-oriented input is flipped with a note", "[mesh]") {
  const Mesh3 out = mesh_of(kCube);
  const Mesh3 in = mesh_of(reversed_faces(kCube));
  CHECK(in.flipped);
  REQUIRE(in.notes.size() == 1);
  CHECK_THAT(in.notes[0], Contains("inward"));
  CHECK(in.volume == 1);
  REQUIRE(in.edges.size() == out.edges.size());
  for (std::size_t e = 0; e < in.edges.size(); ++e) {
    CHECK(in.edges[e].a == out.edges[e].a);
    CHECK(in.edges[e].shape == out.edges[e].shape);
  }
  // Every reversed face is again counter-clockwise from outside: same normal as the original face.
  for (std::size_t f = 0; f < in.faces.size(); ++f) CHECK(in.normals[f] == out.normals[f]);
}

TEST_CASE("two shells and unused vertices are accepted with notes", "[mesh]") {
  std::string two = kCube;
  two += "v 5 5 5\n";  // unused
  // A second cube, shifted: vertices 10..17 (1-based).
  for (const char* v : {"3 0 0", "4 0 0", "4 1 0", "3 1 0", "3 0 1", "4 0 1", "4 1 1", "3 1 1"}) two += std::string("v ") + v + "\n";
  std::istringstream cube(kCube);
  std::string line;
  while (std::getline(cube, line))
    if (line.rfind("f ", 0) == 0) {
      std::istringstream f(line.substr(2));
      int a, b, c;
      f >> a >> b >> c;
      two += "f " + std::to_string(a + 9) + " " + std::to_string(b + 9) + " " + std::to_string(c + 9) + "\n";
    }
  const Mesh3 m = mesh_of(two);
  CHECK(m.shells == 2);
  CHECK(m.volume == 2);
  CHECK(m.notes.size() == 2);
}

// ------------------------------------------------------------------------------------------------------------------
// Bad input

TEST_CASE("bad .obj input is rejected naming the line", "[mesh]") {
  CHECK_THROWS_WITH(obj_of("v 0 0 x\n"), Contains("test.obj:1:") && Contains("coordinate 3"));
  CHECK_THROWS_WITH(obj_of("v 0 0\n"), Contains("test.obj:1:") && Contains("3 coordinates"));
  CHECK_THROWS_WITH(obj_of("v 0 0 0 2\n"), Contains("weight"));
  CHECK_THROWS_WITH(obj_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
                    Contains("test.obj:4:") && Contains("out of range"));
  CHECK_THROWS_WITH(obj_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n"), Contains("test.obj:4:") && Contains("start at 1"));
  CHECK_THROWS_WITH(obj_of("v 0 0 0\nf 1 -3 1\n"), Contains("test.obj:2:") && Contains("before the first"));
  CHECK_THROWS_WITH(obj_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 a 2\n"), Contains("test.obj:4:") && Contains("not an integer"));
  CHECK_THROWS_WITH(obj_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3 4\n"),
                    Contains("test.obj:5:") && Contains("only triangles"));
  CHECK_THROWS_WITH(obj_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1\n"), Contains("test.obj:4:") && Contains("appears twice"));
  CHECK_THROWS_WITH(obj_of("v 0 0 0\n"), Contains("no faces"));
  MeshReadLimits small;
  small.max_vertices = 2;
  std::istringstream three("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  CHECK_THROWS_WITH(read_obj(three, "x", small), Contains("x:3:") && Contains("limit"));
  CHECK_THROWS_WITH(read_obj_file("/nonexistent/file.obj"), Contains("cannot open"));
}

TEST_CASE("open, non-manifold and inconsistently oriented meshes are rejected", "[mesh]") {
  SECTION("open: the cube without its last face") {
    std::string open = kCube;
    open = open.substr(0, open.rfind("f 2 7 6"));
    CHECK_THROWS_WITH(mesh_of(open), Contains("not closed") && Contains("test.obj:") && Contains("edge ("));
  }
  SECTION("inconsistent orientation: one face of the cube reversed") {
    std::string bad = kCube;
    bad.replace(bad.find("f 1 4 3"), 7, "f 1 3 4");
    CHECK_THROWS_WITH(mesh_of(bad), Contains("inconsistent orientation") && Contains("test.obj:9:") &&
                                        Contains("edge (0, 2)") && Contains("line 10"));
  }
  SECTION("non-manifold edge: two tetrahedra sharing an edge") {
    const char* two_tets =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\nv 0 0 -1\n"
        "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
        "f 1 6 2\nf 1 2 5\nf 1 5 6\nf 2 6 5\n";
    CHECK_THROWS_WITH(mesh_of(two_tets), Contains("edge (0, 1)") && Contains("shared by 4 faces") &&
                                             Contains("not edge-manifold"));
  }
  SECTION("non-manifold vertex: two tetrahedra sharing a vertex") {
    const char* bowtie =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n"
        "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
        "f 1 6 5\nf 1 5 7\nf 1 7 6\nf 5 6 7\n";
    CHECK_THROWS_WITH(mesh_of(bowtie), Contains("vertex 0 (line 1)") && Contains("not vertex-manifold"));
  }
  SECTION("zero-area triangle") {
    const char* flat_face = "v 0 0 0\nv 2 0 0\nv 0 1 0\nv 1 0 0\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    CHECK_THROWS_WITH(mesh_of(flat_face), Contains("test.obj:6:") && Contains("zero-area"));
  }
  SECTION("zero volume: two triangles back to back") {
    CHECK_THROWS_WITH(mesh_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n"), Contains("zero volume"));
  }
  SECTION("faces folding back onto each other") {
    // A bipyramid over A B C whose apexes P and Q both lie in the plane y = 0 on the same side of A B.
    const char* fold =
        "v 0 0 0\nv 1 0 0\nv 0.5 1 0.2\nv 0.5 0 1\nv 0.5 0 0.5\n"
        "f 4 1 2\nf 4 2 3\nf 4 3 1\nf 5 2 1\nf 5 3 2\nf 5 1 3\n";
    CHECK_THROWS_WITH(mesh_of(fold), Contains("edge (0, 1)") && Contains("fold back"));
  }
}

TEST_CASE("bad .fea input is rejected naming the line", "[mesh]") {
  const Mesh3 cube = mesh_of(kCube);
  CHECK_THROWS_WITH(fea_of("3\n0 1\n1 2\n"), Contains("test.fea:1:") && Contains("count says 3") && Contains("lists 2"));
  CHECK_THROWS_WITH(fea_of("1\n0 1\n1 2\n"), Contains("test.fea:3:") && Contains("more feature edges"));
  CHECK_THROWS_WITH(fea_of("x\n"), Contains("test.fea:1:") && Contains("not a count"));
  CHECK_THROWS_WITH(fea_of("1 2\n"), Contains("test.fea:1:"));
  CHECK_THROWS_WITH(fea_of("1\n0 1 2\n"), Contains("test.fea:2:") && Contains("two vertex ids"));
  CHECK_THROWS_WITH(fea_of("1\n0 -1\n"), Contains("test.fea:2:") && Contains("0-based"));
  CHECK_THROWS_WITH(fea_of(""), Contains("empty"));
  CHECK_THROWS_WITH(resolve_feature_edges(cube, fea_of("2\n0 1\n0 8\n")),
                    Contains("test.fea:3:") && Contains("vertex id 8 out of range"));
  CHECK_THROWS_WITH(resolve_feature_edges(cube, fea_of("2\n0 1\n0 6\n")),
                    Contains("test.fea:3:") && Contains("(0, 6) is not an edge"));
  CHECK_THROWS_WITH(boundary_from_mesh(cube, std::vector<std::pair<int, int>>{{0, 6}}), Contains("entry 0"));
  // Entries joining a vertex to itself (as in NH-Rep's data) and repeated entries are accepted with notes.
  std::vector<std::string> notes;
  const auto marked = resolve_feature_edges(cube, fea_of("4\n0 1\n3 3\n1 0\n2 2\n"), &notes);
  CHECK(std::count(marked.begin(), marked.end(), 1) == 1);
  REQUIRE(notes.size() == 2);
  CHECK_THAT(notes[0], Contains("2 feature edges join a vertex to itself") && Contains("lines 3, 5"));
  CHECK_THAT(notes[1], Contains("repeat") && Contains("lines 4"));
}

// ------------------------------------------------------------------------------------------------------------------
// Sharpness

TEST_CASE("sharpness angle: domain and exact cos^2 at special angles", "[mesh]") {
  CHECK_THROWS_AS(SharpnessAngle(Rational(180)), InputError);
  CHECK_THROWS_AS(SharpnessAngle(frac(-1, 1000)), InputError);
  CHECK_NOTHROW(SharpnessAngle(q("179.999")));
  const std::map<int, Rational> exact = {{0, 1}, {30, frac(3, 4)}, {45, frac(1, 2)}, {60, frac(1, 4)},
                                         {90, 0}, {120, frac(1, 4)}, {135, frac(1, 2)}, {150, frac(3, 4)}};
  for (int d = 0; d < 180; ++d) {
    const SharpnessAngle s{Rational(d)};
    const auto it = exact.find(d);
    CHECK(s.exact_cos2().has_value() == (it != exact.end()));
    if (it != exact.end()) CHECK(*s.exact_cos2() == it->second);
    // The enclosure holds cos^2 (checked against long double) and is tight.
    const Interval e = s.cos2_enclosure(200);
    const long double c = std::cos(static_cast<long double>(d) * 3.14159265358979323846264338327950288L / 180);
    CHECK(e.lo_double() <= static_cast<double>(c * c) + 1e-15);
    CHECK(e.hi_double() >= static_cast<double>(c * c) - 1e-15);
    CHECK(e.width() < 1e-50);
  }
  CHECK_FALSE(SharpnessAngle(q("30.5")).exact_cos2().has_value());
}

TEST_CASE("sharpness angle on vectors at exact angles", "[mesh]") {
  const PointQ3 x{1, 1, 0};
  struct Case { PointQ3 other; int degrees; };
  const Case cases[] = {{{1, 1, 0}, 0},  {{1, 2, 1}, 30},   {{1, 0, 0}, 45},   {{0, 1, 1}, 60},
                        {{0, 0, 1}, 90}, {{0, -1, -1}, 120}, {{-1, 0, 0}, 135}, {{-1, -2, -1}, 150}};
  for (const Case& c : cases) {
    INFO("angle " << c.degrees);
    // theta < delta is smooth; theta = delta is sharp (NH-Rep: sharp iff deviation >= delta).
    CHECK_FALSE(SharpnessAngle(Rational(c.degrees)).closer_than(x, c.other));
    CHECK(SharpnessAngle(Rational(c.degrees) + frac(1, 10000)).closer_than(x, c.other));
    if (c.degrees > 0) CHECK_FALSE(SharpnessAngle(Rational(c.degrees) - frac(1, 10000)).closer_than(x, c.other));
  }
  // Scaling the vectors changes nothing.
  CHECK_FALSE(SharpnessAngle(Rational(60)).closer_than(PointQ3{3, 3, 0}, PointQ3{0, frac(1, 7), frac(1, 7)}));
  CHECK_THROWS(SharpnessAngle(Rational(30)).closer_than(PointQ3{0, 0, 0}, x));
}

TEST_CASE("sharpness angle: cube edges (90 degrees) and a 45/135-degree prism", "[mesh]") {
  const Mesh3 cube = mesh_of(kCube);
  const int box = edge_of(cube, 0, 1);
  CHECK(classify_edge(cube, box, SharpnessAngle(Rational(90))) == EdgeShape::Convex);
  CHECK(classify_edge(cube, box, SharpnessAngle(Rational(91))) == EdgeShape::Flat);
  CHECK(classify_edge(cube, box, SharpnessAngle(q("89.9999"))) == EdgeShape::Convex);
  CHECK(classify_edge(cube, box, SharpnessAngle(q("90.0001"))) == EdgeShape::Flat);
  CHECK(mesh_edge_type(cube, box, SharpnessAngle(Rational(91))) == FeatureType::Smooth);

  // Quadrilateral (0,0) (2,0) (3,1) (0,1): interior angle 135 at (2,0) (normals 45 degrees apart) and 45 at (3,1)
  // (normals 135 degrees apart); vertices 1 and 2, tops 5 and 6.
  const Mesh3 m = mesh_of(prism_obj({{0, 0}, {2, 0}, {3, 1}, {0, 1}}));
  const int e45 = edge_of(m, 1, 5), e135 = edge_of(m, 2, 6);
  CHECK(m.edges[static_cast<std::size_t>(e45)].shape == EdgeShape::Convex);
  CHECK(m.edges[static_cast<std::size_t>(e135)].shape == EdgeShape::Convex);
  CHECK(classify_edge(m, e45, SharpnessAngle(Rational(45))) == EdgeShape::Convex);
  CHECK(classify_edge(m, e45, SharpnessAngle(q("45.0001"))) == EdgeShape::Flat);
  CHECK(classify_edge(m, e45, SharpnessAngle(q("44.9999"))) == EdgeShape::Convex);
  CHECK(classify_edge(m, e135, SharpnessAngle(Rational(135))) == EdgeShape::Convex);
  CHECK(classify_edge(m, e135, SharpnessAngle(q("135.0001"))) == EdgeShape::Flat);
  CHECK(classify_edge(m, e135, SharpnessAngle(q("134.9999"))) == EdgeShape::Convex);
  CHECK(classify_edge(m, e135, SharpnessAngle(Rational(100))) == EdgeShape::Convex);
  CHECK(classify_edge(m, e45, SharpnessAngle(Rational(100))) == EdgeShape::Flat);
  // A flat edge (a cap diagonal) is smooth even at delta = 0.
  const int diagonal = edge_of(m, 0, 2);
  CHECK(m.edges[static_cast<std::size_t>(diagonal)].shape == EdgeShape::Flat);
  CHECK(classify_edge(m, diagonal, SharpnessAngle()) == EdgeShape::Flat);
}

TEST_CASE("sharpness angle: an edge 2^-300 away from 20 degrees needs refinement", "[mesh]") {
  // t_lo < tan(20 degrees) < t_hi, 2^-300 apart; the normals (1,0,0) and (1,t,0) make the angle atan(t), so
  // 128 bits cannot tell it from 20 degrees.
  const mpfr_prec_t p = 1200;
  const Interval angle = Interval(frac(20, 180), p) * Interval::pi(p);
  mpfr_t lo, hi;
  mpfr_inits2(p, lo, hi, static_cast<mpfr_ptr>(nullptr));
  mpfr_tan(lo, angle.lo(), MPFR_RNDD);
  mpfr_tan(hi, angle.hi(), MPFR_RNDU);
  mpfr_mul_2ui(lo, lo, 300, MPFR_RNDD);
  mpfr_mul_2ui(hi, hi, 300, MPFR_RNDU);
  mpfr_floor(lo, lo);
  mpfr_ceil(hi, hi);
  Rational t_lo, t_hi;
  mpfr_get_q(t_lo.get_mpq_t(), lo);
  mpfr_get_q(t_hi.get_mpq_t(), hi);
  mpfr_clears(lo, hi, static_cast<mpfr_ptr>(nullptr));
  t_lo /= Rational(Integer(1) << 300);
  t_hi /= Rational(Integer(1) << 300);
  REQUIRE(t_hi - t_lo <= make_rational(Integer(1), Integer(1) << 299));
  const SharpnessAngle s{Rational(20)};
  CHECK(s.closer_than(PointQ3{1, 0, 0}, PointQ3{1, t_lo, 0}));
  CHECK_FALSE(s.closer_than(PointQ3{1, 0, 0}, PointQ3{1, t_hi, 0}));
  // The same around 160 degrees (cos < 0): normals (1,0,0) and (-1,t,0) make angle 180 - atan(t).
  const SharpnessAngle s160{Rational(160)};
  CHECK_FALSE(s160.closer_than(PointQ3{1, 0, 0}, PointQ3{-1, t_lo, 0}));
  CHECK(s160.closer_than(PointQ3{1, 0, 0}, PointQ3{-1, t_hi, 0}));
}

// ------------------------------------------------------------------------------------------------------------------
// Properties on random meshes

namespace {

/// An octahedron whose six vertices are the axis points (+-10) moved by the given offsets (in [-8, 8]): closed and
/// manifold by construction, with convex, concave and occasionally flat edges.
std::string random_octahedron(const std::vector<int>& offsets) {
  static const int axis[6][3] = {{10, 0, 0}, {-10, 0, 0}, {0, 10, 0}, {0, -10, 0}, {0, 0, 10}, {0, 0, -10}};
  std::string out;
  for (int v = 0; v < 6; ++v) {
    out += "v";
    for (int k = 0; k < 3; ++k) out += " " + std::to_string(axis[v][k] + offsets[static_cast<std::size_t>(3 * v + k)]);
    out += "\n";
  }
  // 1-based: +x=1, -x=2, +y=3, -y=4, +z=5, -z=6; outward faces.
  out += "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
  return out;
}

/// Fisher-Yates with rapidcheck's choices (inside a property), so failures shrink.
template <typename T>
std::vector<T> shuffled(std::vector<T> v) {
  for (std::size_t i = v.size(); i > 1; --i)
    std::swap(v[i - 1], v[static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, i))]);
  return v;
}

rc::Gen<std::vector<int>> gen_offsets() { return rc::gen::container<std::vector<int>>(18, rc::gen::inRange(-8, 9)); }

/// The mesh, or nullopt when the random geometry is degenerate (zero-area triangle, fold, zero volume).
std::optional<Mesh3> try_mesh(const std::string& obj) {
  try {
    return mesh_of(obj);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

struct Oracle {
  long double det, theta_degrees;
};

Oracle oracle(const Mesh3& m, int edge) {
  auto ld = [](const Rational& r) { return static_cast<long double>(r.get_d()); };  // small integers: exact
  auto p = [&](int v) {
    const PointQ3& x = m.vertices[static_cast<std::size_t>(v)];
    return std::array<long double, 3>{ld(x.x), ld(x.y), ld(x.z)};
  };
  auto sub = [](std::array<long double, 3> a, std::array<long double, 3> b) {
    return std::array<long double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  auto cross = [](std::array<long double, 3> a, std::array<long double, 3> b) {
    return std::array<long double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto dot = [](std::array<long double, 3> a, std::array<long double, 3> b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const MeshEdge& e = m.edges[static_cast<std::size_t>(edge)];
  auto third = [&](int f) {
    for (int v : m.faces[static_cast<std::size_t>(f)])
      if (v != e.a && v != e.b) return v;
    return -1;
  };
  const auto u = p(e.a), v = p(e.b), w1 = p(third(e.face_ab)), w2 = p(third(e.face_ba));
  const auto n1 = cross(sub(v, u), sub(w1, u)), n2 = cross(sub(u, v), sub(w2, v));
  const long double det = dot(n1, sub(w2, u));
  const long double theta =
      std::atan2(std::sqrt(dot(cross(n1, n2), cross(n1, n2))), dot(n1, n2)) * 180 / 3.14159265358979323846264338327950288L;
  return {det, theta};
}

}  // namespace

TEST_CASE("properties: exact decisions agree with a long-double oracle away from the threshold", "[mesh][property]") {
  rc::prop("random octahedra", [] {
    const auto offsets = *gen_offsets();
    const int tenths = *rc::gen::inRange(0, 1800);
    const auto m = try_mesh(random_octahedron(offsets));
    RC_PRE(m.has_value());
    const SharpnessAngle s{frac(tenths, 10)};
    const long double delta = tenths / 10.0L;
    for (int e = 0; e < static_cast<int>(m->edges.size()); ++e) {
      const Oracle o = oracle(*m, e);
      const EdgeShape shape = m->edges[static_cast<std::size_t>(e)].shape;
      RC_ASSERT(shape == (o.det < 0 ? EdgeShape::Convex : o.det > 0 ? EdgeShape::Concave : EdgeShape::Flat));
      if (std::fabs(o.theta_degrees - delta) < 1e-9L) continue;  // too close for the oracle
      const bool smooth = shape == EdgeShape::Flat || o.theta_degrees < delta;
      RC_ASSERT((classify_edge(*m, e, s) == EdgeShape::Flat) == smooth);
    }
  });
  rc::prop("random vector pairs", [] {
    const auto c = *rc::gen::container<std::vector<int>>(6, rc::gen::inRange(-60, 61));
    const int hundredths = *rc::gen::inRange(0, 18000);
    const PointQ3 a{c[0], c[1], c[2]}, b{c[3], c[4], c[5]};
    RC_PRE(dot3(a, a) != 0 && dot3(b, b) != 0);
    const long double dot = static_cast<long double>(c[0]) * c[3] + static_cast<long double>(c[1]) * c[4] +
                            static_cast<long double>(c[2]) * c[5];
    const long double cx = static_cast<long double>(c[1]) * c[5] - static_cast<long double>(c[2]) * c[4];
    const long double cy = static_cast<long double>(c[2]) * c[3] - static_cast<long double>(c[0]) * c[5];
    const long double cz = static_cast<long double>(c[0]) * c[4] - static_cast<long double>(c[1]) * c[3];
    const long double theta =
        std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot) * 180 / 3.14159265358979323846264338327950288L;
    const long double delta = hundredths / 100.0L;
    RC_PRE(std::fabs(theta - delta) > 1e-9L);
    RC_ASSERT(SharpnessAngle(frac(hundredths, 100)).closer_than(a, b) == (theta < delta));
  });
}

TEST_CASE("properties: edge types do not depend on position or numbering", "[mesh][property]") {
  rc::prop("translation, vertex and face permutation, reversal", [] {
    const auto offsets = *gen_offsets();
    const std::string text = random_octahedron(offsets);
    const auto m = try_mesh(text);
    RC_PRE(m.has_value());
    const SharpnessAngle s{Rational(*rc::gen::inRange(0, 180))};
    auto types = [&](const Mesh3& x) {
      std::vector<EdgeShape> t;
      for (int e = 0; e < static_cast<int>(x.edges.size()); ++e) t.push_back(classify_edge(x, e, s));
      return t;
    };
    const auto base = types(*m);
    const ObjMesh obj = obj_of(text);

    // Translation by a rational vector.
    ObjMesh moved = obj;
    const Rational dx = frac(*rc::gen::inRange(-50, 50), 7), dy = frac(*rc::gen::inRange(-50, 50), 3),
                   dz(*rc::gen::inRange(-5, 5));
    for (auto& v : moved.vertices) v = PointQ3{v.x + dx, v.y + dy, v.z + dz};
    const Mesh3 mt = build_mesh3(moved);
    RC_ASSERT(types(mt) == base);
    RC_ASSERT(mt.volume == m->volume);

    // Vertex permutation: old vertex i becomes perm[i].
    std::vector<int> perm(6);
    std::iota(perm.begin(), perm.end(), 0);
    perm = shuffled(perm);
    ObjMesh renumbered = obj;
    for (int i = 0; i < 6; ++i) renumbered.vertices[static_cast<std::size_t>(perm[static_cast<std::size_t>(i)])] = obj.vertices[static_cast<std::size_t>(i)];
    for (auto& f : renumbered.faces)
      for (int& v : f) v = perm[static_cast<std::size_t>(v)];
    const Mesh3 mp = build_mesh3(renumbered);
    const auto tp = types(mp);
    for (std::size_t e = 0; e < m->edges.size(); ++e) {
      const int mapped = mp.find_edge(perm[static_cast<std::size_t>(m->edges[e].a)], perm[static_cast<std::size_t>(m->edges[e].b)]);
      RC_ASSERT(mapped >= 0);
      RC_ASSERT(tp[static_cast<std::size_t>(mapped)] == base[e]);
    }

    // Face permutation with each face's vertices rotated.
    ObjMesh reordered = obj;
    std::vector<std::size_t> order(obj.faces.size());
    std::iota(order.begin(), order.end(), 0);
    order = shuffled(order);
    for (std::size_t i = 0; i < order.size(); ++i) {
      auto f = obj.faces[order[i]];
      std::rotate(f.begin(), f.begin() + *rc::gen::inRange(0, 3), f.end());
      reordered.faces[i] = f;
    }
    RC_ASSERT(types(build_mesh3(reordered)) == base);

    // Reversed orientation is flipped back.
    ObjMesh reversed = obj;
    for (auto& f : reversed.faces) std::swap(f[1], f[2]);
    const Mesh3 mr = build_mesh3(reversed);
    RC_ASSERT(mr.flipped != m->flipped);
    RC_ASSERT(types(mr) == base);
  });
}

// ------------------------------------------------------------------------------------------------------------------
// The shared NH-Rep models (external data; skipped when absent)

namespace {

std::string shared_path(const std::string& name) { return std::string(HSX_SOURCE_DIR) + "/../shared/data/nhrep/" + name; }
bool have_shared() { return std::ifstream(shared_path("broken_bullet.obj")).good(); }

}  // namespace

TEST_CASE("the shared NH-Rep models are accepted as they are", "[mesh][shared]") {
  if (!have_shared()) {
    WARN("../shared/data/nhrep not found: skipped");
    return;
  }
  struct Expect { const char* name; std::size_t faces; int convex, concave, skipped; };
  // Counts from an independent exact computation (Python fractions) of the dihedral signs of the .fea edges.
  for (const Expect& x : {Expect{"00000006_0", 32664, 982, 22, 2}, Expect{"00007974_5", 15702, 804, 294, 4},
                          Expect{"broken_bullet", 3640, 107, 30, 0}}) {
    INFO(x.name);
    const Mesh3 m = read_mesh3_file(shared_path(std::string(x.name) + ".obj"));
    CHECK(m.faces.size() == x.faces);
    CHECK_FALSE(m.flipped);
    std::vector<std::string> notes;
    const BoundarySurface b = boundary_from_mesh(m, read_fea_file(shared_path(std::string(x.name) + ".fea")), 0, &notes);
    CHECK(check_boundary(b).empty());
    const auto t = feature_types(b);
    CHECK(t.count(FeatureType::Smooth) == 0);
    CHECK(t.at(FeatureType::Convex) == x.convex);
    CHECK(t.at(FeatureType::Concave) == x.concave);
    CHECK(notes.size() == (x.skipped ? 1u : 0u));
  }
  // The patches are NH-Rep's (its tool's face-patch files, patches numbered by lowest face index).
  for (const char* name : {"00000006_0", "broken_bullet"}) {
    INFO(name);
    const Mesh3 m = read_mesh3_file(shared_path(std::string(name) + ".obj"));
    const auto labels = patch_labels(boundary_from_mesh(m, read_fea_file(shared_path(std::string(name) + ".fea"))));
    std::ifstream ref(shared_path(std::string("reference/") + name + ".face-patch.txt"));
    std::vector<int> expected;
    for (int x; ref >> x;) expected.push_back(x);
    CHECK(labels == expected);
  }
  // broken_bullet.fea marks every edge whose dihedral angle exceeds 30 degrees: with delta = 30 the sharp edges are
  // exactly the marked ones.
  const Mesh3 bullet = read_mesh3_file(shared_path("broken_bullet.obj"));
  const BoundarySurface b = boundary_from_mesh(bullet, read_fea_file(shared_path("broken_bullet.fea")), 30);
  for (const auto& l : b.links) CHECK(l.feature == (l.type != FeatureType::Smooth));
}

// Measurements for the report, not a timed test: `test_mesh "[.measure]"` prints them.
TEST_CASE("measure the shared NH-Rep models", "[.measure]") {
  if (!have_shared()) return;
  for (const char* name : {"00000006_0", "00007974_5", "broken_bullet"}) {
    for (int delta : {0, 20}) {
      const auto t0 = std::chrono::steady_clock::now();
      ObjMesh obj = read_obj_file(shared_path(std::string(name) + ".obj"));
      const auto t1 = std::chrono::steady_clock::now();
      const Mesh3 m = build_mesh3(std::move(obj));
      const auto t2 = std::chrono::steady_clock::now();
      const FeatureEdgeList fea = read_fea_file(shared_path(std::string(name) + ".fea"));
      const BoundarySurface b = boundary_from_mesh(m, fea, delta);
      const auto t3 = std::chrono::steady_clock::now();
      auto ms = [](auto a, auto z) { return std::chrono::duration<double, std::milli>(z - a).count(); };
      const auto t = feature_types(b);
      auto get = [&](FeatureType k) { return t.count(k) ? t.at(k) : 0; };
      int all_convex = 0, all_concave = 0, all_smooth = 0;
      for (const auto& l : b.links)
        (l.type == FeatureType::Convex ? all_convex : l.type == FeatureType::Concave ? all_concave : all_smooth)++;
      std::cout << name << " delta=" << delta << ": V=" << m.vertices.size() << " F=" << m.faces.size()
                << " E=" << m.edges.size() << " shells=" << m.shells << " | read " << ms(t0, t1) << " ms, validate "
                << ms(t1, t2) << " ms, fea+classify " << ms(t2, t3) << " ms | patches " << patch_count(b)
                << " | feature edges convex " << get(FeatureType::Convex) << " concave " << get(FeatureType::Concave)
                << " smooth " << get(FeatureType::Smooth) << " | all edges convex " << all_convex << " concave "
                << all_concave << " smooth " << all_smooth << "\n";
    }
  }
}

namespace {

/// Boxes [lo, hi]^3 (outward, or reversed for a cavity) as .obj text, vertex ids continuing from `first`.
std::string box_obj(long lo, long hi, bool reversed, int first, std::string& faces) {
  std::string v;
  for (long z : {lo, hi})
    for (const auto& [x, y] : std::vector<std::pair<long, long>>{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}})
      v += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  // the unit cube's triangulation (data/meshes/cube.obj), vertex order 0..7 as above
  const int tris[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                           {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  for (const auto& t : tris) {
    const int a = first + t[0] + 1, b = first + (reversed ? t[2] : t[1]) + 1, c = first + (reversed ? t[1] : t[2]) + 1;
    faces += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
  }
  return v;
}

}  // namespace

TEST_CASE("point in mesh: exact ray parity agrees with the box test, on the surface too", "[mesh][property]") {
  std::string faces;
  const Mesh3 cube = mesh_of(box_obj(0, 3, false, 0, faces) + faces);
  std::vector<int> all(cube.faces.size());
  std::iota(all.begin(), all.end(), 0);
  // Points on a grid of halves around the box: many lie on face planes, edge lines and vertex rays.
  rc::prop("agrees with 0 < x, y, z < 3", [&] {
    const auto c = *rc::gen::container<std::vector<int>>(3, rc::gen::inRange(-3, 10));
    const PointQ3 p{Rational(c[0], 2), Rational(c[1], 2), Rational(c[2], 2)};
    const std::optional<bool> inside = point_inside_faces(cube, all, p);
    auto in = [](int v) { return v > 0 && v < 6; };
    auto on = [](int v) { return v == 0 || v == 6; };
    const bool strictly = in(c[0]) && in(c[1]) && in(c[2]);
    const bool closed = (in(c[0]) || on(c[0])) && (in(c[1]) || on(c[1])) && (in(c[2]) || on(c[2]));
    if (closed && !strictly)
      RC_ASSERT(!inside.has_value());
    else
      RC_ASSERT(inside.has_value() && *inside == strictly);
  });
}

TEST_CASE("nesting: cavities belong to the smallest outer shell around them", "[mesh]") {
  // A box [0,9]^3 with a cavity [1,8]^3 holding an island box [2,7]^3 with its own cavity [3,6]^3; beside it a
  // separate box [20,23]^3 with a cavity [21,22]^3.
  std::string faces, verts;
  int first = 0;
  const std::vector<std::tuple<long, long, bool>> boxes{{0, 9, false}, {1, 8, true}, {2, 7, false},
                                                        {3, 6, true}, {20, 23, false}, {21, 22, true}};
  for (const auto& [lo, hi, cavity] : boxes) {
    verts += box_obj(lo, hi, cavity, first, faces);
    first += 8;
  }
  const Mesh3 m = mesh_of(verts + faces);
  REQUIRE(m.shells == 6);
  const BoundarySurface s = boundary_from_mesh(m, std::vector<std::pair<int, int>>{});
  // pieces 12k..12k+11 are box k; outer shells are numbered 0, 1, 2 (boxes 0, 2, 4)
  auto region = [&](int box) { return s.pieces[static_cast<std::size_t>(12 * box)].region; };
  auto hole = [&](int box) { return s.pieces[static_cast<std::size_t>(12 * box)].hole; };
  CHECK((region(0) == 0 && !hole(0)));
  CHECK((region(1) == 0 && hole(1)));
  CHECK((region(2) == 1 && !hole(2)));
  CHECK((region(3) == 1 && hole(3)));
  CHECK((region(4) == 2 && !hole(4)));
  CHECK((region(5) == 2 && hole(5)));
}

TEST_CASE("nesting: a flat shell (zero volume) is neither outer nor a cavity: its part is unknown", "[mesh]") {
  // fuzz_mesh's finding (data/crashes/mesh/nest-two-outer-components): a box [0,3]^3 and, inside it, a closed
  // shell whose eight vertices were mangled so that it encloses no volume. It used to be filed as an outer shell
  // of the box's part, and --nest-holes then failed its "one outer boundary per part" check as an internal error.
  const Mesh3 m = build_mesh3(read_obj_file(std::string(HSX_SOURCE_DIR) + "/data/crashes/mesh/nest-two-outer-components"));
  REQUIRE(m.shells == 2);
  const BoundarySurface s = boundary_from_mesh(m, std::vector<std::pair<int, int>>{});
  CHECK((s.pieces[0].region == 0 && !s.pieces[0].hole));
  CHECK((s.pieces[12].region == -1 && !s.pieces[12].hole));
}

TEST_CASE("properties: outer shells are numbered by lowest triangle, whatever the face order", "[mesh][property]") {
  // Separate boxes [10k, 10k+3]^3 with their triangles listed in a random order: box k's pieces must all get the
  // region that is the rank of box k's lowest triangle among the boxes' lowest triangles.
  rc::prop("regions follow the lowest triangles", [] {
    const int boxes = *rc::gen::inRange(2, 5);
    std::string verts, box_faces;
    for (int k = 0; k < boxes; ++k) verts += box_obj(10L * k, 10L * k + 3, false, 8 * k, box_faces);
    std::vector<std::string> lines;
    std::istringstream in(box_faces);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    const auto order = *rc::gen::container<std::vector<int>>(lines.size(), rc::gen::arbitrary<int>());
    std::vector<int> perm(lines.size());  // output position -> input face (12k..12k+11 is box k)
    std::iota(perm.begin(), perm.end(), 0);
    std::stable_sort(perm.begin(), perm.end(), [&](int a, int b) { return order[a] < order[b]; });
    std::string faces;
    for (int f : perm) faces += lines[static_cast<std::size_t>(f)] + "\n";
    const Mesh3 m = mesh_of(verts + faces);
    RC_ASSERT(m.shells == boxes);
    const BoundarySurface s = boundary_from_mesh(m, std::vector<std::pair<int, int>>{});
    std::vector<int> lowest(static_cast<std::size_t>(boxes), -1);  // per box its lowest triangle
    for (std::size_t f = perm.size(); f-- > 0;) lowest[static_cast<std::size_t>(perm[f] / 12)] = static_cast<int>(f);
    for (std::size_t f = 0; f < perm.size(); ++f) {
      const int box = perm[f] / 12;
      const auto rank = std::count_if(lowest.begin(), lowest.end(), [&](int l) { return l < lowest[box]; });
      RC_ASSERT(s.pieces[f].region == static_cast<int>(rank));
      RC_ASSERT(!s.pieces[f].hole);
    }
  });
}
