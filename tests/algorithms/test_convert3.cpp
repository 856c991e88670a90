// 3D solids to BSH scenes (algorithms/csg/convert.hpp, issue 14 section 2): the orientation rule on the 3D complex,
// GENERATE-SAMPLES, exact `at` samples, and the round trip, checked here independently of convert's own check
// (through the JSON text, arranged from scratch, extracted, compared by point location).
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/algorithms/csg/convert.hpp>
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/algorithms/csg/separators3.hpp>
#include <hsx/io/csg_text.hpp>
#include <hsx/io/scene_json.hpp>
#include "support/random_expressions.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <string>
#include <vector>

using namespace hsx;

namespace {

Scene3 scene3(const std::string& name) {
  return read_scene3_file(std::string(HSX_SOURCE_DIR) + "/data/scenes3d/" + name);
}

std::vector<std::string> names_of(const Scene3& s) {
  std::vector<std::string> names;
  for (const auto& h : s.halfspaces) names.push_back(h.name);
  return names;
}

std::vector<char> solid_of(const Scene3& s, const Arranged3& a, const std::string& text) {
  return csg::evaluate(*parse_csg_text(text, names_of(s)), a.complex);
}

/// Independently of convert: the written scene through its JSON text, arranged from scratch, extracted with
/// `method`, and carried onto the cells of `on`.
std::vector<char> extracted_from_file(const Scene3& written, const Arranged3& on,
                                      bsh::Method method = bsh::Method::Beam) {
  const Scene3 back = read_scene3_text(write_scene3(written).dump(), std::string(HSX_SOURCE_DIR) + "/data/scenes3d");
  const Arranged3 again = arrange(back);
  bsh::ExtractOptions eo;
  eo.method = method;
  eo.enumerate_ties = false;
  return csg::carry_solid3(again, bsh::extract(bsh::Problem(again.complex), eo).labelling, on);
}

bool all_at_samples(const Scene3& s) {
  for (const Sample3& x : s.samples)
    if (x.snapped || !(x.location == x.given)) return false;
  return true;
}

}  // namespace

TEST_CASE("convert 3D: union, difference (complemented) and both ways (complemented copies) round-trip",
          "[csg][convert3]") {
  const Scene3 s = scene3("split_box.json");
  const Arranged3 a = arrange(s);
  struct Case {
    std::string text;
    std::size_t samples;
    std::vector<std::string> flipped;
  };
  for (const Case& c : {Case{"B | C", 3, {}}, Case{"B - C", 4, {"C"}},
                        Case{"(B - C) | (C - B)", 6, {"B~ (a complemented copy of B)", "C~ (a complemented copy of C)"}}}) {
    INFO(c.text);
    const std::vector<char> solid = solid_of(s, a, c.text);
    const csg::ConversionReport3 r = csg::convert_to_bsh(s, a, solid, bsh::Method::Beam);
    REQUIRE(r.ok());
    CHECK(r.failure.empty());
    CHECK(r.flipped == c.flipped);
    CHECK(r.samples.sample_patches.size() == c.samples);
    CHECK(r.scene.samples.size() == c.samples);
    CHECK(r.scene.domain_given);
    CHECK(all_at_samples(r.scene));
    CHECK(r.scene.halfspaces.size() == s.halfspaces.size() + (c.flipped.size() == 2 ? 2 : 0));
    // The oriented solid is the input solid (the same volume, carried over by point location).
    CHECK(csg::carry_solid3(a, solid, r.oriented) == r.oriented_solid);
    CHECK(extracted_from_file(r.scene, r.oriented) == r.oriented_solid);
  }
  const csg::OrientedScene3 minus = csg::orient_for_bsh(s, a.complex, solid_of(s, a, "B - C"));
  REQUIRE(minus.scene.halfspaces.size() == 2);
  CHECK_FALSE(minus.scene.halfspaces[0].complement);
  CHECK(minus.scene.halfspaces[1].complement);
}

TEST_CASE("convert 3D: the CAD part (complemented box, tori, cylinder, planes) round-trips with 9 samples",
          "[csg][convert3]") {
  const Scene3 s = scene3("cad_part.json");
  const Arranged3 a = arrange(s);
  const std::vector<char> solid = solid_of(s, a, "Cyl & Top & Bottom & Slab & Notch | Ring1 | Ring2");
  const csg::ConversionReport3 r = csg::convert_to_bsh(s, a, solid, bsh::Method::Beam);
  REQUIRE(r.ok());
  CHECK(r.flipped.empty());
  CHECK(r.samples.sample_patches.size() == 9);
  CHECK(r.samples.initial == 9);
  CHECK(r.samples.upper_bound == 15);
  CHECK(extracted_from_file(r.scene, r.oriented) == r.oriented_solid);
}

TEST_CASE("convert 3D: extracts_back sees a scene that does not give the solid back; bad input refused",
          "[csg][convert3]") {
  const Scene3 s = scene3("split_box.json");
  const Arranged3 a = arrange(s);
  const csg::ConversionReport3 r = csg::convert_to_bsh(s, a, solid_of(s, a, "B | C"), bsh::Method::Beam);
  REQUIRE(r.ok());
  CHECK(csg::extracts_back(r.scene, r.oriented, r.oriented_solid, bsh::Method::Beam));
  CHECK_FALSE(csg::extracts_back(r.scene, r.oriented, solid_of(s, a, "B"), bsh::Method::Beam));
  Scene3 fewer = r.scene;
  fewer.samples.pop_back();  // one sample short: B | C minus one of its patches' cells, or another shape
  CHECK_FALSE(csg::extracts_back(fewer, r.oriented, r.oriented_solid, bsh::Method::Beam));
  CHECK_THROWS_AS(csg::convert_to_bsh(s, a, solid_of(s, a, "~B"), bsh::Method::Beam), InputError);
  CHECK_THROWS_AS(csg::convert_to_bsh(s, a, std::vector<char>(2, 1), bsh::Method::Beam), std::invalid_argument);
}

TEST_CASE("convert 3D: random CSG solids on coincident boxes and a plane round-trip through the file format",
          "[csg][convert3]") {
  // boxes_coincident.json: coincident faces (support groups of several halfspaces) and samples of its own, which
  // the conversion drops.
  const Scene3 s = scene3("boxes_coincident.json");
  const Arranged3 a = arrange(s);
  int converted = 0;
  rc::prop("extract(read(write(convert(solid)))) == solid, by point location", [&] {
    const csg::ExprPtr e = test::random_expr(static_cast<int>(s.halfspaces.size()), 3, false);
    const std::vector<char> solid = csg::evaluate(*e, a.complex);
    bool bounded = true, empty = true;
    for (std::size_t k = 0; k < solid.size(); ++k) {
      bounded &= !(solid[k] && a.complex.cells[k].outer);
      empty &= !solid[k];
    }
    RC_PRE(bounded && !empty);
    const csg::ConversionReport3 r = csg::convert_to_bsh(s, a, solid, bsh::Method::BestFirst);
    RC_ASSERT(r.ok());
    RC_ASSERT(all_at_samples(r.scene));
    RC_ASSERT(csg::carry_solid3(a, solid, r.oriented) == r.oriented_solid);
    RC_ASSERT(extracted_from_file(r.scene, r.oriented, bsh::Method::BestFirst) == r.oriented_solid);
    ++converted;
  });
  INFO("solids converted: " << converted);
  CHECK(converted >= 20);
}
