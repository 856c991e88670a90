// Reading and writing hsx scene files (`hsx-scene/1`, see docs/scene-format.md).
//
// Every error is an hsx::InputError whose message starts with the JSON path or the object it is about:
//   "halfspaces[2].radius: expected a number, got \"abc\""
//   "halfspaces[2] (\"C\"): polygon is self-intersecting: edges 0 and 2 cross at [1, 1]"
//   "samples[4] (on \"A\"): point [2, 0] is not on the boundary of \"A\" (about 0.5 away)"
// and, for files, is prefixed with the file path ("scene.json: line 3, column 7: ...").
#pragma once

#include <hsx/geometry/mesh3.hpp>
#include <hsx/geometry/scene.hpp>
#include <hsx/geometry/scene3.hpp>
#include <hsx/io/exact_json.hpp>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace hsx {

inline constexpr const char* kSceneFormat = "hsx-scene/1";

struct SceneReadLimits {
  JsonLimits json;               ///< 64 MiB, depth 64
  NumberLimits numbers;          ///< 20,000 characters per number
  std::size_t max_halfspaces = 100000;
  std::size_t max_samples = 100000;
  std::size_t max_polygon_vertices = 5000;  ///< also enforced by validate_and_resolve
  MeshReadLimits meshes;                    ///< 3D: every `mesh` file
  int max_segments = 4096;                  ///< 3D: segments per circle of a tessellation (at most kMaxSegments)
  /// 3D: the triangles of all surfaces together (tessellations and meshes, before coincident ones are merged),
  /// counted as each is read, so that many large surfaces are refused before all are in memory; 0: no limit.
  /// load_input sets it to ArrangementLimits::max_triangles (--max-triangles).
  std::size_t max_surface_triangles = 4'000'000;
};

/// Checks `format` ("hsx-scene/1") and `dimension` and returns the dimension (2 or 3). The entry point for
/// dispatching between the 2D and 3D readers.
int scene_dimension(const nlohmann::json& doc);

/// Reads a 2D scene from a DOM built by parse_exact_json, then calls validate_and_resolve. A 3D scene is refused
/// with "dimension: 3D scenes are not supported yet" (for callers that read 2D scenes only; dispatch on
/// scene_dimension to read either).
Scene2 read_scene2(const nlohmann::json& doc, const SceneReadLimits& limits = {});

/// parse_exact_json + read_scene2.
Scene2 read_scene_text(std::string_view text, const SceneReadLimits& limits = {});

/// read_exact_json_file + read_scene2; errors are prefixed with the path.
Scene2 read_scene_file(const std::string& path, const SceneReadLimits& limits = {});

/// The scene as JSON with exact numbers (integers fitting int64 as JSON integers, other rationals as strings
/// "-7/3"). The domain is written only when it was given; samples are written as given (`at` or `near`), so
/// read_scene2(write_scene2(s)) reproduces s, including the chosen domain and the snapped locations.
nlohmann::json write_scene2(const Scene2& scene);

/// Reads a 3D scene (docs/scene-format.md, "3D scene"): tessellates the primitives (geometry/tessellate3.hpp),
/// reads `mesh` files (.obj, .off, .ply by extension) relative to `base_directory` (empty: the working
/// directory), then calls validate_and_resolve(Scene3&). A 2D scene is refused with "dimension: expected 3, got 2".
/// Errors name the JSON path ("halfspaces[1].radius: must be positive, got -1") or the halfspace and the mesh
/// file's line.
Scene3 read_scene3(const nlohmann::json& doc, const std::string& base_directory = "",
                   const SceneReadLimits& limits = {});

/// parse_exact_json + read_scene3.
Scene3 read_scene3_text(std::string_view text, const std::string& base_directory = "",
                        const SceneReadLimits& limits = {});

/// read_exact_json_file + read_scene3 with the file's folder as the base; errors are prefixed with the path.
Scene3 read_scene3_file(const std::string& path, const SceneReadLimits& limits = {});

/// A 3D scene as hsx-scene/1 JSON with exact numbers: every halfspace from its parameters (`Primitive3`, the mesh
/// file as written), the domain when given, samples as given; read_scene3(write_scene3(s)) reproduces s (same
/// triangles, same snapped samples) when mesh paths resolve the same way.
nlohmann::json write_scene3(const Scene3& scene);

}  // namespace hsx
