// Tests of geometry/scene3 and geometry/tessellate3: exact sides, validation (each bad input refused with its
// message), sample snapping against a brute-force oracle on random rational points, tessellations closed, manifold,
// outward and converging to the analytic volume, OBJ/OFF/PLY readers giving the same mesh, and the BSH authors'
// nine examples (hidden test [bsh_examples], run by ctest corpus_bsh_examples, skipped without the data).
#include <hsx/geometry/mesh3.hpp>
#include <hsx/geometry/scene3.hpp>
#include <hsx/geometry/tessellate3.hpp>
#include <hsx/io/bsh_config.hpp>
#include <hsx/io/bsh_reference.hpp>
#include <hsx/io/exact_json.hpp>
#include <hsx/io/scene_json.hpp>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

using namespace hsx;
using Catch::Matchers::Contains;

namespace {

Rational frac(long n, long d) { return make_rational(Integer(n), Integer(d)); }
PointQ3 pt(long x, long y, long z) { return PointQ3{Rational(x), Rational(y), Rational(z)}; }

Halfspace3 primitive(HalfspaceKind3 kind, const std::string& name = "A") {
  Halfspace3 h;
  h.name = name;
  h.kind = kind;
  return h;
}

Halfspace3 sphere(const PointQ3& c, const Rational& r, int segments = 16) {
  Halfspace3 h = primitive(HalfspaceKind3::Sphere);
  h.primitive.center = c;
  h.primitive.radius = r;
  h.primitive.tessellation.segments = segments;
  h.surface = tessellate(h, Box3{});
  return h;
}

Halfspace3 box(const PointQ3& lo, const PointQ3& hi, const std::string& name = "A") {
  Halfspace3 h = primitive(HalfspaceKind3::Box, name);
  h.primitive.min = lo;
  h.primitive.max = hi;
  h.surface = tessellate(h, Box3{});
  return h;
}

Halfspace3 plane(const PointQ3& n, const Rational& offset, const std::string& name = "P") {
  Halfspace3 h = primitive(HalfspaceKind3::Plane, name);
  h.normal = n;
  h.offset = offset;
  return h;
}

Mesh3 checked(const TriangleSurface& s) {
  ObjMesh obj;
  obj.source = "tessellation";
  obj.vertices = s.vertices;
  obj.faces = s.triangles;
  return build_mesh3(obj);
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

Scene3 one(Halfspace3 h) {
  Scene3 s;
  s.halfspaces.push_back(std::move(h));
  return s;
}

}  // namespace

TEST_CASE("tessellations are closed, manifold, outward, and converge to the analytic volume", "[scene3]") {
  const double pi = M_PI;
  struct Case {
    const char* name;
    std::function<Halfspace3(int)> make;
    double volume;
  };
  auto with = [](HalfspaceKind3 kind, int n, const std::function<void(Primitive3&)>& set) {
    Halfspace3 h = primitive(kind);
    set(h.primitive);
    h.primitive.tessellation.segments = n;
    h.surface = tessellate(h, Box3{pt(-10, -10, -10), pt(10, 10, 10)});
    return h;
  };
  const std::vector<Case> cases = {
      {"sphere", [&](int n) { return with(HalfspaceKind3::Sphere, n, [](Primitive3& p) { p.center = pt(1, 2, 3); p.radius = 2; }); },
       4.0 / 3 * pi * 8},
      {"cylinder", [&](int n) { return with(HalfspaceKind3::Cylinder, n, [](Primitive3& p) {
         p.point1 = pt(0, 0, 0); p.point2 = pt(1, 2, 2); p.radius = 1; }); }, pi * 3},
      {"cone", [&](int n) { return with(HalfspaceKind3::Cone, n, [](Primitive3& p) {
         p.point1 = pt(0, 0, 3); p.point2 = pt(0, 0, 0); p.radius = 2; }); }, pi * 4 * 3 / 3},
      {"torus", [&](int n) { return with(HalfspaceKind3::Torus, n, [](Primitive3& p) {
         p.center = pt(0, 0, 0); p.axis = pt(1, 1, 1); p.major_radius = 3; p.minor_radius = 1; }); },
       2 * pi * pi * 3},
      {"infinite cylinder", [&](int n) { return with(HalfspaceKind3::Cylinder, n, [](Primitive3& p) {
         p.point1 = pt(0, 0, 0); p.point2 = pt(0, 0, 1); p.radius = 2; p.infinite = true; }); }, pi * 4 * 20},
      {"infinite cylinder crossing the box", [&](int n) { return with(HalfspaceKind3::Cylinder, n, [](Primitive3& p) {
         p.point1 = pt(9, 0, 0); p.point2 = pt(9, 1, 1); p.radius = 2; p.infinite = true; }); }, -1},
  };
  for (const Case& c : cases) {
    SECTION(c.name) {
      double previous_error = 1e9;
      for (int n : {8, 32, 128}) {
        const Halfspace3 h = c.make(n);
        const Mesh3 m = checked(h.surface);
        INFO(c.name << " n=" << n);
        CHECK_FALSE(m.flipped);
        CHECK(m.shells == 1);
        if (c.volume < 0) {
          CHECK(m.volume > 0);
          continue;
        }
        const double error = std::abs(m.volume.get_d() - c.volume) / c.volume;
        CHECK(error < previous_error);
        previous_error = error;
        if (n == 128) CHECK(error < 0.01);
      }
    }
  }
  SECTION("box") {
    const Mesh3 m = checked(box(pt(0, 0, 0), pt(1, 2, 3)).surface);
    CHECK(m.faces.size() == 12);
    CHECK(m.volume == 6);
    CHECK_FALSE(m.flipped);
  }
  SECTION("deterministic vertices on the 2^-32 grid") {
    const Halfspace3 a = sphere(pt(0, 0, 0), frac(1, 3), 12), b = sphere(pt(0, 0, 0), frac(1, 3), 12);
    CHECK(a.surface.vertices == b.surface.vertices);
    for (const PointQ3& p : a.surface.vertices)
      for (const Rational* c : {&p.x, &p.y, &p.z}) CHECK(mpz_sizeinbase(c->get_den_mpz_t(), 2) <= 33);
    const PointQ3& south = a.surface.vertices.front();  // c - r w, rounded to the grid
    CHECK(south.x == 0);
    CHECK(south.y == 0);
    CHECK(abs(south.z + frac(1, 3)) <= make_rational(Integer(1), Integer(1) << 33));
  }
  SECTION("segment counts: the authors' rule and the bounds") {
    CHECK(bsh_segments(0.404, 5.37126) == 84);
    CHECK(bsh_segments(0.404, 0.1) == 15);
    Tessellation3 t;
    t.segments = 2;
    CHECK_THROWS_WITH(circle_segments(t, Rational(1)), Contains("outside the bounds [3, 4096]"));
    t.mode = Tessellation3::Mode::EdgeLength;
    t.edge_length = frac(1, 1000000);
    CHECK_THROWS_WITH(circle_segments(t, Rational(1)), Contains("outside the bounds"));
    t.edge_length = Rational(100);
    CHECK(circle_segments(t, Rational(1)) == 3);
    t.edge_length = frac(1, 10);
    CHECK(circle_segments(t, Rational(1)) == 63);
  }
}

namespace {

/// An independent rebuild of the documented vertex rule in long double: the frame of axis a, the ring formula, and
/// the rounding to the nearest multiple of 2^-32.
struct FrameLD {
  long double u[3], v[3], w[3];
};

FrameLD frame_ld(long double ax, long double ay, long double az) {
  FrameLD f;
  const long double n = std::sqrt(ax * ax + ay * ay + az * az);
  f.w[0] = ax / n, f.w[1] = ay / n, f.w[2] = az / n;
  const long double a[3] = {std::fabs(ax), std::fabs(ay), std::fabs(az)};
  const int e = a[0] <= a[1] && a[0] <= a[2] ? 0 : (a[1] <= a[2] ? 1 : 2);
  const long double E[3] = {e == 0 ? 1.0L : 0.0L, e == 1 ? 1.0L : 0.0L, e == 2 ? 1.0L : 0.0L};
  long double c[3] = {f.w[1] * E[2] - f.w[2] * E[1], f.w[2] * E[0] - f.w[0] * E[2], f.w[0] * E[1] - f.w[1] * E[0]};
  const long double cn = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  for (int i = 0; i < 3; ++i) f.u[i] = c[i] / cn;
  f.v[0] = f.w[1] * f.u[2] - f.w[2] * f.u[1];
  f.v[1] = f.w[2] * f.u[0] - f.w[0] * f.u[2];
  f.v[2] = f.w[0] * f.u[1] - f.w[1] * f.u[0];
  return f;
}

Rational grid(long double x) {
  const long double scaled = std::nearbyint(std::ldexp(x, 32));
  return make_rational(Integer(std::to_string(static_cast<long long>(scaled))), Integer(1) << 32);
}

}  // namespace

TEST_CASE("the documented vertex rule rebuilds the same vertices", "[scene3]") {
  const long double pi = 3.141592653589793238462643383279502884L;
  SECTION("torus about a general axis") {
    Halfspace3 h = primitive(HalfspaceKind3::Torus);
    h.primitive.center = PointQ3{frac(1, 2), Rational(-1), Rational(2)};
    h.primitive.axis = pt(1, 2, 3);
    h.primitive.major_radius = 3;
    h.primitive.minor_radius = frac(3, 4);
    h.primitive.tessellation.segments = 10;
    h.primitive.tessellation.minor_segments = 6;
    h.surface = tessellate(h, Box3{});
    const FrameLD f = frame_ld(1, 2, 3);
    const long double c[3] = {0.5L, -1, 2};
    REQUIRE(h.surface.vertices.size() == 60);
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 10; ++k) {
        const long double t = 2 * pi * k / 10, phi = 2 * pi * j / 6, rho = 3 + 0.75L * std::cos(phi);
        const PointQ3& got = h.surface.vertices[static_cast<std::size_t>(j * 10 + k)];
        long double x[3];
        for (int i = 0; i < 3; ++i)
          x[i] = c[i] + rho * (std::cos(t) * f.u[i] + std::sin(t) * f.v[i]) + 0.75L * std::sin(phi) * f.w[i];
        CHECK(got == PointQ3{grid(x[0]), grid(x[1]), grid(x[2])});
      }
    CHECK(h.surface.triangles[0] == std::array<int, 3>{0, 1, 10});
    CHECK(h.surface.triangles[1] == std::array<int, 3>{1, 11, 10});
  }
  SECTION("sphere: poles, rings and fans") {
    const Halfspace3 h = sphere(pt(1, 2, 3), Rational(2), 8);  // m = 4 bands: rings at -45, 0, 45 degrees
    const FrameLD f = frame_ld(0, 0, 1);
    CHECK(f.u[1] == 1);
    REQUIRE(h.surface.vertices.size() == 2 + 3 * 8);
    CHECK(h.surface.vertices[0] == pt(1, 2, 1));
    CHECK(h.surface.vertices[25] == pt(1, 2, 5));
    for (int j = 1; j <= 3; ++j)
      for (int k = 0; k < 8; ++k) {
        const long double t = 2 * pi * k / 8, phi = -pi / 2 + pi * j / 4;
        const long double c[3] = {1, 2, 3};
        long double x[3];
        for (int i = 0; i < 3; ++i)
          x[i] = c[i] + 2 * std::cos(phi) * (std::cos(t) * f.u[i] + std::sin(t) * f.v[i]) + 2 * std::sin(phi) * f.w[i];
        CHECK(h.surface.vertices[static_cast<std::size_t>(1 + (j - 1) * 8 + k)] == PointQ3{grid(x[0]), grid(x[1]), grid(x[2])});
      }
    CHECK(h.surface.triangles[0] == std::array<int, 3>{0, 2, 1});     // south fan (S, L_k+1, L_k)
    CHECK(h.surface.triangles.back() == std::array<int, 3>{25, 24, 17});  // north fan (N, U_7, U_0)
  }
}

