// 3D scenes: exact sides, validation and sample resolution. See scene3.hpp for the conventions.
//
// Decisions documented here:
// - Surfaces are validated by build_mesh3 (the .obj checks: closed, edge- and vertex-manifold, consistently
//   oriented, no zero-area triangle, no fold, non-zero volume); an inward surface is reversed with a note, so its
//   triangles here are always outward. Messages name the halfspace, then the face (0-based triangle id).
// - Nearest points: triangles are visited in order of a double-precision lower bound of their distance (the
//   distance to their bounding box, rounded down); a triangle is skipped only when that bound exceeds the best
//   exact squared distance found so far (rounded up), so the answer is the exact minimum. Equal distances keep the
//   point of the lowest-numbered triangle.
#include <hsx/geometry/scene3.hpp>
#include <hsx/geometry/text3.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>

namespace hsx {

namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

std::string number_text(const Rational& q) {
  std::string s = exact_string(q);
  constexpr std::size_t kMax = 48;
  if (s.size() <= kMax) return s;
  return s.substr(0, 20) + "..." + s.substr(s.size() - 8) + " (" + std::to_string(s.size()) + " characters)";
}

}  // namespace

std::string point_text(const PointQ3& p) {
  return "[" + number_text(p.x) + ", " + number_text(p.y) + ", " + number_text(p.z) + "]";
}

std::string box_text(const Box3& b) { return "[" + point_text(b.min) + ", " + point_text(b.max) + "]"; }

namespace {

std::string halfspace_label(std::size_t i, const Halfspace3& h) {
  return "halfspaces[" + std::to_string(i) + "] (" + quoted(h.name) + ")";
}

std::string sample_label(std::size_t j, const Scene3& scene) {
  const Sample3& s = scene.samples[j];
  std::string label = "samples[" + std::to_string(j) + "]";
  if (s.halfspace >= 0 && static_cast<std::size_t>(s.halfspace) < scene.halfspaces.size())
    label += " (on " + quoted(scene.halfspaces[static_cast<std::size_t>(s.halfspace)].name) + ")";
  return label;
}

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

PointQ3 sub(const PointQ3& a, const PointQ3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
PointQ3 add_scaled(const PointQ3& a, const Rational& t, const PointQ3& d) {
  return {a.x + t * d.x, a.y + t * d.y, a.z + t * d.z};
}
bool is_zero(const PointQ3& p) { return sgn(p.x) == 0 && sgn(p.y) == 0 && sgn(p.z) == 0; }
Rational norm2(const PointQ3& p) { return dot3(p, p); }

/// The exact nearest point of triangle abc to p (the Voronoi-region walk over vertices, edges and the face).
PointQ3 nearest_on_triangle(const PointQ3& p, const PointQ3& a, const PointQ3& b, const PointQ3& c) {
  const PointQ3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const Rational d1 = dot3(ab, ap), d2 = dot3(ac, ap);
  if (sgn(d1) <= 0 && sgn(d2) <= 0) return a;
  const PointQ3 bp = sub(p, b);
  const Rational d3 = dot3(ab, bp), d4 = dot3(ac, bp);
  if (sgn(d3) >= 0 && d4 <= d3) return b;
  const Rational vc = d1 * d4 - d3 * d2;
  if (sgn(vc) <= 0 && sgn(d1) >= 0 && sgn(d3) <= 0) return add_scaled(a, d1 / (d1 - d3), ab);
  const PointQ3 cp = sub(p, c);
  const Rational d5 = dot3(ab, cp), d6 = dot3(ac, cp);
  if (sgn(d6) >= 0 && d5 <= d6) return c;
  const Rational vb = d5 * d2 - d1 * d6;
  if (sgn(vb) <= 0 && sgn(d2) >= 0 && sgn(d6) <= 0) return add_scaled(a, d2 / (d2 - d6), ac);
  const Rational va = d3 * d6 - d5 * d4;
  if (sgn(va) <= 0 && sgn(d4 - d3) >= 0 && sgn(d5 - d6) >= 0)
    return add_scaled(b, (d4 - d3) / ((d4 - d3) + (d5 - d6)), sub(c, b));
  const Rational denom = va + vb + vc;
  return add_scaled(add_scaled(a, vb / denom, ab), vc / denom, ac);
}

double down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }
double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

/// A lower bound (in double) of the squared distance from p to the box of triangle t; `p_lo`, `p_hi` enclose p.
/// Every gap is rounded down; 0 (no pruning) when the numbers overflow doubles.
double box_distance2_lower(const TriangleSurface& s, const std::array<int, 3>& t, const double p_lo[3],
                           const double p_hi[3]) {
  double total = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int v : t) {
      const PointQ3& q = s.vertices[static_cast<std::size_t>(v)];
      const double x = (axis == 0 ? q.x : axis == 1 ? q.y : q.z).get_d();
      lo = std::min(lo, down(x));
      hi = std::max(hi, up(x));
    }
    double gap = 0;
    if (p_hi[axis] < lo) gap = down(lo - p_hi[axis]);
    else if (p_lo[axis] > hi) gap = down(p_lo[axis] - hi);
    total += std::max(gap, 0.0) * std::max(gap, 0.0);
  }
  return std::isfinite(total) ? total * (1 - 1e-9) : 0.0;
}

