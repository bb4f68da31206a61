"""Chains that change along their length: per-ring and per-contact parameters, integration, energy."""

import itertools

import numpy as np
import pytest
from ringchain.numerics import STANDARD_GRAVITY as G
from ringchain.numerics import Chain, Network, Simulation, initial_state, laws, simulate, simulate_batch
from ringchain.numerics.jobs.junction import junction_pulse
from ringchain.theory import Ring, fit_power_law, hertz_stiffness_pair

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
    net = chain.network()
    assert chain.n_contacts == 7 and net.n_links == 7
    ((law, index),) = net.groups
    np.testing.assert_array_equal(index, np.arange(7))
    np.testing.assert_array_equal(law.K, chain.K)
    np.testing.assert_array_equal(law.n, chain.n)


def test_the_network_places_each_parameter_on_its_link_and_site():
    chain = _dual_spring(4)
    net = chain.network()
    laws_by_class = {type(law): (law, index) for law, index in net.groups}
    contact, contacts = laws_by_class[laws.PowerLaw]
    spring, springs = laws_by_class[laws.LinearSpring]
    np.testing.assert_array_equal(contacts, [*chain.contact_links.tolist(), chain.support_link])
    np.testing.assert_array_equal(contact.K, chain.K)
    np.testing.assert_array_equal(springs, chain.bending_links)
    np.testing.assert_array_equal(spring.K, chain.K_b)
    np.testing.assert_array_equal(net.mass, np.repeat(chain.m / 2, 2))
    np.testing.assert_array_equal(net.weight_mass, np.repeat(chain.m_gravity / 2, 2))


@pytest.mark.parametrize("build", [_power_law, _dual_spring])
def test_hanging_equilibrium_of_a_varying_chain_is_at_rest(build):
    chain = build()
    x, _ = initial_state(chain)
    a = chain.network().accelerations(x[0], np.zeros(chain.n_sites), G)
    # Static extensions invert each bond's own law exactly; the residual accelerations are
    # rounding of forces ~ total weight (~1 N) over masses of grams: 1e-13 relative of g.
    assert np.abs(a).max() < 1e-9 * G


@pytest.mark.parametrize("build", [_power_law, _dual_spring])
def test_fast_path_of_a_varying_chain_is_newtons_law(build):
    """The undamped stepper (per-bond coefficients, per-site masses) against the plain sum of bond forces."""
    chain = build()
    lat = chain.network()
    x = np.random.default_rng(RNG_SEED).normal(scale=1e-6, size=(3, chain.n_sites))
    f = lat.forces(lat.extension(x))
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
    # As for the uniform chain (tests/numerics/engine/test_integrate.py): LSODA at rtol 1e-9 over a short run
    # (measured 2e-9 to 5e-8); Verlet's shadow energy at 60 steps per period, O((omega dt)^2) ~ 1e-3
    # (measured 1.5e-5 to 3.6e-4).
    assert drift < (1e-3 if method == "verlet" else 1e-6)


@pytest.mark.parametrize("model", ["dual-spring", "power-law"])
def test_dashpots_per_contact_and_per_ring_only_remove_energy(model):
    rng = np.random.default_rng(RNG_SEED)
    if model == "dual-spring":
        chain = _dual_spring(6, gamma_c=rng.uniform(0, 4, 6), gamma_b=rng.uniform(0, 4, 6))
    else:  # per-contact exponents through the general (damped) path
        chain = _power_law(6, gamma=rng.uniform(0, 4, 6))
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


# -- chains of given rings ---------------------------------------------------------------------------

NINE, SIX = Ring.from_aspect_ratio(9.0), Ring.from_aspect_ratio(6.0)


@pytest.mark.parametrize("support", ["fixed", "free"])
@pytest.mark.parametrize("model", ["dual-spring", "power-law"])
def test_a_uniform_chain_built_ring_by_ring_is_exactly_the_uniform_chain(model, support):
    built = Chain.from_rings([NINE] * 6, model=model, m_eff_ratio=0.37, support=support)
    assert built == Chain.from_ring(NINE, 6, model, m_eff_ratio=0.37, support=support)
    assert built.uniform


