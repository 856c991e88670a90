#include <hsx/io/files.hpp>

#include <hsx/geometry/scene.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace hsx {

void write_file_atomically(const std::string& path, const std::string& content) {
  if (path == "-") {
    std::cout << content;
    std::cout.flush();
    return;
  }
  const std::string temp = path + ".tmp-hsx-" + std::to_string(::getpid());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write \"" + path + "\": cannot create a file there");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      std::remove(temp.c_str());
      throw std::runtime_error("cannot write \"" + path + "\": write failed");
    }
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    std::remove(temp.c_str());
    throw std::runtime_error("cannot write \"" + path + "\": rename failed");
  }
}

std::string read_file(const std::string& path, std::size_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read \"" + path + "\": no such file or not readable");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError("cannot read \"" + path + "\": a directory");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError("cannot read \"" + path + "\": not a regular file");
  if (static_cast<std::size_t>(size) > max_bytes)
    throw InputError("\"" + path + "\" is too large (" + std::to_string(size) + " bytes; the limit is " +
                     std::to_string(max_bytes) + ")");
  in.seekg(0);
  std::string content(static_cast<std::size_t>(size), '\0');
  in.read(content.data(), size);
  if (!in) throw InputError("cannot read \"" + path + "\"");
  return content;
}

}  // namespace hsx
