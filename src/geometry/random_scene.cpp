// Random valid 2D scenes with forced degeneracies: see random_scene.hpp (the procedure is specified there).
#include <hsx/geometry/random_scene.hpp>

#include <hsx/geometry/scene_builders.hpp>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace hsx {
namespace {

const std::pair<int, int> kUnitNumerators5[] = {{5, 0},  {0, 5},  {-5, 0}, {0, -5},  {3, 4},   {4, 3},
                                                {-3, 4}, {-4, 3}, {3, -4}, {4, -3}, {-3, -4}, {-4, -3}};
const std::pair<int, int> kUnitNumerators13[] = {{5, 12}, {12, 5}, {-5, 12}, {-12, -5}, {12, -5}};
constexpr int kUnits5 = 12, kUnits = 17;

// The 16 primitive integer directions with max-norm <= 2, counter-clockwise from (1, 0).
const std::pair<int, int> kDirections[16] = {{1, 0},  {2, 1},   {1, 1},   {1, 2},   {0, 1},  {-1, 2},
                                             {-1, 1}, {-2, 1},  {-1, 0},  {-2, -1}, {-1, -1}, {-1, -2},
                                             {0, -1}, {1, -2},  {1, -1},  {2, -1}};

/// n/d, canonical (a non-canonical mpq breaks equality and exact text).
Rational frac(long n, long d) { return make_rational(Integer(n), Integer(d)); }

PointQ2 unit(int index) {
  if (index < kUnits5) return {frac(kUnitNumerators5[index].first, 5), frac(kUnitNumerators5[index].second, 5)};
  const auto [a, b] = kUnitNumerators13[index - kUnits5];
  return {frac(a, 13), frac(b, 13)};
}

PointQ2 add(const PointQ2& a, const PointQ2& b) { return {a.x + b.x, a.y + b.y}; }
PointQ2 sub(const PointQ2& a, const PointQ2& b) { return {a.x - b.x, a.y - b.y}; }
PointQ2 scale(const PointQ2& a, const Rational& s) { return {a.x * s, a.y * s}; }
Rational dot(const PointQ2& a, const PointQ2& b) { return a.x * b.x + a.y * b.y; }
PointQ2 canonical(PointQ2 p) {
  p.x.canonicalize();
  p.y.canonicalize();
  return p;
}

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

void check_settings(const RandomSceneSettings& s) {
  auto fail = [](const char* what) { throw std::invalid_argument(std::string("RandomSceneSettings: ") + what); };
  if (s.min_halfspaces < 1 || s.max_halfspaces < s.min_halfspaces) fail("need 1 <= min_halfspaces <= max_halfspaces");
  if (!s.halfplanes && !s.disks && !s.polygons) fail("no halfspace kind allowed");
  if (s.denominator < 1 || s.coordinate_bound < 1 || s.max_radius < 1)
    fail("denominator, coordinate_bound and max_radius must be >= 1");
  if (s.min_degeneracies < 0 || s.max_degeneracies < s.min_degeneracies)
    fail("need 0 <= min_degeneracies <= max_degeneracies");
  for (int w : s.degeneracy_weight)
    if (w < 0) fail("degeneracy weights must be >= 0");
  if (s.max_samples < 0) fail("max_samples must be >= 0");
  if (s.max_samples_per_halfspace > 0 && (s.min_samples_per_halfspace < 0 || s.max_samples > 0 ||
                                          s.min_samples_per_halfspace > s.max_samples_per_halfspace))
    fail("need 0 <= min_samples_per_halfspace <= max_samples_per_halfspace, and max_samples = 0 with them");
  if (s.complement_percent < 0 || s.complement_percent > 100 || s.near_percent < 0 || s.near_percent > 100)
    fail("percentages must be in [0, 100]");
}

/// Steps 2-5 of the procedure: the halfspaces and the domain.
class Builder {
 public:
  Builder(const RandomSceneSettings& s, Random& rng) : s_(s), rng_(rng) {}

