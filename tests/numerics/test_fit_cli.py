"""``ringchain fit static|speed|traces``: round trips from ``ringchain simulate``, JSON, plots, errors."""

from __future__ import annotations

import json

import numpy as np
import pytest
from ringchain.numerics.cli import main
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
    assert_one_line_error(code, out, err, "--drop-height needs one value per file: 1 files, 2 values")
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
    assert_one_line_error(code, out, err, "no pulse at the sensors", exit_code=1)