TEST_CASE("exact sides", "[scene3]") {
  const Halfspace3 p = plane(pt(0, 0, 2), Rational(1));  // z <= 1/2
  CHECK(p.side(PointQ3{Rational(5), Rational(0), frac(1, 2)}) == 0);
  CHECK(p.side(pt(0, 0, 0)) == 1);
  CHECK(p.side(pt(0, 0, 1)) == -1);
  Halfspace3 b = box(pt(0, 0, 0), pt(2, 2, 2));
  CHECK(b.side(pt(1, 1, 1)) == 1);
  CHECK(b.side(pt(3, 1, 1)) == -1);
  CHECK(b.side(pt(2, 1, 1)) == 0);   // on a face
  CHECK(b.side(pt(2, 2, 1)) == 0);   // on an edge
  CHECK(b.side(pt(0, 0, 0)) == 0);   // a vertex
  CHECK(b.side(pt(1, 1, 2)) == 0);   // on a diagonal of a face's two triangles
  b.complement = true;
  CHECK(b.side(pt(1, 1, 1)) == -1);
  CHECK(b.side(pt(3, 1, 1)) == 1);
  const Halfspace3 s = sphere(pt(0, 0, 0), Rational(1), 8);
  CHECK(s.side(pt(0, 0, 0)) == 1);
  CHECK(s.side(pt(0, 0, 2)) == -1);
  CHECK(s.side(s.surface.vertices[5]) == 0);
}

