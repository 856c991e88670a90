// hsx campaign --against: see campaign_against.hpp.
#include "cli/campaign_against.hpp"

#include "cli/commands.hpp"
#include <hsx/algorithms/bsh/grade.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/input.hpp>
#include <hsx/io/result_json.hpp>

#include <algorithm>
#include <iterator>
#include <string>

namespace hsx::cli {
namespace {

using campaign::CheckOutcome;
using campaign::CheckStatus;

CheckOutcome grade_answer(const Complex& c, const bsh::Labelling& theirs, const bsh::ExtractOptions& oracle) {
  const bsh::Problem problem(c);
  // bsh::grade's reference falls back to the exact branch and bound where best-first is left unproven.
  const bsh::Grade g = bsh::grade(problem, theirs, oracle);
  const BoundaryDifference d = boundary_difference(problem, c, theirs, g.optimum.labelling);
  const std::string where = "; theirs only:" + patch_list(c, d.theirs_only) + "; optimum only:" + patch_list(c, d.optimum_only);
  const std::string energies =
      "energy " + energy_text(g.energy, c.dimension) + ", optimum " + energy_text(g.optimum.energy, c.dimension);
  if (!g.orientation_preserving)
    return {campaign::kAgainstCheck, CheckStatus::Failed,
            "invalid: not orientation-preserving: " + g.orientation_problem + "; " + energies + where};
  if (!g.sample_connected)
    return {campaign::kAgainstCheck, CheckStatus::Failed,
            "invalid: not sample-connected (" + std::to_string(g.islands.size()) +
                (g.islands.size() == 1 ? " island" : " islands") + " without a sample); " + energies + where};
  if (g.optimal()) return {campaign::kAgainstCheck, CheckStatus::Held, "optimal: " + energy_text(g.energy, c.dimension)};
  if (g.optimum.optimal && g.versus_optimum == Order::Greater)
    return {campaign::kAgainstCheck, CheckStatus::Failed,
            "suboptimal: gap " + std::to_string(g.missing_samples_gap) + " missing samples, measure " +
                g.measure_gap.decimal(17).digits + "; " + energies + where};
  return {campaign::kAgainstCheck, CheckStatus::Stopped,
          std::string("undecided: ") +
              (g.optimum.optimal            ? std::string("the energies did not separate at the precision cap")
               : !g.optimum.stopped_by.empty() ? "the reference search was stopped by " + g.optimum.stopped_by
                                               : "the reference is not proven optimal: " + g.optimum.optimality_note) +
              "; " + energies};
}

}  // namespace

campaign::ExtraCheck against_check(const ExternalSolver& solver, const campaign::CampaignSettings& settings) {
  check_external_solver(solver);
  bsh::ExtractOptions oracle = bsh::best_first_oracle();
  oracle.max_states = settings.max_states;
  oracle.max_graph_cuts = settings.max_graph_cuts;
  oracle.compare.max_bits = settings.precision_bits;
  oracle.time_limit = settings.time_limit;
  oracle.brute_force_limit = settings.brute_force_limit;
  campaign::ExtraCheck check;
  check.name = campaign::kAgainstCheck;
  check.run = [solver, oracle](std::uint64_t index, const Scene2& scene, const Arranged2& arranged) {
    LoadedInput in;
    in.path = "scene-" + std::to_string(index);
    in.scene = scene;
    in.arranged = arranged;
    const ExternalRun run = run_external_solver(in, solver);
    if (!run.labelling) return CheckOutcome{campaign::kAgainstCheck, CheckStatus::Failed, "no answer: " + run.problem};
    return grade_answer(in.complex(), run.labelling->cells, oracle);
  };
  return check;
}

nlohmann::json against_to_json(const ExternalSolver& solver) {
  return {{"command", solver.command},
          {"input", solver.input == ExternalInput::BshGraphcut ? "bsh-graphcut" : "complex"},
          {"weight_scale", solver.weight_scale}};
}

}  // namespace hsx::cli
