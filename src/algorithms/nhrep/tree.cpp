#include <hsx/algorithms/nhrep/tree.hpp>

#include "geometry/components.hpp"

#include <algorithm>
#include <map>
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

/// Maximal connected subgraphs of the induced subgraph on `vertices` (ascending), each ascending, ordered by lowest
/// vertex.
std::vector<std::vector<int>> mc_subgraphs(const PatchGraph& graph, const std::vector<int>& vertices) {
  std::vector<char> member(graph.patches.size(), 0);
  for (int v : vertices) member[at(v)] = 1;
  std::vector<std::pair<int, int>> edges;
  for (const Curve& c : graph.curves)
    if (member[at(c.patch_a)] && member[at(c.patch_b)]) edges.emplace_back(c.patch_a, c.patch_b);
  return induced_components(vertices, edges);
}

/// Thrown to start the tree construction again on the decomposed graph (restart_after_decomposition).
struct Restart {};

class Builder {
 public:
  Builder(BuildResult& result, const BuildOptions& options) : result_(result), options_(options) {}

  /// ConstructTreeNode(G', r). `parent` is a node id, or -1 for the virtual root (op min).
  /// `at_root`: r is the (virtual or real) root of tree initialisation, where Case 1's first subcase applies.
  void construct(std::vector<int> subgraph, int parent, bool at_root) {
    const Op parent_op = parent < 0 ? Op::Min : result_.tree.nodes[at(parent)].op;
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
        for (auto& component : mc_subgraphs(graph, rest)) construct(std::move(component), node, false);
        return;
      }

      const auto convex = touches(graph, subgraph, [](FeatureType t) {
        return t == FeatureType::Convex || t == FeatureType::Hybrid;
      });
      const auto concave = touches(graph, subgraph, [](FeatureType t) {
        return t == FeatureType::Concave || t == FeatureType::Hybrid;
      });
      // the kind of edge that would make G' more than one op's leaves: convex under a min parent, concave under max
      const auto& other = parent_op == Op::Min ? convex : concave;
      const bool any_other = std::any_of(subgraph.begin(), subgraph.end(), [&](int v) { return other[at(v)]; });
      if (at_root && !any_other) {
        // Case 1, first subcase (Fig. 5): no convex edges, so the solid is a union of its patches' halfspaces.
        // Every vertex has no convex edge, so all of G' are leaves of a min node; under a real min root they are
        // the root's own leaves (a min child under a min node would break alternation). The mirror case only
        // arises for a hole nested under a max node (nest_holes): no concave edges, so its patches' halfspaces
        // are intersected, as the max parent's own leaves.
        step.outcome = parent_op == Op::Min ? "case 1: no convex edges" : "case 1: no concave edges (nested hole)";
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

  /// A node under `parent`; with parent -1 (the virtual root) it is the root of what construct builds, recorded
  /// in `top_`.
  int add_node(Op op, std::vector<int> leaves, int parent) {
    const int id = static_cast<int>(result_.tree.nodes.size());
    result_.tree.nodes.push_back(TreeNode{op, std::move(leaves), {}});
    if (parent < 0)
      top_ = id;
    else
      result_.tree.nodes[at(parent)].children.push_back(id);
    return id;
  }

  /// ConstructTreeNode under the virtual root; returns the node it made the top of the subtree.
  int construct_top(std::vector<int> subgraph) {
    top_ = -1;
    construct(std::move(subgraph), -1, true);
    return top_;
  }

 private:
  BuildResult& result_;
  const BuildOptions& options_;
  int top_ = -1;
};

/// The nesting extension (BuildOptions::nest_holes): one subtree per connected part of the solid, the trees of its
/// holes intersected with the tree of its outer boundary, parts united under a min root.
int build_nested(Builder& builder, BuildResult& result, const std::vector<std::vector<int>>& components) {
  const PatchGraph& graph = result.graph;
  std::map<int, std::pair<std::vector<int>, std::vector<int>>> parts;  // region -> (outer components, holes)
  for (std::size_t k = 0; k < components.size(); ++k) {
    // A component is a hole only if all of it faces a hole: where the solid touches itself at a point, one
    // boundary cycle can run along the outside and a hole.
    int region = -1;
    bool hole = true;
    for (int p : components[k])
      for (int piece_id : graph.patches[at(p)].pieces) {
        const BoundaryPiece& piece = graph.surface.pieces[at(piece_id)];
        region = piece.region;
        hole = hole && piece.hole;
      }
    if (region < 0)
      throw std::invalid_argument("nesting: patch " + std::to_string(components[k].front()) +
                                  " has no known solid part (a cavity outside every outer shell or touching one, or a flat shell that encloses no volume)");
    auto& part = parts[region];
    (hole ? part.second : part.first).push_back(static_cast<int>(k));
  }
  std::vector<int> part_nodes;
  for (auto& [region, part] : parts) {
    if (part.first.size() != 1)
      throw std::invalid_argument("nesting: solid part " + std::to_string(region) + " has " +
                                  std::to_string(part.first.size()) + " outer boundary components, expected 1");
    int node = builder.construct_top(components[at(part.first.front())]);
    if (!part.second.empty()) {
      if (result.tree.nodes[at(node)].op == Op::Min) {  // intersect: a max node above the outer boundary's tree
        const int max_node = builder.add_node(Op::Max, {}, -1);
        result.tree.nodes[at(max_node)].children.push_back(node);
        node = max_node;
      }
      for (int hole : part.second) builder.construct(components[at(hole)], node, true);
    }
    part_nodes.push_back(node);
  }
  if (part_nodes.size() == 1) return part_nodes.front();
  const int root = builder.add_node(Op::Min, {}, -1);
  for (int node : part_nodes) {
    TreeNode& n = result.tree.nodes[at(node)];
    TreeNode& r = result.tree.nodes[at(root)];
    if (n.op == Op::Max) {
      r.children.push_back(node);
    } else {  // a union part joins the root's union (alternation)
      r.leaves.insert(r.leaves.end(), n.leaves.begin(), n.leaves.end());
      r.children.insert(r.children.end(), n.children.begin(), n.children.end());
      n.leaves.clear();
      n.children.clear();
    }
  }
  std::sort(result.tree.nodes[at(root)].leaves.begin(), result.tree.nodes[at(root)].leaves.end());
  return root;
}

/// Drops nodes the root does not reach (left behind when nesting merges a union part into the root) and renumbers
/// the others in creation order; steps follow.
void compact(BuildResult& result) {
  Tree& tree = result.tree;
  std::vector<char> reached(tree.nodes.size(), 0);
  std::vector<int> stack{tree.root};
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    reached[at(n)] = 1;
    for (int c : tree.nodes[at(n)].children) stack.push_back(c);
  }
  std::vector<int> new_id(tree.nodes.size(), -1);
  std::vector<TreeNode> nodes;
  for (std::size_t n = 0; n < tree.nodes.size(); ++n)
    if (reached[n]) {
      new_id[n] = static_cast<int>(nodes.size());
      nodes.push_back(tree.nodes[n]);
    }
  if (nodes.size() == tree.nodes.size()) return;
  for (TreeNode& n : nodes)
    for (int& c : n.children) c = new_id[at(c)];
  tree.root = new_id[at(tree.root)];
  tree.nodes = std::move(nodes);
  for (TreeStep& step : result.steps)
    if (step.node >= 0) step.node = new_id[at(step.node)];
}

