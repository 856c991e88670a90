// SVG and PNG (raster) pictures of a 3D arrangement without a GUI: a few orthographic views side by side, the boundary triangles
// shaded by their halfspace's colour and lit by their normal, painted back to front.
//
// Conventions (owned here):
// - A view looks along `direction` (from the viewer into the scene) with `up` pointing up on screen; screen right
//   is direction x up. The default views (z is up): "front" looks along +y, "side" along -x, "top" along -z (y up on
//   screen), "isometric" along (-1, 1, -1). Views are laid out two per row (a single view takes the whole width),
//   each fitted to the domain box's outline with one scale for all views.
// - What is drawn, per view: every arrangement triangle that is not on the domain box and not seen edge-on (its
//   exact normal (v1-v0)x(v2-v0) is not orthogonal to `direction`, decided exactly): one "face" polygon each, in
//   a "view" group. Nothing else is a polygon. Faces are painted back to front by the depth of their centroid
//   along `direction` (ties by triangle index), filled with the colour of the triangle's first halfspace times a
//   light factor 0.35 + 0.65 |n . l| (n the unit normal, l a fixed light direction leaning from the viewer to the
//   upper left), with `opacity`, so that hidden parts show through. Coordinates and shading are doubles (a
//   picture, not a proof); the choice of triangles is exact.
// - A shape (`cell_fill` set, one entry per cell, 1 inside): instead of every triangle, only the shape's boundary
//   is drawn: the triangles of io/mesh_export.hpp's shape_faces, each a "face" polygon in the colour of its
//   patch's halfspace (the one whose orientation it has). Missing samples (a sample is missing unless its patch's
//   inside cell is filled and its outside cell is not, as in io/svg.hpp) get a red "missing" ring.
// - `highlight_patches` (per patch, 1 = highlighted; e.g. the patches a search removed): every triangle of such a
//   patch is also a "highlight" polygon, amber, painted after all the faces (back to front among themselves, in a
//   second "view" group per view, present when some patch is highlighted) so that they show even inside the shape; the legend says what they are
//   (`highlight_legend`). `cell_marks` (per cell, 1 or 2) draws the patches bounding marked cells the same way, in
//   orange (1) or red (2), in the same second group; a shape's faces are then grey (#b4b4b4), not in their
//   halfspaces' colours, which include orange and red.
// - Drawn on top of the faces, in this order: the domain box's twelve edges ("domain" lines), the samples ("sample"
//   circles in their halfspace's colour, visible through everything), and on request the labels: "c<k>" at cell
//   k's interior point ("cell-id"), "p<k>" at the centroid of patch k's largest triangle ("patch-id"), the ids of
//   the complex (hsx arrange's text and hsx-complex/1). Under the views, a legend of the halfspaces and, for a
//   shape, of the marks ("legend").
// - Output is deterministic: fixed drawing order, numbers with 4 decimals (io/svg.hpp's svg_number).
// - Raster pictures (arrangement_raster3, states_raster3; `hsx extract --png`): the same views, layout, triangles,
//   colours, samples and missing-sample rings, without text (no caption, title, label or legend: the SVG has
//   them; the views keep their places). Each view is drawn with a z-buffer instead of painting back to front:
//   a pixel is covered by a triangle when its centre is inside or on the projected triangle (edge functions in
//   doubles), and takes the nearest covering face's colour (depth interpolated across the triangle; on equal
//   depths the first face in the SVG's drawing order wins), opaque: the fill colour of the SVG's polygon. The
//   highlighted and marked patches get a second z-buffer of their own and are blended over the result with
//   `opacity`. Then the domain box's edges (1 px, dashed 4 on 3 off), the samples (discs of radius 4 px with a
//   black rim) and the missing-sample rings (radius 7 to 9 px, red). Single-threaded and in a fixed order, so
//   the same input gives the same pixels on every run (the coverage decisions use doubles: a picture, not a
//   proof).
#pragma once

#include <hsx/io/png.hpp>

#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/geometry/scene3.hpp>

#include <string>
#include <vector>

