#include <hsx/algorithms/csg/describability.hpp>

#include <algorithm>
#include <map>

namespace hsx::csg {

Describability describability(const Complex& complex, const std::vector<char>& solid) {
  std::vector<int> all(static_cast<std::size_t>(complex.halfspace_count()));
  for (std::size_t h = 0; h < all.size(); ++h) all[h] = static_cast<int>(h);
  return describability(complex, solid, all);
}

Describability describability(const Complex& complex, const std::vector<char>& solid,
                              const std::vector<int>& halfspaces) {
  std::map<std::vector<char>, MixedTerm> terms;
  std::vector<char> signs(halfspaces.size());
  for (int k = 0; k < static_cast<int>(complex.cells.size()); ++k) {
    const auto& inside = complex.cells[static_cast<std::size_t>(k)].inside;
    for (std::size_t i = 0; i < halfspaces.size(); ++i) signs[i] = inside.at(static_cast<std::size_t>(halfspaces[i])) ? 1 : 0;
    MixedTerm& term = terms[signs];
    (solid[static_cast<std::size_t>(k)] ? term.inside_cells : term.outside_cells).push_back(k);
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
