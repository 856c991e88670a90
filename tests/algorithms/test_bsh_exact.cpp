// The exact method (algorithms/bsh/exact.hpp): differential properties against the exhaustive oracle (small
// scenes) and best-first (where it is proven), the kept Prop. 5.1 counterexample, and the limits. proofs/bsh.md
// (entry 10) names these tests.
#include <hsx/algorithms/bsh/checks.hpp>
#include <hsx/algorithms/bsh/exact.hpp>
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/geometry/random_scene.hpp>
#include <hsx/io/scene_json.hpp>
#include "support/random_scenes.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace hsx {
inline void showValue(Order o, std::ostream& os) { os << to_string(o); }
}  // namespace hsx

using namespace hsx;
using namespace hsx::bsh;
using namespace hsx::test;

namespace {

constexpr long kOracleLimit = 20000;
constexpr int kManyTies = 100000;  ///< max_ties large enough that no small scene reaches it

bool contains(const std::vector<Labelling>& list, const Labelling& l) {
  return std::find(list.begin(), list.end(), l) != list.end();
}

ExtractResult exact(const Problem& problem, int max_ties = kManyTies,
                    ExactBranching branching = ExactBranching::Islands) {
  ExtractOptions o;
  o.method = Method::Exact;
  o.max_ties = max_ties;
  o.exact_branching = branching;
  return extract(problem, o);
}

/// On `scene`, the two branchings give the same optimum (up to unseparated ties) and, when ties are proven, the
/// same ties.
void check_branchings_agree(const Scene2& scene) {
  const Complex complex = arrange(scene).complex;
  const Problem problem(complex);
  const ExtractResult islands = exact(problem), cells = exact(problem, kManyTies, ExactBranching::Cells);
  RC_ASSERT(islands.optimal);
  RC_ASSERT(cells.optimal);
  const Order o = compare(islands.energy, cells.energy);
  RC_ASSERT(o != Order::Less);
  RC_ASSERT(o != Order::Greater);
  if (islands.ties.certified && cells.ties.certified) {
    RC_ASSERT(o == Order::Equal);
    RC_ASSERT(islands.ties.count == cells.ties.count);
    RC_ASSERT(islands.labelling == cells.labelling || contains(cells.tied, islands.labelling));
  }
  RC_ASSERT(cells.stats.island_branches == 0);
  RC_CLASSIFY(islands.stats.island_branches > 0, "island branching");
  RC_CLASSIFY(problem.cell_count() > 60, "more than 60 cells");
}

/// Small random scenes with every degeneracy kind (coincident boundaries, tangencies, concurrent lines, ...).
SceneGenOptions small_scenes(int max_halfspaces, std::vector<Degeneracy> degeneracies = {}) {
  SceneGenOptions o;
  o.max_halfspaces = max_halfspaces;
  o.min_degeneracies = degeneracies.empty() ? 0 : 1;
  o.max_degeneracies = 2;
  o.allowed_degeneracies = std::move(degeneracies);
  o.samples = true;
  o.max_samples = 2 * max_halfspaces + 1;
  return o;
}

/// Exact against the oracle: the same energy (Tie only when the oracle itself did not separate), a labelling
/// among the oracle's optima, every tie among them, and the same number of them.
void check_exact_against_oracle(const Problem& problem) {
  BruteForceResult bf;
  try {
    bf = brute_force(problem, true, kOracleLimit);
  } catch (const std::runtime_error&) {
    RC_DISCARD("oracle too large");
  }
  const ExtractResult r = exact(problem);
  RC_ASSERT(r.method == Method::Exact);
  RC_ASSERT(r.optimal);
  RC_ASSERT(r.stopped_by.empty());
  RC_ASSERT(is_orientation_preserving(problem, r.labelling));
  RC_ASSERT(sample_connectivity(problem, r.labelling).sample_connected());
  const Order o = compare(r.energy, bf.energy);
  if (bf.certified) {
    RC_ASSERT(o == Order::Equal);
  } else {
    RC_ASSERT(o == Order::Equal || o == Order::Tie);
  }
  RC_ASSERT(contains(bf.optimal, r.labelling));
  for (const Labelling& t : r.tied) RC_ASSERT(contains(bf.optimal, t));
  RC_ASSERT(r.ties.checked);
  RC_ASSERT(!r.ties.capped);
  if (bf.certified && r.ties.certified) RC_ASSERT(static_cast<std::size_t>(r.ties.count) == bf.optimal.size());
  RC_ASSERT(r.stats.gap.missing_samples == 0);
  RC_ASSERT(r.stats.gap.measure == 0.0);
  RC_CLASSIFY(bf.optimal.size() > 1u, "tie");
  RC_CLASSIFY(!problem.non_generic_junctions().empty(), "non-generic");
  RC_CLASSIFY(r.stats.pruned_by_islands > 0, "island pruning");
  RC_CLASSIFY(r.stats.island_branches > 0, "island branching");
  // The earlier rule (one cell at a time) finds the same optima: the oracle's.
  const ExtractResult cells = exact(problem, kManyTies, ExactBranching::Cells);
  RC_ASSERT(contains(bf.optimal, cells.labelling));
  if (bf.certified && cells.ties.certified) RC_ASSERT(static_cast<std::size_t>(cells.ties.count) == bf.optimal.size());
}

}  // namespace

