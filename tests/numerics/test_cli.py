"""The ``ringchain`` command: each subcommand's output and its error paths (exit codes 0 and 2)."""

import csv
import io
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from ringchain.numerics import Chain, simulate
from ringchain.numerics.cli import main
from ringchain.theory import Ring, paper_data, si_to_n_per_mm, solitary_wave_speed

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def assert_one_line_error(code, out, err, message):
    assert code == 2
    assert out == ""
    assert err.count("\n") == 1 and "error:" in err, err
    assert message in err, err


def number_after(label, text):
    """The first number printed after ``label`` on its line (skipping the label itself)."""
    (line,) = [line for line in text.splitlines() if label in line]
    rest = line.split(label, 1)[1]
    match = re.search(r"[-+]?\d+(?:\.\d*)?(?:e[-+]?\d+)?", rest)
    assert match, f"no number after {label!r} in {line!r}"
    return float(match.group(0))


# -- ringchain ring ------------------------------------------------------------------------------------
def test_ring_prints_everything_about_one_contact(capsys):
    code, out, err = run(capsys, "ring", "--R", "22.5e-3", "--r", "2.5e-3", "--force", "10")
    assert code == 0 and err == ""
    ring = Ring(22.5e-3, 2.5e-3)
    K, n = ring.power_law()
    # Printed to 5 significant figures (4 after the point in e-notation): 5e-5 relative.
    assert number_after("(Eq. 1)", out) == pytest.approx(ring.K_c, rel=5e-5)
    assert number_after("(Eq. 2)", out) == pytest.approx(ring.K_b, rel=5e-5)
    assert number_after("K_b^3/K_c^2", out) == pytest.approx(ring.crossover_force, rel=5e-4)  # 4 figures
    assert number_after("N/m^n, n =", out) == pytest.approx(n, rel=5e-4)  # 4 decimals
    assert number_after("(Eq. 4)  K =", out) == pytest.approx(si_to_n_per_mm(K, n), rel=5e-5)  # 5 figures
    assert number_after("um, local exponent", out) == pytest.approx(ring.local_exponent(10.0), rel=5e-4)
    V_s = solitary_wave_speed(10.0, K, n, ring.spacing, ring.mass)
    assert number_after("V_s =", out) == pytest.approx(V_s, rel=5e-4)  # 4 figures
    # The crossover sits where contact and bending extensions are equal: n = 6/5 there.
    assert "local exponent there 1.2000" in out
    assert "forms a chain" in out and "yes" in out


def test_ring_of_oblique_contact_and_of_a_pair_that_cannot_form_a_chain(capsys):
    code, out, _ = run(capsys, "ring", "--R", "7e-3", "--r", "2.5e-3", "--angle", "80")
    assert code == 0
    assert "no: R/r < 3" in out
    # arccos(1 - 2r/R) for R/r = 2.8: the smallest angle with one Hertz contact.
    assert number_after("single Hertz contact above", out) == pytest.approx(math.degrees(math.acos(1 - 2 / 2.8)),
                                                                            abs=0.005)  # fmt: skip


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--R", "4e-3", "--r", "2.5e-3"], "R must exceed 2 r"),
        (["--R", "22.5e-3", "--r", "2.5e-3", "--angle", "30"], "arccos(1 - 2r/R)"),
        (["--R", "-1"], "R must be positive"),
        (["--R", "abc"], "argument --R: invalid float value: 'abc'"),
        (["--r", "2.5e-3"], "the following arguments are required: --R"),
        (["--R", "22.5e-3", "--force", "-3"], "--force must be positive"),
        (["--R", "22.5e-3", "--material", "unobtainium"], "unknown material 'unobtainium'"),
        (["--R", "22.5e-3", "--window", "100", "1"], "F_min < F_max"),
    ],
)
def test_ring_errors_are_one_line_with_exit_code_2(capsys, argv, message):
    assert_one_line_error(*run(capsys, "ring", *argv), message)


