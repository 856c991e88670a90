#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/bsh/exact.hpp>
#include "algorithms/bsh/support_lists.hpp"

#include <boost/container_hash/hash.hpp>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <unordered_set>

namespace hsx::bsh {

const char* to_string(Method m) {
  switch (m) {
    case Method::GraphCut: return "graphcut";
    case Method::Beam: return "beam";
    case Method::BestFirst: return "best-first";
    case Method::BruteForce: return "brute-force";
    case Method::Exact: return "exact";
  }
  return "?";
}

std::optional<Method> method_from_string(const std::string& name) {
  for (Method m : {Method::GraphCut, Method::Beam, Method::BestFirst, Method::BruteForce, Method::Exact})
    if (name == to_string(m)) return m;
  return std::nullopt;
}

namespace {

using Clock = std::chrono::steady_clock;


/// A search state {r, b}: removed supports r (ascending) and the graph-cut boundary b without them. (The islands
/// of b are found again when the state is expanded: most states never are, and keeping them for all cost more.)
struct State {
  std::vector<int> removed;
  CutResult cut;
  int parent = -1;  // index into the search's archive
};

/// Every state a search made, by index. A deque: it grows by thousands of states without moving them, so a
/// reference to a state stays valid while its children are added.
using Archive = std::deque<State>;

/// Shared bookkeeping of one extract() call: statistics, limits and progress reports.
class SearchContext {
 public:
  SearchContext(const Problem& problem, const ExtractOptions& options)
      : problem_(problem), options_(options), start_(Clock::now()), last_report_(start_) {}

  const Problem& problem() const { return problem_; }
  const ExtractOptions& options() const { return options_; }
  SearchStats& stats() { return stats_; }
  std::string stopped_by;
  std::vector<Labelling> expanded;  // with record_states
  bool unseparated = false;  ///< a best-first pick had a competitor whose energy did not separate from it

  CutResult cut(const std::vector<int>& removed, const std::vector<signed char>& forced) {
    constraints_.removed.assign(problem_.support_count(), 0);
    for (int g : removed) constraints_.removed[g] = 1;
    constraints_.forced.assign(forced.begin(), forced.end());
    ++stats_.graph_cuts;
    std::function<bool()> stop;
    if (options_.time_limit > 0 || options_.cancel) stop = [this] { return !stop_reason().empty(); };
    CutResult result = graph_cut(problem_, constraints_, stop);
    if (result.stopped) stopped_by = stop_reason();  // its energy is -1: every caller drops it
    if (result.stopped && stopped_by.empty()) stopped_by = "cancelled";  // a cancel that said stop only once
    if (result.energy.missing_samples >= 0 && !result.certified) ++stats_.uncertified_cuts;
    return result;
  }

  /// True when a limit says stop; sets stopped_by. Also reports progress about twice a second.
  bool out_of_budget(long queue_size) {
    const auto now = Clock::now();
    if (options_.progress && now - last_report_ > std::chrono::milliseconds(500)) {
      last_report_ = now;
      SearchProgress p{stats_.states_expanded, queue_size, stats_.graph_cuts, best_feasible_energy(), std::nullopt};
      options_.progress(p);
    }
    if (options_.max_states > 0 && stats_.states_expanded >= options_.max_states) stopped_by = "max-states";
    return limit_reached();
  }

  /// True when the graph-cut or time limit says stop (checked before every graph cut); sets stopped_by.
  bool limit_reached() {
    if (options_.max_graph_cuts > 0 && stats_.graph_cuts >= options_.max_graph_cuts) stopped_by = "max-graph-cuts";
    const std::string why = stop_reason();
    if (!why.empty()) stopped_by = why;
    return !stopped_by.empty();
  }

  /// "time-limit" when it has run out, "cancelled" when ExtractOptions::cancel says stop, else "".
  std::string stop_reason() const {
    if (options_.time_limit > 0 && seconds() > options_.time_limit) return "time-limit";
    if (options_.cancel && options_.cancel()) return "cancelled";
    return "";
  }

  /// The oracle's options under this search's limits (`limit`: labellings it may enumerate).
  BruteForceOptions oracle(long limit) const {
    return BruteForceOptions{limit, options_.compare, options_.time_limit > 0 ? seconds_left() : 0,
                             options_.cancel};
  }

  /// Seconds left before the time limit (infinity without one; <= 0 when it has passed).
  double seconds_left() const {
    return options_.time_limit > 0 ? options_.time_limit - seconds() : std::numeric_limits<double>::infinity();
  }

