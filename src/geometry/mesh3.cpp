// Reading and validating closed triangle meshes exactly; edge shapes and the sharpness angle. See mesh3.hpp.
//
// Decisions documented here:
// - Validation runs in a fixed order (indices, zero-area triangles, edge-manifold and orientation, vertex
//   manifold, volume, folds) and reports the first offender in a deterministic order (lowest edge (a, b), lowest
//   vertex id), with the number of further offenders of the same kind, so a message is stable across runs.
// - Orientation is fixed globally by the sign of the total volume, never per shell: a hollow solid's inner shell
//   is legitimately inward.
// - The sharpness comparison refines its interval up to kMaxBits; beyond that it throws std::runtime_error (an
//   internal limit, not an input error). cos^2(delta) is algebraic and cos^2(theta) a rational of bounded size,
//   so the gap is positive; inputs that need more than 2^20 bits would have to approximate cos^2(delta) to
//   ~300,000 digits.
#include <hsx/geometry/mesh3.hpp>

#include "geometry/components.hpp"
#include "kernel/printable.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <istream>
#include <numeric>
#include <stdexcept>
#include <string_view>

namespace hsx {

namespace {

constexpr mpfr_prec_t kBaseBits = 128;
constexpr mpfr_prec_t kMaxBits = mpfr_prec_t(1) << 20;

[[noreturn]] void fail_at(const std::string& source, long line, const std::string& what) {
  throw InputError(source + ":" + std::to_string(line) + ": " + what);
}

[[noreturn]] void fail(const std::string& source, const std::string& what) { throw InputError(source + ": " + what); }

/// Opens a mesh or feature file: a directory, FIFO, device or socket is refused before it is opened (a FIFO would
/// block), a missing file is named as such.
std::ifstream open_regular_file(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status))  // the system's reason: no such file, a loop of symbolic links, ...
    fail(path, "cannot open it: " + (ec && ec != std::errc::no_such_file_or_directory ? ec.message()
                                                                                        : std::string("no such file")));
  if (std::filesystem::is_directory(status)) fail(path, "is a directory, not a file");
  if (!std::filesystem::is_regular_file(status)) fail(path, "not a regular file (a FIFO, device or socket)");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open the file");
  return in;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/// Whitespace-separated tokens of a line, up to a '#' comment.
std::vector<std::string_view> tokens_of(std::string_view line) {
  const std::size_t hash = line.find('#');
  if (hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t begin = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > begin) out.push_back(line.substr(begin, i - begin));
  }
  return out;
}

/// A decimal integer with optional sign; nullopt when not one or when |value| >= 10^15 (no id comes close).
std::optional<long long> parse_integer(std::string_view text) {
  std::size_t i = 0;
  bool negative = false;
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) {
    negative = text[0] == '-';
    i = 1;
  }
  if (i == text.size() || text.size() - i > 15) return std::nullopt;
  long long value = 0;
  for (; i < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return std::nullopt;
    value = value * 10 + (text[i] - '0');
  }
  return negative ? -value : value;
}

std::string quoted(std::string_view s) { return "\"" + printable(s) + "\""; }
// An exact match for std::string arguments: without it, argument-dependent lookup prefers std::quoted.
std::string quoted(const std::string& s) { return quoted(std::string_view(s)); }

PointQ3 minus(const PointQ3& a, const PointQ3& b) { return PointQ3{a.x - b.x, a.y - b.y, a.z - b.z}; }

/// One face's traversal of one edge, for sorting by undirected edge.
struct Half {
  std::uint64_t key;  ///< (min << 32) | max of the two vertex ids
  int face;
  int k;              ///< the face's local edge: faces[face][k] -> faces[face][(k+1)%3]
  bool forward;       ///< traverses min -> max
};

std::vector<Half> halves_of(const std::vector<std::array<int, 3>>& faces) {
  std::vector<Half> halves;
  halves.reserve(faces.size() * 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int u = faces[f][static_cast<std::size_t>(k)], v = faces[f][static_cast<std::size_t>((k + 1) % 3)];
      const auto lo = static_cast<std::uint64_t>(std::min(u, v)), hi = static_cast<std::uint64_t>(std::max(u, v));
      halves.push_back(Half{(lo << 32) | hi, static_cast<int>(f), k, u < v});
    }
  std::sort(halves.begin(), halves.end(), [](const Half& x, const Half& y) {
    return x.key != y.key ? x.key < y.key : (x.face != y.face ? x.face < y.face : x.k < y.k);
  });
  return halves;
}

std::string edge_name(std::uint64_t key) {
  return "edge (" + std::to_string(key >> 32) + ", " + std::to_string(key & 0xffffffffu) + ")";
}

std::string lines_list(const std::vector<long>& lines) {
  std::string out;
  const std::size_t shown = std::min<std::size_t>(lines.size(), 10);
  for (std::size_t i = 0; i < shown; ++i) out += (i ? ", " : "") + std::to_string(lines[i]);
  if (lines.size() > shown) out += ", ...";
  return out;
}

}  // namespace

const char* edge_shape_name(EdgeShape shape) {
  switch (shape) {
    case EdgeShape::Flat: return "flat";
    case EdgeShape::Convex: return "convex";
    case EdgeShape::Concave: return "concave";
  }
  return "?";
}

PointQ3 triangle_normal(const PointQ3& a, const PointQ3& b, const PointQ3& c) {
  const PointQ3 u = minus(b, a), w = minus(c, a);
  return PointQ3{u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z, u.x * w.y - u.y * w.x};
}

Rational dot3(const PointQ3& u, const PointQ3& v) { return u.x * v.x + u.y * v.y + u.z * v.z; }

namespace {

/// sign of det(b - a, c - a, d - a)
int orient3d(const PointQ3& a, const PointQ3& b, const PointQ3& c, const PointQ3& d) {
  return sgn(dot3(triangle_normal(a, b, c), minus(d, a)));
}

}  // namespace

