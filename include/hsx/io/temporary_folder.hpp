// A private temporary folder for a run's scratch files (an external solver's input and output, a benchmark's
// campaign folders), removed with everything in it when it goes out of scope.
#pragma once

#include <string>

namespace hsx {

class TemporaryFolder {
 public:
  /// Makes a new folder `$TMPDIR/<prefix>.XXXXXX` (TMPDIR unset or empty: /tmp), readable by this user only.
  /// Throws OutputError (io/files.hpp) when it cannot be made.
  explicit TemporaryFolder(const std::string& prefix);
  /// Removes the folder and what is in it; errors are ignored.
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;

  /// The folder's absolute path.
  const std::string& path() const { return path_; }
  /// `path()/name`.
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

}  // namespace hsx
