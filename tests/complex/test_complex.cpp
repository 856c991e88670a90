// Tests of complex/ (the complex built from a 2D arrangement): structural invariants, invariance under
// permutation of the halfspaces and under integer translation, exact patch lengths, on random scenes with forced
// degeneracies (tests/support/random_scenes.hpp), plus hand-computed cases.
#include <hsx/complex/complex.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/geometry/arrangement2.hpp>
#include <hsx/geometry/scene.hpp>
#include <hsx/kernel/measure.hpp>
#include "support/random_scenes.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace hsx;
using namespace hsx::test;

namespace {

SceneGenOptions options_with_samples() {
  SceneGenOptions o;
  o.max_halfspaces = 6;
  o.max_degeneracies = 2;
  o.samples = true;
  return o;
}

Box2 box(long x0, long y0, long x1, long y1) { return Box2{pt(x0, y0), pt(x1, y1)}; }

/// 2*pi*r (a full-circle angle times r, keyed "pi").
Measure circumference(const Halfspace2& h) {
  const PointQ2 p{h.center.x + h.radius, h.center.y};
  return Measure::arc_angle(h.center, h.radius, p, p, h.radius);
}

/// |a - b| <= tolerance * (1 + |b|), certified at 256 bits.
bool close(const Measure& a, const Measure& b, double tolerance) {
  const Interval d = a.enclose(256) - b.enclose(256);
  const double tol = tolerance * (1 + std::fabs(b.to_double()));
  return d.lo_double() >= -tol && d.hi_double() <= tol;
}

bool has_disk(const Scene2& s) {
  return std::any_of(s.halfspaces.begin(), s.halfspaces.end(),
                     [](const Halfspace2& h) { return h.kind == HalfspaceKind2::Disk; });
}

// ---- canonical signatures: cells and patches named by what they are, not by their index ----

struct Signed {
  std::string key;
  Measure measure;
};

/// Sign vector in the ORIGINAL halfspace order (original_of[k]: original index of halfspace k) and outer flag.
std::string cell_key(const Complex& c, int cell, const std::vector<int>& original_of) {
  std::string s(c.halfspace_names.size(), '?');
  for (std::size_t k = 0; k < c.halfspace_names.size(); ++k)
    s[original_of[k]] = c.cells.at(cell).inside[k] ? '1' : '0';
  return s + (c.cells.at(cell).outer ? " outer" : " inner");
}

std::string patch_key(const Complex& c, int p, const std::vector<int>& original_of) {
  const Patch& pa = c.patches[p];
  std::set<std::string> group;
  for (int q : c.supports.at(pa.support)) group.insert(c.halfspace_names[c.patches[q].halfspace]);
  std::string g;
  for (const auto& name : group) g += name + ",";
  return c.halfspace_names[pa.halfspace] + " in=" + cell_key(c, pa.inside_cell, original_of) +
         " out=" + cell_key(c, pa.outside_cell, original_of) + " support={" + g + "}";
}

std::vector<Signed> cell_signatures(const Complex& c, const std::vector<int>& original_of) {
  std::vector<Signed> out;
  for (int k = 0; k < static_cast<int>(c.cells.size()); ++k) out.push_back({cell_key(c, k, original_of), c.cells[k].measure});
  return out;
}

std::vector<Signed> patch_signatures(const Complex& c, const std::vector<int>& original_of) {
  std::vector<Signed> out;
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p)
    out.push_back({patch_key(c, p, original_of), c.patches[p].measure});
  return out;
}

/// Matches two multisets of signatures: equal keys and `same` measures. Returns "" or what did not match.
std::string unmatched(std::vector<Signed> a, std::vector<Signed> b,
                      const std::function<bool(const Measure&, const Measure&)>& same) {
  if (a.size() != b.size())
    return "sizes differ: " + std::to_string(a.size()) + " vs " + std::to_string(b.size());
  std::vector<char> used(b.size(), 0);
  for (const Signed& x : a) {
    bool found = false;
    for (std::size_t j = 0; j < b.size() && !found; ++j)
      if (!used[j] && b[j].key == x.key && same(x.measure, b[j].measure)) found = used[j] = 1;
    if (!found) return "no match for " + x.key + " (measure " + x.measure.decimal_string(20) + ")";
  }
  return "";
}

