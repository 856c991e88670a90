// Tests of the 2D NH-Rep input: a solid's boundary edges and exact corner angles (geometry/planar_corners.hpp) and
// the BoundarySurface built from them (complex/boundary_from_arrangement2.hpp). Hand-computed shapes (square,
// L-shapes, disk cut by a line, a line tangent to a circle, union and intersection of disks, squares touching at a
// corner, horns between internally tangent circles) and properties over random scenes and solids: invariance under
// translation, permutation of the halfspaces and mirroring; a brute-force oracle with exact rational pseudo-angles
// for straight-edged scenes; and the turning number of rectilinear boundary cycles.
#include <hsx/complex/boundary.hpp>
#include <hsx/complex/boundary_from_arrangement2.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include "geometry/planar_corners.hpp"
#include "support/random_scenes.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

using namespace hsx;
using namespace hsx::test;

namespace {

Box2 box(long x0, long y0, long x1, long y1) { return Box2{pt(x0, y0), pt(x1, y1)}; }

Halfspace2 rect(const std::string& name, long x0, long y0, long x1, long y1, bool complement = false) {
  return polygon(name, {pt(x0, y0), pt(x1, y0), pt(x1, y1), pt(x0, y1)}, complement);
}

using Predicate = std::function<bool(const std::vector<char>&)>;

/// The inner cells whose sign vector satisfies `in`.
std::vector<char> solid_where(const Arranged2& a, const Predicate& in) {
  std::vector<char> solid;
  for (const Cell& c : a.complex.cells) solid.push_back(!c.outer && in(c.inside) ? 1 : 0);
  return solid;
}

struct Shape {
  Scene2 scene;
  Arranged2 arranged;
  std::vector<char> solid;
  SolidBoundary2 boundary;
  BoundarySurface surface;
};

Shape make_shape(const Box2& domain, std::vector<Halfspace2> halfspaces, const Predicate& in) {
  Shape s;
  s.scene = make_scene(domain, std::move(halfspaces));
  s.arranged = arrange(s.scene);
  s.solid = solid_where(s.arranged, in);
  s.boundary = solid_boundary2(s.arranged.arrangement, s.solid);
  s.surface = boundary_from_arrangement2(s.arranged, s.solid);
  return s;
}

struct Tally {
  int convex = 0, smooth = 0, concave = 0, cusps = 0;
  bool operator==(const Tally& o) const {
    return std::tie(convex, smooth, concave, cusps) == std::tie(o.convex, o.smooth, o.concave, o.cusps);
  }
};
std::ostream& operator<<(std::ostream& os, const Tally& t) {
  return os << "{convex " << t.convex << ", smooth " << t.smooth << ", concave " << t.concave << ", cusps "
            << t.cusps << "}";
}

Tally corner_tally(const SolidBoundary2& b) {
  Tally t;
  for (const SolidCorner2& c : b.corners) {
    (c.angle == CornerAngle::Convex ? t.convex : c.angle == CornerAngle::Smooth ? t.smooth : t.concave) += 1;
    t.cusps += c.cusp ? 1 : 0;
  }
  return t;
}

/// Feature links only (cusps are not visible on links).
Tally feature_tally(const BoundarySurface& s) {
  Tally t;
  for (const BoundaryLink& l : s.links) {
    if (!l.feature) continue;
    (l.type == FeatureType::Convex ? t.convex : l.type == FeatureType::Smooth ? t.smooth : t.concave) += 1;
  }
  return t;
}

Tally tally(int convex, int smooth, int concave, int cusps = 0) { return Tally{convex, smooth, concave, cusps}; }

bool same_point(const OneRootPoint& a, const OneRootPoint& b) { return a.x == b.x && a.y == b.y; }

/// Corners at the vertex with exact coordinates `p`.
std::vector<SolidCorner2> corners_at(const Shape& s, const OneRootPoint& p) {
  std::vector<SolidCorner2> out;
  for (const SolidCorner2& c : s.boundary.corners)
    if (same_point(s.arranged.arrangement.vertices()[c.vertex].point, p)) out.push_back(c);
  return out;
}

/// The (only) link at the vertex with coordinates `p`.
const BoundaryLink& link_at(const Shape& s, const OneRootPoint& p) {
  const BoundaryLink* found = nullptr;
  for (const BoundaryLink& l : s.surface.links)
    if (same_point(s.arranged.arrangement.vertices()[l.origin].point, p)) {
      REQUIRE(found == nullptr);
      found = &l;
    }
  REQUIRE(found != nullptr);
  return *found;
}

void check_common(const Shape& s) {
  REQUIRE(check_boundary(s.surface).empty());
  REQUIRE(s.surface.pieces.size() == s.boundary.edges.size());
  REQUIRE(s.surface.links.size() == s.boundary.corners.size());
  REQUIRE(s.boundary.corners.size() == s.boundary.edges.size());
}

OneRoot root(const char* a0, const char* a1, const char* r) { return OneRoot(q(a0), q(a1), q(r)); }

}  // namespace

// ---------------------------------------------------------------------------------------------------------------
// Hand-computed shapes

