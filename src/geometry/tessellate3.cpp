// Tessellation of 3D primitives: see tessellate3.hpp for the exact vertices and triangles.
#include <hsx/geometry/tessellate3.hpp>

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <utility>

namespace hsx {

namespace {

constexpr mpfr_prec_t kBits = 128;

/// A 128-bit MPFR number (RAII), just enough arithmetic for the vertex formulas.
class Real {
 public:
  Real() { mpfr_init2(v_, kBits); mpfr_set_zero(v_, 1); }
  explicit Real(const Rational& q) : Real() { mpfr_set_q(v_, q.get_mpq_t(), MPFR_RNDN); }
  Real(const Real& o) : Real() { mpfr_set(v_, o.v_, MPFR_RNDN); }
  Real& operator=(const Real& o) { mpfr_set(v_, o.v_, MPFR_RNDN); return *this; }
  ~Real() { mpfr_clear(v_); }
  friend Real operator+(const Real& a, const Real& b) { Real r; mpfr_add(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend Real operator-(const Real& a, const Real& b) { Real r; mpfr_sub(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend Real operator*(const Real& a, const Real& b) { Real r; mpfr_mul(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend Real operator/(const Real& a, const Real& b) { Real r; mpfr_div(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  Real sqrt() const { Real r; mpfr_sqrt(r.v_, v_, MPFR_RNDN); return r; }
  /// cos and sin of 2 pi k / n.
  static std::pair<Real, Real> turn(long k, long n) {
    Real a, c, s;
    mpfr_const_pi(a.v_, MPFR_RNDN);
    mpfr_mul_si(a.v_, a.v_, 2 * k, MPFR_RNDN);
    mpfr_div_si(a.v_, a.v_, n, MPFR_RNDN);
    mpfr_sin_cos(s.v_, c.v_, a.v_, MPFR_RNDN);
    return {c, s};
  }
  /// cos and sin of -pi/2 + pi j / m.
  static std::pair<Real, Real> latitude(long j, long m) {
    Real a, c, s;
    mpfr_const_pi(a.v_, MPFR_RNDN);
    mpfr_mul_si(a.v_, a.v_, 2 * j - m, MPFR_RNDN);
    mpfr_div_si(a.v_, a.v_, 2 * m, MPFR_RNDN);
    mpfr_sin_cos(s.v_, c.v_, a.v_, MPFR_RNDN);
    return {c, s};
  }
  /// The nearest multiple of 2^-kTessellationGridBits (ties to even).
  Rational on_grid() const {
    Real scaled;
    mpfr_mul_2si(scaled.v_, v_, kTessellationGridBits, MPFR_RNDN);
    Integer z;
    mpfr_get_z(z.get_mpz_t(), scaled.v_, MPFR_RNDN);
    Integer den = 1;
    den <<= kTessellationGridBits;
    return make_rational(z, den);
  }

 private:
  mpfr_t v_;
};

struct Vec {
  Real x, y, z;
};
Vec operator+(const Vec& a, const Vec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator*(const Real& s, const Vec& a) { return {s * a.x, s * a.y, s * a.z}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec unit(const Vec& a) {
  const Real n = (a.x * a.x + a.y * a.y + a.z * a.z).sqrt();
  return {a.x / n, a.y / n, a.z / n};
}
Vec real(const PointQ3& p) { return {Real(p.x), Real(p.y), Real(p.z)}; }
PointQ3 on_grid(const Vec& v) { return {v.x.on_grid(), v.y.on_grid(), v.z.on_grid()}; }

struct Frame {
  Vec u, v, w;
};

Vec coordinate_axis(int e) { return {Real(Rational(e == 0)), Real(Rational(e == 1)), Real(Rational(e == 2))}; }

/// The frame of axis `a` under `style` (tessellate3.hpp): e = the coordinate axis of the smallest |a_i|, or the
/// authors' +x (+y when a is parallel to x).
Frame frame_of(const PointQ3& a, Tessellation3::Frame style) {
  Frame f;
  f.w = unit(real(a));
  int e = 0;
  if (style == Tessellation3::Frame::Bsh) {
    e = sgn(a.y) == 0 && sgn(a.z) == 0 ? 1 : 0;
  } else {
    const Rational ax = abs(a.x), ay = abs(a.y), az = abs(a.z);
    e = ax <= ay && ax <= az ? 0 : (ay <= az ? 1 : 2);
  }
  f.u = unit(cross(f.w, coordinate_axis(e)));
  f.v = cross(f.w, f.u);
  return f;
}

/// A sphere's frame: that of +z, or the coordinate frame (u = +x, v = +y, w = +z) in the authors' style.
Frame sphere_frame(Tessellation3::Frame style) {
  if (style == Tessellation3::Frame::Bsh) return {coordinate_axis(0), coordinate_axis(1), coordinate_axis(2)};
  return frame_of(PointQ3{Rational(0), Rational(0), Rational(1)}, style);
}

bool is_zero(const PointQ3& p) { return sgn(p.x) == 0 && sgn(p.y) == 0 && sgn(p.z) == 0; }
PointQ3 sub(const PointQ3& a, const PointQ3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

/// Adds the n ring points c + rho (cos theta_k u + sin theta_k v) (+ offset w, when given); returns the first id.
int add_ring(TriangleSurface& s, const Vec& c, const Real& rho, const Frame& f, int n) {
  const int first = static_cast<int>(s.vertices.size());
  for (int k = 0; k < n; ++k) {
    const auto [ck, sk] = Real::turn(k, n);
    s.vertices.push_back(on_grid(c + rho * ((ck * f.u) + (sk * f.v))));
  }
  return first;
}

void add_band(TriangleSurface& s, int lower, int upper, int n) {
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n;
    s.triangles.push_back({lower + k, lower + k1, upper + k});
    s.triangles.push_back({lower + k1, upper + k1, upper + k});
  }
}
void add_bottom_fan(TriangleSurface& s, int apex, int ring, int n) {
  for (int k = 0; k < n; ++k) s.triangles.push_back({apex, ring + (k + 1) % n, ring + k});
}
void add_top_fan(TriangleSurface& s, int apex, int ring, int n) {
  for (int k = 0; k < n; ++k) s.triangles.push_back({apex, ring + k, ring + (k + 1) % n});
}

void check_positive(const Rational& q, const char* what) {
  if (sgn(q) <= 0) throw InputError(std::string(what) + " must be positive, got " + exact_string(q));
}

void check_triangles(std::size_t count) {
  if (count > kMaxTessellationTriangles)
    throw InputError("tessellation: " + std::to_string(count) + " triangles; the limit is " +
                     std::to_string(kMaxTessellationTriangles) + " per primitive");
}

TriangleSurface box_surface(const PointQ3& lo, const PointQ3& hi) {
  if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
    throw InputError("min must be below max in every coordinate");
  TriangleSurface s;
  for (int i = 0; i < 8; ++i)
    s.vertices.push_back({(i & 1 ? hi : lo).x, (i & 2 ? hi : lo).y, (i & 4 ? hi : lo).z});
  s.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return s;
}

TriangleSurface sphere_surface(const Primitive3& p) {
  check_positive(p.radius, "radius");
  const int n = circle_segments(p.tessellation, p.radius);
  const int m = sphere_bands(p.tessellation, n);
  check_triangles(std::size_t(2) * n * (m - 1));
  const Frame f = sphere_frame(p.tessellation.frame);
  const Vec c = real(p.center);
  const Real r(p.radius);
  TriangleSurface s;
  s.vertices.push_back(on_grid(c + (Real(Rational(-1)) * r) * f.w));
  for (int j = 1; j < m; ++j) {
    const auto [cj, sj] = Real::latitude(j, m);
    add_ring(s, c + (r * sj) * f.w, r * cj, f, n);
  }
  const int north = static_cast<int>(s.vertices.size());
  s.vertices.push_back(on_grid(c + r * f.w));
  add_bottom_fan(s, 0, 1, n);
  for (int j = 1; j + 1 < m; ++j) add_band(s, 1 + (j - 1) * n, 1 + j * n, n);
  add_top_fan(s, north, 1 + (m - 2) * n, n);
  return s;
}

TriangleSurface torus_surface(const Primitive3& p) {
  check_positive(p.minor_radius, "minor_radius");
  if (p.minor_radius >= p.major_radius)
    throw InputError("minor_radius (" + exact_string(p.minor_radius) + ") must be below major_radius (" +
                     exact_string(p.major_radius) + "): otherwise the torus intersects itself");
  if (is_zero(p.axis)) throw InputError("axis_vector must not be zero");
  const int n = circle_segments(p.tessellation, p.major_radius);
  const int m = circle_segments(p.tessellation, p.minor_radius, true);
  check_triangles(std::size_t(2) * n * m);
  const Frame f = frame_of(p.axis, p.tessellation.frame);
  const Vec c = real(p.center);
  const Real big(p.major_radius), r(p.minor_radius);
  TriangleSurface s;
  for (int j = 0; j < m; ++j) {
    const auto [cj, sj] = Real::turn(j, m);
    add_ring(s, c + (r * sj) * f.w, big + r * cj, f, n);
  }
  for (int j = 0; j < m; ++j) add_band(s, j * n, ((j + 1) % m) * n, n);
  return s;
}

TriangleSurface infinite_cone_surface(const Primitive3& p, const Box3& domain);

TriangleSurface cone_surface(const Primitive3& p, const Box3& domain) {
  check_positive(p.radius, "radius");
  const PointQ3 a = sub(p.point2, p.point1);
  if (is_zero(a)) throw InputError("the axis has zero length (apex == base_center)");
  if (p.infinite) return infinite_cone_surface(p, domain);
  const int n = circle_segments(p.tessellation, p.radius);
  check_triangles(std::size_t(2) * n);
  const Frame f = frame_of(a, p.tessellation.frame);
  TriangleSurface s;
  s.vertices.push_back(on_grid(real(p.point1)));
  add_ring(s, real(p.point2), Real(p.radius), f, n);
  s.vertices.push_back(on_grid(real(p.point2)));
  add_bottom_fan(s, 0, 1, n);
  add_top_fan(s, n + 1, 1, n);
  return s;
}

// --- Infinite cylinders: a convex polyhedron clipped exactly ------------------------------------------------

using Polygon3 = std::vector<PointQ3>;

struct PointLess {
  bool operator()(const PointQ3& a, const PointQ3& b) const {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
  }
};

/// Keeps the part of a convex polyhedron (faces counter-clockwise from outside) where n . x <= d, closing it with
/// the cap on the plane.
std::vector<Polygon3> clip(const std::vector<Polygon3>& faces, const PointQ3& n, const Rational& d) {
  std::vector<Polygon3> out;
  for (const Polygon3& f : faces) {
    std::vector<int> side(f.size());
    bool any_out = false, any_in = false;
    for (std::size_t i = 0; i < f.size(); ++i) {
      side[i] = sgn(dot3(n, f[i]) - d);
      any_out = any_out || side[i] > 0;
      any_in = any_in || side[i] < 0;
    }
    if (!any_out) { out.push_back(f); continue; }
    if (!any_in) continue;
    Polygon3 g;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const std::size_t j = (i + 1) % f.size();
      if (side[i] <= 0) g.push_back(f[i]);
      if (side[i] * side[j] < 0) {
        const PointQ3 e = sub(f[j], f[i]);
        const Rational t = (d - dot3(n, f[i])) / dot3(n, e);
        g.push_back({f[i].x + t * e.x, f[i].y + t * e.y, f[i].z + t * e.z});
      }
    }
    if (g.size() >= 3) out.push_back(std::move(g));
  }
  // Directed edges without their reverse lie on the plane: reversed, they chain into the cap.
  std::map<std::pair<PointQ3, PointQ3>, int, bool (*)(const std::pair<PointQ3, PointQ3>&,
                                                      const std::pair<PointQ3, PointQ3>&)>
      edges([](const std::pair<PointQ3, PointQ3>& a, const std::pair<PointQ3, PointQ3>& b) {
        PointLess less;
        if (less(a.first, b.first)) return true;
        if (less(b.first, a.first)) return false;
        return less(a.second, b.second);
      });
  for (const Polygon3& f : out)
    for (std::size_t i = 0; i < f.size(); ++i) edges[{f[i], f[(i + 1) % f.size()]}] = 1;
  std::map<PointQ3, PointQ3, PointLess> next;
  for (const auto& entry : edges)
    if (!edges.count({entry.first.second, entry.first.first})) next[entry.first.second] = entry.first.first;
  if (!next.empty()) {
    Polygon3 cap{next.begin()->first};
    for (PointQ3 p = next.begin()->second; p != cap.front() && cap.size() <= next.size(); p = next.at(p))
      cap.push_back(p);
    if (cap.size() >= 3) out.push_back(std::move(cap));
  }
  return out;
}

bool collinear(const PointQ3& a, const PointQ3& b, const PointQ3& c) { return is_zero(triangle_normal(a, b, c)); }

TriangleSurface surface_of_faces(const std::vector<Polygon3>& faces) {
  TriangleSurface s;
  std::map<PointQ3, int, PointLess> ids;
  auto id = [&](const PointQ3& p) {
    auto [it, fresh] = ids.emplace(p, static_cast<int>(s.vertices.size()));
    if (fresh) s.vertices.push_back(p);
    return it->second;
  };
  for (const Polygon3& f : faces) {
    const std::size_t k = f.size();
    bool strict = true;
    for (std::size_t i = 0; i < k && strict; ++i) strict = !collinear(f[i], f[(i + 1) % k], f[(i + 2) % k]);
    if (strict) {
      for (std::size_t i = 1; i + 1 < k; ++i) s.triangles.push_back({id(f[0]), id(f[i]), id(f[i + 1])});
      continue;
    }
    PointQ3 c{Rational(0), Rational(0), Rational(0)};
    for (const PointQ3& p : f) c = {c.x + p.x, c.y + p.y, c.z + p.z};
    const Rational inv = Rational(1) / Rational(static_cast<long>(k));
    const int centre = id(PointQ3{c.x * inv, c.y * inv, c.z * inv});
    for (std::size_t i = 0; i < k; ++i) s.triangles.push_back({centre, id(f[i]), id(f[(i + 1) % k])});
  }
  return s;
}

std::vector<Polygon3> box_faces(const Box3& b) {
  const TriangleSurface t = box_surface(b.min, b.max);
  std::vector<Polygon3> faces;
  for (std::size_t i = 0; i < t.triangles.size(); i += 2) {  // each pair (a,b,c),(a,c,d) is the quad a,b,c,d
    const auto& p = t.triangles[i];
    const auto& q = t.triangles[i + 1];
    faces.push_back({t.vertices[p[0]], t.vertices[p[1]], t.vertices[p[2]], t.vertices[q[2]]});
  }
  return faces;
}

/// The domain box clipped by n planes, plane k through ring points k and k+1 and `third(k)`, each keeping the side
/// of `inside`; refused (naming `what`) when nothing of the box is left.
TriangleSurface clipped_box(const Box3& domain, const std::vector<PointQ3>& ring,
                            const std::function<PointQ3(std::size_t)>& third, const PointQ3& inside,
                            const std::string& what) {
  const std::size_t n = ring.size();
  std::vector<Polygon3> faces = box_faces(domain);
  for (std::size_t k = 0; k < n; ++k) {
    const PointQ3& q0 = ring[k];
    PointQ3 normal = triangle_normal(q0, ring[(k + 1) % n], third(k));
    if (sgn(dot3(normal, sub(inside, q0))) > 0) normal = {-normal.x, -normal.y, -normal.z};
    faces = clip(faces, normal, dot3(normal, q0));
    if (faces.empty()) break;
  }
  Rational six_volume = 0;
  TriangleSurface s = surface_of_faces(faces);
  for (const auto& t : s.triangles)
    six_volume += dot3(s.vertices[t[0]], triangle_normal(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]));
  if (s.triangles.size() < 4 || sgn(six_volume) <= 0)
    throw InputError("the infinite " + what + " does not cross the domain box (nothing of it lies inside)");
  check_triangles(s.triangles.size());
  return s;
}

TriangleSurface infinite_cylinder_surface(const Primitive3& p, const Box3& domain) {
  const PointQ3 a = sub(p.point2, p.point1);
  const int n = circle_segments(p.tessellation, p.radius);
  TriangleSurface ring;
  add_ring(ring, real(p.point1), Real(p.radius), frame_of(a, p.tessellation.frame), n);
  const auto beside = [&](std::size_t k) {
    const PointQ3& q = ring.vertices[k];
    return PointQ3{q.x + a.x, q.y + a.y, q.z + a.z};
  };
  return clipped_box(domain, ring.vertices, beside, p.point1, "cylinder");
}

/// One nappe from the apex through the base ring, unbounded: the box clipped by the planes through the apex
/// (exact) and consecutive ring points.
TriangleSurface infinite_cone_surface(const Primitive3& p, const Box3& domain) {
  const PointQ3 a = sub(p.point2, p.point1);
  const int n = circle_segments(p.tessellation, p.radius);
  TriangleSurface ring;
  add_ring(ring, real(p.point2), Real(p.radius), frame_of(a, p.tessellation.frame), n);
  return clipped_box(domain, ring.vertices, [&](std::size_t) { return p.point1; }, p.point2, "cone");
}

TriangleSurface cylinder_surface(const Primitive3& p, const Box3& domain) {
  check_positive(p.radius, "radius");
  const PointQ3 a = sub(p.point2, p.point1);
  if (is_zero(a)) throw InputError("the axis has zero length (axis_point1 == axis_point2)");
  if (p.infinite) return infinite_cylinder_surface(p, domain);
  const int n = circle_segments(p.tessellation, p.radius);
  check_triangles(std::size_t(4) * n);
  const Frame f = frame_of(a, p.tessellation.frame);
  const Real r(p.radius);
  TriangleSurface s;
  add_ring(s, real(p.point1), r, f, n);
  add_ring(s, real(p.point2), r, f, n);
  s.vertices.push_back(on_grid(real(p.point1)));
  s.vertices.push_back(on_grid(real(p.point2)));
  add_bottom_fan(s, 2 * n, 0, n);
  add_band(s, 0, n, n);
  add_top_fan(s, 2 * n + 1, n, n);
  return s;
}

}  // namespace

int circle_segments(const Tessellation3& t, const Rational& radius, bool minor) {
  long n = 0;
  if (t.mode == Tessellation3::Mode::Segments) {
    n = minor && t.minor_segments != 0 ? t.minor_segments : t.segments;
  } else {
    if (sgn(t.edge_length) <= 0)
      throw InputError("tessellation.edge_length must be positive, got " + exact_string(t.edge_length));
    const double segments = std::ceil(2 * M_PI * radius.get_d() / t.edge_length.get_d());
    n = !(segments <= kMaxSegments) ? kMaxSegments + 1L : std::max(3L, static_cast<long>(segments));
  }
  if (n < 3 || n > kMaxSegments)
    throw InputError("tessellation: " + std::to_string(n) + " segments per circle" +
                     (t.mode == Tessellation3::Mode::EdgeLength ? " (from edge_length " + exact_string(t.edge_length) +
                                                                      " and radius " + exact_string(radius) + ")"
                                                                : std::string()) +
                     " is outside the bounds [3, " + std::to_string(kMaxSegments) + "]");
  return static_cast<int>(n);
}

int sphere_bands(const Tessellation3& t, int n) {
  const int m = t.bands != 0 ? t.bands : (n + 1) / 2;
  if (m < 2 || m > kMaxSegments)
    throw InputError("tessellation: " + std::to_string(m) + " latitude bands is outside the bounds [2, " +
                     std::to_string(kMaxSegments) + "]");
  return m;
}

int largest_circle_segments(const Halfspace3& h) {
  const Primitive3& p = h.primitive;
  switch (h.kind) {
    case HalfspaceKind3::Sphere:
    case HalfspaceKind3::Cylinder:
    case HalfspaceKind3::Cone: return circle_segments(p.tessellation, p.radius);
    case HalfspaceKind3::Torus:
      return std::max(circle_segments(p.tessellation, p.major_radius),
                      circle_segments(p.tessellation, p.minor_radius, true));
    default: return 0;
  }
}

namespace {
/// max(15, round(fraction pi / asin(h / 2 radius))), 15 when h >= 2 radius; above kMaxSegments: kMaxSegments + 1.
int bsh_count(double h, double radius, double fraction) {
  if (!(radius > 0) || !(h < 2 * radius)) return 15;
  const double n = std::round(fraction * M_PI / std::asin(h / (2 * radius)));
  return n > kMaxSegments ? kMaxSegments + 1 : std::max(15, static_cast<int>(n));
}
}  // namespace

int bsh_segments(double h, double radius) { return bsh_count(h, radius, 1); }

int bsh_sphere_bands(double h, double radius) {
  const int quarter = bsh_count(h, radius, 0.25);
  return quarter > kMaxSegments / 2 ? kMaxSegments + 1 : 2 * quarter;
}

std::vector<std::vector<PointQ3>> box_cut_by_plane(const Box3& box, const PointQ3& normal, const Rational& offset) {
  if (is_zero(normal)) throw std::invalid_argument("box_cut_by_plane: the normal is zero");
  bool interior = false;  // some corner strictly on the kept side: the kept part has volume
  for (int i = 0; i < 8 && !interior; ++i) {
    const PointQ3 c{(i & 1 ? box.max : box.min).x, (i & 2 ? box.max : box.min).y, (i & 4 ? box.max : box.min).z};
    interior = sgn(dot3(normal, c) - offset) < 0;
  }
  if (!interior) return {};
  return clip(box_faces(box), normal, offset);
}

TriangleSurface tessellate(const Halfspace3& h, const Box3& domain) {
  const Primitive3& p = h.primitive;
  switch (h.kind) {
    case HalfspaceKind3::Box: return box_surface(p.min, p.max);
    case HalfspaceKind3::Sphere: return sphere_surface(p);
    case HalfspaceKind3::Cylinder: return cylinder_surface(p, domain);
    case HalfspaceKind3::Cone: return cone_surface(p, domain);
    case HalfspaceKind3::Torus: return torus_surface(p);
    case HalfspaceKind3::Plane:
    case HalfspaceKind3::Mesh: break;
  }
  throw std::invalid_argument("tessellate: a plane or a mesh has no tessellation");
}

std::string tessellation_summary(const Halfspace3& h) {
  std::string out = to_string(h.kind);
  const Tessellation3& t = h.primitive.tessellation;
  switch (h.kind) {
    case HalfspaceKind3::Sphere: {
      const int n = circle_segments(t, h.primitive.radius);
      out += ", " + std::to_string(n) + " x " + std::to_string(sphere_bands(t, n)) + " segments";
      break;
    }
    case HalfspaceKind3::Torus:
      out += ", " + std::to_string(circle_segments(t, h.primitive.major_radius)) + " x " +
             std::to_string(circle_segments(t, h.primitive.minor_radius, true)) + " segments";
      break;
    case HalfspaceKind3::Cylinder:
      out += std::string(h.primitive.infinite ? " (infinite, clipped by the domain)" : "") + ", " +
             std::to_string(circle_segments(t, h.primitive.radius)) + " segments";
      break;
    case HalfspaceKind3::Cone:
      out += std::string(h.primitive.infinite ? " (infinite, clipped by the domain)" : "") + ", " +
             std::to_string(circle_segments(t, h.primitive.radius)) + " segments";
      break;
    default: break;
  }
  return out + ", " + std::to_string(h.surface.triangles.size()) + " triangles";
}

}  // namespace hsx
