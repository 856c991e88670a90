// Exact rationals: parsing (accept/reject tables, hostile input), exact and decimal printing.
#include <hsx/kernel/rational.hpp>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <stdexcept>
#include <string>
#include <vector>
#include <utility>

using hsx::NumberLimits;
using hsx::parse_rational;
using hsx::Rational;

namespace {

Rational q(const char* s) {
  Rational r(s);
  r.canonicalize();
  return r;
}

}  // namespace

TEST_CASE("make_rational canonicalises", "[rational]") {
  const Rational r = hsx::make_rational(hsx::Integer(6), hsx::Integer(-4));
  CHECK(r.get_num() == -3);
  CHECK(r.get_den() == 2);
  CHECK(r == q("-3/2"));
  CHECK(sgn(hsx::make_rational(hsx::Integer(0), hsx::Integer(7))) == 0);
}

TEST_CASE("parse_rational accepts exact spellings", "[rational][parse]") {
  struct Case {
    const char* text;
    const char* value;  // mpq text
  };
  const std::vector<Case> cases = {
      {"12", "12"},        {"-12", "-12"},       {"+12", "12"},         {"0", "0"},
      {"-0", "0"},         {"007", "7"},         {"0.25", "1/4"},       {"0.1", "1/10"},
      {".5", "1/2"},       {"5.", "5"},          {"-.5", "-1/2"},       {"1e-3", "1/1000"},
      {"2.5E+4", "25000"}, {"2.5e4", "25000"},   {"1E0", "1"},          {"-1.25e-2", "-1/80"},
      {"7/3", "7/3"},      {"-7/3", "-7/3"},     {"+7/3", "7/3"},       {"6/4", "3/2"},
      {"0/5", "0"},        {"10/1", "10"},       {"000.000", "0"},      {"0e99", "0"},
      {"123.456e1", "30864/25"}, {"1e-0", "1"},    {"00001/00002", "1/2"},
  };
  for (const auto& c : cases) {
    INFO(c.text);
    std::string why;
    const auto r = parse_rational(c.text, &why);
    REQUIRE(r.has_value());
    CHECK(*r == q(c.value));
    // canonical: numerator and denominator coprime, denominator positive
    CHECK(r->get_str() == q(c.value).get_str());
  }
}

TEST_CASE("parse_rational rejects non-numbers with a reason", "[rational][parse]") {
  const std::vector<const char*> bad = {
      "",     " ",     " 1",    "1 ",    "1 2",   "inf",   "-inf",  "Infinity", "nan",   "NaN",
      "0x1A", "0X10",  "1e",    "1e+",   "e5",    ".",     "-",     "+",        "--1",   "+-1",
      "1..2", "1.2.3", "1/0",   "1/",    "/2",    "1.5/2", "1/2.5", "1/-2",     "1/2/3", "1e3/2",
      "abc",  "1a",    "1,5",   "١",     "1e--3", "1e3.5", "1/+2",  "-/2",      "½",     "1_000",
  };
  for (const char* text : bad) {
    INFO(std::string("text: '") + text + "'");
    std::string why;
    CHECK_FALSE(parse_rational(text, &why).has_value());
    CHECK_FALSE(why.empty());
  }
  std::string why;
  CHECK_FALSE(parse_rational("1/0", &why));
  CHECK(why == "zero denominator");
  CHECK_FALSE(parse_rational("inf", &why));
  CHECK(why == "not a finite number");
  CHECK_FALSE(parse_rational("0x10", &why));
  CHECK(why.find("hexadecimal") != std::string::npos);
  CHECK_FALSE(parse_rational("1.5/2", &why));
  CHECK(why.find("fraction") != std::string::npos);
  // no reason pointer: still fine
  CHECK_FALSE(parse_rational("nan"));
}

