// Carrying a 3D solid to a larger domain: see carry_solid3.hpp.
#include <hsx/complex/carry_solid3.hpp>

#include <hsx/geometry/tessellate3.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace hsx {

Scene3 whole_space_scene3(const Scene3& scene) {
  Scene3 s = scene;
  s.samples.clear();
  const Box3 chosen = choose_domain3(s);
  Box3 box = s.domain;
  box.min = {std::min(box.min.x, chosen.min.x), std::min(box.min.y, chosen.min.y), std::min(box.min.z, chosen.min.z)};
  box.max = {std::max(box.max.x, chosen.max.x), std::max(box.max.y, chosen.max.y), std::max(box.max.z, chosen.max.z)};
  if (box.min == s.domain.min && box.max == s.domain.max) return s;
  s.domain = box;
  s.domain_given = true;
  for (Halfspace3& h : s.halfspaces)
    if (h.kind == HalfspaceKind3::Cylinder && h.primitive.infinite) h.surface = tessellate(h, s.domain);
  validate_and_resolve(s);
  return s;
}

std::vector<char> carry_to_whole_space(const Arranged3& from, const std::vector<char>& solid, const Arranged3& to) {
  if (solid.size() != from.arrangement.cells().size())
    throw std::invalid_argument("carry_to_whole_space: " + std::to_string(solid.size()) + " flags for " +
                                std::to_string(from.arrangement.cells().size()) + " cells");
  const auto& cells = to.arrangement.cells();
  std::vector<char> out(cells.size(), 0);
  long inside = 0;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (cells[c].outer) continue;
    const PointLocation3 where = from.arrangement.locate(cells[c].interior);
    if (where.kind == PointLocation3::Cell && solid.at(static_cast<std::size_t>(where.index))) {
      out[c] = 1;
      ++inside;
    }
  }
  const long expected = std::count_if(solid.begin(), solid.end(), [](char f) { return f != 0; });
  if (inside != expected)
    throw std::logic_error("carry_to_whole_space: " + std::to_string(expected) + " solid cells became " +
                           std::to_string(inside) + " (the solid touches the smaller domain's box?)");
  return out;
}

}  // namespace hsx
