// hsx extract INPUT --method graphcut|beam|best-first|brute-force|exact: the BSH shape (paper, Sections 3 and 5).
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/bsh/graph_cut.hpp>
#include "cli/commands.hpp"
#include <hsx/io/input.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/mesh_export.hpp>
#include <hsx/io/png.hpp>
#include <hsx/io/result_json.hpp>
#include <hsx/io/svg.hpp>
#include <hsx/io/svg3.hpp>

#include <filesystem>

#include <iostream>
#include <memory>
#include <sstream>

namespace hsx::cli {

/// Closed forms with more terms or characters than these are left to the JSON; the summary gives their size.
constexpr std::size_t kSummaryTerms = 6, kSummaryCharacters = 160;

/// "DECIMAL = CLOSED FORM", or "DECIMAL (closed form: N terms, C characters, in --json)" when it is long.
std::string measure_text(const Measure& m) {
  std::string s = m.decimal_string(30);
  if (auto exact = m.exact_string()) {
    const std::size_t terms = closed_form_terms(*exact);
    if (terms <= kSummaryTerms && exact->size() <= kSummaryCharacters)
      s += " = " + *exact;
    else
      s += " (closed form: " + std::to_string(terms) + (terms == 1 ? " term, " : " terms, ") +
           std::to_string(exact->size()) + " characters, in --json)";
  }
  return s;
}

std::string energy_text(const bsh::Energy& e, int dimension) {
  return std::to_string(e.missing_samples) + " missing sample" + (e.missing_samples == 1 ? "" : "s") +
         (dimension == 3 ? ", boundary area " : ", boundary length ") + measure_text(e.measure());
}

namespace {

struct ExtractCommandOptions {
  ArrangementLimits arrangement;  ///< --max-cells, --max-side-table
  std::string input;
  std::string method = "beam";
  int beam_width = 1;
  long max_states = 0;
  long max_graph_cuts = 0;
  long max_labellings = bsh::ExtractOptions().brute_force_limit;
  long max_nodes = 0;
  double time_limit = 0;
  int precision_bits = 2048;
  int max_ties = 16;
  std::string svg_path, json_path, states_svg_path;
  std::string png_path, states_png_path;  ///< 3D: raster pictures
  std::string obj_path, ply_path, off_path;  ///< 3D: the shape's boundary mesh
  bool exact_coordinates = false;
  bool show_removed = false;
  bool labels = false;
  bool no_timing = false;
  bool quiet = false;
};

/// A lower bound or gap: "(missing samples, measure)".
std::string bound_text(const bsh::EnergyBound& b) {
  std::ostringstream out;
  out << "(" << b.missing_samples << ", " << b.measure << ")";
  return out.str();
}

std::string summary(const LoadedInput& in, const bsh::Problem& problem, const bsh::ExtractResult& r,
                    const ExtractCommandOptions& o) {
  std::ostringstream out;
  out << "method " << bsh::to_string(r.method);
  if (r.method == bsh::Method::Beam) out << " (K = " << std::max(1, o.beam_width) << ")";
  out << "  optimal " << (r.optimal ? "yes (proven)" : "not proven");
  if (!r.stopped_by.empty()) out << "  stopped by " << r.stopped_by;
  if (!r.optimality_note.empty()) out << " (" << r.optimality_note << ")";
  out << "\nenergy " << energy_text(r.energy, in.complex().dimension) << "\n";
  const Measure area = bsh::inside_measure(in.complex(), r.labelling);
  out << (in.complex().dimension == 3 ? "volume " : "area ") << measure_text(area);
  out << "\nsample-connected " << (r.sample_connected ? "yes" : "no") << "  ties ";
  if (!r.ties.checked)
    out << "not checked by this method";
  else
    out << r.ties.count << (r.ties.capped ? "+" : "")
        << (r.ties.count > 1 ? (r.ties.certified ? " (proven equal energies)" : " (not separated at the precision cap)")
                             : r.ties.capped ? ""
                             : (r.ties.certified ? " (unique)" : " (unique up to unseparated comparisons)"));
  if (r.ties.capped) out << ", enumeration stopped by " << r.ties.stopped_by << ": there may be more";
  const auto boundary = bsh::boundary_supports(problem, r.labelling);
  out << "\nboundary " << boundary.size() << " patch" << (boundary.size() == 1 ? "" : "es") << ":";
  for (int g : boundary) {
    const int patch = oriented_patch(in.complex(), g, r.labelling);
    out << " " << in.complex().halfspace_names[in.complex().patches[patch].halfspace] << "#" << patch;
  }
  out << "\nstats " << r.stats.graph_cuts << " graph cuts (" << r.stats.uncertified_cuts << " uncertified, "
      << r.stats.reused_cuts << " more reused), "
      << r.stats.states_expanded << " states expanded, " << r.stats.states_created << " created";
  if (r.stats.labellings_enumerated) out << ", " << r.stats.labellings_enumerated << " labellings enumerated";
  out << ", " << r.stats.seconds << " s\n";
  if (r.method == bsh::Method::Exact)
    out << "branch and bound " << r.stats.nodes << " nodes expanded, " << r.stats.pruned_by_bound
        << " pruned by bound, " << r.stats.pruned_by_islands << " by islands, " << r.stats.certified_bounds
        << " certified bounds; lower bound " << bound_text(r.stats.lower_bound) << ", gap "
        << bound_text(r.stats.gap) << " (largest " << bound_text(r.stats.max_gap) << ")\n";
  return out.str();
}

/// Per patch, 1 for the patches of the supports in `supports` (support ids).
std::vector<char> patch_flags(const Complex& c, const std::vector<int>& supports) {
  std::vector<char> flags(c.patches.size(), 0);
  for (int g : supports)
    for (int p : c.supports[static_cast<std::size_t>(g)]) flags[static_cast<std::size_t>(p)] = 1;
  return flags;
}

/// The options of a 3D picture of the shape `labelling` (its boundary in four views, or in the isometric view
/// alone when `small`), `highlight` (per patch, may be empty) marked as removed.
Svg3Options shape_options3(const bsh::Labelling& labelling, const std::vector<char>& highlight,
                           const std::string& title, bool labels, bool small) {
  Svg3Options svg;
  svg.title = title;
  svg.cell_fill = labelling;
  svg.show_cell_ids = svg.show_patch_ids = labels;
  svg.highlight_patches = highlight;
  svg.highlight_legend = "removed patches";
  if (small) {
    svg.width = 560;
    svg.views = {default_svg_views3().back()};
  }
  return svg;
}

/// A picture of the shape `labelling` (2D: the arrangement with the shape filled; 3D: shape_options3's),
/// `highlight` (per patch, may be empty) marked as removed.
std::string shape_picture(const LoadedInput& in, const bsh::Labelling& labelling, const std::vector<char>& highlight,
                          const std::string& title, bool labels, bool small) {
  if (in.scene3)
    return arrangement_svg3(*in.scene3, *in.arranged3, shape_options3(labelling, highlight, title, labels, small));
  SvgOptions svg;
  svg.title = title;
  svg.cell_fill = labelling;
  svg.show_cell_ids = svg.show_patch_ids = labels;
  svg.highlight_legend = "removed patches";
  svg.highlight_patches = highlight;
  if (small) svg.width = 480;
  return arrangement_svg(*in.scene, in.arranged->arrangement, in.complex(), svg);
}

/// The boundary of state k on the search's path: the beam of width 1 expands exactly the states of its path, in
/// order (each expansion keeps one child, the next state), so with ExtractOptions::record_states they are
/// r.expanded; otherwise the graph cut without the state's removed supports, computed again.
bsh::Labelling state_labelling(const bsh::Problem& problem, const bsh::ExtractResult& r, int beam_width,
                               std::size_t k) {
  if (r.method == bsh::Method::Beam && beam_width == 1 && r.expanded.size() == r.steps.size()) return r.expanded[k];
  bsh::CutConstraints constraints;
  constraints.removed.assign(problem.support_count(), 0);
  for (int g : r.steps[k]) constraints.removed[static_cast<std::size_t>(g)] = 1;
  return bsh::graph_cut(problem, constraints).labelling;
}

/// The search's states along the path to the result (ExtractResult::steps): shape, removed patches, title.
std::vector<Svg3State> path_states(const LoadedInput& in, const bsh::Problem& problem, const bsh::ExtractResult& r,
                                   int beam_width) {
  const Complex& c = in.complex();
  std::vector<Svg3State> states;
  for (std::size_t k = 0; k < r.steps.size(); ++k) {
    const bsh::Labelling labelling = state_labelling(problem, r, beam_width, k);
    const bsh::Energy energy = bsh::energy(problem, labelling);
    std::string title = "state " + std::to_string(k) + (r.steps[k].empty() ? ":" : ": removed");
    const std::vector<char> removed = patch_flags(c, r.steps[k]);
    for (std::size_t p = 0; p < removed.size(); ++p)
      if (removed[p]) title += " p" + std::to_string(p);
    if (r.steps[k].empty()) title += " graph cut";
    title += " | " + std::to_string(energy.missing_samples) + " missing, " + (c.dimension == 3 ? "area " : "length ") +
             energy.measure().decimal_string(7);
    states.push_back({labelling, removed, title});
  }
  if (states.empty())  // stopped before a sample-connected state, or replaced by the oracle's optimum
    states.push_back({r.labelling, {}, "the result (" +
                                           std::string(r.stopped_by.empty() ? r.optimality_note
                                                                            : "stopped by " + r.stopped_by) +
                                           "): no path of states"});
  return states;
}

/// path_states as one picture, a panel per state, in a grid.
std::string states_picture(const LoadedInput& in, const std::vector<Svg3State>& states, bool labels) {
  if (in.scene3)  // 3D: each patch drawn once, shared by the panels (io/svg3.hpp)
    return states_svg3(*in.scene3, *in.arranged3, states, shape_options3({}, {}, "", labels, true), 3);
  std::vector<std::string> pictures;
  for (const Svg3State& state : states)
    pictures.push_back(shape_picture(in, state.cell_fill, state.highlight_patches, state.title, labels, true));
  return svg_grid(pictures, 3);
}

/// The shape's boundary mesh outputs (3D), by path; empty texts for outputs not asked for.
struct MeshTexts {
  std::string obj, mtl, ply, off;
};

MeshTexts mesh_texts(const LoadedInput& in, const bsh::Labelling& labelling, const ExtractCommandOptions& o,
                     const std::string& mtl_path) {
  MeshTexts t;
  MeshExportOptions options;
  options.exact = o.exact_coordinates;
  if (!o.obj_path.empty()) {
    ObjText obj = shape_obj(*in.scene3, *in.arranged3, labelling,
                            std::filesystem::path(mtl_path).filename().string(), options);
    t.obj = std::move(obj.obj);
    t.mtl = std::move(obj.mtl);
  }
  if (!o.ply_path.empty()) t.ply = shape_ply(*in.scene3, *in.arranged3, labelling);
  if (!o.off_path.empty()) t.off = shape_off(*in.scene3, *in.arranged3, labelling, options);
  return t;
}

/// The method the options name, after checking every option's value (InputError naming the option).
bsh::Method checked_method(const ExtractCommandOptions& o) {
  const auto method = bsh::method_from_string(o.method);
  if (!method) throw InputError("--method: unknown method \"" + o.method + "\" (graphcut, beam, best-first, brute-force, exact)");
  if (o.beam_width < 1) throw InputError("--beam-width: must be at least 1");
  if (o.max_states < 0) throw InputError("--max-states: must be >= 0");
  if (o.max_graph_cuts < 0) throw InputError("--max-graph-cuts: must be >= 0");
  if (o.max_labellings < 1) throw InputError("--max-labellings: must be at least 1");
  if (o.max_nodes < 0) throw InputError("--max-nodes: must be >= 0");
  if (o.time_limit < 0) throw InputError("--time-limit: must be >= 0");
  if (o.precision_bits < 64) throw InputError("--precision: at least 64 bits");
  for (const auto& [path, option] : {std::pair{o.states_svg_path, "--states-svg"}, {o.states_png_path, "--states-png"}})
    if (!path.empty() && *method != bsh::Method::Beam && *method != bsh::Method::BestFirst)
      throw InputError(std::string(option) + ": only the beam and best-first searches go through states (--method "
                       "beam or best-first)");
  if (o.obj_path == "-") throw InputError("--obj: needs a file (its .mtl is written beside it), not '-'");
  return *method;
}

void run_extract(const ExtractCommandOptions& o) {
  const bsh::Method method = checked_method(o);
  const std::string mtl_path = o.obj_path.empty() ? "" : mtl_path_for(o.obj_path);
  OutputFiles out;  // checked before computing, written all or none at the end
  out.expect(o.json_path, "--json");
  out.expect(o.svg_path, "--svg");
  out.expect(o.states_svg_path, "--states-svg");
  out.expect(o.png_path, "--png");
  out.expect(o.states_png_path, "--states-png");
  out.expect(o.obj_path, "--obj");
  out.expect(mtl_path, "--obj (its .mtl)");
  out.expect(o.ply_path, "--ply");
  out.expect(o.off_path, "--off");
  const LoadedInput in = load_input(o.input, o.arrangement);
  protect_inputs(out, in);
  if (!in.scene && !in.scene3)
    for (const auto& [path, option] : {std::pair{o.svg_path, "--svg"}, {o.states_svg_path, "--states-svg"}})
      if (!path.empty())
        throw InputError(std::string(option) +
                         ": pictures need a scene (an hsx-complex/1 document carries no drawing)");
  if (!in.scene3)
    for (const auto& [path, option] : {std::pair{o.obj_path, "--obj"}, {o.ply_path, "--ply"}, {o.off_path, "--off"}})
      if (!path.empty())
        throw InputError(std::string(option) + ": the boundary mesh needs a 3D scene (or a BSH config.json)");
  if (!in.scene3)
    for (const auto& [path, option] : {std::pair{o.png_path, "--png"}, {o.states_png_path, "--states-png"}})
      if (!path.empty())
        throw InputError(std::string(option) + ": PNG pictures need a 3D scene (or a BSH config.json); 2D: --svg");

  bsh::ExtractOptions options;
  options.method = method;
  options.beam_width = o.beam_width;
  options.max_states = o.max_states;
  options.max_graph_cuts = o.max_graph_cuts;
  options.brute_force_limit = o.max_labellings;
  options.max_nodes = o.max_nodes;
  options.time_limit = o.time_limit;
  options.max_ties = o.max_ties;
  options.compare.max_bits = o.precision_bits;
  options.record_states = !o.states_svg_path.empty() || !o.states_png_path.empty();
  if (!o.quiet)
    options.progress = [](const bsh::SearchProgress& p) {
      std::cerr << "\r[hsx] " << (p.lower_bound ? "nodes " : "states expanded ") << p.states_expanded << ", queue "
                << p.queue_size << ", graph cuts " << p.graph_cuts;
      if (p.best_energy)
        std::cerr << ", best so far " << p.best_energy->missing_samples << " missing / "
                  << p.best_energy->measure().decimal_string(12);
      if (p.lower_bound) std::cerr << ", lower bound " << bound_text(*p.lower_bound);
      std::cerr << "      " << std::flush;
    };
  const bsh::Problem problem(in.complex());
  const bsh::ExtractResult result = bsh::extract(problem, options);
  if (options.progress && result.stats.seconds > 0.5) std::cerr << "\n";

  std::string json_text, svg_text, states_text, png_text, states_png_text;
  if (!o.json_path.empty()) json_text = result_to_json(problem, result, in.pieces(), !o.no_timing).dump(2) + "\n";
  std::vector<char> highlight;
  if (o.show_removed) {
    highlight.assign(in.complex().patches.size(), 0);
    for (int p : patches_of_supports(in.complex(), result.removed)) highlight[p] = 1;
  }
  const std::string title =
      o.input + " - " + bsh::to_string(result.method) + (result.optimal ? " (optimal)" : "");
  if (!o.svg_path.empty()) svg_text = shape_picture(in, result.labelling, highlight, title, o.labels, false);
  if (!o.png_path.empty())
    png_text = png_bytes(arrangement_raster3(*in.scene3, *in.arranged3,
                                             shape_options3(result.labelling, highlight, title, false, false)));
  if (!o.states_svg_path.empty() || !o.states_png_path.empty()) {
    const std::vector<Svg3State> states = path_states(in, problem, result, o.beam_width);
    if (!o.states_svg_path.empty()) states_text = states_picture(in, states, o.labels);
    if (!o.states_png_path.empty())
      states_png_text =
          png_bytes(states_raster3(*in.scene3, *in.arranged3, states, shape_options3({}, {}, "", false, true), 3));
  }
  MeshTexts mesh = in.scene3 ? mesh_texts(in, result.labelling, o, mtl_path) : MeshTexts{};
  out.put(o.json_path, json_text);
  out.put(o.svg_path, svg_text);
  out.put(o.states_svg_path, states_text);
  out.put(o.png_path, std::move(png_text));
  out.put(o.states_png_path, std::move(states_png_text));
  out.put(o.obj_path, std::move(mesh.obj));
  out.put(mtl_path, std::move(mesh.mtl));
  out.put(o.ply_path, std::move(mesh.ply));
  out.put(o.off_path, std::move(mesh.off));
  if (!o.quiet && o.json_path != "-") out.print(summary(in, problem, result, o));
  out.commit();
}

}  // namespace

void add_extract_command(CLI::App& app) {
  auto o = std::make_shared<ExtractCommandOptions>();
  CLI::App* cmd = app.add_subcommand("extract", "Extract the BSH shape (orientation-preserving, sample-connected, "
                                                "least energy) of a scene or a complex");
  cmd->add_option("INPUT", o->input,
                  "hsx-scene/1 (2D or 3D) or hsx-complex/1 JSON file, or a BSH authors' config.json")
      ->required();
  cmd->add_option("--method", o->method, "graphcut | beam | best-first | brute-force | exact (default beam)");
  cmd->add_option("--beam-width", o->beam_width, "K for the beam search (default 1, as in the paper)");
  cmd->add_option("--max-states", o->max_states, "stop after expanding N states (0: no limit; deterministic)");
  cmd->add_option("--max-nodes", o->max_nodes,
                  "exact: stop after expanding N branch-and-bound nodes (0: no limit; deterministic)");
  cmd->add_option("--max-graph-cuts", o->max_graph_cuts, "stop after N graph cuts (0: no limit; deterministic)");
  cmd->add_option("--time-limit", o->time_limit,
                  "stop after S seconds of search (0: no limit; reading and arranging the input are not counted), "
                  "brute force included; where it stops, hence the result, depends on the machine's speed and "
                  "load: --max-states, --max-nodes and --max-graph-cuts do not")
      ->check(seconds());
  cmd->add_option("--max-labellings", o->max_labellings,
                  "brute force: refuse (exit 2) inputs with more than N orientation-preserving labellings "
                  "(default 4194304)");
  cmd->add_option("--precision", o->precision_bits, "precision cap in bits for certified comparisons (default 2048)");
  cmd->add_option("--max-ties", o->max_ties, "stop enumerating optimal boundaries after N (default 16)")
      ->check(CLI::Range(1, 1 << 30));
  cmd->add_option("--svg", o->svg_path,
                  "write a picture of the shape, missing samples ringed red: 2D its boundary bold; 3D its boundary "
                  "patches in four orthographic views (io/svg3.hpp)")
      ->check(output_path());
  cmd->add_option("--png", o->png_path,
                  "3D: write the --svg picture as a PNG (the same four views, z-buffered and opaque, the samples and "
                  "missing-sample rings; no text: no title, caption, label or legend; io/svg3.hpp)")
      ->check(output_path());
  cmd->add_flag("--labels", o->labels,
                "label cells (c<k>) and patches (p<k>) in the SVG pictures, as in the JSON (the PNGs have no text)");
  cmd->add_flag("--show-removed", o->show_removed,
                "highlight the removed patches in the picture, SVG and PNG (paper Fig. 10)");
  cmd->add_option("--states-svg", o->states_svg_path,
                  "beam and best-first: write the states along the search's path to the result as one picture, a "
                  "panel per state (its boundary, its removed patches highlighted, its energy; 3D: the isometric "
                  "view), as in the paper's Fig. 10; K = 1 beam draws the states it recorded, other searches compute "
                  "each state's graph cut again")
      ->check(output_path());
  cmd->add_option("--states-png", o->states_png_path,
                  "3D, beam and best-first: write the --states-svg panels as one PNG, in the same grid (3 per row, "
                  "reading order; no titles: the removed patches are the amber ones)")
      ->check(output_path());
  cmd->add_option("--obj", o->obj_path,
                  "3D: write the shape's boundary as an OBJ mesh (outward, one group per patch, a material per "
                  "halfspace in the .mtl written beside it; io/mesh_export.hpp)")
      ->check(output_path());
  cmd->add_option("--ply", o->ply_path,
                  "3D: write the shape's boundary as an ASCII PLY mesh (outward; per face patch, halfspace, outside "
                  "and inside cell, colour)")
      ->check(output_path());
  cmd->add_option("--off", o->off_path,
                  "3D: write the shape's boundary as an OFF mesh (outward; face colours by halfspace, patch face "
                  "ranges in '# patch' comment lines)")
      ->check(output_path());
  cmd->add_flag("--exact-coordinates", o->exact_coordinates,
                "--obj and --off coordinates as exact rationals (\"-7/3\"; hsx reads them, most viewers do not)");
  cmd->add_option("--json", o->json_path,
                  "write the hsx-result/1 document ('-' for stdout); it holds every measure's exact closed form, "
                  "which the summary gives only when it is short (at most 6 terms and 160 characters; else its size)")
      ->check(output_path());
  cmd->add_flag("--no-timing", o->no_timing, "leave seconds out of the JSON (byte-reproducible output)");
  cmd->add_flag("-q,--quiet", o->quiet, "no summary, no progress");
  add_arrangement_limits(cmd, o->arrangement);
  cmd->callback([o] { run_extract(*o); });
}

}  // namespace hsx::cli