TEST_CASE("exact property 1: exact = brute force on small random scenes (energy, boundary, tie count)",
          "[bsh][exact][property]") {
  rc::prop("any scene", [] {
    const Scene2 scene = *gen_scene(small_scenes(6));
    const Complex complex = arrange(scene).complex;
    check_exact_against_oracle(Problem(complex));
  });
  rc::prop("coincident boundaries", [] {
    const Scene2 scene = *gen_scene(small_scenes(
        6, {Degeneracy::RepeatedHalfspace, Degeneracy::ComplementTwin, Degeneracy::HalfplaneOnPolygonEdge,
            Degeneracy::PolygonsSharingEdge}));
    const Complex complex = arrange(scene).complex;
    check_exact_against_oracle(Problem(complex));
  });
  rc::prop("tangencies and vertices on boundaries", [] {
    const Scene2 scene = *gen_scene(small_scenes(
        6, {Degeneracy::LineTangentToDisk, Degeneracy::DisksTangentOutside, Degeneracy::DisksTangentInside,
            Degeneracy::PolygonVertexOnLine, Degeneracy::PolygonVertexOnCircle}));
    const Complex complex = arrange(scene).complex;
    check_exact_against_oracle(Problem(complex));
  });
  rc::prop("concurrent lines (non-generic junctions)", [] {
    SceneGenOptions o = small_scenes(7, {Degeneracy::ConcurrentLines});
    o.disks = o.polygons = false;
    const Scene2 scene = *gen_scene(o);
    const Complex complex = arrange(scene).complex;
    check_exact_against_oracle(Problem(complex));
  });
}

TEST_CASE("exact property 1b: exact = brute force on scenes rich in exact ties (tie counts)",
          "[bsh][exact][property][ties]") {
  rc::prop("grid rectangles (non-generic junctions, coincident edges)", [] {
    const Complex complex = arrange(*gen_grid_scene()).complex;
    check_exact_against_oracle(Problem(complex));
  });
  rc::prop("rooms (generic crossings)", [] {
    const Complex complex = arrange(*gen_rooms_scene()).complex;
    check_exact_against_oracle(Problem(complex));
  });
}

TEST_CASE("exact property 2: exact = best-first where best-first is proven (medium scenes)",
          "[bsh][exact][property]") {
  rc::prop("same energy and tie count", [] {
    const Scene2 scene = *gen_scene(small_scenes(8));
    const Complex complex = arrange(scene).complex;
    const Problem problem(complex);
    ExtractOptions o;
    o.method = Method::BestFirst;
    o.max_states = 150;  // best-first's cost grows fast: keep the cases that it proves quickly
    o.max_ties = kManyTies;
    const ExtractResult best = extract(problem, o);
    if (!best.optimal || !best.stopped_by.empty()) RC_DISCARD("best-first not proven");
    const ExtractResult r = exact(problem);
    RC_ASSERT(r.optimal);
    const Order order = compare(r.energy, best.energy);
    if (best.ties.certified && r.ties.certified) RC_ASSERT(order == Order::Equal);
    if (best.ties.checked && !best.ties.capped && best.ties.certified && r.ties.certified)
      RC_ASSERT(r.ties.count == best.ties.count);
    RC_CLASSIFY(r.ties.count > 1, "tie");
    RC_CLASSIFY(problem.cell_count() > 20, "more than 20 cells");
  });
}

