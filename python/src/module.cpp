// The extension module hsx._hsx: exceptions, then the bindings by topic. The package python/hsx wraps it.
#include "bindings.hpp"

PYBIND11_MODULE(_hsx, m) {
  m.doc() = "hsx's C++ engine; use the package `hsx`, which wraps this module";
  // hsx::InputError (and its LabellingLimitExceeded) as hsx.InputError, a ValueError, with the CLI's message.
  pybind11::register_exception<hsx::InputError>(m, "InputError", PyExc_ValueError);
  hsxpy::bind_numbers(m);
  hsxpy::bind_cancel(m);
  hsxpy::bind_complex(m);
  hsxpy::bind_algorithms(m);
  hsxpy::bind_csg_module(m);
  hsxpy::bind_nhrep(m);
  hsxpy::bind_campaign(m);
}
