// Exact rational points placed on arrangement edges (samples written back into scenes must be exact `at` points).
#pragma once

#include <hsx/geometry/arrangement2.hpp>

namespace hsx {

/// A rational point strictly inside the edge (not at an end), near its middle:
/// - a segment: the midpoint when both ends are rational; otherwise a rational x (or y, when vertical) close to
///   the middle, with the other coordinate from the supporting line;
/// - an arc: the rational point of the circle cx + r(1-t^2)/(1+t^2), cy + 2rt/(1+t^2) whose parameter t
///   approximates tan(phi/2) at the arc's middle angle phi, refined until the point is proven strictly inside.
/// Throws std::runtime_error when it cannot (a segment with irrational ends and no known supporting line).
PointQ2 rational_point_inside_edge(const ArrEdge2& edge, const std::vector<ArrVertex2>& vertices);

}  // namespace hsx
