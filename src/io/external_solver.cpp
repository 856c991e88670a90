#include <hsx/io/external_solver.hpp>

#include <hsx/io/files.hpp>
#include <hsx/io/temporary_folder.hpp>
#include <hsx/hsx.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace hsx {
namespace {

constexpr std::size_t kTailBytes = 4096;
constexpr rlim_t kMaxFileBytes = rlim_t(256) << 20;  ///< the most the program may write to one file

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string replace_all(std::string text, const std::string& what, const std::string& with) {
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + with.size()))
    text.replace(at, what.size(), with);
  return text;
}

std::string input_text(const LoadedInput& in, const ExternalSolver& solver) {
  switch (solver.input) {
    case ExternalInput::BshGraphcut: return bsh_graphcut_to_json(in.complex(), solver.weight_scale).dump() + "\n";
    case ExternalInput::Complex: return complex_json_text(in);
  }
  return "";
}

/// The last kTailBytes of the file at `path` (only they are read).
std::string file_tail(const std::string& path) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = f ? static_cast<std::streamoff>(f.tellg()) : 0;
  const std::streamoff from = std::max<std::streamoff>(0, size - static_cast<std::streamoff>(kTailBytes));
  f.seekg(from);
  std::string tail(static_cast<std::size_t>(size - from), '\0');
  f.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  tail.resize(static_cast<std::size_t>(f.gcount()));
  return tail;
}

/// The most the program may write to one file: kMaxFileBytes, or the lower file size limit hsx runs under.
rlim_t solver_file_limit() {
  rlimit size{};
  if (getrlimit(RLIMIT_FSIZE, &size) != 0 || size.rlim_cur == RLIM_INFINITY) return kMaxFileBytes;
  return std::min(size.rlim_cur, kMaxFileBytes);
}

/// Starts `/bin/sh -c command` in hsx's working folder, its output into `log`, in a process group of its own, each
/// file it writes at most `max_file_bytes`; -1 on failure.
pid_t start(const std::string& command, const std::string& log, rlim_t max_file_bytes) {
  const pid_t child = fork();
  if (child != 0) {
    if (child > 0) setpgid(child, child);
    return child;
  }
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // hsx killed (Ctrl-C): the program goes too
  // Every file it writes (its log, {output}) is bounded: past `max_file_bytes` it is ended by SIGXFSZ, which hsx
  // itself ignores (io/files.hpp) and so must give back its default action.
  const rlimit size{max_file_bytes, max_file_bytes};
  setrlimit(RLIMIT_FSIZE, &size);
  signal(SIGXFSZ, SIG_DFL);
  const int null = open("/dev/null", O_RDONLY);
  const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  if (null < 0 || out < 0 || dup2(null, 0) < 0 || dup2(out, 1) < 0 || dup2(out, 2) < 0) _exit(127);
  execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
  _exit(127);
}

std::string seconds_text(double s) {
  std::ostringstream out;
  out << s;
  return out.str();
}

}  // namespace

std::optional<ExternalInput> external_input_from_string(const std::string& name) {
  if (name == "bsh-graphcut") return ExternalInput::BshGraphcut;
  if (name == "complex") return ExternalInput::Complex;
  return std::nullopt;
}

void check_external_solver(const ExternalSolver& solver) {
  if (solver.command.find_first_not_of(" \t") == std::string::npos) throw InputError("the solver command is empty");
  for (const char* placeholder : {"{input}", "{output}"})
    if (solver.command.find(placeholder) == std::string::npos)
      throw InputError("the solver command \"" + solver.command + "\" has no " + placeholder +
                       " (where its input and its labelling go)");
  if (!std::isfinite(solver.time_limit) || solver.time_limit < 0)
    throw InputError("the solver's time limit must be a finite number of seconds >= 0");
}

ExternalRun run_external_solver(const LoadedInput& in, const ExternalSolver& solver) {
  check_external_solver(solver);
  const TemporaryFolder folder("hsx-run");
  const std::string input_path = folder.file("input.json"), output_path = folder.file("output.json"),
                    log_path = folder.file("log.txt");
  {
    std::ofstream f(input_path, std::ios::binary);
    f << input_text(in, solver);
    if (!f.flush()) throw OutputError("cannot write the solver's input " + input_path);
  }
  const std::string command =
      replace_all(replace_all(solver.command, "{input}", shell_quoted(input_path)), "{output}", shell_quoted(output_path));

  ExternalRun run;
  const auto begin = std::chrono::steady_clock::now();
  const rlim_t max_file_bytes = solver_file_limit();
  const pid_t child = start(command, log_path, max_file_bytes);
  if (child < 0) throw OutputError("cannot start the solver: fork failed");
  int status = 0;
  auto pause = std::chrono::microseconds(200);
  for (;;) {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child) break;
    if (done < 0 && errno != EINTR) break;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    if (solver.time_limit > 0 && elapsed > solver.time_limit) {
      kill(-child, SIGKILL);
      while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
      }
      run.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
  kill(-child, SIGKILL);  // whatever it left running in its group
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  run.output_tail = file_tail(log_path);
  if (run.timed_out) {
    run.problem = "killed after " + seconds_text(solver.time_limit) + " s (the time limit)";
    return run;
  }
  run.ran = true;
  run.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
  if (run.exit_status != 0) {
    run.problem = "exit status " + std::to_string(run.exit_status) +
                  (run.exit_status == 127                 ? " (command not found?)"
                   : run.exit_status == 128 + SIGXFSZ     ? " (SIGXFSZ: it wrote a file past the limit of " +
                                                              std::to_string(max_file_bytes) + " bytes)"
                                                          : "");
    return run;
  }
  std::error_code missing;
  if (!std::filesystem::exists(output_path, missing)) {
    run.problem = "{output} was not written";
    return run;
  }
  try {
    run.labelling = read_labelling_text(read_file(output_path), "{output}", in.complex());
  } catch (const InputError& e) {
    run.problem = e.what();
  }
  return run;
}

}  // namespace hsx
