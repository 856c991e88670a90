// File output without half-written results: content goes to a temporary file beside the target, which is then
// renamed over it, so a failure leaves either the old file or nothing.
#pragma once

#include <string>

namespace hsx {

/// Writes `content` to `path` atomically ("-" writes to standard output). Throws std::runtime_error naming the
/// path when the file cannot be written.
void write_file_atomically(const std::string& path, const std::string& content);

/// Reads a whole file; throws InputError naming the path when it cannot be read or exceeds `max_bytes`.
std::string read_file(const std::string& path, std::size_t max_bytes = std::size_t(256) << 20);

}  // namespace hsx