namespace {

/// Brute-force oracle: the squared distance from p to triangle abc as the minimum over the projection into the
/// face (when inside) and the three closed edges (clamped parameter), all exact.
Rational brute_distance2(const PointQ3& p, const PointQ3& a, const PointQ3& b, const PointQ3& c) {
  auto sub = [](const PointQ3& u, const PointQ3& v) { return PointQ3{u.x - v.x, u.y - v.y, u.z - v.z}; };
  auto segment = [&](const PointQ3& u, const PointQ3& v) {
    const PointQ3 d = sub(v, u);
    Rational t = dot3(sub(p, u), d) / dot3(d, d);
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    const PointQ3 q{u.x + t * d.x, u.y + t * d.y, u.z + t * d.z};
    return dot3(sub(q, p), sub(q, p));
  };
  Rational best = std::min({segment(a, b), segment(b, c), segment(c, a)});
  const PointQ3 n = triangle_normal(a, b, c);
  const Rational t = dot3(sub(p, a), n) / dot3(n, n);
  const PointQ3 q{p.x - t * n.x, p.y - t * n.y, p.z - t * n.z};
  if (sgn(dot3(n, triangle_normal(q, a, b))) >= 0 && sgn(dot3(n, triangle_normal(q, b, c))) >= 0 &&
      sgn(dot3(n, triangle_normal(q, c, a))) >= 0)
    best = std::min(best, Rational(t * t * dot3(n, n)));
  return best;
}

}  // namespace

