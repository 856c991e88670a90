// Bytes -> a small 3D scene -> the exact 3D arrangement and its complex, with every invariant checked exactly.
// Input: text starting with '{' is an hsx-scene/1 document (at most 8 halfspaces, 16 samples, 12 segments per
// circle); anything else is decoded as byte 0: halfspace count 1 + b % 6, then 8 bytes per halfspace (kind and
// parameters on a half-unit grid in the domain [-6, 6]^3: plane, box, sphere, torus, cylinder or cone, 3 to 8
// segments per circle, bit 7 of the kind byte = complement), then 4 bytes per sample (halfspace, a point to snap
// with `near`). Scenes with more than kMaxInputTriangles surface triangles are skipped (one execution stays well
// under a second). Bad input must end in InputError (a zero plane normal, a sample on a junction, a surface
// intersecting itself ...); anything else is a finding. Checked on every arrangement:
// - the cells' volumes sum to the domain's volume exactly; the cells inside each halfspace fill its volume inside
//   the domain (a surface's enclosed volume, a plane's part of the box, computed here by clipping);
// - every cell's interior point is located in that cell and classifies directly (Halfspace3::side) as its sides;
// - across every triangle the two cells differ exactly in its halfspaces, on the sides it records; check_complex
//   (a patch's cells differ exactly in its support group's halfspaces, and the rest of the complex's structure);
// - each sample is located on the boundary, on a triangle between its patch's two cells when it is on a triangle;
// - a surface that stays off the domain's faces: its patches' areas sum exactly to its triangles' area;
// - a few rational points derived from the input: located in the cell whose sides they have, or off the cells
//   exactly when they lie on a boundary.
#include "fuzz_support.hpp"

#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/io/exact_json.hpp>
#include <hsx/io/scene_json.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace {

constexpr const char* kTarget = "fuzz_arrange3";
constexpr std::size_t kMaxInputTriangles = 200;

using hsx::PointQ3;
using hsx::Rational;

[[noreturn]] void finding(const std::string& what) { hsx::fuzz::finding(kTarget, what); }

