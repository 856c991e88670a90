// SVG pictures of a 2D arrangement and its complex, in the style of the BSH paper's figures: soft grey cells,
// patches coloured per halfspace, samples as dots with a tick along the outward normal of their halfspace, and a
// legend.
//
// Conventions:
// - Coordinates are converted with to_double (a picture, not a proof); y points up in the scene and down in SVG,
//   so y is flipped. Which way an arc turns and whether it spans more than half its circle are decided exactly.
// - Output is deterministic: fixed drawing order and numbers printed with 4 decimals.
// - Element classes, for styling and tests: "cell", "domain", "highlight", "patch", "tick", "sample",
//   "cell-id", "patch-id", "legend", "title". One "patch" path per patch and one "sample" circle per sample.
#pragma once

#include <hsx/complex/complex.hpp>
#include <hsx/geometry/arrangement2.hpp>
#include <hsx/geometry/scene.hpp>

#include <string>
#include <vector>

namespace hsx {

struct SvgOptions {
  int width = 800;                       ///< total picture width in px (the height follows the domain's aspect)
  std::vector<char> cell_fill;           ///< optional, per cell: 1 = filled (inside a shape); empty: grey shading
  bool show_cell_ids = false;
  bool show_patch_ids = false;
  /// optional, per cell: 1 = an inside cell of a mixed term (drawn orange), 2 = an outside cell of a mixed term
  /// (drawn red); overrides cell_fill (describability witnesses)
  std::vector<char> cell_marks;
  std::vector<char> highlight_patches;   ///< optional, per patch: 1 = highlighted (e.g. removed patches)
  std::string title;
};

/// The picture. `complex` must have been built from `arrangement` (cells are its faces, Patch::pieces its edges),
/// and `arrangement` from `scene`. Throws std::invalid_argument when they do not fit together.
std::string arrangement_svg(const Scene2& scene, const Arrangement2& arrangement, const Complex& complex,
                            const SvgOptions& options = {});

// ---- building blocks shared with other pictures of arrangements (io/nhrep_svg.cpp), same style as above ----

/// Scene to picture coordinates: x from min_x, y flipped from max_y, uniform scale, then offset by (left, top).
struct SvgView {
  double min_x = 0, max_y = 0, scale = 1, left = 0, top = 0;
};
/// The halfspace palette, cycled by index (negative indices wrap too).
const char* svg_palette_colour(int index);
/// A coordinate as printed in pictures: 4 decimals, never "-0.0000".
std::string svg_number(double value);
/// XML text escaping.
std::string svg_escape(const std::string& text);
/// Path commands (" L x y" or " A ...") continuing from `from` along arrangement edge `edge` to `to`, two points of
/// the edge in walk order (either may be an interior point of it); `travel_ccw` tells whether that walk turns
/// counter-clockwise (arcs only). Whether an arc spans more than half its circle is decided exactly.
std::string svg_edge_commands(const SvgView& view, const ArrEdge2& edge, const OneRootPoint& from,
                              const OneRootPoint& to, bool travel_ccw);

}  // namespace hsx
