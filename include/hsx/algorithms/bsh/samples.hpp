// GENERATE-SAMPLES (BSH paper, Section 6.2, Fig. 12) on the complex: which patches need a sample so that a target
// boundary is the BSH shape. Positions on those patches are the geometry layer's business
// (geometry/planar_points.hpp); here a sample is "a sample on patch p".
//
// Initial samples: one per connected component of b ∩ b_i, on the component's central patch: the patch whose
// farthest patch of the component is nearest (ties to the lowest index). This is hsx's exact stand-in for the
// paper's geodesic centre. Distances run along the component from patch to patch across shared junctions:
// - 2D: between patch midpoints (half of each end patch plus the patches in between), compared exactly
//   (certified);
// - 3D: the graph distance (one per junction crossed), since an area is no length; on a triangulated patch this
//   is the patch-level analogue of "the vertex minimising the maximum graph distance along the surface". The
//   sample point on the chosen patch is the centroid of its largest triangle (sample_scene.hpp): exact, rational
//   and strictly inside the patch, never on an arrangement edge.
// Each round: extract with the current samples; stop when it returns the target; otherwise add a sample on the
// largest sample-free patch of b \ b' (largest measure, ties to the lowest index).
#pragma once

#include <hsx/algorithms/bsh/extract.hpp>

#include <functional>
#include <string>
#include <vector>

namespace hsx::bsh {

struct SampleGenOptions {
  Method search = Method::Beam;  ///< Beam (K = beam_width) or BestFirst
  int beam_width = 1;
  CompareOptions compare;
  /// When the search returns a boundary provably worse than the target although every patch of b \ b' has a
  /// sample (the search missed the optimum: beam incompleteness, or Prop. 5.1 failing at non-generic junctions),
  /// redo that round with best-first limited to this many states (0: report the failure instead).
  long fallback_states = 300;
  /// Limits of every extraction (ExtractOptions'; 0 / empty: none). A round a limit stops ends the run with
  /// SampleGenResult::stopped_by set (neither reproduced nor a failure).
  long max_states = 0;
  long max_graph_cuts = 0;
  std::function<bool()> cancel;
};

struct SampleGenResult {
  std::vector<int> sample_patches;  ///< one sample per listed patch, in the order added
  int initial = 0;                  ///< initial samples = components of b ∩ b_i (the lower bound)
  int upper_bound = 0;              ///< patches on the target boundary (Prop. 4.1's sufficient set)
  int rounds = 0;                   ///< extractions run
  bool reproduced = false;          ///< the last extraction returned the target
  int fallbacks = 0;                ///< rounds redone with best-first (see SampleGenOptions::fallback_states)
  /// The greedy rounds failed (the search missed the optimum even with best-first: Prop. 5.1 fails at
  /// non-generic junctions) and the samples are Section 6.2's sufficient set: one on every patch of b.
  bool used_sufficient_set = false;
  std::string failure;              ///< why not reproduced (e.g. no sample-free patch left: a counterexample)
  /// The limit that stopped a round's extraction ("max-states", "max-graph-cuts", "cancelled"; ExtractResult's
  /// stopped_by); "" when no limit was reached. When set, `reproduced` is false and `failure` empty.
  std::string stopped_by;
};

/// GENERATE-SAMPLES' initial samples (the header comment): one patch per connected component of b ∩ b_i, in the
/// order of sample_connectivity's components. `target`: a labelling of `complex`'s cells (its samples ignored).
std::vector<int> initial_samples(const Complex& complex, const Labelling& target, const CompareOptions& compare = {});

/// `target`: an orientation-preserving labelling of `complex`'s cells. The complex's own samples are ignored.
SampleGenResult generate_samples(const Complex& complex, const Labelling& target, const SampleGenOptions& options);

/// The complex with its samples replaced by one sample on each listed patch (in order).
Complex with_samples_on(const Complex& complex, const std::vector<int>& patches);

/// The smallest number of samples (one per chosen boundary patch) that reproduces `target` under best-first,
/// found by trying subsets of the boundary's patches by increasing size, starting at the lower bound.
/// Returns -1 when the boundary has more than `max_patches` patches or more than `max_subsets` subsets would be
/// tried.
int minimum_samples(const Complex& complex, const Labelling& target, int max_patches = 14, long max_subsets = 20000);

}  // namespace hsx::bsh
