// hsx in five minutes: the library's front door.
//
// Include this one header and link hsx::hsx (find_package(hsx), add_subdirectory or FetchContent). Every call is
// exact or certified, and every function below throws hsx::InputError (a std::runtime_error whose message names
// the file, the field or the line) on bad input; anything else thrown is a bug in hsx.
//
//   hsx::LoadedInput in = hsx::load_input("lens.json");              // a scene, arranged exactly, or a complex
//   const hsx::Complex& c = in.complex();                           // cells, patches, junctions, samples
//   hsx::bsh::ExtractResult shape = hsx::extract_shape(c);          // BSH shape (default: beam search, K = 1)
//   shape.energy.missing_samples; shape.energy.measure().exact_string();
//   hsx::bsh::Grade g = hsx::grade_labelling(c, my_labels);         // someone else's answer, graded exactly
//   auto checks = hsx::bsh::check_all(c);                           // every proposition checker
//   std::vector<char> solid = hsx::solid_from_csg(c, "(A | B) & ~C");
//   hsx::csg::Describability d = hsx::csg::describability(c, solid);  // Shapiro-Vossler, with witness cells
//   hsx::csg::BhcResult tree = hsx::csg_tree(in, solid);             // BHC tree, verified on every cell
//   hsx::nhrep::BuildResult nh = hsx::nhrep_tree(*in.arranged, solid);  // NH-Rep's Algorithm 1 on its boundary
//   hsx::write_file_atomically("shape.json", hsx::result_json_text(c, shape, in.pieces()));
//
// Where things live (each header documents its conventions and every argument):
//   <hsx/kernel/...>      exact numbers (Rational = GMP's mpq_class, one-root numbers a + b*sqrt(c)), certified
//                         intervals, Measure (lengths, areas: sums of roots and arc terms, compared with proof).
//   <hsx/geometry/...>    scenes (halfspaces, samples, domain box), the exact 2D arrangement, exact meshes.
//   <hsx/complex/...>     the dimension-free complex every algorithm sees, and solids' boundaries.
//   <hsx/algorithms/...>  bsh/ (energy, graph cut, searches, oracle, checkers, GENERATE-SAMPLES, grading),
//                         csg/ (expressions, describability, BHC), nhrep/ (patch graph, Algorithm 1, evaluation).
//   <hsx/io/...>          every format: hsx-scene/1, hsx-complex/1, hsx-result/1, CSG text/JSON, CSGNet,
//                         OpenSCAD, NH-Rep .conf/.obj/.fea, SVG.
#pragma once

#include <hsx/algorithms/bsh/checks.hpp>
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/bsh/grade.hpp>
#include <hsx/algorithms/csg/bhc.hpp>
#include <hsx/algorithms/csg/describability.hpp>
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/complex/complex.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/input.hpp>

#include <string>
#include <vector>

namespace hsx {

/// The BSH shape of `complex` (Definition 3.3) by `options.method` (beam K = 1 by default, as in the paper;
/// Method::Exact proves optimality at any junction and enumerates ties, much faster than Method::BestFirst, which
/// is the paper's complete search). The complex must outlive the call only.
/// Returns the labelling (per cell, 1 inside), its energy, whether it is proven optimal, ties and statistics.
bsh::ExtractResult extract_shape(const Complex& complex, const bsh::ExtractOptions& options = {});

/// Grades a labelling computed elsewhere against the exact optimum (algorithms/bsh/grade.hpp).
/// `labelling`: one entry per cell of `complex`, in the order of its cells (the order of an hsx-complex/1 file's
/// "cells"), 1 inside. Throws InputError when its size is not the number of cells.
bsh::Grade grade_labelling(const Complex& complex, const bsh::Labelling& labelling,
                           const bsh::ExtractOptions& oracle = bsh::best_first_oracle());

/// The cells of `complex` inside a CSG expression over its halfspaces, written in hsx's CSG text ("(A | B) & ~C",
/// names are the scene's halfspace names; io/csg_text.hpp has the grammar). Per cell, 1 inside.
std::vector<char> solid_from_csg(const Complex& complex, const std::string& expression);

/// Buchele-Crawford's BHC tree for `solid` (per cell of `input.complex()`, 1 inside), verified on every cell.
/// When `input` is a scene, half-planes (2D) or planes (3D) are preferred for partitioning, as the paper prefers
/// planes and as `hsx csg` does (csg::build_tree without separators gives the same tree). When the solid
/// is not describable by the halfspaces, `describable` is false and `witness` is the mixed term where BHC stopped.
csg::BhcResult csg_tree(const LoadedInput& input, const std::vector<char>& solid);

/// NH-Rep's Boolean tree (Algorithm 1 with patch decomposition, the paper's reading) of a 2D solid: `solid` per
/// cell of `arranged` (1 inside). The tree's leaves are the patches of the solid's boundary. Throws InputError for
/// a flag vector of the wrong size, an empty solid, or one that reaches the domain's boundary (an outer cell).
/// For natural-halfspace names and the exact evaluation, use nhrep::build_planar_tree (algorithms/nhrep/planar.hpp).
nhrep::BuildResult nhrep_tree(const Arranged2& arranged, const std::vector<char>& solid,
                              const nhrep::BuildOptions& options = {});

/// NH-Rep's Boolean tree of a closed triangle mesh (`obj_path`, an OBJ file) with its feature edges (`fea_path`,
/// NH-Rep's .fea: one edge "a b" per line, 0-based vertices). `sharp_angle_degrees`: edges bending less are smooth
/// (0: the exact feature types of the paper; NH-Rep's tool uses 20).
nhrep::BuildResult nhrep_tree_of_mesh(const std::string& obj_path, const std::string& fea_path,
                                      const Rational& sharp_angle_degrees = 0,
                                      const nhrep::BuildOptions& options = {});

/// Writing: the hsx-complex/1 document of what `load_input` read (with its geometry when it was a scene), the
/// hsx-result/1 document of an extraction (`include_seconds` false: byte-reproducible), as JSON text.
std::string complex_json_text(const LoadedInput& input);
std::string result_json_text(const Complex& complex, const bsh::ExtractResult& result, const PlanarPieces& geometry,
                             bool include_seconds = false);

}  // namespace hsx
