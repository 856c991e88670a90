// Cross-check 2 of issue 5: exact evaluation of an NH-Rep Boolean tree with NATURAL halfspaces in 2D, against the
// solid it was built from, and Shapiro-Vossler describability of that solid by exactly those halfspaces.
//
// Conventions (owned here):
// - The natural halfspace of a live patch is the halfspace of its pieces' `carrier` (BoundaryPiece), complemented
//   when `carrier_complemented` (the solid lies outside the carrier along the patch). Every piece of a patch must
//   agree on (carrier, carrier_complemented); a patch with a piece without a carrier (-1) or out of range, or whose
//   pieces disagree, is a violated check (the evaluation then treats it as empty and goes on).
//   Note: hsx's halfspaces are the scene's; a polygon halfspace's own corners do not split its patch
//   (complex/boundary_from_arrangement2.hpp), so a patch on a polygon gets the whole polygon, not one edge's
//   half-plane. With half-planes and disks only, "natural" is exactly NH-Rep's: a full line, a full circle.
// - A Max node is the intersection of its leaves' and children's halfspaces (f <= 0 inside, max of f's), a Min node
//   their union. On a cell of the complex, a halfspace's value is Cell::inside, so the tree's value on a cell is
//   exact and needs no geometry.
// - The natural halfspace set is the set of carriers of live patches (ascending, each once, complementation
//   forgotten: a canonical term does not care about orientation). Describability (Shapiro-Vossler) w.r.t. that set:
//   a canonical term is the set of cells with one sign vector over those halfspaces; the solid is describable iff
//   no term holds both a solid and a non-solid cell: csg::describability over that subset (tests/algorithms
//   compares it with csg::describability on a complex restricted to those halfspaces).
// - Correctness and describability are about the cells of the complex, i.e. the domain. A region outside the
//   domain whose sign vector no cell has is not seen: evaluate on a complex whose domain contains every vertex of
//   the arrangement (hsx nhsurvey and hsx nhtree enlarge the domain for that), then every sign vector of the plane is some cell's.
// - A tree that is correct on every cell is a Boolean function of the natural halfspaces that equals the solid, so
//   the solid is describable by them: correct && !describable is a violated check (a bug), never a verdict.
#pragma once

#include <hsx/algorithms/csg/describability.hpp>
#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/complex/complex.hpp>

#include <string>
#include <vector>

namespace hsx::nhrep {

/// A leaf's natural halfspace: `halfspace` indexes Complex::halfspace_names (-1 when unknown); the leaf's region is
/// the halfspace's inside, or its outside when `complemented`.
struct NaturalHalfspace {
  int halfspace = -1;
  bool complemented = false;
};

enum class Verdict {
  TreeCorrect,          ///< the tree with natural halfspaces is the solid on every cell
  DescribableButFails,  ///< describable by the natural halfspaces, yet the tree is wrong somewhere (Appendix B)
  NotDescribable,       ///< no Boolean expression of the natural halfspaces is the solid; the tree must fail
};
/// "tree correct", "describable but the tree fails", "not describable by its patches' halfspaces".
const char* verdict_name(Verdict verdict);
/// "correct", "describable-fails", "not-describable" (for tables and file names).
const char* verdict_key(Verdict verdict);

struct Evaluation {
  std::vector<NaturalHalfspace> leaf_halfspace;  ///< per patch id of result.graph (dead patches: halfspace -1)
  std::vector<int> natural_halfspaces;           ///< the natural halfspace set, ascending, each once
  std::vector<char> tree_value;                  ///< per cell: 1 when the tree says inside
  std::vector<int> wrong_inside;                 ///< solid cells the tree says are outside, ascending
  std::vector<int> wrong_outside;                ///< non-solid cells the tree says are inside, ascending
  bool correct = false;                          ///< wrong_inside and wrong_outside are empty
  bool describable = false;                      ///< by natural_halfspaces, Shapiro-Vossler
  int terms = 0;                                 ///< non-empty canonical terms over natural_halfspaces
  /// Canonical terms over natural_halfspaces holding solid and non-solid cells (signs in natural_halfspaces
  /// order), ordered by their smallest cell.
  std::vector<csg::MixedTerm> mixed;
  Verdict verdict = Verdict::NotDescribable;
  /// Violated checks (empty: all hold): leaves without a usable carrier, pieces of one patch disagreeing on their
  /// carrier, a tree that is correct on a non-describable solid.
  std::vector<std::string> violations;
};

/// Evaluates `result.tree` (leaves = live patches of result.graph, whose pieces carry the carriers) on every cell
/// of `complex` and compares it with `solid`: one flag per cell of `complex`, 1 = in the solid (the solid the
/// boundary was built from). Throws std::invalid_argument when `solid` does not have one flag per cell or the tree
/// has no root.
Evaluation evaluate_tree(const BuildResult& result, const Complex& complex, const std::vector<char>& solid);

/// The tree's value on one sign vector (Cell::inside, one entry per halfspace of the complex), with the leaves'
/// natural halfspaces `leaf_halfspace` (Evaluation::leaf_halfspace); a leaf with halfspace -1 is empty.
bool tree_value(const Tree& tree, const std::vector<NaturalHalfspace>& leaf_halfspace, const std::vector<char>& inside);

/// Per patch id of `graph`, the natural halfspace of its pieces; appends violations for patches without a usable
/// or consistent carrier (`halfspace_count`: the complex's, for the range check).
std::vector<NaturalHalfspace> natural_halfspaces(const PatchGraph& graph, int halfspace_count,
                                                 std::vector<std::string>* violations = nullptr);

enum class Diagnosis {
  None,                   ///< the tree is correct, or the solid is not describable by its natural halfspaces
  HolesUnited,            ///< describable, fails, has holes (2D) or cavities (3D), built without nest_holes
  NeedsExtendedSurfaces,  ///< describable, fails otherwise (Appendix B)
};

/// The evaluation of a tree on every cell of a complex, with the witness points of the wrong cells. Dimension-free:
/// nothing here knows whether the complex is 2D or 3D (the cells' sign vectors decide; witnesses have the
/// complex's `dimension` coordinates).
struct CellEvaluation {
  Evaluation evaluation;                       ///< on the cells of the (whole-plane / whole-space) complex
  std::size_t cells = 0;                       ///< cells of that complex
  /// Exact interior points (Cell::witness) of the cells in evaluation.wrong_inside (solid points the tree misses)
  /// and evaluation.wrong_outside (points it adds), in the same order.
  std::vector<std::vector<Rational>> missed, added;
  Diagnosis diagnosis = Diagnosis::None;
};

/// evaluate_tree on `complex`, the witnesses of the wrong cells, and the diagnosis (HolesUnited when a piece of
/// result.graph bounds a hole and `options` did not nest holes).
CellEvaluation evaluate_on_cells(const BuildResult& result, const BuildOptions& options, const Complex& complex,
                                 const std::vector<char>& solid);

/// Per patch id of `result.graph`: the tree node it is a leaf of (-1 for dead patches), for colouring pictures.
std::vector<int> leaf_nodes(const BuildResult& result);

/// Per patch id of `graph`: its natural halfspace's name (Complex::halfspace_names), "~name" when complemented, ""
/// for dead patches and patches without a usable carrier.
std::vector<std::string> leaf_names(const PatchGraph& graph, const Complex& complex);

}  // namespace hsx::nhrep
