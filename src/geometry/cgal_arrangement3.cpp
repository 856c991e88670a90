// The only translation unit that instantiates CGAL for the 3D arrangement (constrained triangulations, box
// intersection, triangle intersections on Epeck; ~40 s and ~2 GB to compile: keep CGAL out of every other file).
// Everything it hands out is plain data (geometry/arrangement3.hpp).
//
// Phases of Arrangement3::build (each a function below):
//  1. input triangles: every surface's triangles, every plane clipped to the box (a convex polygon, fanned), the
//     box's twelve face triangles (outward);
//  2. groups: input triangles by exact supporting plane (both orientations share a plane);
//  3. candidate pairs by CGAL::box_self_intersection_d, exact Triangle_3 x Triangle_3 on Epeck between ORIGINAL
//     input triangles of different planes; pairs of one surface are checked for self-intersection instead;
//  4. one constrained triangulation per group (projected along its dominant axis, lifted back exactly), each
//     output triangle kept once with the input triangles covering it;
//  5. vertices merged by exact coordinates (hash), edges with their triangles sorted radially (exact);
//  6. cells: union-find over triangle sides across edges, floating shells joined to the region around them by an
//     exact ray; sides of every halfspace propagated across triangles (and checked); interior points by a short
//     exact segment from a boundary triangle; volumes by signed tetrahedra; samples on triangles.
#include <hsx/geometry/arrangement3.hpp>
#include "geometry/components.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Constrained_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <functional>
#include <stdexcept>
#include <thread>
#include <unordered_map>

