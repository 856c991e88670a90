// hsx describe / csg / convert / samples / corpus: Halfspace CSG (Shapiro-Vossler, BHC) and the conversion of
// solids to BSH (BSH paper, Section 6). Options are parsed and results printed here; the algorithms are the
// library's (algorithms/csg/solid_tree.hpp, separators.hpp, separators3.hpp, convert.hpp; io/solid.hpp). describe
// and csg run on 2D and 3D scenes (3D: volume, io/svg3.hpp pictures, OpenSCAD with the tessellation explicit,
// separating planes; docs/csg3.md).
// Exit codes of describe and csg: 0 describable (csg: a verified tree was built, after separators when asked),
// 3 not describable (no tree), 2 bad input, 1 internal error (e.g. a tree that fails verification).
#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/algorithms/bsh/sample_scene.hpp>
#include <hsx/algorithms/bsh/samples.hpp>
#include <hsx/algorithms/csg/convert.hpp>
#include <hsx/algorithms/csg/separators3.hpp>
#include <hsx/algorithms/csg/solid_tree.hpp>
#include "cli/commands.hpp"
#include <hsx/io/csg_text.hpp>
#include <hsx/io/csgnet.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/json_values.hpp>
#include <hsx/io/openscad.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/io/solid.hpp>
#include <hsx/io/svg.hpp>
#include <hsx/io/svg3.hpp>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <new>
#include <sstream>

namespace hsx::cli {
namespace {

void add_solid_options(CLI::App* cmd, SolidSource& source) {
  cmd->add_option("--shape", source.shape_path, "the solid as an hsx-result/1 file computed from SCENE");
  cmd->add_option("--csg", source.csg, "the solid as a CSG expression over SCENE's halfspaces, e.g. \"(A & B) | ~C\", "
                                       "or a JSON file holding one");
  cmd->add_option("--mesh", source.mesh_path, "3D: the solid as the cells inside a closed mesh (.obj, .off, .ply) "
                                              "whose faces lie on SCENE's halfspaces");
}

nlohmann::json cell_point(const Complex& c, int k) {
  nlohmann::json p = nlohmann::json::array();
  for (const Rational& x : c.cells[k].witness.get()) p.push_back(exact_string(x));
  return p;
}

nlohmann::json mixed_terms_json(const Complex& c, const csg::Describability& d) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& t : d.mixed) {
    nlohmann::json signs = nlohmann::json::object();
    for (int i = 0; i < c.halfspace_count(); ++i) signs[c.halfspace_names[i]] = t.signs[i] ? "in" : "out";
    out.push_back({{"signs", signs},
                   {"inside_cells", t.inside_cells},
                   {"outside_cells", t.outside_cells},
                   {"witness",
                    {{"inside", {{"cell", t.inside_cells.front()}, {"point", cell_point(c, t.inside_cells.front())}}},
                     {"outside",
                      {{"cell", t.outside_cells.front()}, {"point", cell_point(c, t.outside_cells.front())}}}}}});
  }
  return out;
}

/// The picture of a solid: 2D, the arrangement with the solid filled and, with `marks`, the mixed terms' inside
/// cells in orange and outside cells in red (io/svg.hpp); 3D, the solid's boundary in four views (io/svg3.hpp) and,
/// with `marks`, the patches bounding the mixed terms' cells drawn over it, orange (inside) and red (outside).
std::string svg_of_solid(const LoadedInput& in, const std::vector<char>& cells, const std::string& title,
                         const csg::Describability* marks, bool labels) {
  if (in.scene3) {
    Svg3Options o;
    o.title = title;
    o.show_cell_ids = o.show_patch_ids = labels;
    o.cell_fill = cells;
    if (marks && !marks->mixed.empty()) {
      o.cell_marks.assign(cells.size(), 0);
      for (const auto& t : marks->mixed) {
        for (int k : t.inside_cells) o.cell_marks[static_cast<std::size_t>(k)] = 1;
        for (int k : t.outside_cells) o.cell_marks[static_cast<std::size_t>(k)] = 2;
      }
      o.mark_legend[0] = "inside cells of the " + std::to_string(marks->mixed.size()) + " mixed terms (in the solid)";
      o.mark_legend[1] = "outside cells of the mixed terms (not in the solid, same sign vectors)";
    }
    return arrangement_svg3(*in.scene3, *in.arranged3, o);
  }
  if (!in.scene) throw InputError("--svg: pictures need a scene (an hsx-complex/1 document carries no drawing)");
  SvgOptions o;
  o.title = title;
  o.show_cell_ids = o.show_patch_ids = labels;
  o.cell_fill = cells;
  if (marks) {
    o.cell_marks.assign(cells.size(), 0);
    for (const auto& t : marks->mixed) {
      for (int k : t.inside_cells) o.cell_marks[k] = 1;
      for (int k : t.outside_cells) o.cell_marks[k] = 2;
    }
  }
  return arrangement_svg(*in.scene, in.arranged->arrangement, in.complex(), o);
}

