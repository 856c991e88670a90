// Property tests of the BSH extraction layer (algorithms/bsh) on random 2D scenes with degeneracies
// (tests/support/random_scenes.hpp), small enough for the exhaustive oracle (brute_force). Each property is one
// statement of the paper or of proofs/bsh.md; the comments say which.
#include <hsx/algorithms/bsh/checks.hpp>
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/bsh/graph_cut.hpp>
#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/complex/complex.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/kernel/measure.hpp>
#include "support/random_labellings.hpp"
#include "support/random_scenes.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace hsx {
/// rapidcheck prints RC_ASSERT operands with this.
inline void showValue(Order o, std::ostream& os) { os << to_string(o); }
}  // namespace hsx

using namespace hsx;
using namespace hsx::bsh;
using namespace hsx::test;

namespace {

/// Scenes whose oracle enumerates more orientation-preserving labellings than this are discarded.
constexpr long kOracleLimit = 20000;

SceneGenOptions small_scenes(bool curved = true) {
  SceneGenOptions o;
  o.max_halfspaces = 5;
  o.max_degeneracies = 2;
  o.disks = curved;
  o.samples = true;
  o.max_samples = 7;
  if (!curved) {
    // Degeneracies that need a circle are skipped by the generator when disks are not allowed.
    o.allowed_degeneracies = {Degeneracy::RepeatedHalfspace,      Degeneracy::ComplementTwin,
                              Degeneracy::ConcurrentLines,        Degeneracy::PolygonVertexOnLine,
                              Degeneracy::HalfplaneOnPolygonEdge, Degeneracy::PolygonsSharingEdge};
  }
  return o;
}

Complex complex_of(const Scene2& scene) { return arrange(scene).complex; }

/// Best-first with tie enumeration, under a state budget: the search is exponential in the worst case, and a
/// few random scenes would take seconds. Runs over budget are discarded (rare: about 1 in 50 scenes).
/// `search_only`: no oracle fallback at non-generic junctions (ExtractOptions::certify_limit = 0), so that the
/// search itself is what is tested; otherwise hsx's default, which certifies with the oracle there.
ExtractResult best_first(const Problem& problem, bool search_only = false) {
  ExtractOptions o;
  o.method = Method::BestFirst;
  o.max_states = 200;
  if (search_only) o.certify_limit = 0;
  ExtractResult r = extract(problem, o);
  if (!r.stopped_by.empty()) RC_DISCARD("best-first over its state budget");
  return r;
}

BruteForceResult oracle(const Problem& problem, bool connectivity) {
  try {
    return brute_force(problem, connectivity, kOracleLimit);
  } catch (const std::runtime_error&) {
    RC_DISCARD("oracle too large");
  }
  throw std::logic_error("unreachable");
}

bool curved(const Complex& c) {
  return std::any_of(c.patches.begin(), c.patches.end(), [](const Patch& p) { return p.measure.get().has_special_terms(); });
}

bool contains(const std::vector<Labelling>& list, const Labelling& l) {
  return std::find(list.begin(), list.end(), l) != list.end();
}

/// A result that claims to be the unique, proven optimum.
bool unique_proven(const ExtractResult& r) { return r.optimal && r.ties.count == 1 && r.ties.certified; }

/// Best-first against the oracle. Always: the result is admissible, never below the optimum, and never a
/// false claim of a unique proven optimum. With `exact` (the search is proven complete: generic junctions, or
/// the oracle fallback): energy Equal (Tie only when the oracle itself is unseparated), a boundary among the
/// oracle's optima, and the same number of ties when they were enumerated.
void check_against_oracle(const Problem& problem, const ExtractResult& r, const BruteForceResult& bf, bool exact) {
  RC_ASSERT(r.sample_connected);
  RC_ASSERT(sample_connectivity(problem, r.labelling).sample_connected());
  RC_ASSERT(is_orientation_preserving(problem, r.labelling));
  const Order order = compare(r.energy, bf.energy);
  RC_ASSERT(order != Order::Less);
  if (order != Order::Equal) RC_ASSERT(!unique_proven(r) || (order == Order::Tie && !bf.certified));
  if (!exact) return;
  if (order != Order::Equal) {
    // Only an unseparated tie may differ from Equal, and then neither side may claim a unique proven answer.
    RC_ASSERT(order == Order::Tie);
    RC_ASSERT(!bf.certified);
    RC_ASSERT(!unique_proven(r));
  }
  RC_ASSERT(contains(bf.optimal, r.labelling));
  for (const Labelling& t : r.tied) RC_ASSERT(contains(bf.optimal, t));
  if (r.labelling != bf.optimal.front()) {
    RC_ASSERT(bf.optimal.size() > 1u);
    if (r.ties.checked) RC_ASSERT(r.ties.count > 1);
  }
  if (r.optimal && r.ties.checked && !r.ties.capped && bf.certified && r.ties.certified)
    RC_ASSERT(static_cast<std::size_t>(r.ties.count) == bf.optimal.size());
}

/// A random orientation-preserving labelling (tests/support/random_labellings.hpp).
Labelling random_op_labelling(const Problem& problem) { return test::random_closure(problem, 6); }

Labelling random_labelling(int n) {
  Labelling l(n, 0);
  for (int k = 0; k < n; ++k) l[k] = static_cast<char>(*rc::gen::inRange(0, 2));
  return l;
}

/// The complex with its samples replaced by one sample on every patch of `labelling`'s boundary that lies on it
/// with its own halfspace's orientation (Prop. 4.1; a coincident patch used reversed is not "on b" for its
/// halfspace, problem.hpp), written independently of bsh::with_one_sample_per_boundary_patch.
Complex one_sample_per_boundary_patch(const Complex& complex, const Labelling& labelling) {
  Complex c = complex;
  c.samples.clear();
  for (Patch& p : c.patches) p.samples.clear();
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p)
    if (labelling[c.patches[p].inside_cell] && !labelling[c.patches[p].outside_cell]) {  // on b, own orientation
      c.patches[p].samples.push_back(static_cast<int>(c.samples.size()));
      c.samples.push_back({c.patches[p].halfspace, p});
    }
  return c;
}