def test_each_contact_from_the_two_rings_it_joins():
    chain = Chain.from_rings([NINE, NINE, SIX, SIX], angles=[np.pi / 2, 1.2, np.pi / 2, 1.3])
    steel = (NINE.material.E, NINE.material.nu)
    assert chain.K[1] == hertz_stiffness_pair(NINE.R, NINE.r, *steel, SIX.R, SIX.r, *steel, 1.2)
    assert chain.K[0] == NINE.K_c and chain.K[2] == SIX.K_c
    assert chain.K[3] == Ring.from_aspect_ratio(6.0, angle=1.3).K_c  # the support: the top ring's like
    assert chain.K_b.tolist() == [NINE.K_b, NINE.K_b, SIX.K_b, SIX.K_b]
    # Centre distances: 2(R - r) between equal rings, (R1 - r1) + (R2 - r2) at the change.
    np.testing.assert_array_equal(chain.a, [NINE.spacing, (NINE.R - NINE.r) + (SIX.R - SIX.r), SIX.spacing])
    assert chain.m_gravity.tolist() == [NINE.mass, NINE.mass, SIX.mass, SIX.mass]


def test_power_law_contacts_fit_the_series_law_of_contact_and_ring_below():
    chain = Chain.from_rings([NINE, SIX, SIX], model="power-law", support="free")
    steel = (NINE.material.E, NINE.material.nu)
    K, n = fit_power_law(K_c=hertz_stiffness_pair(NINE.R, NINE.r, *steel, SIX.R, SIX.r, *steel), K_b=NINE.K_b)
    assert (chain.K[0], chain.n[0]) == (float(K), float(n))
    assert (chain.K[1], chain.n[1]) == SIX.power_law()


def test_power_law_rings_sit_where_the_series_law_puts_them():
    """Issue 24, item 16: a second check of which ring's bending goes with a power-law contact (the test above
    alone caught a change of it).  Pulled by a tension T (no gravity), ring k of the power-law chain of
    alternating rings (K_b 3.3e6 and 1.05e7 N/m) sits, through the network's own laws, where the series law
    (Eq. 3) of every contact below it and the ring below each contact puts it; with the ring above instead, ring
    1 would move by 52-129 %."""
    from ringchain.theory import series_displacement

    rings = [NINE, SIX] * 3
    chain = Chain.from_rings(rings, model="power-law", support="free")
    steel = (NINE.material.E, NINE.material.nu)
    below = rings[:-1]  # contact c joins ring c (below) and ring c + 1
    K_c = [float(hertz_stiffness_pair(a.R, a.r, *steel, b.R, b.r, *steel))
           for a, b in zip(below, rings[1:], strict=True)]  # fmt: skip
    for T in (1.0, 3.0, 10.0, 30.0, 100.0):  # N: the window of Eq. (4)'s fit
        position = np.cumsum(chain.network().extension_at(T))
        series = np.cumsum([float(series_displacement(T, K_c=k, K_b=ring.K_b))
                            for k, ring in zip(K_c, below, strict=True)])  # fmt: skip
        # Eq. (4)'s power law misses the series law by up to 4.3 % at the window's ends (measured).
        np.testing.assert_allclose(position, series, rtol=0.06)


@pytest.mark.parametrize("profile", ["linear", "geometric"])
def test_graded_chains_space_their_values_as_asked(profile):
    chain = Chain.graded(NINE, 6, aspect_ratio=(9.0, 5.0), profile=profile)
    R = (chain.m_gravity / NINE.mass) * NINE.R  # ring mass grows with R at fixed r (Pappus)
    expected = np.linspace(9.0, 5.0, 6) if profile == "linear" else np.geomspace(9.0, 5.0, 6)
    np.testing.assert_allclose(R / NINE.r, expected, rtol=1e-14)  # rounding of mass ratios
    angled = Chain.graded(NINE, 6, angle=(np.pi / 2, 1.0), profile=profile, support="free")
    assert angled.K[0] == NINE.K_c and np.all(np.diff(angled.K) > 0)  # flatter contacts are stiffer (Gamma > 1)


