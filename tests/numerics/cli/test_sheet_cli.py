"""``ringchain sheet``: a run written to NetCDF and maps, and every bad input refused before work (exit code 2)."""

import numpy as np
import pytest
from ringchain.numerics import read_sheet_run
from ringchain.numerics.cli.commands import build_parser, main


def test_a_small_sheet_is_run_written_and_mapped(tmp_path, capsys):
    out, frames = tmp_path / "run.nc", tmp_path / "frames"
    code = main(
        [
            "sheet",
            "--pattern",
            "triangular",
            "--size",
            "6x5",
            "--pretension",
            "2",
            "--impact-velocity",
            "0.4",
            "--t-end",
            "2e-4",
            "--samples",
            "21",
            "--out",
            str(out),
            "--plot",
            str(frames),
            "--frames",
            "2",
        ]
    )
    assert code == 0
    printed = capsys.readouterr().out
    assert "triangular sheet of 6x5 rings" in printed and f"fields written to {out}" in printed
    data = read_sheet_run(out)
    assert data["link_force"].shape == (21, data.sizes["link"]) and data.attrs["rows"] == 6
    assert np.all(data["link_force"].values >= 0)  # links pull, never push
    assert sorted(p.name for p in frames.iterdir()) == ["frame_000.png", "frame_001.png"]


def test_a_hanging_sheet_drop(tmp_path, capsys):
    out = tmp_path / "hang.nc"
    code = main(["sheet", "--size", "4x3", "--hanging", "--struck", "bottom", "--drop-height", "0.01", "--t-end",
                 "2e-4", "--samples", "11", "--method", "verlet", "--out", str(out)])  # fmt: skip
    assert code == 0
    assert read_sheet_run(out).attrs["hanging"] == 1


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        (["--size", "40"], "argument --size: expected ROWSxCOLS"),
        (["--size", "1x4"], "at least 2 rows"),
        (["--size", "1000x1000"], "at most 250000"),
        (["--pretension", "-1"], "pretension must be non-negative"),
        (["--pretension", "1", "2", "3"], "one tension or 2"),
        (["--struck", "middle"], "argument --struck: expected an edge"),
        (["--struck", "3,3"], "is not on an edge"),
        (["--struck", "0,40"], "is not in a sheet of 20x20"),
        (["--hanging", "--boundary", "clamped"], "a hanging sheet takes free or periodic"),
        (["--boundary", "free"], "a flat sheet takes clamped or periodic"),
        (["--angle", "95"], "contact angle (deg) must lie in (0, 90]"),
        (["--pattern", "triangular", "--hanging"], "needs boundary='periodic'"),
        (["--samples", "2"], "n_samples must be at least 3"),
        # Issue 31, item 5: negative numbers are values (refused with a reason), not unknown options.
        (["--size", "-3x4"], "argument --size: a sheet needs at least 2 rows and 2 columns, got '-3x4'"),
        (["--struck", "-1,2"], "argument --struck: site (-1, 2) is not in a sheet of 20x20"),
        (["--struck", "0,0"], "argument --struck: site (0, 0) is a corner of the 20x20 sheet"),
        (["--boundary", "periodic"], "argument --struck: a periodic flat sheet has no edges"),
        (["--hanging", "--boundary", "periodic", "--struck", "left"], "the left edge of a periodic sheet wraps"),
        (["--struck", "left", "--impact-direction", "45"], "argument --impact-direction: a whole edge moves"),
        (["--impact-direction", "400"], "impact direction (deg) must lie in (-360, 360]"),
        (["--R", "22.5"], "argument --R: R = 22.5 m is a ring over 1 m: radii are in m (22.5 mm is 0.0225)"),
        (["--rtol", "1"], "argument --rtol: rtol must lie in"),
    ],
)
def test_bad_inputs_exit_with_code_2_and_one_line(tmp_path, capsys, arguments, message):
    out = tmp_path / "run.nc"
    code = main(["sheet", "--impact-velocity", "0.5", "--out", str(out), *arguments])
    error = capsys.readouterr().err
    assert code == 2 and message in error and error.count("\n") == 1
    assert not out.exists()  # refused before any work


def test_a_drop_needs_a_hanging_sheet_and_outputs_are_checked_first(tmp_path, capsys):
    assert main(["sheet", "--drop-height", "0.05", "--out", str(tmp_path / "a.nc")]) == 2
    assert "a drop needs a hanging sheet" in capsys.readouterr().err
    assert main(["sheet", "--impact-velocity", "0.5", "--out", str(tmp_path / "no" / "a.nc")]) == 2
    assert "does not exist" in capsys.readouterr().err


def test_sheet_is_a_subcommand_of_ringchain():
    help_text = build_parser().format_help()
    assert "sheet" in help_text


def test_outputs_keep_their_names_and_folders_are_not_chained(tmp_path, capsys):
    # Issue 31, items 5 and 7: NetCDF is not written to .txt; --plot deep/a/b does not create deep/ and deep/a/.
    assert main(["sheet", "--impact-velocity", "0.5", "--out", str(tmp_path / "o.txt")]) == 2
    assert "o.txt: a sheet's fields are written as NetCDF-4; name the file with .nc" in capsys.readouterr().err
    deep = tmp_path / "deep" / "a" / "b"
    assert main(["sheet", "--impact-velocity", "0.5", "--out", str(tmp_path / "a.nc"), "--plot", str(deep)]) == 2
    assert f"the folder {deep.parent} does not exist" in capsys.readouterr().err
    assert not (tmp_path / "deep").exists() and not (tmp_path / "a.nc").exists()


def test_help_names_the_struck_rings_not_ring_0(capsys):
    assert main(["sheet", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())  # argparse wraps its lines
    assert "ring 0" not in text and "impact speed of the struck rings" in text


def test_fewer_frames_replace_the_old_ones_and_a_direction_strikes_a_periodic_sheet(tmp_path):
    frames = tmp_path / "frames"
    common = ["sheet", "--size", "4x6", "--pretension", "2", "--boundary", "periodic", "--struck", "0,2",
              "--impact-direction", "-90", "--impact-velocity", "0.4", "--t-end", "1e-4", "--samples", "11",
              "--out", str(tmp_path / "run.nc"), "--plot", str(frames)]  # fmt: skip
    assert main([*common, "--frames", "3"]) == 0
    assert main([*common, "--frames", "2"]) == 0
    assert sorted(p.name for p in frames.iterdir()) == ["frame_000.png", "frame_001.png"]
    field = read_sheet_run(tmp_path / "run.nc")["impact_field"].values
    assert np.allclose(field[2], [0.0, -1.0], atol=1e-15)  # -90 deg: down, cos(-pi/2) = 6e-17
