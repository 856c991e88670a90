// hsx arrange INPUT [--svg FILE [--labels]] [--json FILE] [--ply FILE] [--obj FILE] [--export FORMAT FILE]: the exact arrangement of a 2D
// or 3D scene and its complex, or an hsx-complex/1 document read and checked.
#include "cli/commands.hpp"
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/complex_json.hpp>
#include <hsx/io/files.hpp>
#include <hsx/hsx.hpp>
#include <hsx/io/input.hpp>
#include <hsx/io/labelling.hpp>
#include <hsx/io/mesh_export.hpp>
#include <hsx/io/svg.hpp>
#include <hsx/io/svg3.hpp>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace hsx::cli {
namespace {

struct ArrangeOptions {
  std::string scene_path;
  std::string svg_path;
  std::string json_path;
  std::string ply_path, obj_path;  ///< 3D only
  std::vector<std::string> export_spec;  ///< --export FORMAT FILE (empty: none)
  std::int64_t weight_scale = kDefaultGraphcutWeightScale;
  bool labels = false;
  bool quiet = false;
  ArrangementLimits limits;
};

std::string point_text(const std::vector<Rational>& coordinates) {
  std::string text = "[";
  for (std::size_t k = 0; k < coordinates.size(); ++k) text += (k ? ", " : "") + exact_string(coordinates[k]);
  return text + "]";
}

/// "domain [..] .. [..]" and, when known, whether hsx chose it.
std::string domain_line(const LoadedInput& in) {
  std::vector<Rational> lo, hi;
  bool chosen = false;
  if (in.scene) {
    lo = {in.scene->domain.min.x, in.scene->domain.min.y};
    hi = {in.scene->domain.max.x, in.scene->domain.max.y};
    chosen = !in.scene->domain_given;
  } else if (in.scene3) {
    const Box3& d = in.scene3->domain;
    lo = {d.min.x, d.min.y, d.min.z};
    hi = {d.max.x, d.max.y, d.max.z};
    chosen = !in.scene3->domain_given;
  } else if (in.document->domain) {
    lo = {in.document->domain->min.x, in.document->domain->min.y};
    hi = {in.document->domain->max.x, in.document->domain->max.y};
  } else if (in.document->domain3) {
    const Box3& d = *in.document->domain3;
    lo = {d.min.x, d.min.y, d.min.z};
    hi = {d.max.x, d.max.y, d.max.z};
  } else {
    return "";
  }
  return "domain " + point_text(lo) + " .. " + point_text(hi) + (chosen ? " (chosen by hsx)" : "") + "\n";
}

/// The counts line: the geometry's (vertices, edges, and in 3D faces: refined triangles) when there is one.
std::string counts_line(const LoadedInput& in) {
  const Complex& c = in.complex();
  std::ostringstream out;
  if (in.arranged) {
    out << "vertices " << in.arranged->arrangement.vertices().size() << "  edges "
        << in.arranged->arrangement.edges().size() << "  ";
  } else if (in.arranged3) {
    const Arrangement3& a = in.arranged3->arrangement;
    out << "vertices " << a.vertices().size() << "  edges " << a.edges().size() << "  faces " << a.triangles().size()
        << "  ";
  } else if (in.document->has_geometry && c.dimension == 2) {
    out << "vertices " << in.document->vertices.size() << "  edges " << in.document->edges.size() << "  ";
  } else if (in.document->has_geometry) {
    out << "vertices " << in.document->vertices3.size() << "  faces " << in.document->triangles3.size() << "  ";
  }
  out << "cells " << c.cells.size() << "  outer_cells " << c.outer_cell_count() << "  patches " << c.patches.size()
      << "  junctions " << c.junctions.size() << "  samples " << c.samples.size() << "\n";
  return out.str();
}

/// 3D `near` samples: where each landed and how far it moved (the exact squared distance, and a decimal).
std::string snapped_samples_text(const Scene3& scene, const Complex& c) {
  std::ostringstream out;
  for (std::size_t k = 0; k < scene.samples.size(); ++k) {
    const Sample3& s = scene.samples[k];
    if (!s.snapped) continue;
    out << "sample " << k << " (near, on " << scene.halfspaces[s.halfspace].name << "): moved to "
        << point_text({s.location.x, s.location.y, s.location.z}) << ", distance "
        << Measure::sqrt_of(s.distance2).decimal_string(12) << " (squared " << exact_string(s.distance2)
        << "), on patch " << c.samples[k].patch << "\n";
  }
  return out.str();
}

std::string summary_text(const LoadedInput& in) {
  const Complex& c = in.complex();
  std::ostringstream out;
  out << domain_line(in) << counts_line(in);
  out << "patch  halfspace  inside/outside cell  samples  " << (c.dimension == 3 ? "area" : "length") << "\n";
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    const Patch& patch = c.patches[p];
    out << std::left << std::setw(7) << p << std::setw(11) << c.halfspace_names[patch.halfspace]
        << std::setw(21) << (std::to_string(patch.inside_cell) + "/" + std::to_string(patch.outside_cell))
        << std::setw(9) << patch.samples.size() << patch.measure.get().decimal_string(30);
    if (auto exact = patch.measure.get().exact_string()) out << "  = " << *exact;
    if (c.supports[patch.support].size() > 1) out << "  (coincident with another boundary)";
    out << "\n";
  }
  if (in.scene3) {
    out << snapped_samples_text(*in.scene3, c);
    for (const std::string& note : in.scene3->notes) out << "note: " << note << "\n";
  }
  return out.str();
}

