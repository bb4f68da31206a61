"""Parameter sweeps: grids of chains and impacts, run through any executor, one CSV row per point.

A sweep point (:class:`Point`) is one ring geometry (R/r, tube radius, contact angle,
material), one lattice model, one chain length and, optionally, one impact (a drop
height or an impact velocity).  For each point :func:`sweep` reports the static theory
of the contact (K_c, K_b, crossover force, fitted power law, paper Eqs. 1-4) and, when
there is an impact, what the paper measured on its chain (Sec. III.A): the peak forces
at two sensor rings, their arrival times, the time of flight and wave speed, beside the
solitary-wave speed of Eq. (8) at the measured peak force.

Scale.  Points that share a chain (everything but the impact) are integrated together
by :func:`~ringchain.numerics.simulate_batch`, in chunks of ``batch_size`` runs, each run
with its own steps on every core, and the sensors of a chunk's runs are read together
(:func:`~ringchain.numerics.signals.peak` on the batch's traces); benchmarks/bench_sweep.py
measures a sweep of 10^4 drop heights.  The chunks are independent tasks submitted to a
:class:`concurrent.futures.Executor`: by default this process, or local processes when
they would save more than they cost to start, or a Dask cluster without any code change::

    from distributed import Client
    rows = sweep(grid, executor=Client("tcp://scheduler:8786").get_executor())

Cost.  Each task records only its two sensor rings, and every task's work (the expected steps x
sites x runs) is estimated before the first one starts: a sweep with a task longer than
``max_seconds`` is refused with the estimate (:func:`estimate_task`).  The default
duration (:func:`default_t_end`) stays finite as n -> 1.

Determinism.  The grid fixes the chunks (in grid order, independent of the executor and
of the number of workers) and the rows come back in grid order, so the same grid gives
the same rows, and the same CSV, whatever runs it.
"""

from __future__ import annotations

import concurrent.futures as cf
import csv
import functools
import io
import itertools
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, fields

import numpy as np
from ringchain.theory import PAPER_TUBE_RADIUS, Ring, impact_speed, paper_data
from ringchain.theory import _validate as v

from ..engine import signals
from ..engine._files import write_text
from ..engine.executors import InlineExecutor, run_tasks
from ..engine.integrate import DEFAULT_MAX_SECONDS, RunTooLargeError, estimate_run, format_duration, simulate_batch
from ..layouts.chain import MODELS, Chain, default_t_end, sensor_pair, striker_convention
from ..layouts.chain_file import ChainFile, vary
from .experiment import MAX_DOUBLINGS

__all__ = [
    "Point",
    "FilePoint",
    "sweep_chain_file",
    "DYNAMIC_COLUMNS",
    "AXES",
    "expand",
    "sweep",
    "run_points",
    "write_csv",
    "estimate_task",
    "InlineExecutor",
    "DEFAULT_BATCH_SIZE",
    "DEFAULT_SAMPLES",
    "SWEEP_METHOD",
    "SWEEP_RTOL",
    "PYTHON_SECONDS_PER_POINT",
]

#: Runs integrated together in one task (one :func:`simulate_batch` call).
DEFAULT_BATCH_SIZE = 64

#: Samples of each force record (evenly spaced over the duration).  Peak forces and
#: times of flight read from 1001 samples differ from 8001 by < 1e-4 relative on the
#: paper's chain.
DEFAULT_SAMPLES = 1001

#: Seconds of Python a point costs in the process that runs it (its row, its share of making its batch's model and
#: of reading the batch's sensors), on one core: 0.45 ms measured on a sweep of 2048 drop heights with the load
#: average at 6.4 on two cores (benchmarks/bench_sweep.py prints it).  The compiled kernels use every core from one
#: process, so this is all a pool of processes could spread: :func:`sweep` given no executor runs in the calling
#: process unless that saves more than the pool costs to start (10^4 points: about 2 s against 2.5 s or more).
PYTHON_SECONDS_PER_POINT = 4.5e-4

