// OpenSCAD export: see openscad.hpp.
#include <hsx/io/openscad.hpp>

#include <hsx/geometry/tessellate3.hpp>

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

/// The tree walk shared by both dimensions: operators as OpenSCAD blocks, leaves and the domain solid from the
/// subclass. Iterative, so that deep trees do not overflow the stack.
class TreeWriter {
 public:
  virtual ~TreeWriter() = default;

  std::string write(const csg::Expr& root) {
    header();
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
        switch (n.op) {
          case csg::Op::Empty: line(depth, "union() {}  // empty"); break;
          case csg::Op::Full: line(depth, domain_solid() + "  // full"); break;
          case csg::Op::Halfspace: leaf(n.halfspace, depth); break;
          default: throw std::invalid_argument("to_openscad: an operation without children");
        }
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

 protected:
  virtual void header() = 0;
  /// The domain box as one OpenSCAD statement (the full set, and what complements are subtracted from).
  virtual std::string domain_solid() const = 0;
  /// Halfspace `index` (not yet range-checked) at `depth`.
  virtual void leaf(int index, int depth) = 0;

  void line(int depth, const std::string& text) {
    out_.append(static_cast<std::size_t>(depth) * 2, ' ');
    out_ += text;
    out_ += '\n';
  }

  static void check_index(int index, std::size_t count) {
    if (index < 0 || static_cast<std::size_t>(index) >= count)
      throw std::invalid_argument("to_openscad: halfspace index " + std::to_string(index) + " out of range");
  }

  std::string out_;

 private:
  void open(const csg::Expr& n, int depth) {
    switch (n.op) {
      case csg::Op::Union: line(depth, "union() {"); break;
      case csg::Op::Intersection: line(depth, "intersection() {"); break;
      case csg::Op::Difference: line(depth, "difference() {"); break;
      case csg::Op::Complement:
        line(depth, "difference() {  // complement");
        line(depth + 1, domain_solid());
        break;
      default: throw std::invalid_argument("to_openscad: a leaf with children");
    }
  }
};

class Writer2 final : public TreeWriter {
 public:
  Writer2(const Scene2& scene, const OpenScadOptions& options) : scene_(scene), options_(options) {}

 private:
  void header() override {
    out_ += "// hsx CSG expression as a 2D OpenSCAD program.\n";
    out_ += "// a drawing, not exact: circles are polygons with $fn = " + std::to_string(options_.circle_segments) +
            " segments; coordinates rounded to " + std::to_string(kSignificantDigits) + " significant digits.\n";
    if (!scene_.description.empty()) out_ += "// scene: " + comment_text(scene_.description) + "\n";
    out_ += "// domain: " + point(scene_.domain.min) + " to " + point(scene_.domain.max) + "\n";
  }

  std::string domain_solid() const override {
    const Box2& d = scene_.domain;
    return "translate(" + point(d.min) + ") square([" + num(d.max.x - d.min.x) + ", " + num(d.max.y - d.min.y) +
           "]);";
  }

  void leaf(int index, int depth) override {
    check_index(index, scene_.halfspaces.size());
    const Halfspace2& h = scene_.halfspaces[static_cast<std::size_t>(index)];
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
    line(depth + 1, domain_solid());
    line(depth + 1, shape);
    line(depth, "}");
  }

