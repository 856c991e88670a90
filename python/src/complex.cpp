// Inputs and complexes: hsx.Complex (cells, patches, junctions, samples, supports) over a shared input, read from
// JSON text or a file (load_input / load_input_text: the CLI's reading and messages), its hsx-complex/1 text and
// its picture (io/svg.hpp); the random scene generator.
#include "bindings.hpp"

#include <hsx/io/result_json.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/io/svg.hpp>
#include <hsx/geometry/random_scene.hpp>

#include <algorithm>

namespace hsxpy {
namespace {

/// One element of a complex's list, by index; keeps the input alive.
struct ElementView {
  InputPtr input;
  int index;
  const hsx::Complex& complex() const { return input->complex(); }
};
struct CellView : ElementView {};
struct PatchView : ElementView {};
struct JunctionView : ElementView {};
struct SampleView : ElementView {};

template <class View>
py::list views(const InputPtr& input, std::size_t count) {
  py::list l;
  for (std::size_t k = 0; k < count; ++k) l.append(View{{input, static_cast<int>(k)}});
  return l;
}

hsx::ArrangementLimits limits_of(long max_cells, long max_side_table) {
  hsx::ArrangementLimits limits;
  if (max_cells < 0) throw hsx::InputError("max_cells: must be >= 0 (0: no limit)");
  if (max_side_table < 0) throw hsx::InputError("max_side_table: must be >= 0 (0: no limit)");
  limits.max_cells = max_cells;
  limits.max_side_entries = max_side_table;
  return limits;
}

ComplexHandle load_text(const std::string& text, const std::string& source, long max_cells, long max_side_table) {
  const hsx::ArrangementLimits limits = limits_of(max_cells, max_side_table);
  py::gil_scoped_release release;
  return {std::make_shared<const hsx::LoadedInput>(hsx::load_input_text(text, source, limits))};
}

ComplexHandle load_file(const std::string& path, long max_cells, long max_side_table) {
  const hsx::ArrangementLimits limits = limits_of(max_cells, max_side_table);
  py::gil_scoped_release release;
  return {std::make_shared<const hsx::LoadedInput>(hsx::load_input(path, limits))};
}

std::string complex_repr(const ComplexHandle& h) {
  const hsx::Complex& c = h.complex();
  return "<hsx.Complex " + std::to_string(c.dimension) + "D: " + std::to_string(c.halfspace_count()) +
         " halfspaces, " + std::to_string(c.cells.size()) + " cells (" + std::to_string(c.outer_cell_count()) +
         " outer), " + std::to_string(c.patches.size()) + " patches, " + std::to_string(c.junctions.size()) +
         " junctions, " + std::to_string(c.samples.size()) + " samples" +
         (h.input->scene || h.input->scene3 ? "" : ", from an hsx-complex/1 document") + ">";
}

/// Complex.svg: 2D (io/svg.hpp) or 3D (io/svg3.hpp), with the same options.
py::object complex_svg(const ComplexHandle& h, bool labels, int width, const std::string& title, py::object fill,
                       py::object highlight, const std::string& highlight_legend, py::object views) {
  if (width < 1) throw hsx::InputError("width: must be at least 1");
  refuse_views_in_2d(h.input, views);
  std::vector<char> cell_fill, highlighted;
  if (!fill.is_none()) cell_fill = flags_from(fill, h.complex().cells.size(), "fill");
  if (!highlight.is_none()) {
    highlighted.assign(h.complex().patches.size(), 0);
    for (py::handle p : highlight) {
      const int k = p.cast<int>();
      if (k < 0 || k >= static_cast<int>(h.complex().patches.size()))
        throw hsx::InputError("highlight: no patch " + std::to_string(k));
      highlighted[static_cast<std::size_t>(k)] = 1;
    }
  }
  if (h.input->scene3) {
    hsx::Svg3Options o;
    o.show_cell_ids = o.show_patch_ids = labels;
    o.width = width;
    o.title = title;
    o.cell_fill = std::move(cell_fill);
    o.highlight_patches = std::move(highlighted);
    o.highlight_legend = highlight_legend;
    o.views = svg3_views(views);
    return svg3_picture(h.input, o);
  }
  hsx::SvgOptions o;
  o.show_cell_ids = o.show_patch_ids = labels;
  o.width = width;
  o.title = title;
  o.cell_fill = std::move(cell_fill);
  if (!highlight.is_none()) {
    o.highlight_patches = std::move(highlighted);
    o.highlight_legend = highlight_legend;
  }
  return svg_picture(h.input, o);
}

py::tuple surface_mesh(const ComplexHandle& h, bool exact) {
  if (!h.input->arranged3)
    throw hsx::InputError(h.complex().dimension == 3
                              ? "surface_mesh: needs a complex arranged from a 3D scene (an hsx-complex/1 document "
                                "carries no triangles)"
                              : "surface_mesh: needs a 3D complex (2D: Complex.patch_polylines)");
  return face_arrays(*h.input->arranged3, hsx::exported_faces(*h.input->arranged3), exact);
}

void bind_views(py::module_& m) {
  py::class_<CellView>(m, "Cell", "A cell of a complex (complex/complex.hpp)")
      .def_property_readonly("index", [](const CellView& v) { return v.index; })
      .def_property_readonly("outer", [](const CellView& v) { return v.complex().cells[v.index].outer; },
                             "Touches the domain's boundary: always outside any shape")
      .def_property_readonly("witness",
                             [](const CellView& v) { return fraction_tuple(v.complex().cells[v.index].witness.get()); },
                             "An exact interior point, as Fractions")
      .def_property_readonly("sides",
                             [](const CellView& v) {
                               const hsx::Cell& c = v.complex().cells[v.index];
                               py::dict d;
                               for (int i = 0; i < v.complex().halfspace_count(); ++i)
                                 d[py::str(v.complex().halfspace_names[i])] = py::bool_(c.inside[i] != 0);
                               return d;
                             },
                             "Per halfspace name: True when the cell is inside it")
      .def_property_readonly("inside",
                             [](const CellView& v) {
                               const hsx::Cell& c = v.complex().cells[v.index];
                               py::list l;
                               for (int i = 0; i < v.complex().halfspace_count(); ++i)
                                 if (c.inside[i]) l.append(v.complex().halfspace_names[i]);
                               return l;
                             },
                             "Names of the halfspaces the cell is inside")
      .def_property_readonly("measure", [](const CellView& v) { return v.complex().cells[v.index].measure.get(); },
                             "Area (2D) or volume (3D)")
      .def("__repr__", [](const CellView& v) { return "<hsx.Cell " + std::to_string(v.index) + ">"; });
  py::class_<PatchView>(m, "Patch", "A maximal piece of one halfspace's boundary between two cells")
      .def_property_readonly("index", [](const PatchView& v) { return v.index; })
      .def_property_readonly("halfspace",
                             [](const PatchView& v) {
                               return v.complex().halfspace_names[v.complex().patches[v.index].halfspace];
                             },
                             "The halfspace's name")
      .def_property_readonly("halfspace_index",
                             [](const PatchView& v) { return v.complex().patches[v.index].halfspace; })
      .def_property_readonly("inside_cell", [](const PatchView& v) { return v.complex().patches[v.index].inside_cell; })
      .def_property_readonly("outside_cell",
                             [](const PatchView& v) { return v.complex().patches[v.index].outside_cell; })
      .def_property_readonly("cells",
                             [](const PatchView& v) {
                               const hsx::Patch& p = v.complex().patches[v.index];
                               return py::make_tuple(p.inside_cell, p.outside_cell);
                             },
                             "(inside_cell, outside_cell)")
      .def_property_readonly("samples", [](const PatchView& v) { return v.complex().patches[v.index].samples; },
                             "Indices of the samples on it")
      .def_property_readonly("measure", [](const PatchView& v) { return v.complex().patches[v.index].measure.get(); },
                             "Length (2D) or area (3D)")
      .def_property_readonly("support", [](const PatchView& v) { return v.complex().patches[v.index].support; },
                             "Its group of coincident patches (Complex.supports)")
      .def_property_readonly("junctions",
                             [](const PatchView& v) { return v.complex().patches[v.index].junctions; })
      .def("__repr__", [](const PatchView& v) {
        return "<hsx.Patch " + std::to_string(v.index) + " of " +
               v.complex().halfspace_names[v.complex().patches[v.index].halfspace] + ">";
      });
  py::class_<JunctionView>(m, "Junction", "Where patches meet (2D: a vertex; 3D: a chain of edges)")
      .def_property_readonly("index", [](const JunctionView& v) { return v.index; })
      .def_property_readonly("patches", [](const JunctionView& v) { return v.complex().junctions[v.index].patches; })
      .def("__repr__", [](const JunctionView& v) { return "<hsx.Junction " + std::to_string(v.index) + ">"; });
  py::class_<SampleView>(m, "SampleSite", "A sample as the complex sees it: its halfspace and its patch")
      .def_property_readonly("index", [](const SampleView& v) { return v.index; })
      .def_property_readonly("halfspace",
                             [](const SampleView& v) {
                               return v.complex().halfspace_names[v.complex().samples[v.index].halfspace];
                             })
      .def_property_readonly("patch", [](const SampleView& v) { return v.complex().samples[v.index].patch; })
      .def("__repr__", [](const SampleView& v) { return "<hsx.SampleSite " + std::to_string(v.index) + ">"; });
}

}  // namespace

// ---- random scenes (geometry/random_scene.hpp) ----

hsx::RandomSceneSettings random_settings(const py::dict& kw) {
  hsx::RandomSceneSettings s;
  for (auto [key, value] : kw) {
    const std::string k = py::str(key);
    if (k == "min_halfspaces") s.min_halfspaces = value.cast<int>();
    else if (k == "max_halfspaces") s.max_halfspaces = value.cast<int>();
    else if (k == "halfplanes") s.halfplanes = value.cast<bool>();
    else if (k == "disks") s.disks = value.cast<bool>();
    else if (k == "polygons") s.polygons = value.cast<bool>();
    else if (k == "complement_percent") s.complement_percent = value.cast<int>();
    else if (k == "denominator") s.denominator = value.cast<int>();
    else if (k == "coordinate_bound") s.coordinate_bound = value.cast<int>();
    else if (k == "max_radius") s.max_radius = value.cast<int>();
    else if (k == "min_degeneracies") s.min_degeneracies = value.cast<int>();
    else if (k == "max_degeneracies") s.max_degeneracies = value.cast<int>();
    else if (k == "max_samples") s.max_samples = value.cast<int>();
    else if (k == "near_percent") s.near_percent = value.cast<int>();
    else if (k == "degeneracy_weights") {
      const py::dict weights = py::reinterpret_borrow<py::dict>(value);
      for (auto [name, weight] : weights) {
        bool found = false;
        for (int d = 0; d < hsx::kDegeneracyCount; ++d)
          if (py::str(name).cast<std::string>() == hsx::to_string(static_cast<hsx::Degeneracy>(d))) {
            s.degeneracy_weight[d] = weight.cast<int>();
            found = true;
          }
        if (!found)
          throw hsx::InputError("degeneracy_weights: unknown degeneracy \"" + py::str(name).cast<std::string>() +
                                "\" (hsx.DEGENERACIES lists them)");
      }
    } else {
      throw py::type_error("random_scene: unknown setting \"" + k + "\"");
    }
  }
  return s;
}

namespace {

void bind_random(py::module_& m) {
  m.def("_random_scene", [](std::uint64_t seed, std::uint64_t index, const py::dict& settings) {
    const hsx::RandomSceneSettings s = random_settings(settings);
    hsx::RandomScene r;
    {
      py::gil_scoped_release release;
      try {
        r = hsx::random_scene(s, seed, index);
      } catch (const std::invalid_argument& e) {
        throw hsx::InputError(std::string("random_scene: ") + e.what());
      }
    }
    std::vector<std::string> names;
    for (hsx::Degeneracy d : r.degeneracies) names.emplace_back(hsx::to_string(d));
    return py::make_tuple(hsx::write_scene2(r.scene).dump(2) + "\n", names);
  });
  py::list names;
  for (int d = 0; d < hsx::kDegeneracyCount; ++d) names.append(hsx::to_string(static_cast<hsx::Degeneracy>(d)));
  m.attr("DEGENERACIES") = py::tuple(names);
}

}  // namespace

py::object svg_picture(const InputPtr& input, const hsx::SvgOptions& options) {
  if (!input->scene) return py::none();
  std::string svg;
  {
    py::gil_scoped_release release;
    svg = hsx::arrangement_svg(*input->scene, input->arranged->arrangement, input->complex(), options);
  }
  return py::str(svg);
}

hsx::bsh::Method method_named(std::string name, const std::string& what) {
  std::replace(name.begin(), name.end(), '_', '-');
  const auto method = hsx::bsh::method_from_string(name);
  if (!method)
    throw hsx::InputError(what + ": unknown method \"" + name + "\" (graphcut, beam, best-first, brute-force, exact)");
  return *method;
}

void bind_complex(py::module_& m) {
  bind_views(m);
  py::class_<ComplexHandle>(m, "Complex",
                            "The exact arrangement as a dimension-free complex (complex/complex.hpp): what "
                            "hsx.arrange returns and every algorithm reads")
      .def_property_readonly("dimension", [](const ComplexHandle& h) { return h.complex().dimension; })
      .def_property_readonly("halfspaces", [](const ComplexHandle& h) { return h.complex().halfspace_names; },
                             "Halfspace names, in the scene's order")
      .def_property_readonly("cells", [](const ComplexHandle& h) { return views<CellView>(h.input, h.complex().cells.size()); })
      .def_property_readonly("patches",
                             [](const ComplexHandle& h) { return views<PatchView>(h.input, h.complex().patches.size()); })
      .def_property_readonly("junctions", [](const ComplexHandle& h) {
        return views<JunctionView>(h.input, h.complex().junctions.size());
      })
      .def_property_readonly("samples",
                             [](const ComplexHandle& h) { return views<SampleView>(h.input, h.complex().samples.size()); })
      .def_property_readonly("supports", [](const ComplexHandle& h) { return h.complex().supports; },
                             "Groups of coincident patches (each patch in exactly one)")
      .def_property_readonly("outer_cell_count", [](const ComplexHandle& h) { return h.complex().outer_cell_count(); })
      .def("cell_patches", [](const ComplexHandle& h) { return h.complex().cell_patches(); },
           "The patches bounding each cell")
      .def("patch_neighbours", [](const ComplexHandle& h) { return h.complex().patch_neighbours(); },
           "The patches sharing a junction with each patch")
      .def("measure_of", [](const ComplexHandle& h, const std::vector<int>& patches) {
             for (int p : patches)
               if (p < 0 || p >= static_cast<int>(h.complex().patches.size()))
                 throw hsx::InputError("patches: no patch " + std::to_string(p));
             return h.complex().measure_of(patches);
           },
           py::arg("patches"), "The measure of a set of patches as a point set (coincident ones counted once)")
      .def("validate", [](const ComplexHandle& h) { return hsx::check_complex(h.complex()); },
           "Every structural invariant, checked exactly: the violations (empty: valid)")
      .def_property_readonly("identity", [](const ComplexHandle& h) { return hsx::complex_identity(h.complex()); },
                             "complex_id: the identity results carry (io/result_json.hpp)")
      .def_property_readonly("has_scene",
                             [](const ComplexHandle& h) { return h.input->scene.has_value() || h.input->scene3.has_value(); },
                             "Arranged from a scene, 2D or 3D (False: read from an hsx-complex/1 document)")
      .def_property_readonly("source", [](const ComplexHandle& h) { return h.input->path; },
                             "The file or name it was read from")
      .def("scene_json",
           [](const ComplexHandle& h) -> py::object {
             if (h.input->scene) return py::str(hsx::write_scene2(*h.input->scene).dump(2) + "\n");
             if (h.input->scene3) return py::str(hsx::write_scene3(*h.input->scene3).dump(2) + "\n");
             return py::none();
           },
           "The scene as hsx-scene/1 JSON text (exact numbers; 2D: the chosen domain included), None without a "
           "scene")
      .def("to_json", [](const ComplexHandle& h) { return hsx::complex_json_text(*h.input); },
           "The hsx-complex/1 document, byte for byte what `hsx arrange --json` writes")
      .def("svg", &complex_svg, py::arg("labels") = false, py::arg("width") = 800, py::arg("title") = "",
           py::arg("fill") = py::none(), py::arg("highlight") = py::none(),
           py::arg("highlight_legend") = "highlighted patches", py::arg("views") = py::none(),
           "The arrangement's picture as SVG text (as `hsx arrange --svg`; 3D: four orthographic views of its "
           "surfaces, io/svg3.hpp, width at least 200), None without a scene. `views` (3D only): the views to "
           "draw, names among front, side, top, isometric or (name, direction, up) tuples of exact numbers "
           "(None: all four defaults). `labels`: cell and patch ids; "
           "`fill`: per cell, True inside a shape (drawn as `hsx extract --svg` does: 2D boundary bold, 3D only "
           "the shape's boundary; missing samples ringed); `highlight`: patch ids drawn highlighted, described in "
           "the legend by `highlight_legend`")
      .def("surface_mesh", &surface_mesh, py::arg("exact") = false,
           "3D: the arrangement's surfaces (io/mesh_export.hpp's exported_faces, what `hsx arrange --ply/--obj` "
           "write): every triangle not on the domain box once, with its first halfspace and that halfspace's "
           "patch (-1: none), turned so that its normal (v1-v0)x(v2-v0) points out of that halfspace; a patch "
           "coincident with one of a lower halfspace has no faces of its own. (vertices, faces, patch, halfspace): "
           "vertices a float64 (n, 3) array, or with exact=True a list of (x, y, z) exact rational strings; faces "
           "an int64 (m, 3) array of vertex rows; patch and halfspace per face (int64 (m,)). Raises InputError "
           "for a 2D complex or one read from an hsx-complex/1 document")
      .def("_repr_svg_", [](const ComplexHandle& h) {
        if (h.input->scene3) return svg3_picture(h.input, hsx::Svg3Options{});
        return svg_picture(h.input, hsx::SvgOptions{});
      })
      .def("__repr__", &complex_repr);

  m.def("_load_text", &load_text, py::arg("text"), py::arg("source"), py::arg("max_cells"),
        py::arg("max_side_table"));
  m.def("_load_file", &load_file, py::arg("path"), py::arg("max_cells"), py::arg("max_side_table"));
  bind_random(m);
}

}  // namespace hsxpy
