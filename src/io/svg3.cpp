// SVG pictures of 3D arrangements: see svg3.hpp.
#include <hsx/io/svg3.hpp>

#include <hsx/io/mesh_export.hpp>
#include <hsx/io/svg.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace hsx {
namespace {

struct Vec {
  double x = 0, y = 0, z = 0;
};
Vec operator+(const Vec& a, const Vec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator-(const Vec& a, const Vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator*(double k, const Vec& a) { return {k * a.x, k * a.y, k * a.z}; }
double dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(const Vec& a, const Vec& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec unit(const Vec& a) {
  const double n = std::sqrt(dot(a, a));
  return n > 0 && std::isfinite(n) ? (1 / n) * a : Vec{};
}
Vec to_vec(const PointQ3& p) { return {p.x.get_d(), p.y.get_d(), p.z.get_d()}; }

PointQ3 exact_normal(const Arrangement3& arr, const ArrTriangle3& t) {
  const PointQ3& a = arr.vertices()[t.vertices[0]];
  const PointQ3& b = arr.vertices()[t.vertices[1]];
  const PointQ3& c = arr.vertices()[t.vertices[2]];
  const Rational ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  return {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
}

bool seen(const Arrangement3& arr, const ArrTriangle3& t, const PointQ3& direction) {
  if (t.on_box) return false;
  const PointQ3 n = exact_normal(arr, t);
  return n.x * direction.x + n.y * direction.y + n.z * direction.z != 0;
}

/// One view's projection: screen right, screen up and depth (along the viewing direction) as unit vectors.
struct Projection {
  Vec right, up, depth, light;
  double scale = 1, centre_x = 0, centre_y = 0;  // screen = centre + scale * (p - mid) . (right, -up)
  Vec mid;
  double X(const Vec& p) const { return centre_x + scale * dot(p - mid, right); }
  double Y(const Vec& p) const { return centre_y - scale * dot(p - mid, up); }
  std::string xy(const Vec& p) const { return svg_number(X(p)) + "," + svg_number(Y(p)); }
};

Projection projection_of(const SvgView3& view) {
  const Vec d = to_vec(view.direction), u = to_vec(view.up);
  Projection p;
  p.depth = unit(d);
  p.right = unit(cross(d, u));
  p.up = unit(cross(p.right, p.depth));
  p.light = unit(-1.0 * p.depth + 0.5 * p.up - 0.4 * p.right);
  return p;
}

std::array<Vec, 8> corners_of(const Box3& box) {
  std::array<Vec, 8> c;
  const Vec lo = to_vec(box.min), hi = to_vec(box.max);
  for (int k = 0; k < 8; ++k) c[k] = {(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z};
  return c;
}

/// The largest extent of the domain's outline on screen, in scene units (scale 1).
double outline_extent(const Projection& p, const Box3& box) {
  double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
  for (const Vec& c : corners_of(box)) {
    lo_x = std::min(lo_x, dot(c, p.right));
    hi_x = std::max(hi_x, dot(c, p.right));
    lo_y = std::min(lo_y, dot(c, p.up));
    hi_y = std::max(hi_y, dot(c, p.up));
  }
  return std::max(hi_x - lo_x, hi_y - lo_y);
}

struct Rgb {
  double r = 0, g = 0, b = 0;
};

Rgb parse_colour(const char* hex) {  // "#rrggbb"
  unsigned r = 0, g = 0, b = 0;
  std::sscanf(hex, "#%02x%02x%02x", &r, &g, &b);
  return {r / 255.0, g / 255.0, b / 255.0};
}

/// `c` times `factor`, clamped, as 8-bit channels (the colours of both the SVG and the raster pictures).
std::array<std::uint8_t, 3> shade(const Rgb& c, double factor) {
  auto channel = [&](double v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v * factor, 0.0, 1.0) * 255));
  };
  return {channel(c.r), channel(c.g), channel(c.b)};
}

std::string colour_text(const Rgb& c, double factor) {
  const auto rgb = shade(c, factor);
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return buffer;
}

struct Fonts {
  double caption, legend, label;
  explicit Fonts(double width) {
    const double k = width / 1000;
    caption = std::max(10.0, 14 * k);
    legend = std::max(9.0, 12 * k);
    label = std::max(8.0, 11 * k);
  }
};

void check_fit(const Scene3& scene, const Arranged3& a, const Svg3Options& o) {
  const int n = static_cast<int>(scene.halfspaces.size());
  if (a.arrangement.halfspace_count() != n || a.complex.halfspace_count() != n ||
      a.arrangement.cells().size() != a.complex.cells.size() ||
      a.arrangement.sample_triangles().size() != scene.samples.size())
    throw std::invalid_argument("arrangement_svg3: the arrangement was not built from this scene");
  if (o.width < 200) throw std::invalid_argument("arrangement_svg3: width below 200 px");
  if (!(o.opacity > 0 && o.opacity <= 1)) throw std::invalid_argument("arrangement_svg3: opacity not in (0, 1]");
  if (!o.cell_fill.empty() && o.cell_fill.size() != a.complex.cells.size())
    throw std::invalid_argument("arrangement_svg3: cell_fill needs one entry per cell");
  if (!o.highlight_patches.empty() && o.highlight_patches.size() != a.complex.patches.size())
    throw std::invalid_argument("arrangement_svg3: highlight_patches needs one entry per patch");
  if (!o.cell_marks.empty() && o.cell_marks.size() != a.complex.cells.size())
    throw std::invalid_argument("arrangement_svg3: cell_marks needs one entry per cell");
  for (char m : o.cell_marks)
    if (m < 0 || m > 2) throw std::invalid_argument("arrangement_svg3: a cell mark is not 0, 1 or 2");
  for (const SvgView3& v : o.views) {
    const PointQ3& d = v.direction;
    const PointQ3& u = v.up;
    const bool parallel = d.y * u.z == d.z * u.y && d.z * u.x == d.x * u.z && d.x * u.y == d.y * u.x;
    if ((d.x == 0 && d.y == 0 && d.z == 0) || parallel)
      throw std::invalid_argument("arrangement_svg3: view \"" + v.name +
                                  "\" has a zero direction or an up parallel to it");
  }
}

/// A triangle to paint: its arrangement id, the halfspace whose colour it takes (-1: grey), and its class.
struct Paint {
  int triangle = -1;
  int halfspace = -1;
  int overlay = 0;  // 0: a face; drawn over the faces: 1 a highlighted patch, 2 / 3 a patch of a marked cell (1 / 2)
  int patch = -1;  // shapes: the face's patch (data-patch), -1: not written
};

/// Per patch, the mark it is drawn with: its inside cell's mark when set, else its outside cell's (0: none).
std::vector<char> patch_marks(const Complex& c, const std::vector<char>& cell_marks) {
  std::vector<char> out(c.patches.size(), 0);
  if (cell_marks.empty()) return out;
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    const char in = cell_marks[static_cast<std::size_t>(c.patches[p].inside_cell)];
    out[p] = in ? in : cell_marks[static_cast<std::size_t>(c.patches[p].outside_cell)];
  }
  return out;
}

/// Whether some cell is marked: the shape's boundary is then grey, so that the marks (orange, red) are not taken
/// for halfspaces of those colours.
bool any_mark(const Svg3Options& o) {
  return std::any_of(o.cell_marks.begin(), o.cell_marks.end(), [](char m) { return m != 0; });
}

/// What a picture paints (see the conventions): every triangle, or a shape's boundary, then highlighted patches.
std::vector<Paint> paints_of(const Arranged3& a, const Svg3Options& o) {
  std::vector<Paint> paints;
  const auto& triangles = a.arrangement.triangles();
  if (o.cell_fill.empty()) {
    for (std::size_t k = 0; k < triangles.size(); ++k)
      paints.push_back({static_cast<int>(k), triangles[k].halfspaces.empty() ? -1 : triangles[k].halfspaces.front(),
                        0, -1});
  } else {
    const bool grey = any_mark(o);
    for (const ExportedFace& f : shape_faces(a, o.cell_fill))
      paints.push_back({f.triangle, grey ? -1 : f.halfspace, 0, f.patch});
  }
  for (std::size_t p = 0; p < o.highlight_patches.size(); ++p)
    if (o.highlight_patches[p])
      for (int t : a.complex.patches[p].pieces)
        paints.push_back({t, a.complex.patches[p].halfspace, 1, static_cast<int>(p)});
  const std::vector<char> marks = patch_marks(a.complex, o.cell_marks);
  for (std::size_t p = 0; p < marks.size(); ++p)
    if (marks[p])
      for (int t : a.complex.patches[p].pieces)
        paints.push_back({t, a.complex.patches[p].halfspace, 1 + marks[p], static_cast<int>(p)});
  return paints;
}

const char* const kHighlightColour = "#ffc400";
const char* const kGreyColour = "#b4b4b4";  // faces of no halfspace's colour (a shape under cell marks)
const char* const kMarkColours[2] = {"#f4a261", "#e63946"};  // cell_marks 1 and 2, as io/svg.hpp

/// The colour a paint is filled with, before lighting.
Rgb base_colour(const Paint& paint) {
  return parse_colour(paint.overlay == 1   ? kHighlightColour
                      : paint.overlay > 1 ? kMarkColours[paint.overlay - 2]
                      : paint.halfspace < 0 ? kGreyColour
                                            : svg_palette_colour(paint.halfspace));
}

/// The light factor of triangle `t` in projection `p`: 0.35 + 0.65 |n . l|.
double light_factor(const Arrangement3& arr, const ArrTriangle3& t, const Projection& p) {
  return 0.35 + 0.65 * std::fabs(dot(unit(to_vec(exact_normal(arr, t))), p.light));
}

/// The paints with `highlight` set as given, back to front, in one "view" group (none for highlights when there
/// are none).
std::string faces_svg(const Arrangement3& arr, const std::vector<Paint>& paints, bool highlight,
                      const SvgView3& view, const Projection& p, double opacity) {
  if (highlight && std::none_of(paints.begin(), paints.end(), [](const Paint& x) { return x.overlay > 0; })) return "";
  struct Face {
    double depth;
    std::size_t paint;
  };
  std::vector<Face> faces;
  const auto& triangles = arr.triangles();
  for (std::size_t k = 0; k < paints.size(); ++k) {
    const ArrTriangle3& t = triangles.at(static_cast<std::size_t>(paints[k].triangle));
    if ((paints[k].overlay > 0) != highlight || !seen(arr, t, view.direction)) continue;
    Vec c;
    for (int v : t.vertices) c = c + to_vec(arr.vertices()[v]);
    faces.push_back({dot((1.0 / 3) * c, p.depth), k});
  }
  std::sort(faces.begin(), faces.end(), [&](const Face& a, const Face& b) {
    if (a.depth != b.depth) return a.depth > b.depth;  // farthest first
    return paints[a.paint].triangle < paints[b.paint].triangle;
  });
  std::string s = "<g class=\"view\" data-view=\"" + svg_escape(view.name) + "\" fill-opacity=\"" +
                  svg_number(opacity) + "\" stroke-width=\"0.4\" stroke-linejoin=\"round\">\n";
  for (const Face& f : faces) {
    const Paint& paint = paints[f.paint];
    const ArrTriangle3& t = triangles[static_cast<std::size_t>(paint.triangle)];
    const double light = light_factor(arr, t, p);
    const Rgb base = base_colour(paint);
    const char* const kind = paint.overlay == 1 ? "highlight" : paint.overlay == 2 ? "mark-inside"
                             : paint.overlay == 3                                ? "mark-outside"
                                                                                 : "face";
    s += std::string("<polygon class=\"") + kind + "\" data-triangle=\"" +
         std::to_string(paint.triangle) + "\"" +
         (paint.patch >= 0 ? " data-patch=\"" + std::to_string(paint.patch) + "\"" : std::string()) + " points=\"";
    for (int k = 0; k < 3; ++k) s += (k ? " " : "") + p.xy(to_vec(arr.vertices()[t.vertices[k]]));
    s += "\" fill=\"" + colour_text(base, light) + "\" stroke=\"" + colour_text(base, 0.75 * light) + "\"/>\n";
  }
  return s + "</g>\n";
}

std::string domain_svg(const Box3& box, const Projection& p) {
  const auto c = corners_of(box);
  std::string s = "<g class=\"domain\" stroke=\"#555555\" stroke-width=\"1\" stroke-dasharray=\"4 3\">\n";
  for (int k = 0; k < 8; ++k)
    for (int bit : {1, 2, 4})
      if (!(k & bit))
        s += "<line x1=\"" + svg_number(p.X(c[k])) + "\" y1=\"" + svg_number(p.Y(c[k])) + "\" x2=\"" +
             svg_number(p.X(c[k | bit])) + "\" y2=\"" + svg_number(p.Y(c[k | bit])) + "\"/>\n";
  return s + "</g>\n";
}

std::string samples_svg(const Scene3& scene, const Projection& p, const std::vector<char>& missing) {
  std::string s = "<g stroke=\"#000000\" stroke-width=\"0.8\">\n";
  for (std::size_t k = 0; k < scene.samples.size(); ++k) {
    const Vec q = to_vec(scene.samples[k].location);
    const std::string at = "\" cx=\"" + svg_number(p.X(q)) + "\" cy=\"" + svg_number(p.Y(q)) + "\"";
    s += "<circle class=\"sample\" data-id=\"" + std::to_string(k) + at + " r=\"4\" fill=\"" +
         svg_palette_colour(scene.samples[k].halfspace) + "\"/>\n";
    if (k < missing.size() && missing[k])
      s += "<circle class=\"missing\" data-id=\"" + std::to_string(k) + at +
           " r=\"8\" fill=\"none\" stroke=\"#e63946\" stroke-width=\"2\"/>\n";
  }
  return s + "</g>\n";
}

/// Where patch labels go: the centroid of each patch's largest triangle (exact comparison, lowest id on ties).
std::vector<Vec> patch_label_points(const Arranged3& a) {
  const auto& arr = a.arrangement;
  std::vector<Vec> points;
  for (const Patch& patch : a.complex.patches) {
    int best = -1;
    for (int t : patch.pieces)
      if (best < 0 || arr.triangles()[t].area2 > arr.triangles()[best].area2) best = t;
    Vec c;
    if (best >= 0)
      for (int v : arr.triangles()[best].vertices) c = c + (1.0 / 3) * to_vec(arr.vertices()[v]);
    points.push_back(c);
  }
  return points;
}

std::string labels_svg(const Arranged3& a, const std::vector<Vec>& patch_points, const Projection& p,
                       const Svg3Options& o, double font_size) {
  if (!o.show_cell_ids && !o.show_patch_ids) return "";
  const double shift = 0.35 * font_size;
  std::string s = "<g font-size=\"" + svg_number(font_size) + "\" text-anchor=\"middle\" stroke=\"#ffffff\" " +
                  "stroke-width=\"" + svg_number(0.3 * font_size) +
                  "\" stroke-linejoin=\"round\" paint-order=\"stroke\">\n";
  if (o.show_cell_ids)
    for (std::size_t c = 0; c < a.arrangement.cells().size(); ++c) {
      const Vec q = to_vec(a.arrangement.cells()[c].interior);
      s += "<text class=\"cell-id\" x=\"" + svg_number(p.X(q)) + "\" y=\"" + svg_number(p.Y(q) + shift) +
           "\" fill=\"#333333\">c" + std::to_string(c) + "</text>\n";
    }
  if (o.show_patch_ids)
    for (std::size_t k = 0; k < patch_points.size(); ++k)
      s += "<text class=\"patch-id\" x=\"" + svg_number(p.X(patch_points[k])) + "\" y=\"" +
           svg_number(p.Y(patch_points[k]) + shift) + "\" font-weight=\"bold\" fill=\"" +
           svg_palette_colour(a.complex.patches[k].halfspace) + "\">p" + std::to_string(k) + "</text>\n";
  return s + "</g>\n";
}

std::string legend_text(const Halfspace3& h) {
  return h.name + " (" + to_string(h.kind) + (h.complement ? ", complement" : "") + ")";
}

/// A line of the legend under the halfspaces: a swatch (an amber square or a red ring) and its text.
struct Mark {
  enum Swatch { Ring, Highlight, Faces, MarkInside, MarkOutside } swatch = Faces;
  std::string text;
};

std::vector<Mark> marks_of(const Arranged3& a, const Svg3Options& o, const std::vector<char>& missing) {
  std::vector<Mark> marks;
  if (!o.cell_fill.empty()) {
    const long n = static_cast<long>(std::count(missing.begin(), missing.end(), 1));
    marks.push_back({Mark::Faces, "the shape's boundary: " + std::to_string(shape_faces(a, o.cell_fill).size()) +
                                      (any_mark(o) ? " triangles, grey under the marks"
                                                   : " triangles, in their halfspaces' colours")});
    marks.push_back({Mark::Ring, "missing sample, not on the boundary (" + std::to_string(n) + " here)"});
  }
  if (std::find(o.highlight_patches.begin(), o.highlight_patches.end(), 1) != o.highlight_patches.end())
    marks.push_back({Mark::Highlight, o.highlight_legend + " (drawn over the rest)"});
  const std::vector<char> pm = patch_marks(a.complex, o.cell_marks);
  for (char m : {1, 2})
    if (std::find(pm.begin(), pm.end(), m) != pm.end())
      marks.push_back({m == 1 ? Mark::MarkInside : Mark::MarkOutside,
                       o.mark_legend[m - 1] + " (" +
                           std::to_string(std::count(o.cell_marks.begin(), o.cell_marks.end(), m)) +
                           " cells; their boundary patches, drawn over the rest)"});
  return marks;
}

std::string marks_svg(const std::vector<Mark>& marks, double left, double top, double font_size, double* height) {
  const double swatch = 18, gap = 6, line = 1.5 * font_size;
  std::string s;
  for (std::size_t k = 0; k < marks.size(); ++k) {
    const double y = top + static_cast<double>(k) * line;
    if (marks[k].swatch == Mark::Ring)
      s += "<circle cx=\"" + svg_number(left + swatch / 2) + "\" cy=\"" + svg_number(y + 0.45 * font_size) +
           "\" r=\"" + svg_number(0.45 * font_size) + "\" fill=\"none\" stroke=\"#e63946\" stroke-width=\"2\"/>\n";
    else
      s += "<rect x=\"" + svg_number(left) + "\" y=\"" + svg_number(y) + "\" width=\"" + svg_number(swatch) +
           "\" height=\"" + svg_number(0.9 * font_size) + "\" fill=\"" +
           (marks[k].swatch == Mark::Highlight     ? kHighlightColour
            : marks[k].swatch == Mark::MarkInside  ? kMarkColours[0]
            : marks[k].swatch == Mark::MarkOutside ? kMarkColours[1]
                                                   : "#9a9a9a") +
           "\"/>\n";
    s += "<text x=\"" + svg_number(left + swatch + gap) + "\" y=\"" + svg_number(y + 0.8 * font_size) +
         "\" fill=\"#222222\">" + svg_escape(marks[k].text) + "</text>\n";
  }
  *height = static_cast<double>(marks.size()) * line;
  return s;
}

/// The legend of halfspaces in as many equal columns as fit, then the marks one per line; its height goes to
/// *height.
std::string legend_svg(const Scene3& scene, const std::vector<Mark>& marks, double left, double top, double room,
                       double font_size, double* height) {
  const double swatch = 18, gap = 6, column_gap = 18, line = 1.5 * font_size;
  double widest = 0;
  for (const Halfspace3& h : scene.halfspaces) widest = std::max(widest, svg_text_width(legend_text(h), font_size));
  const double column = swatch + gap + widest + column_gap;
  const int columns = std::max(1, static_cast<int>((room + column_gap) / column));
  const int n = static_cast<int>(scene.halfspaces.size());
  const int rows = (n + columns - 1) / columns;
  std::string s = "<g class=\"legend\" font-size=\"" + svg_number(font_size) + "\">\n";
  for (int i = 0; i < n; ++i) {
    const double x = left + (i / rows) * column, y = top + (i % rows) * line;
    s += "<rect x=\"" + svg_number(x) + "\" y=\"" + svg_number(y) + "\" width=\"" + svg_number(swatch) +
         "\" height=\"" + svg_number(0.9 * font_size) + "\" fill=\"" + svg_palette_colour(i) + "\"/>\n";
    s += "<text x=\"" + svg_number(x + swatch + gap) + "\" y=\"" + svg_number(y + 0.8 * font_size) +
         "\" fill=\"#222222\">" + svg_escape(legend_text(scene.halfspaces[static_cast<std::size_t>(i)])) + "</text>\n";
  }
  double marks_height = 0;
  s += marks_svg(marks, left, top + rows * line, font_size, &marks_height);
  *height = rows * line + marks_height;
  return s + "</g>\n";
}

}  // namespace

std::vector<SvgView3> default_svg_views3() {
  const Rational o(0), one(1), m(-1);
  return {{"front (along +y)", {o, one, o}, {o, o, one}},
          {"side (along -x)", {m, o, o}, {o, o, one}},
          {"top (along -z)", {o, o, m}, {o, one, o}},
          {"isometric (along (-1, 1, -1))", {m, one, m}, {o, o, one}}};
}

std::size_t svg3_visible_triangles(const Arrangement3& arrangement, const SvgView3& view) {
  std::size_t n = 0;
  for (const ArrTriangle3& t : arrangement.triangles()) n += seen(arrangement, t, view.direction);
  return n;
}

namespace {

/// Where a picture's parts go: the views' projections (fitted with one scale), the panel size, the legend's top.
struct Layout {
  std::vector<SvgView3> views;
  std::vector<Projection> projections;
  std::vector<double> left, top;  // per view: its panel's corner
  double width = 0, margin = 16, panel = 0, legend_top = 0;
  Fonts fonts{1000};
};

Layout layout_of(const Arranged3& arranged, const Svg3Options& options, bool titled) {
  Layout l;
  l.views = options.views.empty() ? default_svg_views3() : options.views;
  l.width = options.width;
  l.fonts = Fonts(l.width);
  const double title_height = titled ? 2 * l.fonts.caption : 0;
  const std::size_t columns = l.views.size() == 1 ? 1 : 2;
  l.panel = (l.width - 2 * l.margin) / static_cast<double>(columns);
  const double caption = 1.6 * l.fonts.caption, pad = 12;
  const int rows = static_cast<int>((l.views.size() + columns - 1) / columns);
  const Box3& box = arranged.arrangement.domain();
  double scale = INFINITY;
  for (const SvgView3& v : l.views) {
    l.projections.push_back(projection_of(v));
    const double extent = outline_extent(l.projections.back(), box);
    if (extent > 0) scale = std::min(scale, (l.panel - caption - 2 * pad) / extent);
  }
  if (!std::isfinite(scale)) scale = 1;
  const Vec mid = 0.5 * (to_vec(box.min) + to_vec(box.max));
  for (std::size_t k = 0; k < l.views.size(); ++k) {
    Projection& p = l.projections[k];
    l.left.push_back(l.margin + static_cast<double>(k % columns) * l.panel);
    l.top.push_back(l.margin + title_height + static_cast<double>(k / columns) * l.panel);
    p.scale = scale;
    p.mid = mid;
    p.centre_x = l.left[k] + l.panel / 2;
    p.centre_y = l.top[k] + caption + (l.panel - caption) / 2;
  }
  l.legend_top = l.margin + title_height + rows * l.panel + 8;
  return l;
}

std::string caption_svg(const Layout& l, std::size_t k) {
  return "<text class=\"caption\" x=\"" + svg_number(l.left[k] + l.panel / 2) + "\" y=\"" +
         svg_number(l.top[k] + l.fonts.caption) + "\" text-anchor=\"middle\" font-size=\"" +
         svg_number(l.fonts.caption) + "\">" + svg_escape(l.views[k].name) + "</text>\n";
}

std::string title_svg(const Layout& l, const std::string& title) {
  if (title.empty()) return "";
  return "<text class=\"title\" x=\"" + svg_number(l.width / 2) + "\" y=\"" + svg_number(l.margin + l.fonts.caption) +
         "\" text-anchor=\"middle\" font-size=\"" + svg_number(1.2 * l.fonts.caption) + "\">" + svg_escape(title) +
         "</text>\n";
}

std::string svg_open(double width, double height, const std::string& extra) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\"" + extra + " width=\"" + svg_number(width) + "\" height=\"" +
         svg_number(height) + "\" viewBox=\"0 0 " + svg_number(width) + " " + svg_number(height) +
         "\" font-family=\"Helvetica, Arial, sans-serif\">\n<rect x=\"0\" y=\"0\" width=\"" + svg_number(width) +
         "\" height=\"" + svg_number(height) + "\" fill=\"#ffffff\"/>\n";
}

}  // namespace

