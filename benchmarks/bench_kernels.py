"""The compiled kernels against their limits: a C loop, the paper's recipe, the cold compile, ns per ring.

Four measurements, each a ratio measured in one run (issue 20, "Must show"):

(a) ``c``: the C reference.  benchmarks/c/dopri5_chain.c is the scheme of ringchain's "dopri5"
    (:mod:`ringchain.numerics.engine.kernels`: Dormand-Prince 5(4), max-norm error control, the same step-size
    controller) as a plain C loop, built here with the system ``cc -O2`` into a temporary folder.  Both
    integrate a uniform Hertz chain (F = K delta^(3/2) while engaged; K, m and a of the paper's R/r = 9
    ring, free ends, no gravity) of ``--rings`` rings (10^4) with random initial velocities (normal,
    0.1 m/s, seeded) over 0.2 ms, at the same rtol and the same absolute tolerances (rtol times the
    run's displacement and velocity scales, as :func:`ringchain.numerics.simulate` sets them).  Printed:
    the time of each (the C time loop; ringchain's kernel call, and its whole :func:`simulate` call),
    their steps (identical steps show the controller is the same), the largest difference of their
    final states, and each one's error against a tight reference (SciPy's DOP853 at rtol 1e-12),
    relative to the velocity scale and to the displacement scale.  Target: ringchain/C within 3x.
(b) ``paper``: the paper's 20-ring chain (dual-spring, gravity, 5 cm drop, 2 ms): the paper's recipe
    (odeint, the equations written ring by ring: benchmarks/bench_paper_recipe.py) against "dopri5" at
    its default tolerance; both errors (sensor forces of rings 6 and 12 against one tight reference,
    LSODA at rtol 1e-12, relative to their peak) and the speed ratio.  Target: >= 150x at equal or
    better accuracy.
(c) ``cold``: one :func:`simulate` of the paper's chain in a fresh process with an empty
    ``RINGCHAIN_CACHE_DIR`` (every kernel it calls compiled), then in a second process with the cache
    the first one wrote (wall times of the whole process, imports included; its CPU time, the compile's cost
    whatever the load; and the CPU time of each compiled function from Numba's compile events).
(d) ``ns``: nanoseconds per ring per right-hand-side evaluation (run time / (rings x evaluations)) at
    20 and at 10^4 rings, for ringchain's dopri5 and the C loop on the Hertz chain of (a), and for the
    paper's dual-spring chain.

Timings are the best of ``--repeat`` (the solvers taking turns); no timing is a test.  Run:
``python benchmarks/bench_kernels.py`` (all parts; ``--parts c paper`` for some).
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from bench_paper_recipe import DROP, EVERY, SENSORS, T_END, best_times, comparison, paper_rhs, run_recipe, sensor_forces
from ringchain.numerics import STANDARD_GRAVITY, Chain, paper_chain, simulate
from ringchain.numerics.engine import kernels
from ringchain.numerics.engine.integrate import DEFAULT_RTOL

C_SOURCE = Path(__file__).parent / "c" / "dopri5_chain.c"
HERTZ_T_END = 2e-4  # s: 0.2 ms
SPEED = 0.1  # m/s: spread of the random initial velocities
SEED = 20
PARTS = ("c", "paper", "cold", "ns")

COLD_PROBE = """
import time
start = time.perf_counter()
from numba.core import event
spent, open_ = {}, []  # CPU s of each compiled function, its callees' compiles excluded


class Compiles(event.Listener):
    def on_start(self, ev):
        open_.append([time.thread_time(), 0.0])

    def on_end(self, ev):
        began, inner = open_.pop()
        took = time.thread_time() - began
        if open_:
            open_[-1][1] += took
        name = ev.data["dispatcher"].py_func.__qualname__.split(".")[0]
        spent[name] = spent.get(name, 0.0) + took - inner


event.register("numba:compile", Compiles())
from ringchain.numerics import paper_chain, simulate
from ringchain.numerics.engine import kernels
sim = simulate(paper_chain("dual-spring"), 2e-3, drop_height=0.05)
top = sorted(spent.items(), key=lambda item: -item[1])[:8]
print(time.perf_counter() - start, kernels.CACHE is not None, ",".join(f"{k}={v:.2f}" for k, v in top))
"""


# -- the Hertz chain of (a) and (d) -------------------------------------------------------------------------------
def hertz_chain(n_rings: int) -> Chain:
    """A uniform Hertz chain of ``n_rings`` rings: the paper's R/r = 9 ring (its K_c, m_eff, a), free ends."""
    paper = paper_chain("dual-spring")
    return Chain.power_law(n_rings, K=paper.K_c, n=1.5, m=paper.m, a=paper.a, support="free")


