// The 2D NH-Rep pipeline (algorithms/nhrep/planar.hpp): build_planar_tree and evaluate_on_whole_plane, against the
// step-by-step pipeline (boundary, patch graph, Algorithm 1, evaluate_tree) and hand-checked diagnoses.
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/algorithms/nhrep/planar.hpp>
#include <hsx/complex/boundary_from_arrangement2.hpp>
#include <hsx/io/csg_text.hpp>
#include <hsx/io/nhrep_json.hpp>
#include <hsx/io/scene_json.hpp>
#include "support/random_scenes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace hsx;
using namespace hsx::nhrep;
using hsx::test::disk;
using hsx::test::make_scene;
using hsx::test::pt;
using hsx::test::q;

namespace {

Box2 box(int r) {
  return Box2{pt(q(std::to_string(-r)), q(std::to_string(-r))), pt(q(std::to_string(r)), q(std::to_string(r)))};
}

std::vector<char> solid_of(const Arranged2& a, const std::string& csg) {
  return csg::evaluate(*parse_csg_text(csg, a.complex.halfspace_names), a.complex);
}

Scene2 counterexample(const std::string& name, std::string& csg) {
  const std::string base = std::string(HSX_SOURCE_DIR) + "/data/counterexamples/nhrep/" + name;
  const Scene2 scene = read_scene_file(base + ".json");
  csg = base + ".csg";
  return scene;
}

}  // namespace

TEST_CASE("nhplanar: the pipeline gives the step-by-step tree, names and evaluation", "[nhplanar]") {
  std::string csg_path;
  const Scene2 scene = counterexample("pentagram", csg_path);
  const Arranged2 a = arrange(scene);
  const std::vector<char> solid = csg::evaluate(*read_csg_argument(csg_path, a.complex.halfspace_names), a.complex);
  const PlanarTree t = build_planar_tree(a, solid);
  const BuildResult by_hand = build_tree(build_patch_graph(boundary_from_arrangement2(a, solid)));
  CHECK(nhtree_text(t.built.tree) == nhtree_text(by_hand.tree));
  REQUIRE(t.leaf_names.size() == t.built.graph.patches.size());
  for (int p : t.built.graph.live_patches()) {
    CHECK(!t.leaf_names[static_cast<std::size_t>(p)].empty());
    CHECK(t.leaf_node[static_cast<std::size_t>(p)] >= 0);
  }
  // the decomposition cut one edge in two: two halves, one split point
  std::vector<PointQ2> splits;
  for (const auto& pieces : t.pieces)
    for (const PlanarPiece& piece : pieces)
      if (piece.split_point) splits.push_back(*piece.split_point);
  REQUIRE(splits.size() == 2);
  CHECK(splits[0] == splits[1]);
  // the scene's domain is its own choice, so it holds every vertex: evaluation on it is the whole plane's
  const PlanarEvaluation e = evaluate_on_whole_plane(t, scene, a, solid);
  const Evaluation direct = evaluate_tree(t.built, a.complex, solid);
  CHECK(e.cells == a.complex.cells.size());
  CHECK(e.evaluation.verdict == direct.verdict);
  CHECK(e.evaluation.verdict == Verdict::DescribableButFails);
  CHECK(e.diagnosis == Diagnosis::NeedsExtendedSurfaces);
  CHECK(e.missed.size() == direct.wrong_inside.size());
  CHECK(e.added.size() == direct.wrong_outside.size());
  for (std::size_t k = 0; k < e.missed.size(); ++k)
    CHECK(e.missed[k] == a.complex.cells[static_cast<std::size_t>(direct.wrong_inside[k])].witness.get());
}

TEST_CASE("nhplanar: an annulus is diagnosed as united holes, and nested holes fix it", "[nhplanar]") {
  const Scene2 s = make_scene(box(6), {disk("A", pt(q("0"), q("0")), q("3")), disk("B", pt(q("0"), q("0")), q("1"))});
  const Arranged2 a = arrange(s);
  const std::vector<char> solid = solid_of(a, "A - B");
  const PlanarEvaluation united = evaluate_on_whole_plane(build_planar_tree(a, solid), s, a, solid);
  CHECK(united.evaluation.verdict == Verdict::DescribableButFails);
  CHECK(united.diagnosis == Diagnosis::HolesUnited);
  CHECK(united.missed.empty());
  CHECK(!united.added.empty());
  BuildOptions nested;
  nested.nest_holes = true;
  const PlanarTree t = build_planar_tree(a, solid, nested);
  const PlanarEvaluation e = evaluate_on_whole_plane(t, s, a, solid);
  CHECK(e.evaluation.correct);
  CHECK(e.evaluation.verdict == Verdict::TreeCorrect);
  CHECK(e.diagnosis == Diagnosis::None);
  std::vector<std::string> names;
  for (int p : t.built.graph.live_patches()) names.push_back(t.leaf_names[static_cast<std::size_t>(p)]);
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"A", "~B"});
}

TEST_CASE("nhplanar: empty and unbounded solids are bad input", "[nhplanar]") {
  const Scene2 s = make_scene(box(6), {disk("A", pt(q("0"), q("0")), q("3"))});
  const Arranged2 a = arrange(s);
  CHECK_THROWS_AS(build_planar_tree(a, solid_of(a, "A & ~A")), InputError);
  CHECK_THROWS_WITH(build_planar_tree(a, solid_of(a, "~A")), Catch::Contains("bounded solid"));
  CHECK_THROWS_AS(build_planar_tree(a, {1}), std::invalid_argument);
}
