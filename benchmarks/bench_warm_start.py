"""A warm ``ringchain simulate`` in a fresh process: the README's run, its kernels already on disk.

The README's command (the paper's chain, dual-spring model, sensors 6 and 12) is run once on an empty cache
folder (cold: the integrator is compiled and cached), then ``--repeat`` times more, each in a fresh
interpreter sharing that folder (warm).  Printed:

- the wall and CPU time of a warm process (median of ``--repeat``), beside an empty interpreter's start
  (``python -c pass``) and the issue's bound (1.0 s wall);
- where a warm process spends its time (median of ``--repeat`` instrumented processes): ``imports`` (every
  outermost import outside the kernel's load; of them, the first imports of NumPy and of Numba), ``kernel
  load`` (Numba's start-up and the cached kernels read from disk: ``numba.core.caching.Cache.load_overload``,
  with the imports Numba makes on its way, SciPy's BLAS among them), ``output`` (the CSV,
  :func:`~ringchain.numerics.write_traces`), ``run`` (the rest of the command: parsing, the chain, the
  integration, reading the pulses, printing) and the garbage collector's share of all of them;
- how many compiled kernels the command decorated and how many it loaded, and which heavy packages it
  imported (a run without ``--plot`` needs neither Matplotlib nor SymPy).

The load average is printed first: other work on the machine moves the wall times, the CPU times less.
Run: ``python benchmarks/bench_warm_start.py`` (``--cache DIR`` to reuse a folder of compiled kernels).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

#: The README's command, as ``ringchain`` arguments (the CSV goes to a temporary folder).
COMMAND = ["simulate", "--rings", "20", "--drop-height", "0.05", "--model", "dual-spring", "--sensors", "6", "12"]

#: The issue's bound on a warm run in a fresh process, s (wall).
BOUND = 1.0

#: Runs the command in this process, timing its phases (see the module notes); prints one JSON line.
PROBE = r"""
import builtins, gc, json, sys, time
start = time.perf_counter()
phase = {"imports": 0.0, "numpy": 0.0, "numba": 0.0, "kernel load": 0.0, "output": 0.0, "gc": 0.0}
state = {"depth": 0, "loading": False, "patched": False, "gc_start": 0.0}
counts = {"decorated": 0, "loaded": 0}
original_import = builtins.__import__


def timed_output(function):
    def wrapper(*args, **kwargs):
        t = time.perf_counter()
        try:
            return function(*args, **kwargs)
        finally:
            phase["output"] += time.perf_counter() - t
    return wrapper


def ready(name):
    module = sys.modules.get(name)
    return module if module is not None and not getattr(module.__spec__, "_initializing", False) else None


def patch():
    # Wrap the kernel cache's load, the dispatchers' creation and the CSV writer once their modules are loaded.
    caching, dispatcher = ready("numba.core.caching"), ready("numba.core.dispatcher")
    if caching and dispatcher and not state.get("numba"):
        state["numba"] = True
        load = caching.Cache.load_overload

        def load_overload(self, sig, target_context):
            t, state["loading"] = time.perf_counter(), True
            try:
                result = load(self, sig, target_context)
            finally:
                state["loading"] = False
                phase["kernel load"] += time.perf_counter() - t
            counts["loaded"] += result is not None
            return result

        caching.Cache.load_overload = load_overload
        init = dispatcher.Dispatcher.__init__

        def counted(self, py_func, *args, **kwargs):
            counts["decorated"] += py_func.__module__.startswith("ringchain")
            return init(self, py_func, *args, **kwargs)

        dispatcher.Dispatcher.__init__ = counted
    traces = ready("ringchain.numerics.engine.traces")
    if traces is not None and not state["patched"]:
        state["patched"] = True
        traces.write_traces = timed_output(traces.write_traces)


