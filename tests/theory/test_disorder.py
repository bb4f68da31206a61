"""Weak disorder (issue 23): the derivations against known forms, the expansions against exact evaluation,
the scattering theory against transfer matrices, and the compact wave against a lattice."""

import mpmath
import numpy as np
import pytest
import sympy as sp
from ringchain.theory import (
    attenuated_travel_time,
    chain_impedance_spread,
    disorder,
    disorder_attenuation_length,
    disorder_pulse_spread,
    disorder_speed_shift,
    disordered_solitary_wave_speed,
    effective_medium_speed,
    harmonic_mean_speed,
    impedance_spread,
    linear,
    localization_length,
    solitary_wave_speed,
)
from ringchain.theory._codegen import Derived
from scipy.integrate import quad

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


# --- 7.-9. scattering ------------------------------------------------------------------------------------


def test_junction_reflection_and_the_incoherent_loss():
    R, Delta = disorder.junction_reflection()
    Z1, Z2 = sp.symbols("Z_1 Z_2", positive=True)
    direct = (Z2 - Z1) / (Z1 + Z2)  # the textbook reflection of force at an impedance step
    assert sp.simplify((R.subs(Delta, sp.log(Z2 / Z1)) - direct).rewrite(sp.exp)) == 0
    assert_same(disorder.incoherent_loss(), sigma_Z**2 / 2)


def test_coherent_and_lattice_reflectance():
    assert_same(disorder.coherent_reflectance(), sigma_Z**2 * sp.sin(theta) ** 2)
    born = sp.tan(theta / 2) ** 2 * (sigma_m**2 + sigma_k**2 + 2 * rho * sigma_m * sigma_k * sp.cos(theta))
    assert_same(disorder.lattice_born_reflectance(), born)
    # Long waves: theta^2 (sigma_m^2 + sigma_k^2 + 2 rho sigma_m sigma_k)/4 = theta^2 Var(ln Z), smaller than the
    # incoherent <R^2> = sigma_Z^2/2 by 2 theta^2.
    long_wave = sp.series(born, theta, 0, 3).removeO()
    assert_same(long_wave, theta**2 * (sigma_m**2 + sigma_k**2 + 2 * rho * sigma_m * sigma_k) / 4)


def test_localization_length_symbolic():
    s2 = m * omega**2 / (4 * k)  # sin^2(theta/2) of the mean chain
    expected = a * (1 - s2) / (s2 * (sigma_m**2 + sigma_k**2 + 2 * rho * sigma_m * sigma_k * (1 - 2 * s2)))
    assert_same(disorder.localization_length_symbolic(), expected)


def test_single_defect_reflection_against_the_lattice():
    """One heavier ring in a uniform chain: the exact reflection (transfer matrices) against Born's tan(theta/2) mu."""
    for theta_value in (0.3, 1.0, 2.0):
        w = 2 * np.sin(theta_value / 2)  # m = k = 1
        for mu in (1e-3, -2e-3):
            reflected = _transmission(np.array([w]), np.array([[1.0 + mu]]), np.array([[1.0]]))[1]
            born = np.tan(theta_value / 2) * abs(mu)
            assert abs(reflected[0, 0]) == pytest.approx(born, rel=5 * abs(mu))  # Born is first order: O(mu) relative


def test_pulse_spread_symbolic():
    amplitude, spread = disorder.pulse_spread_symbolic()
    x = S["distance"]
    assert_same(spread, sigma_Z * sp.sqrt(a * x))
    assert_same(amplitude, sp.exp(-(q**2) * spread**2 / 2))


# --- 10.-11. the compact wave ----------------------------------------------------------------------------


def test_profile_wavenumbers():
    assert_same(disorder.profile_wavenumber_squared(), 24 * (n - 1) / (n * (n + 1) * (5 - n)))
    assert_same(disorder.profile_wavenumber_squared("force"), 24 * n * (n - 1) / ((3 * n + 1) * (n + 1)))
    with pytest.raises(ValueError, match="weight"):
        disorder.profile_wavenumber_squared("energy")


