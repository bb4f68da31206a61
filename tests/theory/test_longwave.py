"""Long-wave expansion of the power-law chain (paper App. B, Eqs. (B1)-(B17))."""

import mpmath
import numpy as np
import pytest
import sympy as sp
from ringchain.theory import linear_sound_speed, longwave

S = longwave.symbols()
x, t, a, n, K, m, A, c_n = (S[k] for k in ("x", "t", "a", "n", "K", "m", "A", "c_n"))
u, xi = S["u"], S["xi"]
q, delta_0, xi_0, F_0 = S["q"], S["delta_0"], S["xi_0"], S["F_0"]


def D(k):
    """k-th x-derivative of u."""
    return sp.Derivative(u, (x, k))


def assert_same(derived, expected):
    assert sp.simplify(derived - expected) == 0


def test_neighbour_displacements_are_the_taylor_series_of_app_b():
    below, above = longwave.neighbour_displacements()
    paper_above = u + a * D(1) + a**2 / 2 * D(2) + a**3 / 6 * D(3) + a**4 / 24 * D(4)
    paper_below = u - a * D(1) + a**2 / 2 * D(2) - a**3 / 6 * D(3) + a**4 / 24 * D(4)
    # The paper prints through a^4; the code keeps the a^5 term too.
    assert_same(above - a**5 / 120 * D(5), paper_above)
    assert_same(below + a**5 / 120 * D(5), paper_below)


def test_extension_parts_are_app_b_phi_and_psi():
    N, phi, psi = longwave.extension_parts()
    assert_same(N, a * D(1))
    assert_same(phi - a**5 / 120 * D(5), a**2 / 2 * D(2) + a**3 / 6 * D(3) + a**4 / 24 * D(4))
    assert_same(psi - a**5 / 120 * D(5), -(a**2) / 2 * D(2) + a**3 / 6 * D(3) - a**4 / 24 * D(4))


def test_binomial_expansion_is_app_b():
    N, e = S["N"], S["e"]
    paper = N**n + n * N ** (n - 1) * e + n * (n - 1) / 2 * N ** (n - 2) * e**2
    paper += n * (n - 1) * (n - 2) / 6 * N ** (n - 3) * e**3
    assert_same(longwave.binomial_expansion(), paper)


@pytest.mark.parametrize(
    ("k", "paper"),
    [
        (1, a**2 * D(2) + a**4 / 12 * D(4)),
        (2, a**5 / 3 * D(2) * D(3)),
        (3, a**6 / 4 * D(2) ** 3),
    ],
)
def test_power_differences_are_app_b(k, paper):
    assert_same(longwave.power_difference(k), paper)
    # App. B writes O(a^6), O(a^7), O(a^8): the next power, a^(k+4), is absent.
    assert_same(longwave.power_difference(k, through=k + 4), paper)


def test_fourth_power_difference_is_beyond_the_kept_order():
    # phi^4 - psi^4 starts at a^9 > a^(4+3): the binomial series may stop at the cube.
    assert longwave.power_difference(4) == 0
    assert longwave.power_difference(4, through=8) == 0


PAPER_EQ15 = (
    A
    * a ** (n + 1)
    * (
        n * D(1) ** (n - 1) * D(2)
        + n / 12 * a**2 * D(1) ** (n - 1) * D(4)
        + n * (n - 1) / 6 * a**2 * D(1) ** (n - 2) * D(2) * D(3)
        + n * (n - 1) * (n - 2) / 24 * a**2 * D(1) ** (n - 3) * D(2) ** 3
    )
)

PAPER_FLUX = D(1) ** n + n * a**2 / 24 * ((n - 1) * D(1) ** (n - 2) * D(2) ** 2 + 2 * D(1) ** (n - 1) * D(3))


def test_displacement_equation_is_eq_15():
    assert_same(longwave.displacement_equation(), PAPER_EQ15)


def test_direct_expansion_of_the_lattice_gives_eq_15():
    assert_same(longwave.displacement_equation_direct(), PAPER_EQ15)


def test_eq_15_has_only_the_leading_order_and_relative_eps_squared():
    orders = longwave.orders_in_a(longwave.displacement_equation(), leading=n + 1)
    assert sorted(orders) == [0, longwave.RELATIVE_ORDER]


def test_central_difference_is_in_flux_form():
    difference, F = longwave.central_difference()
    F1, F3 = sp.Derivative(F(x), x), sp.Derivative(F(x), (x, 3))
    assert_same(difference, a * F1 + a**3 / 24 * F3)


def test_flux_is_the_conservative_form_of_app_b():
    assert_same(longwave.flux(), PAPER_FLUX)
    assert_same(longwave.displacement_equation_conservative(), PAPER_EQ15)


def test_contact_force_at_midpoint():
    expected = a**n * (D(1) ** n + n * a**2 / 24 * D(1) ** (n - 1) * D(3))
    assert_same(longwave.contact_force_at_midpoint(), expected)


