// A 3D solid (a set of cells of one arrangement) carried to the arrangement of the same halfspaces in a larger
// domain, by exact point location of the target cells' interior points (ArrCell3::interior): the 3D twin of
// carry_solid2.hpp's whole-plane part.
#pragma once

#include <hsx/complex/from_arrangement3.hpp>

#include <vector>

namespace hsx {

/// The scene (samples dropped) in a domain that contains its own domain and the one hsx would choose
/// (choose_domain3: every surface vertex and every point where three planes meet strictly inside, every plane
/// crossing it), validated; infinite cylinders are clipped again to the new box. Every vertex of the arrangement
/// of the planes and surfaces then lies inside the box (a vertex made by an infinite cylinder's lateral planes and
/// the other planes outside both boxes is the one exception: such cylinders are clipped, not extended, by choice).
/// Returns the scene unchanged (but for samples) when its domain already contains the chosen one.
Scene3 whole_space_scene3(const Scene3& scene);

/// A bounded solid of `from` carried to `to`, the arrangement of the same halfspaces in a domain containing
/// `from`'s (e.g. whole_space_scene3): inner cells of `from` are cells of `to` unchanged; a cell of `to` is inside
/// iff its interior point lies in a solid cell of `from`. Returns one entry per cell of `to`. Throws
/// std::logic_error if the inside counts do not match (a solid touching `from`'s box), std::invalid_argument for
/// a wrong size.
std::vector<char> carry_to_whole_space(const Arranged3& from, const std::vector<char>& solid, const Arranged3& to);

}  // namespace hsx