TEST_CASE("exact property 3: branching on islands = branching on cells on larger scenes (energy, ties)",
          "[bsh][exact][property]") {
  rc::prop("random scenes, every degeneracy kind", [] { check_branchings_agree(*gen_scene(small_scenes(10))); });
  rc::prop("concurrent lines and shared edges", [] {
    check_branchings_agree(*gen_scene(small_scenes(10, {Degeneracy::ConcurrentLines, Degeneracy::PolygonsSharingEdge,
                                                        Degeneracy::HalfplaneOnPolygonEdge,
                                                        Degeneracy::LineTangentToDisk})));
  });
}

TEST_CASE("exact: hsx bench --exact's scenes of 12 halfspaces branch on islands and agree with branching on cells",
          "[bsh][exact]") {
  // Deterministic scenes (random_scene, seed 1, 1 to 3 samples per halfspace) on which the candidate has islands.
  const RandomSceneSettings settings = per_halfspace_sampled(12);
  long island_branches = 0;
  for (std::uint64_t index = 0; index < 4; ++index) {
    INFO("scene " << index);
    const Complex complex = arrange(random_scene(settings, 1, index).scene).complex;
    const Problem problem(complex);
    const ExtractResult islands = exact(problem);
    const ExtractResult cells = exact(problem, kManyTies, ExactBranching::Cells);
    REQUIRE(islands.optimal);
    REQUIRE(cells.optimal);
    CHECK(compare(islands.energy, cells.energy) == Order::Equal);
    CHECK(islands.ties.count == cells.ties.count);
    island_branches += islands.stats.island_branches;
  }
  CHECK(island_branches > 0);
}

TEST_CASE("exact: the Prop. 5.1 counterexample (three concurrent lines) gets the oracle's optimum",
          "[bsh][exact][regression]") {
  const auto file = std::filesystem::path(HSX_SOURCE_DIR) / "data" / "counterexamples" / "prop51-concurrent-lines.json";
  const Arranged2 arranged = arrange(read_scene_file(file.string()));
  const Problem problem(arranged.complex);
  REQUIRE(!problem.non_generic_junctions().empty());
  const BruteForceResult bf = brute_force(problem, true);
  const ExtractResult r = exact(problem);
  CHECK(r.optimal);
  CHECK(compare(r.energy, bf.energy) == Order::Equal);
  CHECK(contains(bf.optimal, r.labelling));
  CHECK(static_cast<std::size_t>(r.ties.count) == bf.optimal.size());
  // Best-first's search alone misses it there (the reason the file is kept).
  ExtractOptions o;
  o.method = Method::BestFirst;
  o.certify_limit = 0;
  CHECK(compare(extract(problem, o).energy, bf.energy) == Order::Greater);
}

TEST_CASE("exact: limits stop it with the incumbent and a proven lower bound, never a claim of optimality",
          "[bsh][exact]") {
  const auto file = std::filesystem::path(HSX_SOURCE_DIR) / "data" / "scenes" / "star.json";
  const Arranged2 arranged = arrange(read_scene_file(file.string()));
  const Problem problem(arranged.complex);
  const ExtractResult full = exact(problem);
  REQUIRE(full.optimal);
  REQUIRE(full.stats.nodes > 2);
  const auto check_stopped = [&](const ExtractResult& r, const std::string& by) {
    CHECK(r.stopped_by == by);
    CHECK_FALSE(r.optimal);
    CHECK_FALSE(r.ties.checked);
    CHECK(is_orientation_preserving(problem, r.labelling));
    CHECK(sample_connectivity(problem, r.labelling).sample_connected());
    CHECK(compare(r.energy, full.energy) != Order::Less);
    // The lower bound is proven: never above the optimum.
    const EnergyBound& lb = r.stats.lower_bound;
    CHECK(lb.missing_samples <= full.energy.missing_samples);
    if (lb.missing_samples == full.energy.missing_samples)
      CHECK(lb.measure <= full.energy.measure().enclose(64).hi_double());
  };
  ExtractOptions o;
  o.method = Method::Exact;
  o.max_nodes = 2;
  check_stopped(extract(problem, o), "max-nodes");
  o.max_nodes = 0;
  o.time_limit = 1e-9;
  check_stopped(extract(problem, o), "time-limit");
}