  const Scene2& scene_;
  const OpenScadOptions& options_;
};

std::string point3(const PointQ3& p) { return "[" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + "]"; }

/// `polyhedron(points = [...], faces = [...]);` of faces given counter-clockwise from outside (hsx's orientation);
/// each face is written reversed, clockwise from outside, as OpenSCAD wants. Points are numbered in order of
/// first use.
std::string polyhedron(const std::vector<std::vector<PointQ3>>& faces) {
  std::vector<PointQ3> points;
  std::vector<std::vector<std::size_t>> ids;
  for (const auto& f : faces) {
    std::vector<std::size_t> face;
    for (const PointQ3& p : f) {
      std::size_t k = 0;
      while (k < points.size() && points[k] != p) ++k;
      if (k == points.size()) points.push_back(p);
      face.push_back(k);
    }
    ids.push_back(std::move(face));
  }
  std::string s = "polyhedron(points = [";
  for (std::size_t i = 0; i < points.size(); ++i) s += (i ? ", " : "") + point3(points[i]);
  s += "], faces = [";
  for (std::size_t i = 0; i < ids.size(); ++i) {
    s += i ? ", [" : "[";
    for (std::size_t k = ids[i].size(); k-- > 0;) s += std::to_string(ids[i][k]) + (k ? ", " : "");
    s += "]";
  }
  return s + "]);";
}

/// The same for a triangle surface: its own vertex numbering, each triangle (a, b, c) written as [a, c, b].
std::string polyhedron(const TriangleSurface& surface) {
  std::string s = "polyhedron(points = [";
  for (std::size_t i = 0; i < surface.vertices.size(); ++i) s += (i ? ", " : "") + point3(surface.vertices[i]);
  s += "], faces = [";
  for (std::size_t i = 0; i < surface.triangles.size(); ++i) {
    const auto& t = surface.triangles[i];
    s += (i ? ", [" : "[") + std::to_string(t[0]) + ", " + std::to_string(t[2]) + ", " + std::to_string(t[1]) + "]";
  }
  return s + "]);";
}

class Writer3 final : public TreeWriter {
 public:
  explicit Writer3(const Scene3& scene) : scene_(scene) {}

 private:
  void header() override {
    out_ += "// hsx CSG expression as a 3D OpenSCAD program, with hsx's tessellation made explicit.\n";
    out_ += "// every curved halfspace is the polyhedron hsx arranges (geometry/tessellate3.hpp), every plane the "
            "domain box clipped to it; coordinates rounded to " +
            std::to_string(kSignificantDigits) + " significant digits.\n";
    if (!scene_.description.empty()) out_ += "// scene: " + comment_text(scene_.description) + "\n";
    out_ += "// domain: " + point3(scene_.domain.min) + " to " + point3(scene_.domain.max) + "\n";
  }

  std::string domain_solid() const override {
    const Box3& d = scene_.domain;
    return "translate(" + point3(d.min) + ") cube([" + num(d.max.x - d.min.x) + ", " + num(d.max.y - d.min.y) +
           ", " + num(d.max.z - d.min.z) + "]);";
  }

  void leaf(int index, int depth) override {
    check_index(index, scene_.halfspaces.size());
    const Halfspace3& h = scene_.halfspaces[static_cast<std::size_t>(index)];
    const std::string note = "  // " + comment_text(h.name) + " (" + to_string(h.kind) +
                             (h.complement ? ", complement" : "");
    if (h.kind == HalfspaceKind3::Plane) {
      const PointQ3 n = h.complement ? PointQ3{-h.normal.x, -h.normal.y, -h.normal.z} : h.normal;
      const Rational o = h.complement ? Rational(-h.offset) : h.offset;
      const auto faces = box_cut_by_plane(scene_.domain, n, o);
      if (faces.empty())
        line(depth, "union() {}" + note + ", misses the domain)");
      else
        line(depth, polyhedron(faces) + note + ", the domain box clipped to it)");
      return;
    }
    const std::string counts = ", " + std::to_string(h.surface.vertices.size()) + " vertices, " +
                               std::to_string(h.surface.triangles.size()) + " triangles";
    if (!h.complement) {
      line(depth, polyhedron(h.surface) + note + counts + ")");
      return;
    }
    line(depth, "difference() {" + note + counts + ", subtracted from the domain box)");
    line(depth + 1, domain_solid());
    line(depth + 1, polyhedron(h.surface));
    line(depth, "}");
  }

  const Scene3& scene_;
};

}  // namespace

std::string to_openscad(const csg::Expr& e, const Scene2& scene, const OpenScadOptions& options) {
  if (options.circle_segments < 3 || options.circle_segments > 100000) {
    throw InputError("OpenSCAD circle segments: expected 3 to 100000, got " +
                     std::to_string(options.circle_segments));
  }
  return Writer2(scene, options).write(e);
}

}  // namespace hsx

namespace hsx {

std::string to_openscad(const csg::Expr& e, const Scene3& scene) { return Writer3(scene).write(e); }

}  // namespace hsx
