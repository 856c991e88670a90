// Arrange a scene exactly, extract its BSH shape with the complete search, print the energy and the area, and
// write the hsx-result/1 document.   Usage: arrange_and_extract SCENE.json [RESULT.json]
#include <hsx/hsx.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: arrange_and_extract SCENE.json [RESULT.json]\n";
    return 2;
  }
  try {
    const hsx::LoadedInput in = hsx::load_input(argv[1]);  // exact arrangement of the scene's boundaries
    const hsx::Complex& complex = in.complex();
    std::cout << complex.cells.size() << " cells, " << complex.patches.size() << " patches, "
              << complex.samples.size() << " samples\n";

    hsx::bsh::ExtractOptions options;
    options.method = hsx::bsh::Method::BestFirst;  // complete: the result is proven optimal
    const hsx::bsh::ExtractResult shape = hsx::extract_shape(complex, options);

    const hsx::Measure& length = shape.energy.measure();
    std::cout << "optimal " << (shape.optimal ? "yes" : "no") << ", " << shape.energy.missing_samples
              << " missing samples, boundary length " << length.decimal_string(20) << " = "
              << length.exact_string().value_or("(no closed form)") << "\n";
    const hsx::Measure area = hsx::bsh::inside_measure(complex, shape.labelling);
    std::cout << "area " << area.decimal_string(20) << ", ties " << shape.ties.count << "\n";

    if (argc > 2) hsx::write_file_atomically(argv[2], hsx::result_json_text(complex, shape, in.pieces()));
    return 0;
  } catch (const hsx::InputError& e) {
    std::cerr << "bad input: " << e.what() << "\n";
    return 2;
  }
}
