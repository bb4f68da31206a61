"""Command line: ``ringchain <subcommand>``.

- ``ringchain paper`` -- the README's main job: derives the theory, prints the paper's key
  numbers beside the paper's own, runs the 20-ring drop experiment with both lattice
  models and writes the figures to a folder;
- ``ringchain ring --R 22.5e-3 --r 2.5e-3`` -- everything about one ring contact;
- ``ringchain simulate --rings 20 --drop-height 0.05`` -- one run, sensor traces as CSV;
- ``ringchain sweep --R-over-r 6 9 --drop-height 0.01:0.1:10`` -- a grid, one CSV row per point;
- ``ringchain simulate --chain FILE`` / ``ringchain sweep --chain FILE --vary 2.R.last 0.01:0.02:5`` -- a
  chain that changes along its length, described segment by segment in TOML (:mod:`.chain_file`);
- ``ringchain cache info`` / ``ringchain cache clear`` -- the disk cache of generated code.
- ``ringchain fit static|speed|traces FILE`` -- parameters from measurements (:mod:`.fit_cli`);
- ``ringchain ensemble --count 1000 --spread R=0.05`` -- disordered chains, read at every ring (:mod:`.ensemble_cli`);
- ``ringchain sheet --pattern square --size 40x40`` -- an impact on a sheet of rings (:mod:`.sheet_cli`).

Inputs are SI (m, m/s, N) except contact angles, given in degrees.  Every input and every
output path is checked before any work (:mod:`ringchain.numerics.cli._options`); a bad one
gives a one-line error naming the option, in the units it was given, and exit code 2;
success exits 0, a result beyond its model's validity 1, Ctrl-C 130 (one line), a reader that
closed the pipe 141 (quietly).  This module only parses, calls and prints: one function per
subcommand.
"""

from __future__ import annotations

import argparse
import gc
import math
import os
import sys
import warnings
from pathlib import Path

from . import _options as opt
from . import ensemble as ensemble_cli
from . import rings as rings_cli
from . import sheet as sheet_cli

__all__ = ["main", "build_parser"]


# -- ringchain paper -----------------------------------------------------------------------------
def _paper(args) -> int:
    from ..jobs.paper import paper_job

    h = float(args.drop_height)
    if not h > 0:
        raise ValueError(f"the drop height must be positive (in m), got {h:g}")
    tables, figures = paper_job(h, Path(args.out), stiffness=args.stiffness)
    for table in tables:
        print(table)
    print(f"Figures written to {Path(args.out).resolve()}/: {', '.join(p.name for p in figures)}")
    return 0


def _paper_checked(args) -> int:
    """``ringchain paper`` after the checks of its inputs (the experiment's rings are stainless steel)."""
    opt.check_impact("stainless", drop_heights=[args.drop_height])
    return _paper(args)


# -- ringchain ring ------------------------------------------------------------------------------
def _ring(args) -> int:
    from ..contact.angle import contact_report

    opt.check_geometry(args.R / args.r, [args.angle], chain=False, given="arguments --R and --r", two_patches=True)
    F_lo, F_hi = args.window
    if not F_lo < F_hi:
        raise ValueError(f"argument --window: the force window needs F_min < F_max, got {F_lo:g} {F_hi:g} N")
    given = f"the ring of --R {args.R:g} m and --r {args.r:g} m"
    ring = opt.ring_of(args.R, args.r, args.material, 90.0, given, thin=args.thin)
    where = f"{given} at --angle {args.angle:g} deg, --force {args.force:g} N and --window {F_lo:g} {F_hi:g} N"
    with opt.computing(f"the contact of {where}"):
        try:
            report = contact_report(ring, math.radians(args.angle), args.force, window=(F_lo, F_hi),
                                    m_eff_ratio=args.m_eff_ratio)  # fmt: skip
        except RuntimeError as exc:  # the contact solver's own failure, in one line like every other
            raise ValueError(opt.one_line(exc)) from None
    rows = report.rows()
    pad = max(len(k) for k, _ in rows)
    for key, value in rows:
        print(f"{key.ljust(pad)}  {value}")
    if report.warning is None:
        return 0
    print(f"ringchain ring: warning: {report.warning}: keep --window's F_MAX and --force below about "
          f"{report.contact.limit_force:.3g} N", file=sys.stderr)  # fmt: skip
    return 1


