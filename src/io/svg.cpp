// SVG pictures: see svg.hpp.
#include <hsx/io/svg.hpp>

#include <hsx/kernel/measure.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace hsx {

namespace {

/// Twelve distinguishable colours (Tableau 10 plus two), cycled by halfspace index.
const char* const kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
                                "#e377c2", "#17becf", "#bcbd22", "#7f7f7f", "#393b79", "#e7969c"};
constexpr int kPaletteSize = sizeof(kPalette) / sizeof(kPalette[0]);

const char* colour_of(int halfspace) { return kPalette[((halfspace % kPaletteSize) + kPaletteSize) % kPaletteSize]; }

std::string num(double v) {
  if (!std::isfinite(v)) v = 0;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4f", v);
  std::string s = buffer;
  if (s == "-0.0000") s = "0.0000";
  return s;
}

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // Control characters are not allowed in XML 1.0 text.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
          out += '?';
        } else {
          out += c;
        }
    }
  }
  return out;
}

OneRoot minus(const OneRoot& a, const Rational& c) { return OneRoot(a.a0 - c, a.a1, a.root); }

struct View {
  double min_x = 0, max_y = 0, scale = 1, left = 0, top = 0;
  double X(double x) const { return left + (x - min_x) * scale; }
  double Y(double y) const { return top + (max_y - y) * scale; }
  std::string xy(const OneRootPoint& p) const { return num(X(p.x.to_double())) + " " + num(Y(p.y.to_double())); }
};

/// Path commands continuing from `from` along arrangement edge `e` to `to` (the edge's end points in the order
/// walked); `travel_ccw` tells whether that walk turns counter-clockwise (arcs only).
std::string edge_commands(const View& view, const ArrEdge2& e, const OneRootPoint& from, const OneRootPoint& to,
                          bool travel_ccw) {
  if (e.shape == EdgeShape2::Segment) return " L " + view.xy(to);
  const std::string r = num(e.radius.get_d() * view.scale);
  // SVG's y axis points down: a counter-clockwise turn in the scene is sweep-flag 0 on screen.
  const std::string sweep = travel_ccw ? "0" : "1";
  const OneRoot px = minus(from.x, e.center.x), py = minus(from.y, e.center.y);
  const OneRoot qx = minus(to.x, e.center.x), qy = minus(to.y, e.center.y);
  const int cross = (Measure::product(px, qy) - Measure::product(py, qx)).sign().value_or(0);
  const bool same = px == qx && py == qy;
  if (same) {
    // A full circle: two half circles through the antipode.
    const double ax = 2 * e.center.x.get_d() - from.x.to_double();
    const double ay = 2 * e.center.y.get_d() - from.y.to_double();
    return " A " + r + " " + r + " 0 0 " + sweep + " " + num(view.X(ax)) + " " + num(view.Y(ay)) + " A " + r + " " +
           r + " 0 0 " + sweep + " " + view.xy(to);
  }
  // The angle swept exceeds pi iff the end lies clockwise (for a ccw turn) of the start, as seen from the centre.
  const bool large = travel_ccw ? cross < 0 : cross > 0;
  return " A " + r + " " + r + " 0 " + (large ? "1" : "0") + " " + sweep + " " + view.xy(to);
}

/// Outward unit normal (scene coordinates) of halfspace h at point (x, y) on its boundary.
std::pair<double, double> outward_normal(const Halfspace2& h, double x, double y) {
  double nx = 0, ny = 0;
  switch (h.kind) {
    case HalfspaceKind2::Halfplane:
      nx = h.normal.x.get_d();
      ny = h.normal.y.get_d();
      break;
    case HalfspaceKind2::Disk:
      nx = x - h.center.x.get_d();
      ny = y - h.center.y.get_d();
      break;
    case HalfspaceKind2::Polygon: {
      const std::size_t n = h.vertices.size();
      double best = INFINITY;
      for (std::size_t i = 0; i < n; ++i) {
        const double ax = h.vertices[i].x.get_d(), ay = h.vertices[i].y.get_d();
        const double bx = h.vertices[(i + 1) % n].x.get_d(), by = h.vertices[(i + 1) % n].y.get_d();
        const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
        double t = len2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / len2 : 0;
        t = std::clamp(t, 0.0, 1.0);
        const double ex = ax + t * dx - x, ey = ay + t * dy - y, dist = ex * ex + ey * ey;
        if (dist < best) {
          best = dist;
          nx = dy;  // right of the edge: outside for a counter-clockwise polygon
          ny = -dx;
        }
      }
      if (sgn(signed_area(h.vertices)) < 0) {
        nx = -nx;
        ny = -ny;
      }
      break;
    }
  }
  if (h.complement) {
    nx = -nx;
    ny = -ny;
  }
  const double len = std::hypot(nx, ny);
  if (!(len > 0) || !std::isfinite(len)) return {0, 0};
  return {nx / len, ny / len};
}

