// Tests of geometry/arrangement2: Euler's relation, face classification, exact point location and exact areas on
// random scenes with forced degeneracies (tests/support/random_scenes.hpp), plus hand-computed cases.
#include <hsx/geometry/arrangement2.hpp>
#include <hsx/geometry/scene.hpp>
#include <hsx/kernel/measure.hpp>
#include "support/random_scenes.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <memory>
#include <string>
#include <thread>
#include <vector>

using namespace hsx;
using namespace hsx::test;

namespace {

SceneGenOptions degenerate_options() {
  SceneGenOptions o;
  o.max_halfspaces = 6;
  o.max_degeneracies = 2;
  o.samples = true;
  return o;
}

Box2 box(long x0, long y0, long x1, long y1) { return Box2{pt(x0, y0), pt(x1, y1)}; }

/// pi * r^2 as an exact measure (a full-circle angle, keyed "pi").
Measure disk_area(const Halfspace2& h) {
  const PointQ2 p{h.center.x + h.radius, h.center.y};
  return Measure::arc_angle(h.center, h.radius, p, p, Rational(h.radius * h.radius / 2));
}

/// |a - b| < 10^-30 * (1 + |b|), certified at 256 bits.
bool encloses_same(const Measure& a, const Measure& b) {
  const Interval d = a.enclose(256) - b.enclose(256);
  const double tol = 1e-30 * (1 + std::fabs(b.to_double()));
  return d.lo_double() > -tol && d.hi_double() < tol;
}

/// Index of the arrangement vertex at p, -1 when none.
int vertex_at(const Arrangement2& arr, const PointQ2& p) {
  for (int v = 0; v < static_cast<int>(arr.vertices().size()); ++v) {
    const OneRootPoint& x = arr.vertices()[v].point;
    if (x.x == OneRoot(p.x) && x.y == OneRoot(p.y)) return v;
  }
  return -1;
}

bool carries(const ArrEdge2& e, int h) { return std::binary_search(e.halfspaces.begin(), e.halfspaces.end(), h); }

}  // namespace

// ---------------------------------------------------------------------------------------------------------------
// Properties: checks of one scene, run on random scenes by the properties below

