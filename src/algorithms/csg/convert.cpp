#include <hsx/algorithms/csg/convert.hpp>

#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/algorithms/bsh/sample_scene.hpp>
#include <hsx/algorithms/csg/separators3.hpp>
#include <hsx/algorithms/csg/solid_tree.hpp>
#include <hsx/complex/carry_solid2.hpp>

#include <algorithm>

namespace hsx::csg {
namespace {

struct SupportUse {
  std::vector<char> normal;                        ///< per halfspace: the solid runs along it the right way
  std::vector<const std::vector<int>*> reversed;   ///< supports of b that no halfspace runs along the right way
};

SupportUse support_use(const Complex& complex, const std::vector<char>& solid) {
  SupportUse use{std::vector<char>(complex.halfspace_count(), 0), {}};
  for (const auto& group : complex.supports) {
    const Patch& first = complex.patches[group.front()];
    if (solid[first.inside_cell] == solid[first.outside_cell]) continue;  // not on the solid's boundary
    bool agrees = false;
    for (int p : group) {
      const Patch& patch = complex.patches[p];
      if (solid[patch.inside_cell]) {
        agrees = true;
        use.normal[patch.halfspace] = 1;
      }
    }
    if (!agrees) use.reversed.push_back(&group);
  }
  return use;
}

/// Each reversed support needs one of its (coincident) halfspaces complemented: prefer one already chosen, then
/// one the solid uses nowhere the right way; when every one of them is, a complemented copy is added instead.
void choose_changes(const Complex& complex, const SupportUse& use, std::vector<char>& complement,
                    std::vector<char>& copy) {
  for (const auto* group : use.reversed) {
    int pick = complex.patches[group->front()].halfspace;
    for (int p : *group) {
      const int h = complex.patches[p].halfspace;
      if (complement[h] || copy[h]) {
        pick = h;
        break;
      }
      if (use.normal[pick] && !use.normal[h]) pick = h;
    }
    (use.normal[pick] ? copy : complement)[pick] = 1;
  }
}

template <class SceneT, class HalfspaceT>
HalfspaceT complemented_copy(const SceneT& scene, const HalfspaceT& h) {
  HalfspaceT out = h;
  out.complement = !out.complement;
  out.name += "~";
  while (scene.find_halfspace(out.name) >= 0) out.name += "~";
  return out;
}

void check_bounded(const Complex& complex, const std::vector<char>& solid) {
  for (std::size_t k = 0; k < solid.size(); ++k)
    if (solid[k] && complex.cells[k].outer)
      throw InputError("the solid reaches the domain boundary (cell " + std::to_string(k) +
                       " touches it); enlarge the domain");
}

template <class Report>
std::string conversion_description(const Report& report) {
  std::string d = "BSH conversion: " + std::to_string(report.samples.sample_patches.size()) +
                  " samples from GENERATE-SAMPLES";
  if (!report.flipped.empty()) {
    d += "; complemented (the solid uses them reversed):";
    for (const auto& n : report.flipped) d += " " + n;
  }
  return d;
}

/// The scene as its file holds it (halfspaces, domain when given, `at` points), validated again.
Scene2 as_read_back(const Scene2& scene) {
  Scene2 back = scene;
  for (Sample2& s : back.samples) {
    s.snapped = false;
    s.location = OneRootPoint(s.given);
  }
  validate_and_resolve(back);
  return back;
}

bool extracts_to(const Scene2& scene, const std::vector<char>& solid, bsh::Method search) {
  const Arranged2 again = arrange(as_read_back(scene));
  const bsh::Problem problem(again.complex);
  bsh::ExtractOptions options;
  options.method = search;
  options.enumerate_ties = false;
  return bsh::extract(problem, options).labelling == solid;
}

/// The orientation rule on either dimension's scene.
template <class Oriented, class SceneT>
Oriented orient_scene(const SceneT& scene, const Complex& complex, const std::vector<char>& solid) {
  const SupportUse use = support_use(complex, solid);
  std::vector<char> complement(scene.halfspaces.size(), 0), copy(scene.halfspaces.size(), 0);
  choose_changes(complex, use, complement, copy);
  Oriented out{scene, {}};
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
    if (complement[i]) {
      out.scene.halfspaces[i].complement = !out.scene.halfspaces[i].complement;
      out.flipped.push_back(scene.halfspaces[i].name);
    }
    if (copy[i]) {
      const auto h = complemented_copy(out.scene, scene.halfspaces[i]);
      out.flipped.push_back(h.name + " (a complemented copy of " + scene.halfspaces[i].name + ")");
      out.scene.halfspaces.push_back(h);
    }
  }
  return out;
}

/// The 3D scene as its file holds it (halfspaces, domain, `at` points), validated again.
Scene3 as_read_back(const Scene3& scene) {
  Scene3 back = scene;
  back.notes.clear();
  for (Sample3& s : back.samples) {
    s.snapped = false;
    s.location = s.given;
    s.distance2 = Rational(0);
  }
  validate_and_resolve(back);
  return back;
}

}  // namespace

OrientedScene orient_for_bsh(const Scene2& scene, const Complex& complex, const std::vector<char>& solid) {
  return orient_scene<OrientedScene>(scene, complex, solid);
}

OrientedScene3 orient_for_bsh(const Scene3& scene, const Complex& complex, const std::vector<char>& solid) {
  return orient_scene<OrientedScene3>(scene, complex, solid);
}

