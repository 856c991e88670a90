// CSGNet programs: see csgnet.hpp.
#include <hsx/io/csgnet.hpp>

#include <algorithm>
#include <utility>
#include <vector>

namespace hsx {

namespace {

Rational R(long n, long d = 1) { return make_rational(Integer(n), Integer(d)); }

bool blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

Integer floor_of(const Rational& q) {
  Integer r;
  mpz_fdiv_q(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return r;
}

Integer ceil_of(const Rational& q) {
  Integer r;
  mpz_cdiv_q(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return r;
}

/// (a, b) scaled by a positive factor to coprime integers; (0, 0) stays.
PointQ2 primitive_direction(const Rational& a, const Rational& b) {
  Integer l;
  mpz_lcm(l.get_mpz_t(), a.get_den_mpz_t(), b.get_den_mpz_t());
  Integer x = a.get_num() * (l / a.get_den()), y = b.get_num() * (l / b.get_den());
  Integer g;
  mpz_gcd(g.get_mpz_t(), x.get_mpz_t(), y.get_mpz_t());
  if (g != 0) {
    x /= g;
    y /= g;
  }
  return PointQ2{Rational(x), Rational(y)};
}

Halfspace2 halfplane(std::string name, const Rational& nx, const Rational& ny, const PointQ2& through) {
  Halfspace2 h;
  h.name = std::move(name);
  h.kind = HalfspaceKind2::Halfplane;
  h.normal = primitive_direction(nx, ny);
  h.offset = h.normal.x * through.x + h.normal.y * through.y;
  return h;
}

struct Extent {
  bool any = false;
  Rational xmin, xmax, ymin, ymax;
  void add(const Rational& x0, const Rational& y0, const Rational& x1, const Rational& y1) {
    if (!any) {
      xmin = x0, ymin = y0, xmax = x1, ymax = y1;
      any = true;
      return;
    }
    xmin = std::min(xmin, x0);
    ymin = std::min(ymin, y0);
    xmax = std::max(xmax, x1);
    ymax = std::max(ymax, y1);
  }
};

class ProgramReader {
 public:
  ProgramReader(std::string_view text, const std::string& origin) : text_(text), origin_(origin) {}

  CsgnetProgram read() {
    if (text_.size() > kCsgnetMaxChars) {
      throw InputError(prefix() + "the program is " + std::to_string(text_.size()) + " characters; the limit is " +
                       std::to_string(kCsgnetMaxChars));
    }
    std::vector<csg::ExprPtr> stack;
    while (true) {
      while (pos_ < text_.size() && blank(text_[pos_])) ++pos_;
      if (pos_ >= text_.size()) break;
      ++token_;
      token_start_ = pos_;
      const char c = text_[pos_];
      if (c == 'c' || c == 's' || c == 't') {
        stack.push_back(primitive(c));
      } else if (c == '+' || c == '*' || c == '-') {
        ++pos_;
        if (stack.size() < 2) {
          fail(std::string("stack underflow: '") + c + "' needs two solids, the stack has " +
               std::to_string(stack.size()));
        }
        csg::ExprPtr b = std::move(stack.back());
        stack.pop_back();
        csg::ExprPtr a = std::move(stack.back());
        stack.pop_back();
        if (c == '+') {
          stack.push_back(csg::unite({std::move(a), std::move(b)}));
        } else if (c == '*') {
          stack.push_back(csg::intersect({std::move(a), std::move(b)}));
        } else {
          stack.push_back(csg::difference(std::move(a), std::move(b)));
        }
      } else {
        fail("unknown token starting with " + show(c) + " (expected c(...), s(...), t(...), +, * or -)");
      }
    }
    if (stack.empty()) throw InputError(prefix() + "empty program");
    if (stack.size() > 1) {
      throw InputError(prefix() + "the program leaves " + std::to_string(stack.size()) +
                       " solids on the stack (expected one; an operator is missing)");
    }

    CsgnetProgram out;
    out.expression = std::move(stack.back());
    Scene2& scene = out.scene;
    std::string program(text_);
    while (!program.empty() && blank(program.back())) program.pop_back();
    program.erase(0, std::min(program.size(), program.find_first_not_of(" \t\r\n")));
    scene.description = "CSGNet program" + (origin_.empty() ? std::string() : " (" + origin_ + ")") + ": " + program;
    scene.halfspaces = std::move(halfspaces_);
    const Rational width = extent_.xmax - extent_.xmin, height = extent_.ymax - extent_.ymin;
    const Rational w = std::max(width, height);
    const Integer m = std::max(Integer(8), ceil_of(w / 8));
    scene.domain.min = PointQ2{Rational(floor_of(extent_.xmin) - m), Rational(floor_of(extent_.ymin) - m)};
    scene.domain.max = PointQ2{Rational(ceil_of(extent_.xmax) + m), Rational(ceil_of(extent_.ymax) + m)};
    scene.domain_given = true;
    try {
      validate_and_resolve(scene);
    } catch (const InputError& e) {
      throw InputError(prefix() + e.what());
    }
    return out;
  }

 private:
  std::string prefix() const { return origin_.empty() ? std::string() : origin_ + ": "; }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(prefix() + "token " + std::to_string(token_) + " at column " + std::to_string(token_start_ + 1) +
                     ": " + what);
  }

  static std::string show(char c) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
    return "byte " + std::to_string(u);
  }

  /// Reads `k(a,b,c)` at pos_ and returns the primitive's expression, adding its halfspaces.
  csg::ExprPtr primitive(char kind) {
    const std::string form = std::string(1, kind) + (kind == 'c' ? "(x,y,r)" : "(x,y,l)");
    ++pos_;
    if (pos_ >= text_.size() || text_[pos_] != '(') fail("malformed primitive: expected " + form);
    const std::size_t close = text_.find(')', pos_);
    if (close == std::string_view::npos) fail("malformed primitive: missing ')' in " + form);
    const std::string_view inner = text_.substr(pos_ + 1, close - pos_ - 1);
    pos_ = close + 1;
    std::vector<Rational> values;
    std::size_t from = 0;
    while (true) {
      const std::size_t comma = inner.find(',', from);
      std::string_view part = inner.substr(from, comma == std::string_view::npos ? std::string_view::npos : comma - from);
      while (!part.empty() && blank(part.front())) part.remove_prefix(1);
      while (!part.empty() && blank(part.back())) part.remove_suffix(1);
      std::string why;
      auto q = parse_rational(part, &why);
      if (!q) fail("malformed number \"" + std::string(part.substr(0, 40)) + "\" in " + form + ": " + why);
      values.push_back(*q);
      if (values.size() > 3) break;
      if (comma == std::string_view::npos) break;
      from = comma + 1;
    }
    if (values.size() != 3) {
      fail("malformed primitive: expected three numbers in " + form + ", got " +
           (values.size() > 3 ? std::string("more") : std::to_string(values.size())));
    }
    const Rational &x = values[0], &y = values[1], &size = values[2];
    if (size <= 0) {
      fail(std::string(kind == 'c' ? "the radius" : "the size") + " must be positive, got " +
           decimal_string(size));
    }
    const std::string id = std::string(1, kind) + std::to_string(primitives_++);
    const int first = static_cast<int>(halfspaces_.size());
    if (kind == 'c') {
      Halfspace2 h;
      h.name = id;
      h.kind = HalfspaceKind2::Disk;
      h.center = PointQ2{x, y};
      h.radius = size;
      halfspaces_.push_back(std::move(h));
      extent_.add(x - size, y - size, x + size, y + size);
      return csg::leaf(first);
    }
    if (kind == 's') {
      const Rational h = R(706, 1000) * size;
      halfspaces_.push_back(halfplane(id + ".xmin", R(-1), R(0), PointQ2{x - h, y}));
      halfspaces_.push_back(halfplane(id + ".xmax", R(1), R(0), PointQ2{x + h, y}));
      halfspaces_.push_back(halfplane(id + ".ymin", R(0), R(-1), PointQ2{x, y - h}));
      halfspaces_.push_back(halfplane(id + ".ymax", R(0), R(1), PointQ2{x, y + h}));
      extent_.add(x - h, y - h, x + h, y + h);
      return csg::intersect({csg::leaf(first), csg::leaf(first + 1), csg::leaf(first + 2), csg::leaf(first + 3)});
    }
    const Rational a = R(866, 1000) * size;
    const PointQ2 v[3] = {PointQ2{x - a, y + size / 2}, PointQ2{x + a, y + size / 2}, PointQ2{x, y - size}};
    for (int i = 0; i < 3; ++i) {
      const PointQ2& p = v[i];
      const PointQ2& q = v[(i + 1) % 3];
      const PointQ2& opposite = v[(i + 2) % 3];
      Rational nx = q.y - p.y, ny = p.x - q.x;  // perpendicular to the edge
      if (sgn(Rational(nx * (opposite.x - p.x) + ny * (opposite.y - p.y))) > 0) {
        nx = -nx;  // make it point away from the opposite vertex: outward
        ny = -ny;
      }
      halfspaces_.push_back(halfplane(id + "." + std::to_string(i), nx, ny, p));
    }
    extent_.add(x - a, y - size, x + a, y + size / 2);
    return csg::intersect({csg::leaf(first), csg::leaf(first + 1), csg::leaf(first + 2)});
  }

  std::string_view text_;
  std::string origin_;
  std::size_t pos_ = 0, token_start_ = 0;
  int token_ = 0, primitives_ = 0;
  std::vector<Halfspace2> halfspaces_;
  Extent extent_;
};

}  // namespace

CsgnetProgram read_csgnet(std::string_view program_line, const std::string& origin) {
  return ProgramReader(program_line, origin).read();
}

}  // namespace hsx
