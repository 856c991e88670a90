// Deterministic tessellation of 3D primitives into closed, outward-oriented triangle surfaces with exact rational
// vertices (the Halfspace3 surfaces of box, sphere, cylinder, cone and torus).
//
// Conventions (owned here; docs/scene-format.md repeats them for users, so that others can rebuild the same
// triangles):
// - Frame of an axis a (non-zero): w = a / |a|; e = the coordinate axis of the smallest |a_i| (lowest i on a tie);
//   u = (w x e) / |w x e|; v = w x u. (For a = +z: u = +y, v = -x.) A sphere uses a = +z.
//   Tessellation3::Frame::Bsh (the BSH authors' convention, io/bsh_config.hpp): e = +x, or +y when a is parallel
//   to x; a sphere uses the coordinate frame u = +x, v = +y, w = +z.
// - Angles: theta_k = 2 pi k / n, k = 0..n-1, for a circle of n segments.
// - Vertices of curved primitives: each coordinate of the real point given below is rounded to the nearest
//   multiple of 2^-32 (kTessellationGrid; ties to even). hsx evaluates the real point in 128-bit MPFR arithmetic,
//   which decides the rounding unless the value lies within about 2^-100 of a midpoint. Vertices therefore lie
//   within 2^-33 of the curved surface in each coordinate, not on it; box corners are exact.
//     ring point  P(c, rho, k) = c + rho (cos theta_k u + sin theta_k v)
//     sphere:  m latitude bands (Tessellation3::bands, default ceil(n / 2)); south pole c - r w, rings j = 1..m-1 at phi_j = -pi/2 + pi j / m:
//              c + r cos phi_j (cos theta_k u + sin theta_k v) + r sin phi_j w, north pole c + r w.
//     cylinder (finite): rings P(point1, r, k) and P(point2, r, k), axis a = point2 - point1, cap centres point1 and
//              point2 (rounded the same way).
//     cone:    apex = point1 (rounded), base ring P(point2, r, k), base centre point2 (rounded), a = point2 - point1.
//     torus:   n segments about the axis, m = minor segments around the tube: vertex (k, j) =
//              c + (R + r cos phi_j)(cos theta_k u + sin theta_k v) + r sin phi_j w, phi_j = 2 pi j / m.
// - Triangles (vertex order = outward orientation), for k = 0..n-1 with k+1 taken mod n:
//     band between a lower ring L and an upper ring U (lower = smaller coordinate along w):
//              (L_k, L_k+1, U_k) and (L_k+1, U_k+1, U_k)
//     fan at a bottom point S (south pole, bottom cap centre, cone apex) with ring L: (S, L_k+1, L_k)
//     fan at a top point N (north pole, top cap centre, cone base centre) with ring U: (N, U_k, U_k+1)
//   Order: sphere: south fan, bands j = 1..m-2 (k inner), north fan; cylinder: bottom cap fan, band, top cap fan;
//   cone: apex fan, base fan; torus: bands (ring j, ring j+1 mod m) for j = 0..m-1, k inner. Vertex order: sphere
//   south pole, rings (j outer, k inner), north pole; cylinder bottom ring, top ring, bottom centre, top centre; cone
//   apex, ring, base centre; torus (j outer, k inner).
//   box: corners i = 0..7 with x = (i & 1 ? max : min).x, y = (i & 2 ...), z = (i & 4 ...); triangles (0,2,3),
//   (0,3,1) [z = min], (4,5,7), (4,7,6) [z = max], (0,1,5), (0,5,4) [y = min], (2,6,7), (2,7,3) [y = max],
//   (0,4,6), (0,6,2) [x = min], (1,3,7), (1,7,5) [x = max].
// - Infinite cylinder: the lateral planes of the finite tessellation's prism (through P(point1, r, k) and
//   P(point1, r, k+1), parallel to a) clip the domain box exactly (a convex polyhedron, computed exactly); each
//   face of the result is a convex polygon fanned from its first vertex, or from its vertex centroid when three
//   consecutive vertices are collinear. Its faces on the domain box carry no patch (they are on the box).
// - Infinite cone (Primitive3::infinite, one nappe): the same with the planes through the apex (exact) and ring
//   points P(base_center, r, k) and P(base_center, r, k+1), each keeping the base centre's side.
// - Segment counts: Segments mode gives n directly (torus tube: minor_segments, or n when 0). EdgeLength L gives
//   each circle of radius rho n = max(3, ceil(2 pi rho / L)) (computed in double precision; torus: rho =
//   major_radius about the axis, minor_radius around the tube). Bounds: 3 <= n <=
//   kMaxSegments for every circle, and at most kMaxTessellationTriangles triangles per primitive; outside them the
//   input is refused (InputError).
// - The BSH authors' rule (io/bsh_config.hpp): n = max(15, round(pi / asin(h / 2 rho))) segments per circle in
//   double precision (n = 15 when h >= 2 rho), h = the diagonal of one cell of their grid; a sphere of radius r
//   has m = 2 q latitude bands (m - 1 rings), q = max(15, round(pi / (4 asin(h / 2 r)))) (q = 15 when h >= 2 r);
//   every frame in their style (Frame::Bsh).
#pragma once

