"""``ringchain sheet``: one impact on a sheet of interlinked rings (:mod:`ringchain.numerics.layouts.sheet`).

``ringchain sheet --pattern square --size 40x40 --pretension 2 --impact-velocity 0.5 --out run.nc --plot frames/``
builds the sheet (the ring options of ``ringchain simulate``), strikes it (``--struck``: an edge, ``point``
for the middle of the bottom edge, or ROW,COL), integrates it, writes its fields to a NetCDF file
(:meth:`~ringchain.numerics.SheetSimulation.to_netcdf`) and, with ``--plot``, maps of the link forces at
``--frames`` times into a folder.  Every input is checked before any work; a bad one exits with code 2
and one line naming the option.
"""

from __future__ import annotations

import argparse
import math
import re
from pathlib import Path

from . import _options as opt

__all__ = ["add_parser", "run"]

#: Most rings of a sheet from the command line: a guard against a typo (100000 rings take minutes per ms).
MAX_SITES = 250_000


def sheet_size(text: str) -> tuple[int, int]:
    """argparse type of --size: ROWSxCOLS, each at least 2."""
    parts = text.lower().split("x")
    try:
        rows, cols = (int(p) for p in parts)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected ROWSxCOLS, e.g. 40x40, got {text!r}") from None
    if rows < 2 or cols < 2:
        raise argparse.ArgumentTypeError(f"a sheet needs at least 2 rows and 2 columns, got {text!r}")
    if rows * cols > MAX_SITES:
        raise argparse.ArgumentTypeError(f"{text} is {rows * cols} rings; the command line runs at most {MAX_SITES}")
    return rows, cols


#: Extensions of the NetCDF file ``--out`` writes (NetCDF-4, an HDF5 file): another is refused, never changed.
NETCDF_EXTENSIONS = (".nc", ".nc4")


def netcdf_file(text: str) -> str:
    """argparse type of --out: an output file named as NetCDF (``.nc``), checked writable before any work."""
    if Path(text).suffix.lower() not in NETCDF_EXTENSIONS:
        raise argparse.ArgumentTypeError(f"{text}: a sheet's fields are written as NetCDF-4; name the file with "
                                         f"{' or '.join(NETCDF_EXTENSIONS)} (e.g. run.nc)")  # fmt: skip
    return opt.output_file(text)


#: What ``ringchain --help`` says of ``sheet``.
HELP = "an impact on a sheet of interlinked rings; fields to NetCDF"


def struck_option(text: str):
    """argparse type of --struck: an edge, ``point`` or ROW,COL."""
    from ..layouts.sheet import EDGES

    if text in EDGES or text == "point":
        return text
    try:
        row, col = (int(p) for p in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected an edge ({', '.join(EDGES)}), point (the middle of the bottom edge) or ROW,COL, got {text!r}"
        ) from None
    return row, col