/// Boundary support ends at each junction (a closed patch through a junction ends there twice).
std::map<int, int> boundary_ends(const Problem& problem, const Labelling& labelling) {
  std::map<int, int> ends;
  for (int g : boundary_supports(problem, labelling))
    for (int j : problem.complex().patches[problem.supports()[g].patches.front()].junctions) ++ends[j];
  return ends;
}

/// Junctions that are transversal crossings of two boundaries, decided on the complex alone: four support ends,
/// single-patch supports, two halfspaces with two ends each, and four distinct cells around them taking all
/// four inside/outside combinations of the two halfspaces.
std::vector<int> crossing_junctions(const Problem& problem) {
  const Complex& c = problem.complex();
  std::vector<int> out;
  for (int j = 0; j < static_cast<int>(c.junctions.size()); ++j) {
    std::vector<int> ends;  // patches, with multiplicity
    for (int p : c.junctions[j].patches)
      for (int jj : c.patches[p].junctions)
        if (jj == j) ends.push_back(p);
    if (ends.size() != 4) continue;
    std::map<int, int> per_halfspace;
    std::set<int> cells;
    bool single = true;
    for (int p : ends) {
      single = single && problem.supports()[c.patches[p].support].patches.size() == 1;
      ++per_halfspace[c.patches[p].halfspace];
      cells.insert(c.patches[p].inside_cell);
      cells.insert(c.patches[p].outside_cell);
    }
    if (!single || per_halfspace.size() != 2 || cells.size() != 4) continue;
    const int h = per_halfspace.begin()->first, k = per_halfspace.rbegin()->first;
    if (per_halfspace[h] != 2 || per_halfspace[k] != 2) continue;
    std::set<std::pair<int, int>> sides;
    for (int cell : cells) sides.insert({c.cells[cell].inside[h], c.cells[cell].inside[k]});
    if (sides.size() == 4) out.push_back(j);
  }
  return out;
}

/// Every junction that a boundary can use (some patch there separates a non-outer cell) is a crossing: the
/// hypothesis under which proofs/bsh.md proves Prop. 5.1 (and so the completeness of best-first). Stricter than
/// Problem::non_generic_junctions, which also accepts touching corners and tangencies whose side sectors are
/// distinct cells.
bool every_junction_crosses(const Problem& problem) {
  const Complex& c = problem.complex();
  const auto crossings = crossing_junctions(problem);
  for (int j = 0; j < static_cast<int>(c.junctions.size()); ++j) {
    bool usable = false;
    for (int p : c.junctions[j].patches)
      usable = usable || !c.cells[c.patches[p].inside_cell].outer || !c.cells[c.patches[p].outside_cell].outer;
    if (usable && !std::binary_search(crossings.begin(), crossings.end(), j)) return false;
  }
  return true;
}

