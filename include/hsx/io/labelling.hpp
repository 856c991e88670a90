// Labellings computed elsewhere, for grading (`hsx grade`, algorithms/bsh/grade.hpp), and the BSH authors'
// graph-cut exchange format, so that their tool (or anyone's) runs on hsx's arrangements.
//
// The authors' `graph_cut` tool (BSH reference code) reads a graph
//   {"num_cells": C,
//    "patches": [{"adj_cell_0": c0, "adj_cell_1": c1, "weight": W, "implicit_id": h, "num_samples": n,
//                 "adj_patches": [patch ids]}]}
// and writes {"labels": [B per cell]}, B true for a cell of the object. Their conventions, which the export keeps:
//   - a patch has its cell on the positive side of its implicit (f > 0, outside the solid f < 0) as adj_cell_0 and
//     the one on the negative side (inside) as adj_cell_1; so adj_cell_0 is hsx's Patch::outside_cell and
//     adj_cell_1 its inside_cell (complex/complex.hpp);
//   - samples are numbered patch by patch; only their count per patch is given;
//   - adj_patches: the patches sharing a junction with this one, of any implicit (Complex::patch_neighbours);
//   - "weight" is read as an unsigned integer (their reader calls get<size_t>, which truncates a fraction), so the
//     export writes round(measure * weight_scale), the patch's measure (length or area) scaled. This is a rounding:
//     their graph cut then solves a nearby problem, and `hsx grade` grades its answer on the exact one.
// Their format has no outer cells (cells touching the domain's boundary, always outside a BSH shape, Def. 3.1) and
// no coincident boundaries (hsx gives one patch per coincident halfspace, all separating the same two cells, so a
// cut through them is charged once per patch there). The export adds fields their reader ignores:
//   "format": "bsh-graphcut", "complex_id" (io/result_json.hpp), "weight_scale", "outer_cells": [cell ids],
//   per patch "measure" (a double) and "measure_exact" (the closed form, or null), and "support" (the patch's
//   support group: patches with the same support are one point set).
#pragma once

#include <hsx/complex/complex.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace hsx {

inline constexpr const char* kBshGraphcutFormat = "bsh-graphcut";

/// The default weight scale of the export: weights in millionths of a unit of length (2D) or area (3D).
inline constexpr std::int64_t kDefaultGraphcutWeightScale = 1000000;

/// `complex` as the authors' graph-cut input (see above).
/// - `weight_scale`: patch weights are round(measure * weight_scale), at least 1. Throws InputError when it is < 1
///   or when a weight would exceed 2^53 (not exactly representable where their reader goes through a double).
nlohmann::json bsh_graphcut_to_json(const Complex& complex, std::int64_t weight_scale = kDefaultGraphcutWeightScale);

/// How a labelling file was written.
enum class LabellingFormat {
  Result,       ///< an hsx-result/1 document (its "inside_cells"; its complex_id must be the input's)
  GraphcutLabels,  ///< the authors' {"labels": [true/false or 0/1 per cell]}
  JsonList,     ///< a JSON array of 0/1 or true/false, one per cell in the complex's order (hsx-complex/1's cells)
  PlainList,    ///< text: 0/1 tokens separated by white space or commas, one per cell
};

const char* to_string(LabellingFormat format);

struct ReadLabelling {
  std::vector<char> cells;  ///< per cell of the complex: 1 inside, 0 outside
  LabellingFormat format = LabellingFormat::PlainList;
};

/// Reads a labelling of `complex` from `text`; `source` names it in error messages ("theirs.json: labels[3]: ...").
/// A document starting with '{' or '[' is JSON (an object with "format" is an hsx-result/1, one with "labels" the
/// authors' output), anything else a plain list. Throws InputError naming the source and the field or token when the
/// text is none of these, a value is not 0/1/true/false, or the count is not the complex's cell count.
ReadLabelling read_labelling_text(const std::string& text, const std::string& source, const Complex& complex);

/// The same for a file (io/files.hpp read_file).
ReadLabelling read_labelling_file(const std::string& path, const Complex& complex);

}  // namespace hsx
