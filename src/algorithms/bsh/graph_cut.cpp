#include <hsx/algorithms/bsh/graph_cut.hpp>

#include "algorithms/bsh/problem_memo.hpp"
#include "algorithms/flow_graph.hpp"
#include "geometry/components.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>

namespace hsx::bsh {
namespace {

/// An edge weight: infinite, or (samples, measure) ordered lexicographically, where the measure is kept as an
/// integer combination of support measures ("atoms"): every capacity, flow and residual of the max-flow is one,
/// so additions are exact and cheap. Comparisons first try a rigorous double-interval enclosure of the atoms and
/// fall back to exact Measure arithmetic (problem.hpp) only when it does not separate. Questions that even the
/// certified comparison cannot separate answer "not less" (a tie never counts as positive residual); the
/// certificate check afterwards reports any such tie.
struct Capacity {
  bool infinite = false;
  long samples = 0;
  std::vector<std::pair<int, long>> atoms;  // (support, coefficient), ascending support, no zero coefficient
  const Problem* problem = nullptr;

  Capacity() = default;
  Capacity(int zero) { (void)zero; }  // NOLINT: Boost writes `FlowValue x = 0` and `0 < x`
  static Capacity inf() {
    Capacity c;
    c.infinite = true;
    return c;
  }
  static Capacity of_samples(long samples) {
    Capacity c;
    c.samples = samples;
    return c;
  }
  static Capacity of_support(const Problem& problem, int support) {
    Capacity c;
    c.atoms.emplace_back(support, 1);
    c.problem = &problem;
    return c;
  }
  bool is_zero() const { return !infinite && samples == 0 && atoms.empty(); }
  Measure measure() const {
    Measure m;
    for (const auto& [g, k] : atoms) m += problem->supports()[g].measure * Rational(k);
    return m;
  }
};

Capacity combine(const Capacity& a, const Capacity& b, long sign) {
  Capacity c;
  c.samples = a.samples + sign * b.samples;
  c.problem = a.problem ? a.problem : b.problem;
  std::size_t i = 0, j = 0;
  while (i < a.atoms.size() || j < b.atoms.size()) {
    if (j == b.atoms.size() || (i < a.atoms.size() && a.atoms[i].first < b.atoms[j].first)) {
      c.atoms.push_back(a.atoms[i++]);
    } else if (i == a.atoms.size() || b.atoms[j].first < a.atoms[i].first) {
      c.atoms.emplace_back(b.atoms[j].first, sign * b.atoms[j].second);
      ++j;
    } else {
      const long k = a.atoms[i].second + sign * b.atoms[j].second;
      if (k != 0) c.atoms.emplace_back(a.atoms[i].first, k);
      ++i;
      ++j;
    }
  }
  return c;
}

// Boost's max-flow only needs +, -, < and numeric_limits::max.
Capacity operator+(const Capacity& a, const Capacity& b) {
  if (a.infinite || b.infinite) return Capacity::inf();
  return combine(a, b, 1);
}
Capacity operator-(const Capacity& a, const Capacity& b) {
  if (a.infinite) return Capacity::inf();
  if (b.infinite) throw std::logic_error("graph cut: subtracting an infinite flow");
  return combine(a, b, -1);
}
Capacity& operator+=(Capacity& a, const Capacity& b) { return a = a + b; }

/// The exact Measure's sign of `d` (atoms only), remembered per problem and thread.
std::optional<int> exact_sign_of(const Capacity& d) {
  thread_local ProblemMemo<SignMemo> memo;
  return memo.of(*d.problem).sign(d.atoms, CompareOptions{}, [&] { return d.measure().sign(); });
}

/// Sign of sum k_g * |g|: the kernel's certified double enclosure of the combination first (exact for any long
/// k_g), then the exact Measure; nullopt when even that does not separate at the precision cap.
std::optional<int> sign_of(const Capacity& d) {
  DoubleCombination sum;
  for (const auto& [g, k] : d.atoms) {
    const auto& [lo, hi] = d.problem->support_enclosures()[g];
    sum.add(k, DoubleBounds{lo, hi});
  }
  if (const int s = sum.bounds().certain_sign()) return s;
  return exact_sign_of(d);
}

/// Certified double enclosure of a - b (atoms only), walked without building the difference; sets `equal` when
/// every coefficient cancels.
DoubleBounds difference_bounds(const Capacity& a, const Capacity& b, bool* equal) {
  const Problem* problem = a.problem ? a.problem : b.problem;
  DoubleCombination sum;
  *equal = true;
  const auto add = [&](int g, long k) {
    if (k == 0) return;
    *equal = false;
    const auto& [lo, hi] = problem->support_enclosures()[g];
    sum.add(k, DoubleBounds{lo, hi});
  };
  std::size_t i = 0, j = 0;
  while (i < a.atoms.size() || j < b.atoms.size()) {
    if (j == b.atoms.size() || (i < a.atoms.size() && a.atoms[i].first < b.atoms[j].first)) {
      add(a.atoms[i].first, a.atoms[i].second);
      ++i;
    } else if (i == a.atoms.size() || b.atoms[j].first < a.atoms[i].first) {
      add(b.atoms[j].first, -b.atoms[j].second);
      ++j;
    } else {
      add(a.atoms[i].first, a.atoms[i].second - b.atoms[j].second);
      ++i;
      ++j;
    }
  }
  return sum.bounds();
}

Order order(const Capacity& a, const Capacity& b) {
  if (a.infinite || b.infinite) {
    if (a.infinite && b.infinite) return Order::Equal;
    return a.infinite ? Order::Greater : Order::Less;
  }
  if (a.samples != b.samples) return a.samples < b.samples ? Order::Less : Order::Greater;
  bool equal = false;
  const DoubleBounds bounds = difference_bounds(a, b, &equal);
  if (equal) return Order::Equal;
  if (const int s = bounds.certain_sign()) return s < 0 ? Order::Less : Order::Greater;
  const std::optional<int> s = sign_of(combine(a, b, -1));
  if (!s) return Order::Tie;
  return *s < 0 ? Order::Less : (*s > 0 ? Order::Greater : Order::Equal);
}
/// Certified "a < b"; Tie and Equal answer false.
bool operator<(const Capacity& a, const Capacity& b) { return order(a, b) == Order::Less; }

}  // namespace
}  // namespace hsx::bsh

namespace std {
template <>
class numeric_limits<hsx::bsh::Capacity> {
 public:
  static constexpr bool is_specialized = true;
  static hsx::bsh::Capacity max() { return hsx::bsh::Capacity::inf(); }
};
}  // namespace std