@pytest.mark.parametrize("n_value", [1.1, 1.5, 2.7])
def test_profile_wavenumbers_against_quadrature(n_value):
    """a^2 int f'^2/int f^2 of the paper's force profile cos(omega x)^(2n/(n-1)) and strain profile, by mpmath."""
    with mpmath.workdps(30):
        nn = mpmath.mpf(n_value)
        w = (nn - 1) / (nn + 1) * mpmath.sqrt(6 * (nn + 1) / nn)  # a = 1
        edge = mpmath.pi / (2 * w)
        for weight, p in (("strain", 2 / (nn - 1)), ("force", 2 * nn / (nn - 1))):
            # |cos|: at the edges cos(omega x) may round to a tiny negative number.
            f2 = mpmath.quad(lambda x, p=p: abs(mpmath.cos(w * x)) ** (2 * p), [-edge, 0, edge])
            df2 = mpmath.quad(
                lambda x, p=p: (p * w * abs(mpmath.cos(w * x)) ** (p - 1) * mpmath.sin(w * x)) ** 2, [-edge, 0, edge]
            )
            derived = disorder.profile_wavenumber_squared(weight).subs({n: n_value, a: 1})
            assert float(derived) == pytest.approx(float(df2 / f2), rel=1e-12)  # quadrature at 30 digits


def test_attenuation_and_travel_time_symbolic():
    assert_same(disorder.energy_force_exponent(), (n + 1) / n)
    assert_same(disorder.attenuation_length_symbolic(), a * (n + 1) ** 2 * (5 - n) / (24 * (n - 1) * sigma_Z**2))
    time, beta = disorder.travel_time_symbolic()
    assert_same(beta, (n - 1) / (2 * n))
    x, ell, V_0 = S["distance"], S["ell"], S["V_0"]
    assert_same(time, ell * (sp.exp(beta * x / ell) - 1) / (beta * V_0))


def test_equations_are_equalities_of_the_derivations():
    equations = disorder.equations()
    assert equations["effective_medium_speed"].rhs == disorder.effective_medium_speed_symbolic()
    assert equations["attenuation_length"].rhs == disorder.attenuation_length_symbolic()
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
DERIVED = [obj for obj in vars(disorder).values() if isinstance(obj, Derived)]


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


# --- numeric: impedance spreads ---------------------------------------------------------------------------


def test_chain_impedance_spread_of_independent_and_shared_contacts():
    rng = np.random.default_rng(8)
    chains, rings, s = 200, 400, 0.1
    m_ = np.exp(s * rng.standard_normal((chains, rings)))
    K_ = np.exp(s * rng.standard_normal((chains, rings - 1)))
    pooled = np.sqrt(np.mean(chain_impedance_spread(K=K_, n=1.5, m=m_, lags=0) ** 2))
    expected = np.sqrt(s**2 / 4 + s**2 / (4 * 1.5**2))  # Var(ln m/2 + ln K/(2n)), independent
    # 200 x 399 cells: the pooled variance has a relative standard error sqrt(2/79800) = 0.5 %, bias 1/399.
    assert pooled == pytest.approx(expected, rel=0.01)
    # A contact made of its two rings, K_j = (g_j g_{j+1})^(1/2): neighbours correlate; the long-wave variance of
    # ln K/2 over cells is Var(ln g) (the sum telescopes into sum ln g) against Var(ln g)/2 cell by cell.
    g = np.exp(s * rng.standard_normal((chains, rings)))
    shared = np.sqrt(g[:, :-1] * g[:, 1:])
    one = np.ones((chains, rings))
    with_lag = np.sqrt(np.mean(chain_impedance_spread(K=shared, n=1.0, m=one, lags=1) ** 2))
    without = np.sqrt(np.mean(chain_impedance_spread(K=shared, n=1.0, m=one, lags=0) ** 2))
    assert with_lag == pytest.approx(s / 2, rel=0.02)  # ln Z = ln K/2: sd s/2; estimator error about 1 %
    assert without == pytest.approx(s / 2 / np.sqrt(2), rel=0.02)


