// 3D separators (Shapiro and Vossler; Buchele and Crawford, Sec. 5 and Fig. 11): planes added to a 3D scene until a
// solid that its halfspaces cannot describe becomes describable.
//
// A solid is not describable when a canonical intersection term (a sign vector) holds an inside and an outside
// cell (algorithms/csg/describability.hpp). A separator is a plane { x : normal . x <= offset } that splits such
// terms. Candidates of one round, from the mixed terms of the current arrangement, in this order (planes equal up to
// a non-zero factor of either sign kept once, at their first occurrence; planes of the scene's own plane halfspaces,
// and planes that do not cross the domain box's interior, dropped):
//   1. FacePlane: the supporting planes of the arrangement triangles bounding the mixed terms' cells (inside cells
//      first, then outside cells; cells in term order, triangles in arrangement order);
//   2. EdgeVertex: planes through an arrangement edge and a vertex, for each mixed term: the edges where an inside
//      and an outside cell of the term meet (an edge with a triangle of each among its triangles; Fig. 11's tangent
//      lines), and every vertex of those edges not on the edge's line (edges in arrangement order, vertices
//      ascending);
//   3. Bisector: perpendicular bisector planes of the witness points (ArrCell3::interior) of an inside and an
//      outside cell of each mixed term.
// Each candidate gets a prediction, exact but cheap: per mixed term, each cell is on the plane's negative side, on its
// positive side (all its boundary vertices on that closed side) or crossed. A term with a crossed cell is predicted
// unchanged; otherwise its cells split by side, and a side holding only inside or only outside cells frees them (they
// no longer share a sign vector with a cell of the other kind); the term is resolved when both sides are freed. For
// a term none of whose cells is crossed the prediction is exact (those cells stay whole and take the plane's side,
// and no term without mixed cells becomes mixed); a crossed term may in fact gain or lose cells.
// Candidates predicted to free no cell are not arranged. The others are arranged in order of prediction (most
// resolved terms first, then most freed cells; ties in candidate order):
// the scene plus the plane, arranged exactly (complex/from_arrangement3.hpp), the solid carried over (each new cell
// is inside iff the old cell holding its interior point, Arrangement3::locate, was). The first trial that achieves the
// best prediction (as many fewer mixed terms and mixed cells) is kept at once; otherwise every predicted candidate is
// arranged, at most kMaxPlaneTrials per round (each trial is a whole 3D arrangement), and the best kept (fewest
// mixed terms, then fewest mixed cells, then the first). When the best reduces neither the mixed terms nor the mixed
// cells, no candidate separates and the search stops. A candidate whose arrangement is
// refused (a sample on an edge where boundaries meet, a limit) is recorded as rejected and skipped.
#pragma once

#include <hsx/algorithms/csg/describability.hpp>
#include <hsx/algorithms/csg/separators.hpp>  // SeparatorStop
#include <hsx/complex/from_arrangement3.hpp>

#include <string>
#include <utility>
#include <vector>

namespace hsx::csg {

/// At most this many candidates are arranged per round (in prediction order); the others are not tried.
inline constexpr int kMaxPlaneTrials = 64;

enum class PlaneOrigin { FacePlane, EdgeVertex, Bisector };
const char* to_string(PlaneOrigin origin);  ///< "face-plane", "edge-vertex", "bisector"

/// The halfspace { x : normal . x <= offset }; normal is non-zero.
struct SeparatorPlane {
  PointQ3 normal;
  Rational offset;
  PlaneOrigin origin = PlaneOrigin::FacePlane;
};

/// One candidate of one round and what became of it.
struct PlaneTrial {
  SeparatorPlane plane;
  int predicted_terms = 0;  ///< mixed terms the prediction says it resolves
  int predicted_cells = 0;  ///< mixed terms' cells the prediction says it frees (> 0 for every trial)
  bool arranged = false;   ///< false: rejected by the arrangement (`rejection` says why), or not reached
  std::string rejection;   ///< the arrangement's message when rejected
  int mixed_terms = -1;    ///< after adding it (arranged only)
  int mixed_cells = -1;    ///< inside plus outside cells of the mixed terms after adding it (arranged only)
  bool separated = false;  ///< arranged, and fewer mixed terms or fewer mixed cells than before the round
  bool chosen = false;     ///< the one added in this round
};

struct PlaneRound {
  int mixed_terms = 0, mixed_cells = 0;  ///< before the round
  int candidates = 0;                    ///< distinct candidate planes generated
  int predicted = 0;                     ///< of them, predicted to resolve some term (the others not arranged)
  std::vector<PlaneTrial> trials;        ///< the candidates arranged (or rejected), in the order tried
};

/// The candidate planes of one round, deduplicated, in the order of the header comment.
/// - `scene`, `arranged`: a validated 3D scene and arrange(scene);
/// - `mixed`: the solid's describability on arranged.complex.
std::vector<SeparatorPlane> separator_candidates(const Scene3& scene, const Arranged3& arranged,
                                                 const Describability& mixed);

/// The prediction for `plane` on `arranged` (see the header comment): (mixed terms of `mixed` resolved, cells freed).
std::pair<int, int> predicted_resolved(const Arranged3& arranged, const Describability& mixed,
                                       const SeparatorPlane& plane);

/// The solid `solid` (per cell of `from`) carried to `to`, an arrangement of the same scene with more halfspaces:
/// each cell of `to` is inside iff the cell of `from` holding its interior point is. Throws std::logic_error when
/// an interior point of `to` is not inside a cell of `from` (`to` does not refine `from`).
std::vector<char> carry_solid3(const Arranged3& from, const std::vector<char>& solid, const Arranged3& to);

struct SeparatedSolid3 {
  Scene3 scene;             ///< the input scene plus the separators, planes named "sep0", "sep1", ... (appended)
  Arranged3 arranged;       ///< arrange(scene)
  std::vector<char> cells;  ///< the same solid on arranged.complex, per cell, 1 inside
  int separators = 0;       ///< planes added
  bool describable = false;
  SeparatorStop stop = SeparatorStop::Describable;
  std::vector<PlaneRound> rounds;  ///< one per round run, in order
};

/// Adds separating planes, at most `max_separators` (>= 0), until `solid` is describable.
/// - `scene`, `arranged`: a validated 3D scene and arrange(scene, limits);
/// - `solid`: per cell of arranged.complex, 1 inside;
/// - `limits`: the arrangement limits for every trial arrangement.
/// Never throws on a non-describable result: see `describable` and `stop`.
SeparatedSolid3 add_separators(const Scene3& scene, const Arranged3& arranged, const std::vector<char>& solid,
                               int max_separators = 8, const ArrangementLimits& limits = {});

}  // namespace hsx::csg
