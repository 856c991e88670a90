// Random valid 2D scenes for property tests: a rapidcheck adapter over geometry/random_scene.hpp; see
// random_scenes.hpp.
#include "support/random_scenes.hpp"

#include <hsx/io/scene_json.hpp>

#include <algorithm>
#include <cstdint>
#include <set>
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

/// Scenes rich in exact ties and non-generic junctions: axis-aligned rectangles with corners on the integer grid
/// {0..3}^2 (shared and collinear edges, T-junctions), some of them complemented, with samples at boundary points
/// (multiples of 1/8) that lie inside patches; half of them contain a Fig. 6 pattern (below). Drawn at
/// full size from the first case on (rapidcheck otherwise scales ranges down for early cases).
rc::Gen<Scene2> gen_grid_scene() {
  return rc::gen::resize(100, rc::gen::exec([]() -> Scene2 {
    const Box2 box{pt(-1, -1), pt(5, 5)};
    std::vector<Halfspace2> hs;
    const bool fig6 = *rc::gen::inRange(0, 2) == 0;
    const int n = *rc::gen::inRange(fig6 ? 0 : 1, fig6 ? 3 : 5);
    for (int k = 0; k < n; ++k) {
      auto span = [] {
        const int a = *rc::gen::inRange(0, 4);
        const int b = (a + *rc::gen::inRange(1, 4)) % 4;
        return std::make_pair(std::min(a, b), std::max(a, b));
      };
      const auto [x0, x1] = span();
      const auto [y0, y1] = span();
      hs.push_back(polygon("P" + std::to_string(k), {pt(x0, y0), pt(x1, y0), pt(x1, y1), pt(x0, y1)},
                           *rc::gen::inRange(0, 6) == 0));
    }
    // Half of the time, a Fig. 6 pattern: squares A, B with a square gap between them and a rectangle over all
    // three, sampled at its two ends (on the rectangle and on A, B): two optimal boundaries if nothing
    // else interferes.
    std::vector<std::pair<std::string, PointQ2>> pattern_samples;
    if (fig6) {
      const bool vertical = *rc::gen::inRange(0, 2) == 0;
      const int off = *rc::gen::inRange(0, 3);
      auto at = [&](const Rational& u, const Rational& v) { return vertical ? pt(off + v, u) : pt(u, off + v); };
      auto rect = [&](const std::string& name, int u0, int u1) {
        return polygon(name, {at(u0, 0), at(u1, 0), at(u1, 1), at(u0, 1)});
      };
      const int k = static_cast<int>(hs.size());
      hs.push_back(rect("P" + std::to_string(k), 0, 1));
      hs.push_back(rect("P" + std::to_string(k + 1), 2, 3));
      hs.push_back(rect("P" + std::to_string(k + 2), 0, 3));
      const Rational half(1, 2);
      pattern_samples = {{hs[k].name, at(0, half)},     {hs[k + 2].name, at(0, half)},
                         {hs[k + 1].name, at(3, half)}, {hs[k + 2].name, at(3, half)}};
    }
    Scene2 scene = make_scene(box, hs);
    const Arrangement2 arrangement = Arrangement2::build(scene);
    for (const auto& [name, p] : pattern_samples)
      if (sample_fits(arrangement, scene.find_halfspace(name), p)) add_sample(scene, name, p);
    std::vector<std::pair<int, PointQ2>> fitting;
    for (int i = 0; i < static_cast<int>(scene.halfspaces.size()); ++i) {
      const auto& v = scene.halfspaces[i].vertices;
      for (std::size_t e = 0; e < v.size(); ++e)
        for (int t = 1; t < 8; ++t) {
          const PointQ2& a = v[e];
          const PointQ2& b = v[(e + 1) % v.size()];
          const Rational f = make_rational(t, 8);
          PointQ2 p{a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f};
          p.x.canonicalize();
          p.y.canonicalize();
          if (sample_fits(arrangement, i, p)) fitting.emplace_back(i, p);
        }
    }
    if (fitting.empty()) {
      validate_and_resolve(scene);
      return scene;
    }
    const int samples = fig6 ? *rc::gen::inRange(0, 4) : *rc::gen::inRange(1, 9);
    for (int k = 0; k < samples; ++k) {
      const auto& [i, p] = fitting[*rc::gen::inRange(0, static_cast<int>(fitting.size()))];
      add_sample(scene, scene.halfspaces[i].name, p);
    }
    validate_and_resolve(scene);
    return scene;
  }));
}

