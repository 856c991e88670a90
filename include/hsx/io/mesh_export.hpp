// The refined surfaces of a 3D arrangement, and the boundary of a shape (a labelling of its cells), as meshes for
// MeshLab, ParaView or Blender: ASCII PLY with per-face properties, OBJ with a material library and one group per
// patch, and (shapes) OFF with per-face colours.
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
// - A shape's boundary (shape_faces): every arrangement triangle whose two cells are labelled differently (one
//   inside the shape, the other outside it or beyond the domain), once, turned outward: its normal
//   (v1-v0)x(v2-v0) points out of the shape, so seen from outside its vertices run counter-clockwise and the
//   inside cell is behind it (back_cell; front_cell is the outside cell). Its patch is the patch of its support
//   group (complex/complex.hpp) whose inside cell is the shape's (the one "on b" with its halfspace's orientation,
//   algorithms/bsh/problem.hpp), the group's first patch when none is; its halfspace is that patch's. Faces are
//   ordered by patch, then by triangle. The mesh is closed: every edge is used as often in one direction as in
//   the other (once each where the boundary is a manifold), so sum det(v0, v1, v2) / 6 is the shape's volume.
// - OFF (shapes): "OFF", comment lines "# hsx shape boundary: ...", one "# halfspace <i> <name>" per halfspace and
//   one "# patch <k> halfspace <i> faces <first> <count>" per patch (faces <first> to <first>+<count>-1, 0-based,
//   carry patch k: faces come in patch order), then "nv nf 0", the vertices, and faces "3 a b c r g b" with the
//   halfspace's colour (0-255). Coordinates as in OBJ (decimals, or exact rationals with `exact`).
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

/// The boundary of the shape whose inside cells are those with labelling[c] = 1, outward, in the exports' order
/// (see the conventions). Throws std::invalid_argument when `labelling` does not have one entry per cell or labels
/// an outer cell inside (outer cells are always outside, algorithms/bsh/problem.hpp).
std::vector<ExportedFace> shape_faces(const Arranged3& arranged, const std::vector<char>& labelling);

/// The vertices of some faces, numbered as every export numbers them (the conventions' "Vertices"): from 0, in
/// ascending arrangement order, unused vertices left out.
struct VertexNumbering {
  std::vector<int> id;    ///< per arrangement vertex: its new number, -1 when no face uses it
  std::vector<int> used;  ///< the used arrangement vertices, ascending: used[id[v]] == v
};

/// The numbering of `faces`' vertices (from exported_faces or shape_faces). `arrangement`: the arrangement whose
/// vertex ids the faces carry. Throws std::out_of_range when a face names a vertex the arrangement does not have.
VertexNumbering renumber_vertices(const Arrangement3& arrangement, const std::vector<ExportedFace>& faces);

struct MeshExportOptions {
  bool exact = false;  ///< OBJ and OFF coordinates as exact rationals instead of decimals
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

/// A shape's boundary (shape_faces) as PLY, OBJ (with its .mtl) and OFF. `scene`, `arranged`, `mtl_name` as for
/// the arrangement's; `labelling` per cell, 1 inside. Throws std::invalid_argument as those do and as shape_faces.
std::string shape_ply(const Scene3& scene, const Arranged3& arranged, const std::vector<char>& labelling);
ObjText shape_obj(const Scene3& scene, const Arranged3& arranged, const std::vector<char>& labelling,
                  const std::string& mtl_name, const MeshExportOptions& options = {});
std::string shape_off(const Scene3& scene, const Arranged3& arranged, const std::vector<char>& labelling,
                      const MeshExportOptions& options = {});

/// The .mtl file that goes with an OBJ written to `obj_path`: the same path with extension ".mtl".
std::string mtl_path_for(const std::string& obj_path);

}  // namespace hsx
