"""A sheet's run estimate covers what ``ringchain sheet`` does (run, link forces, energies, file) and refuses in time.

Memory is measured here (tracemalloc: every NumPy array, the compiled kernels' outputs included); time is not (no
timed tests): benchmarks/bench_sheet_estimate.py compares the estimated and measured durations.
"""

import tracemalloc

import numpy as np
import pytest
from ringchain.numerics import RunTooLargeError, Sheet, estimate_run, simulate
from ringchain.numerics.cli import main
from ringchain.numerics.engine import integrate
from ringchain.numerics.engine.network import Network
from ringchain.theory import Ring

RING = Ring.from_aspect_ratio(9.0)


def _everything(sheet, path, samples):
    """What the command does: the run, its link forces and energies, its NetCDF file."""
    run = simulate(sheet, 5e-4, impact_velocity=0.5, n_samples=samples)
    run.link_force, run.energy()
    run.to_netcdf(path)


def test_the_estimate_is_within_1_5x_of_the_measured_peak_memory(tmp_path):
    _everything(Sheet.square(4, 4, RING, pretension=2.0, struck=[1]), tmp_path / "warm.nc", 11)  # imports, kernels
    for n, build in ((20, Sheet.square), (40, Sheet.triangular)):
        sheet = build(n, n, RING, pretension=2.0, struck=[n // 2])
        estimate = estimate_run(sheet, 5e-4, impact_velocities=[0.5], n_samples=201)
        tracemalloc.start()
        try:
            _everything(sheet, tmp_path / f"{n}.nc", 201)
            peak = tracemalloc.get_traced_memory()[1]
        finally:
            tracemalloc.stop()
        # The bound (estimated 1.39 GB against 3.96 GB measured before): within 1.5x either way.
        assert 1 / 1.5 < peak / estimate.memory < 1.5, (n, peak, estimate.memory)


@pytest.mark.parametrize("build", [Sheet.square, Sheet.triangular])
def test_building_a_sheet_takes_less_than_its_bytes_per_site(build):
    from ringchain.numerics.layouts.sheet import _BYTES_PER_SITE

    build(4, 4, RING, pretension=2.0)  # the contact law's fit, cached
    tracemalloc.start()
    try:
        build(60, 60, RING, pretension=2.0)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < _BYTES_PER_SITE * 3600  # the refusal below is not too eager (measured 510 and 700 per site)


def test_a_huge_sheet_is_refused_before_anything_is_allocated(monkeypatch):
    monkeypatch.setattr(integrate, "_available_memory", lambda: 16 * 2**30)

    def built(*args, **kwargs):
        raise AssertionError("the network was built")

    monkeypatch.setattr(Network, "__init__", built)
    with pytest.raises(RunTooLargeError, match=r"400000000 sites needs about 373 GB .* more than the 16 GB available"):
        Sheet.square(20000, 20000, RING)


def test_300x300_is_refused_naming_size_without_running(tmp_path, capsys, monkeypatch):
    # 300 x 300 took 3.96 GB (estimated 0.87 GB with the compiled fields); with 512 MB available the command refuses
    # before the run, naming --size.
    monkeypatch.setattr(integrate, "_available_memory", lambda: 2**29)

    def ran(*args, **kwargs):
        raise AssertionError("the run started")

    monkeypatch.setattr(integrate, "_compiled", ran)
    out = tmp_path / "big.nc"
    code = main(["sheet", "--size", "300x300", "--impact-velocity", "0.5", "--out", str(out)])
    error = capsys.readouterr().err
    assert code == 2 and error.count("\n") == 1, error
    assert "argument --size: this run needs about" in error and "more than the 512 MB available" in error
    assert "take a smaller --size, fewer --samples or a shorter --t-end" in error
    assert "rings=[" not in error and "n_samples" not in error  # the command's options, not the Python API's
    assert not out.exists()


def test_describe_counts_coordinates():
    sheet = Sheet.square(3, 4, RING, pretension=1.0, struck=[1])
    text = estimate_run(sheet, 1e-4, impact_velocities=[0.5], n_samples=11).describe()
    assert text.startswith("1 run(s) x 24 coordinates x 11 samples")  # 12 rings, two coordinates each
    assert np.isfinite(estimate_run(sheet, 1e-4, impact_velocities=[0.5]).seconds)
