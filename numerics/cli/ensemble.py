"""``ringchain ensemble``: the command line of :mod:`ringchain.numerics.jobs.ensemble`.

``ringchain ensemble --rings 40 --drop-height 0.05 --count 1000 --spread R=0.05 r=0.02 --out ens.csv --plot ens.png``
draws ``--count`` chains of rings that differ at random about the ring of ``--R``, ``--r``,
``--angle``, ``--material`` (each ``--spread NAME=VALUE`` a relative standard deviation of R, r,
angle, or for ``--model power-law`` K and m), strikes each as ``ringchain simulate`` does, and
prints, at a few rings, the ordered chain's peak force beside the members' mean, standard error,
standard deviation and 5-95 % range, and the arrival times.  ``--out`` writes one CSV row per member
(its seed and its readings at every ring), ``--summary`` one row per ring, ``--plot`` the peak force
against the ring.  The same ``--seed`` gives the same ensemble; members run on local processes
(``--workers``) or a Dask cluster (``--dask``), with a progress bar on a terminal.  Every input is
checked before any work: a bad one gives one line and exit code 2.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ringchain.theory import _validate as v

from . import _options as opt

__all__ = ["add_parser", "run", "parse_spread", "DEFAULT_COUNT", "SHOWN_RINGS"]

#: Members when ``--count`` is not given.
DEFAULT_COUNT = 100

#: Rings printed in the table: this many, evenly spaced from ring 1 to the last.
SHOWN_RINGS = 6


#: What ``ringchain --help`` says of ``ensemble``.
HELP = "disordered chains struck alike: peak force and arrival at every ring"


def parse_spread(text: str) -> tuple[str, float]:
    """argparse type of one ``--spread`` value: ``NAME=VALUE``, a relative standard deviation >= 0 of NAME."""
    from ..layouts.disorder import SPREAD_NAMES

    name, sep, value = text.partition("=")
    if not sep or name not in SPREAD_NAMES:
        raise argparse.ArgumentTypeError(
            f"expected NAME=VALUE with NAME one of {', '.join(SPREAD_NAMES)} (e.g. R=0.05), got {text!r}"
        )
    return name, opt.Checked(float, lambda x: float(v.nonnegative(f"spread of {name}", x)))(value)


def add_parser(sub) -> None:
    """Add ``ensemble`` to the subparsers ``sub`` of ``ringchain`` (its function: :func:`run`)."""
    from ringchain.theory import paper_data

    from ..engine.integrate import check_samples
    from ..jobs.ensemble import DEFAULT_BATCH_SIZE
    from ..layouts.chain import MODELS

    p = sub.add_parser(
        "ensemble", help=HELP, allow_abbrev=False,
        description="Chains of rings that differ at random about one ring, struck alike and read at every ring. "
                    "Each --spread NAME=VALUE is a relative standard deviation (R, r, angle; K, m for the "
                    "power-law model).",
    )  # fmt: skip
    opt.geometry_options(p)
    opt.impact_options(p, required=True)
    p.add_argument("--rings", type=opt.integer("rings", 2), default=paper_data.CHAIN_RINGS,
                   help=f"rings in each chain (default {paper_data.CHAIN_RINGS})")  # fmt: skip
    p.add_argument("--model", choices=MODELS, default="dual-spring", help="lattice model (default dual-spring)")
    p.add_argument("--count", type=opt.integer("count", 2), default=DEFAULT_COUNT,
                   help=f"members of the ensemble, at least 2 (default {DEFAULT_COUNT})")  # fmt: skip
    p.add_argument("--spread", type=parse_spread, nargs="+", required=True, metavar="NAME=VALUE",
                   help="relative standard deviation of R, r, angle (or K, m with --model power-law), e.g. "
                        "--spread R=0.05 r=0.02")  # fmt: skip
    p.add_argument("--seed", type=opt.integer("seed", 0), default=0,
                   help="seed of the ensemble: the same seed, the same chains (default 0)")  # fmt: skip
    p.add_argument(
        "--t-end",
        type=opt.DURATION,
        default=None,
        metavar="S",
        help="duration of each run, s (default: long enough for the pulse to pass the last ring)",
    )
    p.add_argument("--samples", type=opt.Checked(int, check_samples), default=None,
                   help="samples of each force record (default simulate's 2001)")  # fmt: skip
    opt.executor_options(p, default_batch=DEFAULT_BATCH_SIZE, what="members")
    p.add_argument("--out", type=opt.output_file, metavar="CSV", help="CSV of the members: one row each")
    p.add_argument("--summary", type=opt.output_file, metavar="CSV", help="CSV of the summary: one row per ring")
    p.add_argument("--plot", type=opt.plot_file, metavar="FILE",
                   help="plot the peak force against the ring (.png, .pdf, .svg...)")  # fmt: skip
    p.set_defaults(func=run)


def _checked(args):
    """The nominal ring and the spreads, every input checked against the others before any work."""
    from ..layouts.disorder import check_spread

    paths = [(name, getattr(args, name)) for name in ("out", "summary", "plot") if getattr(args, name)]
    for k, (name, path) in enumerate(paths):
        for other, second in paths[k + 1 :]:
            if Path(path).resolve() == Path(second).resolve():
                raise ValueError(f"arguments --{name} and --{other}: both name {path}; give two files")
    aspect = opt.aspect_ratio(args.R, args.r)
    opt.check_geometry(aspect, [args.angle], chain=True, given="arguments --R and --r")
    impact = {"drop_heights": [args.drop_height]} if args.drop_height is not None else {
        "impact_velocities": [args.impact_velocity]}  # fmt: skip
    opt.check_impact(args.material, **impact)
    ring = opt.ring_of(aspect * args.r, args.r, args.material, args.angle,
                       f"the ring of --R {args.R:g} m and --r {args.r:g} m")  # fmt: skip
    names = [name for name, _ in args.spread]
    repeated = sorted({name for name in names if names.count(name) > 1})
    if repeated:
        raise ValueError(f"argument --spread: {repeated[0]} is given twice")
    try:
        spread = check_spread(dict(args.spread), args.model)
    except ValueError as exc:
        raise ValueError(f"argument --spread: {opt.one_line(exc).removeprefix('spread: ')}") from None
    return ring, spread


def run(args) -> int:
    """Run ``ringchain ensemble``; returns the exit code."""
    import numpy as np

    from ..jobs.ensemble import ensemble

    ring, spread = _checked(args)
    options = {} if args.samples is None else {"n_samples": args.samples}
    with opt.executor_of(args) as executor:
        ens = ensemble(ring, args.rings, args.count, spread=spread, seed=args.seed, model=args.model,
                       m_eff_ratio=args.m_eff_ratio, drop_height=args.drop_height,
                       impact_velocity=args.impact_velocity, t_end=args.t_end, executor=executor,
                       batch_size=args.batch_size, max_workers=args.workers, progress=sys.stderr.isatty(),
                       **options)  # fmt: skip
    print(ens.describe())
    redrawn = int(ens.redrawn.sum())
    print(f"  values drawn again (they would have made a ring impossible; the distributions are truncated there): "
          f"{redrawn}, in {int(np.count_nonzero(ens.redrawn))} of {ens.count} members")  # fmt: skip
    if ens.failures:
        hint = "give a longer --t-end" if args.t_end is not None else "a pulse did not pass within the default duration"
        print(f"  {ens.failures} readings failed (no complete leading pulse; {hint}); they are left out")
    peak, arrival = ens.summary("peak_force"), ens.summary("arrival")
    low, high = peak.quantile_values[0], peak.quantile_values[-1]
    band = f"{100 * peak.quantiles[0]:g}-{100 * peak.quantiles[-1]:g} % (N)"
    rows = [["ring", "ordered (N)", "mean (N)", "+- s.e.", "s.d.", band, "mean/ordered", "arrival (ms)", "+- s.e.",
             "ordered (ms)"]]  # fmt: skip
    shown = sorted({round(x) for x in np.linspace(1, ens.n_rings - 1, min(SHOWN_RINGS, ens.n_rings - 1))})
    for k in shown:
        rows.append([str(k), f"{ens.ordered_peak_force[k]:.4g}", f"{peak.mean[k]:.4g}", f"{peak.sem[k]:.2g}",
                     f"{peak.std[k]:.3g}", f"{low[k]:.4g}-{high[k]:.4g}",
                     f"{peak.mean[k] / ens.ordered_peak_force[k]:.4f}", f"{arrival.mean[k] * 1e3:.4g}",
                     f"{arrival.sem[k] * 1e3:.2g}", f"{ens.ordered_arrival[k] * 1e3:.4g}"])  # fmt: skip
    widths = [max(len(row[j]) for row in rows) for j in range(len(rows[0]))]
    print("\n".join("  " + "  ".join(cell.rjust(width) for cell, width in zip(row, widths, strict=True))
                    for row in rows))  # fmt: skip
    for name, what, write in (("out", "members", lambda path: ens.write_csv(path)),
                              ("summary", "summary", lambda path: ens.write_csv(path, summary=True)),
                              ("plot", "plot", ens.plot)):  # fmt: skip
        path = getattr(args, name)
        if path:
            write(path)
            print(f"{what} written to {path}")
    return 0
