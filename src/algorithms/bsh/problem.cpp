#include <hsx/algorithms/bsh/problem.hpp>

#include "algorithms/bsh/problem_memo.hpp"
#include "algorithms/bsh/support_lists.hpp"

#include "geometry/components.hpp"

#include <algorithm>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>

namespace hsx::bsh {

struct Energy::Value {
  std::shared_ptr<const Problem::SupportAtoms> atoms;  // null: `sum` is given
  std::vector<int> supports;                           // ascending, indices into atoms
  mutable std::once_flag once;
  mutable Measure sum;
};

Energy::Energy(long missing, Measure measure) : missing_samples(missing) {
  if (measure.is_zero()) return;
  auto v = std::make_shared<Value>();
  v->sum = std::move(measure);
  value_ = std::move(v);
}

const Measure& Energy::measure() const {
  static const Measure zero;
  if (!value_) return zero;
  if (value_->atoms)
    std::call_once(value_->once, [v = value_.get()] {
      for (int g : v->supports) v->sum += v->atoms->measures[g];
    });
  return value_->sum;
}

namespace {

/// Sign of |a| - |b| for two support lists of one problem: the supports in only one of them, enclosed by the
/// kernel's certified double combination, then summed exactly when that does not decide (that sign remembered per
/// problem and thread: a search meets the same few unseparated differences in thousands of comparisons). nullopt:
/// not separated. (No allocation on the common path: best-first and the beam compare energies millions of times.)
std::optional<int> support_difference_sign(const std::shared_ptr<const Problem::SupportAtoms>& atoms,
                                           const std::vector<int>& a, const std::vector<int>& b,
                                           const CompareOptions& options) {
  DoubleCombination bounds;
  bool differ = false;
  for_each_difference(a, b, [&](int g, long k) {
    differ = true;
    bounds.add(k, DoubleBounds{atoms->enclosures[g].first, atoms->enclosures[g].second});
  });
  if (!differ) return 0;
  if (const int s = bounds.bounds().certain_sign()) return s;
  SignMemo::Combination difference;
  for_each_difference(a, b, [&](int g, long k) { difference.emplace_back(g, k); });
  thread_local ProblemMemo<SignMemo> memo;
  return memo.of(atoms).sign(difference, options, [&] {
    Measure d;
    for (const auto& [g, k] : difference) {
      if (k > 0) {
        d += atoms->measures[g];
      } else {
        d -= atoms->measures[g];
      }
    }
    return d.sign(options);
  });
}

/// [lo, hi] of `enclosure` times 2^-scale as doubles, rounded outward (mpfr_mul_2si is exact unless it
/// underflows; an end above the largest double becomes +-inf, below it is kept).
std::pair<double, double> scaled_doubles(const Interval& enclosure, long scale) {
  mpfr_t x;
  mpfr_init2(x, enclosure.precision());
  mpfr_mul_2si(x, enclosure.lo(), -scale, MPFR_RNDD);
  const double lo = mpfr_get_d(x, MPFR_RNDD);
  mpfr_mul_2si(x, enclosure.hi(), -scale, MPFR_RNDU);
  const double hi = mpfr_get_d(x, MPFR_RNDU);
  mpfr_clear(x);
  return {lo, hi};
}

}  // namespace

std::pair<double, double> Problem::scaled_enclosure(const Measure& measure) const {
  return scaled_doubles(measure.enclose(64), atoms_->scale);
}

Order compare(const Energy& a, const Energy& b, const CompareOptions& options) {
  if (a.missing_samples != b.missing_samples)
    return a.missing_samples < b.missing_samples ? Order::Less : Order::Greater;
  if (a.value_ && b.value_ && a.value_->atoms && a.value_->atoms == b.value_->atoms) {
    const std::optional<int> s = support_difference_sign(a.value_->atoms, a.value_->supports, b.value_->supports, options);
    if (!s) return Order::Tie;
    return *s < 0 ? Order::Less : (*s > 0 ? Order::Greater : Order::Equal);
  }
  return hsx::compare(a.measure(), b.measure(), options);
}

Problem::Problem(const Complex& complex) : complex_(complex) {
  supports_.resize(complex.supports.size());
  auto atoms = std::make_shared<SupportAtoms>();
  for (std::size_t g = 0; g < complex.supports.size(); ++g) {
    SupportTerm& term = supports_[g];
    term.patches = complex.supports[g];
    const Patch& first = complex.patches.at(term.patches.at(0));
    term.cell_a = first.inside_cell;
    term.cell_b = first.outside_cell;
    bool sampled_a = false, sampled_b = false;
    for (int p : term.patches) {
      const Patch& patch = complex.patches[p];
      term.samples += static_cast<long>(patch.samples.size());
      const bool a_inside = patch.inside_cell == term.cell_a;
      (a_inside ? term.allow_a_inside : term.allow_b_inside) = true;
      if (!patch.samples.empty()) (a_inside ? sampled_a : sampled_b) = true;
    }
    if (sampled_b) term.allow_a_inside = false;
    if (sampled_a) term.allow_b_inside = false;
    term.measure = first.measure;
    atoms->measures.push_back(term.measure);
    total_samples_ += term.samples;
  }
  // The enclosures at 64 bits, then the common scale that brings the largest to at most 2^512, then the doubles.
  std::vector<Interval> enclosures;
  enclosures.reserve(atoms->measures.size());
  for (const Measure& m : atoms->measures) {
    enclosures.push_back(m.enclose(64));
    const mpfr_t& hi = enclosures.back().hi();
    if (mpfr_inf_p(hi) || mpfr_nan_p(hi))
      throw std::logic_error("problem: a support's measure has no finite enclosure");
    if (mpfr_regular_p(hi)) atoms->scale = std::max(atoms->scale, static_cast<long>(mpfr_get_exp(hi)) - 512);
  }
  for (const Interval& e : enclosures) atoms->enclosures.push_back(scaled_doubles(e, atoms->scale));
  atoms_ = std::move(atoms);
  support_neighbours_.resize(supports_.size());
  for (const Junction& j : complex.junctions) {
    std::vector<int> groups;
    for (int p : j.patches) groups.push_back(complex.patches[p].support);
    std::sort(groups.begin(), groups.end());
    groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
    for (int g : groups)
      for (int h : groups)
        if (g != h) support_neighbours_[g].push_back(h);
  }
  for (auto& list : support_neighbours_) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  for (int j = 0; j < static_cast<int>(complex.junctions.size()); ++j) {
    std::map<int, int> ends;  // support -> patch ends at j
    std::set<int> cells;
    bool usable = false;
    for (int p : complex.junctions[j].patches) {
      const Patch& patch = complex.patches[p];
      if (supports_[patch.support].patches.front() != p) continue;  // one patch per support
      ends[patch.support] += static_cast<int>(std::count(patch.junctions.begin(), patch.junctions.end(), j));
      cells.insert(patch.inside_cell);
      cells.insert(patch.outside_cell);
      usable = usable || !complex.cells[patch.inside_cell].outer || !complex.cells[patch.outside_cell].outer;
    }
    if (!usable) continue;
    // Group supports into boundaries: supports of one halfspace meeting here continue that boundary.
    std::map<int, int> ends_per_boundary;  // smallest halfspace of the support -> ends
    for (const auto& [g, count] : ends) {
      int h = complex.halfspace_count();
      for (int p : supports_[g].patches) h = std::min(h, complex.patches[p].halfspace);
      ends_per_boundary[h] += count;
    }
    bool generic = ends_per_boundary.size() == 2 && cells.size() == 4;
    for (const auto& [h, count] : ends_per_boundary) generic = generic && count == 2;
    if (generic) {
      // A crossing shows all four inside/outside combinations of the two boundaries around it; a tangency or two
      // corners touching at a point do not.
      const int h1 = ends_per_boundary.begin()->first, h2 = std::next(ends_per_boundary.begin())->first;
      std::set<std::pair<int, int>> combos;
      for (int k : cells) combos.insert({complex.cells[k].inside[h1], complex.cells[k].inside[h2]});
      generic = combos.size() == 4;
    }
    if (!generic) non_generic_junctions_.push_back(j);
  }
}

std::vector<int> boundary_supports(const Problem& problem, const Labelling& labelling) {
  // Counted first: the list is allocated once, at its size (every state of a search keeps one in its energy).
  std::size_t count = 0;
  for_each_boundary_support(problem, labelling, [&](int) { ++count; });
  std::vector<int> out;
  out.reserve(count);
  for_each_boundary_support(problem, labelling, [&](int g) { out.push_back(g); });
  return out;
}

std::vector<char> boundary_support_flags(const Problem& problem, const Labelling& labelling) {
  std::vector<char> on_b(static_cast<std::size_t>(problem.support_count()), 0);
  for_each_boundary_support(problem, labelling, [&](int g) { on_b[static_cast<std::size_t>(g)] = 1; });
  return on_b;
}

bool is_orientation_preserving(const Problem& problem, const Labelling& labelling, std::string* why) {
  const Complex& c = problem.complex();
  for (int k = 0; k < problem.cell_count(); ++k)
    if (c.cells[k].outer && labelling[k]) {
      if (why) *why = "outer cell " + std::to_string(k) + " is labelled inside";
      return false;
    }
  for (int g : boundary_supports(problem, labelling)) {
    const SupportTerm& s = problem.supports()[g];
    if (!s.allows(labelling[s.cell_a] ? s.cell_a : s.cell_b)) {
      if (why)
        *why = "patch " + std::to_string(s.patches.front()) + " (" +
               c.halfspace_names[c.patches[s.patches.front()].halfspace] +
               ") is on the boundary with an orientation none of its (sampled) halfspaces has";
      return false;
    }
  }
  return true;
}

Energy energy(const Problem& problem, const Labelling& labelling) {
  Energy e;
  e.missing_samples = problem.total_samples();
  auto value = std::make_shared<Energy::Value>();
  value->atoms = problem.support_atoms();
  value->supports = boundary_supports(problem, labelling);
  for (int g : value->supports) {
    for (int p : problem.supports()[g].patches) {
      const Patch& patch = problem.complex().patches[p];
      if (labelling[patch.inside_cell]) e.missing_samples -= static_cast<long>(patch.samples.size());
    }
  }
  if (!value->supports.empty()) e.value_ = std::move(value);
  return e;
}

namespace {

/// The pairs of patches of one halfspace that share a junction (each pair once per junction, in junction order):
/// the only pairs Def. 3.2 may join, the same for every boundary of a problem (kept per problem and thread).
struct SameHalfspacePairs {
  std::vector<std::pair<int, int>> pairs;

