#include "geometry/planar_measures.hpp"

namespace hsx {

Measure edge_length(const ArrEdge2& edge, const OneRootPoint& from, const OneRootPoint& to) {
  if (edge.shape == EdgeShape2::Segment) return Measure::distance(from, to);
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