  /// Remember the best sample-connected labelling seen, the answer when a limit stops the search.
  void offer_feasible(const CutResult& cut) {
    if (!best_feasible_ || compare(cut.energy, best_feasible_->energy, options_.compare) == Order::Less)
      best_feasible_ = cut;
  }
  std::optional<Energy> best_feasible_energy() const {
    if (!best_feasible_) return std::nullopt;
    return best_feasible_->energy;
  }
  const std::optional<CutResult>& best_feasible() const { return best_feasible_; }

  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  const Problem& problem_;
  const ExtractOptions& options_;
  SearchStats stats_;
  CutConstraints constraints_;  // the last cut's, its storage reused by the next
  Clock::time_point start_, last_report_;
  std::optional<CutResult> best_feasible_;
};

/// The certified cuts one search has made, asked before each new cut whether one of them already answers it.
/// A child's constraints only add removed supports, and a removed support only makes arcs infinite. So when the cut
/// of a removed set R (the smallest minimum cut, the source side graph_cut returns) has none of a larger removed set
/// R' on its boundary, it is the smallest minimum cut under R' as well (proofs/bsh.md entry 8 (e)): the same
/// labelling, energy and certificate that graph_cut would return. The forced labels are the search's, the same for
/// every cut it makes.
class KnownCuts {
 public:
  explicit KnownCuts(int supports) : words_((static_cast<std::size_t>(supports) + 63) / 64), query_(words_) {}

  /// Records the cut of the next archive state (states are added in archive order): made under removed set
  /// `removed` (ascending), a child of archive state `parent` (-1 for the root); `answer`: the state whose cut it
  /// took (answering), whose boundary words are copied, or -1. An uncertified cut is never offered as an answer.
  void add(const Problem& problem, int parent, const std::vector<int>& removed, const CutResult& cut, int answer) {
    const int k = static_cast<int>(usable_.size());
    removed_.resize(removed_.size() + words_, 0);
    boundary_.resize(boundary_.size() + words_, 0);
    for (int g : removed) set(removed_, k, g);
    if (answer >= 0)
      std::copy_n(boundary_.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(answer) * words_), words_,
                  boundary_.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(k) * words_));
    else if (cut.certified)
      for_each_boundary_support(problem, cut.labelling, [&](int g) { set(boundary_, k, g); });
    usable_.push_back(cut.certified ? 1 : 0);
    first_child_.push_back(-1);
    next_sibling_.push_back(-1);
    if (parent >= 0) {
      next_sibling_[k] = first_child_[parent];
      first_child_[parent] = k;
    }
  }

  /// An archive state whose cut is the cut under removed set `removed` (ascending), or -1. Only a state whose
  /// removed set lies in `removed` can answer, and a state's removed set contains its parent's: those states form
  /// a subtree of the search tree that holds the root, walked from the root. Which state answers does not matter
  /// (they all hold the same cut).
  int answering(const std::vector<int>& removed) {
    if (usable_.empty()) return -1;
    std::fill(query_.begin(), query_.end(), 0);
    for (int g : removed) query_[g / 64] |= std::uint64_t{1} << (g % 64);
    if (!removed_within(0)) return -1;
    stack_.assign(1, 0);
    while (!stack_.empty()) {
      const int k = stack_.back();
      stack_.pop_back();
      if (usable_[k] && boundary_avoids(k)) return k;
      for (int child = first_child_[k]; child >= 0; child = next_sibling_[child])
        if (removed_within(child)) stack_.push_back(child);
    }
    return -1;
  }

 private:
  // Each state's supports as `words_` 64-bit words, all states in one array (state k at k * words_): the walk
  // reads a few words per state, and one array keeps them together (a bitset object per state scattered them).
  void set(std::vector<std::uint64_t>& bits, int k, int g) const {
    bits[static_cast<std::size_t>(k) * words_ + static_cast<std::size_t>(g) / 64] |= std::uint64_t{1} << (g % 64);
  }
  bool removed_within(int k) const {  // state k's removed set lies in the query
    const std::uint64_t* w = removed_.data() + static_cast<std::size_t>(k) * words_;
    for (std::size_t i = 0; i < words_; ++i)
      if (w[i] & ~query_[i]) return false;
    return true;
  }
  bool boundary_avoids(int k) const {  // state k's boundary has no support of the query
    const std::uint64_t* w = boundary_.data() + static_cast<std::size_t>(k) * words_;
    for (std::size_t i = 0; i < words_; ++i)
      if (w[i] & query_[i]) return false;
    return true;
  }

  std::size_t words_;
  std::vector<std::uint64_t> removed_, boundary_;  ///< per state: its removed supports; its cut's boundary supports
  std::vector<char> usable_;                       ///< per state: its cut is certified
  std::vector<int> first_child_, next_sibling_;    ///< the search tree: per state, its last child; the one before
  std::vector<std::uint64_t> query_;               ///< scratch: the removed set asked about
  std::vector<int> stack_;                         ///< scratch for the walk
};

/// Deterministic total preference between states: certified energy first, then the removed set, then labels.
bool before(const State& a, const State& b, const CompareOptions& options) {
  const Order o = compare(a.cut.energy, b.cut.energy, options);
  if (o == Order::Less) return true;
  if (o == Order::Greater) return false;
  if (a.removed != b.removed) return a.removed < b.removed;
  return a.cut.labelling < b.cut.labelling;
}