namespace {

/// The ray-parity test over `count` triangles; `corners(i)` gives triangle i's three vertices.
template <class Corners>
std::optional<bool> point_inside_by_parity(std::size_t count, const Corners& corners, const PointQ3& p) {
  // Directions (1, k, k^2 + 1), k = 1, 2, ...: each degenerate event below (the ray parallel to a plane, or through
  // a given edge or vertex) holds for at most two k, so some k is free of all of them.
  for (long k = 1;; ++k) {
    const PointQ3 d{Rational(1), Rational(k), Rational(k * k + 1)};
    const PointQ3 q{p.x + d.x, p.y + d.y, p.z + d.z};
    bool degenerate = false;
    long crossings = 0;
    for (std::size_t f = 0; f < count; ++f) {
      const auto [pa, pb, pc] = corners(f);
      const PointQ3& a = *pa;
      const PointQ3& b = *pb;
      const PointQ3& c = *pc;
      const PointQ3 n = triangle_normal(a, b, c);
      const int side = sgn(dot3(n, minus(a, p)));  // 0: p lies in the triangle's plane
      const int toward = sgn(dot3(n, d));          // 0: the ray is parallel to the plane
      if (side == 0) {
        const bool in_triangle = sgn(dot3(n, triangle_normal(p, a, b))) >= 0 &&
                                 sgn(dot3(n, triangle_normal(p, b, c))) >= 0 &&
                                 sgn(dot3(n, triangle_normal(p, c, a))) >= 0;
        if (in_triangle) return std::nullopt;  // p is on the surface
        if (toward != 0) continue;             // the line leaves the plane at p, outside the triangle
        degenerate = true;                     // the ray runs in the triangle's plane
        break;
      }
      if (toward == 0) continue;  // parallel to the plane and off it: no crossing
      const int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
      if ((s1 > 0 || s2 > 0 || s3 > 0) && (s1 < 0 || s2 < 0 || s3 < 0)) continue;  // the line misses it
      if (s1 == 0 || s2 == 0 || s3 == 0) {  // the line meets the triangle's boundary: an edge or a vertex
        degenerate = true;
        break;
      }
      if (side == toward) ++crossings;  // the crossing lies ahead of p
    }
    if (!degenerate) return crossings % 2 == 1;
  }
}

}  // namespace

std::optional<bool> point_inside_faces(const Mesh3& mesh, const std::vector<int>& faces, const PointQ3& p) {
  return point_inside_by_parity(
      faces.size(),
      [&](std::size_t i) {
        const auto& t = mesh.faces[static_cast<std::size_t>(faces[i])];
        return std::array<const PointQ3*, 3>{&mesh.vertices[static_cast<std::size_t>(t[0])],
                                             &mesh.vertices[static_cast<std::size_t>(t[1])],
                                             &mesh.vertices[static_cast<std::size_t>(t[2])]};
      },
      p);
}

std::optional<bool> point_inside_triangles(const std::vector<PointQ3>& vertices,
                                           const std::vector<std::array<int, 3>>& triangles, const PointQ3& p) {
  return point_inside_by_parity(
      triangles.size(),
      [&](std::size_t i) {
        const auto& t = triangles[i];
        return std::array<const PointQ3*, 3>{&vertices[static_cast<std::size_t>(t[0])],
                                             &vertices[static_cast<std::size_t>(t[1])],
                                             &vertices[static_cast<std::size_t>(t[2])]};
      },
      p);
}

// ---------------------------------------------------------------------------------------------------------------
// Readers

ObjMesh read_obj(std::istream& in, const std::string& source, const MeshReadLimits& limits) {
  ObjMesh mesh;
  mesh.source = source;
  std::string line;
  long line_no = 0;
  // Positive indices may refer forward (some writers emit faces first); they are range-checked at the end.
  std::vector<std::pair<long, long>> pending;  // (face, largest positive index) to check once the count is known
  while (std::getline(in, line)) {
    ++line_no;
    const auto tok = tokens_of(line);
    if (tok.empty()) continue;
    if (tok[0] == "v") {
      if (mesh.vertices.size() >= limits.max_vertices)
        fail_at(source, line_no, "more than " + std::to_string(limits.max_vertices) + " vertices (limit)");
      const std::size_t n = tok.size() - 1;
      if (n != 3 && n != 4 && n != 6)
        fail_at(source, line_no, "a vertex needs 3 coordinates (x y z), got " + std::to_string(n));
      Rational c[4];
      const std::size_t parsed = n == 4 ? 4 : 3;  // x y z [w]; the colour of "x y z r g b" is not read
      for (std::size_t i = 0; i < parsed; ++i) {
        std::string why;
        auto q = parse_rational(tok[i + 1], &why, limits.numbers);
        if (!q) fail_at(source, line_no, "coordinate " + std::to_string(i + 1) + " " + quoted(tok[i + 1]) + ": " + why);
        c[i] = std::move(*q);
      }
      // A homogeneous w other than 1 would scale the point; nobody writes it for meshes, so refuse it.
      if (n == 4 && c[3] != 1) fail_at(source, line_no, "vertex weight w must be 1 (got " + exact_string(c[3]) + ")");
      mesh.vertices.push_back(PointQ3{c[0], c[1], c[2]});
      mesh.vertex_lines.push_back(line_no);
    } else if (tok[0] == "f") {
      if (mesh.faces.size() >= limits.max_faces)
        fail_at(source, line_no, "more than " + std::to_string(limits.max_faces) + " faces (limit)");
      const std::size_t n = tok.size() - 1;
      if (n < 3) fail_at(source, line_no, "a face needs 3 vertices, got " + std::to_string(n));
      if (n > 3)
        fail_at(source, line_no,
                "face with " + std::to_string(n) + " vertices: only triangles are accepted (triangulate the mesh)");
      std::array<int, 3> face{};
      long largest = 0;
      for (std::size_t i = 0; i < 3; ++i) {
        const std::string_view spec = tok[i + 1];
        const auto value = parse_integer(spec.substr(0, spec.find('/')));
        if (!value) fail_at(source, line_no, "vertex index " + quoted(spec) + " is not an integer");
        long long id = *value;
        if (id == 0) fail_at(source, line_no, "vertex index 0: .obj indices start at 1");
        if (id < 0) {
          id += static_cast<long long>(mesh.vertices.size());  // -1 is the last vertex read so far
          if (id < 0)
            fail_at(source, line_no, "relative vertex index " + quoted(spec) + " reaches before the first vertex");
        } else {
          if (static_cast<unsigned long long>(id) > limits.max_vertices)
            fail_at(source, line_no, "vertex index " + std::to_string(id) + " out of range");
          largest = std::max<long>(largest, static_cast<long>(id));
          id -= 1;
        }
        face[i] = static_cast<int>(id);
      }
      if (face[0] == face[1] || face[1] == face[2] || face[0] == face[2])
        fail_at(source, line_no, "degenerate face: vertex " + std::to_string(face[0] == face[1] ? face[0] : face[2]) +
                                     " (0-based) appears twice");
      if (largest > 0) pending.emplace_back(static_cast<long>(mesh.faces.size()), largest);
      mesh.faces.push_back(face);
      mesh.face_lines.push_back(line_no);
    }
    // Every other keyword (vn, vt, o, g, s, usemtl, mtllib, l, ...) carries nothing hsx needs.
  }
  if (in.bad()) fail(source, "read error");
  for (const auto& [face, largest] : pending)
    if (static_cast<std::size_t>(largest) > mesh.vertices.size())
      fail_at(source, mesh.face_lines[static_cast<std::size_t>(face)],
              "vertex index " + std::to_string(largest) + " out of range (the file has " +
                  std::to_string(mesh.vertices.size()) + " vertices)");
  if (mesh.faces.empty()) fail(source, "no faces (`f a b c` lines)");
  return mesh;
}

