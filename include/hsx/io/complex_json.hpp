// The `hsx-complex/1` document: a complex (complex/complex.hpp), optionally with the exact 2D or 3D arrangement it
// came from, as JSON. Written by hsx for inspection and read back so that another implementation can hand hsx its own
// arrangement.
//
// Layout (every rational is an exact string such as "-7/3"; one-root numbers are strings "a", "a + b*sqrt(c)",
// "a - b*sqrt(c)", "b*sqrt(c)"; ids are array positions):
//   {
//     "format": "hsx-complex/1", "dimension": 2,
//     "halfspaces": ["A", "B"],
//     "domain": {"min": [x, y], "max": [x, y]},                       (optional; [x, y, z] in 3D)
//     "counts": {"cells", "outer_cells", "patches", "junctions", "samples", ["vertices", "edges"],
//                ["triangles" (3D)]},                                            (optional)
//     "cells":     [{"id", "outer", "witness": [x, y], "inside": [names], "measure": M}],
//     "patches":   [{"id", "halfspace": name, "inside_cell", "outside_cell", "measure": M, "samples": count,
//                    "sample_ids": [...], "support", "junctions": [...], "pieces": [edge ids]}],
//     "supports":  [[patch ids], ...],
//     "junctions": [{"id", "patches": [...], "vertex": id}],
//     "samples":   [{"id", "halfspace": name, "patch"}],
//     "geometry":  {"vertices": [{"id", "point": [x, y], "degree"}],
//                   "edges": [{"id", "source", "target", "halfspaces": [names], "on_box", "left_face",
//                              "right_face", "shape": "segment" | "arc", ("center", "radius", "ccw")}],
//                   "faces": [{"id", "boundary": [[[edge, forward], ...], ...]}]}               (optional, 2D)
//     "geometry":  {"vertices": [[x, y, z], ...],                                                    (optional, 3D)
//                   "triangles": [{"vertices": [a, b, c], "halfspaces": [names], "front_inside": [bools],
//                                  "on_box", "front_cell", "back_cell"}]}
//   }
// In 3D, patch "pieces" are triangle ids and the triangle conventions are Arrangement3's (geometry/arrangement3.hpp):
// the front of [a, b, c] is the side (b - a) x (c - a) points to, cell -1 is outside the domain, `front_inside[k]`
// says whether halfspaces[k]'s inside is on the front. Junctions carry no "vertex" in 3D.
// A measure M is {"decimal": "<30 significant digits>", "exact": "<closed form>" | null}.
//
// Reading (complex_from_json) is strict: unknown fields, wrong types, out-of-range indices, unknown halfspace names
// and inconsistent lists are InputErrors naming the JSON path ("patches[1].inside_cell: ..."); the result also
// passes check_complex. Optional on input: "id" (checked against the position when present), "domain", "counts"
// (checked when present), "supports" (absent: every patch is its own group), patch "support", "samples",
// "sample_ids" and "junctions" (derived from the other lists when absent, checked when present), junction "vertex",
// "junctions", "samples", "geometry", "witness", "pieces".
// With a 3D geometry section the reader also checks that every triangle is non-degenerate and separates two
// different cells (or a cell and the outside, on the box only), that the cells on its two sides are on the sides
// its halfspaces say, that every cell's triangles form closed surfaces (each edge traversed as often in both
// directions), and that each patch's triangles carry its halfspace and separate its two cells.
// Measures:
//   - with "geometry", patch lengths (areas) and cell areas (volumes) are recomputed exactly from it
//     (planar_measures.hpp in 2D; in 3D sums of sqrt(q)/2 and signed tetrahedra), and a given "exact" or
//     "decimal" must agree with the recomputed value (else an error naming the patch or cell);
//   - without it, "exact" is used when present (a closed form: a sum of terms q, q*sqrt(m), sqrt(m) with rationals
//     q and m >= 0); otherwise "decimal" is taken as exactly that decimal (0.1 means 1/10). When both are given,
//     the decimal must agree with the exact value.
//   - a decimal agrees with a value when they differ by at most one unit in its last written digit, where at least
//     6 and at most 60 significant digits are considered ("3.14" does not agree with pi; "3.14159" does).
//   - shorthand: a measure written as a number or a string is read as {"exact": ...}.
#pragma once

