// The theory behind the Halfspace CSG layer, checked on random scenes (tests/support/random_scenes.hpp) and on
// hand cases. Each test names the statement it checks; proofs/csg.md gives the statements and their proofs.
//   1. Shapiro-Vossler describability = BHC success; verified trees; mixed-term witnesses (csg::describability,
//      csg::bhc).
//   2. Every CSG expression over the scene's halfspaces is describable and BHC rebuilds it.
//   3. BHC on hand cases, and BSH Fig. 2's six shapes (data/figures/fig02-*.json).
//   4. GENERATE-SAMPLES (bsh::generate_samples): Prop. 6.1 (best-first) and Prop. B.1 (beam, K = 1) on generic
//      inputs, with the counts' bounds; non-generic inputs are skipped and counted (see proofs/csg.md, Section 5),
//      targets running along a coincident patch reversed are checked too (a bug once, fixed; see theory 4 [bug]).
//   Hidden tests ("[.explore...]") are the searches that found it and tools to study one input round by round.
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/algorithms/bsh/samples.hpp>
#include <hsx/algorithms/csg/bhc.hpp>
#include <hsx/algorithms/csg/describability.hpp>
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/complex/complex.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/csg_text.hpp>
#include <hsx/io/scene_json.hpp>
#include "support/random_labellings.hpp"
#include "support/random_scenes.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace hsx;
using namespace hsx::csg;
using namespace hsx::test;

namespace {

// ---------------------------------------------------------------------------------------------------------------
// Random solids.

SceneGenOptions csg_scenes() {
  SceneGenOptions o;
  o.max_halfspaces = 5;
  o.max_degeneracies = 2;
  return o;
}

std::vector<char> planar_of(const Scene2& scene) {
  std::vector<char> planar;
  for (const auto& h : scene.halfspaces) planar.push_back(h.kind == HalfspaceKind2::Halfplane ? 1 : 0);
  return planar;
}

/// A random expression over halfspaces 0..n-1 (every operation, constants included), built with the constructors.
ExprPtr random_expr(int n, int depth) {
  const int kind = *rc::gen::inRange(0, depth > 0 ? 10 : 3);
  if (kind <= 1) return leaf(*rc::gen::inRange(0, n));
  if (kind == 2) {
    if (*rc::gen::inRange(0, 10) == 0) return *rc::gen::arbitrary<bool>() ? empty() : full();
    return leaf(*rc::gen::inRange(0, n));
  }
  if (kind == 3) return complement(random_expr(n, depth - 1));
  if (kind <= 7) {
    const int k = *rc::gen::inRange(2, 4);
    std::vector<ExprPtr> children;
    for (int i = 0; i < k; ++i) children.push_back(random_expr(n, depth - 1));
    return kind <= 5 ? unite(children) : intersect(children);
  }
  ExprPtr a = random_expr(n, depth - 1);
  return difference(a, random_expr(n, depth - 1));
}

/// Cells grouped by sign vector (the canonical intersection terms that are not empty), computed here directly.
std::map<std::vector<char>, std::vector<int>> terms_of(const Complex& c) {
  std::map<std::vector<char>, std::vector<int>> terms;
  for (int k = 0; k < static_cast<int>(c.cells.size()); ++k) terms[c.cells[k].inside].push_back(k);
  return terms;
}

/// A random solid, in one of four ways: a random labelling with outer cells 0; a random expression;
/// a random function of the sign vector (describable by construction); such a function with one cell of a
/// multi-cell term flipped (not describable by construction, when the complex has such a term; always tried
/// with `prefer_flip`).
std::vector<char> random_solid(const Complex& c, bool prefer_flip = false) {
  const int n = static_cast<int>(c.cells.size());
  std::vector<char> solid(n, 0);
  switch (prefer_flip ? 3 : *rc::gen::inRange(0, 4)) {
    case 0:
      for (int k = 0; k < n; ++k) solid[k] = c.cells[k].outer ? 0 : static_cast<char>(*rc::gen::inRange(0, 2));
      return solid;
    case 1:
      return evaluate(*random_expr(c.halfspace_count(), 3), c);
    default: {
      const auto terms = terms_of(c);
      for (const auto& [signs, cells] : terms) {
        const char v = static_cast<char>(*rc::gen::inRange(0, 2));
        for (int k : cells) solid[k] = v;
      }
      std::vector<const std::vector<int>*> multi;
      for (const auto& [signs, cells] : terms)
        if (cells.size() > 1) multi.push_back(&cells);
      if (multi.empty() || (!prefer_flip && *rc::gen::inRange(0, 2) == 0)) {
          return solid;
      }
      const auto& cells = *multi[static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(multi.size())))];
      const int k = cells[static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(cells.size())))];
      solid[k] = solid[k] ? 0 : 1;
      return solid;
    }
  }
}

/// The canonical disjunctive form: the union, over the sign vectors of the inside cells, of the intersection of
/// every halfspace or its complement. This is the "if" half of the describability theorem, built directly.
ExprPtr canonical_form(const Complex& c, const std::vector<char>& solid) {
  std::set<std::vector<char>> inside;
  for (int k = 0; k < static_cast<int>(c.cells.size()); ++k)
    if (solid[k]) inside.insert(c.cells[k].inside);
  std::vector<ExprPtr> terms;
  for (const auto& signs : inside) {
    std::vector<ExprPtr> lits;
    for (int i = 0; i < c.halfspace_count(); ++i) lits.push_back(signs[i] ? leaf(i) : complement(leaf(i)));
    terms.push_back(intersect(lits));
  }
  return unite(terms);
}

