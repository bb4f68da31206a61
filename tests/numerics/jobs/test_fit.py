"""From measurements to parameters: readers, quasi-static, speed-amplitude and trace fits.

Synthetic measurements are made by :func:`ringchain.numerics.simulate` at known parameters
(at rtol 1e-10 and at the measured sample times, a different path from the fit's own
forward model), with seeded Gaussian noise, a trigger offset and DC offsets.
"""

from __future__ import annotations

import codecs
import dataclasses
import json
import subprocess
import sys

import numpy as np
import pytest
from ringchain.numerics import (
    STANDARD_GRAVITY,
    DataError,
    FitError,
    Network,
    Simulation,
    fit_speed_amplitude,
    fit_static,
    fit_traces,
    paper_chain,
    read_speed_amplitude,
    read_static,
    read_traces,
    simulate,
    simulate_batch,
)
from ringchain.numerics.jobs.fit_dynamic import FIT_RTOL, simulate_parameter_sets
from ringchain.theory import Ring, series_displacement, solitary_wave_speed

#: The paper's chain (Table I, R/r = 9) with a contact dashpot of about 3 % of critical damping
#: (sqrt(m k) ~ 100 N s/m on the tangent stiffness at 30 N): enough to show in the traces.
TRUTH = dataclasses.replace(paper_chain("power-law"), gamma=3.0)


def measured(chain, h, t, t0, *, noise, offsets, seed, rings=(6, 12)):
    """Sensor traces of a drop from height h, read on the clock t with the impact at t0: noise is
    Gaussian with a standard deviation of ``noise`` times the peak, ``offsets`` are DC offsets (N)."""
    rng = np.random.default_rng(seed)
    tau = t - t0
    after = tau >= 0
    sim = simulate(chain, tau[-1], drop_height=h, t_eval=tau[after], rtol=1e-10)
    peak = max(sim.sensor(k).max() for k in rings)
    traces = {}
    for k, offset in zip(rings, offsets, strict=True):
        y = np.full(t.size, sim.sensor(k)[0])  # before the impact the chain hangs at rest
        y[after] = sim.sensor(k)
        traces[k] = y + offset + noise * peak * rng.standard_normal(t.size)
    return traces


def write_csv(path, t, traces, comment=None):
    columns = {"t_s": t, **{f"sensor_ring{k}_N": y for k, y in traces.items()}}
    lines = [] if comment is None else [f"# {comment}"]
    lines.append(",".join(columns))
    lines += [",".join(repr(float(x)) for x in row) for row in zip(*columns.values(), strict=True)]
    path.write_text("\n".join(lines) + "\n")
    return path


# -- reading data ---------------------------------------------------------------------------------------
T = np.linspace(0.0, 1e-3, 40)
PULSE = {6: np.exp(-(((T - 3e-4) / 5e-5) ** 2)), 12: 0.2 + 0.8 * np.exp(-(((T - 6e-4) / 5e-5) ** 2))}


def test_read_traces_reads_what_simulate_writes(tmp_path):
    from ringchain.numerics.cli.commands import main

    path = tmp_path / "run.csv"
    assert main(["simulate", "--model", "power-law", "--drop-height", "0.01", "--samples", "301", "--out",
                 str(path)]) == 0  # fmt: skip
    t, traces = read_traces(path)
    assert list(traces) == [6, 12] and t.size == 301 and t[0] == 0.0
    assert all(y.shape == t.shape for y in traces.values())


def test_read_traces_accepts_comments_other_columns_and_uneven_sampling(tmp_path):
    t = np.sort(np.random.default_rng(0).uniform(0.0, 1e-3, 60))
    y = 1.5 + np.exp(-(((t - 5e-4) / 8e-5) ** 2))  # a DC offset of 1.5 N
    path = tmp_path / "scope.csv"
    path.write_text("# scope export\n\ntemperature_C,t_s,sensor_ring3_N\n"
                    + "".join(f"21.0,{float(a)!r},{float(b)!r}\n" for a, b in zip(t, y, strict=True)))  # fmt: skip
    t_read, traces = read_traces(path)
    np.testing.assert_array_equal(t_read, t)
    np.testing.assert_array_equal(traces[3], y)


