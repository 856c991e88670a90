// Regression test: the BSH paper's 2D figures (data/figures/*.json, described in docs/figures.md).
//
// Every scene in data/figures must have an entry in data/figures/expected.json; for each asserted method the
// scene is arranged and extracted, and every expected field is checked: missing samples, boundary measure (exact
// closed form as hsx prints it and proven equal, or a decimal prefix when transcendental), ties, sample-
// connectedness, optimality, the optimal shape(s) as cells located from interior points, their areas, and the
// optional figure-specific fields (beam steps, corners, cut cost, CSG describability, rejected candidates).
// The expected values were derived independently of hsx (see the expected.json description).
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/bsh/graph_cut.hpp>
#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/complex_json.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/kernel/measure.hpp>
#include <hsx/kernel/rational.hpp>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace hsx;
using nlohmann::json;

namespace {

const std::string kFigureDir = std::string(HSX_SOURCE_DIR) + "/data/figures";

std::vector<std::string> scene_files() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(kFigureDir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".json" && name != "expected.json") names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

json read_expected() {
  std::ifstream in(kFigureDir + "/expected.json");
  REQUIRE(in.good());
  std::stringstream text;
  text << in.rdbuf();
  json doc = json::parse(text.str());
  REQUIRE(doc.at("format") == "hsx-figure-expectations/1");
  return doc.at("scenes");
}

Rational rational(const json& value) {
  const auto q = parse_rational(value.get<std::string>());
  REQUIRE(q.has_value());
  return *q;
}

/// The cells holding the given interior points (each must fall inside a cell).
std::set<int> cells_at(const Arranged2& arranged, const json& points) {
  std::set<int> cells;
  for (const json& p : points) {
    const PointLocation2 at = arranged.arrangement.locate(PointQ2{rational(p.at(0)), rational(p.at(1))});
    INFO("point " << p.dump());
    REQUIRE(at.kind == PointLocation2::Face);
    cells.insert(at.index);
  }
  return cells;
}

std::set<int> inside_cells(const bsh::Labelling& labelling) {
  std::set<int> cells;
  for (int c = 0; c < static_cast<int>(labelling.size()); ++c)
    if (labelling[c]) cells.insert(c);
  return cells;
}

bsh::Labelling labelling_of(const std::set<int>& cells, int cell_count) {
  bsh::Labelling labelling(cell_count, 0);
  for (int c : cells) labelling[c] = 1;
  return labelling;
}

/// {"exact": closed form} (string as hsx prints it, and proven equal) and/or {"decimal": leading digits}.
void check_measure(const Measure& got, const json& expected, const std::string& what) {
  INFO(what << ": hsx " << got.decimal_string(30) << " = " << got.exact_string().value_or("(transcendental)")
            << ", expected " << expected.dump());
  if (expected.contains("exact")) {
    const std::string text = expected.at("exact").get<std::string>();
    CHECK(got.exact_string().value_or("") == text);
    std::string why;
    const auto want = parse_closed_form(text, &why);
    INFO(why);
    REQUIRE(want.has_value());
    CHECK(compare(got, *want) == Order::Equal);
  }
  if (expected.contains("decimal")) {
    const std::string prefix = expected.at("decimal").get<std::string>();
    CHECK(got.decimal_string(30).rfind(prefix, 0) == 0);
  }
  CHECK((expected.contains("exact") || expected.contains("decimal")));
}

/// Junctions where the boundary passes from one halfspace to another (exactly two boundary supports meet there,
/// on different halfspaces).
int corners(const bsh::Problem& problem, const bsh::Labelling& labelling) {
  const Complex& complex = problem.complex();
  std::set<int> on_b;
  for (int g : bsh::boundary_supports(problem, labelling)) on_b.insert(g);
  int count = 0;
  for (const Junction& j : complex.junctions) {
    std::set<int> supports;
    for (int p : j.patches)
      if (on_b.count(complex.patches[p].support)) supports.insert(complex.patches[p].support);
    if (supports.size() != 2) continue;
    const int a = *supports.begin(), b = *supports.rbegin();
    if (complex.patches[complex.supports[a].front()].halfspace != complex.patches[complex.supports[b].front()].halfspace)
      ++count;
  }
  return count;
}

/// CSG-describable on the scene's halfspaces (Shapiro-Vossler): the shape is a union of canonical intersection
/// terms, i.e. cells with the same inside/outside classification by every halfspace get the same label.
bool csg_describable(const Complex& complex, const bsh::Labelling& labelling) {
  std::map<std::vector<char>, int> label_of_term;
  for (int c = 0; c < static_cast<int>(complex.cells.size()); ++c) {
    const auto [it, inserted] = label_of_term.emplace(complex.cells[c].inside, labelling[c]);
    if (!inserted && it->second != labelling[c]) return false;
  }
  return true;
}

void check_method(const Arranged2& arranged, const bsh::Problem& problem, const std::string& name, const json& want,
                  bsh::ExtractResult& result) {
  const auto method = bsh::method_from_string(name);
  REQUIRE(method.has_value());
  bsh::ExtractOptions options;
  options.method = *method;
  options.beam_width = want.value("beam_width", 1);
  result = bsh::extract(problem, options);

  CHECK(result.stopped_by.empty());
  CHECK(result.energy.missing_samples == want.at("missing_samples").get<long>());
  check_measure(result.energy.measure(), want.at("measure"), "energy.measure()");
  CHECK(result.ties.count == want.at("ties").get<int>());
  CHECK(result.ties.certified == want.value("ties_certified", true));
  CHECK(result.sample_connected == want.at("sample_connected").get<bool>());
  CHECK(result.optimal == want.at("optimal").get<bool>());

  // The optimal shape(s): primary + tied, as unordered sets of cells, each with its area.
  std::vector<bsh::Labelling> found{result.labelling};
  found.insert(found.end(), result.tied.begin(), result.tied.end());
  std::vector<std::set<int>> expected_shapes;
  for (const json& shape : want.at("shapes")) expected_shapes.push_back(cells_at(arranged, shape.at("inside_points")));
  REQUIRE(found.size() == expected_shapes.size());
  for (const bsh::Labelling& labelling : found) {
    const std::set<int> cells = inside_cells(labelling);
    const auto match = std::find(expected_shapes.begin(), expected_shapes.end(), cells);
    INFO("shape with " << cells.size() << " inside cells");
    REQUIRE(match != expected_shapes.end());
    const json& shape = want.at("shapes").at(match - expected_shapes.begin());
    check_measure(bsh::inside_measure(problem.complex(), labelling), shape.at("area"), "area");
    // The labelling's own energy agrees with the reported one (all shapes of a method have equal energies).
    const bsh::Energy e = bsh::energy(problem, labelling);
    CHECK(e.missing_samples == result.energy.missing_samples);
    CHECK(compare(e.measure(), result.energy.measure()) == Order::Equal);
    CHECK(bsh::is_orientation_preserving(problem, labelling));
  }

  if (want.contains("steps")) {
    CHECK(static_cast<int>(result.steps.size()) == want.at("steps").get<int>());
    std::vector<int> counts;
    for (const auto& step : result.steps) counts.push_back(static_cast<int>(step.size()));
    CHECK(counts == want.at("removed_counts").get<std::vector<int>>());
  }
  if (want.contains("corners")) CHECK(corners(problem, result.labelling) == want.at("corners").get<int>());
  if (want.contains("cut_cost")) {
    bsh::Energy cost;
    REQUIRE(bsh::cut_cost(problem, {}, result.labelling, &cost));
    CHECK(cost.missing_samples == want.at("cut_cost").at("missing_samples").get<long>());
    check_measure(cost.measure(), want.at("cut_cost").at("measure"), "cut cost");
  }
}

}  // namespace

