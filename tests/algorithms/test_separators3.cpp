// 3D separators (algorithms/csg/separators3.hpp) and 3D trees of solids (algorithms/csg/solid_tree.hpp), on
// data/scenes3d/split_box.json and the rebuilt BHC test objects (bhc_bracket.json, bhc_pocket.json; docs/csg3.md).
#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/algorithms/csg/describability.hpp>
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/algorithms/csg/separators3.hpp>
#include <hsx/algorithms/csg/solid_tree.hpp>
#include <hsx/io/csg_text.hpp>
#include <hsx/io/scene_json.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string>
#include <tuple>
#include <vector>

using namespace hsx;
using namespace hsx::csg;

namespace {

Scene3 scene3(const std::string& name) {
  return read_scene3_file(std::string(HSX_SOURCE_DIR) + "/data/scenes3d/" + name);
}

Rational R(long n, long d = 1) { return make_rational(Integer(n), Integer(d)); }

std::vector<std::string> names_of(const Scene3& s) {
  std::vector<std::string> names;
  for (const auto& h : s.halfspaces) names.push_back(h.name);
  return names;
}

/// The solid's exact volume: the sum of its cells' volumes.
Rational volume(const Arranged3& a, const std::vector<char>& cells) {
  Rational v = 0;
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (cells[c]) v += *a.arrangement.cells()[c].volume;
  return v;
}

/// split_box.json's left half: inside B, outside C, x < 0.
std::vector<char> left_half(const Arranged3& a) {
  std::vector<char> cells;
  for (const ArrCell3& c : a.arrangement.cells())
    cells.push_back(!c.outer && c.inside[0] && !c.inside[1] && c.interior.x < 0 ? 1 : 0);
  return cells;
}

/// bhc_pocket.json's solid, by the rule of docs/csg3.md on each cell's interior point and sides.
std::vector<char> pocket_solid(const Scene3& s, const Arranged3& a) {
  auto in = [&](const ArrCell3& c, const char* name) { return c.inside[static_cast<std::size_t>(s.find_halfspace(name))] != 0; };
  std::vector<char> cells;
  for (const ArrCell3& c : a.arrangement.cells()) {
    const Rational ax = c.interior.x < 0 ? Rational(-c.interior.x) : c.interior.x;
    const Rational ay = c.interior.y < 0 ? Rational(-c.interior.y) : c.interior.y;
    bool block = !c.outer;
    for (const char* h : {"BX0", "BX1", "BY0", "BY1", "BZ0", "BZ1"}) block = block && in(c, h);
    const bool blend = in(c, "P1") || in(c, "P2") || in(c, "P3") || in(c, "P4");
    const bool pocket = c.interior.z > 2 && ax < 3 && ay < R(5, 2) && (ax < 2 || ay < R(3, 2) || blend);
    const bool round = in(c, "O1") || in(c, "O2") || in(c, "O3") || in(c, "O4");
    const bool sliver = ax > 5 && ay > 4 && !round;
    cells.push_back(block && !pocket && !sliver ? 1 : 0);
  }
  return cells;
}

}  // namespace

