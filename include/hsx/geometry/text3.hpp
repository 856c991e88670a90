// 3D points and boxes in messages (InputError texts), as geometry/scene3.cpp writes them.
#pragma once

#include <hsx/geometry/scene3.hpp>

#include <string>

namespace hsx {

/// "[x, y, z]", each coordinate exact, shortened beyond 48 characters ("1234...5678 (60 characters)").
std::string point_text(const PointQ3& p);

/// "[[min], [max]]" in point_text's form.
std::string box_text(const Box3& b);

}  // namespace hsx
