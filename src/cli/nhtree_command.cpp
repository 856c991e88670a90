// `hsx nhtree`: NH-Rep's Boolean tree (Guo et al. 2022, Section 5) of a 2D solid or a 3D mesh, with the patch
// graph, the cross-checks, and optional comparison with a tree written by NH-Rep's own tool.
#include <hsx/algorithms/nhrep/compare.hpp>
#include <hsx/algorithms/nhrep/evaluate.hpp>
#include <hsx/algorithms/nhrep/tree.hpp>
#include "cli/commands.hpp"
#include <hsx/io/input.hpp>
#include <hsx/complex/carry_solid2.hpp>
#include <hsx/io/solid.hpp>
#include <hsx/complex/boundary_from_arrangement2.hpp>
#include <hsx/complex/boundary_from_mesh.hpp>
#include <hsx/geometry/mesh3.hpp>
#include "geometry/planar_corners.hpp"
#include <hsx/io/json_values.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/nhrep_json.hpp>
#include <hsx/io/nhrep_mesh.hpp>
#include <hsx/io/nhrep_svg.hpp>

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

namespace hsx::cli {
namespace {

struct NhtreeOptions {
  std::string input, fea_path, sharp_angle;  ///< empty: 0, or 20 with --nhrep-tool
  bool nhrep_tool = false;
  bool nest_holes = false;
  SolidSource solid;
  std::string json_path, conf_path, svg_path, reference_conf, reference_face_patch, reference_graph;
  std::string decomposed_prefix;  ///< mesh: write PREFIX.obj, PREFIX.fea, PREFIX.face-patch.txt
  bool group = false;
  int max_group = 6;
  bool quiet_steps = false;
};

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(),
                                                 [](char a, char b) { return std::tolower(a) == b; });
}

std::string join(const std::vector<int>& v) {
  std::string s;
  for (std::size_t k = 0; k < v.size(); ++k) s += (k ? " " : "") + std::to_string(v[k]);
  return s;
}

void print_graph(const nhrep::BuildResult& r, const std::vector<std::string>& patch_names, std::ostream& out) {
  const nhrep::PatchGraph& g = r.graph;
  out << "patch graph: " << g.live_patches().size() << " patches (" << r.original_patch_count << " original), "
      << g.curves.size() << " feature curves";
  std::map<FeatureType, int> by_type;
  for (const nhrep::Curve& c : g.curves) ++by_type[c.type];
  const char* sep = ": ";
  for (auto [type, count] : by_type) {
    out << sep << count << " " << feature_type_name(type);
    sep = ", ";
  }
  if (!g.internal_curves.empty()) out << "; " << g.internal_curves.size() << " inside one patch (not edges)";
  out << "\n";
  for (int p : g.live_patches()) {
    const nhrep::PatchInfo& info = g.patches[static_cast<std::size_t>(p)];
    out << "  patch " << p;
    if (!patch_names.empty()) out << " on " << patch_names[static_cast<std::size_t>(p)];
    if (info.parent >= 0) out << " (part of patch " << info.parent << ")";
    out << ": " << info.pieces.size() << (g.surface.dimension == 3 ? " triangle" : " piece") << (info.pieces.size() == 1 ? "" : "s") << "\n";
  }
  for (const nhrep::Curve& c : g.curves)
    out << "  edge " << c.patch_a << "-" << c.patch_b << ": " << feature_type_name(c.type) << " (" << c.links.size()
        << (g.surface.dimension == 3 ? " mesh edge" : " corner") << (c.links.size() == 1 ? "" : "s") << ")\n";
}

/// Interior points of up to `max` cells, as "(x, y)" with 6 significant digits (a pointer, not a proof: the cells
/// are exact).
std::string witnesses(const Complex& complex, const std::vector<int>& cells, std::size_t max = 6) {
  std::string s;
  for (std::size_t i = 0; i < cells.size() && i < max; ++i) {
    const auto& w = complex.cells.at(static_cast<std::size_t>(cells[i])).witness;
    s += (i ? ", (" : "(") + decimal_string(w[0], 6) + ", " + decimal_string(w[1], 6) + ")";
  }
  if (cells.size() > max) s += ", ... (" + std::to_string(cells.size()) + " cells)";
  return s.empty() ? "none" : s;
}

