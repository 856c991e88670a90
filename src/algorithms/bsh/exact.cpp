// Branch and bound for the BSH shape (exact.hpp has the design and conventions; proofs/bsh.md the theorem).
#include <hsx/algorithms/bsh/exact.hpp>

#include "algorithms/flow_graph.hpp"
#include "geometry/components.hpp"

// GCC 12 reports a false "may be used uninitialized" inside Boost's edge iterator as instantiated by the solver.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#pragma GCC diagnostic pop

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>

namespace hsx::bsh {
namespace {

using Clock = std::chrono::steady_clock;
using Labels = std::vector<signed char>;  ///< per cell: -1 undecided, 0, 1

// ---- the search space: closed partial assignments ----

/// The implication graph "x = 1 => y = 1" of orientation preservation, and propagation along it.
class Implications {
 public:
  explicit Implications(const Problem& problem)
      : implies_(problem.cell_count()), implied_by_(problem.cell_count()) {
    for (const SupportTerm& s : problem.supports()) {
      if (!s.allow_b_inside) link(s.cell_b, s.cell_a);  // b inside is not allowed: b = 1 forces a = 1
      if (!s.allow_a_inside) link(s.cell_a, s.cell_b);
    }
  }

  /// Sets `cell` to `value` and everything it implies (1 upwards, 0 downwards); false on a conflict (then
  /// `labels` is partly assigned and must be dropped).
  bool assign(Labels& labels, int cell, signed char value) const {
    if (labels[cell] >= 0) return labels[cell] == value;
    labels[cell] = value;
    std::vector<int> stack{cell};
    while (!stack.empty()) {
      const int x = stack.back();
      stack.pop_back();
      for (int y : value ? implies_[x] : implied_by_[x]) {
        if (labels[y] == value) continue;
        if (labels[y] >= 0) return false;
        labels[y] = value;
        stack.push_back(y);
      }
    }
    return true;
  }

 private:
  std::vector<std::vector<int>> implies_, implied_by_;
  void link(int x, int y) {
    implies_[x].push_back(y);
    implied_by_[y].push_back(x);
  }
};

// ---- the fast rigorous lower bound: an integer min cut of rounded-down capacities ----

/// Section 5.1's graph with integer capacities: support measures rounded down to multiples of 2^-scale_bits,
/// samples weighted sample_weight (more than all measures together). Reused from node to node: only the
/// terminal edges change with the decided cells.
class FastBound {
 public:
  struct Cut {
    long long value = 0;  ///< the max flow = min cut of the rounded capacities
    Labelling labelling;  ///< the minimal source side (label 1)
  };

  explicit FastBound(const Problem& problem) : n_(problem.cell_count()), graph_(problem.cell_count() + 2) {
    choose_scale(problem);
    std::vector<long> source_samples(n_, 0), sink_samples(n_, 0);
    for (const Patch& p : problem.complex().patches) {
      source_samples[p.inside_cell] += static_cast<long>(p.samples.size());
      sink_samples[p.outside_cell] += static_cast<long>(p.samples.size());
    }
    for (int k = 0; k < n_; ++k) {
      source_edges_.push_back(add_pair(n_, k, 0, 0));
      sink_edges_.push_back(add_pair(k, n_ + 1, 0, 0));
      source_base_.push_back(sample_weight_ * source_samples[k]);
      sink_base_.push_back(problem.complex().cells[k].outer ? infinite_ : sample_weight_ * sink_samples[k]);
    }
    for (int g = 0; g < problem.support_count(); ++g) {
      const SupportTerm& s = problem.supports()[g];
      const long long w = rounded_[g];
      support_forward_.push_back(s.allow_a_inside ? w : infinite_);
      support_backward_.push_back(s.allow_b_inside ? w : infinite_);
      support_edges_.push_back(add_pair(s.cell_a, s.cell_b, support_forward_.back(), support_backward_.back()));
    }
  }