def hertz_problem(n_rings: int, rtol: float):
    """The chain, its initial state (at rest, random velocities) and the absolute tolerances simulate sets."""
    chain = hertz_chain(n_rings)
    rng = np.random.default_rng(SEED)
    x0, u0 = np.zeros(n_rings), rng.normal(0.0, SPEED, n_rings)
    X, V, _ = chain.network().scales(x0[None], u0[None], STANDARD_GRAVITY)  # the run's scales (integrate.py)
    atol = rtol * np.concatenate([np.full(n_rings, X[0]), np.full(n_rings, V[0])])
    return chain, x0, u0, atol, float(X[0]), float(V[0])


def build_c(folder: str) -> str:
    """Compile benchmarks/c/dopri5_chain.c with the system cc -O2; the path of the program."""
    cc = shutil.which("cc")
    if cc is None:
        raise SystemExit("no C compiler: the C reference needs the system cc")
    program = os.path.join(folder, "dopri5_chain")
    subprocess.run([cc, "-O2", "-o", program, os.fspath(C_SOURCE), "-lm"], check=True)
    return program


def run_c(program: str, folder: str, chain: Chain, x0, u0, atol, rtol: float, t_end: float):
    """One run of the C loop: (seconds of its time loop, (evaluations, steps, rejections), final state)."""
    N = x0.size
    inputs, outputs = os.path.join(folder, "in.bin"), os.path.join(folder, "out.bin")
    header = [N, chain.K, chain.n, chain.m, rtol, t_end]
    np.concatenate([header, x0, u0, atol]).astype("<f8").tofile(inputs)
    subprocess.run([program, inputs, outputs], check=True)
    out = np.fromfile(outputs, dtype="<f8")
    status, evaluations, steps, rejections, seconds = out[:5]
    if status != 0:
        raise RuntimeError(f"the C loop stopped with status {status:g} ({kernels.STATUS.get(int(status))})")
    return float(seconds), (int(evaluations), int(steps), int(rejections)), out[5:]


def best_c(program, folder, chain, x0, u0, atol, rtol, t_end, repeat):
    """The best of ``repeat`` runs of the C loop, by its own clock (process start and file input excluded)."""
    runs = [run_c(program, folder, chain, x0, u0, atol, rtol, t_end) for _ in range(repeat)]
    return min(runs, key=lambda run: run[0])


def run_kernel(chain: Chain, x0, u0, atol, rtol: float, t_end: float):
    """ringchain's compiled dopri5 called directly: (counts (evaluations, steps, rejections), final state)."""
    packed = kernels.pack(chain.network())
    y0 = np.concatenate([x0, u0])[None]
    *_, final, status, stats = kernels.dopri5(packed, y0, np.array([t_end]), rtol, atol[None], np.arange(0), 0.0,
                                              locate=False)  # the C loop steps over the contacts  # fmt: skip
    if status[0]:
        raise RuntimeError(f"dopri5 stopped: {kernels.STATUS[int(status[0])]}")
    return tuple(int(s) for s in stats[0][:3]), final[0]


def run_simulate(chain: Chain, x0, u0, rtol: float, t_end: float):
    """The whole simulate call (validation, scales, energy watch, result): the final x and u and the stats."""
    sim = simulate(chain, t_end, initial=(x0, u0), gravity=False, n_samples=3, rtol=rtol)
    return np.concatenate([sim.x[-1], sim.u[-1]]), sim.stats


def loops(func, seconds=0.2):
    """Calls of ``func`` that take about ``seconds`` (at least one): a fast run timed over several calls."""
    start = time.perf_counter()
    func()
    once = max(time.perf_counter() - start, 1e-6)
    count = max(1, round(seconds / once))

    def repeated():
        for _ in range(count):
            result = func()
        return result

    return count, repeated