ObjMesh read_obj_file(const std::string& path, const MeshReadLimits& limits) {
  std::ifstream in = open_regular_file(path);
  return read_obj(in, path, limits);
}

namespace {

/// The whitespace-separated tokens of a text with their 1-based lines; `#` starts a comment.
struct LineTokens {
  std::vector<std::string> tokens;
  std::vector<long> lines;
  std::size_t next = 0;
  bool done() const { return next >= tokens.size(); }
  long line() const { return next < lines.size() ? lines[next] : (lines.empty() ? 1 : lines.back()); }
};

LineTokens tokenize(std::istream& in, const std::string& source) {
  LineTokens out;
  std::string line;
  long line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    for (auto t : tokens_of(line)) {
      out.tokens.emplace_back(t);
      out.lines.push_back(line_no);
    }
  }
  if (in.bad()) fail(source, "read error");
  return out;
}

long long count_token(LineTokens& t, const std::string& source, const char* what, unsigned long long limit) {
  if (t.done()) fail_at(source, t.line(), std::string("the file ends before the ") + what);
  const long line = t.line();
  const std::string& text = t.tokens[t.next++];
  const auto v = parse_integer(text);
  if (!v || *v < 0) fail_at(source, line, std::string(what) + " " + quoted(text) + " is not a count");
  if (static_cast<unsigned long long>(*v) > limit)
    fail_at(source, line, std::string(what) + " " + std::to_string(*v) + " exceeds the limit " + std::to_string(limit));
  return *v;
}

Rational number_token(LineTokens& t, const std::string& source, const std::string& what, const NumberLimits& limits) {
  if (t.done()) fail_at(source, t.line(), "the file ends before " + what);
  const long line = t.line();
  const std::string& text = t.tokens[t.next++];
  std::string why;
  auto q = parse_rational(text, &why, limits);
  if (!q) fail_at(source, line, what + " " + quoted(text) + ": " + why);
  return std::move(*q);
}

/// A face given as "3 a b c" with 0-based ids (OFF, PLY).
void read_counted_face(LineTokens& t, ObjMesh& mesh, const std::string& source, std::size_t vertex_count) {
  const long line = t.line();
  const long long n = count_token(t, source, "face vertex count", 1u << 20);
  if (n != 3)
    fail_at(source, line, "face with " + std::to_string(n) + " vertices: only triangles are accepted (triangulate the mesh)");
  std::array<int, 3> face{};
  for (int i = 0; i < 3; ++i) {
    if (t.done() || t.lines[t.next] != line) fail_at(source, line, "a face needs 3 vertex ids on its line");
    const std::string& text = t.tokens[t.next++];
    const auto v = parse_integer(text);
    if (!v || *v < 0 || static_cast<unsigned long long>(*v) >= vertex_count)
      fail_at(source, line, "vertex id " + quoted(text) + " out of range (the file has " +
                                std::to_string(vertex_count) + " vertices, ids 0-based)");
    face[static_cast<std::size_t>(i)] = static_cast<int>(*v);
  }
  if (face[0] == face[1] || face[1] == face[2] || face[0] == face[2])
    fail_at(source, line, "degenerate face: vertex " + std::to_string(face[0] == face[1] ? face[0] : face[2]) +
                              " appears twice");
  mesh.faces.push_back(face);
  mesh.face_lines.push_back(line);
}

/// Whether `name` is one of PLY's scalar types (the specification's names and their sized spellings); with
/// `integer_only`, one of its integer types (a list's count, a face's vertex indices).
bool is_ply_type(const std::string& name, bool integer_only) {
  static const char* const kIntegers[] = {"char", "uchar", "short", "ushort", "int",   "uint",
                                          "int8", "uint8", "int16", "uint16", "int32", "uint32"};
  static const char* const kReals[] = {"float", "double", "float32", "float64"};
  for (const char* type : kIntegers)
    if (name == type) return true;
  if (!integer_only)
    for (const char* type : kReals)
      if (name == type) return true;
  return false;
}

