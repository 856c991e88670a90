// The BSH authors' own result file (`reference-result.grid`, written by their public code next to config.json),
// and its comparison with hsx's exact arrangement and complex of the same config.json.
//
// File format (as their code writes it; conventions owned here):
// - A sequence of sections. A section starts with a header line `NAME COUNT [WIDTH]` and is followed by exactly
//   COUNT lines (a line may be empty). Sections read: `vert` (COUNT lines of 3 decimal coordinates), `face` (COUNT
//   lines of 3 vertex ids, 0-based), `face_implicit` (1 line: per face its halfspace, -1 for faces of their
//   bounding box and of plane parts outside it), `patch_faces` (COUNT lines: the face ids of patch p),
//   `patch_implicit` (1 line: per patch its halfspace), `block_patches` (COUNT lines: the patch ids bounding
//   block b), `patch_labels` (1 line: per patch 1 when it is on their final boundary), `block_labels` (1 line:
//   per block 0 = in their solid, 1 = outside). Other sections (samples, patch_samples, patch_distance_area) are
//   skipped by their line count. `vert`, `face`, `patch_faces`, `block_patches` and `block_labels` are required.
// - Coordinates are read exactly as the decimal text they are written as (hsx::parse_rational: "0.1" is 1/10).
// - Checked on reading: ids in range, every face in at most one patch, every patch in exactly two blocks (their
//   blocks are the regions of the bounding box on either side of a patch), labels 0 or 1, per-face and per-patch
//   lists of the right length. Their files hold blocks with no patch (listed as empty lines) and faces of zero
//   area (collinear vertices): both are accepted, and counted by the comparison. Counts are bounded by BshReferenceLimits so that a hostile
//   file fails fast. Errors are InputError "FILE:LINE: section NAME: ...".
//
// Comparison (conventions owned here):
// - An interior point of each of their blocks is found and proven exactly, on their mesh as read: seeds are blocks
//   whose patch faces form a closed surface (every edge used an even number of times): a point p near a face of
//   such a block is enclosed by its faces iff a segment from p to a point outside all their vertices crosses them
//   an odd number of times; the block is the enclosed side unless the other patches are enclosed too (then it is
//   the outside, reaching their box; with no other patch, the lower-numbered of the two blocks is the outside, as
//   their code numbers them). From a block A with a proven point a, the neighbour B across a patch P is reached by a point
//   pair p+/p- at either side of a face f of P (f's centroid +- a small step along its normal) whose segment meets
//   no face of the mesh but f, at an interior point: one of p+/p- is in A (decided by the parity of the crossings
//   of segment a-p with A's faces; both points lie in their convex bounding box, which no segment leaves), the
//   other in B. Every decision is an exact rational test; a segment through an edge, a vertex or a face's plane
//   is rejected and another face or step is tried. A block none of whose candidates passes has no point (reported).
//   Each point is then moved deeper: half way from a face's centroid to the first face of the block met along the
//   normal (the deepest over the block's largest patches), kept only when the segment from the first point to it
//   crosses the block's faces an even number of times. Depth matters because our tessellation of a primitive
//   need not be theirs (docs/bsh-3d.md: their spheres have more rings).
// - Each point is located in hsx's arrangement (Arrangement3::locate). Their block labels become a labelling of
//   our cells: a cell is in their solid when the blocks mapped onto it are; cells with none are unmapped, cells
//   with blocks of both labels are conflicts.
// - Their graph cut's known defect: its graph has one edge per patch whose weight is the summed area of all
//   patches between the same two blocks, so a block pair sharing k patches is charged k times. `charged` is their
//   final labelling's cost under that rule, `area` its true boundary area (both exact Measures on their faces).
#pragma once

#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/kernel/measure.hpp>
#include <hsx/kernel/rational.hpp>

#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace hsx {

struct BshReference {
  std::vector<PointQ3> vertices;
  std::vector<std::array<int, 3>> faces;          ///< vertex ids; front = (v1-v0)x(v2-v0)
  std::vector<int> face_implicit;                 ///< empty when the section is absent
  std::vector<std::vector<int>> patch_faces;      ///< per patch its face ids, as listed
  std::vector<int> patch_implicit;                ///< empty when absent
  std::vector<std::vector<int>> block_patches;    ///< per block its patch ids, as listed
  std::vector<int> patch_labels;                  ///< empty when absent
  std::vector<int> block_labels;                  ///< 0 = in their solid
  std::vector<std::array<int, 2>> patch_blocks;   ///< derived: the two blocks of each patch, ascending
  std::vector<char> zero_area;                    ///< derived: per face, 1 when its vertices are collinear
};

