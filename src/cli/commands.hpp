// The `hsx` program's subcommands. Each command file adds its subcommand to the app; errors travel as
// exceptions: InputError -> exit 2 (bad input), anything else -> exit 1 (internal error).
#pragma once

#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/geometry/arrangement2.hpp>

#include <CLI/CLI.hpp>

#include <cmath>
#include <memory>
#include <string>

namespace hsx::cli {

/// Makes `cmd` run `run(*options)`; a non-zero status (e.g. 3, a failed check) becomes the program's exit code
/// (main.cpp catches CLI::RuntimeError).
template <class Options>
void run_with_status(CLI::App* cmd, std::shared_ptr<Options> options, int (*run)(const Options&)) {
  cmd->callback([options, run] {
    const int status = run(*options);
    if (status != 0) throw CLI::RuntimeError(status);
  });
}

/// For output-file options: a path, never an empty one ("-" is standard output; io/files.hpp has the policy for
/// links, devices and FIFOs). An empty path is a parse error (exit 2), not an option silently ignored.
inline CLI::Validator output_path() {
  return CLI::Validator([](std::string& s) { return s.empty() ? std::string("an empty path") : std::string(); },
                        "PATH");
}

/// For seconds: a finite number >= 0 ("nan", "inf" and negatives are refused).
inline CLI::Validator seconds() {
  return CLI::Validator(
      [](std::string& s) {
        try {
          std::size_t used = 0;
          const double v = std::stod(s, &used);
          if (used == s.size() && std::isfinite(v) && v >= 0) return std::string();
        } catch (const std::exception&) {
        }
        return std::string("must be a finite number of seconds >= 0, not \"" + s + "\"");
      },
      "SECONDS");
}

/// The arrangement size limits (geometry/arrangement2.hpp, docs/limits.md) as `--max-cells N` and
/// `--max-side-table N` (0: no limit) on a command that arranges a scene; `limits` must outlive the parse.
inline void add_arrangement_limits(CLI::App* cmd, ArrangementLimits& limits) {
  cmd->add_option("--max-cells", limits.max_cells,
                  "refuse a scene whose arrangement has more cells than this (default " +
                      std::to_string(limits.max_cells) + "; 0: no limit; see docs/limits.md)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-side-table", limits.max_side_entries,
                  "refuse a scene whose cells x halfspaces exceeds this (default " +
                      std::to_string(limits.max_side_entries) + "; 0: no limit)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-triangles", limits.max_triangles,
                  "3D scenes: refuse an arrangement with more refined triangles than this (default " +
                      std::to_string(limits.max_triangles) + "; 0: no limit)")
      ->check(CLI::NonNegativeNumber);
}

/// A measure for a summary: "DECIMAL = CLOSED FORM", or the decimal and the closed form's size when it is long
/// (the JSON has it). Defined in extract_command.cpp.
std::string measure_text(const Measure& m);
/// An energy for a summary: "N missing samples, boundary length|area M" (measure_text).
std::string energy_text(const bsh::Energy& e, int dimension);

/// Where a graded boundary and the optimum's differ: the support groups on one and not the other, each as its
/// patch with that boundary's orientation (result_json.hpp oriented_patch). Defined in grade_command.cpp.
struct BoundaryDifference {
  std::vector<int> theirs_only, optimum_only;
};
BoundaryDifference boundary_difference(const bsh::Problem& problem, const Complex& c, const bsh::Labelling& theirs,
                                       const bsh::Labelling& optimum);
/// " name#patch ..." for `patches` (name: the patch's halfspace), " none" when empty.
std::string patch_list(const Complex& c, const std::vector<int>& patches);

void add_arrange_command(CLI::App& app);
void add_extract_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_csg_commands(CLI::App& app);
void add_nhtree_command(CLI::App& app);
void add_nhsurvey_command(CLI::App& app);
void add_reference_command(CLI::App& app);
void add_grade_command(CLI::App& app);
void add_campaign_command(CLI::App& app);

}  // namespace hsx::cli
