#include <hsx/io/nhrep_json.hpp>

#include <hsx/io/files.hpp>
#include <hsx/io/json_values.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
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

/// A tree already in NH-Rep numbering and order (relabel_tree): leaves, then children, each list closed by ','.
void conf_list(const nhrep::Tree& tree, int node, std::string& out) {
  const nhrep::TreeNode& n = tree.nodes[at(node)];
  out += '[';
  for (int leaf : n.leaves) out += std::to_string(leaf) + ',';
  for (int child : n.children) {
    conf_list(tree, child, out);
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

  /// After parse(): per leaf value, the line it is on.
  const std::map<int, long>& leaf_lines() const { return leaf_line_; }

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
    number_leaf_lines();
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
        leaf_pos_.push_back(pos_);
        long value = 0;
        while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') {
          value = value * 10 + (text_[pos_++] - '0');
          if (value > kMaxPatchId) fail("patch id too large (the limit is " + std::to_string(kMaxPatchId) + ")");
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

  /// Lines of the leaves (one pass over the text), and no patch id twice.
  void number_leaf_lines() {
    long line = 1;
    std::size_t scanned = 0;
    for (std::size_t pos : leaf_pos_) {
      line += std::count(text_.begin() + static_cast<long>(scanned), text_.begin() + static_cast<long>(pos), '\n');
      scanned = pos;
      const int value = std::stoi(text_.substr(pos, text_.find_first_not_of("0123456789", pos) - pos));
      const auto [it, fresh] = leaf_line_.emplace(value, line);
      if (!fresh)
        throw InputError(source_ + ":" + std::to_string(line) + ": patch id " + std::to_string(value) +
                         " appears twice (first on line " + std::to_string(it->second) + ")");
    }
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
  std::vector<std::size_t> leaf_pos_;
  std::map<int, long> leaf_line_;
};

[[noreturn]] void empty_file(const std::string& source) { throw InputError(source + ":1: empty file"); }

/// A `.conf` whose lists hold no patch at all (`list = []`) is no Boolean tree.
void require_leaves(const nhrep::Tree& tree, const std::string& source) {
  if (tree.root < 0 || tree.subtree_leaves(tree.root).empty())
    throw InputError(source + ": the tree has no patch at all (list = []): a Boolean tree needs at least one leaf");
}

bool blank(const std::string& text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
}

/// One `edge: A-B : T` line (T = 0 smooth, 1 convex, 2 concave); nullopt for blank and comment lines.
std::optional<nhrep::ReferenceEdge> graph_line(const std::string& line, const std::string& where) {
  if (blank(line) || line[line.find_first_not_of(" \t")] == '#') return std::nullopt;
  long a = -1, b = -1, t = -1;
  char dash = 0, colon = 0;
  std::istringstream fields(line);
  std::string word, rest;
  if (!(fields >> word >> a >> dash >> b >> colon >> t) || (fields >> rest) || word != "edge:" || dash != '-' ||
      colon != ':')
    throw InputError(where + ": expected 'edge: A-B : T', got '" + line + "'");
  if (t < 0 || t > 2) throw InputError(where + ": edge type " + std::to_string(t) + " is not 0, 1 or 2");
  if (a < 0 || b < 0 || a > kMaxPatchId || b > kMaxPatchId || a == b)
    throw InputError(where + ": patch ids must be distinct and in 0.." + std::to_string(kMaxPatchId));
  const FeatureType types[] = {FeatureType::Smooth, FeatureType::Convex, FeatureType::Concave};
  return nhrep::ReferenceEdge{static_cast<int>(std::min(a, b)), static_cast<int>(std::max(a, b)), types[t]};
}

}  // namespace

nhrep::Tree read_nhtree_conf(const std::string& text, const std::string& source) {
  if (blank(text)) empty_file(source);
  nhrep::Tree tree = ConfParser(text, source).parse();
  require_leaves(tree, source);
  return tree;
}

std::vector<nhrep::ReferenceEdge> read_nhrep_patch_graph(const std::string& text, const std::string& source) {
  if (blank(text)) empty_file(source);
  std::vector<nhrep::ReferenceEdge> edges;
  std::map<std::pair<int, int>, long> first_line;
  std::istringstream in(text);
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string where = source + ":" + std::to_string(number);
    const std::optional<nhrep::ReferenceEdge> edge = graph_line(line, where);
    if (!edge) continue;
    const auto [it, fresh] = first_line.emplace(std::make_pair(edge->a, edge->b), number);
    if (!fresh)
      throw InputError(where + ": edge " + std::to_string(edge->a) + "-" + std::to_string(edge->b) +
                       " listed twice (first on line " + std::to_string(it->second) + ")");
    edges.push_back(*edge);
  }
  return edges;
}