// ---------------------------------------------------------------------------------------------------------------
struct DescribeOptions {
  ArrangementLimits limits;  ///< --max-cells, --max-side-table
  std::string input, json_path, svg_path;
  bool labels = false;
  SolidSource solid;
};

int run_describe(const DescribeOptions& o) {
  OutputFiles out;  // checked before computing, written all or none at the end
  out.expect(o.json_path, "--json");
  out.expect(o.svg_path, "--svg");
  const LoadedInput in = load_input(o.input, o.limits);
  protect_inputs(out, in);
  const Solid solid = load_solid(in, o.solid, o.limits);
  const csg::Describability d = csg::describability(in.complex(), solid.cells);
  std::string svg_text;
  if (!o.svg_path.empty()) svg_text = svg_of_solid(in, solid.cells, o.input + " - describability", &d, o.labels);
  if (!o.json_path.empty())
    out.put(o.json_path, nlohmann::json{{"format", "hsx-describe/1"},
                                        {"describable", d.describable},
                                        {"terms", d.terms},
                                        {"mixed_terms", mixed_terms_json(in.complex(), d)}}
                                 .dump(2) + "\n");
  out.put(o.svg_path, svg_text);
  std::ostringstream report;
  if (o.json_path != "-") {
    report << (d.describable ? "describable" : "not describable") << " by the " << in.complex().halfspace_count()
           << " halfspaces (" << d.terms << " canonical intersection terms, " << d.mixed.size() << " mixed)\n";
    for (const auto& t : d.mixed) {
      report << "  mixed term";
      for (int i = 0; i < in.complex().halfspace_count(); ++i)
        report << " " << (t.signs[i] ? "" : "~") << in.complex().halfspace_names[i];
      report << ": inside cells";
      for (int k : t.inside_cells) report << " " << k;
      report << ", outside cells";
      for (int k : t.outside_cells) report << " " << k;
      report << "\n";
    }
  }
  out.print(report.str());
  out.commit();
  return d.describable ? 0 : 3;
}

// ---------------------------------------------------------------------------------------------------------------
struct CsgOptions {
  ArrangementLimits limits;  ///< --max-cells, --max-side-table
  std::string input, json_path, svg_path, openscad_path;
  SolidSource solid;
  bool separators = false;
  int max_separators = 8;
  int circle_segments = kCircleSegmentsNotGiven;  ///< --circle-segments (2D only; 96 when not given)
  bool labels = false;
  static constexpr int kCircleSegmentsNotGiven = std::numeric_limits<int>::min();
};

nlohmann::json stats_json(const csg::BhcResult& r) {
  return {{"depth", r.stats.depth},
          {"internal_nodes", r.stats.internal_nodes},
          {"leaves", r.stats.leaves},
          {"distinct_halfspaces", r.stats.distinct_halfspaces},
          {"duplicated_halfspaces", r.stats.duplicated_halfspaces},
          {"factored", r.factored},
          {"partitions", r.partitions}};
}

const char* to_string(csg::SeparatorStop stop) {
  switch (stop) {
    case csg::SeparatorStop::Describable: return "describable";
    case csg::SeparatorStop::MaxSeparators: return "max-separators";
    case csg::SeparatorStop::NoCandidateSeparates: return "no-candidate-separates";
  }
  return "?";
}

nlohmann::json separators_json(const Scene2& input, const csg::SeparatedSolid& s) {
  nlohmann::json added = nlohmann::json::array();
  const nlohmann::json halfspaces = write_scene2(s.scene).at("halfspaces");
  for (std::size_t k = input.halfspaces.size(); k < s.scene.halfspaces.size(); ++k) added.push_back(halfspaces.at(k));
  return added;
}

nlohmann::json plane_json(const csg::SeparatorPlane& p) {
  return {{"normal", {exact_string(p.normal.x), exact_string(p.normal.y), exact_string(p.normal.z)}},
          {"offset", exact_string(p.offset)},
          {"origin", csg::to_string(p.origin)}};
}

