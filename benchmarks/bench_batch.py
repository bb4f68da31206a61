"""256 drop heights integrated as one batch against 256 separate runs.

The paper's 20-ring chain (:func:`~ringchain.numerics.paper_chain`, R/r = 9, hanging under gravity)
is dropped from 256 heights between 5 mm and 0.5 m, for each lattice model:

- "batch": one :func:`~ringchain.numerics.simulate_batch` call, the 256 runs stacked
  into one (256, n_sites) array problem;
- "separate": 256 :func:`~ringchain.numerics.simulate` calls, one after another.

Both use the same integrator, duration and samples; the script prints both times,
their ratio (the target is at least 20x), and the largest relative difference between
the batch's and the separate runs' peak forces at rings 6 and 12 (with "verlet" and a
common step the two must agree to rounding).  The sweep engine
(:func:`ringchain.numerics.jobs.sweep`) batches with the fixed-step Verlet method by default,
because adaptive methods share one step size across the batch and every run's contact
openings shrink it (run with ``--method LSODA`` or ``--method DOP853`` to see the effect).

Every timing (the batch, and each separate run) is the best of ``--repeat`` (default 3),
so both sides see the same machine load; the load average is printed.  ``--subset k``
times only every k-th of the separate runs and scales by k (the runs cost about the same).

Run: ``python benchmarks/bench_batch.py [--method verlet] [--samples 2001] [--subset 1]``.
"""

from __future__ import annotations

import argparse
import functools
import os
import time

import numpy as np
from ringchain.numerics import paper_chain, simulate, simulate_batch

HEIGHTS = np.linspace(5e-3, 0.5, 256)  # m
T_END = 2e-3  # s: the leading pulse passes ring 12 within about 1.2 ms
SENSORS = (6, 12)


def best_of(repeat, func):
    best, result = np.inf, None
    for _ in range(repeat):
        start = time.perf_counter()
        result = func()
        best = min(best, time.perf_counter() - start)
    return best, result


def peaks(run):
    return np.array([run.peak_force(k) for k in SENSORS])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--method", default="verlet", help="integrator of both sides (default verlet)")
    parser.add_argument("--samples", type=int, default=1001, help="samples per run (default 1001, the sweep's)")
    parser.add_argument("--subset", type=int, default=1, help="time every k-th separate run and scale by k")
    parser.add_argument("--repeat", type=int, default=3, help="best of this many timings (default 3)")
    parser.add_argument("--models", nargs="+", default=["power-law", "dual-spring"])
    args = parser.parse_args()

    print(f"{len(HEIGHTS)} drop heights, 20 rings, method {args.method}, {args.samples} samples, t_end {T_END} s; "
          f"best of {args.repeat}; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")  # fmt: skip
    print(f"{'model':>12} {'batch (s)':>10} {'separate (s)':>13} {'ratio':>7} {'max rel. diff of peaks':>23}")
    for model in args.models:
        chain = paper_chain(model)
        options = {"n_samples": args.samples, "method": args.method}
        if args.method == "verlet":
            # One step for both sides (by default each call picks its own from its fastest impact).
            options["dt"] = simulate_batch(chain, T_END, drop_heights=HEIGHTS[-1:], n_samples=3,
                                           method="verlet").stats["dt"]  # fmt: skip
        simulate(chain, T_END, drop_height=HEIGHTS[0], **options)  # warm up (caches, imports)
        picked = HEIGHTS[:: args.subset]
        t_batch, batch = best_of(args.repeat, functools.partial(simulate_batch, chain, T_END, drop_heights=HEIGHTS,
                                                                **options))  # fmt: skip
        timed = [best_of(args.repeat, functools.partial(simulate, chain, T_END, drop_height=h, **options))
                 for h in picked]  # fmt: skip
        t_sep, runs = sum(t for t, _ in timed), [run for _, run in timed]
        t_sep *= len(HEIGHTS) / len(picked)
        diff = max(
            np.max(np.abs(peaks(run) / peaks(batch[i * args.subset]) - 1.0)) for i, run in enumerate(runs)
        )  # fmt: skip
        print(f"{model:>12} {t_batch:10.3f} {t_sep:13.2f} {t_sep / t_batch:6.1f}x {diff:23.2e}")


if __name__ == "__main__":
    main()