/// Skips the rest of line `line` (extra properties of a PLY element, colours of an OFF face).
void skip_line(LineTokens& t, long line) {
  while (!t.done() && t.lines[t.next] == line) ++t.next;
}

}  // namespace

ObjMesh read_off(std::istream& in, const std::string& source, const MeshReadLimits& limits) {
  LineTokens t = tokenize(in, source);
  ObjMesh mesh;
  mesh.source = source;
  if (t.done() || t.tokens[0] != "OFF")
    fail_at(source, t.line(), "an OFF file starts with \"OFF\" (COFF, NOFF, 4OFF and binary OFF are not read)");
  ++t.next;
  const long header = t.line();
  const auto nv = static_cast<std::size_t>(count_token(t, source, "vertex count", limits.max_vertices));
  const auto nf = static_cast<std::size_t>(count_token(t, source, "face count", limits.max_faces));
  count_token(t, source, "edge count", ~0ull >> 1);
  skip_line(t, header);
  for (std::size_t v = 0; v < nv; ++v) {
    const long line = t.line();
    Rational c[3];
    for (int i = 0; i < 3; ++i) {
      if (!t.done() && t.lines[t.next] != line && i > 0) fail_at(source, line, "a vertex needs 3 coordinates on its line");
      c[i] = number_token(t, source, "coordinate " + std::to_string(i + 1), limits.numbers);
    }
    skip_line(t, line);
    mesh.vertices.push_back(PointQ3{c[0], c[1], c[2]});
    mesh.vertex_lines.push_back(line);
  }
  for (std::size_t f = 0; f < nf; ++f) {
    if (t.done()) fail_at(source, t.line(), "the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const long line = t.line();
    read_counted_face(t, mesh, source, nv);
    skip_line(t, line);
  }
  if (!t.done()) fail_at(source, t.line(), "unexpected text after the last face");
  if (mesh.faces.empty()) fail(source, "no faces");
  return mesh;
}

ObjMesh read_ply(std::istream& in, const std::string& source, const MeshReadLimits& limits) {
  LineTokens t = tokenize(in, source);
  ObjMesh mesh;
  mesh.source = source;
  auto line_tokens = [&]() {  // the tokens of the current line, consumed
    std::vector<std::string> out;
    if (t.done()) return out;
    const long line = t.line();
    while (!t.done() && t.lines[t.next] == line) out.push_back(t.tokens[t.next++]);
    return out;
  };
  if (t.done() || t.tokens[0] != "ply") fail_at(source, 1, "a PLY file starts with \"ply\"");
  line_tokens();
  struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<std::string> properties;  ///< names; a list property is named "list:<name>"
    long line = 0;
  };
  std::vector<Element> elements;
  bool ascii = false;
  for (;;) {
    if (t.done()) fail_at(source, t.line(), "the header has no \"end_header\"");
    const long line = t.line();
    const std::vector<std::string> w = line_tokens();
    if (w[0] == "end_header") break;
    if (w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "format") {
      if (w.size() < 2 || w[1] != "ascii") fail_at(source, line, "only ASCII PLY is read (format ascii 1.0)");
      ascii = true;
    } else if (w[0] == "element") {
      if (w.size() != 3) fail_at(source, line, "an element line is \"element NAME COUNT\"");
      const auto n = parse_integer(w[2]);
      const unsigned long long limit = w[1] == "face" ? limits.max_faces : limits.max_vertices;
      if (!n || *n < 0 || static_cast<unsigned long long>(*n) > limit)
        fail_at(source, line, "element count " + quoted(w[2]) + " is not a count within the limit");
      elements.push_back(Element{w[1], static_cast<std::size_t>(*n), {}, line});
    } else if (w[0] == "property") {
      if (elements.empty()) fail_at(source, line, "a property before any element");
      if (w.size() == 5 && w[1] == "list") {
        const bool indices = w[4] == "vertex_indices" || w[4] == "vertex_index";
        if (!is_ply_type(w[2], true))
          fail_at(source, line, "a list's count type " + quoted(w[2]) + " is not a PLY integer type (uchar, int, ...)");
        if (!is_ply_type(w[3], indices))
          fail_at(source, line, "the list's value type " + quoted(w[3]) + " is not a PLY " +
                                    (indices ? "integer type (int, uint, ...)" : "type (uchar, int, float, ...)"));
        elements.back().properties.push_back("list:" + w[4]);
      } else if (w.size() == 3) {
        if (!is_ply_type(w[1], false))
          fail_at(source, line, "property type " + quoted(w[1]) + " is not a PLY type (uchar, int, float, ...)");
        elements.back().properties.push_back(w[2]);
      } else {
        fail_at(source, line, "a property line is \"property TYPE NAME\" or \"property list TYPE TYPE NAME\"");
      }
    } else {
      fail_at(source, line, "unknown header line " + quoted(w[0]));
    }
  }
  if (!ascii) fail(source, "the header has no \"format ascii 1.0\" line");
  std::size_t nv = 0;
  for (const Element& e : elements) {
    if (e.name == "vertex") {
      int ix = -1, iy = -1, iz = -1;
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        if (e.properties[k].rfind("list:", 0) == 0) fail_at(source, e.line, "a vertex with a list property");
        if (e.properties[k] == "x") ix = static_cast<int>(k);
        if (e.properties[k] == "y") iy = static_cast<int>(k);
        if (e.properties[k] == "z") iz = static_cast<int>(k);
      }
      if (ix < 0 || iy < 0 || iz < 0) fail_at(source, e.line, "the vertex element needs properties x, y and z");
      for (std::size_t v = 0; v < e.count; ++v) {
        const long line = t.line();
        if (t.done()) fail_at(source, line, "the file ends after " + std::to_string(v) + " vertices");
        const std::vector<std::string> w = line_tokens();
        if (w.size() != e.properties.size())
          fail_at(source, line, "a vertex line needs " + std::to_string(e.properties.size()) + " values, got " +
                                    std::to_string(w.size()));
        Rational c[3];
        const int idx[3] = {ix, iy, iz};
        for (int i = 0; i < 3; ++i) {
          std::string why;
          auto q = parse_rational(w[static_cast<std::size_t>(idx[i])], &why, limits.numbers);
          if (!q) fail_at(source, line, "coordinate " + quoted(w[static_cast<std::size_t>(idx[i])]) + ": " + why);
          c[i] = std::move(*q);
        }
        mesh.vertices.push_back(PointQ3{c[0], c[1], c[2]});
        mesh.vertex_lines.push_back(line);
      }
      nv = mesh.vertices.size();
    } else if (e.name == "face") {
      if (e.properties.empty() || (e.properties[0] != "list:vertex_indices" && e.properties[0] != "list:vertex_index"))
        fail_at(source, e.line, "the face element's first property must be the list vertex_indices");
      for (std::size_t f = 0; f < e.count; ++f) {
        if (t.done()) fail_at(source, t.line(), "the file ends after " + std::to_string(f) + " faces");
        const long line = t.line();
        read_counted_face(t, mesh, source, nv);
        if (e.properties.size() > 1)
          skip_line(t, line);  // the face's further properties (colours, ...)
        else if (!t.done() && t.lines[t.next] == line)
          fail_at(source, line, "more values than the face element's one property (the list vertex_indices)");
      }
    } else {
      for (std::size_t k = 0; k < e.count; ++k) line_tokens();  // an element hsx does not use
    }
  }
  if (!t.done()) fail_at(source, t.line(), "unexpected text after the last element");
  if (mesh.faces.empty()) fail(source, "no faces");
  return mesh;
}

