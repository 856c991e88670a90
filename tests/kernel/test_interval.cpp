// Certified intervals (containment of exact results) and one-root numbers (exact sign and comparison).
#include <hsx/kernel/interval.hpp>
#include <hsx/kernel/one_root.hpp>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <cmath>

using hsx::Integer;
using hsx::Interval;
using hsx::OneRoot;
using hsx::Rational;

namespace {

Rational lo_q(const Interval& i) {
  Rational r;
  mpfr_get_q(r.get_mpq_t(), i.lo());
  return r;
}
Rational hi_q(const Interval& i) {
  Rational r;
  mpfr_get_q(r.get_mpq_t(), i.hi());
  return r;
}
bool contains(const Interval& i, const Rational& x) { return lo_q(i) <= x && x <= hi_q(i); }
/// [lo, hi] of `inner` inside `outer`
bool nested(const Interval& inner, const Interval& outer) {
  return lo_q(outer) <= lo_q(inner) && hi_q(inner) <= hi_q(outer);
}

Rational make_q(long n, long d, int shift) {
  Rational r = hsx::make_rational(Integer(n), Integer(d == 0 ? 1 : d));
  const int s = shift % 120;
  const Rational p(Integer(1) << static_cast<unsigned>(s < 0 ? -s : s));
  return s < 0 ? Rational(r / p) : Rational(r * p);
}

/// An interval around `center` widened by a low-precision rounding of `spread` (may straddle 0).
Interval wide(const Rational& center, const Rational& spread, mpfr_prec_t bits) {
  const Interval s(spread, 2);
  return Interval(center, bits) + (s - s);
}

}  // namespace

TEST_CASE("Interval basics", "[interval]") {
  const Interval third(Rational(1, 3), 64);
  CHECK(third.precision() == 64);
  CHECK(contains(third, Rational(1, 3)));
  CHECK(third.lo_double() <= 1.0 / 3.0);
  CHECK(third.hi_double() >= 1.0 / 3.0);
  CHECK(third.width() > 0);
  CHECK(third.certain_sign() == 1);
  CHECK((-third).certain_sign() == -1);
  CHECK((third - third).contains_zero());
  const Interval exact(Rational(3, 4), 64);
  CHECK(exact.width() == 0);
  CHECK(exact.mid_double() == 0.75);
  CHECK(Interval(Rational(0), 64).certain_sign() == 0);
  CHECK_THROWS_AS(third / (third - third), std::domain_error);
  // copies and moves keep the value
  Interval a = third;
  Interval b = std::move(a);
  a = b;
  CHECK(nested(a, third));
  CHECK(nested(third, a));
  b = Interval(Rational(5), 16);
  CHECK(contains(b, Rational(5)));
  CHECK(third.mid_decimal(10) == "0.3333333333");
}

TEST_CASE("Interval: exact results of + - * / lie in the enclosure", "[interval][property]") {
  rc::prop("point operands", [](long an, long ad, int as, long bn, long bd, int bs, unsigned bits_raw) {
    const mpfr_prec_t bits = 2 + bits_raw % 200;
    const Rational a = make_q(an, ad, as), b = make_q(bn, bd, bs);
    const Interval A(a, bits), B(b, bits);
    RC_ASSERT(contains(A, a));
    RC_ASSERT(contains(A + B, Rational(a + b)));
    RC_ASSERT(contains(A - B, Rational(a - b)));
    RC_ASSERT(contains(A * B, Rational(a * b)));
    RC_ASSERT(contains(-A, Rational(-a)));
    if (!B.contains_zero()) RC_ASSERT(contains(A / B, Rational(a / b)));
  });
  rc::prop("wide operands (all sign cases): every corner product/quotient is enclosed",
           [](long an, long ad, int as, long bn, long bd, int bs, long sa, long sb, unsigned bits_raw) {
             const mpfr_prec_t bits = 2 + bits_raw % 100;
             const Interval A = wide(make_q(an, ad, as), Rational(sa), bits);
             const Interval B = wide(make_q(bn, bd, bs), Rational(sb), bits);
             const Rational xs[2] = {lo_q(A), hi_q(A)};
             const Rational ys[2] = {lo_q(B), hi_q(B)};
             const Interval P = A * B, S = A + B, D = A - B;
             for (const Rational& x : xs) {
               for (const Rational& y : ys) {
                 RC_ASSERT(contains(P, Rational(x * y)));
                 RC_ASSERT(contains(S, Rational(x + y)));
                 RC_ASSERT(contains(D, Rational(x - y)));
               }
             }
             // an interior point too
             const Rational xm = (xs[0] + xs[1]) / 2, ym = (ys[0] * 2 + ys[1]) / 3;
             RC_ASSERT(contains(P, Rational(xm * ym)));
             if (!B.contains_zero()) {
               const Interval Q = A / B;
               for (const Rational& x : xs)
                 for (const Rational& y : ys) RC_ASSERT(contains(Q, Rational(x / y)));
               RC_ASSERT(contains(Q, Rational(xm / ym)));
             }
           });
}