TEST_CASE("near samples snap to the exact nearest point (against brute force)", "[scene3]") {
  // The third shape sits at 10^12, where doubles cancel: the pruning bounds must stay lower bounds there.
  const long far = 1000000000000L;
  const std::vector<Halfspace3> shapes = {sphere(pt(0, 0, 0), Rational(3), 10), box(pt(-2, -1, 0), pt(2, 1, 3)),
                                          box(pt(far, far, far), pt(far + 1, far + 2, far + 1))};
  rc::prop("random rational points", [&] {
    const int which = *rc::gen::inRange(0, 3);
    const auto& h = shapes[static_cast<std::size_t>(which)];
    const Rational offset = which == 2 ? Rational(far) : Rational(0);
    const auto coordinate = [&]() -> Rational { return offset + frac(*rc::gen::inRange(-400, 401), *rc::gen::inRange(1, 60)); };
    Scene3 scene = one(h);
    Sample3 s;
    s.halfspace = 0;
    s.snapped = true;
    s.given = PointQ3{coordinate(), coordinate(), coordinate()};
    scene.samples.push_back(s);
    validate_and_resolve(scene);
    const Sample3& r = scene.samples[0];
    Rational best = -1;
    for (const auto& t : h.surface.triangles) {
      const Rational d = brute_distance2(s.given, h.surface.vertices[t[0]], h.surface.vertices[t[1]], h.surface.vertices[t[2]]);
      if (best < 0 || d < best) best = d;
    }
    RC_ASSERT(r.distance2 == best);
    const PointQ3 diff{r.location.x - s.given.x, r.location.y - s.given.y, r.location.z - s.given.z};
    RC_ASSERT(dot3(diff, diff) == r.distance2);
    RC_ASSERT(h.side(r.location) == 0);  // exactly on the boundary
  });
  SECTION("a plane: orthogonal projection") {
    Scene3 scene = one(plane(pt(1, 1, 0), Rational(2)));
    scene.samples.push_back(Sample3{0, pt(3, 3, 7), true, {}, {}});
    validate_and_resolve(scene);
    CHECK(scene.samples[0].location == pt(1, 1, 7));
    CHECK(scene.samples[0].distance2 == 8);
  }
  SECTION("an exact sample on a box face is kept; ties take the lowest triangle") {
    Scene3 scene = one(box(pt(0, 0, 0), pt(2, 2, 2)));
    scene.samples.push_back(Sample3{0, PointQ3{Rational(1), Rational(1), Rational(2)}, false, {}, {}});
    scene.samples.push_back(Sample3{0, pt(1, 1, 1), true, {}, {}});  // the centre: six faces equally near
    validate_and_resolve(scene);
    CHECK(scene.samples[0].location == scene.samples[0].given);
    CHECK(scene.samples[1].distance2 == 1);
    CHECK(scene.samples[1].location == pt(1, 1, 0));  // triangles 0 and 1 are the z = min face
  }
}