ObjMesh read_mesh_file(const std::string& path, const MeshReadLimits& limits) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".obj" && ext != ".off" && ext != ".ply")
    fail(path, "unknown mesh format " + quoted(std::string_view(ext)) + " (expected .obj, .off or .ply)");
  std::ifstream in = open_regular_file(path);
  if (ext == ".off") return read_off(in, path, limits);
  if (ext == ".ply") return read_ply(in, path, limits);
  return read_obj(in, path, limits);
}

FeatureEdgeList read_fea(std::istream& in, const std::string& source, const MeshReadLimits& limits) {
  FeatureEdgeList list;
  list.source = source;
  std::string line;
  long line_no = 0, count_line = 0;
  std::optional<long long> count;
  while (std::getline(in, line)) {
    ++line_no;
    const auto tok = tokens_of(line);
    if (tok.empty()) continue;
    if (!count) {
      if (tok.size() != 1) fail_at(source, line_no, "the first line must be the number of feature edges alone");
      count = parse_integer(tok[0]);
      if (!count || *count < 0) fail_at(source, line_no, "feature edge count " + quoted(tok[0]) + " is not a count");
      if (static_cast<unsigned long long>(*count) > limits.max_feature_edges)
        fail_at(source, line_no, "more than " + std::to_string(limits.max_feature_edges) + " feature edges (limit)");
      count_line = line_no;
      continue;
    }
    if (list.edges.size() >= static_cast<std::size_t>(*count))
      fail_at(source, line_no, "more feature edges than the count " + std::to_string(*count) + " on line " +
                                   std::to_string(count_line));
    if (tok.size() != 2)
      fail_at(source, line_no, "a feature edge is two vertex ids, got " + std::to_string(tok.size()) + " fields");
    int ends[2];
    for (int i = 0; i < 2; ++i) {
      const auto v = parse_integer(tok[static_cast<std::size_t>(i)]);
      if (!v || *v < 0 || *v > 0x7fffffffLL)
        fail_at(source, line_no, "vertex id " + quoted(tok[static_cast<std::size_t>(i)]) +
                                     " is not a 0-based vertex id");
      ends[i] = static_cast<int>(*v);
    }
    list.edges.emplace_back(ends[0], ends[1]);
    list.lines.push_back(line_no);
  }
  if (in.bad()) fail(source, "read error");
  if (!count) fail(source, "empty file: the first line must be the number of feature edges");
  if (list.edges.size() != static_cast<std::size_t>(*count))
    fail_at(source, count_line, "the count says " + std::to_string(*count) + " feature edges but the file lists " +
                                    std::to_string(list.edges.size()));
  return list;
}

FeatureEdgeList read_fea_file(const std::string& path, const MeshReadLimits& limits) {
  std::ifstream in = open_regular_file(path);
  return read_fea(in, path, limits);
}

// ---------------------------------------------------------------------------------------------------------------
// Validation

int Mesh3::find_edge(int u, int v) const {
  const int a = std::min(u, v), b = std::max(u, v);
  auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(a, b),
                             [](const MeshEdge& e, const std::pair<int, int>& k) {
                               return e.a != k.first ? e.a < k.first : e.b < k.second;
                             });
  if (it == edges.end() || it->a != a || it->b != b) return -1;
  return static_cast<int>(it - edges.begin());
}

