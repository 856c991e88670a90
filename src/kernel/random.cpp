// Reproducible random numbers: see random.hpp.
#include <hsx/kernel/random.hpp>

#include <limits>

namespace hsx {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::uint64_t item_seed(std::uint64_t seed, std::uint64_t index) { return splitmix64(seed + index); }

long Random::in(long lo, long hi) {
  if (lo > hi) throw std::invalid_argument("Random::in: empty range");
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t n = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo) + 1;
  if (n == 0) return static_cast<long>(next());  // the whole range of long
  const std::uint64_t limit = kMax - kMax % n;
  std::uint64_t x;
  do x = next(); while (x >= limit);
  return static_cast<long>(static_cast<std::uint64_t>(lo) + x % n);
}

bool Random::percent(int p) {
  if (p < 0 || p > 100) throw std::invalid_argument("Random::percent: p must be in [0, 100]");
  return in(0, 99) < p;
}

std::size_t Random::weighted(const std::vector<int>& weights) {
  long sum = 0;
  for (int w : weights) {
    if (w < 0) throw std::invalid_argument("Random::weighted: negative weight");
    sum += w;
  }
  if (sum == 0) throw std::invalid_argument("Random::weighted: the weights sum to 0");
  long r = in(0, sum - 1);
  for (std::size_t k = 0; k < weights.size(); ++k) {
    if (r < weights[k]) return k;
    r -= weights[k];
  }
  return weights.size() - 1;  // not reached
}

}  // namespace hsx