namespace hsx {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using P3 = K::Point_3;
using P2 = K::Point_2;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_triangulation_2<K, Tds, CGAL::Exact_intersections_tag>;
using BoxD = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;

constexpr int kBox = -1;  // halfspace id of the domain box's own triangles

// ---------------------------------------------------------------- exact vector helpers on PointQ3
PointQ3 operator-(const PointQ3& a, const PointQ3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
PointQ3 operator+(const PointQ3& a, const PointQ3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
PointQ3 scaled(const PointQ3& a, const Rational& f) { return {a.x * f, a.y * f, a.z * f}; }
Rational dot(const PointQ3& a, const PointQ3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
PointQ3 cross(const PointQ3& a, const PointQ3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
const Rational& coord(const PointQ3& p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }
Rational& coord(PointQ3& p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }
int sign(const Rational& q) { return sgn(q); }
PointQ3 normal_of(const std::array<PointQ3, 3>& t) { return cross(t[1] - t[0], t[2] - t[0]); }
/// det(a, b, c) = a . (b x c)
Rational det3(const PointQ3& a, const PointQ3& b, const PointQ3& c) { return dot(a, cross(b, c)); }

std::size_t hash_integer(mpz_srcptr z) {
  std::size_t h = static_cast<std::size_t>(mpz_size(z)) * 1000003u ^ static_cast<std::size_t>(mpz_sgn(z) + 1);
  const std::size_t limbs = std::min<std::size_t>(mpz_size(z), 4);
  for (std::size_t i = 0; i < limbs; ++i) h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::size_t>(mpz_getlimbn(z, i));
  return h;
}
std::size_t hash_rational(const Rational& q) {
  return hash_integer(q.get_num_mpz_t()) * 31u ^ hash_integer(q.get_den_mpz_t());
}
struct PointHash {
  std::size_t operator()(const PointQ3& p) const {
    return (hash_rational(p.x) * 31u ^ hash_rational(p.y)) * 31u ^ hash_rational(p.z);
  }
};

PointQ3 to_q(const P3& p) {
  const auto& e = CGAL::exact(p);
  return {e.x(), e.y(), e.z()};
}
P3 to_k(const PointQ3& p) { return P3(K::FT(p.x), K::FT(p.y), K::FT(p.z)); }

/// A conservative double box around points.
template <typename Points>
BoxD box_of(const Points& points, int info) {
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::numeric_limits<double>::infinity();
    hi[a] = -lo[a];
  }
  for (const PointQ3& p : points)
    for (int a = 0; a < 3; ++a) {
      const auto iv = CGAL::to_interval(coord(p, a));
      lo[a] = std::min(lo[a], iv.first);
      hi[a] = std::max(hi[a], iv.second);
    }
  return BoxD(lo, hi, info);
}

/// The number of worker threads: `requested`, or the hardware's concurrency when 0.
int worker_count(int requested) {
  return requested > 0 ? requested : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// Runs work(i, worker) for i in [0, n) on `threads` threads (worker in [0, threads) names the thread, for
/// per-thread caches); rethrows the exception of the lowest failing i. Results written per i do not depend on the
/// thread count.
void parallel_for(int n, int threads, const std::function<void(int, int)>& work) {
  threads = std::max(1, std::min(threads, n));
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(std::max(n, 0)));
  std::atomic<int> next{0};
  auto run = [&](int worker) {
    for (int i = next++; i < n; i = next++) {
      try {
        work(i, worker);
      } catch (...) {
        errors[static_cast<std::size_t>(i)] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(run, t);
  run(0);
  for (auto& t : pool) t.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

std::string halfspace_label(const Scene3& scene, int h) {
  return "halfspaces[" + std::to_string(h) + "] (\"" + scene.halfspaces[static_cast<std::size_t>(h)].name + "\")";
}

// ---------------------------------------------------------------- 1. input triangles
struct InputTriangle {
  std::array<PointQ3, 3> p;
  int halfspace = kBox;    // kBox for the domain's faces
  int local = -1;          // triangle id within its surface (-1 for planes and the box)
  char front_inside = 0;   // 1: the halfspace's inside is on the front side (box: front is outside the domain)
  int group = -1;
};

/// The plane {normal . x = offset} clipped to the closed box as a convex polygon, counter-clockwise seen from the
/// side `normal` points to; empty when it meets the box in less than a polygon.
std::vector<PointQ3> clip_plane(const PointQ3& normal, const Rational& offset, const Box3& box) {
  std::array<PointQ3, 8> corner;
  for (int i = 0; i < 8; ++i)
    corner[i] = {(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z};
  std::vector<PointQ3> hits;
  auto add = [&hits](const PointQ3& p) {
    if (std::find(hits.begin(), hits.end(), p) == hits.end()) hits.push_back(p);
  };
  for (int i = 0; i < 8; ++i) {
    const Rational si = dot(normal, corner[i]) - offset;
    if (si == 0) add(corner[i]);
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (i & bit) continue;
      const int j = i | bit;
      const Rational sj = dot(normal, corner[j]) - offset;
      if (sign(si) * sign(sj) < 0) add(corner[i] + scaled(corner[j] - corner[i], si / (si - sj)));
    }
  }
  if (hits.size() < 3) return {};
  // Sort around the centroid in the plane: the hits are the vertices of a convex polygon.
  PointQ3 centre{0, 0, 0};
  for (const auto& p : hits) centre = centre + p;
  centre = scaled(centre, Rational(1, static_cast<long>(hits.size())));
  const PointQ3 ref = hits[0] - centre;
  auto half = [&](const PointQ3& p) {  // 0: angle from ref in [0, pi), 1: [pi, 2 pi)
    const int s = sign(det3(normal, ref, p - centre));
    return s > 0 || (s == 0 && dot(ref, p - centre) > 0) ? 0 : 1;
  };
  std::sort(hits.begin(), hits.end(), [&](const PointQ3& a, const PointQ3& b) {
    const int ha = half(a), hb = half(b);
    if (ha != hb) return ha < hb;
    return sign(det3(normal, a - centre, b - centre)) > 0;
  });
  if (sign(det3(normal, hits[1] - hits[0], hits[2] - hits[0])) == 0) return {};  // all on a line
  return hits;
}

std::vector<InputTriangle> input_triangles(const Scene3& scene) {
  std::vector<InputTriangle> out;
  const Box3& box = scene.domain;
  // The box: faces x = min, x = max, ... as two triangles each, front outward.
  for (int axis = 0; axis < 3; ++axis)
    for (int upper = 0; upper < 2; ++upper) {
      PointQ3 n{0, 0, 0};
      coord(n, axis) = upper ? 1 : -1;
      const std::vector<PointQ3> face = clip_plane(n, dot(n, upper ? box.max : box.min), box);
      for (std::size_t k = 1; k + 1 < face.size(); ++k) out.push_back({{face[0], face[k], face[k + 1]}, kBox, -1, 0});
    }
  for (int h = 0; h < static_cast<int>(scene.halfspaces.size()); ++h) {
    const Halfspace3& hs = scene.halfspaces[static_cast<std::size_t>(h)];
    if (hs.kind == HalfspaceKind3::Plane) {
      // inside {n.x <= offset} is behind the polygon's front (n): front_inside only when complemented
      const std::vector<PointQ3> poly = clip_plane(hs.normal, hs.offset, box);
      for (std::size_t k = 1; k + 1 < poly.size(); ++k)
        out.push_back({{poly[0], poly[k], poly[k + 1]}, h, -1, static_cast<char>(hs.complement ? 1 : 0)});
      continue;
    }
    const auto& s = hs.surface;
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      const auto& tri = s.triangles[t];
      out.push_back({{s.vertices.at(static_cast<std::size_t>(tri[0])), s.vertices.at(static_cast<std::size_t>(tri[1])),
                      s.vertices.at(static_cast<std::size_t>(tri[2]))},
                     h, static_cast<int>(t), static_cast<char>(hs.complement ? 1 : 0)});
    }
  }
  return out;
}

// ---------------------------------------------------------------- 2. groups by supporting plane
struct Group {
  PointQ3 normal;    // canonical: normal[axis] > 0, first non-zero component scaled to +-1
  Rational offset;   // normal . x = offset
  int axis = 0;      // dominant axis: the projection drops it
  std::vector<int> members;  // input triangles, ascending
};

struct PlaneKeyHash {
  std::size_t operator()(const std::pair<PointQ3, Rational>& k) const {
    return PointHash()(k.first) * 31u ^ hash_rational(k.second);
  }
};

std::vector<Group> group_by_plane(std::vector<InputTriangle>& inputs) {
  std::vector<Group> groups;
  std::unordered_map<std::pair<PointQ3, Rational>, int, PlaneKeyHash> index;
  for (int t = 0; t < static_cast<int>(inputs.size()); ++t) {
    InputTriangle& in = inputs[static_cast<std::size_t>(t)];
    PointQ3 n = normal_of(in.p);
    int first = 0;
    while (coord(n, first) == 0) ++first;  // non-zero: validated surfaces have no degenerate triangle
    n = scaled(n, 1 / abs(coord(n, first)));
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (abs(coord(n, a)) > abs(coord(n, axis))) axis = a;
    if (coord(n, axis) < 0) n = scaled(n, Rational(-1));
    Rational offset = dot(n, in.p[0]);
    auto [it, fresh] = index.emplace(std::make_pair(n, offset), static_cast<int>(groups.size()));
    if (fresh) groups.push_back({n, offset, axis, {}});
    groups[static_cast<std::size_t>(it->second)].members.push_back(t);
    in.group = it->second;
  }
  return groups;
}

// ---------------------------------------------------------------- 3. pairs and their intersections
std::vector<std::pair<int, int>> candidate_pairs(const std::vector<InputTriangle>& inputs) {
  std::vector<BoxD> boxes;
  boxes.reserve(inputs.size());
  for (int t = 0; t < static_cast<int>(inputs.size()); ++t) boxes.push_back(box_of(inputs[static_cast<std::size_t>(t)].p, t));
  std::vector<std::pair<int, int>> pairs;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&pairs](const BoxD& a, const BoxD& b) {
    pairs.emplace_back(std::min(a.info(), b.info()), std::max(a.info(), b.info()));
  });
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

struct Constraint {
  PointQ3 a, b;  // a == b: an isolated point
};

/// Epeck triangles of the input, built on first use (one cache per thread: lazy numbers are not shared).
class TriangleCache {
 public:
  explicit TriangleCache(const std::vector<InputTriangle>& inputs) : inputs_(inputs), cache_(inputs.size()) {}
  const K::Triangle_3& operator[](int t) {
    auto& slot = cache_[static_cast<std::size_t>(t)];
    if (!slot) {
      const auto& p = inputs_[static_cast<std::size_t>(t)].p;
      slot = K::Triangle_3(to_k(p[0]), to_k(p[1]), to_k(p[2]));
    }
    return *slot;
  }

 private:
  const std::vector<InputTriangle>& inputs_;
  std::vector<std::optional<K::Triangle_3>> cache_;
};

int shared_corners(const InputTriangle& a, const InputTriangle& b, std::vector<PointQ3>* shared) {
  for (const auto& p : a.p)
    if (std::find(b.p.begin(), b.p.end(), p) != b.p.end()) shared->push_back(p);
  return static_cast<int>(shared->size());
}

/// Two triangles of one surface on different planes: they may meet only in their shared corners (a shared edge or
/// vertex). Throws InputError naming both otherwise.
void check_self_pair(const Scene3& scene, const std::vector<InputTriangle>& inputs, TriangleCache& cache, int s,
                     int t) {
  const InputTriangle& a = inputs[static_cast<std::size_t>(s)];
  const InputTriangle& b = inputs[static_cast<std::size_t>(t)];
  std::vector<PointQ3> shared;
  const int n = shared_corners(a, b, &shared);
  if (n >= 2) return;  // a shared edge of non-coplanar triangles: they meet exactly along it
  bool bad = false;
  if (n == 0) {
    bad = CGAL::do_intersect(cache[s], cache[t]);
  } else {
    // sharing one corner: fine when the other triangle's far edge is strictly on one side of this one's plane,
    // otherwise compare the intersection with the corner
    const K::Plane_3 plane = cache[s].supporting_plane();
    std::vector<CGAL::Oriented_side> sides;
    for (const auto& p : b.p)
      if (p != shared[0]) sides.push_back(plane.oriented_side(to_k(p)));
    if (sides[0] != CGAL::ON_ORIENTED_BOUNDARY && sides[0] == sides[1]) return;
    const auto result = CGAL::intersection(cache[s], cache[t]);
    if (result) {
      const P3* point = boost::get<P3>(&*result);
      bad = point == nullptr || to_q(*point) != shared[0];
    }
  }
  if (bad)
    throw InputError(halfspace_label(scene, a.halfspace) + ": the surface intersects itself: its triangles " +
                     std::to_string(a.local) + " and " + std::to_string(b.local) + " meet");
}

/// Per group, the segments and points other planes' triangles leave on it.
std::vector<std::vector<Constraint>> intersect_pairs(const Scene3& scene, const std::vector<InputTriangle>& inputs,
                                                     const std::vector<std::pair<int, int>>& pairs, int groups,
                                                     int threads) {
  const int chunk = 512;
  const int chunks = static_cast<int>((pairs.size() + chunk - 1) / chunk);
  std::vector<std::vector<std::pair<int, Constraint>>> found(static_cast<std::size_t>(chunks));
  const int workers = std::max(1, std::min(threads, chunks));
  std::vector<std::unique_ptr<TriangleCache>> caches(static_cast<std::size_t>(workers));
  parallel_for(chunks, workers, [&](int c, int worker) {
    auto& cache = caches[static_cast<std::size_t>(worker)];
    if (!cache) cache = std::make_unique<TriangleCache>(inputs);
    auto& out = found[static_cast<std::size_t>(c)];
    const std::size_t end = std::min(pairs.size(), static_cast<std::size_t>(c + 1) * chunk);
    for (std::size_t k = static_cast<std::size_t>(c) * chunk; k < end; ++k) {
      const int s = pairs[k].first, t = pairs[k].second;
      const InputTriangle& a = inputs[static_cast<std::size_t>(s)];
      const InputTriangle& b = inputs[static_cast<std::size_t>(t)];
      if (a.group == b.group) continue;  // coplanar: triangulated together
      if (a.halfspace == b.halfspace && a.halfspace != kBox && a.local >= 0) {
        check_self_pair(scene, inputs, *cache, s, t);
        continue;
      }
      if (a.halfspace == b.halfspace) continue;  // a plane's fan or the box: meet along their own edges
      const auto result = CGAL::intersection((*cache)[s], (*cache)[t]);
      if (!result) continue;
      Constraint con;
      if (const P3* p = boost::get<P3>(&*result)) {
        con.a = con.b = to_q(*p);
      } else if (const K::Segment_3* seg = boost::get<K::Segment_3>(&*result)) {
        con.a = to_q(seg->source());
        con.b = to_q(seg->target());
      } else {
        throw std::logic_error("arrangement3: coplanar intersection between triangles of different planes");
      }
      out.emplace_back(a.group, con);
      out.emplace_back(b.group, con);
    }
  });
  std::vector<std::vector<Constraint>> per_group(static_cast<std::size_t>(groups));
  for (auto& list : found)
    for (auto& [g, con] : list) per_group[static_cast<std::size_t>(g)].push_back(std::move(con));
  return per_group;
}

// ---------------------------------------------------------------- 4. one triangulation per group
struct LocalTriangle {
  std::array<PointQ3, 3> p;      // front = group normal side (or the single input's own orientation)
  std::vector<int> covering;     // input triangles covering it, ascending
  std::vector<char> same_side;   // per covering input: its front is this triangle's front
};

struct Projected {
  Rational u, v;
};
Projected project(const PointQ3& p, int axis) { return {coord(p, (axis + 1) % 3), coord(p, (axis + 2) % 3)}; }
int orient2(const Projected& a, const Projected& b, const Projected& c) {
  return sign((b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u));
}
PointQ3 lift(const Group& g, const Rational& u, const Rational& v) {
  PointQ3 p;
  coord(p, (g.axis + 1) % 3) = u;
  coord(p, (g.axis + 2) % 3) = v;
  const Rational rest = coord(g.normal, (g.axis + 1) % 3) * u + coord(g.normal, (g.axis + 2) % 3) * v;
  coord(p, g.axis) = (g.offset - rest) / coord(g.normal, g.axis);
  return p;
}

bool strictly_inside(const std::array<Projected, 3>& t, const Projected& q) {
  const int o = orient2(t[0], t[1], t[2]);
  return orient2(t[0], t[1], q) == o && orient2(t[1], t[2], q) == o && orient2(t[2], t[0], q) == o;
}

std::vector<LocalTriangle> triangulate_group(const Group& g, const std::vector<InputTriangle>& inputs,
                                             const std::vector<Constraint>& constraints) {
  if (g.members.size() == 1) {
    const InputTriangle& in = inputs[static_cast<std::size_t>(g.members[0])];
    bool trivial = true;
    for (const Constraint& c : constraints)
      trivial = trivial && std::find(in.p.begin(), in.p.end(), c.a) != in.p.end() &&
                std::find(in.p.begin(), in.p.end(), c.b) != in.p.end();
    if (trivial) return {LocalTriangle{in.p, {g.members[0]}, {1}}};
  }
  auto to2 = [&g](const PointQ3& p) {
    const Projected q = project(p, g.axis);
    return P2(K::FT(q.u), K::FT(q.v));
  };
  Cdt cdt;
  for (int t : g.members) {
    const auto& p = inputs[static_cast<std::size_t>(t)].p;
    for (int k = 0; k < 3; ++k) cdt.insert_constraint(to2(p[k]), to2(p[(k + 1) % 3]));
  }
  for (const Constraint& c : constraints) {
    if (c.a == c.b) cdt.insert(to2(c.a));
    else cdt.insert_constraint(to2(c.a), to2(c.b));
  }
  std::vector<Projected> uv;
  std::vector<PointQ3> lifted;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    v->info() = static_cast<int>(uv.size());
    const auto& e = CGAL::exact(v->point());
    uv.push_back({e.x(), e.y()});
    lifted.push_back(lift(g, e.x(), e.y()));
  }
  std::vector<std::array<Projected, 3>> members;
  std::vector<char> member_same;  // member's orientation agrees with the group normal
  for (int t : g.members) {
    const auto& p = inputs[static_cast<std::size_t>(t)].p;
    members.push_back({project(p[0], g.axis), project(p[1], g.axis), project(p[2], g.axis)});
    member_same.push_back(static_cast<char>(orient2(members.back()[0], members.back()[1], members.back()[2]) > 0));
  }
  std::vector<LocalTriangle> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const int i0 = f->vertex(0)->info(), i1 = f->vertex(1)->info(), i2 = f->vertex(2)->info();
    const Projected centre{(uv[i0].u + uv[i1].u + uv[i2].u) / 3, (uv[i0].v + uv[i1].v + uv[i2].v) / 3};
    LocalTriangle lt{{lifted[i0], lifted[i1], lifted[i2]}, {}, {}};  // counter-clockwise in (u, v): front = normal
    for (std::size_t m = 0; m < members.size(); ++m)
      if (strictly_inside(members[m], centre)) {
        lt.covering.push_back(g.members[m]);
        lt.same_side.push_back(member_same[m]);
      }
    if (!lt.covering.empty()) out.push_back(std::move(lt));
  }
  return out;
}

// ---------------------------------------------------------------- 5. merged triangles, edges, radial order
struct Built {
  std::vector<PointQ3> vertices;
  std::vector<ArrTriangle3> triangles;
  std::vector<int> source;        // per triangle: its lowest covering input triangle
  std::vector<char> outside_side; // per triangle: -1 none, 0 front faces outside the domain, 1 back does
};

/// The triangle's coverage as ArrTriangle3 fields; throws InputError when one surface covers it twice (two
/// overlapping coplanar triangles of one surface).
void set_coverage(const Scene3& scene, const std::vector<InputTriangle>& inputs, const LocalTriangle& lt,
                  ArrTriangle3* t, char* outside) {
  *outside = -1;
  std::vector<std::pair<int, char>> cover;
  for (std::size_t k = 0; k < lt.covering.size(); ++k) {
    const InputTriangle& in = inputs[static_cast<std::size_t>(lt.covering[k])];
    const char front = static_cast<char>(lt.same_side[k] ? in.front_inside : !in.front_inside);
    if (in.halfspace == kBox) {
      t->on_box = true;
      *outside = static_cast<char>(lt.same_side[k] ? 0 : 1);
      continue;
    }
    for (std::size_t j = 0; j < k; ++j) {
      const InputTriangle& other = inputs[static_cast<std::size_t>(lt.covering[j])];
      if (other.halfspace == in.halfspace)
        throw InputError(halfspace_label(scene, in.halfspace) + ": the surface intersects itself: its triangles " +
                         std::to_string(other.local) + " and " + std::to_string(in.local) + " overlap");
    }
    cover.emplace_back(in.halfspace, front);
  }
  std::sort(cover.begin(), cover.end());
  for (const auto& [h, f] : cover) {
    t->halfspaces.push_back(h);
    t->front_inside.push_back(f);
  }
}

Built merge_triangles(const Scene3& scene, const std::vector<InputTriangle>& inputs,
                      const std::vector<std::vector<LocalTriangle>>& local, const ArrangementLimits& limits) {
  Built b;
  std::size_t total = 0;
  for (const auto& l : local) total += l.size();
  if (limits.max_triangles > 0 && static_cast<long>(total) > limits.max_triangles)
    throw InputError("the arrangement has " + std::to_string(total) + " triangles, over the limit of " +
                     std::to_string(limits.max_triangles) + " (see docs/limits.md)");
  std::unordered_map<PointQ3, int, PointHash> index;
  index.reserve(total);
  b.triangles.reserve(total);
  auto vertex = [&](const PointQ3& p) {
    auto [it, fresh] = index.emplace(p, static_cast<int>(b.vertices.size()));
    if (fresh) b.vertices.push_back(p);
    return it->second;
  };
  for (const auto& group : local)
    for (const LocalTriangle& lt : group) {
      ArrTriangle3 t;
      for (int k = 0; k < 3; ++k) t.vertices[static_cast<std::size_t>(k)] = vertex(lt.p[static_cast<std::size_t>(k)]);
      char outside = -1;
      set_coverage(scene, inputs, lt, &t, &outside);
      const PointQ3 n = normal_of(lt.p);
      t.area2 = dot(n, n);
      b.triangles.push_back(std::move(t));
      b.source.push_back(lt.covering.front());
      b.outside_side.push_back(outside);
    }
  return b;
}

/// Exact radial order of the triangles around edge (a, b): right-handed about the direction a -> b.
void sort_radially(const std::vector<PointQ3>& vertices, const std::vector<ArrTriangle3>& triangles, ArrEdge3* edge) {
  const PointQ3& a = vertices[static_cast<std::size_t>(edge->a)];
  const PointQ3 d = vertices[static_cast<std::size_t>(edge->b)] - a;
  const Rational dd = dot(d, d);
  auto third = [&](int t) {
    for (int v : triangles[static_cast<std::size_t>(t)].vertices)
      if (v != edge->a && v != edge->b) return vertices[static_cast<std::size_t>(v)] - a;
    throw std::logic_error("arrangement3: degenerate triangle");
  };
  std::vector<std::pair<int, PointQ3>> items;
  for (int t : edge->triangles) items.emplace_back(t, third(t));
  const PointQ3 ref = items[0].second;
  auto half = [&](const PointQ3& r) {
    const int o = sign(det3(d, ref, r));
    if (o != 0) return o > 0 ? 0 : 1;
    return sign(dot(ref, r) * dd - dot(ref, d) * dot(r, d)) > 0 ? 0 : 1;
  };
  std::vector<int> halves;
  for (auto& it : items) halves.push_back(half(it.second));
  std::vector<int> order(items.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    if (halves[static_cast<std::size_t>(i)] != halves[static_cast<std::size_t>(j)])
      return halves[static_cast<std::size_t>(i)] < halves[static_cast<std::size_t>(j)];
    if (i == j) return false;
    const int s = sign(det3(d, items[static_cast<std::size_t>(i)].second, items[static_cast<std::size_t>(j)].second));
    if (s == 0) throw std::logic_error("arrangement3: two triangles on one half-plane around an edge");
    return s > 0;
  });
  std::vector<int> sorted;
  for (int i : order) sorted.push_back(items[static_cast<std::size_t>(i)].first);
  edge->triangles = std::move(sorted);
}

std::vector<ArrEdge3> build_edges(const std::vector<PointQ3>& vertices, const std::vector<ArrTriangle3>& triangles) {
  std::vector<std::array<int, 3>> entries;
  entries.reserve(triangles.size() * 3);
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const int u = triangles[static_cast<std::size_t>(t)].vertices[static_cast<std::size_t>(k)];
      const int v = triangles[static_cast<std::size_t>(t)].vertices[static_cast<std::size_t>((k + 1) % 3)];
      entries.push_back({std::min(u, v), std::max(u, v), t});
    }
  std::sort(entries.begin(), entries.end());
  std::vector<ArrEdge3> edges;
  for (std::size_t i = 0; i < entries.size();) {
    ArrEdge3 e;
    e.a = entries[i][0];
    e.b = entries[i][1];
    for (; i < entries.size() && entries[i][0] == e.a && entries[i][1] == e.b; ++i) e.triangles.push_back(entries[i][2]);
    if (e.triangles.size() < 2)
      throw std::logic_error("arrangement3: an edge with a single triangle (the refinement is not conforming)");
    if (e.triangles.size() > 2) sort_radially(vertices, triangles, &e);
    edges.push_back(std::move(e));
  }
  return edges;
}

/// True when the triangle runs along a -> b (its front is then on the positive side of the rotation about a->b).
bool runs_forward(const ArrTriangle3& t, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if (t.vertices[static_cast<std::size_t>(k)] == a && t.vertices[static_cast<std::size_t>((k + 1) % 3)] == b) return true;
  return false;
}

// ---------------------------------------------------------------- 6. cells
int side_id(int t, bool front) { return 2 * t + (front ? 0 : 1); }

/// The first triangle a ray meets, with the side facing the ray's origin.
struct RayHit {
  int triangle = -1;
  bool front = false;  // the origin is on the triangle's front side
  bool clean = false;  // found, and the hit is inside the triangle's interior
};

using IntervalQ = CGAL::Interval_nt<false>;
IntervalQ interval(const Rational& q) {
  const auto iv = CGAL::to_interval(q);
  return IntervalQ(iv.first, iv.second);
}

/// Where a point lies on a triangle: -1 not on it, 0 interior, 1 + k on edge k (v_k, v_k+1), 4 + k at vertex k.
struct OnTriangle {
  int where = -1;
};

/// The arrangement's vertices and triangles, as the index's queries see them.
struct TriangleSoup {
  const std::vector<PointQ3>& vertices;
  const std::vector<ArrTriangle3>& triangles;
  std::array<PointQ3, 3> corners(int t) const {
    const auto& v = triangles[static_cast<std::size_t>(t)].vertices;
    return {vertices[static_cast<std::size_t>(v[0])], vertices[static_cast<std::size_t>(v[1])],
            vertices[static_cast<std::size_t>(v[2])]};
  }
};

/// Exact ray shooting and point-on-triangle tests over a soup's triangles, each triangle's supporting plane
/// precomputed, with conservative interval boxes to skip triangles a ray or point cannot meet. Queries take the
/// soup the index was built from.
class TriangleIndex {
 public:
  explicit TriangleIndex(const TriangleSoup& soup) {
    planes_.reserve(soup.triangles.size());
    for (int t = 0; t < static_cast<int>(soup.triangles.size()); ++t) {
      Plane pl;
      const std::array<PointQ3, 3> p = soup.corners(t);
      pl.n = normal_of(p);
      pl.d = dot(pl.n, p[0]);
      for (int a = 1; a < 3; ++a)
        if (abs(coord(pl.n, a)) > abs(coord(pl.n, pl.axis))) pl.axis = a;
      for (int a = 0; a < 3; ++a) {
        pl.lo[a] = std::numeric_limits<double>::infinity();
        pl.hi[a] = -pl.lo[a];
        for (const PointQ3& q : p) {
          const auto iv = CGAL::to_interval(coord(q, a));
          pl.lo[a] = std::min(pl.lo[a], iv.first);
          pl.hi[a] = std::max(pl.hi[a], iv.second);
        }
      }
      planes_.push_back(std::move(pl));
    }
  }

  /// Where q lies on triangle t (exact).
  OnTriangle on(const TriangleSoup& soup, int t, const PointQ3& q) const {
    const Plane& pl = planes_[static_cast<std::size_t>(t)];
    for (int a = 0; a < 3; ++a) {
      const auto iv = CGAL::to_interval(coord(q, a));
      if (iv.second < pl.lo[a] || iv.first > pl.hi[a]) return {};
    }
    if (dot(pl.n, q) != pl.d) return {};
    return in_plane(soup, t, q);
  }

  /// First triangle met by origin + s * dir, s > 0, among those `skip` leaves; not clean when that hit is on an
  /// edge or vertex, when two triangles are met at once, or when the ray runs inside a triangle's plane.
  RayHit first_hit(const TriangleSoup& soup, const PointQ3& origin, const PointQ3& dir,
                   const std::function<bool(int)>& skip) const {
    CGAL::Protect_FPU_rounding<true> protect;
    IntervalQ o[3], d[3];
    for (int a = 0; a < 3; ++a) {
      o[a] = interval(coord(origin, a));
      d[a] = interval(coord(dir, a));
    }
    RayHit best;
    Rational best_s;
    bool tie = false;
    for (int t = 0; t < static_cast<int>(planes_.size()); ++t) {
      const Plane& pl = planes_[static_cast<std::size_t>(t)];
      if (!may_hit(pl, o, d, dir) || skip(t)) continue;
      const Rational off = pl.d - dot(pl.n, origin);  // n.(origin + s dir) = d  <=>  s * n.dir = off
      const Rational nd = dot(pl.n, dir);
      if (nd == 0) {
        if (off == 0) return {};  // the ray runs in this triangle's plane: try another direction
        continue;
      }
      const Rational s = off / nd;
      if (s <= 0 || (best.triangle >= 0 && s > best_s)) continue;
      const OnTriangle where = in_plane(soup, t, origin + scaled(dir, s));
      if (where.where < 0) continue;
      if (best.triangle >= 0 && s == best_s) {
        tie = true;
        continue;
      }
      best.triangle = t;
      best_s = s;
      best.clean = where.where == 0;
      best.front = sign(off) < 0;  // origin - hit = -s dir: on the front iff n.dir < 0 iff off < 0
      tie = false;
    }
    if (tie) best.clean = false;
    return best;
  }

 private:
  struct Plane {
    PointQ3 n;
    Rational d;
    int axis = 0;
    double lo[3], hi[3];
  };

  /// q on t's plane: where on the triangle.
  OnTriangle in_plane(const TriangleSoup& soup, int t, const PointQ3& q) const {
    const Plane& pl = planes_[static_cast<std::size_t>(t)];
    const std::array<PointQ3, 3> p = soup.corners(t);
    const std::array<Projected, 3> tp = {project(p[0], pl.axis), project(p[1], pl.axis), project(p[2], pl.axis)};
    const Projected qp = project(q, pl.axis);
    const int o = orient2(tp[0], tp[1], tp[2]);
    std::array<int, 3> side{};
    for (int e = 0; e < 3; ++e) {
      side[static_cast<std::size_t>(e)] = orient2(tp[e], tp[(e + 1) % 3], qp) * o;
      if (side[static_cast<std::size_t>(e)] < 0) return {};
    }
    for (int k = 0; k < 3; ++k)
      if (p[static_cast<std::size_t>(k)] == q) return {4 + k};
    for (int e = 0; e < 3; ++e)
      if (side[static_cast<std::size_t>(e)] == 0) return {1 + e};
    return {0};
  }

  /// False only when the ray certainly misses the triangle's box (interval slab test, rounding protected).
  static bool may_hit(const Plane& pl, const IntervalQ o[3], const IntervalQ d[3], const PointQ3& dir) {
    double enter = 0, leave = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (coord(dir, a) == 0) {
        if (o[a].sup() < pl.lo[a] || o[a].inf() > pl.hi[a]) return false;
        continue;
      }
      if (d[a].inf() <= 0 && d[a].sup() >= 0) continue;  // cannot tell the sign: no bound from this axis
      IntervalQ t1 = (IntervalQ(pl.lo[a]) - o[a]) / d[a], t2 = (IntervalQ(pl.hi[a]) - o[a]) / d[a];
      if (d[a].inf() < 0) std::swap(t1, t2);
      enter = std::max(enter, t1.inf());
      leave = std::min(leave, t2.sup());
    }
    return enter <= leave;
  }

  std::vector<Plane> planes_;
};

/// Deterministic ray directions with a positive x component (the first is +x).
PointQ3 ray_direction(int attempt) {
  if (attempt == 0) return {1, 0, 0};
  return {1, Rational(2 * attempt + 1, 7 * attempt + 3) - Rational(1, 2), Rational(3 * attempt + 2, 5 * attempt + 11) - Rational(1, 3)};
}

struct CellBuild {
  std::vector<int> cell_of_side;  // per side id: cell or -1 (outside the domain)
  int cells = 0;
};

/// Signed volumes (x6) of each class of sides, relative to `origin`: positive for bounded regions.
std::vector<Rational> class_volumes(const std::vector<PointQ3>& vertices, const std::vector<ArrTriangle3>& triangles,
                                    const Components& classes, const PointQ3& origin) {
  std::vector<Rational> vol(static_cast<std::size_t>(classes.count));
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    const auto& v = triangles[static_cast<std::size_t>(t)].vertices;
    const Rational d = det3(vertices[static_cast<std::size_t>(v[0])] - origin, vertices[static_cast<std::size_t>(v[1])] - origin,
                            vertices[static_cast<std::size_t>(v[2])] - origin);
    vol[static_cast<std::size_t>(classes.of[static_cast<std::size_t>(side_id(t, false))])] += d;  // region behind
    vol[static_cast<std::size_t>(classes.of[static_cast<std::size_t>(side_id(t, true))])] -= d;
  }
  return vol;
}

