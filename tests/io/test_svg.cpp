#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/io/svg.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace hsx;

namespace {

Rational q(const char* text) { return *parse_rational(text); }

Scene2 picture_scene() {
  Scene2 s;
  s.domain = Box2{PointQ2{q("-6"), q("-5")}, PointQ2{q("8"), q("6")}};
  s.domain_given = true;
  Halfspace2 a;
  a.name = "A<&>";
  a.kind = HalfspaceKind2::Disk;
  a.center = PointQ2{q("0"), q("0")};
  a.radius = q("2");
  Halfspace2 b;
  b.name = "B";
  b.kind = HalfspaceKind2::Halfplane;
  b.normal = PointQ2{q("0"), q("1")};
  b.offset = q("1");
  Halfspace2 c;
  c.name = "C";
  c.kind = HalfspaceKind2::Polygon;
  c.vertices = {PointQ2{q("4"), q("-1")}, PointQ2{q("1"), q("-1")}, PointQ2{q("1"), q("2")}, PointQ2{q("4"), q("2")}};
  Halfspace2 d;
  d.name = "D";
  d.kind = HalfspaceKind2::Disk;
  d.center = PointQ2{q("5"), q("4")};
  d.radius = q("1");
  d.complement = true;
  s.halfspaces = {a, b, c, d};
  auto sample = [](int h, const char* x, const char* y, bool snapped) {
    Sample2 t;
    t.halfspace = h;
    t.given = PointQ2{q(x), q(y)};
    t.snapped = snapped;
    return t;
  };
  s.samples = {sample(0, "-2", "0", false), sample(1, "-4", "1", false), sample(2, "4", "0", false),
               sample(2, "5/2", "-1", false), sample(3, "6", "4", false), sample(0, "1", "-1", true)};
  validate_and_resolve(s);
  return s;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

/// Tags nest properly (a minimal well-formedness check: no comments, CDATA or processing instructions are used).
bool tags_balanced(const std::string& s) {
  std::vector<std::string> stack;
  for (std::size_t i = s.find('<'); i != std::string::npos; i = s.find('<', i + 1)) {
    const std::size_t end = s.find('>', i);
    if (end == std::string::npos) return false;
    const std::string tag = s.substr(i + 1, end - i - 1);
    if (tag.empty()) return false;
    if (tag[0] == '/') {
      if (stack.empty() || stack.back() != tag.substr(1)) return false;
      stack.pop_back();
    } else if (tag.back() != '/') {
      stack.push_back(tag.substr(0, tag.find_first_of(" \n")));
    }
    if (tag.find('<') != std::string::npos) return false;
  }
  return stack.empty();
}

}  // namespace

TEST_CASE("arrangement SVG is well formed and deterministic", "[io][svg]") {
  const Scene2 scene = picture_scene();
  const Arranged2 arranged = arrange(scene);
  const Complex& c = arranged.complex;
  SvgOptions options;
  options.title = "Figure <1> & more";
  const std::string svg = arrangement_svg(scene, arranged.arrangement, c, options);
  CHECK(svg.rfind("<svg", 0) == 0);
  CHECK(svg.size() > 7);
  CHECK(svg.substr(svg.size() - 7) == "</svg>\n");
  CHECK(tags_balanced(svg));
  CHECK(count(svg, "class=\"patch\"") == c.patches.size());
  CHECK(count(svg, "<circle class=\"sample\"") == scene.samples.size());
  CHECK(count(svg, "class=\"tick\"") == scene.samples.size());
  CHECK(count(svg, "class=\"cell\"") == c.cells.size());
  CHECK(count(svg, "class=\"highlight\"") == 0);
  CHECK(count(svg, "class=\"cell-id\"") == 0);
  CHECK(svg.find(" A ") != std::string::npos);  // arcs are drawn as arcs
  CHECK(svg.find("Figure &lt;1&gt; &amp; more") != std::string::npos);
  CHECK(svg.find("A&lt;&amp;&gt; (disk)") != std::string::npos);
  CHECK(svg.find("D (disk, complement)") != std::string::npos);
  CHECK(svg.find("nan") == std::string::npos);
  CHECK(svg.find("inf") == std::string::npos);
  CHECK(svg == arrangement_svg(scene, arranged.arrangement, c, options));
}

TEST_CASE("arrangement SVG options", "[io][svg]") {
  const Scene2 scene = picture_scene();
  const Arranged2 arranged = arrange(scene);
  const Complex& c = arranged.complex;
  SvgOptions options;
  options.width = 500;
  options.show_cell_ids = true;
  options.show_patch_ids = true;
  options.highlight_patches.assign(c.patches.size(), 0);
  options.highlight_patches[0] = 1;
  options.cell_fill.assign(c.cells.size(), 0);
  for (std::size_t k = 0; k < c.cells.size(); ++k) options.cell_fill[k] = !c.cells[k].outer && c.cells[k].inside[0];
  const std::string svg = arrangement_svg(scene, arranged.arrangement, c, options);
  CHECK(tags_balanced(svg));
  CHECK(svg.find("width=\"500.0000\"") != std::string::npos);
  CHECK(count(svg, "class=\"highlight\"") == 1);
  CHECK(count(svg, "class=\"cell-id\"") == c.cells.size());
  CHECK(count(svg, "class=\"patch-id\"") == c.patches.size());
  CHECK(count(svg, "#9dbbe0") >= 1);  // filled cells
  CHECK(svg != arrangement_svg(scene, arranged.arrangement, c, {}));

  Complex wrong = c;
  wrong.cells.pop_back();
  CHECK_THROWS_AS(arrangement_svg(scene, arranged.arrangement, wrong, {}), std::invalid_argument);
}

TEST_CASE("sample ticks point out of their halfspace", "[io][svg]") {
  // One sample per halfspace kind; the tick's end must be outside the halfspace (in scene coordinates).
  const Scene2 scene = picture_scene();
  const Arranged2 arranged = arrange(scene);
  SvgOptions options;
  options.width = 1400;  // scale (1400 - 2*16) / 14 px per unit, no title
  const std::string svg = arrangement_svg(scene, arranged.arrangement, arranged.complex, options);
  std::size_t at = 0;
  for (std::size_t k = 0; k < scene.samples.size(); ++k) {
    at = svg.find("<line class=\"tick\"", at + 1);
    REQUIRE(at != std::string::npos);
    auto attr = [&](const char* name) {
      const std::size_t p = svg.find(std::string(name) + "=\"", at) + std::string(name).size() + 2;
      return std::stod(svg.substr(p, svg.find('"', p) - p));
    };
    const double scale = (1400.0 - 32) / 14;
    const double x = (attr("x2") - 16) / scale - 6;
    const double y = 6 - (attr("y2") - 16) / scale;
    const PointQ2 end{Rational(x), Rational(y)};
    INFO("sample " << k << " tick end " << x << ", " << y);
    CHECK(scene.halfspaces[scene.samples[k].halfspace].side(end) < 0);
  }
}

// ---- labels, legend, boundary and missing samples (issue 9, section 3.4) ----

namespace {

/// One <text> element: its attributes x, y, its class and its (unescaped) content.
struct SvgText {
  double x = 0, y = 0;
  std::string cls, text;
};

std::string attribute(const std::string& element, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t at = element.find(key);
  if (at == std::string::npos) return "";
  const std::size_t from = at + key.size();
  return element.substr(from, element.find('"', from) - from);
}

std::string unescape(std::string s) {
  const std::pair<const char*, const char*> entities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : entities)
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1))
      s.replace(at, std::string(from).size(), to);
  return s;
}