std::string arrangement_svg3(const Scene3& scene, const Arranged3& arranged, const Svg3Options& options) {
  check_fit(scene, arranged, options);
  Layout l = layout_of(arranged, options, !options.title.empty());
  const std::vector<Paint> paints = paints_of(arranged, options);
  const std::vector<char> missing =
      options.cell_fill.empty() ? std::vector<char>{} : svg_missing_samples(arranged.complex, options.cell_fill);
  const std::vector<Vec> patch_points = patch_label_points(arranged);
  std::string body;
  for (std::size_t k = 0; k < l.views.size(); ++k) {
    const Projection& p = l.projections[k];
    body += caption_svg(l, k);
    body += faces_svg(arranged.arrangement, paints, false, l.views[k], p, options.opacity);
    body += faces_svg(arranged.arrangement, paints, true, l.views[k], p, options.opacity);
    body += domain_svg(arranged.arrangement.domain(), p);
    body += samples_svg(scene, p, missing);
    body += labels_svg(arranged, patch_points, p, options, l.fonts.label);
  }
  double legend_height = 0;
  body += legend_svg(scene, marks_of(arranged, options, missing), l.margin, l.legend_top, l.width - 2 * l.margin,
                     l.fonts.legend, &legend_height);
  const double height = l.legend_top + legend_height + l.margin;
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + svg_open(l.width, height, "") + title_svg(l, options.title) +
         body + "</svg>\n";
}

