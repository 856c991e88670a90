// layering-path: python/src/bad_cgal.cpp
// A binding that uses CGAL: only kernel/ and geometry/ may.
#include <CGAL/Exact_rational.h>
