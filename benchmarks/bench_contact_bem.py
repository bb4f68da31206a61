"""A 15-load numerical contact curve of two tori at the angles of Table II; our FFT solver against ContactMechanics.

:func:`ringchain.numerics.contact_curve` on the paper's R/r = 9 stainless ring (r = 2.5 mm),
15 forces log-spaced over 1-100 N (the window of Table II's power law).  For each angle the
script prints the wall and CPU time of the whole call (pilot solves, the 15 loads on one grid with
one elastic kernel, the resolution check), the grid (pixels and spacing), the resolution
check's force change, the number of patches and the time per load; at 30 degrees it also
times the naive axial frame.  The target is under 30 s for 30 degrees on 2 cores.

Then the solver alone, old against new, on the same problems: the gap of each angle's production
grid (:class:`~ringchain.numerics.contact.bem.Tori`, without the other patch's field), each curve's
15 forces on it, the same starting forces and tolerances, solved by
:class:`~ringchain.numerics.contact.halfspace.ElasticHalfSpace` and, if it is installed (it no longer
is a dependency), by ContactMechanics' ``FreeFFTElasticHalfSpace`` and ``minimize_proxy`` (Polonsky and
Keer on the same Hockney-padded kernel), which ran before.  It prints both CPU and wall times, their
ratio and the largest relative difference of the approaches.  Last, the import time of
``ringchain.numerics.contact.bem`` (and of ContactMechanics, if installed) in a fresh process.

Each timing is the best of ``--repeat`` (default 2); the 1-minute load average is printed,
since other work on the machine slows every figure alike (CPU time less than wall time).

Run: ``python benchmarks/bench_contact_bem.py [--repeat 2] [--angles 30 90 60 20] [--no-curves]``.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time
import warnings

import numpy as np
from ringchain.numerics import HalfSpaceWarning, contact_curve
from ringchain.numerics.contact.bem import Tori
from ringchain.numerics.contact.halfspace import ElasticHalfSpace
from ringchain.theory import STAINLESS_STEEL_304, paper_data

R_OVER_R = paper_data.TABLE_II_ASPECT_RATIO
FORCES = np.geomspace(1.0, 100.0, 15)  # N
TARGET_S = 30.0
PENTOL, FORCETOL = 1e-6, 1e-9  # relative to the approach and to the load, as contact_curve asks


def best_of(repeat, func):
    """(wall s, CPU s, result): the smallest wall time of ``repeat`` calls and the CPU time of that call."""
    best, result = (np.inf, np.inf), None
    for _ in range(repeat):
        wall, cpu = time.perf_counter(), time.process_time()
        result = func()
        timing = (time.perf_counter() - wall, time.process_time() - cpu)
        best = min(best, timing)
    return best[0], best[1], result


def load_average():
    return f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs"


def library():
    """ContactMechanics and SurfaceTopography if installed (the solver that ran before ours), else None."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # NuMPI warns that it runs without MPI
            import ContactMechanics
            import SurfaceTopography
    except ImportError:
        return None
    return ContactMechanics, SurfaceTopography


def problems(curve):
    """The curve's grid, the tori's gap on it, and per load: (force on the grid N, approach m) of the curve."""
    tori = Tori(curve.R, curve.r, curve.angle, curve.frame)
    X, Y = np.meshgrid(curve.pressure.x, curve.pressure.y, indexing="ij")
    nx, ny, hx, hy = curve.grid
    totals = curve.pressure.p.sum(axis=(1, 2)) * hx * hy
    loads = list(zip(totals, curve.delta * np.cos(curve.tilt), strict=True))
    return (nx, ny), (nx * hx, ny * hy), tori.gap(X, Y), loads


def guess(gap, approach, total):
    """Hertz's pressure shape on the gap at 0.8 times the approach (both solvers start from it)."""
    forces = np.sqrt(np.maximum(0.0, 0.8 * approach / 2 - gap))
    return forces * total / forces.sum()


def ours(shape, size, E_star, gap, loads):
    space = ElasticHalfSpace(shape, size, E_star)
    return [
        space.solve(
            gap, load=total, initial_forces=guess(gap, delta, total), pentol=PENTOL * delta, forcetol=FORCETOL * total
        ).approach
        for total, delta in loads
    ]


