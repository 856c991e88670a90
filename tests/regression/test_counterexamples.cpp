// Every kept counterexample (data/counterexamples) must still be detected by `hsx check`'s checkers, and hsx must
// never claim a wrong optimum on it.
#include <hsx/algorithms/bsh/checks.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/scene_json.hpp>

#include <catch2/catch.hpp>

#include <filesystem>

using namespace hsx;

TEST_CASE("counterexamples: each is detected, and best-first never claims a wrong optimum", "[regression]") {
  const std::filesystem::path dir = std::filesystem::path(HSX_SOURCE_DIR) / "data" / "counterexamples";
  REQUIRE(std::filesystem::is_directory(dir));
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    INFO(entry.path().filename().string());
    const Scene2 scene = read_scene_file(entry.path().string());
    const Arranged2 arranged = arrange(scene);
    const auto results = bsh::check_all(arranged.complex);
    const bool detected = std::any_of(results.begin(), results.end(),
                                      [](const bsh::CheckResult& r) { return r.status == bsh::CheckResult::Fail; });
    CHECK(detected);
    const bsh::Problem problem(arranged.complex);
    bsh::ExtractOptions options;
    options.method = bsh::Method::BestFirst;
    const bsh::ExtractResult r = bsh::extract(problem, options);
    const bsh::BruteForceResult bf = bsh::brute_force(problem, true);
    if (r.optimal) CHECK(bsh::compare(r.energy, bf.energy) == Order::Equal);
  }
  CHECK(files > 0);
}
