// Graphviz diagrams of an NH-Rep result (2D or 3D, from a scene or a mesh): the Boolean tree, and the patch graph
// with its edge types. Render with `dot -Tsvg FILE.dot > FILE.svg`.
//
// Conventions:
// - Tree (nhtree_dot): one box per node ("n<k>", labelled "max" / "min" with its node id; max = intersection,
//   min = union), one ellipse per leaf ("p<patch>", labelled "P<patch>" and, when `names` has it, its natural
//   halfspace), edges parent -> child in the tree's order. A leaf is filled with the colour of its node (the same
//   palette index the SVG pictures use, io/svg.hpp's svg_palette_colour(node)).
// - Patch graph (nhrep_patch_graph_dot): an undirected graph, one node per live patch ("p<patch>", labelled as in
//   the tree and filled with its tree node's colour), one edge per feature curve (a multigraph: several curves
//   between two patches give several edges), coloured by type: convex red, concave blue, smooth green, hybrid
//   purple (the 2D picture's corner colours), labelled with the type and the curve's link count; decomposed
//   (dead) patches are left out.
// - Output is deterministic (nodes and edges in id order).
#pragma once

#include <hsx/algorithms/nhrep/tree.hpp>

#include <string>
#include <vector>

namespace hsx {

/// @param[in] result  Algorithm 1's result (a tree with a root)
/// @param[in] names   per patch id of result.graph its natural halfspace's name, or empty (no names)
/// @param[in] title   the graph's label (may be empty)
/// Throws std::invalid_argument when the tree has no root or `names` is neither empty nor one per patch.
std::string nhtree_dot(const nhrep::BuildResult& result, const std::vector<std::string>& names,
                       const std::string& title);

/// The patch graph of `result` (see the conventions); arguments as nhtree_dot.
std::string nhrep_patch_graph_dot(const nhrep::BuildResult& result, const std::vector<std::string>& names,
                                  const std::string& title);

}  // namespace hsx
