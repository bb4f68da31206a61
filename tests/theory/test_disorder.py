"""Weak disorder (issue 23), the speeds (theory/disorder.py): the derivations against known forms, the expansions
against exact evaluation, the speeds against Bloch waves; the generated code and the bad inputs of the three
modules of weak disorder.  Scattering and attenuation: test_scattering.py and test_attenuation.py."""

import numpy as np
import pytest
import sympy as sp
from ringchain.theory import (
    attenuated_travel_time,
    attenuation,
    chain_impedance_spread,
    disorder,
    disorder_attenuation_length,
    disorder_speed_shift,
    disordered_solitary_wave_speed,
    effective_medium_speed,
    harmonic_mean_speed,
    impedance_spread,
    linear,
    localization_length,
    scattering,
    solitary_wave_speed,
)
from ringchain.theory._codegen import Derived

S = disorder.symbols()
n, K, m, a, k, F_m, omega, q = (S[name] for name in ("n", "K", "m", "a", "k", "F_m", "omega", "q"))
sigma_K, sigma_m, sigma_a, sigma_k, sigma_Z = (S[f"sigma_{x}"] for x in ("K", "m", "a", "k", "Z"))
rho_mK, rho, theta = S["rho_mK"], S["rho"], S["theta"]
mean_a, mean_m, mean_compliance = S["mean_a"], S["mean_m"], S["mean_compliance"]
mean_K_compliance, mean_transit, mean_ray = S["mean_K_compliance"], S["mean_transit"], S["mean_ray"]


def assert_same(derived, expected):
    assert sp.simplify(derived - expected) == 0, (derived, expected)


# --- 1.-5. speeds of long waves: derivations against the known forms ------------------------------------


def test_cell_transfer_matrix_and_the_uniform_chain():
    T = disorder.cell_transfer_matrix()
    assert T == sp.Matrix([[1 - m * omega**2 / k, 1 / k], [-m * omega**2, 1]])
    assert_same(T.det(), 1)
    # A uniform chain: cos(q a) = tr T/2 must be the monatomic dispersion derived in linear.py.
    omega2 = sp.solve(sp.Eq(sp.cos(q * a), T.trace() / 2), omega**2)[0]
    expected = linear.power_law_dispersion().subs(linear.symbols()["k_c"], k)
    assert sp.simplify(sp.expand_trig((omega2 - expected).rewrite(sp.cos))) == 0


def test_long_wave_trace_of_an_explicit_product():
    # Independent of the induction: three different cells multiplied out.
    masses, stiffnesses = sp.symbols("m1:4", positive=True), sp.symbols("k1:4", positive=True)
    T = disorder.cell_transfer_matrix()
    product = sp.eye(2)
    for m_j, k_j in zip(masses, stiffnesses, strict=True):
        product = T.subs({m: m_j, k: k_j}) * product
    W = sp.Symbol("W", positive=True)
    trace = sp.expand(product.trace().subs(omega, sp.sqrt(W)))
    assert trace.coeff(W, 0) == 2
    assert_same(trace.coeff(W, 1), -sum(masses) * sum(1 / s for s in stiffnesses))
    M, C, long_wave = disorder.long_wave_transfer()
    assert_same(long_wave, 2 - omega**2 * M * C)


def test_homogenised_medium_and_bloch_limit():
    rho, E = disorder.homogenised_constants()
    assert_same(rho, mean_m / mean_a)
    assert_same(E, mean_a / mean_compliance)
    Lambda, M, C, c = disorder.bloch_long_wave_speed()
    assert_same(c, Lambda / sp.sqrt(M * C))
    assert_same(disorder.effective_medium_speed_symbolic(), mean_a / sp.sqrt(mean_m * mean_compliance))
    assert_same(disorder.homogenised_wave_equation()[1], disorder.effective_medium_speed_symbolic())


def test_homogenised_power_law_chain():
    assert_same(disorder.effective_contact_law(), mean_K_compliance ** (-n))
    expected = mean_a * sp.sqrt(2 / (n + 1)) * F_m ** ((n - 1) / (2 * n)) / sp.sqrt(mean_m * mean_K_compliance)
    assert_same(disorder.effective_solitary_speed(), expected)
    # A linear contact (n = 1, <K^(-1/n)> = <1/K>) is the linear chain.
    linear_chain = disorder.effective_medium_speed_symbolic().subs(mean_compliance, mean_K_compliance)
    assert_same(disorder.effective_solitary_speed().subs(n, 1), linear_chain)


