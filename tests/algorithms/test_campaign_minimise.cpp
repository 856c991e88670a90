// Tests of minimising a campaign's failing scenes (algorithms/campaign/minimise.hpp) and of what io keeps of them
// (io/campaign_files.hpp: the .min.json note, the summary's SVG, merging shards):
// - an extra check that fails exactly when a given halfspace is present minimises any scene to that halfspace
//   alone, without samples, with simpler coordinates; the result is the same bytes when run again, and the step
//   budget is honoured;
// - the kept Prop. 5.1 counterexample (data/counterexamples/prop51-campaign-seed1-scene80.json) minimises to a
//   smaller scene on which Prop. 5.1 still fails;
// - simpler_values and lower_segments on known values;
// - carry_by_sign_vectors: a shape carried to fewer halfspaces, refused when a reduction merges inside and outside
//   cells or makes a sign vector no original cell has;
// - 3D: the kept manifold counterexample (seed 1, scene 543) and a Prop. 6.1 failure of a 3D intended shape
//   (seed 1, scene 185: a CSG solid that is not orientation-preserving) minimise to smaller scenes on which the same
//   check fails, the intended shape carried along; the same bytes when run again;
// - check_scene on random_scene's scene is run_scene's record (but for the degeneracies);
// - the summary SVG is well-formed enough (balanced tags) and changes with the rates.
#include <hsx/algorithms/campaign/campaign.hpp>
#include <hsx/algorithms/campaign/minimise.hpp>
#include <hsx/io/campaign_files.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/geometry/scene_builders.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <regex>

using namespace hsx;
using namespace hsx::campaign;

namespace {

/// The extra check "has": fails exactly when the scene has a halfspace named `name`.
ExtraCheck has_halfspace(const std::string& name) {
  ExtraCheck e;
  e.name = "has";
  e.run = [name](std::uint64_t, const Scene2& scene, const Arranged2&) {
    const bool present = scene.find_halfspace(name) >= 0;
    return CheckOutcome{"has", present ? CheckStatus::Failed : CheckStatus::Held,
                        present ? "the halfspace " + name + " is there" : "no " + name};
  };
  return e;
}

Rational q(long n, long d = 1) {
  Rational r(n, d);
  r.canonicalize();
  return r;
}

}  // namespace

TEST_CASE("minimise: simpler_values, simplest first", "[campaign][minimise]") {
  CHECK(simpler_values(q(7, 4)) == std::vector<Rational>{q(0), q(1), q(2)});
  CHECK(simpler_values(q(-5, 8)) == std::vector<Rational>{q(0), q(-1), q(-1, 2), q(-3, 4)});
  CHECK(simpler_values(q(6)) == std::vector<Rational>{q(0), q(3)});
  CHECK(simpler_values(q(0)).empty());
  CHECK(simpler_values(q(1, 2)) == std::vector<Rational>{q(0), q(1)});
}

TEST_CASE("minimise: lower_segments, lowest first", "[campaign][minimise]") {
  CHECK(lower_segments(6) == std::vector<int>{3, 4});
  CHECK(lower_segments(13) == std::vector<int>{3, 4, 6, 8, 12});
  CHECK(lower_segments(3).empty());
}

namespace {

/// The complex of a resolved 2D scene of `halfspaces` in the box [-4, 4]^2.
Complex complex_of(std::vector<Halfspace2> halfspaces) {
  Scene2 scene;
  scene.domain = {{q(-4), q(-4)}, {q(4), q(4)}};
  scene.domain_given = true;
  scene.halfspaces = std::move(halfspaces);
  validate_and_resolve(scene);
  return arrange(scene).complex;
}

/// The flags of the cells whose sign vectors are among `inside`.
std::vector<char> cells_with(const Complex& c, const std::vector<std::vector<char>>& inside) {
  std::vector<char> out(c.cells.size(), 0);
  for (std::size_t k = 0; k < c.cells.size(); ++k)
    out[k] = std::find(inside.begin(), inside.end(), c.cells[k].inside) != inside.end() ? 1 : 0;
  return out;
}

}  // namespace