  SameHalfspacePairs() = default;
  explicit SameHalfspacePairs(const Problem& problem) {
    const Complex& c = problem.complex();
    for (const Junction& j : c.junctions)
      for (std::size_t a = 0; a < j.patches.size(); ++a)
        for (std::size_t b = a + 1; b < j.patches.size(); ++b) {
          const int p = j.patches[a], q = j.patches[b];
          if (c.patches[p].halfspace == c.patches[q].halfspace) pairs.emplace_back(p, q);
        }
  }
};

/// The patches on b of a labelling, joined into the components of Def. 3.2 (patches of one halfspace on b that
/// share a junction). Per-thread scratch, refilled by each call of boundary_components: a search tests thousands
/// of boundaries.
struct BoundaryComponents {
  std::vector<char> on_b;     ///< per patch: on b (its support on b with its halfspace's orientation)
  ReusableDisjointSets sets;  ///< over the patches

  /// The representative of patch p's component.
  int find(int p) { return sets.find_set(p); }
};

BoundaryComponents& boundary_components(const Problem& problem, const Labelling& labelling) {
  thread_local BoundaryComponents scratch;
  const Complex& c = problem.complex();
  const int patches = static_cast<int>(c.patches.size());
  scratch.on_b.assign(patches, 0);
  for_each_boundary_support(problem, labelling, [&](int g) {
    for (int p : problem.supports()[g].patches) scratch.on_b[p] = labelling[c.patches[p].inside_cell];
  });
  scratch.sets.reset(patches);
  thread_local ProblemMemo<SameHalfspacePairs> memo;
  for (const auto& [p, q] : memo.of(problem).pairs)
    if (scratch.on_b[p] && scratch.on_b[q]) scratch.sets.union_set(p, q);
  return scratch;
}

}  // namespace

SampleConnectivity sample_connectivity(const Problem& problem, const Labelling& labelling) {
  const Complex& c = problem.complex();
  BoundaryComponents& b = boundary_components(problem, labelling);
  thread_local std::vector<int> slot;  // per representative: its component's index in `out`, -1 before
  slot.assign(c.patches.size(), -1);
  SampleConnectivity out;
  // Patches ascending: components appear in order of their smallest patch, each with its patches ascending.
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) {
    if (!b.on_b[p]) continue;
    int& s = slot[b.find(p)];
    if (s < 0) {
      s = static_cast<int>(out.components.size());
      out.components.emplace_back();
      out.components.back().halfspace = c.patches[p].halfspace;
    }
    Component& comp = out.components[s];
    comp.patches.push_back(p);
    comp.has_sample = comp.has_sample || !c.patches[p].samples.empty();
  }
  // Ordered by halfspace, then smallest patch (the order above, kept by a stable sort).
  std::stable_sort(out.components.begin(), out.components.end(),
                   [](const Component& x, const Component& y) { return x.halfspace < y.halfspace; });
  for (std::size_t k = 0; k < out.components.size(); ++k)
    if (!out.components[k].has_sample) out.islands.push_back(static_cast<int>(k));
  return out;
}

