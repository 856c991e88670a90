// Exact measures of 2D arrangement pieces (CGAL-free, so io/ can recompute them from serialised geometry).
#pragma once

#include <hsx/geometry/arrangement2.hpp>

#include <utility>
#include <vector>

namespace hsx {

/// Length of an edge running from `from` to `to` (its source and target points): sqrt for a segment, r*theta
/// (a special term keyed by the counter-clockwise arc) for an arc.
Measure edge_length(const ArrEdge2& edge, const OneRootPoint& from, const OneRootPoint& to);

/// Area enclosed by boundary walks with the region on their left (outer walk counter-clockwise, holes
/// clockwise), by Green's theorem: 1/2 * closed integral of (x dy - y dx). A shared arc contributes the same
/// special term with opposite signs to its two faces, so areas add up exactly.
/// `walks`: cycles of (edge index, forward?) into `edges`; `vertices`: edge end points.
Measure enclosed_area(const std::vector<std::vector<std::pair<int, bool>>>& walks,
                      const std::vector<ArrEdge2>& edges, const std::vector<ArrVertex2>& vertices);

}  // namespace hsx
