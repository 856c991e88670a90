// A 3D solid given as a closed triangle mesh whose faces lie on a scene's halfspaces: the solid is the set of the
// scene's cells inside the mesh (docs/csg3.md, "A solid given as a mesh").
#pragma once

#include <hsx/geometry/arrangement3.hpp>
#include <hsx/geometry/mesh3.hpp>

#include <vector>

namespace hsx {

/// Per cell of `arrangement`, 1 if the cell lies inside the closed mesh `mesh`, 0 if outside.
///
/// The mesh must lie on the scene's halfspaces: every point of it on the boundary of some halfspace of `scene`.
/// Decided exactly by arranging the scene once more (samples dropped, the same domain, no volumes) with the mesh
/// as one more halfspace of kind mesh: the mesh lies on the halfspaces iff every triangle of that arrangement
/// carrying the mesh also carries a halfspace of the scene (coincident surfaces share triangles, arrangement3.hpp).
/// The mesh then meets no open cell of `arrangement`: both arrangements have the same open cells, and each cell's
/// side of the mesh is that of the cell of the second arrangement holding its interior point (ArrCell3::interior,
/// located exactly by Arrangement3::locate; about 20 times faster than the mesh's ray parity per cell).
/// A mesh face on the domain box but on no halfspace does not lie on the halfspaces.
///
/// - `scene`: validated (validate_and_resolve), the scene `arrangement` was built from;
/// - `arrangement`: Arrangement3::build(scene, ...);
/// - `mesh`: validated and outward (build_mesh3); messages start with `mesh.source` and name faces and vertices by
///   their 0-based ids and file lines;
/// - `limits`: bounds on the arrangement with the mesh.
/// Throws InputError when a mesh vertex lies outside the domain, when the mesh intersects itself (two of its faces
/// meet away from their shared edges and vertices), when a face is not on the halfspaces (the lowest such face,
/// a point of it on no halfspace, and how many faces are off), or when the arrangement with the mesh outgrows
/// `limits`.
std::vector<char> cells_inside_mesh(const Scene3& scene, const Arrangement3& arrangement, const Mesh3& mesh,
                                    const ArrangementLimits& limits = {});

}  // namespace hsx
