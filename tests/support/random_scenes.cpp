// Random valid 2D scenes for property tests: see random_scenes.hpp.
#include "support/random_scenes.hpp"

#include <hsx/io/scene_json.hpp>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace hsx::test {
namespace {

// Rational unit vectors (Pythagorean triples), for tangencies and rational points on circles.
const std::vector<std::pair<int, int>> kUnitNumerators5 = {{5, 0}, {0, 5}, {-5, 0}, {0, -5}, {3, 4}, {4, 3},
                                                           {-3, 4}, {-4, 3}, {3, -4}, {4, -3}, {-3, -4}, {-4, -3}};
const std::vector<std::pair<int, int>> kUnitNumerators13 = {{5, 12}, {12, 5}, {-5, 12}, {-12, -5}, {12, -5}};

/// n/d, canonical (a non-canonical mpq breaks equality and exact text).
Rational frac(long n, long d) { return make_rational(Integer(n), Integer(d)); }

PointQ2 unit(int index) {
  const int n5 = static_cast<int>(kUnitNumerators5.size());
  if (index < n5) {
    auto [a, b] = kUnitNumerators5[index];
    return {frac(a, 5), frac(b, 5)};
  }
  auto [a, b] = kUnitNumerators13[index - n5];
  return {frac(a, 13), frac(b, 13)};
}
int unit_count() { return static_cast<int>(kUnitNumerators5.size() + kUnitNumerators13.size()); }

// The 16 primitive integer directions with max-norm <= 2, sorted counter-clockwise from (1, 0); index i + 8 is
// the opposite of index i.
const std::pair<int, int> kDirections[16] = {{1, 0},  {2, 1},   {1, 1},   {1, 2},  {0, 1},  {-1, 2},
                                             {-1, 1}, {-2, 1},  {-1, 0},  {-2, -1}, {-1, -1}, {-1, -2},
                                             {0, -1}, {1, -2},  {1, -1},  {2, -1}};

/// Uniform integer in [lo, hi): rapidcheck's inRange scales its range with the test size, which would pin the
/// first tests to lo (every point at the same corner); the geometry must be uniform from the first test on.
int uniform(int lo, int hi) { return *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi)); }
rc::Gen<int> uniform_gen(int lo, int hi) { return rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi)); }

PointQ2 add(const PointQ2& a, const PointQ2& b) { return {a.x + b.x, a.y + b.y}; }
PointQ2 sub(const PointQ2& a, const PointQ2& b) { return {a.x - b.x, a.y - b.y}; }
PointQ2 scale(const PointQ2& a, const Rational& s) { return {a.x * s, a.y * s}; }
Rational dot(const PointQ2& a, const PointQ2& b) { return a.x * b.x + a.y * b.y; }

Rational floor_q(const Rational& v) {
  Integer r;
  mpz_fdiv_q(r.get_mpz_t(), v.get_num_mpz_t(), v.get_den_mpz_t());
  return Rational(r);
}
Rational ceil_q(const Rational& v) {
  Integer r;
  mpz_cdiv_q(r.get_mpz_t(), v.get_num_mpz_t(), v.get_den_mpz_t());
  return Rational(r);
}

bool strictly_inside(const Box2& b, const PointQ2& p) {
  return b.min.x < p.x && p.x < b.max.x && b.min.y < p.y && p.y < b.max.y;
}

/// Everything drawn while generating one scene (only valid inside rc::gen::exec).
class Builder {
 public:
  explicit Builder(const SceneGenOptions& o) : o_(o) {}

  Rational coord() const {
    const int n = o_.coordinate_bound * o_.denominator;
    return make_rational(Integer(uniform(-n, n + 1)), Integer(o_.denominator));
  }
  PointQ2 point() const { return {coord(), coord()}; }
  /// A positive multiple of 1/denominator in (0, max].
  Rational positive(int max) const {
    return make_rational(Integer(uniform(1, max * o_.denominator + 1)), Integer(o_.denominator));
  }
  PointQ2 unit_vector() const { return unit(uniform(0, unit_count())); }
  PointQ2 small_normal() const {
    int a = uniform(-3, 4), b = uniform(-3, 4);
    if (a == 0 && b == 0) a = 1;
    return {Rational(a), Rational(b)};
  }
  bool coin(int one_in) const { return uniform(0, one_in) == one_in - 1; }  // shrinks to false
  bool maybe_complement() const { return o_.complements && coin(4); }

