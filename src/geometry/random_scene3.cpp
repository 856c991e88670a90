#include <hsx/geometry/random_scene3.hpp>
#include <hsx/geometry/scene_builders.hpp>

#include <hsx/kernel/random.hpp>

#include <stdexcept>
#include <string>

namespace hsx {

Scene3 random_plane_scene3(const RandomPlanesSettings& settings, std::uint64_t seed, std::uint64_t index) {
  if (settings.planes < 1 || settings.max_coefficient < 1 || settings.coordinate_bound < 2 || settings.denominator < 1)
    throw std::invalid_argument("random_plane_scene3: settings out of range");
  Random rng(item_seed(seed, index));
  const long b = settings.coordinate_bound, d = settings.denominator, m = settings.max_coefficient;
  Scene3 scene;
  scene.description = std::to_string(settings.planes) + " random planes";
  scene.domain = {{Rational(-b), Rational(-b), Rational(-b)}, {Rational(b), Rational(b), Rational(b)}};
  scene.domain_given = true;
  for (int k = 0; k < settings.planes; ++k) {
    PointQ3 normal;
    do {
      normal.x = rng.in(-m, m);
      normal.y = rng.in(-m, m);
      normal.z = rng.in(-m, m);
    } while (normal.x == 0 && normal.y == 0 && normal.z == 0);
    PointQ3 p;
    for (Rational* c : {&p.x, &p.y, &p.z}) *c = make_rational(rng.in(-(b - 1) * d, (b - 1) * d), d);
    Halfspace3 h = plane_through("P" + std::to_string(k), normal, p);
    h.origin = "random plane";
    h.complement = rng.one_in(4);
    scene.halfspaces.push_back(std::move(h));
  }
  return scene;
}

}  // namespace hsx
