// The only translation unit that instantiates CGAL's 2D arrangement (it takes ~20 s and ~1.2 GB to compile: keep
// CGAL out of every other file). Everything it hands out is plain data (geometry/arrangement2.hpp).
#include <hsx/geometry/arrangement2.hpp>
#include "geometry/components.hpp"
#include "geometry/planar_measures.hpp"
#include "kernel/interval_nt.hpp"

#include <CGAL/Arr_circle_segment_traits_2.h>
#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_observer.h>
#include <CGAL/Arr_walk_along_line_point_location.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Cartesian.h>

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <new>
#include <set>
#include <sstream>

namespace hsx {
namespace {

using NT = mpq_class;
using Kernel = CGAL::Cartesian<NT>;
using BaseTraits = CGAL::Arr_circle_segment_traits_2<Kernel>;
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<BaseTraits, int>;
/// Every vertex, halfedge and face carries its index in Arrangement2's plain data (the face outside the domain
/// -1; both halfedges of an edge the edge's index), set once the insertion is done.
using Dcel = CGAL::Arr_extended_dcel<Traits, int, int, int>;
using CgalArrangement = CGAL::Arrangement_2<Traits, Dcel>;
using CoordNT = BaseTraits::CoordNT;
using CgalPoint = BaseTraits::Point_2;
using BaseCurve = BaseTraits::Curve_2;
using Curve = Traits::Curve_2;
using XCurve = Traits::X_monotone_curve_2;
using Halfedge = CgalArrangement::Halfedge_const_handle;
using FaceHandle = CgalArrangement::Face_const_handle;
using VertexHandle = CgalArrangement::Vertex_const_handle;
using PointLocation = CGAL::Arr_walk_along_line_point_location<CgalArrangement>;

constexpr int kBoxCurve = -1;  // curve data of the domain box's sides

/// Sets `out`, a zero OneRoot, to c, in place (moving a Rational would allocate: gmpxx re-initialises the source).
void assign_zero_one_root(OneRoot& out, const CoordNT& c) {
  out.a0 = c.a0();
  if (!c.is_extended()) return;
  out.a1 = c.a1();
  out.root = c.root();
  out.normalise();
}

CoordNT to_coord(const OneRoot& r) {
  if (r.is_rational()) return CoordNT(r.a0);
  return CoordNT(r.a0, r.a1, r.root);
}

Kernel::Point_2 to_kernel(const PointQ2& p) { return Kernel::Point_2(p.x, p.y); }

/// The part of the line {x : n.x = offset} inside the closed box, as a segment; nullopt when the line misses the
/// box's interior (it may still touch a corner or run along a side: then it is reported too, see below).
std::optional<std::pair<PointQ2, PointQ2>> clip_line_to_box(const PointQ2& n, const Rational& offset,
                                                            const Box2& box) {
  std::vector<PointQ2> hits;
  auto add = [&](const PointQ2& p) {
    if (!box.contains(p)) return;
    for (const auto& q : hits)
      if (q == p) return;
    hits.push_back(p);
  };
  if (n.y != 0) {  // intersections with the vertical sides x = min.x, x = max.x
    for (const Rational& x : {box.min.x, box.max.x}) {
      Rational y = (offset - n.x * x) / n.y;
      add({x, y});
    }
  }
  if (n.x != 0) {  // with the horizontal sides
    for (const Rational& y : {box.min.y, box.max.y}) {
      Rational x = (offset - n.y * y) / n.x;
      add({x, y});
    }
  }
  if (hits.size() < 2) return std::nullopt;  // misses the box or touches it at a single corner
  // A convex box meets a line in one segment: its extreme hits are its end points.
  auto less = [](const PointQ2& a, const PointQ2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  auto [lo, hi] = std::minmax_element(hits.begin(), hits.end(), less);
  return std::make_pair(*lo, *hi);
}

/// A one-root number's first enclosure in rational_strictly_between: its value twice when rational, else the ends
/// of its 64-bit MPFR enclosure as rationals.
struct FirstEnclosure {
  Rational lo, hi;
};
constexpr mpfr_prec_t kFirstBits = 64;

FirstEnclosure first_enclosure(const OneRoot& v) {
  if (v.is_rational()) return {v.a0, v.a0};
  const Interval e = v.enclose(kFirstBits);
  FirstEnclosure out;
  mpfr_get_q(out.lo.get_mpq_t(), e.lo());
  mpfr_get_q(out.hi.get_mpq_t(), e.hi());
  return out;
}

/// The simplest rational (smallest denominator) strictly between two one-root numbers lo < hi, as far as their
/// certified enclosures show it: rational ends are used as they are, irrational ones through the upper end of
/// lo's enclosure and the lower end of hi's, refined until those separate. Short witnesses, still exact.
/// `lo_first`, `hi_first`: first_enclosure(lo) and first_enclosure(hi) when the caller keeps them (a vertex's x
/// serves several faces), else computed here; the answer is the same.
Rational rational_strictly_between(const OneRoot& lo, const OneRoot& hi, const FirstEnclosure* lo_first = nullptr,
                                   const FirstEnclosure* hi_first = nullptr) {
  auto to_q = [](const mpfr_t x) {
    Rational q;
    mpfr_get_q(q.get_mpq_t(), x);
    return q;
  };
  {
    Rational lo_own, hi_own;  // the ends computed here (the given ones and rational values are not copied)
    const Rational& above_lo = lo_first            ? lo_first->hi
                               : lo.is_rational() ? lo.a0
                                                  : (lo_own = to_q(lo.enclose(kFirstBits).hi()));
    const Rational& below_hi = hi_first            ? hi_first->lo
                               : hi.is_rational() ? hi.a0
                                                  : (hi_own = to_q(hi.enclose(kFirstBits).lo()));
    if (above_lo < below_hi) return simplest_rational_in(above_lo, below_hi);
  }
  for (mpfr_prec_t bits = 2 * kFirstBits;; bits *= 2) {  // rational ends are never enclosed (no MPFR for them)
    const Rational above_lo = lo.is_rational() ? lo.a0 : to_q(lo.enclose(bits).hi());
    const Rational below_hi = hi.is_rational() ? hi.a0 : to_q(hi.enclose(bits).lo());
    if (above_lo < below_hi) return simplest_rational_in(above_lo, below_hi);
    if (bits > (1 << 22)) throw std::logic_error("rational_strictly_between: values do not separate");
  }
}

/// Whether the curve of `h` runs exactly between h's two vertices (see DistinctCurves on why this is checked).
bool curve_matches_ends(CgalArrangement::Halfedge_const_handle h) {
  auto same = [](const CgalPoint& p, const CgalPoint& q) {  // one shared representation (the usual case), or equal
    return p.identical(q) ||
           (CGAL::compare(p.x(), q.x()) == CGAL::EQUAL && CGAL::compare(p.y(), q.y()) == CGAL::EQUAL);
  };
  const CgalPoint &a = h->source()->point(), &b = h->target()->point();
  const CgalPoint &l = h->curve().left(), &r = h->curve().right();
  return (same(a, l) && same(b, r)) || (same(a, r) && same(b, l));
}

/// y of a non-vertical x-monotone curve at x0 (x0 within its closed x-range).
OneRoot y_at(const XCurve& cv, const Rational& x0) {
  if (cv.is_linear()) {
    const auto line = cv.supporting_line();
    return OneRoot(Rational(-(line.a() * x0 + line.c()) / line.b()));
  }
  const auto circle = cv.supporting_circle();
  const Rational dx = x0 - circle.center().x();
  Rational radicand = circle.squared_radius() - dx * dx;
  // Counter-clockwise travel runs right to left on the upper half-circle.
  const bool upper = (cv.orientation() == CGAL::COUNTERCLOCKWISE) != cv.is_directed_right();
  OneRoot y(circle.center().y(), Rational(upper ? 1 : -1), radicand);
  y.normalise();
  return y;
}

/// The curves handed to CGAL, each distinct point set once. Coincident boundaries (a halfspace given twice, a
/// disk and its complement, a polygon edge on a half-plane's line clipped to the same segment, a box side) are
/// merged here rather than left to the sweep, whose cost grows with the number of curves overlapping at once
/// (cubically for n copies of one circle). A curve's data is its index g; tags[g] lists what it bounds:
/// halfspace indices and kBoxCurve.
/// Collinear segments that overlap (a polygon edge along part of a half-plane's chord or of a box side, two polygons
/// sharing part of an edge) are cut at every end point on their common line into pieces, each handed over once with
/// the union of the tags covering it: CGAL then never sees an overlap. This is a correctness fix, not only a speed
/// one: Debian's CGAL 5.5 sweep (Arr_circle_segment_traits_2 with consolidated data) can leave an edge whose curve
/// is a longer overlapping segment than the edge itself when several collinear segments overlap among circles
/// (data/crashes/scene/overlap-curve-mismatch.json; Arrangement2::build now also checks every edge's curve).
/// `cells_at_least` is a lower bound on the bounded faces, known before the sweep: inserted first, each distinct
/// half-plane chord (ends on the box, meets every other chord or circle in finitely many points) and each
/// distinct circle splits at least one face, and later curves never merge faces.
struct DistinctCurves {
  std::vector<Curve> curves;
  std::vector<std::vector<int>> tags;
  long cells_at_least = 1;
};

class CurveCollector {
 public:
  void segment(const PointQ2& a, const PointQ2& b, int tag) {
    const bool swapped = b.x < a.x || (b.x == a.x && b.y < a.y);  // the key is the lexicographically ordered pair
    const PointQ2& lo = swapped ? b : a;
    const PointQ2& hi = swapped ? a : b;
    if (add({Rational(0), lo.x, lo.y, hi.x, hi.y}, tag, [&] { return make_segment(lo, hi); }))
      segments_.push_back({lo, hi, last_});
  }
  void circle(const PointQ2& center, const Rational& radius, int tag) {
    const Rational squared = radius * radius;
    add({Rational(1), center.x, center.y, squared}, tag,
        [&] { return BaseCurve(Kernel::Circle_2(to_kernel(center), squared, CGAL::COUNTERCLOCKWISE)); });
  }
  /// A half-plane's chord or a circle: counted in DistinctCurves::cells_at_least unless on the box.
  void mark_splitting() { splitting_.insert(last_); }
  DistinctCurves take() {
    for (int g : splitting_) {
      const std::vector<int>& tags = out_.tags[static_cast<std::size_t>(g)];
      if (std::find(tags.begin(), tags.end(), kBoxCurve) == tags.end()) ++out_.cells_at_least;
    }
    cut_overlaps();
    return std::move(out_);
  }

 private:
  /// A distinct segment: its lexicographically ordered ends and its curve index.
  struct Segment {
    PointQ2 lo, hi;
    int curve;
  };

  static BaseCurve make_segment(const PointQ2& lo, const PointQ2& hi) {
    return BaseCurve(Kernel::Segment_2(to_kernel(lo), to_kernel(hi)));
  }

  /// Adds `tag` to the curve with `key` (made by `make` when new); true when the curve is new.
  template <typename Make>
  bool add(std::vector<Rational> key, int tag, Make make) {
    const auto [it, fresh] = index_.emplace(std::move(key), static_cast<int>(out_.curves.size()));
    if (fresh) {
      out_.curves.emplace_back(make(), it->second);
      out_.tags.emplace_back();
    }
    last_ = it->second;
    std::vector<int>& tags = out_.tags[static_cast<std::size_t>(it->second)];
    if (std::find(tags.begin(), tags.end(), tag) == tags.end()) tags.push_back(tag);
    return fresh;
  }

  /// Replaces every set of overlapping collinear segments by the pieces between their end points (see
  /// DistinctCurves). Pieces keep every end point as a vertex, as CGAL's own overlap handling would.
  void cut_overlaps() {
    // Group by supporting line a x + b y = c, scaled so that its first non-zero coefficient of (a, b) is 1.
    std::map<std::array<Rational, 3>, std::vector<int>> lines;
    for (int k = 0; k < static_cast<int>(segments_.size()); ++k) {
      const Segment& s = segments_[static_cast<std::size_t>(k)];
      Rational a = s.hi.y - s.lo.y, b = s.lo.x - s.hi.x;
      const Rational scale = a != 0 ? a : b;
      a /= scale;
      b /= scale;
      lines[{a, b, a * s.lo.x + b * s.lo.y}].push_back(k);
    }
    // Each cut line's pieces take the place of its first segment, so that the curves keep their order.
    std::vector<char> replaced(out_.curves.size(), 0);
    std::map<int, DistinctCurves> pieces;  // first replaced curve -> the pieces of its line
    for (const auto& [line, members] : lines)
      if (members.size() > 1 && overlapping(members)) {
        int first = at(members[0]).curve;
        for (int k : members) first = std::min(first, at(k).curve);
        cut_line(members, replaced, pieces[first]);
      }
    if (pieces.empty()) return;
    DistinctCurves kept;
    kept.cells_at_least = out_.cells_at_least;
    auto keep = [&](const BaseCurve& curve, std::vector<int> tags) {
      kept.curves.emplace_back(curve, static_cast<int>(kept.curves.size()));
      kept.tags.push_back(std::move(tags));
    };
    for (std::size_t g = 0; g < out_.curves.size(); ++g) {
      if (!replaced[g]) keep(out_.curves[g], std::move(out_.tags[g]));
      const auto line = pieces.find(static_cast<int>(g));
      if (line == pieces.end()) continue;
      for (std::size_t p = 0; p < line->second.curves.size(); ++p)
        keep(line->second.curves[p], std::move(line->second.tags[p]));
    }
    out_ = std::move(kept);
  }

  /// Whether two of the collinear segments `members` share more than an end point. Collinear segments ordered by
  /// their lower ends overlap exactly when one starts before the furthest end seen so far.
  bool overlapping(std::vector<int> members) const {
    std::sort(members.begin(), members.end(), [&](int i, int j) { return less(at(i).lo, at(j).lo); });
    const PointQ2* reach = &at(members[0]).hi;
    for (std::size_t k = 1; k < members.size(); ++k) {
      if (less(at(members[k]).lo, *reach)) return true;
      if (less(*reach, at(members[k]).hi)) reach = &at(members[k]).hi;
    }
    return false;
  }

  /// Cuts the collinear segments `members` at all their end points; each piece covered by some segment goes to
  /// `pieces` with the union of their tags, and the segments are marked in `replaced`.
  void cut_line(const std::vector<int>& members, std::vector<char>& replaced, DistinctCurves& pieces) const {
    std::vector<PointQ2> points;
    for (int k : members) {
      points.push_back(at(k).lo);
      points.push_back(at(k).hi);
      replaced[static_cast<std::size_t>(at(k).curve)] = 1;
    }
    std::sort(points.begin(), points.end(), less);
    points.erase(std::unique(points.begin(), points.end()), points.end());
    // Sweep along the line: which tags cover the piece [points[p], points[p + 1]], with their multiplicities.
    std::vector<std::pair<PointQ2, int>> starts, ends;  // (point, member)
    for (int k : members) {
      starts.emplace_back(at(k).lo, k);
      ends.emplace_back(at(k).hi, k);
    }
    auto by_point = [](const std::pair<PointQ2, int>& u, const std::pair<PointQ2, int>& v) {
      return less(u.first, v.first);
    };
    std::sort(starts.begin(), starts.end(), by_point);
    std::sort(ends.begin(), ends.end(), by_point);
    std::map<int, int> covering;  // tag -> number of active segments carrying it
    std::size_t next_start = 0, next_end = 0;
    for (std::size_t p = 0; p + 1 < points.size(); ++p) {
      for (; next_end < ends.size() && !less(points[p], ends[next_end].first); ++next_end)
        for (int tag : tags_of(ends[next_end].second))
          if (--covering[tag] == 0) covering.erase(tag);
      for (; next_start < starts.size() && !less(points[p], starts[next_start].first); ++next_start)
        for (int tag : tags_of(starts[next_start].second)) ++covering[tag];
      if (covering.empty()) continue;
      std::vector<int> tags;
      for (const auto& [tag, count] : covering) tags.push_back(tag);
      pieces.curves.emplace_back(make_segment(points[p], points[p + 1]), 0);
      pieces.tags.push_back(std::move(tags));
    }
  }

  static bool less(const PointQ2& a, const PointQ2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
  const Segment& at(int k) const { return segments_[static_cast<std::size_t>(k)]; }
  const std::vector<int>& tags_of(int k) const { return out_.tags[static_cast<std::size_t>(at(k).curve)]; }

  std::map<std::vector<Rational>, int> index_;
  std::set<int> splitting_;
  std::vector<Segment> segments_;
  int last_ = -1;
  DistinctCurves out_;
};

DistinctCurves distinct_curves(const Scene2& scene) {
  CurveCollector collect;
  const Box2& box = scene.domain;
  const PointQ2 corners[4] = {box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
  for (int k = 0; k < 4; ++k) collect.segment(corners[k], corners[(k + 1) % 4], kBoxCurve);
  for (int i = 0; i < static_cast<int>(scene.halfspaces.size()); ++i) {
    const Halfspace2& h = scene.halfspaces[static_cast<std::size_t>(i)];
    switch (h.kind) {
      case HalfspaceKind2::Halfplane:
        if (auto seg = clip_line_to_box(h.normal, h.offset, box)) {
          collect.segment(seg->first, seg->second, i);
          collect.mark_splitting();
        }
        break;
      case HalfspaceKind2::Disk:
        collect.circle(h.center, h.radius, i);
        collect.mark_splitting();
        break;
      case HalfspaceKind2::Polygon:
        for (std::size_t k = 0; k < h.vertices.size(); ++k)
          collect.segment(h.vertices[k], h.vertices[(k + 1) % h.vertices.size()], i);
        break;
    }
  }
  return collect.take();
}

/// Watches CGAL build the arrangement and stops it, by throwing InputError, as soon as it has more bounded
/// faces than ArrangementLimits allow, so that an oversized input costs time and memory in proportion to the
/// limit, not to its own arrangement (which can be quadratic in the input).
class SizeGuard : public CGAL::Arr_observer<CgalArrangement> {
 public:
  /// Checks `cells_at_least` first, so that an input known to be too large is refused before the sweep.
  SizeGuard(CgalArrangement& arr, const ArrangementLimits& limits, int halfspaces, long cells_at_least)
      : CGAL::Arr_observer<CgalArrangement>(arr), limits_(limits), halfspaces_(halfspaces) {
    check(cells_at_least);
  }
  void after_split_face(Face_handle, Face_handle, bool) override {
    ++cells_;
    check(cells_);
  }

 private:
  void check(long cells) const {
    if (limits_.max_cells > 0 && cells > limits_.max_cells)
      throw InputError("the arrangement has at least " + std::to_string(cells) + " cells, over the limit of " +
                       std::to_string(limits_.max_cells) + " (raise it with --max-cells; see docs/limits.md)");
    const long entries = cells * halfspaces_;
    if (limits_.max_side_entries > 0 && entries > limits_.max_side_entries)
      throw InputError("the arrangement has at least " + std::to_string(cells) + " cells over " +
                       std::to_string(halfspaces_) + " halfspaces: its side table (cells x halfspaces) exceeds " +
                       std::to_string(limits_.max_side_entries) +
                       " entries, the limit (raise it with --max-side-table; see docs/limits.md)");
  }
  const ArrangementLimits& limits_;
  long halfspaces_;
  long cells_ = 0;  // bounded faces so far
};

using Enclosure = IntervalNT;

/// -1 or +1 when the enclosures separate a below or above b, 0 when they overlap (undecided).
int order(const Enclosure& a, const Enclosure& b) {
  if (a.sup() < b.inf()) return -1;
  if (a.inf() > b.sup()) return 1;
  return 0;
}

/// y of a non-vertical edge at some x, enclosed from its curve's data: a*x + b*y + c = 0 for a segment;
/// cy +- sqrt(r^2 - (x - cx)^2) for an arc (+ on its upper half). Fields p, q, r are a, b, c or cx, cy, r^2.
struct CurveEnclosure {
  bool arc;
  bool upper;
  Enclosure p, q, r;
};

/// A candidate for the nearest boundary above or below the base edge at x0 (InteriorPoints::inside): the
/// enclosure of its y, and the exact y once a comparison needed it.
struct YAtX0 {
  const XCurve* curve;
  Enclosure approx;
  std::optional<OneRoot> exact;
};

/// Exact interior points of faces: from a point of a non-vertical boundary edge (the base), shoot vertically into
/// the face; the open vertical segment up to the next boundary crossing lies in the face. Comparisons are decided
/// on certified enclosures (vertices' x, the edges' y at the shot's x), and exactly only where those overlap, so
/// every decision, and every point, is the one exact comparisons give.
class InteriorPoints {
 public:
  /// `vertices` and `edges`: the arrangement's, complete before the first call of inside() (each vertex's and
  /// edge's enclosure is taken on its first use: most faces are never asked for a point).
  InteriorPoints(const std::vector<ArrVertex2>& vertices, const std::vector<ArrEdge2>& edges)
      : vertices_(vertices), edges_(edges) {}

  /// A rational point strictly inside the face whose boundary halfedges (outer boundary first) are `walk`.
  PointQ2 inside(const std::vector<Halfedge>& walk) const {
    const auto base = std::find_if(walk.begin(), walk.end(), [](Halfedge h) { return !h->curve().is_vertical(); });
    if (base == walk.end()) throw std::logic_error("arrangement face without a non-vertical boundary edge");
    // x0: strictly between the base's left end and the next boundary vertex to its right (within the base).
    const int left = left_end(*base);
    int next = right_end(*base);
    for (Halfedge h : walk) {
      const int v = h->target()->data();
      if (compare_x(v, left) > 0 && compare_x(v, next) < 0) next = v;
    }
    const Rational x0 = rational_strictly_between(x_of(left), x_of(next), &first_x(left), &first_x(next));
    const Enclosure x0_approx = to_interval_nt(x0);
    const OneRoot x0_exact(x0);
    auto compare_to_x0 = [&](int v) {
      const int c = order(x_enclosure(v), x0_approx);
      return c != 0 ? c : compare(x_of(v), x0_exact);
    };
    // y0: strictly between the base and the nearest other boundary edge above it (below it) at x0, where the face
    // lies above (below) the base.
    YAtX0 y_base = y_at_x0(*base, x0_approx);
    y_base.exact = y_at(*y_base.curve, x0);
    const bool face_above = (*base)->direction() == CGAL::ARR_LEFT_TO_RIGHT;
    std::optional<YAtX0> y_next;
    for (Halfedge h : walk) {
      if (h == *base || h->curve().is_vertical()) continue;  // the base is at y_base itself
      if (!(compare_to_x0(left_end(h)) < 0 && compare_to_x0(right_end(h)) > 0)) continue;
      YAtX0 y = y_at_x0(h, x0_approx);
      const int side = compare_y(y, y_base, x0);
      if (face_above ? side <= 0 : side >= 0) continue;
      if (!y_next || (face_above ? compare_y(y, *y_next, x0) < 0 : compare_y(y, *y_next, x0) > 0))
        y_next = std::move(y);
    }
    if (!y_next) throw std::logic_error("arrangement face is not closed above/below its base edge");
    const OneRoot& next_y = exact(*y_next, x0);
    const Rational y0 =
        face_above ? rational_strictly_between(*y_base.exact, next_y) : rational_strictly_between(next_y, *y_base.exact);
    return {x0, y0};
  }

 private:
  static int left_end(Halfedge h) {
    return (h->direction() == CGAL::ARR_LEFT_TO_RIGHT ? h->source() : h->target())->data();
  }
  static int right_end(Halfedge h) {
    return (h->direction() == CGAL::ARR_LEFT_TO_RIGHT ? h->target() : h->source())->data();
  }
  const OneRoot& x_of(int v) const { return vertices_[static_cast<std::size_t>(v)].point.x; }
  /// Vertex v's x enclosed in doubles, computed on its first use.
  const Enclosure& x_enclosure(int v) const {
    if (x_.size() < vertices_.size()) x_.resize(vertices_.size());
    std::optional<Enclosure>& e = x_[static_cast<std::size_t>(v)];
    if (!e) {
      const OneRoot& x = x_of(v);
      e = to_interval_nt(x.a0);
      if (!x.is_rational()) *e += to_interval_nt(x.a1) * CGAL::sqrt(to_interval_nt(x.root));
    }
    return *e;
  }
  /// The curve data of h's edge enclosed in doubles (see CurveEnclosure), computed on its first use.
  const CurveEnclosure& curve_enclosure(Halfedge h) const {
    if (curves_.size() < edges_.size()) curves_.resize(edges_.size());
    std::optional<CurveEnclosure>& c = curves_[static_cast<std::size_t>(h->data())];
    if (!c) {
      const ArrEdge2& e = edges_[static_cast<std::size_t>(h->data())];
      const XCurve& cv = h->curve();
      auto enclose = [](const Rational& q) { return to_interval_nt(q); };
      if (e.shape == EdgeShape2::Arc) {
        const bool upper = (cv.orientation() == CGAL::COUNTERCLOCKWISE) != cv.is_directed_right();
        const Enclosure radius = enclose(e.radius);
        c = CurveEnclosure{true, upper, enclose(e.center.x), enclose(e.center.y), radius * radius};
      } else {
        c = CurveEnclosure{false, false, enclose(e.line_a), enclose(e.line_b), enclose(e.line_c)};
      }
    }
    return *c;
  }
  /// first_enclosure(x_of(v)), computed on its first use (most vertices serve two or more faces).
  const FirstEnclosure& first_x(int v) const {
    if (first_x_.size() < vertices_.size()) first_x_.resize(vertices_.size());
    std::optional<FirstEnclosure>& e = first_x_[static_cast<std::size_t>(v)];
    if (!e) e = first_enclosure(x_of(v));
    return *e;
  }

  /// Exact comparison of vertices u and w by x.
  int compare_x(int u, int w) const {
    if (u == w) return 0;
    const int c = order(x_enclosure(u), x_enclosure(w));
    return c != 0 ? c : compare(x_of(u), x_of(w));
  }

  /// The enclosure of h's y at x0 (h non-vertical, x0 in its closed x-range).
  YAtX0 y_at_x0(Halfedge h, const Enclosure& x0) const {
    const CurveEnclosure& c = curve_enclosure(h);
    Enclosure y;
    if (c.arc) {
      const Enclosure dx = x0 - c.p;
      const Enclosure half_chord = CGAL::sqrt(c.r - dx * dx);
      y = c.upper ? c.q + half_chord : c.q - half_chord;
    } else {
      y = -(c.p * x0 + c.r) / c.q;
    }
    return {&h->curve(), y, std::nullopt};
  }
  static const OneRoot& exact(YAtX0& y, const Rational& x0) {
    if (!y.exact) y.exact = y_at(*y.curve, x0);
    return *y.exact;
  }
  /// Exact comparison of two edges' y at x0.
  static int compare_y(YAtX0& a, YAtX0& b, const Rational& x0) {
    const int c = order(a.approx, b.approx);
    return c != 0 ? c : compare(exact(a, x0), exact(b, x0));
  }

  const std::vector<ArrVertex2>& vertices_;
  const std::vector<ArrEdge2>& edges_;
  mutable std::vector<std::optional<Enclosure>> x_;            // per vertex: see x_enclosure
  mutable std::vector<std::optional<CurveEnclosure>> curves_;  // per edge: see curve_enclosure
  mutable std::vector<std::optional<FirstEnclosure>> first_x_;  // per vertex: see first_x
};

}  // namespace

struct Arrangement2::Impl {
  CgalArrangement arr;  // its records carry their indices (see Dcel)
  std::unique_ptr<PointLocation> locator;
  std::vector<Halfedge> halfedges;           // per edge index: its representative halfedge
  std::vector<VertexHandle> vertices;        // per vertex index: its record
  std::vector<std::vector<int>> on_boundary;  // per halfspace: the edges (not on the box) that carry it
  bool abandoned = false;                      // see build(): never destroyed when true

  /// Exact point location (walking along a vertical line).
  PointLocation2 locate(const CgalPoint& p) const {
    const auto located = locator->locate(p);
    if (const FaceHandle* f = boost::get<FaceHandle>(&located)) {
      if ((*f)->is_unbounded()) return {PointLocation2::Outside, -1};
      return {PointLocation2::Face, (*f)->data()};
    }
    if (const Halfedge* h = boost::get<Halfedge>(&located)) return {PointLocation2::Edge, (*h)->data()};
    const VertexHandle* v = boost::get<VertexHandle>(&located);
    return {PointLocation2::Vertex, (*v)->data()};
  }

  /// locate(p), trying `halfspace`'s edges first.
  PointLocation2 locate_on_boundary(const CgalPoint& p, int halfspace) const {
    if (const auto on_edges = locate_on_edges(p, halfspace)) return *on_edges;
    return locate(p);
  }

  /// locate_on_boundary's answer when p lies on one of `halfspace`'s edges (its ends included), else nullopt.
  std::optional<PointLocation2> locate_on_edges(const CgalPoint& p, int halfspace) const {
    const Traits& traits = *arr.geometry_traits();
    const auto equal = traits.equal_2_object();
    const auto compare_x = traits.compare_x_2_object();
    const auto compare_y_at_x = traits.compare_y_at_x_2_object();
    for (int e : on_boundary[static_cast<std::size_t>(halfspace)]) {
      const Halfedge h = halfedges[static_cast<std::size_t>(e)];
      if (equal(p, h->source()->point())) return PointLocation2{PointLocation2::Vertex, h->source()->data()};
      if (equal(p, h->target()->point())) return PointLocation2{PointLocation2::Vertex, h->target()->data()};
      // Strictly between the ends' x (or at their common x, for a vertical segment) and on the curve there.
      const auto left = compare_x(p, h->source()->point()), right = compare_x(p, h->target()->point());
      if (left != CGAL::EQUAL && left == right) continue;
      if (compare_y_at_x(p, h->curve()) == CGAL::EQUAL) return PointLocation2{PointLocation2::Edge, e};
    }
    return std::nullopt;
  }
};

Arrangement2 Arrangement2::build(const Scene2& scene, const ArrangementLimits& limits) {
  Arrangement2 out;
  out.domain_ = scene.domain;
  out.halfspace_count_ = static_cast<int>(scene.halfspaces.size());
  // CGAL's insertion is not safe against a failed allocation: after std::bad_alloc in the middle of the sweep,
  // destroying the half-built arrangement crashed (SIGSEGV in its destructor, in about 1 of 5 runs of
  // tests/hostile/cases/limits.cases "out of memory is a clean error" under `ulimit -v 150000`). So an arrangement
  // whose insertion ran out of memory is abandoned, never destroyed: its memory is lost, and the caller reports that
  // the input needs more memory. SizeGuard's refusal is thrown after a completed face split, when the arrangement is
  // whole; such an arrangement is destroyed as usual (campaigns refuse scenes and go on).
  auto impl = std::shared_ptr<Impl>(new Impl, [](Impl* built) {
    if (!built->abandoned) delete built;
  });
  CgalArrangement& arr = impl->arr;
  auto pieces = std::make_shared<Pieces>();

  // --- 1. Curves: the box, then every halfspace boundary, each distinct curve once (see DistinctCurves). --------
  const DistinctCurves curves = distinct_curves(scene);
  SizeGuard guard(arr, limits, out.halfspace_count_, curves.cells_at_least);
  try {
    CGAL::insert(arr, curves.curves.begin(), curves.curves.end());
  } catch (const std::bad_alloc&) {
    impl->abandoned = true;
    throw;
  }
  guard.detach();

  // --- 2. Vertices (each record gets its index, see Dcel). --------------------------------------------------------
  pieces->vertices.reserve(arr.number_of_vertices());
  pieces->edges.reserve(arr.number_of_edges());
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    v->set_data(static_cast<int>(pieces->vertices.size()));
    impl->vertices.push_back(v);
    ArrVertex2& vertex = pieces->vertices.emplace_back();  // degree: counted from the edges (step 4)
    assign_zero_one_root(vertex.point.x, v->point().x());
    assign_zero_one_root(vertex.point.y, v->point().y());
  }
  // --- 3. Faces: bounded ones only; the unbounded face is outside the domain (index -1). --------------------------
  std::vector<FaceHandle> faces;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    f->set_data(f->is_unbounded() ? -1 : static_cast<int>(faces.size()));
    if (!f->is_unbounded()) faces.push_back(f);
  }

  // --- 4. Edges: indices here (each edge oriented as CGAL's representative halfedge), records after step 5. ------
  impl->halfedges.reserve(arr.number_of_edges());
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    const int id = static_cast<int>(impl->halfedges.size());
    e->set_data(id);
    e->twin()->set_data(id);
    impl->halfedges.push_back(e);
  }
  // Whether h is its edge's representative halfedge (runs source -> target).
  auto forward = [&](Halfedge h) { return h == impl->halfedges[static_cast<std::size_t>(h->data())]; };