TEST_CASE("bad 3D input is refused with its message", "[scene3]") {
  auto surface_scene = [](std::vector<PointQ3> v, std::vector<std::array<int, 3>> t) {
    Halfspace3 h = primitive(HalfspaceKind3::Mesh, "M");
    h.surface.vertices = std::move(v);
    h.surface.triangles = std::move(t);
    return one(std::move(h));
  };
  const std::vector<PointQ3> tet = {pt(0, 0, 0), pt(1, 0, 0), pt(0, 1, 0), pt(0, 0, 1)};
  SECTION("open") {
    Scene3 s = surface_scene(tet, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}});
    CHECK_THAT(error_of([&] { validate_and_resolve(s); }), Contains("halfspaces[0] (\"M\")") && Contains("not closed"));
  }
  SECTION("inconsistently oriented") {
    Scene3 s = surface_scene(tet, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 3, 2}});
    CHECK_THAT(error_of([&] { validate_and_resolve(s); }), Contains("inconsistent orientation"));
  }
  SECTION("non-manifold: two tetrahedra sharing an edge through four faces") {
    std::vector<PointQ3> v = tet;
    v.push_back(pt(-1, 0, 0));
    v.push_back(pt(0, -1, 0));
    Scene3 s = surface_scene(v, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 5}, {0, 3, 4}, {0, 5, 3}, {4, 3, 5}});
    CHECK_THAT(error_of([&] { validate_and_resolve(s); }), Contains("not edge-manifold"));
  }
  SECTION("non-manifold: two tetrahedra sharing a vertex") {
    std::vector<PointQ3> v = tet;
    v.push_back(pt(-1, 0, 0));
    v.push_back(pt(0, -1, 0));
    v.push_back(pt(0, 0, -1));
    Scene3 s = surface_scene(v, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 5}, {0, 5, 6}, {0, 6, 4}, {4, 6, 5}});
    CHECK_THAT(error_of([&] { validate_and_resolve(s); }), Contains("not vertex-manifold"));
  }
  SECTION("degenerate: a zero-area triangle") {
    std::vector<PointQ3> v = {pt(0, 0, 0), pt(1, 0, 0), pt(2, 0, 0), pt(0, 1, 0)};
    Scene3 s = surface_scene(v, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}});
    CHECK_THAT(error_of([&] { validate_and_resolve(s); }), Contains("zero-area triangle"));
  }
  SECTION("inward surfaces are reversed with a note") {
    Scene3 s = surface_scene(tet, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
    validate_and_resolve(s);
    REQUIRE(s.notes.size() == 1);
    CHECK_THAT(s.notes[0], Contains("oriented inward"));
    CHECK(checked(s.halfspaces[0].surface).flipped == false);
  }
  SECTION("radius <= 0, zero-length axis, bad torus") {
    Halfspace3 h = primitive(HalfspaceKind3::Sphere);
    h.primitive.radius = 0;
    CHECK_THAT(error_of([&] { tessellate(h, Box3{}); }), Contains("radius must be positive"));
    h.kind = HalfspaceKind3::Cylinder;
    h.primitive.radius = 1;
    h.primitive.point1 = h.primitive.point2 = pt(1, 1, 1);
    CHECK_THAT(error_of([&] { tessellate(h, Box3{}); }), Contains("zero length"));
    h.kind = HalfspaceKind3::Torus;
    h.primitive.axis = pt(0, 0, 1);
    h.primitive.major_radius = 1;
    h.primitive.minor_radius = 1;
    CHECK_THAT(error_of([&] { tessellate(h, Box3{}); }), Contains("must be below major_radius"));
  }
  SECTION("tessellation out of bounds") {
    Halfspace3 h = primitive(HalfspaceKind3::Sphere);
    h.primitive.radius = 1;
    h.primitive.tessellation.segments = 5000;
    CHECK_THAT(error_of([&] { tessellate(h, Box3{}); }), Contains("outside the bounds"));
    h.primitive.tessellation.segments = 4000;  // 4000 x 2000 x 2 triangles
    CHECK_THAT(error_of([&] { tessellate(h, Box3{}); }), Contains("the limit is 2000000"));
  }
  SECTION("a mesh outside the domain") {
    Scene3 s = one(box(pt(0, 0, 0), pt(5, 1, 1)));
    s.domain = Box3{pt(-1, -1, -1), pt(4, 4, 4)};
    s.domain_given = true;
    CHECK_THAT(error_of([&] { validate_and_resolve(s); }), Contains("is outside the domain"));
  }
  SECTION("an infinite cylinder that misses the domain") {
    Halfspace3 h = primitive(HalfspaceKind3::Cylinder);
    h.primitive.point1 = pt(50, 0, 0);
    h.primitive.point2 = pt(50, 0, 1);
    h.primitive.radius = 1;
    h.primitive.infinite = true;
    CHECK_THAT(error_of([&] { tessellate(h, Box3{pt(0, 0, 0), pt(1, 1, 1)}); }), Contains("does not cross the domain"));
  }
  SECTION("a sample on no surface") {
    Scene3 s = one(box(pt(0, 0, 0), pt(2, 2, 2)));
    s.samples.push_back(Sample3{0, pt(1, 1, 1), false, {}, {}});
    CHECK_THAT(error_of([&] { validate_and_resolve(s); }),
               Contains("samples[0] (on \"A\")") && Contains("is not on the boundary") && Contains("about 1 away"));
    Scene3 t = one(plane(pt(0, 0, 1), Rational(0)));
    t.samples.push_back(Sample3{0, pt(1, 1, 1), false, {}, {}});
    CHECK_THAT(error_of([&] { validate_and_resolve(t); }), Contains("is not on the plane"));
  }
  SECTION("no halfspace; zero plane normal") {
    Scene3 s;
    CHECK_THAT(error_of([&] { validate_and_resolve(s); }), Contains("no halfspace"));
    Scene3 t = one(plane(pt(0, 0, 0), Rational(1)));
    CHECK_THAT(error_of([&] { validate_and_resolve(t); }), Contains("normal must not be zero"));
  }
}

