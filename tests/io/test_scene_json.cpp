// Tests of io/exact_json and io/scene_json: exact numbers, the field reader, every class of bad input, limits and
// the write -> read round trip.
#include <hsx/io/exact_json.hpp>
#include <hsx/io/scene_json.hpp>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

using namespace hsx;
using nlohmann::json;

namespace {

Rational q(const char* text) {
  auto r = parse_rational(text);
  REQUIRE(r.has_value());
  return *r;
}

const char* kSpecExample = R"({
  "format": "hsx-scene/1",
  "dimension": 2,
  "domain": {"min": [-100, -100], "max": [100, 100]},
  "halfspaces": [
    {"name": "A", "kind": "disk", "center": [0, 0], "radius": "3/2"},
    {"name": "B", "kind": "halfplane", "normal": [0, 1], "offset": 1},
    {"name": "C", "kind": "polygon", "vertices": [[0, 0], [4, 0], [4, 3]]},
    {"name": "D", "kind": "disk", "center": [2, 0], "radius": 1, "complement": true}
  ],
  "samples": [
    {"on": "A", "at": ["-3/2", 0]},
    {"on": "B", "at": [5, 1]},
    {"on": "A", "near": [1.06, 1.06]}
  ]
})";

/// The error message of reading `text` as a scene ("" when it reads fine).
std::string scene_error(const std::string& text) {
  try {
    read_scene_text(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string doc_error(const json& doc) {
  try {
    read_scene2(doc);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string parse_error(const std::string& text, const JsonLimits& limits = {}) {
  try {
    parse_exact_json(text, limits);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// A minimal valid scene as a DOM, to be broken by the tests.
json base_scene() { return parse_exact_json(kSpecExample); }

bool same_scene(const Scene2& a, const Scene2& b) {
  if (a.description != b.description || a.domain_given != b.domain_given || a.domain.min != b.domain.min ||
      a.domain.max != b.domain.max || a.halfspaces.size() != b.halfspaces.size() ||
      a.samples.size() != b.samples.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.halfspaces.size(); ++i) {
    const Halfspace2 &h = a.halfspaces[i], &k = b.halfspaces[i];
    if (h.name != k.name || h.kind != k.kind || h.complement != k.complement) return false;
    switch (h.kind) {
      case HalfspaceKind2::Halfplane:
        if (h.normal != k.normal || h.offset != k.offset) return false;
        break;
      case HalfspaceKind2::Disk:
        if (h.center != k.center || h.radius != k.radius) return false;
        break;
      case HalfspaceKind2::Polygon:
        if (h.vertices != k.vertices) return false;
        break;
    }
  }
  for (std::size_t j = 0; j < a.samples.size(); ++j) {
    const Sample2 &s = a.samples[j], &t = b.samples[j];
    if (s.halfspace != t.halfspace || s.given != t.given || s.snapped != t.snapped ||
        !(s.location.x == t.location.x) || !(s.location.y == t.location.y)) {
      return false;
    }
  }
  return true;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------------
// exact_json

TEST_CASE("exact JSON keeps every number exact", "[json]") {
  json doc = parse_exact_json(R"({"a": 0.1, "b": 1e-3, "c": "-7/3", "d": 12, "e": -5, "f": 123456789012345678901234567890,
    "g": 1e400, "h": -0.0, "i": 2.5E+4, "j": 18446744073709551615, "k": -9223372036854775808, "l": "1e-3", "m": "0.1"})");
  CHECK(is_exact_number(doc["a"]));
  CHECK(doc["a"][kExactNumberKey] == "0.1");
  CHECK(json_rational(doc["a"]) == q("1/10"));
  CHECK(json_rational(doc["b"]) == q("1/1000"));
  CHECK(json_rational(doc["c"]) == q("-7/3"));
  CHECK(doc["d"].is_number_integer());
  CHECK(json_rational(doc["d"]) == 12);
  CHECK(json_rational(doc["e"]) == -5);
  CHECK(is_exact_number(doc["f"]));
  CHECK(json_rational(doc["f"]) == Rational(Integer("123456789012345678901234567890")));
  CHECK(json_rational(doc["g"]) == Rational(Integer("1" + std::string(400, '0'))));
  CHECK(json_rational(doc["h"]) == 0);
  CHECK(json_rational(doc["i"]) == 25000);
  CHECK(doc["j"].is_number_unsigned());  // fits uint64: stays an integer
  CHECK(json_rational(doc["j"]) == Rational(Integer("18446744073709551615")));
  CHECK(doc["k"].is_number_integer());
  CHECK(json_rational(doc["k"]) == Rational(Integer("-9223372036854775808")));
  CHECK(json_rational(doc["l"]) == q("1/1000"));
  CHECK(json_rational(doc["m"]) == q("1/10"));
}

TEST_CASE("exact JSON: numbers inside strings and arrays, positions unchanged", "[json]") {
  json doc = parse_exact_json("[\"1.5\", 1.5, \"x 2.5 \\\" 3.5\", [0.25, {\"k\": 7.75}]]");
  CHECK(doc[0] == "1.5");
  CHECK(is_exact_number(doc[1]));
  CHECK(doc[2] == "x 2.5 \" 3.5");
  CHECK(json_rational(doc[3][0]) == q("1/4"));
  CHECK(json_rational(doc[3][1]["k"]) == q("31/4"));
}

TEST_CASE("json_rational refuses non-numbers with a reason", "[json]") {
  std::string why;
  CHECK_FALSE(json_rational(json("abc"), &why));
  CHECK(why == "expected a number, got \"abc\"");
  CHECK_FALSE(json_rational(json(true), &why));
  CHECK(why == "expected a number, got true");
  CHECK_FALSE(json_rational(json::array({1, 2}), &why));
  CHECK(why == "expected a number, got an array");
  CHECK_FALSE(json_rational(json(nullptr), &why));
  CHECK(why == "expected a number, got null");
  CHECK_FALSE(json_rational(json("1/0"), &why));
  CHECK_THAT(why, Catch::StartsWith("expected a number, got \"1/0\" ("));
  CHECK_FALSE(json_rational(json(0.5), &why));  // a binary double from a plain nlohmann parse
  CHECK_THAT(why, Catch::Contains("binary floating-point"));
  CHECK_FALSE(json_rational(make_exact_number("1e99999999"), &why));
  CHECK_THAT(why, Catch::StartsWith("the number 1e99999999 is not accepted"));
}

TEST_CASE("rational_to_json writes integers as integers and fractions as strings", "[json]") {
  CHECK(rational_to_json(Rational(3)) == json(3));
  CHECK(rational_to_json(Rational(-3)) == json(-3));
  CHECK(rational_to_json(q("-7/3")) == json("-7/3"));
  CHECK(rational_to_json(q("0.1")) == json("1/10"));
  Rational big(Integer("1" + std::string(40, '0')));
  CHECK(rational_to_json(big) == json("1" + std::string(40, '0')));
  for (const char* t : {"0", "-7/3", "1/10", "123456789012345678901234567890/7"}) {
    CHECK(json_rational(rational_to_json(q(t))) == q(t));
  }
}

TEST_CASE("invalid JSON reports line and column", "[json][errors]") {
  CHECK_THAT(parse_error("{\n  \"a\": 1,\n  \"b\": tru\n}"), Catch::StartsWith("line 3, column "));
  std::string e = parse_error("{\"a\": [1, 2,, 3]}");
  CHECK_THAT(e, Catch::StartsWith("line 1, column 13: "));
  CHECK_THAT(e, Catch::Contains("unexpected ','"));
  CHECK_THAT(parse_error("[1, 2"), Catch::StartsWith("line 1, column "));
  CHECK_THAT(parse_error(""), Catch::StartsWith("line 1, column 1: "));
  CHECK_THAT(parse_error("{\"a\": 1.5.3}"), Catch::StartsWith("line 1, column "));
  CHECK_THAT(parse_error("[01]"), Catch::StartsWith("line 1, column "));
  CHECK_THAT(parse_error("[-]"), Catch::StartsWith("line 1, column "));
  CHECK_THAT(parse_error("[1.]"), Catch::StartsWith("line 1, column "));
  CHECK_THAT(parse_error("[NaN]"), Catch::StartsWith("line 1, column "));
  CHECK_THAT(parse_error("[1] x"), Catch::StartsWith("line 1, column "));
  CHECK_THAT(parse_error("\n\n   @"), Catch::StartsWith("line 3, column 4: "));
}

TEST_CASE("duplicate and reserved keys are refused", "[json][errors]") {
  CHECK(parse_error(R"({"halfspaces": [{"name": "A", "name": "B"}]})") ==
        "halfspaces[0]: duplicate key \"name\"");
  CHECK(parse_error(R"({"a": 1, "a": 2})") == "document: duplicate key \"a\"");
  CHECK(parse_error(R"({"r": {"$exact": "1/3"}})") == "r: the key \"$exact\" is reserved");
}

TEST_CASE("nesting depth and input size are limited", "[json][limits]") {
  auto nested = [](int depth) { return std::string(depth, '[') + std::string(depth, ']'); };
  CHECK(parse_error(nested(64)).empty());
  CHECK_THAT(parse_error(nested(65)), Catch::Contains("line 1, column 65: nesting deeper than 64 levels"));
  auto start = std::chrono::steady_clock::now();
  CHECK_THAT(parse_error(nested(1000000)), Catch::Contains("nesting deeper than 64 levels"));
  CHECK_THAT(parse_error(std::string(1000000, '[')), Catch::Contains("nesting deeper than 64 levels"));
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 5.0);
  JsonLimits small;
  small.max_bytes = 10;
  CHECK(parse_error("[1, 2, 3, 4, 5]", small) == "input is 15 bytes; the limit is 10");
  small.max_depth = 2;
  small.max_bytes = 1000;
  CHECK_THAT(parse_error("{\"a\": [[1]]}", small), Catch::Contains("line 1, column 8: nesting deeper than 2 levels"));
}

TEST_CASE("the field reader names the JSON path", "[json]") {
  json doc = parse_exact_json(R"({"halfspaces": [{}, {}, {"radius": "abc", "p": [1], "b": 1, "odd key": {"x": 1}}]})");
  JsonField root(doc, "");
  JsonField h = root.at("halfspaces").at(2);
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(message([&] { h.at("radius").rational(); }) == "halfspaces[2].radius: expected a number, got \"abc\"");
  CHECK(message([&] { h.at("center"); }) == "halfspaces[2]: missing field \"center\"");
  CHECK(message([&] { h.at("p").point2(); }) ==
        "halfspaces[2].p: expected a point [x, y] with 2 coordinates, got 1");
  CHECK(message([&] { h.at("b").boolean(); }) == "halfspaces[2].b: expected true or false, got 1");
  CHECK(message([&] { h.at("b").string(); }) == "halfspaces[2].b: expected a string, got 1");
  CHECK(message([&] { h.at("odd key").at("x").string(); }) ==
        "halfspaces[2][\"odd key\"].x: expected a string, got 1");
  CHECK(message([&] { h.check_keys({"radius", "p", "b"}); }) ==
        "halfspaces[2]: unknown field \"odd key\" (expected one of: radius, p, b)");
  CHECK(message([&] { root.at("halfspaces").string(); }) == "halfspaces: expected a string, got an array");
  CHECK(message([&] { root.at("halfspaces").at(0).size(); }) == "halfspaces[0]: expected an array, got an object");
  CHECK(message([&] { JsonField(json(3), "").expect_object(); }) == "document: expected an object, got 3");
  CHECK(h.at("b").integer() == 1);
  CHECK_FALSE(h.get("nothing").has_value());
}

// ---------------------------------------------------------------------------------------------------------------
// scene_json: reading

TEST_CASE("the spec example reads exactly", "[scene_json]") {
  Scene2 s = read_scene_text(kSpecExample);
  REQUIRE(s.halfspaces.size() == 4);
  CHECK(s.domain_given);
  CHECK(s.domain.min == PointQ2{-100, -100});
  CHECK(s.halfspaces[0].kind == HalfspaceKind2::Disk);
  CHECK(s.halfspaces[0].radius == q("3/2"));
  CHECK(s.halfspaces[1].kind == HalfspaceKind2::Halfplane);
  CHECK(s.halfspaces[1].normal == PointQ2{0, 1});
  CHECK(s.halfspaces[2].vertices.size() == 3);
  CHECK(s.halfspaces[3].complement);
  CHECK_FALSE(s.halfspaces[0].complement);
  REQUIRE(s.samples.size() == 3);
  CHECK(s.samples[0].given == PointQ2{q("-3/2"), 0});
  CHECK(s.samples[0].location.x == OneRoot(q("-3/2")));
  CHECK(s.samples[2].snapped);
  CHECK(s.samples[2].given == PointQ2{q("1.06"), q("1.06")});
  CHECK(s.samples[2].given.x == q("53/50"));  // read from the text, not a double
  CHECK(std::abs(s.samples[2].location.x.to_double() - 1.0606601717798212) < 1e-12);
}

TEST_CASE("description and exact number spellings", "[scene_json]") {
  Scene2 s = read_scene_text(R"({"format": "hsx-scene/1", "dimension": 2, "description": "two disks",
    "halfspaces": [{"name": "A", "kind": "disk", "center": [0.1, "1e-3"], "radius": 2.5E-1},
                   {"name": "B", "kind": "disk", "center": ["-7/3", 0], "radius": "+1"}]})");
  CHECK(s.description == "two disks");
  CHECK(s.halfspaces[0].center == PointQ2{q("1/10"), q("1/1000")});
  CHECK(s.halfspaces[0].radius == q("1/4"));
  CHECK(s.halfspaces[1].center.x == q("-7/3"));
  CHECK_FALSE(s.domain_given);
  CHECK(s.domain.min.x < q("-7/3") - 1);
}

TEST_CASE("every class of bad input is refused with a message naming the field", "[scene_json][errors]") {
  SECTION("missing fields") {
    json d = base_scene();
    d.erase("format");
    CHECK(doc_error(d) == "document: missing field \"format\" (expected \"hsx-scene/1\")");
    d = base_scene();
    d.erase("dimension");
    CHECK(doc_error(d) == "document: missing field \"dimension\"");
    d = base_scene();
    d.erase("halfspaces");
    CHECK(doc_error(d) == "document: missing field \"halfspaces\"");
    d = base_scene();
    d["halfspaces"][0].erase("radius");
    CHECK(doc_error(d) == "halfspaces[0]: missing field \"radius\"");
    d = base_scene();
    d["halfspaces"][1].erase("name");
    CHECK(doc_error(d) == "halfspaces[1]: missing field \"name\"");
    d = base_scene();
    d["halfspaces"][1].erase("kind");
    CHECK(doc_error(d) == "halfspaces[1]: missing field \"kind\"");
    d = base_scene();
    d["samples"][1].erase("at");
    CHECK(doc_error(d) == "samples[1]: missing field \"at\" or \"near\"");
    d = base_scene();
    d["samples"][1].erase("on");
    CHECK(doc_error(d) == "samples[1]: missing field \"on\"");
    d = base_scene();
    d["domain"].erase("max");
    CHECK(doc_error(d) == "domain: missing field \"max\"");
  }
  SECTION("unknown fields") {
    json d = base_scene();
    d["color"] = "red";
    CHECK_THAT(doc_error(d), Catch::StartsWith("document: unknown field \"color\" (expected one of: format, "));
    d = base_scene();
    d["halfspaces"][2]["color"] = "red";
    CHECK(doc_error(d) == "halfspaces[2]: unknown field \"color\" for a polygon (expected one of: name, kind, "
                            "complement, vertices)");
    d = base_scene();
    d["halfspaces"][1]["radius"] = 1;
    CHECK_THAT(doc_error(d), Catch::StartsWith("halfspaces[1]: unknown field \"radius\" for a halfplane"));
    d = base_scene();
    d["samples"][0]["weight"] = 1;
    CHECK_THAT(doc_error(d), Catch::StartsWith("samples[0]: unknown field \"weight\""));
    d = base_scene();
    d["domain"]["center"] = json::array({0, 0});
    CHECK_THAT(doc_error(d), Catch::StartsWith("domain: unknown field \"center\""));
    d = base_scene();
    d["halfspaces"][0]["kind"] = "circle";
    CHECK(doc_error(d) == "halfspaces[0].kind: unknown kind \"circle\" (expected halfplane, disk or polygon)");
    d["halfspaces"][0]["kind"] = "sphere";
    CHECK_THAT(doc_error(d), Catch::StartsWith("halfspaces[0].kind: kind \"sphere\" is a 3D kind"));
  }
  SECTION("wrong types") {
    json d = base_scene();
    d["halfspaces"][0]["radius"] = "abc";
    CHECK(doc_error(d) == "halfspaces[0].radius: expected a number, got \"abc\"");
    d["halfspaces"][0]["radius"] = true;
    CHECK(doc_error(d) == "halfspaces[0].radius: expected a number, got true");
    d = base_scene();
    d["halfspaces"][0]["name"] = 3;
    CHECK(doc_error(d) == "halfspaces[0].name: expected a string, got 3");
    d = base_scene();
    d["halfspaces"][3]["complement"] = "yes";
    CHECK(doc_error(d) == "halfspaces[3].complement: expected true or false, got \"yes\"");
    d = base_scene();
    d["halfspaces"][0]["center"] = json::array({1});
    CHECK(doc_error(d) == "halfspaces[0].center: expected a point [x, y] with 2 coordinates, got 1");
    d = base_scene();
    d["halfspaces"][2]["vertices"] = "triangle";
    CHECK(doc_error(d) == "halfspaces[2].vertices: expected an array, got \"triangle\"");
    d = base_scene();
    d["halfspaces"][2]["vertices"][1][0] = json::object();
    CHECK(doc_error(d) == "halfspaces[2].vertices[1][0]: expected a number, got an object");
    d = base_scene();
    d["samples"] = json::object();
    CHECK(doc_error(d) == "samples: expected an array, got an object");
    d = base_scene();
    d["dimension"] = "2";
    CHECK(doc_error(d) == "dimension: expected 2 or 3, got \"2\"");
    d = base_scene();
    d["format"] = "hsx-scene/2";
    CHECK(doc_error(d) == "format: expected \"hsx-scene/1\", got \"hsx-scene/2\"");
    d = base_scene();
    d["description"] = 5;
    CHECK(doc_error(d) == "description: expected a string, got 5");
    CHECK(doc_error(json::array()) == "document: expected an object, got an array");
  }
  SECTION("3D is not supported yet") {
    json d = base_scene();
    d["dimension"] = 3;
    CHECK(doc_error(d) == "dimension: 3D scenes are not supported yet");
    d["dimension"] = 4;
    CHECK(doc_error(d) == "dimension: expected 2 or 3, got 4");
  }
  SECTION("duplicate names") {
    json d = base_scene();
    d["halfspaces"][3]["name"] = "A";
    CHECK(doc_error(d) == "halfspaces[3].name: duplicate name \"A\" (also halfspaces[0])");
    d["halfspaces"][3]["name"] = "";
    CHECK(doc_error(d) == "halfspaces[3].name: the name must not be empty");
  }
  SECTION("zero or negative radius, zero normal") {
    json d = base_scene();
    d["halfspaces"][0]["radius"] = 0;
    CHECK(doc_error(d) == "halfspaces[0].radius: the radius must be positive, got 0");
    d["halfspaces"][0]["radius"] = "-1/2";
    CHECK(doc_error(d) == "halfspaces[0].radius: the radius must be positive, got \"-1/2\"");
    d = base_scene();
    d["halfspaces"][1]["normal"] = json::array({0, "0/5"});
    CHECK(doc_error(d) == "halfspaces[1].normal: the normal must not be zero");
  }
  SECTION("degenerate or self-intersecting polygon") {
    json d = base_scene();
    d["halfspaces"][2]["vertices"] = json::array({json::array({0, 0}), json::array({1, 1}), json::array({2, 2})});
    CHECK(doc_error(d) == "halfspaces[2] (\"C\"): polygon is degenerate: all its vertices are collinear");
    d["halfspaces"][2]["vertices"] = json::array({json::array({0, 0}), json::array({1, 1})});
    CHECK(doc_error(d) == "halfspaces[2] (\"C\"): polygon needs at least 3 vertices, got 2");
    d["halfspaces"][2]["vertices"] =
        json::array({json::array({0, 0}), json::array({2, 2}), json::array({2, 0}), json::array({0, 2})});
    CHECK(doc_error(d) == "halfspaces[2] (\"C\"): polygon is self-intersecting: edges 0 and 2 cross at [1, 1]");
  }
  SECTION("samples on unknown halfspaces or off their boundary") {
    json d = base_scene();
    d["samples"][1]["on"] = "Z";
    CHECK(doc_error(d) == "samples[1].on: unknown halfspace \"Z\"");
    d = base_scene();
    d["samples"][1]["near"] = json::array({5, 1});
    CHECK(doc_error(d) == "samples[1]: give exactly one of \"at\" and \"near\", not both");
    d = base_scene();
    d["samples"][0]["at"] = json::array({2, 0});
    CHECK(doc_error(d) == "samples[0] (on \"A\"): point [2, 0] is not on the boundary of \"A\" (about 0.5 away)");
    d = base_scene();
    d["samples"][1]["at"] = json::array({5, "1.25"});
    CHECK(doc_error(d) ==
          "samples[1] (on \"B\"): point [5, 5/4] is not on the boundary of \"B\" (about 0.25 away)");
    d = base_scene();
    d["samples"][2]["near"] = json::array({0, 0});
    CHECK_THAT(doc_error(d), Catch::StartsWith("samples[2] (on \"A\"): point [0, 0] is the center of \"A\""));
  }
  SECTION("empty scene") {
    json d = base_scene();
    d["halfspaces"] = json::array();
    d.erase("samples");
    CHECK(doc_error(d) == "halfspaces: the scene has no halfspace (at least one is needed)");
  }
  SECTION("a domain that does not contain the geometry") {
    json d = base_scene();
    d["domain"]["max"] = json::array({3, 100});
    CHECK_THAT(doc_error(d), Catch::StartsWith("halfspaces[2] (\"C\"): vertex 1 [4, 0] is outside the domain"));
    d["domain"]["max"] = json::array({100, 1});
    CHECK_THAT(doc_error(d), Catch::StartsWith("halfspaces[0] (\"A\"): the disk is not inside the domain"));
    d["domain"]["max"] = json::array({-200, 100});
    CHECK(doc_error(d) == "domain: min must be below max in both coordinates");
    d = base_scene();
    d["samples"][1]["at"] = json::array({500, 1});
    CHECK_THAT(doc_error(d), Catch::StartsWith("samples[1] (on \"B\"): point [500, 1] is outside the domain"));
  }
  SECTION("invalid JSON and deep nesting") {
    CHECK_THAT(scene_error(std::string("{\"format\": \"hsx-scene/1\",\n \"dimension\": 2,\n \"halfspaces\": [}")),
               Catch::StartsWith("line 3, column 17: "));
    std::string deep = "{\"format\": \"hsx-scene/1\", \"dimension\": 2, \"halfspaces\": " + std::string(100, '[') +
                       std::string(100, ']') + "}";
    CHECK_THAT(scene_error(deep), Catch::Contains("nesting deeper than 64 levels"));
  }
}

TEST_CASE("10,000-digit numbers work; longer ones fail cleanly", "[scene_json][limits]") {
  std::string digits(10000, '7');
  auto start = std::chrono::steady_clock::now();
  Scene2 s = read_scene_text("{\"format\": \"hsx-scene/1\", \"dimension\": 2, \"halfspaces\": [{\"name\": \"A\", "
                             "\"kind\": \"disk\", \"center\": [" + digits + ", \"1/" + digits + "\"], \"radius\": 0." +
                             digits + "}, {\"name\": \"P\", \"kind\": \"polygon\", \"vertices\": [[0, 0], [" + digits +
                             ", 1], [1, " + digits + "]]}], \"samples\": [{\"on\": \"A\", \"near\": [0, 0]}]}");
  CHECK(s.halfspaces[0].center.x == Rational(Integer(digits)));
  CHECK(s.halfspaces[0].center.y == make_rational(1, Integer(digits)));
  CHECK(s.domain.max.x > Rational(Integer(digits)));
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 5.0);

  std::string huge(30000, '9');
  std::string e = scene_error("{\"format\": \"hsx-scene/1\", \"dimension\": 2, \"halfspaces\": [{\"name\": \"A\", "
                              "\"kind\": \"disk\", \"center\": [0, 0], \"radius\": " + huge + "}]}");
  CHECK_THAT(e, Catch::StartsWith("halfspaces[0].radius: the number 9999"));
  CHECK(e.size() < 300);
  e = scene_error(R"({"format": "hsx-scene/1", "dimension": 2, "halfspaces": [{"name": "A", "kind": "disk",
                  "center": [0, 0], "radius": 1e999999999}]})");
  CHECK_THAT(e, Catch::StartsWith("halfspaces[0].radius: the number 1e999999999 is not accepted"));
}

TEST_CASE("10,000 halfspaces read quickly", "[scene_json][limits]") {
  json doc = json::object();
  doc["format"] = "hsx-scene/1";
  doc["dimension"] = 2;
  json hs = json::array();
  json samples = json::array();
  for (int i = 0; i < 10000; ++i) {
    std::string name = "h" + std::to_string(i);
    if (i % 3 == 0) {
      hs.push_back({{"name", name}, {"kind", "halfplane"}, {"normal", {i % 7 + 1, i % 5 - 2}}, {"offset", i % 11}});
    } else if (i % 3 == 1) {
      hs.push_back({{"name", name}, {"kind", "disk"}, {"center", {i % 100, i % 37}}, {"radius", "1/3"}});
      samples.push_back({{"on", name}, {"near", {i % 100 + 1, i % 37}}});
    } else {
      hs.push_back({{"name", name}, {"kind", "polygon"}, {"vertices", {{i, 0}, {i + 1, 0}, {i, 1}}}});
      samples.push_back({{"on", name}, {"at", {i, "1/2"}}});
    }
  }
  doc["halfspaces"] = hs;
  doc["samples"] = samples;
  std::string text = doc.dump();
  auto start = std::chrono::steady_clock::now();
  Scene2 s = read_scene_text(text);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(s.halfspaces.size() == 10000);
  CHECK(s.samples.size() > 6000);
  CHECK(seconds < 10.0);
  SceneReadLimits limits;
  limits.max_halfspaces = 5000;
  try {
    read_scene_text(text, limits);
    FAIL("expected an error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "halfspaces: too many halfspaces (10000; the limit is 5000)");
  }
}

TEST_CASE("scene files: errors carry the path", "[scene_json]") {
  char name[] = "/tmp/hsx-scene-test-XXXXXX";
  int fd = mkstemp(name);
  REQUIRE(fd >= 0);
  close(fd);
  const std::string path = name;
  {
    std::ofstream out(path);
    out << kSpecExample;
  }
  CHECK(read_scene_file(path).halfspaces.size() == 4);
  {
    std::ofstream out(path);
    out << "{\"format\": \"hsx-scene/1\",\n\"dimension\": 2, \"halfspaces\": [{\"name\": \"A\", \"kind\": \"disk\", "
           "\"center\": [0, 0], \"radius\": \"r\"}]}";
  }
  try {
    read_scene_file(path);
    FAIL("expected an error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == path + ": halfspaces[0].radius: expected a number, got \"r\"");
  }
  {
    std::ofstream out(path);
    out << "{\n  \"format\": \"hsx-scene/1\"\n  \"dimension\": 2}";
  }
  try {
    read_scene_file(path);
    FAIL("expected an error");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::StartsWith(path + ": line 3, column 3: "));
  }
  std::remove(path.c_str());
  try {
    read_scene_file(path);
    FAIL("expected an error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "cannot read \"" + path + "\": No such file or directory");
  }
  try {
    read_scene_file("/tmp");
    FAIL("expected an error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "cannot read \"/tmp\": it is a directory");
  }
}

// ---------------------------------------------------------------------------------------------------------------
// scene_json: writing

TEST_CASE("write -> read round trip", "[scene_json]") {
  Scene2 s = read_scene_text(kSpecExample);
  json out = write_scene2(s);
  CHECK(out["halfspaces"][0]["radius"] == "3/2");
  CHECK(out["halfspaces"][1]["offset"] == 1);
  CHECK(out["samples"][2]["near"][0] == "53/50");
  CHECK(out["halfspaces"][3]["complement"] == true);
  CHECK_FALSE(out["halfspaces"][0].contains("complement"));
  CHECK(same_scene(read_scene2(out), s));
  CHECK(same_scene(read_scene_text(out.dump(2)), s));

  // a chosen domain is not written, and is chosen again identically
  Scene2 t = read_scene_text(R"({"format": "hsx-scene/1", "dimension": 2, "description": "d",
    "halfspaces": [{"name": "A", "kind": "disk", "center": [0.5, 0], "radius": "1/3"}]})");
  json w = write_scene2(t);
  CHECK_FALSE(w.contains("domain"));
  CHECK(w["description"] == "d");
  CHECK(same_scene(read_scene_text(w.dump()), t));
}