std::vector<int> island_supports(const Problem& problem, const Component& component) {
  std::vector<int> out;
  for (int p : component.patches) out.push_back(problem.complex().patches[p].support);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// Prop. 5.1 for b (orientation-preserving, not sample-connected) and b' (orientation-preserving,
/// sample-connected): for every island I of b, I ∩ b' = ∅ or some support of b adjacent to I is not on b'.
/// Returns the first island breaking it, or -1.
int prop51_violation(const Problem& problem, const Labelling& b, const Labelling& b_prime) {
  const SampleConnectivity conn = sample_connectivity(problem, b);
  const auto on_b = boundary_supports(problem, b), on_bp = boundary_supports(problem, b_prime);
  auto in = [](const std::vector<int>& v, int g) { return std::binary_search(v.begin(), v.end(), g); };
  for (int island : conn.islands) {
    const auto is = island_supports(problem, conn.components[island]);
    const bool disjoint = std::none_of(is.begin(), is.end(), [&](int g) { return in(on_bp, g); });
    bool neighbour_missing = false;
    for (int g : is)
      for (int h : problem.support_neighbours()[g])
        if (in(on_b, h) && !in(is, h) && !in(on_bp, h)) neighbour_missing = true;
    if (!disjoint && !neighbour_missing) return island;
  }
  return -1;
}

// Beam K = 1 optimality, recorded by property 8 and printed at its end.
long g_beam_cases = 0, g_beam_optimal = 0;

}  // namespace

TEST_CASE("bsh property 1: best-first = brute force (Prop. 5.2), same boundary unless a tie is reported",
          "[bsh][property][prop52]") {
  rc::prop("best-first energy and boundary match the oracle", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    const BruteForceResult bf = oracle(problem, true);
    const bool generic = problem.non_generic_junctions().empty();
    const bool crossings = every_junction_crosses(problem);
    // The search alone: proven complete when every junction is a crossing (Prop. 5.1); hsx claims optimality
    // only where its own test finds no non-generic junction. Whatever it claims must be right.
    const ExtractResult search = best_first(problem, true);
    check_against_oracle(problem, search, bf, search.optimal || crossings);
    if (!generic) RC_ASSERT(!search.optimal);
    if (crossings && search.stats.uncertified_cuts == 0) RC_ASSERT(search.optimal);
    RC_CLASSIFY(!generic, "non-generic");
    RC_CLASSIFY(!generic && compare(search.energy, bf.energy) == Order::Greater, "search missed the optimum");
    RC_CLASSIFY(search.stats.states_expanded > search.ties.count, "searched past the root");
    RC_CLASSIFY(search.stats.reused_cuts > 0, "reused a cut");
    RC_CLASSIFY(bf.optimal.size() > 1u, "tie");
    // hsx's default certifies non-generic cases with the oracle: then it is exact everywhere.
    check_against_oracle(problem, generic ? search : best_first(problem), bf, true);
  });
}

TEST_CASE("bsh property 1b: best-first = brute force on grid scenes (non-generic junctions, ties)",
          "[bsh][property][prop52][ties]") {
  rc::prop("best-first energy, boundary and tie count match the oracle", [] {
    const Scene2 scene = *gen_grid_scene();
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    const BruteForceResult bf = oracle(problem, true);
    RC_ASSERT(bf.certified);  // straight scenes: every comparison is exact
    const bool generic = problem.non_generic_junctions().empty();
    const ExtractResult search = best_first(problem, true);
    check_against_oracle(problem, search, bf, search.optimal || every_junction_crosses(problem));
    if (!generic) RC_ASSERT(!search.optimal);
    const ExtractResult r = best_first(problem);
    check_against_oracle(problem, r, bf, true);
    RC_ASSERT(r.optimal);
    RC_ASSERT(r.ties.checked);
    RC_ASSERT(r.ties.certified);
    if (!r.ties.capped) RC_ASSERT(static_cast<std::size_t>(r.ties.count) == bf.optimal.size());
    RC_CLASSIFY(r.ties.count > 1, "tie");
    RC_CLASSIFY(!generic, "non-generic");
    RC_CLASSIFY(compare(search.energy, bf.energy) == Order::Greater, "search missed the optimum");
  });
}

