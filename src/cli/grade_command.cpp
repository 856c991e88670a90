// hsx grade INPUT THEIR_RESULT | --run CMD: another program's BSH labelling graded exactly (algorithms/bsh/grade.hpp):
// is it orientation-preserving and sample-connected, of which energy, optimal, and if not, by how much and where.
// With --run the program is run here on the input (io/external_solver.hpp) and its answer graded.
#include <hsx/algorithms/bsh/grade.hpp>
#include "cli/commands.hpp"
#include <hsx/io/external_solver.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/input.hpp>
#include <hsx/io/json_values.hpp>
#include <hsx/io/labelling.hpp>
#include <hsx/io/result_json.hpp>

#include <algorithm>
#include <iostream>
#include <iterator>
#include <optional>
#include <memory>
#include <sstream>

namespace hsx::cli {

BoundaryDifference boundary_difference(const bsh::Problem& problem, const Complex& c, const bsh::Labelling& theirs,
                                       const bsh::Labelling& optimum) {
  const std::vector<int> a = bsh::boundary_supports(problem, theirs), b = bsh::boundary_supports(problem, optimum);
  std::vector<int> only_a, only_b;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only_a));
  std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(only_b));
  BoundaryDifference d;
  for (int g : only_a) d.theirs_only.push_back(oriented_patch(c, g, theirs));
  for (int g : only_b) d.optimum_only.push_back(oriented_patch(c, g, optimum));
  return d;
}

std::string patch_list(const Complex& c, const std::vector<int>& patches) {
  std::string s;
  for (int p : patches) s += " " + c.halfspace_names[c.patches[p].halfspace] + "#" + std::to_string(p);
  return s.empty() ? " none" : s;
}