namespace {

/// V - E + F = 1 + C, degrees, edge/face incidences
void check_structure(const Scene2& scene, const Arrangement2& arr) {
  const int V = static_cast<int>(arr.vertices().size());
  const int E = static_cast<int>(arr.edges().size());
  const int F = static_cast<int>(arr.faces().size()) + 1;  // + the unbounded face outside the box
  const int C = arr.connected_components();
  RC_ASSERT(V - E + F == 1 + C);
  RC_ASSERT(C >= 1);
  RC_ASSERT(arr.halfspace_count() == static_cast<int>(scene.halfspaces.size()));
  // Vertex degrees equal the incident edge counts (a loop would count twice; there are none).
  std::vector<int> degree(V, 0);
  for (const ArrEdge2& e : arr.edges()) {
    RC_ASSERT(e.source >= 0 && e.source < V && e.target >= 0 && e.target < V);
    RC_ASSERT(e.source != e.target);
    ++degree[e.source];
    ++degree[e.target];
    RC_ASSERT(e.on_box || !e.halfspaces.empty());
    RC_ASSERT(std::is_sorted(e.halfspaces.begin(), e.halfspaces.end()));
    RC_ASSERT(std::adjacent_find(e.halfspaces.begin(), e.halfspaces.end()) == e.halfspaces.end());
    // Exactly the box edges border the outside of the domain.
    RC_ASSERT((e.left_face < 0 || e.right_face < 0) == e.on_box);
    RC_ASSERT(e.left_face != e.right_face);
  }
  for (std::size_t e = 0; e < arr.edges().size(); ++e)
    RC_ASSERT(arr.edge_lengths()->get(e).sign() == std::optional<int>(1));
  std::vector<std::vector<int>> ends(V);  // a scan of every edge: the incident edges, ascending
  for (int e = 0; e < E; ++e) {
    ends[arr.edges()[e].source].push_back(e);
    ends[arr.edges()[e].target].push_back(e);
  }
  for (int v = 0; v < V; ++v) {
    RC_ASSERT(arr.vertices()[v].degree == degree[v]);
    RC_ASSERT(arr.incident_edges(v) == ends[v]);
    RC_ASSERT(degree[v] >= 2);
  }
  // Every edge side that is a face is walked exactly once, by that face, with the face on the left.
  std::map<std::pair<int, bool>, int> walked;
  for (int f = 0; f < static_cast<int>(arr.faces().size()); ++f) {
    const ArrFace2& face = arr.faces()[f];
    RC_ASSERT(!face.boundary.empty());
    for (const auto& cycle : face.boundary) {
      RC_ASSERT(!cycle.empty());
      for (std::size_t k = 0; k < cycle.size(); ++k) {
        const auto [e, fwd] = cycle[k];
        const ArrEdge2& edge = arr.edges().at(e);
        RC_ASSERT((fwd ? edge.left_face : edge.right_face) == f);
        ++walked[std::make_pair(e, fwd)];
        // consecutive edges of a walk share a vertex
        const auto [e2, fwd2] = cycle[(k + 1) % cycle.size()];
        const int end = fwd ? edge.target : edge.source;
        const int start = fwd2 ? arr.edges()[e2].source : arr.edges()[e2].target;
        RC_ASSERT(end == start);
      }
    }
  }
  for (int e = 0; e < E; ++e) {
    const ArrEdge2& edge = arr.edges()[e];
    RC_ASSERT(walked[std::make_pair(e, true)] == (edge.left_face >= 0 ? 1 : 0));
    RC_ASSERT(walked[std::make_pair(e, false)] == (edge.right_face >= 0 ? 1 : 0));
  }
}

/// interior points locate to their face; sides and outer flags are right
void check_faces(const Scene2& scene, const Arrangement2& arr) {
  RC_ASSERT(!arr.faces().empty());
  int outer = 0;
  for (int f = 0; f < static_cast<int>(arr.faces().size()); ++f) {
    const ArrFace2& face = arr.faces()[f];
    const PointQ2& p = arr.face_interiors()->get(static_cast<std::size_t>(f));
    RC_ASSERT(scene.domain.min.x < p.x && p.x < scene.domain.max.x);
    RC_ASSERT(scene.domain.min.y < p.y && p.y < scene.domain.max.y);
    const PointLocation2 where = arr.locate(p);
    RC_ASSERT(where.kind == PointLocation2::Face);
    RC_ASSERT(where.index == f);
    RC_ASSERT(face.inside.size() == scene.halfspaces.size());
    for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
      const int side = scene.halfspaces[i].side(p);
      RC_ASSERT(side != 0);
      RC_ASSERT(static_cast<int>(face.inside[i]) == (side > 0 ? 1 : 0));
    }
    bool touches_box = false;
    for (const auto& cycle : face.boundary)
      for (const auto& [e, fwd] : cycle) touches_box |= arr.edges()[e].on_box;
    RC_ASSERT(face.outer == touches_box);
    outer += face.outer;
  }
  RC_ASSERT(outer >= 1);
}

/// random points in the domain and on boundaries
void check_location(const Scene2& scene, const Arrangement2& arr) {
  std::vector<PointQ2> points = *rc::gen::container<std::vector<PointQ2>>(12, gen_point_in(scene.domain, 2));
  // Points on boundaries reach the edge and vertex cases.
  for (const Halfspace2& h : scene.halfspaces)
    for (const PointQ2& p : boundary_points(h, scene.domain)) points.push_back(p);
  for (const PointQ2& p : points) {
    const PointLocation2 where = arr.locate(p);
    RC_ASSERT(where.kind != PointLocation2::Outside);
    // The shortcut for points on a boundary gives the same answer for every halfspace, on its boundary or not.
    for (int i = 0; i < static_cast<int>(scene.halfspaces.size()); ++i) {
      const PointLocation2 on = arr.locate_on_boundary(p, i);
      RC_ASSERT(on.kind == where.kind);
      RC_ASSERT(on.index == where.index);
      // The holding edge: where's edge when it carries i; at a vertex, one of exactly two edges carrying the same
      // halfspaces, i among them; -1 in a face.
      const int held = arr.holding_edge(on, i);
      if (where.kind == PointLocation2::Face) RC_ASSERT(held == -1);
      if (where.kind == PointLocation2::Edge)
        RC_ASSERT(held == (carries(arr.edges()[where.index], i) ? where.index : -1));
      if (where.kind == PointLocation2::Vertex && held >= 0) {
        const std::vector<int> two = arr.incident_edges(where.index);
        RC_ASSERT(two.size() == 2u);
        RC_ASSERT(held == two[0]);
        RC_ASSERT(carries(arr.edges()[two[0]], i));
        RC_ASSERT(arr.edges()[two[0]].halfspaces == arr.edges()[two[1]].halfspaces);
      }
    }
    switch (where.kind) {
      case PointLocation2::Face: {
        const ArrFace2& face = arr.faces().at(where.index);
        for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
          const int side = scene.halfspaces[i].side(p);
          RC_ASSERT(side != 0);
          RC_ASSERT(static_cast<int>(face.inside[i]) == (side > 0 ? 1 : 0));
        }
        break;
      }
      case PointLocation2::Edge: {
        const ArrEdge2& edge = arr.edges().at(where.index);
        RC_ASSERT(!edge.on_box);  // p is strictly inside the domain
        for (int i = 0; i < static_cast<int>(scene.halfspaces.size()); ++i)
          RC_ASSERT((scene.halfspaces[i].side(p) == 0) == carries(edge, i));
        break;
      }
      case PointLocation2::Vertex: {
        const ArrVertex2& v = arr.vertices().at(where.index);
        RC_ASSERT(v.point.x == OneRoot(p.x));
        RC_ASSERT(v.point.y == OneRoot(p.y));
        // Every halfspace carried by an incident edge has p on its boundary.
        for (int e : arr.incident_edges(where.index))
          for (int i : arr.edges()[e].halfspaces) RC_ASSERT(scene.halfspaces[i].side(p) == 0);
        break;
      }
      case PointLocation2::Outside:
        break;
    }
  }
}