TEST_CASE("bsh property 1c: best-first search = brute force on generic scenes with ties (tie enumeration)",
          "[bsh][property][prop52][ties]") {
  rc::prop("the search alone finds the optimum and enumerates every tie", [] {
    const Scene2 scene = *gen_rooms_scene();
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    RC_ASSERT(problem.non_generic_junctions().empty());  // crossings only, by construction
    RC_ASSERT(every_junction_crosses(problem));
    const BruteForceResult bf = oracle(problem, true);
    RC_ASSERT(bf.certified);
    const ExtractResult r = best_first(problem, true);
    check_against_oracle(problem, r, bf, true);
    RC_ASSERT(r.optimal);
    RC_ASSERT(r.ties.checked);
    RC_ASSERT(r.ties.certified);
    if (!r.ties.capped) RC_ASSERT(static_cast<std::size_t>(r.ties.count) == bf.optimal.size());
    RC_CLASSIFY(r.ties.count > 1, "tie");
    RC_CLASSIFY(r.stats.states_expanded > r.ties.count, "searched past the root");
  });
}

TEST_CASE("bsh property 2: graph cut = brute force without sample-connectedness (Section 5.1)",
          "[bsh][property][graphcut]") {
  rc::prop("graph cut energy equals the relaxed oracle's", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    const BruteForceResult bf = oracle(problem, false);
    const CutResult cut = graph_cut(problem, {});
    RC_ASSERT(cut.energy.missing_samples >= 0);
    RC_ASSERT(is_orientation_preserving(problem, cut.labelling));
    RC_ASSERT(compare(cut.energy, energy(problem, cut.labelling)) == Order::Equal);
    const Order order = compare(cut.energy, bf.energy);
    RC_ASSERT(order != Order::Less);
    RC_ASSERT(order != Order::Greater);
    if (order == Order::Tie) RC_ASSERT(!cut.certified || !bf.certified);
    if (!curved(complex)) RC_ASSERT(cut.certified);
    ExtractOptions o;
    o.method = Method::GraphCut;
    const ExtractResult r = extract(problem, o);
    RC_ASSERT(r.labelling == cut.labelling);
    RC_ASSERT(r.optimal == (cut.certified && sample_connectivity(problem, cut.labelling).sample_connected()));
  });
}

/// The cut from the double warm start and the cut from the zero flow, under the same constraints, are the same cut:
/// the source side of a maximum flow does not depend on the flow (graph_cut.hpp). Their `certified` flags may
/// differ: the certificate checks the flow each one found, and one flow can leave an arc whose residual is an exact
/// zero of arc-angle terms that intervals cannot decide (issue 11 §2; found by this property on a scene of disks,
/// rapidcheck seed 9371466805928338663, where the zero flow's certificate tied and the warm start's held).
void check_warm_start_against_zero_flow(const Problem& problem, CutConstraints constraints) {
  constraints.warm_start = true;
  const CutResult warm = graph_cut(problem, constraints);
  constraints.warm_start = false;
  const CutResult cold = graph_cut(problem, constraints);
  RC_ASSERT(warm.labelling == cold.labelling);
  RC_ASSERT(warm.energy.missing_samples == cold.energy.missing_samples);
  if (cold.energy.missing_samples < 0) return;
  const Order order = compare(warm.energy, cold.energy);
  RC_ASSERT(order == Order::Equal || (order == Order::Tie && !(warm.certified && cold.certified)));
}

namespace {

/// The complex of a random scene of small_scenes() with up to `halfspaces` halfspaces and `samples` samples.
Complex gen_larger_complex(int halfspaces, int samples) {
  SceneGenOptions o = small_scenes();
  o.max_halfspaces = halfspaces;
  o.max_samples = samples;
  return complex_of(*gen_scene(o));
}

/// Random removed supports (CutConstraints::removed): each support with probability 1/8.
std::vector<char> gen_removed(const Problem& problem) {
  std::vector<char> removed(problem.support_count(), 0);
  for (auto& r : removed) r = static_cast<char>(*rc::gen::inRange(0, 8) == 0);
  return removed;
}

}  // namespace

TEST_CASE("bsh property 2b: the warm-started cut is the exact optimum (small) and the zero-flow cut (larger)",
          "[bsh][property][graphcut]") {
  rc::prop("small scenes: warm-started cut = relaxed oracle, certified on straight scenes", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    const BruteForceResult bf = oracle(problem, false);
    const CutResult cut = graph_cut(problem, {});
    RC_ASSERT(cut.energy.missing_samples >= 0);
    const Order order = compare(cut.energy, bf.energy);
    RC_ASSERT(order != Order::Less);
    RC_ASSERT(order != Order::Greater);
    if (!curved(complex)) RC_ASSERT(cut.certified);
    check_warm_start_against_zero_flow(problem, {});
  });
  rc::prop("larger scenes, with forced cells and removed supports: warm start = zero flow", [] {
    const Complex complex = gen_larger_complex(14, 20);
    const Problem problem(complex);
    RC_CLASSIFY(problem.cell_count() > 30, "more than 30 cells");
    check_warm_start_against_zero_flow(problem, {});
    CutConstraints k;
    k.forced.assign(problem.cell_count(), -1);
    k.removed = gen_removed(problem);
    for (auto& f : k.forced) f = static_cast<signed char>(*rc::gen::inRange(-6, 2) < 0 ? -1 : *rc::gen::inRange(0, 2));
    check_warm_start_against_zero_flow(problem, k);
  });
}

