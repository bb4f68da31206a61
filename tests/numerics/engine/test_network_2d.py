"""The two-dimensional paths of the network engine: geometry, the general stepper, energies, the flat state.

Small networks whose answers are known without the engine: one link (its force and direction by hand), a
triangle (forces as minus the gradient of the network's own energy, momentum and angular momentum), runs that
conserve energy and momentum, the one-dimensional chain laid out in the plane, periodic images.
"""

import mpmath
import numpy as np
import pytest
from ringchain.numerics import ANCHOR, Chain, Links, Network, simulate
from ringchain.numerics.laws import LinearSpring, PowerLaw

LAW = PowerLaw(K=4.9e6, n=1.3)


def test_one_link_pulls_its_ends_together_along_the_line_between_them():
    m0, m1, a = 2e-3, 3e-3, 0.04
    net = Network([m0, m1], [(0, 1, LAW)], dim=2, positions=[[0.0, 0.0], [a, 0.0]])
    x = np.array([1e-6, -2e-6, 4e-6, 3e-6])  # site 0 (x, y), site 1 (x, y)
    dx, dy = 4e-6 - 1e-6, 3e-6 + 2e-6
    vector = np.array([a + dx, dy])
    length = np.hypot(*vector)
    e = ((2 * a + dx) * dx + dy * dy) / (length + a)  # |v| - a, without the cancellation of two lengths
    force = 4.9e6 * e**1.3
    expected = np.concatenate([force * vector / length / m0, -force * vector / length / m1])
    # The same arithmetic up to the order of operations: a few ulp of the acceleration (1e-13).
    assert np.allclose(net.accelerations(x, g=0.0), expected, rtol=1e-13, atol=0)
    # Gravity pulls along -y (the last component) on every site.
    with_gravity = net.accelerations(x, g=9.81) - expected
    assert np.allclose(with_gravity, [0.0, -9.81, 0.0, -9.81], rtol=1e-13, atol=1e-12)
    # Pushed together, an interlocked contact goes slack.
    assert np.all(net.accelerations(-x * 0 + np.array([1e-6, 0, -1e-6, 0]), g=0.0) == 0.0)


def test_extension_keeps_its_digits_for_tiny_stretches():
    """|b + w| - L0 for w of 1e-10 of the link's length: against 50-digit arithmetic."""
    rng = np.random.default_rng(7)
    positions = rng.uniform(-0.05, 0.05, size=(2, 2))
    net = Network([1e-3, 1e-3], [(0, 1, LAW)], dim=2, positions=positions)
    x = rng.normal(scale=4e-12, size=4)
    mpmath.mp.dps = 50
    P = [[mpmath.mpf(float(c)) for c in row] for row in positions]
    X = [mpmath.mpf(float(c)) for c in x]
    b = [P[1][k] - P[0][k] for k in range(2)]
    far = [P[1][k] + X[2 + k] - P[0][k] - X[k] for k in range(2)]
    exact = mpmath.sqrt(far[0] ** 2 + far[1] ** 2) - mpmath.sqrt(b[0] ** 2 + b[1] ** 2)
    # Rounding of the inputs and of a few operations on numbers of the extension's own size (1e-14): the
    # difference of two lengths would keep only eps L0/e = 1e-6 of it.
    assert np.isclose(net.extension(x)[0], float(exact), rtol=1e-14, atol=0)


def triangle(g_mass=None, law=LAW):
    positions = [[0.0, 0.0], [0.04, 0.0], [0.015, 0.035]]
    mass = [2e-3, 3e-3, 5e-3]
    return Network(mass, [(0, 1, law), (1, 2, law), (2, 0, law)], dim=2, positions=positions, weight_mass=g_mass)


def stretched_state(net, seed=1, scale=2e-5, speed=0.3):
    rng = np.random.default_rng(seed)
    return rng.normal(scale=scale, size=net.n_coords), rng.normal(scale=speed, size=net.n_coords)