/// cells add up to the box; polygons to |signed_area|; disks to pi r^2
void check_areas(const Scene2& scene, const Arrangement2& arr) {
  const Box2& d = scene.domain;
  Measure total;
  for (std::size_t f = 0; f < arr.faces().size(); ++f) {
    RC_ASSERT(arr.face_areas()->get(f).sign() == std::optional<int>(1));
    total += arr.face_areas()->get(f);
  }
  RC_ASSERT(compare(total, Measure(Rational((d.max.x - d.min.x) * (d.max.y - d.min.y)))) == Order::Equal);
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
    const Halfspace2& h = scene.halfspaces[i];
    if (h.kind == HalfspaceKind2::Halfplane) continue;
    Measure in;  // area of the cells inside the polygon or disk itself (complement undone)
    for (std::size_t f = 0; f < arr.faces().size(); ++f)
      if (static_cast<bool>(arr.faces()[f].inside[i]) != h.complement) in += arr.face_areas()->get(f);
    if (h.kind == HalfspaceKind2::Polygon) {
      RC_ASSERT(compare(in, Measure(abs(signed_area(h.vertices)))) == Order::Equal);
    } else {
      const Order o = compare(in, disk_area(h));
      RC_ASSERT(o != Order::Less);
      RC_ASSERT(o != Order::Greater);
      RC_ASSERT(encloses_same(in, disk_area(h)));
    }
  }
}

}  // namespace

TEST_CASE("arrangement2: Euler's relation and structure on random scenes", "[arrangement2][property]") {
  rc::prop("V - E + F = 1 + C, degrees, edge/face incidences", [] {
    const Scene2 scene = *gen_scene(degenerate_options());
    check_structure(scene, Arrangement2::build(scene));
  });
}

TEST_CASE("arrangement2: faces agree with direct evaluation on random scenes", "[arrangement2][property]") {
  rc::prop("interior points locate to their face; sides and outer flags are right", [] {
    const Scene2 scene = *gen_scene(degenerate_options());
    check_faces(scene, Arrangement2::build(scene));
  });
}

TEST_CASE("arrangement2: interior points are the same whenever and by whichever thread they are read",
          "[arrangement2][property]") {
  rc::prop("four threads in shuffled orders, and a cache outliving its arrangement, give one thread's points", [] {
    const Scene2 scene = *gen_scene(degenerate_options());
    const Arrangement2 reference = Arrangement2::build(scene);
    const std::size_t n = reference.faces().size();
    std::vector<PointQ2> expected;
    for (std::size_t f = 0; f < n; ++f) expected.push_back(reference.face_interiors()->get(f));
    std::shared_ptr<const LazyCache<PointQ2>> interiors = Arrangement2::build(scene).face_interiors();
    std::vector<std::vector<std::size_t>> orders;  // per thread: the faces sorted by random keys
    for (int t = 0; t < 4; ++t) {
      const auto keys = *rc::gen::container<std::vector<int>>(n, rc::gen::arbitrary<int>());
      std::vector<std::size_t> order(n);
      for (std::size_t f = 0; f < n; ++f) order[f] = f;
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
      orders.push_back(std::move(order));
    }
    std::vector<std::vector<PointQ2>> got(4, std::vector<PointQ2>(n));
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < 4; ++t)
      threads.emplace_back([&, t] {
        for (std::size_t f : orders[t]) got[t][f] = interiors->get(f);
      });
    for (auto& thread : threads) thread.join();
    for (std::size_t t = 0; t < 4; ++t) RC_ASSERT(got[t] == expected);
  });
}