#include <hsx/complex/complex.hpp>
#include <hsx/geometry/arrangement2.hpp>
#include <hsx/geometry/arrangement3.hpp>
#include <hsx/geometry/scene.hpp>
#include <hsx/kernel/measure.hpp>
#include <hsx/kernel/one_root.hpp>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hsx {

inline constexpr const char* kComplexFormat = "hsx-complex/1";

/// The document for `complex`; `geometry` (the arrangement the complex was built from, with Patch::pieces and
/// Junction::piece referring to it) and `domain` may be null. Deterministic: the same input gives the same JSON.
nlohmann::json complex_to_json(const Complex& complex, const Arrangement2* geometry, const Box2* domain);

/// complex_to_json(...).dump(2) + "\n", byte for byte, written without building the cells' part of the document
/// in memory: the cells list every halfspace each one is inside (cells x halfspaces names), which dominates
/// large documents and costs about 5 times less as text than as a JSON tree.
std::string complex_json_text(const Complex& complex, const Arrangement2* geometry, const Box2* domain);

/// The same for a complex of dimension 3, with the 3D arrangement it came from (may be null) and its domain (may be
/// null).
nlohmann::json complex3_to_json(const Complex& complex, const Arrangement3* geometry, const Box3* domain);
/// complex3_to_json(...).dump(2) + "\n", byte for byte, written as complex_json_text is.
std::string complex3_json_text(const Complex& complex, const Arrangement3* geometry, const Box3* domain);

/// A complex read from a document, with what else it held.
struct ComplexDocument {
  Complex complex;
  std::optional<Box2> domain;   ///< 2D documents
  std::optional<Box3> domain3;  ///< 3D documents
  bool has_geometry = false;
  /// The "geometry" section as arrangement data (face `inside`, `outer` and `interior` taken from the cells).
  /// Empty without geometry.
  std::vector<ArrVertex2> vertices;
  std::vector<ArrEdge2> edges;
  std::vector<ArrFace2> faces;
  /// Exact length of each of `edges` and area of each of `faces`, recomputed from the geometry (empty without).
  std::vector<Measure> edge_lengths, face_areas;
  /// The 3D "geometry" section: vertices and triangles (front_cell/back_cell, halfspaces, front_inside, on_box,
  /// area2 recomputed). Empty without geometry or in 2D.
  std::vector<PointQ3> vertices3;
  std::vector<ArrTriangle3> triangles3;
};

/// Reads and validates a document (see the header comment). Throws InputError naming the JSON path.
/// Numbers may be JSON integers, exact-number markers (io/exact_json.hpp) or strings.
ComplexDocument complex_document_from_json(const nlohmann::json& document);
Complex complex_from_json(const nlohmann::json& document);
/// Reads a file with parse_exact_json; errors are prefixed with the path.
Complex read_complex_file(const std::string& path);

/// "a", "a + b*sqrt(c)", "a - b*sqrt(c)", "b*sqrt(c)", "sqrt(c)", "-sqrt(c)" with rationals a, b and c >= 0
/// (spaces optional). nullopt and *why set otherwise.
std::optional<OneRoot> parse_one_root(std::string_view text, std::string* why = nullptr);

/// A closed form: a sum of terms q, q*sqrt(m), sqrt(m), q*pi, pi, each optionally negated, with rationals q, m >= 0
/// ("1/2 + 3*sqrt(2) - sqrt(5)", "4/3*pi + 1/2*sqrt(3)"). Nested radicals are not accepted; nullopt, *why set.
std::optional<Measure> parse_closed_form(std::string_view text, std::string* why = nullptr);

}  // namespace hsx
