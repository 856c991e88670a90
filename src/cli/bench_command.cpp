// hsx bench [DIR...]: every method on every scene, each timed repeatedly (kernel/timing.hpp), reported as medians
// with their spread and as ratios of medians to the graph cut, side by side in one run; with --meshes, NH-Rep's
// stages on meshes, as ratios to reading the mesh; with --3d, the exact 3D arrangement beside CGAL's Nef polyhedra;
// with --bsh-example, the BSH authors' examples end to end beside their own figures; with --exact, --method exact
// on random scenes of growing size (issue 11's goals).
// --csv and --json write the same figures.
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/bsh/graph_cut.hpp>
#include <hsx/algorithms/campaign/campaign.hpp>
#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/complex/boundary_from_mesh.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/geometry/nef3.hpp>
#include <hsx/geometry/random_scene3.hpp>
#include <hsx/geometry/tessellate3.hpp>
#include <hsx/io/bsh_config.hpp>
#include <hsx/io/campaign_files.hpp>
#include <hsx/geometry/mesh3.hpp>
#include <hsx/geometry/random_scene.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/input.hpp>
#include <hsx/io/temporary_folder.hpp>
#include <hsx/kernel/timing.hpp>
#include "cli/commands.hpp"
#include "cli/distribute.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/edmonds_karp_max_flow.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include <cstdlib>
#include <sys/wait.h>
#include <unistd.h>

