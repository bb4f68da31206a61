"""The run estimate of ``ringchain sheet`` against what the command takes: duration and peak memory at two sizes.

Each size: a square sheet (R/r = 9, m_eff = 0.37 m0, 2 N per link, clamped) struck in the middle of its bottom
edge at 0.5 m/s, 1 ms at 201 samples (the command's defaults), then its link forces, energies and NetCDF file, as
the command does.  Printed per size: the estimate (:func:`ringchain.numerics.estimate_run`: ``seconds`` and
``memory``), the measured processor time of the whole (``time.process_time``: the work, not this machine's
share of it under load) and wall time, the peak memory (tracemalloc), and their ratios.  The issue's bounds:
memory within 1.5x (tested in tests/numerics/test_sheet_estimate.py), time within 3x (here: timings belong in
benchmarks).

Run: ``python benchmarks/bench_sheet_estimate.py [--sizes 60 120]``.
"""

from __future__ import annotations

import argparse
import tempfile
import time
import tracemalloc
from pathlib import Path

from ringchain.numerics import Sheet, estimate_run, simulate
from ringchain.theory import Ring

RING = Ring.from_aspect_ratio(9.0)


def command(sheet, path):
    run = simulate(sheet, 1e-3, impact_velocity=0.5, n_samples=201)
    run.link_force, run.energy()
    run.to_netcdf(path)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[60, 120])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        command(Sheet.square(4, 4, RING, pretension=2.0, struck=[1]), Path(folder) / "warm.nc")  # compile, import
        for n in args.sizes:
            sheet = Sheet.square(n, n, RING, pretension=2.0, m_eff_ratio=0.37, struck=[n // 2])
            estimate = estimate_run(sheet, 1e-3, impact_velocities=[0.5], n_samples=201)
            tracemalloc.start()
            cpu, wall = time.process_time(), time.perf_counter()
            command(sheet, Path(folder) / f"{n}.nc")
            cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
            peak = tracemalloc.get_traced_memory()[1]
            tracemalloc.stop()
            print(f"{n}x{n}: estimated {estimate.seconds:.3g} s, {estimate.memory / 2**20:.4g} MB; measured "
                  f"{cpu:.3g} s of processor ({wall:.3g} s wall), {peak / 2**20:.4g} MB peak; time ratio "
                  f"{cpu / estimate.seconds:.2f}, memory ratio {peak / estimate.memory:.3f}")  # fmt: skip


if __name__ == "__main__":
    main()
