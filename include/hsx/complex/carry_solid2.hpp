// A 2D solid (a set of cells of one arrangement) carried to another arrangement of a related scene, by exact point
// location of the target cells' witness points (ArrFace2::interior):
// - to a refinement: the same scene with halfspaces added (or complemented copies), same domain;
// - to the whole plane: the same halfspaces in a larger domain that holds every arrangement vertex strictly inside,
//   so that every sign vector the plane realises is some cell's (cell-based checks then decide the plane).
// Solids are per-cell vectors, 1 inside, in the arrangement's face order (= the complex's cell order).
#pragma once

#include <hsx/complex/from_arrangement2.hpp>

#include <vector>

namespace hsx {

/// The solid carried to a refinement.
/// - `old_arrangement`: the arrangement `solid` labels (size = its face count);
/// - `refined`: an arrangement of the same domain whose boundaries include every boundary of `old_arrangement`,
///   so each of its cells lies inside one old cell.
/// Returns one entry per face of `refined`. Throws std::logic_error if a refined witness is not inside an old
/// cell (the arrangements are not related that way).
std::vector<char> carry_solid_over(const Arrangement2& old_arrangement, const std::vector<char>& solid,
                                   const Arrangement2& refined);

/// The scene (samples dropped) in a domain that contains its own domain (when given) and the one hsx would
/// choose (choose_domain: every arrangement vertex strictly inside), validated. In that domain every sign vector
/// of the plane is some cell's, and the cells added by enlarging touch only the box.
Scene2 whole_plane_scene(const Scene2& scene);

/// A bounded solid of `from` carried to `to`, the arrangement of the same halfspaces in a larger domain (e.g.
/// whole_plane_scene): inner cells of `from` are cells of `to` unchanged (only the box edges moved), found by
/// exact point location; any other cell of `to` is outside. Returns one entry per cell of `to`.
/// Throws std::logic_error if the inside counts do not match (a solid touching `from`'s box).
std::vector<char> carry_to_whole_plane(const Arranged2& from, const std::vector<char>& solid, const Arranged2& to);

}  // namespace hsx
