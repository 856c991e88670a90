// Reading input files and writing outputs without harm.
//
// The output policy (owned here):
// - "-" is standard output, written directly.
// - A regular file, or a path that does not exist yet, is replaced atomically: the content goes to a temporary file
//   beside it ("PATH.tmp-hsx-PID-N", PATH's name shortened when the whole would exceed the folder's longest file
//   name), which is then renamed over it, so a reader sees the old file or the new one, never half of one. An
//   existing file keeps its permission bits; one we may not write (read-only) is refused, although renaming over
//   it would succeed in a writable folder.
// - A symbolic link is followed: its final target is replaced as above (the link itself stays a link). A link whose
//   target does not exist is refused.
// - A character or block device (/dev/null, /dev/stdout, a terminal) or a FIFO is written directly, never
//   replaced; a directory or a socket is refused.
// - Every failure is the user's (a missing folder, no permission, a read-only place, a full disk): OutputError, an
//   InputError, so the program exits 2 naming the path and the reason.
// - A command's report to standard output (OutputFiles::print) is one of its outputs: written after every file's
//   content and before any file is put in place, so a report that cannot be written fails the run like a file.
// - Where the file system allows (O_TMPFILE: ext4, xfs, btrfs, tmpfs), a temporary file has no name until commit
//   writes it in full, so a run killed by SIGKILL or the out-of-memory killer while computing leaves nothing; it is
//   named just before the renames. A run's named temporary files are removed when it fails, and when it is ended by
//   SIGINT, SIGTERM, SIGHUP, SIGPIPE or SIGXCPU (a CPU time limit). An output past the file size limit (ulimit -f) is a failed write, like a full disk.
// - The hsx program also refuses an output that is one of the run's own inputs (cli/commands.hpp,
//   refuse_outputs_over_inputs); that needs to know which paths are inputs, so it is the program's, not this file's.
#pragma once

#include <hsx/geometry/scene.hpp>  // InputError

#include <cstddef>
#include <memory>
#include <string>

namespace hsx {

/// An output that cannot be written; the message names the path and the reason.
class OutputError : public InputError {
 public:
  using InputError::InputError;
};

/// Writes `content` to `path` under the policy above. Throws OutputError.
void write_file_atomically(const std::string& path, const std::string& content);

/// The outputs of one run, written all or none (as far as a file system allows: every regular file is first
/// written in full to its temporary file and every device written, and only then are the temporary files renamed,
/// so a full disk, a missing folder or a failing device leaves no output behind).
///
///   OutputFiles out;
///   out.expect(o.json_path, "--json");   // before computing: a bad path fails now, not after an hour
///   ... compute ...
///   out.put(o.json_path, text);
///   out.commit();                        // or let `out` go out of scope: nothing is written
class OutputFiles {
 public:
  OutputFiles();
  ~OutputFiles();  ///< removes the temporary files of a run that did not commit
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  /// Checks now that `path` can be written under the policy, and reserves it: for a regular file, its temporary
  /// file is created at once (unnamed where the file system allows). `option` names the path in messages ("--json"). An empty path is an output not asked
  /// for: ignored (here and by put). A path expected twice (also through another spelling or a link) is refused.
  /// Throws OutputError.
  void expect(const std::string& path, const std::string& option);
  /// Marks `path` as an input of the run, one that no output may replace: an expected output (before or after this
  /// call) that is the same existing regular file (through any spelling, hard or symbolic link) is refused with an
  /// InputError naming both, `name` naming the input ("INPUT", "the mesh file of halfspace \"A\""). For inputs
  /// that are not the command line's own options (those are compared when it is parsed): files a scene refers to,
  /// and outputs derived from another (an .obj's .mtl). A path that is not an existing regular file is ignored.
  void protect(const std::string& path, const std::string& name);
  /// The content for an expected path (std::logic_error when it was not expected: a bug).
  void put(const std::string& path, std::string content);
  /// A report for standard output (a command's summary), appended to what was given before. It is written by
  /// commit after every file's content is in place and before any file is renamed, so a report that cannot be
  /// written (standard output on a full disk or closed) fails the commit and leaves no output behind. Once print
  /// was called, commit also fails when anything the program printed to std::cout earlier failed; `text` may be
  /// empty for a command that printed its report as it went.
  void print(const std::string& text);
  /// Writes everything put (paths expected but never put are left alone), then the report given to print. Throws
  /// OutputError and leaves no new output behind on failure.
  void commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Refuses (InputError, so exit 2) writing `output`, the value of `output_option` ("--json"), when it is the same
/// existing regular file as `input` (through any spelling, hard or symbolic link), which `input_name` names in the
/// message ("INPUT", "scene"). "" and "-" are never regular files. The refusal of OutputFiles::protect, for callers
/// that compare paths before any output is expected (the hsx program's check of its command line).
void refuse_output_over_input(const std::string& output_option, const std::string& output,
                              const std::string& input_name, const std::string& input);

/// Makes SIGINT, SIGTERM, SIGHUP, SIGPIPE (a reader of standard output or of a FIFO that went away) and SIGXCPU
/// (past a CPU time limit) remove the temporary files of outputs not yet committed, then end the process as the
/// signal would; and ignores SIGXFSZ, so that a write past the file size limit fails (EFBIG, an OutputError) instead
/// of ending the process. For programs (the hsx CLI calls it first); a library user with signal handlers of its own
/// need not call it (temporary files are still removed on every failure and by ~OutputFiles).
void remove_temporary_outputs_on_signals();

/// Reads a whole file: a regular file, or a FIFO or character device read to its end (a FIFO is opened without
/// waiting for a writer, and one without a writer reads as empty, so a run never hangs on it). "-" is standard
/// input, read to its end. Throws InputError naming the path (or "standard input") when it does not exist, is a
/// directory or a socket, cannot be read, or exceeds `max_bytes`.
std::string read_file(const std::string& path, std::size_t max_bytes = std::size_t(256) << 20);

}  // namespace hsx
