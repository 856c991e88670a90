#include <hsx/algorithms/bsh/sample_scene.hpp>

#include "geometry/planar_points.hpp"

namespace hsx::bsh {

Scene2 scene_with_samples(const Scene2& scene, const Arranged2& arranged, const std::vector<int>& patches,
                          const std::string& description) {
  Scene2 out = scene;
  out.description = description;
  out.samples.clear();
  for (int p : patches) {
    const Patch& patch = arranged.complex.patches.at(p);
    const int edge = patch.pieces.at(patch.pieces.size() / 2);
    Sample2 s;
    s.halfspace = patch.halfspace;
    s.given = rational_point_inside_edge(arranged.arrangement.edges().at(edge), arranged.arrangement.vertices());
    s.location = OneRootPoint(s.given);
    out.samples.push_back(s);
  }
  return out;
}

}  // namespace hsx::bsh