namespace hsx::bsh {
namespace {

using Traits = FlowTraits;
using FlowGraph = hsx::FlowGraph<Capacity>;

// ---- the network of Fig. 8 as plain data ----

/// One arc of the network: s -> c (samples or infinite), c -> t (samples or infinite) or a -> b (the sum of the
/// measures of the supports between a and b with a inside, or infinite). Its reverse arc has capacity 0.
struct Arc {
  int from = 0, to = 0;
  bool infinite = false;
  long samples = 0;
  int atoms_begin = 0, atoms_end = 0;  ///< its supports in Network::atoms, ascending (each counted once)
  DoubleBounds measure;                ///< certified enclosure of the sum of their measures
  double estimate = 0;                 ///< finite arcs: the double flow's capacity (see double_capacity)
};

/// The network: vertices 0..cells-1 (the cells), s = cells, t = cells + 1; arcs in a fixed order (for each cell
/// s -> c then c -> t, then the binary arcs by (a, b)).
struct Network {
  int cells = 0, s = 0, t = 1;
  std::vector<Arc> arcs;
  std::vector<int> atoms;
};

/// Samples weigh more than the measure of every support together (a finite cut's measure is at most that).
double lambda_of(const Problem& problem) {
  double total = 0;
  for (const auto& bounds : problem.support_enclosures()) total += bounds.second;
  return 2 * total + 1;
}

/// The parts of a problem's network that no constraint changes, made once per problem and thread: the unary
/// arcs' samples and outer cells, and the binary arcs, where every support g between cells a and b is an entry of
/// a -> b and of b -> a (allowed when g may lie on b with that cell inside), grouped by (from, to), with the
/// supports ascending and the certified enclosure of their measures' sum.
struct FixedArcs {
  struct Entry {
    int from, to, support;
    bool allowed;
  };
  struct Group {
    int from = 0, to = 0;
    int begin = 0, end = 0;  ///< its entries
    bool disallowed = false;  ///< some entry is not allowed: the arc is infinite under any constraints
    DoubleBounds measure;
    double estimate = 0;      ///< the midpoints of its supports' enclosures, summed in entry order
  };
  std::vector<long> source_samples, sink_samples;  ///< per cell: h_c(0), h_c(1) finite parts
  std::vector<char> outer;                         ///< per cell: an outer cell (its arc to t is infinite)
  std::vector<Entry> entries;                      ///< by (from, to, support)
  std::vector<Group> arcs;
  double lambda = 1;  ///< the double flow's weight of a sample (lambda_of)

  FixedArcs() = default;
  explicit FixedArcs(const Problem& problem) : lambda(lambda_of(problem)) {
    add_unary(problem);
    add_binary(problem);
  }

 private:
  void add_unary(const Problem& problem) {
    const Complex& c = problem.complex();
    const int n = problem.cell_count();
    source_samples.assign(n, 0);
    sink_samples.assign(n, 0);
    outer.assign(n, 0);
    for (int k = 0; k < n; ++k) outer[k] = c.cells[k].outer;
    for (const Patch& p : c.patches) {
      source_samples[p.inside_cell] += static_cast<long>(p.samples.size());
      sink_samples[p.outside_cell] += static_cast<long>(p.samples.size());
    }
  }
  void add_binary(const Problem& problem) {
    entries.reserve(2 * static_cast<std::size_t>(problem.support_count()));
    for (int g = 0; g < problem.support_count(); ++g) {
      const SupportTerm& st = problem.supports()[g];
      entries.push_back({st.cell_a, st.cell_b, g, st.allow_a_inside});
      entries.push_back({st.cell_b, st.cell_a, g, st.allow_b_inside});
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
      return std::tie(x.from, x.to, x.support) < std::tie(y.from, y.to, y.support);
    });
    const IntervalBatch batch;
    for (std::size_t i = 0; i < entries.size();) {
      Group group;
      group.from = entries[i].from;
      group.to = entries[i].to;
      group.begin = static_cast<int>(i);
      for (; i < entries.size() && entries[i].from == group.from && entries[i].to == group.to; ++i) {
        const auto& [lo, hi] = problem.support_enclosures()[entries[i].support];
        group.measure = batch.add(group.measure, DoubleBounds{lo, hi});
        group.estimate += lo + (hi - lo) / 2;
        group.disallowed = group.disallowed || !entries[i].allowed;
      }
      group.end = static_cast<int>(i);
      arcs.push_back(group);
    }
  }
};

/// Fills `net` (its storage reused: a search builds thousands of networks) with the network of `problem` under
/// `constraints`.
void build_network(const Problem& problem, const CutConstraints& constraints, Network& net) {
  thread_local ProblemMemo<FixedArcs> memo;
  const FixedArcs& fixed = memo.of(problem);
  const int n = problem.cell_count();
  net.cells = n;
  net.s = n;
  net.t = n + 1;
  net.arcs.clear();
  net.atoms.clear();
  const auto add_unary = [&net, &fixed](int from, int to, bool infinite, long samples) {
    if (!infinite && samples == 0) return;
    Arc a;
    a.from = from;
    a.to = to;
    a.infinite = infinite;
    a.samples = infinite ? 0 : samples;
    a.estimate = static_cast<double>(a.samples) * fixed.lambda;
    net.arcs.push_back(a);
  };
  for (int k = 0; k < n; ++k) {
    // Forced 1: cutting s -> k is impossible; forced 0 (or an outer cell): cutting k -> t is impossible.
    const int forced = constraints.forced.empty() ? -1 : constraints.forced[k];
    add_unary(net.s, k, forced == 1, fixed.source_samples[k]);
    add_unary(k, net.t, fixed.outer[k] || forced == 0, fixed.sink_samples[k]);
  }
  // Binary arcs: every support g between a and b adds |g| to a -> b and to b -> a, or makes the arc infinite when
  // it does not allow that orientation or is removed.
  for (const FixedArcs::Group& group : fixed.arcs) {
    Arc a;
    a.from = group.from;
    a.to = group.to;
    a.atoms_begin = static_cast<int>(net.atoms.size());
    a.infinite = group.disallowed ||
                 (!constraints.removed.empty() &&
                  std::any_of(fixed.entries.begin() + group.begin, fixed.entries.begin() + group.end,
                              [&](const FixedArcs::Entry& e) { return constraints.removed[e.support] != 0; }));
    if (!a.infinite) {
      for (int k = group.begin; k < group.end; ++k) net.atoms.push_back(fixed.entries[k].support);
      a.measure = group.measure;
      a.estimate = group.estimate;
    }
    a.atoms_end = static_cast<int>(net.atoms.size());
    net.arcs.push_back(a);
  }
}

/// The exact capacity of an arc.
Capacity capacity_of(const Problem& problem, const Network& net, const Arc& a) {
  if (a.infinite) return Capacity::inf();
  Capacity c = Capacity::of_samples(a.samples);
  for (int k = a.atoms_begin; k < a.atoms_end; ++k) c.atoms.emplace_back(net.atoms[k], 1);
  if (!c.atoms.empty()) c.problem = &problem;
  return c;
}

/// A path of infinite arcs from s to t: the constraints admit no finite labelling. (Its adjacency lists and search
/// stack are per-thread scratch, reused by the next cut.)
bool infeasible(const Network& net) {
  // Without an infinite arc out of s (no cell forced inside) no such path starts.
  if (std::none_of(net.arcs.begin(), net.arcs.end(), [&](const Arc& a) { return a.infinite && a.from == net.s; }))
    return false;
  thread_local std::vector<int> start, targets, stack;
  thread_local std::vector<char> seen;
  const int vertices = net.cells + 2;
  start.assign(vertices + 1, 0);
  for (const Arc& a : net.arcs)
    if (a.infinite) ++start[a.from + 1];
  for (int v = 0; v < vertices; ++v) start[v + 1] += start[v];
  targets.resize(start[vertices]);
  stack.assign(start.begin(), start.end() - 1);  // each vertex's next free slot, while filling
  for (const Arc& a : net.arcs)
    if (a.infinite) targets[stack[a.from]++] = a.to;
  seen.assign(vertices, 0);
  stack.assign(1, net.s);
  seen[net.s] = 1;
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    for (int k = start[v]; k < start[v + 1]; ++k)
      if (!seen[targets[k]]) {
        seen[targets[k]] = 1;
        stack.push_back(targets[k]);
      }
  }
  return seen[net.t];
}

