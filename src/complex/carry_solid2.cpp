#include <hsx/complex/carry_solid2.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace hsx {

std::vector<char> carry_solid_over(const Arrangement2& old_arrangement, const std::vector<char>& solid,
                                   const Arrangement2& refined) {
  std::vector<char> out;
  out.reserve(refined.faces().size());
  for (std::size_t f = 0; f < refined.faces().size(); ++f) {
    const PointLocation2 loc = old_arrangement.locate(refined.face_interiors()->get(f));
    if (loc.kind != PointLocation2::Face)
      throw std::logic_error("carrying a solid to a refinement: a refined cell is not inside an old cell");
    out.push_back(solid.at(static_cast<std::size_t>(loc.index)));
  }
  return out;
}

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
  out.reserve(to.arrangement.faces().size());
  long carried = 0;
  for (std::size_t f = 0; f < to.arrangement.faces().size(); ++f) {
    const PointLocation2 loc = from.arrangement.locate(to.arrangement.face_interiors()->get(f));
    const bool in = loc.kind == PointLocation2::Face && solid.at(static_cast<std::size_t>(loc.index));
    out.push_back(in ? 1 : 0);
    carried += in;
  }
  const long expected = std::count(solid.begin(), solid.end(), 1);
  if (carried != expected)
    throw std::logic_error("carrying the solid to the larger domain: " + std::to_string(carried) + " cells for " +
                           std::to_string(expected));
  return out;
}

}  // namespace hsx