#: Integrator of the sweeps: the compiled Dormand-Prince pair, each run of a batch with its own
#: steps (the runs in parallel over the cores), at :data:`SWEEP_RTOL`.  (The NumPy Verlet of
#: earlier versions was chosen because a batch of B runs cost far less than B runs there; compiled,
#: a run costs the same in a batch or alone, and the adaptive pair is 10x more accurate for the
#: same work: benchmarks/bench_kernels.py.)
SWEEP_METHOD = "dopri5"

#: Relative tolerance of :data:`SWEEP_METHOD` in sweeps: sensor forces within 1-4e-4 of the peak
#: against a tight reference on the paper's chain (drops of 1 and 30 cm), where the fixed-step
#: Verlet of earlier sweeps was within 2-4e-3; the default 3e-10 of :func:`simulate` costs 3.4x
#: the steps for digits a sweep's peak forces and times of flight do not show.
SWEEP_RTOL = 1e-7


@dataclass(frozen=True)
class Point:
    """One point of a sweep: a chain of identical rings and, optionally, one impact.

    Parameters
    ----------
    R_over_r : float
        Aspect ratio R/r of the rings; >= 3 for a chain (and > 2 for one contact).
    r : float
        Tube radius, m (default the paper's 2.5 mm).
    angle : float
        Contact angle between adjacent ring planes, rad (default pi/2, Table I).
    material : str
        Material preset key (:data:`ringchain.theory.MATERIALS`).
    model : {"dual-spring", "power-law"}
        Lattice model (paper Sec. III.B); the power-law chain takes K and n fitted to the
        series law of the ring (Eq. 4).
    n_rings : int
        Rings in the chain, ring 0 at the impact end, hanging from a fixed support.
    m_eff_ratio : float
        Inertial mass over ring mass, m_eff/m0 in (0, 1] (the paper fits 0.33-0.37,
        Tables I-II); gravity acts on the full mass m0.
    drop_height : float, optional
        Free-fall height of ring 0, m (> 0).
    impact_velocity : float, optional
        Speed of ring 0 at impact, m/s (> 0); give this or ``drop_height``, or neither
        for the static theory only.
    sensors : tuple of int
        Two sensor rings counted from the impact, near first (default rings 6 and 12).
    striker_mass : {"m_eff", "m0"} or float
        Inertial mass of the struck ring 0 (:class:`~ringchain.numerics.Chain`): the lattice's
        m_eff (default, the paper's convention), the ring's mass m0 (a rigid ring in free
        fall), or a mass in kg.  The row says which (``striker_mass``) and how much
        (``striker_mass_kg``).

    Examples
    --------
    >>> point = Point(R_over_r=9.0, drop_height=0.05)
    >>> round(point.ring.R * 1e3, 2), point.dynamic
    (22.5, True)
    """

    R_over_r: float = 9.0
    r: float = PAPER_TUBE_RADIUS
    angle: float = math.pi / 2
    material: str = "stainless"
    model: str = "dual-spring"
    n_rings: int = paper_data.CHAIN_RINGS
    m_eff_ratio: float = 1.0
    drop_height: float | None = None
    impact_velocity: float | None = None
    sensors: tuple = paper_data.SENSOR_RINGS
    striker_mass: str | float = "m_eff"

    def __post_init__(self):
        set_ = functools.partial(object.__setattr__, self)
        chain = ("striker_mass", "R_over_r", "r", "angle", "m_eff_ratio", "model", "n_rings")
        for name, value in zip(chain, _memo(_checked_chain, *(getattr(self, name) for name in chain)), strict=True):
            set_(name, value)
        if self.drop_height is not None and self.impact_velocity is not None:
            raise ValueError("give a drop height or an impact velocity, not both")
        for name, unit in (("drop_height", "m"), ("impact_velocity", "m/s")):
            value = getattr(self, name)
            if isinstance(value, bool | np.bool_):
                raise ValueError(f"{name.replace('_', ' ')} must be a number (in {unit}), got {value!r}")
            if value is not None:
                set_(name, float(v.positive(name.replace("_", " "), value, unit)))
        set_("sensors", _memo(_checked_sensors, self.sensors, self.R_over_r, self.r, self.material, self.angle,
                              self.n_rings, self.dynamic))  # fmt: skip

    @property
    def ring(self) -> Ring:
        """The ring of this point (R = R/r x r)."""
        return _ring(self.R_over_r, self.r, self.material, self.angle)

    @property
    def dynamic(self) -> bool:
        """Whether the point has an impact to simulate."""
        return self.drop_height is not None or self.impact_velocity is not None

    def chain(self) -> Chain:
        """The hanging chain of this point (:meth:`Chain.from_ring`)."""
        return Chain.from_ring(self.ring, self.n_rings, self.model, m_eff_ratio=self.m_eff_ratio,
                               striker_mass=self.striker_mass)  # fmt: skip

    @property
    def speed(self) -> float | None:
        """Impact speed of ring 0, m/s: sqrt(2 g h) for a drop."""
        if self.drop_height is not None:
            return float(impact_speed(self.drop_height))
        return self.impact_velocity

    @property
    def chain_key(self) -> tuple:
        """What the points integrated together share: all but the impact's size."""
        kind = "drop" if self.drop_height is not None else "velocity" if self.impact_velocity is not None else None
        return (*(getattr(self, name) for name in _CHAIN_FIELDS), kind)

    def columns(self) -> dict:
        """The row's columns before the run: the point and the static theory of its contact (Eqs. 1-4)."""
        return self._columns(self.speed)

    def _columns(self, speed) -> dict:
        """:meth:`columns`, the impact speed (m/s) given."""
        ring = self.ring
        return {
            "R_over_r": self.R_over_r,
            "R_m": ring.R,
            "r_m": ring.r,
            "angle_rad": self.angle,
            "angle_deg": round(math.degrees(self.angle), 9),  # 60, not 59.99999999999999 (radians(60) rounds)
            "material": ring.material.name,
            "model": self.model,
            "n_rings": self.n_rings,
            "m_eff_ratio": self.m_eff_ratio,
            **_striker_columns(self.striker_mass, self.m_eff_ratio * ring.mass, ring.mass),
            "drop_height_m": self.drop_height,
            "impact_velocity_m_s": speed,
            **_contact_theory(ring),
        }