/// Bounds on one file (the defaults hold the authors' examples many times over).
struct BshReferenceLimits {
  NumberLimits numbers{64, 400};      ///< per coordinate
  std::size_t max_vertices = 2'000'000;
  std::size_t max_faces = 4'000'000;
  std::size_t max_patches = 200'000;
  std::size_t max_blocks = 200'000;
  std::size_t max_line_entries = 4'000'000;  ///< ids on one line
};

/// Parses the text of a reference-result.grid; `name` prefixes messages. Throws InputError.
BshReference read_bsh_reference(const std::string& text, const std::string& name,
                                const BshReferenceLimits& limits = {});
/// read_file + read_bsh_reference (messages prefixed with the path).
BshReference read_bsh_reference_file(const std::string& path, const BshReferenceLimits& limits = {});

/// A decimal and a closed-form-free exact value of a measure for reports.
struct BshAreaFigure {
  Measure exact;
  std::string decimal;  ///< 9 significant digits ("~" when not certified)
};

/// One of their blocks located in our arrangement.
struct BshBlockMapping {
  std::optional<PointQ3> point;  ///< proven strictly inside the block (unset: none found)
  int cell = -1;                 ///< our cell holding `point`; -1 when no point or the point is on our boundary
  int label = 1;                 ///< their label: 0 in their solid
};

/// The comparison of their result with our arrangement (see the conventions).
struct BshReferenceComparison {
  int their_patches = 0, their_blocks = 0, their_solid_blocks = 0, their_boundary_patches = 0;
  int their_empty_blocks = 0;     ///< blocks listed with no patch (no point can be found for them)
  int their_zero_area_faces = 0;  ///< faces with collinear vertices (left out of every test)
  int our_patches = 0, our_cells = 0;
  std::vector<BshBlockMapping> blocks;
  int blocks_without_point = 0, blocks_on_our_boundary = 0;
  /// Our cells with more than one of their blocks: {cell, blocks...}.
  std::vector<std::vector<int>> shared_cells;
  /// Per our cell: 1 in their solid, 0 outside, -1 unmapped, -2 conflicting labels.
  std::vector<int> mapped_labels;
  int unmapped_cells = 0, conflicting_cells = 0;
  /// Their block pairs sharing k >= 2 patches: {block a, block b, k}.
  std::vector<std::array<int, 3>> multi_patch_pairs;
  /// The same for our cells (pairs of cells sharing several patches).
  int our_multi_patch_pairs = 0;
  /// Multi-patch block pairs with one block in and one out of their solid (the pairs the defect charges).
  int charged_multi_patch_pairs = 0;
  BshAreaFigure their_area;     ///< true boundary area of their solid, on their faces
  BshAreaFigure their_charged;  ///< their graph cut's cost of that solid (the defect)
  std::optional<BshAreaFigure> our_area_mapped;  ///< boundary area on our cells under the mapped labelling (unset
                                                 ///< when a cell is unmapped or conflicting)
  /// With our labelling (compare_bsh_reference's `ours`): cells on which it agrees with the mapped labelling,
  /// cells where it differs, and our boundary area.
  std::optional<int> agreeing_cells, differing_cells;
  std::optional<BshAreaFigure> our_area;
};

/// Compares `reference` with `arranged` (built from the same config.json). `ours` is an optional labelling of our
/// cells (1 = in our solid), e.g. from bsh::extract or an hsx-result/1 file; empty: no agreement figures.
BshReferenceComparison compare_bsh_reference(const BshReference& reference, const Arranged3& arranged,
                                             const std::vector<char>& ours = {});

/// The comparison as a JSON object (format "hsx-bsh-reference/1"); `name` names the example.
nlohmann::json bsh_reference_to_json(const BshReferenceComparison& comparison, const std::string& name);
/// The comparison as a text table for a terminal.
std::string bsh_reference_table(const BshReferenceComparison& comparison, const std::string& name);

}  // namespace hsx
