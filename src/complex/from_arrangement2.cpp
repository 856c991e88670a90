#include <hsx/complex/from_arrangement2.hpp>

#include <algorithm>
#include <array>
#include <memory>
#include <stdexcept>

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
  // Every chain's edges in one table: chain k's are edges[first[k] .. first[k + 1]).
  std::vector<int> edges;
  std::vector<std::size_t> first{0};
  first.reserve(chains.size() + 1);
  for (const Chain& chain : chains) {
    edges.insert(edges.end(), chain.edges.begin(), chain.edges.end());
    first.push_back(edges.size());
  }
  return std::make_shared<const MeasureCache>(
      chains.size(),
      [edge_lengths = arr.edge_lengths(), edges = std::move(edges), first = std::move(first)](std::size_t k) {
        Measure length;
        for (std::size_t i = first[k]; i < first[k + 1]; ++i)
          length += edge_lengths->get(static_cast<std::size_t>(edges[i]));
        return length;
      });
}

}  // namespace

Complex complex_from_arrangement(const Scene2& scene, const Arrangement2& arr) {
  Complex c;
  c.dimension = 2;
  for (const auto& h : scene.halfspaces) c.halfspace_names.push_back(h.name);
  const auto& edges = arr.edges();
  std::vector<Chain> chains = chains_of(arr);  // non-const: each chain's edges move into its last patch
  // Chain k gives one patch per halfspace of its edges, numbered from first_patch[k] in chain order.
  std::vector<std::size_t> first_patch(chains.size() + 1, 0);
  std::vector<int> chain_starting_at(edges.size(), -1);
  std::vector<int> patch_halfspace;  // per patch
  for (std::size_t k = 0; k < chains.size(); ++k) {
    const int e0 = chains[k].edges.front();
    chain_starting_at[static_cast<std::size_t>(e0)] = static_cast<int>(k);
    const auto& halfspaces = edges[static_cast<std::size_t>(e0)].halfspaces;
    patch_halfspace.insert(patch_halfspace.end(), halfspaces.begin(), halfspaces.end());
    first_patch[k + 1] = patch_halfspace.size();
  }
  const std::size_t patch_count = patch_halfspace.size();
  // Per patch: whether the face left of its chain's first edge lies inside the patch's halfspace (2: not seen).
  // Read while each face's sides are copied into its cell, so the faces' side tables are read in order, once.
  std::vector<char> left_inside(patch_count, 2);

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
    for (const auto& cycle : f.boundary)
      for (const auto& [e, forward] : cycle) {
        const int k = forward ? chain_starting_at[static_cast<std::size_t>(e)] : -1;
        if (k < 0) continue;
        for (std::size_t p = first_patch[static_cast<std::size_t>(k)]; p < first_patch[static_cast<std::size_t>(k) + 1]; ++p)
          left_inside[p] = f.inside[static_cast<std::size_t>(patch_halfspace[p])];
      }
  }
  std::vector<int> junction_of_vertex(arr.vertices().size(), -1);
  std::vector<int> chain_of_edge(edges.size(), -1);
  std::vector<std::vector<int>> patches_of_chain;
  const auto lengths = chain_lengths(arr, chains);
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
  {
    std::vector<std::size_t> ending(static_cast<std::size_t>(junction_count), 0);  // patches ending at each junction
    for (std::size_t k = 0; k < chains.size(); ++k)
      for (int v : chains[k].ends)
        ending[static_cast<std::size_t>(junction_of_vertex[static_cast<std::size_t>(v)])] +=
            first_patch[k + 1] - first_patch[k];
    for (std::size_t j = 0; j < ending.size(); ++j) c.junctions[j].patches.reserve(ending[j]);
  }
  for (std::size_t v = 0; v < junction_of_vertex.size(); ++v)
    if (const int j = junction_of_vertex[v]; j >= 0)
      c.junctions[static_cast<std::size_t>(j)].piece = static_cast<int>(v);
  for (int k = 0; k < static_cast<int>(chains.size()); ++k) {
    Chain& chain = chains[k];
    const ArrEdge2& e0 = edges[chain.edges.front()];
    for (int e : chain.edges) chain_of_edge[e] = k;
    std::vector<int> junctions;
    junctions.reserve(chain.ends.size());
    for (int v : chain.ends) junctions.push_back(junction_of_vertex[static_cast<std::size_t>(v)]);
    const int support = static_cast<int>(c.supports.size());
    c.supports.emplace_back();
    patches_of_chain.emplace_back();
    for (std::size_t i = 0; i < e0.halfspaces.size(); ++i) {
      const int id = static_cast<int>(c.patches.size());
      const char left = left_inside[static_cast<std::size_t>(id)];
      if (left == 2) throw std::logic_error("complex_from_arrangement: a patch edge with no face on its left");
      c.supports[support].push_back(id);
      patches_of_chain[k].push_back(id);
      for (int j : junctions) c.junctions[j].patches.push_back(id);
      Patch& p = c.patches.emplace_back();  // reserved above
      p.halfspace = e0.halfspaces[i];
      p.inside_cell = left ? e0.left_face : e0.right_face;
      p.outside_cell = left ? e0.right_face : e0.left_face;
      p.measure = LazyMeasure(lengths, static_cast<std::size_t>(k));
      p.support = support;
      const bool last = i + 1 == e0.halfspaces.size();  // the chain's last patch takes its lists, the others copy
      p.junctions = last ? std::move(junctions) : junctions;
      p.pieces = last ? std::move(chain.edges) : chain.edges;
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
