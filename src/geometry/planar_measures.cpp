#include "geometry/planar_measures.hpp"

namespace hsx {

namespace {

/// |q - p| along the rational line a x + b y + c = 0 (b != 0): |dx| * sqrt(a^2 + b^2) / |b|, an exact sum of
/// square roots even when p and q carry different radicals (two circles cutting one segment); with b == 0, |dy|.
Measure length_on_line(const ArrEdge2& e, const OneRootPoint& p, const OneRootPoint& q) {
  const bool vertical = e.line_b == 0;
  const OneRoot& u0 = vertical ? p.y : p.x;
  const OneRoot& u1 = vertical ? q.y : q.x;
  const Rational scale = vertical ? Rational(1) : (e.line_a * e.line_a + e.line_b * e.line_b) / (e.line_b * e.line_b);
  const int sign = compare(u1, u0) >= 0 ? 1 : -1;
  // sign * (u1 - u0) * sqrt(scale), term by term: (a0 + a1 sqrt(r)) sqrt(s) = a0 sqrt(s) + a1 sqrt(r s).
  Measure m = Measure::sqrt_of(scale) * Rational(sign * (u1.a0 - u0.a0));
  if (!u1.is_rational()) m += Measure::sqrt_of(u1.root * scale) * Rational(sign * u1.a1);
  if (!u0.is_rational()) m -= Measure::sqrt_of(u0.root * scale) * Rational(sign * u0.a1);
  return m;
}

}  // namespace

Measure edge_length(const ArrEdge2& edge, const OneRootPoint& from, const OneRootPoint& to) {
  if (edge.shape == EdgeShape2::Segment) {
    if (edge.line_a == 0 && edge.line_b == 0) return Measure::distance(from, to);  // line unknown
    return length_on_line(edge, from, to);
  }
  return edge.ccw ? Measure::arc_angle(edge.center, edge.radius, from, to, edge.radius)
                  : Measure::arc_angle(edge.center, edge.radius, to, from, edge.radius);
}

Measure enclosed_area(const std::vector<std::vector<std::pair<int, bool>>>& walks,
                      const std::vector<ArrEdge2>& edges, const std::vector<ArrVertex2>& vertices) {
  Measure area;
  for (const auto& walk : walks)
    for (const auto& [ei, forward] : walk) {
      const ArrEdge2& e = edges.at(ei);
      const OneRootPoint& p = vertices.at(forward ? e.source : e.target).point;
      const OneRootPoint& q = vertices.at(forward ? e.target : e.source).point;
      if (e.shape == EdgeShape2::Segment) {
        area += (Measure::product(p.x, q.y) - Measure::product(q.x, p.y)) * Rational(1, 2);
        continue;
      }
      // Along the circle x = c + r(cos t, sin t): x dy - y dx = (cx r cos t + cy r sin t + r^2) dt, whose
      // integral is cx (qy - py) - cy (qx - px) + r^2 * theta (theta signed by the direction of travel).
      const OneRoot cx(e.center.x), cy(e.center.y);
      area += (Measure::product(cx, q.y) - Measure::product(cx, p.y) - Measure::product(cy, q.x) +
               Measure::product(cy, p.x)) *
              Rational(1, 2);
      const bool travel_ccw = forward == e.ccw;
      const Rational half_r2 = e.radius * e.radius / 2;
      area += travel_ccw ? Measure::arc_angle(e.center, e.radius, p, q, half_r2)
                         : Measure::arc_angle(e.center, e.radius, q, p, -half_r2);
    }
  return area;
}

}  // namespace hsx
