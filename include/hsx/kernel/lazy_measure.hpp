// Measures computed on first request. Building an exact arrangement costs more in its measures (cell areas, patch
// lengths: sums of square roots and arc terms) than in the arrangement itself, and most of them are never asked
// for (a BSH shape's area needs only its own cells). A MeasureCache holds one family of measures and computes
// each the first time it is read; a LazyMeasure is either a known value or one entry of a shared cache.
// Thread safety: a cache may be read by several threads at once (each entry is computed exactly once, under the
// cache's mutex; a computed entry is read without locking); the value is the same Measure an eager computation gives, so outputs do not depend on when
// or by whom it is computed.
#pragma once

#include <hsx/kernel/measure.hpp>

#include <cstddef>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>

namespace hsx {

/// `size` measures, entry k being `compute(k)`, each computed on its first read and kept. Not copyable; share it
/// through std::shared_ptr (LazyMeasure does).
class MeasureCache {
 public:
  /// `size`: number of entries; `compute`: entry k's value for k < size, called once per k unless it throws (it must
  /// own, or share ownership of, everything it reads: the cache may outlive its creator).
  MeasureCache(std::size_t size, std::function<Measure(std::size_t)> compute);
  MeasureCache(const MeasureCache&) = delete;
  MeasureCache& operator=(const MeasureCache&) = delete;

  std::size_t size() const { return size_; }
  /// Entry `k` (k < size(); throws std::out_of_range otherwise), computed on the first call for k. Safe to call
  /// from several threads; an exception from `compute` propagates and leaves the entry to be computed again.
  const Measure& get(std::size_t k) const;

 private:
  std::size_t size_;
  std::function<Measure(std::size_t)> compute_;
  // Not std::call_once: libstdc++ runs it through pthread_once, and an exception from compute (std::bad_alloc
  // under a memory limit) then terminated the process instead of reaching the caller.
  mutable std::mutex mutex_;
  std::unique_ptr<std::atomic<bool>[]> ready_;  // ready_[k]: values_[k] is computed (set once, under mutex_)
  std::unique_ptr<std::unique_ptr<Measure>[]> values_;  // allocated when computed: most entries are never read
};

/// A measure that is either known (set from a Measure) or entry `index` of a shared MeasureCache, computed on
/// first read. Reads convert implicitly to `const Measure&`; use get() to call Measure's members. Copies share the
/// cache (and a known value, which is never modified); assigning a Measure replaces the value without touching the
/// cache. Small (two shared pointers and an index), so that cells and patches are cheap to build and move.
class LazyMeasure {
 public:
  LazyMeasure() = default;  ///< zero
  LazyMeasure(Measure value);  // NOLINT: a measure is a lazy measure
  /// Entry `index` of `cache` (non-null; index < cache->size()).
  LazyMeasure(std::shared_ptr<const MeasureCache> cache, std::size_t index);
  LazyMeasure& operator=(Measure value);

  /// The value (computed on the first read of a cache entry; thread-safe).
  const Measure& get() const { return cache_ ? cache_->get(index_) : value_ ? *value_ : zero(); }
  operator const Measure&() const { return get(); }  // NOLINT: read as a Measure

 private:
  std::shared_ptr<const MeasureCache> cache_;  // null: value_ holds the measure
  std::size_t index_ = 0;
  std::shared_ptr<const Measure> value_;  // null (without cache_): zero
  static const Measure& zero();
};

}  // namespace hsx
