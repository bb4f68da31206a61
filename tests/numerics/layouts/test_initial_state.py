"""Integrating from any initial state: ``simulate(..., initial=(x0, u0))`` and ``simulate_batch``."""

import numpy as np
import pytest
from ringchain.numerics import Chain, initial_state, paper_chain, simulate, simulate_batch

PAPER = paper_chain("dual-spring")


def test_the_impact_state_given_as_initial_reproduces_the_impact_run():
    impact = simulate(PAPER, 5e-4, drop_height=0.05, n_samples=201)
    x0, u0 = initial_state(PAPER, drop_height=0.05)
    given = simulate(PAPER, 5e-4, initial=(x0[0], u0[0]), n_samples=201)
    # The same state, the same scales and the same integrator: the same numbers.
    np.testing.assert_array_equal(given.x, impact.x)
    np.testing.assert_array_equal(given.u, impact.u)
    assert given.drop_height is None and given.impact_velocity == impact.impact_velocity


@pytest.mark.parametrize("method", ["odeint", "verlet"])
def test_the_hanging_equilibrium_stays_at_rest(method):
    chain = paper_chain("power-law")
    x0 = chain.displacement_from_extension(chain.static_extension())
    sim = simulate(chain, 1e-3, initial=(x0, np.zeros(chain.n_sites)), n_samples=11, method=method)
    # The equilibrium is solved to rounding; the motion from the residual force stays at that level.
    scale = np.abs(x0).max()
    assert np.abs(sim.x - x0).max() < 1e-9 * scale
    assert np.abs(sim.u).max() < 1e-9 * scale / 1e-3


def test_a_pre_stretched_free_chain_without_gravity_unloads_from_its_free_end():
    """Uniform tension, fixed top, free bottom, no gravity: the bottom ring is pulled up, the middle waits."""
    chain = Chain.power_law(60, K=1e9, n=1.5, m=0.01, a=0.04)
    F_0 = 2.0
    x0 = chain.displacement_from_extension(np.full(chain.network().n_links, (F_0 / chain.K) ** (1 / chain.n)))
    u0 = np.zeros(chain.n_sites)
    speed = 0.04 * np.sqrt(1.5 * chain.K ** (1 / 1.5) * F_0 ** (1 / 3) / chain.m)  # linear sound speed at F_0
    t_end = 15 * chain.a / speed  # the unloading reaches about ring 15
    sim = simulate(chain, t_end, initial=(x0, u0), gravity=False, n_samples=51)
    assert sim.u[-1, 0] > 0  # the free end moves up, into the chain
    # Ahead of the front the lattice only feels a precursor that falls off faster than exponentially
    # (2e-8 of F_0 at 10 rings ahead, measured); 20 rings ahead nothing has moved to the solver's tolerance.
    np.testing.assert_allclose(sim.contact_force[:, 35:], F_0, rtol=1e-9)


def test_batch_rows_and_a_shared_row():
    chain = Chain.power_law(8, K=1e9, n=1.5, m=0.01, a=0.04, support="free")
    x0 = np.zeros(chain.n_sites)
    u0 = np.zeros((2, chain.n_sites))
    u0[0, 0], u0[1, 0] = -0.5, -1.0
    batch = simulate_batch(chain, 2e-4, initial=(x0, u0), gravity=False, n_samples=101)
    separate = simulate_batch(chain, 2e-4, impact_velocities=[0.5, 1.0], gravity=False, n_samples=101)
    assert len(batch) == 2
    np.testing.assert_allclose(batch.contact_force, separate.contact_force, rtol=1e-6, atol=1e-9)  # tolerances


@pytest.mark.parametrize(
    ("initial", "error", "message"),
    [
        ((np.zeros(40), np.zeros(39)), ValueError, "shape \\(n_sites,\\) or \\(B, n_sites\\) with n_sites = 40"),
        ((np.zeros((2, 3, 40)), np.zeros(40)), ValueError, "shape"),
        ((np.zeros((2, 40)), np.zeros((3, 40))), ValueError, "different numbers of runs: 2 and 3"),
        ((np.full(40, np.nan), np.zeros(40)), ValueError, "must be finite"),
        (np.zeros(40), TypeError, "pair \\(x0, u0\\)"),
    ],
)
def test_initial_is_validated(initial, error, message):
    with pytest.raises(error, match=message):
        simulate_batch(PAPER, 1e-4, initial=initial)


def test_initial_excludes_an_impact_and_simulate_takes_one_state():
    state = (np.zeros(PAPER.n_sites), np.zeros(PAPER.n_sites))
    with pytest.raises(ValueError, match="not both"):
        simulate(PAPER, 1e-4, initial=state, drop_height=0.01)
    with pytest.raises(ValueError, match="use simulate_batch"):
        simulate(PAPER, 1e-4, initial=(np.zeros((2, PAPER.n_sites)), np.zeros(PAPER.n_sites)))