def test_harmonic_means():
    assert_same(disorder.harmonic_mean_speed_symbolic(), mean_a / mean_transit)
    expected = mean_a * sp.sqrt(2 / (n + 1)) * F_m ** ((n - 1) / (2 * n)) / mean_ray
    assert_same(disorder.harmonic_solitary_speed(), expected)


# --- 6. the expansions ------------------------------------------------------------------------------------


def test_second_order_shifts():
    assert_same(disorder.effective_medium_shift(), -(n + 1) / (4 * n**2) * sigma_K**2)
    harmonic = sigma_m**2 / 8 - (2 * n + 1) / (8 * n**2) * sigma_K**2 + rho_mK * sigma_m * sigma_K / (4 * n)
    assert_same(disorder.harmonic_mean_shift(), harmonic)
    # The spacing's spread and every correlation with it drop out of both.
    for shift in (disorder.effective_medium_shift(), disorder.harmonic_mean_shift()):
        assert not shift.has(sigma_a, S["rho_aK"], S["rho_am"])
    # The linear chain (n = 1, K -> k): -sigma_k^2/2, the "about sigma^2/2" of the issue.
    assert_same(disorder.effective_medium_shift().subs(n, 1), -(sigma_K**2) / 2)


def test_the_two_estimates_differ_by_half_the_variance_of_ln_Z():
    variance = sigma_m**2 / 4 + sigma_K**2 / (4 * n**2) + rho_mK * sigma_m * sigma_K / (2 * n)
    assert_same(disorder.impedance_variance(), variance)
    assert_same(disorder.speed_contrast(), variance / 2)
    # The contrast vanishes when ln Z is the same in every cell: mu = -kappa/n (rho = -1, sigma_m = sigma_K/n),
    # i.e. m proportional to 1/k; with m proportional to k (mu = kappa at n = 1) it is sigma_k^2/2.
    assert disorder.speed_contrast().subs({rho_mK: -1, sigma_m: sigma_K / n}) == 0
    assert_same(disorder.speed_contrast().subs({n: 1, rho_mK: 1, sigma_m: sigma_K}), sigma_K**2 / 2)


def test_impedance_ratio_does_not_depend_on_the_force():
    ratio, K2, m2 = disorder.impedance_ratio()
    assert_same(ratio, sp.sqrt(m2 / m) * (K2 / K) ** (1 / (2 * n)))


def test_expectation_uses_the_second_moments():
    kappa, mu = S["kappa"], S["mu"]
    eps = sp.Symbol("epsilon", positive=True)
    value = disorder.expectation((1 + kappa) ** 2 * (1 + mu)).subs(eps, 1)
    assert_same(value, 1 + sigma_K**2 + 2 * rho_mK * sigma_m * sigma_K)
    with pytest.raises(ValueError, match="second"):
        disorder.expectation(kappa, order=3)


# --- the displayed equations ------------------------------------------------------------------------------


def test_equations_are_equalities_of_the_derivations():
    # The displayed forms of the three modules of weak disorder (speeds, scattering, attenuation) together.
    equations = {**disorder.equations(), **scattering.equations(), **attenuation.equations()}
    assert equations["effective_medium_speed"].rhs == disorder.effective_medium_speed_symbolic()
    assert equations["attenuation_length"].rhs == attenuation.attenuation_length_symbolic()
    assert all(isinstance(e, sp.Eq) for e in equations.values())
    assert len(equations) == 22


# --- the generated code against the expressions -------------------------------------------------------------

SAMPLE = {
    "n": 1.3, "sigma_K": 0.2, "sigma_m": 0.15, "rho_mK": 0.4, "sigma_k": 0.1, "rho": -0.3, "sigma_Z": 0.12,
    "omega": 0.7, "m": 0.3, "k": 2e5, "a": 0.04, "x": 1.5, "V_0": 12.0, r"\ell": 3.0,
    "log_mean_a": -3.2, "log_mean_m": -1.1, "log_mean_compliance": -12.0, "log_mean_transit": -6.5,
    "log_F_m": 2.3, "log_mean_K_compliance": -9.0, "log_mean_ray": -4.0,
}  # fmt: skip
SAMPLE["omega"] = 0.9 * 2 * np.sqrt(SAMPLE["k"] / SAMPLE["m"])  # inside the band
DERIVED = [
    obj for module in (disorder, scattering, attenuation) for obj in vars(module).values() if isinstance(obj, Derived)
]


