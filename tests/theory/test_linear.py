"""Linear waves of the chain under static tension: dispersion, band edges, sound speed, travel time."""

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain.theory import (
    BandEdges,
    band_edges,
    dispersion,
    linear,
    linear_sound_speed,
    linear_travel_time,
    series_displacement,
    sound_speed,
)

S = linear.symbols()
q, a, m, n, K, F_0, K_b, k_c = (S[k] for k in ("q", "a", "m", "n", "K", "F_0", "K_b", "k_c"))

#: The paper's R/r = 9 ring: K_c, K_b of the theory, m_eff = 0.37 m0, a = 2(R - r) (SI).
RING = dict(K=7509032236.284589, n=1.5, m=0.00821644566390689, K_b=3315940.832962473)


def assert_same(derived, expected):
    assert sp.simplify(derived - expected) == 0


# --- derivations against the textbook closed forms ------------------------------------------------


def test_contact_stiffness_is_the_slope_of_the_power_law_at_the_static_force():
    assert_same(linear.contact_stiffness(), n * K ** (1 / n) * F_0 ** ((n - 1) / n))
    delta = sp.Symbol("delta", positive=True)
    slope = sp.diff(K * delta**n, delta).subs(delta, (F_0 / K) ** (1 / n))
    assert_same(sp.powsimp(sp.expand_power_base(slope, force=True), force=True), linear.contact_stiffness())


def test_power_law_dispersion_is_the_monatomic_chain():
    assert_same(linear.power_law_dispersion(), 4 * k_c / m * sp.sin(q * a / 2) ** 2)


def test_dual_spring_matrix():
    # Two masses m/2, springs K_b (inside a ring) and k_c (between rings), Bloch phase exp(i q a).
    M = m / 2
    expected = sp.Matrix(
        [
            [(k_c + K_b) / M, -(K_b + k_c * sp.exp(-sp.I * q * a)) / M],
            [-(K_b + k_c * sp.exp(sp.I * q * a)) / M, (k_c + K_b) / M],
        ]
    )
    assert (linear.dual_spring_matrix() - expected).applyfunc(sp.simplify) == sp.zeros(2, 2)


def test_dual_spring_branches_are_the_diatomic_chain():
    """The textbook diatomic chain with equal masses M = m/2 and alternating springs (e.g. Brillouin, Kittel)."""
    acoustic, optical = linear.dual_spring_branches()
    root = sp.sqrt(k_c**2 + K_b**2 + 2 * k_c * K_b * sp.cos(q * a))
    textbook = [2 / m * (k_c + K_b - root), 2 / m * (k_c + K_b + root)]
    for derived, expected in zip((acoustic, optical), textbook, strict=True):
        for values in ({k_c: 3, K_b: 1, q: sp.Rational(7, 10), a: 1, m: 2}, {k_c: 1, K_b: 5, q: 3, a: 2, m: 1}):
            assert abs(sp.N(derived.subs(values) - expected.subs(values), 40)) < 1e-35
    assert_same(sp.expand(acoustic * optical), sp.expand(16 * k_c * K_b * sp.sin(q * a / 2) ** 2 / m**2))


@settings(max_examples=30, deadline=None)
@given(
    kc=st.floats(1e-3, 1e3),
    kb=st.floats(1e-3, 1e3),
    qa=st.floats(-7.0, 7.0),
)
def test_dual_spring_numeric_branches_solve_the_eigenproblem(kc, kb, qa):
    """The numeric branches are the eigenvalues of the 2 x 2 Bloch matrix, evaluated in mpmath."""
    mass = 2.0  # each half 1 kg
    # n = 1: the contact is linear, k_c = K at any static force.
    omega = dispersion(qa, model="dual-spring", F_0=1.0, K=kc, n=1.0, m=mass, a=1.0, K_b=kb)
    z = mpmath.expjpi(qa / mpmath.pi)
    D = mpmath.matrix([[kc + kb, -(kb + kc / z)], [-(kb + kc * z), kc + kb]])  # divided by m/2 = 1
    eigen = sorted(mpmath.re(e) for e in mpmath.eig(D)[0])
    np.testing.assert_allclose(omega**2, [float(e) for e in eigen], rtol=1e-9, atol=1e-12 * (kc + kb))