namespace {

struct GradeCommandOptions {
  ArrangementLimits arrangement;
  std::string input, theirs;
  std::string method = "best-first";
  long max_states = 0, max_graph_cuts = 0, max_nodes = 0;
  long max_labellings = bsh::ExtractOptions().brute_force_limit;
  double time_limit = 0;
  int precision_bits = 2048;
  std::string json_path;
  bool quiet = false;
  std::string run_command, run_input = "bsh-graphcut";  ///< --run, --run-input
  double run_time_limit = 0;                            ///< --run-time-limit
  std::int64_t weight_scale = kDefaultGraphcutWeightScale;
};

/// Exit statuses: 0 optimal (proven), 3 not (invalid, or proven worse than the optimum), 4 undecided (the reference
/// is not proven optimal, or the energies did not separate at the precision cap).
constexpr int kNotOptimal = 3, kUndecided = 4;

/// The verdict, as the JSON and the summary name it.
std::string verdict(const bsh::Grade& g) {
  if (!g.orientation_preserving || !g.sample_connected) return "invalid";
  if (g.optimal()) return "optimal";
  if (g.optimum.optimal && g.versus_optimum == Order::Greater) return "suboptimal";
  return "undecided";
}

const char* order_name(Order o) {
  switch (o) {
    case Order::Less: return "less";
    case Order::Equal: return "equal";
    case Order::Greater: return "greater";
    case Order::Tie: return "tie";
  }
  return "?";
}

/// The options' oracle (InputError naming the option on a bad value).
bsh::ExtractOptions oracle_options(const GradeCommandOptions& o) {
  const auto method = bsh::method_from_string(o.method);
  if (!method || (*method != bsh::Method::BestFirst && *method != bsh::Method::Exact &&
                  *method != bsh::Method::BruteForce))
    throw InputError("--method: the reference must be a complete search: best-first, exact or brute-force, not \"" +
                     o.method + "\"");
  if (o.max_states < 0) throw InputError("--max-states: must be >= 0");
  if (o.max_graph_cuts < 0) throw InputError("--max-graph-cuts: must be >= 0");
  if (o.max_nodes < 0) throw InputError("--max-nodes: must be >= 0");
  if (o.max_labellings < 1) throw InputError("--max-labellings: must be at least 1");
  if (o.precision_bits < 64) throw InputError("--precision: at least 64 bits");
  bsh::ExtractOptions options = bsh::best_first_oracle();
  options.method = *method;
  options.max_states = o.max_states;
  options.max_graph_cuts = o.max_graph_cuts;
  options.max_nodes = o.max_nodes;
  options.brute_force_limit = o.max_labellings;
  options.time_limit = o.time_limit;
  options.compare.max_bits = o.precision_bits;
  return options;
}

nlohmann::json energy_json(const bsh::Energy& e) {
  return {{"missing_samples", e.missing_samples}, {"measure", measure_to_json(e.measure())}};
}

std::vector<int> inside_cells(const bsh::Labelling& labelling) {
  std::vector<int> cells;
  for (std::size_t c = 0; c < labelling.size(); ++c)
    if (labelling[c]) cells.push_back(static_cast<int>(c));
  return cells;
}

nlohmann::json grade_json(const GradeCommandOptions& o, const Complex& c, LabellingFormat format, const bsh::Grade& g,
                          const BoundaryDifference& d) {
  nlohmann::json islands = nlohmann::json::array();
  for (const auto& island : g.islands)
    islands.push_back({{"halfspace", c.halfspace_names[island.halfspace]}, {"patches", island.patches}});
  nlohmann::json optimum = {{"method", bsh::to_string(g.optimum.method)},
                            {"optimal", g.optimum.optimal},
                            {"energy", energy_json(g.optimum.energy)},
                            {"inside_cells", inside_cells(g.optimum.labelling)},
                            {"ties", g.optimum.ties.count}};
  if (!g.optimum.stopped_by.empty()) optimum["stopped_by"] = g.optimum.stopped_by;
  return {{"format", "hsx-grade/1"},
          {"input", o.input},
          {"graded", o.theirs.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.theirs)},
          {"graded_format", to_string(format)},
          {"complex_id", complex_identity(c)},
          {"verdict", verdict(g)},
          {"orientation_preserving", g.orientation_preserving},
          {"orientation_problem", g.orientation_problem},
          {"sample_connected", g.sample_connected},
          {"islands", std::move(islands)},
          {"energy", energy_json(g.energy)},
          {"optimum", std::move(optimum)},
          {"versus_optimum", order_name(g.versus_optimum)},
          {"gap", {{"missing_samples", g.missing_samples_gap}, {"measure", measure_to_json(g.measure_gap)}}},
          {"boundary_difference", {{"theirs_only", d.theirs_only}, {"optimum_only", d.optimum_only}}}};
}

nlohmann::json run_json(const GradeCommandOptions& o, const ExternalRun& r) {
  nlohmann::json j = {{"command", o.run_command}, {"input", o.run_input}, {"ran", r.ran}, {"timed_out", r.timed_out},
                      {"exit_status", r.exit_status}, {"seconds", r.seconds}, {"output_tail", r.output_tail}};
  if (!r.problem.empty()) j["problem"] = r.problem;
  return j;
}

