#include <hsx/complex/whole_plane.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace hsx {

Scene2 whole_plane_scene(const Scene2& scene) {
  Scene2 free = scene;
  free.samples.clear();
  free.domain_given = false;
  const Box2 chosen = choose_domain(free);
  Scene2 out = free;
  out.domain = chosen;
  if (scene.domain_given) {
    out.domain.min.x = std::min(chosen.min.x, scene.domain.min.x);
    out.domain.min.y = std::min(chosen.min.y, scene.domain.min.y);
    out.domain.max.x = std::max(chosen.max.x, scene.domain.max.x);
    out.domain.max.y = std::max(chosen.max.y, scene.domain.max.y);
  }
  out.domain_given = true;
  validate_and_resolve(out);
  return out;
}

std::vector<char> carry_to_whole_plane(const Arranged2& from, const std::vector<char>& solid, const Arranged2& to) {
  std::vector<char> out;
  long carried = 0;
  for (const ArrFace2& f : to.arrangement.faces()) {
    const PointLocation2 loc = from.arrangement.locate(f.interior);
    const bool in = loc.kind == PointLocation2::Face && solid.at(static_cast<std::size_t>(loc.index));
    out.push_back(in ? 1 : 0);
    carried += in;
  }
  if (carried != std::count(solid.begin(), solid.end(), 1))
    throw std::logic_error("carrying the solid to the larger domain: " + std::to_string(carried) + " cells for " +
                           std::to_string(std::count(solid.begin(), solid.end(), 1)));
  return out;
}

}  // namespace hsx
