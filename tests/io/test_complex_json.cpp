#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/complex_json.hpp>
#include <hsx/io/exact_json.hpp>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <string>
#include <vector>

using namespace hsx;
using nlohmann::json;

namespace {

Rational q(const char* text) { return *parse_rational(text); }

Halfspace2 disk(const std::string& name, const char* cx, const char* cy, const char* r, bool complement = false) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Disk;
  h.center = PointQ2{q(cx), q(cy)};
  h.radius = q(r);
  h.complement = complement;
  return h;
}

Halfspace2 halfplane(const std::string& name, const char* nx, const char* ny, const char* offset) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Halfplane;
  h.normal = PointQ2{q(nx), q(ny)};
  h.offset = q(offset);
  return h;
}

Halfspace2 polygon(const std::string& name, const std::vector<std::pair<const char*, const char*>>& points,
                   bool complement = false) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Polygon;
  for (const auto& [x, y] : points) h.vertices.push_back(PointQ2{q(x), q(y)});
  h.complement = complement;
  return h;
}

Sample2 at(int halfspace, const char* x, const char* y) {
  Sample2 s;
  s.halfspace = halfspace;
  s.given = PointQ2{q(x), q(y)};
  return s;
}

Sample2 near(int halfspace, const char* x, const char* y) {
  Sample2 s = at(halfspace, x, y);
  s.snapped = true;
  return s;
}

void set_domain(Scene2& s, const char* lo, const char* hi) {
  s.domain = Box2{PointQ2{q(lo), q(lo)}, PointQ2{q(hi), q(hi)}};
  s.domain_given = true;
}

/// Disks (one complemented), a half-plane, a polygon, a half-plane along a polygon edge (a support group), and
/// samples, one of them snapped to an irrational point.
Scene2 curved_scene() {
  Scene2 s;
  set_domain(s, "-10", "10");
  s.halfspaces = {disk("A", "0", "0", "2"), halfplane("B", "0", "1", "1"),
                  polygon("C", {{"1", "-1"}, {"4", "-1"}, {"4", "2"}, {"1", "2"}}),
                  halfplane("E", "-1", "0", "-1"), disk("D", "5", "5", "3/2", true)};
  s.samples = {at(0, "-2", "0"), at(1, "-5", "1"), at(2, "4", "0"), near(0, "1", "-1"), at(4, "5", "13/2")};
  validate_and_resolve(s);
  return s;
}

/// Straight boundaries only: every measure is algebraic.
Scene2 straight_scene() {
  Scene2 s;
  set_domain(s, "-8", "8");
  s.halfspaces = {polygon("T", {{"0", "0"}, {"4", "0"}, {"1", "3"}}), halfplane("H", "1", "1", "2"),
                  polygon("Q", {{"-3", "-3"}, {"-3", "2"}, {"2", "-3"}}, true)};
  s.samples = {at(0, "3", "0"), at(1, "-1", "3"), at(2, "-3", "0")};
  validate_and_resolve(s);
  return s;
}

void require_equal(const Complex& a, const Complex& b) {
  REQUIRE(a.dimension == b.dimension);
  REQUIRE(a.halfspace_names == b.halfspace_names);
  REQUIRE(a.cells.size() == b.cells.size());
  for (std::size_t k = 0; k < a.cells.size(); ++k) {
    INFO("cell " << k);
    REQUIRE(a.cells[k].outer == b.cells[k].outer);
    REQUIRE(a.cells[k].witness.get() == b.cells[k].witness.get());
    REQUIRE(a.cells[k].inside == b.cells[k].inside);
    REQUIRE(compare(a.cells[k].measure, b.cells[k].measure) == Order::Equal);
  }
  REQUIRE(a.patches.size() == b.patches.size());
  for (std::size_t p = 0; p < a.patches.size(); ++p) {
    INFO("patch " << p);
    const Patch& x = a.patches[p];
    const Patch& y = b.patches[p];
    REQUIRE(x.halfspace == y.halfspace);
    REQUIRE(x.inside_cell == y.inside_cell);
    REQUIRE(x.outside_cell == y.outside_cell);
    REQUIRE(compare(x.measure, y.measure) == Order::Equal);
    REQUIRE(x.samples == y.samples);
    REQUIRE(x.support == y.support);
    REQUIRE(x.junctions == y.junctions);
    REQUIRE(x.pieces == y.pieces);
  }
  REQUIRE(a.supports == b.supports);
  REQUIRE(a.junctions.size() == b.junctions.size());
  for (std::size_t j = 0; j < a.junctions.size(); ++j) {
    REQUIRE(a.junctions[j].patches == b.junctions[j].patches);
    REQUIRE(a.junctions[j].piece == b.junctions[j].piece);
  }
  REQUIRE(a.samples.size() == b.samples.size());
  for (std::size_t s = 0; s < a.samples.size(); ++s) {
    REQUIRE(a.samples[s].halfspace == b.samples[s].halfspace);
    REQUIRE(a.samples[s].patch == b.samples[s].patch);
  }
}