namespace hsx::cli {
namespace {

/// --campaign's second default check list: every check but Props. 5.2 and 5.1 (the checks of best-first itself).
constexpr const char* kWithoutBestFirst = "existence,beam1,prop41-optimum,prop41-beam,uniqueness,certificates,manifold";

struct BenchOptions {
  ArrangementLimits limits;  ///< --max-cells, --max-side-table
  std::vector<std::string> dirs{"data/scenes", "data/figures"};
  std::vector<std::string> meshes;  ///< NH-Rep mode: .obj files, each with a .fea beside it
  bool cuts = false;                ///< graph-cut mode: the certified cut against double baselines
  std::vector<int> cut_halfspaces{10, 50, 100, 200};  ///< graph-cut mode: random scenes of these sizes
  int cut_scenes = 1;               ///< graph-cut mode: scenes per size
  std::vector<std::string> cut_inputs;  ///< graph-cut mode: also these inputs (scenes, config.json, complexes)
  bool three_d = false;             ///< 3D mode: Arrangement3 beside Nef
  std::string bsh_config = "../shared/data/bsh-examples/figure19_b/config.json";
  std::vector<int> h_divisors{1, 2, 4};
  std::vector<int> plane_counts{10, 20, 30, 40, 50};
  long nef_max_triangles = 20000;   ///< Nef is skipped above this many input triangles
  int threads = 0;
  bool phases = false;              ///< 3D mode: also report the median time of each arrangement phase
  bool campaign = false;            ///< campaign mode: scenes per second of `hsx campaign`, 1 and 2 threads
  std::vector<int> campaign_halfspaces{4, 8};  ///< campaign mode: one row per scene size
  long campaign_scenes = 40;        ///< campaign mode: scenes per run
  double campaign_time_limit = 2;   ///< campaign mode: seconds per scene
  long campaign_max_states = 0;     ///< campaign mode: hsx campaign --max-states (0: none)
  /// Campaign mode: also time two processes, `hsx campaign --jobs 2` and `mpirun -np 2 hsx campaign --jobs 1`.
  bool campaign_mpi = false;
  /// Campaign mode: one row per scene size and check list (hsx campaign --checks): every check, and every check
  /// but the two about best-first itself (Props. 5.2 and 5.1, whose complete best-first search dominates).
  std::vector<std::string> campaign_checks{"all", kWithoutBestFirst};
  std::vector<std::string> bsh_examples;  ///< the BSH authors' example folders: end to end beside their figures
  bool arrange = false;             ///< arrangement mode: hsx::arrange beside CGAL's bare Arrangement_2 insertion
  std::vector<int> arrange_halfspaces{4, 16, 32, 64, 128};  ///< arrangement mode: random scenes of these sizes
  int arrange_scenes = 1;           ///< arrangement mode: scenes per size
  std::vector<std::string> arrange_inputs;  ///< arrangement mode: also these 2D scene files
  bool brute = false;               ///< brute-force mode: labellings per second of the oracle
  std::vector<int> brute_halfspaces{8, 10, 12, 14};  ///< brute-force mode: random scenes of these sizes
  int brute_scenes = 3;             ///< brute-force mode: scenes per size
  bool exact = false;               ///< exact mode: --method exact on random scenes (issue 11's goal table)
  std::vector<int> exact_halfspaces{8, 10, 12, 16, 20, 24, 30};  ///< exact mode: the scenes' sizes
  int exact_scenes = 20;            ///< exact mode: random scenes per size
  int exact_best_first_up_to = 12;  ///< exact mode: best-first beside exact up to this many halfspaces
  long brute_force_limit = 200000;
  double time_limit = 60;
  int repetitions = 5;
  double min_time = 0.2;
  std::string csv_path, json_path;
};

// ---- what is reported: one row per input, one timing per stage ----

struct StageResult {
  std::optional<TimingSummary> timing;  ///< empty when the stage was not run
  std::string status = "ok";            ///< "ok", or why there is no timing
};

struct BenchRow {
  std::string input;
  std::string skipped;                  ///< non-empty: why the input was not measured
  std::vector<long> sizes;              ///< per Report::size_names
  std::string phases;                   ///< --3d --phases: the arrangement's phase medians, one line
  std::vector<StageResult> stages;      ///< per Report::stage_names
  std::vector<std::string> notes;       ///< per Report::note_names
};

struct Report {
  std::string mode, input_name;          ///< "scenes" / "meshes"; the first column's title
  std::vector<std::string> size_names, stage_names, note_names;
  int reference = 0;                     ///< the stage ratios are taken to
  std::vector<char> with_ratio;          ///< per stage: report its ratio to the reference
  RepeatOptions repeat;
  std::vector<BenchRow> rows;
  std::vector<std::string> footer;
};

/// Median of stage `k` over the reference's median, when both were measured and the reference took time.
std::optional<double> ratio(const Report& report, const BenchRow& row, std::size_t k) {
  if (!report.with_ratio[k] || row.stages.size() <= k) return std::nullopt;
  const auto& stage = row.stages[k].timing;
  const auto& reference = row.stages[static_cast<std::size_t>(report.reference)].timing;
  if (!stage || !reference || !(reference->median > 0)) return std::nullopt;
  return stage->median / reference->median;
}

std::string printf_string(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

std::string seconds_text(double s) {
  if (s < 1e-3) return printf_string("%.1f us", s * 1e6);
  if (s < 1) return printf_string("%.2f ms", s * 1e3);
  return printf_string("%.3f s", s);
}

// ---- the three renderings ----

constexpr int kTimeWidth = 11, kSpreadWidth = 6, kRatioWidth = 9;

int stage_width(const Report& report, std::size_t k) {
  return kTimeWidth + kSpreadWidth + (report.with_ratio[k] ? kRatioWidth : 0);
}

std::string table_text(const Report& report) {
  std::ostringstream out;
  const int name_width = 28, size_width = 8;
  const std::string reference = report.stage_names[static_cast<std::size_t>(report.reference)];
  // Two header lines: the stages, then their columns.
  out << std::left << std::setw(name_width + size_width * static_cast<int>(report.size_names.size())) << "";
  for (std::size_t k = 0; k < report.stage_names.size(); ++k)
    out << std::right << std::setw(stage_width(report, k)) << report.stage_names[k];
  out << "\n" << std::left << std::setw(name_width) << report.input_name << std::right;
  for (const auto& s : report.size_names) out << std::setw(size_width) << s;
  for (std::size_t k = 0; k < report.stage_names.size(); ++k) {
    out << std::setw(kTimeWidth) << "median" << std::setw(kSpreadWidth) << "iqr";
    if (report.with_ratio[k]) out << std::setw(kRatioWidth) << "ratio";
  }
  for (const auto& n : report.note_names) out << std::setw(11) << n;
  out << "\n";
  for (const BenchRow& row : report.rows) {
    out << std::left << std::setw(name_width) << row.input << std::right;
    if (!row.skipped.empty()) {
      out << " skipped: " << row.skipped << "\n";
      continue;
    }
    for (long s : row.sizes) out << std::setw(size_width) << s;
    for (std::size_t k = 0; k < row.stages.size(); ++k) {
      const auto& t = row.stages[k].timing;
      if (!t) {
        out << std::setw(stage_width(report, k)) << row.stages[k].status;
        continue;
      }
      out << std::setw(kTimeWidth) << seconds_text(t->median)
          << std::setw(kSpreadWidth) << (t->median > 0 ? printf_string("%.0f%%", 100 * t->iqr() / t->median) : "-");
      if (report.with_ratio[k]) {
        const auto r = ratio(report, row, k);
        out << std::setw(kRatioWidth) << (r ? printf_string("%.2fx", *r) : "-");
      }
    }
    for (const auto& n : row.notes) out << std::setw(11) << n;
    out << "\n";
  }
  out << "\n";
  for (const auto& line : report.footer) out << line << "\n";
  out << "median: of at least " << report.repeat.min_repetitions << " runs, repeated until they add up to "
      << report.repeat.min_seconds << " s; iqr: interquartile range in % of the median; ratio: of medians, to "
      << reference << " on the same input (--csv/--json: also quartiles, min, max, total)\n";
  return out.str();
}

/// CSV field quoting (RFC 4180).
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string csv_number(double v) { return printf_string("%.9g", v); }

std::string csv_text(const Report& report) {
  std::ostringstream out;
  out << csv_field(report.input_name);
  for (const auto& s : report.size_names) out << "," << csv_field(s);
  out << ",stage,status,repetitions,median_s,q1_s,q3_s,min_s,max_s,total_s,ratio_to_"
      << csv_field(report.stage_names[static_cast<std::size_t>(report.reference)]) << "\n";
  for (const BenchRow& row : report.rows) {
    if (!row.skipped.empty()) {
      out << csv_field(row.input) << std::string(report.size_names.size(), ',') << ",," << csv_field("skipped: " + row.skipped)
          << ",,,,,,,,\n";
      continue;
    }
    for (std::size_t k = 0; k < row.stages.size(); ++k) {
      out << csv_field(row.input);
      for (long s : row.sizes) out << "," << s;
      out << "," << csv_field(report.stage_names[k]) << "," << csv_field(row.stages[k].status);
      if (const auto& t = row.stages[k].timing) {
        out << "," << t->repetitions;
        for (double v : {t->median, t->q1, t->q3, t->min, t->max, t->total}) out << "," << csv_number(v);
      } else {
        out << ",,,,,,,";
      }
      const auto r = ratio(report, row, k);
      out << "," << (r ? csv_number(*r) : "") << "\n";
    }
  }
  return out.str();
}

nlohmann::json timing_json(const TimingSummary& t) {
  return {{"repetitions", t.repetitions}, {"median_s", t.median}, {"q1_s", t.q1}, {"q3_s", t.q3},
          {"min_s", t.min},           {"max_s", t.max},       {"total_s", t.total}};
}

nlohmann::json report_json(const Report& report) {
  nlohmann::json rows = nlohmann::json::array();
  for (const BenchRow& row : report.rows) {
    nlohmann::json r = {{"input", row.input}};
    if (!row.skipped.empty()) {
      r["skipped"] = row.skipped;
      rows.push_back(r);
      continue;
    }
    for (std::size_t k = 0; k < row.sizes.size(); ++k) r[report.size_names[k]] = row.sizes[k];
    nlohmann::json stages = nlohmann::json::array();
    for (std::size_t k = 0; k < row.stages.size(); ++k) {
      nlohmann::json s = {{"stage", report.stage_names[k]}, {"status", row.stages[k].status}};
      if (const auto& t = row.stages[k].timing) s.update(timing_json(*t));
      const auto q = ratio(report, row, k);
      s["ratio"] = q ? nlohmann::json(*q) : nlohmann::json(nullptr);
      stages.push_back(s);
    }
    r["stages"] = stages;
    for (std::size_t k = 0; k < row.notes.size(); ++k) r[report.note_names[k]] = row.notes[k];
    rows.push_back(r);
  }
  return {{"format", "hsx-bench/1"},
          {"mode", report.mode},
          {"min_repetitions", report.repeat.min_repetitions},
          {"min_seconds", report.repeat.min_seconds},
          {"ratio_to", report.stage_names[static_cast<std::size_t>(report.reference)]},
          {"rows", rows},
          {"footer", report.footer}};
}

/// Prints the table and writes the requested files (all rendered before anything is written, all or none).
void publish(const Report& report, const BenchOptions& o, OutputFiles& files) {
  const std::string csv = o.csv_path.empty() ? "" : csv_text(report);
  const std::string json = o.json_path.empty() ? "" : report_json(report).dump(2) + "\n";
  files.put(o.csv_path, csv);
  files.put(o.json_path, json);
  files.print(table_text(report));
  files.commit();
}

RepeatOptions repeat_options(const BenchOptions& o) {
  if (o.repetitions < 1) throw InputError("--repetitions: must be at least 1");
  if (!std::isfinite(o.min_time) || o.min_time < 0) throw InputError("--min-time: must be >= 0 seconds");
  RepeatOptions r;
  r.min_repetitions = o.repetitions;
  r.max_repetitions = std::max(o.repetitions, 1000000);
  r.min_seconds = o.min_time;
  return r;
}

// ---- BSH methods on scenes ----

std::vector<std::string> scene_files(const std::vector<std::string>& dirs) {
  std::vector<std::string> files;
  for (const auto& dir : dirs) {
    if (!std::filesystem::is_directory(dir)) throw InputError("bench: \"" + dir + "\" is not a directory");
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == ".json" && entry.path().filename() != "expected.json")
        files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

const bsh::Method kMethods[] = {bsh::Method::GraphCut, bsh::Method::Beam, bsh::Method::BestFirst,
                                bsh::Method::BruteForce, bsh::Method::Exact};
constexpr int kMethodCount = 5;
constexpr int kExact = 4;  ///< index of the exact method: the reference optimum for the beam verdict

/// One scene: its arrangement, then every method, each timed repeatedly; `results` gets each method's result.
BenchRow bench_scene(const std::string& file, const BenchOptions& o, const RepeatOptions& repeat,
                     std::optional<bsh::ExtractResult> (&results)[kMethodCount]) {
  BenchRow row;
  row.input = std::filesystem::path(file).filename().string();
  LoadedInput in;
  try {
    in = load_input(file, o.limits);
  } catch (const InputError& e) {
    row.skipped = e.what();
    return row;
  }
  const bsh::Problem problem(in.complex());
  row.sizes = {problem.cell_count(), static_cast<long>(in.complex().patches.size())};
  StageResult arrangement;
  if (in.scene)
    arrangement.timing = time_repeatedly([&] { arrange(*in.scene); }, repeat);
  else
    arrangement.status = "no scene";
  row.stages.push_back(arrangement);
  for (int k = 0; k < kMethodCount; ++k) {
    bsh::ExtractOptions options;
    options.method = kMethods[k];
    options.time_limit = o.time_limit;
    options.brute_force_limit = o.brute_force_limit;
    StageResult stage;
    try {
      stage.timing = time_repeatedly([&] { results[k] = bsh::extract(problem, options); }, repeat);
    } catch (const std::runtime_error&) {
      stage.status = "too large";  // the oracle refused: too many labellings
    }
    row.stages.push_back(stage);
  }
  return row;
}

void run_bench(const BenchOptions& o, OutputFiles& files) {
  Report report;
  report.mode = "scenes";
  report.input_name = "scene";
  report.size_names = {"cells", "patches"};
  report.stage_names = {"arrange", "graphcut", "beam", "best-first", "brute-force", "exact"};
  report.with_ratio = {0, 0, 1, 1, 1, 1};
  report.reference = 1;
  report.note_names = {"bf states", "exact nodes", "beam"};
  report.repeat = repeat_options(o);
  double totals[kMethodCount + 1] = {};
  int beam_optimal = 0, compared = 0;
  const std::vector<std::string> scenes = scene_files(o.dirs);
  for (const std::string& scene : scenes)  // inputs too: no output may replace one
    for (const auto& [option, path] : {std::pair{"--csv", o.csv_path}, std::pair{"--json", o.json_path}})
      refuse_output_over_input(option, path, "scene", scene);
  for (const auto& file : scenes) {
    std::optional<bsh::ExtractResult> results[kMethodCount];
    BenchRow row = bench_scene(file, o, report.repeat, results);
    for (std::size_t k = 0; k < row.stages.size(); ++k)
      if (row.stages[k].timing) totals[k] += row.stages[k].timing->median;
    std::string verdict = "-";
    const auto& optimum = results[kExact] && results[kExact]->optimal ? results[kExact] : results[2];
    if (results[1] && optimum && optimum->optimal) {
      ++compared;
      const bool same = bsh::compare(results[1]->energy, optimum->energy) != Order::Greater;
      beam_optimal += same;
      verdict = same ? "opt" : "subopt";
    }
    if (row.skipped.empty())
      row.notes = {results[2] ? std::to_string(results[2]->stats.states_expanded) : "-",
                   results[kExact] ? std::to_string(results[kExact]->stats.nodes) : "-", verdict};
    report.rows.push_back(std::move(row));
  }
  std::ostringstream footer;
  footer << report.rows.size() << " scenes; sums of medians:";
  for (std::size_t k = 0; k < report.stage_names.size(); ++k)
    footer << (k ? ", " : " ") << report.stage_names[k] << " " << seconds_text(totals[k]);
  report.footer = {footer.str(), "beam K=1 optimal on " + std::to_string(beam_optimal) + " of " +
                                     std::to_string(compared) + " scenes (bf states: best-first's states expanded; exact nodes: "
                                     "branch-and-bound nodes expanded)"};
  publish(report, o, files);
}

// ---- the certified graph cut against double-precision max flows ----
// The baselines are the same graph (Fig. 8, graph_cut.hpp) with double weights samples * lambda + measure (lambda
// above the measure of every support together; infinity for forced edges), built from the Problem and solved by
// Boost's Boykov-Kolmogorov and Edmonds-Karp: the cost of certification is the ratio of the certified cut to them.

using DoubleTraits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
using DoubleFlowGraph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS, boost::no_property,
    boost::property<boost::edge_capacity_t, double,
                    boost::property<boost::edge_residual_capacity_t, double,
                                    boost::property<boost::edge_reverse_t, DoubleTraits::edge_descriptor>>>>;

/// The double graph of `problem` (no constraints); s = cell_count, t = cell_count + 1.
DoubleFlowGraph double_cut_graph(const bsh::Problem& problem) {
  const int n = problem.cell_count();
  const Complex& c = problem.complex();
  double lambda = 1;
  for (const auto& bounds : problem.support_enclosures()) lambda += 2 * bounds.second;
  std::vector<double> source(n, 0), sink(n, 0);
  std::map<std::pair<int, int>, double> binary;
  for (const Patch& p : c.patches) {
    source[p.inside_cell] += lambda * static_cast<double>(p.samples.size());
    sink[p.outside_cell] += lambda * static_cast<double>(p.samples.size());
  }
  const double inf = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k)
    if (c.cells[k].outer) sink[k] = inf;
  for (int g = 0; g < problem.support_count(); ++g) {
    const bsh::SupportTerm& st = problem.supports()[g];
    const auto& [lo, hi] = problem.support_enclosures()[g];
    double& ab = binary[{st.cell_a, st.cell_b}];
    double& ba = binary[{st.cell_b, st.cell_a}];
    ab = st.allow_a_inside ? ab + (lo + hi) / 2 : inf;
    ba = st.allow_b_inside ? ba + (lo + hi) / 2 : inf;
  }
  DoubleFlowGraph g(n + 2);
  auto capacity = boost::get(boost::edge_capacity, g);
  auto reverse = boost::get(boost::edge_reverse, g);
  auto add = [&](int from, int to, double w) {
    if (w == 0) return;
    auto e = boost::add_edge(from, to, g).first;
    auto r = boost::add_edge(to, from, g).first;
    capacity[e] = w;
    capacity[r] = 0;
    reverse[e] = r;
    reverse[r] = e;
  };
  for (int k = 0; k < n; ++k) {
    add(n, k, source[k]);
    add(k, n + 1, sink[k]);
  }
  for (const auto& [pair, w] : binary) add(pair.first, pair.second, w);
  return g;
}

/// Builds the double graph and solves it with Boykov-Kolmogorov (`bk`) or Edmonds-Karp; returns the flow value.
double double_cut(const bsh::Problem& problem, bool bk) {
  DoubleFlowGraph g = double_cut_graph(problem);
  const auto n = boost::num_vertices(g);
  std::vector<boost::default_color_type> color(n);
  std::vector<DoubleTraits::edge_descriptor> pred(n);
  auto index = boost::get(boost::vertex_index, g);
  auto colors = boost::make_iterator_property_map(color.begin(), index);
  const auto s = n - 2, t = n - 1;
  if (bk)
    return boost::boykov_kolmogorov_max_flow(g, boost::get(boost::edge_capacity, g),
                                             boost::get(boost::edge_residual_capacity, g),
                                             boost::get(boost::edge_reverse, g), colors, index, s, t);
  return boost::edmonds_karp_max_flow(g, s, t, boost::get(boost::edge_capacity, g),
                                      boost::get(boost::edge_residual_capacity, g),
                                      boost::get(boost::edge_reverse, g), colors,
                                      boost::make_iterator_property_map(pred.begin(), index));
}

/// Refuses a mode's random-scene options: `prefix`-scenes below 1 (0 allowed when the mode takes given inputs,
/// `inputs` not null, and some are given) and a `prefix`-halfspaces size below 1.
void check_random_scenes(const std::string& prefix, int scenes, const std::vector<int>& sizes,
                         const std::vector<std::string>* inputs) {
  if (scenes < 0 || (scenes == 0 && (!inputs || inputs->empty())))
    throw InputError(prefix + "-scenes: must be at least 1" +
                     (inputs ? " (0 only with " + prefix + "-inputs)" : std::string()));
  for (int h : sizes)
    if (h < 1) throw InputError(prefix + "-halfspaces: every size must be at least 1");
}

/// One measured stage per summary, in order.
std::vector<StageResult> stages_of(const std::vector<TimingSummary>& timings) {
  std::vector<StageResult> stages(timings.size());
  for (std::size_t k = 0; k < timings.size(); ++k) stages[k].timing = timings[k];
  return stages;
}

/// The certified cut (warm-started and from the zero flow) and the two double max flows of one problem, timed
/// alternately.
void time_cuts(const bsh::Problem& problem, long patches, const RepeatOptions& repeat, BenchRow& row) {
  row.sizes = {problem.cell_count(), patches};
  bsh::CutResult cut, cold_cut;
  bsh::CutConstraints cold;
  cold.warm_start = false;
  const auto timings = time_alternately({[&] { cut = bsh::graph_cut(problem, {}); },
                                         [&] { cold_cut = bsh::graph_cut(problem, cold); },
                                         [&] { double_cut(problem, true); }, [&] { double_cut(problem, false); }},
                                        repeat);
  row.stages = stages_of(timings);
  const auto verdict = [](const bsh::CutResult& r) { return r.certified ? "yes" : "no: " + r.certificate_note; };
  row.notes = {verdict(cut), verdict(cold_cut), cut.labelling == cold_cut.labelling ? "yes" : "NO"};
}

/// Random scene `index` of seed 1 under `settings`, arranged within the limits; names `row` ("random H #index") and
/// marks it skipped (nullopt) when the limits refuse the scene.
std::optional<Arranged2> arrange_random(const RandomSceneSettings& settings, int index, const BenchOptions& o,
                                        BenchRow& row) {
  row.input = "random " + std::to_string(settings.max_halfspaces) + " #" + std::to_string(index);
  try {
    return arrange(random_scene(settings, 1, static_cast<std::uint64_t>(index)).scene, o.limits);
  } catch (const InputError& e) {
    row.skipped = e.what();
    return std::nullopt;
  }
}

/// Random scene `index` of `halfspaces` halfspaces (seed 1, up to 3 samples per halfspace): its cut, timed.
BenchRow bench_cut(int halfspaces, int index, const BenchOptions& o, const RepeatOptions& repeat) {
  RandomSceneSettings settings;
  settings.min_halfspaces = settings.max_halfspaces = halfspaces;
  settings.max_samples = 3;
  BenchRow row;
  const std::optional<Arranged2> arranged = arrange_random(settings, index, o, row);
  if (!arranged) return row;
  const bsh::Problem problem(arranged->complex);
  time_cuts(problem, static_cast<long>(arranged->complex.patches.size()), repeat, row);
  return row;
}

/// A given input (2D or 3D scene, the BSH authors' config.json, hsx-complex/1): its cut, timed.
BenchRow bench_cut_input(const std::string& path, const BenchOptions& o, const RepeatOptions& repeat) {
  BenchRow row;
  row.input = path;
  const LoadedInput in = load_input(path, o.limits);  // bad input: exit 2, as everywhere
  const bsh::Problem problem(in.complex());
  time_cuts(problem, static_cast<long>(in.complex().patches.size()), repeat, row);
  return row;
}

/// Graph-cut mode: the certified cut (warm-started, and from the zero flow: CutConstraints::warm_start) and the two
/// double max flows on random scenes, as ratios to Boykov-Kolmogorov; notes: both certified, the same cut.
void run_cut_bench(const BenchOptions& o, OutputFiles& files) {
  check_random_scenes("--cut", o.cut_scenes, o.cut_halfspaces, &o.cut_inputs);
  Report report;
  report.mode = "cuts";
  report.input_name = "scene";
  report.size_names = {"cells", "patches"};
  report.stage_names = {"certified cut", "zero-flow cut", "double BK", "double EK"};
  report.with_ratio = {1, 1, 0, 1};
  report.reference = 2;
  report.note_names = {"certified", "zero-flow", "same cut"};
  report.repeat = repeat_options(o);
  for (int h : o.cut_halfspaces)
    for (int k = 0; k < o.cut_scenes; ++k) report.rows.push_back(bench_cut(h, k, o, report.repeat));
  const std::size_t random_rows = report.rows.size();
  for (const std::string& path : o.cut_inputs) report.rows.push_back(bench_cut_input(path, o, report.repeat));
  report.footer = {std::to_string(random_rows) + " random scenes (seed 1, up to 3 samples per halfspace)" +
                   (o.cut_inputs.empty() ? std::string() : " and " + std::to_string(o.cut_inputs.size()) +
                                                               " given input(s)") +
                   "; ratios to the double Boykov-Kolmogorov "
                   "max flow on the same graph, each built from the problem inside the timing; the four stages "
                   "alternate (rounds of one run of each), so a change of load falls on all of them"};
  publish(report, o, files);
}

// ---- the exact method on random scenes (issue 11's goal table) ----
// Random 2D scenes (half-planes, disks, polygons; random_scene's default settings with 1 to 3 samples per
// halfspace, seed 1, scene k = index k) of each size; `--method exact` timed on each, best-first beside it on the
// small sizes, and per size the distribution the goals speak of.

/// What one scene's row says, for the per-size summary.
struct ExactSceneFigures {
  int halfspaces = 0;
  long cells = 0;
  bool exact_proven = false, best_first_proven = false;
  double exact_seconds = 0, best_first_seconds = 0;
  long nodes = 0;
};

/// Runs `method` on `problem` once (timed); when that run took less than --min-time and was not stopped, the
/// median of repeated runs replaces it. `result` gets the first run's result.
StageResult time_search(const bsh::Problem& problem, bsh::ExtractOptions options, const RepeatOptions& repeat,
                        bsh::ExtractResult& result) {
  StageResult stage;
  stage.timing = time_repeatedly([&] { result = bsh::extract(problem, options); }, RepeatOptions{1, 0, 1, {}});
  if (result.stopped_by.empty() && stage.timing->median < repeat.min_seconds)
    stage.timing = time_repeatedly([&] { bsh::extract(problem, options); }, repeat);
  return stage;
}

/// Random scene `index` of `halfspaces` halfspaces: exact, and best-first when `with_best_first`.
BenchRow bench_exact_scene(int halfspaces, int index, bool with_best_first, const BenchOptions& o,
                           const RepeatOptions& repeat, ExactSceneFigures& figures) {
  RandomSceneSettings settings;
  settings.min_halfspaces = settings.max_halfspaces = halfspaces;
  settings.min_samples_per_halfspace = 1;
  settings.max_samples_per_halfspace = 3;
  BenchRow row;
  const std::optional<Arranged2> arranged = arrange_random(settings, index, o, row);
  if (!arranged) return row;
  const bsh::Problem problem(arranged->complex);
  row.sizes = {problem.cell_count(), static_cast<long>(arranged->complex.patches.size()), problem.total_samples()};
  bsh::ExtractOptions options;
  options.time_limit = o.time_limit;
  options.method = bsh::Method::Exact;
  bsh::ExtractResult exact, best_first;
  row.stages.push_back(time_search(problem, options, repeat, exact));
  figures = {halfspaces, problem.cell_count(), exact.optimal, false, row.stages[0].timing->median, 0, exact.stats.nodes};
  std::string agree = "-";
  if (with_best_first) {
    options.method = bsh::Method::BestFirst;
    row.stages.push_back(time_search(problem, options, repeat, best_first));
    figures.best_first_proven = best_first.optimal && best_first.stopped_by.empty();
    figures.best_first_seconds = row.stages[1].timing->median;
    if (figures.best_first_proven && exact.optimal)
      agree = bsh::compare(exact.energy, best_first.energy) == Order::Greater ||
                      bsh::compare(exact.energy, best_first.energy) == Order::Less
                  ? "DIFFERENT"
                  : "same";
  } else {
    StageResult skipped;
    skipped.status = "not run";
    row.stages.push_back(skipped);
  }
  const auto verdict = [](const bsh::ExtractResult& r) { return r.optimal ? std::string("proven") : r.stopped_by; };
  row.notes = {std::to_string(exact.stats.nodes), verdict(exact),
               with_best_first ? verdict(best_first) : std::string("-"), agree};
  return row;
}

/// The median of `values` (sorted copy; 0 when empty).
double median_of(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

/// One footer line per size: cells, exact proven / median / max time / nodes, best-first proven, speed-up.
std::vector<std::string> exact_summary(const std::vector<ExactSceneFigures>& scenes, const std::vector<int>& sizes,
                                       double time_limit) {
  std::vector<std::string> lines;
  for (int h : sizes) {
    std::vector<double> cells, times, nodes, speedups;
    int proven = 0, best_first = 0, count = 0;
    double worst = 0;
    for (const ExactSceneFigures& f : scenes) {
      if (f.halfspaces != h) continue;
      ++count;
      cells.push_back(static_cast<double>(f.cells));
      times.push_back(f.exact_seconds);
      nodes.push_back(static_cast<double>(f.nodes));
      worst = std::max(worst, f.exact_seconds);
      proven += f.exact_proven;
      best_first += f.best_first_proven;
      if (f.exact_proven && f.best_first_proven) speedups.push_back(f.best_first_seconds / f.exact_seconds);
    }
    std::ostringstream line;
    line << h << " halfspaces: " << count << " scenes, cells median " << median_of(cells) << "; exact proven "
         << proven << "/" << count << ", median " << seconds_text(median_of(times)) << ", max "
         << (proven < count ? "> " + seconds_text(time_limit) + " (stopped)" : seconds_text(worst))
         << ", nodes median " << median_of(nodes);
    if (!speedups.empty())
      line << "; best-first proven " << best_first << "/" << count << ", speed-up median "
           << printf_string("%.0fx", median_of(speedups)) << " (min "
           << printf_string("%.0fx", *std::min_element(speedups.begin(), speedups.end())) << ")";
    lines.push_back(line.str());
  }
  double small_worst = 0;
  int small = 0;
  for (const ExactSceneFigures& f : scenes)
    if (f.cells <= 60) ++small, small_worst = std::max(small_worst, f.exact_proven ? f.exact_seconds : time_limit);
  lines.push_back(std::to_string(small) + " scenes of <= 60 cells: exact's slowest " + seconds_text(small_worst));
  return lines;
}

/// Exact mode: `--method exact` on random scenes of each size (best-first beside it up to
/// --exact-best-first-up-to halfspaces), each within --time-limit; ratio: best-first over exact.
void run_exact_bench(const BenchOptions& o, OutputFiles& files) {
  if (o.exact_scenes < 1) throw InputError("--exact-scenes: must be at least 1");
  for (int h : o.exact_halfspaces)
    if (h < 1) throw InputError("--exact-halfspaces: every size must be at least 1");
  Report report;
  report.mode = "exact";
  report.input_name = "scene";
  report.size_names = {"cells", "patches", "samples"};
  report.stage_names = {"exact", "best-first"};
  report.with_ratio = {0, 1};
  report.reference = 0;
  report.note_names = {"nodes", "exact", "best-first", "energies"};
  report.repeat = repeat_options(o);
  std::vector<ExactSceneFigures> figures;
  for (int h : o.exact_halfspaces)
    for (int k = 0; k < o.exact_scenes; ++k) {
      ExactSceneFigures f;
      report.rows.push_back(bench_exact_scene(h, k, h <= o.exact_best_first_up_to, o, report.repeat, f));
      if (report.rows.back().skipped.empty()) figures.push_back(f);
    }
  report.footer = exact_summary(figures, o.exact_halfspaces, o.time_limit);
  report.footer.push_back("random scenes: seed 1, scene k = index k, 1 to 3 samples per halfspace; each search "
                          "within --time-limit " + seconds_text(o.time_limit) +
                          "; a run under --min-time is repeated; energies: exact's against best-first's where both are proven");
  publish(report, o, files);
}

// ---- NH-Rep stages on meshes ----

BenchRow bench_mesh(const std::string& obj, const RepeatOptions& repeat) {
  BenchRow row;
  row.input = std::filesystem::path(obj).filename().string();
  std::filesystem::path fea = obj;
  fea.replace_extension(".fea");
  Mesh3 mesh;
  FeatureEdgeList features;
  StageResult read;
  read.timing = time_repeatedly(
      [&] {
        mesh = read_mesh3_file(obj);
        features = read_fea_file(fea.string());
      },
      repeat);
  BoundarySurface surface;
  StageResult classify;
  classify.timing = time_repeatedly([&] { surface = boundary_from_mesh(mesh, features); }, repeat);
  BoundarySurface surface_copy;
  nhrep::PatchGraph graph;
  StageResult patch_graph;
  patch_graph.timing = time_repeatedly([&] { graph = nhrep::build_patch_graph(std::move(surface_copy)); }, repeat,
                                       [&] { surface_copy = surface; });
  nhrep::PatchGraph graph_copy;
  std::optional<nhrep::BuildResult> result;
  StageResult algorithm1;
  algorithm1.timing = time_repeatedly([&] { result = nhrep::build_tree(std::move(graph_copy)); }, repeat,
                                      [&] { graph_copy = graph; });
  bool ok = false;
  StageResult check;
  check.timing = time_repeatedly([&] { ok = nhrep::check_tree(*result).empty(); }, repeat);
  row.sizes = {static_cast<long>(mesh.faces.size()), static_cast<long>(graph.patches.size())};
  row.stages = {read, classify, patch_graph, algorithm1, check};
  row.notes = {std::to_string(result->decompositions.size()), ok ? "ok" : "FAILED"};
  return row;
}

/// NH-Rep on meshes: each stage timed repeatedly, as a ratio to reading and validating the mesh.
void run_nhrep_bench(const BenchOptions& o, OutputFiles& files) {
  Report report;
  report.mode = "meshes";
  report.input_name = "mesh";
  report.size_names = {"faces", "patches"};
  report.stage_names = {"read", "classify", "patch graph", "algorithm 1", "check"};
  report.with_ratio = {0, 1, 1, 1, 1};
  report.reference = 0;
  report.note_names = {"decomp", "check"};
  report.repeat = repeat_options(o);
  for (const std::string& obj : o.meshes) report.rows.push_back(bench_mesh(obj, report.repeat));
  report.footer = {std::to_string(report.rows.size()) + " meshes (read: reading and validating the mesh and its .fea)"};
  publish(report, o, files);
}

// ---- the 3D arrangement beside Nef ----

/// The BSH authors' scene tessellated by their rule at h / divisor (io/bsh_config.hpp reads it at divisor 1).
Scene3 bsh_scene_at(const std::string& config, int divisor) {
  BshReadOptions options;
  options.h_scale = 1.0 / divisor;
  return read_bsh_config_file(config, options);
}

long input_triangles(const Scene3& scene) {
  long n = 0;
  for (const Halfspace3& h : scene.halfspaces) n += static_cast<long>(h.surface.triangles.size());
  return n;
}

std::string megabytes(const std::optional<long>& bytes) {
  return bytes ? printf_string("%.0f", static_cast<double>(*bytes) / (1 << 20)) : "-";
}

/// "NAME phases (median of N runs): phase 1.23 ms, ...": each phase's median over the runs.
std::string phase_medians(const std::string& name, const std::vector<Arrangement3Timings>& runs) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> seconds;
  for (const Arrangement3Timings& run : runs)
    for (const auto& [phase, s] : run.phases) {
      if (seconds.find(phase) == seconds.end()) order.push_back(phase);
      seconds[phase].push_back(s);
    }
  std::string line = name + " phases (median of " + std::to_string(runs.size()) + " runs):";
  for (std::size_t k = 0; k < order.size(); ++k)
    line += (k ? ", " : " ") + order[k] + " " + seconds_text(summarize_times(seconds[order[k]]).median);
  return line;
}

/// One 3D scene: the exact arrangement and complex (no volumes), then Nef, each timed and its peak memory taken.
BenchRow bench_scene3(const std::string& name, const Scene3& scene, const BenchOptions& o,
                      const RepeatOptions& repeat) {
  BenchRow row;
  row.input = name;
  Arrangement3Options options;
  options.volumes = false;
  options.threads = o.threads;
  std::optional<Arranged3> arranged;
  StageResult arrangement;
  std::vector<Arrangement3Timings> phase_runs;
  arrangement.timing = time_repeatedly(
      [&] {
        Arrangement3Timings phases;
        options.timings = o.phases ? &phases : nullptr;
        arranged = arrange(scene, o.limits, options);
        if (o.phases) phase_runs.push_back(std::move(phases));
      },
      repeat);
  options.timings = nullptr;
  if (o.phases) row.phases = phase_medians(name, phase_runs);
  const auto arrangement_peak = peak_memory_of([&] { arrange(scene, o.limits, options); });
  const long triangles = input_triangles(scene);
  StageResult nef;
  std::optional<NefCellCounts> counts;
  std::optional<long> nef_peak;
  if (o.nef_max_triangles > 0 && triangles > o.nef_max_triangles) {
    nef.status = "skipped";
  } else {
    nef.timing = time_repeatedly([&] { counts = nef_cell_counts(scene); }, repeat);
    nef_peak = peak_memory_of([&] { nef_cell_counts(scene); });
  }
  const Complex& c = arranged->complex;
  const long cells = static_cast<long>(c.cells.size());
  row.sizes = {static_cast<long>(scene.halfspaces.size()), triangles,
               static_cast<long>(arranged->arrangement.triangles().size()), cells,
               static_cast<long>(c.outer_cell_count()), static_cast<long>(c.patches.size())};
  row.stages = {arrangement, nef};
  std::string agree = "-";
  if (counts) agree = counts->cells == cells && counts->outer_cells == c.outer_cell_count() ? "yes" : "DIFFER";
  row.notes = {counts ? std::to_string(counts->cells) : "-", agree, megabytes(arrangement_peak), megabytes(nef_peak)};
  return row;
}

/// The BSH authors' figure19_b at h, h/2, h/4 and random planes: Arrangement3 beside Nef.
void run_bench3(const BenchOptions& o, OutputFiles& files) {
  Report report;
  report.mode = "3d";
  report.input_name = "scene";
  report.size_names = {"halfsp", "in tri", "tri", "cells", "outer", "patches"};
  report.stage_names = {"arrange", "nef"};
  report.with_ratio = {0, 1};
  report.reference = 0;
  report.note_names = {"nef cells", "agree", "arr MB", "nef MB"};
  report.repeat = repeat_options(o);
  if (o.nef_max_triangles < 0) throw InputError("--nef-max-triangles: must be >= 0");
  const std::string label = std::filesystem::path(o.bsh_config).parent_path().filename().string();
  for (int divisor : o.h_divisors) {
    if (divisor < 1) throw InputError("--h-divisors: every divisor must be at least 1");
    const std::string name =
        (label.empty() ? std::string("bsh") : label) + (divisor == 1 ? " h" : " h/" + std::to_string(divisor));
    if (!std::filesystem::exists(o.bsh_config)) {
      BenchRow row;
      row.input = name;
      row.skipped = "no " + o.bsh_config + " (the BSH authors' data is not in this repository; --bsh-config PATH)";
      report.rows.push_back(row);
      continue;
    }
    report.rows.push_back(bench_scene3(name, bsh_scene_at(o.bsh_config, divisor), o, report.repeat));
  }
  for (int n : o.plane_counts) {
    if (n < 1) throw InputError("--planes: every count must be at least 1");
    RandomPlanesSettings settings;
    settings.planes = n;
    settings.max_coefficient = 50;  // general position is likely
    report.rows.push_back(bench_scene3(std::to_string(n) + " random planes", random_plane_scene3(settings, 1, 0), o,
                                       report.repeat));
  }
  report.footer = {
      "arrange: the exact arrangement and its complex, without volumes (Arrangement3Options::volumes = false); nef: "
      "CGAL's Nef_polyhedron_3 counting the same cells (geometry/nef3.hpp), skipped above --nef-max-triangles input "
      "triangles; in tri: input surface triangles (planes are clipped by the box); tri: refined triangles",
      "agree: Nef's cell and outer-cell counts equal the arrangement's; MB: peak resident memory of a process doing "
      "that computation once (kernel/timing.hpp, peak_memory_of)",
      "the BSH authors' floating-point arrangement of figure19_b at h takes about 1.8 s on the reference machine "
      "(issue 12, section 5)"};
  for (const BenchRow& row : report.rows)
    if (!row.phases.empty()) report.footer.push_back(row.phases);
  publish(report, o, files);
}

// ---- the BSH authors' examples end to end (issue 13, section 4) ----

/// The authors' own code measured on this machine (docs/bsh-3d.md): end to end K = 1 (their arrangement, sample
/// processing and graph cuts) and its search states.
struct AuthorsRun {
  const char* example;
  double seconds;
  long states;
};
constexpr AuthorsRun kAuthorsRuns[] = {{"figure19_b", 2.25, 21}};

/// One of the authors' example folders: the arrangement (reading, tessellating, arranging: load_input), the K = 1
/// beam on it, both end to end, the certified graph cut beside the double Boykov-Kolmogorov cut of the same
/// problem (all timed repeatedly); the complete search (exact) and best-first once each within --time-limit; the
/// peak memory of a process doing the arrangement, the K = 1 beam and the exact search once.
BenchRow bench_bsh_example(const std::string& folder, const BenchOptions& o, const RepeatOptions& repeat) {
  BenchRow row;
  const std::filesystem::path dir = std::filesystem::path(folder).lexically_normal();
  row.input = (dir.has_filename() ? dir : dir.parent_path()).filename().string();
  const std::string config = (dir / "config.json").string();
  if (!std::filesystem::is_regular_file(config)) {
    row.skipped = "no " + config + " (the BSH authors' data is not in this repository)";
    return row;
  }
  std::optional<LoadedInput> in;
  StageResult arrangement, search, end_to_end, certified, double_bk, exact, best_first;
  arrangement.timing = time_repeatedly([&] { in = load_input(config, o.limits); }, repeat);
  const bsh::Problem problem(in->complex());
  bsh::ExtractOptions beam;
  beam.method = bsh::Method::Beam;
  beam.beam_width = 1;
  bsh::ExtractResult beam_result;
  search.timing = time_repeatedly([&] { beam_result = bsh::extract(problem, beam); }, repeat);
  end_to_end.timing = time_repeatedly(
      [&] {
        const LoadedInput loaded = load_input(config, o.limits);
        bsh::extract(bsh::Problem(loaded.complex()), beam);
      },
      repeat);
  bsh::CutResult cut;
  certified.timing = time_repeatedly([&] { cut = bsh::graph_cut(problem, {}); }, repeat);
  double_bk.timing = time_repeatedly([&] { double_cut(problem, true); }, repeat);
  RepeatOptions once;
  once.min_repetitions = 1;
  once.min_seconds = 0;
  bsh::ExtractOptions complete;
  complete.method = bsh::Method::Exact;
  complete.time_limit = o.time_limit;
  bsh::ExtractResult exact_result, best_first_result;
  exact.timing = time_repeatedly([&] { exact_result = bsh::extract(problem, complete); }, once);
  complete.method = bsh::Method::BestFirst;
  best_first.timing = time_repeatedly([&] { best_first_result = bsh::extract(problem, complete); }, once);
  complete.method = bsh::Method::Exact;
  const auto peak = peak_memory_of([&] {
    const LoadedInput loaded = load_input(config, o.limits);
    const bsh::Problem p(loaded.complex());
    bsh::extract(p, beam);
    bsh::extract(p, complete);
  });
  row.sizes = {problem.cell_count(), static_cast<long>(in->complex().patches.size())};
  row.stages = {arrangement, search, end_to_end, certified, double_bk, exact, best_first};
  const auto verdict = [](const bsh::ExtractResult& r) {
    return r.optimal ? std::string("optimal") : "stopped: " + (r.stopped_by.empty() ? "unproven" : r.stopped_by);
  };
  std::string theirs = "-", versus = "-";
  for (const AuthorsRun& run : kAuthorsRuns)
    if (row.input == run.example) {
      theirs = printf_string("%.2f s", run.seconds) + ", " + std::to_string(run.states);
      versus = printf_string("%.2fx", end_to_end.timing->median / run.seconds);
    }
  row.notes = {std::to_string(beam_result.stats.states_expanded), theirs, versus, cut.certified ? "yes" : "no",
               verdict(exact_result), std::to_string(exact_result.stats.nodes),
               !exact_result.optimal                                                  ? "-"
               : bsh::compare(beam_result.energy, exact_result.energy) == Order::Equal ? "yes"
                                                                                       : "no",
               std::to_string(best_first_result.stats.states_expanded) + (best_first_result.optimal ? " (done)" : ""),
               megabytes(peak)};
  return row;
}

void run_bsh_example_bench(const BenchOptions& o, OutputFiles& files) {
  if (!std::isfinite(o.time_limit) || o.time_limit <= 0)  // best-first does not finish on figure19_b
    throw InputError("--time-limit: --bsh-example needs a positive number of seconds for its complete searches");
  Report report;
  report.mode = "bsh-examples";
  report.input_name = "example";
  report.size_names = {"cells", "patches"};
  report.stage_names = {"arrange", "K=1 search", "K=1 e2e", "cert. cut", "double BK", "exact", "best-first"};
  report.with_ratio = {0, 0, 0, 1, 0, 0, 0};
  report.reference = 4;
  report.note_names = {"K=1 states", "theirs e2e", "e2e/theirs", "cut cert.", "exact", "nodes",
                       "beam = opt", "bf states", "peak MB"};
  report.repeat = repeat_options(o);
  for (const std::string& folder : o.bsh_examples) report.rows.push_back(bench_bsh_example(folder, o, report.repeat));
  report.footer = {
      "arrange: reading config.json, tessellating, the exact arrangement and its complex (hsx's load_input); K=1 "
      "search: the beam of width 1 on it (bsh::extract); K=1 e2e: both together, the figure to set beside the "
      "authors' own end to end run (theirs e2e: seconds, states; measured on this machine, docs/bsh-3d.md); cert. "
      "cut: the certified graph cut of the problem, ratio to the double Boykov-Kolmogorov max flow of the same graph",
      "exact and best-first: the complete searches, run once each within --time-limit seconds (" +
          printf_string("%g", o.time_limit) + "); exact: its verdict, nodes: its branch-and-bound "
          "nodes; beam = opt: the K = 1 energy equals the exact one; bf states: states best-first expanded ((done): "
          "it proved its result optimal; the tie enumeration after it may still run into the limit)",
      "peak MB: peak resident memory of a child process doing the arrangement, the K = 1 beam and the exact search "
      "once (kernel/timing.hpp, peak_memory_of)"};
  publish(report, o, files);
}

// ---- campaign throughput (issue 15, section 4) ----

/// `scenes` scenes of `halfspaces` halfspaces (seed 1, every check, the CLI's default generator otherwise) run
/// through the campaign runner on 1 and on 2 threads, each run timed; the records of the two compared.
/// The shell command that runs this hsx's `campaign` on the scenes of a --campaign row as a process of its own:
/// `jobs` threads, under `mpirun -np 2` when `mpi` (each rank one thread), records into folder `out`.
/// mpirun's options: --oversubscribe (CI's machines may show fewer slots than cores), --allow-run-as-root (when
/// run as root, as CI does), and odls_base_sigkill_timeout 0: on exit status 3 (a check failed) Open MPI's mpirun
/// otherwise waits about 2 s before it returns, and pml ob1: both processes are on this machine, so Open MPI's
/// probing for network transports (UCX, OFI), 0.2 s of every start, is skipped (docs/campaigns-cluster.md).
std::string campaign_process_command(int halfspaces, const std::string& checks, const BenchOptions& o, int jobs,
                                     bool mpi, const std::string& out) {
  const auto quoted = [](const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  std::ostringstream command;
  if (mpi) {
    command << "mpirun -np 2 --oversubscribe --mca odls_base_sigkill_timeout 0 --mca pml ob1 ";
    if (geteuid() == 0) command << "--allow-run-as-root ";
  }
  command << quoted(std::filesystem::read_symlink("/proc/self/exe").string()) << " campaign --seed 1 --count "
          << o.campaign_scenes << " --halfspaces " << halfspaces << " --checks " << quoted(checks)
          << " --time-limit " << printf_string("%.17g", o.campaign_time_limit) << " --max-cells " << o.limits.max_cells
          << " --max-side-table " << o.limits.max_side_entries << " --max-states " << o.campaign_max_states << " --no-minimise --jobs " << jobs << " --out "
          << quoted(out) << " >/dev/null 2>&1";
  return command.str();
}

/// Runs `command` with /bin/sh; throws unless it exits with 0 or 3 (campaign: a check failed).
void run_campaign_process(const std::string& command) {
  const int status = std::system(command.c_str());
  if (status == -1 || !WIFEXITED(status) || (WEXITSTATUS(status) != 0 && WEXITSTATUS(status) != 3))
    throw std::runtime_error("bench --campaign-mpi: `" + command + "` failed (status " + std::to_string(status) + ")");
}

/// The lines of `path` (a campaign's results.jsonl).
std::vector<std::string> file_lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// --campaign-mpi: the row's scenes run by two processes, timed side by side (time_alternately: a round is one
/// run of each, so the machine's drift, which reaches a quarter within minutes here, falls on both alike):
/// `hsx campaign --jobs 2` and `mpirun -np 2 hsx campaign --jobs 1`, each run into a folder of its own; both stages
/// and, in `row.notes`, MPI's time over the threads' and whether both processes' last records are `reference`'s
/// bytes (the in-process run on one thread; not compared when a scene of it timed out).
void time_campaign_processes(int halfspaces, const std::string& checks, const BenchOptions& o,
                             const RepeatOptions& repeat, const std::vector<std::string>& reference, BenchRow& row) {
  const TemporaryFolder scratch("hsx-bench");
  std::string last_out[2];  // the folder of each command's latest run
  int runs_made = 0;
  std::vector<std::function<void()>> runs;
  for (bool mpi : {false, true})
    runs.push_back([&, mpi] {
      last_out[mpi] = scratch.file((mpi ? "mpi-" : "threads-") + std::to_string(runs_made++));
      run_campaign_process(campaign_process_command(halfspaces, checks, o, mpi ? 1 : 2, mpi, last_out[mpi]));
    });
  for (TimingSummary& timing : time_alternately(runs, repeat)) {
    StageResult stage;
    stage.timing = std::move(timing);
    row.stages.push_back(stage);
  }
  const double threads = row.stages[2].timing->median, mpi = row.stages[3].timing->median;
  row.notes.push_back(printf_string("%.3f", threads > 0 ? mpi / threads : 0));
  const bool timed_out = std::any_of(reference.begin(), reference.end(), [](const std::string& line) {
    return line.find("\"timed_out\":true") != std::string::npos;
  });
  const bool same = file_lines(last_out[0] + "/results.jsonl") == reference &&
                    file_lines(last_out[1] + "/results.jsonl") == reference;
  row.notes.push_back(timed_out ? "-" : same ? "yes" : "NO");
}

BenchRow bench_campaign(int halfspaces, const std::string& checks, const BenchOptions& o,
                        const RepeatOptions& repeat) {
  campaign::CampaignSettings settings;
  settings.scene.max_samples = 6;  // as `hsx campaign`
  settings.scene.min_halfspaces = settings.scene.max_halfspaces = halfspaces;
  settings.seed = 1;
  settings.time_limit = o.campaign_time_limit;
  settings.max_states = o.campaign_max_states;
  settings.limits = o.limits;
  settings.checks = campaign::parse_check_list(checks);
  campaign::validate(settings);
  std::vector<std::uint64_t> indices(static_cast<std::size_t>(o.campaign_scenes));
  for (std::size_t k = 0; k < indices.size(); ++k) indices[k] = k;
  BenchRow row;
  row.input = std::to_string(halfspaces) + " halfspaces, " +
              (checks == "all" ? std::string("all checks") : checks == kWithoutBestFirst ? "no 5.2/5.1" : checks);
  row.sizes = {halfspaces, o.campaign_scenes};
  std::vector<std::string> lines[2];
  for (int jobs : {1, 2}) {
    StageResult stage;
    stage.timing = time_repeatedly(
        [&] {
          std::vector<std::string>& out = lines[jobs - 1];
          out.clear();
          campaign::run_scenes(settings, indices, jobs,
                               [&](campaign::SceneRecord&& r) { out.push_back(record_to_json(r).dump()); });
        },
        repeat);
    row.stages.push_back(stage);
  }
  long timed_out[2] = {0, 0};  // in the last run of each: where a limit cut a scene, the records may differ
  for (int k : {0, 1})
    for (const std::string& line : lines[k]) timed_out[k] += line.find("\"timed_out\":true") != std::string::npos;
  const double one = row.stages[0].timing->median, two = row.stages[1].timing->median;
  row.notes = {printf_string("%.1f", one > 0 ? static_cast<double>(o.campaign_scenes) / one : 0),
               printf_string("%.2fx", two > 0 ? one / two : 0),
               std::to_string(timed_out[0]) + "/" + std::to_string(timed_out[1]),
               timed_out[0] + timed_out[1] ? "-" : lines[0] == lines[1] ? "yes" : "NO"};
  if (o.campaign_mpi) time_campaign_processes(halfspaces, checks, o, repeat, lines[0], row);
  return row;
}

void run_campaign_bench(const BenchOptions& o, OutputFiles& files) {
  if (o.campaign_scenes < 1) throw InputError("--campaign-scenes: at least 1");
  if (!std::isfinite(o.campaign_time_limit) || o.campaign_time_limit < 0)
    throw InputError("--campaign-time-limit: a finite number of seconds >= 0");
  if (o.campaign_checks.empty()) throw InputError("--campaign-checks: at least one check list");
  for (const std::string& checks : o.campaign_checks) (void)campaign::parse_check_list(checks);  // before timing
  Report report;
  report.mode = "campaign";
  report.input_name = "scenes";
  report.size_names = {"halfsp", "scenes"};
  report.stage_names = {"jobs 1", "jobs 2"};
  report.with_ratio = {0, 1};
  report.reference = 0;
  report.note_names = {"scenes/s", "speed-up", "timed out", "same"};
  if (o.campaign_mpi) {
    if (!built_with_mpi()) throw InputError("--campaign-mpi: this hsx was built without MPI (install libopenmpi-dev)");
    if (std::system("command -v mpirun >/dev/null 2>&1") != 0)
      throw InputError("--campaign-mpi: no mpirun on the PATH (install openmpi-bin)");
    report.stage_names.insert(report.stage_names.end(), {"proc jobs 2", "mpirun 2"});
    report.with_ratio.insert(report.with_ratio.end(), {1, 1});
    report.note_names.insert(report.note_names.end(), {"mpi/thread", "mpi same"});
  }
  report.repeat = repeat_options(o);
  for (int h : o.campaign_halfspaces) {
    if (h < 1) throw InputError("--campaign-halfspaces: every size must be at least 1");
    for (const std::string& checks : o.campaign_checks) report.rows.push_back(bench_campaign(h, checks, o, report.repeat));
  }
  report.footer = {
      "each run: the scenes 0..N-1 of seed 1 generated, arranged and given the row's checks (hsx campaign --checks: "
      "all, or \"no 5.2/5.1\" = every check but prop52 and prop51, whose complete best-first search dominates), "
      "at most --campaign-time-limit seconds per scene; scenes/s: on one thread (median run); speed-up: jobs 1 / "
      "jobs 2; timed out: scenes cut by the time limit in the last run of each (which ones depends on the machine's "
      "load); same: the two runs' records are the same bytes (compared when no scene timed out)",
      "issue 15's goals: >= 100 scenes/s per core at 8 halfspaces, >= 1.9x on 2 cores; MPI against threads is two "
      "processes: time `mpirun -np 2 hsx campaign ... --jobs 1` against `hsx campaign ... --jobs 2` "
      "(docs/campaigns-cluster.md); --campaign-mpi does so: proc jobs 2 and mpirun 2 are those two commands as "
      "processes (start-up included, --no-minimise), run alternately, mpi/thread the ratio of their medians, mpi "
      "same: both processes' records are jobs 1's bytes"};
  publish(report, o, files);
}

// ---- the 2D arrangement beside CGAL's bare insertion (issue 11, section 2) ----

/// Random 2D scene `index` of `halfspaces` halfspaces (seed 1, up to 3 samples per halfspace), the scenes of
/// --cuts, --arrange and --brute.
Scene2 bench_random_scene(int halfspaces, int index) {
  RandomSceneSettings settings;
  settings.min_halfspaces = settings.max_halfspaces = halfspaces;
  settings.max_samples = 3;
  return random_scene(settings, 1, static_cast<std::uint64_t>(index)).scene;
}

/// One scene: hsx::arrange (arrangement and complex) and bare_cgal_arrangement_faces, timed alternately.
BenchRow bench_arrange_scene(const std::string& name, const Scene2& scene, const BenchOptions& o,
                             const RepeatOptions& repeat) {
  BenchRow row;
  row.input = name;
  Arranged2 arranged;
  try {
    arranged = arrange(scene, o.limits);
  } catch (const InputError& e) {
    row.skipped = e.what();
    return row;
  }
  row.sizes = {static_cast<long>(scene.halfspaces.size()), static_cast<long>(arranged.complex.cells.size()),
               static_cast<long>(arranged.arrangement.edges().size())};
  long faces = 0;
  const auto timings =
      time_alternately({[&] { arrange(scene, o.limits); }, [&] { faces = bare_cgal_arrangement_faces(scene); }}, repeat);
  row.stages = stages_of(timings);
  row.notes = {faces == static_cast<long>(arranged.complex.cells.size()) ? "yes" : "NO"};
  return row;
}

/// Arrangement mode: hsx::arrange beside CGAL's bare Arrangement_2 insertion of the same curves, on random scenes
/// of several sizes and on given 2D scene files; the ratio is hsx's median over CGAL's.
void run_arrange_bench(const BenchOptions& o, OutputFiles& files) {
  check_random_scenes("--arrange", o.arrange_scenes, o.arrange_halfspaces, &o.arrange_inputs);
  Report report;
  report.mode = "arrange";
  report.input_name = "scene";
  report.size_names = {"halfsp", "cells", "edges"};
  report.stage_names = {"hsx arrange", "bare CGAL"};
  report.with_ratio = {1, 0};
  report.reference = 1;
  report.note_names = {"same cells"};
  report.repeat = repeat_options(o);
  for (int h : o.arrange_halfspaces)
    for (int k = 0; k < o.arrange_scenes; ++k)
      report.rows.push_back(bench_arrange_scene("random " + std::to_string(h) + " #" + std::to_string(k),
                                                bench_random_scene(h, k), o, report.repeat));
  for (const std::string& path : o.arrange_inputs) {
    const LoadedInput in = load_input(path, o.limits);  // bad input: exit 2, as everywhere
    if (!in.scene) throw InputError(path + ": --arrange-inputs needs 2D scene files");
    report.rows.push_back(bench_arrange_scene(path, *in.scene, o, report.repeat));
  }
  report.footer = {
      "hsx arrange: hsx::arrange (geometry/arrangement2.hpp and complex/from_arrangement2.hpp: CGAL's insertion "
      "with a size guard, then vertices, edges, faces, sides (from face 0's interior point), samples located, the "
      "complex; exact lengths, areas and the other interior points are computed on first read, not here); bare "
      "CGAL: bare_cgal_arrangement_faces, the same curves inserted into the same CGAL arrangement and nothing else; "
      "same cells: both count the same bounded faces",
      "random scenes: seed 1, up to 3 samples per halfspace (halfsp: halfspaces); the two stages alternate "
      "(rounds of one run of each), so a change of load falls on both"};
  publish(report, o, files);
}

// ---- the brute-force oracle's rate (issue 11, section 2) ----

/// Random scene `index` of `halfspaces` halfspaces: brute_force (with sample-connectedness), timed repeatedly;
/// notes: the labellings it enumerates, their rate (over the median run) and the tie count.
BenchRow bench_brute_scene(int halfspaces, int index, const BenchOptions& o, const RepeatOptions& repeat) {
  BenchRow row;
  row.input = "random " + std::to_string(halfspaces) + " #" + std::to_string(index);
  Arranged2 arranged;
  try {
    arranged = arrange(bench_random_scene(halfspaces, index), o.limits);
  } catch (const InputError& e) {
    row.skipped = e.what();
    return row;
  }
  const bsh::Problem problem(arranged.complex);
  row.sizes = {halfspaces, problem.cell_count()};
  bsh::BruteForceOptions options;
  options.limit = o.brute_force_limit;
  options.time_limit = o.time_limit;
  bsh::BruteForceResult result;
  StageResult stage;
  try {
    stage.timing = time_repeatedly([&] { result = bsh::brute_force(problem, true, options); }, repeat);
  } catch (const bsh::LabellingLimitExceeded&) {
    stage.status = "too large";
  }
  row.stages = {stage};
  if (!stage.timing || result.stopped) {
    if (result.stopped) row.stages[0].status = "stopped";
    row.notes = {"-", "-", "-"};
    return row;
  }
  row.notes = {std::to_string(result.enumerated),
               printf_string("%.3g", static_cast<double>(result.enumerated) / stage.timing->median),
               std::to_string(result.optimal.size())};
  return row;
}

/// Brute-force mode: the oracle's labellings per second on random scenes of several sizes.
void run_brute_bench(const BenchOptions& o, OutputFiles& files) {
  check_random_scenes("--brute", o.brute_scenes, o.brute_halfspaces, nullptr);
  Report report;
  report.mode = "brute-force";
  report.input_name = "scene";
  report.size_names = {"halfsp", "cells"};
  report.stage_names = {"brute force"};
  report.with_ratio = {0};
  report.note_names = {"labellings", "per second", "optima"};
  report.repeat = repeat_options(o);
  for (int h : o.brute_halfspaces)
    for (int k = 0; k < o.brute_scenes; ++k) report.rows.push_back(bench_brute_scene(h, k, o, report.repeat));
  report.footer = {"brute force: bsh::brute_force with sample-connectedness (hsx extract --method brute-force), "
                   "refusing above --brute-force-limit labellings; per second: labellings enumerated over the median "
                   "run; optima: the least-energy labellings (ties); random scenes: seed 1, up to 3 samples per "
                   "halfspace (halfsp: halfspaces)"};
  publish(report, o, files);
}

/// --arrange and the options only it takes.
std::vector<CLI::Option*> add_arrange_bench_options(CLI::App* cmd, BenchOptions& o) {
  cmd->add_flag("--arrange", o.arrange,
                "time hsx's 2D arrangement (with its complex) beside CGAL's bare Arrangement_2 insertion of the same "
                "curves on random scenes, instead");
  return {cmd->add_option("--arrange-halfspaces", o.arrange_halfspaces,
                          "--arrange: the random scenes' sizes (default 4,16,32,64,128)")
              ->delimiter(','),
          cmd->add_option("--arrange-scenes", o.arrange_scenes,
                          "--arrange: random scenes per size (default 1; 0 with --arrange-inputs)"),
          cmd->add_option("--arrange-inputs", o.arrange_inputs,
                          "--arrange: also these 2D scene files, after the random scenes")
              ->check(CLI::ExistingFile)};
}

/// --brute and the options only it takes.
std::vector<CLI::Option*> add_brute_bench_options(CLI::App* cmd, BenchOptions& o) {
  cmd->add_flag("--brute", o.brute,
                "time the brute-force oracle on random scenes and report its labellings per second, instead");
  return {cmd->add_option("--brute-halfspaces", o.brute_halfspaces,
                          "--brute: the random scenes' sizes (default 8,10,12,14)")
              ->delimiter(','),
          cmd->add_option("--brute-scenes", o.brute_scenes, "--brute: random scenes per size (default 3)")};
}

/// Refuses the --arrange and --brute options without their mode, and the scene-folder options with them.
void check_arrange_and_brute_options(const BenchOptions& o, const std::vector<CLI::Option*>& scene_options,
                                     const std::vector<CLI::Option*>& only_arrange,
                                     const std::vector<CLI::Option*>& only_brute) {
  for (CLI::Option* option : only_arrange)
    if (!o.arrange && option->count() > 0) throw InputError("bench: " + option->get_name() + " needs --arrange");
  for (CLI::Option* option : only_brute)
    if (!o.brute && option->count() > 0) throw InputError("bench: " + option->get_name() + " needs --brute");
  for (CLI::Option* option : scene_options) {
    if (option->count() == 0) continue;
    const bool brute_takes = option->get_name() != scene_options.front()->get_name();  // the limits, not DIRS
    if (o.arrange || (o.brute && !brute_takes))
      throw InputError("bench: " + option->get_name() + " does not apply to " + (o.arrange ? "--arrange" : "--brute"));
  }
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Time every BSH method on every scene of the given folders, repeatedly, side by side in one run");
  CLI::Option* dirs = cmd->add_option("DIRS", o->dirs, "folders of scenes (default data/scenes data/figures)");
  CLI::Option* brute_force =
      cmd->add_option("--brute-force-limit", o->brute_force_limit, "skip the oracle above this many labellings");
  CLI::Option* time_limit =
      cmd->add_option("--time-limit", o->time_limit, "seconds per search before it stops (default 60)")
          ->check(seconds());
  cmd->add_option("--repetitions", o->repetitions, "run each measurement at least N times (default 5)");
  cmd->add_option("--min-time", o->min_time,
                  "and repeat it until the runs add up to S seconds (default 0.2; 0: exactly --repetitions runs)")
      ->check(seconds());
  cmd->add_option("--csv", o->csv_path, "also write every measurement as CSV (one line per input and stage)")
      ->check(output_path());
  cmd->add_option("--json", o->json_path, "also write every measurement as hsx-bench/1 JSON, with each run's time")
      ->check(output_path());
  cmd->add_option("--meshes", o->meshes,
                  "time NH-Rep's stages on these .obj files (each with its .fea) instead of the BSH methods");
  cmd->add_flag("--cuts", o->cuts,
               "time the certified graph cut beside double Boykov-Kolmogorov and Edmonds-Karp max flows on random "
               "scenes instead");
  cmd->add_option("--cut-halfspaces", o->cut_halfspaces, "--cuts: the scenes' sizes (default 10 50 100 200)");
  cmd->add_option("--cut-scenes", o->cut_scenes, "--cuts: random scenes per size (default 1; 0 with --cut-inputs)");
  cmd->add_option("--cut-inputs", o->cut_inputs,
                  "--cuts: also time the cut of these inputs (2D or 3D scenes, the BSH authors' config.json, "
                  "hsx-complex/1), after the random scenes (--cut-scenes 0: only these)")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--3d", o->three_d,
               "time the exact 3D arrangement beside CGAL's Nef polyhedra on the BSH authors' figure19_b (at h, h/2, "
               "h/4) and on random planes, instead of the BSH methods");
  const std::vector<CLI::Option*> only_3d = {
      cmd->add_option("--bsh-config", o->bsh_config,
                      "--3d: the BSH authors' config.json (default " + o->bsh_config +
                          "; a missing file skips its rows)"),
      cmd->add_option("--h-divisors", o->h_divisors, "--3d: tessellate that scene at h/k for each k (default 1 2 4)")
          ->delimiter(','),
      cmd->add_option("--planes", o->plane_counts, "--3d: random plane scenes of these sizes (default 10 20 30 40 50)")
          ->delimiter(','),
      cmd->add_option("--nef-max-triangles", o->nef_max_triangles,
                      "--3d: skip Nef above this many input triangles (default 20000; 0: never skip)"),
      cmd->add_option("--threads", o->threads, "--3d: worker threads of the arrangement (default 0: all cores)")
          ->check(non_negative()),
      cmd->add_flag("--phases", o->phases,
                    "--3d: also report the median time of each phase of the arrangement (and of its complex)")};
  const std::vector<CLI::Option*> only_campaign = {
      cmd->add_option("--campaign-halfspaces", o->campaign_halfspaces,
                      "--campaign: one row per scene size (default 4,8)")
          ->delimiter(','),
      cmd->add_option("--campaign-scenes", o->campaign_scenes, "--campaign: scenes per run (default 40)"),
      cmd->add_option("--campaign-checks", o->campaign_checks,
                      "--campaign: one row per check list and size, each as hsx campaign --checks (default: all, "
                      "and every check but prop52 and prop51)"),
      cmd->add_option("--campaign-time-limit", o->campaign_time_limit,
                      "--campaign: seconds per scene (default 2; 0: none)")
          ->check(seconds()),
      cmd->add_option("--campaign-max-states", o->campaign_max_states,
                      "--campaign: each search stops after N states (hsx campaign --max-states; default 0: no limit). "
                      "With --campaign-time-limit 0 the runs are deterministic and their records compared")
          ->check(non_negative()),
      cmd->add_flag("--campaign-mpi", o->campaign_mpi,
                    "--campaign: also time `hsx campaign --jobs 2` and `mpirun -np 2 hsx campaign --jobs 1` as "
                    "processes, side by side (needs MPI)")};
  cmd->add_option("--bsh-example", o->bsh_examples,
                  "time the BSH authors' example folders end to end (arrangement, K = 1 beam, the certified and the "
                  "double graph cut, the complete searches within --time-limit, peak memory) beside their own "
                  "figures, instead (a folder without config.json is reported as skipped)");
  cmd->add_flag("--campaign", o->campaign,
                "time hsx campaign's runner (every check) on 1 and 2 threads, scenes per second, instead");
  cmd->add_flag("--exact", o->exact,
                "time --method exact on random 2D scenes of each size (1 to 3 samples per halfspace), best-first "
                "beside it on the small ones, and summarise each size (issue 11's goals), instead");
  const std::vector<CLI::Option*> only_exact = {
      cmd->add_option("--exact-halfspaces", o->exact_halfspaces,
                      "--exact: the scenes' sizes (default 8,10,12,16,20,24,30)")
          ->delimiter(','),
      cmd->add_option("--exact-scenes", o->exact_scenes, "--exact: random scenes per size (default 20)"),
      cmd->add_option("--exact-best-first-up-to", o->exact_best_first_up_to,
                      "--exact: run best-first too on scenes of at most this many halfspaces (default 12; 0: never)")};
  const std::vector<CLI::Option*> only_arrange = add_arrange_bench_options(cmd, *o);
  const std::vector<CLI::Option*> only_brute = add_brute_bench_options(cmd, *o);
  add_arrangement_limits(cmd, o->limits);
  cmd->callback([o, dirs, brute_force, time_limit, only_3d, only_campaign, only_exact, only_arrange, only_brute] {
    check_arrange_and_brute_options(*o, {dirs, brute_force, time_limit}, only_arrange, only_brute);
    for (CLI::Option* option : only_exact)
      if (!o->exact && option->count() > 0) throw InputError("bench: " + option->get_name() + " needs --exact");
    if (o->exact)
      for (CLI::Option* option : {dirs, brute_force})
        if (option->count() > 0) throw InputError("bench: " + option->get_name() + " does not apply to --exact");
    for (CLI::Option* option : only_campaign)
      if (!o->campaign && option->count() > 0) throw InputError("bench: " + option->get_name() + " needs --campaign");
    for (CLI::Option* option : only_3d)
      if (!o->three_d && option->count() > 0) throw InputError("bench: " + option->get_name() + " needs --3d");
    for (CLI::Option* option : {dirs, brute_force, time_limit})
      if (o->three_d && option->count() > 0)
        throw InputError("bench: " + option->get_name() + " does not apply to --3d");
    OutputFiles files;  // checked before the measurements, written at the end
    files.expect(o->csv_path, "--csv");
    files.expect(o->json_path, "--json");
    const bool examples = !o->bsh_examples.empty();
    if (int(o->cuts) + int(o->three_d) + int(!o->meshes.empty()) + int(o->campaign) + int(examples) +
            int(o->arrange) + int(o->brute) + int(o->exact) > 1)
      throw InputError(
          "bench: --cuts, --3d, --meshes, --campaign, --bsh-example, --exact, --arrange and --brute exclude each other");
    if (examples)
      for (CLI::Option* option : {dirs, brute_force})
        if (option->count() > 0) throw InputError("bench: " + option->get_name() + " does not apply to --bsh-example");
    if (o->campaign)
      for (CLI::Option* option : {dirs, brute_force, time_limit})
        if (option->count() > 0) throw InputError("bench: " + option->get_name() + " does not apply to --campaign");
    if (!o->cuts && !o->cut_inputs.empty()) throw InputError("bench: --cut-inputs needs --cuts");
    if (o->exact)
      run_exact_bench(*o, files);
    else if (o->arrange)
      run_arrange_bench(*o, files);
    else if (o->brute)
      run_brute_bench(*o, files);
    else if (examples)
      run_bsh_example_bench(*o, files);
    else if (o->campaign)
      run_campaign_bench(*o, files);
    else if (o->cuts)
      run_cut_bench(*o, files);
    else if (o->three_d)
      run_bench3(*o, files);
    else if (o->meshes.empty())
      run_bench(*o, files);
    else
      run_nhrep_bench(*o, files);
  });
}

}  // namespace hsx::cli
