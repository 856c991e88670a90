// EXTRACT-BOUNDARY (BSH paper, Fig. 9): the sample-connected BSH boundary by search over graph cuts, plus the
// exhaustive oracle that checks it on small inputs.
#pragma once

#include <hsx/algorithms/bsh/graph_cut.hpp>
#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/geometry/scene.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hsx::bsh {

enum class Method {
  GraphCut,   ///< Section 5.1 only: optimal without sample-connectedness
  Beam,       ///< Fig. 9 with the queue pruned to K states (the paper's practical setting, K = 1)
  BestFirst,  ///< Fig. 9, complete (Prop. 5.2)
  BruteForce, ///< every orientation-preserving labelling: the oracle
  Exact       ///< branch and bound over orientation-preserving labellings (bsh/exact.hpp): complete, any junctions
};
const char* to_string(Method m);
std::optional<Method> method_from_string(const std::string& name);

/// A proven lower bound on an energy, lexicographic like Energy: no labelling of the region it bounds has fewer
/// missing samples, and those with exactly `missing_samples` have a measure >= `measure` (a double rounded down:
/// the largest double for measures beyond it). A gap (SearchStats) is a difference of such values, inf beyond it.
struct EnergyBound {
  long missing_samples = 0;
  double measure = 0;
};

struct SearchProgress {
  long states_expanded = 0;  ///< exact: branch-and-bound nodes expanded
  long queue_size = 0;
  long graph_cuts = 0;
  std::optional<Energy> best_energy;  ///< best sample-connected energy found so far
  std::optional<EnergyBound> lower_bound;  ///< exact: the proven lower bound on the optimum so far
};

/// Limits. A limit that stops a search returns the best sample-connected boundary found so far, not proven optimal,
/// with ExtractResult::stopped_by naming it; one that stops only the tie enumeration after the optimum was proven
/// leaves `optimal` true and says so in Ties::stopped_by. max_states and max_graph_cuts are deterministic (the
/// same input stops at the same point on every machine); time_limit is not: where it stops depends on the
/// machine's speed and load. max_states and max_graph_cuts are checked before every graph cut, time_limit also
/// before every augmenting path inside a graph cut's max flow and every 1024 steps of brute force's enumeration.
/// `cancel` is asked wherever time_limit is checked (a host's stop button or Ctrl-C: the Python module's).
/// How the exact method (exact.hpp) branches on a node whose candidate has an island.
enum class ExactBranching {
  /// On the island itself (proofs/bsh.md Lemma 10.6): its patches taken off one by one, or all kept and one
  /// patch next to it put on; every child excludes the candidate. Far fewer nodes on large scenes.
  Islands,
  /// On one undecided cell of the island, the child keeping the candidate's value reusing its cut: the rule of
  /// hsx before Islands. The proposition checkers (checks.hpp, hsx campaign) keep it, because their records count
  /// the search's graph cuts and must stay reproducible.
  Cells,
};

struct ExtractOptions {
  Method method = Method::Beam;
  int beam_width = 1;
  long max_states = 0;          ///< expanded states before stopping (0: no limit)
  long max_graph_cuts = 0;      ///< graph cuts before stopping (0: no limit)
  long max_nodes = 0;           ///< exact: branch-and-bound nodes expanded before stopping (0: no limit)
  ExactBranching exact_branching = ExactBranching::Islands;  ///< exact: how a node with an island branches
  double time_limit = 0;        ///< seconds before stopping (0: no limit), brute force included
  bool enumerate_ties = true;   ///< complete methods: find every optimal boundary (up to max_ties)
  int max_ties = 16;
  /// Orientation-preserving labellings brute force may enumerate: it refuses up front when it can prove there are
  /// more (LabellingLimitExceeded), and stops with that exception when it meets one more.
  long brute_force_limit = 1L << 22;
  /// Best-first on a complex with non-generic junctions (where Prop. 5.2 is not proven) is certified by the
  /// oracle when it needs at most this many labellings; 0 disables it.
  long certify_limit = 200000;
  CompareOptions compare;
  bool record_states = false;   ///< keep the labelling of every expanded state (ExtractResult::expanded)
  /// Called about twice a second during long searches (the CLI prints it on stderr); may be empty.
  std::function<void(const SearchProgress&)> progress;
  /// Asked wherever time_limit is checked (see above), so it must be cheap; true stops the search as the time
  /// limit does, with stopped_by "cancelled" (the best sample-connected boundary so far, not proven). It is
  /// called on the searching thread; to stop from another thread, read an atomic flag. May be empty.
  std::function<bool()> cancel;
};

struct Ties {
  int count = 1;           ///< optimal boundaries found (>= 1)
  bool checked = false;    ///< the method looked for other optimal boundaries (complete methods only)
  bool certified = true;   ///< every tie is proven (exactly equal energies); false: some only unseparated
  bool capped = false;     ///< the enumeration stopped early (stopped_by says why): there may be more than count
  /// Why the enumeration stopped early: "max-ties" (ExtractOptions::max_ties reached) or the limit that cut it
  /// ("time-limit", "max-states", "max-graph-cuts", "cancelled"); "" when it finished (or did not run).
  std::string stopped_by;
};