  // --- 5. Per face: boundary walks; each edge's faces, in a small table of their own (the edge records are filled
  // in order below: writing into them here, at random, was a cache miss per edge). --------------------------------
  const std::size_t edge_count = impl->halfedges.size();
  std::vector<std::array<int, 2>> edge_faces(edge_count, {-1, -1});  // left, right
  pieces->faces.resize(faces.size());
  for (std::size_t fi = 0; fi < faces.size(); ++fi) {
    FaceHandle f = faces[fi];
    ArrFace2& face = pieces->faces[fi];
    auto walk = [&](CgalArrangement::Ccb_halfedge_const_circulator start) {
      std::vector<std::pair<int, bool>> cycle;
      auto c = start;
      do {
        Halfedge h = c;
        const bool fwd = forward(h);
        cycle.emplace_back(h->data(), fwd);
        edge_faces[static_cast<std::size_t>(h->data())][fwd ? 0 : 1] = static_cast<int>(fi);
      } while (++c != start);
      face.boundary.push_back(std::move(cycle));
    };
    walk(f->outer_ccb());
    for (auto hole = f->inner_ccbs_begin(); hole != f->inner_ccbs_end(); ++hole) walk(*hole);
  }

  // Step 4 continued: the edge records, in order; `flips` lists each edge's halfspaces again, flat, for step 6. Then
  // the vertices' degrees, and the outer faces (those with an edge on the box).
  std::vector<int> flips_begin(edge_count + 1, 0), flips;
  flips.reserve(edge_count);
  std::vector<char> box_edge(edge_count, 0);
  std::vector<int> degrees(pieces->vertices.size(), 0);  // counted here, copied into the vertices after the loop
  for (std::size_t id = 0; id < edge_count; ++id) {
    const Halfedge h = impl->halfedges[id];
    ArrEdge2& edge = pieces->edges.emplace_back();  // filled in place (reserved above): no Rational moved
    edge.source = h->source()->data();
    edge.target = h->target()->data();
    ++degrees[static_cast<std::size_t>(edge.source)];  // no loops: arcs are x-monotone
    ++degrees[static_cast<std::size_t>(edge.target)];
    edge.left_face = edge_faces[id][0];  // -1 beside the unbounded face
    edge.right_face = edge_faces[id][1];
    if (!curve_matches_ends(h))
      throw std::logic_error("CGAL left an arrangement edge whose curve does not end at its vertices");
    for (auto it = h->curve().data().begin(); it != h->curve().data().end(); ++it)
      for (int tag : curves.tags[static_cast<std::size_t>(*it)]) {
        if (tag == kBoxCurve)
          edge.on_box = true;
        else
          edge.halfspaces.push_back(tag);
      }
    std::sort(edge.halfspaces.begin(), edge.halfspaces.end());
    edge.halfspaces.erase(std::unique(edge.halfspaces.begin(), edge.halfspaces.end()), edge.halfspaces.end());
    flips.insert(flips.end(), edge.halfspaces.begin(), edge.halfspaces.end());
    flips_begin[id + 1] = static_cast<int>(flips.size());
    box_edge[id] = edge.on_box;
    const XCurve& cv = h->curve();
    if (cv.is_linear()) {
      const auto line = cv.supporting_line();
      edge.line_a = line.a();
      edge.line_b = line.b();
      edge.line_c = line.c();
    }
    if (cv.is_circular()) {
      edge.shape = EdgeShape2::Arc;
      const auto circle = cv.supporting_circle();
      edge.center = {circle.center().x(), circle.center().y()};
      // Arcs come only from disks, and coincident arcs lie on one circle: take the radius of the first disk.
      edge.radius = scene.halfspaces.at(edge.halfspaces.at(0)).radius;
      const bool halfedge_directed_right = h->direction() == CGAL::ARR_LEFT_TO_RIGHT;
      const bool same_as_curve = halfedge_directed_right == cv.is_directed_right();
      edge.ccw = (cv.orientation() == CGAL::COUNTERCLOCKWISE) == same_as_curve;
    }
  }
  for (std::size_t v = 0; v < degrees.size(); ++v) pieces->vertices[v].degree = degrees[v];
  for (ArrFace2& face : pieces->faces)
    for (const auto& cycle : face.boundary)
      for (const auto& step : cycle)
        if (box_edge[static_cast<std::size_t>(step.first)]) face.outer = true;