/// Joins every floating shell complex's exterior with the region around it (found by an exact ray).
void nest_shells(const std::vector<PointQ3>& vertices, const std::vector<ArrTriangle3>& triangles,
                 const std::vector<ArrEdge3>& edges, const PointQ3& origin, DisjointSets& sides) {
  const int n = static_cast<int>(triangles.size());
  DisjointSets shells(static_cast<std::size_t>(n));
  for (const ArrEdge3& e : edges)
    for (int t : e.triangles) shells.union_set(e.triangles[0], t);
  const Components shell = components_of(shells, static_cast<std::size_t>(n));
  std::vector<char> grounded(static_cast<std::size_t>(shell.count), 0);
  for (int t = 0; t < n; ++t)
    if (triangles[static_cast<std::size_t>(t)].on_box) grounded[static_cast<std::size_t>(shell.of[static_cast<std::size_t>(t)])] = 1;
  if (std::all_of(grounded.begin(), grounded.end(), [](char g) { return g != 0; })) return;
  const Components classes = components_of(sides, static_cast<std::size_t>(2 * n));
  const std::vector<Rational> vol = class_volumes(vertices, triangles, classes, origin);
  const auto members = shell.members();
  const TriangleSoup soup{vertices, triangles};
  const TriangleIndex index(soup);
  std::vector<std::pair<int, int>> joins;
  for (int k = 0; k < shell.count; ++k) {
    if (grounded[static_cast<std::size_t>(k)]) continue;
    int exterior = -1, top = -1;  // a side class with negative volume; the vertex of largest x
    for (int t : members[static_cast<std::size_t>(k)]) {
      for (bool front : {true, false}) {
        const int c = classes.of[static_cast<std::size_t>(side_id(t, front))];
        if (vol[static_cast<std::size_t>(c)] < 0) exterior = side_id(t, front);
      }
      for (int v : triangles[static_cast<std::size_t>(t)].vertices)
        if (top < 0 || vertices[static_cast<std::size_t>(v)].x > vertices[static_cast<std::size_t>(top)].x) top = v;
    }
    if (exterior < 0) throw std::logic_error("arrangement3: a floating shell without an exterior");
    RayHit hit;
    for (int attempt = 0; attempt < 64 && !hit.clean; ++attempt)
      hit = index.first_hit(soup, vertices[static_cast<std::size_t>(top)], ray_direction(attempt),
                            [&](int t) { return shell.of[static_cast<std::size_t>(t)] == k; });
    if (!hit.clean) throw std::logic_error("arrangement3: no clean ray out of a floating shell");
    joins.emplace_back(exterior, side_id(hit.triangle, hit.front));
  }
  for (const auto& j : joins) sides.union_set(j.first, j.second);
}

