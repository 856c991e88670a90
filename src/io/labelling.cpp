#include <hsx/io/labelling.hpp>

#include <hsx/geometry/scene.hpp>
#include <hsx/io/exact_json.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/result_json.hpp>

#include "kernel/printable.hpp"

#include <cmath>

namespace hsx {
namespace {

/// 2^53: beyond it not every integer is a double.
constexpr double kLargestExactWeight = 9007199254740992.0;

constexpr const char* kLabelOrder = "one per cell, in the order of the input's hsx-complex/1 cells: `hsx arrange INPUT --json`";

std::string count_mismatch(std::size_t got, std::size_t cells) {
  return std::to_string(got) + " labels for " + std::to_string(cells) + " cells (" + kLabelOrder + ")";
}

/// One JSON label: true/false or the integers 0/1.
char json_label(const nlohmann::json& v, const std::string& field) {
  if (v.is_boolean()) return v.get<bool>() ? 1 : 0;
  if (v.is_number_integer()) {
    const auto k = v.get<long long>();
    if (k == 0 || k == 1) return static_cast<char>(k);
  }
  throw InputError(field + ": expected true, false, 0 or 1, got " + v.dump());
}

std::vector<char> json_labels(const nlohmann::json& list, const std::string& field, const Complex& complex) {
  if (!list.is_array()) throw InputError(field + ": expected an array of labels, one per cell");
  if (list.size() != complex.cells.size()) throw InputError(field + ": " + count_mismatch(list.size(), complex.cells.size()));
  std::vector<char> cells(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) cells[k] = json_label(list[k], field + "[" + std::to_string(k) + "]");
  return cells;
}

/// 0/1 tokens separated by white space or commas; errors name the line.
std::vector<char> plain_labels(const std::string& text, const Complex& complex) {
  std::vector<char> cells;
  int line = 1;
  std::size_t k = 0;
  while (k < text.size()) {
    const char c = text[k];
    if (c == '\n') ++line;
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',') {
      ++k;
      continue;
    }
    std::size_t end = k;
    while (end < text.size() && std::string(" \t\r\n,").find(text[end]) == std::string::npos) ++end;
    const std::string token = text.substr(k, end - k);
    if (token != "0" && token != "1")
      throw InputError("line " + std::to_string(line) + ": label " + std::to_string(cells.size()) + " is \"" +
                       printable(token) + "\", not 0 or 1");
    cells.push_back(token == "1" ? 1 : 0);
    if (cells.size() > complex.cells.size())
      throw InputError("line " + std::to_string(line) + ": more than " + std::to_string(complex.cells.size()) +
                       " labels for " + std::to_string(complex.cells.size()) + " cells (" + kLabelOrder + ")");
    k = end;
  }
  if (cells.size() != complex.cells.size()) throw InputError(count_mismatch(cells.size(), complex.cells.size()));
  return cells;
}

ReadLabelling read_labelling_unprefixed(const std::string& text, const Complex& complex) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) throw InputError("empty: expected a labelling (one 0/1 label per cell)");
  if (text[first] != '{' && text[first] != '[') return {plain_labels(text, complex), LabellingFormat::PlainList};
  const nlohmann::json doc = parse_exact_json(text);
  if (doc.is_array()) return {json_labels(doc, "labels", complex), LabellingFormat::JsonList};
  if (doc.contains("format")) return {read_result_labelling(doc, complex), LabellingFormat::Result};
  if (doc.contains("labels")) return {json_labels(doc.at("labels"), "labels", complex), LabellingFormat::GraphcutLabels};
  throw InputError("expected an hsx-result/1 document (with \"format\"), the BSH graph cut's {\"labels\": [...]}, a "
                   "JSON array of labels or a plain list of 0/1");
}

}  // namespace

const char* to_string(LabellingFormat format) {
  switch (format) {
    case LabellingFormat::Result: return "hsx-result/1";
    case LabellingFormat::GraphcutLabels: return "BSH graph-cut labels";
    case LabellingFormat::JsonList: return "JSON list of labels";
    case LabellingFormat::PlainList: return "plain list of labels";
  }
  return "?";
}

nlohmann::json bsh_graphcut_to_json(const Complex& complex, std::int64_t weight_scale) {
  if (weight_scale < 1) throw InputError("weight scale: must be at least 1, not " + std::to_string(weight_scale));
  const auto neighbours = complex.patch_neighbours();
  nlohmann::json patches = nlohmann::json::array();
  for (std::size_t p = 0; p < complex.patches.size(); ++p) {
    const Patch& patch = complex.patches[p];
    const double measure = patch.measure.get().to_double();
    const double scaled = std::round(measure * static_cast<double>(weight_scale));
    if (!(scaled <= kLargestExactWeight))
      throw InputError("patch " + std::to_string(p) + ": its weight, measure " + patch.measure.get().decimal_string(12) +
                       " times the scale " + std::to_string(weight_scale) +
                       ", exceeds 2^53 (not exact as a double): use a smaller weight scale");
    const auto exact = patch.measure.get().exact_string();
    patches.push_back({{"adj_cell_0", patch.outside_cell},
                       {"adj_cell_1", patch.inside_cell},
                       {"weight", std::max<std::int64_t>(1, static_cast<std::int64_t>(scaled))},
                       {"implicit_id", patch.halfspace},
                       {"num_samples", patch.samples.size()},
                       {"adj_patches", neighbours[p]},
                       {"measure", measure},
                       {"measure_exact", exact ? nlohmann::json(*exact) : nlohmann::json(nullptr)},
                       {"support", patch.support}});
  }
  nlohmann::json outer = nlohmann::json::array();
  for (std::size_t c = 0; c < complex.cells.size(); ++c)
    if (complex.cells[c].outer) outer.push_back(c);
  return {{"format", kBshGraphcutFormat},
          {"complex_id", complex_identity(complex)},
          {"weight_scale", weight_scale},
          {"num_cells", complex.cells.size()},
          {"outer_cells", std::move(outer)},
          {"patches", std::move(patches)}};
}

ReadLabelling read_labelling_text(const std::string& text, const std::string& source, const Complex& complex) {
  try {
    return read_labelling_unprefixed(text, complex);
  } catch (const InputError& e) {
    if (source.empty()) throw;
    throw InputError(source + ": " + e.what());
  }
}

ReadLabelling read_labelling_file(const std::string& path, const Complex& complex) {
  return read_labelling_text(read_file(path), path, complex);
}

}  // namespace hsx
