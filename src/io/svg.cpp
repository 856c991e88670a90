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

/// A point halfway along an edge walked from `from` to `to` (scene coordinates, doubles).
std::pair<double, double> edge_midpoint(const ArrEdge2& e, const OneRootPoint& from, const OneRootPoint& to,
                                        bool travel_ccw) {
  const double px = from.x.to_double(), py = from.y.to_double(), qx = to.x.to_double(), qy = to.y.to_double();
  if (e.shape == EdgeShape2::Segment) return {(px + qx) / 2, (py + qy) / 2};
  const double cx = e.center.x.get_d(), cy = e.center.y.get_d(), r = e.radius.get_d();
  const double a1 = std::atan2(py - cy, px - cx), a2 = std::atan2(qy - cy, qx - cx);
  const double two_pi = 2 * M_PI;
  double delta = travel_ccw ? a2 - a1 : a1 - a2;
  while (delta <= 1e-12) delta += two_pi;
  while (delta > two_pi) delta -= two_pi;
  const double mid = travel_ccw ? a1 + delta / 2 : a1 - delta / 2;
  return {cx + r * std::cos(mid), cy + r * std::sin(mid)};
}

const char* kind_text(const Halfspace2& h) {
  switch (h.kind) {
    case HalfspaceKind2::Halfplane: return "half-plane";
    case HalfspaceKind2::Disk: return "disk";
    case HalfspaceKind2::Polygon: return "polygon";
  }
  return "";
}

}  // namespace