# -- ringchain simulate ----------------------------------------------------------------------------------
def test_simulate_writes_the_sensor_traces_and_a_plot(capsys, tmp_path):
    out_csv, out_png = tmp_path / "run.csv", tmp_path / "run.png"
    argv = ["simulate", "--rings", "8", "--drop-height", "0.05", "--model", "power-law", "--sensors", "2", "5",
            "--t-end", "1e-3", "--samples", "501", "--out", str(out_csv), "--plot", str(out_png)]  # fmt: skip
    code, out, err = run(capsys, *argv)
    assert code == 0 and err == ""
    with open(out_csv) as handle:
        table = list(csv.reader(handle))
    assert table[0] == ["t_s", "sensor_ring2_N", "sensor_ring5_N"]
    data = np.array(table[1:], dtype=float)
    # The same run through the library: the CSV holds its traces (written with 17 digits: exact).
    chain = Chain.from_ring(Ring(22.5e-3, 2.5e-3), 8, "power-law")
    sim = simulate(chain, 1e-3, drop_height=0.05, n_samples=501)
    np.testing.assert_array_equal(data, np.column_stack([sim.t, sim.sensor(2), sim.sensor(5)]))
    assert number_after("ring 5: peak", out) == pytest.approx(sim.peak_force(5), rel=5e-4)  # 4 figures
    assert out_png.read_bytes()[:8] == PNG_MAGIC


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--drop-height", "-0.05"], "drop height must be positive"),
        (["--drop-height", "0"], "drop height must be positive"),
        (["--drop-height", "0.05", "--R", "7e-3"], "cannot form a chain"),
        (["--drop-height", "0.05", "--rings", "10"], "sensor ring 12 is not in a chain of 10 rings"),
        (["--drop-height", "0.05", "--impact-velocity", "1"], "not allowed with argument"),
        (["--drop-height", "0.05", "--model", "granular"], "invalid choice: 'granular'"),
        (["--drop-height", "0.05", "--out", "/nonexistent-dir/run.csv"], "the folder /nonexistent-dir does not exist"),
        (["--out", "run.csv"], "one of the arguments --drop-height --impact-velocity is required"),
    ],
)
def test_simulate_errors_are_one_line_with_exit_code_2(capsys, argv, message):
    if "--out" not in argv:
        argv = [*argv, "--out", "unused.csv"]
    assert_one_line_error(*run(capsys, "simulate", *argv), message)


# -- ringchain sweep -----------------------------------------------------------------------------------
SWEEP = ["sweep", "--model", "power-law", "--rings", "10", "--sensors", "2", "5", "--R-over-r", "6", "9",
         "--drop-height", "0.01:0.05:3", "--workers", "0"]  # fmt: skip


def test_sweep_writes_one_row_per_point_in_grid_order(capsys, tmp_path):
    path = tmp_path / "sweep.csv"
    code, out, err = run(capsys, *SWEEP, "--out", str(path))
    assert code == 0
    assert err == ""  # no progress bar: stderr is not a terminal
    assert "6 rows written" in out
    rows = list(csv.DictReader(io.StringIO(path.read_text())))
    assert [(float(r["R_over_r"]), float(r["drop_height_m"])) for r in rows] == [
        (a, h) for a in (6.0, 9.0) for h in (0.01, 0.03, 0.05)
    ]
    assert all(float(r["peak_force_far_N"]) > 0 and r["model"] == "power-law" for r in rows)


def test_sweep_to_standard_output_and_progress_bar_on_a_terminal(capsys, monkeypatch):
    class Terminal(io.StringIO):
        def isatty(self):
            return True

    terminal = Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    code = main(["sweep", "--R-over-r", "6", "9", "10", "--angle", "90", "60", "--workers", "0"])
    out = capsys.readouterr().out
    assert code == 0
    assert "6/6" in terminal.getvalue()  # tqdm's bar, on the terminal
    rows = list(csv.DictReader(io.StringIO(out)))
    assert [(float(r["R_over_r"]), float(r["angle_deg"])) for r in rows] == [
        (a, t) for a in (6.0, 9.0, 10.0) for t in (90.0, 60.0)
    ]


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--R-over-r", "2.8", "--drop-height", "0.01"], "cannot form a chain"),
        (["--drop-height", "-0.01"], "drop height must be positive"),
        (["--drop-height", "0.01:0.05"], "expected a number or start:stop:count, got '0.01:0.05'"),
        (["--rings", "2.5"], "expected an integer, got '2.5'"),
        (["--model", "granular"], "invalid choice: 'granular'"),
        (["--angle", "20"], "single elliptical Hertz contact does not apply"),
        (["--batch-size", "0"], "batch_size must be a positive integer"),
    ],
)
def test_sweep_errors_are_one_line_with_exit_code_2(capsys, argv, message):
    assert_one_line_error(*run(capsys, "sweep", "--workers", "0", *argv), message)


