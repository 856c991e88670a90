// Campaigns: see campaign.hpp.
#include <hsx/algorithms/campaign/campaign.hpp>

#include <hsx/algorithms/bsh/checks.hpp>
#include <hsx/complex/from_arrangement2.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace hsx::campaign {
namespace {

using Clock = std::chrono::steady_clock;

/// check_all's results do not match the catalogue: a bug of this file, never a scene's outcome.
class CatalogueMismatch : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// A catalogue entry with how its check_all result is recognised: the name starts with `prefix` and, when
/// `suffix` is not empty, ends with it.
struct Entry {
  CheckInfo info;
  const char* prefix;
  const char* suffix;
  bsh::Check id;
};

const std::vector<Entry>& entries() {
  static const std::vector<Entry> e = {
      {{"existence", "Sec. 4.1 (existence): the empty boundary is admissible"},
       "Sec. 4.1", "", bsh::Check::Existence},
      {{"prop52", "Prop. 5.2: best-first = brute force (or = exact branch and bound when brute force is too large)"},
       "Prop. 5.2", "", bsh::Check::Prop52},
      {{"prop51", "Prop. 5.1 (removable sets) on every state best-first expanded"},
       "Prop. 5.1", "", bsh::Check::Prop51},
      {{"beam1", "Beam K=1: admissible, energy >= optimum (its witness says optimal or sub-optimal)"},
       "Beam K=1", "", bsh::Check::Beam},
      {{"prop41-optimum", "Prop. 4.1: one sample per patch reproduces the optimum"},
       "Prop. 4.1", "on the optimum", bsh::Check::Prop41Optimum},
      {{"prop41-beam", "Prop. 4.1: one sample per patch reproduces the beam result"},
       "Prop. 4.1", "on the beam result", bsh::Check::Prop41Beam},
      {{"uniqueness", "Sec. 4.2: the optimum is unique, or its ties are reported"},
       "Sec. 4.2", "", bsh::Check::Uniqueness},
      {{"certificates", "Eqs. 2-4: every graph cut certified (flow feasible, value = energy)"},
       "Eqs. 2-4", "", bsh::Check::Certificates},
      {{"manifold", "Sec. 3.1: orientation-preserving => manifold (junction parity) on the optimum"},
       "Sec. 3.1", "", bsh::Check::Manifold},
  };
  return e;
}

bool starts_with(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }
bool ends_with(const std::string& s, const std::string& p) {
  return s.size() >= p.size() && s.compare(s.size() - p.size(), p.size(), p) == 0;
}

CheckStatus from_bsh(bsh::CheckResult::Status s) {
  switch (s) {
    case bsh::CheckResult::Pass: return CheckStatus::Held;
    case bsh::CheckResult::Fail: return CheckStatus::Failed;
    case bsh::CheckResult::Skipped: return CheckStatus::Skipped;
    case bsh::CheckResult::Stopped: return CheckStatus::Stopped;
  }
  throw std::logic_error("campaign: unknown check status");
}

std::vector<std::string> selected(const CampaignSettings& s) {
  if (!s.checks.empty()) return s.checks;
  std::vector<std::string> all;
  for (const Entry& e : entries()) all.push_back(e.info.name);
  return all;
}

bool is_selected(const std::vector<std::string>& checks, const std::string& name) {
  return std::find(checks.begin(), checks.end(), name) != checks.end();
}

/// Every recorded check with one status and witness (a refused or failing scene).
void all_checks(SceneRecord& r, const std::vector<std::string>& checks, CheckStatus status, const std::string& why) {
  r.checks.clear();
  for (const std::string& c : checks) r.checks.push_back({c, status, why});
}

/// The "suboptimal: gap M missing samples, measure D; ..." witness's (M, D); nullopt when it is not of that form.
std::optional<std::pair<long, double>> against_gap(const std::string& witness) {
  const std::string head = "suboptimal: gap ", mid = " missing samples, measure ";
  if (!starts_with(witness, head)) return std::nullopt;
  const std::size_t m_end = witness.find(mid, head.size());
  if (m_end == std::string::npos) return std::nullopt;
  const std::size_t d_begin = m_end + mid.size(), d_end = witness.find(';', d_begin);
  if (d_end == std::string::npos) return std::nullopt;
  const std::string m = witness.substr(head.size(), m_end - head.size()), d = witness.substr(d_begin, d_end - d_begin);
  if (m.empty() || m.find_first_not_of("0123456789") != std::string::npos || m.size() > 12 || d.empty() ||
      d.find_first_not_of("0123456789.-+e") != std::string::npos)
    return std::nullopt;
  try {
    std::size_t used = 0;
    const double value = std::stod(d, &used);
    if (used != d.size()) return std::nullopt;
    return std::make_pair(std::stol(m), value);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

const std::vector<CheckInfo>& check_catalogue() {
  static const std::vector<CheckInfo> c = [] {
    std::vector<CheckInfo> out;
    for (const Entry& e : entries()) out.push_back(e.info);
    return out;
  }();
  return c;
}

std::vector<std::string> parse_check_list(const std::string& list) {
  std::vector<bool> wanted(entries().size(), false);
  if (list.empty() || list == "all") wanted.assign(entries().size(), true);
  else {
    std::stringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
      const auto it = std::find_if(entries().begin(), entries().end(),
                                   [&](const Entry& e) { return name == e.info.name; });
      if (it == entries().end()) {
        std::string known;
        for (const Entry& e : entries()) known += std::string(known.empty() ? "" : ", ") + e.info.name;
        throw InputError("--checks: unknown check \"" + name + "\" (the checks: " + known + "; or all)");
      }
      const std::size_t k = static_cast<std::size_t>(it - entries().begin());
      if (wanted[k]) throw InputError("--checks: \"" + name + "\" is named twice");
      wanted[k] = true;
    }
    if (!list.empty() && list.back() == ',') throw InputError("--checks: an empty name after the last comma");
  }
  std::vector<std::string> out;
  for (std::size_t k = 0; k < entries().size(); ++k)
    if (wanted[k]) out.push_back(entries()[k].info.name);
  return out;
}

const char* to_string(CheckStatus s) {
  switch (s) {
    case CheckStatus::Held: return "held";
    case CheckStatus::Failed: return "failed";
    case CheckStatus::Skipped: return "skipped";
    case CheckStatus::Stopped: return "stopped";
  }
  return "?";
}

std::optional<CheckStatus> check_status_from_string(const std::string& s) {
  for (CheckStatus c : {CheckStatus::Held, CheckStatus::Failed, CheckStatus::Skipped, CheckStatus::Stopped})
    if (s == to_string(c)) return c;
  return std::nullopt;
}

const char* to_string(SceneOutcome o) {
  switch (o) {
    case SceneOutcome::Checked: return "checked";
    case SceneOutcome::Refused: return "refused";
    case SceneOutcome::Error: return "error";
  }
  return "?";
}

std::optional<SceneOutcome> scene_outcome_from_string(const std::string& s) {
  for (SceneOutcome o : {SceneOutcome::Checked, SceneOutcome::Refused, SceneOutcome::Error})
    if (s == to_string(o)) return o;
  return std::nullopt;
}

bool SceneRecord::failed() const {
  if (outcome == SceneOutcome::Error) return true;
  return std::any_of(checks.begin(), checks.end(), [](const CheckOutcome& c) { return c.status == CheckStatus::Failed; });
}

bool SceneRecord::operator==(const SceneRecord& o) const {
  return index == o.index && seed == o.seed && halfspaces == o.halfspaces && cells == o.cells &&
         patches == o.patches && samples == o.samples && degeneracies == o.degeneracies && outcome == o.outcome &&
         note == o.note && timed_out == o.timed_out && checks == o.checks;
}

std::vector<std::string> recorded_checks(const CampaignSettings& s) {
  std::vector<std::string> names = selected(s);
  for (const ExtraCheck& e : s.extra) names.push_back(e.name);
  return names;
}

void validate(const CampaignSettings& s) {
  for (const std::string& c : s.checks)
    if (!std::any_of(entries().begin(), entries().end(), [&](const Entry& e) { return c == e.info.name; }))
      throw InputError("checks: unknown check \"" + c + "\"");
  for (std::size_t k = 0; k < s.extra.size(); ++k) {
    const ExtraCheck& e = s.extra[k];
    if (e.name.empty()) throw InputError("extra checks: an empty name");
    if (std::any_of(entries().begin(), entries().end(), [&](const Entry& c) { return e.name == c.info.name; }))
      throw InputError("extra checks: \"" + e.name + "\" is a catalogue check's name");
    for (std::size_t j = 0; j < k; ++j)
      if (s.extra[j].name == e.name) throw InputError("extra checks: \"" + e.name + "\" is named twice");
    if (!e.run) throw InputError("extra checks: \"" + e.name + "\" has no function");
  }
  if (s.brute_force_limit < 1) throw InputError("--max-labellings: must be at least 1");
  if (s.max_states < 0) throw InputError("--max-states: must be >= 0");
  if (s.max_graph_cuts < 0) throw InputError("--max-graph-cuts: must be >= 0");
  if (s.precision_bits < 64) throw InputError("--precision: at least 64 bits");
  if (!(s.time_limit >= 0) || !std::isfinite(s.time_limit)) throw InputError("--time-limit: a finite number >= 0");
  if (s.limits.max_cells < 0 || s.limits.max_side_entries < 0) throw InputError("arrangement limits: must be >= 0");
  try {
    // The generator's own validation of its settings, without the arrangement that choosing samples builds.
    RandomSceneSettings g = s.scene;
    g.max_samples = std::min(g.max_samples, 0);
    (void)random_scene(g, s.seed, 0);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("generator settings: ") + e.what());
  }
}

namespace {

/// check_scene with the scene's time limit counted from `start` (run_scene's: before generating the scene).
SceneRecord check_scene_since(const CampaignSettings& s, const Scene2& scene, std::uint64_t index,
                              const std::function<bool()>& cancel, Clock::time_point start) {
  const std::vector<std::string> checks = recorded_checks(s);
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  SceneRecord r;
  r.index = index;
  r.seed = s.seed;
  r.halfspaces = static_cast<int>(scene.halfspaces.size());
  r.samples = static_cast<int>(scene.samples.size());
  std::optional<Arranged2> arranged;
  try {
    try {
      arranged = arrange(scene, s.limits);
    } catch (const InputError& e) {
      r.outcome = SceneOutcome::Refused;
      r.note = e.what();
      all_checks(r, checks, CheckStatus::Skipped, "not run: the scene was refused: " + r.note);
      return r;
    }
    r.cells = static_cast<long>(arranged->complex.cells.size());
    r.patches = static_cast<long>(arranged->complex.patches.size());
    bsh::CheckOptions options;
    options.brute_force_limit = s.brute_force_limit;
    options.compare.max_bits = s.precision_bits;
    options.max_states = s.max_states;
    options.max_graph_cuts = s.max_graph_cuts;
    options.cancel = cancel;
    // The scene's time limit covers its arrangement too: the checks get what is left (at least a nanosecond, so
    // that a spent limit skips them instead of meaning "no limit").
    if (s.time_limit > 0) options.time_limit = std::max(s.time_limit - elapsed(), 1e-9);
    // Only the selected checks are computed; check_all gives them in catalogue order.
    std::vector<const Entry*> wanted;
    for (const Entry& e : entries())
      if (is_selected(checks, e.info.name)) {
        wanted.push_back(&e);
        options.only.push_back(e.id);
      }
    const std::vector<bsh::CheckResult> results = bsh::check_all(arranged->complex, options);
    if (results.size() != wanted.size())
      throw CatalogueMismatch("campaign: check_all gave " + std::to_string(results.size()) + " results, expected " +
                              std::to_string(wanted.size()) + " (update the catalogue in campaign.cpp)");
    for (std::size_t k = 0; k < results.size(); ++k) {
      const Entry& e = *wanted[k];
      if (!starts_with(results[k].name, e.prefix) || !ends_with(results[k].name, e.suffix))
        throw CatalogueMismatch("campaign: check_all's result " + std::to_string(k) + " is \"" + results[k].name +
                                "\", expected \"" + e.prefix + "...\" (update the catalogue in campaign.cpp)");
      r.checks.push_back({e.info.name, from_bsh(results[k].status), results[k].witness});
    }
  } catch (const CatalogueMismatch&) {
    throw;  // the catalogue does not match check_all: a bug of this file, not of the scene
  } catch (const std::exception& e) {
    r.outcome = SceneOutcome::Error;
    r.note = std::string("the library threw: ") + e.what();
    all_checks(r, checks, CheckStatus::Skipped, "not run: " + r.note);
    arranged.reset();
  }
  r.timed_out = s.time_limit > 0 && elapsed() >= s.time_limit;
  // The extra checks, outside the time limit and outside the try: what they throw is not the scene's outcome.
  if (arranged)
    for (const ExtraCheck& e : s.extra) {
      CheckOutcome outcome = e.run(index, scene, *arranged);
      outcome.check = e.name;
      r.checks.push_back(std::move(outcome));
    }
  if (r.failed()) r.scene = scene;
  return r;
}

}  // namespace

SceneRecord check_scene(const CampaignSettings& s, const Scene2& scene, std::uint64_t index,
                        const std::function<bool()>& cancel) {
  return check_scene_since(s, scene, index, cancel, Clock::now());
}

SceneRecord run_scene(const CampaignSettings& s, std::uint64_t index, const std::function<bool()>& cancel) {
  const Clock::time_point start = Clock::now();
  std::optional<RandomScene> generated;
  try {
    generated = random_scene(s.scene, s.seed, index);
  } catch (const InputError& e) {  // choosing samples arranges the scene: the arrangement limits refused it
    SceneRecord r;
    r.index = index;
    r.seed = s.seed;
    r.outcome = SceneOutcome::Refused;
    r.note = std::string("choosing its samples (under the default arrangement limits, which the campaign's do not "
                         "change): ") + e.what();
    all_checks(r, recorded_checks(s), CheckStatus::Skipped, "not run: the scene was refused: " + r.note);
    return r;
  } catch (const std::exception& e) {
    SceneRecord r;
    r.index = index;
    r.seed = s.seed;
    r.outcome = SceneOutcome::Error;
    r.note = std::string("the generator threw: ") + e.what();
    all_checks(r, recorded_checks(s), CheckStatus::Skipped, "not run: " + r.note);
    return r;
  }
  SceneRecord r = check_scene_since(s, generated->scene, index, cancel, start);
  for (Degeneracy d : generated->degeneracies) r.degeneracies.push_back(to_string(d));
  return r;
}

void run_scenes(const CampaignSettings& settings, const std::vector<std::uint64_t>& indices, int jobs,
                const std::function<void(SceneRecord&&)>& sink, const std::function<bool()>& cancel) {
  validate(settings);
  if (jobs < 1) throw InputError("--jobs: at least 1");
  const std::size_t n = indices.size();
  if (jobs == 1 || n <= 1) {
    for (std::uint64_t i : indices) sink(run_scene(settings, i, cancel));
    return;
  }
  // Positions [written, written + window) may be worked on; position p waits in slots[p % window].
  const std::size_t window = 4 * static_cast<std::size_t>(jobs);
  std::mutex m;
  std::condition_variable cv;
  std::vector<std::optional<SceneRecord>> slots(window);
  std::size_t next = 0, written = 0;
  bool stop = false;
  std::exception_ptr worker_error;
  const auto work = [&] {
    std::unique_lock<std::mutex> lock(m);
    for (;;) {
      cv.wait(lock, [&] { return stop || next >= n || next < written + window; });
      if (stop || next >= n) return;
      const std::size_t p = next++;
      lock.unlock();
      std::optional<SceneRecord> record;
      std::exception_ptr error;
      try {
        record = run_scene(settings, indices[p], cancel);
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      if (error) {
        if (!worker_error) worker_error = error;
        stop = true;
      } else {
        slots[p % window] = std::move(record);
      }
      cv.notify_all();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < jobs; ++t) pool.emplace_back(work);
  std::exception_ptr sink_error;
  while (true) {
    std::unique_lock<std::mutex> lock(m);
    cv.wait(lock, [&] { return stop || written >= n || slots[written % window].has_value(); });
    if (stop || written >= n) break;
    SceneRecord record = std::move(*slots[written % window]);
    slots[written % window].reset();
    ++written;
    cv.notify_all();
    lock.unlock();
    try {
      sink(std::move(record));
    } catch (...) {
      sink_error = std::current_exception();
      lock.lock();
      stop = true;
      cv.notify_all();
      break;
    }
  }
  for (std::thread& t : pool) t.join();
  if (sink_error) std::rethrow_exception(sink_error);
  if (worker_error) std::rethrow_exception(worker_error);
}

std::vector<std::uint64_t> shard_indices(std::uint64_t start, std::uint64_t count, std::uint64_t shard,
                                         std::uint64_t shards) {
  if (shards < 1 || shard >= shards) throw InputError("--shard: i/k with 0 <= i < k");
  if (count > 0 && count - 1 > std::numeric_limits<std::uint64_t>::max() - start)
    throw InputError("--start + --count: beyond the largest index 2^64 - 1");
  std::vector<std::uint64_t> out;
  if (shard >= count) return out;
  out.reserve(static_cast<std::size_t>((count - shard + shards - 1) / shards));
  for (std::uint64_t j = shard; j < count; j += shards) {
    out.push_back(start + j);
    if (shards > count - j) break;  // j + shards would pass count (and might wrap)
  }
  return out;
}

RateInterval wilson95(long successes, long trials) {
  if (trials <= 0) return {0, 1};
  const double z = 1.959963984540054, n = static_cast<double>(trials), p = successes / n;
  const double denominator = 1 + z * z / n;
  const double centre = (p + z * z / (2 * n)) / denominator;
  const double half = z * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denominator;
  // The ends are exact at 0 and 1 successes (rounding would give 1e-17 and 1 - 1e-16).
  return {successes == 0 ? 0.0 : std::max(0.0, centre - half), successes == trials ? 1.0 : std::min(1.0, centre + half)};
}

double StatusCounts::held_rate() const {
  return held + failed == 0 ? 0 : static_cast<double>(held) / static_cast<double>(held + failed);
}
RateInterval StatusCounts::held_interval() const { return wilson95(held, held + failed); }

void StatusCounts::add(CheckStatus s) {
  switch (s) {
    case CheckStatus::Held: ++held; break;
    case CheckStatus::Failed: ++failed; break;
    case CheckStatus::Skipped: ++skipped; break;
    case CheckStatus::Stopped: ++stopped; break;
  }
}

Summary::Summary(std::vector<std::string> c) : checks(std::move(c)) {
  if (checks.empty())
    for (const Entry& e : entries()) checks.push_back(e.info.name);
  for (const std::string& name : checks) by_check[name];
  if (std::find(checks.begin(), checks.end(), kAgainstCheck) != checks.end()) against.emplace();
}

void Summary::add(const SceneRecord& record) {
  ++scenes;
  switch (record.outcome) {
    case SceneOutcome::Checked: ++checked; break;
    case SceneOutcome::Refused: ++refused; break;
    case SceneOutcome::Error: ++errors; break;
  }
  if (record.timed_out) ++timed_out;
  if (record.failed()) ++failed_scenes;
  for (const CheckOutcome& c : record.checks) {
    const auto it = by_check.find(c.check);
    if (it == by_check.end()) throw std::logic_error("campaign summary: check \"" + c.check + "\" not tallied");
    it->second.add(c.status);
    by_check_and_halfspaces[c.check][record.halfspaces].add(c.status);
    if (c.check == "beam1" && c.status == CheckStatus::Held) {
      const bool optimal = starts_with(c.witness, "optimal:");
      if (!optimal && !starts_with(c.witness, "sub-optimal:"))
        throw std::logic_error("campaign summary: beam1's witness \"" + c.witness +
                               "\" says neither optimal nor sub-optimal");
      const CheckStatus s = optimal ? CheckStatus::Held : CheckStatus::Failed;
      beam1_optimal.add(s);
      beam1_optimal_by_halfspaces[record.halfspaces].add(s);
    }
    if (c.check == kAgainstCheck) {
      AgainstTally& t = *against;
      const auto bad = [&] {
        return std::logic_error("campaign summary: the against witness \"" + c.witness + "\" does not fit its " +
                                to_string(c.status) + " status");
      };
      switch (c.status) {
        case CheckStatus::Held:
          if (!starts_with(c.witness, "optimal:")) throw bad();
          ++t.optimal;
          break;
        case CheckStatus::Failed:
          if (const auto gap = against_gap(c.witness)) {
            ++t.suboptimal;
            t.gaps.insert(std::upper_bound(t.gaps.begin(), t.gaps.end(), *gap), *gap);
          } else if (starts_with(c.witness, "invalid:")) {
            ++t.invalid;
          } else if (starts_with(c.witness, "no answer:")) {
            ++t.no_answer;
          } else {
            throw bad();
          }
          break;
        case CheckStatus::Stopped:
          if (!starts_with(c.witness, "undecided:")) throw bad();
          ++t.undecided;
          break;
        case CheckStatus::Skipped: ++t.not_run; break;
      }
    }
  }
}

}  // namespace hsx::campaign
