// One-root numbers a0 + a1*sqrt(root): exact sign and comparison by squaring with sign cases
// (see proofs/measures.md, "One-root numbers").
#include <hsx/kernel/one_root.hpp>

#include <stdexcept>

namespace hsx {

namespace {

/// sqrt(q) when q >= 0 is the square of a rational (canonical q = p/d is a square iff p and d are), else nullopt.
std::optional<Rational> rational_sqrt(const Rational& q) {
  if (sgn(q) < 0) return std::nullopt;
  const Integer& p = q.get_num();
  const Integer& d = q.get_den();
  if (!mpz_perfect_square_p(p.get_mpz_t()) || !mpz_perfect_square_p(d.get_mpz_t())) return std::nullopt;
  Integer sp, sd;
  mpz_sqrt(sp.get_mpz_t(), p.get_mpz_t());
  mpz_sqrt(sd.get_mpz_t(), d.get_mpz_t());
  return make_rational(sp, sd);
}

/// Sign of a0 + a1*sqrt(r) for r >= 0.
int sign_of(const Rational& a0, const Rational& a1, const Rational& r) {
  const int s0 = sgn(a0);
  const int s1 = (sgn(r) == 0) ? 0 : sgn(a1);
  if (s1 == 0) return s0;
  if (s0 == 0 || s0 == s1) return s1;
  // Opposite signs: the term of larger magnitude wins; compare squares a0^2 and a1^2*r.
  const int c = cmp(a0 * a0, a1 * a1 * r);
  if (c > 0) return s0;
  if (c < 0) return s1;
  return 0;
}

}  // namespace

OneRoot::OneRoot(const Rational& a0_, const Rational& a1_, const Rational& root_) : a0(a0_), a1(a1_), root(root_) {
  normalise();
}

void OneRoot::normalise() {
  if (sgn(root) < 0) throw std::domain_error("OneRoot: negative radicand " + hsx::exact_string(root));
  if (sgn(a1) == 0 || sgn(root) == 0) {
    a1 = 0;
    root = 0;
    return;
  }
  if (auto s = rational_sqrt(root)) {
    a0 += a1 * *s;
    a1 = 0;
    root = 0;
  }
}

int OneRoot::sign() const { return sign_of(a0, a1, root); }

Interval OneRoot::enclose(mpfr_prec_t precision_bits) const {
  Interval v(a0, precision_bits);
  if (is_rational()) return v;
  // a1*sqrt(root) = sign(a1) * sqrt(a1^2 * root): one rounding instead of two.
  Interval t = Interval::sqrt(Interval(Rational(a1 * a1 * root), precision_bits));
  return sgn(a1) > 0 ? v + t : v - t;
}

std::string OneRoot::exact_string() const {
  if (is_rational()) return hsx::exact_string(a0);
  const Rational mag = abs(a1);
  std::string radical = "sqrt(" + hsx::exact_string(root) + ")";
  if (mag != 1) radical = hsx::exact_string(mag) + "*" + radical;
  if (sgn(a0) == 0) return (sgn(a1) < 0 ? "-" : "") + radical;
  return hsx::exact_string(a0) + (sgn(a1) < 0 ? " - " : " + ") + radical;
}

double OneRoot::to_double() const {
  if (is_rational()) return a0.get_d();
  return enclose(80).mid_double();
}

int compare(const OneRoot& a, const OneRoot& b) {
  // Same root (or at most one radical): the difference is itself a one-root number.
  if (b.is_rational()) return sign_of(a.a0 - b.a0, a.a1, a.root);
  if (a.is_rational()) return sign_of(a.a0 - b.a0, -b.a1, b.root);
  if (a.root == b.root) return sign_of(a.a0 - b.a0, a.a1 - b.a1, a.root);
  // a - b = x + y with x = (a0 - b0) + a1*sqrt(r), y = -b1*sqrt(t). If x and y have the same sign (or one is 0),
  // that is the sign; otherwise the one of larger magnitude decides: sign(x^2 - y^2), where
  // x^2 - y^2 = (p^2 + q^2 r - s^2 t) + 2pq*sqrt(r) is a one-root number.
  const Rational p = a.a0 - b.a0;
  const Rational& q = a.a1;
  const Rational& r = a.root;
  const Rational s = -b.a1;
  const Rational& t = b.root;
  const int sx = sign_of(p, q, r);
  const int sy = sgn(s);
  if (sx == 0) return sy;
  if (sy == 0 || sx == sy) return sx;
  const int c = sign_of(p * p + q * q * r - s * s * t, 2 * p * q, r);
  if (c > 0) return sx;
  if (c < 0) return sy;
  return 0;
}

std::string OneRootPoint::exact_string() const { return "[" + x.exact_string() + ", " + y.exact_string() + "]"; }

}  // namespace hsx
