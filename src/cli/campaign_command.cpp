// hsx campaign: the proposition checkers on many random 2D scenes (algorithms/campaign/campaign.hpp), with the
// results as JSON lines in a folder that a killed run resumes (io/campaign_files.hpp). docs/campaigns.md.
#include "cli/campaign_against.hpp"
#include "cli/commands.hpp"
#include "cli/distribute.hpp"
#include <hsx/algorithms/campaign/campaign.hpp>
#include <hsx/algorithms/campaign/minimise.hpp>
#include <hsx/algorithms/csg/random_solid3.hpp>
#include <hsx/io/campaign_files.hpp>
#include <hsx/io/scene_json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace hsx::cli {
namespace {

struct CampaignCommandOptions {
  campaign::CampaignSettings settings;
  std::uint64_t start = 0;
  std::uint64_t count = 0;
  bool count_given = false;
  std::string shard = "0/1";
  int jobs = 1;
  std::string checks = "default";
  std::string sample_policy = "uniform";
  bool list_checks = false;
  std::string out_dir;
  bool resume = false;
  std::string halfspaces = "1..6";
  std::string degeneracies = "0..2";
  std::string kinds = "halfplane,disk,polygon";
  std::string weights;
  bool against_given = false;                           ///< --against was given (even empty: refused)
  std::string against, against_input = "bsh-graphcut";  ///< --against, --against-input
  double against_time_limit = 0;                        ///< --against-time-limit
  bool minimise = true;                                 ///< --minimise / --no-minimise
  long minimise_steps = campaign::MinimiseOptions{}.max_steps;  ///< --minimise-steps
  std::vector<std::string> merge;                       ///< --merge DIR...
  std::string primitives = "2..4";                      ///< --primitives (3D)
  std::string beam_widths;                              ///< --beam-widths
  const CLI::App* app = nullptr;                        ///< the subcommand, to ask which options were given
};

/// The most scenes one run plans (its index list is held in memory): split larger campaigns with --start.
constexpr std::uint64_t kMaxCount = 100'000'000;

/// Exit status 3 when a check fails (as `hsx check`): a counterexample or a bug, never bad input.
constexpr int kCheckFailed = 3;

/// The most threads --jobs may ask for (each holds up to 512 scenes' records in the window; a thousand of
/// them is far more than any machine's cores).
constexpr int kMaxCampaignJobs = 1024;

/// "A..B" or "A" (A = B), with lo <= A <= B <= hi.
std::pair<int, int> parse_range(const std::string& text, const std::string& option, int lo, int hi = 1000000) {
  const auto number = [&](const std::string& s) {
    std::size_t used = 0;
    long v = 0;
    try {
      v = std::stol(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != s.size() || v < lo || v > hi)
      throw InputError(option + ": \"" + text + "\" is not a range A..B of whole numbers from " + std::to_string(lo) +
                       " to " + std::to_string(hi));
    return static_cast<int>(v);
  };
  const std::size_t dots = text.find("..");
  const int a = number(dots == std::string::npos ? text : text.substr(0, dots));
  const int b = dots == std::string::npos ? a : number(text.substr(dots + 2));
  if (a > b) throw InputError(option + ": \"" + text + "\": the range's first number is larger than its last");
  return {a, b};
}

void parse_shard(const std::string& text, CampaignPlan& plan) {
  const std::size_t slash = text.find('/');
  const auto number = [&](const std::string& s) {
    if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos || s.size() > 18)
      throw InputError("--shard: \"" + text + "\" is not i/k (whole numbers, 0 <= i < k)");
    return static_cast<std::uint64_t>(std::stoull(s));
  };
  if (slash == std::string::npos) throw InputError("--shard: \"" + text + "\" is not i/k (0 <= i < k)");
  plan.shard = number(text.substr(0, slash));
  plan.shards = number(text.substr(slash + 1));
  if (plan.shards < 1 || plan.shard >= plan.shards)
    throw InputError("--shard: \"" + text + "\": need 0 <= i < k");
}

void parse_kinds(const std::string& text, RandomSceneSettings& g) {
  g.halfplanes = g.disks = g.polygons = false;
  std::stringstream in(text);
  std::string kind;
  while (std::getline(in, kind, ',')) {
    bool* flag = kind == "halfplane" ? &g.halfplanes : kind == "disk" ? &g.disks : kind == "polygon" ? &g.polygons : nullptr;
    if (!flag) throw InputError("--kinds: halfplane, disk and/or polygon, comma-separated, got \"" + kind + "\"");
    if (*flag) throw InputError("--kinds: \"" + kind + "\" is named twice");
    *flag = true;
  }
  if (!g.halfplanes && !g.disks && !g.polygons) throw InputError("--kinds: name at least one kind");
}

/// NAME=W,...: the named patterns' weights (`weights`, one per pattern, named by `name_of`); patterns not named
/// keep their weight.
template <std::size_t N, class Name>
void parse_weights(const std::string& text, std::array<int, N>& weights, Name name_of) {
  if (text.empty()) return;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const std::size_t eq = item.find('=');
    const std::string name = item.substr(0, eq);
    std::size_t k = 0;
    while (k < N && name != name_of(k)) ++k;
    if (eq == std::string::npos || k == N) {
      std::string known;
      for (std::size_t d = 0; d < N; ++d) known += std::string(d ? ", " : "") + name_of(d);
      throw InputError("--degeneracy-weights: NAME=WEIGHT items, comma-separated, NAME one of " + known + "; got \"" +
                       item + "\"");
    }
    const std::string w = item.substr(eq + 1);
    if (w.empty() || w.size() > 6 || w.find_first_not_of("0123456789") != std::string::npos)
      throw InputError("--degeneracy-weights: \"" + item + "\": the weight is a whole number 0..999999");
    weights[k] = std::stoi(w);
  }
}

