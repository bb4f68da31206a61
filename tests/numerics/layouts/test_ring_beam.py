"""The ring as a curved beam and the ring-resolved chain: frequencies, stiffness, reduction, dynamics."""

import numpy as np
import pytest
from ringchain.numerics import Chain, Simulation, simulate
from ringchain.numerics.jobs.effective_mass import arrival_times
from ringchain.numerics.layouts.ring_beam import ReducedRing, RingModel
from ringchain.numerics.layouts.ring_chain import RingChain, RingSimulation, simulate_rings
from ringchain.theory import Ring, bending_stiffness, ring_frequencies

E, NU, RHO = 193e9, 0.29, 8000.0  # the package's stainless steel
G = 9.80665
R_PAPER, r_PAPER = 22.5e-3, 2.5e-3  # the paper's R/r = 9 ring


def classical(R, r, k, kind):
    """Hoppe (in plane) and Michell (out of plane) frequencies of a thin ring, Hz, typed from the textbooks
    (Love, Ch. XVIII; Rao, Vibration of Continuous Systems, Ch. 12): E I/(G J) = 1 + nu for a solid disc."""
    I, A = np.pi * r**4 / 4, np.pi * r**2  # noqa: E741
    extra = 1.0 if kind == "in-plane" else 1.0 + NU
    return np.sqrt(E * I / (RHO * A * R**4)) * k * (k**2 - 1) / np.sqrt(k**2 + extra) / (2 * np.pi)


# --- one ring ------------------------------------------------------------------------------------------


@pytest.mark.parametrize("kind", ["in-plane", "out-of-plane"])
def test_slender_ring_frequencies_are_the_classical_ones(kind):
    ring = RingModel(50 * r_PAPER, r_PAPER, elements=64)
    orders = np.arange(2, 7)
    error = ring.frequencies(kind, order=orders) / classical(ring.R, ring.r, orders, kind) - 1
    # At R/r = 50 shear, rotary inertia and extension lower omega_k by ~0.5 (k r/R)^2 <= 0.7 % (k = 6),
    # and the elements add < 2e-4 (test_elements_converge_to_the_continuous_ring).
    assert np.all(np.abs(error) < 0.01)
    assert np.all(error < 0) and np.all(np.diff(error) < 0)  # the corrections grow with k


def test_elements_converge_to_the_continuous_ring():
    """Against the continuum frequencies of the same beam theory (theory.ring_frequencies), at R/r = 9."""
    orders = np.arange(2, 7)
    exact = np.array([ring_frequencies(R_PAPER, r_PAPER, E, NU, rho=RHO, k=k)[0] for k in orders])
    errors = [RingModel(R_PAPER, r_PAPER, elements=n).frequencies(order=orders) / exact - 1 for n in (32, 64)]
    assert np.all(errors[0] > 0) and np.all(errors[1] > 0)  # consistent mass: upper bounds
    # Second order in the element angle (the tangential field is interpolated linearly, as a bar's):
    # halving the elements' angle divides the error by 4 (3.5 allows for the next order).
    assert np.all(errors[0] / errors[1] > 3.5)
    assert errors[1].max() < 3e-3  # 64 elements, k = 6 (measured 2.9e-3); k = 2: 2e-5


