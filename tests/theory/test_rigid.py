"""Rigid tori (theory/rigid.py): moments of inertia and the Hertz stiffness of two surfaces at any contact, each
against an independent computation (the known closed forms, quadrature, App. A's torus formulas, Johnson's
elliptical relations evaluated in mpmath)."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
import sympy as sp
from ringchain.theory import (
    contact_modulus,
    contact_modulus_pair,
    elliptical_factor_grid,
    hertz_stiffness,
    hertz_stiffness_curvatures,
    hertz_stiffness_pair,
    minimum_contact_angle,
    rigid,
    torus_moments,
)
from ringchain.theory.contact import curvature_sums_pair, pair_symbols, symbols
from scipy import integrate

STEEL = (193e9, 0.29)


# -- moments of inertia --------------------------------------------------------------------------------------
def test_moments_derived_over_the_volume_are_the_known_forms():
    t = rigid.torus_symbols()
    R, r, m = t["R"], t["r"], t["m"]
    I_diameter, I_axis = rigid.moments_of_inertia()
    assert sp.simplify(I_diameter - m * (R**2 / 2 + sp.Rational(5, 8) * r**2)) == 0
    assert sp.simplify(I_axis - m * (R**2 + sp.Rational(3, 4) * r**2)) == 0


def test_torus_moments_equal_the_derivation_and_a_quadrature():
    R, r, m = 0.02, 0.004, 0.03
    I_diameter, I_axis = torus_moments(R, r, m=m)
    t = rigid.torus_symbols()
    at = {t["R"]: R, t["r"]: r, t["m"]: m}
    exact = [float(x.evalf(30, subs=at)) for x in rigid.moments_of_inertia()]
    assert float(I_diameter) == pytest.approx(exact[0], rel=1e-15)  # one rounding of a few products
    assert float(I_axis) == pytest.approx(exact[1], rel=1e-15)

    # SciPy's quadrature over the volume in cylindrical coordinates (rho from the axis, z): no SymPy involved
    def moment(weight):
        def integrand(z, rho):
            return weight(rho, z) * 2 * np.pi * rho  # the whole turn about the axis

        def half_height(rho):
            return np.sqrt(max(r**2 - (rho - R) ** 2, 0.0))

        value, _ = integrate.dblquad(
            integrand, R - r, R + r, lambda rho: -half_height(rho), half_height, epsabs=0, epsrel=1e-12
        )
        return value

    volume = moment(lambda rho, z: 1.0)
    axis = moment(lambda rho, z: rho**2) * m / volume
    diameter = moment(lambda rho, z: rho**2 / 2 + z**2) * m / volume  # <y^2> = <rho^2>/2 by symmetry
    assert volume == pytest.approx(2 * np.pi**2 * R * r**2, rel=1e-9)  # quadrature tolerance 1e-12, with margin
    assert float(I_axis) == pytest.approx(axis, rel=1e-9)
    assert float(I_diameter) == pytest.approx(diameter, rel=1e-9)


def test_torus_moments_broadcast_and_refuse_bad_rings():
    I_diameter, I_axis = torus_moments(np.array([0.02, 0.03]), 0.002, m=np.array([[0.01], [0.02]]))
    assert I_diameter.shape == I_axis.shape == (2, 2)
    assert I_axis[1, 0] == pytest.approx(0.02 * (0.02**2 + 0.75 * 0.002**2), rel=1e-15)  # the closed form
    with pytest.raises(ValueError, match="r must be smaller than R"):
        torus_moments(0.01, 0.01, m=1.0)
    with pytest.raises(ValueError, match=r"m must be positive.*kg"):
        torus_moments(0.02, 0.002, m=0.0)
    with pytest.raises(ValueError, match=r"R must be positive.*m"):
        torus_moments(-0.02, 0.002, m=1.0)
    with pytest.raises(TypeError):
        torus_moments(0.02, 0.002, 1.0)  # the mass is keyword-only


# -- curvature sums ------------------------------------------------------------------------------------------------
def test_general_sums_are_app_a_for_two_tori_at_their_crossing():
    c, p, s = rigid.curvature_symbols(), pair_symbols(), symbols()
    total, difference = rigid.curvature_sums_general()
    crossing = {
        c["k1a"]: -1 / (p["R1"] - p["r1"]), c["k1b"]: 1 / p["r1"],
        c["k2a"]: -1 / (p["R2"] - p["r2"]), c["k2b"]: 1 / p["r2"], c["alpha"]: s["theta"],
    }  # fmt: skip
    total_pair, difference_pair = curvature_sums_pair()
    assert sp.simplify(total.subs(crossing) - total_pair) == 0
    assert sp.simplify(sp.expand_trig((difference.subs(crossing) ** 2 - difference_pair**2).expand())) == 0


def test_relative_curvature_matrix_has_the_curvatures_of_aligned_surfaces():
    c = rigid.curvature_symbols()
    H = rigid.relative_curvature_matrix().subs(c["alpha"], 0)
    assert sp.simplify(H - sp.diag((c["k1a"] + c["k2a"]) / 2, (c["k1b"] + c["k2b"]) / 2)) == sp.zeros(2, 2)


# -- the stiffness -------------------------------------------------------------------------------------------------
#: The grid's cubic interpolation: error h^4 |Gamma''''|/24 with h = 1/256 (module notes of theory/rigid.py); its
#: largest relative error against hertz_stiffness's table (1e-15) is 3e-12 near theta_min, so 5e-12.
GRID_TOLERANCE = 5e-12


@pytest.mark.parametrize("degrees", [90.0, 60.0])
def test_equals_hertz_stiffness_at_the_interlocked_crossing(degrees):
    R, r = 22.5e-3, 2.5e-3
    angle = np.radians(degrees)
    K_c = hertz_stiffness_curvatures(-1 / (R - r), 1 / r, -1 / (R - r), 1 / r, angle, *STEEL, *STEEL)
    assert float(K_c) == pytest.approx(float(hertz_stiffness(R, r, *STEEL, angle)), rel=GRID_TOLERANCE)


def test_equals_hertz_stiffness_from_theta_min_to_90_degrees():
    R, r = 22.5e-3, 2.5e-3
    theta_min = float(minimum_contact_angle(R, r))
    angle = np.linspace(theta_min + 1e-3, np.pi / 2, 400)
    K_c = hertz_stiffness_curvatures(-1 / (R - r), 1 / r, -1 / (R - r), 1 / r, angle, *STEEL, *STEEL)
    np.testing.assert_allclose(K_c, hertz_stiffness(R, r, *STEEL, angle), rtol=GRID_TOLERANCE, atol=0)


def test_equals_hertz_stiffness_pair_for_unequal_tori_and_materials():
    rng = np.random.default_rng(3)
    R1, R2 = rng.uniform(10e-3, 30e-3, (2, 50))
    r1, r2 = R1 / rng.uniform(4, 12, 50), R2 / rng.uniform(4, 12, 50)
    E1, E2 = rng.uniform(50e9, 250e9, (2, 50))
    nu1, nu2 = rng.uniform(0.2, 0.4, (2, 50))
    angle = rng.uniform(np.radians(70), np.pi / 2, 50)
    K_c = hertz_stiffness_curvatures(-1 / (R1 - r1), 1 / r1, -1 / (R2 - r2), 1 / r2, angle, E1, nu1, E2, nu2)
    expected = hertz_stiffness_pair(R1, r1, E1, nu1, R2, r2, E2, nu2, angle)
    np.testing.assert_allclose(K_c, expected, rtol=GRID_TOLERANCE, atol=0)


def test_equals_johnsons_elliptical_relations_in_mpmath():
    """Johnson (Contact Mechanics, Sec. 4.2), with semi-axes a = 1, b = sqrt(1 - m), p0 = 1, E* = 1: A and B
    from the elliptic integrals, the approach delta = p0 b K/E*, the load P = 2/3 pi a b p0, K_c = P/delta^1.5."""
    mpmath.mp.dps = 30
    for m in (0.05, 0.3, 0.6, 0.9, 0.99, 0.9999):
        m = mpmath.mpf(m)
        K, E = mpmath.ellipk(m), mpmath.ellipe(m)
        b = mpmath.sqrt(1 - m)
        A = b * (K - E) / m
        B = b * (E / (1 - m) - K) / m
        expected = (2 * mpmath.pi * b / 3) / (b * K) ** 1.5
        # surface 1 with curvatures 2A, 2B, surface 2 flat; E* = E/(2 (1 - nu^2)) = 1 with E = 2, nu = 0
        K_c = hertz_stiffness_curvatures(float(2 * A), float(2 * B), 0.0, 0.0, 0.0, 2.0, 0.0, 2.0, 0.0)
        assert float(K_c) == pytest.approx(float(expected), rel=GRID_TOLERANCE)


def test_contact_modulus_pair_reduces_to_one_material():
    assert float(contact_modulus_pair(*STEEL, *STEEL)) == pytest.approx(float(contact_modulus(*STEEL)), rel=1e-15)
    # a nearly rigid body (E2 = 1e30 Pa) against steel: E* = E/(1 - nu^2), to E/E2 ~ 1e-19
    assert float(contact_modulus_pair(193e9, 0.29, 1e30, 0.3)) == pytest.approx(193e9 / (1 - 0.29**2), rel=1e-15)


def test_grid_starts_at_the_circle_and_decreases():
    values, step = elliptical_factor_grid()
    assert values[0] == 1.0 and np.all(np.diff(values) < 0)
    assert step == rigid.ELLIPTICAL_GRID_STEP
    assert (values.size - 1) * step >= np.log1p(690.0)  # covers ln(B/A) up to 690, as the table of contact.py


def test_refuses_surfaces_that_do_not_close_to_a_point():
    with pytest.raises(ValueError, match="relative curvature A"):
        hertz_stiffness_curvatures(-1.0, 1.0, 0.5, 1.0, 0.0, *STEEL, *STEEL)  # A = (-1 + 0.5)/2 < 0
    with pytest.raises(ValueError, match="nu2"):
        hertz_stiffness_curvatures(1.0, 1.0, 1.0, 1.0, 0.0, *STEEL, 193e9, 0.5)
