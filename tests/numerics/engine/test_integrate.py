"""Integration: energy, convergence, batches, dashpots, limits, results and their checks."""

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain.numerics import (
    DEFAULT_RTOL,
    VERLET_STEPS_PER_PERIOD,
    Chain,
    IntegrationError,
    NoPulseError,
    RunTooLargeError,
    estimate_run,
    paper_chain,
    simulate,
    simulate_batch,
)
from ringchain.numerics.engine.integrate import ENERGY_DRIFT_LIMIT, TOLERANCE_RANGE

PAPER = paper_chain("dual-spring")
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
    chain = paper_chain("dual-spring", gamma_c=2.0, gamma_b=5.0)
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


@pytest.mark.parametrize(("model", "dashpots"), [("dual-spring", dict(gamma_c=2.0, gamma_b=5.0)),
                                                 ("power-law", dict(gamma=2.0))])  # fmt: skip
def test_recorded_forces_of_a_damped_run_obey_newtons_law(model, dashpots):
    """The bond forces read from a run (dashpots included) against the motion itself: the impulse
    of the net force on each site equals the change of its momentum."""
    from scipy.integrate import cumulative_trapezoid

    chain = paper_chain(model, **dashpots)
    sim = simulate(chain, 1e-3, drop_height=DROP, n_samples=4001, rtol=1e-11)
    lat = chain.network()
    f = sim.bond_force
    below = np.pad(f, ((0, 0), (1, 0)))[:, : lat.n_sites]  # bond k-1 pulls site k down (none below site 0)
    above = f[:, : lat.n_sites]  # bond k pulls it up (the last one: the support)
    impulse = cumulative_trapezoid(above - below - lat.weight_mass * sim.g, sim.t, axis=0, initial=0.0)
    momentum = lat.mass * (sim.u - sim.u[0])
    # Trapezoid rule over 0.25 us samples: first order at the force jumps of dashpots in closing
    # contacts (measured 9e-5 and 3e-5 of the largest momentum; 2.6e-4 and 7e-5 at twice the step).
    # A dashpot read with the wrong sign is off by 2.5-6%.
    assert np.abs(impulse - momentum).max() < 1e-3 * np.abs(lat.mass * sim.u).max()
    # The sensors read the same bonds: the ring's bending bond, or the mean of the two contacts.
    expected = f[:, chain.bending_links] if model == "dual-spring" else 0.5 * (below + above)
    np.testing.assert_array_equal(sim.sensor_force, expected)


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
        simulate(paper_chain("power-law", gamma=1.0), 1e-3, drop_height=0.01, method="verlet")


@pytest.mark.parametrize(
    ("ring", "message"),
    [(20, "ring 20 is not in a chain of 20 rings"), (-1, "ring -1 is not in a chain"),
     (2.7, "ring must be an integer, got 2.7"), (True, "ring must be an integer, got True"),
     ("6", "ring must be an integer")],
)  # fmt: skip
def test_sensor_ring_must_be_a_ring_of_the_chain(reference, ring, message):
    # 2.7 used to read ring 2, True ring 1, 20 raised an IndexError.
    with pytest.raises(ValueError, match=message):
        reference.sensor(ring)


def test_sensor_readings_need_rings_in_order_and_a_pulse(reference):
    with pytest.raises(ValueError, match="far ring must lie further from the impact"):
        reference.wave_speed(12, 6)  # used to complain about a "distance" never given
    # No impact: the hanging chain stays at rest, its sensors read their static force only
    # (the arrival time used to be reported as 0).
    at_rest = simulate(PAPER, 5e-4, n_samples=101)
    assert np.ptp(at_rest.sensor(6)) < 1e-9 * at_rest.sensor(6)[0]  # the solver's tolerance on a static state
    with pytest.raises(NoPulseError, match="no pulse"):
        at_rest.arrival_time(6)


# -- recording only what is read; memory and work before the run --------------------------------------
@pytest.mark.parametrize("model", ["power-law", "dual-spring"])
@pytest.mark.parametrize("method", ["odeint", "verlet"])
def test_recording_the_sensor_rings_only_keeps_their_readings(model, method):
    chain = paper_chain(model)
    full = simulate(chain, 1.5e-3, drop_height=DROP, method=method, n_samples=1501)
    kept = simulate(chain, 1.5e-3, drop_height=DROP, method=method, n_samples=1501, rings=SENSORS)
    assert kept.x.shape == (1501, {"power-law": 6, "dual-spring": 4}[model])  # rings 5-7, 11-13 or their halves
    for ring in SENSORS:
        # The same integration, sampled at the same sites: identical numbers.
        np.testing.assert_array_equal(kept.sensor(ring), full.sensor(ring))
        np.testing.assert_array_equal(kept.sensor(ring), full.sensor_force[:, ring])
    assert kept.wave_speed(*SENSORS) == full.wave_speed(*SENSORS)
    with pytest.raises(ValueError, match="ring 3 was not recorded"):
        kept.sensor(3)
    with pytest.raises(ValueError, match="needs every ring"):
        kept.energy()