// ---- states_svg3: several shapes of one arrangement, each patch drawn once ----

namespace {

/// A coordinate of the states picture: rounded to 0.1 px, without trailing zeros ("12.3", "-4").
std::string coarse(double v) {
  const long tenths = std::lround(v * 10);
  const long whole = std::labs(tenths) / 10, tenth = std::labs(tenths) % 10;
  return std::string(tenths < 0 ? "-" : "") + std::to_string(whole) + (tenth ? "." + std::to_string(tenth) : "");
}

/// Patch `patch`'s triangles seen in view `view` as paths (back to front; consecutive triangles of one fill in one
/// path, subpaths "Mx yLx yLx yZ"), in `colour` (a highlight) or its halfspace's colour lit by each normal; the
/// mean depth of their centroids goes to *depth (NaN when none is seen).
std::string patch_paths(const Arranged3& a, int patch, const char* colour, const SvgView3& view,
                        const Projection& p, double* depth) {
  const Arrangement3& arr = a.arrangement;
  struct Face {
    double depth;
    int triangle;
  };
  std::vector<Face> faces;
  double sum = 0;
  for (int t : a.complex.patches[static_cast<std::size_t>(patch)].pieces) {
    const ArrTriangle3& tri = arr.triangles()[static_cast<std::size_t>(t)];
    if (!seen(arr, tri, view.direction)) continue;
    Vec c;
    for (int v : tri.vertices) c = c + to_vec(arr.vertices()[v]);
    faces.push_back({dot((1.0 / 3) * c, p.depth), t});
    sum += faces.back().depth;
  }
  *depth = faces.empty() ? NAN : sum / static_cast<double>(faces.size());
  std::sort(faces.begin(), faces.end(), [](const Face& x, const Face& y) {
    return x.depth != y.depth ? x.depth > y.depth : x.triangle < y.triangle;
  });
  const Rgb base =
      parse_colour(colour ? colour : svg_palette_colour(a.complex.patches[static_cast<std::size_t>(patch)].halfspace));
  std::string s, fill, stroke, d;
  auto flush = [&] {
    if (!d.empty()) s += "<path d=\"" + d + "\" fill=\"" + fill + "\" stroke=\"" + stroke + "\"/>\n";
    d.clear();
  };
  for (const Face& f : faces) {
    const ArrTriangle3& t = arr.triangles()[static_cast<std::size_t>(f.triangle)];
    const double light = light_factor(arr, t, p);
    const std::string here = colour_text(base, light);
    if (here != fill) flush();
    fill = here;
    stroke = colour_text(base, 0.75 * light);
    for (int k = 0; k < 3; ++k) {
      const Vec q = to_vec(arr.vertices()[t.vertices[k]]);
      d += (k ? "L" : "M") + coarse(p.X(q)) + " " + coarse(p.Y(q));
    }
    d += "Z";
  }
  flush();
  return s;
}


/// The arguments of states_svg3 and states_raster3 (`who` names the function in messages); throws
/// std::invalid_argument as they say.
void check_states(const Scene3& scene, const Arranged3& arranged, const std::vector<Svg3State>& states,
                  const Svg3Options& options, int columns, const std::string& who) {
  if (!options.cell_fill.empty() || !options.highlight_patches.empty() || !options.cell_marks.empty() ||
      !options.title.empty())
    throw std::invalid_argument(who + ": the shapes, highlights and titles come from the states");
  if (columns < 1) throw std::invalid_argument(who + ": columns must be at least 1");
  if (states.empty()) throw std::invalid_argument(who + ": no state");
  check_fit(scene, arranged, options);
  for (const Svg3State& state : states) {
    Svg3Options o = options;
    o.cell_fill = state.cell_fill;
    o.highlight_patches = state.highlight_patches;
    check_fit(scene, arranged, o);
    if (state.cell_fill.empty()) throw std::invalid_argument(who + ": a state without a shape");
  }
}

}  // namespace

