// The Nef oracle (geometry/nef3.hpp) on scenes whose cell counts are known by hand or by formula, then
// Arrangement3's cell counts against it on random small scenes and their degenerate variants.
#include <hsx/geometry/nef3.hpp>
#include <hsx/geometry/random_scene3.hpp>
#include <hsx/kernel/random.hpp>

#include <catch2/catch.hpp>

#include <optional>
#include <string>
#include <vector>

using namespace hsx;

namespace {

PointQ3 pt(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }

Rational dot(const PointQ3& a, const PointQ3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
PointQ3 minus(const PointQ3& a, const PointQ3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
PointQ3 cross(const PointQ3& a, const PointQ3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// A convex polytope's surface from its vertices and triangles, each turned to face away from `interior`.
TriangleSurface convex_surface(std::vector<PointQ3> vertices, std::vector<std::array<int, 3>> triangles,
                               const PointQ3& interior) {
  for (auto& t : triangles) {
    const PointQ3 n = cross(minus(vertices[t[1]], vertices[t[0]]), minus(vertices[t[2]], vertices[t[0]]));
    if (dot(n, minus(vertices[t[0]], interior)) < 0) std::swap(t[1], t[2]);
  }
  return {std::move(vertices), std::move(triangles)};
}

Halfspace3 surface_halfspace(const std::string& name, HalfspaceKind3 kind, TriangleSurface surface) {
  Halfspace3 h;
  h.name = name;
  h.kind = kind;
  h.surface = std::move(surface);
  h.origin = "test";
  return h;
}

/// The axis box [lo, hi], 12 triangles (two per face, split along the diagonal from the face's lowest corner).
Halfspace3 axis_box(const std::string& name, const PointQ3& lo, const PointQ3& hi) {
  std::vector<PointQ3> v;
  for (int k = 0; k < 8; ++k) v.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
  const std::vector<std::array<int, 3>> t = {{0, 2, 6}, {0, 6, 4}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                                             {2, 3, 7}, {2, 7, 6}, {0, 1, 3}, {0, 3, 2}, {4, 5, 7}, {4, 7, 6}};
  const PointQ3 centre{(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2};
  return surface_halfspace(name, HalfspaceKind3::Box, convex_surface(v, t, centre));
}

/// The octahedron with vertices c +- r e_i.
Halfspace3 octahedron(const std::string& name, const PointQ3& c, const Rational& r) {
  std::vector<PointQ3> v = {pt(c.x + r, c.y, c.z), pt(c.x - r, c.y, c.z), pt(c.x, c.y + r, c.z),
                            pt(c.x, c.y - r, c.z), pt(c.x, c.y, c.z + r), pt(c.x, c.y, c.z - r)};
  std::vector<std::array<int, 3>> t;
  for (int x : {0, 1})
    for (int y : {2, 3})
      for (int z : {4, 5}) t.push_back({x, y, z});
  return surface_halfspace(name, HalfspaceKind3::Mesh, convex_surface(v, t, c));
}

Halfspace3 tetrahedron(const std::string& name, const PointQ3& a, const PointQ3& b, const PointQ3& c,
                       const PointQ3& d) {
  const PointQ3 centre{(a.x + b.x + c.x + d.x) / 4, (a.y + b.y + c.y + d.y) / 4, (a.z + b.z + c.z + d.z) / 4};
  return surface_halfspace(name, HalfspaceKind3::Mesh,
                           convex_surface({a, b, c, d}, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}, centre));
}

Halfspace3 plane(const std::string& name, const PointQ3& normal, const Rational& offset, bool complement = false) {
  Halfspace3 h;
  h.name = name;
  h.kind = HalfspaceKind3::Plane;
  h.normal = normal;
  h.offset = offset;
  h.complement = complement;
  return h;
}

Scene3 scene_in(const Rational& b, std::vector<Halfspace3> halfspaces) {
  Scene3 s;
  s.domain = {pt(-b, -b, -b), pt(b, b, b)};
  s.domain_given = true;
  s.halfspaces = std::move(halfspaces);
  return s;
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
      planes.push_back(plane("P" + std::to_string(k), pt(rng.in(-20, 20), rng.in(-20, 20), rng.in(-20, 20)),
                             rng.in(-30, 30)));
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

}  // namespace

TEST_CASE("Nef oracle: hand-counted scenes", "[nef3]") {
  struct Case {
    const char* what;
    Scene3 scene;
    long cells, outer;
  };
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
  cases.push_back({"nested boxes", scene_in(3, {axis_box("A", pt(-2, -2, -2), pt(2, 2, 2)),
                                                axis_box("B", pt(-1, -1, -1), pt(1, 1, 1))}),
                   3, 1});
  cases.push_back({"a box on the domain's face", scene_in(2, {axis_box("A", pt(-2, -1, -1), pt(0, 1, 1))}), 2, 2});
  cases.push_back({"boxes sharing a face", scene_in(3, {axis_box("A", pt(0, 0, 0), pt(1, 1, 1)),
                                                        axis_box("B", pt(1, 0, 0), pt(2, 1, 1))}),
                   3, 1});
  cases.push_back({"the same box twice", scene_in(3, {axis_box("A", pt(0, 0, 0), pt(1, 1, 1)),
                                                      axis_box("B", pt(0, 0, 0), pt(1, 1, 1))}),
                   2, 1});
  cases.push_back({"a plane through a box's face", scene_in(3, {axis_box("A", pt(0, 0, 0), pt(1, 1, 1)),
                                                                plane("x", ex, 1)}),
                   3, 2});
  cases.push_back({"a plane through an octahedron's vertices",
                   scene_in(3, {octahedron("O", pt(0, 0, 0), 2), plane("z", ez, 0)}), 4, 2});
  cases.push_back({"a tetrahedron cut by a plane through an edge",
                   scene_in(3, {tetrahedron("T", pt(0, 0, 0), pt(2, 0, 0), pt(0, 2, 0), pt(0, 0, 2)),
                                plane("xy", pt(1, -1, 0), 0)}),
                   4, 2});
  cases.push_back({"disjoint octahedra, one inside a box", scene_in(6, {axis_box("A", pt(-5, -5, -5), pt(0, 0, 0)),
                                                                         octahedron("O", pt(-2, -2, -2), 1),
                                                                         octahedron("Q", pt(3, 3, 3), 1)}),
                   4, 1});
  for (const Case& c : cases) {
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
