"""Chains that change along their length: per-ring and per-contact parameters, integration, energy."""

import numpy as np
import pytest
from ringchain.numerics import Chain, initial_state, simulate, simulate_batch
from ringchain.numerics.models import STANDARD_GRAVITY as G

RNG_SEED = 13


def _power_law(n_rings=8, support="fixed", **over):
    rng = np.random.default_rng(RNG_SEED)
    contacts = n_rings - 1 + (support == "fixed")
    args = dict(
        K=4.9e6 * rng.uniform(0.5, 2.0, contacts), n=rng.uniform(1.05, 1.6, contacts),
        m=8.2e-3 * rng.uniform(0.5, 2.0, n_rings), a=0.04 * rng.uniform(0.8, 1.2, n_rings - 1),
    ) | over  # fmt: skip
    return Chain.power_law(n_rings, support=support, **args)


def _dual_spring(n_rings=8, support="fixed", **over):
    rng = np.random.default_rng(RNG_SEED + 1)
    contacts = n_rings - 1 + (support == "fixed")
    args = dict(
        K_c=7.5e9 * rng.uniform(0.5, 2.0, contacts), K_b=3.3e6 * rng.uniform(0.5, 2.0, n_rings),
        m=8.2e-3 * rng.uniform(0.5, 2.0, n_rings), a=0.04, m_gravity=2.2e-2 * rng.uniform(0.5, 2.0, n_rings),
    ) | over  # fmt: skip
    return Chain.dual_spring(n_rings, support=support, **args)


def test_arrays_of_one_value_are_the_uniform_chain():
    uniform = Chain.dual_spring(5, K_c=7.5e9, K_b=3.3e6, m=8.2e-3, a=0.04)
    arrays = Chain.dual_spring(5, K_c=np.full(5, 7.5e9), K_b=[3.3e6] * 5, m=np.full(5, 8.2e-3), a=np.full(4, 0.04))
    assert arrays == uniform and hash(arrays) == hash(uniform) and arrays.uniform
    assert isinstance(arrays.K, float)  # stored as the number: the same code and rounding as the scalar chain
    varied = Chain.dual_spring(5, K_c=[7.5e9] * 4 + [8e9], K_b=3.3e6, m=8.2e-3, a=0.04)
    assert varied != uniform and not varied.uniform
    assert varied.profile("K").tolist() == [7.5e9] * 4 + [8e9]


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (dict(K=np.ones(3)), r"K must be one number or 5 values \(one per contact\), got shape \(3,\)"),
        (dict(m=np.ones(4)), r"m must be one number or 5 values \(one per ring\)"),
        (dict(a=np.ones(5)), r"a must be one number or 4 values \(one per pair of neighbouring rings\)"),
        (dict(n=[1.2, 1.2, 0.9, 1.2, 1.2]), r"n must lie in \[1, inf\)"),
        (dict(K=[1.0, 1.0, -1.0, 1.0, 1.0]), "K must be positive"),
        (dict(gamma=np.ones((5, 1))), r"gamma must be one number or 5 values"),
    ],
)
def test_per_contact_and_per_ring_arrays_are_validated(kwargs, message):
    args = dict(n_rings=5, K=2e6, n=1.2, m=0.01, a=0.04) | kwargs
    with pytest.raises(ValueError, match=message):
        Chain.power_law(**args)


def test_a_free_chain_has_one_contact_less():
    chain = _power_law(support="free")
    assert chain.n_contacts == 7 and chain.lattice.n_bonds == 7
    np.testing.assert_array_equal(chain.lattice.K_contact, chain.K)
    np.testing.assert_array_equal(chain.lattice.n, chain.n)


def test_the_lattice_places_each_parameter_on_its_bond_and_site():
    chain = _dual_spring(4)
    lat = chain.lattice
    np.testing.assert_array_equal(lat.K_contact[1::2], chain.K)
    np.testing.assert_array_equal(lat.K_spring[0::2], chain.K_b)
    np.testing.assert_array_equal(lat.mass, np.repeat(chain.m / 2, 2))
    np.testing.assert_array_equal(lat.weight_mass, np.repeat(chain.m_gravity / 2, 2))


@pytest.mark.parametrize("build", [_power_law, _dual_spring])
def test_hanging_equilibrium_of_a_varying_chain_is_at_rest(build):
    chain = build()
    x, _ = initial_state(chain)
    a = chain.lattice.accelerations(x[0], np.zeros(chain.n_sites), G)
    # Static extensions invert each bond's own law exactly; the residual accelerations are
    # rounding of forces ~ total weight (~1 N) over masses of grams: 1e-13 relative of g.
    assert np.abs(a).max() < 1e-9 * G