#include <hsx/geometry/scene3.hpp>

#include <cstddef>
#include <vector>

namespace hsx {

inline constexpr int kTessellationGridBits = 32;          ///< vertices are multiples of 2^-32
inline constexpr int kMaxSegments = 4096;                 ///< per circle
inline constexpr std::size_t kMaxTessellationTriangles = 2'000'000;  ///< per primitive

/// Segments of a circle of radius `radius` under `t` (`minor`: the torus tube's circles). Throws InputError
/// ("tessellation: ...") outside the bounds above.
int circle_segments(const Tessellation3& t, const Rational& radius, bool minor = false);

/// The largest segment count of any circle of primitive `h` (sphere, cylinder, cone, torus; 0 for box, plane,
/// mesh), without tessellating it. Throws InputError like circle_segments.
int largest_circle_segments(const Halfspace3& h);

/// The latitude bands of a sphere of `t` with `n` segments per circle: t.bands, or ceil(n / 2) when 0. Throws
/// InputError ("tessellation: ...") outside [2, kMaxSegments].
int sphere_bands(const Tessellation3& t, int n);

/// The BSH authors' segment count for a circle of radius `radius` and their h (see above); kMaxSegments + 1 when
/// the count exceeds kMaxSegments (refused by the tessellation).
int bsh_segments(double h, double radius);

/// The BSH authors' latitude bands of a sphere of radius `radius` at their h (see above; kMaxSegments + 1 when
/// beyond kMaxSegments).
int bsh_sphere_bands(double h, double radius);

/// The surface of halfspace `h` (kind box, sphere, cylinder, cone or torus) from `h.primitive`; `domain` clips an
/// infinite cylinder and is otherwise unused. Throws InputError ("radius must be positive", "the axis has zero
/// length", "minor_radius must be below major_radius", tessellation bounds, an infinite cylinder that misses the
/// domain) without naming the halfspace (the caller prefixes it).
TriangleSurface tessellate(const Halfspace3& h, const Box3& domain);

/// The convex polyhedron box ∩ { x : normal . x <= offset }, computed exactly: its faces, each a convex polygon
/// with its vertices counter-clockwise seen from outside (the parts of the box's six faces on the kept side, in the
/// box_surface face order z = min, z = max, y = min, y = max, x = min, x = max, then the cap on the plane when the
/// plane crosses the box). Every box face is kept whole when the box lies on the kept side (no cap); empty when
/// the kept part has no interior (the box lies on the other side, or touches the plane only). `normal` must be
/// non-zero (std::invalid_argument otherwise). For OpenSCAD output of planes (io/openscad.hpp).
std::vector<std::vector<PointQ3>> box_cut_by_plane(const Box3& box, const PointQ3& normal, const Rational& offset);

/// Describes the tessellation for messages and Halfspace3::origin: "sphere, 32 x 16 segments, 960 triangles".
std::string tessellation_summary(const Halfspace3& h);

}  // namespace hsx
