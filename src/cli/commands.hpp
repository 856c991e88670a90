// The `hsx` program's subcommands. Each command file adds its subcommand to the app; errors travel as
// exceptions: InputError -> exit 2 (bad input), anything else -> exit 1 (internal error).
#pragma once

#include <CLI/CLI.hpp>

#include <memory>

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

void add_arrange_command(CLI::App& app);
void add_extract_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_csg_commands(CLI::App& app);
void add_nhtree_command(CLI::App& app);
void add_nhsurvey_command(CLI::App& app);

}  // namespace hsx::cli
