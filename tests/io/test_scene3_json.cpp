// Tests of the 3D part of hsx-scene/1 (io/scene_json.hpp): every kind read, errors naming the JSON path, mesh
// files in OBJ, OFF and PLY giving the same scene, the write/read round trip, and the regression scenes in
// data/scenes3d.
#include <hsx/geometry/mesh3.hpp>
#include <hsx/geometry/tessellate3.hpp>
#include <hsx/io/bsh_config.hpp>
#include <hsx/io/scene_json.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace hsx;
using Catch::Matchers::Contains;

namespace {

std::string scene_error(const std::string& text, const std::string& base = "") {
  try {
    read_scene3_text(text, base);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string wrap(const std::string& halfspaces, const std::string& extra = "") {
  return R"({"format": "hsx-scene/1", "dimension": 3, )" + extra + R"("halfspaces": [)" + halfspaces + "]}";
}

bool same_scene(const Scene3& a, const Scene3& b) {
  if (a.halfspaces.size() != b.halfspaces.size() || a.samples.size() != b.samples.size()) return false;
  if (!(a.domain.min == b.domain.min && a.domain.max == b.domain.max)) return false;
  for (std::size_t i = 0; i < a.halfspaces.size(); ++i) {
    const Halfspace3 &x = a.halfspaces[i], &y = b.halfspaces[i];
    if (x.name != y.name || x.kind != y.kind || x.complement != y.complement || x.normal != y.normal ||
        x.offset != y.offset || x.surface.vertices != y.surface.vertices || x.surface.triangles != y.surface.triangles)
      return false;
  }
  for (std::size_t j = 0; j < a.samples.size(); ++j)
    if (a.samples[j].location != b.samples[j].location || a.samples[j].halfspace != b.samples[j].halfspace)
      return false;
  return true;
}

const char* kAllKinds = R"({"format": "hsx-scene/1", "dimension": 3, "description": "every kind",
  "domain": {"min": [-10, -10, -10], "max": [10, 10, 10]},
  "halfspaces": [
    {"name": "P", "kind": "plane", "normal": [0, 0, 1], "offset": "1/2"},
    {"name": "B", "kind": "box", "min": [0, 0, 0], "max": [1, 2, 3], "complement": true},
    {"name": "S", "kind": "sphere", "center": [1, 1, 1], "radius": 2.5,
     "tessellation": {"segments": 12, "bands": 4, "frame": "bsh"}},
    {"name": "C", "kind": "cylinder", "axis_point1": [0, 0, -1], "axis_point2": [0, 0, 1], "radius": 1,
     "tessellation": {"edge_length": 0.5}},
    {"name": "I", "kind": "cylinder", "axis_point1": [0, 0, 0], "axis_point2": [1, 0, 0], "radius": 3,
     "infinite": true, "tessellation": {"segments": 8}},
    {"name": "K", "kind": "cone", "apex": [0, 0, 5], "base_center": [0, 0, 2], "radius": 1},
    {"name": "T", "kind": "torus", "center": [0, 0, 0], "axis": [0, 1, 1], "major_radius": 4, "minor_radius": 1,
     "tessellation": {"segments": 16, "minor_segments": 6, "frame": "bsh"}}
  ],
  "samples": [{"on": "P", "at": [3, 3, 0.5]}, {"on": "B", "at": [0, 1, 1]}, {"on": "S", "near": [9, 1, 1]},
              {"on": "T", "near": [0, 0, 0]}]})";

}  // namespace

TEST_CASE("3D scenes: every kind is read and round-trips", "[scene3_json]") {
  const Scene3 s = read_scene3_text(kAllKinds);
  REQUIRE(s.halfspaces.size() == 7);
  CHECK(s.halfspaces[0].kind == HalfspaceKind3::Plane);
  CHECK(s.halfspaces[1].surface.triangles.size() == 12);
  CHECK(s.halfspaces[2].surface.triangles.size() == 2 * 12 * 3);  // 4 bands, 3 rings
  CHECK(s.halfspaces[2].surface.vertices[1].y == 1);  // the authors' frame: ring point 0 towards +x from the centre
  CHECK(s.halfspaces[2].surface.vertices[1].x > 1);
  CHECK(s.halfspaces[3].surface.triangles.size() == 4 * 13);  // ceil(2 pi / 0.5) = 13 segments
  CHECK(s.halfspaces[5].surface.triangles.size() == 2 * 32);
  CHECK(s.halfspaces[6].surface.triangles.size() == 2 * 16 * 6);
  CHECK(s.halfspaces[1].complement);
  CHECK(s.samples[2].snapped);
  CHECK(s.samples[2].location.x > 3);
  CHECK(scene_dimension(parse_exact_json(kAllKinds)) == 3);
  const nlohmann::json written = write_scene3(s);
  const Scene3 back = read_scene3(parse_exact_json(written.dump()));
  CHECK(same_scene(s, back));
  CHECK(written.dump() == write_scene3(back).dump());
}

