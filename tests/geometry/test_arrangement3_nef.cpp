// The Nef oracle (geometry/nef3.hpp) on scenes whose cell counts are known by hand or by formula, then
// Arrangement3's cell counts against it on random small scenes and their degenerate variants.
#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/geometry/arrangement3.hpp>
#include <hsx/geometry/nef3.hpp>
#include <hsx/geometry/random_scene3.hpp>
#include <hsx/geometry/tessellate3.hpp>
#include <hsx/kernel/random.hpp>

#include "geometry/scenes3.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

using namespace hsx;
using namespace hsx::test3;

namespace {

Halfspace3 axis_box(const std::string& name, const PointQ3& lo, const PointQ3& hi) {
  Halfspace3 h = surface(name, box_surface(lo, hi));
  h.kind = HalfspaceKind3::Box;
  return h;
}

Halfspace3 octahedron(const std::string& name, const PointQ3& c, const Rational& r) {
  return surface(name, test3::octahedron(c, r));
}

Halfspace3 tetrahedron(const std::string& name, const PointQ3& a, const PointQ3& b, const PointQ3& c,
                       const PointQ3& d) {
  return surface(name, test3::tetrahedron(a, b, c, d));
}

/// A sphere tessellated with `segments` segments per turn (geometry/tessellate3.hpp), inside [-b, b]^3.
Halfspace3 sphere(const std::string& name, const PointQ3& c, const Rational& r, int segments, const Rational& b) {
  Halfspace3 h;
  h.name = name;
  h.kind = HalfspaceKind3::Sphere;
  h.primitive.center = c;
  h.primitive.radius = r;
  h.primitive.tessellation.segments = segments;
  h.surface = tessellate(h, {pt(-b, -b, -b), pt(b, b, b)});
  return h;
}

Scene3 scene_in(const Rational& b, std::vector<Halfspace3> halfspaces) {
  return scene_of({pt(-b, -b, -b), pt(b, b, b)}, std::move(halfspaces));
}

long choose(long n, long k) {
  if (k < 0 || k > n) return 0;
  long r = 1;
  for (long i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

/// The point where three planes meet, or nullopt when their normals are dependent (Cramer's rule, exact).
std::optional<PointQ3> meet(const Halfspace3& a, const Halfspace3& b, const Halfspace3& c) {
  const Rational det = dot(a.normal, cross(b.normal, c.normal));
  if (det == 0) return std::nullopt;
  const PointQ3 x = {a.offset, b.offset, c.offset};
  const PointQ3 col0 = {a.normal.x, b.normal.x, c.normal.x}, col1 = {a.normal.y, b.normal.y, c.normal.y},
                col2 = {a.normal.z, b.normal.z, c.normal.z};
  return PointQ3{dot(x, cross(col1, col2)) / det, dot(col0, cross(x, col2)) / det, dot(col0, cross(col1, x)) / det};
}

/// n planes in general position (no two parallel, every three meeting in one point, no four in one point) and a
/// box containing every such point strictly: the arrangement in the box has all the cells of the one in space.
Scene3 general_position_planes(int n, Random& rng) {
  for (;;) {
    std::vector<Halfspace3> planes;
    for (int k = 0; k < n; ++k)
      planes.push_back(
          plane("P" + std::to_string(k), pt(rng.in(-20, 20), rng.in(-20, 20), rng.in(-20, 20)), rng.in(-30, 30)));
    bool general = true;
    Rational bound = 1;
    for (int i = 0; i < n && general; ++i)
      for (int j = i + 1; j < n && general; ++j)
        for (int k = j + 1; k < n && general; ++k) {
          const auto p = meet(planes[i], planes[j], planes[k]);
          general = p.has_value();
          for (int l = 0; l < n && general; ++l)
            if (l != i && l != j && l != k) general = dot(planes[l].normal, *p) != planes[l].offset;
          if (general)
            for (const Rational* c : {&p->x, &p->y, &p->z}) {
              const Rational m = abs(*c) + 1;
              if (m > bound) bound = m;
            }
        }
    if (general) return scene_in(bound, std::move(planes));
  }
}

/// A random small scene in [-3, 3]^3: 2 to 5 halfspaces among planes with coefficients in [-2, 2] through
/// half-integer points, axis boxes with integer corners, octahedra and tetrahedra with integer vertices; small
/// numbers make coincident planes and faces, shared edges and vertices frequent. One in three scenes repeats a
/// halfspace (either way round).
Scene3 random_small_scene(Random& rng) {
  std::vector<Halfspace3> hs;
  const long n = rng.in(2, 5);
  for (long k = 0; k < n; ++k) {
    const std::string name = "H" + std::to_string(k);
    switch (rng.in(0, 4)) {
      case 0: {
        PointQ3 normal;
        do normal = pt(rng.in(-2, 2), rng.in(-2, 2), rng.in(-2, 2));
        while (normal == pt(0, 0, 0));
        const PointQ3 p = pt(Rational(rng.in(-4, 4), 2), Rational(rng.in(-4, 4), 2), Rational(rng.in(-4, 4), 2));
        hs.push_back(plane(name, normal, dot(normal, p), rng.one_in(2)));
        break;
      }
      case 1: {
        const PointQ3 lo = pt(rng.in(-3, 1), rng.in(-3, 1), rng.in(-3, 1));
        hs.push_back(axis_box(name, lo, pt(lo.x + rng.in(1, 2), lo.y + rng.in(1, 2), lo.z + rng.in(1, 2))));
        break;
      }
      case 2:
        hs.push_back(octahedron(name, pt(rng.in(-1, 1), rng.in(-1, 1), rng.in(-1, 1)), rng.in(1, 2)));
        break;
      case 3:
        hs.push_back(sphere(name, pt(rng.in(-1, 1), rng.in(-1, 1), rng.in(-1, 1)), rng.in(1, 2),
                            static_cast<int>(rng.in(6, 8)), 3));
        break;
      default: {
        std::array<PointQ3, 4> v;
        do
          for (auto& p : v) p = pt(rng.in(-3, 3), rng.in(-3, 3), rng.in(-3, 3));
        while (dot(sub(v[1], v[0]), cross(sub(v[2], v[0]), sub(v[3], v[0]))) == 0);
        hs.push_back(tetrahedron(name, v[0], v[1], v[2], v[3]));
      }
    }
    if (rng.one_in(2)) hs.back().complement = true;
  }
  if (rng.one_in(3)) {
    Halfspace3 again = hs[rng.index(hs.size())];
    again.name += "'";
    again.complement = rng.one_in(2) ? !again.complement : again.complement;
    hs.push_back(std::move(again));
  }
  return scene_in(3, std::move(hs));
}

struct Case {
  const char* what;
  Scene3 scene;
  long cells, outer;
};

/// Scenes with known counts, most of them degenerate: coincident planes and faces, planes on the domain, through
/// vertices and along edges.
std::vector<Case> hand_counted_cases() {
  const PointQ3 ex = pt(1, 0, 0), ey = pt(0, 1, 0), ez = pt(0, 0, 1);
  std::vector<Case> cases;
  cases.push_back({"no halfspace crossing the box", scene_in(2, {plane("far", ex, 5)}), 1, 1});
  cases.push_back({"one plane", scene_in(2, {plane("x", ex, 0)}), 2, 2});
  cases.push_back({"three axis planes", scene_in(2, {plane("x", ex, 0), plane("y", ey, 0), plane("z", ez, 1)}), 8, 8});
  cases.push_back({"the same plane twice, both orientations",
                   scene_in(2, {plane("a", ex, 1), plane("b", pt(-2, 0, 0), -2)}), 2, 2});
  cases.push_back({"a plane on a box face", scene_in(2, {plane("face", ex, 2)}), 1, 1});
  cases.push_back({"a plane touching a corner", scene_in(2, {plane("corner", pt(1, 1, 1), -6)}), 1, 1});
  cases.push_back({"a plane along a box edge", scene_in(2, {plane("edge", pt(1, 1, 0), 4)}), 1, 1});
  cases.push_back({"an octahedron", scene_in(3, {octahedron("O", pt(0, 0, 0), 2)}), 2, 1});
  cases.push_back(
      {"nested boxes",
       scene_in(3, {axis_box("A", pt(-2, -2, -2), pt(2, 2, 2)), axis_box("B", pt(-1, -1, -1), pt(1, 1, 1))}), 3, 1});
  cases.push_back({"a box on the domain's face", scene_in(2, {axis_box("A", pt(-2, -1, -1), pt(0, 1, 1))}), 2, 2});
  cases.push_back({"boxes sharing a face",
                   scene_in(3, {axis_box("A", pt(0, 0, 0), pt(1, 1, 1)), axis_box("B", pt(1, 0, 0), pt(2, 1, 1))}), 3,
                   1});
  cases.push_back({"the same box twice",
                   scene_in(3, {axis_box("A", pt(0, 0, 0), pt(1, 1, 1)), axis_box("B", pt(0, 0, 0), pt(1, 1, 1))}), 2,
                   1});
  cases.push_back({"a plane through a box's face",
                   scene_in(3, {axis_box("A", pt(0, 0, 0), pt(1, 1, 1)), plane("x", ex, 1)}), 3, 2});
  cases.push_back({"a plane through an octahedron's vertices",
                   scene_in(3, {octahedron("O", pt(0, 0, 0), 2), plane("z", ez, 0)}), 4, 2});
  cases.push_back({"a tetrahedron cut by a plane through an edge",
                   scene_in(3, {tetrahedron("T", pt(0, 0, 0), pt(2, 0, 0), pt(0, 2, 0), pt(0, 0, 2)),
                                plane("xy", pt(1, -1, 0), 0)}),
                   4, 2});
  cases.push_back({"disjoint octahedra, one inside a box",
                   scene_in(6, {axis_box("A", pt(-5, -5, -5), pt(0, 0, 0)), octahedron("O", pt(-2, -2, -2), 1),
                                octahedron("Q", pt(3, 3, 3), 1)}),
                   4, 1});
  cases.push_back({"a plane through a sphere's equator (its vertices and edges)",
                   scene_in(3, {sphere("S", pt(0, 0, 1), 2, 12, 3), plane("z", ez, 1)}), 4, 2});
  cases.push_back({"overlapping spheres",
                   scene_in(4, {sphere("S", pt(-1, 0, 0), 2, 10, 3), sphere("T", pt(1, 0, 0), Rational(3, 2), 8, 3)}),
                   4, 1});
  cases.push_back({"a sphere in a cavity of a box",
                   scene_in(3, {axis_box("A", pt(-2, -2, -2), pt(2, 2, 2)), sphere("S", pt(0, 0, 0), 1, 8, 3)}), 3, 1});
  return cases;
}

}  // namespace

TEST_CASE("Nef oracle: hand-counted scenes", "[nef3]") {
  for (const Case& c : hand_counted_cases()) {
    INFO(c.what);
    const NefCellCounts counts = nef_cell_counts(c.scene);
    CHECK(counts.cells == c.cells);
    CHECK(counts.outer_cells == c.outer);
  }
}

TEST_CASE("Nef oracle: planes in general position follow the formula", "[nef3]") {
  Random rng(12);
  for (int n : {1, 2, 3, 4, 5, 6}) {
    INFO(n << " planes");
    const NefCellCounts counts = nef_cell_counts(general_position_planes(n, rng));
    // Cells of n planes in general position in space: C(n,0) + C(n,1) + C(n,2) + C(n,3); bounded: C(n-1,3).
    CHECK(counts.cells == choose(n, 0) + choose(n, 1) + choose(n, 2) + choose(n, 3));
    CHECK(counts.cells - counts.outer_cells == choose(n - 1, 3));
  }
}

TEST_CASE("random_plane_scene3 is reproducible and valid", "[nef3]") {
  RandomPlanesSettings settings;
  settings.planes = 7;
  const Scene3 a = random_plane_scene3(settings, 5, 3), b = random_plane_scene3(settings, 5, 3);
  REQUIRE(a.halfspaces.size() == 7);
  for (std::size_t i = 0; i < a.halfspaces.size(); ++i) {
    const Halfspace3& h = a.halfspaces[i];
    CHECK(h.normal == b.halfspaces[i].normal);
    CHECK(h.offset == b.halfspaces[i].offset);
    CHECK(h.complement == b.halfspaces[i].complement);
    CHECK_FALSE((h.normal.x == 0 && h.normal.y == 0 && h.normal.z == 0));
    const bool bounded = abs(h.normal.x) <= settings.max_coefficient;
    CHECK(bounded);
  }
  CHECK(a.domain.max.x == settings.coordinate_bound);
  CHECK_THROWS_AS(random_plane_scene3(RandomPlanesSettings{0, 5, 4, 2}, 1, 0), std::invalid_argument);
}

// ---- Arrangement3 against the oracle ----

namespace {

std::string describe(const Scene3& scene) {
  std::string s;
  for (const Halfspace3& h : scene.halfspaces) {
    s += h.name + " " + to_string(h.kind) + (h.complement ? " (complement)" : "");
    if (h.kind == HalfspaceKind3::Plane)
      s += " n=(" + exact_string(h.normal.x) + "," + exact_string(h.normal.y) + "," + exact_string(h.normal.z) +
           ") o=" + exact_string(h.offset);
    else
      s += " v0=(" + exact_string(h.surface.vertices[0].x) + "," + exact_string(h.surface.vertices[0].y) + "," +
           exact_string(h.surface.vertices[0].z) + ")";
    s += "; ";
  }
  return s;
}

/// Arrangement3's cell and outer-cell counts equal Nef's (and `expected`'s when given).
void check_against_nef(Scene3 scene, long expected_cells = -1, long expected_outer = -1) {
  validate_and_resolve(scene);
  INFO(describe(scene));
  const Arranged3 a = arrange(scene);
  const long cells = static_cast<long>(a.complex.cells.size()), outer = a.complex.outer_cell_count();
  const NefCellCounts nef = nef_cell_counts(scene);
  CHECK(cells == nef.cells);
  CHECK(outer == nef.outer_cells);
  if (expected_cells >= 0) CHECK(cells == expected_cells);
  if (expected_outer >= 0) CHECK(outer == expected_outer);
}

}  // namespace

TEST_CASE("Arrangement3 against Nef: hand-counted degenerate scenes", "[nef3][arrangement3]") {
  for (const Case& c : hand_counted_cases()) {
    INFO(c.what);
    check_against_nef(c.scene, c.cells, c.outer);
  }
}

TEST_CASE("Arrangement3 against Nef: planes in general position", "[nef3][arrangement3]") {
  Random rng(7);
  for (int n : {3, 5, 7})
    check_against_nef(general_position_planes(n, rng), choose(n, 0) + choose(n, 1) + choose(n, 2) + choose(n, 3));
}

TEST_CASE("Arrangement3 against Nef: random small scenes", "[nef3][arrangement3]") {
  for (std::uint64_t index = 0; index < 23; ++index) {
    INFO("random_small_scene, item " << index);
    Random rng(item_seed(2024, index));
    check_against_nef(random_small_scene(rng));
  }
}

// A tessellated sphere whose south pole touches the domain's bottom face at a vertex: a floating shell touching the
// box at a vertex (it once threw "no clean ray out of a floating shell": the ray left from the shell's vertex of
// largest x, which may lie on the box).
TEST_CASE("Arrangement3 against Nef: a sphere touching the domain at a vertex", "[nef3][arrangement3]") {
  Random rng(item_seed(2024, 23));
  check_against_nef(random_small_scene(rng));
}

TEST_CASE("Arrangement3 against Nef: random planes with small coefficients (coincident, concurrent)",
          "[nef3][arrangement3]") {
  RandomPlanesSettings settings;
  settings.planes = 5;
  settings.max_coefficient = 2;
  settings.coordinate_bound = 2;
  for (std::uint64_t index = 0; index < 6; ++index) {
    INFO("random_plane_scene3, item " << index);
    check_against_nef(random_plane_scene3(settings, 99, index));
  }
}

// ---- Shells touching at a vertex or along an edge (cells derived by hand, counts checked against Nef) ----

namespace {

/// A cell as the test derives it by hand: its sides (one per halfspace, in scene order), its exact volume, outer.
struct ExpectedCell {
  std::vector<char> inside;
  Rational volume;
  bool outer = false;
  bool operator<(const ExpectedCell& o) const {
    return std::tie(inside, volume, outer) < std::tie(o.inside, o.volume, o.outer);
  }
  bool operator==(const ExpectedCell& o) const { return inside == o.inside && volume == o.volume && outer == o.outer; }
};

struct ContactCase {
  const char* what;
  Scene3 scene;
  std::vector<ExpectedCell> cells;
};

Halfspace3 complemented(Halfspace3 h) {
  h.complement = true;
  return h;
}

/// Floating shells that touch each other, a plane, their enclosing shell or the domain only at a vertex or along an
/// edge. The domain is [-3, 3]^3 (volume 216); every volume below is a box's or a tetrahedron's (|det| / 6).
std::vector<ContactCase> contact_cases() {
  std::vector<ContactCase> cases;
  cases.push_back({"two boxes meeting at one vertex",
                   scene_in(3, {axis_box("A", pt(-1, -1, -1), pt(0, 0, 0)), axis_box("B", pt(0, 0, 0), pt(1, 1, 1))}),
                   {{{0, 0}, 214, true}, {{1, 0}, 1, false}, {{0, 1}, 1, false}}});
  cases.push_back({"two tetrahedra meeting at one vertex",
                   scene_in(3, {tetrahedron("T", pt(0, 0, 0), pt(1, 0, 0), pt(0, 1, 0), pt(0, 0, 1)),
                                tetrahedron("U", pt(0, 0, 0), pt(-1, 0, 0), pt(0, -1, 0), pt(0, 0, -1))}),
                   {{{0, 0}, 216 - Rational(1, 3), true}, {{1, 0}, Rational(1, 6), false}, {{0, 1}, Rational(1, 6), false}}});
  cases.push_back({"a tetrahedron's vertex inside a box's face",
                   scene_in(3, {axis_box("A", pt(-1, -1, -2), pt(1, 1, 0)),
                                tetrahedron("T", pt(Rational(1, 4), Rational(1, 3), 0), pt(0, 0, 1), pt(1, 0, 1), pt(0, 1, 1))}),
                   {{{0, 0}, 216 - 8 - Rational(1, 6), true}, {{1, 0}, 8, false}, {{0, 1}, Rational(1, 6), false}}});
  cases.push_back({"two boxes sharing an edge",
                   scene_in(3, {axis_box("A", pt(-1, -1, -1), pt(0, 0, 1)), axis_box("B", pt(0, 0, -1), pt(1, 1, 1))}),
                   {{{0, 0}, 212, true}, {{1, 0}, 2, false}, {{0, 1}, 2, false}}});
  cases.push_back({"a tetrahedron's edge inside a box's face",
                   scene_in(3, {axis_box("A", pt(-1, -1, -1), pt(1, 1, 0)),
                                tetrahedron("T", pt(Rational(-1, 2), 0, 0), pt(Rational(1, 2), 0, 0), pt(0, -1, 1), pt(0, 1, 1))}),
                   {{{0, 0}, 216 - 4 - Rational(1, 3), true}, {{1, 0}, 4, false}, {{0, 1}, Rational(1, 3), false}}});
  // A hollow box whose cavity (the complemented tetrahedron B) touches the box's top face at a point inside it.
  cases.push_back({"a cavity touching its shell's face at a vertex",
                   scene_in(3, {axis_box("A", pt(-2, -2, -2), pt(2, 2, 2)),
                                complemented(tetrahedron("B", pt(0, 0, 2), pt(-1, -1, 0), pt(1, -1, 0), pt(0, 1, 0)))}),
                   {{{0, 1}, 152, true}, {{1, 1}, 64 - Rational(4, 3), false}, {{1, 0}, Rational(4, 3), false}}});
  cases.push_back({"a cavity touching its shell's corner",
                   scene_in(3, {axis_box("A", pt(-2, -2, -2), pt(2, 2, 2)),
                                complemented(tetrahedron("B", pt(2, 2, 2), pt(0, 0, 0), pt(1, 0, 0), pt(0, 1, 0)))}),
                   {{{0, 1}, 152, true}, {{1, 1}, 64 - Rational(1, 3), false}, {{1, 0}, Rational(1, 3), false}}});
  cases.push_back({"a tetrahedron touching a plane at a vertex",
                   scene_in(3, {plane("P", pt(0, 0, 1), 0),
                                tetrahedron("T", pt(0, 0, 0), pt(-1, -1, 1), pt(1, -1, 1), pt(0, 1, 1))}),
                   {{{1, 0}, 108, true}, {{0, 0}, 108 - Rational(2, 3), true}, {{0, 1}, Rational(2, 3), false}}});
  cases.push_back({"a tetrahedron touching the domain's corner",
                   scene_in(3, {tetrahedron("T", pt(3, 3, 3), pt(1, 1, 2), pt(2, 1, 1), pt(1, 2, 1))}),
                   {{{0}, 216 - Rational(5, 6), true}, {{1}, Rational(5, 6), false}}});
  // Four bars around the unit cube [0, 1]^3, each touching the next along a vertical edge, and two plates below and
  // above it, each touching the four bars along an edge: the cube is enclosed by shells that meet only along edges
  // (a cell of its own, with the same sides as the space around).
  cases.push_back({"a hole enclosed by six boxes meeting along edges",
                   scene_in(3, {axis_box("W", pt(-1, 0, 0), pt(0, 1, 1)), axis_box("S", pt(0, -1, 0), pt(1, 0, 1)),
                                axis_box("E", pt(1, 0, 0), pt(2, 1, 1)), axis_box("N", pt(0, 1, 0), pt(1, 2, 1)),
                                axis_box("D", pt(0, 0, -1), pt(1, 1, 0)), axis_box("U", pt(0, 0, 1), pt(1, 1, 2))}),
                   {{{0, 0, 0, 0, 0, 0}, 209, true},
                    {{0, 0, 0, 0, 0, 0}, 1, false},
                    {{1, 0, 0, 0, 0, 0}, 1, false},
                    {{0, 1, 0, 0, 0, 0}, 1, false},
                    {{0, 0, 1, 0, 0, 0}, 1, false},
                    {{0, 0, 0, 1, 0, 0}, 1, false},
                    {{0, 0, 0, 0, 1, 0}, 1, false},
                    {{0, 0, 0, 0, 0, 1}, 1, false}}});
  return cases;
}

}  // namespace

TEST_CASE("Arrangement3 against Nef: shells touching at a vertex or along an edge", "[nef3][arrangement3]") {
  for (ContactCase& c : contact_cases()) {
    INFO(c.what);
    validate_and_resolve(c.scene);
    const Arrangement3 arr = Arrangement3::build(c.scene);
    std::vector<ExpectedCell> got;
    for (const ArrCell3& cell : arr.cells()) {
      got.push_back({cell.inside, *cell.volume, cell.outer});
      for (std::size_t h = 0; h < c.scene.halfspaces.size(); ++h)
        CHECK(direct_side(c.scene.halfspaces[h], cell.interior) == (cell.inside[h] ? 1 : -1));
    }
    std::sort(got.begin(), got.end());
    std::sort(c.cells.begin(), c.cells.end());
    CHECK(got == c.cells);
    long outer = 0;
    for (const ExpectedCell& e : c.cells) outer += e.outer ? 1 : 0;
    check_against_nef(c.scene, static_cast<long>(c.cells.size()), outer);
  }
}

// Unit cubes and unit-leg tetrahedra at random grid positions: most pairs touch at a vertex or along an edge, or
// share a face, and their holes and pockets are enclosed by such contacts.
TEST_CASE("Arrangement3 against Nef: random grid cubes and corner tetrahedra (contacts at vertices and edges)",
          "[nef3][arrangement3]") {
  for (std::uint64_t index = 0; index < 16; ++index) {
    INFO("grid scene, item " << index);
    Random rng(item_seed(77, index));
    std::vector<Halfspace3> hs;
    const long n = rng.in(3, 10);
    for (long k = 0; k < n; ++k) {
      const PointQ3 o = pt(rng.in(-1, 1), rng.in(-1, 1), rng.in(-1, 1));
      const std::string name = "H" + std::to_string(k);
      if (rng.one_in(3))
        hs.push_back(tetrahedron(name, o, add(o, pt(1, 0, 0)), add(o, pt(0, 1, 0)), add(o, pt(0, 0, 1))));
      else if (rng.one_in(2))
        hs.push_back(tetrahedron(name, add(o, pt(1, 1, 1)), add(o, pt(0, 1, 1)), add(o, pt(1, 0, 1)), add(o, pt(1, 1, 0))));
      else
        hs.push_back(axis_box(name, o, add(o, pt(1, 1, 1))));
    }
    check_against_nef(scene_in(3, std::move(hs)));
  }
}
