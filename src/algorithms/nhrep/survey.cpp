// The NH-Rep survey of one solid and its tallies: see survey.hpp.
#include <hsx/algorithms/nhrep/survey.hpp>

#include <hsx/algorithms/csg/bhc.hpp>
#include <hsx/algorithms/nhrep/patch_graph.hpp>
#include <hsx/complex/boundary_from_arrangement2.hpp>
#include <hsx/complex/boundary_from_arrangement3.hpp>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <exception>
#include <new>
#include <stdexcept>

namespace hsx::nhrep {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

void check_size(const Complex& complex, const std::vector<char>& solid, const char* what) {
  if (solid.size() != complex.cells.size())
    throw std::invalid_argument(std::string("survey: ") + what + " needs one flag per cell");
}

}  // namespace

PipelineRun run_pipeline(const Arranged2& arranged, const std::vector<char>& solid, const BuildOptions& options) {
  return run_pipeline_on([&] { return boundary_from_arrangement2(arranged, solid); }, arranged.complex, solid,
                         options);
}

PipelineRun run_pipeline_on(const std::function<BoundarySurface()>& boundary, const Complex& complex,
                            const std::vector<char>& solid, const BuildOptions& options) {
  PipelineRun o;
  try {
    o.built = build_tree(build_patch_graph(boundary()), options);
    for (const std::string& p : check_tree(o.built)) o.problems.push_back("check_tree: " + p);
    o.eval = evaluate_tree(o.built, complex, solid);
    o.evaluated = true;
    for (const std::string& p : o.eval.violations) o.problems.push_back("evaluation: " + p);
    if (!o.eval.describable && o.eval.correct) o.problems.push_back("evaluation: correct but not describable");
  } catch (const std::bad_alloc&) {
    throw;  // out of memory ends the run (exit 2): it says nothing about the input
  } catch (const std::exception& e) {
    o.problems.push_back(std::string("error: ") + e.what());
  }
  return o;
}

int count_holes(const Complex& complex, const std::vector<char>& solid) {
  check_size(complex, solid, "count_holes");
  // Non-solid cells and the patches between two of them; solid cells stay isolated and are skipped below.
  boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS> graph(complex.cells.size());
  for (const Patch& p : complex.patches)
    if (!solid.at(at(p.inside_cell)) && !solid.at(at(p.outside_cell)))
      boost::add_edge(at(p.inside_cell), at(p.outside_cell), graph);
  std::vector<int> component(complex.cells.size());
  const int count = boost::connected_components(graph, component.data());
  std::vector<char> open(at(count), 0);  // per component: non-solid and reaching an outer cell
  std::vector<char> empty_space(at(count), 0);
  for (std::size_t k = 0; k < complex.cells.size(); ++k) {
    if (solid[k]) continue;
    empty_space[at(component[k])] = 1;
    if (complex.cells[k].outer) open[at(component[k])] = 1;
  }
  int holes = 0;
  for (int c = 0; c < count; ++c) holes += empty_space[at(c)] && !open[at(c)];
  return holes;
}

SurveyOutcome survey_solid(const SurveySolid& s, const BuildOptions& options) {
  check_size(s.arranged.complex, s.solid, "the solid");
  SurveyOutcome o;
  o.status = csg::solid_status(s.arranged.complex, s.solid);
  if (o.status != csg::SolidStatus::Bounded) return o;
  o.whole = run_pipeline(s.arranged, s.solid, options);
  o.problems = o.whole.problems;
  if (s.own_arranged) {
    check_size(s.own_arranged->complex, s.own_solid, "the own-domain solid");
    o.own = run_pipeline(*s.own_arranged, s.own_solid, options);
    for (const std::string& p : o.own->problems) o.problems.push_back("on the scene's own domain: " + p);
    o.own_differs = o.whole.evaluated && o.own->evaluated && o.own->eval.verdict != o.whole.eval.verdict;
  }
  o.holes = count_holes(s.arranged.complex, s.solid);
  return o;
}

SurveyOutcome survey_solid3(const SurveySolid3& s, const BuildOptions& options) {
  check_size(s.arranged.complex, s.solid, "the solid");
  SurveyOutcome o;
  o.status = csg::solid_status(s.arranged.complex, s.solid);
  if (o.status != csg::SolidStatus::Bounded) return o;
  o.whole = run_pipeline_on([&] { return boundary_from_arrangement3(s.arranged, s.solid); }, s.arranged.complex,
                            s.solid, options);
  o.problems = o.whole.problems;
  o.holes = count_holes(s.arranged.complex, s.solid);
  return o;
}

