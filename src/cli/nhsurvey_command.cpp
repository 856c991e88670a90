// hsx nhsurvey: NH-Rep Boolean trees with natural halfspaces over many 2D solids (issue 5, cross-check 2) or random
// 3D solids (issue 14, --dimension 3).
//
// Options, sources and printing only: the survey of one solid and the tallies are algorithms/nhrep/survey.hpp
// (boundary_from_arrangement2 -> build_patch_graph -> build_tree -> check_tree -> evaluate_tree, classified as
// "tree correct", "describable but the tree fails" or "not describable by its patches' halfspaces"), the random
// solids algorithms/csg/random_solid.hpp, the kept examples io/nhrep_survey.hpp.
//
// Sources:
// - `--random N --seed S`: solid i is csg::random_solid(settings, kind, S, i) (reproducible alone, on every
//   machine; the procedure is in random_solid.hpp): even i a random CSG expression over 2-4 primitives, odd i a
//   random set of inner cells of their arrangement. `--random-mode csg|cells|mixed` picks the kinds,
//   `--random-polygons` makes boxes and triangles polygon halfspaces (one patch per polygon, see evaluate.hpp)
//   instead of half-planes.
// - `SCENE...` (files or directories of hsx-scene/1 files; other JSON files in a directory are skipped): the BSH
//   shape extracted as `hsx extract` does, by each method of `--methods` (graphcut, best-first; best-first stops
//   after `--max-states` expanded states, and then uses its best shape so far).
// - `--dimension 3 --random N --seed S`: solid i is csg::random_solid3 (random_solid3.hpp; even i a random CSG
//   expression over 2 to `--max-primitives` boxes, spheres, cylinders and planes, odd i hollow; `--random-mode
//   csg|hollow|mixed`, `--segments`), surveyed by nhrep::survey_solid3 on its own arrangement (a domain chosen by
//   hsx holds every vertex; --keep writes that domain out). Scenes and CSGNet are 2D only.
// - `--csgnet FILE [--from K] [--limit N]`: CSGNet programs, as `hsx corpus csgnet` reads them (malformed lines are
//   skipped and counted; a missing file is reported as skipped).
//
// Whole-plane evaluation (survey.hpp): each solid is moved to the arrangement of its scene (samples dropped) in a
// domain that contains the scene's own domain and the domain hsx would choose (complex/carry_solid2.hpp's whole_plane_scene);
// BSH shapes are carried over by exact point location of cell witnesses (carry_to_whole_plane).
//
// Output: a table per source (counts and rates), then the first `--keep-count` "describable but fails" examples of
// each source; with `--keep DIR` each is written as DIR/<name>.json (the scene used, its description the note)
// and DIR/<name>.csg (the solid as {"description", "csg"}, readable by --csg): the source's own expression, or
// for BSH shapes and cell sets BHC's verified tree (falling back to the union of the solid's canonical terms over
// its natural halfspaces). The table also counts, per source, the describable-but-fails solids with a hole, and
// (for scenes with their own domain) the verdicts that change when evaluated on that domain instead.
// Exit status: 0 when every structural check holds (check_tree, the evaluation's consistency, no pipeline error),
// 3 when one fails, 2 for bad input. Output is deterministic; `--timings` adds seconds.
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/csg/random_solid.hpp>
#include <hsx/algorithms/csg/random_solid3.hpp>
#include <hsx/algorithms/nhrep/survey.hpp>
#include "cli/commands.hpp"
#include <hsx/complex/carry_solid2.hpp>
#include <hsx/complex/boundary_from_arrangement2.hpp>
#include <hsx/io/csgnet.hpp>
#include <hsx/io/exact_json.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/nhrep_survey.hpp>
#include <hsx/io/scene_json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace hsx::cli {
namespace {

constexpr int kCheckFailed = 3;

struct SurveyOptions {
  long random = 0;
  std::uint64_t seed = 1;
  std::string random_mode = "mixed";
  bool random_polygons = false;
  std::vector<std::string> scenes;
  std::string methods = "graphcut,best-first";
  long max_states = 20000;
  std::string csgnet;
  long from = 1;
  long limit = 0;
  std::string keep_dir;
  int keep_count = 3;
  bool timings = false;
  bool verbose = false;
  bool nest_holes = false;
  int dimension = 2;
  int segments = 8;          ///< 3D: segments per circle
  int max_primitives = 4;    ///< 3D: primitives per solid, 2..this (1 when this is 1)
};

using nhrep::SurveySolid;
using nhrep::SurveyTally;

/// Surveys solids and prints what the table does not show (failed checks, -v lines), keeping examples.
class Survey {
 public:
  explicit Survey(const SurveyOptions& o) : opt_(o) { build_.nest_holes = o.nest_holes; }