Mesh3 build_mesh3(ObjMesh obj) {
  Mesh3 m;
  m.source = std::move(obj.source);
  m.vertices = std::move(obj.vertices);
  m.faces = std::move(obj.faces);
  m.vertex_lines = std::move(obj.vertex_lines);
  m.face_lines = std::move(obj.face_lines);
  const std::string& src = m.source;
  const std::size_t nv = m.vertices.size(), nf = m.faces.size();
  // Hand-built ObjMesh values may lack line numbers; then messages fall back to face ids.
  m.vertex_lines.resize(nv, 0);
  m.face_lines.resize(nf, 0);
  auto face_at = [&](int f) -> std::string {
    const long line = m.face_lines[static_cast<std::size_t>(f)];
    return line > 0 ? src + ":" + std::to_string(line) + ": face " + std::to_string(f)
                    : src + ": face " + std::to_string(f);
  };
  auto vertex_name = [&](int v) {
    const long line = m.vertex_lines[static_cast<std::size_t>(v)];
    return "vertex " + std::to_string(v) + (line > 0 ? " (line " + std::to_string(line) + ")" : std::string());
  };
  auto face_line_text = [&](int f) {
    const long line = m.face_lines[static_cast<std::size_t>(f)];
    return line > 0 ? "line " + std::to_string(line) : "face " + std::to_string(f);
  };

  if (nf == 0) fail(src, "no faces");
  if (nv > 0x7fffffffu || nf > 0x7fffffffu / 3) fail(src, "too many vertices or faces");
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& t = m.faces[f];
    for (int v : t)
      if (v < 0 || static_cast<std::size_t>(v) >= nv)
        throw InputError(face_at(static_cast<int>(f)) + ": vertex index " + std::to_string(v) + " out of range");
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw InputError(face_at(static_cast<int>(f)) + ": repeats a vertex");
  }

  // Signs do not change under a positive scale: when every coordinate is a multiple of 1/L for a modest L (decimal
  // input: a power of ten), the predicates below run on L * v, whose rationals are integers, and GMP skips the gcd
  // work that dominates rational arithmetic (about 3x faster on the NH-Rep models).
  Integer scale = 1;
  for (const PointQ3& p : m.vertices) {
    for (const Rational* c : {&p.x, &p.y, &p.z}) mpz_lcm(scale.get_mpz_t(), scale.get_mpz_t(), c->get_den_mpz_t());
    if (mpz_sizeinbase(scale.get_mpz_t(), 2) > 256) {
      scale = 1;  // hostile denominators: stay with plain rationals
      break;
    }
  }
  std::vector<PointQ3> scaled_vertices;
  if (scale != 1) {
    scaled_vertices.reserve(nv);
    const Rational s(scale);
    for (const PointQ3& p : m.vertices) scaled_vertices.push_back(PointQ3{p.x * s, p.y * s, p.z * s});
  }
  const std::vector<PointQ3>& work = scale != 1 ? scaled_vertices : m.vertices;
  auto at = [&](int v) -> const PointQ3& { return work[static_cast<std::size_t>(v)]; };

  // 1. Normals; a zero normal leaves the dihedral type of the triangle's edges undefined.
  m.normals.resize(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& t = m.faces[f];
    m.normals[f] = triangle_normal(at(t[0]), at(t[1]), at(t[2]));
    if (sgn(m.normals[f].x) == 0 && sgn(m.normals[f].y) == 0 && sgn(m.normals[f].z) == 0)
      throw InputError(face_at(static_cast<int>(f)) + ": zero-area triangle (" + std::to_string(t[0]) + ", " +
                       std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                       "): its vertices are collinear, so its normal and its edges' dihedral types are undefined");
  }

  // 2. Every undirected edge in exactly two faces, traversed in opposite directions.
  {
    const std::vector<Half> halves = halves_of(m.faces);
    std::string first;
    std::size_t bad = 0;
    for (std::size_t i = 0; i < halves.size();) {
      std::size_t j = i;
      while (j < halves.size() && halves[j].key == halves[i].key) ++j;
      const std::size_t n = j - i;
      std::string problem;
      if (n == 1) {
        problem = face_at(halves[i].face) + ": " + edge_name(halves[i].key) +
                  " belongs to this face only: the mesh is not closed";
      } else if (n > 2) {
        problem = face_at(halves[i].face) + ": " + edge_name(halves[i].key) + " is shared by " + std::to_string(n) +
                  " faces (";
        for (std::size_t k = i; k < j && k < i + 6; ++k)
          problem += (k > i ? ", " : "") + face_line_text(halves[k].face);
        problem += std::string(n > 6 ? ", ..." : "") + "): the mesh is not edge-manifold";
      } else if (halves[i].forward == halves[i + 1].forward) {
        problem = face_at(halves[i].face) + ": " + edge_name(halves[i].key) + " is traversed in the same direction by " +
                  face_line_text(halves[i + 1].face) + ": inconsistent orientation";
      }
      if (!problem.empty() && bad++ == 0) first = problem;
      i = j;
    }
    if (bad > 0)
      throw InputError(first + (bad > 1 ? " (" + std::to_string(bad - 1) + " more bad edges)" : std::string()));
  }

  // 3. Vertex manifold: around each vertex v, face (v, p, q) maps p -> q. With step 2 passed this is a permutation
  //    of v's neighbours; a single cycle means a single fan.
  {
    std::vector<int> start(nv + 1, 0);
    for (const auto& t : m.faces)
      for (int v : t) ++start[static_cast<std::size_t>(v) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::pair<int, int>> link(nf * 3);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (const auto& t : m.faces)
      for (int k = 0; k < 3; ++k)
        link[static_cast<std::size_t>(fill[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])]++)] = {
            t[static_cast<std::size_t>((k + 1) % 3)], t[static_cast<std::size_t>((k + 2) % 3)]};
    std::size_t unused = 0, pinched = 0;
    std::string first;
    for (std::size_t v = 0; v < nv; ++v) {
      const auto b = link.begin() + start[v], e = link.begin() + start[v + 1];
      const auto degree = static_cast<std::size_t>(e - b);
      if (degree == 0) {
        ++unused;
        continue;
      }
      std::sort(b, e);
      const int origin = b->first;
      int current = origin;
      std::size_t steps = 0;
      do {
        const auto it = std::lower_bound(b, e, std::make_pair(current, -1));
        current = it->second;  // exists: every neighbour starts exactly one wedge (step 2)
        ++steps;
      } while (current != origin && steps <= degree);
      if (steps != degree && pinched++ == 0)
        first = src + ": " + vertex_name(static_cast<int>(v)) + ": its " + std::to_string(degree) +
                " faces form more than one fan (the surface is pinched there): the mesh is not vertex-manifold";
    }
    if (pinched > 0)
      throw InputError(first + (pinched > 1 ? " (" + std::to_string(pinched - 1) + " more such vertices)" : std::string()));
    if (unused > 0)
      m.notes.push_back(std::to_string(unused) + " vertices are used by no face (ignored)");
  }

  // 4. Volume: sum over faces of det(a, b, c) / 6 = a . ((b - a) x (c - a)) / 6.
  Rational six_volume = 0;
  for (std::size_t f = 0; f < nf; ++f) six_volume += dot3(at(m.faces[f][0]), m.normals[f]);
  six_volume /= Rational(scale * scale * scale);
  if (sgn(six_volume) == 0) fail(src, "the mesh encloses zero volume (signed volume is exactly 0)");
  if (sgn(six_volume) < 0) {
    for (std::size_t f = 0; f < nf; ++f) {
      std::swap(m.faces[f][1], m.faces[f][2]);
      m.normals[f] = PointQ3{-m.normals[f].x, -m.normals[f].y, -m.normals[f].z};
    }
    six_volume = -six_volume;
    m.flipped = true;
    m.notes.push_back("the faces were oriented inward (signed volume -" + decimal_string(six_volume / 6, 12) +
                      "); every face was reversed");
  }
  m.volume = six_volume / 6;

  // 5. Edges (after orientation), their shapes, and shells.
  const std::vector<Half> halves = halves_of(m.faces);
  m.edges.reserve(halves.size() / 2);
  m.face_edges.assign(nf, {-1, -1, -1});
  DisjointSets shells(nf);  // faces joined across edges
  std::size_t folds = 0;
  std::string first_fold;
  for (std::size_t i = 0; i + 1 < halves.size(); i += 2) {
    const Half& h0 = halves[i];
    const Half& h1 = halves[i + 1];
    MeshEdge e;
    e.a = static_cast<int>(h0.key >> 32);
    e.b = static_cast<int>(h0.key & 0xffffffffu);
    e.face_ab = h0.forward ? h0.face : h1.face;
    e.face_ba = h0.forward ? h1.face : h0.face;
    const int id = static_cast<int>(m.edges.size());
    m.face_edges[static_cast<std::size_t>(h0.face)][static_cast<std::size_t>(h0.k)] = id;
    m.face_edges[static_cast<std::size_t>(h1.face)][static_cast<std::size_t>(h1.k)] = id;
    shells.union_set(h0.face, h1.face);

    auto third = [&](int f) {
      for (int v : m.faces[static_cast<std::size_t>(f)])
        if (v != e.a && v != e.b) return v;
      return -1;  // unreachable: faces have three distinct vertices
    };
    const PointQ3& n1 = m.normals[static_cast<std::size_t>(e.face_ab)];
    const int w2 = third(e.face_ba);
    const int side = sgn(dot3(n1, minus(at(w2), at(e.a))));
    if (side < 0) {
      e.shape = EdgeShape::Convex;
    } else if (side > 0) {
      e.shape = EdgeShape::Concave;
    } else if (sgn(dot3(n1, m.normals[static_cast<std::size_t>(e.face_ba)])) > 0) {
      e.shape = EdgeShape::Flat;
    } else if (folds++ == 0) {
      // Coplanar faces on the same side of the edge: interior angle 0 or 360 degrees, which the two triangles
      // alone cannot tell apart.
      first_fold = face_at(e.face_ab) + ": " + edge_name(h0.key) + ": this face and " + face_line_text(e.face_ba) +
                   " fold back onto each other (coplanar, on the same side of the edge): the solid has zero "
                   "thickness there";
    }
    m.edges.push_back(e);
  }
  if (folds > 0)
    throw InputError(first_fold + (folds > 1 ? " (" + std::to_string(folds - 1) + " more such edges)" : std::string()));
  m.shells = components_of(shells, nf).count;
  if (m.shells > 1) m.notes.push_back("the mesh has " + std::to_string(m.shells) + " shells (connected components)");
  return m;
}