  std::string name(char letter) { return std::string(1, letter) + std::to_string(next_name_++); }

  // ---- halfspaces; each records an anchor (a point the domain must contain) ----
  int add_halfspace(Halfspace2 h, std::vector<PointQ2> anchors) {
    scene_.halfspaces.push_back(std::move(h));
    for (auto& a : anchors) anchors_.push_back(a);
    return static_cast<int>(scene_.halfspaces.size()) - 1;
  }
  int line_through(const PointQ2& p, const PointQ2& normal) {
    Rational offset = dot(normal, p);
    PointQ2 n = normal;
    if (coin(2)) {  // the same line, the other side
      n = scale(n, -1);
      offset = -offset;
    }
    return add_halfspace(halfplane(name('L'), n, offset, maybe_complement()), {p});
  }
  int random_halfplane() { return line_through(point(), small_normal()); }
  int disk_at(const PointQ2& c, const Rational& r) {
    return add_halfspace(disk(name('D'), c, r, maybe_complement()),
                         {sub(c, PointQ2{r, r}), add(c, PointQ2{r, r})});
  }
  int random_disk() { return disk_at(point(), positive(3)); }
  int polygon_from(std::vector<PointQ2> v) {
    auto anchors = v;
    return add_halfspace(polygon(name('P'), std::move(v), maybe_complement()), std::move(anchors));
  }
  std::vector<PointQ2> random_polygon_vertices() const {
    switch (uniform(0, 3)) {
      case 0: {  // star-shaped around c: directions at sorted indices with gaps in [1, 7] (angular gap < pi)
        const PointQ2 c = point();
        const int k = uniform(3, 7);
        const int hi = k == 3 ? 7 : k == 4 ? 6 : k == 5 ? 5 : 4;
        const auto gaps = *rc::gen::suchThat(rc::gen::container<std::vector<int>>(k - 1, uniform_gen(1, hi + 1)),
                                             [](const std::vector<int>& g) {
                                               const int s = std::accumulate(g.begin(), g.end(), 0);
                                               return s >= 9 && s <= 15;  // last gap 16 - s in [1, 7]
                                             });
        int index = uniform(0, 16);
        std::vector<PointQ2> v;
        for (int j = 0; j < k; ++j) {
          const auto [dx, dy] = kDirections[index % 16];
          const Rational t = frac(uniform(1, 5), 2);  // 1/2, 1, 3/2, 2
          v.push_back(add(c, scale(PointQ2{Rational(dx), Rational(dy)}, t)));
          if (j + 1 < k) index += gaps[j];
        }
        for (auto& p : v) {
          p.x.canonicalize();
          p.y.canonicalize();
        }
        if (coin(2)) std::reverse(v.begin(), v.end());
        return v;
      }
      case 1: {  // axis-aligned rectangle
        const PointQ2 a = point();
        const PointQ2 b = add(a, PointQ2{positive(3), positive(3)});
        std::vector<PointQ2> v = {a, {b.x, a.y}, b, {a.x, b.y}};
        std::rotate(v.begin(), v.begin() + uniform(0, 4), v.end());
        if (coin(2)) std::reverse(v.begin(), v.end());
        return v;
      }
      default: {  // triangle
        const PointQ2 a = point();
        const auto ds = *rc::gen::suchThat(rc::gen::container<std::vector<int>>(4, uniform_gen(-4, 5)),
                                           [](const std::vector<int>& d) { return d[0] * d[3] - d[1] * d[2] != 0; });
        const Rational s = frac(1, o_.denominator);
        return {a, add(a, scale(PointQ2{Rational(ds[0]), Rational(ds[1])}, s)),
                add(a, scale(PointQ2{Rational(ds[2]), Rational(ds[3])}, s))};
      }
    }
  }
  int random_polygon() { return polygon_from(random_polygon_vertices()); }

