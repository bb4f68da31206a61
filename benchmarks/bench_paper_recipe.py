"""The paper's integration recipe against ringchain's solvers, on the same chain.

Paper Sec. III.B integrates the dual-spring chain (Eqs. (5)-(6)) with
``scipy.integrate.odeint`` and "a temporal resolution of 10,000 steps per ms".  This
script runs that recipe on the paper's 20-ring chain (Table I, R/r = 9; K_c and K_b of
the ring; m_eff/m0 = 0.37; hanging under gravity; 5 cm drop; 2 ms; no dashpots, as the
paper does not report its fitted values) and ringchain's solvers on the same chain, and
prints each one's time and its accuracy against a tight reference: the largest error
of the sensor forces in rings 6 and 12 over the run, relative to their peak.

Two versions of the recipe are timed:

- "recipe": odeint (default tolerances, LSODA) with the equations written out as
  in the paper, one ring at a time in a Python loop -- the usual transcription;
- "recipe, vectorised rhs": odeint with ringchain's vectorised right-hand side, so
  that its ratio to ringchain isolates the integrator.

Every timing is the best of ``--repeat`` runs (default 5), the solvers taking turns, so
that a change of machine load is shared by all of them.  Run: ``python benchmarks/bench_paper_recipe.py``.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from ringchain.numerics import STANDARD_GRAVITY, Chain, initial_state, paper_chain, simulate
from scipy.integrate import odeint

DROP = 0.05  # m
T_END = 2e-3  # s
SENSORS = [6, 12]
STEPS_PER_MS = 10_000  # the paper's output resolution


def paper_rhs(chain: Chain, g: float):
    """Eqs. (5)-(6) transcribed ring by ring, as a plain Python loop.

    State: the 2N site displacements (chain order: lower half w_{j-1}, upper half u_j
    of each ring j) then their velocities; the top ring hangs from a fixed support
    through one more Hertz contact (as in ringchain).
    """
    N = chain.n_rings
    K_c, K_b, half = chain.K_c, chain.K_b, chain.m / 2
    g_site = g * chain.m_gravity / chain.m  # weight (m0/2) g over inertia m/2

    def rhs(y, t):
        x, v = y[: 2 * N], y[2 * N :]
        acc = [0.0] * (2 * N)
        for j in range(N):
            lower, upper = 2 * j, 2 * j + 1
            # bending spring of ring j: F_b(w_{j-1} - u_j), bidirectional
            f_b = K_b * (x[upper] - x[lower])
            # Hertz contact above ring j (with ring j+1, or the support): [F_c]_+
            above = x[upper + 1] if j < N - 1 else 0.0
            delta = above - x[upper]
            f_c = K_c * delta**1.5 if delta > 0 else 0.0
            acc[upper] += (f_c - f_b) / half - g_site
            acc[lower] += f_b / half - g_site
            if j < N - 1:
                acc[upper + 1] -= f_c / half
        return np.concatenate([v, acc])

    return rhs


def vectorised_rhs(chain: Chain, g: float):
    """ringchain's vectorised right-hand side on the recipe's state layout."""
    S = chain.n_sites
    rhs = chain.network().first_order_rhs(1, g)  # state interleaved per site: x0, u0, x1, u1, ...
    interleave = np.arange(2 * S).reshape(2, S).T.ravel()  # positions in [x, u] of [x0, u0, x1, ...]
    blocks = np.argsort(interleave)
    return lambda y, t: rhs(t, y[interleave])[blocks]


def run_recipe(chain, rhs, y0, t):
    y = odeint(rhs, y0, t)
    S = chain.n_sites
    return y[:, :S], y[:, S : 2 * S]


def sensor_forces(chain, x, u):
    """Sensor forces of rings 6 and 12 from site states, through ringchain's Simulation."""
    from ringchain.numerics import Simulation

    sim = Simulation(chain=chain, t=np.arange(len(x)), x=x, u=u, dissipated=np.zeros(len(x)), g=0.0,
                     impact_velocity=0.0, drop_height=None)  # fmt: skip
    return sim.sensor_force[:, SENSORS]


def best_time(func, repeat):
    """Best wall time of ``repeat`` calls of ``func``, and its result."""
    return best_times({"": func}, repeat)[""]


def best_times(funcs: dict, repeat: int) -> dict:
    """Best wall time and result of each function, calling them in turn ``repeat`` times
    (round robin), so that a change of machine load is shared by all of them."""
    best = {name: (np.inf, None) for name in funcs}
    for _ in range(repeat):
        for name, func in funcs.items():
            start = time.perf_counter()
            result = func()
            seconds = time.perf_counter() - start
            best[name] = (min(seconds, best[name][0]), result)
    return best