# --- numeric: scattering against exact transfer matrices --------------------------------------------------


def _transmission(w, m_, k_):
    """(t, r): transmitted and reflected amplitudes of a wave exp(i(theta j - omega t)) through rings m_, contacts k_.

    Rings 1..N (shape (chains, N)) between two semi-infinite uniform chains m = k = 1; amplitudes relative to the
    uniform chain (t = 1, r = 0 without disorder).  State (u_j, F_{j-1}) propagated by the cell transfer matrices.
    """
    theta = 2 * np.arcsin(w / 2)
    e = np.exp(1j * theta)
    chains, N = m_.shape
    # The uniform chain's right- and left-going waves at ring j: u = e^(+-i theta j), F_{j-1} = 1 - e^(-+i theta).
    forward, backward = (np.stack(np.broadcast_arrays(z, (1 - 1 / z) * z)) for z in (e, 1 / e))
    states = []
    for start in (forward, backward):
        u, F = (np.broadcast_to(x, (chains, w.size)).astype(complex) for x in start)
        for j in range(N):
            F = F - m_[:, j : j + 1] * w * w * u
            u = u + F / k_[:, j : j + 1]
        states.append((u, F))
    phase_out = np.exp(1j * theta * N)

    def split(u, F):  # (u, F) = P (1, 1 - 1/e) + Q (1, 1 - e) at ring N + 1, as multiples of the waves there
        Q = (F - (1 - 1 / e) * u) / ((1 - e) - (1 - 1 / e))
        return (u - Q) / (e * phase_out), Q * e * phase_out

    (P1, Q1), (P2, Q2) = split(*states[0]), split(*states[1])
    r = -Q1 / Q2  # incident forward wave plus r backward wave leaves no backward wave on the right
    return P1 + r * P2, r


def _lyapunov(w, m_, k_):
    """Growth rate per ring of |(u, F)| under the cell transfer matrices (the amplitude decay rate of t)."""
    chains, N = m_.shape
    u, F = np.ones((chains, w.size)), np.zeros((chains, w.size))
    total = np.zeros((chains, w.size))
    for j in range(N):
        F = F - m_[:, j : j + 1] * w * w * u
        u = u + F / k_[:, j : j + 1]
        if j % 16 == 15:
            norm = np.hypot(u, F)
            total += np.log(norm)
            u, F = u / norm, F / norm
    return (total + np.log(np.hypot(u, F))) / N


def test_transmission_conserves_energy():
    rng = np.random.default_rng(4)
    w = np.array([0.3, 1.0, 1.7])
    t, r = _transmission(w, np.exp(0.2 * rng.standard_normal((3, 50))), np.exp(0.2 * rng.standard_normal((3, 50))))
    assert np.abs(t) ** 2 + np.abs(r) ** 2 == pytest.approx(np.ones((3, 3)), abs=1e-12)  # same chain both sides


@pytest.mark.parametrize(
    ("s_m", "s_k", "correlation", "born_error"),
    [
        # First Born order: relative error O(sigma^2); the bounds are the measured 8 % at (0.2, 0.15) with room,
        # and its sigma^2 scaling (about 1.5 %) at (0.1, 0.05).
        (0.2, 0.15, 0.3, 0.12),
        (0.1, 0.05, -0.5, 0.03),
    ],
)
def test_localization_length_against_lyapunov_exponents(s_m, s_k, correlation, born_error):
    rng = np.random.default_rng(2)
    chains, rings = 32, 20000
    z1 = rng.standard_normal((chains, rings))
    z2 = correlation * z1 + np.sqrt(1 - correlation**2) * rng.standard_normal((chains, rings))
    m_, k_ = 1 + s_m * z1, 1 + s_k * z2  # positive: 5 standard deviations below 1 at most
    theta_values = np.array([0.3, 1.0, 2.0])
    w = 2 * np.sin(theta_values / 2)
    rate = _lyapunov(w, m_, k_)  # per ring, amplitude: 1/(2 ell) with ell in rings (a = 1)
    measured, error = rate.mean(axis=0), rate.std(axis=0) / np.sqrt(chains)
    predicted = 1 / (2 * localization_length(w, k=1.0, m=1.0, a=1.0, sigma_k=s_k, sigma_m=s_m, correlation=correlation))
    # Three standard errors of the mean over the chains, plus the Born order.
    assert np.all(np.abs(measured / predicted - 1) < born_error + 3 * error / predicted)