def test_alternating_and_joined_chains():
    alternating = Chain.alternating(NINE, SIX, 5, angles=[np.pi / 2, 1.2] * 2 + [np.pi / 2])
    assert alternating.K_b.tolist() == [NINE.K_b, SIX.K_b] * 2 + [NINE.K_b]
    a, b = Chain.from_ring(NINE, 4), Chain.from_ring(SIX, 3, support="free")
    joined = Chain.joined(a, b)
    assert joined.n_rings == 7 and joined.support == "free" and joined.n_contacts == 6
    assert joined.K.tolist() == [NINE.K_c] * 4 + [SIX.K_c] * 2  # a's support contact is the junction
    assert joined.a.tolist() == [NINE.spacing] * 3 + [0.5 * (NINE.spacing + SIX.spacing)] + [SIX.spacing] * 2
    custom = Chain.joined(a, b, junction={"K": 1e9, "a": 0.03})
    assert custom.K[3] == 1e9 and custom.a[3] == 0.03
    with pytest.raises(ValueError, match="one model"):
        Chain.joined(a, Chain.from_ring(SIX, 3, "power-law"))
    with pytest.raises(ValueError, match=r"junction takes K, n, gamma and a, got \['K_b'\]"):
        Chain.joined(a, b, junction={"K_b": 1.0})


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: Chain.from_rings([NINE]), "at least two rings"),
        (lambda: Chain.from_rings([NINE, "ring"]), r"rings\[1\] must be a ringchain.theory.Ring"),
        (lambda: Chain.from_rings([NINE, Ring.from_aspect_ratio(2.5)]), r"rings\[1\]: R/r = 2.5 is below 3"),
        (lambda: Chain.from_rings([NINE, NINE], angles=[1.0, 1.2, 1.3]), r"angles must be one angle or 2"),
        (lambda: Chain.from_rings([NINE, NINE], angles=0.5), r"contact of rings 0 and 1: angle 0.5 rad"),
        (lambda: Chain.graded(NINE, 4), "give one of aspect_ratio"),
        (lambda: Chain.graded(NINE, 4, aspect_ratio=(9, 5, 3)), r"aspect_ratio must be two values"),
        (lambda: Chain.graded(NINE, 4, angle=(1.0, 1.2), profile="cubic"), "profile must be one of"),
    ],
)
def test_ring_by_ring_constructors_name_the_bad_input(call, message):
    with pytest.raises((ValueError, TypeError), match=message):
        call()


# -- the junction of two chains: small amplitudes against the impedance theory -----------------------


@pytest.mark.parametrize("model", ["power-law", "dual-spring"])
@pytest.mark.parametrize(("stiffness", "mass"), [(4.0, 1.0), (0.25, 1.0), (1.0, 3.0)])
def test_small_pulse_at_a_junction_against_the_impedance_theory(model, stiffness, mass):
    K1 = 4.9e6 if model == "power-law" else 7.5e9
    reading = junction_pulse(model, K=(K1, stiffness * K1), m=(8e-3, mass * 8e-3))
    R, T, R_theory, T_theory = reading.R, reading.T, reading.R_theory, reading.T_theory
    assert abs(R_theory) > 0.04  # a junction that reflects
    # Long-wave theory against a pulse 4 rings wide (dispersion ~ (a/w)^2/24 ~ 0.3 %) of 2 % of the
    # static force (the tangent stiffness changes by (n - 1)/n of that, ~0.7 %, Z by half): 1 % of
    # the incident force covers both (measured up to 0.72 %, R of the power-law chain with m2 = 3 m1).
    assert R == pytest.approx(R_theory, abs=0.01)
    assert T == pytest.approx(T_theory, abs=0.01)


def test_junction_pulse_takes_the_chains_by_keyword():
    # Issue 24, item 7: K and m are both pairs of positive numbers (a swap would pass silently), and the
    # static force is spelled F_0 as in the theory.
    with pytest.raises(TypeError):
        junction_pulse("power-law", (4.9e6, 4.9e6), (8e-3, 8e-3))
    with pytest.raises(TypeError):
        junction_pulse("power-law", K=(4.9e6, 4.9e6), m=(8e-3, 8e-3), F0=5.0)


