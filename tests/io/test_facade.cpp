// The front door (<hsx/hsx.hpp>) on the bundled scenes: each call agrees with the layer functions it stands for,
// and bad input is an InputError.
#include <hsx/hsx.hpp>
#include <hsx/algorithms/csg/solid_tree.hpp>
#include <hsx/io/csg_text.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace hsx;

namespace {
std::string scene_path(const std::string& name) { return std::string(HSX_SOURCE_DIR) + "/data/scenes/" + name; }
}  // namespace

TEST_CASE("facade: extract_shape is bsh::extract on the complex", "[facade]") {
  for (const char* name : {"lens.json", "concurrent.json", "tangencies.json"}) {
    const LoadedInput in = load_input(scene_path(name));
    bsh::ExtractOptions options;
    options.method = bsh::Method::BestFirst;
    const bsh::ExtractResult a = extract_shape(in.complex(), options);
    const bsh::Problem problem(in.complex());
    const bsh::ExtractResult b = bsh::extract(problem, options);
    CHECK(a.labelling == b.labelling);
    CHECK(compare(a.energy, b.energy) == Order::Equal);
    // The optimum grades optimal; the empty shape does not unless it is optimal itself.
    const bsh::Grade g = grade_labelling(in.complex(), a.labelling);
    CHECK(g.optimal() == a.optimal);
    const bsh::Grade empty = grade_labelling(in.complex(), bsh::Labelling(in.complex().cells.size(), 0));
    CHECK(empty.orientation_preserving);
    CHECK((empty.optimal() == (compare(empty.energy, a.energy) == Order::Equal)));
  }
  const LoadedInput in = load_input(scene_path("lens.json"));
  CHECK_THROWS_AS(grade_labelling(in.complex(), bsh::Labelling(3, 0)), InputError);
}

TEST_CASE("facade: CSG solids, BHC trees and NH-Rep trees", "[facade]") {
  const LoadedInput in = load_input(scene_path("lens.json"));
  const Complex& c = in.complex();
  const std::vector<char> solid = solid_from_csg(c, "(A | B) & ~C");
  CHECK(solid == csg::evaluate(*parse_csg_text("(A | B) & ~C", c.halfspace_names), c));
  CHECK(std::count(solid.begin(), solid.end(), 1) > 0);
  CHECK_THROWS_AS(solid_from_csg(c, "A & nosuchname"), InputError);

  const csg::BhcResult tree = csg_tree(in, solid);
  REQUIRE(tree.describable);
  CHECK(tree.verified);
  CHECK(csg::evaluate(*tree.tree, c) == solid);

  const nhrep::BuildResult nh = nhrep_tree(*in.arranged, solid);
  CHECK(nhrep::check_tree(nh).empty());
  CHECK_THROWS_AS(nhrep_tree(*in.arranged, std::vector<char>(c.cells.size() + 1, 0)), InputError);
}

