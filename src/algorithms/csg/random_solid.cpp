// Random bounded 2D solids: see random_solid.hpp (the procedure is specified there, draw by draw).
#include <hsx/algorithms/csg/random_solid.hpp>

#include <hsx/geometry/scene_builders.hpp>
#include <hsx/kernel/random.hpp>

#include <stdexcept>
#include <string>
#include <utility>

namespace hsx::csg {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

/// h(a, b) of the header: a multiple of 1/2 in [a/2, b/2].
Rational half(Random& rng, long lo, long hi) { return Rational(rng.in(lo, hi)) / 2; }
PointQ2 half_point(Random& rng, long lo, long hi) {
  Rational x = half(rng, lo, hi);
  return {x, half(rng, lo, hi)};
}

// The 16 primitive integer directions of max-norm <= 2, counter-clockwise from (1, 0).
const int kDirections[16][2] = {{1, 0},  {2, 1},   {1, 1},   {1, 2},  {0, 1},   {-1, 2},  {-1, 1}, {-2, 1},
                                {-1, 0}, {-2, -1}, {-1, -1}, {-1, -2}, {0, -1}, {1, -2}, {1, -1}, {2, -1}};

class PrimitiveDrawer {
 public:
  PrimitiveDrawer(Random& rng, bool polygons, Scene2& scene) : rng_(rng), polygons_(polygons), scene_(scene) {}

  /// Appends primitive k's halfspaces and returns its expression (the intersection of them).
  ExprPtr draw(int k) {
    const std::string id = std::to_string(k);
    const long kind = rng_.in(0, 9);
    if (kind <= 3) return disk_primitive(id);
    if (kind <= 5) return box(id);
    if (kind <= 7) return triangle(id);
    return lone_halfplane(id);
  }

 private:
  ExprPtr add(Halfspace2 h) {
    scene_.halfspaces.push_back(std::move(h));
    return leaf(static_cast<int>(scene_.halfspaces.size()) - 1);
  }

  ExprPtr disk_primitive(const std::string& id) {
    const PointQ2 c = half_point(rng_, -6, 6);
    return add(disk("c" + id, c, half(rng_, 1, 6)));
  }

  ExprPtr box(const std::string& id) {
    const Rational x0 = half(rng_, -8, 6), y0 = half(rng_, -8, 6);
    const Rational x1 = x0 + half(rng_, 1, 6);
    const Rational y1 = y0 + half(rng_, 1, 6);
    if (polygons_) return add(polygon("s" + id, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}));
    const PointQ2 lo{x0, y0}, hi{x1, y1};
    return intersect({add(halfplane_through("s" + id + ".xmin", {Rational(-1), Rational(0)}, lo)),
                      add(halfplane_through("s" + id + ".xmax", {Rational(1), Rational(0)}, hi)),
                      add(halfplane_through("s" + id + ".ymin", {Rational(0), Rational(-1)}, lo)),
                      add(halfplane_through("s" + id + ".ymax", {Rational(0), Rational(1)}, hi))});
  }

  ExprPtr triangle(const std::string& id) {
    std::vector<PointQ2> v;
    Rational area2;
    do {
      v.clear();
      for (int i = 0; i < 3; ++i) v.push_back(half_point(rng_, -8, 8));
      area2 = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
    } while (area2 == 0);
    if (area2 < 0) std::swap(v[1], v[2]);  // counter-clockwise
    if (polygons_) return add(polygon("t" + id, v));
    std::vector<ExprPtr> sides;
    for (int i = 0; i < 3; ++i) {
      const PointQ2& p = v[at(i)];
      const PointQ2& q = v[at((i + 1) % 3)];
      sides.push_back(add(halfplane_through("t" + id + "." + std::to_string(i), {q.y - p.y, p.x - q.x}, p)));
    }
    return intersect(sides);
  }

  ExprPtr lone_halfplane(const std::string& id) {
    const long d = rng_.in(0, 15);
    const PointQ2 normal{Rational(kDirections[d][0]), Rational(kDirections[d][1])};
    return add(halfplane_through("h" + id, normal, half_point(rng_, -6, 6)));
  }

  Random& rng_;
  bool polygons_;
  Scene2& scene_;
};


std::vector<char> random_cells(Random& rng, const Complex& complex) {
  std::vector<char> solid(complex.cells.size(), 0);
  for (std::size_t k = 0; k < complex.cells.size(); ++k)
    solid[k] = complex.cells[k].outer ? 0 : static_cast<char>(rng.in(0, 1));
  return solid;
}

void check_settings(const RandomSolidSettings& s) {
  if (s.min_primitives < 1 || s.max_primitives < s.min_primitives)
    throw std::invalid_argument("RandomSolidSettings: need 1 <= min_primitives <= max_primitives");
  if (s.max_draws < 1) throw std::invalid_argument("RandomSolidSettings: max_draws must be >= 1");
}

}  // namespace

ExprPtr random_combination(Random& rng, std::vector<ExprPtr> parts) {
  if (parts.empty()) throw std::invalid_argument("random_combination: no parts");
  while (parts.size() > 1) {
    const std::size_t i = rng.index(parts.size());
    ExprPtr a = parts[i];
    parts.erase(parts.begin() + static_cast<long>(i));
    const std::size_t j = rng.index(parts.size());
    ExprPtr b = parts[j];
    switch (rng.in(0, 3)) {
      case 0: parts[j] = unite({a, b}); break;
      case 1: parts[j] = intersect({a, b}); break;
      case 2: parts[j] = difference(a, b); break;
      default: parts[j] = difference(b, a); break;
    }
  }
  return parts.front();
}

SolidStatus solid_status(const Complex& complex, const std::vector<char>& solid) {
  if (solid.size() != complex.cells.size())
    throw std::invalid_argument("solid_status: one flag per cell expected");
  bool any = false;
  for (std::size_t k = 0; k < solid.size(); ++k) {
    if (!solid[k]) continue;
    if (complex.cells[k].outer) return SolidStatus::Unbounded;
    any = true;
  }
  return any ? SolidStatus::Bounded : SolidStatus::Empty;
}

RandomSolid random_solid(const RandomSolidSettings& settings, RandomSolidKind kind, std::uint64_t seed,
                         std::uint64_t index) {
  check_settings(settings);
  Random rng(item_seed(seed, index));
  for (int draw = 1;; ++draw) {
    RandomSolid r;
    const int primitives = static_cast<int>(rng.in(settings.min_primitives, settings.max_primitives));
    std::vector<ExprPtr> parts;
    PrimitiveDrawer drawer(rng, settings.polygons, r.scene);
    for (int k = 0; k < primitives; ++k) parts.push_back(drawer.draw(k));
    r.scene.description = std::string("random ") + (kind == RandomSolidKind::Csg ? "CSG solid " : "cell set ") +
                          std::to_string(index) + " of seed " + std::to_string(seed);
    validate_and_resolve(r.scene);  // chooses the domain: every vertex strictly inside
    r.arranged = arrange(r.scene);
    if (kind == RandomSolidKind::Cells) {
      r.solid = random_cells(rng, r.arranged.complex);
    } else {
      r.expression = random_combination(rng, std::move(parts));
      r.solid = evaluate(*r.expression, r.arranged.complex);
    }
    r.status = solid_status(r.arranged.complex, r.solid);
    r.draws = draw;
    if (r.status == SolidStatus::Bounded || draw >= settings.max_draws) return r;
  }
}

}  // namespace hsx::csg
