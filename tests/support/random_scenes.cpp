// Random valid 2D scenes for property tests: a rapidcheck adapter over geometry/random_scene.hpp; see
// random_scenes.hpp.
#include "support/random_scenes.hpp"

#include <hsx/io/scene_json.hpp>

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace hsx::test {
namespace {

PointQ2 add(const PointQ2& a, const PointQ2& b) { return {a.x + b.x, a.y + b.y}; }
Rational dot(const PointQ2& a, const PointQ2& b) { return a.x * b.x + a.y * b.y; }

/// A generator of `value` that shrinks towards `target` (rapidcheck's size plays no part).
rc::Gen<int> shrinking(int value, int target) {
  return rc::Gen<int>([value, target](const rc::Random&, int) {
    return rc::shrinkable::shrinkRecur(value, [target](int v) { return rc::shrink::towards(v, target); });
  });
}

/// The seed of one generated value: uniform over 64 bits from the first test on (rapidcheck scales integers with
/// its size, which would give the first tests seeds 0, 1, ...), never shrunk (a shrunk seed is just another scene).
std::uint64_t draw_seed() {
  return *rc::gen::noShrink(rc::gen::resize(rc::kNominalSize, rc::gen::arbitrary<std::uint64_t>()));
}

}  // namespace

RandomSceneSettings scene_settings(const SceneGenOptions& o) {
  RandomSceneSettings s;
  s.min_halfspaces = 1;
  s.max_halfspaces = std::max(1, o.max_halfspaces);
  s.halfplanes = o.halfplanes;
  s.disks = o.disks;
  s.polygons = o.polygons;
  s.complement_percent = o.complements ? 25 : 0;
  s.denominator = o.denominator;
  s.coordinate_bound = o.coordinate_bound;
  s.min_degeneracies = std::max(0, std::min(o.min_degeneracies, o.max_degeneracies));
  s.max_degeneracies = std::max(0, o.max_degeneracies);
  if (!o.allowed_degeneracies.empty()) {
    s.degeneracy_weight.fill(0);
    for (Degeneracy d : o.allowed_degeneracies) s.degeneracy_weight[static_cast<std::size_t>(d)] = 1;
  }
  s.max_samples = o.samples ? std::max(0, o.max_samples) : 0;
  s.near_percent = o.near_samples ? 33 : 0;
  return s;
}

rc::Gen<Scene2> gen_scene(const SceneGenOptions& options) {
  return rc::gen::exec([options]() -> Scene2 {
    const std::uint64_t seed = draw_seed();
    RandomSceneSettings s = scene_settings(options);
    s.max_halfspaces = *shrinking(s.max_halfspaces, 1);
    s.max_samples = *shrinking(s.max_samples, 0);
    if (s.complement_percent > 0 && *shrinking(1, 0) == 0) s.complement_percent = 0;
    return random_scene(s, seed, 0).scene;
  });
}

rc::Gen<PointQ2> gen_point_in(const Box2& box, int denominator) {
  return rc::gen::exec([box, denominator]() -> PointQ2 {
    Random rng(draw_seed());
    return random_grid_point_in(rng, box, denominator);
  });
}

Scene2 translated(const Scene2& scene, const PointQ2& d) {
  Scene2 out = scene;
  out.domain.min = add(out.domain.min, d);
  out.domain.max = add(out.domain.max, d);
  for (Halfspace2& h : out.halfspaces) {
    h.offset += dot(h.normal, d);
    h.center = add(h.center, d);
    for (PointQ2& v : h.vertices) v = add(v, d);
  }
  for (Sample2& s : out.samples) s.given = add(s.given, d);
  validate_and_resolve(out);
  return out;
}

Scene2 permuted(const Scene2& scene, const std::vector<int>& order) {
  Scene2 out = scene;
  std::vector<int> new_index(order.size(), -1);
  for (std::size_t k = 0; k < order.size(); ++k) {
    out.halfspaces[k] = scene.halfspaces.at(order[k]);
    new_index.at(order[k]) = static_cast<int>(k);
  }
  for (Sample2& s : out.samples) s.halfspace = new_index.at(s.halfspace);
  validate_and_resolve(out);
  return out;
}

Rational q(const std::string& text) {
  std::string why;
  auto r = parse_rational(text, &why);
  if (!r) throw std::invalid_argument("q(\"" + text + "\"): " + why);
  return *r;
}

PointQ2 pt(const Rational& x, const Rational& y) { return PointQ2{x, y}; }

void add_sample(Scene2& scene, const std::string& on, const PointQ2& at, bool near) {
  Sample2 s;
  s.halfspace = scene.find_halfspace(on);
  if (s.halfspace < 0) throw std::invalid_argument("add_sample: no halfspace named " + on);
  s.given = at;
  s.snapped = near;
  scene.samples.push_back(s);
}

Scene2 make_scene(const Box2& domain, std::vector<Halfspace2> halfspaces) {
  Scene2 s;
  s.domain = domain;
  s.domain_given = true;
  s.halfspaces = std::move(halfspaces);
  validate_and_resolve(s);
  return s;
}

std::string scene_text(const Scene2& scene) { return write_scene2(scene).dump(); }

}  // namespace hsx::test

namespace hsx {
void showValue(const Scene2& scene, std::ostream& os) { os << test::scene_text(scene); }
void showValue(const PointQ2& p, std::ostream& os) { os << "[" << exact_string(p.x) << ", " << exact_string(p.y) << "]"; }
}  // namespace hsx