TEST_CASE("Interval: sqrt, asin and pi enclosures", "[interval][property]") {
  rc::prop("sqrt encloses sqrt(q): lo^2 <= q <= hi^2", [](long n, long d, int s, unsigned bits_raw) {
    const mpfr_prec_t bits = 2 + bits_raw % 300;
    const Rational q = abs(make_q(n, d, s));
    const Interval r = Interval::sqrt(Interval(q, bits));
    RC_ASSERT(sgn(lo_q(r)) >= 0);
    RC_ASSERT(lo_q(r) * lo_q(r) <= q);
    RC_ASSERT(hi_q(r) * hi_q(r) >= q);
  });
  // pi at low precision contains pi at high precision
  CHECK(nested(Interval::pi(400), Interval::pi(20)));
  CHECK(nested(Interval::pi(400), Interval::pi(64)));
  CHECK(Interval::pi(64).lo_double() <= M_PI);
  CHECK(Interval::pi(64).hi_double() >= M_PI);
  // asin(1/2) = pi/6, asin(1) = pi/2, asin clamps out-of-range ends
  const Interval six(Rational(6), 400);
  CHECK(nested(Interval::pi(400) / six, Interval::asin(Interval(Rational(1, 2), 64))));
  const Interval two(Rational(2), 400);
  CHECK(nested(Interval::pi(400) / two, Interval::asin(Interval(Rational(1), 64))));
  const Interval over = Interval(Rational(1), 64) + Interval(Rational(1, 1000), 64);
  CHECK(nested(Interval::pi(400) / two, Interval::asin(over)));
  CHECK(Interval::sqrt(-Interval(Rational(1), 64)).certain_sign() == 0);
}

TEST_CASE("Interval::rational_between is strictly between", "[interval][property]") {
  rc::prop("a.hi < r < b.lo", [](long an, long ad, long bn, long bd, unsigned bits_raw) {
    const mpfr_prec_t bits = 2 + bits_raw % 80;
    Rational a = make_q(an, ad, 0), b = make_q(bn, bd, 0);
    if (a > b) std::swap(a, b);
    const Interval A(a, bits), B(b, bits);
    RC_PRE(lo_q(B) > hi_q(A));
    const Rational r = Interval::rational_between(A, B);
    RC_ASSERT(hi_q(A) < r);
    RC_ASSERT(r < lo_q(B));
  });
  const Interval one(Rational(1), 64);
  CHECK_THROWS(Interval::rational_between(one, one));
}

// ---------------------------------------------------------------------------------------------------------------

