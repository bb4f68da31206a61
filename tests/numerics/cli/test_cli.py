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
from ringchain.numerics.cli.commands import build_parser, main
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
    assert number_after("(Eq. 4)  K =", out) == pytest.approx(si_to_n_per_mm(K, n=n), rel=5e-5)  # 5 figures
    assert number_after("um, local exponent", out) == pytest.approx(ring.local_exponent(10.0), rel=5e-4)
    V_s = solitary_wave_speed(10.0, K=K, n=n, m=ring.mass, a=ring.spacing)
    assert number_after("V_s =", out) == pytest.approx(V_s, rel=5e-4)  # 4 figures
    # The crossover sits where contact and bending extensions are equal: n = 6/5 there.
    assert "local exponent there 1.2000" in out
    assert "forms a chain" in out and "yes" in out


def test_ring_of_oblique_contact_and_of_a_pair_that_cannot_form_a_chain(capsys):
    # Up to 10 N the ellipse stays within the half-space limit (0.049 r; at 100 N it is 0.11 r, flagged).
    code, out, _ = run(capsys, "ring", "--R", "7e-3", "--r", "2.5e-3", "--angle", "80", "--window", "1", "10")
    assert code == 0 and "Hertz contact (Eq. 1)" in out
    assert "no: R/r < 3" in out
    # arccos(1 - 2r/R) for R/r = 2.8: the smallest angle with one Hertz contact.
    assert number_after("single Hertz contact above", out) == pytest.approx(math.degrees(math.acos(1 - 2 / 2.8)),
                                                                            abs=0.005)  # fmt: skip


def test_ring_below_theta_min_uses_the_numerical_contact(capsys):
    from ringchain.numerics import contact_at_angle

    code, out, _ = run(capsys, "ring", "--R", "22.5e-3", "--r", "2.5e-3", "--angle", "30", "--window", "1", "30")
    assert code == 0 and "two patches (BEM" in out
    ring = Ring.from_aspect_ratio(9.0)
    contact = contact_at_angle(ring.R, ring.r, ring.material.E, ring.material.nu, math.radians(30), K_b=ring.K_b,
                               window=(1.0, 30.0), forces=[10.0])  # fmt: skip
    assert number_after(", n = ", out) == pytest.approx(contact.n, abs=5e-5)  # printed to 4 decimals


def test_ring_hands_over_where_the_ellipse_leaves_the_half_space(capsys):
    # Issue 24, item 3: 39 deg is above theta_min (38.94), but the ellipse at 100 N is 1.0 r long: the single
    # ellipse's K_c (8.8e10, growing without bound towards theta_min) is not printed; the numerical contact is,
    # and it too is beyond the half-space limit: flagged with exit code 1 and one line on stderr (item 4).
    code, out, err = run(capsys, "ring", "--R", "22.5e-3", "--r", "2.5e-3", "--angle", "39")
    assert code == 1 and "one patch (BEM" in out and "Hertz contact (Eq. 1)" not in out
    assert 5e10 < number_after("tilt 0.0 deg)", out) < 1e11  # 6.8e10 from the boundary elements
    assert "above 55.84 deg" in out  # where Hertz's ellipse stays within 0.1 r up to 100 N
    assert err.count("\n") == 1 and err.startswith("ringchain ring: warning: the contact reaches 0.57 r")
    assert "keep --window's F_MAX and --force below about 0.147 N" in err  # 0.1 r, extrapolated as F^(1/3)


def test_ring_flags_a_numerical_contact_beyond_its_limit(capsys):
    # The case of item 4: "contact up to 1.93 r" at 12.85 deg was printed with exit code 0.
    code, out, err = run(capsys, "ring", "--R", "22.5e-3", "--r", "2.5e-3", "--angle", "12.85")
    assert code == 1 and "contact up to 1.93 r at 100 N" in out
    assert err.count("\n") == 1 and "beyond the half-space limit 0.1 r" in err


