"""``fit speed`` of the package's own sweeps: the lattice as forward model recovers the m_eff/m0 that made them."""

import json

import numpy as np
import pytest
from ringchain.numerics import fit_speed_lattice, read_speed_amplitude, sweep, write_csv
from ringchain.numerics.cli import main
from ringchain.numerics.jobs.sweep import Point


def _sweep_file(tmp_path, model, ratio, heights=(0.01, 0.1, 0.3), rings=20):
    rows = sweep([Point(R_over_r=9.0, model=model, n_rings=rings, m_eff_ratio=ratio, drop_height=h) for h in heights],
                 max_workers=0)  # fmt: skip
    path = tmp_path / f"sweep_{model}_{ratio}.csv"
    write_csv(rows, path)
    return path


@pytest.mark.parametrize(("model", "ratio"), [("power-law", 0.37), ("dual-spring", 0.6)])
def test_fit_speed_of_a_sweep_recovers_its_m_eff_ratio(tmp_path, capsys, model, ratio):
    path = _sweep_file(tmp_path, model, ratio)
    assert main(["fit", "speed", str(path), "--json"]) == 0
    fit = json.loads(capsys.readouterr().out)
    low, high = fit["intervals_95"]["m_eff_ratio"]
    assert low <= ratio <= high  # the truth inside the 95 % interval (the issue: excluded, 4.4 % high)
    # The interval is no wider than the engine's resolution allows: 2e-5 relative standard error at least
    # (LATTICE_SPEED_RESOLUTION), t_{0.975, 2} = 4.3: under 1e-3 relative half-width.
    assert high - low < 2e-3 * ratio
    # The paper's route on the same pairs: biased high, beyond the lattice fit's interval (1-10 %: the forming pulse).
    assert fit["fixed"]["eq8_m_eff_ratio"] > high
    if model == "power-law":  # (Eq. (8)'s shape misses the dual-spring chain's three speeds: its fit refuses them)
        assert main(["fit", "speed", str(path), "--eq8", "--json"]) == 0
        eq8 = json.loads(capsys.readouterr().out)
        assert eq8["intervals_95"]["m_eff_ratio"][0] > ratio
        # The same least squares, closed form against lmfit's (stopped within its ftol of 1e-8 of the minimum).
        assert fit["fixed"]["eq8_m_eff_ratio"] == pytest.approx(eq8["values"]["m_eff_ratio"], rel=1e-5)
    assert 0.01 < fit["fixed"]["eq8_bias"] < 0.10


def test_a_sweep_at_the_default_ratio_is_fitted_not_refused(tmp_path, capsys):
    # The README's "ringchain fit speed sweep.csv": a sweep's default m_eff/m0 is 1, which Eq. (8) reads as 1.05
    # and refused as "m/s read as km/s"; the lattice's speeds give 1.
    path = _sweep_file(tmp_path, "power-law", 1.0, heights=(0.02, 0.2, 0.5))
    assert main(["fit", "speed", str(path)]) == 0
    assert "m_eff_ratio  1 " in capsys.readouterr().out


def test_the_forward_model_is_the_lattice_not_eq8(tmp_path):
    # The Python API on three pairs; the fit ends at a fixed point, where the runs at the fitted ratio reproduce the
    # pairs to the integrator's accuracy (relative 1e-9 measured; 1e-6 allowed).
    path = _sweep_file(tmp_path, "power-law", 0.5, heights=(0.05, 0.1, 0.3), rings=20)
    F, V, _ = read_speed_amplitude(path, geometry=True)
    points = [Point(R_over_r=9.0, model="power-law", n_rings=20, drop_height=h) for h in (0.05, 0.1, 0.3)]
    fit = fit_speed_lattice(F, V, points)
    assert fit.values["m_eff_ratio"] == pytest.approx(0.5, rel=1e-6)
    assert np.all(np.abs(fit.residual) < 1e-6 * V)