/// The InputError message of importing `doc` ("" when it is accepted).
std::string import_error(const json& doc) {
  try {
    (void)complex_from_json(doc);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kHandWritten = R"json({
  "format": "hsx-complex/1",
  "dimension": 2,
  "halfspaces": ["A", "B"],
  "cells": [
    {"outer": true, "inside": [], "measure": {"exact": "100 - 3/2 - sqrt(2)"}},
    {"outer": false, "inside": ["A"], "witness": ["1/2", 0], "measure": {"decimal": "1.5"}},
    {"outer": false, "inside": ["A", "B"], "measure": "sqrt(2)"}
  ],
  "patches": [
    {"halfspace": "A", "inside_cell": 1, "outside_cell": 0, "measure": {"exact": "1", "decimal": "1.0"}},
    {"halfspace": "B", "inside_cell": 2, "outside_cell": 1,
     "measure": {"exact": "sqrt(2)", "decimal": "1.41421356237309504880168872421"}}
  ],
  "samples": [{"halfspace": "B", "patch": 1}, {"halfspace": "A", "patch": 0}, {"halfspace": "B", "patch": 1}]
})json";

}  // namespace

TEST_CASE("parse_one_root reads the kernel's spellings", "[io][complex_json]") {
  auto v = [](const char* text) {
    std::string why;
    auto r = parse_one_root(text, &why);
    INFO(text << ": " << why);
    REQUIRE(r);
    return *r;
  };
  CHECK(compare(v("3/2"), OneRoot(Rational(3, 2))) == 0);
  CHECK(compare(v("1 + 2*sqrt(5)"), OneRoot(1, 2, 5)) == 0);
  CHECK(compare(v("1 - 2*sqrt(5)"), OneRoot(1, -2, 5)) == 0);
  CHECK(compare(v("-1/2*sqrt(3)"), OneRoot(0, Rational(-1, 2), 3)) == 0);
  CHECK(compare(v("sqrt(2)"), OneRoot(0, 1, 2)) == 0);
  CHECK(compare(v("-sqrt(2)"), OneRoot(0, -1, 2)) == 0);
  CHECK(compare(v(" 0.5+1e-1*sqrt( 7 ) "), OneRoot(Rational(1, 2), Rational(1, 10), 7)) == 0);
  for (const char* bad : {"", "1 +", "sqrt(2) + sqrt(3)", "sqrt(-1)", "x", "1 + 2*sqrt(5", "2*sqrt(sqrt(2))",
                          "1 2", "--", "1/0", "sqrt()"}) {
    INFO(bad);
    CHECK_FALSE(parse_one_root(bad));
  }
}

TEST_CASE("parse_one_root inverts OneRoot::exact_string", "[io][complex_json]") {
  rc::prop("round trip", [] {
    const Rational a0(*rc::gen::inRange(-50, 50), *rc::gen::inRange(1, 9));
    const Rational a1(*rc::gen::inRange(-50, 50), *rc::gen::inRange(1, 9));
    const Rational root(*rc::gen::inRange(0, 40), *rc::gen::inRange(1, 5));
    const OneRoot x(make_rational(a0.get_num(), a0.get_den()), make_rational(a1.get_num(), a1.get_den()),
                    make_rational(root.get_num(), root.get_den()));
    auto back = parse_one_root(x.exact_string());
    RC_ASSERT(back.has_value());
    RC_ASSERT(compare(*back, x) == 0);
  });
}

