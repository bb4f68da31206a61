r"""The paper's experiment, tables and figures: what ``ringchain paper`` prints and the book shows.

- :func:`paper_experiment` -- the 20-ring drop experiment of Sec. III (R/r = 9, sensors
  in rings 6 and 12) with either lattice model, read as the paper reads it;
- :func:`static_table`, :func:`angle_table`, :func:`speed_table`,
  :func:`experiment_table` -- the key numbers beside the paper's own, as :class:`Table`
  objects (``str(table)`` is the text the command line prints);
- :func:`write_figures` -- the figures (exponent against R/r and angle, the series law,
  V_s against F_m, the sensor traces);
- :func:`paper_job` -- all of it, as ``ringchain paper`` runs it.

Stiffness.  The paper runs its power-law chain on the K and n of its quasi-static tests
(Table I) and its dual-spring chain on the K_c and K_b of Eqs. (1)-(2) (Sec. III.B); at
R/r = 9 the theory's springs are stiffer than the measured ones (fitted power law
K = 4162 against 2284 N/mm^n, n = 1.107 against 1.11), which alone makes the
dual-spring pulse about a quarter faster.  :func:`paper_experiment` therefore takes
one source of stiffness for both models (``stiffness``):

- ``"table"`` (default): the power-law chain takes Table I's K and n; the dual-spring
  chain takes the contact and bending stiffnesses whose series law (Eq. 3), reduced to a
  power law over the same force window as the theory (Eq. 4, 1-100 N), *is* Table I's K
  and n (:func:`ringchain.theory.series_stiffness_for_power_law`: two springs, two measured numbers, an
  exact match).  Keeping the theory's K_b and choosing K_c alone cannot match both: at
  R/r = 9 bending carries most of the compliance, and softening the contact enough to
  reach Table I's K raises n well above 1.11;
- ``"theory"``: both from the ring's theory, the power law fitted to Eqs. (1)-(3).

The source each model used is a field of the result (:attr:`PaperExperiment.stiffness`)
and a column of :func:`experiment_table`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from ringchain.theory import Ring, n_per_mm_to_si, paper_data, series_stiffness_for_power_law
from ringchain.theory import _validate as v

from ..engine.plots import new_figure
from ..engine.results import Simulation
from ..layouts.chain import MODELS, Chain, sensor_pair
from .experiment import run_experiment

__all__ = [
    "PaperExperiment",
    "paper_chain",
    "paper_experiment",
    "stiffness_note",
    "Table",
    "static_table",
    "angle_table",
    "speed_table",
    "experiment_table",
    "experiment_runs",
    "table_parameters",
    "write_figures",
    "paper_job",
    "STIFFNESS_SOURCES",
    "PAPER_FORCES",
    "PAPER_ASPECT_RATIOS",
    "PAPER_DROP_HEIGHT",
    "PAPER_FIGURES",
]

#: Forces at which the speed table evaluates V_s (Eq. (8)), N.
PAPER_FORCES = (1.0, 10.0, 100.0)

#: Aspect ratios of the static table: those of the paper's FE study and Table I.
PAPER_ASPECT_RATIOS = (3.1, 4.0, 5.5, 6.0, 9.0, 10.0)

#: Drop height of the experiment of ``ringchain paper``, m (the paper does not give its heights).
PAPER_DROP_HEIGHT = 0.05

#: Default folder of the figures of ``ringchain paper``.
PAPER_FIGURES = "ringchain-paper-figures"


#: Sources of the stiffness of :func:`paper_chain`: the paper's measured power law (Table I) or
#: the ring's theory (Eqs. 1-4).
STIFFNESS_SOURCES = ("table", "theory")


# -- the paper's chain ------------------------------------------------------------------------------
def paper_chain(model="power-law", aspect_ratio=9.0, n_rings=paper_data.CHAIN_RINGS, *, stiffness=None,
                striker_mass=None, **dashpots) -> Chain:  # fmt: skip
    """The paper's experimental chain: Table I parameters for ``aspect_ratio``.

    Both models use the fitted m_eff/m0 as inertial mass and m0 for gravity; the rings
    are the paper's, r = 2.5 mm, stainless steel.  ``dashpots`` are passed on (default
    undamped: the paper does not report its fitted gamma values).

    Parameters
    ----------
    model : {"power-law", "dual-spring"}
    aspect_ratio : float
        A row of Table I (9, 6 or 5.5).
    n_rings : int
    stiffness : {"table", "theory"}, optional
        "table": the power-law chain takes the measured K (N/mm^n, converted to SI)
        and n; the dual-spring chain the K_c and K_b whose series law reduces to that
        power law over 1-100 N (:func:`ringchain.theory.series_stiffness_for_power_law`).
        "theory": the ring's K_c and K_b (Eqs. 1-2), and for the power-law chain the power
        law fitted to them (Eq. 4).  Default: as the paper did (Sec. III.B), "table" for the
        power-law chain and "theory" for the dual-spring chain.
    striker_mass : float or {"m_eff", "m0"}, optional
        Inertial mass of the struck ring 0 (:class:`~ringchain.numerics.Chain`): default the
        lattice's m_eff, the paper's convention.

    Examples
    --------
    >>> chain = paper_chain("power-law")
    >>> chain.n_rings, chain.n, round(chain.m / chain.m_gravity, 2)
    (20, 1.11, 0.37)
    """
    if aspect_ratio not in paper_data.TABLE_I:
        raise ValueError(f"Table I has aspect ratios {sorted(paper_data.TABLE_I)}, got {aspect_ratio!r}")
    v.choice("model", model, MODELS)
    if stiffness is None:
        stiffness = "table" if model == "power-law" else "theory"
    v.choice("stiffness", stiffness, STIFFNESS_SOURCES)
    K_mm, n, ratio = paper_data.TABLE_I[aspect_ratio]
    ring = Ring.from_aspect_ratio(aspect_ratio, r=paper_data.TUBE_RADIUS)
    if stiffness == "theory":
        return Chain.from_ring(ring, n_rings, model, m_eff_ratio=ratio, striker_mass=striker_mass, **dashpots)
    K_si = float(n_per_mm_to_si(K_mm, n=n))
    if model == "power-law":
        return Chain.from_ring(ring, n_rings, model, m_eff_ratio=ratio, K=K_si, n=n, striker_mass=striker_mass,
                               **dashpots)  # fmt: skip
    if "gamma" in dashpots:
        raise ValueError("K, n and gamma belong to the power-law model; use gamma_c and gamma_b")
    K_c, K_b = series_stiffness_for_power_law(K=K_si, n=n)
    m0 = ring.mass
    return Chain.dual_spring(n_rings, K_c, K_b, ratio * m0, ring.spacing, m_gravity=m0, striker_mass=striker_mass,
                             **dashpots)  # fmt: skip


def stiffness_note(model: str, stiffness: str, aspect_ratio: float = 9.0) -> str:
    """Where the stiffness of :func:`paper_chain` ``(model, stiffness=...)`` comes from, in words."""
    v.choice("model", model, MODELS)
    v.choice("stiffness", stiffness, STIFFNESS_SOURCES)
    K_mm, n, _ = paper_data.TABLE_I[aspect_ratio]
    if stiffness == "theory":
        if model == "power-law":
            return "theory: K, n fitted to Eqs. (1)-(3) over 1-100 N"
        return "theory: K_c of Eq. (1), K_b of Eq. (2)"
    if model == "power-law":
        return f"Table I: K = {K_mm:g} N/mm^n, n = {n:g}"
    return f"K_c, K_b whose power law over 1-100 N is Table I's (K = {K_mm:g} N/mm^n, n = {n:g})"


# -- the experiment -------------------------------------------------------------------------------
@dataclass(frozen=True)
class PaperExperiment:
    """What the paper measured on its 20-ring chain, for one drop and one model.

    Attributes
    ----------
    model : str
    stiffness : {"table", "theory"}
        Source of the chain's stiffness (module notes).
    stiffness_note : str
        The same in words (:func:`stiffness_note`).
    drop_height : float
        m.
    impact_velocity : float
        sqrt(2 g h), m/s.
    sensors : tuple of int
        Rings holding the sensors, counted from the impact (ring 0 is the dropped ring).
    peak_forces : tuple of float
        Leading-pulse peak at each sensor, N (static tension included).
    arrival_times : tuple of float
        Leading-pulse peak times, s after the impact.
    time_of_flight : float
        Between the two sensors, s.
    wave_speed : float
        Sensor distance over time of flight, m/s.
    simulation : Simulation
    """

    model: str
    stiffness: str
    stiffness_note: str
    drop_height: float
    impact_velocity: float
    sensors: tuple
    peak_forces: tuple
    arrival_times: tuple
    time_of_flight: float
    wave_speed: float
    simulation: Simulation = field(repr=False)


def paper_experiment(
    drop_height, model="power-law", *, stiffness="table", t_end=2e-3, sensors=paper_data.SENSOR_RINGS, **options
) -> PaperExperiment:
    """Simulate the paper's drop experiment (Sec. III) and read its two sensors.

    The chain is :func:`paper_chain` for R/r = 9 (Table I: m_eff/m0 = 0.37), 20
    rings hanging under gravity from a fixed support, sensors in rings 6 and 12.

    Parameters
    ----------
    drop_height : float
        Free-fall height of the lowest ring, m (> 0).
    model : {"power-law", "dual-spring"}
    stiffness : {"table", "theory"}, optional
        Source of the stiffness, the same for both models (module notes): Table I's
        measured power law (default), or the ring's theory (Eqs. 1-4).
    t_end : float, optional
        Duration, s (default 2 ms: the leading pulse passes ring 12 within about 1 ms for
        drops of 1 mm and more).
    sensors : tuple of int, optional
        Two rings, near then far from the impact.
    **options
        Passed to :func:`~ringchain.numerics.simulate` (e.g. ``method``, ``rtol``);
        ``gamma``/``gamma_c``/``gamma_b`` and ``striker_mass`` are passed to :func:`paper_chain`.

    Returns
    -------
    PaperExperiment

    Raises
    ------
    ringchain.numerics.signals.PulseError
        If a sensor reads no complete pulse (e.g. ``t_end`` too short for ring 12).

    Examples
    --------
    >>> run = paper_experiment(0.05, "power-law")
    >>> run.stiffness, 10 < run.peak_forces[0] < 1000, 1e-4 < run.time_of_flight < 1e-3  # N, s
    ('table', True, True)
    """
    h = v.positive("drop_height", drop_height, "m")
    if h.ndim:
        raise ValueError(f"drop_height must be one height (m), got an array of shape {h.shape}")
    v.choice("model", model, MODELS)
    v.choice("stiffness", stiffness, STIFFNESS_SOURCES)
    dashpots = {k: options.pop(k) for k in ("gamma", "gamma_c", "gamma_b", "striker_mass") if k in options}
    chain = paper_chain(model, stiffness=stiffness, **dashpots)
    run = run_experiment(chain, drop_height=float(h), sensors=sensor_pair(sensors, paper_data.CHAIN_RINGS),
                         t_end=t_end, rings=None, **options)  # fmt: skip
    return PaperExperiment(
        model=model, stiffness=stiffness, stiffness_note=stiffness_note(model, stiffness),
        drop_height=float(h), impact_velocity=run.impact_velocity, sensors=run.sensors, peak_forces=run.peak_forces,
        arrival_times=run.arrival_times, time_of_flight=run.time_of_flight, wave_speed=run.wave_speed,
        simulation=run.simulation,
    )  # fmt: skip


def experiment_runs(drop_height=PAPER_DROP_HEIGHT, stiffness="table", **options) -> dict:
    """:func:`paper_experiment` of both models, as {model: PaperExperiment}, dual-spring first."""
    return {model: paper_experiment(drop_height, model, stiffness=stiffness, **options) for model in MODELS[::-1]}


# -- tables ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Table:
    """A titled table of strings; ``str(table)`` right-aligns its columns for a terminal."""

    title: str
    headers: tuple
    rows: tuple
    notes: tuple = ()

    def __str__(self) -> str:
        widths = [max(len(h), *(len(row[j]) for row in self.rows)) for j, h in enumerate(self.headers)]
        lines = [self.title, "  " + "  ".join(h.rjust(w) for h, w in zip(self.headers, widths, strict=True))]
        lines += ["  " + "  ".join(c.rjust(w) for c, w in zip(row, widths, strict=True)) for row in self.rows]
        lines += [f"  {note}" for note in self.notes]
        return "\n".join(lines) + "\n"


def _table(title, headers, rows, notes=()) -> Table:
    return Table(title, tuple(headers), tuple(tuple(str(c) for c in row) for row in rows), tuple(notes))


def _g(x, digits=4) -> str:
    return "-" if x is None else f"{float(x):.{digits}g}"


def _as_printed(x) -> str:
    """A value of the paper as it prints it (K = 2284, n = 1.418); '-' if it gives none."""
    return "-" if x is None else f"{x:g}"


def static_table() -> Table:
    """Static theory of one contact against R/r beside the paper's exponents (Sec. II and IV.A, Eqs. 1-4)."""
    from ringchain.theory import Ring, si_to_n_per_mm

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
            _g(si_to_n_per_mm(K, n=n)), f"{n:.3f}", _as_printed(K_paper), _as_printed(n_paper), source,
        ])  # fmt: skip
    return _table(
        "Static theory of one contact against R/r (paper Sec. II and IV.A, Eqs. 1-4); stainless steel, "
        "r = 2.5 mm, 90 deg",
        ["R/r", "K_c (N/m^1.5)", "K_b (N/m)", "F* (N)", "K (N/mm^n)", "n", "K paper", "n paper", "source"],
        rows,
        ["theory: power law F = K delta^n fitted to the series law (Eq. 3) over 1-100 N; "
         "paper: quasi-static tests (Table I) or Abaqus (Sec. IV.A)"],
    )  # fmt: skip


