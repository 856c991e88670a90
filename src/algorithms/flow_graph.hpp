// The Boost max-flow graph type shared by BSH's graph cut and NH-Rep's patch decomposition: a directed adjacency
// list whose edges carry a capacity, a residual capacity and their reverse edge (what edmonds_karp_max_flow needs).
#pragma once

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/detail/augment.hpp>

#include <functional>

namespace hsx {

using FlowTraits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;

template <class Capacity>
using FlowGraph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS, boost::no_property,
    boost::property<boost::edge_capacity_t, Capacity,
                    boost::property<boost::edge_residual_capacity_t, Capacity,
                                    boost::property<boost::edge_reverse_t, FlowTraits::edge_descriptor>>>>;

/// Edmonds-Karp's loop (shortest augmenting paths, as boost::edmonds_karp_max_flow, built from the same Boost pieces)
/// continued from the residual capacities already in `residual` (a feasible flow, e.g. a warm start): asks `stop`
/// before every augmenting path and gives up when it says so, so a long max flow honours a time limit. Leaves the
/// residual capacities of a maximum flow in `residual` (the flow is capacity - residual); returns false when stopped.
template <class Graph, class ResidualMap, class ReverseMap, class ColorMap, class PredMap>
bool interruptible_augment(Graph& g, typename boost::graph_traits<Graph>::vertex_descriptor source,
                           typename boost::graph_traits<Graph>::vertex_descriptor sink, ResidualMap residual,
                           ReverseMap reverse, ColorMap color, PredMap pred, const std::function<bool()>& stop) {
  using Color = boost::color_traits<typename boost::property_traits<ColorMap>::value_type>;
  for (;;) {
    if (stop && stop()) return false;
    boost::queue<typename boost::graph_traits<Graph>::vertex_descriptor> queue;
    boost::breadth_first_search(boost::detail::residual_graph(g, residual), source, queue,
                                boost::make_bfs_visitor(boost::record_edge_predecessors(pred, boost::on_tree_edge())),
                                color);
    if (boost::get(color, sink) == Color::white()) return true;
    boost::detail::augment(g, source, sink, pred, residual, reverse);
  }
}

/// Edmonds-Karp from the zero flow (residual = capacity), interruptible as interruptible_augment.
template <class Graph, class CapacityMap, class ResidualMap, class ReverseMap, class ColorMap, class PredMap>
bool interruptible_max_flow(Graph& g, typename boost::graph_traits<Graph>::vertex_descriptor source,
                            typename boost::graph_traits<Graph>::vertex_descriptor sink, CapacityMap capacity,
                            ResidualMap residual, ReverseMap reverse, ColorMap color, PredMap pred,
                            const std::function<bool()>& stop) {
  for (auto [v, v_end] = boost::vertices(g); v != v_end; ++v)
    for (auto [e, e_end] = boost::out_edges(*v, g); e != e_end; ++e) boost::put(residual, *e, boost::get(capacity, *e));
  return interruptible_augment(g, source, sink, residual, reverse, color, pred, stop);
}

}  // namespace hsx
