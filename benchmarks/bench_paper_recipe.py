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

The reference is independent of ringchain's integrators and located at every contact: SciPy's
DOP853 at rtol 1e-13 on the ring-by-ring right-hand side, restarted at each opening and closing of a
Hertz contact (found by solve_ivp's event location, then integrated again to end exactly there), so
that no step of the reference straddles a kink of the contact law (:func:`event_reference`); its own
uncertainty is printed (its distance to the same at rtol 1e-12, and to LSODA at rtol 1e-12).  A second
table gives the error of ringchain's "dopri5" against its tolerance, with the steps ending at the
contacts' openings and closings (its default) and stepping over them (``locate=False``).

Every timing is the best of ``--repeat`` runs (default 5), the solvers taking turns, so
that a change of machine load is shared by all of them.  Run: ``python benchmarks/bench_paper_recipe.py``.
"""

from __future__ import annotations

import argparse
import functools
import os
import time

import numpy as np
from ringchain.numerics import STANDARD_GRAVITY, Chain, initial_state, paper_chain, simulate
from ringchain.numerics.engine import kernels
from ringchain.numerics.engine.integrate import DEFAULT_RTOL
from scipy.integrate import odeint, solve_ivp

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


def event_reference(chain, y0, t_cmp, g, rtol=1e-13):
    """Sensor forces (rings 6 and 12) on ``t_cmp`` of the recipe's right-hand side (:func:`paper_rhs`) integrated
    by SciPy's DOP853 from contact event to contact event, and the number of events.

    Each segment is found by a run with the Hertz contacts' extensions as terminal events (the first change of
    engagement), then integrated again from its start to end exactly at the event, so that no step of the
    reference crosses a kink of the contact law.  The absolute tolerances are ``rtol`` times the run's scales.
    """
    N = chain.n_rings
    S = 2 * N
    recipe_rhs = paper_rhs(chain, g)

    def rhs(t, y):
        return recipe_rhs(y, t)

    X, V, _ = chain.network().scales(y0[None, :S], y0[None, S:], g)
    atol = rtol * np.concatenate([np.full(S, X[0]), np.full(S, V[0])])

    def extension(j, y):  # the Hertz contact above ring j (with ring j + 1, or the support); on velocities: its rate
        return (y[2 * j + 2] if j < N - 1 else 0.0) - y[2 * j + 1]

    engaged = [extension(j, y0) > 0 or (extension(j, y0) == 0 and extension(j, y0[S:]) > 0) for j in range(N)]
    out = np.empty((t_cmp.size, 2 * S))
    t0, y, events = 0.0, y0.copy(), 0
    while t0 < T_END:
        watch = []
        for j in range(N):
            event = functools.partial(lambda t, y, j: extension(j, y), j=j)
            event.terminal, event.direction = True, (-1.0 if engaged[j] else 1.0)
            watch.append(event)
        probe = solve_ivp(rhs, (t0, T_END), y, method="DOP853", rtol=rtol, atol=atol, events=watch)
        t1 = T_END
        if probe.status == 1:
            t1 = min(times[0] for times in probe.t_events if times.size)
            for j, times in enumerate(probe.t_events):
                if times.size and times[0] == t1:
                    engaged[j] = not engaged[j]
            events += 1
        inside = np.flatnonzero((t_cmp >= t0) & (t_cmp < t1))
        segment = solve_ivp(rhs, (t0, t1), y, method="DOP853", rtol=rtol, atol=atol,
                            t_eval=np.concatenate([t_cmp[inside], [t1]]))  # fmt: skip
        out[inside] = segment.y[:, :-1].T
        t0, y = t1, segment.y[:, -1].copy()
    out[-1] = y
    return sensor_forces(chain, out[:, :S], out[:, S:]), events


def comparison(chain):
    """The recipe's initial state and time grid, the comparison's grid, and on it the reference sensor forces
    (:func:`event_reference` at rtol 1e-13) with the same at 1e-12 and LSODA's at 1e-12 as their checks, N,
    shape (T, 2) each."""
    x0, u0 = initial_state(chain, drop_height=DROP)
    y0 = np.concatenate([x0[0], u0[0]])
    t_recipe = np.linspace(0.0, T_END, round(T_END * 1e3 * STEPS_PER_MS) + 1)
    t_cmp = t_recipe[::EVERY]
    ref = event_reference(chain, y0, t_cmp, STANDARD_GRAVITY)[0]
    looser = event_reference(chain, y0, t_cmp, STANDARD_GRAVITY, rtol=1e-12)[0]
    lsoda = simulate(chain, T_END, drop_height=DROP, t_eval=t_cmp, method="LSODA", rtol=1e-12).sensor_force[:, SENSORS]
    return y0, t_recipe, t_cmp, ref, (looser, lsoda)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--rings", type=int, default=20, help="chain length (the paper's: 20)")
    args = parser.parse_args(argv)

    chain = paper_chain("dual-spring", n_rings=args.rings)
    g = STANDARD_GRAVITY
    y0, t_recipe, t_cmp, ref_f, (looser, lsoda) = comparison(chain)
    every = EVERY
    peak = np.abs(ref_f).max()

    def recipe(rhs):
        x, u = run_recipe(chain, rhs, y0, t_recipe)
        return sensor_forces(chain, x[::every], u[::every])

    def ours(options):
        return simulate(chain, T_END, drop_height=DROP, t_eval=t_cmp, **options).sensor_force[:, SENSORS]

    candidates = {
        "recipe": dict(rhs=paper_rhs(chain, g)),
        "recipe, vectorised rhs": dict(rhs=vectorised_rhs(chain, g)),
        **{f"ringchain dopri5 rtol={r:g}{' (default)' if r == DEFAULT_RTOL else ''}": dict(method="dopri5", rtol=r)
           for r in sorted({1e-7, 1e-8, 1e-9, DEFAULT_RTOL, 1e-10, 1e-11}, reverse=True)},
        "ringchain odeint rtol=1e-9": dict(method="odeint"),
        "ringchain odeint rtol=1e-8": dict(method="odeint", rtol=1e-8),
        "ringchain solve_ivp LSODA rtol=1e-9": dict(method="LSODA"),
        "ringchain DOP853 rtol=1e-9": dict(method="DOP853"),
        "ringchain verlet 60/period (default)": dict(method="verlet"),
        "ringchain verlet 200/period": dict(method="verlet", steps_per_period=200),
    }  # fmt: skip
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
    print(f"error: max |sensor force - reference| in rings 6 and 12 over the run / peak force; reference DOP853"
          f" rtol 1e-13 from contact event to contact event, within {np.abs(looser - ref_f).max() / peak:.0e} of"
          f" the same at rtol 1e-12 and {np.abs(lsoda - ref_f).max() / peak:.0e} of LSODA at rtol 1e-12")  # fmt: skip
    print(f"{'solver':40s} {'time (s)':>9s} {'error':>9s} {'recipe/this':>12s}")
    for name, seconds, err in rows:
        print(f"{name:40s} {seconds:9.4f} {err:9.2e} {recipe_time / seconds:12.1f}")
    for target, label in ((recipe_error, f"the recipe's ({recipe_error:.1e})"), (1e-6, "1e-6 of the peak")):
        fast = [row for row in rows[2:] if row[2] <= target]
        if fast:
            best = min(fast, key=lambda row: row[1])
            print(f"fastest at an error within {label}: {best[0]}, {recipe_time / best[1]:.1f}x faster than the "
                  f"recipe, {rows[1][1] / best[1]:.1f}x faster than the recipe with the vectorised rhs")  # fmt: skip
    order_table(chain, t_cmp, ref_f, peak)


def order_table(chain, t_cmp, ref_f, peak):
    """The error of dopri5 against its tolerance, stepping to the contacts' openings and closings and over them,
    and the slope of log(error) against log(rtol) over each three decades."""
    print("\ndopri5 error against rtol (steps ending at the contacts: the default; stepping over them: "
          "locate=False); slope: d log(error) / d log(rtol) over three decades")  # fmt: skip
    rtols = [1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12]
    errors = {}
    for locate in (True, False):
        dopri5 = kernels.dopri5
        kernels.dopri5 = functools.partial(dopri5, locate=locate)
        try:
            errors[locate] = [
                float(np.abs(simulate(chain, T_END, drop_height=DROP, t_eval=t_cmp, rtol=r).sensor_force[:, SENSORS]
                             - ref_f).max() / peak) for r in rtols
            ]  # fmt: skip
        finally:
            kernels.dopri5 = dopri5
    print(f"{'rtol':>8s} {'located':>9s} {'slope':>6s} {'over':>9s} {'slope':>6s}")
    for k, r in enumerate(rtols):
        slopes = [np.log10(e[k - 3] / e[k]) / 3 if k >= 3 else np.nan for e in (errors[True], errors[False])]
        print(f"{r:8.0e} {errors[True][k]:9.2e} {slopes[0]:6.2f} {errors[False][k]:9.2e} {slopes[1]:6.2f}")


if __name__ == "__main__":
    main()