@pytest.mark.parametrize(("angle", "window"), [("30", "1e4"), ("13", "3000"), ("20", "1e5")])
def test_ring_contacts_round_the_tube_are_one_line(capsys, angle, window):
    # The cases of item 12: a traceback, "ray casting onto the torus did not converge".
    code, out, err = run(capsys, "ring", "--R", "22.5e-3", "--r", "2.5e-3", "--angle", angle, "--window", "1", window)
    assert_one_line_error(code, out, err, f"--angle {angle} deg, --force 10 N and --window 1 {float(window):g} N: "
                                          f"the contact reaches round the tube at {float(window):.3g} N")  # fmt: skip


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--R", "4e-3", "--r", "2.5e-3"], "R must exceed 2 r"),
        (["--R", "22.5e-3", "--r", "2.5e-3", "--angle", "10"], "2 arcsin(r/R)"),
        (["--R", "22.5e-3", "--r", "2.5e-3", "--angle", "12.8"], "curves away from the contact points"),
        (["--R", "-1"], "R must be positive"),
        (["--R", "abc"], "argument --R: invalid float value: 'abc'"),
        (["--r", "2.5e-3"], "the following arguments are required: --R"),
        (["--R", "22.5e-3", "--force", "-3"], "argument --force: force must be positive (in N), got -3"),
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
    assert table[0] == ["t_s", "sensor_ring2_N", "sensor_ring5_N", "support_N"]
    data = np.array(table[1:], dtype=float)
    # The same run through the library: the CSV holds its traces (written with 17 digits: exact).
    chain = Chain.from_ring(Ring(22.5e-3, 2.5e-3), 8, "power-law")
    sim = simulate(chain, 1e-3, drop_height=0.05, n_samples=501)
    np.testing.assert_array_equal(data, np.column_stack([sim.t, sim.sensor(2), sim.sensor(5), sim.support_force]))
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
    # Angles, each contact as `ringchain ring` chooses it: Hertz's ellipse where it stays within the half-space
    # limit up to 100 N (above 55.84 deg), the numerical contact elsewhere (Table II's 30 deg: two patches).
    assert "above 55.84 deg" in out and "a single contact exists above 38.94 deg" in out
    angle60 = Ring.from_aspect_ratio(9.0, angle=math.radians(60.0)).power_law()[1]
    assert row("60 ")[1] == "Hertz" and float(row("60 ")[5]) == pytest.approx(angle60, rel=5e-4)
    (cells,) = [line.split() for line in lines if line.split()[:2] == ["30", "BEM,"]]
    assert cells[2:4] == ["2", "patches"] and 1.0 < float(cells[7]) < 1.5 and cells[9:] == ["4030", "1.18"]
    # V_s (Eq. (8)) for every row of Tables I and II, at 1, 10 and 100 N.
    for aspect, (K_mm, n_t, ratio) in paper_data.TABLE_I.items():
        ring = Ring.from_aspect_ratio(aspect)
        cells = row(f"Table I R/r = {aspect:g} ")
        expected = solitary_wave_speed(np.array([1.0, 10.0, 100.0]), K=K_mm * 1000.0**n_t, n=n_t, m=ratio * ring.mass,
                                       a=ring.spacing)  # fmt: skip
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
    assert code == 0 and all(name in out for name in ("paper", "ring", "simulate", "sweep", "ensemble", "cache"))
    code, out, err = run(capsys)
    required = "the following arguments are required: {paper,ring,simulate,sweep,ensemble,cache,fit,sheet,rings}"
    assert_one_line_error(code, out, err, required)


def test_version_is_the_package_version_in_one_line(capsys):
    # Issue 24, item 17: `ringchain --version` was refused as a missing subcommand.
    from importlib.metadata import version

    code, out, err = run(capsys, "--version")
    assert (code, out, err) == (0, f"ringchain {version('ringchain')}\n", "")
    script = Path(sys.executable).with_name("ringchain")
    done = subprocess.run([script, "--version"], capture_output=True, text=True)
    assert (done.returncode, done.stdout, done.stderr) == (0, f"ringchain {version('ringchain')}\n", "")


def test_the_parser_of_one_command_parses_it_as_the_whole_parser_does(tmp_path):
    # main() builds the options of fit, ensemble, sheet and rings only when it runs one of them: the command it runs
    # reads the same, and ringchain --help lists every command with the same words.
    for argv in ([*SIMULATE, "--out", str(tmp_path / "run.csv")], ["fit", "traces", str(tmp_path / "t.csv"),
                 "--drop-height", "0.05"], ["cache", "info"]):  # fmt: skip
        assert vars(build_parser(argv[0]).parse_args(argv)) == vars(build_parser().parse_args(argv))
    assert build_parser("simulate").format_help() == build_parser().format_help()


def test_simulate_without_a_plot_imports_neither_matplotlib_nor_sympy(tmp_path):
    # A fresh process, as the ringchain script runs it: the run needs the kernels and NumPy, not the plotting
    # library (only --plot does) nor the symbolic engine (the theory's generated code is read from disk).
    program = (
        "import sys; from ringchain.numerics.cli import main; sys.argv[0] = 'ringchain'; code = main(); "
        "print(code, *sorted({name.split('.')[0] for name in sys.modules} & {'matplotlib', 'sympy'}))"
    )
    argv = [sys.executable, "-c", program, *SIMULATE, "--out", str(tmp_path / "run.csv")]
    done = subprocess.run(argv, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-1] == "0"


