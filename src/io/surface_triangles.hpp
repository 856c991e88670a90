// The bound on all surfaces' triangles of a 3D scene, shared by its readers (SceneReadLimits::max_surface_triangles).
#pragma once

#include <hsx/io/exact_json.hpp>

#include <cstddef>
#include <string>

namespace hsx {

/// Throws InputError at `halfspace` (the one just read) when the surfaces read so far, `total` triangles in all,
/// pass `limit` (0: no limit).
inline void check_surface_triangles(std::size_t total, std::size_t limit, const JsonField& halfspace) {
  if (limit > 0 && total > limit)
    halfspace.fail("the surfaces so far have " + std::to_string(total) + " triangles, over the limit of " +
                   std::to_string(limit) + " for all of them together (raise it with --max-triangles; see "
                   "docs/limits.md)");
}

}  // namespace hsx