std::vector<int> identity(std::size_t n) {
  std::vector<int> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = static_cast<int>(k);
  return v;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------------
// Properties: checks of one scene (the permutation and the translation are drawn inside), run on random scenes

namespace {

/// check_complex is empty; patches separate cells that differ exactly in their support group; cells agree with
/// direct evaluation; every interior edge is in a patch; samples sit on their patch.
void check_structure(const Scene2& scene, const Arranged2& a) {
  const Complex& c = a.complex;
  const Arrangement2& arr = a.arrangement;
  const auto problems = check_complex(c);
  for (const auto& p : problems) RC_LOG() << p << "\n";
  RC_ASSERT(problems.empty());
  const int n = c.halfspace_count();
  RC_ASSERT(n == static_cast<int>(scene.halfspaces.size()));
  RC_ASSERT(c.cells.size() == arr.faces().size());
  // Cells: witness strictly inside, sides by direct evaluation.
  for (const Cell& cell : c.cells) {
    RC_ASSERT(cell.witness.get().size() == 2u);
    const PointQ2 w{cell.witness.get()[0], cell.witness.get()[1]};
    for (int i = 0; i < n; ++i) {
      const int side = scene.halfspaces[i].side(w);
      RC_ASSERT(side != 0);
      RC_ASSERT(static_cast<int>(cell.inside[i]) == (side > 0 ? 1 : 0));
    }
  }
  std::set<int> covered_edges;
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) {
    const Patch& pa = c.patches[p];
    const Cell& in = c.cells.at(pa.inside_cell);
    const Cell& out = c.cells.at(pa.outside_cell);
    RC_ASSERT(in.inside[pa.halfspace] == 1);
    RC_ASSERT(out.inside[pa.halfspace] == 0);
    std::vector<int> group;
    for (int q : c.supports.at(pa.support)) group.push_back(c.patches[q].halfspace);
    std::sort(group.begin(), group.end());
    RC_ASSERT(std::adjacent_find(group.begin(), group.end()) == group.end());
    for (int i = 0; i < n; ++i) {
      const bool in_group = std::binary_search(group.begin(), group.end(), i);
      RC_ASSERT((in.inside[i] != out.inside[i]) == in_group);
    }
    // The pieces are interior edges carrying exactly the group's halfspaces, between the patch's two cells.
    RC_ASSERT(!pa.pieces.empty());
    for (int e : pa.pieces) {
      const ArrEdge2& edge = arr.edges().at(e);
      RC_ASSERT(!edge.on_box);
      RC_ASSERT(edge.halfspaces == group);
      RC_ASSERT(std::minmax(edge.left_face, edge.right_face) == std::minmax(pa.inside_cell, pa.outside_cell));
      covered_edges.insert(e);
    }
    RC_ASSERT(pa.junctions.size() == 0u || pa.junctions.size() == 2u);
    RC_ASSERT(pa.measure.get().sign() == std::optional<int>(1));
  }
  // Every interior edge is in some patch.
  for (int e = 0; e < static_cast<int>(arr.edges().size()); ++e)
    RC_ASSERT(arr.edges()[e].on_box == (covered_edges.count(e) == 0));
  // Samples: on a patch of their halfspace whose pieces hold the sample's edge.
  RC_ASSERT(c.samples.size() == scene.samples.size());
  for (std::size_t s = 0; s < scene.samples.size(); ++s) {
    const Patch& pa = c.patches.at(c.samples[s].patch);
    RC_ASSERT(pa.halfspace == scene.samples[s].halfspace);
    const int e = arr.sample_edges().at(s);
    RC_ASSERT(std::find(pa.pieces.begin(), pa.pieces.end(), e) != pa.pieces.end());
  }
}

/// Same cells, patches and sample sites up to renaming, measures exactly equal.
void check_permutation(const Scene2& scene) {
  const std::size_t n = scene.halfspaces.size();
  std::vector<int> order = identity(n);  // Fisher-Yates with generated draws
  for (std::size_t k = n; k > 1; --k) std::swap(order[k - 1], order[*rc::gen::resize(rc::kNominalSize, rc::gen::inRange<std::size_t>(0, k))]);
  const Scene2 other = permuted(scene, order);
  const Arranged2 a = arrange(scene), b = arrange(other);
  RC_ASSERT(a.arrangement.vertices().size() == b.arrangement.vertices().size());
  RC_ASSERT(a.arrangement.edges().size() == b.arrangement.edges().size());
  RC_ASSERT(a.complex.junctions.size() == b.complex.junctions.size());
  auto equal = [](const Measure& x, const Measure& y) { return compare(x, y) == Order::Equal; };
  const auto id = identity(n);
  const std::string cells = unmatched(cell_signatures(a.complex, id), cell_signatures(b.complex, order), equal);
  RC_ASSERT(cells == "");
  const std::string patches =
      unmatched(patch_signatures(a.complex, id), patch_signatures(b.complex, order), equal);
  RC_ASSERT(patches == "");
  for (std::size_t s = 0; s < scene.samples.size(); ++s) {
    const int pa = a.complex.samples[s].patch, pb = b.complex.samples[s].patch;
    RC_ASSERT(patch_key(a.complex, pa, id) == patch_key(b.complex, pb, order));
    RC_ASSERT(equal(a.complex.patches[pa].measure, b.complex.patches[pb].measure));
  }
}

/// Same counts and signatures; measures Equal without disks, never separated (and equal to 25 digits) with disks.
void check_translation(const Scene2& scene) {
  const int dx = *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(-5, 6));
  const int dy = *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(-5, 6));
  const Scene2 other = translated(scene, pt(dx, dy));
  const Arranged2 a = arrange(scene), b = arrange(other);
  RC_ASSERT(a.arrangement.vertices().size() == b.arrangement.vertices().size());
  RC_ASSERT(a.arrangement.edges().size() == b.arrangement.edges().size());
  RC_ASSERT(a.complex.cells.size() == b.complex.cells.size());
  RC_ASSERT(a.complex.outer_cell_count() == b.complex.outer_cell_count());
  RC_ASSERT(a.complex.patches.size() == b.complex.patches.size());
  RC_ASSERT(a.complex.junctions.size() == b.complex.junctions.size());
  const bool disks = has_disk(scene);
  auto same = [disks](const Measure& x, const Measure& y) {
    if (!disks) return compare(x, y) == Order::Equal;
    // Arc terms are keyed by position, so translated arcs cannot cancel: Tie is expected. 512 bits are plenty to
    // separate measures that really differ, and keep the many Ties cheap.
    CompareOptions options;
    options.max_bits = 512;
    const Order o = compare(x, y, options);
    return o != Order::Less && o != Order::Greater && close(x, y, 1e-25);
  };
  const auto id = identity(scene.halfspaces.size());
  RC_ASSERT(unmatched(cell_signatures(a.complex, id), cell_signatures(b.complex, id), same) == "");
  RC_ASSERT(unmatched(patch_signatures(a.complex, id), patch_signatures(b.complex, id), same) == "");
  for (std::size_t s = 0; s < scene.samples.size(); ++s) {
    const int pa = a.complex.samples[s].patch, pb = b.complex.samples[s].patch;
    RC_ASSERT(patch_key(a.complex, pa, id) == patch_key(b.complex, pb, id));
  }
}