std::string summary(const GradeCommandOptions& o, const Complex& c, LabellingFormat format, const bsh::Grade& g,
                    const BoundaryDifference& d) {
  std::ostringstream out;
  out << "graded " << (o.theirs.empty() ? std::string("the output of --run") : o.theirs) << " (" << to_string(format) << ") on " << c.cells.size() << " cells\n";
  out << "orientation-preserving " << (g.orientation_preserving ? "yes" : "no: " + g.orientation_problem) << "\n";
  out << "sample-connected " << (g.sample_connected ? "yes" : "no, " + std::to_string(g.islands.size()) +
                                                                  (g.islands.size() == 1 ? " island" : " islands") +
                                                                  " without a sample:");
  for (const auto& island : g.islands) out << "\n  " << c.halfspace_names[island.halfspace] << ":" << patch_list(c, island.patches);
  out << "\nenergy " << energy_text(g.energy, c.dimension) << "\n";
  out << "optimum " << energy_text(g.optimum.energy, c.dimension) << " (" << bsh::to_string(g.optimum.method)
      << (g.optimum.optimal                 ? std::string(", proven optimal")
          : g.optimum.stopped_by.empty() ? ", NOT proven optimal: " + g.optimum.optimality_note
                                         : ", NOT proven optimal: stopped by " + g.optimum.stopped_by) << ")\n";
  out << "gap " << g.missing_samples_gap << " missing samples, " << (c.dimension == 3 ? "area " : "length ")
      << measure_text(g.measure_gap) << " (" << order_name(g.versus_optimum) << ")\n";
  out << "boundary differs: theirs only" << patch_list(c, d.theirs_only) << "; optimum only"
      << patch_list(c, d.optimum_only) << "\n";
  const std::string v = verdict(g);
  out << "verdict " << v;
  if (v == "invalid" && g.orientation_preserving && g.versus_optimum == Order::Less)
    out << " (its energy is below the optimum's: it buys that by breaking sample-connectedness)";
  if (v == "undecided")
    out << (g.optimum.optimal ? " (the energies did not separate at the precision cap: --precision)"
                              : g.optimum.stopped_by.empty() ? " (the reference is not proven optimal: --method exact)"
                                                             : " (the reference search was stopped by a limit)");
  out << "\n";
  return out.str();
}

/// The labelling to grade: THEIR_RESULT, or what --run's program wrote (nullopt when it gave none: `run` says why).
std::optional<ReadLabelling> their_labelling(const GradeCommandOptions& o, const LoadedInput& in,
                                             std::optional<ExternalRun>& run) {
  if (o.run_command.empty()) return read_labelling_file(o.theirs, in.complex());
  ExternalSolver solver;
  solver.command = o.run_command;
  solver.input = *external_input_from_string(o.run_input);
  solver.weight_scale = o.weight_scale;
  solver.time_limit = o.run_time_limit;
  run = run_external_solver(in, solver);
  return run->labelling;
}

/// --run options checked before anything is computed.
void check_run_options(const GradeCommandOptions& o) {
  if (o.run_command.empty() == o.theirs.empty())
    throw InputError(o.theirs.empty() ? "THEIR_RESULT: give their labelling file, or --run CMD to compute it here"
                                      : "--run: give THEIR_RESULT or --run, not both");
  if (o.run_command.empty()) return;
  if (!external_input_from_string(o.run_input))
    throw InputError("--run-input: unknown format \"" + o.run_input + "\" (bsh-graphcut or complex)");
  if (o.weight_scale < 1) throw InputError("--weight-scale: must be at least 1");
  ExternalSolver solver;
  solver.command = o.run_command;
  solver.time_limit = o.run_time_limit;
  try {
    check_external_solver(solver);
  } catch (const InputError& e) {
    throw InputError(std::string("--run: ") + e.what());
  }
}

int run_grade(const GradeCommandOptions& o) {
  const bsh::ExtractOptions oracle = oracle_options(o);
  check_run_options(o);
  OutputFiles out;
  out.expect(o.json_path, "--json");
  const LoadedInput in = load_input(o.input, o.arrangement);
  protect_inputs(out, in);
  std::optional<ExternalRun> run;
  const std::optional<ReadLabelling> theirs = their_labelling(o, in, run);
  if (!theirs) {  // their program gave no answer: that is its grade, not bad input
    out.put(o.json_path, nlohmann::json{{"format", "hsx-grade/1"}, {"input", o.input}, {"verdict", "no answer"},
                                        {"complex_id", complex_identity(in.complex())}, {"run", run_json(o, *run)}}
                             .dump(2) + "\n");
    if (!o.quiet && o.json_path != "-") {
      std::ostringstream report;
      report << "ran " << o.run_command << ": " << run->problem << " (" << run->seconds << " s)\n"
             << (run->output_tail.empty() ? "" : "its output ends:\n" + run->output_tail +
                                                   (run->output_tail.back() == '\n' ? "" : "\n"))
             << "verdict no answer\n";
      out.print(report.str());
    }
    out.commit();
    return kNotOptimal;
  }
  const bsh::Problem problem(in.complex());
  const bsh::Grade g = bsh::grade(problem, theirs->cells, oracle);
  const BoundaryDifference d = boundary_difference(problem, in.complex(), theirs->cells, g.optimum.labelling);
  nlohmann::json j = grade_json(o, in.complex(), theirs->format, g, d);
  if (run) j["run"] = run_json(o, *run);
  out.put(o.json_path, j.dump(2) + "\n");
  if (!o.quiet && o.json_path != "-") {
    std::ostringstream report;
    if (run) report << "ran " << o.run_command << " in " << run->seconds << " s\n";
    report << summary(o, in.complex(), theirs->format, g, d);
    out.print(report.str());
  }
  out.commit();
  const std::string v = verdict(g);
  return v == "optimal" ? 0 : v == "undecided" ? kUndecided : kNotOptimal;
}

}  // namespace