/// The generator options of the dimension the campaign does not use, when given: refused (never ignored).
void refuse_other_dimension(const CampaignCommandOptions& o, int dimension) {
  static const std::vector<std::string> only2 = {"--halfspaces", "--kinds", "--complement-percent", "--denominator",
                                                 "--coordinate-bound", "--max-radius", "--near-percent", "--against"};
  static const std::vector<std::string> only3 = {"--primitives", "--segments", "--hollow", "--max-draws"};
  for (const std::string& name : dimension == 3 ? only2 : only3)
    if (o.app->count(name) > 0)
      throw InputError(name + ": a " + (dimension == 3 ? "2D" : "3D") + " option (this campaign is --dimension " +
                       std::to_string(dimension) + ")");
}

/// The generator's settings of either dimension from the options.
void parse_generator(const CampaignCommandOptions& o, campaign::CampaignSettings& settings) {
  refuse_other_dimension(o, settings.dimension);
  if (settings.dimension == 3) {
    campaign::Scene3Settings& g = settings.scene3;
    std::tie(g.solid.min_primitives, g.solid.max_primitives) =
        parse_range(o.primitives, "--primitives", 1, csg::kMaxRandomPrimitives3);
    std::tie(g.min_degeneracies, g.max_degeneracies) = parse_range(o.degeneracies, "--degeneracies", 0);
    g.max_samples = settings.scene.max_samples;
    parse_weights(o.weights, g.degeneracy_weight,
                  [](std::size_t k) { return std::string(to_string(static_cast<campaign::Degeneracy3>(k))); });
    return;
  }
  std::tie(settings.scene.min_halfspaces, settings.scene.max_halfspaces) = parse_range(o.halfspaces, "--halfspaces", 1);
  std::tie(settings.scene.min_degeneracies, settings.scene.max_degeneracies) =
      parse_range(o.degeneracies, "--degeneracies", 0);
  parse_kinds(o.kinds, settings.scene);
  parse_weights(o.weights, settings.scene.degeneracy_weight,
                [](std::size_t k) { return std::string(to_string(static_cast<Degeneracy>(k))); });
}