// ---- the double-precision max flow ----
// Both ways of certifying a cut start from a flow found in doubles: Boost's Boykov-Kolmogorov on the capacities
// rounded to one scalar each (samples * lambda + measure, lambda above the measure of every cut, so the scalar
// order of cuts is the lexicographic one up to rounding). The doubles only guide: whatever they are, the answer
// is checked exactly. They are finite: the measures enter as Problem::support_enclosures, which are scaled by one
// power of two (Problem::enclosure_scale) to at most 2^512 each, so measures beyond the largest double (a disk of
// radius 1e399) neither overflow nor make inf - inf = NaN flows; graph_cut skips the guide should a capacity
// still not be finite.


/// An arc's capacity in the double flow: its samples times lambda_of(problem), plus the midpoints of its supports'
/// enclosures (summed once per problem, FixedArcs; an arc has samples or supports, never both).
double double_capacity(const Arc& a) {
  return a.infinite ? std::numeric_limits<double>::infinity() : a.estimate;
}

/// A maximum flow of the rounded capacities, per arc of the network (by index).
struct DoubleFlow {
  std::vector<double> capacity, flow, residual;  ///< residual = capacity - flow as Boykov-Kolmogorov left it
};

/// One edge of the double network: its capacity, residual and reverse edge (Boykov-Kolmogorov's property maps).
using DoubleEdgeDescriptor = boost::detail::csr_edge_descriptor<std::size_t, std::size_t>;
struct DoubleEdge {
  double capacity = 0, residual = 0;
  DoubleEdgeDescriptor reverse;
};
/// A compressed sparse row graph: its edges' properties lie in one array (an adjacency list allocates one per
/// edge), and each vertex's out-edges keep the order they were listed in, so Boykov-Kolmogorov walks them as it
/// would an adjacency list built in that order.
using DoubleGraph = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, DoubleEdge>;

/// Boost's Boykov-Kolmogorov first pushes min(c(s -> v), c(v -> t)) along every path s -> v -> t without
/// raising the reverse edges' residuals (boykov_kolmogorov_max_flow.hpp, augment_direct_paths: "incoming/outgoing
/// edges to/from source/sink don't count for max-flow"), so the reverse residuals read as flows miss that amount on
/// both arcs and the flow looks unconserved at v (every cut of a scene with a sample whose inside cell is outer
/// then failed the fast certification and took the exact max flow). Adds it back: the run is the same, the flow
/// now conserved. Each cell has at most one arc from s and one to t, and when it has both, s -> v comes right
/// before v -> t (build_network's order).
void add_direct_paths(const Network& net, DoubleFlow& flow) {
  for (std::size_t i = 0; i + 1 < net.arcs.size(); ++i) {
    const Arc& in = net.arcs[i];
    const Arc& out = net.arcs[i + 1];
    if (in.from != net.s || in.to >= net.cells || out.from != in.to || out.to != net.t) continue;
    const double pushed = std::min(flow.capacity[i], flow.capacity[i + 1]);
    flow.flow[i] += pushed;
    flow.flow[i + 1] += pushed;
  }
}

/// The graph of a double network: the edges of an arc list, built once and kept per thread while the arcs' ends
/// stay the same (the cuts of one search differ in capacities only: removed supports make arcs infinite, and forced
/// labels add unary arcs only in tie enumeration). Edge 2i is arc i, edge 2i + 1 its reverse (capacity 0);
/// position[k] is edge k's place in the sorted edge list: by source, and in the order above within a source (a
/// stable counting sort).
class DoubleNetwork {
 public:
  /// The graph for `net`'s arcs, with every capacity 0 but the reverse edges' links set.
  DoubleGraph& graph_for(const Network& net) {
    const auto n = static_cast<std::size_t>(net.cells + 2);
    const bool same = n == vertices_ && net.arcs.size() == ends_.size() &&
                      std::equal(net.arcs.begin(), net.arcs.end(), ends_.begin(), [](const Arc& a, const auto& e) {
                        return a.from == e.first && a.to == e.second;
                      });
    if (!same) build(net, n);
    return graph_;
  }
  /// Edge k's descriptor (k = 2i for arc i, 2i + 1 for its reverse).
  DoubleEdgeDescriptor edge(std::size_t k) const {
    const auto& [from, to] = ends_[k / 2];
    return DoubleEdgeDescriptor(static_cast<std::size_t>(k % 2 ? to : from), position_[k]);
  }
  /// The arcs with an end at vertex v, ascending, as [first, last) of arc indices: the arcs of v's out-edges in the
  /// graph (an arc's edge or its reverse leaves each of its ends), for the network graph_for was last asked about.
  std::pair<const int*, const int*> incident_arcs(int v) const {
    return {arc_at_.data() + row_start_[v], arc_at_.data() + row_start_[v + 1]};
  }

