// The only translation unit that instantiates CGAL for the 3D arrangement (constrained triangulations, box
// intersection, triangle intersections and an AABB tree on Epeck; ~40 s and ~2 GB to compile: keep CGAL out of every
// other file).
// Everything it hands out is plain data (geometry/arrangement3.hpp).
//
// Phases of Arrangement3::build (each a function below):
//  1. input triangles: every surface's triangles, every plane clipped to the box (a convex polygon, fanned), the
//     box's twelve face triangles (outward);
//  2. groups: input triangles by exact supporting plane (both orientations share a plane);
//  3. candidate pairs by CGAL::box_self_intersection_d, exact intersections between ORIGINAL input triangles of
//     different planes (each triangle cut by the other's plane, interval filtered; the two cuts overlap on the line
//     where the planes meet); pairs of one surface are checked for self-intersection instead;
//  4. one constrained triangulation per group (projected along its dominant axis, lifted back exactly), each
//     output triangle kept once with the input triangles covering it and its squared area (groups in parallel,
//     largest first);
//  5. vertices merged by exact coordinates (hash), edges with their triangles sorted radially (exact; edges of more
//     than two triangles in parallel);
//  6. cells: union-find over triangle sides across edges, floating shells joined to the cell around them by exact
//     rays from their triangles' centroids; sides of every halfspace propagated across triangles (and checked); interior points by a short
//     exact segment from a boundary triangle (cells in parallel); volumes by signed tetrahedra; samples on triangles.
// Parallel phases write their results per index, so the arrangement does not depend on the thread count. Rays
// (floating shells, locate) take their candidates from an AABB tree of the refined triangles (TriangleIndex).
#include <hsx/geometry/arrangement3.hpp>
#include "geometry/components.hpp"
#include "kernel/threads.hpp"

// Constraints that cross inside one plane are split by CDT_2 at their exact crossing (Epeck): exact, so every
// triple point is the same rational point in each plane's triangulation. CGAL warns on stderr that
// Constrained_triangulation_plus_2 would avoid cascading constructions; the result does not depend on it.
#define CGAL_NO_CDT_2_WARNING

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Constrained_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <unordered_map>
#include <unordered_set>

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

/// Interval arithmetic for filters: Interval_nt<false> needs the FPU rounding upward (CGAL::Protect_FPU_rounding).
using IntervalQ = CGAL::Interval_nt<false>;
IntervalQ interval(const Rational& q) {
  const auto iv = CGAL::to_interval(q);
  return IntervalQ(iv.first, iv.second);
}

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
/// thread count; when the system refuses a thread, the ones started (at least the calling one) do all the work.
/// Once an i fails, no i above it is started: the lowest failing i is still found (every i below it runs), and
/// work that cannot be used is not done. Out of memory, that matters: every item left to run would fail too, and
/// the exceptions kept for them would exhaust the C++ runtime's emergency pool (std::terminate, exit 134).
void parallel_for(int n, int threads, const std::function<void(int, int)>& work) {
  threads = std::max(1, std::min(threads, n));
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(std::max(n, 0)));
  std::atomic<int> next{0};
  std::atomic<int> first_failure{n};
  auto run = [&](int worker) {
    for (int i = next++; i < n && i < first_failure.load(); i = next++) {
      try {
        work(i, worker);
      } catch (...) {
        errors[static_cast<std::size_t>(i)] = std::current_exception();
        for (int seen = first_failure.load(); i < seen && !first_failure.compare_exchange_weak(seen, i);) {
        }
      }
    }
  };
  // A thread the system refuses leaves fewer threads to share the work.
  std::vector<std::thread> pool = start_threads(1, threads, [&run](int worker) { run(worker); });
  run(0);
  for (auto& t : pool) t.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

/// Adds the time since the previous lap to a named phase of `timings` (nothing when it is null).
class PhaseClock {
 public:
  explicit PhaseClock(Arrangement3Timings* timings) : timings_(timings), last_(std::chrono::steady_clock::now()) {}
  void lap(const char* phase) {
    if (timings_ == nullptr) return;
    const auto now = std::chrono::steady_clock::now();
    timings_->add(phase, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

 private:
  Arrangement3Timings* timings_;
  std::chrono::steady_clock::time_point last_;
};

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

/// Interval enclosures of the input triangles' corners and of the groups' planes, for the pair filter (evaluate
/// under CGAL::Protect_FPU_rounding).
struct PairFilter {
  std::vector<std::array<std::array<IntervalQ, 3>, 3>> corners;  // per input triangle, corner, axis
  std::vector<std::array<IntervalQ, 4>> planes;                   // per group: normal x, y, z and offset

  PairFilter(const std::vector<InputTriangle>& inputs, const std::vector<Group>& groups) {
    corners.resize(inputs.size());
    for (std::size_t t = 0; t < inputs.size(); ++t)
      for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 3; ++a) corners[t][static_cast<std::size_t>(k)][static_cast<std::size_t>(a)] = interval(coord(inputs[t].p[static_cast<std::size_t>(k)], a));
    planes.resize(groups.size());
    for (std::size_t g = 0; g < groups.size(); ++g) {
      for (int a = 0; a < 3; ++a) planes[g][static_cast<std::size_t>(a)] = interval(coord(groups[g].normal, a));
      planes[g][3] = interval(groups[g].offset);
    }
  }
};

/// The signs of group g's plane function (normal . x - offset) at triangle t's corners: interval filtered, exact
/// where the filter cannot tell; `value` receives the exact values it computed (the others are left unset).
std::array<int, 3> plane_signs(const std::vector<InputTriangle>& inputs, const std::vector<Group>& groups,
                               const PairFilter& filter, int t, int g, std::array<std::optional<Rational>, 3>* value) {
  std::array<int, 3> out{};
  const auto& pl = filter.planes[static_cast<std::size_t>(g)];
  for (int k = 0; k < 3; ++k) {
    const auto& c = filter.corners[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)];
    const IntervalQ f = pl[0] * c[0] + pl[1] * c[1] + pl[2] * c[2] - pl[3];
    if (f.inf() > 0 || f.sup() < 0) {
      out[static_cast<std::size_t>(k)] = f.inf() > 0 ? 1 : -1;
      continue;
    }
    const Group& group = groups[static_cast<std::size_t>(g)];
    Rational v = dot(group.normal, inputs[static_cast<std::size_t>(t)].p[static_cast<std::size_t>(k)]) - group.offset;
    out[static_cast<std::size_t>(k)] = sign(v);
    (*value)[static_cast<std::size_t>(k)] = std::move(v);
  }
  return out;
}