/// The planes added (as hsx-scene/1 halfspaces) and every round's trials: which candidates separated, which not.
void separators3_json(const Scene3& input, const csg::SeparatedSolid3& s, nlohmann::json& j) {
  nlohmann::json added = nlohmann::json::array();
  const nlohmann::json halfspaces = write_scene3(s.scene).at("halfspaces");
  for (std::size_t k = input.halfspaces.size(); k < s.scene.halfspaces.size(); ++k) added.push_back(halfspaces.at(k));
  nlohmann::json rounds = nlohmann::json::array();
  for (const csg::PlaneRound& r : s.rounds) {
    nlohmann::json trials = nlohmann::json::array();
    for (const csg::PlaneTrial& t : r.trials) {
      nlohmann::json row = plane_json(t.plane);
      row["predicted_terms"] = t.predicted_terms;
      row["predicted_cells"] = t.predicted_cells;
      row["arranged"] = t.arranged;
      if (t.arranged) {
        row["mixed_terms"] = t.mixed_terms;
        row["mixed_cells"] = t.mixed_cells;
        row["separated"] = t.separated;
        row["chosen"] = t.chosen;
      } else {
        row["rejection"] = t.rejection;
      }
      trials.push_back(row);
    }
    rounds.push_back({{"mixed_terms", r.mixed_terms},
                      {"mixed_cells", r.mixed_cells},
                      {"candidates", r.candidates},
                      {"predicted", r.predicted},
                      {"trials", trials}});
  }
  j["separators"] = added;
  j["separator_rounds"] = rounds;
  j["separator_stop"] = to_string(s.stop);
}

/// Why separators did not make the solid describable, for the summary line.
std::string separators_outcome(const csg::SeparatedSolid& s, int max_separators) {
  if (s.stop == csg::SeparatorStop::MaxSeparators)
    return "stopped at --max-separators " + std::to_string(max_separators);
  return "none of the " + std::to_string(s.candidates_tried) + " candidates tried separated the remaining mixed cells";
}

std::string separators3_outcome(const csg::SeparatedSolid3& s, int max_separators) {
  if (s.stop == csg::SeparatorStop::MaxSeparators)
    return "stopped at --max-separators " + std::to_string(max_separators);
  const csg::PlaneRound& last = s.rounds.back();
  return "none of the " + std::to_string(last.trials.size()) + " candidate planes arranged (of " +
         std::to_string(last.candidates) + ") separated the remaining mixed cells";
}

std::string plane_text(const csg::SeparatorPlane& p) {
  return "(" + exact_string(p.normal.x) + ", " + exact_string(p.normal.y) + ", " + exact_string(p.normal.z) +
         ") . x <= " + exact_string(p.offset) + " [" + csg::to_string(p.origin) + "]";
}

/// One line per round: the mixed terms before, the candidates, the trials that separated and did not, the chosen.
void print_plane_rounds(const csg::SeparatedSolid3& s, std::ostream& out) {
  for (std::size_t k = 0; k < s.rounds.size(); ++k) {
    const csg::PlaneRound& r = s.rounds[k];
    int separated = 0, rejected = 0;
    const csg::PlaneTrial* chosen = nullptr;
    for (const auto& t : r.trials) {
      separated += t.separated ? 1 : 0;
      rejected += t.arranged ? 0 : 1;
      if (t.chosen) chosen = &t;
    }
    out << "round " << k + 1 << ": " << r.mixed_terms << " mixed terms (" << r.mixed_cells << " cells), "
        << r.candidates << " candidate planes, " << r.predicted << " predicted to separate, "
        << r.trials.size() << " arranged: " << separated << " separated, "
        << r.trials.size() - static_cast<std::size_t>(separated) - static_cast<std::size_t>(rejected)
        << " did not, " << rejected << " rejected";
    if (chosen)
      out << "; added sep" << k << " " << plane_text(chosen->plane) << " -> " << chosen->mixed_terms
          << " mixed terms";
    out << "\n";
  }
  out << "added " << s.separators << " separating plane(s)\n";
}

void print_tree_summary(const csg::BhcResult& r, const Complex& complex, std::ostream& out) {
  out << "tree " << csg::to_text(*r.tree, complex.halfspace_names) << "\n"
      << "verified on every cell: " << (r.verified ? "yes" : "NO") << "\n"
      << "depth " << r.stats.depth << ", internal nodes " << r.stats.internal_nodes << ", leaves "
      << r.stats.leaves << ", duplicated halfspaces " << r.stats.duplicated_halfspaces << ", factored "
      << r.factored << ", partitions " << r.partitions << "\n";
}

