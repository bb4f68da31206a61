"""Chains that change along their length: cost per ring-step against the uniform chain, both integrators.

Three parts, each printing its numbers:

1. ``stepper`` -- the inner loop of both integrators (``Network.stepper``: the accelerations of every
   site) on a uniform chain, on the same chain with parameters that vary along it (per-contact K
   and n, per-ring m, m_gravity and K_b), and on a uniform chain given as arrays that differ in the
   last bit (the array path with uniform numbers): microseconds per call and nanoseconds per
   ring-step, one run and a batch of 64 runs, 20 and 2000 rings, both models.
2. ``integrators`` -- a 5 cm drop on a 100-ring chain, uniform and graded (R/r 9 to 5, every
   contact different), integrated by "odeint" and by "verlet": wall time, right-hand-side calls,
   and seconds per ring-step (wall time over calls x rings).
3. ``unchanged`` -- the uniform path: a uniform chain built ring by ring (``Chain.from_rings``)
   is the scalar chain (equal, and its runs bit-identical); with ``--compare-python
   /path/to/other/python`` part 1's uniform timings are also measured by another install (e.g.
   main's virtual environment) in a subprocess, to show the uniform path's speed unchanged.

Run: ``python benchmarks/bench_hetero.py [--parts stepper integrators unchanged] [--repeat 5]
[--compare-python PYTHON]``.  Timings on a shared machine are noisy; compare ratios within one run.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time

import numpy as np
from ringchain.numerics import Chain, simulate
from ringchain.theory import Ring

CALLS = 2000
G = 9.80665


def uniform_chain(model, n_rings):
    if model == "power-law":
        return Chain.power_law(n_rings, K=4.9e6, n=1.11, m=8.2e-3, a=0.04, m_gravity=2.2e-2)
    return Chain.dual_spring(n_rings, K_c=7.5e9, K_b=3.3e6, m=8.2e-3, a=0.04, m_gravity=2.2e-2)


def varying_chain(model, n_rings, spread=0.5):
    """The uniform chain's parameters times factors in [1 - spread, 1 + spread] (seeded), per contact or ring."""
    rng = np.random.default_rng(13)
    contacts = n_rings  # fixed support: one contact per ring

    def vary(value, count):
        return value * (1.0 + spread * rng.uniform(-1.0, 1.0, count))

    m = vary(8.2e-3, n_rings)
    if model == "power-law":
        n = vary(1.11, contacts) if spread < 1e-6 else rng.uniform(1.05, 1.5, contacts)
        return Chain.power_law(n_rings, K=vary(4.9e6, contacts), n=n, m=m, a=0.04, m_gravity=vary(2.2e-2, n_rings))
    return Chain.dual_spring(n_rings, K_c=vary(7.5e9, contacts), K_b=vary(3.3e6, n_rings), m=m, a=0.04,
                             m_gravity=vary(2.2e-2, n_rings))  # fmt: skip


def stepper_time(chain, batch, repeat):
    """Best wall time of one stepper call, s."""
    lat = chain.network()
    shape = () if batch == 1 else (batch,)
    step = lat.stepper(shape, G)
    rng = np.random.default_rng(1)
    x = rng.normal(scale=1e-6, size=(*shape, lat.n_sites))
    out = np.empty_like(x)
    best = np.inf
    for _ in range(repeat):
        start = time.perf_counter()
        for _ in range(CALLS):
            step(x, None, out)
        best = min(best, (time.perf_counter() - start) / CALLS)
    return best


def uniform_timings(repeat):
    """{(model, rings, batch): seconds per stepper call} of the uniform chains (also run by --compare-python)."""
    return {
        f"{model}|{n_rings}|{batch}": stepper_time(uniform_chain(model, n_rings), batch, repeat)
        for model in ("power-law", "dual-spring")
        for n_rings in (20, 2000)
        for batch in (1, 64)
    }