PointQ3 sub(const PointQ3& a, const PointQ3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
PointQ3 cross(const PointQ3& a, const PointQ3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// ----- decoding bytes into a scene document -----

std::string half(int v) { return v % 2 == 0 ? std::to_string(v / 2) : std::to_string(v) + "/2"; }
nlohmann::json point(int x, int y, int z) { return nlohmann::json::array({half(x), half(y), half(z)}); }
int signed_mod(std::uint8_t b, int m) { return static_cast<int>(b % (2 * m + 1)) - m; }  // in [-m, m]

nlohmann::json halfspace(const std::uint8_t* b, int index) {
  nlohmann::json h;
  h["name"] = "H" + std::to_string(index);
  if (b[0] & 0x80) h["complement"] = true;
  const int cx = signed_mod(b[1], 4), cy = signed_mod(b[2], 4), cz = signed_mod(b[3], 4);  // half units
  const int axis = b[4] % 3;
  const int dir[3] = {axis == 0, axis == 1, axis == 2};
  switch ((b[0] & 0x7f) % 6) {
    case 0:
      h["kind"] = "plane";
      h["normal"] = nlohmann::json::array({signed_mod(b[1], 2), signed_mod(b[2], 2), signed_mod(b[3], 2)});
      h["offset"] = half(signed_mod(b[5], 8));
      break;
    case 1:
      h["kind"] = "box";
      h["min"] = point(cx, cy, cz);
      h["max"] = point(cx + 1 + b[5] % 4, cy + 1 + b[6] % 4, cz + 1 + b[7] % 4);
      break;
    case 2:
      h["kind"] = "sphere";
      h["center"] = point(cx, cy, cz);
      h["radius"] = half(1 + b[5] % 4);
      h["tessellation"] = {{"segments", 3 + b[6] % 6}};
      break;
    case 3:
      h["kind"] = "torus";
      h["center"] = point(cx, cy, cz);
      h["axis"] = nlohmann::json::array({dir[0], dir[1], dir[2] + (b[7] & 0x80 ? 1 : 0)});
      h["major_radius"] = half(2 + b[5] % 3);
      h["minor_radius"] = std::to_string(1 + b[6] % 3) + "/8";
      h["tessellation"] = {{"segments", 3 + b[7] % 6}, {"minor_segments", 3 + (b[7] >> 3) % 4}};
      break;
    default: {
      const bool cone = (b[0] & 0x7f) % 6 == 5;
      h["kind"] = cone ? "cone" : "cylinder";
      const int length = 1 + b[5] % 4;
      h[cone ? "apex" : "axis_point1"] = point(cx, cy, cz);
      h[cone ? "base_center" : "axis_point2"] = point(cx + length * dir[0], cy + length * dir[1], cz + length * dir[2]);
      h["radius"] = half(1 + b[6] % 3);
      h["tessellation"] = {{"segments", 3 + b[7] % 6}};
      break;
    }
  }
  return h;
}

nlohmann::json decode(const std::uint8_t* data, std::size_t size) {
  nlohmann::json doc = {{"format", "hsx-scene/1"}, {"dimension", 3},
                        {"domain", {{"min", point(-12, -12, -12)}, {"max", point(12, 12, 12)}}}};
  const std::size_t n = size == 0 ? 1 : 1 + data[0] % 6;
  std::vector<std::uint8_t> bytes(data + (size ? 1 : 0), data + size);
  bytes.resize(std::max(bytes.size(), 8 * n), 0);
  nlohmann::json halfspaces = nlohmann::json::array();
  for (std::size_t i = 0; i < n; ++i) halfspaces.push_back(halfspace(&bytes[8 * i], static_cast<int>(i)));
  doc["halfspaces"] = halfspaces;
  nlohmann::json samples = nlohmann::json::array();
  for (std::size_t k = 8 * n; k + 4 <= bytes.size() && samples.size() < 8; k += 4)
    samples.push_back({{"on", "H" + std::to_string(bytes[k] % n)},
                       {"near", point(signed_mod(bytes[k + 1], 12), signed_mod(bytes[k + 2], 12), signed_mod(bytes[k + 3], 12))}});
  doc["samples"] = samples;
  return doc;
}

// ----- independent measures -----

Rational box_volume(const hsx::Box3& b) { return (b.max.x - b.min.x) * (b.max.y - b.min.y) * (b.max.z - b.min.z); }

/// The domain box's part { n . x <= d }: its triangles clipped to the halfspace, tetrahedra about a point of the
/// plane (the cut's cap lies in the plane and adds nothing).
Rational plane_volume(const hsx::Box3& box, const PointQ3& n, const Rational& d) {
  PointQ3 o{0, 0, 0};
  if (n.x != 0) o.x = d / n.x;
  else if (n.y != 0) o.y = d / n.y;
  else o.z = d / n.z;
  std::vector<PointQ3> corner;
  for (int i = 0; i < 8; ++i)
    corner.push_back({(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, (i & 4) ? box.max.z : box.min.z});
  const int triangles[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};  // outward
  Rational six;
  for (const auto& t : triangles) {
    std::vector<PointQ3> clipped;
    for (int i = 0; i < 3; ++i) {
      const PointQ3& a = corner[static_cast<std::size_t>(t[i])];
      const PointQ3& b = corner[static_cast<std::size_t>(t[(i + 1) % 3])];
      const Rational fa = hsx::dot3(n, a) - d, fb = hsx::dot3(n, b) - d;
      if (fa <= 0) clipped.push_back(a);
      if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) {
        const Rational s = fa / (fa - fb);
        clipped.push_back({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.z + s * (b.z - a.z)});
      }
    }
    for (std::size_t i = 1; i + 1 < clipped.size(); ++i)
      six += hsx::dot3(sub(clipped[0], o), cross(sub(clipped[i], o), sub(clipped[i + 1], o)));
  }
  return six / 6;
}

Rational surface_volume(const hsx::TriangleSurface& s) {
  Rational six;
  for (const auto& t : s.triangles) six += hsx::dot3(s.vertices[t[0]], cross(s.vertices[t[1]], s.vertices[t[2]]));
  return six / 6;
}

bool touches_domain(const hsx::TriangleSurface& s, const hsx::Box3& b) {
  for (const PointQ3& p : s.vertices)
    if (p.x == b.min.x || p.x == b.max.x || p.y == b.min.y || p.y == b.max.y || p.z == b.min.z || p.z == b.max.z)
      return true;
  return false;
}

// ----- the checks -----

void check_cells(const hsx::Scene3& scene, const hsx::Arrangement3& arr) {
  Rational total;
  for (std::size_t c = 0; c < arr.cells().size(); ++c) {
    const hsx::ArrCell3& cell = arr.cells()[c];
    if (!cell.volume || *cell.volume <= 0) finding("a cell without a positive volume");
    total += *cell.volume;
    const hsx::PointLocation3 loc = arr.locate(cell.interior);
    if (loc.kind != hsx::PointLocation3::Cell || loc.index != static_cast<int>(c))
      finding("cell " + std::to_string(c) + "'s interior point is not located in it");
    for (std::size_t h = 0; h < scene.halfspaces.size(); ++h)
      if (scene.halfspaces[h].side(cell.interior) != (cell.inside[h] ? 1 : -1))
        finding("cell " + std::to_string(c) + "'s side of halfspace " + std::to_string(h) + " is wrong");
  }
  if (total != box_volume(scene.domain)) finding("cell volumes do not sum to the domain's volume");
  for (std::size_t h = 0; h < scene.halfspaces.size(); ++h) {
    const hsx::Halfspace3& hs = scene.halfspaces[h];
    Rational in;
    for (const hsx::ArrCell3& cell : arr.cells())
      if (cell.inside[h]) in += *cell.volume;
    Rational expected = hs.kind == hsx::HalfspaceKind3::Plane ? plane_volume(scene.domain, hs.normal, hs.offset)
                                                              : surface_volume(hs.surface);
    if (hs.complement) expected = box_volume(scene.domain) - expected;
    if (in != expected) finding("the cells inside halfspace " + std::to_string(h) + " do not fill its volume");
  }
}

void check_triangles(const hsx::Arrangement3& arr) {
  for (const hsx::ArrTriangle3& t : arr.triangles()) {
    if (t.on_box) {
      if ((t.front_cell < 0) == (t.back_cell < 0)) finding("a box triangle without exactly one cell");
      continue;
    }
    if (t.front_cell < 0 || t.back_cell < 0) finding("an inner triangle without two cells");
    const auto& f = arr.cells()[static_cast<std::size_t>(t.front_cell)].inside;
    const auto& b = arr.cells()[static_cast<std::size_t>(t.back_cell)].inside;
    std::size_t k = 0;
    for (int h = 0; h < arr.halfspace_count(); ++h) {
      const bool carried = k < t.halfspaces.size() && t.halfspaces[k] == h;
      if (!carried && f[h] != b[h]) finding("cells across a triangle differ in a halfspace it does not carry");
      if (carried && (f[h] == b[h] || f[h] != t.front_inside[k])) finding("a triangle's sides are wrong");
      if (carried) ++k;
    }
  }
  for (const hsx::ArrEdge3& e : arr.edges())
    if (e.triangles.size() < 2) finding("an edge with fewer than two triangles");
}

void check_complex_and_samples(const hsx::Scene3& scene, const hsx::Arranged3& a) {
  const auto problems = hsx::check_complex(a.complex);
  if (!problems.empty()) finding("check_complex: " + problems.front());
  if (a.complex.samples.size() != scene.samples.size()) finding("samples lost");
  for (std::size_t j = 0; j < scene.samples.size(); ++j) {
    const hsx::PointLocation3 loc = a.arrangement.locate(scene.samples[j].location);
    if (loc.kind == hsx::PointLocation3::Cell || loc.kind == hsx::PointLocation3::Outside)
      finding("sample " + std::to_string(j) + " is not located on the boundary");
    const hsx::Patch& p = a.complex.patches.at(static_cast<std::size_t>(a.complex.samples[j].patch));
    if (loc.kind == hsx::PointLocation3::Triangle) {
      const hsx::ArrTriangle3& t = a.arrangement.triangles()[static_cast<std::size_t>(loc.index)];
      const bool adjacent = (t.front_cell == p.inside_cell && t.back_cell == p.outside_cell) ||
                            (t.front_cell == p.outside_cell && t.back_cell == p.inside_cell);
      if (!adjacent) finding("sample " + std::to_string(j) + " is located on a triangle not between its patch's cells");
    }
  }
  for (std::size_t h = 0; h < scene.halfspaces.size(); ++h) {
    const hsx::Halfspace3& hs = scene.halfspaces[h];
    if (hs.kind == hsx::HalfspaceKind3::Plane || touches_domain(hs.surface, scene.domain)) continue;
    hsx::Measure patches, triangles;
    for (const hsx::Patch& p : a.complex.patches)
      if (p.halfspace == static_cast<int>(h)) patches += p.measure;
    for (const auto& t : hs.surface.triangles) {
      const PointQ3 n = cross(sub(hs.surface.vertices[t[1]], hs.surface.vertices[t[0]]),
                              sub(hs.surface.vertices[t[2]], hs.surface.vertices[t[0]]));
      triangles += hsx::Measure::sqrt_of(hsx::dot3(n, n)) * Rational(1, 2);
    }
    if (!(patches - triangles).is_zero()) finding("halfspace " + std::to_string(h) + "'s patches miss area");
  }
}

void check_points(const hsx::Scene3& scene, const hsx::Arrangement3& arr, const std::uint8_t* data, std::size_t size) {
  const hsx::Box3& b = scene.domain;
  for (std::size_t k = 0; k + 3 <= size && k < 12; k += 3) {
    auto coord = [](const Rational& lo, const Rational& hi, std::uint8_t byte) -> Rational {  // not a gmpxx expression
      return lo + (hi - lo) * hsx::make_rational(hsx::Integer(1 + byte % 63), hsx::Integer(64));  // inside the box
    };
    const PointQ3 p{coord(b.min.x, b.max.x, data[k]), coord(b.min.y, b.max.y, data[k + 1]),
                    coord(b.min.z, b.max.z, data[k + 2])};
    bool on_boundary = false;
    for (const hsx::Halfspace3& h : scene.halfspaces) on_boundary = on_boundary || h.side(p) == 0;
    const hsx::PointLocation3 loc = arr.locate(p);
    if (on_boundary != (loc.kind != hsx::PointLocation3::Cell)) finding("a point located against its sides");
    if (on_boundary) continue;
    const auto& inside = arr.cells()[static_cast<std::size_t>(loc.index)].inside;
    for (std::size_t h = 0; h < scene.halfspaces.size(); ++h)
      if ((scene.halfspaces[h].side(p) > 0) != (inside[h] != 0)) finding("a point located in a cell of other sides");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 8192) return -1;
  hsx::SceneReadLimits limits;
  limits.json.max_bytes = 8192;
  limits.numbers.max_chars = 40;
  limits.numbers.max_exponent = 12;
  limits.max_halfspaces = 8;
  limits.max_samples = 16;
  limits.max_segments = 12;
  hsx::Scene3 scene;
  try {
    const nlohmann::json doc = size > 0 && data[0] == '{' ? hsx::parse_exact_json(hsx::fuzz::as_text(data, size), limits.json)
                                                          : decode(data, size);
    scene = hsx::read_scene3(doc, "/nonexistent-hsx-fuzz-folder", limits);
  } catch (const hsx::InputError&) {
    return 0;
  }
  std::size_t triangles = 0;
  for (const hsx::Halfspace3& h : scene.halfspaces) triangles += h.surface.triangles.size();
  if (triangles > kMaxInputTriangles) return 0;
  hsx::ArrangementLimits arrangement_limits;
  arrangement_limits.max_triangles = 20000;
  hsx::Arrangement3Options options;
  options.threads = 1;
  hsx::Arranged3 a;
  try {
    a = hsx::arrange(scene, arrangement_limits, options);
  } catch (const hsx::InputError&) {
    return 0;
  }
  check_cells(scene, a.arrangement);
  check_triangles(a.arrangement);
  check_complex_and_samples(scene, a);
  check_points(scene, a.arrangement, data, size);
  return 0;
}
