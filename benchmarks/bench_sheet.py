"""A 100 x 100 square sheet, 2 ms after a point impact: wall time and peak memory of each method.

The sheet: rings of R/r = 9 (the paper's, AISI 304), m_eff = 0.37 m0, lying flat with every link
pretensioned to 2 N, its edges clamped; the middle site of the bottom edge struck at 0.5 m/s.  Each
method integrates 2 ms and records every site at 201 samples; printed: wall time, right-hand-side
evaluations (steps for Verlet), the peak memory NumPy and Python allocated during the run
(tracemalloc), the largest link force and the energy drift.  The issue's goal (<= 20 s) is for the
compiled "dopri5" of issue 20, timed here once ``ringchain.numerics.METHODS`` has it.

Run: ``python benchmarks/bench_sheet.py [--size 100] [--t-end 2e-3] [--methods verlet odeint dopri5]``.
Timings on a shared machine are noisy; the ratios within one run are what to compare.
"""

from __future__ import annotations

import argparse
import time
import tracemalloc

import numpy as np
from ringchain.numerics import METHODS, Sheet, simulate
from ringchain.theory import Ring


def build(size):
    sheet = Sheet.square(size, size, Ring.from_aspect_ratio(9.0), pretension=2.0, m_eff_ratio=0.37)
    return sheet.struck_at([sheet.site(0, size // 2)])


def measure(sheet, method, t_end):
    tracemalloc.start()
    start = time.perf_counter()
    run = simulate(sheet, t_end, impact_velocity=0.5, method=method, n_samples=201, max_seconds=None)
    seconds = time.perf_counter() - start
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    energy = run.energy()
    impact = 0.5 * sheet.m * 0.5**2
    drift = float(np.max(np.abs(energy.total - energy.total[0])) / impact)
    return seconds, run.stats.get("nfev"), peak, float(run.link_force.max()), drift


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--size", type=int, default=100)
    parser.add_argument("--t-end", type=float, default=2e-3)
    parser.add_argument("--methods", nargs="+", default=["verlet", "odeint", "dopri5"])
    args = parser.parse_args()
    start = time.perf_counter()
    sheet = build(args.size)
    print(f"{args.size} x {args.size} square sheet: {sheet.n_sites} rings, {sheet.n_links} links, built in "
          f"{time.perf_counter() - start:.2f} s; {args.t_end * 1e3:g} ms after a point impact at 0.5 m/s")  # fmt: skip
    times = {}
    for method in args.methods:
        if method not in METHODS:
            print(f"{method:>8}: not available yet (ringchain.numerics.METHODS = {METHODS})")
            continue
        seconds, nfev, peak, force, drift = measure(sheet, method, args.t_end)
        times[method] = seconds
        print(f"{method:>8}: {seconds:8.1f} s, {nfev} evaluations, peak memory {peak / 2**20:.0f} MB, "
              f"largest link force {force:.4g} N, energy drift {drift:.2g} of the impact")  # fmt: skip
    if "dopri5" in times:
        for method, seconds in times.items():
            if method != "dopri5":
                print(f"ratio {method}/dopri5: {seconds / times['dopri5']:.1f}")


if __name__ == "__main__":
    main()
