// Random CSG expressions for the property tests of algorithms/csg and io/csg_text (rapidcheck generators; call
// inside a property).
#pragma once

#include <hsx/algorithms/csg/expression.hpp>

#include <vector>

namespace hsx::test {

/// A node built without the constructors' simplifications.
csg::ExprPtr raw(csg::Op op, std::vector<csg::ExprPtr> children);

/// A random expression over halfspaces 0..n-1 of at most `depth` levels (every operation, constants included),
/// built with the constructors (simplified) or, with `raw_nodes`, as raw nodes.
csg::ExprPtr random_expr(int n, int depth, bool raw_nodes);

}  // namespace hsx::test
