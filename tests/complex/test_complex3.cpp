#include <hsx/complex/from_arrangement3.hpp>

#include "geometry/scenes3.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <map>

using namespace hsx;
using namespace hsx::test3;

namespace {

long choose(long n, long k) {
  long r = 1;
  for (long i = 0; i < k; ++i) r = r * (n - i) / (i + 1);
  return r;
}

Box3 cube(const Rational& lo, const Rational& hi) { return {{lo, lo, lo}, {hi, hi, hi}}; }

/// The area of a plane's piece inside the box, as the arrangement's own triangles on it sum it up differently:
/// computed here from the clipped polygon (the box's corners and edge crossings, fanned from their centroid).
Measure plane_area_in_box(const Halfspace3& h, const Box3& box) {
  std::vector<PointQ3> pts;
  std::vector<PointQ3> corner;
  for (int i = 0; i < 8; ++i)
    corner.push_back({(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z});
  for (int i = 0; i < 8; ++i) {
    const Rational si = dot(h.normal, corner[i]) - h.offset;
    if (si == 0 && std::find(pts.begin(), pts.end(), corner[i]) == pts.end()) pts.push_back(corner[i]);
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (i & bit) continue;
      const Rational sj = dot(h.normal, corner[i | bit]) - h.offset;
      if (sgn(si) * sgn(sj) < 0) {
        const Rational f = si / (si - sj);
        const PointQ3 d = sub(corner[i | bit], corner[i]);
        pts.push_back(add(corner[i], {d.x * f, d.y * f, d.z * f}));
      }
    }
  }
  // area = |sum over a convex fan| : order the points by angle around the centroid, in the plane
  PointQ3 c{0, 0, 0};
  for (const auto& p : pts) c = add(c, p);
  const Rational k(1, static_cast<long>(pts.size()));
  c = {c.x * k, c.y * k, c.z * k};
  const PointQ3 ref = sub(pts[0], c);
  auto half = [&](const PointQ3& p) {
    const Rational s = dot(h.normal, cross(ref, sub(p, c)));
    return s > 0 || (s == 0 && dot(ref, sub(p, c)) > 0) ? 0 : 1;
  };
  std::sort(pts.begin(), pts.end(), [&](const PointQ3& a, const PointQ3& b) {
    if (half(a) != half(b)) return half(a) < half(b);
    return dot(h.normal, cross(sub(a, c), sub(b, c))) > 0;
  });
  Measure area;
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
    const PointQ3 n = cross(sub(pts[i], pts[0]), sub(pts[i + 1], pts[0]));
    area += Measure::sqrt_of(dot(n, n) / 4);
  }
  return area;
}

Measure surface_area(const TriangleSurface& s) {
  Measure area;
  for (const auto& t : s.triangles) {
    const PointQ3 n = cross(sub(s.vertices[t[1]], s.vertices[t[0]]), sub(s.vertices[t[2]], s.vertices[t[0]]));
    area += Measure::sqrt_of(dot(n, n) / 4);
  }
  return area;
}

/// check_complex, per-halfspace patch areas against the boundary's area inside the box (surfaces lie inside it,
/// planes are measured from their clipped polygon; boundary on the box itself has no patch), volumes.
void check_complex3(const Scene3& scene, const Complex& c, const std::vector<int>& on_box_halfspaces = {}) {
  const auto problems = check_complex(c);
  INFO((problems.empty() ? std::string() : problems.front()));
  REQUIRE(problems.empty());
  REQUIRE(c.dimension == 3);
  for (int h = 0; h < c.halfspace_count(); ++h) {
    if (std::find(on_box_halfspaces.begin(), on_box_halfspaces.end(), h) != on_box_halfspaces.end()) continue;
    Measure sum;
    for (const Patch& p : c.patches)
      if (p.halfspace == h) sum += p.measure;
    const Halfspace3& hs = scene.halfspaces[static_cast<std::size_t>(h)];
    const Measure expected = hs.kind == HalfspaceKind3::Plane ? plane_area_in_box(hs, scene.domain) : surface_area(hs.surface);
    REQUIRE(compare(sum, expected) == Order::Equal);
  }
  Measure volume;
  for (const Cell& cell : c.cells) volume += cell.measure;
  const Box3& b = scene.domain;
  REQUIRE(compare(volume, Measure((b.max.x - b.min.x) * (b.max.y - b.min.y) * (b.max.z - b.min.z))) == Order::Equal);
  // across every patch the two cells differ exactly in its support's halfspaces
  for (const Patch& p : c.patches) {
    std::vector<int> differ;
    for (int h = 0; h < c.halfspace_count(); ++h)
      if (c.cells[p.inside_cell].inside[h] != c.cells[p.outside_cell].inside[h]) differ.push_back(h);
    std::vector<int> support;
    for (int q : c.supports[p.support]) support.push_back(c.patches[q].halfspace);
    std::sort(support.begin(), support.end());
    REQUIRE(differ == support);
  }
}

}  // namespace