/// Polygon patches add up to the perimeter exactly; disk patches enclose 2 pi r.
void check_lengths(const Scene2& scene, const Arranged2& a) {
  const Complex& c = a.complex;
  for (int i = 0; i < static_cast<int>(scene.halfspaces.size()); ++i) {
    const Halfspace2& h = scene.halfspaces[i];
    Measure sum;
    for (const Patch& p : c.patches)
      if (p.halfspace == i) sum += p.measure;
    if (h.kind == HalfspaceKind2::Polygon) {
      Measure perimeter;
      for (std::size_t k = 0; k < h.vertices.size(); ++k)
        perimeter += Measure::distance(h.vertices[k], h.vertices[(k + 1) % h.vertices.size()]);
      RC_LOG() << h.name << ": patches " << sum.decimal_string(30) << " = " << sum.exact_string().value_or("?")
               << ", perimeter " << perimeter.exact_string().value_or("?") << ", compare "
               << to_string(compare(sum, perimeter)) << "\n";
      RC_ASSERT(compare(sum, perimeter) == Order::Equal);
    } else if (h.kind == HalfspaceKind2::Disk) {
      const Order o = compare(sum, circumference(h));
      RC_ASSERT(o != Order::Less);
      RC_ASSERT(o != Order::Greater);
      RC_ASSERT(close(sum, circumference(h), 1e-30));
    }
  }
}

}  // namespace

