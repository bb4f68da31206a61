"""The sweep engine: grids, batches against single runs, determinism across executors, Dask."""

import csv
import importlib
import io
import math
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain.numerics import RunTooLargeError
from ringchain.numerics.cli.commands import main
from ringchain.numerics.jobs.sweep import (
    AXES,
    InlineExecutor,
    Point,
    default_t_end,
    expand,
    run_points,
    sweep,
    write_csv,
)
from ringchain.theory import Ring, fit_power_law, solitary_wave_speed

# The module (ringchain.numerics.sweep names the function).
sweep_module = importlib.import_module("ringchain.numerics.jobs.sweep")

# A short power-law chain read at rings 2 and 5: each run takes a few hundredths of a second.
SMALL = {"model": "power-law", "n_rings": 10, "sensors": (2, 5)}
GRID = {**SMALL, "R_over_r": [6.0, 9.0], "drop_height": [0.01, 0.05, 0.2]}


def read_csv(text):
    return list(csv.DictReader(io.StringIO(text)))


# -- grids and points ----------------------------------------------------------------------------
def test_expand_is_the_product_with_the_last_axis_fastest():
    points = expand({"model": ["power-law", "dual-spring"], "R_over_r": 6.0, "drop_height": [0.01, 0.02]})
    assert [(p.model, p.R_over_r, p.drop_height) for p in points] == [
        ("power-law", 6.0, 0.01), ("power-law", 6.0, 0.02), ("dual-spring", 6.0, 0.01), ("dual-spring", 6.0, 0.02),
    ]  # fmt: skip
    # A sensor pair is one value; a list of pairs is an axis.
    assert [p.sensors for p in expand({"sensors": (1, 4)})] == [(1, 4)]
    assert [p.sensors for p in expand({"sensors": [(1, 4), (2, 6)]})] == [(1, 4), (2, 6)]


def test_expand_takes_points_and_mappings():
    point = Point(R_over_r=5.5)
    assert expand([point, {"R_over_r": 6.0}]) == [point, Point(R_over_r=6.0)]


