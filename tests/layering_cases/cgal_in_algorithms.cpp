// layering-path: src/algorithms/bad.cpp
// CGAL outside kernel/ and geometry/: layering.sh must refuse it.
#include <CGAL/Gmpq.h>