TEST_CASE("minimise: an intended shape carried by sign vectors", "[campaign][minimise]") {
  const Halfspace2 d = disk("D", {q(0), q(0)}, q(2)), l = halfplane("L", {q(1), q(0)}, q(0));
  const Complex both = complex_of({d, l}), alone = complex_of({d});
  // The whole disk: well defined on the disk alone (its cell inside, the outer cell outside).
  const std::vector<char> disk_shape = cells_with(both, {{1, 1}, {1, 0}});
  const std::optional<std::vector<char>> carried = carry_by_sign_vectors(both, disk_shape, {0}, alone);
  REQUIRE(carried);
  CHECK(*carried == cells_with(alone, {{1}}));
  // Unchanged on the same complex.
  CHECK(carry_by_sign_vectors(both, disk_shape, {0, 1}, both) == std::optional<std::vector<char>>(disk_shape));
  // Half the disk: removing L merges its inside and outside halves into one sign vector: not well defined.
  CHECK_FALSE(carry_by_sign_vectors(both, cells_with(both, {{1, 1}}), {0}, alone));
  // A moved disk overlapping the other makes a sign vector (inside both) no original cell has.
  const Complex apart = complex_of({disk("A", {q(-2), q(0)}, q(1)), disk("B", {q(2), q(0)}, q(1))});
  const Complex overlap = complex_of({disk("A", {q(-2), q(0)}, q(1)), disk("B", {q(-1), q(0)}, q(1))});
  const std::vector<char> a_shape = cells_with(apart, {{1, 0}});
  CHECK_FALSE(carry_by_sign_vectors(apart, a_shape, {0, 1}, overlap));
  CHECK(carry_by_sign_vectors(apart, a_shape, {0}, complex_of({disk("A", {q(-2), q(0)}, q(1))})));
  // Sizes that do not match.
  CHECK_THROWS_AS(carry_by_sign_vectors(both, disk_shape, {2}, alone), std::invalid_argument);
  CHECK_THROWS_AS(carry_by_sign_vectors(both, {1}, {0}, alone), std::invalid_argument);
  CHECK_THROWS_AS(carry_by_sign_vectors(both, disk_shape, {0, 1}, alone), std::invalid_argument);
}

TEST_CASE("minimise: check_scene is run_scene without the generator", "[campaign][minimise]") {
  CampaignSettings s;
  s.seed = 3;
  s.scene.min_halfspaces = 2;
  s.scene.max_halfspaces = 4;
  s.scene.max_samples = 5;
  for (std::uint64_t k = 0; k < 4; ++k) {
    SceneRecord a = run_scene(s, k);
    SceneRecord b = check_scene(s, random_scene(s.scene, s.seed, k).scene, k);
    CHECK(b.degeneracies.empty());
    b.degeneracies = a.degeneracies;
    CHECK(a == b);
  }
}

TEST_CASE("minimise: a check failing iff one halfspace is present keeps that halfspace alone", "[campaign][minimise]") {
  CampaignSettings s;
  s.seed = 5;
  s.scene.min_halfspaces = 5;
  s.scene.max_halfspaces = 5;
  s.scene.max_samples = 6;
  s.checks = {"existence"};
  const Scene2 scene = random_scene(s.scene, s.seed, 2).scene;
  REQUIRE(scene.halfspaces.size() == 5);
  const std::string target = scene.halfspaces[2].name;
  s.extra.push_back(has_halfspace(target));
  const SceneRecord record = check_scene(s, scene, 2);
  REQUIRE(record.failed());

  const MinimiseResult m = minimise_scene(s, scene, record);
  CHECK(m.reproduced);
  CHECK_FALSE(m.exhausted);
  CHECK(m.target == std::vector<std::string>{"has"});
  REQUIRE(m.scene.halfspaces.size() == 1);
  CHECK(m.scene.halfspaces[0].name == target);
  CHECK(m.scene.samples.empty());
  CHECK(m.removed_halfspaces == 4);
  CHECK(m.removed_samples == static_cast<int>(scene.samples.size()));
  CHECK(m.simplified_coordinates > 0);  // any valid change keeps "has" failing
  CHECK(m.record.failed());
  CHECK(m.record.checks.back().witness == "the halfspace " + target + " is there");
  // It still fails under the campaign's own settings, and reads back from its file.
  const Scene2 back = read_scene_text(write_scene2(m.scene).dump());
  CHECK(check_scene(s, back, 2).failed());
  // Deterministic: the same bytes again.
  const MinimiseResult again = minimise_scene(s, scene, record);
  CHECK(write_scene2(again.scene).dump() == write_scene2(m.scene).dump());
  CHECK(again.steps == m.steps);
  // The kept file's note.
  const std::optional<Scene2> kept = minimised_failure(record, m);
  REQUIRE(kept);
  CHECK(kept->description.find("scene 2 minimised (5 -> 1 halfspaces") != std::string::npos);
  CHECK(kept->description.find("failed has: the halfspace " + target + " is there") != std::string::npos);
  CHECK(kept->description.find('\n') == std::string::npos);

  SECTION("the step budget") {
    MinimiseOptions o;
    o.max_steps = 3;
    const MinimiseResult cut = minimise_scene(s, scene, record, o);
    CHECK(cut.exhausted);
    CHECK(cut.steps == 3);
    CHECK(cut.scene.halfspaces.size() > 1);
    CHECK(check_scene(s, cut.scene, 2).failed());
  }
  SECTION("a record that did not fail is refused") {
    SceneRecord held = record;
    for (CheckOutcome& c : held.checks) c.status = CheckStatus::Held;
    CHECK_THROWS_AS(minimise_scene(s, scene, held), std::invalid_argument);
  }
}