  /// The min cut with the decided cells of `labels` tied to s (1) or t (0); `labels` must be closed. Per
  /// support, `off` (or empty: none) forbids orientations: bit 1 = cell_a inside, bit 2 = cell_b inside (3: the
  /// support stays off the boundary). Returns nullopt when the constraints admit no labelling.
  std::optional<Cut> solve(const Labels& labels, const std::vector<char>& off = {}) {
    auto capacity = boost::get(boost::edge_capacity, graph_);
    const auto reverse = boost::get(boost::edge_reverse, graph_);
    for (int k = 0; k < n_; ++k) {
      capacity[source_edges_[k]] = labels[k] == 1 ? infinite_ : source_base_[k];
      capacity[sink_edges_[k]] = labels[k] == 0 ? infinite_ : sink_base_[k];
    }
    for (std::size_t g = 0; g < support_edges_.size(); ++g) {
      const char bits = off.empty() ? 0 : off[g];
      capacity[support_edges_[g]] = bits & 1 ? infinite_ : support_forward_[g];
      capacity[reverse[support_edges_[g]]] = bits & 2 ? infinite_ : support_backward_[g];
    }
    if (infinite_path()) return std::nullopt;
    std::vector<boost::default_color_type> color(n_ + 2);
    std::vector<long> distance(n_ + 2);
    std::vector<FlowTraits::edge_descriptor> pred(n_ + 2);
    const auto index = boost::get(boost::vertex_index, graph_);
    Cut cut;
    cut.value = boost::boykov_kolmogorov_max_flow(
        graph_, capacity, boost::get(boost::edge_residual_capacity, graph_), reverse,
        boost::make_iterator_property_map(pred.begin(), index), boost::make_iterator_property_map(color.begin(), index),
        boost::make_iterator_property_map(distance.begin(), index), index, n_, n_ + 1);
    cut.labelling = source_side();
    if (cut.value >= infinite_ || cut_capacity(cut.labelling) != cut.value)
      throw std::logic_error("exact: the integer max flow does not match its cut");
    return cut;
  }

  /// Missing samples of the cut's own labelling: exactly floor(V / M), since V is its rounded energy.
  long missing_samples(long long value) const { return static_cast<long>(value / sample_weight_); }

  /// The lower bound that a cut value proves (floor(V / M), (V mod M) * 2^-scale), its measure in the problem's
  /// enclosure scale (times 2^-Problem::enclosure_scale(), as the rounded capacities are).
  EnergyBound decode(long long value) const {
    return {static_cast<long>(value / sample_weight_), std::ldexp(static_cast<double>(value % sample_weight_), -scale_bits_)};
  }

 private:
  using Graph = FlowGraph<long long>;
  int n_;
  Graph graph_;
  std::vector<FlowTraits::edge_descriptor> source_edges_, sink_edges_, support_edges_;
  std::vector<long long> source_base_, sink_base_, rounded_, support_forward_, support_backward_;
  long long sample_weight_ = 1, infinite_ = 1;
  int scale_bits_ = 0;

  /// Rounded measures floor(lo * 2^scale) summing below 2^B, where B leaves room for the sample weights and the
  /// infinite capacity (M * (samples + 2)) below 2^61.
  void choose_scale(const Problem& problem) {
    double total_hi = 1;
    for (const auto& [lo, hi] : problem.support_enclosures()) total_hi += hi;
    int sample_bits = 0;
    while ((1LL << sample_bits) < problem.total_samples() + 3) ++sample_bits;
    const int budget = std::min(50, 60 - sample_bits);
    int exponent = 0;
    if (!std::isfinite(total_hi))  // Problem::support_enclosures are at most 2^512 each
      throw std::logic_error("exact: the support enclosures' sum is not finite");
    std::frexp(total_hi, &exponent);  // total_hi < 2^exponent
    scale_bits_ = budget - exponent;
    long long sum = 0;
    for (const auto& [lo, hi] : problem.support_enclosures()) {
      const double scaled = std::floor(std::ldexp(lo, scale_bits_));
      rounded_.push_back(scaled > 0 ? static_cast<long long>(scaled) : 0);
      sum += rounded_.back();
    }
    sample_weight_ = sum + 1;
    infinite_ = sample_weight_ * (problem.total_samples() + 2);
  }

  FlowTraits::edge_descriptor add_pair(int from, int to, long long forward, long long backward) {
    auto e = boost::add_edge(from, to, graph_).first;
    auto r = boost::add_edge(to, from, graph_).first;
    auto capacity = boost::get(boost::edge_capacity, graph_);
    auto reverse = boost::get(boost::edge_reverse, graph_);
    capacity[e] = forward;
    capacity[r] = backward;
    reverse[e] = r;
    reverse[r] = e;
    return e;
  }