# -- several chains of one layout as one network (Network.stack) --------------------------------------

STACKS = {  # three chains of one layout each: varying, uniform, varying otherwise
    "dual-spring, undamped (fast path)": lambda: [
        _dual_spring(6), Chain.dual_spring(6, K_c=7.5e9, K_b=3.3e6, m=8.2e-3, a=0.04), _dual_spring(6, m=5e-3)],
    "power-law, damped (general path)": lambda: [
        _power_law(6), Chain.power_law(6, K=4.9e6, n=1.11, m=8.2e-3, a=0.04, gamma=2.0),
        _power_law(6, gamma=np.linspace(0.0, 3.0, 6))],
}  # fmt: skip


def _stacked_drops(chains, heights, t, rtol):
    """Sensor forces of one drop per chain, the chains' networks stacked and integrated as one batch."""
    states = [initial_state(chain, drop_height=h) for chain, h in zip(chains, heights, strict=True)]
    x0, u0 = np.concatenate([x for x, _ in states]), np.concatenate([u for _, u in states])
    stack = Network.stack([chain.network() for chain in chains])
    batch = simulate_batch(stack, t[-1], initial=(x0, u0), t_eval=t, rtol=rtol)
    return [
        Simulation(chain=chain, t=t, x=batch.x[b], u=batch.u[b], dissipated=batch.dissipated[b], g=G,
                   impact_velocity=float(-u0[b][0]), drop_height=h).sensor_force
        for b, (chain, h) in enumerate(zip(chains, heights, strict=True))
    ]  # fmt: skip


@pytest.mark.parametrize("case", list(STACKS))
def test_a_stack_of_lattices_moves_each_chain_by_its_own_law(case):
    chains = STACKS[case]()
    stack = Network.stack([chain.network() for chain in chains])
    assert stack.batch_shape == (3,) and stack.n_sites == chains[0].n_sites and stack.damped == ("general path" in case)
    rng = np.random.default_rng(RNG_SEED)
    x = rng.normal(0.0, 1e-6, (3, stack.n_sites))
    u = rng.normal(0.0, 0.1, x.shape)
    each = np.array([chain.network().accelerations(x[b], u[b]) for b, chain in enumerate(chains)])
    # Rounding only: where a row differs from the others the stack multiplies K delta^n by 1/m,
    # a uniform chain alone by K/m (measured 2.4e-16 of the largest acceleration).
    np.testing.assert_allclose(stack.accelerations(x, u), each, rtol=0, atol=1e-14 * np.abs(each).max())


@pytest.mark.parametrize("case", list(STACKS))
def test_a_stack_of_different_chains_equals_their_separate_runs(case):
    chains, heights = STACKS[case](), [0.02, 0.05, 0.01]
    t = np.linspace(0.0, 5e-4, 201)
    stacked = _stacked_drops(chains, heights, t, rtol=1e-9)
    for chain, h, forces in zip(chains, heights, stacked, strict=True):
        alone = simulate(chain, t[-1], drop_height=h, t_eval=t, rtol=1e-9).sensor_force
        # Integrator tolerance: the batch shares its steps, so each run's error differs from its
        # separate run's, each ~rtol times the scales; at rtol 1e-9 the two differ by at most 2.2e-7
        # of the peak force (measured, as is each from a run at rtol 1e-12: up to 3.3e-7).
        np.testing.assert_allclose(forces, alone, rtol=0, atol=2e-6 * np.abs(alone).max())


def test_a_stack_of_one_uniform_chain_is_that_chains_batch_to_the_last_bit():
    chain = Chain.dual_spring(6, K_c=7.5e9, K_b=3.3e6, m=8.2e-3, a=0.04)
    heights, t = [0.02, 0.05], np.linspace(0.0, 3e-4, 61)
    stacked = _stacked_drops([chain, chain], heights, t, rtol=1e-9)
    batch = simulate_batch(chain, t[-1], drop_heights=heights, t_eval=t, rtol=1e-9).sensor_force
    # Every coefficient is one number across the stack: the same arithmetic as one chain's batch.
    assert np.array_equal(np.array(stacked), batch)