  /// Runs one solid of `tally`'s source.
  void add(SurveyTally& tally, const SurveySolid& c) {
    const nhrep::SurveyOutcome o = nhrep::survey_solid(c, build_);
    const bool example = tally.add(c, o);
    if (o.status != csg::SolidStatus::Bounded) return;
    if (!o.problems.empty()) {
      ++failures_;
      std::cout << "CHECK FAILED " << c.name << " (" << c.origin << "):\n";
      for (std::size_t i = 0; i < o.problems.size() && i < 5; ++i) std::cout << "  " << o.problems[i] << "\n";
    }
    if (!o.whole.evaluated) return;
    if (o.own_differs && opt_.verbose)
      std::cout << c.name << ": on the scene's own domain: " << nhrep::verdict_name(o.own->eval.verdict) << "\n";
    if (opt_.verbose)
      std::cout << c.name << ": " << nhrep::verdict_name(o.whole.eval.verdict) << "; "
                << o.whole.built.graph.live_patches().size() << " patches, " << o.whole.built.decompositions.size()
                << " decompositions, " << o.whole.eval.wrong_inside.size() + o.whole.eval.wrong_outside.size()
                << " of " << c.arranged.complex.cells.size() << " cells wrong\n";
    if (example && !opt_.keep_dir.empty()) write_survey_example(opt_.keep_dir, c, o);
  }

  /// Runs one 3D solid.
  void add3(SurveyTally& tally, const nhrep::SurveySolid3& c) {
    const nhrep::SurveyOutcome o = nhrep::survey_solid3(c, build_);
    const bool example = tally.add(c.name + " (" + c.origin + ")", c.arranged.complex.cells.size(), o);
    if (o.status != csg::SolidStatus::Bounded) return;
    if (!o.problems.empty()) {
      ++failures_;
      std::cout << "CHECK FAILED " << c.name << " (" << c.origin << "):\n";
      for (std::size_t i = 0; i < o.problems.size() && i < 5; ++i) std::cout << "  " << o.problems[i] << "\n";
    }
    if (o.whole.evaluated && opt_.verbose)
      std::cout << c.name << ": " << nhrep::verdict_name(o.whole.eval.verdict) << "; "
                << o.whole.built.graph.live_patches().size() << " patches, " << o.whole.built.decompositions.size()
                << " decompositions, " << o.holes << " cavities, "
                << o.whole.eval.wrong_inside.size() + o.whole.eval.wrong_outside.size() << " of "
                << c.arranged.complex.cells.size() << " cells wrong; " << csg::to_text(*c.expression, c.arranged.complex.halfspace_names)
                << "\n";
    if (example && !opt_.keep_dir.empty()) write_survey_example(opt_.keep_dir, c, o);
  }

  long failures() const { return failures_; }