 private:
  void build(const Network& net, std::size_t n) {
    vertices_ = n;
    ends_.clear();
    for (const Arc& a : net.arcs) ends_.emplace_back(a.from, a.to);
    const std::size_t m = 2 * ends_.size();
    const auto source_of = [&](std::size_t k) {
      return static_cast<std::size_t>(k % 2 ? ends_[k / 2].second : ends_[k / 2].first);
    };
    std::vector<std::size_t> start(n + 1, 0);
    position_.assign(m, 0);
    for (std::size_t k = 0; k < m; ++k) ++start[source_of(k) + 1];
    for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
    row_start_ = start;
    for (std::size_t k = 0; k < m; ++k) position_[k] = start[source_of(k)]++;
    arc_at_.resize(m);
    for (std::size_t k = 0; k < m; ++k) arc_at_[position_[k]] = static_cast<int>(k / 2);
    std::vector<std::pair<std::size_t, std::size_t>> edges(m);
    std::vector<DoubleEdge> properties(m);
    for (std::size_t i = 0; i < ends_.size(); ++i) {
      const auto from = static_cast<std::size_t>(ends_[i].first), to = static_cast<std::size_t>(ends_[i].second);
      const std::size_t e = position_[2 * i], r = position_[2 * i + 1];
      edges[e] = {from, to};
      edges[r] = {to, from};
      properties[e].reverse = DoubleEdgeDescriptor(to, r);
      properties[r].reverse = DoubleEdgeDescriptor(from, e);
    }
    graph_ = DoubleGraph(boost::edges_are_sorted, edges.begin(), edges.end(), properties.begin(), n);
  }

  std::size_t vertices_ = 0;
  std::vector<std::pair<int, int>> ends_;
  std::vector<std::size_t> position_;
  std::vector<std::size_t> row_start_;  ///< per vertex: its first out-edge's position (and the end, last)
  std::vector<int> arc_at_;             ///< per edge position: its arc
  DoubleGraph graph_;
};

/// Fills `out` (its storage reused) with a maximum flow of `net`'s rounded capacities, on `network`'s graph (kept
/// per thread by the caller, rebuilt only when the arcs' ends change).
void double_flow(const Network& net, DoubleNetwork& network, DoubleFlow& out) {
  const auto n = static_cast<std::size_t>(net.cells + 2);
  // Boykov-Kolmogorov's vertex maps, reset as Boost's own overload makes them (zeros) but kept per thread.
  thread_local std::vector<boost::default_color_type> color;
  thread_local std::vector<DoubleEdgeDescriptor> predecessor;
  thread_local std::vector<std::size_t> distance;
  DoubleGraph& g = network.graph_for(net);
  out.capacity.clear();
  for (std::size_t i = 0; i < net.arcs.size(); ++i) {
    const double capacity = double_capacity(net.arcs[i]);
    g[network.edge(2 * i)].capacity = capacity;
    out.capacity.push_back(capacity);
  }
  auto residual = boost::get(&DoubleEdge::residual, g);
  const auto index = boost::get(boost::vertex_index, g);
  color.assign(n, boost::default_color_type());
  predecessor.assign(n, DoubleEdgeDescriptor());
  distance.assign(n, 0);
  boost::boykov_kolmogorov_max_flow(g, boost::get(&DoubleEdge::capacity, g), residual,
                                    boost::get(&DoubleEdge::reverse, g),
                                    boost::make_iterator_property_map(predecessor.begin(), index),
                                    boost::make_iterator_property_map(color.begin(), index),
                                    boost::make_iterator_property_map(distance.begin(), index), index, net.s, net.t);
  out.flow.clear();
  out.residual.clear();
  for (std::size_t i = 0; i < net.arcs.size(); ++i) {
    // The reverse edge's residual = the arc's flow.
    out.flow.push_back(residual[network.edge(2 * i + 1)]);
    out.residual.push_back(residual[network.edge(2 * i)]);
  }
  add_direct_paths(net, out);
}

// ---- certification of a basic flow close to the double flow (the fast path) ----
// The arcs are split by the double flow into zero (Z), saturated (U) and free (F) ones; free arcs that close a
// cycle (s and t taken as one vertex G) are cancelled in doubles (flow pushed around the cycle until an arc reaches
// a bound, which then joins Z or U), so that the free arcs form a forest. The exact flow is then *defined* as 0 on
// Z, the capacity on U, and on each free arc the value conservation forces: the net saturated outflow of the
// subtree below it. It is conserved at every cell by construction, except at the root of a tree without G, where
// the subtree sum must be exactly 0 (checked). What is left to check is 0 <= f <= c on free arcs; intervals decide
// almost all of it, and the exact sums (supports with integer coefficients, then Measure) the rest. The source side
// is then the set reachable from s through positive residuals (decided the same way); t must not be in it.
// proofs/bsh.md entry 3 has the argument. Any check that fails (or does not decide) gives up: the caller falls
// back to the exact augmenting-path max flow below.

enum class ArcState : char { Zero, Saturated, Free };

/// An exact value (samples, measure) known by its samples and an enclosure of its measure.
struct Enclosed {
  long samples = 0;
  DoubleBounds measure;
};

/// Sign of an enclosed value when the enclosure decides it (an enclosure [0, 0] is an exact 0).
std::optional<int> enclosed_sign(const Enclosed& v) {
  if (v.samples != 0) return v.samples > 0 ? 1 : -1;
  if (const int s = v.measure.certain_sign()) return s;
  if (v.measure.lo == 0 && v.measure.hi == 0) return 0;
  return std::nullopt;
}

/// True when `supports` (ascending) are exactly the supports on the boundary of `labelling` (compared without
/// listing the boundary).
bool is_boundary(const Problem& problem, const Labelling& labelling, const std::vector<int>& supports) {
  std::size_t k = 0;
  bool same = true;
  for_each_boundary_support(problem, labelling, [&](int g) {
    same = same && k < supports.size() && supports[k] == g;
    ++k;
  });
  return same && k == supports.size();
}

class BasicFlow {
 public:
  /// Works on `doubles` in place (classification and cycle cancelling move its flows); `network` is the double
  /// flow's, for `net` (its arcs incident to each vertex).
  BasicFlow(const Problem& problem, const Network& net, const DoubleNetwork& network, DoubleFlow& doubles)
      : problem_(problem), net_(net), network_(network), d_(doubles), ground_(net.cells), nodes_(net.cells + 1) {}

  /// The certified cut, or nullopt when a check fails or does not decide.
  std::optional<CutResult> certify();

