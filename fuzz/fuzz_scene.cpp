// Bytes -> scene (hsx-scene/1) -> exact arrangement -> complex -> JSON and SVG. Bad input must end in InputError;
// anything else (crash, sanitizer report, other exception, hang) is a finding. The size bounds keep one input's
// arrangement small: correctness, not scale, is what this target explores.
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/complex_json.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/io/svg.hpp>

#include <cstdint>
#include <cstdlib>
#include <iostream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return -1;
  hsx::SceneReadLimits limits;
  limits.numbers.max_chars = 40;
  limits.numbers.max_exponent = 12;
  limits.max_halfspaces = 24;
  limits.max_samples = 48;
  limits.max_polygon_vertices = 24;
  hsx::Scene2 scene;
  try {
    scene = hsx::read_scene_text(std::string_view(reinterpret_cast<const char*>(data), size), limits);
  } catch (const hsx::InputError&) {
    return 0;
  }
  try {
    const hsx::Arranged2 arranged = hsx::arrange(scene);
    const auto problems = hsx::check_complex(arranged.complex);
    if (!problems.empty()) {
      std::cerr << "inconsistent complex: " << problems.front() << "\n";
      std::abort();
    }
    const auto json = hsx::complex_to_json(arranged.complex, &arranged.arrangement, &scene.domain);
    const hsx::Complex back = hsx::complex_from_json(json);
    if (back.patches.size() != arranged.complex.patches.size() || back.cells.size() != arranged.complex.cells.size())
      std::abort();
    (void)hsx::arrangement_svg(scene, arranged.arrangement, arranged.complex);
  } catch (const hsx::InputError&) {
    // e.g. a sample on a vertex where boundaries meet: a clean rejection.
  }
  return 0;
}
