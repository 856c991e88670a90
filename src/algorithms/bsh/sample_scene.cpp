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

Scene3 scene_with_samples(const Scene3& scene, const Arranged3& arranged, const std::vector<int>& patches,
                          const std::string& description) {
  Scene3 out = scene;
  out.description = description;
  out.samples.clear();
  const auto& triangles = arranged.arrangement.triangles();
  const auto& vertices = arranged.arrangement.vertices();
  for (int p : patches) {
    const Patch& patch = arranged.complex.patches.at(static_cast<std::size_t>(p));
    int largest = patch.pieces.at(0);
    for (int t : patch.pieces)
      if (triangles.at(static_cast<std::size_t>(t)).area2 > triangles[static_cast<std::size_t>(largest)].area2) largest = t;
    const auto& v = triangles[static_cast<std::size_t>(largest)].vertices;
    const PointQ3& a = vertices.at(static_cast<std::size_t>(v[0]));
    const PointQ3& b = vertices.at(static_cast<std::size_t>(v[1]));
    const PointQ3& c = vertices.at(static_cast<std::size_t>(v[2]));
    const Rational third(1, 3);
    Sample3 s;
    s.halfspace = patch.halfspace;
    s.given = PointQ3{(a.x + b.x + c.x) * third, (a.y + b.y + c.y) * third, (a.z + b.z + c.z) * third};
    s.location = s.given;
    out.samples.push_back(s);
  }
  return out;
}

}  // namespace hsx::bsh