@pytest.mark.parametrize(
    ("grid", "message"),
    [
        ({"aspect": [6.0]}, "unknown sweep axis 'aspect'"),
        ({"R_over_r": []}, "axis 'R_over_r' has no values"),
        ({"R_over_r": 2.8, "drop_height": 0.01}, "cannot form a chain"),
        ({"R_over_r": 1.9}, "R must exceed 2 r"),
        ({"drop_height": -0.01}, "drop height must be positive"),
        ({"drop_height": 0.01, "impact_velocity": 1.0}, "not both"),
        ({"n_rings": 10, "drop_height": 0.01}, "sensor ring 12 is not in a chain of 10 rings"),
        ({"sensors": (5, 2)}, "near then far"),
        ({"model": "granular"}, "model must be one of"),
        ({"angle": math.radians(30.0)}, "single elliptical Hertz contact does not apply"),
        ({"m_eff_ratio": 1.5}, "m_eff_ratio must lie in (0, 1]"),
        ({"sensors": (6.5, 12)}, "sensor ring must be an integer, got 6.5"),  # was read as ring 6
        ({"sensors": 6}, "sensors must be two rings"),  # was "'int' object is not iterable"
        ({"n_rings": float("inf")}, "n_rings must be an integer, got inf"),  # was an OverflowError
        ({"drop_height": True}, "drop height must be a number (in m), got True"),  # was a 1 m drop
    ],
)
def test_bad_points_are_refused_with_the_reason(grid, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        expand(grid)


def test_a_single_contact_needs_no_chain():
    # R/r = 2.5 interlocks two rings (R > 2 r) but cannot hold two neighbours (R < 3 r):
    # its static theory is still a valid sweep point.
    (row,) = sweep({"R_over_r": 2.5}, InlineExecutor())
    assert row["n_fit"] == pytest.approx(Ring.from_aspect_ratio(2.5).power_law()[1], rel=1e-15)
    assert "peak_force_near_N" not in row


def test_axes_are_the_point_fields():
    assert set(AXES) >= {"R_over_r", "angle", "drop_height", "n_rings", "model"}


# -- rows and CSV ------------------------------------------------------------------------------------
def test_write_csv_round_trips_floats_and_unions_columns():
    rows = [{"a": 0.1 + 0.2, "b": None}, {"a": 1e-300, "c": "dual-spring", "n": np.int64(3)}]
    text = write_csv(rows)
    assert text.splitlines()[0] == "a,b,c,n"
    back = read_csv(text)
    assert float(back[0]["a"]) == 0.1 + 0.2  # shortest repr reads back to the same double
    assert float(back[1]["a"]) == 1e-300
    assert back[0]["b"] == back[0]["c"] == "" and back[1]["c"] == "dual-spring" and back[1]["n"] == "3"


def test_rows_hold_the_static_theory_and_the_sensor_readings():
    rows = sweep(GRID, InlineExecutor())
    grid_order = [(a, h) for a in (6.0, 9.0) for h in (0.01, 0.05, 0.2)]
    assert [(r["R_over_r"], r["drop_height_m"]) for r in rows] == grid_order
    for row in rows:
        ring = Ring.from_aspect_ratio(row["R_over_r"])
        assert row["K_c_N_m1.5"] == ring.K_c and row["K_b_N_m"] == ring.K_b
        assert row["impact_velocity_m_s"] == pytest.approx(math.sqrt(2 * 9.80665 * row["drop_height_m"]), rel=1e-15)
        assert 0 < row["arrival_near_s"] < row["arrival_far_s"] < row["t_end_s"]
        assert row["time_of_flight_s"] == pytest.approx(row["arrival_far_s"] - row["arrival_near_s"], rel=1e-12)
        assert row["wave_speed_m_s"] == pytest.approx(3 * ring.spacing / row["time_of_flight_s"], rel=1e-12)
    # A higher drop gives a larger, faster pulse (the hallmark of a nonlinear chain, Sec. III.A).
    for a in (0, 3):
        forces = [rows[a + k]["peak_force_near_N"] for k in range(3)]
        speeds = [rows[a + k]["wave_speed_m_s"] for k in range(3)]
        assert forces == sorted(forces) and speeds == sorted(speeds)


def test_a_tiny_drop_is_read_above_the_static_tension():
    """The sweep of the issue: R/r = 9, dual-spring, drops of 10 um and 0.1 mm.

    The 10 um pulse (1.8 N) rides on a static tension of 1.2 N at ring 6 and 2.5 N at ring 12;
    measured from zero, its time of flight was 2.10 ms against 0.59 ms at 0.1 mm (the far
    "pulse" was the reflection from the support).  A pulse this weak travels at about the
    linear sound speed of the hanging chain, a sqrt(k_t/m) with k_t the tangent stiffness of
    the series law (Eq. 3) at each contact's static tension: 0.596 ms from ring 6 to 12.
    """
    rows = sweep({"R_over_r": 9.0, "drop_height": [1e-5, 1e-4]}, InlineExecutor())
    tiny, small = (row["time_of_flight_s"] for row in rows)
    point = Point(R_over_r=9.0, drop_height=1e-5)
    chain = point.chain()
    tension = np.arange(6, 12) * chain.m_gravity * 9.80665  # contacts 6..11 carry rings 1..i (ring 0 is falling)
    k_t = 1.0 / (2.0 / 3.0 * tension ** (-1.0 / 3.0) * chain.K_c ** (-2.0 / 3.0) + 1.0 / chain.K_b)
    linear = np.sum(chain.a / (chain.a * np.sqrt(k_t / chain.m)))
    # The peak of a weak pulse lags the linear front by the lattice's dispersion (measured 4%).
    assert tiny == pytest.approx(linear, rel=0.1)
    assert small < tiny  # the stronger pulse is faster (amplitude-dependent speed, Sec. III.A)


def test_the_default_duration_stays_finite_as_n_tends_to_one():
    # R/r = 100: n = 1.0001 and the long-wave width ~ a/(n - 1) is 10^4 rings; the default
    # duration was 79 s of simulated time (2e8 Verlet steps for the dual-spring chain: hours).
    (row,) = sweep({**SMALL, "R_over_r": 100.0, "drop_height": 0.05, "sensors": (2, 5)}, InlineExecutor())
    # Now a few times the time the pulse takes to reach the far sensor (1.5 x its distance plus
    # half the chain's length over a speed estimate below the actual one).
    assert row["arrival_far_s"] < row["t_end_s"] < 5 * row["arrival_far_s"]
    chain = Point(R_over_r=100.0, drop_height=0.05).chain()
    assert default_t_end(chain, [1.0], (6, 12)) < 1.0  # s (was 78.9)


@settings(max_examples=8, deadline=None)  # each example derives a new ring (~0.4 s)
@given(aspect=st.floats(3.0, 1000.0), model=st.sampled_from(["power-law", "dual-spring"]),
       drop=st.floats(1e-6, 1.0), n_rings=st.integers(13, 200))  # fmt: skip
def test_the_default_duration_is_finite_over_the_admissible_range(aspect, model, drop, n_rings):
    point = Point(R_over_r=aspect, model=model, drop_height=drop, n_rings=n_rings)
    t_end = default_t_end(point.chain(), [point.speed], point.sensors)
    # Finite for every ring that forms a chain, from R/r = 3 (n ~ 1.4) to 1000 (n -> 1, where the
    # long-wave width diverges): at most 1.5 x 12 + n_rings/2 spacings at the estimated speed.
    assert np.isfinite(t_end) and t_end > 0


def test_a_sweep_with_a_task_too_long_is_refused_before_it_starts():
    # Dual-spring: R/r = 100 takes ~1 s compiled (its stiff contacts on soft rings: 10x the steps of R/r = 9).
    grid = {"R_over_r": [9.0, 100.0], "drop_height": 0.05}
    with pytest.raises(RunTooLargeError, match=r"largest task \(R/r = 100, dual-spring, 20 rings\) would take "
                                               r"roughly .* dopri5 steps .* max_seconds = 0.05 s"):  # fmt: skip
        sweep(grid, InlineExecutor(), max_seconds=0.05)


# -- batches against single runs -----------------------------------------------------------------------
def test_a_batch_gives_the_numbers_of_single_runs():
    # One Verlet step and one duration for both: each run of the batch then does the same
    # arithmetic as alone, on a wider array, so they agree to rounding (1e-12 relative).
    options = {"t_end": 1.5e-3, "dt": 2e-6}
    grid = {**SMALL, "model": ["power-law", "dual-spring"], "drop_height": [0.005, 0.02, 0.08, 0.3]}
    batched = sweep(grid, InlineExecutor(), **options)
    single = sweep(grid, InlineExecutor(), batch_size=1, **options)
    for b, s in zip(batched, single, strict=True):
        assert b.keys() == s.keys()
        for key, value in b.items():
            if isinstance(value, float):
                assert value == pytest.approx(s[key], rel=1e-12, abs=0.0), key
            else:
                assert value == s[key], key


def test_a_batch_with_an_adaptive_method_matches_single_runs():
    # LSODA shares its steps across the batch; every run is at least as accurate as its
    # own tolerance (rtol 1e-9, atol 1e-9 of the run's scales), so peaks and times agree
    # to well within 1e-6 relative (measured: below 1e-7).
    options = {"t_end": 1.5e-3, "method": "LSODA"}
    grid = {**SMALL, "drop_height": [0.01, 0.1]}
    batched = sweep(grid, InlineExecutor(), **options)
    single = sweep(grid, InlineExecutor(), batch_size=1, **options)
    for b, s in zip(batched, single, strict=True):
        for key in ("peak_force_near_N", "peak_force_far_N", "time_of_flight_s"):
            assert b[key] == pytest.approx(s[key], rel=1e-6), key


@pytest.mark.parametrize("model", ["power-law", "dual-spring"])
def test_a_batchs_rows_are_its_runs_read_one_at_a_time(model):
    # The rows read every run's sensors at once (signals.peak on the batch's traces).  The runs of a batch take their
    # own steps, so simulating them again and reading each run alone (one Simulation, one trace at a time) must give
    # the same numbers exactly; Eq. (8) evaluated on the batch's array of forces may differ from its scalar call
    # in the last bit only (a vectorised power), so 1e-15 relative.
    from ringchain.numerics import simulate_batch
    from ringchain.numerics.jobs.sweep import DEFAULT_SAMPLES, SWEEP_RTOL

    points = expand({**SMALL, "model": model, "drop_height": [0.004, 0.03, 0.3]})
    rows = run_points(points)
    near, far = SMALL["sensors"]
    runs = simulate_batch(points[0].chain(), rows[0]["t_end_s"], drop_heights=[p.drop_height for p in points],
                          rtol=SWEEP_RTOL, n_samples=DEFAULT_SAMPLES,
                          rings=(near, far, SMALL["n_rings"] - 1))  # fmt: skip
    for row, run in zip(rows, runs, strict=True):
        assert row["peak_force_near_N"] == run.peak_force(near) and row["peak_force_far_N"] == run.peak_force(far)
        assert row["arrival_near_s"] == run.arrival_time(near) and row["arrival_far_s"] == run.arrival_time(far)
        assert row["time_of_flight_s"] == run.time_of_flight(near, far)
        assert row["wave_speed_m_s"] == run.wave_speed(near, far)
        assert row["support_peak_N"] == float(np.max(run.support_force))
        chain = run.chain
        K, n = (chain.K, chain.n) if model == "power-law" else fit_power_law(K_c=chain.K_c, K_b=chain.K_b)
        V_s = float(solitary_wave_speed(run.peak_force(near), K=float(K), n=float(n), a=chain.a, m=chain.m))
        assert row["V_s_theory_m_s"] == pytest.approx(V_s, rel=1e-15, abs=0.0)


def test_run_points_refuses_points_of_different_chains():
    with pytest.raises(ValueError, match="share one chain"):
        run_points(expand({**SMALL, "R_over_r": [6.0, 9.0], "drop_height": 0.01}))


def test_a_short_default_duration_is_doubled_until_the_pulse_has_passed(monkeypatch):
    monkeypatch.setattr(sweep_module, "default_t_end", lambda *args: 1e-4)
    (row,) = run_points(expand({**SMALL, "drop_height": 0.05}))
    assert row["t_end_s"] in (2e-4, 4e-4, 8e-4, 16e-4)
    assert row["arrival_far_s"] < row["t_end_s"]


def test_a_given_duration_that_ends_inside_the_pulse_is_an_error():
    with pytest.raises(ValueError, match="give a longer t_end"):
        sweep({**SMALL, "drop_height": 0.05}, InlineExecutor(), t_end=1e-4)


def test_sweep_options_are_checked():
    with pytest.raises(ValueError, match="progress must be True or False, got 'no'"):  # was read as True
        sweep({"R_over_r": 9.0}, InlineExecutor(), progress="no")
    with pytest.raises(ValueError, match="batch_size must be a positive integer, got inf"):  # an OverflowError
        sweep({"R_over_r": 9.0}, InlineExecutor(), batch_size=float("inf"))
    with pytest.raises(TypeError, match="a grid is a mapping of axes or an iterable of points, got 5"):
        expand(5)


# -- executors and determinism -------------------------------------------------------------------------
@pytest.fixture(scope="module")
def reference_csv():
    return write_csv(sweep(GRID, InlineExecutor(), batch_size=2))


def test_same_grid_same_csv_with_threads_and_local_processes(reference_csv):
    # batch_size=2 splits each chain's three drops into two tasks: tasks finish out of order.
    with ThreadPoolExecutor(2) as pool:
        assert write_csv(sweep(GRID, pool, batch_size=2)) == reference_csv
    assert write_csv(sweep(GRID, batch_size=2, max_workers=2)) == reference_csv  # default: local processes


@pytest.mark.slow
def test_same_grid_same_csv_on_a_dask_cluster(reference_csv, tmp_path, capsys):
    from distributed import Client, LocalCluster

    argv = ["sweep", "--model", "power-law", "--rings", str(SMALL["n_rings"]), "--sensors", "2", "5",
            "--R-over-r", "6", "9", "--drop-height", "0.01", "0.05", "0.2", "--batch-size", "2"]  # fmt: skip
    # ":0": a free port for the HTTP server (8787, the default, clashes with another test's cluster).  One worker
    # process: the results travel through Dask as with many (that they do not depend on the number of workers
    # is test_same_grid_same_csv_with_threads_and_local_processes); each worker costs ~5 s of CPU to start.
    with (
        LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster,
        Client(cluster) as client,
    ):
        assert len(client.scheduler_info()["workers"]) == 1
        rows = sweep(GRID, client.get_executor(), batch_size=2)  # the one-line change for a cluster
        # The command line's --dask: the same grid, through a client of its own.
        assert main([*argv, "--dask", cluster.scheduler_address, "--out", str(tmp_path / "dask.csv")]) == 0
    assert write_csv(rows) == reference_csv
    assert (tmp_path / "dask.csv").read_text() == reference_csv
    assert "6 rows written" in capsys.readouterr().out


def test_progress_bar_only_when_asked(capsys):
    sweep({"R_over_r": [6.0, 9.0]}, InlineExecutor(), progress=True)
    assert "2/2" in capsys.readouterr().err
    sweep({"R_over_r": [6.0, 9.0]}, InlineExecutor(), progress=False)
    assert capsys.readouterr().err == ""
