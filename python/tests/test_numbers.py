"""Measures: exact strings, floats, certified intervals, comparisons with Tie as an outcome, sympy."""
import math
from fractions import Fraction as F

import pytest

import hsx
from hsx import Measure, Order


def test_rational_measures_are_exact():
    m = Measure(F(1, 3)) + Measure("1/6") + 1
    assert m.rational == F(3, 2)
    assert m.exact == "3/2"
    assert float(m) == 1.5
    assert m == F(3, 2) and m < 2 and m > 1 and m != 0
    assert (m * F(2, 3)).rational == 1
    assert (2 * m).rational == 3
    assert (-m).rational == F(-3, 2)
    assert (1 - m).rational == F(-1, 2)
    assert Measure().is_zero()
    with pytest.raises(TypeError):
        Measure(0.5)


def test_roots_and_pi():
    s = Measure.sqrt(8)
    assert s.exact == "2*sqrt(2)"
    assert s.is_algebraic() and s.rational is None
    p = Measure.pi(F(4, 3)) + Measure.sqrt(3) * F(1, 2)
    assert p.exact == "4/3*pi + 1/2*sqrt(3)"
    assert p.pi_coefficient == F(4, 3)
    assert not p.is_algebraic()
    assert abs(float(p) - (4 / 3 * math.pi + math.sqrt(3) / 2)) < 1e-15
    assert p.decimal(12) == "5.05481560857"  # proven digits
    assert p.decimal_certified(12)
    assert Measure.sqrt(2).compare(F(141421, 100000)) == Order.Greater
    assert hsx.compare(Measure.sqrt(2) * 2, Measure.sqrt(8)) == Order.Equal
    assert Measure.sqrt(2) + Measure.sqrt(3) > Measure.pi()  # 3.146 > 3.1416: proven
    assert Measure.sqrt(2).sign() == 1 and (Measure.sqrt(2) - Measure.sqrt(2)).sign() == 0


def test_certified_interval_contains_the_value():
    m = Measure.pi(2) + Measure.sqrt(5)
    lo, hi = m.interval(200)
    assert isinstance(lo, F) and isinstance(hi, F) and lo < hi
    assert hi - lo < F(1, 2 ** 190)
    flo, fhi = m.float_interval()
    assert flo <= float(m) <= fhi
    assert lo <= F(float(m)) + F(1, 10 ** 12) and F(float(m)) - F(1, 10 ** 12) <= hi


def arcs_on_a_circle():
    """Patches of a radius-5 circle cut by three lines through its centre at angles 0, theta and 2*theta
    (theta = atan2(4, 3)): arcs of angle theta (twice), pi - 2*theta and pi (...)"""
    s = hsx.Scene([hsx.Disk((0, 0), 5, "A"), hsx.HalfPlane((0, 1), 0, "L0"),
                   hsx.HalfPlane((-4, 3), 0, "L1"), hsx.HalfPlane((-24, -7), 0, "L2")])
    c = hsx.arrange(s)
    arcs = [p.measure for p in c.patches if p.halfspace == "A"]
    theta = math.atan2(4, 3)
    one = [m for m in arcs if abs(float(m) - 5 * theta) < 1e-9]
    rest = [m for m in arcs if abs(float(m) - 5 * (math.pi - 2 * theta)) < 1e-9]
    return one[0], rest[0]


def test_a_tie_is_an_outcome_never_a_guess():
    arc_theta, arc_rest = arcs_on_a_circle()  # 5*theta and 5*(pi - 2*theta): 5*pi - rest == 2 * arc_theta
    assert arc_theta.exact is None  # theta is not a multiple of pi/12: no closed form
    lhs, rhs = Measure.pi(5) - arc_rest, arc_theta * 2
    assert abs(float(lhs) - float(rhs)) < 1e-12
    assert lhs.compare(rhs) == Order.Tie
    assert hsx.compare(lhs, rhs, max_bits=256) == Order.Tie
    with pytest.raises(hsx.Undecided, match="Tie"):
        lhs == rhs
    assert issubclass(hsx.Undecided, ArithmeticError)
    # separated values are still decided with proof
    assert lhs.compare(rhs + F(1, 10 ** 6)) == Order.Less
    assert lhs.sign() == 1
    assert not lhs.decimal(10).endswith("~")


def test_sympy_when_installed():
    sympy = pytest.importorskip("sympy")
    m = Measure.pi(F(4, 3)) + Measure.sqrt(3) * F(1, 2)
    assert sympy.simplify(m.sympy() - (sympy.Rational(4, 3) * sympy.pi + sympy.sqrt(3) / 2)) == 0
    arc_theta, _ = arcs_on_a_circle()
    with pytest.raises(ValueError, match="no closed form"):
        arc_theta.sympy()


def test_measures_are_not_hashable():
    with pytest.raises(TypeError):
        hash(Measure(1))