TEST_CASE("arrangement2: point location agrees with exact side tests", "[arrangement2][property]") {
  rc::prop("random points in the domain and on boundaries", [] {
    const Scene2 scene = *gen_scene(degenerate_options());
    check_location(scene, Arrangement2::build(scene));
  });
}

TEST_CASE("arrangement2: exact areas on random scenes", "[arrangement2][property]") {
  rc::prop("cells add up to the box; polygons to |signed_area|; disks to pi r^2", [] {
    const Scene2 scene = *gen_scene(degenerate_options());
    check_areas(scene, Arrangement2::build(scene));
  });
}

TEST_CASE("arrangement2: all properties on larger scenes", "[.][stress][arrangement2]") {
  // Hidden (run with "[stress]"): more halfspaces and degeneracies than the default suite.
  rc::prop("larger scenes", [] {
    SceneGenOptions o = degenerate_options();
    o.max_halfspaces = 12;
    o.max_degeneracies = 5;
    o.samples = true;
    const Scene2 scene = *gen_scene(o);
    const Arrangement2 arr = Arrangement2::build(scene);
    check_structure(scene, arr);
    check_faces(scene, arr);
    check_location(scene, arr);
    check_areas(scene, arr);
  });
}

// ---------------------------------------------------------------------------------------------------------------
// Hand-computed cases

TEST_CASE("arrangement2: three concurrent lines meet at one vertex of degree 6", "[arrangement2]") {
  // y = 0, x = 0, y = x through the origin; y = x leaves the box [-2,3]x[-3,2] through (-2,-2) and (2,2), not
  // through corners. V = origin + 6 side points + 4 corners = 11; E = 6 line edges + 10 box edges = 16;
  // F = 6 sectors, all outer.
  const Scene2 s = make_scene(box(-2, -3, 3, 2), {halfplane("X", pt(0, 1), 0), halfplane("Y", pt(1, 0), 0),
                                                  halfplane("D", pt(1, -1), 0)});
  const Arrangement2 arr = Arrangement2::build(s);
  CHECK(arr.vertices().size() == 11);
  CHECK(arr.edges().size() == 16);
  REQUIRE(arr.faces().size() == 6);
  for (const ArrFace2& f : arr.faces()) CHECK(f.outer);
  const PointLocation2 o = arr.locate(pt(0, 0));
  REQUIRE(o.kind == PointLocation2::Vertex);
  CHECK(arr.vertices()[o.index].degree == 6);
  int interior_vertices = 0;
  for (int v = 0; v < static_cast<int>(arr.vertices().size()); ++v) {
    bool on_box = false;
    for (int e : arr.incident_edges(v)) on_box |= arr.edges()[e].on_box;
    if (!on_box) ++interior_vertices;
  }
  CHECK(interior_vertices == 1);
  // Located on the boundary of one line: the origin from each, a point of X's line (y = 0) from X and from D.
  for (int i = 0; i < 3; ++i) {
    CHECK(arr.locate_on_boundary(pt(0, 0), i).kind == PointLocation2::Vertex);
    CHECK(arr.locate_on_boundary(pt(0, 0), i).index == o.index);
  }
  const PointLocation2 on_x = arr.locate(pt(1, 0));
  REQUIRE(on_x.kind == PointLocation2::Edge);
  for (int i : {0, 2}) {
    CHECK(arr.locate_on_boundary(pt(1, 0), i).kind == PointLocation2::Edge);
    CHECK(arr.locate_on_boundary(pt(1, 0), i).index == on_x.index);
  }
  CHECK_THROWS_AS(arr.locate_on_boundary(pt(1, 0), 3), std::invalid_argument);
  CHECK_THROWS_AS(arr.locate_on_boundary(pt(1, 0), -1), std::invalid_argument);
  CHECK_THROWS_AS(arr.incident_edges(11), std::invalid_argument);
  // No edge holds the origin (six edges meet there); an edge of X holds (1, 0) for X, none for Y or D.
  for (int i = 0; i < 3; ++i) CHECK(arr.holding_edge(o, i) == -1);
  CHECK(arr.holding_edge(on_x, 0) == on_x.index);
  CHECK(arr.holding_edge(on_x, 1) == -1);
  CHECK(arr.holding_edge(on_x, 2) == -1);
  CHECK_THROWS_AS(arr.holding_edge(on_x, 3), std::invalid_argument);
  CHECK_THROWS_AS(arr.holding_edge(PointLocation2{PointLocation2::Edge, 16}, 0), std::invalid_argument);
  CHECK_THROWS_AS(arr.holding_edge(PointLocation2{PointLocation2::Vertex, -1}, 0), std::invalid_argument);
  // The six sectors have areas adding up to 25.
  Measure total;
  for (std::size_t f = 0; f < arr.faces().size(); ++f) total += arr.face_areas()->get(f);
  CHECK(compare(total, Measure(Rational(25))) == Order::Equal);
}

