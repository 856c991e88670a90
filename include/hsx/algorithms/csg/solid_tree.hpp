// A halfspace CSG tree for a solid given as cells: BHC (algorithms/csg/bhc.hpp), on a 2D scene with the
// preference for planar halfspaces and, when asked and needed, separators (algorithms/csg/separators.hpp) first.
//
// Outcomes (what `hsx csg` reports, exit codes in parentheses):
//   a tree was built and verified on every cell (0);
//   the solid is not describable by the halfspaces, separators included when asked: no tree (3);
//   a tree was built but fails verification: an internal error (1).
#pragma once

#include <hsx/algorithms/csg/bhc.hpp>
#include <hsx/algorithms/csg/separators.hpp>
#include <hsx/algorithms/csg/separators3.hpp>

#include <optional>
#include <vector>

namespace hsx::csg {

/// Per halfspace of `scene`: 1 when its boundary is a line (a half-plane), the BhcOptions::planar preference.
std::vector<char> planar_halfspaces(const Scene2& scene);

/// Per halfspace of `scene`: 1 when it is a plane, the BhcOptions::planar preference in 3D.
std::vector<char> planar_halfspaces(const Scene3& scene);

struct SolidTreeOptions {
  bool separators = false;  ///< when the solid is not describable, add separators and retry
  int max_separators = 8;   ///< at most this many (>= 0)
};

struct SolidTree {
  /// BHC on the input's complex, or on separated->arranged.complex when separators were tried.
  BhcResult bhc;
  /// The solid's describability on that same complex (its mixed terms when not describable).
  Describability describability;
  /// Set when separators were tried: asked for, and the solid was not describable by the scene's halfspaces.
  std::optional<SeparatedSolid> separated;
  /// The same for a 3D scene (separating planes).
  std::optional<SeparatedSolid3> separated3;
  /// True iff there is a verified tree (bhc.tree) of the solid.
  bool has_verified_tree() const { return bhc.describable && bhc.verified; }
};

/// The tree of a solid on a complex without geometry (e.g. read from an hsx-complex/1 document): plain BHC.
/// - `complex`: any complex; `solid`: per cell, 1 inside.
SolidTree build_tree(const Complex& complex, const std::vector<char>& solid);

/// The tree of a solid on a 2D scene: BHC preferring half-planes; when not describable and options.separators,
/// add_separators and BHC again on the refined scene.
/// - `scene`, `arranged`: a validated scene and arrange(scene); `solid`: per cell of arranged.complex, 1 inside.
SolidTree build_tree(const Scene2& scene, const Arranged2& arranged, const std::vector<char>& solid,
                     const SolidTreeOptions& options);

/// The tree of a solid on a 3D scene: BHC preferring planes; when not describable and options.separators,
/// add_separators (separators3.hpp, trial arrangements within `limits`) and BHC again on the refined scene.
/// - `scene`, `arranged`: a validated 3D scene and arrange(scene); `solid`: per cell of arranged.complex, 1 inside.
SolidTree build_tree(const Scene3& scene, const Arranged3& arranged, const std::vector<char>& solid,
                     const SolidTreeOptions& options, const ArrangementLimits& limits = {});

}  // namespace hsx::csg
