"""Rigid rings in space: wall time, peak memory and final residual of the static drape of a chain-mail sheet.

A sheet of 4-in-1 chain mail (:meth:`~ringchain.numerics.Rings.mail`: the paper's steel ring, R/r = 9, ``--rows``
x ``--cols`` rings, the top row fixed) hung under gravity and solved for its static state by
:meth:`~ringchain.numerics.Rings.equilibrium` (``--tol``: the largest residual force on a free ring, in weights
m g; ``--iterations``: Newton iterations per stage).  The kernels are compiled (or loaded from the disk cache)
by the sheet's first evaluation, timed apart.

Prints the wall and CPU time of the solve, the peak of the memory it allocated (tracemalloc: NumPy's arrays
included), the peak resident memory of the process, and the largest residual force and torque on a free ring
(from a search of every contact from scratch) with the vertical load on the fixed rings against the weight of
the free ones.  When the solver stops short, its message gives the residual it reached.

Measured on a 2-core machine shared with other jobs (load average 4-5), 30 x 30 rings (7,538 candidate pairs),
``--iterations 30`` (120 Newton iterations in all): 1017 s wall, 237 s of CPU, 20 MB allocated at peak, 245 MB
resident; it stopped at a residual force of 9.6 N (44 m g), far from the static state.  Smaller sheets, 200
iterations per stage: 2 x 3 rings reach 1.3e-9 m g (their fixed row carries 3.0000000026 weights), 4 x 4 rings
2.9e-5 m g in 57 s, 3 x 3 rings 2.9e-3 m g in 30 s.  What is left: a minimum of the distance next to a maximum,
both in overlap (tubes nearly parallel over an arc), is found or missed by the contact search as the pose changes
by a rounding error; :func:`~ringchain.numerics.engine.rings_kernels.fold_weights` makes its share of the force
small there, not zero, and each Newton iteration of the sheet costs some 100 evaluations of its 7,538 pairs.

Run: ``python benchmarks/bench_rings_drape.py [--rows 30] [--cols 30] [--tol 1e-6] [--iterations 30]``.
"""

from __future__ import annotations

import argparse
import resource
import time
import tracemalloc

import numpy as np
from ringchain.numerics import Rings
from ringchain.numerics.layouts.rings_static import static_state
from ringchain.theory import STANDARD_GRAVITY, Ring


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=30)
    parser.add_argument("--cols", type=int, default=30)
    parser.add_argument("--tol", type=float, default=1e-6, help="residual force, in weights m g")
    parser.add_argument("--iterations", type=int, default=30, help="Newton iterations per stage")
    args = parser.parse_args()

    ring = Ring.from_aspect_ratio(9.0)
    start = time.perf_counter()
    sheet = Rings.mail(args.rows, args.cols, ring)
    sheet.potential(sheet.centres, sheet.orientations)  # compile (or load) the kernels
    warm_up = time.perf_counter() - start

    print(f"{args.rows} x {args.cols} chain mail, {len(sheet.pairs)} candidate pairs, tolerance {args.tol:g} m g")
    print(f"  build and compile or load of the kernels: {warm_up:.1f} s")
    tracemalloc.start()
    start, cpu = time.perf_counter(), time.process_time()
    centres, orientations, phases = static_state(sheet, force_tol=args.tol, max_iterations=args.iterations)
    wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**10  # kB -> MB (Linux)
    for p in phases:
        print(f"  {p['phase']:8s} softening {p['softening']:g}: {p['iterations']} iterations, {p['evaluations']} "
              f"evaluations, {p['wall']:.1f} s wall, {p['cpu']:.1f} s of CPU, {p['memory'] / 2**20:.1f} MB at peak, "
              f"residual {p['residual']:.2e} m g")  # fmt: skip
    print(f"  solve: {wall:.1f} s wall, {cpu:.1f} s of CPU")
    print(f"  memory: {peak / 2**20:.0f} MB allocated at peak during the solve; {rss:.0f} MB resident at peak")
    _, forces, torques = sheet.potential(centres, orientations)  # every contact searched from scratch
    weight = ring.mass * STANDARD_GRAVITY
    free = ~sheet.fixed
    force, torque = np.abs(forces[free]).max() / weight, np.abs(torques[free]).max() / (weight * ring.R)
    verdict = "converged" if max(force, torque) <= args.tol else "not converged"
    print(f"  largest residual on a free ring: force {force:.2e} m g, torque {torque:.2e} m g R ({verdict})")
    print(f"  vertical load on the fixed rings {-forces[sheet.fixed, 2].sum() / weight:.6f} m g, weight of the "
          f"free rings {free.sum()} m g")  # fmt: skip


if __name__ == "__main__":
    main()