CellBuild find_cells(const Built& b, const std::vector<ArrEdge3>& edges, const Box3& box) {
  const int n = static_cast<int>(b.triangles.size());
  DisjointSets sides(static_cast<std::size_t>(2 * n));
  for (const ArrEdge3& e : edges) {
    const std::size_t m = e.triangles.size();
    for (std::size_t i = 0; i < m; ++i) {
      const int t = e.triangles[i], u = e.triangles[(i + 1) % m];
      const bool t_pos = runs_forward(b.triangles[static_cast<std::size_t>(t)], e.a, e.b);
      const bool u_pos = runs_forward(b.triangles[static_cast<std::size_t>(u)], e.a, e.b);
      sides.union_set(side_id(t, t_pos), side_id(u, !u_pos));  // the wedge from t to u
    }
  }
  int outside = -1;
  for (int t = 0; t < n; ++t) {
    const char o = b.outside_side[static_cast<std::size_t>(t)];
    if (o < 0) continue;
    const int s = side_id(t, o == 0);
    if (outside < 0) outside = s;
    sides.union_set(outside, s);
  }
  nest_shells(b.vertices, b.triangles, edges, box.min, sides);
  const Components classes = components_of(sides, static_cast<std::size_t>(2 * n));
  const int outside_class = classes.of[static_cast<std::size_t>(outside)];
  CellBuild cb;
  std::vector<int> cell_of_class(static_cast<std::size_t>(classes.count), -1);
  cb.cell_of_side.resize(static_cast<std::size_t>(2 * n));
  for (int s = 0; s < 2 * n; ++s) {
    const int c = classes.of[static_cast<std::size_t>(s)];
    if (c == outside_class) {
      cb.cell_of_side[static_cast<std::size_t>(s)] = -1;
      continue;
    }
    int& cell = cell_of_class[static_cast<std::size_t>(c)];
    if (cell < 0) cell = cb.cells++;
    cb.cell_of_side[static_cast<std::size_t>(s)] = cell;
  }
  return cb;
}

