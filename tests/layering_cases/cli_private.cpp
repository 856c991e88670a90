// layering-path: src/cli/bad_command.cpp
// A CLI file that reaches into a private header of the library: layering.sh must refuse it.
#include "geometry/planar_points.hpp"