TEST_CASE("parse_closed_form reads sums of square roots", "[io][complex_json]") {
  auto m = parse_closed_form("1/2 + 3*sqrt(2) - sqrt(5) + 2*sqrt(8)");
  REQUIRE(m);
  const Measure expected = Measure(Rational(1, 2)) + Measure::sqrt_of(2) * Rational(7) - Measure::sqrt_of(5);
  CHECK(compare(*m, expected) == Order::Equal);
  CHECK(compare(*parse_closed_form("-sqrt(1/4)"), Measure(Rational(-1, 2))) == Order::Equal);
  std::string why;
  CHECK_FALSE(parse_closed_form("sqrt(5 + 2*sqrt(6))", &why));
  CHECK_THAT(why, Catch::Contains("nested"));
  // pi terms (the exact areas and lengths of arcs whose angles are multiples of pi/12)
  CHECK(compare(*parse_closed_form("4/3*pi + 1/2*sqrt(3)"), Measure::pi(Rational(4, 3)) + Measure::sqrt_of(Rational(3, 4))) ==
        Order::Equal);
  CHECK(compare(*parse_closed_form("-pi + 1"), Measure(Rational(1)) - Measure::pi()) == Order::Equal);
  for (const char* bad : {"", "+", "1 + + 2 +", "pie", "2*pi*sqrt(2)", "sqrt(pi)", "1e99999999", "sqrt(-2)",
                          "2**sqrt(2)", "(1)"}) {
    INFO(bad);
    CHECK_FALSE(parse_closed_form(bad));
  }
  CHECK_FALSE(parse_closed_form(std::string(300000, '1')));
}

TEST_CASE("complex JSON round trip with geometry", "[io][complex_json]") {
  const Scene2 scene = curved_scene();
  const Arranged2 arranged = arrange(scene);
  const json doc = complex_to_json(arranged.complex, &arranged.arrangement, &scene.domain);
  const std::string text = doc.dump(1);
  CHECK(text == complex_to_json(arranged.complex, &arranged.arrangement, &scene.domain).dump(1));
  CHECK(doc["format"] == "hsx-complex/1");
  CHECK(doc["counts"]["cells"] == arranged.complex.cells.size());
  CHECK(doc["geometry"]["edges"].size() == arranged.arrangement.edges().size());
  bool has_support_group = false;
  for (const auto& g : arranged.complex.supports) has_support_group = has_support_group || g.size() > 1;
  CHECK(has_support_group);

  const ComplexDocument back = complex_document_from_json(parse_exact_json(text));
  require_equal(arranged.complex, back.complex);
  REQUIRE(back.has_geometry);
  REQUIRE(back.domain);
  CHECK(back.domain->min == scene.domain.min);
  REQUIRE(back.edges.size() == arranged.arrangement.edges().size());
  for (std::size_t e = 0; e < back.edges.size(); ++e)
    CHECK(compare(back.edge_lengths[e], arranged.arrangement.edge_lengths()->get(e)) == Order::Equal);
  // Export of the import gives the same bytes.
  CHECK(complex_to_json(back.complex, nullptr, nullptr).dump() ==
        complex_to_json(arranged.complex, nullptr, nullptr).dump());
}

TEST_CASE("complex JSON round trip without geometry (algebraic measures)", "[io][complex_json]") {
  const Scene2 scene = straight_scene();
  const Arranged2 arranged = arrange(scene);
  const json doc = complex_to_json(arranged.complex, nullptr, nullptr);
  CHECK_FALSE(doc.contains("geometry"));
  CHECK_FALSE(doc["counts"].contains("vertices"));
  const Complex back = complex_from_json(parse_exact_json(doc.dump()));
  require_equal(arranged.complex, back);
  // Also with geometry.
  require_equal(arranged.complex,
                complex_from_json(complex_to_json(arranged.complex, &arranged.arrangement, &scene.domain)));
}

