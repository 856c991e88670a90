// layering-path: include/hsx/geometry/bad.hpp
// A public header that exposes CGAL: layering.sh must refuse it.
#include <CGAL/Exact_rational.h>