std::string states_svg3(const Scene3& scene, const Arranged3& arranged, const std::vector<Svg3State>& states,
                        const Svg3Options& options, int columns) {
  check_states(scene, arranged, states, options, columns, "states_svg3");
  const Complex& c = arranged.complex;
  const Layout l = layout_of(arranged, options, true);
  const std::vector<Vec> patch_points = patch_label_points(arranged);
  // Shared definitions: per view, every patch on some state's boundary (its colour) or highlighted (amber).
  std::vector<char> on_boundary(c.patches.size(), 0), lit(c.patches.size(), 0);
  for (const Svg3State& state : states) {
    for (const ExportedFace& f : shape_faces(arranged, state.cell_fill))
      on_boundary[static_cast<std::size_t>(f.patch)] = 1;
    for (std::size_t p = 0; p < state.highlight_patches.size(); ++p) lit[p] |= state.highlight_patches[p];
  }
  std::string defs = "<defs>\n";
  std::vector<std::vector<double>> depth(l.views.size(), std::vector<double>(c.patches.size(), NAN));
  for (std::size_t v = 0; v < l.views.size(); ++v) {
    const Projection& p = l.projections[v];
    const std::string view = "v" + std::to_string(v);
    for (std::size_t q = 0; q < c.patches.size(); ++q) {
      const int patch = static_cast<int>(q);
      if (on_boundary[q])
        defs += "<g id=\"" + view + "p" + std::to_string(q) + "\">\n" +
                patch_paths(arranged, patch, nullptr, l.views[v], p, &depth[v][q]) + "</g>\n";
      double unused = 0;
      if (lit[q])
        defs += "<g id=\"" + view + "h" + std::to_string(q) + "\">\n" +
                patch_paths(arranged, patch, kHighlightColour, l.views[v], p, &unused) + "</g>\n";
    }
    defs += "<g id=\"" + view + "d\">\n" + domain_svg(arranged.arrangement.domain(), p) + samples_svg(scene, p, {}) +
            labels_svg(arranged, patch_points, p, options, l.fonts.label) + "</g>\n";
  }
  defs += "</defs>\n";
  auto use = [](const std::string& kind, std::size_t patch, const std::string& id) {
    return "<use class=\"" + kind + "\" data-patch=\"" + std::to_string(patch) + "\" xlink:href=\"#" + id + "\"/>\n";
  };
  std::vector<std::string> panels;
  std::vector<double> heights;
  for (const Svg3State& state : states) {
    Svg3Options o = options;
    o.cell_fill = state.cell_fill;
    o.highlight_patches = state.highlight_patches;
    const std::vector<char> missing = svg_missing_samples(c, state.cell_fill);
    std::vector<char> drawn(c.patches.size(), 0);
    for (const ExportedFace& f : shape_faces(arranged, state.cell_fill)) drawn[static_cast<std::size_t>(f.patch)] = 1;
    std::string body = title_svg(l, state.title);
    for (std::size_t v = 0; v < l.views.size(); ++v) {
      const std::string view = "v" + std::to_string(v);
      body += caption_svg(l, v);
      std::vector<std::size_t> order;
      for (std::size_t q = 0; q < c.patches.size(); ++q)
        if (drawn[q] && !std::isnan(depth[v][q])) order.push_back(q);
      std::stable_sort(order.begin(), order.end(),
                       [&](std::size_t x, std::size_t y) { return depth[v][x] > depth[v][y]; });  // farthest first
      body += "<g class=\"view\" data-view=\"" + svg_escape(l.views[v].name) + "\" fill-opacity=\"" +
              svg_number(options.opacity) + "\" stroke-width=\"0.4\" stroke-linejoin=\"round\">\n";
      for (std::size_t q : order) body += use("face", q, view + "p" + std::to_string(q));
      body += "</g>\n";
      const auto& lit_here = state.highlight_patches;
      if (std::find(lit_here.begin(), lit_here.end(), 1) != lit_here.end()) {
        body += "<g class=\"view\" data-view=\"" + svg_escape(l.views[v].name) + "\" fill-opacity=\"" +
                svg_number(options.opacity) + "\" stroke-width=\"0.4\" stroke-linejoin=\"round\">\n";
        for (std::size_t q = 0; q < state.highlight_patches.size(); ++q)
          if (state.highlight_patches[q]) body += use("highlight", q, view + "h" + std::to_string(q));
        body += "</g>\n";
      }
      body += "<use xlink:href=\"#" + view + "d\"/>\n";
      std::string rings;
      const Projection& p = l.projections[v];
      for (std::size_t k = 0; k < scene.samples.size() && k < missing.size(); ++k)
        if (missing[k]) {
          const Vec q = to_vec(scene.samples[k].location);
          rings += "<circle class=\"missing\" data-id=\"" + std::to_string(k) + "\" cx=\"" + svg_number(p.X(q)) +
                   "\" cy=\"" + svg_number(p.Y(q)) +
                   "\" r=\"8\" fill=\"none\" stroke=\"#e63946\" stroke-width=\"2\"/>\n";
        }
      body += rings;
    }
    double legend_height = 0;
    body += legend_svg(scene, marks_of(arranged, o, missing), l.margin, l.legend_top, l.width - 2 * l.margin,
                       l.fonts.legend, &legend_height);
    panels.push_back(body);
    heights.push_back(l.legend_top + legend_height + l.margin);
  }
  // The grid: `columns` panels per row, each row as high as its highest panel.
  const double gap = 8;
  const std::size_t n = panels.size(), cols = std::min<std::size_t>(n, static_cast<std::size_t>(columns));
  std::vector<double> row_height((n + cols - 1) / cols, 0);
  for (std::size_t k = 0; k < n; ++k) row_height[k / cols] = std::max(row_height[k / cols], heights[k]);
  std::vector<double> top(row_height.size(), gap);
  for (std::size_t r = 1; r < top.size(); ++r) top[r] = top[r - 1] + row_height[r - 1] + gap;
  const double width = static_cast<double>(cols) * (l.width + gap) + gap, height = top.back() + row_height.back() + gap;
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" +
                  svg_open(width, height, " xmlns:xlink=\"http://www.w3.org/1999/xlink\"") + defs;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = gap + static_cast<double>(k % cols) * (l.width + gap);
    s += "<svg x=\"" + svg_number(x) + "\" y=\"" + svg_number(top[k / cols]) + "\" width=\"" + svg_number(l.width) +
         "\" height=\"" + svg_number(heights[k]) + "\">\n" + panels[k] + "</svg>\n";
  }
  return s + "</svg>\n";
}


