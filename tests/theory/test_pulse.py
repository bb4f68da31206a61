"""Energy and momentum of the compact solitary wave (App. B) and the impact law built on them."""

import warnings

import mpmath
import numpy as np
import pytest
import sympy as sp
from ringchain.theory import (
    impact_amplitude,
    pulse,
    solitary_wave_energy,
    solitary_wave_momentum,
    solitary_wave_width,
)

S = pulse.symbols()
a, n, K, m, F_m, xi_max, k = (S[name] for name in ("a", "n", "K", "m", "F_m", "xi_max", "k"))
m_s, v_0 = S["m_s"], S["v_0"]


# --- independent evaluation: the compact profile integrated numerically with mpmath -------------------


def mp_wave(F, K_, n_, m_, a_):
    """Profile data of App. B in mpmath: (strain(x) on the hump, support length, speed), x from the edge.

    From the paper's closed forms: xi = xi_max sin(omega x)^(2/(n-1)), omega = (n-1)/(n+1) sqrt(6(n+1)/n)/a,
    xi_max = (F/K)^(1/n)/a, V_s from Eq. (8).
    """
    F, K_, n_, m_, a_ = (mpmath.mpf(x) for x in (F, K_, n_, m_, a_))
    omega = (n_ - 1) / (n_ + 1) * mpmath.sqrt(6 * (n_ + 1) / n_) / a_
    xi_m = (F / K_) ** (1 / n_) / a_
    speed = a_ * mpmath.sqrt(2 / (n_ + 1)) * mpmath.sqrt(K_ ** (1 / n_) / m_) * F ** ((n_ - 1) / (2 * n_))

    def strain(x):
        return xi_m * abs(mpmath.sin(omega * x)) ** (2 / (n_ - 1))

    return strain, mpmath.pi / omega, speed


def mp_invariants(F, K_, n_, m_, a_):
    """(kinetic, contact, momentum) of the wave by quadrature of the lattice densities per unit length."""
    strain, length, speed = mp_wave(F, K_, n_, m_, a_)
    K_, n_, m_, a_ = (mpmath.mpf(x) for x in (K_, n_, m_, a_))
    with mpmath.workdps(30):
        kinetic = mpmath.quad(lambda x: m_ * (speed * strain(x)) ** 2 / (2 * a_), [0, length / 2, length])
        contact = mpmath.quad(lambda x: K_ * (a_ * strain(x)) ** (n_ + 1) / ((n_ + 1) * a_), [0, length / 2, length])
        momentum = mpmath.quad(lambda x: m_ * speed * strain(x) / a_, [0, length / 2, length])
    return kinetic, contact, momentum


# --- symbolic -------------------------------------------------------------------------------------------


def test_euler_integral_is_the_beta_function():
    alpha, beta_, value = pulse.euler_beta_integral()
    assert sp.simplify(value - sp.gamma(alpha) * sp.gamma(beta_) / sp.gamma(alpha + beta_)) == 0


@pytest.mark.parametrize(("n_value", "k_value"), [(1.5, 1), (1.5, 2.5), (1.2, 2), (1.07, 3.3)])
def test_profile_integral_against_quadrature(n_value, k_value):
    expr = pulse.profile_integral().subs({n: n_value, k: k_value, a: 0.04, xi_max: 2e-5})
    strain, length, _ = mp_wave(1.0, 1.0, n_value, 1.0, 0.04)
    scale = 2e-5 / strain(length / 2)  # the quadrature's own xi_max, rescaled to 2e-5
    with mpmath.workdps(30):
        reference = mpmath.quad(lambda x: (scale * strain(x)) ** k_value, [0, length / 2, length])
    assert float(expr.evalf(30)) == pytest.approx(float(reference), rel=1e-20)


def test_energy_densities():
    kinetic, contact, density = pulse.energy_densities()
    X, V = S["X"], S["V_s"]
    assert sp.simplify(kinetic - m * V**2 * X**2 / (2 * a)) == 0
    assert sp.simplify(contact - K * a**n * X ** (n + 1) / (n + 1)) == 0
    assert sp.simplify(density + m * V * X / a) == 0


@pytest.mark.parametrize("n_value", [sp.Rational(3, 2), sp.Rational(6, 5), sp.Rational(11, 10), sp.Rational(7, 3)])
def test_kinetic_over_contact_energy(n_value):
    """Not equipartition: 2(n+1)/(n+3), 10/9 for Hertz (from B(1/2, x + 1) = B(1/2, x) x/(x + 1/2)); exact."""
    kinetic, contact = pulse.energy_parts()
    ratio = sp.gammasimp((kinetic / contact).subs(n, n_value).rewrite(sp.gamma))
    assert sp.nsimplify(ratio) == 2 * (n_value + 1) / (n_value + 3)