TEST_CASE("separator candidates 3D: distinct planes crossing the domain, none of the scene's", "[csg][separators3]") {
  const Scene3 s = scene3("split_box.json");
  const Arranged3 a = arrange(s);
  const std::vector<char> solid = left_half(a);
  const Describability d = describability(a.complex, solid);
  REQUIRE(d.mixed.size() == 1);
  const auto candidates = separator_candidates(s, a, d);
  REQUIRE(!candidates.empty());
  std::set<std::tuple<Rational, Rational, Rational, Rational>> keys;
  bool bisector = false;
  for (const SeparatorPlane& p : candidates) {
    const Rational k = p.normal.x != 0 ? p.normal.x : p.normal.y != 0 ? p.normal.y : p.normal.z;
    REQUIRE(k != 0);
    CHECK(keys.insert({p.normal.x / k, p.normal.y / k, p.normal.z / k, p.offset / k}).second);
    bisector = bisector || p.origin == PlaneOrigin::Bisector;
  }
  CHECK(bisector);
  // x <= -1/2 (a face plane of C) frees both cells and resolves the term; y <= 0 crosses both cells.
  CHECK(predicted_resolved(a, d, SeparatorPlane{PointQ3{R(1), R(0), R(0)}, R(-1, 2)}) == std::make_pair(1, 2));
  CHECK(predicted_resolved(a, d, SeparatorPlane{PointQ3{R(0), R(1), R(0)}, R(0)}) == std::make_pair(0, 0));
  // x <= 0 goes through C only: both halves stay on their sides, resolved too.
  CHECK(predicted_resolved(a, d, SeparatorPlane{PointQ3{R(-2), R(0), R(0)}, R(0)}) == std::make_pair(1, 2));
}

TEST_CASE("carry_solid3: the same solid on a refining arrangement", "[csg][separators3]") {
  const Scene3 s = scene3("split_box.json");
  const Arranged3 a = arrange(s);
  const std::vector<char> solid = left_half(a);
  Scene3 t = s;
  Halfspace3 h;
  h.name = "cut";
  h.kind = HalfspaceKind3::Plane;
  h.normal = PointQ3{R(0), R(0), R(1)};
  h.offset = R(0);
  t.halfspaces.push_back(h);
  const Arranged3 b = arrange(t);
  const std::vector<char> carried = carry_solid3(a, solid, b);
  REQUIRE(carried.size() == b.complex.cells.size());
  CHECK(std::count(carried.begin(), carried.end(), 1) == 2);  // the left half, cut by z = 0
  CHECK(volume(b, carried) == volume(a, solid));
  CHECK(volume(a, solid) == R(6));
  CHECK_THROWS_AS(carry_solid3(a, std::vector<char>(2, 0), b), std::invalid_argument);
}

TEST_CASE("add_separators 3D: split box needs one plane; the limit stops it", "[csg][separators3]") {
  const Scene3 s = scene3("split_box.json");
  const Arranged3 a = arrange(s);
  const std::vector<char> solid = left_half(a);
  const SeparatedSolid3 r = add_separators(s, a, solid);
  CHECK(r.describable);
  CHECK(r.stop == SeparatorStop::Describable);
  CHECK(r.separators == 1);
  REQUIRE(r.rounds.size() == 1);
  REQUIRE(!r.rounds[0].trials.empty());
  int chosen = 0;
  for (const PlaneTrial& t : r.rounds[0].trials) {
    chosen += t.chosen ? 1 : 0;
    CHECK(t.arranged);
    CHECK(t.separated == (t.mixed_terms < r.rounds[0].mixed_terms || t.mixed_cells < r.rounds[0].mixed_cells));
  }
  CHECK(chosen == 1);
  CHECK(r.scene.halfspaces.size() == 3);
  CHECK(r.scene.halfspaces[2].name == "sep0");
  CHECK(volume(r.arranged, r.cells) == R(6));
  CHECK(describability(r.arranged.complex, r.cells).describable);
  // The chosen plane separates the two halves: their interior points lie on opposite sides.
  const Halfspace3& sep = r.scene.halfspaces[2];
  const auto side = [&](const PointQ3& p) { return sgn(dot3(sep.normal, p) - sep.offset); };
  CHECK(side(PointQ3{R(-5, 4), R(0), R(0)}) * side(PointQ3{R(5, 4), R(0), R(0)}) < 0);

  const SeparatedSolid3 none = add_separators(s, a, solid, 0);
  CHECK(!none.describable);
  CHECK(none.stop == SeparatorStop::MaxSeparators);
  CHECK(none.rounds.empty());
  CHECK_THROWS_AS(add_separators(s, a, solid, -1), std::invalid_argument);
}

