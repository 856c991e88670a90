// A project of its own with an io/ and a geometry/ folder of its own would collide with bare "io/files.hpp"
// includes; hsx's headers are all under <hsx/...>.
#include <hsx/hsx.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const hsx::LoadedInput in = hsx::load_input(argv[1]);
  const hsx::bsh::ExtractResult shape = hsx::extract_shape(in.complex());
  std::cout << in.complex().cells.size() << " cells; energy " << shape.energy.missing_samples << " missing, "
            << shape.energy.measure().decimal_string(12) << "\n";
  return 0;
}