/// --against: the solver it runs (InputError naming the option when bad; nullopt without --against).
std::optional<ExternalSolver> against_solver(const CampaignCommandOptions& o) {
  if (!o.against_given) return std::nullopt;  // --against-input and --against-time-limit need --against (CLI11)
  ExternalSolver solver;
  solver.command = o.against;
  const auto input = external_input_from_string(o.against_input);
  if (!input) throw InputError("--against-input: unknown format \"" + o.against_input + "\" (bsh-graphcut or complex)");
  solver.input = *input;
  solver.time_limit = o.against_time_limit;
  try {
    check_external_solver(solver);
  } catch (const InputError& e) {
    throw InputError(std::string("--against: ") + e.what());
  }
  return solver;
}

/// campaign.json: the settings and plan, and --against's command and input kind when given.
nlohmann::json campaign_manifest(const campaign::CampaignSettings& settings, const CampaignPlan& plan,
                                 const std::optional<ExternalSolver>& against) {
  nlohmann::json j = campaign_to_json(settings, plan);
  if (against) j["against"] = against_to_json(*against);
  return j;
}

/// A record and, for a kept failure, its minimised scene (minimised_failure's, its note as description).
struct Kept {
  campaign::SceneRecord record;
  std::optional<Scene2> minimised;
  std::optional<Scene3> minimised3;  ///< a 3D campaign's
};

/// A record as one MPI message: its results.jsonl line, a line holding the scene (hsx-scene/1, one line) that
/// failures/ keeps for a failed record (empty otherwise), then the minimised scene when there is one;
/// decode_record is the inverse. The minimised scene is made on the rank that ran the scene and travels with it.
std::string encode_record(const Kept& k) {
  std::string text = record_to_json(k.record).dump() + "\n";
  if (k.record.scene) text += write_scene2(*k.record.scene).dump();
  if (k.record.scene3) text += write_scene3(*k.record.scene3).dump();
  text += "\n";
  if (k.minimised) text += write_scene2(*k.minimised).dump();
  if (k.minimised3) text += write_scene3(*k.minimised3).dump();
  return text;
}

Kept decode_record(const std::string& text) {
  const std::size_t end = text.find('\n'), second = text.find('\n', end + 1);
  Kept k;
  k.record = record_from_json(nlohmann::json::parse(text.substr(0, end)));
  const std::string_view scene = std::string_view(text).substr(end + 1, second - end - 1);
  if (!scene.empty()) {
    if (nlohmann::json::parse(scene).value("dimension", 2) == 3) k.record.scene3 = read_scene3_text(scene);
    else k.record.scene = read_scene_text(scene);
  }
  if (second + 1 < text.size()) {
    const std::string_view minimised = std::string_view(text).substr(second + 1);
    if (nlohmann::json::parse(minimised).value("dimension", 2) == 3) k.minimised3 = read_scene3_text(minimised);
    else k.minimised = read_scene_text(minimised);
  }
  return k;
}

