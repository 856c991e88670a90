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

}  // namespace hsxpy
