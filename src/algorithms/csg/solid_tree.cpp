#include <hsx/algorithms/csg/solid_tree.hpp>

namespace hsx::csg {

std::vector<char> planar_halfspaces(const Scene2& scene) {
  std::vector<char> planar;
  planar.reserve(scene.halfspaces.size());
  for (const auto& h : scene.halfspaces) planar.push_back(h.kind == HalfspaceKind2::Halfplane ? 1 : 0);
  return planar;
}

std::vector<char> planar_halfspaces(const Scene3& scene) {
  std::vector<char> planar;
  planar.reserve(scene.halfspaces.size());
  for (const auto& h : scene.halfspaces) planar.push_back(h.kind == HalfspaceKind3::Plane ? 1 : 0);
  return planar;
}

namespace {

SolidTree tree_with(const Complex& complex, const std::vector<char>& solid, const BhcOptions& options) {
  SolidTree out;
  out.bhc = bhc(complex, solid, options);
  out.describability = describability(complex, solid);
  return out;
}

}  // namespace

SolidTree build_tree(const Complex& complex, const std::vector<char>& solid) { return tree_with(complex, solid, {}); }

SolidTree build_tree(const Scene2& scene, const Arranged2& arranged, const std::vector<char>& solid,
                     const SolidTreeOptions& options) {
  BhcOptions bhc_options;
  bhc_options.planar = planar_halfspaces(scene);
  SolidTree out = tree_with(arranged.complex, solid, bhc_options);
  if (out.bhc.describable || !options.separators) return out;
  SeparatedSolid separated = add_separators(scene, arranged, solid, options.max_separators);
  bhc_options.planar = planar_halfspaces(separated.scene);
  out = tree_with(separated.arranged.complex, separated.cells, bhc_options);
  out.separated = std::move(separated);
  return out;
}

SolidTree build_tree(const Scene3& scene, const Arranged3& arranged, const std::vector<char>& solid,
                     const SolidTreeOptions& options, const ArrangementLimits& limits) {
  BhcOptions bhc_options;
  bhc_options.planar = planar_halfspaces(scene);
  SolidTree out = tree_with(arranged.complex, solid, bhc_options);
  if (out.bhc.describable || !options.separators) return out;
  SeparatedSolid3 separated = add_separators(scene, arranged, solid, options.max_separators, limits);
  bhc_options.planar = planar_halfspaces(separated.scene);
  out = tree_with(separated.arranged.complex, separated.cells, bhc_options);
  out.separated3 = std::move(separated);
  return out;
}

}  // namespace hsx::csg
