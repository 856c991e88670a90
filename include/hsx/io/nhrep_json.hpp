// NH-Rep Boolean trees as documents: hsx's JSON, NH-Rep's own `.conf` form, and a one-line text form.
//
// `hsx-nhtree/1` JSON:
//   {"format": "hsx-nhtree/1", "dimension": 2|3,
//    "tree": N, where N = {"op": "max"|"min", "leaves": [patch ids], "children": [N...]},
//    "patches": [{"id", "conf_id" (live only), "alive", "parent" (-1: original), "pieces", "origins": [ids]}],
//      ("tree", "patch_graph", "decompositions", "steps" and "groups" use patch ids, Algorithm 1's own numbering;
//       "conf_id" maps each live one to NH-Rep's number, the one `.conf`, face-patch files and hsx nhtree's text
//       tree use: algorithms/nhrep/compare.hpp, nhrep_patch_numbers),
//    "patch_graph": [{"a", "b", "type": "convex"|"concave"|"smooth"|"hybrid", "links"}],
//    "internal_curves": [{"patch", "type", "links"}] feature curves with one patch on both sides (not edges),
//    "decompositions": [{"patch", "subpatches", "pieces_split", "cut_links", "both_kinds_before",
//                        "both_kinds_after"}],
//    "steps": [{"subgraph", "parent_op", "parent_virtual", "q", "outcome", "decomposition"?}],
//    "groups": [[patch ids]...] (only when grouping was asked for)}
//   2D documents add (nhtree_planar_json): "natural_halfspaces": {patch id: name, "~name" complemented},
//    "patch_pieces": {patch id: [{"edge", "kept_vertex"?, "split_point"? (exact [x, y])}]},
//    "evaluation": {"verdict", "correct", "describable", "cells", "wrong_inside", "wrong_outside" (exact points),
//                   "violations"}
// `.conf` (NH-Rep's FeatureSample format): `csg{\n    list = [leaves..., [child]...],\n    flag_convex = 1|0,\n}`,
// leaves numbered by conf_id: live patches in order of their lowest origin (mesh triangle index), as NH-Rep
// numbers the patches of a (decomposed) mesh; flag_convex = 1 iff the root is a max node. A node's leaves come
// ascending, then its children in order of their lowest leaf (nhrep::relabel_tree).
// Reference files written by NH-Rep's tool (read before any computation; every error names file and line):
//   `.conf` as above (each patch id at most once), a face-patch file (one patch id per line, per input triangle),
//   a patch-graph listing (`edge: A-B : T` per adjacent pair, T = 0 smooth, 1 convex, 2 concave; '#' comments).
//   Patch ids are limited to 0..kMaxPatchId.
#pragma once

#include <hsx/algorithms/nhrep/compare.hpp>
#include <hsx/algorithms/nhrep/planar.hpp>
#include <hsx/algorithms/nhrep/solid3.hpp>
#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/geometry/scene.hpp>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hsx {

inline constexpr const char* kNhTreeFormat = "hsx-nhtree/1";
inline constexpr int kMaxPatchId = 100000000;  ///< the largest patch id a reference file may hold

/// Per patch id, its conf_id (-1 for decomposed patches): nhrep::nhrep_patch_numbers.
std::vector<int> nhtree_conf_ids(const nhrep::PatchGraph& graph);

/// `groups` may be null (no grouping).
nlohmann::json nhtree_to_json(const nhrep::BuildResult& result, const std::vector<std::vector<int>>* groups);

/// The 2D keys above, to merge into nhtree_to_json's document.
nlohmann::json nhtree_planar_json(const nhrep::PlanarTree& tree, const nhrep::PlanarEvaluation& evaluation);

/// The 3D keys, to merge into nhtree_to_json's document: "natural_halfspaces" (per live patch), "patch_triangles"
/// (per live patch, its pieces' arrangement triangles, a split piece as {"triangle", "kept_edge"}: the arrangement
/// edge whose sub-triangle it is), "evaluation" as in 2D with points of three exact coordinates.
nlohmann::json nhtree_solid3_json(const nhrep::SolidTree3& tree, const nhrep::CellEvaluation& evaluation);

/// NH-Rep's `.conf` text.
std::string nhtree_conf(const nhrep::BuildResult& result);

/// `max(0, 1, min(3, 4))`, leaves as the tree holds them (patch ids; for NH-Rep's numbers and order, print
/// nhrep::relabel_tree(tree, nhtree_conf_ids(graph))).
std::string nhtree_text(const nhrep::Tree& tree);

/// Reads NH-Rep's `.conf` tree (`list = [...]`, `flag_convex = 0|1`; ops alternate with depth). Leaves keep the
/// file's patch numbers. Throws InputError naming `source` and the line.
nhrep::Tree read_nhtree_conf(const std::string& text, const std::string& source);

/// Reads a face-patch file (one patch id per line, per triangle; blank lines skipped). Throws InputError naming
/// `source` and the line, also for a file without any patch id.
std::vector<int> read_face_patch(const std::string& text, const std::string& source);

/// Reads NH-Rep's patch-graph listing (`edge: A-B : T`). Returns the edges with a < b, in file order. Throws
/// InputError naming `source` and the line: a malformed line, a type other than 0/1/2, a = b, an id beyond
/// kMaxPatchId, a pair listed twice, an empty file.
std::vector<nhrep::ReferenceEdge> read_nhrep_patch_graph(const std::string& text, const std::string& source);

/// The paths of NH-Rep reference files (empty: not given).
struct NhrepReferenceFiles {
  std::string tree;        ///< `.conf`
  std::string face_patch;  ///< the reference's patch per triangle (needs `tree`)
  std::string graph;       ///< patch-graph listing
};

struct NhrepReference {
  NhrepReferenceFiles files;
  std::optional<nhrep::ReferenceTree> tree;           ///< set iff files.tree is given
  std::optional<std::vector<nhrep::ReferenceEdge>> graph;  ///< set iff files.graph is given
};

/// Reads and checks every given reference file, so that bad references fail before any computation. Besides each
/// reader's checks: a face-patch file needs a tree, and every leaf of the tree must have a triangle in it (the
/// error names the `.conf` line of the leaf). Memory is linear in the files' sizes, whatever ids they hold.
/// Throws InputError naming the file (and line), also for missing, unreadable or non-regular files.
NhrepReference read_nhrep_reference(const NhrepReferenceFiles& files);

/// Checks a reference's face-patch list against the mesh it is to be compared with: one patch id per triangle.
/// @param[in] reference  as read_nhrep_reference returned it
/// @param[in] triangles  the input mesh's triangle count
/// Throws InputError naming the face-patch file.
void check_reference_mesh(const NhrepReference& reference, std::size_t triangles);

}  // namespace hsx
