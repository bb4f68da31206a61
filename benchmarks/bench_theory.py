"""Speed of the theory's numeric functions against hand-written NumPy, on 10^5 points.

Each case times a package function and a reference on the same arrays and prints both
times and their ratio:

- ``hertz_stiffness`` at 90 degrees (R an array, r, E, nu numbers) against the circular
  closed form of the paper's Eq. (1), typed here as 4/3 E/(2(1 - nu^2)) sqrt(r(R - r)/(R - 2r))
  (target: within 1.5x);
- ``hertz_stiffness`` at 60 degrees, and at 10^5 angles between 60 and 89 degrees, against
  the package's own 90-degree call on the same rings (target: within 10x); the elliptical
  contact has no closed form to write by hand;
- ``solitary_wave_speed`` (F_m an array) against Eq. (8) typed here as
  a sqrt(2/(n+1)) sqrt(K^(1/n)/m) F_m^((n-1)/(2n)) (target: within 1.5x);
- ``solitary_wave_speed_prestressed`` against the compact wave's speed, for information.

The references live only here and in the tests; the package derives its formulas.  Every
time is the best of ``--repeat`` runs (default 200), the package and the reference timed
alternately so that both see the same load; the machine's load average is printed, and
ratios taken on a busy machine are noisy.  The warm-up call of each function (which may
derive it, or load it from the disk cache) is not timed.  The largest relative difference
between each pair of results is printed as a check that both compute the same thing.

Run: ``python benchmarks/bench_theory.py [--points 100000] [--repeat 200]``.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from ringchain.theory import (
    hertz_stiffness,
    minimum_contact_angle,
    solitary_wave_speed,
    solitary_wave_speed_prestressed,
)

E, NU, TUBE = 193e9, 0.29, 2.5e-3  # Pa, -, m: the paper's steel rings
K, N, SPACING, MASS = 2.284e3 * 1000**1.11, 1.11, 0.04, 0.37 * 0.0265  # Table I, R/r = 9, in SI


def hertz_circular_by_hand(R, r, E, nu):
    return 4.0 / 3.0 * E / (2.0 * (1.0 - nu**2)) * np.sqrt(r * (R - r) / (R - 2.0 * r))


def speed_by_hand(F_m, K, n, a, m):
    return a * np.sqrt(2.0 / (n + 1.0)) * np.sqrt(K ** (1.0 / n) / m) * F_m ** ((n - 1.0) / (2.0 * n))


def best_pair(repeat, first, second):
    """Best times (s) of two callables timed alternately, and their results."""
    out = [first(), second()]  # warm-up (derivation or cache load), not timed
    best = [np.inf, np.inf]
    for _ in range(repeat):
        for k, func in enumerate((first, second)):
            start = time.perf_counter()
            out[k] = func()
            best[k] = min(best[k], time.perf_counter() - start)
    return best, out


def report(name, target, times, results):
    ours, reference = times
    difference = np.max(np.abs(np.asarray(results[0]) / np.asarray(results[1]) - 1))
    ratio = ours / reference
    print(
        f"{name:<58s} {ours * 1e3:8.3f} ms  vs {reference * 1e3:8.3f} ms  ratio {ratio:6.2f}"
        f"  (target {target})  max rel. diff {difference:.1e}"
    )
    return ratio


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=100_000, help="array length (default 10^5)")
    parser.add_argument("--repeat", type=int, default=200, help="best of this many timings (default 200)")
    args = parser.parse_args()
    rng = np.random.default_rng(2024)
    size, repeat = args.points, args.repeat
    print(f"{size} points, best of {repeat}; load average {os.getloadavg()[0]:.2f} (ratios are noisy under load)")

    R = rng.uniform(8.0, 50.0, size) * TUBE  # m: aspect ratios 8-50, oblique contact down to 60 deg
    circular = lambda: hertz_stiffness(R, TUBE, E, NU)  # noqa: E731
    times, results = best_pair(repeat, circular, lambda: hertz_circular_by_hand(R, TUBE, E, NU))
    report("hertz_stiffness, 90 deg / closed form by hand", "<= 1.5", times, results)
    circular_time = times[0]

    oblique = np.radians(60.0)
    angles = rng.uniform(np.radians(60.0), np.radians(89.0), size)
    assert np.all(angles > minimum_contact_angle(R, TUBE))
    for label, angle in (("60 deg", oblique), ("60-89 deg (array)", angles)):
        times, results = best_pair(repeat, lambda a=angle: hertz_stiffness(R, TUBE, E, NU, a), circular)
        ratio = times[0] / circular_time
        print(
            f"{'hertz_stiffness, ' + label + ' / package at 90 deg':<58s} {times[0] * 1e3:8.3f} ms  vs "
            f"{circular_time * 1e3:8.3f} ms  ratio {ratio:6.2f}  (target <= 10)"
        )

    F_m = rng.uniform(1.0, 100.0, size)  # N: the paper's range of peak forces
    times, results = best_pair(
        repeat,
        lambda: solitary_wave_speed(F_m, K=K, n=N, m=MASS, a=SPACING),
        lambda: speed_by_hand(F_m, K, N, SPACING, MASS),
    )
    report("solitary_wave_speed / Eq. (8) by hand", "<= 1.5", times, results)

    F_0 = F_m * rng.uniform(0.0, 1.0, size)
    times, _ = best_pair(
        repeat,
        lambda: solitary_wave_speed_prestressed(F_m, F_0=F_0, K=K, n=N, m=MASS, a=SPACING),
        lambda: solitary_wave_speed(F_m, K=K, n=N, m=MASS, a=SPACING),
    )
    print(
        f"{'solitary_wave_speed_prestressed / solitary_wave_speed':<58s} {times[0] * 1e3:8.3f} ms  vs "
        f"{times[1] * 1e3:8.3f} ms  ratio {times[0] / times[1]:6.2f}  (for information)"
    )


if __name__ == "__main__":
    main()