TEST_CASE("complex: structural invariants on random scenes", "[complex][property]") {
  rc::prop("check_complex is empty; patches separate cells that differ exactly in their support group", [] {
    const Scene2 scene = *gen_scene(options_with_samples());
    check_structure(scene, arrange(scene));
  });
}

TEST_CASE("complex: invariant under permutation of the halfspaces", "[complex][property]") {
  rc::prop("same cells, patches and sample sites up to renaming, measures exactly equal",
           [] { check_permutation(*gen_scene(options_with_samples())); });
}

TEST_CASE("complex: invariant under integer translation", "[complex][property]") {
  rc::prop("same counts and signatures; measures Equal without disks, never separated with disks",
           [] { check_translation(*gen_scene(options_with_samples())); });
}

TEST_CASE("complex: patch lengths add up exactly", "[complex][property]") {
  rc::prop("polygon patches give the perimeter exactly; disk patches enclose 2 pi r", [] {
    const Scene2 scene = *gen_scene(options_with_samples());
    check_lengths(scene, arrange(scene));
  });
}

TEST_CASE("complex: polygon patch lengths with straight boundaries only", "[complex][property]") {
  // Without disks every vertex is rational and every length a sum of square roots of rationals: Equal is certain.
  rc::prop("perimeters exactly, and cell measures add up to the box", [] {
    SceneGenOptions o = options_with_samples();
    o.disks = false;
    const Scene2 scene = *gen_scene(o);
    const Arranged2 a = arrange(scene);
    for (int i = 0; i < static_cast<int>(scene.halfspaces.size()); ++i) {
      const Halfspace2& h = scene.halfspaces[i];
      if (h.kind != HalfspaceKind2::Polygon) continue;
      Measure sum, perimeter;
      for (const Patch& p : a.complex.patches)
        if (p.halfspace == i) sum += p.measure;
      for (std::size_t k = 0; k < h.vertices.size(); ++k)
        perimeter += Measure::distance(h.vertices[k], h.vertices[(k + 1) % h.vertices.size()]);
      RC_ASSERT(compare(sum, perimeter) == Order::Equal);
    }
    Measure total;
    for (const Cell& cell : a.complex.cells) total += cell.measure;
    const Box2& d = scene.domain;
    RC_ASSERT(compare(total, Measure(Rational((d.max.x - d.min.x) * (d.max.y - d.min.y)))) == Order::Equal);
  });
}

