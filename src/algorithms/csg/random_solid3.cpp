// Random bounded 3D solids: see random_solid3.hpp (the procedure is specified there, draw by draw).
#include <hsx/algorithms/csg/random_solid3.hpp>
#include <hsx/geometry/scene_builders.hpp>

#include <hsx/geometry/tessellate3.hpp>
#include <hsx/kernel/random.hpp>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace hsx::csg {
namespace {

Rational half(Random& rng, long lo, long hi) { return Rational(rng.in(lo, hi)) / 2; }
PointQ3 point(Random& rng) {
  Rational x = half(rng, -4, 4);
  Rational y = half(rng, -4, 4);
  return {x, y, half(rng, -4, 4)};
}

class Drawer {
 public:
  Drawer(Random& rng, int segments, Scene3& scene) : rng_(rng), segments_(segments), scene_(scene) {}

  /// Appends primitive k's halfspaces and returns its expression; `inner` receives its inner primitive's
  /// expression when asked for and it has one.
  ExprPtr draw(int k, std::optional<ExprPtr>* inner) {
    const std::string id = std::to_string(k);
    const long kind = rng_.in(0, 9);
    if (kind <= 2) {
      const PointQ3 lo = point(rng_);
      Rational sx = half(rng_, 2, 8);
      Rational sy = half(rng_, 2, 8);
      Rational sz = half(rng_, 2, 8);
      const PointQ3 hi{lo.x + sx, lo.y + sy, lo.z + sz};
      ExprPtr e = box("b" + id, lo, hi);
      if (inner) {
        const Rational r = std::min({sx, sy, sz}) / 6;
        *inner = sphere("i", {(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2}, r);
      }
      return e;
    }
    if (kind <= 5) {
      const PointQ3 c = point(rng_);
      const Rational r = half(rng_, 2, 6);
      ExprPtr e = sphere("s" + id, c, r);
      if (inner) {
        const Rational d = r / 3;
        *inner = box("i", {c.x - d, c.y - d, c.z - d}, {c.x + d, c.y + d, c.z + d});
      }
      return e;
    }
    if (kind <= 7) {
      const long axis = rng_.in(0, 2);
      const PointQ3 c = point(rng_);
      const Rational r = half(rng_, 1, 4);
      const Rational l = half(rng_, 2, 6);
      PointQ3 a = c, b = c;
      Rational& ca = axis == 0 ? a.x : axis == 1 ? a.y : a.z;
      Rational& cb = axis == 0 ? b.x : axis == 1 ? b.y : b.z;
      ca -= l;
      cb += l;
      Halfspace3 h = curved("c" + id, HalfspaceKind3::Cylinder);
      h.primitive.point1 = a;
      h.primitive.point2 = b;
      h.primitive.radius = r;
      return add(std::move(h));
    }
    const long d = rng_.in(0, 12);
    int count = 0;
    PointQ3 normal;
    for (int x = 0; x <= 1 && count <= d; ++x)
      for (int y = -1; y <= 1 && count <= d; ++y)
        for (int z = -1; z <= 1 && count <= d; ++z) {
          const bool leading = x == 1 || (x == 0 && (y == 1 || (y == 0 && z == 1)));
          if (!leading) continue;
          if (count++ == d) normal = {Rational(x), Rational(y), Rational(z)};
        }
    return plane("p" + id, normal, point(rng_));
  }

 private:
  ExprPtr add(Halfspace3 h) {
    if (h.kind != HalfspaceKind3::Plane) {
      h.surface = tessellate(h, Box3{});
      h.origin = tessellation_summary(h);
    }
    scene_.halfspaces.push_back(std::move(h));
    return leaf(static_cast<int>(scene_.halfspaces.size()) - 1);
  }
  Halfspace3 curved(const std::string& name, HalfspaceKind3 kind) const {
    Halfspace3 h;
    h.name = name;
    h.kind = kind;
    h.primitive.tessellation.segments = segments_;
    return h;
  }
  ExprPtr plane(const std::string& name, const PointQ3& normal, const PointQ3& through) {
    return add(plane_through(name, normal, through));
  }
  ExprPtr box(const std::string& name, const PointQ3& lo, const PointQ3& hi) {
    const Rational one(1), zero(0);
    return intersect({plane(name + ".xmin", {-one, zero, zero}, lo), plane(name + ".xmax", {one, zero, zero}, hi),
                      plane(name + ".ymin", {zero, -one, zero}, lo), plane(name + ".ymax", {zero, one, zero}, hi),
                      plane(name + ".zmin", {zero, zero, -one}, lo), plane(name + ".zmax", {zero, zero, one}, hi)});
  }
  ExprPtr sphere(const std::string& name, const PointQ3& c, const Rational& r) {
    Halfspace3 h = curved(name, HalfspaceKind3::Sphere);
    h.primitive.center = c;
    h.primitive.radius = r;
    return add(std::move(h));
  }

  Random& rng_;
  int segments_;
  Scene3& scene_;
};

}  // namespace

RandomSolid3 random_solid3(const RandomSolid3Settings& settings, std::uint64_t seed, std::uint64_t index,
                           const ArrangementLimits& limits, int* drawn) {
  if (drawn) *drawn = 0;
  if (settings.min_primitives < 1 || settings.max_primitives < settings.min_primitives ||
      settings.max_primitives > kMaxRandomPrimitives3)
    throw std::invalid_argument("RandomSolid3Settings: need 1 <= min_primitives <= max_primitives <= " +
                                std::to_string(kMaxRandomPrimitives3));
  if (settings.segments < 6 || settings.segments > 64)
    throw std::invalid_argument("RandomSolid3Settings: segments must be in [6, 64]");
  if (settings.max_draws < 1) throw std::invalid_argument("RandomSolid3Settings: max_draws must be >= 1");
  Random rng(item_seed(seed, index));
  for (int draw = 1;; ++draw) {
    RandomSolid3 r;
    const int primitives = static_cast<int>(rng.in(settings.min_primitives, settings.max_primitives));
    std::vector<ExprPtr> parts;
    std::optional<ExprPtr> inner;
    Drawer drawer(rng, settings.segments, r.scene);
    for (int k = 0; k < primitives; ++k) parts.push_back(drawer.draw(k, settings.hollow && k == 0 ? &inner : nullptr));
    r.expression = random_combination(rng, parts);
    if (inner) {
      r.expression = difference(unite({r.expression, parts.front()}), *inner);
      r.hollowed = true;
    }
    r.scene.description = "random 3D CSG solid " + std::to_string(index) + " of seed " + std::to_string(seed) +
                          (settings.hollow ? " (hollow)" : "");
    if (drawn) *drawn = static_cast<int>(r.scene.halfspaces.size());
    validate_and_resolve(r.scene);
    Arrangement3Options options;
    options.volumes = false;
    options.threads = 1;
    r.arranged = arrange(r.scene, limits, options);
    r.solid = evaluate(*r.expression, r.arranged.complex);
    r.status = solid_status(r.arranged.complex, r.solid);
    r.draws = draw;
    if (r.status == SolidStatus::Bounded || draw >= settings.max_draws) return r;
  }
}

}  // namespace hsx::csg