/// The order in which a patch's pieces are walked: (edge, forward) steps forming a chain.
std::vector<std::pair<int, bool>> patch_walk(const std::vector<ArrEdge2>& edges, const std::vector<int>& pieces) {
  std::vector<std::pair<int, bool>> steps;
  if (pieces.empty()) return steps;
  const ArrEdge2& e0 = edges.at(pieces[0]);
  int v = e0.source;
  if (pieces.size() > 1) {
    const ArrEdge2& e1 = edges.at(pieces[1]);
    if (e0.target != e1.source && e0.target != e1.target) v = e0.target;
  }
  for (int p : pieces) {
    const ArrEdge2& e = edges.at(p);
    const bool forward = e.source == v;
    steps.emplace_back(p, forward);
    v = forward ? e.target : e.source;
  }
  return steps;
}

/// The point at fraction t (0 < t < 1; of length, for segments and arcs alike) along an edge walked from `from` to
/// `to` (scene coordinates, doubles).
std::pair<double, double> edge_point(const ArrEdge2& e, const OneRootPoint& from, const OneRootPoint& to,
                                     bool travel_ccw, double t) {
  const double px = from.x.to_double(), py = from.y.to_double(), qx = to.x.to_double(), qy = to.y.to_double();
  if (e.shape == EdgeShape2::Segment) return {px + t * (qx - px), py + t * (qy - py)};
  const double cx = e.center.x.get_d(), cy = e.center.y.get_d(), r = e.radius.get_d();
  const double a1 = std::atan2(py - cy, px - cx), a2 = std::atan2(qy - cy, qx - cx);
  const double two_pi = 2 * M_PI;
  double delta = travel_ccw ? a2 - a1 : a1 - a2;
  while (delta <= 1e-12) delta += two_pi;
  while (delta > two_pi) delta -= two_pi;
  const double at = travel_ccw ? a1 + t * delta : a1 - t * delta;
  return {cx + r * std::cos(at), cy + r * std::sin(at)};
}

const char* kind_text(const Halfspace2& h) {
  switch (h.kind) {
    case HalfspaceKind2::Halfplane: return "half-plane";
    case HalfspaceKind2::Disk: return "disk";
    case HalfspaceKind2::Polygon: return "polygon";
  }
  return "";
}

/// Helvetica (= Arial) advance widths of ASCII 32..126, in 1/1000 em (Adobe's Helvetica AFM).
constexpr short kHelveticaWidths[95] = {
    278, 278, 355, 556, 556, 889, 667, 191, 333, 333, 389, 584, 278, 333, 278, 278,  // space .. /
    556, 556, 556, 556, 556, 556, 556, 556, 556, 556, 278, 278, 584, 584, 584, 556,  // 0 .. ?
    1015, 667, 667, 722, 722, 667, 611, 778, 722, 278, 500, 667, 556, 833, 722, 778,  // @ .. O
    667, 778, 722, 667, 611, 722, 667, 944, 667, 667, 611, 278, 278, 278, 469, 556,  // P .. _
    333, 556, 556, 500, 556, 556, 278, 556, 556, 222, 222, 500, 222, 833, 556, 556,  // ` .. o
    556, 556, 333, 500, 278, 556, 500, 722, 500, 500, 500, 334, 260, 334, 584};      // p .. ~

double text_width(const std::string& text, double font_size) {
  double em = 0;
  for (unsigned char c : text) {
    if (c >= 32 && c < 127)
      em += kHelveticaWidths[c - 32] / 1000.0;
    else if (c >= 0xC0 || c < 0x80)  // the lead byte of a multi-byte character, or a control character
      em += 1.0;
  }
  return 1.15 * em * font_size;
}

/// Sizes that follow the picture's width.
struct Fonts {
  double title, legend, label;
  explicit Fonts(double width) {
    const double k = width / 800;
    title = std::max(11.0, 15 * k);
    legend = std::max(9.0, 12 * k);
    label = std::max(8.0, 11 * k);
  }
};

// ---- the legend ----