  /// An s-t path of infinite capacities: no finite cut (checked first: such flows would overflow).
  bool infinite_path() const {
    const auto capacity = boost::get(boost::edge_capacity, graph_);
    std::vector<char> seen(n_ + 2, 0);
    std::vector<int> stack{n_};
    seen[n_] = 1;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (auto [it, end] = boost::out_edges(v, graph_); it != end; ++it) {
        const int w = static_cast<int>(boost::target(*it, graph_));
        if (!seen[w] && capacity[*it] >= infinite_) {
          seen[w] = 1;
          stack.push_back(w);
        }
      }
    }
    return seen[n_ + 1];
  }

  /// Cells reachable from s through positive residual capacity: label 1.
  Labelling source_side() const {
    const auto residual = boost::get(boost::edge_residual_capacity, graph_);
    std::vector<char> reach(n_ + 2, 0);
    std::vector<int> stack{n_};
    reach[n_] = 1;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (auto [it, end] = boost::out_edges(v, graph_); it != end; ++it) {
        const int w = static_cast<int>(boost::target(*it, graph_));
        if (!reach[w] && residual[*it] > 0) {
          reach[w] = 1;
          stack.push_back(w);
        }
      }
    }
    return Labelling(reach.begin(), reach.begin() + n_);
  }

  /// Capacity of the cut (S = s and the cells labelled 1): the flow's certificate of optimality.
  long long cut_capacity(const Labelling& labelling) const {
    const auto capacity = boost::get(boost::edge_capacity, graph_);
    auto side = [&](int v) { return v == n_ ? 1 : (v == n_ + 1 ? 0 : labelling[v]); };
    long long total = 0;
    for (int v = 0; v < n_ + 2; ++v) {
      if (!side(v)) continue;
      for (auto [it, end] = boost::out_edges(v, graph_); it != end; ++it)
        if (!side(static_cast<int>(boost::target(*it, graph_)))) total += capacity[*it];
    }
    return total;
  }
};

// ---- the island rule ----

/// The island rule (exact.hpp): a patch of halfspace i that may still lie on b with i's orientation is "dead"
/// when its component among such patches of i holds no sample of i - it would be in an island. A node with a
/// dead definite patch has no sample-connected completion; elsewhere, dead patches forbid their support's
/// orientation in the node's cut (every sample-connected completion avoids it, so the bound stays valid).
class IslandRule {
 public:
  struct Verdict {
    bool hopeless = false;
    std::vector<int> dead;  ///< the dead patches (none when hopeless)
    std::vector<char> off;  ///< per support, the orientations dead patches forbid (FastBound::solve's bits)
  };

  explicit IslandRule(const Problem& problem) : problem_(problem), neighbours_(problem.complex().patches.size()) {
    const Complex& c = problem.complex();
    for (const Junction& j : c.junctions)
      for (int p : j.patches)
        for (int q : j.patches)
          if (p != q && c.patches[p].halfspace == c.patches[q].halfspace) neighbours_[p].push_back(q);
    for (const Patch& patch : c.patches) {
      const SupportTerm& s = problem.supports()[patch.support];
      inside_.push_back(patch.inside_cell);
      outside_.push_back(patch.outside_cell);
      allowed_.push_back(s.allows(patch.inside_cell));
      sampled_.push_back(!patch.samples.empty());
      bit_.push_back(patch.inside_cell == s.cell_a ? 1 : 2);
      support_.push_back(patch.support);
    }
  }