Mesh3 read_mesh3_file(const std::string& path, const MeshReadLimits& limits) {
  return build_mesh3(read_obj_file(path, limits));
}

std::vector<char> resolve_feature_edges(const Mesh3& mesh, const FeatureEdgeList& features,
                                        std::vector<std::string>* notes) {
  std::vector<char> marked(mesh.edges.size(), 0);
  std::vector<long> self_lines, duplicate_lines;
  const auto nv = static_cast<long long>(mesh.vertices.size());
  for (std::size_t i = 0; i < features.edges.size(); ++i) {
    const auto [u, v] = features.edges[i];
    const long line = i < features.lines.size() ? features.lines[i] : 0;
    auto where = [&]() {
      return line > 0 ? features.source + ":" + std::to_string(line) : features.source + ": entry " + std::to_string(i);
    };
    for (int x : {u, v})
      if (x < 0 || x >= nv)
        throw InputError(where() + ": vertex id " + std::to_string(x) + " out of range (the mesh has " +
                         std::to_string(nv) + " vertices, ids 0-based)");
    if (u == v) {
      self_lines.push_back(line > 0 ? line : static_cast<long>(i));
      continue;
    }
    const int e = mesh.find_edge(u, v);
    if (e < 0)
      throw InputError(where() + ": (" + std::to_string(u) + ", " + std::to_string(v) +
                       ") is not an edge of the mesh (no face has both vertices as an edge)");
    if (marked[static_cast<std::size_t>(e)]) duplicate_lines.push_back(line > 0 ? line : static_cast<long>(i));
    marked[static_cast<std::size_t>(e)] = 1;
  }
  if (notes) {
    const std::string what = features.lines.empty() ? "entries " : "lines ";
    if (!self_lines.empty())
      notes->push_back(features.source + ": " + std::to_string(self_lines.size()) +
                       " feature edges join a vertex to itself and were skipped (" + what + lines_list(self_lines) + ")");
    if (!duplicate_lines.empty())
      notes->push_back(features.source + ": " + std::to_string(duplicate_lines.size()) +
                       " feature edges repeat an earlier one (" + what + lines_list(duplicate_lines) + ")");
  }
  return marked;
}

// ---------------------------------------------------------------------------------------------------------------
// Sharpness

