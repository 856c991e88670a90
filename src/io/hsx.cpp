#include <hsx/hsx.hpp>

#include <hsx/algorithms/nhrep/patch_graph.hpp>
#include <hsx/algorithms/csg/solid_tree.hpp>
#include <hsx/algorithms/nhrep/planar.hpp>
#include <hsx/complex/boundary_from_mesh.hpp>
#include <hsx/io/complex_json.hpp>
#include <hsx/io/csg_text.hpp>
#include <hsx/io/result_json.hpp>

#include <stdexcept>

namespace hsx {

bsh::ExtractResult extract_shape(const Complex& complex, const bsh::ExtractOptions& options) {
  const bsh::Problem problem(complex);
  return bsh::extract(problem, options);
}

bsh::Grade grade_labelling(const Complex& complex, const bsh::Labelling& labelling,
                           const bsh::ExtractOptions& oracle) {
  if (labelling.size() != complex.cells.size())
    throw InputError("the labelling has " + std::to_string(labelling.size()) + " labels, the complex " +
                     std::to_string(complex.cells.size()) + " cells");
  const bsh::Problem problem(complex);
  return bsh::grade(problem, labelling, oracle);
}

std::vector<char> solid_from_csg(const Complex& complex, const std::string& expression) {
  const csg::ExprPtr e = parse_csg_text(expression, complex.halfspace_names, "expression");
  return csg::evaluate(*e, complex);
}

csg::BhcResult csg_tree(const LoadedInput& input, const std::vector<char>& solid) {
  const Complex& complex = input.complex();
  if (solid.size() != complex.cells.size())
    throw InputError("the solid has " + std::to_string(solid.size()) + " cell flags, the complex " +
                     std::to_string(complex.cells.size()) + " cells");
  csg::BhcOptions options;
  // As `hsx csg` (csg::build_tree): half-planes preferred in 2D, planes in 3D.
  if (input.scene) options.planar = csg::planar_halfspaces(*input.scene);
  else if (input.scene3) options.planar = csg::planar_halfspaces(*input.scene3);
  return csg::bhc(complex, solid, options);
}

nhrep::BuildResult nhrep_tree(const Arranged2& arranged, const std::vector<char>& solid,
                              const nhrep::BuildOptions& options) {
  try {
    return nhrep::build_planar_tree(arranged, solid, options).built;
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("nhrep_tree: ") + e.what());
  }
}

nhrep::BuildResult nhrep_tree_of_mesh(const std::string& obj_path, const std::string& fea_path,
                                      const Rational& sharp_angle_degrees, const nhrep::BuildOptions& options) {
  const Mesh3 mesh = read_mesh3_file(obj_path);
  const FeatureEdgeList features = read_fea_file(fea_path);
  return nhrep::build_tree(nhrep::build_patch_graph(boundary_from_mesh(mesh, features, sharp_angle_degrees)),
                           options);
}

std::string complex_json_text(const LoadedInput& input) {
  if (input.arranged)
    return complex_json_text(input.complex(), &input.arranged->arrangement, &input.scene->domain);
  if (input.arranged3)
    return complex3_json_text(input.complex(), &input.arranged3->arrangement, &input.scene3->domain);
  if (input.document->complex.dimension == 3)
    return complex3_json_text(input.complex(), nullptr, input.document->domain3 ? &*input.document->domain3 : nullptr);
  return complex_json_text(input.complex(), nullptr, input.document->domain ? &*input.document->domain : nullptr);
}

std::string result_json_text(const Complex& complex, const bsh::ExtractResult& result, const PlanarPieces& geometry,
                             bool include_seconds) {
  const bsh::Problem problem(complex);
  return result_to_json(problem, result, geometry, include_seconds).dump(2) + "\n";
}

}  // namespace hsx
