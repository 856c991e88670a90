#include <hsx/algorithms/nhrep/planar.hpp>

#include <hsx/complex/boundary_from_arrangement2.hpp>
#include <hsx/complex/carry_solid2.hpp>
#include "geometry/planar_corners.hpp"

#include <algorithm>
#include <stdexcept>

namespace hsx::nhrep {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

void check_solid(const Arranged2& arranged, const std::vector<char>& solid) {
  if (solid.size() != arranged.complex.cells.size())
    throw std::invalid_argument("build_planar_tree: one flag per cell expected");
  if (std::none_of(solid.begin(), solid.end(), [](char c) { return c; }))
    throw InputError("the solid is empty: it has no boundary patches");
  for (std::size_t c = 0; c < solid.size(); ++c)
    if (solid[c] && arranged.complex.cells[c].outer)
      throw InputError("the solid reaches the domain's boundary (cell " + std::to_string(c) +
                       " touches it): NH-Rep needs a bounded solid inside the domain");
}

std::vector<std::vector<PlanarPiece>> patch_pieces(const PatchGraph& g, const Arrangement2& arrangement) {
  std::vector<std::vector<PlanarPiece>> pieces(g.patches.size());
  for (int p : g.live_patches())
    for (int piece_id : g.patches[at(p)].pieces) {
      const BoundaryPiece& piece = g.surface.pieces[at(piece_id)];
      PlanarPiece entry;
      entry.edge = piece.origin;
      if (piece.split_of >= 0) {
        entry.kept_vertex = g.surface.links[at(piece.kept_link)].origin;
        entry.split_point = edge_split_point(arrangement, piece.origin);
      }
      pieces[at(p)].push_back(entry);
    }
  return pieces;
}

}  // namespace

PlanarTree build_planar_tree(const Arranged2& arranged, const std::vector<char>& solid_cells,
                             const BuildOptions& options, CurveRule rule) {
  check_solid(arranged, solid_cells);
  PlanarTree t;
  t.options = options;
  t.built = build_tree(build_patch_graph(boundary_from_arrangement2(arranged, solid_cells), rule), options);
  t.leaf_names = leaf_names(t.built.graph, arranged.complex);
  t.pieces = patch_pieces(t.built.graph, arranged.arrangement);
  t.leaf_node = leaf_nodes(t.built);
  return t;
}

PlanarEvaluation evaluate_planar_tree(const PlanarTree& tree, const Arranged2& whole,
                                      const std::vector<char>& whole_solid) {
  return evaluate_on_cells(tree.built, tree.options, whole.complex, whole_solid);
}

PlanarEvaluation evaluate_on_whole_plane(const PlanarTree& tree, const Scene2& scene, const Arranged2& arranged,
                                         const std::vector<char>& solid_cells) {
  if (solid_cells.size() != arranged.complex.cells.size())
    throw std::invalid_argument("evaluate_on_whole_plane: one flag per cell expected");
  const Scene2 whole_scene = whole_plane_scene(scene);
  if (whole_scene.domain.min == scene.domain.min && whole_scene.domain.max == scene.domain.max)
    return evaluate_planar_tree(tree, arranged, solid_cells);  // the scene's own domain hides no vertex
  const Arranged2 whole = arrange(whole_scene);
  return evaluate_planar_tree(tree, whole, carry_to_whole_plane(arranged, solid_cells, whole));
}

}  // namespace hsx::nhrep