TEST_CASE("parse_rational enforces the number limits", "[rational][parse]") {
  std::string why;
  // Hostile exponents fail before any power of ten is computed, and without overflow.
  CHECK_FALSE(parse_rational("1e99999999999999999999", &why));
  CHECK(why.find("exponent") != std::string::npos);
  CHECK_FALSE(parse_rational("1e-99999999999999999999999999999999999", &why));
  CHECK(why.find("exponent") != std::string::npos);
  CHECK_FALSE(parse_rational("1e9223372036854775808", &why));
  CHECK_FALSE(parse_rational("1e20001", &why));
  CHECK_FALSE(parse_rational("1e-20001", &why));
  // The limit itself is accepted.
  const auto big = parse_rational("1e20000");
  REQUIRE(big);
  CHECK(big->get_num().get_str().size() == 20001);
  const auto small = parse_rational("1e-20000");
  REQUIRE(small);
  CHECK(small->get_den().get_str().size() == 20001);
  // Leading zeros in the exponent do not count against the limit.
  const auto padded = parse_rational("1e0000000000000000000000000003");
  REQUIRE(padded);
  CHECK(*padded == 1000);
  // Custom limits.
  NumberLimits tight;
  tight.max_chars = 5;
  tight.max_exponent = 3;
  CHECK(parse_rational("12345", nullptr, tight));
  CHECK_FALSE(parse_rational("123456", &why, tight));
  CHECK(why.find("too long") != std::string::npos);
  CHECK(parse_rational("1e3", nullptr, tight));
  CHECK_FALSE(parse_rational("1e4", &why, tight));
  NumberLimits zero_exp;
  zero_exp.max_exponent = 0;
  CHECK(parse_rational("1e0", nullptr, zero_exp));
  CHECK_FALSE(parse_rational("1e5", nullptr, zero_exp));
  // Too many characters.
  CHECK_FALSE(parse_rational(std::string(20001, '1'), &why));
  CHECK(why.find("too long") != std::string::npos);
}

TEST_CASE("parse_rational handles 10,000-digit numbers", "[rational][parse]") {
  std::string digits(10000, '0');
  for (std::size_t i = 0; i < digits.size(); ++i) digits[i] = static_cast<char>('0' + (i * 7 + 3) % 10);
  digits[0] = '9';
  const auto n = parse_rational(digits);
  REQUIRE(n);
  CHECK(n->get_num().get_str() == digits);
  const auto frac = parse_rational("-" + digits + "/" + digits.substr(0, 5000));
  REQUIRE(frac);
  CHECK(sgn(*frac) < 0);
  const auto dec = parse_rational("0." + digits);
  REQUIRE(dec);
  CHECK(*dec < 1);
  CHECK(*dec > Rational(9, 10));
  // exact: multiplying back by 10^10000 gives the digits
  hsx::Integer p;
  mpz_ui_pow_ui(p.get_mpz_t(), 10, 10000);
  CHECK(Rational(*dec * p) == *n);
}

TEST_CASE("exact_string", "[rational]") {
  CHECK(hsx::exact_string(Rational(3)) == "3");
  CHECK(hsx::exact_string(q("-7/3")) == "-7/3");
  CHECK(hsx::exact_string(Rational(0)) == "0");
  CHECK(hsx::exact_string(hsx::make_rational(10, -4)) == "-5/2");
}

TEST_CASE("exact_string round-trips through parse_rational", "[rational][property]") {
  rc::prop("parse(exact_string(q)) == q", [](long n, long d, int shift) {
    RC_PRE(d != 0);
    Rational r = hsx::make_rational(hsx::Integer(n), hsx::Integer(d));
    const int s = shift % 200;
    if (s > 0) r *= Rational(hsx::Integer(1) << static_cast<unsigned>(s));
    const auto back = parse_rational(hsx::exact_string(r));
    RC_ASSERT(back.has_value());
    RC_ASSERT(*back == r);
  });
  rc::prop("parse(decimal_string(q, 60)) is within a relative 1e-59 of q", [](long n, long d) {
    RC_PRE(d != 0 && n != 0);
    const Rational r = hsx::make_rational(hsx::Integer(n), hsx::Integer(d));
    const auto back = parse_rational(hsx::decimal_string(r, 60));
    RC_ASSERT(back.has_value());
    const Rational err = abs(Rational(*back - r)) / abs(r);
    RC_ASSERT(err * Rational(hsx::Integer("100000000000000000000000000000000000000000000000000000000000")) <= 1);
  });
}

