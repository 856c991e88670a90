// The `hsx-result/1` document: a shape (a labelled complex) and how it was found. Fields as
// shared/spec/scene-format.md requires, plus what a reader needs to check it:
//   {"format": "hsx-result/1", "method", "optimal", "stopped_by"?,
//    "energy": {"missing_samples", "measure": M}, "area": M, "sample_connected",
//    "ties": {"count", "checked", "certified", "capped"},
//    "boundary": [{"patch", "halfspace", "coincident": [names], "pieces": [{"from": P, "to": P,
//                  "shape": "segment"|"arc", ("center", "radius", "ccw")}]}],   pieces run with the shape on
//                  their left; pieces are omitted when the complex has no geometry
//    "inside_cells": [ids], "removed_patches": [ids], "steps": [[patch ids]...] (beam), "tied": [[cell ids]...],
//    "stats": {"graph_cuts", "uncertified_cuts", "states_expanded", "states_created", "max_queue",
//              "labellings_enumerated", "seconds",
//              "branch_and_bound" (exact only): {"nodes", "nodes_created", "pruned_by_bound", "pruned_by_islands",
//                "certified_bounds", "lower_bound", "gap", "max_gap"}}}   bounds and gaps as
//                {"missing_samples", "measure" (a double: the bound rounded down; gaps incumbent's upper enclosure
//                minus the bound)}
// M = {"decimal", "exact"}; P = [x, y] exact strings.
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

/// The inside cells of an hsx-result/1 document, as a labelling of a complex with `cell_count` cells. Throws
/// InputError naming the field when the document is not a result or does not fit the complex.
std::vector<char> read_result_labelling(const nlohmann::json& document, int cell_count);

/// Patches of the supports flagged in `supports` (per support), ascending.
std::vector<int> patches_of_supports(const Complex& complex, const std::vector<char>& supports);

}  // namespace hsx
