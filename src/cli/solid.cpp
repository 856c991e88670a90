#include "cli/solid.hpp"

#include <hsx/algorithms/csg/describability.hpp>
#include <hsx/io/csg_text.hpp>
#include <hsx/io/exact_json.hpp>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace hsx::cli {

Solid load_solid(const LoadedInput& in, const SolidSource& source) {
  if (source.shape_path.empty() == source.csg.empty())
    throw InputError("give the solid either as a result file (--shape, or --target for samples) or as --csg EXPR, exactly one");
  Solid solid;
  const Complex& complex = in.complex();
  if (!source.shape_path.empty()) {
    try {
      solid.cells = read_result_labelling(read_exact_json_file(source.shape_path),
                                          static_cast<int>(complex.cells.size()));
    } catch (const InputError& e) {
      throw InputError(source.shape_path + ": " + e.what());
    }
    return solid;
  }
  solid.expression = read_csg_argument(source.csg, complex.halfspace_names);
  solid.cells = csg::evaluate(*solid.expression, complex);
  return solid;
}

std::vector<char> planar_halfspaces(const Scene2& scene) {
  std::vector<char> planar;
  for (const auto& h : scene.halfspaces) planar.push_back(h.kind == HalfspaceKind2::Halfplane);
  return planar;
}

namespace {

struct Candidate {
  PointQ2 normal;
  Rational offset;
};

/// The line through two distinct rational points, as normal . x = offset.
std::optional<Candidate> line_through(const PointQ2& p, const PointQ2& q) {
  if (p == q) return std::nullopt;
  const PointQ2 n{q.y - p.y, p.x - q.x};
  return Candidate{n, n.x * p.x + n.y * p.y};
}

}  // namespace

std::vector<char> carry_solid_over(const Arrangement2& old_arrangement, const std::vector<char>& solid,
                                   const Arrangement2& refined) {
  std::vector<char> out;
  for (const ArrFace2& f : refined.faces()) {
    const PointLocation2 loc = old_arrangement.locate(f.interior);
    if (loc.kind != PointLocation2::Face) throw std::logic_error("separator: refined cell not inside an old cell");
    out.push_back(solid[loc.index]);
  }
  return out;
}

namespace {

int mixed_cells(const csg::Describability& d) {
  int n = 0;
  for (const auto& t : d.mixed) n += static_cast<int>(t.inside_cells.size() + t.outside_cells.size());
  return n;
}

}  // namespace

SeparatedSolid add_separators(const Scene2& scene, const Arranged2& arranged, const std::vector<char>& solid,
                              int max_separators) {
  SeparatedSolid out{scene, arranged, solid, 0, false};
  for (;;) {
    const csg::Describability d = csg::describability(out.arranged.complex, out.cells);
    if (d.describable) {
      out.describable = true;
      return out;
    }
    if (out.separators >= max_separators) return out;
    // Candidate lines.
    std::vector<Candidate> candidates;
    std::vector<PointQ2> rational_vertices;
    for (const ArrVertex2& v : out.arranged.arrangement.vertices())
      if (v.point.is_rational() && v.degree > 2) rational_vertices.push_back({v.point.x.a0, v.point.y.a0});
    for (std::size_t a = 0; a < rational_vertices.size(); ++a)
      for (std::size_t b = a + 1; b < rational_vertices.size(); ++b)
        if (auto l = line_through(rational_vertices[a], rational_vertices[b])) candidates.push_back(*l);
    const auto& hs = out.scene.halfspaces;
    for (std::size_t a = 0; a < hs.size(); ++a)
      for (std::size_t b = a + 1; b < hs.size(); ++b)
        if (hs[a].kind == HalfspaceKind2::Disk && hs[b].kind == HalfspaceKind2::Disk && hs[a].center != hs[b].center) {
          // Radical axis: |x - c1|^2 - r1^2 = |x - c2|^2 - r2^2.
          const PointQ2& c1 = hs[a].center;
          const PointQ2& c2 = hs[b].center;
          const PointQ2 n{2 * (c2.x - c1.x), 2 * (c2.y - c1.y)};
          const Rational offset = c2.x * c2.x + c2.y * c2.y - c1.x * c1.x - c1.y * c1.y - hs[b].radius * hs[b].radius +
                                  hs[a].radius * hs[a].radius;
          candidates.push_back({n, offset});
        }
    for (const auto& term : d.mixed)
      for (int i : term.inside_cells)
        for (int o : term.outside_cells) {
          const ArrFace2& fi = out.arranged.arrangement.faces()[i];
          const ArrFace2& fo = out.arranged.arrangement.faces()[o];
          // The perpendicular bisector of the two witnesses separates them.
          const PointQ2 n{fo.interior.x - fi.interior.x, fo.interior.y - fi.interior.y};
          const PointQ2 m{(fi.interior.x + fo.interior.x) / 2, (fi.interior.y + fo.interior.y) / 2};
          candidates.push_back({n, n.x * m.x + n.y * m.y});
        }
    // Deduplicate (lines are equal up to scaling).
    std::vector<Candidate> unique;
    std::set<std::tuple<Rational, Rational, Rational>> seen;
    for (const auto& c : candidates) {
      const Rational s = c.normal.x != 0 ? c.normal.x : c.normal.y;
      if (s == 0) continue;
      if (seen.insert({c.normal.x / s, c.normal.y / s, c.offset / s}).second) unique.push_back(c);
    }
    // Pick the best by exact re-arrangement.
    std::optional<SeparatedSolid> best;
    std::pair<int, int> best_key{0, 0};
    for (const auto& c : unique) {
      Scene2 trial = out.scene;
      Halfspace2 h;
      h.name = "sep" + std::to_string(out.separators);
      h.kind = HalfspaceKind2::Halfplane;
      h.normal = c.normal;
      h.offset = c.offset;
      trial.halfspaces.push_back(h);
      try {
        Arranged2 refined = arrange(trial);
        std::vector<char> cells = carry_solid_over(out.arranged.arrangement, out.cells, refined.arrangement);
        const csg::Describability dd = csg::describability(refined.complex, cells);
        const std::pair<int, int> key{static_cast<int>(dd.mixed.size()), mixed_cells(dd)};
        if (!best || key < best_key) {
          best_key = key;
          best = SeparatedSolid{std::move(trial), std::move(refined), std::move(cells), out.separators + 1, false};
        }
      } catch (const InputError&) {
        continue;  // e.g. the line passes through a sample: not a usable separator
      }
    }
    if (!best || (best_key.first >= static_cast<int>(d.mixed.size()) && best_key.second >= mixed_cells(d)))
      return out;  // no candidate helps
    out = std::move(*best);
  }
}

}  // namespace hsx::cli
