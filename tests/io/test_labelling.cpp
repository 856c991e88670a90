// Labellings from elsewhere (io/labelling.hpp): the four formats read back what was written, errors name the source
// and the field, and the BSH graph-cut export keeps the authors' conventions (adj_cell_0 outside, adj_cell_1
// inside, integer weights, samples and neighbours per patch).
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/io/external_solver.hpp>
#include <hsx/io/input.hpp>
#include <hsx/io/labelling.hpp>
#include <hsx/io/result_json.hpp>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <fstream>
#include <signal.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace hsx;

namespace {

std::string scene_path(const std::string& name) { return std::string(HSX_SOURCE_DIR) + "/data/scenes/" + name; }

std::string plain(const std::vector<char>& cells, const char* separator) {
  std::string s;
  for (std::size_t k = 0; k < cells.size(); ++k) s += (k ? separator : "") + std::string(cells[k] ? "1" : "0");
  return s;
}

std::string message_of(const std::string& text, const Complex& complex) {
  try {
    read_labelling_text(text, "theirs.json", complex);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("labelling: every format reads back the labelling written", "[labelling]") {
  const LoadedInput in = load_input(scene_path("star.json"));
  const Complex& c = in.complex();
  rc::prop("four formats, one labelling", [&] {
    std::vector<char> cells(c.cells.size());
    for (auto& v : cells) v = *rc::gen::element<char>(0, 1);
    const auto plain_read = read_labelling_text(plain(cells, " ") + "\n", "", c);
    RC_ASSERT(plain_read.cells == cells);
    RC_ASSERT(plain_read.format == LabellingFormat::PlainList);
    RC_ASSERT(read_labelling_text(plain(cells, ",\n"), "", c).cells == cells);
    nlohmann::json bools = nlohmann::json::array(), ints = nlohmann::json::array();
    for (char v : cells) {
      bools.push_back(v != 0);
      ints.push_back(static_cast<int>(v));
    }
    const auto labels = read_labelling_text(nlohmann::json{{"labels", bools}}.dump(), "", c);
    RC_ASSERT(labels.cells == cells);
    RC_ASSERT(labels.format == LabellingFormat::GraphcutLabels);
    const auto list = read_labelling_text(ints.dump(), "", c);
    RC_ASSERT(list.cells == cells);
    RC_ASSERT(list.format == LabellingFormat::JsonList);
  });
  // An hsx-result/1 of this input reads as its inside cells.
  const bsh::Problem problem(c);
  bsh::ExtractOptions options;
  options.method = bsh::Method::BestFirst;
  const auto result = bsh::extract(problem, options);
  const auto read = read_labelling_text(result_to_json(problem, result, in.pieces(), false).dump(), "", c);
  CHECK(read.format == LabellingFormat::Result);
  CHECK(read.cells == result.labelling);
}

TEST_CASE("labelling: bad labellings are InputErrors naming the source and the place", "[labelling]") {
  const LoadedInput in = load_input(scene_path("star.json"));
  const Complex& c = in.complex();
  CHECK_THAT(message_of("0 1", c), Catch::Contains("theirs.json: 2 labels for " + std::to_string(c.cells.size())));
  CHECK_THAT(message_of("0\n1\nx", c), Catch::Contains("theirs.json: line 3: label 2 is \"x\", not 0 or 1"));
  CHECK_THAT(message_of("", c), Catch::Contains("theirs.json: empty"));
  nlohmann::json bad = nlohmann::json::array();
  for (std::size_t k = 0; k < c.cells.size(); ++k) bad.push_back(k == 1 ? nlohmann::json(2) : nlohmann::json(false));
  CHECK_THAT(message_of(nlohmann::json{{"labels", bad}}.dump(), c),
             Catch::Contains("theirs.json: labels[1]: expected true, false, 0 or 1, got 2"));
  CHECK_THAT(message_of("{\"labels\": [true]}", c), Catch::Contains("1 labels for"));
  CHECK_THAT(message_of("{\"cells\": []}", c), Catch::Contains("expected an hsx-result/1 document"));
  CHECK_THAT(message_of("[1, ", c), Catch::Contains("theirs.json: line 1"));
  // A result of another scene names its complex_id.
  const LoadedInput other = load_input(scene_path("lens.json"));
  const bsh::Problem problem(other.complex());
  const auto result = bsh::extract(problem, {});
  CHECK_THAT(message_of(result_to_json(problem, result, other.pieces(), false).dump(), c),
             Catch::Contains("complex_id"));
}

TEST_CASE("labelling: the BSH graph-cut export keeps the authors' conventions", "[labelling]") {
  for (const char* name : {"star.json", "coincident.json", "tangencies.json"}) {
    const LoadedInput in = load_input(scene_path(name));
    const Complex& c = in.complex();
    const nlohmann::json g = bsh_graphcut_to_json(c, 1000);
    REQUIRE(g.at("num_cells") == c.cells.size());
    REQUIRE(g.at("patches").size() == c.patches.size());
    CHECK(g.at("complex_id") == complex_identity(c));
    const auto neighbours = c.patch_neighbours();
    for (std::size_t p = 0; p < c.patches.size(); ++p) {
      const auto& e = g.at("patches")[p];
      CHECK(e.at("adj_cell_0") == c.patches[p].outside_cell);
      CHECK(e.at("adj_cell_1") == c.patches[p].inside_cell);
      CHECK(e.at("implicit_id") == c.patches[p].halfspace);
      CHECK(e.at("num_samples") == c.patches[p].samples.size());
      CHECK(e.at("adj_patches").get<std::vector<int>>() == neighbours[p]);
      REQUIRE(e.at("weight").is_number_integer());
      const double expected = std::max(1.0, std::round(c.patches[p].measure.get().to_double() * 1000));
      CHECK(e.at("weight").get<double>() == expected);
    }
    std::size_t outer = 0;
    for (const auto& cell : c.cells) outer += cell.outer;
    CHECK(g.at("outer_cells").size() == outer);
  }
  const LoadedInput in = load_input(scene_path("star.json"));
  CHECK_THROWS_AS(bsh_graphcut_to_json(in.complex(), 0), InputError);
  CHECK_THROWS_WITH(bsh_graphcut_to_json(in.complex(), std::int64_t(1) << 62), Catch::Contains("exceeds 2^53"));
}

TEST_CASE("external solver: runs, times out, fails, and leaves nothing behind", "[labelling][external]") {
  const LoadedInput in = load_input(scene_path("star.json"));
  const std::size_t cells = in.complex().cells.size();
  const std::string tmp = std::filesystem::temp_directory_path() / ("hsx-external-test-" + std::to_string(getpid()));
  std::filesystem::create_directories(tmp);
  setenv("TMPDIR", tmp.c_str(), 1);
  ExternalSolver solver;
  // A program that writes the empty shape as a plain list, after checking that its input is the graph-cut JSON.
  solver.command = "grep -q adj_cell_0 {input} && python3 -c \"print(' '.join(['0'] * " + std::to_string(cells) +
                   "))\" > {output}";
  ExternalRun run = run_external_solver(in, solver);
  CHECK(run.ran);
  CHECK(run.exit_status == 0);
  REQUIRE(run.labelling);
  CHECK(run.labelling->cells == std::vector<char>(cells, 0));
  CHECK(run.labelling->format == LabellingFormat::PlainList);
  // hsx-complex/1 as the input, a JSON list as the output.
  solver.input = ExternalInput::Complex;
  std::string list = "[0";
  for (std::size_t k = 1; k < cells; ++k) list += ",0";
  solver.command = "grep -q hsx-complex/1 {input} && echo '" + list + "]' > {output}";
  run = run_external_solver(in, solver);
  REQUIRE(run.labelling);
  CHECK(run.labelling->format == LabellingFormat::JsonList);
  // A malformed output: the problem names {output}, not the private folder.
  solver.command = "echo '" + list + "' > {output}; : {input}";
  run = run_external_solver(in, solver);
  CHECK(run.exit_status == 0);
  CHECK_FALSE(run.labelling);
  CHECK_THAT(run.problem, Catch::StartsWith("{output}: line "));
  // Failing, silent and slow programs.
  solver.input = ExternalInput::BshGraphcut;
  solver.command = "echo oops >&2; exit 5 # {input} {output}";
  run = run_external_solver(in, solver);
  CHECK(run.exit_status == 5);
  CHECK(run.problem == "exit status 5");
  CHECK(run.output_tail == "oops\n");
  solver.command = "true {input} {output}";
  run = run_external_solver(in, solver);
  CHECK(run.problem == "{output} was not written");
  solver.command = "sleep 30 & sleep 30; : {input} {output}";
  solver.time_limit = 0.3;
  run = run_external_solver(in, solver);
  CHECK(run.timed_out);
  CHECK_FALSE(run.ran);
  CHECK(run.seconds < 10);
  // A long log: only its last 4 KiB are kept.
  solver.time_limit = 0;
  solver.command = "seq 1 5000; exit 1 # {input} {output}";
  run = run_external_solver(in, solver);
  CHECK(run.output_tail.size() == 4096);
  CHECK_THAT(run.output_tail, Catch::EndsWith("\n4999\n5000\n"));
  // What the program leaves running is ended with it, also in a session of its own, also at the time limit.
  const std::string pid_file = tmp + "/escaped.pid";
  for (const double limit : {0.0, 0.5}) {
    solver.time_limit = limit;
    solver.command = "setsid sleep 60 & echo $! > '" + pid_file + "'; " + (limit > 0 ? "sleep 60; " : "") +
                     ": {input} {output}";
    run = run_external_solver(in, solver);
    CHECK(run.timed_out == (limit > 0));
    std::ifstream f(pid_file);
    pid_t escaped = 0;
    REQUIRE(f >> escaped);
    CHECK(::kill(escaped, 0) != 0);  // gone (and reaped: not even a zombie)
    std::filesystem::remove(pid_file);
  }
  solver.time_limit = 0;
  // hsx killed while the program runs (here a forked stand-in): by SIGKILL, so no handler of hsx's runs, or by
  // SIGINT sent to hsx and its keeper alike, as `pkill hsx` does. The keeper still ends what the program left, and
  // removes the private folder.
  for (const int how : {SIGKILL, SIGINT}) {
    CAPTURE(how);
    const pid_t stand_in = fork();
    REQUIRE(stand_in >= 0);
    if (stand_in == 0) {
      ::signal(SIGINT, SIG_DFL);
      solver.command = "setsid sleep 60 & echo $! > '" + pid_file + "'; sleep 60; : {input} {output}";
      try {
        run_external_solver(in, solver);
      } catch (...) {
      }
      _exit(0);
    }
    pid_t escaped = 0;
    for (int waited = 0; waited < 2000; ++waited) {
      std::ifstream f(pid_file);
      if (f >> escaped) break;
      escaped = 0;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    pid_t keeper = 0;
    {
      std::ifstream children("/proc/" + std::to_string(stand_in) + "/task/" + std::to_string(stand_in) + "/children");
      children >> keeper;
    }
    ::kill(stand_in, how);
    if (how != SIGKILL && keeper > 0) ::kill(keeper, how);
    ::waitpid(stand_in, nullptr, 0);
    REQUIRE(escaped > 0);
    CHECK((how == SIGKILL || keeper > 0));
    std::filesystem::remove(pid_file);
    bool cleaned = false;  // the keeper works after the stand-in is gone: wait for it, 10 s at most
    for (int waited = 0; waited < 1000 && !cleaned; ++waited) {
      cleaned = ::kill(escaped, 0) != 0 && std::filesystem::is_empty(tmp);
      if (!cleaned) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    CHECK(::kill(escaped, 0) != 0);  // gone (and reaped by the keeper: not even a zombie)
    CHECK(std::filesystem::is_empty(tmp));
    if (::kill(escaped, 0) == 0) ::kill(escaped, SIGKILL);
  }
  // Every private folder is gone.
  CHECK(std::filesystem::is_empty(tmp));
  std::filesystem::remove_all(tmp);
  unsetenv("TMPDIR");
  // Bad solvers are InputErrors.
  solver.time_limit = 0;
  solver.command = "cat {input}";
  CHECK_THROWS_WITH(run_external_solver(in, solver), Catch::Contains("has no {output}"));
  solver.command = " ";
  CHECK_THROWS_WITH(run_external_solver(in, solver), Catch::Contains("empty"));
}