TEST_CASE("BHC Fig. 9 rebuilt: the bracket is describable, its tree verified", "[csg][separators3][bhc_objects]") {
  const Scene3 s = scene3("bhc_bracket.json");
  REQUIRE(s.halfspaces.size() == 20);
  const Arranged3 a = arrange(s);
  const ExprPtr e = parse_csg_text("X0 & Y0 & Y1 & Z0 & ((X1 & Z1 & Ch1) | (U1 & Z2 & Ch2) | (G0 & G1 & Gd) | Boss) "
                                   "& ~H1 & ~H2 & ~H3 & ~(S0 & S1 & Sz)",
                                   names_of(s));
  const std::vector<char> solid = evaluate(*e, a.complex);
  const SolidTree t = build_tree(s, a, solid, SolidTreeOptions{true, 8});
  CHECK(!t.separated3);  // describable: separators not needed
  REQUIRE(t.has_verified_tree());
  CHECK(evaluate(*t.bhc.tree, a.complex) == solid);
  // The figures docs/csg3.md reports.
  CHECK(t.bhc.stats.leaves == 29);
  CHECK(t.bhc.stats.internal_nodes == 21);
  CHECK(t.bhc.stats.depth == 8);
  CHECK(t.bhc.stats.distinct_halfspaces == 20);
  CHECK(t.bhc.stats.duplicated_halfspaces == 7);
  CHECK(t.bhc.partitions == 2);
}

TEST_CASE("BHC Figs. 10-12 rebuilt: the rounded pocket, witness cells, 8 separating planes, the tree",
          "[csg][separators3][bhc_objects]") {
  const Scene3 s = scene3("bhc_pocket.json");
  REQUIRE(s.halfspaces.size() == 19);
  const Arranged3 a = arrange(s);
  const std::vector<char> solid = pocket_solid(s, a);
  const Describability d = describability(a.complex, solid);
  CHECK(!d.describable);
  // 8 terms of the block's rounded vertical edges (4 edges, each cut by the floor plane F) with one inside and one
  // outside cell each; the pocket's term: its 4 corner slivers (inside) and the pocket (outside).
  REQUIRE(d.mixed.size() == 9);
  int singles = 0;
  for (const MixedTerm& m : d.mixed)
    if (m.inside_cells.size() == 1 && m.outside_cells.size() == 1) ++singles;
  CHECK(singles == 8);
  CHECK(d.mixed.back().inside_cells.size() == 4);
  CHECK(d.mixed.back().outside_cells.size() == 1);

  const SolidTree t = build_tree(s, a, solid, SolidTreeOptions{true, 8});
  REQUIRE(t.separated3);
  CHECK(t.separated3->separators == 8);
  CHECK(t.separated3->describable);
  REQUIRE(t.has_verified_tree());
  // Every separator is a vertical plane through two tangent lines of a blend (an edge-vertex candidate).
  for (std::size_t k = 19; k < t.separated3->scene.halfspaces.size(); ++k) {
    const Halfspace3& h = t.separated3->scene.halfspaces[k];
    CHECK(h.kind == HalfspaceKind3::Plane);
    CHECK(h.normal.z == 0);
    CHECK(h.normal.x * h.normal.x == h.normal.y * h.normal.y);
  }
  for (const PlaneRound& r : t.separated3->rounds)
    for (const PlaneTrial& tr : r.trials)
      if (tr.chosen) CHECK(tr.plane.origin == PlaneOrigin::EdgeVertex);
  CHECK(volume(t.separated3->arranged, t.separated3->cells) == volume(a, solid));
  CHECK(t.bhc.stats.leaves == 27);
  CHECK(t.bhc.stats.internal_nodes == 19);
  CHECK(t.bhc.stats.duplicated_halfspaces == 0);
  // Seven separators are not enough.
  const SeparatedSolid3 short_of = add_separators(s, a, solid, 7);
  CHECK(!short_of.describable);
  CHECK(short_of.stop == SeparatorStop::MaxSeparators);
}