@pytest.mark.parametrize("derived", DERIVED, ids=lambda d: d.name)
def test_generated_code_equals_evalf(derived):
    args, expr = derived.expression()
    values = [SAMPLE[str(arg)] for arg in args]
    got = np.asarray(derived(*values), dtype=float)
    parts = list(expr) if isinstance(expr, (tuple, sp.Tuple)) else [expr]
    point = dict(zip(args, values, strict=True))
    expected = np.array([float(sp.N(part.rewrite(sp.exp).subs(point), 20)) for part in parts])
    assert np.allclose(got.ravel(), expected, rtol=1e-12)  # double precision against 20 digits


# --- numeric: speeds against Bloch waves computed independently -------------------------------------------


def _diatomic_long_wave_speed(a1, a2, m1, m2, k1, k2):
    """omega/q -> c of the two-phase periodic chain, from its 2 x 2 dynamical matrix (NumPy, no SymPy).

    Cell: ring 1 (m1), contact k1, ring 2 (m2), contact k2, period a1 + a2.  With Bloch phase exp(i q L),
    det(K(q) - omega^2 M) = 0 is m1 m2 W^2 - (k1 + k2)(m1 + m2) W + 4 k1 k2 sin^2(q L/2) = 0; the acoustic root
    is taken as 2c/(b + sqrt(b^2 - 4ac)) (no cancellation), at two small q, Richardson-extrapolated in q^2.
    """
    L = a1 + a2
    speeds = []
    for qL in (2e-3, 1e-3):
        A, B, C = m1 * m2, (k1 + k2) * (m1 + m2), 4 * k1 * k2 * np.sin(qL / 2) ** 2
        W = 2 * C / (B + np.sqrt(B * B - 4 * A * C))
        speeds.append(W / (qL / L) ** 2)  # c^2 + O(q^2)
    return np.sqrt((4 * speeds[1] - speeds[0]) / 3)


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_two_phase_chain_against_its_bloch_limit(seed):
    rng = np.random.default_rng(seed)
    a1, a2, m1, m2, k1, k2 = rng.uniform(0.2, 5.0, 6)
    c = effective_medium_speed(k=[k1, k2], m=[m1, m2], a=[a1, a2])
    # Richardson leaves O(q^4) ~ 1e-12 and the root keeps its digits: 1e-9 is rounding with margin.
    assert c == pytest.approx(_diatomic_long_wave_speed(a1, a2, m1, m2, k1, k2), rel=1e-9)
    assert harmonic_mean_speed(k=[k1, k2], m=[m1, m2], a=[a1, a2]) > c


def test_harmonic_mean_equals_effective_medium_only_at_constant_impedance():
    a_ = [1.0, 1.0]
    # m proportional to 1/k: the impedance sqrt(m k) is the same in both cells, nothing scatters.
    same = (
        effective_medium_speed(k=[1.0, 4.0], m=[4.0, 1.0], a=a_),
        harmonic_mean_speed(k=[1.0, 4.0], m=[4.0, 1.0], a=a_),
    )
    assert same[0] == pytest.approx(same[1], rel=1e-15)  # both 0.8 exactly, up to rounding
    # m proportional to k: every local speed is 1, yet the effective medium is slower, 1/sqrt(<k><1/k>) = 0.8.
    assert harmonic_mean_speed(k=[1.0, 4.0], m=[1.0, 4.0], a=a_) == pytest.approx(1.0, rel=1e-15)
    assert effective_medium_speed(k=[1.0, 4.0], m=[1.0, 4.0], a=a_) == pytest.approx(0.8, rel=1e-15)