# A grid's points share their chain: its fields are checked once per chain, not once per point (a tenth of a
# millisecond each, a second of a sweep of 10^4 drop heights).
def _memo(check, *values):
    """``check(*values)`` through its cache, keyed on the values and their types (1 and True, 20 and 20.0 are
    checked apart); values that cannot be hashed (a list of sensors) are checked without it."""
    try:
        return check(*((type(x), x) for x in values))
    except TypeError as exc:
        if "unhashable" not in str(exc):
            raise
        return check.__wrapped__(*((type(x), x) for x in values))


@functools.lru_cache(maxsize=1024)
def _checked_chain(*typed) -> tuple:
    """The chain's fields of a :class:`Point` (striker, R/r, r, angle, m_eff/m0, model, ring count), checked."""
    striker, R_over_r, r, angle, m_eff_ratio, model, n_rings = (x for _, x in typed)
    return (striker_convention(striker), float(v.positive("R/r", R_over_r)), float(v.positive("r", r, "m")),
            float(v.as_float("angle", angle)), float(v.in_range("m_eff_ratio", m_eff_ratio, 0.0, 1.0)),
            v.choice("model", str(model), MODELS), v.count("n_rings", n_rings, 2))  # fmt: skip


@functools.lru_cache(maxsize=1024)
def _checked_sensors(*typed) -> tuple:
    """A :class:`Point`'s sensors, checked with its ring (R > 2 r, the angle, the material: errors that say why) and,
    with an impact, against its chain."""
    sensors, R_over_r, r, material, angle, n_rings, dynamic = (x for _, x in typed)
    sensors = sensor_pair(sensors)
    ring = _ring(R_over_r, r, material, angle)
    if dynamic:
        ring.check_chain()
        sensor_pair(sensors, n_rings)
    return sensors


# The points of a sweep share a few rings: each ring and the static theory of its contact (Eqs. 1-4, a fit of
# the power law among them) are made once, not once per point (a fifth of a sweep of drop heights).
@functools.lru_cache(maxsize=1024)
def _ring(R_over_r, r, material, angle) -> Ring:
    return Ring.from_aspect_ratio(R_over_r, r=r, material=material, angle=angle)


