// Values computed on first request. Building an exact arrangement costs more in what it could report (cell areas,
// patch lengths: sums of square roots and arc terms; exact interior points of cells) than in the arrangement itself,
// and most of it is never asked for (a BSH shape's area needs only its own cells; no search reads a witness point).
// A LazyCache holds one family of values and computes each the first time it is read; a Lazy value is either a
// known value or one entry of a shared cache.
// Thread safety: a cache may be read by several threads at once (each entry is computed exactly once, under the
// cache's mutex; a computed entry is read without locking); an entry is the value an eager computation gives, so
// outputs do not depend on when or by whom it is computed.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace hsx {

/// `size` values of type T, entry k being `compute(k)`, each computed on its first read and kept. Not copyable;
/// share it through std::shared_ptr (Lazy does).
template <class T>
class LazyCache {
 public:
  /// `size`: number of entries; `compute`: entry k's value for k < size, called once per k unless it throws (it must
  /// own, or share ownership of, everything it reads: the cache may outlive its creator). Calls of `compute` never
  /// overlap (they run under the cache's mutex), so it may keep private state of its own.
  LazyCache(std::size_t size, std::function<T(std::size_t)> compute)
      : size_(size), compute_(std::move(compute)), ready_(new std::atomic<bool>[size]()),
        values_(new std::unique_ptr<T>[size]()) {}
  LazyCache(const LazyCache&) = delete;
  LazyCache& operator=(const LazyCache&) = delete;

  std::size_t size() const { return size_; }
  /// Entry `k` (k < size(); throws std::out_of_range otherwise), computed on the first call for k. Safe to call
  /// from several threads; an exception from `compute` propagates and leaves the entry to be computed again.
  const T& get(std::size_t k) const {
    if (k >= size_)
      throw std::out_of_range("LazyCache::get: entry " + std::to_string(k) + " of " + std::to_string(size_));
    if (ready_[k].load(std::memory_order_acquire)) return *values_[k];
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!ready_[k].load(std::memory_order_relaxed)) {
      values_[k] = std::make_unique<T>(compute_(k));  // may throw: the entry stays to be computed
      ready_[k].store(true, std::memory_order_release);
    }
    return *values_[k];
  }

 private:
  std::size_t size_;
  std::function<T(std::size_t)> compute_;
  // Not std::call_once: libstdc++ runs it through pthread_once, and an exception from compute (std::bad_alloc
  // under a memory limit) then terminated the process instead of reaching the caller.
  mutable std::mutex mutex_;
  std::unique_ptr<std::atomic<bool>[]> ready_;  // ready_[k]: values_[k] is computed (set once, under mutex_)
  std::unique_ptr<std::unique_ptr<T>[]> values_;  // allocated when computed: most entries are never read
};

/// A T that is either known (set from a T) or entry `index` of a shared LazyCache<T>, computed on first read. Reads
/// convert implicitly to `const T&`; use get() to call T's members. Copies share the cache (and a known value, which
/// is never modified); assigning a T replaces the value without touching the cache. Small (two shared pointers and an
/// index), so that the records holding it are cheap to build and move. Default: T{}.
template <class T>
class Lazy {
 public:
  Lazy() = default;
  Lazy(T value) : value_(std::make_shared<const T>(std::move(value))) {}  // NOLINT: a T is a lazy T
  /// Entry `index` of `cache` (non-null; index < cache->size(); std::out_of_range otherwise).
  Lazy(std::shared_ptr<const LazyCache<T>> cache, std::size_t index) : cache_(std::move(cache)), index_(index) {
    if (!cache_ || index_ >= cache_->size()) throw std::out_of_range("Lazy: no such cache entry");
  }
  Lazy& operator=(T value) {
    cache_.reset();
    index_ = 0;
    value_ = std::make_shared<const T>(std::move(value));
    return *this;
  }

  /// The value (computed on the first read of a cache entry; thread-safe).
  const T& get() const { return cache_ ? cache_->get(index_) : value_ ? *value_ : empty(); }
  operator const T&() const { return get(); }  // NOLINT: read as a T

 private:
  std::shared_ptr<const LazyCache<T>> cache_;  // null: value_ holds the value
  std::size_t index_ = 0;
  std::shared_ptr<const T> value_;  // null (without cache_): T{}
  static const T& empty() {
    static const T value{};
    return value;
  }
};

}  // namespace hsx