def test_band_edges_are_the_springs_alone_and_together():
    edges = linear.band_edges_symbolic()
    for kc, kb in ((3, 1), (1, 5), (2, 2)):
        values = {k_c: kc, K_b: kb, m: 7}
        assert sp.simplify(edges["acoustic_top"].subs(values) - sp.Rational(4 * min(kc, kb), 7)) == 0
        assert sp.simplify(edges["optical_bottom"].subs(values) - sp.Rational(4 * max(kc, kb), 7)) == 0
        assert sp.simplify(edges["optical_top"].subs(values) - sp.Rational(4 * (kc + kb), 7)) == 0


def test_dual_spring_sound_speed_is_contact_and_bending_in_series():
    series = 1 / (1 / k_c + 1 / K_b)
    assert_same(linear.dual_spring_sound_speed() ** 2, a**2 * series / m)


def test_stiff_rings_give_the_power_law_chain():
    """K_b -> infinity: the acoustic branch of the dual-spring chain is the power-law chain with the contact."""
    acoustic, optical = linear.dual_spring_branches()
    assert_same(sp.limit(acoustic, K_b, sp.oo), linear.power_law_dispersion())
    assert sp.limit(optical, K_b, sp.oo) == sp.oo


def test_equal_springs_fold_the_monatomic_chain_of_half_spacing():
    """k_c = K_b: masses m/2 every a/2 on springs k, whose single branch 2 sqrt(2k/m) |sin(q a/4)| is folded."""
    acoustic, optical = (b.subs(K_b, k_c) for b in linear.dual_spring_branches())
    for value in (sp.Rational(1, 3), sp.Integer(1), sp.Rational(5, 2)):
        point = {q: value, a: 1, m: 3, k_c: 2}
        assert abs(sp.N(acoustic.subs(point) - sp.Rational(16, 3) * sp.sin(value / 4) ** 2, 30)) < 1e-25
        assert abs(sp.N(optical.subs(point) - sp.Rational(16, 3) * sp.cos(value / 4) ** 2, 30)) < 1e-25


# --- numeric functions ---------------------------------------------------------------------------------


def test_dispersion_shapes_and_branch_order():
    qs = np.linspace(-np.pi, np.pi, 7)[:, None] / 0.04
    forces = np.array([0.5, 2.0, 20.0])
    omega = dispersion(qs, model="dual-spring", F_0=forces, a=0.04, **RING)
    assert omega.shape == (7, 3, 2)
    assert np.all(omega[..., 0] <= omega[..., 1])
    np.testing.assert_allclose(omega, omega[::-1], rtol=1e-12)  # even in q
    single = dispersion(qs, model="power-law", F_0=forces, K=4.9e6, n=1.11, m=0.0082, a=0.04)
    assert single.shape == (7, 3, 1)
    shifted = dispersion(qs + 2 * np.pi / 0.04, model="power-law", F_0=forces, K=4.9e6, n=1.11, m=0.0082, a=0.04)
    np.testing.assert_allclose(shifted, single, rtol=1e-9, atol=1e-6)  # 2 pi/a periodic


def test_power_law_dispersion_numbers():
    qa = np.array([0.3, 1.0, 3.0])
    F_0, Kp, npow, mass, spacing = 2.0, 4.9e6, 1.11, 0.0082, 0.04
    k = npow * Kp ** (1 / npow) * F_0 ** ((npow - 1) / npow)
    expected = 2 * np.sqrt(k / mass) * np.abs(np.sin(qa / 2))
    omega = dispersion(qa / spacing, model="power-law", F_0=F_0, K=Kp, n=npow, m=mass, a=spacing)[..., 0]
    np.testing.assert_allclose(omega, expected, rtol=1e-12)