def _pulse_through_random_chains(s, rings, width, seed, chains=16):
    """Ordered and disordered outputs of a Gaussian force pulse of rms duration ``width`` (m = k = a = 1)."""
    rng = np.random.default_rng(seed)
    z = rng.standard_normal((2, chains, rings))
    m_, k_ = np.exp(s * z[0] - s * s / 2), np.exp(s * z[1] - s * s / 2)  # log-normal, mean 1
    samples, duration = 2**15, 2.0**14  # a window long beside the chain's travel time and the coda
    w_all = 2 * np.pi * np.fft.rfftfreq(samples, duration / samples)
    keep = (w_all > 0) & (w_all < 8 / width)  # the spectrum exp(-(w width)^2/2) is below 1e-14 beyond
    w = w_all[keep]
    t, _ = _transmission(w, m_, k_)
    spectrum = np.exp(-((w * width) ** 2) / 2)
    theta_w = 2 * np.arcsin(w / 2)
    # NumPy's inverse FFT sums exp(+i w t): the conjugate of the exp(-i w t) convention of _transmission.
    ordered_spectrum = spectrum * np.exp(-1j * theta_w * rings)

    def signal(spec):
        full = np.zeros((*spec.shape[:-1], w_all.size), complex)
        full[..., keep] = spec
        return np.fft.irfft(full, samples, axis=-1)

    return dict(
        m=m_, k=k_, w=w, spectrum=spectrum, theta=theta_w, time=np.arange(samples) * duration / samples,
        ordered=signal(ordered_spectrum), disordered=signal(ordered_spectrum * np.conj(t)), t=t, signal=signal,
        ordered_spectrum=ordered_spectrum,
    )  # fmt: skip


