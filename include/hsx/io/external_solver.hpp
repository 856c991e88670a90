// Another program run as a BSH solver on one input, so that its answer can be graded (`hsx grade --run`, and
// campaigns against other implementations): hsx writes the input in the form the program reads, runs the
// command, and reads the labelling it wrote (io/labelling.hpp: any accepted format).
//
// The command is a shell command line (run by /bin/sh -c) in which `{input}` and `{output}` stand for the two
// files; each must occur at least once. They are replaced by single-quoted absolute paths in a fresh private
// folder (under $TMPDIR, else /tmp) that is removed afterwards, whatever happens. The program runs in hsx's working
// folder (so relative paths in the command work), in a process group of its own, with standard input from
// /dev/null; its standard output and error are kept (their last 4 KiB) for the report. Each file it writes (that
// log, {output}, any other) may hold at most 256 MiB, or less when hsx itself runs under a lower file size limit
// (ulimit -f): past it the program is ended by SIGXFSZ (exit status 153), so one that writes without end fills
// neither the disk nor hsx's memory.
//
// Between hsx and the shell stands a keeper process, a child subreaper (Linux's PR_SET_CHILD_SUBREAPER): every
// process the program starts and leaves behind becomes the keeper's child when its parent ends, even one that
// started a session of its own (setsid, a daemon's double fork). When the shell ends, or when the time limit
// passes (hsx sends the keeper SIGTERM), the keeper kills the shell's process group and then every such process
// until none is left, so nothing the program started outlives the run. When hsx itself ends while the program
// runs (killed, even by SIGKILL or the out-of-memory killer), the kernel sends the keeper SIGTERM
// (PR_SET_PDEATHSIG): it ends everything the program started, as at the time limit, then removes hsx's private
// folder.
#pragma once

#include <hsx/io/input.hpp>
#include <hsx/io/labelling.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace hsx {

/// What `{input}` holds.
enum class ExternalInput {
  BshGraphcut,  ///< the BSH authors' graph-cut input (bsh_graphcut_to_json)
  Complex,      ///< the hsx-complex/1 document (`hsx arrange --json`)
};

/// Parses "bsh-graphcut" or "complex"; nullopt otherwise.
std::optional<ExternalInput> external_input_from_string(const std::string& name);

struct ExternalSolver {
  std::string command;  ///< shell command with {input} and {output} (see above)
  ExternalInput input = ExternalInput::BshGraphcut;
  std::int64_t weight_scale = kDefaultGraphcutWeightScale;  ///< for ExternalInput::BshGraphcut
  double time_limit = 0;  ///< seconds (0: none); when it passes the program is killed
};

/// Throws InputError when the command is empty or lacks {input} or {output}, or the time limit is negative or
/// not finite.
void check_external_solver(const ExternalSolver& solver);

struct ExternalRun {
  bool ran = false;          ///< the program was started and ended by itself (not killed by the time limit)
  bool timed_out = false;    ///< killed when the time limit passed
  int exit_status = -1;      ///< its exit status when it exited; 128 + N when signal N ended it
  double seconds = 0;        ///< wall-clock time from start to end
  std::string output_tail;   ///< the last 4 KiB of its standard output and error, interleaved as written
  /// Its labelling when it exited with status 0 and {output} holds one; otherwise empty and `problem` says why
  /// ("exit status 3", "exit status 153 (SIGXFSZ: ...)", "killed after 10 s", "{output}: line 2: ...", "{output}
  /// was not written").
  std::optional<ReadLabelling> labelling;
  std::string problem;
};

/// Runs `solver` on `in` (see above). Throws InputError for a bad solver (check_external_solver) and OutputError
/// when the private folder cannot be made or written; everything the program does wrong is in the result.
ExternalRun run_external_solver(const LoadedInput& in, const ExternalSolver& solver);

}  // namespace hsx