  // ---- draws ----
  Rational grid(long k) const { return frac(k, s_.denominator); }
  Rational coord() {
    const long n = static_cast<long>(s_.coordinate_bound) * s_.denominator;
    return grid(rng_.in(-n, n));
  }
  PointQ2 point() {
    Rational x = coord();
    return {x, coord()};
  }
  Rational positive(int max) { return grid(rng_.in(1, static_cast<long>(max) * s_.denominator)); }
  PointQ2 unit_vector() { return unit(static_cast<int>(rng_.in(0, kUnits - 1))); }
  PointQ2 small_normal() {
    long a = rng_.in(-3, 3);
    const long b = rng_.in(-3, 3);
    if (a == 0 && b == 0) a = 1;
    return {Rational(a), Rational(b)};
  }
  bool complemented() { return rng_.percent(s_.complement_percent); }
  std::string name(char letter) { return std::string(1, letter) + std::to_string(next_name_++); }

  // ---- halfspaces; each records its anchors (points the domain must contain) ----
  void add_halfspace(Halfspace2 h, const std::vector<PointQ2>& anchors) {
    scene_.halfspaces.push_back(std::move(h));
    anchors_.insert(anchors_.end(), anchors.begin(), anchors.end());
  }
  void line_through(const PointQ2& p, const PointQ2& normal) {
    const bool flip = rng_.one_in(2);
    const PointQ2 n = flip ? scale(normal, Rational(-1)) : normal;
    const std::string id = name('L');
    add_halfspace(halfplane_through(id, n, p, complemented()), {p});
  }
  void disk_at(const PointQ2& c, const Rational& r) {
    const std::string id = name('D');
    add_halfspace(disk(id, c, r, complemented()), {sub(c, PointQ2{r, r}), add(c, PointQ2{r, r})});
  }
  void polygon_from(std::vector<PointQ2> v) {
    const std::string id = name('P');
    const std::vector<PointQ2> anchors = v;
    add_halfspace(polygon(id, std::move(v), complemented()), anchors);
  }

  std::vector<PointQ2> star_vertices() {
    const PointQ2 c = point();
    const int k = static_cast<int>(rng_.in(3, 7));
    const int hi = k == 3 ? 7 : k == 4 ? 6 : k == 5 ? 5 : 4;
    std::vector<int> gaps;
    int sum = 0;
    do {
      gaps.clear();
      for (int j = 0; j + 1 < k; ++j) gaps.push_back(static_cast<int>(rng_.in(1, hi)));
      sum = std::accumulate(gaps.begin(), gaps.end(), 0);
    } while (sum < 9 || sum > 15);  // the last gap 16 - sum in [1, 7]: angular gaps below pi
    int index = static_cast<int>(rng_.in(0, 15));
    std::vector<PointQ2> v;
    for (int j = 0; j < k; ++j) {
      const auto [dx, dy] = kDirections[index % 16];
      const Rational t = grid(rng_.in(1, 2L * s_.denominator));
      v.push_back(canonical(add(c, scale(PointQ2{Rational(dx), Rational(dy)}, t))));
      if (j + 1 < k) index += gaps[static_cast<std::size_t>(j)];
    }
    if (rng_.one_in(2)) std::reverse(v.begin(), v.end());
    return v;
  }
  std::vector<PointQ2> rectangle_vertices() {
    const PointQ2 a = point();
    const Rational w = positive(3);
    const PointQ2 b = add(a, PointQ2{w, positive(3)});
    std::vector<PointQ2> v = {a, {b.x, a.y}, b, {a.x, b.y}};
    std::rotate(v.begin(), v.begin() + rng_.in(0, 3), v.end());
    if (rng_.one_in(2)) std::reverse(v.begin(), v.end());
    return v;
  }
  std::vector<PointQ2> triangle_vertices() {
    const PointQ2 a = point();
    long d[4];
    do {
      for (long& x : d) x = rng_.in(-4, 4);
    } while (d[0] * d[3] - d[1] * d[2] == 0);
    return {a, canonical(add(a, PointQ2{grid(d[0]), grid(d[1])})), canonical(add(a, PointQ2{grid(d[2]), grid(d[3])}))};
  }
  std::vector<PointQ2> polygon_vertices() {
    switch (rng_.in(0, 2)) {
      case 0: return star_vertices();
      case 1: return rectangle_vertices();
      default: return triangle_vertices();
    }
  }