enum class Swatch { None, Line, Dashed, Bold, Highlight, Fill, Sample, Ring };

struct LegendEntry {
  Swatch swatch;
  std::string colour;
  std::string text;
};

/// The legend's entries: one per halfspace, then what the shading, line styles and marks mean.
struct Legend {
  std::vector<LegendEntry> halfspaces, key;
};

/// Greedy word wrapping of `text` into lines no wider than `room` px (a single word may be wider).
std::vector<std::string> wrap_words(const std::string& text, double font_size, double room) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t space = text.find(' ', at);
    if (space == std::string::npos) space = text.size();
    const std::string word = text.substr(at, space - at);
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && text_width(longer, font_size) > room) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
    at = space + 1;
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

/// Draws one swatch in the box [x, x + w] centred vertically on y.
std::string swatch_svg(const LegendEntry& e, double x, double y, double w, double font_size) {
  const std::string x1 = num(x), x2 = num(x + w), ys = num(y), colour = e.colour;
  auto line = [&](const std::string& attributes) {
    return "<line x1=\"" + x1 + "\" y1=\"" + ys + "\" x2=\"" + x2 + "\" y2=\"" + ys + "\" " + attributes + "/>\n";
  };
  switch (e.swatch) {
    case Swatch::None: return "";
    case Swatch::Line: return line("stroke=\"" + colour + "\" stroke-width=\"3\"");
    case Swatch::Dashed: return line("stroke=\"" + colour + "\" stroke-width=\"2.5\" stroke-dasharray=\"5 4\"");
    case Swatch::Bold:
      return line("stroke=\"#222222\" stroke-width=\"6\"") + line("stroke=\"" + colour + "\" stroke-width=\"2.5\"");
    case Swatch::Highlight: return line("stroke=\"#ffc400\" stroke-opacity=\"0.6\" stroke-width=\"9\"");
    case Swatch::Fill: {
      const double h = 0.9 * font_size;
      return "<rect x=\"" + x1 + "\" y=\"" + num(y - h / 2) + "\" width=\"" + num(w) + "\" height=\"" + num(h) +
             "\" fill=\"" + colour + "\" stroke=\"#999999\" stroke-width=\"0.6\"/>\n";
    }
    case Swatch::Sample:
      return "<line x1=\"" + num(x + w / 2) + "\" y1=\"" + ys + "\" x2=\"" + num(x + w / 2 + 9) + "\" y2=\"" + ys +
             "\" stroke=\"" + colour + "\" stroke-width=\"1.8\"/>\n<circle cx=\"" + num(x + w / 2) + "\" cy=\"" + ys +
             "\" r=\"3.5\" fill=\"" + colour + "\" stroke=\"#000000\" stroke-width=\"0.8\"/>\n";
    case Swatch::Ring:
      return "<circle cx=\"" + num(x + w / 2) + "\" cy=\"" + ys + "\" r=\"3.5\" fill=\"" + colour +
             "\" stroke=\"#000000\" stroke-width=\"0.8\"/>\n<circle cx=\"" + num(x + w / 2) + "\" cy=\"" + ys +
             "\" r=\"7\" fill=\"none\" stroke=\"#e63946\" stroke-width=\"2\"/>\n";
  }
  return "";
}

/// A block of entries laid out in equal columns across `room` px from (left, top): its SVG and its height.
struct LegendBlock {
  std::string svg;
  double height = 0;
};

LegendBlock layout_legend_block(const std::vector<LegendEntry>& entries, double left, double top, double room,
                                double font_size) {
  LegendBlock block;
  if (entries.empty()) return block;
  const double swatch = 22, gap = 6, column_gap = 16, line_height = 1.45 * font_size;
  const double text_room = std::max(room - swatch - gap, font_size);
  double widest = 0;
  for (const LegendEntry& e : entries) widest = std::max(widest, text_width(e.text, font_size));
  const double column_width = swatch + gap + std::min(widest, text_room) + column_gap;
  const int columns = std::max(1, static_cast<int>((room + column_gap) / column_width));
  double row_top = top;
  for (std::size_t first = 0; first < entries.size(); first += columns) {
    std::size_t row_lines = 1;
    for (std::size_t k = first; k < std::min(entries.size(), first + columns); ++k) {
      const LegendEntry& e = entries[k];
      const double x = left + static_cast<double>(k - first) * column_width;
      const auto lines = wrap_words(e.text, font_size, text_room);
      row_lines = std::max(row_lines, lines.size());
      const double middle = row_top + line_height / 2;
      block.svg += swatch_svg(e, x, middle, swatch, font_size);
      for (std::size_t l = 0; l < lines.size(); ++l)
        block.svg += "<text x=\"" + num(x + swatch + gap) + "\" y=\"" +
                     num(middle + 0.35 * font_size + static_cast<double>(l) * line_height) + "\" fill=\"#222222\">" +
                     escape(lines[l]) + "</text>\n";
    }
    row_top += static_cast<double>(row_lines) * line_height;
  }
  block.height = row_top - top;
  return block;
}

