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
- ``ringchain fit static|speed|traces FILE`` -- parameters from measurements (:mod:`.fit_cli`).

Inputs are SI (m, m/s, N) except contact angles, given in degrees.  Every input and every
output path is checked before any work (:mod:`ringchain.numerics._cli_options`); a bad one
gives a one-line error naming the option, in the units it was given, and exit code 2;
success exits 0.  This module only parses, calls and prints: one function per subcommand.
"""

from __future__ import annotations

import argparse
import math
import sys
import warnings
from pathlib import Path

import numpy as np

from . import _cli_options as opt
from .paper import PAPER_DROP_HEIGHT, PAPER_FIGURES, STIFFNESS_SOURCES
from .paper import new_figure as _figure

__all__ = ["main", "build_parser"]


# -- ringchain paper -----------------------------------------------------------------------------
def _paper(args) -> int:
    from .paper import paper_job

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
    from ringchain.theory import (
        MIN_CHAIN_ASPECT_RATIO,
        crossover_force,
        local_exponent,
        minimum_contact_angle,
        si_to_n_per_mm,
        solitary_wave_speed,
        solitary_wave_width,
    )

    from .contact_bem import HALF_SPACE_LIMIT, NUMERICAL, contact_at_angle

    aspect = args.R / args.r
    opt.check_geometry(aspect, [args.angle], chain=False, given="arguments --R and --r", two_patches=True)
    F_lo, F_hi = args.window
    if not F_lo < F_hi:
        raise ValueError(f"argument --window: the force window needs F_min < F_max, got {F_lo:g} {F_hi:g} N")
    given = f"the ring of --R {args.R:g} m and --r {args.r:g} m"
    F, ratio = args.force, args.m_eff_ratio
    # Mass, spacing and K_b do not depend on the angle; the contact is Hertz's or the numerical one
    # (ringchain.numerics.contact_at_angle, the choice the paper's angle table makes too).
    ring = opt.ring_of(args.R, args.r, args.material, 90.0, given, thin=args.thin)
    mat = ring.material
    where = f"{given} at --angle {args.angle:g} deg, --force {F:g} N and --window {F_lo:g} {F_hi:g} N"
    with opt.computing(f"the contact of {where}"):
        try:
            contact = contact_at_angle(ring.R, ring.r, mat.E, mat.nu, math.radians(args.angle), K_b=ring.K_b,
                                       window=(F_lo, F_hi), forces=[F])  # fmt: skip
        except RuntimeError as exc:  # the contact solver's own failure, in one line like every other
            raise ValueError(opt.one_line(exc)) from None
    K, n, K_c = contact.K, contact.n, contact.K_c
    m = ratio * ring.mass
    lowest = math.degrees(float(minimum_contact_angle(ring.R, ring.r)))
    top = max(F_hi, F)
    chain_note = "yes" if ring.can_form_chain else (
        f"no: R/r < {MIN_CHAIN_ASPECT_RATIO:g}, two rings interlock but a chain cannot form")  # fmt: skip
    with opt.computing(f"{given} at --force {F:g} N"):
        F_star = float(crossover_force(K_c=K_c, K_b=ring.K_b))
        n_star = float(local_exponent(F_star, K_c=K_c, K_b=ring.K_b))
        V_s = float(solitary_wave_speed(F, K=K, n=n, m=m, a=ring.spacing))
        width = float(solitary_wave_width(n=n, a=ring.spacing))
        extension = float(contact.extension(F))
        n_F = float(contact.local_exponent(F))
    if contact.method == NUMERICAL:
        patches = "two patches" if contact.n_patches == 2 else "one patch"
        contact_line = (f"K_c, {patches} (BEM, tilt {math.degrees(contact.curve.tilt):.1f} deg)",
                        f"{K_c:.4e} N/m^1.5 (F = K_c delta^1.5 fitted over {F_lo:g}-{F_hi:g} N; contact up to "
                        f"{contact.extent_over_r:.2f} r at {top:g} N)")  # fmt: skip
    else:
        contact_line = ("K_c, Hertz contact (Eq. 1)",
                        f"{K_c:.4e} N/m^1.5 (ellipse up to {contact.extent_over_r:.3f} r at {top:g} N)")  # fmt: skip
    if contact.handover is None:
        hertz_range = f"none within the half-space limit at {top:g} N"
    else:
        hertz_range = f"within the half-space limit up to {top:g} N above {math.degrees(contact.handover):.2f} deg"
    lines = [
        ("geometry", f"R = {ring.R * 1e3:g} mm, r = {ring.r * 1e3:g} mm, "
                     f"R/r = {opt.distinct(ring.aspect_ratio, MIN_CHAIN_ASPECT_RATIO)}"),
        ("material", f"{mat.name}: E = {mat.E / 1e9:g} GPa, nu = {mat.nu:g}, rho = {mat.rho:g} kg/m^3"),
        ("contact angle", f"{args.angle:g} deg (single Hertz contact above {lowest:.2f} deg; {hertz_range})"),
        ("forms a chain", chain_note),
        ("ring mass m0", f"{ring.mass * 1e3:.4g} g"),
        ("spacing a = 2(R - r)", f"{ring.spacing * 1e3:.4g} mm"),
        contact_line,
        ("K_b, ring bending (Eq. 2)", f"{ring.K_b:.4e} N/m" + (" (thin ring)" if args.thin else "")),
        ("crossover F* = K_b^3/K_c^2", f"{F_star:.4g} N (local exponent there {n_star:.4f})"),
        (f"power law over {F_lo:g}-{F_hi:g} N (Eq. 4)",
         f"K = {float(si_to_n_per_mm(K, n=n)):.5g} N/mm^n = {K:.5g} N/m^n, n = {n:.4f}"),
        (f"at F = {F:g} N (Eq. 3)", f"extension {extension * 1e6:.4g} um, local exponent {n_F:.4f}"),
        (f"solitary wave at F_m = {F:g} N", f"V_s = {V_s:.4g} m/s (Eq. (8), m = {ratio:g} m0 = {m * 1e3:.4g} g), "
         f"width {width * 1e3:.4g} mm = {width / ring.spacing:.3g} a"),
    ]  # fmt: skip
    pad = max(len(k) for k, _ in lines)
    for key, value in lines:
        print(f"{key.ljust(pad)}  {value}")
    if contact.within_half_space:
        return 0
    print(f"ringchain ring: warning: the contact reaches {contact.extent_over_r:.2f} r from its centre at {top:g} N, "
          f"beyond the half-space limit {HALF_SPACE_LIMIT:g} r of both contact models, so K_c, K, n and V_s above "
          f"extrapolate them: keep --window's F_MAX and --force below about {contact.limit_force:.3g} N",
          file=sys.stderr)  # fmt: skip
    return 1


# -- ringchain simulate ------------------------------------------------------------------------------
def _simulate_point(args):
    """The sweep point of ``ringchain simulate``, every input checked against the others."""
    from .sweep import Point

    aspect = opt.aspect_ratio(args.R, args.r)
    opt.check_geometry(aspect, [args.angle], chain=True, given="arguments --R and --r")
    opt.check_sensors(args.sensors, [args.rings])
    if args.drop_height is not None:
        impact = {"drop_height": args.drop_height}
        opt.check_impact(args.material, drop_heights=[args.drop_height])
    else:
        impact = {"impact_velocity": args.impact_velocity}
        opt.check_impact(args.material, impact_velocities=[args.impact_velocity])
    given = f"the ring of --R {args.R:g} m and --r {args.r:g} m"
    opt.ring_of(aspect * args.r, args.r, args.material, args.angle, given)
    return Point(
        R_over_r=aspect, r=args.r, angle=math.radians(args.angle), material=args.material, model=args.model,
        n_rings=args.rings, m_eff_ratio=args.m_eff_ratio, sensors=tuple(args.sensors), **impact,
    )  # fmt: skip


#: The single-ring options that --chain replaces, with their defaults.
_GEOMETRY_DEFAULTS = {"R": 22.5e-3, "r": 2.5e-3, "angle": 90.0, "material": "stainless", "rings": 20}


def _simulate_chain_file(args) -> int:
    """``ringchain simulate --chain FILE``: a chain that changes along its length (:mod:`.chain_file`)."""
    from .models import STANDARD_GRAVITY
    from .solve import _impact_speeds, simulate
    from .sweep import default_t_end

    description = args.chain
    opt.check_chain_file_alone(args, _GEOMETRY_DEFAULTS)
    opt.check_sensors(args.sensors, [description.n_rings])
    impact = {"drop_height": args.drop_height} if args.drop_height is not None else {
        "impact_velocity": args.impact_velocity}  # fmt: skip
    for material in {segment.material for segment in description.segments}:
        opt.check_impact(material, drop_heights=[args.drop_height] if args.drop_height else None,
                         impact_velocities=[args.impact_velocity] if args.impact_velocity else None)  # fmt: skip
    speed = float(_impact_speeds(args.impact_velocity, args.drop_height, STANDARD_GRAVITY)[0][0])
    with opt.computing(f"the chain of {description.source}"):
        chain = description.chain(args.model, args.m_eff_ratio)
        t_end = default_t_end(chain, [speed], args.sensors) if args.t_end is None else args.t_end
    solver = {} if args.method is None else {"method": args.method}
    if args.samples is not None:
        solver["n_samples"] = args.samples
    sim = simulate(chain, t_end, **impact, **solver)
    near, far = args.sensors
    columns = {"t_s": sim.t, **{f"sensor_ring{k}_N": sim.sensor(k) for k in (near, far)}}
    if sim.support_force is not None:
        columns["support_N"] = sim.support_force
    np.savetxt(args.out, np.column_stack(list(columns.values())), delimiter=",", header=",".join(columns),
               comments="", fmt="%.17g")  # fmt: skip
    if args.plot:
        _plot_traces(args.plot, sim, (near, far), speed)
    lines = [f"{chain.n_rings} rings from {description.source} ({len(description.segments)} segments), "
             f"{chain.model} model, impact at {speed:.4g} m/s, {t_end * 1e3:.4g} ms"]  # fmt: skip
    for k in (near, far):
        lines.append(f"  ring {k}: peak {sim.peak_force(k):.4g} N at {sim.arrival_time(k) * 1e3:.4g} ms")
    lines.append(f"  time of flight {sim.time_of_flight(near, far) * 1e3:.4g} ms, speed "
                 f"{sim.wave_speed(near, far):.4g} m/s")  # fmt: skip
    if sim.support_force is not None:
        lines.append(f"  support: largest force {np.max(sim.support_force):.4g} N")
    print("\n".join(lines))
    print(f"sensor traces written to {args.out}")
    if args.plot:
        print(f"plot written to {args.plot}")
    return 0


def _simulate(args) -> int:
    from .solve import simulate
    from .sweep import default_t_end

    if args.plot is not None and Path(args.plot).resolve() == Path(args.out).resolve():
        raise ValueError(f"arguments --out and --plot: both name {args.out}; give two files")
    if args.chain is not None:
        return _simulate_chain_file(args)
    point = _simulate_point(args)
    impact = {"drop_height": point.drop_height} if point.drop_height is not None else {
        "impact_velocity": point.impact_velocity}  # fmt: skip
    with opt.computing(f"the chain of {args.rings} rings"):
        chain = point.chain()
        t_end = default_t_end(chain, [point.speed], point.sensors) if args.t_end is None else args.t_end
    solver = {} if args.method is None else {"method": args.method}
    if args.samples is not None:
        solver["n_samples"] = args.samples
    sim = simulate(chain, t_end, **impact, **solver)
    try:
        summary = _run_summary(sim, point, t_end)
        failure = None
    except ValueError as exc:
        summary, failure = [], exc
    columns = {"t_s": sim.t, **{f"sensor_ring{k}_N": sim.sensor(k) for k in point.sensors}}
    np.savetxt(args.out, np.column_stack(list(columns.values())), delimiter=",", header=",".join(columns),
               comments="", fmt="%.17g")  # fmt: skip
    if args.plot:
        _plot_traces(args.plot, sim, point.sensors, point.speed)
    print("\n".join(summary))
    print(f"sensor traces written to {args.out}")
    if args.plot:
        print(f"plot written to {args.plot}")
    if failure is not None:
        hint = "; give a longer --t-end" if args.t_end is not None else ""
        reason = opt.one_line(failure)
        raise ValueError(f"the traces are written, but their leading pulses cannot be read: {reason}{hint}")
    return 0


def _run_summary(sim, point, t_end) -> list[str]:
    """The lines ``ringchain simulate`` prints about one run: peaks, arrivals, time of flight, speed."""
    from ringchain.theory import solitary_wave_speed

    chain = sim.chain
    near, far = point.sensors
    K, n = (chain.K, chain.n) if chain.model == "power-law" else point.ring.power_law()
    lines = [f"{chain.n_rings} rings, {chain.model} model, R/r = {point.R_over_r:g}, impact at {point.speed:.4g} "
             f"m/s, {t_end * 1e3:.4g} ms"]  # fmt: skip
    for k in point.sensors:
        lines.append(f"  ring {k}: peak {sim.peak_force(k):.4g} N at {sim.arrival_time(k) * 1e3:.4g} ms")
    V_s = float(solitary_wave_speed(sim.peak_force(near), K=K, n=n, m=chain.m, a=chain.a))
    lines.append(f"  time of flight {sim.time_of_flight(near, far) * 1e3:.4g} ms, speed "
                 f"{sim.wave_speed(near, far):.4g} m/s (Eq. (8) at ring {near}'s peak: {V_s:.4g} m/s)")  # fmt: skip
    return lines


def _plot_traces(path, sim, sensors, speed) -> None:
    fig = _figure(figsize=(6, 3.6))
    ax = fig.add_subplot()
    for k in sensors:
        ax.plot(sim.t * 1e3, sim.sensor(k), label=f"ring {k}")
    ax.set(xlabel="time after impact (ms)", ylabel="sensor force (N)",
           title=f"{sim.chain.model}, {sim.chain.n_rings} rings, impact {speed:.3g} m/s")  # fmt: skip
    ax.legend()
    fig.savefig(path, dpi=120)


# -- ringchain sweep -------------------------------------------------------------------------------
def _sweep_grid(args) -> dict:
    """The grid of ``ringchain sweep``, every value checked against the others before any work."""
    aspects, angles, rings = opt.flat(args.R_over_r), opt.flat(args.angle), opt.flat(args.rings)
    impacts = {"drop_height": opt.flat(args.drop_height)} if args.drop_height is not None else (
        {"impact_velocity": opt.flat(args.impact_velocity)} if args.impact_velocity is not None else {})  # fmt: skip
    for aspect in aspects:
        opt.check_geometry(aspect, angles, chain=bool(impacts), given="argument --R-over-r")
    if impacts:
        opt.check_sensors(args.sensors, rings)
        opt.check_impact(args.material, drop_heights=impacts.get("drop_height"),
                         impact_velocities=impacts.get("impact_velocity"))  # fmt: skip
    # Axis order fixes the row order: the impact varies fastest, so runs of one chain are adjacent.
    grid = {
        "model": args.model or ["dual-spring"],
        "n_rings": rings,
        "R_over_r": aspects,
        "angle": [math.radians(a) for a in angles],
        "m_eff_ratio": opt.flat(args.m_eff_ratio),
        "r": [args.r],
        "material": [args.material],
        "sensors": [tuple(args.sensors)],
        **impacts,
    }
    size = math.prod(len(values) for values in grid.values())
    if size > opt.MAX_GRID_POINTS:
        shape = " x ".join(str(len(values)) for values in grid.values() if len(values) > 1)
        raise ValueError(f"the grid has {size} points ({shape}); the command line runs at most {opt.MAX_GRID_POINTS} "
                         "(split it, or call ringchain.numerics.sweep)")  # fmt: skip
    # The rings at the corners of the grid, where the theory's numbers are most extreme.
    for aspect in {min(aspects), max(aspects)}:
        for angle in {min(angles), max(angles)}:
            opt.ring_of(aspect * args.r, args.r, args.material, angle,
                        f"the ring of --R-over-r {aspect:g}, --r {args.r:g} m, --angle {angle:g} deg")  # fmt: skip
    return grid


def _write_rows(rows, out) -> int:
    """The rows of a sweep as CSV, to standard output ("-") or to the file ``out``."""
    from .sweep import write_csv

    if out == "-":
        write_csv(rows, sys.stdout)
    else:
        write_csv(rows, out)
        print(f"{len(rows)} rows written to {out}")
    return 0


def _sweep_chain_file(args) -> int:
    """``ringchain sweep --chain FILE [--vary FIELD VALUES]``: one chain per value, the impacts as a batch."""
    from .chain_file import sweep_chain_file

    defaults = _GEOMETRY_DEFAULTS | {"R_over_r": [[9.0]], "angle": [[90.0]], "rings": [[20]], "m_eff_ratio": [[1.0]]}
    opt.check_chain_file_alone(args, {k: v for k, v in defaults.items() if k != "m_eff_ratio"})
    if args.dask or args.workers is not None:
        flag = "--dask" if args.dask else "--workers"
        raise ValueError(f"argument {flag}: a sweep of a chain file runs in this process (one batch per chain)")
    if args.drop_height is None and args.impact_velocity is None:
        raise ValueError("a sweep of a chain file needs impacts: give --drop-height or --impact-velocity")
    field, values = opt.vary_values(args.vary) if args.vary else (None, [None])
    ratios, models = opt.flat(args.m_eff_ratio), args.model or ["dual-spring"]
    if len(ratios) > 1 or len(models) > 1:
        raise ValueError("with --chain, give one --model and one --m-eff-ratio (vary the chain with --vary)")
    heights = opt.flat(args.drop_height) if args.drop_height is not None else None
    velocities = opt.flat(args.impact_velocity) if args.impact_velocity is not None else None
    for material in {segment.material for segment in args.chain.segments}:
        opt.check_impact(material, drop_heights=heights, impact_velocities=velocities)
    rows = sweep_chain_file(args.chain, field, values, model=models[0], m_eff_ratio=ratios[0],
                            drop_heights=heights, impact_velocities=velocities, sensors=tuple(args.sensors),
                            t_end=args.t_end, n_samples=args.samples)  # fmt: skip
    return _write_rows(rows, args.out)


def _sweep(args) -> int:
    from .executors import dask_client
    from .sweep import expand, sweep

    if args.chain is not None:
        return _sweep_chain_file(args)
    if args.vary:
        raise ValueError("argument --vary: varies a field of a chain file; give --chain FILE")
    points = expand(_sweep_grid(args))
    options = dict(batch_size=args.batch_size, max_workers=args.workers, progress=sys.stderr.isatty(),
                   t_end=args.t_end)  # fmt: skip
    if args.samples is not None:
        options["n_samples"] = args.samples
    if args.dask:
        try:
            client = dask_client(args.dask, args.dask_timeout)
        except ImportError:
            raise ValueError("--dask needs the dask extra: pip install 'ringchain[dask]'") from None
        except (ConnectionError, ValueError) as exc:
            raise ValueError(f"argument --dask: {opt.one_line(exc)}") from None
        with client, opt.naming_t_end(args):
            rows = sweep(points, client.get_executor(), **options)
    else:
        with opt.naming_t_end(args):
            rows = sweep(points, **options)
    return _write_rows(rows, args.out)


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
    removed, nbytes = clear_cache()
    print(f"removed {removed} files ({_size(nbytes)}) from {directory}")
    return 0


# -- ringchain fit (numerics/fit_cli.py) -------------------------------------------------------------------
def _fit(args) -> int:
    from .fit_cli import run

    return run(args)


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


def build_parser() -> argparse.ArgumentParser:
    from .solve import ADAPTIVE_METHODS

    parser = _Parser(prog="ringchain", description=__doc__.split("\n\n")[0], allow_abbrev=False)
    parser.add_argument("--version", action="version", version=f"ringchain {_version()}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="{paper,ring,simulate,sweep,cache,fit}")

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
    opt.impact_options(p, required=True)
    opt.chain_options(p)
    p.add_argument("--method", choices=(*ADAPTIVE_METHODS, "verlet"), default=None,
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
    opt.impact_options(p, many=True)
    opt.chain_options(p, many=True)
    p.add_argument("--batch-size", type=opt.Checked(int, opt.batch_size), default=64,
                   help="runs of one chain integrated together (default 64)")  # fmt: skip
    p.add_argument("--workers", type=opt.integer("workers", 0), default=None,
                   help="local worker processes (default: CPUs; 0: run in this process)")  # fmt: skip
    p.add_argument("--dask", metavar="ADDRESS", help="run on a Dask cluster, e.g. tcp://scheduler:8786")
    p.add_argument("--dask-timeout", type=opt.DURATION, default=5.0, metavar="S",
                   help="seconds to wait for the Dask scheduler to answer (default 5)")  # fmt: skip
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
    from .fit_cli import add_parser as add_fit_parser

    add_fit_parser(sub, geometry=opt.geometry_options)
    sub.choices["fit"].set_defaults(func=_fit)
    return parser


#: Floating-point trouble in NumPy (the theory's generated code, the solvers) stops the command with a
#: message instead of printing numbers made of inf and nan.
_FLOATING_POINT = r"(overflow|invalid value|divide by zero) encountered"


def main(argv=None) -> int:
    """Run ``ringchain`` with ``argv`` (default ``sys.argv[1:]``); returns the exit code."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help (0) or a usage error (2), already printed
        return int(exc.code or 0)
    command = " ".join(filter(None, (args.command, getattr(args, "action", None))))
    try:
        with warnings.catch_warnings():
            warnings.filterwarnings("error", message=_FLOATING_POINT, category=RuntimeWarning)
            return args.func(args)
    except (ValueError, TypeError, OSError, ArithmeticError, RuntimeWarning) as exc:
        message = opt.one_line(exc)
    except MemoryError:
        message = "out of memory; use fewer --rings, --samples or grid points"
    print(f"ringchain {command}: error: {message}", file=sys.stderr)
    return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