TEST_CASE("a hand-written complex without geometry", "[io][complex_json]") {
  const Complex c = complex_from_json(parse_exact_json(kHandWritten));
  REQUIRE(c.cells.size() == 3);
  REQUIRE(c.patches.size() == 2);
  CHECK(c.outer_cell_count() == 1);
  CHECK(c.cells[1].inside == std::vector<char>{1, 0});
  CHECK(c.cells[1].witness.get() == std::vector<Rational>{Rational(1, 2), Rational(0)});
  CHECK(c.cells[0].witness.get().empty());
  CHECK(compare(c.cells[1].measure, Measure(Rational(3, 2))) == Order::Equal);
  CHECK(compare(c.cells[2].measure, Measure::sqrt_of(2)) == Order::Equal);
  CHECK(compare(c.patches[0].measure, Measure(1)) == Order::Equal);
  CHECK(compare(c.patches[1].measure, Measure::sqrt_of(2)) == Order::Equal);
  CHECK(c.patches[1].samples == std::vector<int>{0, 2});
  CHECK(c.patches[0].samples == std::vector<int>{1});
  CHECK(c.supports == std::vector<std::vector<int>>{{0}, {1}});
  CHECK(c.patches[1].support == 1);
  CHECK(c.junctions.empty());
  CHECK(check_complex(c).empty());
  // A decimal is taken as exactly that decimal.
  json doc = parse_exact_json(kHandWritten);
  doc["patches"][0]["measure"] = json{{"decimal", "0.1"}};
  CHECK(compare(complex_from_json(doc).patches[0].measure, Measure(Rational(1, 10))) == Order::Equal);
  doc["patches"][0]["measure"] = parse_exact_json(R"({"decimal": 0.1, "exact": null})");
  CHECK(compare(complex_from_json(doc).patches[0].measure, Measure(Rational(1, 10))) == Order::Equal);
}

TEST_CASE("junctions and supports are read and cross-checked", "[io][complex_json]") {
  // Two half-planes crossing: 4 cells, 4 patches meeting at one junction.
  const char* text = R"json({
    "format": "hsx-complex/1", "dimension": 2, "halfspaces": ["X", "Y"],
    "cells": [
      {"outer": true, "inside": [], "measure": 1}, {"outer": true, "inside": ["X"], "measure": 1},
      {"outer": true, "inside": ["X", "Y"], "measure": 1}, {"outer": true, "inside": ["Y"], "measure": 1}],
    "patches": [
      {"halfspace": "X", "inside_cell": 1, "outside_cell": 0, "measure": 1, "junctions": [0]},
      {"halfspace": "Y", "inside_cell": 2, "outside_cell": 1, "measure": 1},
      {"halfspace": "X", "inside_cell": 2, "outside_cell": 3, "measure": 1},
      {"halfspace": "Y", "inside_cell": 3, "outside_cell": 0, "measure": 1}],
    "supports": [[0], [1], [2], [3]],
    "junctions": [{"id": 0, "patches": [3, 2, 1, 0], "vertex": 7}]
  })json";
  const Complex c = complex_from_json(parse_exact_json(text));
  CHECK(c.junctions[0].patches == std::vector<int>{0, 1, 2, 3});
  CHECK(c.junctions[0].piece == 7);
  CHECK(c.patches[1].junctions == std::vector<int>{0});
  CHECK(c.patch_neighbours()[0] == std::vector<int>{1, 2, 3});

  json doc = parse_exact_json(text);
  doc["junctions"][0]["patches"] = json::array({1, 2, 3});
  CHECK_THAT(import_error(doc), Catch::StartsWith("patches[0].junctions") && Catch::Contains("does not list"));
  doc["supports"] = json::array({json::array({0}), json::array({2}), json::array({3})});
  CHECK_THAT(import_error(doc), Catch::StartsWith("supports: patch 1 is in no support group"));
  doc["supports"] = json::array({json::array({0}), json::array({1}), json::array({2}), json::array({3, 2})});
  CHECK_THAT(import_error(doc), Catch::StartsWith("supports[3]: patch 2 is already"));
  doc["supports"] = json::array({json::array({0, 2}), json::array({1}), json::array({3})});
  CHECK_THAT(import_error(doc), Catch::StartsWith("supports[0]: two of its patches lie on halfspace \"X\""));
  doc["supports"] = json::array({json::array({0, 1}), json::array({2}), json::array({3})});
  CHECK_THAT(import_error(doc), Catch::StartsWith("supports[0]: patches 0 and 1 separate different cells"));
  doc = parse_exact_json(text);
  doc["patches"][2]["support"] = 1;
  CHECK_THAT(import_error(doc), Catch::StartsWith("patches[2].support: is 1"));
}