TEST_CASE("the chosen domain contains surfaces, samples and plane triple points", "[scene3]") {
  Scene3 s;
  s.halfspaces.push_back(plane(pt(1, 0, 0), Rational(10), "X"));
  s.halfspaces.push_back(plane(pt(0, 1, 0), Rational(-10), "Y"));
  s.halfspaces.push_back(plane(pt(0, 0, 1), Rational(20), "Z"));
  s.halfspaces.push_back(box(pt(0, 0, 0), pt(1, 1, 1), "B"));
  s.halfspaces.push_back(plane(pt(0, 0, 1), Rational(-100), "far"));  // parallel to Z: must still cross the box
  validate_and_resolve(s);
  const Box3& d = s.domain;
  CHECK(d.min.x < 0);
  CHECK(d.max.x > 10);
  CHECK(d.min.y < -10);
  CHECK(d.max.z > 20);
  CHECK(d.min.z < -100);
  CHECK_FALSE(s.domain_given);
  Scene3 many;
  for (std::size_t i = 0; i <= kMaxPlanesWithoutDomain; ++i)
    many.halfspaces.push_back(plane(pt(1, static_cast<long>(i), static_cast<long>(i * i)), Rational(1), "P" + std::to_string(i)));
  CHECK_THAT(error_of([&] { validate_and_resolve(many); }), Contains("domain: the scene has 151 planes and no domain"));
}

