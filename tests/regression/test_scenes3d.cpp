// Regression test of our own 3D scenes (data/scenes3d/: the shapes of BSH Figs. 15, 16 and 19 with our numbers, and
// degenerate ones), against expectations derived without the code under test:
// - cell counts, outer cells, patch and support counts by counting (the reasoning is written beside each scene);
// - exact volumes from an independent rebuild of the documented tessellation (include/hsx/geometry/
//   tessellate3.hpp) in long double, rounded to the 2^-32 grid as documented, then exact rational sums: the volume
//   of a closed triangle mesh is the sum of det(a, b, c) / 6, and of a mesh cut by a plane the same sum over the
//   triangles clipped to the halfspace, taken about a point of the plane (the cap then adds nothing);
// - for every halfspace, the cells inside it fill exactly its volume inside the domain; for every surface, its
//   patches' areas sum exactly to the rebuilt surface's area (sqrt(q) / 2 per triangle);
// - the K = 1 beam search's shape: the cells it must contain (read off the construction: the samples sit on every
//   face of the intended solid), its volume where that is independent, and its boundary's patch and support counts;
// - invariance: translated by a rational vector, mirrored, with the halfspaces permuted, every scene gives the same
//   counts and the same cells (sides and exact volumes) up to renaming.
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/io/scene_json.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

using namespace hsx;
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------------------------------------------
// Independent geometry: rational vectors, meshes rebuilt from the documented tessellation, volumes and areas.