TEST_CASE("3D scene errors name the JSON path", "[scene3_json]") {
  CHECK_THAT(scene_error(wrap(R"({"name": "S", "kind": "sphere", "center": [0, 0, 0], "radius": -1})")),
             Contains("halfspaces[0].radius: must be positive"));
  CHECK_THAT(scene_error(wrap(R"({"name": "S", "kind": "sphere", "center": [0, 0], "radius": 1})")),
             Contains("halfspaces[0].center: expected [x, y, z]"));
  CHECK_THAT(scene_error(wrap(R"({"name": "C", "kind": "cylinder", "axis_point1": [0, 0, 0], "axis_point2": [0, 0, 0], "radius": 1})")),
             Contains("halfspaces[0].axis_point2: the axis has zero length"));
  CHECK_THAT(scene_error(wrap(R"({"name": "S", "kind": "sphere", "center": [0, 0, 0], "radius": 1, "tessellation": {"segments": 2}})")),
             Contains("halfspaces[0].tessellation.segments: must be between 3 and 4096"));
  CHECK_THAT(scene_error(wrap(R"({"name": "S", "kind": "sphere", "center": [0, 0, 0], "radius": 1, "tessellation": {"edge_length": "1e-9"}})")),
             Contains("halfspaces[0]: tessellation:") );
  CHECK_THAT(scene_error(wrap(R"({"name": "S", "kind": "sphere", "center": [0, 0, 0], "radius": 1, "tessellation": {"segments": 8, "bands": 1}})")),
             Contains("halfspaces[0].tessellation.bands: must be between 2 and 4096, got 1"));
  CHECK_THAT(scene_error(wrap(R"({"name": "S", "kind": "sphere", "center": [0, 0, 0], "radius": 1, "tessellation": {"segments": 8, "frame": "z"}})")),
             Contains("halfspaces[0].tessellation.frame: expected \"smallest-axis\" or \"bsh\""));
  CHECK_THAT(scene_error(wrap(R"({"name": "T", "kind": "torus", "center": [0, 0, 0], "axis": [0, 0, 1], "major_radius": 2, "minor_radius": 1, "tessellation": {"segments": 8, "bands": 4}})")),
             Contains("halfspaces[0].tessellation: unknown field \"bands\""));
  CHECK_THAT(scene_error(wrap(R"({"name": "S", "kind": "sphere", "center": [0, 0, 0], "radius": 1, "color": 3})")),
             Contains("halfspaces[0]: unknown field \"color\""));
  CHECK_THAT(scene_error(wrap(R"({"name": "D", "kind": "disk", "center": [0, 0], "radius": 1})")),
             Contains("is a 2D kind"));
  CHECK_THAT(scene_error(wrap(R"({"name": "I", "kind": "cylinder", "axis_point1": [0, 0, 0], "axis_point2": [0, 0, 1], "radius": 1, "infinite": true})")),
             Contains("halfspaces[0].infinite: an infinite cylinder is clipped by the domain"));
  CHECK_THAT(scene_error(wrap(R"({"name": "M", "kind": "mesh", "file": "missing.obj"})")),
             Contains("halfspaces[0].file: missing.obj: cannot open it"));
  CHECK_THAT(scene_error(wrap(R"({"name": "B", "kind": "box", "min": [0, 0, 0], "max": [1, 1, 1]})",
                              R"("samples": [{"on": "B", "at": [5, 5, 5]}], )")),
             Contains("samples[0] (on \"B\"): point [5, 5, 5] is not on the boundary"));
  CHECK_THAT(scene_error(wrap(R"({"name": "B", "kind": "box", "min": [0, 0, 0], "max": [1, 1, 1]})",
                              R"("domain": {"min": [0, 0, 0], "max": [1, 1, "1/2"]}, )")),
             Contains("halfspaces[0] (\"B\"): vertex 4 [0, 0, 1] is outside the domain"));
  CHECK_THAT(scene_error(R"({"format": "hsx-scene/1", "dimension": 2, "halfspaces": []})"),
             Contains("dimension: expected 3, got 2"));
  // The 2D reader keeps refusing 3D scenes.
  CHECK_THROWS_WITH(read_scene_text(wrap(R"({"name": "P", "kind": "plane", "normal": [0, 0, 1], "offset": 0})")),
                    Contains("dimension: 3D scenes are not supported yet"));
}

