// NH-Rep on 3D solids from halfspaces (algorithms/nhrep/solid3.hpp, complex/boundary_from_arrangement3.hpp,
// complex/carry_solid3.hpp, algorithms/csg/random_solid3.hpp, io/nhrep_dot.hpp): hand-checked boundaries, trees and
// verdicts on small scenes, the cavity finding with and without nest_holes, an edge where two solid wedges touch,
// the whole-space domain, and reproducible random solids.
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/algorithms/csg/random_solid3.hpp>
#include <hsx/algorithms/nhrep/solid3.hpp>
#include <hsx/algorithms/nhrep/survey.hpp>
#include <hsx/complex/boundary_from_arrangement3.hpp>
#include <hsx/complex/carry_solid3.hpp>
#include <hsx/io/csg_text.hpp>
#include <hsx/io/nhrep_dot.hpp>
#include <hsx/io/nhrep_svg.hpp>
#include <hsx/io/scene_json.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <string>

using namespace hsx;
using namespace hsx::nhrep;

namespace {

/// Planes of axis boxes: "<name>.x0" ... "<name>.z1" for each box lo..hi, in a domain [-4, 6]^3 (given).
std::string boxes_scene(const std::vector<std::pair<std::array<int, 3>, std::array<int, 3>>>& boxes,
                        const std::string& domain = "{\"min\": [-4, -4, -4], \"max\": [6, 6, 6]}") {
  std::string hs;
  int k = 0;
  for (const auto& [lo, hi] : boxes) {
    const std::string n = "B" + std::to_string(k++);
    const char* axis[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      std::string minus = "[0, 0, 0]", plus = "[0, 0, 0]";
      minus[1 + 3 * i] = '-';
      minus.insert(2 + 3 * i, "1");
      plus[1 + 3 * i] = '1';
      hs += std::string(hs.empty() ? "" : ",\n") + "{\"name\": \"" + n + "." + axis[i] + "0\", \"kind\": \"plane\", " +
            "\"normal\": " + minus + ", \"offset\": " + std::to_string(-lo[static_cast<std::size_t>(i)]) + "},\n" +
            "{\"name\": \"" + n + "." + axis[i] + "1\", \"kind\": \"plane\", \"normal\": " + plus + ", \"offset\": " +
            std::to_string(hi[static_cast<std::size_t>(i)]) + "}";
    }
  }
  return "{\"format\": \"hsx-scene/1\", \"dimension\": 3, \"domain\": " + domain + ", \"halfspaces\": [\n" + hs + "]}";
}

std::string all_of_box(int k) {
  const std::string n = "B" + std::to_string(k);
  return "(" + n + ".x0 & " + n + ".x1 & " + n + ".y0 & " + n + ".y1 & " + n + ".z0 & " + n + ".z1)";
}

std::vector<char> solid_of(const Arranged3& a, const std::string& csg) {
  return csg::evaluate(*parse_csg_text(csg, a.complex.halfspace_names), a.complex);
}

Scene3 scene3(const std::string& name) { return read_scene3_file(std::string(HSX_SOURCE_DIR) + "/data/scenes3d/" + name); }

}  // namespace