/// The open states of a search. pop() returns the state before() prefers to every other open state, without
/// comparing it with all of them: states are kept ordered by missing samples, then by a certified double lower
/// bound `lo` of their boundary's measure (the sum of its supports' enclosures, Problem::support_enclosures,
/// rounded outward), with the upper bound `hi` beside it. The preferred state m has the fewest missing samples,
/// and |b_m| <= |b_t| <= hi_t for the first state t in that order, so it lies in the window of states with as
/// many missing samples and lo <= hi_t. pop() scans the window in order, keeping the state before() prefers so
/// far and widening the window to that state's hi; every state left outside is then proven no better than the
/// choice (more missing samples, or lo > hi of the choice). When before() is a total order (always, unless two
/// energies did not separate: Order::Tie) this is the minimum of the whole queue, the state a linear scan finds.
class Frontier {
 public:
  struct Key {
    long missing = 0;
    double lo = 0, hi = 0;  ///< certified bounds of the boundary's measure
    int state = -1;         ///< index into the archive
    bool operator<(const Key& o) const {
      if (missing != o.missing) return missing < o.missing;
      if (lo != o.lo) return lo < o.lo;
      return state < o.state;
    }
  };

  /// `archive` grows while the frontier lives; states are pushed by index.
  Frontier(const Problem& problem, const Archive& archive, const CompareOptions& compare)
      : problem_(problem), archive_(archive), compare_(compare) {}

  bool empty() const { return open_.empty(); }
  long size() const { return static_cast<long>(open_.size()); }

  void push(int state) {
    const CutResult& cut = archive_[state].cut;
    DoubleCombination sum;
    for_each_boundary_support(problem_, cut.labelling, [&](int g) {
      const auto& [lo, hi] = problem_.support_enclosures()[g];
      sum.add(1, DoubleBounds{lo, hi});
    });
    open_.insert(Key{cut.energy.missing_samples, sum.bounds().lo, sum.bounds().hi, state});
  }

  /// Removes and returns the preferred open state (see the class comment); the frontier is not empty.
  Key pop() {
    const auto first = open_.begin();
    auto best = first;
    double reach = first->hi;
    for (auto it = std::next(first); it != open_.end() && it->missing == first->missing && it->lo <= reach; ++it)
      if (before(archive_[it->state], archive_[best->state], compare_)) {
        best = it;
        reach = std::max(reach, best->hi);
      }
    const Key key = *best;
    open_.erase(best);
    return key;
  }

  /// Calls f(state) for every open state whose energy may equal or tie with `popped`'s (as many missing samples,
  /// lo <= popped.hi): every other open state is proven more costly.
  template <class F>
  void for_each_rival(const Key& popped, F f) const {
    for (auto it = open_.begin(); it != open_.end() && it->missing == popped.missing && it->lo <= popped.hi; ++it)
      f(it->state);
  }

  /// Beam: keeps the `width` preferred open states.
  void keep_best(int width) {
    if (size() <= width) return;
    std::vector<Key> kept;
    while (static_cast<int>(kept.size()) < width) kept.push_back(pop());
    open_.clear();
    open_.insert(kept.begin(), kept.end());
  }

 private:
  const Problem& problem_;
  const Archive& archive_;
  const CompareOptions& compare_;
  std::set<Key> open_;
};

