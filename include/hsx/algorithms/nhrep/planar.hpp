// NH-Rep on a 2D solid (the pipeline behind `hsx nhtree SCENE --csg ...`): the solid's boundary as a patch graph
// (complex/boundary_from_arrangement2.hpp), Algorithm 1 (tree.hpp), each leaf's natural halfspace, and the exact
// evaluation of the tree with those halfspaces (evaluate.hpp) with a diagnosis of why a describable solid's tree
// fails.
//
// Conventions (owned here):
// - A solid is one flag per cell of the arrangement's complex (1 = inside); it must be non-empty and bounded inside
//   the domain (no solid cell is outer), as NH-Rep needs a closed boundary.
// - Evaluation must see every sign vector of the plane (evaluate.hpp): evaluate_on_whole_plane arranges the scene
//   in a domain holding every vertex when its own domain does not (complex/carry_solid2.hpp) and carries the solid
//   there; evaluate_planar_tree takes such an arrangement ready-made.
// - Diagnosis of a tree that fails although the solid is describable by its natural halfspaces: with holes and
//   without BuildOptions::nest_holes, Section 5.2's initialisation united a hole's boundary where it should be
//   intersected (proofs/nhrep.md, Finding 5.2); otherwise NH-Rep needs extended surfaces (its Appendix B).
#pragma once

#include <hsx/algorithms/nhrep/evaluate.hpp>
#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/kernel/rational.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hsx::nhrep {

/// Where one piece of a patch lies.
struct PlanarPiece {
  int edge = -1;                       ///< arrangement edge (BoundaryPiece::origin)
  /// For a half made by patch decomposition: the arrangement vertex of the end it keeps (-1 otherwise) and the
  /// exact rational point where the edge was cut (geometry's edge_split_point; a picture's choice, not a decision).
  int kept_vertex = -1;
  std::optional<PointQ2> split_point;
};

struct PlanarTree {
  BuildOptions options;                         ///< as given to build_planar_tree
  BuildResult built;
  /// Per patch id of built.graph: its natural halfspace's name, "~name" when complemented, "" for dead patches.
  std::vector<std::string> leaf_names;
  /// Per patch id of built.graph: its pieces (empty for dead patches).
  std::vector<std::vector<PlanarPiece>> pieces;
  /// Per patch id: the tree node it is a leaf of (-1 for dead patches), for colouring pictures.
  std::vector<int> leaf_node;
};

/// Builds the patch graph of the solid's boundary and NH-Rep's tree of it.
/// @param[in] arranged     the scene's arrangement and complex (cells = arrangement faces)
/// @param[in] solid_cells  #arranged.complex.cells flags, 1 = inside
/// @param[in] options      Algorithm 1's options
/// @param[in] rule         how a feature curve's type follows from its corners' (patch_graph.hpp)
/// Throws InputError when the solid is empty or has an outer cell; std::invalid_argument when `solid_cells` has
/// the wrong size; whatever build_tree throws (std::invalid_argument for nest_holes without nesting,
/// std::runtime_error past its guard).
PlanarTree build_planar_tree(const Arranged2& arranged, const std::vector<char>& solid_cells,
                             const BuildOptions& options = {}, CurveRule rule = CurveRule::Paper);

/// The 2D evaluation: CellEvaluation (evaluate.hpp) on the whole-plane complex (witnesses have 2 coordinates).
using PlanarEvaluation = CellEvaluation;

/// Evaluates `tree` exactly with natural halfspaces on the whole plane.
/// @param[in] tree         build_planar_tree's result
/// @param[in] whole        the same scene arranged in a domain holding every vertex (may be the original)
/// @param[in] whole_solid  #whole.complex.cells flags: the solid carried to `whole`
/// Throws std::invalid_argument when `whole_solid` has the wrong size.
PlanarEvaluation evaluate_planar_tree(const PlanarTree& tree, const Arranged2& whole,
                                      const std::vector<char>& whole_solid);

/// Evaluates `tree` exactly with natural halfspaces on the whole plane of `scene`.
/// @param[in] tree         build_planar_tree(arranged, solid_cells, ...)'s result
/// @param[in] scene        the validated scene `arranged` was built from
/// @param[in] arranged     as given to build_planar_tree
/// @param[in] solid_cells  as given to build_planar_tree
/// Throws std::invalid_argument when `solid_cells` has the wrong size.
PlanarEvaluation evaluate_on_whole_plane(const PlanarTree& tree, const Scene2& scene, const Arranged2& arranged,
                                         const std::vector<char>& solid_cells);

}  // namespace hsx::nhrep
