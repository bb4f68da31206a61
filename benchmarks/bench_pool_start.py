"""What a pool of worker processes costs before it saves anything: the threshold of ``run_tasks``.

A sweep or an ensemble given no executor runs its tasks on local "spawn" worker processes
(:func:`ringchain.numerics.engine.executors.default_executor`).  Each worker is a fresh interpreter: it
imports NumPy, SciPy, Numba and ringchain and loads the compiled kernels from the disk cache before
its first task.  This script measures that cost: the wall time from starting a pool of ``--workers``
processes to each one having run one short simulation of the paper's chain (0.1 ms), against the same
simulation in this process, warm.  The difference is
:data:`~ringchain.numerics.engine.executors.POOL_START_SECONDS` (a pool pays it once; the calling process
never).  Run: ``python benchmarks/bench_pool_start.py`` (best of ``--repeat``).
"""

from __future__ import annotations

import argparse
import os
import time


def one_run(_=None) -> float:
    """One short simulation of the paper's chain (the kernels loaded from the cache on first use)."""
    from ringchain.numerics import paper_chain, simulate

    start = time.perf_counter()
    simulate(paper_chain("dual-spring"), 1e-4, drop_height=0.05, n_samples=11)
    return time.perf_counter() - start


def main(argv=None):
    from ringchain.numerics.engine.executors import POOL_START_SECONDS, default_executor

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args(argv)
    one_run()  # compile or load the kernels here first, so that the workers find them on disk
    here = min(one_run() for _ in range(args.repeat))
    pools = []
    for _ in range(args.repeat):
        start = time.perf_counter()
        with default_executor(args.workers, args.workers, "bench_pool_start") as pool:
            list(pool.map(one_run, range(args.workers)))
        pools.append(time.perf_counter() - start)
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores; best of {args.repeat}")
    print(f"one run in this process, warm: {here:.3f} s; a pool of {args.workers} processes, each running it once: "
          f"{min(pools):.2f} s (median {sorted(pools)[len(pools) // 2]:.2f} s)")  # fmt: skip
    print(f"the pool's cost: {min(pools) - here:.2f} s (POOL_START_SECONDS = {POOL_START_SECONDS:g} s)")


if __name__ == "__main__":
    main()