/// Exact interior points of cells (of the whole-plane arrangement, whose cell ids mean nothing to the caller).
nlohmann::json witness_json(const Complex& complex, const std::vector<int>& cells) {
  nlohmann::json points = nlohmann::json::array();
  for (int c : cells) {
    const auto& w = complex.cells.at(static_cast<std::size_t>(c)).witness;
    points.push_back({exact_string(w[0]), exact_string(w[1])});
  }
  return points;
}

nhrep::BuildOptions build_options(const NhtreeOptions& o) {
  nhrep::BuildOptions options;
  options.restart_after_decomposition = o.nhrep_tool;
  options.decompose_within_subgraph = o.nhrep_tool;
  options.nest_holes = o.nest_holes;
  return options;
}

/// Algorithm 1. The paper's version needs fewer decompositions than patches (proofs/nhrep.md, Lemma 4.3); NH-Rep's
/// tool's scoped decomposition has no such bound, so its guard is reported as a result, not an internal error.
nhrep::BuildResult run_algorithm1(nhrep::PatchGraph graph, const NhtreeOptions& o) {
  const nhrep::BuildOptions options = build_options(o);
  try {
    return nhrep::build_tree(std::move(graph), options);
  } catch (const std::invalid_argument& e) {
    if (!o.nest_holes) throw;
    throw InputError(std::string("--nest-holes: ") + e.what());
  } catch (const std::runtime_error& e) {
    if (!o.nhrep_tool) throw;
    std::cout << "NH-Rep tool mode did not finish: " << e.what() << "\n";
    throw CLI::RuntimeError(3);
  }
}

void print_run(const nhrep::BuildResult& r, std::ostream& out) {
  for (const nhrep::Decomposition& d : r.decompositions)
    out << "decomposed patch " << d.patch << (d.whole_patch ? "" : " (against its cluster only)") << " into "
        << join(d.subpatches) << " (" << d.pieces_split << (d.pieces_split == 1 ? " piece" : " pieces")
        << " face-split, " << d.cut_links << (d.cut_links == 1 ? " link" : " links")
        << " cut); patches with both convex and concave edges: "
        << d.both_kinds_before << " -> " << d.both_kinds_after << "\n";
  if (r.rounds > 1) out << "tree constructions: " << r.rounds << " (restarted after each decomposition)\n";
  out << "tree: " << nhtree_text(r.tree) << "\n";
}

/// The original patch id of every patch (itself for original patches), for comparing through decompositions.
std::vector<int> original_labels(const nhrep::PatchGraph& g) {
  std::vector<int> label(g.patches.size());
  for (std::size_t p = 0; p < g.patches.size(); ++p) label[p] = g.original_of(static_cast<int>(p));
  return label;
}

