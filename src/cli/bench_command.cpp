// hsx bench [DIR...]: every method on every scene, timed in one run, reported as ratios to the graph cut; with
// --meshes, NH-Rep's stages on meshes, as ratios to reading the mesh.
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/complex/boundary_from_mesh.hpp>
#include <hsx/geometry/mesh3.hpp>
#include "cli/commands.hpp"
#include <hsx/io/input.hpp>

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

namespace hsx::cli {
namespace {

struct BenchOptions {
  std::vector<std::string> dirs{"data/scenes", "data/figures"};
  std::vector<std::string> meshes;  ///< NH-Rep mode: .obj files, each with a .fea beside it
  long brute_force_limit = 200000;
  double time_limit = 60;
};

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void run_bench(const BenchOptions& o) {
  std::vector<std::string> files;
  for (const auto& dir : o.dirs) {
    if (!std::filesystem::is_directory(dir)) throw InputError("bench: \"" + dir + "\" is not a directory");
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == ".json" && entry.path().filename() != "expected.json")
        files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  const bsh::Method methods[] = {bsh::Method::GraphCut, bsh::Method::Beam, bsh::Method::BestFirst,
                                 bsh::Method::BruteForce};
  std::cout << std::left << std::setw(34) << "scene" << std::right << std::setw(7) << "cells" << std::setw(8)
            << "patches" << std::setw(11) << "arrange s" << std::setw(11) << "graphcut s";
  for (const char* m : {"beam", "best-first", "brute-force"}) std::cout << std::setw(13) << m;
  std::cout << std::setw(11) << "bf states" << std::setw(8) << "beam" << "\n";
  double totals[4] = {0, 0, 0, 0};
  int beam_optimal = 0, compared = 0;
  for (const auto& file : files) {
    const auto t0 = std::chrono::steady_clock::now();
    LoadedInput in;
    try {
      in = load_input(file);
    } catch (const InputError& e) {
      std::cout << std::left << std::setw(34) << std::filesystem::path(file).filename().string()
                << " skipped: " << e.what() << "\n";
      continue;
    }
    const double arrange_seconds = seconds_since(t0);
    const bsh::Problem problem(in.complex());
    double t[4] = {0, 0, 0, 0};
    std::optional<bsh::ExtractResult> results[4];
    for (int k = 0; k < 4; ++k) {
      bsh::ExtractOptions options;
      options.method = methods[k];
      options.time_limit = o.time_limit;
      options.brute_force_limit = o.brute_force_limit;
      const auto start = std::chrono::steady_clock::now();
      try {
        results[k] = bsh::extract(problem, options);
      } catch (const std::runtime_error&) {
        t[k] = -1;  // the oracle refused: too many labellings
        continue;
      }
      t[k] = seconds_since(start);
      totals[k] += t[k];
    }
    std::cout << std::left << std::setw(34) << std::filesystem::path(file).filename().string() << std::right
              << std::setw(7) << problem.cell_count() << std::setw(8) << in.complex().patches.size() << std::fixed
              << std::setprecision(4) << std::setw(11) << arrange_seconds << std::setw(11) << t[0];
    for (int k = 1; k < 4; ++k) {
      if (t[k] < 0) {
        std::cout << std::setw(13) << "too large";
        continue;
      }
      std::ostringstream cell;
      cell << std::fixed << std::setprecision(1) << (t[0] > 0 ? t[k] / t[0] : 0.0) << "x";
      std::cout << std::setw(13) << cell.str();
    }
    std::string beam_verdict = "-";
    if (results[1] && results[2] && results[2]->optimal) {
      ++compared;
      const bool same = bsh::compare(results[1]->energy, results[2]->energy) != Order::Greater;
      beam_optimal += same;
      beam_verdict = same ? "opt" : "subopt";
    }
    std::cout << std::setw(11) << (results[2] ? results[2]->stats.states_expanded : -1) << std::setw(8)
              << beam_verdict << "\n";
  }
  std::cout << std::defaultfloat << "\n" << files.size() << " scenes; total seconds: graphcut " << totals[0]
            << ", beam " << totals[1] << ", best-first " << totals[2] << ", brute-force " << totals[3]
            << "\nbeam K=1 optimal on " << beam_optimal << " of " << compared
            << " scenes (method columns are times relative to the graph cut of the same scene)\n";
}

/// NH-Rep on meshes: each stage timed in one run, as a ratio to reading and validating the mesh.
void run_nhrep_bench(const BenchOptions& o) {
  std::cout << std::left << std::setw(34) << "mesh" << std::right << std::setw(9) << "faces" << std::setw(9)
            << "patches" << std::setw(11) << "read s" << std::setw(13) << "classify" << std::setw(13)
            << "patch graph" << std::setw(13) << "algorithm 1" << std::setw(13) << "check" << std::setw(8)
            << "decomp" << "\n";
  for (const std::string& obj : o.meshes) {
    std::filesystem::path fea = obj;
    fea.replace_extension(".fea");
    auto t = std::chrono::steady_clock::now();
    const Mesh3 mesh = read_mesh3_file(obj);
    const FeatureEdgeList features = read_fea_file(fea.string());
    const double read = seconds_since(t);
    t = std::chrono::steady_clock::now();
    BoundarySurface surface = boundary_from_mesh(mesh, features);
    const double classify = seconds_since(t);
    t = std::chrono::steady_clock::now();
    nhrep::PatchGraph graph = nhrep::build_patch_graph(std::move(surface));
    const double patch_graph = seconds_since(t);
    const std::size_t patches = graph.patches.size();
    t = std::chrono::steady_clock::now();
    const nhrep::BuildResult result = nhrep::build_tree(std::move(graph));
    const double algorithm1 = seconds_since(t);
    t = std::chrono::steady_clock::now();
    const bool ok = nhrep::check_tree(result).empty();
    const double check = seconds_since(t);
    auto ratio = [&](double x) {
      std::ostringstream cell;
      cell << std::fixed << std::setprecision(3) << (read > 0 ? x / read : 0.0) << "x";
      return cell.str();
    };
    std::cout << std::left << std::setw(34) << std::filesystem::path(obj).filename().string() << std::right
              << std::setw(9) << mesh.faces.size() << std::setw(9) << patches << std::fixed << std::setprecision(4)
              << std::setw(11) << read << std::setw(13) << ratio(classify) << std::setw(13) << ratio(patch_graph)
              << std::setw(13) << ratio(algorithm1) << std::setw(13) << ratio(check) << std::setw(8)
              << result.decompositions.size() << (ok ? "" : "  CHECK FAILED") << "\n";
  }
  std::cout << std::defaultfloat << "(stage columns are times relative to reading and validating the same mesh)\n";
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand("bench", "Time every BSH method on every scene of the given folders, in one run");
  cmd->add_option("DIRS", o->dirs, "folders of scenes (default data/scenes data/figures)");
  cmd->add_option("--brute-force-limit", o->brute_force_limit, "skip the oracle above this many labellings");
  cmd->add_option("--time-limit", o->time_limit, "seconds per search before it stops (default 60)");
  cmd->add_option("--meshes", o->meshes,
                  "time NH-Rep's stages on these .obj files (each with its .fea) instead of the BSH methods");
  cmd->callback([o] {
    if (o->meshes.empty())
      run_bench(*o);
    else
      run_nhrep_bench(*o);
  });
}

}  // namespace hsx::cli