def angle_table() -> Table:
    """Exponent against contact angle beside Table II (Sec. IV.B, App. A).

    Each angle's contact from :func:`~ringchain.numerics.contact_at_angle`, the choice ``ringchain ring``
    makes too: the closed-form Hertz ellipse (App. A) where it stays within the half-space limit over
    the fit's window, the numerical contact of the exact torus gap (:func:`~ringchain.numerics.contact_curve`,
    two patches below arccos(1 - 2r/R), each in its tangent plane) elsewhere; in series with bending.
    """
    from ringchain.theory import STAINLESS_STEEL_304, Ring, minimum_contact_angle, si_to_n_per_mm

    from ..contact.angle import HERTZ, contact_at_angle
    from ..contact.bem import HALF_SPACE_LIMIT

    aspect = paper_data.TABLE_II_ASPECT_RATIO
    lowest = math.degrees(float(minimum_contact_angle(aspect, 1.0)))
    ring90 = Ring.from_aspect_ratio(aspect, r=paper_data.TUBE_RADIUS)
    steel = STAINLESS_STEEL_304
    rows, notes, handover = [], [], None
    for angle_deg, (K_paper, n_paper, _) in paper_data.TABLE_II.items():
        contact = contact_at_angle(ring90.R, ring90.r, steel.E, steel.nu, math.radians(angle_deg), K_b=ring90.K_b)
        handover = contact.handover
        crossover = ring90.K_b**3 / contact.K_c**2
        method = "Hertz" if contact.method == HERTZ else f"BEM, {contact.n_patches} patch" + (
            "es" if contact.n_patches > 1 else "")  # fmt: skip
        rows.append([
            f"{angle_deg:.0f}", method, f"{contact.K_c:.4e}", _g(crossover), _g(si_to_n_per_mm(contact.K, n=contact.n)),
            f"{contact.n:.3f}", f"{contact.extent_over_r:.3f}", _as_printed(K_paper), _as_printed(n_paper),
        ])  # fmt: skip
        if not contact.within_half_space:
            reach = f"the contact reaches {contact.extent_over_r:.2f} r at 100 N"
            within = f"within it up to {contact.limit_force:.3g} N"
            notes.append(f"{angle_deg:g} deg: {reach}, beyond the half-space limit {HALF_SPACE_LIMIT:g} r ({within})")
    above = "at no angle" if handover is None else f"above {math.degrees(handover):.2f} deg"
    return _table(
        f"Exponent against contact angle (paper Sec. IV.B, App. A), R/r = {aspect:g}",
        ["angle (deg)", "contact", "K_c (N/m^1.5)", "F* (N)", "K (N/mm^n)", "n", "contact/r", "K Table II",
         "n Table II"],
        rows,
        [*notes,
         f"contact: Hertz's ellipse (Eq. 1, App. A) where it stays within {HALF_SPACE_LIMIT:g} r up to 100 N ({above}; "
         f"a single contact exists above {lowest:.2f} deg = arccos(1 - 2r/R)), else the numerical contact of the exact "
         "torus gap (BEM, ringchain.numerics.contact_at_angle; two patches below arccos(1 - 2r/R), the paper's "
         "Abaqus regime); in series with bending, fitted over 1-100 N",
         "contact/r: largest half-length of the contact at 100 N over the tube radius",
         f"Table II's rings: R/r = {aspect:g} (paper_data.TABLE_II_ASPECT_RATIO; Sec. IV.B says R = 20 mm)"],
    )  # fmt: skip


