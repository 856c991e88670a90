// Every kept counterexample (data/counterexamples) must still be detected by `hsx check`'s checkers, and hsx must
// never claim a wrong optimum on it.
#include <hsx/algorithms/bsh/checks.hpp>
#include <hsx/io/input.hpp>

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
    const LoadedInput in = load_input(entry.path().string());  // 2D or 3D
    const Complex& complex = in.complex();
    const auto results = bsh::check_all(complex);
    const bool detected = std::any_of(results.begin(), results.end(),
                                      [](const bsh::CheckResult& r) { return r.status == bsh::CheckResult::Fail; });
    CHECK(detected);
    const bsh::Problem problem(complex);
    bsh::ExtractOptions options;
    options.method = bsh::Method::BestFirst;
    const bsh::ExtractResult r = bsh::extract(problem, options);
    const bsh::BruteForceResult bf = bsh::brute_force(problem, true);
    if (r.optimal) CHECK(bsh::compare(r.energy, bf.energy) == Order::Equal);
  }
  CHECK(files > 0);
}