/// Checks statement 1 on one solid (rapidcheck assertions); returns whether it is describable.
bool check_bhc_against_describability(const Complex& c, const std::vector<char>& solid, const BhcOptions& options) {
  const Describability d = describability(c, solid);
  const BhcResult r = bhc(c, solid, options);
  RC_ASSERT(r.describable == d.describable);

  // The definition, computed here: no sign vector holds both an inside and an outside cell.
  bool mixed = false;
  for (const auto& [signs, cells] : terms_of(c)) {
    bool in = false, out = false;
    for (int k : cells) (solid[k] ? in : out) = true;
    mixed = mixed || (in && out);
  }
  RC_ASSERT(d.describable == !mixed);
  RC_ASSERT(static_cast<std::size_t>(d.terms) == terms_of(c).size());

  if (r.describable) {
    RC_ASSERT(r.tree != nullptr);
    RC_ASSERT(r.verified);
    RC_ASSERT(evaluate(*r.tree, c) == solid);  // re-checked here
    RC_ASSERT(evaluate(*canonical_form(c, solid), c) == solid);
    const ExprStats s = stats(*r.tree);
    RC_ASSERT(s.depth == r.stats.depth);
    RC_ASSERT(s.leaves == r.stats.leaves);
    RC_ASSERT(s.duplicated_halfspaces == r.stats.duplicated_halfspaces);
    // Each factor adds one halfspace leaf, each partition at most two (a branch that is all out vanishes); the
    // constants survive only as the whole tree (stats counts them as a leaf).
    const bool constant = r.tree->op == Op::Empty || r.tree->op == Op::Full;
    RC_ASSERT(!constant || (r.factored == 0 && r.partitions == 0 && r.stats.leaves == 1));
    const int halfspace_leaves = constant ? 0 : r.stats.leaves;
    RC_ASSERT(halfspace_leaves <= r.factored + 2 * r.partitions);
    if (r.partitions == 0) {
      RC_ASSERT(r.stats.duplicated_halfspaces == 0);
      // Not equality: a factor applied after the region became all out in the same round (e.g. ~B after A when
      // B lies outside A and the solid is A) is counted and then simplified away (psi & empty = empty).
      RC_ASSERT(halfspace_leaves <= r.factored);
    }
    // Every support on the solid's boundary needs one of its halfspaces in the tree.
    std::set<int> used;
    std::vector<const Expr*> stack{r.tree.get()};
    while (!stack.empty()) {
      const Expr* e = stack.back();
      stack.pop_back();
      if (e->op == Op::Halfspace) used.insert(e->halfspace);
      for (const auto& ch : e->children) stack.push_back(ch.get());
    }
    for (const auto& group : c.supports) {
      const Patch& p = c.patches[group.front()];
      if (solid[p.inside_cell] == solid[p.outside_cell]) continue;
      RC_ASSERT(std::any_of(group.begin(), group.end(), [&](int q) { return used.count(c.patches[q].halfspace); }));
    }
  } else {
    RC_ASSERT(r.tree == nullptr);
    const MixedTerm& w = r.witness;
    RC_ASSERT(!w.inside_cells.empty());
    RC_ASSERT(!w.outside_cells.empty());
    for (int k : w.inside_cells) {
      RC_ASSERT(c.cells[k].inside == w.signs);
      RC_ASSERT(solid[k] != 0);
    }
    for (int k : w.outside_cells) {
      RC_ASSERT(c.cells[k].inside == w.signs);
      RC_ASSERT(solid[k] == 0);
    }
    // BHC's region is cut out by sides of halfspaces, so it holds the whole term: the witness is one of the
    // mixed terms that describability lists, cells and all.
    const bool listed = std::any_of(d.mixed.begin(), d.mixed.end(), [&](const MixedTerm& t) {
      return t.signs == w.signs && t.inside_cells == w.inside_cells && t.outside_cells == w.outside_cells;
    });
    RC_ASSERT(listed);
  }
  return r.describable;
}

// ---------------------------------------------------------------------------------------------------------------
// Hand-made scenes.

Complex complex_of(const Scene2& scene) { return arrange(scene).complex; }

std::string text(const BhcResult& r, const Complex& c) { return r.tree ? to_text(*r.tree, c.halfspace_names) : "-"; }

Scene2 fig02(int k) {
  return read_scene_file(std::string(HSX_SOURCE_DIR) + "/data/figures/fig02-" + std::to_string(k) + ".json");
}

}  // namespace

// =================================================================================================================
// 1. Describability and BHC.

TEST_CASE("csg theory 1: BHC succeeds exactly on describable solids; trees verified, witnesses are mixed terms",
          "[csg][theory][bhc][describability]") {
  rc::prop("bhc.describable == describability; verified tree or mixed witness", [] {
    const Scene2 scene = *gen_scene(csg_scenes());
    const Complex c = complex_of(scene);
    int not_describable = 0;
    for (int k = 0; k < 4; ++k) {  // several solids per arrangement (the arrangement is the costly part)
      const std::vector<char> solid = random_solid(c, k == 3);
      BhcOptions options;
      if (*rc::gen::arbitrary<bool>()) options.planar = planar_of(scene);
      not_describable += check_bhc_against_describability(c, solid, options) ? 0 : 1;
    }
    RC_TAG(std::to_string(not_describable) + " of 4 solids not describable");
  });
}

TEST_CASE("csg theory 1b: BHC on hand-written complexes with repeated sign vectors", "[csg][theory][bhc]") {
  // A complex written by hand (no geometry): the complex layer's conventions allow BHC to run on anything with
  // cells and sign vectors, so its correctness may not depend on the arrangement.
  rc::prop("random sign vectors over 1-4 halfspaces, 1-10 cells", [] {
    Complex c;
    const int h = *rc::gen::inRange(1, 5);
    for (int i = 0; i < h; ++i) c.halfspace_names.push_back("H" + std::to_string(i));
    const int n = *rc::gen::inRange(1, 11);
    for (int k = 0; k < n; ++k) {
      Cell cell;
      for (int i = 0; i < h; ++i) cell.inside.push_back(static_cast<char>(*rc::gen::inRange(0, 2)));
      c.cells.push_back(cell);
    }
    std::vector<char> solid(n);
    for (int k = 0; k < n; ++k) solid[k] = static_cast<char>(*rc::gen::inRange(0, 2));
    RC_TAG(check_bhc_against_describability(c, solid, {}) ? "describable" : "not describable");
  });
}

// =================================================================================================================
// 2. Every CSG expression is describable and BHC rebuilds it.

TEST_CASE("csg theory 2: a CSG expression's solid is describable and BHC's tree evaluates to it",
          "[csg][theory][bhc][describability]") {
  rc::prop("describable(evaluate(e)); evaluate(bhc(evaluate(e))) == evaluate(e)", [] {
    const Scene2 scene = *gen_scene(csg_scenes());
    const Complex c = complex_of(scene);
    const ExprPtr e = random_expr(c.halfspace_count(), *rc::gen::inRange(0, 5));
    const std::vector<char> solid = evaluate(*e, c);
    const Describability d = describability(c, solid);
    RC_ASSERT(d.describable);
    RC_ASSERT(d.mixed.empty());
    BhcOptions options;
    options.planar = planar_of(scene);
    const BhcResult r = bhc(c, solid, options);
    RC_ASSERT(r.describable);
    RC_ASSERT(r.verified);
    RC_ASSERT(evaluate(*r.tree, c) == solid);
    // Same value as e on every sign vector that the arrangement realises.
    for (const Cell& cell : c.cells) RC_ASSERT(evaluate(*r.tree, cell.inside) == evaluate(*e, cell.inside));
  });
}

// =================================================================================================================
// 3. Hand cases.