/// Compares with NH-Rep's tree. Without a face-patch file the reference leaves are taken to use our conf
/// numbering. With one, each reference patch is mapped to the original patch holding its triangles.
bool compare_reference(const NhtreeOptions& o, const nhrep::BuildResult& r, std::ostream& out) {
  const nhrep::Tree theirs = read_nhtree_conf(read_file(o.reference_conf), o.reference_conf);
  int max_leaf = -1;
  for (const auto& node : theirs.nodes)
    for (int leaf : node.leaves) max_leaf = std::max(max_leaf, leaf);
  const nhrep::PatchGraph& g = r.graph;
  const std::vector<int> conf_id = nhtree_conf_ids(g);
  std::vector<int> their_label(static_cast<std::size_t>(max_leaf + 1), -1);
  std::vector<int> our_label;
  std::string basis;
  if (o.reference_face_patch.empty()) {
    // their leaf k is our patch with conf_id k
    our_label = conf_id;
    for (int k = 0; k <= max_leaf; ++k) their_label[static_cast<std::size_t>(k)] = k;
    basis = "patch numbers (lowest triangle first)";
  } else {
    const std::vector<int> face_patch = read_face_patch(read_file(o.reference_face_patch), o.reference_face_patch);
    // our original patch of every triangle
    std::vector<int> face_original(face_patch.size(), -1);
    for (std::size_t p = 0; p < g.patches.size(); ++p)
      for (int piece : g.patches[p].pieces) {
        const int f = g.surface.pieces[static_cast<std::size_t>(piece)].origin;
        if (f >= 0 && f < static_cast<int>(face_original.size())) face_original[static_cast<std::size_t>(f)] = g.original_of(static_cast<int>(p));
      }
    if (face_patch.size() != static_cast<std::size_t>(std::count_if(g.surface.pieces.begin(), g.surface.pieces.end(),
                                                                    [](const BoundaryPiece& p) { return p.split_of < 0; })))
      throw InputError(o.reference_face_patch + ": " + std::to_string(face_patch.size()) +
                       " lines, but the mesh has a different number of triangles");
    std::map<int, std::set<int>> originals_of_theirs;
    for (std::size_t f = 0; f < face_patch.size(); ++f) originals_of_theirs[face_patch[f]].insert(face_original[f]);
    for (const auto& [theirs_id, originals] : originals_of_theirs) {
      if (theirs_id > max_leaf) continue;
      if (originals.size() != 1) {
        out << "reference patch " << theirs_id << " spans " << originals.size() << " of our original patches\n";
        return false;
      }
      their_label[static_cast<std::size_t>(theirs_id)] = *originals.begin();
    }
    our_label = original_labels(g);
    basis = "original patches (each reference patch mapped through its triangles)";
  }
  for (const auto& node : theirs.nodes)
    for (int leaf : node.leaves)
      if (their_label[static_cast<std::size_t>(leaf)] < 0)
        throw InputError(o.reference_conf + ": leaf " + std::to_string(leaf) + " has no triangles");
  const nhrep::TreeComparison c = nhrep::compare_trees(r.tree, our_label, theirs, their_label);
  out << "reference " << o.reference_conf << ": " << (c.equal ? "same tree" : "DIFFERENT tree") << " up to " << basis
      << "\n";
  if (!c.equal) {
    out << "  ours:   " << c.ours << "\n  theirs: " << c.theirs << "\n";
    for (const std::string& d : c.differences) out << "  " << d << "\n";
  }
  return c.equal;
}

/// Compares the original patch graph (numbered by lowest triangle) with NH-Rep's `edge: a-b : t` listing
/// (t = 1 convex, 2 concave, 0 smooth; one line per adjacent pair). Our multigraph's curves between a pair are
/// combined as curve types combine (convex with concave gives hybrid). Returns the number of differences.
int compare_reference_graph(const std::string& path, const nhrep::PatchGraph& original, std::ostream& out) {
  const std::string text = read_file(path);
  std::map<std::pair<int, int>, int> theirs;
  std::istringstream in(text);
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    int a = -1, b = -1, t = -1;
    char dash = 0, colon = 0;
    std::istringstream fields(line);
    std::string word;
    if (!(fields >> word >> a >> dash >> b >> colon >> t) || word != "edge:" || dash != '-' || colon != ':' || t < 0 ||
        t > 2 || a < 0 || b < 0)
      throw InputError(path + ":" + std::to_string(number) + ": expected 'edge: A-B : T'");
    theirs[{std::min(a, b), std::max(a, b)}] = t;
  }
  const std::vector<int> conf_id = nhtree_conf_ids(original);
  std::map<std::pair<int, int>, FeatureType> ours;
  for (const nhrep::Curve& c : original.curves) {
    const int a = conf_id[static_cast<std::size_t>(c.patch_a)], b = conf_id[static_cast<std::size_t>(c.patch_b)];
    auto [it, fresh] = ours.emplace(std::make_pair(std::min(a, b), std::max(a, b)), c.type);
    if (!fresh) it->second = combine_feature_types(it->second, c.type);
  }
  const char* names[] = {"smooth", "convex", "concave"};
  int differences = 0;
  for (const auto& [pair, t] : theirs) {
    auto it = ours.find(pair);
    if (it == ours.end()) {
      out << "  edge " << pair.first << "-" << pair.second << ": only theirs (" << names[t] << ")\n";
      ++differences;
    } else if (feature_type_name(it->second) != std::string(names[t])) {
      out << "  edge " << pair.first << "-" << pair.second << ": ours " << feature_type_name(it->second) << ", theirs "
          << names[t] << "\n";
      ++differences;
    }
  }
  for (const auto& [pair, type] : ours)
    if (!theirs.count(pair)) {
      out << "  edge " << pair.first << "-" << pair.second << ": only ours (" << feature_type_name(type) << ")\n";
      ++differences;
    }
  out << "reference patch graph " << path << ": " << theirs.size() << " edges, " << differences << " differences\n";
  return differences;
}

