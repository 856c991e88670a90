// hsx: exact-arithmetic research and verification engine for halfspace-based solid modelling.
#include "cli/commands.hpp"
#include <hsx/geometry/scene.hpp>
#include <hsx/io/files.hpp>
#include <hsx/kernel/memory.hpp>

#include <iostream>
#include <new>

#ifdef HSX_WITH_JEMALLOC
// jemalloc's settings for this program, read when it starts (MALLOC_CONF in the environment overrides them). Freed
// pages stay with the program for reuse instead of being handed back to the system over the following seconds
// (jemalloc's default "decay"): a loop that builds and frees large tables, one scene after another, otherwise
// pays a page fault for every page it touches again. Measured (docs/limits.md, session 21): at 10,000 cells
// hsx::arrange's complex took 30-41 ms with the default and 11-16 ms without decay, and a campaign of 300 scenes
// 2.51-2.58 s against 2.18-2.50 s. The price is a resident size at its high-water mark (that campaign: 28 MB
// instead of 23-24 MB); the address space used is the same (jemalloc retains its mappings either way).
// Freed extents may also be split for requests up to 1024 times smaller (lg_extent_max_active_fit 10; jemalloc's
// default is 64 times): without purging, freed memory is only useful if it can be reused, and with the default a
// loop alternating hsx::arrange at 10,000 cells with other work kept carving fresh pages instead, its resident size
// growing by 6.6 MB per arrangement (81 -> 247 MB over 25) with a thousand page faults each. Measured (docs/
// limits.md, session 23): that loop stays at 84-87 MB with almost no faults; a campaign of 200 scenes of 24-32
// halfspaces peaks at 31 MB instead of 74 MB.
extern "C" {
const char* malloc_conf = "dirty_decay_ms:-1,muzzy_decay_ms:-1,lg_extent_max_active_fit:10";
}
#endif

namespace {

/// Parses the command line and runs its command; the exit code.
int run_program(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::RuntimeError& e) {  // a command's own non-zero status (e.g. a failed check)
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (const hsx::InputError& e) {
    std::cerr << "hsx: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "hsx: error: out of memory: this input needs more memory than the process may use (docs/limits.md"
                 " says how time and memory grow with the input, and which limits bound them)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "hsx: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  hsx::cli::occupy_closed_standard_descriptors();
  hsx::remove_temporary_outputs_on_signals();
  hsx::install_gmp_allocation_handlers();
  hsx::install_out_of_memory_reserve(std::size_t{16} << 20);  // room to unwind and report "out of memory"
  CLI::App app{"hsx: exact arrangements, BSH shapes and halfspace CSG, with certified answers"};
  app.set_version_flag("--version", std::string("hsx ") + HSX_VERSION);
  app.require_subcommand(1);
  hsx::cli::add_arrange_command(app);
  hsx::cli::add_extract_command(app);
  hsx::cli::add_check_command(app);
  hsx::cli::add_grade_command(app);
  hsx::cli::add_csg_commands(app);
  hsx::cli::add_nhtree_command(app);
  hsx::cli::add_nhsurvey_command(app);
  hsx::cli::add_reference_command(app);
  hsx::cli::add_campaign_command(app);
  hsx::cli::add_bench_command(app);
  hsx::cli::read_integers_in_decimal(app);
  // Once the whole command line is parsed, before any command runs: no output may replace one of the inputs.
  app.parse_complete_callback([&app] { hsx::cli::refuse_outputs_over_inputs(app); });
  int code = run_program(app, argc, argv);
  // What was printed must have arrived: a full disk or a closed descriptor behind standard output is an error (exit
  // 2 instead of a success; a run that already failed keeps its code, a check's 3 or 4 too).
  if (code != 1 && code != 2) {
    const std::string error = hsx::cli::standard_output_error();
    if (!error.empty()) {
      std::cerr << "hsx: error: cannot write standard output: " << error << "\n";
      if (code == 0) code = 2;
    }
  }
  return code;
}