# -- ringchain simulate ------------------------------------------------------------------------------
def _simulate(args) -> int:
    from ..jobs.experiment import run_experiment

    if args.plot is not None and Path(args.plot).resolve() == Path(args.out).resolve():
        raise ValueError(f"arguments --out and --plot: both name {args.out}; give two files")
    opt.check_outputs([args.chain and args.chain.path], [("--out", args.out), ("--plot", args.plot)])
    chain, described = opt.simulated_chain(args)
    impact = {"drop_height": args.drop_height} if args.drop_height is not None else {
        "impact_velocity": args.impact_velocity}  # fmt: skip
    solver = {
        name: value for name, value in (("method", args.method), ("n_samples", args.samples)) if value is not None
    }
    with opt.naming_size(args):
        run = run_experiment(chain, **impact, sensors=tuple(args.sensors), t_end=args.t_end, out=args.out,
                             plot=args.plot, gravity=args.gravity, **solver)  # fmt: skip
    try:
        lines = run.summary(described)
    except ValueError as exc:
        hint = "; give a longer --t-end" if args.t_end is not None else ""
        reason = opt.one_line(exc)
        raise ValueError(f"the traces are written, but their leading pulses cannot be read: {reason}{hint}") from None
    print("\n".join(lines))
    print(f"sensor traces written to {args.out}")
    if args.plot:
        print(f"plot written to {args.plot}")
    return 0


# -- ringchain sweep -------------------------------------------------------------------------------
def _sweep(args) -> int:
    from ..jobs.sweep import sweep, write_csv

    opt.check_outputs([args.chain and args.chain.path], [("--out", args.out)])
    points = opt.sweep_points(args)
    options = dict(batch_size=args.batch_size, max_workers=args.workers, progress=sys.stderr.isatty(),
                   t_end=args.t_end, gravity=args.gravity)  # fmt: skip
    if args.samples is not None:
        options["n_samples"] = args.samples
    with opt.executor_of(args) as executor, opt.naming_t_end(args), opt.naming_size(args):
        rows = sweep(points, executor, **options)
    if args.out == "-":
        write_csv(rows, sys.stdout)
    else:
        write_csv(rows, args.out)
        print(f"{len(rows)} rows written to {args.out}")
    return 0


# -- ringchain cache -----------------------------------------------------------------------------------
def _size(nbytes: int) -> str:
    for unit in ("bytes", "kB", "MB"):
        if nbytes < 1000 or unit == "MB":
            return f"{nbytes} {unit}" if unit == "bytes" else f"{nbytes:.1f} {unit}"
        nbytes /= 1000
    raise AssertionError  # pragma: no cover


def _cache_info(args) -> int:
    from ringchain.theory._codegen import cache_info

    info = cache_info()
    if info.path is None:
        print("location  none: the disk cache is disabled (RINGCHAIN_CACHE_DIR is set and empty)")
        print(f"key       {info.key}")
        return 0
    if info.path.exists() and not info.exists:
        raise ValueError(f"the cache folder {info.path} ({info.origin}) is a file, not a folder: each process derives "
                         "the theory again; point RINGCHAIN_CACHE_DIR at a folder")  # fmt: skip
    origin = {"RINGCHAIN_CACHE_DIR": "from RINGCHAIN_CACHE_DIR", "XDG_CACHE_HOME": "from XDG_CACHE_HOME",
              "default": "the default; RINGCHAIN_CACHE_DIR moves it"}[info.origin]  # fmt: skip
    entries = (f"{info.current} for this key, {info.stale} stale (other keys), {info.temporary} temporary files"
               if info.exists else "none (the folder does not exist yet)")  # fmt: skip
    writable = ("yes" if info.exists else "yes (the folder will be created)") if info.writable else (
        "no: each process derives the theory again (about a second)")  # fmt: skip
    print(f"location  {info.path} ({origin})")
    print(f"key       {info.key} (hash of the theory's source and of the SymPy and NumPy versions)")
    print(f"entries   {entries}")
    print(f"size      {_size(info.size)}")
    print(f"writable  {writable}")
    return 0