/// The scenes `todo`, each record (with its minimised scene when `minimise` and it failed) to `sink` in the order
/// of `todo`: here on `jobs` threads, or under mpirun (`mpi` set) split over the ranks, every record reaching rank
/// 0's sink (cli/distribute.hpp). A failed scene is minimised on the thread that receives the records, one at a
/// time (failures are rare), on the rank that ran it; it depends only on the scene, so the bytes are the same for
/// any number of jobs and processes. Returns how many threads ran the scenes here (campaign::run_scenes; under mpirun,
/// `jobs` less the threads this rank's system refused).
int run_all(const campaign::CampaignSettings& settings, const std::vector<std::uint64_t>& todo, int jobs,
             const MpiRun* mpi, const std::optional<campaign::MinimiseOptions>& minimise,
             const std::function<void(Kept&&)>& sink) {
  const auto keep = [&](campaign::SceneRecord&& r) {
    Kept k;
    const auto say = [&](const auto& m, bool kept) {
      if (kept)
        std::cerr << "hsx campaign: scene " << r.index << " minimised to " << m.scene.halfspaces.size()
                  << " halfspaces and " << m.scene.samples.size() << " samples in " << m.steps << " steps\n";
    };
    if (minimise && r.failed() && r.scene3) {
      const campaign::MinimiseResult3 m = campaign::minimise_scene(settings, *r.scene3, r, *minimise);
      k.minimised3 = minimised_failure(r, m);
      say(m, k.minimised3.has_value());
    }
    if (minimise && r.failed() && r.scene) {
      const campaign::MinimiseResult m = campaign::minimise_scene(settings, *r.scene, r, *minimise);
      k.minimised = minimised_failure(r, m);
      say(m, k.minimised.has_value());
    }
    k.record = std::move(r);
    return k;
  };
  if (!mpi) return campaign::run_scenes(settings, todo, jobs, [&](campaign::SceneRecord&& r) { sink(keep(std::move(r))); });
  int threads = jobs;
  mpi->distribute(
      todo,
      [&](const std::vector<std::uint64_t>& mine, const std::function<void(std::string&&)>& out) {
        const int used = campaign::run_scenes(settings, mine, jobs, [&](campaign::SceneRecord&& r) {
          out(encode_record(keep(std::move(r))));
        });
        // one scene runs on the calling thread anyway; fewer scenes than jobs start fewer threads, not refused ones
        const int wanted = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(jobs), mine.size()));
        if (mine.size() > 1) threads = std::min(threads, jobs - (wanted - used));
      },
      [&](std::string&& message) { sink(decode_record(message)); });
  return threads;
}

/// hsx campaign --out OUT --merge DIR...: io's merge_campaigns, then the table and the exit status of a run.
int run_merge(const CampaignCommandOptions& o) {
  if (o.out_dir.empty()) throw InputError("--merge: needs --out DIR (the merged campaign's new folder)");
  if (o.count_given || o.resume) throw InputError("--merge: takes only --out and the shard folders (not --count or --resume)");
  if (launched_by_mpi()) throw InputError("--merge: run it without mpirun (it only copies and counts)");
  const campaign::Summary summary = merge_campaigns(o.out_dir, o.merge, [](const campaign::SceneRecord& r) {
    if (r.failed()) std::cout << failure_note(r) << "\n";  // as a run prints them
  });
  std::cout << summary_table(summary);
  std::cerr << "hsx campaign: merged " << o.merge.size() << " shards into " << o.out_dir << " (" << summary.scenes
            << " scenes)\n";
  return summary.failed_scenes > 0 ? kCheckFailed : 0;
}

