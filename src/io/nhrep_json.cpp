#include <hsx/io/nhrep_json.hpp>

#include <algorithm>
#include <climits>
#include <numeric>
#include <cctype>
#include <sstream>

namespace hsx {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

nlohmann::json node_json(const nhrep::Tree& tree, int node) {
  const nhrep::TreeNode& n = tree.nodes[at(node)];
  nlohmann::json children = nlohmann::json::array();
  for (int child : n.children) children.push_back(node_json(tree, child));
  return {{"op", nhrep::op_name(n.op)}, {"leaves", n.leaves}, {"children", children}};
}

void conf_list(const nhrep::Tree& tree, int node, const std::vector<int>& conf_id, std::string& out) {
  const nhrep::TreeNode& n = tree.nodes[at(node)];
  std::vector<int> leaves;
  for (int leaf : n.leaves) leaves.push_back(conf_id[at(leaf)]);
  std::sort(leaves.begin(), leaves.end());
  out += '[';
  for (int leaf : leaves) out += std::to_string(leaf) + ',';
  // children in order of their lowest leaf, as NH-Rep lists them
  std::vector<std::pair<int, int>> children;
  for (int child : n.children) {
    int lowest = INT_MAX;
    for (int leaf : tree.subtree_leaves(child)) lowest = std::min(lowest, conf_id[at(leaf)]);
    children.emplace_back(lowest, child);
  }
  std::sort(children.begin(), children.end());
  for (const auto& [lowest, child] : children) {
    conf_list(tree, child, conf_id, out);
    out += ',';
  }
  out += ']';
}

void text(const nhrep::Tree& tree, int node, std::string& out) {
  const nhrep::TreeNode& n = tree.nodes[at(node)];
  out += nhrep::op_name(n.op);
  out += '(';
  bool first = true;
  for (int leaf : n.leaves) {
    out += (first ? "" : ", ") + std::to_string(leaf);
    first = false;
  }
  for (int child : n.children) {
    out += first ? "" : ", ";
    first = false;
    text(tree, child, out);
  }
  out += ')';
}

class ConfParser {
 public:
  ConfParser(const std::string& text, const std::string& source) : text_(text), source_(source) {}

  nhrep::Tree parse() {
    expect_word("csg");
    expect('{');
    expect_word("list");
    expect('=');
    std::vector<Item> root = list();
    skip();
    if (peek() == ',') ++pos_;
    expect_word("flag_convex");
    expect('=');
    skip();
    const char flag = peek();
    if (flag != '0' && flag != '1') fail("flag_convex must be 0 or 1");
    ++pos_;
    skip();
    if (peek() == ',') ++pos_;
    expect('}');
    skip();
    if (pos_ != text_.size()) fail("unexpected text after the closing brace");
    nhrep::Tree tree;
    tree.root = build(tree, root, flag == '1' ? nhrep::Op::Max : nhrep::Op::Min);
    return tree;
  }

 private:
  struct Item {
    int leaf = -1;
    std::vector<Item> list;
  };

  int build(nhrep::Tree& tree, const std::vector<Item>& items, nhrep::Op op) {
    const int id = static_cast<int>(tree.nodes.size());
    tree.nodes.push_back(nhrep::TreeNode{op, {}, {}});
    for (const Item& item : items) {
      if (item.leaf >= 0) {
        tree.nodes[at(id)].leaves.push_back(item.leaf);
      } else {
        const int child = build(tree, item.list, op == nhrep::Op::Max ? nhrep::Op::Min : nhrep::Op::Max);
        tree.nodes[at(id)].children.push_back(child);
      }
    }
    std::sort(tree.nodes[at(id)].leaves.begin(), tree.nodes[at(id)].leaves.end());
    return id;
  }

  std::vector<Item> list() {
    if (++depth_ > 1000) fail("lists nested too deeply");
    expect('[');
    std::vector<Item> items;
    for (;;) {
      skip();
      const char c = peek();
      if (c == ']') {
        ++pos_;
        break;
      }
      Item item;
      if (c == '[') {
        item.list = list();
      } else if (c >= '0' && c <= '9') {
        long value = 0;
        while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') {
          value = value * 10 + (text_[pos_++] - '0');
          if (value > 100000000) fail("patch id too large");
        }
        item.leaf = static_cast<int>(value);
      } else {
        fail(std::string("expected a patch id, '[' or ']'"));
      }
      items.push_back(std::move(item));
      skip();
      if (peek() == ',') ++pos_;
    }
    --depth_;
    return items;
  }

  void skip() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void expect(char c) {
    skip();
    if (peek() != c) fail(std::string("expected '") + c + "'");
    ++pos_;
  }
  void expect_word(const std::string& word) {
    skip();
    if (text_.compare(pos_, word.size(), word) != 0) fail("expected '" + word + "'");
    pos_ += word.size();
  }
  [[noreturn]] void fail(const std::string& what) const {
    const long line = 1 + std::count(text_.begin(), text_.begin() + static_cast<long>(std::min(pos_, text_.size())), '\n');
    throw InputError(source_ + ":" + std::to_string(line) + ": " + what);
  }

