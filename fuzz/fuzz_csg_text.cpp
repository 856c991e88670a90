// Bytes -> CSG expression, as the --csg argument reads it (io/csg_text.hpp): the text form, or inline JSON when the
// bytes start with '{'. Bad input must end in InputError; anything else is a finding. Checked on every accepted
// expression: to_text parses back to an expression with the same value on every sign vector of the five
// halfspaces, and the JSON form (csg_to_json, csg_from_json) does too.
#include "fuzz_support.hpp"

#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/io/csg_text.hpp>

#include <string>
#include <vector>

namespace {

constexpr const char* kTarget = "fuzz_csg_text";

// "full" as a halfspace name must be quoted in text (io/csg_text.hpp); "x y" is not an identifier.
const std::vector<std::string> kNames = {"A", "B", "c.1", "full", "x y"};

// The expression's value on all 2^5 sign vectors.
std::vector<char> truth_table(const hsx::csg::Expr& e) {
  std::vector<char> table;
  for (unsigned bits = 0; bits < (1u << kNames.size()); ++bits) {
    std::vector<char> inside(kNames.size());
    for (std::size_t h = 0; h < kNames.size(); ++h) inside[h] = (bits >> h) & 1u;
    table.push_back(hsx::csg::evaluate(e, inside));
  }
  return table;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return -1;
  const std::string text(hsx::fuzz::as_text(data, size));
  hsx::csg::ExprPtr e;
  try {
    // read_csg_argument would take an existing file's name as a path; parse the two inline forms directly.
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    e = first != std::string::npos && text[first] == '{'
            ? hsx::csg_from_json(hsx::parse_exact_json(text), kNames)
            : hsx::parse_csg_text(text, kNames);
  } catch (const hsx::InputError&) {
    return 0;
  }
  if (!e) hsx::fuzz::finding(kTarget, "accepted without an expression");
  const std::vector<char> table = truth_table(*e);
  const std::string written = hsx::csg::to_text(*e, kNames);
  hsx::csg::ExprPtr back;
  try {
    back = hsx::parse_csg_text(written, kNames, "to_text");
  } catch (const hsx::InputError& error) {
    hsx::fuzz::finding(kTarget, "to_text is not read back: " + written + ": " + error.what());
  }
  if (truth_table(*back) != table) hsx::fuzz::finding(kTarget, "to_text changed the value: " + written);
  const hsx::csg::ExprPtr from_json = hsx::csg_from_json(hsx::csg_to_json(*e, kNames), kNames);
  if (truth_table(*from_json) != table) hsx::fuzz::finding(kTarget, "the JSON form changed the value");
  return 0;
}