@pytest.mark.parametrize(
    ("edit", "expected"),
    [
        (lambda lines: [lines[0].replace("t_s", "time"), *lines[1:]], ["missing column", "t_s", "line 1"]),
        (lambda lines: ["t_s,force"] + [",".join(r.split(",")[:2]) for r in lines[1:]], ["sensor_ring<k>_N"]),
        (lambda lines: [*lines[:6], lines[4], *lines[7:]], ["time does not increase", "line 7", "column 1 (t_s)"]),
        (
            lambda lines: [*lines[:9], lines[9].rsplit(",", 1)[0] + ",nan", *lines[10:]],
            ["line 10", "column 3 (sensor_ring12_N)", "not a finite number: 'nan'"],
        ),
        (lambda lines: [*lines[:9], lines[9].rsplit(",", 1)[0], *lines[10:]], ["line 10", "column 3", "no value"]),
        (lambda lines: lines[:8], ["7 samples; at least 10"]),
        (
            lambda lines: [lines[0]] + [r.rsplit(",", 1)[0] + ",0.25" for r in lines[1:]],
            ["column 3 (sensor_ring12_N)", "no pulse"],
        ),
    ],
    ids=["missing-time", "no-sensor", "time-backwards", "nan", "short-row", "too-few", "no-pulse"],
)
def test_read_traces_says_what_is_wrong_and_where(tmp_path, edit, expected):
    lines = write_csv(tmp_path / "good.csv", T, PULSE).read_text().splitlines()
    path = tmp_path / "bad.csv"
    path.write_text("\n".join(edit(lines)) + "\n")
    with pytest.raises(DataError) as info:
        read_traces(path)
    message = str(info.value)
    assert message.startswith(str(path)), message
    for part in expected:
        assert part in message, message


@pytest.mark.parametrize(
    "header",
    ["t_s,sensor_ring6_N,sensor_ring12_kN", "t_s,sensor_ring6_N,Sensor_Ring12_N", "t_s,sensor_ring6_N,sensor_ring12",
     "t_s,sensor_ring6_N,sensor_ring-1_N", "t_s,sensor_ring6_N,ring12_N"],
)  # fmt: skip
def test_read_traces_refuses_columns_that_almost_name_a_sensor(tmp_path, header):
    # Issue 24, item 6: such a column was ignored and the fit ran on one channel.
    path = tmp_path / "near.csv"
    path.write_text(header + "\n" + "".join(f"{t},{a},{b}\n" for t, a, b in zip(T, PULSE[6], PULSE[12],
                                                                                     strict=True)))  # fmt: skip
    bad = header.split(",")[-1]
    with pytest.raises(DataError, match=rf"line 1, column 3 \({bad}\): looks like a sensor column but is not named "
                                        r"sensor_ring<k>_N"):  # fmt: skip
        read_traces(path)


@pytest.mark.parametrize(
    ("header", "message"),
    [("t_s,sensor_ring6_N,sensor_ring6_N", r"column 'sensor_ring6_N' appears 2 times \(columns 2, 3\)"),
     ("t_s,t_s,sensor_ring6_N", r"column 't_s' appears 2 times \(columns 1, 2\)"),
     ("t_s,sensor_ring6_N,sensor_ring06_N", r"columns 2 \(sensor_ring6_N\) and 3 \(sensor_ring06_N\) are both the "
      "sensor of ring 6")],
)  # fmt: skip
def test_read_traces_refuses_a_column_given_twice(tmp_path, header, message):
    # Issue 24, item 6: the second of two equal columns was ignored.
    path = tmp_path / "twice.csv"
    path.write_text(header + "\n" + "".join(f"{t},{a},{a}\n" for t, a in zip(T, PULSE[6], strict=True)))
    with pytest.raises(DataError, match=message):
        read_traces(path)


@pytest.mark.parametrize(
    "encode",
    [lambda text: text.encode("utf-8-sig"), lambda text: text.encode("utf-16"),
     lambda text: codecs.BOM_UTF16_BE + text.encode("utf-16-be")],
    ids=["utf-8-bom", "utf-16", "utf-16-be-bom"],
)  # fmt: skip
def test_data_files_in_excel_encodings_are_read(tmp_path, encode):
    # Issue 24, item 15: Excel's "CSV UTF-8" starts with a byte-order mark (it became part of the first
    # column's name: "missing column"); "Unicode text" is UTF-16 with one.
    text = "# \u00b5m and \u00b0C\ndisplacement_m,force_N\n" + "".join(f"{i * 1e-6},{i * 0.5}\n" for i in range(1, 13))
    plain, excel = tmp_path / "plain.csv", tmp_path / "excel.csv"
    plain.write_text(text, encoding="utf-8")
    excel.write_bytes(encode(text))
    for a, b in zip(read_static(excel), read_static(plain), strict=True):
        np.testing.assert_array_equal(a, b)