@pytest.mark.parametrize("kind", ["in-plane", "out-of-plane"])
def test_spectrum_by_order_is_the_assembled_ring(kind):
    ring = RingModel(R_PAPER, r_PAPER, elements=16)
    from scipy.linalg import eigh

    K, M = ring.matrices(kind)
    assembled = np.sqrt(np.abs(eigh(K, M, eigvals_only=True))) / (2 * np.pi)
    by_order = []
    for k, (omega2, _) in ring._spectrum(kind).items():
        copies = 1 if k in (0, ring.elements // 2) else 2  # each 0 < k < n/2 is a degenerate pair
        by_order += [np.sqrt(np.abs(w)) / (2 * np.pi) for w in omega2] * copies
    by_order = np.sort(by_order)
    assert np.allclose(assembled[3:], by_order[3:], rtol=1e-9)  # same matrices, two eigensolvers
    # Three rigid-body modes (two translations and a rotation, or a translation and two rotations),
    # zero to rounding against the first elastic frequency, and excluded by frequencies().
    assert np.all(assembled[:3] < 1e-5 * assembled[3])
    assert ring.frequencies(kind, count=1)[0] == pytest.approx(assembled[3], rel=1e-9)


@pytest.mark.parametrize("aspect", [3.5, 5.5, 9.0, 20.0])
@pytest.mark.parametrize("elements", [8, 64])
def test_diametral_stiffness_is_castiglianos(aspect, elements):
    ring = RingModel(aspect * r_PAPER, r_PAPER, elements=elements)
    thick = bending_stiffness(ring.R, ring.r, E, NU)
    # The elements are statically exact: any mesh gives the curved-beam K_b, to rounding (the condensed
    # stiffness is a difference of terms ~1e4 larger).
    assert ring.diametral_stiffness() == pytest.approx(float(thick), rel=1e-9)
    assert ring.diametral_stiffness() < bending_stiffness(ring.R, ring.r, E, NU, thin=True)


def test_mode_shapes():
    ring = RingModel(R_PAPER, r_PAPER, elements=32)
    shape = ring.mode_shape(2)
    w, u, _ = shape.displacement
    assert shape.order == 2 and shape.frequency == pytest.approx(ring.frequencies(order=2), rel=1e-12)
    # Flexural k = 2: w = cos 2(theta - pi/2), largest at the contacts (top outward), and nearly
    # inextensional, u' = -w: u = -sin 2(theta - pi/2)/2, to O((r/R)^2) ~ 1 %.
    assert np.allclose(w, np.cos(2 * (shape.theta - np.pi / 2)), atol=1e-3)
    assert np.allclose(u, -0.5 * np.sin(2 * (shape.theta - np.pi / 2)), atol=0.02)
    top = np.argmin(np.abs(shape.theta - np.pi / 2))
    assert w[top] == pytest.approx(1.0)
    out = ring.mode_shape(3, "out-of-plane")
    # Nodes exact (a Fourier mode of the assembled ring); between them the static shape functions
    # interpolate the dynamic shape to O(beta^2) ~ 4e-3 at 32 elements.
    assert np.allclose(out.displacement[0], np.cos(3 * (out.theta - np.pi / 2)), atol=5e-3)


def test_orders_of_the_lowest_modes():
    ring = RingModel(R_PAPER, r_PAPER, elements=32)
    # In plane at R/r = 9 the breathing mode (k = 0, extension) falls between the flexural k = 4 and 5.
    assert ring.mode_orders(count=5).tolist() == [2, 3, 4, 0, 5]
    assert np.all(np.diff(ring.frequencies(count=8)) >= 0)


# --- the ring as the chain sees it --------------------------------------------------------------------------


@pytest.fixture(scope="module")
def ring_model():
    return RingModel(R_PAPER, r_PAPER, elements=16)


def test_reduction_keeps_mass_stiffness_and_rigid_translation(ring_model):
    full = ring_model.reduce(None)
    from scipy.linalg import eigh

    free = eigh(full.stiffness, full.mass, eigvals_only=True)
    for modes in (0, 3, full.n_dof - 2):
        reduced = ring_model.reduce(modes)
        assert reduced.m == pytest.approx(ring_model.mass, rel=1e-12)
        assert reduced.K_b == pytest.approx(ring_model.diametral_stiffness(), rel=1e-12)
        assert np.allclose(reduced.stiffness @ reduced.rigid, 0.0)  # exactly singular by construction
        if modes == full.n_dof - 2:  # all modes: a change of basis, the same symmetric spectrum
            reduced_free = eigh(reduced.stiffness, reduced.mass, eigvals_only=True)
            assert np.allclose(reduced_free[1:], free[1:], rtol=1e-8)
    assert np.allclose(full.stiffness @ full.rigid, 0.0, atol=1e-9 * np.abs(full.stiffness).max())
    # The fixed-interface modes of the reduction are those of the full ring with its contacts held.
    assert np.allclose(ring_model.reduce(3).mode_frequencies, full.mode_frequencies[:3], rtol=1e-10)


@pytest.mark.parametrize("modes", [0, 4, None])
def test_sensor_reads_the_static_load(ring_model, modes):
    """Pulled by T at the top and bottom, the two side sections carry T between them (statics)."""
    ring = ring_model.reduce(modes)
    load = np.zeros(ring.n_dof)
    load[1], load[0] = 10.0, -10.0  # N
    x = np.zeros(ring.n_dof)
    x[1:] = np.linalg.solve(ring.stiffness[1:, 1:], load[1:])  # bottom held
    assert ring.sensor @ x == pytest.approx(10.0, rel=1e-8)  # static fields exact: rounding only
    assert x[1] - x[0] == pytest.approx(10.0 / ring.K_b, rel=1e-10)


def test_two_masses_ring_is_the_dual_spring_models():
    ring = ReducedRing.two_masses(0.02, 3e6)
    assert ring.m == pytest.approx(0.02) and ring.K_b == pytest.approx(3e6)
    assert np.allclose(ring.sensor @ np.array([0.0, 1e-6]), 3.0)


# --- the chain -------------------------------------------------------------------------------------------------


RING9 = Ring.from_aspect_ratio(9.0)


def short_chain(modes, n_rings=4, elements=16):
    return RingChain.from_ring(RING9, n_rings, modes=modes, elements=elements)


def test_two_masses_chain_is_the_dual_spring_chain():
    """Each ring two lumped halves on K_b: the ring-resolved machinery integrates the paper's Eqs. (5)-(6)."""
    m = RING9.mass
    dual = Chain.dual_spring(6, RING9.K_c, RING9.K_b, m, RING9.spacing, m_gravity=m)
    rings = RingChain(6, ReducedRing.two_masses(m, RING9.K_b), RING9.K_c, RING9.spacing)
    lattice = simulate(dual, 6e-4, drop_height=0.05, n_samples=601, method="odeint")
    resolved = simulate_rings(rings, 6e-4, drop_height=0.05, n_samples=601, method="odeint")
    scale = lattice.contact_force.max()
    # Two LSODA runs at rtol 1e-9 on the same equations in different layouts: agree to ~1e-8 of the peak.
    for name in ("contact_force", "sensor_force", "support_force"):
        assert np.abs(getattr(resolved, name) - getattr(lattice, name)).max() < 1e-7 * scale


def test_hanging_chain_is_at_rest():
    chain = short_chain(modes=3, n_rings=5)
    sim = simulate_rings(chain, 2e-4, impact_velocity=0.0, n_samples=21)
    weight = chain.m * G
    # Contact i carries the rings 0..i; the sensor the mean of the forces on its two sides.
    expected = weight * np.arange(1, 5)
    assert np.allclose(sim.contact_force, expected, rtol=1e-9)  # static solution: linear algebra and rounding
    assert np.allclose(sim.support_force, 5 * weight, rtol=1e-9)
    forces = np.concatenate([[0.0], expected, [5 * weight]])
    assert np.allclose(sim.sensor_force, 0.5 * (forces[:-1] + forces[1:]), rtol=1e-8)
    assert np.abs(sim.u).max() < 1e-9  # m/s: an equilibrium stays put (Verlet steps of rounding)


def test_drop_starts_with_ring_0_free_and_undeformed():
    chain = short_chain(modes=3, n_rings=5)
    x, u = chain.initial_state(drop_height=0.05)
    assert np.allclose(x[0] - x[0, 0] * chain.ring.rigid, 0.0)  # a rigid translation: no internal load
    assert np.allclose(u[0], -np.sqrt(2 * G * 0.05) * chain.ring.rigid)
    e = chain.contact_extension(x)
    assert e[0] == pytest.approx(0.0, abs=1e-15)  # just taut
    assert np.allclose(chain.contact_forces(e)[1:], chain.m * G * np.arange(1, 5), rtol=1e-9)


def test_energy_is_conserved_without_damping():
    chain = short_chain(modes=4)
    impact = 0.5 * chain.m * 2 * G * 0.05
    accurate = simulate_rings(chain, 5e-4, drop_height=0.05, n_samples=501, method="odeint", rtol=1e-11)
    total = accurate.energy().total
    assert np.abs(total - total[0]).max() < 1e-7 * impact  # LSODA at rtol 1e-11 (measured ~1e-9)
    drifts = []
    for steps in (60, 120):
        sim = simulate_rings(chain, 5e-4, drop_height=0.05, n_samples=501, steps_per_period=steps)
        total = sim.energy().total
        drifts.append(np.abs(total - total[0]).max() / impact)
    assert drifts[0] < 1e-4  # default Verlet step (measured ~3e-5 on the 20-ring chain)
    assert 3.0 < drifts[0] / drifts[1] < 5.0  # second order: doubling the steps divides it by 4


def test_craig_bampton_with_all_modes_is_the_full_model():
    full = short_chain(modes=None)
    cb_all = short_chain(modes=full.ring.n_dof - 2)
    dt = 2e-8  # one step for both: Verlet commutes with the linear change of coordinates
    a = simulate_rings(full, 3e-4, drop_height=0.05, n_samples=301, dt=dt)
    b = simulate_rings(cb_all, 3e-4, drop_height=0.05, n_samples=301, dt=dt)
    scale = np.abs(a.sensor_force).max()
    assert np.abs(a.sensor_force - b.sensor_force).max() < 1e-8 * scale  # rounding over 15000 steps
    assert np.abs(a.contact_force - b.contact_force).max() < 1e-8 * scale


def test_reduction_converges_to_the_full_model():
    """Sensor traces (low-passed at 10 kHz, as for the arrival times) of a 6-ring chain, 0.8 ms."""
    from ringchain.numerics.jobs.effective_mass import lowpass

    runs = {m: simulate_rings(short_chain(m, n_rings=6), 8e-4, drop_height=0.05, n_samples=801)
            for m in (0, 4, 12, None)}  # fmt: skip
    reference = lowpass(runs[None].t, runs[None].sensor_force.T)
    errors = [np.abs(lowpass(run.t, run.sensor_force.T) - reference).max() / reference.max()
              for run in (runs[0], runs[4], runs[12])]  # fmt: skip
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] < 0.01  # 12 modes (the default): within 1 % of the peak (measured 0.3 %)


