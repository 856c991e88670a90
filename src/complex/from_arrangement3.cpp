#include <hsx/complex/from_arrangement3.hpp>
#include "geometry/components.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace hsx {
namespace {

/// An edge inside a patch region: exactly two triangles, neither on the box, on the same boundaries.
bool joins_region(const Arrangement3& arr, const ArrEdge3& e) {
  if (e.triangles.size() != 2) return false;
  const ArrTriangle3& s = arr.triangles()[static_cast<std::size_t>(e.triangles[0])];
  const ArrTriangle3& t = arr.triangles()[static_cast<std::size_t>(e.triangles[1])];
  return !s.on_box && !t.on_box && !s.halfspaces.empty() && s.halfspaces == t.halfspaces;
}

bool patch_triangle(const ArrTriangle3& t) { return !t.on_box && !t.halfspaces.empty(); }

/// Patch regions: triangles of patches joined across region edges, numbered by lowest triangle (-1: none).
std::vector<int> patch_regions(const Arrangement3& arr, int* count) {
  const std::size_t n = arr.triangles().size();
  DisjointSets sets(n);
  for (const ArrEdge3& e : arr.edges())
    if (joins_region(arr, e)) sets.union_set(static_cast<std::size_t>(e.triangles[0]), static_cast<std::size_t>(e.triangles[1]));
  std::vector<char> keep(n);
  for (std::size_t t = 0; t < n; ++t) keep[t] = patch_triangle(arr.triangles()[t]);
  const auto members = components_of(sets, n).members(keep);
  std::vector<int> region(n, -1);
  for (std::size_t r = 0; r < members.size(); ++r)
    for (int t : members[r]) region[static_cast<std::size_t>(t)] = static_cast<int>(r);
  *count = static_cast<int>(members.size());
  return region;
}

/// The sheets along each edge (Junction::sheets): the lowest patch of the region of each patch triangle on it,
/// sorted; empty for edges inside a patch region and edges touching no patch.
std::vector<std::vector<int>> edge_sheets(const Arrangement3& arr, const std::vector<int>& region,
                                          const std::vector<std::vector<int>>& patches_of_region) {
  const auto& edges = arr.edges();
  std::vector<std::vector<int>> sheets(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (joins_region(arr, edges[e])) continue;
    for (int t : edges[e].triangles) {
      const int r = region[static_cast<std::size_t>(t)];
      if (r >= 0) sheets[e].push_back(patches_of_region[static_cast<std::size_t>(r)].front());
    }
    std::sort(sheets[e].begin(), sheets[e].end());
  }
  return sheets;
}

/// Every edge id at each vertex.
std::vector<std::vector<int>> edges_at_vertices(const Arrangement3& arr) {
  std::vector<std::vector<int>> at(arr.vertices().size());
  for (std::size_t e = 0; e < arr.edges().size(); ++e) {
    at[static_cast<std::size_t>(arr.edges()[e].a)].push_back(static_cast<int>(e));
    at[static_cast<std::size_t>(arr.edges()[e].b)].push_back(static_cast<int>(e));
  }
  return at;
}

/// Junctions: chains of junction edges (edges touching a patch that are not inside one), joined at vertices where
/// exactly two junction edges meet with the same sheets. Returns each edge's junction (-1: none).
std::vector<int> add_junctions(const Arrangement3& arr, const std::vector<int>& region,
                               const std::vector<std::vector<int>>& patches_of_region,
                               const std::vector<std::vector<int>>& at_vertex, Complex* c) {
  const auto& edges = arr.edges();
  const std::vector<std::vector<int>> sheets = edge_sheets(arr, region, patches_of_region);
  DisjointSets chains(edges.size());
  for (const auto& all : at_vertex) {
    std::vector<int> list;
    for (int e : all)
      if (!sheets[static_cast<std::size_t>(e)].empty()) list.push_back(e);
    if (list.size() == 2 && sheets[static_cast<std::size_t>(list[0])] == sheets[static_cast<std::size_t>(list[1])])
      chains.union_set(static_cast<std::size_t>(list[0]), static_cast<std::size_t>(list[1]));
  }
  std::vector<char> keep(edges.size(), 0);
  for (std::size_t e = 0; e < edges.size(); ++e) keep[e] = !sheets[e].empty();
  std::vector<int> junction_of(edges.size(), -1);
  for (const auto& chain : components_of(chains, edges.size()).members(keep)) {
    const int j = static_cast<int>(c->junctions.size());
    Junction junction;
    junction.piece = chain.front();
    junction.sheets = sheets[static_cast<std::size_t>(chain.front())];
    for (int e : chain) {
      junction_of[static_cast<std::size_t>(e)] = j;
      for (int t : edges[static_cast<std::size_t>(e)].triangles) {
        const int r = region[static_cast<std::size_t>(t)];
        if (r >= 0)
          junction.patches.insert(junction.patches.end(), patches_of_region[static_cast<std::size_t>(r)].begin(),
                                  patches_of_region[static_cast<std::size_t>(r)].end());
      }
    }
    std::sort(junction.patches.begin(), junction.patches.end());
    junction.patches.erase(std::unique(junction.patches.begin(), junction.patches.end()), junction.patches.end());
    for (int p : junction.patches) c->patches[static_cast<std::size_t>(p)].junctions.push_back(j);
    c->junctions.push_back(std::move(junction));
  }
  for (Patch& p : c->patches) {
    std::sort(p.junctions.begin(), p.junctions.end());
    p.junctions.erase(std::unique(p.junctions.begin(), p.junctions.end()), p.junctions.end());
  }
  return junction_of;
}

/// The corner at vertex v (complex.hpp): fans of patch triangles around v joined across region edges, spokes the
/// junction edges at v. `triangle_at`: scratch, -1 for every triangle on entry and exit.
Corner corner_at(const Arrangement3& arr, int v, const std::vector<int>& region,
                 const std::vector<std::vector<int>>& patches_of_region, const std::vector<int>& edges_at_v,
                 const std::vector<int>& junction_of, std::vector<int>& triangle_at) {
  Corner corner;
  corner.piece = v;
  std::vector<int> local;  // patch triangles at v
  for (int e : edges_at_v)
    for (int t : arr.edges()[static_cast<std::size_t>(e)].triangles)
      if (region[static_cast<std::size_t>(t)] >= 0 && triangle_at[static_cast<std::size_t>(t)] < 0) {
        triangle_at[static_cast<std::size_t>(t)] = static_cast<int>(local.size());
        local.push_back(t);
      }
  DisjointSets fans(local.size());
  std::vector<std::pair<int, int>> ends;  // (local triangle, spoke)
  for (int e : edges_at_v) {
    const ArrEdge3& edge = arr.edges()[static_cast<std::size_t>(e)];
    if (joins_region(arr, edge)) {
      fans.union_set(static_cast<std::size_t>(triangle_at[static_cast<std::size_t>(edge.triangles[0])]),
                     static_cast<std::size_t>(triangle_at[static_cast<std::size_t>(edge.triangles[1])]));
    } else if (junction_of[static_cast<std::size_t>(e)] >= 0) {
      const int spoke = static_cast<int>(corner.spokes.size());
      corner.spokes.push_back(junction_of[static_cast<std::size_t>(e)]);
      for (int t : edge.triangles)
        if (region[static_cast<std::size_t>(t)] >= 0) ends.emplace_back(triangle_at[static_cast<std::size_t>(t)], spoke);
    }
  }
  const Components comp = components_of(fans, local.size());
  std::vector<std::vector<int>> fan_ends(static_cast<std::size_t>(comp.count));
  for (const auto& [t, spoke] : ends) fan_ends[static_cast<std::size_t>(comp.of[static_cast<std::size_t>(t)])].push_back(spoke);
  for (int f = 0; f < comp.count; ++f) {
    const std::vector<int>& fe = fan_ends[static_cast<std::size_t>(f)];
    if (fe.size() != 0 && fe.size() != 2)
      throw std::logic_error("complex_from_arrangement: a fan of patch triangles with " + std::to_string(fe.size()) +
                             " ends at vertex " + std::to_string(v));
    const int t = local[static_cast<std::size_t>(std::find(comp.of.begin(), comp.of.end(), f) - comp.of.begin())];
    const int patch = patches_of_region[static_cast<std::size_t>(region[static_cast<std::size_t>(t)])].front();
    corner.wedges.push_back(fe.empty() ? Corner::Wedge{patch, -1, -1}
                                       : Corner::Wedge{patch, std::min(fe[0], fe[1]), std::max(fe[0], fe[1])});
  }
  for (int t : local) triangle_at[static_cast<std::size_t>(t)] = -1;
  return corner;
}

/// A corner the junctions settle: one whole disc and no spoke (inside a patch), or two spokes that every fan
/// joins (along a junction).
bool settled(const Corner& corner) {
  if (corner.spokes.empty()) return corner.wedges.size() == 1;
  if (corner.spokes.size() != 2) return false;
  return std::all_of(corner.wedges.begin(), corner.wedges.end(),
                     [](const Corner::Wedge& w) { return w.from == 0 && w.to == 1; });
}

/// Complex::corners: every vertex touching a patch whose corner is not settled.
void add_corners(const Arrangement3& arr, const std::vector<int>& region,
                 const std::vector<std::vector<int>>& patches_of_region, const std::vector<std::vector<int>>& at_vertex,
                 const std::vector<int>& junction_of, Complex* c) {
  std::vector<int> triangle_at(arr.triangles().size(), -1);
  for (std::size_t v = 0; v < at_vertex.size(); ++v) {
    Corner corner = corner_at(arr, static_cast<int>(v), region, patches_of_region, at_vertex[v], junction_of, triangle_at);
    if (!corner.wedges.empty() && !settled(corner)) c->corners.push_back(std::move(corner));
  }
}

}  // namespace