TEST_CASE("OBJ, OFF and PLY of the same mesh give the same ObjMesh", "[scene3]") {
  const std::string obj = "# tetrahedron\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 0.5\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const std::string off = "OFF\n# tetrahedron\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 0.5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::string ply =
      "ply\nformat ascii 1.0\ncomment tetrahedron\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
      "0 0 0.5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  std::istringstream a(obj), b(off), c(ply);
  const ObjMesh mo = read_obj(a, "t.obj"), mf = read_off(b, "t.off"), mp = read_ply(c, "t.ply");
  CHECK(mo.vertices == mf.vertices);
  CHECK(mo.vertices == mp.vertices);
  CHECK(mo.faces == mf.faces);
  CHECK(mo.faces == mp.faces);
  CHECK(mo.vertices[3].z == frac(1, 2));
  CHECK(build_mesh3(mp).volume == frac(1, 12));
  SECTION("errors name the file and line") {
    auto off_error = [](const std::string& text) {
      return error_of([&] { std::istringstream in(text); read_off(in, "m.off"); });
    };
    auto ply_error = [](const std::string& text) {
      return error_of([&] { std::istringstream in(text); read_ply(in, "m.ply"); });
    };
    CHECK_THAT(off_error("OFF\n1 1 0\n0 0 x\n3 0 0 0\n"), Contains("m.off:3: coordinate 3 \"x\""));
    CHECK_THAT(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 0\n"), Contains("m.off:6: face with 4 vertices"));
    CHECK_THAT(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"), Contains("m.off:6: vertex id \"7\" out of range"));
    CHECK_THAT(off_error("3 1 0\n"), Contains("m.off:1: an OFF file starts with \"OFF\""));
    CHECK_THAT(ply_error("ply\nformat binary_little_endian 1.0\nend_header\n"), Contains("m.ply:2: only ASCII PLY"));
    CHECK_THAT(ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n"),
               Contains("needs properties x, y and z"));
    // A face's values past its one property are an error; after further properties they are those properties'.
    std::string extra = ply;
    extra.replace(extra.rfind("3 1 2 3\n"), 8, "3 1 2 3 4\n");
    CHECK_THAT(ply_error(extra), Contains("m.ply:18: more values than the face element's one property"));
    // Hostile bytes in a message are escaped, and a long token is cut.
    CHECK_THAT(ply_error("ply\nformat ascii 1.0\n\x1b[2Jbad\nend_header\n"),
               Contains("m.ply:3: unknown header line \"\\x1b[2Jbad\""));
    CHECK_THAT(ply_error("ply\nformat ascii 1.0\n" + std::string(50, 'w') + "\nend_header\n"),
               Contains("unknown header line \"" + std::string(40, 'w') + "...\""));
    // Property types are PLY's: a list counts with an integer type, and face indices are integers.
    std::string typed = ply;
    typed.replace(typed.find("list uchar int"), 14, "list float int");
    CHECK_THAT(ply_error(typed), Contains("m.ply:9: a list's count type \"float\" is not a PLY integer type"));
    typed = ply;
    typed.replace(typed.find("list uchar int"), 14, "list uchar double");
    CHECK_THAT(ply_error(typed), Contains("m.ply:9: the list's value type \"double\" is not a PLY integer type"));
    typed = ply;
    typed.replace(typed.find("property float z"), 16, "property real z");
    CHECK_THAT(ply_error(typed), Contains("m.ply:7: property type \"real\" is not a PLY type"));
    typed = ply;
    typed.replace(typed.find("property float y"), 16, "property float64 y");
    typed.replace(typed.find("list uchar int"), 14, "list uint8 uint32");
    std::istringstream sized(typed);
    CHECK(read_ply(sized, "m.ply").faces == mp.faces);
    std::string coloured = extra;
    coloured.replace(coloured.find("end_header"), 10, "property uchar red\nend_header");
    std::istringstream in(coloured);
    CHECK(read_ply(in, "m.ply").faces == mp.faces);
  }
}