TEST_CASE("complex: all properties on larger scenes", "[.][stress][complex]") {
  // Hidden (run with "[stress]"): more halfspaces and degeneracies than the default suite. check_lengths is left
  // out so that the known Measure::distance limitation (the [bug] case below) does not mask other failures.
  rc::prop("larger scenes", [] {
    SceneGenOptions o = options_with_samples();
    o.max_halfspaces = 12;
    o.max_degeneracies = 5;
    const Scene2 scene = *gen_scene(o);
    check_structure(scene, arrange(scene));
    check_permutation(scene);
    check_translation(scene);
  });
}

// ---------------------------------------------------------------------------------------------------------------
// Hand-computed cases

TEST_CASE("complex: a polygon edge cut by two circles has exact patch lengths", "[complex][bug]") {
  // Minimal reproducer of the failures of "patch lengths add up exactly". The edge (0,0)-(6,6) of T meets circle A
  // at x = y = (1 + sqrt 7)/2 and circle B at x = y = 5 - sqrt(2)/2; the piece between them has length
  // sqrt(2) * (9/2 - sqrt(2)/2 - sqrt(7)/2) = -1 + 9/2 sqrt(2) - 1/2 sqrt(14), an exact sum of square roots.
  // Measure::distance (kernel/measure.cpp) keeps it as the special term sqrt(45 - 9 sqrt 2 - 9 sqrt 7 + sqrt 14)
  // because dx and dy each hold two radicals, so the patch lengths of T cannot be compared exactly with its
  // perimeter: compare answers Tie instead of Equal.
  const Scene2 s = make_scene(box(-2, -3, 10, 8), {polygon("T", {pt(0, 0), pt(6, 6), pt(8, 0)}),
                                                   disk("A", pt(1, 0), 2), disk("B", pt(5, 5), 1)});
  const Complex c = arrange(s).complex;
  CHECK(check_complex(c).empty());
  Measure sum;
  bool found_piece = false;
  const Measure expected_piece = Measure(Rational(-1)) + Measure::sqrt_of(Rational(81, 2)) - Measure::sqrt_of(Rational(7, 2));
  for (const Patch& p : c.patches)
    if (p.halfspace == 0) {
      sum += p.measure;
      if (close(p.measure, expected_piece, 1e-30)) {
        found_piece = true;
        INFO("piece between the circles: " << p.measure.get().exact_string().value_or("?"));
        CHECK(compare(p.measure, expected_piece) == Order::Equal);
        CHECK(!p.measure.get().has_special_terms());
      }
    }
  CHECK(found_piece);
  const Measure perimeter = Measure(Rational(8)) + Measure::sqrt_of(Rational(72)) + Measure::sqrt_of(Rational(40));
  INFO("sum of T's patches: " << sum.exact_string().value_or("?"));
  CHECK(compare(sum, perimeter) == Order::Equal);
}

TEST_CASE("complex: two crossing disks", "[complex]") {
  // A (0,0) r 2 and B (2,0) r 2 cross at (1, +-sqrt 3). Cells: outside (outer), A only, lens, B only.
  // Patches: each circle is cut into an outer arc (angle 4pi/3, length 8pi/3) and an inner arc (2pi/3, 4pi/3).
  const Scene2 s = make_scene(box(-4, -4, 6, 4), {disk("A", pt(0, 0), 2), disk("B", pt(2, 0), 2)});
  const Arranged2 a = arrange(s);
  const Complex& c = a.complex;
  CHECK(check_complex(c).empty());
  CHECK(c.cells.size() == 4);
  CHECK(c.outer_cell_count() == 1);
  REQUIRE(c.patches.size() == 4);
  CHECK(c.supports.size() == 4);
  REQUIRE(c.junctions.size() == 2);
  for (const Junction& j : c.junctions) CHECK(j.patches.size() == 4);
  for (const auto& n : c.patch_neighbours()) CHECK(n.size() == 3);
  const double pi = std::acos(-1.0);
  int long_arcs = 0, short_arcs = 0;
  for (const Patch& p : c.patches) {
    const double len = p.measure.get().to_double();
    if (std::fabs(len - 8 * pi / 3) < 1e-12) ++long_arcs;
    if (std::fabs(len - 4 * pi / 3) < 1e-12) ++short_arcs;
  }
  CHECK(long_arcs == 2);
  CHECK(short_arcs == 2);
  for (const auto& list : c.cell_patches()) CHECK(list.size() == 2);
}

