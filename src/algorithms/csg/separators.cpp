#include <hsx/algorithms/csg/separators.hpp>

#include <hsx/complex/carry_solid2.hpp>

#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>

namespace hsx::csg {
namespace {

/// The line through two distinct rational points.
std::optional<SeparatorLine> line_through(const PointQ2& p, const PointQ2& q) {
  if (p == q) return std::nullopt;
  const PointQ2 n{q.y - p.y, p.x - q.x};
  return SeparatorLine{n, n.x * p.x + n.y * p.y};
}

void add_polygon_edge_lines(const Scene2& scene, std::vector<SeparatorLine>& out) {
  for (const Halfspace2& h : scene.halfspaces) {
    if (h.kind != HalfspaceKind2::Polygon) continue;
    for (std::size_t k = 0; k < h.vertices.size(); ++k)
      if (auto l = line_through(h.vertices[k], h.vertices[(k + 1) % h.vertices.size()])) out.push_back(*l);
  }
}

void add_complemented_halfplanes(const Scene2& scene, std::vector<SeparatorLine>& out) {
  for (const Halfspace2& h : scene.halfspaces)
    if (h.kind == HalfspaceKind2::Halfplane) out.push_back({PointQ2{-h.normal.x, -h.normal.y}, -h.offset});
}

void add_vertex_pair_lines(const Arranged2& arranged, std::vector<SeparatorLine>& out) {
  std::vector<PointQ2> rational_vertices;
  for (const ArrVertex2& v : arranged.arrangement.vertices())
    if (v.point.is_rational() && v.degree > 2) rational_vertices.push_back({v.point.x.a0, v.point.y.a0});
  for (std::size_t a = 0; a < rational_vertices.size(); ++a)
    for (std::size_t b = a + 1; b < rational_vertices.size(); ++b)
      if (auto l = line_through(rational_vertices[a], rational_vertices[b])) out.push_back(*l);
}

void add_radical_axes(const Scene2& scene, std::vector<SeparatorLine>& out) {
  const auto& hs = scene.halfspaces;
  for (std::size_t a = 0; a < hs.size(); ++a)
    for (std::size_t b = a + 1; b < hs.size(); ++b) {
      if (hs[a].kind != HalfspaceKind2::Disk || hs[b].kind != HalfspaceKind2::Disk || hs[a].center == hs[b].center)
        continue;
      // |x - c1|^2 - r1^2 = |x - c2|^2 - r2^2.
      const PointQ2& c1 = hs[a].center;
      const PointQ2& c2 = hs[b].center;
      const PointQ2 n{2 * (c2.x - c1.x), 2 * (c2.y - c1.y)};
      const Rational offset = c2.x * c2.x + c2.y * c2.y - c1.x * c1.x - c1.y * c1.y - hs[b].radius * hs[b].radius +
                              hs[a].radius * hs[a].radius;
      out.push_back({n, offset});
    }
}

void add_witness_bisectors(const Arranged2& arranged, const Describability& mixed, std::vector<SeparatorLine>& out) {
  const LazyCache<PointQ2>& interiors = *arranged.arrangement.face_interiors();
  for (const auto& term : mixed.mixed)
    for (int i : term.inside_cells)
      for (int o : term.outside_cells) {
        const PointQ2& p = interiors.get(static_cast<std::size_t>(i));
        const PointQ2& q = interiors.get(static_cast<std::size_t>(o));
        const PointQ2 n{q.x - p.x, q.y - p.y};
        const PointQ2 m{(p.x + q.x) / 2, (p.y + q.y) / 2};
        out.push_back({n, n.x * m.x + n.y * m.y});
      }
}

/// Lines equal up to a non-zero factor (of either sign) kept once, first occurrence first.
std::vector<SeparatorLine> unique_lines(const std::vector<SeparatorLine>& lines) {
  std::vector<SeparatorLine> out;
  std::set<std::tuple<Rational, Rational, Rational>> seen;
  for (const auto& l : lines) {
    const Rational s = l.normal.x != 0 ? l.normal.x : l.normal.y;
    if (s == 0) continue;
    if (seen.insert({l.normal.x / s, l.normal.y / s, l.offset / s}).second) out.push_back(l);
  }
  return out;
}

int mixed_cells(const Describability& d) {
  int n = 0;
  for (const auto& t : d.mixed) n += static_cast<int>(t.inside_cells.size() + t.outside_cells.size());
  return n;
}

using Key = std::pair<int, int>;  // (mixed terms, mixed cells)
Key key_of(const Describability& d) { return {static_cast<int>(d.mixed.size()), mixed_cells(d)}; }

/// The current solid with one more separator, or nothing when the line cannot be arranged (through a sample).
std::optional<SeparatedSolid> with_separator(const SeparatedSolid& current, const SeparatorLine& line, Key& key) {
  Scene2 trial = current.scene;
  Halfspace2 h;
  h.name = "sep" + std::to_string(current.separators);
  h.kind = HalfspaceKind2::Halfplane;
  h.normal = line.normal;
  h.offset = line.offset;
  trial.halfspaces.push_back(h);
  try {
    Arranged2 refined = arrange(trial);
    std::vector<char> cells = carry_solid_over(current.arranged.arrangement, current.cells, refined.arrangement);
    key = key_of(describability(refined.complex, cells));
    SeparatedSolid out{std::move(trial), std::move(refined), std::move(cells), current.separators + 1, false};
    return out;
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace

std::vector<SeparatorLine> separator_candidates(const Scene2& scene, const Arranged2& arranged,
                                                const Describability& mixed) {
  std::vector<SeparatorLine> lines;
  add_polygon_edge_lines(scene, lines);
  add_complemented_halfplanes(scene, lines);
  add_vertex_pair_lines(arranged, lines);
  add_radical_axes(scene, lines);
  add_witness_bisectors(arranged, mixed, lines);
  return unique_lines(lines);
}

SeparatedSolid add_separators(const Scene2& scene, const Arranged2& arranged, const std::vector<char>& solid,
                              int max_separators) {
  SeparatedSolid out{scene, arranged, solid, 0, false};
  for (;;) {
    const Describability d = describability(out.arranged.complex, out.cells);
    if (d.describable) {
      out.describable = true;
      out.stop = SeparatorStop::Describable;
      return out;
    }
    if (out.separators >= max_separators) {
      out.stop = SeparatorStop::MaxSeparators;
      return out;
    }
    const std::vector<SeparatorLine> candidates = separator_candidates(out.scene, out.arranged, d);
    const Key now = key_of(d);
    std::optional<SeparatedSolid> best;
    Key best_key;
    for (const SeparatorLine& line : candidates) {
      Key key;
      std::optional<SeparatedSolid> trial = with_separator(out, line, key);
      if (trial && (!best || key < best_key)) {
        best_key = key;
        best = std::move(trial);
      }
    }
    out.candidates_tried = static_cast<int>(candidates.size());
    if (!best || (best_key.first >= now.first && best_key.second >= now.second)) {
      out.stop = SeparatorStop::NoCandidateSeparates;
      return out;
    }
    const int tried = out.candidates_tried;
    out = std::move(*best);
    out.candidates_tried = tried;
  }
}

}  // namespace hsx::csg