#: The comparison's grid: every EVERY-th step of the recipe's, a 1 us grid.
EVERY = 10


def comparison(chain):
    """The recipe's initial state and time grid, the comparison's grid, and on it the reference sensor forces
    (LSODA at rtol 1e-12) with DOP853's at 1e-13 as their check, N, shape (T, 2) each."""
    x0, u0 = initial_state(chain, drop_height=DROP)
    y0 = np.concatenate([x0[0], u0[0]])
    t_recipe = np.linspace(0.0, T_END, round(T_END * 1e3 * STEPS_PER_MS) + 1)
    t_cmp = t_recipe[::EVERY]
    ref = simulate(chain, T_END, drop_height=DROP, t_eval=t_cmp, method="LSODA", rtol=1e-12).sensor_force[:, SENSORS]
    check = simulate(chain, T_END, drop_height=DROP, t_eval=t_cmp, method="DOP853", rtol=1e-13).sensor_force[:, SENSORS]
    return y0, t_recipe, t_cmp, ref, check


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--rings", type=int, default=20, help="chain length (the paper's: 20)")
    args = parser.parse_args(argv)

    chain = paper_chain("dual-spring", n_rings=args.rings)
    g = STANDARD_GRAVITY
    y0, t_recipe, t_cmp, ref_f, check = comparison(chain)
    every = EVERY
    peak = np.abs(ref_f).max()
    ref_uncertainty = float(np.abs(check - ref_f).max() / peak)

    def recipe(rhs):
        x, u = run_recipe(chain, rhs, y0, t_recipe)
        return sensor_forces(chain, x[::every], u[::every])

    def ours(options):
        return simulate(chain, T_END, drop_height=DROP, t_eval=t_cmp, **options).sensor_force[:, SENSORS]

    candidates = {
        "recipe": dict(rhs=paper_rhs(chain, g)),
        "recipe, vectorised rhs": dict(rhs=vectorised_rhs(chain, g)),
        "ringchain dopri5 rtol=1e-9": dict(method="dopri5", rtol=1e-9),
        "ringchain dopri5 rtol=1e-8": dict(method="dopri5", rtol=1e-8),
        "ringchain dopri5 rtol=1e-7": dict(method="dopri5", rtol=1e-7),
        "ringchain odeint rtol=1e-9": dict(method="odeint"),
        "ringchain odeint rtol=3e-9": dict(method="odeint", rtol=3e-9),
        "ringchain odeint rtol=1e-8": dict(method="odeint", rtol=1e-8),
        "ringchain solve_ivp LSODA rtol=1e-9": dict(method="LSODA"),
        "ringchain solve_ivp LSODA rtol=1e-8": dict(method="LSODA", rtol=1e-8),
        "ringchain DOP853 rtol=1e-9": dict(method="DOP853"),
        "ringchain verlet 60/period (default)": dict(method="verlet"),
        "ringchain verlet 200/period": dict(method="verlet", steps_per_period=200),
    }
    funcs = {
        name: (lambda o=o: recipe(o["rhs"])) if "rhs" in o else (lambda o=o: ours(o)) for name, o in candidates.items()
    }
    load = os.getloadavg()[0]
    timed = best_times(funcs, args.repeat)
    rows = [(name, seconds, float(np.abs(forces - ref_f).max() / peak)) for name, (seconds, forces) in timed.items()]
    recipe_time, recipe_error = rows[0][1], rows[0][2]

    print(f"{args.rings}-ring dual-spring chain (R/r = 9), {DROP * 100:g} cm drop, {T_END * 1e3:g} ms; "
          f"best of {args.repeat}, round robin; load average {load:.1f} -> {os.getloadavg()[0]:.1f} "
          f"on {os.cpu_count()} cores")  # fmt: skip
    print(
        "error: max |sensor force - reference| in rings 6 and 12 over the run / peak force; reference LSODA"
        f" rtol 1e-12, within {ref_uncertainty:.0e} of DOP853 rtol 1e-13"
    )
    print(f"{'solver':40s} {'time (s)':>9s} {'error':>9s} {'recipe/this':>12s}")
    for name, seconds, err in rows:
        print(f"{name:40s} {seconds:9.3f} {err:9.2e} {recipe_time / seconds:12.1f}")
    fast = [row for row in rows[2:] if row[2] <= recipe_error]
    if fast:
        best = min(fast, key=lambda row: row[1])
        print(f"fastest at equal or better accuracy than the recipe ({recipe_error:.1e}): {best[0]}, "
              f"{recipe_time / best[1]:.1f}x faster than the recipe, "
              f"{rows[1][1] / best[1]:.1f}x faster than the recipe with the vectorised rhs")  # fmt: skip


if __name__ == "__main__":
    main()