# -- (a) the C reference -----------------------------------------------------------------------------------------
def part_c(args, folder, program, rows):
    N, rtol = args.rings, args.rtol
    chain, x0, u0, atol, X, V = hertz_problem(N, rtol)
    run_kernel(chain, x0, u0, atol, rtol, HERTZ_T_END)  # compile (or load) before timing
    run_simulate(chain, x0, u0, rtol, HERTZ_T_END)
    c_seconds, c_counts, c_final = best_c(program, folder, chain, x0, u0, atol, rtol, HERTZ_T_END, args.repeat)
    timed = best_times({
        "kernel": lambda: run_kernel(chain, x0, u0, atol, rtol, HERTZ_T_END),
        "simulate": lambda: run_simulate(chain, x0, u0, rtol, HERTZ_T_END),
    }, args.repeat)  # fmt: skip
    k_seconds, (k_counts, k_final) = timed["kernel"]
    s_seconds, (s_final, s_stats) = timed["simulate"]
    reference = simulate(chain, HERTZ_T_END, initial=(x0, u0), gravity=False, n_samples=3, rtol=1e-12,
                         method="DOP853")  # fmt: skip
    ref = np.concatenate([reference.x[-1], reference.u[-1]])

    def errors(final):
        return np.abs(final[:N] - ref[:N]).max() / X, np.abs(final[N:] - ref[N:]).max() / V

    print(f"\n(a) uniform Hertz chain of {N} rings, random velocities ({SPEED:g} m/s rms), {HERTZ_T_END * 1e3:g} ms, "
          f"rtol {rtol:g} (atol rtol x scales); reference DOP853 rtol 1e-12; errors of the final state / scale "
          f"(X = {X:.3g} m, V = {V:.3g} m/s)")  # fmt: skip
    print(f"{'solver':28s} {'time (s)':>9s} {'evals':>7s} {'steps':>6s} {'rejected':>8s} {'x error':>9s} "
          f"{'u error':>9s} {'this/C':>7s}")  # fmt: skip
    for name, seconds, counts, final in (("C loop (cc -O2)", c_seconds, c_counts, c_final),
                                         ("ringchain kernels.dopri5", k_seconds, k_counts, k_final),
                                         ("ringchain simulate dopri5", s_seconds, None, s_final)):  # fmt: skip
        if counts is None:
            counts = (s_stats["nfev"], s_stats["steps"][0], s_stats["rejected"][0])
        ex, eu = errors(final)
        print(f"{name:28s} {seconds:9.4f} {counts[0]:7d} {counts[1]:6d} {counts[2]:8d} {ex:9.2e} {eu:9.2e} "
              f"{seconds / c_seconds:7.2f}")  # fmt: skip
    same = np.abs(k_final - c_final)
    print(
        f"same steps as C: {k_counts == c_counts}; final states differ by at most {same[:N].max() / X:.2e} X and "
        f"{same[N:].max() / V:.2e} V ({np.count_nonzero(same)} of {2 * N} components not bit-identical)"
    )
    rows["c"] = (c_seconds, k_seconds, s_seconds, c_counts[0], k_counts[0], s_stats["nfev"])


# -- (b) the paper's recipe --------------------------------------------------------------------------------------
def part_paper(args, rows):
    chain = paper_chain("dual-spring")
    y0, t_recipe, t_cmp, ref, check = comparison(chain)
    every = EVERY
    peak = np.abs(ref).max()
    rhs = paper_rhs(chain, STANDARD_GRAVITY)

    def recipe():
        x, u = run_recipe(chain, rhs, y0, t_recipe)
        return sensor_forces(chain, x[::every], u[::every])

    def ours():
        sim = simulate(chain, T_END, drop_height=DROP, t_eval=t_cmp)
        return sim.sensor_force[:, SENSORS], sim.stats

    ours()  # compile (or load) before timing
    timed = best_times({"recipe": recipe, "dopri5": ours}, args.repeat)
    (r_seconds, r_forces), (d_seconds, (d_forces, stats)) = timed["recipe"], timed["dopri5"]
    r_error, d_error = (float(np.abs(f - ref).max() / peak) for f in (r_forces, d_forces))
    print(f"\n(b) the paper's 20-ring chain (dual-spring, R/r = 9), {DROP * 100:g} cm drop, {T_END * 1e3:g} ms; error: "
          f"max |sensor force - reference| (rings 6, 12) / peak; reference DOP853 rtol 1e-13 from contact event to "
          f"contact event, within {np.abs(check[0] - ref).max() / peak:.0e} of the same at rtol 1e-12")  # fmt: skip
    print(f"{'solver':40s} {'time (s)':>9s} {'error':>9s} {'recipe/this':>12s}")
    print(f"{'recipe (odeint, ring-by-ring rhs)':40s} {r_seconds:9.4f} {r_error:9.2e} {1.0:12.1f}")
    print(f"{f'ringchain dopri5 rtol {DEFAULT_RTOL:g} (default)':40s} {d_seconds:9.4f} {d_error:9.2e} "
          f"{r_seconds / d_seconds:12.1f}")  # fmt: skip
    rows["paper"] = (r_seconds, d_seconds, r_error, d_error, stats["nfev"])


