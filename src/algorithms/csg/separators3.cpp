// 3D separators: see separators3.hpp.
#include <hsx/algorithms/csg/separators3.hpp>
#include <hsx/geometry/scene_builders.hpp>

#include <algorithm>
#include <numeric>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace hsx::csg {

const char* to_string(PlaneOrigin origin) {
  switch (origin) {
    case PlaneOrigin::FacePlane: return "face-plane";
    case PlaneOrigin::EdgeVertex: return "edge-vertex";
    case PlaneOrigin::Bisector: return "bisector";
  }
  return "?";
}

namespace {

bool is_zero3(const PointQ3& p) { return sgn(p.x) == 0 && sgn(p.y) == 0 && sgn(p.z) == 0; }

/// The plane scaled so that its first non-zero normal coordinate is 1: equal keys iff equal planes up to a
/// non-zero factor of either sign.
std::tuple<Rational, Rational, Rational, Rational> plane_key(const PointQ3& n, const Rational& offset) {
  const Rational s = sgn(n.x) != 0 ? n.x : sgn(n.y) != 0 ? n.y : n.z;
  return {n.x / s, n.y / s, n.z / s, offset / s};
}

/// Some corner of the box strictly on each side of the plane.
bool crosses_box(const Box3& box, const PointQ3& n, const Rational& offset) {
  bool below = false, above = false;
  for (int i = 0; i < 8; ++i) {
    const PointQ3 c{(i & 1 ? box.max : box.min).x, (i & 2 ? box.max : box.min).y, (i & 4 ? box.max : box.min).z};
    const int s = sgn(dot3(n, c) - offset);
    below = below || s < 0;
    above = above || s > 0;
  }
  return below && above;
}

/// Per cell, the ids of the triangles bounding it (ascending).
std::vector<std::vector<int>> cell_triangles(const Arrangement3& arr) {
  std::vector<std::vector<int>> out(arr.cells().size());
  const auto& tris = arr.triangles();
  for (std::size_t t = 0; t < tris.size(); ++t) {
    if (tris[t].front_cell >= 0) out[static_cast<std::size_t>(tris[t].front_cell)].push_back(static_cast<int>(t));
    if (tris[t].back_cell >= 0 && tris[t].back_cell != tris[t].front_cell)
      out[static_cast<std::size_t>(tris[t].back_cell)].push_back(static_cast<int>(t));
  }
  return out;
}

/// Per cell, the ids of its boundary vertices (ascending, once each).
std::vector<std::vector<int>> cell_vertices(const Arrangement3& arr, const std::vector<std::vector<int>>& triangles) {
  std::vector<std::vector<int>> out(triangles.size());
  for (std::size_t c = 0; c < triangles.size(); ++c) {
    for (int t : triangles[c])
      for (int v : arr.triangles()[static_cast<std::size_t>(t)].vertices) out[c].push_back(v);
    std::sort(out[c].begin(), out[c].end());
    out[c].erase(std::unique(out[c].begin(), out[c].end()), out[c].end());
  }
  return out;
}

struct Prediction {
  int terms = 0;  ///< mixed terms resolved
  int cells = 0;  ///< cells of mixed terms that no longer share their sign vector with a cell of the other kind
};

class CandidateList {
 public:
  CandidateList(const Scene3& scene) : domain_(scene.domain) {
    for (const Halfspace3& h : scene.halfspaces)
      if (h.kind == HalfspaceKind3::Plane) seen_.insert(plane_key(h.normal, h.offset));
  }
  void add(const PointQ3& n, const Rational& offset, PlaneOrigin origin) {
    if (is_zero3(n) || !crosses_box(domain_, n, offset)) return;
    if (seen_.insert(plane_key(n, offset)).second) out_.push_back({n, offset, origin});
  }
  std::vector<SeparatorPlane> take() { return std::move(out_); }

 private:
  Box3 domain_;
  std::set<std::tuple<Rational, Rational, Rational, Rational>> seen_;
  std::vector<SeparatorPlane> out_;
};

/// -1: every boundary vertex of the cell on the closed negative side (normal . x <= offset), +1: on the closed
/// positive side, 0: crossed. A cell with all its vertices on the plane cannot exist (it has volume).
int cell_side(const Arrangement3& arr, const std::vector<int>& vertices, const SeparatorPlane& p) {
  bool neg = false, pos = false;
  for (int v : vertices) {
    const int s = sgn(dot3(p.normal, arr.vertices()[static_cast<std::size_t>(v)]) - p.offset);
    neg = neg || s < 0;
    pos = pos || s > 0;
    if (neg && pos) return 0;
  }
  return pos ? 1 : -1;
}

Prediction predicted_with(const Arrangement3& arr, const std::vector<std::vector<int>>& vertices,
                          const Describability& mixed, const SeparatorPlane& plane) {
  Prediction p;
  for (const MixedTerm& t : mixed.mixed) {
    // Per side (-1, +1): does it hold inside cells, outside cells, how many cells.
    int in[2] = {0, 0}, out[2] = {0, 0};
    bool crossed = false;
    for (bool inside : {true, false})
      for (int c : inside ? t.inside_cells : t.outside_cells) {
        const int s = cell_side(arr, vertices[static_cast<std::size_t>(c)], plane);
        if (s == 0) {
          crossed = true;
          break;
        }
        ++(inside ? in : out)[s > 0 ? 1 : 0];
      }
    if (crossed) continue;
    int still_mixed = 0;
    for (int side = 0; side < 2; ++side)
      if (in[side] > 0 && out[side] > 0) still_mixed += in[side] + out[side];
    if (still_mixed == 0) ++p.terms;
    p.cells += in[0] + in[1] + out[0] + out[1] - still_mixed;
  }
  return p;
}

int mixed_cell_count(const Describability& d) {
  int n = 0;
  for (const MixedTerm& t : d.mixed) n += static_cast<int>(t.inside_cells.size() + t.outside_cells.size());
  return n;
}

}  // namespace

