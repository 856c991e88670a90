// Certified MPFR intervals: lower ends rounded toward -inf (MPFR_RNDD), upper ends toward +inf (MPFR_RNDU).
// Every operation is monotone in each argument on the region used, or evaluated at all end-point combinations, so
// the exact result of the operation on any points of the operands lies in the result (see proofs/measures.md).
#include <hsx/kernel/interval.hpp>

#include <algorithm>
#include <stdexcept>

namespace hsx {

namespace {

mpfr_prec_t clamp_prec(mpfr_prec_t p) { return std::max<mpfr_prec_t>(p, MPFR_PREC_MIN); }

/// RAII scratch value.
struct Scratch {
  mpfr_t v;
  explicit Scratch(mpfr_prec_t p) { mpfr_init2(v, p); }
  ~Scratch() { mpfr_clear(v); }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
};

mpfr_prec_t joint_prec(const Interval& a, const Interval& b) { return std::max(a.precision(), b.precision()); }

Rational to_rational(const mpfr_t x) {
  Rational q;
  mpfr_get_q(q.get_mpq_t(), x);  // exact: every finite binary float is a dyadic rational
  return q;
}

}  // namespace

Interval::Interval(mpfr_prec_t precision_bits) {
  const mpfr_prec_t p = clamp_prec(precision_bits);
  mpfr_init2(lo_, p);
  mpfr_init2(hi_, p);
  mpfr_set_zero(lo_, 1);
  mpfr_set_zero(hi_, 1);
}

Interval::Interval(const Rational& q, mpfr_prec_t precision_bits) {
  const mpfr_prec_t p = clamp_prec(precision_bits);
  mpfr_init2(lo_, p);
  mpfr_init2(hi_, p);
  mpfr_set_q(lo_, q.get_mpq_t(), MPFR_RNDD);
  mpfr_set_q(hi_, q.get_mpq_t(), MPFR_RNDU);
}

Interval Interval::from_ends(const mpfr_t lo, const mpfr_t hi) {
  Interval r(std::max(mpfr_get_prec(lo), mpfr_get_prec(hi)));
  mpfr_set(r.lo_, lo, MPFR_RNDD);  // exact: the target precision is at least the source's
  mpfr_set(r.hi_, hi, MPFR_RNDU);
  return r;
}

Interval::Interval(const Interval& other) {
  mpfr_init2(lo_, mpfr_get_prec(other.lo_));
  mpfr_init2(hi_, mpfr_get_prec(other.hi_));
  mpfr_set(lo_, other.lo_, MPFR_RNDD);
  mpfr_set(hi_, other.hi_, MPFR_RNDU);
}

Interval::Interval(Interval&& other) noexcept {
  // Leave `other` a valid (tiny) interval; mpfr_init2 aborts rather than throws on allocation failure.
  mpfr_init2(lo_, MPFR_PREC_MIN);
  mpfr_init2(hi_, MPFR_PREC_MIN);
  mpfr_set_zero(lo_, 1);
  mpfr_set_zero(hi_, 1);
  mpfr_swap(lo_, other.lo_);
  mpfr_swap(hi_, other.hi_);
}

Interval& Interval::operator=(const Interval& other) {
  if (this != &other) {
    mpfr_set_prec(lo_, mpfr_get_prec(other.lo_));
    mpfr_set_prec(hi_, mpfr_get_prec(other.hi_));
    mpfr_set(lo_, other.lo_, MPFR_RNDD);
    mpfr_set(hi_, other.hi_, MPFR_RNDU);
  }
  return *this;
}

Interval& Interval::operator=(Interval&& other) noexcept {
  mpfr_swap(lo_, other.lo_);
  mpfr_swap(hi_, other.hi_);
  return *this;
}

Interval::~Interval() {
  mpfr_clear(lo_);
  mpfr_clear(hi_);
}

mpfr_prec_t Interval::precision() const { return std::max(mpfr_get_prec(lo_), mpfr_get_prec(hi_)); }

double Interval::lo_double() const { return mpfr_get_d(lo_, MPFR_RNDD); }
double Interval::hi_double() const { return mpfr_get_d(hi_, MPFR_RNDU); }

double Interval::mid_double() const {
  Scratch m(precision() + 1);
  mpfr_add(m.v, lo_, hi_, MPFR_RNDN);  // exact at precision+1 unless exponents differ a lot; display only
  mpfr_div_2ui(m.v, m.v, 1, MPFR_RNDN);
  return mpfr_get_d(m.v, MPFR_RNDN);
}

int Interval::certain_sign() const {
  if (mpfr_sgn(lo_) > 0) return 1;
  if (mpfr_sgn(hi_) < 0) return -1;
  return 0;
}

double Interval::width() const {
  Scratch w(precision());
  mpfr_sub(w.v, hi_, lo_, MPFR_RNDU);
  return mpfr_get_d(w.v, MPFR_RNDU);
}

Interval operator+(const Interval& a, const Interval& b) {
  Interval r(joint_prec(a, b));
  mpfr_add(r.lo_, a.lo_, b.lo_, MPFR_RNDD);
  mpfr_add(r.hi_, a.hi_, b.hi_, MPFR_RNDU);
  return r;
}

Interval operator-(const Interval& a, const Interval& b) {
  Interval r(joint_prec(a, b));
  mpfr_sub(r.lo_, a.lo_, b.hi_, MPFR_RNDD);
  mpfr_sub(r.hi_, a.hi_, b.lo_, MPFR_RNDU);
  return r;
}

Interval operator*(const Interval& a, const Interval& b) {
  const mpfr_prec_t p = joint_prec(a, b);
  Interval r(p);
  // Product of intervals = [min, max] over the four end-point products: each computed twice, rounded down for the
  // minimum and up for the maximum. Sign-case shortcuts are an optimisation for the common non-negative case.
  if (mpfr_sgn(a.lo_) >= 0 && mpfr_sgn(b.lo_) >= 0) {
    mpfr_mul(r.lo_, a.lo_, b.lo_, MPFR_RNDD);
    mpfr_mul(r.hi_, a.hi_, b.hi_, MPFR_RNDU);
    return r;
  }
  const mpfr_srcptr xs[2] = {a.lo_, a.hi_};
  const mpfr_srcptr ys[2] = {b.lo_, b.hi_};
  Scratch t(p);
  bool first = true;
  for (mpfr_srcptr x : xs) {
    for (mpfr_srcptr y : ys) {
      mpfr_mul(t.v, x, y, MPFR_RNDD);
      if (first || mpfr_less_p(t.v, r.lo_)) mpfr_set(r.lo_, t.v, MPFR_RNDD);
      mpfr_mul(t.v, x, y, MPFR_RNDU);
      if (first || mpfr_greater_p(t.v, r.hi_)) mpfr_set(r.hi_, t.v, MPFR_RNDU);
      first = false;
    }
  }
  return r;
}

Interval operator/(const Interval& a, const Interval& b) {
  if (b.contains_zero()) throw std::domain_error("Interval division by an interval containing 0");
  const mpfr_prec_t p = joint_prec(a, b);
  Interval r(p);
  const mpfr_srcptr xs[2] = {a.lo_, a.hi_};
  const mpfr_srcptr ys[2] = {b.lo_, b.hi_};
  Scratch t(p);
  bool first = true;
  for (mpfr_srcptr x : xs) {
    for (mpfr_srcptr y : ys) {
      mpfr_div(t.v, x, y, MPFR_RNDD);
      if (first || mpfr_less_p(t.v, r.lo_)) mpfr_set(r.lo_, t.v, MPFR_RNDD);
      mpfr_div(t.v, x, y, MPFR_RNDU);
      if (first || mpfr_greater_p(t.v, r.hi_)) mpfr_set(r.hi_, t.v, MPFR_RNDU);
      first = false;
    }
  }
  return r;
}

Interval Interval::operator-() const {
  Interval r(precision());
  mpfr_neg(r.lo_, hi_, MPFR_RNDD);  // exact
  mpfr_neg(r.hi_, lo_, MPFR_RNDU);
  return r;
}

Interval Interval::sqrt(const Interval& a) {
  Interval r(a.precision());
  if (mpfr_sgn(a.lo_) > 0)
    mpfr_sqrt(r.lo_, a.lo_, MPFR_RNDD);
  else
    mpfr_set_zero(r.lo_, 1);
  if (mpfr_sgn(a.hi_) > 0)
    mpfr_sqrt(r.hi_, a.hi_, MPFR_RNDU);
  else
    mpfr_set_zero(r.hi_, 1);
  return r;
}

Interval Interval::asin(const Interval& a) {
  const mpfr_prec_t p = a.precision();
  Interval r(p);
  Scratch t(p);
  // asin is increasing on [-1, 1]; clamp the ends into the domain first.
  mpfr_set(t.v, a.lo_, MPFR_RNDD);
  if (mpfr_cmp_si(t.v, -1) < 0) mpfr_set_si(t.v, -1, MPFR_RNDD);
  if (mpfr_cmp_si(t.v, 1) > 0) mpfr_set_si(t.v, 1, MPFR_RNDD);
  mpfr_asin(r.lo_, t.v, MPFR_RNDD);
  mpfr_set(t.v, a.hi_, MPFR_RNDU);
  if (mpfr_cmp_si(t.v, -1) < 0) mpfr_set_si(t.v, -1, MPFR_RNDU);
  if (mpfr_cmp_si(t.v, 1) > 0) mpfr_set_si(t.v, 1, MPFR_RNDU);
  mpfr_asin(r.hi_, t.v, MPFR_RNDU);
  return r;
}

Interval Interval::pi(mpfr_prec_t precision_bits) {
  Interval r(precision_bits);
  mpfr_const_pi(r.lo_, MPFR_RNDD);
  mpfr_const_pi(r.hi_, MPFR_RNDU);
  return r;
}

Rational Interval::rational_between(const Interval& a, const Interval& b) {
  if (!mpfr_less_p(a.hi_, b.lo_)) throw std::invalid_argument("Interval::rational_between: a.hi >= b.lo");
  // The exact midpoint of two dyadic rationals is a dyadic rational strictly between them.
  Rational m = to_rational(a.hi_) + to_rational(b.lo_);
  m /= 2;
  return m;
}

std::string Interval::mid_decimal(int significant) const {
  Rational m = to_rational(lo_) + to_rational(hi_);
  m /= 2;
  return decimal_string(m, significant);
}

}  // namespace hsx
