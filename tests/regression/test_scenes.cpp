// Regression test over every bundled scene (data/scenes/*.json): read, arrange, check the complex, and compare
// the counts with tests/regression/expected.json. Every expectation there was verified by hand (see the
// "reasoning" field of each entry). A scene without an expectation fails, so new data is never silently untested;
// an expectation without a scene fails too.
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/scene_json.hpp>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

using namespace hsx;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> scene_files() {
  std::vector<fs::path> out;
  for (const auto& entry : fs::directory_iterator(fs::path(HSX_SOURCE_DIR) / "data" / "scenes"))
    if (entry.is_regular_file() && entry.path().extension() == ".json") out.push_back(entry.path());
  std::sort(out.begin(), out.end());
  return out;
}

nlohmann::json expectations() {
  return nlohmann::json::parse(read_file((fs::path(HSX_SOURCE_DIR) / "tests" / "regression" / "expected.json").string()));
}

}  // namespace

TEST_CASE("regression: every bundled scene has an expectation and meets it", "[regression]") {
  const nlohmann::json expected = expectations().at("scenes");
  const std::vector<fs::path> files = scene_files();
  REQUIRE(!files.empty());
  std::set<std::string> seen;
  for (const fs::path& file : files) {
    const std::string name = file.filename().string();
    seen.insert(name);
    INFO("scene " << name);
    if (!expected.contains(name)) {
      FAIL_CHECK("no expectation recorded in tests/regression/expected.json for data/scenes/" << name
                                                                                             << ": verify its counts by hand and add them");
      continue;
    }
    const nlohmann::json& e = expected.at(name);
    const Scene2 scene = read_scene_file(file.string());
    CHECK(!scene.description.empty());
    const Arranged2 a = arrange(scene);
    std::string problems;
    for (const auto& p : check_complex(a.complex)) problems += p + "\n";
    CHECK(problems == "");
    CHECK(a.arrangement.vertices().size() == e.at("vertices").get<std::size_t>());
    CHECK(a.arrangement.edges().size() == e.at("edges").get<std::size_t>());
    CHECK(a.complex.cells.size() == e.at("cells").get<std::size_t>());
    CHECK(a.complex.outer_cell_count() == e.at("outer_cells").get<int>());
    CHECK(a.complex.patches.size() == e.at("patches").get<std::size_t>());
    if (e.contains("junctions")) CHECK(a.complex.junctions.size() == e.at("junctions").get<std::size_t>());
    if (e.contains("supports")) CHECK(a.complex.supports.size() == e.at("supports").get<std::size_t>());
    // Euler's relation for the record: V - E + F = 1 + C with F counting the unbounded face.
    CHECK(static_cast<int>(a.arrangement.vertices().size()) - static_cast<int>(a.arrangement.edges().size()) +
              static_cast<int>(a.arrangement.faces().size()) + 1 ==
          1 + a.arrangement.connected_components());
  }
  for (const auto& [name, value] : expected.items()) {
    INFO("expectation " << name);
    CHECK(seen.count(name) == 1);  // an expectation whose scene file is gone
  }
}
