// BSH's proposition checkers and GENERATE-SAMPLES on 3D complexes: the Sec. 3.1 manifold check against a
// triangle-level oracle on every labelling of small scenes, the kept 3D counterexamples, and GENERATE-SAMPLES
// end to end (samples placed in the scene, written, read back, arranged and extracted).
#include <hsx/algorithms/bsh/checks.hpp>
#include <hsx/algorithms/bsh/sample_scene.hpp>
#include <hsx/algorithms/bsh/samples.hpp>
#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/io/scene_json.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <string>

using namespace hsx;
using namespace hsx::bsh;

namespace {

std::string box(const std::string& name, const std::string& lo, const std::string& hi) {
  return R"({"name": ")" + name + R"(", "kind": "box", "min": )" + lo + R"(, "max": )" + hi + "}";
}

std::string scene_text(const std::string& domain_lo, const std::string& domain_hi, const std::string& halfspaces,
                       const std::string& samples) {
  return R"({"format": "hsx-scene/1", "dimension": 3, "domain": {"min": )" + domain_lo + R"(, "max": )" +
         domain_hi + R"(}, "halfspaces": [)" + halfspaces + R"(], "samples": [)" + samples + "]}";
}

/// Small scenes, generic and not: name -> hsx-scene/1 text.
std::map<std::string, std::string> small_scenes() {
  return {
      {"box and plane",
       scene_text("[-1,-1,-1]", "[2,2,2]",
                  box("A", "[0,0,0]", "[1,1,1]") + R"(, {"name": "P", "kind": "plane", "normal": [0,0,1], "offset": "1/2"})",
                  R"({"on": "A", "at": [0, "1/2", "1/4"]}, {"on": "P", "at": ["1/2", "1/2", "1/2"]})")},
      {"two boxes overlapping",
       scene_text("[-1,-1,-1]", "[4,4,4]", box("A", "[0,0,0]", "[2,2,2]") + ", " + box("B", R"([1,"1/2","1/3"])", R"([3,"5/2","7/3"])"),
                  R"({"on": "A", "at": [0, 1, 1]}, {"on": "B", "at": [3, 1, 1]})")},
      {"two boxes sharing an edge",
       scene_text("[-1,-1,-1]", "[3,3,2]", box("A", "[0,0,0]", "[1,1,1]") + ", " + box("B", "[1,1,0]", "[2,2,1]"),
                  R"({"on": "A", "at": [0, "1/2", "1/2"]}, {"on": "B", "at": [2, "3/2", "1/2"]})")},
      {"two boxes sharing a vertex",
       scene_text("[-1,-1,-1]", "[3,3,3]", box("A", "[0,0,0]", "[1,1,1]") + ", " + box("B", "[1,1,1]", "[2,2,2]"),
                  R"({"on": "A", "at": [0, "1/2", "1/2"]}, {"on": "B", "at": [2, "3/2", "3/2"]})")},
      {"two boxes sharing a face, two planes through an edge",
       scene_text("[-1,-1,-1]", "[3,2,2]",
                  box("A", "[0,0,0]", "[1,1,1]") + ", " + box("B", "[1,0,0]", "[2,1,1]") +
                      R"(, {"name": "P", "kind": "plane", "normal": [1,1,0], "offset": 2})" +
                      R"(, {"name": "Q", "kind": "plane", "normal": [0,0,-1], "offset": -1})",
                  R"({"on": "A", "at": [0, "1/2", "1/2"]})")},
  };
}

Arranged3 arranged(const std::string& text) { return arrange(read_scene3_text(text)); }

/// Every labelling of the inner cells (outer cells 0), at most 2^12.
std::vector<Labelling> all_labellings(const Complex& c) {
  std::vector<int> inner;
  for (int k = 0; k < static_cast<int>(c.cells.size()); ++k)
    if (!c.cells[k].outer) inner.push_back(k);
  REQUIRE(inner.size() <= 12);
  std::vector<Labelling> out;
  for (unsigned mask = 0; mask < (1u << inner.size()); ++mask) {
    Labelling l(c.cells.size(), 0);
    for (std::size_t i = 0; i < inner.size(); ++i) l[inner[i]] = (mask >> i) & 1;
    out.push_back(l);
  }
  return out;
}

/// The oracle, from the arrangement's triangles alone: b (the triangles whose two cells differ) is a 2-manifold
/// iff every edge has 0 or 2 of them and, at every vertex, they form one cycle (or none) around it.
bool manifold_by_triangles(const Arrangement3& arr, const Labelling& l) {
  const auto label = [&](int cell) { return cell >= 0 && l[cell]; };
  std::vector<char> on_b(arr.triangles().size());
  for (std::size_t t = 0; t < on_b.size(); ++t)
    on_b[t] = label(arr.triangles()[t].front_cell) != label(arr.triangles()[t].back_cell);
  for (const ArrEdge3& e : arr.edges()) {
    const long k = std::count_if(e.triangles.begin(), e.triangles.end(), [&](int t) { return on_b[t] != 0; });
    if (k != 0 && k != 2) return false;
  }
  // Vertex links: arcs between the two other vertices of each b triangle at v; one cycle iff connected.
  std::vector<std::vector<std::pair<int, int>>> arcs(arr.vertices().size());
  for (std::size_t t = 0; t < on_b.size(); ++t) {
    if (!on_b[t]) continue;
    const auto& v = arr.triangles()[t].vertices;
    for (int i = 0; i < 3; ++i) arcs[v[i]].push_back({v[(i + 1) % 3], v[(i + 2) % 3]});
  }
  for (const auto& list : arcs) {
    if (list.empty()) continue;
    std::set<int> reached{list.front().first};
    for (bool grew = true; grew;) {
      grew = false;
      for (const auto& [a, b] : list)
        if (reached.count(a) != reached.count(b)) {
          reached.insert(a);
          reached.insert(b);
          grew = true;
        }
    }
    std::set<int> all;
    for (const auto& [a, b] : list) all.insert({a, b});
    if (reached.size() != all.size()) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("bsh3: the Sec. 3.1 manifold check agrees with a triangle-level oracle on every labelling", "[bsh3]") {
  auto scenes = small_scenes();
  scenes["primitives"] = "";
  for (const auto& [name, text] : scenes) {
    INFO(name);
    const Arranged3 a = text.empty() ? arrange(read_scene3_file(std::string(HSX_SOURCE_DIR) +
                                                                "/data/scenes3d/primitives.json"))
                                     : arranged(text);
    const Problem problem(a.complex);
    int manifold = 0, not_manifold = 0;
    for (const Labelling& l : all_labellings(a.complex)) {
      const bool expected = manifold_by_triangles(a.arrangement, l);
      const CheckResult r = check_manifold_parity(problem, l);
      INFO(r.witness);
      CHECK((r.status == CheckResult::Pass) == expected);
      CHECK(r.status != CheckResult::Skipped);
      (expected ? manifold : not_manifold) += 1;
    }
    CHECK(manifold > 0);
    if (name.find("sharing an edge") != std::string::npos || name.find("sharing a vertex") != std::string::npos)
      CHECK(not_manifold > 0);
  }
}

TEST_CASE("bsh3: sheets and corners of the pinched scenes", "[bsh3]") {
  const auto scenes = small_scenes();
  SECTION("two boxes sharing an edge: one junction, each box's patch on both of its sides") {
    const Arranged3 a = arranged(scenes.at("two boxes sharing an edge"));
    REQUIRE(a.complex.junctions.size() == 1);
    CHECK(a.complex.junctions[0].sheets.size() == 4);
    Labelling both(a.complex.cells.size(), 0);
    for (const Patch& p : a.complex.patches) both[p.inside_cell] = 1;
    const CheckResult r = check_manifold_parity(Problem(a.complex), both);
    CHECK(r.status == CheckResult::Fail);
    CHECK(r.witness.find("4 sheets") != std::string::npos);
  }
  SECTION("two boxes sharing a vertex: no junction, a corner with two whole-disc wedges") {
    const Arranged3 a = arranged(scenes.at("two boxes sharing a vertex"));
    CHECK(a.complex.junctions.empty());
    REQUIRE(a.complex.corners.size() == 1);
    CHECK(a.complex.corners[0].spokes.empty());
    CHECK(a.complex.corners[0].wedges.size() == 2);
    Labelling both(a.complex.cells.size(), 0);
    for (const Patch& p : a.complex.patches) both[p.inside_cell] = 1;
    const CheckResult r = check_manifold_parity(Problem(a.complex), both);
    CHECK(r.status == CheckResult::Fail);
    CHECK(r.witness.find("2 circles") != std::string::npos);
  }
  SECTION("a complex without sheets and corners: skipped, not passed") {
    Complex c = arranged(scenes.at("box and plane")).complex;
    for (Junction& j : c.junctions) j.sheets.clear();
    c.corners.clear();
    CHECK(check_manifold_parity(Problem(c), Labelling(c.cells.size(), 0)).status == CheckResult::Skipped);
  }
}

TEST_CASE("bsh3: every checker runs on small 3D scenes; only the pinched ones fail, and only Sec. 3.1", "[bsh3]") {
  for (const auto& [name, text] : small_scenes()) {
    INFO(name);
    const Arranged3 a = arranged(text);
    const bool pinched = name.find("sharing an edge") != std::string::npos || name.find("sharing a vertex") != std::string::npos;
    for (const CheckResult& r : check_all(a.complex)) {
      INFO(r.name << ": " << r.witness);
      const bool manifold_check = r.name.rfind("Sec. 3.1", 0) == 0;
      CHECK(r.status != CheckResult::Stopped);
      if (manifold_check && pinched) CHECK(r.status == CheckResult::Fail);
      else CHECK(r.status != CheckResult::Fail);
    }
  }
}

TEST_CASE("bsh3: GENERATE-SAMPLES in 3D, end to end through the scene format", "[bsh3]") {
  for (const auto& [name, text] : small_scenes()) {
    INFO(name);
    const Scene3 scene = read_scene3_text(text);
    const Arranged3 a = arrange(scene);
    const Problem problem(a.complex);
    int targets = 0;
    for (const Labelling& target : all_labellings(a.complex)) {
      if (!is_orientation_preserving(problem, target)) continue;
      ++targets;
      SampleGenOptions options;  // beam, K = 1
      const SampleGenResult r = generate_samples(a.complex, target, options);
      REQUIRE(r.reproduced);
      CHECK(r.initial <= static_cast<int>(r.sample_patches.size()));
      // Placed, written, read back and arranged: every sample on its patch, strictly inside a triangle.
      const Scene3 sampled = scene_with_samples(scene, a, r.sample_patches, "generated");
      const Scene3 back = read_scene3(write_scene3(sampled));
      const Arranged3 b = arrange(back);
      REQUIRE(b.complex.samples.size() == r.sample_patches.size());
      for (std::size_t s = 0; s < r.sample_patches.size(); ++s) {
        CHECK(b.complex.samples[s].patch == r.sample_patches[s]);
        CHECK(b.arrangement.locate(back.samples[s].location).kind == PointLocation3::Triangle);
      }
      ExtractOptions beam;
      beam.method = Method::Beam;
      CHECK(extract(Problem(b.complex), beam).labelling == target);
    }
    CHECK(targets > 1);
  }
}

TEST_CASE("bsh3: the central patch in 3D is the one of least graph eccentricity", "[bsh3]") {
  // Box A cut by two parallel planes: A's surface falls into three patches in a row (bottom, middle band, top);
  // the target A alone has one component of A, whose centre is the band (eccentricity 1, the ends have 2).
  const std::string text = scene_text(
      "[-1,-1,-1]", "[2,2,2]",
      box("A", "[0,0,0]", "[1,1,1]") + R"(, {"name": "P", "kind": "plane", "normal": [0,0,1], "offset": "1/3"})" +
          R"(, {"name": "Q", "kind": "plane", "normal": [0,0,1], "offset": "2/3"})",
      "");
  const Arranged3 a = arranged(text);
  Labelling target(a.complex.cells.size(), 0);
  std::vector<int> a_patches;
  for (int p = 0; p < static_cast<int>(a.complex.patches.size()); ++p)
    if (a.complex.patches[p].halfspace == 0) {
      a_patches.push_back(p);
      target[a.complex.patches[p].inside_cell] = 1;
    }
  REQUIRE(a_patches.size() == 3);
  const SampleGenResult r = generate_samples(a.complex, target, {});
  REQUIRE(r.reproduced);
  REQUIRE(r.initial == 1);
  const int centre = r.sample_patches.front();
  // The band touches both planes; the ends touch one each.
  std::set<int> halfspaces_met;
  for (int j : a.complex.patches[centre].junctions)
    for (int q : a.complex.junctions[j].patches) halfspaces_met.insert(a.complex.patches[q].halfspace);
  CHECK(halfspaces_met == std::set<int>{0, 1, 2});
}