bool any_set(const std::vector<char>& flags) {
  return std::any_of(flags.begin(), flags.end(), [](char f) { return f != 0; });
}

/// The fill of cell f (see the shading convention in svg.hpp).
const char* cell_colour(const Cell& cell, std::size_t f, const SvgOptions& o) {
  if (f < o.cell_marks.size() && o.cell_marks[f]) return o.cell_marks[f] == 1 ? "#f4a261" : "#e63946";
  if (!o.cell_fill.empty()) {
    const bool filled = f < o.cell_fill.size() && o.cell_fill[f];
    return filled ? "#9dbbe0" : (cell.outer ? "#fafafa" : "#f0f0f0");
  }
  const long count = std::count(cell.inside.begin(), cell.inside.end(), 1);
  if (cell.outer) return count % 2 ? "#ececec" : "#f7f7f7";
  return count % 2 ? "#d2d2d2" : "#e4e4e4";
}

/// Per sample: 1 when it is missing from the shape given by `fill` (see svg.hpp).
std::vector<char> missing_samples(const Complex& c, const std::vector<char>& fill) {
  auto filled = [&](int cell) { return cell >= 0 && static_cast<std::size_t>(cell) < fill.size() && fill[cell]; };
  std::vector<char> missing(c.samples.size(), 1);
  for (std::size_t k = 0; k < c.samples.size(); ++k) {
    const int p = c.samples[k].patch;
    if (p < 0 || static_cast<std::size_t>(p) >= c.patches.size()) continue;
    const Patch& patch = c.patches[p];
    missing[k] = !(filled(patch.inside_cell) && !filled(patch.outside_cell));
  }
  return missing;
}

/// Per support: 1 when its cells are filled differently (it lies on the shape's boundary).
std::vector<char> boundary_of_fill(const Complex& c, const std::vector<char>& fill) {
  auto filled = [&](int cell) { return cell >= 0 && static_cast<std::size_t>(cell) < fill.size() && fill[cell]; };
  std::vector<char> on(c.supports.size(), 0);
  for (std::size_t g = 0; g < c.supports.size(); ++g) {
    if (c.supports[g].empty()) continue;
    const Patch& p = c.patches.at(c.supports[g].front());
    on[g] = filled(p.inside_cell) != filled(p.outside_cell);
  }
  return on;
}

Legend legend_entries(const Scene2& scene, const Complex& c, const SvgOptions& o, bool draw_boundary,
                      long missing_count) {
  Legend legend;
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
    const Halfspace2& h = scene.halfspaces[i];
    legend.halfspaces.push_back({Swatch::Line, colour_of(static_cast<int>(i)),
                                 h.name + " (" + kind_text(h) + (h.complement ? ", complement" : "") + ")"});
  }
  auto& key = legend.key;
  if (o.cell_fill.empty()) {
    key.push_back({Swatch::Fill, "#d2d2d2", "cell in an odd number of halfspaces"});
    key.push_back({Swatch::Fill, "#e4e4e4", "cell in an even number (or none)"});
    key.push_back({Swatch::Fill, "#f7f7f7", "outer cells (touch the domain box): paler"});
  } else {
    key.push_back({Swatch::Fill, "#9dbbe0", "inside the shape"});
    key.push_back({Swatch::Fill, "#f0f0f0", "outside the shape"});
  }
  if (std::find(o.cell_marks.begin(), o.cell_marks.end(), 1) != o.cell_marks.end())
    key.push_back({Swatch::Fill, "#f4a261", "inside cell of a mixed term"});
  if (std::find(o.cell_marks.begin(), o.cell_marks.end(), 2) != o.cell_marks.end())
    key.push_back({Swatch::Fill, "#e63946", "outside cell of a mixed term"});
  if (draw_boundary) key.push_back({Swatch::Bold, "#7f7f7f", "boundary of the shape (bold)"});
  if (any_set(o.highlight_patches)) key.push_back({Swatch::Highlight, "", o.highlight_legend});
  const bool coincident = std::any_of(c.supports.begin(), c.supports.end(), [](const auto& g) { return g.size() > 1; });
  if (coincident) key.push_back({Swatch::Dashed, "#7f7f7f", "coincident boundaries (alternating dashes)"});
  if (!scene.samples.empty())
    key.push_back({Swatch::Sample, "#7f7f7f", "sample; its tick points out of its halfspace"});
  if (draw_boundary)
    key.push_back({Swatch::Ring, "#7f7f7f",
                   "missing sample, not on the boundary (" + std::to_string(missing_count) + " here)"});
  if (o.show_cell_ids || o.show_patch_ids)
    key.push_back({Swatch::None, "", "c<k>, p<k>: cell k, patch k, as in the text and JSON"});
  return legend;
}