  int random_halfspace() {
    std::vector<int> kinds;
    if (o_.halfplanes) kinds.push_back(0);
    if (o_.disks) kinds.push_back(1);
    if (o_.polygons) kinds.push_back(2);
    if (kinds.empty()) throw std::invalid_argument("SceneGenOptions: no halfspace kind allowed");
    switch (*rc::gen::elementOf(kinds)) {
      case 0: return random_halfplane();
      case 1: return random_disk();
      default: return random_polygon();
    }
  }

  // ---- degeneracies ----
  bool applicable(Degeneracy d) const {
    switch (d) {
      case Degeneracy::RepeatedHalfspace:
      case Degeneracy::ComplementTwin:
        return true;
      case Degeneracy::LineTangentToDisk:
        return o_.halfplanes && o_.disks;
      case Degeneracy::DisksTangentOutside:
      case Degeneracy::DisksTangentInside:
        return o_.disks;
      case Degeneracy::ConcurrentLines:
        return o_.halfplanes;
      case Degeneracy::PolygonVertexOnLine:
      case Degeneracy::HalfplaneOnPolygonEdge:
        return o_.halfplanes && o_.polygons;
      case Degeneracy::PolygonVertexOnCircle:
        return o_.polygons && o_.disks;
      case Degeneracy::PolygonsSharingEdge:
        return o_.polygons;
    }
    return false;
  }
  static int cost(Degeneracy d) {
    switch (d) {
      case Degeneracy::RepeatedHalfspace:
      case Degeneracy::ComplementTwin:
        return 1;
      case Degeneracy::ConcurrentLines:
        return 3;
      default:
        return 2;
    }
  }
  void apply(Degeneracy d, int budget) {
    const int n = static_cast<int>(scene_.halfspaces.size());
    switch (d) {
      case Degeneracy::RepeatedHalfspace: {
        const int i = uniform(0, n);
        Halfspace2 h = scene_.halfspaces[i];
        h.name = name(h.name[0]);
        add_halfspace(std::move(h), {});  // the original's anchors already count
        break;
      }
      case Degeneracy::ComplementTwin: {
        std::vector<int> disks;
        for (int i = 0; i < n; ++i)
          if (scene_.halfspaces[i].kind == HalfspaceKind2::Disk) disks.push_back(i);
        const int i = disks.empty() ? uniform(0, n) : *rc::gen::elementOf(disks);
        Halfspace2 h = scene_.halfspaces[i];
        h.name = name(h.name[0]);
        h.complement = !h.complement;
        add_halfspace(std::move(h), {});  // the original's anchors already count
        break;
      }
      case Degeneracy::LineTangentToDisk: {
        const PointQ2 c = point();
        const Rational r = positive(3);
        disk_at(c, r);
        // Tangent at c + r*u, normal u: u . x = u . c + r. u = (0, 1) gives y = b + r.
        const PointQ2 u = coin(2) ? unit(1) : unit_vector();
        line_through(add(c, scale(u, r)), scale(u, Rational(uniform(1, 4))));
        break;
      }
      case Degeneracy::DisksTangentOutside: {
        const PointQ2 c = point();
        const Rational r1 = positive(2), r2 = positive(2);
        disk_at(c, r1);
        disk_at(add(c, scale(unit_vector(), r1 + r2)), r2);
        break;
      }
      case Degeneracy::DisksTangentInside: {
        const PointQ2 c = point();
        const int k1 = uniform(2, 3 * o_.denominator + 1), k2 = uniform(1, k1);
        const Rational r1 = make_rational(Integer(k1), Integer(o_.denominator));
        const Rational r2 = make_rational(Integer(k2), Integer(o_.denominator));  // 0 < r2 < r1
        disk_at(c, r1);
        disk_at(add(c, scale(unit_vector(), r1 - r2)), r2);
        break;
      }
      case Degeneracy::ConcurrentLines: {
        const PointQ2 p = point();
        const int lines = budget >= 4 && coin(2) ? 4 : 3;
        // Distinct directions among the first 8 (a half turn): distinct lines through p.
        std::vector<int> left(8);
        std::iota(left.begin(), left.end(), 0);
        std::vector<int> dirs;
        for (int k = 0; k < lines; ++k) {
          const int j = uniform(0, static_cast<int>(left.size()));
          dirs.push_back(left[j]);
          left.erase(left.begin() + j);
        }
        for (int k : dirs) {
          const auto [dx, dy] = kDirections[k];
          line_through(p, PointQ2{Rational(-dy), Rational(dx)});
        }
        break;
      }
      case Degeneracy::PolygonVertexOnLine: {
        auto v = random_polygon_vertices();
        const PointQ2 p = *rc::gen::elementOf(v);
        polygon_from(v);
        line_through(p, small_normal());
        break;
      }
      case Degeneracy::PolygonVertexOnCircle: {
        auto v = random_polygon_vertices();
        const PointQ2 p = *rc::gen::elementOf(v);
        polygon_from(v);
        const Rational r = positive(2);
        disk_at(sub(p, scale(unit_vector(), r)), r);
        break;
      }
      case Degeneracy::HalfplaneOnPolygonEdge: {
        auto v = random_polygon_vertices();
        const int k = uniform(0, static_cast<int>(v.size()));
        const PointQ2 a = v[k], b = v[(k + 1) % v.size()];
        polygon_from(v);
        const PointQ2 d = sub(b, a);
        line_through(a, PointQ2{-d.y, d.x});
        break;
      }
      case Degeneracy::PolygonsSharingEdge: {
        // [x0, x1] x [y0, y1] and [x1, x2] x [y2, y3]: the vertical edges at x1 overlap when the y ranges do.
        const PointQ2 a = point();
        const Rational x1 = a.x + positive(2), x2 = x1 + positive(2);
        const Rational y1 = a.y + positive(3);
        const Rational y2 = a.y + make_rational(Integer(uniform(-2 * o_.denominator, 2 * o_.denominator)),
                                                Integer(o_.denominator));
        const Rational y3 = std::max(y2, a.y) + positive(2);
        polygon_from({a, {x1, a.y}, {x1, y1}, {a.x, y1}});
        polygon_from({{x1, y2}, {x2, y2}, {x2, y3}, {x1, y3}});
        break;
      }
    }
  }

