// Exact rationals: parsing and printing. See rational.hpp for the accepted spellings.
//
// Decisions documented here (and in proofs/measures.md):
// - "1.5/2" is refused: both sides of a fraction must be integers (the numerator may carry the sign).
// - decimal_string rounds half away from zero (ties are real for rationals: 0.125 -> "0.13" at 2 digits), strips
//   trailing zeros (like printf's %g), and uses plain notation when the rounded magnitude m satisfies
//   1e-6 <= m < 1e21 (the same switch points as JavaScript's Number.prototype.toString), otherwise scientific
//   notation "1.5e-40" / "1e21" (no '+' sign in the exponent; parse_rational accepts both spellings).
#include <hsx/kernel/rational.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace hsx {

Rational make_rational(const Integer& n, const Integer& d) {
  Rational q(n, d);
  q.canonicalize();
  return q;
}

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return is_digit(c); });
}

std::optional<Rational> fail(std::string* why, std::string reason) {
  if (why) *why = std::move(reason);
  return std::nullopt;
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

Integer digits_to_integer(std::string_view digits) {
  // mpz_set_str needs a NUL-terminated string; GMP's conversion is sub-quadratic, so 10^4 digits is instant.
  std::string s(digits);
  Integer z;
  if (s.empty()) return z;
  z.set_str(s, 10);
  return z;
}

Integer pow10(unsigned long e) {
  Integer z;
  mpz_ui_pow_ui(z.get_mpz_t(), 10, e);
  return z;
}

}  // namespace