TEST_CASE("bad complexes are rejected with the JSON path", "[io][complex_json]") {
  const json good = parse_exact_json(kHandWritten);
  REQUIRE(import_error(good).empty());
  struct Case {
    std::string pointer;
    json value;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"/patches/1/inside_cell", 0, "patches[1].inside_cell: cell 0 is not inside halfspace \"B\""},
      {"/patches/1/inside_cell", 99, "patches[1].inside_cell: cell 99 is out of range"},
      {"/patches/1/inside_cell", -1, "patches[1].inside_cell: cell -1 is out of range"},
      {"/patches/1/inside_cell", make_exact_number("1e30"), "patches[1].inside_cell: expected an integer"},
      {"/patches/1/inside_cell", json(18446744073709551615ULL), "patches[1].inside_cell: integer"},
      {"/patches/1/inside_cell", "2", "patches[1].inside_cell: expected an integer"},
      {"/patches/1/outside_cell", 2, "patches[1].outside_cell: is the same cell"},
      {"/patches/0/outside_cell", 2, "patches[0].outside_cell: cell 2 is inside halfspace \"A\""},
      {"/patches/0/halfspace", "Z", "patches[0].halfspace: unknown halfspace \"Z\""},
      {"/patches/0/halfspace", 0, "patches[0].halfspace: expected a string"},
      {"/patches/0/colour", "red", "patches[0]: unknown field \"colour\""},
      {"/patches/0/measure", json{{"decimal", "-1"}}, "patches[0].measure: a patch's length must be positive"},
      {"/patches/0/measure", json{{"exact", "0"}}, "patches[0].measure: a patch's length must be positive"},
      {"/patches/0/measure", json{{"exact", "1 - sqrt(2)"}}, "patches[0].measure: a patch's length must be positive"},
      {"/cells/1/measure", json{{"decimal", "-1.5"}}, "cells[1].measure: a cell's area must be positive"},
      {"/patches/0/id", -1, "patches[0].id: is -1"},
      {"/patches/0/sample_ids", json::array({0}), "patches[0].sample_ids: lists sample 0, which sits on patch 1"},
      {"/patches/0/sample_ids", json::array(), "patches[0].sample_ids: does not list sample 1"},
      {"/patches/0/sample_ids", json::array({1, 1}), "patches[0].sample_ids: lists sample 1 twice"},
      {"/patches/0/sample_ids", json::array({7}), "patches[0].sample_ids[0]: sample 7 is out of range"},
      {"/patches/0/samples", 2, "patches[0].samples: is 2 but 1 samples"},
      {"/patches/0/junctions", json::array({0}), "patches[0].junctions[0]: junction 0 is out of range"},
      {"/patches/0/support", 1, "patches[0].support: is 1"},
      {"/patches/0/measure", json::object(), "patches[0].measure: needs \"exact\" or \"decimal\""},
      {"/patches/0/measure", json::array(), "patches[0].measure: expected a measure"},
      {"/patches/0/measure/exact", "sqrt(sqrt(2))", "patches[0].measure.exact: not an accepted closed form"},
      {"/patches/0/measure/exact", "1 +", "patches[0].measure.exact: not an accepted closed form"},
      {"/patches/0/measure/decimal", "1.1", "patches[0].measure.decimal: does not agree"},
      {"/patches/0/measure/decimal", "1/1", "patches[0].measure.decimal: expected a decimal number"},
      {"/patches", json::object(), "patches: expected an array"},
      {"/patches/1", 3, "patches[1]: expected an object"},
      {"/cells/0/inside", json::array({"A", "A"}), "cells[0].inside[1]: halfspace listed twice"},
      {"/cells/0/inside", "A", "cells[0].inside: expected an array"},
      {"/cells/1/witness", json::array({1}), "cells[1].witness: expected 2 coordinates"},
      {"/cells/1/witness/0", "x", "cells[1].witness[0]: expected a number"},
      {"/cells/2/outer", 1, "cells[2].outer: expected true or false"},
      {"/samples/0/patch", 5, "samples[0].patch: patch 5 is out of range"},
      {"/samples/0/halfspace", "A", "samples[0].halfspace: is \"A\" but patch 1 lies on halfspace \"B\""},
      {"/halfspaces/1", "A", "halfspaces[1]: duplicate halfspace name"},
      {"/halfspaces/1", "", "halfspaces[1]: the name must not be empty"},
      {"/halfspaces/1", "A\u001b[2J", "halfspaces[1]: the name \"A\\u001b[2J\" has a control character"},
      {"/format", "hsx-complex/2", "format: expected \"hsx-complex/1\""},
      {"/dimension", 4, "dimension: expected 2 or 3"},
      {"/counts", json{{"cells", 4}}, "counts.cells: is 4 but the document has 3"},
      {"/counts", json{{"edges", 4}}, "counts.edges: given, but the document has no geometry"},
      {"/cells/0/inside", json::array({"B"}), "the complex is inconsistent: patch 0: its cells differ in halfspace 1"},
      {"/junctions", json::array({json{{"patches", json::array({0, 5})}}}), "junctions[0].patches[1]: patch 5"},
      {"/domain", json{{"min", json::array({1, 1})}, {"max", json::array({0, 2})}}, "domain: min must be below"},
      {"/geometry", json{{"vertices", json::array()}, {"edges", json::array()}, {"faces", json::array()}},
       "geometry.faces: has 0 faces but there are 3 cells"},
  };
  for (const Case& c : cases) {
    json doc = good;
    doc[json::json_pointer(c.pointer)] = c.value;
    INFO(c.pointer << " = " << c.value.dump());
    CHECK_THAT(import_error(doc), Catch::StartsWith(c.expected));
  }
  json doc = good;
  doc.erase("patches");
  CHECK_THAT(import_error(doc), Catch::StartsWith("document: missing field \"patches\""));
  doc = good;
  doc["cells"][0].erase("measure");
  CHECK_THAT(import_error(doc), Catch::StartsWith("cells[0]: missing field \"measure\""));
  CHECK_THAT(import_error(json::array()), Catch::StartsWith("document: expected an object"));
}