 private:
  const SurveyOptions& opt_;
  nhrep::BuildOptions build_;
  long failures_ = 0;
};

// ---- sources --------------------------------------------------------------------------------------------------------

/// Random solid `index` (algorithms/csg/random_solid.hpp).
SurveySolid random_case(const SurveyOptions& o, long index, bool cells, int* redraws) {
  csg::RandomSolidSettings settings;
  settings.polygons = o.random_polygons;
  csg::RandomSolid r = csg::random_solid(settings, cells ? csg::RandomSolidKind::Cells : csg::RandomSolidKind::Csg,
                                         o.seed, static_cast<std::uint64_t>(index));
  *redraws += r.draws - 1;
  SurveySolid c;
  c.name = std::string(cells ? "random-cells-" : "random-csg-") + std::to_string(index);
  c.origin = "random solid " + std::to_string(index) + " of --seed " + std::to_string(o.seed) + ", " +
             (cells ? "a random set of cells" : "a random CSG expression") +
             (o.random_polygons ? ", --random-polygons" : "") +
             (r.draws > 1 ? ", draw " + std::to_string(r.draws) : "");
  c.scene = std::move(r.scene);
  c.scene.description = c.origin;
  c.arranged = std::move(r.arranged);
  c.solid = std::move(r.solid);
  c.expression = r.expression;
  return c;
}

void print_table(const std::vector<SurveyTally>& tallies, bool timings);

/// Random 3D solid `index` (algorithms/csg/random_solid3.hpp): hollow or not by --random-mode.
nhrep::SurveySolid3 random_case3(const SurveyOptions& o, long index, bool hollow, int* redraws) {
  csg::RandomSolid3Settings settings;
  settings.hollow = hollow;
  settings.segments = o.segments;
  settings.max_primitives = o.max_primitives;
  settings.min_primitives = std::min(2, o.max_primitives);
  csg::RandomSolid3 r = csg::random_solid3(settings, o.seed, static_cast<std::uint64_t>(index));
  *redraws += r.draws - 1;
  nhrep::SurveySolid3 c;
  c.name = std::string(hollow ? "random3-hollow-" : "random3-csg-") + std::to_string(index);
  c.origin = "random 3D solid " + std::to_string(index) + " of --seed " + std::to_string(o.seed) +
             (hollow ? ", hollow" : "") + (r.draws > 1 ? ", draw " + std::to_string(r.draws) : "");
  c.scene = std::move(r.scene);
  c.arranged = std::move(r.arranged);
  c.solid = std::move(r.solid);
  c.expression = r.expression;
  return c;
}

/// --keep DIR: an existing folder, or a new one whose parent exists (a mistyped path must not create a chain of
/// folders); not the folder of one of the run's inputs (`o`'s scenes and --csgnet), since examples are written
/// there as the run goes, under names an input may have.
void check_keep_directory(const SurveyOptions& o) {
  const std::string& dir = o.keep_dir;
  if (dir.empty()) return;
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path path(dir);
  if (fs::exists(path, ec)) {
    if (!fs::is_directory(path, ec)) throw InputError("--keep: " + dir + " exists and is not a folder");
    std::vector<std::string> inputs = o.scenes;
    if (!o.csgnet.empty()) inputs.push_back(o.csgnet);
    for (const std::string& input : inputs) {
      const fs::path folder = fs::path(input).has_parent_path() ? fs::path(input).parent_path() : fs::path(".");
      if (input != "-" && fs::equivalent(folder, path, ec))
        throw InputError("--keep: " + dir + " holds the input " + input +
                         "; examples are written there as the run goes: give a folder of their own");
    }
    return;
  }
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec))
    throw InputError("--keep: the folder " + parent.string() + " (where " + dir + " would be made) does not exist");
}

/// With --keep DIR: how many examples were written there.
void print_kept(const std::vector<SurveyTally>& tallies, const std::string& keep_dir) {
  if (keep_dir.empty()) return;
  long kept = 0;
  for (const SurveyTally& t : tallies) kept += static_cast<long>(t.examples.size());
  std::cout << "kept " << kept << " example(s) in " << keep_dir << "\n";
}

