"""Hertz contact of two tori (paper Eq. 1, App. A): symbolic forms, limits, numerics, errors."""

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain.theory import contact, contact_ellipse, hertz_stiffness, minimum_contact_angle
from ringchain.theory.special import carlson_rd, carlson_rf

S = contact.symbols()
R, r, E, nu, theta, m = (S[k] for k in ("R", "r", "E", "nu", "theta", "m"))


def paper_K_c():
    """Paper Eq. (1) as printed, with 1/E* = 2(1 - nu^2)/E for identical rings (App. A)."""
    E_star = E / (2 * (1 - nu**2))
    return sp.Rational(4, 3) * E_star * sp.sqrt(r * (R - r) / (R - 2 * r))


def test_principal_radii_are_tube_and_inner_equator():
    assert contact.principal_radii() == (r, -(R - r), r, -(R - r))


def test_curvature_sum_matches_app_a():
    total, difference = contact.curvature_sums()
    assert sp.simplify(total - (1 / r - 1 / (R - r))) == 0
    # |A - B| = (1/r + 1/(R - r)) |cos theta|: zero for perpendicular rings (circular contact).
    assert sp.simplify(difference - (1 / r + 1 / (R - r)) * sp.cos(theta)) == 0
    assert difference.subs(theta, sp.pi / 2) == 0


def test_perpendicular_equivalent_radii_are_papers():
    R1, R2 = contact.equivalent_radius_perpendicular()
    expected = r * (R - r) / (R - 2 * r)
    assert sp.simplify(R1 - expected) == 0
    assert sp.simplify(R2 - expected) == 0


def test_effective_modulus_identical_bodies():
    assert sp.simplify(contact.effective_modulus() - E / (2 * (1 - nu**2))) == 0
    E1, E2, n1, n2 = sp.symbols("E1 E2 nu1 nu2", positive=True)
    general = contact.effective_modulus(E1, n1, E2, n2)
    assert sp.simplify(1 / general - ((1 - n1**2) / E1 + (1 - n2**2) / E2)) == 0


def test_circular_hertz_is_paper_eq_1():
    assert sp.simplify(contact.hertz_circular() - paper_K_c()) == 0


def test_elliptical_hertz_reduces_to_circular_as_eccentricity_vanishes():
    K_c, E_star = contact.hertz_elliptical()
    A = S["A"]
    R_e = sp.Symbol("R_e", positive=True)
    circular_limit = sp.limit(K_c.subs(A, 1 / (2 * R_e)), m, 0)
    assert sp.simplify(circular_limit - sp.Rational(4, 3) * E_star * sp.sqrt(R_e)) == 0


def test_shape_ratio_is_one_for_a_circle():
    assert sp.limit(contact.ellipse_shape_ratio(), m, 0) == 1


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


@pytest.mark.parametrize("m_value", [0.2, 0.7])
def test_carlson_rewrite_keeps_the_value(m_value):
    ratio = contact.ellipse_shape_ratio()
    (_,), rewritten = contact._shape_ratio.expression()
    a = ratio.subs(m, sp.Rational(str(m_value))).evalf(30)
    b = rewritten.subs(m, sp.Rational(str(m_value))).evalf(30)
    assert abs(a - b) < 1e-20 * abs(a)  # same number at 30 digits; 1e-20 leaves room for rounding


def _johnson_independent(R_, r_, E_, nu_, theta_):
    """K_c from Johnson's elliptical relations solved with mpmath, independently of the package."""
    with mpmath.workdps(30):
        return _johnson_at_30_digits(R_, r_, E_, nu_, theta_)


def _johnson_at_30_digits(R_, r_, E_, nu_, theta_):
    total = 1 / mpmath.mpf(r_) - 1 / mpmath.mpf(R_ - r_)
    diff = (1 / mpmath.mpf(r_) + 1 / mpmath.mpf(R_ - r_)) * abs(mpmath.cos(theta_))
    A, B = (total - diff) / 2, (total + diff) / 2
    Es = mpmath.mpf(E_) / (2 * (1 - mpmath.mpf(nu_) ** 2))

    def ratio(mm):
        K, Ee = mpmath.ellipk(mm), mpmath.ellipe(mm)
        return (Ee / (1 - mm) - K) / (K - Ee)

    mm = mpmath.findroot(lambda x: ratio(x) - B / A, (mpmath.mpf("1e-12"), mpmath.mpf("0.999999")), solver="anderson")
    K, Ee = mpmath.ellipk(mm), mpmath.ellipe(mm)
    a = mpmath.mpf("1e-4")  # any semi-axis: K_c does not depend on the load
    b = a * mpmath.sqrt(1 - mm)
    p0 = A * Es * a**2 * mm / (b * (K - Ee))
    P = 2 * mpmath.pi * a * b * p0 / 3
    delta = p0 * b * K / Es
    return float(P / delta**1.5), float(mm)