def table_parameters():
    """(label, ring, (K in N/mm^n, n, m_eff/m0)) for each row of Tables I and II (Table II at 90 deg geometry)."""
    from ringchain.theory import Ring

    for aspect, values in paper_data.TABLE_I.items():
        yield f"Table I R/r = {aspect:g}", Ring.from_aspect_ratio(aspect, r=paper_data.TUBE_RADIUS), values
    ring = Ring.from_aspect_ratio(paper_data.TABLE_II_ASPECT_RATIO, r=paper_data.TUBE_RADIUS)
    for angle, values in paper_data.TABLE_II.items():
        yield f"Table II {angle:g} deg", ring, values


def speed_table(forces=PAPER_FORCES) -> Table:
    """V_s(F_m) (Eq. (8)) with the measured K, n and m_eff of every row of Tables I and II, at ``forces`` (N)."""
    from ringchain.theory import STAINLESS_STEEL_304, n_per_mm_to_si, solitary_wave_speed

    forces = np.atleast_1d(v.positive("forces", forces, "N"))
    rows = []
    for label, ring, (K_mm, n, ratio) in table_parameters():
        m = ratio * ring.mass
        V = solitary_wave_speed(forces, K=float(n_per_mm_to_si(K_mm, n=n)), n=n, m=m, a=ring.spacing)
        rows.append([
            label, _as_printed(K_mm), _as_printed(n), f"{m * 1e3:.2f}", f"{ring.spacing * 1e3:.1f}",
            *(_g(x) for x in V),
        ])  # fmt: skip
    return _table(
        "Solitary-wave speed V_s(F_m) (paper Eq. (8)) with the measured K, n and m_eff (Tables I and II)",
        ["row", "K (N/mm^n)", "n", "m_eff (g)", "a (mm)", *(f"V_s({F:g} N) (m/s)" for F in forces)],
        rows,
        [f"m_eff = (m_eff/m0) x ring mass (torus 2 pi^2 R r^2 of {STAINLESS_STEEL_304.name} steel, "
         f"{STAINLESS_STEEL_304.rho:g} kg/m^3); a = 2(R - r)"],
    )  # fmt: skip


