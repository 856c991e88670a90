// Solids for the CSG commands: a labelling of a scene's cells, given as a BSH result or a CSG expression, and the
// 2D separators that make a non-describable solid describable.
#pragma once

#include <hsx/algorithms/csg/bhc.hpp>
#include <hsx/complex/whole_plane.hpp>
#include <hsx/io/input.hpp>

#include <string>
#include <vector>

namespace hsx::cli {

struct SolidSource {
  std::string shape_path;  ///< an hsx-result/1 file computed from the same scene
  std::string csg;         ///< an expression: text, or a JSON file holding one
};

struct Solid {
  std::vector<char> cells;  ///< per cell: 1 inside
  csg::ExprPtr expression;  ///< set when given as --csg
};

/// Exactly one of shape_path / csg must be set (InputError otherwise).
Solid load_solid(const LoadedInput& in, const SolidSource& source);

/// Per halfspace: its boundary is a line (BHC prefers those for partitioning).
std::vector<char> planar_halfspaces(const Scene2& scene);

/// The solid carried over to an arrangement of the same scene with more (or complemented) halfspaces: each
/// refined cell lies inside one old cell, found by exact point location of its witness.
std::vector<char> carry_solid_over(const Arrangement2& old_arrangement, const std::vector<char>& solid,
                                   const Arrangement2& refined);

/// 2D separators (Shapiro-Vossler): half-planes added to the scene until the solid is describable. Candidates
/// are lines through pairs of rational arrangement vertices, the radical axes of pairs of circles (through their
/// intersection points), and lines through pairs of cell witness points of mixed terms; each round adds the one
/// that leaves the fewest mixed terms (then fewest mixed cells, then the first), checked by re-arranging exactly.
struct SeparatedSolid {
  Scene2 scene;             ///< the input scene plus the separators (named "sep0", "sep1", ...)
  Arranged2 arranged;
  std::vector<char> cells;  ///< the same solid on the refined arrangement
  int separators = 0;
  bool describable = false;
};
SeparatedSolid add_separators(const Scene2& scene, const Arranged2& arranged, const std::vector<char>& solid,
                              int max_separators = 8);

/// Whole-plane evaluation (complex/whole_plane.hpp; moved to the library).
using hsx::carry_to_whole_plane;
using hsx::whole_plane_scene;

}  // namespace hsx::cli
