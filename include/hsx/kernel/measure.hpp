// Measures (lengths, areas) held exactly where that is decidable and as certified enclosures where it is not.
//
// A Measure is a finite sum   sum_k c_k * sqrt(k)  +  sum_t c_t * T_t
//   - the algebraic part: rational coefficients c_k over positive integer radicands k, kept so that no two
//     radicands have a perfect-square product (sqrt(8) is stored as 2*sqrt(2), sqrt(9) as 3). Square roots of
//     distinct square-free integers are linearly independent over Q, so this part is zero iff every coefficient is
//     zero, and its sign is decided by interval refinement, which terminates for a non-zero value.
//   - special terms T_t, each identified by a canonical key so that the same term on both sides of a comparison
//     cancels exactly:
//       * angle of a counter-clockwise circular arc (transcendental: arc length r*theta, area r^2/2*theta);
//       * nested radical sqrt(A + B*sqrt(c)) that does not denest (a segment ending on a circle).
//     Their signs are decided only by certified MPFR enclosures.
// See proofs/measures.md for what is exact, what is certified, and why.
#pragma once

#include <hsx/kernel/interval.hpp>
#include <hsx/kernel/one_root.hpp>
#include <hsx/kernel/rational.hpp>

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
  mpfr_prec_t max_bits = 2048;  ///< precision cap for special terms; purely algebraic values ignore it
};

/// A special (non-square-root) term: knows its canonical key, an exact text when algebraic, and how to enclose
/// its value at any precision.
class SpecialTerm {
 public:
  virtual ~SpecialTerm() = default;
  virtual const std::string& key() const = 0;
  virtual Interval enclose(mpfr_prec_t bits) const = 0;
  /// Closed form when the term is algebraic ("sqrt(3 + 2*sqrt(2))"), nullopt when transcendental.
  virtual std::optional<std::string> exact_string() const = 0;
};

class Measure {
 public:
  Measure() = default;  ///< zero
  Measure(const Rational& q);  // NOLINT: a rational is a measure

  /// sqrt(q) exactly; q >= 0 (throws std::domain_error otherwise).
  static Measure sqrt_of(const Rational& q);
  /// a*b exactly, as an algebraic sum (sqrt(c)*sqrt(d) = sqrt(c*d)).
  static Measure product(const OneRoot& a, const OneRoot& b);
  /// Euclidean distance |p - q|: exact sqrt of a rational when both points are rational, a denested sum when
  /// sqrt(A + B sqrt(c)) denests, otherwise a nested-radical special term.
  static Measure distance(const OneRootPoint& p, const OneRootPoint& q);
  /// coefficient * theta, theta in (0, 2*pi] the counter-clockwise angle from `from` to `to` around the circle
  /// (center, radius); from == to means the full circle (2*pi). Both points must lie on the circle (caller's
  /// duty). theta is a special term keyed by (center, radius, from, to), so the same arc cancels exactly.
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
  bool is_algebraic() const;  ///< no transcendental term (nested radicals are algebraic)
  bool has_special_terms() const { return !special_.empty(); }
  std::optional<Rational> rational_value() const;  ///< set when the value is rational

  /// Certified enclosure of the whole sum.
  Interval enclose(mpfr_prec_t bits) const;
  double to_double() const;
  /// Closed form ("1/2 + 3*sqrt(2) + sqrt(5 + 2*sqrt(6))") when algebraic, nullopt otherwise. Deterministic.
  std::optional<std::string> exact_string() const;
  /// At least `significant` correct significant digits (the enclosure is refined until they are pinned down, or
  /// until 8192 bits, after which the midpoint is printed). "0" for zero.
  std::string decimal_string(int significant = 30) const;

  /// Exact sign where decidable: -1, 0, +1; for values with special terms, the sign of a certified enclosure
  /// or nullopt when it contains 0 at `options.max_bits`.
  std::optional<int> sign(const CompareOptions& options = {}) const;

 private:
  // radicand (positive integer, no two with a perfect-square product) -> coefficient; radicand 1 = rational part
  std::map<Integer, Rational> algebraic_;
  struct Special {
    std::shared_ptr<const SpecialTerm> term;
    Rational coefficient;
  };
  std::map<std::string, Special> special_;  // keyed by SpecialTerm::key()
  // Radicands of algebraic_ not proven square-free; only these need the perfect-square-product scan when a
  // proven square-free radicand is added (see measure.cpp). Usually empty.
  std::set<Integer> unsure_;

  void add_sqrt_term(const Rational& coefficient, const Integer& radicand);
  void add_sqrt_rational(const Rational& coefficient, const Rational& q);  // coefficient*sqrt(q), q >= 0
  // radicand: positive, no square factor of a prime below 1000, not a square unless 1; squarefree: proven so.
  void insert_reduced(const Rational& coefficient, const Integer& radicand, bool squarefree);
  void add_measure(const Measure& other, bool negate);
  void add_special(const std::shared_ptr<const SpecialTerm>& term, const Rational& coefficient);
  static Measure multiply_algebraic(const Measure& a, const Measure& b);  // special terms are ignored
  int algebraic_sign(mpfr_prec_t start_bits) const;                      // exact sign of the algebraic part
  // Certified double enclosure [lo, hi] of the algebraic part (fast filter); false when not applicable
  // (special terms present, or magnitudes outside the safe double range).
  bool double_enclosure(double& lo, double& hi) const;
  friend Order compare(const Measure& a, const Measure& b, const CompareOptions& options);
};

/// Certified comparison: Less/Equal/Greater are proofs; Tie means the values were not separated at
/// options.max_bits. Tie never happens when a - b has no special terms left (all-straight boundaries).
Order compare(const Measure& a, const Measure& b, const CompareOptions& options = {});

}  // namespace hsx