int run_csg(const CsgOptions& o) {
  OutputFiles out;  // checked before computing, written all or none at the end
  out.expect(o.json_path, "--json");
  out.expect(o.svg_path, "--svg");
  out.expect(o.openscad_path, "--openscad");
  const LoadedInput in = load_input(o.input, o.limits);
  protect_inputs(out, in);
  if (o.max_separators < 0) throw InputError("--max-separators: must be >= 0");
  if (!in.scene && !in.scene3 && o.separators)
    throw InputError("--separators: needs a scene (separating half-planes and planes are geometry), not a complex");
  if (!in.scene && !in.scene3 && !o.openscad_path.empty())
    throw InputError("--openscad: needs a scene, not a complex");
  if (o.circle_segments != CsgOptions::kCircleSegmentsNotGiven && (in.scene3 || o.openscad_path.empty()))
    throw InputError(in.scene3 ? "--circle-segments: 2D only (a 3D OpenSCAD program uses the scene's own "
                                 "tessellation)"
                               : "--circle-segments: only with --openscad");
  const Solid solid = load_solid(in, o.solid, o.limits);
  const csg::SolidTreeOptions tree_options{o.separators, o.max_separators};
  const csg::SolidTree t = in.scene    ? csg::build_tree(*in.scene, *in.arranged, solid.cells, tree_options)
                           : in.scene3 ? csg::build_tree(*in.scene3, *in.arranged3, solid.cells, tree_options, o.limits)
                                       : csg::build_tree(in.complex(), solid.cells);
  const csg::BhcResult& r = t.bhc;
  const Complex& complex = t.separated    ? t.separated->arranged.complex
                           : t.separated3 ? t.separated3->arranged.complex
                                          : in.complex();
  const std::vector<char>& cells = t.separated ? t.separated->cells : t.separated3 ? t.separated3->cells : solid.cells;
  const Scene2* scene = t.separated ? &t.separated->scene : (in.scene ? &*in.scene : nullptr);
  const Scene3* scene3 = t.separated3 ? &t.separated3->scene : (in.scene3 ? &*in.scene3 : nullptr);
  nlohmann::json j{{"format", "hsx-csg/1"}, {"describable", r.describable}, {"verified", r.verified}};
  const Measure area = bsh::inside_measure(complex, cells);  // the solid's area (2D) or volume (3D)
  const char* const measure_name = complex.dimension == 3 ? "volume" : "area";
  j[measure_name] = measure_to_json(area);
  if (t.separated) {
    j["separators"] = separators_json(*in.scene, *t.separated);
    j["separator_candidates_tried"] = t.separated->candidates_tried;
    j["separator_stop"] = to_string(t.separated->stop);
  }
  if (t.separated3) separators3_json(*in.scene3, *t.separated3, j);
  if (r.describable) {
    j["tree"] = csg_to_json(*r.tree, complex.halfspace_names);
    j["text"] = csg::to_text(*r.tree, complex.halfspace_names);
    j["stats"] = stats_json(r);
  } else {
    j["mixed_terms"] = mixed_terms_json(complex, t.describability);
  }
  std::string svg_text, scad_text;
  if (!o.svg_path.empty()) svg_text = svg_of_solid(in, solid.cells, o.input + " - BHC", nullptr, o.labels);
  const bool write_scad = !o.openscad_path.empty() && t.has_verified_tree();
  if (write_scad) {
    if (scene3) {
      scad_text = to_openscad(*r.tree, *scene3);
    } else {
      OpenScadOptions so;
      if (o.circle_segments != CsgOptions::kCircleSegmentsNotGiven) so.circle_segments = o.circle_segments;
      scad_text = to_openscad(*r.tree, *scene, so);
    }
  }
  if (!o.json_path.empty()) out.put(o.json_path, j.dump(2) + "\n");
  out.put(o.svg_path, svg_text);
  if (write_scad) out.put(o.openscad_path, scad_text);
  if (!o.openscad_path.empty() && !write_scad)
    std::cerr << "hsx: --openscad: " << o.openscad_path << " not written: there is no verified tree\n";
  std::ostringstream report;
  if (o.json_path != "-") {
    if (t.separated) report << "added " << t.separated->separators << " separating half-plane(s)\n";
    if (t.separated3) print_plane_rounds(*t.separated3, report);
    if (r.describable) {
      print_tree_summary(r, complex, report);
    } else {
      report << "not describable: BHC stopped at a canonical intersection term holding inside cells";
      for (int k : r.witness.inside_cells) report << " " << k;
      report << " and outside cells";
      for (int k : r.witness.outside_cells) report << " " << k;
      if (t.separated)
        report << " (" << separators_outcome(*t.separated, o.max_separators) << ")";
      else if (t.separated3)
        report << " (" << separators3_outcome(*t.separated3, o.max_separators) << ")";
      else if (in.scene || in.scene3)
        report << " (try --separators)";
      report << "\n";
    }
    report << measure_name << " " << area.decimal_string(30);
    if (auto e = area.exact_string()) report << " = " << *e;
    report << "\n";
  }
  out.print(report.str());
  out.commit();
  if (t.has_verified_tree()) return 0;
  return r.describable ? 1 : 3;
}

// ---------------------------------------------------------------------------------------------------------------
std::optional<bsh::Method> search_method(const std::string& name) {
  if (name == "beam") return bsh::Method::Beam;
  if (name == "best-first") return bsh::Method::BestFirst;
  return std::nullopt;
}

