"""Trace fits: the time of a fit, its forward runs, and the batched Jacobian against one run at a time.

The measurement is synthetic: the paper's 20-ring chain (:func:`~ringchain.numerics.paper_chain`, R/r = 9,
Table I) with a contact dashpot gamma = 3 N s/m, dropped from 20 mm, read by the sensors in
rings 6 and 12 (1500 samples over 1.5 ms, 1 % noise, a trigger offset and DC offsets).

- "fit": :func:`~ringchain.numerics.fit_traces` of (m, gamma, t0) from a start 30 % off in m
  and 40 % in gamma, with the Jacobian's runs as one batch (default) and one at a time;
- "Jacobian": one Jacobian of the fit (the base point and one run per chain parameter) at
  the solution, batched against one run at a time, for 2 and 4 free chain parameters.

Each timing is the best of ``--repeat`` (default 3), and a fit's CPU time (this process, its threads included)
the mean of them; the load average is printed (the machine may be shared: compare the ratios, measured in
one run, and the CPU times more than the wall times).

Measured (issue 30).  Before: 0.29-0.34 s quiet, 0.65 s at load 5.2; 18 integrator calls were 36 % of a fit, the
rest per-run Python.  What changed: the notice's check of the kernel's compiled version no longer types every
argument in Numba each call (10 ms a call: ``_kernel_calls.fingerprint``); the forward model records only the
sensors' sites and reads every run's sensors in one pass over the batch; a run serves values that differ in the DC
offsets only (one run fewer: 31 runs in 17 calls); each set of chain values makes its chain once.  The fitted
values, standard errors and residuals are byte-identical.  Two sessions, load average 4.5-5.0 on 2 cores shared
with other jobs (before: the commit this work started from, the same script): the fit (batched) 1.09 -> 0.63 s wall
and 0.55 -> 0.33 s CPU (0.60x), 1.08 -> 0.77 s wall in the other session; one run at a time 0.98 -> 0.71 s wall,
0.53 -> 0.40 s CPU; one Jacobian of 3 runs 0.057 -> 0.052 s (0.076 -> 0.033 s in the other session), of 5 runs
0.081 -> 0.074 s (0.115 -> 0.049 s).  Of a fit's CPU time the integrator is now about half (0.17-0.20 s,
instrumented; it was about 0.23 s of 0.53 s).  Issue 30's 0.15 s (quiet) is not shown here, and likely not reached:
the integrator's own time is now most of a fit, and fewer or cheaper runs change the fit's numbers.

Run: ``python benchmarks/bench_fit.py [--model power-law] [--repeat 3]``.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import time

import numpy as np
from bench_batch import best_of  # this folder is on sys.path when a script runs from it
from ringchain.numerics import fit_traces, paper_chain, simulate
from ringchain.numerics.jobs.fit_dynamic import _records, _TraceProblem

DROP = 0.02  # m
T0 = 4e-5  # s: the impact 40 us after the trigger
CLOCK = np.linspace(-0.1e-3, 1.4e-3, 1500)  # s
GAMMA = {"power-law": {"gamma": 3.0}, "dual-spring": {"gamma": 1.0, "gamma_b": 0.5}}


def measurement(truth):
    rng = np.random.default_rng(1)
    tau = CLOCK - T0
    after = tau >= 0
    sim = simulate(truth, tau[-1], drop_height=DROP, t_eval=tau[after], rtol=1e-10)
    peak = max(sim.sensor(k).max() for k in (6, 12))
    traces = {}
    for k, offset in ((6, 0.3), (12, -0.2)):
        y = np.full(CLOCK.size, sim.sensor(k)[0])
        y[after] = sim.sensor(k)
        traces[k] = y + offset + 0.01 * peak * rng.standard_normal(CLOCK.size)
    return traces


def jacobian_time(fit, chain, traces, free, batched, repeat):
    """Seconds of one Jacobian of ``fit_traces`` at the fitted values (and its forward runs)."""
    import lmfit

    records = _records(CLOCK, traces, chain, DROP, None)
    problem = _TraceProblem(records, chain, free, t0=[0.0], offsets=True, rtol=1e-8, gravity=True, batched=batched)
    params = lmfit.Parameters()
    for name in fit.names:
        params.add(name, value=fit.values[name])
    for name in free:
        if name not in params:
            params.add(name, value=float(getattr(fit.chain, name)))
    seconds, _ = best_of(repeat, lambda: problem.jacobian(params))
    return seconds, problem.n_runs // repeat


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default="power-law", choices=("power-law", "dual-spring"))
    parser.add_argument("--repeat", type=int, default=3, help="best of this many timings (default 3)")
    args = parser.parse_args()

    truth = dataclasses.replace(paper_chain(args.model), **GAMMA[args.model])
    traces = measurement(truth)
    start = dataclasses.replace(truth, m=1.3 * truth.m, gamma=0.6 * truth.gamma)
    free = ("m", "gamma", "t0")
    fit_traces(CLOCK, traces, start, drop_height=DROP, free=free)  # warm up (imports, caches)
    print(f"{args.model} chain of {truth.n_rings} rings, drop {DROP * 1e3:g} mm, {CLOCK.size} samples x 2 sensors, "
          f"1 % noise; best of {args.repeat}; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} "
          "cores")  # fmt: skip
    print(f"{'fit (m, gamma, t0)':>24} {'time (s)':>9} {'CPU (s)':>8} {'forward runs':>13} {'integrator calls':>17} "
          f"{'m error':>9} {'gamma error':>12}")  # fmt: skip
    times = {}
    for batched in (True, False):
        cpu = time.process_time()
        seconds, fit = best_of(args.repeat, lambda b=batched: fit_traces(CLOCK, traces, start, drop_height=DROP,
                                                                         free=free, batched=b))  # fmt: skip
        cpu = (time.process_time() - cpu) / args.repeat
        times[batched] = seconds
        label = "batched Jacobian" if batched else "one run at a time"
        print(f"{label:>24} {seconds:9.2f} {cpu:8.2f} {fit.n_forward_runs:13d} {fit.n_batches:17d} "
              f"{fit.values['m'] / truth.m - 1:+9.1e} {fit.values['gamma'] / truth.gamma - 1:+12.1e}")  # fmt: skip
    print(f"{'speed-up of the fit':>24} {times[False] / times[True]:8.2f}x")
    print()
    print(f"{'one Jacobian':>24} {'runs':>5} {'batched (s)':>12} {'one at a time (s)':>18} {'speed-up':>9}")
    sets = [("m", "gamma", "t0"), ("m", "gamma", "K", "n", "t0")]
    for jac_free in sets:
        t_batch, runs = jacobian_time(fit, start, traces, jac_free, True, args.repeat)
        t_single, _ = jacobian_time(fit, start, traces, jac_free, False, args.repeat)
        print(f"{','.join(jac_free):>24} {runs:5d} {t_batch:12.3f} {t_single:18.3f} {t_single / t_batch:8.2f}x")


if __name__ == "__main__":
    main()
