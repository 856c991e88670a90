// NH-Rep Boolean trees as documents: hsx's JSON, NH-Rep's own `.conf` form, and a one-line text form.
//
// `hsx-nhtree/1` JSON:
//   {"format": "hsx-nhtree/1", "dimension": 2|3,
//    "tree": N, where N = {"op": "max"|"min", "leaves": [patch ids], "children": [N...]},
//    "patches": [{"id", "conf_id" (live only), "alive", "parent" (-1: original), "pieces", "origins": [ids]}],
//    "patch_graph": [{"a", "b", "type": "convex"|"concave"|"smooth"|"hybrid", "links"}],
//    "internal_curves": [{"patch", "type", "links"}] feature curves with one patch on both sides (not edges),
//    "decompositions": [{"patch", "subpatches", "pieces_split", "cut_links", "both_kinds_before",
//                        "both_kinds_after"}],
//    "steps": [{"subgraph", "parent_op", "parent_virtual", "q", "outcome", "decomposition"?}],
//    "groups": [[patch ids]...] (only when grouping was asked for)}
// `.conf` (NH-Rep's FeatureSample format): `csg{\n    list = [leaves..., [child]...],\n    flag_convex = 1|0,\n}`,
// leaves numbered by conf_id: live patches in order of their lowest origin (mesh triangle index), as NH-Rep
// numbers the patches of a (decomposed) mesh; flag_convex = 1 iff the root is a max node.
#pragma once

#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/geometry/scene.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace hsx {

inline constexpr const char* kNhTreeFormat = "hsx-nhtree/1";

/// Per patch id, its conf_id (-1 for decomposed patches).
std::vector<int> nhtree_conf_ids(const nhrep::PatchGraph& graph);

/// `groups` may be null (no grouping).
nlohmann::json nhtree_to_json(const nhrep::BuildResult& result, const std::vector<std::vector<int>>* groups);

/// NH-Rep's `.conf` text.
std::string nhtree_conf(const nhrep::BuildResult& result);

/// `max(0, 1, min(3, 4))`, leaves by patch id.
std::string nhtree_text(const nhrep::Tree& tree);

/// Reads NH-Rep's `.conf` tree (`list = [...]`, `flag_convex = 0|1`; ops alternate with depth). Leaves keep the
/// file's patch numbers. Throws InputError naming `source` and the line.
nhrep::Tree read_nhtree_conf(const std::string& text, const std::string& source);

/// Reads a face-patch file (one patch id per line, per triangle). Throws InputError naming `source` and the line.
std::vector<int> read_face_patch(const std::string& text, const std::string& source);

}  // namespace hsx
