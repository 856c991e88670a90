// Random orientation-preserving labellings for the BSH and CSG property tests (rapidcheck; call inside a
// property).
#pragma once

#include <hsx/algorithms/bsh/problem.hpp>

#include <vector>

namespace hsx::test {

/// The implications of orientation preservation (algorithms/bsh/problem.hpp), per support with cells a, b: only
/// "a inside" allowed means b inside => a inside; only "b inside" the converse; neither: equal labels. Per cell,
/// the cells its being inside forces inside.
std::vector<std::vector<int>> implications(const bsh::Problem& problem);

/// A random orientation-preserving labelling: each cell is a seed with probability 1/density (density drawn from
/// [1, max_density)), each seed closed under the implications; seeds whose closure reaches an outer cell are
/// dropped. A union of closed sets is closed.
bsh::Labelling random_closure(const bsh::Problem& problem, int max_density);

}  // namespace hsx::test