TEST_CASE("the BSH authors' nine examples", "[.][bsh_examples]") {
  const char* env = std::getenv("HSX_BSH_DATA");
  const std::filesystem::path dir = env ? env : std::string(HSX_SOURCE_DIR) + "/../shared/data/bsh-examples";
  if (!std::filesystem::exists(dir / "figure19_b" / "config.json")) {
    std::cout << "SKIPPED: BSH examples not present at " << dir << "\n";
    std::exit(77);
  }
  int read = 0;
  for (const char* name : {"figure15_a", "figure15_b", "figure15_c", "figure15_d", "figure16_sphere_torus",
                           "figure16_tori", "figure19_b", "figure19_c", "figure19_d"}) {
    INFO(name);
    const Scene3 s = read_bsh_config_file((dir / name / "config.json").string());
    CHECK(read_scene3_input_file((dir / name / "config.json").string()).samples.size() == s.samples.size());
    CHECK(s.domain_given);
    CHECK_FALSE(s.samples.empty());
    std::size_t triangles = 0;
    for (const Halfspace3& h : s.halfspaces) triangles += h.surface.triangles.size();
    std::cout << name << ": " << s.halfspaces.size() << " halfspaces, " << triangles << " triangles, "
              << s.samples.size() << " samples\n";
    // Their tessellation (Mesh_BSH.cpp): every vertex of our curved surfaces inside the box is one of the vertices
    // of their reference-result.grid, within 2^-30 per coordinate (ours are rounded to 2^-32, theirs doubles).
    const BshReference theirs = read_bsh_reference_file((dir / name / "reference-result.grid").string());
    auto cell = [](double x) { return static_cast<long>(std::floor(std::ldexp(x, 20))); };
    std::vector<std::array<double, 3>> theirs_d;
    std::map<std::array<long, 3>, std::vector<std::size_t>> in_cell;  // their vertices by cells of side 2^-20
    for (const PointQ3& v : theirs.vertices) {
      theirs_d.push_back({v.x.get_d(), v.y.get_d(), v.z.get_d()});
      const auto& d = theirs_d.back();
      in_cell[{cell(d[0]), cell(d[1]), cell(d[2])}].push_back(theirs_d.size() - 1);
    }
    auto found = [&](const PointQ3& p) {
      const double q[3] = {p.x.get_d(), p.y.get_d(), p.z.get_d()};
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            auto it = in_cell.find({cell(q[0]) + dx, cell(q[1]) + dy, cell(q[2]) + dz});
            if (it == in_cell.end()) continue;
            for (std::size_t k : it->second) {
              double d = 0;
              for (int i = 0; i < 3; ++i) d = std::max(d, std::abs(theirs_d[k][i] - q[i]));
              if (d <= std::ldexp(1.0, -30)) return true;
            }
          }
      return false;
    };
    for (const Halfspace3& h : s.halfspaces) {
      if (h.kind != HalfspaceKind3::Sphere && h.kind != HalfspaceKind3::Torus) continue;
      INFO(h.name << ": " << h.origin);
      std::size_t inside = 0, matched = 0;
      for (const PointQ3& v : h.surface.vertices) {
        if (!(s.domain.min.x <= v.x && v.x <= s.domain.max.x && s.domain.min.y <= v.y && v.y <= s.domain.max.y &&
              s.domain.min.z <= v.z && v.z <= s.domain.max.z))
          continue;
        ++inside;
        matched += found(v) ? 1 : 0;
      }
      CHECK(inside > 0);
      CHECK(matched == inside);
    }
    if (std::string(name) == "figure15_a") {  // their radius-0.3 spheres: 17 segments, 30 bands (29 rings)
      const Halfspace3& sphere = s.halfspaces[1];
      CHECK(sphere.surface.vertices.size() == std::size_t(29 * 17 + 2));
      CHECK(sphere.surface.triangles.size() == std::size_t(2 * 17 * 29));
    }
    if (std::string(name) == "figure19_b") {
      CHECK(s.halfspaces.size() == 17);
      CHECK(s.samples.size() == 23);
      CHECK(triangles > 7000);
      CHECK(triangles < 9000);
      // Written as hsx-scene/1 and read back: the same triangles and snapped samples.
      const Scene3 back = read_scene3(parse_exact_json(write_scene3(s).dump()));
      REQUIRE(back.halfspaces.size() == s.halfspaces.size());
      for (std::size_t i = 0; i < s.halfspaces.size(); ++i) {
        CHECK(back.halfspaces[i].surface.vertices == s.halfspaces[i].surface.vertices);
        CHECK(back.halfspaces[i].surface.triangles == s.halfspaces[i].surface.triangles);
        CHECK(back.halfspaces[i].complement == s.halfspaces[i].complement);
      }
      for (std::size_t j = 0; j < s.samples.size(); ++j) CHECK(back.samples[j].location == s.samples[j].location);
      // At h/2 each circle gets about twice the segments.
      BshReadOptions half;
      half.h_scale = 0.5;
      std::size_t finer = 0;
      for (const Halfspace3& h : read_bsh_config_file((dir / name / "config.json").string(), half).halfspaces)
        finer += h.surface.triangles.size();
      std::cout << name << " at h/2: " << finer << " triangles\n";
      CHECK(finer > triangles * 3 / 2);
    }
    ++read;
  }
  CHECK(read == 9);
  SECTION("the authors' refusals") {
    const std::string folder = (dir / "figure19_b").string();
    auto refusal = [&](const char* entry) {
      return error_of([&] { read_bsh_config(parse_exact_json(std::string(R"({"input": [)") + entry + "]}"), folder); });
    };
    CHECK_THAT(refusal(R"({"type": "rbf", "name": "1"})"), Contains("config.json: input[0].type: type \"rbf\" is not supported"));
    CHECK_THAT(refusal(R"({"type": "quadric", "name": "1"})"), Contains("type \"quadric\" is not supported"));
    CHECK_THAT(refusal(R"({"type": "cone", "name": "1"})"), Contains("missing field \"apex\""));
    CHECK_THAT(refusal(R"({"type": "sphere", "name": "1", "center": [0, 0, 0], "radius": 0})"),
               Contains("input[0].radius: must be positive"));
    CHECK_THAT(refusal(R"({"type": "sphere", "name": "1", "center": [0, 0, 0], "radius": 1, "samples": "none.xyz"})"),
               Contains("none.xyz\": No such file or directory"));
  }
}