  /// Dead patches are the possible ones that no possible sampled patch of their halfspace reaches. `forbidden`
  /// (per support, FastBound::solve's bits; empty: none) holds the orientations the node has excluded: patches
  /// with those are not possible. The verdict's `off` has the dead orientations and the forbidden ones.
  Verdict judge(const Labels& labels, const std::vector<char>& forbidden) const {
    const std::size_t count = inside_.size();
    std::vector<char> possible(count, 0), alive(count, 0);
    std::vector<int> stack;
    for (std::size_t p = 0; p < count; ++p) {
      possible[p] = allowed_[p] && labels[inside_[p]] != 0 && labels[outside_[p]] != 1 &&
                    !(!forbidden.empty() && (forbidden[support_[p]] & bit_[p]));
      if (possible[p] && sampled_[p]) {
        alive[p] = 1;
        stack.push_back(static_cast<int>(p));
      }
    }
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      for (int q : neighbours_[p])
        if (possible[q] && !alive[q]) {
          alive[q] = 1;
          stack.push_back(q);
        }
    }
    Verdict verdict;
    verdict.off = forbidden.empty() ? std::vector<char>(problem_.support_count(), 0) : forbidden;
    for (std::size_t p = 0; p < count; ++p) {
      if (!possible[p] || alive[p]) continue;
      if (labels[inside_[p]] == 1 && labels[outside_[p]] == 0) {
        verdict.hopeless = true;
        return verdict;
      }
      verdict.dead.push_back(static_cast<int>(p));
      verdict.off[support_[p]] |= bit_[p];
    }
    return verdict;
  }

  int inside(int p) const { return inside_[p]; }
  int outside(int p) const { return outside_[p]; }
  int support(int p) const { return support_[p]; }
  /// The orientation bit of patch p on its support (FastBound::solve's convention).
  char bit(int p) const { return bit_[p]; }
  /// The patches of p's halfspace that share a junction with p.
  const std::vector<int>& neighbours(int p) const { return neighbours_[p]; }

 private:
  const Problem& problem_;
  std::vector<std::vector<int>> neighbours_;  ///< per patch, the patches of its halfspace sharing a junction
  std::vector<int> inside_, outside_, support_;
  std::vector<char> allowed_, sampled_, bit_;
};

/// True when `labelling` extends the partial assignment `labels`.
bool agrees(const Labelling& labelling, const Labels& labels) {
  for (std::size_t k = 0; k < labels.size(); ++k)
    if (labels[k] >= 0 && labelling[k] != labels[k]) return false;
  return true;
}

/// True when `labelling` puts a support on the boundary with an orientation `off` forbids.
bool uses_forbidden(const Problem& problem, const Labelling& labelling, const std::vector<char>& off) {
  for (int g : boundary_supports(problem, labelling)) {
    const SupportTerm& s = problem.supports()[g];
    if (off[g] & (labelling[s.cell_a] ? 1 : 2)) return true;
  }
  return false;
}

// ---- the search ----

/// A node's relaxed optimum (the fast cut), shared by the child that keeps it; exact facts computed on demand.
struct Candidate {
  FastBound::Cut cut;
  EnergyBound bound;
  std::optional<Energy> energy;
  std::optional<SampleConnectivity> connectivity;
};

/// A node: closed labels and the orientations its branching excluded (per support, FastBound::solve's bits).
struct Node {
  Labels labels;
  std::vector<char> off;
  std::shared_ptr<Candidate> candidate;
  long id = 0;
};

/// Heap order: the smallest bound on top, then the newest node (a dive towards the leaves).
struct NodeAfter {
  bool operator()(const Node& a, const Node& b) const {
    if (a.candidate->cut.value != b.candidate->cut.value) return a.candidate->cut.value > b.candidate->cut.value;
    return a.id < b.id;
  }
};

/// Lexicographic "a < b" on bounds.
bool less(const EnergyBound& a, const EnergyBound& b) {
  return a.missing_samples != b.missing_samples ? a.missing_samples < b.missing_samples : a.measure < b.measure;
}

class ExactSearch {
 public:
  ExactSearch(const Problem& problem, const ExtractOptions& options)
      : problem_(problem), options_(options), implications_(problem), bound_(problem), islands_(problem),
        start_(Clock::now()), last_report_(start_) {}

  /// The algorithm's outline: best-bound first, prune by bound and by islands, take sample-connected
  /// candidates as incumbents, branch on a cell that the candidate's islands depend on.
  ExtractResult run() {
    set_incumbent(Labelling(problem_.cell_count(), 0), std::nullopt);
    push_root();
    while (!queue_.empty() && !out_of_budget()) {
      Node node = pop();
      track_gap(node.candidate->bound);
      if (bound_prunes(node.candidate->bound)) {
        ++stats_.pruned_by_bound;
        continue;
      }
      ++stats_.nodes;
      if (connected(*node.candidate)) offer(node.candidate->cut.labelling, energy_of(*node.candidate));
      if (undecided(node.labels) == 0) continue;  // the region is the candidate alone
      if (certified_bound_prunes(node)) {
        ++stats_.pruned_by_bound;
        continue;
      }
      branch(node);
    }
    return finish();
  }