def test_a_run_too_large_for_memory_is_refused_with_the_way_out():
    # 10^5 rings, dual-spring: 2e5 sites, 2001 samples of x and u are 6.4 GB before any force is
    # derived; the run used to end in a MemoryError traceback.
    chain = Chain.dual_spring(100_000, K_c=7.5e9, K_b=3.3e6, m=8.2e-3, a=0.04)
    full = estimate_run(chain, 2e-3, drop_heights=0.05, method="verlet")
    assert full.memory > 2 * 2001 * 200_000 * 8  # at least x and u of every site at every sample
    sensors = estimate_run(chain, 2e-3, drop_heights=0.05, method="verlet", rings=SENSORS)
    assert sensors.memory < 50 * 2**20  # 4 sites recorded; the state of 2e5 sites remains (~20 MB)
    with pytest.raises(RunTooLargeError, match=r"needs about 8\.\d+ GB .* record only the rings you read"):
        simulate(chain, 2e-3, drop_height=0.05, method="verlet", max_memory=2**30)
    with pytest.raises(RunTooLargeError, match=r"needs about 18\.\d MB"):
        simulate(chain, 2e-3, drop_height=0.05, method="verlet", rings=SENSORS, max_memory=2**20)


def test_a_run_of_hours_is_refused_before_it_starts():
    chain = Chain.power_law(10, K=1e9, n=1.5, m=0.01, a=0.02)
    # 1e12 steps of 1e-15 s: the run used to start and not end.
    with pytest.raises(RunTooLargeError, match=r"roughly [\d.]+ days .* 1e\+12 Verlet steps"):
        simulate(chain, 1e-3, impact_velocity=0.1, method="verlet", dt=1e-15)


# -- integrator settings: validated, and blow-up detected ---------------------------------------------------
@pytest.mark.parametrize(
    ("options", "message"),
    [
        # dt = 1e-4 s returned forces of 1e30 N; steps_per_period = 1, 1e23 N.
        (dict(method="verlet", dt=1e-4), r"above the stability limit of velocity Verlet .* 2/omega_max = 6\.\d+e-05 s"),
        (dict(method="verlet", steps_per_period=3), "steps_per_period must exceed pi"),
        (dict(method="verlet", steps_per_period=np.inf), "steps_per_period must be finite"),
        (dict(method="verlet", dt=np.nan), "dt must be finite"),
        # rtol = 10 returned 592 N where the converged largest contact force is 85 N; 1e-15 made odeint
        # fail ("illegal input").
        (dict(rtol=10.0), r"rtol must lie in \[1e-13, 0.001\]"),
        (dict(rtol=1e-15), r"rtol must lie in \[1e-13, 0.001\]"),
        (dict(atol=10.0), r"atol must lie in \(0, 0.001\]"),
        (dict(atol=0.0), r"atol must lie in \(0, 0.001\]"),
    ],
)
def test_integrator_settings_are_validated(options, message):
    with pytest.raises(ValueError, match=message):
        simulate(paper_chain("power-law"), 2e-3, drop_height=DROP, **options)


def test_the_stability_limit_is_that_of_verlet_on_a_linear_chain():
    """For a linear chain (power law n = 1) the fastest mode is omega_max = 2 sqrt(K/m), and
    leapfrog is stable for omega dt < 2 (the textbook bound): the limit is 1/sqrt(K/m)."""
    K, m = 1e6, 0.01
    chain = Chain.power_law(40, K=K, n=1.0, m=m, a=0.04, support="free")
    limit = 1.0 / np.sqrt(K / m)
    with pytest.raises(ValueError, match=f"2/omega_max = {limit:.3g} s"):
        simulate(chain, 2e-2, impact_velocity=0.1, gravity=False, method="verlet", dt=1.001 * limit)
    # Just below the limit it is stable (the energy error is bounded, not growing), but at ~pi steps
    # per period its energy error exceeds the 1% drift bound: allowed by max_energy_drift=None.
    sim = simulate(chain, 2e-2, impact_velocity=0.1, gravity=False, method="verlet", dt=0.9 * limit,
                   max_energy_drift=None, n_samples=201)  # fmt: skip
    assert np.all(np.isfinite(sim.x))


@pytest.mark.parametrize(
    ("options", "drift"),
    # Returned before: dt = 3e-5 s (10 steps per period) with the energy off by 8%, LSODA at rtol = 1e-3
    # by 5% (the max-norm control of the default dopri5 keeps the energy within 1% even there).
    [(dict(method="verlet", dt=3e-5), "0.0[1-9]"), (dict(method="odeint", rtol=1e-3), r"0\.0[1-9]")],
)
def test_energy_drift_stops_an_inaccurate_run(options, drift):
    with pytest.raises(IntegrationError, match=f"total energy drifted by {drift}"):
        simulate(paper_chain("power-law"), 2e-3, drop_height=DROP, **options)


