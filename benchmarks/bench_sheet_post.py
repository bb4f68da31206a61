"""A 100 x 100 sheet, 2 ms after a point impact, all sites recorded: the integration against what follows it.

The sheet of benchmarks/bench_sheet.py (rings of R/r = 9, AISI 304, m_eff = 0.37 m0, lying flat, every link
pretensioned to 2 N, edges clamped; the middle site of the bottom edge struck at 0.5 m/s), 2 ms at 201 samples
(``ringchain sheet``'s default), every site recorded.  Timed, each the best of ``--repeat`` runs (the machine is
shared; the load average is printed before and after):

- ``run``: :func:`ringchain.numerics.simulate` alone (the integration, warm kernels);
- ``link_force``, ``energy``: the run's link forces and energy budget, each on a fresh result, and ``both`` on
  one fresh result (what the command does: one compiled pass gives both, :mod:`ringchain.numerics.engine.fields`),
  and ``both, NumPy``: the same by the NumPy reference (the path before the compiled fields), in the same process;
- ``file``: :meth:`~ringchain.numerics.SheetSimulation.to_netcdf` with the forces and energies already made;
- ``command``: ``ringchain sheet --size 100x100 --pretension 2 --m-eff-ratio 0.37 --impact-velocity 0.5
  --t-end 2e-3 --out FILE`` in this process (building the sheet, the run, forces, energies, the file).

The issue's bound: (run + both + file) <= 1.3 run.  ``--compile`` also times, in a fresh process on
an empty cache, the first link forces and energies of a small sheet (the cold compile of the compiled fields).

Measured (2-core machine shared with three other sessions; the load average stated with each):

- before (the fields in NumPy), load average 2.0-4.1: run 20.2 s, link_force 0.75 s, energy 0.73 s, file
  1.15 s: the rest 2.62 s = 0.13x the run (total 1.13x); the command 21.9 s.  (The run took 5.5 s when the issue
  was filed; the integrator now ends a step at every contact that opens or closes, 20200 links here.)
- after (compiled fields), load average 4.7-8.2 (the run also slower): run 35.9 s, link_force 0.67 s, energy
  0.54 s, both 0.60 s, file 1.18 s: the rest 1.78 s = 0.05x the run (total 1.05x); the command 33.9 s.
  Again at load 8.1-8.6: run 40.2 s, both 0.69 s against 4.59 s by NumPy in the same process (6.7x), file
  1.36 s: the rest 2.05 s = 0.05x (total 1.05x); the command 45.2 s.  On a machine at load 4 (processor time,
  forces and energies of recorded states without a run): 55-66 ns per link and sample, 0.23 s here, and the
  file 0.50 s of processor time (0.28 s of it fixed: its 32 variables), so that a run of 5.5 s would have
  about 1.0 s after it (1.2x).
- Cold compile of the fields (``--compile``): 5.4-5.7 s wall at load 4.7-4.9 (2.6 s of processor time);
  39 ms to load them from the disk cache in a new process.

Run: ``python benchmarks/bench_sheet_post.py [--size 100] [--repeat 3] [--compile]``.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from ringchain.numerics import Sheet, simulate
from ringchain.numerics.cli import main as ringchain
from ringchain.theory import Ring

T_END, SAMPLES, SPEED = 2e-3, 201, 0.5


def build(size):
    sheet = Sheet.square(size, size, Ring.from_aspect_ratio(9.0), pretension=2.0, m_eff_ratio=0.37)
    return sheet.struck_at([sheet.site(0, size // 2)])


def run(sheet):
    return simulate(sheet, T_END, impact_velocity=SPEED, n_samples=SAMPLES, max_seconds=None)


def best(repeat, setup, timed):
    """The shortest wall time of ``timed(setup())`` over ``repeat`` calls, s."""
    times = []
    for _ in range(repeat):
        arg = setup()
        start = time.perf_counter()
        timed(arg)
        times.append(time.perf_counter() - start)
    return min(times)


def load() -> str:
    return ", ".join(f"{x:.2f}" for x in os.getloadavg())


COMPILE = """
import time
from ringchain.numerics import Sheet, simulate
from ringchain.theory import Ring
sheet = Sheet.square(4, 4, Ring.from_aspect_ratio(9.0), pretension=2.0, struck=[1])
result = simulate(sheet, 1e-4, impact_velocity=0.5, n_samples=11)
start = time.perf_counter()
result.link_force, result.energy()
first = time.perf_counter() - start
result = simulate(sheet, 1e-4, impact_velocity=0.5, n_samples=11)
start = time.perf_counter()
result.link_force, result.energy()
print(first, time.perf_counter() - start)
"""


def cold_fields() -> tuple[float, float]:
    """(first, second) link forces and energies of a 4 x 4 sheet in a fresh process on an empty cache, s."""
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, RINGCHAIN_CACHE_DIR=cache)
        out = subprocess.run([sys.executable, "-c", COMPILE], env=env, capture_output=True, text=True, check=True)
    first, second = (float(x) for x in out.stdout.split())
    return first, second


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--size", type=int, default=100)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--compile", action="store_true", help="time the cold compile of the fields too")
    args = parser.parse_args()
    print(f"load average {load()}")
    if args.compile:
        first, second = cold_fields()
        print(f"fields of a 4 x 4 sheet in a fresh process, empty cache: first {first:.2f} s (the compile), "
              f"then {second * 1e3:.1f} ms")  # fmt: skip
    with tempfile.TemporaryDirectory() as folder:
        small = build(4)
        warm = run(small)
        warm.link_force, warm.energy()
        warm.to_netcdf(Path(folder) / "warm.nc")  # every kernel compiled or loaded, xarray imported
        sheet = build(args.size)
        print(f"{args.size} x {args.size} square sheet: {sheet.n_sites} rings, {sheet.n_links} links, "
              f"{T_END * 1e3:g} ms at {SAMPLES} samples, every site recorded")  # fmt: skip
        times = {"run": best(args.repeat, lambda: sheet, run)}
        result = run(sheet)
        times["link_force"] = best(args.repeat, lambda: run_copy(result), lambda r: r.link_force)
        times["energy"] = best(args.repeat, lambda: run_copy(result), lambda r: r.energy())
        times["both"] = best(args.repeat, lambda: run_copy(result), lambda r: (r.link_force, r.energy()))
        times["both, NumPy"] = best(args.repeat, lambda: result, numpy_fields)
        result.link_force, result.energy()
        path = Path(folder) / "run.nc"
        times["file"] = best(args.repeat, lambda: result, lambda r: r.to_netcdf(path))
        size = f"{args.size}x{args.size}"
        options = f"sheet --size {size} --pretension 2 --m-eff-ratio 0.37 --impact-velocity {SPEED} --t-end {T_END}"
        options = [*options.split(), "--out", str(Path(folder) / "cli.nc")]
        times["command"] = best(args.repeat, lambda: None, lambda _: quiet(ringchain, options))
    rest = times["both"] + times["file"]
    for name, seconds in times.items():
        print(f"{name:>12}: {seconds:6.2f} s")
    print(f"the rest (link_force and energy of one run, file) {rest:.2f} s = {rest / times['run']:.2f}x the run; total "
          f"{(times['run'] + rest) / times['run']:.2f}x the run (bound 1.3x); the command {times['command']:.2f} s = "
          f"{times['command'] / times['run']:.2f}x the run")  # fmt: skip
    print(f"load average {load()}")


def numpy_fields(result):
    """The link forces and energies by the NumPy reference (Network.link_forces, Network.energy): the path before."""
    net = result.network
    net.link_forces(result.x, result.u)
    net.energy(result.x, result.u, result.x[:1], result.g, result.dissipated)


def run_copy(result):
    """The same run as a fresh result (nothing derived from it cached yet)."""
    return type(result)(**{name: getattr(result, name) for name in result.__dataclass_fields__})


def quiet(command, options):
    import contextlib
    import io

    with contextlib.redirect_stdout(io.StringIO()):
        if command(options) != 0:
            raise RuntimeError(f"ringchain {' '.join(options)} failed")


if __name__ == "__main__":
    main()