def test_forces_are_minus_the_gradient_of_the_networks_energy():
    net = triangle()
    x, _ = stretched_state(net)
    force = net.accelerations(x, g=0.0) * np.repeat(net.mass, 2)
    zeros = np.zeros_like(x)

    def stored(y):
        return float(net.energy(y, zeros, zeros, 0.0, 0.0).contact)

    h = 1e-9  # central differences: error h^2 E''' ~ 1e-9 of the force here, rounding eps E/h ~ 1e-8
    gradient = np.array([(stored(x + h * d) - stored(x - h * d)) / (2 * h) for d in np.eye(x.size)])
    assert np.allclose(force, -gradient, rtol=0, atol=1e-6 * np.abs(force).max())


def test_internal_forces_carry_no_net_force_and_no_torque():
    net = triangle(g_mass=[1e-3, 2e-3, 0.0])
    x, _ = stretched_state(net, seed=3)
    F = (net.accelerations(x, g=9.81) * np.repeat(net.mass, 2)).reshape(3, 2)
    # Newton's third law: the links' forces cancel; gravity is what is left (rounding of the sums, 1e-12 N).
    assert np.allclose(F.sum(axis=0), [0.0, -9.81 * 3e-3], rtol=0, atol=1e-12 * np.abs(F).max())
    internal = (net.accelerations(x, g=0.0) * np.repeat(net.mass, 2)).reshape(3, 2)
    r = net.positions + x.reshape(3, 2)
    torque = np.sum(r[:, 0] * internal[:, 1] - r[:, 1] * internal[:, 0])
    assert abs(torque) < 1e-12 * np.abs(internal).max() * 0.05  # central forces, rounding of the sums


@pytest.mark.parametrize("method", ["odeint", "verlet"])
def test_a_free_triangle_conserves_energy_and_momentum(method):
    net = triangle()
    x0, u0 = stretched_state(net, seed=5)
    options = dict(rtol=1e-12) if method == "odeint" else dict(steps_per_period=400)
    run = simulate(net, 2e-3, initial=(x0, u0), gravity=False, method=method, n_samples=201, **options)
    energy = run.energy().total
    momentum = np.einsum("s,tsc->tc", net.mass, run.velocity)
    initial = float(energy[0])
    # odeint at rtol = 1e-12: drift ~1e-10 of the energy; Verlet, 400 steps per period: its energy error
    # oscillates with amplitude ~ (omega dt)^2/8 ~ 3e-5 of the energy.
    limit = 1e-9 if method == "odeint" else 1e-4
    assert np.max(np.abs(energy - initial)) < limit * initial
    # Momentum: the forces cancel to rounding at every step, so both conserve it to accumulated rounding: Verlet
    # ~ steps x eps = 4000 x 1e-16 (5e-13 found), odeint's few hundred steps less (6e-16 found); 1e-11.
    scale = np.sum(net.mass * np.abs(u0.reshape(3, 2)).max(axis=1))
    assert np.allclose(momentum, momentum[0], rtol=0, atol=1e-11 * scale)


def test_damped_links_only_take_energy_out_and_the_budget_closes():
    net = triangle(law=PowerLaw(K=4.9e6, n=1.3, gamma=0.5))
    x0, u0 = stretched_state(net, seed=9)
    e, rate, _ = net.geometry(x0, u0)
    assert np.all(net.dissipation_rate(e, rate) >= 0.0)
    run = simulate(net, 1e-3, initial=(x0, u0), gravity=False, rtol=1e-12, n_samples=101)
    budget = run.energy()
    assert budget.dissipated[-1] > 0.01 * budget.total[0]  # the dashpots did take energy out
    assert np.all(np.diff(budget.mechanical) <= 1e-9 * budget.total[0])  # and mechanical energy only falls
    # Total energy with the dissipated part: conserved to the solver's tolerance (1e-9 of it).
    assert np.allclose(budget.total, budget.total[0], rtol=1e-9, atol=0)


