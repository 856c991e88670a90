// Private to complex/: the connected components of a solid's cells, or of its void, on a complex of either
// dimension (boundary_from_arrangement2 and boundary_from_arrangement3 use it for the nesting of parts and holes).
#pragma once

#include <hsx/complex/complex.hpp>

#include "geometry/components.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace hsx::detail {

/// Components of the cells c with solid[c] == want (`solid`: one flag per cell of `complex`), adjacent across
/// patches that have such cells on both sides. Returns per cell its component (-1 for the other cells); components
/// are numbered in the order of their lowest cell. `touches_box` gets, per component, 1 when it holds an outer cell
/// (one that reaches the domain box), else 0.
inline std::vector<int> solid_components(const Complex& complex, const std::vector<char>& solid, char want,
                                         std::vector<char>& touches_box) {
  const std::size_t n = complex.cells.size();
  const auto at = [](int i) { return static_cast<std::size_t>(i); };
  std::vector<std::pair<int, int>> edges;
  for (const Patch& p : complex.patches)
    if (p.inside_cell >= 0 && p.outside_cell >= 0 && solid[at(p.inside_cell)] == want &&
        solid[at(p.outside_cell)] == want)
      edges.emplace_back(p.inside_cell, p.outside_cell);
  std::vector<char> wanted(n);
  for (std::size_t c = 0; c < n; ++c) wanted[c] = solid[c] == want;
  std::vector<int> component(n, -1);
  touches_box.clear();
  for (const std::vector<int>& cells : graph_components(n, edges).members(wanted)) {  // by lowest cell
    char outer = 0;
    for (int c : cells) {
      component[at(c)] = static_cast<int>(touches_box.size());
      if (complex.cells[at(c)].outer) outer = 1;
    }
    touches_box.push_back(outer);
  }
  return component;
}

}  // namespace hsx::detail