struct Nearest {
  PointQ3 point;
  Rational distance2;
  int triangle = -1;
};

/// The exact nearest point of a surface to p; ties keep the lowest triangle id.
Nearest nearest_on_surface(const TriangleSurface& s, const PointQ3& p) {
  const double pd[3] = {p.x.get_d(), p.y.get_d(), p.z.get_d()};
  const double p_lo[3] = {down(pd[0]), down(pd[1]), down(pd[2])}, p_hi[3] = {up(pd[0]), up(pd[1]), up(pd[2])};
  std::vector<std::pair<double, int>> order;
  order.reserve(s.triangles.size());
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    order.emplace_back(box_distance2_lower(s, s.triangles[i], p_lo, p_hi), static_cast<int>(i));
  std::sort(order.begin(), order.end());
  Nearest best;
  double best_upper = std::numeric_limits<double>::infinity();
  for (const auto& [bound, i] : order) {
    if (bound > best_upper) break;  // sorted: every later triangle is farther
    const auto& t = s.triangles[static_cast<std::size_t>(i)];
    const PointQ3 q = nearest_on_triangle(p, s.vertices[static_cast<std::size_t>(t[0])],
                                          s.vertices[static_cast<std::size_t>(t[1])],
                                          s.vertices[static_cast<std::size_t>(t[2])]);
    Rational d2 = norm2(sub(q, p));
    const int c = best.triangle < 0 ? -1 : cmp(d2, best.distance2);
    if (c < 0 || (c == 0 && i < best.triangle)) {
      best = Nearest{q, std::move(d2), i};
      const double d = up(best.distance2.get_d()) * (1 + 1e-9);
      best_upper = std::isfinite(d) ? d : std::numeric_limits<double>::infinity();
    }
  }
  return best;
}

bool on_triangle(const PointQ3& p, const PointQ3& a, const PointQ3& b, const PointQ3& c) {
  const PointQ3 n = triangle_normal(a, b, c);
  if (sgn(dot3(n, sub(p, a))) != 0) return false;
  return sgn(dot3(n, triangle_normal(p, a, b))) >= 0 && sgn(dot3(n, triangle_normal(p, b, c))) >= 0 &&
         sgn(dot3(n, triangle_normal(p, c, a))) >= 0;
}

std::string distance_text(const Rational& d2) {
  const double d = std::sqrt(d2.get_d());
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", d);
  return buf;
}

void validate_surface(std::size_t i, Halfspace3& h, std::vector<std::string>& notes) {
  const std::string where = halfspace_label(i, h);
  if (h.surface.triangles.empty()) fail(where, "the surface has no triangles");
  ObjMesh obj;
  obj.source = where + (h.origin.empty() ? std::string() : " (" + h.origin + ")");
  obj.vertices = h.surface.vertices;
  obj.faces = h.surface.triangles;
  for (const auto& t : obj.faces)
    for (int v : t)
      if (v < 0 || static_cast<std::size_t>(v) >= obj.vertices.size())
        fail(where, "a triangle refers to vertex " + std::to_string(v) + ", which does not exist");
  Mesh3 mesh = build_mesh3(std::move(obj));
  if (mesh.flipped) {
    h.surface.triangles = std::move(mesh.faces);
    notes.push_back(where + ": the surface was oriented inward; every triangle was reversed");
  }
}