 private:
  int node(int vertex) const { return vertex < net_.cells ? vertex : ground_; }
  void classify();
  void build_forest();
  void cancel_cycle(int e);
  void root_forest();
  void solve_flows();
  std::optional<int> exact_sign(int below, int sign, int plus_arc);
  std::optional<int> sign_of_flow(int e, bool slack);
  bool decide_residuals();
  std::optional<CutResult> cut_from_residuals();

  const Problem& problem_;
  const Network& net_;
  const DoubleNetwork& network_;
  DoubleFlow& d_;
  int ground_, nodes_;
  // Per thread, reused by the next cut (every one is reset by the step that fills it; one BasicFlow at a time
  // per thread): a search makes thousands of cuts, and these allocations were a good part of each.
  static thread_local std::vector<ArcState> state_;
  static thread_local std::vector<std::vector<int>> forest_;  // per node: its free (forest) arcs
  static thread_local std::vector<int> parent_arc_, order_, position_, size_;
  static thread_local std::vector<Enclosed> subtree_, flow_;  // per node: net saturated outflow of its subtree;
                                                              // per arc: the flow
  static thread_local std::vector<char> forward_, backward_;  // per arc: positive residual forward (capacity - f),
                                                              // backward (f)
  static thread_local std::vector<int> stamp_, via_;          // scratch for cycle search
  static thread_local ReusableDisjointSets sets_;             // scratch: the forest's trees while it is built
  static thread_local std::vector<int> queue_;                // scratch for cycle search and tree walks
  static thread_local std::vector<std::pair<int, int>> cycle_;  // scratch: a cycle's (arc, orientation)
  static thread_local std::vector<long> coefficient_;         // per support: scratch for exact sums (kept 0)
  static thread_local std::vector<int> touched_;              // scratch: supports with a coefficient
  static thread_local std::vector<char> reach_;               // scratch: per vertex, on the source side
  static thread_local std::vector<int> supports_;             // scratch: the supports across the cut
  int stamp_now_ = 0;
};

thread_local std::vector<ArcState> BasicFlow::state_;
thread_local std::vector<std::vector<int>> BasicFlow::forest_;
thread_local std::vector<int> BasicFlow::parent_arc_, BasicFlow::order_, BasicFlow::position_, BasicFlow::size_;
thread_local std::vector<Enclosed> BasicFlow::subtree_, BasicFlow::flow_;
thread_local std::vector<char> BasicFlow::forward_, BasicFlow::backward_;
thread_local std::vector<int> BasicFlow::stamp_, BasicFlow::via_, BasicFlow::queue_;
thread_local std::vector<std::pair<int, int>> BasicFlow::cycle_;
thread_local ReusableDisjointSets BasicFlow::sets_;
thread_local std::vector<long> BasicFlow::coefficient_;
thread_local std::vector<int> BasicFlow::touched_, BasicFlow::supports_;
thread_local std::vector<char> BasicFlow::reach_;

void BasicFlow::classify() {
  double largest = 0;
  for (double c : d_.capacity)
    if (std::isfinite(c)) largest = std::max(largest, c);
  const double tolerance = std::ldexp(largest, -40);
  state_.assign(net_.arcs.size(), ArcState::Free);
  for (std::size_t e = 0; e < net_.arcs.size(); ++e) {
    if (!net_.arcs[e].infinite && d_.residual[e] <= tolerance) {
      state_[e] = ArcState::Saturated;
      d_.flow[e] = d_.capacity[e];
    } else if (d_.flow[e] <= tolerance) {
      state_[e] = ArcState::Zero;
      d_.flow[e] = 0;
    }
  }
}

void BasicFlow::build_forest() {
  forest_.resize(nodes_);
  for (auto& arcs : forest_) arcs.clear();  // keeps their storage for the next cut
  stamp_.assign(nodes_, 0);
  via_.assign(nodes_, -1);
  ReusableDisjointSets& sets = sets_;
  sets.reset(static_cast<std::size_t>(nodes_));
  for (std::size_t e = 0; e < net_.arcs.size(); ++e) {
    if (state_[e] != ArcState::Free) continue;
    const int u = node(net_.arcs[e].from), v = node(net_.arcs[e].to);
    const auto ru = sets.find_set(u), rv = sets.find_set(v);
    if (ru == rv) {
      cancel_cycle(static_cast<int>(e));
      continue;
    }
    sets.link(ru, rv);
    forest_[u].push_back(static_cast<int>(e));
    forest_[v].push_back(static_cast<int>(e));
  }
}

/// Free arc e closes a cycle with the forest: pushes flow around the cycle (in doubles) in the direction that
/// reaches a bound first; the arc that reaches it becomes zero or saturated and leaves the forest, e takes its place.
void BasicFlow::cancel_cycle(int e) {
  const int u = node(net_.arcs[e].from), v = node(net_.arcs[e].to);
  // Breadth-first search of the forest from v to u: via_[x] = the forest arc that reached x.
  ++stamp_now_;
  queue_.assign(1, v);
  stamp_[v] = stamp_now_;
  for (std::size_t head = 0; head < queue_.size() && stamp_[u] != stamp_now_; ++head) {
    const int x = queue_[head];
    for (int a : forest_[x]) {
      const int y = node(net_.arcs[a].from) == x ? node(net_.arcs[a].to) : node(net_.arcs[a].from);
      if (stamp_[y] == stamp_now_) continue;
      stamp_[y] = stamp_now_;
      via_[y] = a;
      queue_.push_back(y);
    }
  }
  // The cycle u -> v along e, then back from v to u through the forest; orientation +1 where the arc points
  // along the cycle.
  cycle_.assign(1, {e, 1});
  for (int x = u; x != v;) {
    const int a = via_[x];
    const int y = node(net_.arcs[a].from) == x ? node(net_.arcs[a].to) : node(net_.arcs[a].from);
    cycle_.emplace_back(a, node(net_.arcs[a].from) == y ? 1 : -1);  // walked from y to x
    x = y;
  }
  const auto room = [this](int a, int direction) {  // how far a's flow can move in `direction`
    return direction > 0 ? std::max(0.0, d_.capacity[a] - d_.flow[a]) : d_.flow[a];
  };
  double best = std::numeric_limits<double>::infinity();
  int limiting = e, push = 1;
  for (int direction : {1, -1})
    for (const auto& [a, orientation] : cycle_) {
      const double r = room(a, direction * orientation);
      if (r < best) {
        best = r;
        limiting = a;
        push = direction;
      }
    }
  for (const auto& [a, orientation] : cycle_) d_.flow[a] += push * orientation * best;
  const int hit = push * (limiting == e ? 1 : [&] {
    for (const auto& [a, orientation] : cycle_)
      if (a == limiting) return orientation;
    return 1;
  }());
  state_[limiting] = hit > 0 ? ArcState::Saturated : ArcState::Zero;
  d_.flow[limiting] = hit > 0 ? d_.capacity[limiting] : 0;
  if (limiting == e) return;
  for (int x : {node(net_.arcs[limiting].from), node(net_.arcs[limiting].to)}) {
    auto& arcs = forest_[x];
    arcs.erase(std::find(arcs.begin(), arcs.end(), limiting));
  }
  forest_[u].push_back(e);
  forest_[v].push_back(e);
}

