#include <hsx/algorithms/bsh/samples.hpp>

#include <algorithm>
#include <limits>

namespace hsx::bsh {

Complex with_samples_on(const Complex& complex, const std::vector<int>& patches) {
  Complex c = complex;
  c.samples.clear();
  for (Patch& p : c.patches) p.samples.clear();
  for (int p : patches) {
    c.patches.at(p).samples.push_back(static_cast<int>(c.samples.size()));
    c.samples.push_back({c.patches[p].halfspace, p});
  }
  return c;
}

namespace {

/// The central patch of a component (see the header). Distances are Measures compared with certified compare.
int central_patch(const Complex& c, const std::vector<int>& component, const CompareOptions& compare_options) {
  if (component.size() == 1) return component.front();
  const int n = static_cast<int>(component.size());
  std::vector<std::vector<int>> adjacent(n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      if (a == b) continue;
      const auto& ja = c.patches[component[a]].junctions;
      const auto& jb = c.patches[component[b]].junctions;
      for (int j : ja)
        if (std::find(jb.begin(), jb.end(), j) != jb.end()) {
          adjacent[a].push_back(b);
          break;
        }
    }
  // Dijkstra from every patch (components are small); edge a-b costs (|a| + |b|) / 2 in 2D, 1 in 3D.
  const auto cost = [&](int a, int b) {
    if (c.dimension == 3) return Measure(Rational(1));
    return (c.patches[component[a]].measure.get() + c.patches[component[b]].measure.get()) * Rational(1, 2);
  };
  int best = -1;
  Measure best_radius;
  for (int s = 0; s < n; ++s) {
    std::vector<std::optional<Measure>> dist(n);
    std::vector<char> done(n, 0);
    dist[s] = Measure();
    for (int round = 0; round < n; ++round) {
      int u = -1;
      for (int v = 0; v < n; ++v)
        if (!done[v] && dist[v] && (u < 0 || compare(*dist[v], *dist[u], compare_options) == Order::Less)) u = v;
      if (u < 0) break;
      done[u] = 1;
      for (int v : adjacent[u]) {
        Measure d = *dist[u] + cost(u, v);
        if (!dist[v] || compare(d, *dist[v], compare_options) == Order::Less) dist[v] = d;
      }
    }
    Measure radius;
    for (int v = 0; v < n; ++v)
      if (dist[v] && compare(*dist[v], radius, compare_options) == Order::Greater) radius = *dist[v];
    if (best < 0 || compare(radius, best_radius, compare_options) == Order::Less) {
      best = s;
      best_radius = radius;
    }
  }
  return component[best];
}

ExtractResult run(const Complex& sampled, const SampleGenOptions& options, Method method, long max_states = 0) {
  const Problem problem(sampled);
  ExtractOptions extract_options;
  extract_options.method = method;
  extract_options.max_states = max_states;
  extract_options.beam_width = options.beam_width;
  extract_options.enumerate_ties = false;
  extract_options.compare = options.compare;
  if (options.max_states > 0 && (max_states == 0 || options.max_states < max_states))
    extract_options.max_states = options.max_states;
  extract_options.max_graph_cuts = options.max_graph_cuts;
  extract_options.cancel = options.cancel;
  return extract(problem, extract_options);
}

/// Fig. 12's next sample: the largest patch of b \ b' (b: `target`'s boundary, b': `found`'s; both labellings of
/// `problem`) that holds no sample yet (not in `sampled`), among the patches b runs along with their halfspace's
/// orientation (a sample on a coincident patch used reversed would forbid the target's own orientation,
/// problem.hpp); the first of equally large ones. -1 when there is none.
int largest_unsampled_patch(const Problem& problem, const Labelling& target, const Labelling& found,
                            const std::vector<int>& sampled, const CompareOptions& compare_options) {
  const Complex& complex = problem.complex();
  const std::vector<char> on_found = boundary_support_flags(problem, found);
  int pick = -1;
  for (int g : boundary_supports(problem, target)) {
    if (on_found[static_cast<std::size_t>(g)]) continue;
    for (int p : problem.supports()[g].patches) {
      if (std::find(sampled.begin(), sampled.end(), p) != sampled.end()) continue;
      if (!target[complex.patches[p].inside_cell] || target[complex.patches[p].outside_cell]) continue;
      if (pick < 0 ||
          compare(complex.patches[p].measure, complex.patches[pick].measure, compare_options) == Order::Greater)
        pick = p;
    }
  }
  return pick;
}

}  // namespace

std::vector<int> initial_samples(const Complex& complex, const Labelling& target, const CompareOptions& compare) {
  const Problem problem(complex);
  std::vector<int> out;
  for (const Component& comp : sample_connectivity(problem, target).components)
    out.push_back(central_patch(complex, comp.patches, compare));
  return out;
}

SampleGenResult generate_samples(const Complex& complex, const Labelling& target, const SampleGenOptions& options) {
  SampleGenResult result;
  const Problem target_problem(complex);
  result.sample_patches = initial_samples(complex, target, options.compare);
  result.initial = static_cast<int>(result.sample_patches.size());
  for (int g : boundary_supports(target_problem, target))
    result.upper_bound += static_cast<int>(target_problem.supports()[g].patches.size());
  for (;;) {
    const Complex sampled = with_samples_on(complex, result.sample_patches);
    ExtractResult found = run(sampled, options, options.search);
    ++result.rounds;
    if (!found.stopped_by.empty()) {
      result.stopped_by = found.stopped_by;
      return result;
    }
    if (found.labelling == target) {
      result.reproduced = true;
      return result;
    }
    int pick = largest_unsampled_patch(target_problem, target, found.labelling, result.sample_patches, options.compare);
    if (pick < 0 && options.search != Method::BestFirst && options.fallback_states > 0) {
      // Every patch of b \ b' has a sample, so the target covers more samples than b': the search missed the
      // optimum. Redo this round with the complete search.
      const Problem sampled_problem(sampled);
      if (compare(energy(sampled_problem, target), found.energy, options.compare) == Order::Less) {
        ++result.fallbacks;
        found = run(sampled, options, Method::BestFirst, options.fallback_states);
        if (!found.stopped_by.empty() && found.stopped_by != "max-states") {
          result.stopped_by = found.stopped_by;
          return result;
        }
        if (found.labelling == target) {
          result.reproduced = true;
          return result;
        }
        pick = largest_unsampled_patch(target_problem, target, found.labelling, result.sample_patches, options.compare);
      }
    }
    if (pick < 0) {
      // Section 6.2's sufficient set: one sample on every patch that b runs along with its halfspace's
      // orientation. The target then covers every sample and any other admissible boundary misses one or is
      // longer, so the root graph cut already returns it.
      std::vector<int> all;
      for (int p = 0; p < static_cast<int>(complex.patches.size()); ++p)
        if (target[complex.patches[p].inside_cell] && !target[complex.patches[p].outside_cell]) all.push_back(p);
      const ExtractResult last = run(with_samples_on(complex, all), options, options.search);
      ++result.rounds;
      if (!last.stopped_by.empty()) {
        result.stopped_by = last.stopped_by;
        return result;
      }
      result.used_sufficient_set = true;
      result.sample_patches = all;
      result.reproduced = last.labelling == target;
      if (!result.reproduced)
        result.failure = "no sample-free patch in b \\ b', and one sample per patch does not reproduce b either";
      return result;
    }
    result.sample_patches.push_back(pick);
    if (result.rounds > result.upper_bound + 1) {
      result.failure = "more rounds than boundary patches";
      return result;
    }
  }
}

int minimum_samples(const Complex& complex, const Labelling& target, int max_patches, long max_subsets) {
  const Problem problem(complex);
  std::vector<int> patches;
  for (int g : boundary_supports(problem, target))
    for (int p : problem.supports()[g].patches) patches.push_back(p);
  const int n = static_cast<int>(patches.size());
  if (n > max_patches) return -1;
  const int lower = static_cast<int>(sample_connectivity(problem, target).components.size());
  long tried = 0;
  SampleGenOptions best_first;
  best_first.search = Method::BestFirst;
  for (int k = lower; k <= n; ++k) {
    // Subsets of size k in lexicographic order.
    std::vector<int> pick(k);
    for (int i = 0; i < k; ++i) pick[i] = i;
    for (;;) {
      if (++tried > max_subsets) return -1;
      std::vector<int> chosen;
      for (int i : pick) chosen.push_back(patches[i]);
      const ExtractResult r = run(with_samples_on(complex, chosen), best_first, Method::BestFirst);
      if (r.labelling == target) return k;
      int i = k - 1;
      while (i >= 0 && pick[i] == n - k + i) --i;
      if (i < 0) break;
      ++pick[i];
      for (int j = i + 1; j < k; ++j) pick[j] = pick[j - 1] + 1;
    }
  }
  return n;
}

}  // namespace hsx::bsh