void check_cell_limits(long cells, long halfspaces, const ArrangementLimits& limits) {
  if (limits.max_cells > 0 && cells > limits.max_cells)
    throw InputError("the arrangement has " + std::to_string(cells) + " cells, over the limit of " +
                     std::to_string(limits.max_cells) + " (raise it with --max-cells; see docs/limits.md)");
  if (limits.max_side_entries > 0 && cells * halfspaces > limits.max_side_entries)
    throw InputError("the arrangement has " + std::to_string(cells) + " cells over " + std::to_string(halfspaces) +
                     " halfspaces: its side table (cells x halfspaces) exceeds " +
                     std::to_string(limits.max_side_entries) +
                     " entries, the limit (raise it with --max-side-table; see docs/limits.md)");
}

bool carries(const ArrTriangle3& t, int h) { return std::binary_search(t.halfspaces.begin(), t.halfspaces.end(), h); }

/// Each cell's side of every halfspace: known next to the halfspace's own triangles, carried across every other
/// triangle (both sides agree there); a halfspace without triangles (a plane missing the box) is evaluated at the
/// box's centre. Then every triangle is checked against the result.
std::vector<std::vector<char>> cell_sides(const Scene3& scene, const std::vector<ArrTriangle3>& triangles, int cells) {
  const int H = static_cast<int>(scene.halfspaces.size());
  std::vector<std::vector<std::pair<int, int>>> adjacent(static_cast<std::size_t>(cells));  // (other cell, triangle)
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    const ArrTriangle3& tr = triangles[static_cast<std::size_t>(t)];
    if (tr.front_cell < 0 || tr.back_cell < 0) continue;
    adjacent[static_cast<std::size_t>(tr.front_cell)].emplace_back(tr.back_cell, t);
    adjacent[static_cast<std::size_t>(tr.back_cell)].emplace_back(tr.front_cell, t);
  }
  std::vector<std::vector<char>> inside(static_cast<std::size_t>(cells), std::vector<char>(static_cast<std::size_t>(H), 0));
  for (int h = 0; h < H; ++h) {
    std::vector<signed char> side(static_cast<std::size_t>(cells), -1);
    std::vector<int> queue;
    for (const ArrTriangle3& tr : triangles) {
      const auto it = std::lower_bound(tr.halfspaces.begin(), tr.halfspaces.end(), h);
      if (it == tr.halfspaces.end() || *it != h) continue;
      const char front = tr.front_inside[static_cast<std::size_t>(it - tr.halfspaces.begin())];
      for (const auto& [cell, value] : {std::make_pair(tr.front_cell, front), std::make_pair(tr.back_cell, static_cast<char>(!front))})
        if (cell >= 0 && side[static_cast<std::size_t>(cell)] < 0) {
          side[static_cast<std::size_t>(cell)] = static_cast<signed char>(value);
          queue.push_back(cell);
        }
    }
    if (queue.empty()) {
      const Halfspace3& hs = scene.halfspaces[static_cast<std::size_t>(h)];
      const PointQ3 centre = scaled(scene.domain.min + scene.domain.max, Rational(1, 2));
      const bool in = (dot(hs.normal, centre) <= hs.offset) != hs.complement;
      for (auto& s : side) s = static_cast<signed char>(in);
    }
    for (std::size_t k = 0; k < queue.size(); ++k)
      for (const auto& [other, t] : adjacent[static_cast<std::size_t>(queue[k])])
        if (side[static_cast<std::size_t>(other)] < 0 && !carries(triangles[static_cast<std::size_t>(t)], h)) {
          side[static_cast<std::size_t>(other)] = side[static_cast<std::size_t>(queue[k])];
          queue.push_back(other);
        }
    for (int c = 0; c < cells; ++c) {
      if (side[static_cast<std::size_t>(c)] < 0) throw std::logic_error("arrangement3: a cell no side reaches");
      inside[static_cast<std::size_t>(c)][static_cast<std::size_t>(h)] = static_cast<char>(side[static_cast<std::size_t>(c)]);
    }
  }
  for (const ArrTriangle3& tr : triangles) {
    if (tr.front_cell < 0 || tr.back_cell < 0) continue;
    for (int h = 0; h < H; ++h) {
      const auto it = std::lower_bound(tr.halfspaces.begin(), tr.halfspaces.end(), h);
      const char f = inside[static_cast<std::size_t>(tr.front_cell)][static_cast<std::size_t>(h)];
      const char b = inside[static_cast<std::size_t>(tr.back_cell)][static_cast<std::size_t>(h)];
      const bool on = it != tr.halfspaces.end() && *it == h;
      const bool ok = on ? (f == tr.front_inside[static_cast<std::size_t>(it - tr.halfspaces.begin())] && b != f) : f == b;
      if (!ok) throw std::logic_error("arrangement3: inconsistent sides across a triangle");
    }
  }
  return inside;
}

