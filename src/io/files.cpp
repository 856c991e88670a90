#include <hsx/io/files.hpp>
#include <hsx/io/temporary_folder.hpp>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fcntl.h>
#include <iostream>
#include <limits.h>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace hsx {
namespace {

// ---- temporary files removed on SIGINT / SIGTERM / SIGHUP / SIGPIPE / SIGXCPU -----------------------------------
// A fixed table the signal handler can read without allocating: a slot holds a NUL-terminated path while `live`.

constexpr std::size_t kSlots = 64;
constexpr std::size_t kPathMax = 4096;
std::array<std::array<char, kPathMax>, kSlots> g_temp_paths;
std::array<volatile std::sig_atomic_t, kSlots> g_temp_live{};
std::mutex g_temp_mutex;

int register_temporary(const std::string& path) {
  if (path.size() + 1 > kPathMax) return -1;
  std::lock_guard<std::mutex> lock(g_temp_mutex);
  for (std::size_t s = 0; s < kSlots; ++s)
    if (!g_temp_live[s]) {
      std::memcpy(g_temp_paths[s].data(), path.c_str(), path.size() + 1);
      g_temp_live[s] = 1;
      return static_cast<int>(s);
    }
  return -1;  // more than kSlots outputs at once: still removed on failure, not on a signal
}

void unregister_temporary(int slot) {
  if (slot < 0) return;
  std::lock_guard<std::mutex> lock(g_temp_mutex);
  g_temp_live[static_cast<std::size_t>(slot)] = 0;
}

extern "C" void remove_temporaries_and_die(int signal_number) {
  for (std::size_t s = 0; s < kSlots; ++s)
    if (g_temp_live[s]) ::unlink(g_temp_paths[s].data());
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

std::string reason(int error) { return std::strerror(error); }

[[noreturn]] void fail(const std::string& option, const std::string& path, const std::string& why) {
  throw OutputError("cannot write " + (option.empty() ? "" : option + " ") + "\"" + path + "\": " + why);
}

// ---- where an output goes ---------------------------------------------------------------------------------------

enum class Kind { Stdout, Descriptor, Direct, Replace };

struct Target {
  Kind kind = Kind::Replace;
  std::string path;      ///< as given
  std::string option;
  std::string final;     ///< the file replaced (symlinks resolved) or written directly
  int descriptor = -1;   ///< Kind::Descriptor: /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N
  mode_t mode = 0644;    ///< Kind::Replace: the permission bits the new file gets
  bool existed = false;
  std::string identity;  ///< to refuse the same output twice
  std::string folder;    ///< Kind::Replace: the folder of `final`
  std::string temp;      ///< Kind::Replace: the temporary file's name (it exists unless `anonymous`)
  int temp_fd = -1;
  bool anonymous = false;  ///< temp_fd is an unnamed file (O_TMPFILE) in `folder`, named only at commit
  int slot = -1;
  bool has_content = false;
  std::string content;
};

std::string directory_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string base_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// The temporary file beside `final` (a file in `folder`): "FINAL.tmp-hsx-PID-N", N counting this process's
/// temporaries. When that name would be longer than the folder allows (a legal 255-byte output name leaves no room
/// for the suffix), the final name's part in it is shortened: the suffix alone keeps it unique.
std::string temporary_beside(const std::string& final, const std::string& folder) {
  static long counter = 0;
  const std::string suffix = ".tmp-hsx-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const std::string base = base_of(final);
  const long name_max = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  const std::size_t longest = name_max > 0 ? static_cast<std::size_t>(name_max) : NAME_MAX;
  if (base.size() + suffix.size() <= longest) return final + suffix;
  const std::size_t kept = longest > suffix.size() ? longest - suffix.size() : 0;
  return final.substr(0, final.size() - base.size()) + base.substr(0, kept) + suffix;
}

std::optional<int> descriptor_path(const std::string& path) {
  if (path == "/dev/stdout") return 1;
  if (path == "/dev/stderr") return 2;
  for (const char* prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    const std::string p = prefix;
    if (path.size() > p.size() && path.compare(0, p.size(), p) == 0 &&
        path.find_first_not_of("0123456789", p.size()) == std::string::npos && path.size() - p.size() <= 6)
      return std::stoi(path.substr(p.size()));
  }
  return std::nullopt;
}

std::string real_path(const std::string& path) {
  char buffer[PATH_MAX];
  if (!::realpath(path.c_str(), buffer)) return {};
  return buffer;
}

/// Creates `t.temp` (a new name when a file of that name is left from a killed run with the same process id) and
/// opens it as t.temp_fd, registered for removal on signals; 0 or the errno of the failure.
int create_named_temporary(Target& t) {
  for (int attempt = 0;; ++attempt) {
    t.slot = register_temporary(t.temp);
    t.temp_fd = ::open(t.temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (t.temp_fd >= 0) return 0;
    const int error = errno;
    unregister_temporary(t.slot);
    t.slot = -1;
    if (error != EEXIST || attempt == 100) {
      t.temp.clear();  // not ours: never removed
      return error;
    }
    t.temp = temporary_beside(t.final, t.folder);
  }
}

/// Gives the unnamed file t.temp_fd the name t.temp; false when this system cannot (then it stays unnamed).
bool name_anonymous_temporary(Target& t) {
  const std::string self = "/proc/self/fd/" + std::to_string(t.temp_fd);
  for (int attempt = 0; attempt <= 100; ++attempt) {
    t.slot = register_temporary(t.temp);
    // AT_EMPTY_PATH needs a privilege (CAP_DAC_READ_SEARCH); /proc/self/fd needs /proc.
    if (::linkat(t.temp_fd, "", AT_FDCWD, t.temp.c_str(), AT_EMPTY_PATH) == 0 ||
        ::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, t.temp.c_str(), AT_SYMLINK_FOLLOW) == 0) {
      t.anonymous = false;
      return true;
    }
    const int error = errno;
    unregister_temporary(t.slot);
    t.slot = -1;
    if (error != EEXIST) return false;
    t.temp = temporary_beside(t.final, t.folder);
  }
  return false;
}

/// Decides the kind of output and checks it can be written; for Kind::Replace creates the temporary file.
void resolve(Target& t) {
  if (t.path.empty()) fail(t.option, t.path, "an empty path");
  if (t.path == "-") {
    t.kind = Kind::Stdout;
    t.identity = "fd:1";
    return;
  }
  if (const std::optional<int> fd = descriptor_path(t.path)) {
    if (::fcntl(*fd, F_GETFD) == -1) fail(t.option, t.path, "file descriptor " + std::to_string(*fd) + " is not open");
    t.kind = Kind::Descriptor;
    t.descriptor = *fd;
    t.identity = "fd:" + std::to_string(*fd);
    return;
  }
  struct stat link_info {};
  t.final = t.path;
  if (::lstat(t.path.c_str(), &link_info) == 0 && S_ISLNK(link_info.st_mode)) {
    t.final = real_path(t.path);
    if (t.final.empty()) fail(t.option, t.path, "a symbolic link to a missing file (" + reason(errno) + ")");
  }
  struct stat info {};
  if (::stat(t.final.c_str(), &info) == 0) {
    t.existed = true;
    t.identity = "ino:" + std::to_string(info.st_dev) + ":" + std::to_string(info.st_ino);
    if (S_ISDIR(info.st_mode)) fail(t.option, t.path, "it is a directory");
    if (S_ISSOCK(info.st_mode)) fail(t.option, t.path, "it is a socket");
    if (S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode) || S_ISFIFO(info.st_mode)) {
      t.kind = Kind::Direct;  // written in place at commit: never replaced by a regular file
      if (::access(t.final.c_str(), W_OK) != 0) fail(t.option, t.path, reason(errno));
      return;
    }
    if (!S_ISREG(info.st_mode)) fail(t.option, t.path, "not a regular file");
    // A file its owner made read-only is not replaced, though the rename into its writable folder would succeed.
    if (::access(t.final.c_str(), W_OK) != 0) fail(t.option, t.path, reason(errno) + " (the file is read-only)");
    t.mode = info.st_mode & 07777;
  } else if (errno != ENOENT) {
    fail(t.option, t.path, reason(errno));
  }
  const std::string folder = directory_of(t.final);
  struct stat folder_info {};
  if (::stat(folder.c_str(), &folder_info) != 0) fail(t.option, t.path, "no folder \"" + folder + "\" (" + reason(errno) + ")");
  if (!S_ISDIR(folder_info.st_mode)) fail(t.option, t.path, "\"" + folder + "\" is not a folder");
  if (!t.existed) t.identity = "new:" + real_path(folder) + "/" + base_of(t.final);
  t.kind = Kind::Replace;
  t.folder = folder;
  // An unnamed file first: it has no name until commit, so a run killed by SIGKILL (or the OOM killer) while
  // computing leaves nothing behind. A file system without O_TMPFILE gets a named temporary file at once.
  t.temp = temporary_beside(t.final, folder);
  t.temp_fd = ::open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  t.anonymous = t.temp_fd >= 0;
  if (t.anonymous) return;
  if (const int error = create_named_temporary(t))
    fail(t.option, t.path, "cannot create a file in \"" + folder + "\" (" + reason(error) + ")");
}

/// Writes all of `content` to `fd`; returns 0 or the errno of the failure.
int write_all(int fd, const std::string& content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

/// Writes t.content to the temporary file with its final permission bits, names it (an unnamed file, or, where
/// it cannot be named, a named file written again), and closes it; 0 or the errno of the failure.
int fill_temporary(Target& t) {
  const auto fill = [&t] {
    if (const int error = write_all(t.temp_fd, t.content)) return error;
    return ::fchmod(t.temp_fd, t.mode) == 0 ? 0 : errno;
  };
  if (const int error = fill()) return error;
  if (t.anonymous && !name_anonymous_temporary(t)) {
    ::close(t.temp_fd);
    t.temp_fd = -1;
    t.anonymous = false;
    if (const int error = create_named_temporary(t)) return error;
    if (const int error = fill()) return error;
  }
  const int closed = ::close(t.temp_fd);
  t.temp_fd = -1;
  return closed == 0 ? 0 : errno;
}

void discard_temporary(Target& t) {
  if (t.temp_fd >= 0) ::close(t.temp_fd);
  t.temp_fd = -1;
  if (!t.temp.empty() && !t.anonymous) ::unlink(t.temp.c_str());
  unregister_temporary(t.slot);
  t.slot = -1;
  t.temp.clear();
}

}  // namespace

struct OutputFiles::Impl {
  std::vector<Target> targets;
  std::optional<std::string> report;  ///< for standard output (print)
  std::map<std::string, std::size_t> by_path;
  std::map<std::string, std::string> identities;  ///< identity -> option that expected it
  std::map<std::string, std::pair<std::string, std::string>> inputs;  ///< identity -> (name, path), of protect
};

namespace {

/// The identity (as Target::identity) of the existing regular file at `path`; "" for anything else.
std::string regular_file_identity(const std::string& path) {
  struct stat info {};
  if (path.empty() || path == "-" || ::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return "";
  return "ino:" + std::to_string(info.st_dev) + ":" + std::to_string(info.st_ino);
}

[[noreturn]] void refuse_over_input(const std::string& option, const std::string& path, const std::string& name,
                                    const std::string& input) {
  throw InputError("cannot write " + option + " \"" + path + "\": it is the same file as the input " + name + " \"" +
                   input + "\"; hsx does not replace a file it reads (write elsewhere)");
}

}  // namespace

void refuse_output_over_input(const std::string& output_option, const std::string& output,
                              const std::string& input_name, const std::string& input) {
  const std::string identity = regular_file_identity(output);
  if (!identity.empty() && identity == regular_file_identity(input))
    refuse_over_input(output_option, output, input_name, input);
}

OutputFiles::OutputFiles() : impl_(std::make_unique<Impl>()) {}

OutputFiles::~OutputFiles() {
  for (Target& t : impl_->targets) discard_temporary(t);
}

void OutputFiles::expect(const std::string& path, const std::string& option) {
  if (path.empty()) return;
  Target t;
  t.path = path;
  t.option = option;
  resolve(t);
  const auto same = impl_->identities.find(t.identity);
  if (impl_->by_path.count(path) || same != impl_->identities.end()) {
    discard_temporary(t);
    fail(option, path, "the same file is already the output of " +
                           (same != impl_->identities.end() ? same->second : std::string("another option")));
  }
  if (const auto input = impl_->inputs.find(t.identity); input != impl_->inputs.end()) {
    discard_temporary(t);
    refuse_over_input(option, path, input->second.first, input->second.second);
  }
  impl_->identities[t.identity] = option;
  impl_->by_path[path] = impl_->targets.size();
  impl_->targets.push_back(std::move(t));
}

void OutputFiles::protect(const std::string& path, const std::string& name) {
  const std::string identity = regular_file_identity(path);
  if (identity.empty()) return;
  if (impl_->identities.count(identity))
    for (const Target& t : impl_->targets)
      if (t.identity == identity) refuse_over_input(t.option, t.path, name, path);
  impl_->inputs.emplace(identity, std::make_pair(name, path));
}

void OutputFiles::put(const std::string& path, std::string content) {
  if (path.empty()) return;
  const auto it = impl_->by_path.find(path);
  if (it == impl_->by_path.end()) throw std::logic_error("OutputFiles::put: \"" + path + "\" was not expected");
  Target& t = impl_->targets[it->second];
  t.content = std::move(content);
  t.has_content = true;
}

void OutputFiles::print(const std::string& text) {
  if (!impl_->report) impl_->report.emplace();
  *impl_->report += text;
}

void OutputFiles::commit() {
  std::vector<Target>& targets = impl_->targets;
  const auto discard_all = [&] {
    for (Target& u : targets) discard_temporary(u);
  };
  const auto cleanup_and_fail = [&](const Target& t, const std::string& why) {
    const std::string option = t.option, path = t.path;
    discard_all();
    fail(option, path, why);
  };
  // Writes `text` to std::cout; 0 when it arrived, else the errno of the failure (-1 when an earlier write failed).
  const auto print = [](const std::string& text) {
    errno = 0;
    std::cout << text;
    std::cout.flush();
    return std::cout ? 0 : errno != 0 ? errno : -1;
  };
  // 1. Every regular file in full to its temporary file, and every device or FIFO: the steps that can fail.
  for (Target& t : targets) {
    if (!t.has_content) continue;
    if (t.kind == Kind::Replace) {
      if (const int error = fill_temporary(t)) cleanup_and_fail(t, reason(error));
    } else if (t.kind == Kind::Direct) {
      const int fd = ::open(t.final.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
      if (fd < 0) cleanup_and_fail(t, reason(errno));
      const int error = write_all(fd, t.content);
      ::close(fd);
      if (error) cleanup_and_fail(t, reason(error));
    } else if (t.kind == Kind::Descriptor) {
      if (t.descriptor == 1) std::cout.flush();
      if (const int error = write_all(t.descriptor, t.content)) cleanup_and_fail(t, reason(error));
    } else {
      if (print(t.content) != 0) cleanup_and_fail(t, "standard output failed");
    }
  }
  // 2. The report, the last step that can fail before anything is renamed.
  if (impl_->report) {
    const int error = print(*impl_->report);
    impl_->report.reset();
    if (error != 0) {
      discard_all();
      throw OutputError("cannot write standard output: " +
                        (error > 0 ? reason(error) : std::string("an earlier write to it failed")));
    }
  }
  // 3. The renames.
  for (Target& t : targets) {
    if (t.kind != Kind::Replace) continue;
    if (!t.has_content) {
      discard_temporary(t);
      continue;
    }
    if (::rename(t.temp.c_str(), t.final.c_str()) != 0) cleanup_and_fail(t, "rename failed (" + reason(errno) + ")");
    unregister_temporary(t.slot);
    t.slot = -1;
    t.temp.clear();
  }
  targets.clear();
  impl_->by_path.clear();
  impl_->identities.clear();
}

void write_file_atomically(const std::string& path, const std::string& content) {
  if (path.empty()) fail("", path, "an empty path");
  OutputFiles out;
  out.expect(path, "");
  out.put(path, content);
  out.commit();
}

void remove_temporary_outputs_on_signals() {
  struct sigaction action {};
  action.sa_handler = remove_temporaries_and_die;
  sigemptyset(&action.sa_mask);
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGXCPU}) ::sigaction(s, &action, nullptr);
  // Past the file size limit (ulimit -f) a write then fails with EFBIG, an error like a full disk, instead of the
  // signal ending the process with half a temporary file left.
  ::signal(SIGXFSZ, SIG_IGN);
}

namespace {

/// Reads `fd` to its end; `name` ("\"PATH\"" or "standard input") for messages.
std::string read_to_end(int fd, const std::string& name, std::size_t max_bytes) {
  std::string content;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError("cannot read " + name + ": " + reason(errno));
    if (n == 0) return content;
    content.append(buffer, static_cast<std::size_t>(n));
    if (content.size() > max_bytes)
      throw InputError(name + " is too large (the limit is " + std::to_string(max_bytes) + " bytes)");
  }
}

}  // namespace