TEST_CASE("bsh property 2c: a cut whose boundary avoids more removed supports is their cut too (proofs/bsh.md 8 (e))",
          "[bsh][property][graphcut]") {
  // The lemma behind best-first's reuse of cuts (KnownCuts in extract.cpp): removed set R, its certified cut b,
  // and R' = R plus supports that are not on b: graph_cut under R' returns b again, certified, with b's energy.
  rc::prop("graph_cut(R') = graph_cut(R) when R is in R' and b(R) avoids R'", [] {
    const Complex complex = gen_larger_complex(12, 12);
    const Problem problem(complex);
    CutConstraints k;
    k.removed = gen_removed(problem);
    if (*rc::gen::inRange(0, 3) == 0) {  // sometimes forced cells too: a tie enumeration's searches have them
      k.forced.assign(problem.cell_count(), -1);
      k.forced[*rc::gen::inRange(0, problem.cell_count())] = static_cast<signed char>(*rc::gen::inRange(0, 2));
    }
    const CutResult cut = graph_cut(problem, k);
    RC_PRE(cut.energy.missing_samples >= 0 && cut.certified);
    const std::vector<char> on_b = boundary_support_flags(problem, cut.labelling);
    CutConstraints more = k;
    int added = 0;
    for (int g = 0; g < problem.support_count(); ++g)
      if (!on_b[g] && !more.removed[g] && *rc::gen::inRange(0, 3) == 0) {
        more.removed[g] = 1;
        ++added;
      }
    RC_CLASSIFY(added == 0, "nothing added");
    const CutResult again = graph_cut(problem, more);
    RC_ASSERT(again.labelling == cut.labelling);
    RC_ASSERT(again.energy.missing_samples == cut.energy.missing_samples);
    const Order order = compare(again.energy, cut.energy);
    RC_ASSERT(order != Order::Less);
    RC_ASSERT(order != Order::Greater);
    RC_ASSERT(again.certified);
    // And the converse that makes the lemma's condition necessary: removing a support of b changes the cut.
    const auto first_on_b = std::find(on_b.begin(), on_b.end(), 1);
    if (first_on_b != on_b.end()) {
      more.removed[first_on_b - on_b.begin()] = 1;
      RC_ASSERT(graph_cut(problem, more).labelling != cut.labelling);
    }
  });
}

TEST_CASE("bsh property 3: cut cost = labelling energy (Eqs. 2-4); straight scenes give certified cuts",
          "[bsh][property][eq24]") {
  rc::prop("every graph cut on a straight scene is certified", [] {
    const Scene2 scene = *gen_scene(small_scenes(false));
    const Complex complex = complex_of(scene);
    RC_PRE(!curved(complex));
    const Problem problem(complex);
    const CutResult root = graph_cut(problem, {});
    RC_ASSERT(root.certified);
    // Children of the root (removed sets), and cuts with one random label forced.
    const auto sets = removable_sets(problem, root.labelling, sample_connectivity(problem, root.labelling));
    for (const auto& set : sets) {
      CutConstraints k;
      k.removed.assign(problem.support_count(), 0);
      for (int g : set) k.removed[g] = 1;
      const CutResult child = graph_cut(problem, k);
      RC_ASSERT(child.energy.missing_samples >= 0);  // the empty boundary is always admissible
      RC_ASSERT(child.certified);
    }
    CutConstraints k;
    k.forced.assign(problem.cell_count(), -1);
    k.forced[*rc::gen::inRange(0, problem.cell_count())] = static_cast<signed char>(*rc::gen::inRange(0, 2));
    const CutResult forced = graph_cut(problem, k);
    if (forced.energy.missing_samples >= 0) RC_ASSERT(forced.certified);
  });
  rc::prop("cut_cost(L) == energy(L) for orientation-preserving L, infinite otherwise", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    const Labelling l = random_op_labelling(problem);
    RC_ASSERT(is_orientation_preserving(problem, l));
    Energy cost;
    RC_ASSERT(cut_cost(problem, {}, l, &cost));
    RC_ASSERT(cost.missing_samples == energy(problem, l).missing_samples);
    RC_ASSERT(compare(cost.measure(), energy(problem, l).measure()) == Order::Equal);
    // An arbitrary labelling costs infinity exactly when it breaks orientation preservation.
    const Labelling any = random_labelling(problem.cell_count());
    const bool finite = cut_cost(problem, {}, any, &cost);
    RC_ASSERT(finite == is_orientation_preserving(problem, any));
    if (finite) RC_ASSERT(compare(cost, energy(problem, any)) == Order::Equal);
    // With removed supports: finite exactly when no removed support is on b.
    CutConstraints k;
    k.removed.assign(problem.support_count(), 0);
    for (auto& r : k.removed) r = *rc::gen::inRange(0, 4) == 0;
    bool uses_removed = false;
    for (int g : boundary_supports(problem, l)) uses_removed = uses_removed || k.removed[g];
    RC_ASSERT(cut_cost(problem, k, l, &cost) == !uses_removed);
    // The graph cut is never worse than the labelling (weak duality).
    if (!uses_removed) {
      const CutResult cut = graph_cut(problem, k);
      RC_ASSERT(compare(cut.energy, energy(problem, l)) != Order::Greater);
    }
  });
}

