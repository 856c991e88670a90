#include <hsx/algorithms/nhrep/compare.hpp>

#include <algorithm>
#include <map>

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

}  // namespace

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

}  // namespace hsx::nhrep