TEST_CASE("minimise: the Prop. 5.1 counterexample of campaign seed 1, scene 80", "[campaign][minimise]") {
  const Scene2 scene = read_scene_file(std::string(HSX_SOURCE_DIR) +
                                       "/data/counterexamples/prop51-campaign-seed1-scene80.json");
  CampaignSettings s;
  s.seed = 1;
  s.checks = {"prop51"};
  const SceneRecord record = check_scene(s, scene, 80);
  REQUIRE(record.failed());
  MinimiseOptions o;
  o.max_steps = 60;
  const MinimiseResult m = minimise_scene(s, scene, record, o);
  CHECK(m.reproduced);
  CHECK(m.scene.halfspaces.size() < scene.halfspaces.size());
  CHECK(m.scene.samples.size() <= scene.samples.size());
  CHECK(m.steps <= 60);
  const SceneRecord again = check_scene(s, read_scene_text(write_scene2(m.scene).dump()), 80);
  REQUIRE(again.checks.size() == 1);
  CHECK(again.checks[0].check == "prop51");
  CHECK(again.checks[0].status == CheckStatus::Failed);
  INFO(m.scene.halfspaces.size() << " halfspaces, " << m.scene.samples.size() << " samples, " << m.steps << " steps");
}

TEST_CASE("summary SVG: balanced, deterministic, and it follows the rates", "[campaign][svg]") {
  Summary a({"existence", "beam1"});
  SceneRecord r;
  r.halfspaces = 3;
  r.checks = {{"existence", CheckStatus::Held, "ok"}, {"beam1", CheckStatus::Held, "optimal: 1"}};
  a.add(r);
  r.halfspaces = 4;
  r.checks = {{"existence", CheckStatus::Failed, "no"}, {"beam1", CheckStatus::Held, "sub-optimal: 2"}};
  a.add(r);
  const std::string svg = summary_svg(a);
  CHECK(svg == summary_svg(a));
  CHECK(svg.rfind("<?xml", 0) == 0);
  // Every element opened is closed, in order (a minimal parse: no attribute holds '<' or '>').
  std::vector<std::string> open;
  const std::regex tag("<(/?)([a-zA-Z]+)[^>]*?(/?)>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), tag); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    if (m[3] == "/") continue;
    if (m[1] == "/") {
      REQUIRE_FALSE(open.empty());
      CHECK(open.back() == m[2].str());
      open.pop_back();
    } else {
      open.push_back(m[2]);
    }
  }
  CHECK(open.empty());
  const auto count = [&](const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
    return n;
  };
  CHECK(count(svg, "class=\"panel\"") == 3);  // existence, beam1, beam1 optimality
  CHECK(count(svg, "class=\"rate\"") == 6);   // two halfspace counts in each
  Summary b = a;
  r.checks = {{"existence", CheckStatus::Held, "ok"}, {"beam1", CheckStatus::Held, "optimal: 1"}};
  b.add(r);
  CHECK(summary_svg(b) != svg);
}

