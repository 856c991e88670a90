// hsx campaign --against: another program run on every scene of a campaign and its answer graded exactly, as the
// campaign's extra check "against" (algorithms/campaign/campaign.hpp kAgainstCheck, whose witness grammar this
// follows). docs/campaigns.md.
#pragma once

#include <hsx/algorithms/campaign/campaign.hpp>
#include <hsx/io/external_solver.hpp>

#include <nlohmann/json.hpp>

namespace hsx::cli {

/// The "against" check: on each arranged scene, `solver` is run on the scene's complex (run_external_solver; its
/// program's failure, time-out or unreadable labelling is the verdict "no answer") and the labelling it wrote is
/// graded (bsh::grade with the best-first oracle under the campaign's limits: `settings`' max_states,
/// max_graph_cuts, brute_force_limit and precision_bits, and its time_limit as the reference's time limit; where
/// best-first is left unproven without a limit stopping it, bsh::reference_optimum's exact branch and bound is the
/// reference instead). The outcome's witness
/// is deterministic (no timings): the verdict, the energy or the gap (missing samples and the measure's decimal
/// to 17 digits), both energies (with their closed forms) and the patches where the boundary differs from the
/// optimum's. `solver` must be valid
/// (check_external_solver); `settings` is read when this is called (later changes to it are not seen).
campaign::ExtraCheck against_check(const ExternalSolver& solver, const campaign::CampaignSettings& settings);

/// What campaign.json records about --against (part of the campaign's identity): {"command", "input":
/// "bsh-graphcut" or "complex", "weight_scale"}.
nlohmann::json against_to_json(const ExternalSolver& solver);

}  // namespace hsx::cli
