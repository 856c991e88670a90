// Bytes -> hsx-complex/1 import. Bad input must end in InputError; a complex that imports must pass
// check_complex (the importer runs it) and export again.
#include <hsx/io/complex_json.hpp>
#include <hsx/io/exact_json.hpp>

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return -1;
  try {
    hsx::JsonLimits limits;
    const auto doc = hsx::parse_exact_json(std::string_view(reinterpret_cast<const char*>(data), size), limits);
    const hsx::Complex complex = hsx::complex_from_json(doc);
    (void)hsx::complex_to_json(complex, nullptr, nullptr);
  } catch (const hsx::InputError&) {
  }
  return 0;
}
