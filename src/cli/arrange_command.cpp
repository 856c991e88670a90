// hsx arrange SCENE [--svg FILE [--labels]] [--json FILE]: the exact arrangement of a scene and its complex.
#include "cli/commands.hpp"
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/complex_json.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/io/svg.hpp>

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
  bool labels = false;
  bool quiet = false;
  ArrangementLimits limits;
};

std::string summary_text(const Scene2& scene, const Arranged2& arranged) {
  const Complex& c = arranged.complex;
  const Arrangement2& arr = arranged.arrangement;
  std::ostringstream out;
  out << "domain " << "[" << exact_string(scene.domain.min.x) << ", " << exact_string(scene.domain.min.y)
      << "] .. [" << exact_string(scene.domain.max.x) << ", " << exact_string(scene.domain.max.y) << "]"
      << (scene.domain_given ? "" : " (chosen by hsx)") << "\n";
  out << "vertices " << arr.vertices().size() << "  edges " << arr.edges().size() << "  cells " << c.cells.size()
      << "  outer_cells " << c.outer_cell_count() << "  patches " << c.patches.size() << "  junctions "
      << c.junctions.size() << "  samples " << c.samples.size() << "\n";
  out << "patch  halfspace  inside/outside cell  samples  length\n";
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    const Patch& patch = c.patches[p];
    out << std::left << std::setw(7) << p << std::setw(11) << c.halfspace_names[patch.halfspace]
        << std::setw(21) << (std::to_string(patch.inside_cell) + "/" + std::to_string(patch.outside_cell))
        << std::setw(9) << patch.samples.size() << patch.measure.decimal_string(30);
    if (auto exact = patch.measure.exact_string()) out << "  = " << *exact;
    if (c.supports[patch.support].size() > 1) out << "  (coincident with another boundary)";
    out << "\n";
  }
  return out.str();
}

void run_arrange(const ArrangeOptions& options) {
  OutputFiles out;  // checked before computing, written all or none at the end
  out.expect(options.json_path, "--json");
  out.expect(options.svg_path, "--svg");
  const Scene2 scene = read_scene_file(options.scene_path);
  const Arranged2 arranged = arrange(scene, options.limits);
  std::string json_text, svg_text;
  if (!options.json_path.empty())
    json_text = complex_json_text(arranged.complex, &arranged.arrangement, &scene.domain);
  if (!options.svg_path.empty()) {
    SvgOptions svg_options;
    svg_options.title = options.scene_path;
    svg_options.show_cell_ids = svg_options.show_patch_ids = options.labels;
    svg_text = arrangement_svg(scene, arranged.arrangement, arranged.complex, svg_options);
  }
  out.put(options.json_path, std::move(json_text));
  out.put(options.svg_path, std::move(svg_text));
  out.commit();
  if (!options.quiet && options.json_path != "-") std::cout << summary_text(scene, arranged);
}

}  // namespace

void add_arrange_command(CLI::App& app) {
  auto options = std::make_shared<ArrangeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "arrange", "Build the exact arrangement of a 2D scene and its complex; print counts and patches");
  cmd->add_option("SCENE", options->scene_path, "hsx-scene/1 JSON file")->required();
  cmd->add_option("--svg", options->svg_path, "write a picture: cells, patches per halfspace, samples")
      ->check(output_path());
  cmd->add_flag("--labels", options->labels, "label cells (c<k>) and patches (p<k>) in the picture, as in the text");
  cmd->add_option("--json", options->json_path, "write the complex as hsx-complex/1 JSON ('-' for stdout)")
      ->check(output_path());
  cmd->add_flag("-q,--quiet", options->quiet, "do not print the summary");
  add_arrangement_limits(cmd, options->limits);
  cmd->callback([options] { run_arrange(*options); });
}

}  // namespace hsx::cli