@functools.lru_cache(maxsize=1024)
def _contact_theory(ring: Ring) -> dict:
    """The columns of the static theory of ``ring``'s contact (:meth:`Point.columns`); a copy is not needed: the
    caller unpacks it into its own row."""
    K, n = ring.power_law()
    return {"ring_mass_kg": ring.mass, "spacing_m": ring.spacing, "K_c_N_m1.5": ring.K_c, "K_b_N_m": ring.K_b,
            "crossover_force_N": ring.crossover_force, "K_fit_N_mn": K, "n_fit": n}  # fmt: skip


@functools.lru_cache(maxsize=1024)
def _fitted_power_law(K_c: float, K_b: float) -> tuple[float, float]:
    """The power law fitted to a dual-spring chain's springs (Eq. 4), once per chain of a sweep."""
    from ringchain.theory import fit_power_law

    return tuple(float(x) for x in fit_power_law(K_c=K_c, K_b=K_b))


@dataclass(frozen=True)
class FilePoint:
    """One point of a sweep of a chain file: the chain of a :class:`~ringchain.numerics.layouts.chain_file.ChainFile`
    (one field varied, :func:`~ringchain.numerics.layouts.chain_file.vary`) and one impact.

    Parameters
    ----------
    description : ChainFile
    field : str or None
        The varied field (``"2.R.last"``...), or None for the description as it is.
    value : float or None
        Its value (m, degrees or a ring count).
    model : {"dual-spring", "power-law"}
    m_eff_ratio : float
    drop_height, impact_velocity : float, optional
        The impact (m, or m/s).
    sensors : (int, int)
    striker_mass : {"m_eff", "m0"} or float
        As in :class:`Point` (``"m0"``: the mass of ring 0 of the chain).
    """

    description: ChainFile
    field: str | None = None
    value: float | None = None
    model: str = "dual-spring"
    m_eff_ratio: float = 1.0
    drop_height: float | None = None
    impact_velocity: float | None = None
    sensors: tuple = paper_data.SENSOR_RINGS
    striker_mass: str | float = "m_eff"

    dynamic = True

    def __post_init__(self):
        object.__setattr__(self, "striker_mass", striker_convention(self.striker_mass))

    @functools.cached_property
    def varied(self) -> ChainFile:
        return self.description if self.field is None else vary(self.description, self.field, self.value)

    def chain(self) -> Chain:
        chain = self.varied.chain(self.model, self.m_eff_ratio, striker_mass=self.striker_mass)
        sensor_pair(self.sensors, chain.n_rings)
        return chain

    @property
    def speed(self) -> float:
        return float(impact_speed(self.drop_height)) if self.drop_height is not None else self.impact_velocity

    @property
    def chain_key(self) -> tuple:
        kind = "drop" if self.drop_height is not None else "velocity"
        return (self.description, self.field, self.value, self.model, self.m_eff_ratio, self.sensors,
                self.striker_mass, kind)  # fmt: skip

    def columns(self) -> dict:
        return self._columns(self.speed)

    def _columns(self, speed) -> dict:
        row = {} if self.field is None else {self.field: self.value}
        m0 = self.varied.rings()[0].mass  # ring 0, the struck ring
        row |= {"n_rings": self.varied.n_rings, "model": self.model, "m_eff_ratio": self.m_eff_ratio,
                **_striker_columns(self.striker_mass, self.m_eff_ratio * m0, m0),
                "impact_velocity_m_s": speed}  # fmt: skip
        if self.drop_height is not None:
            row["drop_height_m"] = self.drop_height
        return row


def _striker_columns(striker, m_eff: float, m0: float) -> dict:
    """The striker's columns of a row: its convention ("m_eff", "m0", or "kg" for a given mass) and its mass, kg."""
    mass = {"m_eff": m_eff, "m0": m0}.get(striker, striker)
    return {"striker_mass": striker if isinstance(striker, str) else "kg", "striker_mass_kg": mass}