// ---- raster pictures: the same views with a z-buffer (see the conventions' "Raster pictures") ----

namespace {

using Colour8 = std::array<std::uint8_t, 3>;

/// Per pixel, the nearest surface drawn so far: its depth (infinity: none) and colour.
struct DepthBuffer {
  std::vector<double> depth;
  std::vector<Colour8> colour;
  explicit DepthBuffer(const RgbImage& image)
      : depth(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height), INFINITY),
        colour(depth.size()) {}
};

/// Pixels whose centres (x + 1/2, y + 1/2) lie in the triangle (sx, sy) (inside or on an edge, either turn),
/// within [x0, x1) x [y0, y1): each gets the triangle's depth there and `colour` when nearer than what it holds.
void cover_triangle(DepthBuffer& buffer, int image_width, const double (&sx)[3], const double (&sy)[3],
                    const double (&depth)[3], const Colour8& colour, int x0, int y0, int x1, int y1) {
  auto edge = [](double ax, double ay, double bx, double by, double px, double py) {
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  };
  const double area = edge(sx[0], sy[0], sx[1], sy[1], sx[2], sy[2]);
  if (!(area != 0) || !std::isfinite(area)) return;
  const int lo_x = std::max(x0, static_cast<int>(std::floor(std::min({sx[0], sx[1], sx[2]}) - 0.5)));
  const int hi_x = std::min(x1 - 1, static_cast<int>(std::ceil(std::max({sx[0], sx[1], sx[2]}))));
  const int lo_y = std::max(y0, static_cast<int>(std::floor(std::min({sy[0], sy[1], sy[2]}) - 0.5)));
  const int hi_y = std::min(y1 - 1, static_cast<int>(std::ceil(std::max({sy[0], sy[1], sy[2]}))));
  for (int y = lo_y; y <= hi_y; ++y)
    for (int x = lo_x; x <= hi_x; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const double w0 = edge(sx[1], sy[1], sx[2], sy[2], px, py), w1 = edge(sx[2], sy[2], sx[0], sy[0], px, py),
                   w2 = edge(sx[0], sy[0], sx[1], sy[1], px, py);
      if (area > 0 ? (w0 < 0 || w1 < 0 || w2 < 0) : (w0 > 0 || w1 > 0 || w2 > 0)) continue;
      const double d = (w0 * depth[0] + w1 * depth[1] + w2 * depth[2]) / area;
      const std::size_t k = static_cast<std::size_t>(y) * static_cast<std::size_t>(image_width) + x;
      if (d < buffer.depth[k]) {
        buffer.depth[k] = d;
        buffer.colour[k] = colour;
      }
    }
}

