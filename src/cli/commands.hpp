// The `hsx` program's subcommands. Each command file adds its subcommand to the app; errors travel as
// exceptions: InputError -> exit 2 (bad input), anything else -> exit 1 (internal error).
#pragma once

#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/geometry/arrangement2.hpp>

#include <CLI/CLI.hpp>

#include <cmath>
#include <memory>
#include <string>

namespace hsx {
class OutputFiles;
struct LoadedInput;
}  // namespace hsx

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

/// The name of output_path()'s validator: it marks an option as an output (refuse_outputs_over_inputs).
inline constexpr const char* kOutputPathValidator = "output-path";

/// For output-file options: a path, never an empty one ("-" is standard output; io/files.hpp has the policy for
/// links, devices and FIFOs). An empty path is a parse error (exit 2), not an option silently ignored. Every option
/// that names an output file carries it: it is how refuse_outputs_over_inputs tells outputs from inputs.
inline CLI::Validator output_path() {
  return CLI::Validator([](std::string& s) { return s.empty() ? std::string("an empty path") : std::string(); },
                        "PATH", kOutputPathValidator);
}

/// Refuses (InputError, so exit 2) a command line whose output would replace one of the run's own inputs: the value
/// of an output option (one checked by output_path()) that is, through any spelling, hard link or symbolic link, the
/// same existing regular file as the value of any other option or positional argument of the parsed subcommands
/// (a scene, a shape, a mesh, a program to run). `app` is the parsed top-level app; main.cpp calls it once the
/// command line is parsed, before any command runs. Paths an output derives from another (an .obj's .mtl, the files
/// of --decomposed PREFIX) and files a scene refers to are compared by the commands (protect_inputs).
void refuse_outputs_over_inputs(CLI::App& app);

/// Marks the files `in` was read from (its path, "INPUT", and LoadedInput::files: a scene's mesh files, a BSH
/// config's grid and samples files) as inputs no output of `out` may replace (OutputFiles::protect): call it after
/// load_input, so that outputs derived from an option (an .obj's .mtl) and files a scene refers to are compared too.
void protect_inputs(OutputFiles& out, const LoadedInput& in);

/// Makes every whole-number option of `app` and of its subcommands (those CLI11 converts to an integer type: type
/// name INT or UINT) read its value as decimal digits, an optional sign (a '-' only where the type is signed) and
/// surrounding spaces allowed: "010" is ten and "+5" five, while "0x10", "1e6" and "5.0" are refused, and so is a
/// value beyond the 64-bit range. Without it CLI11 reads C's base-0 notation ("010" = 8, "0x10" = 16) and a value
/// over 2^63 - 1 saturates (`--max-cells 99999999999999999999` would mean "no limit"); the conversion to a narrower
/// type keeps refusing what does not fit. main.cpp calls it once every command is added.
void read_integers_in_decimal(CLI::App& app);

/// Makes a standard descriptor (0, 1, 2) that the program was started without point at a stand-in that refuses
/// its use (/dev/null opened the other way round: reading standard input or writing standard output then fails with
/// "Bad file descriptor"). Without it the first file the program opens would take the free number, and what it
/// prints would go into that file, an output. main.cpp calls it first.
void occupy_closed_standard_descriptors();

/// The reason standard output could not be written, or "" when everything the program printed was written. Flushes
/// it first. main.cpp asks after the command ran: a full disk or a closed descriptor behind standard output is then
/// reported (exit 2) instead of being a silent success.
std::string standard_output_error();

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

/// For counts and limits: a number >= 0, refused as "must be >= 0, not \"-1\"" (CLI11's NonNegativeNumber names a
/// range up to 1.8e308 in its message). What is not a number is left to the option's own conversion to refuse.
inline CLI::Validator non_negative() {
  return CLI::Validator(
      [](std::string& s) {
        try {
          std::size_t used = 0;
          if (std::stod(s, &used) < 0 && used == s.size()) return std::string("must be >= 0, not \"" + s + "\"");
        } catch (const std::exception&) {
        }
        return std::string();
      },
      "NONNEGATIVE");
}

/// The arrangement size limits (geometry/arrangement2.hpp, docs/limits.md) as `--max-cells N` and
/// `--max-side-table N` (0: no limit) on a command that arranges a scene; `limits` must outlive the parse.
inline void add_arrangement_limits(CLI::App* cmd, ArrangementLimits& limits) {
  cmd->add_option("--max-cells", limits.max_cells,
                  "refuse a scene whose arrangement has more cells than this (default " +
                      std::to_string(limits.max_cells) + "; 0: no limit; see docs/limits.md)")
      ->check(non_negative());
  cmd->add_option("--max-side-table", limits.max_side_entries,
                  "refuse a scene whose cells x halfspaces exceeds this (default " +
                      std::to_string(limits.max_side_entries) + "; 0: no limit)")
      ->check(non_negative());
  cmd->add_option("--max-triangles", limits.max_triangles,
                  "3D scenes: refuse an arrangement with more refined triangles than this (default " +
                      std::to_string(limits.max_triangles) + "; 0: no limit)")
      ->check(non_negative());
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