bool SurveyTally::add(const SurveySolid& s, const SurveyOutcome& o) {
  return add(s.name + " (" + s.origin + ")", s.arranged.complex.cells.size(), o);
}

bool SurveyTally::add(const std::string& label, std::size_t cell_count, const SurveyOutcome& o) {
  switch (o.status) {
    case csg::SolidStatus::Empty: ++empty; return false;
    case csg::SolidStatus::Unbounded: ++unbounded; return false;
    case csg::SolidStatus::Bounded: break;
  }
  ++solids;
  if (!o.problems.empty()) ++check_failures;
  if (!o.whole.evaluated) return false;
  if (o.own && o.own->evaluated) {
    ++own_domain_runs;
    if (o.own_differs) ++own_domain_differs;
  }
  patches += static_cast<long>(o.whole.built.graph.live_patches().size());
  cells += static_cast<long>(cell_count);
  if (o.holes > 0) {
    ++with_holes;
    if (o.whole.eval.verdict == Verdict::TreeCorrect) ++correct_with_holes;
    if (o.whole.eval.verdict == Verdict::NotDescribable) ++not_describable_with_holes;
  }
  if (!o.whole.built.decompositions.empty()) ++decomposed;
  decompositions += static_cast<long>(o.whole.built.decompositions.size());
  switch (o.whole.eval.verdict) {
    case Verdict::TreeCorrect: ++correct; break;
    case Verdict::DescribableButFails:
      ++describable_fails;
      if (o.holes > 0) ++fails_with_holes;
      break;
    case Verdict::NotDescribable: ++not_describable; break;
  }
  if (o.whole.eval.verdict != Verdict::DescribableButFails || static_cast<int>(examples.size()) >= max_examples)
    return false;
  examples.push_back(label);
  return true;
}

csg::ExprPtr canonical_union(const Complex& complex, const std::vector<char>& solid, const std::vector<int>& natural) {
  check_size(complex, solid, "canonical_union");
  std::vector<std::vector<char>> terms;
  for (std::size_t k = 0; k < solid.size(); ++k) {
    if (!solid[k]) continue;
    std::vector<char> signs;
    for (int h : natural) signs.push_back(complex.cells[k].inside.at(at(h)));
    if (std::find(terms.begin(), terms.end(), signs) == terms.end()) terms.push_back(signs);
  }
  if (terms.empty()) throw std::invalid_argument("canonical_union: the solid is empty");
  std::vector<csg::ExprPtr> parts;
  for (const auto& signs : terms) {
    std::vector<csg::ExprPtr> literals;
    for (std::size_t i = 0; i < signs.size(); ++i) {
      csg::ExprPtr l = csg::leaf(natural[i]);
      literals.push_back(signs[i] ? l : csg::complement(l));
    }
    parts.push_back(literals.size() == 1 ? literals.front() : csg::intersect(literals));
  }
  return parts.size() == 1 ? parts.front() : csg::unite(parts);
}

namespace {

/// example_expression for a 2D or a 3D survey solid (the same fields).
template <class Solid>
csg::ExprPtr example_expression_of(const Solid& s, const SurveyOutcome& o) {
  csg::ExprPtr expr = s.expression;
  if (!expr) {
    if (!o.whole.evaluated) throw std::logic_error(s.name + ": no expression for a solid that was not evaluated");
    const csg::BhcResult bhc = csg::bhc(s.arranged.complex, s.solid);
    expr = bhc.describable && bhc.verified ? bhc.tree
                                           : canonical_union(s.arranged.complex, s.solid, o.whole.eval.natural_halfspaces);
  }
  if (csg::evaluate(*expr, s.arranged.complex) != s.solid)
    throw std::logic_error(s.name + ": the kept expression is not the solid");
  return expr;
}

}  // namespace

csg::ExprPtr example_expression(const SurveySolid& s, const SurveyOutcome& o) { return example_expression_of(s, o); }

csg::ExprPtr example_expression(const SurveySolid3& s, const SurveyOutcome& o) { return example_expression_of(s, o); }

}  // namespace hsx::nhrep