def test_console_script_exit_codes():
    script = Path(sys.executable).with_name("ringchain")
    ok = subprocess.run([script, "ring", "--R", "22.5e-3", "--r", "2.5e-3"], capture_output=True, text=True)
    assert ok.returncode == 0, ok.stderr
    assert "K_c, Hertz contact" in ok.stdout
    bad = subprocess.run([script, "ring", "--R", "4e-3", "--r", "2.5e-3"], capture_output=True, text=True)
    assert bad.returncode == 2
    assert bad.stderr.strip().splitlines() == [bad.stderr.strip()] and "R must exceed 2 r" in bad.stderr


# -- output paths: checked before any work, never changed ------------------------------------------------
class WorkStarted(Exception):
    """Raised in place of the solver or the sweep: the command got past its checks."""


@pytest.fixture
def no_work(monkeypatch):
    """Replace the solver and the sweep, so that a test sees whether the command started its work."""
    import importlib

    from ringchain.numerics.jobs import experiment

    sweep_module = importlib.import_module("ringchain.numerics.jobs.sweep")

    def work(*args, **kwargs):
        raise WorkStarted

    monkeypatch.setattr(experiment, "run_experiment", work)
    monkeypatch.setattr(sweep_module, "sweep", work)


SIMULATE = ["simulate", "--rings", "8", "--drop-height", "0.05", "--model", "power-law", "--sensors", "2", "5",
            "--t-end", "1e-3", "--samples", "201"]  # fmt: skip


def test_a_plot_into_an_existing_folder_is_refused_and_no_other_file_is_written(capsys, tmp_path, no_work):
    folder = tmp_path / "figures"
    folder.mkdir()
    code, out, err = run(capsys, *SIMULATE, "--out", str(tmp_path / "run.csv"), "--plot", str(folder))
    assert_one_line_error(code, out, err, f"argument --plot: {folder} is a folder")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["figures"]  # no figures.png, no run.csv


@pytest.mark.parametrize(
    ("option", "name", "message"),
    [
        ("--out", "missing/run.csv", "argument --out: cannot write {path}: the folder {tmp}/missing does not exist"),
        ("--out", "afile/run.csv", "argument --out: cannot write {path}: the folder {tmp}/afile is not a folder"),
        ("--out", "", "argument --out: the file name is empty"),
        (
            "--plot",
            "plot.xyz",
            "argument --plot: {path}: its extension .xyz is not an image format; name the file with one of",
        ),
        ("--plot", "plot.csv", "its extension .csv is not an image format"),
        ("--plot", "plot", "argument --plot: {path}: it has no extension; name the file with one of"),
        ("--plot", "missing/plot.png", "argument --plot: cannot write {path}: the folder {tmp}/missing does not exist"),
    ],
)
def test_simulate_checks_its_output_paths_before_any_work(capsys, tmp_path, no_work, option, name, message):
    (tmp_path / "afile").write_text("")
    path = str(tmp_path / name) if name else ""
    outputs = {"--out": str(tmp_path / "run.csv"), option: path}
    argv = [*SIMULATE, *(x for pair in outputs.items() for x in pair)]
    code, out, err = run(capsys, *argv)
    assert_one_line_error(code, out, err, message.format(path=path, tmp=tmp_path))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile"]


def test_simulate_refuses_one_file_for_both_outputs(capsys, tmp_path, no_work):
    path = str(tmp_path / "run.png")
    code, out, err = run(capsys, *SIMULATE, "--out", path, "--plot", path)
    assert_one_line_error(code, out, err, f"arguments --out and --plot: both name {path}; give two files")


def test_sweep_and_paper_check_their_outputs_before_any_work(capsys, tmp_path, no_work):
    code, out, err = run(capsys, *SWEEP, "--out", str(tmp_path))
    assert_one_line_error(code, out, err, f"argument --out: {tmp_path} is a folder")
    blocker = tmp_path / "figures.png"
    blocker.write_text("")
    code, out, err = run(capsys, "paper", "--out", str(blocker))
    assert_one_line_error(code, out, err, f"argument --out: {blocker} exists and is not a folder")
    code, out, err = run(capsys, "paper", "--out", str(blocker / "figures"))
    assert_one_line_error(code, out, err, f"cannot create the folder {blocker / 'figures'}: {blocker} is not a folder")


def test_a_plot_is_written_under_the_name_given_in_the_format_its_extension_names(capsys, tmp_path):
    out_csv, out_pdf = tmp_path / "run.csv", tmp_path / "traces.pdf"
    code, out, err = run(capsys, *SIMULATE, "--out", str(out_csv), "--plot", str(out_pdf))
    assert code == 0, err
    assert f"plot written to {out_pdf}\n" in out
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.csv", "traces.pdf"]
    assert out_pdf.read_bytes()[:5] == b"%PDF-"


