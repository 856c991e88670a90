// CSG expressions (algorithms/csg/expression.hpp): constructors and their simplifications, evaluation on sign
// vectors and on complexes (against an independent per-cell oracle: exact side tests of each cell's witness
// point), statistics, and the text form's minimal parentheses.
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include "support/random_scenes.hpp"

#include "support/random_expressions.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <functional>
#include <string>
#include <vector>

using namespace hsx;
using namespace hsx::csg;

namespace {

using hsx::test::random_expr;
using hsx::test::raw;

const std::vector<std::string> kNames = {"A", "B", "C", "D", "E"};

ExprPtr A() { return leaf(0); }
ExprPtr B() { return leaf(1); }
ExprPtr C() { return leaf(2); }
ExprPtr D() { return leaf(3); }

/// Independent oracle: the set semantics, written directly on a membership function.
bool oracle(const Expr& e, const std::function<bool(int)>& in) {
  switch (e.op) {
    case Op::Halfspace: return in(e.halfspace);
    case Op::Empty: return false;
    case Op::Full: return true;
    case Op::Complement: return !oracle(*e.children[0], in);
    case Op::Difference: return oracle(*e.children[0], in) && !oracle(*e.children[1], in);
    case Op::Union:
      for (const auto& c : e.children)
        if (oracle(*c, in)) return true;
      return false;
    case Op::Intersection:
      for (const auto& c : e.children)
        if (!oracle(*c, in)) return false;
      return true;
  }
  return false;
}

std::vector<char> sign_vector(unsigned mask, int n) {
  std::vector<char> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = (mask >> i) & 1u ? 1 : 0;
  return v;
}

/// No Empty/Full below the root, unions and intersections flat with >= 2 children, no double complement.
bool simplified(const Expr& e, bool root = true) {
  if (!root && (e.op == Op::Empty || e.op == Op::Full)) return false;
  if ((e.op == Op::Union || e.op == Op::Intersection) && e.children.size() < 2) return false;
  for (const auto& c : e.children) {
    if ((e.op == Op::Union || e.op == Op::Intersection) && c->op == e.op) return false;
    if (e.op == Op::Complement && c->op == Op::Complement) return false;
    if (!simplified(*c, false)) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("csg constructors simplify as documented", "[csg]") {
  CHECK(complement(empty())->op == Op::Full);
  CHECK(complement(full())->op == Op::Empty);
  CHECK(complement(complement(A()))->op == Op::Halfspace);

  ExprPtr u = unite({A(), unite({B(), C()}), empty()});
  REQUIRE(u->op == Op::Union);
  REQUIRE(u->children.size() == 3);
  CHECK(u->children[2]->halfspace == 2);
  CHECK(unite({A(), full(), B()})->op == Op::Full);
  CHECK(unite({})->op == Op::Empty);
  CHECK(unite({empty(), B()})->halfspace == 1);

  ExprPtr i = intersect({intersect({A(), B()}), C(), full()});
  REQUIRE(i->op == Op::Intersection);
  CHECK(i->children.size() == 3);
  CHECK(intersect({A(), empty()})->op == Op::Empty);
  CHECK(intersect({})->op == Op::Full);
  CHECK(intersect({full(), full()})->op == Op::Full);

  CHECK(difference(A(), empty())->halfspace == 0);
  CHECK(difference(A(), full())->op == Op::Empty);
  CHECK(difference(empty(), A())->op == Op::Empty);
  ExprPtr fb = difference(full(), B());
  REQUIRE(fb->op == Op::Complement);
  CHECK(fb->children[0]->halfspace == 1);
  ExprPtr d = difference(A(), B());
  REQUIRE(d->op == Op::Difference);
  CHECK(d->children[0]->halfspace == 0);
  CHECK(d->children[1]->halfspace == 1);

  // Repeated children are kept (no deduplication).
  CHECK(unite({A(), A()})->children.size() == 2);

  CHECK_THROWS_AS(leaf(-1), std::invalid_argument);
  CHECK_THROWS_AS(unite({A(), nullptr}), std::invalid_argument);
}

TEST_CASE("csg evaluation on sign vectors", "[csg]") {
  ExprPtr e = unite({intersect({A(), B()}), complement(C())});  // (A & B) | ~C
  CHECK(evaluate(*e, std::vector<char>{1, 1, 1}));
  CHECK_FALSE(evaluate(*e, std::vector<char>{1, 0, 1}));
  CHECK(evaluate(*e, std::vector<char>{0, 0, 0}));
  ExprPtr d = difference(difference(A(), B()), C());
  CHECK(evaluate(*d, std::vector<char>{1, 0, 0}));
  CHECK_FALSE(evaluate(*d, std::vector<char>{1, 0, 1}));
  CHECK_FALSE(evaluate(*d, std::vector<char>{1, 1, 0}));
  CHECK_FALSE(evaluate(*empty(), std::vector<char>{}));
  CHECK(evaluate(*full(), std::vector<char>{}));
  CHECK_THROWS_AS(evaluate(*C(), std::vector<char>{1, 1}), std::invalid_argument);
}

TEST_CASE("csg evaluation on a hand complex, outer cells included", "[csg]") {
  Complex c;
  c.halfspace_names = {"A", "B"};
  for (int mask = 0; mask < 4; ++mask) {
    Cell cell;
    cell.inside = sign_vector(static_cast<unsigned>(mask), 2);
    cell.outer = mask == 0;
    c.cells.push_back(cell);
  }
  CHECK(evaluate(*difference(A(), B()), c) == std::vector<char>{0, 1, 0, 0});
  CHECK(evaluate(*unite({A(), B()}), c) == std::vector<char>{0, 1, 1, 1});
  CHECK(evaluate(*complement(unite({A(), B()})), c) == std::vector<char>{1, 0, 0, 0});  // the outer cell too
  CHECK(evaluate(*full(), c) == std::vector<char>{1, 1, 1, 1});
  CHECK(evaluate(*empty(), c) == std::vector<char>{0, 0, 0, 0});
  CHECK_THROWS_AS(evaluate(*C(), c), std::invalid_argument);
}

TEST_CASE("csg evaluation on arranged scenes equals the per-cell witness oracle", "[csg][property]") {
  test::SceneGenOptions options;
  options.max_halfspaces = 5;
  rc::prop("evaluate(e, complex)[k] == e on the exact sides of cell k's witness", [&] {
    const Scene2 scene = *test::gen_scene(options);
    const Arranged2 arranged = arrange(scene);
    const Complex& complex = arranged.complex;
    const int n = complex.halfspace_count();
    const bool raw_nodes = *rc::gen::arbitrary<bool>();
    const ExprPtr e = random_expr(n, 4, raw_nodes);
    const std::vector<char> labels = evaluate(*e, complex);
    RC_ASSERT(labels.size() == complex.cells.size());
    for (std::size_t k = 0; k < complex.cells.size(); ++k) {
      const Cell& cell = complex.cells[k];
      const PointQ2 w{cell.witness.get().at(0), cell.witness.get().at(1)};
      const bool expected = oracle(*e, [&](int h) {
        const int side = scene.halfspaces[static_cast<std::size_t>(h)].side(w);
        RC_ASSERT(side != 0);  // a witness is interior to its cell
        return side > 0;
      });
      RC_ASSERT((labels[k] != 0) == expected);
    }
  });
}

TEST_CASE("csg constructors keep the value and give simplified trees", "[csg][property]") {
  rc::prop("constructors == raw nodes on every sign vector", [] {
    const int n = *rc::gen::inRange(1, 6);
    // The same random choices, once raw and once simplified: draw a seed tree raw, then rebuild it.
    const ExprPtr r = random_expr(n, 4, true);
    std::function<ExprPtr(const Expr&)> rebuild = [&](const Expr& e) -> ExprPtr {
      std::vector<ExprPtr> c;
      for (const auto& x : e.children) c.push_back(rebuild(*x));
      switch (e.op) {
        case Op::Halfspace: return leaf(e.halfspace);
        case Op::Empty: return empty();
        case Op::Full: return full();
        case Op::Complement: return complement(c[0]);
        case Op::Union: return unite(c);
        case Op::Intersection: return intersect(c);
        case Op::Difference: return difference(c[0], c[1]);
      }
      return nullptr;
    };
    const ExprPtr s = rebuild(*r);
    RC_ASSERT(simplified(*s));
    for (unsigned mask = 0; mask < (1u << n); ++mask) {
      const auto v = sign_vector(mask, n);
      RC_ASSERT(evaluate(*s, v) == evaluate(*r, v));
      RC_ASSERT(evaluate(*r, v) == oracle(*r, [&](int h) { return v[static_cast<std::size_t>(h)] != 0; }));
    }
  });
}

TEST_CASE("csg stats on hand cases", "[csg]") {
  ExprStats s = stats(*A());
  CHECK(s.depth == 0);
  CHECK(s.internal_nodes == 0);
  CHECK(s.leaves == 1);
  CHECK(s.distinct_halfspaces == 1);
  CHECK(s.duplicated_halfspaces == 0);

  // (A & B) | ~(A - C) | A: depth 3 (| -> ~ -> - -> A), internal: |, &, ~, - = 4; leaves A B A C A = 5.
  ExprPtr e = unite({intersect({A(), B()}), complement(difference(A(), C())), A()});
  s = stats(*e);
  CHECK(s.depth == 3);
  CHECK(s.internal_nodes == 4);
  CHECK(s.leaves == 5);
  CHECK(s.distinct_halfspaces == 3);
  CHECK(s.duplicated_halfspaces == 1);  // A

  ExprPtr f = intersect({unite({B(), C()}), unite({B(), C()}), D()});
  s = stats(*f);
  CHECK(s.depth == 2);
  CHECK(s.internal_nodes == 3);
  CHECK(s.leaves == 5);
  CHECK(s.distinct_halfspaces == 3);
  CHECK(s.duplicated_halfspaces == 2);  // B and C

  s = stats(*empty());
  CHECK(s.leaves == 1);
  CHECK(s.distinct_halfspaces == 0);
}

TEST_CASE("csg to_text uses minimal parentheses", "[csg]") {
  auto t = [](const ExprPtr& e) { return to_text(*e, kNames); };
  CHECK(t(unite({intersect({A(), B()}), complement(C())})) == "A & B | ~C");
  CHECK(t(intersect({unite({A(), B()}), C()})) == "(A | B) & C");
  CHECK(t(difference(difference(A(), B()), C())) == "A - B - C");
  CHECK(t(difference(A(), difference(B(), C()))) == "A - (B - C)");
  CHECK(t(difference(unite({A(), B()}), C())) == "(A | B) - C");
  CHECK(t(difference(A(), unite({B(), C()}))) == "A - (B | C)");
  CHECK(t(difference(A(), intersect({B(), C()}))) == "A - B & C");
  CHECK(t(intersect({difference(A(), B()), C()})) == "(A - B) & C");
  CHECK(t(unite({difference(A(), B()), C()})) == "A - B | C");
  CHECK(t(complement(intersect({A(), B()}))) == "~(A & B)");
  CHECK(t(complement(difference(A(), B()))) == "~(A - B)");
  CHECK(t(intersect({complement(A()), complement(B())})) == "~A & ~B");
  CHECK(t(raw(Op::Complement, {complement(A())})) == "~~A");
  CHECK(t(empty()) == "empty");
  CHECK(t(full()) == "full");
  // Raw nested operations print without superfluous parentheses: the text still means the same set.
  CHECK(t(raw(Op::Union, {A(), raw(Op::Union, {B(), C()})})) == "A | B | C");
  CHECK(t(raw(Op::Intersection, {A(), raw(Op::Intersection, {B(), C()})})) == "A & B & C");

  // Names that are not identifiers, and the reserved words, are quoted.
  const std::vector<std::string> odd = {"s1.x+", "empty", "a\"b\\c", "t2.0", "_x9"};
  CHECK(to_text(*unite({leaf(0), leaf(1)}), odd) == "\"s1.x+\" | \"empty\"");
  CHECK(to_text(*intersect({leaf(2), leaf(3), leaf(4)}), odd) == "\"a\\\"b\\\\c\" & t2.0 & _x9");
  CHECK_THROWS_AS(to_text(*leaf(7), kNames), std::invalid_argument);
}

TEST_CASE("csg traversals do not recurse: a deep tree", "[csg]") {
  // 20,000 levels of (~e) - B. (Not deeper: destroying a chain of shared_ptr nodes is itself recursive.)
  ExprPtr e = A();
  for (int i = 0; i < 10000; ++i) e = difference(complement(e), B());
  CHECK(stats(*e).depth == 20000);
  CHECK(stats(*e).leaves == 10001);
  // With B = 0 every level negates: an even number of negations gives back A.
  CHECK(evaluate(*e, std::vector<char>{0, 0}) == false);
  CHECK(evaluate(*e, std::vector<char>{1, 0}) == true);
  CHECK(evaluate(*e, std::vector<char>{1, 1}) == false);
  const std::string text = to_text(*e, kNames);
  CHECK(text.size() > 20000);
  Complex c;
  c.halfspace_names = {"A", "B"};
  Cell cell;
  cell.inside = {1, 0};
  c.cells.push_back(cell);
  CHECK(evaluate(*e, c) == std::vector<char>{1});
}