TEST_CASE("csg theory 3: a solid that is one halfspace gives a single leaf", "[csg][theory][bhc][hand]") {
  const Scene2 scene = make_scene(Box2{pt(-6, -6), pt(6, 6)},
                                  {disk("A", pt(0, 0), 2), disk("B", pt(1, 0), 2), halfplane("H", pt(0, 1), 1)});
  const Complex c = complex_of(scene);
  for (int i = 0; i < 2; ++i) {
    const std::vector<char> solid = evaluate(*leaf(i), c);
    const BhcResult r = bhc(c, solid, {planar_of(scene)});
    INFO(text(r, c));
    REQUIRE(r.describable);
    CHECK(r.verified);
    REQUIRE(r.tree->op == Op::Halfspace);
    CHECK(r.tree->halfspace == i);
    CHECK(r.stats.leaves == 1);
    CHECK(r.stats.depth == 0);
    CHECK(r.partitions == 0);
    CHECK(r.factored == 1);
  }
  // The complement of a disk (unbounded in the domain: it covers the outer cell) is a single complemented leaf.
  const BhcResult r = bhc(c, evaluate(*complement(leaf(0)), c), {planar_of(scene)});
  CHECK(text(r, c) == "~A");
  CHECK(r.verified);
}

TEST_CASE("csg theory 3: the union of two disjoint disks is A | B without a partition", "[csg][theory][bhc][hand]") {
  const Scene2 scene = make_scene(Box2{pt(-6, -6), pt(6, 6)}, {disk("A", pt(-2, 0), 1), disk("B", pt(2, 0), 1)});
  const Complex c = complex_of(scene);
  const std::vector<char> solid = evaluate(*unite({leaf(0), leaf(1)}), c);
  const BhcResult r = bhc(c, solid, {planar_of(scene)});
  CHECK(text(r, c) == "A | B");
  CHECK(r.verified);
  CHECK(r.partitions == 0);
  CHECK(r.factored == 2);
  CHECK(r.stats.depth == 1);
  CHECK(r.stats.leaves == 2);
  CHECK(r.stats.duplicated_halfspaces == 0);
}

TEST_CASE("csg theory 3: symmetric difference needs one partition; stats count it", "[csg][theory][bhc][hand]") {
  // A xor B for two overlapping disks: no halfspace dominates (inside A: A∩B out, A\B in; outside A: B\A in, the
  // rest out; the same for B), so BHC partitions on A (the lowest index: both split the boundary's two faces
  // equally, neither is planar), then factors ~B on A's side and B on the other.
  const Scene2 scene = make_scene(Box2{pt(-6, -6), pt(6, 6)}, {disk("A", pt(-1, 0), 2), disk("B", pt(1, 0), 2)});
  const Complex c = complex_of(scene);
  const ExprPtr xor_ab = unite({difference(leaf(0), leaf(1)), difference(leaf(1), leaf(0))});
  const std::vector<char> solid = evaluate(*xor_ab, c);
  const BhcResult r = bhc(c, solid, {planar_of(scene)});
  INFO(text(r, c));
  REQUIRE(r.describable);
  CHECK(r.verified);
  CHECK(text(r, c) == "A & ~B | ~A & B");
  CHECK(r.partitions == 1);
  CHECK(r.factored == 2);
  CHECK(r.stats.depth == 3);  // union, intersection, complement, leaf
  CHECK(r.stats.leaves == 4);
  CHECK(r.stats.internal_nodes == 5);  // complements are internal nodes
  CHECK(r.stats.distinct_halfspaces == 2);
  CHECK(r.stats.duplicated_halfspaces == 2);
}

TEST_CASE("csg theory 3: partition ties prefer a planar halfspace, then the lowest index", "[csg][theory][bhc][hand]") {
  // D xor H (a disk and a half-plane through it): each boundary is one face that the other splits once; with
  // planar flags BHC partitions on H (index 1), without them on D (index 0).
  const Scene2 scene = make_scene(Box2{pt(-6, -6), pt(6, 6)}, {disk("D", pt(0, 0), 2), halfplane("H", pt(0, 1), 0)});
  const Complex c = complex_of(scene);
  const std::vector<char> solid =
      evaluate(*unite({difference(leaf(0), leaf(1)), difference(leaf(1), leaf(0))}), c);
  auto first_partition = [&](const BhcResult& r) {
    // (psi & a) | (~psi & b): the first child of the root union is the intersection with psi.
    REQUIRE(r.tree->op == Op::Union);
    const Expr& left = *r.tree->children.front();
    REQUIRE(left.op == Op::Intersection);
    REQUIRE(left.children.front()->op == Op::Halfspace);
    return left.children.front()->halfspace;
  };
  const BhcResult with_planar = bhc(c, solid, {planar_of(scene)});
  const BhcResult without = bhc(c, solid, {});
  INFO(text(with_planar, c) << " / " << text(without, c));
  CHECK(with_planar.verified);
  CHECK(without.verified);
  CHECK(with_planar.partitions == 1);
  CHECK(first_partition(with_planar) == 1);
  CHECK(first_partition(without) == 0);
}

TEST_CASE("csg theory 3: cells decide the plane only when every arrangement vertex lies in the domain",
          "[csg][theory][describability][domain]") {
  // Two lines crossing at (20, 0): L1 & L2 is the wedge beyond the crossing. With a given domain [-3, 3]^2 (both
  // lines cross it, the crossing does not lie in it) that term has no cell: the expression is 0 on every cell,
  // and the complex cannot tell it from `empty`. With hsx's chosen domain (every line-line vertex inside), the
  // wedge meets the box in an outer cell: the solid is seen, and seen to be unbounded.
  const Halfspace2 l1 = halfplane("L1", pt(-1, 10), -20);   // 10y - x <= -20: below the line through (20, 0), slope 1/10
  const Halfspace2 l2 = halfplane("L2", pt(-1, -10), -20);  // -10y - x <= -20: above the line with slope -1/10
  const ExprPtr wedge = intersect({leaf(0), leaf(1)});
  const Complex small = complex_of(make_scene(Box2{pt(-3, -3), pt(3, 3)}, {l1, l2}));
  const std::vector<char> in_small = evaluate(*wedge, small);
  CHECK(std::none_of(in_small.begin(), in_small.end(), [](char x) { return x != 0; }));
  CHECK(in_small == evaluate(*empty(), small));
  CHECK(terms_of(small).size() == 3);  // three of the four sign vectors

  Scene2 chosen;
  chosen.halfspaces = {l1, l2};
  validate_and_resolve(chosen);  // domain_given = false: choose_domain
  REQUIRE(chosen.domain.contains(pt(20, 0)));
  const Complex big = complex_of(chosen);
  CHECK(terms_of(big).size() == 4);
  const std::vector<char> in_big = evaluate(*wedge, big);
  int inside = 0;
  for (int k = 0; k < static_cast<int>(big.cells.size()); ++k)
    if (in_big[k]) {
      ++inside;
      CHECK(big.cells[k].outer);  // unbounded: it meets the box's boundary
    }
  CHECK(inside == 1);
  const BhcResult r = bhc(big, in_big, {planar_of(chosen)});
  CHECK(text(r, big) == "L1 & L2");
}

