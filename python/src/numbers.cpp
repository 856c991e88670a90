// Exact numbers: Rational <-> fractions.Fraction, Measure (exact string, float, certified interval, certified
// comparisons with Tie as an outcome), Order.
#include "bindings.hpp"

#include <pybind11/numpy.h>

#include <mpfr.h>

namespace hsxpy {
namespace {

py::object& fraction_type() {
  static py::object* type = new py::object(py::module_::import("fractions").attr("Fraction"));  // lives forever
  return *type;
}

py::object& rational_abc() {
  static py::object* type = new py::object(py::module_::import("numbers").attr("Rational"));
  return *type;
}

/// An MPFR number as its exact rational value (an interval end is a dyadic rational, finite here).
hsx::Rational exact_value(const mpfr_t x) {
  if (!mpfr_number_p(x)) throw std::domain_error("interval end is not finite");
  hsx::Rational q;
  mpfr_get_q(q.get_mpq_t(), x);
  return q;
}

/// Raised by Measure's rich comparisons when the certified comparison is a Tie (nothing is guessed).
struct Undecided : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// `other` as a Measure: a Measure, or an exact number; nullopt for anything else (then NotImplemented).
std::optional<hsx::Measure> as_measure(py::handle other) {
  if (py::isinstance<hsx::Measure>(other)) return other.cast<hsx::Measure>();
  if (py::isinstance<py::bool_>(other) || py::isinstance<py::float_>(other)) return std::nullopt;
  if (py::isinstance<py::int_>(other) || py::isinstance(other, rational_abc()))
    return hsx::Measure(to_rational(other, "operand"));
  return std::nullopt;
}

/// A rich comparison: the certified order, or Undecided on a Tie.
py::object rich_compare(const hsx::Measure& a, py::handle b, int op, const hsx::CompareOptions& options = {}) {
  const std::optional<hsx::Measure> m = as_measure(b);
  if (!m) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
  const hsx::Order o = hsx::compare(a, *m, options);
  if (o == hsx::Order::Tie)
    throw Undecided("the measures did not separate at the precision cap (Order.Tie): they may be equal; use "
                    "Measure.compare() to get the tie as an outcome");
  const int c = o == hsx::Order::Less ? -1 : o == hsx::Order::Greater ? 1 : 0;
  switch (op) {
    case Py_LT: return py::bool_(c < 0);
    case Py_LE: return py::bool_(c <= 0);
    case Py_EQ: return py::bool_(c == 0);
    case Py_NE: return py::bool_(c != 0);
    case Py_GT: return py::bool_(c > 0);
    default: return py::bool_(c >= 0);
  }
}

std::string measure_repr(const hsx::Measure& m) {
  if (auto exact = m.exact_string()) return "Measure('" + *exact + "')";
  return "Measure(~" + m.decimal_string(17) + ")";
}

void bind_order(py::module_& m) {
  py::enum_<hsx::Order>(m, "Order", "The outcome of a certified comparison; Tie: not separated at the precision "
                                    "cap (possibly equal), never reported as decided")
      .value("Less", hsx::Order::Less)
      .value("Equal", hsx::Order::Equal)
      .value("Greater", hsx::Order::Greater)
      .value("Tie", hsx::Order::Tie);
}

void bind_measure(py::module_& m) {
  py::class_<hsx::Measure> c(m, "Measure",
                             "A length or area: sums of square roots, rational multiples of pi and other arc terms, "
                             "held exactly and compared with proof (kernel/measure.hpp)");
  c.def(py::init([](py::handle q) { return hsx::Measure(to_rational(q, "Measure")); }), py::arg("value") = 0,
        "The exact rational `value` (int, Fraction or exact string)")
      .def_static("sqrt", [](py::handle q) { return hsx::Measure::sqrt_of(to_rational(q, "sqrt")); },
                  py::arg("q"), "sqrt(q) exactly (q >= 0)")
      .def_static("pi", [](py::handle q) { return hsx::Measure::pi(to_rational(q, "pi")); },
                  py::arg("coefficient") = 1, "coefficient * pi exactly")
      .def_property_readonly("exact", &hsx::Measure::exact_string,
                             "The closed form ('4/3*pi + 1/2*sqrt(3)'), or None when an arc angle other than a "
                             "multiple of pi/12 is left")
      .def("decimal", &hsx::Measure::decimal_string, py::arg("digits") = 30,
           "`digits` significant digits, proven unless the text ends in '~' (not pinned down at 8192 bits)")
      .def("decimal_certified", [](const hsx::Measure& x, int digits) { return x.decimal(digits).certified; },
           py::arg("digits") = 30, "Whether decimal(digits) is proven")
      .def("__float__", &hsx::Measure::to_double)
      .def("interval",
           [](const hsx::Measure& x, int bits) {
             const hsx::Interval i = x.enclose(bits);
             return py::make_tuple(to_fraction(exact_value(i.lo())), to_fraction(exact_value(i.hi())));
           },
           py::arg("bits") = 128,
           "A certified enclosure (lo, hi) as Fractions at `bits` bits of precision: lo <= value <= hi")
      .def("float_interval",
           [](const hsx::Measure& x, int bits) {
             const hsx::Interval i = x.enclose(bits);
             return py::make_tuple(i.lo_double(), i.hi_double());
           },
           py::arg("bits") = 128, "The enclosure rounded outward to floats (lo rounded down, hi up)")
      .def("sign",
           [](const hsx::Measure& x, long max_bits) {
             hsx::CompareOptions o;
             o.max_bits = max_bits;
             return x.sign(o);
           },
           py::arg("max_bits") = 2048, "-1, 0 or +1, proven; None when not decided at max_bits")
      .def("compare",
           [](const hsx::Measure& a, py::handle b, long max_bits) {
             const std::optional<hsx::Measure> other = as_measure(b);
             if (!other) throw py::type_error("compare: a Measure, an int, a Fraction or an exact string");
             hsx::CompareOptions o;
             o.max_bits = max_bits;
             return hsx::compare(a, *other, o);
           },
           py::arg("other"), py::arg("max_bits") = 2048,
           "The certified order: Less, Equal, Greater are proofs; Tie means not separated at max_bits")
      .def_property_readonly("rational", &hsx::Measure::rational_value,
                             "The value as an exact Rational when it is rational, else None")
      .def_property_readonly("pi_coefficient", &hsx::Measure::pi_coefficient, "q of the term q*pi (0 when none)")
      .def("is_zero", &hsx::Measure::is_zero, "Exact")
      .def("is_algebraic", &hsx::Measure::is_algebraic, "No transcendental term (pi, arc angles)")
      .def("__repr__", &measure_repr)
      .def("__str__", [](const hsx::Measure& x) { return x.exact_string().value_or(x.decimal_string(30)); })
      .def("__neg__", [](const hsx::Measure& x) { return -x; })
      .def("__add__", [](const hsx::Measure& a, py::handle b) -> py::object {
             auto m = as_measure(b);
             return m ? py::cast(a + *m) : py::reinterpret_borrow<py::object>(Py_NotImplemented);
           })
      .def("__radd__", [](const hsx::Measure& a, py::handle b) -> py::object {
             auto m = as_measure(b);
             return m ? py::cast(*m + a) : py::reinterpret_borrow<py::object>(Py_NotImplemented);
           })
      .def("__sub__", [](const hsx::Measure& a, py::handle b) -> py::object {
             auto m = as_measure(b);
             return m ? py::cast(a - *m) : py::reinterpret_borrow<py::object>(Py_NotImplemented);
           })
      .def("__rsub__", [](const hsx::Measure& a, py::handle b) -> py::object {
             auto m = as_measure(b);
             return m ? py::cast(*m - a) : py::reinterpret_borrow<py::object>(Py_NotImplemented);
           })
      .def("__mul__", [](const hsx::Measure& a, py::handle q) -> py::object {
             if (!py::isinstance<py::int_>(q) && !py::isinstance(q, rational_abc()))
               return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::cast(a * to_rational(q, "factor"));
           })
      .def("__rmul__", [](const hsx::Measure& a, py::handle q) -> py::object {
             if (!py::isinstance<py::int_>(q) && !py::isinstance(q, rational_abc()))
               return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::cast(a * to_rational(q, "factor"));
           });
  for (auto [name, op] : {std::pair{"__lt__", Py_LT}, {"__le__", Py_LE}, {"__eq__", Py_EQ}, {"__ne__", Py_NE},
                          {"__gt__", Py_GT}, {"__ge__", Py_GE}}) {
    const int o = op;
    c.def(name, [o](const hsx::Measure& a, py::handle b) { return rich_compare(a, b, o); }, py::is_operator());
  }
  c.attr("__hash__") = py::none();
  m.def("compare",
        [](const hsx::Measure& a, const hsx::Measure& b, long max_bits) {
          hsx::CompareOptions o;
          o.max_bits = max_bits;
          return hsx::compare(a, b, o);
        },
        py::arg("a"), py::arg("b"), py::arg("max_bits") = 2048, "Certified comparison of two measures");
}

}  // namespace

py::object to_fraction(const hsx::Rational& q) {
  return fraction_type()(py::int_(py::str(q.get_num().get_str())), py::int_(py::str(q.get_den().get_str())));
}

hsx::Rational to_rational(py::handle value, const std::string& what) {
  if (py::isinstance<py::bool_>(value))
    throw py::type_error(what + ": a bool is not a number");
  if (py::isinstance<py::str>(value)) {
    const std::string text = value.cast<std::string>();
    std::string why;
    if (auto q = hsx::parse_rational(text, &why)) return *q;
    throw hsx::InputError(what + ": \"" + text + "\" is not an exact number (" + why + ")");
  }
  if (py::isinstance<py::int_>(value)) {
    return hsx::Rational(hsx::Integer(py::str(value).cast<std::string>()));
  }
  if (py::isinstance(value, rational_abc())) {
    const hsx::Integer n(py::str(value.attr("numerator")).cast<std::string>());
    const hsx::Integer d(py::str(value.attr("denominator")).cast<std::string>());
    return hsx::make_rational(n, d);
  }
  if (py::isinstance<py::float_>(value))
    throw py::type_error(what + ": " + py::repr(value).cast<std::string>() +
                         " is a float, not an exact number (0.1 is not 1/10): pass an int, a fractions.Fraction "
                         "or a string such as \"0.1\"");
  throw py::type_error(what + ": expected an int, a fractions.Fraction or an exact string, got " +
                       py::repr(py::type::handle_of(value)).cast<std::string>());
}

py::tuple fraction_tuple(const std::vector<hsx::Rational>& values) {
  py::tuple t(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) t[k] = to_fraction(values[k]);
  return t;
}

py::object bool_array(const std::vector<char>& flags) {
  py::array_t<bool> a(static_cast<py::ssize_t>(flags.size()));
  auto out = a.mutable_unchecked<1>();
  for (std::size_t k = 0; k < flags.size(); ++k) out(static_cast<py::ssize_t>(k)) = flags[k] != 0;
  return std::move(a);
}

std::vector<char> flags_from(py::handle sequence, std::size_t size, const std::string& what) {
  const py::sequence s = py::reinterpret_borrow<py::sequence>(py::module_::import("builtins").attr("list")(sequence));
  if (s.size() != size)
    throw hsx::InputError(what + ": " + std::to_string(s.size()) + " entries, but the complex has " +
                          std::to_string(size) + " cells");
  std::vector<char> flags(size);
  for (std::size_t k = 0; k < size; ++k) {
    const py::object v = s[k];
    if (py::isinstance<py::float_>(v)) throw py::type_error(what + "[" + std::to_string(k) + "]: a float, not 0/1");
    const long x = py::int_(v).cast<long>();
    if (x != 0 && x != 1)
      throw hsx::InputError(what + "[" + std::to_string(k) + "]: " + std::to_string(x) + " is not 0 or 1");
    flags[k] = static_cast<char>(x);
  }
  return flags;
}

void bind_numbers(py::module_& m) {
  py::register_exception<Undecided>(m, "Undecided", PyExc_ArithmeticError);
  bind_order(m);
  bind_measure(m);
}

}  // namespace hsxpy