def test_a_file_that_is_not_utf8_is_refused_naming_file_line_and_byte(tmp_path):
    # Issue 24, item 15: a Latin-1 file gave "'utf-8' codec can't decode byte 0xb5 in position 21", no file.
    path = tmp_path / "latin.csv"
    path.write_bytes("displacement_m,force_N\n# Weg in \u00b5m\n".encode("latin-1"))
    with pytest.raises(
        DataError, match=rf"^{path}, line 2: byte 10 \(0xb5\) is not UTF-8 text .*save the file as UTF-8"
    ):
        read_static(path)


def test_a_static_file_whose_displacement_never_changes_is_refused(tmp_path):
    # Issue 24, item 15: it exited 0 with n at its bound, after NumPy's RankWarning.
    path = tmp_path / "stuck.csv"
    path.write_text("displacement_m,force_N\n" + "".join(f"1e-05,{i * 0.5}\n" for i in range(1, 13)))
    with pytest.raises(DataError, match=r"column 1 \(displacement_m\): the same value, 1e-05 m, on every row"):
        read_static(path)
    with pytest.raises(ValueError, match=r"displacement takes one value, 1e-05 m, at every sample"):
        fit_static(np.full(12, 1e-5), np.arange(1.0, 13.0))


def test_read_static_and_speed_files(tmp_path):
    path = tmp_path / "static.csv"
    path.write_text("# tensile test\ndisplacement_m,force_N\n" + "".join(f"{i * 1e-6},{i * 0.5}\n" for i in range(12)))
    delta, force = read_static(path)
    assert delta.size == 12 and force[-1] == 5.5
    path.write_text("force_N\n" + "".join(f"{i}\n" for i in range(12)))
    with pytest.raises(DataError, match=r"missing column.*displacement_m, force_N"):
        read_static(path)
    sweep_like = tmp_path / "sweep.csv"
    sweep_like.write_text("peak_force_near_N,wave_speed_m_s,other\n" + "".join(f"{i + 1},{100 + i},x\n"
                                                                              for i in range(10)))  # fmt: skip
    F, V = read_speed_amplitude(sweep_like)
    assert F[0] == 1.0 and V[-1] == 109.0


# -- quasi-static -----------------------------------------------------------------------------------------
RING = Ring.from_aspect_ratio(9.0)
K_TABLE, N_TABLE = TRUTH.K, TRUTH.n  # Table I: 2284 N/mm^n, n = 1.11
DELTA = np.linspace(1e-6, 3e-5, 60)  # m: 1 to 50 N on the Table I law


def test_static_fits_recover_exact_laws_with_and_without_offset():
    for offset in (0.0, 4e-7):
        F = K_TABLE * DELTA**N_TABLE
        fit = fit_static(DELTA + offset, F, "power-law", offset=bool(offset))
        # Exact data: only the least squares' own tolerance (ftol, xtol 1e-8) remains.
        assert fit.values["n"] == pytest.approx(N_TABLE, rel=1e-6)
        assert fit.values["K"] == pytest.approx(K_TABLE, rel=1e-5)
        if offset:
            assert fit.values["delta0"] == pytest.approx(offset, rel=1e-4)
        F = np.linspace(1.0, 100.0, 40)
        fit = fit_static(series_displacement(F, K_c=RING.K_c, K_b=RING.K_b) + offset, F, "series", offset=bool(offset))
        assert fit.values["K_c"] == pytest.approx(RING.K_c, rel=1e-5)
        assert fit.values["K_b"] == pytest.approx(RING.K_b, rel=1e-6)


def test_static_information_criterion_tells_the_laws_apart():
    rng = np.random.default_rng(3)
    F = np.linspace(1.0, 100.0, 60)
    delta = series_displacement(F, K_c=RING.K_c, K_b=RING.K_b)
    noisy = F + 0.2 * rng.standard_normal(F.size)  # 0.2 % of the largest force
    power, series = fit_static(delta, noisy, "power-law"), fit_static(delta, noisy, "series")
    # The series law generated the data: its AIC and BIC are lower by far more than the ~2 that
    # would be chance between two laws with two parameters each.
    assert series.aic < power.aic - 10 and series.bic < power.bic - 10
    assert series.values["K_c"] == pytest.approx(RING.K_c, abs=4 * series.stderr["K_c"])
    power_law_data = K_TABLE * DELTA**N_TABLE + 0.05 * rng.standard_normal(DELTA.size)
    assert fit_static(DELTA, power_law_data, "power-law").aic < fit_static(DELTA, power_law_data, "series").aic - 10


