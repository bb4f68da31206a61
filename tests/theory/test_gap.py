"""The exact gap of two interlocked tori (theory/gap.py): derivation, its Hertz limit, two contacts."""

import mpmath
import numpy as np
import pytest
import sympy as sp
from ringchain.theory import contact, contact_modulus, contact_patches, gap, minimum_contact_angle, torus_gap
from scipy import optimize

S, G = contact.symbols(), gap.gap_symbols()
R, r, theta, L = S["R"], S["r"], S["theta"], G["L"]
R_, r_ = 22.5e-3, 2.5e-3  # the paper's R/r = 9 ring


def test_torus_distance_against_sampled_centre_circle():
    # Independent: the distance to 200 000 points of the centre circle, minimised by brute force.
    rng = np.random.default_rng(7)
    phi = np.linspace(0, 2 * np.pi, 200_000, endpoint=False)
    circle = R_ * np.stack([np.cos(phi), np.zeros_like(phi), np.sin(phi)])
    points = rng.uniform(-1.2 * R_, 1.2 * R_, size=(5, 3))
    D, _ = gap.torus_distance(*points.T, R_, r_)
    for point, value in zip(points, D, strict=True):
        brute = np.min(np.linalg.norm(circle - point[:, None], axis=0)) - r_
        # The sampled circle's chord error is R (pi/200000)^2/2 ~ 3e-12 m.
        assert value == pytest.approx(brute, abs=1e-11)


def test_torus_distance_gradient_is_the_unit_normal():
    rng = np.random.default_rng(3)
    X, Y, Z = rng.uniform(-0.03, 0.03, size=(3, 50))
    _D, gradient = gap.torus_distance(X, Y, Z, R_, r_)
    assert np.allclose(np.linalg.norm(np.stack(gradient), axis=0), 1.0, rtol=1e-12)  # a distance function
    h = 1e-7
    plus, minus = gap.torus_distance(X + h, Y, Z, R_, r_)[0], gap.torus_distance(X - h, Y, Z, R_, r_)[0]
    numeric = (plus - minus) / (2 * h)
    assert np.allclose(gradient[0], numeric, atol=1e-7)  # central difference, error ~ h^2 D''' ~ 1e-10


def test_inner_surface_lies_on_the_torus():
    f = gap.inner_surface_height()
    p, q = G["p"], G["q"]
    on_torus = gap.torus_distance_expr().subs({G["X"]: p, G["Y"]: q, G["Z"]: f + R - r})
    # Evaluated at 40 digits with mpmath (SymPy's evalf of an exact zero keeps raising its precision).
    distance = sp.lambdify((p, q), on_torus.subs({R: 9, r: 1}), "mpmath")
    with mpmath.workdps(40):
        for p_value, q_value in ((0.3, 0.2), (-0.9, 0.6), (2.0, -0.95)):
            assert abs(distance(mpmath.mpf(p_value), mpmath.mpf(q_value))) < 1e-35  # zero to 40 digits
    assert sp.simplify(f.subs({p: 0, q: 0}).subs(R, L + r)) == 0  # through the inner equator


def test_quadratic_part_of_the_exact_gap_gives_the_hertz_curvatures():
    """App. A, Eqs. (A1)-(A2): the gap's quadratic form has eigenvalues A and B."""
    x, y = G["x"], G["y"]
    quadratic = gap.surface_gap_quadratic()
    M = sp.Matrix(
        [
            [quadratic.coeff(x, 2), quadratic.coeff(x, 1).coeff(y, 1) / 2],
            [quadratic.coeff(x, 1).coeff(y, 1) / 2, quadratic.coeff(y, 2)],
        ]
    )
    A, B = (c.subs(R, L + r) for c in contact.relative_curvatures())
    total, difference = (c.subs(R, L + r) for c in contact.curvature_sums())
    assert sp.simplify(M.trace() - (A + B)) == 0
    assert sp.simplify(M.trace() - total) == 0
    assert sp.simplify(M.det() - A * B) == 0
    # The eigenvalues' difference is |A - B| of Eq. (A2b).
    assert sp.simplify((M.trace() ** 2 - 4 * M.det()) - difference**2) == 0