TEST_CASE("square polygon: four convex corners inside one patch", "[boundary2]") {
  const Shape s = make_shape(box(-1, -1, 3, 3), {rect("S", 0, 0, 2, 2)}, [](auto& in) { return in[0] == 1; });
  check_common(s);
  CHECK(corner_tally(s.boundary) == tally(4, 0, 0));
  CHECK(feature_tally(s.surface) == tally(0, 0, 0));
  for (const BoundaryPiece& p : s.surface.pieces) {
    CHECK(p.carrier == 0);
    CHECK(!p.carrier_complemented);
    CHECK(p.links.size() == 2u);
  }
  // Orientation: solid on the left, so the walk around a square is counter-clockwise.
  const auto& arr = s.arranged.arrangement;
  for (const SolidBoundaryEdge2& b : s.boundary.edges) {
    const ArrEdge2& e = arr.edges()[b.edge];
    CHECK((b.forward ? e.left_face : e.right_face) >= 0);
    CHECK(s.solid[b.forward ? e.left_face : e.right_face] == 1);
  }
  // A piece's first link is at its start, the second at its end.
  for (std::size_t p = 0; p < s.surface.pieces.size(); ++p) {
    CHECK(s.surface.links[s.surface.pieces[p].links[0]].piece_b == static_cast<int>(p));
    CHECK(s.surface.links[s.surface.pieces[p].links[1]].piece_a == static_cast<int>(p));
  }
}

TEST_CASE("square from four half-planes: four convex feature corners", "[boundary2]") {
  const Shape s = make_shape(box(-1, -1, 3, 3),
                             {halfplane("R", pt(1, 0), 2), halfplane("L", pt(-1, 0), 0), halfplane("T", pt(0, 1), 2),
                              halfplane("B", pt(0, -1), 0)},
                             [](auto& in) { return in[0] && in[1] && in[2] && in[3]; });
  check_common(s);
  CHECK(corner_tally(s.boundary) == tally(4, 0, 0));
  CHECK(feature_tally(s.surface) == tally(4, 0, 0));
  std::set<int> carriers;
  for (const BoundaryPiece& p : s.surface.pieces) carriers.insert(p.carrier);
  CHECK(carriers == std::set<int>{0, 1, 2, 3});
}

TEST_CASE("L-shape as a union of rectangles: one concave corner", "[boundary2]") {
  // R1 = [0,2]x[0,1], R2 = [0,1]x[0,2]; they share the left and bottom sides in part.
  const Shape s = make_shape(box(-1, -1, 3, 3), {rect("R1", 0, 0, 2, 1), rect("R2", 0, 0, 1, 2)},
                             [](auto& in) { return in[0] || in[1]; });
  check_common(s);
  // Corners (0,0) (2,0) (2,1) (1,2) (0,2) convex, (1,1) concave; (1,0) and (0,1) straight through.
  CHECK(corner_tally(s.boundary) == tally(5, 2, 1));
  CHECK(corners_at(s, pt(1, 1)).at(0).angle == CornerAngle::Concave);
  // Shared sides are carried by R1 (lowest index inside), so the straight continuation at (1,0) stays on R1
  // while at (0,1) R1 hands over to R2: a smooth feature.
  CHECK(feature_tally(s.surface) == tally(0, 1, 1));
  CHECK(!link_at(s, pt(1, 0)).feature);
  CHECK(link_at(s, pt(0, 1)).feature);
  CHECK(link_at(s, pt(0, 1)).type == FeatureType::Smooth);
  CHECK(link_at(s, pt(1, 1)).type == FeatureType::Concave);
}

TEST_CASE("L-shape as a difference of rectangles: complemented carriers", "[boundary2]") {
  const Shape s = make_shape(box(-1, -1, 4, 4), {rect("A", 0, 0, 2, 2), rect("B", 1, 1, 3, 3)},
                             [](auto& in) { return in[0] && !in[1]; });
  check_common(s);
  CHECK(corner_tally(s.boundary) == tally(5, 0, 1));
  // (2,1) and (1,2): A meets B, convex features; (1,1) is B's own corner: concave, but inside B's patch.
  CHECK(feature_tally(s.surface) == tally(2, 0, 0));
  CHECK(!link_at(s, pt(1, 1)).feature);
  CHECK(link_at(s, pt(1, 1)).type == FeatureType::Concave);
  int on_b = 0;
  for (const BoundaryPiece& p : s.surface.pieces) {
    CHECK(p.carrier_complemented == (p.carrier == 1));
    on_b += p.carrier == 1;
  }
  CHECK(on_b == 2);
}

TEST_CASE("disk cut by a half-plane: convex corners at irrational points", "[boundary2]") {
  const Shape s = make_shape(box(-3, -3, 3, 3), {disk("D", pt(0, 0), 2), halfplane("H", pt(0, 1), 1)},
                             [](auto& in) { return in[0] && in[1]; });
  check_common(s);
  // (+-sqrt 3, 1) convex; (+-2, 0) where CGAL splits the circle: smooth, inside the disk's patch.
  CHECK(corner_tally(s.boundary) == tally(2, 2, 0));
  CHECK(feature_tally(s.surface) == tally(2, 0, 0));
  const OneRootPoint right(root("0", "1", "3"), OneRoot(q("1")));
  const OneRootPoint left(root("0", "-1", "3"), OneRoot(q("1")));
  CHECK(link_at(s, right).type == FeatureType::Convex);
  CHECK(link_at(s, left).type == FeatureType::Convex);
  // The complement side inside a box: the same points become concave.
  const Shape t = make_shape(box(-4, -4, 4, 4), {disk("D", pt(0, 0), 2), halfplane("H", pt(0, 1), 1),
                                                 rect("B", -3, -3, 3, 3)},
                             [](auto& in) { return in[2] && !(in[0] && in[1]); });
  check_common(t);
  CHECK(link_at(t, right).type == FeatureType::Concave);
  CHECK(link_at(t, left).type == FeatureType::Concave);
}