@pytest.mark.parametrize("offset", [False, True])
def test_static_95_percent_intervals_cover_the_truth(offset):
    rng = np.random.default_rng(11)
    truth = {"K": K_TABLE, "n": N_TABLE, "delta0": 0.0}
    hits = dict.fromkeys(truth, 0)
    replicates = 300
    for _ in range(replicates):
        force = K_TABLE * DELTA**N_TABLE + 0.3 * rng.standard_normal(DELTA.size)  # 0.3 N on forces up to 50 N
        fit = fit_static(DELTA, force, "power-law", offset=offset)
        for name in fit.names:
            low, high = fit.intervals[name]
            hits[name] += low <= truth[name] <= high
    # 95 % intervals over 300 replicates: the binomial standard deviation is 1.3 %, so 90-99 % is
    # -3.9 to +3.2 sigma around 95 % (the linearised intervals of a nonlinear fit may be a little off).
    for name in fit.names:
        assert 0.90 <= hits[name] / replicates <= 0.99, (name, hits[name])


def test_static_fit_that_cannot_converge_says_so():
    force = K_TABLE * DELTA**N_TABLE
    with pytest.raises(FitError, match="did not converge after 2 evaluations"):
        fit_static(DELTA, force, "power-law", start={"K": 1.0, "n": 3.0}, max_nfev=2)
    # From K = 1 N/m^3 the model is ~1e-15 N everywhere, its gradient vanishes and the least
    # squares stop "successfully" where they started: refused, not returned.
    with pytest.raises(FitError, match="explains none of the data"):
        fit_static(DELTA, force, "power-law", start={"K": 1.0, "n": 3.0})


def test_static_rejects_bad_input():
    with pytest.raises(ValueError, match="model must be one of"):
        fit_static(DELTA, DELTA, "cubic")
    with pytest.raises(ValueError, match="same length"):
        fit_static(DELTA, DELTA[:-1])
    with pytest.raises(ValueError, match="at least 10"):
        fit_static(DELTA[:5], DELTA[:5])


# -- speed against amplitude ----------------------------------------------------------------------------
def test_speed_amplitude_recovers_m_eff_and_n():
    F = np.geomspace(2.0, 150.0, 15)
    m0 = RING.mass
    V = solitary_wave_speed(F, K=K_TABLE, n=N_TABLE, m=0.37 * m0, a=RING.spacing)
    fit = fit_speed_amplitude(F, V, K=K_TABLE, n=N_TABLE, a=RING.spacing, m0=m0, start=0.6)
    assert fit.values["m_eff_ratio"] == pytest.approx(0.37, rel=1e-7)  # exact data: solver tolerance
    # V^2 is proportional to 1/m_eff at fixed F: a speed 1 % too high means m_eff 2 % too low.
    fit = fit_speed_amplitude(F, 1.01 * V, K=K_TABLE, n=N_TABLE, a=RING.spacing, m0=m0)
    assert fit.values["m_eff_ratio"] == pytest.approx(0.37 / 1.01**2, rel=1e-6)
    noisy = V * (1.0 + 0.01 * np.random.default_rng(5).standard_normal(F.size))
    fit = fit_speed_amplitude(F, noisy, K=K_TABLE, n=1.3, a=RING.spacing, m0=m0, free_n=True)
    assert fit.names == ("m_eff_ratio", "n")
    assert fit.values["n"] == pytest.approx(N_TABLE, abs=4 * fit.stderr["n"])
    assert fit.values["m_eff_ratio"] == pytest.approx(0.37, abs=4 * fit.stderr["m_eff_ratio"])
    assert fit.fixed["K"] == K_TABLE and "n" not in fit.fixed


# -- sensor traces ---------------------------------------------------------------------------------------
CLOCK = np.linspace(-0.1e-3, 1.4e-3, 1000)  # s: 0.1 ms of pre-trigger, the pulse past ring 12
T0 = 4e-5  # s: the impact 40 us after the trigger
OFFSETS = (0.3, -0.2)  # N: DC offsets of the two channels
START = dataclasses.replace(TRUTH, m=1.3 * TRUTH.m, gamma=0.6 * TRUTH.gamma)  # 30 % and 40 % off