  // Interior points, each found on its first read: face f's walks as halfedges (an edge's representative halfedge
  // runs forward, its twin backward), outer boundary first, then InteriorPoints::inside. The cache owns what it
  // reads (the CGAL arrangement through impl, the plain data, the enclosures); its calls never overlap, so
  // InteriorPoints' per-vertex and per-edge memos need no lock.
  const auto interior_points = std::make_shared<InteriorPoints>(pieces->vertices, pieces->edges);
  out.face_interiors_ = std::make_shared<const LazyCache<PointQ2>>(
      pieces->faces.size(), [impl = std::shared_ptr<const Impl>(impl), pieces, interior_points](std::size_t f) {
        std::vector<Halfedge> walk;
        for (const auto& cycle : pieces->faces[f].boundary)
          for (const auto& [e, fwd] : cycle) {
            const Halfedge h = impl->halfedges[static_cast<std::size_t>(e)];
            walk.push_back(fwd ? h : h->twin());
          }
        return interior_points->inside(walk);
      });

  // --- 6. Sides: evaluate one face directly, then flip halfspace bits across edges (breadth first). ---------------
  const std::size_t n_half = scene.halfspaces.size();
  if (!pieces->faces.empty()) {
    std::vector<char> seen(pieces->faces.size(), 0);
    ArrFace2& root = pieces->faces[0];
    root.inside.assign(n_half, 0);
    for (std::size_t i = 0; i < n_half; ++i) {
      const int side = scene.halfspaces[i].side(out.face_interiors_->get(0));
      if (side == 0) throw std::logic_error("face interior point lies on a boundary");
      root.inside[i] = side > 0;
    }
    std::deque<int> queue{0};
    seen[0] = 1;
    while (!queue.empty()) {
      const int fi = queue.front();
      queue.pop_front();
      for (const auto& cycle : pieces->faces[fi].boundary)
        for (const auto& [ei, fwd] : cycle) {
          const int other = edge_faces[static_cast<std::size_t>(ei)][fwd ? 1 : 0];
          if (other < 0 || seen[other]) continue;
          seen[other] = 1;
          pieces->faces[other].inside = pieces->faces[fi].inside;
          for (int k = flips_begin[ei]; k < flips_begin[ei + 1]; ++k) pieces->faces[other].inside[flips[k]] ^= 1;
          queue.push_back(other);
        }
    }
    if (std::find(seen.begin(), seen.end(), 0) != seen.end())
      throw std::logic_error("arrangement faces inside the domain are not connected");
  }

