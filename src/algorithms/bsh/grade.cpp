#include <hsx/algorithms/bsh/grade.hpp>

#include <stdexcept>

namespace hsx::bsh {

ExtractOptions best_first_oracle() {
  ExtractOptions options;
  options.method = Method::BestFirst;
  return options;
}

ExtractResult reference_optimum(const Problem& problem, const ExtractOptions& oracle) {
  ExtractResult result = extract(problem, oracle);
  if (oracle.method != Method::BestFirst || result.optimal || !result.stopped_by.empty()) return result;
  ExtractOptions exact_options = oracle;
  exact_options.method = Method::Exact;
  ExtractResult exact = extract(problem, exact_options);
  if (!exact.optimal) {
    result.optimality_note += "; the exact branch and bound, asked instead, was stopped by " + exact.stopped_by;
    return result;
  }
  exact.optimality_note = "best-first was left unproven (" + result.optimality_note +
                          "): the exact branch and bound decided";
  return exact;
}

Grade grade(const Problem& problem, const Labelling& labelling, const ExtractOptions& oracle) {
  if (static_cast<int>(labelling.size()) != problem.cell_count())
    throw std::invalid_argument("grade: the labelling has " + std::to_string(labelling.size()) +
                                " labels, the complex " + std::to_string(problem.cell_count()) + " cells");
  Grade g;
  g.orientation_preserving = is_orientation_preserving(problem, labelling, &g.orientation_problem);
  const SampleConnectivity connectivity = sample_connectivity(problem, labelling);
  g.sample_connected = connectivity.sample_connected();
  for (int i : connectivity.islands) g.islands.push_back(connectivity.components[static_cast<std::size_t>(i)]);
  g.energy = energy(problem, labelling);
  g.optimum = reference_optimum(problem, oracle);
  g.versus_optimum = compare(g.energy, g.optimum.energy, oracle.compare);
  g.missing_samples_gap = g.energy.missing_samples - g.optimum.energy.missing_samples;
  g.measure_gap = g.energy.measure() - g.optimum.energy.measure();
  return g;
}

}  // namespace hsx::bsh