// ---- the drawing ----

void check_fit(const Scene2& scene, const Arrangement2& arr, const Complex& c) {
  if (c.cells.size() != arr.faces().size())
    throw std::invalid_argument("arrangement_svg: the complex's cells are not the arrangement's faces");
  if (static_cast<std::size_t>(c.halfspace_count()) != scene.halfspaces.size())
    throw std::invalid_argument("arrangement_svg: the complex's halfspaces are not the scene's");
  for (const Patch& p : c.patches)
    for (int e : p.pieces)
      if (e < 0 || static_cast<std::size_t>(e) >= arr.edges().size())
        throw std::invalid_argument("arrangement_svg: a patch piece is not an arrangement edge");
  if (c.samples.size() != scene.samples.size())
    throw std::invalid_argument("arrangement_svg: the complex's samples are not the scene's");
  for (const auto& g : c.supports)
    for (int p : g)
      if (p < 0 || static_cast<std::size_t>(p) >= c.patches.size())
        throw std::invalid_argument("arrangement_svg: a support names no patch");
}

std::string cells_svg(const Arrangement2& arr, const Complex& c, const View& view, const SvgOptions& o) {
  const auto& vertices = arr.vertices();
  const auto& edges = arr.edges();
  const auto& faces = arr.faces();
  std::string s = "<g stroke=\"none\" fill-rule=\"evenodd\">\n";
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::string d;
    for (const auto& walk : faces[f].boundary) {
      if (walk.empty()) continue;
      bool first = true;
      for (const auto& [ei, forward] : walk) {
        const ArrEdge2& e = edges.at(ei);
        const OneRootPoint& p = vertices.at(forward ? e.source : e.target).point;
        const OneRootPoint& q = vertices.at(forward ? e.target : e.source).point;
        if (first) d += (d.empty() ? "M " : " M ") + view.xy(p);
        first = false;
        d += edge_commands(view, e, p, q, forward == e.ccw);
      }
      d += " Z";
    }
    s += "<path class=\"cell\" data-id=\"" + std::to_string(f) + "\" fill=\"" + cell_colour(c.cells[f], f, o) +
         "\" d=\"" + d + "\"/>\n";
  }
  return s + "</g>\n";
}

/// Each patch's path and a point of it (scene coordinates) for its label.
struct PatchPaths {
  std::vector<std::string> d;
  std::vector<std::pair<double, double>> point;
};

/// Where along its middle piece patch p is labelled: halfway, or spread out along coincident patches so that
/// their labels do not cover each other.
double label_fraction(const Complex& c, std::size_t p) {
  const int support = c.patches[p].support;
  if (support < 0 || static_cast<std::size_t>(support) >= c.supports.size()) return 0.5;
  const auto& group = c.supports[support];
  const auto position = std::find(group.begin(), group.end(), static_cast<int>(p)) - group.begin();
  return static_cast<double>(position + 1) / static_cast<double>(group.size() + 1);
}

PatchPaths patch_paths(const Arrangement2& arr, const Complex& c, const View& view) {
  const auto& vertices = arr.vertices();
  const auto& edges = arr.edges();
  PatchPaths out;
  out.d.resize(c.patches.size());
  out.point.assign(c.patches.size(), {view.min_x, view.max_y});
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    const auto steps = patch_walk(edges, c.patches[p].pieces);
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const auto& [ei, forward] = steps[k];
      const ArrEdge2& e = edges[ei];
      const OneRootPoint& from = vertices.at(forward ? e.source : e.target).point;
      const OneRootPoint& to = vertices.at(forward ? e.target : e.source).point;
      if (k == 0) out.d[p] += "M " + view.xy(from);
      out.d[p] += edge_commands(view, e, from, to, forward == e.ccw);
      if (k == steps.size() / 2) out.point[p] = edge_point(e, from, to, forward == e.ccw, label_fraction(c, p));
    }
  }
  return out;
}

