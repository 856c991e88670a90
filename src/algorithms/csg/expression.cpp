// CSG expressions: see expression.hpp.
//
// Every traversal here is iterative (an explicit stack), so a deep tree built in code or imported from a long
// CSGNet program cannot overflow the call stack.
//
// Simplifications done by the constructors (each preserves the value on every sign vector):
//   complement: ~empty = full, ~full = empty, ~~a = a;
//   unite:      nested unions flattened, Empty dropped, Full absorbs, no child -> Empty, one child -> that child;
//   intersect:  nested intersections flattened, Full dropped, Empty absorbs, no child -> Full, one child -> it;
//   difference: a - empty = a, a - full = empty, empty - b = empty, full - b = ~b.
// Nothing else is rewritten: repeated children and repeated halfspaces are kept, so a tree read from a file or a
// CSGNet program keeps its shape.
#include <hsx/algorithms/csg/expression.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace hsx::csg {

namespace {

ExprPtr make(Op op, std::vector<ExprPtr> children, int halfspace = -1) {
  auto e = std::make_shared<Expr>();
  e->op = op;
  e->halfspace = halfspace;
  e->children = std::move(children);
  return e;
}

const ExprPtr& empty_node() {
  static const ExprPtr node = make(Op::Empty, {});
  return node;
}

const ExprPtr& full_node() {
  static const ExprPtr node = make(Op::Full, {});
  return node;
}

void check_not_null(const ExprPtr& e, const char* where) {
  if (!e) throw std::invalid_argument(std::string("csg::") + where + ": null expression");
}


void check_arity(const Expr& e) {
  switch (e.op) {
    case Op::Halfspace:
    case Op::Empty:
    case Op::Full:
      if (!e.children.empty()) throw std::invalid_argument("csg: a leaf with children");
      break;
    case Op::Complement:
      if (e.children.size() != 1) throw std::invalid_argument("csg: a complement needs exactly one child");
      break;
    case Op::Difference:
      if (e.children.size() != 2) throw std::invalid_argument("csg: a difference needs exactly two children");
      break;
    case Op::Union:
    case Op::Intersection:
      if (e.children.empty()) throw std::invalid_argument("csg: a union or intersection without children");
      break;
  }
}

void check_halfspace(const Expr& e, std::size_t count) {
  if (e.halfspace < 0 || static_cast<std::size_t>(e.halfspace) >= count) {
    throw std::invalid_argument("csg: halfspace index " + std::to_string(e.halfspace) + " out of range (" +
                                std::to_string(count) + " halfspaces)");
  }
}

bool is_identifier(const std::string& s) {
  if (s.empty()) return false;
  auto alpha = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (!alpha(s[0])) return false;
  for (char c : s)
    if (!alpha(c) && !digit(c) && c != '.') return false;
  return s != "empty" && s != "full";
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  out += '"';
  return out;
}

}  // namespace

ExprPtr leaf(int halfspace) {
  if (halfspace < 0) throw std::invalid_argument("csg::leaf: negative halfspace index");
  return make(Op::Halfspace, {}, halfspace);
}

ExprPtr empty() { return empty_node(); }
ExprPtr full() { return full_node(); }

ExprPtr complement(ExprPtr a) {
  check_not_null(a, "complement");
  if (a->op == Op::Empty) return full();
  if (a->op == Op::Full) return empty();
  if (a->op == Op::Complement && a->children.size() == 1) return a->children[0];
  return make(Op::Complement, {std::move(a)});
}

namespace {

/// unite / intersect: `op` the n-ary operation, `neutral` the constant it drops, `absorbing` the one that wins.
ExprPtr nary(Op op, Op neutral, Op absorbing, std::vector<ExprPtr> children, const char* where) {
  std::vector<ExprPtr> flat;
  flat.reserve(children.size());
  for (ExprPtr& c : children) {
    check_not_null(c, where);
    if (c->op == absorbing) return c;
    if (c->op == neutral) continue;
    if (c->op == op) {
      // Children built by the constructors are already flat and constant-free.
      for (const ExprPtr& g : c->children) {
        check_not_null(g, where);
        flat.push_back(g);
      }
    } else {
      flat.push_back(std::move(c));
    }
  }
  if (flat.empty()) return neutral == Op::Empty ? empty() : full();
  if (flat.size() == 1) return flat[0];
  return make(op, std::move(flat));
}

}  // namespace

ExprPtr unite(std::vector<ExprPtr> children) {
  return nary(Op::Union, Op::Empty, Op::Full, std::move(children), "unite");
}

ExprPtr intersect(std::vector<ExprPtr> children) {
  return nary(Op::Intersection, Op::Full, Op::Empty, std::move(children), "intersect");
}

ExprPtr difference(ExprPtr a, ExprPtr b) {
  check_not_null(a, "difference");
  check_not_null(b, "difference");
  if (b->op == Op::Empty) return a;
  if (b->op == Op::Full || a->op == Op::Empty) return empty();
  if (a->op == Op::Full) return complement(std::move(b));
  return make(Op::Difference, {std::move(a), std::move(b)});
}