def test_random_periodic_chain_against_transfer_matrices():
    """A period of 7 random cells: cos(q L) = tr(T_7 ... T_1)/2 at small omega, by NumPy matrix products."""
    rng = np.random.default_rng(11)
    a_, m_, k_ = rng.uniform(0.5, 2.0, (3, 7))
    speeds = []
    for w in (2e-3, 1e-3):
        P = np.eye(2)
        for m_j, k_j in zip(m_, k_, strict=True):
            P = np.array([[1 - m_j * w * w / k_j, 1 / k_j], [-m_j * w * w, 1.0]]) @ P
        qL = np.arccos(np.trace(P) / 2)
        speeds.append((w * a_.sum() / qL) ** 2)
    c = np.sqrt((4 * speeds[1] - speeds[0]) / 3)
    # arccos near 1 loses half the digits: qL ~ 1e-3 has a relative error ~ 1e-16/1e-6; 1e-8 covers it.
    assert effective_medium_speed(k=k_, m=m_, a=a_) == pytest.approx(c, rel=1e-8)


# --- numeric: the second-order expansions against exact evaluation on seeded samples ---------------------


def _samples(seed, size=4000, symmetric=False):
    """Standardised deviations (z_K, z_m, z_a), correlated; skewed (centred exponentials) or exactly symmetric."""
    rng = np.random.default_rng(seed)
    base = rng.exponential(size=(3, size)) - 1.0  # skewness 2
    mixed = np.array([base[0], 0.6 * base[0] + 0.8 * base[1], 0.3 * base[1] + base[2]])
    if symmetric:  # every odd joint moment of the sample vanishes
        mixed = np.concatenate([mixed, -mixed], axis=1)
    mixed -= mixed.mean(axis=1, keepdims=True)
    return mixed / mixed.std(axis=1, keepdims=True)


def _sample_spreads(K_, m_):
    kappa, mu = K_ / K_.mean() - 1, m_ / m_.mean() - 1
    return kappa.std(), mu.std(), np.mean(kappa * mu) / (kappa.std() * mu.std())


def _scaling(errors, spreads):
    """Slope of log|error| against log(spread)."""
    return np.polyfit(np.log(spreads), np.log(np.abs(errors)), 1)[0]


@pytest.mark.parametrize(("symmetric", "order"), [(False, 3), (True, 4)])
@pytest.mark.parametrize("n_value", [1.0, 1.3])
def test_speed_shifts_against_exact_evaluation(symmetric, order, n_value):
    z_K, z_m, z_a = _samples(5, symmetric=symmetric)
    spreads = np.geomspace(0.005, 0.08, 6)
    errors = {estimate: [] for estimate in disorder.ESTIMATES}
    contrast_errors = []
    for sigma in spreads:
        K_, m_, a_ = 2.0 * (1 + sigma * z_K), 0.3 * (1 + 0.7 * sigma * z_m), 0.05 * (1 + 0.5 * sigma * z_a)
        sK, sm, corr = _sample_spreads(K_, m_)
        uniform = solitary_wave_speed(1.5, K=K_.mean(), n=n_value, a=a_.mean(), m=m_.mean()) if n_value > 1 else None
        speeds = {}
        for estimate in disorder.ESTIMATES:
            if n_value > 1:
                exact = (
                    disordered_solitary_wave_speed(1.5, estimate=estimate, K=K_, n=n_value, m=m_, a=a_) / uniform - 1
                )
            else:  # the linear chain: K is the stiffness k
                speed = effective_medium_speed if estimate == "effective-medium" else harmonic_mean_speed
                exact = speed(k=K_, m=m_, a=a_) / (a_.mean() * np.sqrt(K_.mean() / m_.mean())) - 1
            speeds[estimate] = exact
            predicted = disorder_speed_shift(estimate=estimate, n=n_value, sigma_K=sK, sigma_m=sm, correlation=corr)
            errors[estimate].append(exact - predicted)
        contrast = (1 + speeds["harmonic-mean"]) / (1 + speeds["effective-medium"]) - 1
        contrast_errors.append(
            contrast - impedance_spread(n=n_value, sigma_K=sK, sigma_m=sm, correlation=corr) ** 2 / 2
        )
    for estimate in disorder.ESTIMATES:
        error = np.array(errors[estimate])
        assert np.all(np.abs(error) < 0.2 * spreads**2)  # beyond second order: small beside sigma^2
        # The error is the next order: sigma^3 (skewed sample) or sigma^4 (odd moments zero).  The fitted slope
        # differs from it by the relative size of the order after, O(sigma) < 0.08 here, so 0.25 bounds it.
        assert _scaling(error, spreads) == pytest.approx(order, abs=0.25)
    # The contrast sigma_Z^2/2 (sigma_Z to first order): its error is of third order at least.
    assert _scaling(np.array(contrast_errors), spreads) > 2.75