void write_outputs(const NhtreeOptions& o, const nhrep::BuildResult& r, const std::vector<std::vector<int>>* groups,
                   nlohmann::json extra) {
  if (!o.json_path.empty()) {
    nlohmann::json doc = nhtree_to_json(r, groups);
    for (auto& [key, value] : extra.items()) doc[key] = value;
    write_file_atomically(o.json_path, doc.dump(1) + "\n");
  }
  if (!o.conf_path.empty()) write_file_atomically(o.conf_path, nhtree_conf(r));
}

/// Per patch, the tree node it is a leaf of (for colouring pictures).
std::vector<int> leaf_nodes(const nhrep::BuildResult& r) {
  std::vector<int> node_of(r.graph.patches.size(), -1);
  for (std::size_t n = 0; n < r.tree.nodes.size(); ++n)
    for (int leaf : r.tree.nodes[n].leaves) node_of[static_cast<std::size_t>(leaf)] = static_cast<int>(n);
  return node_of;
}

int finish(const NhtreeOptions& o, const nhrep::BuildResult& r, std::vector<std::string> problems, std::ostream& out) {
  std::vector<std::vector<int>> groups;
  if (o.group) {
    groups = nhrep::group_patches(r.graph, o.max_group);
    out << "groups (at most " << o.max_group << " non-adjacent patches each): " << groups.size() << "\n";
    for (std::size_t k = 0; k < groups.size(); ++k) out << "  group " << k << ": " << join(groups[k]) << "\n";
  }
  const std::vector<std::string> structure = nhrep::check_tree(r);
  out << "check structure (leaves, alternation, Q conditions, maximal connected subgraphs, termination): "
      << (structure.empty() ? "ok" : "FAILED") << "\n";
  for (const std::string& p : structure) out << "  " << p << "\n";
  problems.insert(problems.end(), structure.begin(), structure.end());
  return problems.empty() ? 0 : 3;
}

