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

/// Junctions: chains of junction edges (edges touching a patch that are not inside one), joined at vertices where
/// exactly two junction edges meet with the same patches.
void add_junctions(const Arrangement3& arr, const std::vector<int>& region,
                   const std::vector<std::vector<int>>& patches_of_region, Complex* c) {
  const auto& edges = arr.edges();
  std::vector<std::vector<int>> edge_patches(edges.size());
  std::vector<int> junction_edges;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (joins_region(arr, edges[e])) continue;
    std::vector<int>& ps = edge_patches[e];
    for (int t : edges[e].triangles) {
      const int r = region[static_cast<std::size_t>(t)];
      if (r >= 0) ps.insert(ps.end(), patches_of_region[static_cast<std::size_t>(r)].begin(),
                            patches_of_region[static_cast<std::size_t>(r)].end());
    }
    std::sort(ps.begin(), ps.end());
    ps.erase(std::unique(ps.begin(), ps.end()), ps.end());
    if (!ps.empty()) junction_edges.push_back(static_cast<int>(e));
  }
  std::vector<std::vector<int>> at_vertex(arr.vertices().size());
  for (int e : junction_edges) {
    at_vertex[static_cast<std::size_t>(edges[static_cast<std::size_t>(e)].a)].push_back(e);
    at_vertex[static_cast<std::size_t>(edges[static_cast<std::size_t>(e)].b)].push_back(e);
  }
  DisjointSets chains(edges.size());
  for (const auto& list : at_vertex)
    if (list.size() == 2 && edge_patches[static_cast<std::size_t>(list[0])] == edge_patches[static_cast<std::size_t>(list[1])])
      chains.union_set(static_cast<std::size_t>(list[0]), static_cast<std::size_t>(list[1]));
  std::vector<char> keep(edges.size(), 0);
  for (int e : junction_edges) keep[static_cast<std::size_t>(e)] = 1;
  const auto members = components_of(chains, edges.size()).members(keep);
  for (const auto& chain : members) {
    const int j = static_cast<int>(c->junctions.size());
    c->junctions.push_back(Junction{edge_patches[static_cast<std::size_t>(chain.front())], chain.front()});
    for (int p : c->junctions.back().patches) c->patches[static_cast<std::size_t>(p)].junctions.push_back(j);
  }
  for (Patch& p : c->patches) {
    std::sort(p.junctions.begin(), p.junctions.end());
    p.junctions.erase(std::unique(p.junctions.begin(), p.junctions.end()), p.junctions.end());
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
    out.witness = {cell.interior.x, cell.interior.y, cell.interior.z};
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
  add_junctions(arr, region, patches_of_region, &c);
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