NhrepReference read_nhrep_reference(const NhrepReferenceFiles& files) {
  if (!files.face_patch.empty() && files.tree.empty())
    throw InputError("the reference face-patch file " + files.face_patch + " needs the reference tree (.conf)");
  NhrepReference r;
  r.files = files;
  if (!files.graph.empty()) r.graph = read_nhrep_patch_graph(read_file(files.graph), files.graph);
  if (files.tree.empty()) return r;
  const std::string text = read_file(files.tree);
  if (blank(text)) empty_file(files.tree);
  ConfParser parser(text, files.tree);
  r.tree.emplace();
  r.tree->tree = parser.parse();
  require_leaves(r.tree->tree, files.tree);
  if (files.face_patch.empty()) return r;
  r.tree->face_patch = read_face_patch(read_file(files.face_patch), files.face_patch);
  const std::set<int> listed(r.tree->face_patch.begin(), r.tree->face_patch.end());
  for (const auto& [leaf, line] : parser.leaf_lines())
    if (!listed.count(leaf))
      throw InputError(files.tree + ":" + std::to_string(line) + ": patch " + std::to_string(leaf) +
                       " has no triangle in " + files.face_patch);
  return r;
}

void check_reference_mesh(const NhrepReference& reference, std::size_t triangles) {
  if (!reference.tree || reference.tree->face_patch.empty()) return;
  const std::size_t lines = reference.tree->face_patch.size();
  if (lines != triangles)
    throw InputError(reference.files.face_patch + ": " + std::to_string(lines) + " patch ids, but the mesh has " +
                     std::to_string(triangles) + " triangles");
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
    if (used != line.size() || value < 0 || value > kMaxPatchId)
      throw InputError(source + ":" + std::to_string(number) + ": expected a patch id (0.." +
                       std::to_string(kMaxPatchId) + "), got '" + line + "'");
    result.push_back(static_cast<int>(value));
  }
  if (result.empty()) throw InputError(source + ":1: " + (blank(text) ? "empty file" : "no patch ids"));
  return result;
}

std::vector<int> nhtree_conf_ids(const nhrep::PatchGraph& graph) { return nhrep::nhrep_patch_numbers(graph); }

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

namespace {

nlohmann::json exact_points(const std::vector<std::vector<Rational>>& points) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : points) {
    nlohmann::json point = nlohmann::json::array();
    for (const Rational& q : p) point.push_back(exact_string(q));
    out.push_back(point);
  }
  return out;
}

}  // namespace

nlohmann::json nhtree_planar_json(const nhrep::PlanarTree& tree, const nhrep::PlanarEvaluation& evaluation) {
  nlohmann::json names = nlohmann::json::object(), where = nlohmann::json::object();
  for (int p : tree.built.graph.live_patches()) {
    names[std::to_string(p)] = tree.leaf_names[at(p)];
    nlohmann::json pieces = nlohmann::json::array();
    for (const nhrep::PlanarPiece& piece : tree.pieces[at(p)]) {
      nlohmann::json entry = {{"edge", piece.edge}};
      if (piece.split_point) {
        entry["kept_vertex"] = piece.kept_vertex;
        entry["split_point"] = point_to_json(*piece.split_point);
      }
      pieces.push_back(entry);
    }
    where[std::to_string(p)] = pieces;
  }
  const nhrep::Evaluation& e = evaluation.evaluation;
  return {{"natural_halfspaces", names},
          {"patch_pieces", where},
          {"evaluation",
           {{"verdict", nhrep::verdict_key(e.verdict)}, {"correct", e.correct}, {"describable", e.describable},
            {"cells", evaluation.cells}, {"wrong_inside", exact_points(evaluation.missed)},
            {"wrong_outside", exact_points(evaluation.added)}, {"violations", e.violations}}}};
}

nlohmann::json nhtree_solid3_json(const nhrep::SolidTree3& tree, const nhrep::CellEvaluation& evaluation) {
  nlohmann::json names = nlohmann::json::object(), where = nlohmann::json::object();
  const nhrep::PatchGraph& g = tree.built.graph;
  for (int p : g.live_patches()) {
    names[std::to_string(p)] = tree.leaf_names[at(p)];
    nlohmann::json pieces = nlohmann::json::array();
    for (int piece_id : g.patches[at(p)].pieces) {
      const BoundaryPiece& piece = g.surface.pieces[at(piece_id)];
      if (piece.split_of < 0)
        pieces.push_back(piece.origin);
      else
        pieces.push_back({{"triangle", piece.origin}, {"kept_edge", g.surface.links[at(piece.kept_link)].origin}});
    }
    where[std::to_string(p)] = pieces;
  }
  const nhrep::Evaluation& e = evaluation.evaluation;
  return {{"natural_halfspaces", names},
          {"patch_triangles", where},
          {"evaluation",
           {{"verdict", nhrep::verdict_key(e.verdict)}, {"correct", e.correct}, {"describable", e.describable},
            {"cells", evaluation.cells}, {"wrong_inside", exact_points(evaluation.missed)},
            {"wrong_outside", exact_points(evaluation.added)}, {"violations", e.violations}}}};
}

std::string nhtree_conf(const nhrep::BuildResult& result) {
  const nhrep::Tree tree = nhrep::relabel_tree(result.tree, nhtree_conf_ids(result.graph));
  std::string list;
  conf_list(tree, tree.root, list);
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