/// --dimension 3: random 3D CSG solids only.
int run_survey3(const SurveyOptions& o) {
  if (o.random_mode != "mixed" && o.random_mode != "csg" && o.random_mode != "hollow")
    throw InputError("--random-mode: in 3D csg, hollow or mixed, got \"" + o.random_mode + "\"");
  if (!o.scenes.empty() || !o.csgnet.empty())
    throw InputError("--dimension 3 surveys random solids only (--random N); scenes and --csgnet are 2D");
  if (o.random <= 0) throw InputError("--dimension 3: give --random N");
  if (o.keep_count < 0) throw InputError("--keep-count: must be >= 0");
  check_keep_directory(o);
  if (o.segments < 6 || o.segments > 64) throw InputError("--segments: 6 to 64");
  if (o.max_primitives < 1 || o.max_primitives > csg::kMaxRandomPrimitives3)
    throw InputError("--max-primitives: 1 to " + std::to_string(csg::kMaxRandomPrimitives3) + ", got " +
                     std::to_string(o.max_primitives));
  Survey survey(o);
  SurveyTally csg_tally{"random3 csg", o.keep_count}, hollow_tally{"random3 hollow", o.keep_count};
  using Clock = std::chrono::steady_clock;
  int redraws = 0;
  double csg_seconds = 0, hollow_seconds = 0;
  for (long i = 0; i < o.random; ++i) {
    const bool hollow = o.random_mode == "hollow" || (o.random_mode == "mixed" && i % 2 == 1);
    const auto start = Clock::now();
    const nhrep::SurveySolid3 c = random_case3(o, i, hollow, &redraws);
    survey.add3(hollow ? hollow_tally : csg_tally, c);
    (hollow ? hollow_seconds : csg_seconds) += std::chrono::duration<double>(Clock::now() - start).count();
  }
  csg_tally.seconds = csg_seconds;
  hollow_tally.seconds = hollow_seconds;
  std::vector<SurveyTally> tallies;
  if (o.random_mode != "hollow") tallies.push_back(csg_tally);
  if (o.random_mode != "csg") tallies.push_back(hollow_tally);
  std::cout << "random: " << o.random << " 3D solids from --seed " << o.seed << " (boxes, spheres, cylinders, planes; "
            << std::min(2, o.max_primitives) << "-" << o.max_primitives << " primitives, " << o.segments << " segments; " << redraws
            << " empty or unbounded draws redrawn)" << (o.nest_holes ? "; cavities nested" : "") << "\n";
  print_table(tallies, o.timings);
  print_kept(tallies, o.keep_dir);
  if (o.timings)
    std::cout << "rate: " << std::fixed << std::setprecision(2)
              << static_cast<double>(o.random) / std::max(1e-9, csg_seconds + hollow_seconds) << " solids/s\n";
  if (survey.failures() > 0) {
    std::cout << "STRUCTURAL CHECKS FAILED on " << survey.failures() << " solid(s)\n";
    return kCheckFailed;
  }
  std::cout << "all structural checks hold\n";
  return 0;
}

bool is_scene_file(const std::filesystem::path& path) {
  try {
    const nlohmann::json doc = read_exact_json_file(path.string());
    return doc.is_object() && doc.contains("format") && doc.at("format") == "hsx-scene/1";
  } catch (const InputError&) {
    return false;
  }
}

/// Scene files from the arguments: files as given (they must be scenes), directories' *.json scenes, sorted.
std::vector<std::string> scene_files(const std::vector<std::string>& args, long* skipped) {
  std::vector<std::string> files;
  for (const std::string& arg : args) {
    const std::filesystem::path path(arg);
    if (std::filesystem::is_directory(path)) {
      std::vector<std::string> here;
      for (const auto& entry : std::filesystem::directory_iterator(path))
        if (entry.path().extension() == ".json") {
          if (is_scene_file(entry.path()))
            here.push_back(entry.path().string());
          else
            ++*skipped;
        }
      std::sort(here.begin(), here.end());
      files.insert(files.end(), here.begin(), here.end());
    } else if (std::filesystem::is_regular_file(path)) {
      files.push_back(arg);
    } else {
      throw InputError(arg + ": no such file or directory");
    }
  }
  return files;
}

std::string file_stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