void add_grade_command(CLI::App& app) {
  auto o = std::make_shared<GradeCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "grade", "Grade another program's BSH labelling exactly: orientation-preserving, sample-connected, its energy "
               "against the proven optimum and where the boundaries differ; exit 0 optimal, 3 invalid or worse, 4 "
               "undecided");
  cmd->add_option("INPUT", o->input, "the scene (2D or 3D, or a BSH config.json) or hsx-complex/1 file it was computed on")
      ->required();
  cmd->add_option("THEIR_RESULT", o->theirs,
                  "their labelling: an hsx-result/1, the BSH graph cut's {\"labels\": [...]} (true: inside), a JSON "
                  "array or a plain list of 0/1, one per cell in the order of `hsx arrange INPUT --json`'s cells "
                  "(`hsx arrange INPUT --export bsh-graphcut F` writes their graph-cut input); or --run");
  cmd->add_option("--method", o->method,
                  "the reference search: best-first (default; where it is left unproven without a limit, exact "
                  "decides), exact or brute-force");
  cmd->add_option("--max-states", o->max_states, "reference: stop after expanding N states (0: no limit)");
  cmd->add_option("--max-nodes", o->max_nodes, "reference, exact: stop after N branch-and-bound nodes (0: no limit)");
  cmd->add_option("--max-graph-cuts", o->max_graph_cuts, "reference: stop after N graph cuts (0: no limit)");
  cmd->add_option("--max-labellings", o->max_labellings, "reference, brute-force: refuse more labellings (exit 2)");
  cmd->add_option("--time-limit", o->time_limit,
                  "reference: stop after S seconds (0: no limit); a stopped reference makes the verdict undecided "
                  "unless the labelling is invalid")
      ->check(seconds());
  cmd->add_option("--precision", o->precision_bits, "precision cap in bits for certified comparisons (default 2048)");
  cmd->add_option("--run", o->run_command,
                  "instead of THEIR_RESULT: run this shell command here and grade the labelling it writes; {input} "
                  "and {output} stand for the two files, in a private folder removed afterwards "
                  "(io/external_solver.hpp); a program that fails, times out or writes no labelling gets the "
                  "verdict \"no answer\" (exit 3)");
  cmd->add_option("--run-input", o->run_input,
                  "--run: what {input} holds: bsh-graphcut (default, `hsx arrange --export bsh-graphcut`) or "
                  "complex (hsx-complex/1)");
  cmd->add_option("--run-time-limit", o->run_time_limit, "--run: kill the program after S seconds (0: no limit)")
      ->check(seconds());
  cmd->add_option("--weight-scale", o->weight_scale,
                  "--run-input bsh-graphcut: integer weight = round(measure x this), at least 1 (default 1000000)");
  cmd->add_option("--json", o->json_path, "write the grade as hsx-grade/1 JSON ('-' for stdout)")->check(output_path());
  cmd->add_flag("-q,--quiet", o->quiet, "no summary (the exit status says the verdict)");
  add_arrangement_limits(cmd, o->arrangement);
  run_with_status(cmd, o, &run_grade);
}

}  // namespace hsx::cli
