#include "support/random_expressions.hpp"

#include <rapidcheck.h>

namespace hsx::test {

using namespace hsx::csg;

ExprPtr raw(Op op, std::vector<ExprPtr> children) {
  auto e = std::make_shared<Expr>();
  e->op = op;
  e->children = std::move(children);
  return e;
}

ExprPtr random_expr(int n, int depth, bool raw_nodes) {
  const int kind = *rc::gen::inRange(0, depth > 0 ? 10 : 4);
  if (kind <= 2) return leaf(*rc::gen::inRange(0, n));
  if (kind == 3) return *rc::gen::inRange(0, 8) == 0 ? (*rc::gen::arbitrary<bool>() ? empty() : full())
                                                     : leaf(*rc::gen::inRange(0, n));
  if (kind == 4) {
    ExprPtr a = random_expr(n, depth - 1, raw_nodes);
    return raw_nodes ? raw(Op::Complement, {a}) : complement(a);
  }
  if (kind <= 7) {
    const int k = *rc::gen::inRange(2, 4);
    std::vector<ExprPtr> children;
    for (int i = 0; i < k; ++i) children.push_back(random_expr(n, depth - 1, raw_nodes));
    const Op op = kind <= 5 ? Op::Union : Op::Intersection;
    if (raw_nodes) return raw(op, children);
    return op == Op::Union ? unite(children) : intersect(children);
  }
  ExprPtr a = random_expr(n, depth - 1, raw_nodes), b = random_expr(n, depth - 1, raw_nodes);
  return raw_nodes ? raw(Op::Difference, {a, b}) : difference(a, b);
}

}  // namespace hsx::test
