#include <hsx/complex/from_arrangement2.hpp>

#include <algorithm>
#include <array>
#include <memory>

namespace hsx {
namespace {

/// Edges that can belong to a patch: on some halfspace's boundary and not on the domain box.
bool patch_edge(const ArrEdge2& e) { return !e.on_box && !e.halfspaces.empty(); }

struct Chain {
  std::vector<int> edges;   // in walk order
  std::vector<int> ends;    // end vertices (none for a closed loop)
};

/// Maximal runs of patch edges through degree-2 vertices (at such a vertex both edges lie on the same curves).
std::vector<Chain> chains_of(const Arrangement2& arr) {
  const auto& edges = arr.edges();
  const auto& vertices = arr.vertices();
  // Per vertex of degree 2: its two edges (runs continue only through those).
  std::vector<std::array<int, 2>> pair(vertices.size(), {-1, -1});
  for (int e = 0; e < static_cast<int>(edges.size()); ++e)
    for (int v : {edges[e].source, edges[e].target})
      if (vertices[v].degree == 2) pair[v][pair[v][0] < 0 ? 0 : 1] = e;
  // The other patch edge through v continuing edge e, or -1 when the run ends at v.
  auto continuation = [&](int e, int v) {
    if (vertices[v].degree != 2) return -1;
    const int other = pair[v][0] == e ? pair[v][1] : pair[v][0];
    if (!patch_edge(edges[other]) || edges[other].halfspaces != edges[e].halfspaces) return -1;
    return other;
  };
  std::vector<char> used(edges.size(), 0);
  std::vector<Chain> chains;
  for (int start = 0; start < static_cast<int>(edges.size()); ++start) {
    if (used[start] || !patch_edge(edges[start])) continue;
    // Walk backwards from start's source to find the run's first edge (or detect a closed loop).
    int first = start, v = edges[start].source;
    bool closed = false;
    for (;;) {
      const int prev = continuation(first, v);
      if (prev < 0) break;
      if (prev == start) { closed = true; break; }
      v = edges[prev].source == v ? edges[prev].target : edges[prev].source;
      first = prev;
    }
    Chain chain;
    int e = first, w = v;  // w: the vertex e is entered from
    if (!closed) chain.ends.push_back(v);
    for (;;) {
      chain.edges.push_back(e);
      used[e] = 1;
      const int exit = edges[e].source == w ? edges[e].target : edges[e].source;
      const int next = continuation(e, exit);
      if (next < 0) { chain.ends.push_back(exit); break; }
      if (next == first) break;  // closed loop
      e = next;
      w = exit;
    }
    chains.push_back(std::move(chain));
  }
  return chains;
}

/// The chains' lengths (sums of their edges' lengths), each computed on first read.
std::shared_ptr<const MeasureCache> chain_lengths(const Arrangement2& arr, const std::vector<Chain>& chains) {
  std::vector<std::vector<int>> chain_edges;
  chain_edges.reserve(chains.size());
  for (const Chain& chain : chains) chain_edges.push_back(chain.edges);
  return std::make_shared<const MeasureCache>(
      chains.size(), [edge_lengths = arr.edge_lengths(), chain_edges = std::move(chain_edges)](std::size_t k) {
        Measure length;
        for (int e : chain_edges[k]) length += edge_lengths->get(static_cast<std::size_t>(e));
        return length;
      });
}

}  // namespace

Complex complex_from_arrangement(const Scene2& scene, const Arrangement2& arr) {
  Complex c;
  c.dimension = 2;
  for (const auto& h : scene.halfspaces) c.halfspace_names.push_back(h.name);
  c.cells.reserve(arr.faces().size());
  const auto witnesses = std::make_shared<const LazyCache<std::vector<Rational>>>(
      arr.faces().size(), [interiors = arr.face_interiors()](std::size_t f) {
        const PointQ2& p = interiors->get(f);
        return std::vector<Rational>{p.x, p.y};
      });
  for (const ArrFace2& f : arr.faces()) {
    Cell cell;
    cell.outer = f.outer;
    cell.witness = Lazy<std::vector<Rational>>(witnesses, c.cells.size());
    cell.inside = f.inside;
    cell.measure = LazyMeasure(arr.face_areas(), c.cells.size());
    c.cells.push_back(std::move(cell));
  }
  const auto& edges = arr.edges();
  std::vector<int> junction_of_vertex(arr.vertices().size(), -1);
  std::vector<int> chain_of_edge(edges.size(), -1);
  std::vector<std::vector<int>> patches_of_chain;
  const std::vector<Chain> chains = chains_of(arr);
  const auto lengths = chain_lengths(arr, chains);
  std::size_t patch_count = 0;
  for (const Chain& chain : chains) patch_count += edges[chain.edges.front()].halfspaces.size();
  c.patches.reserve(patch_count);
  c.supports.reserve(chains.size());
  patches_of_chain.reserve(chains.size());
  // Junctions: the chains' end vertices, numbered in the order the chains first reach them.
  int junction_count = 0;
  for (const Chain& chain : chains)
    for (int v : chain.ends) {
      int& junction = junction_of_vertex[static_cast<std::size_t>(v)];
      if (junction < 0) junction = junction_count++;
    }
  c.junctions.resize(static_cast<std::size_t>(junction_count));
  for (std::size_t v = 0; v < junction_of_vertex.size(); ++v)
    if (const int j = junction_of_vertex[v]; j >= 0)
      c.junctions[static_cast<std::size_t>(j)].piece = static_cast<int>(v);
  for (int k = 0; k < static_cast<int>(chains.size()); ++k) {
    const Chain& chain = chains[k];
    const ArrEdge2& e0 = edges[chain.edges.front()];
    for (int e : chain.edges) chain_of_edge[e] = k;
    std::vector<int> junctions;
    junctions.reserve(chain.ends.size());
    for (int v : chain.ends) junctions.push_back(junction_of_vertex[static_cast<std::size_t>(v)]);
    const int support = static_cast<int>(c.supports.size());
    c.supports.emplace_back();
    patches_of_chain.emplace_back();
    for (int h : e0.halfspaces) {
      Patch p;
      p.halfspace = h;
      const bool left_inside = c.cells.at(e0.left_face).inside[h];
      p.inside_cell = left_inside ? e0.left_face : e0.right_face;
      p.outside_cell = left_inside ? e0.right_face : e0.left_face;
      p.measure = LazyMeasure(lengths, static_cast<std::size_t>(k));
      p.support = support;
      p.junctions = junctions;
      p.pieces = chain.edges;
      const int id = static_cast<int>(c.patches.size());
      c.supports[support].push_back(id);
      patches_of_chain[k].push_back(id);
      for (int j : junctions) c.junctions[j].patches.push_back(id);
      c.patches.push_back(std::move(p));
    }
  }
  for (auto& j : c.junctions) {
    std::sort(j.patches.begin(), j.patches.end());
    j.patches.erase(std::unique(j.patches.begin(), j.patches.end()), j.patches.end());
  }
  for (std::size_t s = 0; s < scene.samples.size(); ++s) {
    const int h = scene.samples[s].halfspace;
    int patch = -1;
    for (int p : patches_of_chain.at(chain_of_edge.at(arr.sample_edges()[s])))
      if (c.patches[p].halfspace == h) patch = p;
    c.samples.push_back({h, patch});
    c.patches.at(patch).samples.push_back(static_cast<int>(s));
  }
  return c;
}

Arranged2 arrange(const Scene2& scene, const ArrangementLimits& limits) {
  Arranged2 out{Arrangement2::build(scene, limits), {}};
  out.complex = complex_from_arrangement(scene, out.arrangement);
  return out;
}

Arranged2 arrange(const Scene2& scene, const Arrangement2& arrangement) {
  Arranged2 out{arrangement.with_samples(scene), {}};
  out.complex = complex_from_arrangement(scene, out.arrangement);
  return out;
}

}  // namespace hsx
