// Reading the BSH authors' reference-result.grid (conventions in include/hsx/io/bsh_reference.hpp).
#include <hsx/io/bsh_reference.hpp>

#include <hsx/geometry/mesh3.hpp>
#include <hsx/io/files.hpp>

#include <charconv>
#include <map>
#include <string_view>

namespace hsx {

namespace {

/// The file as lines, with the position of each for messages.
struct GridText {
  std::string name;
  std::vector<std::string_view> lines;

  [[noreturn]] void fail(std::size_t line, const std::string& section, const std::string& what) const {
    throw InputError(name + ":" + std::to_string(line + 1) + ": " +
                     (section.empty() ? std::string() : "section " + section + ": ") + what);
  }
};

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

bool parse_count(std::string_view token, long long& value) {
  const auto* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

/// Where each section's lines are: header line index and count.
struct Section {
  std::size_t header = 0;
  std::size_t count = 0;
};

std::map<std::string, Section> find_sections(const GridText& g, const BshReferenceLimits& limits) {
  std::map<std::string, Section> sections;
  const std::size_t max_count = std::max({limits.max_vertices, limits.max_faces, limits.max_patches,
                                          limits.max_blocks});
  std::size_t i = 0;
  while (i < g.lines.size()) {
    const auto t = tokens(g.lines[i]);
    if (t.empty()) {  // blank lines between sections (at the end of the file)
      ++i;
      continue;
    }
    const std::string name(t[0]);
    long long count = 0;
    if (t.size() < 2 || t.size() > 3 || !parse_count(t[1], count) || count < 0)
      g.fail(i, "", "expected a section header \"NAME COUNT\", not \"" + std::string(g.lines[i].substr(0, 60)) + "\"");
    if (static_cast<unsigned long long>(count) > max_count)
      g.fail(i, name, "count " + std::to_string(count) + " exceeds the limit " + std::to_string(max_count));
    if (sections.count(name)) g.fail(i, name, "appears twice");
    if (g.lines.size() - i - 1 < static_cast<std::size_t>(count))
      g.fail(i, name, "announces " + std::to_string(count) + " lines but the file ends after " +
                          std::to_string(g.lines.size() - i - 1));
    sections[name] = {i, static_cast<std::size_t>(count)};
    i += 1 + static_cast<std::size_t>(count);
  }
  return sections;
}

/// Reads the sections into a BshReference.
class GridReader {
 public:
  GridReader(const GridText& g, const BshReferenceLimits& limits)
      : g_(g), limits_(limits), sections_(find_sections(g, limits)) {}

  BshReference read() {
    BshReference r;
    r.vertices = read_vertices();
    r.faces = read_faces(r.vertices.size());
    r.face_implicit = read_single_line("face_implicit", r.faces.size(), -1, false);
    r.patch_faces = read_lists("patch_faces", limits_.max_patches, r.faces.size());
    r.patch_implicit = read_single_line("patch_implicit", r.patch_faces.size(), -1, false);
    r.block_patches = read_lists("block_patches", limits_.max_blocks, r.patch_faces.size());
    r.patch_labels = read_single_line("patch_labels", r.patch_faces.size(), 0, true, false);
    r.block_labels = read_single_line("block_labels", r.block_patches.size(), 0, true, true);
    check_patch_faces(r);
    r.patch_blocks = patch_blocks(r);
    r.zero_area = zero_area_faces(r);
    return r;
  }

 private:
  const GridText& g_;
  const BshReferenceLimits& limits_;
  std::map<std::string, Section> sections_;

  const Section& require(const std::string& name) const {
    const auto it = sections_.find(name);
    if (it == sections_.end()) g_.fail(g_.lines.empty() ? 0 : g_.lines.size() - 1, name, "missing");
    return it->second;
  }

  int read_id(std::string_view token, std::size_t line, const std::string& section, long long lo,
              std::size_t bound) const {
    long long v = 0;
    if (!parse_count(token, v))  // from_chars takes a leading '-'
      g_.fail(line, section, "\"" + std::string(token.substr(0, 40)) + "\" is not an integer");
    if (v < lo || v >= static_cast<long long>(bound))
      g_.fail(line, section, std::to_string(v) + " is out of range [" + std::to_string(lo) + ", " +
                                 std::to_string(bound) + ")");
    return static_cast<int>(v);
  }

  std::vector<PointQ3> read_vertices() const {
    const Section& s = require("vert");
    if (s.count > limits_.max_vertices) g_.fail(s.header, "vert", "too many vertices");
    std::vector<PointQ3> out(s.count);
    for (std::size_t k = 0; k < s.count; ++k) {
      const std::size_t line = s.header + 1 + k;
      const auto t = tokens(g_.lines[line]);
      if (t.size() != 3) g_.fail(line, "vert", "expected 3 coordinates, found " + std::to_string(t.size()));
      Rational* c[3] = {&out[k].x, &out[k].y, &out[k].z};
      for (int i = 0; i < 3; ++i) {
        std::string why;
        const auto q = parse_rational(t[i], &why, limits_.numbers);
        if (!q) g_.fail(line, "vert", "\"" + std::string(t[i].substr(0, 40)) + "\": " + why);
        *c[i] = *q;
      }
    }
    return out;
  }

  std::vector<std::array<int, 3>> read_faces(std::size_t vertex_count) const {
    const Section& s = require("face");
    if (s.count > limits_.max_faces) g_.fail(s.header, "face", "too many faces");
    std::vector<std::array<int, 3>> out(s.count);
    for (std::size_t k = 0; k < s.count; ++k) {
      const std::size_t line = s.header + 1 + k;
      const auto t = tokens(g_.lines[line]);
      if (t.size() != 3) g_.fail(line, "face", "expected 3 vertex ids, found " + std::to_string(t.size()));
      for (int i = 0; i < 3; ++i) out[k][i] = read_id(t[i], line, "face", 0, vertex_count);
      if (out[k][0] == out[k][1] || out[k][1] == out[k][2] || out[k][0] == out[k][2])
        g_.fail(line, "face", "face " + std::to_string(k) + " repeats a vertex");
    }
    return out;
  }

  /// One-line sections: `length` entries in [lo, bound) (labels: [0, 2)); absent and not `required`: empty.
  std::vector<int> read_single_line(const std::string& name, std::size_t length, long long lo, bool labels,
                                    bool required = false) const {
    if (!sections_.count(name)) {
      if (required) require(name);
      return {};
    }
    const Section& s = sections_.at(name);
    if (s.count != 1) g_.fail(s.header, name, "expected a count of 1, found " + std::to_string(s.count));
    const auto t = tokens(g_.lines[s.header + 1]);
    if (t.size() != length)
      g_.fail(s.header + 1, name, "expected " + std::to_string(length) + " entries, found " + std::to_string(t.size()));
    std::vector<int> out;
    out.reserve(t.size());
    const std::size_t bound = labels ? 2 : static_cast<std::size_t>(1) << 30;
    for (const auto& token : t) out.push_back(read_id(token, s.header + 1, name, lo, bound));
    return out;
  }

  /// Sections of COUNT lines of ids below `bound`.
  std::vector<std::vector<int>> read_lists(const std::string& name, std::size_t max_count, std::size_t bound) const {
    const Section& s = require(name);
    if (s.count > max_count) g_.fail(s.header, name, "count exceeds the limit " + std::to_string(max_count));
    std::vector<std::vector<int>> out(s.count);
    for (std::size_t k = 0; k < s.count; ++k) {
      const std::size_t line = s.header + 1 + k;
      const auto t = tokens(g_.lines[line]);
      if (t.empty() && name != "block_patches") g_.fail(line, name, "entry " + std::to_string(k) + " is empty");
      if (t.size() > limits_.max_line_entries) g_.fail(line, name, "too many entries on one line");
      for (const auto& token : t) out[k].push_back(read_id(token, line, name, 0, bound));
    }
    return out;
  }

  void check_patch_faces(const BshReference& r) const {
    const Section& s = sections_.at("patch_faces");
    std::vector<int> owner(r.faces.size(), -1);
    for (std::size_t p = 0; p < r.patch_faces.size(); ++p)
      for (int f : r.patch_faces[p]) {
        if (owner[f] >= 0)
          g_.fail(s.header + 1 + p, "patch_faces", "face " + std::to_string(f) + " is in patches " +
                                                       std::to_string(owner[f]) + " and " + std::to_string(p));
        owner[f] = static_cast<int>(p);
      }
  }

  std::vector<std::array<int, 2>> patch_blocks(const BshReference& r) const {
    const Section& s = sections_.at("block_patches");
    std::vector<std::vector<int>> blocks(r.patch_faces.size());
    for (std::size_t b = 0; b < r.block_patches.size(); ++b)
      for (int p : r.block_patches[b]) {
        if (!blocks[p].empty() && blocks[p].back() == static_cast<int>(b))
          g_.fail(s.header + 1 + b, "block_patches", "patch " + std::to_string(p) + " listed twice");
        blocks[p].push_back(static_cast<int>(b));
        if (blocks[p].size() > 2)
          g_.fail(s.header + 1 + b, "block_patches", "patch " + std::to_string(p) + " is in more than two blocks");
      }
    std::vector<std::array<int, 2>> out(blocks.size());
    for (std::size_t p = 0; p < blocks.size(); ++p) {
      if (blocks[p].size() != 2)
        g_.fail(s.header, "block_patches", "patch " + std::to_string(p) + " is in " +
                                               std::to_string(blocks[p].size()) + " block(s), not two");
      out[p] = {blocks[p][0], blocks[p][1]};
    }
    return out;
  }

  static std::vector<char> zero_area_faces(const BshReference& r) {
    std::vector<char> zero(r.faces.size(), 0);
    for (std::size_t f = 0; f < r.faces.size(); ++f) {
      const auto& v = r.faces[f];
      const PointQ3 n = triangle_normal(r.vertices[v[0]], r.vertices[v[1]], r.vertices[v[2]]);
      zero[f] = sgn(n.x) == 0 && sgn(n.y) == 0 && sgn(n.z) == 0;
    }
    return zero;
  }
};

}  // namespace

BshReference read_bsh_reference(const std::string& text, const std::string& name, const BshReferenceLimits& limits) {
  GridText g{name, split_lines(text)};
  return GridReader(g, limits).read();
}

BshReference read_bsh_reference_file(const std::string& path, const BshReferenceLimits& limits) {
  return read_bsh_reference(read_file(path), path, limits);
}

}  // namespace hsx