TEST_CASE("csg theory 3: BSH Fig. 2 - shapes 1-4 describable by A and B, shapes 5 and 6 not (mixed witness)",
          "[csg][theory][bhc][fig2]") {
  // The six targets: four CSG expressions, and the best-first results of fig02-5 and fig02-6 (which have no
  // CSG expression over A and B). Cells: centre = A∩B, arms L (x < 0) and R of A\B, arms of B\A.
  const std::vector<std::string> expressions = {"A | B", "A & B", "A", "B", "", ""};
  for (int k = 1; k <= 6; ++k) {
    INFO("fig02-" << k);
    const Scene2 scene = fig02(k);
    const Arranged2 arranged = arrange(scene);
    const Complex& c = arranged.complex;
    REQUIRE(c.halfspace_names == std::vector<std::string>{"A", "B"});
    REQUIRE(c.cells.size() == 6);  // five cells and the outer one
    // The best-first result of the scene: the figure's shape.
    bsh::ExtractOptions eo;
    eo.method = bsh::Method::BestFirst;
    const bsh::Problem problem(c);
    const bsh::ExtractResult best = bsh::extract(problem, eo);
    CHECK(best.optimal);
    std::vector<char> solid = best.labelling;
    if (!expressions[k - 1].empty()) {
      const std::vector<char> from_csg = evaluate(*parse_csg_text(expressions[k - 1], c.halfspace_names), c);
      CHECK(from_csg == solid);
    } else {
      // Independently: centre + L (shape 5) or B + L (shape 6), L being the A\B cell with negative x.
      std::vector<char> expected(c.cells.size(), 0);
      for (int cell = 0; cell < static_cast<int>(c.cells.size()); ++cell) {
        const auto& s = c.cells[cell].inside;
        const bool left = c.cells[cell].witness.get()[0] < 0;
        const bool centre = s[0] && s[1], arm_l = s[0] && !s[1] && left, b = s[1];
        expected[cell] = (k == 5 ? centre || arm_l : b || arm_l) ? 1 : 0;
      }
      CHECK(expected == solid);
    }
    const Describability d = describability(c, solid);
    const BhcResult r = bhc(c, solid, {planar_of(scene)});
    if (k <= 4) {
      CHECK(d.describable);
      REQUIRE(r.describable);
      CHECK(r.verified);
      CHECK(r.partitions == 0);
      CHECK(to_text(*r.tree, c.halfspace_names) == expressions[k - 1]);
    } else {
      CHECK_FALSE(d.describable);
      REQUIRE(d.mixed.size() == 1);
      CHECK_FALSE(r.describable);
      // The witness: the term A ∩ ~B, holding L (inside) and R (outside).
      const MixedTerm& w = r.witness;
      CHECK(w.signs == std::vector<char>{1, 0});
      REQUIRE(w.inside_cells.size() == 1);
      REQUIRE(w.outside_cells.size() == 1);
      CHECK(c.cells[w.inside_cells[0]].witness.get()[0] < 0);
      CHECK(c.cells[w.outside_cells[0]].witness.get()[0] > 0);
      CHECK(w.inside_cells == d.mixed[0].inside_cells);
      CHECK(w.outside_cells == d.mixed[0].outside_cells);

      // With the separating half-plane C: x <= 0 (docs/figures.md), shape 5 = A & (B | C), shape 6 = B | (A & C).
      Scene2 separated = scene;
      separated.halfspaces.push_back(halfplane("C", pt(1, 0), 0));
      separated.samples.clear();
      validate_and_resolve(separated);
      const Complex cs = complex_of(separated);
      const std::string expected = k == 5 ? "A & (B | C)" : "B | A & C";
      const std::vector<char> target = evaluate(*parse_csg_text(expected, cs.halfspace_names), cs);
      CHECK(describability(cs, target).describable);
      const BhcResult rs = bhc(cs, target, {planar_of(separated)});
      REQUIRE(rs.describable);
      CHECK(rs.verified);
      CHECK(bsh::inside_measure(cs, target).exact_string() == bsh::inside_measure(c, solid).exact_string());
    }
  }
}

// =================================================================================================================
// 4. GENERATE-SAMPLES.

