// NH-Rep on 3D solids built from halfspaces (issue 14, Section 3): the solid's boundary from the exact 3D
// arrangement with each triangle's halfspace known (complex/boundary_from_arrangement3.hpp), Algorithm 1 with
// patch decomposition on it, and the exact evaluation of the tree with natural halfspaces on every cell of the
// arrangement in a domain holding every vertex (complex/carry_solid3.hpp), against Shapiro-Vossler
// describability: the 3D twin of planar.hpp.
//
// The evaluation itself is evaluate.hpp's evaluate_on_cells, the same code as in 2D: it reads only the cells' sign
// vectors (Cell::inside) and the patches' carriers, never the dimension. What is 3D here is how the boundary and
// its carriers are found (triangles of the 3D arrangement) and how the solid reaches the whole-space domain.
#pragma once

#include <hsx/algorithms/nhrep/evaluate.hpp>
#include <hsx/algorithms/nhrep/patch_graph.hpp>
#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/complex/from_arrangement3.hpp>

#include <string>
#include <vector>

namespace hsx::nhrep {

struct SolidTree3 {
  BuildOptions options;                   ///< as given to build_solid_tree3
  BuildResult built;
  /// Per patch id of built.graph: its natural halfspace's name, "~name" when complemented, "" for dead patches.
  std::vector<std::string> leaf_names;
  /// Per patch id: the tree node it is a leaf of (-1 for dead patches), for colouring pictures.
  std::vector<int> leaf_node;
};

/// Builds the patch graph of the 3D solid's boundary and NH-Rep's tree of it.
/// @param[in] arranged     the 3D scene's arrangement and complex
/// @param[in] solid_cells  #arranged.complex.cells flags, 1 = inside
/// @param[in] options      Algorithm 1's options
/// @param[in] rule         how a feature curve's type follows from its links' (patch_graph.hpp)
/// Throws InputError when the solid is empty or has an outer cell; std::invalid_argument when `solid_cells` has
/// the wrong size; whatever build_tree throws.
SolidTree3 build_solid_tree3(const Arranged3& arranged, const std::vector<char>& solid_cells,
                             const BuildOptions& options = {}, CurveRule rule = CurveRule::Paper);

/// Evaluates `tree` exactly with natural halfspaces on every cell of `whole` (the same halfspaces in a domain
/// holding every vertex, or the original arrangement when its domain already does).
/// @param[in] tree         build_solid_tree3's result
/// @param[in] whole        the arrangement to evaluate on
/// @param[in] whole_solid  #whole.complex.cells flags: the solid on `whole`
CellEvaluation evaluate_solid_tree3(const SolidTree3& tree, const Arranged3& whole,
                                    const std::vector<char>& whole_solid);

/// evaluate_solid_tree3 on the whole space of `scene`: re-arranges whole_space_scene3(scene) (within `limits`,
/// without volumes) and carries the solid there, unless `scene`'s domain already holds every vertex.
/// @param[in] tree         build_solid_tree3(arranged, solid_cells, ...)'s result
/// @param[in] scene        the validated scene `arranged` was built from
/// @param[in] arranged     as given to build_solid_tree3
/// @param[in] solid_cells  as given to build_solid_tree3
/// @param[in] limits       bounds on the whole-space arrangement
CellEvaluation evaluate_on_whole_space(const SolidTree3& tree, const Scene3& scene, const Arranged3& arranged,
                                       const std::vector<char>& solid_cells, const ArrangementLimits& limits = {});

}  // namespace hsx::nhrep