 private:
  const Problem& problem_;
  const ExtractOptions& options_;
  Implications implications_;
  FastBound bound_;
  IslandRule islands_;
  Clock::time_point start_, last_report_;
  SearchStats stats_;
  std::string stopped_by_;
  std::vector<Node> queue_;  // a heap under NodeAfter
  long next_id_ = 0;
  // The incumbent and its ties.
  Labelling incumbent_;
  Energy incumbent_energy_;
  // Rigorous double enclosure of its measure times 2^-Problem::enclosure_scale(), the scale of the nodes' bounds
  // (and of stats_.max_gap while the search runs); reported bounds are unscaled by `reported`.
  double incumbent_lo_ = 0, incumbent_hi_ = 0;
  std::set<Labelling> optimal_;                 // labellings with the incumbent's energy (up to max_ties)
  bool unseparated_ = false;                    // a tie was only "not separated" (Order::Tie)

  bool want_ties() const {
    return options_.enumerate_ties && static_cast<int>(optimal_.size()) < std::max(1, options_.max_ties);
  }

  // -- nodes --

  void push_root() {
    Node root{Labels(problem_.cell_count(), -1), std::vector<char>(problem_.support_count(), 0), nullptr, next_id_++};
    for (int k = 0; k < problem_.cell_count(); ++k)
      if (problem_.complex().cells[k].outer && !implications_.assign(root.labels, k, 0))
        throw std::logic_error("exact: outer cells are forced inside");
    seed_incumbent(root.labels);
    consider(std::move(root), nullptr);
  }

  /// The first incumbent, greedily: the root's fast cut (dead orientations forbidden), then the same with every
  /// island's supports kept off the boundary, until it is sample-connected. It ends: each step keeps at least one
  /// more support off, and with every support off only the empty labelling is left.
  void seed_incumbent(const Labels& root) {
    std::vector<char> off = islands_.judge(root, {}).off;
    FastBound::Cut cut = *bound_.solve(root, off);  // no cell forced 1: the empty labelling is always there
    ++stats_.graph_cuts;
    for (;;) {
      const SampleConnectivity connectivity = sample_connectivity(problem_, cut.labelling);
      if (connectivity.sample_connected()) break;
      for (int island : connectivity.islands)
        for (int p : connectivity.components[island].patches) off[problem_.complex().patches[p].support] = 3;
      cut = *bound_.solve(root, off);
      ++stats_.graph_cuts;
    }
    offer(cut.labelling, energy(problem_, cut.labelling));
  }

  /// Bounds a new node (reusing `keep`, a candidate that still fits it) and queues it unless it is pruned.
  void consider(Node node, const std::shared_ptr<Candidate>& keep) {
    const IslandRule::Verdict verdict = settle(node.labels, node.off);
    if (!verdict.hopeless) {
      const bool reuse = keep && agrees(keep->cut.labelling, node.labels) &&
                         !uses_forbidden(problem_, keep->cut.labelling, verdict.off);
      node.candidate = reuse ? keep : solve(node.labels, verdict.off);
    }
    if (!node.candidate) {  // no completion is sample-connected
      ++stats_.pruned_by_islands;
      return;
    }
    if (bound_prunes(node.candidate->bound)) {
      ++stats_.pruned_by_bound;
      return;
    }
    queue_.push_back(std::move(node));
    std::push_heap(queue_.begin(), queue_.end(), NodeAfter());
    stats_.max_queue = std::max(stats_.max_queue, static_cast<long>(queue_.size()));
  }

