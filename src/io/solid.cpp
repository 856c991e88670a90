#include <hsx/io/solid.hpp>

#include <hsx/io/csg_text.hpp>
#include <hsx/io/exact_json.hpp>

namespace hsx {

Solid load_solid(const LoadedInput& in, const SolidSource& source) {
  if (source.shape_path.empty() == source.csg.empty())
    throw InputError("give the solid either as a result file (" + source.shape_option + " RESULT) or as " +
                     source.csg_option + " EXPR, exactly one");
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
  solid.expression = read_csg_argument(source.csg, complex.halfspace_names);
  solid.cells = csg::evaluate(*solid.expression, complex);
  return solid;
}

}  // namespace hsx
