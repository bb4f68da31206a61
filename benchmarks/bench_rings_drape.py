"""Rigid rings in space: wall time, peak memory and final residual of the static drape of a chain-mail sheet.

A sheet of 4-in-1 chain mail (:meth:`~ringchain.numerics.Rings.mail`: the paper's steel ring, R/r = 9, ``--rows``
x ``--cols`` rings, the top row fixed) hung under gravity and solved for its static state by the solver of
:meth:`~ringchain.numerics.Rings.equilibrium` (``static_state`` of its module, which also returns the record of
its phases; ``--tol``: the largest residual force on a free ring, in weights m g; ``--iterations``: Newton
iterations per stage).  The kernels are compiled (or loaded from the disk cache) by the sheet's first
evaluation, timed apart.

Prints, per phase (in each stage of softened contacts, the L-BFGS descent then Newton's method), its iterations,
evaluations of the loads, wall and CPU time, the peak of the memory it allocated and the residual after it; then
the wall and CPU time of the whole solve, the peak of the memory it allocated (tracemalloc: NumPy's arrays
included), the peak resident memory of the process, and the largest residual force and torque on a free ring
(from a search of every contact from scratch) with the vertical load on the fixed rings against the weight of
the free ones.

Measured on a 2-core machine shared with other jobs (load average 3-5), ``--iterations 30`` unless said:

- 4 x 4 rings (76 candidate pairs), 200 iterations per stage: 13.7 s wall; the descents take 1,597, 103, 97 and 95
  steps (one evaluation each, 1,767 for the first), Newton's method 18, 21, 16 and 200 iterations (8,000
  evaluations, most of them the last stage's); residual 1.0e-4 m g, short of 1e-6 (Newton's method alone, same
  machine: 29 s, 1.6e-4 m g).
- 10 x 10 rings (718 pairs), on a quiet machine: 161 s wall, 161 s of CPU, 4 MB allocated at peak, 205 MB resident;
  residual 4.0e-3 m g (force; torque 1.6e-3 m g R), the fixed row carrying 90.000115 of the 90 weights. The
  descents: the budget of 5,000 steps to 0.20 m g (softening 1e-3) and to 8.4e-2 m g (1e-2), 1,163 and 567 steps to
  1e-2 m g (1e-1, 1); after each, Newton's method 30, 30, 28 and 30 iterations. Before the overdamped steps
  (``FORCED``) the first descent stopped at 0.18 m g after 1,779 steps and the run reached 1.2e-3 m g in 202 s on
  the loaded machine. Newton's method alone (50 iterations per stage): 3.4e3 m g.
- 30 x 30 rings (7,538 pairs): not solved. The descent of the softest stage (1e-3 of the stiffness) reaches 25.7 m g
  after 2,010 steps (226 s wall; 2,867 evaluations of some 50-80 ms on the loaded machine, 31 ms on a quiet one) and
  stops where no step along the loads lowers the energy or the residual; with overdamped steps there (``FORCED``) it
  runs its 5,000 steps (521 s) to 76 m g. The pose it leaves has rings deep in each other's tubes (at full stiffness
  the fixed row would carry 8e5 weights): the next stages cannot step from it (their residual grows tenfold with
  each stage, 7.7e4 m g at the end), 575 s wall, 412 s of CPU, 21 MB allocated at peak (Newton's sparse factors; a
  descent 2.6 MB), 310 MB resident. Newton's method alone (the run before this phase): 1017 s wall, stopped at 44 m
  g.

What is left. The loads are not the gradient of the energy where a pair's minima meet at a fold
(:func:`~ringchain.numerics.engine.rings_kernels.fold_weights` scales a contact's stiffness by a share that depends
on the pose, and the loads leave the share's derivative out, as the Hertz law of the curvatures leaves dK/dpose
out): there the line search of either phase finds no lower energy along the loads, and on the large sheet the
softest stage lets rings sink into one another before the stiffer stages can push them out. Loads that are the
gradient of the energy there (a kernel change), or stiffer first stages with shorter steps, are the next things to
measure.

Run: ``python benchmarks/bench_rings_drape.py [--rows 30] [--cols 30] [--tol 1e-6] [--iterations 30]
[--save pose.npz]``.
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
    parser.add_argument("--save", help="write the pose reached (centres, m; orientations) to this .npz file")
    parser.add_argument("--untraced", action="store_true", help="without tracemalloc (it slows the solver's "
                        "Python several times): no peak of the memory allocated")  # fmt: skip
    args = parser.parse_args()

    ring = Ring.from_aspect_ratio(9.0)
    start = time.perf_counter()
    sheet = Rings.mail(args.rows, args.cols, ring)
    sheet.potential(sheet.centres, sheet.orientations)  # compile (or load) the kernels
    warm_up = time.perf_counter() - start

    print(f"{args.rows} x {args.cols} chain mail, {len(sheet.pairs)} candidate pairs, tolerance {args.tol:g} m g")
    print(f"  build and compile or load of the kernels: {warm_up:.1f} s")
    if not args.untraced:
        tracemalloc.start()
    start, cpu = time.perf_counter(), time.process_time()
    centres, orientations, phases = static_state(sheet, force_tol=args.tol, max_iterations=args.iterations)
    wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    _, peak = tracemalloc.get_traced_memory()  # (0, 0) when not tracing
    tracemalloc.stop()
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**10  # kB -> MB (Linux)
    for p in phases:
        allocated = (p["memory"] or 0) / 2**20
        print(f"  {p['phase']:8s} softening {p['softening']:g}: {p['iterations']} iterations, {p['evaluations']} "
              f"evaluations, {p['wall']:.1f} s wall, {p['cpu']:.1f} s of CPU, {allocated:.1f} MB at peak, "
              f"residual {p['residual']:.2e} m g")  # fmt: skip
    print(f"  solve: {wall:.1f} s wall, {cpu:.1f} s of CPU")
    print(f"  memory: {peak / 2**20:.0f} MB allocated at peak during the solve; {rss:.0f} MB resident at peak")
    if args.save:
        np.savez(args.save, centres=centres, orientations=orientations)
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