  /// Propagates the island rule and the node's excluded orientations into the labels until nothing changes: a
  /// dead or excluded orientation (inside cell `in`, outside cell `out`) may not have in = 1 and out = 0
  /// (Lemmas 10.2 and 10.6 of proofs/bsh.md), so one of them decided forces the other. Hopeless when that
  /// conflicts. The labels stay closed under the implications.
  IslandRule::Verdict settle(Labels& labels, const std::vector<char>& forbidden) const {
    for (;;) {
      IslandRule::Verdict verdict = islands_.judge(labels, forbidden);
      if (verdict.hopeless) return verdict;
      bool changed = false;
      for (int g = 0; g < problem_.support_count(); ++g) {
        if (!verdict.off[g]) continue;
        const SupportTerm& s = problem_.supports()[g];
        for (const auto& [bit, in, out] : {std::tuple<char, int, int>{1, s.cell_a, s.cell_b}, {2, s.cell_b, s.cell_a}}) {
          if (!(verdict.off[g] & bit)) continue;
          bool ok = !(labels[in] == 1 && labels[out] == 0);
          if (ok && labels[in] == 1 && labels[out] < 0) ok = implications_.assign(labels, out, 1), changed = true;
          else if (ok && labels[out] == 0 && labels[in] < 0) ok = implications_.assign(labels, in, 0), changed = true;
          if (!ok) return IslandRule::Verdict{true, {}, {}};
        }
      }
      if (!changed) return verdict;
    }
  }

  /// The node's fast cut under the orientations its dead patches forbid; null when they admit no labelling.
  std::shared_ptr<Candidate> solve(const Labels& labels, const std::vector<char>& off) {
    ++stats_.nodes_created;
    ++stats_.graph_cuts;
    std::optional<FastBound::Cut> cut = bound_.solve(labels, off);
    if (!cut) return nullptr;
    auto candidate = std::make_shared<Candidate>();
    candidate->cut = std::move(*cut);
    candidate->bound = bound_.decode(candidate->cut.value);
    return candidate;
  }

  Node pop() {
    std::pop_heap(queue_.begin(), queue_.end(), NodeAfter());
    Node node = std::move(queue_.back());
    queue_.pop_back();
    return node;
  }

  static int undecided(const Labels& labels) {
    return static_cast<int>(std::count(labels.begin(), labels.end(), static_cast<signed char>(-1)));
  }

  /// On an island of the candidate when it has one (branch_on_island), else two children on one undecided cell;
  /// the one with the candidate's value keeps the candidate (it is still feasible and optimal for the rounded cut
  /// there). It is queued last, so it is expanded first on equal bounds.
  void branch(const Node& node) {
    const SampleConnectivity& connectivity = connectivity_of(*node.candidate);
    if (!connectivity.islands.empty() && options_.exact_branching == ExactBranching::Islands)
      return branch_on_island(node, connectivity);
    const int cell = branch_cell(node);
    const signed char keep = node.candidate->cut.labelling[cell];
    for (signed char value : {static_cast<signed char>(1 - keep), keep}) {
      Node child{node.labels, node.off, nullptr, next_id_++};
      if (!implications_.assign(child.labels, cell, value)) continue;  // no labelling there
      consider(std::move(child), value == keep ? node.candidate : nullptr);
    }
  }

  /// Lemma 10.6's partition of the region by an island I = p_1..p_k of the candidate (halfspace i) and its
  /// frontier F = f_1..f_m (the patches of i sharing a junction with I, outside it): child j has p_1..p_{j-1} on b
  /// with i's orientation and p_j's orientation excluded; child k + j has all of I on, f_1..f_{j-1} excluded and
  /// f_j on. What is left (I on, F off) has an island: no admissible labelling. Each child excludes the candidate.
  /// The island with the fewest children is taken.
  void branch_on_island(const Node& node, const SampleConnectivity& connectivity) {
    ++stats_.island_branches;
    std::vector<int> island, frontier;
    for (int k : connectivity.islands) {
      std::vector<int> patches = connectivity.components[k].patches;
      std::sort(patches.begin(), patches.end());
      std::vector<int> around;
      for (int p : patches)
        for (int q : islands_.neighbours(p))
          if (!std::binary_search(patches.begin(), patches.end(), q)) around.push_back(q);
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
      if (island.empty() || patches.size() + around.size() < island.size() + frontier.size()) {
        island = std::move(patches);
        frontier = std::move(around);
      }
    }
    Node rest{node.labels, node.off, nullptr, 0};  // the patches handled so far: on (I), excluded (F)
    for (int p : island) {
      Node child{rest.labels, rest.off, nullptr, next_id_++};
      child.off[islands_.support(p)] |= islands_.bit(p);
      consider(std::move(child), nullptr);
      if (!put_on(rest.labels, p)) return;  // no labelling has I on
    }
    for (int f : frontier) {
      Node child{rest.labels, rest.off, nullptr, next_id_++};
      if (put_on(child.labels, f)) consider(std::move(child), nullptr);
      rest.off[islands_.support(f)] |= islands_.bit(f);
    }
  }