@pytest.mark.parametrize("build", [_power_law, _dual_spring])
def test_fast_path_of_a_varying_chain_is_newtons_law(build):
    """The undamped stepper (per-bond coefficients, per-site masses) against the plain sum of bond forces."""
    chain = build()
    lat = chain.lattice
    x = np.random.default_rng(RNG_SEED).normal(scale=1e-6, size=(3, chain.n_sites))
    f = lat.bond_forces(lat.extension(x))
    below = np.pad(f, ((0, 0), (1, 0)))[:, : lat.n_sites]
    expected = (f[:, : lat.n_sites] - below - lat.weight_mass * G) / lat.mass
    # Same operations in another order: rounding, relative 1e-15 of the largest acceleration.
    np.testing.assert_allclose(lat.accelerations(x, None, G), expected, rtol=0, atol=1e-13 * np.abs(expected).max())


CASES = {
    "power-law: K, n, m, a per ring/contact": lambda: _power_law(),
    "power-law free end": lambda: _power_law(support="free"),
    "dual-spring: K_c, K_b, m, m_gravity": lambda: _dual_spring(),
    "dual-spring free end": lambda: _dual_spring(support="free"),
    "alternating masses only": lambda: Chain.power_law(8, K=4.9e6, n=1.11, m=[8e-3, 2e-3] * 4, a=0.04),
    "stiffness step only": lambda: Chain.dual_spring(8, K_c=[7.5e9] * 4 + [2e9] * 4, K_b=3.3e6, m=8e-3, a=0.04),
}


@pytest.mark.parametrize("method", ["odeint", "verlet"])
@pytest.mark.parametrize("case", list(CASES))
def test_energy_is_conserved_without_dashpots_on_every_kind_of_varying_chain(case, method):
    chain = CASES[case]()
    gravity = chain.support == "fixed"
    sim = simulate(chain, 5e-4, impact_velocity=0.5, gravity=gravity, method=method, n_samples=201)
    energy = sim.energy()
    assert np.all(energy.dissipated == 0.0)
    drift = np.abs(energy.total - energy.total[0]).max() / energy.kinetic[0]
    # As for the uniform chain (tests/numerics/test_solve.py): LSODA at rtol 1e-9 over a short run
    # (measured ~1e-9); Verlet's shadow energy at 60 steps per period, O((omega dt)^2) ~ 1e-3.
    assert drift < (1e-3 if method == "verlet" else 1e-6)


def test_dashpots_per_contact_and_per_ring_only_remove_energy():
    rng = np.random.default_rng(RNG_SEED)
    chain = _dual_spring(6, gamma_c=rng.uniform(0, 4, 6), gamma_b=rng.uniform(0, 4, 6))
    batch = simulate_batch(chain, 5e-4, drop_heights=[0.02, 0.05], n_samples=201)
    energy = batch.energy()
    assert np.all(np.diff(energy.dissipated, axis=-1) >= 0) and energy.dissipated[:, -1].min() > 0
    # total (dissipated included) is conserved to the integration error (rtol 1e-9 scales; measured ~1e-9).
    drift = np.abs(energy.total - energy.total[..., :1]).max(axis=-1) / energy.kinetic[:, 0]
    assert drift.max() < 1e-6


def test_odeint_and_verlet_agree_on_a_varying_chain():
    chain = _power_law()
    a = simulate(chain, 3e-4, drop_height=0.05, n_samples=61, rtol=1e-11)
    b = simulate(chain, 3e-4, drop_height=0.05, n_samples=61, method="verlet", steps_per_period=400)
    # Verlet at 400 steps per period: second-order error ~ (2 pi/400)^2 ~ 2.5e-4 of the force.
    np.testing.assert_allclose(b.sensor_force, a.sensor_force, rtol=0, atol=1e-3 * np.abs(a.sensor_force).max())


def test_wave_speed_of_a_varying_chain_uses_the_real_distance():
    chain = _power_law(12)
    sim = simulate(chain, 2e-3, drop_height=0.05, n_samples=4001)
    distance = float(np.sum(chain.a[1:5]))
    assert sim.wave_speed(1, 5) == pytest.approx(distance / sim.time_of_flight(1, 5), rel=1e-12)