@pytest.fixture(scope="module")
def noise_fits():
    fits = {}
    for noise in (0.0, 0.01, 0.05):
        traces = measured(TRUTH, 0.02, CLOCK, T0, noise=noise, offsets=OFFSETS, seed=101)
        fits[noise] = fit_traces(CLOCK, traces, START, drop_height=0.02, free=("m", "gamma", "t0"))
    return fits


@pytest.mark.parametrize("noise", [0.0, 0.01, 0.05])
def test_trace_fit_recovers_the_chain_within_a_tolerance_that_scales_with_the_noise(noise_fits, noise):
    fit = noise_fits[noise]
    truth = {"m": TRUTH.m, "gamma": TRUTH.gamma, "t0": T0, "offset_ring6": OFFSETS[0], "offset_ring12": OFFSETS[1]}
    # Noise-free floor: the fit's forward model (FIT_RTOL, spline on the sample grid) against the
    # data's (rtol 1e-10 at the samples) differ by ~1e-6 of the peak; measured errors without noise
    # were 1e-6 (m), 2e-5 (gamma), 0.2 ns (t0), 6e-6 N: these floors leave a factor 10.
    floor = {"m": 1e-5 * TRUTH.m, "gamma": 2e-4 * TRUTH.gamma, "t0": 2e-9, "offset_ring6": 1e-4,
             "offset_ring12": 1e-4}  # fmt: skip
    for name, value in truth.items():
        # With noise the tolerance is 4 standard errors, and the standard error is proportional to
        # the noise (checked below): a 4-sigma band fails once in 16000 honest fits.
        assert fit.values[name] == pytest.approx(value, abs=4 * fit.stderr[name] + floor[name]), name
    assert fit.chain.m == fit.values["m"] and fit.chain.gamma == fit.values["gamma"]
    assert fit.chain.K == TRUTH.K and fit.fixed["K"] == TRUTH.K  # held fixed
    assert fit.residual.shape == (2 * CLOCK.size,) and not fit.notes


def test_trace_fit_standard_errors_scale_with_the_noise(noise_fits):
    # Same noise draw, five times larger: the linearised standard errors scale by 5 (to the 10 %
    # the fit's own scatter and the data's nonlinearity leave).
    for name in ("m", "gamma", "t0"):
        ratio = noise_fits[0.05].stderr[name] / noise_fits[0.01].stderr[name]
        assert ratio == pytest.approx(5.0, rel=0.1), name


def test_trace_fit_is_fast_in_forward_runs(noise_fits):
    # Alignment (a few runs) and about six to ten Jacobians of three runs each: the count, not a time,
    # is what a test can hold (benchmarks/bench_fit.py times it).  Measured 21, 25 and 41 runs at 0, 1 and
    # 5 % noise since the least squares solve in scaled parameters (fit.minimize), whose step tolerance
    # is relative to every parameter, not to the largest in SI units (21, 22 and 36 before).
    for fit in noise_fits.values():
        assert fit.n_forward_runs <= 45
        assert fit.n_batches < fit.n_forward_runs  # the Jacobian's runs went as one batch


def test_trace_jacobian_matches_central_differences_column_by_column():
    # Issue 24, item 16: dividing every record's v0 column by the first record's step left the fitted values right
    # but scaled each record's v0 standard error by v0_first/v0_r.  Three drops (5, 20, 80 mm: speeds 0.31 to
    # 1.25 m/s), each column of the batched Jacobian against central differences of the residual.
    import lmfit
    from ringchain.numerics.jobs.fit_dynamic import _records, _TraceProblem
    from ringchain.theory import impact_speed

    chain = paper_chain("power-law")
    clock = np.linspace(-0.1e-3, 1.4e-3, 600)
    heights = (0.005, 0.02, 0.08)
    data = [(clock, measured(chain, h, clock, 4e-5, noise=0.0, offsets=(0.3, -0.2), seed=1), h) for h in heights]
    records = _records(None, data, chain, None, None)
    problem = _TraceProblem(records, chain, ("m", "t0", "v0"), t0=[0.0] * 3, offsets=True, rtol=FIT_RTOL,
                            gravity=True, batched=True)  # fmt: skip
    values = {"m": 1.1 * chain.m}  # away from the solution: a Jacobian anywhere, not only where the residual is 0
    for r, h in enumerate(heights):
        values[f"t0_{r}"], values[f"v0_{r}"] = 3e-5, 0.95 * float(impact_speed(h))
    values |= dict.fromkeys(problem.offset_names(), 0.1)
    params = lmfit.Parameters()
    for name, value in values.items():
        params.add(name, value=value)
    jacobian = problem.jacobian(params)
    for j, name in enumerate(params):
        step = 1e-4 * abs(values[name])
        up = problem.residual_of({**values, name: values[name] + step})
        down = problem.residual_of({**values, name: values[name] - step})
        central = (up - down) / (2 * step)
        error = np.linalg.norm(jacobian[:, j] - central) / np.linalg.norm(central)
        # Forward differences at JACOBIAN_STEP = 1e-4 against central ones: measured 4e-4 (m) and 4e-4 to 2e-3 (v0);
        # t0 from the spline's slope against differences of the spline: up to 1e-2; offsets exact (rounding, 1e-10).
        tolerance = {"m": 1e-2, "v0": 1e-2, "t0": 3e-2}.get(name.split("_")[0], 1e-8)
        assert error < tolerance, (name, error)