/// Where triangle t meets the plane of group g (t not on it): its corners on the plane and the crossings of its
/// edges, in edge order (one or two distinct points); false when t is strictly on one side.
bool plane_cut(const std::vector<InputTriangle>& inputs, const std::vector<Group>& groups, const PairFilter& filter,
               int t, int g, std::vector<PointQ3>* cut) {
  std::array<std::optional<Rational>, 3> value;
  const std::array<int, 3> s = plane_signs(inputs, groups, filter, t, g, &value);
  if (s[0] == s[1] && s[1] == s[2] && s[0] != 0) return false;
  const auto& p = inputs[static_cast<std::size_t>(t)].p;
  const Group& group = groups[static_cast<std::size_t>(g)];
  auto exact = [&](int k) -> const Rational& {
    auto& v = value[static_cast<std::size_t>(k)];
    if (!v) v = dot(group.normal, p[static_cast<std::size_t>(k)]) - group.offset;
    return *v;
  };
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    if (s[static_cast<std::size_t>(k)] == 0) cut->push_back(p[static_cast<std::size_t>(k)]);
    if (s[static_cast<std::size_t>(k)] * s[static_cast<std::size_t>(j)] < 0) {
      const Rational& vk = exact(k);
      const Rational f = vk / (vk - exact(j));
      cut->push_back(p[static_cast<std::size_t>(k)] + scaled(p[static_cast<std::size_t>(j)] - p[static_cast<std::size_t>(k)], f));
    }
  }
  return true;
}

/// The axis along which the points of a line (two distinct points of it among `a`, `b`) are ordered.
int line_axis(const std::vector<PointQ3>& a, const std::vector<PointQ3>& b) {
  const std::vector<PointQ3>& two = a.size() == 2 ? a : b;
  for (int axis = 0; axis < 3; ++axis)
    if (coord(two[0], axis) != coord(two[1], axis)) return axis;
  throw std::logic_error("arrangement3: a cut of two equal points");
}

/// The exact intersection of input triangles s and t of different planes: a point or a segment, or nothing. Both
/// meet the line where their planes cross in a segment (or point); the intersection is the overlap of the two.
std::optional<Constraint> intersect_triangles(const std::vector<InputTriangle>& inputs,
                                              const std::vector<Group>& groups, const PairFilter& filter, int s,
                                              int t) {
  std::vector<PointQ3> cut_s, cut_t;
  if (!plane_cut(inputs, groups, filter, t, inputs[static_cast<std::size_t>(s)].group, &cut_t)) return std::nullopt;
  if (!plane_cut(inputs, groups, filter, s, inputs[static_cast<std::size_t>(t)].group, &cut_s)) return std::nullopt;
  if (cut_s.size() == 1 && cut_t.size() == 1) {
    if (cut_s[0] != cut_t[0]) return std::nullopt;
    return Constraint{cut_s[0], cut_s[0]};
  }
  const int axis = line_axis(cut_s, cut_t);
  auto order = [axis](std::vector<PointQ3>& cut) {
    if (cut.size() == 2 && coord(cut[1], axis) < coord(cut[0], axis)) std::swap(cut[0], cut[1]);
  };
  order(cut_s);
  order(cut_t);
  const PointQ3& lo = coord(cut_s.front(), axis) < coord(cut_t.front(), axis) ? cut_t.front() : cut_s.front();
  const PointQ3& hi = coord(cut_s.back(), axis) < coord(cut_t.back(), axis) ? cut_s.back() : cut_t.back();
  const int c = cmp(coord(lo, axis), coord(hi, axis));
  if (c > 0) return std::nullopt;
  return Constraint{lo, c == 0 ? lo : hi};
}

int shared_corners(const InputTriangle& a, const InputTriangle& b, std::vector<PointQ3>* shared) {
  for (const auto& p : a.p)
    if (std::find(b.p.begin(), b.p.end(), p) != b.p.end()) shared->push_back(p);
  return static_cast<int>(shared->size());
}

/// Two triangles of one surface on different planes: they may meet only in their shared corners (a shared edge or
/// vertex). Throws InputError naming both otherwise.
void check_self_pair(const Scene3& scene, const std::vector<InputTriangle>& inputs, const std::vector<Group>& groups,
                     const PairFilter& filter, int s, int t) {
  const InputTriangle& a = inputs[static_cast<std::size_t>(s)];
  const InputTriangle& b = inputs[static_cast<std::size_t>(t)];
  std::vector<PointQ3> shared;
  const int n = shared_corners(a, b, &shared);
  if (n >= 2) return;  // a shared edge of non-coplanar triangles: they meet exactly along it
  const std::optional<Constraint> meet = intersect_triangles(inputs, groups, filter, s, t);
  const bool bad = meet && (n == 0 || meet->a != meet->b || meet->a != shared[0]);
  if (bad)
    throw InputError(halfspace_label(scene, a.halfspace) + ": the surface intersects itself: its triangles " +
                     std::to_string(a.local) + " and " + std::to_string(b.local) + " meet");
}

/// Per group, the segments and points other planes' triangles leave on it.
std::vector<std::vector<Constraint>> intersect_pairs(const Scene3& scene, const std::vector<InputTriangle>& inputs,
                                                     const std::vector<Group>& groups,
                                                     const std::vector<std::pair<int, int>>& pairs, int threads) {
  const PairFilter filter(inputs, groups);
  const int chunk = 512;
  const int chunks = static_cast<int>((pairs.size() + chunk - 1) / chunk);
  std::vector<std::vector<std::pair<int, Constraint>>> found(static_cast<std::size_t>(chunks));
  const int workers = std::max(1, std::min(threads, chunks));
  parallel_for(chunks, workers, [&](int c, int) {
    CGAL::Protect_FPU_rounding<true> protect;  // the filter's intervals round upward
    auto& out = found[static_cast<std::size_t>(c)];
    const std::size_t end = std::min(pairs.size(), static_cast<std::size_t>(c + 1) * chunk);
    for (std::size_t k = static_cast<std::size_t>(c) * chunk; k < end; ++k) {
      const int s = pairs[k].first, t = pairs[k].second;
      const InputTriangle& a = inputs[static_cast<std::size_t>(s)];
      const InputTriangle& b = inputs[static_cast<std::size_t>(t)];
      if (a.group == b.group) continue;  // coplanar: triangulated together
      if (a.halfspace == b.halfspace && a.halfspace != kBox && a.local >= 0) {
        check_self_pair(scene, inputs, groups, filter, s, t);
        continue;
      }
      if (a.halfspace == b.halfspace) continue;  // a plane's fan or the box: meet along their own edges
      std::optional<Constraint> con = intersect_triangles(inputs, groups, filter, s, t);
      if (!con) continue;
      out.emplace_back(a.group, *con);
      out.emplace_back(b.group, std::move(*con));
    }
  });
  std::vector<std::vector<Constraint>> per_group(groups.size());
  for (auto& list : found)
    for (auto& [g, con] : list) per_group[static_cast<std::size_t>(g)].push_back(std::move(con));
  return per_group;
}

// ---------------------------------------------------------------- 4. one triangulation per group
struct LocalTriangle {
  std::array<PointQ3, 3> p;      // front = group normal side (or the single input's own orientation)
  std::vector<int> covering;     // input triangles covering it, ascending
  std::vector<char> same_side;   // per covering input: its front is this triangle's front
  Rational area2;                // |(p1-p0)x(p2-p0)|^2, computed by the (parallel) triangulation
};