TEST_CASE("OneRoot normalises, prints and signs exactly", "[one_root]") {
  CHECK(OneRoot(Rational(1), Rational(2), Rational(5)).exact_string() == "1 + 2*sqrt(5)");
  CHECK(OneRoot(Rational(0), Rational(-1, 2), Rational(3)).exact_string() == "-1/2*sqrt(3)");
  CHECK(OneRoot(Rational(3, 2)).exact_string() == "3/2");
  CHECK(OneRoot(Rational(1), Rational(-1), Rational(2)).exact_string() == "1 - sqrt(2)");
  CHECK(OneRoot(Rational(-1), Rational(1), Rational(1, 2)).exact_string() == "-1 + sqrt(1/2)");
  CHECK(hsx::OneRootPoint(OneRoot(Rational(1)), OneRoot(Rational(0), Rational(1), Rational(2))).exact_string() ==
        "[1, sqrt(2)]");
  // perfect squares fold: sqrt(9/4) = 3/2, sqrt(4) = 2
  const OneRoot folded(Rational(0), Rational(1), Rational(9, 4));
  CHECK(folded.is_rational());
  CHECK(folded.a0 == Rational(3, 2));
  CHECK(folded.exact_string() == "3/2");
  const OneRoot five(Rational(1), Rational(2), Rational(4));
  CHECK(five.is_rational());
  CHECK(five.a0 == 5);
  CHECK(OneRoot(Rational(7), Rational(0), Rational(3)).root == 0);
  CHECK_THROWS_AS(OneRoot(Rational(0), Rational(1), Rational(-2)), std::domain_error);
  // normalise() on hand-built values
  OneRoot h;
  h.a0 = 1;
  h.a1 = -3;
  h.root = Rational(1, 9);
  h.normalise();
  CHECK(h.is_rational());
  CHECK(h.a0 == 0);

  CHECK(OneRoot(Rational(1), Rational(-1), Rational(2)).sign() == -1);
  CHECK(OneRoot(Rational(-1), Rational(1), Rational(2)).sign() == 1);
  CHECK(OneRoot(Rational(3, 2), Rational(-1), Rational(2)).sign() == 1);      // 1.5 - 1.414
  CHECK(OneRoot(Rational(7, 5), Rational(-1), Rational(2)).sign() == -1);     // 1.4 - 1.414
  CHECK(OneRoot(Rational(0), Rational(0), Rational(0)).sign() == 0);
  CHECK(OneRoot(Rational(-2), Rational(0), Rational(0)).sign() == -1);
  CHECK(OneRoot(Rational(0), Rational(-2), Rational(7)).sign() == -1);
  // the sign survives a hand-built unnormalised perfect square root
  OneRoot u;
  u.a0 = 3;
  u.a1 = -2;
  u.root = Rational(9, 4);
  CHECK(u.sign() == 0);
  CHECK(std::abs(OneRoot(Rational(1), Rational(1), Rational(2)).to_double() - (1 + std::sqrt(2.0))) < 1e-15);
  CHECK(OneRoot(Rational(1), Rational(1), Rational(2)).enclose(64).certain_sign() == 1);
}

TEST_CASE("OneRoot compare with equal and different roots", "[one_root]") {
  const OneRoot s2(Rational(0), Rational(1), Rational(2));
  const OneRoot s8(Rational(0), Rational(1), Rational(8));
  const OneRoot two_s2(Rational(0), Rational(2), Rational(2));
  CHECK(hsx::compare(s8, two_s2) == 0);
  CHECK(s8 == two_s2);
  CHECK(s2 < s8);
  CHECK(hsx::compare(s8, s2) == 1);
  // 1 + sqrt(2) = 2.414 < sqrt(6) = 2.449
  CHECK(hsx::compare(OneRoot(Rational(1), Rational(1), Rational(2)), OneRoot(Rational(0), Rational(1), Rational(6))) ==
        -1);
  // 1 + sqrt(2) vs rational 12/5 = 2.4 and 5/2
  CHECK(hsx::compare(OneRoot(Rational(1), Rational(1), Rational(2)), OneRoot(Rational(12, 5))) == 1);
  CHECK(hsx::compare(OneRoot(Rational(5, 2)), OneRoot(Rational(1), Rational(1), Rational(2))) == 1);
  // (1 + sqrt(3))^2 = 4 + 2 sqrt(3): 1 + sqrt(3) vs sqrt(4 + 2 sqrt 3) can't be a one-root; instead: sqrt(3) - 1 vs
  // sqrt(2 - sqrt(3))*sqrt(2) ... keep to one-roots: 3 - sqrt(2) vs 2 + sqrt(1/2) (1.586 vs 2.707)
  CHECK(hsx::compare(OneRoot(Rational(3), Rational(-1), Rational(2)), OneRoot(Rational(2), Rational(1), Rational(1, 2))) ==
        -1);
  // equal values, different radicands: 1 + sqrt(1/2) == 1 + 1/2*sqrt(2)
  CHECK(OneRoot(Rational(1), Rational(1), Rational(1, 2)) == OneRoot(Rational(1), Rational(1, 2), Rational(2)));
}

TEST_CASE("OneRoot compare agrees with high-precision enclosures", "[one_root][property]") {
  rc::prop("exact compare vs 1000-bit enclosure", [](int a0, int a1, unsigned r, int b0, int b1, unsigned s) {
    const OneRoot a(hsx::make_rational(a0 % 50, 7), hsx::make_rational(a1 % 20, 3), Rational(r % 40));
    const OneRoot b(hsx::make_rational(b0 % 50, 7), hsx::make_rational(b1 % 20, 3), Rational(s % 40));
    const int c = hsx::compare(a, b);
    RC_ASSERT(hsx::compare(b, a) == -c);
    RC_ASSERT(hsx::compare(a, a) == 0);
    const Interval d = a.enclose(1000) - b.enclose(1000);
    if (d.certain_sign() != 0) RC_ASSERT(c == d.certain_sign());
    if (c == 0) RC_ASSERT(d.contains_zero());
  });
}