TEST_CASE("boundary_from_arrangement3: a cube of six planes", "[nhrep][solid3]") {
  const Scene3 s = read_scene3_text(boxes_scene({{{0, 0, 0}, {2, 2, 2}}}));
  const Arranged3 a = arrange(s);
  const std::vector<char> solid = solid_of(a, all_of_box(0));
  const BoundarySurface b = boundary_from_arrangement3(a, solid);
  CHECK(b.dimension == 3);
  CHECK(check_boundary(b).empty());
  REQUIRE(b.pieces.size() >= 12);
  std::map<int, int> per_carrier;
  for (const BoundaryPiece& p : b.pieces) {
    CHECK_FALSE(p.carrier_complemented);
    CHECK_FALSE(p.hole);
    CHECK(p.region == 0);
    ++per_carrier[p.carrier];
  }
  CHECK(per_carrier.size() == 6);
  for (const BoundaryLink& l : b.links) {
    const bool same = b.pieces[static_cast<std::size_t>(l.piece_a)].carrier == b.pieces[static_cast<std::size_t>(l.piece_b)].carrier;
    CHECK(l.feature == !same);
    CHECK(l.type == (same ? FeatureType::Smooth : FeatureType::Convex));  // flat inside a face, 90 degrees between
  }
  const SolidTree3 t = build_solid_tree3(a, solid);
  CHECK(check_tree(t.built).empty());
  REQUIRE(t.built.tree.nodes.size() == 1);
  CHECK(t.built.tree.nodes[0].op == Op::Max);
  CHECK(t.built.tree.nodes[0].leaves.size() == 6);
  const CellEvaluation e = evaluate_on_whole_space(t, s, a, solid);
  CHECK(e.evaluation.verdict == Verdict::TreeCorrect);
  CHECK(e.evaluation.violations.empty());
  CHECK(e.evaluation.natural_halfspaces.size() == 6);
}

TEST_CASE("3D NH-Rep: an L of two boxes has concave edges and a min node; correct", "[nhrep][solid3]") {
  const Scene3 s = read_scene3_text(boxes_scene({{{0, 0, 0}, {3, 1, 1}}, {{0, 0, 0}, {1, 3, 1}}}));
  const Arranged3 a = arrange(s);
  const std::vector<char> solid = solid_of(a, all_of_box(0) + " | " + all_of_box(1));
  const SolidTree3 t = build_solid_tree3(a, solid);
  CHECK(check_tree(t.built).empty());
  const auto concave = std::count_if(t.built.graph.curves.begin(), t.built.graph.curves.end(),
                                     [](const Curve& c) { return c.type == FeatureType::Concave; });
  CHECK(concave == 1);  // the inner vertical edge of the L
  bool has_min = false;
  for (const TreeNode& n : t.built.tree.nodes) has_min = has_min || n.op == Op::Min;
  CHECK(has_min);
  const CellEvaluation e = evaluate_on_whole_space(t, s, a, solid);
  CHECK(e.evaluation.verdict == Verdict::TreeCorrect);
  // The diagrams name every node and patch once.
  const std::string dot = nhtree_dot(t.built, t.leaf_names, "L");
  for (int p : t.built.graph.live_patches())
    CHECK(dot.find("  p" + std::to_string(p) + " [") != std::string::npos);
  const std::string graph = nhrep_patch_graph_dot(t.built, t.leaf_names, "L");
  CHECK(std::count(graph.begin(), graph.end(), '-') >= static_cast<long>(2 * t.built.graph.curves.size()));
  CHECK(graph.find("concave (") != std::string::npos);
  const std::string svg = nhrep_svg3(s, a, solid, t.built.graph.surface, t.built.graph.piece_patch, t.leaf_node, "L");
  CHECK(svg.find("class=\"feature\" data-id") != std::string::npos);
  CHECK(svg.find("data-type=\"concave\"") != std::string::npos);
  // The legend has one swatch per tree node holding leaves (the patches' colour groups).
  std::vector<int> groups;
  for (int p : t.built.graph.live_patches()) groups.push_back(t.leaf_node[static_cast<std::size_t>(p)]);
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  std::size_t swatches = 0;
  for (std::size_t at = svg.find("class=\"node-swatch\""); at != std::string::npos;
       at = svg.find("class=\"node-swatch\"", at + 1))
    ++swatches;
  CHECK(swatches == groups.size());
  CHECK(swatches >= 2);
  // A title too long for the width is set smaller (15 px otherwise).
  CHECK(svg.find("class=\"title\" x=\"500.0000\" y=\"18\" text-anchor=\"middle\" font-size=\"15.0000\"") !=
        std::string::npos);
  const std::string long_title = nhrep_svg3(s, a, solid, t.built.graph.surface, t.built.graph.piece_patch,
                                            t.leaf_node, std::string(200, 'x'));
  CHECK(long_title.find("font-size=\"15.0000\">xxx") == std::string::npos);
  CHECK(long_title.find("\">" + std::string(200, 'x') + "</text>") != std::string::npos);
}