def experiment_table(runs) -> Table:
    """The drop experiment (Sec. III) of both models: sensor peaks, arrivals, time of flight, speed, stiffness source.

    ``runs`` maps a model to its :class:`PaperExperiment` (:func:`experiment_runs`), all of one drop.
    """
    from ringchain.theory import n_per_mm_to_si, solitary_wave_speed

    runs = dict(runs)
    K_mm, n, ratio = paper_data.TABLE_I[9.0]
    first = next(iter(runs.values()))
    near, far = first.sensors
    rows, sources = [], []
    for model, run in runs.items():
        chain = run.simulation.chain
        V_s = float(
            solitary_wave_speed(run.peak_forces[0], K=float(n_per_mm_to_si(K_mm, n=n)), n=n, m=chain.m, a=chain.a)
        )
        rows.append([
            model, _g(run.peak_forces[0]), _g(run.peak_forces[1]), _g(run.arrival_times[0] * 1e3),
            _g(run.arrival_times[1] * 1e3), _g(run.time_of_flight * 1e3), _g(run.wave_speed), _g(V_s), run.stiffness,
        ])  # fmt: skip
        sources.append(f"stiffness of the {model} chain: {run.stiffness_note}")
    return _table(
        f"The paper's experiment (Sec. III): {paper_data.CHAIN_RINGS} rings of R/r = 9 hanging under gravity, "
        f"ring 0 dropped from h = {first.drop_height:g} m (impact at {first.impact_velocity:.3g} m/s); "
        f"m_eff/m0 = {ratio:g} (Table I)",
        ["model", f"F ring {near} (N)", f"F ring {far} (N)", f"t ring {near} (ms)", f"t ring {far} (ms)",
         "time of flight (ms)", "speed (m/s)", "V_s Eq. (8) (m/s)", "stiffness"],
        rows,
        [f"F, t: peak and arrival of the leading pulse at the ring's sensor; speed = {far - near} a / time of flight; "
         f"V_s at ring {near}'s peak force with Table I's power law (K = {K_mm:g} N/mm^n, n = {n:g})",
         *sources,
         "paper: arrival at the downstream sensor printed as 0.426 (low) and 0.348 (high amplitude), unit 's'"],
    )  # fmt: skip


