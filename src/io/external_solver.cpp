#include <hsx/io/external_solver.hpp>

#include <hsx/io/files.hpp>
#include <hsx/io/temporary_folder.hpp>
#include <hsx/hsx.hpp>

#include <algorithm>
#include <cerrno>
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
#include <time.h>
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

/// In the program's process, before exec: its files bounded by `max_file_bytes` (past it SIGXFSZ ends it; hsx
/// ignores SIGXFSZ (io/files.hpp), so the program gets back the default action), no signal blocked, standard input
/// from /dev/null, standard output and error into `log`; then /bin/sh -c `command`. Never returns.
[[noreturn]] void exec_shell(const char* command, const char* log, rlim_t max_file_bytes) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // the keeper killed: the shell goes too
  const rlimit size{max_file_bytes, max_file_bytes};
  setrlimit(RLIMIT_FSIZE, &size);
  signal(SIGXFSZ, SIG_DFL);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  const int null = open("/dev/null", O_RDONLY);
  const int out = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0600);
  if (null < 0 || out < 0 || dup2(null, 0) < 0 || dup2(out, 1) < 0 || dup2(out, 2) < 0) _exit(127);
  execl("/bin/sh", "sh", "-c", command, static_cast<char*>(nullptr));
  _exit(127);
}

/// Kills every child of the calling (single-threaded) process that /proc lists; false when /proc cannot list them
/// (a kernel without CONFIG_PROC_CHILDREN). Allocates nothing: it runs in a child forked from a threaded process.
bool kill_listed_children() {
  const int fd = open("/proc/thread-self/children", O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  char buffer[4096];
  long pid = 0;
  for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0 || (n < 0 && errno == EINTR);)
    for (ssize_t i = 0; i < n; ++i) {
      if (buffer[i] >= '0' && buffer[i] <= '9') {
        pid = pid * 10 + (buffer[i] - '0');
      } else if (pid > 0) {
        kill(static_cast<pid_t>(pid), SIGKILL);
        pid = 0;
      }
    }
  if (pid > 0) kill(static_cast<pid_t>(pid), SIGKILL);
  close(fd);
  return true;
}

/// The end of a keeper whose hsx has ended (killed, even by SIGKILL): nobody else will remove hsx's private
/// `folder`, so the keeper becomes `rm -rf` on it (exec: it allocates nothing). Never returns.
[[noreturn]] void remove_folder(const char* folder) {
  execl("/bin/rm", "rm", "-rf", "--", folder, static_cast<char*>(nullptr));
  _exit(127);
}

