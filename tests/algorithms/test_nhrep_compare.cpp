// Comparing NH-Rep trees and patch graphs with references (algorithms/nhrep/compare.hpp) and reading NH-Rep's
// reference files (io/nhrep_json.hpp), through the public API. The comparison is checked against a brute-force
// oracle: a reference written from our own tree in NH-Rep's numbering compares equal; every single mutation of it
// (a leaf renumbered, an op flipped, a subtree moved) compares different and is located.
#include <hsx/algorithms/nhrep/compare.hpp>
#include <hsx/io/nhrep_json.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

using namespace hsx;
using namespace hsx::nhrep;

namespace {

constexpr FeatureType X = FeatureType::Convex;
constexpr FeatureType V = FeatureType::Concave;

/// One closed 2D cycle of pieces, piece i meeting piece i+1 at a feature link of type types[i]; piece i's origin is
/// i (standing for triangle i of a mesh).
BoundarySurface cycle(const std::vector<FeatureType>& types) {
  BoundarySurface s;
  s.dimension = 2;
  const int n = static_cast<int>(types.size());
  s.pieces.resize(types.size());
  for (int i = 0; i < n; ++i) {
    s.pieces[static_cast<std::size_t>(i)].origin = i;
    BoundaryLink link;
    link.piece_a = i;
    link.piece_b = (i + 1) % n;
    link.feature = true;
    link.type = types[static_cast<std::size_t>(i)];
    s.links.push_back(link);
    s.pieces[static_cast<std::size_t>(i)].links.push_back(i);
    s.pieces[static_cast<std::size_t>((i + 1) % n)].links.push_back(i);
  }
  return s;
}

/// Fig. 2 of the paper: max(0, 1, 2, 3, min(4, 7, max(5, 6))).
BuildResult fig2() { return build_tree(build_patch_graph(cycle({X, X, X, X, V, X, V, X}))); }

Tree conf(const std::string& list, bool max_root = true) {
  return read_nhtree_conf("csg{\n    list = " + list + ",\n    flag_convex = " + (max_root ? "1" : "0") + ",\n}",
                          "test.conf");
}

ReferenceComparison against(const BuildResult& r, const Tree& theirs, std::vector<int> face_patch = {}) {
  return compare_with_reference(r, ReferenceTree{theirs, std::move(face_patch)});
}

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l == text; });
}

}  // namespace

TEST_CASE("nhrep compare: NH-Rep's numbering follows the lowest origin, also after decomposition", "[nhrep][compare]") {
  const BuildResult plain = fig2();
  CHECK(nhrep_patch_numbers(plain.graph) == std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7});
  // alternating corners: patch 0 is decomposed into two halves of piece 0 (origin 0), which come first
  const BuildResult r = build_tree(build_patch_graph(cycle({X, V, X, V})));
  REQUIRE(r.decompositions.size() == 1);
  const std::vector<int> subs = r.decompositions[0].subpatches;
  REQUIRE(subs.size() == 2);
  const std::vector<int> number = nhrep_patch_numbers(r.graph);
  CHECK(number[0] == -1);
  CHECK(number[static_cast<std::size_t>(subs[0])] == 0);
  CHECK(number[static_cast<std::size_t>(subs[1])] == 1);
  CHECK(number[1] == 2);
  CHECK(number[3] == 4);
  CHECK(original_labels(r.graph)[static_cast<std::size_t>(subs[1])] == 0);
  // the relabelled tree has exactly the numbers 0..4 as leaves, and is what the .conf writer writes
  const Tree t = relabel_tree(r.tree, number);
  std::vector<int> leaves;
  for (const TreeNode& n : t.nodes) leaves.insert(leaves.end(), n.leaves.begin(), n.leaves.end());
  std::sort(leaves.begin(), leaves.end());
  CHECK(leaves == std::vector<int>{0, 1, 2, 3, 4});
  CHECK(canonical_form(read_nhtree_conf(nhtree_conf(r), "ours.conf"), {0, 1, 2, 3, 4}) ==
        canonical_form(t, {0, 1, 2, 3, 4}));
}

TEST_CASE("nhrep compare: relabel_tree puts leaves ascending and children by their lowest label", "[nhrep][compare]") {
  const BuildResult r = fig2();
  // reverse the numbering: 0..7 -> 7..0
  const Tree t = relabel_tree(r.tree, {7, 6, 5, 4, 3, 2, 1, 0});
  REQUIRE(t.root == 0);
  CHECK(t.nodes[0].op == Op::Max);
  CHECK(t.nodes[0].leaves == std::vector<int>{4, 5, 6, 7});
  REQUIRE(t.nodes[0].children.size() == 1);
  const TreeNode& min = t.nodes[static_cast<std::size_t>(t.nodes[0].children[0])];
  CHECK(min.leaves == std::vector<int>{0, 3});
  CHECK_THROWS_AS(relabel_tree(r.tree, {0, 1, 2}), std::invalid_argument);
  CHECK_THROWS_AS(relabel_tree(r.tree, {0, 1, 2, 3, 4, 5, 6, -1}), std::invalid_argument);
}