/// The <text> elements of `svg` between offsets [from, to).
std::vector<SvgText> texts(const std::string& svg, std::size_t from = 0, std::size_t to = std::string::npos) {
  std::vector<SvgText> out;
  for (std::size_t at = svg.find("<text", from); at < to && at != std::string::npos; at = svg.find("<text", at + 1)) {
    const std::size_t open_end = svg.find('>', at);
    const std::size_t close = svg.find("</text>", open_end);
    const std::string element = svg.substr(at, open_end - at);
    SvgText t;
    t.x = std::stod(attribute(element, "x"));
    t.y = std::stod(attribute(element, "y"));
    t.cls = attribute(element, "class");
    t.text = unescape(svg.substr(open_end + 1, close - open_end - 1));
    out.push_back(t);
  }
  return out;
}

/// The font-size of the first <g> whose opening tag contains `marker`, and the range of that group.
struct Group {
  double font_size = 0;
  std::size_t begin = 0, end = 0;
};
Group group_with(const std::string& svg, const std::string& marker) {
  Group g;
  const std::size_t at = svg.find(marker);
  REQUIRE(at != std::string::npos);
  g.begin = svg.rfind("<g", at);
  const std::string open = svg.substr(g.begin, svg.find('>', g.begin) - g.begin);
  g.font_size = std::stod(attribute(open, "font-size"));
  g.end = svg.find("</g>", g.begin);
  return g;
}

double picture_number(const std::string& svg, const char* name) { return std::stod(attribute(svg.substr(0, 300), name)); }