namespace {

/// A random orientation-preserving labelling (tests/support/random_labellings.hpp).
bsh::Labelling random_closure(const bsh::Problem& problem) { return test::random_closure(problem, 5); }

/// Patches on the boundary of `l` with their halfspace's orientation (inside cell 1, outside cell 0), counted here.
bool on_boundary(const Patch& p, const bsh::Labelling& l) { return l[p.inside_cell] && !l[p.outside_cell]; }
int boundary_patch_count(const Complex& c, const bsh::Labelling& l) {
  int n = 0;
  for (const Patch& p : c.patches) n += on_boundary(p, l) ? 1 : 0;
  return n;
}

/// Connected components of b ∩ b_i over all i, counted here: patches of halfspace i on b, joined when they share a
/// junction.
int component_count(const Complex& c, const bsh::Labelling& l) {
  const int np = static_cast<int>(c.patches.size());
  std::vector<int> parent(np);
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
  auto on_b = [&](int p) { return on_boundary(c.patches[p], l); };
  for (const Junction& j : c.junctions)
    for (int p : j.patches)
      for (int q : j.patches)
        if (on_b(p) && on_b(q) && c.patches[p].halfspace == c.patches[q].halfspace) parent[find(p)] = find(q);
  int n = 0;
  for (int p = 0; p < np; ++p) n += on_b(p) && find(p) == p ? 1 : 0;
  return n;
}

struct SkipCounts {
  long cases = 0;  // scenes
  long targets = 0;
  long non_empty = 0;        // targets checked with a non-empty boundary
  long minimum_checked = 0;  // targets whose true minimum was computed
  long non_generic = 0;
  long reversed_twin = 0;
  long too_large = 0;
};

/// True when b runs along a coincident patch against that patch's halfspace (a halfspace and its complement
/// given on one curve, the target using the complement's side): bsh::generate_samples may put a sample on such a
/// patch (see "GENERATE-SAMPLES samples a coincident patch against the target's orientation" below).
bool reversed_coincident_patch_on_b(const Complex& c, const bsh::Labelling& l) {
  return std::any_of(c.patches.begin(), c.patches.end(),
                     [&](const Patch& p) { return !l[p.inside_cell] && l[p.outside_cell]; });
}

/// A random target: the best-first result of a random scene with samples, or a random closure (orientation-
/// preserving without samples: generate_samples ignores the scene's own samples).
bool random_target(const Complex& c, const bsh::Problem& problem, bsh::Labelling& target) {
  if (!c.samples.empty() && *rc::gen::arbitrary<bool>()) {
    bsh::ExtractOptions eo;
    eo.method = bsh::Method::BestFirst;
    eo.max_states = 200;
    eo.enumerate_ties = false;
    eo.certify_limit = 0;  // any orientation-preserving, sample-connected boundary will do as a target
    const bsh::ExtractResult r = bsh::extract(problem, eo);
    if (!r.stopped_by.empty()) return false;
    target = r.labelling;
    if (std::any_of(target.begin(), target.end(), [](char x) { return x != 0; })) {
      return true;
    }
  }
  {
    const Complex bare = bsh::with_samples_on(c, {});
    target = random_closure(bsh::Problem(bare));
  }
  return true;
}

/// One target on one scene; false when the target is skipped (counted in `skipped`).
bool check_one_target(const Complex& c, const bsh::Problem& problem, bsh::Method method, SkipCounts& skipped) {
  ++skipped.targets;
  bsh::Labelling target;
  if (!random_target(c, problem, target)) {
    ++skipped.too_large;
    return false;
  }
  const Complex bare = bsh::with_samples_on(c, {});
  RC_ASSERT(bsh::is_orientation_preserving(bsh::Problem(bare), target));
  // Targets running along a coincident patch reversed were skipped while generate_samples could sample such a
  // patch (theory 4 [bug] below, fixed); they are now counted and checked like every other target.
  if (reversed_coincident_patch_on_b(c, target)) ++skipped.reversed_twin;
  const int patches = boundary_patch_count(c, target);
  if (patches > 16) {
    ++skipped.too_large;
    return false;
  }
  if (patches > 0) ++skipped.non_empty;

  bsh::SampleGenOptions options;
  options.search = method;
  options.beam_width = 1;
  options.fallback_states = 0;  // the paper's algorithm alone: no best-first rescue of a beam round
  const bsh::SampleGenResult r = bsh::generate_samples(c, target, options);
  RC_LOG() << "failure: " << r.failure << "\n";
  RC_ASSERT(r.reproduced);
  RC_ASSERT(r.failure.empty());
  // Fig. 12's greedy rounds did it: no fallback to Section 6.2's sufficient set (one sample per patch of b).
  RC_ASSERT(r.fallbacks == 0);
  RC_ASSERT(!r.used_sufficient_set);
  RC_ASSERT(r.upper_bound >= patches);  // all patches of b's supports; `patches` counts those with b's orientation
  RC_ASSERT(r.rounds >= 1);
  RC_ASSERT(r.rounds <= patches + 1);
  RC_ASSERT(r.initial == component_count(c, target));
  const int samples = static_cast<int>(r.sample_patches.size());
  RC_ASSERT(samples >= r.initial);
  RC_ASSERT(samples == r.initial + r.rounds - 1);  // one sample per round that did not reproduce the target
  RC_ASSERT(samples <= patches);  // distinct patches of b (below)
  // Every sample on a distinct patch of the target boundary.
  std::set<int> distinct(r.sample_patches.begin(), r.sample_patches.end());
  RC_ASSERT(distinct.size() == r.sample_patches.size());
  for (int p : r.sample_patches) RC_ASSERT(on_boundary(c.patches[p], target));
  // Re-checked here: extracting with exactly these samples gives the target back.
  const Complex sampled = bsh::with_samples_on(c, r.sample_patches);
  const bsh::Problem sampled_problem(sampled);
  bsh::ExtractOptions eo;
  eo.method = method;
  eo.beam_width = 1;
  eo.enumerate_ties = false;
  RC_ASSERT(bsh::extract(sampled_problem, eo).labelling == target);
  // The true minimum, when small enough to search: between the lower bound and the greedy count.
  if (method == bsh::Method::BestFirst) {
    const int minimum = bsh::minimum_samples(c, target, 8, 300);
    if (minimum >= 0) {
      ++skipped.minimum_checked;
      RC_ASSERT(minimum >= r.initial);
      RC_ASSERT(minimum <= samples);
    }
  }
  return true;
}

/// Statement 4 for one search method on generic inputs (Prop. 6.1 for best-first, Prop. B.1 for beam K = 1): three
/// targets per scene.
void check_generate_samples(bsh::Method method, SkipCounts& skipped) {
  SceneGenOptions o;
  o.max_halfspaces = 5;
  o.max_degeneracies = 1;
  o.samples = true;
  o.max_samples = 6;
  const Scene2 scene = *gen_scene(o);
  const Complex c = complex_of(scene);
  const bsh::Problem problem(c);
  ++skipped.cases;
  if (!problem.non_generic_junctions().empty()) {
    // Prop. 6.1 and B.1 rest on Prop. 5.1/5.2, proven for generic junctions only (proofs/csg.md, Section 5).
    ++skipped.non_generic;
    RC_DISCARD("non-generic junctions");
  }
  int checked = 0;
  for (int t = 0; t < 3; ++t) checked += check_one_target(c, problem, method, skipped) ? 1 : 0;
  if (checked == 0) RC_DISCARD("every target skipped");
}

}  // namespace

TEST_CASE("csg theory 4: GENERATE-SAMPLES with best-first reproduces the target (Prop. 6.1); counts bounded",
          "[csg][theory][samples][prop61]") {
  SkipCounts skipped;
  // rc::check rather than rc::prop: the counts are printed after the run, also when it fails.
  const bool ok = rc::check("generic inputs: reproduced, rounds <= patches + 1, initial = components, minimum in range", [&skipped] { check_generate_samples(bsh::Method::BestFirst, skipped); });
  std::cout << "csg theory 4 (Prop. 6.1, best-first): minimum_samples computed on " << skipped.minimum_checked
            << " targets; " << skipped.cases << " scenes drawn, " << skipped.non_generic
            << " skipped for non-generic junctions; " << skipped.targets << " targets on the others, "
            << skipped.reversed_twin << " with b along a coincident patch reversed (checked), "
            << skipped.too_large << " skipped as too large; " << skipped.non_empty
            << " non-empty targets checked\n";
  CHECK(ok);
}

