// NH-Rep's patch graph (Guo et al. 2022, Section 5.2) and patch decomposition, on a dimension-free boundary
// (complex/boundary.hpp).
//
// Conventions (owned here):
// - A patch is a connected component of live pieces across non-feature links. Patches are numbered in order of
//   their lowest piece index (for meshes: lowest triangle index, as the NH-Rep tool numbers them). Patches made
//   by decomposition get the next free ids, in order of their lowest piece index; the decomposed patch stays in
//   `patches` with `alive == false`.
// - A feature curve is a maximal set of feature links between the same two patches, chained through corners where
//   exactly two feature links of the whole boundary meet (2D: every feature link is its own curve). Its type
//   (Section 3 of the paper): smooth if all its links are smooth; convex if none is concave and some is convex;
//   concave if none is convex and some is concave; hybrid if it has both.
// - The patch graph is the multigraph of live patches with one edge per feature curve. A feature curve whose
//   two sides lie on the same patch is not an edge (it separates nothing); it is kept in `internal_curves`.
// - A patch "has convex edges" if one of its curves is convex or hybrid, "concave edges" if one is concave or
//   hybrid.
#pragma once

#include <hsx/complex/boundary.hpp>

#include <string>
#include <vector>

namespace hsx::nhrep {

/// How a feature curve's type follows from its links' types.
enum class CurveRule {
  Paper,     ///< Section 3: smooth / convex / concave / hybrid as above
  Majority,  ///< NH-Rep's tool: the most frequent link type; a tie between convex and concave is hybrid, a tie of
             ///< either with smooth goes to the sharp type
};

struct PatchInfo {
  std::vector<int> pieces;        ///< live pieces, ascending
  int parent = -1;                ///< the patch this one was decomposed from, -1 for an original patch
  bool alive = true;              ///< false once decomposed
};

struct Curve {
  int patch_a = -1, patch_b = -1; ///< patch_a <= patch_b
  FeatureType type = FeatureType::Smooth;
  std::vector<int> links;         ///< ascending
};

struct PatchGraph {
  BoundarySurface surface;        ///< owned: decomposition splits its pieces
  std::vector<int> piece_patch;   ///< per piece, its patch; -1 for retired pieces
  std::vector<PatchInfo> patches;
  std::vector<Curve> curves;      ///< graph edges, ordered by (patch_a, patch_b, first link)
  std::vector<Curve> internal_curves;
  CurveRule rule = CurveRule::Paper;

  std::vector<int> live_patches() const;
  /// Per patch id, the indices into `curves` of its edges (empty for dead patches).
  std::vector<std::vector<int>> incident_curves() const;
  bool has_convex(int patch) const;
  bool has_concave(int patch) const;
  /// Live patches with both convex and concave edges (the quantity patch decomposition strictly reduces).
  int both_kinds_count() const;
  /// The patch's original ancestor (itself for an original patch).
  int original_of(int patch) const;
};

/// Builds patches and curves. Throws std::invalid_argument naming the problem if check_boundary fails.
PatchGraph build_patch_graph(BoundarySurface surface, CurveRule rule = CurveRule::Paper);

/// Recomputes `curves` and `internal_curves` from the surface and piece_patch.
void rebuild_curves(PatchGraph& graph);

struct Decomposition {
  int patch = -1;                     ///< the decomposed patch
  std::vector<int> subpatches;        ///< new patch ids, ascending
  int pieces_split = 0;               ///< face-splitting: pieces that carried both convex and concave links
  int cut_links = 0;                  ///< links cut by the minimum cut (they become smooth feature links)
  int both_kinds_before = 0, both_kinds_after = 0;  ///< both_kinds_count() over the whole graph
  bool whole_patch = true;            ///< false: only curves to `scope` patches were separated (NH-Rep's tool)
};

/// Patch decomposition (Section 5.2, implementation paragraph): face-splits the pieces of `patch` that carry both
/// convex and concave feature links, labels its pieces by a minimum cut on their dual graph (unit capacity per
/// non-feature link; pieces on convex links forced to one side, on concave links to the other; hybrid curves are
/// split by their links' own types), and makes every connected component of each label a subpatch. Links between
/// different subpatches become smooth feature links. Requires has_convex and has_concave for `patch`; the result
/// has no subpatch with both kinds of edges.
///
/// `scope` (optional, per patch id): when given, only feature links to patches with scope[p] != 0 force labels,
/// as NH-Rep's tool does when it separates a patch's curves within the cluster where Q was empty; subpatches may
/// then keep both kinds of edges to patches outside the scope.
Decomposition decompose_patch(PatchGraph& graph, int patch, const std::vector<char>* scope = nullptr);

}  // namespace hsx::nhrep