/// Generic scenes (every junction a transversal crossing) with exact ties: a rectangle R = [0,w]x[0,h] crossed by
/// vertical lines at integer x (either orientation) and maybe the line y = h/2, samples at multiples of 1/4 inside
/// patches. Half of them contain the tie of "bsh unit: Fig. 6 (generic)": a 2 x 2 room between x = a and
/// x = a + 2 with samples on both lines, on R's top and bottom over the room, and on R's two ends.
rc::Gen<Scene2> gen_rooms_scene() {
  return rc::gen::resize(100, rc::gen::exec([]() -> Scene2 {
    const bool tie = *rc::gen::inRange(0, 2) == 0;
    const int w = *rc::gen::inRange(tie ? 5 : 3, 7), h = tie ? 2 : *rc::gen::inRange(1, 3);
    std::vector<Halfspace2> hs{polygon("R", {pt(0, 0), pt(w, 0), pt(w, h), pt(0, h)})};
    std::set<int> used;
    std::vector<std::pair<std::string, PointQ2>> pattern_samples;
    if (tie) {
      // The generic tie of "bsh unit: Fig. 6 (generic)": a 2 x 2 room between x = a and x = a + 2.
      const int a = *rc::gen::inRange(1, w - 2);
      used = {a, a + 2};
      hs.push_back(halfplane("x" + std::to_string(a) + "-", pt(1, 0), a));
      hs.push_back(halfplane("x" + std::to_string(a + 2) + "+", pt(-1, 0), -(a + 2)));
      pattern_samples = {{hs[1].name, pt(a, 1)}, {hs[2].name, pt(a + 2, 1)}, {"R", pt(a + 1, 0)},
                         {"R", pt(a + 1, 2)},    {"R", pt(0, 1)},           {"R", pt(w, 1)}};
    }
    const int n = *rc::gen::inRange(tie ? 0 : 1, tie ? 2 : 4);
    for (int k = 0; k < n; ++k) {
      const int c = *rc::gen::inRange(1, w);
      if (!used.insert(c).second) continue;
      const int sign = *rc::gen::inRange(0, 2) ? 1 : -1;
      hs.push_back(halfplane("x" + std::to_string(c) + (sign > 0 ? "-" : "+"), pt(sign, 0), sign * c));
    }
    if (*rc::gen::inRange(0, 2)) hs.push_back(halfplane("y", pt(0, 1), make_rational(h, 2)));
    Scene2 scene = make_scene(Box2{pt(-1, -1), pt(w + 1, h + 1)}, hs);
    const Arrangement2 arrangement = Arrangement2::build(scene);
    std::vector<std::pair<int, PointQ2>> fitting;
    for (int i = 0; i < static_cast<int>(scene.halfspaces.size()); ++i)
      for (int x = 0; x <= 4 * w; ++x)
        for (int y = 0; y <= 4 * h; ++y) {
          const PointQ2 p = pt(make_rational(x, 4), make_rational(y, 4));
          if (scene.halfspaces[i].side(p) == 0 && sample_fits(arrangement, i, p)) fitting.emplace_back(i, p);
        }
    for (const auto& [name, p] : pattern_samples)
      if (sample_fits(arrangement, scene.find_halfspace(name), p)) add_sample(scene, name, p);
    const int samples = tie ? *rc::gen::inRange(0, 3) : *rc::gen::inRange(1, 9);
    for (int k = 0; k < samples && !fitting.empty(); ++k) {
      const auto& [i, p] = fitting[*rc::gen::inRange(0, static_cast<int>(fitting.size()))];
      add_sample(scene, scene.halfspaces[i].name, p);
    }
    validate_and_resolve(scene);
    return scene;
  }));
}

RandomSceneSettings per_halfspace_sampled(int halfspaces) {
  RandomSceneSettings s;
  s.min_halfspaces = s.max_halfspaces = halfspaces;
  s.min_samples_per_halfspace = 1;
  s.max_samples_per_halfspace = 3;
  return s;
}

}  // namespace hsx::test

namespace hsx {
void showValue(const Scene2& scene, std::ostream& os) { os << test::scene_text(scene); }
void showValue(const PointQ2& p, std::ostream& os) { os << "[" << exact_string(p.x) << ", " << exact_string(p.y) << "]"; }
}  // namespace hsx
