// SVG of a 2D NH-Rep patch layout: see nhrep_svg.hpp.
#include <hsx/io/nhrep_svg.hpp>

#include "geometry/planar_corners.hpp"
#include <hsx/io/svg.hpp>
#include <hsx/io/svg3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <utility>

namespace hsx {

const char* feature_type_colour(FeatureType type) {
  switch (type) {
    case FeatureType::Convex: return "#e41a1c";
    case FeatureType::Concave: return "#377eb8";
    case FeatureType::Smooth: return "#4daf4a";
    case FeatureType::Hybrid: return "#984ea3";
  }
  return "#000000";
}

namespace {

struct Frame {
  SvgView view;
  double X(double x) const { return view.left + (x - view.min_x) * view.scale; }
  double Y(double y) const { return view.top + (view.max_y - y) * view.scale; }
  std::string xy(double x, double y) const { return svg_number(X(x)) + " " + svg_number(Y(y)); }
  std::string xy(const OneRootPoint& p) const { return xy(p.x.to_double(), p.y.to_double()); }
};

/// The drawn extent of a piece: along `edge` from `from` to `to`, turning counter-clockwise iff travel_ccw.
struct Span {
  const ArrEdge2* edge = nullptr;
  OneRootPoint from, to;
  bool travel_ccw = false;
};

/// The point halfway (in doubles) along a span, for labels.
std::pair<double, double> span_middle(const Span& s) {
  const double px = s.from.x.to_double(), py = s.from.y.to_double();
  const double qx = s.to.x.to_double(), qy = s.to.y.to_double();
  if (s.edge->shape == EdgeShape2::Segment) return {(px + qx) / 2, (py + qy) / 2};
  const double cx = s.edge->center.x.get_d(), cy = s.edge->center.y.get_d(), r = s.edge->radius.get_d();
  const double a1 = std::atan2(py - cy, px - cx), a2 = std::atan2(qy - cy, qx - cx);
  double delta = s.travel_ccw ? a2 - a1 : a1 - a2;
  while (delta <= 0) delta += 2 * M_PI;
  while (delta > 2 * M_PI) delta -= 2 * M_PI;
  const double mid = s.travel_ccw ? a1 + delta / 2 : a1 - delta / 2;
  return {cx + r * std::cos(mid), cy + r * std::sin(mid)};
}

}  // namespace

std::string nhrep_svg(const Scene2& scene, const Arranged2& arranged, const std::vector<char>& solid_cells,
                      const BoundarySurface& surface, const std::vector<int>& piece_patch,
                      const std::vector<int>& patch_colour_group, const std::string& title, int width_px) {
  const Arrangement2& arr = arranged.arrangement;
  const auto& vertices = arr.vertices();
  const auto& edges = arr.edges();
  const auto& faces = arr.faces();
  auto fail = [](const std::string& why) { throw std::invalid_argument("nhrep_svg: " + why); };
  if (surface.dimension != 2) fail("the boundary is not 2D");
  if (solid_cells.size() != faces.size()) fail("one solid flag per cell expected");
  if (static_cast<std::size_t>(arr.halfspace_count()) != scene.halfspaces.size())
    fail("the arrangement's halfspaces are not the scene's");
  if (piece_patch.size() != surface.pieces.size()) fail("one patch id per piece expected");

  // Exact geometry of every live piece.
  std::map<int, PointQ2> split_points;  // edge -> split point, computed once per split edge
  auto split_point = [&](int edge) -> const PointQ2& {
    auto it = split_points.find(edge);
    if (it == split_points.end()) it = split_points.emplace(edge, edge_split_point(arr, edge)).first;
    return it->second;
  };
  std::vector<Span> spans(surface.pieces.size());
  std::vector<int> patch_first_piece;  // per patch id, its lowest live piece
  for (std::size_t p = 0; p < surface.pieces.size(); ++p) {
    const BoundaryPiece& piece = surface.pieces[p];
    if (piece.retired) continue;
    const std::string name = "piece " + std::to_string(p);
    if (piece.origin < 0 || static_cast<std::size_t>(piece.origin) >= edges.size())
      fail(name + ": origin is not an arrangement edge");
    const int patch = piece_patch[p];
    if (patch < 0) fail(name + ": live but in no patch");
    if (!patch_colour_group.empty() && static_cast<std::size_t>(patch) >= patch_colour_group.size())
      fail(name + ": patch " + std::to_string(patch) + " has no colour group");
    if (static_cast<std::size_t>(patch) >= patch_first_piece.size()) patch_first_piece.resize(patch + 1, -1);
    if (patch_first_piece[patch] < 0) patch_first_piece[patch] = static_cast<int>(p);
    const ArrEdge2& e = edges[static_cast<std::size_t>(piece.origin)];
    Span& s = spans[p];
    s.edge = &e;
    if (piece.split_of < 0) {
      s.from = vertices.at(e.source).point;
      s.to = vertices.at(e.target).point;
      s.travel_ccw = e.ccw;
      continue;
    }
    if (piece.kept_link < 0 || static_cast<std::size_t>(piece.kept_link) >= surface.links.size())
      fail(name + ": split piece without a kept link");
    const int v = surface.links[static_cast<std::size_t>(piece.kept_link)].origin;
    if (v != e.source && v != e.target) fail(name + ": its kept link is not at an end of its edge");
    s.from = vertices.at(v).point;
    s.to = OneRootPoint(split_point(piece.origin));
    s.travel_ccw = (v == e.source) == e.ccw;
  }

  // Where each feature link is drawn.
  std::vector<std::pair<int, OneRootPoint>> dots;  // link, position
  for (std::size_t l = 0; l < surface.links.size(); ++l) {
    const BoundaryLink& link = surface.links[l];
    if (!link.feature) continue;
    if (link.origin >= 0) {
      if (static_cast<std::size_t>(link.origin) >= vertices.size()) fail("link origin is not a vertex");
      dots.emplace_back(static_cast<int>(l), vertices[static_cast<std::size_t>(link.origin)].point);
      continue;
    }
    const int a = link.piece_a, b = link.piece_b;
    if (a < 0 || b < 0 || static_cast<std::size_t>(a) >= surface.pieces.size() ||
        static_cast<std::size_t>(b) >= surface.pieces.size())
      fail("link " + std::to_string(l) + ": piece out of range");
    const BoundaryPiece& pa = surface.pieces[static_cast<std::size_t>(a)];
    const BoundaryPiece& pb = surface.pieces[static_cast<std::size_t>(b)];
    if (pa.split_of < 0 || pa.split_of != pb.split_of)
      fail("link " + std::to_string(l) + ": no vertex and not between two halves of one edge");
    dots.emplace_back(static_cast<int>(l), OneRootPoint(split_point(pa.origin)));
  }

  // Layout, as arrangement_svg.
  const Box2& box = arr.domain();
  const double min_x = box.min.x.get_d(), max_x = box.max.x.get_d();
  const double min_y = box.min.y.get_d(), max_y = box.max.y.get_d();
  const double margin = 16;
  const double width = std::max(width_px, 100);
  const double title_height = title.empty() ? 0 : 26;
  const double draw_width = width - 2 * margin;
  Frame frame;
  frame.view.min_x = min_x;
  frame.view.max_y = max_y;
  frame.view.scale = max_x > min_x ? draw_width / (max_x - min_x) : 1;
  frame.view.left = margin;
  frame.view.top = margin + title_height;
  const double draw_height = (max_y - min_y) * frame.view.scale;
  const double legend_top = frame.view.top + draw_height + 14;
  const double height = legend_top + 18 + margin;
  auto* const n = &svg_number;

  std::string s;
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + n(width) + "\" height=\"" + n(height) +
       "\" viewBox=\"0 0 " + n(width) + " " + n(height) + "\" font-family=\"Helvetica, Arial, sans-serif\">\n";
  s += "<rect x=\"0\" y=\"0\" width=\"" + n(width) + "\" height=\"" + n(height) + "\" fill=\"#ffffff\"/>\n";
  if (!title.empty())
    s += "<text class=\"title\" x=\"" + n(width / 2) + "\" y=\"" + n(margin + 14) +
         "\" text-anchor=\"middle\" font-size=\"15\">" + svg_escape(title) + "</text>\n";

  // The solid.
  s += "<g stroke=\"none\" fill-rule=\"evenodd\" fill=\"#9dbbe0\">\n";
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!solid_cells[f]) continue;
    std::string d;
    for (const auto& walk : faces[f].boundary) {
      bool first = true;
      for (const auto& [ei, forward] : walk) {
        const ArrEdge2& e = edges.at(static_cast<std::size_t>(ei));
        const OneRootPoint& p = vertices.at(forward ? e.source : e.target).point;
        const OneRootPoint& q = vertices.at(forward ? e.target : e.source).point;
        if (first) d += (d.empty() ? "M " : " M ") + frame.xy(p);
        first = false;
        d += svg_edge_commands(frame.view, e, p, q, forward == e.ccw);
      }
      if (!walk.empty()) d += " Z";
    }
    s += "<path class=\"cell\" data-id=\"" + std::to_string(f) + "\" d=\"" + d + "\"/>\n";
  }
  s += "</g>\n";

  // The rest of the arrangement, for context.
  std::vector<char> on_boundary(edges.size(), 0);
  for (const BoundaryPiece& piece : surface.pieces)
    if (piece.origin >= 0 && static_cast<std::size_t>(piece.origin) < edges.size()) on_boundary[piece.origin] = 1;
  s += "<g fill=\"none\" stroke=\"#c8c8c8\" stroke-width=\"0.8\">\n";
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (on_boundary[e] || edges[e].on_box) continue;
    const ArrEdge2& edge = edges[e];
    const OneRootPoint& p = vertices.at(edge.source).point;
    const OneRootPoint& q = vertices.at(edge.target).point;
    s += "<path class=\"edge\" d=\"M " + frame.xy(p) + svg_edge_commands(frame.view, edge, p, q, edge.ccw) + "\"/>\n";
  }
  s += "</g>\n";
  s += "<rect class=\"domain\" x=\"" + n(frame.X(min_x)) + "\" y=\"" + n(frame.Y(max_y)) + "\" width=\"" +
       n(draw_width) + "\" height=\"" + n(draw_height) + "\" fill=\"none\" stroke=\"#999999\" stroke-width=\"0.8\"/>\n";

  // Pieces, coloured by patch (or its group).
  auto colour_index = [&](int patch) { return patch_colour_group.empty() ? patch : patch_colour_group[patch]; };
  s += "<g fill=\"none\" stroke-width=\"3\" stroke-linecap=\"butt\">\n";
  for (std::size_t p = 0; p < surface.pieces.size(); ++p) {
    if (surface.pieces[p].retired) continue;
    const Span& sp = spans[p];
    s += "<path class=\"piece\" data-id=\"" + std::to_string(p) + "\" data-patch=\"" + std::to_string(piece_patch[p]) +
         "\" stroke=\"" + svg_palette_colour(colour_index(piece_patch[p])) + "\" d=\"M " + frame.xy(sp.from) +
         svg_edge_commands(frame.view, *sp.edge, sp.from, sp.to, sp.travel_ccw) + "\"/>\n";
  }
  s += "</g>\n";

  // Feature corners.
  s += "<g stroke=\"#000000\" stroke-width=\"0.8\">\n";
  for (const auto& [l, at] : dots) {
    const FeatureType type = surface.links[static_cast<std::size_t>(l)].type;
    s += "<circle class=\"feature\" data-id=\"" + std::to_string(l) + "\" data-type=\"" + feature_type_name(type) +
         "\" cx=\"" + n(frame.X(at.x.to_double())) + "\" cy=\"" + n(frame.Y(at.y.to_double())) +
         "\" r=\"4\" fill=\"" + feature_type_colour(type) + "\"/>\n";
  }
  s += "</g>\n";

  // Patch labels at the middle of each patch's lowest piece, with the carrier ("~" when complemented).
  s += "<g font-size=\"11\" text-anchor=\"middle\" stroke=\"#ffffff\" stroke-width=\"2.5\" paint-order=\"stroke\">\n";
  for (std::size_t patch = 0; patch < patch_first_piece.size(); ++patch) {
    const int p = patch_first_piece[patch];
    if (p < 0) continue;
    const BoundaryPiece& piece = surface.pieces[static_cast<std::size_t>(p)];
    std::string label = "P" + std::to_string(patch);
    if (piece.carrier >= 0 && static_cast<std::size_t>(piece.carrier) < scene.halfspaces.size())
      label += " " + std::string(piece.carrier_complemented ? "~" : "") + scene.halfspaces[piece.carrier].name;
    const auto [x, y] = span_middle(spans[static_cast<std::size_t>(p)]);
    s += "<text class=\"patch-id\" x=\"" + n(frame.X(x)) + "\" y=\"" + n(frame.Y(y) - 5) + "\" fill=\"" +
         svg_palette_colour(colour_index(static_cast<int>(patch))) + "\">" + svg_escape(label) + "</text>\n";
  }
  s += "</g>\n";

  // Legend: the corner types.
  s += "<g class=\"legend\" font-size=\"12\">\n";
  double x = margin;
  const double y = legend_top + 9;
  for (FeatureType type : {FeatureType::Convex, FeatureType::Concave, FeatureType::Smooth}) {
    s += "<circle cx=\"" + n(x + 5) + "\" cy=\"" + n(y) + "\" r=\"4\" fill=\"" + feature_type_colour(type) +
         "\" stroke=\"#000000\" stroke-width=\"0.8\"/>\n";
    s += "<text x=\"" + n(x + 14) + "\" y=\"" + n(y + 4) + "\" fill=\"#222222\">" + feature_type_name(type) +
         " corner</text>\n";
    x += 120;
  }
  s += "</g>\n";
  s += "</svg>\n";
  return s;
}