int run_mesh(const NhtreeOptions& o) {
  if (o.fea_path.empty()) throw InputError("nhtree: a mesh needs its feature edges: --fea FILE");
  if (!o.svg_path.empty()) throw InputError("nhtree: --svg draws 2D solids only");
  const std::string sharp_text = !o.sharp_angle.empty() ? o.sharp_angle : o.nhrep_tool ? "20" : "0";
  std::string why;
  const std::optional<Rational> parsed = parse_rational(sharp_text, &why);
  if (!parsed) throw InputError("--sharp-angle: " + why);
  const Rational angle = *parsed;
  const Mesh3 mesh = read_mesh3_file(o.input);
  std::vector<std::string> notes = mesh.notes;
  const FeatureEdgeList fea = read_fea_file(o.fea_path);
  BoundarySurface surface = boundary_from_mesh(mesh, fea, angle, &notes);
  const long feature_count = std::count_if(surface.links.begin(), surface.links.end(),
                                           [](const BoundaryLink& l) { return l.feature; });
  nhrep::PatchGraph original = nhrep::build_patch_graph(
      std::move(surface), o.nhrep_tool ? nhrep::CurveRule::Majority : nhrep::CurveRule::Paper);
  std::ostream& out = std::cout;
  std::optional<int> graph_differences;
  if (!o.reference_graph.empty()) graph_differences = compare_reference_graph(o.reference_graph, original, out);
  nhrep::BuildResult r = run_algorithm1(std::move(original), o);
  out << o.input << ": " << mesh.vertices.size() << " vertices, " << mesh.faces.size() << " triangles, "
      << feature_count << " feature edges; sharpness angle " << sharp_text << " degrees"
      << (o.nhrep_tool ? "; NH-Rep tool mode (majority vote per curve, scoped decomposition, restart)" : "")
      << (o.nest_holes ? "; cavities nested" : "") << "\n";
  for (const std::string& n : notes) out << "note: " << n << "\n";
  print_graph(r, {}, out);
  print_run(r, out);
  const int status = finish(o, r, {}, out);
  nlohmann::json extra = {{"input", o.input}, {"sharp_angle", sharp_text}, {"nhrep_tool", o.nhrep_tool},
                          {"nest_holes", o.nest_holes}};
  if (!o.reference_conf.empty()) extra["reference_equal"] = compare_reference(o, r, out);
  if (graph_differences) extra["reference_graph_differences"] = *graph_differences;
  std::unique_ptr<std::vector<std::vector<int>>> groups;
  if (o.group) groups = std::make_unique<std::vector<std::vector<int>>>(nhrep::group_patches(r.graph, o.max_group));
  write_outputs(o, r, groups.get(), extra);
  if (!o.decomposed_prefix.empty()) {
    const DecomposedMesh d = write_decomposed_mesh(mesh, r.graph, nhtree_conf_ids(r.graph));
    write_file_atomically(o.decomposed_prefix + ".obj", d.obj);
    write_file_atomically(o.decomposed_prefix + ".fea", d.fea);
    write_file_atomically(o.decomposed_prefix + ".face-patch.txt", d.face_patch);
    out << "decomposed mesh " << o.decomposed_prefix << ".obj: " << d.faces << " triangles (" << d.split_faces
        << (d.split_faces == 1 ? " input triangle" : " input triangles") << " split), " << d.feature_edges
        << " feature edges\n";
  }
  return status;
}