std::string patches_svg(const Complex& c, const PatchPaths& paths, const std::vector<char>& boundary,
                        const SvgOptions& o) {
  std::string s = "<g fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  for (std::size_t p = 0; p < c.patches.size(); ++p)
    if (p < o.highlight_patches.size() && o.highlight_patches[p])
      s += "<path class=\"highlight\" data-id=\"" + std::to_string(p) +
           "\" stroke=\"#ffc400\" stroke-opacity=\"0.6\" stroke-width=\"9\" d=\"" + paths.d[p] + "\"/>\n";
  // The boundary: a dark casing under the patches' colours, once per support.
  for (std::size_t g = 0; g < boundary.size(); ++g)
    if (boundary[g])
      s += "<path class=\"boundary\" data-support=\"" + std::to_string(g) +
           "\" stroke=\"#222222\" stroke-width=\"6.5\" d=\"" + paths.d[c.supports[g].front()] + "\"/>\n";
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    const Patch& patch = c.patches[p];
    std::string dash;
    if (patch.support >= 0 && static_cast<std::size_t>(patch.support) < c.supports.size()) {
      const auto& group = c.supports[patch.support];
      if (group.size() > 1) {
        const auto position = std::find(group.begin(), group.end(), static_cast<int>(p)) - group.begin();
        dash = " stroke-dasharray=\"8 " + std::to_string(8 * (group.size() - 1)) + "\" stroke-dashoffset=\"" +
               std::to_string(8 * position) + "\"";
      }
    }
    s += "<path class=\"patch\" data-id=\"" + std::to_string(p) + "\" stroke=\"" + colour_of(patch.halfspace) +
         "\" stroke-width=\"2.5\"" + dash + " d=\"" + paths.d[p] + "\"/>\n";
  }
  return s + "</g>\n";
}

/// Samples: a tick along the outward normal, then the dot; missing ones get a red ring.
std::string samples_svg(const Scene2& scene, const View& view, const std::vector<char>& missing) {
  std::string s = "<g>\n";
  const std::size_t n_half = scene.halfspaces.size();
  for (const Sample2& sample : scene.samples) {
    if (sample.halfspace < 0 || static_cast<std::size_t>(sample.halfspace) >= n_half) continue;
    const double x = sample.location.x.to_double(), y = sample.location.y.to_double();
    const auto [nx, ny] = outward_normal(scene.halfspaces[sample.halfspace], x, y);
    const double sx = view.X(x), sy = view.Y(y), tick = 12;
    s += "<line class=\"tick\" x1=\"" + num(sx) + "\" y1=\"" + num(sy) + "\" x2=\"" + num(sx + tick * nx) +
         "\" y2=\"" + num(sy - tick * ny) + "\" stroke=\"" + colour_of(sample.halfspace) +
         "\" stroke-width=\"1.8\"/>\n";
  }
  for (std::size_t k = 0; k < scene.samples.size(); ++k) {
    const Sample2& sample = scene.samples[k];
    const std::string cx = num(view.X(sample.location.x.to_double())), cy = num(view.Y(sample.location.y.to_double()));
    s += "<circle class=\"sample\" data-id=\"" + std::to_string(k) + "\" cx=\"" + cx + "\" cy=\"" + cy +
         "\" r=\"3.5\" fill=\"" + colour_of(sample.halfspace) + "\" stroke=\"#000000\" stroke-width=\"0.8\"/>\n";
    if (k < missing.size() && missing[k])
      s += "<circle class=\"missing\" data-id=\"" + std::to_string(k) + "\" cx=\"" + cx + "\" cy=\"" + cy +
           "\" r=\"7\" fill=\"none\" stroke=\"#e63946\" stroke-width=\"2\"/>\n";
  }
  return s + "</g>\n";
}