  int count() const { return static_cast<int>(scene_.halfspaces.size()); }

  Scene2 finish_geometry(int margin_lo_x, int margin_lo_y, int margin_hi_x, int margin_hi_y) {
    Rational xmin = anchors_.front().x, xmax = xmin, ymin = anchors_.front().y, ymax = ymin;
    for (const PointQ2& p : anchors_) {
      xmin = std::min(xmin, p.x);
      xmax = std::max(xmax, p.x);
      ymin = std::min(ymin, p.y);
      ymax = std::max(ymax, p.y);
    }
    scene_.domain.min = {floor_q(xmin) - margin_lo_x, floor_q(ymin) - margin_lo_y};
    scene_.domain.max = {ceil_q(xmax) + margin_hi_x, ceil_q(ymax) + margin_hi_y};
    scene_.domain_given = true;
    scene_.description = "random scene (tests/support/random_scenes)";
    validate_and_resolve(scene_);
    return scene_;
  }

 private:
  const SceneGenOptions& o_;
  Scene2 scene_;
  std::vector<PointQ2> anchors_;
  int next_name_ = 0;
};

std::vector<Degeneracy> all_degeneracies() {
  std::vector<Degeneracy> out;
  for (int k = 0; k < kDegeneracyCount; ++k) out.push_back(static_cast<Degeneracy>(k));
  return out;
}

/// Candidate sample points of halfspace i: boundary_points plus the midpoints of its rational segment edges.
std::vector<PointQ2> sample_candidates(const Scene2& scene, const Arrangement2& arr, int i) {
  std::vector<PointQ2> out = boundary_points(scene.halfspaces[i], scene.domain);
  for (const ArrEdge2& e : arr.edges()) {
    if (e.shape != EdgeShape2::Segment || e.on_box) continue;
    if (!std::binary_search(e.halfspaces.begin(), e.halfspaces.end(), i)) continue;
    const OneRootPoint& a = arr.vertices()[e.source].point;
    const OneRootPoint& b = arr.vertices()[e.target].point;
    if (!a.is_rational() || !b.is_rational()) continue;
    out.push_back({(a.x.a0 + b.x.a0) / 2, (a.y.a0 + b.y.a0) / 2});
  }
  return out;
}

}  // namespace

