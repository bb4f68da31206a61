"""Chain descriptions in TOML and ``ringchain simulate|sweep --chain FILE``."""

import csv
import io
import math

import numpy as np
import pytest
from ringchain.numerics import Chain, simulate
from ringchain.numerics.cli.commands import main
from ringchain.numerics.layouts.chain_file import parse_chain, read_chain_file, vary
from ringchain.theory import Ring

TWO_SEGMENTS = """
[[segment]]
rings = 5
R = 22.5e-3
r = 2.5e-3

[[segment]]
rings = 4
R = [22.5e-3, 12.5e-3]
r = 2.5e-3
angle = [90, 70]
profile = "geometric"
"""


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_a_description_gives_the_chain_of_its_rings():
    chain = parse_chain(TWO_SEGMENTS).chain("power-law", 0.37)
    R = np.r_[np.full(5, 22.5e-3), np.geomspace(22.5e-3, 12.5e-3, 4)]
    angles = np.r_[np.full(5, 90.0), np.geomspace(90, 70, 4)]  # degrees in the file, graded as R
    rings = [Ring(R=R[i], r=2.5e-3, angle=math.radians(angles[i])) for i in range(9)]
    assert chain == Chain.from_rings(rings, model="power-law", m_eff_ratio=0.37)


def test_a_uniform_description_is_the_uniform_chain():
    text = "[[segment]]\nrings = 6\nR = 22.5e-3\nr = 2.5e-3\nmaterial = 'stainless'\n"
    assert parse_chain(text).chain() == Chain.from_ring(Ring(22.5e-3, 2.5e-3), 6)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("[[segment]]\nrings = 4\nR = -1.0\nr = 2.5e-3\n", "segment 1, field 'R': R must lie in (0, inf], got -1"),
        (TWO_SEGMENTS + "[[segment]]\nrings = 2\nR = 0.02\n", "segment 3: field 'r' is missing"),
        (TWO_SEGMENTS.replace("rings = 4", "rings = 2.5"), "segment 2, field 'rings': rings must be an integer"),
        (TWO_SEGMENTS.replace("angle = [90, 70]", "angle = [90, 70, 50]"), "segment 2, field 'angle': must be a"),
        (TWO_SEGMENTS.replace("angle = [90, 70]", "angle = 95"), "segment 2, field 'angle': angle must lie in"),
        (TWO_SEGMENTS.replace('"geometric"', '"cubic"'), "segment 2, field 'profile': must be one of"),
        (TWO_SEGMENTS.replace("profile", "colour = 1\nprofile"), "segment 2: unknown field 'colour'"),
        ("[[segment]]\nrings = 4\nR = 0.02\nr = 2.5e-3\nmaterial = 'cheese'\n", "segment 1, field 'material'"),
        ("rings = 4\n", "unknown key 'rings'"),
        ("support = 'fixed'\n", "no [[segment]] tables"),
        ("[[segment]\n", "not valid TOML"),
    ],
)
def test_a_malformed_description_names_the_segment_and_the_field(text, message):
    with pytest.raises(ValueError, match=None) as error:
        parse_chain(text)
    assert message in str(error.value)


def test_rings_that_cannot_form_a_chain_are_named_by_segment():
    text = TWO_SEGMENTS.replace("R = [22.5e-3, 12.5e-3]", "R = [22.5e-3, 6e-3]").replace("angle = [90, 70]", "")
    with pytest.raises(ValueError, match=r"segment 2, field 'R': R/r = 2.4 \(ring 8\) is below 3"):
        parse_chain(text).chain()


def test_vary_sets_a_field_or_one_end_of_its_grading():
    base = parse_chain(TWO_SEGMENTS)
    assert vary(base, "2.R.last", 15e-3).segments[1].R == (22.5e-3, 15e-3)
    assert vary(base, "1.R.first", 20e-3).segments[0].R == (20e-3, 22.5e-3)
    assert vary(base, "1.rings", 7).n_rings == 11
    for spec, message in [("3.R", "there is no segment 3"), ("R", "SEGMENT.FIELD"), ("1.E", "must be one of"),
                          ("1.rings.last", "ring count is one number")]:  # fmt: skip
        with pytest.raises(ValueError, match=message):
            vary(base, spec, 1.0)
    with pytest.raises(ValueError, match="segment 1, field 'R': R must lie in"):
        vary(base, "1.R", -2.0)


