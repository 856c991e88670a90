// The Boost max-flow graph type shared by BSH's graph cut and NH-Rep's patch decomposition: a directed adjacency
// list whose edges carry a capacity, a residual capacity and their reverse edge (what edmonds_karp_max_flow needs).
#pragma once

#include <boost/graph/adjacency_list.hpp>

namespace hsx {

using FlowTraits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;

template <class Capacity>
using FlowGraph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS, boost::no_property,
    boost::property<boost::edge_capacity_t, Capacity,
                    boost::property<boost::edge_residual_capacity_t, Capacity,
                                    boost::property<boost::edge_reverse_t, FlowTraits::edge_descriptor>>>>;

}  // namespace hsx