std::vector<int> merged(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

struct SearchOutcome {
  bool found = false;
  Archive archive;
  int result = -1;
};

/// True when every open state's energy is certified greater than `bound`: `picked` (just popped) and its rivals
/// (every other open state is proven no cheaper than `picked`, so greater than `bound` as well).
bool all_above(const Archive& archive, const Frontier& queue, const Frontier::Key& picked,
               const Energy& bound, const CompareOptions& cmp) {
  if (compare(archive[picked.state].cut.energy, bound, cmp) != Order::Greater) return false;
  bool above = true;
  queue.for_each_rival(picked, [&](int other) {
    above = above && compare(archive[other].cut.energy, bound, cmp) == Order::Greater;
  });
  return above;
}

/// Fig. 9 from the state {base_removed, graph-cut}: best-first when beam_width <= 0, else a beam of that width.
/// `forced` fixes cell labels (tie enumeration). With `bound` (best-first only), the search gives up, found
/// false, once every open state costs more than `bound`: a state's descendants cost at least as much as it does
/// (their cuts have more supports removed), so no boundary it could still reach costs `bound` or less.
SearchOutcome search(SearchContext& ctx, const std::vector<int>& base_removed,
                     const std::vector<signed char>& forced, int beam_width, const Energy* bound = nullptr) {
  const Problem& problem = ctx.problem();
  const CompareOptions& cmp = ctx.options().compare;
  SearchOutcome out;
  if (ctx.limit_reached()) return out;
  // The removed sets met so far: only asked whether one is new, so hashed.
  std::unordered_set<std::vector<int>, boost::hash<std::vector<int>>> visited{base_removed};
  State root{base_removed, ctx.cut(base_removed, forced), -1};
  if (root.cut.energy.missing_samples < 0) return out;  // the constraints admit no labelling
  KnownCuts known(problem.support_count());
  known.add(problem, -1, root.removed, root.cut, -1);
  out.archive.push_back(std::move(root));
  Frontier queue(problem, out.archive, cmp);
  queue.push(0);
  ++ctx.stats().states_created;
  while (!queue.empty()) {
    if (ctx.out_of_budget(queue.size())) return out;
    const Frontier::Key picked = queue.pop();
    // Only while every cut is certified: an uncertified cut's energy need not be its constraints' minimum.
    if (bound && ctx.stats().uncertified_cuts == 0 && all_above(out.archive, queue, picked, *bound, cmp)) return out;
    const int current = picked.state;
    const State& state = out.archive[current];  // stays valid while children are added (Archive)
    ++ctx.stats().states_expanded;
    const Labelling& labelling = state.cut.labelling;
    if (ctx.options().record_states) ctx.expanded.push_back(labelling);
    const SampleConnectivity connectivity = sample_connectivity(problem, labelling);
    if (connectivity.sample_connected()) {
      // Optimal only if proven no worse than every state still queued (their descendants cost at least as much).
      if (beam_width <= 0)
        queue.for_each_rival(picked, [&](int other) {
          if (compare(out.archive[other].cut.energy, state.cut.energy, cmp) == Order::Tie)
            ctx.unseparated = true;
        });
      ctx.offer_feasible(state.cut);
      out.found = true;
      out.result = current;
      return out;
    }
    for (const std::vector<int>& set : removable_sets(problem, labelling, connectivity)) {
      std::vector<int> removed = merged(state.removed, set);
      if (!visited.insert(removed).second) continue;
      if (ctx.limit_reached()) return out;
      const int answer = known.answering(removed);
      if (answer >= 0) ++ctx.stats().reused_cuts;
      CutResult cut = answer >= 0 ? out.archive[answer].cut : ctx.cut(removed, forced);
      if (cut.energy.missing_samples < 0) continue;
      if (is_sample_connected(problem, cut.labelling)) ctx.offer_feasible(cut);
      known.add(problem, current, removed, cut, answer);
      out.archive.push_back(State{std::move(removed), std::move(cut), current});
      queue.push(static_cast<int>(out.archive.size()) - 1);
      ++ctx.stats().states_created;
    }
    if (beam_width > 0) queue.keep_best(beam_width);
    ctx.stats().max_queue = std::max(ctx.stats().max_queue, queue.size());
  }
  return out;
}

/// Labels that put support g on the boundary as `labelling` has it (its inside cell 1, the other 0).
bool force_on(const Problem& problem, int g, const Labelling& labelling, std::vector<signed char>& forced) {
  const SupportTerm& s = problem.supports()[g];
  const int inside = labelling[s.cell_a] ? s.cell_a : s.cell_b;
  const int outside = inside == s.cell_a ? s.cell_b : s.cell_a;
  if (forced[inside] == 0 || forced[outside] == 1) return false;
  forced[inside] = 1;
  forced[outside] = 0;
  return true;
}

/// Lawler-style enumeration of every optimal boundary. Any boundary b' != b inside a subspace either misses
/// a support of b that the subspace does not force (one sub-search per such support, forcing the ones before
/// it) or strictly contains b, which costs more. Each sub-search is complete (Prop. 5.2 holds under forced
/// labels and removed supports: the target satisfies them).
void enumerate_ties(SearchContext& ctx, const CutResult& optimum, ExtractResult& result) {
  const Problem& problem = ctx.problem();
  const CompareOptions& cmp = ctx.options().compare;
  struct Subspace {
    std::vector<int> removed;
    std::vector<signed char> forced;
    Labelling optimum;
  };
  std::vector<Subspace> work{{{}, std::vector<signed char>(problem.cell_count(), -1), optimum.labelling}};
  std::set<Labelling> found{optimum.labelling};
  result.ties.checked = true;
  while (!work.empty()) {
    Subspace space = std::move(work.back());
    work.pop_back();
    std::vector<signed char> forced = space.forced;
    for (int g : boundary_supports(problem, space.optimum)) {
      const SupportTerm& s = problem.supports()[g];
      const int inside = space.optimum[s.cell_a] ? s.cell_a : s.cell_b;
      const int outside = inside == s.cell_a ? s.cell_b : s.cell_a;
      const bool already_forced = forced[inside] == 1 && forced[outside] == 0;
      if (!already_forced && !std::binary_search(space.removed.begin(), space.removed.end(), g)) {
        std::vector<int> removed = merged(space.removed, {g});
        SearchOutcome sub = search(ctx, removed, forced, 0, &optimum.energy);  // a tie costs no more
        if (!ctx.stopped_by.empty()) {
          result.ties.capped = true;
          result.ties.stopped_by = ctx.stopped_by;
          result.ties.count = static_cast<int>(found.size());
          return;
        }
        if (sub.found) {
          const CutResult& cut = sub.archive[sub.result].cut;
          const Order o = compare(cut.energy, optimum.energy, cmp);
          if (o == Order::Equal || o == Order::Tie) {
            if (o == Order::Tie) result.ties.certified = false;
            if (found.insert(cut.labelling).second) {
              result.tied.push_back(cut.labelling);
              if (static_cast<int>(found.size()) >= ctx.options().max_ties) {
                result.ties.capped = true;
                result.ties.stopped_by = "max-ties";
                result.ties.count = static_cast<int>(found.size());
                return;
              }
            }
            work.push_back({removed, forced, cut.labelling});
          }
        }
      }
      if (!force_on(problem, g, space.optimum, forced)) break;  // nothing later in this subspace can keep g
    }
  }
  result.ties.count = static_cast<int>(found.size());
}

void fill_from_cut(const Problem& problem, const CutResult& cut, ExtractResult& result) {
  result.labelling = cut.labelling;
  result.energy = cut.energy;
  result.sample_connected = is_sample_connected(problem, cut.labelling);
}

/// Best-first at non-generic junctions: Prop. 5.2 rests on Prop. 5.1, which needs generic junctions (a
/// counterexample with three concurrent lines is kept in data/counterexamples), so the oracle certifies `found`
/// when it needs at most ExtractOptions::certify_limit labellings and the time limit allows; else the result
/// stays unproven. Returns the labellings the oracle enumerated.
long certify_with_oracle(SearchContext& ctx, const CutResult& found, ExtractResult& result) {
  const Problem& problem = ctx.problem();
  const ExtractOptions& options = ctx.options();
  const std::string where = std::to_string(problem.non_generic_junctions().size()) + " non-generic junction(s)";
  result.optimal = false;
  result.optimality_note = where + ": best-first is not proven complete here and the oracle is too large";
  if (options.certify_limit <= 0 || ctx.seconds_left() <= 0) return 0;
  BruteForceResult bf;
  try {
    bf = brute_force(problem, true, ctx.oracle(options.certify_limit));
  } catch (const LabellingLimitExceeded&) {
    return 0;
  }
  if (bf.stopped) {
    result.stopped_by = bf.stopped_by;
    result.optimality_note = where + ": best-first is not proven complete here and the oracle was stopped (" +
                             bf.stopped_by + ")";
    return bf.enumerated;
  }
  const Order o = compare(found.energy, bf.energy, options.compare);
  if (o == Order::Greater) {
    result.labelling = bf.optimal.front();
    result.energy = bf.energy;
    result.sample_connected = true;
    result.steps.clear();
    result.optimality_note = where + ": best-first missed the optimum (Prop. 5.1 fails there); this is the "
                                     "oracle's optimum";
  } else {
    result.optimality_note = where + ": optimality certified by exhaustive enumeration";
  }
  result.optimal = o != Order::Tie && bf.certified;
  result.ties.checked = true;
  result.ties.count = static_cast<int>(bf.optimal.size());
  result.ties.certified = bf.certified;
  for (const Labelling& l : bf.optimal)
    if (l != result.labelling) result.tied.push_back(l);
  return bf.enumerated;
}

ExtractResult run_brute_force(const Problem& problem, const ExtractOptions& options) {
  const auto start = Clock::now();
  const BruteForceResult bf =
      brute_force(problem, true, BruteForceOptions{options.brute_force_limit, options.compare, options.time_limit,
                                                   options.cancel});
  ExtractResult result;
  result.method = Method::BruteForce;
  result.labelling = bf.optimal.front();
  result.energy = bf.energy;
  result.sample_connected = true;
  if (bf.stopped) {
    // The best of the labellings enumerated before the time limit (or the cancel): not proven, ties not known.
    result.stopped_by = bf.stopped_by;
  } else {
    result.optimal = true;
    result.ties.checked = true;
    result.ties.count = static_cast<int>(bf.optimal.size());
    result.ties.certified = bf.certified;
    result.tied.assign(bf.optimal.begin() + 1, bf.optimal.end());
  }
  result.stats.labellings_enumerated = bf.enumerated;
  result.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace

ExtractResult extract(const Problem& problem, const ExtractOptions& options) {
  if (options.method == Method::BruteForce) return run_brute_force(problem, options);
  if (options.method == Method::Exact) return extract_exact(problem, options);
  SearchContext ctx(problem, options);
  ExtractResult result;
  result.method = options.method;
  const std::vector<signed char> free_labels(problem.cell_count(), -1);
  long stats_enumerated = 0;

  if (options.method == Method::GraphCut) {
    CutResult cut = ctx.cut({}, free_labels);
    result.stopped_by = ctx.stopped_by;
    if (cut.stopped) {  // the empty boundary, always admissible
      cut.labelling.assign(problem.cell_count(), 0);
      cut.energy = energy(problem, cut.labelling);
    }
    fill_from_cut(problem, cut, result);
    // A relaxed optimum that happens to be sample-connected is the BSH optimum.
    result.optimal = cut.certified && result.sample_connected;
    result.removed.assign(problem.support_count(), 0);
  } else {
    const int width = options.method == Method::Beam ? std::max(1, options.beam_width) : 0;
    SearchOutcome outcome = search(ctx, {}, free_labels, width);
    result.stopped_by = ctx.stopped_by;
    if (outcome.found) {
      const State& best = outcome.archive[outcome.result];
      fill_from_cut(problem, best.cut, result);
      result.removed.assign(problem.support_count(), 0);
      for (int g : best.removed) result.removed[g] = 1;
      for (int k = outcome.result; k >= 0; k = outcome.archive[k].parent)
        result.steps.insert(result.steps.begin(), outcome.archive[k].removed);
      const bool all_certified = ctx.stats().uncertified_cuts == 0;
      if (!all_certified) {
        // Some max flow met measures that did not separate: the answer may tie with another boundary.
        result.optimality_note = "a graph cut could not be certified (unseparated measures)";
        result.ties.certified = false;
      }
      if (options.method == Method::BestFirst) {
        result.optimal = all_certified;
        if (!problem.non_generic_junctions().empty() && all_certified)
          stats_enumerated = certify_with_oracle(ctx, best.cut, result);
      } else {
        // Beam results are optimal when they meet the unconstrained lower bound (the root graph cut).
        const Order o = compare(best.cut.energy, outcome.archive[0].cut.energy, options.compare);
        result.optimal = all_certified && o == Order::Equal;
      }
      if (ctx.unseparated) result.ties.certified = false;
      // A limit met here cuts only the tie enumeration (Ties::stopped_by): the optimum stays proven.
      if (options.method == Method::BestFirst && options.enumerate_ties && result.optimal && !result.ties.checked)
        enumerate_ties(ctx, best.cut, result);
    } else {
      // A limit stopped the search: the best sample-connected boundary seen, else the empty one.
      result.removed.assign(problem.support_count(), 0);
      if (ctx.best_feasible()) {
        fill_from_cut(problem, *ctx.best_feasible(), result);
      } else {
        result.labelling.assign(problem.cell_count(), 0);
        result.energy = energy(problem, result.labelling);
        result.sample_connected = true;
      }
      result.optimal = false;
    }
  }
  result.stats = ctx.stats();
  result.stats.labellings_enumerated = stats_enumerated;
  result.stats.seconds = ctx.seconds();
  result.expanded = std::move(ctx.expanded);
  return result;
}

namespace {

/// The oracle's constraints: "x = 1 => y = 1" for x the outside cell of a support and y its inside cell; a support
/// whose coincident halfspaces disagree ties its two cells together. Labellings are the sets closed under
/// `implies` that leave the outer cells (and everything that implies one) at 0.
struct Implications {
  std::vector<std::vector<int>> implies, implied_by;
  explicit Implications(const Problem& problem) : implies(problem.cell_count()), implied_by(problem.cell_count()) {
    for (const SupportTerm& s : problem.supports()) {
      // Only a-inside allowed: b = 1 forces a = 1; only b-inside: the reverse; neither: equal labels.
      if (!s.allow_b_inside) link(s.cell_b, s.cell_a);
      if (!s.allow_a_inside) link(s.cell_a, s.cell_b);
    }
  }
  void link(int x, int y) {
    implies[x].push_back(y);
    implied_by[y].push_back(x);
  }
};

/// k such that there are at least 2^k labellings, found greedily: k free cells (label -1 in `label`) no two of
/// which imply one another. Every subset of them, closed under `implies`, is a different labelling (no free cell
/// implies a fixed 0). Stops once k reaches `enough`.
int independent_cells(const Implications& g, const std::vector<signed char>& label, int enough) {
  const int n = static_cast<int>(label.size());
  std::vector<char> related(n, 0);
  int k = 0;
  std::vector<int> stack;
  for (int c = 0; c < n && k < enough; ++c) {
    if (label[c] >= 0 || related[c]) continue;
    ++k;
    for (const auto* edges : {&g.implies, &g.implied_by}) {
      stack.assign(1, c);
      std::vector<char> seen(n, 0);
      seen[c] = 1;
      while (!stack.empty()) {
        const int x = stack.back();
        stack.pop_back();
        related[x] = 1;
        for (int y : (*edges)[x])
          if (!seen[y]) {
            seen[y] = 1;
            stack.push_back(y);
          }
      }
    }
  }
  return k;
}

std::string limit_advice(long limit) {
  return "; the limit is " + std::to_string(limit) +
         ": raise it with --max-labellings (ExtractOptions::brute_force_limit) or use best-first";
}

/// Thrown inside the enumeration when the time limit runs out or the cancel says stop (caught by brute_force).
struct OutOfTime {
  const char* reason;  ///< "time-limit" or "cancelled"
};

/// Depth-first enumeration of the labellings: over the first unassigned cell, 0 then 1, with propagation of the
/// implications. Both values always propagate without conflict (a value forced by a neighbour would already be
/// assigned), so the tree is binary and the first leaf is the empty labelling. No allocation per node: one trail
/// and one propagation stack serve the whole enumeration.
class Enumerator {
 public:
  Enumerator(const Problem& problem, const Implications& g, const BruteForceOptions& options)
      : g_(g), options_(options), start_(Clock::now()), label_(problem.cell_count(), -1) {
    for (int k = 0; k < problem.cell_count(); ++k)
      if (problem.complex().cells[k].outer && !assign(k, 0))
        throw std::logic_error("brute force: outer cells forced inside");
    trail_.clear();
  }
  /// The labels after the outer cells are fixed: -1 free, 0 fixed.
  const std::vector<signed char>& root() const { return label_; }
  /// Calls leaf(labels) on every labelling; throws OutOfTime when the time limit runs out.
  void run(const std::function<void(const std::vector<signed char>&)>& leaf) { descend(0, leaf); }

 private:
  // Assign with propagation, recording every label set on trail_; returns false on a conflict.
  bool assign(int v, signed char value) {
    if (label_[v] >= 0) return label_[v] == value;
    label_[v] = value;
    trail_.push_back(v);
    stack_.assign(1, v);
    while (!stack_.empty()) {
      const int x = stack_.back();
      stack_.pop_back();
      for (int y : value ? g_.implies[x] : g_.implied_by[x]) {
        if (label_[y] == value) continue;
        if (label_[y] >= 0) return false;
        label_[y] = value;
        trail_.push_back(y);
        stack_.push_back(y);
      }
    }
    return true;
  }
  void descend(int from, const std::function<void(const std::vector<signed char>&)>& leaf) {
    if ((options_.time_limit > 0 || options_.cancel) && (++steps_ & 1023) == 0) {
      if (options_.time_limit > 0 &&
          std::chrono::duration<double>(Clock::now() - start_).count() > options_.time_limit)
        throw OutOfTime{"time-limit"};
      if (options_.cancel && options_.cancel()) throw OutOfTime{"cancelled"};
    }
    const int n = static_cast<int>(label_.size());
    int v = from;
    while (v < n && label_[v] >= 0) ++v;
    if (v == n) {
      leaf(label_);
      return;
    }
    for (signed char value : {0, 1}) {
      const std::size_t mark = trail_.size();
      if (assign(v, value)) descend(v + 1, leaf);
      while (trail_.size() > mark) {
        label_[trail_.back()] = -1;
        trail_.pop_back();
      }
    }
  }

  const Implications& g_;
  const BruteForceOptions& options_;
  Clock::time_point start_;
  std::vector<signed char> label_;
  std::vector<int> trail_, stack_;
  long steps_ = 0;
};

/// Recognises, without building an Energy or testing sample-connectedness, the labellings whose energy compare()
/// proves Greater than the best so far (most of them): brute force skips those, whether sample-connected or not,
/// as it would after the full test. The decision is compare()'s own: missing samples counted as energy() counts
/// them, then on equal counts the certified double sum of the supports on only one of the two boundaries
/// (DoubleCombination, the same terms added in the same order as compare() adds them, after a plain-double sum
/// that implies its verdict when it is clear); anything it does not prove Greater goes to the full test.
class GreaterScreen {
 public:
  explicit GreaterScreen(const Problem& problem) : problem_(problem) {
    const Complex& c = problem.complex();
    for (const SupportTerm& s : problem.supports())
      for (int p : s.patches)
        if (!c.patches[p].samples.empty())
          sampled_.push_back({s.cell_a, s.cell_b, c.patches[p].inside_cell,
                              static_cast<long>(c.patches[p].samples.size())});
  }
  /// The new best labelling (compare() found it Less than the previous one, or it is the first).
  void set_best(const std::vector<signed char>& label) {
    best_missing_ = missing(label);
    boundary(label, best_supports_);
    have_best_ = true;
  }
  /// True when compare(energy(label), best) is Greater.
  bool greater(const std::vector<signed char>& label) {
    if (!have_best_) return false;
    const long m = missing(label);
    if (m != best_missing_) return m > best_missing_;
    boundary(label, supports_);
    // First in plain doubles: the terms DoubleCombination would add (lo of a support only on this boundary, -hi
    // of one only on the best), summed in round-to-nearest. When that sum exceeds 4 (n + 1) 2^-52 times the sum
    // of the terms' magnitudes, the outward-rounded sum of the same n terms (error at most about n 2^-52 times
    // that, and the nearest sum's at most n 2^-53) has a positive lower end too: Greater, no rounding-mode switch.
    double sum = 0, magnitude = 0;
    long terms = 0;
    for_each_difference(supports_, best_supports_, [&](int g, int k) {
      const auto& e = problem_.support_enclosures()[g];
      const double x = k > 0 ? e.first : -e.second;
      sum += x;
      magnitude += std::fabs(x);
      ++terms;
    });
    if (std::isfinite(magnitude) && sum > 4 * static_cast<double>(terms + 1) * DBL_EPSILON * magnitude) return true;
    DoubleCombination bounds;  // undecided in doubles: exactly compare()'s first test
    for_each_difference(supports_, best_supports_, [&](int g, int k) {
      const auto& e = problem_.support_enclosures()[g];
      bounds.add(k, DoubleBounds{e.first, e.second});
    });
    return bounds.bounds().certain_sign() > 0;
  }

 private:
  struct SampledPatch {
    int cell_a, cell_b, inside_cell;
    long samples;
  };
  // Samples not covered: those of patches off b or on b reversed, as energy() counts them.
  long missing(const std::vector<signed char>& label) const {
    long m = problem_.total_samples();
    for (const SampledPatch& p : sampled_)
      if (label[p.cell_a] != label[p.cell_b] && label[p.inside_cell]) m -= p.samples;
    return m;
  }
  // The supports on the boundary of `label`, ascending (boundary_supports without a Labelling copy).
  void boundary(const std::vector<signed char>& label, std::vector<int>& out) const {
    out.clear();
    for (int g = 0; g < problem_.support_count(); ++g) {
      const SupportTerm& s = problem_.supports()[g];
      if (label[s.cell_a] != label[s.cell_b]) out.push_back(g);
    }
  }

  const Problem& problem_;
  std::vector<SampledPatch> sampled_;
  bool have_best_ = false;
  long best_missing_ = 0;
  std::vector<int> best_supports_, supports_;
};

/// Refuses before the real enumeration when there are more than `limit` labellings: at once when 2^k > limit for
/// k independent cells, else by counting them (no energies, no connectivity: much cheaper), up to limit + 1.
void refuse_above_limit(Enumerator& enumerate, const Implications& g, long limit) {
  int bits = 0;
  while (bits < 62 && (1L << bits) <= limit) ++bits;
  if (const int k = independent_cells(g, enumerate.root(), bits); k >= bits)
    throw LabellingLimitExceeded(limit, "brute force: at least 2^" + std::to_string(k) +
                                            " orientation-preserving labellings (" + std::to_string(k) +
                                            " cells whose labels are independent)" + limit_advice(limit));
  long count = 0;
  enumerate.run([&](const std::vector<signed char>&) {
    if (++count > limit)
      throw LabellingLimitExceeded(limit, "brute force: more than " + std::to_string(limit) +
                                              " orientation-preserving labellings" + limit_advice(limit));
  });
}

}  // namespace

BruteForceResult brute_force(const Problem& problem, bool connectivity, long limit, const CompareOptions& compare) {
  return brute_force(problem, connectivity, BruteForceOptions{limit, compare, 0, {}});
}

BruteForceResult brute_force(const Problem& problem, bool connectivity, const BruteForceOptions& options) {
  const Implications g(problem);
  Enumerator enumerate(problem, g, options);
  BruteForceResult result;
  bool have_best = false;
  GreaterScreen screen(problem);
  auto leaf = [&](const std::vector<signed char>& label) {
    ++result.enumerated;
    if (screen.greater(label)) return;  // compare() would say Greater: skipped, sample-connected or not
    Labelling l(label.begin(), label.end());
    if (connectivity && !is_sample_connected(problem, l)) return;
    Energy e = energy(problem, l);
    if (!have_best) {
      have_best = true;
      result.energy = e;
      result.optimal = {l};
      screen.set_best(label);
      return;
    }
    const Order o = bsh::compare(e, result.energy, options.compare);
    if (o == Order::Less) {
      result.energy = e;
      result.optimal = {l};
      result.certified = true;
      screen.set_best(label);
    } else if (o == Order::Equal || o == Order::Tie) {
      if (o == Order::Tie) result.certified = false;
      result.optimal.push_back(l);
    }
  };
  try {
    refuse_above_limit(enumerate, g, options.limit);
    enumerate.run(leaf);
  } catch (const OutOfTime& out) {
    result.stopped = true;
    result.stopped_by = out.reason;
  }
  if (!have_best) {
    if (result.stopped) {  // stopped before the first leaf: the empty labelling, always admissible
      result.optimal = {Labelling(problem.cell_count(), 0)};
      result.energy = energy(problem, result.optimal.front());
      return result;
    }
    throw std::logic_error("brute force: no labelling (the empty one always exists)");
  }
  return result;
}

}  // namespace hsx::bsh
