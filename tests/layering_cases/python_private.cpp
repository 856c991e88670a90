// layering-path: python/src/bad_binding.cpp
// A binding that reaches into a private header of the library: layering.sh must refuse it.
#include "geometry/planar_points.hpp"
