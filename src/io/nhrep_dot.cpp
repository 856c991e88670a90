// Graphviz diagrams of NH-Rep results: see nhrep_dot.hpp.
#include <hsx/io/nhrep_dot.hpp>
#include <hsx/io/nhrep_svg.hpp>

#include <hsx/io/svg.hpp>

#include <stdexcept>

namespace hsx {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n')
      out += "\\n";  // Graphviz's line break
    else
      out += c;
  }
  return out + "\"";
}

void check(const nhrep::BuildResult& r, const std::vector<std::string>& names, const char* who) {
  if (r.tree.root < 0 || r.tree.root >= static_cast<int>(r.tree.nodes.size()))
    throw std::invalid_argument(std::string(who) + ": the tree has no root");
  if (!names.empty() && names.size() != r.graph.patches.size())
    throw std::invalid_argument(std::string(who) + ": one name per patch expected");
}

std::string leaf_label(int patch, const std::vector<std::string>& names) {
  std::string label = "P" + std::to_string(patch);
  if (!names.empty() && !names[at(patch)].empty()) label += "\n" + names[at(patch)];
  return label;
}

std::string patch_node(int patch, int node, const std::vector<std::string>& names) {
  std::string fill = node >= 0 ? svg_palette_colour(node) : "#ffffff";
  return "  p" + std::to_string(patch) + " [shape=ellipse, style=filled, fillcolor=\"" + fill + "\", label=" +
         quoted(leaf_label(patch, names)) + "];\n";
}

std::vector<int> node_of_patch(const nhrep::BuildResult& r) {
  std::vector<int> node_of(r.graph.patches.size(), -1);
  for (std::size_t n = 0; n < r.tree.nodes.size(); ++n)
    for (int leaf : r.tree.nodes[n].leaves)
      if (leaf >= 0 && at(leaf) < node_of.size()) node_of[at(leaf)] = static_cast<int>(n);
  return node_of;
}

std::string header(const char* kind, const std::string& title) {
  std::string s = std::string(kind) + " nhrep {\n  fontname=\"Helvetica\";\n  node [fontname=\"Helvetica\", "
                  "fontsize=11];\n  edge [fontname=\"Helvetica\", fontsize=9];\n";
  if (!title.empty()) s += "  label=" + quoted(title) + ";\n  labelloc=t;\n";
  return s;
}

}  // namespace

std::string nhtree_dot(const nhrep::BuildResult& r, const std::vector<std::string>& names, const std::string& title) {
  check(r, names, "nhtree_dot");
  std::string s = header("digraph", title);
  const std::vector<int> node_of = node_of_patch(r);
  for (std::size_t n = 0; n < r.tree.nodes.size(); ++n) {
    const nhrep::TreeNode& node = r.tree.nodes[n];
    s += "  n" + std::to_string(n) + " [shape=box, style=\"rounded,bold\", color=\"" +
         svg_palette_colour(static_cast<int>(n)) + "\", label=\"" + nhrep::op_name(node.op) + " (n" +
         std::to_string(n) + (node.op == nhrep::Op::Max ? ", intersection" : ", union") + ")\"];\n";
  }
  for (std::size_t n = 0; n < r.tree.nodes.size(); ++n)
    for (int leaf : r.tree.nodes[n].leaves) s += patch_node(leaf, node_of.at(at(leaf)), names);
  for (std::size_t n = 0; n < r.tree.nodes.size(); ++n) {
    for (int leaf : r.tree.nodes[n].leaves) s += "  n" + std::to_string(n) + " -> p" + std::to_string(leaf) + ";\n";
    for (int child : r.tree.nodes[n].children)
      s += "  n" + std::to_string(n) + " -> n" + std::to_string(child) + ";\n";
  }
  return s + "}\n";
}

std::string nhrep_patch_graph_dot(const nhrep::BuildResult& r, const std::vector<std::string>& names,
                                  const std::string& title) {
  check(r, names, "nhrep_patch_graph_dot");
  std::string s = header("graph", title);
  const std::vector<int> node_of = node_of_patch(r);
  for (int p : r.graph.live_patches()) s += patch_node(p, node_of.at(at(p)), names);
  for (const nhrep::Curve& c : r.graph.curves)
    s += "  p" + std::to_string(c.patch_a) + " -- p" + std::to_string(c.patch_b) + " [color=\"" +
         feature_type_colour(c.type) + "\", penwidth=2, label=\"" + feature_type_name(c.type) + " (" +
         std::to_string(c.links.size()) + ")\"];\n";
  return s + "}\n";
}

}  // namespace hsx