std::vector<SeparatorPlane> separator_candidates(const Scene3& scene, const Arranged3& arranged,
                                                 const Describability& mixed) {
  const Arrangement3& arr = arranged.arrangement;
  const auto& verts = arr.vertices();
  const auto triangles = cell_triangles(arr);
  CandidateList list(scene);
  // 1. supporting planes of the triangles bounding the mixed terms' cells.
  for (bool inside : {true, false})
    for (const MixedTerm& t : mixed.mixed)
      for (int c : inside ? t.inside_cells : t.outside_cells)
        for (int k : triangles[static_cast<std::size_t>(c)]) {
          const ArrTriangle3& tri = arr.triangles()[static_cast<std::size_t>(k)];
          const PointQ3& a = verts[static_cast<std::size_t>(tri.vertices[0])];
          const PointQ3 n = triangle_normal(a, verts[static_cast<std::size_t>(tri.vertices[1])],
                                            verts[static_cast<std::size_t>(tri.vertices[2])]);
          list.add(n, dot3(n, a), PlaneOrigin::FacePlane);
        }
  // 2. planes through an edge where an inside and an outside cell of a term meet, and a vertex of another such edge.
  for (const MixedTerm& t : mixed.mixed) {
    std::set<int> ins(t.inside_cells.begin(), t.inside_cells.end());
    std::set<int> outs(t.outside_cells.begin(), t.outside_cells.end());
    std::vector<int> meeting;  // edge ids
    for (std::size_t e = 0; e < arr.edges().size(); ++e) {
      bool touches_in = false, touches_out = false;
      for (int k : arr.edges()[e].triangles) {
        const ArrTriangle3& tri = arr.triangles()[static_cast<std::size_t>(k)];
        for (int c : {tri.front_cell, tri.back_cell}) {
          touches_in = touches_in || ins.count(c) > 0;
          touches_out = touches_out || outs.count(c) > 0;
        }
      }
      if (touches_in && touches_out) meeting.push_back(static_cast<int>(e));
    }
    std::vector<int> ends;
    for (int e : meeting) {
      ends.push_back(arr.edges()[static_cast<std::size_t>(e)].a);
      ends.push_back(arr.edges()[static_cast<std::size_t>(e)].b);
    }
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    for (int e : meeting) {
      const PointQ3& a = verts[static_cast<std::size_t>(arr.edges()[static_cast<std::size_t>(e)].a)];
      const PointQ3& b = verts[static_cast<std::size_t>(arr.edges()[static_cast<std::size_t>(e)].b)];
      for (int v : ends) {
        const PointQ3 n = triangle_normal(a, b, verts[static_cast<std::size_t>(v)]);
        if (!is_zero3(n)) list.add(n, dot3(n, a), PlaneOrigin::EdgeVertex);
      }
    }
  }
  // 3. bisectors of inside and outside witness points.
  for (const MixedTerm& t : mixed.mixed)
    for (int i : t.inside_cells)
      for (int o : t.outside_cells) {
        const PointQ3& p = arr.cells()[static_cast<std::size_t>(i)].interior;
        const PointQ3& q = arr.cells()[static_cast<std::size_t>(o)].interior;
        const PointQ3 n{q.x - p.x, q.y - p.y, q.z - p.z};
        const PointQ3 m{(p.x + q.x) / 2, (p.y + q.y) / 2, (p.z + q.z) / 2};
        list.add(n, dot3(n, m), PlaneOrigin::Bisector);
      }
  return list.take();
}

std::pair<int, int> predicted_resolved(const Arranged3& arranged, const Describability& mixed,
                                       const SeparatorPlane& plane) {
  const Arrangement3& arr = arranged.arrangement;
  const Prediction p = predicted_with(arr, cell_vertices(arr, cell_triangles(arr)), mixed, plane);
  return {p.terms, p.cells};
}