TEST_CASE("facade: csg_tree prefers planes in 3D, as hsx csg (csg::build_tree) does", "[facade][csg3]") {
  const LoadedInput in = load_input(std::string(HSX_SOURCE_DIR) + "/data/scenes3d/bhc_bracket.json");
  REQUIRE(in.scene3);
  const Complex& c = in.complex();
  const std::vector<char> solid = solid_from_csg(
      c, "X0 & Y0 & Y1 & Z0 & ((X1 & Z1 & Ch1) | (U1 & Z2 & Ch2) | (G0 & G1 & Gd) | Boss) & ~H1 & ~H2 & ~H3 & "
         "~(S0 & S1 & Sz)");
  const csg::BhcResult tree = csg_tree(in, solid);
  REQUIRE(tree.describable);
  CHECK(tree.verified);
  const csg::SolidTree cli = csg::build_tree(*in.scene3, *in.arranged3, solid, csg::SolidTreeOptions{});
  REQUIRE(cli.has_verified_tree());
  CHECK(csg::to_text(*tree.tree, c.halfspace_names) == csg::to_text(*cli.bhc.tree, c.halfspace_names));


  // A sphere S, a plane P and a box B: inside B, S xor P needs a partition where S and P split as many faces, so
  // the preference decides: P (planar) first, where plain BHC would take S (the lower index).
  const LoadedInput xor_in = load_input_text(
      R"({"format": "hsx-scene/1", "dimension": 3, "domain": {"min": [-4, -4, -4], "max": [4, 4, 4]},
          "halfspaces": [{"name": "S", "kind": "sphere", "center": [0, 0, 0], "radius": 2,
                          "tessellation": {"segments": 8}},
                         {"name": "P", "kind": "plane", "normal": [0, 0, 1], "offset": 0},
                         {"name": "B", "kind": "box", "min": [-3, -3, -3], "max": [3, 3, 3]}]})",
      "xor.json");
  const Complex& xc = xor_in.complex();
  const std::vector<char> xor_solid = solid_from_csg(xc, "B & (S & ~P | ~S & P)");
  const csg::BhcResult xor_tree = csg_tree(xor_in, xor_solid);
  REQUIRE(xor_tree.describable);
  CHECK(xor_tree.verified);
  CHECK(csg::to_text(*xor_tree.tree, xc.halfspace_names) == "B & (P & ~S | ~P & S)");
  const csg::SolidTree xor_cli = csg::build_tree(*xor_in.scene3, *xor_in.arranged3, xor_solid, csg::SolidTreeOptions{});
  CHECK(csg::to_text(*xor_cli.bhc.tree, xc.halfspace_names) == "B & (P & ~S | ~P & S)");
  const csg::BhcResult plain = csg::bhc(xc, xor_solid);  // no preference: S first
  REQUIRE(plain.describable);
  CHECK(csg::to_text(*plain.tree, xc.halfspace_names) == "B & (S & ~P | ~S & P)");
}

TEST_CASE("facade: NH-Rep tree of a bundled mesh", "[facade]") {
  const std::string dir = std::string(HSX_SOURCE_DIR) + "/data/meshes/";
  const nhrep::BuildResult r = nhrep_tree_of_mesh(dir + "lprism.obj", dir + "lprism_open_corner.fea");
  CHECK(nhrep::check_tree(r).empty());
  CHECK(r.graph.live_patches().size() >= 2);
  CHECK_THROWS_AS(nhrep_tree_of_mesh(dir + "no-such.obj", dir + "lprism_open_corner.fea"), InputError);
}

TEST_CASE("facade: the JSON writers round-trip through the readers", "[facade]") {
  const LoadedInput in = load_input(scene_path("lens.json"));
  const std::string complex_text = complex_json_text(in);
  const Complex back = complex_from_json(nlohmann::json::parse(complex_text));
  CHECK(back.cells.size() == in.complex().cells.size());
  CHECK(back.patches.size() == in.complex().patches.size());
  const bsh::ExtractResult shape = extract_shape(in.complex());
  const std::string result_text = result_json_text(in.complex(), shape, in.pieces());
  CHECK(read_result_labelling(nlohmann::json::parse(result_text), in.complex()) == shape.labelling);
  // The result carries its input's identity: the complex read back from JSON has the same, another scene not.
  CHECK(complex_identity(back) == complex_identity(in.complex()));
  CHECK(read_result_labelling(nlohmann::json::parse(result_text), back) == shape.labelling);
  const LoadedInput other = load_input(scene_path("star.json"));
  CHECK_THROWS_WITH(read_result_labelling(nlohmann::json::parse(result_text), other.complex()),
                    Catch::Contains("computed from another scene or complex"));
  nlohmann::json anonymous = nlohmann::json::parse(result_text);
  anonymous.erase("complex_id");
  CHECK_THROWS_WITH(read_result_labelling(anonymous, in.complex()), Catch::Contains("complex_id: missing"));
  CHECK(result_text == result_json_text(in.complex(), shape, in.pieces()));  // no seconds: reproducible bytes
}
