// Building the complex from an exact 3D arrangement.
#pragma once

#include <hsx/complex/complex.hpp>
#include <hsx/geometry/arrangement3.hpp>
#include <hsx/geometry/scene3.hpp>

namespace hsx {

/// A 3D scene's arrangement and its complex, built together so that pictures and reports can refer from patches
/// (Patch::pieces: triangle ids) back to the arrangement.
struct Arranged3 {
  Arrangement3 arrangement;
  Complex complex;
};

/// Patches are maximal sets of triangles of one halfspace connected across edges that no other boundary meets
/// (edges with exactly two triangles, neither on the box, carrying the same halfspaces); coincident halfspaces
/// share such a set and form a support group (complex.hpp). Patch::pieces are their triangles, ascending; patches
/// are numbered by their lowest triangle, then by halfspace. Triangles on the domain box give no patch. Cells are
/// the arrangement's cells, in the same order. Cell::measure is the volume (zero when volumes were not computed),
/// Patch::measure the exact area (the sum of sqrt(area2) / 2 over its triangles).
/// Junctions: the edges that bound a patch (every edge touching a patch triangle that is not inside a patch),
/// chained through vertices where exactly two such edges meet with the same sheets; Junction::piece is the
/// chain's lowest edge id, Junction::patches every patch whose triangles touch the chain, Junction::sheets the
/// lowest patch of the support group of each patch triangle along one of its edges (sorted).
/// Corners: every arrangement vertex touching a patch triangle, except those inside a patch (one fan that is a
/// whole disc, no junction edge) and those along a junction (two junction edges, every fan from one to the
/// other); spokes in the order of the vertex's edges (by edge id), wedges in order of their first triangle met along those edges.
Complex complex_from_arrangement(const Scene3& scene, const Arrangement3& arrangement);

/// validate_and_resolve(Scene3&) must have been called on `scene`.
Arranged3 arrange(const Scene3& scene, const ArrangementLimits& limits = {},
                  const Arrangement3Options& options = {});

}  // namespace hsx
