// Measures (lengths, areas) held exactly where that is decidable and as certified enclosures where it is not.
//
// A Measure is a finite sum   sum_k c_k * sqrt(k)  +  sum_t c_t * T_t
//   - the algebraic part: rational coefficients c_k over positive integer radicands k, kept so that no two
//     radicands have a perfect-square product (sqrt(8) is stored as 2*sqrt(2), sqrt(9) as 3). Square roots of
//     distinct square-free integers are linearly independent over Q, so this part is zero iff every coefficient is
//     zero, and its sign is decided by interval refinement, which terminates for a non-zero value.
//   - special terms T_t, each identified by a canonical key so that the same term on both sides of a comparison
//     cancels exactly:
//       * pi (key "pi"): every arc whose angle is a rational multiple of pi (multiples of pi/12; by Theorem 6.5 of
//         proofs/measures.md no other rational multiple of pi has a rotation with one-root end points);
//       * any other arc angle theta, keyed by its rotation (cos theta, sin theta), exact algebraic numbers, so that
//         congruent arcs on different circles, and arcs of equal angle on circles of any radius, share one key
//         (arc length r*theta, area r^2/2*theta);
//       * nested radical sqrt(A + B*sqrt(c)) that does not denest (a segment ending on a circle).
//     pi is transcendental, so a value q*pi + (sum of square roots) is zero iff q = 0 and the sum is zero: signs
//     of such values are exact. Values with other special terms are decided by certified MPFR enclosures.
// See proofs/measures.md for what is exact, what is certified, and why.
#pragma once

#include <hsx/kernel/interval.hpp>
#include <hsx/kernel/one_root.hpp>
#include <hsx/kernel/rational.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

namespace hsx {

/// Result of a certified comparison.
enum class Order {
  Less,     ///< proven a < b
  Equal,    ///< proven a == b (exact)
  Greater,  ///< proven a > b
  Tie       ///< not separated at the precision cap: possibly equal, never reported as decided
};
const char* to_string(Order o);

/// How hard `compare` tries before answering Tie. Passed explicitly: no global settings.
struct CompareOptions {
  mpfr_prec_t start_bits = 64;
  mpfr_prec_t max_bits = 2048;  ///< cap for special terms; provably non-zero values (see sign) ignore it
};

/// A special (non-square-root) term: knows its canonical key, an exact text when it has a closed form, and how to
/// enclose its value at any precision.
class SpecialTerm {
 public:
  virtual ~SpecialTerm() = default;
  virtual const std::string& key() const = 0;
  virtual Interval enclose(mpfr_prec_t bits) const = 0;
  /// Closed form when known: nested radicals ("sqrt(3 + 2*sqrt(2))") and "pi"; nullopt for other arc angles.
  virtual std::optional<std::string> exact_string() const = 0;
};

/// Certified double enclosure [lo, hi] of a real number (lo <= value <= hi; ends may be infinite).
struct DoubleBounds {
  double lo = 0, hi = 0;
  /// -1 if hi < 0, +1 if lo > 0, 0 when the enclosure contains 0 (not decided).
  int certain_sign() const { return lo > 0 ? 1 : (hi < 0 ? -1 : 0); }
};

/// Certified double enclosure of an integer combination sum_i k_i * m_i of reals m_i known only by certified
/// double enclosures (for instance the measures of a max-flow's capacities). Start from zero and `add` terms;
/// the running enclosure is kept with outward rounding (CGAL::Interval_nt inside measure.cpp), and any long k_i is
/// enclosed exactly (|k_i| > 2^53 is not representable as a double: it is widened to the neighbouring doubles).
class DoubleCombination {
 public:
  /// Adds k * m where m lies in `m` (lo <= hi, not NaN; throws std::invalid_argument otherwise).
  void add(long k, const DoubleBounds& m);
  const DoubleBounds& bounds() const { return sum_; }