/// Preorder of each tree (G's first), with parent arcs and subtree sizes: a subtree is a range of the preorder.
void BasicFlow::root_forest() {
  parent_arc_.assign(nodes_, -1);
  position_.assign(nodes_, -1);
  size_.assign(nodes_, 1);
  order_.clear();
  order_.reserve(nodes_);
  std::vector<int>& stack = queue_;
  stack.clear();
  for (int root = -1; root < nodes_; ++root) {
    const int r = root < 0 ? ground_ : root;
    if (position_[r] >= 0) continue;
    stack.push_back(r);
    position_[r] = 0;
    while (!stack.empty()) {
      const int x = stack.back();
      stack.pop_back();
      position_[x] = static_cast<int>(order_.size());
      order_.push_back(x);
      for (int a : forest_[x]) {
        if (a == parent_arc_[x]) continue;
        const int y = node(net_.arcs[a].from) == x ? node(net_.arcs[a].to) : node(net_.arcs[a].from);
        parent_arc_[y] = a;
        position_[y] = 0;
        stack.push_back(y);
      }
    }
  }
  for (auto it = order_.rbegin(); it != order_.rend(); ++it)
    if (parent_arc_[*it] >= 0) {
      const Arc& a = net_.arcs[parent_arc_[*it]];
      size_[node(a.from) == *it ? node(a.to) : node(a.from)] += size_[*it];
    }
}

/// Enclosures of the subtree sums and of the free arcs' flows, leaves first.
void BasicFlow::solve_flows() {
  const IntervalBatch batch;
  subtree_.assign(nodes_, Enclosed{});
  flow_.assign(net_.arcs.size(), Enclosed{});
  for (std::size_t e = 0; e < net_.arcs.size(); ++e) {
    if (state_[e] != ArcState::Saturated) continue;
    const Arc& a = net_.arcs[e];
    Enclosed& out = subtree_[node(a.from)];
    Enclosed& in = subtree_[node(a.to)];
    out.samples += a.samples;
    out.measure = batch.add(out.measure, a.measure);
    in.samples -= a.samples;
    in.measure = batch.subtract(in.measure, a.measure);
    flow_[e] = {a.samples, a.measure};
  }
  for (auto it = order_.rbegin(); it != order_.rend(); ++it) {
    const int x = *it, p = parent_arc_[x];
    if (p < 0) continue;
    const Arc& a = net_.arcs[p];
    const Enclosed& below = subtree_[x];
    const bool into = node(a.to) == x;  // p points into the subtree: f = its sum; out of it: f = -its sum
    flow_[p] = into ? below : Enclosed{-below.samples, DoubleBounds{-below.measure.hi, -below.measure.lo}};
    Enclosed& up = subtree_[into ? node(a.from) : node(a.to)];
    up.samples += below.samples;
    up.measure = batch.add(up.measure, below.measure);
  }
}

/// Exact sign of sign * (the subtree sum below node `below`) + (capacity of arc plus_arc, when >= 0): the
/// saturated arcs that cross the subtree's border, summed support by support; nullopt when not separated.
std::optional<int> BasicFlow::exact_sign(int below, int sign, int plus_arc) {
  const int first = position_[below], last = first + size_[below];
  const auto inside = [&](int vertex) {
    const int x = node(vertex);
    return position_[x] >= first && position_[x] < last;
  };
  coefficient_.resize(problem_.support_count(), 0);
  std::vector<int>& touched = touched_;
  touched.clear();
  long samples = 0;
  const auto add_arc = [&](const Arc& a, long k) {
    samples += k * a.samples;
    for (int i = a.atoms_begin; i < a.atoms_end; ++i) {
      if (coefficient_[net_.atoms[i]] == 0) touched.push_back(net_.atoms[i]);
      coefficient_[net_.atoms[i]] += k;
    }
  };
  for (std::size_t e = 0; e < net_.arcs.size(); ++e) {
    if (state_[e] != ArcState::Saturated) continue;
    const Arc& a = net_.arcs[e];
    const bool from = inside(a.from), to = inside(a.to);
    if (from != to) add_arc(a, from ? sign : -sign);
  }
  if (plus_arc >= 0) add_arc(net_.arcs[plus_arc], 1);
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  Capacity sum = Capacity::of_samples(samples);
  sum.problem = &problem_;
  for (int g : touched) {
    if (coefficient_[g] != 0) sum.atoms.emplace_back(g, coefficient_[g]);
    coefficient_[g] = 0;
  }
  if (sum.samples != 0) return sum.samples > 0 ? 1 : -1;
  if (sum.atoms.empty()) return 0;
  return sign_of(sum);
}

/// Sign of a free arc's flow (slack: of its capacity minus its flow), by enclosure or exactly.
std::optional<int> BasicFlow::sign_of_flow(int e, bool slack) {
  const Arc& a = net_.arcs[e];
  Enclosed v = flow_[e];
  if (slack) {
    const IntervalBatch batch;
    v = {a.samples - v.samples, batch.subtract(a.measure, v.measure)};
  }
  if (const auto s = enclosed_sign(v)) return s;
  // f = +-(sum below x), x the arc's lower end in the tree.
  const int x = parent_arc_[node(a.to)] == e ? node(a.to) : node(a.from);
  const int sign = node(a.to) == x ? 1 : -1;
  return slack ? exact_sign(x, -sign, e) : exact_sign(x, sign, -1);
}