PointQ3 sub(const PointQ3& a, const PointQ3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Rational dot(const PointQ3& a, const PointQ3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
PointQ3 cross(const PointQ3& a, const PointQ3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Rational q(long n, long d = 1) { return make_rational(Integer(n), Integer(d)); }
PointQ3 pt(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }

struct Solid {
  std::vector<PointQ3> v;
  std::vector<std::array<int, 3>> t;  // outward
};

/// The documented rounding: the nearest multiple of 2^-32 (ties to even; long double carries 64 bits).
Rational grid(long double x) {
  const long double scaled = std::nearbyint(std::ldexp(x, 32));
  return make_rational(Integer(std::to_string(static_cast<long long>(scaled))), Integer(1) << 32);
}

const long double kPi = 3.141592653589793238462643383279502884L;

long double ld(const Rational& r) {
  return std::stold(r.get_num().get_str()) / std::stold(r.get_den().get_str());  // 64 bits, not a double's 53
}

/// The frame of the axis +z (every curved primitive of these scenes): u = +y, v = -x, w = +z. A ring point
/// c + rho (cos t u + sin t v) + h w, rounded.
PointQ3 ring_point(const PointQ3& c, long double rho, long double t, long double h) {
  return {grid(ld(c.x) - rho * std::sin(t)), grid(ld(c.y) + rho * std::cos(t)), grid(ld(c.z) + h)};
}

void band(Solid& s, int lower, int upper, int n) {
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n;
    s.t.push_back({lower + k, lower + k1, upper + k});
    s.t.push_back({lower + k1, upper + k1, upper + k});
  }
}
void fan_bottom(Solid& s, int pole, int ring, int n) {
  for (int k = 0; k < n; ++k) s.t.push_back({pole, ring + (k + 1) % n, ring + k});
}
void fan_top(Solid& s, int pole, int ring, int n) {
  for (int k = 0; k < n; ++k) s.t.push_back({pole, ring + k, ring + (k + 1) % n});
}

Solid box_solid(const PointQ3& lo, const PointQ3& hi) {
  Solid s;
  for (int i = 0; i < 8; ++i) s.v.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  s.t = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
         {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return s;
}

Solid sphere_solid(const PointQ3& c, const Rational& radius, int n) {
  const long double r = ld(radius);
  const int m = (n + 1) / 2;
  Solid s;
  s.v.push_back(ring_point(c, 0, 0, -r));  // poles are rounded like every vertex
  for (int j = 1; j < m; ++j) {
    const long double phi = -kPi / 2 + kPi * j / m;
    for (int k = 0; k < n; ++k) s.v.push_back(ring_point(c, r * std::cos(phi), 2 * kPi * k / n, r * std::sin(phi)));
  }
  s.v.push_back(ring_point(c, 0, 0, r));
  fan_bottom(s, 0, 1, n);
  for (int j = 1; j + 1 < m; ++j) band(s, 1 + (j - 1) * n, 1 + j * n, n);
  fan_top(s, static_cast<int>(s.v.size()) - 1, 1 + (m - 2) * n, n);
  return s;
}

Solid torus_solid(const PointQ3& c, const Rational& major, const Rational& minor, int n, int m) {
  Solid s;
  for (int j = 0; j < m; ++j) {
    const long double phi = 2 * kPi * j / m;
    for (int k = 0; k < n; ++k)
      s.v.push_back(ring_point(c, ld(major) + ld(minor) * std::cos(phi), 2 * kPi * k / n, ld(minor) * std::sin(phi)));
  }
  for (int j = 0; j < m; ++j) band(s, j * n, ((j + 1) % m) * n, n);
  return s;
}

/// A finite cylinder along +z from c1 to c2 (c2 = c1 + h z).
Solid cylinder_solid(const PointQ3& c1, const PointQ3& c2, const Rational& radius, int n) {
  Solid s;
  for (const PointQ3* c : {&c1, &c2})
    for (int k = 0; k < n; ++k) s.v.push_back(ring_point(*c, ld(radius), 2 * kPi * k / n, 0));
  s.v.push_back(ring_point(c1, 0, 0, 0));  // cap centres, rounded the same way
  s.v.push_back(ring_point(c2, 0, 0, 0));
  fan_bottom(s, 2 * n, 0, n);
  band(s, 0, n, n);
  fan_top(s, 2 * n + 1, n, n);
  return s;
}

/// The surface of a halfspace of these scenes, rebuilt from its parameters (box, sphere, torus, finite cylinder;
/// every axis +z).
Solid rebuild(const Halfspace3& h) {
  const Primitive3& p = h.primitive;
  const Tessellation3& t = p.tessellation;
  REQUIRE(t.mode == Tessellation3::Mode::Segments);
  switch (h.kind) {
    case HalfspaceKind3::Box: return box_solid(p.min, p.max);
    case HalfspaceKind3::Sphere: return sphere_solid(p.center, p.radius, t.segments);
    case HalfspaceKind3::Torus:
      REQUIRE(p.axis == pt(0, 0, 1));
      return torus_solid(p.center, p.major_radius, p.minor_radius, t.segments, t.minor_segments ? t.minor_segments : t.segments);
    case HalfspaceKind3::Cylinder:
      REQUIRE((!p.infinite && p.point1.x == p.point2.x && p.point1.y == p.point2.y && p.point1.z < p.point2.z));
      return cylinder_solid(p.point1, p.point2, p.radius, t.segments);
    default: FAIL("no rebuild for this kind"); return {};
  }
}

/// The polygon a, b, c clipped to { x : n . x <= d } (Sutherland-Hodgman, exact).
std::vector<PointQ3> clip(const std::vector<PointQ3>& poly, const PointQ3& n, const Rational& d) {
  std::vector<PointQ3> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const PointQ3& a = poly[i];
    const PointQ3& b = poly[(i + 1) % poly.size()];
    const Rational fa = dot(n, a) - d, fb = dot(n, b) - d;
    if (fa <= 0) out.push_back(a);
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) {
      const Rational s = fa / (fa - fb);
      out.push_back({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.z + s * (b.z - a.z)});
    }
  }
  return out;
}

/// Volume of the solid cut to { n . x <= d }: signed tetrahedra of the clipped faces about a point of the plane.
Rational volume_in(const Solid& s, const PointQ3& n, const Rational& d) {
  // a point on the plane: along the largest normal coordinate
  PointQ3 o{0, 0, 0};
  if (n.x != 0) o.x = d / n.x;
  else if (n.y != 0) o.y = d / n.y;
  else o.z = d / n.z;
  Rational six;
  for (const auto& tri : s.t) {
    const std::vector<PointQ3> poly = clip({s.v[tri[0]], s.v[tri[1]], s.v[tri[2]]}, n, d);
    for (std::size_t i = 1; i + 1 < poly.size(); ++i)
      six += dot(sub(poly[0], o), cross(sub(poly[i], o), sub(poly[i + 1], o)));
  }
  return six / 6;
}

Rational volume(const Solid& s) {
  Rational six;
  for (const auto& tri : s.t) six += dot(s.v[tri[0]], cross(s.v[tri[1]], s.v[tri[2]]));
  return six / 6;
}

Measure area(const Solid& s) {
  Measure total;
  for (const auto& tri : s.t) {
    const PointQ3 c = cross(sub(s.v[tri[1]], s.v[tri[0]]), sub(s.v[tri[2]], s.v[tri[0]]));
    total += Measure::sqrt_of(dot(c, c)) * q(1, 2);
  }
  return total;
}

/// Area of a convex polygon in a plane z = const (shoelace).
Rational area_xy(const std::vector<PointQ3>& poly) {
  Rational twice;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const PointQ3& a = poly[i];
    const PointQ3& b = poly[(i + 1) % poly.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return twice / 2;
}

/// Area of the convex polygon cut by half-planes a x + b y <= c, given as (a, b, c).
Rational clipped_area(std::vector<PointQ3> poly, const std::vector<std::array<long, 3>>& halfplanes) {
  for (const auto& h : halfplanes) poly = clip(poly, pt(h[0], h[1], 0), Rational(h[2]));
  return poly.size() < 3 ? Rational(0) : area_xy(poly);
}

Rational box_volume(const Box3& b) { return (b.max.x - b.min.x) * (b.max.y - b.min.y) * (b.max.z - b.min.z); }

// ---------------------------------------------------------------------------------------------------------------
// Scenes and their expectations.

Scene3 load(const std::string& name) {
  return read_scene3_file((fs::path(HSX_SOURCE_DIR) / "data" / "scenes3d" / name).string());
}

/// A cell's side of the halfspace named `name`.
struct Sides {
  const Scene3& scene;
  const std::vector<char>& inside;
  bool operator()(const char* name) const {
    const int h = scene.find_halfspace(name);
    REQUIRE(h >= 0);
    return inside[static_cast<std::size_t>(h)] != 0;
  }
};
using CellTest = std::function<bool(const Sides&)>;

/// Cells with given sides: how many there are and, when known independently, their total volume.
struct Group {
  std::string what;
  CellTest test;
  int cells;
  std::optional<Rational> volume;
};

struct Expectation {
  std::string file;
  int cells, outer, patches, supports;  ///< patches, supports: -1 when not derived
  std::vector<Group> groups;
  CellTest shape;                        ///< the cells of the K = 1 beam search's shape (never outer ones)
  std::optional<Rational> shape_volume;  ///< when independent of the arrangement
  int shape_patches, shape_supports;     ///< patches / support groups on the shape's boundary
};

/// Volume inside halfspace h within the domain, independently: a plane cuts the domain box, a surface is rebuilt.
Rational independent_volume(const Scene3& scene, const Halfspace3& h) {
  const Rational box = box_volume(scene.domain);
  Rational in;
  if (h.kind == HalfspaceKind3::Plane) {
    in = volume_in(box_solid(scene.domain.min, scene.domain.max), h.normal, h.offset);
  } else {
    const Solid s = rebuild(h);
    CHECK(s.v == h.surface.vertices);   // the rebuild is the surface the scene arranged
    CHECK(s.t == h.surface.triangles);
    in = volume(s);
  }
  return h.complement ? box - in : in;
}

void check_scene(const Expectation& e) {
  INFO("scene " << e.file);
  const Scene3 scene = load(e.file);
  CHECK(!scene.description.empty());
  const Arranged3 a = arrange(scene);
  const Arrangement3& arr = a.arrangement;
  const Complex& cx = a.complex;
  std::string problems;
  for (const auto& p : check_complex(cx)) problems += p + "\n";
  CHECK(problems == "");
  CHECK(cx.cells.size() == static_cast<std::size_t>(e.cells));
  CHECK(cx.outer_cell_count() == e.outer);
  if (e.patches >= 0) CHECK(cx.patches.size() == static_cast<std::size_t>(e.patches));
  if (e.supports >= 0) CHECK(cx.supports.size() == static_cast<std::size_t>(e.supports));
  REQUIRE(arr.cells().size() == cx.cells.size());

  std::vector<Rational> vol;
  Rational total;
  for (const ArrCell3& c : arr.cells()) {
    REQUIRE(c.volume);
    CHECK(*c.volume > 0);
    vol.push_back(*c.volume);
    total += *c.volume;
  }
  CHECK(total == box_volume(scene.domain));
  // Every halfspace: the cells inside it fill its volume inside the domain; every surface: its patches its area.
  for (std::size_t h = 0; h < scene.halfspaces.size(); ++h) {
    INFO("halfspace " << scene.halfspaces[h].name);
    Rational in;
    for (std::size_t c = 0; c < arr.cells().size(); ++c)
      if (arr.cells()[c].inside[h]) in += vol[c];
    CHECK(in == independent_volume(scene, scene.halfspaces[h]));
    if (scene.halfspaces[h].kind == HalfspaceKind3::Plane) continue;
    Measure patches;
    for (const Patch& p : cx.patches)
      if (p.halfspace == static_cast<int>(h)) patches += p.measure;
    CHECK((patches - area(rebuild(scene.halfspaces[h]))).is_zero());
  }
  // The groups of cells by sides.
  int grouped = 0;
  for (const Group& g : e.groups) {
    INFO("group " << g.what);
    int count = 0;
    Rational sum;
    for (std::size_t c = 0; c < arr.cells().size(); ++c)
      if (g.test(Sides{scene, arr.cells()[c].inside})) ++count, sum += vol[c];
    CHECK(count == g.cells);
    grouped += count;
    if (g.volume) CHECK(sum == *g.volume);
  }
  CHECK(grouped == e.cells);  // the groups partition the cells

  // The BSH shape, K = 1 beam search.
  const bsh::Problem problem(cx);
  bsh::ExtractOptions options;
  options.method = bsh::Method::Beam;
  options.beam_width = 1;
  const bsh::ExtractResult r = bsh::extract(problem, options);
  CHECK(r.energy.missing_samples == 0);
  CHECK(r.sample_connected);
  CHECK(r.optimal);  // every label is forced by the samples: the first state is the optimum, proven
  Rational shape_volume;
  for (std::size_t c = 0; c < cx.cells.size(); ++c) {
    const bool expected = !cx.cells[c].outer && e.shape(Sides{scene, cx.cells[c].inside});
    INFO("cell " << c);
    CHECK((r.labelling[c] != 0) == expected);
    if (r.labelling[c]) shape_volume += vol[c];
  }
  if (e.shape_volume) CHECK(shape_volume == *e.shape_volume);
  int patches = 0;
  std::set<int> supports;
  for (const Patch& p : cx.patches)
    if (r.labelling[p.inside_cell] != r.labelling[p.outside_cell]) ++patches, supports.insert(p.support);
  CHECK(patches == e.shape_patches);
  CHECK(static_cast<int>(supports.size()) == e.shape_supports);
}

// ---------------------------------------------------------------------------------------------------------------
// The expectations, scene by scene, with the reasoning.

/// Fig. 15 (a). Each sphere (r = 3/10) is centred on the torus's core and wider than its tube (r = 1/5), so it cuts
/// the tube through: the torus minus the spheres is 4 arcs, each sphere meets the torus in one piece and keeps one
/// piece outside it (a ball with a tunnel), and the outside is connected: 1 + 4 + 4 + 4 = 13 cells, 1 outer.
/// Patches: the torus surface in 4 arcs outside the spheres and 4 bands inside them; each sphere's surface in an
/// annulus outside the torus and the two discs where the tube passes: 8 + 4 * 3 = 20, no coincidences. The union
/// (the samples sit on the 4 arcs and the 4 annuli) is bounded by those 8 patches.
Expectation torus_spheres() {
  Expectation e{"torus_spheres.json", 13, 1, 20, 20, {}, {}, std::nullopt, 8, 8};
  auto any_sphere = [](const Sides& s) { return s("S1") || s("S2") || s("S3") || s("S4"); };
  e.groups.push_back({"torus outside the spheres", [=](const Sides& s) { return s("T") && !any_sphere(s); }, 4, {}});
  for (const char* name : {"S1", "S2", "S3", "S4"}) {
    const std::string n = name;
    e.groups.push_back({n + " and the torus", [=](const Sides& s) { return s(n.c_str()) && s("T"); }, 1, {}});
    e.groups.push_back({n + " outside the torus", [=](const Sides& s) { return s(n.c_str()) && !s("T"); }, 1, {}});
  }
  e.groups.push_back({"outside", [=](const Sides& s) { return !s("T") && !any_sphere(s); }, 1, {}});
  e.shape = [=](const Sides& s) { return s("T") || any_sphere(s); };
  return e;
}

/// Fig. 16 (spheres with a flipped torus). In a half-plane through the z axis the torus is a disc of radius 6/5 at
/// distance 13/10 from the axis (so it misses the axis by 1/10) and each sphere a half-disc of radius 1 on the axis
/// at height +-3/2; each sphere disc crosses the torus disc (centre distance sqrt(3.94) < 2.2). Cells (sides of
/// S1, S2 and the torus solid): outside everything: the outer region and the pocket around the origin sealed by the
/// two spheres and the torus's inner wall (2); each sphere minus the torus (2, touching the axis); each sphere and
/// the torus (2, rings); the torus minus the spheres (1): 7 cells, 1 outer. Patches: the torus circle minus the two
/// lenses is an inner arc (the pocket's wall) and an outer arc, plus its arcs inside either sphere: 4; each sphere's
/// circle: the arc in the torus and two caps outside it (towards the pocket, and away): 3 + 3. Total 10. The
/// samples (outer caps, both bands, the pocket's wall, each with the flipped torus's inside outward) force every
/// cell: the shape is S1 \ torus, S2 \ torus and the pocket, bounded by those 5 patches.
Expectation spheres_flipped_torus() {
  Expectation e{"spheres_flipped_torus.json", 7, 1, 10, 10, {}, {}, std::nullopt, 5, 5};
  // "T" is the flipped torus: inside = outside the torus solid
  e.groups = {
      {"outer and pocket", [](const Sides& s) { return s("T") && !s("S1") && !s("S2"); }, 2, {}},
      {"S1 minus torus", [](const Sides& s) { return s("T") && s("S1"); }, 1, {}},
      {"S2 minus torus", [](const Sides& s) { return s("T") && s("S2"); }, 1, {}},
      {"S1 and torus", [](const Sides& s) { return !s("T") && s("S1"); }, 1, {}},
      {"S2 and torus", [](const Sides& s) { return !s("T") && s("S2"); }, 1, {}},
      {"torus minus spheres", [](const Sides& s) { return !s("T") && !s("S1") && !s("S2"); }, 1, {}},
  };
  e.shape = [](const Sides& s) { return s("T"); };  // outer cell excluded by check_scene
  return e;
}

/// Fig. 16 (four tori), z = 0 for every core. Adjacent core circles (centres 6/5 sqrt 2 apart, radius 1) cross
/// twice at 64 degrees; between the crossings they are up to 0.303 apart, more than 1/25 + 1/12, so the two
/// crossings of a pair are separate lenses; opposite tori are 0.3 (thin) and 0.23 (thick) apart. A thin tube is cut
/// through at each of its 4 crossings (the thick tube's section covers its disc); a thick one is only pierced. Cells:
/// the thin tori minus the others: 4 + 4 arcs; the thick ones: 1 + 1; the 8 lenses; the outside: 19, 1 outer.
/// Patches: a thin torus's surface in 4 arcs outside and 4 bands inside the thick tubes (8 each); a thick torus's
/// surface is one piece outside with 8 discs where the thin tubes enter and leave (9 each): 34. The union (samples on
/// every thin arc and on each thick torus) is bounded by the 4 + 4 + 1 + 1 outside pieces.
Expectation four_tori() {
  Expectation e{"four_tori.json", 19, 1, 34, 34, {}, {}, std::nullopt, 10, 10};
  const char* names[4] = {"T1", "T2", "T3", "T4"};
  const int alone[4] = {4, 1, 4, 1};
  for (int i = 0; i < 4; ++i) {
    const std::string a = names[i], b = names[(i + 1) % 4];
    e.groups.push_back({a + " alone", [=](const Sides& s) {
                          int n = 0;
                          for (const char* m : {"T1", "T2", "T3", "T4"}) n += s(m);
                          return n == 1 && s(a.c_str());
                        }, alone[i], {}});
    e.groups.push_back({a + " and " + b, [=](const Sides& s) { return s(a.c_str()) && s(b.c_str()); }, 2, {}});
  }
  e.groups.push_back({"outside", [](const Sides& s) { return !s("T1") && !s("T2") && !s("T3") && !s("T4"); }, 1, {}});
  e.shape = [](const Sides& s) { return s("T1") || s("T2") || s("T3") || s("T4"); };
  return e;
}

/// The CAD part (2.5D apart from the rings): Top and Bottom split the domain into layers L0 (z < 0), L1 and L2
/// (z > 2); the cylinder fills L1 over the 16-gon D; the slab is the strip |y| <= 1 from z = -1 to 3; the notch box
/// (its halfspace is the complement) is |x| <= 1/2, |y| <= 5/2 from z = 1 to 3; each ring is cut in halves by Top
/// along its equator (vertices and edges in the plane). Cells by layer, with areas from D clipped exactly:
/// L0: slab part, the rest (2). L2: slab and notch, slab minus notch (2: x < -1/2, x > 1/2), notch minus slab (2),
/// the rest, two upper ring halves (8). L1: cylinder and slab minus notch (1, the part), cylinder and slab and notch
/// (1), cylinder caps |y| > 1 minus notch (2), caps in the notch (2), slab ends outside D (2), notch outside D and
/// slab (2), the rest, two lower ring halves (13). Total 23; outer: the rest of each layer (3).
/// The shape's samples sit on every face of the part (cylinder and slab minus notch, in L1) and on both halves of
/// each ring; its boundary: the bottom face (Bottom and Cyl's cap coincide: 1 support, 2 patches), the top face
/// either side of the notch (2 supports of Top and Cyl, 4 patches), the notch's floor and walls (1: the box's edges
/// join them), the slab's faces y = +-1 (2), the cylinder's wall either end (2), the ring halves (4): 12 supports,
/// 15 patches. Its volume: the part's prism minus the notch's bite, plus both rings.
/// All patch regions (a region carries one patch per halfspace on it; a box's edges do not split its surface):
/// Top: D cut by the slab's lines y = +-1 and the notch's x = +-1/2 into 9 (each with Cyl's cap), the slab's and the
/// notch's rectangles outside D (2 + 2), each ring's annulus and hole (4), the rest (1): 18 regions, 27 patches.
/// Bottom: D cut by y = +-1 into 3 (with Cyl's cap), the slab's rectangle outside D (2), the rest (1): 6, 9.
/// Cyl's wall: 4 pieces between the slab's faces, the two at |y| > 1 each cut into a U and the notch's window: 6.
/// Slab: its bottom face with the band z < 0 (1); in 0 < z < 2 the parts outside D either end (2) and on each of
/// y = +-1 a U around the notch's window and the window (4); in z > 2 with the top face: the parts either side of
/// the notch (2), the windows on y = +-1 (2), and the top's square shared with the notch's top (1, 2 patches):
/// 12 regions, 13 patches. Notch (floor and walls joined): below Top, the channel inside the slab, the parts between
/// the slab and the wall, the parts beyond the wall (with the end faces) (1 + 2 + 2); above Top, the parts beyond
/// the slab with the top face (2) and its walls x = +-1/2 inside the slab (2): 9 regions (+ the shared square).
/// Rings: 2 halves each (4). Supports: 18 + 6 + 6 + 12 + 9 + 4 = 55; patches: 27 + 9 + 6 + 13 + 9 + 4 = 68.
Expectation cad_part(const Scene3& scene) {
  // D: the cylinder's bottom ring in the plane z = 0.
  const Halfspace3& cyl = scene.halfspaces[static_cast<std::size_t>(scene.find_halfspace("Cyl"))];
  const Solid c = rebuild(cyl);
  std::vector<PointQ3> disc(c.v.begin(), c.v.begin() + cyl.primitive.tessellation.segments);
  for (PointQ3& p : disc) p.z = 0;
  const Rational two(2);
  const Rational a_d = clipped_area(disc, {});
  const Rational a_ds = clipped_area(disc, {{0, 1, 1}, {0, -1, 1}});                      // D, |y| <= 1
  const Rational a_dn = clipped_area(disc, {{2, 0, 1}, {-2, 0, 1}});                      // D, |x| <= 1/2
  const Rational a_dsn = clipped_area(disc, {{0, 1, 1}, {0, -1, 1}, {2, 0, 1}, {-2, 0, 1}});
  const Rational strip = 12, notch = 5;                                                   // 6 x 2, 1 x 5
  auto ring = [&](const char* name, bool upper) {
    const Halfspace3& h = scene.halfspaces[static_cast<std::size_t>(scene.find_halfspace(name))];
    const Solid s = rebuild(h);
    const Rational below = volume_in(s, pt(0, 0, 1), two);
    return upper ? volume(s) - below : below;
  };
  const Rational rings_low = ring("Ring1", false) + ring("Ring2", false);
  const Rational rings_up = ring("Ring1", true) + ring("Ring2", true);
  const Rational layer = 8 * 10 * 2;  // every layer of the domain [-4, 4] x [-5, 5] x [-2, 4] is 2 high

  auto L0 = [](const Sides& s) { return s("Top") && !s("Bottom"); };
  auto L1 = [](const Sides& s) { return s("Top") && s("Bottom"); };
  auto L2 = [](const Sides& s) { return !s("Top") && s("Bottom"); };
  auto ring_cell = [](const Sides& s) { return s("Ring1") || s("Ring2"); };
  auto notch_box = [](const Sides& s) { return !s("Notch"); };
  Expectation e{"cad_part.json", 23, 3, 68, 55, {}, {}, {}, 15, 12};
  const Rational part = two * a_ds - a_dsn;
  const Rational caps = two * (a_d - a_ds) - (a_dn - a_dsn), caps_notch = a_dn - a_dsn;
  const Rational slab_ends = two * (strip - a_ds), notch_out = notch - a_dn;
  e.groups = {
      {"L0 slab", [=](const Sides& s) { return L0(s) && s("Slab"); }, 1, Rational(12)},
      {"L0 rest", [=](const Sides& s) { return L0(s) && !s("Slab"); }, 1, layer - 12},
      {"L1 part", [=](const Sides& s) { return L1(s) && s("Cyl") && s("Slab") && !notch_box(s); }, 1, part},
      {"L1 part in the notch", [=](const Sides& s) { return L1(s) && s("Cyl") && s("Slab") && notch_box(s); }, 1, a_dsn},
      {"L1 caps", [=](const Sides& s) { return L1(s) && s("Cyl") && !s("Slab") && !notch_box(s); }, 2, caps},
      {"L1 caps in the notch", [=](const Sides& s) { return L1(s) && s("Cyl") && !s("Slab") && notch_box(s); }, 2, caps_notch},
      {"L1 slab ends", [=](const Sides& s) { return L1(s) && !s("Cyl") && s("Slab"); }, 2, slab_ends},
      {"L1 notch outside", [=](const Sides& s) { return L1(s) && !s("Cyl") && !s("Slab") && notch_box(s); }, 2, notch_out},
      {"L1 rings", [=](const Sides& s) { return L1(s) && ring_cell(s); }, 2, rings_low},
      {"L1 rest", [=](const Sides& s) { return L1(s) && !s("Cyl") && !s("Slab") && !notch_box(s) && !ring_cell(s); }, 1,
       layer - (part + a_dsn + caps + caps_notch + slab_ends + notch_out + rings_low)},
      {"L2 slab and notch", [=](const Sides& s) { return L2(s) && s("Slab") && notch_box(s); }, 1, Rational(2)},
      {"L2 slab", [=](const Sides& s) { return L2(s) && s("Slab") && !notch_box(s); }, 2, Rational(10)},
      {"L2 notch", [=](const Sides& s) { return L2(s) && !s("Slab") && notch_box(s); }, 2, Rational(3)},
      {"L2 rings", [=](const Sides& s) { return L2(s) && ring_cell(s); }, 2, rings_up},
      {"L2 rest", [=](const Sides& s) { return L2(s) && !s("Slab") && !notch_box(s) && !ring_cell(s); }, 1,
       layer - 15 - rings_up},
  };
  e.shape = [=](const Sides& s) { return (L1(s) && s("Cyl") && s("Slab") && !notch_box(s)) || ring_cell(s); };
  e.shape_volume = part + rings_low + rings_up;
  return e;
}

/// Coplanar faces. P (z >= 2) splits the domain; below it A, B and the rest (connected), above it one cell: 4
/// cells, 2 outer (the rest below, above). Q lies on the domain's face: no patch, every cell inside. Patch regions
/// (a box's edges do not split its surface): A alone, B alone, P alone (the plane minus both tops), A with B (the
/// shared square x = 2, 1 <= y <= 2), A with P, B with P: 6 supports, 9 patches. The union A + B: volume 16, its
/// boundary A alone, B alone and the two tops (4 supports, 6 patches).
Expectation coplanar_faces() {
  Expectation e{"coplanar_faces.json", 4, 2, 9, 6, {}, {}, Rational(16), 6, 4};
  e.groups = {
      {"A", [](const Sides& s) { return s("A") && s("Q"); }, 1, Rational(8)},
      {"B", [](const Sides& s) { return s("B") && s("Q"); }, 1, Rational(8)},
      {"below", [](const Sides& s) { return !s("A") && !s("B") && !s("P") && s("Q"); }, 1, Rational(6 * 5 * 3 - 16)},
      {"above", [](const Sides& s) { return s("P") && s("Q"); }, 1, Rational(6 * 5 * 1)},
  };
  e.shape = [](const Sides& s) { return s("A") || s("B"); };
  return e;
}

/// Planes tangent to the sphere's tessellation. Touch and Equator split the domain into three layers; Face stays
/// below z = -0.98 inside the domain, so it splits only the bottom layer, and the tessellated (convex) sphere lies
/// on its inside, touching it along one triangle. Cells: the top layer (1); the middle layer: the upper hemisphere
/// (touching Touch at its pole only) and the rest (2); the bottom layer: the lower hemisphere, the rest on the
/// sphere's side of Face, and beyond Face (3): 6 cells, 4 outer. Patches: the sphere's upper half, its lower half
/// minus the triangle, the triangle (with Face's coincident patch: same orientation), Face's rest, the equator
/// disc and the rest of Equator, Touch (one piece: the pole is only a vertex of it): 8 patches, 7 supports. The
/// ball: volume of the rebuilt sphere, 3 supports (4 patches).
Expectation tangent_planes(const Scene3& scene) {
  const Halfspace3& s = scene.halfspaces[static_cast<std::size_t>(scene.find_halfspace("S"))];
  const Halfspace3& face = scene.halfspaces[static_cast<std::size_t>(scene.find_halfspace("Face"))];
  const Solid ball = rebuild(s);
  const Rational low = volume_in(ball, pt(0, 0, 1), Rational(0));
  const Rational up = volume(ball) - low;
  const Rational bottom = 6 * 6 * 3;
  const Rational bottom_face = volume_in(box_solid(pt(-3, -3, -3), pt(3, 3, 0)), face.normal, face.offset);
  Expectation e{"tangent_planes.json", 6, 4, 8, 7, {}, {}, volume(ball), 4, 3};
  e.groups = {
      {"top layer", [](const Sides& x) { return !x("Touch"); }, 1, Rational(36)},
      {"upper hemisphere", [](const Sides& x) { return x("S") && !x("Equator"); }, 1, up},
      {"middle rest", [](const Sides& x) { return x("Touch") && !x("Equator") && !x("S"); }, 1, Rational(72) - up},
      {"lower hemisphere", [](const Sides& x) { return x("S") && x("Equator"); }, 1, low},
      {"bottom, sphere side", [](const Sides& x) { return x("Equator") && x("Face") && !x("S"); }, 1, bottom_face - low},
      {"bottom, beyond Face", [](const Sides& x) { return x("Equator") && !x("Face"); }, 1, bottom - bottom_face},
  };
  e.shape = [](const Sides& x) { return x("S"); };
  return e;
}

/// Three nested shells (the cavity's halfspace is the outside of its sphere): outside the box, the box minus the
/// cavity, the cavity's gap, the core: 4 cells, 1 outer, 3 patches (one per surface, nothing crosses them). The
/// samples (box outward, cavity wall towards the box's material, core outward) give box minus cavity plus core.
Expectation nested_cavity(const Scene3& scene) {
  const Rational cavity = volume(rebuild(scene.halfspaces[1])), core = volume(rebuild(scene.halfspaces[2]));
  Expectation e{"nested_cavity.json", 4, 1, 3, 3, {}, {}, Rational(216) - cavity + core, 3, 3};
  e.groups = {
      {"outside", [](const Sides& s) { return !s("Box"); }, 1, Rational(512 - 216)},
      {"box material", [](const Sides& s) { return s("Box") && s("Cavity"); }, 1, Rational(216) - cavity},
      {"gap", [](const Sides& s) { return s("Box") && !s("Cavity") && !s("Core"); }, 1, cavity - core},
      {"core", [](const Sides& s) { return s("Core"); }, 1, core},
  };
  e.shape = [](const Sides& s) { return (s("Box") && s("Cavity")) || s("Core"); };
  return e;
}

// ---------------------------------------------------------------------------------------------------------------
// Invariance: an isometry x -> M x + t with M diagonal (+-1) and a permutation of the halfspaces.

Scene3 moved(const Scene3& s, const PointQ3& t, bool mirror_x, const std::vector<int>& order) {
  auto f = [&](const PointQ3& p) { return PointQ3{(mirror_x ? -p.x : p.x) + t.x, p.y + t.y, p.z + t.z}; };
  Scene3 out;
  out.description = s.description;
  out.domain_given = true;
  const PointQ3 a = f(s.domain.min), b = f(s.domain.max);
  out.domain = {{std::min(a.x, b.x), a.y, a.z}, {std::max(a.x, b.x), b.y, b.z}};
  std::vector<int> new_index(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    Halfspace3 h = s.halfspaces[static_cast<std::size_t>(order[i])];
    new_index[static_cast<std::size_t>(order[i])] = static_cast<int>(i);
    if (h.kind == HalfspaceKind3::Plane) {
      if (mirror_x) h.normal.x = -h.normal.x;
      h.offset += dot(h.normal, t);  // n . (x - t) <= d
    }
    for (PointQ3& p : h.surface.vertices) p = f(p);
    if (mirror_x)
      for (auto& tri : h.surface.triangles) std::swap(tri[1], tri[2]);  // keep the surface outward
    out.halfspaces.push_back(std::move(h));
  }
  for (Sample3 sample : s.samples) {
    sample.halfspace = new_index[static_cast<std::size_t>(sample.halfspace)];
    sample.given = f(sample.given);
    sample.location = f(sample.location);
    out.samples.push_back(sample);
  }
  return out;
}

/// The cells as sorted (sides in the original halfspace order, volume, outer).
std::vector<std::tuple<std::vector<char>, Rational, bool>> cells_of(const Arrangement3& arr, const std::vector<int>& order) {
  std::vector<std::tuple<std::vector<char>, Rational, bool>> out;
  for (const ArrCell3& c : arr.cells()) {
    std::vector<char> sides(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) sides[static_cast<std::size_t>(order[i])] = c.inside[i];
    out.emplace_back(sides, *c.volume, c.outer);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("scenes3d: Fig. 15 torus with spheres", "[regression][scenes3d]") { check_scene(torus_spheres()); }
TEST_CASE("scenes3d: Fig. 16 spheres with a flipped torus", "[regression][scenes3d]") {
  check_scene(spheres_flipped_torus());
}
TEST_CASE("scenes3d: Fig. 16 four tori", "[regression][scenes3d]") { check_scene(four_tori()); }
TEST_CASE("scenes3d: CAD part with planes, a cylinder, boxes and tori", "[regression][scenes3d]") {
  check_scene(cad_part(load("cad_part.json")));
}
TEST_CASE("scenes3d: coplanar faces", "[regression][scenes3d]") { check_scene(coplanar_faces()); }
TEST_CASE("scenes3d: planes tangent to a sphere's tessellation", "[regression][scenes3d]") {
  check_scene(tangent_planes(load("tangent_planes.json")));
}
TEST_CASE("scenes3d: nested shells and a cavity", "[regression][scenes3d]") {
  check_scene(nested_cavity(load("nested_cavity.json")));
}

TEST_CASE("scenes3d: a plane sharing a face with the sphere makes an unsampled component of its own", "[regression][scenes3d]") {
  // Without the sample on Face, the triangle Face shares with S (same orientation) is on the ball's boundary as a
  // component of Face with no sample (proofs/bsh.md, entry 1): the ball is not sample-connected, the lower
  // hemisphere cannot be in any sample-connected shape, and the best shape misses both sphere samples.
  Scene3 scene = load("tangent_planes.json");
  const int face = scene.find_halfspace("Face");
  scene.samples.erase(std::remove_if(scene.samples.begin(), scene.samples.end(),
                                     [&](const Sample3& s) { return s.halfspace == face; }),
                      scene.samples.end());
  const Arranged3 a = arrange(scene);
  const bsh::Problem problem(a.complex);
  bsh::Labelling ball(a.complex.cells.size(), 0);
  for (std::size_t c = 0; c < ball.size(); ++c) ball[c] = a.complex.cells[c].inside[0];
  CHECK_FALSE(bsh::sample_connectivity(problem, ball).sample_connected());
  bsh::ExtractOptions options;
  options.method = bsh::Method::Beam;
  const bsh::ExtractResult r = bsh::extract(problem, options);
  CHECK(r.energy.missing_samples == 2);
}

TEST_CASE("scenes3d: translated, mirrored and permuted scenes give the same cells", "[regression][scenes3d]") {
  for (const char* name : {"torus_spheres.json", "cad_part.json", "coplanar_faces.json", "tangent_planes.json",
                           "nested_cavity.json"}) {
    INFO("scene " << name);
    const Scene3 scene = load(name);
    const Arranged3 a = arrange(scene);
    const int n = static_cast<int>(scene.halfspaces.size());
    std::vector<int> identity(static_cast<std::size_t>(n)), reversed;
    for (int i = 0; i < n; ++i) identity[static_cast<std::size_t>(i)] = i;
    reversed.assign(identity.rbegin(), identity.rend());
    const auto reference = cells_of(a.arrangement, identity);
    struct Variant {
      const char* what;
      PointQ3 t;
      bool mirror;
      std::vector<int> order;
    };
    const std::vector<Variant> variants = {
        {"translated by (1/3, -2/7, 5/11)", pt(q(1, 3), q(-2, 7), q(5, 11)), false, identity},
        {"mirrored in x = 0", pt(0, 0, 0), true, identity},
        {"halfspaces reversed", pt(0, 0, 0), false, reversed},
    };
    for (const Variant& v : variants) {
      INFO(v.what);
      const Arranged3 b = arrange(moved(scene, v.t, v.mirror, v.order));
      CHECK(b.complex.patches.size() == a.complex.patches.size());
      CHECK(b.complex.supports.size() == a.complex.supports.size());
      CHECK(b.complex.junctions.size() == a.complex.junctions.size());
      CHECK(b.complex.outer_cell_count() == a.complex.outer_cell_count());
      CHECK(cells_of(b.arrangement, v.order) == reference);
      // every halfspace's patches have the same total area, exactly
      std::vector<Measure> x(static_cast<std::size_t>(n)), y(static_cast<std::size_t>(n));
      for (const Patch& p : a.complex.patches) x[static_cast<std::size_t>(p.halfspace)] += p.measure;
      for (const Patch& p : b.complex.patches)
        y[static_cast<std::size_t>(v.order[static_cast<std::size_t>(p.halfspace)])] += p.measure;
      for (int h = 0; h < n; ++h) CHECK((x[static_cast<std::size_t>(h)] - y[static_cast<std::size_t>(h)]).is_zero());
    }
  }
}