/// An exact point strictly inside each cell: from the centroid of the cell's largest boundary triangle, along
/// its normal into the cell, half way to the first triangle met (or to the end of a short probe segment).
std::vector<PointQ3> interior_points(const std::vector<PointQ3>& vertices, const std::vector<ArrTriangle3>& triangles,
                                     int cells) {
  std::vector<int> best(static_cast<std::size_t>(cells), -1);
  std::vector<char> best_front(static_cast<std::size_t>(cells), 0);
  std::vector<double> best_area(static_cast<std::size_t>(cells), -1);
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    const ArrTriangle3& tr = triangles[static_cast<std::size_t>(t)];
    const double a = tr.area2.get_d();
    for (const auto& [cell, front] : {std::make_pair(tr.front_cell, true), std::make_pair(tr.back_cell, false)})
      if (cell >= 0 && a > best_area[static_cast<std::size_t>(cell)]) {
        best_area[static_cast<std::size_t>(cell)] = a;
        best[static_cast<std::size_t>(cell)] = t;
        best_front[static_cast<std::size_t>(cell)] = front;
      }
  }
  std::vector<PointQ3> start(static_cast<std::size_t>(cells)), end(static_cast<std::size_t>(cells));
  std::vector<BoxD> probes, boxes;
  for (int c = 0; c < cells; ++c) {
    const auto& v = triangles[static_cast<std::size_t>(best[static_cast<std::size_t>(c)])].vertices;
    const std::array<PointQ3, 3> p = {vertices[static_cast<std::size_t>(v[0])], vertices[static_cast<std::size_t>(v[1])],
                                      vertices[static_cast<std::size_t>(v[2])]};
    const PointQ3 n = normal_of(p);
    // |lambda * n| about sqrt(|n|), the triangle's size: lambda a power of two near |n|^(-1/2)
    const int e = static_cast<int>(std::lround(-0.25 * std::log2(best_area[static_cast<std::size_t>(c)])));
    Rational lambda(1);
    if (e >= 0) mpq_mul_2exp(lambda.get_mpq_t(), lambda.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    else mpq_div_2exp(lambda.get_mpq_t(), lambda.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
    if (!best_front[static_cast<std::size_t>(c)]) lambda = -lambda;
    start[static_cast<std::size_t>(c)] = scaled(p[0] + p[1] + p[2], Rational(1, 3));
    end[static_cast<std::size_t>(c)] = start[static_cast<std::size_t>(c)] + scaled(n, lambda);
    probes.push_back(box_of(std::array<PointQ3, 2>{start[static_cast<std::size_t>(c)], end[static_cast<std::size_t>(c)]}, c));
  }
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    const auto& v = triangles[static_cast<std::size_t>(t)].vertices;
    boxes.push_back(box_of(std::array<PointQ3, 3>{vertices[static_cast<std::size_t>(v[0])], vertices[static_cast<std::size_t>(v[1])],
                                                  vertices[static_cast<std::size_t>(v[2])]},
                           t));
  }
  std::vector<std::vector<int>> candidates(static_cast<std::size_t>(cells));
  CGAL::box_intersection_d(probes.begin(), probes.end(), boxes.begin(), boxes.end(),
                           [&candidates](const BoxD& probe, const BoxD& tri) {
                             candidates[static_cast<std::size_t>(probe.info())].push_back(tri.info());
                           });
  std::vector<PointQ3> out(static_cast<std::size_t>(cells));
  for (int c = 0; c < cells; ++c) {
    auto& cand = candidates[static_cast<std::size_t>(c)];
    std::sort(cand.begin(), cand.end());
    const PointQ3& s = start[static_cast<std::size_t>(c)];
    const PointQ3 dir = end[static_cast<std::size_t>(c)] - s;
    const Rational dd = dot(dir, dir);
    const K::Segment_3 seg(to_k(s), to_k(end[static_cast<std::size_t>(c)]));
    Rational t_min(1);
    for (int t : cand) {
      if (t == best[static_cast<std::size_t>(c)]) continue;
      const auto& v = triangles[static_cast<std::size_t>(t)].vertices;
      const K::Triangle_3 tri(to_k(vertices[static_cast<std::size_t>(v[0])]), to_k(vertices[static_cast<std::size_t>(v[1])]),
                              to_k(vertices[static_cast<std::size_t>(v[2])]));
      const auto result = CGAL::intersection(seg, tri);
      if (!result) continue;
      std::vector<PointQ3> hits;
      if (const P3* p = boost::get<P3>(&*result)) hits.push_back(to_q(*p));
      if (const K::Segment_3* g = boost::get<K::Segment_3>(&*result)) {
        hits.push_back(to_q(g->source()));
        hits.push_back(to_q(g->target()));
      }
      for (const PointQ3& q : hits) {
        const Rational at = dot(q - s, dir) / dd;
        if (at > 0 && at < t_min) t_min = at;
      }
    }
    out[static_cast<std::size_t>(c)] = s + scaled(dir, t_min / 2);
  }
  return out;
}

