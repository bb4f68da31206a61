"""First call of the theory in a fresh process: the cost of the disk cache of generated code.

A derivation runs on first use and its generated NumPy code is cached on disk
(``theory/_codegen.py``); a later process loads it without importing SymPy.  This script
times, in fresh interpreters sharing one temporary cache directory:

- ``import``: ``import ringchain.theory``;
- ``cold``: the first ``hertz_stiffness`` call with an empty cache (derives, writes the entry);
- ``warm``: the first ``hertz_stiffness`` call with the entry on disk (reads, checks, compiles);
- ``second``: the next call in the same process (the compiled function only).

Printed: the median over ``--repeat`` processes of each, in ms, and the ratio warm/second (what
loading the cache adds to a call).  Run: ``python benchmarks/bench_cache.py``.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile

PROBE = """
import time
t0 = time.perf_counter()
import ringchain.theory as theory
t1 = time.perf_counter()
theory.hertz_stiffness(22.5e-3, 2.5e-3, 193e9, 0.29)
t2 = time.perf_counter()
theory.hertz_stiffness(22.5e-3, 2.5e-3, 193e9, 0.29)
t3 = time.perf_counter()
print(t1 - t0, t2 - t1, t3 - t2)
"""


def probe(cache: str) -> tuple[float, float, float]:
    env = {**os.environ, "RINGCHAIN_CACHE_DIR": cache}
    out = subprocess.run([sys.executable, "-c", PROBE], env=env, capture_output=True, text=True, check=True).stdout
    return tuple(float(x) for x in out.split())


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=9)
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as cache:
        _, cold, _ = probe(cache)
        runs = [probe(cache) for _ in range(args.repeat)]
    imports, warm, second = (statistics.median(column) for column in zip(*runs, strict=True))
    print(f"import ringchain.theory      {imports * 1e3:8.2f} ms")
    print(f"first call, cold cache       {cold * 1e3:8.2f} ms (one process)")
    print(f"first call, warm cache       {warm * 1e3:8.2f} ms (median of {args.repeat} processes)")
    print(f"second call                  {second * 1e3:8.2f} ms")
    print(f"warm first call / second     {warm / second:8.1f}")


if __name__ == "__main__":
    main()