  void random_halfspace() {
    std::vector<int> kinds;
    if (s_.halfplanes) kinds.push_back(0);
    if (s_.disks) kinds.push_back(1);
    if (s_.polygons) kinds.push_back(2);
    switch (rng_.pick(kinds)) {
      case 0: {
        const PointQ2 p = point();
        line_through(p, small_normal());
        break;
      }
      case 1: {
        const PointQ2 c = point();
        disk_at(c, positive(s_.max_radius));
        break;
      }
      default: polygon_from(polygon_vertices()); break;
    }
  }

  // ---- degeneracies ----
  bool applicable(Degeneracy d) const {
    switch (d) {
      case Degeneracy::RepeatedHalfspace:
      case Degeneracy::ComplementTwin: return true;
      case Degeneracy::LineTangentToDisk: return s_.halfplanes && s_.disks;
      case Degeneracy::DisksTangentOutside:
      case Degeneracy::DisksTangentInside: return s_.disks;
      case Degeneracy::ConcurrentLines: return s_.halfplanes;
      case Degeneracy::PolygonVertexOnLine:
      case Degeneracy::HalfplaneOnPolygonEdge: return s_.halfplanes && s_.polygons;
      case Degeneracy::PolygonVertexOnCircle: return s_.polygons && s_.disks;
      case Degeneracy::PolygonsSharingEdge: return s_.polygons;
    }
    return false;
  }

  void repeat(bool complement_it) {
    const int n = count();
    std::vector<int> disks;
    if (complement_it)
      for (int i = 0; i < n; ++i)
        if (scene_.halfspaces[static_cast<std::size_t>(i)].kind == HalfspaceKind2::Disk) disks.push_back(i);
    const int i = disks.empty() ? static_cast<int>(rng_.in(0, n - 1)) : rng_.pick(disks);
    Halfspace2 h = scene_.halfspaces[static_cast<std::size_t>(i)];
    h.name = name(h.name[0]);
    if (complement_it) h.complement = !h.complement;
    add_halfspace(std::move(h), {});  // the original's anchors already count
  }

  void apply(Degeneracy d, int budget) {
    switch (d) {
      case Degeneracy::RepeatedHalfspace: repeat(false); break;
      case Degeneracy::ComplementTwin: repeat(true); break;
      case Degeneracy::LineTangentToDisk: line_tangent_to_disk(); break;
      case Degeneracy::DisksTangentOutside: disks_tangent_outside(); break;
      case Degeneracy::DisksTangentInside: disks_tangent_inside(); break;
      case Degeneracy::ConcurrentLines: concurrent_lines(budget); break;
      case Degeneracy::PolygonVertexOnLine: polygon_vertex_on_line(); break;
      case Degeneracy::PolygonVertexOnCircle: polygon_vertex_on_circle(); break;
      case Degeneracy::HalfplaneOnPolygonEdge: halfplane_on_polygon_edge(); break;
      case Degeneracy::PolygonsSharingEdge: polygons_sharing_edge(); break;
    }
  }

  void line_tangent_to_disk() {
    const PointQ2 c = point();
    const Rational r = positive(s_.max_radius);
    disk_at(c, r);
    // Tangent at c + r u with normal u: u . x = u . c + r.
    const long m = rng_.in(1, 3);
    const PointQ2 u = rng_.one_in(2) ? unit(1) : unit_vector();
    line_through(canonical(add(c, scale(u, r))), scale(u, Rational(m)));
  }

  void disks_tangent_outside() {
    const PointQ2 c = point();
    const Rational r1 = positive(2);
    disk_at(c, r1);
    const Rational r2 = positive(2);
    disk_at(canonical(add(c, scale(unit_vector(), r1 + r2))), r2);
  }