  impl->locator = std::make_unique<PointLocation>(arr);
  impl->on_boundary.resize(n_half);
  for (std::size_t e = 0; e < pieces->edges.size(); ++e)
    if (!pieces->edges[e].on_box)
      for (int i : pieces->edges[e].halfspaces) impl->on_boundary[static_cast<std::size_t>(i)].push_back(static_cast<int>(e));
  out.impl_ = std::move(impl);
  out.edge_lengths_ = std::make_shared<const MeasureCache>(pieces->edges.size(), [pieces](std::size_t e) {
    const ArrEdge2& edge = pieces->edges[e];
    return edge_length(edge, pieces->vertices[edge.source].point, pieces->vertices[edge.target].point);
  });
  out.face_areas_ = std::make_shared<const MeasureCache>(pieces->faces.size(), [pieces](std::size_t f) {
    return enclosed_area(pieces->faces[f].boundary, pieces->edges, pieces->vertices);
  });
  out.pieces_ = std::move(pieces);
  // --- 7. Samples: exact point location on the boundary of their halfspace. ---------------------------------------
  out.sample_edges_ = out.place_samples(scene);
  return out;
}

Arrangement2 Arrangement2::with_samples(const Scene2& scene) const {
  if (static_cast<int>(scene.halfspaces.size()) != halfspace_count_ || !(scene.domain.min == domain_.min) ||
      !(scene.domain.max == domain_.max))
    throw std::invalid_argument("Arrangement2::with_samples: the scene's halfspaces or domain are not the arrangement's");
  Arrangement2 out = *this;
  out.sample_edges_ = place_samples(scene);
  return out;
}

std::vector<int> Arrangement2::place_samples(const Scene2& scene) const {
  const Pieces& pieces = *pieces_;
  std::vector<int> sample_edges;
  sample_edges.reserve(scene.samples.size());
  for (std::size_t s = 0; s < scene.samples.size(); ++s) {
    const Sample2& sample = scene.samples[s];
    const std::string who = "samples[" + std::to_string(s) + "] (on \"" +
                            scene.halfspaces.at(sample.halfspace).name + "\")";
    const CgalPoint p(to_coord(sample.location.x), to_coord(sample.location.y));
    const PointLocation2 where = impl_->locate_on_boundary(p, sample.halfspace);
    const int edge = holding_edge(where, sample.halfspace);
    if (edge < 0) {
      if (where.kind == PointLocation2::Edge && pieces.edges[where.index].on_box)
        throw InputError(who + ": lies on the domain boundary " + sample.location.exact_string() +
                         "; move it inside the domain");
      if (where.kind == PointLocation2::Edge)
        throw std::logic_error(who + ": located on an edge of another boundary");
      if (where.kind == PointLocation2::Vertex)
        throw InputError(who + ": lies on an arrangement vertex " + sample.location.exact_string() +
                         " where boundaries meet; a sample must lie inside a patch");
      throw InputError(who + ": " + sample.location.exact_string() + " is not on the boundary inside the domain");
    }
    sample_edges.push_back(edge);
  }
  return sample_edges;
}

long bare_cgal_arrangement_faces(const Scene2& scene) {
  const DistinctCurves curves = distinct_curves(scene);
  CgalArrangement arr;
  CGAL::insert(arr, curves.curves.begin(), curves.curves.end());
  return static_cast<long>(arr.number_of_faces()) - static_cast<long>(arr.number_of_unbounded_faces());
}

int Arrangement2::connected_components() const {
  DisjointSets sets(vertices().size());
  for (const auto& e : edges()) sets.union_set(e.source, e.target);
  return components_of(sets, vertices().size()).count;
}

std::vector<int> Arrangement2::incident_edges(int vertex) const {
  if (vertex < 0 || vertex >= static_cast<int>(impl_->vertices.size()))
    throw std::invalid_argument("Arrangement2::incident_edges: no vertex " + std::to_string(vertex));
  const VertexHandle v = impl_->vertices[static_cast<std::size_t>(vertex)];
  std::vector<int> incident;
  incident.reserve(v->degree());
  if (v->is_isolated()) return incident;
  auto h = v->incident_halfedges();  // the halfedges whose target is v: one per edge end at v
  const auto first = h;
  do incident.push_back((*h).data());
  while (++h != first);
  std::sort(incident.begin(), incident.end());
  return incident;
}

int Arrangement2::holding_edge(const PointLocation2& where, int halfspace) const {
  if (halfspace < 0 || halfspace >= halfspace_count_)
    throw std::invalid_argument("Arrangement2::holding_edge: no halfspace " + std::to_string(halfspace));
  const Pieces& pieces = *pieces_;
  auto carries = [&](int e) {
    const ArrEdge2& edge = pieces.edges[static_cast<std::size_t>(e)];
    return !edge.on_box && std::binary_search(edge.halfspaces.begin(), edge.halfspaces.end(), halfspace);
  };
  if (where.kind == PointLocation2::Edge) {
    if (where.index < 0 || where.index >= static_cast<int>(pieces.edges.size()))
      throw std::invalid_argument("Arrangement2::holding_edge: no edge " + std::to_string(where.index));
    return carries(where.index) ? where.index : -1;
  }
  if (where.kind != PointLocation2::Vertex) return -1;
  // A degree-2 vertex inside one curve run (a polygon corner, a circle's x-extreme point) is inside a patch.
  const std::vector<int> incident = incident_edges(where.index);
  const bool inside_run = incident.size() == 2 && carries(incident[0]) && carries(incident[1]) &&
                          pieces.edges[static_cast<std::size_t>(incident[0])].halfspaces ==
                              pieces.edges[static_cast<std::size_t>(incident[1])].halfspaces;
  return inside_run ? incident[0] : -1;
}

PointLocation2 Arrangement2::locate_on_boundary(const PointQ2& p, int halfspace) const {
  if (halfspace < 0 || halfspace >= halfspace_count_)
    throw std::invalid_argument("Arrangement2::locate_on_boundary: no halfspace " + std::to_string(halfspace));
  return impl_->locate_on_boundary(CgalPoint(CoordNT(p.x), CoordNT(p.y)), halfspace);
}

PointLocation2 Arrangement2::locate(const PointQ2& p) const {
  return impl_->locate(CgalPoint(CoordNT(p.x), CoordNT(p.y)));
}

}  // namespace hsx