std::string percent(long part, long whole) {
  if (whole == 0) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << 100.0 * static_cast<double>(part) / static_cast<double>(whole) << "%";
  return s.str();
}

void print_table(const std::vector<SurveyTally>& tallies, bool timings) {
  std::ostringstream out;
  auto cell = [&](long n, long whole) { return std::to_string(n) + " (" + percent(n, whole) + ")"; };
  out << std::left << std::setw(16) << "source" << std::right << std::setw(7) << "solids" << std::setw(8) << "skipped"
      << std::setw(11) << "check-fail" << std::setw(14) << "decomposed" << std::setw(15) << "tree correct"
      << std::setw(19) << "describable-fails" << std::setw(12) << "(holes)" << std::setw(16) << "not describable"
      << std::setw(13) << "own-domain";
  if (timings) out << std::setw(9) << "seconds";
  out << "\n";
  for (const SurveyTally& t : tallies) {
    out << std::left << std::setw(16) << t.source << std::right;
    if (!t.note.empty()) {
      out << "  " << t.note << "\n";
      continue;
    }
    out << std::setw(7) << t.solids << std::setw(8) << t.empty + t.unbounded + t.malformed << std::setw(11)
        << t.check_failures << std::setw(14) << cell(t.decomposed, t.solids) << std::setw(15)
        << cell(t.correct, t.solids) << std::setw(19) << cell(t.describable_fails, t.solids) << std::setw(12)
        << t.fails_with_holes << std::setw(16) << cell(t.not_describable, t.solids) << std::setw(13)
        << (t.own_domain_runs ? std::to_string(t.own_domain_differs) + "/" + std::to_string(t.own_domain_runs)
                              : std::string("-"));
    if (timings) out << std::setw(9) << std::fixed << std::setprecision(2) << t.seconds;
    out << "\n";
  }
  out << "skipped: empty or unbounded solids and malformed programs; decomposed: trees that needed a patch "
         "decomposition;\n(holes): describable-fails solids with a hole; own-domain: verdicts that change when "
         "evaluated on the scene's own domain instead of the whole plane\n";
  for (const SurveyTally& t : tallies) {
    if (!t.note.empty()) continue;
    out << t.source << ": " << t.patches << " patches, " << t.cells << " cells, " << t.decompositions
        << " decompositions in all";
    if (t.empty + t.unbounded + t.malformed > 0)
      out << "; skipped " << t.empty << " empty, " << t.unbounded << " unbounded, " << t.malformed << " malformed";
    out << "\n";
    if (t.with_holes > 0)
      out << "  with a hole or cavity: " << t.with_holes << " solids: " << t.correct_with_holes << " tree correct, "
          << t.with_holes - t.correct_with_holes - t.not_describable_with_holes << " describable but fails, "
          << t.not_describable_with_holes << " not describable\n";
    for (const std::string& e : t.examples) out << "  describable but fails: " << e << "\n";
  }
  std::cout << out.str();
}