# -- messages: the option, in the user's units ----------------------------------------------------------
@pytest.mark.parametrize(
    ("argv", "message"),
    [
        # Angles are given in degrees: the message is in degrees (it was in radians).
        (["ring", "--R", "22.5e-3", "--angle", "91"], "argument --angle: contact angle (deg) must lie in (0, 90]"),
        (["ring", "--R", "22.5e-3", "--angle", "-10"], "contact angle (deg) must lie in (0, 90], got -10"),
        (["sweep", "--angle", "95"], "argument --angle: contact angle (deg) must lie in (0, 90], got 95"),
        (["simulate", "--drop-height", "0.05", "--angle", "0"], "contact angle (deg) must lie in (0, 90], got 0"),
        # An angle that rounds onto the lowest one is printed with the digits that tell them apart.
        # (A chain needs one Hertz contact per pair of rings; `ring` alone goes below with the numerical contact.)
        (
            ["simulate", "--drop-height", "0.05", "--angle", "38.94244"],
            "a contact angle of 38.94244 deg is at or below arccos(1 - 2r/R) = 38.942441 deg for R/r = 9",
        ),
        # The option the user gave, not a quantity derived from it.
        (["simulate", "--drop-height", "0.05", "--R", "0"], "argument --R: R must be positive (in m), got 0"),
        (["simulate", "--drop-height", "0.05", "--r", "-1"], "argument --r: r must be positive (in m), got -1"),
        (["simulate", "--drop-height", "0.05", "--r", "0"], "argument --r: r must be positive (in m), got 0"),
        (["ring", "--R", "22.5e-3", "--force", "inf"], "argument --force: force must be finite, got inf"),
        (["simulate", "--drop-height", "0.05", "--t-end", "inf"], "argument --t-end: duration must be finite"),
        (["simulate", "--drop-height", "0.05", "--rings", "0"], "argument --rings: rings must be at least 2, got 0"),
        (
            ["simulate", "--drop-height", "0.05", "--samples", "0"],
            "argument --samples: n_samples must be at least 3, got 0",
        ),
        (["simulate", "--drop-height", "0.05", "--m-eff-ratio", "2"], "argument --m-eff-ratio: m_eff/m0 must lie in"),
        (["simulate", "--drop-height", "0.05", "--sensors", "12", "6"], "argument --sensors: the near ring comes"),
        (["simulate", "--drop-height", "0.05", "--method", "bogus"], "argument --method: invalid choice: 'bogus'"),
        (["ring", "--R", "1e300"], "argument --R: R = 1e+300 m is a ring over 1 m: radii are in m"),
        (["sweep", "--R-over-r", "1e300"], "cannot compute the ring of --R-over-r 1e+300, --r 0.0025 m, --angle 90"),
        # No rounding in a message: R/r = 2.99999996 is not "3 < 3".
        (["simulate", "--drop-height", "0.05", "--R", "7.4999999e-3"], "arguments --R and --r: R/r = 2.99999996 < 3"),
        (["sweep", "--R-over-r", "2.9999999", "--drop-height", "0.01"], "argument --R-over-r: R/r = 2.9999999 < 3"),
        # Impacts far beyond where contact mechanics holds (the solver failed, or returned numbers, exit 0).
        (
            ["simulate", "--drop-height", "1e300"],
            "argument --drop-height: a drop of 1e+300 m gives an impact at "
            "4.43e+150 m/s, which is not below the bar-wave speed",
        ),
        (["simulate", "--impact-velocity", "1e10"], "argument --impact-velocity: 1e+10 m/s is not below the bar-wave"),
        (["sweep", "--impact-velocity", "1", "1e4"], "argument --impact-velocity: 10000 m/s is not below"),
        # Worker counts, ranges and grid sizes.
        (["sweep", "--workers", "-1"], "argument --workers: workers must be at least 0, got -1"),
        (
            ["sweep", "--R-over-r", "6:9:0"],
            "the count of start:stop:count must be an integer from 1 to 100000, got '0' in '6:9:0'",
        ),
        (["sweep", "--R-over-r", "6:9:2.5"], "the count of start:stop:count must be an integer from 1 to 100000"),
        (["sweep", "--R-over-r", "6:9:1000000000"], "the count of start:stop:count must be an integer from 1"),
        (["sweep", "--drop-height", "0.05:0.05:3"], "argument --drop-height: '0.05:0.05:3' gives 3 equal values"),
        (["sweep", "--R-over-r", "1:0:5"], "argument --R-over-r: R/r must be positive, got 0"),
        (
            ["sweep", "--R-over-r", "4:9:400", "--angle", "61:90:400"],
            "the grid has 160000 points (400 x 400); the command line runs at most 100000",
        ),
    ],
    ids=lambda value: " ".join(value) if isinstance(value, list) else "",
)
def test_errors_name_the_option_in_the_users_units(capsys, no_work, argv, message):
    if argv[0] == "simulate":
        argv = [*argv, "--out", "unused.csv"]
    elif argv[0] == "sweep":
        argv = [*argv, "--workers", "0"]
    assert_one_line_error(*run(capsys, *argv), message)