struct Projected {
  Rational u, v;
};
Projected project(const PointQ3& p, int axis) { return {coord(p, (axis + 1) % 3), coord(p, (axis + 2) % 3)}; }
/// Orientation of (a, b, c): interval filtered, exact when the filter cannot tell.
int orient2(const Projected& a, const Projected& b, const Projected& c) {
  {
    CGAL::Protect_FPU_rounding<true> protect;
    const IntervalQ au = interval(a.u), av = interval(a.v);
    const IntervalQ det = (interval(b.u) - au) * (interval(c.v) - av) - (interval(b.v) - av) * (interval(c.u) - au);
    if (det.inf() > 0) return 1;
    if (det.sup() < 0) return -1;
  }
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

/// q in the closed triangle t (t not degenerate).
bool in_closed(const std::array<Projected, 3>& t, const Projected& q) {
  const int o = orient2(t[0], t[1], t[2]);
  for (int e = 0; e < 3; ++e)
    if (orient2(t[static_cast<std::size_t>(e)], t[static_cast<std::size_t>((e + 1) % 3)], q) == -o) return false;
  return true;
}

std::vector<LocalTriangle> triangulate_group(const Group& g, const std::vector<InputTriangle>& inputs,
                                             const std::vector<Constraint>& constraints) {
  if (g.members.size() == 1) {
    const InputTriangle& in = inputs[static_cast<std::size_t>(g.members[0])];
    bool trivial = true;
    for (const Constraint& c : constraints)
      trivial = trivial && std::find(in.p.begin(), in.p.end(), c.a) != in.p.end() &&
                std::find(in.p.begin(), in.p.end(), c.b) != in.p.end();
    if (trivial) {
      const PointQ3 n = normal_of(in.p);
      return {LocalTriangle{in.p, {g.members[0]}, {1}, dot(n, n)}};
    }
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
  // A face lies inside a member or outside it (the member's edges are constraints): inside iff its three corners
  // are in the closed member. A single member covers every face (all constraints lie on it). Per vertex and
  // member, memoized: -1 unknown, 0 out, 1 in.
  std::vector<signed char> in_member(uv.size() * members.size(), -1);
  auto covers = [&](std::size_t m, int vertex) {
    if (members.size() == 1) return true;
    signed char& memo = in_member[static_cast<std::size_t>(vertex) * members.size() + m];
    if (memo < 0) memo = static_cast<signed char>(in_closed(members[m], uv[static_cast<std::size_t>(vertex)]));
    return memo == 1;
  };
  std::vector<LocalTriangle> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const int i0 = f->vertex(0)->info(), i1 = f->vertex(1)->info(), i2 = f->vertex(2)->info();
    LocalTriangle lt{{lifted[i0], lifted[i1], lifted[i2]}, {}, {}, {}};  // counter-clockwise in (u, v): front = normal
    for (std::size_t m = 0; m < members.size(); ++m)
      if (covers(m, i0) && covers(m, i1) && covers(m, i2)) {
        lt.covering.push_back(g.members[m]);
        lt.same_side.push_back(member_same[m]);
      }
    if (lt.covering.empty()) continue;
    const PointQ3 n = normal_of(lt.p);
    lt.area2 = dot(n, n);
    out.push_back(std::move(lt));
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
                     std::to_string(limits.max_triangles) + " (raise it with --max-triangles; see docs/limits.md)");
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
      t.area2 = lt.area2;
      b.triangles.push_back(std::move(t));
      b.source.push_back(lt.covering.front());
      b.outside_side.push_back(outside);
    }
  return b;
}

using IntervalVector = std::array<IntervalQ, 3>;
IntervalVector interval_vector(const PointQ3& p) { return {interval(p.x), interval(p.y), interval(p.z)}; }

/// The sign of det(a, b, c), given interval enclosures of a, b, c: by intervals when they decide it, else exact.
/// Call with the FPU rounding upward (CGAL::Protect_FPU_rounding).
int det3_sign(const PointQ3& a, const PointQ3& b, const PointQ3& c, const IntervalVector& ia,
              const IntervalVector& ib, const IntervalVector& ic) {
  const IntervalQ det = ia[0] * (ib[1] * ic[2] - ib[2] * ic[1]) + ia[1] * (ib[2] * ic[0] - ib[0] * ic[2]) +
                        ia[2] * (ib[0] * ic[1] - ib[1] * ic[0]);
  if (det.inf() > 0) return 1;
  if (det.sup() < 0) return -1;
  return sign(det3(a, b, c));
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
  CGAL::Protect_FPU_rounding<true> protect;  // for the interval filter of det3_sign
  std::vector<std::pair<int, PointQ3>> items;
  std::vector<IntervalVector> boxes;
  for (int t : edge->triangles) {
    items.emplace_back(t, third(t));
    boxes.push_back(interval_vector(items.back().second));
  }
  const IntervalVector dbox = interval_vector(d);
  const PointQ3 ref = items[0].second;
  auto half = [&](std::size_t i) {
    const int o = det3_sign(d, ref, items[i].second, dbox, boxes[0], boxes[i]);
    if (o != 0) return o > 0 ? 0 : 1;
    const PointQ3& r = items[i].second;
    return sign(dot(ref, r) * dd - dot(ref, d) * dot(r, d)) > 0 ? 0 : 1;
  };
  std::vector<int> halves;
  for (std::size_t i = 0; i < items.size(); ++i) halves.push_back(half(i));
  std::vector<int> order(items.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    if (halves[static_cast<std::size_t>(i)] != halves[static_cast<std::size_t>(j)])
      return halves[static_cast<std::size_t>(i)] < halves[static_cast<std::size_t>(j)];
    if (i == j) return false;
    const std::size_t a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(j);
    const int s = det3_sign(d, items[a].second, items[b].second, dbox, boxes[a], boxes[b]);
    if (s == 0) throw std::logic_error("arrangement3: two triangles on one half-plane around an edge");
    return s > 0;
  });
  std::vector<int> sorted;
  for (int i : order) sorted.push_back(items[static_cast<std::size_t>(i)].first);
  edge->triangles = std::move(sorted);
}

std::vector<ArrEdge3> build_edges(const std::vector<PointQ3>& vertices, const std::vector<ArrTriangle3>& triangles,
                                  int threads) {
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
    edges.push_back(std::move(e));
  }
  std::vector<int> shared;  // edges of more than two triangles: sorted radially, each on its own
  for (int e = 0; e < static_cast<int>(edges.size()); ++e)
    if (edges[static_cast<std::size_t>(e)].triangles.size() > 2) shared.push_back(e);
  parallel_for(static_cast<int>(shared.size()), threads, [&](int k, int) {
    sort_radially(vertices, triangles, &edges[static_cast<std::size_t>(shared[static_cast<std::size_t>(k)])]);
  });
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