def test_tolerances_at_the_edge_of_the_range(reference):
    # The upper bound of TOLERANCE_RANGE still controls the error: sensor errors below 10% of the
    # peak over 1 ms (measured 3-8% at rtol = 1e-3 over 2 ms), and 100x less at 1e-5.
    coarse = simulate(PAPER, 1e-3, drop_height=DROP, n_samples=1001, rtol=TOLERANCE_RANGE[1], max_energy_drift=None)
    finer = simulate(PAPER, 1e-3, drop_height=DROP, n_samples=1001, rtol=1e-5)
    assert sensor_error(coarse, reference) < 0.1
    assert sensor_error(finer, reference) < sensor_error(coarse, reference) / 10
    # The lower bound works (LSODA refused 1e-14 as illegal input).
    assert sensor_error(simulate(PAPER, 1e-3, drop_height=DROP, n_samples=1001, rtol=TOLERANCE_RANGE[0]),
                        reference) < 1e-8  # fmt: skip


@pytest.mark.parametrize(
    ("method", "budget", "reason"),
    [("odeint", "_MAX_STEPS_PER_SAMPLE", r"Excess work done .* try method='verlet'"),
     ("dopri5", "_MAX_DOPRI5_STEPS", r"dopri5 stopped before t = 0.001 s in run 0: too many steps")],
)  # fmt: skip
def test_an_integrator_failure_is_a_value_error_with_its_reason(monkeypatch, method, budget, reason):
    # atol 1e-30 of the scales asks for more steps than the integrator may take: this was a
    # RuntimeError "odeint failed" (and an ODEintWarning).  The budget is cut (LSODA: from 1e6 to
    # 1e4 steps per sample; dopri5: from 1e7 to 1e4 steps) so that the failure comes in a fraction
    # of a second, not 20 s.
    from ringchain.numerics.engine import integrate

    monkeypatch.setattr(integrate, budget, 10_000)
    chain = Chain.power_law(5, K=1e6, n=1.5, m=0.01, a=0.04)
    with pytest.raises(IntegrationError, match=reason):
        simulate(chain, 1e-3, impact_velocity=1.0, atol=1e-30, method=method)


def test_default_runs_stay_far_below_the_drift_bound():
    for method in ("odeint", "verlet"):
        sim = simulate(paper_chain("dual-spring"), 2e-3, drop_height=DROP, method=method)
        energy = sim.energy()
        # Verlet's shadow energy at 60 steps per period: 1e-4 (test above); LSODA 1e-8.
        assert np.abs(energy.total - energy.total[0]).max() / energy.kinetic[0] < ENERGY_DRIFT_LIMIT / 10


# -- edge inputs: a ValueError that names the argument ---------------------------------------------------
@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (dict(gravity="no"), "gravity must be True or False, got 'no'"),  # was read as True
        (dict(n_samples=np.inf), "n_samples must be an integer, got inf"),  # was an OverflowError
        (dict(drop_heights=[]), r"drop_height must be one value or a 1-d array .* shape \(0,\)"),  # odeint failed
        (dict(drop_heights=[[0.1, 0.2]]), r"drop_height must be one value .* shape \(1, 2\)"),  # a broadcast error
        (dict(drop_heights=[0.1], rings=[3.5]), "ring must be an integer, got 3.5"),
        (dict(drop_heights=[0.1], rings=[]), "rings must name at least one ring"),
        (dict(drop_heights=[0.1], method=["verlet"]), "method must be one of"),
    ],
)
def test_simulate_batch_names_the_bad_argument(kwargs, message):
    with pytest.raises(ValueError, match=message):
        simulate_batch(PAPER, 1e-3, **kwargs)


@settings(max_examples=15, deadline=None)
@given(
    n_rings=st.integers(2, 8), n=st.floats(1.0, 1.5), speed=st.floats(1e-3, 10.0),
    model=st.sampled_from(["power-law", "dual-spring"]), method=st.sampled_from(["odeint", "verlet"]),
)  # fmt: skip
def test_short_runs_are_finite_and_conserve_energy(n_rings, n, speed, model, method):
    if model == "dual-spring":
        chain = Chain.dual_spring(n_rings, K_c=7.5e9, K_b=3.3e6, m=8.2e-3, a=0.04, support="free")
    else:
        chain = Chain.power_law(n_rings, K=4.9e6, n=n, m=8.2e-3, a=0.04, support="free")
    sim = simulate(chain, 2e-4, impact_velocity=speed, gravity=False, method=method, n_samples=51)
    assert np.all(np.isfinite(sim.contact_force))
    energy = sim.energy()
    # The run's own check (ENERGY_DRIFT_LIMIT) at the sample times: what it lets through is bounded.
    assert np.abs(energy.total - energy.total[0]).max() <= ENERGY_DRIFT_LIMIT * energy.kinetic[0]