TEST_CASE("decimal_string rounds to nearest with the requested significant digits", "[rational][decimal]") {
  using hsx::decimal_string;
  CHECK(decimal_string(Rational(0)) == "0");
  CHECK(decimal_string(q("1/3"), 6) == "0.333333");
  CHECK(decimal_string(q("2/3"), 6) == "0.666667");
  CHECK(decimal_string(q("-2/3"), 6) == "-0.666667");
  CHECK(decimal_string(q("1/4")) == "0.25");
  CHECK(decimal_string(q("1/4"), 1) == "0.3");  // tie: half away from zero
  CHECK(decimal_string(q("-1/4"), 1) == "-0.3");
  CHECK(decimal_string(q("1/8"), 2) == "0.13");
  CHECK(decimal_string(q("3")) == "3");
  CHECK(decimal_string(q("100")) == "100");
  CHECK(decimal_string(q("123456"), 3) == "123000");
  CHECK(decimal_string(q("999999/1000000"), 3) == "1");
  CHECK(decimal_string(q("9995/10"), 3) == "1000");
  CHECK(decimal_string(q("99949/100"), 3) == "999");
  CHECK(decimal_string(q("1/1000000")) == "0.000001");
  CHECK(decimal_string(q("1/10000000")) == "1e-7");
  CHECK(decimal_string(q("3/20000000")) == "1.5e-7");
  CHECK(decimal_string(q("15/100000000000000000000000000000000000000000")) == "1.5e-40");
  CHECK(decimal_string(q("100000000000000000000")) == "100000000000000000000");      // 1e20
  CHECK(decimal_string(q("999999999999999999999")) == "999999999999999999999");      // < 1e21
  CHECK(decimal_string(q("1000000000000000000000")) == "1e21");
  CHECK(decimal_string(q("999999999999999999999"), 5) == "1e21");                    // rounds up across 1e21
  CHECK(decimal_string(q("-123456789012345678901234567890")) == "-1.2345678901234567890123456789e29");
  CHECK(decimal_string(q("1/7"), 30) == "0.142857142857142857142857142857");
  CHECK(decimal_string(q("22/7"), 10) == "3.142857143");
  CHECK(decimal_string(q("1/3"), 0) == "0.3");  // at least one digit
  CHECK(decimal_string(q("25/2"), 2) == "13");
  CHECK(decimal_string(q("123456/1000000000"), 3) == "0.000123");
  CHECK(decimal_string(q("1235/10000000"), 3) == "0.000124");
  // Huge and tiny magnitudes.
  const auto big = parse_rational("7e20000");
  REQUIRE(big);
  CHECK(decimal_string(*big) == "7e20000");
  const auto tiny = parse_rational("-25e-20000");
  REQUIRE(tiny);
  CHECK(decimal_string(*tiny) == "-2.5e-19999");
}

TEST_CASE("decimal_string is the nearest sig-digit decimal", "[rational][decimal][property]") {
  rc::prop("|parse(decimal(q, s)) - q| <= half an ulp of the last digit", [](long n, long d, unsigned s_raw) {
    RC_PRE(d != 0 && n != 0);
    const int s = 1 + static_cast<int>(s_raw % 25);
    const Rational r = hsx::make_rational(hsx::Integer(n), hsx::Integer(d));
    const auto back = parse_rational(hsx::decimal_string(r, s));
    RC_ASSERT(back.has_value());
    // 10^E <= |back| (after rounding) and the error is at most 1/2 * 10^(E - s + 1) where 10^E <= |r|.
    Rational mag = abs(r);
    long E = 0;
    while (mag >= 10) {
      mag /= 10;
      ++E;
    }
    while (mag < 1) {
      mag *= 10;
      --E;
    }
    Rational ulp = 1;
    const long k = E - s + 1;
    for (long i = 0; i < (k < 0 ? -k : k); ++i) ulp = (k < 0) ? Rational(ulp / 10) : Rational(ulp * 10);
    RC_ASSERT(abs(Rational(*back - r)) <= ulp / 2);
  });
}

TEST_CASE("simplest_rational_in: fixed cases", "[rational][simplest]") {
  using hsx::simplest_rational_in;
  CHECK(simplest_rational_in(q("0"), q("1")) == q("1/2"));
  CHECK(simplest_rational_in(q("1/3"), q("1/2")) == q("2/5"));
  CHECK(simplest_rational_in(q("-1/2"), q("1/3")) == 0);
  CHECK(simplest_rational_in(q("-7/2"), q("-3")) == q("-10/3"));
  CHECK(simplest_rational_in(q("2"), q("5")) == 3);          // open: 2 itself is excluded
  CHECK(simplest_rational_in(q("-5"), q("-2")) == -3);       // least absolute value among integers
  CHECK(simplest_rational_in(q("3"), q("31/10")) == q("34/11"));
  CHECK(simplest_rational_in(q("314159/100000"), q("314160/100000")) == q("355/113"));
  // a dyadic-midpoint-sized interval around 1/3 gives 1/3 back
  CHECK(simplest_rational_in(q("6148914691236517205/18446744073709551616"),
                             q("6148914691236517206/18446744073709551616")) == q("1/3"));
  CHECK_THROWS_AS(simplest_rational_in(q("1"), q("1")), std::invalid_argument);
  CHECK_THROWS_AS(simplest_rational_in(q("2"), q("1")), std::invalid_argument);
}

