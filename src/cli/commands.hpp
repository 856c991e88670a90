// The `hsx` program's subcommands. Each command file adds its subcommand to the app; errors travel as
// exceptions: InputError -> exit 2 (bad input), anything else -> exit 1 (internal error).
#pragma once

#include <CLI/CLI.hpp>

namespace hsx::cli {

void add_arrange_command(CLI::App& app);
void add_extract_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_csg_commands(CLI::App& app);
void add_nhtree_command(CLI::App& app);
void add_nhsurvey_command(CLI::App& app);

}  // namespace hsx::cli