def test_a_chain_laid_out_in_the_plane_is_the_one_dimensional_chain():
    """A hanging power-law chain along y: its accelerations and its run are those of the chain's network."""
    chain = Chain.power_law(6, K=4.9e6, n=1.11, m=3e-3, a=0.04, m_gravity=8e-3)
    line = chain.network()
    y = np.arange(6) * 0.04
    positions = np.stack([np.zeros(6), y], axis=-1)
    plane = Network(line.mass, [Links(line.i, line.j, line.law_of(0), anchor=[0.0, 6 * 0.04])], dim=2,
                    positions=positions, weight_mass=line.weight_mass)  # fmt: skip
    x1, u1 = chain.impact_state(np.array([0.4]), False, True, 9.81)
    x1 = x1 + np.random.default_rng(2).normal(scale=3e-7, size=x1.shape)  # off the hanging equilibrium
    x2, u2 = np.zeros((1, 12)), np.zeros((1, 12))
    x2[:, 1::2], u2[:, 1::2] = x1, u1
    a1, a2 = line.accelerations(x1, g=9.81), plane.accelerations(x2, g=9.81)
    assert np.all(a2[:, 0::2] == 0.0)  # nothing pulls sideways
    # Extensions from (2 b.w + w.w)/(l + L0) rather than x_j - x_i, forces per unit mass computed in another
    # order: rounding of the accelerations, relative to the largest (1e-12).
    assert np.allclose(a2[:, 1::2], a1, rtol=0, atol=1e-12 * np.abs(a1).max())
    runs = [simulate(net, 5e-4, initial=(x[0], u[0]), method="verlet", dt=2e-7, n_samples=51)
            for net, x, u in ((line, x1, u1), (plane, x2, u2))]  # fmt: skip
    forces = [run.link_force for run in runs]
    # One fixed step on both: the two runs differ by the rounding above, carried through 2500 steps (1e-10).
    assert np.allclose(forces[1], forces[0], rtol=0, atol=1e-10 * forces[0].max())


def test_the_first_order_state_packs_and_unpacks_and_its_rhs_is_the_stepper():
    net = triangle()
    x, u = stretched_state(net, seed=11)
    xs, us = np.stack([x, 2 * x]), np.stack([u, -u])
    y = net.pack(xs, us)
    back_x, back_u, dissipated = net.unpack(y[:, None], 2)
    assert np.array_equal(back_x[..., 0], xs) and np.array_equal(back_u[..., 0], us) and dissipated is None
    dy = net.first_order_rhs(2, 9.81)(0.0, y)
    dx, du, _ = net.unpack(dy[:, None], 2)
    assert np.array_equal(dx[..., 0], us)
    assert np.array_equal(du[..., 0], net.accelerations(xs, g=9.81))


def test_the_jacobian_lies_within_the_stated_bands():
    rng = np.random.default_rng(4)
    positions = np.stack(np.meshgrid(np.arange(4) * 0.04, np.arange(3) * 0.04, indexing="xy"), -1).reshape(-1, 2)
    links = [(s, s + 1, LAW) for s in range(12) if s % 4 != 3] + [(s, s + 4, LAW) for s in range(8)]
    net = Network(np.full(12, 2e-3), links, dim=2, positions=positions)
    x = rng.uniform(1e-6, 2e-6, size=net.n_coords) * np.tile([1, 1], 12) + positions.ravel() * 1e-4
    y = net.pack(x[None], rng.normal(size=(1, net.n_coords)))
    rhs = net.first_order_rhs(1, 0.0)
    f0 = rhs(0.0, y)
    jacobian = np.stack([(rhs(0.0, y + 1e-10 * d) - f0) / 1e-10 for d in np.eye(y.size)], axis=1)
    lower, upper = net.bandwidth
    rows, cols = np.nonzero(jacobian)
    assert np.all(rows - cols <= lower) and np.all(cols - rows <= upper)
    assert np.max(rows - cols) == lower  # the band is tight for a grid numbered along its rows