/// The picture: the 2D drawing, or the 3D orthographic views.
std::string picture(const LoadedInput& in, const ArrangeOptions& options) {
  if (in.scene) {
    SvgOptions svg_options;
    svg_options.title = options.scene_path;
    svg_options.show_cell_ids = svg_options.show_patch_ids = options.labels;
    return arrangement_svg(*in.scene, in.arranged->arrangement, in.complex(), svg_options);
  }
  if (in.scene3) {
    Svg3Options svg_options;
    svg_options.title = options.scene_path;
    svg_options.show_cell_ids = svg_options.show_patch_ids = options.labels;
    return arrangement_svg3(*in.scene3, *in.arranged3, svg_options);
  }
  throw InputError("--svg: pictures need a scene (an hsx-complex/1 document carries no drawing)");
}

void run_arrange(const ArrangeOptions& options) {
  OutputFiles out;  // checked before computing, written all or none at the end
  const std::string export_path = options.export_spec.empty() ? "" : options.export_spec.at(1);
  if (!options.export_spec.empty()) {
    if (options.export_spec.at(0) != kBshGraphcutFormat)
      throw InputError("--export: unknown format \"" + options.export_spec.at(0) + "\" (known: " +
                       kBshGraphcutFormat + ")");
    if (export_path.empty()) throw InputError("--export: an empty path");
    if (options.weight_scale < 1) throw InputError("--weight-scale: must be at least 1");
  }
  out.expect(export_path, "--export");
  if (options.obj_path == "-") throw InputError("--obj: needs a file (its .mtl is written beside it), not '-'");
  const std::string mtl_path = options.obj_path.empty() ? "" : mtl_path_for(options.obj_path);
  out.expect(options.json_path, "--json");
  out.expect(options.svg_path, "--svg");
  out.expect(options.ply_path, "--ply");
  out.expect(options.obj_path, "--obj");
  out.expect(mtl_path, "--obj (its .mtl)");
  const LoadedInput in = load_input(options.scene_path, options.limits);
  protect_inputs(out, in);
  if (!in.scene3 && !(options.ply_path.empty() && options.obj_path.empty()))
    throw InputError(std::string(options.ply_path.empty() ? "--obj" : "--ply") + ": needs a 3D scene");
  std::string json_text, svg_text, ply_text;
  ObjText obj;
  if (!options.json_path.empty()) json_text = complex_json_text(in);
  std::string export_text;
  if (!export_path.empty()) export_text = bsh_graphcut_to_json(in.complex(), options.weight_scale).dump(1) + "\n";
  if (!options.svg_path.empty()) svg_text = picture(in, options);
  if (!options.ply_path.empty()) ply_text = arrangement_ply(*in.scene3, *in.arranged3);
  if (!options.obj_path.empty())
    obj = arrangement_obj(*in.scene3, *in.arranged3, std::filesystem::path(mtl_path).filename().string());
  out.put(options.json_path, std::move(json_text));
  out.put(export_path, std::move(export_text));
  out.put(options.svg_path, std::move(svg_text));
  out.put(options.ply_path, std::move(ply_text));
  out.put(options.obj_path, std::move(obj.obj));
  out.put(mtl_path, std::move(obj.mtl));
  if (!options.quiet && options.json_path != "-" && export_path != "-") out.print(summary_text(in));
  out.commit();
}

}  // namespace

void add_arrange_command(CLI::App& app) {
  auto options = std::make_shared<ArrangeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "arrange",
      "Build the exact arrangement of a 2D or 3D scene and its complex, or read and check an hsx-complex/1 "
      "document; print counts and patches");
  cmd->add_option("INPUT", options->scene_path,
                  "hsx-scene/1 JSON file (2D or 3D), a BSH config.json, or an hsx-complex/1 document")
      ->required();
  cmd->add_option("--svg", options->svg_path,
                  "write a picture: 2D cells, patches per halfspace, samples; 3D four orthographic views of the "
                  "boundary triangles, shaded by halfspace and lit by their normal")
      ->check(output_path());
  cmd->add_option("--ply", options->ply_path,
                  "3D: write the refined surfaces as ASCII PLY with per-face patch, halfspace, cells and colour")
      ->check(output_path());
  cmd->add_option("--obj", options->obj_path,
                  "3D: write the refined surfaces as OBJ, one group per patch, with a .mtl of halfspace colours "
                  "beside it")
      ->check(output_path());
  cmd->add_flag("--labels", options->labels, "label cells (c<k>) and patches (p<k>) in the picture, as in the text");
  cmd->add_option("--json", options->json_path, "write the complex as hsx-complex/1 JSON ('-' for stdout)")
      ->check(output_path());
  cmd->add_option("--export", options->export_spec,
                  "FORMAT FILE: write the complex for another program ('-' for stdout). bsh-graphcut: the BSH "
                  "authors' graph_cut input {num_cells, patches: [{adj_cell_0 (outside), adj_cell_1 (inside), "
                  "weight, implicit_id, num_samples, adj_patches}]}, weights the patch measures times "
                  "--weight-scale rounded to integers, plus outer_cells and exact measures (io/labelling.hpp); "
                  "grade its answer with hsx grade INPUT LABELS")
      ->expected(2)
      ->type_name("FORMAT FILE")
      ->check(output_path());
  cmd->add_option("--weight-scale", options->weight_scale,
                  "bsh-graphcut: integer weight = round(measure x this), at least 1 (default 1000000)");
  cmd->add_flag("-q,--quiet", options->quiet, "do not print the summary");
  add_arrangement_limits(cmd, options->limits);
  cmd->callback([options] { run_arrange(*options); });
}

}  // namespace hsx::cli