def test_effective_medium_ignores_mass_and_spacing_spreads():
    rng = np.random.default_rng(3)
    K_ = np.full(50, 2.0)
    m_, a_ = rng.uniform(0.1, 0.5, 50), rng.uniform(0.01, 0.1, 50)
    exact = disordered_solitary_wave_speed(2.0, estimate="effective-medium", K=K_, n=1.4, m=m_, a=a_)
    assert exact == pytest.approx(
        solitary_wave_speed(2.0, K=2.0, n=1.4, a=a_.mean(), m=m_.mean()), rel=1e-14
    )  # rounding


# --- the numeric functions: closed forms, limits, shapes, refusals -------------------------------------------


def test_shapes_broadcast_over_chains():
    rng = np.random.default_rng(9)
    K_, m_, a_ = rng.uniform(1.0, 2.0, (3, 4, 20)), rng.uniform(1.0, 2.0, (1, 4, 21)), rng.uniform(1.0, 2.0, 21)
    speed = disordered_solitary_wave_speed([[1.0], [2.0], [3.0]], estimate="effective-medium", K=K_, n=1.3, m=m_, a=a_)
    assert speed.shape == (3, 4)
    one = disordered_solitary_wave_speed(2.0, estimate="effective-medium", K=K_[1, 2], n=1.3, m=m_[0, 2], a=a_)
    assert speed[1, 2] == pytest.approx(one, rel=1e-14)
    assert effective_medium_speed(k=K_, m=m_, a=a_).shape == (3, 4)
    assert chain_impedance_spread(K=K_, n=1.3, m=m_).shape == (3, 4)
    assert disorder_speed_shift(
        estimate="effective-medium", n=[1.0, 1.5], sigma_K=0.1, sigma_m=[[0.0], [0.1]]
    ).shape == (2, 2)
    with pytest.raises(ValueError, match="cannot be broadcast"):
        harmonic_mean_speed(k=K_, m=m_, a=a_)  # 21 rings against 20 contacts: the harmonic mean pairs them


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: effective_medium_speed(k=[1.0], m=[1.0], a=[]), "at least one ring"),
        (lambda: effective_medium_speed(k=[1.0], m=[-1.0], a=[1.0]), "m must be positive"),
        (lambda: disordered_solitary_wave_speed(1.0, estimate="harmonic-mean", K=1.0, n=1.0, m=1.0, a=1.0), "n > 1"),
        (
            lambda: disordered_solitary_wave_speed(1.0, estimate="ray", K=1.0, n=1.5, m=1.0, a=1.0),
            "estimate must be one of",
        ),
        (lambda: disorder_speed_shift(estimate="harmonic-mean", n=1.0, sigma_K=0.1, correlation=1.5), "correlation"),
        (lambda: disorder_speed_shift(estimate="effective-medium", n=0.0, sigma_K=0.1), "n > 0"),
        (
            lambda: disorder_speed_shift(estimate="effective-medium", n=1.0, sigma_K=-0.1),
            "sigma_K must be non-negative",
        ),
        (lambda: localization_length(2.0, k=1.0, m=1.0, a=1.0, sigma_k=0.1, sigma_m=0.1), "inside the band"),
        (lambda: disorder_attenuation_length(n=5.0, a=1.0, sigma_Z=0.1), "cusp"),
        (
            lambda: attenuated_travel_time(1.0, V0=1.0, n=1.5, attenuation_length=0.0),
            "attenuation_length must be positive",
        ),
        (
            lambda: attenuated_travel_time(1.0, V0=1.0, n=1.5, attenuation_length=np.nan),
            "attenuation_length must be positive",
        ),
        (lambda: chain_impedance_spread(K=[1.0, 2.0, 3.0], n=1.0, m=[1.0, 2.0]), "give N rings"),
        (lambda: chain_impedance_spread(K=[1.0], n=1.0, m=[1.0, 2.0]), "lags must be smaller"),
        (
            lambda: chain_impedance_spread(K=[1.0], n=1.0, m=[1.0, 2.0], lags=True),
            "lags must be a non-negative integer",
        ),
    ],
)
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()