/// Checks 0 <= f <= c on free arcs and exact conservation at the roots without G; sets forward_ / backward_.
bool BasicFlow::decide_residuals() {
  forward_.assign(net_.arcs.size(), 0);
  backward_.assign(net_.arcs.size(), 0);
  for (int x = 0; x < nodes_; ++x) {
    if (x == ground_ || parent_arc_[x] >= 0) continue;
    const auto s = enclosed_sign(subtree_[x]);
    if (s ? *s != 0 : exact_sign(x, 1, -1) != std::optional<int>(0)) return false;
  }
  for (std::size_t i = 0; i < net_.arcs.size(); ++i) {
    const int e = static_cast<int>(i);
    const Arc& a = net_.arcs[e];
    const auto positive_capacity = [&] {
      if (a.infinite || a.samples > 0 || a.measure.lo > 0) return true;
      const auto s = enclosed_sign(Enclosed{a.samples, a.measure});
      return s ? *s > 0 : sign_of(capacity_of(problem_, net_, a)) == std::optional<int>(1);
    };
    switch (state_[e]) {
      case ArcState::Zero: forward_[e] = positive_capacity(); break;
      case ArcState::Saturated: backward_[e] = positive_capacity(); break;
      case ArcState::Free: {
        const auto f = sign_of_flow(e, false);
        if (!f || *f < 0) return false;
        backward_[e] = *f > 0;
        if (a.infinite) {
          forward_[e] = 1;
          break;
        }
        const auto slack = sign_of_flow(e, true);
        if (!slack || *slack < 0) return false;
        forward_[e] = *slack > 0;
        break;
      }
    }
  }
  return true;
}

/// The source side (reachable from s through positive residuals), its energy and the check that the cut's
/// capacity equals that energy; nullopt when t is reachable or the check fails.
std::optional<CutResult> BasicFlow::cut_from_residuals() {
  const int n = net_.cells;
  std::vector<int>& stack = queue_;
  std::vector<char>& reach = reach_;
  reach.assign(n + 2, 0);
  stack.assign(1, net_.s);
  reach[net_.s] = 1;
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    const auto [first, last] = network_.incident_arcs(v);
    for (const int* it = first; it != last; ++it) {
      const int e = *it;
      const Arc& a = net_.arcs[e];
      const int w = a.from == v ? a.to : a.from;
      if (reach[w] || !(a.from == v ? forward_[e] : backward_[e])) continue;
      reach[w] = 1;
      stack.push_back(w);
    }
  }
  if (reach[net_.t]) return std::nullopt;
  CutResult result;
  result.labelling.assign(reach.begin(), reach.begin() + n);
  result.energy = energy(problem_, result.labelling);
  // The cut's capacity: its samples and its supports (each arc across counted once) must be the energy's.
  long samples = 0;
  std::vector<int>& supports = supports_;
  supports.clear();
  for (const Arc& a : net_.arcs) {
    if (!reach[a.from] || reach[a.to]) continue;
    if (a.infinite) return std::nullopt;
    samples += a.samples;
    supports.insert(supports.end(), net_.atoms.begin() + a.atoms_begin, net_.atoms.begin() + a.atoms_end);
  }
  std::sort(supports.begin(), supports.end());
  if (samples != result.energy.missing_samples || !is_boundary(problem_, result.labelling, supports))
    return std::nullopt;
  result.certified = true;
  return result;
}

std::optional<CutResult> BasicFlow::certify() {
  classify();
  build_forest();
  root_forest();
  solve_flows();
  if (!decide_residuals()) return std::nullopt;
  return cut_from_residuals();
}

// ---- the exact max flow by augmenting paths (the reference, and the fallback of the fast path) ----

/// One arc of the exact flow network (its reverse edge, of capacity 0, is reverse[e]).
struct ExactArc {
  Traits::edge_descriptor e;
  int from, to;
};

/// The network on a Boost graph with exact capacities, with its arcs in the order of Network::arcs.
struct ExactNetwork {
  explicit ExactNetwork(int vertices) : g(vertices) {}
  FlowGraph g;
  std::vector<ExactArc> arcs;
};

/// Augments the exact flow by its certified bottleneck along `path` (arc indices, s to t); a path whose bottleneck
/// is not certainly positive is left alone.
void augment_exactly(ExactNetwork& net, const std::vector<int>& path) {
  auto residual = boost::get(boost::edge_residual_capacity, net.g);
  auto reverse = boost::get(boost::edge_reverse, net.g);
  Capacity bottleneck = residual[net.arcs[path.front()].e];
  for (int i : path)
    if (residual[net.arcs[i].e] < bottleneck) bottleneck = residual[net.arcs[i].e];
  if (!(Capacity() < bottleneck)) return;
  for (int i : path) {
    const auto e = net.arcs[i].e;
    residual[e] = residual[e] - bottleneck;
    residual[reverse[e]] = residual[reverse[e]] + bottleneck;
  }
}

/// Decomposes `flow` (per arc, in doubles) into s-t paths, depth first with a current arc per vertex (an arc whose
/// remaining flow is negligible, or that closes a cycle, is passed over for good), and augments the exact flow
/// along each. Asks `stop` before each path; false when stopped. It ends whatever the doubles: every path takes
/// its smallest flow off each of its arcs, so at least one reaches 0 (or NaN, from an infinite flow) and is passed
/// over, and a NaN flow counts as negligible.
bool warm_start(ExactNetwork& net, std::vector<double> flow, int s, int t, const std::function<bool()>& stop) {
  const int n = static_cast<int>(boost::num_vertices(net.g));
  double largest = 0;
  for (double f : flow)
    if (std::isfinite(f)) largest = std::max(largest, f);
  const double negligible = largest * 1e-12;
  std::vector<std::vector<int>> out(n);
  for (std::size_t i = 0; i < net.arcs.size(); ++i)
    if (flow[i] > negligible) out[net.arcs[i].from].push_back(static_cast<int>(i));  // false for NaN
  std::vector<std::size_t> current(n, 0);
  std::vector<char> on_path(n, 0);
  for (;;) {
    if (stop && stop()) return false;
    std::vector<int> path;
    int v = s;
    on_path[s] = 1;
    while (v != t) {
      auto& k = current[v];
      while (k < out[v].size() && (!(flow[out[v][k]] > negligible) || on_path[net.arcs[out[v][k]].to])) ++k;
      if (k < out[v].size()) {
        path.push_back(out[v][k]);
        v = net.arcs[out[v][k]].to;
        on_path[v] = 1;
        continue;
      }
      if (path.empty()) return true;  // s has no flow left
      on_path[v] = 0;                  // a dead end: back up and pass its arc over
      v = net.arcs[path.back()].from;
      path.pop_back();
      ++current[v];
    }
    double delta = std::numeric_limits<double>::infinity();
    for (int i : path) delta = std::min(delta, flow[i]);
    for (int i : path) {
      flow[i] -= delta;
      on_path[net.arcs[i].to] = 0;
    }
    augment_exactly(net, path);
  }
}

CutResult stopped_result(int cells) {
  CutResult stopped;
  stopped.labelling.assign(cells, 0);
  stopped.energy.missing_samples = -1;
  stopped.certificate_note = "stopped";
  stopped.stopped = true;
  return stopped;
}

