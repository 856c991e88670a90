#include "algorithms/nhrep/tree.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace hsx::nhrep {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

Op opposite(Op op) { return op == Op::Max ? Op::Min : Op::Max; }

bool blocks(FeatureType type, Op parent_op) {
  // Q for a min parent excludes patches with concave edges, for a max parent those with convex edges.
  if (type == FeatureType::Hybrid) return true;
  return parent_op == Op::Min ? type == FeatureType::Concave : type == FeatureType::Convex;
}

/// Which of `vertices` (ascending) have an edge of a type that `test` accepts to another vertex of the set.
template <class Test>
std::vector<char> touches(const PatchGraph& graph, const std::vector<int>& vertices, Test test) {
  std::vector<char> member(graph.patches.size(), 0), result(graph.patches.size(), 0);
  for (int v : vertices) member[at(v)] = 1;
  for (const Curve& c : graph.curves)
    if (member[at(c.patch_a)] && member[at(c.patch_b)] && test(c.type)) result[at(c.patch_a)] = result[at(c.patch_b)] = 1;
  return result;
}

/// Maximal connected subgraphs of the induced subgraph on `vertices`, each ascending, ordered by lowest vertex.
std::vector<std::vector<int>> mc_subgraphs(const PatchGraph& graph, const std::vector<int>& vertices) {
  std::vector<char> member(graph.patches.size(), 0), seen(graph.patches.size(), 0);
  for (int v : vertices) member[at(v)] = 1;
  const auto incident = graph.incident_curves();
  std::vector<std::vector<int>> result;
  for (int start : vertices) {
    if (seen[at(start)]) continue;
    std::vector<int> component{start};
    seen[at(start)] = 1;
    for (std::size_t k = 0; k < component.size(); ++k)
      for (int c : incident[at(component[k])]) {
        const Curve& curve = graph.curves[at(c)];
        const int w = curve.patch_a == component[k] ? curve.patch_b : curve.patch_a;
        if (member[at(w)] && !seen[at(w)]) {
          seen[at(w)] = 1;
          component.push_back(w);
        }
      }
    std::sort(component.begin(), component.end());
    result.push_back(std::move(component));
  }
  return result;
}

/// Thrown to start the tree construction again on the decomposed graph (restart_after_decomposition).
struct Restart {};

class Builder {
 public:
  Builder(BuildResult& result, const BuildOptions& options) : result_(result), options_(options) {}