TEST_CASE("complex: a disk tangent to a line", "[complex]") {
  // Disk |x| <= 1, y <= 1 in [-3,3]^2. Cells: above the line, below it outside the disk (both outer), the disk.
  // Patches: the line left and right of (0,1) (both between the two outer cells) and the whole circle, which
  // starts and ends at the tangency junction.
  const Scene2 s = make_scene(box(-3, -3, 3, 3), {disk("A", pt(0, 0), 1), halfplane("L", pt(0, 1), 1)});
  const Complex c = arrange(s).complex;
  CHECK(check_complex(c).empty());
  CHECK(c.cells.size() == 3);
  CHECK(c.outer_cell_count() == 2);
  REQUIRE(c.patches.size() == 3);
  // Junctions: the tangency point (3 patches) and the line's two ends on the box (1 patch each).
  REQUIRE(c.junctions.size() == 3);
  std::multiset<std::size_t> sizes;
  int tangency = -1;
  for (int j = 0; j < 3; ++j) {
    sizes.insert(c.junctions[j].patches.size());
    if (c.junctions[j].patches.size() == 3) tangency = j;
  }
  CHECK(sizes == std::multiset<std::size_t>{1, 1, 3});
  int line_patches = 0;
  for (const Patch& p : c.patches) {
    if (p.halfspace == 1) {
      ++line_patches;
      CHECK(compare(p.measure, Measure(Rational(3))) == Order::Equal);
      CHECK(c.cells[p.inside_cell].outer);
      CHECK(c.cells[p.outside_cell].outer);
    } else {
      CHECK(p.junctions == std::vector<int>{tangency, tangency});
      CHECK(close(p.measure, circumference(s.halfspaces[0]), 1e-30));
      CHECK(!c.cells[p.inside_cell].outer);
    }
  }
  CHECK(line_patches == 2);
}

TEST_CASE("complex: a disk and its complement", "[complex]") {
  // One circle carrying D and Dc: two patches in one support group, no junction (a closed patch).
  const Scene2 s = make_scene(box(-2, -2, 2, 2), {disk("D", pt(0, 0), 1), disk("Dc", pt(0, 0), 1, true)});
  const Complex c = arrange(s).complex;
  CHECK(check_complex(c).empty());
  REQUIRE(c.cells.size() == 2);
  CHECK(c.outer_cell_count() == 1);
  REQUIRE(c.patches.size() == 2);
  REQUIRE(c.supports.size() == 1);
  CHECK(c.supports[0].size() == 2);
  CHECK(c.junctions.empty());
  for (const Patch& p : c.patches) CHECK(p.junctions.empty());
  for (const auto& n : c.patch_neighbours()) CHECK(n.empty());
  for (const Cell& cell : c.cells)
    CHECK(cell.inside == (cell.outer ? std::vector<char>{0, 1} : std::vector<char>{1, 0}));
  CHECK(c.patches[0].inside_cell == c.patches[1].outside_cell);
  // The point set is counted once: 2 pi, not 4 pi.
  CHECK(close(c.measure_of({0, 1}), circumference(s.halfspaces[0]), 1e-30));
}

