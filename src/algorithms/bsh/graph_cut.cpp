#include <hsx/algorithms/bsh/graph_cut.hpp>

#include "algorithms/flow_graph.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

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

/// Sign of sum k_g * |g|: the kernel's certified double enclosure of the combination first (exact for any long
/// k_g), then the exact Measure; nullopt when even that does not separate at the precision cap.
std::optional<int> sign_of(const Capacity& d) {
  DoubleCombination sum;
  for (const auto& [g, k] : d.atoms) {
    const auto& [lo, hi] = d.problem->support_enclosures()[g];
    sum.add(k, DoubleBounds{lo, hi});
  }
  if (const int s = sum.bounds().certain_sign()) return s;
  return d.measure().sign();
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

/// The unary and binary terms of Eqs. 2-4 as plain data.
struct Terms {
  std::vector<long> source_samples, sink_samples;  // h_c(0), h_c(1) finite parts
  std::vector<char> source_infinite, sink_infinite; // forced labels: forced 1 (or outer) can't be cut from s
  std::map<std::pair<int, int>, Capacity> binary;  // (a, b) -> h_ab(1, 0)
};

Terms build_terms(const Problem& problem, const CutConstraints& constraints) {
  const Complex& c = problem.complex();
  Terms t;
  const int n = problem.cell_count();
  t.source_samples.assign(n, 0);
  t.sink_samples.assign(n, 0);
  t.sink_infinite.assign(n, 0);
  t.source_infinite.assign(n, 0);
  for (int k = 0; k < n; ++k) {
    t.sink_infinite[k] = c.cells[k].outer;
  }
  for (int k = 0; k < n; ++k) {
    if (constraints.forced.empty() || constraints.forced[k] < 0) continue;
    // Forced 1: cutting s -> k is impossible; forced 0: cutting k -> t is impossible.
    if (constraints.forced[k] == 1) t.source_infinite[k] = 1; else t.sink_infinite[k] = 1;
  }
  for (const Patch& p : c.patches) {
    t.source_samples[p.inside_cell] += static_cast<long>(p.samples.size());
    t.sink_samples[p.outside_cell] += static_cast<long>(p.samples.size());
  }
  for (int g = 0; g < problem.support_count(); ++g) {
    const SupportTerm& s = problem.supports()[g];
    Capacity& ab = t.binary[{s.cell_a, s.cell_b}];
    Capacity& ba = t.binary[{s.cell_b, s.cell_a}];
    const bool removed = !constraints.removed.empty() && constraints.removed[g];
    ab = !removed && s.allow_a_inside ? ab + Capacity::of_support(problem, g) : Capacity::inf();
    ba = !removed && s.allow_b_inside ? ba + Capacity::of_support(problem, g) : Capacity::inf();
  }
  return t;
}


/// One arc of the flow network (its reverse edge, of capacity 0, is reverse[e]).
struct Arc {
  Traits::edge_descriptor e;
  int from, to;
};

/// The network of Fig. 8 built on a Boost graph, with its arcs in insertion order.
struct Network {
  explicit Network(int vertices) : g(vertices) {}
  FlowGraph g;
  std::vector<Arc> arcs;
};

// ---- the double-precision warm start ----
// The certified max flow starts from a flow found in doubles: Boost's Boykov-Kolmogorov on the capacities rounded to
// one scalar each (samples * lambda + measure, lambda above the measure of every cut, so the scalar order of cuts
// is the lexicographic one up to rounding), decomposed into s-t paths; each path is then augmented exactly by its
// certified bottleneck. Rounding only makes the warm start less than maximal: Edmonds-Karp finishes the flow in
// exact arithmetic and the certificate below is checked exactly, so the result does not depend on the doubles
// (the source side is the set reachable from s in the residual graph of a maximum flow, the same for every
// maximum flow).

using DoubleGraph = hsx::FlowGraph<double>;

/// Samples weigh more than the measure of every support together (a finite cut's measure is at most that).
double lambda_of(const Problem& problem) {
  double total = 0;
  for (const auto& bounds : problem.support_enclosures()) total += bounds.second;
  return 2 * total + 1;
}

double double_capacity(const Capacity& c, const Problem& problem, double lambda) {
  if (c.infinite) return std::numeric_limits<double>::infinity();
  double value = static_cast<double>(c.samples) * lambda;
  for (const auto& [g, k] : c.atoms) {
    const auto& [lo, hi] = problem.support_enclosures()[g];
    value += static_cast<double>(k) * (lo + (hi - lo) / 2);
  }
  return value;
}

/// The flow on each arc of `net` (by index) of a maximum flow of the rounded capacities.
std::vector<double> double_flow(const Network& net, const Problem& problem, int s, int t) {
  const double lambda = lambda_of(problem);
  const auto n = boost::num_vertices(net.g);
  DoubleGraph g(n);
  auto capacity = boost::get(boost::edge_capacity, g);
  auto residual = boost::get(boost::edge_residual_capacity, g);
  auto reverse = boost::get(boost::edge_reverse, g);
  auto exact_capacity = boost::get(boost::edge_capacity, net.g);
  std::vector<Traits::edge_descriptor> reverse_of_arc;
  for (const Arc& a : net.arcs) {
    auto e = boost::add_edge(a.from, a.to, g).first;
    auto r = boost::add_edge(a.to, a.from, g).first;
    capacity[e] = double_capacity(exact_capacity[a.e], problem, lambda);
    capacity[r] = 0;
    reverse[e] = r;
    reverse[r] = e;
    reverse_of_arc.push_back(r);
  }
  std::vector<boost::default_color_type> color(n);
  boost::boykov_kolmogorov_max_flow(g, capacity, residual, reverse,
                                    boost::make_iterator_property_map(color.begin(), boost::get(boost::vertex_index, g)),
                                    boost::get(boost::vertex_index, g), s, t);
  std::vector<double> flow;
  flow.reserve(net.arcs.size());
  for (const auto& r : reverse_of_arc) flow.push_back(residual[r]);  // the reverse edge's residual = the arc's flow
  return flow;
}

/// Augments the exact flow by its certified bottleneck along `path` (arc indices, s to t); a path whose bottleneck
/// is not certainly positive is left alone.
void augment_exactly(Network& net, const std::vector<int>& path) {
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
/// along each. Asks `stop` before each path; false when stopped.
bool warm_start(Network& net, std::vector<double> flow, int s, int t, const std::function<bool()>& stop) {
  const int n = static_cast<int>(boost::num_vertices(net.g));
  double largest = 0;
  for (double f : flow)
    if (std::isfinite(f)) largest = std::max(largest, f);
  const double negligible = largest * 1e-12;
  std::vector<std::vector<int>> out(n);
  for (std::size_t i = 0; i < net.arcs.size(); ++i)
    if (flow[i] > negligible) out[net.arcs[i].from].push_back(static_cast<int>(i));
  std::vector<std::size_t> current(n, 0);
  std::vector<char> on_path(n, 0);
  for (;;) {
    if (stop && stop()) return false;
    std::vector<int> path;
    int v = s;
    on_path[s] = 1;
    while (v != t) {
      auto& k = current[v];
      while (k < out[v].size() && (flow[out[v][k]] <= negligible || on_path[net.arcs[out[v][k]].to])) ++k;
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

}  // namespace

bool cut_cost(const Problem& problem, const CutConstraints& constraints, const Labelling& labelling, Energy* cost) {
  const Terms t = build_terms(problem, constraints);
  Capacity total;
  for (int k = 0; k < problem.cell_count(); ++k) {
    if (labelling[k]) {
      if (t.sink_infinite[k]) return false;
      total = total + Capacity::of_samples(t.sink_samples[k]);
    } else {
      if (t.source_infinite[k]) return false;
      total = total + Capacity::of_samples(t.source_samples[k]);
    }
  }
  for (const auto& [pair, w] : t.binary)
    if (labelling[pair.first] && !labelling[pair.second]) total = total + w;
  if (total.infinite) return false;
  *cost = Energy(total.samples, total.measure());
  return true;
}

CutResult graph_cut(const Problem& problem, const CutConstraints& constraints, const std::function<bool()>& stop) {
  const int n = problem.cell_count();
  const Terms terms = build_terms(problem, constraints);
  Network net(n + 2);
  FlowGraph& g = net.g;
  const int s = n, t = n + 1;
  auto capacity = boost::get(boost::edge_capacity, g);
  auto residual = boost::get(boost::edge_residual_capacity, g);
  auto reverse = boost::get(boost::edge_reverse, g);
  auto add = [&](int from, int to, const Capacity& w) {
    auto e = boost::add_edge(from, to, g).first;
    auto r = boost::add_edge(to, from, g).first;
    capacity[e] = w;
    capacity[r] = Capacity();
    residual[e] = w;
    residual[r] = Capacity();
    reverse[e] = r;
    reverse[r] = e;
    net.arcs.push_back({e, from, to});
  };
  for (int k = 0; k < n; ++k) {
    if (terms.source_infinite[k])
      add(s, k, Capacity::inf());
    else if (terms.source_samples[k])
      add(s, k, Capacity::of_samples(terms.source_samples[k]));
    if (terms.sink_infinite[k])
      add(k, t, Capacity::inf());
    else if (terms.sink_samples[k])
      add(k, t, Capacity::of_samples(terms.sink_samples[k]));
  }
  for (const auto& [pair, w] : terms.binary)
    if (!w.is_zero()) add(pair.first, pair.second, w);

  // Infeasible constraints show as a path of infinite edges from s to t; Edmonds-Karp would loop on it.
  {
    std::vector<char> seen(n + 2, 0);
    std::vector<int> stack{s};
    seen[s] = 1;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (auto [it, end] = boost::out_edges(v, g); it != end; ++it) {
        const int w = static_cast<int>(boost::target(*it, g));
        if (!seen[w] && capacity[*it].infinite) {
          seen[w] = 1;
          stack.push_back(w);
        }
      }
    }
    if (seen[t]) {
      CutResult infeasible;
      infeasible.labelling.assign(n, 0);
      infeasible.energy.missing_samples = -1;
      infeasible.certificate_note = "infeasible constraints";
      return infeasible;
    }
  }
  std::vector<boost::default_color_type> color(n + 2);
  std::vector<Traits::edge_descriptor> pred(n + 2);
  // The flow value is computed below from the flow on each arc out of s (Boost's own sum would add "capacity -
  // residual" on infinite edges, which is meaningless here). `stop` is asked before the double flow, before each
  // warm-start path and before each augmenting path of Edmonds-Karp.
  const auto stopped_result = [n] {
    CutResult stopped;
    stopped.labelling.assign(n, 0);
    stopped.energy.missing_samples = -1;
    stopped.certificate_note = "stopped";
    stopped.stopped = true;
    return stopped;
  };
  if (stop && stop()) return stopped_result();
  if (constraints.warm_start && !warm_start(net, double_flow(net, problem, s, t), s, t, stop))
    return stopped_result();
  if (!interruptible_augment(
          g, s, t, residual, reverse,
          boost::make_iterator_property_map(color.begin(), boost::get(boost::vertex_index, g)),
          boost::make_iterator_property_map(pred.begin(), boost::get(boost::vertex_index, g)), stop))
    return stopped_result();

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
  for (const Arc& a : net.arcs) {
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

}  // namespace hsx::bsh