/// A triangle a ray meets at origin + at * dir.
struct RayCrossing {
  Rational at;
  int triangle = -1;
  bool interior = false;  // the hit is inside the triangle's interior
  bool front = false;     // the origin is on the triangle's front side
};

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
/// precomputed. A ray's candidates come from CGAL's AABB tree over the triangles (Epeck: its box and ray-triangle
/// tests are exact predicates, so the candidates are exactly the triangles the closed ray meets), in
/// O(log triangles + candidates) for a typical query. Queries take the soup the index was built from. The tree's
/// lazy-exact triangles are made exact on construction, so concurrent const queries only read them.
class TriangleIndex {
 public:
  TriangleIndex(const TriangleIndex&) = delete;
  TriangleIndex& operator=(const TriangleIndex&) = delete;
  explicit TriangleIndex(const TriangleSoup& soup) {
    std::vector<P3> corners;
    corners.reserve(soup.vertices.size());
    for (const PointQ3& v : soup.vertices) corners.push_back(to_k(v));
    shapes_.reserve(soup.triangles.size());
    planes_.reserve(soup.triangles.size());
    for (int t = 0; t < static_cast<int>(soup.triangles.size()); ++t) {
      const auto& v = soup.triangles[static_cast<std::size_t>(t)].vertices;
      shapes_.emplace_back(corners[static_cast<std::size_t>(v[0])], corners[static_cast<std::size_t>(v[1])],
                           corners[static_cast<std::size_t>(v[2])]);
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
      pl.n_box = interval_vector(pl.n);
      pl.d_box = interval(pl.d);
      planes_.push_back(std::move(pl));
    }
    // The tree's boxes and splits from the conservative boxes above (CGAL's default build would compare the lazy
    // triangles' corners, falling back to exact numbers on every tie of shared corners): a node's box is the union
    // of its triangles' boxes, so it holds them; the split (by box centres) only shapes the tree.
    tree_.insert(shapes_.cbegin(), shapes_.cend());
    auto index_of = [this](const Primitive& p) { return static_cast<std::size_t>(p.id() - shapes_.cbegin()); };
    auto box = [this, index_of](const Primitive& p) {
      const Plane& pl = planes_[index_of(p)];
      return CGAL::Bbox_3(pl.lo[0], pl.lo[1], pl.lo[2], pl.hi[0], pl.hi[1], pl.hi[2]);
    };
    using PrimitiveIterator = std::vector<Primitive>::iterator;
    tree_.custom_build(
        [box](PrimitiveIterator first, PrimitiveIterator beyond) {
          CGAL::Bbox_3 b = box(*first);
          for (++first; first != beyond; ++first) b += box(*first);
          return b;
        },
        [this, index_of](PrimitiveIterator first, PrimitiveIterator beyond, const CGAL::Bbox_3& b) {
          int axis = 0;
          for (int a = 1; a < 3; ++a)
            if (b.max(a) - b.min(a) > b.max(axis) - b.min(axis)) axis = a;
          auto centre = [&](const Primitive& p) {
            const Plane& pl = planes_[index_of(p)];
            return pl.lo[axis] + pl.hi[axis];
          };
          std::nth_element(first, first + (beyond - first) / 2, beyond,
                           [&](const Primitive& x, const Primitive& y) { return centre(x) < centre(y); });
        });
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

  /// Every triangle met by origin + s * dir with s > 0, sorted by s (ties in triangle order); nullopt when the ray
  /// runs inside a triangle's plane (try another direction).
  std::optional<std::vector<RayCrossing>> all_hits(const TriangleSoup& soup, const PointQ3& origin,
                                                   const PointQ3& dir) const {
    return hits_among(soup, origin, dir, met_by(origin, dir));
  }

  /// The triangles the closed ray origin + s * dir, s >= 0, meets (every triangle holding the origin among them),
  /// ascending.
  std::vector<int> met_by(const PointQ3& origin, const PointQ3& dir) const {
    const K::Ray_3 ray(to_k(origin), K::Vector_3(K::FT(dir.x), K::FT(dir.y), K::FT(dir.z)));
    std::vector<Primitive::Id> ids;
    tree_.all_intersected_primitives(ray, std::back_inserter(ids));
    std::vector<int> out;
    out.reserve(ids.size());
    for (const auto& id : ids) out.push_back(static_cast<int>(id - shapes_.cbegin()));
    std::sort(out.begin(), out.end());
    return out;
  }

  /// all_hits restricted to `candidates` (ascending), which must hold every triangle the ray meets.
  std::optional<std::vector<RayCrossing>> hits_among(const TriangleSoup& soup, const PointQ3& origin,
                                                     const PointQ3& dir, const std::vector<int>& candidates) const {
    std::vector<RayCrossing> hits;
    for (int t : candidates) {
      Crossing c = crossing(soup, origin, dir, t);
      if (c.kind == Crossing::InPlane) return std::nullopt;
      if (c.kind == Crossing::Hit) hits.push_back(std::move(c.hit));
    }
    std::sort(hits.begin(), hits.end(), [](const RayCrossing& x, const RayCrossing& y) {
      const int c = cmp(x.at, y.at);
      return c != 0 ? c < 0 : x.triangle < y.triangle;
    });
    return hits;
  }

  /// First triangle met by origin + s * dir, s > 0; not clean when that hit is on an edge or vertex, when two
  /// triangles are met at once, or when the ray runs inside a triangle's plane.
  RayHit first_hit(const TriangleSoup& soup, const PointQ3& origin, const PointQ3& dir,
                   const std::vector<int>& candidates) const {
    // The same answer as the front of hits_among, computing few crossings exactly: candidates are visited by an
    // interval lower bound of their ray parameter (unbounded when the ray may be parallel to the plane, so every
    // triangle whose plane may contain the ray is visited), and the visit stops at the first bound beyond the upper
    // bound of the best crossing found: later ones lie strictly beyond it (no tie).
    struct Estimate {
      double lo;
      int triangle;
    };
    std::vector<Estimate> order;
    {
      CGAL::Protect_FPU_rounding<true> protect;
      const IntervalVector o = interval_vector(origin), d = interval_vector(dir);
      for (int t : candidates) {
        const Plane& pl = planes_[static_cast<std::size_t>(t)];
        const IntervalQ nd = pl.n_box[0] * d[0] + pl.n_box[1] * d[1] + pl.n_box[2] * d[2];
        if (nd.inf() <= 0 && nd.sup() >= 0) {
          order.push_back({-std::numeric_limits<double>::infinity(), t});
          continue;
        }
        const IntervalQ at = (pl.d_box - (pl.n_box[0] * o[0] + pl.n_box[1] * o[1] + pl.n_box[2] * o[2])) / nd;
        if (at.sup() > 0) order.push_back({at.inf(), t});  // otherwise at <= 0: no crossing
      }
    }
    std::sort(order.begin(), order.end(), [](const Estimate& x, const Estimate& y) {
      return x.lo != y.lo ? x.lo < y.lo : x.triangle < y.triangle;
    });
    std::optional<RayCrossing> best;
    double best_hi = 0;
    bool tie = false;
    for (const Estimate& e : order) {
      if (best && e.lo > best_hi) break;
      Crossing c = crossing(soup, origin, dir, e.triangle);
      if (c.kind == Crossing::InPlane) return {};
      if (c.kind != Crossing::Hit) continue;
      const int k = best ? cmp(c.hit.at, best->at) : -1;
      if (k == 0) {
        tie = true;
        if (c.hit.triangle < best->triangle) best = std::move(c.hit);
      } else if (k < 0) {
        tie = false;
        best = std::move(c.hit);
        best_hi = CGAL::to_interval(best->at).second;
      }
    }
    if (!best) return {};
    return {best->triangle, best->front, best->interior && !tie};
  }

 private:
  struct Plane {
    PointQ3 n;
    Rational d;
    int axis = 0;
    double lo[3], hi[3];    // the triangle's box, rounded outward
    IntervalVector n_box;   // enclosures of n and d
    IntervalQ d_box;
  };

  /// How a ray meets triangle t, exactly.
  struct Crossing {
    enum Kind { None, Hit, InPlane } kind = None;  // InPlane: the ray runs inside t's plane
    RayCrossing hit;                               // when Hit (at > 0, on the closed triangle)
  };
  Crossing crossing(const TriangleSoup& soup, const PointQ3& origin, const PointQ3& dir, int t) const {
    const Plane& pl = planes_[static_cast<std::size_t>(t)];
    const Rational off = pl.d - dot(pl.n, origin);  // n.(origin + s dir) = d  <=>  s * n.dir = off
    const Rational nd = dot(pl.n, dir);
    if (nd == 0) return {off == 0 ? Crossing::InPlane : Crossing::None, {}};
    Rational at = off / nd;
    if (at <= 0) return {};
    const OnTriangle where = in_plane(soup, t, origin + scaled(dir, at));
    if (where.where < 0) return {};
    // origin - hit = -at dir: on the front iff n.dir < 0 iff off < 0
    return {Crossing::Hit, {std::move(at), t, where.where == 0, sign(off) < 0}};
  }

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

  using Shapes = std::vector<K::Triangle_3>;
  using Primitive = CGAL::AABB_triangle_primitive<K, Shapes::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

  Shapes shapes_;  // the triangles as CGAL sees them; the tree points into it (never resized after construction)
  Tree tree_;
  std::vector<Plane> planes_;
};

/// Deterministic ray directions with a positive x component (the first is +x; the others along no axis).
PointQ3 ray_direction(int attempt) {
  if (attempt == 0) return {1, 0, 0};
  return {1, Rational(2 * attempt + 1, 7 * attempt + 3) - Rational(1, 2), Rational(3 * attempt + 2, 5 * attempt + 11) - Rational(1, 3)};
}

struct CellBuild {
  std::vector<int> cell_of_side;  // per side id: cell or -1 (outside the domain)
  int cells = 0;
};

/// The pair of sides a ray from a floating shell joins: the side facing away from the ray's origin at its last
/// crossing of the shell (or of the origin's own triangle when it crosses none), and the side facing the origin at
/// the next crossing, of another shell. The open segment between them meets no triangle and lies outside the shell
/// (beyond its last crossing), so both sides bound one cell: the one around the shell. Nullopt when either
/// crossing is not clean (on an edge or vertex, or two triangles at once): try another ray.
std::optional<std::pair<int, int>> shell_join(const std::vector<RayCrossing>& hits, const Components& shell, int k,
                                              int origin_side) {
  int last = -1;  // the last crossing of shell k
  for (int i = 0; i < static_cast<int>(hits.size()); ++i)
    if (shell.of[static_cast<std::size_t>(hits[static_cast<std::size_t>(i)].triangle)] == k) last = i;
  auto clean = [&hits](int i) {
    const RayCrossing& h = hits[static_cast<std::size_t>(i)];
    const bool tie = (i > 0 && hits[static_cast<std::size_t>(i - 1)].at == h.at) ||
                     (i + 1 < static_cast<int>(hits.size()) && hits[static_cast<std::size_t>(i + 1)].at == h.at);
    return h.interior && !tie;
  };
  const int next = last + 1;
  if (next >= static_cast<int>(hits.size()) || (last >= 0 && !clean(last)) || !clean(next)) return std::nullopt;
  const int away = last < 0 ? origin_side
                            : side_id(hits[static_cast<std::size_t>(last)].triangle, !hits[static_cast<std::size_t>(last)].front);
  const RayCrossing& h = hits[static_cast<std::size_t>(next)];
  return std::make_pair(away, side_id(h.triangle, h.front));
}

/// Joins every floating shell (a set of triangles connected across edges, none on the box) with the cell around
/// it, found by exact rays from the centroids of its triangles (see shell_join). A shell touching another one or
/// the box only at a vertex is floating too, and is nested the same way.
void nest_shells(const std::vector<PointQ3>& vertices, const std::vector<ArrTriangle3>& triangles,
                 const std::vector<ArrEdge3>& edges, DisjointSets& sides) {
  const int n = static_cast<int>(triangles.size());
  DisjointSets shells(static_cast<std::size_t>(n));
  for (const ArrEdge3& e : edges)
    for (int t : e.triangles) shells.union_set(e.triangles[0], t);
  const Components shell = components_of(shells, static_cast<std::size_t>(n));
  std::vector<char> grounded(static_cast<std::size_t>(shell.count), 0);
  for (int t = 0; t < n; ++t)
    if (triangles[static_cast<std::size_t>(t)].on_box) grounded[static_cast<std::size_t>(shell.of[static_cast<std::size_t>(t)])] = 1;
  if (std::all_of(grounded.begin(), grounded.end(), [](char g) { return g != 0; })) return;
  const auto members = shell.members();
  const TriangleSoup soup{vertices, triangles};
  const TriangleIndex index(soup);
  std::vector<std::pair<int, int>> joins;
  for (int k = 0; k < shell.count; ++k) {
    if (grounded[static_cast<std::size_t>(k)]) continue;
    const auto& own = members[static_cast<std::size_t>(k)];
    std::optional<std::pair<int, int>> join;
    for (int attempt = 0; attempt < 64 && !join; ++attempt) {
      // the centroid of one of the shell's triangles: strictly inside the domain (no floating triangle is on the box)
      const int t = own[static_cast<std::size_t>(attempt / 8) * 7919 % own.size()];
      const std::array<PointQ3, 3> p = soup.corners(t);
      const PointQ3 origin = scaled(p[0] + p[1] + p[2], Rational(1, 3));
      const PointQ3 dir = ray_direction(1 + attempt % 8);  // along no axis (see locate)
      const auto hits = index.all_hits(soup, origin, dir);
      const int facing = sign(dot(normal_of(p), dir));  // the ray leaves t on its front iff facing > 0
      if (!hits || facing == 0) continue;
      join = shell_join(*hits, shell, k, side_id(t, facing > 0));
    }
    if (!join) throw std::logic_error("arrangement3: no clean ray out of a floating shell");
    joins.push_back(*join);
  }
  for (const auto& j : joins) sides.union_set(j.first, j.second);
}

CellBuild find_cells(const Built& b, const std::vector<ArrEdge3>& edges) {
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
  nest_shells(b.vertices, b.triangles, edges, sides);
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

/// Throws when `cells` (the count, or with `at_least` a lower bound on it) is over a limit.
void check_cell_limits(long cells, long halfspaces, const ArrangementLimits& limits, bool at_least = false) {
  const std::string has = "the arrangement has " + std::string(at_least ? "at least " : "") + std::to_string(cells);
  if (limits.max_cells > 0 && cells > limits.max_cells)
    throw InputError(has + " cells, over the limit of " + std::to_string(limits.max_cells) +
                     " (raise it with --max-cells; see docs/limits.md)");
  if (limits.max_side_entries > 0 && cells * halfspaces > limits.max_side_entries)
    throw InputError(has + " cells over " + std::to_string(halfspaces) +
                     " halfspaces: its side table (cells x halfspaces) exceeds " +
                     std::to_string(limits.max_side_entries) +
                     " entries, the limit (raise it with --max-side-table; see docs/limits.md)");
}

/// The most pairs and the most triples of planes cells_at_least examines (a few seconds at most).
constexpr long kPlanePairBudget = 2'000'000;
constexpr long kPlaneTripleBudget = 2'000'000;

/// The axis of `v`'s first non-zero coordinate (v non-zero).
int leading_axis(const PointQ3& v) { return v.x != 0 ? 0 : (v.y != 0 ? 1 : 2); }

/// The planes' flats that meet the open domain box, counted without repeats until the count passes `enough`.
class FlatCounter {
 public:
  FlatCounter(const Box3& box, long enough) : box_(box), enough_(enough) {}
  bool enough() const { return count() > enough_; }
  long count() const { return static_cast<long>(planes_.size() + lines_.size() + points_.size()); }

  /// The plane {x : normal . x = offset}.
  void plane(const PointQ3& normal, const Rational& offset) {
    Rational lowest = 0, highest = 0;  // of normal . x over the box
    for (int a = 0; a < 3; ++a) {
      const Rational& n = coord(normal, a);
      lowest += n * (n > 0 ? coord(box_.min, a) : coord(box_.max, a));
      highest += n * (n > 0 ? coord(box_.max, a) : coord(box_.min, a));
    }
    if (!(lowest < offset && offset < highest)) return;
    const Rational scale = 1 / coord(normal, leading_axis(normal));  // canonical: a leading 1
    planes_.insert({scaled(normal, scale), offset * scale});
  }

  /// The line through `point` along `direction` (non-zero).
  void line(const PointQ3& point, const PointQ3& direction) {
    // where it is inside the box: the open interval (after, before) of its parameter
    std::optional<Rational> after, before;
    for (int a = 0; a < 3; ++a) {
      const Rational& d = coord(direction, a);
      const Rational& p = coord(point, a);
      if (d == 0) {
        if (!(coord(box_.min, a) < p && p < coord(box_.max, a))) return;
        continue;
      }
      Rational t1 = (coord(box_.min, a) - p) / d, t2 = (coord(box_.max, a) - p) / d;
      if (t2 < t1) std::swap(t1, t2);
      if (!after || *after < t1) after = t1;
      if (!before || t2 < *before) before = t2;
    }
    if (!(*after < *before)) return;
    // canonical: the direction with a leading one, the point where that coordinate is zero
    const int lead = leading_axis(direction);
    const PointQ3 unit = scaled(direction, 1 / coord(direction, lead));
    lines_.insert({unit, point - scaled(unit, coord(point, lead))});
  }

  /// The point `p`.
  void point(const PointQ3& p) {
    if (box_.min.x < p.x && p.x < box_.max.x && box_.min.y < p.y && p.y < box_.max.y && box_.min.z < p.z &&
        p.z < box_.max.z)
      points_.insert(p);
  }

 private:
  struct PairHash {
    std::size_t operator()(const std::pair<PointQ3, PointQ3>& k) const {
      return PointHash()(k.first) * 31u ^ PointHash()(k.second);
    }
  };
  const Box3& box_;
  long enough_;
  std::unordered_set<std::pair<PointQ3, Rational>, PlaneKeyHash> planes_;  ///< normal, offset
  std::unordered_set<std::pair<PointQ3, PointQ3>, PairHash> lines_;          ///< direction, point
  std::unordered_set<PointQ3, PointHash> points_;
};

/// A lower bound on the cells, known before any triangle is cut: 1 + the distinct planes, lines where two planes
/// meet, and points where three meet (normals independent) that meet the open domain box (proofs/arrangement3.md,
/// Claim 2.3: each adds at least one cell when the planes are inserted one by one, and every other surface only
/// splits cells further). Counting stops once the bound passes `enough`; past kPlanePairBudget pairs no more lines
/// are counted, past kPlaneTripleBudget triples no more points: then it is the bound found so far (the check after
/// the refinement still holds). Pairs and triples are visited by their last plane, so that a budget cut counts a
/// prefix of the planes in full.
long cells_at_least(const Scene3& scene, long enough) {
  std::vector<const Halfspace3*> planes;
  for (const Halfspace3& h : scene.halfspaces)
    if (h.kind == HalfspaceKind3::Plane) planes.push_back(&h);
  FlatCounter flats(scene.domain, enough - 1);
  for (const Halfspace3* p : planes) flats.plane(p->normal, p->offset);
  // Lines first: they are fewer to find (a star of planes through one point has its cells on them, not on points).
  long pairs = 0;
  for (std::size_t k = 1; k < planes.size() && !flats.enough() && pairs < kPlanePairBudget; ++k)
    for (std::size_t j = 0; j < k && !flats.enough() && pairs < kPlanePairBudget; ++j, ++pairs) {
      const PointQ3 &nj = planes[j]->normal, &nk = planes[k]->normal;
      const PointQ3 jk = cross(nj, nk);
      if (jk.x == 0 && jk.y == 0 && jk.z == 0) continue;  // parallel: no line
      // a point of the line: its corner with the plane through the origin normal to it
      flats.line(scaled(scaled(cross(nk, jk), planes[j]->offset) + scaled(cross(jk, nj), planes[k]->offset),
                        1 / dot(jk, jk)),
                 jk);
    }
  long triples = 0;
  for (std::size_t k = 2; k < planes.size() && !flats.enough() && triples < kPlaneTripleBudget; ++k)
    for (std::size_t j = 1; j < k && !flats.enough() && triples < kPlaneTripleBudget; ++j) {
      const PointQ3 &nj = planes[j]->normal, &nk = planes[k]->normal;
      const PointQ3 jk = cross(nj, nk);
      if (jk.x == 0 && jk.y == 0 && jk.z == 0) continue;  // parallel: no corner
      for (std::size_t i = 0; i < j && !flats.enough() && triples < kPlaneTripleBudget; ++i, ++triples) {
        const PointQ3& ni = planes[i]->normal;
        const Rational det = dot(ni, jk);
        if (det == 0) continue;
        // Cramer: (d_i (n_j x n_k) + d_j (n_k x n_i) + d_k (n_i x n_j)) / (n_i . (n_j x n_k))
        flats.point(scaled(scaled(jk, planes[i]->offset) + scaled(cross(nk, ni), planes[j]->offset) +
                               scaled(cross(ni, nj), planes[k]->offset),
                           1 / det));
      }
    }
  return 1 + flats.count();
}

/// Refuses, before the refinement, a scene whose planes alone make more cells than the limits allow, or with a
/// surface of more triangles than the arrangement may have: a surface's triangles meet only at corners, and the
/// refinement cuts each into one or more, so no fewer refined triangles carry it.
void check_limits_before_refinement(const Scene3& scene, const ArrangementLimits& limits) {
  if (limits.max_triangles > 0)
    for (std::size_t h = 0; h < scene.halfspaces.size(); ++h) {
      const long triangles = static_cast<long>(scene.halfspaces[h].surface.triangles.size());
      if (triangles > limits.max_triangles)
        throw InputError(halfspace_label(scene, static_cast<int>(h)) + " has " + std::to_string(triangles) +
                         " triangles, so the arrangement has at least as many, over the limit of " +
                         std::to_string(limits.max_triangles) + " (raise it with --max-triangles; see docs/limits.md)");
    }
  const long halfspaces = std::max<long>(1, static_cast<long>(scene.halfspaces.size()));
  long enough = std::numeric_limits<long>::max();
  if (limits.max_cells > 0) enough = limits.max_cells;
  if (limits.max_side_entries > 0) enough = std::min(enough, limits.max_side_entries / halfspaces);
  if (enough == std::numeric_limits<long>::max()) return;
  check_cell_limits(cells_at_least(scene, enough), halfspaces, limits, /*at_least=*/true);
}

/// Refuses, before the refinement, an arrangement sure to have more refined triangles than the limit allows. In one
/// plane the refinement cuts each input triangle into one or more, and one surface's triangles in one plane do not
/// overlap (else the merge refuses the surface as intersecting itself), so the plane holds at least as many refined
/// triangles as the surface (or the domain box) with most triangles in it; distinct planes share none. (Summing
/// over surfaces would not be a bound: coincident surfaces share their refined triangles.)
void check_triangles_at_least(const std::vector<InputTriangle>& inputs, const std::vector<Group>& groups,
                              const ArrangementLimits& limits) {
  if (limits.max_triangles <= 0) return;
  long at_least = 0;
  for (const Group& g : groups) {
    // members ascend, and input_triangles lists each surface's triangles together: one run per surface
    long most = 0, run = 0;
    for (std::size_t k = 0; k < g.members.size(); ++k) {
      const int h = inputs[static_cast<std::size_t>(g.members[k])].halfspace;
      run = k > 0 && inputs[static_cast<std::size_t>(g.members[k - 1])].halfspace == h ? run + 1 : 1;
      most = std::max(most, run);
    }
    at_least += most;
  }
  if (at_least > limits.max_triangles)
    throw InputError("the arrangement has at least " + std::to_string(at_least) + " triangles, over the limit of " +
                     std::to_string(limits.max_triangles) + " (raise it with --max-triangles; see docs/limits.md)");
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

/// The least parameter lambda in (0, 1] at which s + lambda * dir (ending at e = s + dir; dd = dir . dir) meets
/// the closed triangle p, or nullopt when it meets it nowhere there. A segment inside the triangle's plane is
/// handed to CGAL's exact Segment_3 x Triangle_3.
std::optional<Rational> segment_meets(const std::array<PointQ3, 3>& p, const PointQ3& s, const PointQ3& dir,
                                      const PointQ3& e, const Rational& dd) {
  {  // interval filter: both ends strictly on one side of the triangle's plane
    CGAL::Protect_FPU_rounding<true> protect;
    const IntervalVector a = interval_vector(p[0]), b = interval_vector(p[1]), c = interval_vector(p[2]);
    const IntervalVector is = interval_vector(s), ie = interval_vector(e);
    IntervalVector u, w, fs_v, fe_v;
    for (std::size_t k = 0; k < 3; ++k) {
      u[k] = b[k] - a[k];
      w[k] = c[k] - a[k];
      fs_v[k] = is[k] - a[k];
      fe_v[k] = ie[k] - a[k];
    }
    const IntervalQ n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const IntervalQ fs = n[0] * fs_v[0] + n[1] * fs_v[1] + n[2] * fs_v[2];
    const IntervalQ fe = n[0] * fe_v[0] + n[1] * fe_v[1] + n[2] * fe_v[2];
    if ((fs.inf() > 0 && fe.inf() > 0) || (fs.sup() < 0 && fe.sup() < 0)) return std::nullopt;
  }
  const PointQ3 n = normal_of(p);
  const Rational fs = dot(n, s - p[0]), fe = dot(n, e - p[0]);
  if (sign(fs) == 0 && sign(fe) == 0) {
    const auto result = CGAL::intersection(K::Segment_3(to_k(s), to_k(e)), K::Triangle_3(to_k(p[0]), to_k(p[1]), to_k(p[2])));
    if (!result) return std::nullopt;
    std::optional<Rational> least;
    auto consider = [&](const P3& q) {
      const Rational at = dot(to_q(q) - s, dir) / dd;
      if (at > 0 && (!least || at < *least)) least = at;
    };
    if (const P3* q = boost::get<P3>(&*result)) consider(*q);
    if (const K::Segment_3* g = boost::get<K::Segment_3>(&*result)) {
      consider(g->source());
      consider(g->target());
    }
    return least;
  }
  if (sign(fs) * sign(fe) > 0) return std::nullopt;
  const Rational at = fs / (fs - fe);
  const PointQ3 q = s + scaled(dir, at);
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (abs(coord(n, a)) > abs(coord(n, axis))) axis = a;
  const std::array<Projected, 3> tp = {project(p[0], axis), project(p[1], axis), project(p[2], axis)};
  if (!in_closed(tp, project(q, axis))) return std::nullopt;
  return at;
}

/// An exact point strictly inside each cell: from the centroid of the cell's largest boundary triangle, along
/// its normal into the cell, half way to the first triangle met (or to the end of a short probe segment).
std::vector<PointQ3> interior_points(const std::vector<PointQ3>& vertices, const std::vector<ArrTriangle3>& triangles,
                                     int cells, int threads) {
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
  parallel_for(cells, threads, [&](int c, int) {
    auto& cand = candidates[static_cast<std::size_t>(c)];
    std::sort(cand.begin(), cand.end());
    const PointQ3& s = start[static_cast<std::size_t>(c)];
    const PointQ3 dir = end[static_cast<std::size_t>(c)] - s;
    const Rational dd = dot(dir, dir);
    Rational t_min(1);
    for (int t : cand) {
      if (t == best[static_cast<std::size_t>(c)]) continue;
      const auto& v = triangles[static_cast<std::size_t>(t)].vertices;
      const std::array<PointQ3, 3> p = {vertices[static_cast<std::size_t>(v[0])], vertices[static_cast<std::size_t>(v[1])],
                                        vertices[static_cast<std::size_t>(v[2])]};
      if (const std::optional<Rational> at = segment_meets(p, s, dir, end[static_cast<std::size_t>(c)], dd))
        if (*at > 0 && *at < t_min) t_min = *at;
    }
    out[static_cast<std::size_t>(c)] = s + scaled(dir, t_min / 2);
  });
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
  std::vector<std::array<std::pair<double, double>, 3>> box(vertices.size());  // per vertex: interval per axis
  if (!scene.samples.empty())
    for (std::size_t v = 0; v < vertices.size(); ++v)
      for (int a = 0; a < 3; ++a) box[v][static_cast<std::size_t>(a)] = CGAL::to_interval(coord(vertices[v], a));
  auto may_hold = [&](const std::array<int, 3>& v, const std::array<std::pair<double, double>, 3>& q) {
    for (std::size_t a = 0; a < 3; ++a) {
      double lo = box[static_cast<std::size_t>(v[0])][a].first, hi = box[static_cast<std::size_t>(v[0])][a].second;
      for (int k = 1; k < 3; ++k) {
        lo = std::min(lo, box[static_cast<std::size_t>(v[static_cast<std::size_t>(k)])][a].first);
        hi = std::max(hi, box[static_cast<std::size_t>(v[static_cast<std::size_t>(k)])][a].second);
      }
      if (q[a].second < lo || q[a].first > hi) return false;
    }
    return true;
  };
  std::vector<int> out;
  for (std::size_t k = 0; k < scene.samples.size(); ++k) {
    const Sample3& sample = scene.samples[k];
    const PointQ3& q = sample.location;
    const std::string label = "samples[" + std::to_string(k) + "] (of " + halfspace_label(scene, sample.halfspace) + ")";
    const std::array<std::pair<double, double>, 3> q_box = {CGAL::to_interval(q.x), CGAL::to_interval(q.y),
                                                            CGAL::to_interval(q.z)};
    int found = -1;
    bool ok = true;
    for (int t : by_halfspace.at(static_cast<std::size_t>(sample.halfspace))) {
      const auto& v = triangles[static_cast<std::size_t>(t)].vertices;
      if (!may_hold(v, q_box)) continue;
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
      std::array<int, 3> side{};
      for (int e = 0; e < 3; ++e) side[static_cast<std::size_t>(e)] = orient2(tp[e], tp[(e + 1) % 3], qp) * o;
      // Outside the triangle: its edges say nothing about q, even one whose line passes through q.
      if (std::any_of(side.begin(), side.end(), [](int s) { return s < 0; })) continue;
      for (int e = 0; e < 3; ++e)
        if (side[static_cast<std::size_t>(e)] == 0) ok = ok && patch_interior(edge_of(v[e], v[(e + 1) % 3]));
      if (triangles[static_cast<std::size_t>(t)].on_box)
        throw InputError(label + ": lies on the domain box, where its halfspace has no patch");
      if (found < 0) found = t;
    }
    if (found < 0) throw InputError(label + ": not on its halfspace's boundary inside the domain");
    if (!ok) throw InputError(label + ": lies on an edge where boundaries meet; move it into a patch");
    out.push_back(found);
  }
  return out;
}

}  // namespace

void Arrangement3Timings::add(const std::string& name, double seconds) {
  for (auto& [phase, total] : phases)
    if (phase == name) {
      total += seconds;
      return;
    }
  phases.emplace_back(name, seconds);
}

/// What locate needs beyond the public data: the triangles' planes and boxes, built on the first locate (copies of
/// an Arrangement3 share it; the triangles never change after build).
struct Arrangement3::Impl {
  mutable std::once_flag built;                  // the index is built on the first locate
  mutable std::unique_ptr<const TriangleIndex> index;
};

Arrangement3 Arrangement3::build(const Scene3& scene, const ArrangementLimits& limits,
                                 const Arrangement3Options& options) {
  const int threads = worker_count(options.threads);
  PhaseClock clock(options.timings);
  check_limits_before_refinement(scene, limits);
  clock.lap("lower bounds on the cells and triangles");
  std::vector<InputTriangle> inputs = input_triangles(scene);
  const std::vector<Group> groups = group_by_plane(inputs);
  check_triangles_at_least(inputs, groups, limits);
  clock.lap("input triangles and planes");
  const std::vector<std::pair<int, int>> pairs = candidate_pairs(inputs);
  clock.lap("candidate pairs");
  const std::vector<std::vector<Constraint>> constraints =
      intersect_pairs(scene, inputs, groups, pairs, threads);
  clock.lap("pair intersections");
  std::vector<std::vector<LocalTriangle>> local(groups.size());
  // largest groups first, so that no large one is left to a single thread at the end
  std::vector<int> by_size(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) by_size[g] = static_cast<int>(g);
  auto size_of = [&](int g) { return groups[static_cast<std::size_t>(g)].members.size() + constraints[static_cast<std::size_t>(g)].size(); };
  std::stable_sort(by_size.begin(), by_size.end(), [&](int x, int y) { return size_of(x) > size_of(y); });
  parallel_for(static_cast<int>(groups.size()), threads, [&](int k, int) {
    const std::size_t g = static_cast<std::size_t>(by_size[static_cast<std::size_t>(k)]);
    local[g] = triangulate_group(groups[g], inputs, constraints[g]);
  });
  clock.lap("triangulations");
  Built b = merge_triangles(scene, inputs, local, limits);
  local.clear();
  clock.lap("vertex merge");
  Arrangement3 arr;
  arr.domain_ = scene.domain;
  arr.halfspace_count_ = static_cast<int>(scene.halfspaces.size());
  arr.edges_ = build_edges(b.vertices, b.triangles, threads);
  clock.lap("edges and radial order");
  const CellBuild cb = find_cells(b, arr.edges_);
  check_cell_limits(cb.cells, arr.halfspace_count_, limits);
  clock.lap("cells and shells");
  for (int t = 0; t < static_cast<int>(b.triangles.size()); ++t) {
    b.triangles[static_cast<std::size_t>(t)].front_cell = cb.cell_of_side[static_cast<std::size_t>(side_id(t, true))];
    b.triangles[static_cast<std::size_t>(t)].back_cell = cb.cell_of_side[static_cast<std::size_t>(side_id(t, false))];
  }
  const auto inside = cell_sides(scene, b.triangles, cb.cells);
  clock.lap("sides");
  const auto witness = interior_points(b.vertices, b.triangles, cb.cells, threads);
  clock.lap("interior points");
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
  clock.lap("volumes and witness checks");
  arr.sample_triangles_ = place_samples(scene, b.vertices, b.triangles, arr.edges_);
  clock.lap("samples");
  arr.vertices_ = std::move(b.vertices);
  arr.triangles_ = std::move(b.triangles);
  arr.impl_ = std::make_shared<const Impl>();
  return arr;
}

PointLocation3 Arrangement3::locate(const PointQ3& p) const {
  if (!domain_.contains(p)) return {PointLocation3::Outside, -1};
  const TriangleSoup soup{vertices_, triangles_};
  std::call_once(impl_->built, [&] { impl_->index = std::make_unique<const TriangleIndex>(soup); });
  const TriangleIndex& index = *impl_->index;
  // every triangle holding p meets the closed ray from p: the lowest one is among the first ray's candidates
  // rays along no axis: an axis ray leaves the origin's other coordinates unchanged, and CGAL's interval filter of
  // the ray-box test cannot order an inexact coordinate against itself (every box would be decided exactly)
  std::vector<int> candidates = index.met_by(p, ray_direction(1));
  for (int t : candidates) {
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
  for (int attempt = 1; attempt <= 64; ++attempt) {
    if (attempt > 1) candidates = index.met_by(p, ray_direction(attempt));
    const RayHit hit = index.first_hit(soup, p, ray_direction(attempt), candidates);
    if (!hit.clean) continue;
    const ArrTriangle3& t = triangles_[static_cast<std::size_t>(hit.triangle)];
    return {PointLocation3::Cell, hit.front ? t.front_cell : t.back_cell};
  }
  throw std::logic_error("Arrangement3::locate: no clean ray");
}

}  // namespace hsx
