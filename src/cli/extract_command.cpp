// hsx extract INPUT --method graphcut|beam|best-first|brute-force|exact: the BSH shape (paper, Sections 3 and 5).
#include <hsx/algorithms/bsh/extract.hpp>
#include "cli/commands.hpp"
#include <hsx/io/input.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/result_json.hpp>
#include <hsx/io/svg.hpp>

#include <iostream>
#include <memory>
#include <sstream>

namespace hsx::cli {
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
  std::string svg_path, json_path;
  bool show_removed = false;
  bool labels = false;
  bool no_timing = false;
  bool quiet = false;
};

std::string energy_text(const bsh::Energy& e) {
  std::string s = std::to_string(e.missing_samples) + " missing sample" + (e.missing_samples == 1 ? "" : "s") +
                  ", boundary measure " + e.measure().decimal_string(30);
  if (auto exact = e.measure().exact_string()) s += " = " + *exact;
  return s;
}

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
  out << "\nenergy " << energy_text(r.energy) << "\n";
  const Measure area = bsh::inside_measure(in.complex(), r.labelling);
  out << (in.complex().dimension == 3 ? "volume " : "area ") << area.decimal_string(30);
  if (auto exact = area.exact_string()) out << " = " << *exact;
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
    const Patch& p = in.complex().patches[problem.supports()[g].patches.front()];
    out << " " << in.complex().halfspace_names[p.halfspace] << "#" << problem.supports()[g].patches.front();
  }
  out << "\nstats " << r.stats.graph_cuts << " graph cuts (" << r.stats.uncertified_cuts << " uncertified), "
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

void run_extract(const ExtractCommandOptions& o) {
  const auto method = bsh::method_from_string(o.method);
  if (!method) throw InputError("--method: unknown method \"" + o.method + "\" (graphcut, beam, best-first, brute-force, exact)");
  if (o.beam_width < 1) throw InputError("--beam-width: must be at least 1");
  if (o.max_states < 0) throw InputError("--max-states: must be >= 0");
  if (o.max_graph_cuts < 0) throw InputError("--max-graph-cuts: must be >= 0");
  if (o.max_labellings < 1) throw InputError("--max-labellings: must be at least 1");
  if (o.max_nodes < 0) throw InputError("--max-nodes: must be >= 0");
  if (o.time_limit < 0) throw InputError("--time-limit: must be >= 0");
  if (o.precision_bits < 64) throw InputError("--precision: at least 64 bits");
  OutputFiles out;  // checked before computing, written all or none at the end
  out.expect(o.json_path, "--json");
  out.expect(o.svg_path, "--svg");
  const LoadedInput in = load_input(o.input, o.arrangement);
  if (!o.svg_path.empty() && !in.scene)
    throw InputError("--svg: pictures need a scene (an hsx-complex/1 document carries no drawing)");

  bsh::ExtractOptions options;
  options.method = *method;
  options.beam_width = o.beam_width;
  options.max_states = o.max_states;
  options.max_graph_cuts = o.max_graph_cuts;
  options.brute_force_limit = o.max_labellings;
  options.max_nodes = o.max_nodes;
  options.time_limit = o.time_limit;
  options.max_ties = o.max_ties;
  options.compare.max_bits = o.precision_bits;
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

  std::string json_text, svg_text;
  if (!o.json_path.empty()) json_text = result_to_json(problem, result, in.pieces(), !o.no_timing).dump(2) + "\n";
  if (!o.svg_path.empty()) {
    SvgOptions svg;
    svg.title = o.input + " - " + bsh::to_string(result.method) + (result.optimal ? " (optimal)" : "");
    svg.cell_fill = result.labelling;
    svg.show_cell_ids = svg.show_patch_ids = o.labels;
    if (o.show_removed) {
      svg.highlight_legend = "removed patches";
      svg.highlight_patches.assign(in.complex().patches.size(), 0);
      for (int p : patches_of_supports(in.complex(), result.removed)) svg.highlight_patches[p] = 1;
    }
    svg_text = arrangement_svg(*in.scene, in.arranged->arrangement, in.complex(), svg);
  }
  out.put(o.json_path, json_text);
  out.put(o.svg_path, svg_text);
  out.commit();
  if (!o.quiet && o.json_path != "-") std::cout << summary(in, problem, result, o);
}

}  // namespace

void add_extract_command(CLI::App& app) {
  auto o = std::make_shared<ExtractCommandOptions>();
  CLI::App* cmd = app.add_subcommand("extract", "Extract the BSH shape (orientation-preserving, sample-connected, "
                                                "least energy) of a scene or a complex");
  cmd->add_option("INPUT", o->input, "hsx-scene/1 or hsx-complex/1 JSON file")->required();
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
  cmd->add_option("--svg", o->svg_path, "write a picture of the shape: its boundary bold, missing samples ringed red")
      ->check(output_path());
  cmd->add_flag("--labels", o->labels, "label cells (c<k>) and patches (p<k>) in the picture, as in the JSON");
  cmd->add_flag("--show-removed", o->show_removed, "highlight the removed patches in the picture (paper Fig. 10)");
  cmd->add_option("--json", o->json_path, "write the hsx-result/1 document ('-' for stdout)")->check(output_path());
  cmd->add_flag("--no-timing", o->no_timing, "leave seconds out of the JSON (byte-reproducible output)");
  cmd->add_flag("-q,--quiet", o->quiet, "no summary, no progress");
  add_arrangement_limits(cmd, o->arrangement);
  cmd->callback([o] { run_extract(*o); });
}

}  // namespace hsx::cli