TEST_CASE("bsh property 3b: energies compared by their supports agree with their exact sums",
          "[bsh][property][energy]") {
  rc::prop("compare(energy(L1), energy(L2)) == compare of the summed measures; measure() is the sum", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    const Labelling l1 = random_op_labelling(problem);
    const Labelling l2 = *rc::gen::inRange(0, 4) == 0 ? l1 : random_op_labelling(problem);
    const Energy e1 = energy(problem, l1), e2 = energy(problem, l2);
    // The eager sum, formed independently of Energy: the measures of the boundary's supports.
    const auto sum = [&](const Labelling& l) {
      Measure m;
      for (int g : boundary_supports(problem, l)) m += problem.supports()[g].measure;
      return Energy(energy(problem, l).missing_samples, m);
    };
    const Energy s1 = sum(l1), s2 = sum(l2);
    RC_ASSERT((e1.measure() - s1.measure()).is_zero());
    const Order lazy = compare(e1, e2), eager = compare(s1, s2);
    if (lazy != Order::Tie && eager != Order::Tie) RC_ASSERT(lazy == eager);
    if (l1 == l2) RC_ASSERT(lazy == Order::Equal);
    // Energies outlive their problem: the supports' measures are shared.
    const Energy kept = [&] {
      const Problem other(complex);
      return energy(other, l1);
    }();
    RC_ASSERT((kept.measure() - s1.measure()).is_zero());
  });
}

TEST_CASE("bsh property 4: a child state's energy is never below its parent's (Prop. 5.2)",
          "[bsh][property][monotone]") {
  rc::prop("graph cut with a removable set removed has energy >= the root's", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    const CutResult root = graph_cut(problem, {});
    const SampleConnectivity conn = sample_connectivity(problem, root.labelling);
    RC_CLASSIFY(conn.sample_connected(), "root sample-connected");
    for (const auto& set : removable_sets(problem, root.labelling, conn)) {
      CutConstraints k;
      k.removed.assign(problem.support_count(), 0);
      for (int g : set) k.removed[g] = 1;
      const CutResult child = graph_cut(problem, k);
      RC_ASSERT(child.energy.missing_samples >= 0);
      RC_ASSERT(compare(child.energy, root.energy) != Order::Less);
      for (int g : boundary_supports(problem, child.labelling)) RC_ASSERT(!k.removed[g]);
    }
  });
  rc::prop("the same under forced labels and an initial removed set (as enumerate_ties uses it)", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    CutConstraints base;
    base.removed.assign(problem.support_count(), 0);
    for (auto& r : base.removed) r = *rc::gen::inRange(0, 5) == 0;
    // Force a random orientation-preserving boundary's support on, as force_on does.
    base.forced.assign(problem.cell_count(), -1);
    const Labelling target = random_op_labelling(problem);
    const auto on = boundary_supports(problem, target);
    if (!on.empty()) {
      const SupportTerm& s = problem.supports()[on[*rc::gen::inRange(0, static_cast<int>(on.size()))]];
      const int one = target[s.cell_a] ? s.cell_a : s.cell_b;
      base.forced[one] = 1;
      base.forced[one == s.cell_a ? s.cell_b : s.cell_a] = 0;
    }
    const CutResult root = graph_cut(problem, base);
    RC_PRE(root.energy.missing_samples >= 0);
    for (int k = 0; k < problem.cell_count(); ++k)
      if (base.forced[k] >= 0) RC_ASSERT(root.labelling[k] == base.forced[k]);
    const SampleConnectivity conn = sample_connectivity(problem, root.labelling);
    for (const auto& set : removable_sets(problem, root.labelling, conn)) {
      CutConstraints k = base;
      for (int g : set) k.removed[g] = 1;
      const CutResult child = graph_cut(problem, k);
      if (child.energy.missing_samples < 0) continue;  // forced labels may make a child infeasible
      RC_ASSERT(compare(child.energy, root.energy) != Order::Less);
      for (int g : boundary_supports(problem, child.labelling)) RC_ASSERT(!k.removed[g]);
    }
  });
}

