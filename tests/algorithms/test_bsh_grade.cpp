// bsh::grade (algorithms/bsh/grade.hpp) against the exhaustive oracle on random scenes: a labelling is graded
// optimal exactly when it is one of the oracle's optima, its validity flags agree with direct checks, and its gaps
// are its energy minus the optimum's.
#include <hsx/algorithms/bsh/grade.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/geometry/random_scene.hpp>
#include <hsx/io/scene_json.hpp>
#include "support/random_labellings.hpp"
#include "support/random_scenes.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <stdexcept>
#include <string>

using namespace hsx;
using namespace hsx::bsh;
using namespace hsx::test;

namespace {

SceneGenOptions small_scenes() {
  SceneGenOptions o;
  o.max_halfspaces = 4;
  o.max_degeneracies = 1;
  o.samples = true;
  o.max_samples = 5;
  return o;
}

}  // namespace

TEST_CASE("grade: random labellings against the oracle", "[bsh][grade]") {
  rc::prop("graded optimal iff among the oracle's optima; flags and gaps agree with direct checks", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = arrange(scene).complex;
    const Problem problem(complex);
    BruteForceResult bf;
    try {
      bf = brute_force(problem, true, 20000);
    } catch (const std::runtime_error&) {
      RC_DISCARD("oracle too large");
    }
    RC_PRE(bf.certified);
    // Half the time one of the optima, otherwise a random orientation-preserving labelling, or a random one.
    const int kind = *rc::gen::inRange(0, 3);
    Labelling labelling;
    if (kind == 0)
      labelling = bf.optimal[static_cast<std::size_t>(*rc::gen::inRange<int>(0, static_cast<int>(bf.optimal.size())))];
    else if (kind == 1)
      labelling = random_closure(problem, *rc::gen::inRange(1, 4));
    else
      labelling = *rc::gen::container<Labelling>(complex.cells.size(), rc::gen::element<char>(0, 1));

    ExtractOptions oracle = best_first_oracle();
    oracle.max_states = 2000;
    const Grade g = grade(problem, labelling, oracle);
    if (!g.optimum.optimal) RC_DISCARD("best-first reference over its budget");

    RC_ASSERT(g.orientation_preserving == is_orientation_preserving(problem, labelling));
    RC_ASSERT(g.sample_connected == sample_connectivity(problem, labelling).sample_connected());
    RC_ASSERT(g.islands.size() == sample_connectivity(problem, labelling).islands.size());
    RC_ASSERT(g.missing_samples_gap == g.energy.missing_samples - bf.energy.missing_samples);
    RC_ASSERT(compare(g.energy.measure() - g.measure_gap, bf.energy.measure()) == Order::Equal);
    const bool among_optima = std::find(bf.optimal.begin(), bf.optimal.end(), labelling) != bf.optimal.end();
    if (kind == 0) RC_ASSERT(among_optima);
    RC_ASSERT(g.optimal() == among_optima);
  });
}

TEST_CASE("grade: a labelling of the wrong size is refused", "[bsh][grade]") {
  const Complex complex = arrange(read_scene_file(std::string(HSX_SOURCE_DIR) + "/data/scenes/lens.json")).complex;
  const Problem problem(complex);
  CHECK_THROWS_AS(grade(problem, Labelling(complex.cells.size() + 1, 0)), std::invalid_argument);
}

TEST_CASE("grade: the reference falls back to exact where best-first is left unproven", "[bsh][grade]") {
  // Scene 153 of seed 1 under hsx campaign's generator settings: best-first ends unproven with no limit stopping
  // it (a graph cut whose measures did not separate).
  RandomSceneSettings settings;
  settings.max_samples = 6;
  const Complex complex = arrange(random_scene(settings, 1, 153).scene).complex;
  const Problem problem(complex);
  const ExtractResult best = extract(problem, best_first_oracle());
  REQUIRE_FALSE(best.optimal);
  REQUIRE(best.stopped_by.empty());
  const ExtractResult reference = reference_optimum(problem);
  CHECK(reference.method == Method::Exact);
  CHECK(reference.optimal);
  CHECK(reference.optimality_note.find("exact branch and bound decided") != std::string::npos);
  const BruteForceResult bf = brute_force(problem, true);
  CHECK(compare(reference.energy, bf.energy, {}) == Order::Equal);
  const Grade g = grade(problem, reference.labelling);
  CHECK(g.optimal());
  // Elsewhere (here a proven best-first, and any other method) the reference is the oracle's own result.
  ExtractOptions exact;
  exact.method = Method::Exact;
  CHECK(reference_optimum(problem, exact).method == Method::Exact);
}
