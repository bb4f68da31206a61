"""Rigid rings in space: wall time, peak memory and final residual of the static drape of a chain-mail sheet.

A sheet of 4-in-1 chain mail (:meth:`~ringchain.numerics.Rings.mail`: the paper's steel ring, R/r = 9, ``--rows``
x ``--cols`` rings, the top row fixed) hung under gravity and solved for its static state by the solver of
:meth:`~ringchain.numerics.Rings.equilibrium` (``static_state`` of its module, which also returns the record of
its phases; ``--tol``: the largest residual force on a free ring, in weights m g; ``--iterations``: Newton
iterations per stage).  The kernels are compiled (or loaded from the disk cache) by the sheet's first
evaluation, timed apart.

Prints, per phase (in each stage of softened contacts, the preconditioned L-BFGS descent, then Newton's method
where the descent stops short), its iterations, evaluations of the loads, wall and CPU time, the peak of the memory
it allocated and the residual after it; then the wall and CPU time of the whole solve, the peak of the memory it
allocated (tracemalloc: NumPy's arrays included; ``--untraced`` leaves it out, as tracemalloc slows the solver's
Python 3.5-4.7 times on these sheets), the peak resident memory of the process, and the largest residual force and
torque on a free ring (from a search of every contact from scratch) with the vertical load on the fixed rings
against the weight of the free ones.

Measured on a 2-core machine shared with other jobs (load average 4-7), the solver of this version (the loads the
energy's gradient, the descent preconditioned by the stiffness matrix and run to each stage's tolerance; its finite
differences and factorisations checked, below):

- 4 x 4, ``--untraced``: 1.7 s wall and of CPU, 189 MB resident; residual 9.2e-7 m g (torque 1.3e-7 m g R); the
  descents take 651, 14, 13 and 32 steps (1,639, 77, 76 and 100 evaluations).
- 10 x 10, ``--untraced``: 19.7 s wall, 19.5 s of CPU, 206 MB resident; residual 7.8e-7 m g (torque 6.1e-7 m g R),
  the fixed row carrying 90.000002 of the 90 weights; the descents 1,634, 40, 18 and 58 steps (4,431, 133, 111 and
  162 evaluations).
- 30 x 30 (7,538 pairs), ``--untraced``, the whole drape from the start: solved, residual 7.8e-7 m g (torque
  4.3e-7 m g R), the fixed row carrying 870.000000 of the 870 weights; 2,546 s wall (load 4-7), 1,647 s of CPU,
  464 MB resident at peak (with the checks of the run described below wrapped round the solver, which cost little
  beside the evaluations).  The softest stage's descent runs 6,094 steps (18,966 evaluations; 711 s of CPU) to
  16.6 m g and its Newton iterations (30, 1,677 evaluations, 58 s) to 1.0 m g; the next stage's descent 3,801 steps
  (17,136 evaluations, 710 s) to 3.3e-5 m g; the last two 206 and 443 steps (2,089 and 1,788 evaluations, 89 s and
  79 s) to 7.5e-4 and 7.8e-7 m g.  Newton's method is needed only in the softest stage.

Before the checks:

- 4 x 4 rings (76 candidate pairs), ``--untraced``: 5.6 s wall, 2.7 s of CPU, 188 MB resident; residual 3.6e-7 m g
  (torque 2.7e-8 m g R); the descents take 828, 14, 13 and 32 steps (2,212, 76, 75 and 101 evaluations, the
  preconditioner's finite differences included), Newton's method is not needed.  Traced: 23.6 s wall, 12.7 s of
  CPU, 0.5 MB allocated at peak.
- 10 x 10 rings (718 pairs), ``--untraced``: 25.7 s wall, 22.2 s of CPU, 210 MB resident; residual 3.9e-7 m g
  (torque 1.3e-7 m g R), the fixed row carrying 90.000000 of the 90 weights; the descents 2,108, 40, 18 and 59 steps
  (6,161, 132, 110 and 162 evaluations).  Traced: 144 s wall, 79 s of CPU, 3.2 MB allocated at peak.
- 30 x 30 rings (7,538 pairs), ``--untraced``, with the search before its look between samples: not solved.  The
  descent of the softest stage
  runs 9,723 steps (33,252 evaluations, the preconditioner's included; 1,215 s of CPU, 1,649 s wall) to 10.4 m g
  and stops where no step lowers the energy or the residual; the stiffer stages cannot step from there (their
  descents give up at once, Newton's method keeps the residual, 1.04e4 m g at the end: the pose of the softest
  stage, whose approaches are a hundred times those at full stiffness).  1,770 s wall, 1,334 s of CPU, 598 MB
  resident at peak.  Why it stops (the pose saved and searched again): the two worst rings (752 and 782, 10.4 m g
  each) are a pair whose distance has twin minima, 0.043 r and 0.040 r deep, on either side of a maximum 0.039 r
  deep (in overlap); the cold search finds only the first, because the second lies 0.086 rad (0.88 of the scan's
  spacing h = 2 pi / 64) from the maximum and the first 0.132 rad, farther than the h/2 within which an
  inflection starts the finer look.  Moves of either ring along its loads by 1e-7 r to 1e-3 r, either way, find
  both, and the energy there is 6.1e-5 J higher: the descent has walked into a pose where a contact is missed, and
  every trial step out of it is rejected.  With the search that looks between two samples where g' may dip
  (:mod:`ringchain.numerics.engine.rings_kernels`: a minimum and its maximum between the same two samples), that
  pose's residual is 15.4 m g, every minimum found, and the softest stage's descent moves on from it: 500 steps (in
  fresh descents of 100: 0.22, 3.0, 0.80, 0.033 and 0.0039 m g after each; 1,527 evaluations, 72 s of CPU, 200 s
  wall at load 5-9).

The solver before (Newton's method after a descent handed over at 1e-2 m g, the loads missing the derivatives of
Hertz's K_c and of the shares of twin contacts; traced, ``--iterations 30`` unless said): 4 x 4 (200 iterations
per stage) 1.0e-4 m g in 13.7 s, the last stage's Newton iterations stalling; 10 x 10 4.0e-3 m g in 161 s (4 MB
allocated at peak, 205 MB resident); 30 x 30 not solved: the softest stage's descent stopped at 26-76 m g with rings
deep in each other's tubes, and the stiffer stages could not step from there (7.7e4 m g at the end, 575 s wall,
412 s of CPU, 21 MB allocated at peak, 310 MB resident); Newton's method alone stopped at 44 m g after 1017 s.
With the loads the energy's gradient but the descent not preconditioned, a 4 x 4 sheet reaches 9.3e-7 m g by the
descents alone in 37 s of CPU (17,000 steps at full stiffness), and the old Newton's polish of the last stage
stalls at 2.6e-4 m g (a contact barely closed makes its model fail for steps longer than its approach).

The whole 30 x 30 drape again, ``--untraced``, with the search's first version (g'' at every sample, and the
Hermite test taking the other root where the model's leading coefficient is negative, so that it missed a minimum and
its maximum between two samples where g' < 0 at both): not solved.  The softest stage's descent ran 16,578 steps
(40,276 evaluations; 1,895 s of CPU, 4,858 s wall at load 5-9) to 12.5 m g and stopped; the stiffer stages could not
step from there (1.35e4 m g at the end); 5,011 s wall, 1,972 s of CPU, 606 MB resident at peak.  On the pose where
it stopped that version misses 10 of the 5,927 minima of the sheet's 3,861 pairs within 2 mm (a profile sampled at
2^13 points; the version here misses none): the residual there is 32.0 m g with every minimum found, and 200 steps of
the softest stage's descent from it (fresh descents of 100) reach 5.1 and 5.7 m g.

The whole 30 x 30 drape with this version of the search, from the start, ``--untraced``: stopped after some 39 min of
CPU (613 MB resident) on BLAS's complaints from inside SuperLU ("On entry to DTRSV parameter number 6 had an illegal
value", and DGEMV's parameter 2: an illegal leading dimension and a negative row count, which its BLAS prints and
ignores).  Run again (the factorisations already refused as below) with every factorisation and every evaluation checked
(finite entries, size, largest and smallest diagonal, the factor's fill, a probe solve; the pose and matrix saved): no
matrix had an entry not finite, but from 677 s of CPU on (the softest stage's Newton iterations, its descent having
stopped at about 5 m g) every stiffness matrix held entries of 4.6e148 (builds 70-79, till that run was stopped at
790 s).  Their cause: Hertz's stiffness of the curvatures, whose ellipse the compiled law caps at ln(B/A) = 690 when a
law's row gives no cap (the rows of rigid rings give none), so that a contact whose smaller curvature sum A turns
negative gets K_c some 1e150 times its size: a cliff of the energy.  Trial poses of the descent met such cliffs from its
first minute (energies of 1e132-1e144 J, loads up to 1e149 m g; rejected by the line search), and a finite difference
of the stiffness matrix across one put 1e141 m g over 1e-7 r into the matrix; the pin of the spins copied it into every
ring's block, the shifts of the preconditioner began at 1e140 and Newton's steps shrank to nothing, each accepted and
each costing a new matrix (builds 70-79 at one pose).  At an earlier base pose (build 6) the contact of rings 726 and
756, its A/B = 4.3e-5 at a crossing of 38.7 degrees, gave the matrix a real 5.8e8 (the energy's change over 1e-9 to
1e-6 r matching the trapezoid rule on the loads to 1e-4 or better), with a cliff 1e-4 r away (2.5e142 J).  No small
matrix reproduced the BLAS errors (NaN or infinite entries anywhere, entries up to 1e300, the saved 5,220-unknown
matrix with its spins pinned at 1e100-1e156: SuperLU reports a singular factor or solves), so the path from these
matrices to the errors is inferred, not shown.  Now (rings_static module notes): a finite difference whose change of the
energy misses the trapezoid rule is taken backward, or left out; and a factorisation is refused where its matrix or its
probe solve is not finite or the probe's backward error exceeds 1e-8, the callers shifting as for a matrix not positive
definite.

The whole drape with these checks, from the start, ``--untraced`` (load 4-7 beside the suite's run): no matrix with an
entry not finite or above 1e8 (the largest of every 20th build: 7.7e4), no probe solve not finite, no message of BLAS,
no difference left out; solved (the figures at the top).  At the pose where the softest stage's descent stopped, 6 of
the 108 columns of the stiffness matrix (18 colours) crossed a cliff forward (the energy's change 2e133 J against the
trapezoid rule's 1e131 J, differences of the loads of 3.9e149) and were taken backward, where they match the trapezoid
rule to 3e-16 J of changes of 5e-11 to 3e-10 J.

The cliffs removed in the engine: the rigid rings' law bounds Hertz's stiffness where A -> 0 by the quartic term
of the gap along the flat direction (:func:`~ringchain.numerics.engine.rings_law.contact_stiffness`: Hertz's K of an
effective curvature A_eff(A, C delta), the force the derivative of the stored energy 2/5 K delta^(5/2); within 4 per
cent of the half-space solver's force on the quartic gap for A/sqrt(C delta) >= -0.25, the table in the module notes
of rings_law).  Counting the solver's evaluations whose energy exceeds 1e10 J (a wrapper round its evaluation, not
kept), ``--untraced``, the machine shared (load 3-5), before and after, at one commit apart:

- 4 x 4: before 5.4 s wall, 2.7 s of CPU, residual 9.2e-7 m g (torque 1.3e-7 m g R); 1,302 evaluations at searched
  poses (bases and trial poses) and 590 of the finite differences, none above 1e10 J (the largest 0.12 J).  After 6.1
  and 4.6 s wall (two runs), 3.0 s of CPU, residual 8.7e-7 m g (torque 3.5e-7 m g R); 1,825 and 657 evaluations, none
  above 1e10 J (the largest 0.17 J); the softest stage's descent 702 steps (2,231 evaluations) against 651 (1,639):
  the bounded law changes its path, where contacts softened a thousandfold approach ten times deeper and more of them
  feel C.
- 10 x 10: before 35.6 and 38.1 s wall (two runs), 22.1 and 24.1 s of CPU, residual 7.8e-7 m g (torque 6.1e-7 m g R);
  3,259 and 1,578 evaluations, 14 of the searched poses above 1e10 J (the largest 3.7e141 J: the cliff, rejected by
  the line search). After 44.9 and 34.7 s wall, 24.4 and 23.7 s of CPU, residual 2.7e-7 m g (torque 7.7e-8 m g R), the
  fixed row carrying 90.000000 of the 90 weights; 3,096 and 1,742 evaluations, none above 1e10 J (the largest 0.20 J);
  the descents 1,810, 40, 18 and 62 steps (4,415, 133, 111 and 179 evaluations).  The time is the same within the
  machine's noise: 14 of 4,837 evaluations were all the cliff cost here; on the 30 x 30 sheet it also put 1e148 in the
  stiffness matrices, now refused by the checks above.
- 30 x 30, ``--untraced``, the whole drape from the start with the bounded law (and the smaller compile of the
  integrators): solved, residual 7.4e-7 m g (torque 6.5e-7 m g R), the fixed row carrying 870.000000 of the 870
  weights; 1,066 s wall (65 s of it the kernels' compile; two other jobs beside it for the first half, then alone),
  815 s of CPU, 512 MB resident at peak.  Every stage settles by its descent alone, no Newton phase: 6,935, 223, 257
  and 306 steps (15,387, 634, 1,384 and 1,394 evaluations; 615, 28, 63 and 65 s of CPU) to 7.7e-4, 8.8e-4, 9.9e-4
  and 7.4e-7 m g.  Before the bounded law (above): 1,647 s of CPU, the softest stage's descent stopping at 16.6 m g
  and needing Newton's method, the next stage's descent 3,801 steps.
- The same with the law made continuous through the circle B = A (its B moved with A_eff; rings_law's notes), alone on
  a quiet machine but for a few minutes: solved, residual 7.3e-7 m g (torque 4.9e-7 m g R), 870.000000 of the 870
  weights on the fixed row; 699 s wall (35 s of it the kernels' compile), 696 s of CPU, 544 MB resident at peak; the
  descents 6,973, 302, 120 and 467 steps (15,882, 1,371, 483 and 1,587 evaluations; 522, 54, 20 and 63 s of CPU),
  no Newton phase.  10 x 10 with it, quiet: 28.9 s wall and of CPU, residual 4.5e-7 m g (torque 1.3e-7 m g R),
  90.000001 of 90 weights, the descents 1,825, 40, 18 and 60 steps (19.5 s of CPU quiet before the bounded law).

What is left.  Newton's steps accepted where the
2-norm of the residual falls though the energy rises: after the softest stage's Newton iterations the largest residual,
1.0 m g, was that of rings of the lowest rows 3e-3 r clear of every neighbour, each feeling its weight alone (the next
stage's descent brought them back).  The time: the two softest stages' descents take 86 per cent of the CPU (10,000
steps); carry the preconditioner from stage to stage, and rebuild it less often on large sheets (each build costs six
evaluations per colour of the rings, some 110 on the 30 x 30 sheet).

Run: ``python benchmarks/bench_rings_drape.py [--rows 30] [--cols 30] [--tol 1e-6] [--iterations 30]
[--save pose.npz] [--untraced]``.
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