def test_long_waves_see_the_whole_mass_and_the_series_stiffness():
    """The acoustic branch of every ring reduction, and of the dual-spring ring, tends to the series law
    (paper Eq. (3)) with the ring mass: omega/q -> sqrt(k_s/m0)."""
    tension = 1.0  # N
    k = 1.5 * RING9.K_c ** (2 / 3) * tension ** (1 / 3)
    k_series = 1 / (1 / k + 1 / RING9.K_b)
    rings = [short_chain(m).ring for m in (0, 6, None)] + [ReducedRing.two_masses(RING9.mass, RING9.K_b)]
    q = np.array([1e-3, 2e-3])
    for ring in rings:
        chain = RingChain(4, ring, RING9.K_c, RING9.spacing)
        speed = chain.linear_dispersion(q, tension)[:, 0] * 2 * np.pi / q
        deviation = np.abs(speed / np.sqrt(k_series / RING9.mass) - 1)
        assert deviation[0] < 1e-5  # dispersion O(q^2) ~ 1e-6 at q = 1e-3 (full ring: eigensolver rounding)


def test_one_mode_ring_chain_against_the_dual_spring_chain():
    """Guyan rings (rigid translation + static stretch: one internal shape) vs the dual-spring chain (m0):
    the same mass, static law and long-wave limit; they differ in the inertia of the stretch,
    (a - b)/2 of the consistent mass matrix [[a, b], [b, a]] against m0/4 of two lumped halves."""
    guyan = short_chain(0, n_rings=8).ring
    a, b = guyan.mass[0, 0], guyan.mass[0, 1]
    assert 2 * (a + b) == pytest.approx(RING9.mass, rel=1e-12)
    assert (a - b) / 2 < RING9.mass / 4  # the stretch moves the ring's sides less than its ends
    dual = Chain.dual_spring(8, RING9.K_c, RING9.K_b, RING9.mass, RING9.spacing, m_gravity=RING9.mass)
    rings = RingChain(8, guyan, RING9.K_c, RING9.spacing)
    t_dual = arrival_times(simulate(dual, 8e-4, drop_height=0.05, n_samples=801), (2, 6))
    t_ring = arrival_times(simulate_rings(rings, 8e-4, drop_height=0.05, n_samples=801), (2, 6))
    # Long waves travel alike; the pulse, a few rings wide, feels the rings' internal dynamics, whose
    # time scale is 1/omega of the stretch: sqrt(((a - b)/2)/K_b) against sqrt((m0/4)/K_b).  So the
    # lighter stretch makes the Guyan chain faster, by less than the ratio of those time scales
    # (measured: 10-11 %, against a bound of 26 %).
    bound = 1 - np.sqrt((a - b) / 2 / (RING9.mass / 4))
    assert np.all(t_ring < t_dual) and np.all(1 - t_ring / t_dual < bound)