TEST_CASE("figures: every scene has an expectation and every expectation a scene", "[figures]") {
  const json expected = read_expected();
  const std::vector<std::string> files = scene_files();
  CHECK(files.size() >= 20);
  for (const std::string& file : files) {
    INFO(file);
    CHECK(expected.contains(file));
    if (expected.contains(file)) CHECK(!expected.at(file).at("methods").empty());
  }
  for (const auto& item : expected.items()) {
    INFO(item.key());
    CHECK(std::find(files.begin(), files.end(), item.key()) != files.end());
  }
}

TEST_CASE("figures: asserted outcomes", "[figures]") {
  const json expected = read_expected();
  for (const std::string& file : scene_files()) {
    DYNAMIC_SECTION(file) {
      INFO(file);
      REQUIRE(expected.contains(file));
      const json& want = expected.at(file);
      const Scene2 scene = read_scene_file(kFigureDir + "/" + file);
      CHECK(scene.domain_given);
      CHECK(!scene.description.empty());
      for (const Sample2& s : scene.samples) CHECK(!s.snapped);  // exact `at` samples only
      const Arranged2 arranged = arrange(scene);
      const bsh::Problem problem(arranged.complex);

      std::map<std::string, bsh::ExtractResult> results;
      for (const auto& method : want.at("methods").items()) {
        INFO("method " << method.key());
        check_method(arranged, problem, method.key(), method.value(), results[method.key()]);
      }

      if (want.contains("csg_describable")) {
        for (const auto& [name, result] : results) {
          INFO("method " << name);
          CHECK(csg_describable(arranged.complex, result.labelling) == want.at("csg_describable").get<bool>());
        }
      }

      // Fig. 3: shapes with the same halfspaces and samples that hsx must not return.
      if (want.contains("candidates")) {
        const bsh::ExtractResult& reference = results.count("best-first") ? results.at("best-first") : results.begin()->second;
        for (const json& candidate : want.at("candidates")) {
          INFO("candidate " << candidate.at("name").get<std::string>());
          const bsh::Labelling labelling =
              labelling_of(cells_at(arranged, candidate.at("inside_points")), problem.cell_count());
          for (const auto& [name, result] : results) CHECK(result.labelling != labelling);
          const bool op = bsh::is_orientation_preserving(problem, labelling);
          CHECK(op == candidate.at("orientation_preserving").get<bool>());
          if (!op) continue;
          const bsh::Energy e = bsh::energy(problem, labelling);
          CHECK(e.missing_samples == candidate.at("missing_samples").get<long>());
          check_measure(e.measure(), candidate.at("measure"), "candidate measure");
          CHECK(bsh::sample_connectivity(problem, labelling).sample_connected() ==
                candidate.at("sample_connected").get<bool>());
          if (candidate.value("worse_than_result", false)) CHECK(bsh::compare(e, reference.energy) == Order::Greater);
        }
      }
    }
  }
}