/// The triangle holding each sample, carrying its halfspace; InputError when the sample is on no such triangle,
/// on the domain box, or on an edge or vertex where its patch ends.
std::vector<int> place_samples(const Scene3& scene, const std::vector<PointQ3>& vertices,
                               const std::vector<ArrTriangle3>& triangles, const std::vector<ArrEdge3>& edges) {
  std::vector<std::vector<int>> by_halfspace(scene.halfspaces.size());
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    for (int h : triangles[static_cast<std::size_t>(t)].halfspaces) by_halfspace[static_cast<std::size_t>(h)].push_back(t);
  auto edge_of = [&edges](int a, int b) -> const ArrEdge3& {
    const auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(std::min(a, b), std::max(a, b)),
                                     [](const ArrEdge3& e, const std::pair<int, int>& k) { return std::make_pair(e.a, e.b) < k; });
    return *it;
  };
  auto patch_interior = [&triangles](const ArrEdge3& e) {
    if (e.triangles.size() != 2) return false;
    const ArrTriangle3& s = triangles[static_cast<std::size_t>(e.triangles[0])];
    const ArrTriangle3& t = triangles[static_cast<std::size_t>(e.triangles[1])];
    return !s.on_box && !t.on_box && s.halfspaces == t.halfspaces;
  };
  std::vector<int> out;
  for (std::size_t k = 0; k < scene.samples.size(); ++k) {
    const Sample3& sample = scene.samples[k];
    const PointQ3& q = sample.location;
    const std::string label = "samples[" + std::to_string(k) + "] (of " + halfspace_label(scene, sample.halfspace) + ")";
    int found = -1;
    bool ok = true;
    for (int t : by_halfspace.at(static_cast<std::size_t>(sample.halfspace))) {
      const auto& v = triangles[static_cast<std::size_t>(t)].vertices;
      const std::array<PointQ3, 3> p = {vertices[static_cast<std::size_t>(v[0])], vertices[static_cast<std::size_t>(v[1])],
                                        vertices[static_cast<std::size_t>(v[2])]};
      const PointQ3 n = normal_of(p);
      if (dot(n, q - p[0]) != 0) continue;
      int axis = 0;
      for (int a = 1; a < 3; ++a)
        if (abs(coord(n, a)) > abs(coord(n, axis))) axis = a;
      const std::array<Projected, 3> tp = {project(p[0], axis), project(p[1], axis), project(p[2], axis)};
      const Projected qp = project(q, axis);
      const int o = orient2(tp[0], tp[1], tp[2]);
      int on_edges = 0;
      bool out_of = false;
      for (int e = 0; e < 3; ++e) {
        const int s = orient2(tp[e], tp[(e + 1) % 3], qp) * o;
        if (s < 0) out_of = true;
        if (s == 0) {
          ++on_edges;
          ok = ok && patch_interior(edge_of(v[e], v[(e + 1) % 3]));
        }
      }
      if (out_of) continue;
      if (triangles[static_cast<std::size_t>(t)].on_box)
        throw InputError(label + ": lies on the domain box, where its halfspace has no patch");
      if (found < 0) found = t;
      (void)on_edges;
    }
    if (found < 0) throw InputError(label + ": not on its halfspace's boundary inside the domain");
    if (!ok) throw InputError(label + ": lies on an edge where boundaries meet; move it into a patch");
    out.push_back(found);
  }
  return out;
}

}  // namespace

