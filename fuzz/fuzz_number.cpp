// Bytes -> exact rational. Accepted text must round-trip through exact_string; nothing may crash or run long.
#include <hsx/kernel/rational.hpp>

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return -1;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  hsx::NumberLimits limits;
  limits.max_exponent = 2000;
  std::string why;
  if (auto q = hsx::parse_rational(text, &why, limits)) {
    auto again = hsx::parse_rational(hsx::exact_string(*q), &why, limits);
    if (!again || *again != *q) std::abort();
    (void)hsx::decimal_string(*q, 30);
  }
  return 0;
}
