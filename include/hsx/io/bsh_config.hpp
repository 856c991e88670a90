// The BSH authors' own 3D scene files (their public Boundary-Sampled Halfspaces code): a folder with `config.json`
// ({"input": [{"type": ..., "name": ..., "samples": "N_sample.xyz", ...}]}), one samples file per halfspace
// (first token 3, then x y z triples) and `grid_64.json` (`bbox_min`, `bbox_max`: the domain; `resolution`: three
// cell counts, 1 to 1000000, which give their h).
//
// Conventions (owned here):
// - Every number is read as the exact decimal it is written as ("0.45609" is 45609/100000), never as a double.
// - The solid is the side f < 0 of each halfspace; `is_flipped` (default false) negates f, i.e. sets complement.
//     plane:    `point`, `normal`; f = n . (x - p)           -> plane, normal n, offset n . p
//     sphere:   `center`, `radius`                            -> sphere
//     cylinder: `axis_point1`, `axis_point2`, `radius`        -> infinite cylinder (their f is the distance to the
//               axis line), clipped exactly by the domain box
//     torus:    `center`, `axis_vector`, `major_radius`, `minor_radius` -> torus
//   tessellated the authors' way (their src/Mesh_BSH.cpp, read and checked against the vertices of their
//   reference-result.grid files; geometry/tessellate3.hpp gives the vertices, rounded to 2^-32 as documented there):
//   h = the diagonal of one cell of their grid, |(bbox_max - bbox_min) / resolution| (grid_64.json), in double
//   precision; n = max(15, round(pi / asin(h / 2r))) segments per circle of radius r (15 when h >= 2r; torus:
//   r = major_radius about the axis, minor_radius around the tube); a sphere has 2 q latitude bands (2 q - 1 rings
//   of n vertices, plus the poles), q = max(15, round(pi / (4 asin(h / 2r)))), in the coordinate frame (rings
//   about +z, theta measured from +x towards +y); tori and cylinders in their frame: u = the unit w x (+x) (w x (+y)
//   when the axis is parallel to x), v = w x u (Tessellation3::Frame::Bsh). Their cylinder is a prism whose
//   lateral planes pass through the ring of axis_point1 (their ring is shifted along the axis, which leaves the
//   planes unchanged). Their planes are quads reaching beyond the box, which inside the box is the plane itself:
//   hsx keeps them exact planes, clipped by the arrangement.
//     cone:     `apex`, `axis_vector`, `apex_angle` (the half angle, in (0, pi/2)) -> one infinite nappe (their f < 0
//               where the angle between x - apex and the axis is below apex_angle), clipped exactly by the domain
//               box: their ring (Mesh_BSH::generate_cone, in double precision, its doubles taken exactly) has its
//               centre at apex + L cos(apex_angle) w and radius L sin(apex_angle), L = 1.001 times the distance
//               from the apex to the farthest box corner, w = the unit axis; n = their count for a circle of radius
//               (box diagonal) sin(apex_angle); the lateral planes through the apex and consecutive ring points
//               (rounded as in geometry/tessellate3.hpp) clip the box. An obtuse apex_angle is refused: their mesh
//               then lies on the +axis nappe while their f's zero set is the -axis one.
// - `quadric` and `rbf` are refused with a message naming the entry. `color` is ignored;
//   any other unknown field is refused.
// - Samples are inexact points near the surface: each becomes a `near` sample of its halfspace (snapped exactly).
// - Errors are InputError naming the file and the JSON path or line: "config.json: input[3].radius: ...",
//   "4_sample.xyz:2: ...".
#pragma once

#include <hsx/geometry/scene3.hpp>
#include <hsx/io/scene_json.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace hsx {

/// Options of the reader (the defaults are the authors' own settings).
struct BshReadOptions {
  double h_scale = 1;  ///< h = their grid cell's diagonal * h_scale: 1/2 and 1/4 give finer tessellations (benchmarks)
  /// All surfaces' triangles together, counted as each is tessellated (SceneReadLimits::max_surface_triangles).
  std::size_t max_surface_triangles = 4'000'000;
};

/// True when `doc` is the authors' config: a JSON object with an "input" member (and no hsx "format").
bool is_bsh_config(const nlohmann::json& doc);

/// Reads the authors' config DOM (from parse_exact_json); samples files and grid_64.json are looked up in
/// `directory` (empty: the working directory); `config_name` (its path) prefixes messages about the config, and
/// its file name is in the description. Samples files may have 64 MiB and, together, 100,000 samples
/// (SceneReadLimits::max_samples). Validated (validate_and_resolve). When `files_read` is given, the path of each
/// file read is appended to it as it was opened: grid_64.json, then the samples files in the config's order.
Scene3 read_bsh_config(const nlohmann::json& doc, const std::string& directory,
                       const std::string& config_name = "config.json", const BshReadOptions& options = {},
                       std::vector<std::string>* files_read = nullptr);

/// read_exact_json_file + read_bsh_config with the file's folder.
Scene3 read_bsh_config_file(const std::string& path, const BshReadOptions& options = {});

/// A 3D scene file of either kind, told apart by content: the authors' config (is_bsh_config) or an hsx-scene/1
/// document with dimension 3 (read_scene3, mesh paths relative to the file's folder). Errors are prefixed with the
/// path.
Scene3 read_scene3_input_file(const std::string& path, const SceneReadLimits& limits = {});

}  // namespace hsx