/// Edmonds-Karp in exact arithmetic from `warm` (a double flow decomposed into paths) or, when null, from the zero
/// flow; the source side of the maximum flow and the a-posteriori certificate of CutResult.
CutResult exact_max_flow_cut(const Problem& problem, const Network& flat, const std::vector<double>* warm,
                             const std::function<bool()>& stop) {
  const int n = flat.cells, s = flat.s, t = flat.t;
  ExactNetwork net(n + 2);
  FlowGraph& g = net.g;
  auto capacity = boost::get(boost::edge_capacity, g);
  auto residual = boost::get(boost::edge_residual_capacity, g);
  auto reverse = boost::get(boost::edge_reverse, g);
  for (const Arc& a : flat.arcs) {
    const Capacity w = capacity_of(problem, flat, a);
    auto e = boost::add_edge(a.from, a.to, g).first;
    auto r = boost::add_edge(a.to, a.from, g).first;
    capacity[e] = w;
    capacity[r] = Capacity();
    residual[e] = w;
    residual[r] = Capacity();
    reverse[e] = r;
    reverse[r] = e;
    net.arcs.push_back({e, a.from, a.to});
  }
  std::vector<boost::default_color_type> color(n + 2);
  std::vector<Traits::edge_descriptor> pred(n + 2);
  // The flow value is computed below from the flow on each arc out of s (Boost's own sum would add "capacity -
  // residual" on infinite edges, which is meaningless here). `stop` is asked before each warm-start path and
  // before each augmenting path of Edmonds-Karp.
  if (warm && !warm_start(net, *warm, s, t, stop)) return stopped_result(n);
  if (!interruptible_augment(
          g, s, t, residual, reverse,
          boost::make_iterator_property_map(color.begin(), boost::get(boost::vertex_index, g)),
          boost::make_iterator_property_map(pred.begin(), boost::get(boost::vertex_index, g)), stop))
    return stopped_result(n);

  // S side: vertices reachable from s through edges with (certainly) positive residual capacity.
  CutResult result;
  result.labelling.assign(n, 0);

  std::vector<char> reach(n + 2, 0);
  std::vector<int> stack{s};
  reach[s] = 1;
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    for (auto [it, end] = boost::out_edges(v, g); it != end; ++it) {
      const int w = static_cast<int>(boost::target(*it, g));
      if (!reach[w] && Capacity() < residual[*it]) {
        reach[w] = 1;
        stack.push_back(w);
      }
    }
  }
  for (int k = 0; k < n; ++k) result.labelling[k] = reach[k];
  result.energy = energy(problem, result.labelling);

  // Certificate: feasibility of the flow and value == energy of the labelling.
  auto note = [&](const std::string& why) {
    if (result.certificate_note.empty()) result.certificate_note = why;
  };
  if (reach[t]) note("sink reachable after max flow");
  std::vector<Capacity> balance(n + 2);
  Capacity flow;
  for (const ExactArc& a : net.arcs) {
    const Capacity& cap = capacity[a.e];
    const Capacity& res = residual[a.e];
    if (cap.infinite) {
      // Flow on an infinite edge is infinite minus its residual; it is feasible by definition, but it must
      // also be a finite, non-negative amount for conservation: track it from the reverse edge.
      const Capacity& back = residual[reverse[a.e]];
      if (order(back, Capacity()) == Order::Less || order(back, Capacity()) == Order::Tie) note("negative flow");
      balance[a.to] = balance[a.to] + back;
      balance[a.from] = balance[a.from] - back;
      if (a.from == s) flow += back;
      continue;
    }
    const Capacity f = cap - res;
    const Order lo = order(Capacity(), f), hi = order(res, Capacity());
    if (lo == Order::Greater || lo == Order::Tie) note("flow not provably >= 0 on an edge");
    if (hi == Order::Less || hi == Order::Tie) note("flow not provably <= capacity on an edge");
    balance[a.to] = balance[a.to] + f;
    balance[a.from] = balance[a.from] - f;
    if (a.from == s) flow += f;
  }
  for (int k = 0; k < n; ++k)
    if (!balance[k].is_zero())
      note("flow not conserved at cell " + std::to_string(k));
  if (flow.infinite || flow.samples != result.energy.missing_samples)
    note("flow value differs from the energy of the cut");
  else {
    // The energy as atoms: one of each support on the boundary. Equal vectors prove equality; otherwise the
    // values are compared exactly.
    Capacity energy_atoms;
    for (int g : boundary_supports(problem, result.labelling)) energy_atoms += Capacity::of_support(problem, g);
    const Capacity diff = combine(flow, energy_atoms, -1);
    if (!diff.atoms.empty()) {
      const std::optional<int> sgn = sign_of(diff);
      if (!sgn || *sgn != 0) note("flow value differs from the energy of the cut");
    }
  }
  result.certified = result.certificate_note.empty();
  return result;
}

}  // namespace

bool cut_cost(const Problem& problem, const CutConstraints& constraints, const Labelling& labelling, Energy* cost) {
  Network net;
  build_network(problem, constraints, net);
  const auto side = [&](int vertex) { return vertex == net.s || (vertex != net.t && labelling[vertex]); };
  Capacity total;
  for (const Arc& a : net.arcs) {
    if (!side(a.from) || side(a.to)) continue;
    if (a.infinite) return false;
    total += capacity_of(problem, net, a);
  }
  *cost = Energy(total.samples, total.measure());
  return true;
}

CutResult graph_cut(const Problem& problem, const CutConstraints& constraints, const std::function<bool()>& stop) {
  const int n = problem.cell_count();
  // The network, its double graph, the double flow and its copy for the warm start, per thread: a search makes
  // thousands of cuts, and allocating these was a good part of each.
  thread_local Network net;
  thread_local DoubleNetwork network;
  thread_local DoubleFlow doubles;
  thread_local std::vector<double> warm;
  build_network(problem, constraints, net);
  if (infeasible(net)) {
    CutResult infeasible;
    infeasible.labelling.assign(n, 0);
    infeasible.energy.missing_samples = -1;
    infeasible.certificate_note = "infeasible constraints";
    return infeasible;
  }
  if (stop && stop()) return stopped_result(n);
  const bool finite = std::all_of(net.arcs.begin(), net.arcs.end(),
                                  [](const Arc& a) { return a.infinite || std::isfinite(double_capacity(a)); });
  if (!constraints.warm_start || !finite) return exact_max_flow_cut(problem, net, nullptr, stop);
  double_flow(net, network, doubles);
  warm.assign(doubles.flow.begin(), doubles.flow.end());
  if (auto certified = BasicFlow(problem, net, network, doubles).certify()) return *std::move(certified);
  return exact_max_flow_cut(problem, net, &warm, stop);
}

}  // namespace hsx::bsh
