// Kept examples of the NH-Rep survey (algorithms/nhrep/survey.hpp; hsx nhsurvey --keep): a "describable but the
// tree fails" solid written as a scene whose description explains it, and its expression; 2D and 3D.
#pragma once

#include <hsx/algorithms/nhrep/survey.hpp>

#include <string>

namespace hsx {

/// The explanation of a describable-but-fails example: its natural halfspaces, Algorithm 1's tree over them
/// (leaves named "<halfspace>#<patch>", "~" when complemented), the cells it gets wrong (at most 6 listed, with
/// witnesses to 6 significant digits), whether the solid has holes, the decompositions used. `outcome` must have
/// been evaluated (outcome.whole.evaluated; std::logic_error otherwise).
std::string survey_example_note(const nhrep::SurveySolid& solid, const nhrep::SurveyOutcome& outcome);
/// The same for a 3D solid (witnesses with three coordinates; holes are cavities and tunnels' voids).
std::string survey_example_note(const nhrep::SurveySolid3& solid, const nhrep::SurveyOutcome& outcome);

/// Writes `dir`/<solid.name>.json (solid.scene with survey_example_note as its description, hsx-scene/1) and
/// `dir`/<solid.name>.csg ({"description", "csg"}: nhrep::example_expression's text over the scene's halfspace
/// names, readable by --csg), creating `dir`. Throws std::logic_error when the expression is not the solid, and
/// std::runtime_error when a file cannot be written.
void write_survey_example(const std::string& dir, const nhrep::SurveySolid& solid,
                          const nhrep::SurveyOutcome& outcome);
/// The same for a 3D solid: an hsx-scene/1 file of dimension 3 with its domain written out (the one the survey
/// arranged it in, so that the file gives the same cells).
void write_survey_example(const std::string& dir, const nhrep::SurveySolid3& solid,
                          const nhrep::SurveyOutcome& outcome);

}  // namespace hsx
