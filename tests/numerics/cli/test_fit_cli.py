"""``ringchain fit static|speed|traces``: round trips from ``ringchain simulate``, JSON, plots, errors."""

from __future__ import annotations

import json

import numpy as np
import pytest
from ringchain.numerics.cli.commands import main
from ringchain.theory import Ring, series_displacement, solitary_wave_speed

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
RING = Ring.from_aspect_ratio(9.0)


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture(scope="module")
def simulated(tmp_path_factory):
    """Two power-law runs of ``ringchain simulate`` (m_eff/m0 = 0.37), drop heights 5 and 20 mm."""
    folder = tmp_path_factory.mktemp("runs")
    paths = {}
    for h in (0.005, 0.02):
        paths[h] = folder / f"drop{h}.csv"
        argv = ["simulate", "--model", "power-law", "--m-eff-ratio", "0.37", "--drop-height", str(h), "--samples",
                "801", "--t-end", "1.6e-3", "--out", str(paths[h])]  # fmt: skip
        assert main(argv) == 0
    return paths


def test_round_trip_simulate_then_fit_traces_recovers_m_eff(simulated, capsys, tmp_path):
    plot = tmp_path / "fit.png"
    code, out, err = run(capsys, "fit", "traces", simulated[0.02], "--model", "power-law", "--m-eff-ratio",
                         "0.5", "--drop-height", "0.02", "--free", "m,t0", "--json")  # fmt: skip
    assert code == 0 and err == ""
    data = json.loads(out)
    # Noise-free data from the same model: only the forward models' difference (1e-6 of the peak)
    # remains; 1e-5 relative on m leaves a margin.
    assert data["values"]["m"] / RING.mass == pytest.approx(0.37, rel=1e-5)
    assert data["values"]["t0"] == pytest.approx(0.0, abs=1e-9)  # s; simulate's clock starts at the impact
    assert set(data["correlation"]) == {"m", "t0", "offset_ring6", "offset_ring12"}
    # The same chain given by --K and --n (the ring's power law, Eq. 4, which simulate used).
    K, n = RING.power_law()
    code, out, _ = run(capsys, "fit", "traces", simulated[0.02], "--model", "power-law", "--K", repr(K), "--n",
                       repr(n), "--m-eff-ratio", "0.3", "--drop-height", "0.02", "--free", "m,t0", "--plot",
                       plot)  # fmt: skip
    assert code == 0
    assert "m/m0 = 0.37" in out and "kg" in out and f"plot written to {plot}" in out
    assert plot.read_bytes().startswith(PNG_MAGIC)


def test_fit_traces_of_two_files_jointly(simulated, capsys):
    code, out, _ = run(capsys, "fit", "traces", simulated[0.005], simulated[0.02], "--model", "power-law",
                       "--m-eff-ratio", "0.45", "--drop-height", "0.005", "0.02", "--free", "m,t0",
                       "--json")  # fmt: skip
    assert code == 0
    data = json.loads(out)
    assert {"t0_0", "t0_1", "offset_ring6_0", "offset_ring12_1"} <= set(data["values"])
    assert data["values"]["m"] / RING.mass == pytest.approx(0.37, rel=1e-5)


def test_fit_static_compares_the_two_laws(capsys, tmp_path):
    F = np.linspace(1.0, 100.0, 50)
    noisy = F + 0.1 * np.random.default_rng(2).standard_normal(F.size)
    path = tmp_path / "static.csv"
    delta = series_displacement(F, K_c=RING.K_c, K_b=RING.K_b)
    rows = "".join(f"{d!r},{f!r}\n" for d, f in zip(delta.tolist(), noisy.tolist(), strict=True))
    path.write_text("# series law of the R/r = 9 ring\ndisplacement_m,force_N\n" + rows)
    plot = tmp_path / "static.png"
    code, out, _ = run(capsys, "fit", "static", path, "--plot", plot)
    assert code == 0
    assert "static power-law fit" in out and "static series fit" in out
    # One line naming both laws by their equations (issue 24, item 15: "than the power-law law's").
    assert "the data support the series law (Eq. 3): its AIC is lower by " in out
    assert "than that of the power law (Eq. 4)" in out and "law law" not in out
    assert plot.read_bytes().startswith(PNG_MAGIC)
    code, out, _ = run(capsys, "fit", "static", path, "--model", "series", "--offset", "--json")
    data = json.loads(out)
    assert set(data["values"]) == {"K_c", "K_b", "delta0"}
    # 0.1 N noise on 1-100 N: K_c and K_b within 4 standard errors of the ring's.
    assert data["values"]["K_b"] == pytest.approx(RING.K_b, abs=4 * data["stderr"]["K_b"])


