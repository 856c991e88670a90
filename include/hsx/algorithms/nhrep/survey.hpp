// The NH-Rep survey (hsx nhsurvey; proofs/nhrep.md "Rates", Section 5b for 3D): one 2D (or, survey_solid3, 3D)
// solid through the pipeline
// boundary_from_arrangement2 -> build_patch_graph -> build_tree -> check_tree -> evaluate_tree, classified as
// "tree correct", "describable but the tree fails" (NH-Rep needs its extended surfaces, Appendix B) or "not
// describable by its patches' halfspaces", and the per-source tallies of many such solids.
//
// Whole-plane evaluation (a convention of the survey): a cell-based check only sees sign vectors that some cell
// has. A surveyed solid should therefore be given on an arrangement where every sign vector of the plane is some
// cell's (the scene in a domain containing every vertex strictly inside, e.g. the domain choose_domain picks);
// when the source has its own smaller domain (BSH scenes, CSGNet), the same solid on that domain can be given as
// well (`own_arranged`), and the survey counts the verdicts that change there.
#pragma once

#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/algorithms/csg/random_solid.hpp>
#include <hsx/algorithms/nhrep/evaluate.hpp>
#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/complex/from_arrangement3.hpp>

#include <functional>

#include <optional>
#include <string>
#include <vector>

