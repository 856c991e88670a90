// Reproducible random numbers: the one random number source of the library's generators (random scenes,
// geometry/random_scene.hpp; random CSG solids, algorithms/csg/random_solid.hpp).
//
// Conventions (owned here):
// - The engine is std::mt19937_64, whose output sequence the C++ standard fixes for a given seed. No std
//   distribution is used (their output is implementation-defined); every draw below is specified exactly, so a
//   result is reproducible on every machine and standard library from its seed.
// - Item `index` of a stream with seed `seed` (scene k of seed s, solid i of `hsx nhsurvey --seed S`) uses the
//   engine seeded with item_seed(seed, index) = splitmix64(seed + index) (mod 2^64): any item can be reproduced
//   alone, without drawing the ones before it.
// - Probabilities are whole percents (0..100), drawn exactly (Random::percent).
#pragma once

#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

namespace hsx {

/// splitmix64's output function (Steele, Lea, Flood 2014): x += 0x9e3779b97f4a7c15, then
/// x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9, x = (x ^ (x >> 27)) * 0x94d049bb133111eb, x ^ (x >> 31), mod 2^64.
std::uint64_t splitmix64(std::uint64_t x);

/// The engine seed of item `index` of stream `seed`: splitmix64(seed + index), the sum mod 2^64.
std::uint64_t item_seed(std::uint64_t seed, std::uint64_t index);

/// A std::mt19937_64 with exactly specified integer draws.
class Random {
 public:
  /// The engine seeded with `seed` (std::mt19937_64(seed)).
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  /// The engine's next 64-bit output.
  std::uint64_t next() { return engine_(); }

  /// Uniform integer in [lo, hi] (both included): with n = hi - lo + 1 and L = (2^64 - 1) - (2^64 - 1) mod n,
  /// draws x = next() until x < L, then returns lo + x mod n (rejection: no modulo bias). One draw when n == 1
  /// is still consumed. Throws std::invalid_argument when lo > hi.
  long in(long lo, long hi);

  /// True with probability p/100: in(0, 99) < p. Throws std::invalid_argument unless 0 <= p <= 100.
  bool percent(int p);

  /// True with probability 1/n: in(0, n - 1) == n - 1. Throws std::invalid_argument when n < 1.
  bool one_in(long n) { return in(0, n - 1) == n - 1; }

  /// Index in [0, size) drawn by in(0, size - 1). Throws std::invalid_argument when size == 0.
  std::size_t index(std::size_t size) {
    if (size == 0) throw std::invalid_argument("Random::index: empty range");
    return static_cast<std::size_t>(in(0, static_cast<long>(size) - 1));
  }

  /// An element of `items` drawn by index(items.size()). Throws std::invalid_argument when `items` is empty.
  template <class T>
  const T& pick(const std::vector<T>& items) {
    return items[index(items.size())];
  }

  /// Index k in [0, weights.size()) with probability weights[k] / sum (weights >= 0, sum > 0): r = in(0, sum - 1),
  /// the first k whose running sum exceeds r. Throws std::invalid_argument for a negative weight or a zero sum.
  std::size_t weighted(const std::vector<int>& weights);

 private:
  std::mt19937_64 engine_;
};

}  // namespace hsx