def test_torus_gap_matches_its_quadratic_part_near_the_axis():
    A, B, _ = contact.contact_ellipse(R_, r_, np.radians(60))
    e = np.array([np.cos(np.radians(30)), np.sin(np.radians(30))])
    for s in (1e-5, 1e-4):
        along = torus_gap(s * e[0], s * e[1], R_, r_, np.radians(60))
        across = torus_gap(-s * e[1], s * e[0], R_, r_, np.radians(60))
        # The next terms are quartic: relative error (s/r)^2 up to a factor of order one.
        assert along == pytest.approx(A * s**2, rel=10 * (s / r_) ** 2)
        assert across == pytest.approx(B * s**2, rel=10 * (s / r_) ** 2)


@pytest.mark.parametrize("angle_deg", [75.0, 30.0])
def test_torus_gap_symmetries(angle_deg):
    """Half turn about the chain axis, and the reflection in the bisector plane that swaps the rings."""
    rng = np.random.default_rng(11)
    x, y = rng.uniform(-1.5e-3, 1.5e-3, size=(2, 40))
    half = np.radians(angle_deg) / 2
    g = torus_gap(x, y, R_, r_, np.radians(angle_deg))
    assert np.allclose(torus_gap(-x, -y, R_, r_, np.radians(angle_deg)), g, rtol=1e-12, atol=1e-18)
    # Reflection in the line at angle theta/2: (x, y) -> rotation by theta of (x, -y).
    xr = np.cos(2 * half) * x + np.sin(2 * half) * y
    yr = np.sin(2 * half) * x - np.cos(2 * half) * y
    assert np.allclose(torus_gap(xr, yr, R_, r_, np.radians(angle_deg)), g, rtol=1e-12, atol=1e-18)


def test_torus_gap_refuses_points_off_the_tubes():
    with pytest.raises(ValueError, match="over both tubes"):
        torus_gap(0.0, 1.1 * r_, R_, r_, np.pi / 2)


@pytest.mark.parametrize("angle_deg", [36.0, 30.0, 20.0])
def test_two_contact_points_against_a_numerical_minimum(angle_deg):
    angle = np.radians(angle_deg)
    c, gap, tilt = (float(v) for v in contact_patches(R_, r_, angle))

    def g(point):
        try:
            return float(torus_gap(point[0] * r_, point[1] * r_, R_, r_, angle)) / r_
        except ValueError:  # off the tubes: no contact there
            return 1.0

    start = 0.9 * c / r_ * np.array([np.cos(angle / 2), np.sin(angle / 2)]) + np.array([0.05, -0.05])
    found = optimize.minimize(g, start, method="Nelder-Mead", options=dict(xatol=1e-10, fatol=1e-16))
    # A minimum located from gap values rounded at ~1e-18 m with curvature A ~ 50/m is fixed only to
    # sqrt(1e-18/50) ~ 1e-10 m in position; its value agrees to rounding.
    assert found.x * r_ == pytest.approx(c * np.array([np.cos(angle / 2), np.sin(angle / 2)]), abs=1e-9)
    assert found.fun * r_ == pytest.approx(gap, rel=1e-9)
    # Closed forms, typed independently: gap = 2 (cos(t/2) sqrt(R^2 - r^2/sin^2(t/2)) - (R - r)),
    # tan(tilt) = c / sqrt(R^2 sin^2(t/2) - r^2).
    s2 = np.sin(angle / 2)
    assert gap == pytest.approx(2 * (np.cos(angle / 2) * np.sqrt(R_**2 - r_**2 / s2**2) - (R_ - r_)), rel=1e-12)
    assert np.tan(tilt) == pytest.approx(c / np.sqrt(R_**2 * s2**2 - r_**2), rel=1e-12)


