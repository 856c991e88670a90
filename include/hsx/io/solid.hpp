// A solid on a loaded input: a labelling of its cells, read from an hsx-result/1 file computed from the same input,
// computed from a CSG expression over the input's halfspaces, or (3D scenes) the cells inside a closed mesh whose
// faces lie on the scene's halfspaces.
#pragma once

#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/io/input.hpp>

#include <string>
#include <vector>

namespace hsx {

/// Where a solid comes from: exactly one of `shape_path`, `csg` and `mesh_path` is non-empty.
struct SolidSource {
  std::string shape_path;  ///< an hsx-result/1 file computed from the same scene or complex (its cell ids)
  std::string csg;         ///< a CSG expression: text, inline JSON or a JSON file (read_csg_argument)
  std::string mesh_path;   ///< 3D scenes: a closed triangle mesh (.obj, .off, .ply) on the scene's halfspaces
  /// The names of the options in error messages (a command may spell the shape option --target).
  std::string shape_option = "--shape";
  std::string csg_option = "--csg";
  std::string mesh_option = "--mesh";
};

struct Solid {
  std::vector<char> cells;  ///< per cell of the input's complex: 1 inside, 0 outside
  csg::ExprPtr expression;  ///< the expression when given as `csg` (null for a result file or a mesh)
};

/// The solid on `in.complex()`.
/// - `in`: a loaded scene or complex (load_input);
/// - `source`: exactly one of shape_path / csg / mesh_path set;
/// - `limits`: bounds on the arrangement of the scene with the mesh (mesh_path only; geometry/mesh_solid3.hpp).
/// Throws InputError when none or several are set (naming the options), when the result file is unreadable or
/// was computed from another input (the message starts with the file's path), when the expression names an
/// unknown halfspace or does not parse (read_csg_argument's message), and for a mesh: when the input is not a 3D
/// scene (the message names the option), when the file is unreadable, open, non-manifold, inconsistently oriented
/// or degenerate (read_mesh_file and build_mesh3: "PATH:LINE: ..."), and when it leaves the domain, intersects
/// itself or has a face off the scene's halfspaces (cells_inside_mesh: "PATH[:LINE]: ...", naming the face).
Solid load_solid(const LoadedInput& in, const SolidSource& source, const ArrangementLimits& limits = {});

}  // namespace hsx