struct ConvertOptions {
  ArrangementLimits limits;  ///< --max-cells, --max-side-table
  std::string input, csgnet, out_path, json_path, search = "beam";
  SolidSource solid;
};

int run_convert(const ConvertOptions& o) {
  const auto search = search_method(o.search);
  if (!search) throw InputError("--search: beam or best-first");
  if (o.out_path.empty()) throw InputError("--out: required (the BSH scene to write)");
  OutputFiles out;  // checked before computing, written all or none at the end
  out.expect(o.out_path, "--out");
  out.expect(o.json_path, "--json");
  csg::ConversionReport report;
  std::optional<csg::ConversionReport3> report3;
  if (!o.csgnet.empty()) {
    if (!o.input.empty() || !o.solid.csg.empty() || !o.solid.shape_path.empty() || !o.solid.mesh_path.empty())
      throw InputError("--csgnet: give the program alone (it defines the scene and the solid)");
    const CsgnetProgram program = read_csgnet(o.csgnet, "--csgnet");
    report = csg::convert_to_bsh(program.scene, *program.expression, *search);
  } else {
    if (o.input.empty()) throw InputError("give a SCENE with --csg/--shape/--mesh, or --csgnet PROGRAM");
    const LoadedInput in = load_input(o.input, o.limits);
    protect_inputs(out, in);
  protect_inputs(out, in);
    if (!in.scene && !in.scene3) throw InputError(o.input + ": convert needs a scene, not a complex");
    const std::vector<char> cells = load_solid(in, o.solid, o.limits).cells;
    if (in.scene3)
      report3 = csg::convert_to_bsh(*in.scene3, *in.arranged3, cells, *search, o.limits);
    else
      report = csg::convert_to_bsh(*in.scene, *in.arranged, cells, *search);
  }
  const bsh::SampleGenResult& samples = report3 ? report3->samples : report.samples;
  if (report3 ? !report3->ok() : !report.ok()) {
    std::cerr << "hsx: conversion failed: " << (report3 ? report3->failure : report.failure) << "\n";
    return 3;
  }
  const std::vector<std::string>& flipped = report3 ? report3->flipped : report.flipped;
  out.put(o.out_path, (report3 ? write_scene3(report3->scene) : write_scene2(report.scene)).dump(2) + "\n");
  nlohmann::json summary{{"samples", samples.sample_patches.size()},
                         {"lower_bound", samples.initial},
                         {"upper_bound", samples.upper_bound},
                         {"rounds", samples.rounds},
                         {"round_trip", report3 ? report3->round_trip : report.round_trip},
                         {"complemented", flipped}};
  if (report3) {
    // The solid on the complex the samples are on (the oriented scene's): its size and its cells.
    const Complex& c = report3->oriented.complex;
    std::vector<int> inside;
    for (std::size_t k = 0; k < report3->oriented_solid.size(); ++k)
      if (report3->oriented_solid[k]) inside.push_back(static_cast<int>(k));
    summary["dimension"] = 3;
    summary["cells"] = c.cells.size();
    summary["patches"] = c.patches.size();
    summary["inside_cells"] = inside;
    summary["sample_patches"] = samples.sample_patches;
    summary["volume"] = measure_to_json(bsh::inside_measure(c, report3->oriented_solid));
  }
  out.put(o.json_path, summary.dump(2) + "\n");
  std::ostringstream printed;
  printed << "wrote " << o.out_path << ": " << samples.sample_patches.size() << " samples (lower bound "
          << samples.initial << ", upper bound " << samples.upper_bound << ", " << samples.rounds
          << " extraction rounds); hsx extract gives the solid back: yes\n";
  if (!flipped.empty()) {
    printed << "complemented (the solid runs along them reversed):";
    for (const std::string& n : flipped) printed << " " << n;
    printed << "\n";
  }
  out.print(printed.str());
  out.commit();
  return 0;
}

// ---------------------------------------------------------------------------------------------------------------
struct SamplesOptions {
  ArrangementLimits limits;  ///< --max-cells, --max-side-table
  std::string input, out_path, json_path, search = "beam";
  SolidSource solid{"", "", "", "--target", "--csg", "--mesh"};
  int exhaustive_patches = 14;
};