namespace hsx {

struct SvgView3 {
  std::string name;   ///< shown above the view
  PointQ3 direction;  ///< the viewing direction, into the scene; non-zero
  PointQ3 up;         ///< up on screen; not parallel to direction
};

/// front, side, top, isometric (see the conventions).
std::vector<SvgView3> default_svg_views3();

struct Svg3Options {
  int width = 1000;                ///< total picture width in px (>= 200); each view is half of it, square
  std::vector<SvgView3> views;     ///< empty: default_svg_views3()
  double opacity = 0.85;           ///< fill opacity of the faces, in (0, 1]
  bool show_cell_ids = false;      ///< label every cell "c<k>"
  bool show_patch_ids = false;     ///< label every patch "p<k>"
  std::vector<char> cell_fill;     ///< optional, per cell: 1 = inside a shape; set: draw the shape (see above)
  std::vector<char> highlight_patches;                   ///< optional, per patch: 1 = highlighted
  std::string highlight_legend = "highlighted patches";  ///< what the highlight means, for the legend
  /// Optional, per cell: 0 unmarked, 1 or 2 marked (e.g. the inside and outside cells of mixed terms). Every patch
  /// bounding a marked cell is drawn over the faces like a highlight, orange for mark 1 and red for mark 2 (the
  /// colours of io/svg.hpp's cell_marks), in the mark of its inside cell when that is marked, else of its outside
  /// cell; classes "mark-inside" and "mark-outside". The legend says what they are (`mark_legend`).
  std::vector<char> cell_marks;
  std::string mark_legend[2] = {"inside cells of mixed terms", "outside cells of mixed terms"};
  std::string title;
};

/// The picture. `arranged` must have been built from `scene` (same halfspaces and samples). Throws
/// std::invalid_argument when they do not fit together, the options break the bounds above, or `cell_fill` (when
/// set), `highlight_patches` or `cell_marks` (when set) does not have one entry per cell or patch, or a cell mark is
/// not 0, 1 or 2.
std::string arrangement_svg3(const Scene3& scene, const Arranged3& arranged, const Svg3Options& options = {});

/// One panel of states_svg3: a shape, the patches to highlight over it, a title.
struct Svg3State {
  std::vector<char> cell_fill;          ///< per cell, 1 = inside the shape
  std::vector<char> highlight_patches;  ///< per patch (1 = highlighted), or empty
  std::string title;
};

/// Several shapes of one arrangement (e.g. the states of a search, BSH Fig. 10), `columns` panels per row, each a
/// nested <svg> drawn as arrangement_svg3 draws a shape with `options` and the state's cell_fill,
/// highlight_patches and title, but compact, so that dozens of states of a large complex stay small:
/// - Each patch on some state's boundary is drawn once per view, in a shared <defs> group (id "v<view>p<patch>";
///   "v<view>h<patch>" for its highlight in amber; "v<view>d" for the domain box, the samples and the labels):
///   its visible triangles back to front, consecutive triangles of one fill merged into one <path> (subpaths
///   "Mx yLx yLx yZ"), coordinates rounded to 0.1 px. A panel refers to them with <use> elements (class "face" or
///   "highlight", data-patch = the patch), painted back to front by the mean depth of each patch's triangle
///   centroids (a patch at a time, not a triangle at a time as in arrangement_svg3); its title, captions, missing
///   sample rings and legend are its own.
/// Throws std::invalid_argument as arrangement_svg3 does for each state, when `states` is empty, a state has no
/// cell_fill, `columns` < 1, or `options` sets cell_fill, highlight_patches, cell_marks or title (the states do).
std::string states_svg3(const Scene3& scene, const Arranged3& arranged, const std::vector<Svg3State>& states,
                        const Svg3Options& options, int columns);

/// The raster picture of arrangement_svg3 with the same arguments (see the conventions' "Raster pictures"):
/// options.width px wide, as high as the views (the SVG's height without its title and legend). Throws as
/// arrangement_svg3 does.
RgbImage arrangement_raster3(const Scene3& scene, const Arranged3& arranged, const Svg3Options& options = {});

/// The raster picture of states_svg3 with the same arguments: each state drawn as arrangement_raster3 draws it with
/// `options` and the state's cell_fill and highlight_patches (the titles are not drawn), the panels in a grid of
/// `columns` per row, 8 px apart, each framed by a 1 px grey line. Throws as states_svg3 does.
RgbImage states_raster3(const Scene3& scene, const Arranged3& arranged, const std::vector<Svg3State>& states,
                        const Svg3Options& options, int columns);

/// How many "face" polygons view `view` of arrangement_svg3 draws: the triangles not on the box and not seen
/// edge-on (exact). For tests and reports.
std::size_t svg3_visible_triangles(const Arrangement3& arrangement, const SvgView3& view);

}  // namespace hsx