def test_ring_simulation_has_the_simulation_interface(tmp_path):
    chain = short_chain(modes=2, n_rings=8)
    sim = simulate_rings(chain, 8e-4, drop_height=0.05, n_samples=801)
    assert isinstance(sim, RingSimulation) and isinstance(sim, Simulation)
    assert sim.contact_force.shape == (801, 7) and sim.sensor_force.shape == (801, 8)
    assert sim.bending_force is None and sim.support_force.shape == (801,)
    assert 0 < sim.arrival_time(2) < sim.arrival_time(6) < 8e-4
    assert sim.time_of_flight(2, 6) == pytest.approx(sim.arrival_time(6) - sim.arrival_time(2))
    assert sim.wave_speed(2, 6) == pytest.approx(4 * chain.a / sim.time_of_flight(2, 6))
    assert sim.peak_force(2) > 0 and sim.pulse_width(2) > 0
    assert np.allclose(sim.ring_velocity[0, 0], -np.sqrt(2 * G * 0.05))
    sim.to_csv(tmp_path / "run.csv")
    data = np.genfromtxt(tmp_path / "run.csv", delimiter=",", names=True)
    assert np.allclose(data["contact_2_3_N"], sim.contact_force[:, 2])
    assert np.allclose(data["support_N"], sim.support_force)