int run_campaign(const CampaignCommandOptions& o) {
  if (o.list_checks) {
    for (const campaign::CheckInfo& c : campaign::check_catalogue())
      std::cout << std::left << std::setw(16) << c.name << c.description << "\n";
    std::cout << std::left << std::setw(16) << "beamK"
              << "Beam K=K for any K in 2.." << campaign::kMaxBeamWidth
              << " (by name, or --beam-widths): as beam2 and beam4\n";
    return 0;
  }
  if (!o.merge.empty()) return run_merge(o);
  if (!o.count_given) throw InputError("--count: how many scenes (give --count N; --list-checks lists the checks)");
  if (o.count > kMaxCount)
    throw InputError("--count: at most " + std::to_string(kMaxCount) + " scenes per run (run larger campaigns in parts "
                     "with --start)");
  if (o.jobs < 1 || o.jobs > kMaxCampaignJobs)
    throw InputError("--jobs: 1 to " + std::to_string(kMaxCampaignJobs) + ", got " + std::to_string(o.jobs));
  if (o.minimise_steps < 0) throw InputError("--minimise-steps: at least 0 (0: no limit)");
  if (o.out_dir == "-") throw InputError("--out: a folder, not - (standard output holds the table)");
  if (o.resume && o.out_dir.empty()) throw InputError("--resume: needs --out DIR (the campaign to continue)");
  campaign::CampaignSettings settings = o.settings;
  parse_generator(o, settings);
  settings.checks = campaign::parse_check_list(o.checks);
  if (o.app->count("--beam-widths") > 0) settings.checks = campaign::with_beam_widths(settings.checks, o.beam_widths);
  const std::optional<campaign::SamplePolicy> policy = campaign::sample_policy_from_string(o.sample_policy);
  if (!policy) throw InputError("--sample-policy: uniform or intended, not \"" + o.sample_policy + "\"");
  settings.sample_policy = *policy;
  const std::optional<ExternalSolver> against = against_solver(o);
  if (against) settings.extra.push_back(against_check(*against, settings));
  campaign::validate(settings);
  CampaignPlan plan;
  plan.start = o.start;
  plan.count = o.count;
  parse_shard(o.shard, plan);
  const std::vector<std::uint64_t> indices = plan.indices();

  // Under mpirun every rank parses the same options; rank 0 alone owns the folder and the output and tells the
  // others whether to go on, then which scenes are left to do.
  std::optional<MpiRun> mpi;
  if (launched_by_mpi()) mpi.emplace();
  const bool root = !mpi || mpi->rank() == 0;
  std::unique_ptr<CampaignFolder> folder;
  if (root && !o.out_dir.empty()) {
    try {
      folder = std::make_unique<CampaignFolder>(o.out_dir, campaign_manifest(settings, plan, against), o.resume, indices);
    } catch (...) {
      if (mpi) mpi->broadcast(false);
      throw;
    }
  }
  if (mpi && !mpi->broadcast(true)) return 2;  // rank 0 refused the folder and says why
  campaign::Summary summary(campaign::recorded_checks(settings));
  const auto report = [&](const campaign::SceneRecord& r) {
    if (r.failed()) std::cout << failure_note(r) << "\n";
  };
  std::size_t done = 0;
  if (folder) {
    for (const campaign::SceneRecord& r : folder->records()) {
      summary.add(r);
      report(r);
    }
    done = folder->records().size();
    if (o.resume)
      std::cerr << "hsx campaign: resumed " << o.out_dir << ": " << done << " of " << indices.size()
                << " scenes were done" << (folder->cut_torn_line() ? " (a torn last line was cut off)" : "") << "\n";
  }
  std::vector<std::uint64_t> todo(indices.begin() + static_cast<std::ptrdiff_t>(done), indices.end());
  if (mpi) todo = mpi->broadcast(todo);
  const auto begin = std::chrono::steady_clock::now();
  // Minimising keeps files only: without --out there is nothing to keep it in.
  std::optional<campaign::MinimiseOptions> minimise;
  if (o.minimise && !o.out_dir.empty()) {
    minimise.emplace();
    minimise->max_steps = o.minimise_steps;
  }
  const int threads = run_all(settings, todo, o.jobs, mpi ? &*mpi : nullptr, minimise, [&](Kept&& k) {
    if (folder) folder->append(k.record, k.minimised, k.minimised3);
    summary.add(k.record);
    report(k.record);
  });
  if (!root) return 0;  // rank 0 writes the summary and gives the exit status
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  if (folder) folder->write_summary(summary);
  std::cout << summary_table(summary);
  std::cerr << "hsx campaign: " << todo.size() << " scenes run in " << std::fixed << std::setprecision(2) << seconds
            << " s (" << std::setprecision(1) << (seconds > 0 ? todo.size() / seconds : 0) << " scenes/s, " << o.jobs
            << " job" << (o.jobs == 1 ? "" : "s") << (mpi ? " per process, " + std::to_string(mpi->size()) + " MPI processes" : "")
            << ")\n";
  if (threads < std::min<std::uint64_t>(o.jobs, todo.size()) && todo.size() > 1)
    std::cerr << "hsx campaign: the system started " << threads << " of the " << o.jobs << " threads asked for"
              << (mpi ? " (on rank 0)" : "") << "; the records are the same\n";
  return summary.failed_scenes > 0 ? kCheckFailed : 0;
}

}  // namespace

