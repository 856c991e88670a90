// The output policy of io/files.hpp, on real files in a temporary folder: regular files replaced atomically (mode
// kept), links followed, devices and FIFOs written in place, directories and missing folders refused, a run's
// outputs all or none (the printed report included), temporary files gone after a failure, a SIGTERM or a SIGPIPE;
// reading never blocks on a FIFO.
#include <hsx/io/files.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <dirent.h>
#include <fcntl.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace hsx;

namespace {

struct TempDir {
  std::string path;
  TempDir() {
    char name[] = "/tmp/hsx-files-XXXXXX";
    path = ::mkdtemp(name);
  }
  ~TempDir() { std::system(("rm -rf '" + path + "'").c_str()); }
  std::string operator/(const std::string& name) const { return path + "/" + name; }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    DIR* d = ::opendir(path.c_str());
    while (dirent* e = ::readdir(d))
      if (std::string(e->d_name) != "." && std::string(e->d_name) != "..") names.push_back(e->d_name);
    ::closedir(d);
    std::sort(names.begin(), names.end());
    return names;
  }
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void spit(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

mode_t mode_of(const std::string& path) {
  struct stat st {};
  ::lstat(path.c_str(), &st);
  return st.st_mode;
}

}  // namespace

TEST_CASE("files: a regular file is replaced, keeping its mode; a new one is created", "[files]") {
  TempDir dir;
  spit(dir / "a.json", "old");
  ::chmod((dir / "a.json").c_str(), 0640);
  write_file_atomically(dir / "a.json", "new");
  CHECK(slurp(dir / "a.json") == "new");
  CHECK((mode_of(dir / "a.json") & 07777) == 0640);
  write_file_atomically(dir / "b.json", "fresh");
  CHECK(slurp(dir / "b.json") == "fresh");
  CHECK(dir.entries() == std::vector<std::string>{"a.json", "b.json"});
}

TEST_CASE("files: an output name as long as the folder allows is written (its temporary name is shortened)",
          "[files]") {
  TempDir dir;
  const long name_max = ::pathconf(dir.path.c_str(), _PC_NAME_MAX);
  REQUIRE(name_max > 20);
  // Two names of the longest length that differ only in their last bytes: their temporaries share the same shortened
  // prefix, and must still be two files.
  const std::string a(static_cast<std::size_t>(name_max) - 5, 'n');
  spit(dir / (a + ".json"), "old");
  OutputFiles out;
  out.expect(dir / (a + ".json"), "--json");
  out.expect(dir / (a + ".svgz"), "--svg");
  out.put(dir / (a + ".json"), "replaced");
  out.put(dir / (a + ".svgz"), "<svg/>");
  out.commit();
  CHECK(slurp(dir / (a + ".json")) == "replaced");
  CHECK(slurp(dir / (a + ".svgz")) == "<svg/>");
  CHECK(dir.entries() == std::vector<std::string>{a + ".json", a + ".svgz"});
  // One byte more is not a legal name: refused before anything is computed, as the system says.
  CHECK_THROWS_WITH(OutputFiles().expect(dir / (a + ".json5"), "--json"), Catch::Contains("File name too long"));
}

TEST_CASE("files: a symbolic link is followed, and stays a link", "[files]") {
  TempDir dir;
  spit(dir / "t.json", "keep");
  REQUIRE(::symlink("t.json", (dir / "l.json").c_str()) == 0);
  write_file_atomically(dir / "l.json", "through the link");
  CHECK(S_ISLNK(mode_of(dir / "l.json")));
  CHECK(slurp(dir / "t.json") == "through the link");
  REQUIRE(::symlink("missing.json", (dir / "dangling.json").c_str()) == 0);
  CHECK_THROWS_WITH(write_file_atomically(dir / "dangling.json", "x"), Catch::Contains("link to a missing file"));
}

TEST_CASE("files: devices and FIFOs are written in place, never replaced", "[files]") {
  write_file_atomically("/dev/null", "gone");
  CHECK(S_ISCHR(mode_of("/dev/null")));
  CHECK_THROWS_AS(write_file_atomically("/dev/full", "x"), OutputError);
  CHECK(S_ISCHR(mode_of("/dev/full")));
  TempDir dir;
  REQUIRE(::mkfifo((dir / "fifo").c_str(), 0600) == 0);
  const pid_t reader = ::fork();
  if (reader == 0) {  // a reader, so that opening the FIFO for writing does not block
    std::ifstream in(dir / "fifo");
    std::string line;
    std::getline(in, line);
    ::_exit(line == "through the fifo" ? 0 : 1);
  }
  write_file_atomically(dir / "fifo", "through the fifo\n");
  int status = 0;
  ::waitpid(reader, &status, 0);
  CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
  CHECK(S_ISFIFO(mode_of(dir / "fifo")));
}

TEST_CASE("files: what cannot be written is an OutputError naming the path", "[files]") {
  TempDir dir;
  ::mkdir((dir / "d").c_str(), 0700);
  CHECK_THROWS_WITH(write_file_atomically(dir / "d", "x"), Catch::Contains("is a directory") && Catch::Contains("/d\""));
  CHECK_THROWS_WITH(write_file_atomically(dir / "no/such/folder.json", "x"), Catch::Contains("no folder"));
  CHECK_THROWS_WITH(write_file_atomically("", "x"), Catch::Contains("empty path"));
  CHECK_THROWS_AS(write_file_atomically("/proc/out.svg", "x"), OutputError);
  CHECK(dir.entries() == std::vector<std::string>{"d"});
}

TEST_CASE("files: a read-only file is not replaced, though its folder is writable", "[files]") {
  // Root may write anything, so the check runs in a child that, when started as root, becomes `nobody` first.
  TempDir dir;
  spit(dir / "ro.json", "keep");
  const pid_t child = ::fork();
  if (child == 0) {
    const uid_t nobody = 65534;
    if (::geteuid() == 0 &&
        (::chown(dir.path.c_str(), nobody, nobody) != 0 || ::chown((dir / "ro.json").c_str(), nobody, nobody) != 0 ||
         ::setgid(nobody) != 0 || ::setuid(nobody) != 0))
      ::_exit(10);
    if (::chmod((dir / "ro.json").c_str(), 0444) != 0) ::_exit(11);
    try {
      write_file_atomically(dir / "ro.json", "replaced");
      ::_exit(12);  // replaced: the check is missing
    } catch (const OutputError& e) {
      ::_exit(std::string(e.what()).find("read-only") != std::string::npos ? 0 : 13);
    }
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(slurp(dir / "ro.json") == "keep");
  CHECK(dir.entries() == std::vector<std::string>{"ro.json"});
}

TEST_CASE("files: a run's outputs are written all or none", "[files]") {
  TempDir dir;
  spit(dir / "old.json", "old");
  {
    OutputFiles out;
    out.expect(dir / "old.json", "--json");
    out.expect(dir / "new.svg", "--svg");
    CHECK_THROWS_WITH(out.expect(dir / "old.json", "--other"), Catch::Contains("already the output of --json"));
    out.put(dir / "old.json", "replaced");
    out.put(dir / "new.svg", "<svg/>");
    // no commit: the run failed after computing
  }
  CHECK(dir.entries() == std::vector<std::string>{"old.json"});
  CHECK(slurp(dir / "old.json") == "old");
  {
    OutputFiles out;
    out.expect(dir / "old.json", "--json");
    out.expect("/dev/full", "--svg");  // fails at commit, after old.json's temporary file is written
    out.put(dir / "old.json", "replaced");
    out.put("/dev/full", "<svg/>");
    CHECK_THROWS_WITH(out.commit(), Catch::Contains("--svg") && Catch::Contains("/dev/full"));
  }
  CHECK(dir.entries() == std::vector<std::string>{"old.json"});
  CHECK(slurp(dir / "old.json") == "old");
  OutputFiles out;
  out.expect(dir / "old.json", "--json");
  out.expect(dir / "unused.txt", "--conf");  // expected, never put: left alone
  out.put(dir / "old.json", "replaced");
  out.commit();
  CHECK(slurp(dir / "old.json") == "replaced");
  CHECK(dir.entries() == std::vector<std::string>{"old.json"});
}

TEST_CASE("files: a protected input is never an output, whichever comes first", "[files]") {
  TempDir dir;
  spit(dir / "mesh.obj", "v");
  ::symlink((dir / "mesh.obj").c_str(), (dir / "link.obj").c_str());
  {
    OutputFiles out;
    out.protect(dir / "mesh.obj", "the mesh");
    out.protect(dir / "missing.obj", "nothing");  // not a file: ignored
    out.protect("-", "standard input");           // ignored
    CHECK_THROWS_AS(out.expect(dir / "link.obj", "--obj"), InputError);
    CHECK_THROWS_WITH(out.expect(dir / "mesh.obj", "--obj"),
                      Catch::Contains("cannot write --obj \"" + (dir / "mesh.obj") +
                                      "\": it is the same file as the input the mesh \"" + (dir / "mesh.obj") + "\""));
    out.expect(dir / "missing.obj", "--json");
    out.expect(dir / "other.obj", "--svg");
  }
  {
    OutputFiles out;
    out.expect(dir / "link.obj", "--obj (its .mtl)");
    CHECK_THROWS_WITH(out.protect(dir / "mesh.obj", "INPUT"), Catch::Contains("cannot write --obj (its .mtl)"));
  }
  CHECK(dir.entries() == std::vector<std::string>{"link.obj", "mesh.obj"});
  CHECK(slurp(dir / "mesh.obj") == "v");
}

TEST_CASE("files: refuse_output_over_input compares files, not spellings", "[files]") {
  TempDir dir;
  spit(dir / "scene.json", "{}");
  ::symlink((dir / "scene.json").c_str(), (dir / "link.json").c_str());
  ::link((dir / "scene.json").c_str(), (dir / "hard.json").c_str());
  for (const std::string& output : {dir / "scene.json", dir / "link.json", dir / "hard.json"})
    CHECK_THROWS_WITH(refuse_output_over_input("--json", output, "scene", dir / "scene.json"),
                      Catch::Contains("cannot write --json \"" + output + "\": it is the same file as the input scene"));
  CHECK_NOTHROW(refuse_output_over_input("--json", dir / "other.json", "scene", dir / "scene.json"));  // missing
  CHECK_NOTHROW(refuse_output_over_input("--json", "-", "scene", "-"));                                // never files
  CHECK_NOTHROW(refuse_output_over_input("--json", "", "scene", ""));
  CHECK_NOTHROW(refuse_output_over_input("--json", dir.path, "scene", dir.path));                      // a folder
  spit(dir / "copy.json", "{}");
  CHECK_NOTHROW(refuse_output_over_input("--json", dir / "copy.json", "scene", dir / "scene.json"));  // equal text
}

namespace {

/// Standard output's stand-in while a test runs: keeps what is written, and what `watched` held at the first write.
class WatchingBuffer : public std::stringbuf {
 public:
  explicit WatchingBuffer(std::string watched) : watched_(std::move(watched)) {}
  std::string at_first_write;

 protected:
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (!seen_) at_first_write = slurp(watched_);
    seen_ = true;
    return std::stringbuf::xsputn(s, n);
  }

 private:
  std::string watched_;
  bool seen_ = false;
};

}  // namespace

TEST_CASE("files: the printed report is written before any file is put in place, or nothing is", "[files]") {
  TempDir dir;
  spit(dir / "old.json", "old");
  WatchingBuffer printed(dir / "old.json");
  std::streambuf* const standard = std::cout.rdbuf(&printed);
  {
    OutputFiles out;
    out.expect(dir / "old.json", "--json");
    out.put(dir / "old.json", "replaced");
    out.print("summary ");
    out.print("line\n");
    out.commit();
  }
  CHECK(printed.str() == "summary line\n");
  CHECK(printed.at_first_write == "old");  // the report went out while the file was still the old one
  CHECK(slurp(dir / "old.json") == "replaced");
  {
    OutputFiles out;
    out.expect(dir / "old.json", "--json");
    out.put(dir / "old.json", "again");
    out.print("");              // nothing more to print, but what was printed before must have arrived:
    std::cout.setstate(std::ios::badbit);  // an earlier write to standard output failed
    CHECK_THROWS_WITH(out.commit(), Catch::Contains("cannot write standard output"));
  }
  std::cout.clear();
  std::cout.rdbuf(standard);
  CHECK(slurp(dir / "old.json") == "replaced");
  CHECK(dir.entries() == std::vector<std::string>{"old.json"});
}

TEST_CASE("files: SIGPIPE (standard output's reader gone) removes the temporary files too", "[files]") {
  TempDir dir;
  const pid_t child = ::fork();
  if (child == 0) {
    remove_temporary_outputs_on_signals();
    int ends[2];
    if (::pipe(ends) != 0 || ::dup2(ends[1], 1) < 0) ::_exit(10);
    ::close(ends[0]);  // no reader left
    OutputFiles out;
    out.expect(dir / "out.json", "--json");
    out.put(dir / "out.json", "content");
    out.print("the report\n");
    try {
      out.commit();
    } catch (...) {
    }
    ::_exit(11);  // not reached: the write to the pipe raises SIGPIPE
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGPIPE);
  CHECK(dir.entries().empty());
}

TEST_CASE("files: SIGTERM removes the temporary files of outputs not yet committed", "[files]") {
  TempDir dir;
  const pid_t child = ::fork();
  if (child == 0) {
    remove_temporary_outputs_on_signals();
    OutputFiles out;
    out.expect(dir / "big.json", "--json");
    out.put(dir / "big.json", std::string(1 << 20, 'x'));
    std::raise(SIGTERM);
    ::_exit(0);  // not reached
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK(dir.entries().empty());
}

TEST_CASE("files: SIGKILL while computing leaves no temporary file where the file system has unnamed files",
          "[files]") {
  TempDir dir;
  const int probe = ::open(dir.path.c_str(), O_TMPFILE | O_WRONLY, 0600);
  const bool unnamed = probe >= 0;
  if (probe >= 0) ::close(probe);
  const pid_t child = ::fork();
  if (child == 0) {
    OutputFiles out;
    out.expect(dir / "out.json", "--json");
    out.put(dir / "out.json", "computed");
    std::raise(SIGKILL);  // no handler can run: only a file without a name is gone with the process
    ::_exit(0);           // not reached
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  CHECK(WIFSIGNALED(status));
  const std::vector<std::string> left = dir.entries();
  if (unnamed) {
    CHECK(left.empty());
  } else {  // the fallback: a named temporary file, which only a catchable signal removes
    REQUIRE(left.size() == 1);
    CHECK_THAT(left[0], Catch::StartsWith("out.json.tmp-hsx-"));
  }
  // And a committed run still leaves exactly its output, with the mode a new file gets.
  OutputFiles out;
  out.expect(dir / "out.json", "--json");
  out.put(dir / "out.json", "done");
  out.commit();
  CHECK(slurp(dir / "out.json") == "done");
  CHECK((mode_of(dir / "out.json") & 0777) == 0644);
  if (unnamed) CHECK(dir.entries() == std::vector<std::string>{"out.json"});
}

namespace {

/// read_file("-", max_bytes) with `text` (small: it fits a pipe's buffer) on standard input; the message of its
/// InputError, if any, in `error`.
std::string read_standard_input_holding(const std::string& text, std::size_t max_bytes, std::string& error) {
  int pipe_ends[2];
  REQUIRE(::pipe(pipe_ends) == 0);
  REQUIRE(::write(pipe_ends[1], text.data(), text.size()) == static_cast<ssize_t>(text.size()));
  ::close(pipe_ends[1]);
  const int saved = ::dup(0);
  REQUIRE(::dup2(pipe_ends[0], 0) == 0);
  ::close(pipe_ends[0]);
  std::string got;
  try {
    got = read_file("-", max_bytes);
  } catch (const InputError& e) {
    error = e.what();
  }
  ::dup2(saved, 0);
  ::close(saved);
  return got;
}

}  // namespace

TEST_CASE("files: \"-\" reads standard input to its end", "[files]") {
  const std::string text = "{\"format\": \"hsx-scene/1\"}";
  std::string error;
  CHECK(read_standard_input_holding(text, 100, error) == text);
  CHECK(error.empty());
  CHECK(read_standard_input_holding(text, 10, error).empty());
  CHECK(error == "standard input is too large (the limit is 10 bytes)");
}

TEST_CASE("files: reading refuses directories; a FIFO never blocks", "[files]") {
  TempDir dir;
  ::mkdir((dir / "d").c_str(), 0700);
  CHECK_THROWS_WITH(read_file(dir / "d"), Catch::Contains("is a directory"));
  REQUIRE(::mkfifo((dir / "fifo").c_str(), 0600) == 0);
  CHECK(read_file(dir / "fifo").empty());  // no writer: end of file at once, not a hang
  CHECK_THROWS_WITH(read_file(dir / "missing"), Catch::Contains("No such file"));
  spit(dir / "big", std::string(100, 'x'));
  CHECK_THROWS_WITH(read_file(dir / "big", 99), Catch::Contains("too large"));
  CHECK(read_file(dir / "big", 100).size() == 100);
}
