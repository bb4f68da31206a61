"""Solitary wave on a pre-stretched chain (beyond the paper; App. B, Eq. (B19)): the first integral and the speed."""

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain.theory import (
    linear_sound_speed,
    longwave,
    prestressed,
    solitary,
    solitary_wave_speed,
    solitary_wave_speed_prestressed,
)

S = solitary.symbols()
a, n, c_n, tau = (S[k] for k in ("a", "n", "c_n", "tau"))
X = S["X"]
xi_0, xi_max, F_m, F_0 = S["xi_0"], S["xi_max"], S["F_m"], S["F_0"]
f = S["f"]


def assert_same(derived, expected):
    difference = sp.simplify(derived - expected)
    if difference != 0:
        # simplify leaves sqrt(n**2 + 2*n + 1); factoring the bases of powers lets it see n + 1.
        factored = difference.replace(lambda e: e.is_Pow and e.base.is_Add, lambda e: sp.factor(e.base) ** e.exp)
        difference = sp.simplify(factored)
    assert difference == 0


# --- pre-stretched chain ------------------------------------------------------------------------------


def test_first_integral_is_conserved_along_eq_19():
    lhs, rhs = prestressed.first_integral()
    assert_same(lhs, n * a**2 / 24 * X ** (n - 1) * sp.Symbol("xi_tau", real=True) ** 2)
    # d/dtau (lhs - rhs) along xi = f(tau) is -f' times the residual of Eq. (B19): conserved on solutions.
    on_path = (lhs - rhs).subs(sp.Symbol("xi_tau", real=True), sp.Derivative(f(tau), tau)).subs(X, f(tau))
    residual = solitary.eq19_residual(f(tau), sp.Derivative(f(tau), tau), sp.Derivative(f(tau), (tau, 2)), C_1=0)
    assert_same(sp.diff(on_path, tau) + sp.Derivative(f(tau), tau) * residual, 0)


def test_prestressed_speed_is_nesterenko_for_hertz():
    # Nesterenko's weakly compressed Hertz chain (book Sec. 1.3; Daraio et al., PRE 73, 026610, 2006):
    # V_s = c_0/(xi_r - 1) [4/15 (3 + 2 xi_r^(5/2) - 5 xi_r)]^(1/2), xi_r = xi_max/xi_0, c_0^2 = 3/2 c_n^2 xi_0^(1/2).
    half = sp.Rational(3, 2)
    ratio = xi_max / xi_0
    c_0_squared = half * c_n**2 * sp.sqrt(xi_0)
    nesterenko = c_0_squared / (ratio - 1) ** 2 * sp.Rational(4, 15) * (3 + 2 * ratio ** sp.Rational(5, 2) - 5 * ratio)
    assert_same(prestressed.prestressed_speed_squared().subs(n, half), nesterenko)


def test_prestressed_speed_without_prestress_is_the_compact_wave():
    assert_same(sp.limit(prestressed.prestressed_speed_squared(), xi_0, 0), solitary.speed_from_strain() ** 2)


@pytest.mark.parametrize("n_value", [sp.Rational(11, 10), sp.Rational(3, 2), 2, sp.Rational(7, 3)])
def test_prestressed_speed_of_a_small_wave_is_the_sound_speed(n_value):
    speed2 = prestressed.prestressed_speed_squared().subs(n, n_value)
    sound2 = longwave.sound_speed_continuum().subs(S["xi_0"], xi_0) ** 2
    assert_same(sp.limit(speed2, xi_max, xi_0), sound2.subs(n, n_value))


def test_hypergeometric_form_equals_the_elementary_form_for_symbolic_n():
    z = sp.Symbol("z", positive=True)
    hypergeometric = prestressed.prestressed_speed_hypergeometric().rewrite(sp.hyper)
    expanded = sp.hyperexpand(hypergeometric.subs(xi_0, (1 - z) * xi_max))
    elementary = prestressed.prestressed_speed_squared().subs(xi_0, (1 - z) * xi_max)
    assert sp.simplify(sp.powsimp(sp.expand((expanded - elementary) / xi_max ** (n - 1)), force=True)) == 0


def test_hypergeometric_form_limits():
    form = prestressed.prestressed_speed_hypergeometric().rewrite(sp.hyper)
    assert_same(sp.hyperexpand(form.subs(xi_0, xi_max)), n * c_n**2 * xi_max ** (n - 1))
    assert_same(sp.hyperexpand(form.subs(xi_0, 0)), solitary.speed_from_strain() ** 2)