TEST_CASE("a line tangent to a circle: smooth feature corners", "[boundary2]") {
  // A stadium end: the unit disk and the rectangle [0,3]x[-1,1] whose long sides touch the circle at (0, +-1).
  const Shape s = make_shape(box(-2, -2, 4, 2), {disk("D", pt(0, 0), 1), rect("R", 0, -1, 3, 1)},
                             [](auto& in) { return in[0] || in[1]; });
  check_common(s);
  CHECK(corner_tally(s.boundary) == tally(2, 3, 0));  // (3, +-1); (0, +-1) and the split point (-1, 0)
  CHECK(feature_tally(s.surface) == tally(0, 2, 0));
  CHECK(link_at(s, pt(0, 1)).type == FeatureType::Smooth);
  CHECK(link_at(s, pt(0, -1)).type == FeatureType::Smooth);
  // Half-planes instead of a polygon: the far corners become features too; the tangent points stay smooth.
  const Shape h = make_shape(box(-2, -2, 4, 2),
                             {disk("D", pt(0, 0), 1), halfplane("top", pt(0, 1), 1), halfplane("bottom", pt(0, -1), 1),
                              halfplane("left", pt(-1, 0), 0), halfplane("right", pt(1, 0), 3)},
                             [](auto& in) { return in[0] || (in[1] && in[2] && in[3] && in[4]); });
  check_common(h);
  CHECK(feature_tally(h.surface) == tally(2, 2, 0));
  CHECK(link_at(h, pt(0, 1)).type == FeatureType::Smooth);
  // The disk alone, with the tangent line in the scene: the circle just continues through the tangent point
  // (a vertex of the arrangement) inside one patch.
  const Shape d = make_shape(box(-2, -2, 2, 2), {disk("D", pt(0, 0), 1), halfplane("top", pt(0, 1), 1)},
                             [](auto& in) { return in[0] == 1; });
  check_common(d);
  CHECK(feature_tally(d.surface) == tally(0, 0, 0));
}

TEST_CASE("two overlapping disks: union concave, lens convex", "[boundary2]") {
  const std::vector<Halfspace2> disks = {disk("D1", pt(0, 0), 2), disk("D2", pt(2, 0), 2)};
  const OneRootPoint top(OneRoot(q("1")), root("0", "1", "3")), bottom(OneRoot(q("1")), root("0", "-1", "3"));
  const Shape u = make_shape(box(-3, -3, 5, 3), disks, [](auto& in) { return in[0] || in[1]; });
  check_common(u);
  CHECK(feature_tally(u.surface) == tally(0, 0, 2));
  CHECK(link_at(u, top).type == FeatureType::Concave);
  CHECK(link_at(u, bottom).type == FeatureType::Concave);
  const Shape l = make_shape(box(-3, -3, 5, 3), disks, [](auto& in) { return in[0] && in[1]; });
  check_common(l);
  CHECK(feature_tally(l.surface) == tally(2, 0, 0));
  CHECK(link_at(l, top).type == FeatureType::Convex);
  CHECK(link_at(l, bottom).type == FeatureType::Convex);
  // The circles' x-extreme split points (2,0) and (0,0) lie on the lens: smooth corners inside one patch.
  CHECK(corner_tally(l.boundary) == tally(2, 2, 0));
  CHECK(l.surface.pieces.size() == 4u);
  const Shape d = make_shape(box(-3, -3, 5, 3), disks, [](auto& in) { return in[0] && !in[1]; });
  check_common(d);  // a moon: convex at both points
  CHECK(feature_tally(d.surface) == tally(2, 0, 0));
}