def test_energy_does_not_depend_on_mass_or_spacing_and_momentum_not_on_spacing():
    assert pulse.energy().free_symbols == {F_m, K, n}
    assert pulse.momentum().free_symbols == {F_m, K, n, m}
    # E ~ F_m^((n+1)/n) and P ~ F_m^((n+1)/(2n)): P^2/E is a mass independent of the amplitude.
    mass = sp.simplify(pulse.momentum() ** 2 / (2 * pulse.energy()))
    assert F_m not in mass.free_symbols and K not in mass.free_symbols


@pytest.mark.parametrize("n_value", [1.5, 1.2, 1.05])
def test_energy_and_momentum_against_quadrature(n_value):
    point = dict(F=37.0, K_=4.9e6, n_=n_value, m_=8.2e-3, a_=0.04)
    kinetic, contact, momentum = mp_invariants(**point)
    values = {F_m: point["F"], K: point["K_"], n: n_value, m: point["m_"], a: point["a_"]}
    derived_kinetic, derived_contact = (e.subs(values).evalf(30) for e in pulse.energy_parts())
    assert float(derived_kinetic) == pytest.approx(float(kinetic), rel=1e-20)
    assert float(derived_contact) == pytest.approx(float(contact), rel=1e-20)
    assert float(pulse.momentum().subs(values).evalf(30)) == pytest.approx(float(momentum), rel=1e-20)
    # The numeric functions, to double precision.
    args = dict(K=point["K_"], n=n_value, m=point["m_"], a=point["a_"])
    assert float(solitary_wave_energy(point["F"], **args)) == pytest.approx(float(kinetic + contact), rel=1e-12)
    assert float(solitary_wave_momentum(point["F"], **args)) == pytest.approx(float(momentum), rel=1e-12)


def test_impact_law_puts_the_striker_energy_into_the_wave():
    law = pulse.impact_law()
    for values in ({n: 1.5, K: 2.0, m_s: 0.3, v_0: 1.7}, {n: 1.11, K: 4.9e6, m_s: 8.2e-3, v_0: 0.99}):
        energy = pulse.energy().subs(F_m, law).subs(values).evalf(40)
        assert float(energy / (values[m_s] * values[v_0] ** 2 / 2)) == pytest.approx(1.0, rel=1e-30)
    # The exponents from scaling: d log F_m/d log v_0 = 2n/(n+1), and F_m ~ m_s^(n/(n+1)).
    log_law = sp.expand_log(sp.log(law), force=True)
    assert sp.simplify(v_0 * sp.diff(log_law, v_0) - 2 * n / (n + 1)) == 0
    assert sp.simplify(m_s * sp.diff(log_law, m_s) - n / (n + 1)) == 0


def test_the_striker_mass_is_a_symbol_of_the_derivation():
    """The striker's mass enters the impact law as m_s, derived (not typed): with m_s = m, the chain's own ring,
    it is the law of the paper's convention (the energy of the wave equal to m v_0^2/2); a rigid striker of
    mass m0 raises F_m by (m0/m)^(n/(n+1))."""
    law = pulse.impact_law()
    assert m_s in law.free_symbols and m not in law.free_symbols  # the chain's m cancels: only the striker's counts
    (own,) = sp.solve(sp.Eq(pulse.energy(), m * v_0**2 / 2), F_m, check=False)

    def same(x, y):  # powers of positive quantities: equal logarithms
        return sp.simplify(sp.expand_log(sp.log(x) - sp.log(y), force=True)) == 0

    assert same(law.subs(m_s, m), own)
    m0 = sp.Symbol("m_0", positive=True)
    assert same(law.subs(m_s, m0) / law.subs(m_s, m), (m0 / m) ** (n / (n + 1)))
    assert not same(law.subs(m_s, m0), own)  # the check can fail
    # The numeric function: the default striker is the ring (m_striker = m), and a heavier one scales the same way.
    args = dict(K=4.9e6, n=1.11, m=8.2e-3, a=0.04)
    heavy = impact_amplitude(0.99, **args, m_striker=8.2e-3 / 0.37) / impact_amplitude(0.99, **args)
    assert float(heavy) == pytest.approx((1 / 0.37) ** (1.11 / 2.11), rel=1e-12)  # rounding of exp/log only


# --- numeric functions -------------------------------------------------------------------------------


