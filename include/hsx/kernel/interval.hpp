// Certified enclosures with MPFR: every operation rounds its lower end down and its upper end up, so the true
// value always lies in [lo, hi]. Used to decide signs of algebraic and transcendental quantities that exact
// arithmetic cannot reach (arc lengths r*theta, nested radicals).
#pragma once

#include <hsx/kernel/rational.hpp>

#include <mpfr.h>

#include <string>

namespace hsx {

/// A closed interval [lo, hi] with MPFR end points at a fixed precision (bits). Value semantics.
class Interval {
 public:
  explicit Interval(mpfr_prec_t precision_bits = 128);
  Interval(const Rational& q, mpfr_prec_t precision_bits);  ///< tightest enclosure of q
  /// [lo, hi] from end points already rounded outward by the caller (copied exactly; precision = the larger).
  static Interval from_ends(const mpfr_t lo, const mpfr_t hi);
  Interval(const Interval& other);
  Interval(Interval&& other) noexcept;
  Interval& operator=(const Interval& other);
  Interval& operator=(Interval&& other) noexcept;
  ~Interval();

  mpfr_prec_t precision() const;
  const mpfr_t& lo() const { return lo_; }
  const mpfr_t& hi() const { return hi_; }
  double lo_double() const;  ///< rounded down
  double hi_double() const;  ///< rounded up
  double mid_double() const;

  /// -1 if hi < 0, +1 if lo > 0, 0 if the interval contains 0 (sign not decided at this precision).
  int certain_sign() const;
  bool contains_zero() const { return certain_sign() == 0; }
  /// Width hi - lo rounded up, as a double.
  double width() const;

  friend Interval operator+(const Interval& a, const Interval& b);
  friend Interval operator-(const Interval& a, const Interval& b);
  friend Interval operator*(const Interval& a, const Interval& b);
  friend Interval operator/(const Interval& a, const Interval& b);  ///< throws if b contains 0
  Interval operator-() const;

  static Interval sqrt(const Interval& a);   ///< clamps a negative lower end to 0 (callers pass a >= 0 values)
  static Interval asin(const Interval& a);   ///< clamps to [-1, 1]
  static Interval pi(mpfr_prec_t precision_bits);
  /// Rational strictly between hi(a) and lo(b); precondition: a.hi < b.lo.
  static Rational rational_between(const Interval& a, const Interval& b);

  /// Decimal text of the midpoint with `significant` digits (for display; exactness is not claimed).
  std::string mid_decimal(int significant) const;

 private:
  mpfr_t lo_, hi_;
};

}  // namespace hsx
