// `hsx reference FOLDER`: the BSH authors' own result (reference-result.grid) against hsx's exact arrangement of
// the same config.json (io/bsh_reference.hpp does the work; this file parses, calls and prints).
#include "commands.hpp"

#include <hsx/io/bsh_reference.hpp>
#include <hsx/io/exact_json.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/input.hpp>
#include <hsx/io/result_json.hpp>

#include <filesystem>
#include <iostream>

namespace hsx::cli {

namespace {

struct ReferenceOptions {
  std::string folder;
  std::string shape_path;
  std::string json_path;
  ArrangementLimits limits;
};

int run_reference(const ReferenceOptions& o) {
  const std::filesystem::path folder(o.folder);
  if (!std::filesystem::is_directory(folder)) throw InputError(o.folder + ": not a folder");
  for (const char* file : {"reference-result.grid", "config.json"})
    refuse_output_over_input("--json", o.json_path, "FOLDER's", (folder / file).string());
  OutputFiles out;
  out.expect(o.json_path, "--json");
  const BshReference reference = read_bsh_reference_file((folder / "reference-result.grid").string());
  const LoadedInput in = load_input((folder / "config.json").string(), o.limits);
  protect_inputs(out, in);
  std::vector<char> ours;
  if (!o.shape_path.empty()) {
    const nlohmann::json document = read_exact_json_file(o.shape_path);
    try {
      ours = read_result_labelling(document, in.complex());
    } catch (const InputError& e) {
      throw InputError(o.shape_path + ": " + e.what());
    }
  }
  const std::string name = folder.filename().empty() ? folder.parent_path().filename().string()
                                                     : folder.filename().string();
  const BshReferenceComparison comparison = compare_bsh_reference(reference, *in.arranged3, ours);
  out.print(bsh_reference_table(comparison, name));
  if (!o.json_path.empty()) out.put(o.json_path, bsh_reference_to_json(comparison, name).dump(1) + "\n");
  out.commit();
  return 0;
}

}  // namespace

void add_reference_command(CLI::App& app) {
  auto o = std::make_shared<ReferenceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "reference", "Compare the BSH authors' reference-result.grid with hsx's exact arrangement of the same "
                   "config.json: patches, cells, their blocks mapped onto our cells, areas, their graph cut's defect");
  cmd->add_option("FOLDER", o->folder, "an example folder of the authors' code (config.json, reference-result.grid)")
      ->required();
  cmd->add_option("--shape", o->shape_path,
                  "our shape (hsx-result/1 of FOLDER/config.json) to compare with their final labelling");
  cmd->add_option("--json", o->json_path, "write the comparison as JSON (hsx-bsh-reference/1)")->check(output_path());
  add_arrangement_limits(cmd, o->limits);
  run_with_status(cmd, o, &run_reference);
}

}  // namespace hsx::cli
