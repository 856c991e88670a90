// Bytes -> NH-Rep `.conf` tree (io/nhrep_json.hpp, read_nhtree_conf) and the same bytes as a face-patch file. Bad
// input must end in InputError; anything else (crash, sanitizer report, other exception, hang) is a finding. On
// every accepted tree: ops alternate with depth, the canonical form is stable, and a tree compares equal to itself.
#include "fuzz_support.hpp"

#include <hsx/algorithms/nhrep/compare.hpp>
#include <hsx/io/nhrep_json.hpp>

#include <algorithm>
#include <cstdint>
#include <string>

namespace {

[[noreturn]] void finding(const std::string& what) { hsx::fuzz::finding("fuzz_nhtree_conf", what); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)hsx::read_face_patch(text, "fuzz.txt");
  } catch (const hsx::InputError&) {
  }
  hsx::nhrep::Tree tree;
  try {
    tree = hsx::read_nhtree_conf(text, "fuzz.conf");
  } catch (const hsx::InputError&) {
    return 0;
  }
  if (tree.root != 0 || tree.nodes.empty()) finding("accepted tree without root");
  int max_leaf = -1;
  for (const auto& node : tree.nodes) {
    for (int child : node.children)
      if (tree.nodes[static_cast<std::size_t>(child)].op == node.op) finding("ops do not alternate");
    for (int leaf : node.leaves) max_leaf = std::max(max_leaf, leaf);
  }
  if (max_leaf > 100000000) finding("leaf beyond the limit");
  std::vector<int> label(static_cast<std::size_t>(max_leaf + 1));
  for (std::size_t i = 0; i < label.size(); ++i) label[i] = static_cast<int>(i % 7);
  const hsx::nhrep::TreeComparison c = hsx::nhrep::compare_trees(tree, label, tree, label);
  if (!c.equal || !c.differences.empty()) finding("a tree differs from itself");
  return 0;
}