 private:
  DoubleBounds sum_;
};

/// Certified sums and differences of DoubleBounds for a batch of operations with one FPU rounding-mode switch
/// (DoubleCombination switches per operation): the constructor sets the FPU to round upward, the destructor
/// restores the caller's mode (CGAL's FPU control inside measure.cpp). `add` and `subtract` round outward only
/// while their batch is alive; every other double operation in that scope rounds upward too, so the scope should
/// hold interval arithmetic only (or double arithmetic whose rounding does not matter). Not copyable; nests.
class IntervalBatch {
 public:
  IntervalBatch();
  ~IntervalBatch();
  IntervalBatch(const IntervalBatch&) = delete;
  IntervalBatch& operator=(const IntervalBatch&) = delete;
  /// a + b, outward rounded (a and b are enclosures: lo <= hi, not NaN).
  DoubleBounds add(const DoubleBounds& a, const DoubleBounds& b) const;
  /// a - b, outward rounded (a and b are enclosures: lo <= hi, not NaN).
  DoubleBounds subtract(const DoubleBounds& a, const DoubleBounds& b) const;

 private:
  unsigned long saved_mode_;  // CGAL::FPU_CW_t, an unsigned integer on every platform CGAL supports
};

class Measure {
 public:
  Measure() = default;  ///< zero
  Measure(const Rational& q);  // NOLINT: a rational is a measure

  /// sqrt(q) exactly; q >= 0 (throws std::domain_error otherwise).
  static Measure sqrt_of(const Rational& q);
  /// a*b exactly, as an algebraic sum (sqrt(c)*sqrt(d) = sqrt(c*d)).
  static Measure product(const OneRoot& a, const OneRoot& b);
  /// coefficient * pi, exactly.
  static Measure pi(const Rational& coefficient = Rational(1));
  /// Euclidean distance |p - q|: exact sqrt of a rational when both points are rational, a denested sum when
  /// sqrt(A + B sqrt(c)) denests, otherwise a nested-radical special term.
  static Measure distance(const OneRootPoint& p, const OneRootPoint& q);
  /// coefficient * theta, theta in (0, 2*pi] the counter-clockwise angle from `from` to `to` around the circle
  /// (center, radius > 0; throws std::domain_error otherwise); from == to means the full circle (2*pi). Both
  /// points must lie on the circle (caller's duty). When theta is a multiple of pi/12 the result is the exact
  /// term (coefficient * k/12) * pi; otherwise theta is a special term keyed by the rotation
  /// (cos theta, sin theta) = ((to - center) / radius) * conj((from - center) / radius), whose coordinates are
  /// exact algebraic sums: arcs with the same rotation share the key and cancel exactly, whatever their circle.
  /// Arc length: coefficient = radius. Area swept (Green's theorem): coefficient = radius^2/2.
  static Measure arc_angle(const PointQ2& center, const Rational& radius, const OneRootPoint& from,
                           const OneRootPoint& to, const Rational& coefficient);

  Measure& operator+=(const Measure& other);
  Measure& operator-=(const Measure& other);
  Measure& operator*=(const Rational& factor);
  friend Measure operator+(Measure a, const Measure& b) { return a += b; }
  friend Measure operator-(Measure a, const Measure& b) { return a -= b; }
  friend Measure operator*(Measure a, const Rational& f) { return a *= f; }
  Measure operator-() const;

  bool is_zero() const;       ///< exact: no terms left
  bool is_algebraic() const;  ///< no transcendental term (nested radicals are algebraic; pi is not)
  /// The rational q of the term q*pi (0 when there is none).
  Rational pi_coefficient() const;
  bool has_special_terms() const { return !special_.empty(); }
  std::optional<Rational> rational_value() const;  ///< set when the value is rational

  /// Certified enclosure of the whole sum.
  Interval enclose(mpfr_prec_t bits) const;
  double to_double() const;
  /// Closed form ("4/3*pi + 1/2 + 3*sqrt(2) + sqrt(5 + 2*sqrt(6))": the pi term first, then the algebraic part in
  /// radicand order, then nested radicals) when every term has one; nullopt when an arc angle other than a
  /// multiple of pi/12 is left. Deterministic.
  std::optional<std::string> exact_string() const;

  /// Decimal text and whether its digits are proven.
  struct Decimal {
    std::string digits;     ///< "3.14159..." (significant digits, see hsx::decimal_string for the format)
    bool certified = true;  ///< false: the enclosure did not pin the digits down at 8192 bits (midpoint shown)
  };
  /// `significant` (>= 1) significant digits, refined until both ends of the enclosure round to the same text
  /// (then certified), or up to 8192 bits, after which the midpoint is returned with certified = false.
  Decimal decimal(int significant = 30) const;
  /// decimal(significant).digits, followed by "~" when not certified. "0" for zero.
  std::string decimal_string(int significant = 30) const;