/// Pixel (x, y) blended towards `colour` by `alpha`; pixels outside the image are left alone.
void blend(RgbImage& image, int x, int y, const Colour8& colour, double alpha) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  std::uint8_t* p = image.at(x, y);
  for (int c = 0; c < 3; ++c)
    p[c] = static_cast<std::uint8_t>(std::lround((1 - alpha) * p[c] + alpha * colour[static_cast<std::size_t>(c)]));
}

/// The paints with `overlay` as given (faces, or highlights and marks) of one view, z-buffered within the view's
/// panel [x0, x1) x [y0, y1), then laid over `image` with `alpha`.
void raster_faces(RgbImage& image, const Arrangement3& arr, const std::vector<Paint>& paints, bool overlay,
                  const SvgView3& view, const Projection& p, double alpha, int x0, int y0, int x1, int y1) {
  DepthBuffer buffer(image);
  bool any = false;
  for (const Paint& paint : paints) {
    const ArrTriangle3& t = arr.triangles().at(static_cast<std::size_t>(paint.triangle));
    if ((paint.overlay > 0) != overlay || !seen(arr, t, view.direction)) continue;
    double sx[3], sy[3], depth[3];
    for (int k = 0; k < 3; ++k) {
      const Vec q = to_vec(arr.vertices()[t.vertices[static_cast<std::size_t>(k)]]);
      sx[k] = p.X(q);
      sy[k] = p.Y(q);
      depth[k] = dot(q, p.depth);
    }
    cover_triangle(buffer, image.width, sx, sy, depth, shade(base_colour(paint), light_factor(arr, t, p)), x0, y0,
                   x1, y1);
    any = true;
  }
  if (!any) return;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::size_t k = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + x;
      if (buffer.depth[k] < INFINITY) blend(image, x, y, buffer.colour[k], alpha);
    }
}