def test_acoustic_branch_keeps_its_digits_at_long_wavelength():
    """omega/q -> c: the stable form loses nothing at q a = 1e-9, where the difference form loses everything."""
    c = sound_speed(model="dual-spring", F_0=2.0, a=0.04, **RING)
    q_small = 1e-9 / 0.04
    omega = dispersion(q_small, model="dual-spring", F_0=2.0, a=0.04, **RING)[0]
    # omega = c q (1 - O((q a)^2)), the correction below 1e-18 here.
    assert omega / q_small == pytest.approx(float(c), rel=1e-13)


def test_band_edges_are_the_dispersion_at_the_zone_edges():
    equal = (RING["K_b"] / 1.5) ** 3 / RING["K"] ** 2  # N: k_c = 1.5 K^(2/3) F_0^(1/3) = K_b (0.19 N)
    forces = np.array([0.05, 0.15, 1.0, 30.0])  # both sides of k_c = K_b
    edges = band_edges(model="dual-spring", F_0=forces, **RING)
    assert isinstance(edges, BandEdges)
    at_edge = dispersion(np.pi / 0.04, model="dual-spring", F_0=forces, a=0.04, **RING)
    at_centre = dispersion(0.0, model="dual-spring", F_0=forces, a=0.04, **RING)
    np.testing.assert_allclose(edges.acoustic_top, at_edge[:, 0], rtol=1e-12)
    np.testing.assert_allclose(edges.optical_bottom, at_edge[:, 1], rtol=1e-12)
    np.testing.assert_allclose(edges.optical_top, at_centre[:, 1], rtol=1e-12)
    # One edge is the ring body alone, 2 sqrt(K_b/m), at every force (module docstring).
    ring_mode = 2 * np.sqrt(RING["K_b"] / RING["m"])
    bending_edge = np.where(forces < equal, edges.optical_bottom, edges.acoustic_top)
    np.testing.assert_allclose(bending_edge, ring_mode, rtol=1e-12)


def test_slack_contacts_leave_every_ring_on_its_own():
    """F_0 = 0 (n > 1): k_c = 0, the acoustic band collapses to 0 and the optical band is flat at 2 sqrt(K_b/m)."""
    qs = np.linspace(0.0, np.pi / 0.04, 9)
    omega = dispersion(qs, model="dual-spring", F_0=0.0, a=0.04, **RING)
    np.testing.assert_array_equal(omega[:, 0], 0.0)
    np.testing.assert_allclose(omega[:, 1], 2 * np.sqrt(RING["K_b"] / RING["m"]), rtol=1e-12)
    edges = band_edges(model="dual-spring", F_0=0.0, **RING)
    assert edges.optical_bottom == pytest.approx(edges.optical_top, rel=1e-12)


def test_power_law_band_edges():
    edges = band_edges(model="power-law", F_0=[1.0, 8.0], K=1.0, n=3.0, m=4.0)
    # k_c = 3 F_0^(2/3): 3 and 12, top 2 sqrt(k_c/m).
    np.testing.assert_allclose(edges.acoustic_top, [np.sqrt(3.0), np.sqrt(12.0)], rtol=1e-12)
    assert np.all(np.isnan(edges.optical_bottom)) and np.all(np.isnan(edges.optical_top))


def test_sound_speed_of_each_model():
    power = sound_speed(model="power-law", F_0=[1.0, 3.0], K=4.9e6, n=1.11, m=0.0082, a=0.04)
    np.testing.assert_array_equal(power, linear_sound_speed([1.0, 3.0], K=4.9e6, n=1.11, m=0.0082, a=0.04))
    # Dual spring: the tangent stiffness of the series law Eq. (3), here by differentiating delta(F) numerically.
    F_0, h = 2.0, 1e-4
    delta = [series_displacement(F, K_c=RING["K"], K_b=RING["K_b"]) for F in (F_0 - h, F_0 + h)]
    stiffness = 2 * h / (delta[1] - delta[0])
    c = sound_speed(model="dual-spring", F_0=F_0, a=0.04, **RING)
    assert float(c) == pytest.approx(0.04 * np.sqrt(stiffness / RING["m"]), rel=1e-7)  # central difference, h^2