std::string read_file(const std::string& path, std::size_t max_bytes) {
  if (path == "-") return read_to_end(0, "standard input", max_bytes);
  const std::string name = "\"" + path + "\"";
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) throw InputError("cannot read " + name + ": " + reason(errno));
  if (S_ISDIR(info.st_mode)) throw InputError("cannot read " + name + ": it is a directory");
  const bool stream = S_ISFIFO(info.st_mode) || S_ISCHR(info.st_mode);
  if (!S_ISREG(info.st_mode) && !stream)
    throw InputError("cannot read " + name + ": not a regular file, FIFO or character device");
  if (S_ISREG(info.st_mode) && static_cast<std::size_t>(info.st_size) > max_bytes)
    throw InputError(name + " is too large (" + std::to_string(info.st_size) + " bytes; the limit is " +
                     std::to_string(max_bytes) + ")");
  // O_NONBLOCK: opening a FIFO never waits for a writer. Reads then block again, and a FIFO without a writer
  // reads as empty (end of file) instead of hanging.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) throw InputError("cannot read " + name + ": " + reason(errno));
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  try {
    std::string content = read_to_end(fd, name, max_bytes);
    ::close(fd);
    return content;
  } catch (...) {
    ::close(fd);
    throw;
  }
}

TemporaryFolder::TemporaryFolder(const std::string& prefix) {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/" + prefix + ".XXXXXX";
  if (!mkdtemp(pattern.data())) throw OutputError("cannot make a private folder " + pattern + ": " + std::strerror(errno));
  path_ = pattern;
}

TemporaryFolder::~TemporaryFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace hsx