TEST_CASE("arrangement2: a half-plane whose line only touches a box corner has no edge", "[arrangement2]") {
  // x + y <= 0 touches [0,2]^2 at (0,0) only: the box is outside (closed half-plane, open cells). x + y <= 4
  // touches it at (2,2): the box is inside. A disk gives the arrangement a second face.
  for (bool far_side : {false, true}) {
    const Rational offset = far_side ? 4 : 0;
    const Scene2 s = make_scene(box(0, 0, 2, 2), {halfplane("H", pt(1, 1), offset), disk("D", pt(1, 1), q("1/2"))});
    const Arrangement2 arr = Arrangement2::build(s);
    CHECK(arr.vertices().size() == 6);  // 4 corners + the circle's two x-extreme points
    CHECK(arr.edges().size() == 6);
    REQUIRE(arr.faces().size() == 2);
    for (const ArrEdge2& e : arr.edges()) CHECK(!carries(e, 0));
    for (const ArrFace2& f : arr.faces()) CHECK(static_cast<int>(f.inside[0]) == (far_side ? 1 : 0));
    CHECK(arr.connected_components() == 2);
  }
}

TEST_CASE("arrangement2: a half-plane whose line lies on a box side has no interior edge", "[arrangement2]") {
  // x >= 0 (normal (-1,0)) on the box [0,2]^2: its line is the left side. Inside everywhere; x <= 0: nowhere.
  for (bool inside : {true, false}) {
    const Scene2 s = make_scene(box(0, 0, 2, 2), {halfplane("H", pt(inside ? -1 : 1, 0), 0),
                                                  disk("D", pt(1, 1), q("1/2"))});
    const Arrangement2 arr = Arrangement2::build(s);
    CHECK(arr.vertices().size() == 6);
    CHECK(arr.edges().size() == 6);
    REQUIRE(arr.faces().size() == 2);
    int carrying = 0;
    for (const ArrEdge2& e : arr.edges())
      if (carries(e, 0)) {
        ++carrying;
        CHECK(e.on_box);
      }
    CHECK(carrying == 1);
    for (const ArrFace2& f : arr.faces()) CHECK(static_cast<int>(f.inside[0]) == (inside ? 1 : 0));
  }
}

TEST_CASE("arrangement2: a disk tangent to a line", "[arrangement2]") {
  // Disk |x| <= 1 and y <= 1 in [-3,3]^2: the line touches the circle at (0,1).
  // V = 4 corners + 2 line/box + tangent point + 2 x-extremes = 9; E = 6 box + 2 line + 3 arcs = 11; F = 3:
  // above the line (outer), below it outside the disk (outer), the disk.
  const Scene2 s = make_scene(box(-3, -3, 3, 3), {disk("A", pt(0, 0), 1), halfplane("L", pt(0, 1), 1)});
  const Arrangement2 arr = Arrangement2::build(s);
  CHECK(arr.vertices().size() == 9);
  CHECK(arr.edges().size() == 11);
  REQUIRE(arr.faces().size() == 3);
  CHECK(std::count_if(arr.faces().begin(), arr.faces().end(), [](const ArrFace2& f) { return f.outer; }) == 2);
  const int t = vertex_at(arr, pt(0, 1));
  REQUIRE(t >= 0);
  CHECK(arr.vertices()[t].degree == 4);
  CHECK(arr.connected_components() == 1);
  // The disk's face has area pi exactly (two quarter arcs and a half arc around one circle).
  const PointLocation2 c = arr.locate(pt(0, 0));
  REQUIRE(c.kind == PointLocation2::Face);
  CHECK(encloses_same(arr.face_areas()->get(static_cast<std::size_t>(c.index)), disk_area(s.halfspaces[0])));
}