std::string labels_svg(const Arrangement2& arr, const Complex& c, const View& view, const PatchPaths& paths,
                       const SvgOptions& o, double font_size) {
  if (!o.show_cell_ids && !o.show_patch_ids) return "";
  const double shift = 0.35 * font_size;  // baseline below the labelled point: the text is centred on it
  std::string s = "<g font-size=\"" + num(font_size) + "\" text-anchor=\"middle\" stroke=\"#ffffff\" stroke-width=\"" +
                  num(0.3 * font_size) + "\" stroke-linejoin=\"round\" paint-order=\"stroke\">\n";
  if (o.show_cell_ids) {
    for (std::size_t f = 0; f < c.cells.size(); ++f) {
      const std::vector<Rational>& w = c.cells[f].witness.get();
      const PointQ2 p = w.size() == 2 ? PointQ2{w[0], w[1]} : arr.face_interiors()->get(f);
      const double x = p.x.get_d(), y = p.y.get_d();
      s += "<text class=\"cell-id\" x=\"" + num(view.X(x)) + "\" y=\"" + num(view.Y(y) + shift) +
           "\" fill=\"#333333\">c" + std::to_string(f) + "</text>\n";
    }
  }
  if (o.show_patch_ids) {
    for (std::size_t p = 0; p < c.patches.size(); ++p)
      s += "<text class=\"patch-id\" x=\"" + num(view.X(paths.point[p].first)) + "\" y=\"" +
           num(view.Y(paths.point[p].second) + shift) + "\" font-weight=\"bold\" fill=\"" +
           colour_of(c.patches[p].halfspace) + "\">p" + std::to_string(p) + "</text>\n";
  }
  return s + "</g>\n";
}

}  // namespace

std::string arrangement_svg(const Scene2& scene, const Arrangement2& arr, const Complex& c, const SvgOptions& o) {
  check_fit(scene, arr, c);
  const bool draw_boundary = !o.cell_fill.empty() && o.shape_boundary;
  const std::vector<char> boundary = draw_boundary ? boundary_of_fill(c, o.cell_fill) : std::vector<char>{};
  const std::vector<char> missing = draw_boundary ? missing_samples(c, o.cell_fill) : std::vector<char>{};

  const Box2& box = arr.domain();
  const double min_x = box.min.x.get_d(), max_x = box.max.x.get_d();
  const double min_y = box.min.y.get_d(), max_y = box.max.y.get_d();
  const double margin = 16;
  const double width = std::max(o.width, 100);
  const Fonts fonts(width);
  const double title_height = o.title.empty() ? 0 : 1.75 * fonts.title;
  const double draw_width = width - 2 * margin;
  View view;
  view.min_x = min_x;
  view.max_y = max_y;
  view.scale = max_x > min_x ? draw_width / (max_x - min_x) : 1;
  view.left = margin;
  view.top = margin + title_height;
  const double draw_height = (max_y - min_y) * view.scale;

  const Legend legend =
      legend_entries(scene, c, o, draw_boundary, static_cast<long>(std::count(missing.begin(), missing.end(), 1)));
  const double legend_top = view.top + draw_height + 14;
  const LegendBlock halfspaces = layout_legend_block(legend.halfspaces, margin, legend_top, draw_width, fonts.legend);
  const double key_top = legend_top + halfspaces.height + (halfspaces.height > 0 ? 0.5 * fonts.legend : 0);
  const LegendBlock key = layout_legend_block(legend.key, margin, key_top, draw_width, fonts.legend);
  const double height = key_top + key.height + margin;

  std::string s;
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width) + "\" height=\"" + num(height) +
       "\" viewBox=\"0 0 " + num(width) + " " + num(height) + "\" font-family=\"Helvetica, Arial, sans-serif\">\n";
  s += "<rect x=\"0\" y=\"0\" width=\"" + num(width) + "\" height=\"" + num(height) + "\" fill=\"#ffffff\"/>\n";
  if (!o.title.empty())
    s += "<text class=\"title\" x=\"" + num(width / 2) + "\" y=\"" + num(margin + fonts.title) +
         "\" text-anchor=\"middle\" font-size=\"" + num(fonts.title) + "\">" + escape(o.title) + "</text>\n";
  s += cells_svg(arr, c, view, o);
  s += "<rect class=\"domain\" x=\"" + num(view.X(min_x)) + "\" y=\"" + num(view.Y(max_y)) + "\" width=\"" +
       num(draw_width) + "\" height=\"" + num(draw_height) + "\" fill=\"none\" stroke=\"#999999\" stroke-width=\"0.8\"/>\n";
  const PatchPaths paths = patch_paths(arr, c, view);
  s += patches_svg(c, paths, boundary, o);
  s += samples_svg(scene, view, missing);
  s += labels_svg(arr, c, view, paths, o, fonts.label);
  s += "<g class=\"legend\" font-size=\"" + num(fonts.legend) + "\">\n" + halfspaces.svg + key.svg + "</g>\n";
  s += "</svg>\n";
  return s;
}