_IMPACT = ("drop_height", "impact_velocity")
_CHAIN_FIELDS = tuple(f.name for f in fields(Point) if f.name not in _IMPACT)

#: Names a grid may vary (the fields of :class:`Point`).
AXES = tuple(f.name for f in fields(Point))


def expand(grid) -> list[Point]:
    """The points of a grid, in a fixed order.

    Parameters
    ----------
    grid : mapping or iterable
        A mapping from axis names (:data:`AXES`) to a value or a sequence of values: the
        Cartesian product, the last axis varying fastest (axes in the mapping's order);
        or an iterable of :class:`Point` s or of mappings, one per point.

    Returns
    -------
    list of Point

    Examples
    --------
    >>> points = expand({"R_over_r": [6.0, 9.0], "drop_height": [0.01, 0.05]})
    >>> [(p.R_over_r, p.drop_height) for p in points]
    [(6.0, 0.01), (6.0, 0.05), (9.0, 0.01), (9.0, 0.05)]
    """
    if isinstance(grid, Mapping):
        _check_axes(grid)
        names = list(grid)
        values = [_values(name, grid[name]) for name in names]
        return [Point(**dict(zip(names, combo, strict=True))) for combo in itertools.product(*values)]
    if isinstance(grid, str) or not isinstance(grid, Iterable):
        raise TypeError(f"a grid is a mapping of axes or an iterable of points, got {grid!r}")
    points = []
    for item in grid:
        if isinstance(item, Point | FilePoint):
            points.append(item)
        elif isinstance(item, Mapping):
            _check_axes(item)
            points.append(Point(**item))
        else:
            raise TypeError(f"a grid is a mapping of axes or an iterable of points, got an item {item!r}")
    return points


def _check_axes(mapping):
    unknown = [name for name in mapping if name not in AXES]
    if unknown:
        raise ValueError(f"unknown sweep axis {unknown[0]!r}; axes: {', '.join(AXES)}")


def _values(name, value) -> list:
    if name == "sensors":  # a pair is one value, a list of pairs several
        return list(value) if np.ndim(value) == 2 else [value]
    if isinstance(value, str) or np.ndim(value) == 0:
        return [value]
    values = list(value)
    if not values:
        raise ValueError(f"axis {name!r} has no values")
    return values


# -- running -------------------------------------------------------------------------------------
#: Columns a point with an impact adds to its row (:func:`run_points`), in order; units in the names.
DYNAMIC_COLUMNS = (
    "sensor_near", "sensor_far", "peak_force_near_N", "peak_force_far_N", "arrival_near_s", "arrival_far_s",
    "time_of_flight_s", "wave_speed_m_s", "V_s_theory_m_s", "support_peak_N", "t_end_s",
)  # fmt: skip


def _dynamics(sensors, runs) -> list[dict]:
    """The :data:`DYNAMIC_COLUMNS` of each run of a batch: the sensors read as the paper reads them (Sec. III.A),
    every run's at once (:func:`~ringchain.numerics.signals.peak` on the batch's traces), Eq. (8) at the near
    sensor's peak force (a uniform chain: its power law, or for the dual-spring chain the one fitted to its
    springs, Eq. 4), the largest force on the support."""
    from ringchain.theory import solitary_wave_speed

    near, far = sensors
    chain = runs.chain
    F_near = runs.peak_force(near)
    V_s = None
    if chain.uniform:
        K, n = (chain.K, chain.n) if chain.model == "power-law" else _fitted_power_law(chain.K_c, chain.K_b)
        V_s = solitary_wave_speed(F_near, K=K, n=n, a=chain.a, m=chain.m)
    support = runs.support_force
    columns = (F_near, runs.peak_force(far), runs.arrival_time(near), runs.arrival_time(far),
               runs.time_of_flight(near, far), runs.wave_speed(near, far), V_s,
               None if support is None else np.max(support, axis=-1))  # fmt: skip
    t_end = float(runs.t[-1])
    return [dict(zip(DYNAMIC_COLUMNS, (near, far, *(None if c is None else float(c[b]) for c in columns), t_end),
                     strict=True)) for b in range(len(runs))]  # fmt: skip


