// NH-Rep on 3D solids from halfspaces: see solid3.hpp.
#include <hsx/algorithms/nhrep/solid3.hpp>

#include <hsx/complex/boundary_from_arrangement3.hpp>
#include <hsx/complex/carry_solid3.hpp>

#include <algorithm>
#include <stdexcept>

namespace hsx::nhrep {

SolidTree3 build_solid_tree3(const Arranged3& arranged, const std::vector<char>& solid_cells,
                             const BuildOptions& options, CurveRule rule) {
  if (solid_cells.size() != arranged.complex.cells.size())
    throw std::invalid_argument("build_solid_tree3: one flag per cell expected");
  if (std::none_of(solid_cells.begin(), solid_cells.end(), [](char c) { return c; }))
    throw InputError("the solid is empty: it has no boundary patches");
  for (std::size_t c = 0; c < solid_cells.size(); ++c)
    if (solid_cells[c] && arranged.complex.cells[c].outer)
      throw InputError("the solid reaches the domain's boundary (cell " + std::to_string(c) +
                       " touches it): NH-Rep needs a bounded solid inside the domain");
  SolidTree3 t;
  t.options = options;
  t.built = build_tree(build_patch_graph(boundary_from_arrangement3(arranged, solid_cells), rule), options);
  t.leaf_names = leaf_names(t.built.graph, arranged.complex);
  t.leaf_node = leaf_nodes(t.built);
  return t;
}

CellEvaluation evaluate_solid_tree3(const SolidTree3& tree, const Arranged3& whole,
                                    const std::vector<char>& whole_solid) {
  return evaluate_on_cells(tree.built, tree.options, whole.complex, whole_solid);
}

CellEvaluation evaluate_on_whole_space(const SolidTree3& tree, const Scene3& scene, const Arranged3& arranged,
                                       const std::vector<char>& solid_cells, const ArrangementLimits& limits) {
  if (solid_cells.size() != arranged.complex.cells.size())
    throw std::invalid_argument("evaluate_on_whole_space: one flag per cell expected");
  const Scene3 whole_scene = whole_space_scene3(scene);
  if (whole_scene.domain.min == scene.domain.min && whole_scene.domain.max == scene.domain.max)
    return evaluate_solid_tree3(tree, arranged, solid_cells);
  Arrangement3Options options;
  options.volumes = false;
  const Arranged3 whole = arrange(whole_scene, limits, options);
  return evaluate_solid_tree3(tree, whole, carry_to_whole_space(arranged, solid_cells, whole));
}

}  // namespace hsx::nhrep
