"""Cost of a run against the number of rings, 20 to 10^4.

The paper's chains (Table I, R/r = 9) of N rings, without gravity (so that the static
load of a long hanging chain does not stiffen its top and change the physics with N),
struck at 1 m/s and integrated for 2 ms: the pulse crosses 25-35 rings, so
the step sizes do not depend on N and the cost per step should be proportional to N
once N is large enough for NumPy's per-call overhead not to dominate.

Printed per solver: N, wall time (best of ``--repeat``), right-hand-side evaluations,
and the cost per ring per evaluation (ns); the last line fits cost = c N^p over the two
largest N.  Run: ``python benchmarks/bench_scaling.py``.
"""

from __future__ import annotations

import argparse

import numpy as np
from bench_paper_recipe import best_time  # this folder is on sys.path when a script runs from it
from ringchain.numerics import Chain, paper_chain, simulate

RINGS = (20, 100, 1000, 10_000)
T_END = 2e-3  # s


def chain(model: str, n_rings: int) -> Chain:
    paper = paper_chain(model)
    params = dict(n_rings=n_rings, m=paper.m, a=paper.a, m_gravity=paper.m_gravity)
    if model == "power-law":
        return Chain.power_law(K=paper.K, n=paper.n, **params)
    return Chain.dual_spring(K_c=paper.K_c, K_b=paper.K_b, **params)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--rings", type=int, nargs="+", default=list(RINGS))
    args = parser.parse_args(argv)
    print(f"{'model':12s} {'solver':7s} {'rings':>6s} {'time (s)':>9s} {'rhs evals':>10s} {'ns/(ring eval)':>15s}")
    for model in ("power-law", "dual-spring"):
        for method in ("odeint", "LSODA", "verlet"):
            rows = []
            for n in args.rings:
                run = chain(model, n)
                seconds, sim = best_time(
                    lambda run=run, method=method: simulate(
                        run, T_END, impact_velocity=1.0, gravity=False, method=method, n_samples=3
                    ),
                    args.repeat,
                )
                nfev = sim.stats["nfev"]
                rows.append((n, seconds))
                print(f"{model:12s} {method:7s} {n:6d} {seconds:9.3f} {nfev:10d} {1e9 * seconds / (n * nfev):15.1f}")
            (n1, s1), (n2, s2) = rows[-2], rows[-1]
            power = np.log(s2 / s1) / np.log(n2 / n1)
            print(f"{model:12s} {method:7s} cost ~ N^{power:.2f} between {n1} and {n2} rings")


if __name__ == "__main__":
    main()
