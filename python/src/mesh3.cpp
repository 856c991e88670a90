// 3D surfaces and pictures for Python: faces of a 3D arrangement (io/mesh_export.hpp's exported_faces and
// shape_faces, vertices numbered by its renumber_vertices, as the mesh files number them) as numpy arrays, and the
// orthographic views of io/svg3.hpp.
#include "bindings.hpp"

#include <pybind11/numpy.h>

#include <hsx/io/mesh_export.hpp>
#include <hsx/io/svg3.hpp>

namespace hsxpy {

py::tuple face_arrays(const hsx::Arranged3& arranged, const std::vector<hsx::ExportedFace>& faces, bool exact) {
  const hsx::VertexNumbering numbering = hsx::renumber_vertices(arranged.arrangement, faces);
  const auto& points = arranged.arrangement.vertices();
  const auto n = static_cast<py::ssize_t>(numbering.used.size());
  const auto m = static_cast<py::ssize_t>(faces.size());
  py::object vertices;
  if (exact) {
    py::list rows;
    for (int v : numbering.used) {
      const hsx::PointQ3& p = points[static_cast<std::size_t>(v)];
      rows.append(py::make_tuple(hsx::exact_string(p.x), hsx::exact_string(p.y), hsx::exact_string(p.z)));
    }
    vertices = rows;
  } else {
    py::array_t<double> a({n, py::ssize_t{3}});
    auto w = a.mutable_unchecked<2>();
    for (py::ssize_t k = 0; k < n; ++k) {
      const hsx::PointQ3& p = points[static_cast<std::size_t>(numbering.used[static_cast<std::size_t>(k)])];
      w(k, 0) = p.x.get_d();
      w(k, 1) = p.y.get_d();
      w(k, 2) = p.z.get_d();
    }
    vertices = a;
  }
  py::array_t<std::int64_t> tri({m, py::ssize_t{3}}), patch(m), halfspace(m);
  auto t = tri.mutable_unchecked<2>();
  auto pa = patch.mutable_unchecked<1>();
  auto ha = halfspace.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < m; ++i) {
    const hsx::ExportedFace& f = faces[static_cast<std::size_t>(i)];
    for (int j = 0; j < 3; ++j)
      t(i, j) = numbering.id[static_cast<std::size_t>(f.vertices[static_cast<std::size_t>(j)])];
    pa(i) = f.patch;
    ha(i) = f.halfspace;
  }
  return py::make_tuple(vertices, tri, patch, halfspace);
}

std::vector<hsx::SvgView3> svg3_views(py::handle views) {
  std::vector<hsx::SvgView3> out;
  if (views.is_none()) return out;
  if (py::isinstance<py::str>(views)) throw py::type_error("views: a list of views (a single name: [\"top\"])");
  const std::vector<hsx::SvgView3> defaults = hsx::default_svg_views3();
  static const char* const kNames[] = {"front", "side", "top", "isometric"};  // default_svg_views3's order
  std::size_t k = 0;
  for (py::handle v : views) {
    const std::string where = "views[" + std::to_string(k++) + "]";
    if (py::isinstance<py::str>(v)) {
      const std::string name = v.cast<std::string>();
      bool found = false;
      for (std::size_t i = 0; i < defaults.size(); ++i)
        if (name == kNames[i]) {
          out.push_back(defaults[i]);
          found = true;
        }
      if (!found)
        throw hsx::InputError(where + ": unknown view \"" + name + "\" (front, side, top, isometric, or a tuple "
                              "(name, direction, up))");
      continue;
    }
    if (!py::isinstance<py::sequence>(v) || py::len(v) != 3 || !py::isinstance<py::str>(v[py::int_(0)]))
      throw py::type_error(where + ": a view name or a tuple (name, direction, up)");
    const py::sequence t = py::reinterpret_borrow<py::sequence>(v);
    auto point = [&](py::handle p, const std::string& what) {
      if (!py::isinstance<py::sequence>(p) || py::isinstance<py::str>(p))
        throw py::type_error(where + "." + what + ": a point (x, y, z)");
      const std::vector<py::object> c = py::reinterpret_borrow<py::object>(p).cast<std::vector<py::object>>();
      if (c.size() != 3) throw py::type_error(where + "." + what + ": 3 coordinates, got " + std::to_string(c.size()));
      return hsx::PointQ3{to_rational(c[0], where + "." + what + "[0]"), to_rational(c[1], where + "." + what + "[1]"),
                          to_rational(c[2], where + "." + what + "[2]")};
    };
    hsx::SvgView3 view;
    view.name = t[0].cast<std::string>();
    view.direction = point(t[1], "direction");
    view.up = point(t[2], "up");
    const hsx::PointQ3& d = view.direction;
    const hsx::PointQ3& u = view.up;
    if (d.x == 0 && d.y == 0 && d.z == 0) throw hsx::InputError(where + ".direction: must not be zero");
    if (d.y * u.z == d.z * u.y && d.z * u.x == d.x * u.z && d.x * u.y == d.y * u.x)
      throw hsx::InputError(where + ".up: must not be parallel to the direction (nor zero)");
    out.push_back(std::move(view));
  }
  if (out.empty()) throw hsx::InputError("views: at least one view (None: the four default ones)");
  return out;
}

py::object svg3_picture(const InputPtr& input, hsx::Svg3Options options) {
  if (!input->scene3) return py::none();
  if (options.width < 200) throw hsx::InputError("width: a 3D picture needs at least 200");
  std::string svg;
  {
    py::gil_scoped_release release;
    svg = hsx::arrangement_svg3(*input->scene3, *input->arranged3, options);
  }
  return py::str(svg);
}

void refuse_views_in_2d(const InputPtr& input, py::handle views) {
  if (!views.is_none() && !input->scene3) throw hsx::InputError("views: only 3D pictures have views");
}

}  // namespace hsxpy