def test_hertz_numbers_against_gamma_closed_forms():
    """n = 3/2 in units K = m = a = F_m = 1: E = 2 (B(1/2, 9/2) + B(1/2, 11/2))/sqrt(10), P = sqrt(2) B(1/2, 5/2)."""
    with mpmath.workdps(30):
        energy = 2 * (mpmath.beta(0.5, 4.5) + mpmath.beta(0.5, 5.5)) / mpmath.sqrt(10)
        momentum = mpmath.sqrt(mpmath.mpf(1.5) / 3) * mpmath.beta(0.5, 2.5) / 0.5
    assert float(solitary_wave_energy(1.0, K=1.0, n=1.5, m=1.0, a=1.0)) == pytest.approx(float(energy), rel=1e-13)
    assert float(solitary_wave_momentum(1.0, K=1.0, n=1.5, m=1.0, a=1.0)) == pytest.approx(float(momentum), rel=1e-13)
    # The wave moves like a particle of 1.34 ring masses.
    mass = float(momentum**2 / (2 * energy))
    assert 1.34 < mass < 1.35


def test_scaling_and_broadcasting():
    F = np.array([1.0, 10.0, 100.0])
    E = solitary_wave_energy(F[:, None], K=4.9e6, n=[1.11, 1.5], m=8.2e-3, a=0.04)
    assert E.shape == (3, 2)
    np.testing.assert_allclose(E[1] / E[0], 10.0 ** ((np.array([1.11, 1.5]) + 1) / [1.11, 1.5]), rtol=1e-12)
    P = solitary_wave_momentum(F[:, None], K=4.9e6, n=1.5, m=[8.2e-3, 4 * 8.2e-3], a=0.04)
    np.testing.assert_allclose(P[:, 1] / P[:, 0], 2.0, rtol=1e-12)  # sqrt(m)
    # a cancels; v0 over three decades with the exponent 2n/(n+1).
    assert solitary_wave_energy(3.0, K=4.9e6, n=1.3, m=8.2e-3, a=0.04) == solitary_wave_energy(
        3.0, K=4.9e6, n=1.3, m=1.0, a=7.0
    )
    v0 = np.array([0.01, 0.1, 1.0, 10.0])
    F_v = impact_amplitude(v0, K=4.9e6, n=1.3, m=8.2e-3, a=0.04)
    np.testing.assert_allclose(np.diff(np.log(F_v)) / np.log(10.0), 2 * 1.3 / 2.3, rtol=1e-12)


def test_impact_amplitude_inverts_the_energy():
    F = impact_amplitude(0.99, K=4.9e6, n=1.11, m=8.2e-3, a=0.04, m_striker=0.0222)
    assert float(solitary_wave_energy(F, K=4.9e6, n=1.11, m=8.2e-3, a=0.04)) == pytest.approx(
        0.5 * 0.0222 * 0.99**2, rel=1e-12
    )
    default = impact_amplitude(0.99, K=4.9e6, n=1.11, m=8.2e-3, a=0.04)
    assert float(default) == float(impact_amplitude(0.99, K=4.9e6, n=1.11, m=8.2e-3, a=0.04, m_striker=8.2e-3))


def test_near_n_one_the_numbers_stay_finite():
    """As n -> 1 the Beta arguments grow as 1/(n - 1); SciPy's beta keeps them finite, without warnings."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        n_values = np.array([1.0001, 1.001, 1.01])
        E = solitary_wave_energy(10.0, K=4.9e6, n=n_values, m=8.2e-3, a=0.04)
        P = solitary_wave_momentum(10.0, K=4.9e6, n=n_values, m=8.2e-3, a=0.04)
        F = impact_amplitude(1.0, K=4.9e6, n=n_values, m=8.2e-3, a=0.04)
    assert np.all(np.isfinite(E) & np.isfinite(P) & np.isfinite(F) & (E > 0) & (P > 0) & (F > 0))
    # The wave widens as 1/(n - 1) and carries more energy at a given force: E grows as the width^(1/2).
    width = solitary_wave_width(n=n_values, a=0.04)
    assert np.all(np.diff(E) < 0) and np.all(np.diff(width) < 0)


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: solitary_wave_energy(0.0, K=1.0, n=1.5, m=1.0, a=1.0), "F_m must be positive"),
        (lambda: solitary_wave_energy(1.0, K=1.0, n=1.0, m=1.0, a=1.0), "compact solitary wave only for n > 1"),
        (lambda: solitary_wave_momentum(1.0, K=1.0, n=1.5, m=-1.0, a=1.0), "m must be positive"),
        (lambda: impact_amplitude(-1.0, K=1.0, n=1.5, m=1.0, a=1.0), "v0 must be positive"),
        (lambda: impact_amplitude(1.0, K=1.0, n=1.5, m=1.0, a=0.0), "a must be positive"),
        (lambda: impact_amplitude(1.0, K=1.0, n=1.5, m=1.0, a=1.0, m_striker=0.0), "m_striker must be positive"),
    ],
)
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()
