// layering-path: src/io/bad.cpp
// A public header spelled as a private one: layering.sh must refuse it.
#include "kernel/rational.hpp"