def test_periodic_images_close_a_ring_of_sites():
    """Four sites along x, the last linked to the image of the first one period L further on."""
    a, N = 0.04, 4
    positions = np.stack([np.arange(N) * a, np.zeros(N)], axis=-1)
    links = [Links(np.arange(N - 1), np.arange(1, N), LAW), Links([N - 1], [0], LAW, shift=[N * a, 0.0])]
    net = Network(np.full(N, 1e-3), links, dim=2, positions=positions)
    assert np.allclose(net.rest_lengths, a, rtol=1e-15)
    assert net.length_scale == pytest.approx(a, rel=1e-15)
    # A uniform stretch of the period: every link, the wrapping one too, extends by the same amount.
    x = np.zeros((N, 2))
    x[:, 0] = np.arange(N) * 1e-6
    e = net.extension(x.ravel())
    assert np.allclose(e, [1e-6, 1e-6, 1e-6, -3e-6], rtol=1e-9)  # the image does not move with the stretch
    # The same ring pretensioned: rest positions at the stretched lattice, each link prestretched by e0, the
    # image one stretched period on.  At rest every link carries e0; a uniform displacement changes nothing.
    e0, stretched = 1e-6, positions * (1 + 1e-6 / a)
    links = [Links(np.arange(N - 1), np.arange(1, N), LAW, prestretch=e0),
             Links([N - 1], [0], LAW, shift=[N * (a + e0), 0.0], prestretch=e0)]  # fmt: skip
    taut = Network(np.full(N, 1e-3), links, dim=2, positions=stretched)
    assert np.allclose(taut.rest_lengths, a, rtol=1e-12)  # spans less the prestretch: the unloaded length
    assert np.array_equal(taut.extension(np.zeros(2 * N)), np.full(N, e0))  # exactly the prestretch
    # A uniform displacement: w = 0 exactly, so the extensions stay exactly e0 and the pulls cancel.
    assert np.array_equal(taut.extension(np.tile([3e-6, -2e-6], N)), np.full(N, e0))
    assert np.all(taut.accelerations(np.zeros(2 * N), g=0.0) == 0.0)
    with pytest.raises(ValueError, match="two or three dimensions"):
        Network([1e-3, 1e-3], [Links([0], [1], LAW, prestretch=1e-6)], positions=[0.0, 0.04])


def test_a_stack_of_planar_networks_steps_each_on_its_own():
    nets = [triangle(), triangle(law=PowerLaw(K=2.0e6, n=1.5))]
    stack = Network.stack(nets)
    xs = np.stack([stretched_state(net, seed=k)[0] for k, net in enumerate(nets)])
    together = stack.accelerations(xs, g=9.81)
    for b, net in enumerate(nets):
        assert np.array_equal(together[b], net.accelerations(xs[b], g=9.81))


def test_anchored_links_and_three_components():
    """A site hung from two anchors in space (dim 3): at the equilibrium the links' pulls carry its weight."""
    spring = LinearSpring(K=1e3)
    net = Network([1e-2], [Links([0, 0], [ANCHOR, ANCHOR], spring, anchor=[[-0.1, 0.0, 0.1], [0.1, 0.0, 0.1]])],
                  dim=3, positions=[[0.0, 0.0, 0.0]])  # fmt: skip
    L0 = np.sqrt(0.02)
    # At the site's rest position the springs are unstretched: only gravity, along -z.
    assert np.allclose(net.accelerations(np.zeros(3), g=9.81), [0.0, 0.0, -9.81], rtol=0, atol=1e-15)
    # Lowered by z: each spring pulls with K (l - L0) along the line to its anchor; the vertical parts
    # balance the weight where 2 K (l - L0) (0.1 + z)/l = m g.
    from scipy.optimize import brentq

    def residual(z):
        length = np.hypot(0.1, 0.1 + z)
        return 2e3 * (length - L0) * (0.1 + z) / length - 1e-2 * 9.81

    z = brentq(residual, 0.0, 0.01, xtol=1e-16)
    assert np.allclose(net.accelerations([0.0, 0.0, -z], g=9.81), 0.0, rtol=0, atol=1e-11)
