// A deliberately simple BSH solver in double precision, the kind of program `hsx grade` exists to referee: a graph
// cut and the K = 1 beam search of the BSH paper (Section 5), on the BSH authors' graph-cut input, which
// `hsx arrange INPUT --export bsh-graphcut GRAPH.json` writes. It does not link hsx.
//
//   naive_graphcut GRAPH.json LABELS.json     writes {"labels": [true (inside) / false per cell]}
//   hsx grade INPUT LABELS.json               grades it exactly
//
// It keeps, on purpose, the shortcuts fast implementations take, so that grading shows their typical failures:
//   - energies are doubles, a missed sample costs a large constant (not a lexicographic pair), and among children
//     of equal cost the first one wins (float ties);
//   - every patch is charged its own weight, so a cut through coincident boundaries (several patches, one point
//     set, the same two cells) is charged once per patch there;
//   - K = 1: the beam keeps only the cheapest child, so it may end above the optimum.
// The graph: adj_cell_0 lies outside the patch's halfspace, adj_cell_1 inside; a patch is on the boundary when its
// inside cell is labelled inside and its outside cell outside; the reverse is forbidden (orientation-preserving);
// "outer_cells" (hsx's addition; absent from the authors' own files) are kept outside.
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace {

struct Patch {
  int outside = 0, inside = 0;  // adj_cell_0, adj_cell_1
  double weight = 0;
  int implicit = 0;
  int samples = 0;
  std::vector<int> neighbours;
};

struct Graph {
  int cells = 0;
  std::vector<Patch> patches;
  std::vector<int> outer;
};

Graph load(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  const nlohmann::json doc = nlohmann::json::parse(in);
  Graph g;
  g.cells = doc.at("num_cells").get<int>();
  for (const auto& p : doc.at("patches"))
    g.patches.push_back({p.at("adj_cell_0").get<int>(), p.at("adj_cell_1").get<int>(), p.at("weight").get<double>(),
                         p.at("implicit_id").get<int>(), p.at("num_samples").get<int>(),
                         p.at("adj_patches").get<std::vector<int>>()});
  if (doc.contains("outer_cells")) g.outer = doc.at("outer_cells").get<std::vector<int>>();
  return g;
}

using Traits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
using FlowGraph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS,
    boost::property<boost::vertex_color_t, boost::default_color_type,
                    boost::property<boost::vertex_predecessor_t, Traits::edge_descriptor,
                                    boost::property<boost::vertex_distance_t, long>>>,
    boost::property<boost::edge_capacity_t, double,
                    boost::property<boost::edge_residual_capacity_t, double,
                                    boost::property<boost::edge_reverse_t, Traits::edge_descriptor>>>>;

constexpr double kInfinity = 1e300;

struct Cut {
  std::vector<bool> inside;  // per cell
  double cost = 0;
};

/// The least-cost labelling with the `prohibited` patches kept off the boundary. Source side = inside. A patch
/// costs its weight on the boundary, infinity reversed, and `miss` per sample when off the boundary.
Cut graph_cut(const Graph& g, const std::vector<bool>& prohibited, double miss) {
  FlowGraph flow(g.cells + 2);
  const int source = g.cells, sink = g.cells + 1;
  auto capacity = boost::get(boost::edge_capacity, flow);
  auto reverse = boost::get(boost::edge_reverse, flow);
  auto add = [&](int u, int v, double c) {
    const auto e = boost::add_edge(u, v, flow).first, r = boost::add_edge(v, u, flow).first;
    capacity[e] = c;
    capacity[r] = 0;
    reverse[e] = r;
    reverse[r] = e;
  };
  for (std::size_t k = 0; k < g.patches.size(); ++k) {
    const Patch& p = g.patches[k];
    add(p.inside, p.outside, prohibited[k] ? kInfinity : p.weight);  // inside in, outside out: on the boundary
    add(p.outside, p.inside, kInfinity);                             // reversed: forbidden
    if (p.samples > 0 && !prohibited[k]) {                           // off the boundary: the samples are missed
      add(source, p.inside, miss * p.samples);
      add(p.outside, sink, miss * p.samples);
    }
  }
  for (int c : g.outer) add(c, sink, kInfinity);
  Cut cut;
  cut.cost = boost::boykov_kolmogorov_max_flow(flow, source, sink);
  const auto color = boost::get(boost::vertex_color, flow);
  cut.inside.resize(g.cells);
  for (int c = 0; c < g.cells; ++c) cut.inside[c] = color[c] == boost::get(color, source);
  return cut;
}

bool on_boundary(const Patch& p, const std::vector<bool>& inside) { return inside[p.inside] && !inside[p.outside]; }

/// The islands: components of boundary patches of one implicit (joined through adj_patches) without a sample.
std::vector<std::vector<int>> islands(const Graph& g, const std::vector<bool>& inside) {
  std::vector<int> seen(g.patches.size(), 0);
  std::vector<std::vector<int>> out;
  for (std::size_t start = 0; start < g.patches.size(); ++start) {
    if (seen[start] || !on_boundary(g.patches[start], inside)) continue;
    std::vector<int> component{static_cast<int>(start)}, stack{static_cast<int>(start)};
    seen[start] = 1;
    int samples = 0;
    while (!stack.empty()) {
      const Patch& p = g.patches[stack.back()];
      stack.pop_back();
      samples += p.samples;
      for (int q : p.neighbours)
        if (!seen[q] && g.patches[q].implicit == p.implicit && on_boundary(g.patches[q], inside)) {
          seen[q] = 1;
          component.push_back(q);
          stack.push_back(q);
        }
    }
    if (samples == 0) out.push_back(component);
  }
  return out;
}

/// The K = 1 beam: from the graph cut, while the boundary has islands, try prohibiting each island and keep the
/// cheapest child; stops when sample-connected or when no child is feasible.
std::vector<bool> beam(const Graph& g) {
  double total = 1;
  for (const Patch& p : g.patches) total += p.weight;
  const double miss = 1e3 * total;  // "large enough", in doubles
  std::vector<bool> prohibited(g.patches.size(), false);
  Cut state = graph_cut(g, prohibited, miss);
  for (;;) {
    const auto found = islands(g, state.inside);
    if (found.empty()) return state.inside;
    Cut best;
    std::vector<bool> best_prohibited;
    best.cost = std::numeric_limits<double>::infinity();
    for (const auto& island : found) {
      std::vector<bool> child = prohibited;
      for (int p : island) child[p] = true;
      Cut cut = graph_cut(g, child, miss);
      if (cut.cost < best.cost) {  // the first of equal costs wins
        best = std::move(cut);
        best_prohibited = std::move(child);
      }
    }
    if (!(best.cost < kInfinity)) return state.inside;  // nothing feasible: give up with the last state
    state = std::move(best);
    prohibited = std::move(best_prohibited);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: naive_graphcut GRAPH.json LABELS.json\n";
    return 2;
  }
  try {
    const Graph g = load(argv[1]);
    const std::vector<bool> labels = beam(g);
    std::ofstream out(argv[2]);
    out << nlohmann::json{{"labels", labels}}.dump() << "\n";
    if (!out) throw std::runtime_error(std::string(argv[2]) + ": cannot be written");
  } catch (const std::exception& e) {
    std::cerr << "naive_graphcut: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