def stepper(repeat):
    print("1. stepper: one call of the accelerations (best of repeats of 2000 calls)")
    print(f"   {'model':12s} {'rings':>5s} {'runs':>4s}   {'uniform':>22s}   {'varying':>22s}   "
          f"{'uniform as arrays':>22s}   varying/uniform")  # fmt: skip
    for model in ("power-law", "dual-spring"):
        for n_rings in (20, 2000):
            for batch in (1, 64):
                times = {
                    "uniform": stepper_time(uniform_chain(model, n_rings), batch, repeat),
                    "varying": stepper_time(varying_chain(model, n_rings), batch, repeat),
                    # factors 1 +- 1e-15: arrays whose values differ in the last bits (the array path)
                    "arrays": stepper_time(varying_chain(model, n_rings, spread=1e-15), batch, repeat),
                }
                ring_steps = n_rings * batch
                cells = [f"{t * 1e6:8.2f} us {t / ring_steps * 1e9:7.2f} ns/ring" for t in times.values()]
                print(f"   {model:12s} {n_rings:5d} {batch:4d}   " + "   ".join(cells)
                      + f"   {times['varying'] / times['uniform']:.2f}")  # fmt: skip


def integrators(repeat):
    ring = Ring.from_aspect_ratio(9.0)
    n_rings = 100
    chains = {
        "uniform": Chain.from_ring(ring, n_rings, m_eff_ratio=0.37),
        "graded 9 to 5": Chain.graded(ring, n_rings, aspect_ratio=(9.0, 5.0), m_eff_ratio=0.37),
    }
    print(f"2. integrators: {n_rings}-ring dual-spring chains, 5 cm drop, 3 ms, 1001 samples (best of {repeat})")
    for method in ("odeint", "verlet"):
        per = {}
        for name, chain in chains.items():
            best, stats = np.inf, None
            for _ in range(repeat):
                start = time.perf_counter()
                sim = simulate(chain, 3e-3, drop_height=0.05, method=method, n_samples=1001)
                best = min(best, time.perf_counter() - start)
                stats = sim.stats
            per[name] = best / (stats["nfev"] * n_rings)
            print(f"   {method:7s} {name:14s} {best:7.3f} s, {stats['nfev']:7d} right-hand sides, "
                  f"{per[name] * 1e9:6.1f} ns per ring-step")  # fmt: skip
        print(f"   {method:7s} graded/uniform cost per ring-step: {per['graded 9 to 5'] / per['uniform']:.2f}")


def unchanged(repeat, compare_python):
    ring = Ring.from_aspect_ratio(9.0)
    built = Chain.from_rings([ring] * 20, m_eff_ratio=0.37)
    scalar = Chain.from_ring(ring, 20, m_eff_ratio=0.37)
    same = built == scalar
    runs = [simulate(c, 1e-3, drop_height=0.05, n_samples=201) for c in (built, scalar)]
    identical = np.array_equal(runs[0].x, runs[1].x) and np.array_equal(runs[0].u, runs[1].u)
    print(f"3. unchanged: from_rings of 20 equal rings == from_ring: {same}; runs bit-identical: {identical}")
    if compare_python is None:
        return
    here = uniform_timings(repeat)
    code = ("import json, sys; sys.path.insert(0, sys.argv[1]); import bench_hetero as b; "
            "print(json.dumps(b.uniform_timings(int(sys.argv[2]))))")  # fmt: skip
    folder = str(__import__("pathlib").Path(__file__).resolve().parent)
    other = json.loads(subprocess.run([compare_python, "-c", code, folder, str(repeat)], capture_output=True,
                                      text=True, check=True).stdout)  # fmt: skip
    print(f"   uniform stepper, this install vs {compare_python}:")
    for key, seconds in here.items():
        model, rings, batch = key.split("|")
        print(f"   {model:12s} {rings:>5s} rings {batch:>3s} runs: {seconds * 1e6:8.2f} us vs "
              f"{other[key] * 1e6:8.2f} us (ratio {seconds / other[key]:.2f})")  # fmt: skip


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--parts", nargs="+", default=["stepper", "integrators", "unchanged"],
                        choices=["stepper", "integrators", "unchanged"])  # fmt: skip
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--compare-python", default=None, metavar="PYTHON")
    args = parser.parse_args(argv)
    if "stepper" in args.parts:
        stepper(args.repeat)
    if "integrators" in args.parts:
        integrators(max(1, args.repeat // 2))
    if "unchanged" in args.parts:
        unchanged(args.repeat, args.compare_python)


if __name__ == "__main__":
    sys.exit(main())
