// A token of hostile text, fit for an error message.
#pragma once

#include <string>
#include <string_view>

namespace hsx {

/// At most 40 characters of `token`, bytes outside printable ASCII as \xNN, "..." after a longer one.
inline std::string printable(std::string_view token) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (std::size_t k = 0; k < token.size() && k < 40; ++k) {
    const auto c = static_cast<unsigned char>(token[k]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return token.size() > 40 ? out + "..." : out;
}

}  // namespace hsx
