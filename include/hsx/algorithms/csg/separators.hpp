// 2D separators (Shapiro and Vossler): half-planes added to a scene until a solid that its halfspaces cannot
// describe becomes describable.
//
// A solid is not describable when a canonical intersection term (a sign vector) holds an inside and an outside
// cell (algorithms/csg/describability.hpp). A separator is a half-plane whose line splits such terms. Candidates,
// in this order (duplicates, i.e. the same line up to scale and orientation, dropped after the first):
//   1. the supporting lines of polygon edges (the classical Shapiro-Vossler candidates);
//   2. the lines of the scene's half-planes, complemented (for completeness: such a line is already in the
//      arrangement, so it never splits a term on its own);
//   3. lines through pairs of rational arrangement vertices where boundaries meet (degree > 2);
//   4. radical axes of pairs of non-concentric circles (the lines through their intersection points);
//   5. perpendicular bisectors of the witness points of an inside and an outside cell of each mixed term.
// Each round arranges the scene plus each candidate exactly, carries the solid over (complex/carry_solid2.hpp) and
// keeps the candidate that leaves the fewest mixed terms, then the fewest mixed cells, then the first; when that
// one reduces neither the mixed terms nor the mixed cells, no candidate separates and the search stops. Candidates
// whose line passes through a sample (Arrangement2::build rejects it) are skipped.
#pragma once

#include <hsx/algorithms/csg/describability.hpp>
#include <hsx/complex/from_arrangement2.hpp>

#include <vector>

namespace hsx::csg {

/// The half-plane { x : normal . x <= offset }; its line is normal . x = offset. normal is non-zero.
struct SeparatorLine {
  PointQ2 normal;
  Rational offset;
};

/// The candidate lines for one round, deduplicated, in the order of the header comment.
/// - `scene`, `arranged`: a validated scene and its arrangement (arranged = arrange(scene));
/// - `mixed`: the solid's describability on arranged.complex (its mixed terms give the bisector candidates).
std::vector<SeparatorLine> separator_candidates(const Scene2& scene, const Arranged2& arranged,
                                                const Describability& mixed);

enum class SeparatorStop {
  Describable,           ///< the solid is describable (possibly with no separator at all)
  MaxSeparators,         ///< max_separators were added and the solid is still not describable
  NoCandidateSeparates,  ///< in the last round, no candidate reduced the mixed terms or the mixed cells
};

struct SeparatedSolid {
  Scene2 scene;             ///< the input scene plus the separators, named "sep0", "sep1", ... (after its halfspaces)
  Arranged2 arranged;       ///< arrange(scene)
  std::vector<char> cells;  ///< the same solid on arranged.complex, per cell, 1 inside
  int separators = 0;       ///< half-planes added
  bool describable = false;
  SeparatorStop stop = SeparatorStop::Describable;
  int candidates_tried = 0;  ///< candidates arranged in the last round (0 when no round ran)
};

/// Adds separators, at most `max_separators` (>= 0), until `solid` is describable.
/// - `scene`, `arranged`: a validated scene and arrange(scene);
/// - `solid`: per cell of arranged.complex, 1 inside.
/// Never throws on a non-describable result: see `describable` and `stop`.
SeparatedSolid add_separators(const Scene2& scene, const Arranged2& arranged, const std::vector<char>& solid,
                              int max_separators = 8);

}  // namespace hsx::csg
