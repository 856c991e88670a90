// Certified double enclosures of exact numbers as CGAL intervals: the library's one interval filter
// (kernel/measure.cpp; geometry/cgal_arrangement2.cpp's interior points). Private header: it includes CGAL.
#pragma once

#include <hsx/kernel/rational.hpp>

#include <CGAL/Interval_nt.h>

namespace hsx {

using IntervalNT = CGAL::Interval_nt<true>;  // protected: every operation sets and restores the rounding mode

/// Certified enclosure of q: numerator and denominator below 2^53 are doubles exactly, and Interval_nt's division
/// rounds outward (the common, fast case); otherwise CGAL::to_interval (MPFR, rounded away from zero).
IntervalNT to_interval_nt(const Rational& q);
/// Certified enclosure of z (exact when |z| < 2^53).
IntervalNT to_interval_nt(const Integer& z);

}  // namespace hsx