TEST_CASE("mesh files in OBJ, OFF and PLY give the same scene; regression scenes read", "[scene3_json]") {
  const std::string dir = std::string(HSX_SOURCE_DIR) + "/data/scenes3d";
  const Scene3 a = read_scene3_file(dir + "/mesh_obj.json");
  const Scene3 b = read_scene3_file(dir + "/mesh_off.json");
  const Scene3 c = read_scene3_file(dir + "/mesh_ply.json");
  CHECK(same_scene(a, b));
  CHECK(same_scene(a, c));
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    INFO(entry.path().string());
    const Scene3 s = read_scene3_file(entry.path().string());
    CHECK_FALSE(s.halfspaces.empty());
    CHECK(read_scene3_input_file(entry.path().string()).halfspaces.size() == s.halfspaces.size());
    ++count;
  }
  CHECK(count >= 6);
}

TEST_CASE("the BSH authors' config: a folder of our own", "[scene3_json]") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hsx_test_bsh_config";
  std::filesystem::create_directories(dir);
  auto write = [&](const char* name, const std::string& text) { std::ofstream(dir / name) << text; };
  write("grid_64.json", R"({"resolution": [64, 64, 64], "bbox_min": [-2, -2, -2], "bbox_max": [2, 2, 2]})");
  write("1_sample.xyz", "3\n0.5 0 0.01 \n0 0.5 0\n");
  write("2_sample.xyz", "3\n0 0 1.9\n");
  write("config.json", R"({"input": [
      {"type": "sphere", "name": "1", "center": [0, 0, 0], "radius": 0.5, "is_flipped": true, "samples": "1_sample.xyz",
       "color": [1, 0, 0, 1]},
      {"type": "plane", "name": "2", "point": [0, 0, 1.9], "normal": [0, 0, 1], "samples": "2_sample.xyz"}]})");
  const Scene3 s = read_scene3_input_file((dir / "config.json").string());
  REQUIRE(s.halfspaces.size() == 2);
  CHECK(s.halfspaces[0].complement);
  CHECK(s.halfspaces[0].primitive.tessellation.segments == 29);  // h = sqrt(48)/64: round(pi / asin(h / 1)) = 29
  CHECK(s.halfspaces[1].offset == make_rational(Integer(19), Integer(10)));
  CHECK(s.samples.size() == 3);
  CHECK(s.samples[2].distance2 == 0);
  CHECK(s.domain.max.x == 2);
  // The files it read, as it opened them: the grid, then the samples files in the config's order.
  std::vector<std::string> files;
  read_bsh_config(read_exact_json_file((dir / "config.json").string()), dir.string(), "config.json", {}, &files);
  CHECK(files == std::vector<std::string>{(dir / "grid_64.json").string(), (dir / "1_sample.xyz").string(),
                                          (dir / "2_sample.xyz").string()});
  // Their cone: one nappe from the apex, half angle 0.5 about +z, clipped by the box: here the cone of height 2.
  write("cone.json", R"({"input": [{"type": "cone", "name": "K", "apex": [0, 0, 0], "axis_vector": [0, 0, 3],
      "apex_angle": 0.5, "is_flipped": false}]})");
  const Scene3 cone = read_bsh_config_file((dir / "cone.json").string());
  REQUIRE(cone.halfspaces.size() == 1);
  const Halfspace3& k = cone.halfspaces[0];
  CHECK(k.kind == HalfspaceKind3::Cone);
  CHECK(k.primitive.infinite);
  CHECK(k.primitive.tessellation.segments == bsh_segments(std::sqrt(48.0) / 64, std::sqrt(48.0) * std::sin(0.5)));
  double six_volume = 0;
  for (const auto& t : k.surface.triangles) {
    const PointQ3 &a = k.surface.vertices[t[0]], &b = k.surface.vertices[t[1]], &c = k.surface.vertices[t[2]];
    six_volume += dot3(a, triangle_normal(a, b, c)).get_d();
  }
  const double height = 2, radius = 2 * std::tan(0.5), analytic = M_PI * radius * radius * height / 3;
  CHECK(six_volume / 6 < analytic);  // inscribed
  CHECK(six_volume / 6 > analytic * 0.999);
  CHECK(write_scene3(cone).dump().find("\"infinite\":true") != std::string::npos);
  const Scene3 back = read_scene3(parse_exact_json(write_scene3(cone).dump()));
  CHECK(back.halfspaces[0].surface.triangles == k.surface.triangles);
  write("cone.json", R"({"input": [{"type": "cone", "name": "K", "apex": [0, 0, 0], "axis_vector": [0, 0, 1],
      "apex_angle": 2}]})");
  CHECK_THROWS_WITH(read_bsh_config_file((dir / "cone.json").string()),
                    Contains("input[0].apex_angle: must be between 0 and pi/2"));
  write("1_sample.xyz", "3\n0.5 0 zero\n");
  CHECK_THROWS_WITH(read_bsh_config_file((dir / "config.json").string()), Contains("1_sample.xyz:2: coordinate \"zero\""));
  write("1_sample.xyz", "3\n0.5 0\n");
  CHECK_THROWS_WITH(read_bsh_config_file((dir / "config.json").string()), Contains("fewer than 3 coordinates"));
  // Hostile samples files: bytes shown escaped, a size and a count bounded, a folder refused.
  write("1_sample.xyz", std::string("3\n0 0 \x01\0x\n", 13));
  CHECK_THROWS_WITH(read_bsh_config_file((dir / "config.json").string()), Contains(":2: coordinate \"\\x01\\x00x\""));
  write("1_sample.xyz", "3\n0.5 0 0\n");
  std::filesystem::resize_file(dir / "1_sample.xyz", std::uintmax_t(1) << 30);  // sparse: NUL bytes
  CHECK_THROWS_WITH(read_bsh_config_file((dir / "config.json").string()),
                    Contains("1_sample.xyz\" is too large (1073741824 bytes; the limit is 67108864)"));
  std::string many = "3\n";
  for (int k = 0; k <= 100000; ++k) many += "0.5 0 0\n";
  write("1_sample.xyz", many);
  CHECK_THROWS_WITH(read_bsh_config_file((dir / "config.json").string()),
                    Contains("1_sample.xyz:100002: more than 100000 samples"));
  std::filesystem::remove(dir / "1_sample.xyz");
  std::filesystem::create_directory(dir / "1_sample.xyz");
  CHECK_THROWS_WITH(read_bsh_config_file((dir / "config.json").string()), Contains("1_sample.xyz"));
  std::filesystem::remove(dir / "1_sample.xyz");
  // Numbers past the range of doubles, in which their program computes h and the cone's mesh.
  write("cone.json", R"({"input": [{"type": "cone", "name": "K", "apex": ["1e400", 0, 0], "axis_vector": [0, 0, 1],
      "apex_angle": 0.5}]})");
  CHECK_THROWS_WITH(read_bsh_config_file((dir / "cone.json").string()),
                    Contains("cone.json: input[0]: the authors' cone mesh, computed in double precision, overflows"));
  write("cone.json", R"({"input": [{"type": "cone", "name": "K", "apex": [0, 0, 0], "axis_vector": ["1e-400", 0, 0],
      "apex_angle": 0.5}]})");
  CHECK_THROWS_WITH(read_bsh_config_file((dir / "cone.json").string()), Contains("overflows"));
  write("grid_64.json", R"({"resolution": [64, 64, 64], "bbox_min": ["-1e400", -2, -2], "bbox_max": [2, 2, 2]})");
  CHECK_THROWS_WITH(read_bsh_config_file((dir / "config.json").string()),
                    Contains("grid_64.json: document: the grid cell's diagonal (their h, in double precision) is infinite"));
  std::filesystem::remove(dir / "grid_64.json");
  CHECK_THROWS_WITH(read_bsh_config_file((dir / "config.json").string()), Contains("grid_64.json"));
  std::filesystem::remove_all(dir);
}