void resolve_sample(std::size_t j, Scene3& scene) {
  Sample3& s = scene.samples[j];
  if (s.halfspace < 0 || static_cast<std::size_t>(s.halfspace) >= scene.halfspaces.size())
    fail(sample_label(j, scene), "refers to no halfspace");
  const Halfspace3& h = scene.halfspaces[static_cast<std::size_t>(s.halfspace)];
  const std::string where = sample_label(j, scene);
  if (h.kind == HalfspaceKind3::Plane) {
    const Rational excess = dot3(h.normal, s.given) - h.offset;
    const Rational t = excess / norm2(h.normal);
    if (!s.snapped) {
      if (sgn(excess) != 0)
        fail(where, "point " + point_text(s.given) + " is not on the plane " + quoted(h.name) + " (about " +
                        distance_text(t * excess) + " away)");
      s.location = s.given;
      s.distance2 = 0;
      return;
    }
    s.location = add_scaled(s.given, -t, h.normal);
    s.distance2 = t * excess;
    return;
  }
  if (!s.snapped) {
    for (const auto& t : h.surface.triangles)
      if (on_triangle(s.given, h.surface.vertices[static_cast<std::size_t>(t[0])],
                      h.surface.vertices[static_cast<std::size_t>(t[1])],
                      h.surface.vertices[static_cast<std::size_t>(t[2])])) {
        s.location = s.given;
        s.distance2 = 0;
        return;
      }
    const Nearest n = nearest_on_surface(h.surface, s.given);
    fail(where, "point " + point_text(s.given) + " is not on the boundary of " + quoted(h.name) + " (about " +
                    distance_text(n.distance2) + " away; its nearest boundary point is on triangle " +
                    std::to_string(n.triangle) + "; use \"near\" to snap it)");
  }
  Nearest n = nearest_on_surface(h.surface, s.given);
  s.location = std::move(n.point);
  s.distance2 = std::move(n.distance2);
}

/// A growing axis-aligned extent.
struct Extent3 {
  bool empty = true;
  PointQ3 lo, hi;
  void add(const PointQ3& p) {
    if (empty) {
      lo = hi = p;
      empty = false;
      return;
    }
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
};

/// The point where three planes meet, if they meet in one point (Cramer's rule).
std::optional<PointQ3> meet(const Halfspace3& a, const Halfspace3& b, const Halfspace3& c) {
  const PointQ3 bc = triangle_normal(PointQ3{}, b.normal, c.normal);  // b.n x c.n
  const Rational det = dot3(a.normal, bc);
  if (sgn(det) == 0) return std::nullopt;
  const PointQ3 ca = triangle_normal(PointQ3{}, c.normal, a.normal), ab = triangle_normal(PointQ3{}, a.normal, b.normal);
  PointQ3 x{a.offset * bc.x + b.offset * ca.x + c.offset * ab.x, a.offset * bc.y + b.offset * ca.y + c.offset * ab.y,
            a.offset * bc.z + b.offset * ca.z + c.offset * ab.z};
  return PointQ3{x.x / det, x.y / det, x.z / det};
}

/// Whether a plane crosses (or touches) the box: n.x - offset takes both signs (or zero) over its corners.
bool plane_meets(const Halfspace3& h, const PointQ3& lo, const PointQ3& hi) {
  bool below = false, above = false;
  for (int i = 0; i < 8; ++i) {
    const PointQ3 corner{(i & 1 ? hi : lo).x, (i & 2 ? hi : lo).y, (i & 4 ? hi : lo).z};
    const int s = sgn(dot3(h.normal, corner) - h.offset);
    below = below || s <= 0;
    above = above || s >= 0;
  }
  return below && above;
}

}  // namespace

const char* to_string(HalfspaceKind3 kind) {
  switch (kind) {
    case HalfspaceKind3::Plane: return "plane";
    case HalfspaceKind3::Mesh: return "mesh";
    case HalfspaceKind3::Box: return "box";
    case HalfspaceKind3::Sphere: return "sphere";
    case HalfspaceKind3::Cylinder: return "cylinder";
    case HalfspaceKind3::Cone: return "cone";
    case HalfspaceKind3::Torus: return "torus";
  }
  return "?";
}

int Halfspace3::side(const PointQ3& p) const {
  int s = 0;
  if (kind == HalfspaceKind3::Plane) {
    s = -sgn(dot3(normal, p) - offset);
  } else {
    const std::optional<bool> inside = point_inside_triangles(surface.vertices, surface.triangles, p);
    s = !inside ? 0 : (*inside ? 1 : -1);
  }
  return complement ? -s : s;
}