Complex complex_from_arrangement(const Scene3& scene, const Arrangement3& arr) {
  Complex c;
  c.dimension = 3;
  for (const auto& h : scene.halfspaces) c.halfspace_names.push_back(h.name);
  for (const ArrCell3& cell : arr.cells()) {
    Cell out;
    out.outer = cell.outer;
    out.witness = std::vector<Rational>{cell.interior.x, cell.interior.y, cell.interior.z};
    out.inside = cell.inside;
    if (cell.volume) out.measure = Measure(*cell.volume);
    c.cells.push_back(std::move(out));
  }
  int regions = 0;
  const std::vector<int> region = patch_regions(arr, &regions);
  std::vector<std::vector<int>> triangles_of(static_cast<std::size_t>(regions));
  for (std::size_t t = 0; t < region.size(); ++t)
    if (region[t] >= 0) triangles_of[static_cast<std::size_t>(region[t])].push_back(static_cast<int>(t));
  std::vector<std::vector<int>> patches_of_region(static_cast<std::size_t>(regions));
  for (int r = 0; r < regions; ++r) {
    const auto& tris = triangles_of[static_cast<std::size_t>(r)];
    const ArrTriangle3& first = arr.triangles()[static_cast<std::size_t>(tris.front())];
    Measure area;
    for (int t : tris) area += Measure::sqrt_of(arr.triangles()[static_cast<std::size_t>(t)].area2 / 4);
    const int support = static_cast<int>(c.supports.size());
    c.supports.emplace_back();
    for (std::size_t k = 0; k < first.halfspaces.size(); ++k) {
      Patch p;
      p.halfspace = first.halfspaces[k];
      p.inside_cell = first.front_inside[k] ? first.front_cell : first.back_cell;
      p.outside_cell = first.front_inside[k] ? first.back_cell : first.front_cell;
      p.measure = area;
      p.support = support;
      p.pieces = tris;
      const int id = static_cast<int>(c.patches.size());
      c.supports.back().push_back(id);
      patches_of_region[static_cast<std::size_t>(r)].push_back(id);
      c.patches.push_back(std::move(p));
    }
  }
  const std::vector<std::vector<int>> at_vertex = edges_at_vertices(arr);
  const std::vector<int> junction_of = add_junctions(arr, region, patches_of_region, at_vertex, &c);
  add_corners(arr, region, patches_of_region, at_vertex, junction_of, &c);
  for (std::size_t s = 0; s < scene.samples.size(); ++s) {
    const int h = scene.samples[s].halfspace;
    const int r = region.at(static_cast<std::size_t>(arr.sample_triangles().at(s)));
    int patch = -1;
    for (int p : patches_of_region.at(static_cast<std::size_t>(r)))
      if (c.patches[static_cast<std::size_t>(p)].halfspace == h) patch = p;
    if (patch < 0) throw std::logic_error("complex_from_arrangement: a sample's triangle has no patch of its halfspace");
    c.samples.push_back({h, patch});
    c.patches[static_cast<std::size_t>(patch)].samples.push_back(static_cast<int>(s));
  }
  return c;
}

Arranged3 arrange(const Scene3& scene, const ArrangementLimits& limits, const Arrangement3Options& options) {
  Arranged3 out{Arrangement3::build(scene, limits, options), {}};
  const auto start = std::chrono::steady_clock::now();
  out.complex = complex_from_arrangement(scene, out.arrangement);
  if (options.timings != nullptr)
    options.timings->add("complex", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return out;
}

}  // namespace hsx