struct SearchStats {
  long graph_cuts = 0;
  long uncertified_cuts = 0;
  /// Searches: states whose cut an earlier cut of the same search provably is (proofs/bsh.md entry 8 (e)), taken
  /// from it instead of made again (not counted in graph_cuts)
  long reused_cuts = 0;
  long states_expanded = 0;
  long states_created = 0;
  long max_queue = 0;
  long labellings_enumerated = 0;  ///< brute force
  // Exact (branch and bound, bsh/exact.hpp): the proof of optimality in numbers.
  long nodes = 0;               ///< nodes expanded (popped from the queue and not pruned there)
  long nodes_created = 0;       ///< nodes whose bound was computed
  long pruned_by_bound = 0;     ///< nodes dropped because their lower bound exceeds the incumbent
  long pruned_by_islands = 0;   ///< nodes dropped by the island rule (no completion is sample-connected)
  long island_branches = 0;     ///< nodes branched on an island of their candidate (removed, or connected)
  long certified_bounds = 0;    ///< exact certified graph cuts run to decide a bound the fast one left open
  EnergyBound lower_bound;      ///< proven lower bound on the optimum at the end (= the energy when optimal)
  EnergyBound gap;              ///< incumbent - lower_bound at the end: (missing samples, measure) differences
  EnergyBound max_gap;          ///< the largest such gap over the search (lexicographic)
  double seconds = 0;
};

struct ExtractResult {
  Method method = Method::Beam;
  bool optimal = false;          ///< proven: the least-energy orientation-preserving sample-connected boundary
  Labelling labelling;
  Energy energy;
  bool sample_connected = false;
  std::vector<char> removed;     ///< per support: removed in the returned state (searches)
  /// Beam search: the removed sets of the states along the path to the result (BSH Fig. 10).
  std::vector<std::vector<int>> steps;
  Ties ties;
  std::vector<Labelling> tied;   ///< the other optimal labellings when ties.count > 1
  /// The limit that stopped the search for the optimum: "" (finished), "max-states", "max-graph-cuts", "max-nodes" (exact),
  /// "time-limit", "cancelled" (ExtractOptions::cancel; then optimal is false). A limit that cut only the tie
  /// enumeration is in ties.stopped_by.
  std::string stopped_by;
  std::string optimality_note;   ///< how optimality was decided when the search alone could not prove it
  std::vector<Labelling> expanded;  ///< with ExtractOptions::record_states: every expanded state's boundary
  SearchStats stats;
};

/// Brute force has more orientation-preserving labellings than its limit: a refusal of the input (exit 2 in the
/// hsx program, whose option for the limit is --max-labellings), not an internal error.
class LabellingLimitExceeded : public InputError {
 public:
  /// `limit`: the limit that was exceeded; `what`: the message, naming the limit.
  LabellingLimitExceeded(long limit, const std::string& what) : InputError(what), limit(limit) {}
  long limit;
};

/// Runs `options.method` on the problem. Never fails on valid input: a limit returns the best sample-connected
/// boundary found so far with optimal = false (the empty boundary is always sample-connected).
/// Throws LabellingLimitExceeded when brute force would exceed options.brute_force_limit.
ExtractResult extract(const Problem& problem, const ExtractOptions& options);

/// The oracle: every orientation-preserving labelling (closed sets of "outside cell inside => inside cell
/// inside"), enumerated without visiting all 2^cells; returns the least-energy sample-connected ones (all ties).
/// `connectivity` false: ignore sample-connectedness (to check the graph cut).
struct BruteForceResult {
  std::vector<Labelling> optimal;   ///< every least-energy labelling (ties), in enumeration order
  Energy energy;
  bool certified = true;            ///< every comparison that picked them was proven
  long enumerated = 0;
  /// BruteForceOptions::time_limit ran out or `cancel` said stop: `optimal` is the best of the labellings
  /// enumerated so far (the empty one always among them), not proven.
  bool stopped = false;
  std::string stopped_by;           ///< when stopped: "time-limit" or "cancelled"
};
struct BruteForceOptions {
  /// Labellings to enumerate at most. When a lower bound on their number (2^k for k cells whose labels are
  /// independent) already exceeds it, brute force refuses before enumerating; otherwise it stops at limit + 1.
  /// Either way it throws LabellingLimitExceeded.
  long limit = 1L << 22;
  CompareOptions compare;
  double time_limit = 0;            ///< seconds (0: no limit); running out sets BruteForceResult::stopped
  std::function<bool()> cancel;     ///< asked where the time limit is; true stops as it does (may be empty)
};
BruteForceResult brute_force(const Problem& problem, bool connectivity, const BruteForceOptions& options);
/// The same with only a limit and comparison options.
BruteForceResult brute_force(const Problem& problem, bool connectivity, long limit = 1L << 22,
                             const CompareOptions& compare = {});

}  // namespace hsx::bsh