const char* to_string(Degeneracy d) {
  switch (d) {
    case Degeneracy::RepeatedHalfspace: return "RepeatedHalfspace";
    case Degeneracy::ComplementTwin: return "ComplementTwin";
    case Degeneracy::LineTangentToDisk: return "LineTangentToDisk";
    case Degeneracy::DisksTangentOutside: return "DisksTangentOutside";
    case Degeneracy::DisksTangentInside: return "DisksTangentInside";
    case Degeneracy::ConcurrentLines: return "ConcurrentLines";
    case Degeneracy::PolygonVertexOnLine: return "PolygonVertexOnLine";
    case Degeneracy::PolygonVertexOnCircle: return "PolygonVertexOnCircle";
    case Degeneracy::HalfplaneOnPolygonEdge: return "HalfplaneOnPolygonEdge";
    case Degeneracy::PolygonsSharingEdge: return "PolygonsSharingEdge";
  }
  return "?";
}

rc::Gen<Scene2> gen_scene(const SceneGenOptions& options) {
  return rc::gen::exec([options]() -> Scene2 {
    Builder b(options);
    // Degeneracy patterns first (so the budget is known), then the random halfspaces, then the patterns.
    std::vector<Degeneracy> pool;
    for (Degeneracy d : options.allowed_degeneracies.empty() ? all_degeneracies() : options.allowed_degeneracies)
      if (b.applicable(d)) pool.push_back(d);
    std::vector<Degeneracy> patterns;
    if (!pool.empty() && options.max_degeneracies > 0) {
      const int count = uniform(std::max(0, options.min_degeneracies), options.max_degeneracies + 1);
      for (int k = 0; k < count; ++k) patterns.push_back(*rc::gen::elementOf(pool));
    }
    int pattern_cost = 0;
    for (Degeneracy d : patterns) pattern_cost += Builder::cost(d);
    const int max_total = std::max(1, options.max_halfspaces);
    const int base = uniform(1, std::max(1, max_total - pattern_cost) + 1);
    for (int k = 0; k < base; ++k) b.random_halfspace();
    for (Degeneracy d : patterns)
      if (b.count() + Builder::cost(d) <= max_total) b.apply(d, max_total - b.count());
    const int m1 = uniform(1, 3), m2 = uniform(1, 3), m3 = uniform(1, 3),
              m4 = uniform(1, 3);
    Scene2 scene = b.finish_geometry(m1, m2, m3, m4);
    if (!options.samples || options.max_samples <= 0) return scene;

    // Samples: candidates that lie inside patches of the sample-free arrangement.
    const Arrangement2 arr = Arrangement2::build(scene);
    std::vector<std::pair<int, PointQ2>> fitting;
    for (int i = 0; i < static_cast<int>(scene.halfspaces.size()); ++i)
      for (const PointQ2& p : sample_candidates(scene, arr, i))
        if (sample_fits(arr, i, p)) fitting.emplace_back(i, p);
    if (fitting.empty()) return scene;
    const int count = uniform(0, options.max_samples + 1);
    for (int k = 0; k < count; ++k) {
      const auto& [i, p] = fitting[uniform(0, static_cast<int>(fitting.size()))];
      const Halfspace2& h = scene.halfspaces[i];
      Sample2 s;
      s.halfspace = i;
      s.given = p;
      if (options.near_samples && h.kind != HalfspaceKind2::Polygon && b.coin(3)) {
        // A point off the boundary whose nearest boundary point is exactly p.
        s.snapped = true;
        if (h.kind == HalfspaceKind2::Halfplane) {
          s.given = add(p, scale(h.normal, *rc::gen::element(frac(1, 2), Rational(-1), Rational(1))));
        } else {
          s.given = add(h.center, scale(sub(p, h.center), *rc::gen::element(frac(1, 2), Rational(2))));
        }
      }
      scene.samples.push_back(s);
    }
    validate_and_resolve(scene);
    return scene;
  });
}

