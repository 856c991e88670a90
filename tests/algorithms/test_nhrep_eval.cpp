// Cross-check 2 of issue 5: NH-Rep trees with natural halfspaces evaluated exactly on every cell of 2D solids
// (algorithms/nhrep/evaluate.hpp), on hand-checked solids, random scenes and the kept counterexamples.
#include <hsx/algorithms/csg/describability.hpp>
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/algorithms/nhrep/compare.hpp>
#include <hsx/algorithms/nhrep/evaluate.hpp>
#include <hsx/complex/boundary_from_arrangement2.hpp>
#include <hsx/io/csg_text.hpp>
#include <hsx/io/nhrep_json.hpp>
#include <hsx/io/scene_json.hpp>
#include "support/random_scenes.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>

using namespace hsx;
using namespace hsx::nhrep;
using hsx::test::disk;
using hsx::test::halfplane;
using hsx::test::make_scene;
using hsx::test::polygon;
using hsx::test::pt;
using hsx::test::q;

namespace {

struct Pipeline {
  Arranged2 arranged;
  std::vector<char> solid;
  BuildResult built;
  std::vector<std::string> tree_problems;
  Evaluation eval;
};

Pipeline run_cells(Arranged2 arranged, std::vector<char> solid, bool nest_holes = false) {
  Pipeline p;
  p.arranged = std::move(arranged);
  p.solid = std::move(solid);
  BuildOptions options;
  options.nest_holes = nest_holes;
  p.built = build_tree(build_patch_graph(boundary_from_arrangement2(p.arranged, p.solid)), options);
  p.tree_problems = check_tree(p.built);
  p.eval = evaluate_tree(p.built, p.arranged.complex, p.solid);
  return p;
}

Pipeline run(const Scene2& scene, const std::string& csg, bool nest_holes = false) {
  Arranged2 arranged = arrange(scene);
  const auto expr = parse_csg_text(csg, arranged.complex.halfspace_names);
  std::vector<char> solid = csg::evaluate(*expr, arranged.complex);
  return run_cells(std::move(arranged), std::move(solid), nest_holes);
}

Box2 box(int r) { return Box2{pt(q(std::to_string(-r)), q(std::to_string(-r))), pt(q(std::to_string(r)), q(std::to_string(r)))}; }

/// x <= c ("X<c>"), x >= c, y <= c, y >= c as half-planes.
Halfspace2 x_le(const std::string& n, const std::string& c) { return halfplane(n, pt(q("1"), q("0")), q(c)); }
Halfspace2 x_ge(const std::string& n, const std::string& c) { return halfplane(n, pt(q("-1"), q("0")), -q(c)); }
Halfspace2 y_le(const std::string& n, const std::string& c) { return halfplane(n, pt(q("0"), q("1")), q(c)); }
Halfspace2 y_ge(const std::string& n, const std::string& c) { return halfplane(n, pt(q("0"), q("-1")), -q(c)); }

std::vector<std::string> natural_names(const Pipeline& p) {
  std::vector<std::string> names;
  for (int h : p.eval.natural_halfspaces) names.push_back(p.arranged.complex.halfspace_names[static_cast<std::size_t>(h)]);
  return names;
}

/// The leaves of `node` as "name" / "~name" (complemented), sorted, for readable expectations.
std::vector<std::string> leaf_names(const Pipeline& p, int node) {
  std::vector<std::string> out;
  for (int leaf : p.built.tree.nodes[static_cast<std::size_t>(node)].leaves) {
    const NaturalHalfspace& h = p.eval.leaf_halfspace[static_cast<std::size_t>(leaf)];
    out.push_back((h.complemented ? "~" : "") + p.arranged.complex.halfspace_names[static_cast<std::size_t>(h.halfspace)]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Describability w.r.t. the natural halfspaces by csg::describability on the complex restricted to them.
bool restricted_describable(const Complex& c, const std::vector<int>& halfspaces, const std::vector<char>& solid) {
  Complex r;
  r.dimension = c.dimension;
  for (int h : halfspaces) r.halfspace_names.push_back(c.halfspace_names[static_cast<std::size_t>(h)]);
  for (const Cell& cell : c.cells) {
    Cell k;
    k.outer = cell.outer;
    for (int h : halfspaces) k.inside.push_back(cell.inside[static_cast<std::size_t>(h)]);
    r.cells.push_back(k);
  }
  return csg::describability(r, solid).describable;
}

void require_consistent(const Pipeline& p) {
  INFO("tree " << nhtree_text(p.built.tree));
  REQUIRE(p.tree_problems.empty());
  REQUIRE(p.eval.violations.empty());
  CHECK(p.eval.describable == restricted_describable(p.arranged.complex, p.eval.natural_halfspaces, p.solid));
}

}  // namespace

// ---- hand-checked solids ------------------------------------------------------------------------------------------

TEST_CASE("nheval: a square of four half-planes is max of its sides, correct", "[nheval]") {
  const Scene2 s = make_scene(box(5), {x_ge("L", "0"), x_le("R", "2"), y_ge("B", "0"), y_le("T", "2")});
  const Pipeline p = run(s, "L & R & B & T");
  require_consistent(p);
  REQUIRE(p.built.tree.nodes.size() == 1);
  CHECK(p.built.tree.nodes[0].op == Op::Max);
  CHECK(leaf_names(p, 0) == std::vector<std::string>{"B", "L", "R", "T"});
  CHECK(p.eval.correct);
  CHECK(p.eval.verdict == Verdict::TreeCorrect);
  CHECK(natural_names(p) == std::vector<std::string>{"L", "R", "B", "T"});
}

TEST_CASE("nheval: a square polygon is one patch, one leaf, correct", "[nheval]") {
  const Scene2 s = make_scene(box(5), {polygon("P", {pt(q("0"), q("0")), pt(q("2"), q("0")), pt(q("2"), q("2")),
                                                     pt(q("0"), q("2"))})});
  const Pipeline p = run(s, "P");
  require_consistent(p);
  CHECK(p.built.graph.live_patches().size() == 1);
  CHECK(p.eval.verdict == Verdict::TreeCorrect);
}

TEST_CASE("nheval: an L shape from two rectangle polygons is min of them, correct", "[nheval]") {
  const Scene2 s = make_scene(box(5), {polygon("R1", {pt(q("0"), q("0")), pt(q("2"), q("0")), pt(q("2"), q("1")),
                                                      pt(q("0"), q("1"))}),
                                       polygon("R2", {pt(q("0"), q("0")), pt(q("1"), q("0")), pt(q("1"), q("2")),
                                                      pt(q("0"), q("2"))})});
  const Pipeline p = run(s, "R1 | R2");
  require_consistent(p);
  REQUIRE(p.built.tree.nodes.size() == 1);
  CHECK(p.built.tree.nodes[0].op == Op::Min);
  CHECK(leaf_names(p, 0) == std::vector<std::string>{"R1", "R2"});
  CHECK(p.eval.verdict == Verdict::TreeCorrect);
}

TEST_CASE("nheval: an L shape of six half-planes is max(sides, min(notch sides)), correct", "[nheval]") {
  const Scene2 s = make_scene(box(5), {x_ge("X0", "0"), y_ge("Y0", "0"), x_le("X2", "2"), y_le("Y1", "1"),
                                       x_le("X1", "1"), y_le("Y2", "2")});
  const Pipeline p = run(s, "(X0 & Y0 & X2 & Y1) | (X0 & Y0 & X1 & Y2)");
  require_consistent(p);
  REQUIRE(p.built.tree.nodes.size() == 2);
  CHECK(p.built.tree.nodes[0].op == Op::Max);
  CHECK(leaf_names(p, 0) == std::vector<std::string>{"X0", "X2", "Y0", "Y2"});
  CHECK(p.built.tree.nodes[1].op == Op::Min);
  CHECK(leaf_names(p, 1) == std::vector<std::string>{"X1", "Y1"});
  CHECK(p.eval.verdict == Verdict::TreeCorrect);
}

TEST_CASE("nheval: union of two disks is min, lens is max, disk minus a notch is max(A, ~B); all correct", "[nheval]") {
  const Scene2 s = make_scene(box(6), {disk("A", pt(q("0"), q("0")), q("2")), disk("B", pt(q("3"), q("0")), q("2"))});
  SECTION("union") {
    const Pipeline p = run(s, "A | B");
    require_consistent(p);
    REQUIRE(p.built.tree.nodes.size() == 1);
    CHECK(p.built.tree.nodes[0].op == Op::Min);
    CHECK(leaf_names(p, 0) == std::vector<std::string>{"A", "B"});
    CHECK(p.eval.verdict == Verdict::TreeCorrect);
  }
  SECTION("lens") {
    const Pipeline p = run(s, "A & B");
    require_consistent(p);
    REQUIRE(p.built.tree.nodes.size() == 1);
    CHECK(p.built.tree.nodes[0].op == Op::Max);
    CHECK(leaf_names(p, 0) == std::vector<std::string>{"A", "B"});
    CHECK(p.eval.verdict == Verdict::TreeCorrect);
  }
  SECTION("notch") {
    const Pipeline p = run(s, "A - B");
    require_consistent(p);
    REQUIRE(p.built.tree.nodes.size() == 1);
    CHECK(p.built.tree.nodes[0].op == Op::Max);
    CHECK(leaf_names(p, 0) == std::vector<std::string>{"A", "~B"});
    CHECK(p.eval.verdict == Verdict::TreeCorrect);
  }
}

TEST_CASE("nheval: two towers of different heights: describable, but the short tower's top line cuts the tall one",
          "[nheval]") {
  // [0,4]x[0,1] | [0,1]x[1,3] | [3,4]x[1,2]. The right tower's top y <= 2 has convex corners only, so it is a leaf
  // of the max root; its natural half-plane (the whole line y = 2) removes the left tower above y = 2.
  const Scene2 s = make_scene(box(6), {y_ge("B", "0"), x_le("R", "4"), y_le("T2", "2"), x_ge("I3", "3"),
                                       y_le("M", "1"), x_le("I1", "1"), y_le("T3", "3"), x_ge("L", "0")});
  const Pipeline p = run(s, "(L & R & B & M) | (L & I1 & B & T3) | (I3 & R & B & T2)");
  require_consistent(p);
  REQUIRE(p.built.tree.nodes.size() == 2);
  CHECK(leaf_names(p, 0) == std::vector<std::string>{"B", "L", "R", "T2", "T3"});
  CHECK(leaf_names(p, 1) == std::vector<std::string>{"I1", "I3", "M"});
  CHECK(p.eval.describable);
  CHECK_FALSE(p.eval.correct);
  CHECK(p.eval.verdict == Verdict::DescribableButFails);
  CHECK(p.eval.wrong_outside.empty());
  REQUIRE_FALSE(p.eval.wrong_inside.empty());
  for (int k : p.eval.wrong_inside) {  // exactly the left tower above y = 2
    const auto& w = p.arranged.complex.cells[static_cast<std::size_t>(k)].witness.get();
    CHECK(w[0] < q("1"));
    CHECK(w[1] > q("2"));
  }
  // The tree itself is right elsewhere: only those cells are wrong.
  std::vector<char> fixed = p.eval.tree_value;
  for (int k : p.eval.wrong_inside) fixed[static_cast<std::size_t>(k)] = 1;
  CHECK(fixed == p.solid);
}

TEST_CASE("nheval: an annulus gets a min root over its two loops, which is the whole plane",
          "[nheval]") {
  const Scene2 s = make_scene(box(6), {disk("A", pt(q("0"), q("0")), q("3")), disk("B", pt(q("0"), q("0")), q("1"))});
  const Pipeline p = run(s, "A - B");
  require_consistent(p);
  REQUIRE(p.built.tree.nodes.size() == 3);
  CHECK(p.built.tree.nodes[0].op == Op::Min);
  CHECK(p.eval.verdict == Verdict::DescribableButFails);
  CHECK(p.eval.wrong_inside.empty());
  // min(A, ~B) is the whole plane: the hole and everything outside A are wrong.
  CHECK(std::all_of(p.eval.tree_value.begin(), p.eval.tree_value.end(), [](char v) { return v != 0; }));
  CHECK(static_cast<long>(p.eval.wrong_outside.size()) == std::count(p.solid.begin(), p.solid.end(), 0));
}

TEST_CASE("nheval: with nest_holes, holes are intersected with their part and islands united", "[nheval]") {
  const Scene2 s = make_scene(box(6), {disk("A", pt(q("0"), q("0")), q("3")), disk("B", pt(q("0"), q("0")), q("2")),
                                       disk("C", pt(q("0"), q("0")), q("1")), x_le("X", "4"), x_ge("W", "-4"),
                                       y_le("Y", "4"), y_ge("Z", "-4")});
  SECTION("an annulus") {
    const Pipeline p = run(s, "A - B", true);
    require_consistent(p);
    CHECK(p.built.tree.nodes[static_cast<std::size_t>(p.built.tree.root)].op == Op::Max);
    CHECK(p.eval.verdict == Verdict::TreeCorrect);
  }
  SECTION("an annulus with an island in its hole") {
    const Pipeline paper = run(s, "(A - B) | C");
    require_consistent(paper);
    CHECK(paper.eval.verdict == Verdict::DescribableButFails);
    const Pipeline p = run(s, "(A - B) | C", true);
    require_consistent(p);
    CHECK(p.built.tree.nodes[static_cast<std::size_t>(p.built.tree.root)].op == Op::Min);
    CHECK(p.eval.verdict == Verdict::TreeCorrect);
  }
  SECTION("a square with a round hole, and with a square hole") {
    CHECK(run(s, "X & W & Y & Z - B", true).eval.verdict == Verdict::TreeCorrect);
    CHECK(run(s, "X & W & Y & Z - B").eval.verdict == Verdict::DescribableButFails);
  }
}

TEST_CASE("nheval: a wedge bitten by a disk is not describable by its patches' halfspaces", "[nheval]") {
  // y >= |x| minus the disk of radius 5/2 around (0, 3): the disk crosses both lines, so the wedge outside the
  // disk has two pieces with the same signs; the solid is the one at the apex.
  const Scene2 s = make_scene(box(8), {halfplane("U", pt(q("1"), q("-1")), q("0")),
                                       halfplane("V", pt(q("-1"), q("-1")), q("0")),
                                       disk("D", pt(q("0"), q("3")), q("5/2"))});
  Arranged2 a = arrange(s);
  std::vector<char> solid(a.complex.cells.size(), 0);
  for (std::size_t k = 0; k < solid.size(); ++k) {
    const Cell& c = a.complex.cells[k];
    solid[k] = c.inside[0] && c.inside[1] && !c.inside[2] && c.witness.get()[1] < q("1");
  }
  const Pipeline p = run_cells(std::move(a), solid);
  require_consistent(p);
  CHECK_FALSE(p.eval.describable);
  CHECK(p.eval.verdict == Verdict::NotDescribable);
  CHECK_FALSE(p.eval.wrong_outside.empty());  // the far piece of the wedge
  REQUIRE(p.eval.mixed.size() == 1);
  CHECK(p.eval.mixed[0].signs == std::vector<char>{1, 1, 0});
}

TEST_CASE("nheval: a broken tree or a wrong carrier is caught", "[nheval]") {
  const Scene2 s = make_scene(box(6), {disk("A", pt(q("0"), q("0")), q("2")), disk("B", pt(q("3"), q("0")), q("2"))});
  Pipeline p = run(s, "A | B");
  REQUIRE(p.eval.correct);
  SECTION("flipping the root's op makes the tree wrong on the cells of A xor B") {
    BuildResult broken = p.built;
    broken.tree.nodes[0].op = Op::Max;
    const Evaluation e = evaluate_tree(broken, p.arranged.complex, p.solid);
    CHECK_FALSE(e.correct);
    CHECK(e.verdict == Verdict::DescribableButFails);
    CHECK(e.wrong_outside.empty());
    CHECK(e.wrong_inside.size() >= 2);
  }
  SECTION("a piece on no halfspace is a violation") {
    BuildResult broken = p.built;
    broken.graph.surface.pieces[0].carrier = -1;
    CHECK_FALSE(evaluate_tree(broken, p.arranged.complex, p.solid).violations.empty());
  }
  SECTION("pieces of one patch on different carriers is a violation") {
    BuildResult broken = p.built;
    const auto live = broken.graph.live_patches();
    const auto& pieces = broken.graph.patches[static_cast<std::size_t>(live[0])].pieces;
    REQUIRE(pieces.size() >= 2);  // a circle is split by CGAL at its x-extreme points
    broken.graph.surface.pieces[static_cast<std::size_t>(pieces[1])].carrier_complemented ^= true;
    CHECK_FALSE(evaluate_tree(broken, p.arranged.complex, p.solid).violations.empty());
  }
  SECTION("a wrong solid size is refused") {
    CHECK_THROWS_AS(evaluate_tree(p.built, p.arranged.complex, std::vector<char>(1, 0)), std::invalid_argument);
  }
}

// ---- random scenes --------------------------------------------------------------------------------------------------

namespace {

csg::ExprPtr gen_expr(int halfspaces, int depth) {
  if (depth == 0 || *rc::gen::inRange(0, 4) == 0) {
    csg::ExprPtr l = csg::leaf(*rc::gen::inRange(0, halfspaces));
    return *rc::gen::inRange(0, 4) == 0 ? csg::complement(l) : l;
  }
  csg::ExprPtr a = gen_expr(halfspaces, depth - 1), b = gen_expr(halfspaces, depth - 1);
  switch (*rc::gen::inRange(0, 3)) {
    case 0: return csg::unite({a, b});
    case 1: return csg::intersect({a, b});
    default: return csg::difference(a, b);
  }
}

/// A random solid on the scene's cells: a random subset of the inner cells, or a CSG expression (outer cells
/// dropped, the solid must stay inside the domain).
std::vector<char> gen_solid(const Complex& c) {
  std::vector<char> solid(c.cells.size(), 0);
  if (*rc::gen::arbitrary<bool>()) {
    for (std::size_t k = 0; k < solid.size(); ++k)
      solid[k] = c.cells[k].outer ? 0 : static_cast<char>(*rc::gen::inRange(0, 2));
  } else {
    solid = csg::evaluate(*gen_expr(c.halfspace_count(), 3), c);
    for (std::size_t k = 0; k < solid.size(); ++k)
      if (c.cells[k].outer) solid[k] = 0;
  }
  return solid;
}

/// The solid carried to an arrangement of the same geometry moved by `offset`: each new cell's witness, moved
/// back, lies in one old cell.
std::vector<char> carry(const Arranged2& from, const std::vector<char>& solid, const Arranged2& to,
                        const PointQ2& offset) {
  std::vector<char> out;
  for (std::size_t f = 0; f < to.arrangement.faces().size(); ++f) {
    const PointQ2& p = to.arrangement.face_interiors()->get(f);
    const PointLocation2 loc = from.arrangement.locate(PointQ2{p.x - offset.x, p.y - offset.y});
    RC_ASSERT(loc.kind == PointLocation2::Face);
    out.push_back(solid[static_cast<std::size_t>(loc.index)]);
  }
  return out;
}

bool has_coincident_boundaries(const Complex& c) {
  return std::any_of(c.supports.begin(), c.supports.end(), [](const std::vector<int>& g) { return g.size() > 1; });
}

void assert_consistent(const Pipeline& p) {
  RC_ASSERT(p.tree_problems.empty());
  RC_ASSERT(p.eval.violations.empty());
  RC_ASSERT(p.eval.correct == (p.eval.wrong_inside.empty() && p.eval.wrong_outside.empty()));
  if (p.eval.correct) RC_ASSERT(p.eval.describable);
  if (!p.eval.describable) RC_ASSERT(!(p.eval.wrong_inside.empty() && p.eval.wrong_outside.empty()));
  RC_ASSERT(p.eval.describable == restricted_describable(p.arranged.complex, p.eval.natural_halfspaces, p.solid));
  // The tree value agrees with the public one-vector evaluation, and wrong cells are exactly the disagreements.
  for (std::size_t k = 0; k < p.solid.size(); ++k) {
    const bool v = tree_value(p.built.tree, p.eval.leaf_halfspace, p.arranged.complex.cells[k].inside);
    RC_ASSERT(static_cast<char>(v) == p.eval.tree_value[k]);
  }
  std::size_t disagreements = 0;
  for (std::size_t k = 0; k < p.solid.size(); ++k) disagreements += (p.solid[k] != 0) != (p.eval.tree_value[k] != 0);
  RC_ASSERT(disagreements == p.eval.wrong_inside.size() + p.eval.wrong_outside.size());
  // Every natural halfspace carries some boundary edge of the solid, and every boundary edge's carrier is natural.
  const auto& names = p.eval.natural_halfspaces;
  for (const BoundaryPiece& piece : p.built.graph.surface.pieces)
    if (!piece.retired) RC_ASSERT(std::binary_search(names.begin(), names.end(), piece.carrier));
  RC_TAG(verdict_key(p.eval.verdict));
  RC_TAG(p.built.decompositions.empty() ? "no decomposition" : "decomposed");
}

test::SceneGenOptions eval_scenes() {
  test::SceneGenOptions o;
  o.max_halfspaces = 5;
  o.max_degeneracies = 1;
  return o;
}

}  // namespace

TEST_CASE("nheval: on random solids the tree is valid and the classification consistent", "[nheval][property]") {
  rc::prop("check_tree holds; correct => describable; not describable => wrong cells", [] {
    const Scene2 scene = *test::gen_scene(eval_scenes());
    Arranged2 a = arrange(scene);
    const std::vector<char> solid = gen_solid(a.complex);
    RC_PRE(std::any_of(solid.begin(), solid.end(), [](char c) { return c != 0; }));
    assert_consistent(run_cells(std::move(a), solid));
  });
}

TEST_CASE("nheval: nest_holes keeps trees valid and changes nothing for solids without holes", "[nheval][property]") {
  rc::prop("nested vs paper", [] {
    const Scene2 scene = *test::gen_scene(eval_scenes());
    Arranged2 a = arrange(scene);
    const std::vector<char> solid = gen_solid(a.complex);
    RC_PRE(std::any_of(solid.begin(), solid.end(), [](char c) { return c != 0; }));
    const Pipeline paper = run_cells(a, solid);
    const Pipeline nested = run_cells(std::move(a), solid, true);
    assert_consistent(nested);
    const auto& pieces = nested.built.graph.surface.pieces;
    const bool holes = std::any_of(pieces.begin(), pieces.end(), [](const BoundaryPiece& b) { return b.hole; });
    std::vector<int> identity(paper.built.graph.patches.size());
    std::iota(identity.begin(), identity.end(), 0);
    if (!holes) {
      RC_ASSERT(canonical_form(paper.built.tree, identity) == canonical_form(nested.built.tree, identity));
      RC_ASSERT(paper.eval.verdict == nested.eval.verdict);
    }
    RC_TAG(holes ? "holes" : "no holes");
    RC_TAG(std::string("paper ") + verdict_key(paper.eval.verdict) + ", nested " + verdict_key(nested.eval.verdict));
  });
}

TEST_CASE("nheval: the classification does not depend on where the scene is or how its halfspaces are ordered",
          "[nheval][property]") {
  rc::prop("translation and permutation", [] {
    const Scene2 scene = *test::gen_scene(eval_scenes());
    const Arranged2 a = arrange(scene);
    const std::vector<char> solid = gen_solid(a.complex);
    RC_PRE(std::any_of(solid.begin(), solid.end(), [](char c) { return c != 0; }));
    const Pipeline base = run_cells(a, solid);
    assert_consistent(base);

    const PointQ2 offset = pt(Rational(*rc::gen::inRange(-7, 8)) / 2, Rational(*rc::gen::inRange(-7, 8)) / 3);
    const Arranged2 moved_arranged = arrange(test::translated(scene, offset));
    const Pipeline moved = run_cells(moved_arranged, carry(a, solid, moved_arranged, offset));
    assert_consistent(moved);
    // Translation keeps the arrangement's combinatorics: the same verdict, natural set and wrong-cell counts.
    RC_ASSERT(moved.eval.verdict == base.eval.verdict);
    RC_ASSERT(moved.eval.natural_halfspaces == base.eval.natural_halfspaces);
    RC_ASSERT(moved.eval.wrong_inside.size() == base.eval.wrong_inside.size());
    RC_ASSERT(moved.eval.wrong_outside.size() == base.eval.wrong_outside.size());

    std::vector<int> order(scene.halfspaces.size());
    std::iota(order.begin(), order.end(), 0);
    for (int i = static_cast<int>(order.size()); i > 1; --i)
      std::swap(order[static_cast<std::size_t>(i - 1)], order[static_cast<std::size_t>(*rc::gen::inRange(0, i))]);
    const Arranged2 permuted_arranged = arrange(test::permuted(scene, order));
    const Pipeline perm = run_cells(permuted_arranged, carry(a, solid, permuted_arranged, pt(Rational(0), Rational(0))));
    assert_consistent(perm);
    // Coincident boundaries pick the lowest-index carrier, so the patches (and the natural set) may depend on the
    // order there; elsewhere the natural set is the same halfspaces renamed, and so is describability.
    if (!has_coincident_boundaries(a.complex)) {
      std::vector<int> renamed;
      for (int h : perm.eval.natural_halfspaces) renamed.push_back(order[static_cast<std::size_t>(h)]);
      std::sort(renamed.begin(), renamed.end());
      RC_ASSERT(renamed == base.eval.natural_halfspaces);
      RC_ASSERT(perm.eval.describable == base.eval.describable);
      // Without decompositions Algorithm 1 sees isomorphic patch graphs and builds the same tree up to names.
      if (base.built.decompositions.empty() && perm.built.decompositions.empty())
        RC_ASSERT(perm.eval.verdict == base.eval.verdict);
    }
  });
}

// ---- the kept counterexamples ---------------------------------------------------------------------------------------

TEST_CASE("nheval: every kept NH-Rep counterexample is still describable with a failing natural tree", "[nheval]") {
  const std::filesystem::path dir = std::filesystem::path(HSX_SOURCE_DIR) / "data" / "counterexamples" / "nhrep";
  REQUIRE(std::filesystem::is_directory(dir));
  int files = 0;
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".json") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  for (const auto& path : scenes) {
    INFO(path.filename().string());
    std::filesystem::path csg_path = path;
    csg_path.replace_extension(".csg");
    REQUIRE(std::filesystem::is_regular_file(csg_path));
    ++files;
    const Scene2 scene = read_scene_file(path.string());
    Arranged2 a = arrange(scene);
    const auto expr = read_csg_argument(csg_path.string(), a.complex.halfspace_names);
    const std::vector<char> solid = csg::evaluate(*expr, a.complex);
    const Pipeline p = run_cells(std::move(a), solid);
    require_consistent(p);
    CHECK(p.eval.verdict == Verdict::DescribableButFails);
  }
  CHECK(files > 0);
}
