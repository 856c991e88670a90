#include <hsx/algorithms/nhrep/compare.hpp>

#include <algorithm>
#include <climits>
#include <map>
#include <set>
#include <stdexcept>

namespace hsx::nhrep {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

std::string leaves_text(const std::vector<int>& labels) {
  std::string s;
  for (std::size_t k = 0; k < labels.size(); ++k) s += (k ? "," : "") + std::to_string(labels[k]);
  return s;
}

std::vector<int> leaf_labels(const Tree& tree, const std::vector<int>& label, int node) {
  std::vector<int> labels;
  for (int leaf : tree.nodes[at(node)].leaves) labels.push_back(label[at(leaf)]);
  std::sort(labels.begin(), labels.end());
  return labels;
}

/// Walks both trees, matching children by canonical form first and then, for what remains, by order of their
/// canonical texts; reports the first differing node on every path.
void diff(const Tree& a, const std::vector<int>& la, int na, const Tree& b, const std::vector<int>& lb, int nb,
          const std::string& path, std::vector<std::string>& out) {
  const TreeNode& x = a.nodes[at(na)];
  const TreeNode& y = b.nodes[at(nb)];
  if (x.op != y.op) out.push_back(path + ": ours is " + op_name(x.op) + ", theirs " + op_name(y.op));
  const auto xl = leaf_labels(a, la, na), yl = leaf_labels(b, lb, nb);
  if (xl != yl) out.push_back(path + ": leaves ours {" + leaves_text(xl) + "}, theirs {" + leaves_text(yl) + "}");
  std::multimap<std::string, int> xs, ys;
  for (int c : x.children) xs.emplace(canonical_form(a, la, c), c);
  for (int c : y.children) ys.emplace(canonical_form(b, lb, c), c);
  std::vector<std::pair<std::string, int>> xr, yr;
  for (auto& [form, c] : xs) {
    auto it = ys.find(form);
    if (it != ys.end()) ys.erase(it);
    else xr.emplace_back(form, c);
  }
  for (auto& [form, c] : ys) yr.emplace_back(form, c);
  const std::size_t common = std::min(xr.size(), yr.size());
  for (std::size_t k = 0; k < common; ++k)
    diff(a, la, xr[k].second, b, lb, yr[k].second, path + "/" + std::to_string(k), out);
  for (std::size_t k = common; k < xr.size(); ++k) out.push_back(path + ": only ours has child " + xr[k].first);
  for (std::size_t k = common; k < yr.size(); ++k) out.push_back(path + ": only theirs has child " + yr[k].first);
}

/// The lowest label in every node's subtree (memo[node], INT_MAX while unknown).
int lowest_label(const Tree& tree, const std::vector<int>& label, int node, std::vector<int>& memo) {
  int lowest = INT_MAX;
  for (int leaf : tree.nodes[at(node)].leaves) lowest = std::min(lowest, label[at(leaf)]);
  for (int child : tree.nodes[at(node)].children) lowest = std::min(lowest, lowest_label(tree, label, child, memo));
  return memo[at(node)] = lowest;
}

int copy_relabelled(const Tree& tree, const std::vector<int>& label, const std::vector<int>& lowest, int node,
                    Tree& out) {
  const TreeNode& n = tree.nodes[at(node)];
  const int id = static_cast<int>(out.nodes.size());
  out.nodes.push_back(TreeNode{n.op, leaf_labels(tree, label, node), {}});
  std::vector<std::pair<int, int>> children;
  for (int child : n.children) children.emplace_back(lowest[at(child)], child);
  std::stable_sort(children.begin(), children.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [low, child] : children) {
    const int copied = copy_relabelled(tree, label, lowest, child, out);
    out.nodes[at(id)].children.push_back(copied);
  }
  return id;
}

/// The reference tree with its leaves renumbered 0, 1, ... in ascending order of their values (`values[k]` is
/// the value of new leaf k): labels can then be vectors as long as the tree, whatever the file's numbers are.
Tree dense_leaves(const Tree& tree, std::vector<int>& values) {
  std::map<int, int> index;
  for (const TreeNode& n : tree.nodes)
    for (int leaf : n.leaves) index.emplace(leaf, 0);
  values.clear();
  for (auto& [value, k] : index) {
    k = static_cast<int>(values.size());
    values.push_back(value);
  }
  Tree dense = tree;
  for (TreeNode& n : dense.nodes)
    for (int& leaf : n.leaves) leaf = index.at(leaf);
  return dense;
}

/// Per reference patch number, the set of our original patches its triangles lie on.
std::map<int, std::set<int>> originals_of_reference_patches(const PatchGraph& g, const std::vector<int>& face_patch) {
  const std::size_t original_pieces = static_cast<std::size_t>(std::count_if(
      g.surface.pieces.begin(), g.surface.pieces.end(), [](const BoundaryPiece& p) { return p.split_of < 0; }));
  if (face_patch.size() != original_pieces)
    throw std::invalid_argument("compare_with_reference: the face-patch list has " +
                                std::to_string(face_patch.size()) + " entries, the mesh " +
                                std::to_string(original_pieces) + " triangles");
  std::vector<int> face_original(face_patch.size(), -1);
  for (std::size_t p = 0; p < g.patches.size(); ++p)
    for (int piece : g.patches[p].pieces) {
      const int f = g.surface.pieces[at(piece)].origin;
      if (f >= 0 && at(f) < face_original.size()) face_original[at(f)] = g.original_of(static_cast<int>(p));
    }
  std::map<int, std::set<int>> originals;
  for (std::size_t f = 0; f < face_patch.size(); ++f) originals[face_patch[f]].insert(face_original[f]);
  return originals;
}

}  // namespace