  /// ConstructTreeNode(G', r). `parent` is a node id, or -1 for the virtual root (op min).
  void construct(std::vector<int> subgraph, int parent) {
    const Op parent_op = parent < 0 ? Op::Min : result_.tree.nodes[at(parent)].op;
    const bool at_root = parent < 0 || parent == result_.tree.root;
    for (;;) {
      PatchGraph& graph = result_.graph;
      TreeStep step;
      step.subgraph = subgraph;
      step.parent_op = parent_op;
      step.parent_virtual = parent < 0;
      step.round = result_.rounds - 1;
      const auto blocked = touches(graph, subgraph, [&](FeatureType t) { return blocks(t, parent_op); });
      for (int v : subgraph)
        if (!blocked[at(v)]) step.q.push_back(v);

      if (!step.q.empty()) {  // Case 2
        step.outcome = "case 2";
        const int node = add_node(opposite(parent_op), step.q, parent);
        step.node = node;
        result_.steps.push_back(step);
        std::vector<int> rest;
        std::set_difference(subgraph.begin(), subgraph.end(), step.q.begin(), step.q.end(), std::back_inserter(rest));
        for (auto& component : mc_subgraphs(graph, rest)) construct(std::move(component), node);
        return;
      }

      const auto convex = touches(graph, subgraph, [](FeatureType t) {
        return t == FeatureType::Convex || t == FeatureType::Hybrid;
      });
      const bool any_convex = std::any_of(subgraph.begin(), subgraph.end(), [&](int v) { return convex[at(v)]; });
      if (at_root && parent_op == Op::Min && !any_convex) {
        // Case 1, first subcase (Fig. 5): no convex edges, so the solid is a union of its patches' halfspaces.
        // Every vertex has no convex edge, so all of G' are leaves of a min node; under a real min root they are
        // the root's own leaves (a min child under a min node would break alternation).
        step.outcome = "case 1: no convex edges";
        if (parent < 0) {
          step.node = add_node(Op::Min, subgraph, parent);
        } else {
          auto& leaves = result_.tree.nodes[at(parent)].leaves;
          leaves.insert(leaves.end(), subgraph.begin(), subgraph.end());
          std::sort(leaves.begin(), leaves.end());
          step.node = parent;
        }
        result_.steps.push_back(step);
        return;
      }

      // Case 1, second subcase: decompose the lowest patch of G' with both convex and concave edges in G'.
      const auto concave = touches(graph, subgraph, [](FeatureType t) {
        return t == FeatureType::Concave || t == FeatureType::Hybrid;
      });
      const auto pick = std::find_if(subgraph.begin(), subgraph.end(), [&](int v) { return convex[at(v)] && concave[at(v)]; });
      if (pick == subgraph.end())
        throw std::logic_error("Algorithm 1: Q is empty but no patch has both convex and concave edges");
      if (static_cast<int>(result_.decompositions.size()) >= options_.max_decompositions)
        throw std::runtime_error("Algorithm 1: more than " + std::to_string(options_.max_decompositions) +
                                 " patch decompositions");
      const int patch = *pick;
      std::vector<char> scope(graph.patches.size(), 0);
      for (int v : subgraph) scope[at(v)] = 1;
      Decomposition d = decompose_patch(graph, patch, options_.decompose_within_subgraph ? &scope : nullptr);
      step.outcome = "case 1: decompose";
      step.decomposition = static_cast<int>(result_.decompositions.size());
      step.round = result_.rounds - 1;
      result_.steps.push_back(step);
      if (options_.restart_after_decomposition) {
        result_.decompositions.push_back(std::move(d));
        throw Restart{};
      }
      subgraph.erase(std::find(subgraph.begin(), subgraph.end(), patch));
      subgraph.insert(subgraph.end(), d.subpatches.begin(), d.subpatches.end());
      std::sort(subgraph.begin(), subgraph.end());
      result_.decompositions.push_back(std::move(d));
    }
  }

  int add_node(Op op, std::vector<int> leaves, int parent) {
    const int id = static_cast<int>(result_.tree.nodes.size());
    result_.tree.nodes.push_back(TreeNode{op, std::move(leaves), {}});
    if (parent < 0)
      result_.tree.root = id;
    else
      result_.tree.nodes[at(parent)].children.push_back(id);
    return id;
  }

 private:
  BuildResult& result_;
  const BuildOptions& options_;
};

}  // namespace

const char* op_name(Op op) { return op == Op::Max ? "max" : "min"; }

std::vector<int> Tree::subtree_leaves(int node) const {
  std::vector<int> leaves;
  std::vector<int> stack{node};
  while (!stack.empty()) {
    const TreeNode& n = nodes[at(stack.back())];
    stack.pop_back();
    leaves.insert(leaves.end(), n.leaves.begin(), n.leaves.end());
    stack.insert(stack.end(), n.children.begin(), n.children.end());
  }
  std::sort(leaves.begin(), leaves.end());
  return leaves;
}

BuildResult build_tree(PatchGraph graph, const BuildOptions& options) {
  BuildResult result;
  result.original_patch_count = static_cast<int>(graph.patches.size());
  result.graph = std::move(graph);
  const std::vector<int> live = result.graph.live_patches();
  if (live.empty()) throw std::invalid_argument("the solid has no boundary patches");
  Builder builder(result, options);
  for (;;) {
    try {
      auto components = mc_subgraphs(result.graph, result.graph.live_patches());
      if (components.size() == 1) {
        builder.construct(std::move(components.front()), -1);  // the virtual root vanishes
      } else {
        const int root = builder.add_node(Op::Min, {}, -1);   // tree initialisation: a min root over the components
        for (auto& component : components) builder.construct(std::move(component), root);
      }
      return result;
    } catch (const Restart&) {
      result.tree = Tree{};
      ++result.rounds;
    }
  }
}