  const std::string& text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

nhrep::Tree read_nhtree_conf(const std::string& text, const std::string& source) {
  return ConfParser(text, source).parse();
}

std::vector<int> read_face_patch(const std::string& text, const std::string& source) {
  std::vector<int> result;
  std::istringstream in(text);
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::size_t used = 0;
    long value = -1;
    try {
      value = std::stol(line, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != line.size() || value < 0 || value > 100000000)
      throw InputError(source + ":" + std::to_string(number) + ": expected a patch id, got '" + line + "'");
    result.push_back(static_cast<int>(value));
  }
  return result;
}

std::vector<int> nhtree_conf_ids(const nhrep::PatchGraph& graph) {
  std::vector<int> live = graph.live_patches();
  std::vector<int> lowest(graph.patches.size(), INT_MAX);
  for (int p : live)
    for (int piece : graph.patches[at(p)].pieces)
      lowest[at(p)] = std::min(lowest[at(p)], graph.surface.pieces[at(piece)].origin);
  std::stable_sort(live.begin(), live.end(), [&](int a, int b) { return lowest[at(a)] < lowest[at(b)]; });
  std::vector<int> conf_id(graph.patches.size(), -1);
  for (std::size_t k = 0; k < live.size(); ++k) conf_id[at(live[k])] = static_cast<int>(k);
  return conf_id;
}

nlohmann::json nhtree_to_json(const nhrep::BuildResult& result, const std::vector<std::vector<int>>* groups) {
  const nhrep::PatchGraph& graph = result.graph;
  const std::vector<int> conf_id = nhtree_conf_ids(graph);
  nlohmann::json patches = nlohmann::json::array();
  for (std::size_t p = 0; p < graph.patches.size(); ++p) {
    const nhrep::PatchInfo& info = graph.patches[p];
    std::vector<int> origins;
    for (int piece : info.pieces) origins.push_back(graph.surface.pieces[at(piece)].origin);
    std::sort(origins.begin(), origins.end());
    origins.erase(std::unique(origins.begin(), origins.end()), origins.end());
    nlohmann::json patch = {{"id", p}, {"alive", info.alive}, {"parent", info.parent},
                            {"pieces", info.pieces.size()}, {"origins", origins}};
    if (info.alive) patch["conf_id"] = conf_id[p];
    patches.push_back(patch);
  }
  nlohmann::json edges = nlohmann::json::array();
  for (const nhrep::Curve& c : graph.curves)
    edges.push_back({{"a", c.patch_a}, {"b", c.patch_b}, {"type", feature_type_name(c.type)}, {"links", c.links.size()}});
  nlohmann::json internal = nlohmann::json::array();
  for (const nhrep::Curve& c : graph.internal_curves)
    internal.push_back({{"patch", c.patch_a}, {"type", feature_type_name(c.type)}, {"links", c.links.size()}});
  nlohmann::json decompositions = nlohmann::json::array();
  for (const nhrep::Decomposition& d : result.decompositions)
    decompositions.push_back({{"patch", d.patch}, {"subpatches", d.subpatches}, {"pieces_split", d.pieces_split},
                              {"cut_links", d.cut_links}, {"both_kinds_before", d.both_kinds_before},
                              {"both_kinds_after", d.both_kinds_after}});
  nlohmann::json steps = nlohmann::json::array();
  for (const nhrep::TreeStep& s : result.steps) {
    nlohmann::json step = {{"subgraph", s.subgraph}, {"parent_op", nhrep::op_name(s.parent_op)},
                           {"parent_virtual", s.parent_virtual}, {"q", s.q}, {"outcome", s.outcome}};
    if (s.decomposition >= 0) step["decomposition"] = s.decomposition;
    steps.push_back(step);
  }
  nlohmann::json doc = {{"format", kNhTreeFormat},
                        {"dimension", graph.surface.dimension},
                        {"tree", node_json(result.tree, result.tree.root)},
                        {"patches", patches},
                        {"patch_graph", edges},
                        {"internal_curves", internal},
                        {"decompositions", decompositions},
                        {"steps", steps}};
  if (groups) doc["groups"] = *groups;
  return doc;
}

std::string nhtree_conf(const nhrep::BuildResult& result) {
  const std::vector<int> conf_id = nhtree_conf_ids(result.graph);
  std::string list;
  conf_list(result.tree, result.tree.root, conf_id, list);
  // NH-Rep writes a comma after every element, the root list included.
  std::string out = "csg{\n    list = ";
  out += list;
  out += ",\n    flag_convex = ";
  out += result.tree.nodes[at(result.tree.root)].op == nhrep::Op::Max ? "1" : "0";
  out += ",\n}";  // no final newline, byte for byte as NH-Rep writes it
  return out;
}

std::string nhtree_text(const nhrep::Tree& tree) {
  std::string out;
  text(tree, tree.root, out);
  return out;
}

}  // namespace hsx