def test_a_ratio_of_exactly_three_forms_a_chain_whatever_the_division_rounds_to(no_work):
    assert 0.3 / 0.1 < 3  # 2.9999999999999996 in binary floating point
    with pytest.raises(WorkStarted):
        main(["simulate", "--drop-height", "0.05", "--R", "0.3", "--r", "0.1", "--out", "unused.csv"])


def test_a_too_short_t_end_of_a_sweep_is_named_as_the_users_option(capsys):
    argv = [*SWEEP[:-4], "--drop-height", "0.05", "--t-end", "1e-9", "--workers", "0"]
    message = "argument --t-end: the pulse is still passing ring 5 at --t-end = 1e-09 s"
    assert_one_line_error(*run(capsys, *argv), message)


EDGE_VALUES = ["0", "-1", "nan", "inf", "-inf", "1e308", "1e-308", "abc", "", "2.5", "1:0:5"]
OPTIONS = {
    "ring": (["ring", "--R", "22.5e-3"], ["--R", "--r", "--angle", "--force", "--m-eff-ratio", "--material"]),
    "simulate": (["simulate", "--drop-height", "0.05", "--out", "unused.csv"],
                 ["--R", "--r", "--angle", "--m-eff-ratio", "--rings", "--drop-height", "--t-end", "--samples",
                  "--plot", "--out"]),
    "sweep": (["sweep", "--workers", "0", "--drop-height", "0.05"],
              ["--R-over-r", "--r", "--angle", "--m-eff-ratio", "--rings", "--drop-height", "--t-end", "--samples",
               "--batch-size", "--workers", "--out"]),
}  # fmt: skip


@pytest.mark.parametrize(
    ("command", "option"), [(command, option) for command, (_, options) in OPTIONS.items() for option in options]
)
def test_no_edge_value_of_any_option_gives_a_traceback(capsys, tmp_path, monkeypatch, no_work, command, option):
    """Every edge value is refused in one line (exit 2) or gets past the checks to the work; nothing else."""
    monkeypatch.chdir(tmp_path)
    base, _ = OPTIONS[command]
    for value in EDGE_VALUES:
        try:
            code = main([*base, option, value])
        except WorkStarted:
            capsys.readouterr()
            continue
        _, err = capsys.readouterr()
        if code == 0:
            assert command == "ring" and err == "", (option, value, err)
        else:
            assert code == 2 and err.count("\n") == 1 and "error:" in err, (option, value, err)
    for window in (["0", "1"], ["1", "1e308"], ["1e-308", "1"], ["nan", "1"], ["3", "2"]):
        code = main([*OPTIONS["ring"][0], "--window", *window])
        _, err = capsys.readouterr()
        assert code == 0 or (code == 2 and err.count("\n") == 1), (window, err)


