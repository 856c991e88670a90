// `hsx nhtree`: NH-Rep's Boolean tree (Guo et al. 2022, Section 5) of a 2D solid or a 3D mesh, with the patch
// graph, the cross-checks, and optional comparison with a tree written by NH-Rep's own tool.
#include "cli/commands.hpp"
#include <hsx/io/solid.hpp>

#include <hsx/algorithms/nhrep/compare.hpp>
#include <hsx/algorithms/nhrep/evaluate.hpp>
#include <hsx/algorithms/nhrep/planar.hpp>
#include <hsx/algorithms/nhrep/solid3.hpp>
#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/complex/boundary_from_mesh.hpp>
#include <hsx/geometry/mesh3.hpp>
#include <hsx/io/input.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/nhrep_json.hpp>
#include <hsx/io/nhrep_mesh.hpp>
#include <hsx/io/nhrep_dot.hpp>
#include <hsx/io/nhrep_svg.hpp>

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

namespace hsx::cli {
namespace {

struct NhtreeOptions {
  ArrangementLimits limits;  ///< --max-cells, --max-side-table
  std::string input, fea_path, sharp_angle;  ///< empty: 0, or 20 with --nhrep-tool
  bool nhrep_tool = false;
  bool nest_holes = false;
  SolidSource solid;
  std::string json_path, conf_path, svg_path, tree_dot_path, graph_dot_path, reference_conf, reference_face_patch, reference_graph;
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

/// Up to `max` exact points as "(x, y)" or "(x, y, z)" with 6 significant digits (a pointer, not a proof: the
/// cells are exact).
std::string points_text(const std::vector<std::vector<Rational>>& points, std::size_t max = 6) {
  std::string s;
  for (std::size_t i = 0; i < points.size() && i < max; ++i) {
    s += i ? ", (" : "(";
    for (std::size_t k = 0; k < points[i].size(); ++k) s += (k ? ", " : "") + decimal_string(points[i][k], 6);
    s += ")";
  }
  if (points.size() > max) s += ", ... (" + std::to_string(points.size()) + " cells)";
  return s.empty() ? "none" : s;
}

nhrep::BuildOptions build_options(const NhtreeOptions& o) {
  nhrep::BuildOptions options;
  options.restart_after_decomposition = o.nhrep_tool;
  options.decompose_within_subgraph = o.nhrep_tool;
  options.nest_holes = o.nest_holes;
  return options;
}

nhrep::CurveRule curve_rule(const NhtreeOptions& o) {
  return o.nhrep_tool ? nhrep::CurveRule::Majority : nhrep::CurveRule::Paper;
}

/// Runs Algorithm 1 (`build`). The paper's version needs fewer decompositions than patches (proofs/nhrep.md,
/// Lemma 4.3); NH-Rep's tool's scoped decomposition has no such bound, so its guard is reported as a result, not an
/// internal error.
template <class Build>
auto run_algorithm1(const NhtreeOptions& o, Build build) {
  try {
    return build();
  } catch (const std::invalid_argument& e) {
    if (!o.nest_holes) throw;
    throw InputError(std::string("--nest-holes: ") + e.what());
  } catch (const std::runtime_error& e) {
    if (!o.nhrep_tool || dynamic_cast<const InputError*>(&e)) throw;
    std::cout << "NH-Rep tool mode did not finish: " << e.what() << "\n";
    throw CLI::RuntimeError(3);
  }
}

/// The tree in NH-Rep's numbering (the one --conf, --decomposed and --reference use), and, where that differs
/// from Algorithm 1's patch ids (used above it and in --json), the mapping.
void print_tree(const nhrep::BuildResult& r, std::ostream& out) {
  const std::vector<int> number = nhtree_conf_ids(r.graph);
  std::string mapping;
  bool some_unchanged = false;
  for (int p : r.graph.live_patches()) {
    if (number[static_cast<std::size_t>(p)] != p)
      mapping += " " + std::to_string(p) + "->" + std::to_string(number[static_cast<std::size_t>(p)]);
    else
      some_unchanged = true;
  }
  if (!mapping.empty())
    out << "patch numbers: the tree below and --conf use NH-Rep's (live patches by lowest "
        << (r.graph.surface.dimension == 3 ? "triangle" : "edge") << "); the patch ids above and in --json map"
        << mapping << (some_unchanged ? " (the others are unchanged)" : "") << "\n";
  out << "tree: " << nhtree_text(nhrep::relabel_tree(r.tree, number)) << "\n";
}

void print_run(const nhrep::BuildResult& r, std::ostream& out) {
  for (const nhrep::Decomposition& d : r.decompositions)
    out << "decomposed patch " << d.patch << (d.whole_patch ? "" : " (against its cluster only)") << " into "
        << join(d.subpatches) << " (" << d.pieces_split << (d.pieces_split == 1 ? " piece" : " pieces")
        << " face-split, " << d.cut_links << (d.cut_links == 1 ? " link" : " links")
        << " cut); patches with both convex and concave edges: "
        << d.both_kinds_before << " -> " << d.both_kinds_after << "\n";
  if (r.rounds > 1) out << "tree constructions: " << r.rounds << " (restarted after each decomposition)\n";
  print_tree(r, out);
}

bool print_reference_comparison(const nhrep::BuildResult& r, const NhrepReference& ref, std::ostream& out) {
  const nhrep::ReferenceComparison c = nhrep::compare_with_reference(r, *ref.tree);
  if (c.mismatch) {
    out << c.mismatch.value() << "\n";
    return false;
  }
  out << "reference " << ref.files.tree << ": " << (c.equal ? "same tree" : "DIFFERENT tree") << " up to "
      << c.basis << "\n";
  if (!c.equal) {
    out << "  ours:   " << c.trees.ours << "\n  theirs: " << c.trees.theirs << "\n";
    for (const std::string& d : c.trees.differences) out << "  " << d << "\n";
  }
  return c.equal;
}

std::string type_name(const std::optional<FeatureType>& type) {
  return type ? feature_type_name(*type) : "none";
}

int print_graph_comparison(const nhrep::PatchGraph& original, const NhrepReference& ref, std::ostream& out) {
  const nhrep::GraphComparison c = nhrep::compare_patch_graphs(original, *ref.graph);
  for (const nhrep::EdgeDifference& d : c.differences) {
    out << "  edge " << d.a << "-" << d.b << ": ";
    if (!d.ours) out << "only theirs (" << type_name(d.theirs) << ")\n";
    else if (!d.theirs) out << "only ours (" << type_name(d.ours) << ")\n";
    else out << "ours " << type_name(d.ours) << ", theirs " << type_name(d.theirs) << "\n";
  }
  out << "reference patch graph " << ref.files.graph << ": " << c.reference_edges << " edges, "
      << c.differences.size() << " differences\n";
  return static_cast<int>(c.differences.size());
}

/// Every output path of the run, checked before any work (written all or none by OutputFiles::commit).
void expect_outputs(const NhtreeOptions& o, OutputFiles& out) {
  out.expect(o.json_path, "--json");
  out.expect(o.conf_path, "--conf");
  out.expect(o.svg_path, "--svg");
  out.expect(o.tree_dot_path, "--tree-dot");
  out.expect(o.graph_dot_path, "--graph-dot");
  if (!o.decomposed_prefix.empty())
    for (const char* suffix : {".obj", ".fea", ".face-patch.txt"}) out.expect(o.decomposed_prefix + suffix, "--decomposed");
}

void put_outputs(const NhtreeOptions& o, const nhrep::BuildResult& r, const std::vector<std::vector<int>>* groups,
                 nlohmann::json extra, OutputFiles& files) {
  if (!o.json_path.empty()) {
    nlohmann::json doc = nhtree_to_json(r, groups);
    for (auto& [key, value] : extra.items()) doc[key] = value;
    files.put(o.json_path, doc.dump(1) + "\n");
  }
  if (!o.conf_path.empty()) files.put(o.conf_path, nhtree_conf(r));
}

/// --tree-dot and --graph-dot (`names`: per patch id its natural halfspace, or empty).
void put_diagrams(const NhtreeOptions& o, const nhrep::BuildResult& r, const std::vector<std::string>& names,
                  const std::string& title, OutputFiles& files) {
  if (!o.tree_dot_path.empty()) files.put(o.tree_dot_path, nhtree_dot(r, names, title));
  if (!o.graph_dot_path.empty()) files.put(o.graph_dot_path, nhrep_patch_graph_dot(r, names, title));
}

/// Groups (when asked for) and cross-check 1; returns the exit status (3 when a check failed).
int finish(const NhtreeOptions& o, const nhrep::BuildResult& r, const std::vector<std::vector<int>>& groups,
           std::vector<std::string> problems, std::ostream& out) {
  if (o.group) {
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

std::vector<std::vector<int>> groups_of(const NhtreeOptions& o, const nhrep::BuildResult& r) {
  return o.group ? nhrep::group_patches(r.graph, o.max_group) : std::vector<std::vector<int>>{};
}

NhrepReference read_references(const NhtreeOptions& o) {
  return read_nhrep_reference({o.reference_conf, o.reference_face_patch, o.reference_graph});
}

int run_mesh(const NhtreeOptions& o, OutputFiles& files) {
  if (o.fea_path.empty()) throw InputError("nhtree: a mesh needs its feature edges: --fea FILE");
  if (!o.svg_path.empty()) throw InputError("nhtree: --svg draws solids on scenes only (a mesh: use --graph-dot)");
  if (!o.solid.csg.empty() || !o.solid.shape_path.empty() || !o.solid.mesh_path.empty())
    throw InputError(std::string("nhtree: ") +
                     (!o.solid.csg.empty() ? "--csg" : !o.solid.shape_path.empty() ? "--shape" : "--mesh") +
                     " gives a solid on a scene; a mesh (.obj) is its own solid");
  const std::string sharp_text = !o.sharp_angle.empty() ? o.sharp_angle : o.nhrep_tool ? "20" : "0";
  std::string why;
  const std::optional<Rational> parsed = parse_rational(sharp_text, &why);
  if (!parsed) throw InputError("--sharp-angle: " + why);
  const Rational angle = *parsed;
  const NhrepReference reference = read_references(o);  // bad references fail before any work
  const Mesh3 mesh = read_mesh3_file(o.input);
  check_reference_mesh(reference, mesh.faces.size());
  std::vector<std::string> notes = mesh.notes;
  const FeatureEdgeList fea = read_fea_file(o.fea_path);
  BoundarySurface surface = boundary_from_mesh(mesh, fea, angle, &notes);
  const long feature_count = std::count_if(surface.links.begin(), surface.links.end(),
                                           [](const BoundaryLink& l) { return l.feature; });
  nhrep::PatchGraph original = nhrep::build_patch_graph(std::move(surface), curve_rule(o));
  std::ostream& out = std::cout;
  std::optional<int> graph_differences;
  if (reference.graph) graph_differences = print_graph_comparison(original, reference, out);
  nhrep::BuildResult r =
      run_algorithm1(o, [&] { return nhrep::build_tree(std::move(original), build_options(o)); });
  out << o.input << ": " << mesh.vertices.size() << " vertices, " << mesh.faces.size() << " triangles, "
      << feature_count << " feature edges; sharpness angle " << sharp_text << " degrees"
      << (o.nhrep_tool ? "; NH-Rep tool mode (majority vote per curve, scoped decomposition, restart)" : "")
      << (o.nest_holes ? "; cavities nested" : "") << "\n";
  for (const std::string& n : notes) out << "note: " << n << "\n";
  print_graph(r, {}, out);
  print_run(r, out);
  const std::vector<std::vector<int>> groups = groups_of(o, r);
  const int status = finish(o, r, groups, {}, out);
  nlohmann::json extra = {{"input", o.input}, {"sharp_angle", sharp_text}, {"nhrep_tool", o.nhrep_tool},
                          {"nest_holes", o.nest_holes}};
  if (reference.tree) extra["reference_equal"] = print_reference_comparison(r, reference, out);
  if (graph_differences) extra["reference_graph_differences"] = *graph_differences;
  put_outputs(o, r, o.group ? &groups : nullptr, extra, files);
  put_diagrams(o, r, {}, o.input, files);
  if (!o.decomposed_prefix.empty()) {
    const DecomposedMesh d = write_decomposed_mesh(mesh, r.graph, nhtree_conf_ids(r.graph));
    files.put(o.decomposed_prefix + ".obj", d.obj);
    files.put(o.decomposed_prefix + ".fea", d.fea);
    files.put(o.decomposed_prefix + ".face-patch.txt", d.face_patch);
    out << "decomposed mesh " << o.decomposed_prefix << ".obj: " << d.faces << " triangles (" << d.split_faces
        << (d.split_faces == 1 ? " input triangle" : " input triangles") << " split), " << d.feature_edges
        << " feature edges\n";
  }
  return status;
}

void print_evaluation(const nhrep::CellEvaluation& pe, int dimension, std::ostream& out) {
  const nhrep::Evaluation& e = pe.evaluation;
  out << "exact evaluation with natural halfspaces on the whole " << (dimension == 3 ? "space" : "plane") << " ("
      << pe.cells << " cells of a domain holding every vertex): "
      << (e.correct ? "correct on every cell"
                    : std::to_string(e.wrong_inside.size() + e.wrong_outside.size()) + " cells wrong")
      << "; " << nhrep::verdict_name(e.verdict) << "\n";
  if (e.verdict == nhrep::Verdict::DescribableButFails)
    out << "  solid points the tree misses: " << points_text(pe.missed) << "; points it adds: "
        << points_text(pe.added) << "\n";
  if (pe.diagnosis == nhrep::Diagnosis::HolesUnited)
    out << "  the solid has " << (dimension == 3 ? "cavities" : "holes") << ", and the tree initialisation (Section 5.2) unites its boundary components where "
           "holes should be intersected (see --nest-holes)\n";
  else if (pe.diagnosis == nhrep::Diagnosis::NeedsExtendedSurfaces)
    out << "  NH-Rep needs extended surfaces here (Appendix B)\n";
  for (const std::string& v : e.violations) out << "  violated: " << v << "\n";
}

/// A 3D scene with a solid on it (--csg or --shape): the boundary from the arrangement, Algorithm 1, and the exact
/// evaluation on the whole space.
int run_solid3(const NhtreeOptions& o, const LoadedInput& in, OutputFiles& files) {
  const Solid solid = load_solid(in, o.solid, o.limits);
  const Arranged3& arranged = *in.arranged3;
  const nhrep::SolidTree3 t = run_algorithm1(
      o, [&] { return nhrep::build_solid_tree3(arranged, solid.cells, build_options(o), curve_rule(o)); });
  const nhrep::BuildResult& r = t.built;
  std::ostream& out = std::cout;
  print_graph(r, t.leaf_names, out);
  print_run(r, out);
  const nhrep::CellEvaluation e = nhrep::evaluate_on_whole_space(t, *in.scene3, arranged, solid.cells, o.limits);
  print_evaluation(e, 3, out);
  const std::vector<std::vector<int>> groups = groups_of(o, r);
  const int status = finish(o, r, groups, e.evaluation.violations, out);
  nlohmann::json extra = nhtree_solid3_json(t, e);
  extra["input"] = o.input;
  put_outputs(o, r, o.group ? &groups : nullptr, extra, files);
  put_diagrams(o, r, t.leaf_names, o.input, files);
  if (!o.svg_path.empty())
    files.put(o.svg_path, nhrep_svg3(*in.scene3, arranged, solid.cells, r.graph.surface, r.graph.piece_patch,
                                     t.leaf_node, "NH-Rep tree: " + nhtree_text(r.tree)));
  return status;
}

int run_planar(const NhtreeOptions& o, OutputFiles& files) {
  if (!o.fea_path.empty()) throw InputError("nhtree: --fea belongs to a mesh (.obj) input");
  if (!o.decomposed_prefix.empty()) throw InputError("nhtree: --decomposed writes meshes; use --json for 2D");
  if (!o.reference_conf.empty() || !o.reference_face_patch.empty() || !o.reference_graph.empty())
    throw InputError("nhtree: --reference, --reference-face-patch and --reference-graph compare meshes (.obj)");
  const LoadedInput in = load_input(o.input, o.limits);
  protect_inputs(files, in);
  if (in.arranged3) return run_solid3(o, in, files);
  if (!in.arranged)
    throw InputError(o.input + ": nhtree needs a scene, not a complex: corner angles need the geometry");
  const Solid solid = load_solid(in, o.solid, o.limits);
  const Arranged2& arranged = *in.arranged;
  const nhrep::PlanarTree t = run_algorithm1(
      o, [&] { return nhrep::build_planar_tree(arranged, solid.cells, build_options(o), curve_rule(o)); });
  const nhrep::BuildResult& r = t.built;
  std::ostream& out = std::cout;
  print_graph(r, t.leaf_names, out);
  print_run(r, out);
  const nhrep::PlanarEvaluation e = nhrep::evaluate_on_whole_plane(t, *in.scene, arranged, solid.cells);
  print_evaluation(e, 2, out);
  const std::vector<std::vector<int>> groups = groups_of(o, r);
  const int status = finish(o, r, groups, e.evaluation.violations, out);
  nlohmann::json extra = nhtree_planar_json(t, e);
  extra["input"] = o.input;
  put_outputs(o, r, o.group ? &groups : nullptr, extra, files);
  put_diagrams(o, r, t.leaf_names, o.input, files);
  if (!o.svg_path.empty())
    files.put(o.svg_path, nhrep_svg(*in.scene, arranged, solid.cells, r.graph.surface, r.graph.piece_patch,
                                                t.leaf_node, "NH-Rep tree: " + nhtree_text(r.tree)));
  return status;
}

int run_nhtree(const NhtreeOptions& o) {
  if (o.max_group < 1) throw InputError("--max-group must be at least 1");
  OutputFiles files;
  expect_outputs(o, files);
  // --decomposed's files are derived from its PREFIX: compare them with the inputs here (the options are compared
  // when the command line is parsed)
  for (const auto& [path, name] :
       {std::pair{o.input, "INPUT"}, {o.fea_path, "--fea"}, {o.reference_conf, "--reference"},
        {o.reference_face_patch, "--reference-face-patch"}, {o.reference_graph, "--reference-graph"}})
    files.protect(path, name);
  const int status = ends_with(o.input, ".obj") ? run_mesh(o, files) : run_planar(o, files);
  files.print("");  // the report went to standard output as it was made: the commit checks that it arrived
  files.commit();
  return status;
}

}  // namespace

void add_nhtree_command(CLI::App& app) {
  auto o = std::make_shared<NhtreeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "nhtree", "NH-Rep's Boolean tree (Algorithm 1 with patch decomposition) of a 2D or 3D solid on a scene or a 3D "
                "mesh, its patch graph with exact feature types, and its cross-checks");
  cmd->add_option("INPUT", o->input, "a mesh (.obj, with --fea) or an hsx-scene/1 file of dimension 2 or 3 (with --shape, --csg or --mesh)")->required();
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
  cmd->add_option("--shape", o->solid.shape_path, "scene: the solid as an hsx-result/1 file computed from INPUT");
  cmd->add_option("--csg", o->solid.csg, "scene: the solid as a CSG expression over INPUT's halfspaces");
  cmd->add_option("--mesh", o->solid.mesh_path, "3D scene: the solid as the cells inside a closed mesh (.obj, .off, "
                                                ".ply) whose faces lie on INPUT's halfspaces");
  cmd->add_option("--json", o->json_path, "write the tree, patch graph, decompositions and steps (hsx-nhtree/1)")
      ->check(output_path());
  cmd->add_option("--conf", o->conf_path,
                  "write the tree in NH-Rep's .conf form (its patch numbers are the printed tree's)")
      ->check(output_path());
  cmd->add_option("--svg", o->svg_path, "scene: draw the patches coloured by tree node (3D: four views)")
      ->check(output_path());
  cmd->add_option("--tree-dot", o->tree_dot_path, "write the tree as a Graphviz diagram (leaves: patches)")
      ->check(output_path());
  cmd->add_option("--graph-dot", o->graph_dot_path,
                  "write the patch graph as a Graphviz diagram (edges: feature curves by type, patches coloured "
                  "by tree node)")->check(output_path());
  cmd->add_option("--decomposed", o->decomposed_prefix,
                  "mesh: write the decomposed mesh as PREFIX.obj, PREFIX.fea and PREFIX.face-patch.txt (NH-Rep's "
                  "form; patch ids as in --conf)")->check(output_path());
  cmd->add_flag("--group", o->group, "group non-adjacent patches by graph colouring (NH-Rep Section 6)");
  cmd->add_option("--max-group", o->max_group, "at most this many patches per group (default 6)");
  cmd->add_option("--reference", o->reference_conf, "compare with a tree written by NH-Rep's tool (.conf)");
  cmd->add_option("--reference-graph", o->reference_graph,
                  "compare the original patch graph with NH-Rep's 'edge: a-b : t' listing");
  cmd->add_option("--reference-face-patch", o->reference_face_patch,
                  "the reference's patch id per triangle, to compare through decompositions");
  add_arrangement_limits(cmd, o->limits);
  run_with_status(cmd, o, &run_nhtree);
}

}  // namespace hsx::cli