/// With nesting, a child may hold several components (a solid part: its outer boundary and its holes): every
/// component must lie in exactly one child, and the components of one child must share their region.
bool unions_of_components(const PatchGraph& graph, const std::set<std::vector<int>>& components,
                          const std::set<std::vector<int>>& children) {
  std::map<int, int> child_of;
  int index = 0;
  for (const auto& child : children) {
    for (int p : child) child_of[p] = index;
    ++index;
  }
  std::map<int, int> region_of_child;
  for (const auto& component : components) {
    const int child = child_of.count(component.front()) ? child_of[component.front()] : -1;
    if (child < 0) return false;
    for (int p : component)
      if (!child_of.count(p) || child_of[p] != child) return false;
    const int region =
        graph.surface.pieces[at(graph.patches[at(component.front())].pieces.front())].region;
    auto [it, fresh] = region_of_child.emplace(child, region);
    if (!fresh && it->second != region) return false;
  }
  std::size_t covered = 0;
  for (const auto& component : components) covered += component.size();
  return covered == child_of.size();
}

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
        result.tree.root = builder.construct_top(std::move(components.front()));  // the virtual root vanishes
      } else if (options.nest_holes) {
        result.tree.root = build_nested(builder, result, components);
        result.nested = true;
      } else {
        const int root = builder.add_node(Op::Min, {}, -1);   // tree initialisation: a min root over the components
        for (auto& component : components) builder.construct(std::move(component), root, true);
        result.tree.root = root;
      }
      compact(result);
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
    if (expected != actual && !(result.nested && unions_of_components(graph, expected, actual)))
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