int run_samples(const SamplesOptions& o) {
  const auto search = search_method(o.search);
  if (!search) throw InputError("--search: beam or best-first");
  OutputFiles out;  // checked before computing, written all or none at the end
  out.expect(o.json_path, "--json");
  out.expect(o.out_path, "--out");
  const LoadedInput in = load_input(o.input, o.limits);
  protect_inputs(out, in);
  const Solid solid = load_solid(in, o.solid, o.limits);
  const bsh::Problem problem(in.complex());
  std::string why;
  if (!bsh::is_orientation_preserving(problem, solid.cells, &why))
    throw InputError("--target: the target boundary is not orientation-preserving: " + why +
                     " (hsx convert complements such halfspaces)");
  bsh::SampleGenOptions options;
  options.search = *search;
  const bsh::SampleGenResult r = bsh::generate_samples(in.complex(), solid.cells, options);
  const int minimum = bsh::minimum_samples(in.complex(), solid.cells, o.exhaustive_patches);
  nlohmann::json j{{"format", "hsx-samples/1"},
                   {"search", o.search},
                   {"samples", r.sample_patches.size()},
                   {"sample_patches", r.sample_patches},
                   {"lower_bound", r.initial},
                   {"upper_bound", r.upper_bound},
                   {"rounds", r.rounds},
                   {"reproduced", r.reproduced}};
  if (minimum >= 0) j["minimum"] = minimum; else j["minimum"] = nullptr;
  if (!r.reproduced) j["failure"] = r.failure;
  std::string scene_text;
  std::optional<bool> round_trip;  // --out: extracting the written scene gives the target back
  if (!o.out_path.empty()) {
    if (!in.scene && !in.scene3) throw InputError("--out: needs a scene input");
    const std::string description = "samples from GENERATE-SAMPLES (" + o.search + ")";
    if (in.scene) {
      const Scene2 written = bsh::scene_with_samples(*in.scene, *in.arranged, r.sample_patches, description);
      if (r.reproduced && in.scene->samples.empty()) round_trip = csg::extracts_back(written, solid.cells, *search);
      scene_text = write_scene2(written).dump(2) + "\n";
    } else {
      Scene3 written = bsh::scene_with_samples(*in.scene3, *in.arranged3, r.sample_patches, description);
      written.domain_given = true;  // written out: otherwise chosen again from the new samples
      if (r.reproduced) round_trip = csg::extracts_back(written, *in.arranged3, solid.cells, *search, o.limits);
      scene_text = write_scene3(written).dump(2) + "\n";
    }
    if (round_trip) j["round_trip"] = *round_trip;
  }
  out.put(o.json_path, j.dump(2) + "\n");
  out.put(o.out_path, scene_text);
  std::ostringstream report;
  report << r.sample_patches.size() << " samples (lower bound " << r.initial << ", upper bound " << r.upper_bound
         << ", " << r.rounds << " rounds, reproduced: " << (r.reproduced ? "yes" : "NO") << ")";
  if (minimum >= 0) report << "; true minimum " << minimum << " (greedy excess " << r.sample_patches.size() - minimum << ")";
  report << "\n";
  if (round_trip)
    report << "wrote " << o.out_path << "; hsx extract gives the target back: " << (*round_trip ? "yes" : "NO")
           << "\n";
  out.print(report.str());
  out.commit();
  return r.reproduced && round_trip.value_or(true) ? 0 : 3;
}

// ---------------------------------------------------------------------------------------------------------------
struct CorpusOptions {
  std::string kind, file, json_path, search = "beam";
  long first = 1;  // first line to run (1-based)
  long limit = 0;
};