int run_planar(const NhtreeOptions& o) {
  if (!o.fea_path.empty()) throw InputError("nhtree: --fea belongs to a mesh (.obj) input");
  if (!o.decomposed_prefix.empty()) throw InputError("nhtree: --decomposed writes meshes; use --json for 2D");
  const LoadedInput in = load_input(o.input);
  if (!in.arranged)
    throw InputError(o.input + ": nhtree needs a scene, not a complex: corner angles need the geometry");
  const Solid solid = load_solid(in, o.solid);
  const Arranged2& arranged = *in.arranged;
  if (std::none_of(solid.cells.begin(), solid.cells.end(), [](char c) { return c; }))
    throw InputError("the solid is empty: it has no boundary patches");
  for (std::size_t c = 0; c < solid.cells.size(); ++c)
    if (solid.cells[c] && arranged.complex.cells[c].outer)
      throw InputError("the solid reaches the domain's boundary (cell " + std::to_string(c) +
                       " touches it): NH-Rep needs a bounded solid inside the domain");
  nhrep::BuildResult r = run_algorithm1(
      nhrep::build_patch_graph(boundary_from_arrangement2(arranged, solid.cells),
                               o.nhrep_tool ? nhrep::CurveRule::Majority : nhrep::CurveRule::Paper),
      o);
  std::ostream& out = std::cout;
  // each patch's natural halfspace by name (~ for complemented)
  std::vector<std::string> names(r.graph.patches.size());
  const auto natural = nhrep::natural_halfspaces(r.graph, arranged.complex.halfspace_count());
  for (int p : r.graph.live_patches()) {
    const nhrep::NaturalHalfspace& h = natural[static_cast<std::size_t>(p)];
    names[static_cast<std::size_t>(p)] =
        (h.complemented ? "~" : "") + arranged.complex.halfspace_names[static_cast<std::size_t>(h.halfspace)];
  }
  print_graph(r, names, out);
  print_run(r, out);
  // Evaluate on the whole plane: the scene in a domain holding every vertex, so that every sign vector of the
  // plane is some cell's (the tree's leaves name halfspaces, which are the same there).
  const Scene2 whole_scene = whole_plane_scene(*in.scene);
  const bool same_domain = whole_scene.domain.min == in.scene->domain.min && whole_scene.domain.max == in.scene->domain.max;
  std::optional<Arranged2> larger;  // only when the scene's own domain hides some vertex
  if (!same_domain) larger = arrange(whole_scene);
  const Arranged2& whole = larger ? *larger : arranged;
  const std::vector<char> whole_solid = larger ? carry_to_whole_plane(arranged, solid.cells, whole) : solid.cells;
  const nhrep::Evaluation e = nhrep::evaluate_tree(r, whole.complex, whole_solid);
  out << "exact evaluation with natural halfspaces on the whole plane (" << whole.complex.cells.size()
      << " cells of a domain holding every vertex): "
      << (e.correct ? "correct on every cell"
                    : std::to_string(e.wrong_inside.size() + e.wrong_outside.size()) + " cells wrong")
      << "; " << nhrep::verdict_name(e.verdict) << "\n";
  if (e.verdict == nhrep::Verdict::DescribableButFails) {
    out << "  solid points the tree misses: " << witnesses(whole.complex, e.wrong_inside)
        << "; points it adds: " << witnesses(whole.complex, e.wrong_outside) << "\n";
    const auto& pieces = r.graph.surface.pieces;
    const bool holes = std::any_of(pieces.begin(), pieces.end(), [](const BoundaryPiece& p) { return p.hole; });
    if (holes && !o.nest_holes)
      out << "  the solid has holes, and the tree initialisation (Section 5.2) unites its boundary components where "
             "holes should be intersected (see --nest-holes)\n";
    else
      out << "  NH-Rep needs extended surfaces here (Appendix B)\n";
  }
  std::vector<std::string> problems = e.violations;
  for (const std::string& v : e.violations) out << "  violated: " << v << "\n";
  const int status = finish(o, r, problems, out);
  std::unique_ptr<std::vector<std::vector<int>>> groups;
  if (o.group) groups = std::make_unique<std::vector<std::vector<int>>>(nhrep::group_patches(r.graph, o.max_group));
  nlohmann::json leaves = nlohmann::json::object();
  for (int p : r.graph.live_patches()) leaves[std::to_string(p)] = names[static_cast<std::size_t>(p)];
  // Where each live patch lies: arrangement edges, and for halves made by patch decomposition, which end they keep
  // and the exact split point.
  nlohmann::json where = nlohmann::json::object();
  for (int p : r.graph.live_patches()) {
    nlohmann::json pieces = nlohmann::json::array();
    for (int piece_id : r.graph.patches[static_cast<std::size_t>(p)].pieces) {
      const BoundaryPiece& piece = r.graph.surface.pieces[static_cast<std::size_t>(piece_id)];
      nlohmann::json entry = {{"edge", piece.origin}};
      if (piece.split_of >= 0) {
        entry["kept_vertex"] = r.graph.surface.links[static_cast<std::size_t>(piece.kept_link)].origin;
        entry["split_point"] = point_to_json(edge_split_point(arranged.arrangement, piece.origin));
      }
      pieces.push_back(entry);
    }
    where[std::to_string(p)] = pieces;
  }
  write_outputs(o, r, groups.get(),
                {{"input", o.input},
                 {"natural_halfspaces", leaves},
                 {"patch_pieces", where},
                 {"evaluation", {{"verdict", nhrep::verdict_key(e.verdict)}, {"correct", e.correct},
                                 {"describable", e.describable}, {"cells", whole.complex.cells.size()},
                                 {"wrong_inside", witness_json(whole.complex, e.wrong_inside)},
                                 {"wrong_outside", witness_json(whole.complex, e.wrong_outside)},
                                 {"violations", e.violations}}}});
  if (!o.svg_path.empty())
    write_file_atomically(o.svg_path, nhrep_svg(*in.scene, arranged, solid.cells, r.graph.surface, r.graph.piece_patch,
                                                leaf_nodes(r), "NH-Rep tree: " + nhtree_text(r.tree)));
  return status;
}