def test_tilt_is_the_slope_of_the_tube_at_the_contact_point():
    angle = np.radians(30.0)
    c, _, tilt = (float(v) for v in contact_patches(R_, r_, angle))
    p, q = c * np.cos(angle / 2), c * np.sin(angle / 2)
    f = gap.inner_surface_height()
    height = sp.lambdify((G["p"], G["q"]), f.subs({R: sp.Rational(225, 10000), r: sp.Rational(25, 10000)}), "mpmath")
    with mpmath.workdps(30):
        slope = [mpmath.diff(lambda s: height(s, q), p), mpmath.diff(lambda s: height(p, s), q)]
        expected = float(mpmath.atan(mpmath.sqrt(slope[0] ** 2 + slope[1] ** 2)))
    assert tilt == pytest.approx(expected, rel=1e-10)


def test_one_contact_at_and_above_theta_min_and_continuity_below():
    lowest = float(minimum_contact_angle(R_, r_))
    c, gap, tilt = contact_patches(R_, r_, np.array([np.pi / 2, np.radians(60), lowest]))
    assert np.all(c == 0) and np.all(gap == 0) and np.all(tilt == 0)
    eps = np.array([1e-4, 1e-6, 1e-8])
    c, gap, tilt = contact_patches(R_, r_, lowest - eps)
    assert np.all(np.diff(c) < 0) and np.all(c > 0) and c[-1] < 1e-3 * r_  # c ~ sqrt(eps): -> 0
    # gap ~ -eps^2 r: below 1e-16 r (rounding) at eps = 1e-8, where it may round to 0.
    assert np.all(gap[:2] < 0) and gap[-1] <= 0 and abs(gap[-1]) < 1e-12 * r_


def test_contact_points_refused_past_the_sides_of_the_tubes():
    with pytest.raises(ValueError, match="sides of the tubes"):
        contact_patches(R_, r_, 2 * np.arcsin(r_ / R_))


def test_contact_modulus_is_app_a():
    assert float(contact_modulus(193e9, 0.29)) == pytest.approx(193e9 / (2 * (1 - 0.29**2)), rel=1e-14)
    with pytest.raises(ValueError, match="nu"):
        contact_modulus(193e9, 0.5)


def test_fold_quartic_is_the_quartic_of_the_exact_gap_at_theta_min():
    derived = gap.fold_quartic()
    assert sp.simplify(derived - 1 / (4 * R * r * (R - r))) == 0
    # Independent: the height of each inner tube surface solved from the torus's own equation
    # (sqrt(x^2 + z^2) - R)^2 + y^2 = r^2 at 40 digits, summed for both rings along the bisector at theta_min,
    # where the gap is C c^4 + D c^6 + ...: g/c^4 at c and c/2, extrapolated (Richardson) to c = 0.
    mpmath.mp.dps = 40
    R0, r0 = mpmath.mpf("22.5e-3"), mpmath.mpf("2.5e-3")
    half = mpmath.asin(mpmath.sqrt(r0 / R0))  # theta_min / 2 (contact.minimum_angle)

    def height(x, y):  # the inner surface above its inner-equator point (ring 1's own coordinates)
        return mpmath.findroot(lambda z: (mpmath.sqrt(x**2 + z**2) - R0) ** 2 + y**2 - r0**2, R0 - r0) - (R0 - r0)

    def along(c):  # ring 1 at (c cos, c sin) of the half angle, ring 2 (turned by theta) at (c cos, -c sin)
        x, y = c * mpmath.cos(half), c * mpmath.sin(half)
        return (height(x, y) + height(x, -y)) / c**4

    c = mpmath.mpf("1e-6")
    quartic = (4 * along(c / 2) - along(c)) / 3  # the c^2 term of g/c^4 cancelled: error ~ (c/r)^4 ~ 1e-14
    expected = float(derived.subs({R: R_, r: r_}))
    assert float(quartic) == pytest.approx(expected, rel=1e-9)  # Richardson's remainder, and 40 digits
    mpmath.mp.dps = 15
