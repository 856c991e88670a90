// NH-Rep's Boolean tree (Guo et al. 2022, Section 5.2, Algorithm 1 ConstructTreeNode) and its structural checks.
//
// Conventions (owned here):
// - A node's op is Max (intersection of its children's halfspaces f <= 0) or Min (union). Leaves are patch ids of
//   the final (decomposed) patch graph. A node lists its leaves first, then its child nodes.
// - The vertex set Q for a parent r collects the vertices of the subgraph with no edge of type edgetype(op(r)):
//   when op(r) = min, patches with no concave (or hybrid) edge; when op(r) = max, patches with no convex (or
//   hybrid) edge. This is the paper's own explanation (items (1) and (2) after the definition of Q) and its Fig. 3;
//   the formula's "edgetype(op+(r))" contradicts both and is read as a misprint (proofs/nhrep.md).
// - The tree root: with several connected components a real Min root; with one, the virtual root (op min) vanishes
//   and its only child is the root.
// - Patch choice for decomposition (the paper picks randomly): the lowest live patch id in the subgraph that has
//   both convex and concave edges.
#pragma once

#include <hsx/algorithms/nhrep/patch_graph.hpp>

#include <string>
#include <vector>

namespace hsx::nhrep {

enum class Op { Max, Min };
const char* op_name(Op op);  ///< "max", "min"

struct TreeNode {
  Op op = Op::Max;
  std::vector<int> leaves;        ///< patch ids, ascending
  std::vector<int> children;      ///< node ids, in creation order
};

struct Tree {
  std::vector<TreeNode> nodes;
  int root = -1;
  /// Every leaf in the subtree of `node`, ascending.
  std::vector<int> subtree_leaves(int node) const;
};

/// One call of ConstructTreeNode, for the report.
struct TreeStep {
  std::vector<int> subgraph;      ///< G' (patch ids, ascending) as the step saw it
  Op parent_op = Op::Min;
  bool parent_virtual = false;
  std::vector<int> q;             ///< Q, ascending
  /// "case 2" (Q not empty), "case 1: no convex edges" (first subcase), "case 1: decompose" (second subcase)
  std::string outcome;
  int node = -1;                  ///< the node created (case 2 and the first subcase), else -1
  int decomposition = -1;         ///< index into BuildResult::decompositions for the second subcase
  int round = 0;                  ///< restarts before this step (restart_after_decomposition)
};

struct BuildOptions {
  int max_decompositions = 10000; ///< guard; exceeding it throws std::runtime_error (it cannot happen, see proofs)
  /// Departures of NH-Rep's own tool from Algorithm 1 (off by default; `hsx nhtree --nhrep-tool` sets both):
  /// after a decomposition, rebuild the whole tree from the start on the decomposed patch graph (one patch per
  /// round) instead of retrying on the same subgraph under the same parent ...
  bool restart_after_decomposition = false;
  /// ... and separate only the decomposed patch's curves to patches of the current subgraph G'.
  bool decompose_within_subgraph = false;
  /// An extension, not the paper: Section 5.2's initialisation takes several boundary components for several
  /// volume components and unites them, which is wrong for holes and cavities (proofs/nhrep.md, Finding 5.2).
  /// With this set, components are grouped by BoundaryPiece::region; each part's hole components are built under
  /// (intersected with) its outer component's tree, and parts are united. Needs the nesting on the pieces.
  bool nest_holes = false;
};

struct BuildResult {
  Tree tree;
  PatchGraph graph;               ///< the final, decomposed patch graph the leaves refer to
  int original_patch_count = 0;
  std::vector<Decomposition> decompositions;
  std::vector<TreeStep> steps;
  int rounds = 1;                 ///< tree constructions run (more than 1 only with restart_after_decomposition)
  bool nested = false;            ///< built with nest_holes over several components (check_tree allows parts)
};

/// Tree initialisation and ConstructTreeNode (Algorithm 1) on `graph`.
BuildResult build_tree(PatchGraph graph, const BuildOptions& options = {});

/// Cross-check 1 of the tree against its patch graph: every live patch is exactly one leaf and every leaf a live
/// patch; ops alternate between parent and child; each node's leaves obey the Q condition within its subtree's
/// patches; each node's child subtrees are connected and pairwise non-adjacent (maximal connected subgraphs);
/// every decomposition reduced both_kinds_count by exactly one (which implies termination). Returns violations (empty: all hold).
std::vector<std::string> check_tree(const BuildResult& result);

/// Patch grouping (Section 6): a greedy colouring of the final patch graph in patch order, each patch joining the
/// lowest group with no adjacent patch and fewer than `max_group` members. Returns groups of patch ids.
std::vector<std::vector<int>> group_patches(const PatchGraph& graph, int max_group = 6);

}  // namespace hsx::nhrep
