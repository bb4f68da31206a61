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