@pytest.mark.parametrize(("s", "rings"), [(0.1, 4000), (0.2, 1000)])
def test_long_pulse_through_a_random_chain(s, rings):
    """O'Doherty-Anstey: the pulse keeps its shape up to a Gaussian spread and arrives at the effective-medium time."""
    width = 10.0  # rms duration in ring transit times: a pulse about 10 rings wide
    run = _pulse_through_random_chains(s, rings, width, seed=7)
    m_, k_, w = run["m"], run["k"], run["w"]
    sigma = np.sqrt(np.mean(chain_impedance_spread(K=k_, n=1.0, m=m_, lags=0) ** 2))  # pooled over the chains
    # Peak: the ordered output convolved with the Gaussian of disorder_pulse_spread (q = theta/a).
    spread = disorder_pulse_spread(rings, a=1.0, sigma_Z=sigma)
    smoothed = run["signal"](run["ordered_spectrum"] * np.exp(-((run["theta"] * spread) ** 2) / 2))
    peak = run["disordered"].max(axis=1) / run["ordered"].max()
    predicted_loss = 1 - smoothed.max() / run["ordered"].max()
    loss, loss_error = 1 - peak.mean(), peak.std() / np.sqrt(peak.size)
    # Tolerance on the loss: 3 standard errors; the two ends of the random segment (impedance steps against the
    # uniform chains outside, about (w/N)^2... relative w^2/N = 2.5 % and 10 %); Born O(sigma^2) (1-4 %).
    edges = width**2 / rings
    assert abs(loss / predicted_loss - 1) < 3 * loss_error / predicted_loss + edges + 4 * s**2
    # Energy: <ln T> = -x/ell(omega) at each frequency (localization_length), against the exact |t|^2, averaged over
    # the chains and weighted by the pulse's spectrum.  (The mean of T itself differs from exp(-x/ell) at second
    # order in x/ell, about 9 % here: the statistic of the localization length is the logarithm.)
    weight = run["spectrum"] ** 2 / np.sum(run["spectrum"] ** 2)
    log_loss = -np.sum(np.log(np.abs(run["t"]) ** 2) * weight, axis=1)
    spreads = dict(sigma_k=k_.std() / k_.mean(), sigma_m=m_.std() / m_.mean())  # the relative spreads of the samples
    predicted_log_loss = np.sum(rings / localization_length(w, k=1.0, m=1.0, a=1.0, **spreads) * weight)
    log_error = log_loss.std() / np.sqrt(log_loss.size)
    assert abs(log_loss.mean() / predicted_log_loss - 1) < 3 * log_error / predicted_log_loss + edges + 4 * s**2
    energy = np.sum(np.abs(run["t"]) ** 2 * weight, axis=1)
    # Pulses shorter than a ring would lose <R^2> = sigma_Z^2/2 per ring, incoherently: nearly everything here.
    incoherent = 1 - np.exp(-rings * float(disorder.incoherent_loss().subs(sigma_Z, sigma)))
    assert incoherent > 0.99 and 1 - energy.mean() < 0.1 * incoherent
    # Arrival: each chain's effective-medium time sqrt(sum m sum 1/k), not its harmonic (ray) time sum sqrt(m/k).
    delay = run["time"][run["disordered"].argmax(axis=1)] - run["time"][run["ordered"].argmax()]
    effective = rings / effective_medium_speed(k=k_, m=m_, a=np.ones(rings)) - rings
    harmonic = rings / harmonic_mean_speed(k=k_, m=m_, a=np.ones(rings)) - rings
    gap = np.mean(effective - harmonic)  # rings sigma_Z^2/2: 10 transit times for both parameter sets
    assert gap == pytest.approx(rings * sigma**2 / 2, rel=0.1)  # second order, sigma_Z^2 <= 0.02
    # The sampling step is 0.5 and the pulse 10 wide: the argmax of each chain is good to a few tenths.
    assert abs(np.mean(delay - effective)) < 0.1 * gap
    assert abs(np.mean(delay - harmonic)) > 0.9 * gap


# --- the compact wave on the power-law lattice -------------------------------------------------------------


def _power_law_lattice(n_value, m_, K_, v0=1.0, dt=0.02, t_end=450.0):
    """Peak force and its time at every contact of power-law chains struck at ring 0 (velocity Verlet, NumPy).

    m u_j'' = K_j (u_{j+1} - u_j)_+^n - K_{j-1} (u_j - u_{j-1})_+^n (tension positive, a = 1); ring 0 moves off at
    v0 away from the chain.  Units K ~ m ~ 1: the wave crosses a ring in about 1.3 time units, dt = 0.02 resolves
    the fastest contact oscillation (omega dt < 0.1) and the peak time to dt.
    """
    u, v = np.zeros_like(m_), np.zeros_like(m_)
    v[:, 0] = -v0

    def acceleration(u):
        force = K_ * np.maximum(np.diff(u, axis=1), 0.0) ** n_value
        total = np.zeros_like(u)
        total[:, :-1] += force
        total[:, 1:] -= force
        return total / m_, force

    acc, force = acceleration(u)
    peak, when = np.zeros_like(K_), np.zeros_like(K_)
    for step in range(1, int(t_end / dt) + 1):
        v += 0.5 * dt * acc
        u += dt * v
        acc, force = acceleration(u)
        v += 0.5 * dt * acc
        higher = force > peak
        peak = np.where(higher, force, peak)
        when = np.where(higher, step * dt, when)
    return peak, when