TEST_CASE("squares touching at a corner: a non-manifold vertex with two corners", "[boundary2]") {
  const Shape s = make_shape(box(-1, -1, 3, 3), {rect("S1", 0, 0, 1, 1), rect("S2", 1, 1, 2, 2)},
                             [](auto& in) { return in[0] || in[1]; });
  check_common(s);
  CHECK(corner_tally(s.boundary) == tally(8, 0, 0));
  const auto at = corners_at(s, pt(1, 1));
  REQUIRE(at.size() == 2u);
  // Each sector pairs two sides of the same square (pairing across squares would make features).
  CHECK(feature_tally(s.surface) == tally(0, 0, 0));
  for (const SolidCorner2& c : at) {
    const auto& edges = s.arranged.arrangement.edges();
    CHECK(edges[c.in_edge].halfspaces == edges[c.out_edge].halfspaces);
  }
  // The complement inside a frame: the two other quadrants at (1,1), again two right angles at one vertex.
  const Shape t = make_shape(box(-2, -2, 4, 4),
                             {rect("S1", 0, 0, 1, 1), rect("S2", 1, 1, 2, 2), rect("F", -1, -1, 3, 3)},
                             [](auto& in) { return in[2] && !in[0] && !in[1]; });
  check_common(t);
  const auto at2 = corners_at(t, pt(1, 1));
  REQUIRE(at2.size() == 2u);
  CHECK(at2[0].angle == CornerAngle::Convex);
  CHECK(at2[1].angle == CornerAngle::Convex);
  // The frame's four corners, 270 degrees at the squares' six other corners; the hole is one boundary cycle
  // through (1,1) twice, turning 2 - 6 = -4 right angles.
  CHECK(corner_tally(t.boundary) == tally(6, 0, 6));
  CHECK(feature_tally(t.surface) == tally(2, 0, 0));
  // Same squares with diagonal wedges from half-planes: x <= 1, y <= 1 and x >= 1, y >= 1 touching at (1,1).
  const Shape w = make_shape(box(-1, -1, 3, 3),
                             {halfplane("x<=1", pt(1, 0), 1), halfplane("y<=1", pt(0, 1), 1),
                              rect("F", 0, 0, 2, 2)},
                             [](auto& in) { return in[2] && in[0] == in[1]; });
  check_common(w);
  const auto at3 = corners_at(w, pt(1, 1));
  REQUIRE(at3.size() == 2u);
  CHECK(at3[0].angle == CornerAngle::Convex);
  CHECK(at3[1].angle == CornerAngle::Convex);
  CHECK(link_at(w, pt(2, 2)).type == FeatureType::Convex);
}

TEST_CASE("horns between internally tangent circles: cusps of 0 and 360 degrees", "[boundary2]") {
  // D1: radius 2 at the origin; D2: radius 1 at (1,0), touching D1 from inside at (2,0); H: y >= 0.
  const std::vector<Halfspace2> hs = {disk("D1", pt(0, 0), 2), disk("D2", pt(1, 0), 1), halfplane("H", pt(0, -1), 0),
                                      rect("B", -3, -3, 3, 3)};
  const Box2 domain = box(-4, -4, 4, 4);
  auto horn = [](const std::vector<char>& in) { return in[0] && !in[1] && in[2]; };
  const Shape s = make_shape(domain, hs, horn);
  check_common(s);
  // (2,0): a horn, angle 0; (0,0) and (-2,0): 90 degrees.
  CHECK(corner_tally(s.boundary) == tally(3, 0, 0, 1));
  CHECK(feature_tally(s.surface) == tally(3, 0, 0));
  REQUIRE(corners_at(s, pt(2, 0)).size() == 1u);
  CHECK(corners_at(s, pt(2, 0))[0].cusp);
  CHECK(link_at(s, pt(2, 0)).type == FeatureType::Convex);
  // The frame minus the horn: 360 degrees at (2,0), 270 at (0,0) and (-2,0), the frame's four corners, and
  // the frame's sides straight through where the line y = 0 crosses them.
  const Shape c = make_shape(domain, hs, [&](auto& in) { return in[3] && !horn(in); });
  check_common(c);
  CHECK(corner_tally(c.boundary) == tally(4, 2, 3, 1));
  CHECK(corners_at(c, pt(2, 0))[0].cusp);
  CHECK(link_at(c, pt(2, 0)).type == FeatureType::Concave);
  CHECK(link_at(c, pt(0, 0)).type == FeatureType::Concave);
  // The whole crescent D1 \ D2: two horns at (2,0), one above and one below the line.
  const Shape m = make_shape(domain, hs, [](auto& in) { return in[0] && !in[1]; });
  check_common(m);
  const auto at = corners_at(m, pt(2, 0));
  REQUIRE(at.size() == 2u);
  CHECK((at[0].cusp && at[1].cusp));
  CHECK(at[0].angle == CornerAngle::Convex);
  CHECK(at[1].angle == CornerAngle::Convex);
  // The frame minus the crescent: at (2,0) both circles just continue (180 degrees), inside each circle's patch.
  const Shape f = make_shape(domain, hs, [](auto& in) { return in[3] && !(in[0] && !in[1]); });
  check_common(f);
  const auto at2 = corners_at(f, pt(2, 0));
  REQUIRE(at2.size() == 2u);
  CHECK(at2[0].angle == CornerAngle::Smooth);
  CHECK(at2[1].angle == CornerAngle::Smooth);
  CHECK(!at2[0].cusp);
}

TEST_CASE("circles tangent from outside: two disks touching at one point", "[boundary2]") {
  // D1 radius 1 at (0,0), D2 radius 1 at (2,0): touching at (1,0). Union: two 360-degree cusps? No: each disk's
  // sector is 180 degrees (the circles just continue), so the union has two smooth corners at (1,0).
  const std::vector<Halfspace2> hs = {disk("D1", pt(0, 0), 1), disk("D2", pt(2, 0), 1), rect("B", -2, -2, 4, 2)};
  const Shape u = make_shape(box(-3, -3, 5, 3), hs, [](auto& in) { return in[0] || in[1]; });
  check_common(u);
  const auto at = corners_at(u, pt(1, 0));
  REQUIRE(at.size() == 2u);
  CHECK(at[0].angle == CornerAngle::Smooth);
  CHECK(at[1].angle == CornerAngle::Smooth);
  // The frame minus both disks: two horns meet at (1,0), each of angle 0.
  const Shape c = make_shape(box(-3, -3, 5, 3), hs, [](auto& in) { return in[2] && !in[0] && !in[1]; });
  check_common(c);
  const auto at2 = corners_at(c, pt(1, 0));
  REQUIRE(at2.size() == 2u);
  CHECK((at2[0].cusp && at2[1].cusp));
  CHECK(at2[0].angle == CornerAngle::Convex);
  CHECK(link_at(c, pt(-2, -2)).type == FeatureType::Convex);
}

