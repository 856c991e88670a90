// Tests of io/nhrep_svg: one path per live piece, one dot per feature link (split edges included), deterministic
// output, rejected inputs.
#include <hsx/complex/boundary.hpp>
#include <hsx/complex/boundary_from_arrangement2.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/nhrep_svg.hpp>
#include <hsx/io/svg.hpp>
#include "support/random_scenes.hpp"

#include <catch2/catch.hpp>

#include <functional>
#include <numeric>
#include <string>
#include <vector>

using namespace hsx;
using namespace hsx::test;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

/// Patches as components of live pieces across non-feature links, numbered by lowest piece.
std::vector<int> patches_of(const BoundarySurface& s) {
  std::vector<int> parent(s.pieces.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
  for (const BoundaryLink& l : s.links)
    if (!l.feature) parent[find(l.piece_a)] = find(l.piece_b);
  std::vector<int> id_of_root(s.pieces.size(), -1), patch(s.pieces.size(), -1);
  int next = 0;
  for (std::size_t p = 0; p < s.pieces.size(); ++p) {
    if (s.pieces[p].retired) continue;
    int& id = id_of_root[find(static_cast<int>(p))];
    if (id < 0) id = next++;
    patch[p] = id;
  }
  return patch;
}

int live_pieces(const BoundarySurface& s) {
  int n = 0;
  for (const BoundaryPiece& p : s.pieces) n += p.retired ? 0 : 1;
  return n;
}

int feature_links(const BoundarySurface& s) {
  int n = 0;
  for (const BoundaryLink& l : s.links) n += l.feature ? 1 : 0;
  return n;
}

}  // namespace

TEST_CASE("nhrep_svg draws every live piece and every feature link", "[nhrep_svg]") {
  // A disk minus a rectangle: convex, concave and (arc split points) non-feature corners, arcs and segments.
  const Scene2 scene = make_scene(Box2{pt(-4, -4), pt(6, 4)},
                                  {disk("D", pt(0, 0), 3), polygon("R", {pt(1, -1), pt(5, -1), pt(5, 1), pt(1, 1)})});
  const Arranged2 a = arrange(scene);
  std::vector<char> solid;
  for (const Cell& c : a.complex.cells) solid.push_back(!c.outer && c.inside[0] && !c.inside[1]);
  BoundarySurface surface = boundary_from_arrangement2(a, solid);
  REQUIRE(feature_links(surface) == 2);

  const std::string svg = nhrep_svg(scene, a, solid, surface, patches_of(surface), {}, "disk minus <R>");
  CHECK(count(svg, "class=\"piece\"") == static_cast<std::size_t>(live_pieces(surface)));
  CHECK(count(svg, "class=\"feature\"") == 2u);
  CHECK(count(svg, "data-type=\"convex\"") == 2u);
  CHECK(count(svg, "class=\"patch-id\"") == 2u);
  CHECK(svg.find("disk minus &lt;R&gt;") != std::string::npos);
  CHECK(svg == nhrep_svg(scene, a, solid, surface, patches_of(surface), {}, "disk minus <R>"));

  // Split the piece from (1,1) to (1,-1) and make the link between its halves a smooth feature (as patch
  // decomposition does): one more path, one more dot, at the split point (1, 0).
  int inner = -1;
  for (std::size_t p = 0; p < surface.pieces.size(); ++p)
    if (surface.pieces[p].carrier == 1 && a.arrangement.edges()[surface.pieces[p].origin].line_b == 0) inner = p;
  REQUIRE(inner >= 0);
  const std::vector<int> halves = split_piece(surface, inner);
  REQUIRE(halves.size() == 2u);
  const int middle = surface.pieces[halves[0]].links.back();
  surface.links[middle].feature = true;
  surface.links[middle].type = FeatureType::Smooth;
  const std::vector<int> patches = patches_of(surface);
  std::vector<int> groups(patches.size() + 4, 0);  // every patch in colour group 0
  const std::string split_svg = nhrep_svg(scene, a, solid, surface, patches, groups, "");
  CHECK(count(split_svg, "class=\"piece\"") == static_cast<std::size_t>(live_pieces(surface)));
  CHECK(count(split_svg, "class=\"piece\"") == count(svg, "class=\"piece\"") + 1);
  CHECK(count(split_svg, "class=\"feature\"") == 3u);
  CHECK(count(split_svg, "data-type=\"smooth\"") == 1u);
  // One colour group: every piece drawn in the first palette colour.
  CHECK(count(split_svg, "stroke=\"" + std::string(svg_palette_colour(0)) + "\" d=") ==
        static_cast<std::size_t>(live_pieces(surface)));
}

TEST_CASE("nhrep_svg rejects inputs that do not fit together", "[nhrep_svg]") {
  const Scene2 scene = make_scene(Box2{pt(-1, -1), pt(3, 3)}, {polygon("S", {pt(0, 0), pt(2, 0), pt(2, 2), pt(0, 2)})});
  const Arranged2 a = arrange(scene);
  std::vector<char> solid;
  for (const Cell& c : a.complex.cells) solid.push_back(!c.outer && c.inside[0]);
  const BoundarySurface surface = boundary_from_arrangement2(a, solid);
  const std::vector<int> patches = patches_of(surface);
  CHECK_NOTHROW(nhrep_svg(scene, a, solid, surface, patches, {}, ""));
  CHECK_THROWS_AS(nhrep_svg(scene, a, solid, surface, {}, {}, ""), std::invalid_argument);
  CHECK_THROWS_AS(nhrep_svg(scene, a, std::vector<char>{}, surface, patches, {}, ""), std::invalid_argument);
  CHECK_THROWS_AS(nhrep_svg(scene, a, solid, surface, std::vector<int>(patches.size(), -1), {}, ""),
                  std::invalid_argument);
  // A colour group list that misses the patch (patch 3, groups for patch 0 only).
  CHECK_THROWS_AS(nhrep_svg(scene, a, solid, surface, std::vector<int>(patches.size(), 3), {0}, ""),
                  std::invalid_argument);
}
