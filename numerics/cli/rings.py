"""``ringchain rings``: rigid rings in 3D -- a struck chain, a draped or struck chain-mail sheet, a PAM block.

``ringchain rings --layout chain --rings 20 --impact-velocity 0.5 --t-end 1e-3 --out run.nc --vtk frames/``
builds the network (:meth:`~ringchain.numerics.Rings.chain`, :meth:`~ringchain.numerics.Rings.mail`,
:meth:`~ringchain.numerics.Rings.pam`; the top ring, row or layer fixed), then either strikes its bottom
(ring 0, the bottom row or the bottom layer moving down at ``--impact-velocity``) and integrates it, or,
with ``--static``, finds its static state under gravity (the drape).  The run goes to a NetCDF file
(``--out``, every input needed to rebuild it) and, with ``--vtk``, to one VTK file of meshed tori per frame
and a ``.pvd`` series for ParaView.  Every input is checked before any work; a bad one exits with code 2
and one line naming the option.
"""

from __future__ import annotations

import argparse

import numpy as np

from . import _options as opt

__all__ = ["add_parser", "run", "LAYOUTS"]

#: The layouts of ``--layout``.
LAYOUTS = ("chain", "mail", "pam")

#: Most rings from the command line: a guard against a typo (each ring costs its contacts at every step).
MAX_RINGS = 20_000


