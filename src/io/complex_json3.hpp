// The 3D parts of hsx-complex/1 (layout and checks in include/hsx/io/complex_json.hpp). Private to io.
#pragma once

#include "io/complex_json_detail.hpp"

#include <hsx/geometry/arrangement3.hpp>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <vector>

namespace hsx::complex_json_detail {

/// "domain" of a 3D document: min below max in every coordinate.
Box3 read_domain3(const JsonField& f);
/// "geometry" of a 3D document: vertices and triangles with every check that needs no cells (each triangle
/// non-degenerate, two different sides, -1 only on the box, halfspaces ascending; every cell closed). Sets
/// doc.vertices3, doc.triangles3, doc.has_geometry.
void read_geometry3(const JsonField& g, const Names& names, std::size_t cell_count, ComplexDocument& doc);
/// Exact cell volumes from the triangles (read_geometry3 must have run).
std::vector<Rational> geometry3_volumes(const ComplexDocument& doc, std::size_t cell_count);
/// After the cells are read: the cells on each triangle's sides lie on the sides its halfspaces say.
void check_triangle_sides3(const JsonField& triangles, const ComplexDocument& doc);
/// A patch's exact area from its triangles ("pieces"), each checked to carry its halfspace and separate its cells.
Measure patch_area3(const JsonField& patch_field, const Patch& patch, const ComplexDocument& doc, Budget& budget);
/// Writing: the geometry section and the domain of a 3D document.
nlohmann::json geometry3_json(const Complex& complex, const Arrangement3& geometry);
nlohmann::json box3_json(const Box3& box);
/// Distinct undirected edges of a triangle list (the "edges" count of a 3D document).
std::size_t edge_count3(const std::vector<ArrTriangle3>& triangles);

}  // namespace hsx::complex_json_detail