def _speeds(points) -> list:
    """The impact speed of each point (m/s; None for a static point), drop heights made speeds in one call
    (:func:`~ringchain.theory.impact_speed`: the points of a task share their kind of impact)."""
    heights = [p.drop_height for p in points]
    if any(h is None for h in heights):
        return [p.speed for p in points]
    return [float(u) for u in impact_speed(np.array(heights))]


def _batch(points, speeds, t_end, n_samples, method, solver):
    """The chain of points that share one, its duration and the arguments of :func:`simulate_batch`."""
    first = points[0]
    chain = first.chain()
    if t_end is None:
        t_end = default_t_end(chain, speeds, first.sensors)
    if first.drop_height is not None:
        impact = {"drop_heights": [p.drop_height for p in points]}
    else:
        impact = {"impact_velocities": speeds}
    rings = (*first.sensors, chain.n_rings - 1)  # the sensors and the top ring (the support's force)
    if method == SWEEP_METHOD and solver.get("rtol") is None:
        solver = dict(solver, rtol=SWEEP_RTOL)
    return chain, t_end, dict(impact, n_samples=n_samples, method=method, rings=rings, **solver)


def run_points(points, *, t_end=None, n_samples=DEFAULT_SAMPLES, method=SWEEP_METHOD, **solver):
    """Rows of points that share a chain (one task of :func:`sweep`): one batch, one row each.

    Every point (:class:`Point` or :class:`FilePoint`) must have the same ``chain_key``.  ``t_end`` (s) defaults to
    :func:`default_t_end` at the smallest impact of the points, doubled (up to
    four times) while a leading pulse has not passed the far sensor by the end; a
    ``t_end`` given that is too short raises
    :class:`~ringchain.numerics.signals.TruncatedPulseError`.  Only what the two sensors and
    the support need is recorded.  ``n_samples``, ``method`` and ``solver`` (e.g. ``dt``, ``rtol``,
    ``max_seconds``) go to :func:`~ringchain.numerics.simulate_batch`.
    """
    points = list(points)
    keys = {p.chain_key for p in points}
    if len(keys) != 1:
        raise ValueError("run_points takes points that share one chain")
    speeds = _speeds(points)
    rows = [p._columns(speed) for p, speed in zip(points, speeds, strict=True)]
    first = points[0]
    if not first.dynamic:
        return rows
    retries = 0 if t_end is not None else MAX_DOUBLINGS
    chain, t_end, arguments = _batch(points, speeds, t_end, n_samples, method, solver)
    while True:
        runs = simulate_batch(chain, t_end, **arguments)
        try:
            runs.peak_force(first.sensors[1])  # every run's far pulse, read once (the rows use it)
            break
        except (signals.TruncatedPulseError, signals.NoPulseError) as exc:
            # An impact always sends a pulse: none at the far sensor means it has not got there yet.
            if retries == 0:
                raise signals.TruncatedPulseError(
                    f"the pulse is still passing ring {first.sensors[1]} at t_end = {t_end:g} s; give a longer t_end "
                    f"({exc})"
                ) from None
        retries -= 1
        t_end *= 2.0
    for row, dynamics in zip(rows, _dynamics(first.sensors, runs), strict=True):
        row.update(dynamics)
    return rows


def estimate_task(points, *, t_end=None, n_samples=DEFAULT_SAMPLES, method=SWEEP_METHOD, **solver):
    """:class:`~ringchain.numerics.RunEstimate` of :func:`run_points` on ``points`` (None if static).

    The first attempt only: a default duration doubled by :func:`run_points` doubles the work.
    """
    points = list(points)
    if not points[0].dynamic:
        return None
    chain, t_end, arguments = _batch(points, _speeds(points), t_end, n_samples, method, solver)
    for option in ("max_memory", "max_seconds", "max_energy_drift"):
        arguments.pop(option, None)
    return estimate_run(chain, t_end, **arguments)


