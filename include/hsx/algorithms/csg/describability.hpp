// Shapiro-Vossler describability on a complex: a solid (a set of cells) is describable by the halfspaces iff no
// canonical intersection term (the cells sharing one sign vector over all halfspaces) holds both an inside and an
// outside cell. See proofs/csg.md.
#pragma once

#include <hsx/complex/complex.hpp>

#include <vector>

namespace hsx::csg {

struct MixedTerm {
  std::vector<char> signs;          ///< the term's sign vector (per halfspace: 1 inside)
  std::vector<int> inside_cells;    ///< its cells in the solid, ascending
  std::vector<int> outside_cells;   ///< its cells not in the solid, ascending
};

struct Describability {
  bool describable = true;
  int terms = 0;                    ///< non-empty canonical intersection terms
  std::vector<MixedTerm> mixed;     ///< ordered by smallest cell
};

/// `solid`: per cell, 1 inside.
Describability describability(const Complex& complex, const std::vector<char>& solid);

/// Describability by a subset of the halfspaces: a term is the set of cells with one sign vector over
/// `halfspaces` (indices into the complex's halfspaces); MixedTerm::signs has one entry per element of
/// `halfspaces`, in that order. With every halfspace, this is the function above.
Describability describability(const Complex& complex, const std::vector<char>& solid,
                              const std::vector<int>& halfspaces);

}  // namespace hsx::csg