bool is_sample_connected(const Problem& problem, const Labelling& labelling) {
  const Complex& c = problem.complex();
  BoundaryComponents& b = boundary_components(problem, labelling);
  thread_local std::vector<char> sampled;  // per representative: its component holds a sample
  sampled.assign(c.patches.size(), 0);
  for (std::size_t p = 0; p < c.patches.size(); ++p)
    if (b.on_b[p] && !c.patches[p].samples.empty()) sampled[b.find(static_cast<int>(p))] = 1;
  for (std::size_t p = 0; p < c.patches.size(); ++p)
    if (b.on_b[p] && !sampled[b.find(static_cast<int>(p))]) return false;
  return true;
}

std::vector<std::vector<int>> removable_sets(const Problem& problem, const Labelling& labelling,
                                             const SampleConnectivity& connectivity) {
  const Complex& c = problem.complex();
  const std::vector<char> on_b = boundary_support_flags(problem, labelling);
  std::set<std::vector<int>> seen;
  std::vector<std::vector<int>> out;
  auto add = [&](std::vector<int> set) {
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
    if (seen.insert(set).second) out.push_back(std::move(set));
  };
  for (int island : connectivity.islands) {
    std::vector<int> island_supports;
    for (int p : connectivity.components[island].patches) island_supports.push_back(c.patches[p].support);
    std::sort(island_supports.begin(), island_supports.end());
    island_supports.erase(std::unique(island_supports.begin(), island_supports.end()), island_supports.end());
    add(island_supports);
    std::set<int> adjacent;
    for (int g : island_supports)
      for (int h : problem.support_neighbours()[g])
        if (on_b[h] && !std::binary_search(island_supports.begin(), island_supports.end(), h)) adjacent.insert(h);
    for (int h : adjacent) add({h});
  }
  return out;
}

Measure inside_measure(const Complex& complex, const Labelling& labelling) {
  Measure total;
  for (std::size_t k = 0; k < complex.cells.size(); ++k)
    if (labelling[k]) total += complex.cells[k].measure;
  return total;
}

}  // namespace hsx::bsh
