"""The same workloads timed in two installations of ringchain, in turn, in one run.

For a restructuring or a new engine: are the paper recipe, the scaling run, a fit and a batch
as fast as before?  ``--other`` names the Python of a second virtual environment holding
another version of the package (e.g. the last release's); this script runs each workload in a
fresh process of each interpreter, alternating them ``--repeat`` times, and prints the best
time of each and their ratio (this one over the other).  The workloads use only names both
versions have (``paper_chain`` is looked up, else ``Chain.from_paper``).

Run: ``python benchmarks/compare_installs.py --other /path/to/other/.venv/bin/python``.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys

PRELUDE = """
import json, time
import numpy as np
import ringchain.numerics as N
paper_chain = getattr(N, "paper_chain", None) or N.Chain.from_paper
def timed(func, repeat):
    func()  # warm: derivations from the disk cache, imports, compilation
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter(); func(); best = min(best, time.perf_counter() - start)
    return best
"""

WORKLOADS = {
    # The paper's 20-ring dual-spring chain (Table I springs), 5 cm drop, 2 ms, the default method.
    "paper chain, 2 ms": (
        "chain = paper_chain('dual-spring', stiffness='table')\n"
        "seconds = timed(lambda: N.simulate(chain, 2e-3, drop_height=0.05), 5)"
    ),
    # 10^4 rings, no gravity, struck at 1 m/s, 2 ms, odeint (bench_scaling.py's largest chain).
    "10^4 rings, odeint": (
        "p = paper_chain('power-law')\n"
        "chain = N.Chain.power_law(10_000, K=p.K, n=p.n, m=p.m, a=p.a, m_gravity=p.m_gravity)\n"
        "seconds = timed(lambda: N.simulate(chain, 2e-3, impact_velocity=1.0, gravity=False, n_samples=3), 2)"
    ),
    # 64 drop heights of the paper's chain as one batch, fixed-step Verlet (a sweep task).
    "batch of 64, verlet": (
        "chain = paper_chain('dual-spring', stiffness='table')\n"
        "h = np.linspace(5e-3, 0.5, 64)\n"
        "seconds = timed(lambda: N.simulate_batch(chain, 2e-3, drop_heights=h, method='verlet', n_samples=1001,"
        " rings=[6, 12]), 3)"
    ),
    # m, gamma and t0 of the power-law chain fitted to two noisy 20-ring sensor traces (bench_fit.py).
    "fit of m, gamma, t0": (
        "import dataclasses\n"
        "truth = dataclasses.replace(paper_chain('power-law'), gamma=3.0)\n"
        "clock = np.linspace(-0.1e-3, 1.4e-3, 1500); tau = clock - 4e-5; after = tau >= 0\n"
        "sim = N.simulate(truth, tau[-1], drop_height=0.02, t_eval=tau[after], rtol=1e-10)\n"
        "rng = np.random.default_rng(1); traces = {}\n"
        "for k, off in ((6, 0.3), (12, -0.2)):\n"
        "    y = np.full(clock.size, sim.sensor(k)[0]); y[after] = sim.sensor(k)\n"
        "    traces[k] = y + off + 0.3 * rng.standard_normal(clock.size)\n"
        "start = dataclasses.replace(truth, m=1.2 * truth.m, gamma=1.0)\n"
        "seconds = timed(lambda: N.fit_traces(clock, traces, start, drop_height=0.02, free=('m', 'gamma', 't0')), 3)"
    ),
}


def run(python: str, body: str) -> float:
    code = PRELUDE + body + "\nprint(json.dumps(seconds))"
    out = subprocess.run([python, "-c", code], capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--other", required=True, help="Python of the other installation")
    parser.add_argument("--repeat", type=int, default=3, help="processes of each installation per workload")
    parser.add_argument("--only", nargs="*", default=None, help="workloads to run (default all)")
    args = parser.parse_args(argv)
    print(f"{'workload':24s} {'this (s)':>9s} {'other (s)':>10s} {'ratio':>6s}")
    for name, body in WORKLOADS.items():
        if args.only and name not in args.only:
            continue
        this, other = float("inf"), float("inf")
        for _ in range(args.repeat):
            this = min(this, run(sys.executable, body))
            other = min(other, run(args.other, body))
        print(f"{name:24s} {this:9.4f} {other:10.4f} {this / other:6.2f}")


if __name__ == "__main__":
    main()