@pytest.mark.slow
@pytest.mark.parametrize("n_value", [1.2, 1.5])
def test_compact_wave_in_a_random_power_law_chain(n_value):
    """Attenuation and mean speed of the formed compact wave against the disorder theory (K = m = a = 1 on average)."""
    chains, rings, first, last = 16, 300, 60, 260  # the wave has formed by ring 60 (its support: 5-10 rings)
    rng = np.random.default_rng(3)
    m_ = np.exp(0.15 * rng.standard_normal((chains, rings)))
    K_ = np.exp(0.2 * rng.standard_normal((chains, rings - 1)))
    m_, K_ = m_ / m_.mean(axis=1, keepdims=True), K_ / K_.mean(axis=1, keepdims=True)
    ordered, ordered_time = _power_law_lattice(n_value, np.ones((1, rings)), np.ones((1, rings - 1)))
    peak, time = _power_law_lattice(n_value, m_, K_)
    contacts = np.arange(first, last)
    # Attenuation: the slope of ln(F_m/F_m,ordered) ring by ring (the ordered wave's own formation divides out).
    relative = np.log(peak[:, first:last] / ordered[0, first:last])
    slopes = np.array([np.polyfit(contacts, relative[c], 1)[0] for c in range(chains)])
    sigma = np.sqrt(np.mean(chain_impedance_spread(K=K_, n=n_value, m=m_, lags=0) ** 2))
    ratio = -1 / slopes.mean() / disorder_attenuation_length(n=n_value, a=1.0, sigma_Z=sigma)
    ratio_error = abs(ratio) * slopes.std() / np.sqrt(chains) / abs(slopes.mean())
    # A leading-order estimate in a^2 <q^2> (0.48 for n = 1.2, 0.91 for n = 1.5): measured 1.08 and 1.10 here, each
    # +- 0.03; the documented 0.9-1.25 with 3 standard errors.
    assert 0.9 - 3 * ratio_error < ratio < 1.25 + 3 * ratio_error
    # The force weighting of the profile (profile_wavenumber_squared("force")) would be off by 1.3 and 1.6.
    weights = [float(disorder.profile_wavenumber_squared(w).subs({n: n_value, a: 1})) for w in ("force", "strain")]
    assert ratio * weights[0] / weights[1] > 1.25
    # While the wave forms it loses more: by ring 10 the peak is 15 % below the ordered chain's (16 chains: the
    # standard error is about 1 %), 3-5 times what the formed wave's rate gives over 10 rings.
    early = -np.mean(np.log(peak[:, 10] / ordered[0, 10]))
    assert 0.12 < early < 0.18 and early > 2.5 * 10 * -slopes.mean()
    # Speed: the travel time from contact `first` to `last` against each chain's estimates at the local force (the
    # fitted exponential trend), both scaled by the ordered chain's ratio of measured to Eq. (8) time (Eq. (8) is a
    # long-wave speed, about 1 % slow for n = 1.5 on the lattice).
    base = (ordered_time[0, last] - ordered_time[0, first]) / np.sum(
        1 / solitary_wave_speed(ordered[0, first:last], K=1.0, n=n_value, a=1.0, m=1.0)
    )
    excess = {estimate: np.empty(chains) for estimate in disorder.ESTIMATES}
    for c in range(chains):
        force = np.exp(np.polyval(np.polyfit(contacts, np.log(peak[c, first:last]), 1), contacts))
        K_c, m_c = K_[c, first:last], m_[c, first:last]
        # Harmonic mean: each cell at its own speed (one-ring "chains", one per cell, at that cell's force).
        local = disordered_solitary_wave_speed(
            force, estimate="harmonic-mean", K=K_c[:, None], n=n_value, m=m_c[:, None], a=1
        )
        # Effective medium: the homogenised cells crossed, at the force of each step.
        medium = disordered_solitary_wave_speed(
            force[:, None], estimate="effective-medium", K=K_c, n=n_value, m=m_c, a=1.0
        )
        took = time[c, last] - time[c, first]
        excess["harmonic-mean"][c] = took / (base * np.sum(1 / local)) - 1
        excess["effective-medium"][c] = took / (base * np.sum(1 / medium)) - 1
    harmonic, medium_ = excess["harmonic-mean"], excess["effective-medium"]
    gap = np.mean(harmonic - medium_)  # sigma_Z^2/2 of these chains, about 0.5 %
    assert gap == pytest.approx(sigma**2 / 2, rel=0.25)  # the second-order contrast; the rest is O(sigma^3)
    # The wave crosses each ring at its local speed: within 0.3 % of the harmonic-mean time (3 standard errors are
    # 0.03 %), and at least half the gap faster than the effective medium.
    assert abs(harmonic.mean()) < 0.003
    assert medium_.mean() < -0.5 * gap


