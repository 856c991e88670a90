// Whole-plane evaluation: a cell-based check only sees sign vectors that some cell has, and a scene's own domain
// may hide some (a region outside the box whose sign vector no cell inside has). Arranging the same scene in a
// domain that holds every vertex of the arrangement makes every sign vector of the plane some cell's.
#pragma once

#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/geometry/scene.hpp>

#include <vector>

namespace hsx {

/// The scene (samples dropped) in a domain that contains its own domain and the one hsx would choose
/// (choose_domain: every vertex of the arrangement strictly inside); validated and resolved.
/// @param[in] scene  a validated scene
Scene2 whole_plane_scene(const Scene2& scene);

/// A bounded solid of `from` carried to `to`, the arrangement of the same scene in a larger domain: inner cells of
/// `from` are cells of `to` unchanged (only the box edges moved), found by exact point location; any other cell of
/// `to` is outside.
/// @param[in] from   the scene's arrangement in its own domain
/// @param[in] solid  #from cells flags, 1 = inside; no outer cell may be inside
/// @param[in] to     the same scene arranged in a domain containing from's (whole_plane_scene)
/// @return  #to cells flags
/// Throws std::logic_error if the counts do not match (a solid touching `from`'s box).
std::vector<char> carry_to_whole_plane(const Arranged2& from, const std::vector<char>& solid, const Arranged2& to);

}  // namespace hsx
