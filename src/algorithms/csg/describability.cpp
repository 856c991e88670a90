#include "algorithms/csg/describability.hpp"

#include <algorithm>
#include <map>

namespace hsx::csg {

Describability describability(const Complex& complex, const std::vector<char>& solid) {
  std::map<std::vector<char>, MixedTerm> terms;
  for (int k = 0; k < static_cast<int>(complex.cells.size()); ++k) {
    MixedTerm& term = terms[complex.cells[k].inside];
    (solid[k] ? term.inside_cells : term.outside_cells).push_back(k);
  }
  Describability out;
  out.terms = static_cast<int>(terms.size());
  for (auto& [signs, term] : terms)
    if (!term.inside_cells.empty() && !term.outside_cells.empty()) {
      term.signs = signs;
      out.mixed.push_back(std::move(term));
    }
  std::sort(out.mixed.begin(), out.mixed.end(), [](const MixedTerm& a, const MixedTerm& b) {
    return std::min(a.inside_cells.front(), a.outside_cells.front()) <
           std::min(b.inside_cells.front(), b.outside_cells.front());
  });
  out.describable = out.mixed.empty();
  return out;
}

}  // namespace hsx::csg