  /// Puts patch p on b with its halfspace's orientation (inside cell 1, outside cell 0); false on a conflict.
  bool put_on(Labels& labels, int p) const {
    return implications_.assign(labels, islands_.inside(p), 1) && implications_.assign(labels, islands_.outside(p), 0);
  }

  /// An undecided cell of a patch of the candidate's first island (ExactBranching::Cells), else of a boundary
  /// support, else the first.
  int branch_cell(const Node& node) {
    const Complex& c = problem_.complex();
    const Candidate& candidate = *node.candidate;
    const SampleConnectivity& connectivity = connectivity_of(*node.candidate);
    for (int island : connectivity.islands)
      for (int p : connectivity.components[island].patches)
        for (int cell : {c.patches[p].inside_cell, c.patches[p].outside_cell})
          if (node.labels[cell] < 0) return cell;
    for (int g : boundary_supports(problem_, candidate.cut.labelling))
      for (int cell : {problem_.supports()[g].cell_a, problem_.supports()[g].cell_b})
        if (node.labels[cell] < 0) return cell;
    return static_cast<int>(std::find(node.labels.begin(), node.labels.end(), -1) - node.labels.begin());
  }

  // -- bounds --

  /// The bound provably exceeds the incumbent (or reaches it, when no more ties are wanted).
  bool bound_prunes(const EnergyBound& bound) const {
    if (bound.missing_samples != incumbent_energy_.missing_samples)
      return bound.missing_samples > incumbent_energy_.missing_samples;
    return want_ties() ? bound.measure > incumbent_hi_ : bound.measure >= incumbent_hi_;
  }

  /// When the fast bound left the node open although its candidate is exactly no better than the incumbent,
  /// the certified graph cut (an exact proof) may still close it.
  bool certified_bound_prunes(const Node& node) {
    if (surely_better(*node.candidate)) return false;
    const Order o = compare(energy_of(*node.candidate), incumbent_energy_, options_.compare);
    if (!(o == Order::Greater || (o == Order::Equal && !want_ties()))) return false;
    ++stats_.certified_bounds;
    ++stats_.graph_cuts;
    const CutResult cut = graph_cut(problem_, CutConstraints{{}, node.labels});
    if (!cut.certified) {
      ++stats_.uncertified_cuts;
      return false;
    }
    if (sample_connectivity(problem_, cut.labelling).sample_connected()) offer(cut.labelling, cut.energy);
    const Order p = compare(cut.energy, incumbent_energy_, options_.compare);
    return p == Order::Greater || (p == Order::Equal && !want_ties());
  }

  /// The candidate is certainly better than the incumbent, by its exact sample count and a double enclosure of
  /// its measure (which spares the exact energy).
  bool surely_better(const Candidate& candidate) const {
    const long missing = bound_.missing_samples(candidate.cut.value);
    if (missing != incumbent_energy_.missing_samples) return missing < incumbent_energy_.missing_samples;
    DoubleCombination measure;
    for (int g : boundary_supports(problem_, candidate.cut.labelling)) {
      const auto& [lo, hi] = problem_.support_enclosures()[g];
      measure.add(1, DoubleBounds{lo, hi});
    }
    return measure.bounds().hi < incumbent_lo_;
  }

  // -- candidates and the incumbent --

  const Energy& energy_of(Candidate& candidate) const {
    if (!candidate.energy) candidate.energy = energy(problem_, candidate.cut.labelling);
    return *candidate.energy;
  }
  const SampleConnectivity& connectivity_of(Candidate& candidate) const {
    if (!candidate.connectivity) candidate.connectivity = sample_connectivity(problem_, candidate.cut.labelling);
    return *candidate.connectivity;
  }
  bool connected(Candidate& candidate) const { return connectivity_of(candidate).sample_connected(); }

  void set_incumbent(const Labelling& labelling, const std::optional<Energy>& e) {
    incumbent_ = labelling;
    incumbent_energy_ = e ? *e : energy(problem_, labelling);
    std::tie(incumbent_lo_, incumbent_hi_) = problem_.scaled_enclosure(incumbent_energy_.measure());
    optimal_ = {labelling};
    unseparated_ = false;
  }