def sweep(
    grid,
    executor: cf.Executor | None = None,
    *,
    batch_size: int = DEFAULT_BATCH_SIZE,
    max_workers: int | None = None,
    progress: bool = False,
    t_end: float | None = None,
    n_samples: int = DEFAULT_SAMPLES,
    method: str = SWEEP_METHOD,
    max_seconds: float | None = DEFAULT_MAX_SECONDS,
    **solver,
) -> list[dict]:
    """Run every point of a grid and return one row (a dict) per point, in grid order.

    Parameters
    ----------
    grid : mapping or iterable
        Axes and values, or points (see :func:`expand`; :class:`FilePoint` s too).
    executor : concurrent.futures.Executor, optional
        Where the tasks run: any Executor, e.g. a Dask ``Client(...).get_executor()``.
        Default: this process, or a pool of local processes (shut down at the end) when it
        would save more than it costs to start (:data:`PYTHON_SECONDS_PER_POINT`); one line
        on stderr says which.
    batch_size : int, optional
        Most runs of one chain integrated together in one task.  Part of the grid's
        definition: it fixes the chunks, so changing it may change the last digits.
    max_workers : int, optional
        Processes of the default pool (the number of CPUs: given, the pool is used); 0 runs
        every task in this process (:class:`InlineExecutor`).  The pool starts its workers with
        "spawn", which imports a calling script again in every worker: in a script, call
        :func:`sweep` under ``if __name__ == "__main__":`` (a call outside it raises
        ``RuntimeError`` before any worker starts; see
        :mod:`ringchain.numerics.engine.executors`).
    progress : bool, optional
        Show a tqdm progress bar (on stderr).
    t_end : float, optional
        Duration of every run, s (default per task, :func:`default_t_end`).
    n_samples, method, **solver
        Passed to :func:`~ringchain.numerics.simulate_batch` (default: 1001 samples,
        fixed-step Verlet with the step it picks for the fastest run of each task).
    max_seconds : float, optional
        Longest rough duration of one task (:func:`estimate_task`), s; the work of every
        task is estimated before any starts, and a sweep with a longer task is refused
        with :class:`~ringchain.numerics.RunTooLargeError` giving the estimate.  None: no
        limit.

    Returns
    -------
    list of dict
        Columns with units in their names: the point, the static theory (K_c, K_b,
        crossover force, fitted K and n of Eq. 4) and, for a point with an impact, the
        sensor readings and V_s of Eq. (8) at the near sensor's peak force.

    Examples
    --------
    >>> rows = sweep({"R_over_r": [6.0, 9.0]}, InlineExecutor())  # static theory only
    >>> [round(row["n_fit"], 3) for row in rows]
    [1.225, 1.107]
    """
    try:
        batch_size = v.count("batch_size", batch_size, 1)
    except ValueError:
        raise ValueError(f"batch_size must be a positive integer, got {batch_size!r}") from None
    progress = v.flag("progress", progress)
    if t_end is not None:
        t_end = float(v.positive("t_end", t_end, "s"))
    points = expand(grid)
    groups: dict[tuple, list[int]] = {}
    for i, point in enumerate(points):
        groups.setdefault(point.chain_key, []).append(i)
    tasks = [idx[k : k + batch_size] for idx in groups.values() for k in range(0, len(idx), batch_size)]
    options = {"t_end": t_end, "n_samples": n_samples, "method": method, "max_seconds": max_seconds, **solver}
    seconds = _check_work([[points[i] for i in task] for task in tasks], options)
    serial = PYTHON_SECONDS_PER_POINT * len(points)  # all a pool could spread: the kernels use every core here
    results = run_tasks(run_points, [([points[i] for i in task],) for task in tasks], executor, options=options,
                        max_workers=max_workers, progress=progress, sizes=[len(task) for task in tasks], name="sweep",
                        unit="point", seconds=serial + (seconds or 0.0), serial=serial)  # fmt: skip
    rows: list[dict | None] = [None] * len(points)
    for task, result in zip(tasks, results, strict=True):
        for i, row in zip(task, result, strict=True):
            rows[i] = row
    return rows