namespace {

struct V3 {
  double x = 0, y = 0, z = 0;
};
V3 to_v3(const PointQ3& p) { return {p.x.get_d(), p.y.get_d(), p.z.get_d()}; }
V3 minus(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 cross3(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot3(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 unit(V3 a) {
  const double n = std::sqrt(dot3(a, a));
  return n > 0 ? V3{a.x / n, a.y / n, a.z / n} : a;
}

std::string shade(const char* hex, double light) {
  unsigned r = 0, g = 0, b = 0;
  std::sscanf(hex, "#%02x%02x%02x", &r, &g, &b);
  auto c = [&](unsigned v) { return std::min(255, static_cast<int>(std::lround(v * light))); };
  char out[8];
  std::snprintf(out, sizeof out, "#%02x%02x%02x", c(r), c(g), c(b));
  return out;
}

}  // namespace

std::string nhrep_svg3(const Scene3& scene, const Arranged3& arranged, const std::vector<char>& solid_cells,
                       const BoundarySurface& surface, const std::vector<int>& piece_patch,
                       const std::vector<int>& patch_colour_group, const std::string& title, int width_px) {
  const Arrangement3& arr = arranged.arrangement;
  auto fail = [](const std::string& why) { throw std::invalid_argument("nhrep_svg3: " + why); };
  if (surface.dimension != 3) fail("the boundary is not 3D");
  if (solid_cells.size() != arr.cells().size()) fail("one solid flag per cell expected");
  if (static_cast<std::size_t>(arr.halfspace_count()) != scene.halfspaces.size())
    fail("the arrangement's halfspaces are not the scene's");
  if (piece_patch.size() != surface.pieces.size()) fail("one patch id per piece expected");
  const auto& tris = arr.triangles();
  const auto& verts = arr.vertices();
  const auto& edges = arr.edges();

  // Each live piece as a triangle in doubles.
  struct Drawn {
    int piece = -1, patch = -1;
    V3 p[3];
  };
  std::vector<Drawn> drawn;
  std::vector<int> first_piece;  // per patch, index into drawn of its lowest piece
  for (std::size_t k = 0; k < surface.pieces.size(); ++k) {
    const BoundaryPiece& piece = surface.pieces[k];
    if (piece.retired) continue;
    if (piece.origin < 0 || static_cast<std::size_t>(piece.origin) >= tris.size())
      fail("piece " + std::to_string(k) + ": origin is not an arrangement triangle");
    const int patch = piece_patch[k];
    if (patch < 0) fail("piece " + std::to_string(k) + ": live but in no patch");
    if (!patch_colour_group.empty() && static_cast<std::size_t>(patch) >= patch_colour_group.size())
      fail("piece " + std::to_string(k) + ": patch " + std::to_string(patch) + " has no colour group");
    const ArrTriangle3& t = tris[static_cast<std::size_t>(piece.origin)];
    Drawn d;
    d.piece = static_cast<int>(k);
    d.patch = patch;
    for (int i = 0; i < 3; ++i) d.p[i] = to_v3(verts.at(static_cast<std::size_t>(t.vertices[static_cast<std::size_t>(i)])));
    if (piece.split_of >= 0 && piece.kept_link >= 0 && static_cast<std::size_t>(piece.kept_link) < surface.links.size()) {
      const int e = surface.links[static_cast<std::size_t>(piece.kept_link)].origin;
      if (e >= 0 && static_cast<std::size_t>(e) < edges.size()) {
        const V3 c{(d.p[0].x + d.p[1].x + d.p[2].x) / 3, (d.p[0].y + d.p[1].y + d.p[2].y) / 3,
                   (d.p[0].z + d.p[1].z + d.p[2].z) / 3};
        d.p[0] = c;
        d.p[1] = to_v3(verts.at(static_cast<std::size_t>(edges[static_cast<std::size_t>(e)].a)));
        d.p[2] = to_v3(verts.at(static_cast<std::size_t>(edges[static_cast<std::size_t>(e)].b)));
      }
    }
    if (static_cast<std::size_t>(patch) >= first_piece.size()) first_piece.resize(static_cast<std::size_t>(patch) + 1, -1);
    if (first_piece[static_cast<std::size_t>(patch)] < 0) first_piece[static_cast<std::size_t>(patch)] = static_cast<int>(drawn.size());
    drawn.push_back(d);
  }

  // Views: screen axes of io/svg3.hpp's default views, one scale fitted to the domain box's corners.
  struct View {
    std::string name;
    V3 dir, right, up;
  };
  std::vector<View> views;
  for (const SvgView3& v : default_svg_views3()) {
    View w;
    w.name = v.name;
    w.dir = unit(to_v3(v.direction));
    const V3 up = to_v3(v.up);
    w.right = unit(cross3(w.dir, up));
    w.up = unit(cross3(w.right, w.dir));
    views.push_back(w);
  }
  const Box3& box = arr.domain();
  std::vector<V3> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back(to_v3({i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z}));
  double extent = 0;
  std::vector<std::pair<double, double>> centre(views.size());
  for (std::size_t v = 0; v < views.size(); ++v) {
    double lx = 1e300, hx = -1e300, ly = 1e300, hy = -1e300;
    for (const V3& c : corners) {
      const double x = dot3(c, views[v].right), y = dot3(c, views[v].up);
      lx = std::min(lx, x), hx = std::max(hx, x), ly = std::min(ly, y), hy = std::max(hy, y);
    }
    extent = std::max({extent, hx - lx, hy - ly});
    centre[v] = {(lx + hx) / 2, (ly + hy) / 2};
  }
  const double width = std::max(width_px, 200);
  const double cell = width / 2, margin = 12, title_height = title.empty() ? 0 : 26;
  const double scale = extent > 0 ? (cell - 2 * margin - 18) / extent : 1;
  const std::size_t rows = (views.size() + 1) / 2;
  const double legend_top = title_height + rows * cell + 6, legend_line = 20;
  // Second legend line: the patches of each colour (a tree node's leaves), when colours are groups.
  std::map<int, std::vector<int>> group_patches;
  if (!patch_colour_group.empty())
    for (std::size_t patch = 0; patch < first_piece.size(); ++patch)
      if (first_piece[patch] >= 0) group_patches[patch_colour_group[patch]].push_back(static_cast<int>(patch));
  const double height = legend_top + (group_patches.empty() ? 1 : 2) * legend_line + 4;
  auto* const n = &svg_number;
  const V3 light = unit({-0.3, 0.5, 0.8});
  auto colour_index = [&](int patch) { return patch_colour_group.empty() ? patch : patch_colour_group[static_cast<std::size_t>(patch)]; };

  std::string s;
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + n(width) + "\" height=\"" + n(height) +
       "\" viewBox=\"0 0 " + n(width) + " " + n(height) + "\" font-family=\"Helvetica, Arial, sans-serif\">\n";
  s += "<rect x=\"0\" y=\"0\" width=\"" + n(width) + "\" height=\"" + n(height) + "\" fill=\"#ffffff\"/>\n";
  if (!title.empty()) {
    // A long tree's title is set smaller to fit the width (down to 8 px; beyond that it runs over).
    const double fits = 15 * (width - 2 * margin) / std::max(1.0, svg_text_width(title, 15));
    s += "<text class=\"title\" x=\"" + n(width / 2) + "\" y=\"18\" text-anchor=\"middle\" font-size=\"" +
         n(std::clamp(fits, 8.0, 15.0)) + "\">" + svg_escape(title) + "</text>\n";
  }
  for (std::size_t v = 0; v < views.size(); ++v) {
    const View& w = views[v];
    const double left = (v % 2) * cell, top = title_height + (v / 2) * cell;
    auto X = [&](V3 p) { return left + cell / 2 + (dot3(p, w.right) - centre[v].first) * scale; };
    auto Y = [&](V3 p) { return top + 18 + (cell - 18) / 2 - (dot3(p, w.up) - centre[v].second) * scale; };
    s += "<g class=\"view\" data-name=\"" + w.name + "\">\n";
    s += "<text x=\"" + n(left + cell / 2) + "\" y=\"" + n(top + 14) + "\" text-anchor=\"middle\" font-size=\"12\">" +
         w.name + "</text>\n";
    std::vector<std::pair<double, int>> order;
    for (std::size_t k = 0; k < drawn.size(); ++k) {
      const Drawn& d = drawn[k];
      const V3 c{(d.p[0].x + d.p[1].x + d.p[2].x) / 3, (d.p[0].y + d.p[1].y + d.p[2].y) / 3,
                 (d.p[0].z + d.p[1].z + d.p[2].z) / 3};
      order.emplace_back(-dot3(c, w.dir), static_cast<int>(k));  // far first: larger depth along dir
    }
    std::sort(order.begin(), order.end());
    for (const auto& [depth, k] : order) {
      const Drawn& d = drawn[static_cast<std::size_t>(k)];
      const V3 normal = unit(cross3(minus(d.p[1], d.p[0]), minus(d.p[2], d.p[0])));
      const double lit = 0.35 + 0.65 * std::fabs(dot3(normal, light));
      s += "<polygon class=\"piece\" data-id=\"" + std::to_string(d.piece) + "\" data-patch=\"" +
           std::to_string(d.patch) + "\" fill=\"" + shade(svg_palette_colour(colour_index(d.patch)), lit) +
           "\" fill-opacity=\"0.85\" stroke=\"none\" points=\"";
      for (int i = 0; i < 3; ++i) s += (i ? " " : "") + n(X(d.p[i])) + "," + n(Y(d.p[i]));
      s += "\"/>\n";
    }
    for (std::size_t l = 0; l < surface.links.size(); ++l) {
      const BoundaryLink& link = surface.links[l];
      if (!link.feature || link.origin < 0 || static_cast<std::size_t>(link.origin) >= edges.size()) continue;
      const ArrEdge3& e = edges[static_cast<std::size_t>(link.origin)];
      const V3 a = to_v3(verts.at(static_cast<std::size_t>(e.a))), b = to_v3(verts.at(static_cast<std::size_t>(e.b)));
      s += "<line class=\"feature\" data-id=\"" + std::to_string(l) + "\" data-type=\"" + feature_type_name(link.type) +
           "\" x1=\"" + n(X(a)) + "\" y1=\"" + n(Y(a)) + "\" x2=\"" + n(X(b)) + "\" y2=\"" + n(Y(b)) + "\" stroke=\"" +
           feature_type_colour(link.type) + "\" stroke-width=\"1.5\"/>\n";
    }
    for (std::size_t patch = 0; patch < first_piece.size(); ++patch) {
      if (first_piece[patch] < 0) continue;
      const Drawn& d = drawn[static_cast<std::size_t>(first_piece[patch])];
      const BoundaryPiece& piece = surface.pieces[static_cast<std::size_t>(d.piece)];
      std::string label = "P" + std::to_string(patch);
      if (piece.carrier >= 0 && static_cast<std::size_t>(piece.carrier) < scene.halfspaces.size())
        label += " " + std::string(piece.carrier_complemented ? "~" : "") +
                 scene.halfspaces[static_cast<std::size_t>(piece.carrier)].name;
      const V3 c{(d.p[0].x + d.p[1].x + d.p[2].x) / 3, (d.p[0].y + d.p[1].y + d.p[2].y) / 3,
                 (d.p[0].z + d.p[1].z + d.p[2].z) / 3};
      s += "<text class=\"patch-id\" x=\"" + n(X(c)) + "\" y=\"" + n(Y(c)) + "\" font-size=\"10\" text-anchor=\"middle\" "
           "stroke=\"#ffffff\" stroke-width=\"2\" paint-order=\"stroke\">" + svg_escape(label) + "</text>\n";
    }
    s += "</g>\n";
  }
  s += "<g class=\"legend\" font-size=\"12\">\n";
  double x = margin;
  for (FeatureType type : {FeatureType::Convex, FeatureType::Concave, FeatureType::Smooth}) {
    const std::string text = std::string(feature_type_name(type)) + " feature edge";
    s += "<line x1=\"" + n(x) + "\" y1=\"" + n(legend_top + 9) + "\" x2=\"" + n(x + 16) + "\" y2=\"" + n(legend_top + 9) +
         "\" stroke=\"" + feature_type_colour(type) + "\" stroke-width=\"2\"/>\n";
    s += "<text x=\"" + n(x + 20) + "\" y=\"" + n(legend_top + 13) + "\" fill=\"#222222\">" + text + "</text>\n";
    x += 20 + svg_text_width(text, 12) + 18;
  }
  x = margin;
  const double y = legend_top + legend_line;
  if (!group_patches.empty()) {
    const std::string heading = "patches by tree node:";
    s += "<text x=\"" + n(x) + "\" y=\"" + n(y + 13) + "\" fill=\"#222222\">" + heading + "</text>\n";
    x += svg_text_width(heading, 12) + 10;
  }
  for (const auto& [group, patches] : group_patches) {
    std::string text;
    for (std::size_t k = 0; k < patches.size() && k < 6; ++k) text += (k ? " P" : "P") + std::to_string(patches[k]);
    if (patches.size() > 6) text += " ...";
    s += "<rect class=\"node-swatch\" x=\"" + n(x) + "\" y=\"" + n(y + 3) + "\" width=\"16\" height=\"11\" fill=\"" +
         svg_palette_colour(group) + "\"/>\n";
    s += "<text x=\"" + n(x + 20) + "\" y=\"" + n(y + 13) + "\" fill=\"#222222\">" + text + "</text>\n";
    x += 20 + svg_text_width(text, 12) + 14;
  }
  s += "</g>\n</svg>\n";
  return s;
}

}  // namespace hsx