TEST_CASE("csg theory 4: GENERATE-SAMPLES with beam K=1 reproduces the target (Prop. B.1); counts bounded",
          "[csg][theory][samples][propB1]") {
  SkipCounts skipped;
  // rc::check rather than rc::prop: the counts are printed after the run, also when it fails.
  const bool ok = rc::check("generic inputs: reproduced, rounds <= patches + 1, initial = components", [&skipped] { check_generate_samples(bsh::Method::Beam, skipped); });
  std::cout << "csg theory 4 (Prop. B.1, beam K=1): " << skipped.cases << " scenes drawn, " << skipped.non_generic
            << " skipped for non-generic junctions; " << skipped.targets << " targets on the others, "
            << skipped.reversed_twin << " with b along a coincident patch reversed (checked), "
            << skipped.too_large << " skipped as too large; " << skipped.non_empty
            << " non-empty targets checked\n";
  CHECK(ok);
}

TEST_CASE("csg theory 4: GENERATE-SAMPLES samples a coincident patch against the target's orientation",
          "[csg][theory][samples][propB1][bug]") {
  // Generic input (no non-generic junction), found by "[.explore-twins]" and shrunk: D4 is D1's complement twin,
  // so each arc of D1's circle is a support with one patch of D1 and one of D4. Target: D1 (one component of
  // b ∩ b_D1, one initial sample, on D1's patch 11).
  // Round 1 (beam K = 1) returns the empty boundary (allowed: beam is incomplete; Prop. B.1 only promises a
  // sample-free patch of b \ b'). Fig. 12 then samples the largest sample-free patch of b \ b', but
  // bsh::generate_samples (samples.cpp, the `pick` loop) takes it among ALL patches of b's supports, including
  // D4's patch 12, which b runs along against D4's orientation. A sample there says "this arc with D4's inside"
  // (problem.hpp), which forbids the target's orientation on that arc: the target is no longer admissible and no
  // later round can return it. After 8 rounds every patch of b \ b' has a sample and the loop gives up (then
  // falls back to one sample per patch: 4 samples where 2 suffice, 1 with best-first).
  // Picking only patches that b runs along with their own orientation (inside cell 1, outside cell 0) fixes it
  // here, on 3000 random generic inputs with coincident boundaries ("[.explore-twins]", oriented picks), and on
  // the 8 CSGNet programs whose conversion ends with the sufficient set (proofs/csg.md, Section 5).
  // Failed until generate_samples picked only such oriented patches (commit c9bf8e8).
  const Scene2 scene = make_scene(Box2{pt(-3, -6), pt(6, 4)},
                                  {disk("D1", pt(3, q("-1/2")), q("3/2")), disk("D2", pt(q("3/2"), q("-3/2")), 3),
                                   disk("D3", pt(1, q("1/2")), 2, true), disk("D4", pt(3, q("-1/2")), q("3/2"), true)});
  const Complex c = complex_of(scene);
  REQUIRE(bsh::Problem(c).non_generic_junctions().empty());
  const bsh::Labelling target = evaluate(*leaf(0), c);
  REQUIRE(bsh::is_orientation_preserving(bsh::Problem(c), target));
  bsh::SampleGenOptions options;
  options.search = bsh::Method::Beam;
  options.fallback_states = 0;
  const bsh::SampleGenResult r = bsh::generate_samples(c, target, options);
  INFO("rounds " << r.rounds << ", samples " << r.sample_patches.size() << ", failure '" << r.failure << "'");
  CHECK(r.reproduced);
  CHECK_FALSE(r.used_sufficient_set);
  for (int p : r.sample_patches) {
    INFO("sample on patch " << p << " of " << c.halfspace_names[c.patches[p].halfspace]);
    CHECK(on_boundary(c.patches[p], target));
  }
  // With the default options (best-first fallback) too.
  const bsh::SampleGenResult d = bsh::generate_samples(c, target, bsh::SampleGenOptions{});
  CHECK(d.reproduced);
  CHECK_FALSE(d.used_sufficient_set);
}

// Not run by default: a search for GENERATE-SAMPLES failures on non-generic inputs (concurrent lines, tangencies),
// where Props. 6.1/B.1 are not proven. Run with: test_csg_theory "[.explore]". Every failure it found so far was
// the coincident-patch pick bug (theory 4 [bug]), not a failure of the propositions: see "[.explore-oriented]".
TEST_CASE("csg theory explore: GENERATE-SAMPLES on non-generic junctions", "[.explore]") {
  rc::prop("non-generic inputs: reproduced (beam and best-first)", [] {
    SceneGenOptions o;
    o.max_halfspaces = std::getenv("HSX_EXPLORE_MAX") ? std::atoi(std::getenv("HSX_EXPLORE_MAX")) : 5;
    o.min_degeneracies = 1;
    o.max_degeneracies = 2;
    o.allowed_degeneracies = {Degeneracy::ConcurrentLines, Degeneracy::LineTangentToDisk,
                              Degeneracy::DisksTangentOutside, Degeneracy::DisksTangentInside,
                              Degeneracy::PolygonVertexOnLine, Degeneracy::PolygonVertexOnCircle};
    o.samples = true;
    o.max_samples = 6;
    const Scene2 scene = *gen_scene(o);
    const Complex c = complex_of(scene);
    const bsh::Problem problem(c);
    RC_PRE(!problem.non_generic_junctions().empty());
    bsh::Labelling target;
    RC_PRE(random_target(c, problem, target));
    RC_PRE(boundary_patch_count(c, target) <= 16);
    std::vector<bsh::Method> methods{bsh::Method::Beam};
    if (!std::getenv("HSX_EXPLORE_BEAM_ONLY")) methods.push_back(bsh::Method::BestFirst);
    for (bsh::Method m : methods) {
      bsh::SampleGenOptions so;
      so.search = m;
      so.fallback_states = 0;
      const bsh::SampleGenResult r = bsh::generate_samples(c, target, so);
      std::string cells;
      for (int k = 0; k < problem.cell_count(); ++k)
        if (target[k]) cells += " " + std::to_string(k);
      RC_LOG() << bsh::to_string(m) << ": " << r.failure << "; target cells" << cells << "\n";
      RC_ASSERT(r.reproduced);
      RC_ASSERT(!r.used_sufficient_set);
    }
  });
}

