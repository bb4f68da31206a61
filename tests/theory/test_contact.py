"""Hertz contact of two tori (paper Eq. 1, App. A): symbolic forms, limits, numerics, errors."""

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain.theory import contact, contact_ellipse, elliptical, hertz_stiffness, minimum_contact_angle

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


@pytest.mark.parametrize("m_value", ["0", "1e-12", "0.2", "0.7", "0.999999", "0.99999999999999999999"])
def test_carlson_forms_against_mpmath_closed_forms(m_value):
    # The shape ratio and the elliptical factor in Carlson's form (in m_1 = 1 - m), evaluated by
    # mpmath at 30 digits, against Johnson's forms with mpmath's own K(m) and E(m): independent of
    # the rewrite, and across the whole range, m = 0 (a limit there) to m -> 1.
    m_1 = S["m_1"]
    with mpmath.workdps(60):  # 1 - m keeps 40 digits at m = 1 - 1e-20
        mm = mpmath.mpf(m_value)
        K, Ei = mpmath.ellipk(mm), mpmath.ellipe(mm)
        if mm == 0:
            ratio, factor = mpmath.mpf(1), mpmath.mpf(1)
        else:
            ratio = (Ei / (1 - mm) - K) / (K - Ei)
            # Gamma = K_c(m, A)/K_c(0, A): Johnson's elliptical relations against the sphere's 4/3 E* sqrt(R_e).
            curvature = mpmath.mpf(50)
            factor = _johnson_stiffness(mm, curvature, 1) / (mpmath.mpf(4) / 3 * mpmath.sqrt(1 / (2 * curvature)))
        exact_m_1 = 1 - sp.Rational(m_value)
        derived_ratio = elliptical.carlson_form(elliptical.ellipse_shape_ratio()).subs(m_1, exact_m_1).evalf(30)
        derived_factor = elliptical.carlson_form(elliptical.elliptical_factor()).subs(m_1, exact_m_1).evalf(30)
    # 30-digit evaluation of both sides: agreement to 1e-25.
    assert abs(derived_ratio / sp.Float(ratio, 40) - 1) < 1e-25
    assert abs(derived_factor / sp.Float(factor, 40) - 1) < 1e-25


def _johnson_stiffness(mm, A, Es):
    """K_c = P/delta^(3/2) from Johnson's elliptical relations (Sec. 4.2) at eccentricity mm, curvature A, E* Es."""
    K, Ee = mpmath.ellipk(mm), mpmath.ellipe(mm)
    a = mpmath.mpf("1e-4")  # any semi-axis: K_c does not depend on the load
    b = a * mpmath.sqrt(1 - mm)
    p0 = A * Es * a**2 * mm / (b * (K - Ee))
    P = 2 * mpmath.pi * a * b * p0 / 3
    delta = p0 * b * K / Es
    return P / delta**1.5


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
    return float(_johnson_stiffness(mm, A, Es)), float(mm)


@pytest.mark.parametrize(("aspect", "angle_deg"), [(9.0, 85.0), (9.0, 60.0), (8.0, 45.0), (4.0, 70.0), (3.1, 89.0)])
def test_elliptical_stiffness_against_independent_johnson_solution(aspect, angle_deg):
    r_ = 2.5e-3
    R_ = aspect * r_
    expected, m_expected = _johnson_independent(R_, r_, 193e9, 0.29, np.radians(angle_deg))
    _, _, m_value = contact_ellipse(R_, r_, np.radians(angle_deg))
    # The bisection resolves m to 2^-60 and the rest is double-precision arithmetic: 1e-12.
    assert np.isclose(m_value, m_expected, rtol=1e-9, atol=1e-14)
    assert np.isclose(hertz_stiffness(R_, r_, 193e9, 0.29, np.radians(angle_deg)), expected, rtol=1e-12, atol=0)