TEST_CASE("empty solid and rejected inputs", "[boundary2]") {
  const Scene2 scene = make_scene(box(-1, -1, 3, 3), {rect("S", 0, 0, 2, 2)});
  const Arranged2 a = arrange(scene);
  const std::vector<char> none(a.complex.cells.size(), 0);
  const BoundarySurface empty = boundary_from_arrangement2(a, none);
  CHECK(empty.pieces.empty());
  CHECK(empty.links.empty());
  std::vector<char> outer(a.complex.cells.size(), 0);
  for (std::size_t f = 0; f < outer.size(); ++f) outer[f] = a.complex.cells[f].outer ? 1 : 0;
  CHECK_THROWS_AS(boundary_from_arrangement2(a, outer), std::invalid_argument);
  CHECK_THROWS_AS(boundary_from_arrangement2(a, std::vector<char>(outer.size() + 1, 0)), std::invalid_argument);
  CHECK_THROWS_AS(solid_boundary2(a.arrangement, std::vector<char>{}), std::invalid_argument);
}

TEST_CASE("split points are strictly inside their edges", "[boundary2]") {
  const Shape s = make_shape(box(-3, -3, 3, 3), {disk("D", pt(0, 0), 2), halfplane("H", pt(0, 1), 1)},
                             [](auto& in) { return in[0] && in[1]; });
  const auto& arr = s.arranged.arrangement;
  for (const SolidBoundaryEdge2& b : s.boundary.edges) {
    const PointQ2 p = edge_split_point(arr, b.edge);
    const PointLocation2 where = arr.locate(p);
    CHECK(where.kind == PointLocation2::Edge);
    CHECK(where.index == b.edge);
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Properties over random scenes and solids

namespace {

/// A random solid: each inner face in or out.
std::vector<char> random_solid(const Arranged2& a) {
  std::vector<char> solid;
  for (const Cell& c : a.complex.cells)
    solid.push_back(!c.outer && *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, 2)) == 1 ? 1 : 0);
  return solid;
}

/// The solid carried to another arrangement of the same (moved) scene: face f goes where `move` sends its
/// interior point.
std::vector<char> carried(const Arranged2& from, const std::vector<char>& solid, const Arranged2& to,
                          const std::function<PointQ2(const PointQ2&)>& move) {
  std::vector<char> out(to.complex.cells.size(), 0);
  for (std::size_t f = 0; f < from.arrangement.faces().size(); ++f) {
    const PointLocation2 where = to.arrangement.locate(move(from.arrangement.face_interiors()->get(f)));
    RC_ASSERT(where.kind == PointLocation2::Face);
    if (solid[f]) out.at(static_cast<std::size_t>(where.index)) = 1;
  }
  return out;
}

/// One corner as geometry sees it: where, what angle, and the feature flag of its link.
struct CornerSig {
  OneRootPoint at;
  CornerAngle angle;
  bool cusp;
  bool feature;
  int in_carrier, out_carrier;  ///< -1 when not compared
};

std::vector<CornerSig> signatures(const Arranged2& a, const SolidBoundary2& b, const BoundarySurface& s,
                                  const std::function<OneRootPoint(const OneRootPoint&)>& back,
                                  const std::vector<int>& original_of, bool with_features,
                                  bool reversed = false) {
  std::vector<CornerSig> out;
  for (std::size_t k = 0; k < b.corners.size(); ++k) {
    const SolidCorner2& c = b.corners[k];
    const BoundaryLink& link = s.links[k];
    CornerSig sig{back(a.arrangement.vertices()[c.vertex].point), c.angle, c.cusp, false, -1, -1};
    if (with_features) {
      sig.feature = link.feature;
      const BoundaryPiece& in = s.pieces[link.piece_a];
      const BoundaryPiece& out_piece = s.pieces[link.piece_b];
      sig.in_carrier = original_of[in.carrier] * 2 + in.carrier_complemented;
      sig.out_carrier = original_of[out_piece.carrier] * 2 + out_piece.carrier_complemented;
      if (reversed) std::swap(sig.in_carrier, sig.out_carrier);
    }
    out.push_back(sig);
  }
  return out;
}

bool same_sig(const CornerSig& x, const CornerSig& y) {
  return same_point(x.at, y.at) && x.angle == y.angle && x.cusp == y.cusp && x.feature == y.feature &&
         x.in_carrier == y.in_carrier && x.out_carrier == y.out_carrier;
}

/// Multiset equality by exact matching.
bool same_multiset(const std::vector<CornerSig>& xs, std::vector<CornerSig> ys) {
  if (xs.size() != ys.size()) return false;
  for (const CornerSig& x : xs) {
    auto it = std::find_if(ys.begin(), ys.end(), [&](const CornerSig& y) { return same_sig(x, y); });
    if (it == ys.end()) {
      RC_LOG() << "unmatched corner at " << x.at.exact_string() << " " << corner_angle_name(x.angle) << "\n";
      return false;
    }
    ys.erase(it);
  }
  return true;
}

bool has_coincident_boundaries(const Arrangement2& arr) {
  for (const ArrEdge2& e : arr.edges())
    if (e.halfspaces.size() > 1) return true;
  return false;
}

std::vector<int> identity(std::size_t n) {
  std::vector<int> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = static_cast<int>(k);
  return v;
}

/// x -> -x: domain, normals, centres and polygon vertices mirrored (polygons change orientation, allowed).
Scene2 mirrored(const Scene2& scene) {
  Scene2 m = scene;
  m.samples.clear();
  m.domain = Box2{pt(-scene.domain.max.x, scene.domain.min.y), pt(-scene.domain.min.x, scene.domain.max.y)};
  for (Halfspace2& h : m.halfspaces) {
    h.normal.x = -h.normal.x;
    h.center.x = -h.center.x;
    for (PointQ2& v : h.vertices) v.x = -v.x;
  }
  validate_and_resolve(m);
  return m;
}

OneRoot neg(const OneRoot& a) { return OneRoot(-a.a0, -a.a1, a.root); }

SceneGenOptions general_options() {
  SceneGenOptions o;
  o.max_halfspaces = 5;
  o.max_degeneracies = 2;
  return o;
}

}  // namespace

