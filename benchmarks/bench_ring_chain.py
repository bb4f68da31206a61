"""The ring-resolved chain: speed and convergence of the reduction, and the predicted effective mass.

Four parts, each printing its numbers:

1. ``reduction`` -- the paper's 20-ring chain (R/r = 9, hanging, 5 cm drop, 3 ms) with each ring
   reduced to 0..16 fixed-interface modes (Craig-Bampton) and as the full finite-element ring
   (64 elements, its symmetric subspace): wall time (best of ``--repeat``), integrator steps,
   and against the full model the arrival times and peaks at the sensors in rings 6 and 12
   (low-passed at 10 kHz, as the effective-mass fit reads them) and the largest error of the
   low-passed sensor traces over the run, relative to their peak.  The last line is the
   speed ratio full/default.
2. ``elements`` -- the default reduction on rings of 32, 64 and 128 elements.
3. ``prediction`` -- m_eff/m0 of the power-law lattice (K and n: the rings' quasi-static power
   law) and of the dual-spring lattice (the rings' K_c and K_b) fitted to the ring-resolved
   chain for R/r = 9, 6 and 5.5 over the drop heights 1 cm to 50 cm, untuned, each height
   alone and all together, beside the paper's Table I; the power-law fit with Table I's
   measured K and n; and for R/r = 9 the sensitivity to the low-pass cut-off.
4. ``trailing`` -- the strongest lines of the trailing oscillation in ring 6, beside the free
   ring's in-plane modes (orders k) and the modes with its contacts held.

Run: ``python benchmarks/bench_ring_chain.py [--parts reduction elements prediction trailing]``.
Timings on a shared machine are noisy; the ratios within one run are what to compare.
"""

from __future__ import annotations

import argparse

import numpy as np
from bench_paper_recipe import best_time  # this folder is on sys.path when a script runs from it
from ringchain.numerics.jobs.effective_mass import (
    DROP_HEIGHTS,
    arrival_times,
    fit_effective_mass,
    lowpass,
    predict_effective_mass,
    spectral_peaks,
    trailing_spectrum,
)
from ringchain.numerics.layouts.ring_beam import DEFAULT_MODES, RingModel
from ringchain.numerics.layouts.ring_chain import RingChain, simulate_rings
from ringchain.theory import Ring, n_per_mm_to_si, paper_data

T_END = 3e-3  # s
DROP = 0.05  # m
SENSORS = paper_data.SENSOR_RINGS


def run(ring, modes, elements=64, drop=DROP):
    chain = RingChain.from_ring(ring, paper_data.CHAIN_RINGS, modes=modes, elements=elements)
    return simulate_rings(chain, T_END, drop_height=drop, n_samples=3001)


def readings(sim):
    filtered = lowpass(sim.t, np.array([sim.sensor(i) for i in SENSORS]))
    return arrival_times(sim, SENSORS), filtered.max(axis=1), filtered


def reduction(repeat):
    ring = Ring.from_aspect_ratio(9.0)
    print(f"1. reduction: R/r = 9, {paper_data.CHAIN_RINGS} rings, {DROP * 100:g} cm drop, {T_END * 1e3:g} ms")
    print(f"{'modes':>6s} {'coords/ring':>11s} {'time (s)':>9s} {'steps':>7s} {'arrival 6, 12 (ms)':>20s} "
          f"{'peak 6, 12 (N)':>16s} {'trace error':>11s}")  # fmt: skip
    results = {}
    for modes in (0, 2, 4, 6, 8, 12, 16, None):
        seconds, sim = best_time(lambda modes=modes: run(ring, modes), repeat)
        results[modes] = (seconds, sim)
    _, full = results[None]
    t_ref, _, f_ref = readings(full)
    for modes, (seconds, sim) in results.items():
        t, p, f = readings(sim)
        error = np.abs(f - f_ref).max() / f_ref.max()
        print(f"{'full' if modes is None else modes:>6} {sim.chain.ring.n_dof:11d} {seconds:9.2f} "
              f"{sim.stats['nfev']:7d} {t[0] * 1e3:9.4f} {t[1] * 1e3:10.4f} {p[0]:7.1f} {p[1]:8.1f} "
              f"{error:11.2e}")  # fmt: skip
    ratio = results[None][0] / results[DEFAULT_MODES][0]
    print(f"full model / default ({DEFAULT_MODES} modes): {ratio:.1f}x the time; arrival times differ by "
          f"{np.abs(readings(results[DEFAULT_MODES][1])[0] / t_ref - 1).max():.1e} (relative)")  # fmt: skip


