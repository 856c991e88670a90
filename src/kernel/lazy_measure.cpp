#include <hsx/kernel/lazy_measure.hpp>

#include <stdexcept>
#include <string>

namespace hsx {

MeasureCache::MeasureCache(std::size_t size, std::function<Measure(std::size_t)> compute)
    : size_(size), compute_(std::move(compute)), ready_(new std::atomic<bool>[size]()),
      values_(new std::unique_ptr<Measure>[size]()) {}

const Measure& MeasureCache::get(std::size_t k) const {
  if (k >= size_)
    throw std::out_of_range("MeasureCache::get: entry " + std::to_string(k) + " of " + std::to_string(size_));
  if (ready_[k].load(std::memory_order_acquire)) return *values_[k];
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!ready_[k].load(std::memory_order_relaxed)) {
    values_[k] = std::make_unique<Measure>(compute_(k));  // may throw: the entry stays to be computed
    ready_[k].store(true, std::memory_order_release);
  }
  return *values_[k];
}

LazyMeasure::LazyMeasure(Measure value) : value_(std::make_shared<const Measure>(std::move(value))) {}

LazyMeasure::LazyMeasure(std::shared_ptr<const MeasureCache> cache, std::size_t index)
    : cache_(std::move(cache)), index_(index) {
  if (!cache_ || index_ >= cache_->size()) throw std::out_of_range("LazyMeasure: no such cache entry");
}

LazyMeasure& LazyMeasure::operator=(Measure value) {
  cache_.reset();
  index_ = 0;
  value_ = std::make_shared<const Measure>(std::move(value));
  return *this;
}

const Measure& LazyMeasure::zero() {
  static const Measure zero;
  return zero;
}

}  // namespace hsx
