// Measures computed on first request (kernel/lazy.hpp): exact lengths, areas and volumes of an arrangement are
// computed when first read, never while it is built.
#pragma once

#include <hsx/kernel/lazy.hpp>
#include <hsx/kernel/measure.hpp>

namespace hsx {

/// A family of measures, each computed on its first read (LazyCache).
using MeasureCache = LazyCache<Measure>;
/// A measure, known or one entry of a shared MeasureCache (Lazy); the default is zero.
using LazyMeasure = Lazy<Measure>;

}  // namespace hsx
