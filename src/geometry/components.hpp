// Connected components through Boost, numbered the way hsx's outputs need them. Private header of the library; it
// lives in geometry/, the lowest layer that uses it, so that geometry, complex and algorithms share it.
//
// Convention: components are numbered 0, 1, ... in order of their lowest element (many outputs are ordered by
// lowest index, and Boost's own numbering is not promised to be that).
#pragma once

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hsx {

/// Union-find over the elements 0..n-1: Boost's disjoint sets (union by rank, path compression).
///   DisjointSets sets(n); sets.union_set(a, b); sets.find_set(a) -> representative (an arbitrary member)
/// Elements are ints in [0, n); Boost grows the storage silently for larger ones, so callers keep them in range.
using DisjointSets = boost::disjoint_sets_with_storage<>;

/// Boost's disjoint sets over 0..n-1 on storage that is kept between uses: reset(n) starts again from n singletons
/// without allocating once the storage has grown, for callers that run many small union-finds (keep the object per
/// thread). Same operations as DisjointSets.
class ReusableDisjointSets {
 public:
  void reset(std::size_t n) {
    rank_.assign(n, 0);
    parent_.resize(n);
    sets_ = boost::disjoint_sets<int*, int*>(rank_.data(), parent_.data());
    for (std::size_t e = 0; e < n; ++e) sets_.make_set(static_cast<int>(e));
  }
  int find_set(int e) { return sets_.find_set(e); }
  void link(int a, int b) { sets_.link(a, b); }
  void union_set(int a, int b) { sets_.union_set(a, b); }

 private:
  std::vector<int> rank_, parent_;
  boost::disjoint_sets<int*, int*> sets_{nullptr, nullptr};
};

/// A partition of 0..n-1 into components, numbered by lowest element.
struct Components {
  std::vector<int> of;  ///< per element (size n) its component in 0..count-1
  int count = 0;        ///< number of components (0 when n = 0)

  /// The members of each component, ascending, components in number order (size count).
  std::vector<std::vector<int>> members() const {
    std::vector<std::vector<int>> out(static_cast<std::size_t>(count));
    for (std::size_t e = 0; e < of.size(); ++e) out[static_cast<std::size_t>(of[e])].push_back(static_cast<int>(e));
    return out;
  }

  /// The same, but only the elements with keep[e] != 0 (keep: one flag per element); components without a kept
  /// element are left out, the others stay in number order, i.e. ordered by their lowest kept element.
  std::vector<std::vector<int>> members(const std::vector<char>& keep) const {
    if (keep.size() != of.size())
      throw std::invalid_argument("Components::members: " + std::to_string(keep.size()) + " flags for " +
                                  std::to_string(of.size()) + " elements");
    std::vector<std::vector<int>> out;
    std::vector<int> slot(static_cast<std::size_t>(count), -1);
    for (std::size_t e = 0; e < of.size(); ++e) {
      if (!keep[e]) continue;
      int& s = slot[static_cast<std::size_t>(of[e])];
      if (s < 0) {
        s = static_cast<int>(out.size());
        out.emplace_back();
      }
      out[static_cast<std::size_t>(s)].push_back(static_cast<int>(e));
    }
    return out;
  }
};

/// Renumbers a labelling of 0..n-1 (label[e] >= 0 names e's component; labels need not be dense) by lowest element:
/// element 0's component becomes 0, the next element with a label not seen yet starts component 1, and so on.
/// Throws std::invalid_argument for a negative label.
inline Components components_by_lowest(const std::vector<int>& label) {
  Components c;
  c.of.resize(label.size());
  std::vector<int> number_of_label;  // per label its component number, -1 until seen
  for (std::size_t e = 0; e < label.size(); ++e) {
    const int l = label[e];
    if (l < 0) throw std::invalid_argument("components_by_lowest: negative label " + std::to_string(l));
    const std::size_t slot = static_cast<std::size_t>(l);
    if (slot >= number_of_label.size()) number_of_label.resize(slot + 1, -1);
    int& number = number_of_label[slot];
    if (number < 0) number = c.count++;
    c.of[e] = number;
  }
  return c;
}

/// The sets of `sets` (a DisjointSets over 0..n-1, n its element count) as components numbered by lowest element.
inline Components components_of(DisjointSets& sets, std::size_t n) {
  std::vector<int> root(n);
  for (std::size_t e = 0; e < n; ++e) root[e] = static_cast<int>(sets.find_set(e));
  return components_by_lowest(root);
}

/// Connected components (boost::connected_components) of the undirected graph on the vertices 0..n-1 with the
/// given edges (pairs of vertices; loops and repeated edges are fine), numbered by lowest vertex. Throws
/// std::out_of_range when an edge end is outside [0, n).
inline Components graph_components(std::size_t n, const std::vector<std::pair<int, int>>& edges) {
  boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS> graph(n);
  for (const auto& [a, b] : edges) {
    if (a < 0 || b < 0 || static_cast<std::size_t>(a) >= n || static_cast<std::size_t>(b) >= n)
      throw std::out_of_range("graph_components: edge (" + std::to_string(a) + ", " + std::to_string(b) +
                              ") outside the " + std::to_string(n) + " vertices");
    boost::add_edge(static_cast<std::size_t>(a), static_cast<std::size_t>(b), graph);
  }
  std::vector<int> label(n);
  if (n > 0) boost::connected_components(graph, label.data());
  return components_by_lowest(label);
}

/// Connected components of the subgraph on `vertices` (ascending and distinct, any ints) with the given edges
/// (pairs of entries of `vertices`): each component as its vertices, ascending, components ordered by their lowest
/// vertex. The graph is built on `vertices` alone, so the cost does not depend on how large the ids are. Throws
/// std::out_of_range when an edge end is not in `vertices`.
inline std::vector<std::vector<int>> induced_components(const std::vector<int>& vertices,
                                                        const std::vector<std::pair<int, int>>& edges) {
  auto position = [&](int v) {
    const auto it = std::lower_bound(vertices.begin(), vertices.end(), v);
    if (it == vertices.end() || *it != v)
      throw std::out_of_range("induced_components: edge end " + std::to_string(v) + " is not a vertex");
    return static_cast<int>(it - vertices.begin());
  };
  std::vector<std::pair<int, int>> local;
  local.reserve(edges.size());
  for (const auto& [a, b] : edges) local.emplace_back(position(a), position(b));
  std::vector<std::vector<int>> out = graph_components(vertices.size(), local).members();
  for (auto& component : out)
    for (int& v : component) v = vertices[static_cast<std::size_t>(v)];
  return out;
}

}  // namespace hsx