TEST_CASE("complex3: random planes in general position") {
  rc::prop("cells, patches and measures", [] {
    const int n = *rc::gen::inRange(3, 6);  // from 3 on, every line of the arrangement holds a triple point
    const Scene3 scene = random_planes(n, 3, *rc::gen::inRange(0, 1 << 30));
    const Arranged3 a = arrange(scene);
    RC_ASSERT(static_cast<long>(a.complex.cells.size()) == 1 + n + choose(n, 2) + choose(n, 3));
    // each plane is cut by the other n - 1 planes' lines, in general position within it
    RC_ASSERT(static_cast<long>(a.complex.patches.size()) == n * (1 + (n - 1) + choose(n - 1, 2)));
    RC_ASSERT(a.complex.supports.size() == a.complex.patches.size());
    check_complex3(scene, a.complex);
    RC_ASSERT(a.complex.outer_cell_count() == static_cast<int>(a.complex.cells.size()) - (n >= 4 ? static_cast<int>(choose(n - 1, 3)) : 0));
  });
}

TEST_CASE("complex3: coincident planes form one support group") {
  for (bool complement : {false, true}) {
    const Scene3 scene = scene_of(cube(-2, 2), {plane("A", {1, 2, 0}, 1), plane("B", {-1, -2, 0}, -1, complement),
                                                plane("C", {0, 0, 1}, 0)});
    const Arranged3 a = arrange(scene);
    check_complex3(scene, a.complex);
    REQUIRE(a.complex.cells.size() == 4);
    REQUIRE(a.complex.patches.size() == 6);  // A and B: two each (C cuts them), C: two
    int pairs = 0;
    for (const auto& s : a.complex.supports) pairs += s.size() == 2;
    REQUIRE(pairs == 2);
    const Measure expected = plane_area_in_box(scene.halfspaces[0], scene.domain) +
                             plane_area_in_box(scene.halfspaces[2], scene.domain);
    REQUIRE(compare(a.complex.measure_of({0, 1, 2, 3, 4, 5}), expected) == Order::Equal);
  }
}

TEST_CASE("complex3: boxes sharing a face, a plane on the domain face") {
  const Scene3 touching = scene_of(cube(-1, 5), {surface("A", box_surface({0, 0, 0}, {2, 2, 2})),
                                                 surface("B", box_surface({2, 0, 0}, {4, 2, 2}))});
  const Arranged3 a = arrange(touching);
  check_complex3(touching, a.complex);
  REQUIRE(a.complex.cells.size() == 3);
  REQUIRE(a.complex.patches.size() == 4);
  REQUIRE(a.complex.supports.size() == 3);
  REQUIRE(a.complex.outer_cell_count() == 1);
  const Scene3 face = scene_of(cube(0, 2), {plane("A", {0, 0, 1}, 2), plane("B", {1, 0, 0}, 1)});
  const Arranged3 b = arrange(face);
  check_complex3(face, b.complex, {0});
  REQUIRE(b.complex.patches.size() == 1);
}

TEST_CASE("complex3: an octahedron cut by planes through its vertices and along its edges") {
  const Scene3 scene = scene_of(cube(-2, 2), {surface("O", octahedron({0, 0, 0}, 1)), plane("Z", {0, 0, 1}, 0),
                                              plane("X", {1, 0, 0}, 0)});
  const Arranged3 a = arrange(scene);
  check_complex3(scene, a.complex);
  REQUIRE(a.complex.cells.size() == 8);
  int of_o = 0;
  for (const auto& p : a.complex.patches) of_o += p.halfspace == 0;
  REQUIRE(of_o == 4);
}

TEST_CASE("complex3: a cavity and floating components") {
  const Scene3 hollow = scene_of(cube(-1, 5), {surface("A", box_surface({0, 0, 0}, {4, 4, 4})),
                                               surface("B", box_surface({1, 1, 1}, {3, 3, 3}), true)});
  const Arranged3 a = arrange(hollow);
  check_complex3(hollow, a.complex);
  REQUIRE(a.complex.cells.size() == 3);
  REQUIRE(a.complex.patches.size() == 2);
  REQUIRE(a.complex.junctions.empty());
  // B is complemented: its inside is the outer shell side
  const Patch& pb = a.complex.patches[1];
  REQUIRE(pb.halfspace == 1);
  REQUIRE(a.complex.cells[pb.inside_cell].inside == std::vector<char>{1, 1});
  REQUIRE(a.complex.cells[pb.outside_cell].inside == std::vector<char>{1, 0});
}

TEST_CASE("complex3: samples sit on their patches") {
  Scene3 scene = scene_of(cube(-2, 2), {surface("A", box_surface({-1, -1, -1}, {1, 1, 1})), plane("P", {0, 0, 1}, 0)});
  for (const PointQ3& at : {PointQ3{Rational(1, 2), Rational(1, 3), 1}, PointQ3{Rational(1, 3), Rational(1, 2), -1},
                            PointQ3{Rational(3, 2), Rational(1, 3), 0}}) {
    Sample3 s;
    s.halfspace = at.z == 0 ? 1 : 0;
    s.given = s.location = at;
    scene.samples.push_back(s);
  }
  const Arranged3 a = arrange(scene);
  check_complex3(scene, a.complex);
  REQUIRE(a.complex.samples.size() == 3);
  REQUIRE(a.complex.samples[0].patch != a.complex.samples[1].patch);
  REQUIRE(a.complex.patches[a.complex.samples[2].patch].halfspace == 1);
}