std::optional<Rational> parse_rational(std::string_view text, std::string* why, const NumberLimits& limits) {
  if (text.size() > limits.max_chars)
    return fail(why, "number too long (" + std::to_string(text.size()) + " characters, limit " +
                         std::to_string(limits.max_chars) + ")");
  if (text.empty()) return fail(why, "empty number");

  std::size_t pos = 0;
  bool negative = false;
  if (text[0] == '+' || text[0] == '-') {
    negative = text[0] == '-';
    pos = 1;
  }
  std::string_view body = text.substr(pos);
  if (body.empty()) return fail(why, "sign without digits");
  if (iequals(body, "inf") || iequals(body, "infinity") || iequals(body, "nan"))
    return fail(why, "not a finite number");
  if (body.size() >= 2 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X'))
    return fail(why, "hexadecimal numbers are not accepted");
  for (char c : body) {
    if (std::isspace(static_cast<unsigned char>(c))) return fail(why, "spaces are not allowed in a number");
  }

  const std::size_t slash = body.find('/');
  if (slash != std::string_view::npos) {
    std::string_view num = body.substr(0, slash);
    std::string_view den = body.substr(slash + 1);
    if (!all_digits(num) || !all_digits(den))
      return fail(why, "a fraction needs integer digits on both sides of '/' (e.g. -7/3)");
    Integer d = digits_to_integer(den);
    if (d == 0) return fail(why, "zero denominator");
    Integer n = digits_to_integer(num);
    if (negative) n = -n;
    return make_rational(n, d);
  }

  // [digits] ['.' [digits]] [(e|E) [sign] digits]
  std::size_t i = 0;
  const std::size_t int_begin = i;
  while (i < body.size() && is_digit(body[i])) ++i;
  std::string_view int_digits = body.substr(int_begin, i - int_begin);
  std::string_view frac_digits;
  if (i < body.size() && body[i] == '.') {
    ++i;
    const std::size_t frac_begin = i;
    while (i < body.size() && is_digit(body[i])) ++i;
    frac_digits = body.substr(frac_begin, i - frac_begin);
  }
  if (int_digits.empty() && frac_digits.empty()) return fail(why, "no digits in the number");

  long exponent = 0;
  if (i < body.size() && (body[i] == 'e' || body[i] == 'E')) {
    ++i;
    bool exp_negative = false;
    if (i < body.size() && (body[i] == '+' || body[i] == '-')) {
      exp_negative = body[i] == '-';
      ++i;
    }
    const std::size_t exp_begin = i;
    while (i < body.size() && is_digit(body[i])) ++i;
    if (i == exp_begin) return fail(why, "missing exponent digits");
    if (i != body.size()) return fail(why, std::string("unexpected character '") + body[i] + "'");
    // Accumulate without overflow: stop as soon as the magnitude passes the limit (limit <= LONG_MAX).
    long magnitude = 0;
    const long limit = std::max(0L, limits.max_exponent);
    for (std::size_t k = exp_begin; k < i; ++k) {
      const long digit = body[k] - '0';
      if (magnitude > limit / 10 || (magnitude == limit / 10 && digit > limit % 10))
        return fail(why, "exponent too large (limit " + std::to_string(limit) + ")");
      magnitude = magnitude * 10 + digit;
    }
    exponent = exp_negative ? -magnitude : magnitude;
  }
  if (i != body.size()) return fail(why, std::string("unexpected character '") + body[i] + "'");

  std::string mantissa;
  mantissa.reserve(int_digits.size() + frac_digits.size());
  mantissa.append(int_digits);
  mantissa.append(frac_digits);
  // Strip leading zeros (only a cost saving).
  const std::size_t first = mantissa.find_first_not_of('0');
  if (first == std::string::npos) return Rational(0);
  Integer n = digits_to_integer(std::string_view(mantissa).substr(first));
  if (negative) n = -n;
  // |exponent| <= max_exponent and frac_digits.size() <= max_chars, so this cannot overflow a long.
  const long scale = exponent - static_cast<long>(frac_digits.size());
  if (scale >= 0) return Rational(n * pow10(static_cast<unsigned long>(scale)));
  return make_rational(n, pow10(static_cast<unsigned long>(-scale)));
}

std::string exact_string(const Rational& q) { return q.get_str(10); }

std::string decimal_string(const Rational& q, int significant) {
  if (sgn(q) == 0) return "0";
  const int sig = std::clamp(significant, 1, 1000000);
  const bool negative = sgn(q) < 0;
  const Integer n = abs(q.get_num());
  const Integer& d = q.get_den();

  // E with 10^E <= |q| < 10^(E+1): estimate from bit lengths (off by at most one or two), then fix exactly.
  const long nbits = static_cast<long>(mpz_sizeinbase(n.get_mpz_t(), 2));
  const long dbits = static_cast<long>(mpz_sizeinbase(d.get_mpz_t(), 2));
  long E = static_cast<long>(std::floor(static_cast<double>(nbits - dbits) * 0.30102999566398120));
  auto at_least_pow10 = [&](long e) {  // |q| >= 10^e ?
    if (e >= 0) return n >= d * pow10(static_cast<unsigned long>(e));
    return n * pow10(static_cast<unsigned long>(-e)) >= d;
  };
  while (!at_least_pow10(E)) --E;
  while (at_least_pow10(E + 1)) ++E;

  // M = round(|q| * 10^(sig-1-E)), half away from zero; sig digits unless rounding carried into 10^sig.
  const long k = static_cast<long>(sig) - 1 - E;
  Integer num = n, den = d;
  if (k >= 0)
    num *= pow10(static_cast<unsigned long>(k));
  else
    den *= pow10(static_cast<unsigned long>(-k));
  Integer M = (2 * num + den) / (2 * den);  // floor for non-negative operands
  if (M == pow10(static_cast<unsigned long>(sig))) {
    M /= 10;
    ++E;
  }
  std::string digits = M.get_str(10);
  const std::size_t last = digits.find_last_not_of('0');
  digits.erase(last + 1);  // M > 0, so there is a non-zero digit

  std::string out = negative ? "-" : "";
  const long L = static_cast<long>(digits.size());
  if (E >= -6 && E <= 20) {
    if (E >= 0) {
      if (L <= E + 1) {
        out += digits;
        out.append(static_cast<std::size_t>(E + 1 - L), '0');
      } else {
        out += digits.substr(0, static_cast<std::size_t>(E + 1));
        out += '.';
        out += digits.substr(static_cast<std::size_t>(E + 1));
      }
    } else {
      out += "0.";
      out.append(static_cast<std::size_t>(-E - 1), '0');
      out += digits;
    }
  } else {
    out += digits[0];
    if (L > 1) {
      out += '.';
      out += digits.substr(1);
    }
    out += 'e';
    out += std::to_string(E);
  }
  return out;
}

namespace {

Rational simplest_nonnegative_big(const Rational& lo, const std::optional<Rational>& hi);

/// Ends of at most kSmallBits bits take simplest_small: the same steps in 128-bit integers, where no value of the
/// descent exceeds the ends (see there).
constexpr std::size_t kSmallBits = 120;
using Small = unsigned __int128;

bool small_enough(const Integer& v) { return mpz_sizeinbase(v.get_mpz_t(), 2) <= kSmallBits; }

Small to_small(const Integer& v) {  // 0 <= v < 2^kSmallBits
  static_assert(sizeof(mp_limb_t) == 8, "64-bit GMP limbs");
  return (static_cast<Small>(mpz_getlimbn(v.get_mpz_t(), 1)) << 64) | mpz_getlimbn(v.get_mpz_t(), 0);
}

Integer from_small(Small v) {
  Integer out(static_cast<unsigned long>(v >> 64));
  out <<= 64;
  out += static_cast<unsigned long>(static_cast<std::uint64_t>(v));
  return out;
}

/// simplest_nonnegative's descent in 128-bit integers, for ends a/b (and c/d when bounded) of at most kSmallBits
/// bits. Nothing overflows: "f d < c" is asked as "f <= (c - 1) / d"; the ends' numerators and denominators only
/// shrink (each step leaves remainders of the previous ones); the folded convergents p/r of the answer are at most
/// its numerator and denominator, which are at most a + c and b + d: the mediant (a + c)/(b + d) lies strictly
/// inside, and the answer, a Stern-Brocot ancestor of every fraction inside, has numerator and denominator at most
/// theirs (unbounded: the answer is an integer f <= a / b + 1). The descent takes at most about 1.44 * kSmallBits
/// steps (the ends shrink at least like Fibonacci numbers): fewer than kSteps.
Rational simplest_small(Small a, Small b, Small c, Small d, bool bounded) {
  constexpr int kSteps = 400;
  Small quotients[kSteps];
  int count = 0;
  while (true) {
    const Small f = a / b + 1;  // the smallest integer above lo
    if (!bounded || f <= (c - 1) / d) {
      Small p = f, r = 1;
      for (int k = count - 1; k >= 0; --k) {
        r += quotients[k] * p;
        std::swap(p, r);
      }
      return make_rational(from_small(p), from_small(r));
    }
    const Small q = f - 1;  // floor(lo)
    c -= q * d;  // c - q d > 0
    a -= q * b;  // a - q b >= 0
    if (count == kSteps) throw std::logic_error("simplest_rational_in: more continued-fraction steps than possible");
    quotients[count++] = q;
    bounded = a != 0;
    std::swap(a, d);
    std::swap(b, c);
  }
}

/// Simplest rational in the open interval (lo, hi) with 0 <= lo < hi (hi = nullopt: +infinity). If the
/// smallest integer n > lo is below hi it is the answer (denominator 1, least value). Otherwise (lo, hi) lies in
/// [f, f + 1] with f = floor(lo), and x = f + 1/y maps it onto the open interval of y, (1/(hi - f), 1/(lo - f))
/// (the upper end infinite when lo = f); x has the smallest denominator iff y has the smallest numerator, and the
/// continued-fraction step preserves simplicity (proofs/measures.md, Claim 1.4). Iterative, on the ends'
/// numerators and denominators in place (lo = a/b, hi = c/d, b and d > 0; no reduction is needed, floors and
/// comparisons do not depend on it): the partial quotients are collected and folded back at the end.
Rational simplest_nonnegative(const Rational& lo, const std::optional<Rational>& hi) {
  if (small_enough(lo.get_num()) && small_enough(lo.get_den()) &&
      (!hi || (small_enough(hi->get_num()) && small_enough(hi->get_den()))))
    return simplest_small(to_small(lo.get_num()), to_small(lo.get_den()), hi ? to_small(hi->get_num()) : 0,
                          hi ? to_small(hi->get_den()) : 1, hi.has_value());
  return simplest_nonnegative_big(lo, hi);
}

/// simplest_nonnegative on integers of any size.
Rational simplest_nonnegative_big(const Rational& lo, const std::optional<Rational>& hi) {
  Integer a = lo.get_num(), b = lo.get_den(), c, d, f, t;
  bool bounded = hi.has_value();
  if (bounded) {
    c = hi->get_num();
    d = hi->get_den();
  }
  std::vector<Integer> quotients;
  while (true) {
    mpz_fdiv_q(f.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    mpz_add_ui(f.get_mpz_t(), f.get_mpz_t(), 1);  // f + 1, the smallest integer above lo
    if (bounded) mpz_mul(t.get_mpz_t(), f.get_mpz_t(), d.get_mpz_t());
    if (!bounded || t < c) {
      // Fold x = q + 1/x back from x = f + 1, as p/r (continued-fraction convergents are in lowest terms).
      Integer p = f, r = 1;
      for (auto it = quotients.rbegin(); it != quotients.rend(); ++it) {
        mpz_addmul(r.get_mpz_t(), it->get_mpz_t(), p.get_mpz_t());
        mpz_swap(p.get_mpz_t(), r.get_mpz_t());
      }
      return make_rational(p, r);
    }
    mpz_sub_ui(f.get_mpz_t(), f.get_mpz_t(), 1);  // back to floor(lo)
    // (lo, hi) := (1 / (hi - f), 1 / (lo - f)) = (d / (c - f d), b / (a - f b)).
    mpz_submul(c.get_mpz_t(), f.get_mpz_t(), d.get_mpz_t());  // c - f d > 0
    mpz_submul(a.get_mpz_t(), f.get_mpz_t(), b.get_mpz_t());  // a - f b >= 0
    quotients.push_back(f);
    bounded = sgn(a) != 0;
    mpz_swap(a.get_mpz_t(), d.get_mpz_t());  // a = d, d = a - f b
    mpz_swap(b.get_mpz_t(), c.get_mpz_t());  // b = c - f d, c = b
  }
}

}  // namespace

Rational simplest_rational_in(const Rational& lo, const Rational& hi) {
  if (!(lo < hi)) {
    throw std::invalid_argument("simplest_rational_in: empty interval (" + exact_string(lo) + ", " +
                                exact_string(hi) + ")");
  }
  if (sgn(lo) < 0 && sgn(hi) > 0) return Rational(0);
  if (sgn(hi) <= 0) return -simplest_nonnegative(-hi, Rational(-lo));
  return simplest_nonnegative(lo, hi);
}

}  // namespace hsx
