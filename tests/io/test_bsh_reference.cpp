// The reader of the BSH authors' reference-result.grid and the comparison with our arrangement, on hand-written
// files: a cube [1/4, 3/4]^3 inside the box [-1, 2]^3 (their mesh) against hsx's arrangement of a box halfspace.
#include <hsx/io/bsh_reference.hpp>
#include <hsx/io/input.hpp>

#include <catch2/catch.hpp>

#include <sstream>

using namespace hsx;
using Catch::Matchers::Contains;

namespace {

/// Cube vertices 0..7 (corner i: x = i & 1, y = i & 2, z = i & 4 at 0.25 / 0.75), box corners 8..15.
std::string vertices() {
  std::ostringstream s;
  s << "vert 16 3\n";
  for (int i = 0; i < 8; ++i)
    s << (i & 1 ? "0.75" : "0.25") << " " << (i & 2 ? "0.75" : ".25") << " " << (i & 4 ? "7.5e-1" : "0.25") << "\n";
  for (int i = 0; i < 8; ++i) s << (i & 1 ? "2" : "-1") << " " << (i & 2 ? "2" : "-1") << " " << (i & 4 ? "2" : "-1") << "\n";
  return s.str();
}

/// The 12 triangles of a box with corners offset..offset+7 (outward), z = max ones last but two... in file order.
std::string box_faces(int o) {
  const int t[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                        {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  std::ostringstream s;
  for (const auto& f : t) s << f[0] + o << " " << f[1] + o << " " << f[2] + o << "\n";
  return s.str();
}

/// Faces 0..11 the cube, 12..23 the box; `patches`: the patch_faces section's lines.
std::string grid(const std::string& patches, int patch_count, const std::string& tail) {
  std::ostringstream s;
  s << vertices() << "face 24\n" << box_faces(0) << box_faces(8);
  s << "face_implicit 1\n0 0 0 0 0 0 0 0 0 0 0 0 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1\n";
  s << "patch_faces " << patch_count << "\n" << patches;
  s << "samples 1\n0.25 0.5 0.5\n";
  s << tail;
  return s.str();
}

const char* kOnePatchTail = "block_patches 2\n0\n0\npatch_labels 1\n1\nblock_labels 1\n1 0\n";
const std::string kOnePatch = grid("0 1 2 3 4 5 6 7 8 9 10 11\n", 1, kOnePatchTail);
const char* kTwoPatchTail = "block_patches 2\n0 1\n0 1\nblock_labels 1\n1 0\n";
const std::string kTwoPatches = grid("0 1 4 5 6 7 8 9 10 11\n2 3\n", 2, kTwoPatchTail);

std::string error_of(const std::string& text) {
  try {
    read_bsh_reference(text, "r.grid");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

LoadedInput cube_scene() {
  return load_input_text(R"({"format": "hsx-scene/1", "dimension": 3,
    "domain": {"min": [-1, -1, -1], "max": [2, 2, 2]},
    "halfspaces": [{"name": "B", "kind": "box", "min": [0.25, 0.25, 0.25], "max": [0.75, 0.75, 0.75]}]})",
                         "cube.json");
}

}  // namespace

TEST_CASE("bsh reference: sections are read exactly", "[io][bsh_reference]") {
  const BshReference r = read_bsh_reference(kOnePatch, "r.grid");
  REQUIRE(r.vertices.size() == 16);
  CHECK(r.vertices[7].z == Rational(3, 4));
  CHECK(r.vertices[0].y == Rational(1, 4));
  CHECK(r.faces.size() == 24);
  CHECK(r.face_implicit[12] == -1);
  REQUIRE(r.patch_faces.size() == 1);
  CHECK(r.patch_faces[0].size() == 12);
  CHECK(r.block_patches.size() == 2);
  CHECK(r.patch_blocks[0] == std::array<int, 2>{0, 1});
  CHECK(r.block_labels == std::vector<int>{1, 0});
  CHECK(r.patch_labels == std::vector<int>{1});
  CHECK(r.patch_implicit.empty());
}

TEST_CASE("bsh reference: malformed files name the file, line and section", "[io][bsh_reference]") {
  CHECK_THAT(error_of(""), Contains("section vert: missing"));
  CHECK_THAT(error_of("vert 2 3\n0 0 0\n"), Contains("r.grid:1: section vert: announces 2 lines but the file ends"));
  CHECK_THAT(error_of("vert 1 3\n0 0 x\n"), Contains("r.grid:2: section vert: \"x\""));
  CHECK_THAT(error_of("vert 1 3\n0 0\n"), Contains("expected 3 coordinates"));
  CHECK_THAT(error_of("vert 99999999999 3\n"), Contains("exceeds the limit"));
  CHECK_THAT(error_of("hello\n"), Contains("r.grid:1: expected a section header"));
  CHECK_THAT(error_of("vert 1 3\n0 0 1e99999\n"), Contains("r.grid:2: section vert"));
  // a face id out of range, a face in two patches, a patch in one block, a bad label
  std::string bad = kOnePatch;
  bad.replace(bad.find("\n0 2 3\n"), 7, "\n0 2 30\n");
  CHECK_THAT(error_of(bad), Contains("r.grid:19: section face: 30 is out of range [0, 16)"));
  CHECK_THAT(error_of(grid("0 1 2 3 4 5 6 7 8 9 10 11\n11\n", 2, kTwoPatchTail)),
             Contains("section patch_faces: face 11 is in patches 0 and 1"));
  // a block with no patch is accepted (their files have them), but then patch 0 has one block
  CHECK_THAT(error_of(grid("0 1 2 3 4 5 6 7 8 9 10 11\n", 1, "block_patches 2\n0\n\nblock_labels 1\n1 0\n")),
             Contains("section block_patches: patch 0 is in 1 block(s), not two"));
  CHECK_THAT(error_of(grid("0 1 2 3 4 5 6 7 8 9 10 11\n\n", 2, kTwoPatchTail)),
             Contains("r.grid:47: section patch_faces: entry 1 is empty"));
  CHECK_THAT(error_of(grid("0 1 2 3 4 5 6 7 8 9 10 11\n", 1, "block_patches 2\n0\n0 0\nblock_labels 1\n1 0\n")),
             Contains("patch 0 listed twice"));
  CHECK_THAT(error_of(grid("0 1 2 3 4 5 6 7 8 9 10 11\n", 1, "block_patches 1\n0\nblock_labels 1\n1\n")),
             Contains("patch 0 is in 1 block(s), not two"));
  CHECK_THAT(error_of(grid("0 1 2 3 4 5 6 7 8 9 10 11\n", 1, "block_patches 2\n0\n0\nblock_labels 1\n1 2\n")),
             Contains("section block_labels: 2 is out of range [0, 2)"));
  CHECK_THAT(error_of(grid("0 1 2 3 4 5 6 7 8 9 10 11\n", 1, "block_patches 2\n0\n0\nblock_labels 1\n1\n")),
             Contains("section block_labels: expected 2 entries, found 1"));
  CHECK_THAT(error_of(grid("0 1 2 3 4 5 6 7 8 9 10 11\n", 1, "block_patches 2\n0\n0\n")),
             Contains("section block_labels: missing"));
  CHECK_THAT(error_of(kOnePatch + "vert 0\n"), Contains("section vert: appears twice"));
}

TEST_CASE("bsh reference: small limits refuse large counts", "[io][bsh_reference]") {
  BshReferenceLimits limits;
  limits.max_vertices = 8;
  CHECK_THROWS_WITH(read_bsh_reference(kOnePatch, "r.grid", limits), Contains("too many vertices"));
}

TEST_CASE("bsh reference: a cube maps onto our cube, areas and the defect", "[io][bsh_reference]") {
  const LoadedInput in = cube_scene();
  REQUIRE(in.arranged3);
  REQUIRE(in.complex().cells.size() == 2);
  const int inner = in.complex().cells[0].inside[0] ? 0 : 1;

  const BshReferenceComparison one = compare_bsh_reference(read_bsh_reference(kOnePatch, "r.grid"), *in.arranged3);
  CHECK(one.their_patches == 1);
  CHECK(one.their_blocks == 2);
  CHECK(one.our_patches == 1);
  CHECK(one.our_cells == 2);
  CHECK(one.blocks_without_point == 0);
  CHECK(one.blocks[1].cell == inner);
  CHECK(one.blocks[0].cell == 1 - inner);
  CHECK(one.mapped_labels[inner] == 1);
  CHECK(one.their_area.exact.rational_value() == Rational(3, 2));
  CHECK(one.their_charged.exact.rational_value() == Rational(3, 2));
  REQUIRE(one.our_area_mapped);
  CHECK(one.our_area_mapped->exact.rational_value() == Rational(3, 2));
  CHECK(one.multi_patch_pairs.empty());

  // Two patches between the same two blocks: their graph cut charges each with both, 2 x 3/2.
  const BshReferenceComparison two = compare_bsh_reference(read_bsh_reference(kTwoPatches, "r.grid"), *in.arranged3);
  CHECK(two.their_area.exact.rational_value() == Rational(3, 2));
  CHECK(two.their_charged.exact.rational_value() == Rational(3));
  REQUIRE(two.multi_patch_pairs.size() == 1);
  CHECK(two.multi_patch_pairs[0] == std::array<int, 3>{0, 1, 2});
  CHECK(two.charged_multi_patch_pairs == 1);

  // Our labelling: the cube in agrees on both cells; the empty shape differs on one.
  std::vector<char> ours(2, 0);
  ours[inner] = 1;
  const BshReferenceComparison agree = compare_bsh_reference(read_bsh_reference(kOnePatch, "r.grid"), *in.arranged3, ours);
  CHECK(agree.agreeing_cells == 2);
  CHECK(agree.differing_cells == 0);
  const BshReferenceComparison differ =
      compare_bsh_reference(read_bsh_reference(kOnePatch, "r.grid"), *in.arranged3, std::vector<char>(2, 0));
  CHECK(differ.differing_cells == 1);
  CHECK(differ.our_area->exact.is_zero());
  const auto json = bsh_reference_to_json(one, "cube");
  CHECK(json["format"] == "hsx-bsh-reference/1");
  CHECK(json["theirs"]["boundary_area"]["decimal"] == "1.5");
}

TEST_CASE("bsh reference: a vertex beyond the range of doubles is compared exactly", "[io][bsh_reference]") {
  // The box's corner (2, 2, 2) moved to (10^400, 2, 2): the point outside every vertex is found without doubles.
  std::string text = kOnePatch;
  const std::string corner = "2 2 2\n";
  const std::size_t at = text.rfind(corner, text.find("face 24"));
  REQUIRE(at != std::string::npos);
  text.replace(at, corner.size(), "1e400 2 2\n");
  const LoadedInput in = cube_scene();
  const BshReferenceComparison c = compare_bsh_reference(read_bsh_reference(text, "r.grid"), *in.arranged3);
  CHECK(c.their_blocks == 2);
  CHECK(c.blocks_without_point == 0);
}