def test_linear_travel_time_sums_the_cells():
    chain = dict(K=4.9e6, n=1.11, m=0.0082, a=0.04)
    weight = 0.0222 * 9.80665
    t = linear_travel_time(3, 9, model="power-law", m_gravity=0.0222, **chain)
    cells = [0.04 / sound_speed(model="power-law", F_0=(k + 1) * weight, **chain) for k in range(3, 9)]
    assert float(t) == pytest.approx(float(np.sum(cells)), rel=1e-14)
    # A linear chain (n = 1) has one speed: the time is distance over speed.
    linear_chain = linear_travel_time(0, 10, model="power-law", K=4.0, n=1.0, m=1.0, a=0.5)
    assert float(linear_chain) == pytest.approx(10 * 0.5 / (0.5 * 2.0), rel=1e-14)
    # m_gravity defaults to m; g and the parameters broadcast.
    default = linear_travel_time(2, 5, model="dual-spring", a=0.04, **RING)
    explicit = linear_travel_time(2, 5, model="dual-spring", a=0.04, m_gravity=RING["m"], **RING)
    assert float(default) == float(explicit)
    both = linear_travel_time(2, 5, model="dual-spring", a=0.04, g=[9.80665, 1.62], **RING)
    assert both.shape == (2,) and both[0] == pytest.approx(float(default)) and both[1] > both[0]  # the Moon: slower


def test_travel_time_grows_less_than_the_distance_up_a_hanging_chain():
    """The weight below grades the force, so the same distance is crossed faster higher up."""
    low = linear_travel_time(0, 10, model="dual-spring", a=0.04, **RING)
    high = linear_travel_time(50, 60, model="dual-spring", a=0.04, **RING)
    assert high < low
    # Far up, the contacts are much stiffer than the rings: the speed tends to a sqrt(K_b/m).
    far = linear_travel_time(100000, 100001, model="dual-spring", a=0.04, **RING)
    assert float(far) == pytest.approx(0.04 / (0.04 * np.sqrt(RING["K_b"] / RING["m"])), rel=0.02)


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: dispersion(1.0, model="chain", F_0=1.0, K=1.0, n=1.5, m=1.0, a=1.0), "model must be one of"),
        (lambda: dispersion(1.0, model="dual-spring", F_0=1.0, K=1.0, n=1.5, m=1.0, a=1.0), "needs the bending"),
        (lambda: dispersion(1.0, model="power-law", F_0=1.0, K=1.0, n=1.5, m=1.0, a=1.0, K_b=1.0), "K_b belongs"),
        (lambda: dispersion(1.0, model="power-law", F_0=-1.0, K=1.0, n=1.5, m=1.0, a=1.0), "F_0 must be non-neg"),
        (lambda: band_edges(model="power-law", F_0=0.0, K=1.0, n=0.8, m=1.0), "F_0 = 0 with n < 1"),
        (lambda: sound_speed(model="power-law", F_0=1.0, K=1.0, n=1.5, m=0.0, a=1.0), "m must be positive"),
        (lambda: linear_travel_time(5, 5, model="power-law", K=1.0, n=1.5, m=1.0, a=1.0), "ring_from < ring_to"),
        (lambda: linear_travel_time(0, 3, model="power-law", K=1.0, n=1.5, m=1.0, a=1.0, g=0.0), "g must be"),
    ],
)
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_ring_index_must_be_an_integer():
    with pytest.raises(TypeError, match="integer ring index"):
        linear_travel_time(0, 2.5, model="power-law", K=1.0, n=1.5, m=1.0, a=1.0)