std::vector<std::string> check_tree(const BuildResult& result) {
  std::vector<std::string> problems;
  const Tree& tree = result.tree;
  const PatchGraph& graph = result.graph;
  if (tree.root < 0 || tree.root >= static_cast<int>(tree.nodes.size())) return {"the tree has no root"};

  // Every live (sub)patch is exactly one leaf.
  std::vector<int> count(graph.patches.size(), 0);
  for (const TreeNode& node : tree.nodes)
    for (int leaf : node.leaves) {
      if (leaf < 0 || leaf >= static_cast<int>(graph.patches.size())) {
        problems.push_back("leaf " + std::to_string(leaf) + " is not a patch");
        continue;
      }
      ++count[at(leaf)];
    }
  for (std::size_t p = 0; p < graph.patches.size(); ++p) {
    const std::string name = "patch " + std::to_string(p);
    if (graph.patches[p].alive && count[p] != 1)
      problems.push_back(name + " is a leaf " + std::to_string(count[p]) + " times");
    if (!graph.patches[p].alive && count[p] != 0) problems.push_back(name + " was decomposed but is a leaf");
  }

  for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
    const TreeNode& node = tree.nodes[n];
    const std::string name = "node " + std::to_string(n);
    for (int child : node.children)
      if (tree.nodes[at(child)].op == node.op) problems.push_back(name + ": child " + std::to_string(child) + " has the same op");
    // The Q condition within the subgraph the node was made from (its subtree's patches).
    const std::vector<int> subtree = tree.subtree_leaves(static_cast<int>(n));
    const Op made_under = opposite(node.op);
    const auto blocked = touches(graph, subtree, [&](FeatureType t) { return blocks(t, made_under); });
    for (int leaf : node.leaves)
      if (blocked[at(leaf)])
        problems.push_back(name + " (" + op_name(node.op) + "): leaf " + std::to_string(leaf) + " has a " +
                           (node.op == Op::Max ? "concave" : "convex") + " edge inside its subgraph");
    // The children are the maximal connected subgraphs of the subgraph minus the leaves.
    std::vector<int> rest;
    std::vector<int> leaves = node.leaves;
    std::sort(leaves.begin(), leaves.end());
    std::set_difference(subtree.begin(), subtree.end(), leaves.begin(), leaves.end(), std::back_inserter(rest));
    std::set<std::vector<int>> expected, actual;
    for (auto& component : mc_subgraphs(graph, rest)) expected.insert(component);
    for (int child : node.children) actual.insert(tree.subtree_leaves(child));
    if (expected != actual)
      problems.push_back(name + ": its children are not the connected components of its subgraph without its leaves");
  }
  for (std::size_t d = 0; d < result.decompositions.size(); ++d) {
    const Decomposition& dec = result.decompositions[d];
    if (!dec.whole_patch) continue;  // NH-Rep's tool's scoped decomposition promises nothing outside its cluster
    // proofs/nhrep.md, Lemma 4.3: exactly the decomposed patch leaves the count; its neighbours keep their kinds.
    if (dec.both_kinds_after != dec.both_kinds_before - 1)
      problems.push_back("decomposition " + std::to_string(d) + " of patch " + std::to_string(dec.patch) +
                         " did not reduce the patches with both convex and concave edges by one (" +
                         std::to_string(dec.both_kinds_before) + " -> " + std::to_string(dec.both_kinds_after) + ")");
    for (int sub : dec.subpatches)
      if (graph.patches[at(sub)].alive && graph.has_convex(sub) && graph.has_concave(sub))
        problems.push_back("decomposition " + std::to_string(d) + ": subpatch " + std::to_string(sub) +
                           " has both convex and concave edges");
  }
  return problems;
}

std::vector<std::vector<int>> group_patches(const PatchGraph& graph, int max_group) {
  if (max_group < 1) throw std::invalid_argument("group size must be at least 1");
  std::vector<std::vector<int>> groups;
  std::vector<int> group_of(graph.patches.size(), -1);
  const auto incident = graph.incident_curves();
  for (int p : graph.live_patches()) {
    std::set<int> taken;
    for (int c : incident[at(p)]) {
      const Curve& curve = graph.curves[at(c)];
      const int w = curve.patch_a == p ? curve.patch_b : curve.patch_a;
      if (group_of[at(w)] >= 0) taken.insert(group_of[at(w)]);
    }
    int g = 0;
    while (g < static_cast<int>(groups.size()) &&
           (taken.count(g) || static_cast<int>(groups[at(g)].size()) >= max_group))
      ++g;
    if (g == static_cast<int>(groups.size())) groups.emplace_back();
    groups[at(g)].push_back(p);
    group_of[at(p)] = g;
  }
  return groups;
}

}  // namespace hsx::nhrep
