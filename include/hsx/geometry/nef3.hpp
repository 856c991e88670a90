// An independent count of the cells of a 3D scene's arrangement by CGAL's Nef polyhedra: a test oracle for
// Arrangement3 (geometry/arrangement3.hpp) and the exact reference of `hsx bench`'s 3D entry. It shares no code
// with the arrangement (one CGAL translation unit of its own, src/geometry/cgal_nef3.cpp).
//
// Conventions (owned here):
// - The computation, exact throughout (CGAL::Nef_polyhedron_3 on Epeck):
//     region = interior(domain box) minus the union of every halfspace's boundary,
//   and the cells are the marked volumes of `region` (the connected components of the open box minus all
//   boundaries, as Arrangement3 defines them). A plane's boundary is taken as the boundary of the convex polytope
//   convex_hull_3(halfspace intersected with the box) (its faces on the box are outside the open box, so they
//   remove nothing); a plane that does not cross the open box (the box lies in one closed side of it: it misses
//   the box or only touches a face, an edge or a corner) removes nothing and is skipped. A surface's boundary is
//   the Nef polyhedron of its triangles. `complement` does not matter (a boundary is the same set either way).
// - A cell is outer iff one of the facets bounding it lies on a face of the box (Arrangement3's definition: a
//   boundary triangle on the box; touching the box only along an edge or at a corner does not make a cell outer).
// - Cost (measured on the project's 2-core machine, g++ 12 -O2, shared with other jobs, so figures vary by 2-3x):
//   random planes in general position: 10 planes 1.3-2 s, 20 planes 8-11 s, 30 planes ~19 s; the BSH authors'
//   figure19_b (17 halfspaces, 7,982 triangles) 4-27 s and 130-170 MB peak, at h/2 (15,874 triangles) 22 s and
//   280 MB. It is single-threaded and keeps no source id per facet, so it gives counts only: use it on small
//   scenes in tests; `hsx bench --3d` times it beside Arrangement3.
#pragma once

#include <hsx/geometry/scene3.hpp>

namespace hsx {

struct NefCellCounts {
  long cells = 0;        ///< connected open regions of the box minus every boundary
  long outer_cells = 0;  ///< of which bounded by a facet on the box
  long facets = 0;       ///< halffacet pairs (Nef facets) of the final region, for sizes in reports
};

/// The counts above for `scene`, which validate_and_resolve(Scene3&) must have accepted (its domain is used as
/// given; samples are ignored). Surfaces must be closed and consistently oriented (validated scenes are); a
/// surface CGAL cannot turn into a Nef polyhedron throws std::runtime_error naming the halfspace.
NefCellCounts nef_cell_counts(const Scene3& scene);

}  // namespace hsx