@pytest.mark.parametrize(("n_value", "ratio"), [(1.07, 0.3), (1.5, 0.01), (1.5, 0.999), (2.7, 0.5), (3.0, 0.0)])
def test_hypergeometric_form_equals_elementary_form(n_value, ratio):
    # mpmath at 30 digits, independent of the hyperexpand proof inside the derivation.
    with mpmath.workdps(30):
        nv, q = mpmath.mpf(n_value), mpmath.mpf(ratio)
        elementary = 2 * ((1 - q ** (nv + 1)) / (nv + 1) - q**nv * (1 - q)) / (1 - q) ** 2
        assert abs(nv * mpmath.hyp2f1(1 - nv, 2, 3, 1 - q) / elementary - 1) < mpmath.mpf(10) ** -25


@pytest.mark.parametrize(("n_value", "w_value"), [("1.07", "0.3"), ("1.5", "0.999"), ("2.7", "0.01"), ("40", "0.9")])
def test_prestress_factor_forms_agree(n_value, w_value):
    # G^2 three ways, each evaluated by mpmath at 30 digits: n(n+1)/2 2F1 (mpmath's hyp2f1), the
    # elementary form in q = w^n and Z = 1 - w, and Euler's integral by mpmath's own quadrature.
    factor, _ = prestressed.prestress_factor()
    closed, q, Z = prestressed.prestress_factor_elementary()
    integrand, t, Z_integral = prestressed.prestress_factor_integral()
    with mpmath.workdps(30):
        nv, wv = mpmath.mpf(n_value), mpmath.mpf(w_value)
        reference = nv * (nv + 1) / 2 * mpmath.hyp2f1(1 - nv, 2, 3, 1 - wv)
        point = {n: sp.Float(nv, 30)}
        elementary = closed.subs(point).subs({q: sp.Float(wv**nv, 30), Z: sp.Float(1 - wv, 30)}).evalf(30)
        f = sp.lambdify(t, integrand.subs(point).subs(Z_integral, sp.Float(1 - wv, 30)), "mpmath")
        quadrature = mpmath.quad(f, [0, 1])
    for value in (elementary, quadrature):
        assert abs(float(value) / float(reference) - 1) < 1e-14  # 30-digit arithmetic on both sides
    assert factor.has(hyp2f1_class()) and not factor.has(S["xi_max"])


def hyp2f1_class():
    from ringchain.theory.special import hyp2f1

    return type(hyp2f1(1, 2, 3, sp.Symbol("z")))


def test_prestressed_speed_from_force_limits():
    speed = prestressed.prestressed_speed_from_force().rewrite(sp.hyper)
    assert_same(sp.hyperexpand(speed.subs(F_0, 0)), solitary.speed_from_force())
    sound = longwave.sound_speed_from_force()
    assert_same(sp.hyperexpand(speed.subs(F_m, F_0)), sound)


# --- numeric functions ----------------------------------------------------------------------------------

#: (F_m N, K N/m^n, n, a m, m kg): Table I-like rings and round numbers (as in test_solitary.py).
POINTS = [
    (10.0, 2.284e3 * 1000**1.11, 1.11, 0.04, 0.37 * 0.0265),
    (3.0, 1e9, 1.5, 0.01, 0.005),
    (8.0, 1.0, 3.0, 1.0, 1.0),
]


def _prestressed_reference(F_m_, F_0_, K_, n_, a_, m_):
    """App. B's first integral at 60 digits: V_s^2 = 2 c_n^2 [(X^(n+1) - X0^(n+1))/(n+1) - X0^n (X - X0)]/(X - X0)^2,
    with X = xi_max, X0 = xi_0 from F = K (a xi)^n; its limit n c_n^2 X^(n-1) at X0 = X."""
    with mpmath.workdps(60):
        F, F_static, Kv, nv, av, mv = (mpmath.mpf(value) for value in (F_m_, F_0_, K_, n_, a_, m_))
        c2 = Kv * av ** (nv + 1) / mv
        X, X0 = (F / Kv) ** (1 / nv) / av, (F_static / Kv) ** (1 / nv) / av
        if X0 == X:
            return float(mpmath.sqrt(nv * c2 * X ** (nv - 1)))
        bracket = (X ** (nv + 1) - X0 ** (nv + 1)) / (nv + 1) - X0**nv * (X - X0)
        return float(mpmath.sqrt(2 * c2 * bracket / (X - X0) ** 2))