TEST_CASE("arrangement2: two crossing disks", "[arrangement2]") {
  // A: centre (0,0), B: centre (2,0), radius 2, crossing at (1, +-sqrt(3)), in [-4,6]x[-4,4].
  // V = 4 corners + 2 crossings + 4 x-extremes = 10; E = 4 box + 4 + 4 arcs = 12; C = 2 (box and circles);
  // F = 4: outside (outer, with a hole), A only, lens, B only. Lens area 8pi/3 - 2 sqrt(3).
  const Scene2 s = make_scene(box(-4, -4, 6, 4), {disk("A", pt(0, 0), 2), disk("B", pt(2, 0), 2)});
  const Arrangement2 arr = Arrangement2::build(s);
  CHECK(arr.vertices().size() == 10);
  CHECK(arr.edges().size() == 12);
  CHECK(arr.connected_components() == 2);
  REQUIRE(arr.faces().size() == 4);
  const PointLocation2 lens = arr.locate(pt(1, 0));
  REQUIRE(lens.kind == PointLocation2::Face);
  const ArrFace2& f = arr.faces()[lens.index];
  CHECK(f.inside == std::vector<char>{1, 1});
  CHECK(!f.outer);
  // 8pi/3 - 2sqrt(3) = 4.913478870...
  const Interval a = arr.face_areas()->get(static_cast<std::size_t>(lens.index)).enclose(128);
  CHECK(a.lo_double() > 4.9134787944);
  CHECK(a.hi_double() < 4.9134787945);
  const PointLocation2 out = arr.locate(pt(5, 3));
  REQUIRE(out.kind == PointLocation2::Face);
  CHECK(arr.faces()[out.index].outer);
  CHECK(arr.faces()[out.index].boundary.size() == 2);  // outer boundary and one hole
}

TEST_CASE("arrangement2: samples on degree-2 vertices are accepted", "[arrangement2]") {
  // A polygon corner and a circle's x-extreme point lie inside one curve run: accepted, on an edge of their
  // halfspace.
  Scene2 s = make_scene(box(-1, -1, 5, 3), {polygon("P", {pt(0, 0), pt(2, 0), pt(2, 2), pt(0, 2)}),
                                            disk("D", pt(4, 1), q("1/2"))});
  add_sample(s, "P", pt(2, 2));
  add_sample(s, "D", pt(q("9/2"), 1));
  validate_and_resolve(s);
  const Arrangement2 arr = Arrangement2::build(s);
  REQUIRE(arr.sample_edges().size() == 2);
  CHECK(carries(arr.edges()[arr.sample_edges()[0]], 0));
  CHECK(carries(arr.edges()[arr.sample_edges()[1]], 1));
  CHECK(sample_fits(arr, 0, pt(2, 2)));
  // The corner's holding edge is the lower-indexed of its two edges, for P only.
  const PointLocation2 corner = arr.locate(pt(2, 2));
  REQUIRE(corner.kind == PointLocation2::Vertex);
  const std::vector<int> two = arr.incident_edges(corner.index);
  REQUIRE(two.size() == 2);
  CHECK(two[0] < two[1]);
  CHECK(arr.holding_edge(corner, 0) == two[0]);
  CHECK(arr.sample_edges()[0] == two[0]);
  CHECK(arr.holding_edge(corner, 1) == -1);
  CHECK_FALSE(sample_fits(arr, 1, pt(2, 2)));
}

