// Exact rational numbers: the only number type that decides anything in hsx.
//
// Conventions
// - `Rational` is GMP's mpq_class. A value built from a numerator and a denominator must be canonicalised
//   (`make_rational` does it); a non-canonical mpq breaks equality and zero tests.
// - Text is read exactly: "0.1" is 1/10, never a binary double.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace hsx {

using Rational = mpq_class;
using Integer = mpz_class;

/// Limits on the text of one number, so that hostile input fails fast instead of exhausting memory.
struct NumberLimits {
  std::size_t max_chars = 20000;  ///< total characters of the spelling
  long max_exponent = 20000;      ///< |e| in "1e<e>" (10^20000 has 20001 digits: fine; 10^1e9 is refused)
};

/// Canonical n/d. Precondition: d != 0.
Rational make_rational(const Integer& n, const Integer& d);

/// Parse an exact rational from text. Accepted spellings (optional leading '-' or '+'):
///   integer "12", decimal "0.25", ".5", "5.", scientific "1e-3", "2.5E+4", fraction "-7/3" (integers on both
///   sides, non-zero denominator). No spaces, no "inf"/"nan", no hex.
/// Returns nullopt and sets *why (if given) to a short reason when the text is not a number or breaks `limits`.
std::optional<Rational> parse_rational(std::string_view text, std::string* why = nullptr,
                                       const NumberLimits& limits = {});

/// Exact text: "3", "-7/3". Round-trips through parse_rational.
std::string exact_string(const Rational& q);

/// Decimal text with `significant` significant digits, rounded to nearest ("0.333333"); exact values with a
/// finite expansion that fits are printed without trailing zeros ("0.25").
std::string decimal_string(const Rational& q, int significant = 30);

/// The simplest rational strictly inside the OPEN interval (lo, hi): the one with the smallest positive
/// denominator; when several share it (only possible for denominator 1), the integer of least absolute value.
/// Found by continued fractions (a descent of the Stern-Brocot tree), exact. Used to choose short witness points
/// ("1/2" rather than "4611686018427387905/9223372036854775808"). Throws std::invalid_argument unless lo < hi.
Rational simplest_rational_in(const Rational& lo, const Rational& hi);

/// A rational point of the plane or of space; `dimension()` coordinates.
struct PointQ2 {
  Rational x, y;
  friend bool operator==(const PointQ2& a, const PointQ2& b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(const PointQ2& a, const PointQ2& b) { return !(a == b); }
};

}  // namespace hsx