/// The view arrangement_svg uses (margin 16, no title): picture to scene coordinates.
struct Unview {
  double min_x, max_y, scale;
  Unview(const Box2& domain, int width)
      : min_x(domain.min.x.get_d()), max_y(domain.max.y.get_d()),
        scale((width - 32.0) / (domain.max.x.get_d() - domain.min.x.get_d())) {}
  double x(double px) const { return min_x + (px - 16) / scale; }
  double y(double py) const { return max_y - (py - 16) / scale; }
};

/// Distance (scene units) from (x, y) to the boundary of h.
double boundary_distance(const Halfspace2& h, double x, double y) {
  switch (h.kind) {
    case HalfspaceKind2::Halfplane: {
      const double nx = h.normal.x.get_d(), ny = h.normal.y.get_d();
      return std::abs(nx * x + ny * y - h.offset.get_d()) / std::hypot(nx, ny);
    }
    case HalfspaceKind2::Disk:
      return std::abs(std::hypot(x - h.center.x.get_d(), y - h.center.y.get_d()) - h.radius.get_d());
    case HalfspaceKind2::Polygon: {
      double best = INFINITY;
      for (std::size_t i = 0; i < h.vertices.size(); ++i) {
        const auto& a = h.vertices[i];
        const auto& b = h.vertices[(i + 1) % h.vertices.size()];
        const double ax = a.x.get_d(), ay = a.y.get_d(), dx = b.x.get_d() - ax, dy = b.y.get_d() - ay;
        const double t = std::clamp(((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
        best = std::min(best, std::hypot(ax + t * dx - x, ay + t * dy - y));
      }
      return best;
    }
  }
  return INFINITY;
}

Scene2 scene_file(const std::string& name) { return read_scene_file(std::string(HSX_SOURCE_DIR) + "/" + name); }

}  // namespace

TEST_CASE("labels name each cell at its witness and each patch on the patch", "[io][svg]") {
  for (const Scene2& scene : {picture_scene(), scene_file("data/scenes/star.json"), scene_file("data/scenes/lens.json")}) {
    const Arranged2 arranged = arrange(scene);
    const Complex& c = arranged.complex;
    SvgOptions options;
    options.width = 1000;
    options.show_cell_ids = options.show_patch_ids = true;
    const std::string svg = arrangement_svg(scene, arranged.arrangement, c, options);
    const Group labels = group_with(svg, "class=\"cell-id\"");
    const Unview back(arranged.arrangement.domain(), options.width);
    std::vector<int> cells_seen(c.cells.size(), 0), patches_seen(c.patches.size(), 0);
    for (const SvgText& t : texts(svg, labels.begin, labels.end)) {
      // The label is centred on its point: baseline 0.35 em below it.
      const double x = back.x(t.x), y = back.y(t.y - 0.35 * labels.font_size);
      const double tolerance = 1e-3 * (1 + std::abs(x) + std::abs(y));
      REQUIRE(t.text.size() >= 2);
      const int id = std::stoi(t.text.substr(1));
      INFO(t.cls << " " << t.text << " at " << x << ", " << y);
      if (t.cls == "cell-id") {
        REQUIRE(t.text[0] == 'c');
        REQUIRE(id >= 0);
        REQUIRE(static_cast<std::size_t>(id) < c.cells.size());
        ++cells_seen[id];
        CHECK(std::abs(x - c.cells[id].witness.get()[0].get_d()) < tolerance);
        CHECK(std::abs(y - c.cells[id].witness.get()[1].get_d()) < tolerance);
      } else {
        REQUIRE(t.cls == "patch-id");
        REQUIRE(t.text[0] == 'p');
        REQUIRE(id >= 0);
        REQUIRE(static_cast<std::size_t>(id) < c.patches.size());
        ++patches_seen[id];
        const Patch& patch = c.patches[id];
        CHECK(boundary_distance(scene.halfspaces[patch.halfspace], x, y) < tolerance);
        // On this patch, not on another patch of the same boundary: the other halfspaces see the point as the
        // patch's cells do.
        const PointQ2 point{Rational(x), Rational(y)};
        for (int i = 0; i < c.halfspace_count(); ++i)
          if (i != patch.halfspace && boundary_distance(scene.halfspaces[i], x, y) > tolerance)
            CHECK((scene.halfspaces[i].side(point) > 0) == (c.cells[patch.inside_cell].inside[i] == 1));
      }
    }
    CHECK(std::count(cells_seen.begin(), cells_seen.end(), 1) == static_cast<long>(c.cells.size()));
    CHECK(std::count(patches_seen.begin(), patches_seen.end(), 1) == static_cast<long>(c.patches.size()));
  }
}

TEST_CASE("label and legend fonts follow the picture's width", "[io][svg]") {
  const Scene2 scene = picture_scene();
  const Arranged2 arranged = arrange(scene);
  SvgOptions small, large;
  small.width = 800;
  large.width = 1600;
  small.show_cell_ids = large.show_cell_ids = true;
  const std::string a = arrangement_svg(scene, arranged.arrangement, arranged.complex, small);
  const std::string b = arrangement_svg(scene, arranged.arrangement, arranged.complex, large);
  CHECK(group_with(b, "class=\"cell-id\"").font_size > 1.5 * group_with(a, "class=\"cell-id\"").font_size);
  CHECK(group_with(b, "class=\"legend\"").font_size > 1.5 * group_with(a, "class=\"legend\"").font_size);
  // The halo: labels are stroked white under their fill.
  const std::size_t at = a.rfind("<g", a.find("class=\"cell-id\""));
  const std::string open = a.substr(at, a.find('>', at) - at);
  CHECK(attribute(open, "stroke") == "#ffffff");
  CHECK(attribute(open, "paint-order") == "stroke");
}

TEST_CASE("svg_text_width is an upper estimate of Helvetica's widths", "[io][svg]") {
  CHECK(svg_text_width("", 12) == 0);
  CHECK(svg_text_width("W", 10) >= 9.44);      // Helvetica W: 944/1000 em
  CHECK(svg_text_width("iiii", 10) >= 8.88);   // i: 222
  CHECK(svg_text_width("0123456789", 10) >= 55.6);
  CHECK(svg_text_width("ab", 20) == Approx(2 * svg_text_width("ab", 10)));
  CHECK(svg_text_width("\xc3\xa9", 10) >= 5);  // one non-ASCII character (é)
}

TEST_CASE("legend lines do not overlap and stay in the picture", "[io][svg]") {
  Scene2 long_names = picture_scene();
  long_names.halfspaces[1].name = "a very long halfspace name that cannot fit on one line of a narrow picture at all";
  long_names.halfspaces[2].name = "Wide_WWWWWWWWWWWWWWWW_name";
  const std::vector<Scene2> scenes = {picture_scene(), scene_file("data/scenes/star.json"), long_names};
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const Arranged2 arranged = arrange(scenes[k]);
    for (int width : {300, 800, 1200}) {
      for (int variant = 0; variant < 2; ++variant) {
        SvgOptions options;
        options.width = width;
        options.title = "legend test";
        options.show_cell_ids = variant == 1;
        if (variant == 1) options.cell_fill.assign(arranged.complex.cells.size(), 0);
        const std::string svg = arrangement_svg(scenes[k], arranged.arrangement, arranged.complex, options);
        const Group legend = group_with(svg, "class=\"legend\"");
        const std::vector<SvgText> lines = texts(svg, legend.begin, legend.end);
        INFO("scene " << k << ", width " << width << ", variant " << variant);
        REQUIRE(lines.size() >= scenes[k].halfspaces.size() + 2);
        const double fs = legend.font_size, picture_width = picture_number(svg, "width"),
                     picture_height = picture_number(svg, "height");
        struct Box {
          double x0, x1, y0, y1;
        };
        std::vector<Box> boxes;
        for (const SvgText& t : lines) {
          const Box b{t.x, t.x + svg_text_width(t.text, fs), t.y - 0.8 * fs, t.y + 0.25 * fs};
          INFO("'" << t.text << "' at " << t.x << ", " << t.y);
          const bool one_word_too_long = t.text.find(' ') == std::string::npos && b.x1 > picture_width;
          if (!one_word_too_long) CHECK(b.x1 <= picture_width);
          CHECK(b.x0 >= 0);
          CHECK(b.y0 >= 0);
          CHECK(b.y1 <= picture_height);
          boxes.push_back(b);
        }
        // Swatches: lines (with half their stroke width), rectangles and circles.
        std::vector<Box> swatches;
        for (const char* tag : {"<line", "<rect", "<circle"})
          for (std::size_t at = svg.find(tag, legend.begin); at < legend.end; at = svg.find(tag, at + 1)) {
            const std::string e = svg.substr(at, svg.find('>', at) - at);
            auto a = [&](const char* name) { return std::stod(attribute(e, name)); };
            if (tag[1] == 'l') {
              const double half = a("stroke-width") / 2;
              swatches.push_back({std::min(a("x1"), a("x2")), std::max(a("x1"), a("x2")),
                                  std::min(a("y1"), a("y2")) - half, std::max(a("y1"), a("y2")) + half});
            } else if (tag[1] == 'r') {
              swatches.push_back({a("x"), a("x") + a("width"), a("y"), a("y") + a("height")});
            } else {
              const double r = a("r") + a("stroke-width") / 2;
              swatches.push_back({a("cx") - r, a("cx") + r, a("cy") - r, a("cy") + r});
            }
          }
        CHECK(swatches.size() >= scenes[k].halfspaces.size());
        auto overlap = [](const Box& a, const Box& b) {
          return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
        };
        for (std::size_t i = 0; i < boxes.size(); ++i) {
          for (std::size_t j = i + 1; j < boxes.size(); ++j) {
            INFO("'" << lines[i].text << "' and '" << lines[j].text << "'");
            CHECK_FALSE(overlap(boxes[i], boxes[j]));
          }
          for (const Box& w : swatches) {
            INFO("'" << lines[i].text << "' and the swatch at " << w.x0 << ", " << w.y0);
            CHECK_FALSE(overlap(boxes[i], w));
          }
        }
      }
    }
  }
}

TEST_CASE("the legend says what the shading means", "[io][svg]") {
  const Scene2 scene = picture_scene();
  const Arranged2 arranged = arrange(scene);
  const Complex& c = arranged.complex;
  const std::string plain = arrangement_svg(scene, arranged.arrangement, c, {});
  CHECK(plain.find("odd number of halfspaces") != std::string::npos);
  CHECK(plain.find("inside the shape") == std::string::npos);
  SvgOptions shape;
  shape.cell_fill.assign(c.cells.size(), 0);
  shape.highlight_patches.assign(c.patches.size(), 0);
  shape.highlight_patches[0] = 1;
  shape.highlight_legend = "removed patches";
  const std::string filled = arrangement_svg(scene, arranged.arrangement, c, shape);
  CHECK(filled.find("inside the shape") != std::string::npos);
  CHECK(filled.find("odd number of halfspaces") == std::string::npos);
  CHECK(filled.find("removed patches") != std::string::npos);
}

TEST_CASE("the shape's boundary is bold and missing samples are ringed exactly when expected", "[io][svg]") {
  // Oracle: bsh's own boundary and energy of the same labelling.
  for (const Scene2& scene : {picture_scene(), scene_file("data/scenes/lens.json"), scene_file("data/figures/fig10.json")}) {
    const Arranged2 arranged = arrange(scene);
    const Complex& c = arranged.complex;
    const bsh::Problem problem(c);
    {
      const std::string svg = arrangement_svg(scene, arranged.arrangement, c, {});
      CHECK(count(svg, "class=\"boundary\"") == 0);
      CHECK(count(svg, "class=\"missing\"") == 0);
      CHECK(svg.find("missing sample") == std::string::npos);
    }
    std::mt19937_64 random(20261201);
    for (int round = 0; round < 12; ++round) {
      bsh::Labelling labelling(c.cells.size(), 0);
      for (std::size_t f = 0; f < c.cells.size(); ++f)
        labelling[f] = round == 0 ? 0 : round == 1 ? !c.cells[f].outer : !c.cells[f].outer && (random() & 1);
      SvgOptions options;
      options.cell_fill = labelling;
      const std::string svg = arrangement_svg(scene, arranged.arrangement, c, options);
      const auto expected_boundary = bsh::boundary_supports(problem, labelling);
      const long expected_missing = bsh::energy(problem, labelling).missing_samples;
      INFO("round " << round);
      CHECK(count(svg, "class=\"boundary\"") == expected_boundary.size());
      for (int g : expected_boundary)
        CHECK(svg.find("class=\"boundary\" data-support=\"" + std::to_string(g) + "\"") != std::string::npos);
      CHECK(static_cast<long>(count(svg, "class=\"missing\"")) == expected_missing);
      CHECK(svg.find("missing sample, not on the boundary (" + std::to_string(expected_missing) + " here)") !=
            std::string::npos);
      CHECK(svg.find("boundary of the shape") != std::string::npos);
      options.shape_boundary = false;
      const std::string without = arrangement_svg(scene, arranged.arrangement, c, options);
      CHECK(count(without, "class=\"boundary\"") == 0);
      CHECK(count(without, "class=\"missing\"") == 0);
    }
    // The extracted shape covers every sample it can: the picture rings exactly its missing samples.
    bsh::ExtractOptions extract_options;
    extract_options.method = bsh::Method::GraphCut;
    const bsh::ExtractResult result = bsh::extract(problem, extract_options);
    SvgOptions options;
    options.cell_fill = result.labelling;
    const std::string svg = arrangement_svg(scene, arranged.arrangement, c, options);
    CHECK(static_cast<long>(count(svg, "class=\"missing\"")) == result.energy.missing_samples);
  }
}