@pytest.mark.parametrize(
    ("call", "error", "message"),
    [
        (lambda: RingModel(2.5e-3, 2.5e-3), ValueError, "r must be smaller than R"),
        (lambda: RingModel(R_PAPER, r_PAPER, elements=30), ValueError, "multiple of 4"),
        (lambda: RingModel(R_PAPER, r_PAPER, material="gold"), ValueError, "unknown material"),
        (lambda: RingModel(R_PAPER, r_PAPER, elements=8).frequencies(order=5), ValueError, "order 5 is above"),
        (lambda: RingModel(R_PAPER, r_PAPER).frequencies("radial"), ValueError, "kind must be one of"),
        (lambda: RingModel(R_PAPER, r_PAPER, elements=8).reduce(50), ValueError, "internal coordinates"),
        (lambda: RingChain(1, ReducedRing.two_masses(1.0, 1.0), 1.0, 1.0), ValueError, "n_rings must be"),
        (lambda: RingChain.from_ring(Ring.from_aspect_ratio(2.5), 4), ValueError, "cannot form a chain"),
        (lambda: simulate_rings(short_chain(0), 1e-4, drop_height=[0.1, 0.2]), ValueError, "one impact"),
        (lambda: simulate_rings(short_chain(0), 1e-4, method="RK45"), ValueError, "method must be one of"),
    ],
)
def test_bad_inputs(call, error, message):
    with pytest.raises(error, match=message):
        call()
