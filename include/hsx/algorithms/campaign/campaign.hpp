// Campaigns: the proposition checkers (bsh::check_all) on many random scenes, reproducible from a seed.
//
// Scene k of a campaign with seed s is random_scene(settings.scene, s, k) (geometry/random_scene.hpp: the same on
// every machine), arranged by arrange() (complex/from_arrangement2.hpp) within settings.limits, then checked by
// bsh::check_all with the campaign's limits. The checks have stable short names (check_catalogue(), the order of
// check_all's results); a campaign computes and records the ones it was asked for (bsh::CheckOptions::only: each
// gives the result it gives in a full run), each as held / failed / skipped / stopped with check_all's witness,
// never silently dropped. A scene the arrangement limits refuse is recorded as refused
// (every selected check skipped, with the reason); an exception from the library on a generated scene is a bug
// and is recorded as an error (the message kept, every selected check skipped, the scene counted and kept as a
// failure), so it is never lost.
//
// Determinism: a scene's record depends only on (settings, index), except where --time-limit cuts a scene short
// (which checks finish then depends on the machine's speed and load). run_scenes hands the records to its sink in
// the order of the indices whatever the number of threads, so a campaign's output is the same bytes for any
// number of jobs. Reading and writing records and folders is io/campaign_files.hpp; the CLI is `hsx campaign`
// (docs/campaigns.md).
#pragma once

#include <hsx/geometry/arrangement2.hpp>
#include <hsx/geometry/random_scene.hpp>
#include <hsx/geometry/scene.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hsx {
struct Arranged2;
}

namespace hsx::campaign {

/// A check of the catalogue: its stable short name (used by `--checks`, in records and summaries) and what it is.
struct CheckInfo {
  const char* name;         ///< e.g. "prop52"
  const char* description;  ///< the check_all result it stands for, e.g. "Prop. 5.2 (best-first = brute force)"
};

/// Every check a campaign can run, in the order of bsh::check_all's results: existence, prop52, prop51, beam1,
/// prop41-optimum, prop41-beam, uniqueness, certificates, manifold.
const std::vector<CheckInfo>& check_catalogue();

/// The catalogue's names for a comma-separated list ("all" or empty: every check, in catalogue order). Names are
/// kept in catalogue order whatever order they were given in. Throws InputError naming an unknown or repeated
/// name.
std::vector<std::string> parse_check_list(const std::string& list);

enum class CheckStatus {
  Held,     ///< the proposition held on this scene
  Failed,   ///< a counterexample or a bug: the witness says which and why
  Skipped,  ///< not run: not applicable, the oracle too large, the scene refused, the time spent before it
  Stopped   ///< run but cut short by a limit (a time limit, --max-states, --max-graph-cuts): neither pass nor fail
};
/// "held", "failed", "skipped", "stopped".
const char* to_string(CheckStatus s);
/// The inverse of to_string; std::nullopt for any other text.
std::optional<CheckStatus> check_status_from_string(const std::string& s);

/// One check on one scene.
struct CheckOutcome {
  std::string check;    ///< the short name (check_catalogue)
  CheckStatus status = CheckStatus::Held;
  std::string witness;  ///< check_all's witness (what was compared, or the counterexample), or why not run
  bool operator==(const CheckOutcome& o) const {
    return check == o.check && status == o.status && witness == o.witness;
  }
};

/// What became of one scene.
enum class SceneOutcome {
  Checked,  ///< arranged and checked (each check's own status says how it went)
  /// the arrangement limits refused it (`note` says which; choosing samples arranges the scene once more, inside
  /// random_scene, under the default ArrangementLimits); its checks are Skipped
  Refused,
  Error     ///< the library threw on it (`note` has the message): a bug; its checks are Skipped, the scene failed()
};
/// "checked", "refused", "error".
const char* to_string(SceneOutcome o);
/// The inverse of to_string; std::nullopt for any other text.
std::optional<SceneOutcome> scene_outcome_from_string(const std::string& s);

/// The record of scene `index` of seed `seed`.
struct SceneRecord {
  std::uint64_t index = 0;
  std::uint64_t seed = 0;
  int halfspaces = 0;                     ///< the scene's halfspace count
  long cells = 0;                         ///< its complex's cells (0 when not arranged)
  long patches = 0;                       ///< its complex's patches (0 when not arranged)
  int samples = 0;                        ///< its samples
  std::vector<std::string> degeneracies;  ///< the patterns applied (to_string(Degeneracy)), in order
  SceneOutcome outcome = SceneOutcome::Checked;
  std::string note;                       ///< Refused / Error: the reason; empty when Checked
  /// True when the campaign has a time limit and the scene's arrangement and checks together reached it: some of
  /// its checks may then be Stopped or Skipped by the limit (check_all's witnesses say which).
  bool timed_out = false;
  std::vector<CheckOutcome> checks;       ///< the selected checks, in catalogue order
  /// The scene itself, set by run_scene when failed() (so that it can be kept); never read from a record file.
  std::optional<Scene2> scene;

