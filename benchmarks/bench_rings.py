"""Rigid rings in space: wall time and peak memory of a struck chain of 1,000 rings for 1 ms.

A straight chain along z (:meth:`~ringchain.numerics.Rings.chain`: the paper's steel ring, R/r = 9, planes
alternating, neighbours just touching, the top ring fixed), ring 0 struck along the axis at ``--speed``,
integrated for ``--duration`` by
:func:`ringchain.numerics.simulate` (the compiled Dormand-Prince pair at its default tolerance, or
``--method verlet``), every ring recorded at ``--samples`` times.  The kernels are compiled (or loaded from
the disk cache) by a short run of a small chain first, timed apart: the cold compile is a one-off cost.

Prints the wall time of the compile/warm-up, the wall and CPU time of the run (on a busy machine the CPU
time is the cost), the steps it took, the peak resident memory of the process and, with ``--traced``, the peak
of the memory the run allocated (tracemalloc: NumPy's arrays included).  Traced, the run takes three times as
long: the compiled kernels allocate their small work arrays (a pose's matrices, a scan's brackets) from Python's
allocator once per pair and evaluation, and tracemalloc sees every one (all figures below up to the next paragraph
but one were traced, as the benchmark then always was).

Measured on a 2-core machine shared with other jobs (load average 13-15), the Hertz law of the curvatures,
kernels loaded from the disk cache: Verlet 1508 steps in 12.8 s wall (4.8 s of CPU), dopri5 1101 steps (6698
evaluations) in 95.9 s wall (23.9 s of CPU); 42 MB allocated at peak, 240-390 MB resident.  The cold compile
of the kernels took 217 s of wall time on that machine.  The goal, 20 s on 2 cores: Verlet meets it, dopri5
at its default tolerance (3e-10) does not (about 3.6 ms per evaluation of 1,000 rings).

Again (load average 4 on the 2 cores), the same runs: before the stages of dopri5 followed the contacts, dopri5
42.8 and 57.2 s wall (17.4 and 16.6 s of CPU), Verlet 22.0 and 23.7 s wall (5.3 and 5.7 s of CPU), the cold
compile 141.7 s wall; the contacts searched once per accepted step and followed by one Newton step at the other
stages (:mod:`ringchain.numerics.engine.rings_step`), dopri5 26.9 and 30.1 s wall (13.4 and 14.9 s of CPU: 2.1 ms
per evaluation), Verlet 10.9 and 14.4 s wall (5.4 and 5.6 s of CPU), the cold compile 148.9 s wall; the same
steps, evaluations and peak link force (688.7 N).  On two idle cores the CPU time is the wall time: dopri5 meets
the goal.

Nearly quiet (load 1.3: one other single-threaded job on the two cores), kernels from the disk cache: dopri5 16.4 s
wall (16.0 s of CPU; 1101 steps, 6698 evaluations), Verlet 5.7 s wall (5.7 s of CPU, 1508 steps); 42 MB allocated
at peak, 218 and 255 MB resident.

Untraced, quiet (load below 1), kernels from the disk cache, with the loads the energy's gradient (the derivatives
of Hertz's K_c over the pose and the shares of twin contacts) and the search's look between samples: dopri5 15.0 s
wall (15.0 s of CPU; 1101 steps, 6698 evaluations, 2.2 ms each), 220 MB resident; traced, the same run 45.2 s wall
(317 MB resident).  The goal (20 s on 2 cores) is met.

With the contact law bounded near a fold (:func:`~ringchain.numerics.engine.rings_law.contact_stiffness`) and the
smaller compile of the integrators, untraced, one other single-threaded job on the other core (load 1.8), kernels
from the disk cache: dopri5 15.3 s wall (15.2 s of CPU; the same 1101 steps, 6698 evaluations and peak link force
688.7 N), 217 MB resident.  On an empty cache the same process compiled for 48.5 s first (384 MB resident).

With the contact search's look between two samples and the warm start's check for a twin beyond a maximum
(:mod:`ringchain.numerics.engine.rings_kernels`), against the search before them, alternately on a machine at load
4-9, kernels from the disk cache: dopri5 49.9 and 45.4 s of CPU against 48.9 and 47.1 (the same 1101 steps, 6698
evaluations and peak link force 688.7 N): no difference above the noise.  Searched alone (the linked and resting
pairs of bench_rings_contact.py, both versions in one process, best of 7, two runs), the cold search costs 2.4-3.4
us a pair against 2.1-2.7 (12-25 per cent more), the warm start 1.3-1.9 us against 1.1-1.4 (20-32 per cent more:
four more evaluations of the profile per minimum); the warm search is some 10 per cent of a dopri5 run (999 pairs
at about 1.2 us, once per step of six evaluations of about 2 ms), so its growth stays within the run's noise.

Run: ``python benchmarks/bench_rings.py [--rings 1000] [--duration 1e-3] [--speed 1.0] [--samples 201]
[--method dopri5]``.
"""

from __future__ import annotations

import argparse
import resource
import time
import tracemalloc

import numpy as np
from ringchain.numerics import Rings, simulate
from ringchain.theory import Ring


def run(n, duration, speed, samples, method):
    rings = Rings.chain(n, Ring.from_aspect_ratio(9.0))  # the top ring fixed
    t = np.linspace(0.0, duration, samples)
    return simulate(rings, duration, impact_velocity=speed, gravity=False, t_eval=t, method=method)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rings", type=int, default=1000)
    parser.add_argument("--duration", type=float, default=1e-3, help="s")
    parser.add_argument("--speed", type=float, default=1.0, help="impact speed, m/s")
    parser.add_argument("--samples", type=int, default=201)
    parser.add_argument("--method", default="dopri5", choices=["dopri5", "verlet"])
    parser.add_argument("--traced", action="store_true", help="measure the memory the run allocates (tracemalloc: "
                        "the run then takes about three times as long)")  # fmt: skip
    args = parser.parse_args()

    start = time.perf_counter()
    run(4, 1e-5, args.speed, 3, args.method)  # compile (or load) the kernels
    warm_up = time.perf_counter() - start

    if args.traced:
        tracemalloc.start()
    start, cpu = time.perf_counter(), time.process_time()
    sim = run(args.rings, args.duration, args.speed, args.samples, args.method)
    wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    peak = tracemalloc.get_traced_memory()[1] if args.traced else None
    tracemalloc.stop()
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**10  # kB -> MB (Linux)

    force = sim.link_force
    front = int(np.argmax(force[-1] > 0.01 * force.max())) if force.max() > 0 else 0
    steps = sim.stats.get("steps", [sim.stats.get("nfev")])
    print(f"{args.rings} rings, {args.duration * 1e3:g} ms after an impact at {args.speed:g} m/s, {args.method}")
    print(f"  compile or load of the kernels (a 4-ring run): {warm_up:.1f} s")
    print(f"  run: {wall:.1f} s wall, {cpu:.1f} s of CPU, {steps[0]} steps ({sim.stats.get('nfev')} evaluations)")
    allocated = f"{peak / 2**20:.0f} MB allocated at peak during the run (traced); " if args.traced else ""
    print(f"  memory: {allocated}{rss:.0f} MB resident at peak")
    print(f"  peak link force {force.max():.1f} N; the pulse has reached link {front} at t = {sim.t[-1] * 1e3:g} ms")


if __name__ == "__main__":
    main()