@pytest.mark.parametrize("aspect", [2.0000001, 2.2, 3.1, 9.0, 50.0, 1e6])
def test_numeric_circular_stiffness_is_papers_eq_1(aspect):
    r_ = 2.5e-3
    R_ = aspect * r_
    with mpmath.workdps(30):  # paper Eq. (1), typed here, with 1/E* = 2(1 - nu^2)/E (App. A)
        E_star = mpmath.mpf(193e9) / (2 * (1 - mpmath.mpf(0.29) ** 2))
        expected = 4 * E_star / 3 * mpmath.sqrt(r_ * (mpmath.mpf(R_) - r_) / (mpmath.mpf(R_) - 2 * r_))
    # A few roundings in double precision (R - 2r is exact by Sterbenz near R = 2r): 1e-15.
    assert np.isclose(hertz_stiffness(R_, r_, 193e9, 0.29), float(expected), rtol=1e-15, atol=0)


def test_circular_limit_of_the_elliptical_solution_is_papers_eq_1():
    K_c, E_star = elliptical.circular_limit()
    A90, _ = contact.relative_curvatures()
    K_c = K_c.subs(S["A"], A90.subs(theta, sp.pi / 2)).subs(E_star, contact.effective_modulus())
    # Squares: both sides are positive, and SymPy does not see sqrt(x) sqrt(1/x) = 1 by itself.
    assert sp.simplify(K_c**2 - paper_K_c() ** 2) == 0
    assert sp.simplify(K_c**2 - contact.hertz_circular() ** 2) == 0  # the sphere relations give the same


def test_minimum_angle_solves_a_equals_zero():
    A, _ = contact.relative_curvatures()
    assert sp.simplify(sp.expand_trig(A.subs(theta, contact.minimum_angle()))) == 0


def test_half_angle_curvatures_are_a_and_b():
    A, B = contact.relative_curvatures()
    A_half, excess = contact.half_angle_curvatures()
    assert sp.simplify(sp.expand_trig(A_half - A)) == 0
    assert sp.simplify(sp.expand_trig(A_half * (1 + excess) - B)) == 0


@pytest.mark.parametrize("aspect", [2.5, 8.0, 1e4, 1e12])
def test_minimum_angle_against_mpmath(aspect):
    # arccos(1 - 2r/R) at 40 digits; in double precision 1 - 2r/R rounds away r/R for thin rings,
    # and arccos then loses half the digits (at R/r = 1e12, most of them): the half-angle form keeps them.
    with mpmath.workdps(40):
        expected = mpmath.acos(1 - 2 / mpmath.mpf(aspect))
    assert np.isclose(
        minimum_contact_angle(aspect * 2.5e-3, 2.5e-3), float(expected), rtol=4e-16, atol=0
    )  # a few roundings


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
    for i, R_ in enumerate((20e-3, 22.5e-3)):
        for j, angle in enumerate(angles):
            # Element by element the same number: the interpolated factor at 90 degrees is 1 to rounding.
            assert np.isclose(out[i, j], hertz_stiffness(R_, 2.5e-3, 193e9, 0.29, angle), rtol=1e-15, atol=0)


def test_broadcasting_error_names_the_arguments():
    with pytest.raises(ValueError, match=r"R \(shape \(3,\)\) and r \(shape \(2,\)\) cannot be broadcast"):
        hertz_stiffness([20e-3, 21e-3, 22e-3], [2e-3, 2.5e-3], 193e9, 0.29)
    with pytest.raises(ValueError, match=r"r \(shape \(2,\)\) and angle \(shape \(3,\)\)"):
        contact_ellipse(22e-3, [2e-3, 2.5e-3], [1.0, 1.2, 1.4])


def test_perpendicular_contact_is_exactly_circular():
    # angle = pi/2 (the double nearest it) means perpendicular rings: A = B and m = 0 exactly.
    A, B, m_value = contact_ellipse(np.array([8e-3, 22.5e-3, 1.0]), 2.5e-3, np.pi / 2)
    assert np.array_equal(A, B) and np.all(m_value == 0.0)