# -- (c) the cold compile ----------------------------------------------------------------------------------------
def part_cold(args, rows):
    with tempfile.TemporaryDirectory(prefix="ringchain-cold-") as cache:
        env = {**os.environ, "RINGCHAIN_CACHE_DIR": cache}
        walls = []
        for _ in range(2):
            start, cpu = time.perf_counter(), resource.getrusage(resource.RUSAGE_CHILDREN)
            out = subprocess.run([sys.executable, "-W", "error", "-c", COLD_PROBE], env=env, capture_output=True,
                                 text=True, check=True).stdout.split()  # fmt: skip
            used = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = used.ru_utime + used.ru_stime - cpu.ru_utime - cpu.ru_stime
            walls.append((time.perf_counter() - start, float(out[0]), out[1] == "True", cpu, os.getloadavg()[0],
                          out[2] if len(out) > 2 else ""))  # fmt: skip
    print("\n(c) one simulate of the paper's chain in a fresh process (wall s: whole process / import and call; CPU s "
          "of the process: the compile's cost whatever the load)")  # fmt: skip
    for name, (wall, inner, cached, cpu, load, _) in zip(("empty cache (cold)", "warm cache"), walls, strict=True):
        print(f"{name:28s} {wall:9.2f} {inner:9.2f}  CPU {cpu:6.2f}  load {load:4.1f}  "
              f"disk cache {'on' if cached else 'off'}")  # fmt: skip
    print("cold compile, CPU s per compiled function (Numba's compile events, its callees excluded): "
          + walls[0][5].replace(",", ", ").replace("=", " "))  # fmt: skip
    rows["cold"] = walls


# -- (d) ns per ring per evaluation ------------------------------------------------------------------------------
def part_ns(args, folder, program, rows):
    print("\n(d) ns per ring per right-hand-side evaluation (run time / (rings x evaluations); best of "
          f"{args.repeat})")  # fmt: skip
    print(f"{'problem':44s} {'rings':>6s} {'evals':>7s} {'time (s)':>10s} {'ns/ring/eval':>13s}")
    for N in (20, args.rings):
        chain, x0, u0, atol, *_ = hertz_problem(N, args.rtol)
        run_kernel(chain, x0, u0, atol, args.rtol, HERTZ_T_END)
        count, kernel = loops(lambda chain=chain, x0=x0, u0=u0, atol=atol: run_kernel(chain, x0, u0, atol, args.rtol,
                                                                                      HERTZ_T_END))  # fmt: skip
        c_seconds, c_counts, _ = best_c(program, folder, chain, x0, u0, atol, args.rtol, HERTZ_T_END, args.repeat)
        k_seconds, (k_counts, _) = best_times({"": kernel}, args.repeat)[""]
        k_seconds /= count
        for name, seconds, evals in (("Hertz chain, C loop", c_seconds, c_counts[0]),
                                     ("Hertz chain, ringchain kernels.dopri5", k_seconds, k_counts[0])):  # fmt: skip
            print(f"{name:44s} {N:6d} {evals:7d} {seconds:10.5f} {1e9 * seconds / (N * evals):13.2f}")
    chain = paper_chain("dual-spring")
    simulate(chain, T_END, drop_height=DROP)
    count, run = loops(lambda: simulate(chain, T_END, drop_height=DROP))
    seconds, sim = best_times({"": run}, args.repeat)[""]
    seconds /= count
    evals = sim.stats["nfev"]
    print(f"{'paper dual-spring chain, simulate dopri5':44s} {20:6d} {evals:7d} {seconds:10.5f} "
          f"{1e9 * seconds / (20 * evals):13.2f}  (2 sites per ring, 2001 samples)")  # fmt: skip


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--parts", nargs="+", choices=PARTS, default=list(PARTS))
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--rings", type=int, default=10_000, help="rings of the Hertz chain of (a) and (d)")
    parser.add_argument("--rtol", type=float, default=DEFAULT_RTOL, help="rtol of (a) and (d)")
    args = parser.parse_args(argv)
    load = os.getloadavg()[0]
    print(f"load average {load:.1f} on {os.cpu_count()} cores; Numba cache: {kernels.CACHE}")
    rows: dict = {}
    with tempfile.TemporaryDirectory(prefix="ringchain-c-") as folder:
        program = build_c(folder) if {"c", "ns"} & set(args.parts) else None
        if "c" in args.parts:
            part_c(args, folder, program, rows)
        if "paper" in args.parts:
            part_paper(args, rows)
        if "ns" in args.parts:
            part_ns(args, folder, program, rows)
    if "cold" in args.parts:
        part_cold(args, rows)
    print("\nsummary")
    if "c" in rows:
        c, k, s, *_ = rows["c"]
        print(f"  {args.rings} rings: ringchain/C = {k / c:.2f} (kernel), {s / c:.2f} (simulate); target <= 3")
    if "paper" in rows:
        r, d, re, de, _ = rows["paper"]
        print(f"  paper chain: recipe/dopri5 = {r / d:.0f}x at errors {de:.1e} (dopri5) and {re:.1e} (recipe); "
              "target >= 150x at equal or better accuracy")  # fmt: skip
    if "cold" in rows:
        (cold, _, _, cold_cpu, *_), (warm, *_) = rows["cold"]
        print(f"  one simulate in a fresh process: {cold:.1f} s cold ({cold_cpu:.1f} s of CPU), {warm:.2f} s with a "
              "warm cache")  # fmt: skip
    print(f"load average now {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
