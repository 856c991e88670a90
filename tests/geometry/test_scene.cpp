// Tests of geometry/scene: side tests, validation, sample resolution and the chosen domain.
#include <hsx/geometry/scene.hpp>
#include <hsx/kernel/measure.hpp>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

using namespace hsx;

namespace {

Rational q(const char* text) {
  auto r = parse_rational(text);
  REQUIRE(r.has_value());
  return *r;
}

PointQ2 pt(long x, long y) { return PointQ2{Rational(x), Rational(y)}; }

Halfspace2 halfplane(const std::string& name, PointQ2 n, Rational o) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Halfplane;
  h.normal = n;
  h.offset = o;
  return h;
}

Halfspace2 disk(const std::string& name, PointQ2 c, Rational r) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Disk;
  h.center = c;
  h.radius = r;
  return h;
}

Halfspace2 polygon(const std::string& name, std::vector<PointQ2> v) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Polygon;
  h.vertices = std::move(v);
  return h;
}

Sample2 sample(int halfspace, PointQ2 p, bool snapped) {
  Sample2 s;
  s.halfspace = halfspace;
  s.given = p;
  s.snapped = snapped;
  return s;
}

Scene2 scene_of(std::vector<Halfspace2> hs, std::vector<Sample2> samples = {}) {
  Scene2 s;
  s.halfspaces = std::move(hs);
  s.samples = std::move(samples);
  return s;
}

