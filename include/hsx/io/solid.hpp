// A solid on a loaded input: a labelling of its cells, read from an hsx-result/1 file computed from the same input
// or computed from a CSG expression over the input's halfspaces.
#pragma once

#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/io/input.hpp>

#include <string>
#include <vector>

namespace hsx {

/// Where a solid comes from: exactly one of `shape_path` and `csg` is non-empty.
struct SolidSource {
  std::string shape_path;  ///< an hsx-result/1 file computed from the same scene or complex (its cell ids)
  std::string csg;         ///< a CSG expression: text, inline JSON or a JSON file (read_csg_argument)
  /// The names of the two options in error messages (a command may spell the shape option --target).
  std::string shape_option = "--shape";
  std::string csg_option = "--csg";
};

struct Solid {
  std::vector<char> cells;  ///< per cell of the input's complex: 1 inside, 0 outside
  csg::ExprPtr expression;  ///< the expression when given as `csg` (null for a result file)
};

/// The solid on `in.complex()`.
/// - `in`: a loaded scene or complex (load_input);
/// - `source`: exactly one of shape_path / csg set.
/// Throws InputError when both or neither are set (naming both options), when the result file is unreadable or
/// was computed from another input (the message starts with the file's path), or when the expression names an
/// unknown halfspace or does not parse (read_csg_argument's message).
Solid load_solid(const LoadedInput& in, const SolidSource& source);

}  // namespace hsx