TEST_CASE("measures are recomputed from the geometry and checked", "[io][complex_json]") {
  const Scene2 scene = curved_scene();
  const Arranged2 arranged = arrange(scene);
  const json good = complex_to_json(arranged.complex, &arranged.arrangement, &scene.domain);
  REQUIRE(import_error(good).empty());
  // Find a straight patch (algebraic length) and a curved one (exact null, or a closed form with pi).
  int straight = -1, curved = -1;
  for (std::size_t p = 0; p < good["patches"].size(); ++p) {
    const json& exact = good["patches"][p]["measure"]["exact"];
    if (exact.is_null() || exact.get<std::string>().find("pi") != std::string::npos) {
      if (curved < 0) curved = static_cast<int>(p);
    } else if (straight < 0) {
      straight = static_cast<int>(p);
    }
  }
  REQUIRE(straight >= 0);
  REQUIRE(curved >= 0);
  const std::string sp = "patches[" + std::to_string(straight) + "]";
  const std::string cp = "patches[" + std::to_string(curved) + "]";

  json doc = good;
  doc["patches"][straight]["measure"]["exact"] = "7";
  CHECK_THAT(import_error(doc), Catch::StartsWith(sp + ".measure.exact: differs from the length recomputed"));
  doc = good;
  doc["patches"][straight]["measure"]["exact"] = "sqrt(7 + sqrt(2))";
  CHECK_THAT(import_error(doc), Catch::StartsWith(sp + ".measure.exact: differs"));
  doc = good;
  doc["patches"][curved]["measure"]["decimal"] = "1.5";
  CHECK_THAT(import_error(doc), Catch::StartsWith(cp + ".measure.decimal: differs"));
  doc = good;
  doc["patches"][curved]["measure"]["exact"] = "1";
  CHECK_THAT(import_error(doc), Catch::StartsWith(cp + ".measure.exact: differs"));
  // A decimal with fewer digits is fine when it agrees to its last digit (at least 6 significant digits).
  doc = good;
  const std::string decimal = good["patches"][curved]["measure"]["decimal"];
  doc["patches"][curved]["measure"]["decimal"] = decimal.substr(0, 9);
  CHECK(import_error(doc).empty());
  // Measures may be left out: they are recomputed.
  doc = good;
  for (auto& p : doc["patches"]) p.erase("measure");
  for (auto& c : doc["cells"]) c.erase("measure");
  require_equal(arranged.complex, complex_from_json(doc));
  // A cell area.
  doc = good;
  doc["cells"][0]["measure"]["decimal"] = "3";
  CHECK_THAT(import_error(doc), Catch::StartsWith("cells[0].measure.decimal: differs from the area recomputed"));

  // Geometry errors.
  auto edge_index_of_shape = [&](const char* shape) {
    for (std::size_t e = 0; e < good["geometry"]["edges"].size(); ++e)
      if (good["geometry"]["edges"][e]["shape"] == shape) return static_cast<int>(e);
    return -1;
  };
  const int arc = edge_index_of_shape("arc");
  REQUIRE(arc >= 0);
  const std::string ap = "geometry.edges[" + std::to_string(arc) + "]";
  doc = good;
  doc["geometry"]["edges"][arc]["radius"] = "3";
  CHECK_THAT(import_error(doc), Catch::StartsWith(ap + ".source: the vertex does not lie on the arc's circle"));
  doc = good;
  doc["geometry"]["edges"][arc]["radius"] = "-2";
  CHECK_THAT(import_error(doc), Catch::StartsWith(ap + ".radius: must be positive"));
  doc = good;
  doc["geometry"]["edges"][arc]["shape"] = "segment";
  CHECK_THAT(import_error(doc), Catch::StartsWith(ap + ": unknown field"));
  doc = good;
  doc["geometry"]["edges"][0]["source"] = 100000;
  CHECK_THAT(import_error(doc), Catch::StartsWith("geometry.edges[0].source: vertex 100000 is out of range"));
  doc = good;
  doc["geometry"]["vertices"][0]["point"][0] = "1 + sqrt(2) + sqrt(3)";
  CHECK_THAT(import_error(doc), Catch::StartsWith("geometry.vertices[0].point[0]: expected an exact number"));
  doc = good;
  doc["geometry"]["vertices"][0]["degree"] = 17;
  CHECK_THAT(import_error(doc), Catch::StartsWith("geometry.vertices[0].degree: is 17"));
  doc = good;
  doc["geometry"]["faces"][0]["boundary"][0][0][1] = !doc["geometry"]["faces"][0]["boundary"][0][0][1].get<bool>();
  CHECK_THAT(import_error(doc), Catch::StartsWith("geometry.faces[0].boundary[0][0]: edge"));
  doc = good;
  doc["patches"][straight].erase("pieces");
  CHECK_THAT(import_error(doc), Catch::StartsWith(sp + ": needs \"pieces\""));
  doc = good;
  doc["patches"][straight]["pieces"].push_back(doc["patches"][straight]["pieces"][0]);
  CHECK_THAT(import_error(doc), Catch::StartsWith(sp + ".pieces: lists edge"));
  doc = good;
  doc["junctions"][0]["vertex"] = 123456;
  CHECK_THAT(import_error(doc), Catch::StartsWith("junctions[0].vertex: vertex 123456 is out of range"));
}

