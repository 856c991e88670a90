// data/complexes holds hsx-complex/1 documents (fuzz seeds for fuzz_complex_json, and regression inputs): each
// must import, pass check_complex, and describe the same arrangement as the scene it was exported from.
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/complex_json.hpp>
#include <hsx/io/scene_json.hpp>

#include <catch2/catch.hpp>

#include <filesystem>

using namespace hsx;

TEST_CASE("complexes: bundled hsx-complex/1 documents import and match their scenes", "[regression][io]") {
  const std::filesystem::path root(HSX_SOURCE_DIR);
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(root / "data" / "complexes")) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    INFO(entry.path().filename().string());
    const Complex imported = read_complex_file(entry.path().string());
    CHECK(check_complex(imported).empty());
    const auto scene_path = root / "data" / "scenes" / entry.path().filename();
    REQUIRE(std::filesystem::exists(scene_path));
    const Arranged2 arranged = arrange(read_scene_file(scene_path.string()));
    const Complex& original = arranged.complex;
    REQUIRE(imported.cells.size() == original.cells.size());
    REQUIRE(imported.patches.size() == original.patches.size());
    for (std::size_t p = 0; p < original.patches.size(); ++p)
      CHECK(compare(imported.patches[p].measure, original.patches[p].measure) == Order::Equal);
    // The same BSH optimum from both.
    bsh::ExtractOptions options;
    options.method = bsh::Method::BestFirst;
    const bsh::Problem a(imported), b(original);
    CHECK(bsh::extract(a, options).labelling == bsh::extract(b, options).labelling);
  }
  CHECK(files > 0);
}
