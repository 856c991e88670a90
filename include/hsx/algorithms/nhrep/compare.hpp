// Comparing NH-Rep trees up to patch numbering: each leaf is replaced by a label (e.g. the original patch it came
// from) and trees are compared as unordered trees, a node being its op, the multiset of its leaf labels and the
// multiset of its children.
#pragma once

#include <hsx/algorithms/nhrep/tree.hpp>

#include <string>
#include <vector>

namespace hsx::nhrep {

/// A canonical text of the subtree at `node`: `max{3,5,[min{1,1}]}` with leaves replaced by `label[leaf]`
/// (`label` indexed by patch id; leaves sorted, children sorted by their own canonical text). Equal texts mean
/// equal trees up to the order of children.
std::string canonical_form(const Tree& tree, const std::vector<int>& label, int node = -1);

struct TreeComparison {
  bool equal = false;
  std::string ours, theirs;            ///< canonical forms
  /// Human-readable differences, node by node along the matching path (empty when equal).
  std::vector<std::string> differences;
};

/// Compares two trees through leaf labels (`our_label` indexed by our patch ids, `their_label` by theirs).
TreeComparison compare_trees(const Tree& ours, const std::vector<int>& our_label, const Tree& theirs,
                             const std::vector<int>& their_label);

}  // namespace hsx::nhrep
