// What every libFuzzer target shares. A target feeds its bytes to one reader (and what follows it); bad input must
// end in hsx::InputError (or a refusal the target's header comment documents), and anything else - a crash, a
// sanitizer report, another exception, a broken invariant, a hang - is a finding. An invariant broken on accepted
// input is reported through finding(), which aborts so that libFuzzer keeps the input as a crash artifact.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <string_view>

namespace hsx::fuzz {

/// Reports a broken invariant and aborts. `target` names the fuzz target ("fuzz_csgnet"), `what` the invariant.
[[noreturn]] inline void finding(const char* target, const std::string& what) {
  std::cerr << target << ": " << what << "\n";
  std::abort();
}

/// The fuzzer's bytes as text (`data`, `size` as libFuzzer passes them).
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace hsx::fuzz
