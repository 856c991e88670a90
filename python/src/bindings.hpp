// Shared declarations of the Python module's sources (python/src). The bindings convert and forward: every
// computation is the library's (include/hsx), called through its public headers only, as the CLI does.
//
// Conventions (owned here):
// - Exact numbers cross as fractions.Fraction (Rational, witness coordinates, intervals' ends) and exact strings
//   (closed forms); a Python float is never read as a number here (python/hsx/_scene.py owns exact_from_float).
// - An arranged or read input is held by shared pointer (InputPtr); every view (Complex, Cell, Result, ...) keeps
//   it alive, so views never dangle.
// - Long computations run with the GIL released inside a Guard (cancel.cpp): Ctrl-C, a CancelToken and a
//   progress callback reach them through bsh::ExtractOptions::cancel/progress.
#pragma once

#include <hsx/hsx.hpp>
#include <hsx/geometry/random_scene.hpp>
#include <hsx/io/mesh_export.hpp>
#include <hsx/io/svg.hpp>
#include <hsx/io/svg3.hpp>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hsxpy {

namespace py = pybind11;

/// What hsx.arrange/hsx.load produced: a scene arranged exactly, or an hsx-complex/1 document.
using InputPtr = std::shared_ptr<const hsx::LoadedInput>;

/// The Python side of a complex: the input it belongs to.
struct ComplexHandle {
  InputPtr input;
  const hsx::Complex& complex() const { return input->complex(); }
};

// ---- numbers.cpp ----
/// q as fractions.Fraction.
py::object to_fraction(const hsx::Rational& q);
/// An exact number from int, fractions.Fraction (any numbers.Rational) or an exact string ("7/3", "0.1");
/// `what` names it in the error. Throws hsx::InputError for a string that is not a number and py::type_error for
/// a float or any other type.
hsx::Rational to_rational(py::handle value, const std::string& what);
/// A tuple of Fractions.
py::tuple fraction_tuple(const std::vector<hsx::Rational>& values);
/// A numpy bool array of a per-cell flag vector, and back (any sequence of bools or 0/1 of length `size`;
/// `what` names it in the error).
py::object bool_array(const std::vector<char>& flags);
std::vector<char> flags_from(py::handle sequence, std::size_t size, const std::string& what);

// ---- complex.cpp ----
/// The picture of `input` (io/svg.hpp) with `options`, as a str; None for an input without a scene.
py::object svg_picture(const InputPtr& input, const hsx::SvgOptions& options);
/// RandomSceneSettings from hsx.random_scene's keyword arguments (`kw`: min_halfspaces, max_halfspaces,
/// halfplanes, disks, polygons, complement_percent, denominator, coordinate_bound, max_radius, min_degeneracies,
/// max_degeneracies, max_samples, near_percent, degeneracy_weights = {name: weight}); unset fields keep their
/// defaults. Throws py::type_error for an unknown key and InputError for an unknown degeneracy name. The ranges are
/// checked by random_scene itself (campaign::validate for a campaign).
hsx::RandomSceneSettings random_settings(const py::dict& kw);
/// The method named `name` ("best_first" is read as "best-first"); `what` names the argument in the error.
hsx::bsh::Method method_named(std::string name, const std::string& what);

// ---- mesh3.cpp ----
/// `faces` of `arranged` (io/mesh_export.hpp's exported_faces or shape_faces) as (vertices, faces, patch,
/// halfspace): vertices numbered by mesh_export's renumber_vertices (the used ones, ascending), a float64 (n, 3)
/// numpy array or, with `exact`, a list of (x, y, z) tuples of exact rational strings ("-7/3"); faces an int64
/// (m, 3) array of vertex rows in `faces`' order and turning; per face its patch and halfspace (int64 (m,)).
py::tuple face_arrays(const hsx::Arranged3& arranged, const std::vector<hsx::ExportedFace>& faces, bool exact);
/// The 3D picture of `input` (io/svg3.hpp's arrangement_svg3) with `options`, as a str; None for an input without
/// a 3D scene. Throws InputError for a width below 200 (io/svg3.hpp's bound).
py::object svg3_picture(const InputPtr& input, hsx::Svg3Options options);
/// Svg3Options::views from Python: None (empty: the default four), or a non-empty sequence of default view names
/// ("front", "side", "top", "isometric") and (name, direction, up) tuples of exact coordinates (io/svg3.hpp's
/// SvgView3). Throws InputError for an unknown name, a zero direction or an up parallel to it, py::type_error for
/// a malformed entry or a float coordinate.
std::vector<hsx::SvgView3> svg3_views(py::handle views);
/// Throws InputError ("views: only 3D pictures have views") when `views` is given for an input without a 3D scene.
void refuse_views_in_2d(const InputPtr& input, py::handle views);

// ---- cancel.cpp ----
/// A stop flag another Python thread sets (hsx.CancelToken().cancel()); read by the search through its cancel hook.
struct CancelToken {
  std::atomic<bool> cancelled{false};
};

/// Wires Ctrl-C, a CancelToken and a progress callback into one library computation. Build it with the GIL held,
/// run the computation inside `release()`'s scope with the hooks from cancel()/progress(), then call finish() with
/// the GIL held again: it raises KeyboardInterrupt (or the callback's exception) when that stopped the work.
class Guard {
 public:
  /// `token`: may be null; `progress`: None or a callable taking a dict.
  Guard(std::shared_ptr<CancelToken> token, py::object progress);
  /// The hook for ExtractOptions::cancel / CheckOptions::cancel: true once Ctrl-C arrived (checked every 20 ms
  /// with the GIL briefly taken), the token was set, or the progress callback raised.
  std::function<bool()> cancel() const;
  /// The hook for ExtractOptions::progress (empty when no callback was given).
  std::function<void(const hsx::bsh::SearchProgress&)> progress() const;
  /// With the GIL held: rethrows the Python exception that stopped the computation, if any.
  void finish() const;

  struct State;

 private:
  std::shared_ptr<State> state_;
};

// ---- the binding functions, one per source file ----
void bind_numbers(py::module_& m);
void bind_complex(py::module_& m);
void bind_algorithms(py::module_& m);
void bind_cancel(py::module_& m);
void bind_nhrep(py::module_& m);
void bind_csg_module(py::module_& m);
void bind_campaign(py::module_& m);

}  // namespace hsxpy

namespace pybind11::detail {
/// Rational results cross as fractions.Fraction; Rational arguments accept what to_rational accepts.
template <>
struct type_caster<hsx::Rational> {
  PYBIND11_TYPE_CASTER(hsx::Rational, const_name("fractions.Fraction"));
  bool load(handle src, bool) {
    if (PyFloat_Check(src.ptr())) return false;
    try {
      value = hsxpy::to_rational(src, "value");
      return true;
    } catch (const std::exception&) {
      PyErr_Clear();
      return false;
    }
  }
  static handle cast(const hsx::Rational& q, return_value_policy, handle) { return hsxpy::to_fraction(q).release(); }
};
}  // namespace pybind11::detail