TEST_CASE("complex: a halfspace given twice gives support groups of size 2", "[complex]") {
  // H and H2: y <= 0, twice; a unit disk at the origin. Cells: 2 outer halves, 2 half disks. The line is cut at
  // x = -1, 1 into 3 pieces, each carrying H and H2 (3 groups of 2); the circle into 2 arcs (2 groups of 1).
  const Scene2 s = make_scene(box(-3, -3, 3, 3), {halfplane("H", pt(0, 1), 0), halfplane("H2", pt(0, 1), 0),
                                                  disk("D", pt(0, 0), 1)});
  const Complex c = arrange(s).complex;
  CHECK(check_complex(c).empty());
  CHECK(c.cells.size() == 4);
  CHECK(c.outer_cell_count() == 2);
  CHECK(c.patches.size() == 8);
  REQUIRE(c.supports.size() == 5);
  int pairs = 0;
  for (const auto& g : c.supports) {
    if (g.size() == 2) {
      ++pairs;
      std::set<int> hs{c.patches[g[0]].halfspace, c.patches[g[1]].halfspace};
      CHECK(hs == std::set<int>{0, 1});
      CHECK(compare(c.measure_of(g), c.patches[g[0]].measure) == Order::Equal);
    } else {
      CHECK(g.size() == 1);
      CHECK(c.patches[g[0]].halfspace == 2);
    }
  }
  CHECK(pairs == 3);
  // H's patches: total length 6 (the whole chord of the box), counted once with H2.
  std::vector<int> all(c.patches.size());
  for (std::size_t p = 0; p < all.size(); ++p) all[p] = static_cast<int>(p);
  Measure line;
  for (const Patch& p : c.patches)
    if (p.halfspace == 0) line += p.measure;
  CHECK(compare(line, Measure(Rational(6))) == Order::Equal);
  CHECK(close(c.measure_of(all), Measure(Rational(6)) + circumference(s.halfspaces[2]), 1e-30));
}

TEST_CASE("complex: a half-plane containing a polygon edge", "[complex]") {
  // Triangle (-1,0),(1,0),(0,1) and y >= 0 in [-3,3]^2: the base edge is coincident with the line.
  const Scene2 s = make_scene(box(-3, -3, 3, 3), {polygon("P", {pt(-1, 0), pt(1, 0), pt(0, 1)}),
                                                  halfplane("H", pt(0, -1), 0)});
  const Complex c = arrange(s).complex;
  CHECK(check_complex(c).empty());
  CHECK(c.cells.size() == 3);  // triangle, above the line, below it
  CHECK(c.outer_cell_count() == 2);
  // H: [-3,-1], [-1,1] (with P), [1,3]; P: [-1,1] (with H) and the two slanted edges through the apex.
  CHECK(c.patches.size() == 5);
  int groups_of_two = 0;
  for (const auto& g : c.supports)
    if (g.size() == 2) {
      ++groups_of_two;
      const Patch& p = c.patches[g[0]];
      CHECK(compare(p.measure, Measure(Rational(2))) == Order::Equal);
      // The triangle is inside both; the cell below is outside both.
      const Cell& a = c.cells[p.inside_cell];
      const Cell& b = c.cells[p.outside_cell];
      CHECK(a.inside[0] != b.inside[0]);
      CHECK(a.inside[1] != b.inside[1]);
    }
  CHECK(groups_of_two == 1);
}

TEST_CASE("complex: three concurrent lines", "[complex]") {
  const Scene2 s = make_scene(box(-2, -3, 3, 2), {halfplane("X", pt(0, 1), 0), halfplane("Y", pt(1, 0), 0),
                                                  halfplane("D", pt(1, -1), 0)});
  const Arranged2 a = arrange(s);
  const Complex& c = a.complex;
  CHECK(check_complex(c).empty());
  CHECK(c.cells.size() == 6);
  CHECK(c.outer_cell_count() == 6);
  CHECK(c.patches.size() == 6);
  // Junctions: the common point (6 patches) and the six line ends on the box (1 patch each).
  REQUIRE(c.junctions.size() == 7);
  int centre = 0;
  for (const Junction& j : c.junctions) {
    if (j.patches.size() == 6) {
      ++centre;
      CHECK(a.arrangement.vertices().at(j.piece).degree == 6);
    } else {
      CHECK(j.patches.size() == 1);
    }
  }
  CHECK(centre == 1);
}

