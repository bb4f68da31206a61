"""``ringchain fit``: the command line of :mod:`ringchain.numerics.jobs.fit`.

- ``ringchain fit static FILE`` -- F = K delta^n and the series law (Eqs. 3-4) fitted to a
  quasi-static test (``displacement_m``, ``force_N``), with AIC and BIC to tell them apart;
- ``ringchain fit speed FILE`` -- m_eff/m0 (and n) through Eq. (8) from (peak force, speed)
  pairs (``peak_force_N``, ``speed_m_s``); of a ``ringchain sweep`` file, with the lattice's own
  speeds between the file's sensors as the model (:func:`~ringchain.numerics.fit_speed_lattice`: Eq. (8)
  reads m_eff/m0 high where the pulse is still forming; ``--eq8`` asks for the paper's route);
- ``ringchain fit traces FILE [FILE ...]`` -- a chain fitted to sensor traces (the CSV of
  ``ringchain simulate --out``), files fitted jointly.

The chain is given as ``ringchain simulate`` takes it (geometry, material, model,
``--m-eff-ratio``, or ``--chain FILE`` for traces), or by ``--K`` (SI) and ``--n``; a sweep file
given to ``fit speed`` names its own rings, row by row.  ``--json`` prints values, standard
errors and correlations as JSON on stdout; ``--plot`` draws data, fit and residuals (its path
checked before the fit, as every output).  A fit that does not converge prints one line and
exits with code 1.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from ..engine._files import save_figure

__all__ = ["add_parser", "run"]

#: What ``ringchain --help`` says of ``fit``.
HELP = "fit parameters to measurements (static test, speeds, sensor traces)"

#: Free parameters of ``ringchain fit traces`` by default.
DEFAULT_FREE = "m,gamma,t0"


def _free_list(text: str) -> tuple:
    import argparse

    from ..jobs.fit_dynamic import CHAIN_PARAMETERS

    names = tuple(name.strip() for name in text.split(",") if name.strip())
    allowed = (*CHAIN_PARAMETERS, "t0", "v0", "h0")
    unknown = [name for name in names if name not in allowed]
    if not names or unknown:
        raise argparse.ArgumentTypeError(f"expected a comma list of {','.join(allowed)}, got {text!r}")
    return names


def add_parser(sub, *, geometry) -> None:
    """Add ``fit`` and its three subcommands to the subparsers ``sub`` of ``ringchain``.

    ``geometry(parser)`` adds the ring options of ``ringchain simulate`` (--R, --r, --angle,
    --material, --m-eff-ratio), checked as they are there.
    """
    from ..layouts.chain import MODELS
    from . import _options as opt

    fit = sub.add_parser("fit", help=HELP, allow_abbrev=False,
                         description="Fit parameters to measurements: a quasi-static test, "
                         "(peak force, speed) pairs, or sensor traces (SI units).")  # fmt: skip
    kinds = fit.add_subparsers(dest="fit_command", required=True, metavar="{static,speed,traces}")

    def common(p):
        p.add_argument("--json", action="store_true", help="print values, stderr and correlations as JSON")
        p.add_argument("--plot", type=opt.plot_file, metavar="FILE",
                       help="plot data, fit and residuals (.png, .pdf, .svg...: the extension sets the "
                            "format)")  # fmt: skip
        p.add_argument("--max-evaluations", type=opt.integer("max evaluations", 1), default=None, metavar="N",
                       help="most evaluations of the model by the least squares (default: lmfit's; traces "
                            "60)")  # fmt: skip

    p = kinds.add_parser("static", help="K and n (power law, Eq. 4) or K_c and K_b (series, Eq. 3)",
                         allow_abbrev=False)  # fmt: skip
    p.add_argument("file", metavar="FILE", help="CSV with displacement_m and force_N")
    p.add_argument("--model", choices=("power-law", "series", "both"), default="both",
                   help="law to fit (default both, compared by AIC)")  # fmt: skip
    p.add_argument("--offset", action="store_true", help="also fit a displacement offset (uncertain zero)")
    common(p)

    def chain_by_law(p):
        geometry(p)
        p.add_argument("--K", type=float, metavar="N/M^N", help="power-law stiffness, SI (default: the ring's, Eq. 4)")
        p.add_argument("--n", type=float, help="power-law exponent (with --K)")

    p = kinds.add_parser("speed", help="m_eff/m0 through Eq. (8) from (peak force, speed) pairs", allow_abbrev=False)
    p.add_argument("file", metavar="FILE", help="CSV with peak_force_N and speed_m_s (or a ringchain sweep CSV)")
    chain_by_law(p)
    p.add_argument("--free-n", action="store_true", help="fit the exponent n too (Eq. (8) route)")
    p.add_argument("--eq8", action="store_true",
                   help="fit Eq. (8) even to a sweep's file (the paper's route: biased where the pulse is still "
                        "forming; by default a sweep's pairs are fitted with the lattice's own speeds)")  # fmt: skip
    common(p)

    p = kinds.add_parser("traces", help="a chain fitted to sensor traces (ringchain simulate --out files)",
                         allow_abbrev=False)  # fmt: skip
    p.add_argument("files", nargs="+", metavar="FILE", help="CSV files of sensor traces, fitted jointly")
    chain_by_law(p)
    p.add_argument("--rings", type=opt.Checked(int, opt.ring_count), default=20, action=opt.Given,
                   help="rings in the chain (default 20)")  # fmt: skip
    p.add_argument("--chain", type=opt.chain_file, metavar="FILE",
                   help="TOML chain description, as ringchain simulate --chain takes it; replaces --R, --r, --angle, "
                        "--material, --rings")  # fmt: skip
    p.add_argument("--model", choices=MODELS, default="dual-spring", help="lattice model (default dual-spring)")
    p.add_argument("--gamma", type=float, default=0.0, metavar="NS/M",
                   help="contact dashpot (start or fixed value), N s/m (default 0)")  # fmt: skip
    p.add_argument("--gamma-b", type=float, default=0.0, metavar="NS/M",
                   help="bending dashpot of the dual-spring model, N s/m (default 0)")  # fmt: skip
    impact = p.add_mutually_exclusive_group(required=True)
    impact.add_argument("--drop-height", type=float, nargs="+", metavar="M", help="drop height of each file, m")
    impact.add_argument("--impact-velocity", type=float, nargs="+", metavar="M/S",
                        help="impact speed of each file, m/s")  # fmt: skip
    p.add_argument("--free", type=_free_list, default=DEFAULT_FREE, metavar="LIST",
                   help=f"free parameters, a comma list (default {DEFAULT_FREE}; also K, n, K_b, gamma_b, v0, "
                        "h0)")  # fmt: skip
    p.add_argument("--no-offsets", action="store_true", help="do not fit a DC offset per channel")
    from ._options import striker_option

    striker_option(p)  # as ringchain simulate takes it
    common(p)
    fit.set_defaults(func=run)


def run(args) -> int:
    """Run ``ringchain fit <kind>``; returns the exit code (1 if a fit does not converge)."""
    from ..jobs.fit import FitError
    from . import _options as opt

    files = args.files if args.fit_command == "traces" else [args.file]
    opt.check_outputs([*files, getattr(getattr(args, "chain", None), "path", None)], [("--plot", args.plot)])
    try:
        return {"static": _static, "speed": _speed, "traces": _traces}[args.fit_command](args)
    except FitError as exc:
        message = opt.one_line(exc).replace("allow more evaluations", "allow more evaluations (--max-evaluations)")
        print(f"ringchain fit {args.fit_command}: error: {message}", file=sys.stderr)
        return 1


def _print(args, results) -> None:
    """--json: the results' dicts (one, or keyed by name); else their reports."""
    if args.json:
        dicts = {k: r.to_dict() for k, r in results.items()}
        print(json.dumps(dicts if len(dicts) > 1 else next(iter(dicts.values())), indent=2))
    else:
        print("\n\n".join(r.report() for r in results.values()))