int run_survey(const SurveyOptions& o) {
  if (o.random < 0) throw InputError("--random: must be >= 0");
  if (o.dimension != 2 && o.dimension != 3) throw InputError("--dimension: 2 or 3");
  if (o.dimension == 3) return run_survey3(o);
  if (o.random_mode != "mixed" && o.random_mode != "csg" && o.random_mode != "cells")
    throw InputError("--random-mode: csg, cells or mixed, got \"" + o.random_mode + "\"");
  if (o.keep_count < 0) throw InputError("--keep-count: must be >= 0");
  if (o.max_states < 1) throw InputError("--max-states: must be at least 1");
  if (o.from < 1) throw InputError("--from: lines count from 1");
  if (o.limit < 0) throw InputError("--limit: must be >= 0");
  check_keep_directory(o);
  std::vector<bsh::Method> methods;
  {
    std::stringstream list(o.methods);
    std::string name;
    while (std::getline(list, name, ',')) {
      if (name == "graphcut") methods.push_back(bsh::Method::GraphCut);
      else if (name == "best-first") methods.push_back(bsh::Method::BestFirst);
      else throw InputError("--methods: graphcut and/or best-first, comma-separated, got \"" + name + "\"");
    }
  }
  if (o.random == 0 && o.scenes.empty() && o.csgnet.empty())
    throw InputError("nothing to survey: give --random N, SCENE files or directories, or --csgnet FILE");
  long skipped_files = 0;
  const std::vector<std::string> files = scene_files(o.scenes, &skipped_files);

  Survey survey(o);
  std::vector<SurveyTally> tallies;
  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };

  // (a) random solids
  if (o.random > 0) {
    SurveyTally csg_tally{"random csg", o.keep_count}, cells_tally{"random cells", o.keep_count};
    int redraws = 0;
    double csg_seconds = 0, cells_seconds = 0;
    for (long i = 0; i < o.random; ++i) {
      const bool cells = o.random_mode == "cells" || (o.random_mode == "mixed" && i % 2 == 1);
      const auto start = Clock::now();
      const SurveySolid c = random_case(o, i, cells, &redraws);
      survey.add(cells ? cells_tally : csg_tally, c);
      (cells ? cells_seconds : csg_seconds) += seconds_since(start);
    }
    csg_tally.seconds = csg_seconds;
    cells_tally.seconds = cells_seconds;
    if (o.random_mode != "cells") tallies.push_back(csg_tally);
    if (o.random_mode != "csg") tallies.push_back(cells_tally);
    std::cout << "random: " << o.random << " solids from --seed " << o.seed << " (" << redraws
              << " empty or unbounded draws redrawn)\n";
  }

  // (b) BSH shapes of scene files
  if (!files.empty()) {
    for (bsh::Method method : methods) {
      SurveyTally t{std::string("bsh ") + bsh::to_string(method), o.keep_count};
      const auto start = Clock::now();
      long unfinished = 0;
      for (const std::string& file : files) {
        const Scene2 original = read_scene_file(file);
        const Arranged2 arranged = arrange(original);
        const bsh::Problem problem(arranged.complex);
        bsh::ExtractOptions options;
        options.method = method;
        options.max_states = o.max_states;
        options.enumerate_ties = false;
        const bsh::ExtractResult r = bsh::extract(problem, options);
        if (!r.stopped_by.empty()) ++unfinished;
        SurveySolid c;
        c.name = std::string("bsh-") + bsh::to_string(method) + "-" + file_stem(file);
        c.origin = "the " + std::string(bsh::to_string(method)) + " BSH shape of " + file +
                   (r.stopped_by.empty() ? "" : " (search stopped by " + r.stopped_by + ")");
        c.scene = whole_plane_scene(original);
        c.arranged = arrange(c.scene);
        c.solid = carry_to_whole_plane(arranged, r.labelling, c.arranged);
        if (c.arranged.complex.cells.size() != arranged.complex.cells.size() || c.scene.domain.min != original.domain.min ||
            c.scene.domain.max != original.domain.max) {
          c.own_arranged = arranged;
          c.own_solid = r.labelling;
        }
        survey.add(t, c);
      }
      t.seconds = seconds_since(start);
      if (unfinished)
        std::cout << t.source << ": " << unfinished << " searches stopped at --max-states " << o.max_states
                  << " (their best shape so far is used)\n";
      tallies.push_back(t);
    }
    std::cout << "scenes: " << files.size() << " files";
    if (skipped_files) std::cout << " (" << skipped_files << " JSON files in the directories are not scenes, skipped)";
    std::cout << "\n";
  }

  // (c) CSGNet programs
  if (!o.csgnet.empty()) {
    SurveyTally t{"csgnet", o.keep_count};
    std::error_code unknown;  // other than "not found": read_file says what
    if (std::filesystem::status(o.csgnet, unknown).type() == std::filesystem::file_type::not_found) {
      t.note = "skipped: corpus not present at " + o.csgnet;
    } else {
      // Present: read as every input is (a directory is refused, a FIFO never blocks).
      std::istringstream in(read_file(o.csgnet));
      const auto start = Clock::now();
      std::string line;
      long number = 0;
      while (std::getline(in, line)) {
        ++number;
        if (line.empty() || number < o.from) continue;
        if (o.limit > 0 && number >= o.from + o.limit) break;
        std::optional<CsgnetProgram> program;
        try {
          program = read_csgnet(line, "line " + std::to_string(number));
        } catch (const InputError&) {
          ++t.malformed;
          continue;
        }
        SurveySolid c;
        c.name = "csgnet-line-" + std::to_string(number);
        c.origin = "CSGNet " + o.csgnet + " line " + std::to_string(number) + ": " + line;
        c.scene = whole_plane_scene(program->scene);
        c.arranged = arrange(c.scene);
        c.expression = program->expression;
        c.solid = csg::evaluate(*c.expression, c.arranged.complex);
        c.own_arranged = arrange(program->scene);
        c.own_solid = csg::evaluate(*c.expression, c.own_arranged->complex);
        survey.add(t, c);
      }
      t.seconds = seconds_since(start);
    }
    tallies.push_back(t);
  }

  print_table(tallies, o.timings);
  print_kept(tallies, o.keep_dir);
  if (survey.failures() > 0) {
    std::cout << "STRUCTURAL CHECKS FAILED on " << survey.failures() << " solid(s)\n";
    return kCheckFailed;
  }
  std::cout << "all structural checks hold\n";
  return 0;
}

}  // namespace

