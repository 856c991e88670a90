// A mesh after NH-Rep's patch decomposition, written as NH-Rep's tool writes it (`*.decomposed.obj/.fea` and a
// face-patch file), so that the next stage of an NH-Rep pipeline can read it.
//
// Conventions:
// - Faces in the order of the input's triangles; a triangle split by face-splitting is replaced, in place, by its
//   sub-triangles (centroid, then the kept edge's two vertices, oriented as the triangle was). Without face
//   splits, face i is the input's face i, so face-patch files compare line by line.
// - Vertices: the input's, then one centroid per split triangle. Coordinates are written as exact decimals when
//   their expansion ends within 30 significant digits (always true for vertices read from decimal text); a
//   centroid whose expansion does not end is rounded to 30 significant digits (the only inexact output here).
// - Orientation: outward (a mesh read inward-facing was flipped by geometry/mesh3.hpp and stays flipped).
// - `.fea`: the count, then one line "a b" (0-based, a < b) per feature edge of the decomposed patches: the
//   input's feature edges, plus the edges the minimum cut crossed (NH-Rep's tool marks those too); sorted.
// - face-patch: per face, the patch's conf_id (io/nhrep_json.hpp: live patches by lowest input triangle).
#pragma once

#include <hsx/algorithms/nhrep/patch_graph.hpp>
#include <hsx/geometry/mesh3.hpp>

#include <string>
#include <vector>

namespace hsx {

struct DecomposedMesh {
  std::string obj, fea, face_patch;
  int faces = 0;          ///< triangles written
  int split_faces = 0;    ///< input triangles replaced by their sub-triangles
  int feature_edges = 0;
};

/// `graph` must have been built from boundary_from_mesh(mesh, ...) (pieces = triangles, links = mesh edges, then
/// whatever decomposition added); `conf_id` per patch id (nhtree_conf_ids). Throws std::invalid_argument otherwise.
DecomposedMesh write_decomposed_mesh(const Mesh3& mesh, const nhrep::PatchGraph& graph, const std::vector<int>& conf_id);

}  // namespace hsx