bool evaluate(const Expr& e, const std::vector<char>& inside) {
  return fold<char>(e, [&](const Expr& n, std::vector<char> v) -> char {
    check_arity(n);
    switch (n.op) {
      case Op::Halfspace:
        check_halfspace(n, inside.size());
        return inside[static_cast<std::size_t>(n.halfspace)] ? 1 : 0;
      case Op::Empty: return 0;
      case Op::Full: return 1;
      case Op::Complement: return v[0] ? 0 : 1;
      case Op::Difference: return v[0] && !v[1] ? 1 : 0;
      case Op::Union: return std::any_of(v.begin(), v.end(), [](char x) { return x != 0; }) ? 1 : 0;
      case Op::Intersection: return std::all_of(v.begin(), v.end(), [](char x) { return x != 0; }) ? 1 : 0;
    }
    return 0;
  }) != 0;
}

std::vector<char> evaluate(const Expr& e, const Complex& complex) {
  const std::size_t cells = complex.cells.size();
  const std::size_t count = static_cast<std::size_t>(complex.halfspace_count());
  for (std::size_t k = 0; k < cells; ++k) {
    if (complex.cells[k].inside.size() != count) {
      throw std::invalid_argument("csg::evaluate: cell " + std::to_string(k) + " has " +
                                  std::to_string(complex.cells[k].inside.size()) + " sides for " +
                                  std::to_string(count) + " halfspaces");
    }
  }
  // One value per cell per node, combined bottom-up.
  return fold<std::vector<char>>(e, [&](const Expr& n, std::vector<std::vector<char>> v) {
    check_arity(n);
    std::vector<char> out(cells, 0);
    switch (n.op) {
      case Op::Halfspace:
        check_halfspace(n, count);
        for (std::size_t k = 0; k < cells; ++k)
          out[k] = complex.cells[k].inside[static_cast<std::size_t>(n.halfspace)] ? 1 : 0;
        break;
      case Op::Empty: break;
      case Op::Full: std::fill(out.begin(), out.end(), 1); break;
      case Op::Complement:
        for (std::size_t k = 0; k < cells; ++k) out[k] = v[0][k] ? 0 : 1;
        break;
      case Op::Difference:
        for (std::size_t k = 0; k < cells; ++k) out[k] = v[0][k] && !v[1][k] ? 1 : 0;
        break;
      case Op::Union:
        for (const auto& c : v)
          for (std::size_t k = 0; k < cells; ++k) out[k] = out[k] || c[k] ? 1 : 0;
        break;
      case Op::Intersection:
        std::fill(out.begin(), out.end(), 1);
        for (const auto& c : v)
          for (std::size_t k = 0; k < cells; ++k) out[k] = out[k] && c[k] ? 1 : 0;
        break;
    }
    return out;
  });
}

ExprStats stats(const Expr& e) {
  ExprStats s;
  std::map<int, int> uses;
  const int depth = fold<int>(e, [&](const Expr& n, std::vector<int> v) {
    if (n.children.empty()) {
      ++s.leaves;
      if (n.op == Op::Halfspace) ++uses[n.halfspace];
      return 0;
    }
    ++s.internal_nodes;
    return 1 + *std::max_element(v.begin(), v.end());
  });
  s.depth = depth;
  s.distinct_halfspaces = static_cast<int>(uses.size());
  for (const auto& [h, k] : uses)
    if (k > 1) ++s.duplicated_halfspaces;
  return s;
}

std::string to_text(const Expr& e, const std::vector<std::string>& names) {
  // Precedence levels: atoms 5, ~ 4, & 3, - 2, | 1. Difference is left-associative: its right operand needs
  // parentheses when it is itself a difference.
  struct Text {
    std::string s;
    int level;
  };
  auto wrap = [](Text t, bool parens) { return parens ? "(" + t.s + ")" : std::move(t.s); };
  return fold<Text>(e, [&](const Expr& n, std::vector<Text> v) -> Text {
    check_arity(n);
    switch (n.op) {
      case Op::Halfspace: {
        check_halfspace(n, names.size());
        const std::string& name = names[static_cast<std::size_t>(n.halfspace)];
        return {is_identifier(name) ? name : quoted(name), 5};
      }
      case Op::Empty: return {"empty", 5};
      case Op::Full: return {"full", 5};
      case Op::Complement: {
        const bool parens = v[0].level < 4;
        return {"~" + wrap(std::move(v[0]), parens), 4};
      }
      case Op::Difference: {
        const bool left = v[0].level < 2, right = v[1].level <= 2;
        std::string s = wrap(std::move(v[0]), left);
        s += " - ";
        s += wrap(std::move(v[1]), right);
        return {std::move(s), 2};
      }
      case Op::Intersection:
      case Op::Union: {
        const bool conj = n.op == Op::Intersection;
        const int level = conj ? 3 : 1;
        std::string s;
        for (std::size_t i = 0; i < v.size(); ++i) {
          if (i) s += conj ? " & " : " | ";
          const bool parens = v[i].level < level;
          s += wrap(std::move(v[i]), parens);
        }
        return {std::move(s), level};
      }
    }
    return {"", 5};
  }).s;
}

}  // namespace hsx::csg