def _stiffness_from_curvatures(A, B, E_, nu_):
    """K_c from Johnson's relations at given relative curvatures A <= B, solved in mpmath (40 digits)."""
    with mpmath.workdps(40):
        A, B = mpmath.mpf(A), mpmath.mpf(B)
        Es = mpmath.mpf(E_) / (2 * (1 - mpmath.mpf(nu_) ** 2))
        if A == B:
            return float(mpmath.mpf(4) / 3 * Es * mpmath.sqrt(1 / (2 * A)))

        def log_ratio(y):  # ln(B/A)(m_1 = e^y), Carlson's forms, accurate as m_1 -> 0
            m_1 = mpmath.exp(y)
            return mpmath.log(mpmath.elliprd(0, 1, m_1) / mpmath.elliprd(0, m_1, 1))

        target = mpmath.log(B / A)
        # ln(B/A) falls monotonically as y = ln(m_1) rises to 0; B/A ~ 1/(m_1 ln(4/sqrt(m_1))) brackets the root.
        lower = -(target + mpmath.log(1 + target) + 4)
        y = mpmath.findroot(lambda y: log_ratio(y) - target, (lower, mpmath.mpf(0)), solver="anderson")
        m_1 = mpmath.exp(y)
        K, D = mpmath.elliprf(0, m_1, 1), mpmath.elliprd(0, m_1, 1) / 3  # K(m), (K - E)/m
        a = mpmath.mpf(1)
        b = a * mpmath.sqrt(m_1)
        p0 = A * Es * a**2 / (b * D)  # Johnson: A = p0 b (K - E)/(E* a^2 m)
        P, delta = 2 * mpmath.pi * a * b * p0 / 3, p0 * b * K / Es
        return float(P / delta**1.5)


@settings(max_examples=30, deadline=None, derandomize=True)
@given(aspect=st.floats(2.01, 1e3), closeness=st.floats(-16.0, -1e-3))
def test_stiffness_over_the_whole_range_of_shapes(aspect, closeness):
    # From the circle to ln(B/A) ~ 40 (angles within 1e-16 relative of theta_min): the interpolated
    # factor against Johnson's relations solved in mpmath at the same curvatures A, B (the ones the
    # package reports), so that only the solution of the shape equation is compared.  An angle that
    # close to theta_min determines A to no better than rounding, whatever the method.
    r_ = 2.5e-3
    R_ = aspect * r_
    lowest = float(minimum_contact_angle(R_, r_))
    angle = lowest + 10.0**closeness * (np.pi / 2 - lowest)
    try:
        A, B, _ = contact_ellipse(R_, r_, angle)
    except ValueError as error:  # the angle rounded onto theta_min
        assert "at or below theta_min" in str(error)
        return
    expected = _stiffness_from_curvatures(A, B, 193e9, 0.29)
    # The table's interpolation error is checked below 1e-14 when it is built; 2e-15 measured.
    assert np.isclose(hertz_stiffness(R_, r_, 193e9, 0.29, angle), expected, rtol=1e-14, atol=0)


def test_angles_just_above_the_minimum_are_finite():
    # Before: NaN (and a RuntimeWarning) one to a few ulps above theta_min.
    R_, r_ = 22.5e-3, 2.5e-3
    angle = float(minimum_contact_angle(R_, r_))
    checked = 0
    for _ in range(16):
        angle = np.nextafter(angle, 2.0)
        try:
            K = hertz_stiffness(R_, r_, 193e9, 0.29, angle)
            A, B, m_value = contact_ellipse(R_, r_, angle)
        except ValueError as error:  # the computed A is 0: the angle is theta_min to double precision
            assert "at or below theta_min" in str(error)
            continue
        checked += 1
        assert np.isfinite(K) and 0 < m_value <= 1  # 1 - m below 1e-16 rounds m to 1
        assert np.isclose(K, _stiffness_from_curvatures(A, B, 193e9, 0.29), rtol=1e-14, atol=0)  # table accuracy
    assert checked > 10


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
        (dict(R=20e-3, r=2.5e-3, E=193e9, nu=0.29, angle=0.5), r"angle 0\.5 rad \(28\.6479 deg\) is at or below"),
        (dict(R=4.999999999e-3, r=2.5e-3, E=193e9, nu=0.29), r"R/r = 1\.99999999959"),
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