/// A 1 px line from (ax, ay) to (bx, by), dashed `on` px drawn, `off` px not (off = 0: solid).
void raster_line(RgbImage& image, double ax, double ay, double bx, double by, const Colour8& colour, double on,
                 double off) {
  const double length = std::hypot(bx - ax, by - ay);
  const int steps = std::max(1, static_cast<int>(std::ceil(length)));
  for (int i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    if (off > 0 && std::fmod(t * length, on + off) >= on) continue;
    blend(image, static_cast<int>(std::floor(ax + t * (bx - ax))), static_cast<int>(std::floor(ay + t * (by - ay))),
          colour, 1);
  }
}

/// The pixels whose centres are at a distance in [inner, outer] from (cx, cy), in `colour`.
void raster_ring(RgbImage& image, double cx, double cy, double inner, double outer, const Colour8& colour) {
  for (int y = static_cast<int>(std::floor(cy - outer)); y <= static_cast<int>(std::ceil(cy + outer)); ++y)
    for (int x = static_cast<int>(std::floor(cx - outer)); x <= static_cast<int>(std::ceil(cx + outer)); ++x) {
      const double r = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
      if (r >= inner && r <= outer) blend(image, x, y, colour, 1);
    }
}

Colour8 colour8(const char* hex) { return shade(parse_colour(hex), 1); }

}  // namespace