def timed_import(name, *args, **kwargs):
    outermost = state["depth"] == 0 and not state["loading"]
    first = name in ("numpy", "numba") and name not in sys.modules  # the first import of the package, wherever
    t = time.perf_counter()
    state["depth"] += 1
    try:
        return original_import(name, *args, **kwargs)
    finally:
        state["depth"] -= 1
        if outermost:
            phase["imports"] += time.perf_counter() - t
        if first:
            phase[name] = time.perf_counter() - t
        patch()


def collector(stage, info):
    if stage == "start":
        state["gc_start"] = time.perf_counter()
    else:
        phase["gc"] += time.perf_counter() - state["gc_start"]


builtins.__import__ = timed_import
gc.callbacks.append(collector)
t = time.perf_counter()
from ringchain.numerics.cli import main
sys.argv[0] = "ringchain"
code = main()  # the process's own command line, as the ringchain script runs it
end = time.perf_counter()
builtins.__import__ = original_import
phase["run"] = end - start - phase["imports"] - phase["kernel load"] - phase["output"]
heavy = sorted(name for name in ("sympy", "matplotlib", "scipy", "numba") if name in sys.modules)
print(json.dumps({"code": code, "total": end - start, **phase, **counts, "heavy": heavy}), file=sys.stderr)
"""


def run(args: list[str], cache: str) -> tuple[float, float, str]:
    """(wall s, CPU s of the child, its stderr) of one fresh process."""
    env = {**os.environ, "RINGCHAIN_CACHE_DIR": cache, "RINGCHAIN_NOTICES": "0"}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    done = subprocess.run([sys.executable, *args], env=env, capture_output=True, text=True)
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(args)} failed ({done.returncode}): {done.stderr.strip()}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, done.stderr


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--cache", default=None, help="folder of compiled kernels (default: a new temporary one)")
    args = parser.parse_args(argv)
    print("load average (1, 5, 15 min): {:.2f} {:.2f} {:.2f}".format(*os.getloadavg()))
    with tempfile.TemporaryDirectory() as scratch:
        cache = args.cache or os.path.join(scratch, "cache")
        command = [*COMMAND, "--out", os.path.join(scratch, "run.csv")]
        cli = ["-m", "ringchain.numerics.cli", *command]
        cold, _, _ = run(cli, cache)
        empty = statistics.median(run(["-c", "pass"], cache)[0] for _ in range(args.repeat))
        warm = [run(cli, cache)[:2] for _ in range(args.repeat)]
        probes = [json.loads(run(["-c", PROBE, *command], cache)[2].strip().splitlines()[-1])
                  for _ in range(args.repeat)]  # fmt: skip
    wall, cpu = (statistics.median(column) for column in zip(*warm, strict=True))
    print(f"ringchain {' '.join(COMMAND)} --out run.csv")
    print(f"  first process (cold unless --cache held the kernels)  {cold:6.2f} s wall")
    print(f"  warm, fresh process, median of {args.repeat}: {wall:6.3f} s wall, {cpu:6.3f} s CPU"
          f" (bound {BOUND:.1f} s wall: {'met' if wall <= BOUND else 'NOT met'})")  # fmt: skip
    print(f"    of which an empty interpreter's start (python -c pass)  {empty:6.3f} s wall")
    print(f"  split of a warm process, median of {args.repeat} instrumented processes (s):")
    for name in ("imports", "numpy", "numba", "kernel load", "run", "output", "total", "gc"):
        value = statistics.median(p[name] for p in probes)
        note = {"numpy": "  (of the imports: NumPy's own)", "numba": "  (of the imports: Numba's own, NumPy apart)",
                "gc": "  (the garbage collector, inside the phases above)",
                "total": "  (from the first import to the exit code)"}.get(name, "")  # fmt: skip
        print(f"    {name:<12} {value:6.3f}{note}")
    last = probes[-1]
    print(f"  compiled kernels: {last['decorated']} decorated, {last['loaded']} loaded from the cache")
    print(f"  heavy packages imported: {', '.join(last['heavy']) or 'none'}")


if __name__ == "__main__":
    main()
