// hsx describe / csg / convert / samples / corpus: Halfspace CSG (Shapiro-Vossler, BHC) and the conversion of
// solids to BSH (BSH paper, Section 6).
#include <hsx/algorithms/bsh/samples.hpp>
#include <hsx/algorithms/csg/bhc.hpp>
#include "cli/commands.hpp"
#include "cli/solid.hpp"
#include "geometry/planar_points.hpp"
#include <hsx/io/csg_text.hpp>
#include <hsx/io/csgnet.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/json_values.hpp>
#include <hsx/io/openscad.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/io/svg.hpp>

#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace hsx::cli {
namespace {

void add_solid_options(CLI::App* cmd, SolidSource& source) {
  cmd->add_option("--shape", source.shape_path, "the solid as an hsx-result/1 file computed from SCENE");
  cmd->add_option("--csg", source.csg, "the solid as a CSG expression over SCENE's halfspaces, e.g. \"(A & B) | ~C\", "
                                       "or a JSON file holding one");
}

nlohmann::json cell_point(const Complex& c, int k) {
  nlohmann::json p = nlohmann::json::array();
  for (const Rational& x : c.cells[k].witness) p.push_back(exact_string(x));
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

std::string svg_of_solid(const LoadedInput& in, const std::vector<char>& cells, const std::string& title,
                         const csg::Describability* marks) {
  if (!in.scene) throw InputError("--svg: pictures need a scene (an hsx-complex/1 document carries no drawing)");
  SvgOptions o;
  o.title = title;
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
  std::string input, json_path, svg_path;
  SolidSource solid;
};

int run_describe(const DescribeOptions& o) {
  const LoadedInput in = load_input(o.input);
  const Solid solid = load_solid(in, o.solid);
  const csg::Describability d = csg::describability(in.complex(), solid.cells);
  std::string svg_text;
  if (!o.svg_path.empty()) svg_text = svg_of_solid(in, solid.cells, o.input + " - describability", &d);
  if (!o.json_path.empty())
    write_file_atomically(o.json_path, nlohmann::json{{"format", "hsx-describe/1"},
                                                      {"describable", d.describable},
                                                      {"terms", d.terms},
                                                      {"mixed_terms", mixed_terms_json(in.complex(), d)}}
                                               .dump(2) + "\n");
  if (!o.svg_path.empty()) write_file_atomically(o.svg_path, svg_text);
  if (o.json_path != "-") {
    std::cout << (d.describable ? "describable" : "not describable") << " by the " << in.complex().halfspace_count()
              << " halfspaces (" << d.terms << " canonical intersection terms, " << d.mixed.size() << " mixed)\n";
    for (const auto& t : d.mixed) {
      std::cout << "  mixed term";
      for (int i = 0; i < in.complex().halfspace_count(); ++i)
        std::cout << " " << (t.signs[i] ? "" : "~") << in.complex().halfspace_names[i];
      std::cout << ": inside cells";
      for (int k : t.inside_cells) std::cout << " " << k;
      std::cout << ", outside cells";
      for (int k : t.outside_cells) std::cout << " " << k;
      std::cout << "\n";
    }
  }
  return 0;
}

// ---------------------------------------------------------------------------------------------------------------
struct CsgOptions {
  std::string input, json_path, svg_path, openscad_path;
  SolidSource solid;
  bool separators = false;
  int max_separators = 8;
  int circle_segments = 96;
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

int run_csg(const CsgOptions& o) {
  const LoadedInput in = load_input(o.input);
  const Solid solid = load_solid(in, o.solid);
  const Complex* complex = &in.complex();
  const Scene2* scene = in.scene ? &*in.scene : nullptr;
  std::vector<char> cells = solid.cells;
  csg::BhcOptions options;
  if (scene) options.planar = planar_halfspaces(*scene);
  csg::BhcResult r = csg::bhc(*complex, cells, options);
  std::optional<SeparatedSolid> separated;
  if (!r.describable && o.separators) {
    if (!in.scene) throw InputError("--separators: needs a scene (separating half-planes are geometry)");
    separated = add_separators(*in.scene, *in.arranged, solid.cells, o.max_separators);
    complex = &separated->arranged.complex;
    scene = &separated->scene;
    cells = separated->cells;
    options.planar = planar_halfspaces(*scene);
    r = csg::bhc(*complex, cells, options);
  }
  nlohmann::json j{{"format", "hsx-csg/1"}, {"describable", r.describable}, {"verified", r.verified}};
  const Measure area = bsh::inside_measure(*complex, cells);
  j["area"] = measure_to_json(area);
  if (separated) {
    nlohmann::json added = nlohmann::json::array();
    for (std::size_t k = in.scene->halfspaces.size(); k < scene->halfspaces.size(); ++k)
      added.push_back(write_scene2(*scene).at("halfspaces").at(k));
    j["separators"] = added;
  }
  if (r.describable) {
    j["tree"] = csg_to_json(*r.tree, complex->halfspace_names);
    j["text"] = csg::to_text(*r.tree, complex->halfspace_names);
    j["stats"] = stats_json(r);
  } else {
    const csg::Describability d = csg::describability(*complex, cells);
    j["mixed_terms"] = mixed_terms_json(*complex, d);
  }
  std::string svg_text, scad_text;
  if (!o.svg_path.empty()) svg_text = svg_of_solid(in, solid.cells, o.input + " - BHC", nullptr);
  if (!o.openscad_path.empty()) {
    if (!scene) throw InputError("--openscad: needs a scene");
    if (!r.describable) throw InputError("--openscad: the solid is not describable, there is no tree to export");
    OpenScadOptions so;
    so.circle_segments = o.circle_segments;
    scad_text = to_openscad(*r.tree, *scene, so);
  }
  if (!o.json_path.empty()) write_file_atomically(o.json_path, j.dump(2) + "\n");
  if (!o.svg_path.empty()) write_file_atomically(o.svg_path, svg_text);
  if (!o.openscad_path.empty()) write_file_atomically(o.openscad_path, scad_text);
  if (o.json_path != "-") {
    if (separated) std::cout << "added " << separated->separators << " separating half-plane(s)\n";
    if (r.describable) {
      std::cout << "tree " << csg::to_text(*r.tree, complex->halfspace_names) << "\n"
                << "verified on every cell: " << (r.verified ? "yes" : "NO") << "\n"
                << "depth " << r.stats.depth << ", internal nodes " << r.stats.internal_nodes << ", leaves "
                << r.stats.leaves << ", duplicated halfspaces " << r.stats.duplicated_halfspaces << ", factored "
                << r.factored << ", partitions " << r.partitions << "\n";
    } else {
      std::cout << "not describable: BHC stopped at a canonical intersection term holding inside cells";
      for (int k : r.witness.inside_cells) std::cout << " " << k;
      std::cout << " and outside cells";
      for (int k : r.witness.outside_cells) std::cout << " " << k;
      std::cout << (o.separators ? " (separators did not help)" : " (try --separators)") << "\n";
    }
    std::cout << "area " << area.decimal_string(30);
    if (auto e = area.exact_string()) std::cout << " = " << *e;
    std::cout << "\n";
  }
  return r.describable && r.verified ? 0 : (r.describable ? 1 : 0);
}

// ---------------------------------------------------------------------------------------------------------------
/// A BSH scene whose samples sit on the given patches: the scene's halfspaces and domain, one exact `at` sample
/// per patch, on the patch's middle arrangement edge (geometry/planar_points.hpp says where exactly).
Scene2 scene_with_samples(const Scene2& scene, const Arranged2& arranged, const std::vector<int>& patches,
                          const std::string& description) {
  Scene2 out = scene;
  out.description = description;
  out.samples.clear();
  for (int p : patches) {
    const Patch& patch = arranged.complex.patches.at(p);
    const int edge = patch.pieces.at(patch.pieces.size() / 2);
    Sample2 s;
    s.halfspace = patch.halfspace;
    s.given = rational_point_inside_edge(arranged.arrangement.edges().at(edge), arranged.arrangement.vertices());
    s.location = OneRootPoint(s.given);
    out.samples.push_back(s);
  }
  return out;
}

struct ConversionReport {
  Scene2 scene;                   // the BSH scene written
  bsh::SampleGenResult samples;
  std::vector<std::string> flipped;  // halfspaces complemented because the solid uses their boundary reversed
  bool round_trip = false;        // extracting the written scene (re-read from its JSON text) gives the solid
  std::string failure;
};

/// A BSH boundary must run along every halfspace with that halfspace's orientation (Def. 3.1). A CSG solid may
/// use a boundary reversed (A - B runs along B with the solid outside B): those halfspaces are complemented in the
/// BSH scene. One boundary used both ways would need a halfspace and its coincident complement, which hsx's
/// coincidence convention keeps off every boundary (algorithms/bsh/problem.hpp): reported as a failure.
std::optional<Scene2> orient_for_bsh(const Scene2& scene, const Complex& complex, const std::vector<char>& solid,
                                     std::vector<std::string>& flipped, std::string& failure) {
  std::vector<char> normal(scene.halfspaces.size(), 0), reversed(scene.halfspaces.size(), 0);
  std::vector<const std::vector<int>*> reversed_only;  // supports on b that no halfspace runs along correctly
  for (const auto& group : complex.supports) {
    const Patch& first = complex.patches[group.front()];
    if (solid[first.inside_cell] == solid[first.outside_cell]) continue;
    bool agrees = false;
    for (int p : group) {
      const Patch& patch = complex.patches[p];
      if (solid[patch.inside_cell]) {
        agrees = true;
        normal[patch.halfspace] = 1;
      }
    }
    if (!agrees) reversed_only.push_back(&group);
  }
  // Each such support needs one of its (coincident) halfspaces complemented: prefer one used nowhere else; when
  // every one of them also runs along the solid correctly somewhere, add a complemented copy instead.
  std::vector<char> copy(scene.halfspaces.size(), 0);
  for (const auto* group : reversed_only) {
    int pick = complex.patches[group->front()].halfspace;
    for (int p : *group) {
      const int h = complex.patches[p].halfspace;
      if (reversed[h] || copy[h]) { pick = h; break; }
      if (normal[pick] && !normal[h]) pick = h;
    }
    (normal[pick] ? copy : reversed)[pick] = 1;
  }
  Scene2 out = scene;
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
    if (reversed[i]) {
      out.halfspaces[i].complement = !out.halfspaces[i].complement;
      flipped.push_back(scene.halfspaces[i].name);
    }
    if (copy[i]) {
      Halfspace2 h = scene.halfspaces[i];
      h.complement = !h.complement;
      h.name += "~";
      while (out.find_halfspace(h.name) >= 0) h.name += "~";
      flipped.push_back(h.name + " (a complemented copy of " + scene.halfspaces[i].name + ")");
      out.halfspaces.push_back(h);
    }
  }
  (void)failure;
  return out;
}

/// Section 6.2: the solid's boundary patches (one sample each reproduces it, Prop. 4.1), reduced by
/// GENERATE-SAMPLES; then the written scene is read back and extracted with `search` to check the round trip.
ConversionReport convert_to_bsh(const Scene2& scene, const Arranged2& arranged, const std::vector<char>& solid,
                                bsh::Method search) {
  ConversionReport report;
  for (std::size_t k = 0; k < solid.size(); ++k)
    if (solid[k] && arranged.complex.cells[k].outer)
      throw InputError("the solid reaches the domain boundary (cell " + std::to_string(k) +
                       " touches it); enlarge the domain");
  const std::optional<Scene2> oriented = orient_for_bsh(scene, arranged.complex, solid, report.flipped, report.failure);
  if (!oriented) return report;
  Scene2 bare = *oriented;
  bare.samples.clear();
  const Arranged2 oriented_arranged = report.flipped.empty() && scene.samples.empty() ? arranged : arrange(bare);
  // Cell order may differ after adding copies: carry the solid over by point location.
  const std::vector<char> oriented_solid =
      report.flipped.empty() && scene.samples.empty()
          ? solid
          : carry_solid_over(arranged.arrangement, solid, oriented_arranged.arrangement);
  bsh::SampleGenOptions options;
  options.search = search;
  report.samples = bsh::generate_samples(oriented_arranged.complex, oriented_solid, options);
  if (!report.samples.reproduced) {
    report.failure = report.samples.failure;
    return report;
  }
  std::string description = "BSH conversion: " + std::to_string(report.samples.sample_patches.size()) +
                            " samples from GENERATE-SAMPLES";
  if (!report.flipped.empty()) {
    description += "; complemented (the solid uses them reversed):";
    for (const auto& n : report.flipped) description += " " + n;
  }
  report.scene = scene_with_samples(bare, oriented_arranged, report.samples.sample_patches, description);
  // Round trip through the file format: write, read back, arrange, extract.
  const Scene2 back = read_scene_text(write_scene2(report.scene).dump());
  const Arranged2 again = arrange(back);
  const bsh::Problem problem(again.complex);
  bsh::ExtractOptions extract_options;
  extract_options.method = search;
  extract_options.enumerate_ties = false;
  const bsh::ExtractResult r = bsh::extract(problem, extract_options);
  report.round_trip = r.labelling == oriented_solid;
  if (!report.round_trip) report.failure = "extracting the written scene does not give the solid back";
  return report;
}

std::optional<bsh::Method> search_method(const std::string& name) {
  if (name == "beam") return bsh::Method::Beam;
  if (name == "best-first") return bsh::Method::BestFirst;
  return std::nullopt;
}

struct ConvertOptions {
  std::string input, csgnet, out_path, json_path, search = "beam";
  SolidSource solid;
};

int run_convert(const ConvertOptions& o) {
  const auto search = search_method(o.search);
  if (!search) throw InputError("--search: beam or best-first");
  if (o.out_path.empty()) throw InputError("--out: required (the BSH scene to write)");
  Scene2 scene;
  Arranged2 arranged;
  std::vector<char> solid;
  if (!o.csgnet.empty()) {
    if (!o.input.empty() || !o.solid.csg.empty() || !o.solid.shape_path.empty())
      throw InputError("--csgnet: give the program alone (it defines the scene and the solid)");
    CsgnetProgram program = read_csgnet(o.csgnet, "--csgnet");
    scene = program.scene;
    arranged = arrange(scene);
    solid = csg::evaluate(*program.expression, arranged.complex);
  } else {
    if (o.input.empty()) throw InputError("give a SCENE with --csg/--shape, or --csgnet PROGRAM");
    const LoadedInput in = load_input(o.input);
    if (!in.scene) throw InputError(o.input + ": convert needs a scene, not a complex");
    scene = *in.scene;
    arranged = *in.arranged;
    solid = load_solid(in, o.solid).cells;
  }
  const ConversionReport report = convert_to_bsh(scene, arranged, solid, *search);
  if (!report.samples.reproduced || !report.round_trip) {
    std::cerr << "hsx: conversion failed: " << report.failure << "\n";
    return 3;
  }
  write_file_atomically(o.out_path, write_scene2(report.scene).dump(2) + "\n");
  const nlohmann::json summary{{"samples", report.samples.sample_patches.size()},
                               {"lower_bound", report.samples.initial},
                               {"upper_bound", report.samples.upper_bound},
                               {"rounds", report.samples.rounds},
                               {"round_trip", report.round_trip}};
  if (!o.json_path.empty()) write_file_atomically(o.json_path, summary.dump(2) + "\n");
  std::cout << "wrote " << o.out_path << ": " << report.samples.sample_patches.size() << " samples (lower bound "
            << report.samples.initial << ", upper bound " << report.samples.upper_bound << ", "
            << report.samples.rounds << " extraction rounds); hsx extract gives the solid back: yes\n";
  return 0;
}

// ---------------------------------------------------------------------------------------------------------------
struct SamplesOptions {
  std::string input, target, out_path, json_path, search = "beam";
  std::string csg;
  int exhaustive_patches = 14;
};

int run_samples(const SamplesOptions& o) {
  const auto search = search_method(o.search);
  if (!search) throw InputError("--search: beam or best-first");
  const LoadedInput in = load_input(o.input);
  const Solid solid = load_solid(in, SolidSource{o.target, o.csg});
  const bsh::Problem problem(in.complex());
  std::string why;
  if (!bsh::is_orientation_preserving(problem, solid.cells, &why))
    throw InputError("--target: the target boundary is not orientation-preserving: " + why);
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
  if (!o.out_path.empty()) {
    if (!in.scene) throw InputError("--out: needs a scene input");
    scene_text = write_scene2(scene_with_samples(*in.scene, *in.arranged, r.sample_patches,
                                                 "samples from GENERATE-SAMPLES (" + o.search + ")"))
                     .dump(2) + "\n";
  }
  if (!o.json_path.empty()) write_file_atomically(o.json_path, j.dump(2) + "\n");
  if (!o.out_path.empty()) write_file_atomically(o.out_path, scene_text);
  std::cout << r.sample_patches.size() << " samples (lower bound " << r.initial << ", upper bound " << r.upper_bound
            << ", " << r.rounds << " rounds, reproduced: " << (r.reproduced ? "yes" : "NO") << ")";
  if (minimum >= 0) std::cout << "; true minimum " << minimum << " (greedy excess " << r.sample_patches.size() - minimum << ")";
  std::cout << "\n";
  return r.reproduced ? 0 : 3;
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
  std::ifstream in(o.file);
  if (!in) throw InputError("corpus: cannot read \"" + o.file + "\"");
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
      CsgnetProgram& program = *parsed;
      const Arranged2 arranged = arrange(program.scene);
      const std::vector<char> solid = csg::evaluate(*program.expression, arranged.complex);
      const csg::Describability d = csg::describability(arranged.complex, solid);
      csg::BhcOptions bhc_options;
      bhc_options.planar = planar_halfspaces(program.scene);
      const csg::BhcResult tree = csg::bhc(arranged.complex, solid, bhc_options);
      row.leaves = tree.stats.leaves;
      row.duplicated = tree.stats.duplicated_halfspaces;
      if (!d.describable) {
        ++not_describable;
        row.failure = "not describable";
      } else if (!tree.describable || !tree.verified) {
        ++bhc_failed;
        row.failure = "BHC tree missing or wrong";
      } else if (std::none_of(solid.begin(), solid.end(), [](char c) { return c != 0; })) {
        ++ok;  // an empty solid converts to the empty sample set trivially
      } else {
        const ConversionReport report = convert_to_bsh(program.scene, arranged, solid, *search);
        if (!report.samples.reproduced) {
          ++round_trip_failed;
          row.failure = report.failure;
          row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          total_seconds += row.seconds;
          std::cout << "line " << row.line << ": " << row.failure << "\n  " << row.program << "\n";
          rows.push_back(row);
          continue;
        }
        row.samples = report.samples.sample_patches.size();
        row.sufficient_set = report.samples.used_sufficient_set;
        if (row.sufficient_set) {
          ++sufficient_sets;
          std::cout << "line " << row.line << ": GENERATE-SAMPLES missed the target (search incomplete at "
                    << "non-generic junctions); used one sample per boundary patch\n";
        }
        row.lower = report.samples.initial;
        row.upper = report.samples.upper_bound;
        if (!report.round_trip) {
          ++round_trip_failed;
          row.failure = report.failure;
        } else {
          ++ok;
          total_samples += static_cast<long>(row.samples);
          total_lower += row.lower;
          total_upper += row.upper;
        }
      }
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
    write_file_atomically(o.json_path, nlohmann::json{{"format", "hsx-corpus/1"}, {"programs", list}}.dump(1) + "\n");
  }
  std::cout << (ok == static_cast<long>(rows.size()) ? "all" : "NOT all") << " programs passed\n";
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
    cmd->add_option("--json", o->json_path, "write describable and mixed_terms as JSON");
    cmd->add_option("--svg", o->svg_path, "draw the solid; mixed terms' cells in orange (inside) and red (outside)");
    run_with_status(cmd, o, &run_describe);
  }
  {
    auto o = std::make_shared<CsgOptions>();
    CLI::App* cmd = app.add_subcommand("csg", "Build a halfspace CSG tree of the solid with BHC, verified on every cell");
    cmd->add_option("SCENE", o->input, "hsx-scene/1 or hsx-complex/1 file")->required();
    add_solid_options(cmd, o->solid);
    cmd->add_flag("--separators", o->separators, "when not describable, add separating half-planes (2D) and retry");
    cmd->add_option("--max-separators", o->max_separators, "at most this many separators (default 8)");
    cmd->add_option("--json", o->json_path, "write tree, verified, stats, area as JSON");
    cmd->add_option("--svg", o->svg_path, "draw the solid");
    cmd->add_option("--openscad", o->openscad_path, "write the tree as OpenSCAD (a drawing, not exact)");
    cmd->add_option("--circle-segments", o->circle_segments, "OpenSCAD $fn for circles (default 96)");
    run_with_status(cmd, o, &run_csg);
  }
  {
    auto o = std::make_shared<ConvertOptions>();
    CLI::App* cmd = app.add_subcommand("convert", "Convert a CSG solid to a BSH scene (samples from GENERATE-SAMPLES) "
                                                  "and check that extracting it gives the solid back");
    cmd->add_option("SCENE", o->input, "hsx-scene/1 file (with --csg or --shape)");
    add_solid_options(cmd, o->solid);
    cmd->add_option("--csgnet", o->csgnet, "a CSGNet postfix program, e.g. \"c(32,32,16)s(32,40,12)-\"");
    cmd->add_option("--out", o->out_path, "the BSH scene to write")->required();
    cmd->add_option("--search", o->search, "beam (K = 1, default) or best-first");
    cmd->add_option("--json", o->json_path, "write sample counts and bounds as JSON");
    run_with_status(cmd, o, &run_convert);
  }
  {
    auto o = std::make_shared<SamplesOptions>();
    CLI::App* cmd = app.add_subcommand("samples", "GENERATE-SAMPLES (BSH Fig. 12): samples that reproduce a target "
                                                  "shape; counts against the lower and upper bounds");
    cmd->add_option("SCENE", o->input, "hsx-scene/1 file")->required();
    cmd->add_option("--target", o->target, "the target shape as an hsx-result/1 file");
    cmd->add_option("--csg", o->csg, "or the target as a CSG expression");
    cmd->add_option("--search", o->search, "beam (K = 1, default) or best-first");
    cmd->add_option("--exhaustive-patches", o->exhaustive_patches,
                    "compute the true minimum when the boundary has at most this many patches (default 14)");
    cmd->add_option("--out", o->out_path, "write the scene with the generated samples");
    cmd->add_option("--json", o->json_path, "write counts as JSON");
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
    cmd->add_option("--json", o->json_path, "write one row per program as JSON");
    run_with_status(cmd, o, &run_corpus);
  }
}

}  // namespace hsx::cli
