// OpenSCAD export: see openscad.hpp.
#include <hsx/io/openscad.hpp>

#include <stdexcept>
#include <vector>

namespace hsx {

namespace {

constexpr int kSignificantDigits = 17;

std::string num(const Rational& q) { return decimal_string(q, kSignificantDigits); }

std::string point(const PointQ2& p) { return "[" + num(p.x) + ", " + num(p.y) + "]"; }

/// Text for a one-line comment: control characters replaced.
std::string comment_text(const std::string& s) {
  std::string out;
  for (char c : s) out += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
  return out;
}

std::string points_list(const std::vector<PointQ2>& points) {
  std::string s = "polygon(points = [";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i) s += ", ";
    s += point(points[i]);
  }
  return s + "]);";
}

/// The domain box clipped to { p : n . p <= o } (Sutherland-Hodgman on one edge, exact), counter-clockwise,
/// without repeated vertices.
std::vector<PointQ2> clip_box(const Box2& box, const PointQ2& n, const Rational& o) {
  const std::vector<PointQ2> corners = {box.min, PointQ2{box.max.x, box.min.y}, box.max,
                                        PointQ2{box.min.x, box.max.y}};
  auto value = [&](const PointQ2& p) { return Rational(n.x * p.x + n.y * p.y - o); };
  std::vector<PointQ2> out;
  auto add = [&](const PointQ2& p) {
    if (out.empty() || out.back() != p) out.push_back(p);
  };
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const PointQ2& p = corners[i];
    const PointQ2& q = corners[(i + 1) % corners.size()];
    const Rational vp = value(p), vq = value(q);
    if (sgn(vp) <= 0) add(p);
    if ((sgn(vp) < 0 && sgn(vq) > 0) || (sgn(vp) > 0 && sgn(vq) < 0)) {
      const Rational t = vp / (vp - vq);
      add(PointQ2{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  if (out.size() < 3) out.clear();
  return out;
}

class Writer {
 public:
  Writer(const Scene2& scene, const OpenScadOptions& options) : scene_(scene), options_(options) {}

  std::string write(const csg::Expr& root) {
    out_ += "// hsx CSG expression as a 2D OpenSCAD program.\n";
    out_ += "// a drawing, not exact: circles are polygons with $fn = " + std::to_string(options_.circle_segments) +
            " segments; coordinates rounded to " + std::to_string(kSignificantDigits) + " significant digits.\n";
    if (!scene_.description.empty()) out_ += "// scene: " + comment_text(scene_.description) + "\n";
    out_ += "// domain: " + point(scene_.domain.min) + " to " + point(scene_.domain.max) + "\n";

    struct Frame {
      const csg::Expr* node;
      std::size_t next;
      int depth;
    };
    std::vector<Frame> frames{{&root, 0, 0}};
    while (!frames.empty()) {
      Frame& top = frames.back();
      const csg::Expr& n = *top.node;
      const int depth = top.depth;
      if (n.children.empty()) {
        leaf(n, depth);
        frames.pop_back();
        continue;
      }
      if (top.next == 0) open(n, depth);
      if (top.next < n.children.size()) {
        const csg::Expr* child = n.children[top.next++].get();
        if (!child) throw std::invalid_argument("to_openscad: null child in an expression");
        frames.push_back({child, 0, depth + 1});
        continue;
      }
      line(depth, "}");
      frames.pop_back();
    }
    return out_;
  }

 private:
  void line(int depth, const std::string& text) {
    out_.append(static_cast<std::size_t>(depth) * 2, ' ');
    out_ += text;
    out_ += '\n';
  }

  std::string domain_square() const {
    const Box2& d = scene_.domain;
    return "translate(" + point(d.min) + ") square([" + num(d.max.x - d.min.x) + ", " + num(d.max.y - d.min.y) +
           "]);";
  }

  void open(const csg::Expr& n, int depth) {
    switch (n.op) {
      case csg::Op::Union: line(depth, "union() {"); break;
      case csg::Op::Intersection: line(depth, "intersection() {"); break;
      case csg::Op::Difference: line(depth, "difference() {"); break;
      case csg::Op::Complement:
        line(depth, "difference() {  // complement");
        line(depth + 1, domain_square());
        break;
      default: throw std::invalid_argument("to_openscad: a leaf with children");
    }
  }

  void leaf(const csg::Expr& n, int depth) {
    switch (n.op) {
      case csg::Op::Empty: line(depth, "union() {}  // empty"); return;
      case csg::Op::Full: line(depth, domain_square() + "  // full"); return;
      case csg::Op::Halfspace: break;
      default: throw std::invalid_argument("to_openscad: an operation without children");
    }
    if (n.halfspace < 0 || static_cast<std::size_t>(n.halfspace) >= scene_.halfspaces.size()) {
      throw std::invalid_argument("to_openscad: halfspace index " + std::to_string(n.halfspace) + " out of range");
    }
    const Halfspace2& h = scene_.halfspaces[static_cast<std::size_t>(n.halfspace)];
    const std::string note = "  // " + comment_text(h.name);
    if (h.kind == HalfspaceKind2::Halfplane) {
      const std::vector<PointQ2> clipped =
          h.complement ? clip_box(scene_.domain, PointQ2{-h.normal.x, -h.normal.y}, Rational(-h.offset))
                       : clip_box(scene_.domain, h.normal, h.offset);
      if (clipped.empty()) {
        line(depth, "union() {}" + note + " (half-plane misses the domain)");
      } else {
        line(depth, points_list(clipped) + note + (h.complement ? " (complement)" : ""));
      }
      return;
    }
    std::string shape;
    if (h.kind == HalfspaceKind2::Disk) {
      shape = "translate(" + point(h.center) + ") circle(r = " + num(h.radius) +
              ", $fn = " + std::to_string(options_.circle_segments) + ");";
    } else {
      shape = points_list(h.vertices);
    }
    if (!h.complement) {
      line(depth, shape + note);
      return;
    }
    line(depth, "difference() {" + note + " (complement)");
    line(depth + 1, domain_square());
    line(depth + 1, shape);
    line(depth, "}");
  }

  const Scene2& scene_;
  const OpenScadOptions& options_;
  std::string out_;
};

}  // namespace

std::string to_openscad(const csg::Expr& e, const Scene2& scene, const OpenScadOptions& options) {
  if (options.circle_segments < 3 || options.circle_segments > 100000) {
    throw InputError("OpenSCAD circle segments: expected 3 to 100000, got " +
                     std::to_string(options.circle_segments));
  }
  return Writer(scene, options).write(e);
}

}  // namespace hsx
