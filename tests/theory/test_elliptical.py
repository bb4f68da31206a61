"""Hertz's elliptical contact of two bodies (Johnson Sec. 4.2): its circular limit, the shape equation, Carlson's forms.

The table that inverts the shape equation is checked through the stiffness of two tori in test_contact.py.
"""

import mpmath
import pytest
import sympy as sp
from ringchain.theory import elliptical
from ringchain.theory.special import carlson_rd, carlson_rf

S = elliptical.symbols()
m = S["m"]


def test_elliptical_hertz_reduces_to_circular_as_eccentricity_vanishes():
    K_c, E_star = elliptical.hertz_elliptical()
    A = S["A"]
    R_e = sp.Symbol("R_e", positive=True)
    circular_limit = sp.limit(K_c.subs(A, 1 / (2 * R_e)), m, 0)
    assert sp.simplify(circular_limit - sp.Rational(4, 3) * E_star * sp.sqrt(R_e)) == 0


def test_shape_ratio_is_one_for_a_circle():
    assert sp.limit(elliptical.ellipse_shape_ratio(), m, 0) == 1


@pytest.mark.parametrize("m_value", [0.0, 1e-6, 0.1, 0.5, 0.9, 0.999])
def test_carlson_identities_against_mpmath(m_value):
    with mpmath.workdps(30):
        mv = mpmath.mpf(str(m_value))
        K, Ei = sp.Float(mpmath.ellipk(mv), 30), sp.Float(mpmath.ellipe(mv), 30)
    exact_m = sp.Rational(str(m_value))
    rf = carlson_rf(0, 1 - m, 1).subs(m, exact_m).evalf(30)
    rd = carlson_rd(0, 1 - m, 1).subs(m, exact_m).evalf(30)
    # 25 digits: both sides are evaluated by mpmath at 30 digits.
    assert abs(rf - K) < 1e-25
    assert abs(exact_m * rd / 3 - (K - Ei)) < 1e-25


def test_elliptical_factor_is_one_for_a_circle():
    assert sp.limit(elliptical.elliptical_factor(), m, 0) == 1
