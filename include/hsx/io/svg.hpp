// SVG pictures of a 2D arrangement and its complex, in the style of the BSH paper's figures: soft grey cells,
// patches coloured per halfspace, samples as dots with a tick along the outward normal of their halfspace, and a
// legend.
//
// Conventions:
// - Coordinates are converted with to_double (a picture, not a proof); y points up in the scene and down in SVG,
//   so y is flipped. Which way an arc turns and whether it spans more than half its circle are decided exactly.
// - Output is deterministic: fixed drawing order and numbers printed with 4 decimals.
// - Element classes, for styling and tests: "cell", "domain", "highlight", "patch", "boundary", "tick", "sample",
//   "missing", "cell-id", "patch-id", "legend", "title". One "patch" path per patch and one "sample" circle per
//   sample.
// - Cell shading (the legend says which applies): without `cell_fill`, a cell is darker when an odd number of
//   halfspaces contain it and lighter when an even number (none included) do; outer cells (touching the domain
//   box) are paler still. With `cell_fill`, filled cells are blue ("inside the shape") and the others near white.
// - With `cell_fill` (and `shape_boundary`), the shape's boundary is drawn bold: one "boundary" path per support
//   (group of coincident patches, complex/complex.hpp) whose two cells are filled differently. A sample is
//   "missing" (algorithms/bsh/problem.hpp) unless its patch's inside cell is filled and its outside cell is not;
//   each missing sample gets a red "missing" ring.
// - Labels: "c<k>" is cell k and "p<k>" patch k, the indices of the complex (the ids of `hsx arrange`'s text and
//   of hsx-complex/1 JSON). A cell's label is centred on its witness point, a patch's on a point of the patch:
//   text-anchor middle, baseline 0.35 em below the point. Font sizes grow with `width` (12 px legend text at
//   800 px), labels carry a white halo.
// - The legend wraps: entries are laid out in as many equal columns as fit the picture's width, an entry wider
//   than the picture is wrapped onto several lines, and no two lines of legend text overlap when the text is no
//   wider than svg_text_width says.
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
  /// with cell_fill: draw the shape's boundary bold and ring the missing samples (see the conventions above)
  bool shape_boundary = true;
  bool show_cell_ids = false;            ///< label every cell "c<k>" at its witness point
  bool show_patch_ids = false;           ///< label every patch "p<k>" at a point of it
  /// optional, per cell: 1 = an inside cell of a mixed term (drawn orange), 2 = an outside cell of a mixed term
  /// (drawn red); overrides cell_fill (describability witnesses)
  std::vector<char> cell_marks;
  std::vector<char> highlight_patches;   ///< optional, per patch: 1 = highlighted (e.g. removed patches)
  std::string highlight_legend = "highlighted patches";  ///< what the highlight means, for the legend
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
/// Per sample of `complex`: 1 when it is missing from the shape whose cells are filled in `fill` (per cell, 1 =
/// inside): unless its patch's inside cell is filled and its outside cell is not (see the conventions above).
std::vector<char> svg_missing_samples(const Complex& complex, const std::vector<char>& fill);
/// Complete pictures (SVG documents as the functions here and in io/svg3.hpp write them: an optional XML
/// declaration, then one root <svg> with width and height in px) laid out in a grid of `columns` (>= 1) columns,
/// row by row, as one document: each picture is nested as an <svg> element at its own size, rows as tall as their
/// tallest picture, 8 px apart, on white. Throws std::invalid_argument when a picture has no such root.
std::string svg_grid(const std::vector<std::string>& pictures, int columns);
/// XML text escaping.
std::string svg_escape(const std::string& text);
/// An upper estimate, in px, of the width of `text` (UTF-8) drawn at `font_size` px in the pictures' sans-serif
/// font: Helvetica/Arial advance widths plus 15% (DejaVu Sans, the usual fallback, is about 14% wider); a
/// non-ASCII character counts as 1.15 em. Used to lay out legends; not a font metric to rely on elsewhere.
double svg_text_width(const std::string& text, double font_size);
/// Path commands (" L x y" or " A ...") continuing from `from` along arrangement edge `edge` to `to`, two points of
/// the edge in walk order (either may be an interior point of it); `travel_ccw` tells whether that walk turns
/// counter-clockwise (arcs only). Whether an arc spans more than half its circle is decided exactly.
std::string svg_edge_commands(const SvgView& view, const ArrEdge2& edge, const OneRootPoint& from,
                              const OneRootPoint& to, bool travel_ccw);

}  // namespace hsx