TEST_CASE("exact: max_ties caps the enumeration and says so", "[bsh][exact]") {
  rc::prop("capped at 1: the optimum still exact", [] {
    const Scene2 scene = *gen_scene(small_scenes(6));
    const Complex complex = arrange(scene).complex;
    const Problem problem(complex);
    const ExtractResult all = exact(problem);
    const ExtractResult one = exact(problem, 1);
    RC_ASSERT(one.optimal);
    RC_ASSERT(one.ties.count == 1);
    RC_ASSERT(one.ties.capped);
    RC_ASSERT(compare(one.energy, all.energy) != Order::Less);
    RC_ASSERT(compare(one.energy, all.energy) != Order::Greater);
    RC_ASSERT(one.labelling == all.labelling || contains(all.tied, one.labelling));
  });
}

TEST_CASE("exact: hsx check's Prop. 5.2 row uses exact as the oracle when brute force is too large",
          "[bsh][exact][checks]") {
  for (const char* name : {"star.json", "lens.json"}) {
    INFO(name);
    const auto file = std::filesystem::path(HSX_SOURCE_DIR) / "data" / "scenes" / name;
    const Arranged2 arranged = arrange(read_scene_file(file.string()));
    const auto results = check_all(arranged.complex, 1);  // the oracle may enumerate one labelling: too large
    const auto row = std::find_if(results.begin(), results.end(),
                                  [](const CheckResult& r) { return r.name.rfind("Prop. 5.2", 0) == 0; });
    REQUIRE(row != results.end());
    CHECK(row->name.find("exact") != std::string::npos);
    CHECK(row->status == CheckResult::Pass);
  }
}

// Domains and disks beyond the largest double (1e400 is within the input limits): the exact search's integer
// bound rounded measures of enclosure [DBL_MAX, inf] to garbage integers (a half-plane in a domain of +-1e400
// crashed with SIGSEGV; four disks of radius 1e399 ended with "the integer max flow does not match its cut").
// Now the enclosures are scaled by one power of two: the same optimum as brute force, proven, with a finite bound.
TEST_CASE("exact: measures beyond the largest double get brute force's optimum, proven", "[bsh][exact][regression]") {
  const std::string domain = R"("domain":{"min":["-1e400","-1e400"],"max":["1e400","1e400"]},)";
  const std::vector<std::string> scenes = {
      R"({"format":"hsx-scene/1","dimension":2,)" + domain +
          R"("halfspaces":[{"name":"A","kind":"halfplane","normal":[0,1],"offset":0}],"samples":[{"on":"A","at":[0,0]}]})",
      R"({"format":"hsx-scene/1","dimension":2,)" + domain +
          R"("halfspaces":[{"name":"A","kind":"disk","center":[0,0],"radius":"1e399"},)"
          R"({"name":"B","kind":"disk","center":["1e-400",0],"radius":"1e399"},)"
          R"({"name":"C","kind":"disk","center":[0,"1e-400"],"radius":"1e399"},)"
          R"({"name":"D","kind":"halfplane","normal":["1e-400","1"],"offset":"1e-400"}],)"
          R"("samples":[{"on":"A","near":[0,"1e399"]},{"on":"D","near":[1,1]}]})",
      R"({"format":"hsx-scene/1","dimension":2,)" + domain +
          R"("halfspaces":[{"name":"A","kind":"disk","center":[0,0],"radius":"1e399"},)"
          R"({"name":"B","kind":"disk","center":[1,0],"radius":"1e399"}],"samples":[{"on":"A","near":[0,"1e399"]}]})"};
  for (const std::string& text : scenes) {
    INFO(text);
    const Arranged2 arranged = arrange(read_scene_text(text));
    const Problem problem(arranged.complex);
    CHECK(problem.enclosure_scale() > 0);
    const BruteForceResult bf = brute_force(problem, true);
    REQUIRE(bf.certified);
    const ExtractResult r = exact(problem);
    CHECK(r.optimal);
    CHECK(compare(r.energy, bf.energy) == Order::Equal);
    CHECK(contains(bf.optimal, r.labelling));
    CHECK(static_cast<std::size_t>(r.ties.count) == bf.optimal.size());
    // The reported lower bound is the optimum's, rounded down to a double (the largest one beyond it).
    CHECK(std::isfinite(r.stats.lower_bound.measure));
    CHECK(r.stats.lower_bound.missing_samples == bf.energy.missing_samples);
    CHECK(r.stats.lower_bound.measure <= bf.energy.measure().enclose(64).hi_double());
  }
}