def grid_size(text: str) -> tuple[int, ...]:
    """argparse type of --size: ROWSxCOLS (mail) or NXxNYxNZ (pam), each at least 2."""
    try:
        sizes = tuple(int(p) for p in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected ROWSxCOLS or NXxNYxNZ, e.g. 10x10, got {text!r}") from None
    if len(sizes) not in (2, 3) or min(sizes) < 2:
        raise argparse.ArgumentTypeError(f"expected 2 or 3 sizes, each at least 2, got {text!r}")
    if int(np.prod(sizes)) > MAX_RINGS:
        raise argparse.ArgumentTypeError(f"{text} is {int(np.prod(sizes))} sites; the command line builds at most "
                                         f"{MAX_RINGS}")  # fmt: skip
    return sizes


#: What ``ringchain --help`` says of ``rings``.
HELP = "rigid rings in 3D: a struck chain, a draped sheet, a PAM block; NetCDF, VTK"


def add_parser(sub) -> None:
    """Add ``rings`` to the subparsers ``sub`` of ``ringchain``."""
    from ..engine.integrate import check_samples

    p = sub.add_parser("rings", help=HELP, allow_abbrev=False, description=__doc__.split("\n\n")[0])  # fmt: skip
    p.add_argument("--layout", choices=LAYOUTS, default="chain", help="chain, mail (4-in-1) or pam (default chain)")
    p.add_argument("--rings", type=opt.Checked(int, lambda n: opt.v.count("rings", n, 2)), default=10,
                   help="rings of a chain (default 10)")  # fmt: skip
    p.add_argument(
        "--size",
        type=grid_size,
        default=None,
        metavar="AxB[xC]",
        help="rows x columns of a sheet (default 6x6), sites NXxNYxNZ of a PAM block (default 3x3x3)",
    )
    p.add_argument("--R", type=opt.LENGTH_R, default=22.5e-3, metavar="M", help="major radius, m (default 22.5e-3)")
    p.add_argument("--r", type=opt.LENGTH_r, default=2.5e-3, metavar="M", help="tube radius, m (default 2.5e-3)")
    p.add_argument("--material", type=opt.Checked(str, opt.material), default="stainless",
                   help="material preset (default stainless: AISI 304)")  # fmt: skip
    p.add_argument("--law", choices=("hertz", "power-law"), default="hertz", help="contact law (default hertz)")
    p.add_argument("--friction", type=opt.Checked(float, lambda x: float(opt.v.nonnegative("friction", x))),
                   default=0.0, metavar="MU", help="Coulomb coefficient (default 0)")  # fmt: skip
    load = p.add_mutually_exclusive_group(required=True)
    load.add_argument("--impact-velocity", type=opt.IMPACT_VELOCITY, metavar="M/S",
                      help="speed of the struck bottom rings, downwards, m/s")  # fmt: skip
    load.add_argument("--static", action="store_true", help="the static state under gravity (a drape)")
    p.add_argument("--t-end", type=opt.DURATION, default=1e-3, metavar="S", help="duration, s (default 1e-3)")
    p.add_argument("--samples", type=opt.Checked(int, check_samples), default=51, help="frames (default 51)")
    p.add_argument("--out", type=opt.output_file, required=True, metavar="NC", help="NetCDF file of the run")
    p.add_argument("--vtk", type=opt.output_folder, metavar="DIR", help="folder for VTK frames (.vtu, .pvd)")
    p.set_defaults(func=run)


def _network(args):
    """The network of the options, every value checked against the others first."""
    from ..layouts.rings import Rings
    from ..layouts.rings_layouts import mail_geometry

    size = args.size
    if args.layout == "chain" and size is not None:
        raise ValueError("argument --size: a chain takes --rings, not --size")
    if args.layout == "mail" and size is not None and len(size) != 2:
        raise ValueError(f"argument --size: a sheet takes ROWSxCOLS, got {len(size)} sizes")
    if args.layout == "pam" and size is not None and len(size) != 3:
        raise ValueError(f"argument --size: a PAM block takes NXxNYxNZ, got {len(size)} sizes")
    aspect = opt.aspect_ratio(args.R, args.r)
    opt.check_geometry(aspect, [90.0], chain=True, given="arguments --R and --r")
    if args.impact_velocity is not None:
        opt.check_impact(args.material, impact_velocities=[args.impact_velocity])
    ring = opt.ring_of(args.R, args.r, args.material, 90.0, f"the ring of --R {args.R:g} m and --r {args.r:g} m")
    options = {"law": args.law, "friction": args.friction}
    if args.layout == "chain":
        return Rings.chain(args.rings, ring, **options)
    try:  # the rest pose is checked on construction: a failure is the rings' proportions
        if args.layout == "mail":
            mail_geometry(ring)
            rows, cols = size or (6, 6)
            return Rings.mail(rows, cols, ring, **options)
        nx, ny, nz = size or (3, 3, 3)
        return Rings.pam(nx, ny, nz, ring, **options)
    except ValueError as exc:
        raise ValueError(f"arguments --R and --r: R/r = {aspect:.4g}: {opt.one_line(exc)}") from None


def run(args) -> int:
    """Run ``ringchain rings``: build, strike or settle, write; returns the exit code."""
    from ..engine.integrate import simulate
    from ..layouts.rings_files import rings_dataset, write_rings_netcdf, write_rings_vtk

    network = _network(args)
    attrs = {"layout": args.layout, "law": args.law, "friction": args.friction, "material_name": args.material}
    n = network.n_rings
    if args.static:
        rest = network.equilibrium()
        t = np.zeros(1)
        centres, orientations = rest.centres[None], rest.orientations[None]
        extra = {}
        attrs["load"] = "static state under gravity"
        sag = network.centres[:, 2].min() - rest.centres[:, 2].min()
        summary = f"static state: lowest ring {sag * 1e3:.4g} mm below its rest pose"
    else:
        bottom = np.flatnonzero(np.isclose(network.centres[:, 2], network.centres[:, 2].min()))
        velocity = np.zeros((n, 3))
        velocity[bottom, 2] = -args.impact_velocity
        result = simulate(network, args.t_end, velocity=velocity, n_samples=args.samples)
        t, centres, orientations = result.t, result.centres, result.orientations
        extra = {"velocities": result.velocities, "angular_velocities": result.angular_velocities,
                 "link_force": result.link_force}  # fmt: skip
        attrs.update({"load": "impact", "impact_velocity_m_s": args.impact_velocity, "t_end_s": args.t_end})
        summary = f"{t.size} frames over {args.t_end * 1e3:g} ms; largest link force {np.max(result.link_force):.4g} N"
    dataset = rings_dataset(t, centres, orientations, list(network.rings), network.links,
                            fixed=np.flatnonzero(network.fixed), attrs=attrs, **extra)  # fmt: skip
    write_rings_netcdf(args.out, dataset)
    print(f"{args.layout}: {n} rings, {len(network.links)} links, {int(network.fixed.sum())} fixed")
    print(summary)
    print(f"run written to {args.out}")
    if args.vtk:
        pvd = write_rings_vtk(args.vtk, t, centres, orientations, list(network.rings))
        print(f"{t.size} VTK frames written to {args.vtk} ({pvd.name} for ParaView)")
    return 0