TEST_CASE("write -> read round trip (property)", "[scene_json][property]") {
  rc::prop("random scenes", [](std::vector<std::tuple<int, int, int, unsigned, bool>> raw, bool with_domain) {
    RC_PRE(!raw.empty());
    Scene2 s;
    s.description = with_domain ? "with domain" : "";
    for (std::size_t i = 0; i < raw.size() && i < 30; ++i) {
      auto [a, b, c, d, complement] = raw[i];
      Halfspace2 h;
      h.name = "h" + std::to_string(i);
      h.complement = complement;
      Sample2 smp;
      smp.halfspace = static_cast<int>(i);
      smp.snapped = true;
      switch (d % 3) {
        case 0:
          h.kind = HalfspaceKind2::Halfplane;
          h.normal = PointQ2{Rational(a % 9), Rational(b % 9 == 0 && a % 9 == 0 ? 1 : b % 9)};
          h.offset = make_rational(c % 1000, 7);
          smp.given = PointQ2{make_rational(a % 20, 3), make_rational(b % 20, 11)};
          break;
        case 1:
          h.kind = HalfspaceKind2::Disk;
          h.center = PointQ2{make_rational(a % 100, 3), Rational(b % 100)};
          h.radius = make_rational(d % 50 + 1, 4);
          smp.given = PointQ2{h.center.x + make_rational(std::abs(c % 7), 5) + 1, h.center.y};
          break;
        default: {
          h.kind = HalfspaceKind2::Polygon;
          Rational x0 = make_rational(a % 100, 9), y0 = Rational(b % 100);
          Rational w = make_rational(d % 40 + 1, 3);
          h.vertices = {PointQ2{x0, y0}, PointQ2{x0 + w, y0}, PointQ2{x0 + w, y0 + w}, PointQ2{x0, y0 + 2 * w}};
          smp.given = PointQ2{x0 + make_rational(c % 10, 10) * w, y0 - 1};
          smp.snapped = c % 2 == 0;
          if (!smp.snapped) smp.given = PointQ2{x0 + make_rational(std::abs(c % 10), 10) * w, y0};
          break;
        }
      }
      s.halfspaces.push_back(h);
      s.samples.push_back(smp);
    }
    if (with_domain) {
      s.domain_given = true;
      s.domain = Box2{PointQ2{-1000, -1000}, PointQ2{1000, 1000}};
    }
    validate_and_resolve(s);
    Scene2 back = read_scene_text(write_scene2(s).dump());
    RC_ASSERT(same_scene(back, s));
  });
}