TEST_CASE("simplest_rational_in: inside, and no smaller denominator fits", "[rational][simplest][property]") {
  rc::prop("brute force over all smaller denominators", [] {
    const long n1 = *rc::gen::inRange(-2000, 2000), d1 = *rc::gen::inRange(1, 300);
    const long n2 = *rc::gen::inRange(-2000, 2000), d2 = *rc::gen::inRange(1, 300);
    Rational a = hsx::make_rational(hsx::Integer(n1), hsx::Integer(d1));
    Rational b = hsx::make_rational(hsx::Integer(n2), hsx::Integer(d2));
    RC_PRE(a != b);
    if (b < a) std::swap(a, b);
    const Rational x = hsx::simplest_rational_in(a, b);
    RC_ASSERT(a < x);
    RC_ASSERT(x < b);
    const hsx::Integer den = x.get_den();
    for (long d = 1; hsx::Integer(d) < den; ++d) {
      // the least n with n/d > a is floor(a*d) + 1; it must not be below b
      const Rational ad = a * Rational(d);
      hsx::Integer f;
      mpz_fdiv_q(f.get_mpz_t(), ad.get_num_mpz_t(), ad.get_den_mpz_t());
      RC_ASSERT(hsx::make_rational(f + 1, hsx::Integer(d)) >= b);
    }
    // among denominator-1 answers, the least absolute value
    if (den == 1 && sgn(x) != 0) {
      const Rational closer = x - Rational(sgn(x));
      RC_ASSERT(!(a < closer && closer < b));
    }
  });
}

TEST_CASE("simplest_rational_in: long ends, checked against the Stern-Brocot neighbours",
          "[rational][simplest][property]") {
  // Ends of 40 to 180 bits: below and above the 120 bits that the 128-bit descent takes. The answer p/r (r > 1)
  // is the simplest in (a, b) iff it is inside and its two Stern-Brocot parents, the fractions next to it among
  // denominators below r, are not: every fraction strictly between them has denominator at least r.
  const auto big = [](int bits) {
    hsx::Integer v = 1;
    for (int k = 0; k < bits; k += 30) {
      v <<= 30;
      v += *rc::gen::inRange(0, 1 << 30);
    }
    return v;
  };
  rc::prop("inside, parents outside", [&] {
    const int bits = *rc::gen::inRange(40, 180);
    const hsx::Integer den = big(bits), num = big(bits + *rc::gen::inRange(-8, 8)), width = big(bits / 2);
    Rational a = hsx::make_rational(num, den);
    Rational b = a + hsx::make_rational(width, den * den);  // a very short interval: r > 1 unless it holds an integer
    const bool negative = *rc::gen::arbitrary<bool>();
    if (negative) {
      std::swap(a, b);
      a = -a;
      b = -b;
    }
    const Rational x = hsx::simplest_rational_in(a, b);
    RC_ASSERT(a < x);
    RC_ASSERT(x < b);
    const Rational ax = negative ? -b : a, bx = negative ? -a : b, y = negative ? -x : x;  // mirrored to 0 < a < b
    const hsx::Integer p = y.get_num(), r = y.get_den();
    if (r == 1) {
      RC_ASSERT(Rational(p - 1) <= ax);
      return;
    }
    hsx::Integer g, s, t;
    mpz_gcdext(g.get_mpz_t(), s.get_mpz_t(), t.get_mpz_t(), p.get_mpz_t(), r.get_mpz_t());  // p s + r t = 1
    hsx::Integer r1;
    mpz_fdiv_r(r1.get_mpz_t(), s.get_mpz_t(), r.get_mpz_t());  // p r1 = 1 (mod r), 0 < r1 < r
    const hsx::Integer p1 = (p * r1 - 1) / r;                   // p r1 - p1 r = 1: the left parent p1/r1
    const Rational left = hsx::make_rational(p1, r1), right = hsx::make_rational(p - p1, r - r1);
    RC_ASSERT(left <= ax);
    RC_ASSERT(right >= bx);
  });
}