SharpnessAngle::SharpnessAngle(const Rational& degrees) : degrees_(degrees), cos2_(kBaseBits) {
  degrees_.canonicalize();  // the integer test below needs lowest terms
  if (sgn(degrees_) < 0 || degrees_ >= 180)
    throw InputError("sharpness angle: must be at least 0 and less than 180 degrees, got " + exact_string(degrees_));
  cos_sign_ = degrees_ < 90 ? 1 : (degrees_ == 90 ? 0 : -1);
  // cos^2(delta) = (1 + cos 2 delta) / 2 is rational iff cos(2 delta) is, i.e. (Niven) 2 delta is a multiple of 60
  // or 90 degrees.
  if (degrees_.get_den() == 1) {
    const long d = degrees_.get_num().get_si();
    static constexpr struct { long degrees; int num, den; } kTable[] = {
        {0, 1, 1}, {30, 3, 4}, {45, 1, 2}, {60, 1, 4}, {90, 0, 1}, {120, 1, 4}, {135, 1, 2}, {150, 3, 4}};
    for (const auto& row : kTable)
      if (row.degrees == d) cos2_exact_ = make_rational(Integer(row.num), Integer(row.den));
  }
  cos2_ = cos2_enclosure(kBaseBits);
}

Interval SharpnessAngle::cos2_enclosure(mpfr_prec_t bits) const {
  if (cos2_exact_) return Interval(*cos2_exact_, bits);
  const mpfr_prec_t work = bits + 16;
  const Interval pi = Interval::pi(work);
  const Interval angle = Interval(degrees_ / 180, work) * pi;  // in (0, pi): both factors positive
  mpfr_t c_lo, c_hi, s_lo, s_hi;
  mpfr_inits2(work, c_lo, c_hi, s_lo, s_hi, static_cast<mpfr_ptr>(nullptr));
  // cos is decreasing on [0, pi]; the true angle is below pi, so an upper end at or past pi's lower bound only
  // tells us cos > -1.
  if (mpfr_cmp(angle.hi(), pi.lo()) >= 0)
    mpfr_set_si(c_lo, -1, MPFR_RNDD);
  else
    mpfr_cos(c_lo, angle.hi(), MPFR_RNDD);
  mpfr_cos(c_hi, angle.lo(), MPFR_RNDU);
  if (mpfr_sgn(c_lo) >= 0) {
    mpfr_sqr(s_lo, c_lo, MPFR_RNDD);
    mpfr_sqr(s_hi, c_hi, MPFR_RNDU);
  } else if (mpfr_sgn(c_hi) <= 0) {
    mpfr_sqr(s_lo, c_hi, MPFR_RNDD);
    mpfr_sqr(s_hi, c_lo, MPFR_RNDU);
  } else {  // c_lo < 0 < c_hi: the square ranges over [0, max(c_lo^2, c_hi^2)]
    mpfr_sqr(s_lo, c_lo, MPFR_RNDU);
    mpfr_sqr(s_hi, c_hi, MPFR_RNDU);
    mpfr_max(s_hi, s_hi, s_lo, MPFR_RNDU);
    mpfr_set_zero(s_lo, 1);
  }
  Interval result = Interval::from_ends(s_lo, s_hi);
  mpfr_clears(c_lo, c_hi, s_lo, s_hi, static_cast<mpfr_ptr>(nullptr));
  return result;
}

bool SharpnessAngle::closer_than(const PointQ3& n1, const PointQ3& n2) const {
  auto zero = [](const PointQ3& v) { return sgn(v.x) == 0 && sgn(v.y) == 0 && sgn(v.z) == 0; };
  if (zero(n1) || zero(n2)) throw std::invalid_argument("SharpnessAngle::closer_than: a zero vector has no direction");
  const Rational c = dot3(n1, n2);
  const int s = sgn(c);
  if (cos_sign_ == 0) return s > 0;                  // delta = 90: theta < 90 iff cos theta > 0
  if (cos_sign_ > 0 && s <= 0) return false;         // cos theta <= 0 < cos delta
  if (cos_sign_ < 0 && s >= 0) return true;          // cos theta >= 0 > cos delta
  const Rational cos2_theta = c * c / (dot3(n1, n1) * dot3(n2, n2));
  // Same signs: delta < 90 needs cos^2 theta > cos^2 delta; delta > 90 needs cos^2 theta < cos^2 delta.
  int order = 0;  // sign of cos^2 theta - cos^2 delta
  if (cos2_exact_) {
    order = cmp(cos2_theta, *cos2_exact_);
  } else {
    for (mpfr_prec_t bits = kBaseBits;; bits *= 2) {
      if (bits > kMaxBits)
        throw std::runtime_error("sharpness angle: comparison with cos^2(" + exact_string(degrees_) +
                                 " degrees) not decided at " + std::to_string(kMaxBits) + " bits");
      const Interval enclosure = bits == kBaseBits ? cos2_ : cos2_enclosure(bits);
      if (mpfr_cmp_q(enclosure.hi(), cos2_theta.get_mpq_t()) < 0) { order = 1; break; }
      if (mpfr_cmp_q(enclosure.lo(), cos2_theta.get_mpq_t()) > 0) { order = -1; break; }
    }
  }
  return cos_sign_ > 0 ? order > 0 : order < 0;
}

bool SharpnessAngle::smooth(const Mesh3& mesh, int edge) const {
  const MeshEdge& e = mesh.edges[static_cast<std::size_t>(edge)];
  return e.shape == EdgeShape::Flat ||
         closer_than(mesh.normals[static_cast<std::size_t>(e.face_ab)], mesh.normals[static_cast<std::size_t>(e.face_ba)]);
}

EdgeShape classify_edge(const Mesh3& mesh, int edge, const SharpnessAngle& sharpness) {
  return sharpness.smooth(mesh, edge) ? EdgeShape::Flat : mesh.edges[static_cast<std::size_t>(edge)].shape;
}

}  // namespace hsx