RgbImage arrangement_raster3(const Scene3& scene, const Arranged3& arranged, const Svg3Options& options) {
  check_fit(scene, arranged, options);
  const Layout l = layout_of(arranged, options, false);
  RgbImage image(options.width, static_cast<int>(std::ceil(l.legend_top - 8 + l.margin)));
  const std::vector<Paint> paints = paints_of(arranged, options);
  const std::vector<char> missing =
      options.cell_fill.empty() ? std::vector<char>{} : svg_missing_samples(arranged.complex, options.cell_fill);
  const Arrangement3& arr = arranged.arrangement;
  for (std::size_t v = 0; v < l.views.size(); ++v) {
    const Projection& p = l.projections[v];
    const int x0 = std::max(0, static_cast<int>(std::floor(l.left[v])));
    const int y0 = std::max(0, static_cast<int>(std::floor(l.top[v])));
    const int x1 = std::min(image.width, static_cast<int>(std::ceil(l.left[v] + l.panel)));
    const int y1 = std::min(image.height, static_cast<int>(std::ceil(l.top[v] + l.panel)));
    raster_faces(image, arr, paints, false, l.views[v], p, 1, x0, y0, x1, y1);
    raster_faces(image, arr, paints, true, l.views[v], p, options.opacity, x0, y0, x1, y1);
    const auto c = corners_of(arr.domain());
    for (int k = 0; k < 8; ++k)
      for (int bit : {1, 2, 4})
        if (!(k & bit))
          raster_line(image, p.X(c[k]), p.Y(c[k]), p.X(c[k | bit]), p.Y(c[k | bit]), colour8("#555555"), 4, 3);
    for (std::size_t k = 0; k < scene.samples.size(); ++k) {
      const Vec q = to_vec(scene.samples[k].location);
      raster_ring(image, p.X(q), p.Y(q), 0, 3.6, colour8(svg_palette_colour(scene.samples[k].halfspace)));
      raster_ring(image, p.X(q), p.Y(q), 3.6, 4.4, colour8("#000000"));
      if (k < missing.size() && missing[k]) raster_ring(image, p.X(q), p.Y(q), 7, 9, colour8("#e63946"));
    }
  }
  return image;
}

RgbImage states_raster3(const Scene3& scene, const Arranged3& arranged, const std::vector<Svg3State>& states,
                        const Svg3Options& options, int columns) {
  check_states(scene, arranged, states, options, columns, "states_raster3");
  std::vector<RgbImage> panels;
  for (const Svg3State& state : states) {
    Svg3Options o = options;
    o.cell_fill = state.cell_fill;
    o.highlight_patches = state.highlight_patches;
    panels.push_back(arrangement_raster3(scene, arranged, o));
  }
  const int gap = 8, n = static_cast<int>(panels.size()), cols = std::min(n, columns), rows = (n + cols - 1) / cols;
  const int w = panels.front().width, h = panels.front().height;  // every panel has one size: same options
  RgbImage image(gap + cols * (w + gap), gap + rows * (h + gap));
  const Colour8 frame = colour8("#b4b4b4");
  for (int k = 0; k < n; ++k) {
    const int left = gap + (k % cols) * (w + gap), top = gap + (k / cols) * (h + gap);
    for (int y = 0; y < h; ++y)
      std::copy_n(panels[static_cast<std::size_t>(k)].at(0, y), 3 * w, image.at(left, top + y));
    raster_line(image, left - 1, top - 1, left + w, top - 1, frame, 1, 0);
    raster_line(image, left - 1, top + h, left + w, top + h, frame, 1, 0);
    raster_line(image, left - 1, top - 1, left - 1, top + h, frame, 1, 0);
    raster_line(image, left + w, top - 1, left + w, top + h, frame, 1, 0);
  }
  return image;
}

}  // namespace hsx