const char* svg_palette_colour(int index) { return colour_of(index); }

std::vector<char> svg_missing_samples(const Complex& complex, const std::vector<char>& fill) {
  return missing_samples(complex, fill);
}

namespace {

/// The root <svg> element of a picture: where its tag starts and ends, and its size.
struct SvgRoot {
  std::size_t open = 0, close = 0;  // text[open..close) is the root's start tag, '<' to '>' included
  double width = 0, height = 0;
};

double attribute_px(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t at = tag.find(key);
  if (at == std::string::npos) throw std::invalid_argument("svg_grid: the root <svg> has no " + name);
  std::size_t used = 0;
  const double v = std::stod(tag.substr(at + key.size()), &used);
  if (!(v >= 0) || !std::isfinite(v)) throw std::invalid_argument("svg_grid: bad " + name);
  return v;
}

SvgRoot svg_root(const std::string& text) {
  SvgRoot root;
  std::size_t start = 0;
  if (text.rfind("<?xml", 0) == 0) {
    start = text.find("?>");
    if (start == std::string::npos) throw std::invalid_argument("svg_grid: an unterminated XML declaration");
    start = text.find_first_not_of(" \t\r\n", start + 2);
  }
  if (start == std::string::npos || text.compare(start, 5, "<svg ") != 0)
    throw std::invalid_argument("svg_grid: a picture does not start with its root <svg>");
  root.open = start;
  root.close = text.find('>', start);
  if (root.close == std::string::npos) throw std::invalid_argument("svg_grid: an unterminated <svg> tag");
  ++root.close;
  const std::string tag = text.substr(root.open, root.close - root.open);
  root.width = attribute_px(tag, "width");
  root.height = attribute_px(tag, "height");
  return root;
}

}  // namespace

std::string svg_grid(const std::vector<std::string>& pictures, int columns) {
  if (columns < 1) throw std::invalid_argument("svg_grid: columns must be at least 1");
  std::vector<SvgRoot> roots;
  for (const std::string& p : pictures) roots.push_back(svg_root(p));
  const double gap = 8;
  std::vector<double> column_width(static_cast<std::size_t>(columns), 0);
  std::vector<double> row_height((pictures.size() + columns - 1) / columns, 0);
  for (std::size_t k = 0; k < roots.size(); ++k) {
    column_width[k % columns] = std::max(column_width[k % columns], roots[k].width);
    row_height[k / columns] = std::max(row_height[k / columns], roots[k].height);
  }
  std::vector<double> left(static_cast<std::size_t>(columns), gap), top(row_height.size(), gap);
  for (std::size_t c = 1; c < left.size(); ++c) left[c] = left[c - 1] + column_width[c - 1] + gap;
  for (std::size_t r = 1; r < top.size(); ++r) top[r] = top[r - 1] + row_height[r - 1] + gap;
  const double width = left.back() + column_width.back() + gap;
  const double height = top.empty() ? 2 * gap : top.back() + row_height.back() + gap;
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width) + "\" height=\"" + num(height) +
       "\" viewBox=\"0 0 " + num(width) + " " + num(height) + "\">\n";
  s += "<rect x=\"0\" y=\"0\" width=\"" + num(width) + "\" height=\"" + num(height) + "\" fill=\"#ffffff\"/>\n";
  for (std::size_t k = 0; k < pictures.size(); ++k) {
    const std::string& p = pictures[k];
    const SvgRoot& r = roots[k];
    s += "<svg x=\"" + num(left[k % columns]) + "\" y=\"" + num(top[k / columns]) + "\"" +
         p.substr(r.open + 4, r.close - r.open - 4) + "\n";
    std::string body = p.substr(r.close);
    while (!body.empty() && (body.back() == '\n' || body.back() == ' ')) body.pop_back();
    s += body.front() == '\n' ? body.substr(1) : body;
    s += "\n";
  }
  return s + "</svg>\n";
}

std::string svg_number(double value) { return num(value); }

std::string svg_escape(const std::string& text) { return escape(text); }

double svg_text_width(const std::string& text, double font_size) { return text_width(text, font_size); }

std::string svg_edge_commands(const SvgView& v, const ArrEdge2& edge, const OneRootPoint& from,
                              const OneRootPoint& to, bool travel_ccw) {
  return edge_commands(View{v.min_x, v.max_y, v.scale, v.left, v.top}, edge, from, to, travel_ccw);
}

}  // namespace hsx
