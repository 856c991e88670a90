// Scene validation and resolution: exact checks on GMP rationals (CGAL only for its interval filter, Interval_nt)
//
// Limits (documented in docs/scene-format.md):
// - a polygon has at most kMaxPolygonVertices vertices and all polygons together at most kMaxTotalPolygonVertices:
//   the simplicity test is a bounding-box sweep with filtered exact predicates, quadratic in the worst case.
#include <hsx/geometry/scene.hpp>

#include <CGAL/Interval_nt.h>
#include <CGAL/gmpxx.h>

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace hsx {

namespace {

constexpr std::size_t kMaxPolygonVertices = 5000;
constexpr std::size_t kMaxTotalPolygonVertices = 200000;

// ---------------------------------------------------------------------------------------------------------------
// Text helpers for error messages

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

/// Exact text, abbreviated when very long so that a 10,000-digit number does not flood an error message.
std::string number_text(const Rational& q) {
  std::string s = exact_string(q);
  constexpr std::size_t kMax = 48;
  if (s.size() <= kMax) return s;
  return s.substr(0, 20) + "..." + s.substr(s.size() - 8) + " (" + std::to_string(s.size()) + " characters)";
}

std::string point_text(const PointQ2& p) { return "[" + number_text(p.x) + ", " + number_text(p.y) + "]"; }

std::string point_text(const OneRootPoint& p) {
  if (p.is_rational()) return point_text(PointQ2{p.x.a0, p.y.a0});
  return p.exact_string();
}

std::string halfspace_label(std::size_t i, const Halfspace2& h) {
  return "halfspaces[" + std::to_string(i) + "] (" + quoted(h.name) + ")";
}

std::string sample_label(std::size_t j, const Scene2& scene) {
  const Sample2& s = scene.samples[j];
  std::string label = "samples[" + std::to_string(j) + "]";
  if (s.halfspace >= 0 && static_cast<std::size_t>(s.halfspace) < scene.halfspaces.size()) {
    label += " (on " + quoted(scene.halfspaces[static_cast<std::size_t>(s.halfspace)].name) + ")";
  }
  return label;
}

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

/// Approximate decimal ("0.5", "1.41", "3e-41") of sqrt(num2) / den, or of num / den when num2 is not used.
/// Only for messages; 3 significant digits, computed with MPFR at 128 bits.
class Approx {
 public:
  Approx() { mpfr_init2(v_, 128); }
  explicit Approx(const Rational& q) : Approx() { mpfr_set_q(v_, q.get_mpq_t(), MPFR_RNDN); }
  Approx(const Approx& o) : Approx() { mpfr_set(v_, o.v_, MPFR_RNDN); }
  Approx& operator=(const Approx&) = delete;
  ~Approx() { mpfr_clear(v_); }
  Approx sqrt() const {
    Approx r;
    mpfr_sqrt(r.v_, v_, MPFR_RNDN);
    return r;
  }
  friend Approx operator+(const Approx& a, const Approx& b) {
    Approx r;
    mpfr_add(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  friend Approx operator/(const Approx& a, const Approx& b) {
    Approx r;
    mpfr_div(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  std::string text() const {
    char* buf = nullptr;
    if (mpfr_asprintf(&buf, "%.3Rg", v_) < 0 || buf == nullptr) return "?";
    std::string s(buf);
    mpfr_free_str(buf);
    return s;
  }

 private:
  mpfr_t v_;
};

// ---------------------------------------------------------------------------------------------------------------
// Exact predicates

Rational cross(const PointQ2& a, const PointQ2& b, const PointQ2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

int orient_exact(const PointQ2& a, const PointQ2& b, const PointQ2& c) { return sgn(cross(a, b, c)); }

Rational dot(const PointQ2& u, const PointQ2& v) { return u.x * v.x + u.y * v.y; }
PointQ2 minus(const PointQ2& a, const PointQ2& b) { return {a.x - b.x, a.y - b.y}; }

/// p on the closed segment [a, b] (a != b or a == b both fine).
bool on_segment(const PointQ2& a, const PointQ2& b, const PointQ2& p) {
  if (orient_exact(a, b, p) != 0) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

/// Nearest point of segment [a, b] to p, and its squared distance. Exact.
std::pair<PointQ2, Rational> nearest_on_segment(const PointQ2& a, const PointQ2& b, const PointQ2& p) {
  PointQ2 ab = minus(b, a);
  Rational len2 = dot(ab, ab);
  Rational t = len2 == 0 ? Rational(0) : Rational(dot(minus(p, a), ab) / len2);
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  PointQ2 q{a.x + t * ab.x, a.y + t * ab.y};
  PointQ2 d = minus(p, q);
  return {q, dot(d, d)};
}

// CGAL's interval arithmetic (Interval_nt rounds every end outward and restores the rounding mode itself) is the
// filter in front of the exact predicates of the simplicity test. Coordinates beyond 2^500 in magnitude skip the
// filter, so that no difference or product overflows (no infinite ends, no 0 * inf).
using DI = CGAL::Interval_nt<true>;

struct PointDI {
  DI x, y;
  bool filtered = false;  ///< both coordinates within [-2^500, 2^500]
};

PointDI enclose(const PointQ2& p) {
  const auto ex = CGAL::to_interval(p.x), ey = CGAL::to_interval(p.y);  // certified
  const double limit = std::ldexp(1.0, 500);
  PointDI out{DI(ex.first, ex.second), DI(ey.first, ey.second)};
  out.filtered = std::fabs(ex.first) <= limit && std::fabs(ex.second) <= limit && std::fabs(ey.first) <= limit &&
                 std::fabs(ey.second) <= limit;
  return out;
}

/// Sign of cross(a, b, c): the interval filter first, exact arithmetic when the filter cannot decide.
int orient_filtered(const PointQ2& a, const PointQ2& b, const PointQ2& c, const PointDI& ad, const PointDI& bd,
                    const PointDI& cd) {
  if (ad.filtered && bd.filtered && cd.filtered) {
    const DI v = (bd.x - ad.x) * (cd.y - ad.y) - (bd.y - ad.y) * (cd.x - ad.x);
    if (v.inf() > 0) return 1;
    if (v.sup() < 0) return -1;
  }
  return orient_exact(a, b, c);
}

// ---------------------------------------------------------------------------------------------------------------
// Polygon checks

void check_polygon(std::size_t index, const Halfspace2& h) {
  const auto& v = h.vertices;
  const std::size_t n = v.size();
  const std::string where = halfspace_label(index, h);
  if (n < 3) fail(where, "polygon needs at least 3 vertices, got " + std::to_string(n));
  if (n > kMaxPolygonVertices) {
    fail(where, "polygon has " + std::to_string(n) + " vertices; the limit is " +
                    std::to_string(kMaxPolygonVertices));
  }

  // Repeated vertices (anywhere, not only consecutive).
  {
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
      int cx = cmp(v[i].x, v[j].x);
      if (cx != 0) return cx < 0;
      int cy = cmp(v[i].y, v[j].y);
      if (cy != 0) return cy < 0;
      return i < j;
    });
    std::size_t best_i = n, best_j = n;
    for (std::size_t k = 1; k < n; ++k) {
      std::size_t i = order[k - 1], j = order[k];
      if (v[i] == v[j] && (best_i == n || std::make_pair(i, j) < std::make_pair(best_i, best_j))) {
        best_i = i;
        best_j = j;
      }
    }
    if (best_i != n) {
      fail(where, "polygon repeats a vertex: vertices " + std::to_string(best_i) + " and " + std::to_string(best_j) +
                      " are both " + point_text(v[best_i]));
    }
  }

  // Not all collinear.
  {
    bool collinear = true;
    for (std::size_t k = 2; k < n && collinear; ++k) collinear = orient_exact(v[0], v[1], v[k]) == 0;
    if (collinear) fail(where, "polygon is degenerate: all its vertices are collinear");
  }

  // Consecutive edges (i-1, i) share vertex i; they meet elsewhere only when the polygon folds back on itself.
  for (std::size_t i = 0; i < n; ++i) {
    const PointQ2& a = v[(i + n - 1) % n];
    const PointQ2& b = v[i];
    const PointQ2& c = v[(i + 1) % n];
    if (orient_exact(a, b, c) == 0 && dot(minus(b, a), minus(c, b)) < 0) {
      fail(where, "polygon is self-intersecting: edges " + std::to_string((i + n - 1) % n) + " and " +
                      std::to_string(i) + " overlap (the boundary folds back at vertex " + std::to_string(i) + " " +
                      point_text(b) + ")");
    }
  }
  if (n == 3) return;

  // Non-adjacent edges must not meet at all. Edge i runs from vertex i to vertex i+1 (mod n). Sweep over
  // conservative double bounding boxes sorted by their lower x, then filtered exact tests. Stops at the first
  // offending pair found (deterministic: the order only depends on the input).
  std::vector<PointDI> vd(n);
  for (std::size_t i = 0; i < n; ++i) vd[i] = enclose(v[i]);
  struct EdgeBox {
    double xlo, xhi, ylo, yhi;
  };
  std::vector<EdgeBox> box(n);
  for (std::size_t i = 0; i < n; ++i) {
    const PointDI& p = vd[i];
    const PointDI& q = vd[(i + 1) % n];
    box[i] = {std::min(p.x.inf(), q.x.inf()), std::max(p.x.sup(), q.x.sup()), std::min(p.y.inf(), q.y.inf()),
              std::max(p.y.sup(), q.y.sup())};
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    if (box[i].xlo != box[j].xlo) return box[i].xlo < box[j].xlo;
    return i < j;
  });

  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t ea = order[s];
    for (std::size_t t = s + 1; t < n && box[order[t]].xlo <= box[ea].xhi; ++t) {
      const std::size_t eb = order[t];
      if (box[eb].ylo > box[ea].yhi || box[ea].ylo > box[eb].yhi) continue;
      std::size_t i = std::min(ea, eb), j = std::max(ea, eb);
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // adjacent: handled above
      const PointQ2 &p1 = v[i], &p2 = v[(i + 1) % n], &q1 = v[j], &q2 = v[(j + 1) % n];
      const PointDI &p1d = vd[i], &p2d = vd[(i + 1) % n], &q1d = vd[j], &q2d = vd[(j + 1) % n];
      int d1 = orient_filtered(q1, q2, p1, q1d, q2d, p1d);
      int d2 = orient_filtered(q1, q2, p2, q1d, q2d, p2d);
      if (d1 * d2 > 0) continue;
      int d3 = orient_filtered(p1, p2, q1, p1d, p2d, q1d);
      int d4 = orient_filtered(p1, p2, q2, p1d, p2d, q2d);
      if (d3 * d4 > 0) continue;
      const std::string pair = "edges " + std::to_string(i) + " and " + std::to_string(j);
      if (d1 == 0 && d2 == 0 && d3 == 0 && d4 == 0) {
        // Collinear: they meet iff an end point of one lies on the other. No vertex is repeated, so a shared point
        // means an overlap of positive length.
        if (on_segment(p1, p2, q1) || on_segment(p1, p2, q2) || on_segment(q1, q2, p1) || on_segment(q1, q2, p2)) {
          fail(where, "polygon is self-intersecting: " + pair + " overlap");
        }
        continue;
      }
      // The supporting lines are not parallel here (parallel distinct lines give d1 == d2 != 0).
      PointQ2 r = minus(p2, p1), w = minus(q2, q1);
      Rational denom = r.x * w.y - r.y * w.x;
      Rational tt = ((q1.x - p1.x) * w.y - (q1.y - p1.y) * w.x) / denom;
      PointQ2 x{p1.x + tt * r.x, p1.y + tt * r.y};
      bool proper = d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
      fail(where, "polygon is self-intersecting: " + pair + (proper ? " cross at " : " touch at ") + point_text(x));
    }
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Samples

/// Approximate distance of p to h's boundary, as text ("0.5"). Only called when p is off the boundary.
std::string distance_text(const Halfspace2& h, const PointQ2& p) {
  switch (h.kind) {
    case HalfspaceKind2::Halfplane: {
      Rational s = abs(Rational(dot(h.normal, p) - h.offset));
      return (Approx(s) / Approx(dot(h.normal, h.normal)).sqrt()).text();
    }
    case HalfspaceKind2::Disk: {
      // | |p-c| - r | = | |p-c|^2 - r^2 | / (|p-c| + r): no cancellation.
      PointQ2 d = minus(p, h.center);
      Rational d2 = dot(d, d);
      Rational num = abs(Rational(d2 - h.radius * h.radius));
      return (Approx(num) / (Approx(d2).sqrt() + Approx(h.radius))).text();
    }
    case HalfspaceKind2::Polygon: {
      Rational best = -1;
      const std::size_t n = h.vertices.size();
      for (std::size_t i = 0; i < n; ++i) {
        Rational d2 = nearest_on_segment(h.vertices[i], h.vertices[(i + 1) % n], p).second;
        if (best < 0 || d2 < best) best = d2;
      }
      return Approx(best).sqrt().text();
    }
  }
  return "?";
}

OneRootPoint snap(const Halfspace2& h, const PointQ2& p, const std::string& where) {
  switch (h.kind) {
    case HalfspaceKind2::Halfplane: {
      Rational t = (dot(h.normal, p) - h.offset) / dot(h.normal, h.normal);
      return OneRootPoint(PointQ2{p.x - t * h.normal.x, p.y - t * h.normal.y});
    }
    case HalfspaceKind2::Disk: {
      PointQ2 d = minus(p, h.center);
      Rational D = dot(d, d);
      if (D == 0) {
        fail(where, "point " + point_text(p) + " is the center of " + quoted(h.name) +
                        ": the nearest boundary point is not unique");
      }
      // c + r (p - c) / |p - c| = c + (r d / D) sqrt(D)
      OneRoot x(h.center.x, Rational(h.radius * d.x / D), D);
      OneRoot y(h.center.y, Rational(h.radius * d.y / D), D);
      x.normalise();
      y.normalise();
      return OneRootPoint(std::move(x), std::move(y));
    }
    case HalfspaceKind2::Polygon: {
      // Nearest point over all edges, squared distances compared exactly. When two different points are equally
      // near, the first edge in vertex order wins (strict '<' below): deterministic.
      const std::size_t n = h.vertices.size();
      PointQ2 best_point;
      Rational best = -1;
      for (std::size_t i = 0; i < n; ++i) {
        auto [q, d2] = nearest_on_segment(h.vertices[i], h.vertices[(i + 1) % n], p);
        if (best < 0 || d2 < best) {
          best = d2;
          best_point = q;
        }
      }
      return OneRootPoint(best_point);
    }
  }
  return {};
}

int cmp_one_root(const Rational& a, const OneRoot& b) { return compare(OneRoot(a), b); }

bool box_contains(const Box2& box, const OneRootPoint& p) {
  if (p.is_rational()) return box.contains(PointQ2{p.x.a0, p.y.a0});
  return cmp_one_root(box.min.x, p.x) <= 0 && cmp_one_root(box.max.x, p.x) >= 0 &&
         cmp_one_root(box.min.y, p.y) <= 0 && cmp_one_root(box.max.y, p.y) >= 0;
}

std::string box_text(const Box2& b) { return "[" + point_text(b.min) + ", " + point_text(b.max) + "]"; }

// ---------------------------------------------------------------------------------------------------------------
// Domain choice

struct Extent {
  bool has_x = false, has_y = false;
  Rational xmin, xmax, ymin, ymax;
  bool empty() const { return !has_x && !has_y; }
  void add_x(const Rational& x) {
    if (!has_x || x < xmin) xmin = x;
    if (!has_x || x > xmax) xmax = x;
    has_x = true;
  }
  void add_y(const Rational& y) {
    if (!has_y || y < ymin) ymin = y;
    if (!has_y || y > ymax) ymax = y;
    has_y = true;
  }
  void add(const PointQ2& p) {
    add_x(p.x);
    add_y(p.y);
  }
};

/// The line a*x + b*y = o.
struct LineQ {
  Rational a, b, o;
};

/// Min and max of the first coordinate (x when swap == false, y when swap == true) over every intersection point
/// of two of `lines`, in O(n log n): the extreme vertices of a line arrangement are intersections of lines that
/// are adjacent in slope order (the order of the lines far to the left/right), or lie on a line perpendicular to
/// the axis. Adds them to `range` via add_x (swap == false) or add_y (swap == true).
void vertex_range(const std::vector<LineQ>& lines, bool swap, Extent& range) {
  // Coordinates (u, w): u is the axis measured, w the other one. A line is a_u*u + a_w*w = o.
  std::vector<std::pair<Rational, Rational>> sloped;  // (m, k): w = m*u + k
  std::vector<Rational> perpendicular;                // u = const
  for (const LineQ& l : lines) {
    const Rational& au = swap ? l.b : l.a;
    const Rational& aw = swap ? l.a : l.b;
    if (aw == 0) {
      perpendicular.push_back(l.o / au);
    } else {
      sloped.emplace_back(Rational(-au / aw), Rational(l.o / aw));
    }
  }
  auto add = [&](const Rational& u) {
    if (swap) {
      range.add_y(u);
    } else {
      range.add_x(u);
    }
  };
  if (!sloped.empty()) {
    for (const Rational& u : perpendicular) add(u);
  }
  std::sort(sloped.begin(), sloped.end(), [](const auto& p, const auto& q) {
    int c = cmp(p.first, q.first);
    return c != 0 ? c < 0 : p.second < q.second;
  });
  // Slope classes: (m, kmin, kmax) in increasing m.
  struct Class {
    Rational m, kmin, kmax;
  };
  std::vector<Class> classes;
  for (const auto& [m, k] : sloped) {
    if (classes.empty() || classes.back().m != m) {
      classes.push_back({m, k, k});
    } else {
      classes.back().kmax = k;
    }
  }
  for (std::size_t c = 1; c < classes.size(); ++c) {
    const Class& p = classes[c - 1];
    const Class& q = classes[c];
    for (const Rational* k1 : {&p.kmin, &p.kmax}) {
      for (const Rational* k2 : {&q.kmin, &q.kmax}) add((*k2 - *k1) / (p.m - q.m));
    }
  }
}

Rational floor_q(const Rational& q) {
  Integer r;
  mpz_fdiv_q(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return Rational(r);
}

Rational ceil_q(const Rational& q) {
  Integer r;
  mpz_cdiv_q(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return Rational(r);
}

}  // namespace

// -----------------------------------------------------------------------------------------------------------------

const char* to_string(HalfspaceKind2 kind) {
  switch (kind) {
    case HalfspaceKind2::Halfplane:
      return "halfplane";
    case HalfspaceKind2::Disk:
      return "disk";
    case HalfspaceKind2::Polygon:
      return "polygon";
  }
  return "?";
}

int Halfspace2::side(const PointQ2& p) const {
  int inside = 0;  // +1 inside, 0 boundary, -1 outside, before complement
  switch (kind) {
    case HalfspaceKind2::Halfplane:
      inside = -sgn(Rational(dot(normal, p) - offset));
      break;
    case HalfspaceKind2::Disk: {
      PointQ2 d = minus(p, center);
      inside = -sgn(Rational(dot(d, d) - radius * radius));
      break;
    }
    case HalfspaceKind2::Polygon: {
      const std::size_t n = vertices.size();
      int winding = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const PointQ2& a = vertices[i];
        const PointQ2& b = vertices[(i + 1) % n];
        if (on_segment(a, b, p)) return 0;
        if (a.y <= p.y) {
          if (b.y > p.y && orient_exact(a, b, p) > 0) ++winding;
        } else {
          if (b.y <= p.y && orient_exact(a, b, p) < 0) --winding;
        }
      }
      inside = winding != 0 ? 1 : -1;
      break;
    }
  }
  return complement ? -inside : inside;
}

int Scene2::find_halfspace(const std::string& name) const {
  for (std::size_t i = 0; i < halfspaces.size(); ++i) {
    if (halfspaces[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

Rational signed_area(const std::vector<PointQ2>& polygon) {
  Rational twice = 0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const PointQ2& a = polygon[i];
    const PointQ2& b = polygon[(i + 1) % n];
    twice += a.x * b.y - a.y * b.x;
  }
  return twice / 2;
}

void validate_and_resolve(Scene2& scene) {
  if (scene.halfspaces.empty()) fail("halfspaces", "the scene has no halfspace (at least one is needed)");

  // The total is checked before any polygon's (quadratic) simplicity test, so an oversized scene is refused at once.
  std::size_t total_polygon_vertices = 0;
  for (const Halfspace2& h : scene.halfspaces)
    if (h.kind == HalfspaceKind2::Polygon) total_polygon_vertices += h.vertices.size();
  if (total_polygon_vertices > kMaxTotalPolygonVertices) {
    fail("halfspaces", "all polygons together have " + std::to_string(total_polygon_vertices) +
                           " vertices, more than the limit of " + std::to_string(kMaxTotalPolygonVertices));
  }
  std::unordered_map<std::string, std::size_t> names;
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
    const Halfspace2& h = scene.halfspaces[i];
    const std::string where = halfspace_label(i, h);
    if (h.name.empty()) fail("halfspaces[" + std::to_string(i) + "]", "the name is empty");
    auto [it, fresh] = names.emplace(h.name, i);
    if (!fresh) fail(where, "duplicate name (also used by halfspaces[" + std::to_string(it->second) + "])");
    switch (h.kind) {
      case HalfspaceKind2::Halfplane:
        if (h.normal.x == 0 && h.normal.y == 0) fail(where, "the normal of a halfplane must not be zero");
        break;
      case HalfspaceKind2::Disk:
        if (h.radius <= 0) fail(where, "the radius must be positive, got " + number_text(h.radius));
        break;
      case HalfspaceKind2::Polygon:
        check_polygon(i, h);
        break;
    }
  }

  for (std::size_t j = 0; j < scene.samples.size(); ++j) {
    Sample2& s = scene.samples[j];
    if (s.halfspace < 0 || static_cast<std::size_t>(s.halfspace) >= scene.halfspaces.size()) {
      fail(sample_label(j, scene), "halfspace index " + std::to_string(s.halfspace) + " is out of range");
    }
    const Halfspace2& h = scene.halfspaces[static_cast<std::size_t>(s.halfspace)];
    const std::string where = sample_label(j, scene);
    if (s.snapped) {
      s.location = snap(h, s.given, where);
    } else {
      if (h.side(s.given) != 0) {
        fail(where, "point " + point_text(s.given) + " is not on the boundary of " + quoted(h.name) + " (about " +
                        distance_text(h, s.given) + " away)");
      }
      s.location = OneRootPoint(s.given);
    }
  }

  if (!scene.domain_given) {
    scene.domain = choose_domain(scene);
    return;
  }
  const Box2& d = scene.domain;
  if (!(d.min.x < d.max.x && d.min.y < d.max.y)) {
    fail("domain", "min must be below max in both coordinates, got " + box_text(d));
  }
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
    const Halfspace2& h = scene.halfspaces[i];
    if (h.kind == HalfspaceKind2::Disk) {
      if (h.center.x - h.radius < d.min.x || h.center.x + h.radius > d.max.x || h.center.y - h.radius < d.min.y ||
          h.center.y + h.radius > d.max.y) {
        fail(halfspace_label(i, h), "the disk is not inside the domain " + box_text(d));
      }
    } else if (h.kind == HalfspaceKind2::Polygon) {
      for (std::size_t k = 0; k < h.vertices.size(); ++k) {
        if (!d.contains(h.vertices[k])) {
          fail(halfspace_label(i, h), "vertex " + std::to_string(k) + " " + point_text(h.vertices[k]) +
                                          " is outside the domain " + box_text(d));
        }
      }
    }
  }
  for (std::size_t j = 0; j < scene.samples.size(); ++j) {
    const Sample2& s = scene.samples[j];
    if (!box_contains(d, s.location)) {
      fail(sample_label(j, scene), std::string(s.snapped ? "snapped point " : "point ") + point_text(s.location) +
                                       " is outside the domain " + box_text(d));
    }
  }
}

Box2 choose_domain(const Scene2& scene) {
  Extent e;
  std::vector<LineQ> lines;
  for (const Halfspace2& h : scene.halfspaces) {
    switch (h.kind) {
      case HalfspaceKind2::Halfplane:
        if (h.normal.x != 0 || h.normal.y != 0) lines.push_back({h.normal.x, h.normal.y, h.offset});
        break;
      case HalfspaceKind2::Disk: {
        // Every intersection of the circle with anything lies in its bounding box.
        Rational r = abs(h.radius);
        e.add(PointQ2{h.center.x - r, h.center.y - r});
        e.add(PointQ2{h.center.x + r, h.center.y + r});
        break;
      }
      case HalfspaceKind2::Polygon:
        for (const PointQ2& p : h.vertices) e.add(p);
        break;
    }
  }
  for (const Sample2& s : scene.samples) {
    // A snapped sample with an irrational location lies on a circle, hence inside that disk's bounding box.
    if (!s.snapped) {
      e.add(s.given);
    } else if (s.location.is_rational()) {
      e.add(PointQ2{s.location.x.a0, s.location.y.a0});
    }
  }
  // Line-line vertices (the line-circle and line-polygon ones are inside the boxes above).
  vertex_range(lines, false, e);
  vertex_range(lines, true, e);
  // The two passes find the same vertices, so x and y ranges come together; keep the extent consistent anyway.
  if (e.has_x != e.has_y) {
    if (!e.has_x) e.add_x(0);
    if (!e.has_y) e.add_y(0);
  }

  // Every line must cross the box: a line that does not cross the current extent gets the point of it nearest
  // to the extent's center (or to the origin when there is nothing else, e.g. parallel half-planes only).
  const bool had_extent = !e.empty();
  const Extent base = e;
  PointQ2 center{0, 0};
  if (had_extent) center = PointQ2{(base.xmin + base.xmax) / 2, (base.ymin + base.ymax) / 2};
  for (const LineQ& l : lines) {
    if (had_extent) {
      bool below = false, above = false;
      for (const Rational* x : {&base.xmin, &base.xmax}) {
        for (const Rational* y : {&base.ymin, &base.ymax}) {
          int s = sgn(Rational(l.a * *x + l.b * *y - l.o));
          below |= s < 0;
          above |= s > 0;
        }
      }
      if (below && above) continue;
    }
    Rational t = (l.a * center.x + l.b * center.y - l.o) / (l.a * l.a + l.b * l.b);
    e.add(PointQ2{center.x - t * l.a, center.y - t * l.b});
  }
  if (e.empty()) e.add(PointQ2{0, 0});

  Rational w = e.xmax - e.xmin, hgt = e.ymax - e.ymin;
  Rational margin = std::max(w, hgt) / 10;
  if (margin < 1) margin = 1;
  Box2 box;
  box.min = PointQ2{floor_q(e.xmin - margin), floor_q(e.ymin - margin)};
  box.max = PointQ2{ceil_q(e.xmax + margin), ceil_q(e.ymax + margin)};
  return box;
}

}  // namespace hsx
