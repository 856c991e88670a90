// A BSH scene whose samples sit on chosen patches: where GENERATE-SAMPLES (algorithms/bsh/samples.hpp) says "a
// sample on patch p", this places an exact point there, so the scene can be written and read back.
#pragma once

#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/complex/from_arrangement3.hpp>

#include <string>
#include <vector>

namespace hsx::bsh {

/// The scene's halfspaces and domain with `description` and one `at` sample per listed patch (in order), on the
/// patch's middle arrangement edge (pieces[size / 2]) at an exact rational point strictly inside that edge, near
/// its middle. The scene's own samples are dropped.
/// - `scene`, `arranged`: a validated scene and arrange(scene) (the patches are arranged.complex's);
/// - `patches`: patch indices of arranged.complex (std::out_of_range otherwise).
/// Throws std::runtime_error when no rational point can be placed (a segment with irrational ends and no known
/// supporting line; not produced by Arrangement2::build).
Scene2 scene_with_samples(const Scene2& scene, const Arranged2& arranged, const std::vector<int>& patches,
                          const std::string& description);

/// The same in 3D: one `at` sample per listed patch at the centroid of the patch's largest triangle (exact area
/// comparison, ties to the lowest triangle id): a rational point strictly inside one triangle of the patch, so
/// never on an arrangement edge, and `hsx extract` places it on the same patch again.
/// - `scene`, `arranged`: a validated 3D scene and arrange(scene);
/// - `patches`: patch indices of arranged.complex (std::out_of_range otherwise).
Scene3 scene_with_samples(const Scene3& scene, const Arranged3& arranged, const std::vector<int>& patches,
                          const std::string& description);

}  // namespace hsx::bsh