  void disks_tangent_inside() {
    const PointQ2 c = point();
    const long k1 = rng_.in(2, 3L * s_.denominator);
    const Rational r1 = grid(k1);
    disk_at(c, r1);
    const Rational r2 = grid(rng_.in(1, k1 - 1));  // 0 < r2 < r1
    disk_at(canonical(add(c, scale(unit_vector(), r1 - r2))), r2);
  }

  void concurrent_lines(int budget) {
    const PointQ2 p = point();
    const int lines = budget >= 4 && rng_.one_in(2) ? 4 : 3;
    std::vector<int> left(8);  // distinct directions among the first 8 (a half turn): distinct lines
    std::iota(left.begin(), left.end(), 0);
    std::vector<int> dirs;
    for (int k = 0; k < lines; ++k) {
      const std::size_t j = rng_.index(left.size());
      dirs.push_back(left[j]);
      left.erase(left.begin() + static_cast<long>(j));
    }
    for (int k : dirs) line_through(p, PointQ2{Rational(-kDirections[k].second), Rational(kDirections[k].first)});
  }

  void polygon_vertex_on_line() {
    std::vector<PointQ2> v = polygon_vertices();
    const PointQ2 p = rng_.pick(v);
    polygon_from(v);
    line_through(p, small_normal());
  }

  void polygon_vertex_on_circle() {
    std::vector<PointQ2> v = polygon_vertices();
    const PointQ2 p = rng_.pick(v);
    polygon_from(v);
    const Rational r = positive(2);
    disk_at(canonical(sub(p, scale(unit_vector(), r))), r);
  }

  void halfplane_on_polygon_edge() {
    std::vector<PointQ2> v = polygon_vertices();
    const std::size_t k = rng_.index(v.size());
    const PointQ2 a = v[k], b = v[(k + 1) % v.size()];
    polygon_from(v);
    const PointQ2 e = sub(b, a);
    line_through(a, PointQ2{-e.y, e.x});
  }

  void polygons_sharing_edge() {
    const PointQ2 a = point();
    const Rational x1 = a.x + positive(2);
    const Rational x2 = x1 + positive(2);
    const long k1 = rng_.in(1, 3L * s_.denominator);  // y1 = y0 + positive(3)
    const Rational y1 = a.y + grid(k1);
    const Rational y2 = a.y + grid(rng_.in(-2L * s_.denominator, k1 - 1));  // y2 < y1: the edges overlap
    const Rational y3 = std::max(y2, a.y) + positive(2);
    polygon_from({a, {x1, a.y}, {x1, y1}, {a.x, y1}});
    polygon_from({{x1, y2}, {x2, y2}, {x2, y3}, {x1, y3}});
  }

  int count() const { return static_cast<int>(scene_.halfspaces.size()); }

  Scene2 finish_geometry() {
    Rational xmin = anchors_.front().x, xmax = xmin, ymin = anchors_.front().y, ymax = ymin;
    for (const PointQ2& p : anchors_) {
      xmin = std::min(xmin, p.x);
      xmax = std::max(xmax, p.x);
      ymin = std::min(ymin, p.y);
      ymax = std::max(ymax, p.y);
    }
    const long lo_x = rng_.in(1, 2), lo_y = rng_.in(1, 2), hi_x = rng_.in(1, 2), hi_y = rng_.in(1, 2);
    scene_.domain.min = {floor_q(xmin) - lo_x, floor_q(ymin) - lo_y};
    scene_.domain.max = {ceil_q(xmax) + hi_x, ceil_q(ymax) + hi_y};
    scene_.domain_given = true;
    scene_.description = "random scene (geometry/random_scene)";
    validate_and_resolve(scene_);
    return scene_;
  }