TEST_CASE("nhrep compare: our own tree in NH-Rep's numbering compares equal", "[nhrep][compare]") {
  const BuildResult r = fig2();
  const ReferenceComparison same = against(r, conf("[0,1,2,3,[4,7,[5,6,],],]"));
  CHECK(same.equal);
  CHECK(!same.mismatch);
  CHECK(same.trees.differences.empty());
  CHECK(same.basis == "patch numbers (lowest triangle first)");
  // the order of leaves and children in the file does not matter
  CHECK(against(r, conf("[[[6,5,],7,4,],3,2,1,0,]")).equal);
}

TEST_CASE("nhrep compare: one leaf renumbered, one op flipped, one subtree moved: different, and where", "[nhrep][compare]") {
  const BuildResult r = fig2();
  SECTION("a leaf renumbered") {
    const ReferenceComparison c = against(r, conf("[0,1,2,3,[4,8,[5,6,],],]"));
    CHECK(!c.equal);
    CHECK(c.trees.theirs == "max{0,1,2,3,[min{4,8,[max{5,6}]}]}");
    CHECK(c.trees.differences == std::vector<std::string>{"root/0: leaves ours {4,7}, theirs {4,8}"});
  }
  SECTION("an op flipped") {
    Tree theirs = conf("[0,1,2,3,[4,7,[5,6,],],]");
    for (TreeNode& n : theirs.nodes)
      if (n.leaves == std::vector<int>{5, 6}) n.op = Op::Min;
    const ReferenceComparison c = against(r, theirs);
    CHECK(!c.equal);
    CHECK(c.trees.differences == std::vector<std::string>{"root/0/0: ours is max, theirs min"});
  }
  SECTION("the root's op flipped") {
    const ReferenceComparison c = against(r, conf("[0,1,2,3,[4,7,[5,6,],],]", false));
    CHECK(!c.equal);
    CHECK(mentions(c.trees.differences, "root: ours is max, theirs min"));
  }
  SECTION("a subtree moved up to the root") {
    const ReferenceComparison c = against(r, conf("[0,1,2,3,[4,7,],[5,6,],]"));
    CHECK(!c.equal);
    CHECK(mentions(c.trees.differences, "root/0: only ours has child max{5,6}"));
    CHECK(mentions(c.trees.differences, "root: only theirs has child min{5,6}"));
    CHECK(c.trees.differences.size() == 2);
  }
  SECTION("a leaf moved between nodes") {
    const ReferenceComparison c = against(r, conf("[0,1,2,[3,4,7,[5,6,],],]"));
    CHECK(!c.equal);
    CHECK(mentions(c.trees.differences, "root: leaves ours {0,1,2,3}, theirs {0,1,2}"));
    CHECK(mentions(c.trees.differences, "root/0: leaves ours {4,7}, theirs {3,4,7}"));
  }
}

TEST_CASE("nhrep compare: a huge reference patch id costs nothing in proportion to it", "[nhrep][compare]") {
  const BuildResult r = fig2();
  const ReferenceComparison c = against(r, conf("[0,1,2,3,[4,99999999,[5,6,],],]"));
  CHECK(!c.equal);
  CHECK(c.trees.differences == std::vector<std::string>{"root/0: leaves ours {4,7}, theirs {4,99999999}"});
}

TEST_CASE("nhrep compare: through a face-patch list, reference patches map to our original patches", "[nhrep][compare]") {
  const BuildResult r = fig2();
  // the reference numbers our patch p (one piece, origin p) as 10 + 7 - p
  std::vector<int> face_patch;
  for (int f = 0; f < 8; ++f) face_patch.push_back(17 - f);
  SECTION("the same tree under another numbering") {
    const ReferenceComparison c = against(r, conf("[17,16,15,14,[13,10,[12,11,],],]"), face_patch);
    CHECK(c.equal);
    CHECK(c.basis == "original patches (each reference patch mapped through its triangles)");
  }
  SECTION("a different tree under that numbering") {
    const ReferenceComparison c = against(r, conf("[17,16,15,[14,13,10,[12,11,],],]"), face_patch);
    CHECK(!c.equal);
    CHECK(!c.trees.differences.empty());
  }
  SECTION("a reference patch on two of our patches cannot be matched") {
    face_patch[1] = 17;
    const ReferenceComparison c = against(r, conf("[17,15,14,[13,10,[12,11,],],]"), face_patch);
    CHECK(!c.equal);
    REQUIRE(c.mismatch);
    CHECK(*c.mismatch == "reference patch 17 spans 2 of our original patches");
  }
  SECTION("bad lists are the caller's error") {
    CHECK_THROWS_AS(against(r, conf("[17,16,]"), {17, 16}), std::invalid_argument);  // not one per triangle
    CHECK_THROWS_AS(against(r, conf("[17,99,]"), face_patch), std::invalid_argument);  // leaf without triangles
  }
}