void add_campaign_command(CLI::App& app) {
  auto o = std::make_shared<CampaignCommandOptions>();
  o->settings.scene.max_samples = 6;
  CLI::App* cmd = app.add_subcommand(
      "campaign",
      "Run the proposition checkers on random 2D scenes (scene k of seed s is the same on every machine); results "
      "as JSON lines in --out DIR, resumable; exit 3 when a check fails (docs/campaigns.md)");
  cmd->add_option("--seed", o->settings.seed, "the campaign's seed: scene k is random_scene(settings, seed, k) "
                                              "(default 1)");
  cmd->add_option_function<std::uint64_t>(
      "--count",
      [o](const std::uint64_t& n) {
        o->count = n;
        o->count_given = true;
      },
      "how many scenes: indices --start .. --start + N - 1 (required; at most 10^8 per run)");
  cmd->add_option("--start", o->start, "the first scene index (default 0)");
  cmd->add_option("--shard", o->shard,
                  "i/k: only the indices whose offset from --start is i mod k (default 0/1); the k shards together "
                  "are the whole range");
  cmd->add_option("--jobs", o->jobs, "threads (default 1, at most 1024); the output is the same bytes for any number");
  cmd->add_option("--checks", o->checks,
                  "comma-separated check names, default (check_all's nine: the default) or all; see --list-checks. "
                  "Only the named checks are computed (each as in a full run), recorded, counted, and able to fail "
                  "a scene");
  cmd->add_option("--beam-widths", o->beam_widths,
                  "K1,K2,...: add the beam checks of these widths to --checks (1: beam1, check_all's; K >= 2: beamK, "
                  "beam K against the optimum, with its optimality table; beam2 and beam4 are the catalogue's)");
  cmd->add_flag("--list-checks", o->list_checks, "print the check names and what each checks, then exit");
  cmd->add_option("--out", o->out_dir,
                  "folder for campaign.json, results.jsonl (one line per scene), failures/ and summary.json: a new "
                  "or empty folder, or with --resume one holding this campaign")
      ->check(output_path());
  cmd->add_option("--merge", o->merge,
                  "DIR...: merge the shard folders (--shard i/k runs of one campaign, each finished) into --out, as "
                  "one run of the whole range writes it; refused when the settings differ or a shard is missing or "
                  "unfinished");
  cmd->add_flag("--minimise,!--no-minimise", o->minimise,
                "with --out: minimise each failing scene (remove halfspaces, samples, simplify coordinates while the "
                "same checks fail) into failures/scene-K.min.json beside scene-K.json (default on; the records do "
                "not depend on it)");
  cmd->add_option("--minimise-steps", o->minimise_steps,
                  "the most reduced scenes checked per minimisation (default " + std::to_string(o->minimise_steps) +
                      "; 0: no limit)");
  cmd->add_flag("--resume", o->resume,
                "continue the campaign in --out: skip the scenes recorded, cut a torn last line, run the rest");
  cmd->add_option("--time-limit", o->settings.time_limit,
                  "seconds per scene for arrangement and checks (0: none, default); a scene that reaches it is "
                  "counted as timed out and its cut checks reported as stopped (or skipped when no time was left); "
                  "which ones depends on the machine's speed and load")
      ->check(seconds());
  CLI::Option* against = cmd->add_option_function<std::string>(
      "--against",
      [o](const std::string& command) {
        o->against = command;
        o->against_given = true;
      },
                  "grade another program on every scene: this shell command, with {input} and {output} standing for "
                  "the files it reads and writes (as hsx grade --run); recorded as the check \"against\" (held: "
                  "optimal; failed: suboptimal, invalid or no answer; stopped: undecided), with its own table");
  cmd->add_option("--against-input", o->against_input,
                  "--against: what {input} holds: bsh-graphcut (default) or complex (hsx-complex/1)")
      ->needs(against);
  cmd->add_option("--against-time-limit", o->against_time_limit,
                  "--against: kill the program after S seconds (0: no limit, default); a killed program's verdict is "
                  "no answer")
      ->check(seconds())
      ->needs(against);
  // The generator (geometry/random_scene.hpp's RandomSceneSettings).
  cmd->add_option("--halfspaces", o->halfspaces, "number of halfspaces as A..B or N (default 1..6)");
  cmd->add_option("--kinds", o->kinds, "halfspace kinds: halfplane, disk, polygon, comma-separated (default all)");
  cmd->add_option("--complement-percent", o->settings.scene.complement_percent,
                  "percent chance that a new halfspace is complemented (default 25)");
  cmd->add_option("--denominator", o->settings.scene.denominator,
                  "the coordinate grid is multiples of 1/D (default 2)");
  cmd->add_option("--coordinate-bound", o->settings.scene.coordinate_bound,
                  "grid coordinates lie in [-B, B] (default 3)");
  cmd->add_option("--max-radius", o->settings.scene.max_radius, "disk radii in (0, R] (default 3)");
  cmd->add_option("--degeneracies", o->degeneracies,
                  "number of forced degeneracy patterns as A..B or N (default 0..2)");
  cmd->add_option("--degeneracy-weights", o->weights,
                  "NAME=W,...: relative weights of the patterns (default 1 each; 0: never), NAME as in "
                  "geometry/random_scene.hpp (RepeatedHalfspace, ConcurrentLines, ...)");
  cmd->add_option("--sample-policy", o->sample_policy,
                  "uniform (default: up to --samples samples on the boundaries) or intended (a random "
                  "orientation-preserving shape, sampled once per boundary component; docs/campaigns.md)");
  cmd->add_option("--samples", o->settings.scene.max_samples,
                  "up to N samples per scene, each on a patch (default 6; 0: none)");
  cmd->add_option("--near-percent", o->settings.scene.near_percent,
                  "percent chance that a sample is given as a `near` point snapped to its boundary (default 33)");
  // The checks' limits (bsh::CheckOptions).
  cmd->add_option("--max-labellings,--brute-force-limit", o->settings.brute_force_limit,
                  "largest number of labellings the oracle may enumerate (default 200000)");
  cmd->add_option("--max-states", o->settings.max_states,
                  "per search: stop after expanding N states (0: no limit; deterministic)");
  cmd->add_option("--max-graph-cuts", o->settings.max_graph_cuts,
                  "per search: stop after N graph cuts (0: no limit; deterministic)");
  cmd->add_option("--precision", o->settings.precision_bits,
                  "precision cap in bits for certified comparisons (default 2048)");
  cmd->add_option("--max-cells", o->settings.limits.max_cells,
                  "refuse (record as refused) a scene whose arrangement has more cells (default " +
                      std::to_string(o->settings.limits.max_cells) + "; 0: no limit)")
      ->check(non_negative());
  cmd->add_option("--max-side-table", o->settings.limits.max_side_entries,
                  "refuse a scene whose cells x halfspaces exceeds this (default " +
                      std::to_string(o->settings.limits.max_side_entries) + "; 0: no limit)")
      ->check(non_negative());
  // The 3D generator (algorithms/campaign/scene3.hpp).
  cmd->add_option("--dimension", o->settings.dimension,
                  "2 (default: random 2D scenes) or 3: random 3D CSG scenes of boxes, spheres, cylinders and planes "
                  "with degeneracy patterns (algorithms/campaign/scene3.hpp); --degeneracies, "
                  "--degeneracy-weights (PlaneOnBoxFace, CoincidentFaces, ConcurrentPlanes), --samples and "
                  "--sample-policy apply to both");
  cmd->add_option("--primitives", o->primitives,
                  "3D: the number of primitives as A..B or N (default 2..4; at most 64)");
  cmd->add_option("--segments", o->settings.scene3.solid.segments,
                  "3D: segments per circle of spheres and cylinders, 6..64 (default 8)");
  cmd->add_flag("--hollow", o->settings.scene3.solid.hollow,
                "3D: subtract an inner primitive from a box or sphere primitive 0 (a cavity)");
  cmd->add_option("--max-draws", o->settings.scene3.solid.max_draws,
                  "3D: an empty or unbounded solid is drawn again, at most this many draws (default 20)");
  o->app = cmd;
  run_with_status(cmd, o, &run_campaign);
}

}  // namespace hsx::cli
