// layering-path: src/complex/bad.cpp
// The complex layer including an algorithm: layering.sh must refuse it.
#include <hsx/algorithms/bsh/problem.hpp>