def _static(args) -> int:
    import numpy as np

    from ..engine.traces import read_static
    from ..jobs.fit import fit_static

    delta, force = read_static(args.file)
    models = ("power-law", "series") if args.model == "both" else (args.model,)
    results = {model: fit_static(delta, force, model, offset=args.offset, max_nfev=args.max_evaluations)
               for model in models}  # fmt: skip
    _print(args, results)
    if len(results) == 2 and not args.json:
        aic = {model: r.aic for model, r in results.items()}
        best = min(aic, key=aic.get)
        other = max(aic, key=aic.get)
        law = {"power-law": "power law (Eq. 4)", "series": "series law (Eq. 3)"}
        print(f"\nthe data support the {law[best]}: its AIC is lower by {aic[other] - aic[best]:.3g} than that of the "
              f"{law[other]}")  # fmt: skip
    if args.plot:
        from ..engine.plots import new_figure

        fig = new_figure(figsize=(6, 5))
        ax, ax_r = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": (3, 1)})
        order = np.argsort(delta)
        ax.plot(delta * 1e6, force, ".", color="0.5", label="data")
        for model, r in results.items():
            model_force = force + r.residual
            ax.plot(delta[order] * 1e6, model_force[order], label=f"{model} (AIC {r.aic:.4g})")
            ax_r.plot(delta[order] * 1e6, r.residual[order], ".", ms=3, label=model)
        ax.set(ylabel="force (N)", title="quasi-static test")
        ax.legend()
        ax_r.set(xlabel="displacement (um)", ylabel="fit - data (N)")
        save_figure(fig, args.plot, dpi=120)
        print(f"plot written to {args.plot}")
    return 0


