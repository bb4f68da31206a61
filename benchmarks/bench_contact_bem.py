"""A 15-load numerical contact curve of two tori, at 30 degrees and at the other angles of Table II.

:func:`ringchain.numerics.contact_curve` on the paper's R/r = 9 stainless ring (r = 2.5 mm),
15 forces log-spaced over 1-100 N (the window of Table II's power law).  For each angle the
script prints the wall time of the whole call (pilot solves, the 15 loads on one grid with
one elastic kernel, the resolution check), the grid (pixels and spacing), the resolution
check's force change, the number of patches and the time per load; at 30 degrees it also
times the naive axial frame.  The target is under 30 s for 30 degrees on 2 cores.

Each timing is the best of ``--repeat`` (default 2); the 1-minute load average is printed,
since other work on the machine slows every figure alike.

Run: ``python benchmarks/bench_contact_bem.py [--repeat 2] [--angles 30 90 60 20]``.
"""

from __future__ import annotations

import argparse
import os
import warnings

import numpy as np
from bench_batch import best_of  # this folder is on sys.path when a script runs from it
from ringchain.numerics import HalfSpaceWarning, contact_curve
from ringchain.theory import STAINLESS_STEEL_304, paper_data

R_OVER_R = paper_data.TABLE_II_ASPECT_RATIO
FORCES = np.geomspace(1.0, 100.0, 15)  # N
TARGET_S = 30.0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--angles", type=float, nargs="+", default=[30.0, 90.0, 60.0, 20.0])
    args = parser.parse_args()
    r = paper_data.TUBE_RADIUS
    R, steel = R_OVER_R * r, STAINLESS_STEEL_304
    print(f"contact_curve: R/r = {R_OVER_R:g}, r = {r * 1e3:g} mm, {len(FORCES)} forces over 1-100 N; "
          f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs")  # fmt: skip
    cases = [(angle, "tangent") for angle in args.angles]
    if 30.0 in args.angles:
        cases.insert(1, (30.0, "axial"))
    for angle, frame in cases:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", HalfSpaceWarning)  # the largest contacts reach 0.1-0.3 r

            def run(a=angle, f=frame):
                return contact_curve(R, r, steel.E, steel.nu, np.radians(a), FORCES, frame=f)

            seconds, curve = best_of(args.repeat, run)
        nx, ny, hx, hy = curve.grid
        verdict = f" (target < {TARGET_S:g} s: {'met' if seconds < TARGET_S else 'MISSED'})" if angle == 30.0 else ""
        print(f"  {angle:4g} deg {frame:7s}: {seconds:6.2f} s{verdict}, {seconds / len(FORCES) * 1e3:5.0f} ms per load "
              f"(with pilots and check); grid {nx} x {ny} pixels of {hx * 1e6:.2f} x {hy * 1e6:.2f} um; "
              f"resolution check {curve.resolution_error:.2%}; patches {int(curve.n_patches[0])}")  # fmt: skip


if __name__ == "__main__":
    main()
