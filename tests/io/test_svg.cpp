#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/svg.hpp>

#include <catch2/catch.hpp>

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
