// hsx-complex/1 of dimension 3: the geometry section's checks and recomputed measures, on documents written by
// hand (two unit cubes side by side, split by the plane x = 1).
#include <hsx/io/complex_json.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <functional>
#include <string>

using namespace hsx;
using nlohmann::json;

namespace {

/// Vertex id of grid point (x, y, z), x in 0..2, y and z in 0..1.
int vid(int x, int y, int z) { return x * 4 + y * 2 + z; }

json triangle(int a, int b, int c, std::vector<std::string> halfspaces, std::vector<bool> front_inside, bool on_box,
              int front, int back) {
  return json{{"vertices", {a, b, c}}, {"halfspaces", halfspaces}, {"front_inside", front_inside},
              {"on_box", on_box}, {"front_cell", front}, {"back_cell", back}};
}

/// The quad a b c d (counter-clockwise seen from the front) as two triangles.
void quad(json& out, std::array<int, 4> v, std::vector<std::string> hs, std::vector<bool> fi, bool on_box, int front,
          int back) {
  out.push_back(triangle(v[0], v[1], v[2], hs, fi, on_box, front, back));
  out.push_back(triangle(v[0], v[2], v[3], hs, fi, on_box, front, back));
}

/// Domain [0,2]x[0,1]x[0,1]; halfspace P = {x <= 1}; cell 0 is x < 1 (inside P), cell 1 is x > 1.
json two_cubes() {
  json vertices = json::array();
  for (int x = 0; x <= 2; ++x)
    for (int y = 0; y <= 1; ++y)
      for (int z = 0; z <= 1; ++z) vertices.push_back({x, y, z});
  json t = json::array();
  for (int c = 0; c < 2; ++c) {
    const int x0 = c, x1 = c + 1;
    // outward normals point out of the domain: the cell is at the back, the outside (-1) at the front
    quad(t, {vid(x0, 0, 0), vid(x1, 0, 0), vid(x1, 0, 1), vid(x0, 0, 1)}, {}, {}, true, -1, c);  // y = 0, normal -y
    quad(t, {vid(x0, 1, 0), vid(x0, 1, 1), vid(x1, 1, 1), vid(x1, 1, 0)}, {}, {}, true, -1, c);  // y = 1, normal +y
    quad(t, {vid(x0, 0, 0), vid(x0, 1, 0), vid(x1, 1, 0), vid(x1, 0, 0)}, {}, {}, true, -1, c);  // z = 0, normal -z
    quad(t, {vid(x0, 0, 1), vid(x1, 0, 1), vid(x1, 1, 1), vid(x0, 1, 1)}, {}, {}, true, -1, c);  // z = 1, normal +z
  }
  quad(t, {vid(0, 0, 0), vid(0, 0, 1), vid(0, 1, 1), vid(0, 1, 0)}, {}, {}, true, -1, 0);  // x = 0, normal -x
  quad(t, {vid(2, 0, 0), vid(2, 1, 0), vid(2, 1, 1), vid(2, 0, 1)}, {}, {}, true, -1, 1);  // x = 2, normal +x
  // the plane x = 1, front normal +x towards cell 1; P's inside (x <= 1) is at the back
  quad(t, {vid(1, 0, 0), vid(1, 1, 0), vid(1, 1, 1), vid(1, 0, 1)}, {"P"}, {false}, false, 1, 0);
  const int patch_first = static_cast<int>(t.size()) - 2;
  json doc = {{"format", "hsx-complex/1"},
              {"dimension", 3},
              {"halfspaces", {"P"}},
              {"domain", {{"min", {0, 0, 0}}, {"max", {2, 1, 1}}}},
              {"counts", {{"vertices", 12}, {"triangles", t.size()}, {"cells", 2}, {"patches", 1}}},
              {"cells",
               {{{"outer", true}, {"witness", {"1/2", "1/2", "1/2"}}, {"inside", {"P"}}, {"measure", "1"}},
                {{"outer", true}, {"witness", {"3/2", "1/2", "1/2"}}, {"inside", json::array()}, {"measure", 1}}}},
              {"patches",
               {{{"halfspace", "P"}, {"inside_cell", 0}, {"outside_cell", 1}, {"measure", {{"exact", "1"}}},
                 {"pieces", {patch_first, patch_first + 1}}}}},
              {"geometry", {{"vertices", vertices}, {"triangles", t}}}};
  return doc;
}

std::string error_of(const json& doc) {
  try {
    complex_document_from_json(doc);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a 3D complex document with geometry: volumes and areas recomputed exactly", "[io][complex_json][3d]") {
  const ComplexDocument doc = complex_document_from_json(two_cubes());
  REQUIRE(doc.complex.dimension == 3);
  REQUIRE(doc.has_geometry);
  REQUIRE(doc.domain3);
  CHECK(doc.domain3->max.x == 2);
  REQUIRE(doc.complex.cells.size() == 2);
  CHECK(doc.complex.cells[0].measure.get().rational_value() == Rational(1));
  CHECK(doc.complex.cells[1].measure.get().rational_value() == Rational(1));
  REQUIRE(doc.complex.patches.size() == 1);
  CHECK(doc.complex.patches[0].measure.get().rational_value() == Rational(1));
  CHECK(doc.triangles3.size() == 22);
  CHECK(doc.vertices3.size() == 12);
}

TEST_CASE("a 3D complex document round-trips through complex3_to_json without geometry", "[io][complex_json][3d]") {
  const ComplexDocument doc = complex_document_from_json(two_cubes());
  const json written = complex3_to_json(doc.complex, nullptr, &*doc.domain3);
  CHECK(written.at("dimension") == 3);
  CHECK(written.at("domain").at("max") == json({"2", "1", "1"}));
  const ComplexDocument back = complex_document_from_json(written);
  CHECK(complex3_to_json(back.complex, nullptr, &*back.domain3) == written);
  CHECK(complex3_json_text(doc.complex, nullptr, &*doc.domain3) == written.dump(2) + "\n");
}

TEST_CASE("a 3D complex document's geometry is checked", "[io][complex_json][3d]") {
  using Edit = std::function<void(json&)>;
  const std::vector<std::pair<Edit, std::string>> cases = {
      {[](json& d) { d["cells"][0]["measure"] = "2"; }, "differs from the volume recomputed"},
      {[](json& d) { d["patches"][0]["measure"] = {{"decimal", "1.5"}}; }, "differs from the area recomputed"},
      {[](json& d) { d["geometry"]["triangles"].erase(0); }, "is not closed"},
      {[](json& d) { d["geometry"]["triangles"][20]["front_inside"] = {true}; }, "is on the inside of \"P\" here"},
      {[](json& d) { d["geometry"]["triangles"][0]["vertices"] = {0, 4, 8}; }, "collinear"},
      {[](json& d) { d["geometry"]["triangles"][0]["vertices"] = {0, 0, 8}; }, "repeats a vertex"},
      {[](json& d) { d["geometry"]["triangles"][20]["on_box"] = true; d["geometry"]["triangles"][20]["front_cell"] = 0; },
       "same cell on both sides"},
      {[](json& d) { d["geometry"]["triangles"][3]["on_box"] = false; }, "not on the box"},
      {[](json& d) { d["patches"][0]["pieces"] = {0, 21}; }, "triangle 0 is not on the boundary of halfspace \"P\""},
      {[](json& d) { d["patches"][0]["pieces"] = {21, 21}; }, "lists triangle 21 twice"},
      {[](json& d) { d["patches"][0]["pieces"] = {21, 99}; }, "triangle 99 is out of range"},
      {[](json& d) { d["domain"] = {{"min", {0, 0}}, {"max", {2, 1}}}; }, "expected a point [x, y, z]"},
      {[](json& d) { d["domain"]["max"] = {2, 0, 1}; }, "min must be below max in all three coordinates"},
      {[](json& d) { d["counts"]["triangles"] = 3; }, "counts.triangles: is 3 but the document has 22"},
      {[](json& d) { d["counts"]["edges"] = 3; }, "counts.edges: is 3 but the document has"},
      {[](json& d) { d["cells"][0]["witness"] = {"1/2", "1/2"}; }, "expected 3 coordinates"},
      {[](json& d) { d["geometry"]["faces"] = json::array(); }, "unknown field \"faces\""},
  };
  for (const auto& [edit, expected] : cases) {
    json doc = two_cubes();
    edit(doc);
    INFO(expected);
    CHECK_THAT(error_of(doc), Catch::Contains(expected));
  }
  CHECK(error_of(two_cubes()).empty());
}

TEST_CASE("a 3D complex document without geometry takes its measures as given", "[io][complex_json][3d]") {
  json doc = two_cubes();
  doc.erase("geometry");
  doc["counts"].erase("vertices");
  doc["counts"].erase("triangles");
  doc["patches"][0].erase("pieces");
  doc["cells"][1]["measure"] = "5/2";
  const ComplexDocument read = complex_document_from_json(doc);
  CHECK_FALSE(read.has_geometry);
  CHECK(read.complex.cells[1].measure.get().rational_value() == Rational(5, 2));
  doc["cells"][1]["measure"] = "0";
  CHECK_THAT(error_of(doc), Catch::Contains("a cell's volume must be positive"));
}
