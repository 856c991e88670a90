// A CSG solid as a BSH scene (BSH paper, Section 6): the samples come from GENERATE-SAMPLES
// (algorithms/bsh/samples.hpp), placed exactly (algorithms/bsh/sample_scene.hpp), and the conversion is checked by
// extracting the scene back.
//
// Orientation rule (Def. 3.1): a BSH boundary runs along every halfspace with that halfspace's orientation (the
// solid on its inside). A solid may run along a boundary reversed (A - B runs along B with the solid outside B):
// such a halfspace is complemented in the BSH scene; when the solid also runs along the same boundary the right way
// somewhere, a complemented copy named "<name>~" (more "~" until unique) is appended instead.
//
// 3D (Scene3, docs/csg3.md): the same rule on the 3D complex (a complemented surface swaps inside and outside, its
// triangles keep their orientation); samples are placed by bsh::scene_with_samples(Scene3...) (the centroid of the
// patch's largest arrangement triangle: an exact rational point in the patch's relative interior, on the
// halfspace's tessellated boundary, so an `at` sample); the round trip re-arranges the written scene.
#pragma once

#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/bsh/samples.hpp>
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/complex/from_arrangement3.hpp>

#include <string>
#include <vector>

namespace hsx::csg {

struct OrientedScene {
  Scene2 scene;                      ///< the scene with halfspaces complemented or copies appended (samples kept)
  std::vector<std::string> flipped;  ///< per change, in halfspace order: "A", or "A~ (a complemented copy of A)"
};

/// The orientation rule above.
/// - `scene`: a validated scene; `complex`: arrange(scene).complex; `solid`: per cell, 1 inside.
OrientedScene orient_for_bsh(const Scene2& scene, const Complex& complex, const std::vector<char>& solid);

struct ConversionReport {
  Scene2 scene;                      ///< the BSH scene (no samples besides the generated ones); see `ok`
  bsh::SampleGenResult samples;      ///< GENERATE-SAMPLES on the oriented scene
  std::vector<std::string> flipped;  ///< OrientedScene::flipped
  /// Extracting `scene`, rebuilt from what its file holds (halfspaces, domain when given, `at` points) and
  /// validated and arranged again, gives the solid back.
  bool round_trip = false;
  std::string failure;               ///< why not ok
  bool ok() const { return samples.reproduced && round_trip; }
};

/// Converts a bounded solid to a BSH scene.
/// - `scene`, `arranged`: a validated scene and arrange(scene); `solid`: per cell of arranged.complex, 1 inside;
/// - `search`: the extraction used by GENERATE-SAMPLES and by the round-trip check.
/// Throws InputError when the solid reaches the domain box (a BSH shape is bounded inside it).
ConversionReport convert_to_bsh(const Scene2& scene, const Arranged2& arranged, const std::vector<char>& solid,
                                bsh::Method search);

/// The same for the solid of `expression` (over scene's halfspaces) on arrange(scene).
ConversionReport convert_to_bsh(const Scene2& scene, const Expr& expression, bsh::Method search);

/// The orientation rule in 3D. `scene`: a validated 3D scene; `complex`: arrange(scene).complex; `solid`: per cell.
struct OrientedScene3 {
  Scene3 scene;                      ///< as OrientedScene::scene
  std::vector<std::string> flipped;  ///< as OrientedScene::flipped
};
OrientedScene3 orient_for_bsh(const Scene3& scene, const Complex& complex, const std::vector<char>& solid);

struct ConversionReport3 {
  Scene3 scene;                      ///< the BSH scene (no samples besides the generated ones; the domain given,
                                     ///< the input's); see `ok`
  bsh::SampleGenResult samples;      ///< GENERATE-SAMPLES on the oriented scene
  std::vector<std::string> flipped;  ///< OrientedScene3::flipped
  /// Extracting `scene` as its file holds it (halfspaces, domain, `at` samples; validated and arranged again)
  /// gives the solid back, cell for cell (the cells of `oriented`).
  bool round_trip = false;
  std::string failure;               ///< why not ok
  Arranged3 oriented;                ///< arrange(scene without samples): the complex the samples are on
  std::vector<char> oriented_solid;  ///< the solid on oriented.complex (per cell, 1 inside)
  bool ok() const { return samples.reproduced && round_trip; }
};

/// Converts a bounded 3D solid to a BSH scene.
/// - `scene`, `arranged`: a validated 3D scene and arrange(scene); `solid`: per cell of arranged.complex, 1 inside;
/// - `search`: the extraction used by GENERATE-SAMPLES and by the round-trip check;
/// - `limits`: for the arrangements made here (the oriented scene when it differs, the round trip).
/// Throws InputError when the solid reaches the domain box, or an arrangement exceeds `limits`.
ConversionReport3 convert_to_bsh(const Scene3& scene, const Arranged3& arranged, const std::vector<char>& solid,
                                 bsh::Method search, const ArrangementLimits& limits = {});

/// The round-trip check: extracting `written` as its file holds it (halfspaces, domain when given, `at` samples;
/// validated and arranged again) gives `solid` back, cell for cell.
/// - 2D: `solid` per cell of arrange(written without its samples).
/// - 3D: `on`, an arrangement of the same halfspaces (e.g. of `written` without its samples); `solid` per cell of
///   on.complex; cells are matched by point location (carry_solid3). `limits` bound the arrangement made here.
bool extracts_back(const Scene2& written, const std::vector<char>& solid, bsh::Method search);
bool extracts_back(const Scene3& written, const Arranged3& on, const std::vector<char>& solid, bsh::Method search,
                   const ArrangementLimits& limits = {});

/// One CSG program end to end (the CSGNet corpus pipeline): describability, BHC (verified), conversion to BSH and
/// extraction back. The first stage that fails decides the outcome.
enum class ProgramOutcome { Ok, NotDescribable, BhcFailed, ConversionFailed };

struct ProgramCheck {
  ProgramOutcome outcome = ProgramOutcome::Ok;
  std::string failure;           ///< empty iff outcome == Ok
  int leaves = 0;                ///< BHC tree's leaves and duplicated halfspaces (0 without a tree)
  int duplicated = 0;
  std::size_t samples = 0;       ///< the conversion's samples (0 for an empty solid: the empty sample set)
  int lower_bound = 0, upper_bound = 0;
  bool sufficient_set = false;   ///< SampleGenResult::used_sufficient_set
};

/// - `scene`: a validated scene; `expression`: over its halfspaces; `search`: as for convert_to_bsh.
/// Throws what arrange and convert_to_bsh throw (e.g. InputError for a solid reaching the domain box).
ProgramCheck check_program(const Scene2& scene, const Expr& expression, bsh::Method search);

}  // namespace hsx::csg