def _cache_clear(args) -> int:
    from ringchain.theory._codegen import cache_dir, clear_cache

    directory = cache_dir()
    if directory is None:
        print("nothing to clear: the disk cache is disabled (RINGCHAIN_CACHE_DIR is set and empty)")
        return 0
    if directory.exists() and not directory.is_dir():
        raise ValueError(f"the cache folder {directory} is a file, not a folder: nothing to clear (the file is left "
                         "as it is)")  # fmt: skip
    removed, nbytes = clear_cache()
    print(f"removed {removed} {'file' if removed == 1 else 'files'} ({_size(nbytes)}) from {directory}")
    return 0


# -- the parser ----------------------------------------------------------------------------------------
class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors: ``prog: error: message (see prog --help)``, exit code 2."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def _version() -> str:
    """The installed package's version (importlib.metadata), as ``ringchain --version`` prints it."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("ringchain")
    except PackageNotFoundError:  # pragma: no cover - run from a source tree that was never installed
        return "(not installed)"


def build_parser(command: str | None = None) -> argparse.ArgumentParser:
    """The parser of ``ringchain``; given the ``command`` a process runs, the options of the subcommands kept in
    modules of their own (``fit``, ``ensemble``, ``sheet``, ``rings``) are built only if it is one of them (the
    others are listed with their help, as ``ringchain --help`` shows them: building them imports their jobs)."""
    from ..engine.integrate import METHODS
    from ..jobs.paper import PAPER_DROP_HEIGHT, PAPER_FIGURES, STIFFNESS_SOURCES

    parser = _Parser(prog="ringchain", description=__doc__.split("\n\n")[0], allow_abbrev=False)
    parser.add_argument("--version", action="version", version=f"ringchain {_version()}")
    sub = parser.add_subparsers(
        dest="command", required=True, metavar="{paper,ring,simulate,sweep,ensemble,cache,fit,sheet,rings}"
    )

    p = sub.add_parser("paper", help="derive the theory, print the paper's key numbers, write the figures",
                       allow_abbrev=False)  # fmt: skip
    p.add_argument("--out", type=opt.output_folder, default=PAPER_FIGURES, metavar="DIR",
                   help=f"folder for the figures (default ./{PAPER_FIGURES})")  # fmt: skip
    p.add_argument("--drop-height", type=opt.DROP_HEIGHT, default=PAPER_DROP_HEIGHT, metavar="M",
                   help=f"drop height of the 20-ring experiment, m (default {PAPER_DROP_HEIGHT:g})")  # fmt: skip
    p.add_argument("--stiffness", choices=STIFFNESS_SOURCES, default="table",
                   help="stiffness of both lattice models: Table I's power law (default) or the theory")  # fmt: skip
    p.set_defaults(func=_paper_checked)

    p = sub.add_parser("ring", help="everything about one ring contact", allow_abbrev=False)
    opt.geometry_options(p, R_required=True)
    p.add_argument("--force", type=opt.FORCE, default=10.0, metavar="N",
                   help="force for the local exponent and the solitary-wave speed, N (default 10)")  # fmt: skip
    p.add_argument("--window", type=opt.positive("force window", "N"), nargs=2, default=[1.0, 100.0],
                   metavar=("F_MIN", "F_MAX"), help="force window of the power-law fit, N (default 1 100)")  # fmt: skip
    p.add_argument("--thin", action="store_true", help="thin-ring bending stiffness instead of the curved beam")
    p.set_defaults(func=_ring)

    p = sub.add_parser("simulate", help="one drop or impact; sensor traces to CSV", allow_abbrev=False)
    opt.geometry_options(p)
    opt.striker_option(p)
    opt.impact_options(p, required=True)
    opt.chain_options(p)
    p.add_argument("--method", choices=METHODS, default=None,
                   help="integrator of ringchain.numerics.simulate (default its DEFAULT_METHOD)")  # fmt: skip
    p.add_argument("--out", type=opt.output_file, required=True, metavar="CSV", help="CSV of the sensor traces")
    p.add_argument("--plot", type=opt.plot_file, metavar="FILE",
                   help="also plot the sensor traces (.png, .pdf, .svg...: the extension sets the format)")  # fmt: skip
    opt.chain_file_options(p)
    p.set_defaults(func=_simulate)

    p = sub.add_parser("sweep", help="a grid of chains and impacts, one CSV row per point", allow_abbrev=False,
                       description="Values: numbers, or start:stop:count for evenly spaced ones (start > stop "
                                   f"counts down; at most {opt.MAX_GRID_POINTS} points in all).")  # fmt: skip
    opt.geometry_options(p, many=True)
    opt.striker_option(p, many=True)
    opt.impact_options(p, many=True)
    opt.chain_options(p, many=True)
    opt.executor_options(p, default_batch=64)
    p.add_argument("--out", type=opt.output_csv, default="-", metavar="CSV",
                   help="output CSV (default: standard output)")  # fmt: skip
    opt.chain_file_options(p, sweep=True)
    p.set_defaults(func=_sweep)

    p = sub.add_parser("cache", help="the disk cache of the theory's generated code", allow_abbrev=False)
    actions = p.add_subparsers(dest="action", required=True, metavar="{info,clear}")
    actions.add_parser("info", help="location, key, entries, size and whether it is writable",
                       allow_abbrev=False).set_defaults(func=_cache_info)  # fmt: skip
    actions.add_parser("clear", help="remove every entry (the theory is derived again on next use)",
                       allow_abbrev=False).set_defaults(func=_cache_clear)  # fmt: skip
    from . import fit as fit_cli

    built = {"fit": lambda: fit_cli.add_parser(sub, geometry=opt.geometry_options),  # each sets its own func
             "ensemble": lambda: ensemble_cli.add_parser(sub), "sheet": lambda: sheet_cli.add_parser(sub),
             "rings": lambda: rings_cli.add_parser(sub)}  # fmt: skip
    helps = {"fit": fit_cli.HELP, "ensemble": ensemble_cli.HELP, "sheet": sheet_cli.HELP, "rings": rings_cli.HELP}
    known = {*sub.choices, *built}
    for name, build in built.items():
        if command in (None, name) or command not in known:
            build()
        else:
            sub.add_parser(name, help=helps[name], allow_abbrev=False)
    return parser


def _command_of(argv) -> str | None:
    """The subcommand ``argv`` (default ``sys.argv[1:]``) names: its first word that is not an option."""
    return next((word for word in (sys.argv[1:] if argv is None else argv) if not word.startswith("-")), None)


#: Exit codes of a command its reader stopped (128 + SIGPIPE, as a shell reports ``yes | head``) and of one
#: interrupted by Ctrl-C (128 + SIGINT).
BROKEN_PIPE, INTERRUPTED = 141, 130

#: Floating-point trouble in NumPy (the theory's generated code, the solvers) stops the command with a
#: message instead of printing numbers made of inf and nan.
_FLOATING_POINT = r"(overflow|invalid value|divide by zero) encountered"


def main(argv=None) -> int:
    """Run ``ringchain`` with ``argv`` (default ``sys.argv[1:]``); returns the exit code.

    Run as the process's own command (``argv`` None: the ``ringchain`` script, ``python -m``), the cyclic garbage
    collector is paused while the command starts (the imports and the parser make objects that live as long
    as the process, which the collector would walk again and again) and those objects are then set aside
    (:func:`gc.freeze`) before it resumes for the command's own work.
    """
    starting = argv is None and gc.isenabled()
    if starting:
        gc.disable()
    try:
        parser = build_parser(_command_of(argv))
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help (0) or a usage error (2), already printed
        return int(exc.code or 0)
    finally:
        if starting:
            gc.freeze()
            gc.enable()
    command = " ".join(filter(None, (args.command, getattr(args, "action", None), getattr(args, "fit_command", None))))
    try:
        with warnings.catch_warnings():
            warnings.filterwarnings("error", message=_FLOATING_POINT, category=RuntimeWarning)
            return args.func(args)
    except BrokenPipeError:  # the reader of the standard output stopped (| head): end quietly, as cat does
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # the interpreter's last flush must not fail
        return BROKEN_PIPE
    except KeyboardInterrupt:
        print(f"\nringchain {command}: interrupted", file=sys.stderr)
        return INTERRUPTED
    except (ValueError, TypeError, OSError, ArithmeticError, RuntimeWarning) as exc:
        message = opt.one_line(exc)
    except MemoryError:
        message = "out of memory; use fewer --rings, --samples or grid points"
    print(f"ringchain {command}: error: {message}", file=sys.stderr)
    return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