  /// True when some check failed or the outcome is Error: a scene to keep.
  bool failed() const;
  /// Equal in every recorded field (`scene` is not compared).
  bool operator==(const SceneRecord& o) const;
};

/// The name of the check that grades another program's answer (`hsx campaign --against`, docs/campaigns.md). Its
/// witnesses start with the verdict, which Summary tallies:
///   held:    "optimal: ENERGY"
///   failed:  "suboptimal: gap M missing samples, measure D; ..." (M >= 0 a whole number, D a decimal; the energy
///            is lexicographically larger than the optimum's), "invalid: ..." (not orientation-preserving or not
///            sample-connected) or "no answer: ..." (the program failed, timed out or wrote no labelling)
///   stopped: "undecided: ..." (a valid answer, but the reference was stopped by a limit or the energies did not
///            separate at the precision cap)
///   skipped: anything ("not run: ...": the scene was refused or the library threw on it)
inline constexpr const char* kAgainstCheck = "against";

/// A check computed outside the catalogue, by the caller (the CLI's --against runs another program; algorithms/
/// may not run programs). It is recorded after the catalogue's checks, under `name`, on every scene.
struct ExtraCheck {
  std::string name;  ///< its short name in records and summaries (not a catalogue name)
  /// Called once per arranged scene, after the catalogue's checks, on the worker thread that runs the scene (so it
  /// must be safe to call from several threads at once): `index` is the scene's index, `scene` and `arranged` the
  /// generated scene and its arrangement. Returns the outcome (its `check` is overwritten with `name`). For output
  /// that is the same bytes for any number of jobs, the outcome must depend on the scene only. It is not called on
  /// a refused scene or one the library threw on (the check is then Skipped like the others); an exception it
  /// throws is not a scene's outcome: it stops the campaign (run_scenes rethrows it).
  std::function<CheckOutcome(std::uint64_t index, const Scene2& scene, const Arranged2& arranged)> run;
};

/// A campaign's settings: which scenes, which checks, which limits. Everything here except `extra` is part of a
/// campaign's identity (io/campaign_files.hpp writes it to the folder, and a resumed campaign must match it); the
/// extra checks' names are recorded in every record, and whoever sets `extra` adds what determines them to the
/// folder's manifest (the CLI writes --against's command and input kind there).
struct CampaignSettings {
  RandomSceneSettings scene;        ///< the generator's settings
  std::uint64_t seed = 1;           ///< scene k is random_scene(scene, seed, k)
  std::vector<std::string> checks;  ///< the selected checks (parse_check_list); empty: every check
  ArrangementLimits limits;         ///< arrange()'s limits; a scene beyond them is Refused
  long brute_force_limit = 200000;  ///< bsh::CheckOptions::brute_force_limit
  long max_states = 0;              ///< bsh::CheckOptions::max_states (per search; 0: none)
  long max_graph_cuts = 0;          ///< bsh::CheckOptions::max_graph_cuts (per search; 0: none)
  int precision_bits = 2048;        ///< bsh::CompareOptions::max_bits of the certified comparisons
  /// Seconds per scene for the arrangement and the checks together (0: none). A scene that reaches it is
  /// timed_out; the checks it cut are Stopped (or Skipped when no time was left for them).
  double time_limit = 0;
  /// Checks run after the catalogue's on every arranged scene (their time is not counted in `time_limit`, and does
  /// not make a scene timed_out); names must differ from the catalogue's and from each other (validate).
  std::vector<ExtraCheck> extra;
};

/// The names a campaign records on each scene: the selected catalogue checks (every one when `checks` is empty), in
/// catalogue order, then the extra checks' names in their order. Summary takes this list.
std::vector<std::string> recorded_checks(const CampaignSettings& settings);

/// Checks `settings` (the generator's ranges via random_scene's own validation, the checks' names, the extra
/// checks' names and functions, the limits) and throws InputError naming the first bad one.
void validate(const CampaignSettings& settings);

/// Scene `index` of the campaign: generated, arranged and checked (the catalogue's checks, then settings.extra's).
/// Never throws for a scene (a refusal or a library exception becomes the record's outcome); throws InputError
/// only for invalid settings (validate), and what an extra check's function throws.
/// - `cancel`: empty, or asked where the time limit is (bsh::CheckOptions::cancel; thread-safe, it may be called
///   from several scenes at once); once it returns true the running catalogue check stops and the rest are skipped,
///   so the record is no longer the scene's reproducible one: a caller that cancels drops it. (The arrangement and
///   the extra checks are not interrupted.) Not part of the campaign's identity.
SceneRecord run_scene(const CampaignSettings& settings, std::uint64_t index,
                      const std::function<bool()>& cancel = {});

/// The checks of run_scene on a given scene (run_scene is random_scene, then this, then the generator's
/// degeneracies added to the record): `scene` arranged within settings.limits and checked (the catalogue's selected
/// checks, then settings.extra's), its record filled as run_scene's (index and seed from `index` and settings.seed,
/// `degeneracies` left empty, `scene` set when failed()). `scene` must be resolved (validate_and_resolve, as
/// read_scene2 and random_scene return it). settings.time_limit counts from this call. Never throws for the
/// scene; throws what an extra check's function throws. Used to minimise a failing scene
/// (algorithms/campaign/minimise.hpp).
SceneRecord check_scene(const CampaignSettings& settings, const Scene2& scene, std::uint64_t index,
                        const std::function<bool()>& cancel = {});

/// Runs the scenes `indices` on `jobs` threads (>= 1) and calls `sink` with each record, on the calling thread,
/// in the order of `indices`, as soon as it and every record before it are done (at most about 4 x jobs records
/// wait for their turn). An exception from `sink` stops the run (the threads finish their current scene) and is
/// rethrown. Throws InputError for invalid settings or jobs < 1.
/// - `cancel`: run_scene's, for every scene (empty: none). Cancelling does not stop run_scenes by itself: the sink
///   decides (it throws to stop, e.g. the Python module's campaign iterator on Ctrl-C), and the scenes in progress
///   then end at their next check of `cancel` instead of running to their end.
void run_scenes(const CampaignSettings& settings, const std::vector<std::uint64_t>& indices, int jobs,
                const std::function<void(SceneRecord&&)>& sink, const std::function<bool()>& cancel = {});

/// The indices of shard `shard` of `shards` among start, start + 1, ..., start + count - 1: those with
/// (index - start) mod shards == shard, in increasing order. The shards 0..shards-1 partition the range. Throws
/// InputError unless 0 <= shard < shards, and when the last index start + count - 1 is beyond 2^64 - 1.
std::vector<std::uint64_t> shard_indices(std::uint64_t start, std::uint64_t count, std::uint64_t shard,
                                         std::uint64_t shards);

/// A 95% Wilson score interval for a proportion: `successes` of `trials` (0 <= successes <= trials), z = 1.959964.
/// With 0 trials the interval is [0, 1]; its low end is exactly 0 when successes == 0 and its high end exactly 1
/// when successes == trials. (Floating point: a statistic of counts, not geometry.)
struct RateInterval {
  double low = 0, high = 1;
};
RateInterval wilson95(long successes, long trials);

/// Counts of one check's statuses.
struct StatusCounts {
  long held = 0, failed = 0, skipped = 0, stopped = 0;
  long total() const { return held + failed + skipped + stopped; }
  /// held / (held + failed): the rate among the scenes where the check decided (0 when none did).
  double held_rate() const;
  /// wilson95(held, held + failed).
  RateInterval held_interval() const;
  void add(CheckStatus s);
};

/// The "against" check's verdicts (kAgainstCheck's witnesses), when it is tallied (Summary::against). A
/// namespace-level struct, not nested in Summary: clang 14 cannot default-construct a nested struct with member
/// initializers inside std::optional while the enclosing class is incomplete.
struct AgainstTally {
  long optimal = 0, suboptimal = 0, invalid = 0, no_answer = 0;
  long undecided = 0;  ///< stopped: a valid answer whose optimality was not decided
  long not_run = 0;    ///< skipped: the scene was refused or the library threw on it
  /// Answers that are valid BSH boundaries (orientation-preserving and sample-connected).
  long valid() const { return optimal + suboptimal + undecided; }
  /// The suboptimal answers' gaps (missing samples, measure as its witness's decimal), in increasing
  /// lexicographic order (floating point: a statistic, the exact gaps are in the witnesses).
  std::vector<std::pair<long, double>> gaps;
};

/// A campaign's tallies: per check, in all and by the scenes' number of halfspaces.
struct Summary {
  long scenes = 0, checked = 0, refused = 0, errors = 0, timed_out = 0;
  long failed_scenes = 0;  ///< scenes with a failed check (errors included)
  std::vector<std::string> checks;  ///< the tallied checks, in catalogue order
  std::map<std::string, StatusCounts> by_check;
  std::map<std::string, std::map<int, StatusCounts>> by_check_and_halfspaces;

  /// Beam K = 1's optimality on the scenes where beam1 held, by its witness (check_all's beam check writes
  /// "optimal: E" when the beam's energy equals the optimum, "sub-optimal: E" when it is larger): `held` counts the
  /// optimal scenes, `failed` the sub-optimal ones (a rate, not a failure of anything). Empty unless beam1 is
  /// tallied.
  StatusCounts beam1_optimal;
  std::map<int, StatusCounts> beam1_optimal_by_halfspaces;

  using AgainstTally = campaign::AgainstTally;
  std::optional<AgainstTally> against;  ///< set when kAgainstCheck is among `checks`

  /// `checks`: the tallied names (recorded_checks(settings)); empty: every catalogue check.
  explicit Summary(std::vector<std::string> checks = {});
  /// Adds a record: its outcome, and each of its checks (a check not among `checks`, a held beam1 whose witness
  /// says neither optimal nor sub-optimal, or an against witness outside kAgainstCheck's grammar, is a
  /// logic_error).
  void add(const SceneRecord& record);
};

}  // namespace hsx::campaign
