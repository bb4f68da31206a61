"""128 disordered 40-ring chains in one ``ensemble`` call on 2 cores, and how the time scales.

The chains are the issue's (issue 23): R/r = 9 rings (the paper's, m_eff/m0 = 0.37) whose radii
spread by 10 % (R) and 5 % (r), 40 to a chain, hanging, struck by a 5 cm drop and read at every
ring.  The script prints, each measured in this run on this machine:

- the headline: one :func:`~ringchain.numerics.jobs.ensemble` call of 128 members on ``--workers``
  local processes (default 2), wall time and time per member (issue 30's goal: 5 s on a quiet
  two-core machine); the wall time includes starting the worker processes, which the script
  measures separately (an ensemble of two members, one per worker); then the same call in this
  process (``max_workers=0``), its CPU time split into Python on one core and the kernels' threads;
- the same 128 members as a loop over :func:`~ringchain.numerics.simulate` on one core (the
  issue's "today 6-8 s"), on every ``--subset``-th member scaled up;
- scaling with the count (16 to 128 members) and with the workers (0: this process, 1, 2) at a
  fixed batch size, and with the batch size in this process: an adaptive method steps a
  stacked batch with one step size, so batching pays only when the engine gives each member its
  own steps (issue 20).

The integrator is :func:`~ringchain.numerics.simulate_batch`'s default unless ``--method`` says
otherwise; every timing is the best of ``--repeat`` (default 1: the runs are long); the load
average is printed, since the machine is shared.

Measured (issue 30).  Before: 9.6-11.4 s at load 3.8-4.9 (5.8-9.4 s quiet, earlier), bound by Python making the
chains (a Ring made and checked per drawn ring, a scalar K_c call per contact) and then the kernels.  What changed:
the drawn rings are checked together (``draw_rings``: hertz_stiffness and bending_stiffness on arrays; 90 % of a
draw), a chain's contacts of different rings are one ``hertz_stiffness_pair`` call (``Chain.from_rings``; 40 calls
a chain before), each distinct key hashed once.  The ensemble's CSV (members and summary) is byte-identical.  Two
sessions at load average 4.9-7.0 on 2 cores shared with other jobs, ``--quick`` (before: the commit this work
started from, the same script): in this process 11.35 -> 8.48 s CPU (10.18 -> 9.02 s in the other session), of
which Python on one core 4.42 -> 1.83 s (3.77 -> 2.09 s) and the kernels' threads 6.93 -> 6.65 s (6.41 -> 6.93 s:
the same work, moved by the load); wall 22.4 -> 17.3 s in this process, 35.6 -> 26.6 s on 2 workers (starting them:
10-11 s at that load).  The kernels' 6-7 s of CPU, over two threads, is most of what is
left: on a quiet machine that is 3 s or more of wall before any Python, and issue 30's 5 s is not shown here.

Run: ``python benchmarks/bench_ensemble.py [--model power-law] [--workers 2] [--method odeint] [--quick]``.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from bench_batch import best_of  # the benchmarks' one timer (run from benchmarks/, as each script is)
from ringchain.numerics import DEFAULT_METHOD, Chain, ensemble, simulate
from ringchain.numerics.jobs.ensemble import DEFAULT_BATCH_SIZE
from ringchain.numerics.layouts.disorder import member_seeds
from ringchain.theory import Ring

RING = Ring.from_aspect_ratio(9.0)
SPREAD = {"R": 0.10, "r": 0.05}
N_RINGS, COUNT, DROP, M_EFF = 40, 128, 0.05, 0.37


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default="power-law", choices=("power-law", "dual-spring"))
    parser.add_argument("--workers", type=int, default=2, help="local processes of the headline call (default 2)")
    parser.add_argument("--method", default=None, help=f"integrator (default simulate's, {DEFAULT_METHOD})")
    parser.add_argument("--batch-size", type=int, default=DEFAULT_BATCH_SIZE)
    parser.add_argument("--subset", type=int, default=4, help="time every k-th member of the loop, scale by k")
    parser.add_argument("--repeat", type=int, default=1, help="best of this many timings (default 1)")
    parser.add_argument("--quick", action="store_true", help="the headline and the loop only")
    args = parser.parse_args()
    solver = {} if args.method is None else {"method": args.method}
    common = dict(spread=SPREAD, seed=0, model=args.model, m_eff_ratio=M_EFF, drop_height=DROP, **solver)

    print(f"{COUNT} chains of {N_RINGS} R/r = 9 rings, {args.model}, spread R 10 %, r 5 %, drop {DROP} m; method "
          f"{args.method or DEFAULT_METHOD}, batch size {args.batch_size}; load average {os.getloadavg()[0]:.1f} "
          f"on {os.cpu_count()} cores")  # fmt: skip
    ensemble(RING, N_RINGS, 2, max_workers=0, **common)  # warm up: imports, the theory's cache
    startup, _ = best_of(args.repeat, lambda: ensemble(RING, N_RINGS, 2, batch_size=1, max_workers=args.workers,
                                                     **common))  # fmt: skip
    wall, ens = best_of(args.repeat, lambda: ensemble(RING, N_RINGS, COUNT, batch_size=args.batch_size,
                                                    max_workers=args.workers, **common))  # fmt: skip
    print(f"one ensemble call, {COUNT} members on {args.workers} workers: {wall:.2f} s, {wall / COUNT * 1e3:.1f} ms "
          f"a member ({args.workers} x {wall / COUNT * args.workers * 1e3:.1f} ms of a core); starting the workers "
          f"and a two-member call: {startup:.2f} s; goal 5 s on a quiet machine (issue 30)")  # fmt: skip
    cpu, main = time.process_time(), time.thread_time()
    inline, _ = best_of(1, lambda: ensemble(RING, N_RINGS, COUNT, batch_size=args.batch_size, max_workers=0,
                                            **common))  # fmt: skip
    cpu, main = time.process_time() - cpu, time.thread_time() - main
    print(f"the same call in this process: {inline:.2f} s wall, {cpu:.2f} s CPU, of which Python on one core "
          f"{main:.2f} s (drawing the rings, building the chains, reading the sensors) and the kernels' threads "
          f"{cpu - main:.2f} s; load average now {os.getloadavg()[0]:.1f}")  # fmt: skip

    # The loop the issue starts from: one simulate call per member, one core.
    seeds = member_seeds(0, COUNT)[:: args.subset]
    chains = [Chain.disordered(RING, N_RINGS, spread=SPREAD, seed=s, model=args.model, m_eff_ratio=M_EFF)
              for s in seeds]  # fmt: skip
    loop, runs = best_of(args.repeat, lambda: [simulate(c, ens.t_end, drop_height=DROP, **solver) for c in chains])
    loop *= COUNT / len(chains)
    diff = max(abs(run.peak_force(35) - ens.peak_force[k * args.subset, 35]) for k, run in enumerate(runs))
    print(f"a loop over simulate, one core: {loop:.2f} s ({loop / COUNT * 1e3:.1f} ms a member; every "
          f"{args.subset}th member timed); ensemble/loop {wall / loop:.2f}; largest difference of the peak at ring 35: "
          f"{diff / np.max(ens.peak_force[:, 35]):.1e} of it")  # fmt: skip
    if args.quick:
        return

    print("\nscaling (wall time, ms a member):")
    for count in (16, 32, 64, 128):
        t, _ = best_of(args.repeat, lambda count=count: ensemble(RING, N_RINGS, count, batch_size=args.batch_size,
                                                               max_workers=args.workers, **common))  # fmt: skip
        per = t / count * 1e3
        print(f"  count {count:4d}, {args.workers} workers, batch {args.batch_size:3d}: {t:7.2f} s  {per:6.1f}")
    for workers in (0, 1, 2):
        t, _ = best_of(args.repeat, lambda workers=workers: ensemble(RING, N_RINGS, 32, batch_size=args.batch_size,
                                                                   max_workers=workers, **common))  # fmt: skip
        print(f"  count   32, {workers} workers, batch {args.batch_size:3d}: {t:7.2f} s  {t / 32 * 1e3:6.1f}")
    for batch in (1, 4, 16, 32):
        t, _ = best_of(args.repeat, lambda batch=batch: ensemble(RING, N_RINGS, 32, batch_size=batch, max_workers=0,
                                                               **common))  # fmt: skip
        print(f"  count   32, this process, batch {batch:3d}: {t:7.2f} s  {t / 32 * 1e3:6.1f}")


if __name__ == "__main__":
    main()