TEST_CASE("random solids: valid boundaries, each edge in one corner each way, deterministic", "[boundary2][property]") {
  rc::prop("structure", [] {
    const Scene2 scene = *gen_scene(general_options());
    const Arranged2 a = arrange(scene);
    const std::vector<char> solid = random_solid(a);
    const SolidBoundary2 b = solid_boundary2(a.arrangement, solid);
    const BoundarySurface s = boundary_from_arrangement2(a, solid);
    RC_ASSERT(check_boundary(s).empty());
    RC_ASSERT(s.pieces.size() == b.edges.size());
    std::map<int, int> as_in, as_out;
    for (const SolidCorner2& c : b.corners) {
      ++as_in[c.in_edge];
      ++as_out[c.out_edge];
      const auto& e = a.arrangement.edges();
      const SolidBoundaryEdge2* in = nullptr;
      for (const auto& be : b.edges)
        if (be.edge == c.in_edge) in = &be;
      RC_ASSERT(in != nullptr);
      RC_ASSERT((in->forward ? e[c.in_edge].target : e[c.in_edge].source) == c.vertex);
    }
    for (const SolidBoundaryEdge2& be : b.edges) {
      RC_ASSERT(as_in[be.edge] == 1);
      RC_ASSERT(as_out[be.edge] == 1);
    }
    // Carriers: a halfspace of the edge, the solid on the side the flag says.
    for (const BoundaryPiece& p : s.pieces) {
      const ArrEdge2& e = a.arrangement.edges()[p.origin];
      RC_ASSERT(std::find(e.halfspaces.begin(), e.halfspaces.end(), p.carrier) != e.halfspaces.end());
      const bool forward = std::find_if(b.edges.begin(), b.edges.end(), [&](const SolidBoundaryEdge2& x) {
                             return x.edge == p.origin;
                           })->forward;
      const int solid_face = forward ? e.left_face : e.right_face;
      RC_ASSERT(static_cast<bool>(a.complex.cells[solid_face].inside[p.carrier]) != p.carrier_complemented);
    }
    // Coverage of the interesting cases (printed by rapidcheck).
    const Tally t = corner_tally(b);
    std::map<int, int> per_vertex;
    for (const SolidCorner2& c : b.corners) ++per_vertex[c.vertex];
    RC_CLASSIFY(t.cusps > 0, "cusp");
    RC_CLASSIFY(feature_tally(s).smooth > 0, "smooth feature");
    RC_CLASSIFY(t.concave > 0, "concave");
    RC_CLASSIFY(std::any_of(per_vertex.begin(), per_vertex.end(), [](auto& kv) { return kv.second > 1; }),
                "non-manifold vertex");
    // Same input, same output.
    const BoundarySurface again = boundary_from_arrangement2(a, solid);
    RC_ASSERT(again.links.size() == s.links.size());
    for (std::size_t l = 0; l < s.links.size(); ++l) {
      RC_ASSERT(again.links[l].piece_a == s.links[l].piece_a);
      RC_ASSERT(again.links[l].piece_b == s.links[l].piece_b);
      RC_ASSERT(again.links[l].type == s.links[l].type);
      RC_ASSERT(again.links[l].feature == s.links[l].feature);
    }
  });
}