TEST_CASE("bsh property 5: Prop. 5.1 - an island or one of its neighbours is not on a sample-connected b'",
          "[bsh][property][prop51]") {
  rc::prop("root graph cut vs best-first result, and random boundaries vs every optimum", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    // b' ranges over every optimum (from the oracle) and the best-first result; b over the root graph cut and a
    // random orientation-preserving labelling. Proven when every junction is a crossing (proofs/bsh.md); otherwise
    // a failure is recorded, not asserted (see "bsh unit: three concurrent lines ..." and "... tangent ...").
    const BruteForceResult bf = oracle(problem, true);
    std::vector<Labelling> targets = bf.optimal;
    targets.push_back(best_first(problem, true).labelling);
    const bool generic = every_junction_crosses(problem);
    const CutResult root = graph_cut(problem, {});
    const Labelling random = random_op_labelling(problem);
    RC_CLASSIFY(!sample_connectivity(problem, root.labelling).sample_connected(), "root has islands");
    RC_CLASSIFY(!generic, "a junction is not a crossing");
    bool failed_non_generic = false;
    for (const Labelling& b : {root.labelling, random}) {
      if (sample_connectivity(problem, b).sample_connected()) continue;
      for (const Labelling& b_prime : targets) {
        const int bad = prop51_violation(problem, b, b_prime);
        const bool checker_passes = check_prop51(problem, b, b_prime).status == CheckResult::Pass;
        RC_ASSERT(checker_passes == (bad == -1));  // hsx's checker agrees with this file's
        if (!generic) {
          failed_non_generic = failed_non_generic || bad >= 0;
          continue;
        }
        if (bad >= 0) {
          const auto comps = sample_connectivity(problem, b).components;
          RC_LOG() << "island starting at patch " << comps[bad].patches.front() << " of halfspace "
                   << comps[bad].halfspace << "\n";
        }
        RC_ASSERT(bad == -1);
      }
    }
    RC_CLASSIFY(failed_non_generic, "Prop. 5.1 fails (not all crossings)");
  });
}

TEST_CASE("bsh property 6: Prop. 4.1 - one sample per boundary patch reproduces the boundary uniquely",
          "[bsh][property][prop41]") {
  rc::prop("random orientation-preserving boundary and the scene's optimum round-trip", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = complex_of(scene);
    const Problem plain(complex);
    std::vector<Labelling> labellings{random_op_labelling(plain)};
    labellings.push_back(best_first(plain).labelling);
    for (const Labelling& l : labellings) {
      const Complex sampled = one_sample_per_boundary_patch(complex, l);
      RC_ASSERT(check_complex(sampled).empty());
      const Problem problem(sampled);
      RC_ASSERT(sample_connectivity(problem, l).sample_connected());
      const ExtractResult r = best_first(problem);
      RC_ASSERT(r.labelling == l);
      RC_ASSERT(r.energy.missing_samples == 0);
      RC_ASSERT(r.ties.count == 1);
      RC_ASSERT(r.ties.certified);
      RC_ASSERT(r.optimal || curved(sampled));
      const BruteForceResult bf = oracle(problem, true);
      RC_ASSERT(bf.optimal.size() == 1u);
      RC_ASSERT(bf.optimal.front() == l);
      // hsx's checker: never Fail here (it may say Skipped where a coincident patch is used reversed; see
      // "bsh unit: two squares sharing an edge ...").
      RC_ASSERT(check_prop41(complex, l).status != CheckResult::Fail);
    }
  });
}

