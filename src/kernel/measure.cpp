// Measures: exact algebraic sums of square roots plus keyed special terms (nested radicals, arc angles).
// proofs/measures.md explains what is exact, what is only certified, and why.
//
// Representation of the algebraic part (the invariant that makes is_zero() exact):
//   every radicand k is a positive integer with no factor p^2 for a prime p < 1000, k is not a perfect square
//   unless k == 1, and no two radicands have a perfect-square product (equivalently: distinct square-free parts).
// A radicand is "proven square-free" when its factorisation over the primes below 1000 left a cofactor u that is
// 1, a prime (u < 1009^2, or a deterministic Miller-Rabin test for u < 2^64), or below 1009^3 and not a square
// (then u = p*q with distinct primes p, q >= 1009). Two distinct proven-square-free radicands never have a square
// product, so a new proven radicand only has to be checked against the (rare) unproven ones, kept in unsure_.
#include <hsx/kernel/measure.hpp>

#include "kernel/interval_nt.hpp"

#include <CGAL/Interval_nt.h>
#include <CGAL/gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace hsx {

const char* to_string(Order o) {
  switch (o) {
    case Order::Less: return "Less";
    case Order::Equal: return "Equal";
    case Order::Greater: return "Greater";
    case Order::Tie: return "Tie";
  }
  return "?";
}