# -- ringchain sweep --dask: a scheduler answers, or one line says why not ----------------------------
class Listener:
    """A TCP server on 127.0.0.1 that is not a Dask scheduler; it stops when the test ends.

    ``banner`` speaks first (as an SSH server does); ``http`` waits for a request and
    answers 400 to any bytes (an HTTP server); ``silent`` accepts and never says a word;
    ``closing`` accepts and closes the connection at once.
    """

    def __init__(self, kind):
        import socket
        import threading

        self.kind, self.stop = kind, threading.Event()
        self.server = socket.create_server(("127.0.0.1", 0))
        self.server.settimeout(0.1)
        self.port = self.server.getsockname()[1]
        self.connections = []
        self.thread = threading.Thread(target=self.serve, daemon=True)
        self.thread.start()

    def serve(self):
        while not self.stop.is_set():
            try:
                conn, _ = self.server.accept()
            except OSError:
                continue
            self.connections.append(conn)
            conn.settimeout(0.1)
            if self.kind == "banner":
                conn.sendall(b"SSH-2.0-OpenSSH_9.6\r\n")
            if self.kind == "closing":
                conn.close()
            if self.kind == "http":
                while not self.stop.is_set():
                    try:
                        if conn.recv(4096):
                            conn.sendall(b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n")
                            break
                    except OSError:
                        continue

    def close(self):
        self.stop.set()
        self.thread.join(5)
        for conn in [*self.connections, self.server]:
            conn.close()


@pytest.fixture
def listener(request):
    server = Listener(request.param)
    yield server
    server.close()


def sweep_on_dask(address, timeout=None):
    """``ringchain sweep --dask address`` in a process of its own (a hang or a crash stays there)."""
    argv = [sys.executable, "-m", "ringchain.numerics.cli", "sweep", "--R-over-r", "9", "--dask", address,
            "--dask-timeout", "2"]  # fmt: skip
    # Dask's own client waits 30 s for a silent or closed address: 25 s tells the two apart.
    return subprocess.run(argv, capture_output=True, text=True, timeout=timeout or 25)


@pytest.mark.parametrize(
    ("listener", "reason"),
    [
        (
            "banner",
            "accepts connections, but it speaks another protocol (its first message is not one distributed can read)",
        ),
        ("http", "accepts connections, but it sent nothing within 2 s, while a Dask scheduler greets at once"),
        ("silent", "accepts connections, but it sent nothing within 2 s"),
        ("closing", "accepts connections, but it closed the connection without a Dask handshake"),
    ],
    indirect=["listener"],
)
def test_dask_at_an_address_where_something_else_listens_is_one_line(listener, reason):
    address = f"tcp://127.0.0.1:{listener.port}"
    result = sweep_on_dask(address)
    assert result.returncode == 2, result.stderr
    assert result.stderr.count("\n") == 1, result.stderr
    assert f"ringchain sweep: error: argument --dask: no Dask scheduler at {address}: 127.0.0.1:{listener.port} " \
           f"{reason}" in result.stderr  # fmt: skip
    assert "a scheduler listens on port 8786 unless told otherwise" in result.stderr


def test_dask_at_a_closed_port_is_one_line_at_once():
    import socket

    with socket.create_server(("127.0.0.1", 0)) as server:
        port = server.getsockname()[1]  # closed when the block ends: nothing listens there
    result = sweep_on_dask(f"127.0.0.1:{port}")
    assert result.returncode == 2
    assert result.stderr == (f"ringchain sweep: error: argument --dask: no Dask scheduler at 127.0.0.1:{port}: "
                             f"connection refused (nothing listens on 127.0.0.1:{port})\n")  # fmt: skip


@pytest.mark.parametrize(
    ("address", "message"),
    [
        ("tcp://127.0.0.1:99999", "malformed Dask address 'tcp://127.0.0.1:99999': the port must be an integer"),
        ("tcp://:8786", "malformed Dask address 'tcp://:8786': no host"),
        ("tcp://[::1", "malformed Dask address 'tcp://[::1'"),
    ],
)
def test_a_malformed_dask_address_is_one_line(capsys, address, message):
    assert_one_line_error(*run(capsys, "sweep", "--dask", address), f"argument --dask: {message}")


# -- ringchain cache -------------------------------------------------------------------------------------
def test_cache_info_and_clear(capsys, tmp_path, monkeypatch):
    from ringchain.theory import _codegen

    cache = tmp_path / "cache"
    monkeypatch.setenv("RINGCHAIN_CACHE_DIR", str(cache))
    code, out, _ = run(capsys, "cache", "info")
    assert code == 0
    assert f"location  {cache} (from RINGCHAIN_CACHE_DIR)" in out
    assert "none (the folder does not exist yet)" in out and "yes (the folder will be created)" in out
    # One entry of the current key, one stale, one leftover temporary file and files of the user's, two of
    # them named like the cache's (issue 24, item 15: `cache clear` removed any *-<key>.py and .tmp-*.py).
    x = __import__("sympy").Symbol("x")
    _codegen.Derived(lambda: ((x,), x + 1), name="probe")(1.0)
    (cache / "contact.old-0123456789abcdef0123.py").write_bytes(_codegen._MAGIC + b"0" * 64 + b"\n# old\n")
    (cache / ".tmp-contact.old-0123456789abcdef0123-42-0a1b2c3d.py").write_text("")
    (cache / "notes.txt").write_text("mine")
    (cache / f"mine-{_codegen.source_key()}.py").write_text("print('my own script')\n")
    (cache / ".tmp-mine.py").write_text("")
    users = {"notes.txt", f"mine-{_codegen.source_key()}.py", ".tmp-mine.py"}
    code, out, _ = run(capsys, "cache", "info")
    assert code == 0
    assert f"key       {_codegen.source_key()}" in out
    assert "entries   1 for this key, 1 stale (other keys), 1 temporary files" in out
    size = sum(p.stat().st_size for p in cache.iterdir() if p.name not in users)
    assert f"size      {size} bytes" in out
    assert "writable  yes\n" in out
    code, out, _ = run(capsys, "cache", "clear")
    assert code == 0 and out == f"removed 3 files ({size} bytes) from {cache}\n"
    assert {p.name for p in cache.iterdir()} == users  # only the cache's own files go
    _codegen.Derived(lambda: ((x,), x + 2), name="probe2")(1.0)
    code, out, _ = run(capsys, "cache", "clear")
    assert code == 0 and out.startswith("removed 1 file (")  # not "1 files"


def test_cache_info_and_clear_of_a_file_where_the_folder_should_be(capsys, tmp_path, monkeypatch):
    # Issue 24, item 15: `cache info` said "the folder does not exist yet" of a plain file.
    plain = tmp_path / "plain"
    plain.write_text("data")
    monkeypatch.setenv("RINGCHAIN_CACHE_DIR", str(plain))
    for action in ("info", "clear"):
        code, out, err = run(capsys, "cache", action)
        assert_one_line_error(code, out, err, f"ringchain cache {action}: error: the cache folder {plain} ")
        assert "is a file, not a folder" in err
    assert plain.read_text() == "data"


def test_cache_info_of_a_disabled_and_of_an_unwritable_cache(capsys, tmp_path, monkeypatch):
    monkeypatch.setenv("RINGCHAIN_CACHE_DIR", "")
    code, out, _ = run(capsys, "cache", "info")
    assert code == 0 and "the disk cache is disabled" in out
    code, out, _ = run(capsys, "cache", "clear")
    assert code == 0 and out.startswith("nothing to clear: the disk cache is disabled")
    blocker = tmp_path / "file"
    blocker.write_text("")
    monkeypatch.setenv("RINGCHAIN_CACHE_DIR", str(blocker / "cache"))  # a folder under a file: never writable
    code, out, _ = run(capsys, "cache", "info")
    assert code == 0 and "writable  no: each process derives the theory again" in out


def test_paper_refuses_a_drop_beyond_contact_mechanics_before_any_work(capsys, tmp_path):
    code, out, err = run(capsys, "paper", "--out", str(tmp_path / "figures"), "--drop-height", "1e300")
    # sqrt(2 g h) = sqrt(2 x 9.80665 x 1e300) = 4.43e150 m/s; AISI 304: sqrt(193 GPa / 8000 kg/m^3) = 4912 m/s.
    message = "a drop of 1e+300 m gives an impact at 4.43e+150 m/s, which is not below the bar-wave speed"
    assert_one_line_error(code, out, err, f"argument --drop-height: {message} sqrt(E/rho) = 4912 m/s")
    assert not (tmp_path / "figures").exists()


def test_running_out_of_memory_is_one_line(capsys, monkeypatch, tmp_path):
    from ringchain.numerics.jobs import experiment

    def exhausted(*args, **kwargs):
        raise MemoryError

    monkeypatch.setattr(experiment, "run_experiment", exhausted)
    code, out, err = run(capsys, *SIMULATE, "--out", str(tmp_path / "run.csv"))
    assert_one_line_error(code, out, err, "ringchain simulate: error: out of memory; use fewer --rings, --samples")


# -- issue 24: sizes, durations, interruptions ------------------------------------------------------------
def test_a_chain_too_long_for_the_command_line_is_refused_before_it_is_built(capsys, tmp_path, no_work):
    # Issue 24, item 11: --rings 100000000 took 15.7 GB and 34 s before refusing; a chain file of 1e8 rings,
    # 2.8 GB and growing.  The refusal names the command line's limit and the way around it.
    code, out, err = run(capsys, "simulate", "--rings", "100000000", "--drop-height", "0.05", "--out",
                         str(tmp_path / "run.csv"))  # fmt: skip
    assert_one_line_error(code, out, err, "argument --rings: at most 1000000 rings from the command line (use "
                                          "ringchain.numerics.simulate for more), got 100000000")  # fmt: skip
    code, out, err = run(capsys, "sweep", "--rings", "20", "100000000", "--drop-height", "0.05")
    assert_one_line_error(code, out, err, "argument --rings: at most 1000000 rings")
    chain = tmp_path / "long.toml"
    chain.write_text("[[segment]]\nrings = 100000000\nR = 22.5e-3\nr = 2.5e-3\n")
    code, out, err = run(capsys, "simulate", "--chain", str(chain), "--drop-height", "0.05", "--out",
                         str(tmp_path / "run.csv"))  # fmt: skip
    assert_one_line_error(code, out, err, f"argument --chain: chain file {chain} has 100000000 rings; the command "
                                          "line builds chains of at most 1000000 rings")  # fmt: skip


def test_a_chain_that_cannot_fit_in_memory_is_refused_before_its_network_is_built(capsys, monkeypatch, tmp_path):
    # Issue 24, item 11: the estimate came after the network (and the memory) was built.  With 100 MB
    # available, the 2e6 sites of 1e6 rings need 3.2e8 bytes at 160 bytes per site: 305 MB of 2^20 bytes.
    from ringchain.numerics import RunTooLargeError
    from ringchain.numerics.engine import integrate

    monkeypatch.setattr(integrate, "_available_memory", lambda: 100 * 2**20)

    def built(self):
        raise AssertionError("the network was built")

    monkeypatch.setattr(Chain, "network", built)
    chain = Chain.from_ring(Ring.from_aspect_ratio(9.0), 1_000_000)
    with pytest.raises(RunTooLargeError, match=r"a model of 2000000 sites needs about 305 MB .* more than the 100 MB"):
        simulate(chain, 1e-3, drop_height=0.05)
    code, out, err = run(capsys, "simulate", "--rings", "1000000", "--drop-height", "0.05", "--out",
                         str(tmp_path / "run.csv"))  # fmt: skip
    # The command line's remedies name its own options (issue 31, item 7), not the Python API's.
    assert_one_line_error(code, out, err, "a run needs about 305 MB of memory, more than the 100 MB available; take "
                                          "fewer --rings, fewer --samples or a shorter --t-end")  # fmt: skip


def test_simulate_records_only_the_rings_it_writes(capsys, monkeypatch, tmp_path):
    # Issue 24, item 11: --rings 100000 recorded every ring (5.4 GB) though only two sensors are written.
    from ringchain.numerics.jobs import experiment

    recorded = []

    def spy(chain, t_end, **options):
        recorded.append(options["rings"])
        return simulate(chain, t_end, **options)

    monkeypatch.setattr(experiment, "simulate", spy)
    assert run(capsys, *SIMULATE, "--out", str(tmp_path / "run.csv"))[0] == 0
    assert recorded == [[2, 5, 7]]  # the two sensors and the top ring (the support's force)


def test_the_default_duration_grows_until_the_pulse_has_passed(capsys, tmp_path):
    # Issue 24, item 15: the default t_end ended inside the pulse on a 2-ring chain, and simulate stopped at "the
    # traces are written, but their leading pulses cannot be read".
    argv = ["--rings", "2", "--sensors", "0", "1", "--drop-height", "0.05", "--out", str(tmp_path / "run.csv")]
    code, out, err = run(capsys, "simulate", *argv)
    assert code == 0 and err == "", err
    assert "time of flight" in out


def test_radii_in_millimetres_are_refused_naming_the_unit(capsys, tmp_path):
    # Issue 31, item 4: --R 22.5 (mm as m) ran rings 45 m across and printed peaks of 1.5e9 N.
    code, out, err = run(capsys, "simulate", "--R", "22.5", "--r", "2.5", "--drop-height", "0.05", "--out",
                         str(tmp_path / "run.csv"))  # fmt: skip
    assert_one_line_error(code, out, err, "argument --R: R = 22.5 m is a ring over 1 m: radii are in m (22.5 mm is "
                                          "0.0225)")  # fmt: skip
    assert not (tmp_path / "run.csv").exists()


def test_ctrl_c_ends_in_one_line(capsys, monkeypatch, tmp_path):
    # Issue 24, item 10: Ctrl-C gave a traceback.
    from ringchain.numerics.jobs import experiment

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(experiment, "run_experiment", interrupted)
    code, out, err = run(capsys, *SIMULATE, "--out", str(tmp_path / "run.csv"))
    assert code == 130 and out == "" and err.strip() == "ringchain simulate: interrupted"


def test_a_reader_that_stops_early_ends_the_command_quietly():
    # Issue 24, item 15: `--json | head` printed "error: [Errno 32] Broken pipe" and Python's own complaint.
    program = ("import sys\n"
               "from ringchain.numerics.cli import commands as cli\n"
               "def info(args):\n"
               "    for k in range(200000):\n"
               "        print(k)\n"
               "    return 0\n"
               "cli._cache_info = info\n"
               "sys.exit(cli.main(['cache', 'info']))\n")  # fmt: skip
    with subprocess.Popen([sys.executable, "-c", program], stdout=subprocess.PIPE, stderr=subprocess.PIPE) as reader:
        first = reader.stdout.readline()
        reader.stdout.close()  # as head does after its lines
        stderr = reader.stderr.read()
        code = reader.wait(timeout=60)
    assert code == 141 and first == b"0\n"  # 128 + SIGPIPE, as a shell reports `yes | head`
    assert stderr == b""
