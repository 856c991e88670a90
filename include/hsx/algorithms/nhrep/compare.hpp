// Patch numberings of NH-Rep trees, and comparing trees and patch graphs with the ones NH-Rep's own tool writes.
//
// Conventions (owned here):
// - NH-Rep's numbering (the one its `.conf`, face-patch and patch-graph files use, and hsx's --conf/--decomposed
//   output): the live patches of a patch graph in order of their lowest piece origin (mesh: lowest input triangle
//   index; 2D: lowest arrangement edge index), numbered 0, 1, 2, ... Decomposed (dead) patches have no number. For
//   a graph without decompositions built from a mesh this is the patch id itself (patch_graph.hpp numbers patches
//   by lowest piece, and pieces are triangles in input order).
// - Trees are compared up to patch numbering: each leaf is replaced by a label (e.g. the original patch it came
//   from) and trees are compared as unordered trees, a node being its op, the multiset of its leaf labels and the
//   multiset of its children.
// - A reference patch graph lists one edge per adjacent pair of original patches (NH-Rep numbering of the
//   undecomposed mesh) with one type; hsx's multigraph's curves between a pair are combined as curve types combine
//   (combine_feature_types: convex with concave gives hybrid, which no reference edge has).
#pragma once

#include <hsx/algorithms/nhrep/tree.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hsx::nhrep {

/// NH-Rep's number of every patch of `graph` (see the header comment).
/// @param[in] graph  a patch graph (decomposed or not)
/// @return  #graph.patches list: the number of a live patch, -1 for a dead one
std::vector<int> nhrep_patch_numbers(const PatchGraph& graph);

/// @return  #graph.patches list: each patch's original ancestor (PatchGraph::original_of; itself if original)
std::vector<int> original_labels(const PatchGraph& graph);

/// `tree` with every leaf `p` replaced by `label[p]` and put in NH-Rep's `.conf` order: a node's leaves ascending,
/// its children in order of the lowest label in their subtrees; node 0 is the root, then depth first.
/// @param[in] tree   a tree with a root
/// @param[in] label  per leaf id of `tree` (indexed by patch id), its new number; must be >= 0 for every leaf
/// Throws std::invalid_argument when a leaf has no label (out of range or negative) or the tree has no root.
Tree relabel_tree(const Tree& tree, const std::vector<int>& label);

/// A canonical text of the subtree at `node`: `max{3,5,[min{1,1}]}` with leaves replaced by `label[leaf]`
/// (`label` indexed by patch id; leaves sorted, children sorted by their own canonical text). Equal texts mean
/// equal trees up to the order of children.
std::string canonical_form(const Tree& tree, const std::vector<int>& label, int node = -1);

struct TreeComparison {
  bool equal = false;
  std::string ours, theirs;            ///< canonical forms
  /// Human-readable differences, node by node along the matching path (empty when equal): each starts with the
  /// node's path from the root ("root", "root/0", ...: the k-th unmatched child) and says what differs (the op,
  /// the leaves, or a child only one side has).
  std::vector<std::string> differences;
};

/// Compares two trees through leaf labels (`our_label` indexed by our patch ids, `their_label` by theirs).
TreeComparison compare_trees(const Tree& ours, const std::vector<int>& our_label, const Tree& theirs,
                             const std::vector<int>& their_label);

/// A tree written by NH-Rep's tool (read by io/nhrep_json.hpp).
struct ReferenceTree {
  Tree tree;                    ///< leaves: the reference's patch numbers (any non-negative ints)
  /// Optional (empty: none): per input mesh triangle (the mesh the tree was built from, in input order), the
  /// reference patch it belongs to. With it, trees are compared through original patches, so that different
  /// decompositions (and their numberings) of the same original patches can still compare equal.
  std::vector<int> face_patch;
};

struct ReferenceComparison {
  /// How leaves were matched: "patch numbers (lowest triangle first)" (no face-patch: their leaf k is our patch
  /// with NH-Rep number k) or "original patches (each reference patch mapped through its triangles)".
  std::string basis;
  bool equal = false;
  /// Set when the trees could not be matched at all (a reference patch whose triangles lie on several of our
  /// original patches); `trees` is then empty and `equal` false.
  std::optional<std::string> mismatch;
  TreeComparison trees;
};

/// Compares the tree of `result` with NH-Rep's `reference`. Memory is linear in the sizes of the two trees and the
/// face-patch list, whatever the reference's patch numbers are.
/// @param[in] result     Algorithm 1's result; with a face-patch list, its graph must come from a mesh
///                       (pieces' origins = triangle indices)
/// @param[in] reference  the reference tree, and optionally its face-patch list
/// Throws std::invalid_argument when the face-patch list does not have one entry per input triangle of
/// result.graph, or a reference leaf has no triangle in it (io/nhrep_json.hpp's readers check both up front).
ReferenceComparison compare_with_reference(const BuildResult& result, const ReferenceTree& reference);

/// One line of a reference patch graph: original patches a < b are adjacent with `type` (Smooth, Convex or
/// Concave).
struct ReferenceEdge {
  int a = -1, b = -1;
  FeatureType type = FeatureType::Smooth;
};

/// An adjacent pair on which the two graphs differ: an edge only one side has, or different types.
struct EdgeDifference {
  int a = -1, b = -1;                     ///< NH-Rep numbers, a < b
  std::optional<FeatureType> ours, theirs; ///< unset: that side has no edge between a and b
};

struct GraphComparison {
  int reference_edges = 0;
  /// Sorted by (a, b) over the reference's edges first, then the edges only ours has, sorted by (a, b).
  std::vector<EdgeDifference> differences;
};

/// Compares an original (undecomposed) patch graph, numbered by nhrep_patch_numbers, with NH-Rep's listing.
/// @param[in] original  the patch graph before Algorithm 1
/// @param[in] theirs    the reference's edges; pairs given as a < b, each pair at most once (the io reader checks)
/// Throws std::invalid_argument when an edge has a >= b or a pair is listed twice.
GraphComparison compare_patch_graphs(const PatchGraph& original, const std::vector<ReferenceEdge>& theirs);

}  // namespace hsx::nhrep
