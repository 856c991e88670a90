// The refined surfaces of a 3D arrangement as meshes for MeshLab, ParaView or Blender: ASCII PLY with per-face
// properties, and OBJ with a material library and one group per patch.
//
// Conventions (owned here):
// - Exported faces: every arrangement triangle that is not on the domain box, once, in ascending triangle order,
//   with the first (lowest-index) halfspace whose boundary contains it and that halfspace's patch containing it
//   (coincident boundaries give one face, not one per halfspace). Each face is turned so that its normal points out
//   of that halfspace (the arrangement's front side unless the halfspace's inside is in front); its colour is the
//   halfspace's colour in the pictures (io/svg.hpp's palette).
// - Vertices: those of the exported faces, in ascending arrangement order, renumbered from 0 (OBJ: from 1).
// - Coordinates are decimals that read back as the same doubles ("%.17g"), or with `exact` the exact rationals
//   ("-7/3"), which hsx's OBJ reader takes but most viewers do not (PLY is always decimal: its numbers are typed).
// - PLY (format ascii 1.0): vertex x, y, z (double); face vertex_indices (list uchar int), patch, halfspace,
//   front_cell, back_cell (int; cells of the complex, -1 outside the domain, front = the side the exported normal
//   points to), red, green, blue (uchar). Comments name the halfspaces.
// - OBJ: "mtllib NAME" then the vertices, then per patch in ascending order "g patch_<k>", "usemtl halfspace_<i>"
//   and its faces; the .mtl defines "halfspace_<i>" with its colour (Kd) for every halfspace.
// - Output is deterministic.
#pragma once

#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/geometry/scene3.hpp>

#include <array>
#include <string>
#include <vector>

namespace hsx {

struct ExportedFace {
  int triangle = -1;             ///< arrangement triangle
  std::array<int, 3> vertices{}; ///< arrangement vertex ids, turned as the conventions say
  int halfspace = -1;            ///< its first halfspace
  int patch = -1;                ///< that halfspace's patch containing it (-1 if the complex has none)
  int front_cell = -1, back_cell = -1;  ///< on the side its normal points to / the other side
};

/// The faces the exports write, in their order (see the conventions). `arranged` must come from `scene`.
std::vector<ExportedFace> exported_faces(const Arranged3& arranged);

struct MeshExportOptions {
  bool exact = false;  ///< OBJ coordinates as exact rationals instead of decimals
};

/// The PLY text. Throws std::invalid_argument when `arranged` does not fit `scene`.
std::string arrangement_ply(const Scene3& scene, const Arranged3& arranged);

struct ObjText {
  std::string obj, mtl;
};

/// The OBJ text, naming `mtl_name` (the .mtl file's name as the OBJ refers to it, e.g. "out.mtl"), and the .mtl
/// text. Throws std::invalid_argument when `arranged` does not fit `scene` or `mtl_name` is empty or has a line
/// break.
ObjText arrangement_obj(const Scene3& scene, const Arranged3& arranged, const std::string& mtl_name,
                        const MeshExportOptions& options = {});

/// The .mtl file that goes with an OBJ written to `obj_path`: the same path with extension ".mtl".
std::string mtl_path_for(const std::string& obj_path);

}  // namespace hsx