namespace {

constexpr unsigned long kTrialBound = 1000;     // trial-divide by the primes below this
constexpr unsigned long kNextPrime = 1009;      // the first prime above kTrialBound
constexpr unsigned long long kNextPrimeCube = 1009ULL * 1009ULL * 1009ULL;
constexpr mpfr_prec_t kAlgebraicCeilingBits = mpfr_prec_t(1) << 20;
constexpr mpfr_prec_t kDecimalCapBits = 8192;

const std::vector<unsigned long>& small_primes() {
  static const std::vector<unsigned long> primes = [] {
    std::vector<unsigned long> out;
    std::vector<bool> composite(kTrialBound, false);
    for (unsigned long i = 2; i < kTrialBound; ++i) {
      if (composite[i]) continue;
      out.push_back(i);
      for (unsigned long j = i * i; j < kTrialBound; j += i) composite[j] = true;
    }
    return out;
  }();
  return primes;
}

// ---- deterministic primality for 64-bit integers: Miller-Rabin with the first 12 prime bases, which is exact
// for all n < 3.3e24 (Sorenson & Webster 2015; see proofs/measures.md). Montgomery arithmetic avoids 128-bit
// divisions. ----
using u64 = unsigned long long;
using u128 = unsigned __int128;

struct Montgomery {
  u64 n, n_inv, r2;  // n odd; n * n_inv == 1 mod 2^64; r2 = 2^128 mod n
  explicit Montgomery(u64 n_) : n(n_) {
    n_inv = n;  // Newton iteration doubles the number of correct low bits: 3 -> 6 -> ... -> 96
    for (int i = 0; i < 5; ++i) n_inv *= 2 - n * n_inv;
    const u64 r = (0 - n) % n;  // 2^64 mod n
    r2 = static_cast<u64>(static_cast<u128>(r) * r % n);
  }
  /// T * 2^-64 mod n for T < n * 2^64: T - m n is divisible by 2^64 and lies in (-n 2^64, n 2^64).
  u64 reduce(u128 T) const {
    const u64 m = static_cast<u64>(T) * n_inv;
    const u128 mn = static_cast<u128>(m) * n;
    const u64 th = static_cast<u64>(T >> 64), mh = static_cast<u64>(mn >> 64);
    return th >= mh ? th - mh : th - mh + n;
  }
  u64 mul(u64 a, u64 b) const { return reduce(static_cast<u128>(a) * b); }
  u64 to(u64 a) const { return mul(a % n, r2); }
};

bool is_prime_u64(u64 n) {
  if (n < 2) return false;
  static const u64 bases[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37};
  for (u64 p : bases) {
    if (n % p == 0) return n == p;
  }
  u64 d = n - 1;
  int s = 0;
  while ((d & 1) == 0) {
    d >>= 1;
    ++s;
  }
  const Montgomery M(n);
  const u64 one = M.to(1), minus_one = M.to(n - 1);
  for (u64 a : bases) {
    // x = a^d mod n (Montgomery form)
    u64 x = one, b = M.to(a);
    for (u64 e = d; e; e >>= 1) {
      if (e & 1) x = M.mul(x, b);
      b = M.mul(b, b);
    }
    if (x == one || x == minus_one) continue;
    bool witness = true;
    for (int i = 1; i < s; ++i) {
      x = M.mul(x, x);
      if (x == minus_one) {
        witness = false;
        break;
      }
    }
    if (witness) return false;
  }
  return true;
}

/// Odd small primes with their inverses mod 2^64: p | n  iff  n * inv <= (2^64 - 1) / p.
struct OddPrime {
  u64 p, inv, limit;
};
const std::vector<OddPrime>& odd_primes() {
  static const std::vector<OddPrime> table = [] {
    std::vector<OddPrime> out;
    for (unsigned long p : small_primes()) {
      if (p == 2) continue;
      u64 inv = p;
      for (int i = 0; i < 5; ++i) inv *= 2 - p * inv;
      out.push_back({p, inv, ~u64(0) / p});
    }
    return out;
  }();
  return table;
}

bool fits_u64(const Integer& z) { return mpz_sizeinbase(z.get_mpz_t(), 2) <= 64 && sgn(z) >= 0; }
u64 to_u64(const Integer& z) {
  u64 v = 0;
  mpz_export(&v, nullptr, -1, sizeof(v), 0, 0, z.get_mpz_t());
  return v;
}
Integer from_u64(u64 v) {
  Integer z;
  mpz_import(z.get_mpz_t(), 1, -1, sizeof(v), 0, 0, &v);
  return z;
}

bool is_square(const Integer& z) { return mpz_perfect_square_p(z.get_mpz_t()) != 0; }
Integer isqrt(const Integer& z) {
  Integer r;
  mpz_sqrt(r.get_mpz_t(), z.get_mpz_t());
  return r;
}

/// k = root^2 * rest, rest free of p^2 for primes p < 1000 and not a square unless 1.
struct Reduced {
  Integer root, rest;
  bool squarefree = false;  ///< rest proven square-free
};

Reduced reduce_radicand(const Integer& k) {
  Reduced out;
  if (is_square(k)) {
    out.root = isqrt(k);
    out.rest = 1;
    out.squarefree = true;
    return out;
  }
  if (fits_u64(k)) {
    u64 u = to_u64(k), s = 1, m = 1;
    bool fully = false;  // u is 1 or prime
    {
      int e = 0;
      while ((u & 1) == 0) {
        u >>= 1;
        ++e;
      }
      for (int i = 0; i < e / 2; ++i) m *= 2;
      if (e & 1) s *= 2;
    }
    for (const OddPrime& q : odd_primes()) {
      const u64 p = q.p;
      if (p * p > u) {
        fully = true;
        break;
      }
      if (u * q.inv > q.limit) continue;  // p does not divide u
      int e = 0;
      do {
        u = u * q.inv;  // exact division: u / p
        ++e;
      } while (u * q.inv <= q.limit);
      for (int i = 0; i < e / 2; ++i) m *= p;
      if (e & 1) s *= p;
    }
    if (!fully) {
      // u has no prime factor below kNextPrime.
      const Integer U = from_u64(u);
      if (is_square(U)) {
        m *= to_u64(isqrt(U));
        u = 1;
        fully = true;
      } else if (u < static_cast<u64>(kNextPrime) * kNextPrime || u < kNextPrimeCube || is_prime_u64(u)) {
        fully = true;  // prime, or p*q with distinct primes, or prime
      }
    }
    out.root = from_u64(m);
    out.rest = from_u64(s) * from_u64(u);
    out.squarefree = fully;
    return out;
  }
  Integer u = k, s = 1, m = 1;
  bool fully = false;
  for (unsigned long p : small_primes()) {
    if (mpz_cmp_ui(u.get_mpz_t(), p * p) < 0) {
      fully = true;
      break;
    }
    if (!mpz_divisible_ui_p(u.get_mpz_t(), p)) continue;
    int e = 0;
    do {
      mpz_divexact_ui(u.get_mpz_t(), u.get_mpz_t(), p);
      ++e;
    } while (mpz_divisible_ui_p(u.get_mpz_t(), p));
    for (int i = 0; i < e / 2; ++i) m *= p;
    if (e & 1) s *= p;
  }
  if (!fully) {
    if (is_square(u)) {
      m *= isqrt(u);
      u = 1;
      fully = true;
    } else if (fits_u64(u)) {
      const u64 v = to_u64(u);
      fully = v < kNextPrimeCube || is_prime_u64(v);
    }
  }
  out.root = m;
  out.rest = s * u;
  out.squarefree = fully;
  return out;
}

/// "c*body" pieces of a sum; `first` decides between "-x" and " - x".
void append_term(std::string& out, const Rational& c, const std::string& body, bool first) {
  const int s = sgn(c);
  const Rational mag = abs(c);
  if (first) {
    if (s < 0) out += '-';
  } else {
    out += (s < 0) ? " - " : " + ";
  }
  if (body.empty()) {
    out += exact_string(mag);
  } else {
    if (mag != 1) {
      out += exact_string(mag);
      out += '*';
    }
    out += body;
  }
}

Rational to_rational(const mpfr_t x) {
  Rational q;
  mpfr_get_q(q.get_mpq_t(), x);
  return q;
}

// ---- special terms ----

/// sqrt(v) for an algebraic, positive measure v that is not a square in the representation (nested radical).
class SqrtTerm final : public SpecialTerm {
 public:
  SqrtTerm(Measure radicand, std::string key) : radicand_(std::move(radicand)), key_(std::move(key)) {}
  const std::string& key() const override { return key_; }
  Interval enclose(mpfr_prec_t bits) const override { return Interval::sqrt(radicand_.enclose(bits)); }
  std::optional<std::string> exact_string() const override { return "sqrt(" + *radicand_.exact_string() + ")"; }

 private:
  Measure radicand_;
  std::string key_;
};

/// The constant pi: every arc angle that is a rational multiple of pi is a multiple of this one term (key "pi").
class PiTerm final : public SpecialTerm {
 public:
  const std::string& key() const override { return key_; }
  Interval enclose(mpfr_prec_t bits) const override { return Interval::pi(bits); }
  std::optional<std::string> exact_string() const override { return key_; }

