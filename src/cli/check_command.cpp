// hsx check INPUT: every applicable proposition checker, as a table with witnesses.
#include <hsx/algorithms/bsh/checks.hpp>
#include "cli/commands.hpp"
#include <hsx/io/input.hpp>
#include <hsx/io/files.hpp>

#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace hsx::cli {
namespace {

struct CheckCommandOptions {
  ArrangementLimits arrangement;  ///< --max-cells, --max-side-table
  std::string input;
  std::string json_path;
  bsh::CheckOptions limits;
  int precision_bits = 2048;
};

/// Exit status 3 when a check fails: a counterexample or a bug, never bad input.
constexpr int kCheckFailed = 3;

int run_check(const CheckCommandOptions& o) {
  if (o.limits.brute_force_limit < 1) throw InputError("--max-labellings: must be at least 1");
  if (o.limits.max_states < 0) throw InputError("--max-states: must be >= 0");
  if (o.limits.max_graph_cuts < 0) throw InputError("--max-graph-cuts: must be >= 0");
  if (o.precision_bits < 64) throw InputError("--precision: at least 64 bits");
  OutputFiles out;
  out.expect(o.json_path, "--json");
  const LoadedInput in = load_input(o.input, o.arrangement);
  protect_inputs(out, in);
  bsh::CheckOptions limits = o.limits;
  limits.compare.max_bits = o.precision_bits;
  const auto results = bsh::check_all(in.complex(), limits);
  std::ostringstream table;
  bool failed = false, complete = true;
  nlohmann::json json = nlohmann::json::array();
  for (const auto& r : results) {
    table << std::left << std::setw(70) << r.name << " " << std::setw(9) << bsh::to_string(r.status) << r.witness << "\n";
    failed = failed || r.status == bsh::CheckResult::Fail;
    complete = complete && r.status != bsh::CheckResult::Stopped && r.status != bsh::CheckResult::Skipped;
    json.push_back({{"check", r.name}, {"status", bsh::to_string(r.status)}, {"witness", r.witness}});
  }
  out.put(o.json_path, nlohmann::json{{"format", "hsx-check/1"}, {"input", o.input}, {"passed", !failed}, {"complete", complete},
                                      {"checks", json}}
                            .dump(2) + "\n");
  out.print(table.str());
  out.commit();
  return failed ? kCheckFailed : 0;
}

}  // namespace

void add_check_command(CLI::App& app) {
  auto o = std::make_shared<CheckCommandOptions>();
  CLI::App* cmd = app.add_subcommand("check", "Run every applicable proposition checker (BSH Props. 4.1, 5.1, 5.2, "
                                              "existence, uniqueness, certificates) on a scene or complex; exit 3 "
                                              "when one fails");
  cmd->add_option("INPUT", o->input, "hsx-scene/1 or hsx-complex/1 JSON file")->required();
  cmd->add_option("--json", o->json_path, "write the table as JSON")->check(output_path());
  cmd->add_option("--max-labellings,--brute-force-limit", o->limits.brute_force_limit,
                  "largest number of labellings the oracle may enumerate (default 200000; more: Prop. 5.2 skipped)");
  cmd->add_option("--max-states", o->limits.max_states,
                  "per search: stop after expanding N states (0: no limit; deterministic)");
  cmd->add_option("--max-graph-cuts", o->limits.max_graph_cuts,
                  "per search: stop after N graph cuts (0: no limit; deterministic)");
  cmd->add_option("--time-limit", o->limits.time_limit,
                  "seconds for all checks together (0: no limit); which checks finish then depends on the machine's "
                  "speed and load. A check cut short by a limit is reported as \"stopped\", one left no time as "
                  "\"skipped\": neither counts as a failure")
      ->check(seconds());
  cmd->add_option("--precision", o->precision_bits, "precision cap in bits for certified comparisons");
  add_arrangement_limits(cmd, o->arrangement);
  run_with_status(cmd, o, &run_check);
}

}  // namespace hsx::cli