def test_simulate_with_a_chain_file_is_the_library_run(capsys, tmp_path):
    path = tmp_path / "chain.toml"
    path.write_text(TWO_SEGMENTS)
    out_csv = tmp_path / "run.csv"
    argv = ["simulate", "--chain", str(path), "--drop-height", "0.05", "--model", "power-law", "--sensors", "2", "7",
            "--t-end", "1.5e-3", "--samples", "401", "--out", str(out_csv)]  # fmt: skip
    code, out, err = run(capsys, *argv)
    assert code == 0 and err == "", err
    chain = read_chain_file(path).chain("power-law")
    sim = simulate(chain, 1.5e-3, drop_height=0.05, n_samples=401)
    with open(out_csv) as handle:
        table = list(csv.reader(handle))
    assert table[0] == ["t_s", "sensor_ring2_N", "sensor_ring7_N", "support_N"]
    expected = np.column_stack([sim.t, sim.sensor(2), sim.sensor(7), sim.support_force])
    np.testing.assert_array_equal(np.array(table[1:], dtype=float), expected)  # 17 digits: exact
    assert "9 rings from chain file" in out and "support: largest force" in out


def test_sweep_varies_a_grading_parameter(capsys, tmp_path, notices):
    path = tmp_path / "chain.toml"
    path.write_text(TWO_SEGMENTS)
    argv = ["sweep", "--chain", str(path), "--vary", "2.R.last", "0.0125:0.0225:3", "--drop-height", "0.02", "0.05",
            "--model", "power-law", "--sensors", "2", "7"]  # fmt: skip
    code, out, err = run(capsys, *argv)
    assert code == 0 and err == "", err
    assert [line.split(" (")[0] for line in notices if line.startswith("sweep")] == ["sweep: 6 points in this process"]
    rows = list(csv.DictReader(io.StringIO(out)))
    assert [(float(r["2.R.last"]), float(r["drop_height_m"])) for r in rows] == [
        (0.0125, 0.02), (0.0125, 0.05), (0.0175, 0.02), (0.0175, 0.05), (0.0225, 0.02), (0.0225, 0.05)]  # fmt: skip
    assert all(float(r["support_peak_N"]) > 0 and math.isfinite(float(r["wave_speed_m_s"])) for r in rows)


def test_a_free_chain_runs_without_gravity_in_this_process(capsys, tmp_path):
    # Issue 24, item 15: support = "free" was documented but no command could run it (gravity always on);
    # sweep --chain --workers 0 was refused.
    path = tmp_path / "free.toml"
    path.write_text('support = "free"\n' + TWO_SEGMENTS)
    out_csv = tmp_path / "run.csv"
    code, out, err = run(capsys, "simulate", "--chain", str(path), "--impact-velocity", "1", "--no-gravity", "--model",
                         "power-law", "--sensors", "2", "7", "--samples", "401", "--out", str(out_csv))  # fmt: skip
    assert code == 0 and err == "", err
    assert "support:" not in out  # a free far end carries no support force
    table = np.loadtxt(out_csv, delimiter=",", skiprows=1)
    chain = read_chain_file(path).chain("power-law")
    sim = simulate(chain, table[-1, 0], impact_velocity=1.0, gravity=False, n_samples=401)
    np.testing.assert_array_equal(table[:, 1:], np.column_stack([sim.sensor(2), sim.sensor(7)]))  # 17 digits: exact
    code, out, err = run(capsys, "sweep", "--chain", str(path), "--impact-velocity", "1", "2", "--no-gravity",
                         "--workers", "0", "--sensors", "2", "7")  # fmt: skip
    assert code == 0 and err == "", err
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == 2 and rows[0]["support_peak_N"] == "" and float(rows[1]["peak_force_near_N"]) > 0


@pytest.mark.parametrize("encoding", ["utf-8-sig", "utf-16"])
def test_a_chain_file_with_a_byte_order_mark_is_read(tmp_path, encoding):
    # Issue 24, item 15: an editor's byte-order mark gave "Invalid statement (at line 1, column 1)".
    path = tmp_path / "chain.toml"
    path.write_text("# R in m, angle in \u00b0\n" + TWO_SEGMENTS, encoding=encoding)
    assert read_chain_file(path).segments == parse_chain(TWO_SEGMENTS).segments