def add_parser(sub) -> None:
    """Add ``sheet`` to the subparsers ``sub`` of ``ringchain``."""
    from ..engine.integrate import METHODS, check_samples
    from ..layouts.sheet import PATTERNS

    p = sub.add_parser("sheet", help=HELP, allow_abbrev=False, description=__doc__.split("\n\n")[0])  # fmt: skip
    # ROWSxCOLS and ROW,COL may start with a minus sign: read "-3x4" and "-1,2" as values (refused with a reason),
    # not as unknown options (argparse's "expected one argument").
    p._negative_number_matcher = re.compile(r"^-\d")
    p.add_argument("--pattern", choices=PATTERNS, default="square", help="4-in-1 (square) or 6-in-1 (triangular)")
    p.add_argument("--size", type=sheet_size, default=(20, 20), metavar="ROWSxCOLS", help="rows x columns (20x20)")
    opt.geometry_options(p)
    load = p.add_mutually_exclusive_group()
    load.add_argument("--hanging", action="store_true", help="hang the sheet from its top edge under gravity")
    load.add_argument("--pretension", type=opt.Checked(float, lambda x: float(opt.v.nonnegative("pretension", x,
                      "N"))), nargs="+", metavar="N", help="static tension per link, N: one, or one per family "
                      "(x y; 0 60 120 deg); default 0 (every link just taut)")  # fmt: skip
    p.add_argument(
        "--boundary",
        choices=("clamped", "periodic", "free"),
        default=None,
        help="edges of a flat sheet (clamped, periodic) or sides of a hanging one (free, periodic)",
    )
    p.add_argument("--struck", type=struck_option, default="point", metavar="WHERE",
                   help="bottom, top, left, right (a whole edge), point (default: the middle of the bottom edge) "
                        "or ROW,COL (a site of an edge)")  # fmt: skip
    opt.impact_options(p, required=True, struck="the struck rings")
    p.add_argument("--impact-direction", type=opt.Checked(float, lambda x: float(opt.v.in_range(
                   "impact direction (deg)", x, -360.0, 360.0))), metavar="DEG",
                   help="direction of the struck rings' velocity, degrees from x (default: the outward normal of "
                        "their edge; needed on a periodic sheet)")  # fmt: skip
    p.add_argument("--gamma", type=opt.Checked(float, lambda x: float(opt.v.nonnegative("gamma", x, "N s/m"))),
                   default=0.0, metavar="NS/M", help="contact dashpot, N s/m (default 0)")  # fmt: skip
    p.add_argument("--t-end", type=opt.DURATION, default=1e-3, metavar="S", help="duration, s (default 1e-3)")
    p.add_argument("--samples", type=opt.Checked(int, check_samples), default=201, help="samples (default 201)")
    p.add_argument("--method", choices=METHODS, default=None, help="integrator (default simulate's)")
    p.add_argument("--rtol", type=opt.Checked(float, _rtol), default=None, metavar="X",
                   help="relative tolerance of the adaptive methods (default the method's)")  # fmt: skip
    p.add_argument("--out", type=netcdf_file, required=True, metavar="NC", help="NetCDF file of the fields (.nc)")
    p.add_argument("--plot", type=opt.output_folder, metavar="DIR", help="folder for maps of the link forces")
    p.add_argument("--frames", type=opt.integer("frames", 1), default=6, help="maps with --plot (default 6)")
    p.set_defaults(func=run)


def _rtol(x):
    from ..engine.integrate import TOLERANCE_RANGE

    return float(opt.v.in_range("rtol", x, *TOLERANCE_RANGE))


