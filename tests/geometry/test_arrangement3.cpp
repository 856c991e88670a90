#include <hsx/geometry/arrangement3.hpp>

#include "geometry/scenes3.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <map>
#include <random>

using namespace hsx;
using namespace hsx::test3;

namespace {

/// Checks usable both in Catch test cases and in rapidcheck properties: a failure throws, naming the condition.
#define EXPECT3(cond) \
  do { \
    if (!(cond)) throw std::runtime_error(std::string("check failed at line ") + std::to_string(__LINE__) + ": " #cond); \
  } while (0)

long choose(long n, long k) {
  long r = 1;
  for (long i = 0; i < k; ++i) r = r * (n - i) / (i + 1);
  return r;
}

Rational box_volume(const Box3& b) { return (b.max.x - b.min.x) * (b.max.y - b.min.y) * (b.max.z - b.min.z); }

/// Every invariant of an arrangement that needs no reference: volumes sum to the box, cells on either side of a
/// triangle differ exactly in its halfspaces (on the right sides), witnesses classify directly as their sides,
/// edges are closed (>= 2 triangles).
void check_invariants(const Scene3& scene, const Arrangement3& arr) {
  Rational total;
  for (const ArrCell3& c : arr.cells()) {
    EXPECT3(c.volume);
    EXPECT3(*c.volume > 0);
    total += *c.volume;
    for (std::size_t h = 0; h < scene.halfspaces.size(); ++h)
      EXPECT3(direct_side(scene.halfspaces[h], c.interior) == (c.inside[h] ? 1 : -1));
    EXPECT3(arr.locate(c.interior).kind == PointLocation3::Cell);
    EXPECT3(arr.locate(c.interior).index >= 0);
  }
  EXPECT3(total == box_volume(scene.domain));
  for (std::size_t c = 0; c < arr.cells().size(); ++c)
    EXPECT3(arr.locate(arr.cells()[c].interior).index == static_cast<int>(c));
  for (const ArrTriangle3& t : arr.triangles()) {
    if (t.on_box) EXPECT3((t.front_cell < 0) != (t.back_cell < 0));
    if (t.front_cell < 0 || t.back_cell < 0) continue;
    for (int h = 0; h < arr.halfspace_count(); ++h) {
      const auto it = std::find(t.halfspaces.begin(), t.halfspaces.end(), h);
      const char f = arr.cells()[t.front_cell].inside[h], b = arr.cells()[t.back_cell].inside[h];
      if (it == t.halfspaces.end()) EXPECT3(f == b);
      else EXPECT3((f == t.front_inside[it - t.halfspaces.begin()] && b != f));
    }
  }
  for (const ArrEdge3& e : arr.edges()) EXPECT3(e.triangles.size() >= 2);
}

/// Random rational points in the box located, against direct classification.
void check_random_points(const Scene3& scene, const Arrangement3& arr, int count) {
  const Box3& b = scene.domain;
  std::mt19937 engine(static_cast<unsigned>(*rc::gen::inRange(0, 1 << 30)));
  for (int k = 0; k < count; ++k) {
    auto r = [&engine](const Rational& lo, const Rational& hi) -> Rational {
      Rational f(std::uniform_int_distribution<int>(1, 999)(engine), 1000);
      f.canonicalize();  // mpq_class(n, d) is not canonical, and exact equality needs canonical operands
      return lo + (hi - lo) * f;
    };
    const PointQ3 p = {r(b.min.x, b.max.x), r(b.min.y, b.max.y), r(b.min.z, b.max.z)};
    const PointLocation3 loc = arr.locate(p);
    bool on_boundary = false;
    for (const auto& h : scene.halfspaces) on_boundary = on_boundary || direct_side(h, p) == 0;
    if (on_boundary) {
      EXPECT3(loc.kind != PointLocation3::Cell);
      continue;
    }
    EXPECT3(loc.kind == PointLocation3::Cell);
    EXPECT3(loc.index >= 0);
    for (std::size_t h = 0; h < scene.halfspaces.size(); ++h)
      EXPECT3(arr.cells()[static_cast<std::size_t>(loc.index)].inside[h] == (direct_side(scene.halfspaces[h], p) > 0 ? 1 : 0));
  }
}

/// The cells as a sorted list of (sides, volume, outer), for comparisons up to renaming.
std::vector<std::tuple<std::vector<char>, Rational, bool>> cell_signature(const Arrangement3& arr,
                                                                         const std::vector<int>& order) {
  std::vector<std::tuple<std::vector<char>, Rational, bool>> out;
  for (const ArrCell3& c : arr.cells()) {
    std::vector<char> sides;
    for (int h : order) sides.push_back(c.inside[static_cast<std::size_t>(h)]);
    out.emplace_back(sides, *c.volume, c.outer);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> identity(int n) {
  std::vector<int> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = i;
  return v;
}

Box3 cube(const Rational& lo, const Rational& hi) { return {{lo, lo, lo}, {hi, hi, hi}}; }

}  // namespace

TEST_CASE("arrangement3: one plane through the box") {
  const Scene3 scene = scene_of(cube(-1, 1), {plane("A", {1, 1, 0}, 0)});
  const Arrangement3 arr = Arrangement3::build(scene);
  REQUIRE(arr.cells().size() == 2);
  check_invariants(scene, arr);
  for (const auto& c : arr.cells()) REQUIRE(*c.volume == 4);
}

TEST_CASE("arrangement3: random planes in general position give 1 + n + C(n,2) + C(n,3) cells") {
  rc::prop("cell count and invariants", [] {
    const int n = *rc::gen::inRange(3, 7);  // from 3 on, every line of the arrangement holds a triple point
    const Scene3 scene = random_planes(n, 3, *rc::gen::inRange(0, 1 << 30));
    const Arrangement3 arr = Arrangement3::build(scene);
    RC_ASSERT(static_cast<long>(arr.cells().size()) == 1 + n + choose(n, 2) + choose(n, 3));
    check_invariants(scene, arr);
    check_random_points(scene, arr, 10);
  });
}

TEST_CASE("arrangement3: the result does not depend on the thread count") {
  rc::prop("threads 1 and 2", [] {
    const Scene3 scene = random_planes(*rc::gen::inRange(3, 6), 3, *rc::gen::inRange(0, 1 << 30));
    Arrangement3Options one, two;
    one.threads = 1;
    two.threads = 2;
    const Arrangement3 a = Arrangement3::build(scene, {}, one), b = Arrangement3::build(scene, {}, two);
    RC_ASSERT(a.vertices() == b.vertices());
    RC_ASSERT(a.triangles().size() == b.triangles().size());
    for (std::size_t t = 0; t < a.triangles().size(); ++t) {
      RC_ASSERT(a.triangles()[t].vertices == b.triangles()[t].vertices);
      RC_ASSERT(a.triangles()[t].front_cell == b.triangles()[t].front_cell);
    }
  });
}

TEST_CASE("arrangement3: the same complex after permuting, translating and rotating") {
  rc::prop("renaming invariance", [] {
    const int n = *rc::gen::inRange(3, 6);
    const Scene3 scene = random_planes(n, 3, *rc::gen::inRange(0, 1 << 30));
    const Arrangement3 arr = Arrangement3::build(scene);
    // permuted
    std::vector<int> perm = identity(n);
    std::reverse(perm.begin(), perm.end());
    std::rotate(perm.begin(), perm.begin() + *rc::gen::inRange(0, n), perm.end());  // any rotation of a reversal
    Scene3 permuted = scene;
    for (int i = 0; i < n; ++i) permuted.halfspaces[static_cast<std::size_t>(i)] = scene.halfspaces[static_cast<std::size_t>(perm[i])];
    std::vector<int> inverse(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) inverse[static_cast<std::size_t>(perm[i])] = i;
    RC_ASSERT(cell_signature(Arrangement3::build(permuted), inverse) == cell_signature(arr, identity(n)));
    // translated by an integer vector
    const PointQ3 v = {*rc::gen::inRange(-5, 6), *rc::gen::inRange(-5, 6), *rc::gen::inRange(-5, 6)};
    Scene3 moved = scene;
    moved.domain = {add(scene.domain.min, v), add(scene.domain.max, v)};
    for (auto& h : moved.halfspaces) h.offset += dot(h.normal, v);
    RC_ASSERT(cell_signature(Arrangement3::build(moved), identity(n)) == cell_signature(arr, identity(n)));
    // rotated by 90 degrees about z: (x, y, z) -> (-y, x, z)
    auto rot = [](const PointQ3& p) { return PointQ3{-p.y, p.x, p.z}; };
    Scene3 turned = scene;
    turned.domain = {{-scene.domain.max.y, scene.domain.min.x, scene.domain.min.z},
                     {-scene.domain.min.y, scene.domain.max.x, scene.domain.max.z}};
    for (auto& h : turned.halfspaces) h.normal = rot(h.normal);
    RC_ASSERT(cell_signature(Arrangement3::build(turned), identity(n)) == cell_signature(arr, identity(n)));
  });
}

TEST_CASE("arrangement3: the same plane twice, in both orientations") {
  for (bool complement : {false, true}) {
    const Scene3 scene = scene_of(cube(-2, 2), {plane("A", {1, 2, 0}, 1), plane("B", {-1, -2, 0}, -1, complement),
                                                plane("C", {0, 0, 1}, 0)});
    const Arrangement3 arr = Arrangement3::build(scene);
    REQUIRE(arr.cells().size() == 4);
    check_invariants(scene, arr);
    int shared = 0;
    for (const auto& t : arr.triangles())
      if (t.halfspaces.size() == 2) ++shared;
    REQUIRE(shared > 0);
  }
}

TEST_CASE("arrangement3: a plane on the domain's face") {
  const Scene3 scene = scene_of(cube(0, 2), {plane("A", {0, 0, 1}, 2), plane("B", {1, 0, 0}, 1)});
  const Arrangement3 arr = Arrangement3::build(scene);
  REQUIRE(arr.cells().size() == 2);
  check_invariants(scene, arr);
  for (const auto& c : arr.cells()) REQUIRE(c.inside[0] == 1);
  bool carried = false;
  for (const auto& t : arr.triangles()) carried = carried || (t.on_box && t.halfspaces == std::vector<int>{0});
  REQUIRE(carried);
}

TEST_CASE("arrangement3: boxes with coincident faces, a box face on a plane") {
  const Scene3 touching = scene_of(cube(-1, 5), {surface("A", box_surface({0, 0, 0}, {2, 2, 2})),
                                                 surface("B", box_surface({2, 0, 0}, {4, 2, 2}))});
  const Arrangement3 a = Arrangement3::build(touching);
  REQUIRE(a.cells().size() == 3);
  check_invariants(touching, a);
  const Scene3 on_plane = scene_of(cube(-1, 3), {surface("A", box_surface({0, 0, 0}, {2, 2, 2})),
                                                 plane("P", {0, 0, 1}, 2, true)});
  const Arrangement3 b = Arrangement3::build(on_plane);
  REQUIRE(b.cells().size() == 3);
  check_invariants(on_plane, b);
  const Scene3 overlapping = scene_of(cube(-1, 5), {surface("A", box_surface({0, 0, 0}, {2, 2, 2})),
                                                    surface("B", box_surface({1, 0, 1}, {3, 2, 3}))});
  const Arrangement3 c = Arrangement3::build(overlapping);
  REQUIRE(c.cells().size() == 4);
  check_invariants(overlapping, c);
}

TEST_CASE("arrangement3: a plane through mesh vertices and along mesh edges") {
  const Scene3 scene = scene_of(cube(-2, 2), {surface("O", octahedron({0, 0, 0}, 1)), plane("Z", {0, 0, 1}, 0),
                                              plane("X", {1, 0, 0}, 0)});
  const Arrangement3 arr = Arrangement3::build(scene);
  REQUIRE(arr.cells().size() == 8);
  check_invariants(scene, arr);
}

TEST_CASE("arrangement3: a cavity and floating components") {
  // A hollow box: the outer box, and inside it a complemented inner box (a cavity).
  const Scene3 hollow = scene_of(cube(-1, 5), {surface("A", box_surface({0, 0, 0}, {4, 4, 4})),
                                               surface("B", box_surface({1, 1, 1}, {3, 3, 3}), true)});
  const Arrangement3 a = Arrangement3::build(hollow);
  REQUIRE(a.cells().size() == 3);
  check_invariants(hollow, a);
  std::vector<Rational> volumes;
  for (const auto& c : a.cells()) volumes.push_back(*c.volume);
  std::sort(volumes.begin(), volumes.end());
  REQUIRE(volumes == std::vector<Rational>{8, 56, 216 - 64});
  // two floating tetrahedra, one inside a floating octahedron
  const Scene3 floating = scene_of(cube(-4, 4), {surface("T", tetrahedron({2, 2, 2}, {3, 2, 2}, {2, 3, 2}, {2, 2, 3})),
                                                 surface("O", octahedron({0, 0, 0}, 2)),
                                                 surface("U", tetrahedron({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}))});
  const Arrangement3 b = Arrangement3::build(floating);
  REQUIRE(b.cells().size() == 4);
  check_invariants(floating, b);
  for (const auto& c : b.cells()) REQUIRE(c.outer == (c.inside == std::vector<char>{0, 0, 0}));
}

TEST_CASE("arrangement3: samples on patches, refused on edges where boundaries meet") {
  Scene3 scene = scene_of(cube(-2, 2), {surface("A", box_surface({-1, -1, -1}, {1, 1, 1})), plane("P", {0, 0, 1}, 0)});
  Sample3 s;
  s.halfspace = 0;
  s.given = s.location = {Rational(1, 2), Rational(1, 3), 1};
  scene.samples.push_back(s);
  const Arrangement3 arr = Arrangement3::build(scene);
  const ArrTriangle3& t = arr.triangles()[static_cast<std::size_t>(arr.sample_triangles()[0])];
  REQUIRE(t.halfspaces == std::vector<int>{0});
  scene.samples[0].location = scene.samples[0].given = {1, Rational(1, 3), 0};  // where P crosses A
  REQUIRE_THROWS_AS(Arrangement3::build(scene), InputError);
  scene.samples[0].location = scene.samples[0].given = {Rational(1, 2), Rational(1, 2), 1};  // A's face diagonal
  REQUIRE_NOTHROW(Arrangement3::build(scene));
  // On P outside A, on the line of an edge where P crosses A (x = 1): inside a patch of P. A triangle of P whose
  // edge's line passes through the sample but which does not hold it says nothing (it refused such samples once:
  // campaign 3D seed 1, scene 4264).
  scene.samples[0].halfspace = 1;
  scene.samples[0].location = scene.samples[0].given = {1, Rational(3, 2), 0};
  const Arrangement3 on_p = Arrangement3::build(scene);
  CHECK(on_p.triangles()[static_cast<std::size_t>(on_p.sample_triangles()[0])].halfspaces == std::vector<int>{1});
  scene.samples[0].location = scene.samples[0].given = {1, Rational(1, 2), 0};  // on that edge: refused
  REQUIRE_THROWS_AS(Arrangement3::build(scene), InputError);
}

TEST_CASE("arrangement3: a surface that intersects itself is refused, naming its triangles") {
  TriangleSurface two = tetrahedron({0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2});
  const TriangleSurface other = tetrahedron({Rational(1, 2), Rational(1, 2), Rational(1, 2)}, {3, 1, 1}, {1, 3, 1}, {1, 1, 3});
  for (const auto& t : other.triangles) two.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  two.vertices.insert(two.vertices.end(), other.vertices.begin(), other.vertices.end());
  const Scene3 scene = scene_of(cube(-1, 4), {surface("S", two)});
  REQUIRE_THROWS_WITH(Arrangement3::build(scene), Catch::Contains("halfspaces[0] (\"S\")") &&
                                                      Catch::Contains("intersects itself") &&
                                                      Catch::Contains("triangles"));
}

namespace {

/// Axis boxes as one surface (several shells of one mesh), vertices not shared between boxes.
TriangleSurface boxes_surface(const std::vector<std::pair<PointQ3, PointQ3>>& boxes) {
  TriangleSurface out;
  for (const auto& [lo, hi] : boxes) {
    const TriangleSurface b = box_surface(lo, hi);
    const int base = static_cast<int>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (const auto& t : b.triangles) out.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  return out;
}

}  // namespace

// Two boxes of one mesh whose faces lie in common planes: overlapping over an area (face to face, or part of a face),
// or touching along part of an edge inside a common plane. Every such contact is refused; the reason is in
// proofs/arrangement3.md (Claim 1.3): an area overlap leaves a refined triangle covered twice by the surface, and a
// partial edge contact leaves a non-coplanar pair of the surface meeting along a segment that is not a shared edge.
// Boxes of one mesh meeting at a shared corner or along a whole shared edge are a valid (non-manifold) solid.
TEST_CASE("arrangement3: a surface overlapping itself inside a plane is refused, naming two of its triangles") {
  const Rational h(1, 2);
  const std::vector<std::pair<const char*, std::vector<std::pair<PointQ3, PointQ3>>>> refused = {
      {"face to face", {{{0, 0, 0}, {1, 1, 1}}, {{1, 0, 0}, {2, 1, 1}}}},
      {"part of a face", {{{0, 0, 0}, {1, 1, 1}}, {{1, h, 0}, {2, 1 + h, 1}}}},
      {"inside a plane, along part of an edge", {{{0, 0, 0}, {1, 1, 1}}, {{1, 1, 0}, {2, 2, 2}}}},
      {"along part of an edge, out of every common plane", {{{0, 0, 0}, {1, 1, 1}}, {{1, 1, h}, {2, 2, 1 + h}}}},
      {"a box inside another, sharing three faces", {{{0, 0, 0}, {2, 2, 2}}, {{0, 0, 0}, {1, 1, 1}}}}};
  for (const auto& [what, boxes] : refused) {
    INFO(what);
    const Scene3 scene = scene_of(cube(-3, 3), {plane("P", {1, 1, 1}, -7), surface("M", boxes_surface(boxes))});
    REQUIRE_THROWS_AS(Arrangement3::build(scene), InputError);
    REQUIRE_THROWS_WITH(Arrangement3::build(scene), Catch::StartsWith("halfspaces[1] (\"M\"): the surface intersects "
                                                                      "itself: its triangles ") &&
                                                        (Catch::EndsWith(" meet") || Catch::EndsWith(" overlap")));
  }
  for (const auto& [what, boxes] : std::vector<std::pair<const char*, std::vector<std::pair<PointQ3, PointQ3>>>>{
           {"at a shared corner", {{{0, 0, 0}, {1, 1, 1}}, {{1, 1, 1}, {2, 2, 2}}}},
           {"along a whole shared edge", {{{0, 0, 0}, {1, 1, 1}}, {{1, 1, 0}, {2, 2, 1}}}}}) {
    INFO(what);
    const Scene3 scene = scene_of(cube(-3, 3), {surface("M", boxes_surface(boxes))});
    const Arrangement3 arr = Arrangement3::build(scene);
    REQUIRE(arr.cells().size() == 3);
    check_invariants(scene, arr);
  }
}

// locate (an AABB tree of the triangles, exact ray shooting) against direct classification of random rational
// points, and on the arrangement's own vertices, edge midpoints and triangle centroids.
TEST_CASE("arrangement3: locate agrees with direct classification and names vertices, edges and triangles") {
  const Scene3 scene =
      scene_of(cube(-3, 3), {surface("O", octahedron({0, 0, 0}, 2)), surface("A", box_surface({-1, -1, -1}, {1, 1, 2})),
                             plane("P", {1, 2, -1}, Rational(1, 2)), plane("Q", {0, 0, 1}, 0, true),
                             surface("T", tetrahedron({1, 1, 1}, {3, 1, 1}, {1, 3, 1}, {1, 1, 3}))});
  const Arrangement3 arr = Arrangement3::build(scene);
  std::mt19937 engine(12);
  auto coordinate = [&engine] {
    const int den = std::uniform_int_distribution<int>(1, 3)(engine) * 500;  // in [-3, 3]
    Rational q(std::uniform_int_distribution<int>(-3 * den, 3 * den)(engine), den);
    q.canonicalize();
    return q;
  };
  int in_cells = 0, on_boundary = 0;
  for (int k = 0; k < 2000; ++k) {
    const PointQ3 p = {coordinate(), coordinate(), coordinate()};
    const PointLocation3 loc = arr.locate(p);
    bool boundary = false;
    for (const auto& h : scene.halfspaces) boundary = boundary || direct_side(h, p) == 0;
    const bool on_box = p.x == -3 || p.x == 3 || p.y == -3 || p.y == 3 || p.z == -3 || p.z == 3;
    if (boundary || on_box) {
      ++on_boundary;
      REQUIRE(loc.kind != PointLocation3::Cell);
      continue;
    }
    ++in_cells;
    REQUIRE(loc.kind == PointLocation3::Cell);
    for (std::size_t h = 0; h < scene.halfspaces.size(); ++h)
      REQUIRE(arr.cells()[static_cast<std::size_t>(loc.index)].inside[h] == (direct_side(scene.halfspaces[h], p) > 0 ? 1 : 0));
  }
  CHECK(in_cells > 1500);
  CHECK(on_boundary > 3);  // the grid of coordinates puts points on the planes, the box and the mesh faces
  for (int v = 0; v < static_cast<int>(arr.vertices().size()); ++v) {
    const PointLocation3 loc = arr.locate(arr.vertices()[static_cast<std::size_t>(v)]);
    REQUIRE(loc.kind == PointLocation3::Vertex);
    REQUIRE(loc.index == v);
  }
  for (int e = 0; e < static_cast<int>(arr.edges().size()); ++e) {
    const ArrEdge3& edge = arr.edges()[static_cast<std::size_t>(e)];
    const PointQ3 mid = add(arr.vertices()[static_cast<std::size_t>(edge.a)], arr.vertices()[static_cast<std::size_t>(edge.b)]);
    const PointLocation3 loc = arr.locate({mid.x / 2, mid.y / 2, mid.z / 2});
    REQUIRE(loc.kind == PointLocation3::Edge);
    REQUIRE(loc.index == e);
  }
  for (int t = 0; t < static_cast<int>(arr.triangles().size()); ++t) {
    const auto& v = arr.triangles()[static_cast<std::size_t>(t)].vertices;
    const PointQ3 sum = add(add(arr.vertices()[static_cast<std::size_t>(v[0])], arr.vertices()[static_cast<std::size_t>(v[1])]),
                            arr.vertices()[static_cast<std::size_t>(v[2])]);
    const PointLocation3 loc = arr.locate({sum.x / 3, sum.y / 3, sum.z / 3});
    REQUIRE(loc.kind == PointLocation3::Triangle);
    REQUIRE(loc.index == t);
  }
  REQUIRE(arr.locate({4, 0, 0}).kind == PointLocation3::Outside);
}

TEST_CASE("arrangement3: limits") {
  const Scene3 scene = scene_of(cube(-4, 4), {plane("A", {1, 0, 0}, 0), plane("B", {0, 1, 0}, 0),
                                              plane("C", {0, 0, 1}, 0), plane("D", {1, 1, 1}, 1)});
  ArrangementLimits limits;
  limits.max_cells = 5;
  REQUIRE_THROWS_WITH(Arrangement3::build(scene, limits), Catch::Contains("--max-cells"));
  limits = {};
  limits.max_triangles = 10;
  REQUIRE_THROWS_WITH(Arrangement3::build(scene, limits), Catch::Contains("triangles"));
  // A surface of more triangles than the limit is refused before the refinement; one of exactly as many is not.
  const Scene3 boxed = scene_of(cube(-4, 4), {surface("B", box_surface({-1, -1, -1}, {1, 1, 1}))});
  limits.max_triangles = 11;
  REQUIRE_THROWS_WITH(Arrangement3::build(boxed, limits),
                      Catch::Contains("(\"B\") has 12 triangles, so the arrangement has at least as many"));
  limits.max_triangles = 12 + 12;  // the box surface's 12 and the domain box's 12 (two per face)
  REQUIRE(Arrangement3::build(boxed, limits).cells().size() == 2);
  // Two apart are refused before the refinement too, by the sum over planes; the same box given twice is not (the
  // copies share their refined triangles).
  const Scene3 two = scene_of(cube(-4, 4), {surface("B", box_surface({-3, -3, -3}, {-1, -1, -1})),
                                            surface("C", box_surface({1, 1, 1}, {3, 3, 3}))});
  limits.max_triangles = 35;
  REQUIRE_THROWS_WITH(Arrangement3::build(two, limits),
                      Catch::Contains("the arrangement has at least 36 triangles, over the limit of 35"));
  limits.max_triangles = 36;
  REQUIRE(Arrangement3::build(two, limits).triangles().size() == 36);
  const Scene3 twice = scene_of(cube(-4, 4), {surface("B", box_surface({-1, -1, -1}, {1, 1, 1})),
                                              surface("C", box_surface({-1, -1, -1}, {1, 1, 1}))});
  limits.max_triangles = 24;
  REQUIRE(Arrangement3::build(twice, limits).triangles().size() == 24);
}

TEST_CASE("arrangement3: the lower bound on the cells checked before refinement is exact in general position") {
  rc::prop("a limit one below the cells is refused before refinement, naming the count", [] {
    const int n = *rc::gen::inRange(3, 9);
    const Scene3 scene = random_planes(n, 3, *rc::gen::inRange(0, 1 << 30));
    const long cells = 1 + n + choose(n, 2) + choose(n, 3);
    ArrangementLimits limits;
    limits.max_cells = cells - 1;
    try {
      Arrangement3::build(scene, limits);
      RC_FAIL("built over the limit");
    } catch (const InputError& e) {
      RC_ASSERT(std::string(e.what()).find("has at least " + std::to_string(cells) + " cells") != std::string::npos);
    }
    limits.max_cells = cells;
    RC_ASSERT(static_cast<long>(Arrangement3::build(scene, limits).cells().size()) == cells);
  });
}

TEST_CASE("arrangement3: the lower bounds on the cells and triangles never refuse a scene within the limits") {
  // Small integer planes: parallel, coincident and concurrent planes, corners and lines on the domain's faces; and
  // box surfaces, which only add cells.
  rc::prop("building with limits equal to the cells and the side entries succeeds", [] {
    const int n = *rc::gen::inRange(0, 8);
    std::vector<Halfspace3> halfspaces;
    for (int k = 0; k < n; ++k) {
      PointQ3 normal = {*rc::gen::inRange(-2, 3), *rc::gen::inRange(-2, 3), *rc::gen::inRange(-2, 3)};
      if (normal == PointQ3{0, 0, 0}) normal.z = 1;
      halfspaces.push_back(plane("P" + std::to_string(k), normal, *rc::gen::inRange(-3, 4)));
    }
    // Box surfaces with integer corners: overlapping, coincident, or on the domain's faces.
    for (const char* name : {"B", "C"})
      if (name[0] == 'C' && halfspaces.size() == static_cast<std::size_t>(n) + 1 && *rc::gen::inRange(0, 3) == 0) {
        halfspaces.push_back(surface(name, halfspaces.back().surface));  // B again
      } else if (halfspaces.empty() || *rc::gen::arbitrary<bool>()) {
        int low[3], high[3];
        for (int a = 0; a < 3; ++a) {
          low[a] = *rc::gen::inRange(-2, 2);
          high[a] = *rc::gen::inRange(low[a] + 1, 3);
        }
        halfspaces.push_back(surface(name, box_surface({low[0], low[1], low[2]}, {high[0], high[1], high[2]})));
      }
    const Scene3 scene = scene_of(cube(-2, 2), halfspaces);
    const Arrangement3 unlimited = Arrangement3::build(scene, ArrangementLimits{0, 0, 0});
    const long cells = static_cast<long>(unlimited.cells().size());
    ArrangementLimits limits;
    limits.max_cells = cells;
    limits.max_side_entries = cells * static_cast<long>(halfspaces.size());
    limits.max_triangles = static_cast<long>(unlimited.triangles().size());
    RC_ASSERT(static_cast<long>(Arrangement3::build(scene, limits).cells().size()) == cells);
  });
}
