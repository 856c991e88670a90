// Campaigns: see campaign.hpp.
#include <hsx/algorithms/campaign/campaign.hpp>

#include <hsx/algorithms/bsh/checks.hpp>
#include <hsx/algorithms/bsh/sample_scene.hpp>
#include <hsx/algorithms/bsh/samples.hpp>
#include <hsx/algorithms/campaign/scene_checks.hpp>
#include <hsx/complex/carry_solid2.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include "kernel/threads.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <new>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <type_traits>

namespace hsx::campaign {
namespace {

using Clock = std::chrono::steady_clock;

/// check_all's results do not match the catalogue: a bug of this file, never a scene's outcome.
class CatalogueMismatch : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// The campaign's own checks (scene_checks.hpp), run by check_own.
enum class Own { None, Prop61, PropB1, Beam, Describability, NhRep };

/// A catalogue entry: a check_all result (`own` None), recognised by its name starting with `prefix` and, when
/// `suffix` is not empty, ending with it; or one of the campaign's own checks.
struct Entry {
  CheckInfo info;
  const char* prefix;
  const char* suffix;
  bsh::Check id;
  Own own = Own::None;
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
      {{"prop61", "Prop. 6.1: GENERATE-SAMPLES with best-first reproduces the intended shape by its greedy rounds alone"},
       "", "", bsh::Check::Existence, Own::Prop61},
      {{"propB1", "Prop. B.1: GENERATE-SAMPLES with beam K=1 reproduces the intended shape by its greedy rounds alone"},
       "", "", bsh::Check::Existence, Own::PropB1},
      {{"beam2", "Beam K=2: admissible, energy >= optimum (its witness says optimal or sub-optimal)"},
       "", "", bsh::Check::Existence, Own::Beam},
      {{"beam4", "Beam K=4: admissible, energy >= optimum (its witness says optimal or sub-optimal)"},
       "", "", bsh::Check::Existence, Own::Beam},
      {{"describability", "Shapiro-Vossler describability = BHC builds a verified tree (intended shape, else optimum)"},
       "", "", bsh::Check::Existence, Own::Describability},
      {{"nhrep", "NH-Rep Thm. 4.3 tree checks and natural-halfspace evaluation (intended shape, else optimum)"},
       "", "", bsh::Check::Existence, Own::NhRep},
  };
  return e;
}

bool is_beam_check(const std::string& name) { return name == "beam1" || beam_width_of(name).has_value(); }

/// A check's place in catalogue order: its entry's index; every beamK (K >= 2) at beam2's entry, ordered by K.
std::pair<std::size_t, int> catalogue_rank(const std::string& name) {
  const auto it = std::find_if(entries().begin(), entries().end(), [&](const Entry& e) { return name == e.info.name; });
  const std::optional<int> width = beam_width_of(name);
  if (width) {
    const auto beam2 = std::find_if(entries().begin(), entries().end(),
                                    [](const Entry& e) { return std::string(e.info.name) == "beam2"; });
    return {static_cast<std::size_t>(beam2 - entries().begin()), *width};
  }
  if (it == entries().end()) throw std::logic_error("campaign: catalogue_rank of an unknown check");
  return {static_cast<std::size_t>(it - entries().begin()), 0};
}

bool is_known_check(const std::string& name) {
  return beam_width_of(name).has_value() ||
         std::any_of(entries().begin(), entries().end(), [&](const Entry& e) { return name == e.info.name; });
}

/// `names` in catalogue order (catalogue_rank), each once.
std::vector<std::string> in_catalogue_order(std::vector<std::string> names) {
  std::sort(names.begin(), names.end(),
            [](const std::string& a, const std::string& b) { return catalogue_rank(a) < catalogue_rank(b); });
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

/// The verdicts a held describability or nhrep witness starts with (scene_checks.hpp); empty for other checks.
const std::vector<std::string>& verdicts_of(const std::string& check) {
  static const std::vector<std::string> none, describability = {"describable", "not describable"},
                                              nhrep = {"tree correct", "describable, tree fails", "not describable"};
  return check == "describability" ? describability : check == "nhrep" ? nhrep : none;
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

std::vector<std::string> selected(const CampaignSettings& s) { return s.checks.empty() ? default_checks() : s.checks; }

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

const std::vector<std::string>& default_checks() {
  static const std::vector<std::string> d = [] {
    std::vector<std::string> out;
    for (const Entry& e : entries())
      if (e.own == Own::None) out.push_back(e.info.name);
    return out;
  }();
  return d;
}

std::optional<int> beam_width_of(const std::string& name) {
  if (name.size() < 5 || name.size() > 8 || name.compare(0, 4, "beam") != 0 || name[4] == '0' ||
      name.find_first_not_of("0123456789", 4) != std::string::npos)
    return std::nullopt;
  const int k = std::stoi(name.substr(4));
  if (k < 2 || k > kMaxBeamWidth) return std::nullopt;
  return k;
}

std::vector<std::string> parse_check_list(const std::string& list) {
  std::vector<std::string> out;
  if (list.empty() || list == "default") return default_checks();
  if (list == "all") {
    for (const Entry& e : entries()) out.push_back(e.info.name);
    return out;
  }
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (!is_known_check(name)) {
      std::string known;
      for (const Entry& e : entries()) known += std::string(known.empty() ? "" : ", ") + e.info.name;
      throw InputError("--checks: unknown check \"" + name + "\" (the checks: " + known + ", beamK for any K in 2.." +
                       std::to_string(kMaxBeamWidth) + "; or default, or all)");
    }
    if (std::find(out.begin(), out.end(), name) != out.end())
      throw InputError("--checks: \"" + name + "\" is named twice");
    out.push_back(name);
  }
  if (!list.empty() && list.back() == ',') throw InputError("--checks: an empty name after the last comma");
  return in_catalogue_order(out);
}

std::vector<std::string> with_beam_widths(std::vector<std::string> checks, const std::string& widths) {
  if (checks.empty()) checks = default_checks();
  std::stringstream in(widths);
  std::string item;
  while (std::getline(in, item, ',')) {
    const std::string name = "beam" + item;
    if (name != "beam1" && !beam_width_of(name))
      throw InputError("--beam-widths: \"" + item + "\" is not a beam width (a whole number 1.." +
                       std::to_string(kMaxBeamWidth) + ", no leading zero)");
    checks.push_back(name);
  }
  if (widths.empty() || widths.back() == ',') throw InputError("--beam-widths: an empty width");
  return in_catalogue_order(checks);
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

const char* to_string(SamplePolicy p) {
  switch (p) {
    case SamplePolicy::Uniform: return "uniform";
    case SamplePolicy::Intended: return "intended";
  }
  return "?";
}

std::optional<SamplePolicy> sample_policy_from_string(const std::string& s) {
  for (SamplePolicy p : {SamplePolicy::Uniform, SamplePolicy::Intended})
    if (s == to_string(p)) return p;
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
    if (!is_known_check(c)) throw InputError("checks: unknown check \"" + c + "\"");
  for (std::size_t k = 0; k < s.extra.size(); ++k) {
    const ExtraCheck& e = s.extra[k];
    if (e.name.empty()) throw InputError("extra checks: an empty name");
    if (is_known_check(e.name))
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
  if (s.dimension != 2 && s.dimension != 3) throw InputError("--dimension: 2 or 3");
  if (s.dimension == 3) {
    if (!s.extra.empty()) throw InputError("--against: 2D campaigns only (the graded programs read 2D inputs)");
    try {
      validate(s.scene3);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("3D generator settings: ") + e.what());
    }
    return;
  }
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

/// The largest orientation-preserving part of `solid`: while a patch has its outside cell inside and its inside
/// cell outside, its outside cell goes outside (problem.hpp's "outside cell inside => inside cell inside").
void make_orientation_preserving(const Complex& complex, std::vector<char>& solid) {
  for (bool changed = true; changed;) {
    changed = false;
    for (const Patch& p : complex.patches)
      if (p.inside_cell >= 0 && p.outside_cell >= 0 && solid[static_cast<std::size_t>(p.outside_cell)] &&
          !solid[static_cast<std::size_t>(p.inside_cell)]) {
        solid[static_cast<std::size_t>(p.outside_cell)] = 0;
        changed = true;
      }
  }
}

/// SamplePolicy::Intended's step 2 (campaign.hpp).
std::vector<char> draw_intended(const Complex& complex, Random& rng) {
  std::vector<char> solid;
  for (int draw = 0; draw < 8; ++draw) {
    solid.assign(complex.cells.size(), 0);
    for (std::size_t k = 0; k < complex.cells.size(); ++k)
      if (!complex.cells[k].outer) solid[k] = rng.in(0, 1) == 1 ? 1 : 0;
    make_orientation_preserving(complex, solid);
    if (std::find(solid.begin(), solid.end(), 1) != solid.end()) break;
  }
  if (!bsh::is_orientation_preserving(bsh::Problem(complex), solid))
    throw std::logic_error("campaign: the intended solid is not orientation-preserving after its closure");
  return solid;
}

/// A generated scene: the scene and its patterns, and under SamplePolicy::Intended its arrangement (within the
/// campaign's limits) and intended solid.
struct Generated {
  RandomScene generated;
  std::optional<Arranged2> arranged;
  std::vector<char> intended;
};

/// SamplePolicy::Intended (campaign.hpp). Throws InputError when the arrangement limits refuse the scene.
Generated generate_intended(const CampaignSettings& s, std::uint64_t index) {
  Generated g;
  Random rng(item_seed(s.seed, index));
  RandomSceneSettings settings = s.scene;
  settings.max_samples = 0;
  g.generated = random_scene(settings, rng);
  const Arranged2 bare = arrange(g.generated.scene, s.limits);
  const std::vector<char> solid = draw_intended(bare.complex, rng);
  CompareOptions compare;
  compare.max_bits = s.precision_bits;
  const std::vector<int> patches = bsh::initial_samples(bare.complex, solid, compare);
  Scene2 sampled = bsh::scene_with_samples(g.generated.scene, bare, patches, g.generated.scene.description);
  validate_and_resolve(sampled);
  g.generated.scene = std::move(sampled);
  g.arranged = arrange(g.generated.scene, bare.arrangement);  // the samples placed on the same arrangement
  g.intended = carry_solid_over(bare.arrangement, solid, g.arranged->arrangement);
  return g;
}

/// The time and cancellation of one scene's checks.
class Deadline {
 public:
  Deadline(double seconds, std::function<bool()> cancel)
      : limited_(seconds > 0), end_(Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                      std::chrono::duration<double>(std::max(seconds, 0.0)))),
        cancel_(std::move(cancel)) {}
  bool expired() const { return limited_ && Clock::now() >= end_; }
  bool stop() const { return expired() || (cancel_ && cancel_()); }
  /// Seconds left (0: no limit; at least a nanosecond when limited, so a spent limit is not "none").
  double left() const {
    return limited_ ? std::max(std::chrono::duration<double>(end_ - Clock::now()).count(), 1e-9) : 0;
  }
  const std::function<bool()>& cancel() const { return cancel_; }

 private:
  bool limited_;
  Clock::time_point end_;
  std::function<bool()> cancel_;
};

/// One scene's checking context: the scene, the campaign's limits, and the optimum, computed once when a check
/// needs it.
struct SceneChecks {
  const CampaignSettings& settings;
  const Complex& complex;             ///< the scene's (2D or 3D)
  /// check_nhrep on the scene (2D: check_nhrep, 3D: check_nhrep3), for (name, solid, what).
  std::function<CheckOutcome(const std::string&, const std::vector<char>&, const std::string&)> nhrep;
  const std::vector<char>& intended;  ///< empty: none
  const Deadline& deadline;
  std::optional<bsh::ExtractResult> optimum;

  CheckLimits limits() const {
    CheckLimits l;
    l.max_states = settings.max_states;
    l.max_graph_cuts = settings.max_graph_cuts;
    l.compare.max_bits = settings.precision_bits;
    l.certify_limit = settings.brute_force_limit;
    const Deadline* d = &deadline;
    l.cancel = [d] { return d->stop(); };
    return l;
  }
  const bsh::ExtractResult& the_optimum() {
    if (!optimum) optimum = reference_optimum(complex, limits());
    return *optimum;
  }
};

/// check_all's selected checks (`wanted`, in catalogue order) on the scene.
std::vector<CheckOutcome> run_check_all(SceneChecks& c, const std::vector<const Entry*>& wanted) {
  if (wanted.empty()) return {};
  bsh::CheckOptions options;
  options.brute_force_limit = c.settings.brute_force_limit;
  options.compare.max_bits = c.settings.precision_bits;
  options.max_states = c.settings.max_states;
  options.max_graph_cuts = c.settings.max_graph_cuts;
  options.cancel = c.deadline.cancel();
  options.time_limit = c.deadline.left();
  for (const Entry* e : wanted) options.only.push_back(e->id);
  const std::vector<bsh::CheckResult> results = bsh::check_all(c.complex, options);
  if (results.size() != wanted.size())
    throw CatalogueMismatch("campaign: check_all gave " + std::to_string(results.size()) + " results, expected " +
                            std::to_string(wanted.size()) + " (update the catalogue in campaign.cpp)");
  std::vector<CheckOutcome> out;
  for (std::size_t k = 0; k < results.size(); ++k) {
    const Entry& e = *wanted[k];
    if (!starts_with(results[k].name, e.prefix) || !ends_with(results[k].name, e.suffix))
      throw CatalogueMismatch("campaign: check_all's result " + std::to_string(k) + " is \"" + results[k].name +
                              "\", expected \"" + e.prefix + "...\" (update the catalogue in campaign.cpp)");
    out.push_back({e.info.name, from_bsh(results[k].status), results[k].witness});
  }
  return out;
}

/// The solid describability and nhrep run on: the intended shape, else the optimum (nullopt, with `why`, when the
/// optimum was not proven).
std::optional<std::vector<char>> shape_for(SceneChecks& c, std::string& what, std::string& why) {
  if (!c.intended.empty()) {
    what = "the intended shape";
    return c.intended;
  }
  what = "the optimum";
  const bsh::ExtractResult& o = c.the_optimum();
  if (!o.optimal) {
    why = o.stopped_by.empty() ? "the optimum was not proven" : "the optimum stopped by " + o.stopped_by;
    return std::nullopt;
  }
  return o.labelling;
}

/// One of the campaign's own checks on the scene: `name` (an entry's, or beamK), `own` its kind.
CheckOutcome run_own(SceneChecks& c, const std::string& name, Own own) {
  if (c.deadline.stop())
    return {name, CheckStatus::Skipped, "the time limit was spent (or the run was cancelled) before this check"};
  CheckOutcome out;
  switch (own) {
    case Own::Prop61:
    case Own::PropB1:
      if (c.intended.empty())
        return {name, CheckStatus::Skipped,
                "not run: no intended shape (the samples are uniform; --sample-policy intended gives one)"};
      out = check_generate_samples(name, c.complex, c.intended,
                                   own == Own::Prop61 ? bsh::Method::BestFirst : bsh::Method::Beam, c.limits());
      break;
    case Own::Beam:
      out = check_beam_optimality(name, c.complex, *beam_width_of(name), c.the_optimum(), c.limits());
      break;
    case Own::Describability:
    case Own::NhRep: {
      std::string what, why;
      const std::optional<std::vector<char>> solid = shape_for(c, what, why);
      if (!solid) return {name, CheckStatus::Stopped, why};
      out = own == Own::Describability ? check_describability(name, c.complex, *solid, what)
                                         : c.nhrep(name, *solid, what);
      break;
    }
    case Own::None: throw std::logic_error("campaign: run_own on a check_all check");
  }
  if (out.status == CheckStatus::Stopped && c.deadline.expired()) out.witness += " (the scene's time limit)";
  return out;
}

}  // namespace

namespace {

/// check_arranged's body for either dimension: `complex` the scene's, `nhrep` its NH-Rep check.
std::vector<CheckOutcome> check_complex(
    const CampaignSettings& s, const Complex& complex,
    std::function<CheckOutcome(const std::string&, const std::vector<char>&, const std::string&)> nhrep,
    const std::vector<char>& intended, double time_limit, const std::function<bool()>& cancel) {
  if (!intended.empty() && intended.size() != complex.cells.size())
    throw std::invalid_argument("check_arranged: the intended solid needs one flag per cell");
  const std::vector<std::string> checks = selected(s);
  const Deadline deadline(time_limit, cancel);
  SceneChecks c{s, complex, std::move(nhrep), intended, deadline, std::nullopt};
  std::vector<const Entry*> of_check_all;
  std::vector<std::pair<std::string, Own>> own;
  for (const std::string& name : in_catalogue_order(checks)) {
    const auto e = std::find_if(entries().begin(), entries().end(), [&](const Entry& x) { return name == x.info.name; });
    if (e == entries().end()) own.emplace_back(name, Own::Beam);  // beamK beyond the catalogue's
    else if (e->own == Own::None) of_check_all.push_back(&*e);
    else own.emplace_back(name, e->own);
  }
  std::vector<CheckOutcome> out = run_check_all(c, of_check_all);
  for (const auto& [name, kind] : own) out.push_back(run_own(c, name, kind));
  return out;
}

}  // namespace

std::vector<CheckOutcome> check_arranged(const CampaignSettings& s, const Scene2& scene, const Arranged2& arranged,
                                         const std::vector<char>& intended, double time_limit,
                                         const std::function<bool()>& cancel) {
  return check_complex(
      s, arranged.complex,
      [&](const std::string& name, const std::vector<char>& solid, const std::string& what) {
        return check_nhrep(name, scene, arranged, solid, what);
      },
      intended, time_limit, cancel);
}

std::vector<CheckOutcome> check_arranged(const CampaignSettings& s, const Scene3& scene, const Arranged3& arranged,
                                         const std::vector<char>& intended, double time_limit,
                                         const std::function<bool()>& cancel) {
  return check_complex(
      s, arranged.complex,
      [&](const std::string& name, const std::vector<char>& solid, const std::string& what) {
        return check_nhrep3(name, scene, arranged, solid, what);
      },
      intended, time_limit, cancel);
}

namespace {

/// check_scene with the scene's time limit counted from `start` (run_scene's: before generating the scene), and,
/// when the generator already arranged it (SamplePolicy::Intended), its arrangement and intended solid.
void keep_scene(SceneRecord& r, const Scene2& scene) { r.scene = scene; }
void keep_scene(SceneRecord& r, const Scene3& scene) { r.scene3 = scene; }

/// Scene2 with Arranged2, Scene3 with Arranged3 (a 3D scene comes arranged from its generator).
template <class Scene, class Arranged>
SceneRecord check_scene_since(const CampaignSettings& s, const Scene& scene, std::uint64_t index,
                              const std::function<bool()>& cancel, Clock::time_point start,
                              std::optional<Arranged> arranged = std::nullopt,
                              const std::vector<char>& intended = {}) {
  const std::vector<std::string> checks = recorded_checks(s);
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  SceneRecord r;
  r.index = index;
  r.seed = s.seed;
  r.halfspaces = static_cast<int>(scene.halfspaces.size());
  r.samples = static_cast<int>(scene.samples.size());
  for (std::size_t k = 0; k < intended.size(); ++k)
    if (intended[k]) r.intended.push_back(static_cast<int>(k));
  try {
    if (!arranged) {
      try {
        arranged = arrange(scene, s.limits);
      } catch (const InputError& e) {
        r.outcome = SceneOutcome::Refused;
        r.note = e.what();
        all_checks(r, checks, CheckStatus::Skipped, "not run: the scene was refused: " + r.note);
        return r;
      }
    }
    r.cells = static_cast<long>(arranged->complex.cells.size());
    r.patches = static_cast<long>(arranged->complex.patches.size());
    // The scene's time limit covers its arrangement too: the checks get what is left (at least a nanosecond, so
    // that a spent limit skips them instead of meaning "no limit").
    const double left = s.time_limit > 0 ? std::max(s.time_limit - elapsed(), 1e-9) : 0;
    r.checks = check_arranged(s, scene, *arranged, intended, left, cancel);
  } catch (const CatalogueMismatch&) {
    throw;  // the catalogue does not match check_all: a bug of this file, not of the scene
  } catch (const std::bad_alloc&) {
    throw;  // out of memory ends the run (exit 2): it says nothing about the input
  } catch (const std::exception& e) {
    r.outcome = SceneOutcome::Error;
    r.note = std::string("the library threw: ") + e.what();
    all_checks(r, checks, CheckStatus::Skipped, "not run: " + r.note);
    arranged.reset();
  }
  r.timed_out = s.time_limit > 0 && elapsed() >= s.time_limit;
  // The extra checks, outside the time limit and outside the try: what they throw is not the scene's outcome.
  if constexpr (std::is_same_v<Scene, Scene2>)
    if (arranged)
      for (const ExtraCheck& e : s.extra) {
      CheckOutcome outcome = e.run(index, scene, *arranged);
      outcome.check = e.name;
      r.checks.push_back(std::move(outcome));
    }
  if (r.failed()) keep_scene(r, scene);
  return r;
}

/// A record of a scene the generator could not make: refused by the arrangement limits, or an error.
/// `halfspaces`: the scene's halfspace count as far as the generator made it (the summary tallies it there).
SceneRecord not_generated(const CampaignSettings& s, std::uint64_t index, SceneOutcome outcome, std::string note,
                          int halfspaces) {
  SceneRecord r;
  r.index = index;
  r.seed = s.seed;
  r.halfspaces = halfspaces;
  r.outcome = outcome;
  r.note = std::move(note);
  all_checks(r, recorded_checks(s), CheckStatus::Skipped,
             outcome == SceneOutcome::Refused ? "not run: the scene was refused: " + r.note : "not run: " + r.note);
  return r;
}

}  // namespace

SceneRecord check_scene(const CampaignSettings& s, const Scene2& scene, std::uint64_t index,
                        const std::function<bool()>& cancel) {
  return check_scene_since<Scene2, Arranged2>(s, scene, index, cancel, Clock::now());
}

SceneRecord check_scene(const CampaignSettings& s, const Scene2& scene, Arranged2 arranged,
                        const std::vector<char>& intended, std::uint64_t index, const std::function<bool()>& cancel) {
  if (!intended.empty() && intended.size() != arranged.complex.cells.size())
    throw std::invalid_argument("check_scene: the intended solid needs one flag per cell");
  return check_scene_since<Scene2, Arranged2>(s, scene, index, cancel, Clock::now(), std::move(arranged), intended);
}

SceneRecord check_scene(const CampaignSettings& s, const Scene3& scene, Arranged3 arranged,
                        const std::vector<char>& intended, std::uint64_t index, const std::function<bool()>& cancel) {
  if (!intended.empty() && intended.size() != arranged.complex.cells.size())
    throw std::invalid_argument("check_scene: the intended solid needs one flag per cell");
  return check_scene_since<Scene3, Arranged3>(s, scene, index, cancel, Clock::now(), std::move(arranged), intended);
}

namespace {

/// The halfspace count of 2D scene `index` before its samples: random_scene without samples (no arrangement; the
/// same halfspaces under either sample policy), or 0 when even that throws.
int halfspaces_drawn(const CampaignSettings& s, std::uint64_t index) {
  RandomSceneSettings bare = s.scene;
  bare.max_samples = 0;
  try {
    return static_cast<int>(random_scene(bare, s.seed, index).scene.halfspaces.size());
  } catch (const std::bad_alloc&) {
    throw;  // out of memory ends the run (exit 2): it says nothing about the input
  } catch (const std::exception&) {
    return 0;
  }
}

/// run_scene for CampaignSettings::dimension 3.
SceneRecord run_scene3(const CampaignSettings& s, std::uint64_t index, const std::function<bool()>& cancel) {
  const Clock::time_point start = Clock::now();
  const bool intended = s.sample_policy == SamplePolicy::Intended;
  CampaignScene3 g;
  int generated = 0;
  try {
    g = random_campaign_scene3(s.scene3, intended ? Samples3::Intended : Samples3::Uniform, s.seed, index, s.limits,
                               &generated);
  } catch (const InputError& e) {
    return not_generated(s, index, SceneOutcome::Refused, std::string("generating it: ") + e.what(), generated);
  } catch (const std::bad_alloc&) {
    throw;  // out of memory ends the run (exit 2): it says nothing about the input
  } catch (const std::exception& e) {
    return not_generated(s, index, SceneOutcome::Error, std::string("the generator threw: ") + e.what(), generated);
  }
  const std::vector<char> none;
  SceneRecord r = check_scene_since<Scene3, Arranged3>(s, g.scene, index, cancel, start, std::move(g.arranged),
                                                       intended ? g.intended : none);
  r.degeneracies = g.degeneracies;
  return r;
}

}  // namespace

Scene2 generate_scene(const CampaignSettings& s, std::uint64_t index) {
  if (s.dimension != 2) throw std::invalid_argument("generate_scene: a 2D campaign's scenes only");
  return s.sample_policy == SamplePolicy::Intended ? generate_intended(s, index).generated.scene
                                                   : random_scene(s.scene, s.seed, index).scene;
}

/// Whether `limits` refuse nothing the default ArrangementLimits accept (each limit none, or at least the default).
bool admits_defaults(const ArrangementLimits& limits) {
  const ArrangementLimits defaults;
  const auto admits = [](long limit, long default_limit) { return limit == 0 || limit >= default_limit; };
  return admits(limits.max_cells, defaults.max_cells) && admits(limits.max_side_entries, defaults.max_side_entries);
}

/// The arrangement of a generated scene for its checks, reusing the one the generator built to choose the samples
/// (arranging a scene again costs about a tenth of a campaign's time at 8 halfspaces). nullopt when the campaign's
/// limits are stricter than the generator's defaults, or when placing the samples fails: check_scene_since then
/// arranges the scene itself, and refuses or reports it as it always did.
std::optional<Arranged2> generated_arrangement(const CampaignSettings& s, const RandomScene& generated) {
  if (!generated.arrangement || !admits_defaults(s.limits)) return std::nullopt;
  try {
    return arrange(generated.scene, *generated.arrangement);
  } catch (const std::bad_alloc&) {
    throw;  // out of memory ends the run (exit 2): it says nothing about the input
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

SceneRecord run_scene(const CampaignSettings& s, std::uint64_t index, const std::function<bool()>& cancel) {
  if (s.dimension == 3) return run_scene3(s, index, cancel);
  const Clock::time_point start = Clock::now();
  Generated g;
  try {
    if (s.sample_policy == SamplePolicy::Intended) g = generate_intended(s, index);
    else {
      g.generated = random_scene(s.scene, s.seed, index);
      g.arranged = generated_arrangement(s, g.generated);
    }
  } catch (const InputError& e) {  // choosing samples arranges the scene: the arrangement limits refused it
    return not_generated(s, index, SceneOutcome::Refused,
                         s.sample_policy == SamplePolicy::Intended
                             ? std::string("arranging it to choose its intended shape: ") + e.what()
                             : std::string("choosing its samples (under the default arrangement limits, which the "
                                           "campaign's do not change): ") + e.what(),
                         halfspaces_drawn(s, index));
  } catch (const std::bad_alloc&) {
    throw;  // out of memory ends the run (exit 2): it says nothing about the input
  } catch (const std::exception& e) {
    return not_generated(s, index, SceneOutcome::Error, std::string("the generator threw: ") + e.what(),
                         halfspaces_drawn(s, index));
  }
  SceneRecord r = check_scene_since<Scene2, Arranged2>(s, g.generated.scene, index, cancel, start,
                                                       std::move(g.arranged), g.intended);
  for (Degeneracy d : g.generated.degeneracies) r.degeneracies.push_back(to_string(d));
  return r;
}

int run_scenes(const CampaignSettings& settings, const std::vector<std::uint64_t>& indices, int jobs,
               const std::function<void(SceneRecord&&)>& sink, const std::function<bool()>& cancel) {
  validate(settings);
  if (jobs < 1) throw InputError("--jobs: at least 1");
  const std::size_t n = indices.size();
  jobs = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(jobs), n));  // no thread without a scene
  if (jobs <= 1) {
    for (std::uint64_t i : indices) sink(run_scene(settings, i, cancel));
    return 1;
  }
  // Positions [written, written + window) may be worked on; position p waits in slots[p % window]. The window is
  // wide so that one slow scene (seconds, against milliseconds for most) does not stop the other threads until it
  // ends: they go on up to 512 scenes each past it, holding their records (a few kilobytes each) meanwhile.
  const std::size_t window = std::min(n, 512 * static_cast<std::size_t>(jobs));
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
  // A thread the system refuses leaves fewer threads: the same records.
  std::vector<std::thread> pool = start_threads(0, jobs, [&work](int) { work(); });
  if (pool.empty()) {  // not even one: this thread runs them (nothing has been started or written yet)
    for (std::uint64_t i : indices) sink(run_scene(settings, i, cancel));
    return 1;
  }
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
  return static_cast<int>(pool.size());
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
  if (checks.empty()) checks = default_checks();
  for (const std::string& name : checks) {
    by_check[name];
    if (is_beam_check(name)) beam_optimal[name];
    for (const std::string& v : verdicts_of(name)) verdicts[name][v];
  }
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
    if (is_beam_check(c.check) && c.status == CheckStatus::Held) {
      const bool optimal = starts_with(c.witness, "optimal:");
      if (!optimal && !starts_with(c.witness, "sub-optimal:"))
        throw std::logic_error("campaign summary: " + c.check + "'s witness \"" + c.witness +
                               "\" says neither optimal nor sub-optimal");
      const CheckStatus s = optimal ? CheckStatus::Held : CheckStatus::Failed;
      beam_optimal[c.check].add(s);
      beam_optimal_by_halfspaces[c.check][record.halfspaces].add(s);
      if (c.check == "beam1") {
        beam1_optimal.add(s);
        beam1_optimal_by_halfspaces[record.halfspaces].add(s);
      }
    }
    if (!verdicts_of(c.check).empty() && c.status == CheckStatus::Held) {
      const std::string verdict = c.witness.substr(0, c.witness.find(':'));
      const std::vector<std::string>& known = verdicts_of(c.check);
      if (std::find(known.begin(), known.end(), verdict) == known.end())
        throw std::logic_error("campaign summary: " + c.check + "'s witness \"" + c.witness + "\" has no verdict");
      ++verdicts[c.check][verdict];
      ++verdicts_by_halfspaces[c.check][record.halfspaces][verdict];
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