std::vector<char> carry_solid3(const Arranged3& from, const std::vector<char>& solid, const Arranged3& to) {
  if (solid.size() != from.complex.cells.size())
    throw std::invalid_argument("carry_solid3: the solid needs one entry per cell");
  std::vector<char> out(to.arrangement.cells().size(), 0);
  for (std::size_t c = 0; c < out.size(); ++c) {
    const PointLocation3 where = from.arrangement.locate(to.arrangement.cells()[c].interior);
    if (where.kind != PointLocation3::Cell)
      throw std::logic_error("carry_solid3: cell " + std::to_string(c) +
                             "'s interior point is not inside a cell of the coarser arrangement");
    out[c] = solid[static_cast<std::size_t>(where.index)];
  }
  return out;
}

SeparatedSolid3 add_separators(const Scene3& scene, const Arranged3& arranged, const std::vector<char>& solid,
                               int max_separators, const ArrangementLimits& limits) {
  if (max_separators < 0) throw std::invalid_argument("add_separators: max_separators must be >= 0");
  SeparatedSolid3 s{scene, arranged, solid};
  Describability d = describability(s.arranged.complex, s.cells);
  while (!d.describable) {
    if (s.separators >= max_separators) {
      s.stop = SeparatorStop::MaxSeparators;
      break;
    }
    PlaneRound round;
    round.mixed_terms = static_cast<int>(d.mixed.size());
    round.mixed_cells = mixed_cell_count(d);
    const std::vector<SeparatorPlane> candidates = separator_candidates(s.scene, s.arranged, d);
    round.candidates = static_cast<int>(candidates.size());
    const Arrangement3& arr = s.arranged.arrangement;
    const auto vertices = cell_vertices(arr, cell_triangles(arr));
    struct Ranked {
      Prediction p;
      std::size_t k;
    };
    std::vector<Ranked> order;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const Prediction p = predicted_with(arr, vertices, d, candidates[k]);
      if (p.cells > 0) order.push_back({p, k});
    }
    round.predicted = static_cast<int>(order.size());
    std::stable_sort(order.begin(), order.end(), [](const Ranked& a, const Ranked& b) {
      return a.p.terms != b.p.terms ? a.p.terms > b.p.terms : a.p.cells > b.p.cells;
    });
    const Prediction best_prediction = order.empty() ? Prediction{} : order.front().p;

    struct Best {
      int trial = -1, terms = 0, cells = 0;
      Scene3 scene;
      Arranged3 arranged;
      std::vector<char> cells_inside;
      Describability d;
    };
    std::optional<Best> best;
    const std::string name = "sep" + std::to_string(s.separators);
    for (const Ranked& ranked : order) {
      if (static_cast<int>(round.trials.size()) >= kMaxPlaneTrials) break;
      const std::size_t k = ranked.k;
      PlaneTrial trial{candidates[k], ranked.p.terms, ranked.p.cells};
      Scene3 next = s.scene;
      next.halfspaces.push_back(plane(name, candidates[k].normal, candidates[k].offset));
      std::optional<Arranged3> a;
      try {
        a = arrange(next, limits);
      } catch (const InputError& e) {
        trial.rejection = e.what();
        round.trials.push_back(trial);
        continue;
      }
      std::vector<char> cells = carry_solid3(s.arranged, s.cells, *a);
      Describability nd = describability(a->complex, cells);
      trial.arranged = true;
      trial.mixed_terms = static_cast<int>(nd.mixed.size());
      trial.mixed_cells = mixed_cell_count(nd);
      trial.separated = trial.mixed_terms < round.mixed_terms || trial.mixed_cells < round.mixed_cells;
      round.trials.push_back(trial);
      const bool better = !best || trial.mixed_terms < best->terms ||
                          (trial.mixed_terms == best->terms && trial.mixed_cells < best->cells);
      if (better)
        best = Best{static_cast<int>(round.trials.size()) - 1, trial.mixed_terms, trial.mixed_cells,
                    std::move(next), std::move(*a), std::move(cells), std::move(nd)};
      // Nothing later is predicted better than what this trial achieved.
      if (round.mixed_terms - trial.mixed_terms >= best_prediction.terms &&
          round.mixed_cells - trial.mixed_cells >= best_prediction.cells)
        break;
    }
    const bool progress =
        best && (best->terms < round.mixed_terms || best->cells < round.mixed_cells);
    if (!progress) {
      s.rounds.push_back(std::move(round));
      s.stop = SeparatorStop::NoCandidateSeparates;
      break;
    }
    round.trials[static_cast<std::size_t>(best->trial)].chosen = true;
    s.rounds.push_back(std::move(round));
    s.scene = std::move(best->scene);
    s.arranged = std::move(best->arranged);
    s.cells = std::move(best->cells_inside);
    d = std::move(best->d);
    ++s.separators;
  }
  s.describable = d.describable;
  if (s.describable) s.stop = SeparatorStop::Describable;
  return s;
}

}  // namespace hsx::csg