@pytest.mark.parametrize("point", POINTS)
@pytest.mark.parametrize("ratio", [0.0, 0.2, 0.5, 0.9, 1 - 1e-6, 1.0])
def test_prestressed_speed_against_the_first_integral(point, ratio):
    F_m_, K_, n_, a_, m_ = point
    expected = _prestressed_reference(F_m_, ratio * F_m_, K_, n_, a_, m_)
    # The elementary form or 12-point quadrature, both to a few 1e-16: 1e-13.
    assert np.isclose(
        solitary_wave_speed_prestressed(F_m_, F_0=ratio * F_m_, K=K_, n=n_, m=m_, a=a_), expected, rtol=1e-13, atol=0
    )


@pytest.mark.parametrize(
    ("F_m_", "ratio", "n_"),
    [
        (10.0, 0.5, 1e6),  # SciPy's hyp2f1 returned NaN here
        (1e4, 0.5, 1e4),  # ... and lost 9 digits here
        (1e6, 1 - 1e-12, 1.11),  # a long hanging chain: the static force is nearly the peak
        (1e9, 1 - 1e-15, 1.5),
        (1e-3, 1e-300, 1.0001),
    ],
)
def test_prestressed_speed_for_long_chains_and_large_exponents(F_m_, ratio, n_):
    K_, a_, m_ = 2.6e8, 0.04, 0.0098
    expected = _prestressed_reference(F_m_, ratio * F_m_, K_, n_, a_, m_)
    # 1e-13 as above; the reference resolves the 0/0 of F_0 -> F_m with 60 digits.
    assert np.isclose(
        solitary_wave_speed_prestressed(F_m_, F_0=ratio * F_m_, K=K_, n=n_, m=m_, a=a_), expected, rtol=1e-13, atol=0
    )


# --- properties -----------------------------------------------------------------------------------------

forces = st.floats(1e-3, 1e4)
exponents = st.floats(1.01, 3.0)
stiffness = st.floats(1e3, 1e12)
spacing = st.floats(1e-3, 0.1)
masses = st.floats(1e-4, 1.0)


@settings(derandomize=True, max_examples=60, deadline=None)
@given(forces, st.floats(0.0, 1.0), exponents, stiffness, spacing, masses)
def test_prestressed_speed_bounds(F_m_, fraction, n_, K_, a_, m_):
    F_0_ = fraction * F_m_
    V = solitary_wave_speed_prestressed(F_m_, F_0=F_0_, K=K_, n=n_, m=m_, a=a_)
    slack = 1 + 1e-12  # equalities hold at fraction 0 and 1; allow rounding
    # Between the compact wave of the same peak force and the sound speed at the peak ...
    assert solitary_wave_speed(F_m_, K=K_, n=n_, m=m_, a=a_) <= V * slack
    assert V <= linear_sound_speed(F_m_, K=K_, n=n_, m=m_, a=a_) * slack
    # ... and supersonic with respect to the pre-stretched chain.
    assert linear_sound_speed(F_0_, K=K_, n=n_, m=m_, a=a_) <= V * slack


@settings(derandomize=True, max_examples=40, deadline=None)
@given(forces, exponents, stiffness, spacing, masses)
def test_prestressed_limits_numerically(F_m_, n_, K_, a_, m_):
    compact = solitary_wave_speed(F_m_, K=K_, n=n_, m=m_, a=a_)
    # F_0/F_m = 1e-12: V^2 moves by O((F_0/F_m)^(1/n)) <= 1e-12^(1/3) = 1e-4 relative.
    assert np.isclose(
        solitary_wave_speed_prestressed(F_m_, F_0=1e-12 * F_m_, K=K_, n=n_, m=m_, a=a_), compact, rtol=2e-4, atol=0
    )
    sound = linear_sound_speed(F_m_, K=K_, n=n_, m=m_, a=a_)
    # F_m/F_0 = 1 + 1e-9: V moves by O(1e-9) relative.
    assert np.isclose(
        solitary_wave_speed_prestressed(F_m_, F_0=F_m_ / (1 + 1e-9), K=K_, n=n_, m=m_, a=a_), sound, rtol=1e-8, atol=0
    )