TEST_CASE("arrangement2: samples where boundaries meet are input errors", "[arrangement2]") {
  SECTION("a crossing of two lines") {
    Scene2 s = make_scene(box(-2, -2, 2, 2), {halfplane("X", pt(0, 1), 0), halfplane("Y", pt(1, 0), 0)});
    add_sample(s, "X", pt(0, 0));
    validate_and_resolve(s);
    CHECK_THROWS_AS(Arrangement2::build(s), InputError);
  }
  SECTION("a tangency point") {
    Scene2 s = make_scene(box(-3, -3, 3, 3), {disk("A", pt(0, 0), 1), halfplane("L", pt(0, 1), 1)});
    add_sample(s, "A", pt(0, 1));
    validate_and_resolve(s);
    CHECK_THROWS_AS(Arrangement2::build(s), InputError);
  }
  SECTION("a polygon corner on a line") {
    Scene2 s = make_scene(box(-3, -3, 3, 3), {polygon("P", {pt(0, 0), pt(2, 0), pt(0, 2)}),
                                              halfplane("L", pt(1, 1), 0)});
    add_sample(s, "P", pt(0, 0));
    validate_and_resolve(s);
    CHECK_THROWS_AS(Arrangement2::build(s), InputError);
  }
  SECTION("the same point on a patch is fine") {
    Scene2 s = make_scene(box(-2, -2, 2, 2), {halfplane("X", pt(0, 1), 0), halfplane("Y", pt(1, 0), 0)});
    add_sample(s, "X", pt(1, 0));
    validate_and_resolve(s);
    CHECK_NOTHROW(Arrangement2::build(s));
  }
}

TEST_CASE("arrangement2: size limits hold exactly at the arrangement's own size", "[arrangement2][property][limits]") {
  rc::prop("max_cells = cells passes, cells - 1 is refused; the same for cells x halfspaces", [] {
    const Scene2 scene = *gen_scene(degenerate_options());
    const Arrangement2 whole = Arrangement2::build(scene, ArrangementLimits{0, 0});
    const long cells = static_cast<long>(whole.faces().size());
    const long entries = cells * static_cast<long>(scene.halfspaces.size());
    RC_ASSERT(Arrangement2::build(scene, ArrangementLimits{cells, entries}).faces().size() == whole.faces().size());
    RC_ASSERT_THROWS_AS(Arrangement2::build(scene, ArrangementLimits{cells - 1, 0}), InputError);
    RC_ASSERT_THROWS_AS(Arrangement2::build(scene, ArrangementLimits{0, entries - 1}), InputError);
  });
}

namespace {

Scene2 parallel_lines(int n) {
  Scene2 scene;
  scene.domain = box(-10, -10, 10, 10);
  scene.domain_given = true;
  for (int i = 0; i < n; ++i) {
    Halfspace2 h;
    h.name = "L" + std::to_string(i);
    h.normal = pt(0, 1);
    h.offset = Rational(i - n / 2, n);
    scene.halfspaces.push_back(h);
  }
  validate_and_resolve(scene);
  return scene;
}

}  // namespace

TEST_CASE("arrangement2: a side table known to be too large is refused before the sweep", "[arrangement2][limits]") {
  // 2000 parallel chords give at least 2001 cells: 2001 x 2000 entries, over a limit of 10^6, known up front.
  try {
    Arrangement2::build(parallel_lines(2000), ArrangementLimits{0, 1000000});
    FAIL("not refused");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("at least 2001 cells over 2000 halfspaces") &&
                             Catch::Contains("--max-side-table"));
  }
  try {
    Arrangement2::build(parallel_lines(50), ArrangementLimits{40, 0});
    FAIL("not refused");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("at least 51 cells, over the limit of 40") && Catch::Contains("--max-cells"));
  }
  CHECK(Arrangement2::build(parallel_lines(50), ArrangementLimits{51, 51 * 50}).faces().size() == 51);
}

TEST_CASE("arrangement2: coincident copies of a boundary are one curve carrying every copy", "[arrangement2]") {
  // 300 copies of one disk (as CSGNet programs repeat primitives) and a half-plane along the box side: the sweep
  // sees one circle, each edge of it lists all copies.
  Scene2 scene;
  scene.domain = box(-4, -4, 4, 4);
  scene.domain_given = true;
  for (int i = 0; i < 300; ++i) {
    Halfspace2 h;
    h.name = "D" + std::to_string(i);
    h.kind = HalfspaceKind2::Disk;
    h.center = pt(0, 0);
    h.radius = 2;
    h.complement = i % 2 == 1;
    scene.halfspaces.push_back(h);
  }
  Halfspace2 side;
  side.name = "S";
  side.normal = pt(1, 0);
  side.offset = 4;
  scene.halfspaces.push_back(side);
  validate_and_resolve(scene);
  const Arrangement2 arr = Arrangement2::build(scene);
  CHECK(arr.faces().size() == 2);
  int arcs = 0;
  for (const ArrEdge2& e : arr.edges()) {
    if (e.shape != EdgeShape2::Arc) {
      CHECK(e.on_box);
      continue;
    }
    ++arcs;
    REQUIRE(e.halfspaces.size() == 300);
    for (int i = 0; i < 300; ++i) CHECK(e.halfspaces[static_cast<std::size_t>(i)] == i);
  }
  CHECK(arcs == 2);
}