def theirs(modules, shape, size, E_star, gap, loads):
    contact_mechanics, topography = modules
    substrate = contact_mechanics.FreeFFTElasticHalfSpace(shape, E_star, size)
    pad = ((0, shape[0]), (0, shape[1]))
    approaches = []
    for total, delta in loads:
        system = contact_mechanics.make_system(surface=topography.Topography(-gap, size), substrate=substrate)
        result = system.minimize_proxy(
            external_force=total, initial_forces=-np.pad(guess(gap, delta, total), pad),
            pentol=PENTOL * delta, forcetol=FORCETOL * total, maxiter=5000,
        )  # fmt: skip
        if not result.success:
            raise RuntimeError(result.message)
        approaches.append(result.offset)
    return approaches


def import_seconds(module):
    """Wall time (s) of importing ``module`` in a fresh interpreter (the interpreter's own start excluded)."""
    code = (
        "import time, warnings; warnings.simplefilter('ignore'); t = time.perf_counter(); "
        f"import {module}; print(time.perf_counter() - t)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return float(out.stdout)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--angles", type=float, nargs="+", default=[30.0, 90.0, 60.0, 20.0])
    parser.add_argument("--no-curves", action="store_true", help="skip the whole curves' timings")
    args = parser.parse_args()
    r = paper_data.TUBE_RADIUS
    R, steel = R_OVER_R * r, STAINLESS_STEEL_304
    print(f"contact_curve: R/r = {R_OVER_R:g}, r = {r * 1e3:g} mm, {len(FORCES)} forces over 1-100 N; {load_average()}")
    cases = [(angle, "tangent") for angle in args.angles]
    if 30.0 in args.angles and not args.no_curves:
        cases.insert(1, (30.0, "axial"))
    curves = {}
    for angle, frame in cases:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", HalfSpaceWarning)  # the largest contacts reach 0.1-0.3 r

            def run(a=angle, f=frame):
                return contact_curve(R, r, steel.E, steel.nu, np.radians(a), FORCES, frame=f)

            seconds, cpu, curve = best_of(1 if args.no_curves else args.repeat, run)
        if frame == "tangent":
            curves[angle] = curve
        if args.no_curves:
            continue
        nx, ny, hx, hy = curve.grid
        verdict = f" (target < {TARGET_S:g} s: {'met' if seconds < TARGET_S else 'MISSED'})" if angle == 30.0 else ""
        print(f"  {angle:4g} deg {frame:7s}: {seconds:6.2f} s wall, {cpu:6.2f} s CPU{verdict}, "
              f"{seconds / len(FORCES) * 1e3:5.0f} ms per load (with pilots and check); grid {nx} x {ny} pixels of "
              f"{hx * 1e6:.2f} x {hy * 1e6:.2f} um; resolution check {curve.resolution_error:.2%}; "
              f"patches {int(curve.n_patches[0])}")  # fmt: skip

    modules = library()
    print(f"the solver alone, {len(FORCES)} force-controlled loads on each curve's grid; {load_average()}")
    if modules is None:
        print("  (ContactMechanics is not installed: our solver only)")
    E_star = float(curves[args.angles[0]].E_star)
    for angle, curve in curves.items():
        shape, size, gap, loads = problems(curve)
        wall, cpu, approach = best_of(args.repeat, lambda: ours(shape, size, E_star, gap, loads))  # noqa: B023
        line = f"  {angle:4g} deg, {shape[0]} x {shape[1]}: ours {wall:6.2f} s wall, {cpu:6.2f} s CPU"
        if modules is not None:
            wall_cm, cpu_cm, approach_cm = best_of(
                args.repeat,
                lambda: theirs(modules, shape, size, E_star, gap, loads),  # noqa: B023
            )
            worst = np.max(np.abs(np.array(approach) / np.array(approach_cm) - 1))
            line += (
                f"; ContactMechanics {wall_cm:6.2f} s wall, {cpu_cm:6.2f} s CPU; ratio {wall_cm / wall:.1f} (wall), "
                f"{cpu_cm / cpu:.1f} (CPU); approaches differ by {worst:.1e} at most"
            )
        print(line)
    print(f"import in a fresh process; {load_average()}")
    print(f"  ringchain.numerics.contact.bem: {import_seconds('ringchain.numerics.contact.bem'):.2f} s")
    if modules is not None:
        print(f"  ContactMechanics, SurfaceTopography: {import_seconds('ContactMechanics, SurfaceTopography'):.2f} s")


if __name__ == "__main__":
    main()
