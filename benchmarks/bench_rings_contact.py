"""The contact search of two tori: a cold scan and a warm-started call per pair, in microseconds.

Pairs of linked rings (R/r = 9, the paper's proportions) in random poses near contact, and as many
unlinked pairs resting across one another, searched in one compiled call
(:func:`ringchain.numerics.engine.rings_kernels.pairs_contacts`): first cold (the scan of ``--scan`` samples and a
safeguarded Newton refinement of each minimum), then warm-started after every ring has turned by
``--turn`` rad and moved by ``--move`` of R (a time step of a simulation), from the minima of the cold
call.  Prints the time per pair of each, the Newton iterations per pair, and how often the warm start
fell back on the cold search.

Then the angular offset Delta of the two contacts of two linked rings below theta_min from their
crossing, against theta, their gap at the spacing 2(R - r) and their depth below the maximum between them
(at the crossing): the cold search separates the two minima once Delta exceeds about one sample spacing
2 pi/n_scan, and closer twins from the second, finer look that an inflection next to a minimum triggers
(the choice of the default n_scan = 64, :mod:`ringchain.numerics.contact.tori`).

Run: ``python benchmarks/bench_rings_contact.py [--pairs 2000] [--scan 64] [--turn 1e-3] [--move 1e-4]``.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from bench_batch import best_of  # the benchmarks' one timer (run from benchmarks/, as each script is)
from ringchain.numerics.contact.tori import torus_contacts
from ringchain.numerics.engine import rings_kernels as rk
from ringchain.theory import Ring, minimum_contact_angle

R, r = 22.5e-3, 2.5e-3


def multiply(a, b):
    """Quaternion products a b, (n, 4) each."""
    w1, v1, w2, v2 = a[:, :1], a[:, 1:], b[:, :1], b[:, 1:]
    return np.hstack([w1 * w2 - np.sum(v1 * v2, axis=1, keepdims=True), w1 * v2 + w2 * v1 + np.cross(v1, v2)])


def about(axis, angle):
    """Quaternions of the rotations by ``angle`` (n,) about the unit ``axis`` (n, 3)."""
    return np.hstack([np.cos(angle / 2)[:, None], np.sin(angle / 2)[:, None] * axis])


def unit(v):
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def linked_and_resting(rng, n):
    """Centres (2m, 3) and orientations (2m, 4) of n linked pairs and n resting pairs (rings 2k, 2k + 1)."""
    theta_min = float(minimum_contact_angle(R, r))
    q1 = unit(rng.normal(size=(n, 4)))
    w, v = q1[:, :1], q1[:, 1:]
    ex = np.tile([1.0, 0, 0], (n, 1))
    t = 2 * np.cross(v, ex)
    x1 = ex + w * t + np.cross(v, t)  # body x of ring 1 in space: the line of centres
    theta = rng.uniform(theta_min + np.radians(5), np.pi / 2, n)
    q2 = multiply(about(x1, theta), q1)  # ring 1 turned about the line of centres
    q2 = multiply(about(unit(rng.normal(size=(n, 3))), rng.uniform(0, 0.2, n)), q2)  # and tilted a little
    c2 = x1 * (2 * (R - r) * rng.uniform(0.995, 1.002, n))[:, None]
    centres = np.zeros((4 * n, 3))
    quats = np.zeros((4 * n, 4))
    centres[1 : 2 * n : 2], quats[0 : 2 * n : 2], quats[1 : 2 * n : 2] = c2, q1, q2
    # resting: ring 2 lying across ring 1 (both nearly flat), its circle crossing ring 1's twice
    shift = rng.uniform(0.5 * R, 1.5 * R, n)
    bearing = rng.uniform(0, 2 * np.pi, n)
    centres[2 * n + 1 :: 2] = np.column_stack([shift * np.cos(bearing), shift * np.sin(bearing), np.full(n, 1.999 * r)])
    quats[2 * n :: 2] = [1.0, 0, 0, 0]
    quats[2 * n + 1 :: 2] = about(unit(rng.normal(size=(n, 3))), rng.uniform(0, 0.02, n))
    return centres, quats


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=2000, help="pairs of each kind (default 2000)")
    parser.add_argument("--scan", type=int, default=rk.N_SCAN, help=f"samples of the cold search (default {rk.N_SCAN})")
    parser.add_argument("--turn", type=float, default=1e-3, help="rotation of each ring per step, rad")
    parser.add_argument("--move", type=float, default=1e-4, help="displacement of each ring per step, in R")
    parser.add_argument("--repeat", type=int, default=5, help="best of this many timings (default 5)")
    args = parser.parse_args()
    rng = np.random.default_rng(29)
    n = args.pairs
    centres, quats = linked_and_resting(rng, n)
    m = centres.shape[0] // 2
    pairs = np.arange(2 * m).reshape(m, 2)
    radii, tubes = np.full(2 * m, R), np.full(2 * m, r)
    out = np.empty((m, rk.MAX_CONTACTS, rk.FIELDS))
    counts, state, stats = np.zeros(m, np.int64), np.zeros((m, rk.MAX_CONTACTS)), np.zeros(3, np.int64)

    def cold():
        rk.pairs_contacts(centres, quats, radii, tubes, pairs, args.scan, rk.COLD, 6, state, counts, out, stats)
        return stats.copy()

    cold()  # compile
    t_cold, cold_stats = best_of(args.repeat, cold)
    cold_counts, cold_state = counts.copy(), state.copy()
    # one step of motion: a small rotation about a random axis and a small displacement
    moved = multiply(about(unit(rng.normal(size=(2 * m, 3))), np.full(2 * m, args.turn)), quats)
    shifted = centres + args.move * R * rng.normal(size=centres.shape)

    def warm():
        counts[:], state[:] = cold_counts, cold_state
        rk.pairs_contacts(shifted, moved, radii, tubes, pairs, args.scan, rk.WARM, 6, state, counts, out, stats)
        return stats.copy()

    t_warm, warm_stats = best_of(args.repeat, warm)

    def follow():  # one Newton step from the cold call's angles, no check: what a Runge-Kutta stage needs
        counts[:], state[:] = cold_counts, cold_state
        rk.pairs_contacts(shifted, moved, radii, tubes, pairs, args.scan, rk.FOLLOW, 1, state, counts, out, stats)
        return stats.copy()

    t_follow, follow_stats = best_of(args.repeat, follow)
    single = np.empty((rk.MAX_CONTACTS, rk.FIELDS))
    s0, n0 = cold_state[0].copy(), int(cold_counts[0])

    def python_calls():  # one pair followed from Python, m times: the cost of a call from Python
        for _ in range(m):
            rk.pair_contacts_follow(shifted[0], moved[0], R, r, shifted[1], moved[1], R, r, s0, n0, 1, single)

    python_calls()
    t_python, _ = best_of(args.repeat, python_calls)

    def cpu(func):  # processor time of one call: on a loaded machine the wall time counts other processes too
        start = time.process_time()
        func()
        return time.process_time() - start

    c_cold, c_warm, c_follow = cpu(cold), cpu(warm), cpu(follow)
    print(f"{m} pairs ({n} linked, {n} resting); n_scan {args.scan}; best of {args.repeat}; "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")  # fmt: skip
    print(f"contacts (minima) per pair: {cold_counts.mean():.2f}")
    print(f"cold: {t_cold / m * 1e6:8.2f} us per pair, {cold_stats[0] / m:.2f} Newton iterations per pair")
    print(f"      (processor time per pair: cold {c_cold / m * 1e6:.2f} us, warm {c_warm / m * 1e6:.2f} us, "
          f"follow {c_follow / m * 1e6:.2f} us)")  # fmt: skip
    print(f"warm: {t_warm / m * 1e6:8.2f} us per pair, {warm_stats[0] / m:.2f} Newton iterations per pair, "
          f"fell back on the cold search for {warm_stats[2]} of {m} pairs; "
          f"step: turn {args.turn} rad, move {args.move} R")  # fmt: skip
    print(f"follow: {t_follow / m * 1e6:8.2f} us per pair (one Newton step per minimum, no check; "
          f"{follow_stats[2]} fell back on the cold search)")  # fmt: skip
    print(f"one pair_contacts_follow called from Python: {t_python / m * 1e6:.2f} us (the call's own cost)")

    # the two contacts below theta_min: their offset on circle 1 against the angle
    ring = Ring(R, r)
    theta_min = float(minimum_contact_angle(R, r))
    print(f"\nR/r = {R / r:g}: theta_min = {np.degrees(theta_min):.3f} deg; sample spacing "
          f"{360 / args.scan:.3f} deg (n_scan {args.scan})")  # fmt: skip
    print(f"{'theta_min - theta (deg)':>24} {'Delta (deg)':>12} {'contacts found':>15} {'gap (um)':>9} "
          f"{'depth (um)':>11}")  # fmt: skip
    q1 = np.array([np.cos(-np.pi / 4), np.sin(-np.pi / 4), 0, 0])  # ring 1 in the xz plane
    for below in (0.0001, 0.001, 0.01, 0.1, 0.3, 0.5, 1.0, 1.5, 2.0, 5.0, 10.0):
        theta = theta_min - np.radians(below)
        turn = np.array([np.cos(theta / 2), 0, 0, np.sin(theta / 2)])  # about the chain axis z
        q2 = np.array([turn[0] * q1[0] - turn[3] * q1[3], turn[0] * q1[1] - turn[3] * q1[2],
                       turn[0] * q1[2] + turn[3] * q1[1], turn[3] * q1[0] + turn[0] * q1[3]])  # fmt: skip
        dense = torus_contacts([0, 0, 0], q1, ring, [0, 0, 2 * (R - r)], q2, ring, margin=np.inf, n_scan=4096)
        found = torus_contacts([0, 0, 0], q1, ring, [0, 0, 2 * (R - r)], q2, ring, margin=np.inf, n_scan=args.scan)
        offset = np.degrees(np.abs(dense.s_1 - 1.5 * np.pi)).max()
        between = np.empty((1, rk.FIELDS))  # the crossing itself, s_1 = 3 pi/2: the maximum between the two
        rk.pair_contacts_follow(np.zeros(3), q1, R, r, np.array([0, 0, 2 * (R - r)]), q2, R, r,
                                np.array([1.5 * np.pi]), 1, 0, between)  # fmt: skip
        depth = between[0, 0] - dense.gap.min()
        print(f"{below:24.4f} {offset:12.3f} {len(found):15d} {dense.gap.min() * 1e6:9.3g} {depth * 1e6:11.3g}")


if __name__ == "__main__":
    main()