TEST_CASE("boundary_from_arrangement3: two boxes touching along an edge give two links there", "[nhrep][solid3]") {
  const Scene3 s = read_scene3_text(boxes_scene({{{0, 0, 0}, {1, 1, 1}}, {{1, 1, 0}, {2, 2, 1}}}));
  const Arranged3 a = arrange(s);
  const std::vector<char> solid = solid_of(a, all_of_box(0) + " | " + all_of_box(1));
  const BoundarySurface b = boundary_from_arrangement3(a, solid);
  CHECK(check_boundary(b).empty());
  std::map<int, int> links_per_edge;
  for (const BoundaryLink& l : b.links) ++links_per_edge[l.origin];
  int doubled = 0;
  for (const auto& [edge, count] : links_per_edge) {
    CHECK(count <= 2);
    if (count == 2) {
      ++doubled;
      const ArrEdge3& e = a.arrangement.edges()[static_cast<std::size_t>(edge)];
      const PointQ3& p = a.arrangement.vertices()[static_cast<std::size_t>(e.a)];
      const PointQ3& q = a.arrangement.vertices()[static_cast<std::size_t>(e.b)];
      CHECK(p.x == 1);  // on the shared edge x = y = 1
      CHECK(q.y == 1);
    }
  }
  CHECK(doubled >= 1);
  for (const BoundaryLink& l : b.links)
    if (links_per_edge[l.origin] == 2) CHECK(l.type == FeatureType::Convex);  // each wedge is 90 degrees
  // Two solid parts, neither holed.
  std::vector<int> regions;
  for (const BoundaryPiece& p : b.pieces) regions.push_back(p.region);
  CHECK(*std::max_element(regions.begin(), regions.end()) == 1);
  const SolidTree3 t = build_solid_tree3(a, solid);
  CHECK(check_tree(t.built).empty());
  CHECK(evaluate_on_whole_space(t, s, a, solid).evaluation.verdict == Verdict::TreeCorrect);
}

TEST_CASE("3D NH-Rep: a hollow sphere fails without nest_holes and is correct with it", "[nhrep][solid3]") {
  const Scene3 s = scene3("sphere_cavity.json");
  const Arranged3 a = arrange(s);
  const std::vector<char> solid = solid_of(a, "Outer & Cavity");
  const BoundarySurface b = boundary_from_arrangement3(a, solid);
  for (const BoundaryPiece& p : b.pieces) CHECK(p.hole == (a.complex.halfspace_names[static_cast<std::size_t>(p.carrier)] == "Cavity"));
  const SolidTree3 united = build_solid_tree3(a, solid);
  const CellEvaluation e = evaluate_on_whole_space(united, s, a, solid);
  CHECK(e.evaluation.verdict == Verdict::DescribableButFails);
  CHECK(e.diagnosis == Diagnosis::HolesUnited);
  CHECK_FALSE(e.added.empty());  // the cavity (and the box beside it) is added by the union
  CHECK(e.added.front().size() == 3);
  BuildOptions nested;
  nested.nest_holes = true;
  const SolidTree3 t = build_solid_tree3(a, solid, nested);
  CHECK(check_tree(t.built).empty());
  CHECK(evaluate_on_whole_space(t, s, a, solid).evaluation.verdict == Verdict::TreeCorrect);
  // The same pipeline as the survey's.
  SurveySolid3 c;
  c.scene = s;
  c.arranged = a;
  c.solid = solid;
  const SurveyOutcome o = survey_solid3(c);
  CHECK(o.problems.empty());
  CHECK(o.holes == 1);
  CHECK(o.whole.eval.verdict == Verdict::DescribableButFails);
}

