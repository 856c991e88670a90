#include "support/random_labellings.hpp"

#include <rapidcheck.h>

namespace hsx::test {

std::vector<std::vector<int>> implications(const bsh::Problem& problem) {
  std::vector<std::vector<int>> implies(static_cast<std::size_t>(problem.cell_count()));
  for (const bsh::SupportTerm& s : problem.supports()) {
    if (!s.allow_b_inside) implies[static_cast<std::size_t>(s.cell_b)].push_back(s.cell_a);
    if (!s.allow_a_inside) implies[static_cast<std::size_t>(s.cell_a)].push_back(s.cell_b);
  }
  return implies;
}

bsh::Labelling random_closure(const bsh::Problem& problem, int max_density) {
  const int n = problem.cell_count();
  const auto implies = implications(problem);
  const int density = *rc::gen::inRange(1, max_density);
  bsh::Labelling l(static_cast<std::size_t>(n), 0);
  for (int seed = 0; seed < n; ++seed) {
    if (*rc::gen::inRange(0, density) != 0) continue;
    std::vector<char> in(static_cast<std::size_t>(n), 0);
    std::vector<int> stack{seed};
    in[static_cast<std::size_t>(seed)] = 1;
    bool outer = false;
    while (!stack.empty()) {
      const int x = stack.back();
      stack.pop_back();
      outer = outer || problem.complex().cells[static_cast<std::size_t>(x)].outer;
      for (int y : implies[static_cast<std::size_t>(x)])
        if (!in[static_cast<std::size_t>(y)]) {
          in[static_cast<std::size_t>(y)] = 1;
          stack.push_back(y);
        }
    }
    if (outer) continue;
    for (int k = 0; k < n; ++k) l[static_cast<std::size_t>(k)] = l[static_cast<std::size_t>(k)] || in[static_cast<std::size_t>(k)];
  }
  return l;
}

}  // namespace hsx::test
