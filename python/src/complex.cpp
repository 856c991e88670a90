// Inputs and complexes: hsx.Complex (cells, patches, junctions, samples, supports) over a shared input, read from
// JSON text or a file (load_input / load_input_text: the CLI's reading and messages), its hsx-complex/1 text and
// its picture (io/svg.hpp).
#include "bindings.hpp"

#include <hsx/io/result_json.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/io/svg.hpp>

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
         (h.input->scene ? "" : ", from an hsx-complex/1 document") + ">";
}

void bind_views(py::module_& m) {
  py::class_<CellView>(m, "Cell", "A cell of a complex (complex/complex.hpp)")
      .def_property_readonly("index", [](const CellView& v) { return v.index; })
      .def_property_readonly("outer", [](const CellView& v) { return v.complex().cells[v.index].outer; },
                             "Touches the domain's boundary: always outside any shape")
      .def_property_readonly("witness",
                             [](const CellView& v) { return fraction_tuple(v.complex().cells[v.index].witness); },
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
      .def_property_readonly("measure", [](const CellView& v) { return v.complex().cells[v.index].measure; },
                             "Area (2D)")
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
      .def_property_readonly("measure", [](const PatchView& v) { return v.complex().patches[v.index].measure; },
                             "Length (2D)")
      .def_property_readonly("support", [](const PatchView& v) { return v.complex().patches[v.index].support; },
                             "Its group of coincident patches (Complex.supports)")
      .def_property_readonly("junctions",
                             [](const PatchView& v) { return v.complex().patches[v.index].junctions; })
      .def("__repr__", [](const PatchView& v) {
        return "<hsx.Patch " + std::to_string(v.index) + " of " +
               v.complex().halfspace_names[v.complex().patches[v.index].halfspace] + ">";
      });
  py::class_<JunctionView>(m, "Junction", "Where patches meet (2D: a vertex)")
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

/// The picture of `h` with `options`; None for an input without a scene (nothing to draw).
py::object picture(const ComplexHandle& h, const hsx::SvgOptions& options) {
  if (!h.input->scene) return py::none();
  std::string svg;
  {
    py::gil_scoped_release release;
    svg = hsx::arrangement_svg(*h.input->scene, h.input->arranged->arrangement, h.complex(), options);
  }
  return py::str(svg);
}

}  // namespace

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
      .def_property_readonly("has_scene", [](const ComplexHandle& h) { return h.input->scene.has_value(); },
                             "Arranged from a scene (False: read from an hsx-complex/1 document)")
      .def_property_readonly("source", [](const ComplexHandle& h) { return h.input->path; },
                             "The file or name it was read from")
      .def("scene_json",
           [](const ComplexHandle& h) -> py::object {
             if (!h.input->scene) return py::none();
             return py::str(hsx::write_scene2(*h.input->scene).dump(2) + "\n");
           },
           "The scene as hsx-scene/1 JSON text (exact numbers; the chosen domain included), None without a scene")
      .def("to_json", [](const ComplexHandle& h) { return hsx::complex_json_text(*h.input); },
           "The hsx-complex/1 document, byte for byte what `hsx arrange --json` writes")
      .def("svg",
           [](const ComplexHandle& h, bool labels, int width, const std::string& title, py::object fill,
              py::object highlight, const std::string& highlight_legend) {
             hsx::SvgOptions o;
             o.show_cell_ids = o.show_patch_ids = labels;
             if (width < 1) throw hsx::InputError("width: must be at least 1");
             o.width = width;
             o.title = title;
             if (!fill.is_none()) o.cell_fill = flags_from(fill, h.complex().cells.size(), "fill");
             if (!highlight.is_none()) {
               o.highlight_patches.assign(h.complex().patches.size(), 0);
               for (py::handle p : highlight) {
                 const int k = p.cast<int>();
                 if (k < 0 || k >= static_cast<int>(h.complex().patches.size()))
                   throw hsx::InputError("highlight: no patch " + std::to_string(k));
                 o.highlight_patches[k] = 1;
               }
               o.highlight_legend = highlight_legend;
             }
             return picture(h, o);
           },
           py::arg("labels") = false, py::arg("width") = 800, py::arg("title") = "", py::arg("fill") = py::none(),
           py::arg("highlight") = py::none(), py::arg("highlight_legend") = "highlighted patches",
           "The arrangement's picture as SVG text (as `hsx arrange --svg`), None without a scene. `fill`: per cell, "
           "True inside a shape (drawn as `hsx extract --svg` does, boundary bold, missing samples ringed); "
           "`highlight`: patch ids drawn highlighted, described in the legend by `highlight_legend`")
      .def("_repr_svg_", [](const ComplexHandle& h) { return picture(h, hsx::SvgOptions{}); })
      .def("__repr__", &complex_repr);

  m.def("_load_text", &load_text, py::arg("text"), py::arg("source"), py::arg("max_cells"),
        py::arg("max_side_table"));
  m.def("_load_file", &load_file, py::arg("path"), py::arg("max_cells"), py::arg("max_side_table"));
}

}  // namespace hsxpy
