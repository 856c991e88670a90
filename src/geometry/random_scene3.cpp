#include <hsx/geometry/random_scene3.hpp>

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
    Halfspace3 h;
    h.name = "P" + std::to_string(k);
    h.kind = HalfspaceKind3::Plane;
    do {
      h.normal.x = rng.in(-m, m);
      h.normal.y = rng.in(-m, m);
      h.normal.z = rng.in(-m, m);
    } while (h.normal.x == 0 && h.normal.y == 0 && h.normal.z == 0);
    PointQ3 p;
    for (Rational* c : {&p.x, &p.y, &p.z}) *c = make_rational(rng.in(-(b - 1) * d, (b - 1) * d), d);
    h.offset = h.normal.x * p.x + h.normal.y * p.y + h.normal.z * p.z;
    h.origin = "random plane";
    h.complement = rng.one_in(4);
    scene.halfspaces.push_back(std::move(h));
  }
  return scene;
}

}  // namespace hsx
