"""10^4 drop heights in one sweep, as the command line runs it, and where its time goes (issue 30).

The issue's must-show: ``ringchain sweep --drop-height 0.01:0.5:10000 --model dual-spring --m-eff-ratio 0.37``
in at most 8 s on a quiet two-core machine.  The script prints, each measured in this run:

- the command itself, in a fresh process (imports, the compiled kernels loaded from the disk cache, the
  choice of executor, the CSV written to a temporary folder): wall time, and CPU time of the process
  (all its threads); the load average before and after, since the machine may be shared;
- the same sweep in this process (:func:`~ringchain.numerics.sweep`, ``max_workers=0``), split into its
  parts: the points (:func:`~ringchain.numerics.jobs.sweep.expand`), the work estimate, the integration
  (:func:`~ringchain.numerics.simulate_batch`, its kernels on every core), the rest of each task (the rows'
  static columns and the sensors read: Python on one core) and the CSV; the Python share per point beside
  :data:`~ringchain.numerics.jobs.sweep.PYTHON_SECONDS_PER_POINT`, which decides between this process and a
  pool of workers.

Run from benchmarks/: ``python bench_sweep.py [--count 10000] [--skip-command]``.
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from ringchain.numerics.jobs import sweep as sweep_module
from ringchain.numerics.jobs.sweep import expand, sweep, write_csv

GRID = {"model": "dual-spring", "m_eff_ratio": 0.37}
GOAL = 8.0  # s, for 10^4 points (issue 30)


def load() -> str:
    return f"{os.getloadavg()[0]:.1f}"


def command(count: int) -> None:
    """The command line in a fresh process: wall and CPU seconds."""
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder) / "sweep.csv"
        args = [sys.executable, "-m", "ringchain.numerics.cli", "sweep", "--drop-height", f"0.01:0.5:{count}",
                "--model", "dual-spring", "--m-eff-ratio", "0.37", "--out", str(out)]  # fmt: skip
        before, start = resource.getrusage(resource.RUSAGE_CHILDREN), time.perf_counter()
        loaded = load()
        done = subprocess.run(args, capture_output=True, text=True, check=True)
        wall = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        rows = sum(1 for _ in out.open()) - 1
    notes = [line for line in done.stderr.splitlines() if line.startswith(("sweep:", "ringchain:"))]
    print(f"command, {count} drop heights ({rows} rows): {wall:.2f} s wall, {cpu:.2f} s CPU; load average "
          f"{loaded} -> {load()} on {os.cpu_count()} cores; goal {GOAL:g} s for 10^4 on a quiet machine")  # fmt: skip
    for line in notes:
        print(f"  {line}")


def split(count: int) -> None:
    """The sweep in this process, part by part."""
    heights = list(np.linspace(0.01, 0.5, count))
    sweep({**GRID, "drop_height": heights[:2]}, max_workers=0)  # warm: imports, kernels, the theory's cache
    integration = [0.0]
    simulate_batch = sweep_module.simulate_batch

    def timed(*args, **kwargs):
        start = time.perf_counter()
        try:
            return simulate_batch(*args, **kwargs)
        finally:
            integration[0] += time.perf_counter() - start

    loaded = load()
    start, cpu, main = time.perf_counter(), time.process_time(), time.thread_time()
    points = expand({**GRID, "drop_height": heights})
    t_points = time.perf_counter() - start
    sweep_module.simulate_batch = timed
    try:
        rows = sweep(points, max_workers=0)
    finally:
        sweep_module.simulate_batch = simulate_batch
    t_sweep = time.perf_counter() - start - t_points
    mark = time.perf_counter()
    with tempfile.TemporaryDirectory() as folder:
        write_csv(rows, Path(folder) / "sweep.csv")
    t_csv = time.perf_counter() - mark
    wall, cpu, main = time.perf_counter() - start, time.process_time() - cpu, time.thread_time() - main
    rest = t_sweep - integration[0]
    per_point = getattr(sweep_module, "PYTHON_SECONDS_PER_POINT", None)  # (a version before it: None)
    constant = "" if per_point is None else f"; PYTHON_SECONDS_PER_POINT {per_point * 1e3:.3f} ms"
    print(f"\nin this process, {count} drop heights: {wall:.2f} s wall, {cpu:.2f} s CPU (this thread, Python: "
          f"{main:.2f} s, {main / count * 1e3:.3f} ms a point{constant}); load average {loaded} -> "
          f"{load()}")  # fmt: skip
    for name, seconds in (("points (expand)", t_points), ("integration (simulate_batch)", integration[0]),
                          ("estimate, rows and readings", rest), ("CSV", t_csv)):  # fmt: skip
        print(f"  {name:30s} {seconds:7.2f} s  {seconds / wall:6.1%}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=10_000, help="drop heights (default 10^4)")
    parser.add_argument("--split-count", type=int, default=None, help="drop heights of the split (default --count)")
    parser.add_argument("--skip-command", action="store_true", help="only the split in this process")
    args = parser.parse_args()
    if not args.skip_command:
        command(args.count)
    split(args.split_count or args.count)


if __name__ == "__main__":
    main()
