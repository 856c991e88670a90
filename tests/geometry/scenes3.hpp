// Hand-built 3D scenes for the arrangement and complex tests, and a direct (arrangement-free) classification of
// points by the halfspaces, to test the arrangement against.
#pragma once

#include <hsx/geometry/scene3.hpp>

#include <random>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace hsx::test3 {

inline PointQ3 pt(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }
inline PointQ3 sub(const PointQ3& a, const PointQ3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline PointQ3 add(const PointQ3& a, const PointQ3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Rational dot(const PointQ3& a, const PointQ3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline PointQ3 cross(const PointQ3& a, const PointQ3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// A sample of `halfspace` given exactly at `p` (Sample3::given), as a scene file's "at".
inline Sample3 at_sample(int halfspace, const PointQ3& p) {
  Sample3 s;
  s.halfspace = halfspace;
  s.given = p;
  return s;
}
inline Halfspace3 plane(const std::string& name, PointQ3 normal, Rational offset, bool complement = false) {
  Halfspace3 h;
  h.name = name;
  h.kind = HalfspaceKind3::Plane;
  h.normal = std::move(normal);
  h.offset = std::move(offset);
  h.complement = complement;
  return h;
}

inline Halfspace3 surface(const std::string& name, TriangleSurface s, bool complement = false) {
  Halfspace3 h;
  h.name = name;
  h.kind = HalfspaceKind3::Mesh;
  h.surface = std::move(s);
  h.complement = complement;
  return h;
}

/// An axis-aligned box as 12 outward triangles.
inline TriangleSurface box_surface(const PointQ3& lo, const PointQ3& hi) {
  TriangleSurface s;
  for (int i = 0; i < 8; ++i) s.vertices.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  // faces as quads (outward, counter-clockwise), split along one diagonal
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.triangles.push_back({q[0], q[1], q[2]});
    s.triangles.push_back({q[0], q[2], q[3]});
  }
  return s;
}

/// The octahedron |x - c|_1 <= r.
inline TriangleSurface octahedron(const PointQ3& c, const Rational& r) {
  TriangleSurface s;
  s.vertices = {add(c, pt(r, 0, 0)), add(c, pt(-r, 0, 0)), add(c, pt(0, r, 0)),
                add(c, pt(0, -r, 0)), add(c, pt(0, 0, r)), add(c, pt(0, 0, -r))};
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        std::array<int, 3> t = {sx, 2 + sy, 4 + sz};
        // outward iff the orientation matches the octant's sign parity
        const PointQ3 n = cross(sub(s.vertices[t[1]], s.vertices[t[0]]), sub(s.vertices[t[2]], s.vertices[t[0]]));
        const PointQ3 out = sub(add(add(s.vertices[t[0]], s.vertices[t[1]]), s.vertices[t[2]]), add(add(c, c), c));
        if (dot(n, out) < 0) std::swap(t[1], t[2]);
        s.triangles.push_back(t);
      }
  return s;
}

/// The tetrahedron with the given corners (any orientation; made outward).
inline TriangleSurface tetrahedron(const PointQ3& a, const PointQ3& b, const PointQ3& c, const PointQ3& d) {
  TriangleSurface s;
  s.vertices = {a, b, c, d};
  const Rational vol = dot(sub(b, a), cross(sub(c, a), sub(d, a)));
  if (vol > 0) s.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  else s.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return s;
}

/// Exact side of p for a plane or a closed surface (ray parity, retried on degenerate rays): +1 inside, 0 on the
/// boundary, -1 outside (complement applied).
inline int direct_side(const Halfspace3& h, const PointQ3& p) {
  if (h.kind == HalfspaceKind3::Plane) {
    const Rational s = dot(h.normal, p) - h.offset;
    if (s == 0) return 0;
    return ((s < 0) != h.complement) ? 1 : -1;
  }
  const auto& S = h.surface;
  for (int attempt = 0; attempt < 50; ++attempt) {
    const PointQ3 dir = {1, Rational(attempt * 7 + 1, 13 + attempt), Rational(attempt * 3 + 2, 17 + 5 * attempt)};
    int crossings = 0;
    bool degenerate = false;
    for (const auto& t : S.triangles) {
      const PointQ3 &a = S.vertices[t[0]], &b = S.vertices[t[1]], &c = S.vertices[t[2]];
      const PointQ3 n = cross(sub(b, a), sub(c, a));
      const Rational off = dot(n, sub(a, p)), nd = dot(n, dir);
      if (off == 0) {
        // p on the triangle's plane: on the boundary iff inside the triangle (barycentric signs)
        const PointQ3 ab = cross(sub(b, a), sub(p, a)), bc = cross(sub(c, b), sub(p, b)), ca = cross(sub(a, c), sub(p, c));
        if (dot(ab, n) >= 0 && dot(bc, n) >= 0 && dot(ca, n) >= 0) return 0;
        if (nd == 0) { degenerate = true; break; }
        continue;
      }
      if (nd == 0) continue;
      const Rational s = off / nd;
      if (s <= 0) continue;
      const PointQ3 q = add(p, {dir.x * s, dir.y * s, dir.z * s});
      const Rational u = dot(cross(sub(b, a), sub(q, a)), n), v = dot(cross(sub(c, b), sub(q, b)), n),
                     w = dot(cross(sub(a, c), sub(q, c)), n);
      if (u < 0 || v < 0 || w < 0) continue;
      if (u == 0 || v == 0 || w == 0) { degenerate = true; break; }
      ++crossings;
    }
    if (degenerate) continue;
    const bool in = (crossings % 2 == 1) != h.complement;
    return in ? 1 : -1;
  }
  throw std::logic_error("direct_side: no clean ray");
}

/// n planes with small integer normals through small offsets in general position (no two parallel, every three
/// meeting in one point, no four through a point), with a domain containing every triple point with margin.
/// `seed` drives a std::mt19937 (rapidcheck's own generators are scaled down at small sizes, which would make the
/// rejection loop below crawl).
inline Scene3 random_planes(int n, int seed_bits, unsigned seed) {
  std::mt19937 engine(seed);
  auto draw = [&engine](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi - 1)(engine); };
  Scene3 scene;
  auto det = [](const PointQ3& a, const PointQ3& b, const PointQ3& c) { return dot(a, cross(b, c)); };
  std::vector<PointQ3> triples;
  int tries = 0;
  while (static_cast<int>(scene.halfspaces.size()) < n) {
    if (++tries > 100000) throw std::logic_error("random_planes: no general position found");
    const PointQ3 normal = {draw(-9, 10), draw(-9, 10), draw(-9, 10)};
    if (normal == PointQ3{0, 0, 0}) continue;
    const Rational offset(draw(-(1 << seed_bits), 1 << seed_bits), 1);
    bool ok = true;
    std::vector<PointQ3> fresh;
    const auto& hs = scene.halfspaces;
    for (std::size_t i = 0; i < hs.size() && ok; ++i) {
      if (cross(normal, hs[i].normal) == PointQ3{0, 0, 0}) ok = false;
      for (std::size_t j = i + 1; j < hs.size() && ok; ++j) {
        const Rational d = det(normal, hs[i].normal, hs[j].normal);
        if (d == 0) { ok = false; break; }
        // Cramer's rule for the point on the new plane and planes i, j
        const PointQ3 ox = {offset, hs[i].offset, hs[j].offset};
        const PointQ3 nx = {normal.x, hs[i].normal.x, hs[j].normal.x};
        const PointQ3 ny = {normal.y, hs[i].normal.y, hs[j].normal.y};
        const PointQ3 nz = {normal.z, hs[i].normal.z, hs[j].normal.z};
        const PointQ3 x = {det(ox, ny, nz) / d, det(nx, ox, nz) / d, det(nx, ny, ox) / d};
        for (std::size_t k = 0; k < hs.size(); ++k)
          if (k != i && k != j && dot(hs[k].normal, x) == hs[k].offset) ok = false;  // a fourth plane through it
        fresh.push_back(x);
      }
    }
    if (!ok) continue;
    scene.halfspaces.push_back(plane("P" + std::to_string(scene.halfspaces.size()), normal, offset,
                                     draw(0, 2) == 1));
    triples.insert(triples.end(), fresh.begin(), fresh.end());
  }
  PointQ3 lo{-1, -1, -1}, hi{1, 1, 1};
  for (const auto& x : triples) {
    lo = {std::min(lo.x, x.x), std::min(lo.y, x.y), std::min(lo.z, x.z)};
    hi = {std::max(hi.x, x.x), std::max(hi.y, x.y), std::max(hi.z, x.z)};
  }
  // integer box with margin 1
  auto floor_q = [](const Rational& q) { Integer f; mpz_fdiv_q(f.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t()); return Rational(f); };
  scene.domain = {{floor_q(lo.x) - 1, floor_q(lo.y) - 1, floor_q(lo.z) - 1},
                  {floor_q(hi.x) + 2, floor_q(hi.y) + 2, floor_q(hi.z) + 2}};
  scene.domain_given = true;
  return scene;
}

inline Scene3 scene_of(Box3 domain, std::vector<Halfspace3> halfspaces) {
  Scene3 s;
  s.domain = std::move(domain);
  s.domain_given = true;
  s.halfspaces = std::move(halfspaces);
  return s;
}

}  // namespace hsx::test3