int run_nhtree(const NhtreeOptions& o) {
  if (o.max_group < 1) throw InputError("--max-group must be at least 1");
  return ends_with(o.input, ".obj") ? run_mesh(o) : run_planar(o);
}

}  // namespace

void add_nhtree_command(CLI::App& app) {
  auto o = std::make_shared<NhtreeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "nhtree", "NH-Rep's Boolean tree (Algorithm 1 with patch decomposition) of a 2D solid or a 3D mesh, its patch "
                "graph with exact feature types, and its cross-checks");
  cmd->add_option("INPUT", o->input, "a mesh (.obj, with --fea) or an hsx-scene/1 file (with --shape or --csg)")->required();
  cmd->add_option("--fea", o->fea_path, "mesh: feature edges (first line the count, then 0-based vertex pairs)");
  cmd->add_option("--sharp-angle", o->sharp_angle,
                  "mesh: feature edges bending less than this many degrees count as smooth (exact; default 0: only "
                  "flat edges)");
  cmd->add_flag("--nhrep-tool", o->nhrep_tool,
               "behave like NH-Rep's own tool: sharpness angle 20 unless given, majority vote per feature curve, "
               "decomposition against the current cluster only, and a fresh tree after each decomposition");
  cmd->add_flag("--nest-holes", o->nest_holes,
               "extension: build each hole's or cavity's tree under its solid part's tree (intersected) instead of "
               "uniting every boundary component as Section 5.2 does");
  cmd->add_option("--shape", o->solid.shape_path, "2D: the solid as an hsx-result/1 file computed from INPUT");
  cmd->add_option("--csg", o->solid.csg, "2D: the solid as a CSG expression over INPUT's halfspaces");
  cmd->add_option("--json", o->json_path, "write the tree, patch graph, decompositions and steps (hsx-nhtree/1)");
  cmd->add_option("--conf", o->conf_path, "write the tree in NH-Rep's .conf form");
  cmd->add_option("--svg", o->svg_path, "2D: draw the patches coloured by tree node");
  cmd->add_option("--decomposed", o->decomposed_prefix,
                  "mesh: write the decomposed mesh as PREFIX.obj, PREFIX.fea and PREFIX.face-patch.txt (NH-Rep's "
                  "form; patch ids as in --conf)");
  cmd->add_flag("--group", o->group, "group non-adjacent patches by graph colouring (NH-Rep Section 6)");
  cmd->add_option("--max-group", o->max_group, "at most this many patches per group (default 6)");
  cmd->add_option("--reference", o->reference_conf, "compare with a tree written by NH-Rep's tool (.conf)");
  cmd->add_option("--reference-graph", o->reference_graph,
                  "compare the original patch graph with NH-Rep's 'edge: a-b : t' listing");
  cmd->add_option("--reference-face-patch", o->reference_face_patch,
                  "the reference's patch id per triangle, to compare through decompositions");
  run_with_status(cmd, o, &run_nhtree);
}

}  // namespace hsx::cli