/// What locate needs beyond the public data: the triangles' planes and boxes (copies of an Arrangement3 share
/// it; the triangles never change after build).
struct Arrangement3::Impl {
  TriangleIndex index;
};

Arrangement3 Arrangement3::build(const Scene3& scene, const ArrangementLimits& limits,
                                 const Arrangement3Options& options) {
  const int threads = worker_count(options.threads);
  std::vector<InputTriangle> inputs = input_triangles(scene);
  const std::vector<Group> groups = group_by_plane(inputs);
  const std::vector<std::pair<int, int>> pairs = candidate_pairs(inputs);
  const std::vector<std::vector<Constraint>> constraints =
      intersect_pairs(scene, inputs, pairs, static_cast<int>(groups.size()), threads);
  std::vector<std::vector<LocalTriangle>> local(groups.size());
  parallel_for(static_cast<int>(groups.size()), threads, [&](int g, int) {
    local[static_cast<std::size_t>(g)] =
        triangulate_group(groups[static_cast<std::size_t>(g)], inputs, constraints[static_cast<std::size_t>(g)]);
  });
  Built b = merge_triangles(scene, inputs, local, limits);
  local.clear();
  Arrangement3 arr;
  arr.domain_ = scene.domain;
  arr.halfspace_count_ = static_cast<int>(scene.halfspaces.size());
  arr.edges_ = build_edges(b.vertices, b.triangles);
  const CellBuild cb = find_cells(b, arr.edges_, scene.domain);
  check_cell_limits(cb.cells, arr.halfspace_count_, limits);
  for (int t = 0; t < static_cast<int>(b.triangles.size()); ++t) {
    b.triangles[static_cast<std::size_t>(t)].front_cell = cb.cell_of_side[static_cast<std::size_t>(side_id(t, true))];
    b.triangles[static_cast<std::size_t>(t)].back_cell = cb.cell_of_side[static_cast<std::size_t>(side_id(t, false))];
  }
  const auto inside = cell_sides(scene, b.triangles, cb.cells);
  const auto witness = interior_points(b.vertices, b.triangles, cb.cells);
  arr.cells_.resize(static_cast<std::size_t>(cb.cells));
  for (int c = 0; c < cb.cells; ++c) {
    arr.cells_[static_cast<std::size_t>(c)].inside = inside[static_cast<std::size_t>(c)];
    arr.cells_[static_cast<std::size_t>(c)].interior = witness[static_cast<std::size_t>(c)];
    if (options.volumes) arr.cells_[static_cast<std::size_t>(c)].volume = Rational(0);
  }
  for (const ArrTriangle3& t : b.triangles) {
    for (int c : {t.front_cell, t.back_cell})
      if (c >= 0 && t.on_box) arr.cells_[static_cast<std::size_t>(c)].outer = true;
    if (!options.volumes) continue;
    const Rational d = det3(b.vertices[static_cast<std::size_t>(t.vertices[0])] - scene.domain.min,
                            b.vertices[static_cast<std::size_t>(t.vertices[1])] - scene.domain.min,
                            b.vertices[static_cast<std::size_t>(t.vertices[2])] - scene.domain.min) /
                       6;
    if (t.back_cell >= 0) *arr.cells_[static_cast<std::size_t>(t.back_cell)].volume += d;
    if (t.front_cell >= 0) *arr.cells_[static_cast<std::size_t>(t.front_cell)].volume -= d;
  }
  // planes are checked directly at every witness
  for (int h = 0; h < arr.halfspace_count_; ++h) {
    const Halfspace3& hs = scene.halfspaces[static_cast<std::size_t>(h)];
    if (hs.kind != HalfspaceKind3::Plane) continue;
    for (const ArrCell3& c : arr.cells_) {
      const Rational s = dot(hs.normal, c.interior) - hs.offset;
      if (s == 0 || ((s < 0) != hs.complement) != (c.inside[static_cast<std::size_t>(h)] != 0))
        throw std::logic_error("arrangement3: a cell's side of a plane disagrees with its witness");
    }
  }
  arr.sample_triangles_ = place_samples(scene, b.vertices, b.triangles, arr.edges_);
  arr.vertices_ = std::move(b.vertices);
  arr.triangles_ = std::move(b.triangles);
  arr.impl_ = std::make_shared<const Impl>(Impl{TriangleIndex(TriangleSoup{arr.vertices_, arr.triangles_})});
  return arr;
}

PointLocation3 Arrangement3::locate(const PointQ3& p) const {
  if (!domain_.contains(p)) return {PointLocation3::Outside, -1};
  const TriangleIndex& index = impl_->index;
  const TriangleSoup soup{vertices_, triangles_};
  for (int t = 0; t < static_cast<int>(triangles_.size()); ++t) {
    const OnTriangle where = index.on(soup, t, p);
    if (where.where < 0) continue;
    const auto& v = triangles_[static_cast<std::size_t>(t)].vertices;
    if (where.where >= 4) return {PointLocation3::Vertex, v[static_cast<std::size_t>(where.where - 4)]};
    if (where.where == 0) return {PointLocation3::Triangle, t};
    const int e = where.where - 1;
    const auto key = std::make_pair(std::min(v[static_cast<std::size_t>(e)], v[static_cast<std::size_t>((e + 1) % 3)]),
                                    std::max(v[static_cast<std::size_t>(e)], v[static_cast<std::size_t>((e + 1) % 3)]));
    const auto it = std::lower_bound(edges_.begin(), edges_.end(), key, [](const ArrEdge3& x, const std::pair<int, int>& k) {
      return std::make_pair(x.a, x.b) < k;
    });
    return {PointLocation3::Edge, static_cast<int>(it - edges_.begin())};
  }
  for (int attempt = 0; attempt < 64; ++attempt) {
    const RayHit hit = index.first_hit(soup, p, ray_direction(attempt), [](int) { return false; });
    if (!hit.clean) continue;
    const ArrTriangle3& t = triangles_[static_cast<std::size_t>(hit.triangle)];
    return {PointLocation3::Cell, hit.front ? t.front_cell : t.back_cell};
  }
  throw std::logic_error("Arrangement3::locate: no clean ray");
}

}  // namespace hsx