namespace {

/// The 3D campaign of proofs/campaigns.md (seed 1, 1..3 primitives, 6 segments, intended samples) with `checks`.
CampaignSettings campaign3(const std::string& checks) {
  CampaignSettings s;
  s.dimension = 3;
  s.seed = 1;
  s.scene3.solid.min_primitives = 1;
  s.scene3.solid.max_primitives = 3;
  s.scene3.solid.segments = 6;
  s.sample_policy = SamplePolicy::Intended;
  s.checks = parse_check_list(checks);
  return s;
}

/// The record of a 3D scene under `s` with the intended shape `cells` (cells of its complex).
SceneRecord record3(const CampaignSettings& s, const Scene3& scene, const std::vector<int>& cells,
                    std::uint64_t index) {
  Arranged3 arranged = arrange_campaign_scene3(scene, s.limits);
  std::vector<char> intended;
  if (!cells.empty()) {
    intended.assign(arranged.complex.cells.size(), 0);
    for (int c : cells) intended.at(static_cast<std::size_t>(c)) = 1;
  }
  return check_scene(s, scene, std::move(arranged), intended, index);
}

}  // namespace

TEST_CASE("minimise 3D: the manifold counterexample of seed 1, scene 543", "[campaign][minimise][campaign3]") {
  const Scene3 scene = read_scene3_file(std::string(HSX_SOURCE_DIR) +
                                        "/data/counterexamples/manifold3-campaign-seed1-scene543.json");
  const CampaignSettings s = campaign3("manifold");
  const SceneRecord record = record3(s, scene, {}, 543);
  REQUIRE(record.failed());
  const MinimiseResult3 m = minimise_scene(s, scene, record);
  CHECK(m.reproduced);
  CHECK_FALSE(m.exhausted);
  CHECK(m.scene.halfspaces.size() < scene.halfspaces.size());
  CHECK(m.lowered_segments > 0);
  CHECK(m.record.intended.empty());  // manifold does not look at the intended shape
  // It reads back from its file and fails the same way; the same bytes again.
  const std::string text = write_scene3(m.scene).dump();
  const SceneRecord again = record3(s, read_scene3_text(text), {}, 543);
  REQUIRE(again.checks.size() == 1);
  CHECK(again.checks[0].status == CheckStatus::Failed);
  CHECK(again.checks[0].witness.find("pinches at a point") != std::string::npos);
  CHECK(write_scene3(minimise_scene(s, scene, record).scene).dump() == text);
  const std::optional<Scene3> kept = minimised_failure(record, m);
  REQUIRE(kept);
  CHECK(kept->description.find("scene 543 minimised (3 -> ") != std::string::npos);
  CHECK(kept->description.find(" segment count") != std::string::npos);
  // A 2D campaign's settings are refused.
  CampaignSettings two = s;
  two.dimension = 2;
  CHECK_THROWS_AS(minimise_scene(two, scene, record), std::invalid_argument);
}

TEST_CASE("minimise 3D: a Prop. 6.1 failure keeps its intended shape (seed 1, scene 185)",
          "[campaign][minimise][campaign3]") {
  const CampaignSettings s = campaign3("prop61");
  const SceneRecord record = run_scene(s, 185);
  REQUIRE(record.failed());
  REQUIRE(record.scene3);
  REQUIRE_FALSE(record.intended.empty());
  REQUIRE(record.checks[0].witness.find("the target is not orientation-preserving") == 0);
  const MinimiseResult3 m = minimise_scene(s, *record.scene3, record);
  CHECK(m.reproduced);
  CHECK(m.scene.halfspaces.size() < record.scene3->halfspaces.size());
  REQUIRE_FALSE(m.record.intended.empty());  // the carried shape
  CHECK(m.record.checks.at(0).status == CheckStatus::Failed);
  // Checked again from its file with the carried shape (the note names its cells): the same failure.
  const SceneRecord again = record3(s, read_scene3_text(write_scene3(m.scene).dump()), m.record.intended, 185);
  CHECK(again.checks.at(0).status == CheckStatus::Failed);
  CHECK(again.checks.at(0).witness == m.record.checks.at(0).witness);
  // Without its intended shape the reduced scene does not fail: the shape is part of the failure.
  CHECK_FALSE(record3(s, m.scene, {}, 185).failed());
  const std::optional<Scene3> kept = minimised_failure(record, m);
  REQUIRE(kept);
  CHECK(kept->description.find("[the intended shape carried to it: cells {") != std::string::npos);
  CHECK(write_scene3(minimise_scene(s, *record.scene3, record).scene).dump() == write_scene3(m.scene).dump());
}