TEST_CASE("corner types are invariant under translation", "[boundary2][property]") {
  rc::prop("translation", [] {
    const Scene2 scene = *gen_scene(general_options());
    const int dx = *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(-5, 6));
    const int dy = *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(-5, 6));
    const PointQ2 d = pt(dx, dy);
    const Scene2 moved = translated(scene, d);
    const Arranged2 a = arrange(scene), b = arrange(moved);
    const std::vector<char> solid = random_solid(a);
    const std::vector<char> solid_b = carried(a, solid, b, [&](const PointQ2& p) { return pt(p.x + d.x, p.y + d.y); });
    const auto ids = identity(scene.halfspaces.size());
    auto same = [](const OneRootPoint& p) { return p; };
    auto back = [&](const OneRootPoint& p) {
      return OneRootPoint(OneRoot(p.x.a0 - d.x, p.x.a1, p.x.root), OneRoot(p.y.a0 - d.y, p.y.a1, p.y.root));
    };
    const auto sa = signatures(a, solid_boundary2(a.arrangement, solid), boundary_from_arrangement2(a, solid), same,
                               ids, true);
    const auto sb = signatures(b, solid_boundary2(b.arrangement, solid_b), boundary_from_arrangement2(b, solid_b),
                               back, ids, true);
    RC_ASSERT(same_multiset(sa, sb));
  });
}

TEST_CASE("corner types are invariant under permutation of the halfspaces", "[boundary2][property]") {
  rc::prop("permutation", [] {
    const Scene2 scene = *gen_scene(general_options());
    const std::size_t n = scene.halfspaces.size();
    std::vector<int> order = identity(n);
    for (std::size_t k = n; k > 1; --k)
      std::swap(order[k - 1], order[*rc::gen::resize(rc::kNominalSize, rc::gen::inRange<std::size_t>(0, k))]);
    const Scene2 other = permuted(scene, order);
    const Arranged2 a = arrange(scene), b = arrange(other);
    const std::vector<char> solid = random_solid(a);
    const std::vector<char> solid_b = carried(a, solid, b, [](const PointQ2& p) { return p; });
    // With coincident boundaries the carrier is the lowest index, which a permutation changes; then only the
    // geometry (where, which angle) must agree.
    const bool features = !has_coincident_boundaries(a.arrangement);
    auto same = [](const OneRootPoint& p) { return p; };
    const auto sa = signatures(a, solid_boundary2(a.arrangement, solid), boundary_from_arrangement2(a, solid), same,
                               identity(n), features);
    const auto sb = signatures(b, solid_boundary2(b.arrangement, solid_b), boundary_from_arrangement2(b, solid_b),
                               same, order, features);
    RC_ASSERT(same_multiset(sa, sb));
  });
}

TEST_CASE("corner types are invariant under mirroring", "[boundary2][property]") {
  rc::prop("mirror x -> -x", [] {
    const Scene2 scene = *gen_scene(general_options());
    const Scene2 other = mirrored(scene);
    const Arranged2 a = arrange(scene), b = arrange(other);
    const std::vector<char> solid = random_solid(a);
    const std::vector<char> solid_b = carried(a, solid, b, [](const PointQ2& p) { return pt(-p.x, p.y); });
    const auto ids = identity(scene.halfspaces.size());
    auto same = [](const OneRootPoint& p) { return p; };
    auto back = [](const OneRootPoint& p) { return OneRootPoint(neg(p.x), p.y); };
    const auto sa = signatures(a, solid_boundary2(a.arrangement, solid), boundary_from_arrangement2(a, solid), same,
                               ids, true);
    // A mirror reverses the walk with the solid on the left: incoming and outgoing pieces swap.
    const auto sb = signatures(b, solid_boundary2(b.arrangement, solid_b), boundary_from_arrangement2(b, solid_b),
                               back, ids, true, true);
    RC_ASSERT(same_multiset(sa, sb));
  });
}

namespace {

/// A rational pseudo-angle in [0, 4), strictly increasing with the direction's angle in [0, 2 pi); opposite
/// directions differ by exactly 2. Independent of the cross-product sort under test.
Rational pseudo_angle(const Rational& x, const Rational& y) {
  if (y >= 0 && x > 0) return y / (x + y);
  if (x <= 0 && y > 0) return 1 + (-x) / (-x + y);
  if (y <= 0 && x < 0) return 2 + (-y) / (-x - y);
  return 3 + x / (x - y);  // x >= 0, y < 0
}

PointQ2 rational_point(const OneRootPoint& p) {
  RC_ASSERT(p.is_rational());
  return {p.x.a0, p.y.a0};
}

}  // namespace