TEST_CASE("complex: half-planes whose line only touches the box give no patch", "[complex]") {
  SECTION("line through a corner only") {
    const Scene2 s = make_scene(box(0, 0, 2, 2), {halfplane("H", pt(1, 1), 0), disk("D", pt(1, 1), q("1/2"))});
    const Complex c = arrange(s).complex;
    CHECK(check_complex(c).empty());
    CHECK(c.cells.size() == 2);
    REQUIRE(c.patches.size() == 1);
    CHECK(c.patches[0].halfspace == 1);
    for (const Cell& cell : c.cells) CHECK(cell.inside[0] == 0);
  }
  SECTION("line along a box side") {
    const Scene2 s = make_scene(box(0, 0, 2, 2), {halfplane("H", pt(-1, 0), 0), disk("D", pt(1, 1), q("1/2"))});
    const Complex c = arrange(s).complex;
    CHECK(check_complex(c).empty());
    CHECK(c.cells.size() == 2);
    REQUIRE(c.patches.size() == 1);
    CHECK(c.patches[0].halfspace == 1);
    for (const Cell& cell : c.cells) CHECK(cell.inside[0] == 1);
  }
}

TEST_CASE("complex: samples", "[complex]") {
  SECTION("a sample on a polygon corner sits on the polygon's patch") {
    Scene2 s = make_scene(box(-1, -1, 3, 3), {polygon("P", {pt(0, 0), pt(2, 0), pt(2, 2), pt(0, 2)})});
    add_sample(s, "P", pt(2, 2));
    validate_and_resolve(s);
    const Complex c = arrange(s).complex;
    CHECK(check_complex(c).empty());
    REQUIRE(c.patches.size() == 1);
    CHECK(c.patches[0].junctions.empty());  // a closed run through the four corners
    CHECK(compare(c.patches[0].measure, Measure(Rational(8))) == Order::Equal);
    REQUIRE(c.samples.size() == 1);
    CHECK(c.samples[0].patch == 0);
    CHECK(c.patches[0].samples == std::vector<int>{0});
  }
  SECTION("a polygon vertex with a straight angle is inside one patch") {
    // (1,0) lies between (0,0) and (2,0): a degree-2 vertex between two collinear edges of P.
    Scene2 s = make_scene(box(-1, -1, 3, 3), {polygon("P", {pt(0, 0), pt(1, 0), pt(2, 0), pt(2, 2), pt(0, 2)})});
    add_sample(s, "P", pt(1, 0));
    validate_and_resolve(s);
    const Arranged2 a = arrange(s);
    CHECK(check_complex(a.complex).empty());
    CHECK(a.arrangement.vertices().size() == 9);
    REQUIRE(a.complex.patches.size() == 1);
    CHECK(compare(a.complex.patches[0].measure, Measure(Rational(8))) == Order::Equal);
    CHECK(a.complex.patches[0].samples == std::vector<int>{0});
  }
  SECTION("samples on coincident boundaries sit on their own halfspace's patch") {
    Scene2 s = make_scene(box(-2, -2, 2, 2), {disk("D", pt(0, 0), 1), disk("Dc", pt(0, 0), 1, true)});
    add_sample(s, "Dc", pt(q("3/5"), q("4/5")));
    add_sample(s, "D", pt(q("-3/5"), q("4/5")));
    validate_and_resolve(s);
    const Complex c = arrange(s).complex;
    CHECK(check_complex(c).empty());
    REQUIRE(c.samples.size() == 2);
    CHECK(c.patches[c.samples[0].patch].halfspace == 1);
    CHECK(c.patches[c.samples[1].patch].halfspace == 0);
  }
  SECTION("a sample on a crossing is an input error") {
    Scene2 s = make_scene(box(-2, -2, 2, 2), {halfplane("X", pt(0, 1), 0), disk("D", pt(0, 0), 1)});
    add_sample(s, "D", pt(1, 0));
    validate_and_resolve(s);
    CHECK_THROWS_AS(arrange(s), InputError);
  }
}