# -- ringchain paper -------------------------------------------------------------------------------------
def test_paper_prints_the_key_numbers_beside_the_papers_and_writes_figures(capsys, tmp_path):
    code, out, err = run(capsys, "paper", "--out", str(tmp_path / "figures"))
    assert code == 0 and err == ""
    lines = out.splitlines()

    def row(prefix):
        (line,) = [line for line in lines if line.strip().startswith(prefix)]
        return line.split()

    # Static table: theory beside Table I (R/r = 9: measured K = 2284 N/mm^n, n = 1.11).
    cells = row("9.0 ")
    ring = Ring.from_aspect_ratio(9.0)
    n = ring.power_law()[1]
    assert float(cells[1]) == pytest.approx(ring.K_c, rel=5e-5)  # 4 decimals in e-notation
    assert float(cells[5]) == pytest.approx(n, rel=5e-4)
    assert cells[6:9] == ["2284", "1.11", "Table"]
    assert row("3.1 ")[7] == "1.418"  # the paper's Abaqus exponent
    # Angles: Table II's 30 degrees lies below arccos(1 - 2/9) = 38.9 degrees: no single Hertz contact.
    assert "no single Hertz contact below 38.9 deg" in out
    angle60 = Ring.from_aspect_ratio(9.0, angle=math.radians(60.0)).power_law()[1]
    assert float(row("60 ")[4]) == pytest.approx(angle60, rel=5e-4)
    # V_s (Eq. vsfm) for every row of Tables I and II, at 1, 10 and 100 N.
    for aspect, (K_mm, n_t, ratio) in paper_data.TABLE_I.items():
        ring = Ring.from_aspect_ratio(aspect)
        cells = row(f"Table I R/r = {aspect:g} ")
        expected = solitary_wave_speed(np.array([1.0, 10.0, 100.0]), K_mm * 1000.0**n_t, n_t, ring.spacing,
                                       ratio * ring.mass)  # fmt: skip
        np.testing.assert_allclose([float(c) for c in cells[-3:]], expected, rtol=5e-4)  # 4 figures
    assert len([line for line in lines if line.strip().startswith("Table II ")]) == len(paper_data.TABLE_II)
    # The experiment: both models, peak forces and times of flight.
    for model in ("dual-spring", "power-law"):
        cells = row(model)
        forces, times = [float(c) for c in cells[1:3]], [float(c) for c in cells[3:6]]
        assert all(f > 0 for f in forces)
        assert 0 < times[0] < times[1] and times[2] == pytest.approx(times[1] - times[0], abs=2e-3)  # 4 figures
    # Figures.
    figures = sorted((tmp_path / "figures").glob("*.png"))
    assert len(figures) == 5
    assert all(path.read_bytes()[:8] == PNG_MAGIC for path in figures)
    assert str((tmp_path / "figures").resolve()) in out


def test_paper_refuses_a_negative_drop_height(capsys, tmp_path):
    assert_one_line_error(*run(capsys, "paper", "--drop-height", "-1", "--out", str(tmp_path)),
                          "drop height must be positive")  # fmt: skip


# -- the parser and the console script ------------------------------------------------------------------
def test_help_exits_0_and_no_subcommand_exits_2(capsys):
    code, out, _ = run(capsys, "--help")
    assert code == 0 and all(name in out for name in ("paper", "ring", "simulate", "sweep"))
    code, out, err = run(capsys)
    assert_one_line_error(code, out, err, "the following arguments are required: {paper,ring,simulate,sweep}")


def test_console_script_exit_codes():
    script = Path(sys.executable).with_name("ringchain")
    ok = subprocess.run([script, "ring", "--R", "22.5e-3", "--r", "2.5e-3"], capture_output=True, text=True)
    assert ok.returncode == 0, ok.stderr
    assert "K_c, Hertz contact" in ok.stdout
    bad = subprocess.run([script, "ring", "--R", "4e-3", "--r", "2.5e-3"], capture_output=True, text=True)
    assert bad.returncode == 2
    assert bad.stderr.strip().splitlines() == [bad.stderr.strip()] and "R must exceed 2 r" in bad.stderr