int Scene3::find_halfspace(const std::string& name) const {
  for (std::size_t i = 0; i < halfspaces.size(); ++i)
    if (halfspaces[i].name == name) return static_cast<int>(i);
  return -1;
}

void validate_and_resolve(Scene3& scene) {
  if (scene.halfspaces.empty()) fail("halfspaces", "the scene has no halfspace (at least one is needed)");
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
    Halfspace3& h = scene.halfspaces[i];
    if (h.kind == HalfspaceKind3::Plane) {
      if (is_zero(h.normal)) fail(halfspace_label(i, h), "the normal must not be zero");
    } else {
      validate_surface(i, h, scene.notes);
    }
  }
  for (std::size_t j = 0; j < scene.samples.size(); ++j) resolve_sample(j, scene);
  if (!scene.domain_given) {
    scene.domain = choose_domain3(scene);
    return;
  }
  const Box3& d = scene.domain;
  if (!(d.min.x < d.max.x && d.min.y < d.max.y && d.min.z < d.max.z))
    fail("domain", "min must be below max in every coordinate, got " + box_text(d));
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
    const Halfspace3& h = scene.halfspaces[i];
    for (std::size_t v = 0; v < h.surface.vertices.size(); ++v)
      if (!d.contains(h.surface.vertices[v]))
        fail(halfspace_label(i, h), "vertex " + std::to_string(v) + " " + point_text(h.surface.vertices[v]) +
                                        " is outside the domain " + box_text(d));
  }
  for (std::size_t j = 0; j < scene.samples.size(); ++j) {
    const Sample3& s = scene.samples[j];
    if (!d.contains(s.location))
      fail(sample_label(j, scene), std::string(s.snapped ? "snapped point " : "point ") + point_text(s.location) +
                                       " is outside the domain " + box_text(d));
  }
}

Box3 choose_domain3(const Scene3& scene) {
  std::size_t plane_count = 0;
  for (const Halfspace3& h : scene.halfspaces) plane_count += h.kind == HalfspaceKind3::Plane;
  if (plane_count > kMaxPlanesWithoutDomain)
    fail("domain", "the scene has " + std::to_string(plane_count) + " planes and no domain; give \"domain\" (hsx "
                   "chooses one only for at most " + std::to_string(kMaxPlanesWithoutDomain) + " planes)");
  Extent3 e;
  std::vector<const Halfspace3*> planes;
  for (const Halfspace3& h : scene.halfspaces) {
    if (h.kind == HalfspaceKind3::Plane) {
      if (!is_zero(h.normal)) planes.push_back(&h);
    } else {
      for (const PointQ3& p : h.surface.vertices) e.add(p);
    }
  }
  for (const Sample3& s : scene.samples) {
    e.add(s.given);
    e.add(s.location);
  }
  for (std::size_t a = 0; a < planes.size(); ++a)
    for (std::size_t b = a + 1; b < planes.size(); ++b)
      for (std::size_t c = b + 1; c < planes.size(); ++c)
        if (auto x = meet(*planes[a], *planes[b], *planes[c])) e.add(*x);
  // Every plane must cross the box: one that misses the extent gets its point nearest to the extent's centre.
  for (const Halfspace3* h : planes) {
    if (!e.empty && plane_meets(*h, e.lo, e.hi)) continue;
    const PointQ3 centre = e.empty ? PointQ3{Rational(0), Rational(0), Rational(0)}
                                   : PointQ3{(e.lo.x + e.hi.x) / 2, (e.lo.y + e.hi.y) / 2, (e.lo.z + e.hi.z) / 2};
    const Rational t = (dot3(h->normal, centre) - h->offset) / norm2(h->normal);
    e.add(add_scaled(centre, -t, h->normal));
  }
  if (e.empty) e.add(PointQ3{Rational(0), Rational(0), Rational(0)});
  Rational side = std::max({e.hi.x - e.lo.x, e.hi.y - e.lo.y, e.hi.z - e.lo.z});
  const Rational margin = sgn(side) == 0 ? Rational(1) : side / 10;
  Box3 box;
  box.min = {e.lo.x - margin, e.lo.y - margin, e.lo.z - margin};
  box.max = {e.hi.x + margin, e.hi.y + margin, e.hi.z + margin};
  return box;
}

}  // namespace hsx