  /// Exact sign where decidable: -1, 0, +1. Decided exactly (never nullopt) when the value is provably non-zero:
  /// no special terms, or a non-zero pi coefficient with only square roots and nested radicals besides (pi is
  /// transcendental). Otherwise the sign of a certified enclosure, or nullopt when it contains 0 at
  /// `options.max_bits`.
  std::optional<int> sign(const CompareOptions& options = {}) const;
  /// Certified double enclosure of the value (CGAL::Interval_nt arithmetic); nullopt when a term is outside the
  /// safe double range or the value has special terms other than pi.
  std::optional<DoubleBounds> double_bounds() const;

 private:
  /// Quadratic characters of a radicand k modulo 64 fixed primes q (measure.cpp): bit i of `residues` is set
  /// when k is a non-zero square mod q_i, of `divides` when q_i divides k. If k*j is a perfect square then
  /// (k|q)(j|q) = 1 for every q dividing neither, so the residues agree wherever neither divides: a necessary
  /// condition for "same square class", checked before the exact perfect-square test.
  struct ClassPrint {
    std::uint64_t residues = 0, divides = 0;
    bool known = false;
    bool compatible(const ClassPrint& o) const { return ((residues ^ o.residues) & ~(divides | o.divides)) == 0; }
  };
  struct Term {
    Rational c;
    ClassPrint print;  ///< computed when the measure is indexed (see below); radicand 1 has none
  };
  // radicand (positive integer, no two with a perfect-square product) -> coefficient; radicand 1 = rational part
  std::map<Integer, Term> algebraic_;
  struct Special {
    std::shared_ptr<const SpecialTerm> term;
    Rational coefficient;
  };
  std::map<std::string, Special> special_;  // keyed by SpecialTerm::key()
  // Radicands of algebraic_ not proven square-free; only these need the perfect-square-product scan when a
  // proven square-free radicand is added (see measure.cpp). Usually empty.
  std::set<Integer> unsure_;
  // Square-class index, built once a measure holds an unproven radicand among many terms (3D areas: thousands
  // of triangles with large radicands): every radicand other than 1 is in `classes_` under its residues, or in
  // `unclean_` when a fingerprint prime divides it. Finding a radicand's class partner is then a lookup.
  bool indexed_ = false;
  std::multimap<std::uint64_t, Integer> classes_;
  std::set<Integer> unclean_;

  static ClassPrint class_print(const Integer& radicand);
  void build_index();
  void index_insert(const Integer& radicand, const ClassPrint& print);
  void index_erase(const Integer& radicand, const ClassPrint& print);
  void erase_term(std::map<Integer, Term>::iterator it);
  const Integer* class_partner(const Integer& radicand, bool squarefree, ClassPrint* print);
  void add_sqrt_term(const Rational& coefficient, const Integer& radicand);
  void add_sqrt_rational(const Rational& coefficient, const Rational& q);  // coefficient*sqrt(q), q >= 0
  // radicand: positive, no square factor of a prime below 1000, not a square unless 1; squarefree: proven so.
  // print: the radicand's class print when the caller has it (another measure's term), else unknown.
  void insert_reduced(const Rational& coefficient, const Integer& radicand, bool squarefree, ClassPrint print);
  void add_measure(const Measure& other, bool negate);
  void add_special(const std::shared_ptr<const SpecialTerm>& term, const Rational& coefficient);
  static Measure multiply_algebraic(const Measure& a, const Measure& b);  // special terms are ignored
  int algebraic_sign(mpfr_prec_t start_bits) const;                      // exact sign of the algebraic part
  bool provably_nonzero() const;  // non-empty and (no special terms, or pi-coefficient != 0 and no arc angles)
  int refined_sign(mpfr_prec_t start_bits) const;  // sign of a provably non-zero value by refinement
  friend Order compare(const Measure& a, const Measure& b, const CompareOptions& options);
};

/// Certified comparison: Less/Equal/Greater are proofs; Tie (not separated at options.max_bits) never happens when
/// a - b has only square roots and pi left, nor with a non-zero pi coefficient and no arc-angle term (sign()).
Order compare(const Measure& a, const Measure& b, const CompareOptions& options = {});

}  // namespace hsx
