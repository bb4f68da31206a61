"""Integration: energy, convergence, batches, dashpots, limits, results and their checks."""

import itertools

import numpy as np
import pytest
from ringchain.numerics import DEFAULT_RTOL, VERLET_STEPS_PER_PERIOD, Chain, simulate, simulate_batch

PAPER = Chain.from_paper("dual-spring")
DROP = 0.05  # m: a 1 m/s impact, peak forces ~ 80 N
SENSORS = [6, 12]


@pytest.fixture(scope="module")
def reference():
    """The paper's dual-spring chain over 1 ms (the leading pulse passes ring 12) at rtol 1e-12."""
    return simulate(PAPER, 1e-3, drop_height=DROP, n_samples=1001, rtol=1e-12)


def sensor_error(sim, ref):
    """Largest sensor-force error in rings 6 and 12, relative to their peak."""
    exact = ref.sensor_force[:, SENSORS]
    return np.abs(sim.sensor_force[:, SENSORS] - exact).max() / np.abs(exact).max()


def test_default_tolerance_converges(reference):
    errors = [sensor_error(simulate(PAPER, 1e-3, drop_height=DROP, n_samples=1001, rtol=r), reference)
              for r in (1e-7, 1e-8, DEFAULT_RTOL)]  # fmt: skip
    # LSODA's error follows its tolerance (Adams, order up to 12): at least 10x per two decades ...
    assert errors[2] < errors[0] / 10
    # ... and the default gives the sensor traces to 1e-6 of their peak (measured: ~1e-7).
    assert errors[2] < 1e-6


def test_verlet_is_second_order(reference):
    errors = [
        sensor_error(simulate(PAPER, 1e-3, drop_height=DROP, n_samples=1001, method="verlet", steps_per_period=s),
                     reference)
        for s in (40, 80, 160)
    ]  # fmt: skip
    # Halving the step divides the error by 4 for a second-order method; the kinks of the
    # contact law at delta = 0 do not spoil it (measured ratios 3.9-4.0).
    for coarse, fine in itertools.pairwise(errors):
        assert 3.5 < coarse / fine < 4.5
    # The default step gives the sensors to 1e-4 of the peak over 1 ms (measured 4e-5).
    assert errors[0] * (40 / VERLET_STEPS_PER_PERIOD) ** 2 < 1e-4


@pytest.mark.parametrize("method", ["odeint", "LSODA", "verlet"])
def test_energy_is_conserved_without_dashpots(method):
    sim = simulate(PAPER, 2e-3, drop_height=DROP, method=method)
    energy = sim.energy()
    impact = energy.kinetic[0]
    assert np.all(energy.dissipated == 0.0)
    drift = np.abs(energy.total - energy.total[0]).max() / impact
    # LSODA: errors of rtol 1e-9 amplified along 2 ms of rattling contacts (measured 2e-8);
    # Verlet: its shadow energy differs from the energy by O((omega dt)^2) ~ 1e-3 at 60 steps
    # per period (measured 1e-4), and does not drift.
    assert drift < (1e-3 if method == "verlet" else 1e-6)


def test_odeint_and_solve_ivp_lsoda_agree(reference):
    # The same LSODA integrator, stepped from Fortran or from Python: both within their
    # tolerance (rtol 1e-9 -> ~1e-7 of the peak, test above) of the rtol 1e-12 reference.
    for method in ("odeint", "LSODA"):
        sim = simulate(PAPER, 1e-3, drop_height=DROP, n_samples=1001, method=method)
        assert sensor_error(sim, reference) < 1e-6


def test_sample_times_need_not_start_at_zero(reference):
    t = reference.t[500:]
    late = simulate(PAPER, 1e-3, drop_height=DROP, t_eval=t, rtol=1e-12)
    np.testing.assert_array_equal(late.t, t)
    # Same integration, sampled later: equal to the reference within its tolerance (1e-12 rtol).
    peak = np.abs(reference.sensor_force).max()
    assert np.abs(late.sensor_force - reference.sensor_force[500:]).max() < 1e-8 * peak


def test_dashpots_only_remove_energy():
    chain = Chain.from_paper("dual-spring", gamma_c=2.0, gamma_b=5.0)
    sim = simulate(chain, 2e-3, drop_height=DROP)
    energy = sim.energy()
    impact = energy.kinetic[0]
    # The dissipated energy only grows and the mechanical energy only falls; allowance: the
    # solver's error, rtol 1e-9 of the energy scale (measured: every 2 us sample dissipates
    # more than 1e-5 of the impact energy, far above it).
    assert np.all(np.diff(energy.dissipated) >= -1e-8 * impact)
    assert np.all(np.diff(energy.mechanical) <= 1e-8 * impact)
    assert energy.dissipated[-1] > 0.1 * impact  # they do take energy out
    # Mechanical + dissipated is conserved (same tolerance as the undamped budget).
    assert np.abs(energy.total - energy.total[0]).max() < 1e-6 * impact


def test_momentum_of_a_free_chain_is_conserved():
    chain = Chain.power_law(30, K=1.0, n=1.5, m=1.0, a=1.0, support="free")
    sim = simulate(chain, 40.0, impact_velocity=1.0, gravity=False)
    momentum = sim.ring_velocity.sum(axis=1) * chain.m
    # No external force, and the internal forces cancel in every evaluation: LSODA's Adams
    # formulas are linear combinations of them, so momentum is kept to rounding (measured 3e-15).
    np.testing.assert_allclose(momentum, -1.0, atol=1e-12)