# -- figures ----------------------------------------------------------------------------------------------
def write_figures(out, runs) -> list[Path]:
    """Write the paper's figures as PNG files into the folder ``out`` (created if needed); returns their paths.

    ``runs`` maps a model to its :class:`PaperExperiment` (for the sensor traces).
    """
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

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
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
    _, n = fit_power_law(K_c=K_c, K_b=K_b)
    fig = new_figure(figsize=(5, 3.6))
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
    _, n = fit_power_law(K_c=K_c, K_b=bending_stiffness(R, r, steel.E, steel.nu))
    fig = new_figure(figsize=(5, 3.6))
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
    fig = new_figure(figsize=(5, 3.6))
    ax = fig.add_subplot()
    for k, a_r in enumerate(PAPER_ASPECT_RATIOS):
        R = a_r * r
        K_c, K_b = hertz_stiffness(R, r, steel.E, steel.nu), bending_stiffness(R, r, steel.E, steel.nu)
        K, n = fit_power_law(K_c=K_c, K_b=K_b)
        color = f"C{k}"
        ax.plot(series_displacement(F, K_c=K_c, K_b=K_b) * 1e6, F, color=color, label=f"R/r = {a_r:g}")
        ax.plot((F / K) ** (1.0 / n) * 1e6, F, "--", color=color)
    ax.set(xscale="log", yscale="log", xlabel="extension delta (um)", ylabel="force F (N)",
           title="Series law (solid) and fitted power law (dashed)")  # fmt: skip
    ax.legend(fontsize="small")
    save(fig, "force_extension.png")

    # V_s against F_m (Eq. (8), Fig. 4).
    F_m = np.geomspace(0.5, 300.0, 100)
    fig = new_figure(figsize=(8, 3.6))
    axes = fig.subplots(1, 2, sharey=True)
    for label, ring, (K_mm, n, ratio) in table_parameters():
        ax = axes[0] if label.startswith("Table I ") else axes[1]
        V = solitary_wave_speed(F_m, K=float(n_per_mm_to_si(K_mm, n=n)), n=n, m=ratio * ring.mass, a=ring.spacing)
        ax.plot(F_m, V, label=label.split(" ", 2)[2])
    for ax, title in zip(axes, ("Table I: aspect ratio", "Table II: contact angle"), strict=True):
        ax.set(xscale="log", xlabel="peak force F_m (N)", title=title)
        ax.legend()
    axes[0].set_ylabel("solitary-wave speed V_s (m/s)")
    save(fig, "wave_speed_vs_force.png")

    # Sensor traces of the experiment (Sec. III, Fig. 1 d-e).
    fig = new_figure(figsize=(8, 3.6))
    axes = fig.subplots(1, len(runs), sharey=True, squeeze=False)[0]
    for ax, (model, run) in zip(axes, runs.items(), strict=True):
        sim = run.simulation
        for ring_index in run.sensors:
            ax.plot(sim.t * 1e3, sim.sensor(ring_index), label=f"ring {ring_index}")
        ax.set(xlabel="time after impact (ms)", title=f"{model}, h = {run.drop_height:g} m, {run.stiffness}")
        ax.legend(loc="upper right")
    axes[0].set_ylabel("sensor force (N)")
    save(fig, "experiment_sensor_forces.png")
    return written


# -- the whole job ----------------------------------------------------------------------------------------
def paper_job(drop_height=PAPER_DROP_HEIGHT, out=PAPER_FIGURES, stiffness="table") -> tuple[list[Table], list[Path]]:
    """Everything ``ringchain paper`` shows: its tables, and the figures written to the folder ``out``.

    Parameters
    ----------
    drop_height : float, optional
        Drop height of the experiment, m (> 0).
    out : str or path, optional
        Folder for the figures (created if needed).
    stiffness : {"table", "theory"}, optional
        Source of the stiffness of both lattice models (module notes).

    Returns
    -------
    tables : list of Table
        Static theory against R/r, exponent against angle, V_s(F_m), the experiment.
    figures : list of Path
    """
    h = v.positive("drop_height", drop_height, "m")
    v.choice("stiffness", stiffness, STIFFNESS_SOURCES)
    Path(out).mkdir(parents=True, exist_ok=True)  # a folder that cannot be made fails before the work
    tables = [static_table(), angle_table(), speed_table()]
    runs = experiment_runs(float(h), stiffness)
    tables.append(experiment_table(runs))
    return tables, write_figures(out, runs)
