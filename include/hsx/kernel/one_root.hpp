// One-root numbers a0 + a1*sqrt(r) with rational a0, a1 and rational r >= 0: the exact coordinates of every
// vertex of an arrangement of lines and circles with rational data (CGAL calls them Sqrt_extension).
#pragma once

#include <hsx/kernel/interval.hpp>
#include <hsx/kernel/rational.hpp>

#include <string>

namespace hsx {

struct OneRoot {
  Rational a0 = 0, a1 = 0, root = 0;  ///< value = a0 + a1*sqrt(root); a1 == 0 or root == 0 means rational

  OneRoot() = default;
  OneRoot(const Rational& q) : a0(q) {}  // NOLINT: implicit on purpose, a rational is a one-root number
  OneRoot(const Rational& a0_, const Rational& a1_, const Rational& root_);

  bool is_rational() const { return a1 == 0 || root == 0; }
  /// Exact sign (-1, 0, +1).
  int sign() const;
  /// Certified enclosure at `precision_bits`.
  Interval enclose(mpfr_prec_t precision_bits) const;
  /// Exact text: "3/2", "1 + 2*sqrt(5)", "-1/2*sqrt(3)".
  std::string exact_string() const;
  double to_double() const;
  /// Canonical form: root reduced so that a rational root is folded into a0 when it is a perfect square.
  void normalise();
};

/// Exact comparison of two one-root numbers (possibly with different roots): -1, 0, +1.
int compare(const OneRoot& a, const OneRoot& b);
inline bool operator==(const OneRoot& a, const OneRoot& b) { return compare(a, b) == 0; }
inline bool operator<(const OneRoot& a, const OneRoot& b) { return compare(a, b) < 0; }

/// A point whose coordinates are one-root numbers.
struct OneRootPoint {
  OneRoot x, y;
  OneRootPoint() = default;
  OneRootPoint(const PointQ2& p) : x(p.x), y(p.y) {}  // NOLINT: rational points are one-root points
  OneRootPoint(OneRoot x_, OneRoot y_) : x(std::move(x_)), y(std::move(y_)) {}
  bool is_rational() const { return x.is_rational() && y.is_rational(); }
  std::string exact_string() const;  ///< "[x, y]" with exact coordinates
};

}  // namespace hsx
