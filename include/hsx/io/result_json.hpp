// The `hsx-result/1` document: a shape (a labelled complex) and how it was found. Fields as
// shared/spec/scene-format.md requires, plus what a reader needs to check it:
//   {"format": "hsx-result/1", "complex_id", "method", "optimal", "stopped_by"?,
//    "energy": {"missing_samples", "measure": M}, "area": M (2D) | "volume": M (3D: exact rational),
//    "boundary_area": M + {"terms"} (3D only: energy.measure again, the boundary's exact area, with the number of
//      terms of its closed form), "sample_connected",
//    "ties": {"count", "checked", "certified", "capped", "stopped_by"?},  stopped_by ("max-ties", "time-limit",
//      "max-states", "max-graph-cuts") says why a capped enumeration stopped; the top-level "stopped_by" names
//      a limit that stopped the search for the optimum itself (then "optimal" is false)
//    "boundary": [{"patch", "halfspace", "coincident": [names], "measure": M, "pieces": [{"from": P, "to": P,
//                  "shape": "segment"|"arc", ("center", "radius", "ccw")}]}],   one item per support group on the
//                  boundary; "patch" is its patch with the boundary's orientation (oriented_patch below), the
//                  other halfspaces of the group are "coincident"; 2D pieces run with the shape on their left and
//                  are omitted when the complex has no geometry; 3D items have "inside_cell" and "outside_cell"
//                  (the shape's side and the other) and "triangles" (the patch's arrangement triangles: the
//                  boundary mesh is extract's --obj/--ply/--off, io/mesh_export.hpp)
//    "inside_cells": [ids], "removed_patches": [ids], "steps": [[patch ids]...] (beam), "tied": [[cell ids]...],
//    "stats": {"graph_cuts", "uncertified_cuts", "reused_cuts", "states_expanded", "states_created", "max_queue",
//              "labellings_enumerated", "seconds",
//              "branch_and_bound" (exact only): {"nodes", "nodes_created", "pruned_by_bound", "pruned_by_islands",
//                "island_branches", "certified_bounds", "lower_bound", "gap", "max_gap"}}}   bounds and gaps as
//                {"missing_samples", "measure" (a double: the bound rounded down; gaps incumbent's upper enclosure
//                minus the bound)}
// M = {"decimal", "certified": false (only when the digits are not pinned down), "exact" (null: no closed form)};
// P = [x, y] exact strings.
// "complex_id" is the identity of the input the cell ids refer to (complex_identity below); a reader refuses a
// result whose identity is not that of its own input.
#pragma once

#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/complex/complex.hpp>
#include <hsx/geometry/arrangement2.hpp>

#include <nlohmann/json.hpp>

namespace hsx {

inline constexpr const char* kResultFormat = "hsx-result/1";

/// The 2D pieces that patches refer to (Patch::pieces): an arrangement's, or those read from a complex document.
struct PlanarPieces {
  const std::vector<ArrVertex2>* vertices = nullptr;
  const std::vector<ArrEdge2>* edges = nullptr;
  bool known() const { return vertices && edges && !edges->empty(); }
};

/// `geometry` may be empty (a complex imported without geometry). `include_seconds` false leaves timing out so
/// that documents are byte-for-byte reproducible.
nlohmann::json result_to_json(const bsh::Problem& problem, const bsh::ExtractResult& result,
                              const PlanarPieces& geometry, bool include_seconds = true);

/// The identity of a complex: "sha1:" and the SHA-1 (40 hex digits) of its canonical text, which holds what a
/// result's cell ids mean and nothing else, one item per line ('\n'), numbers in decimal:
///   hsx-complex-id/1
///   dimension D
///   halfspaces H, then each name as a JSON string
///   cells C, then per cell: "1" or "0" (outer), a space, and its inside flag per halfspace as 0/1 digits
///   patches P, then per patch: halfspace inside_cell outside_cell, then " :" and its junction ids
///   supports S, then per support group its patch ids
/// Ids are positions in the lists. So a scene and the hsx-complex/1 document `hsx arrange --json` writes of it have
/// the same identity, and so do scenes that differ only in their samples (a result names cells, a solid of the
/// arrangement, whatever samples chose it); geometry that moves without changing any cell's sign vector or any
/// adjacency keeps it too (the cells are then the same sign-vector regions).
std::string complex_identity(const Complex& complex);

/// The inside cells of an hsx-result/1 document as a labelling of `complex`. Throws InputError naming the field
/// when the document is not a result, was computed from another input (its complex_id differs from
/// complex_identity(complex), or it has none), or names a cell the complex does not have.
std::vector<char> read_result_labelling(const nlohmann::json& document, const Complex& complex);

/// The patch of support group `support` that lies on the boundary of `labelling` with its halfspace's
/// orientation (its inside cell labelled 1: algorithms/bsh/problem.hpp); the group's first patch when none does.
int oriented_patch(const Complex& complex, int support, const std::vector<char>& labelling);

/// The number of terms of a Measure's closed form (Measure::exact_string): the " + " and " - " outside
/// parentheses, plus one; 0 for an empty text.
std::size_t closed_form_terms(const std::string& text);

/// Patches of the supports flagged in `supports` (per support), ascending.
std::vector<int> patches_of_supports(const Complex& complex, const std::vector<char>& supports);

}  // namespace hsx