def test_fit_speed_from_speed_amplitude_pairs(capsys, tmp_path):
    K, n = RING.power_law()
    F = np.geomspace(2.0, 100.0, 12)
    V = solitary_wave_speed(F, K=K, n=n, m=0.35 * RING.mass, a=RING.spacing)
    path = tmp_path / "speeds.csv"
    path.write_text("peak_force_N,speed_m_s\n" + "".join(f"{f!r},{v!r}\n" for f, v in zip(F.tolist(), V.tolist(),
                                                                                           strict=True)))  # fmt: skip
    code, out, _ = run(capsys, "fit", "speed", path, "--json")
    assert code == 0
    assert json.loads(out)["values"]["m_eff_ratio"] == pytest.approx(0.35, rel=1e-6)  # exact data
    code, out, _ = run(capsys, "fit", "speed", path, "--free-n", "--plot", tmp_path / "speed.png")
    assert code == 0 and "the ring's series law, Eq. 4" in out and (tmp_path / "speed.png").is_file()


def assert_one_line_error(code, out, err, message, exit_code=2):
    assert code == exit_code
    assert out == ""
    assert err.count("\n") == 1 and "error:" in err, err
    assert message in err, err


def test_fit_errors_are_one_line(simulated, capsys, tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("t_s,sensor_ring6_N\n" + "".join(f"{i * 1e-5},{np.exp(-(i - 20) ** 2 / 20)}\n" for i in range(30))
                   + "2e-4,1.0\n")  # fmt: skip
    code, out, err = run(capsys, "fit", "traces", bad, "--drop-height", "0.02")
    assert_one_line_error(code, out, err, f"{bad}, line 32, column 1 (t_s): time does not increase")
    code, out, err = run(capsys, "fit", "traces", simulated[0.02], "--drop-height", "0.02", "0.01")
    assert_one_line_error(code, out, err, "--drop-height needs one value per file: 1 file, 2 values")  # not "1 files"
    code, out, err = run(capsys, "fit", "traces", simulated[0.02], "--drop-height", "0.02", "--free", "m,mass")
    assert_one_line_error(code, out, err, "argument --free: expected a comma list")
    code, out, err = run(capsys, "fit", "traces", simulated[0.02], "--drop-height", "0.02", "--K", "1e6", "--n", "1.1")
    assert_one_line_error(code, out, err, "--K and --n give a power law: use them with --model power-law")
    code, out, err = run(capsys, "fit", "traces", simulated[0.02], "--model", "power-law", "--drop-height", "0.02",
                         "--K", "1e6")  # fmt: skip
    assert_one_line_error(code, out, err, "give both --K and --n")
    code, out, err = run(capsys, "fit", "static", tmp_path / "missing.csv")
    assert_one_line_error(code, out, err, "cannot read the file")
    # A starting chain a thousand times too soft: no pulse reaches the sensors -> the fit refuses (exit 1).
    code, out, err = run(capsys, "fit", "traces", simulated[0.02], "--model", "power-law", "--K", "8e3", "--n",
                         "1.107", "--drop-height", "0.02", "--free", "m,t0")  # fmt: skip
    assert_one_line_error(code, out, err, "the starting chain's pulse at ring 6 peaks at", exit_code=1)


# -- issue 24: the inverse workflow, round two -----------------------------------------------------------------
SIX = Ring.from_aspect_ratio(6.0)
SWEEP_COLUMNS = "R_over_r,R_m,r_m,angle_rad,angle_deg,material,model,m_eff_ratio,peak_force_near_N,wave_speed_m_s"


def sweep_like(path, rings, ratio=0.35):
    """A file with a sweep's columns: speeds of Eq. (8) at m_eff/m0 = ``ratio`` on each ring's power law (Eq. 4)."""
    lines = [SWEEP_COLUMNS]
    for ring in rings:
        K, n = ring.power_law()
        for F in np.geomspace(20.0, 200.0, 4):
            V = float(solitary_wave_speed(F, K=K, n=n, m=ratio * ring.mass, a=ring.spacing))
            geometry = ",".join(repr(float(x)) for x in (ring.aspect_ratio, ring.R, ring.r, ring.angle))
            lines.append(f"{geometry},90.0,stainless,dual-spring,{ratio},{float(F)!r},{V!r}")
    path.write_text("\n".join(lines) + "\n")
    return path


def test_fit_speed_takes_the_rings_a_sweep_file_names(capsys, tmp_path):
    # Issue 24, item 1: a sweep at R/r = 6 was fitted with the default ring (R/r = 9): 0.246, exit 0.
    path = sweep_like(tmp_path / "sweep6.csv", [SIX])
    code, out, err = run(capsys, "fit", "speed", path, "--json")
    assert code == 0 and err == "", err
    # Exact data of Eq. (8) on the file's ring: only the least squares' tolerance remains.
    assert json.loads(out)["values"]["m_eff_ratio"] == pytest.approx(0.35, rel=1e-6)
    assert json.loads(out)["fixed"]["a"] == pytest.approx(SIX.spacing, rel=1e-12)  # 17 digits in the file
    # A ring option that agrees with the file is allowed; one that differs is refused, naming the line.
    assert run(capsys, "fit", "speed", path, "--R", repr(SIX.R))[0] == 0
    code, out, err = run(capsys, "fit", "speed", path, "--R", "22.5e-3")
    expected = f"argument --R: {path} names its rings, and line 2 gives R = 0.015 m, not the 0.0225 m given; leave"
    assert_one_line_error(code, out, err, expected)


def test_fit_speed_fits_pairs_from_several_rings_each_with_its_own_law(capsys, tmp_path):
    # Issue 24, item 1: a sweep over R/r = 6 and 9 was pooled with one ring's law (0.825 +- 0.055).
    path = sweep_like(tmp_path / "sweep69.csv", [SIX, RING])
    code, out, err = run(capsys, "fit", "speed", path)
    assert code == 0 and err == "", err
    assert "one m_eff/m0 fitted to pairs from 2 rings" in out and "R = 0.015 m" in out and "R = 0.0225 m" in out
    code, out, _ = run(capsys, "fit", "speed", path, "--json")
    assert json.loads(out)["values"]["m_eff_ratio"] == pytest.approx(0.35, rel=1e-6)  # exact data, as above
    code, out, err = run(capsys, "fit", "speed", path, "--K", "4.9e6", "--n", "1.11")
    assert_one_line_error(code, out, err, "arguments --K and --n give one power law, but")
    code, out, err = run(capsys, "fit", "speed", path, "--free-n")
    assert_one_line_error(code, out, err, "free_n fits one exponent, but the pairs' exponents differ")


def test_fit_speed_of_speeds_in_km_per_s_is_refused(capsys, tmp_path):
    # Issue 24, item 5: m_eff/m0 = 349714 +- 86, exit 0.
    K, n = RING.power_law()
    F = np.geomspace(2.0, 100.0, 12)
    V = solitary_wave_speed(F, K=K, n=n, m=0.35 * RING.mass, a=RING.spacing) / 1000.0
    path = tmp_path / "kms.csv"
    path.write_text("peak_force_N,speed_m_s\n" + "".join(f"{f!r},{v!r}\n" for f, v in zip(F.tolist(), V.tolist(),
                                                                                           strict=True)))  # fmt: skip
    code, out, err = run(capsys, "fit", "speed", path)
    # V ~ m_eff^(-1/2): speeds 1000 times low give 0.35e6; the message gives the factor, sqrt of it.
    assert_one_line_error(code, out, err, "m_eff/m0 = 3.5e+05 (95 % interval from", exit_code=1)
    assert "lies above 1: the speeds are 592 times slower than Eq. (8) allows" in err and "in m/s" in err


def test_fit_speed_with_equal_forces(capsys, tmp_path):
    # Issue 24, item 15: equal forces ended in "give better starting values".
    K, n = RING.power_law()
    V = float(solitary_wave_speed(40.0, K=K, n=n, m=0.35 * RING.mass, a=RING.spacing))
    path = tmp_path / "equal.csv"
    path.write_text("peak_force_N,speed_m_s\n" + "".join(f"40,{V * (1 + 0.01 * k)!r}\n" for k in (-1, 0, 1, 2, -2)))
    code, out, err = run(capsys, "fit", "speed", path, "--json")
    assert code == 0 and err == "", err
    # The mean speed, 1.0 V, at m_eff/m0 = 0.35 / (mean of 1 + 0.01 k)^2 = 0.35 exactly; solver tolerance.
    assert json.loads(out)["values"]["m_eff_ratio"] == pytest.approx(0.35, rel=1e-6)
    code, out, err = run(capsys, "fit", "speed", path, "--free-n")
    assert_one_line_error(code, out, err, "free_n needs peak forces that differ: every F_m is 40 N")


def test_fit_plot_path_is_checked_before_the_fit(capsys, tmp_path):
    # Issue 24, item 9: --plot st wrote st.png and said "plot written to st"; a bad extension was refused
    # only after the fit.
    F = np.linspace(1.0, 100.0, 20)
    path = tmp_path / "static.csv"
    path.write_text("displacement_m,force_N\n" + "".join(f"{d!r},{f!r}\n" for d, f in zip(
        series_displacement(F, K_c=RING.K_c, K_b=RING.K_b).tolist(), F.tolist(), strict=True)))  # fmt: skip
    for plot, message in [("st", "it has no extension"), ("st.csv", "its extension .csv is not an image format")]:
        code, out, err = run(capsys, "fit", "static", path, "--plot", tmp_path / plot)
        assert_one_line_error(code, out, err, f"argument --plot: {tmp_path / plot}: {message}")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["static.csv"]
    code, out, err = run(capsys, "fit", "static", path, "--plot", tmp_path / "missing" / "st.png")
    assert_one_line_error(code, out, err, "the folder")


def test_fit_traces_of_times_in_ms_is_refused_at_once(simulated, capsys, tmp_path):
    # Issue 24, item 10: times in ms labelled t_s ran for minutes in odeint.
    table = np.loadtxt(simulated[0.02], delimiter=",", skiprows=1)
    table[:, 0] *= 1e3
    path = tmp_path / "ms.csv"
    np.savetxt(path, table, delimiter=",", header="t_s,sensor_ring6_N,sensor_ring12_N,support_N", comments="")
    code, out, err = run(capsys, "fit", "traces", path, "--model", "power-law", "--drop-height", "0.02")
    assert_one_line_error(code, out, err, "the times span 1.6 s, ")
    assert "the pulse needs to pass ring 12: are they in s (not ms)?" in err


def test_fit_traces_of_forces_far_from_the_chain_names_the_ratio(simulated, capsys, tmp_path):
    # Issue 24, item 15: forces x 1e12 gave "the starting chain gives no pulse".
    table = np.loadtxt(simulated[0.02], delimiter=",", skiprows=1)
    table[:, 1:] *= 1e12
    path = tmp_path / "x1e12.csv"
    np.savetxt(path, table, delimiter=",", header="t_s,sensor_ring6_N,sensor_ring12_N,support_N", comments="")
    code, out, err = run(capsys, "fit", "traces", path, "--model", "power-law", "--drop-height", "0.02",
                         "--m-eff-ratio", "0.37")  # fmt: skip
    # The starting chain is the simulated one: its pulse is 1e12 times below (to the printed 3 digits).
    assert_one_line_error(code, out, err, "the starting chain's pulse at ring 6 peaks at ", exit_code=1)
    assert "1e+12 times below the measured" in err and "are the forces in N?" in err


def test_fit_traces_takes_a_chain_file(simulated, capsys, tmp_path):
    # Issue 24, item 15: the README said fit traces takes the chain as simulate does; it had no --chain.
    chain = tmp_path / "chain.toml"
    chain.write_text("[[segment]]\nrings = 20\nR = 22.5e-3\nr = 2.5e-3\n")
    code, out, err = run(capsys, "fit", "traces", simulated[0.02], "--chain", chain, "--model", "power-law",
                         "--m-eff-ratio", "0.5", "--drop-height", "0.02", "--free", "m,t0", "--json")  # fmt: skip
    assert code == 0 and err == "", err
    # The file's chain is the ring options' chain: as in the round trip above (1e-5 relative on m).
    assert json.loads(out)["values"]["m"] / RING.mass == pytest.approx(0.37, rel=1e-5)
    for extra, message in [
        (["--rings", "20"], "argument --rings: not allowed with --chain"),
        (["--material", "stainless"], "argument --material: not allowed with --chain"),
        (["--K", "1e6", "--n", "1.1"], "arguments --K and --n: not allowed with --chain"),
    ]:
        code, out, err = run(capsys, "fit", "traces", simulated[0.02], "--chain", chain, "--model", "power-law",
                             "--drop-height", "0.02", *extra)  # fmt: skip
        assert_one_line_error(code, out, err, message)


def test_fit_traces_of_micrometre_rings_converges(capsys, tmp_path):
    # Issue 24, item 2: a simulated R = 22.5 um chain failed after 60 evaluations: SciPy moved the start of m,
    # 8e-12 kg, to 1e-10 kg, its distance from the bound 0 (fit.minimize now solves in scaled units).
    path = tmp_path / "um.csv"
    ring = ["--R", "22.5e-6", "--r", "2.5e-6", "--model", "power-law"]
    assert run(capsys, "simulate", *ring, "--m-eff-ratio", "0.37", "--drop-height", "0.02", "--samples", "801",
               "--out", path)[0] == 0  # fmt: skip
    code, out, err = run(capsys, "fit", "traces", path, *ring, "--m-eff-ratio", "0.5", "--drop-height", "0.02",
                         "--free", "m,t0", "--json")  # fmt: skip
    assert code == 0 and err == "", err
    m0 = Ring(22.5e-6, 2.5e-6).mass
    assert json.loads(out)["values"]["m"] / m0 == pytest.approx(0.37, rel=1e-5)  # as the round trip above
    code, out, err = run(capsys, "fit", "traces", path, *ring, "--drop-height", "0.02", "--free", "m,t0",
                         "--max-evaluations", "2")  # fmt: skip
    assert_one_line_error(code, out, err, "did not converge after 2 evaluations", exit_code=1)
    assert "allow more evaluations (--max-evaluations)" in err