std::string arrangement_svg(const Scene2& scene, const Arrangement2& arr, const Complex& c, const SvgOptions& o) {
  const auto& vertices = arr.vertices();
  const auto& edges = arr.edges();
  const auto& faces = arr.faces();
  if (c.cells.size() != faces.size())
    throw std::invalid_argument("arrangement_svg: the complex's cells are not the arrangement's faces");
  if (static_cast<std::size_t>(c.halfspace_count()) != scene.halfspaces.size())
    throw std::invalid_argument("arrangement_svg: the complex's halfspaces are not the scene's");
  for (const Patch& p : c.patches)
    for (int e : p.pieces)
      if (e < 0 || static_cast<std::size_t>(e) >= edges.size())
        throw std::invalid_argument("arrangement_svg: a patch piece is not an arrangement edge");
  if (c.samples.size() != scene.samples.size())
    throw std::invalid_argument("arrangement_svg: the complex's samples are not the scene's");

  const Box2& box = arr.domain();
  const double min_x = box.min.x.get_d(), max_x = box.max.x.get_d();
  const double min_y = box.min.y.get_d(), max_y = box.max.y.get_d();
  const double margin = 16;
  const double width = std::max(o.width, 100);
  const double title_height = o.title.empty() ? 0 : 26;
  const double draw_width = width - 2 * margin;
  View view;
  view.min_x = min_x;
  view.max_y = max_y;
  view.scale = max_x > min_x ? draw_width / (max_x - min_x) : 1;
  view.left = margin;
  view.top = margin + title_height;
  const double draw_height = (max_y - min_y) * view.scale;
  const std::size_t n_half = scene.halfspaces.size();
  const int columns = std::max(1, static_cast<int>(draw_width / 160));
  const int rows = static_cast<int>((n_half + columns - 1) / columns);
  const double legend_top = view.top + draw_height + 14;
  const double height = legend_top + rows * 18 + margin;

  std::string s;
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width) + "\" height=\"" + num(height) +
       "\" viewBox=\"0 0 " + num(width) + " " + num(height) + "\" font-family=\"Helvetica, Arial, sans-serif\">\n";
  s += "<rect x=\"0\" y=\"0\" width=\"" + num(width) + "\" height=\"" + num(height) + "\" fill=\"#ffffff\"/>\n";
  if (!o.title.empty()) {
    s += "<text class=\"title\" x=\"" + num(width / 2) + "\" y=\"" + num(margin + 14) +
         "\" text-anchor=\"middle\" font-size=\"15\">" + escape(o.title) + "</text>\n";
  }

  // Cells
  s += "<g stroke=\"none\" fill-rule=\"evenodd\">\n";
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Cell& cell = c.cells[f];
    const char* fill;
    if (!o.cell_fill.empty()) {
      const bool filled = f < o.cell_fill.size() && o.cell_fill[f];
      fill = filled ? "#9dbbe0" : (cell.outer ? "#fafafa" : "#f0f0f0");
    } else {
      const long count = std::count(cell.inside.begin(), cell.inside.end(), 1);
      if (cell.outer)
        fill = count % 2 ? "#ececec" : "#f7f7f7";
      else
        fill = count % 2 ? "#d2d2d2" : "#e4e4e4";
    }
    if (f < o.cell_marks.size() && o.cell_marks[f]) fill = o.cell_marks[f] == 1 ? "#f4a261" : "#e63946";
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
    s += "<path class=\"cell\" data-id=\"" + std::to_string(f) + "\" fill=\"" + fill + "\" d=\"" + d + "\"/>\n";
  }
  s += "</g>\n";
  s += "<rect class=\"domain\" x=\"" + num(view.X(min_x)) + "\" y=\"" + num(view.Y(max_y)) + "\" width=\"" +
       num(draw_width) + "\" height=\"" + num(draw_height) + "\" fill=\"none\" stroke=\"#999999\" stroke-width=\"0.8\"/>\n";

  // Patches
  std::vector<std::string> patch_d(c.patches.size());
  std::vector<std::pair<double, double>> patch_mid(c.patches.size(), {min_x, max_y});
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    const auto steps = patch_walk(edges, c.patches[p].pieces);
    std::string d;
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const auto& [ei, forward] = steps[k];
      const ArrEdge2& e = edges[ei];
      const OneRootPoint& from = vertices.at(forward ? e.source : e.target).point;
      const OneRootPoint& to = vertices.at(forward ? e.target : e.source).point;
      if (k == 0) d += "M " + view.xy(from);
      d += edge_commands(view, e, from, to, forward == e.ccw);
      if (k == steps.size() / 2) patch_mid[p] = edge_midpoint(e, from, to, forward == e.ccw);
    }
    patch_d[p] = d;
  }
  s += "<g fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    if (p < o.highlight_patches.size() && o.highlight_patches[p]) {
      s += "<path class=\"highlight\" data-id=\"" + std::to_string(p) +
           "\" stroke=\"#ffc400\" stroke-opacity=\"0.6\" stroke-width=\"9\" d=\"" + patch_d[p] + "\"/>\n";
    }
  }
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
         "\" stroke-width=\"2.5\"" + dash + " d=\"" + patch_d[p] + "\"/>\n";
  }
  s += "</g>\n";

  // Samples: a tick along the outward normal, then the dot.
  s += "<g>\n";
  for (std::size_t k = 0; k < scene.samples.size(); ++k) {
    const Sample2& sample = scene.samples[k];
    if (sample.halfspace < 0 || static_cast<std::size_t>(sample.halfspace) >= n_half) continue;
    const double x = sample.location.x.to_double(), y = sample.location.y.to_double();
    const auto [nx, ny] = outward_normal(scene.halfspaces[sample.halfspace], x, y);
    const double sx = view.X(x), sy = view.Y(y);
    const double tick = 12;
    s += "<line class=\"tick\" x1=\"" + num(sx) + "\" y1=\"" + num(sy) + "\" x2=\"" + num(sx + tick * nx) +
         "\" y2=\"" + num(sy - tick * ny) + "\" stroke=\"" + colour_of(sample.halfspace) +
         "\" stroke-width=\"1.8\"/>\n";
  }
  for (std::size_t k = 0; k < scene.samples.size(); ++k) {
    const Sample2& sample = scene.samples[k];
    const double x = sample.location.x.to_double(), y = sample.location.y.to_double();
    s += "<circle class=\"sample\" data-id=\"" + std::to_string(k) + "\" cx=\"" + num(view.X(x)) + "\" cy=\"" +
         num(view.Y(y)) + "\" r=\"3.5\" fill=\"" + colour_of(sample.halfspace) +
         "\" stroke=\"#000000\" stroke-width=\"0.8\"/>\n";
  }
  s += "</g>\n";

  // Labels
  if (o.show_cell_ids || o.show_patch_ids) {
    s += "<g font-size=\"10\" text-anchor=\"middle\" stroke=\"#ffffff\" stroke-width=\"2.5\" "
         "paint-order=\"stroke\">\n";
    if (o.show_cell_ids) {
      for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto& w = c.cells[f].witness;
        const double x = w.size() == 2 ? w[0].get_d() : faces[f].interior.x.get_d();
        const double y = w.size() == 2 ? w[1].get_d() : faces[f].interior.y.get_d();
        s += "<text class=\"cell-id\" x=\"" + num(view.X(x)) + "\" y=\"" + num(view.Y(y) + 3.5) +
             "\" fill=\"#555555\">c" + std::to_string(f) + "</text>\n";
      }
    }
    if (o.show_patch_ids) {
      for (std::size_t p = 0; p < c.patches.size(); ++p) {
        s += "<text class=\"patch-id\" x=\"" + num(view.X(patch_mid[p].first)) + "\" y=\"" +
             num(view.Y(patch_mid[p].second) - 4) + "\" fill=\"" + colour_of(c.patches[p].halfspace) + "\">p" +
             std::to_string(p) + "</text>\n";
      }
    }
    s += "</g>\n";
  }

  // Legend
  s += "<g class=\"legend\" font-size=\"12\">\n";
  const double column_width = draw_width / columns;
  for (std::size_t i = 0; i < n_half; ++i) {
    const Halfspace2& h = scene.halfspaces[i];
    const double x = margin + static_cast<double>(i % columns) * column_width;
    const double y = legend_top + static_cast<double>(i / columns) * 18 + 9;
    s += "<line x1=\"" + num(x) + "\" y1=\"" + num(y) + "\" x2=\"" + num(x + 22) + "\" y2=\"" + num(y) +
         "\" stroke=\"" + colour_of(static_cast<int>(i)) + "\" stroke-width=\"3\"/>\n";
    s += "<text x=\"" + num(x + 28) + "\" y=\"" + num(y + 4) + "\" fill=\"#222222\">" + escape(h.name) + " (" +
         kind_text(h) + (h.complement ? ", complement" : "") + ")</text>\n";
  }
  s += "</g>\n";
  s += "</svg>\n";
  return s;
}

const char* svg_palette_colour(int index) { return colour_of(index); }

std::string svg_number(double value) { return num(value); }

std::string svg_escape(const std::string& text) { return escape(text); }

std::string svg_edge_commands(const SvgView& v, const ArrEdge2& edge, const OneRootPoint& from,
                              const OneRootPoint& to, bool travel_ccw) {
  return edge_commands(View{v.min_x, v.max_y, v.scale, v.left, v.top}, edge, from, to, travel_ccw);
}

}  // namespace hsx