def _sheet(args):
    """The sheet of the options, every value checked against the others first."""
    from ..layouts.sheet import Sheet

    rows, cols = args.size
    periodic_or = {True: ("free", "periodic"), False: ("clamped", "periodic")}[args.hanging]
    if args.boundary is not None and args.boundary not in periodic_or:
        raise ValueError(f"argument --boundary: a {'hanging' if args.hanging else 'flat'} sheet takes "
                         f"{' or '.join(periodic_or)}, got {args.boundary}")  # fmt: skip
    families = 2 if args.pattern == "square" else 3
    if args.pretension is not None and len(args.pretension) not in (1, families):
        raise ValueError(f"argument --pretension: one tension or {families} (one per link family of the "
                         f"{args.pattern} sheet), got {len(args.pretension)}")  # fmt: skip
    if args.drop_height is not None and not args.hanging:
        raise ValueError("argument --drop-height: a drop needs a hanging sheet (--hanging); give --impact-velocity")
    aspect = opt.aspect_ratio(args.R, args.r)
    opt.check_geometry(aspect, [args.angle], chain=True, given="arguments --R and --r", two_patches=True)
    opt.check_impact(args.material, drop_heights=[args.drop_height] if args.drop_height else None,
                     impact_velocities=[args.impact_velocity] if args.impact_velocity else None)  # fmt: skip
    ring = opt.ring_of(aspect * args.r, args.r, args.material, 90.0, f"the ring of --R {args.R:g} m")
    struck = args.struck
    if struck == "point":
        struck = (0, cols // 2)
    if isinstance(struck, tuple):
        row, col = struck
        if not (0 <= row < rows and 0 <= col < cols):
            raise ValueError(f"argument --struck: site ({row}, {col}) is not in a sheet of {rows}x{cols}")
        if row not in (0, rows - 1) and col not in (0, cols - 1) and args.impact_direction is None:
            raise ValueError(f"argument --struck: site ({row}, {col}) is not on an edge of the {rows}x{cols} sheet "
                             "(it moves away from the sheet, along the edge's outward normal); or give "
                             "--impact-direction")  # fmt: skip
        if row in (0, rows - 1) and col in (0, cols - 1) and args.impact_direction is None:
            raise ValueError(f"argument --struck: site ({row}, {col}) is a corner of the {rows}x{cols} sheet, on two "
                             "edges: give --impact-direction (deg), or strike a site of one edge")  # fmt: skip
        struck = [row * cols + col]
    if args.impact_direction is None and args.boundary == "periodic" and not args.hanging:
        raise ValueError("argument --struck: a periodic flat sheet has no edges (its rows and columns wrap around, "
                         "each linked to the opposite one): give --impact-direction (deg)")  # fmt: skip
    if args.boundary == "periodic" and struck in ("left", "right"):
        raise ValueError(f"argument --struck: the {struck} edge of a periodic sheet wraps around to the opposite one; "
                         "strike the bottom, or ROW,COL with --impact-direction (deg)")  # fmt: skip
    if isinstance(struck, str) and args.impact_direction is not None:
        raise ValueError("argument --impact-direction: a whole edge moves along its outward normal; give --struck "
                         "ROW,COL to strike one site in another direction")  # fmt: skip
    pretension = None if args.pretension is None else (
        args.pretension[0] if len(args.pretension) == 1 else tuple(args.pretension))  # fmt: skip
    build = Sheet.square if args.pattern == "square" else Sheet.triangular
    with opt.computing(f"the {args.pattern} sheet of {rows}x{cols} rings"):
        return build(rows, cols, ring, angle=math.radians(args.angle), m_eff_ratio=args.m_eff_ratio,
                     hanging=args.hanging, pretension=pretension, boundary=args.boundary, gamma=args.gamma,
                     struck=struck, impact_direction=None if args.impact_direction is None else
                     math.radians(args.impact_direction))  # fmt: skip


def run(args) -> int:
    """Run ``ringchain sheet``: build, strike, integrate, write; returns the exit code."""
    from ..engine.integrate import RunTooLargeError, simulate
    from ..layouts.sheet_runs import write_force_frames

    sheet = _sheet(args)
    impact = {"drop_height": args.drop_height} if args.drop_height is not None else {
        "impact_velocity": args.impact_velocity}  # fmt: skip
    options = {"method": args.method} if args.method else {}
    if args.rtol is not None:
        options["rtol"] = args.rtol
    with opt.naming_solver(args):
        try:
            result = simulate(sheet, args.t_end, n_samples=args.samples, **impact, **options)
        except RunTooLargeError as exc:
            raise opt.too_large(exc, "take a smaller --size, fewer --samples or a shorter --t-end", "--size") from None
    result.to_netcdf(args.out)
    forces = result.link_force
    rows, cols = sheet.shape
    print(f"{sheet.pattern} sheet of {rows}x{cols} rings, {sheet.n_links} links; struck sites "
          f"{sheet.struck_sites.tolist()[:8]}{' ...' if sheet.struck_sites.size > 8 else ''}")  # fmt: skip
    print(f"{result.t.size} samples over {args.t_end * 1e3:g} ms ({result.stats.get('method')}); largest link force "
          f"{forces.max():.4g} N")  # fmt: skip
    print(f"fields written to {args.out}")
    if args.plot:
        paths = write_force_frames(result, args.plot, args.frames)
        print(f"{len(paths)} maps of the link forces written to {args.plot}")
    return 0
