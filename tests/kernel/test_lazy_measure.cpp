// Lazy values (kernel/lazy.hpp) and measures: each cache entry computed once, on first read, also when several
// threads read at once.
#include <hsx/kernel/lazy_measure.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

using hsx::LazyMeasure;
using hsx::Measure;
using hsx::MeasureCache;
using hsx::Order;
using hsx::Rational;

TEST_CASE("MeasureCache computes each entry once, on first read", "[lazy_measure]") {
  std::vector<int> calls(3, 0);
  auto cache = std::make_shared<const MeasureCache>(3, [&](std::size_t k) {
    ++calls[k];
    return Measure::sqrt_of(Rational(static_cast<long>(k) + 2));
  });
  CHECK(calls == std::vector<int>{0, 0, 0});
  const LazyMeasure a(cache, 1), b = a;  // copies share the cache
  CHECK(compare(a, Measure::sqrt_of(Rational(3))) == Order::Equal);
  CHECK(compare(b.get(), Measure::sqrt_of(Rational(3))) == Order::Equal);
  CHECK(calls == std::vector<int>{0, 1, 0});
  CHECK_THROWS_AS(cache->get(3), std::out_of_range);
  CHECK_THROWS_AS(LazyMeasure(cache, 3), std::out_of_range);
}

TEST_CASE("LazyMeasure holds a value until a Measure is assigned", "[lazy_measure]") {
  LazyMeasure m;
  CHECK(m.get().is_zero());
  auto cache = std::make_shared<const MeasureCache>(1, [](std::size_t) { return Measure(Rational(7)); });
  m = LazyMeasure(cache, 0);
  CHECK(m.get().rational_value() == Rational(7));
  m = Rational(2);  // a measure replaces the cache entry
  CHECK(m.get().rational_value() == Rational(2));
}

TEST_CASE("MeasureCache is read safely by several threads", "[lazy_measure]") {
  constexpr std::size_t n = 200;
  std::vector<std::atomic<int>> calls(n);
  for (auto& c : calls) c = 0;
  const auto cache = std::make_shared<const MeasureCache>(n, [&](std::size_t k) {
    ++calls[k];
    return Measure::sqrt_of(Rational(static_cast<long>(k) + 1)) * Rational(3);
  });
  std::vector<std::thread> threads;
  std::atomic<int> wrong{0};
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = (i * 7 + static_cast<std::size_t>(t) * 13) % n;
        if (compare(cache->get(k), Measure::sqrt_of(Rational(static_cast<long>(k) + 1)) * Rational(3)) != Order::Equal)
          ++wrong;
      }
    });
  for (auto& th : threads) th.join();
  CHECK(wrong == 0);
  for (std::size_t k = 0; k < n; ++k) CHECK(calls[k] == 1);
}

TEST_CASE("Lazy of another type: empty by default, a known value, or a cache entry", "[lazy_measure]") {
  hsx::Lazy<std::vector<int>> none;
  CHECK(none.get().empty());
  int calls = 0;
  const auto cache = std::make_shared<const hsx::LazyCache<std::vector<int>>>(2, [&](std::size_t k) {
    ++calls;
    return std::vector<int>(k + 1, 7);
  });
  const hsx::Lazy<std::vector<int>> second(cache, 1), copy = second;
  CHECK(calls == 0);
  CHECK(copy.get() == std::vector<int>{7, 7});
  CHECK(second.get() == std::vector<int>{7, 7});
  CHECK(calls == 1);
  none = std::vector<int>{1};
  CHECK(none.get() == std::vector<int>{1});
  CHECK_THROWS_AS(hsx::Lazy<std::vector<int>>(cache, 2), std::out_of_range);
}

TEST_CASE("LazyCache: threads that ask for the same entries at once compute each once, never two at a time",
          "[lazy_measure]") {
  // The guarantees of LazyCache::get that a lost lock would break: entry k is computed once although four
  // threads ask for it together, and calls of compute never overlap. Each call sleeps, so that without the lock
  // the threads would meet inside it.
  constexpr std::size_t n = 24;
  std::vector<std::atomic<int>> calls(n);
  for (auto& c : calls) c = 0;
  std::atomic<int> inside{0}, overlaps{0};
  const auto cache = std::make_shared<const hsx::LazyCache<long>>(n, [&](std::size_t k) {
    if (inside.fetch_add(1) != 0) ++overlaps;
    std::this_thread::sleep_for(std::chrono::microseconds(300));
    ++calls[k];
    inside.fetch_sub(1);
    return static_cast<long>(k * k);
  });
  std::atomic<int> ready{0}, wrong{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      ++ready;
      while (ready.load() < 4) std::this_thread::yield();  // start together
      for (std::size_t k = 0; k < n; ++k)
        if (cache->get(k) != static_cast<long>(k * k)) ++wrong;
    });
  for (auto& th : threads) th.join();
  CHECK(wrong == 0);
  CHECK(overlaps == 0);
  for (std::size_t k = 0; k < n; ++k) CHECK(calls[k] == 1);
}