def test_stacking_names_what_does_not_fit():
    five, six = (Chain.power_law(k, K=4.9e6, n=1.11, m=8.2e-3, a=0.04) for k in (5, 6))
    with pytest.raises(ValueError, match=r"networks\[1\] has 5 sites and 5 links, networks\[0\] 6 and 6"):
        Network.stack([six.network(), five.network()])
    with pytest.raises(TypeError, match=r"networks\[0\] must be a Network, got Chain"):
        Network.stack([six])
    with pytest.raises(ValueError, match="at least one network"):
        Network.stack([])
    stack = Network.stack([six.network(), six.network()])
    with pytest.raises(ValueError, match=r"networks\[0\] is already a stack of 2"):
        Network.stack([stack])
    with pytest.raises(ValueError, match="a stack of 2 networks integrates one run each, got n_runs = 3"):
        stack.first_order_rhs(3, G)


def test_a_disordered_chains_contacts_at_spread_angles_are_each_contacts_own():
    # The contacts of different rings in one array call of hertz_stiffness_pair, against one scalar call per
    # contact: the elliptical contacts' numbers may differ in the last bit (NumPy's array loops against the scalar
    # path: measured in 6 of 12000 contacts, by 1-5e-16); 4 machine epsilons bound that.  The support's contact,
    # a ring with itself, is one scalar call as a uniform chain's is: exactly the scalar number.
    from ringchain.numerics import draw_rings

    draw = draw_rings(Ring.from_aspect_ratio(9.0), 40, {"R": 0.1, "r": 0.05, "angle": 0.1}, 11)
    rings, angles = draw.rings, draw.angles
    chain = Chain.from_rings(rings, angles)
    pairs = [*itertools.pairwise(rings), (rings[-1], rings[-1])]
    K_c = [float(hertz_stiffness_pair(b.R, b.r, b.material.E, b.material.nu, a.R, a.r, a.material.E, a.material.nu,
                                      float(angle))) for (b, a), angle in zip(pairs, angles, strict=True)]  # fmt: skip
    np.testing.assert_allclose(chain.profile("K"), K_c, rtol=4 * np.finfo(float).eps, atol=0)
    assert chain.profile("K")[-1] == K_c[-1]


@pytest.mark.parametrize("model", ["dual-spring", "power-law"])
def test_a_disordered_chains_numbers_are_each_rings_own(model):
    # Chain.from_rings evaluates the rings' K_b, the contacts' K_c and the power-law fits once for all of a chain's
    # distinct rings and contacts (arrays); each must be the number the theory gives that ring or contact alone,
    # exactly (elementwise arithmetic; at right angles the contacts' too: see the next test for other angles).
    from ringchain.numerics import draw_rings
    from ringchain.theory import bending_stiffness

    rings = draw_rings(Ring.from_aspect_ratio(9.0), 12, {"R": 0.1, "r": 0.05}, 5, model=model).rings
    assert len(set(rings)) == 12
    chain = Chain.from_rings(rings, model=model)
    pairs = [*itertools.pairwise(rings), (rings[-1], rings[-1])]  # the support: a ring like the top one
    K_c = [float(hertz_stiffness_pair(b.R, b.r, b.material.E, b.material.nu, a.R, a.r, a.material.E,
                                      a.material.nu, b.angle)) for b, a in pairs]  # fmt: skip
    K_b = [float(bending_stiffness(q.R, q.r, q.material.E, q.material.nu, thin=q.thin)) for q in rings]
    if model == "dual-spring":
        assert chain.profile("K").tolist() == K_c and chain.profile("K_b").tolist() == K_b
    else:  # each contact with the ring below it
        fits = [fit_power_law(K_c=kc, K_b=kb) for kc, kb in zip(K_c, K_b, strict=True)]
        assert chain.profile("K").tolist() == [float(K) for K, _ in fits]
        assert chain.profile("n").tolist() == [float(n) for _, n in fits]