int run_corpus(const CorpusOptions& o) {
  if (o.kind != "csgnet") throw InputError("corpus: the only corpus kind is csgnet");
  const auto search = search_method(o.search);
  if (!search) throw InputError("--search: beam or best-first");
  if (o.first < 1) throw InputError("--from: lines are numbered from 1");
  if (o.limit < 0) throw InputError("--limit: must be >= 0 (0: no limit)");
  OutputFiles out;  // checked before the run, written at the end
  out.expect(o.json_path, "--json");
  std::istringstream in(read_file(o.file));  // a directory, FIFO or device is refused, never read
  struct Row {
    long line;
    std::string program, failure;
    std::size_t samples = 0;
    int lower = 0, upper = 0, leaves = 0, duplicated = 0;
    bool sufficient_set = false;
    double seconds = 0;
  };
  std::vector<Row> rows;
  std::string line;
  long number = 0;
  long ok = 0, not_describable = 0, bhc_failed = 0, round_trip_failed = 0, errors = 0, malformed = 0;
  long sufficient_sets = 0;
  long total_samples = 0, total_lower = 0, total_upper = 0;
  double total_seconds = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || number < o.first) continue;
    if (o.limit > 0 && number >= o.first + o.limit) break;  // the range is of lines, malformed ones included
    Row row{number, line, ""};
    const auto start = std::chrono::steady_clock::now();
    std::optional<CsgnetProgram> parsed;
    try {
      parsed = read_csgnet(line, "line " + std::to_string(number));
    } catch (const InputError& e) {
      // Malformed programs (the corpus has truncated ones) are reported and skipped, not counted as failures.
      ++malformed;
      std::cout << "skipped malformed " << e.what() << "\n";
      continue;
    }
    try {
      const csg::ProgramCheck c = csg::check_program(parsed->scene, *parsed->expression, *search);
      row.leaves = c.leaves;
      row.duplicated = c.duplicated;
      row.samples = c.samples;
      row.lower = c.lower_bound;
      row.upper = c.upper_bound;
      row.sufficient_set = c.sufficient_set;
      row.failure = c.failure;
      if (c.sufficient_set) {
        ++sufficient_sets;
        std::cout << "line " << row.line << ": GENERATE-SAMPLES missed the target (search incomplete at "
                  << "non-generic junctions); used one sample per boundary patch\n";
      }
      switch (c.outcome) {
        case csg::ProgramOutcome::Ok:
          ++ok;
          total_samples += static_cast<long>(row.samples);
          total_lower += row.lower;
          total_upper += row.upper;
          break;
        case csg::ProgramOutcome::NotDescribable: ++not_describable; break;
        case csg::ProgramOutcome::BhcFailed: ++bhc_failed; break;
        case csg::ProgramOutcome::ConversionFailed: ++round_trip_failed; break;
      }
    } catch (const std::bad_alloc&) {
      throw;  // out of memory ends the run (exit 2): it says nothing about the program
    } catch (const std::exception& e) {
      ++errors;
      row.failure = std::string("error: ") + e.what();
    }
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    total_seconds += row.seconds;
    if (!row.failure.empty()) std::cout << "line " << row.line << ": " << row.failure << "\n  " << row.program << "\n";
    rows.push_back(row);
  }
  std::cout << rows.size() << " programs (" << malformed << " malformed lines skipped): " << ok << " ok, " << not_describable << " not describable, " << bhc_failed
            << " BHC failures, " << round_trip_failed << " round-trip failures, " << errors << " errors\n"
            << "samples " << total_samples << " (lower bound " << total_lower << ", upper bound " << total_upper
            << "), " << sufficient_sets << " programs needed one sample per boundary patch, " << total_seconds
            << " s\n";
  if (!o.json_path.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const Row& r : rows)
      list.push_back({{"line", r.line}, {"program", r.program}, {"ok", r.failure.empty()}, {"failure", r.failure},
                      {"samples", r.samples}, {"lower_bound", r.lower}, {"upper_bound", r.upper},
                      {"leaves", r.leaves}, {"duplicated_halfspaces", r.duplicated},
                      {"sufficient_set", r.sufficient_set}, {"seconds", r.seconds}});
    out.put(o.json_path, nlohmann::json{{"format", "hsx-corpus/1"}, {"programs", list}}.dump(1) + "\n");
  }
  if (rows.empty()) throw InputError("corpus: " + o.file + " has no program in the lines asked for");
  out.print(std::string(ok == static_cast<long>(rows.size()) ? "all" : "NOT all") + " programs passed\n");
  out.commit();
  return ok == static_cast<long>(rows.size()) ? 0 : 3;
}

}  // namespace