def test_forward_model_batched_agrees_with_one_run_at_a_time():
    chains = [TRUTH, dataclasses.replace(TRUTH, m=1.01 * TRUTH.m), dataclasses.replace(TRUTH, gamma=0.0)]
    speeds = np.array([[0.6, 1.0], [0.6, 1.0], [0.62, 1.0]])
    t = np.linspace(0.0, 1.4e-3, 700)
    rings = [(6, 12), (3,)]
    batched = simulate_parameter_sets(chains, speeds, [True, False], t, rings)
    single = simulate_parameter_sets(chains, speeds, [True, False], t, rings, batched=False)
    converged = simulate_parameter_sets(chains, speeds, [True, False], t, rings, batched=False, rtol=1e-11)
    for b, s, c in zip(batched, single, converged, strict=True):
        peak = np.abs(c).max()
        # At FIT_RTOL = 1e-9 both are within ~5e-7 of the peak of the converged forces (measured);
        # 2e-6 is the accuracy FIT_RTOL documents, with a margin.
        assert np.abs(s - c).max() < 2e-6 * peak
        assert np.abs(b - c).max() < 2e-6 * peak
    # Each run is the chain simulate() integrates: ring 3 of record 1 (an impact from equilibrium).
    sim = simulate(chains[2], t[-1], impact_velocity=1.0, t_eval=t, rtol=FIT_RTOL)
    np.testing.assert_allclose(batched[1][2, 0], sim.sensor(3), atol=2e-6 * np.abs(sim.sensor(3)).max())


