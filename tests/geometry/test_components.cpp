// Tests of geometry/components.hpp (Boost disjoint sets and connected_components, numbered by lowest element)
// against a brute-force oracle: reachability by repeated relaxation over the edge list.
#include "geometry/components.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <utility>
#include <vector>

using namespace hsx;

namespace {

using Edges = std::vector<std::pair<int, int>>;

/// Per vertex the lowest vertex it reaches (its component's lowest element), by relaxing every edge until nothing
/// changes: quadratic, obviously right.
std::vector<int> lowest_reached(std::size_t n, const Edges& edges) {
  std::vector<int> low(n);
  for (std::size_t v = 0; v < n; ++v) low[v] = static_cast<int>(v);
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [a, b] : edges) {
      const int m = std::min(low[static_cast<std::size_t>(a)], low[static_cast<std::size_t>(b)]);
      for (int v : {a, b})
        if (low[static_cast<std::size_t>(v)] != m) {
          low[static_cast<std::size_t>(v)] = m;
          changed = true;
        }
    }
  }
  return low;
}

/// The oracle's numbering: components in order of their lowest element.
Components oracle(std::size_t n, const Edges& edges) {
  const std::vector<int> low = lowest_reached(n, edges);
  Components c;
  std::vector<int> number(n, -1);
  for (std::size_t v = 0; v < n; ++v) {
    int& k = number[static_cast<std::size_t>(low[v])];
    if (k < 0) k = c.count++;
    c.of.push_back(k);
  }
  return c;
}

Edges random_edges(int n) {
  if (n == 0) return {};
  const auto vertex = rc::gen::inRange(0, n);
  return *rc::gen::container<Edges>(rc::gen::pair(vertex, vertex));
}

}  // namespace

TEST_CASE("components: a hand-made graph", "[components]") {
  // 0-3, 3-5, 1-4, 2 alone; 6-6 a loop; components numbered by lowest vertex: {0,3,5} {1,4} {2} {6}
  const Edges edges{{5, 3}, {4, 1}, {3, 0}, {6, 6}, {3, 5}};
  const Components c = graph_components(7, edges);
  CHECK(c.count == 4);
  CHECK(c.of == std::vector<int>{0, 1, 2, 0, 1, 0, 3});
  CHECK(c.members() == std::vector<std::vector<int>>{{0, 3, 5}, {1, 4}, {2}, {6}});
  CHECK(c.members({0, 1, 0, 0, 1, 0, 1}) == std::vector<std::vector<int>>{{1, 4}, {6}});
  CHECK(graph_components(0, {}).count == 0);
  CHECK_THROWS_AS(graph_components(3, {{0, 3}}), std::out_of_range);
  CHECK_THROWS_AS(c.members({1, 0}), std::invalid_argument);
  CHECK(induced_components({2, 10, 11, 40}, {{40, 2}, {11, 10}}) == std::vector<std::vector<int>>{{2, 40}, {10, 11}});
  CHECK_THROWS_AS(induced_components({2, 10}, {{2, 3}}), std::out_of_range);
}

TEST_CASE("properties: Boost components agree with brute-force reachability", "[components][property]") {
  rc::prop("graph_components, disjoint sets and induced subgraphs number components by lowest element", [] {
    const int n = *rc::gen::inRange(0, 40);
    const Edges edges = random_edges(n);
    const Components expected = oracle(static_cast<std::size_t>(n), edges);

    const Components graph = graph_components(static_cast<std::size_t>(n), edges);
    RC_ASSERT(graph.count == expected.count);
    RC_ASSERT(graph.of == expected.of);

    DisjointSets sets(static_cast<std::size_t>(n));
    for (const auto& [a, b] : edges) sets.union_set(a, b);
    const Components joined = components_of(sets, static_cast<std::size_t>(n));
    RC_ASSERT(joined.count == expected.count);
    RC_ASSERT(joined.of == expected.of);

    // The same graph on spread-out ids (vertex v named 3v + 7) as an induced subgraph.
    std::vector<int> ids;
    for (int v = 0; v < n; ++v) ids.push_back(3 * v + 7);
    Edges renamed;
    for (const auto& [a, b] : edges) renamed.emplace_back(3 * a + 7, 3 * b + 7);
    std::vector<std::vector<int>> want = expected.members();
    for (auto& component : want)
      for (int& v : component) v = 3 * v + 7;
    RC_ASSERT(induced_components(ids, renamed) == want);
  });
}