 private:
  std::string key_ = "pi";
};

const std::shared_ptr<const SpecialTerm>& pi_term() {
  static const std::shared_ptr<const SpecialTerm> t = std::make_shared<PiTerm>();
  return t;
}

/// theta in (0, pi), not a multiple of pi/12, given by its exact rotation (cos theta, sin theta), sin > 0 (a
/// rotation with sin < 0 is 2*pi minus its conjugate's angle: Measure::arc_angle keys only the upper half).
/// Enclosed through the half angle, on the well-conditioned side of asin (argument <= 1/sqrt(2)):
///   theta/2 = asin(sqrt((1 - cos)/2))          when cos >= 0 (theta/2 <= pi/4),
///   theta/2 = pi/2 - asin(sqrt((1 + cos)/2))   when cos < 0.
class RotationTerm final : public SpecialTerm {
 public:
  RotationTerm(const Measure& cosine, int cos_sign, std::string key)
      : half_sine2_((cos_sign >= 0 ? Measure(Rational(1)) - cosine : Measure(Rational(1)) + cosine) *
                    Rational(1, 2)),
        cos_negative_(cos_sign < 0),
        key_(std::move(key)) {}
  const std::string& key() const override { return key_; }
  Interval enclose(mpfr_prec_t bits) const override {
    const Interval two(Rational(2), bits);
    const Interval a = Interval::asin(Interval::sqrt(half_sine2_.enclose(bits)));
    return two * (cos_negative_ ? Interval::pi(bits) / two - a : a);
  }
  std::optional<std::string> exact_string() const override { return std::nullopt; }