std::vector<int> nhrep_patch_numbers(const PatchGraph& graph) {
  std::vector<int> live = graph.live_patches();
  std::vector<int> lowest(graph.patches.size(), INT_MAX);
  for (int p : live)
    for (int piece : graph.patches[at(p)].pieces)
      lowest[at(p)] = std::min(lowest[at(p)], graph.surface.pieces[at(piece)].origin);
  std::stable_sort(live.begin(), live.end(), [&](int a, int b) { return lowest[at(a)] < lowest[at(b)]; });
  std::vector<int> number(graph.patches.size(), -1);
  for (std::size_t k = 0; k < live.size(); ++k) number[at(live[k])] = static_cast<int>(k);
  return number;
}

std::vector<int> original_labels(const PatchGraph& g) {
  std::vector<int> label(g.patches.size());
  for (std::size_t p = 0; p < g.patches.size(); ++p) label[p] = g.original_of(static_cast<int>(p));
  return label;
}

Tree relabel_tree(const Tree& tree, const std::vector<int>& label) {
  if (tree.root < 0 || at(tree.root) >= tree.nodes.size()) throw std::invalid_argument("relabel_tree: no root");
  for (const TreeNode& n : tree.nodes)
    for (int leaf : n.leaves)
      if (leaf < 0 || at(leaf) >= label.size() || label[at(leaf)] < 0)
        throw std::invalid_argument("relabel_tree: leaf " + std::to_string(leaf) + " has no label");
  std::vector<int> lowest(tree.nodes.size(), INT_MAX);
  lowest_label(tree, label, tree.root, lowest);
  Tree out;
  out.root = copy_relabelled(tree, label, lowest, tree.root, out);
  return out;
}

std::string canonical_form(const Tree& tree, const std::vector<int>& label, int node) {
  if (node < 0) node = tree.root;
  const TreeNode& n = tree.nodes[at(node)];
  std::vector<std::string> children;
  for (int c : n.children) children.push_back(canonical_form(tree, label, c));
  std::sort(children.begin(), children.end());
  std::string s = std::string(op_name(n.op)) + "{" + leaves_text(leaf_labels(tree, label, node));
  for (const std::string& c : children) s += (s.back() == '{' ? "" : ",") + ("[" + c + "]");
  return s + "}";
}

TreeComparison compare_trees(const Tree& ours, const std::vector<int>& our_label, const Tree& theirs,
                             const std::vector<int>& their_label) {
  TreeComparison result;
  result.ours = canonical_form(ours, our_label);
  result.theirs = canonical_form(theirs, their_label);
  result.equal = result.ours == result.theirs;
  if (!result.equal) diff(ours, our_label, ours.root, theirs, their_label, theirs.root, "root", result.differences);
  return result;
}

ReferenceComparison compare_with_reference(const BuildResult& result, const ReferenceTree& reference) {
  std::vector<int> values;
  const Tree theirs = dense_leaves(reference.tree, values);
  std::vector<int> their_label(values.size(), -1);
  std::vector<int> our_label;
  ReferenceComparison c;
  if (reference.face_patch.empty()) {
    // their leaf k is our patch with NH-Rep number k
    our_label = nhrep_patch_numbers(result.graph);
    their_label = values;
    c.basis = "patch numbers (lowest triangle first)";
  } else {
    const auto originals = originals_of_reference_patches(result.graph, reference.face_patch);
    for (std::size_t k = 0; k < values.size(); ++k) {
      const auto it = originals.find(values[k]);
      if (it == originals.end())
        throw std::invalid_argument("compare_with_reference: reference leaf " + std::to_string(values[k]) +
                                    " has no triangles");
      if (it->second.size() != 1) {
        c.mismatch = "reference patch " + std::to_string(values[k]) + " spans " +
                     std::to_string(it->second.size()) + " of our original patches";
        return c;
      }
      their_label[k] = *it->second.begin();
    }
    our_label = original_labels(result.graph);
    c.basis = "original patches (each reference patch mapped through its triangles)";
  }
  c.trees = compare_trees(result.tree, our_label, theirs, their_label);
  c.equal = c.trees.equal;
  return c;
}

GraphComparison compare_patch_graphs(const PatchGraph& original, const std::vector<ReferenceEdge>& theirs) {
  std::map<std::pair<int, int>, FeatureType> their_type;
  for (const ReferenceEdge& e : theirs) {
    if (e.a >= e.b) throw std::invalid_argument("compare_patch_graphs: edge " + std::to_string(e.a) + "-" +
                                                std::to_string(e.b) + " is not ordered a < b");
    if (!their_type.emplace(std::make_pair(e.a, e.b), e.type).second)
      throw std::invalid_argument("compare_patch_graphs: edge " + std::to_string(e.a) + "-" + std::to_string(e.b) +
                                  " listed twice");
  }
  const std::vector<int> number = nhrep_patch_numbers(original);
  std::map<std::pair<int, int>, FeatureType> ours;
  for (const Curve& curve : original.curves) {
    const int a = number[at(curve.patch_a)], b = number[at(curve.patch_b)];
    auto [it, fresh] = ours.emplace(std::make_pair(std::min(a, b), std::max(a, b)), curve.type);
    if (!fresh) it->second = combine_feature_types(it->second, curve.type);
  }
  GraphComparison c;
  c.reference_edges = static_cast<int>(their_type.size());
  for (const auto& [pair, type] : their_type) {
    const auto it = ours.find(pair);
    if (it == ours.end()) c.differences.push_back({pair.first, pair.second, std::nullopt, type});
    else if (it->second != type) c.differences.push_back({pair.first, pair.second, it->second, type});
  }
  for (const auto& [pair, type] : ours)
    if (!their_type.count(pair)) c.differences.push_back({pair.first, pair.second, type, std::nullopt});
  return c;
}

}  // namespace hsx::nhrep