TEST_CASE("straight-edged solids: corners agree with a brute-force pseudo-angle oracle", "[boundary2][property]") {
  rc::prop("oracle", [] {
    SceneGenOptions o = general_options();
    o.disks = false;
    o.max_halfspaces = 6;
    const Scene2 scene = *gen_scene(o);
    const Arranged2 a = arrange(scene);
    const std::vector<char> solid = random_solid(a);
    const auto& arr = a.arrangement;
    // The boundary, from the face flags alone: (vertex, edge) -> direction leaving the vertex, out or in.
    struct Dir {
      int edge;
      bool out;
      Rational angle;
    };
    std::map<int, std::vector<Dir>> at;
    for (int e = 0; e < static_cast<int>(arr.edges().size()); ++e) {
      const ArrEdge2& edge = arr.edges()[e];
      const bool l = edge.left_face >= 0 && solid[edge.left_face], r = edge.right_face >= 0 && solid[edge.right_face];
      if (l == r) continue;
      const int from = l ? edge.source : edge.target, to = l ? edge.target : edge.source;
      const PointQ2 p = rational_point(arr.vertices()[from].point), q2 = rational_point(arr.vertices()[to].point);
      at[from].push_back({e, true, pseudo_angle(q2.x - p.x, q2.y - p.y)});
      at[to].push_back({e, false, pseudo_angle(p.x - q2.x, p.y - q2.y)});
    }
    std::vector<std::tuple<int, int, int, CornerAngle>> expected;  // vertex, out, in, angle
    for (const auto& [v, dirs] : at)
      for (const Dir& o_dir : dirs) {
        if (!o_dir.out) continue;
        const Dir* best = nullptr;
        Rational best_turn;
        for (const Dir& r : dirs) {
          if (r.out) continue;
          Rational turn = r.angle - o_dir.angle;
          if (turn < 0) turn += 4;
          RC_ASSERT(turn != 0);  // distinct segments never leave along one direction
          if (!best || turn < best_turn) {
            best = &r;
            best_turn = turn;
          }
        }
        RC_ASSERT(best != nullptr);
        const CornerAngle angle =
            best_turn < 2 ? CornerAngle::Convex : best_turn == 2 ? CornerAngle::Smooth : CornerAngle::Concave;
        expected.emplace_back(v, o_dir.edge, best->edge, angle);
      }
    std::sort(expected.begin(), expected.end());
    const SolidBoundary2 b = solid_boundary2(arr, solid);
    std::vector<std::tuple<int, int, int, CornerAngle>> got;
    for (const SolidCorner2& c : b.corners) {
      RC_ASSERT(!c.cusp);
      got.emplace_back(c.vertex, c.out_edge, c.in_edge, c.angle);
    }
    RC_ASSERT(got == expected);
  });
}

namespace {

/// Axis-aligned rectangles and half-planes with integer data in [-3, 3], domain [-5, 5]^2.
rc::Gen<Scene2> gen_rectilinear_scene() {
  return rc::gen::exec([] {
    auto uniform = [](int lo, int hi) { return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi)); };
    const int count = uniform(1, 5);
    std::vector<Halfspace2> hs;
    for (int k = 0; k < count; ++k) {
      const std::string name = "h" + std::to_string(k);
      const bool complement = uniform(0, 4) == 0;
      if (uniform(0, 3) == 0) {
        const int axis = uniform(0, 4);
        const PointQ2 normal = axis == 0 ? pt(1, 0) : axis == 1 ? pt(-1, 0) : axis == 2 ? pt(0, 1) : pt(0, -1);
        hs.push_back(halfplane(name, normal, uniform(-3, 4), complement));
      } else {
        const int x0 = uniform(-3, 3), y0 = uniform(-3, 3);
        const int x1 = uniform(x0 + 1, 4), y1 = uniform(y0 + 1, 4);
        hs.push_back(rect(name, x0, y0, x1, y1, complement));
      }
    }
    return make_scene(box(-5, -5, 5, 5), hs);
  });
}

}  // namespace

TEST_CASE("rectilinear solids: convex minus concave corners is 4 per outer cycle, -4 per hole",
          "[boundary2][property]") {
  rc::prop("turning number", [] {
    const Scene2 scene = *gen_rectilinear_scene();
    const Arranged2 a = arrange(scene);
    const std::vector<char> solid = random_solid(a);
    const SolidBoundary2 b = solid_boundary2(a.arrangement, solid);
    const auto& arr = a.arrangement;
    std::map<int, const SolidCorner2*> corner_after;  // in_edge -> its corner
    std::map<int, bool> forward;
    for (const SolidCorner2& c : b.corners) corner_after[c.in_edge] = &c;
    for (const SolidBoundaryEdge2& e : b.edges) forward[e.edge] = e.forward;
    std::set<int> seen;
    int total = 0, ccw_cycles = 0, cw_cycles = 0;
    for (const SolidBoundaryEdge2& start : b.edges) {
      if (seen.count(start.edge)) continue;
      int turn = 0;
      Rational twice_area = 0;
      for (int e = start.edge; !seen.count(e);) {
        seen.insert(e);
        const ArrEdge2& edge = arr.edges()[e];
        const PointQ2 p = rational_point(arr.vertices()[forward[e] ? edge.source : edge.target].point);
        const PointQ2 q2 = rational_point(arr.vertices()[forward[e] ? edge.target : edge.source].point);
        twice_area += p.x * q2.y - p.y * q2.x;
        const SolidCorner2& c = *corner_after.at(e);
        RC_ASSERT(!c.cusp);
        turn += c.angle == CornerAngle::Convex ? 1 : c.angle == CornerAngle::Concave ? -1 : 0;
        e = c.out_edge;
      }
      RC_ASSERT(twice_area != 0);
      RC_ASSERT(turn == (twice_area > 0 ? 4 : -4));
      (twice_area > 0 ? ccw_cycles : cw_cycles) += 1;
      total += turn;
    }
    RC_ASSERT(seen.size() == b.edges.size());
    const Tally t = corner_tally(b);
    RC_ASSERT(t.convex - t.concave == total);
    RC_ASSERT(total == 4 * (ccw_cycles - cw_cycles));
  });
}