 private:
  const RandomSceneSettings& s_;
  Random& rng_;
  Scene2 scene_;
  std::vector<PointQ2> anchors_;
  int next_name_ = 0;
};

/// The candidate sample points of halfspace i that fit (sample_fits): the rational_boundary_points that do, then the
/// midpoints of its rational segment edges. A midpoint lies inside its edge, which carries i and holds no vertex
/// or other edge there, so it fits by construction and is not located (point location is most of a scene's
/// drawing time).
std::vector<PointQ2> fitting_candidates(const Scene2& scene, const Arrangement2& arr, int i) {
  std::vector<PointQ2> out;
  for (const PointQ2& p : rational_boundary_points(scene.halfspaces[static_cast<std::size_t>(i)], scene.domain))
    if (sample_fits(arr, i, p)) out.push_back(p);
  for (const ArrEdge2& e : arr.edges()) {
    if (e.shape != EdgeShape2::Segment || e.on_box) continue;
    if (!std::binary_search(e.halfspaces.begin(), e.halfspaces.end(), i)) continue;
    const OneRootPoint& a = arr.vertices()[static_cast<std::size_t>(e.source)].point;
    const OneRootPoint& b = arr.vertices()[static_cast<std::size_t>(e.target)].point;
    if (!a.is_rational() || !b.is_rational()) continue;
    out.push_back(canonical({(a.x.a0 + b.x.a0) / 2, (a.y.a0 + b.y.a0) / 2}));
  }
  return out;
}

/// One sample of halfspace i at the candidate p: `at`, or `near` (an off-boundary point snapping exactly to p).
Sample2 draw_sample(const RandomSceneSettings& s, Random& rng, const Scene2& scene, int i, const PointQ2& p) {
  const Halfspace2& h = scene.halfspaces[static_cast<std::size_t>(i)];
  Sample2 sample;
  sample.halfspace = i;
  sample.given = p;
  if (h.kind != HalfspaceKind2::Polygon && rng.percent(s.near_percent)) {
    sample.snapped = true;
    if (h.kind == HalfspaceKind2::Halfplane)
      sample.given = canonical(add(p, scale(h.normal, rng.pick(std::vector<Rational>{frac(1, 2), Rational(-1), Rational(1)}))));
    else
      sample.given = canonical(add(h.center, scale(sub(p, h.center), rng.pick(std::vector<Rational>{frac(1, 2), Rational(2)}))));
  }
  return sample;
}

/// Step 6: samples on patches of the sample-free arrangement (in all, or per halfspace); returns that arrangement.
Arrangement2 add_samples(const RandomSceneSettings& s, Random& rng, Scene2& scene) {
  Arrangement2 arr = Arrangement2::build(scene);
  std::vector<std::vector<PointQ2>> fitting(scene.halfspaces.size());
  std::vector<std::pair<int, PointQ2>> all;
  for (int i = 0; i < static_cast<int>(scene.halfspaces.size()); ++i)
    for (const PointQ2& p : fitting_candidates(scene, arr, i)) {
      fitting[static_cast<std::size_t>(i)].push_back(p);
      all.emplace_back(i, p);
    }
  if (all.empty()) return arr;
  if (s.max_samples_per_halfspace > 0) {
    for (int i = 0; i < static_cast<int>(scene.halfspaces.size()); ++i) {
      const auto& mine = fitting[static_cast<std::size_t>(i)];
      if (mine.empty()) continue;
      const long count = rng.in(s.min_samples_per_halfspace, s.max_samples_per_halfspace);
      for (long k = 0; k < count; ++k) scene.samples.push_back(draw_sample(s, rng, scene, i, rng.pick(mine)));
    }
  } else {
    const long count = rng.in(0, s.max_samples);
    for (long k = 0; k < count; ++k) {
      const auto& [i, p] = rng.pick(all);
      scene.samples.push_back(draw_sample(s, rng, scene, i, p));
    }
  }
  validate_and_resolve(scene);
  return arr;
}

std::vector<Degeneracy> draw_patterns(const RandomSceneSettings& s, const Builder& b, Random& rng) {
  std::vector<Degeneracy> pool;
  std::vector<int> weights;
  for (int k = 0; k < kDegeneracyCount; ++k) {
    const auto d = static_cast<Degeneracy>(k);
    if (s.degeneracy_weight[static_cast<std::size_t>(k)] > 0 && b.applicable(d)) {
      pool.push_back(d);
      weights.push_back(s.degeneracy_weight[static_cast<std::size_t>(k)]);
    }
  }
  std::vector<Degeneracy> patterns;
  if (pool.empty() || s.max_degeneracies <= 0) return patterns;
  const long count = rng.in(s.min_degeneracies, s.max_degeneracies);
  for (long k = 0; k < count; ++k) patterns.push_back(pool[rng.weighted(weights)]);
  return patterns;
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

int degeneracy_cost(Degeneracy d) {
  switch (d) {
    case Degeneracy::RepeatedHalfspace:
    case Degeneracy::ComplementTwin: return 1;
    case Degeneracy::ConcurrentLines: return 3;
    default: return 2;
  }
}

RandomScene random_scene(const RandomSceneSettings& settings, std::uint64_t seed, std::uint64_t index) {
  Random rng(item_seed(seed, index));
  RandomScene r = random_scene(settings, rng);
  r.scene.description = "random scene " + std::to_string(index) + " of seed " + std::to_string(seed) +
                        " (geometry/random_scene)";
  return r;
}

RandomScene random_scene(const RandomSceneSettings& s, Random& rng) {
  check_settings(s);
  Builder b(s, rng);
  const std::vector<Degeneracy> patterns = draw_patterns(s, b, rng);
  int cost = 0;
  for (Degeneracy d : patterns) cost += degeneracy_cost(d);
  const long base = rng.in(1, std::max(1, s.max_halfspaces - cost));
  for (long k = 0; k < base; ++k) b.random_halfspace();
  RandomScene out;
  for (Degeneracy d : patterns)
    if (b.count() + degeneracy_cost(d) <= s.max_halfspaces) {
      b.apply(d, s.max_halfspaces - b.count());
      out.degeneracies.push_back(d);
    }
  while (b.count() < s.min_halfspaces) b.random_halfspace();
  out.scene = b.finish_geometry();
  if (s.max_samples > 0 || s.max_samples_per_halfspace > 0) out.arrangement = add_samples(s, rng, out.scene);
  return out;
}

PointQ2 random_grid_point_in(Random& rng, const Box2& box, int denominator) {
  if (denominator < 1) throw std::invalid_argument("random_grid_point_in: denominator must be >= 1");
  auto coordinate = [&](const Rational& lo, const Rational& hi) {
    const Rational a = floor_q(lo * denominator) + 1, b = ceil_q(hi * denominator) - 1;
    if (a > b) return Rational((lo + hi) / 2);
    return frac(rng.in(a.get_num().get_si(), b.get_num().get_si()), denominator);
  };
  Rational x = coordinate(box.min.x, box.max.x);
  return PointQ2{x, coordinate(box.min.y, box.max.y)};
}

std::vector<PointQ2> rational_boundary_points(const Halfspace2& h, const Box2& box) {
  std::vector<PointQ2> out;
  switch (h.kind) {
    case HalfspaceKind2::Halfplane: {
      // Points p + t d on the line, d along it, p its point nearest to the box centre.
      const PointQ2 c{(box.min.x + box.max.x) / 2, (box.min.y + box.max.y) / 2};
      const Rational t0 = (dot(h.normal, c) - h.offset) / dot(h.normal, h.normal);
      const PointQ2 p = sub(c, scale(h.normal, t0));
      const PointQ2 d{-h.normal.y, h.normal.x};
      for (int k : {0, 1, -1, 2, -2, 3, -3})
        for (const Rational& t : {Rational(k), frac(k, 2)}) out.push_back(add(p, scale(d, t)));
      break;
    }
    case HalfspaceKind2::Disk:
      for (int k = 0; k < kUnits; ++k) out.push_back(add(h.center, scale(unit(k), h.radius)));
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
  for (const PointQ2& p : out) {
    const PointQ2 q = canonical(p);
    if (strictly_inside(box, q)) inside.push_back(q);
  }
  return inside;
}

bool sample_fits(const Arrangement2& arr, int halfspace, const PointQ2& p) {
  return arr.holding_edge(arr.locate_on_boundary(p, halfspace), halfspace) >= 0;
}

}  // namespace hsx