/// The keeper, a process between hsx (process `hsx`) and the program: it runs the shell and waits for it, or for
/// SIGTERM, sent by hsx when the time limit passed or by the kernel when hsx ended (PR_SET_PDEATHSIG), or for
/// SIGTERM, SIGINT or SIGHUP from elsewhere (`pkill hsx` reaches the keeper too: it is a fork of hsx). Then it
/// kills the shell's process group and, being a child subreaper, every process the program left behind, even one
/// that started a session of its own (its orphans become the keeper's children), until none is left. It exits with
/// the shell's exit status, or 128 + the signal that ended the shell; when hsx has ended, it removes hsx's private
/// `folder` instead. Allocates nothing (a child forked from a threaded process). Never returns.
[[noreturn]] void keep(const char* command, const char* log, rlim_t max_file_bytes, pid_t hsx, const char* folder) {
  prctl(PR_SET_PDEATHSIG, SIGTERM);  // hsx ended: clean up as at the time limit (SIGTERM is blocked: see start)
  if (getppid() != hsx) remove_folder(folder);  // hsx ended before that line: no signal will come
  prctl(PR_SET_CHILD_SUBREAPER, 1);
  // hsx's handlers remove hsx's temporary files (io/files.hpp): never from here. Their signals are blocked (see
  // start); those that stop the keeper stay blocked and are waited for, the others get their default action.
  for (int inherited : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGXCPU}) signal(inherited, SIG_DFL);
  signal(SIGCHLD, SIG_DFL);  // never SIG_IGN: that would reap the children before waitpid sees them
  sigset_t wake;
  sigemptyset(&wake);
  for (int waited : {SIGCHLD, SIGTERM, SIGINT, SIGHUP}) sigaddset(&wake, waited);
  sigprocmask(SIG_SETMASK, &wake, nullptr);
  const pid_t shell = fork();
  if (shell == 0) {
    setpgid(0, 0);
    exec_shell(command, log, max_file_bytes);
  }
  if (shell < 0) _exit(127);
  setpgid(shell, shell);
  int status = 0;
  bool ended = false, from_elsewhere = false;
  for (bool stop = false; !ended && !stop;) {
    int st = 0;
    for (pid_t done; (done = waitpid(-1, &st, WNOHANG)) > 0;)
      if (done == shell) {
        status = st;
        ended = true;
      }
    if (ended) break;
    siginfo_t info{};
    const int woken = sigwaitinfo(&wake, &info);
    stop = woken > 0 && woken != SIGCHLD;
    from_elsewhere = stop && !(woken == SIGTERM && info.si_pid == hsx);
  }
  kill(-shell, SIGKILL);
  for (;;) {
    const bool listed = kill_listed_children();
    int st = 0;
    const pid_t done = waitpid(-1, &st, listed ? 0 : WNOHANG);
    if (done < 0 && errno == EINTR) continue;
    if (done <= 0) break;  // none left (or, without /proc's list, none that has ended)
  }
  // A signal from elsewhere is most likely ending hsx as well: give it a second to end, then remove its folder.
  const timespec pause{0, 10'000'000};
  for (int waited = 0; from_elsewhere && waited < 100 && getppid() == hsx; ++waited) nanosleep(&pause, nullptr);
  if (getppid() != hsx) remove_folder(folder);
  if (!ended) _exit(128 + SIGKILL);
  _exit(WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status));
}

/// Starts the keeper (see keep) in a process group of its own, the program's output into `log` (in hsx's private
/// `folder`), each file it writes at most `max_file_bytes`; -1 on failure.
pid_t start(const std::string& command, const std::string& log, rlim_t max_file_bytes, const std::string& folder) {
  // The keeper starts with the signals hsx handles blocked: until it has set itself up, hsx's own handlers (which
  // remove hsx's temporary files) must not run in it.
  sigset_t handled, before;
  sigemptyset(&handled);
  for (int by_hsx : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGXCPU}) sigaddset(&handled, by_hsx);
  pthread_sigmask(SIG_BLOCK, &handled, &before);
  const pid_t hsx = getpid();
  const pid_t child = fork();
  if (child != 0) {
    pthread_sigmask(SIG_SETMASK, &before, nullptr);
    if (child > 0) setpgid(child, child);
    return child;
  }
  setpgid(0, 0);
  keep(command.c_str(), log.c_str(), max_file_bytes, hsx, folder.c_str());
}

/// Asks the keeper to end the program (SIGTERM) and waits for it; after 10 s, kills it (its shell goes with it,
/// by the shell's PR_SET_PDEATHSIG, though not what the program left in other process groups).
void end_keeper(pid_t keeper, int& status) {
  kill(keeper, SIGTERM);
  for (int waited = 0; waited < 1000; ++waited) {
    const pid_t done = waitpid(keeper, &status, WNOHANG);
    if (done == keeper || (done < 0 && errno != EINTR)) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  kill(-keeper, SIGKILL);
  while (waitpid(keeper, &status, 0) < 0 && errno == EINTR) {
  }
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
  const pid_t child = start(command, log_path, max_file_bytes, folder.path());
  if (child < 0) throw OutputError("cannot start the solver: fork failed");
  int status = 0;
  auto pause = std::chrono::microseconds(200);
  for (;;) {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child) break;
    if (done < 0 && errno != EINTR) break;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    if (solver.time_limit > 0 && elapsed > solver.time_limit) {
      end_keeper(child, status);
      run.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
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
