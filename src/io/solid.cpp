#include <hsx/io/solid.hpp>

#include <hsx/geometry/mesh_solid3.hpp>
#include <hsx/io/csg_text.hpp>
#include <hsx/io/exact_json.hpp>

namespace hsx {

Solid load_solid(const LoadedInput& in, const SolidSource& source, const ArrangementLimits& limits) {
  const int given = !source.shape_path.empty() + !source.csg.empty() + !source.mesh_path.empty();
  if (given != 1)
    throw InputError("give the solid as a result file (" + source.shape_option + " RESULT), as " +
                     source.csg_option + " EXPR or as " + source.mesh_option + " FILE, exactly one");
  Solid solid;
  const Complex& complex = in.complex();
  if (!source.shape_path.empty()) {
    const nlohmann::json document = read_exact_json_file(source.shape_path);  // its errors name the path
    try {
      solid.cells = read_result_labelling(document, complex);
    } catch (const InputError& e) {
      throw InputError(source.shape_path + ": " + e.what());
    }
    return solid;
  }
  if (!source.mesh_path.empty()) {
    if (!in.scene3)
      throw InputError(source.mesh_option + ": a solid given as a mesh needs a 3D scene (" + in.path + " is " +
                       (in.scene ? "a 2D scene" : "a complex") + "; give " + source.csg_option + " or " +
                       source.shape_option + ")");
    const Mesh3 mesh = build_mesh3(read_mesh_file(source.mesh_path));
    solid.cells = cells_inside_mesh(*in.scene3, in.arranged3->arrangement, mesh, limits);
    return solid;
  }
  solid.expression = read_csg_argument(source.csg, complex.halfspace_names);
  solid.cells = csg::evaluate(*solid.expression, complex);
  return solid;
}

}  // namespace hsx