def test_a_chain_file_that_is_not_utf8_is_refused_by_name(capsys, tmp_path):
    # Issue 24, item 15: "'utf-8' codec can't decode byte 0xb0", without the file's name.
    path = tmp_path / "latin.toml"
    path.write_bytes(("# angle in \u00b0\n" + TWO_SEGMENTS).encode("latin-1"))
    code, out, err = run(capsys, "simulate", "--chain", str(path), "--drop-height", "0.05", "--out",
                         str(tmp_path / "x.csv"))  # fmt: skip
    assert code == 2 and out == "" and err.count("\n") == 1
    assert f"argument --chain: {path}, line 1: byte 12 (0xb0) is not UTF-8 text" in err


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["simulate", "--chain", "/nonexistent/chain.toml", "--drop-height", "0.05", "--out", "x.csv"],
         "argument --chain: /nonexistent/chain.toml: cannot read the file (No such file or directory)"),
        (["simulate", "--chain", "{bad}", "--drop-height", "0.05", "--out", "x.csv"],
         "segment 2, field 'profile': must be one of"),
        (["simulate", "--chain", "{good}", "--drop-height", "0.05", "--R", "0.03", "--out", "x.csv"],
         "argument --R: not allowed with --chain"),
        # Issue 24, item 15: the remedy was "give --rings 13", which --chain refuses.
        (["simulate", "--chain", "{good}", "--drop-height", "0.05", "--out", "x.csv"],
         "sensor ring 12 is not in the 9 rings of chain file {good} (0..8); give sensors below 9 (--sensors 3 6, say), "
         "or a chain file of 13 rings or more"),
        (["sweep", "--chain", "{good}", "--drop-height", "0.05"], "sensor ring 12 is not in the 9 rings of chain file"),
        (["sweep", "--chain", "{good}", "--vary", "1.rings", "2", "--drop-height", "0.05", "--sensors", "2", "7"],
         "sensor ring 7 is not in the 6 rings of chain file"),
        (["sweep", "--chain", "{good}", "--vary", "1.rings", "2000000", "--drop-height", "0.05", "--sensors", "2", "7"],
         "argument --vary: the chain of 1.rings = 2e+06 has 2000004 rings; the command line builds chains of at most "
         "1000000 rings"),
        # Issue 24, item 15: --material was accepted silently when it named the default material.
        (["simulate", "--chain", "{good}", "--drop-height", "0.05", "--material", "stainless", "--out", "x.csv"],
         "argument --material: not allowed with --chain"),
        (["simulate", "--chain", "{good}", "--drop-height", "0.05", "--rings", "20", "--out", "x.csv"],
         "argument --rings: not allowed with --chain"),
        (["sweep", "--chain", "{good}", "--drop-height", "0.05", "--R-over-r", "9", "--sensors", "2", "7"],
         "argument --R-over-r: not allowed with --chain"),
        # Issue 24, item 8: the output overwrote the chain file.
        (["simulate", "--chain", "{good}", "--drop-height", "0.05", "--sensors", "2", "7", "--out", "{good}"],
         "argument --out: {good} is an input of this command and would be overwritten"),
        (["sweep", "--chain", "{good}", "--drop-height", "0.05", "--sensors", "2", "7", "--out", "{good}"],
         "argument --out: {good} is an input of this command and would be overwritten"),
        # Issue 24, item 15: a free far end could not be run (gravity always on).
        (["simulate", "--chain", "{free}", "--impact-velocity", "1", "--sensors", "2", "7", "--out", "x.csv"],
         'has support = "free": a chain with a free far end cannot hang under gravity; give --no-gravity'),
        (["sweep", "--chain", "{good}", "--vary", "2.R.last", "--drop-height", "0.05"], "give a field and at least"),
        (["sweep", "--chain", "{good}", "--vary", "4.R", "0.01", "--drop-height", "0.05", "--sensors", "2", "7"],
         "there is no segment 4"),
        (["sweep", "--vary", "2.R", "0.01", "--drop-height", "0.05"], "argument --vary: varies a field of a chain"),
        (["sweep", "--chain", "{good}", "--sensors", "2", "7"], "needs impacts: give --drop-height"),
    ],
)  # fmt: skip
def test_chain_file_errors_are_one_line_with_exit_code_2(capsys, tmp_path, argv, message):
    good, bad, free = tmp_path / "good.toml", tmp_path / "bad.toml", tmp_path / "free.toml"
    good.write_text(TWO_SEGMENTS)
    bad.write_text(TWO_SEGMENTS.replace('"geometric"', '"cubic"'))
    free.write_text('support = "free"\n' + TWO_SEGMENTS)
    argv = [a.format(good=good, bad=bad, free=free) if "{" in a else a for a in argv]
    message = message.format(good=good)
    argv = [str(tmp_path / a) if a == "x.csv" else a for a in argv]
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == "" and err.count("\n") == 1, err
    assert message in err, err
