// NH-Rep patch graphs, Algorithm 1 and patch decomposition on hand-built boundaries (no geometry).
#include <hsx/algorithms/nhrep/tree.hpp>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <map>
#include <set>

using namespace hsx;
using namespace hsx::nhrep;

namespace {

constexpr FeatureType X = FeatureType::Convex;
constexpr FeatureType V = FeatureType::Concave;
constexpr FeatureType S = FeatureType::Smooth;

/// A 2D boundary: cycles of pieces; piece i of a cycle meets piece i+1 at link i. `types[k]` is the type of the
/// link after piece k, or nullopt-like "same patch" when `same[k]`.
struct Cycle {
  std::vector<FeatureType> types;
  std::vector<char> same;  // optional: 1 = non-feature link (the two pieces lie on one patch)
};

BoundarySurface curves(const std::vector<Cycle>& cycles) {
  BoundarySurface s;
  s.dimension = 2;
  for (const Cycle& cycle : cycles) {
    const int first = static_cast<int>(s.pieces.size());
    const int n = static_cast<int>(cycle.types.size());
    for (int i = 0; i < n; ++i) s.pieces.emplace_back();
    for (int i = 0; i < n; ++i) {
      BoundaryLink link;
      link.piece_a = first + i;
      link.piece_b = first + (i + 1) % n;
      link.feature = cycle.same.empty() || !cycle.same[static_cast<std::size_t>(i)];
      link.type = cycle.types[static_cast<std::size_t>(i)];
      const int id = static_cast<int>(s.links.size());
      s.links.push_back(link);
      s.pieces[static_cast<std::size_t>(link.piece_a)].links.push_back(id);
      s.pieces[static_cast<std::size_t>(link.piece_b)].links.push_back(id);
    }
  }
  return s;
}

/// A closed surface: an n x m grid of quads on a torus (a closed manifold), links between grid neighbours.
/// `patch_of` groups cells into patches (links inside a group are non-feature); `type_of(link)` types the others.
template <class PatchOf, class TypeOf>
BoundarySurface torus(int n, int m, PatchOf patch_of, TypeOf type_of) {
  BoundarySurface s;
  s.dimension = 3;
  s.corner_count = n * m;
  s.pieces.resize(static_cast<std::size_t>(n * m));
  auto cell = [&](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j)
      for (int dir = 0; dir < 2; ++dir) {
        const int a = cell(i, j), b = dir == 0 ? cell(i + 1, j) : cell(i, j + 1);
        BoundaryLink link;
        link.piece_a = a;
        link.piece_b = b;
        link.feature = patch_of(a) != patch_of(b);
        const int id = static_cast<int>(s.links.size());
        link.type = link.feature ? type_of(id) : S;
        // the shared grid edge's end points, as corners (grid vertices)
        if (dir == 0) {
          link.corner_a = cell(i + 1, j);
          link.corner_b = cell(i + 1, j + 1);
        } else {
          link.corner_a = cell(i, j + 1);
          link.corner_b = cell(i + 1, j + 1);
        }
        s.links.push_back(link);
        s.pieces[static_cast<std::size_t>(a)].links.push_back(id);
        s.pieces[static_cast<std::size_t>(b)].links.push_back(id);
      }
  return s;
}

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

TEST_CASE("nhrep: a square is one max node of its four sides", "[nhrep]") {
  const BuildResult r = build_tree(build_patch_graph(curves({{{X, X, X, X}}})));
  REQUIRE(check_tree(r).empty());
  REQUIRE(r.tree.nodes.size() == 1);
  CHECK(r.tree.nodes[0].op == Op::Max);
  CHECK(r.tree.nodes[0].leaves == std::vector<int>{0, 1, 2, 3});
  CHECK(r.decompositions.empty());
}

TEST_CASE("nhrep: an L shape puts the two sides of its concave corner under a min node", "[nhrep]") {
  // sides 0..5, corner after side 3 is concave
  const BuildResult r = build_tree(build_patch_graph(curves({{{X, X, X, V, X, X}}})));
  REQUIRE(check_tree(r).empty());
  REQUIRE(r.tree.nodes.size() == 2);
  CHECK(r.tree.nodes[0].op == Op::Max);
  CHECK(r.tree.nodes[0].leaves == std::vector<int>{0, 1, 2, 5});
  CHECK(r.tree.nodes[1].op == Op::Min);
  CHECK(r.tree.nodes[1].leaves == std::vector<int>{3, 4});
}

TEST_CASE("nhrep: the union of two disks has no convex edge (case 1, first subcase)", "[nhrep]") {
  const BuildResult r = build_tree(build_patch_graph(curves({{{V, V}}})));
  REQUIRE(check_tree(r).empty());
  REQUIRE(r.tree.nodes.size() == 1);
  CHECK(r.tree.nodes[0].op == Op::Min);
  CHECK(r.tree.nodes[0].leaves == std::vector<int>{0, 1});
  REQUIRE(r.steps.size() == 1);
  CHECK(r.steps[0].outcome == "case 1: no convex edges");
}

TEST_CASE("nhrep: Fig. 2's solid gives max(f1..f4, min(f5, f8, max(f6, f7)))", "[nhrep]") {
  // Sides P1..P8 in boundary order (pieces 0..7); the corners of Fig. 2-(a): P5|P6 and P7|P8 concave, all
  // others convex.
  const BuildResult r = build_tree(build_patch_graph(curves({{{X, X, X, X, V, X, V, X}}})));
  REQUIRE(check_tree(r).empty());
  REQUIRE(r.tree.nodes.size() == 3);
  CHECK(r.tree.nodes[0].op == Op::Max);
  CHECK(r.tree.nodes[0].leaves == std::vector<int>{0, 1, 2, 3});
  CHECK(r.tree.nodes[0].children == std::vector<int>{1});
  CHECK(r.tree.nodes[1].op == Op::Min);
  CHECK(r.tree.nodes[1].leaves == std::vector<int>{4, 7});
  CHECK(r.tree.nodes[2].op == Op::Max);
  CHECK(r.tree.nodes[2].leaves == std::vector<int>{5, 6});
}

TEST_CASE("nhrep: several components get a min root", "[nhrep]") {
  const BuildResult r = build_tree(build_patch_graph(curves({{{X, X, X}}, {{X, X, X, X}}})));
  REQUIRE(check_tree(r).empty());
  const Tree& t = r.tree;
  CHECK(t.nodes[static_cast<std::size_t>(t.root)].op == Op::Min);
  CHECK(t.nodes[static_cast<std::size_t>(t.root)].children.size() == 2);
}

TEST_CASE("nhrep: non-feature links merge pieces into one patch; a lone closed patch is a leaf", "[nhrep]") {
  // a circle in two arcs (one patch) next to a square with a polygon corner inside one patch
  const BuildResult r = build_tree(build_patch_graph(curves({{{S, S}, {1, 1}}, {{X, X, X, X}, {0, 1, 0, 0}}})));
  REQUIRE(check_tree(r).empty());
  CHECK(r.graph.patches.size() == 4);  // the circle, and the square's 3 patches (two sides share one)
  CHECK(r.graph.patches[0].pieces == std::vector<int>{0, 1});
}

TEST_CASE("nhrep: alternating corners force a decomposition (case 1, second subcase)", "[nhrep]") {
  const BuildResult r = build_tree(build_patch_graph(curves({{{X, V, X, V}}})));
  REQUIRE(check_tree(r).empty());
  REQUIRE(r.decompositions.size() >= 1);
  const Decomposition& d = r.decompositions[0];
  CHECK(d.patch == 0);                 // the lowest patch with both kinds
  CHECK(d.pieces_split == 1);          // a single curve piece with a convex and a concave end: split in two
  CHECK(d.subpatches.size() == 2);
  CHECK(d.both_kinds_after < d.both_kinds_before);
  CHECK(r.steps[0].outcome == "case 1: decompose");
  for (int sub : d.subpatches) CHECK(r.graph.patches[static_cast<std::size_t>(sub)].parent == 0);
}

TEST_CASE("nhrep: decomposition on a surface splits by a minimum cut", "[nhrep]") {
  // 4 x 8 torus: patch A = columns 0..3, patch B = columns 4..7. The A|B curve at column 3|4 is convex, the one
  // at 7|0 concave: both patches touch both kinds.
  auto patch_of = [](int cell) { return (cell % 8) < 4 ? 0 : 1; };
  BoundarySurface s = torus(4, 8, patch_of, [](int) { return S; });
  for (auto& link : s.links)
    if (link.feature) link.type = (link.piece_a % 8 == 3 || link.piece_b % 8 == 3) ? X : V;
  const BuildResult r = build_tree(build_patch_graph(s));
  REQUIRE(check_tree(r).empty());
  REQUIRE(!r.decompositions.empty());
  const Decomposition& d = r.decompositions[0];
  CHECK(d.patch == 0);
  CHECK(d.pieces_split == 0);
  CHECK(d.cut_links == 4);  // one ring of the torus: the minimum cut between the two feature curves
  CHECK(d.subpatches.size() == 2);
}

TEST_CASE("nhrep: feature curves chain through corners where two feature links meet", "[nhrep]") {
  // torus 4 x 4 with one patch per column pair: two curves between patches 0 and 1 (at columns 1|2 and 3|0)
  auto patch_of = [](int cell) { return (cell % 4) < 2 ? 0 : 1; };
  const PatchGraph g = build_patch_graph(torus(4, 4, patch_of, [](int) { return X; }));
  REQUIRE(g.curves.size() == 2);
  CHECK(g.curves[0].links.size() == 4);
  CHECK(g.curves[1].links.size() == 4);
}

TEST_CASE("nhrep: a curve with convex and concave links is hybrid", "[nhrep]") {
  auto patch_of = [](int cell) { return (cell % 4) < 2 ? 0 : 1; };
  BoundarySurface s = torus(4, 4, patch_of, [](int link) { return link % 3 == 0 ? V : X; });
  const PatchGraph g = build_patch_graph(s);
  bool hybrid = false;
  for (const Curve& c : g.curves) hybrid |= c.type == FeatureType::Hybrid;
  CHECK(hybrid);
  const BuildResult r = build_tree(g);
  CHECK(check_tree(r).empty());
}

TEST_CASE("nhrep: a bad boundary is rejected with the offending link", "[nhrep]") {
  BoundarySurface s = curves({{{X, X, X}}});
  s.links[1].piece_b = 7;
  CHECK_THROWS_WITH(build_patch_graph(s), Catch::Contains("link 1"));
}

TEST_CASE("nhrep: check_tree catches a broken tree", "[nhrep]") {
  BuildResult r = build_tree(build_patch_graph(curves({{{X, X, X, V, X, X}}})));
  REQUIRE(check_tree(r).empty());
  SECTION("a leaf moved to the wrong node") {
    r.tree.nodes[0].leaves.push_back(3);
    r.tree.nodes[1].leaves = {4};
    CHECK(!check_tree(r).empty());
  }
  SECTION("ops that do not alternate") {
    r.tree.nodes[1].op = Op::Max;
    CHECK(!check_tree(r).empty());
  }
  SECTION("a patch missing") {
    r.tree.nodes[1].leaves = {3};
    CHECK(!check_tree(r).empty());
  }
}

TEST_CASE("nhrep: grouping never puts adjacent patches together and respects the size", "[nhrep]") {
  const PatchGraph g = build_patch_graph(curves({{{X, X, X, X, X, X, X, X, X, X, X, X, X, X}}}));
  const auto groups = group_patches(g, 6);
  std::set<int> all;
  for (const auto& group : groups) {
    CHECK(group.size() <= 6);
    for (int p : group) all.insert(p);
    for (const Curve& c : g.curves)
      CHECK(!(std::count(group.begin(), group.end(), c.patch_a) && std::count(group.begin(), group.end(), c.patch_b)));
  }
  CHECK(all.size() == 14);
  // greedy in patch order: evens 0..10 and odds 1..11 fill two groups, 12 opens a third and 13 (next to 12 and
  // to 0) a fourth
  CHECK(groups.size() == 4);
}

namespace {

FeatureType gen_type(int k) { return std::array<FeatureType, 3>{X, V, S}[static_cast<std::size_t>(k)]; }

}  // namespace

TEST_CASE("nhrep: Algorithm 1 terminates with a valid tree on random 2D boundaries", "[nhrep][property]") {
  rc::prop("check_tree holds", [] {
    const int cycle_count = *rc::gen::inRange(1, 4);
    std::vector<Cycle> cycles;
    for (int c = 0; c < cycle_count; ++c) {
      const int n = *rc::gen::inRange(2, 12);
      Cycle cycle;
      for (int i = 0; i < n; ++i) {
        cycle.types.push_back(gen_type(*rc::gen::inRange(0, 3)));
        cycle.same.push_back(*rc::gen::inRange(0, 5) == 0);
      }
      cycles.push_back(cycle);
    }
    const BuildResult r = build_tree(build_patch_graph(curves(cycles)));
    const auto problems = check_tree(r);
    RC_ASSERT(problems.empty());
    // every original piece is covered by exactly one live patch
    std::vector<int> cover(r.graph.surface.pieces.size(), 0);
    for (int p : r.graph.live_patches())
      for (int piece : r.graph.patches[static_cast<std::size_t>(p)].pieces) ++cover[static_cast<std::size_t>(piece)];
    for (std::size_t piece = 0; piece < cover.size(); ++piece)
      RC_ASSERT(cover[piece] == (r.graph.surface.pieces[piece].retired ? 0 : 1));
  });
}

TEST_CASE("nhrep: Algorithm 1 terminates with a valid tree on random closed surfaces", "[nhrep][property]") {
  rc::prop("check_tree holds on tori with random patches and feature types", [] {
    const int n = *rc::gen::inRange(2, 7), m = *rc::gen::inRange(2, 7);
    const int patches = *rc::gen::inRange(2, 7);
    const auto patch_of_cell = *rc::gen::container<std::vector<int>>(static_cast<std::size_t>(n * m), rc::gen::inRange(0, patches));
    const auto link_types = *rc::gen::container<std::vector<int>>(static_cast<std::size_t>(2 * n * m), rc::gen::inRange(0, 3));
    const BoundarySurface s = torus(
        n, m, [&](int cell) { return patch_of_cell[static_cast<std::size_t>(cell)]; },
        [&](int link) { return gen_type(link_types[static_cast<std::size_t>(link)]); });
    const BuildResult r = build_tree(build_patch_graph(s));
    RC_ASSERT(check_tree(r).empty());
    RC_ASSERT(check_boundary(r.graph.surface).empty());
  });
}

namespace {

/// Marks the pieces of cycle `cycle` (in the order given to curves()) with a region and a hole flag.
void set_nesting(BoundarySurface& s, const std::vector<Cycle>& cycles, const std::vector<std::pair<int, bool>>& nest) {
  std::size_t piece = 0;
  for (std::size_t c = 0; c < cycles.size(); ++c)
    for (std::size_t k = 0; k < cycles[c].types.size(); ++k, ++piece) {
      s.pieces[piece].region = nest[c].first;
      s.pieces[piece].hole = nest[c].second;
    }
}

}  // namespace

TEST_CASE("nhrep: Section 5.2 unites a hole with its outer boundary; nest_holes intersects them", "[nhrep]") {
  // A square with a square hole: the hole's corners are concave seen from the solid.
  const std::vector<Cycle> cycles{{{X, X, X, X}}, {{V, V, V, V}}};
  BoundarySurface s = curves(cycles);
  set_nesting(s, cycles, {{0, false}, {0, true}});
  const BuildResult paper = build_tree(build_patch_graph(s));
  REQUIRE(check_tree(paper).empty());
  CHECK(paper.tree.nodes[static_cast<std::size_t>(paper.tree.root)].op == Op::Min);  // the union: wrong
  BuildOptions nest;
  nest.nest_holes = true;
  const BuildResult nested = build_tree(build_patch_graph(s), nest);
  REQUIRE(check_tree(nested).empty());
  const TreeNode& root = nested.tree.nodes[static_cast<std::size_t>(nested.tree.root)];
  CHECK(root.op == Op::Max);
  CHECK(root.leaves == std::vector<int>{0, 1, 2, 3});
  REQUIRE(root.children.size() == 1);
  CHECK(nested.tree.nodes[static_cast<std::size_t>(root.children[0])].op == Op::Min);
  CHECK(nested.tree.nodes[static_cast<std::size_t>(root.children[0])].leaves == std::vector<int>{4, 5, 6, 7});
}

TEST_CASE("nhrep: nest_holes puts a max node above a union part with a hole, and unites parts", "[nhrep]") {
  // part 0: two disks' union (concave corners only) with a round hole; part 1: a triangle.
  const std::vector<Cycle> cycles{{{V, V}}, {{S}, {1}}, {{X, X, X}}};
  BoundarySurface s = curves(cycles);
  // the round hole is one closed patch: its single piece's link joins it to itself, which curves() cannot build;
  // use a two-piece circle instead
  s = curves({{{V, V}}, {{S, S}, {1, 1}}, {{X, X, X}}});
  set_nesting(s, {{{V, V}}, {{S, S}}, {{X, X, X}}}, {{0, false}, {0, true}, {1, false}});
  BuildOptions nest;
  nest.nest_holes = true;
  const BuildResult r = build_tree(build_patch_graph(s), nest);
  const auto problems = check_tree(r);
  INFO((problems.empty() ? std::string() : problems.front()));
  REQUIRE(problems.empty());
  const TreeNode& root = r.tree.nodes[static_cast<std::size_t>(r.tree.root)];
  CHECK(root.op == Op::Min);
  CHECK(root.leaves.empty());
  REQUIRE(root.children.size() == 2);
  // the part with the hole: max(min(disk arcs), min(hole)); the triangle: max(sides)
  const TreeNode& part0 = r.tree.nodes[static_cast<std::size_t>(root.children[0])];
  CHECK(part0.op == Op::Max);
  CHECK(part0.leaves.empty());
  CHECK(part0.children.size() == 2);
  SECTION("a part without a known region is refused") {
    s.pieces[0].region = s.pieces[1].region = -1;
    CHECK_THROWS_AS(build_tree(build_patch_graph(s), nest), std::invalid_argument);
  }
}

TEST_CASE("nhrep: nest_holes gives valid trees on random nested boundaries", "[nhrep][property]") {
  rc::prop("check_tree holds", [] {
    const int parts = *rc::gen::inRange(1, 3);
    std::vector<Cycle> cycles;
    std::vector<std::pair<int, bool>> nest;
    for (int part = 0; part < parts; ++part) {
      const int holes = *rc::gen::inRange(0, 3);
      for (int k = 0; k <= holes; ++k) {
        const int n = *rc::gen::inRange(2, 9);
        Cycle cycle;
        for (int i = 0; i < n; ++i) {
          cycle.types.push_back(gen_type(*rc::gen::inRange(0, 3)));
          cycle.same.push_back(*rc::gen::inRange(0, 5) == 0);
        }
        cycles.push_back(cycle);
        nest.emplace_back(part, k > 0);
      }
    }
    BoundarySurface s = curves(cycles);
    set_nesting(s, cycles, nest);
    BuildOptions options;
    options.nest_holes = true;
    const BuildResult r = build_tree(build_patch_graph(s), options);
    RC_ASSERT(check_tree(r).empty());
  });
}