void add_nhsurvey_command(CLI::App& app) {
  auto o = std::make_shared<SurveyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "nhsurvey", "NH-Rep trees with natural halfspaces over many 2D solids (random, BSH scenes, CSGNet) or random 3D solids: how often "
                  "the tree is exactly the solid, and when not, whether the solid is describable; exit 3 when a "
                  "structural check fails");
  cmd->add_option("SCENE", o->scenes, "hsx-scene/1 files or directories of them (BSH shapes are extracted)");
  cmd->add_option("--random", o->random, "survey N random solids (default 0)");
  cmd->add_option("--seed", o->seed, "seed of the random solids (default 1)");
  cmd->add_option("--random-mode", o->random_mode,
                  "csg, cells or mixed (default: even solids csg, odd cells); with --dimension 3: csg, hollow or "
                  "mixed (even csg, odd hollow)");
  cmd->add_option("--dimension", o->dimension, "2 (default) or 3: random 3D CSG solids (boxes, spheres, cylinders, "
                                               "planes), evaluated exactly on their 3D arrangements");
  cmd->add_option("--segments", o->segments, "3D: segments per circle of spheres and cylinders (default 8)");
  cmd->add_option("--max-primitives", o->max_primitives,
                  "3D: 2 to this many primitives per solid (default 4; at most 64)");
  cmd->add_flag("--random-polygons", o->random_polygons, "random boxes and triangles as polygon halfspaces");
  cmd->add_option("--methods", o->methods, "BSH methods for scenes: graphcut,best-first (default both)");
  cmd->add_option("--max-states", o->max_states, "best-first: stop after N expanded states (default 20000)");
  cmd->add_option("--csgnet", o->csgnet, "a CSGNet corpus file, one postfix program per line");
  cmd->add_option("--from", o->from, "CSGNet: start at this line (1-based, default 1)");
  cmd->add_option("--limit", o->limit, "CSGNet: at most N lines (default: all)");
  cmd->add_option("--keep", o->keep_dir, "write the kept 'describable but fails' examples to DIR (scene + .csg)");
  cmd->add_option("--keep-count", o->keep_count, "keep the first K examples of each source (default 3)");
  cmd->add_flag("--timings", o->timings, "add seconds per source to the table");
  cmd->add_flag("-v,--verbose", o->verbose, "one line per solid");
  cmd->add_flag("--nest-holes", o->nest_holes,
                "extension: holes' trees intersected with their part's tree (hsx nhtree --nest-holes)");
  run_with_status(cmd, o, &run_survey);
}

}  // namespace hsx::cli