@pytest.mark.parametrize(("aspect", "angle_deg"), [(9.0, 85.0), (9.0, 60.0), (8.0, 45.0), (4.0, 70.0), (3.1, 89.0)])
def test_elliptical_stiffness_against_independent_johnson_solution(aspect, angle_deg):
    r_ = 2.5e-3
    R_ = aspect * r_
    expected, m_expected = _johnson_independent(R_, r_, 193e9, 0.29, np.radians(angle_deg))
    _, _, m_value = contact_ellipse(R_, r_, np.radians(angle_deg))
    # The bisection resolves m to 2^-60 and the rest is double-precision arithmetic: 1e-12.
    assert np.isclose(m_value, m_expected, rtol=1e-9, atol=1e-14)
    assert np.isclose(hertz_stiffness(R_, r_, 193e9, 0.29, np.radians(angle_deg)), expected, rtol=1e-12)


@pytest.mark.parametrize("aspect", [2.2, 3.1, 9.0, 50.0])
def test_numeric_circular_stiffness_equals_evalf(aspect):
    values = {R: aspect * 2.5e-3, r: 2.5e-3, E: 193e9, nu: 0.29}
    expected = float(contact.hertz_circular().evalf(20, subs=values))
    got = hertz_stiffness(values[R], values[r], values[E], values[nu])
    assert np.isclose(got, expected, rtol=1e-13)  # double-precision evaluation of the same expression


def test_perpendicular_limit_is_continuous():
    args = (22.5e-3, 2.5e-3, 193e9, 0.29)
    circle = hertz_stiffness(*args)
    near = hertz_stiffness(*args, angle=np.pi / 2 - 1e-7)
    # K_c(theta) is smooth and even about pi/2, so the change is O((1e-7)^2): far below 1e-10.
    assert abs(near / circle - 1) < 1e-10


def test_broadcasting():
    angles = np.radians([50.0, 70.0, 90.0])
    out = hertz_stiffness(np.array([[20e-3], [22.5e-3]]), 2.5e-3, 193e9, 0.29, angles)
    assert out.shape == (2, 3)
    assert np.isclose(out[1, 2], hertz_stiffness(22.5e-3, 2.5e-3, 193e9, 0.29))


def test_minimum_angle():
    # cos(theta_min) = 1 - 2 r/R = 0.75 for R/r = 8.
    assert np.isclose(minimum_contact_angle(20e-3, 2.5e-3), np.arccos(0.75))


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (dict(R=5e-3, r=2.5e-3, E=193e9, nu=0.29), "R must exceed 2 r"),
        (dict(R=4e-3, r=2.5e-3, E=193e9, nu=0.29), "R must exceed 2 r"),
        (dict(R=-1.0, r=2.5e-3, E=193e9, nu=0.29), "R must be positive"),
        (dict(R=20e-3, r=2.5e-3, E=-1.0, nu=0.29), "E must be positive"),
        (dict(R=20e-3, r=2.5e-3, E=193e9, nu=0.6), "nu must lie in"),
        (dict(R=20e-3, r=2.5e-3, E=193e9, nu=0.29, angle=np.radians(30)), "single elliptical Hertz contact"),
        (dict(R=20e-3, r=2.5e-3, E=193e9, nu=0.29, angle=2.0), "angle must lie in"),
        (dict(R=np.nan, r=2.5e-3, E=193e9, nu=0.29), "R must be finite"),
    ],
)
def test_bad_inputs_name_the_problem(kwargs, message):
    with pytest.raises(ValueError, match=message):
        hertz_stiffness(**kwargs)


@settings(max_examples=60, deadline=None)
@given(
    aspect=st.floats(2.05, 40.0),
    r_=st.floats(1e-4, 1e-2),
    frac=st.floats(0.01, 1.0),
)
def test_stiffness_positive_and_stiffer_when_oblique(aspect, r_, frac):
    R_ = aspect * r_
    lowest = float(minimum_contact_angle(R_, r_))
    angle = lowest + frac * (np.pi / 2 - lowest)
    K = hertz_stiffness(R_, r_, 193e9, 0.29, angle)
    K90 = hertz_stiffness(R_, r_, 193e9, 0.29)
    assert np.isfinite(K) and K > 0
    # Tilting the rings spreads A and B apart at fixed A + B, which raises the equivalent radius:
    # the contact never gets softer than the perpendicular one (1e-12: rounding).
    assert K >= K90 * (1 - 1e-12)
