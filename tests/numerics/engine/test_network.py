"""The lattice right-hand sides are the paper's Eqs. (5)-(7)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain.numerics import ANCHOR, Chain, Network, laws, linear_spring_force, power_law_force

G = 9.81


def test_power_law_force_values():
    assert power_law_force(2.0, K=3.0, n=1.5) == pytest.approx(3.0 * 2.0**1.5, rel=1e-15)
    # A dashpot inside the bracket adds gamma delta_dot while engaged ...
    assert power_law_force(1.0, 2.0, K=3.0, n=1.2, gamma=0.5) == pytest.approx(4.0, rel=1e-15)
    # ... the bracket clips a negative total to zero (never adhesive) ...
    assert power_law_force(1.0, -10.0, K=3.0, n=1.2, gamma=0.5) == 0.0
    # ... and an open contact carries nothing, however fast it closes.
    assert power_law_force(-1e-9, 100.0, K=3.0, n=1.5, gamma=0.5) == 0.0
    assert power_law_force(0.0, 100.0, K=3.0, n=1.5, gamma=0.5) == 0.0


def test_linear_spring_is_bidirectional():
    assert linear_spring_force(-2.0, K=3.0) == -6.0
    assert linear_spring_force(2.0, -1.0, K=3.0, gamma=0.5) == 5.5


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [(dict(K=-1.0, n=1.5), "K must be positive"), (dict(K=1.0, n=0.9), "n must lie in"),
     (dict(K=1.0, n=1.5, gamma=-1.0), "gamma must be non-negative")],
)  # fmt: skip
def test_power_law_force_validates(kwargs, message):
    with pytest.raises(ValueError, match=message):
        power_law_force(1.0, **kwargs)


def test_shapes_that_do_not_broadcast_are_named():
    with pytest.raises(ValueError, match=r"do not broadcast together: delta \(3,\), K \(2,\)"):
        power_law_force([1.0, 2.0, 3.0], K=[1.0, 2.0], n=1.5)
    with pytest.raises(ValueError, match=r"delta \(3,\), delta_rate \(2,\)"):
        linear_spring_force([1.0, 2.0, 3.0], [0.0, 1.0], K=1.0)


@settings(max_examples=50, deadline=None)
@given(delta=st.floats(-1e-3, 1e-3), rate=st.floats(-10.0, 10.0), n=st.floats(1.0, 2.0), gamma=st.floats(0.0, 100.0))
def test_contact_never_pushes(delta, rate, n, gamma):
    assert power_law_force(delta, rate, K=1e7, n=n, gamma=gamma) >= 0.0


def paper_power_law(x, u, K, n, gamma, m, m_g, anchored):
    """Eq. (7) written as printed, site by site, in the paper's compression form.

    The paper's displacement is minus ours (its axis points towards the impact), so its
    F(u_{i-1} - u_i) is evaluated at U_{i-1} - U_i with U = -x.
    """
    U, dU = -x, -u
    N = len(x)

    def bracket(d, dd):  # [F(d) + gamma dd]_+, F = K d^n for d > 0 (open contact: no force)
        return max(K * d**n + gamma * dd, 0.0) if d > 0 else 0.0

    acc = np.empty(N)
    for i in range(N):
        below = bracket(U[i - 1] - U[i], dU[i - 1] - dU[i]) if i > 0 else 0.0
        if i < N - 1:
            above = bracket(U[i] - U[i + 1], dU[i] - dU[i + 1])
        else:  # the support: a contact with a site that does not move
            above = bracket(U[i], dU[i]) if anchored else 0.0
        acc[i] = (below - above) / m
    return -acc - G * m_g / m  # back to our axis, gravity pulling towards the impact


def paper_dual_spring(x, u, K_c, K_b, gamma_c, gamma_b, m, m_g, anchored):
    """Eqs. (5)-(6) written as printed for cells (u_i, w_i), in the paper's sign.

    Mapping (module docstring of ringchain.numerics.layouts.chain): ring j = (w_{j-1}, u_j), so our
    site 2j is w_{j-1} and site 2j+1 is u_j; w_{N-1} is the fixed support (if anchored).
    """
    N = len(x) // 2
    U, dU = -x, -u  # the paper's axis points towards the impact
    uu, du = U[1::2], dU[1::2]  # u_0 .. u_{N-1}
    w = np.concatenate([U[2::2], [0.0]])  # w_0 .. w_{N-2}, and w_{N-1} = support (at rest)
    dw = np.concatenate([dU[2::2], [0.0]])
    w_m1, dw_m1 = U[0], dU[0]  # w_{-1}: lower half of ring 0

    def contact(d, dd):
        return max(K_c * d**1.5 + gamma_c * dd, 0.0) if d > 0 else 0.0

    def bending(d, dd):
        return K_b * d + gamma_b * dd

    acc_u, acc_w = np.empty(N), np.empty(N)
    for i in range(N):
        wp, dwp = (w[i - 1], dw[i - 1]) if i > 0 else (w_m1, dw_m1)
        f_c = contact(uu[i] - w[i], du[i] - dw[i]) if (i < N - 1 or anchored) else 0.0
        acc_u[i] = (bending(wp - uu[i], dwp - du[i]) - f_c) / (m / 2)
        if i < N - 1:
            acc_w[i] = (f_c - bending(w[i] - uu[i + 1], dw[i] - du[i + 1])) / (m / 2)
    # w_{-1} (site 0) only has the bending spring of ring 0 above it.
    acc_wm1 = -bending(w_m1 - uu[0], dw_m1 - du[0]) / (m / 2)
    ours = np.empty(2 * N)
    ours[0] = acc_wm1
    ours[1::2] = acc_u
    ours[2::2] = acc_w[: N - 1]
    return -ours - G * m_g / m


@pytest.mark.parametrize("support", ["fixed", "free"])
@pytest.mark.parametrize("gamma", [0.0, 0.7])
def test_power_law_lattice_is_the_papers_equation(support, gamma):
    rng = np.random.default_rng(1)
    chain = Chain.power_law(7, K=2e6, n=1.2, m=0.01, a=0.04, gamma=gamma, m_gravity=0.03, support=support)
    x = rng.normal(0, 1e-5, 7)
    u = rng.normal(0, 0.5, 7)
    expected = paper_power_law(x, u, 2e6, 1.2, gamma, 0.01, 0.03, support == "fixed")
    # Same arithmetic in a different order: rounding only.
    np.testing.assert_allclose(chain.network().accelerations(x, u, g=G), expected, rtol=1e-11, atol=1e-9)


@pytest.mark.parametrize("support", ["fixed", "free"])
@pytest.mark.parametrize("gammas", [(0.0, 0.0), (0.3, 0.9)])
def test_dual_spring_lattice_is_the_papers_equation(support, gammas):
    rng = np.random.default_rng(2)
    N, K_c, K_b, m, m_g = 6, 7.5e9, 3.3e6, 0.008, 0.022
    chain = Chain.dual_spring(N, K_c, K_b, m, 0.04, *gammas, m_gravity=m_g, support=support)
    x = rng.normal(0, 1e-6, 2 * N)
    u = rng.normal(0, 0.5, 2 * N)
    expected = paper_dual_spring(x, u, K_c, K_b, *gammas, m, m_g, support == "fixed")
    np.testing.assert_allclose(chain.network().accelerations(x, u, g=G), expected, rtol=1e-11, atol=1e-6)


@pytest.mark.parametrize(
    "chain",
    [
        Chain.dual_spring(5, 7.5e9, 3.3e6, 0.008, 0.04, gamma_c=0.2),  # damped: general path
        # Eight sites, undamped (the fast path): a 64-byte row stride, where NumPy 2.4.6's
        # np.negative with a strided out= gave wrong values for every run after the first.
        Chain.dual_spring(4, 7.5e9, 3.3e6, 0.008, 0.04),
        Chain.power_law(8, 1e9, 1.5, 0.01, 0.02),
        Chain.power_law(8, 1e9, 1.5, 0.01, 0.02, gamma=0.1),  # eight sites on the general path
    ],
    ids=["dual-damped-10", "dual-8", "power-8", "power-damped-8"],
)
def test_batched_accelerations_equal_one_by_one(chain):
    rng = np.random.default_rng(3)
    lat = chain.network()
    x = rng.normal(0, 1e-6, (4, lat.n_sites))
    u = rng.normal(0, 0.3, (4, lat.n_sites))
    batch = lat.accelerations(x, u)
    for k in range(4):
        np.testing.assert_array_equal(batch[k], lat.accelerations(x[k], u[k]))  # same operations: exact


def test_internal_forces_cancel_in_a_free_chain():
    # Newton's third law: without gravity and support, sum of m a vanishes.
    rng = np.random.default_rng(4)
    lat = Chain.dual_spring(8, 7.5e9, 3.3e6, 0.008, 0.04, 0.3, 0.9, support="free").network()
    x, u = rng.normal(0, 1e-6, 16), rng.normal(0, 0.3, 16)
    ma = lat.mass * lat.accelerations(x, u, g=0.0)
    assert abs(ma.sum()) <= 1e-12 * np.abs(ma).max()  # cancellation to rounding


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1))
def test_dashpots_only_take_energy_out(seed):
    rng = np.random.default_rng(seed)
    lat = Chain.dual_spring(
        6, 7.5e9, 3.3e6, 0.008, 0.04, gamma_c=rng.uniform(0, 5), gamma_b=rng.uniform(0, 5)
    ).network()
    e = rng.normal(0, 1e-6, (10, lat.n_links))
    e_rate = rng.normal(0, 1.0, (10, lat.n_links))
    assert np.all(lat.dissipation_rate(e, e_rate) >= 0.0)


@pytest.mark.parametrize(
    ("links", "message"),
    [
        ([(0, 3, laws.Hertz(1.0))], "link site j out of range: sites are 0..2"),
        ([(1, 1, laws.Hertz(1.0))], "a link joins two different sites"),
        ([(0, 1, "hertz")], "law must be a ringchain.numerics.laws.Law, got str"),
        ([], "a network needs at least one link"),
    ],
)
def test_network_validates_its_links(links, message):
    with pytest.raises((ValueError, TypeError), match=message):
        Network(np.ones(3), links)


def test_a_network_built_link_by_link_is_the_chains():
    # Three rings of the dual-spring chain hanging from the support: site by site, link by link.
    m, m_g, K_c, K_b = 0.008, 0.022, 7.5e9, 3.3e6
    hertz, spring = laws.Hertz(K_c), laws.LinearSpring(K_b)
    by_hand = Network(
        [m / 2] * 6,
        [(0, 1, spring), (1, 2, hertz), (2, 3, spring), (3, 4, hertz), (4, 5, spring), (5, ANCHOR, hertz)],
        weight_mass=[m_g / 2] * 6,
    )
    chain = Chain.dual_spring(3, K_c, K_b, m, 0.04, m_gravity=m_g).network()
    rng = np.random.default_rng(5)
    x, u = rng.normal(0, 1e-6, 6), rng.normal(0, 0.3, 6)
    # The same laws on the same links: the same forces, whatever the grouping (exact).
    np.testing.assert_array_equal(by_hand.forces(by_hand.extension(x)), chain.forces(chain.extension(x)))
    np.testing.assert_allclose(by_hand.accelerations(x, u, G), chain.accelerations(x, u, G), rtol=1e-14)


def test_energy_of_a_stack_at_one_time_and_over_a_record_is_each_members():
    # The engine's energy watch passes a stack's states at one time, shape (B, n); a record has
    # shape (B, T, n).  Both were read with the stacked masses broadcast against the wrong axis.
    chains = [Chain.power_law(4, K=K, n=1.5, m=m, a=0.04) for K, m in ((1e6, 0.01), (2e6, 0.03))]
    stack = Network.stack([c.network() for c in chains])
    rng = np.random.default_rng(1)
    x, u = rng.normal(0, 1e-5, (2, 3, 4)), rng.normal(0, 0.1, (2, 3, 4))
    for b, chain in enumerate(chains):
        alone = chain.network().energy(x[b], u[b], np.zeros(4), 9.81, 0.0)
        at_once = stack.energy(x[:, 1], u[:, 1], np.zeros((2, 4)), 9.81, 0.0)
        over = stack.energy(x, u, np.zeros((2, 1, 4)), 9.81, 0.0)
        # The same sums in the same order: equal to rounding.
        np.testing.assert_allclose(at_once.total[b], alone.total[1], rtol=1e-12)
        np.testing.assert_allclose(over.total[b], alone.total, rtol=1e-12)
        np.testing.assert_allclose(over.kinetic[b], alone.kinetic, rtol=1e-12)