TEST_CASE("csg theory explore: GENERATE-SAMPLES on the Prop. 5.1 counterexample scene", "[.explore]") {
  const Scene2 scene =
      read_scene_file(std::string(HSX_SOURCE_DIR) + "/data/counterexamples/prop51-concurrent-lines.json");
  const Complex c = complex_of(scene);
  const Complex bare = bsh::with_samples_on(c, {});
  rc::prop("every closure target reproduced", [&] {
    const bsh::Labelling target = random_closure(bsh::Problem(bare));
    for (bsh::Method m : {bsh::Method::Beam, bsh::Method::BestFirst}) {
      bsh::SampleGenOptions so;
      so.search = m;
      so.fallback_states = 0;
      const bsh::SampleGenResult r = bsh::generate_samples(c, target, so);
      std::string cells;
      for (int k = 0; k < static_cast<int>(target.size()); ++k)
        if (target[k]) cells += " " + std::to_string(k);
      RC_LOG() << bsh::to_string(m) << ": " << r.failure << "; target cells" << cells << "\n";
      RC_ASSERT(r.reproduced);
      RC_ASSERT(!r.used_sufficient_set);
    }
  });
}

// Not run by default: GENERATE-SAMPLES on one input, for studying a counterexample. Environment: HSX_CX_SCENE (a
// scene file), HSX_CX_TARGET (the target as a CSG expression over its halfspaces), HSX_CX_METHOD (beam or
// best-first). Prints the rounds and whether the greedy rounds reproduced the target without fallbacks.
TEST_CASE("csg theory explore: GENERATE-SAMPLES on one input", "[.explore-one]") {
  const char* path = std::getenv("HSX_CX_SCENE");
  const char* expr = std::getenv("HSX_CX_TARGET");
  const char* method = std::getenv("HSX_CX_METHOD");
  if (!path || !expr) return;
  const Scene2 scene = read_scene_file(path);
  const Complex c = complex_of(scene);
  const bsh::Labelling target = evaluate(*parse_csg_text(expr, c.halfspace_names), c);
  const bsh::Problem problem(c);
  bsh::SampleGenOptions so;
  so.search = method && std::string(method) == "best-first" ? bsh::Method::BestFirst : bsh::Method::Beam;
  so.fallback_states = 0;
  const bsh::SampleGenResult r = bsh::generate_samples(c, target, so);
  std::cout << "non-generic junctions " << problem.non_generic_junctions().size() << ", orientation-preserving "
            << bsh::is_orientation_preserving(bsh::Problem(bsh::with_samples_on(c, {})), target) << ", initial "
            << r.initial << ", rounds " << r.rounds << ", reproduced " << r.reproduced << ", sufficient set "
            << r.used_sufficient_set << ", boundary patches " << boundary_patch_count(c, target) << "\n";
  CHECK(r.reproduced);
  CHECK_FALSE(r.used_sufficient_set);
}

// Not run by default: GENERATE-SAMPLES on generic scenes with coincident boundaries (a halfspace given twice, a
// halfspace and its complement). Run with: test_csg_theory "[.explore-twins]".
TEST_CASE("csg theory explore: GENERATE-SAMPLES with coincident boundaries", "[.explore-twins]") {
  rc::prop("generic inputs with twins: the greedy rounds reproduce the target", [] {
    SceneGenOptions o;
    o.max_halfspaces = 6;
    o.min_degeneracies = 1;
    o.max_degeneracies = 2;
    o.allowed_degeneracies = {Degeneracy::ComplementTwin, Degeneracy::RepeatedHalfspace,
                              Degeneracy::HalfplaneOnPolygonEdge, Degeneracy::PolygonsSharingEdge};
    const Scene2 scene = *gen_scene(o);
    const Complex c = complex_of(scene);
    const bsh::Problem problem(c);
    RC_PRE(problem.non_generic_junctions().empty());
    const Complex bare = bsh::with_samples_on(c, {});
    const ExprPtr e = random_expr(c.halfspace_count(), 3);
    const bsh::Labelling target = evaluate(*e, c);
    RC_PRE(bsh::is_orientation_preserving(bsh::Problem(bare), target));
    RC_PRE(boundary_patch_count(c, target) <= 16);
    RC_LOG() << "target " << to_text(*e, c.halfspace_names) << "\n";
    for (bsh::Method m : {bsh::Method::Beam, bsh::Method::BestFirst}) {
      bsh::SampleGenOptions so;
      so.search = m;
      so.fallback_states = 0;
      const bsh::SampleGenResult r = bsh::generate_samples(c, target, so);
      std::string cells;
      for (int k = 0; k < static_cast<int>(target.size()); ++k)
        if (target[k]) cells += " " + std::to_string(k);
      RC_LOG() << bsh::to_string(m) << ": " << r.failure << "; target cells" << cells << "\n";
      RC_ASSERT(r.reproduced);
      RC_ASSERT(!r.used_sufficient_set);
    }
  });
}

