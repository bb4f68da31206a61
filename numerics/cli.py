"""Command line: ``ringchain <subcommand>``.

- ``ringchain paper`` -- the README's main job: derives the theory, prints the paper's key
  numbers beside the paper's own, runs the 20-ring drop experiment with both lattice
  models and writes the figures to a folder;
- ``ringchain ring --R 22.5e-3 --r 2.5e-3`` -- everything about one ring contact;
- ``ringchain simulate --rings 20 --drop-height 0.05`` -- one run, sensor traces as CSV;
- ``ringchain sweep --R-over-r 6 9 --drop-height 0.01:0.1:10`` -- a grid, one CSV row per point.

Inputs are SI (m, m/s, N) except contact angles, given in degrees.  Bad arguments give
a one-line error and exit code 2; success exits 0.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np
from ringchain.theory import PAPER_TUBE_RADIUS, paper_data

__all__ = ["main", "build_parser"]

#: Forces at which ``ringchain paper`` evaluates V_s (Eq. vsfm), N.
PAPER_FORCES = (1.0, 10.0, 100.0)

#: Aspect ratios of the static table of ``ringchain paper``: those of the paper's FE study and Table I.
PAPER_ASPECT_RATIOS = (3.1, 4.0, 5.5, 6.0, 9.0, 10.0)

#: Drop height of the experiment run by ``ringchain paper``, m (the paper does not give its heights).
PAPER_DROP_HEIGHT = 0.05

#: Default folder of the figures of ``ringchain paper``.
PAPER_FIGURES = "ringchain-paper-figures"


# -- formatting ------------------------------------------------------------------------------------
def _table(title: str, headers, rows, notes=()) -> None:
    """Print a titled table with right-aligned columns."""
    cells = [[str(c) for c in row] for row in rows]
    widths = [max(len(h), *(len(row[j]) for row in cells)) for j, h in enumerate(headers)]
    print(title)
    print("  " + "  ".join(h.rjust(w) for h, w in zip(headers, widths, strict=True)))
    for row in cells:
        print("  " + "  ".join(c.rjust(w) for c, w in zip(row, widths, strict=True)))
    for note in notes:
        print(f"  {note}")
    print()


def _g(x, digits=4) -> str:
    return "-" if x is None else f"{float(x):.{digits}g}"


def _as_printed(x) -> str:
    """A value of the paper as it prints it (K = 2284, n = 1.418); '-' if it gives none."""
    return "-" if x is None else f"{x:g}"


def _figure(**kwargs):
    """A matplotlib Figure drawn by the Agg canvas (no pyplot, no display needed).

    Fixed margins rather than a layout engine: one draw per figure, which keeps
    ``ringchain paper`` quick.
    """
    from matplotlib.figure import Figure

    fig = Figure(layout=None, **kwargs)  # explicit: a user's rcParams may turn a layout engine on
    fig.subplots_adjust(left=0.15, right=0.97, bottom=0.14, top=0.9, wspace=0.08)
    return fig


# -- ringchain paper -----------------------------------------------------------------------------
def _paper(args) -> int:
    from ringchain.theory import (
        STAINLESS_STEEL_304,
        Ring,
        minimum_contact_angle,
        n_per_mm_to_si,
        si_to_n_per_mm,
        solitary_wave_speed,
    )

    from .solve import paper_experiment

    out = Path(args.out)
    h = float(args.drop_height)
    if not h > 0:
        raise ValueError(f"the drop height must be positive (in m), got {h:g}")
    out.mkdir(parents=True, exist_ok=True)

    # 1. Static theory against R/r (Sec. II and IV.A).
    rows = []
    for aspect in PAPER_ASPECT_RATIOS:
        ring = Ring.from_aspect_ratio(aspect)
        K, n = ring.power_law()
        K_paper, n_paper, source = None, paper_data.FE_EXPONENTS.get(aspect), "FE"
        if aspect in paper_data.TABLE_I:
            K_paper, n_paper, _ = paper_data.TABLE_I[aspect]
            source = "Table I"
        rows.append([
            f"{aspect:.1f}", f"{ring.K_c:.4e}", f"{ring.K_b:.4e}", _g(ring.crossover_force),
            _g(si_to_n_per_mm(K, n)), f"{n:.3f}", _as_printed(K_paper), _as_printed(n_paper), source,
        ])  # fmt: skip
    _table(
        "Static theory of one contact against R/r (paper Sec. II and IV.A, Eqs. 1-4); stainless steel, "
        "r = 2.5 mm, 90 deg",
        ["R/r", "K_c (N/m^1.5)", "K_b (N/m)", "F* (N)", "K (N/mm^n)", "n", "K paper", "n paper", "source"],
        rows,
        ["theory: power law F = K delta^n fitted to the series law (Eq. 3) over 1-100 N; "
         "paper: quasi-static tests (Table I) or Abaqus (Sec. IV.A)"],
    )  # fmt: skip

    # 2. Exponent against contact angle (Sec. IV.B, Table II).
    aspect = paper_data.TABLE_II_ASPECT_RATIO
    lowest = math.degrees(float(minimum_contact_angle(aspect, 1.0)))
    rows, notes = [], []
    for angle_deg, (K_paper, n_paper, _) in paper_data.TABLE_II.items():
        theory = _ring_or_none(aspect, math.radians(angle_deg))
        if theory is None:
            cells = ["n/a"] * 4
            notes.append(f"{angle_deg:g} deg: no single Hertz contact below {lowest:.1f} deg = arccos(1 - 2r/R); "
                         "the tori touch at two patches (the paper's Abaqus regime, Sec. IV.B)")  # fmt: skip
        else:
            K, n = theory.power_law()
            cells = [f"{theory.K_c:.4e}", _g(theory.crossover_force), _g(si_to_n_per_mm(K, n)), f"{n:.3f}"]
        rows.append([f"{angle_deg:.0f}", *cells, _as_printed(K_paper), _as_printed(n_paper)])
    _table(
        f"Exponent against contact angle (paper Sec. IV.B, App. A), R/r = {aspect:g}",
        ["angle (deg)", "K_c (N/m^1.5)", "F* (N)", "K (N/mm^n)", "n", "K Table II", "n Table II"],
        rows,
        [*notes, f"Table II's rings: R/r = {aspect:g} (paper_data.TABLE_II_ASPECT_RATIO; Sec. IV.B says R = 20 mm)"],
    )  # fmt: skip

    # 3. Solitary-wave speed with the measured parameters (Eq. vsfm, Tables I-II).
    rows = []
    for label, ring, (K_mm, n, ratio) in _table_rows():
        m = ratio * ring.mass
        V = solitary_wave_speed(np.array(PAPER_FORCES), float(n_per_mm_to_si(K_mm, n)), n, ring.spacing, m)
        rows.append([
            label, _as_printed(K_mm), _as_printed(n), f"{m * 1e3:.2f}", f"{ring.spacing * 1e3:.1f}",
            *(_g(x) for x in V),
        ])  # fmt: skip
    _table(
        "Solitary-wave speed V_s(F_m) (paper Eq. vsfm) with the measured K, n and m_eff (Tables I and II)",
        ["row", "K (N/mm^n)", "n", "m_eff (g)", "a (mm)", *(f"V_s({F:g} N) (m/s)" for F in PAPER_FORCES)],
        rows,
        [f"m_eff = (m_eff/m0) x ring mass (torus 2 pi^2 R r^2 of {STAINLESS_STEEL_304.name} steel, "
         f"{STAINLESS_STEEL_304.rho:g} kg/m^3); a = 2(R - r)"],
    )  # fmt: skip

    # 4. The 20-ring drop experiment (Sec. III), both lattice models (paper_experiment: Table I, R/r = 9).
    runs = {model: paper_experiment(h, model) for model in ("dual-spring", "power-law")}
    K_mm, n, ratio = paper_data.TABLE_I[9.0]
    near, far = paper_data.SENSOR_RINGS
    rows = []
    for model, run in runs.items():
        chain = run.simulation.chain
        V_s = float(solitary_wave_speed(run.peak_forces[0], float(n_per_mm_to_si(K_mm, n)), n, chain.a, chain.m))
        rows.append([
            model, _g(run.peak_forces[0]), _g(run.peak_forces[1]), _g(run.arrival_times[0] * 1e3),
            _g(run.arrival_times[1] * 1e3), _g(run.time_of_flight * 1e3), _g(run.wave_speed), _g(V_s),
        ])  # fmt: skip
    v0 = runs["power-law"].impact_velocity
    _table(
        f"The paper's experiment (Sec. III): {paper_data.CHAIN_RINGS} rings of R/r = 9 hanging under gravity, "
        f"ring 0 dropped from h = {h:g} m (impact at {v0:.3g} m/s); Table I: K = {K_mm:g} N/mm^n, n = {n:g}, "
        f"m_eff/m0 = {ratio:g}",
        ["model", f"F ring {near} (N)", f"F ring {far} (N)", f"t ring {near} (ms)", f"t ring {far} (ms)",
         "time of flight (ms)", "speed (m/s)", "V_s Eq. vsfm (m/s)"],
        rows,
        [f"F, t: peak and arrival of the leading pulse at the ring's sensor; speed = {far - near} a / time of flight; "
         f"V_s at ring {near}'s peak force with Table I's power law",
         "paper: arrival at the downstream sensor printed as 0.426 (low) and 0.348 (high amplitude), unit 's'"],
    )  # fmt: skip

    # 5. Figures.
    written = _paper_figures(out, runs)
    print(f"Figures written to {out.resolve()}/: {', '.join(p.name for p in written)}")
    return 0


def _ring_or_none(aspect, angle):
    """The ring of aspect ratio ``aspect`` at contact ``angle`` (rad), or None below the single-contact angle."""
    from ringchain.theory import Ring, minimum_contact_angle

    ring_r = paper_data.TUBE_RADIUS
    if angle <= float(minimum_contact_angle(aspect * ring_r, ring_r)):
        return None
    return Ring.from_aspect_ratio(aspect, r=ring_r, angle=angle)


def _table_rows():
    """(label, ring, (K in N/mm^n, n, m_eff/m0)) of Tables I and II, Table II at 90 deg geometry."""
    from ringchain.theory import Ring

    for aspect, values in paper_data.TABLE_I.items():
        yield f"Table I R/r = {aspect:g}", Ring.from_aspect_ratio(aspect, r=paper_data.TUBE_RADIUS), values
    ring = Ring.from_aspect_ratio(paper_data.TABLE_II_ASPECT_RATIO, r=paper_data.TUBE_RADIUS)
    for angle, values in paper_data.TABLE_II.items():
        yield f"Table II {angle:g} deg", ring, values


def _paper_figures(out: Path, runs) -> list[Path]:
    from ringchain.theory import (
        STAINLESS_STEEL_304,
        bending_stiffness,
        fit_power_law,
        hertz_stiffness,
        minimum_contact_angle,
        n_per_mm_to_si,
        series_displacement,
        solitary_wave_speed,
    )

    steel, r = STAINLESS_STEEL_304, paper_data.TUBE_RADIUS
    written = []

    def save(fig, name):
        path = out / name
        fig.savefig(path, dpi=120)
        written.append(path)

    # n against R/r (Sec. IV.A).
    aspect = np.linspace(3.02, 12.0, 200)
    K_c = hertz_stiffness(aspect * r, r, steel.E, steel.nu)
    K_b = bending_stiffness(aspect * r, r, steel.E, steel.nu)
    _, n = fit_power_law(K_c, K_b)
    fig = _figure(figsize=(5, 3.6))
    ax = fig.add_subplot()
    ax.plot(aspect, n, label="theory (Eqs. 1-4), fit over 1-100 N")
    ax.plot(list(paper_data.FE_EXPONENTS), list(paper_data.FE_EXPONENTS.values()), "^", label="paper, Abaqus")
    ax.plot(list(paper_data.TABLE_I), [row[1] for row in paper_data.TABLE_I.values()], "o", label="paper, Table I")
    ax.set(xlabel="aspect ratio R/r", ylabel="exponent n", title="Nonlinearity against aspect ratio")
    ax.legend()
    save(fig, "exponent_vs_aspect_ratio.png")

    # n against contact angle (Sec. IV.B).
    R = paper_data.TABLE_II_ASPECT_RATIO * r
    lowest = float(minimum_contact_angle(R, r))
    angle = np.linspace(lowest + 1e-3, np.pi / 2, 150)
    K_c = hertz_stiffness(R, r, steel.E, steel.nu, angle)
    _, n = fit_power_law(K_c, bending_stiffness(R, r, steel.E, steel.nu))
    fig = _figure(figsize=(5, 3.6))
    ax = fig.add_subplot()
    ax.plot(np.degrees(angle), n, label="theory, elliptical Hertz contact")
    ax.axvspan(0, np.degrees(lowest), color="0.9", label="no single Hertz contact")
    ax.plot(list(paper_data.TABLE_II), [row[1] for row in paper_data.TABLE_II.values()], "o", label="paper, Table II")
    ax.set(xlabel="contact angle (deg)", ylabel="exponent n", xlim=(0, 90),
           title=f"Nonlinearity against contact angle, R/r = {paper_data.TABLE_II_ASPECT_RATIO:g}")  # fmt: skip
    ax.legend()
    save(fig, "exponent_vs_angle.png")

    # Force against extension: series law and its power law (Eqs. 3-4, Fig. 2).
    F = np.geomspace(0.01, 100.0, 120)
    fig = _figure(figsize=(5, 3.6))
    ax = fig.add_subplot()
    for k, a_r in enumerate(PAPER_ASPECT_RATIOS):
        R = a_r * r
        K_c, K_b = hertz_stiffness(R, r, steel.E, steel.nu), bending_stiffness(R, r, steel.E, steel.nu)
        K, n = fit_power_law(K_c, K_b)
        color = f"C{k}"
        ax.plot(series_displacement(F, K_c, K_b) * 1e6, F, color=color, label=f"R/r = {a_r:g}")
        ax.plot((F / K) ** (1.0 / n) * 1e6, F, "--", color=color)
    ax.set(xscale="log", yscale="log", xlabel="extension delta (um)", ylabel="force F (N)",
           title="Series law (solid) and fitted power law (dashed)")  # fmt: skip
    ax.legend(fontsize="small")
    save(fig, "force_extension.png")

    # V_s against F_m (Eq. vsfm, Fig. 4).
    F_m = np.geomspace(0.5, 300.0, 100)
    fig = _figure(figsize=(8, 3.6))
    axes = fig.subplots(1, 2, sharey=True)
    for label, ring, (K_mm, n, ratio) in _table_rows():
        ax = axes[0] if label.startswith("Table I ") else axes[1]
        V = solitary_wave_speed(F_m, float(n_per_mm_to_si(K_mm, n)), n, ring.spacing, ratio * ring.mass)
        ax.plot(F_m, V, label=label.split(" ", 2)[2])
    for ax, title in zip(axes, ("Table I: aspect ratio", "Table II: contact angle"), strict=True):
        ax.set(xscale="log", xlabel="peak force F_m (N)", title=title)
        ax.legend()
    axes[0].set_ylabel("solitary-wave speed V_s (m/s)")
    save(fig, "wave_speed_vs_force.png")

    # Sensor traces of the experiment (Sec. III, Fig. 1 d-e).
    fig = _figure(figsize=(8, 3.6))
    axes = fig.subplots(1, 2, sharey=True)
    for ax, (model, run) in zip(axes, runs.items(), strict=True):
        sim = run.simulation
        for ring_index in run.sensors:
            ax.plot(sim.t * 1e3, sim.sensor(ring_index), label=f"ring {ring_index}")
        ax.set(xlabel="time after impact (ms)", title=f"{model}, h = {run.drop_height:g} m")
        ax.legend(loc="upper right")
    axes[0].set_ylabel("sensor force (N)")
    save(fig, "experiment_sensor_forces.png")
    return written


# -- ringchain ring ------------------------------------------------------------------------------
def _ring(args) -> int:
    from ringchain.theory import (
        Ring,
        minimum_contact_angle,
        series_displacement,
        si_to_n_per_mm,
        solitary_wave_speed,
        solitary_wave_width,
    )

    ring = Ring(args.R, args.r, material=args.material, angle=math.radians(args.angle), thin=args.thin)
    F = float(_positive("--force", args.force))
    ratio = float(args.m_eff_ratio)
    if not 0 < ratio <= 1:
        raise ValueError(f"--m-eff-ratio must lie in (0, 1], got {ratio:g}")
    F_lo, F_hi = args.window
    K, n = ring.power_law(F_lo, F_hi)
    mat = ring.material
    m = ratio * ring.mass
    lowest = math.degrees(float(minimum_contact_angle(ring.R, ring.r)))
    chain_note = "yes" if ring.can_form_chain else f"no: R/r < {3:g}, two rings interlock but a chain cannot form"
    F_star = ring.crossover_force
    n_star = float(ring.local_exponent(F_star))
    V_s = float(solitary_wave_speed(F, K, n, ring.spacing, m))
    width = float(solitary_wave_width(n, ring.spacing))
    lines = [
        ("geometry", f"R = {ring.R * 1e3:g} mm, r = {ring.r * 1e3:g} mm, R/r = {ring.aspect_ratio:.4g}"),
        ("material", f"{mat.name}: E = {mat.E / 1e9:g} GPa, nu = {mat.nu:g}, rho = {mat.rho:g} kg/m^3"),
        ("contact angle", f"{args.angle:g} deg (single Hertz contact above {lowest:.2f} deg)"),
        ("forms a chain", chain_note),
        ("ring mass m0", f"{ring.mass * 1e3:.4g} g"),
        ("spacing a = 2(R - r)", f"{ring.spacing * 1e3:.4g} mm"),
        ("K_c, Hertz contact (Eq. 1)", f"{ring.K_c:.4e} N/m^1.5"),
        ("K_b, ring bending (Eq. 2)", f"{ring.K_b:.4e} N/m" + (" (thin ring)" if args.thin else "")),
        ("crossover F* = K_b^3/K_c^2", f"{F_star:.4g} N (local exponent there {n_star:.4f})"),
        (f"power law over {F_lo:g}-{F_hi:g} N (Eq. 4)",
         f"K = {float(si_to_n_per_mm(K, n)):.5g} N/mm^n = {K:.5g} N/m^n, n = {n:.4f}"),
        (f"at F = {F:g} N (Eq. 3)", f"extension {float(series_displacement(F, ring.K_c, ring.K_b)) * 1e6:.4g} um, "
         f"local exponent {float(ring.local_exponent(F)):.4f}"),
        (f"solitary wave at F_m = {F:g} N", f"V_s = {V_s:.4g} m/s (Eq. vsfm, m = {ratio:g} m0 = {m * 1e3:.4g} g), "
         f"width {width * 1e3:.4g} mm = {width / ring.spacing:.3g} a"),
    ]  # fmt: skip
    pad = max(len(k) for k, _ in lines)
    for key, value in lines:
        print(f"{key.ljust(pad)}  {value}")
    return 0


def _check_folder(path):
    """Refuse an output file in a folder that does not exist, before any work."""
    if path is not None and not Path(path).resolve().parent.is_dir():
        raise ValueError(f"cannot write {path}: the folder {Path(path).parent} does not exist")


def _positive(name, value):
    if not value > 0:
        raise ValueError(f"{name} must be positive, got {value:g}")
    return value


# -- ringchain simulate ------------------------------------------------------------------------------
def _point_from(args, **impact):
    from .sweep import Point

    return Point(
        R_over_r=args.R / args.r, r=args.r, angle=math.radians(args.angle), material=args.material,
        model=args.model, n_rings=args.rings, m_eff_ratio=args.m_eff_ratio, sensors=tuple(args.sensors), **impact,
    )  # fmt: skip


def _simulate(args) -> int:
    from ringchain.theory import solitary_wave_speed

    from .solve import simulate
    from .sweep import default_t_end

    if args.drop_height is not None:
        impact = {"drop_height": args.drop_height}
    else:
        impact = {"impact_velocity": args.impact_velocity}
    point = _point_from(args, **impact)
    for path in (args.out, args.plot):
        _check_folder(path)
    chain = point.chain()
    t_end = default_t_end(chain, [point.speed], point.sensors) if args.t_end is None else args.t_end
    t_end = float(_positive("--t-end", t_end))
    solver = {} if args.method is None else {"method": args.method}
    if args.samples is not None:
        solver["n_samples"] = args.samples
    sim = simulate(chain, t_end, **impact, **solver)
    near, far = point.sensors
    columns = {"t_s": sim.t, **{f"sensor_ring{k}_N": sim.sensor(k) for k in point.sensors}}
    header = ",".join(columns)
    np.savetxt(args.out, np.column_stack(list(columns.values())), delimiter=",", header=header, comments="",
               fmt="%.17g")  # fmt: skip
    K, n = (chain.K, chain.n) if chain.model == "power-law" else point.ring.power_law()
    print(f"{chain.n_rings} rings, {chain.model} model, R/r = {point.R_over_r:g}, impact at {point.speed:.4g} m/s, "
          f"{t_end * 1e3:.4g} ms")  # fmt: skip
    for k in point.sensors:
        print(f"  ring {k}: peak {sim.peak_force(k):.4g} N at {sim.arrival_time(k) * 1e3:.4g} ms")
    V_s = float(solitary_wave_speed(sim.peak_force(near), K, n, chain.a, chain.m))
    print(f"  time of flight {sim.time_of_flight(near, far) * 1e3:.4g} ms, speed {sim.wave_speed(near, far):.4g} m/s "
          f"(Eq. vsfm at ring {near}'s peak: {V_s:.4g} m/s)")  # fmt: skip
    print(f"sensor traces written to {args.out}")
    if args.plot:
        fig = _figure(figsize=(6, 3.6))
        ax = fig.add_subplot()
        for k in point.sensors:
            ax.plot(sim.t * 1e3, sim.sensor(k), label=f"ring {k}")
        ax.set(xlabel="time after impact (ms)", ylabel="sensor force (N)",
               title=f"{chain.model}, {chain.n_rings} rings, impact {point.speed:.3g} m/s")  # fmt: skip
        ax.legend()
        fig.savefig(args.plot, dpi=120)
        print(f"plot written to {args.plot}")
    return 0


# -- ringchain sweep -------------------------------------------------------------------------------
def _numbers(kind):
    """argparse type: a number, or ``start:stop:count`` for ``count`` evenly spaced values."""

    def parse(text: str):
        parts = text.split(":")
        try:
            if len(parts) == 1:
                return [kind(text)]
            if len(parts) == 3 and kind is float:
                start, stop, count = float(parts[0]), float(parts[1]), int(parts[2])
                if count < 1:
                    raise ValueError
                # 12 significant digits: 0.08, not linspace's 0.07999999999999999.
                return [float(f"{x:.12g}") for x in np.linspace(start, stop, count)]
        except ValueError:
            pass
        form = "a number or start:stop:count" if kind is float else "an integer"
        raise argparse.ArgumentTypeError(f"expected {form}, got {text!r}")

    parse.__name__ = kind.__name__
    return parse


def _flat(lists):
    return None if lists is None else [x for values in lists for x in values]


def _sweep(args) -> int:
    from .sweep import expand, sweep, write_csv

    # Axis order fixes the row order: the impact varies fastest, so runs of one chain are adjacent.
    grid = {
        "model": args.model,
        "n_rings": _flat(args.rings),
        "R_over_r": _flat(args.R_over_r),
        "angle": [math.radians(a) for a in _flat(args.angle)],
        "m_eff_ratio": _flat(args.m_eff_ratio),
        "r": [args.r],
        "material": [args.material],
        "sensors": [tuple(args.sensors)],
    }
    if args.drop_height is not None:
        grid["drop_height"] = _flat(args.drop_height)
    elif args.impact_velocity is not None:
        grid["impact_velocity"] = _flat(args.impact_velocity)
    if args.t_end is not None:
        _positive("--t-end", args.t_end)
    points = expand(grid)  # validates every point before any work
    if args.out != "-":
        _check_folder(args.out)
    options = dict(batch_size=args.batch_size, max_workers=args.workers, progress=sys.stderr.isatty(),
                   t_end=args.t_end)  # fmt: skip
    if args.samples is not None:
        options["n_samples"] = args.samples
    if args.dask:
        try:
            from distributed import Client
        except ImportError:
            raise ValueError("--dask needs the dask extra: pip install 'ringchain[dask]'") from None
        with Client(args.dask) as client:
            rows = sweep(points, client.get_executor(), **options)
    else:
        rows = sweep(points, **options)
    if args.out == "-":
        write_csv(rows, sys.stdout)
    else:
        write_csv(rows, args.out)
        print(f"{len(rows)} rows written to {args.out}")
    return 0


# -- the parser ----------------------------------------------------------------------------------------
class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors: ``prog: error: message (see prog --help)``, exit code 2."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def _geometry(p, *, R_default=True):
    if R_default:
        p.add_argument("--R", type=float, default=22.5e-3, metavar="M",
                       help="major (centroidal) radius of the rings, m (default 22.5e-3)")  # fmt: skip
    p.add_argument("--r", type=float, default=PAPER_TUBE_RADIUS, metavar="M",
                   help="tube radius, m (default 2.5e-3, the paper's)")  # fmt: skip
    p.add_argument("--material", default="stainless", help="material preset (default stainless: AISI 304)")
    p.add_argument("--m-eff-ratio", type=float, default=1.0, metavar="X",
                   help="inertial over ring mass m_eff/m0 in (0, 1] (default 1; the paper fits 0.33-0.37)")  # fmt: skip


def _chain_options(p, *, many=False):
    from .chain import MODELS

    nargs = "+" if many else None
    p.add_argument("--model", choices=MODELS, default=None if many else "dual-spring", nargs=nargs,
                   help="lattice model (paper Sec. III.B; default dual-spring)")  # fmt: skip
    p.add_argument("--sensors", type=int, nargs=2, default=list(paper_data.SENSOR_RINGS), metavar=("NEAR", "FAR"),
                   help="sensor rings counted from the impact (default 6 12)")  # fmt: skip
    p.add_argument("--t-end", type=float, default=None, metavar="S",
                   help="duration, s (default: long enough for the pulse to pass the far sensor)")  # fmt: skip
    p.add_argument("--samples", type=int, default=None,
                   help="samples of each force record (default: simulate's 2001, sweep's 1001)")  # fmt: skip


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="ringchain", description=__doc__.split("\n\n")[0], allow_abbrev=False)
    sub = parser.add_subparsers(dest="command", required=True, metavar="{paper,ring,simulate,sweep}")

    p = sub.add_parser("paper", help="derive the theory, print the paper's key numbers, write the figures",
                       allow_abbrev=False)  # fmt: skip
    p.add_argument("--out", default=PAPER_FIGURES, metavar="DIR",
                   help=f"folder for the figures (default ./{PAPER_FIGURES})")  # fmt: skip
    p.add_argument("--drop-height", type=float, default=PAPER_DROP_HEIGHT, metavar="M",
                   help=f"drop height of the 20-ring experiment, m (default {PAPER_DROP_HEIGHT:g})")  # fmt: skip
    p.set_defaults(func=_paper)

    p = sub.add_parser("ring", help="everything about one ring contact", allow_abbrev=False)
    p.add_argument("--R", type=float, required=True, metavar="M", help="major (centroidal) radius, m")
    _geometry(p, R_default=False)
    p.add_argument("--angle", type=float, default=90.0, metavar="DEG", help="contact angle, degrees (default 90)")
    p.add_argument("--force", type=float, default=10.0, metavar="N",
                   help="force for the local exponent and the solitary-wave speed, N (default 10)")  # fmt: skip
    p.add_argument("--window", type=float, nargs=2, default=[1.0, 100.0], metavar=("F_MIN", "F_MAX"),
                   help="force window of the power-law fit, N (default 1 100)")  # fmt: skip
    p.add_argument("--thin", action="store_true", help="thin-ring bending stiffness instead of the curved beam")
    p.set_defaults(func=_ring)

    p = sub.add_parser("simulate", help="one drop or impact; sensor traces to CSV", allow_abbrev=False)
    _geometry(p)
    p.add_argument("--angle", type=float, default=90.0, metavar="DEG", help="contact angle, degrees (default 90)")
    p.add_argument("--rings", type=int, default=paper_data.CHAIN_RINGS, help="rings in the chain (default 20)")
    impact = p.add_mutually_exclusive_group(required=True)
    impact.add_argument("--drop-height", type=float, metavar="M", help="free-fall height of ring 0, m")
    impact.add_argument("--impact-velocity", type=float, metavar="M/S", help="impact speed of ring 0, m/s")
    _chain_options(p)
    p.add_argument("--method", default=None,
                   help="integrator of ringchain.numerics.simulate (default its DEFAULT_METHOD)")  # fmt: skip
    p.add_argument("--out", required=True, metavar="CSV", help="CSV of the sensor traces")
    p.add_argument("--plot", metavar="PNG", help="also plot the sensor traces")
    p.set_defaults(func=_simulate)

    p = sub.add_parser("sweep", help="a grid of chains and impacts, one CSV row per point", allow_abbrev=False,
                       description="Values: numbers, or start:stop:count for evenly spaced ones.")  # fmt: skip
    real, integer = _numbers(float), _numbers(int)
    p.add_argument("--R-over-r", type=real, nargs="+", default=[[9.0]], metavar="X", help="aspect ratios (default 9)")
    p.add_argument("--angle", type=real, nargs="+", default=[[90.0]], metavar="DEG", help="contact angles, degrees")
    p.add_argument("--rings", type=integer, nargs="+", default=[[paper_data.CHAIN_RINGS]], metavar="N",
                   help="chain lengths (default 20)")  # fmt: skip
    impact = p.add_mutually_exclusive_group()
    impact.add_argument("--drop-height", type=real, nargs="+", metavar="M", help="drop heights, m")
    impact.add_argument("--impact-velocity", type=real, nargs="+", metavar="M/S", help="impact speeds, m/s")
    p.add_argument("--r", type=float, default=PAPER_TUBE_RADIUS, metavar="M", help="tube radius, m (default 2.5e-3)")
    p.add_argument("--material", default="stainless", help="material preset (default stainless)")
    p.add_argument("--m-eff-ratio", type=real, nargs="+", default=[[1.0]], metavar="X",
                   help="m_eff/m0 values in (0, 1] (default 1)")  # fmt: skip
    _chain_options(p, many=True)
    p.add_argument("--batch-size", type=int, default=64, help="runs of one chain integrated together (default 64)")
    p.add_argument("--workers", type=int, default=None,
                   help="local worker processes (default: CPUs; 0: run in this process)")  # fmt: skip
    p.add_argument("--dask", metavar="ADDRESS", help="run on a Dask cluster, e.g. tcp://scheduler:8786")
    p.add_argument("--out", default="-", metavar="CSV", help="output CSV (default: standard output)")
    p.set_defaults(func=_sweep)
    return parser


def main(argv=None) -> int:
    """Run ``ringchain`` with ``argv`` (default ``sys.argv[1:]``); returns the exit code."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help (0) or a usage error (2), already printed
        return int(exc.code or 0)
    if args.command == "sweep" and args.model is None:
        args.model = ["dual-spring"]
    try:
        return args.func(args)
    except (ValueError, TypeError, OSError) as exc:
        message = " ".join(str(exc).split())
        print(f"ringchain {args.command}: error: {message}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