namespace hsx::nhrep {

/// One solid to survey. The survey reads `arranged`, `solid`, `own_arranged` and `own_solid`; the other fields
/// label the solid and are kept for reports and examples (io/nhrep_survey.hpp).
struct SurveySolid {
  std::string name;           ///< unique within a run (names kept example files)
  std::string origin;         ///< where it came from, for notes
  Scene2 scene;               ///< the scene of `arranged` (samples dropped)
  Arranged2 arranged;         ///< whole-plane arrangement (header comment)
  std::vector<char> solid;    ///< per cell of arranged.complex, 1 inside
  csg::ExprPtr expression;    ///< the source's own expression over scene's halfspaces, when it has one
  std::optional<Arranged2> own_arranged;  ///< the solid's own-domain arrangement, when it differs
  std::vector<char> own_solid;            ///< per cell of own_arranged->complex
};

/// The pipeline on one arrangement.
struct PipelineRun {
  std::vector<std::string> problems;  ///< violated structural checks and pipeline errors ("check_tree: ...",
                                      ///< "evaluation: ...", "error: <what()>")
  bool evaluated = false;             ///< evaluate_tree ran (false after an exception)
  BuildResult built;
  Evaluation eval;
};

/// Runs the pipeline on `solid` (one flag per cell of arranged.complex). Never throws for the pipeline's own
/// exceptions (std::exception): they become an "error: " problem with evaluated = false.
PipelineRun run_pipeline(const Arranged2& arranged, const std::vector<char>& solid, const BuildOptions& options);

/// The same pipeline on any boundary: `boundary` builds the solid's BoundarySurface (called inside the pipeline's
/// guard, so its exceptions become problems too); `complex` holds the cells the tree is evaluated on. Dimension-free.
PipelineRun run_pipeline_on(const std::function<BoundarySurface()>& boundary, const Complex& complex,
                            const std::vector<char>& solid, const BuildOptions& options);

/// What the survey found for one solid.
struct SurveyOutcome {
  csg::SolidStatus status = csg::SolidStatus::Empty;  ///< empty and unbounded solids are not run
  PipelineRun whole;                 ///< on SurveySolid::arranged (when status is Bounded)
  std::optional<PipelineRun> own;    ///< on own_arranged, when given (and status is Bounded)
  /// whole.problems, then own's prefixed "on the scene's own domain: "; non-empty means a structural check
  /// failed (or the pipeline threw).
  std::vector<std::string> problems;
  int holes = 0;                     ///< holes of the solid (count_holes), when status is Bounded
  bool own_differs = false;          ///< both evaluated and the own-domain verdict differs from whole's
};

/// Surveys one solid: its status, the pipeline on the whole-plane and (when given) own-domain arrangements, its
/// holes. `options` go to build_tree. Throws std::invalid_argument when `solid` (or `own_solid`) does not have one
/// flag per cell.
SurveyOutcome survey_solid(const SurveySolid& solid, const BuildOptions& options = {});

/// One 3D solid to survey (hsx nhsurvey --dimension 3): `arranged` must hold every vertex (a domain chosen by
/// hsx, as random_solid3 gives), so that every sign vector of space is some cell's.
struct SurveySolid3 {
  std::string name, origin;
  Scene3 scene;
  Arranged3 arranged;
  std::vector<char> solid;    ///< per cell of arranged.complex
  csg::ExprPtr expression;    ///< when the source has one
};

/// Surveys one 3D solid: boundary_from_arrangement3 -> build_patch_graph -> build_tree -> check_tree ->
/// evaluate_tree on arranged.complex, and its holes (cavities and tunnels' voids: count_holes). No own domain.
SurveyOutcome survey_solid3(const SurveySolid3& solid, const BuildOptions& options = {});

/// Holes of a solid (one flag per cell of `complex`): connected components of non-solid cells (adjacent across a
/// patch) that contain no outer cell.
int count_holes(const Complex& complex, const std::vector<char>& solid);

/// Counts of one source's solids (a row of hsx nhsurvey's table).
struct SurveyTally {
  explicit SurveyTally(std::string name, int max_examples = 3) : source(std::move(name)), max_examples(max_examples) {}
  std::string source;
  int max_examples;         ///< names of at most this many describable-but-fails solids are kept in `examples`
  long solids = 0;          ///< bounded solids run (evaluated or failed)
  long empty = 0, unbounded = 0, malformed = 0;  ///< skipped (malformed: counted by the caller)
  long check_failures = 0;  ///< solids with a violated structural check or a pipeline error
  long decomposed = 0, decompositions = 0;
  long correct = 0, describable_fails = 0, not_describable = 0;
  long fails_with_holes = 0;  ///< describable-but-fails solids that have a hole
  long with_holes = 0;        ///< evaluated solids with a hole (2D) or cavity (3D)
  long correct_with_holes = 0, not_describable_with_holes = 0;  ///< of those, by verdict
  long own_domain_runs = 0, own_domain_differs = 0;
  long patches = 0, cells = 0;
  double seconds = 0;                 ///< filled by the caller
  std::vector<std::string> examples;  ///< "name (origin)" of the first describable-but-fails solids
  std::string note;                   ///< set by the caller instead of counts, e.g. "skipped: corpus not present"

  /// Counts one surveyed solid. Returns true when it was added to `examples`.
  bool add(const SurveySolid& solid, const SurveyOutcome& outcome);
  /// The same for any solid: `label` is "name (origin)" for `examples`, `cells` the evaluated complex's cell count.
  bool add(const std::string& label, std::size_t cells, const SurveyOutcome& outcome);
};

/// The union of the solid's canonical terms over `natural` (halfspace indices of `complex`): an expression equal to
/// the solid when it is describable by them. `solid` has one flag per cell and at least one cell inside
/// (std::invalid_argument otherwise).
csg::ExprPtr canonical_union(const Complex& complex, const std::vector<char>& solid, const std::vector<int>& natural);

/// An expression of a describable-but-fails example over its scene's halfspaces: the source's own expression, or
/// BHC's verified tree, or else the canonical union over the natural halfspaces. Checked exactly against the
/// solid; throws std::logic_error if it differs (or the outcome was not evaluated).
csg::ExprPtr example_expression(const SurveySolid& solid, const SurveyOutcome& outcome);
/// The same for a 3D survey solid.
csg::ExprPtr example_expression(const SurveySolid3& solid, const SurveyOutcome& outcome);

}  // namespace hsx::nhrep