TEST_CASE("nhrep compare: patch graphs differ by the edges they do not share", "[nhrep][compare]") {
  const BuildResult r = fig2();  // the cycle 0-1-...-7-0; corners 4|5 and 6|7 concave
  std::vector<ReferenceEdge> theirs;
  for (int i = 0; i < 8; ++i) {
    const int a = i, b = (i + 1) % 8;
    theirs.push_back({std::min(a, b), std::max(a, b), (i == 4 || i == 6) ? V : X});
  }
  // the graph after Algorithm 1 equals the original here (no decomposition)
  GraphComparison same = compare_patch_graphs(r.graph, theirs);
  CHECK(same.reference_edges == 8);
  CHECK(same.differences.empty());
  theirs[2].type = FeatureType::Smooth;  // 2-3: ours convex, theirs smooth
  theirs.erase(theirs.begin() + 5);      // 5-6: only ours
  theirs.push_back({2, 5, X});           // 2-5: only theirs
  const GraphComparison c = compare_patch_graphs(r.graph, theirs);
  CHECK(c.reference_edges == 8);
  REQUIRE(c.differences.size() == 3);
  CHECK(c.differences[0].a == 2);
  CHECK(c.differences[0].b == 3);
  CHECK(c.differences[0].ours == X);
  CHECK(c.differences[0].theirs == FeatureType::Smooth);
  CHECK(c.differences[1].a == 2);
  CHECK(c.differences[1].b == 5);
  CHECK(!c.differences[1].ours);
  CHECK(c.differences[2].a == 5);
  CHECK(c.differences[2].b == 6);
  CHECK(!c.differences[2].theirs);
  theirs.push_back({2, 5, V});
  CHECK_THROWS_AS(compare_patch_graphs(r.graph, theirs), std::invalid_argument);
}

TEST_CASE("nhrep io: reference files are checked with file and line", "[nhrep][compare][io]") {
  CHECK_THROWS_WITH(read_nhtree_conf("", "e.conf"), "e.conf:1: empty file");
  CHECK_THROWS_WITH(read_nhtree_conf("csg{\n list = [0,\n1,0,],\n flag_convex = 1,\n}", "d.conf"),
                    "d.conf:3: patch id 0 appears twice (first on line 2)");
  CHECK_THROWS_WITH(read_nhtree_conf("csg{\n list = [0,\n123456789,],\n flag_convex = 1,\n}", "h.conf"),
                    Catch::StartsWith("h.conf:3: patch id too large"));
  CHECK_THROWS_WITH(read_face_patch("0\n1\n-2\n", "f.txt"), Catch::StartsWith("f.txt:3: expected a patch id"));
  CHECK_THROWS_WITH(read_face_patch("\n\n", "f.txt"), "f.txt:1: empty file");
  const std::vector<ReferenceEdge> edges = read_nhrep_patch_graph("# header\nedge: 3-1 : 2\r\nedge: 0-1 : 0\n", "g.txt");
  REQUIRE(edges.size() == 2);
  CHECK(edges[0].a == 1);
  CHECK(edges[0].b == 3);
  CHECK(edges[0].type == V);
  CHECK(edges[1].type == FeatureType::Smooth);
  CHECK_THROWS_WITH(read_nhrep_patch_graph("edge: 0-1 : 1\nedge: 0-1 : 1 extra\n", "g.txt"),
                    Catch::StartsWith("g.txt:2: expected 'edge: A-B : T'"));
  CHECK_THROWS_WITH(read_nhrep_patch_graph("edge: 0-1 : 1\nedge: 1-0 : 2\n", "g.txt"),
                    "g.txt:2: edge 0-1 listed twice (first on line 1)");
  CHECK_THROWS_WITH(read_nhrep_patch_graph("edge: 0-1 : 3\n", "g.txt"), "g.txt:1: edge type 3 is not 0, 1 or 2");
  CHECK_THROWS_WITH(read_nhrep_patch_graph("edge: 2-2 : 1\n", "g.txt"), Catch::StartsWith("g.txt:1: patch ids must"));
  CHECK_THROWS_WITH(read_nhrep_patch_graph(" \n", "g.txt"), "g.txt:1: empty file");
}
