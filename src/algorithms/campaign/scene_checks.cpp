// The campaign's checks outside check_all: see scene_checks.hpp.
#include <hsx/algorithms/campaign/scene_checks.hpp>

#include <hsx/algorithms/bsh/samples.hpp>
#include <hsx/complex/carry_solid2.hpp>

#include <stdexcept>

namespace hsx::campaign {
namespace {

std::string energy_text(const bsh::Energy& e) {
  return std::to_string(e.missing_samples) + " missing / " + e.measure().decimal_string(15);
}

std::string cells_text(const std::vector<int>& cells) {
  std::string out = "{";
  for (std::size_t k = 0; k < cells.size(); ++k) out += (k ? "," : "") + std::to_string(cells[k]);
  return out + "}";
}

bsh::ExtractOptions search_options(const CheckLimits& limits, bsh::Method method, int beam_width = 1) {
  bsh::ExtractOptions o;
  o.method = method;
  o.beam_width = beam_width;
  o.max_states = limits.max_states;
  o.max_graph_cuts = limits.max_graph_cuts;
  o.compare = limits.compare;
  o.cancel = limits.cancel;
  o.enumerate_ties = false;
  o.certify_limit = limits.certify_limit;
  o.exact_branching = bsh::ExactBranching::Cells;  // the records count exact's graph cuts: keep them reproducible
  return o;
}

}  // namespace

std::string genericity_note(const Complex& complex) {
  const bsh::Problem problem(complex);
  const std::size_t n = problem.non_generic_junctions().size();
  return n == 0 ? "" : " [" + std::to_string(n) + " non-generic junction(s): the proposition is not guaranteed]";
}

bsh::ExtractResult reference_optimum(const Complex& complex, const CheckLimits& limits) {
  // The exact branch and bound: right at any junction, and far cheaper than best-first on most scenes.
  return bsh::extract(bsh::Problem(complex), search_options(limits, bsh::Method::Exact));
}

CheckOutcome check_generate_samples(const std::string& name, const Complex& complex, const bsh::Labelling& target,
                                    bsh::Method search, const CheckLimits& limits) {
  if (target.size() != complex.cells.size())
    throw std::invalid_argument("check_generate_samples: the target needs one flag per cell");
  const std::string genericity = genericity_note(complex);
  const std::string method = search == bsh::Method::BestFirst ? "best-first" : "beam K=1";
  CheckOutcome out{name, CheckStatus::Held, ""};
  std::string why;
  if (!bsh::is_orientation_preserving(bsh::Problem(complex), target, &why)) {
    out.status = CheckStatus::Failed;
    out.witness = "the target is not orientation-preserving (not an input of the proposition): " + why;
    return out;
  }
  bsh::SampleGenOptions o;
  o.search = search;
  o.beam_width = 1;
  o.compare = limits.compare;
  o.fallback_states = 0;
  o.max_states = limits.max_states;
  o.max_graph_cuts = limits.max_graph_cuts;
  o.cancel = limits.cancel;
  const bsh::SampleGenResult r = bsh::generate_samples(complex, target, o);
  const std::string numbers = std::to_string(r.rounds) + " round(s), " + std::to_string(r.sample_patches.size()) +
                              " sample(s) (" + std::to_string(r.initial) + " initial), " +
                              std::to_string(r.upper_bound) + " patch(es) on b";
  if (!r.stopped_by.empty()) {
    out.status = CheckStatus::Stopped;
    out.witness = method + " stopped by " + r.stopped_by + " after " + numbers;
    return out;
  }
  const int bound = r.upper_bound - r.initial + 1;
  if (r.reproduced && !r.used_sufficient_set && r.fallbacks == 0 && r.failure.empty() && r.rounds <= bound) {
    out.witness = "reproduced by " + method + " in " + numbers + genericity;
    return out;
  }
  out.status = CheckStatus::Failed;
  out.witness = "not reproduced by " + method + "'s greedy rounds alone: " +
                (r.used_sufficient_set ? std::string("no sample-free patch of b \\ b' was left")
                 : !r.failure.empty()  ? r.failure
                 : r.rounds > bound    ? "more than " + std::to_string(bound) + " rounds"
                                       : std::string("stuck")) +
                "; " + numbers + "; samples on patches " + cells_text(r.sample_patches) + genericity;
  return out;
}

CheckOutcome check_beam_optimality(const std::string& name, const Complex& complex, int beam_width,
                                   const bsh::ExtractResult& optimum, const CheckLimits& limits) {
  if (beam_width < 1) throw std::invalid_argument("check_beam_optimality: beam width at least 1");
  CheckOutcome out{name, CheckStatus::Held, ""};
  if (!optimum.stopped_by.empty() || !optimum.optimal) {
    out.status = CheckStatus::Stopped;
    out.witness = optimum.stopped_by.empty() ? "the optimum was not proven" : "the optimum stopped by " + optimum.stopped_by;
    return out;
  }
  const bsh::Problem problem(complex);
  const bsh::ExtractResult beam = bsh::extract(problem, search_options(limits, bsh::Method::Beam, beam_width));
  if (!beam.stopped_by.empty()) {
    out.status = CheckStatus::Stopped;
    out.witness = "beam stopped by " + beam.stopped_by;
    return out;
  }
  std::string why;
  const Order o = bsh::compare(beam.energy, optimum.energy, limits.compare);
  if (!bsh::is_orientation_preserving(problem, beam.labelling, &why) || !beam.sample_connected ||
      o == Order::Less) {
    out.status = CheckStatus::Failed;
    out.witness = "beam K=" + std::to_string(beam_width) + " " + energy_text(beam.energy) + " vs optimum " +
                  energy_text(optimum.energy) +
                  (o == Order::Less ? " (below the optimum)" : !beam.sample_connected ? " (not sample-connected)"
                                                                                           : " " + why);
    return out;
  }
  out.witness = std::string(o == Order::Greater ? "sub-optimal: " : "optimal: ") + energy_text(beam.energy);
  return out;
}

CheckOutcome describability_outcome(const std::string& name, const csg::Describability& d, const csg::BhcResult& b,
                                    const std::string& what, long cells) {
  CheckOutcome out{name, CheckStatus::Held, ""};
  const auto term = [](const csg::MixedTerm& t) {
    return "cells " + cells_text(t.inside_cells) + " inside and " + cells_text(t.outside_cells) + " outside";
  };
  if (d.describable != b.describable) {
    out.status = CheckStatus::Failed;
    out.witness = what + ": Shapiro-Vossler says " + (d.describable ? "describable" : "not describable") +
                  " (" + std::to_string(d.terms) + " terms" +
                  (d.mixed.empty() ? std::string() : "; mixed: " + term(d.mixed.front())) + "), BHC says " +
                  (b.describable ? "describable" : "not describable") +
                  (b.describable ? std::string() : " (stopped at " + term(b.witness) + ")");
  } else if (b.describable && !b.verified) {
    out.status = CheckStatus::Failed;
    out.witness = what + ": describable, but BHC's tree differs from the solid on some cell";
  } else if (b.describable) {
    out.witness = "describable: " + what + ", BHC's tree verified on all " + std::to_string(cells) + " cells (" +
                  std::to_string(b.stats.leaves) + " leaves, " + std::to_string(b.factored) + " factored, " +
                  std::to_string(b.partitions) + " partitions)";
  } else {
    out.witness = "not describable: " + what + ", " + std::to_string(d.mixed.size()) +
                  " mixed term(s), BHC stops at one (" + term(b.witness) + ")";
  }
  return out;
}

CheckOutcome check_describability(const std::string& name, const Complex& complex, const std::vector<char>& solid,
                                  const std::string& what) {
  if (solid.size() != complex.cells.size())
    throw std::invalid_argument("check_describability: the solid needs one flag per cell");
  return describability_outcome(name, csg::describability(complex, solid), csg::bhc(complex, solid), what,
                                static_cast<long>(complex.cells.size()));
}

CheckOutcome nhrep_outcome(const std::string& name, const nhrep::SurveyOutcome& o, const std::string& what) {
  CheckOutcome out{name, CheckStatus::Held, ""};
  if (o.status != csg::SolidStatus::Bounded) {
    out.status = CheckStatus::Skipped;
    out.witness = "not run: " + what + " is " +
                  (o.status == csg::SolidStatus::Empty ? "empty" : "unbounded (it holds a cell touching the domain box)");
    return out;
  }
  if (!o.problems.empty()) {
    out.status = CheckStatus::Failed;
    out.witness = what + ": " + o.problems.front() +
                  (o.problems.size() > 1 ? " (and " + std::to_string(o.problems.size() - 1) + " more)" : "");
    return out;
  }
  if (!o.whole.evaluated) {  // problems would say why; a logic error of the survey otherwise
    out.status = CheckStatus::Failed;
    out.witness = what + ": the tree was not evaluated";
    return out;
  }
  const nhrep::Evaluation& e = o.whole.eval;
  const std::string verdict = e.verdict == nhrep::Verdict::TreeCorrect           ? "tree correct"
                              : e.verdict == nhrep::Verdict::DescribableButFails ? "describable, tree fails"
                                                                                  : "not describable";
  out.witness = verdict + ": " + what + ", " + std::to_string(o.whole.built.graph.live_patches().size()) +
                " patch(es), " + std::to_string(o.whole.built.decompositions.size()) + " decomposition(s), " +
                std::to_string(e.natural_halfspaces.size()) + " natural halfspace(s)" +
                (e.correct ? std::string()
                           : ", wrong cells " + cells_text(e.wrong_inside) + " inside, " + cells_text(e.wrong_outside) +
                                 " outside (whole-plane cells)") +
                (o.holes ? ", " + std::to_string(o.holes) + " hole(s)" : "") +
                (o.own_differs ? "; the own domain's verdict differs" : "");
  return out;
}

CheckOutcome check_nhrep(const std::string& name, const Scene2& scene, const Arranged2& arranged,
                         const std::vector<char>& solid, const std::string& what) {
  if (solid.size() != arranged.complex.cells.size())
    throw std::invalid_argument("check_nhrep: the solid needs one flag per cell");
  nhrep::SurveySolid s;
  s.name = what;
  s.origin = "campaign";
  nhrep::SurveyOutcome not_run;
  not_run.status = csg::solid_status(arranged.complex, solid);
  if (not_run.status != csg::SolidStatus::Bounded) return nhrep_outcome(name, not_run, what);
  s.scene = whole_plane_scene(scene);
  try {
    s.arranged = arrange(s.scene);
  } catch (const InputError& e) {
    return {name, CheckStatus::Skipped, std::string("not run: the whole-plane arrangement was refused: ") + e.what()};
  }
  s.solid = carry_to_whole_plane(arranged, solid, s.arranged);
  s.own_arranged = arranged;
  s.own_solid = solid;
  return nhrep_outcome(name, nhrep::survey_solid(s), what);
}

CheckOutcome check_nhrep3(const std::string& name, const Scene3& scene, const Arranged3& arranged,
                          const std::vector<char>& solid, const std::string& what) {
  if (solid.size() != arranged.complex.cells.size())
    throw std::invalid_argument("check_nhrep3: the solid needs one flag per cell");
  nhrep::SurveyOutcome not_run;
  not_run.status = csg::solid_status(arranged.complex, solid);
  if (not_run.status != csg::SolidStatus::Bounded) return nhrep_outcome(name, not_run, what);
  if (scene.domain_given)
    return {name, CheckStatus::Skipped,
            "not run: the scene's domain was given (the 3D survey needs a domain chosen by hsx, holding every vertex)"};
  nhrep::SurveySolid3 s;
  s.name = what;
  s.origin = "campaign";
  s.scene = scene;
  s.arranged = arranged;
  s.solid = solid;
  return nhrep_outcome(name, nhrep::survey_solid3(s), what);
}

}  // namespace hsx::campaign
