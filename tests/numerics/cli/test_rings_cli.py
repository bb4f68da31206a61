"""``ringchain rings``: checks before any work (exit code 2, one line naming the option), small runs read back."""

import numpy as np
import pytest
from ringchain.numerics.cli import main
from ringchain.numerics.layouts.rings_files import read_rings_run


@pytest.mark.parametrize(
    ("argv", "names"),
    [
        (["--layout", "chain", "--rings", "1", "--static"], "argument --rings"),
        (["--layout", "mail", "--size", "3x3x3", "--static"], "argument --size"),
        (["--layout", "pam", "--size", "3x3", "--static"], "argument --size"),
        (["--layout", "chain", "--size", "3x3", "--static"], "argument --size"),
        (["--layout", "chain", "--R", "0.005", "--static"], "arguments --R and --r"),
        (["--layout", "mail", "--R", "0.01", "--static"], "arguments --R and --r"),
        (["--layout", "chain", "--impact-velocity", "-1"], "argument --impact-velocity"),
        (["--layout", "chain", "--impact-velocity", "1e4"], "argument --impact-velocity"),
        (["--layout", "chain"], "--impact-velocity"),  # a load is required
    ],
)
def test_bad_options_exit_2_naming_the_option(tmp_path, capsys, argv, names):
    out = tmp_path / "run.nc"
    assert main(["rings", *argv, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert names in err and "\n" not in err
    assert not out.exists()  # nothing written: checked before any work


def test_static_chain_writes_netcdf_and_vtk(tmp_path, capsys):
    out, folder = tmp_path / "run.nc", tmp_path / "frames"
    assert (
        main(["rings", "--layout", "chain", "--rings", "3", "--static", "--out", str(out), "--vtk", str(folder)]) == 0
    )
    run = read_rings_run(out)
    assert run["centre"].shape == (1, 3, 3) and run["fixed"].values.tolist() == [0, 0, 1]
    # The static chain hangs below its rest pose (just touching) by the contacts' approaches: down, not up.
    assert np.all(run["centre"].values[0, :2, 2] < 2 * (22.5e-3 - 2.5e-3) * np.arange(2) + 1e-15)
    assert (folder / "rings.pvd").exists() and (folder / "rings_0000.vtu").exists()
    assert "run written to" in capsys.readouterr().out


def test_struck_chain_records_link_forces(tmp_path):
    out = tmp_path / "run.nc"
    argv = ["rings", "--layout", "chain", "--rings", "3", "--impact-velocity", "0.1", "--t-end", "2e-5",
            "--samples", "5", "--out", str(out)]  # fmt: skip
    assert main(argv) == 0
    run = read_rings_run(out)
    assert run["link_force"].shape == (5, 2) and run.attrs["impact_velocity_m_s"] == 0.1
    assert float(run["link_force"].max()) > 0  # the struck ring pulls its link within 20 us at 0.1 m/s