def _check_work(tasks, options) -> float | None:
    """Estimate every task before any starts; refuse the sweep if one would take longer than max_seconds.
    Returns the estimated work of all tasks, s (None when not estimated: no max_seconds)."""
    limit = options["max_seconds"]
    if limit is None:
        return None
    limit = float(v.positive("max_seconds", limit, "s"))
    worst, total = None, 0.0
    for points in tasks:
        estimate = estimate_task(points, **options)
        if estimate is None or estimate.seconds is None:
            continue
        total += estimate.seconds
        if worst is None or estimate.seconds > worst[1].seconds:
            worst = (points[0], estimate)
    if worst is not None and worst[1].seconds > limit:
        point, estimate = worst
        raise RunTooLargeError(
            f"the sweep's largest task ({_described(point)}) would take roughly {format_duration(estimate.seconds)}: "
            f"{estimate.describe()}; all {len(tasks)} tasks about {format_duration(total)}; more than max_seconds = "
            f"{limit:g} s. Give a shorter t_end or a larger dt, drop the point, or raise max_seconds"
        )
    return total if worst is not None else None


def write_csv(rows: Iterable[dict], file=None) -> str | None:
    """Write rows as CSV: the union of their columns in first-seen order, floats exactly.

    Floats are written as Python's shortest repr (they read back to the same double), so
    equal rows give byte-identical files.

    Parameters
    ----------
    rows : iterable of dict
    file : str, path or text file, optional
        Where to write; default: return the CSV text.
    """
    rows = list(rows)
    columns: dict[str, None] = {}
    for row in rows:
        columns.update(dict.fromkeys(row))
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(columns)
    for row in rows:
        writer.writerow([_cell(row.get(c)) for c in columns])
    text = buffer.getvalue()
    if file is None:
        return text
    if hasattr(file, "write"):
        file.write(text)
    else:
        write_text(file, text)  # whole or not at all
    return None


def _cell(value) -> str:
    if value is None:
        return ""
    if isinstance(value, float | np.floating):
        return repr(float(value))
    if isinstance(value, np.integer):
        return str(int(value))
    return str(value)


def sweep_chain_file(description: ChainFile, field=None, values=(None,), *, model="dual-spring", m_eff_ratio=1.0,
                     drop_heights=None, impact_velocities=None, sensors=paper_data.SENSOR_RINGS, executor=None,
                     striker_mass="m_eff", **options) -> list[dict]:  # fmt: skip
    """One row per value of ``field`` (:func:`~ringchain.numerics.layouts.chain_file.vary`) and impact, through
    :func:`sweep`.

    Parameters
    ----------
    description : ChainFile
    field : str, optional
        The varied field (``"2.R.last"``...); None runs ``description`` as it is.
    values : sequence
        Its values (m, degrees or ring counts).
    model, m_eff_ratio, striker_mass
        As in :meth:`~ringchain.numerics.layouts.chain_file.ChainFile.chain`.
    drop_heights, impact_velocities : sequence of float
        The impacts (m, or m/s), integrated together as one batch per chain.
    sensors : (int, int)
        Near and far sensor rings.
    executor : concurrent.futures.Executor, optional
        As in :func:`sweep` (default: local processes).
    **options
        Passed to :func:`sweep` (``t_end``, ``n_samples``, ``method``, ``max_workers``...).

    Returns
    -------
    list of dict
        Columns: the varied field's value, the chain's length, model, m_eff/m0 and striker, the impact, and the
        :data:`DYNAMIC_COLUMNS` (Eq. (8) only for a chain that does not change along its length).
    """
    if (drop_heights is None) == (impact_velocities is None):
        raise ValueError("give drop_heights or impact_velocities")
    impacts = [{"drop_height": h} for h in drop_heights] if drop_heights is not None else [
        {"impact_velocity": u} for u in impact_velocities]  # fmt: skip
    points = [FilePoint(description, field, value, model, m_eff_ratio, sensors=tuple(sensors),
                        striker_mass=striker_mass, **impact)
              for value in values for impact in impacts]  # fmt: skip
    return sweep(points, executor, **options)


def _described(point) -> str:
    """A point's chain in a few words, for a message."""
    if isinstance(point, Point):
        return f"R/r = {point.R_over_r:g}, {point.model}, {point.n_rings} rings"
    field = "" if point.field is None else f", {point.field} = {point.value:g}"
    return f"{point.description.source}{field}, {point.model}"
