// SVG picture of a 2D NH-Rep input or result: the solid filled, its boundary pieces coloured by patch (or by the
// tree node / group of the patch), split pieces drawn as the halves they are, feature corners as dots coloured
// by type, and patch ids as labels. Style and coordinates as io/svg.hpp (doubles for drawing only; arc spans and
// split ends decided exactly).
//
// Conventions:
// - A piece is an arrangement edge (BoundaryPiece::origin). A split piece (split_of >= 0) runs from the vertex of
//   its kept link (links[kept_link].origin) to the edge's split point (edge_split_point, planar_corners.hpp).
//   Only one level of splitting can be drawn (what 2D face splitting makes); a piece whose kept link has no
//   vertex is rejected.
// - A feature link is drawn at its vertex (origin), or, for the link between the two halves of a split edge
//   (origin -1), at the split point. Non-feature links are not drawn.
// - Element classes, for styling and tests: "cell" (solid cells only), "edge" (the other arrangement edges, thin
//   grey), "domain", "piece" (one path per live piece, data-patch = its patch), "feature" (one circle per feature
//   link, data-type = convex/concave/smooth), "patch-id", "legend", "title".
// - Output is deterministic.
#pragma once

#include <hsx/complex/boundary.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/geometry/scene.hpp>
#include <hsx/geometry/scene3.hpp>

#include <string>
#include <vector>

namespace hsx {

/// The colour of a feature type in hsx's NH-Rep pictures (SVG and Graphviz), after NH-Rep's Fig. 4: convex red
/// "#e41a1c", concave blue "#377eb8", smooth green "#4daf4a", hybrid purple "#984ea3".
const char* feature_type_colour(FeatureType type);

/// `solid_cells`: per cell, 1 = in the solid. `piece_patch`: per piece of `surface`, its patch id (-1 for retired
/// pieces). `patch_colour_group`: per patch id, the colour index to draw it with (e.g. its tree node); empty:
/// colour by patch id. Throws std::invalid_argument when the inputs do not fit together.
std::string nhrep_svg(const Scene2& scene, const Arranged2& arranged, const std::vector<char>& solid_cells,
                      const BoundarySurface& surface, const std::vector<int>& piece_patch,
                      const std::vector<int>& patch_colour_group, const std::string& title, int width = 800);

/// The 3D picture (a boundary from complex/boundary_from_arrangement3.hpp): the four views of io/svg3.hpp
/// (default_svg_views3: directions and screen axes; one scale for all), each drawing every live piece as a "piece"
/// polygon (data-patch = its patch) filled with the colour of its patch's group (svg_palette_colour) lit by its
/// normal (0.35 + 0.65 |n . l|, the light of io/svg3.hpp), painted back to front by centroid depth (ties by piece
/// id), opacity 0.85; then every feature link as a "feature" line along its arrangement edge, coloured by type
/// (data-type), and "patch-id" labels "P<k> <halfspace>" at the centroid of each patch's lowest piece. The legend
/// gives the feature types' colours and, when `patch_colour_group` is set, the live patches of each colour (one
/// "node-swatch" each, e.g. a tree node's leaves). A piece
/// split by face-splitting is drawn as its sub-triangle (the split triangle's centroid and the kept link's edge);
/// a piece whose kept link is not an arrangement edge (a split of a split) is drawn as its whole triangle. Doubles
/// for drawing only. Arguments as nhrep_svg (`arranged` built from `scene`); throws std::invalid_argument when they
/// do not fit together.
std::string nhrep_svg3(const Scene3& scene, const Arranged3& arranged, const std::vector<char>& solid_cells,
                       const BoundarySurface& surface, const std::vector<int>& piece_patch,
                       const std::vector<int>& patch_colour_group, const std::string& title, int width = 1000);

}  // namespace hsx
