// Halfspace CSG: solids from expressions or results, Shapiro-Vossler describability, BHC trees (with
// separators), and the conversion of CSG solids (and CSGNet programs) to BSH scenes. Each function converts its
// arguments, runs the library's call with the GIL released and wraps the result.
#include "bindings.hpp"

#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/algorithms/csg/convert.hpp>
#include <hsx/algorithms/csg/solid_tree.hpp>
#include <hsx/io/csg_text.hpp>
#include <hsx/io/csgnet.hpp>
#include <hsx/io/exact_json.hpp>
#include <hsx/io/result_json.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/io/solid.hpp>
#include <hsx/io/svg.hpp>

namespace hsxpy {
namespace {

namespace bsh = hsx::bsh;
namespace csg = hsx::csg;

struct DescribeHandle {
  InputPtr input;
  std::vector<char> solid;
  csg::Describability d;
};

struct CsgHandle {
  InputPtr input;
  std::shared_ptr<const csg::SolidTree> tree;
};

// ---- CSG: solids, describability, BHC ----

py::object mixed_term(const hsx::Complex& c, const csg::MixedTerm& t) {
  py::dict signs;
  for (int i = 0; i < c.halfspace_count() && i < static_cast<int>(t.signs.size()); ++i)
    signs[py::str(c.halfspace_names[i])] = py::bool_(t.signs[i] != 0);
  py::dict d;
  d["signs"] = signs;
  d["inside_cells"] = t.inside_cells;
  d["outside_cells"] = t.outside_cells;
  return std::move(d);
}

py::object describe_svg(const DescribeHandle& h, bool labels) {
  hsx::SvgOptions o;
  o.cell_fill = h.solid;
  o.show_cell_ids = o.show_patch_ids = labels;
  o.cell_marks.assign(h.solid.size(), 0);
  for (const auto& t : h.d.mixed) {
    for (int k : t.inside_cells) o.cell_marks[k] = 1;
    for (int k : t.outside_cells) o.cell_marks[k] = 2;
  }
  return svg_picture(h.input, o);
}

/// The complex the tree is over: the refined scene's when separators were added, the input's otherwise.
const hsx::Complex& tree_complex(const CsgHandle& h) {
  return h.tree->separated    ? h.tree->separated->arranged.complex
         : h.tree->separated3 ? h.tree->separated3->arranged.complex
                              : h.input->complex();
}

void bind_csg(py::module_& m) {
  m.def("_solid_from_csg",
        [](const ComplexHandle& h, const std::string& expression) {
          return bool_array(hsx::solid_from_csg(h.complex(), expression));
        },
        py::arg("complex"), py::arg("expression"));
  m.def("_solid_from_mesh",
        [](const ComplexHandle& h, const std::string& path) {
          hsx::SolidSource source{"", "", path, "shape=", "csg=", "mesh="};
          std::vector<char> cells;
          {
            py::gil_scoped_release release;
            cells = hsx::load_solid(*h.input, source).cells;
          }
          return bool_array(cells);
        },
        py::arg("complex"), py::arg("path"));
  m.def("_result_labelling",
        [](const ComplexHandle& h, const std::string& json_text) {
          return bool_array(hsx::read_result_labelling(hsx::parse_exact_json(json_text), h.complex()));
        },
        py::arg("complex"), py::arg("json_text"));
  m.def("_flags", [](const ComplexHandle& h, py::handle labelling) {
    return bool_array(flags_from(labelling, h.complex().cells.size(), "solid"));
  });
  py::class_<DescribeHandle>(m, "Describability", "Shapiro-Vossler describability of a solid by the halfspaces")
      .def_property_readonly("describable", [](const DescribeHandle& h) { return h.d.describable; })
      .def_property_readonly("terms", [](const DescribeHandle& h) { return h.d.terms; },
                             "Non-empty canonical intersection terms")
      .def_property_readonly("mixed",
                             [](const DescribeHandle& h) {
                               py::list l;
                               for (const auto& t : h.d.mixed) l.append(mixed_term(h.input->complex(), t));
                               return l;
                             },
                             "Mixed terms: signs per halfspace, inside and outside cells (the witnesses)")
      .def("svg", &describe_svg, py::arg("labels") = false)
      .def("_repr_svg_", [](const DescribeHandle& h) { return describe_svg(h, false); })
      .def("__bool__", [](const DescribeHandle& h) { return h.d.describable; });
  m.def("_describe", [](const ComplexHandle& h, py::handle solid) {
    DescribeHandle d{h.input, flags_from(solid, h.complex().cells.size(), "solid"), {}};
    py::gil_scoped_release release;
    d.d = csg::describability(h.complex(), d.solid);
    return d;
  });

  py::class_<CsgHandle>(m, "CsgTree", "Buchele-Crawford's BHC tree of a solid, verified on every cell")
      .def_property_readonly("describable", [](const CsgHandle& h) { return h.tree->bhc.describable; })
      .def_property_readonly("verified", [](const CsgHandle& h) { return h.tree->has_verified_tree(); })
      .def_property_readonly("text",
                             [](const CsgHandle& h) -> py::object {
                               if (!h.tree->bhc.tree) return py::none();
                               const hsx::Complex& c = tree_complex(h);
                               return py::str(csg::to_text(*h.tree->bhc.tree, c.halfspace_names));
                             },
                             "The tree in hsx's CSG text, None when not describable")
      .def_property_readonly("stats",
                             [](const CsgHandle& h) {
                               const csg::BhcResult& r = h.tree->bhc;
                               py::dict d;
                               d["depth"] = r.stats.depth;
                               d["internal_nodes"] = r.stats.internal_nodes;
                               d["leaves"] = r.stats.leaves;
                               d["distinct_halfspaces"] = r.stats.distinct_halfspaces;
                               d["duplicated_halfspaces"] = r.stats.duplicated_halfspaces;
                               d["factored"] = r.factored;
                               d["partitions"] = r.partitions;
                               return d;
                             })
      .def_property_readonly("mixed",
                             [](const CsgHandle& h) {
                               const hsx::Complex& c = tree_complex(h);
                               py::list l;
                               for (const auto& t : h.tree->describability.mixed) l.append(mixed_term(c, t));
                               return l;
                             },
                             "When not describable: the mixed terms")
      .def_property_readonly("separated_scene_json",
                             [](const CsgHandle& h) -> py::object {
                               if (h.tree->separated3)
                                 return py::str(hsx::write_scene3(h.tree->separated3->scene).dump(2) + "\n");
                               if (!h.tree->separated) return py::none();
                               return py::str(hsx::write_scene2(h.tree->separated->scene).dump(2) + "\n");
                             },
                             "With separators=True and a solid not describable by the scene: the scene with the "
                             "separating half-planes (2D) or planes (3D) added")
      .def("__bool__", [](const CsgHandle& h) { return h.tree->has_verified_tree(); });
  m.def("_csg", [](const ComplexHandle& h, py::handle solid, bool separators, int max_separators) {
    const std::vector<char> cells = flags_from(solid, h.complex().cells.size(), "solid");
    if (max_separators < 0) throw hsx::InputError("max_separators: must be >= 0");
    if (!h.input->scene && !h.input->scene3 && separators)
      throw hsx::InputError("separators: needs a scene (separating half-planes and planes are geometry), not a "
                            "complex");
    py::gil_scoped_release release;
    const InputPtr& in = h.input;
    // As `hsx csg`: BHC preferring half-planes (2D) or planes (3D), plain BHC on a complex without geometry.
    auto tree = std::make_shared<csg::SolidTree>(
        in->scene    ? csg::build_tree(*in->scene, *in->arranged, cells, csg::SolidTreeOptions{separators, max_separators})
        : in->scene3 ? csg::build_tree(*in->scene3, *in->arranged3, cells,
                                       csg::SolidTreeOptions{separators, max_separators})
                     : csg::build_tree(in->complex(), cells));
    return CsgHandle{h.input, tree};
  });
}

// ---- conversion of CSG solids to BSH scenes ----

bsh::Method search_named(const std::string& search) {
  const bsh::Method m = method_named(search, "search");
  if (m != bsh::Method::Beam && m != bsh::Method::BestFirst) throw hsx::InputError("search: beam or best-first");
  return m;
}

/// A conversion as Python sees it, 2D or 3D: `hsx convert`'s summary (its --json) and the scene it writes.
struct Conversion {
  int dimension = 2;
  bsh::SampleGenResult samples;
  std::vector<std::string> flipped;
  bool round_trip = false;
  std::string failure;
  std::string scene_json;  ///< what `hsx convert --out` writes
  // 3D: the complex the samples are on (the oriented scene's) and the solid on it
  std::size_t cells = 0, patches = 0;
  std::vector<int> inside_cells;
  std::optional<hsx::Measure> volume;
  bool ok() const { return samples.reproduced && round_trip; }
};

Conversion conversion_of(const csg::ConversionReport& r) {
  return Conversion{2, r.samples, r.flipped, r.round_trip, r.failure, hsx::write_scene2(r.scene).dump(2) + "\n",
                    0, 0, {}, std::nullopt};
}

Conversion conversion_of(const csg::ConversionReport3& r) {
  Conversion c{3, r.samples, r.flipped, r.round_trip, r.failure, hsx::write_scene3(r.scene).dump(2) + "\n",
               r.oriented.complex.cells.size(), r.oriented.complex.patches.size(), {},
               bsh::inside_measure(r.oriented.complex, r.oriented_solid)};
  for (std::size_t k = 0; k < r.oriented_solid.size(); ++k)
    if (r.oriented_solid[k]) c.inside_cells.push_back(static_cast<int>(k));
  return c;
}

void bind_convert(py::module_& m) {
  py::class_<Conversion>(m, "Conversion",
                         "A CSG solid as a BSH scene (`hsx convert`, 2D or 3D): samples from GENERATE-SAMPLES, "
                         "checked by extracting the scene back")
      .def_property_readonly("ok", &Conversion::ok, "The samples reproduce the solid and the round trip gives it "
                                                    "back")
      .def_readonly("dimension", &Conversion::dimension, "2 or 3")
      .def_readonly("round_trip", &Conversion::round_trip)
      .def_readonly("failure", &Conversion::failure)
      .def_readonly("flipped", &Conversion::flipped,
                    "Halfspaces complemented (or copied complemented) for the orientation rule")
      .def_property_readonly("samples", [](const Conversion& r) { return r.samples.sample_patches.size(); })
      .def_property_readonly("sample_patches", [](const Conversion& r) { return r.samples.sample_patches; },
                             "The patches sampled (3D: ids on the oriented scene's complex)")
      .def_property_readonly("lower_bound", [](const Conversion& r) { return r.samples.initial; })
      .def_property_readonly("upper_bound", [](const Conversion& r) { return r.samples.upper_bound; })
      .def_property_readonly("rounds", [](const Conversion& r) { return r.samples.rounds; })
      .def_property_readonly(
          "cells", [](const Conversion& r) { return r.dimension == 3 ? py::cast(r.cells) : py::none(); },
          "3D: cells of the complex the samples are on (the oriented scene's); None in 2D")
      .def_property_readonly(
          "patches", [](const Conversion& r) { return r.dimension == 3 ? py::cast(r.patches) : py::none(); },
          "3D: patches of that complex; None in 2D")
      .def_property_readonly(
          "inside_cells",
          [](const Conversion& r) { return r.dimension == 3 ? py::cast(r.inside_cells) : py::none(); },
          "3D: the solid's cells on that complex, ascending; None in 2D")
      .def_property_readonly(
          "volume", [](const Conversion& r) { return r.volume ? py::cast(*r.volume) : py::none(); },
          "3D: the solid's exact volume (a Measure); None in 2D")
      .def("scene_json", [](const Conversion& r) { return r.scene_json; },
           "The BSH scene as hsx-scene/1 JSON text (what `hsx convert --out` writes)")
      .def("__bool__", &Conversion::ok);
  m.def("_convert", [](const ComplexHandle& h, py::handle solid, const std::string& search) {
    const hsx::LoadedInput& in = *h.input;
    if (!in.scene && !in.scene3) throw hsx::InputError("convert needs a scene, not a complex");
    const std::vector<char> cells = flags_from(solid, h.complex().cells.size(), "solid");
    const bsh::Method method = search_named(search);
    py::gil_scoped_release release;
    if (in.scene3) return conversion_of(csg::convert_to_bsh(*in.scene3, *in.arranged3, cells, method));
    return conversion_of(csg::convert_to_bsh(*in.scene, *in.arranged, cells, method));
  });
  m.def("_convert_csgnet", [](const std::string& program, const std::string& search) {
    const bsh::Method method = search_named(search);
    py::gil_scoped_release release;
    const hsx::CsgnetProgram p = hsx::read_csgnet(program, "csgnet");
    return conversion_of(csg::convert_to_bsh(p.scene, *p.expression, method));
  });
}

}  // namespace

void bind_csg_module(py::module_& m) {
  bind_csg(m);
  bind_convert(m);
}

}  // namespace hsxpy
