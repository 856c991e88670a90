// BHC (Buchele and Crawford 2003, Figs. 1, 3, 5): a solid to a halfspace CSG tree, on exact cell sets.
//
// The paper works on b-reps and keeps "factored faces" to remember which parts of a region are in or out; on the
// complex every region is an explicit set of cells, so those questions are answered exactly by looking at the
// cells. The outline is the paper's:
//   region R (initially every cell), halfspaces Psi (initially all);
//   while R is neither all in nor all out:
//     factor every dominating halfspace (psi with every cell of R in psi inside the solid: union with psi;
//       psi with every such cell outside: intersect with the complement), solid first, then complement;
//     if none: partition by the halfspace of Psi that splits the fewest faces (faces = connected pieces of the
//       solid's boundary on one halfspace inside R), preferring planar halfspaces, then the lowest index;
//     if no halfspace of Psi splits R, R lies in one canonical intersection term with cells in and out: the solid
//       is not describable (Shapiro-Vossler), and that term is the witness.
#pragma once

#include <hsx/algorithms/csg/describability.hpp>
#include <hsx/algorithms/csg/expression.hpp>

#include <string>
#include <vector>

namespace hsx::csg {

struct BhcOptions {
  std::vector<char> planar;  ///< per halfspace: its boundary is a line/plane (preferred for partitioning); may be empty
};

struct BhcResult {
  bool describable = false;
  ExprPtr tree;                  ///< set when describable
  bool verified = false;         ///< the tree evaluates to the solid on every cell (checked exactly)
  ExprStats stats;
  int factored = 0;              ///< dominating halfspaces factored
  int partitions = 0;            ///< partitioning steps
  MixedTerm witness;             ///< when not describable: the mixed term BHC stopped at
};

/// `solid`: per cell, 1 inside.
BhcResult bhc(const Complex& complex, const std::vector<char>& solid, const BhcOptions& options = {});

}  // namespace hsx::csg