  /// A sample-connected orientation-preserving labelling: a better incumbent, or one more tie.
  void offer(const Labelling& labelling, const Energy& e) {
    const Order o = compare(e, incumbent_energy_, options_.compare);
    if (o == Order::Less) {
      set_incumbent(labelling, e);
    } else if ((o == Order::Equal || o == Order::Tie) && want_ties() && !optimal_.count(labelling)) {
      optimal_.insert(labelling);
      unseparated_ = unseparated_ || o == Order::Tie;
    }
  }

  // -- limits, progress, the gap --

  EnergyBound incumbent_bound() const { return {incumbent_energy_.missing_samples, incumbent_lo_}; }

  /// The proven lower bound on the optimum: the smallest open bound (the heap's top), or the incumbent.
  EnergyBound lower_bound() const {
    if (queue_.empty()) return incumbent_bound();
    const EnergyBound& top = queue_.front().candidate->bound;
    return less(top, incumbent_bound()) ? top : incumbent_bound();
  }

  /// `bound` (in the enclosure scale) in the measure's own units: times 2^enclosure_scale(), exact unless it
  /// passes the largest double, where a lower bound (`lower`) stays the largest double and a gap becomes inf.
  EnergyBound reported(const EnergyBound& bound, bool lower) const {
    EnergyBound out{bound.missing_samples, std::ldexp(bound.measure, static_cast<int>(problem_.enclosure_scale()))};
    if (lower && std::isinf(out.measure)) out.measure = std::numeric_limits<double>::max();
    return out;
  }

  EnergyBound gap_to(const EnergyBound& bound) const {
    return {incumbent_energy_.missing_samples - bound.missing_samples, incumbent_hi_ - bound.measure};
  }

  /// Called with the bound of the node just taken (the smallest open one).
  void track_gap(const EnergyBound& popped) {
    const EnergyBound gap = gap_to(less(popped, incumbent_bound()) ? popped : incumbent_bound());
    if (less(stats_.max_gap, gap)) stats_.max_gap = gap;
  }

  bool out_of_budget() {
    const auto now = Clock::now();
    if (options_.progress && now - last_report_ > std::chrono::milliseconds(500)) {
      last_report_ = now;
      SearchProgress p;
      p.states_expanded = stats_.nodes;
      p.queue_size = static_cast<long>(queue_.size());
      p.graph_cuts = stats_.graph_cuts;
      p.best_energy = incumbent_energy_;
      p.lower_bound = reported(lower_bound(), true);
      options_.progress(p);
    }
    if (options_.max_nodes > 0 && stats_.nodes >= options_.max_nodes) stopped_by_ = "max-nodes";
    if (options_.time_limit > 0 && std::chrono::duration<double>(now - start_).count() > options_.time_limit)
      stopped_by_ = "time-limit";
    else if (options_.cancel && options_.cancel())
      stopped_by_ = "cancelled";
    return !stopped_by_.empty();
  }

  ExtractResult finish() {
    ExtractResult result;
    result.method = Method::Exact;
    result.stopped_by = stopped_by_;
    result.optimal = stopped_by_.empty();  // up to ties that did not separate (ties.certified), as brute force
    result.labelling = incumbent_;
    result.energy = incumbent_energy_;
    result.sample_connected = true;
    result.removed.assign(problem_.support_count(), 0);
    result.ties.checked = options_.enumerate_ties && stopped_by_.empty();
    result.ties.count = static_cast<int>(optimal_.size());
    result.ties.certified = !unseparated_;
    result.ties.capped = result.ties.checked && !want_ties();
    if (result.ties.capped) result.ties.stopped_by = "max-ties";
    for (const Labelling& l : optimal_)
      if (l != incumbent_) result.tied.push_back(l);
    stats_.gap = stopped_by_.empty() ? EnergyBound{} : reported(gap_to(lower_bound()), false);
    stats_.lower_bound = reported(lower_bound(), true);
    stats_.max_gap = reported(stats_.max_gap, false);
    stats_.states_expanded = stats_.nodes;
    stats_.states_created = stats_.nodes_created;
    stats_.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    result.stats = stats_;
    return result;
  }
};

}  // namespace

ExtractResult extract_exact(const Problem& problem, const ExtractOptions& options) {
  return ExactSearch(problem, options).run();
}

}  // namespace hsx::bsh
