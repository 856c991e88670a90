// NH-Rep on a 2D solid (`hsx nhtree SCENE --csg ...`, the paper's reading of Algorithm 1 with patch
// decomposition): the tree, NH-Rep's .conf, the structural checks, the exact evaluation with natural halfspaces,
// the hsx-nhtree/1 document and the picture. Meshes (.obj + .fea) and NH-Rep's tool mode stay with the program.
#include "bindings.hpp"

#include <hsx/algorithms/nhrep/compare.hpp>
#include <hsx/algorithms/nhrep/planar.hpp>
#include <hsx/io/nhrep_json.hpp>
#include <hsx/io/nhrep_svg.hpp>

namespace hsxpy {
namespace {

namespace nhrep = hsx::nhrep;

struct NhTreeHandle {
  InputPtr input;
  std::vector<char> solid;
  std::shared_ptr<const nhrep::PlanarTree> tree;
  std::shared_ptr<const nhrep::PlanarEvaluation> evaluation;
  const nhrep::BuildResult& built() const { return tree->built; }
};

NhTreeHandle build(const ComplexHandle& h, py::handle solid, bool nest_holes) {
  if (!h.input->arranged)
    throw hsx::InputError("nhtree needs a scene, not a complex: corner angles need the geometry");
  NhTreeHandle t{h.input, flags_from(solid, h.complex().cells.size(), "solid"), nullptr, nullptr};
  nhrep::BuildOptions options;
  options.nest_holes = nest_holes;
  py::gil_scoped_release release;
  try {
    t.tree = std::make_shared<const nhrep::PlanarTree>(nhrep::build_planar_tree(*h.input->arranged, t.solid, options));
  } catch (const std::invalid_argument& e) {  // nest_holes on a solid without nesting, as the program reports it
    if (!nest_holes) throw;
    throw hsx::InputError(std::string("nest_holes: ") + e.what());
  }
  t.evaluation = std::make_shared<const nhrep::PlanarEvaluation>(
      nhrep::evaluate_on_whole_plane(*t.tree, *h.input->scene, *h.input->arranged, t.solid));
  return t;
}

std::string document(const NhTreeHandle& t) {
  nlohmann::json doc = hsx::nhtree_to_json(t.built(), nullptr);
  nlohmann::json extra = hsx::nhtree_planar_json(*t.tree, *t.evaluation);
  extra["input"] = t.input->path;
  for (auto& [key, value] : extra.items()) doc[key] = value;
  return doc.dump(1) + "\n";
}

std::string picture(const NhTreeHandle& t) {
  const nhrep::BuildResult& r = t.built();
  return hsx::nhrep_svg(*t.input->scene, *t.input->arranged, t.solid, r.graph.surface, r.graph.piece_patch,
                        t.tree->leaf_node, "NH-Rep tree: " + hsx::nhtree_text(r.tree));
}

}  // namespace

void bind_nhrep(py::module_& m) {
  py::class_<NhTreeHandle>(m, "NhTree", "NH-Rep's Boolean tree of a 2D solid and its exact evaluation")
      .def_property_readonly("tree",
                             [](const NhTreeHandle& t) {
                               return hsx::nhtree_text(
                                   nhrep::relabel_tree(t.built().tree, hsx::nhtree_conf_ids(t.built().graph)));
                             },
                             "The tree in NH-Rep's patch numbers (those of conf), as `hsx nhtree` prints it")
      .def_property_readonly("tree_ids", [](const NhTreeHandle& t) { return hsx::nhtree_text(t.built().tree); },
                             "The tree with Algorithm 1's patch ids (those of the document)")
      .def_property_readonly("conf", [](const NhTreeHandle& t) { return hsx::nhtree_conf(t.built()); },
                             "NH-Rep's .conf text")
      .def_property_readonly("leaf_names", [](const NhTreeHandle& t) { return t.tree->leaf_names; },
                             "Per patch id: its natural halfspace ('~A' when complemented; '' for dead patches)")
      .def_property_readonly("decompositions", [](const NhTreeHandle& t) { return t.built().decompositions.size(); })
      .def_property_readonly("structure_violations", [](const NhTreeHandle& t) { return nhrep::check_tree(t.built()); },
                             "Cross-check 1 (leaves, alternation, Q conditions, maximal subgraphs); empty: all hold")
      .def_property_readonly("verdict",
                             [](const NhTreeHandle& t) {
                               return std::string(nhrep::verdict_name(t.evaluation->evaluation.verdict));
                             },
                             "The exact evaluation with natural halfspaces against describability")
      .def_property_readonly("correct", [](const NhTreeHandle& t) { return t.evaluation->evaluation.correct; },
                             "The tree with natural halfspaces is the solid on every cell of the whole plane")
      .def_property_readonly("describable", [](const NhTreeHandle& t) { return t.evaluation->evaluation.describable; },
                             "The solid is describable by its natural halfspaces")
      .def_property_readonly("evaluation_violations",
                             [](const NhTreeHandle& t) { return t.evaluation->evaluation.violations; })
      .def_property_readonly("missed", [](const NhTreeHandle& t) {
        py::list l;
        for (const auto& p : t.evaluation->missed) l.append(fraction_tuple(p));
        return l;
      }, "Exact points of the solid the tree misses")
      .def_property_readonly("added", [](const NhTreeHandle& t) {
        py::list l;
        for (const auto& p : t.evaluation->added) l.append(fraction_tuple(p));
        return l;
      }, "Exact points outside the solid the tree adds")
      .def("to_json", &document, "The hsx-nhtree/1 document (`hsx nhtree SCENE --csg E --json F` writes the same)")
      .def("svg", &picture, "The picture (`hsx nhtree --svg`)")
      .def("_repr_svg_", &picture);
  m.def("_nhtree", &build, py::arg("complex"), py::arg("solid"), py::arg("nest_holes"));
}

}  // namespace hsxpy