namespace {

Halfspace2 rectangle(const std::string& name, const Rational& x0, const Rational& y0, const Rational& x1,
                     const Rational& y1, bool complement) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Polygon;
  h.vertices = {pt(x0, y0), pt(x1, y0), pt(x1, y1), pt(x0, y1)};
  h.complement = complement;
  return h;
}

Halfspace2 disk(const std::string& name, const Rational& x, const Rational& y, const Rational& r) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Disk;
  h.center = pt(x, y);
  h.radius = r;
  return h;
}

}  // namespace

TEST_CASE("arrangement2: overlapping collinear segments among circles (data/crashes/scene/overlap-curve-mismatch.json)",
          "[arrangement2][regression]") {
  // Three rectangles and a half-plane share the line y = 4, which two circles cross. CGAL 5.5's sweep, given the
  // overlapping segments, left the edge [1/2, 1] x {4} with the curve [-1, 1] x {4}, and the arrangement failed
  // ("face is not closed above its base edge"); the overlaps are now cut before the sweep.
  const Rational h(1, 2);
  Scene2 scene;
  scene.domain = box(-9, -7, 8, 9);
  scene.domain_given = true;
  scene.halfspaces.push_back(rectangle("P61", -1, 1, 3 * h, 4, true));
  scene.halfspaces.push_back(rectangle("P150", -1, 1, h, 4, false));
  scene.halfspaces.push_back(disk("D181", 0, 2, 5 * h));
  scene.halfspaces.push_back(disk("D182", -5 * h, 5 * h, 3));
  scene.halfspaces.push_back(rectangle("P188", -3 * h, 5 * h, 1, 4, true));
  Halfspace2 line;
  line.name = "L198";
  line.normal = pt(0, -1);
  line.offset = -4;
  scene.halfspaces.push_back(line);
  validate_and_resolve(scene);
  const Arrangement2 arr = Arrangement2::build(scene);
  CHECK_NOTHROW(check_structure(scene, arr));
  CHECK_NOTHROW(check_faces(scene, arr));
  CHECK_NOTHROW(check_areas(scene, arr));
}

TEST_CASE("arrangement2: a polygon edge along part of a half-plane's line splits it into pieces with their halfspaces",
          "[arrangement2]") {
  // The square [0, 2]^2 has its bottom edge on the line y = 0 of half-plane H (y >= 0); a second square
  // [1, 3] x [-2, 0] has its top edge on it too, overlapping the first on [1, 2]. On y = 0 the pieces are
  // [-4, 0] H, [0, 1] H+A, [1, 2] H+A+B, [2, 3] H+B, [3, 4] H.
  Scene2 scene;
  scene.domain = box(-4, -4, 4, 4);
  scene.domain_given = true;
  Halfspace2 line;
  line.name = "H";
  line.normal = pt(0, -1);
  line.offset = 0;
  scene.halfspaces.push_back(line);
  scene.halfspaces.push_back(rectangle("A", 0, 0, 2, 2, false));
  scene.halfspaces.push_back(rectangle("B", 1, -2, 3, 0, false));
  validate_and_resolve(scene);
  const Arrangement2 arr = Arrangement2::build(scene);
  CHECK_NOTHROW(check_structure(scene, arr));
  CHECK_NOTHROW(check_faces(scene, arr));
  CHECK_NOTHROW(check_areas(scene, arr));
  std::map<std::pair<Rational, Rational>, std::vector<int>> on_line;  // (x0, x1) -> halfspaces, for edges on y = 0
  for (const ArrEdge2& e : arr.edges()) {
    const OneRootPoint &a = arr.vertices()[e.source].point, &b = arr.vertices()[e.target].point;
    if (!a.y.is_rational() || !b.y.is_rational() || a.y.a0 != 0 || b.y.a0 != 0) continue;
    on_line[std::minmax(a.x.a0, b.x.a0)] = e.halfspaces;
  }
  const std::map<std::pair<Rational, Rational>, std::vector<int>> expected{
      {{-4, 0}, {0}}, {{0, 1}, {0, 1}}, {{1, 2}, {0, 1, 2}}, {{2, 3}, {0, 2}}, {{3, 4}, {0}}};
  CHECK(on_line == expected);
  CHECK(arr.faces().size() == 4);  // below y = 0 outside B, B, A, above y = 0 outside A
}