# --- the numeric functions: closed forms, limits, shapes, refusals -------------------------------------------


def test_attenuation_length_and_travel_time_numbers():
    # ell = a (n+1)^2 (5-n)/(24 (n-1) sigma_Z^2): n = 1.5, a = 2 mm, sigma_Z = 0.1 -> 6.25 * 3.5/12 * 0.2 m.
    assert disorder_attenuation_length(n=1.5, a=2e-3, sigma_Z=0.1) == pytest.approx(
        6.25 * 3.5 / 12 * 2e-3 / 0.01, rel=1e-14
    )
    assert np.isinf(disorder_attenuation_length(n=1.2, a=1.0, sigma_Z=0.0))
    V0, n_value, ell = 3.0, 1.25, 0.4
    for x in (1e-9, 0.05, 1.0, 7.0):
        numeric = quad(lambda y: np.exp((n_value - 1) / (2 * n_value) * y / ell) / V0, 0, x, epsabs=0, epsrel=1e-13)[0]
        assert attenuated_travel_time(x, V0=V0, n=n_value, attenuation_length=ell) == pytest.approx(
            numeric, rel=1e-12
        )  # quad's tolerance
    # No decay, or n -> 1 (no amplitude dependence of the speed): x/V0 to rounding, through expm1.
    assert attenuated_travel_time(2.0, V0=4.0, n=1.3, attenuation_length=np.inf) == 0.5
    assert attenuated_travel_time(2.0, V0=4.0, n=1 + 1e-12, attenuation_length=1e-3) == pytest.approx(
        0.5 * np.expm1(1e-9) / 1e-9, rel=1e-12
    )


def test_pulse_spread_and_localization_numbers():
    assert disorder_pulse_spread([0.0, 4.0], a=1e-2, sigma_Z=0.05) == pytest.approx(
        [0.0, 0.05 * np.sqrt(4e-2)], rel=1e-14
    )
    # theta = pi/2 (omega = sqrt(2 k/m)): tan^2 = 1, cos = 0 -> ell = a/(sigma_m^2 + sigma_k^2).
    assert localization_length(
        np.sqrt(2.0), k=1.0, m=1.0, a=0.02, sigma_k=0.2, sigma_m=0.1, correlation=0.7
    ) == pytest.approx(0.02 / 0.05, rel=1e-13)
    assert np.isinf(localization_length(1.0, k=1.0, m=1.0, a=1.0, sigma_k=0.0, sigma_m=0.0))
    # Fully anticorrelated equal spreads: the impedance is constant to first order; what is left scatters as
    # 2 sigma^2 (1 - cos theta) tan^2(theta/2), of order theta^4 at long waves.
    small = localization_length(1e-2, k=1.0, m=1.0, a=1.0, sigma_k=0.1, sigma_m=0.1, correlation=-1.0)
    assert small == pytest.approx(1 / (0.01 * (1e-2) ** 4 / 4), rel=1e-3)  # theta = 1e-2 up to O(theta^2)
    assert (
        impedance_spread(n=1.0, sigma_K=0.1, sigma_m=0.1, correlation=-1.0) == 0.0
    )  # exactly, the sum-of-squares form


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


@pytest.mark.parametrize("n_value", [1e-150, 1e-300])
def test_chain_impedance_spread_of_a_tiny_exponent(n_value):
    # ln K/(2n) is huge for n -> 0: its squared deviations overflowed (a RuntimeWarning, an error in this suite).
    # With equal masses sigma_Z is exactly proportional to 1/n.
    K_, m_ = [1.0, 2.0, 4.0, 3.0], [1.0, 1.0, 1.0, 1.0]
    for lags in (0, 1):
        unit = float(chain_impedance_spread(K=K_, n=1.0, m=m_, lags=lags))
        assert float(chain_impedance_spread(K=K_, n=n_value, m=m_, lags=lags)) == pytest.approx(unit / n_value)


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
