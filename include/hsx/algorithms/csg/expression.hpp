// CSG expressions over a complex's halfspaces, evaluated exactly on its cells.
//
// Conventions (owned here):
// - A leaf names a halfspace by index (Complex::halfspace_names); its value on a cell is Cell::inside[i].
// - Operations are the regularized set operations; on cells (open regions of the arrangement) they are plain
//   Boolean operations on the per-cell values, which is why evaluation on the complex is exact.
// - Empty and Full are the constant solids (BHC terminates branches with them; they never survive
//   simplification inside a larger tree).
#pragma once

#include <hsx/complex/complex.hpp>

#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace hsx::csg {

enum class Op { Halfspace, Complement, Union, Intersection, Difference, Empty, Full };

struct Expr;
using ExprPtr = std::shared_ptr<const Expr>;

/// An immutable expression node. Union and Intersection are n-ary (>= 2 children), Difference binary (a - b),
/// Complement unary; Halfspace carries `halfspace`.
struct Expr {
  Op op = Op::Empty;
  int halfspace = -1;
  std::vector<ExprPtr> children;
};

ExprPtr leaf(int halfspace);
ExprPtr complement(ExprPtr a);
ExprPtr unite(std::vector<ExprPtr> children);      ///< flattens nested unions; drops Empty; Full absorbs
ExprPtr intersect(std::vector<ExprPtr> children);  ///< flattens nested intersections; drops Full; Empty absorbs
ExprPtr difference(ExprPtr a, ExprPtr b);
ExprPtr empty();
ExprPtr full();

/// The solid as a labelling of the complex's cells (1 inside). Outer cells get the expression's value too:
/// a solid that covers an outer cell is unbounded within the domain.
std::vector<char> evaluate(const Expr& e, const Complex& complex);
/// Value on one sign vector (Cell::inside).
bool evaluate(const Expr& e, const std::vector<char>& inside);

struct ExprStats {
  int depth = 0;            ///< edges on the longest root-to-leaf path
  int internal_nodes = 0;
  int leaves = 0;
  int distinct_halfspaces = 0;
  int duplicated_halfspaces = 0;  ///< halfspaces used by more than one leaf
};
ExprStats stats(const Expr& e);

/// Compact text: names joined by `|` (union), `&` (intersection), `-` (difference), `~` (complement), with
/// parentheses where needed; "empty" and "full" for the constants. Names that are not identifiers are quoted.
std::string to_text(const Expr& e, const std::vector<std::string>& names);

/// Post-order fold without recursion (expressions may be deeper than the stack allows): `combine(node,
/// child_results)` is called once per node occurrence (a shared subtree is visited once per parent), children
/// first, left to right. Throws std::invalid_argument on a null child.
template <class R, class F>
R fold(const Expr& root, F combine) {
  struct Frame {
    const Expr* node;
    std::size_t next;
  };
  std::vector<Frame> frames{{&root, 0}};
  std::vector<R> values;
  while (!frames.empty()) {
    Frame& top = frames.back();
    if (top.next < top.node->children.size()) {
      const Expr* child = top.node->children[top.next++].get();
      if (!child) throw std::invalid_argument("csg: null child in an expression");
      frames.push_back({child, 0});
      continue;
    }
    const Expr* node = top.node;
    frames.pop_back();
    const std::size_t k = node->children.size();
    std::vector<R> args(std::make_move_iterator(values.end() - static_cast<std::ptrdiff_t>(k)),
                        std::make_move_iterator(values.end()));
    values.resize(values.size() - k);
    values.push_back(combine(*node, std::move(args)));
  }
  return std::move(values.back());
}

}  // namespace hsx::csg