void add_csg_commands(CLI::App& app) {
  {
    auto o = std::make_shared<DescribeOptions>();
    CLI::App* cmd = app.add_subcommand("describe", "Is the solid describable by the scene's halfspaces "
                                                   "(Shapiro-Vossler)? Mixed canonical terms with witness cells");
    cmd->add_option("SCENE", o->input, "hsx-scene/1 or hsx-complex/1 file")->required();
    add_solid_options(cmd, o->solid);
    cmd->add_option("--json", o->json_path, "write describable and mixed_terms as JSON")
        ->check(output_path());
    cmd->add_option("--svg", o->svg_path, "draw the solid; mixed terms' cells in orange (inside) and red (outside); 3D: four views of the "
                    "solid's boundary, with the patches bounding those cells")
        ->check(output_path());
    cmd->add_flag("--labels", o->labels, "label cells (c<k>) and patches (p<k>) in the picture, as in the JSON");
    cmd->footer("Exit codes: 0 describable; 3 not describable (--json and --svg are still written); 2 bad input; "
                "1 internal error.");
    add_arrangement_limits(cmd, o->limits);
    run_with_status(cmd, o, &run_describe);
  }
  {
    auto o = std::make_shared<CsgOptions>();
    CLI::App* cmd = app.add_subcommand("csg", "Build a halfspace CSG tree of the solid with BHC, verified on every cell");
    cmd->add_option("SCENE", o->input, "hsx-scene/1 or hsx-complex/1 file")->required();
    add_solid_options(cmd, o->solid);
    cmd->add_flag("--separators", o->separators, "when not describable, add separating half-planes (2D) or planes (3D; "
                  "algorithms/csg/separators3.hpp) and retry");
    cmd->add_option("--max-separators", o->max_separators, "at most this many separators (default 8)");
    cmd->add_option("--json", o->json_path, "write tree, verified, stats, area (2D) or volume (3D) as JSON")
        ->check(output_path());
    cmd->add_option("--svg", o->svg_path, "draw the solid (3D: its boundary in four views)")
        ->check(output_path());
    cmd->add_flag("--labels", o->labels, "label cells (c<k>) and patches (p<k>) in the picture, as in the JSON");
    cmd->add_option("--openscad", o->openscad_path, "write the tree as OpenSCAD (a drawing, not exact; 3D: every "
                                                    "halfspace as the polyhedron hsx arranges, io/openscad.hpp); not "
                                                    "written when there is no verified tree")
        ->check(output_path());
    cmd->add_option("--circle-segments", o->circle_segments, "2D OpenSCAD $fn for circles (default 96; only with --openscad)");
    cmd->footer("Exit codes: 0 a verified tree was built (after separators, when --separators was given and needed); "
                "3 the solid is not describable by the halfspaces (separators included), so there is no tree: "
                "--json and --svg are still written, --openscad is not (a message says so); 2 bad input only "
                "(e.g. --separators or --openscad with a complex instead of a scene); 1 internal error (e.g. a tree "
                "that fails verification).");
    add_arrangement_limits(cmd, o->limits);
    run_with_status(cmd, o, &run_csg);
  }
  {
    auto o = std::make_shared<ConvertOptions>();
    CLI::App* cmd = app.add_subcommand("convert", "Convert a CSG solid to a BSH scene (samples from GENERATE-SAMPLES) "
                                                  "and check that extracting it gives the solid back");
    cmd->add_option("SCENE", o->input, "hsx-scene/1 file, 2D or 3D, or the BSH authors' config.json (with --csg or --shape)");
    add_solid_options(cmd, o->solid);
    cmd->add_option("--csgnet", o->csgnet, "a CSGNet postfix program, e.g. \"c(32,32,16)s(32,40,12)-\"");
    cmd->add_option("--out", o->out_path, "the BSH scene to write")->required()
        ->check(output_path());
    cmd->add_option("--search", o->search, "beam (K = 1, default) or best-first");
    cmd->add_option("--json", o->json_path, "write sample counts and bounds as JSON")
        ->check(output_path());
    add_arrangement_limits(cmd, o->limits);
    run_with_status(cmd, o, &run_convert);
  }
  {
    auto o = std::make_shared<SamplesOptions>();
    CLI::App* cmd = app.add_subcommand("samples", "GENERATE-SAMPLES (BSH Fig. 12): samples that reproduce a target "
                                                  "shape; counts against the lower and upper bounds");
    cmd->add_option("SCENE", o->input, "hsx-scene/1 file (2D or 3D) or the BSH authors' config.json")->required();
    cmd->add_option("--target", o->solid.shape_path, "the target shape as an hsx-result/1 file");
    cmd->add_option("--csg", o->solid.csg, "or the target as a CSG expression");
    cmd->add_option("--mesh", o->solid.mesh_path, "or (3D) the target as the cells inside a closed mesh (.obj, .off, "
                                                  ".ply) whose faces lie on the scene's halfspaces");
    cmd->add_option("--search", o->search, "beam (K = 1, default) or best-first");
    cmd->add_option("--exhaustive-patches", o->exhaustive_patches,
                    "compute the true minimum when the boundary has at most this many patches (default 14)")
        ->check(non_negative());
    cmd->add_option("--out", o->out_path,
                    "write the scene with the generated samples (2D: inside a patch edge; 3D: at the centroid of the "
                    "patch's largest triangle, the domain written out) and check that extracting it gives the target "
                    "back (round_trip in --json; exit 3 when not)")
        ->check(output_path());
    cmd->add_option("--json", o->json_path, "write counts as JSON")
        ->check(output_path());
    add_arrangement_limits(cmd, o->limits);
    run_with_status(cmd, o, &run_samples);
  }
  {
    auto o = std::make_shared<CorpusOptions>();
    CLI::App* cmd = app.add_subcommand("corpus", "Run a corpus end to end: hsx corpus csgnet FILE (describability, "
                                                 "BHC, conversion to BSH and back)");
    cmd->add_option("KIND", o->kind, "csgnet")->required();
    cmd->add_option("FILE", o->file, "the corpus file")->required();
    cmd->add_option("--from", o->first, "start at this line (1-based, default 1)");
    cmd->add_option("--limit", o->limit, "run at most N programs");
    cmd->add_option("--search", o->search, "beam (default) or best-first for the conversion");
    cmd->add_option("--json", o->json_path, "write one row per program as JSON")
        ->check(output_path());
    run_with_status(cmd, o, &run_corpus);
  }
}

}  // namespace hsx::cli