bool extracts_back(const Scene2& written, const std::vector<char>& solid, bsh::Method search) {
  return extracts_to(written, solid, search);
}

bool extracts_back(const Scene3& written, const Arranged3& on, const std::vector<char>& solid, bsh::Method search,
                   const ArrangementLimits& limits) {
  const Arranged3 again = arrange(as_read_back(written), limits);
  bsh::ExtractOptions extract_options;
  extract_options.method = search;
  extract_options.enumerate_ties = false;
  const bsh::Problem problem(again.complex);
  const std::vector<char> back = bsh::extract(problem, extract_options).labelling;
  // The same scene without samples arranges to the same cells in the same order; compare through point
  // location all the same, so that a different cell order could not pass unnoticed.
  return back.size() == solid.size() && carry_solid3(again, back, on) == solid;
}

ConversionReport3 convert_to_bsh(const Scene3& scene, const Arranged3& arranged, const std::vector<char>& solid,
                                 bsh::Method search, const ArrangementLimits& limits) {
  if (solid.size() != arranged.complex.cells.size())
    throw std::invalid_argument("convert_to_bsh: the solid needs one entry per cell");
  check_bounded(arranged.complex, solid);
  ConversionReport3 report;
  OrientedScene3 oriented = orient_for_bsh(scene, arranged.complex, solid);
  report.flipped = oriented.flipped;
  Scene3 bare = std::move(oriented.scene);
  bare.samples.clear();
  bare.notes.clear();
  // The domain is written out: hsx would otherwise choose it again from the samples and could pick another box.
  bare.domain_given = true;
  const bool unchanged = report.flipped.empty() && scene.samples.empty();
  report.oriented = unchanged ? arranged : arrange(bare, limits);
  // Cell order may differ after adding copies: carry the solid over by point location.
  report.oriented_solid = unchanged ? solid : carry_solid3(arranged, solid, report.oriented);
  bsh::SampleGenOptions options;
  options.search = search;
  report.samples = bsh::generate_samples(report.oriented.complex, report.oriented_solid, options);
  if (!report.samples.reproduced) {
    report.failure = report.samples.failure;
    return report;
  }
  report.scene = bsh::scene_with_samples(bare, report.oriented, report.samples.sample_patches,
                                         conversion_description(report));
  report.round_trip = extracts_back(report.scene, report.oriented, report.oriented_solid, search, limits);
  if (!report.round_trip) report.failure = "extracting the written scene does not give the solid back";
  return report;
}

ConversionReport convert_to_bsh(const Scene2& scene, const Arranged2& arranged, const std::vector<char>& solid,
                                bsh::Method search) {
  check_bounded(arranged.complex, solid);
  ConversionReport report;
  OrientedScene oriented = orient_for_bsh(scene, arranged.complex, solid);
  report.flipped = oriented.flipped;
  Scene2 bare = std::move(oriented.scene);
  bare.samples.clear();
  const bool unchanged = report.flipped.empty() && scene.samples.empty();
  const Arranged2 oriented_arranged = unchanged ? arranged : arrange(bare);
  // Cell order may differ after adding copies: carry the solid over by point location.
  const std::vector<char> oriented_solid =
      unchanged ? solid : carry_solid_over(arranged.arrangement, solid, oriented_arranged.arrangement);
  bsh::SampleGenOptions options;
  options.search = search;
  report.samples = bsh::generate_samples(oriented_arranged.complex, oriented_solid, options);
  if (!report.samples.reproduced) {
    report.failure = report.samples.failure;
    return report;
  }
  report.scene = bsh::scene_with_samples(bare, oriented_arranged, report.samples.sample_patches,
                                         conversion_description(report));
  report.round_trip = extracts_to(report.scene, oriented_solid, search);
  if (!report.round_trip) report.failure = "extracting the written scene does not give the solid back";
  return report;
}

ConversionReport convert_to_bsh(const Scene2& scene, const Expr& expression, bsh::Method search) {
  const Arranged2 arranged = arrange(scene);
  return convert_to_bsh(scene, arranged, evaluate(expression, arranged.complex), search);
}

ProgramCheck check_program(const Scene2& scene, const Expr& expression, bsh::Method search) {
  ProgramCheck check;
  const Arranged2 arranged = arrange(scene);
  const std::vector<char> solid = evaluate(expression, arranged.complex);
  const SolidTree tree = build_tree(scene, arranged, solid, {});
  check.leaves = tree.bhc.stats.leaves;
  check.duplicated = tree.bhc.stats.duplicated_halfspaces;
  if (!tree.describability.describable) {
    check.outcome = ProgramOutcome::NotDescribable;
    check.failure = "not describable";
    return check;
  }
  if (!tree.has_verified_tree()) {
    check.outcome = ProgramOutcome::BhcFailed;
    check.failure = "BHC tree missing or wrong";
    return check;
  }
  if (std::none_of(solid.begin(), solid.end(), [](char c) { return c != 0; }))
    return check;  // an empty solid converts to the empty sample set trivially
  const ConversionReport report = convert_to_bsh(scene, arranged, solid, search);
  if (report.samples.reproduced) {
    check.samples = report.samples.sample_patches.size();
    check.sufficient_set = report.samples.used_sufficient_set;
    check.lower_bound = report.samples.initial;
    check.upper_bound = report.samples.upper_bound;
  }
  if (!report.ok()) {
    check.outcome = ProgramOutcome::ConversionFailed;
    check.failure = report.failure;
  }
  return check;
}

}  // namespace hsx::csg
