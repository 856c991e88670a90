// Building halfspaces in code (generators, tests, examples); the conventions are geometry/scene.hpp's.
#pragma once

#include <hsx/geometry/scene.hpp>
#include <hsx/geometry/scene3.hpp>

#include <string>
#include <vector>

namespace hsx {

/// The half-plane { x : normal . x <= offset } named `name` (normal: outward, non-zero, need not be unit),
/// complemented when `complement`. Nothing is validated here (validate_and_resolve does).
Halfspace2 halfplane(const std::string& name, const PointQ2& normal, const Rational& offset, bool complement = false);

/// The half-plane with outward `normal` whose line passes through `through`: offset = normal . through.
Halfspace2 halfplane_through(const std::string& name, const PointQ2& normal, const PointQ2& through,
                             bool complement = false);

/// The closed disk of `center` and `radius` (> 0, checked by validate_and_resolve).
Halfspace2 disk(const std::string& name, const PointQ2& center, const Rational& radius, bool complement = false);

/// The closed region bounded by the simple polygon `vertices` (either order, >= 3 vertices; validate_and_resolve
/// checks simplicity).
Halfspace2 polygon(const std::string& name, std::vector<PointQ2> vertices, bool complement = false);

/// The half-space { x : normal . x <= offset } of 3D named `name` (normal: outward, non-zero, need not be unit),
/// complemented when `complement`: the 3D twin of halfplane. Nothing is validated here (validate_and_resolve3
/// does).
Halfspace3 plane(const std::string& name, const PointQ3& normal, const Rational& offset, bool complement = false);

/// The half-space with outward `normal` whose plane passes through `through`: offset = normal . through.
Halfspace3 plane_through(const std::string& name, const PointQ3& normal, const PointQ3& through,
                         bool complement = false);

}  // namespace hsx