namespace {
/// Fig. 12's greedy loop written here from the public API, for diagnosis: initial samples on the first patch of
/// each component of b ∩ b_i (hsx uses a central patch), then the largest sample-free patch of b \ b', taken
/// among all patches of b's supports (as bsh::generate_samples does) or only among those with b's orientation.
/// Prints every round; returns true when the target is reproduced.
bool greedy_diagnosis(const Complex& c, const bsh::Labelling& target, bsh::Method method, bool oriented_only,
                      bool quiet = false) {
  std::ostringstream sink;
  std::ostream& out = quiet ? sink : std::cout;
  const bsh::Problem problem(c);
  std::vector<int> samples;
  for (const bsh::Component& comp : bsh::sample_connectivity(problem, target).components) {
    int pick = comp.patches.front();
    if (std::getenv("HSX_CX_CENTRAL")) {
      // samples.hpp's central patch, in doubles: least eccentricity, distances between patch midpoints along the
      // component (edge a-b costs (|a| + |b|) / 2), ties to the first.
      const auto& ps = comp.patches;
      const int n = static_cast<int>(ps.size());
      double best = 1e300;
      for (int src = 0; src < n; ++src) {
        std::vector<double> dist(n, 1e300);
        std::vector<char> done(n, 0);
        dist[src] = 0;
        for (int round = 0; round < n; ++round) {
          int u = -1;
          for (int v = 0; v < n; ++v)
            if (!done[v] && dist[v] < 1e300 && (u < 0 || dist[v] < dist[u])) u = v;
          if (u < 0) break;
          done[u] = 1;
          for (int v = 0; v < n; ++v) {
            if (v == u) continue;
            const auto& ju = c.patches[ps[u]].junctions;
            const auto& jv = c.patches[ps[v]].junctions;
            const bool adjacent = std::any_of(ju.begin(), ju.end(), [&](int j) {
              return std::find(jv.begin(), jv.end(), j) != jv.end();
            });
            if (!adjacent) continue;
            const double d = dist[u] + (c.patches[ps[u]].measure.get().to_double() +
                                        c.patches[ps[v]].measure.get().to_double()) / 2;
            if (d < dist[v]) dist[v] = d;
          }
        }
        double radius = 0;
        for (int v = 0; v < n; ++v)
          if (dist[v] < 1e300) radius = std::max(radius, dist[v]);
        if (radius < best - 1e-12) {
          best = radius;
          pick = ps[src];
        }
      }
    }
    samples.push_back(pick);
  }
  if (const char* initial = std::getenv("HSX_CX_INITIAL")) {  // comma-separated patch ids
    samples.clear();
    std::string text = initial;
    for (std::size_t at = 0; at < text.size();) {
      const std::size_t end = std::min(text.find(',', at), text.size());
      samples.push_back(std::stoi(text.substr(at, end - at)));
      at = end + 1;
    }
  }
  for (int round = 1; round <= 64; ++round) {
    const Complex sampled = bsh::with_samples_on(c, samples);
    const bsh::Problem sp(sampled);
    bsh::ExtractOptions eo;
    eo.method = method;
    eo.enumerate_ties = false;
    eo.certify_limit = 0;  // the paper's search alone (no oracle replacing best-first at non-generic junctions)
    eo.max_states = 5000;
    const bsh::ExtractResult found = bsh::extract(sp, eo);
    if (!found.stopped_by.empty()) {
      out << "  round " << round << ": search stopped by " << found.stopped_by << "\n";
      return true;  // inconclusive
    }
    out << "  round " << round << ": samples on patches";
    for (int p : samples) out << " " << p << "(" << c.halfspace_names[c.patches[p].halfspace] << ")";
    out << "; target admissible " << bsh::is_orientation_preserving(sp, target) << ", target energy "
              << bsh::energy(sp, target).missing_samples << " missing / "
              << bsh::energy(sp, target).measure().decimal_string(6) << "; found " << found.energy.missing_samples
              << " missing / " << found.energy.measure().decimal_string(6) << "\n";
    if (found.labelling == target) return true;
    std::vector<char> on_found(problem.support_count(), 0);
    for (int g : bsh::boundary_supports(problem, found.labelling)) on_found[g] = 1;
    int pick = -1;
    for (int g : bsh::boundary_supports(problem, target)) {
      if (on_found[g]) continue;
      for (int p : problem.supports()[g].patches) {
        if (std::find(samples.begin(), samples.end(), p) != samples.end()) continue;
        if (oriented_only && !on_boundary(c.patches[p], target)) continue;
        if (pick < 0 || compare(c.patches[p].measure, c.patches[pick].measure) == Order::Greater) pick = p;
      }
    }
    if (pick < 0) {
      out << "  stuck: every patch of b \\ b' has a sample\n";
      return false;
    }
    samples.push_back(pick);
  }
  return false;
}
}  // namespace

TEST_CASE("csg theory explore: the greedy loop round by round", "[.explore-greedy]") {
  const char* path = std::getenv("HSX_CX_SCENE");
  const char* expr = std::getenv("HSX_CX_TARGET");
  if (!path || !expr) return;
  const Scene2 scene = read_scene_file(path);
  const Complex c = complex_of(scene);
  bsh::Labelling target;
  if (std::string(expr) == "@samples") {  // the target: best-first's shape for the scene's own samples
    bsh::ExtractOptions eo;
    eo.method = bsh::Method::BestFirst;
    eo.enumerate_ties = false;
    target = bsh::extract(bsh::Problem(c), eo).labelling;
  } else {
    target = evaluate(*parse_csg_text(expr, c.halfspace_names), c);
  }
  for (bool oriented : {false, true})
    for (bsh::Method m : {bsh::Method::Beam, bsh::Method::BestFirst}) {
      if (std::getenv("HSX_EXPLORE_BEAM_ONLY") && m != bsh::Method::Beam) continue;
      std::cout << bsh::to_string(m) << (oriented ? ", picks with b's orientation only" : ", picks as hsx") << "\n";
      const bool ok = greedy_diagnosis(c, target, m, oriented);
      std::cout << "  reproduced " << ok << "\n";
    }
}

TEST_CASE("csg theory explore: the greedy loop with oriented picks on coincident boundaries", "[.explore-twins]") {
  rc::prop("generic inputs with twins: oriented picks reproduce the target", [] {
    SceneGenOptions o;
    o.max_halfspaces = 6;
    o.min_degeneracies = 1;
    o.max_degeneracies = 2;
    o.allowed_degeneracies = {Degeneracy::ComplementTwin, Degeneracy::RepeatedHalfspace,
                              Degeneracy::HalfplaneOnPolygonEdge, Degeneracy::PolygonsSharingEdge};
    const Scene2 scene = *gen_scene(o);
    const Complex c = complex_of(scene);
    RC_PRE(bsh::Problem(c).non_generic_junctions().empty());
    const bsh::Labelling target = random_closure(bsh::Problem(bsh::with_samples_on(c, {})));
    RC_PRE(boundary_patch_count(c, target) <= 16);
    for (bsh::Method m : {bsh::Method::Beam, bsh::Method::BestFirst}) RC_ASSERT(greedy_diagnosis(c, target, m, true, true));
  });
}

TEST_CASE("csg theory explore: the greedy loop with oriented picks at non-generic junctions", "[.explore-oriented]") {
  rc::prop("non-generic inputs: oriented picks reproduce the target", [] {
    SceneGenOptions o;
    o.max_halfspaces = std::getenv("HSX_EXPLORE_MAX") ? std::atoi(std::getenv("HSX_EXPLORE_MAX")) : 6;
    o.min_degeneracies = 1;
    o.max_degeneracies = 2;
    o.allowed_degeneracies = {Degeneracy::ConcurrentLines, Degeneracy::LineTangentToDisk,
                              Degeneracy::DisksTangentOutside, Degeneracy::DisksTangentInside,
                              Degeneracy::PolygonVertexOnLine, Degeneracy::PolygonVertexOnCircle};
    o.samples = true;
    const Scene2 scene = *gen_scene(o);
    const Complex c = complex_of(scene);
    const bsh::Problem problem(c);
    RC_PRE(!problem.non_generic_junctions().empty());
    bsh::Labelling target;
    RC_PRE(random_target(c, problem, target));
    RC_PRE(boundary_patch_count(c, target) <= 16);
    std::string cells;
    for (int k = 0; k < static_cast<int>(target.size()); ++k)
      if (target[k]) cells += " " + std::to_string(k);
    RC_LOG() << "target cells" << cells << "\n";
    const bool beam_only = std::getenv("HSX_EXPLORE_BEAM_ONLY") != nullptr;
    RC_ASSERT(greedy_diagnosis(c, target, bsh::Method::Beam, true, true));
    if (!beam_only) RC_ASSERT(greedy_diagnosis(c, target, bsh::Method::BestFirst, true, true));
  });
}
