// layering-path: include/hsx/geometry/bad.hpp
// A public header that includes a private header of its own layer: layering.sh must refuse it.
#include "geometry/planar_points.hpp"