def _speed(args) -> int:
    from ..engine.traces import read_speed_amplitude
    from ..jobs.fit import fit_speed_rings
    from . import _options as opt

    F_m, V_s, rows = read_speed_amplitude(args.file, geometry=True)
    rings = opt.speed_rings(args, rows)
    start = args.m_eff_ratio if "m_eff_ratio" in opt.given(args) else None  # None: fit_speed_amplitude's own
    if rows is not None and "model" in rows and not (args.eq8 or args.free_n or args.K is not None):
        from ..jobs.fit import fit_speed_lattice

        with opt.computing(f"the chains of {args.file}"):
            points = opt.speed_points(rows, rings)
        result = fit_speed_lattice(F_m, V_s, points, start=start, max_nfev=args.max_evaluations)
    else:
        result = fit_speed_rings(F_m, V_s, rings, K=args.K, n=args.n, free_n=args.free_n, start=start,
                                 max_nfev=args.max_evaluations)  # fmt: skip
    _print(args, {"speed": result})
    if not args.json and "K" in result.fixed:
        source = "given" if args.K is not None else "the ring's series law, Eq. 4"
        where = "" if rows is None else f" ({args.file}'s rings)"
        print(f"K = {result.fixed['K']:.6g} N/m^n ({source}), a = {result.fixed['a']:.6g} m, m0 = "
              f"{result.fixed['m0']:.6g} kg{where}")  # fmt: skip
    if args.plot:
        import numpy as np

        from ..engine.plots import new_figure

        fig = new_figure(figsize=(6, 4))
        ax = fig.add_subplot()
        ax.plot(F_m, V_s, "o", label="data")
        order = np.argsort(F_m)
        label = f"Eq. (8), m_eff/m0 = {result.values['m_eff_ratio']:.4g}"
        ax.plot(F_m[order], (V_s + result.residual)[order], label=label)
        ax.set(xscale="log", xlabel="peak force F_m (N)", ylabel="wave speed V_s (m/s)")
        ax.legend()
        save_figure(fig, args.plot, dpi=120)
        print(f"plot written to {args.plot}")
    return 0


def _traces(args) -> int:
    from ..engine.traces import read_traces
    from ..jobs.fit_dynamic import fit_traces
    from . import _options as opt

    impacts = args.drop_height if args.drop_height is not None else args.impact_velocity
    if len(impacts) != len(args.files):
        kind = "--drop-height" if args.drop_height is not None else "--impact-velocity"
        files = f"{len(args.files)} file{'s' if len(args.files) != 1 else ''}"
        raise ValueError(f"{kind} needs one value per file: {files}, {len(impacts)} values")
    chain, m0 = opt.trace_chain(args)
    data = [read_traces(path) for path in args.files]
    if args.drop_height is not None:
        records = [(t, traces, h) for (t, traces), h in zip(data, impacts, strict=True)]
        speeds = None
    else:
        records = [(t, traces, None) for t, traces in data]
        speeds = impacts
    evaluations = {} if args.max_evaluations is None else {"max_nfev": args.max_evaluations}
    if len(records) == 1:
        ((t, traces, h),) = records
        kwargs = {"drop_height": h} if h is not None else {"impact_velocity": speeds[0]}
        result = fit_traces(t, traces, chain, free=args.free, offsets=not args.no_offsets, **kwargs, **evaluations)
    else:
        result = fit_traces(None, records, chain, free=args.free, impact_velocity=speeds,
                            offsets=not args.no_offsets, **evaluations)  # fmt: skip
    _print(args, {"traces": result})
    if not args.json and "m" in result.names:
        ratio, sd = result.values["m"] / m0, result.stderr["m"] / m0
        from ._options import striker_words

        striker = striker_words(args.striker_mass, m0)
        print(f"m/m0 = {ratio:.6g} +/- {sd:.2g} (m0 = {m0:.6g} kg, the mass of ring 0; {striker})")
    if args.plot:
        _plot_traces(result, args.plot, [Path(p).name for p in args.files])
        print(f"plot written to {args.plot}")
    return 0


def _plot_traces(result, path, labels) -> None:
    from ..engine.plots import new_figure

    records = result.records
    fig = new_figure(figsize=(7, 2.2 + 2.6 * len(records)))
    fig.subplots_adjust(hspace=0.35, left=0.12, top=0.95, bottom=0.07)
    axes = fig.subplots(2 * len(records), 1, gridspec_kw={"height_ratios": (3, 1) * len(records)})
    for i, (record, label) in enumerate(zip(records, labels, strict=True)):
        ax, ax_r = axes[2 * i], axes[2 * i + 1]
        for j, ring in enumerate(record.measured):
            color = f"C{j}"
            t_ms = record.t * 1e3
            ax.plot(t_ms, record.measured[ring], ".", ms=1.5, color=color, alpha=0.5, label=f"ring {ring} measured")
            ax.plot(t_ms, record.fitted[ring], color=color, lw=1.2, label=f"ring {ring} fitted")
            ax_r.plot(t_ms, record.residual[ring], color=color, lw=0.6)
        ax.set(ylabel="force (N)", title=f"{label}: impact at {record.t0 * 1e3:.4g} ms, {record.v0:.4g} m/s")
        ax.legend(fontsize="x-small", ncol=2)
        ax_r.set(xlabel="measured time (ms)", ylabel="fit - data (N)")
    save_figure(fig, path, dpi=120)