 private:
  Measure half_sine2_;  // (1 - cos)/2 or (1 + cos)/2, see above
  bool cos_negative_;
  std::string key_;
};

/// cos(k*pi/12) for k = 0..6, exactly: 1, (sqrt6 + sqrt2)/4, sqrt3/2, sqrt2/2, 1/2, (sqrt6 - sqrt2)/4, 0.
Measure cos_first_quadrant(int k) {
  switch (k) {
    case 0: return Rational(1);
    case 1: return (Measure::sqrt_of(6) + Measure::sqrt_of(2)) * Rational(1, 4);
    case 2: return Measure::sqrt_of(Rational(3, 4));
    case 3: return Measure::sqrt_of(Rational(1, 2));
    case 4: return Rational(1, 2);
    case 5: return (Measure::sqrt_of(6) - Measure::sqrt_of(2)) * Rational(1, 4);
    default: return Measure();
  }
}

/// cos(k*pi/12) for k = 0..23 by the quadrant symmetries; sin(k*pi/12) = cos((k - 6)*pi/12).
const std::vector<Measure>& cos_twelfths() {
  static const std::vector<Measure> table = [] {
    std::vector<Measure> out;
    for (int k = 0; k < 24; ++k) {
      if (k <= 6) out.push_back(cos_first_quadrant(k));
      else if (k <= 12) out.push_back(-cos_first_quadrant(12 - k));
      else if (k <= 18) out.push_back(-cos_first_quadrant(k - 12));
      else out.push_back(cos_first_quadrant(24 - k));
    }
    return out;
  }();
  return table;
}

/// k in 0..23 when (cosine, sine) is exactly the rotation by k*pi/12. The double values only choose the one
/// candidate; the answer is decided by exact equality of algebraic sums (Claim 4.3).
std::optional<int> twelfths_of_pi(const Measure& cosine, const Measure& sine) {
  const double theta = std::atan2(sine.to_double(), cosine.to_double());
  const double step = 3.14159265358979323846 / 12;
  const long k = ((std::lround(theta / step) % 24) + 24) % 24;
  const auto& table = cos_twelfths();
  if ((cosine - table[k]).is_zero() && (sine - table[(k + 18) % 24]).is_zero()) return static_cast<int>(k);
  return std::nullopt;
}

/// Canonical exact text of an algebraic measure ("0" for zero).
std::string algebraic_text(const Measure& m) { return *m.exact_string(); }

// ---- CGAL interval filter (one for the whole library: Measure::double_bounds, DoubleCombination) ----

bool fits_double_exactly(mpz_srcptr z) { return mpz_sizeinbase(z, 2) <= 53; }

/// k exactly when |k| <= 2^53 (a double holds it), else the doubles either side of the nearest one: a long
/// above 2^53 is rounded on conversion, by at most half an ulp.
IntervalNT to_interval_nt(long k) {
  constexpr long kExact = 1L << 53;
  const double d = static_cast<double>(k);
  if (-kExact <= k && k <= kExact) return IntervalNT(d);
  constexpr double inf = std::numeric_limits<double>::infinity();
  return IntervalNT(std::nextafter(d, -inf), std::nextafter(d, inf));
}

IntervalNT pi_interval_nt() {
  static const IntervalNT pi = [] {
    const Interval e = Interval::pi(128);
    return IntervalNT(e.lo_double(), e.hi_double());  // MPFR, rounded outward
  }();
  return pi;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------------

Measure::Measure(const Rational& q) {
  if (sgn(q) != 0) algebraic_.emplace(Integer(1), Term{q, {}});
}

Measure Measure::sqrt_of(const Rational& q) {
  if (sgn(q) < 0) throw std::domain_error("Measure::sqrt_of: negative argument " + hsx::exact_string(q));
  Measure m;
  m.add_sqrt_rational(Rational(1), q);
  return m;
}

void Measure::add_sqrt_rational(const Rational& coefficient, const Rational& q) {
  if (sgn(coefficient) == 0 || sgn(q) == 0) return;
  if (sgn(q) < 0) throw std::domain_error("Measure: square root of a negative number " + hsx::exact_string(q));
  // sqrt(p/d) = sqrt(p*d)/d
  const Integer& d = q.get_den();
  if (d == 1) {
    add_sqrt_term(coefficient, q.get_num());
  } else {
    add_sqrt_term(coefficient / Rational(d), q.get_num() * d);
  }
}

void Measure::add_sqrt_term(const Rational& coefficient, const Integer& radicand) {
  if (sgn(coefficient) == 0 || sgn(radicand) == 0) return;
  if (sgn(radicand) < 0) throw std::domain_error("Measure: square root of a negative integer");
  if (radicand == 1) {
    insert_reduced(coefficient, radicand, true, ClassPrint());
    return;
  }
  const Reduced r = reduce_radicand(radicand);
  insert_reduced(r.root == 1 ? coefficient : Rational(coefficient * r.root), r.rest, r.squarefree, ClassPrint());
}

// ---- square-class index ----------------------------------------------------------------------------------
namespace {

constexpr std::size_t kIndexThreshold = 24;  // below this many terms a linear scan is as fast as the index

/// The 64 fingerprint primes: the first 64 primes above 2^16, so that a radicand (free of small square factors)
/// is rarely divisible by one.
const std::vector<unsigned long>& print_primes() {
  static const std::vector<unsigned long> primes = [] {
    std::vector<unsigned long> out;
    for (unsigned long n = 65537; out.size() < 64; n += 2) {
      bool prime = true;
      for (unsigned long d = 3; d * d <= n && prime; d += 2) prime = n % d != 0;
      if (prime) out.push_back(n);
    }
    return out;
  }();
  return primes;
}

}  // namespace

void Measure::build_index() {
  indexed_ = true;
  for (auto& [k, t] : algebraic_) {
    if (k == 1) continue;
    if (!t.print.known) t.print = class_print(k);
    index_insert(k, t.print);
  }
}

Measure::ClassPrint Measure::class_print(const Integer& k) {
  ClassPrint p;
  const std::vector<unsigned long>& primes = print_primes();
  for (std::size_t i = 0; i < primes.size(); ++i) {
    const int r = mpz_kronecker_ui(k.get_mpz_t(), primes[i]);
    if (r == 1) p.residues |= std::uint64_t(1) << i;
    if (r == 0) p.divides |= std::uint64_t(1) << i;
  }
  p.known = true;
  return p;
}

void Measure::index_insert(const Integer& radicand, const ClassPrint& print) {
  if (print.divides != 0) {
    unclean_.insert(radicand);
  } else {
    classes_.emplace(print.residues, radicand);
  }
}

void Measure::index_erase(const Integer& radicand, const ClassPrint& print) {
  if (print.divides != 0) {
    unclean_.erase(radicand);
    return;
  }
  auto [lo, hi] = classes_.equal_range(print.residues);
  for (auto it = lo; it != hi; ++it)
    if (it->second == radicand) {
      classes_.erase(it);
      return;
    }
}

void Measure::erase_term(std::map<Integer, Term>::iterator it) {
  if (!unsure_.empty()) unsure_.erase(it->first);
  if (indexed_ && it->first != 1) index_erase(it->first, it->second.print);
  algebraic_.erase(it);
}

const Integer* Measure::class_partner(const Integer& radicand, bool squarefree, ClassPrint* print) {
  // The radicand j already held (at most one, by the invariant) with radicand*j a perfect square.
  Integer product;
  auto same_class = [&](const Integer& j) {
    product = radicand * j;
    return is_square(product);
  };
  if (!indexed_ && !squarefree && algebraic_.size() >= kIndexThreshold) build_index();
  if (!indexed_) {
    if (squarefree) {
      for (const Integer& j : unsure_)
        if (same_class(j)) return &j;
    } else {
      for (const auto& [j, t] : algebraic_)
        if (j != 1 && same_class(j)) return &j;
    }
    return nullptr;
  }
  if (!print->known) *print = class_print(radicand);
  // Two proven square-free radicands are never in one class: a proven one only looks at unproven partners.
  auto candidate = [&](const Integer& j, const ClassPrint& pj) {
    return (!squarefree || unsure_.count(j) != 0) && print->compatible(pj) && same_class(j);
  };
  if (print->divides != 0) {  // rare: a fingerprint prime divides the radicand, so every class may match
    for (const auto& [j, t] : algebraic_)
      if (j != 1 && candidate(j, t.print)) return &j;
    return nullptr;
  }
  auto [lo, hi] = classes_.equal_range(print->residues);
  for (auto it = lo; it != hi; ++it)
    if (candidate(it->second, algebraic_.at(it->second).print)) return &it->second;
  for (const Integer& j : unclean_)
    if (candidate(j, algebraic_.at(j).print)) return &j;
  return nullptr;
}

void Measure::insert_reduced(const Rational& coefficient, const Integer& radicand, bool squarefree,
                             ClassPrint print) {
  if (sgn(coefficient) == 0) return;
  auto it = algebraic_.find(radicand);
  if (it != algebraic_.end()) {
    it->second.c += coefficient;
    if (sgn(it->second.c) == 0) erase_term(it);
    return;
  }
  if (radicand != 1) {
    if (const Integer* match = class_partner(radicand, squarefree, &print)) {
      // radicand = g*a^2 and j = g*b^2 with g = gcd: c_j*sqrt(j) + c*sqrt(radicand) = (c_j*b + c*a)*sqrt(g).
      const Integer j = *match;
      Integer g;
      mpz_gcd(g.get_mpz_t(), radicand.get_mpz_t(), j.get_mpz_t());
      auto jt = algebraic_.find(j);
      const Rational cj = jt->second.c;
      const Integer a = isqrt(Integer(radicand / g));
      const Integer b = isqrt(Integer(j / g));
      const Rational total = cj * b + coefficient * a;
      if (g == j) {
        jt->second.c = total;
        if (sgn(total) == 0) erase_term(jt);
        return;
      }
      erase_term(jt);
      add_sqrt_term(total, g);  // g is in the same class and smaller; no other radicand is in this class
      return;
    }
  }
  Term& t = algebraic_.emplace(radicand, Term{coefficient, print}).first->second;
  if (!squarefree) unsure_.insert(radicand);
  if (indexed_ && radicand != 1) {
    if (!t.print.known) t.print = class_print(radicand);
    index_insert(radicand, t.print);
  }
}

void Measure::add_special(const std::shared_ptr<const SpecialTerm>& term, const Rational& coefficient) {
  if (sgn(coefficient) == 0) return;
  auto it = special_.find(term->key());
  if (it == special_.end()) {
    special_.emplace(term->key(), Special{term, coefficient});
    return;
  }
  it->second.coefficient += coefficient;
  if (sgn(it->second.coefficient) == 0) special_.erase(it);
}

void Measure::add_measure(const Measure& other, bool negate) {
  if (&other == this) {
    if (negate) {
      algebraic_.clear();
      special_.clear();
      unsure_.clear();
      indexed_ = false;
      classes_.clear();
      unclean_.clear();
    } else {
      *this *= Rational(2);
    }
    return;
  }
  for (const auto& [k, t] : other.algebraic_) {
    const bool squarefree = other.unsure_.empty() || other.unsure_.count(k) == 0;
    insert_reduced(negate ? Rational(-t.c) : t.c, k, squarefree, t.print);
  }
  for (const auto& [key, s] : other.special_) add_special(s.term, negate ? Rational(-s.coefficient) : s.coefficient);
}

Measure& Measure::operator+=(const Measure& other) {
  add_measure(other, false);
  return *this;
}

Measure& Measure::operator-=(const Measure& other) {
  add_measure(other, true);
  return *this;
}

Measure& Measure::operator*=(const Rational& factor) {
  if (sgn(factor) == 0) {
    algebraic_.clear();
    special_.clear();
    unsure_.clear();
    indexed_ = false;
    classes_.clear();
    unclean_.clear();
    return *this;
  }
  for (auto& [k, t] : algebraic_) t.c *= factor;
  for (auto& [key, s] : special_) s.coefficient *= factor;
  return *this;
}

Measure Measure::operator-() const {
  Measure m = *this;
  for (auto& [k, t] : m.algebraic_) t.c = -t.c;
  for (auto& [key, s] : m.special_) s.coefficient = -s.coefficient;
  return m;
}

Measure Measure::product(const OneRoot& a, const OneRoot& b) {
  // (a0 + a1 sqrt(r))(b0 + b1 sqrt(s)) = a0 b0 + a0 b1 sqrt(s) + a1 b0 sqrt(r) + a1 b1 sqrt(r s)
  Measure m;
  const bool ra = !a.is_rational(), rb = !b.is_rational();
  m.insert_reduced(a.a0 * b.a0, Integer(1), true, ClassPrint());
  if (rb) m.add_sqrt_rational(a.a0 * b.a1, b.root);
  if (ra) m.add_sqrt_rational(a.a1 * b.a0, a.root);
  if (ra && rb) m.add_sqrt_rational(a.a1 * b.a1, a.root == b.root ? Rational(a.root * a.root) : Rational(a.root * b.root));
  return m;
}

Measure Measure::multiply_algebraic(const Measure& a, const Measure& b) {
  Measure m;
  for (const auto& [k1, t1] : a.algebraic_) {
    for (const auto& [k2, t2] : b.algebraic_) {
      const Rational &c1 = t1.c, &c2 = t2.c;
      // sqrt(k1 k2) = g*sqrt((k1/g)(k2/g)), g = gcd(k1, k2)
      Integer g;
      mpz_gcd(g.get_mpz_t(), k1.get_mpz_t(), k2.get_mpz_t());
      if (g == 1) {
        m.add_sqrt_term(c1 * c2, k1 * k2);
      } else {
        m.add_sqrt_term(c1 * c2 * g, Integer(k1 / g) * Integer(k2 / g));
      }
    }
  }
  return m;
}

Measure Measure::distance(const OneRootPoint& p, const OneRootPoint& q) {
  if (p.is_rational() && q.is_rational()) {
    const Rational dx = p.x.a0 - q.x.a0, dy = p.y.a0 - q.y.a0;
    return sqrt_of(Rational(dx * dx + dy * dy));
  }
  const Measure dx = product(p.x, Rational(1)) - product(q.x, Rational(1));
  const Measure dy = product(p.y, Rational(1)) - product(q.y, Rational(1));
  // Axis-parallel: |dx| or |dy| exactly.
  if (dy.is_zero()) return dx.algebraic_sign(64) < 0 ? -dx : dx;
  if (dx.is_zero()) return dy.algebraic_sign(64) < 0 ? -dy : dy;
  Measure d2 = multiply_algebraic(dx, dx);
  d2 += multiply_algebraic(dy, dy);
  if (auto r = d2.rational_value()) return sqrt_of(*r);

  Measure out;
  const bool one_radical =
      d2.algebraic_.size() == 1 || (d2.algebraic_.size() == 2 && d2.algebraic_.begin()->first == 1);
  if (one_radical) {
    // d2 = A + B*sqrt(c). If A^2 - B^2 c = s^2 (s >= 0 rational), then
    // sqrt(A + B sqrt(c)) = sqrt((A + s)/2) + sign(B)*sqrt((A - s)/2).
    const auto last = std::prev(d2.algebraic_.end());
    const Integer c = last->first;
    const Rational B = last->second.c;
    const Rational A = d2.algebraic_.size() == 2 ? d2.algebraic_.begin()->second.c : Rational(0);
    const Rational disc = A * A - B * B * c;
    if (sgn(disc) >= 0 && is_square(disc.get_num()) && is_square(disc.get_den())) {
      const Rational s = make_rational(isqrt(disc.get_num()), isqrt(disc.get_den()));
      // d2 > 0 and A^2 >= B^2 c imply A >= s >= 0 (proofs/measures.md), so both radicands are >= 0.
      out.add_sqrt_rational(Rational(1), Rational((A + s) / 2));
      out.add_sqrt_rational(Rational(sgn(B)), Rational((A - s) / 2));
      return out;
    }
    const std::string key = "nsqrt(" + hsx::exact_string(A) + "," + hsx::exact_string(B) + "," + c.get_str(10) + ")";
    out.add_special(std::make_shared<SqrtTerm>(std::move(d2), key), Rational(1));
    return out;
  }
  const std::string key = "sqrt(" + *d2.exact_string() + ")";
  out.add_special(std::make_shared<SqrtTerm>(std::move(d2), key), Rational(1));
  return out;
}

Measure Measure::pi(const Rational& coefficient) {
  Measure out;
  out.add_special(pi_term(), coefficient);
  return out;
}

Measure Measure::arc_angle(const PointQ2& center, const Rational& radius, const OneRootPoint& from,
                           const OneRootPoint& to, const Rational& coefficient) {
  if (sgn(radius) <= 0) throw std::domain_error("Measure::arc_angle: radius must be positive");
  if (sgn(coefficient) == 0) return Measure();
  if (compare(from.x, to.x) == 0 && compare(from.y, to.y) == 0) return pi(Rational(2 * coefficient));
  // Rotation z = v * conj(u) with u = (from - c)/r, v = (to - c)/r: cos = u.v, sin = u x v (exact sums).
  OneRoot fx = from.x, fy = from.y, tx = to.x, ty = to.y;
  fx.a0 -= center.x;
  fy.a0 -= center.y;
  tx.a0 -= center.x;
  ty.a0 -= center.y;
  const Rational inv_r2 = 1 / Rational(radius * radius);
  const Measure cosine = (product(fx, tx) + product(fy, ty)) * inv_r2;
  const Measure sine = (product(fx, ty) - product(fy, tx)) * inv_r2;
  const int sin_sign = sine.algebraic_sign(64);
  if (sin_sign == 0) return pi(coefficient);  // distinct points on the circle with u x v = 0: opposite ends
  if (const auto k = twelfths_of_pi(cosine, sine)) return pi(Rational(coefficient * *k / 12));
  // theta(z) = 2*pi - theta(conj z) for sin < 0: one key per pair of conjugate rotations, so that an arc and its
  // reverse add up to the full circle exactly.
  const Measure upper_sine = sin_sign > 0 ? sine : -sine;
  std::string key = "rot(" + algebraic_text(cosine) + ", " + algebraic_text(upper_sine) + ")";
  Measure out = sin_sign > 0 ? Measure() : pi(Rational(2 * coefficient));
  out.add_special(std::make_shared<RotationTerm>(cosine, cosine.algebraic_sign(64), std::move(key)),
                  sin_sign > 0 ? coefficient : Rational(-coefficient));
  return out;
}

bool Measure::is_zero() const { return algebraic_.empty() && special_.empty(); }

bool Measure::is_algebraic() const {
  for (const auto& [key, s] : special_)
    if (!dynamic_cast<const SqrtTerm*>(s.term.get())) return false;
  return true;
}

std::optional<Rational> Measure::rational_value() const {
  if (!special_.empty()) return std::nullopt;
  if (algebraic_.empty()) return Rational(0);
  if (algebraic_.size() == 1 && algebraic_.begin()->first == 1) return algebraic_.begin()->second.c;
  return std::nullopt;
}

Interval Measure::enclose(mpfr_prec_t bits) const {
  // Accumulate the two end points in place (this is the hot path of compare): for c*sqrt(k) with c > 0 the
  // lower end is down(down(sqrt(down(k))) * c) and the upper end the same rounded up; for c < 0 the roles of the
  // sqrt bounds swap. Every step rounds outward, so [lo, hi] contains the exact sum.
  const mpfr_prec_t p = std::max<mpfr_prec_t>(bits, MPFR_PREC_MIN);
  mpfr_t lo, hi, s_lo, s_hi;
  mpfr_inits2(p, lo, hi, s_lo, s_hi, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_zero(lo, 1);
  mpfr_set_zero(hi, 1);
  for (const auto& [k, t] : algebraic_) {
    const Rational& c = t.c;
    if (k == 1) {
      mpfr_set_q(s_lo, c.get_mpq_t(), MPFR_RNDD);
      mpfr_set_q(s_hi, c.get_mpq_t(), MPFR_RNDU);
    } else {
      mpfr_set_z(s_lo, k.get_mpz_t(), MPFR_RNDD);
      mpfr_set_z(s_hi, k.get_mpz_t(), MPFR_RNDU);
      mpfr_sqrt(s_lo, s_lo, MPFR_RNDD);
      mpfr_sqrt(s_hi, s_hi, MPFR_RNDU);
      if (sgn(c) < 0) mpfr_swap(s_lo, s_hi);  // multiplying by a negative number reverses the order
      mpfr_mul_q(s_lo, s_lo, c.get_mpq_t(), MPFR_RNDD);
      mpfr_mul_q(s_hi, s_hi, c.get_mpq_t(), MPFR_RNDU);
    }
    mpfr_add(lo, lo, s_lo, MPFR_RNDD);
    mpfr_add(hi, hi, s_hi, MPFR_RNDU);
  }
  Interval sum = Interval::from_ends(lo, hi);
  mpfr_clears(lo, hi, s_lo, s_hi, static_cast<mpfr_ptr>(nullptr));
  for (const auto& [key, s] : special_) sum = sum + Interval(s.coefficient, p) * s.term->enclose(p);
  return sum;
}

double Measure::to_double() const {
  if (auto r = rational_value()) return r->get_d();
  return enclose(80).mid_double();
}

Rational Measure::pi_coefficient() const {
  const auto it = special_.find(pi_term()->key());
  return it == special_.end() ? Rational(0) : it->second.coefficient;
}

std::optional<std::string> Measure::exact_string() const {
  if (is_zero()) return std::string("0");
  for (const auto& [key, s] : special_)
    if (!s.term->exact_string()) return std::nullopt;
  std::string out;
  bool first = true;
  const Rational q = pi_coefficient();
  if (sgn(q) != 0) {
    append_term(out, q, pi_term()->key(), first);
    first = false;
  }
  for (const auto& [k, t] : algebraic_) {
    const Rational& c = t.c;
    append_term(out, c, k == 1 ? std::string() : "sqrt(" + k.get_str(10) + ")", first);
    first = false;
  }
  for (const auto& [key, s] : special_) {
    if (key == pi_term()->key()) continue;
    append_term(out, s.coefficient, *s.term->exact_string(), first);
    first = false;
  }
  return out;
}

Measure::Decimal Measure::decimal(int significant) const {
  if (auto r = rational_value()) return {hsx::decimal_string(*r, significant), true};
  const int sig = std::max(significant, 1);
  mpfr_prec_t bits = std::max<mpfr_prec_t>(64, static_cast<mpfr_prec_t>(sig) * 4 + 32);
  while (true) {
    const Interval e = enclose(bits);
    const std::string lo = hsx::decimal_string(to_rational(e.lo()), sig);
    if (lo == hsx::decimal_string(to_rational(e.hi()), sig)) return {lo, true};  // rounding is monotone
    if (bits >= kDecimalCapBits) return {e.mid_decimal(sig), false};
    bits = std::min(bits * 2, kDecimalCapBits);
  }
}

std::string Measure::decimal_string(int significant) const {
  Decimal d = decimal(significant);
  if (!d.certified) d.digits += '~';
  return d.digits;
}

std::optional<DoubleBounds> Measure::double_bounds() const {
  // CGAL::Interval_nt keeps every end rounded outward (proofs/measures.md, Claim 4.7). Terms are limited to
  // |c| in [2^-401, 2^401] and k < 2^800 so that nothing overflows (no infinite ends, no 0 * inf).
  // Two passes: the conversions (which may call MPFR) in the caller's rounding mode, then the arithmetic with
  // unprotected intervals inside one Protect_FPU_rounding block (one mode switch instead of one per operation).
  std::vector<std::pair<IntervalNT, IntervalNT>> terms;  // (c, k), k = 1 for the rational part
  terms.reserve(algebraic_.size() + special_.size());
  for (const auto& [k, t] : algebraic_) {
    const Rational& c = t.c;
    const long e = static_cast<long>(mpz_sizeinbase(c.get_num_mpz_t(), 2)) -
                   static_cast<long>(mpz_sizeinbase(c.get_den_mpz_t(), 2));
    if (e > 400 || e < -400) return std::nullopt;
    if (mpz_sizeinbase(k.get_mpz_t(), 2) > 800) return std::nullopt;
    terms.emplace_back(to_interval_nt(c), to_interval_nt(k));
  }
  for (const auto& [key, s] : special_) {
    if (s.term != pi_term()) return std::nullopt;
    terms.emplace_back(to_interval_nt(s.coefficient), IntervalNT(1));
  }
  const IntervalNT pi = pi_interval_nt();
  using Fast = CGAL::Interval_nt<false>;
  const CGAL::Protect_FPU_rounding<true> upward;  // restores the caller's mode on leaving the scope
  Fast sum(0);
  std::size_t i = 0;
  for (const auto& entry : algebraic_) {
    const Integer& k = entry.first;
    const auto& [ci, ki] = terms[i++];
    const Fast cf(ci.inf(), ci.sup());
    sum += k == 1 ? cf : cf * CGAL::sqrt(Fast(ki.inf(), ki.sup()));
  }
  for (; i < terms.size(); ++i) sum += Fast(terms[i].first.inf(), terms[i].first.sup()) * Fast(pi.inf(), pi.sup());
  return DoubleBounds{sum.inf(), sum.sup()};
}

void DoubleCombination::add(long k, const DoubleBounds& m) {
  if (!(m.lo <= m.hi)) throw std::invalid_argument("DoubleCombination::add: not an interval (lo > hi or NaN)");
  if (k == 0) return;
  const IntervalNT term(m.lo, m.hi);
  const IntervalNT sum = k == 1    ? IntervalNT(sum_.lo, sum_.hi) + term
                         : k == -1 ? IntervalNT(sum_.lo, sum_.hi) - term
                                   : IntervalNT(sum_.lo, sum_.hi) + to_interval_nt(k) * term;
  sum_ = {sum.inf(), sum.sup()};
}

IntervalBatch::IntervalBatch() {
  static_assert(std::is_unsigned<CGAL::FPU_CW_t>::value && sizeof(CGAL::FPU_CW_t) <= sizeof(unsigned long),
                "IntervalBatch keeps CGAL::FPU_CW_t in an unsigned long");
  saved_mode_ = CGAL::FPU_get_and_set_cw(CGAL_FE_UPWARD);
}
IntervalBatch::~IntervalBatch() { CGAL::FPU_set_cw(static_cast<CGAL::FPU_CW_t>(saved_mode_)); }

// CGAL::Interval_nt<false> assumes upward rounding (set by the batch) and keeps the compiler from folding the
// negated sums that give the lower ends.
DoubleBounds IntervalBatch::add(const DoubleBounds& a, const DoubleBounds& b) const {
  using Fast = CGAL::Interval_nt<false>;
  const Fast sum = Fast(a.lo, a.hi) + Fast(b.lo, b.hi);
  return {sum.inf(), sum.sup()};
}
DoubleBounds IntervalBatch::subtract(const DoubleBounds& a, const DoubleBounds& b) const {
  using Fast = CGAL::Interval_nt<false>;
  const Fast difference = Fast(a.lo, a.hi) - Fast(b.lo, b.hi);
  return {difference.inf(), difference.sup()};
}

int Measure::algebraic_sign(mpfr_prec_t start_bits) const {
  const std::size_t n = algebraic_.size();
  if (n == 0) return 0;
  auto it = algebraic_.begin();
  if (n == 1) return sgn(it->second.c);
  const bool has_rational = it->first == 1;
  if (n == 2) {
    const auto second = std::next(it);
    if (has_rational) return OneRoot(it->second.c, second->second.c, Rational(second->first)).sign();
    return compare(OneRoot(0, it->second.c, Rational(it->first)),
                   OneRoot(0, -second->second.c, Rational(second->first)));
  }
  if (n == 3 && has_rational) {
    const auto b = std::next(it), c = std::next(b);
    return compare(OneRoot(it->second.c, b->second.c, Rational(b->first)), OneRoot(0, -c->second.c, Rational(c->first)));
  }
  if (const auto bounds = double_bounds()) {
    if (const int s = bounds->certain_sign()) return s;
  }
  // Non-zero (the radicands are in distinct square classes and some coefficient is non-zero), so refinement ends.
  for (mpfr_prec_t bits = std::max<mpfr_prec_t>(start_bits, 32);; bits *= 2) {
    if (bits > kAlgebraicCeilingBits)
      throw std::runtime_error("Measure: sign of a non-zero algebraic sum not found at 2^20 bits");
    const int s = enclose(bits).certain_sign();
    if (s != 0) return s;
  }
}

bool Measure::provably_nonzero() const {
  if (is_zero()) return false;
  if (special_.empty()) return true;  // Claim 4.3
  if (sgn(pi_coefficient()) == 0) return false;
  for (const auto& [key, s] : special_)  // q*pi + algebraic with q != 0: pi is transcendental (Claim 6.4)
    if (s.term != pi_term() && !dynamic_cast<const SqrtTerm*>(s.term.get())) return false;
  return true;
}

int Measure::refined_sign(mpfr_prec_t start_bits) const {
  if (special_.empty()) return algebraic_sign(start_bits);
  if (const auto bounds = double_bounds()) {
    if (const int s = bounds->certain_sign()) return s;
  }
  for (mpfr_prec_t bits = std::max<mpfr_prec_t>(start_bits, 32);; bits *= 2) {
    if (bits > kAlgebraicCeilingBits)
      throw std::runtime_error("Measure: sign of a provably non-zero value not found at 2^20 bits");
    const int s = enclose(bits).certain_sign();
    if (s != 0) return s;
  }
}

std::optional<int> Measure::sign(const CompareOptions& options) const {
  if (is_zero()) return 0;
  if (provably_nonzero()) return refined_sign(options.start_bits);
  for (mpfr_prec_t bits = std::max<mpfr_prec_t>(options.start_bits, 32);;) {
    const int s = enclose(bits).certain_sign();
    if (s != 0) return s;
    if (bits >= options.max_bits) return std::nullopt;
    bits = std::min(bits * 2, options.max_bits);
  }
}

Order compare(const Measure& a, const Measure& b, const CompareOptions& options) {
  // Filter: disjoint certified enclosures decide without building a - b (most comparisons in a search).
  const auto da = a.double_bounds(), db = b.double_bounds();
  if (da && db) {
    if (da->hi < db->lo) return Order::Less;
    if (db->hi < da->lo) return Order::Greater;
  } else {
    const mpfr_prec_t bits = std::max<mpfr_prec_t>(options.start_bits, 32);
    const Interval ea = a.enclose(bits), eb = b.enclose(bits);
    if (mpfr_less_p(ea.hi(), eb.lo())) return Order::Less;
    if (mpfr_less_p(eb.hi(), ea.lo())) return Order::Greater;
  }
  const Measure d = a - b;
  if (d.is_zero()) return Order::Equal;
  const std::optional<int> s = d.sign(options);
  if (!s) return Order::Tie;
  return *s < 0 ? Order::Less : (*s > 0 ? Order::Greater : Order::Equal);
}

IntervalNT to_interval_nt(const Rational& q) {
  if (fits_double_exactly(q.get_num_mpz_t()) && fits_double_exactly(q.get_den_mpz_t())) {
    const IntervalNT num(mpz_get_d(q.get_num_mpz_t()));
    if (q.get_den() == 1) return num;
    return num / IntervalNT(mpz_get_d(q.get_den_mpz_t()));
  }
  const std::pair<double, double> e = CGAL::to_interval(q);
  return IntervalNT(e.first, e.second);
}

IntervalNT to_interval_nt(const Integer& z) {
  if (fits_double_exactly(z.get_mpz_t())) return IntervalNT(mpz_get_d(z.get_mpz_t()));
  const std::pair<double, double> e = CGAL::to_interval(z);
  return IntervalNT(e.first, e.second);
}

}  // namespace hsx
