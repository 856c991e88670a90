#include "geometry/planar_points.hpp"

#include <stdexcept>

namespace hsx {
namespace {

/// A rational strictly between two distinct one-root numbers lo < hi, close to their midpoint.
Rational middle_rational(const OneRoot& lo, const OneRoot& hi) {
  for (mpfr_prec_t bits = 64; bits <= (1 << 16); bits *= 2) {
    Interval mid = (lo.enclose(bits) + hi.enclose(bits)) * Interval(Rational(1, 2), bits);
    mpq_class q;
    mpfr_get_q(q.get_mpq_t(), mid.lo());
    q.canonicalize();
    if (compare(lo, OneRoot(q)) < 0 && compare(OneRoot(q), hi) < 0) return q;
  }
  throw std::runtime_error("no rational point found between two edge ends");
}

int sign_of_cross(const PointQ2& c, const OneRootPoint& a, const OneRootPoint& b) {
  // (a - c) x (b - c) = (ax - cx)(by - cy) - (ay - cy)(bx - cx), expanded into exact products.
  const OneRoot cx(c.x), cy(c.y);
  Measure m = Measure::product(a.x, b.y) - Measure::product(a.x, cy) - Measure::product(cx, b.y) -
              Measure::product(a.y, b.x) + Measure::product(a.y, cx) + Measure::product(cy, b.x);
  return *m.sign();
}

}  // namespace

PointQ2 rational_point_inside_edge(const ArrEdge2& e, const std::vector<ArrVertex2>& vertices) {
  const OneRootPoint& a = vertices.at(e.source).point;
  const OneRootPoint& b = vertices.at(e.target).point;
  if (e.shape == EdgeShape2::Segment) {
    if (a.is_rational() && b.is_rational())
      return {(a.x.a0 + b.x.a0) / 2, (a.y.a0 + b.y.a0) / 2};
    if (e.line_a == 0 && e.line_b == 0) throw std::runtime_error("segment edge without a known supporting line");
    if (e.line_b != 0) {  // not vertical: choose x, solve for y
      const bool ascending = compare(a.x, b.x) < 0;
      const Rational x = ascending ? middle_rational(a.x, b.x) : middle_rational(b.x, a.x);
      return {x, -(e.line_a * x + e.line_c) / e.line_b};
    }
    const bool ascending = compare(a.y, b.y) < 0;
    const Rational y = ascending ? middle_rational(a.y, b.y) : middle_rational(b.y, a.y);
    return {-(e.line_c) / e.line_a, y};
  }
  // Arc: counter-clockwise from `from` to `to`.
  const OneRootPoint& from = e.ccw ? a : b;
  const OneRootPoint& to = e.ccw ? b : a;
  const Rational& r = e.radius;
  for (mpfr_prec_t bits = 64; bits <= (1 << 14); bits *= 2) {
    // The middle angle from midpoint enclosures of both ends (approximate: the result is verified exactly).
    auto angle_of = [&](mpfr_t out, const OneRootPoint& p) {
      const Interval dx = p.x.enclose(bits) - Interval(e.center.x, bits);
      const Interval dy = p.y.enclose(bits) - Interval(e.center.y, bits);
      mpfr_atan2(out, dy.lo(), dx.lo(), MPFR_RNDN);
    };
    mpfr_t phi_from, phi_to, scratch, t;
    mpfr_inits2(bits, phi_from, phi_to, scratch, t, static_cast<mpfr_ptr>(nullptr));
    angle_of(phi_from, from);
    angle_of(phi_to, to);
    if (mpfr_cmp(phi_to, phi_from) <= 0) {  // counter-clockwise: make phi_to > phi_from
      mpfr_const_pi(scratch, MPFR_RNDN);
      mpfr_mul_ui(scratch, scratch, 2, MPFR_RNDN);
      mpfr_add(phi_to, phi_to, scratch, MPFR_RNDN);
    }
    mpfr_add(scratch, phi_from, phi_to, MPFR_RNDN);
    mpfr_div_ui(scratch, scratch, 4, MPFR_RNDN);  // half of the middle angle
    mpfr_tan(t, scratch, MPFR_RNDN);
    mpq_class tq;
    const bool finite = mpfr_number_p(t) != 0;
    if (finite) {
      mpfr_get_q(tq.get_mpq_t(), t);
      tq.canonicalize();
    }
    mpfr_clears(phi_from, phi_to, scratch, t, static_cast<mpfr_ptr>(nullptr));
    if (!finite) continue;
    const Rational d = 1 + tq * tq;
    const PointQ2 p{e.center.x + r * (1 - tq * tq) / d, e.center.y + 2 * r * tq / d};
    // Strictly inside an arc of at most pi: strictly left of from->p and of p->to around the centre.
    if (sign_of_cross(e.center, from, OneRootPoint(p)) > 0 && sign_of_cross(e.center, OneRootPoint(p), to) > 0)
      return p;
  }
  throw std::runtime_error("no rational point found inside an arc");
}

}  // namespace hsx
