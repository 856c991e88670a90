// BSH: extract (every method, limits, ties, stats, steps), grade, check and GENERATE-SAMPLES. Each function
// converts its arguments, runs the library's call with the GIL released (inside a Guard where the library can be
// stopped) and wraps the result.
#include "bindings.hpp"

#include <hsx/algorithms/bsh/sample_scene.hpp>
#include <hsx/algorithms/bsh/samples.hpp>
#include <hsx/io/labelling.hpp>
#include <hsx/io/result_json.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/io/svg.hpp>

#include <pybind11/numpy.h>

#include <cmath>


namespace hsxpy {
namespace {

namespace bsh = hsx::bsh;

struct ResultHandle {
  InputPtr input;
  std::shared_ptr<const bsh::ExtractResult> result;
  const bsh::ExtractResult& r() const { return *result; }
};

struct GradeHandle {
  InputPtr input;
  std::shared_ptr<const bsh::Grade> grade;
};

struct SamplesHandle {
  InputPtr input;
  bsh::SampleGenResult r;
  int minimum = -1;
};

// ---- extraction options, as the CLI checks them ----

struct ExtractArgs {
  std::string method;
  int beam_width;
  long max_states, max_graph_cuts, max_nodes;
  double time_limit;
  long max_labellings;
  int max_ties;
  bool enumerate_ties;
  int precision;
  bool record_states;
};

/// `seconds` as a time limit (0: none); NaN, infinities and negative numbers are refused, as the CLI's are.
double checked_time_limit(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0)
    throw hsx::InputError("time_limit: must be a finite number of seconds >= 0");
  return seconds;
}

bsh::ExtractOptions extract_options(const ExtractArgs& a) {
  bsh::ExtractOptions o;
  o.method = method_named(a.method, "method");
  if (a.beam_width < 1) throw hsx::InputError("beam_width: must be at least 1");
  if (a.max_states < 0) throw hsx::InputError("max_states: must be >= 0");
  if (a.max_graph_cuts < 0) throw hsx::InputError("max_graph_cuts: must be >= 0");
  if (a.max_nodes < 0) throw hsx::InputError("max_nodes: must be >= 0");
  if (a.max_labellings < 1) throw hsx::InputError("max_labellings: must be at least 1");
  if (a.max_ties < 1) throw hsx::InputError("max_ties: must be at least 1");
  if (a.precision < 64) throw hsx::InputError("precision: at least 64 bits");
  o.beam_width = a.beam_width;
  o.max_states = a.max_states;
  o.max_graph_cuts = a.max_graph_cuts;
  o.max_nodes = a.max_nodes;
  o.time_limit = checked_time_limit(a.time_limit);
  o.brute_force_limit = a.max_labellings;
  o.max_ties = a.max_ties;
  o.enumerate_ties = a.enumerate_ties;
  o.compare.max_bits = a.precision;
  o.record_states = a.record_states;
  return o;
}

ResultHandle run_extract(const ComplexHandle& h, const ExtractArgs& args, py::object progress,
                         std::shared_ptr<CancelToken> token) {
  bsh::ExtractOptions options = extract_options(args);
  const Guard guard(std::move(token), std::move(progress));
  options.cancel = guard.cancel();
  options.progress = guard.progress();
  std::shared_ptr<bsh::ExtractResult> result;
  {
    py::gil_scoped_release release;
    const bsh::Problem problem(h.complex());
    result = std::make_shared<bsh::ExtractResult>(bsh::extract(problem, options));
  }
  guard.finish();
  return {h.input, result};
}

// ---- results ----

py::list labellings(const std::vector<bsh::Labelling>& ls) {
  py::list l;
  for (const auto& x : ls) l.append(bool_array(x));
  return l;
}

std::vector<int> boundary_patches(const ResultHandle& h) {
  const hsx::Complex& c = h.input->complex();
  const bsh::Problem problem(c);
  std::vector<char> on(c.supports.size(), 0);
  for (int g : bsh::boundary_supports(problem, h.r().labelling)) on[g] = 1;
  return hsx::patches_of_supports(c, on);
}

// The shape's boundary (io/mesh_export.hpp's shape_faces: outward, closed) as face_arrays gives it.
py::tuple boundary_mesh(const ResultHandle& h, bool exact) {
  const hsx::LoadedInput& in = *h.input;
  if (!in.arranged3) throw hsx::InputError("boundary_mesh: needs a result of a 3D scene");
  return face_arrays(*in.arranged3, hsx::shape_faces(*in.arranged3, h.r().labelling), exact);
}

std::vector<std::vector<int>> step_patches(const ResultHandle& h) {
  const hsx::Complex& c = h.input->complex();
  std::vector<std::vector<int>> out;
  for (const auto& removed : h.r().steps) {
    std::vector<char> flags(c.supports.size(), 0);
    for (int g : removed) flags[g] = 1;
    out.push_back(hsx::patches_of_supports(c, flags));
  }
  return out;
}

py::dict bound_dict(const bsh::EnergyBound& b) {
  py::dict d;
  d["missing_samples"] = b.missing_samples;
  d["measure"] = b.measure;
  return d;
}

py::dict stats_dict(const bsh::SearchStats& s) {
  py::dict d;
  d["graph_cuts"] = s.graph_cuts;
  d["uncertified_cuts"] = s.uncertified_cuts;
  d["reused_cuts"] = s.reused_cuts;
  d["states_expanded"] = s.states_expanded;
  d["states_created"] = s.states_created;
  d["max_queue"] = s.max_queue;
  d["labellings_enumerated"] = s.labellings_enumerated;
  d["nodes"] = s.nodes;
  d["nodes_created"] = s.nodes_created;
  d["pruned_by_bound"] = s.pruned_by_bound;
  d["pruned_by_islands"] = s.pruned_by_islands;
  d["island_branches"] = s.island_branches;
  d["certified_bounds"] = s.certified_bounds;
  d["lower_bound"] = bound_dict(s.lower_bound);
  d["gap"] = bound_dict(s.gap);
  d["max_gap"] = bound_dict(s.max_gap);
  d["seconds"] = s.seconds;
  return d;
}

py::object result_svg(const ResultHandle& h, bool show_removed, bool labels, int width, const std::string& title,
                      py::object views) {
  refuse_views_in_2d(h.input, views);
  std::vector<char> highlight;
  if (show_removed) {
    highlight.assign(h.input->complex().patches.size(), 0);
    for (int p : hsx::patches_of_supports(h.input->complex(), h.r().removed)) highlight[p] = 1;
  }
  if (h.input->scene3) {  // as `hsx extract --svg` on a 3D scene: the shape's boundary in four views
    hsx::Svg3Options o;
    o.width = width;
    o.title = title;
    o.cell_fill = h.r().labelling;
    o.show_cell_ids = o.show_patch_ids = labels;
    o.highlight_patches = highlight;
    o.highlight_legend = "removed patches";
    o.views = svg3_views(views);
    return svg3_picture(h.input, o);
  }
  hsx::SvgOptions o;
  o.width = width;
  o.title = title;
  o.cell_fill = h.r().labelling;
  o.show_cell_ids = o.show_patch_ids = labels;
  if (show_removed) {
    o.highlight_legend = "removed patches";
    o.highlight_patches = highlight;
  }
  return svg_picture(h.input, o);
}

void bind_result(py::module_& m) {
  py::class_<bsh::Energy>(m, "Energy", "E(b) = (missing samples, boundary measure), compared lexicographically")
      .def_readonly("missing_samples", &bsh::Energy::missing_samples)
      .def_property_readonly("measure", [](const bsh::Energy& e) { return e.measure(); })
      .def("compare",
           [](const bsh::Energy& a, const bsh::Energy& b, long max_bits) {
             hsx::CompareOptions o;
             o.max_bits = max_bits;
             return bsh::compare(a, b, o);
           },
           py::arg("other"), py::arg("max_bits") = 2048, "Certified: Less/Equal/Greater are proofs, Tie is not")
      .def("__iter__", [](const bsh::Energy& e) { return py::iter(py::make_tuple(e.missing_samples, e.measure())); })
      .def("__repr__", [](const bsh::Energy& e) {
        return "Energy(missing_samples=" + std::to_string(e.missing_samples) +
               ", measure=" + py::repr(py::cast(e.measure())).cast<std::string>() + ")";
      });
  py::class_<bsh::Ties>(m, "Ties", "Other optimal boundaries (complete methods)")
      .def_readonly("count", &bsh::Ties::count)
      .def_readonly("checked", &bsh::Ties::checked)
      .def_readonly("certified", &bsh::Ties::certified)
      .def_readonly("capped", &bsh::Ties::capped)
      .def_readonly("stopped_by", &bsh::Ties::stopped_by)
      .def("__repr__", [](const bsh::Ties& t) {
        return "Ties(count=" + std::to_string(t.count) + ", checked=" + (t.checked ? "True" : "False") +
               ", certified=" + (t.certified ? "True" : "False") + ", capped=" + (t.capped ? "True" : "False") +
               ")";
      });
  py::class_<ResultHandle>(m, "Result", "A BSH shape and how it was found (hsx-result/1)")
      .def_property_readonly("complex", [](const ResultHandle& h) { return ComplexHandle{h.input}; })
      .def_property_readonly("method", [](const ResultHandle& h) { return std::string(bsh::to_string(h.r().method)); })
      .def_property_readonly("optimal", [](const ResultHandle& h) { return h.r().optimal; },
                             "Proven the least-energy orientation-preserving sample-connected boundary")
      .def_property_readonly("labelling", [](const ResultHandle& h) { return bool_array(h.r().labelling); },
                             "Per cell: True inside the shape (a numpy bool array)")
      .def_property_readonly("inside_cells",
                             [](const ResultHandle& h) {
                               std::vector<int> cells;
                               for (std::size_t k = 0; k < h.r().labelling.size(); ++k)
                                 if (h.r().labelling[k]) cells.push_back(static_cast<int>(k));
                               return cells;
                             })
      .def_property_readonly("energy", [](const ResultHandle& h) { return h.r().energy; })
      .def_property_readonly("area", [](const ResultHandle& h) {
        return bsh::inside_measure(h.input->complex(), h.r().labelling);
      }, "The measure of the inside: its area (2D) or its volume (3D)")
      .def_property_readonly("volume", [](const ResultHandle& h) {
        if (h.input->complex().dimension != 3) throw hsx::InputError("volume: a 2D result has an area (Result.area)");
        return bsh::inside_measure(h.input->complex(), h.r().labelling);
      }, "3D: the inside's exact volume (`hsx extract --json`'s volume); raises InputError for a 2D result")
      .def_property_readonly("sample_connected", [](const ResultHandle& h) { return h.r().sample_connected; })
      .def_property_readonly("boundary_patches", &boundary_patches, "Patches on the shape's boundary, ascending")
      .def("boundary_mesh", &boundary_mesh, py::arg("exact") = false,
           "3D: the shape's boundary as a closed, outward triangle mesh (io/mesh_export.hpp's shape_faces, what "
           "`hsx extract --obj/--ply/--off` write): (vertices, faces, patch, halfspace); vertices a float64 (n, 3) "
           "array, or with exact=True a list of (x, y, z) exact rational strings; faces an int64 (m, 3) array of "
           "vertex rows, normal (v1-v0)x(v2-v0) outward; patch and halfspace per face (int64 (m,)). Raises "
           "InputError for a 2D result")
      .def_property_readonly("removed_patches",
                             [](const ResultHandle& h) {
                               return hsx::patches_of_supports(h.input->complex(), h.r().removed);
                             })
      .def_property_readonly("steps", &step_patches,
                             "Beam search: the removed patches of each state on the path to the result (Fig. 10)")
      .def_property_readonly("ties", [](const ResultHandle& h) { return h.r().ties; })
      .def_property_readonly("tied", [](const ResultHandle& h) { return labellings(h.r().tied); },
                             "The other optimal labellings")
      .def_property_readonly("stopped_by", [](const ResultHandle& h) { return h.r().stopped_by; },
                             "The limit that stopped the search ('' when it finished; 'cancelled')")
      .def_property_readonly("optimality_note", [](const ResultHandle& h) { return h.r().optimality_note; })
      .def_property_readonly("expanded", [](const ResultHandle& h) { return labellings(h.r().expanded); },
                             "With record_states=True: every expanded state's labelling")
      .def_property_readonly("stats", [](const ResultHandle& h) { return stats_dict(h.r().stats); })
      .def("to_json",
           [](const ResultHandle& h, bool include_seconds) {
             return hsx::result_json_text(h.input->complex(), h.r(), h.input->pieces(), include_seconds);
           },
           py::arg("include_seconds") = false,
           "The hsx-result/1 document (`hsx extract --json --no-timing` writes the same bytes)")
      .def("svg", &result_svg, py::arg("show_removed") = false, py::arg("labels") = false, py::arg("width") = 800,
           py::arg("title") = "", py::arg("views") = py::none(),
           "The shape's picture (as `hsx extract --svg`; 3D: its boundary in four orthographic views, io/svg3.hpp, "
           "width at least 200), None without a scene. `show_removed`: the search's removed patches highlighted; "
           "`views` (3D only): as Complex.svg's")
      .def("_repr_svg_", [](const ResultHandle& h) { return result_svg(h, false, false, 800, "", py::none()); })
      .def("__repr__", [](const ResultHandle& h) {
        return "<hsx.Result " + std::string(bsh::to_string(h.r().method)) + (h.r().optimal ? " optimal" : "") +
               ": " + std::to_string(h.r().energy.missing_samples) + " missing, measure " +
               h.r().energy.measure().decimal_string(12) + ">";
      });
}

// ---- grade, check ----

void bind_grade(py::module_& m) {
  py::class_<GradeHandle>(m, "Grade", "A labelling computed elsewhere, graded exactly against the optimum")
      .def_property_readonly("orientation_preserving", [](const GradeHandle& g) { return g.grade->orientation_preserving; })
      .def_property_readonly("orientation_problem", [](const GradeHandle& g) { return g.grade->orientation_problem; })
      .def_property_readonly("sample_connected", [](const GradeHandle& g) { return g.grade->sample_connected; })
      .def_property_readonly("islands",
                             [](const GradeHandle& g) {
                               py::list l;
                               for (const auto& c : g.grade->islands) {
                                 py::dict d;
                                 d["halfspace"] = g.input->complex().halfspace_names[c.halfspace];
                                 d["patches"] = c.patches;
                                 l.append(d);
                               }
                               return l;
                             },
                             "Components of b ∩ b_i without a sample of i")
      .def_property_readonly("energy", [](const GradeHandle& g) { return g.grade->energy; })
      .def_property_readonly("optimum",
                             [](const GradeHandle& g) {
                               return ResultHandle{g.input, std::shared_ptr<const bsh::ExtractResult>(
                                                                g.grade, &g.grade->optimum)};
                             })
      .def_property_readonly("versus_optimum", [](const GradeHandle& g) { return g.grade->versus_optimum; })
      .def_property_readonly("missing_samples_gap", [](const GradeHandle& g) { return g.grade->missing_samples_gap; })
      .def_property_readonly("measure_gap", [](const GradeHandle& g) { return g.grade->measure_gap; })
      .def_property_readonly("optimal", [](const GradeHandle& g) { return g.grade->optimal(); },
                             "A valid boundary whose energy is proven equal to a proven optimum");
  m.def("_grade",
        [](const ComplexHandle& h, py::handle labelling, const std::string& method, double time_limit,
           py::object progress, std::shared_ptr<CancelToken> token) {
          const std::vector<char> flags = flags_from(labelling, h.complex().cells.size(), "labelling");
          bsh::ExtractOptions oracle = bsh::best_first_oracle();
          oracle.method = method_named(method, "oracle");
          oracle.time_limit = checked_time_limit(time_limit);
          const Guard guard(std::move(token), std::move(progress));
          oracle.cancel = guard.cancel();
          oracle.progress = guard.progress();
          std::shared_ptr<bsh::Grade> g;
          {
            py::gil_scoped_release release;
            g = std::make_shared<bsh::Grade>(hsx::grade_labelling(h.complex(), flags, oracle));
          }
          guard.finish();
          return GradeHandle{h.input, g};
        },
        py::arg("complex"), py::arg("labelling"), py::arg("oracle"), py::arg("time_limit"), py::arg("progress"),
        py::arg("cancel"));
  // io/labelling.hpp: a labelling written elsewhere (an hsx-result/1, the BSH authors' {"labels": [...]}, a JSON
  // list or a plain 0/1 list) as a per-cell numpy bool array; and the authors' graph-cut input.
  m.def("_labelling_text",
        [](const ComplexHandle& h, const std::string& text, const std::string& source) {
          return bool_array(hsx::read_labelling_text(text, source, h.complex()).cells);
        },
        py::arg("complex"), py::arg("text"), py::arg("source"));
  m.def("_labelling_file",
        [](const ComplexHandle& h, const std::string& path) {
          return bool_array(hsx::read_labelling_file(path, h.complex()).cells);
        },
        py::arg("complex"), py::arg("path"));
  m.def("_export_graphcut",
        [](const ComplexHandle& h, std::int64_t weight_scale) {
          return hsx::bsh_graphcut_to_json(h.complex(), weight_scale).dump();
        },
        py::arg("complex"), py::arg("weight_scale"));
  m.attr("DEFAULT_GRAPHCUT_WEIGHT_SCALE") = hsx::kDefaultGraphcutWeightScale;
}

void bind_check(py::module_& m) {
  py::class_<bsh::CheckResult>(m, "CheckResult", "One proposition checker's outcome (as a row of `hsx check`)")
      .def_readonly("name", &bsh::CheckResult::name)
      .def_property_readonly("status", [](const bsh::CheckResult& c) { return std::string(bsh::to_string(c.status)); },
                             "'pass', 'FAIL', 'skipped' or 'stopped'")
      .def_readonly("witness", &bsh::CheckResult::witness)
      .def("__repr__", [](const bsh::CheckResult& c) {
        return "<hsx.CheckResult " + std::string(bsh::to_string(c.status)) + ": " + c.name + ">";
      });
  m.def("_check",
        [](const ComplexHandle& h, long brute_force_limit, double time_limit, long max_states, long max_graph_cuts,
           int precision, std::shared_ptr<CancelToken> token) {
          bsh::CheckOptions o;
          if (brute_force_limit < 1) throw hsx::InputError("max_labellings: must be at least 1");
          if (max_states < 0) throw hsx::InputError("max_states: must be >= 0");
          if (max_graph_cuts < 0) throw hsx::InputError("max_graph_cuts: must be >= 0");
          if (precision < 64) throw hsx::InputError("precision: at least 64 bits");
          o.brute_force_limit = brute_force_limit;
          o.time_limit = checked_time_limit(time_limit);
          o.max_states = max_states;
          o.max_graph_cuts = max_graph_cuts;
          o.compare.max_bits = precision;
          const Guard guard(std::move(token), py::none());
          o.cancel = guard.cancel();
          std::vector<bsh::CheckResult> results;
          {
            py::gil_scoped_release release;
            results = bsh::check_all(h.complex(), o);
          }
          guard.finish();
          return results;
        },
        py::arg("complex"), py::arg("max_labellings"), py::arg("time_limit"), py::arg("max_states"),
        py::arg("max_graph_cuts"), py::arg("precision"), py::arg("cancel"));
}

// ---- GENERATE-SAMPLES ----

void bind_samples(py::module_& m) {
  py::class_<SamplesHandle>(m, "Samples", "GENERATE-SAMPLES (BSH Fig. 12): samples that reproduce a target")
      .def_property_readonly("sample_patches", [](const SamplesHandle& h) { return h.r.sample_patches; },
                             "One sample per listed patch, in the order added")
      .def_property_readonly("count", [](const SamplesHandle& h) { return h.r.sample_patches.size(); })
      .def_property_readonly("lower_bound", [](const SamplesHandle& h) { return h.r.initial; })
      .def_property_readonly("upper_bound", [](const SamplesHandle& h) { return h.r.upper_bound; })
      .def_property_readonly("rounds", [](const SamplesHandle& h) { return h.r.rounds; })
      .def_property_readonly("reproduced", [](const SamplesHandle& h) { return h.r.reproduced; })
      .def_property_readonly("fallbacks", [](const SamplesHandle& h) { return h.r.fallbacks; })
      .def_property_readonly("used_sufficient_set", [](const SamplesHandle& h) { return h.r.used_sufficient_set; })
      .def_property_readonly("failure", [](const SamplesHandle& h) { return h.r.failure; })
      .def_property_readonly("minimum",
                             [](const SamplesHandle& h) -> py::object {
                               if (h.minimum < 0) return py::none();
                               return py::int_(h.minimum);
                             },
                             "The exhaustive minimum, None when too large to search")
      .def("scene_json",
           [](const SamplesHandle& h, const std::string& description) -> py::object {
             if (h.input->scene3)  // 3D: at the centroid of each patch's largest triangle (sample_scene.hpp)
               return py::str(hsx::write_scene3(bsh::scene_with_samples(*h.input->scene3, *h.input->arranged3,
                                                                        h.r.sample_patches, description))
                                  .dump(2) + "\n");
             if (!h.input->scene) return py::none();
             return py::str(hsx::write_scene2(bsh::scene_with_samples(*h.input->scene, *h.input->arranged,
                                                                      h.r.sample_patches, description))
                                .dump(2) + "\n");
           },
           py::arg("description") = "samples from GENERATE-SAMPLES",
           "The scene with these samples instead of its own (None without a scene)");
  m.def("_samples", [](const ComplexHandle& h, py::handle target, const std::string& search, int beam_width,
                       int exhaustive_patches) {
    const std::vector<char> cells = flags_from(target, h.complex().cells.size(), "target");
    bsh::SampleGenOptions o;
    o.search = method_named(search, "search");
    if (o.search != bsh::Method::Beam && o.search != bsh::Method::BestFirst)
      throw hsx::InputError("search: beam or best-first");
    if (beam_width < 1) throw hsx::InputError("beam_width: must be at least 1");
    if (exhaustive_patches < 0) throw hsx::InputError("exhaustive_patches: must be >= 0");
    o.beam_width = beam_width;
    SamplesHandle s{h.input, {}, -1};
    py::gil_scoped_release release;
    const bsh::Problem problem(h.complex());
    std::string why;
    if (!bsh::is_orientation_preserving(problem, cells, &why))
      throw hsx::InputError("target: the target boundary is not orientation-preserving: " + why);
    s.r = bsh::generate_samples(h.complex(), cells, o);
    s.minimum = bsh::minimum_samples(h.complex(), cells, exhaustive_patches);
    return s;
  });
}

}  // namespace

void bind_algorithms(py::module_& m) {
  bind_result(m);
  m.def("_extract",
        [](const ComplexHandle& h, const std::string& method, int beam_width, long max_states, long max_graph_cuts,
           long max_nodes, double time_limit, long max_labellings, int max_ties, bool enumerate_ties, int precision,
           bool record_states, py::object progress, std::shared_ptr<CancelToken> cancel) {
          return run_extract(h,
                             ExtractArgs{method, beam_width, max_states, max_graph_cuts, max_nodes, time_limit,
                                         max_labellings, max_ties, enumerate_ties, precision, record_states},
                             std::move(progress), std::move(cancel));
        },
        py::arg("complex"), py::arg("method"), py::arg("beam_width"), py::arg("max_states"),
        py::arg("max_graph_cuts"), py::arg("max_nodes"), py::arg("time_limit"), py::arg("max_labellings"),
        py::arg("max_ties"), py::arg("enumerate_ties"), py::arg("precision"), py::arg("record_states"),
        py::arg("progress"), py::arg("cancel"));
  m.attr("DEFAULT_MAX_LABELLINGS") = bsh::ExtractOptions().brute_force_limit;
  bind_grade(m);
  bind_check(m);
  bind_samples(m);
}

}  // namespace hsxpy