TEST_CASE("whole_space_scene3: a domain too small for a plane triple point is enlarged; the solid carries over",
          "[nhrep][solid3]") {
  // A cube and a slanted plane that meets the cube's planes far outside the given domain [-1, 3]^3.
  std::string text = boxes_scene({{{0, 0, 0}, {2, 2, 2}}}, "{\"min\": [-1, -1, -1], \"max\": [3, 3, 3]}");
  text.insert(text.rfind(']'), ",\n{\"name\": \"S\", \"kind\": \"plane\", \"normal\": [1, 1, 20], \"offset\": 41}");
  const Scene3 s = read_scene3_text(text);
  const Scene3 whole = whole_space_scene3(s);
  CHECK(whole.domain.max.z > s.domain.max.z);
  CHECK(whole.domain.min.x < s.domain.min.x);
  const Arranged3 a = arrange(s);
  const Arranged3 w = arrange(whole);
  const std::vector<char> solid = solid_of(a, all_of_box(0) + " & S");
  const std::vector<char> carried = carry_to_whole_space(a, solid, w);
  CHECK(carried == solid_of(w, all_of_box(0) + " & S"));
  const SolidTree3 t = build_solid_tree3(a, solid);
  const CellEvaluation e = evaluate_on_whole_space(t, s, a, solid);
  CHECK(e.cells == w.complex.cells.size());
  CHECK(e.evaluation.verdict == Verdict::TreeCorrect);
}

TEST_CASE("random_solid3: reproducible, bounded, its expression is its solid", "[nhrep][solid3][random]") {
  csg::RandomSolid3Settings settings;
  for (std::uint64_t i = 0; i < 4; ++i) {
    settings.hollow = i % 2 == 1;
    const csg::RandomSolid3 r = csg::random_solid3(settings, 7, i);
    const csg::RandomSolid3 again = csg::random_solid3(settings, 7, i);
    CHECK(csg::to_text(*r.expression, r.arranged.complex.halfspace_names) ==
          csg::to_text(*again.expression, again.arranged.complex.halfspace_names));
    CHECK(r.solid == again.solid);
    CHECK((!r.hollowed || settings.hollow));
    if (r.status == csg::SolidStatus::Bounded) CHECK(csg::evaluate(*r.expression, r.arranged.complex) == r.solid);
  }
  settings.segments = 5;
  CHECK_THROWS_AS(csg::random_solid3(settings, 1, 0), std::invalid_argument);
}

TEST_CASE("3D survey pipeline on random solids: structural checks and Claim 5.1 hold", "[nhrep][solid3][random]") {
  // 12 solids of seed 3, plain and hollow: every check holds, a correct tree is never on a non-describable solid,
  // and a cavity left whole makes the tree fail unless nested.
  csg::RandomSolid3Settings settings;
  BuildOptions nested;
  nested.nest_holes = true;
  int bounded = 0;
  for (std::uint64_t i = 0; i < 12; ++i) {
    settings.hollow = i % 2 == 1;
    const csg::RandomSolid3 r = csg::random_solid3(settings, 3, i);
    if (r.status != csg::SolidStatus::Bounded) continue;
    ++bounded;
    SurveySolid3 c;
    c.scene = r.scene;
    c.arranged = r.arranged;
    c.solid = r.solid;
    const SurveyOutcome o = survey_solid3(c);
    INFO("solid " << i << ": " << csg::to_text(*r.expression, r.arranged.complex.halfspace_names));
    CHECK(o.problems.empty());
    REQUIRE(o.whole.evaluated);
    CHECK((!o.whole.eval.correct || o.whole.eval.describable));
    CHECK(check_boundary(o.whole.built.graph.surface).empty());
    if (o.holes > 0) CHECK_FALSE(o.whole.eval.correct);  // Section 5.2 unites the cavity's boundary
    const SurveyOutcome n = survey_solid3(c, nested);
    CHECK(n.problems.empty());
  }
  CHECK(bounded >= 8);
}
