// A solid's boundary edges and exact corner angles: see planar_corners.hpp.
#include "geometry/planar_corners.hpp"

#include "geometry/planar_points.hpp"
#include <hsx/kernel/measure.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

namespace hsx {

const char* corner_angle_name(CornerAngle angle) {
  switch (angle) {
    case CornerAngle::Convex: return "convex";
    case CornerAngle::Smooth: return "smooth";
    case CornerAngle::Concave: return "concave";
  }
  return "?";
}

namespace {

/// A boundary curve leaving a vertex: an outgoing boundary edge, or an incoming one walked backwards.
struct Ray {
  int edge = -1;
  bool outgoing = false;
  OneRoot dx, dy;       ///< tangent direction leaving the vertex (not normalised)
  Rational curvature;   ///< signed curvature along the ray's travel (left turn positive)
  bool upper = false;   ///< direction angle in [0, pi): the first half of a counter-clockwise sweep from +x
};

OneRoot minus(const OneRoot& a, const Rational& c) { return OneRoot(a.a0 - c, a.a1, a.root); }
OneRoot negated(const OneRoot& a) { return OneRoot(-a.a0, -a.a1, a.root); }

/// Exact sign of an algebraic Measure (products of one-root numbers never carry special terms).
int exact_sign(const Measure& m) {
  const std::optional<int> s = m.sign();
  if (!s) throw std::logic_error("planar_corners: undecided sign of an algebraic number");
  return *s;
}

int cross_sign(const Ray& a, const Ray& b) {
  return exact_sign(Measure::product(a.dx, b.dy) - Measure::product(a.dy, b.dx));
}

int dot_sign(const Ray& a, const Ray& b) {
  return exact_sign(Measure::product(a.dx, b.dx) + Measure::product(a.dy, b.dy));
}

/// The tangent and curvature of edge `e` leaving its end vertex `v`.
Ray make_ray(const Arrangement2& arr, int edge, int v, bool outgoing) {
  const ArrEdge2& e = arr.edges()[static_cast<std::size_t>(edge)];
  const OneRootPoint& p = arr.vertices().at(static_cast<std::size_t>(v)).point;
  const bool from_source = e.source == v;
  Ray ray;
  ray.edge = edge;
  ray.outgoing = outgoing;
  if (e.shape == EdgeShape2::Segment) {
    const OneRootPoint& other = arr.vertices().at(static_cast<std::size_t>(from_source ? e.target : e.source)).point;
    if (e.line_a != 0 || e.line_b != 0) {
      // Along the line, other - p = lambda * (b, -a); the sign of lambda orients the direction.
      int lambda = e.line_b != 0 ? sgn(e.line_b) * compare(other.x, p.x) : -sgn(e.line_a) * compare(other.y, p.y);
      if (lambda == 0) throw std::logic_error("planar_corners: a segment edge of zero length");
      ray.dx = OneRoot(lambda > 0 ? Rational(e.line_b) : Rational(-e.line_b));
      ray.dy = OneRoot(lambda > 0 ? Rational(-e.line_a) : Rational(e.line_a));
    } else if (p.is_rational() && other.is_rational()) {
      ray.dx = OneRoot(Rational(other.x.a0 - p.x.a0));
      ray.dy = OneRoot(Rational(other.y.a0 - p.y.a0));
    } else {
      throw std::runtime_error("planar_corners: segment edge " + std::to_string(edge) +
                               " has irrational ends and no known supporting line");
    }
    ray.curvature = 0;
  } else {
    const OneRoot ux = minus(p.x, e.center.x), uy = minus(p.y, e.center.y);
    const bool travel_ccw = from_source == e.ccw;
    // The counter-clockwise tangent of a circle at p is (vertex - center) turned by +90 degrees.
    ray.dx = travel_ccw ? negated(uy) : uy;
    ray.dy = travel_ccw ? ux : negated(ux);
    ray.curvature = travel_ccw ? Rational(1 / e.radius) : Rational(-1 / e.radius);
  }
  const int sy = ray.dy.sign();
  ray.upper = sy > 0 || (sy == 0 && ray.dx.sign() > 0);
  return ray;
}

/// Counter-clockwise order from the +x direction; equal tangents: the curve turning less to the left first
/// (it lies clockwise of the other near the vertex).
bool ccw_before(const Ray& a, const Ray& b) {
  if (a.upper != b.upper) return a.upper;
  const int c = cross_sign(a, b);
  if (c != 0) return c > 0;
  return a.curvature < b.curvature;
}

bool same_tangent_and_curvature(const Ray& a, const Ray& b) {
  return a.upper == b.upper && cross_sign(a, b) == 0 && a.curvature == b.curvature;
}

/// The interior angle of the solid sector from o counter-clockwise to r.
std::pair<CornerAngle, bool> corner_angle(const Ray& o, const Ray& r) {
  const int c = cross_sign(o, r);
  if (c > 0) return {CornerAngle::Convex, false};
  if (c < 0) return {CornerAngle::Concave, false};
  if (dot_sign(o, r) < 0) return {CornerAngle::Smooth, false};
  // Same tangent: r right after o counter-clockwise means a horn of angle 0 (r turns more to the left);
  // otherwise the sector wraps all the way round, 360 degrees.
  return {r.curvature > o.curvature ? CornerAngle::Convex : CornerAngle::Concave, true};
}

}  // namespace

SolidBoundary2 solid_boundary2(const Arrangement2& arr, const std::vector<char>& solid) {
  const auto& faces = arr.faces();
  const auto& edges = arr.edges();
  if (solid.size() != faces.size())
    throw std::invalid_argument("solid_boundary2: " + std::to_string(solid.size()) + " solid flags for " +
                                std::to_string(faces.size()) + " faces");
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (solid[f] && faces[f].outer)
      throw std::invalid_argument("solid_boundary2: outer face " + std::to_string(f) +
                                  " is marked solid (outer faces touch the domain box and are never solid)");
  auto in_solid = [&](int f) { return f >= 0 && solid[static_cast<std::size_t>(f)] != 0; };

  SolidBoundary2 out;
  std::map<int, std::vector<Ray>> rays;  // by vertex, ascending: deterministic corner order
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    const ArrEdge2& edge = edges[static_cast<std::size_t>(e)];
    const bool left = in_solid(edge.left_face), right = in_solid(edge.right_face);
    if (left == right) continue;
    if (edge.on_box) throw std::logic_error("solid_boundary2: box edge " + std::to_string(e) + " bounds the solid");
    out.edges.push_back({e, left});
    const int from = left ? edge.source : edge.target;
    const int to = left ? edge.target : edge.source;
    rays[from].push_back(make_ray(arr, e, from, true));
    rays[to].push_back(make_ray(arr, e, to, false));
  }