rc::Gen<PointQ2> gen_point_in(const Box2& box, int denominator) {
  return rc::gen::exec([box, denominator]() -> PointQ2 {
    auto coordinate = [&](const Rational& lo, const Rational& hi) {
      // multiples of 1/denominator strictly between lo and hi; the midpoint when there is none
      const Rational a = floor_q(lo * denominator) + 1, b = ceil_q(hi * denominator) - 1;
      if (a > b) return Rational((lo + hi) / 2);
      const long k = uniform(a.get_num().get_si(), b.get_num().get_si() + 1);
      return make_rational(Integer(k), Integer(denominator));
    };
    return PointQ2{coordinate(box.min.x, box.max.x), coordinate(box.min.y, box.max.y)};
  });
}

std::vector<PointQ2> boundary_points(const Halfspace2& h, const Box2& box) {
  std::vector<PointQ2> out;
  switch (h.kind) {
    case HalfspaceKind2::Halfplane: {
      // Points p + t*d on the line, d along it, p its point nearest to the box centre.
      const PointQ2 c{(box.min.x + box.max.x) / 2, (box.min.y + box.max.y) / 2};
      const Rational t0 = (dot(h.normal, c) - h.offset) / dot(h.normal, h.normal);
      const PointQ2 p = sub(c, scale(h.normal, t0));
      const PointQ2 d{-h.normal.y, h.normal.x};
      for (int k : {0, 1, -1, 2, -2, 3, -3}) {
        for (const Rational& t : {Rational(k), frac(k, 2)}) {
          PointQ2 x = add(p, scale(d, t));
          x.x.canonicalize();
          x.y.canonicalize();
          if (strictly_inside(box, x)) out.push_back(x);
        }
      }
      break;
    }
    case HalfspaceKind2::Disk:
      for (int k = 0; k < unit_count(); ++k) out.push_back(add(h.center, scale(unit(k), h.radius)));
      break;
    case HalfspaceKind2::Polygon: {
      const std::size_t n = h.vertices.size();
      for (std::size_t k = 0; k < n; ++k) {
        const PointQ2& a = h.vertices[k];
        const PointQ2& b = h.vertices[(k + 1) % n];
        out.push_back(a);
        out.push_back(scale(add(a, b), frac(1, 2)));
        out.push_back(add(a, scale(sub(b, a), frac(1, 3))));
      }
      break;
    }
  }
  std::vector<PointQ2> inside;
  for (PointQ2& p : out) {
    p.x.canonicalize();
    p.y.canonicalize();
    if (strictly_inside(box, p)) inside.push_back(p);
  }
  return inside;
}

bool sample_fits(const Arrangement2& arr, int halfspace, const PointQ2& p) {
  auto carries = [&](int e) {
    const ArrEdge2& edge = arr.edges()[e];
    return !edge.on_box && std::binary_search(edge.halfspaces.begin(), edge.halfspaces.end(), halfspace);
  };
  const PointLocation2 where = arr.locate(p);
  if (where.kind == PointLocation2::Edge) return carries(where.index);
  if (where.kind != PointLocation2::Vertex) return false;
  std::vector<int> incident;
  for (int e = 0; e < static_cast<int>(arr.edges().size()); ++e) {
    const ArrEdge2& edge = arr.edges()[e];
    if (edge.source == where.index) incident.push_back(e);
    if (edge.target == where.index) incident.push_back(e);
  }
  return incident.size() == 2 && carries(incident[0]) && carries(incident[1]) &&
         arr.edges()[incident[0]].halfspaces == arr.edges()[incident[1]].halfspaces;
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

Halfspace2 halfplane(const std::string& name, const PointQ2& normal, const Rational& offset, bool complement) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Halfplane;
  h.normal = normal;
  h.offset = offset;
  h.complement = complement;
  return h;
}

Halfspace2 disk(const std::string& name, const PointQ2& center, const Rational& radius, bool complement) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Disk;
  h.center = center;
  h.radius = radius;
  h.complement = complement;
  return h;
}

Halfspace2 polygon(const std::string& name, std::vector<PointQ2> vertices, bool complement) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Polygon;
  h.vertices = std::move(vertices);
  h.complement = complement;
  return h;
}

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