# --- the semi-axes of the contact ellipse (issue 24, item 3: where the Hertz ellipse leaves the half-space) --


def _johnson_semi_axes(R_, r_, E_, nu_, theta_, P):
    """(a, b) from Johnson's relations (Sec. 4.2) at 30 digits: a^3 = 3 P (K - E)/(2 pi m A E*), b = a sqrt(1 - m)."""
    with mpmath.workdps(30):
        total = 1 / mpmath.mpf(r_) - 1 / mpmath.mpf(R_ - r_)
        diff = (1 / mpmath.mpf(r_) + 1 / mpmath.mpf(R_ - r_)) * abs(mpmath.cos(theta_))
        A = (total - diff) / 2
        Es = mpmath.mpf(E_) / (2 * (1 - mpmath.mpf(nu_) ** 2))
        _, mm = _johnson_at_30_digits(R_, r_, E_, nu_, theta_)
        mm = mpmath.mpf(mm)
        D = (mpmath.ellipk(mm) - mpmath.ellipe(mm)) / mm if mm > 1e-20 else mpmath.pi / 4
        a = (3 * P * D / (2 * mpmath.pi * A * Es)) ** (mpmath.mpf(1) / 3)
        return float(a), float(a * mpmath.sqrt(1 - mm))


@pytest.mark.parametrize(("aspect", "angle_deg"), [(9.0, 90.0), (9.0, 85.0), (9.0, 55.0), (8.0, 45.0), (3.1, 89.0)])
def test_semi_axes_against_johnson(aspect, angle_deg):
    r_ = 2.5e-3
    R_ = aspect * r_
    a, b = contact.contact_semi_axes(R_, r_, 193e9, 0.29, np.radians(angle_deg), F=100.0)
    a_ref, b_ref = _johnson_semi_axes(R_, r_, 193e9, 0.29, np.radians(angle_deg), 100.0)
    # m from the package's table (1e-9 relative, test above) enters a through (K - E)/m and b through
    # sqrt(1 - m): 1e-9 leaves room for both.
    assert (float(a), float(b)) == (pytest.approx(a_ref, rel=1e-9), pytest.approx(b_ref, rel=1e-9))


def test_semi_axes_of_the_circle_are_hertz_spheres():
    R_, r_, E_, nu_ = 22.5e-3, 2.5e-3, 193e9, 0.29
    F = np.array([1.0, 100.0])
    a, b = contact.contact_semi_axes(R_, r_, E_, nu_, F=F)
    R_e = r_ * (R_ - r_) / (R_ - 2 * r_)  # App. A
    E_star = E_ / (2 * (1 - nu_**2))
    # Johnson's sphere a^3 = 3 P R_e/(4 E*), typed independently: rounding only.
    np.testing.assert_allclose(a, (3 * F * R_e / (4 * E_star)) ** (1 / 3), rtol=1e-14)
    np.testing.assert_array_equal(a, b)
    # The approach of the same contact: delta = a^2/R_e, so F = K_c delta^1.5 holds with these semi-axes.
    np.testing.assert_allclose(F, hertz_stiffness(R_, r_, E_, nu_) * (a**2 / R_e) ** 1.5, rtol=1e-13)


def test_semi_axes_refuse_what_has_no_ellipse():
    with pytest.raises(ValueError, match="at or below theta_min"):
        contact.contact_semi_axes(22.5e-3, 2.5e-3, 193e9, 0.29, 0.5, F=1.0)
    with pytest.raises(ValueError, match="F must be positive"):
        contact.contact_semi_axes(22.5e-3, 2.5e-3, 193e9, 0.29, F=0.0)