  for (auto& [v, list] : rays) {
    std::sort(list.begin(), list.end(), ccw_before);
    const std::size_t n = list.size();
    const auto outgoing = std::count_if(list.begin(), list.end(), [](const Ray& r) { return r.outgoing; });
    if (2 * static_cast<std::size_t>(outgoing) != n)
      throw std::logic_error("solid_boundary2: vertex " + std::to_string(v) + " has unequal in and out edges");
    for (std::size_t i = 0; i < n; ++i) {
      const Ray& a = list[i];
      const Ray& b = list[(i + 1) % n];
      if (n > 1 && same_tangent_and_curvature(a, b))
        throw std::logic_error("solid_boundary2: edges " + std::to_string(a.edge) + " and " + std::to_string(b.edge) +
                               " leave vertex " + std::to_string(v) + " along the same curve");
      if (!a.outgoing) continue;
      // The solid lies counter-clockwise of o (on its left); the next boundary curve closes the sector.
      if (b.outgoing)
        throw std::logic_error("solid_boundary2: two outgoing boundary edges in a row at vertex " + std::to_string(v));
      SolidCorner2 corner;
      corner.vertex = v;
      corner.in_edge = b.edge;
      corner.out_edge = a.edge;
      std::tie(corner.angle, corner.cusp) = corner_angle(a, b);
      out.corners.push_back(corner);
    }
  }
  std::sort(out.corners.begin(), out.corners.end(), [](const SolidCorner2& a, const SolidCorner2& b) {
    return std::tie(a.vertex, a.out_edge) < std::tie(b.vertex, b.out_edge);
  });
  return out;
}

PointQ2 edge_split_point(const Arrangement2& arrangement, int edge) {
  return rational_point_inside_edge(arrangement.edges().at(static_cast<std::size_t>(edge)), arrangement.vertices());
}

}  // namespace hsx