TEST_CASE("oversized documents are refused quickly", "[io][complex_json]") {
  json doc = parse_exact_json(kHandWritten);
  json big = doc;
  for (int i = 0; i < 20000; ++i) big["halfspaces"].push_back("h" + std::to_string(i));
  for (int i = 0; i < 20000; ++i) big["cells"].push_back(json{{"outer", true}, {"inside", json::array()}, {"measure", 1}});
  CHECK_THAT(import_error(big), Catch::StartsWith("document: too large"));
  std::string sum = "1";
  for (int i = 1; i < 4096; ++i) sum += " + 1";
  big = doc;
  for (int i = 0; i < 12; ++i) big["cells"].push_back(json{{"outer", true}, {"inside", json::array()}, {"measure", sum}});
  CHECK_THAT(import_error(big), Catch::Contains("work limit"));
  sum += " + 1";
  doc["cells"][0]["measure"] = sum;
  CHECK_THAT(import_error(doc), Catch::StartsWith("cells[0].measure: not an accepted closed form (more than 4096 terms)"));
}

TEST_CASE("importing mutated documents never crashes", "[io][complex_json]") {
  const Scene2 scene = curved_scene();
  const Arranged2 arranged = arrange(scene);
  const json with_geometry = complex_to_json(arranged.complex, &arranged.arrangement, &scene.domain);
  const json without = complex_to_json(arrange(straight_scene()).complex, nullptr, nullptr);
  const std::vector<json> junk = {json(-1), json(0), json(1), json(3), json(1000000), make_exact_number("1e30"),
                                  json(9223372036854775807LL), json(18446744073709551615ULL), json("x"),
                                  json("1/0"), json("sqrt(2)"), json(nullptr), json(true), json::array(),
                                  json::object(), json::array({0, 1}), json(0.5)};
  for (const json* base : {&with_geometry, &without}) {
    const json flat = base->flatten();
    std::vector<std::string> pointers;
    for (const auto& item : flat.items()) pointers.push_back(item.key());
    const std::string name = std::string("mutations give a complex or an InputError, ") +
                             (base == &with_geometry ? "with geometry" : "without geometry");
    rc::prop(name, [&] {
      json doc = *base;
      const int mutations = *rc::gen::inRange(1, 3);
      for (int k = 0; k < mutations; ++k) {
        std::string pointer = *rc::gen::elementOf(pointers);
        if (*rc::gen::inRange(0, 4) == 0) pointer = pointer.substr(0, pointer.rfind('/'));  // a whole container
        const json value = *rc::gen::elementOf(junk);
        try {
          doc[json::json_pointer(pointer)] = value;
        } catch (const json::exception&) {  // an earlier mutation replaced a container by a scalar
        }
      }
      try {
        const Complex c = complex_from_json(doc);
        RC_ASSERT(check_complex(c).empty());
      } catch (const InputError&) {
      }
    });
  }
}

TEST_CASE("complex_json_text writes complex_to_json(...).dump(2) byte for byte", "[io][complex_json]") {
  for (const Scene2& scene : {curved_scene(), straight_scene()}) {
    const Arranged2 arranged = arrange(scene);
    CHECK(complex_json_text(arranged.complex, &arranged.arrangement, &scene.domain) ==
          complex_to_json(arranged.complex, &arranged.arrangement, &scene.domain).dump(2) + "\n");
    CHECK(complex_json_text(arranged.complex, nullptr, nullptr) ==
          complex_to_json(arranged.complex, nullptr, nullptr).dump(2) + "\n");
  }
  // A halfspace whose name looks like the cells key cannot confuse where the cells go.
  Scene2 scene = straight_scene();
  scene.halfspaces.front().name = "\n  \"cells\": []";
  const Arranged2 arranged = arrange(scene);
  CHECK(complex_json_text(arranged.complex, &arranged.arrangement, &scene.domain) ==
        complex_to_json(arranged.complex, &arranged.arrangement, &scene.domain).dump(2) + "\n");
}