def test_batch_is_one_problem_with_the_numbers_of_separate_runs():
    heights = [0.01, 0.05, 0.2]
    batch = simulate_batch(PAPER, 1e-3, drop_heights=heights, n_samples=1001)
    assert batch.contact_force.shape == (3, 1001, 19) and len(batch) == 3
    for k, h in enumerate(heights):
        single = simulate(PAPER, 1e-3, drop_height=h, n_samples=1001)
        peak = np.abs(single.contact_force).max()
        # The batch shares its steps across runs, so it differs from the single run by their
        # global errors: at rtol 1e-9 over 1 ms, measured against rtol 1e-12 at up to 1.1e-6
        # of the peak (the 1 cm drop's impact contact; the batch's own error is smaller).
        assert np.abs(batch[k].contact_force - single.contact_force).max() < 3e-6 * peak
        assert batch[k].drop_height == h


def test_verlet_batch_is_exactly_separate_runs():
    chain = Chain.power_law(10, K=1e9, n=1.5, m=0.01, a=0.02)
    kwargs = dict(method="verlet", dt=2e-7, n_samples=101)
    batch = simulate_batch(chain, 2e-4, impact_velocities=[0.2, 0.5], **kwargs)
    for k, v in enumerate([0.2, 0.5]):
        # Same step, same elementwise operations: identical to the last bit.
        np.testing.assert_array_equal(batch[k].x, simulate(chain, 2e-4, impact_velocity=v, **kwargs).x)


def test_dual_spring_tends_to_the_hertz_chain_as_bending_stiffens():
    """K_b -> infinity: each ring rigid, the dual-spring chain is the power-law chain with n = 3/2."""
    K_c, m, a = 7.5e9, 0.008, 0.04
    kwargs = dict(impact_velocity=0.5, gravity=False, n_samples=401)
    hertz = simulate(Chain.power_law(10, K_c, 1.5, m, a, support="free"), 4e-4, **kwargs).contact_force
    errors = []
    for K_b in (1e8, 1e9, 1e10):
        dual = simulate(Chain.dual_spring(10, K_c, K_b, m, a, support="free"), 4e-4, **kwargs).contact_force
        errors.append(np.abs(dual - hertz).max() / hertz.max())
    # The ring's compliance adds F/K_b to the contact's (F/K_c)^(2/3): the error is first order
    # in 1/K_b once K_b exceeds the contact stiffness (~4e7 N/m at the 160 N peak); measured
    # 0.66, 0.079, 0.0080, so a factor 10 per decade, within 20%.
    assert 8 < errors[1] / errors[2] < 12
    assert errors[2] < 1e-2


def test_results_are_arrays_and_csv(tmp_path):
    chain = Chain.power_law(4, K=1e9, n=1.5, m=0.01, a=0.02)
    sim = simulate(chain, 1e-4, impact_velocity=0.1, n_samples=11)
    assert sim.contact_force.shape == (11, 3) and sim.sensor_force.shape == (11, 4)
    assert sim.support_force.shape == (11,) and sim.bending_force is None
    path = tmp_path / "run.csv"
    sim.to_csv(path)
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    header = path.read_text().splitlines()[0].split(",")
    assert header[:2] == ["t_s", "contact_0_1_N"] and header[-1] == "support_N"
    np.testing.assert_allclose(data[:, 0], sim.t, rtol=1e-15)  # repr of floats round-trips
    np.testing.assert_allclose(data[:, 1:4], sim.contact_force, rtol=1e-15)


def test_power_law_sensor_is_the_mean_of_the_two_sides():
    chain = Chain.power_law(4, K=1e9, n=1.5, m=0.01, a=0.02)
    sim = simulate(chain, 1e-4, impact_velocity=0.1, n_samples=11)
    f, top = sim.contact_force, sim.support_force
    np.testing.assert_allclose(sim.sensor_force[:, 0], f[:, 0] / 2, rtol=1e-15)
    np.testing.assert_allclose(sim.sensor_force[:, 2], (f[:, 1] + f[:, 2]) / 2, rtol=1e-15)
    np.testing.assert_allclose(sim.sensor_force[:, 3], (f[:, 2] + top) / 2, rtol=1e-15)


@pytest.mark.parametrize(
    ("kwargs", "error", "message"),
    [
        (dict(impact_velocity=1.0, drop_height=0.1), ValueError, "not both"),
        (dict(impact_velocity=[1.0, 2.0]), ValueError, "use simulate_batch"),
        (dict(impact_velocity=-1.0), ValueError, "impact_velocity must be non-negative"),
        (dict(impact_velocity=1.0, method="euler"), ValueError, "method must be one of"),
        (dict(impact_velocity=1.0, t_eval=[0.0, 2.0]), ValueError, "within"),
        (dict(impact_velocity=1.0, n_samples=2), ValueError, "n_samples"),
    ],
)
def test_simulate_validates(kwargs, error, message):
    with pytest.raises(error, match=message):
        simulate(PAPER, 1e-3, **kwargs)


def test_verlet_refuses_dashpots():
    with pytest.raises(ValueError, match="undamped"):
        simulate(Chain.from_paper("power-law", gamma=1.0), 1e-3, drop_height=0.01, method="verlet")


def test_sensor_ring_must_exist(reference):
    with pytest.raises(IndexError, match="ring 20 is not in a chain of 20"):
        reference.sensor(20)
