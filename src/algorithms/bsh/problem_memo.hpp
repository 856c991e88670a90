// Internal to the BSH algorithms: values made from one problem's supports, kept per thread so that the many graph
// cuts and energy comparisons of one search do not recompute them.
#pragma once

#include <hsx/algorithms/bsh/problem.hpp>

#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace hsx::bsh {

/// A value made from a problem, kept per thread (make the memo `thread_local`) for the last problem this thread
/// asked about, keyed by its support atoms (held, so that their address is not reused while the value is kept).
template <class T>
class ProblemMemo {
 public:
  /// The value for `problem`, made by T(problem) when this thread last asked about another problem.
  T& of(const Problem& problem) { return of(problem.support_atoms(), [&] { return T(problem); }); }
  /// The value for the problem whose support atoms are `atoms`, made by T() when they changed.
  T& of(const std::shared_ptr<const Problem::SupportAtoms>& atoms) {
    return of(atoms, [] { return T(); });
  }

 private:
  template <class Make>
  T& of(const std::shared_ptr<const Problem::SupportAtoms>& atoms, Make make) {
    if (atoms_ != atoms) {
      value_ = make();
      atoms_ = atoms;
    }
    return value_;
  }

  std::shared_ptr<const Problem::SupportAtoms> atoms_;
  T value_;
};

/// Exact signs decided for integer combinations sum k_g * |g| of one problem's support measures, keyed by the
/// combination ((support, k) pairs, ascending support, no zero k): a search meets the same few combinations that
/// its certified doubles do not separate (mostly exact zeros, the costliest to decide: MPFR enclosures up to the
/// precision cap) in many graph cuts and comparisons. A sign depends only on the combination and the precision
/// options, so remembering it changes no answer. Bounded: cleared when full.
class SignMemo {
 public:
  using Combination = std::vector<std::pair<int, long>>;

  SignMemo() = default;
  explicit SignMemo(const Problem&) {}

  /// The sign of `combination` under `options` (nullopt: not separated at the cap), computed by `decide()` the
  /// first time it is asked.
  template <class Decide>
  std::optional<int> sign(const Combination& combination, const CompareOptions& options, Decide decide) {
    constexpr std::size_t kLimit = 1 << 12;
    if (options.start_bits != options_.start_bits || options.max_bits != options_.max_bits) {
      signs_.clear();
      options_ = options;
    }
    if (signs_.size() >= kLimit) signs_.clear();
    if (const auto known = signs_.find(combination); known != signs_.end()) return known->second;
    const std::optional<int> s = decide();
    signs_.emplace(combination, s);
    return s;
  }

 private:
  CompareOptions options_;
  std::map<Combination, std::optional<int>> signs_;
};

}  // namespace hsx::bsh