def test_wave_speed_squared():
    assert_same(longwave.wave_speed_squared(), K * a ** (n + 1) / m)


def test_strain_equation_is_eq_17():
    equation = longwave.strain_equation()
    paper_flux = xi**n + n * a**2 / 24 * (
        (n - 1) * xi ** (n - 2) * sp.diff(xi, x) ** 2 + 2 * xi ** (n - 1) * sp.diff(xi, x, 2)
    )
    assert equation.lhs == sp.Derivative(xi, (t, 2))
    assert_same(equation.rhs.doit(), c_n**2 * sp.diff(paper_flux, x, 2))


def test_lattice_dispersion_and_sound_speed():
    k_0 = longwave.linear_contact_stiffness()
    assert_same(k_0, n * K * delta_0 ** (n - 1))
    assert_same(longwave.lattice_dispersion(), 4 * k_0 / m * sp.sin(q * a / 2) ** 2)
    assert_same(longwave.sound_speed_lattice(), a * sp.sqrt(n * K * delta_0 ** (n - 1) / m))


def test_continuum_dispersion_is_the_long_wave_lattice_dispersion():
    # Eq. (B17) is exact to relative order eps^2: its dispersion matches the lattice's through q^4.
    lattice = sp.series(longwave.lattice_dispersion(), q, 0, 5).removeO()
    continuum = longwave.continuum_dispersion().subs(c_n**2, longwave.wave_speed_squared())
    continuum = continuum.subs(xi_0, delta_0 / a)
    assert_same(sp.expand(lattice - continuum), 0)


def test_both_sound_speeds_agree():
    continuum = longwave.sound_speed_continuum().subs(c_n, sp.sqrt(longwave.wave_speed_squared()))
    assert_same(continuum.subs(xi_0, delta_0 / a), longwave.sound_speed_lattice())


def test_sound_speed_from_force():
    expected = a * sp.sqrt(n * K * delta_0 ** (n - 1) / m)
    assert_same(longwave.sound_speed_from_force(), expected.subs(delta_0, (F_0 / K) ** (1 / n)))


@pytest.mark.parametrize(
    "point",
    [
        (3.0, 2.1e8, 1.11, 0.04, 0.012),
        (50.0, 5e7, 1.5, 0.03, 0.02),
        (1.0, 4.0, 0.8, 2.0, 1.0),
        (1e300, 1e300, 2.5, 1e200, 1e100),
    ],
)
def test_linear_sound_speed_against_a_numerical_derivative(point):
    # c_0 = a sqrt(k_0/m) with k_0 = dF/d delta of F = K delta^n at the static extension, by mpmath's
    # numerical derivative at 40 digits: independent of the package's expressions.  The last point
    # (c_0 ~ 1e300, with F_0^p K^(1/(2n)) a ~ 1e350 on the way) once overflowed.
    F_0_, K_, n_, a_, m_ = point
    with mpmath.workdps(40):
        K_v, n_v = mpmath.mpf(K_), mpmath.mpf(n_)
        delta_0 = (mpmath.mpf(F_0_) / K_v) ** (1 / n_v)
        k_0 = mpmath.diff(lambda d: K_v * d**n_v, delta_0, h=delta_0 * mpmath.mpf(10) ** -12)  # relative step
        expected = mpmath.mpf(a_) * mpmath.sqrt(k_0 / mpmath.mpf(m_))
    # exp(log C + p log F_0) with log c_0 up to 690: relative error about 690 x 1e-16 < 1e-13.
    assert np.isclose(linear_sound_speed(F_0_, K=K_, n=n_, m=m_, a=a_), float(expected), rtol=1e-13, atol=0)


def test_linear_sound_speed_broadcasts_and_vanishes_without_prestress():
    c = linear_sound_speed(np.array([[0.0], [1.0]]), K=1e8, n=np.array([1.2, 1.5]), m=0.01, a=0.04)
    assert c.shape == (2, 2)
    assert np.all(c[0] == 0.0)  # sonic vacuum: no static force, no sound for n > 1
    assert np.all(c[1] > 0)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ((-1.0, 1e8, 1.5, 0.04, 0.01), "F_0"),
        ((1.0, 0.0, 1.5, 0.04, 0.01), "K"),
        ((1.0, 1e8, -1.0, 0.04, 0.01), "n"),
        ((1.0, 1e8, 1.5, 0.0, 0.01), "a"),
        ((1.0, 1e8, 1.5, 0.04, -2.0), "m"),
        ((0.0, 1e8, 0.5, 0.04, 0.01), "infinite"),
        ((np.nan, 1e8, 1.5, 0.04, 0.01), "finite"),
    ],
)
def test_linear_sound_speed_rejects_bad_input(args, message):
    with pytest.raises(ValueError, match=message):
        F_0_, K_, n_, a_, m_ = args
        linear_sound_speed(F_0_, K=K_, n=n_, m=m_, a=a_)