/// The message of the InputError thrown by validate_and_resolve ("" when none).
std::string validation_error(Scene2 scene) {
  try {
    validate_and_resolve(scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

int sgn_q(const Rational& v) { return sgn(v); }

/// Exact test that p lies on the circle (c, r): (x-cx)^2 + (y-cy)^2 - r^2 == 0 with x, y one-root numbers.
bool exactly_on_circle(const OneRootPoint& p, const PointQ2& c, const Rational& r) {
  OneRoot dx(p.x.a0 - c.x, p.x.a1, p.x.root), dy(p.y.a0 - c.y, p.y.a1, p.y.root);
  // (a0 + a1 sqrt(s))^2 = a0^2 + a1^2 s + 2 a0 a1 sqrt(s)
  Rational rational_part = dx.a0 * dx.a0 + dx.a1 * dx.a1 * dx.root + dy.a0 * dy.a0 + dy.a1 * dy.a1 * dy.root - r * r;
  Rational bx = 2 * dx.a0 * dx.a1, by = 2 * dy.a0 * dy.a1;
  if (bx == 0 || by == 0 || dx.root == dy.root) return rational_part == 0 && bx + by == 0;
  // Different radicands on the two coordinates: let Measure decide.
  Measure m = Measure::product(dx, dx) + Measure::product(dy, dy) - Measure(r * r);
  return m.is_zero();
}

// Brute-force point-in-polygon: on an edge -> 0; otherwise even-odd count of the edges crossed by the ray going
// right from p, with exact crossing abscissae (half-open rule on y).
int brute_polygon_side(const std::vector<PointQ2>& v, const PointQ2& p) {
  const std::size_t n = v.size();
  bool inside = false;
  for (std::size_t i = 0; i < n; ++i) {
    const PointQ2& a = v[i];
    const PointQ2& b = v[(i + 1) % n];
    Rational cr = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    if (cr == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
        p.y <= std::max(a.y, b.y)) {
      return 0;
    }
    if ((a.y > p.y) != (b.y > p.y)) {
      Rational x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (x > p.x) inside = !inside;
    }
  }
  return inside ? 1 : -1;
}

// A random star-shaped polygon around `center`: directions with distinct angles (always including the four axis
// directions, so consecutive angles are less than pi apart), sorted by angle, scaled by random radii.
std::vector<PointQ2> star_polygon(const PointQ2& center, std::vector<std::pair<int, int>> dirs,
                                  const std::vector<int>& radii, bool clockwise) {
  dirs.insert(dirs.end(), {{1, 0}, {0, 1}, {-1, 0}, {0, -1}});
  auto half = [](const std::pair<int, int>& d) { return (d.second > 0 || (d.second == 0 && d.first > 0)) ? 0 : 1; };
  auto angle_less = [&](const std::pair<int, int>& a, const std::pair<int, int>& b) {
    if (half(a) != half(b)) return half(a) < half(b);
    return static_cast<long>(a.first) * b.second - static_cast<long>(a.second) * b.first > 0;
  };
  auto same_angle = [&](const std::pair<int, int>& a, const std::pair<int, int>& b) {
    return !angle_less(a, b) && !angle_less(b, a);
  };
  dirs.erase(std::remove(dirs.begin(), dirs.end(), std::pair<int, int>{0, 0}), dirs.end());
  std::stable_sort(dirs.begin(), dirs.end(), angle_less);
  dirs.erase(std::unique(dirs.begin(), dirs.end(), same_angle), dirs.end());
  std::vector<PointQ2> v;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    Rational r = radii.empty() ? Rational(1) : Rational(radii[i % radii.size()], 3);
    r.canonicalize();
    v.push_back(PointQ2{center.x + r * dirs[i].first, center.y + r * dirs[i].second});
  }
  if (clockwise) std::reverse(v.begin(), v.end());
  return v;
}

bool strictly_inside(const Box2& b, const PointQ2& p) {
  return b.min.x < p.x && p.x < b.max.x && b.min.y < p.y && p.y < b.max.y;
}

}  // namespace

TEST_CASE("to_string of halfspace kinds", "[scene]") {
  CHECK(std::string(to_string(HalfspaceKind2::Halfplane)) == "halfplane");
  CHECK(std::string(to_string(HalfspaceKind2::Disk)) == "disk");
  CHECK(std::string(to_string(HalfspaceKind2::Polygon)) == "polygon");
}

TEST_CASE("side of a point: halfplane, disk, polygon, complement", "[scene]") {
  Halfspace2 b = halfplane("B", pt(0, 1), 1);
  CHECK(b.side(pt(5, 0)) == 1);
  CHECK(b.side(pt(5, 1)) == 0);
  CHECK(b.side(pt(5, 2)) == -1);
  b.complement = true;
  CHECK(b.side(pt(5, 0)) == -1);
  CHECK(b.side(pt(5, 1)) == 0);

  Halfspace2 a = disk("A", pt(0, 0), q("3/2"));
  CHECK(a.side(PointQ2{q("-3/2"), 0}) == 0);
  CHECK(a.side(PointQ2{q("9/10"), q("6/5")}) == 0);  // 0.81 + 1.44 = 2.25
  CHECK(a.side(pt(1, 1)) == 1);
  CHECK(a.side(pt(1, 2)) == -1);

  Halfspace2 c = polygon("C", {pt(0, 0), pt(4, 0), pt(4, 3)});
  CHECK(c.side(pt(3, 1)) == 1);
  CHECK(c.side(pt(2, 0)) == 0);
  CHECK(c.side(pt(4, 3)) == 0);
  CHECK(c.side(PointQ2{2, q("3/2")}) == 0);
  CHECK(c.side(pt(1, 2)) == -1);
  c.complement = true;
  CHECK(c.side(pt(3, 1)) == -1);
  CHECK(c.side(pt(1, 2)) == 1);
}

TEST_CASE("side of a non-convex polygon agrees with brute force", "[scene]") {
  // A U shape, both orientations.
  std::vector<PointQ2> u = {pt(0, 0), pt(6, 0), pt(6, 5), pt(4, 5), pt(4, 2), pt(2, 2), pt(2, 5), pt(0, 5)};
  for (bool reversed : {false, true}) {
    auto v = u;
    if (reversed) std::reverse(v.begin(), v.end());
    Halfspace2 h = polygon("U", v);
    for (int x = -2; x <= 14; ++x) {
      for (int y = -2; y <= 12; ++y) {
        PointQ2 p{Rational(x, 2), Rational(y, 2)};
        p.x.canonicalize();
        p.y.canonicalize();
        INFO("p = " << exact_string(p.x) << ", " << exact_string(p.y));
        CHECK(h.side(p) == brute_polygon_side(v, p));
      }
    }
  }
}

TEST_CASE("side agrees with brute force (property)", "[scene][property]") {
  rc::prop("halfplane and disk", [](int nx, int ny, int o, int cx, int cy, unsigned r0, int px, int py) {
    RC_PRE(nx != 0 || ny != 0);
    PointQ2 p{Rational(px % 50), Rational(py % 50)};
    Halfspace2 h = halfplane("H", PointQ2{Rational(nx % 10), Rational(ny % 10)}, Rational(o % 50));
    RC_PRE(h.normal.x != 0 || h.normal.y != 0);
    Rational s = h.normal.x * p.x + h.normal.y * p.y - h.offset;
    RC_ASSERT(h.side(p) == -sgn_q(s));
    Halfspace2 d = disk("D", PointQ2{Rational(cx % 20), Rational(cy % 20)}, Rational(r0 % 20 + 1));
    Rational dd = (p.x - d.center.x) * (p.x - d.center.x) + (p.y - d.center.y) * (p.y - d.center.y);
    RC_ASSERT(d.side(p) == -sgn_q(dd - d.radius * d.radius));
    d.complement = true;
    RC_ASSERT(d.side(p) == sgn_q(dd - d.radius * d.radius));
  });
  rc::prop("star-shaped polygon", [](std::vector<std::pair<int, int>> dirs, std::vector<int> radii, int px, int py,
                                     bool clockwise) {
    for (auto& d : dirs) d = {d.first % 7, d.second % 7};
    for (auto& r : radii) r = std::abs(r % 9) + 1;
    auto v = star_polygon(pt(0, 0), dirs, radii, clockwise);
    Halfspace2 h = polygon("P", v);
    PointQ2 p{Rational(px % 60, 6), Rational(py % 60, 6)};
    p.x.canonicalize();
    p.y.canonicalize();
    RC_ASSERT(h.side(p) == brute_polygon_side(v, p));
    // a vertex and an edge midpoint are on the boundary
    RC_ASSERT(h.side(v[0]) == 0);
    RC_ASSERT(h.side(PointQ2{(v[0].x + v[1].x) / 2, (v[0].y + v[1].y) / 2}) == 0);
  });
}

TEST_CASE("signed area", "[scene]") {
  CHECK(signed_area({pt(0, 0), pt(4, 0), pt(4, 3)}) == 6);
  CHECK(signed_area({pt(4, 3), pt(4, 0), pt(0, 0)}) == -6);
  CHECK(signed_area({PointQ2{0, 0}, PointQ2{1, 0}, PointQ2{0, q("1/3")}}) == q("1/6"));
}

TEST_CASE("find_halfspace", "[scene]") {
  Scene2 s = scene_of({disk("A", pt(0, 0), 1), halfplane("B", pt(0, 1), 0)});
  CHECK(s.find_halfspace("A") == 0);
  CHECK(s.find_halfspace("B") == 1);
  CHECK(s.find_halfspace("Z") == -1);
}

TEST_CASE("validation errors name the halfspace", "[scene][errors]") {
  SECTION("empty scene") { CHECK_THAT(validation_error(scene_of({})), Catch::Contains("halfspaces: the scene has no")); }
  SECTION("radius zero or negative") {
    CHECK_THAT(validation_error(scene_of({disk("A", pt(0, 0), 0)})),
               Catch::Contains("halfspaces[0] (\"A\"): the radius must be positive, got 0"));
    CHECK_THAT(validation_error(scene_of({halfplane("B", pt(0, 1), 0), disk("A", pt(0, 0), -2)})),
               Catch::Contains("halfspaces[1] (\"A\"): the radius must be positive, got -2"));
  }
  SECTION("zero normal") {
    CHECK_THAT(validation_error(scene_of({halfplane("B", pt(0, 0), 1)})),
               Catch::Contains("halfspaces[0] (\"B\"): the normal of a halfplane must not be zero"));
  }
  SECTION("names") {
    CHECK_THAT(validation_error(scene_of({disk("A", pt(0, 0), 1), disk("A", pt(5, 0), 1)})),
               Catch::Contains("halfspaces[1] (\"A\"): duplicate name (also used by halfspaces[0])"));
    CHECK_THAT(validation_error(scene_of({disk("", pt(0, 0), 1)})), Catch::Contains("halfspaces[0]: the name is empty"));
  }
  SECTION("degenerate polygons") {
    CHECK_THAT(validation_error(scene_of({polygon("C", {pt(0, 0), pt(1, 0)})})),
               Catch::Contains("halfspaces[0] (\"C\"): polygon needs at least 3 vertices, got 2"));
    CHECK_THAT(validation_error(scene_of({polygon("C", {pt(0, 0), pt(1, 0), pt(2, 0), pt(3, 0)})})),
               Catch::Contains("all its vertices are collinear"));
    CHECK_THAT(validation_error(scene_of({polygon("C", {pt(0, 0), pt(2, 0), pt(2, 2), pt(2, 0), pt(0, 2)})})),
               Catch::Contains("vertices 1 and 3 are both [2, 0]"));
    CHECK_THAT(validation_error(scene_of({polygon("C", {pt(0, 0), pt(4, 0), pt(2, 0), pt(2, 3)})})),
               Catch::Contains("edges 0 and 1 overlap"));
  }
  SECTION("self-intersecting polygons") {
    CHECK(validation_error(scene_of({disk("A", pt(9, 9), 1), polygon("B", {pt(0, 0), pt(1, 0), pt(0, 1)}),
                                     polygon("C", {pt(0, 0), pt(2, 2), pt(2, 0), pt(0, 2)})})) ==
          "halfspaces[2] (\"C\"): polygon is self-intersecting: edges 0 and 2 cross at [1, 1]");
    CHECK(validation_error(scene_of({polygon("C", {pt(0, 0), pt(2, 0), pt(0, 2), pt(2, 2)})})) ==
          "halfspaces[0] (\"C\"): polygon is self-intersecting: edges 1 and 3 cross at [1, 1]");
    // a vertex on a non-adjacent edge
    CHECK_THAT(validation_error(scene_of({polygon("C", {pt(0, 0), pt(4, 0), pt(4, 4), pt(2, 0), pt(0, 4)})})),
               Catch::Contains("edges 0 and 2 touch at [2, 0]") || Catch::Contains("edges 0 and 3 touch at [2, 0]"));
    // collinear overlap of non-adjacent edges
    CHECK_THAT(validation_error(scene_of({polygon("C", {pt(0, 0), pt(4, 0), pt(4, 2), pt(3, 2), pt(3, 0),
                                                        pt(1, 0), pt(1, 2), pt(0, 2)})})),
               Catch::Contains("polygon is self-intersecting: edges"));
    // rational crossing point
    CHECK_THAT(validation_error(scene_of({polygon("C", {pt(0, 0), pt(3, 0), pt(0, 1), pt(1, -1)})})),
               Catch::EndsWith("polygon is self-intersecting: edges 0 and 2 cross at [1/2, 0]"));
  }
  SECTION("sample index out of range") {
    CHECK_THAT(validation_error(scene_of({disk("A", pt(0, 0), 1)}, {sample(3, pt(1, 0), false)})),
               Catch::Contains("samples[0]: halfspace index 3 is out of range"));
  }
}

TEST_CASE("`at` samples must lie exactly on the boundary; the error says how far off", "[scene][samples]") {
  Scene2 s = scene_of({disk("A", pt(0, 0), q("3/2")), halfplane("B", pt(0, 1), 1),
                       polygon("C", {pt(0, 0), pt(4, 0), pt(4, 3)})},
                      {sample(0, PointQ2{q("-3/2"), 0}, false), sample(1, pt(5, 1), false),
                       sample(2, pt(2, 0), false)});
  CHECK(validation_error(s).empty());

  CHECK(validation_error(scene_of({disk("A", pt(0, 0), q("3/2"))}, {sample(0, PointQ2{0, q("3/2")}, false),
                                                                     sample(0, pt(2, 0), false)})) ==
        "samples[1] (on \"A\"): point [2, 0] is not on the boundary of \"A\" (about 0.5 away)");
  CHECK_THAT(validation_error(scene_of({halfplane("B", pt(0, 2), 2)}, {sample(0, pt(5, 4), false)})),
             Catch::Contains("samples[0] (on \"B\"): point [5, 4] is not on the boundary of \"B\" (about 3 away)"));
  CHECK_THAT(validation_error(scene_of({polygon("C", {pt(0, 0), pt(4, 0), pt(4, 3)})},
                                       {sample(0, PointQ2{2, q("1/10")}, false)})),
             Catch::Contains("point [2, 1/10] is not on the boundary of \"C\" (about 0.1 away)"));
  // a tiny distance is still reported (no cancellation)
  CHECK_THAT(validation_error(scene_of({disk("A", pt(0, 0), 1)}, {sample(0, PointQ2{q("1.000000000000000000000000000000000000001"), 0}, false)})),
             Catch::Contains("about 1e-39 away"));
}

TEST_CASE("`near` samples snap exactly onto the boundary", "[scene][samples]") {
  SECTION("disk: an exact one-root point on the circle") {
    Scene2 s = scene_of({disk("A", pt(0, 0), q("3/2"))}, {sample(0, PointQ2{q("1.06"), q("1.06")}, true),
                                                         sample(0, PointQ2{3, 4}, true)});
    validate_and_resolve(s);
    const auto& a = s.samples[0];
    CHECK(a.snapped);
    CHECK(exactly_on_circle(a.location, pt(0, 0), q("3/2")));
    CHECK(std::abs(a.location.x.to_double() - 1.5 / std::sqrt(2.0)) < 1e-12);
    CHECK(std::abs(a.location.y.to_double() - 1.5 / std::sqrt(2.0)) < 1e-12);
    // (3, 4) has |p| = 5: the snapped point is rational (9/10, 6/5)
    CHECK(s.samples[1].location.x == OneRoot(q("9/10")));
    CHECK(s.samples[1].location.y == OneRoot(q("6/5")));
  }
  SECTION("disk, property: random points land exactly on the circle, on the ray from the center") {
    rc::prop("snap to circle", [](int cx, int cy, unsigned r0, int px, int py, unsigned den) {
      Rational r(r0 % 50 + 1, den % 7 + 1);
      r.canonicalize();
      PointQ2 c{Rational(cx % 100), Rational(cy % 100)};
      PointQ2 p{Rational(px % 1000, 7), Rational(py % 1000, 3)};
      p.x.canonicalize();
      p.y.canonicalize();
      RC_PRE(p != c);
      Scene2 s = scene_of({disk("A", c, r)}, {sample(0, p, true)});
      validate_and_resolve(s);
      const OneRootPoint& loc = s.samples[0].location;
      RC_ASSERT(exactly_on_circle(loc, c, r));
      double dx = Rational(p.x - c.x).get_d(), dy = Rational(p.y - c.y).get_d(), len = std::hypot(dx, dy);
      RC_ASSERT(std::abs(loc.x.to_double() - (c.x.get_d() + r.get_d() * dx / len)) < 1e-9);
      RC_ASSERT(std::abs(loc.y.to_double() - (c.y.get_d() + r.get_d() * dy / len)) < 1e-9);
    });
  }
  SECTION("disk center: nearest point not unique") {
    CHECK_THAT(validation_error(scene_of({disk("A", pt(1, 1), 1)}, {sample(0, pt(1, 1), true)})),
               Catch::Contains("samples[0] (on \"A\"): point [1, 1] is the center of \"A\": the nearest boundary point "
                               "is not unique"));
  }
  SECTION("halfplane: exact orthogonal projection") {
    Scene2 s = scene_of({halfplane("B", pt(1, 2), 3)}, {sample(0, pt(5, 5), true)});
    validate_and_resolve(s);
    const OneRootPoint& loc = s.samples[0].location;
    REQUIRE(loc.is_rational());
    PointQ2 p{loc.x.a0, loc.y.a0};
    CHECK(s.halfspaces[0].side(p) == 0);
    // p - given is parallel to the normal
    CHECK((p.x - 5) * 2 - (p.y - 5) * 1 == 0);
    CHECK(p == PointQ2{q("13/5"), q("1/5")});
  }
  SECTION("polygon: nearest point over the edges, exact") {
    Scene2 s = scene_of({polygon("C", {pt(0, 0), pt(4, 0), pt(4, 3)})},
                        {sample(0, PointQ2{2, q("1/10")}, true), sample(0, pt(6, 5), true), sample(0, pt(0, 3), true)});
    validate_and_resolve(s);
    CHECK(s.samples[0].location.is_rational());
    CHECK(s.samples[0].location.x == OneRoot(Rational(2)));
    CHECK(s.samples[0].location.y == OneRoot(Rational(0)));
    CHECK(s.samples[1].location.x == OneRoot(Rational(4)));  // the vertex (4, 3)
    CHECK(s.samples[1].location.y == OneRoot(Rational(3)));
    // (0, 3): nearest on the hypotenuse y = 3x/4: t = (0*4 + 3*3)/25 -> (36/25, 27/25)
    CHECK(s.samples[2].location.x == OneRoot(q("36/25")));
    CHECK(s.samples[2].location.y == OneRoot(q("27/25")));
    for (const auto& smp : s.samples) {
      CHECK(s.halfspaces[0].side(PointQ2{smp.location.x.a0, smp.location.y.a0}) == 0);
    }
  }
  SECTION("polygon tie: the first edge in vertex order wins") {
    // (2, 2) is equally near to (2, 0) on edge 0 and (4, 2) on edge 1... and (0, 2) on edge 3.
    Scene2 s = scene_of({polygon("S", {pt(0, 0), pt(4, 0), pt(4, 4), pt(0, 4)})}, {sample(0, pt(2, 1), true),
                                                                                     sample(0, pt(2, 2), true)});
    validate_and_resolve(s);
    CHECK(s.samples[0].location.x == OneRoot(Rational(2)));
    CHECK(s.samples[0].location.y == OneRoot(Rational(0)));
    CHECK(s.samples[1].location.x == OneRoot(Rational(2)));
    CHECK(s.samples[1].location.y == OneRoot(Rational(0)));
  }
}

TEST_CASE("a given domain must contain the geometry", "[scene][domain]") {
  auto with_domain = [](Scene2 s, PointQ2 lo, PointQ2 hi) {
    s.domain = Box2{lo, hi};
    s.domain_given = true;
    return s;
  };
  CHECK(validation_error(with_domain(scene_of({disk("A", pt(0, 0), 2)}), pt(-2, -2), pt(2, 2))).empty());
  CHECK_THAT(validation_error(with_domain(scene_of({disk("A", pt(0, 0), 2)}), pt(-2, -2), pt(1, 2))),
             Catch::Contains("halfspaces[0] (\"A\"): the disk is not inside the domain [[-2, -2], [1, 2]]"));
  CHECK_THAT(validation_error(with_domain(scene_of({polygon("C", {pt(0, 0), pt(4, 0), pt(4, 3)})}), pt(-1, -1),
                                          pt(3, 5))),
             Catch::Contains("halfspaces[0] (\"C\"): vertex 1 [4, 0] is outside the domain"));
  CHECK_THAT(validation_error(with_domain(scene_of({halfplane("B", pt(0, 1), 1)}, {sample(0, pt(50, 1), false)}),
                                          pt(-10, -10), pt(10, 10))),
             Catch::Contains("samples[0] (on \"B\"): point [50, 1] is outside the domain"));
  // a snapped sample with an irrational location: exact comparison against the box
  CHECK(validation_error(with_domain(scene_of({disk("A", pt(0, 0), 2)}, {sample(0, pt(1, 1), true)}), pt(-2, -2),
                                     pt(2, 2)))
            .empty());
  CHECK_THAT(validation_error(with_domain(scene_of({disk("A", pt(0, 0), 1)}), pt(2, -2), pt(-2, 2))),
             Catch::Contains("domain: min must be below max"));
}

TEST_CASE("the chosen domain strictly contains the geometry", "[scene][domain]") {
  SECTION("disks, polygons, samples") {
    Scene2 s = scene_of({disk("A", pt(0, 0), q("3/2")), polygon("C", {pt(0, 0), pt(4, 0), pt(4, 3)}),
                         halfplane("B", pt(0, 1), 1)},
                        {sample(1, pt(4, 1), false)});
    validate_and_resolve(s);
    CHECK_FALSE(s.domain_given);
    CHECK(strictly_inside(s.domain, PointQ2{q("-3/2"), q("-3/2")}));
    CHECK(strictly_inside(s.domain, pt(4, 3)));
    CHECK(s.domain.min.x < s.domain.max.x);
    // deterministic
    Scene2 t = s;
    t.domain = {};
    validate_and_resolve(t);
    CHECK(t.domain.min == s.domain.min);
    CHECK(t.domain.max == s.domain.max);
  }
  SECTION("parallel half-planes only: every line crosses the box") {
    Scene2 s = scene_of({halfplane("a", pt(1, 1), 100), halfplane("b", pt(2, 2), -300), halfplane("c", pt(1, 1), 7)});
    validate_and_resolve(s);
    for (const auto& h : s.halfspaces) {
      int lo = 2, hi = -2;
      for (const auto& x : {s.domain.min.x, s.domain.max.x}) {
        for (const auto& y : {s.domain.min.y, s.domain.max.y}) {
          int v = sgn_q(h.normal.x * x + h.normal.y * y - h.offset);
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
      }
      CHECK(lo < 0);
      CHECK(hi > 0);
    }
  }
  SECTION("property: every pairwise line intersection is strictly inside, every line crosses") {
    rc::prop("lines", [](std::vector<std::tuple<int, int, int>> raw) {
      RC_PRE(!raw.empty());
      std::vector<Halfspace2> hs;
      for (std::size_t i = 0; i < raw.size() && i < 25; ++i) {
        auto [a, b, o] = raw[i];
        a %= 5;
        b %= 5;
        if (a == 0 && b == 0) b = 1;
        hs.push_back(halfplane("h" + std::to_string(i), PointQ2{Rational(a), Rational(b)}, Rational(o % 30)));
      }
      Scene2 s = scene_of(hs);
      validate_and_resolve(s);
      for (std::size_t i = 0; i < hs.size(); ++i) {
        const auto& l = hs[i];
        bool neg = false, pos = false;
        for (const auto& x : {s.domain.min.x, s.domain.max.x}) {
          for (const auto& y : {s.domain.min.y, s.domain.max.y}) {
            int v = sgn_q(l.normal.x * x + l.normal.y * y - l.offset);
            neg |= v < 0;
            pos |= v > 0;
          }
        }
        RC_ASSERT(neg && pos);
        for (std::size_t j = i + 1; j < hs.size(); ++j) {
          const auto& m = hs[j];
          Rational det = l.normal.x * m.normal.y - l.normal.y * m.normal.x;
          if (det == 0) continue;
          PointQ2 x{(l.offset * m.normal.y - m.offset * l.normal.y) / det,
                    (l.normal.x * m.offset - m.normal.x * l.offset) / det};
          RC_ASSERT(strictly_inside(s.domain, x));
        }
      }
    });
  }
}

TEST_CASE("random simple polygons are accepted, polygons with a forced crossing are rejected", "[scene][property]") {
  rc::prop("star-shaped polygons are simple", [](std::vector<std::pair<int, int>> dirs, std::vector<int> radii,
                                                 int cx, int cy, bool clockwise) {
    for (auto& d : dirs) d = {d.first % 20, d.second % 20};
    for (auto& r : radii) r = std::abs(r % 30) + 1;
    auto v = star_polygon(PointQ2{Rational(cx % 100, 7), Rational(cy % 100)}, dirs, radii, clockwise);
    Scene2 s = scene_of({polygon("P", v)});
    std::string err = validation_error(s);
    RC_ASSERT(err.empty());
    RC_ASSERT((signed_area(v) > 0) == !clockwise);
  });
  rc::prop("a forced crossing is rejected", [](unsigned a, unsigned b, unsigned c, unsigned d, int ox, int oy,
                                               std::vector<std::pair<int, int>> extra) {
    // edges 0 (A -> B) and 2 (C -> D) cross at (ox, oy); extra vertices after D stay far to the left
    PointQ2 o{Rational(ox % 100), Rational(oy % 100)};
    PointQ2 A{o.x - Rational(a % 50 + 1), o.y}, B{o.x + Rational(b % 50 + 1), o.y};
    PointQ2 C{o.x, o.y - Rational(c % 50 + 1)}, D{o.x, o.y + Rational(d % 50 + 1)};
    std::vector<PointQ2> v = {A, B, C, D};
    for (std::size_t i = 0; i < extra.size() && i < 20; ++i) {
      v.push_back(PointQ2{o.x - 1000 - std::abs(extra[i].first % 500), Rational(extra[i].second % 500)});
    }
    std::string err = validation_error(scene_of({polygon("X", v)}));
    RC_ASSERT(err.rfind("halfspaces[0] (\"X\"): polygon", 0) == 0);
    if (extra.empty()) {
      RC_ASSERT(err == "halfspaces[0] (\"X\"): polygon is self-intersecting: edges 0 and 2 cross at [" +
                           exact_string(o.x) + ", " + exact_string(o.y) + "]");
    }
  });
}

TEST_CASE("large polygons: 5,000 vertices are checked quickly, more are refused", "[scene][limits]") {
  auto regular = [](std::size_t n) {
    // rational points on a circle-like star: (cos, sin) approximated by rationals with distinct angles
    std::vector<PointQ2> v;
    for (std::size_t i = 0; i < n; ++i) {
      double t = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
      Rational x(static_cast<long>(std::llround(std::cos(t) * 1e9)), 1000000000L);
      Rational y(static_cast<long>(std::llround(std::sin(t) * 1e9)), 1000000000L);
      x.canonicalize();
      y.canonicalize();
      v.push_back(PointQ2{x, y});
    }
    return v;
  };
  auto start = std::chrono::steady_clock::now();
  CHECK(validation_error(scene_of({polygon("P", regular(5000))})).empty());
  CHECK_THAT(validation_error(scene_of({polygon("P", regular(10000))})),
             Catch::Contains("halfspaces[0] (\"P\"): polygon has 10000 vertices; the limit is 5000"));
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(seconds < 10.0);
}

TEST_CASE("10,000 half-planes and disks validate quickly", "[scene][limits]") {
  std::vector<Halfspace2> hs;
  for (int i = 0; i < 10000; ++i) {
    if (i % 2 == 0) {
      hs.push_back(halfplane("h" + std::to_string(i), pt(i % 97 + 1, i % 89 - 44), i % 101));
    } else {
      hs.push_back(disk("d" + std::to_string(i), pt(i % 300, i % 211), Rational(i % 7 + 1)));
    }
  }
  auto start = std::chrono::steady_clock::now();
  Scene2 s = scene_of(hs);
  validate_and_resolve(s);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(seconds < 10.0);
  CHECK(s.domain.min.x < s.domain.max.x);
}

TEST_CASE("the simplicity filter leaves near misses and huge coordinates to exact arithmetic", "[scene][filter]") {
  // Vertex 3 lies 2^-80 above (or on, or below) edge 0 from (0,0) to (3,1): in doubles 1/2 + 2^-80 is 1/2, so only
  // a certified filter that falls back to exact predicates gets all three right.
  const Rational tiny = Rational(1) / Rational(Integer(1) << 80);
  auto with = [](const Rational& dy, const Rational& scale) {
    auto p = [&](const Rational& x, const Rational& y) { return PointQ2{Rational(x * scale), Rational(y * scale)}; };
    return scene_of({polygon("C", {p(0, 0), p(3, 1), p(3, 3), p(Rational(3, 2), Rational(Rational(1, 2) + dy)),
                                   p(0, 3)})});
  };
  // ordinary, tiny and beyond-double magnitudes (the filter is skipped above 2^500; below, intervals hold 0)
  for (const Rational& scale : {Rational(1), make_rational(Integer(1), Integer(1) << 600), Rational(Integer(1) << 1100)}) {
    INFO("scale " << scale.get_d());
    CHECK(validation_error(with(tiny, scale)).empty());
    CHECK_THAT(validation_error(with(Rational(0), scale)), Catch::Contains("touch"));
    CHECK_THAT(validation_error(with(Rational(-tiny), scale)), Catch::Contains("self-intersecting"));
  }
}