def elements(repeat):
    ring = Ring.from_aspect_ratio(9.0)
    print(f"\n2. elements per ring ({DEFAULT_MODES} modes)")
    reference = None
    for n in (128, 64, 32):
        seconds, sim = best_time(lambda n=n: run(ring, DEFAULT_MODES, elements=n), repeat)
        t, p, _ = readings(sim)
        reference = t if reference is None else reference
        print(f"{n:4d} elements: {seconds:6.2f} s, arrival 6, 12 = {t[0] * 1e3:.4f}, {t[1] * 1e3:.4f} ms "
              f"(vs 128: {np.abs(t / reference - 1).max():.1e}), peaks {p[0]:.1f}, {p[1]:.1f} N")  # fmt: skip


def prediction(heights):
    print(f"\n3. predicted m_eff/m0, drop heights {', '.join(f'{h * 100:g}' for h in heights)} cm")
    print(f"{'R/r':>4s} {'lattice':>12s} {'all heights':>14s} {'each height':>40s} {'largest residual':>17s} "
          f"{'paper':>6s}")  # fmt: skip
    for aspect in sorted(paper_data.TABLE_I, reverse=True):
        p = predict_effective_mass(aspect, heights, per_height=True)
        for model, fit in p.fits.items():
            each = " ".join(f"{x:.2f}" for x in p.per_height[model])
            print(f"{aspect:4g} {model:>12s} {fit.ratio:8.3f}+-{fit.standard_error:.3f} {each:>40s} "
                  f"{np.abs(fit.residuals).max():17.3f} {p.paper_ratio:6.2f}")  # fmt: skip
        K_mm, n, _ = paper_data.TABLE_I[aspect]
        ring = Ring.from_aspect_ratio(aspect)
        table = fit_effective_mass(p.runs, ring, K=float(n_per_mm_to_si(K_mm, n=n)), n=n)
        print(f"     power law with Table I's K, n: m_eff/m0 = {table.ratio:.3f}+-{table.standard_error:.3f}, "
              f"largest residual {np.abs(table.residuals).max():.3f}")  # fmt: skip
        if aspect == 9.0:
            for cutoff in (5e3, 20e3, None):
                alt = fit_effective_mass(p.runs, ring, cutoff=cutoff)
                label = "none" if cutoff is None else f"{cutoff / 1e3:g} kHz"
                print(f"     power law, low-pass cut-off {label}: m_eff/m0 = {alt.ratio:.3f}")


def trailing():
    print("\n4. trailing oscillations in ring 6 (from the end of the leading pulse to 3 ms)")
    for aspect in sorted(paper_data.TABLE_I, reverse=True):
        ring = Ring.from_aspect_ratio(aspect)
        model = RingModel.from_ring(ring)
        sim = run(ring, DEFAULT_MODES, drop=0.05)
        y = sim.sensor(6)
        smooth = lowpass(sim.t, y)
        k = np.argmax(smooth)
        end = k + np.argmax(smooth[k:] < 0.1 * smooth[k])
        f, a = trailing_spectrum(sim.t, y, sim.t[end], T_END)
        lines = np.sort(spectral_peaks(f[f > 2e3], a[f > 2e3], count=4))
        free = model.frequencies(count=6)
        print(f"R/r = {aspect:g}: lines at {', '.join(f'{x / 1e3:.1f}' for x in lines)} kHz; free ring "
              + ", ".join(f"k={k_}: {x / 1e3:.1f}" for k_, x in zip(model.mode_orders(count=6), free, strict=True))
              + " kHz; contacts held: "
              + ", ".join(f"{x / 1e3:.1f}" for x in model.reduce(4).mode_frequencies) + " kHz")  # fmt: skip


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--parts", nargs="+", default=["reduction", "elements", "prediction", "trailing"])
    parser.add_argument("--heights", type=float, nargs="+", default=list(DROP_HEIGHTS), help="drop heights, m")
    args = parser.parse_args(argv)
    if "reduction" in args.parts:
        reduction(args.repeat)
    if "elements" in args.parts:
        elements(args.repeat)
    if "prediction" in args.parts:
        prediction(args.heights)
    if "trailing" in args.parts:
        trailing()


if __name__ == "__main__":
    main()