def test_forward_model_reads_the_batch_as_each_run_read_alone():
    # The forward model records the sensors' sites only and reads every run's sensors in one pass over the stacked
    # batch; the same batch read run by run, every site recorded, as a Simulation of each chain (the reading the
    # one-pass path replaced) must give the same forces.  Each force is the same elementwise arithmetic on the same
    # states; 1e-15 of the peak allows a last bit from NumPy's vector loops over arrays of other shapes.
    chains = [TRUTH, dataclasses.replace(TRUTH, m=1.01 * TRUTH.m), dataclasses.replace(TRUTH, gamma=0.0)]
    speeds = np.array([[0.6, 1.0], [0.6, 1.0], [0.62, 1.0]])
    dropped = [True, False]
    t = np.linspace(0.0, 1.4e-3, 700)
    rings = [(6, 12), (3,)]
    batched = simulate_parameter_sets(chains, speeds, dropped, t, rings)
    runs = [(chain, r) for chain in chains for r in range(2)]
    states = [chain.impact_state(np.array([speed]), dropped[r], True, STANDARD_GRAVITY)
              for (chain, r), speed in zip(runs, speeds.ravel(), strict=True)]  # fmt: skip
    batch = simulate_batch(Network.stack([chain.network() for chain, _ in runs]), t[-1], t_eval=t, rtol=FIT_RTOL,
                           atol=FIT_RTOL, initial=(np.concatenate([x for x, _ in states]),
                                                   np.concatenate([u for _, u in states])),
                           shared_steps=True, max_energy_drift=None)  # fmt: skip
    for b, (chain, r) in enumerate(runs):
        sim = Simulation(t=t, x=batch.x[b], u=batch.u[b], dissipated=batch.dissipated[b], g=batch.g, chain=chain)
        expected = sim.sensor_force[:, list(rings[r])].T
        np.testing.assert_allclose(batched[r][b // 2], expected, rtol=0, atol=1e-15 * np.abs(expected).max())
    # One run alone (the residual's): recorded at its sensors only, against every site recorded.
    alone = simulate_parameter_sets(chains[:1], speeds[:1, :1], dropped[:1], t, rings[:1])
    x, u = chains[0].impact_state(speeds[0, :1], True, True, STANDARD_GRAVITY)
    sim = simulate(chains[0], t[-1], initial=(x, u), t_eval=t, rtol=FIT_RTOL, atol=FIT_RTOL, max_energy_drift=None)
    expected = sim.sensor_force[:, [6, 12]].T
    np.testing.assert_allclose(alone[0][0], expected, rtol=0, atol=1e-15 * np.abs(expected).max())


def test_power_law_chain_has_the_scaling_symmetry_behind_eq_8():
    """m/alpha, K/alpha^n, gamma/alpha hit at alpha v0: the same sensor forces (gravity included)."""
    alpha = 1.3
    scaled = dataclasses.replace(TRUTH, m=TRUTH.m / alpha, K=TRUTH.K / alpha**TRUTH.n, gamma=TRUTH.gamma / alpha)
    t = np.linspace(0.0, 1.4e-3, 500)
    a = simulate(TRUTH, t[-1], drop_height=0.02, t_eval=t, rtol=1e-11)
    b = simulate(scaled, t[-1], drop_height=0.02 * alpha**2, t_eval=t, rtol=1e-11)
    # Exact symmetry: the difference is the solver's (rtol 1e-11 -> ~1e-9 of the peak, measured).
    np.testing.assert_allclose(b.sensor_force, a.sensor_force, atol=1e-7 * np.abs(a.sensor_force).max())
    # It moves along K^(1/n)/m = const, the only combination Eq. (8) depends on.
    assert scaled.K ** (1 / scaled.n) / scaled.m == pytest.approx(TRUTH.K ** (1 / TRUTH.n) / TRUTH.m, rel=1e-12)


HEIGHT_OFFSET = 1e-3  # m: every true free fall is 1 mm longer than the nominal height
DROPS = ((0.005, 2e-5), (0.02, 5e-5), (0.08, -3e-5))  # nominal height (m), impact time on the clock (s)
CHAIN_START = dataclasses.replace(TRUTH, m=1.3 * TRUTH.m, K=0.7 * TRUTH.K)


def drop_records():
    clocks = [np.linspace(-0.05e-3, 1.35e-3, 700), None, np.linspace(-0.05e-3, 1.35e-3, 700)]
    rng = np.random.default_rng(21)
    clocks[1] = np.sort(rng.uniform(-0.05e-3, 1.35e-3, 700))  # uneven sampling
    return [
        (clock, measured(TRUTH, h + HEIGHT_OFFSET, clock, t0, noise=0.01, offsets=OFFSETS, seed=i), h)
        for i, (clock, (h, t0)) in enumerate(zip(clocks, DROPS, strict=True))
    ]


@pytest.mark.slow
def test_one_drop_leaves_m_and_K_correlated_three_drops_separate_them():
    records = drop_records()
    free = ("m", "K", "h0", "t0")
    t, traces, h = records[1]
    one = fit_traces(t, traces, CHAIN_START, drop_height=h, free=free)
    # One drop: the height offset trades against m and K along K^(1/n)/m = const (the symmetry
    # above, broken only by the fixed dashpot).
    assert abs(one.corr("m", "K")) > 0.9
    three = fit_traces(None, records, CHAIN_START, free=free)
    # Three heights: sqrt(h_i + h0) cannot follow one common factor, so m and K come apart.
    assert abs(three.corr("m", "K")) < 0.9
    assert three.stderr["m"] < one.stderr["m"] / 10
    for name, value in (("m", TRUTH.m), ("K", TRUTH.K), ("h0", HEIGHT_OFFSET)):
        # 1 % noise; 4 standard errors (see the recovery test) plus 1e-4 for the model's floor.
        assert three.values[name] == pytest.approx(value, abs=4 * three.stderr[name] + 1e-4 * abs(value)), name
    assert [name for name in three.names if name.startswith("t0")] == ["t0_0", "t0_1", "t0_2"]
    for r, (h, t0) in enumerate(DROPS):
        assert three.values[f"t0_{r}"] == pytest.approx(t0, abs=4 * three.stderr[f"t0_{r}"] + 2e-9)
        assert three.records[r].drop_height == h
        assert three.records[r].v0 == pytest.approx(np.sqrt(2 * 9.80665 * (h + three.values["h0"])), rel=1e-12)


@pytest.mark.slow
def test_an_exact_symmetry_is_reported_as_not_identifiable_never_with_error_bars():
    """With the dashpot free, m, K, gamma and the impact speeds follow the symmetry exactly: whatever the
    number of drops if each has its own speed, with one drop if the heights share an unknown zero."""
    records = drop_records()
    t, traces, h = records[1]
    start = dataclasses.replace(CHAIN_START, gamma=1.0)
    one = fit_traces(t, traces, start, drop_height=h, free=("m", "K", "gamma", "h0", "t0"))
    two = fit_traces(None, records[1:], start, free=("m", "K", "gamma", "v0", "t0"))  # any number: take two
    for fit, speeds in ((one, ["h0"]), (two, ["v0_0", "v0_1"])):
        for name in ("m", "K", "gamma", *speeds):
            assert fit.stderr[name] == np.inf, name
            assert np.isinf(fit.intervals[name]).all()
        assert np.isnan(fit.corr("m", "K"))
        assert fit.stderr["t0" if fit is one else "t0_1"] < 1e-6  # s: the impact times are still determined
        (note,) = fit.notes
        assert note.startswith("not identifiable from these data: m, gamma, K, " + ", ".join(speeds))
    # The values are one point of the valley K^(1/n)/m = const of Eq. (8): on it to the noise of the fit.
    for fit in (one, two):
        invariant = fit.values["K"] ** (1 / TRUTH.n) / fit.values["m"]
        assert invariant == pytest.approx(TRUTH.K ** (1 / TRUTH.n) / TRUTH.m, rel=2e-3)


def test_trace_fit_that_does_not_converge_says_so():
    traces = measured(TRUTH, 0.02, CLOCK, T0, noise=0.01, offsets=OFFSETS, seed=3)
    with pytest.raises(FitError, match="did not converge after 2 evaluations"):
        fit_traces(CLOCK, traces, START, drop_height=0.02, free=("m", "gamma", "t0"), max_nfev=2)


def test_trace_fit_reports_a_misfit_far_above_the_noise():
    # A dual-spring chain's trailing oscillations, fitted with the power-law chain: converges, but
    # says that the residual is far above the noise of the traces.
    truth = paper_chain("dual-spring")
    t = np.linspace(0.0, 1.4e-3, 700)
    traces = measured(truth, 0.02, t, 0.0, noise=0.002, offsets=(0.0, 0.0), seed=4)
    fit = fit_traces(t, traces, paper_chain("power-law"), drop_height=0.02, free=("m", "t0"))
    assert any("times the noise of the traces" in note for note in fit.notes)
    assert "note: the residual" in fit.report()


def test_fit_result_report_and_json():
    traces = measured(TRUTH, 0.02, CLOCK, T0, noise=0.01, offsets=OFFSETS, seed=8)
    fit = fit_traces(CLOCK, traces, TRUTH, drop_height=0.02, free=("m", "t0"))
    text = fit.report()
    for part in ("m ", "kg", "t0", "95 % interval", "fixed: gamma = 3 N s/m", "forward runs"):
        assert part in text, text
    data = json.loads(json.dumps(fit.to_dict()))
    assert set(data["values"]) == set(fit.names) == set(data["correlation"])
    assert data["correlation"]["m"]["m"] == pytest.approx(1.0)
    assert data["correlation"]["m"]["t0"] == pytest.approx(fit.corr("t0", "m"))
    with pytest.raises(KeyError, match="not a free parameter"):
        fit.corr("m", "K")


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"free": ("m", "mass")}, "free parameters are"),
        ({"free": ("v0", "h0")}, "not both"),
        ({"free": ("K_b",)}, "belong to the dual-spring model"),
        ({"drop_height": None}, "give a drop height or an impact velocity"),
        ({"traces": {25: PULSE[6]}}, "sensor ring 25 is not in a chain of 20 rings"),
        ({"traces": {6: np.zeros(T.size)}}, "no pulse"),
        ({"t": T[::-1]}, "t must increase"),
        ({"t0": [0.0, 1.0]}, "t0 must be one value or one per record"),
    ],
)
def test_trace_fit_rejects_bad_input(kwargs, message):
    arguments = {"t": T, "traces": PULSE, "drop_height": 0.02, **kwargs}
    with pytest.raises(ValueError, match=message):
        fit_traces(arguments.pop("t"), arguments.pop("traces"), TRUTH, **arguments)
    with pytest.raises(ValueError, match="only"):
        fit_traces(T, PULSE, paper_chain("dual-spring"), drop_height=0.02, free=("n",))


def test_import_does_not_import_lmfit():
    code = "import sys, ringchain.numerics; print('lmfit' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"