TEST_CASE("bsh property 7: permuting halfspaces or translating by an integer vector keeps the optimum",
          "[bsh][property][invariance]") {
  rc::prop("same optimal energy and area", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const int n = static_cast<int>(scene.halfspaces.size());
    const auto keys = *rc::gen::container<std::vector<int>>(n, rc::gen::inRange(0, 1000));
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return keys[a] < keys[b]; });
    const PointQ2 offset{Rational(*rc::gen::inRange(-5, 6)), Rational(*rc::gen::inRange(-5, 6))};
    const Complex c0 = complex_of(scene);
    const Problem p0(c0);
    const ExtractResult r0 = best_first(p0);
    std::vector<Labelling> optima0{r0.labelling};
    optima0.insert(optima0.end(), r0.tied.begin(), r0.tied.end());
    const bool arcs = curved(c0);
    struct Variant {
      Scene2 scene;
      bool translated;
    };
    for (const Variant& v : {Variant{permuted(scene, order), false}, Variant{translated(scene, offset), true}}) {
      const Complex c1 = complex_of(v.scene);
      const Problem p1(c1);
      const ExtractResult r1 = best_first(p1);
      RC_ASSERT(r1.energy.missing_samples == r0.energy.missing_samples);
      const Order e = compare(r1.energy.measure(), r0.energy.measure());
      RC_ASSERT(e != Order::Less);
      RC_ASSERT(e != Order::Greater);
      if (e == Order::Tie) {
        // Arc terms are keyed by position: a translation may leave them unseparated. A permutation keeps the
        // keys, so a Tie there needs an unseparated tie between optima.
        RC_ASSERT(arcs);
        if (!v.translated) RC_ASSERT(!unique_proven(r0) || !unique_proven(r1));
      }
      // The area of the optimum, or of one of the optima when there are ties.
      bool area_matches = false;
      for (const Labelling& l : optima0) {
        const Order a = compare(inside_measure(c1, r1.labelling), inside_measure(c0, l));
        area_matches = area_matches || a == Order::Equal || (a == Order::Tie && arcs);
      }
      if (r0.ties.checked && !r0.ties.capped) RC_ASSERT(area_matches);
    }
  });
}

TEST_CASE("bsh property 8: beam K=1 is admissible and never below the optimum (rate recorded)",
          "[bsh][property][beam]") {
  rc::prop("beam K=1 result is orientation-preserving, sample-connected, energy >= optimum", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    const BruteForceResult bf = oracle(problem, true);
    ExtractOptions o;
    o.method = Method::Beam;
    o.beam_width = 1;
    const ExtractResult beam = extract(problem, o);
    RC_ASSERT(beam.stopped_by.empty());
    RC_ASSERT(is_orientation_preserving(problem, beam.labelling));
    RC_ASSERT(beam.sample_connected);
    RC_ASSERT(sample_connectivity(problem, beam.labelling).sample_connected());
    const Order order = compare(beam.energy, bf.energy);
    RC_ASSERT(order != Order::Less);
    if (beam.optimal) RC_ASSERT(order == Order::Equal);
    ++g_beam_cases;
    if (order != Order::Greater) ++g_beam_optimal;
    RC_CLASSIFY(order == Order::Greater, "beam sub-optimal");
    // Wider beams are admissible too.
    o.beam_width = 3;
    const ExtractResult wide = extract(problem, o);
    RC_ASSERT(wide.sample_connected);
    RC_ASSERT(compare(wide.energy, bf.energy) != Order::Less);
  });
  std::cout << "beam K=1 optimal (energy equal to brute force) in " << g_beam_optimal << " of " << g_beam_cases
            << " random scenes" << (g_beam_cases ? " (" + std::to_string(100 * g_beam_optimal / g_beam_cases) + "%)" : "")
            << "\n";
}

TEST_CASE("bsh property 9: junction parity, and 0 or 2 boundary ends at transversal crossings (Section 3.1)",
          "[bsh][property][manifold]") {
  rc::prop("every labelling has even ends at every junction; orientation-preserving ones 0 or 2 at crossings", [] {
    const Scene2 scene = *gen_scene(small_scenes());
    const Complex complex = complex_of(scene);
    const Problem problem(complex);
    const Labelling l = random_op_labelling(problem);
    const Labelling any = random_labelling(problem.cell_count());
    for (const Labelling& x : {l, any}) {
      Labelling y = x;
      for (int k = 0; k < problem.cell_count(); ++k)
        if (complex.cells[k].outer) y[k] = 0;  // parity needs only the outer cells outside
      for (const auto& [j, n] : boundary_ends(problem, y)) RC_ASSERT(n % 2 == 0);
      RC_ASSERT(check_manifold_parity(problem, y).status == CheckResult::Pass);
    }
    const auto ends = boundary_ends(problem, l);
    const auto crossings = crossing_junctions(problem);
    RC_CLASSIFY(!crossings.empty(), "has crossings");
    for (int j : crossings) {
      const auto it = ends.find(j);
      RC_ASSERT((it == ends.end() || it->second == 2));
    }
  });
}
