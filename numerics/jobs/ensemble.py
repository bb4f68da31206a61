r"""Ensembles of disordered chains: many chains of randomly differing rings struck alike (issue 23).

:func:`ensemble` draws ``count`` chains about a nominal ring (:meth:`~ringchain.numerics.Chain.disordered`,
:mod:`~ringchain.numerics.layouts.disorder`), strikes ring 0 of each as the paper's experiment does (a drop
or an impact), and reads the leading pulse at the sensor of every ring: its peak force and arrival
time, and the static tension it rides on.  It also runs the ordered chain (every ring the nominal
one) with the same settings, so that each reading can be set against the chain without disorder
at the same impact.  The result, an :class:`Ensemble`, holds the readings (count x rings), the
seeds, a :meth:`~Ensemble.summary` per ring (mean, standard deviation, standard error,
quantiles), and writes them as CSV.

Scale.  The members are integrated in batches of ``batch_size``: the chains of a batch are
stacked into one network (:meth:`~ringchain.numerics.Network.stack`) and integrated by
:func:`~ringchain.numerics.simulate_batch` as one array problem, with its default method and
tolerances unless told otherwise.  The batches are independent tasks run through any
:class:`concurrent.futures.Executor`, as :func:`~ringchain.numerics.sweep` runs its points: local
processes by default, or a Dask cluster (``executor=client.get_executor()``).

Determinism.  Member i's chain comes from its own seed, the i-th child of the ensemble's
(:func:`~ringchain.numerics.layouts.disorder.member_seeds`), so it does not depend on ``batch_size`` nor
on the number of workers.  For a given ``batch_size`` the results are identical whatever runs
them; between batch sizes they agree to the integrator's tolerance, since an adaptive method
steps a batch with one step size chosen for the whole batch (the members of a batch share their
steps).  tests/numerics/jobs/test_ensemble.py checks both.

Readings.  Every ring's sensor (:attr:`~ringchain.numerics.Simulation.sensor_force`) is read by
:func:`~ringchain.numerics.signals.peak`: the peak of its leading pulse (static tension included,
as :meth:`~ringchain.numerics.Simulation.peak_force`) and its time.  A reading that fails (no
complete pulse within ``t_end``) is NaN and left out of the summary, which counts the readings
per ring.  The duration defaults to :func:`~ringchain.numerics.layouts.chain.default_t_end` of the
ordered chain with the last ring as far sensor, the same for every member.
"""

from __future__ import annotations

import math
import re
import time
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from ringchain.theory import STANDARD_GRAVITY, Ring
from ringchain.theory import _validate as v

from ..engine import signals
from ..engine._files import save_figure
from ..engine._kernel_calls import compiled
from ..engine.executors import run_tasks
from ..engine.integrate import (
    DEFAULT_SAMPLES,
    ENERGY_DRIFT_LIMIT,
    IntegrationError,
    check_samples,
    impact_speeds,
    simulate_batch,
)
from ..engine.network import Network
from ..engine.plots import new_figure
from ..engine.results import Simulation
from ..layouts.chain import MODELS, Chain, default_t_end
from ..layouts.disorder import check_seed, check_spread, describe_spread, draw_rings, member_seeds
from .experiment import MAX_DOUBLINGS
from .sweep import write_csv

__all__ = [
    "ensemble",
    "Ensemble",
    "Summary",
    "summarize",
    "run_members",
    "DEFAULT_BATCH_SIZE",
    "DEFAULT_QUANTILES",
    "CHAIN_OPTIONS",
]

#: Members integrated together in one task (one stacked network, one :func:`simulate_batch` call).
#: Part of an ensemble's definition: it fixes the batches, and so the last digits of adaptive runs.
#: benchmarks/bench_ensemble.py measures the cost per member against it: with SciPy's adaptive
#: methods a batch shares one step size, and a batch of 16 costs about 1.3 times a single run per
#: member (40-ring chains); a method that steps each member on its own (issue 20) makes batches pay.
DEFAULT_BATCH_SIZE = 16

#: Quantiles of the summary per ring: the median, the quartiles, and 90 % of the members between the ends.
DEFAULT_QUANTILES = (0.05, 0.25, 0.5, 0.75, 0.95)

#: Options of the chains passed on to :meth:`~ringchain.numerics.Chain.from_rings`.
CHAIN_OPTIONS = ("support", "gamma", "gamma_c", "gamma_b", "striker_mass")


@dataclass(frozen=True)
class Summary:
    """Statistics per ring of a (members x rings) array of readings (:func:`summarize`).

    Attributes
    ----------
    mean, std, sem : ndarray, shape (n_rings,)
        Mean over the members, standard deviation (ddof = 1) and standard error of the mean
        std/sqrt(count), in the readings' units.
    quantiles : tuple of float
        The probabilities of :attr:`quantile_values`.
    quantile_values : ndarray, shape (len(quantiles), n_rings)
    count : ndarray, shape (n_rings,)
        Readings per ring (members whose reading did not fail).
    """

    mean: np.ndarray
    std: np.ndarray
    sem: np.ndarray
    quantiles: tuple
    quantile_values: np.ndarray
    count: np.ndarray

    def quantile(self, q: float) -> np.ndarray:
        """The values of quantile ``q`` (one of :attr:`quantiles`) per ring."""
        if q not in self.quantiles:
            raise ValueError(f"q must be one of the summary's quantiles {self.quantiles}, got {q!r}")
        return self.quantile_values[self.quantiles.index(q)]


def summarize(values, quantiles=DEFAULT_QUANTILES) -> Summary:
    """Mean, standard deviation, standard error and quantiles of each column of ``values``, NaN left out.

    Parameters
    ----------
    values : array_like, shape (members, n)
        Readings, one row per member (e.g. :attr:`Ensemble.peak_force`, or its ratio to the ordered chain).
    quantiles : sequence of float, optional
        Probabilities in [0, 1].

    Returns
    -------
    Summary
        NaN where a column has fewer readings than a statistic needs (two for the spread).

    Examples
    --------
    >>> s = summarize([[1.0, 2.0], [3.0, np.nan], [5.0, 4.0]], quantiles=(0.5,))
    >>> s.mean.tolist(), s.std.tolist(), s.count.tolist(), s.quantile(0.5).tolist()
    ([3.0, 3.0], [2.0, 1.4142135623730951], [3, 2], [3.0, 3.0])
    """
    values = v.as_array("values", values)
    if values.ndim != 2:
        raise ValueError(f"values must be a (members, n) array, got shape {values.shape}")
    quantiles = tuple(float(q) for q in v.in_range("quantiles", quantiles, 0.0, 1.0, closed_low=True).ravel())
    finite = np.isfinite(values)
    count = finite.sum(axis=0)
    filled = np.where(finite, values, 0.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = np.where(count > 0, filled.sum(axis=0) / count, np.nan)
        squares = np.where(finite, (values - mean) ** 2, 0.0).sum(axis=0)
        std = np.where(count > 1, np.sqrt(squares / (count - 1)), np.nan)
        sem = std / np.sqrt(count)
    table = np.full((len(quantiles), values.shape[1]), np.nan)
    for k in np.flatnonzero(count):
        table[:, k] = np.quantile(values[finite[:, k], k], quantiles)
    return Summary(mean=mean, std=std, sem=sem, quantiles=quantiles, quantile_values=table, count=count)


def _read(sim: Simulation, traces) -> dict:
    """Peak (N), its time (s) and the static tension (N) of every ring's leading pulse of each run of ``sim`` (a
    batch: x of shape (B, T, n)), every trace read at once; the traces of the rings ``traces``, (B, len(traces), T)."""
    force = np.moveaxis(sim.sensor_force, -1, -2)  # (B, n_rings, T)
    baseline = signals.estimate_baseline(sim.t, force)
    arrival, peak = signals.peak(sim.t, force, baseline=baseline, errors="nan")  # NaN: left out of the summary
    return {"peak_force": peak, "arrival": arrival, "baseline": baseline, "traces": force[:, list(traces)]}


def run_members(ring, n_rings, spread, seeds, *, model, m_eff_ratio, speed, dropped, t_end, traces=(),
                n_samples=DEFAULT_SAMPLES, chain_options=None, gravity=True, g=STANDARD_GRAVITY,
                max_energy_drift=ENERGY_DRIFT_LIMIT, **solver) -> dict:  # fmt: skip
    """Draw, strike and read the members of one batch (one task of :func:`ensemble`).

    Parameters
    ----------
    ring, n_rings, spread, model, m_eff_ratio
        As in :func:`ensemble` (checked there).
    seeds : sequence of numpy.random.SeedSequence
        One per member of the batch.
    speed : float
        Impact speed of ring 0, m/s.
    dropped : bool
        A drop (the chain's drop protocol) or an impact on the hanging chain.
    t_end : float
        Duration, s.
    traces : sequence of int, optional
        Rings whose sensor force is kept.
    n_samples, gravity, g, max_energy_drift, **solver
        As in :func:`~ringchain.numerics.simulate_batch`.
    chain_options : dict, optional
        Passed to :meth:`~ringchain.numerics.Chain.from_rings`.

    Returns
    -------
    dict
        ``peak_force``, ``arrival``, ``baseline`` (B, n_rings); ``traces`` (B, len(traces), T);
        ``t`` (T,); ``redrawn`` (B,) values drawn again; ``spacing`` (B, n_rings - 1), m.
    """
    options = dict(chain_options or {})
    draws = [draw_rings(ring, n_rings, spread, seed, model=model, support=options.get("support", "fixed"))
             for seed in seeds]  # fmt: skip
    chains = [draw.build(Chain, model, m_eff_ratio, **options) for draw in draws]
    states = [chain.impact_state(np.array([speed]), dropped, gravity, g) for chain in chains]
    x0 = np.concatenate([x for x, _ in states])
    u0 = np.concatenate([u for _, u in states])
    network = Network.stack([chain.network() for chain in chains]) if len(chains) > 1 else chains[0].network()
    try:
        batch = simulate_batch(network, t_end, initial=(x0, u0), n_samples=n_samples, gravity=gravity, g=g,
                               max_energy_drift=max_energy_drift, **solver)  # fmt: skip
    except IntegrationError as error:  # name the member by its seed, which redraws it
        run = re.search(r" in run (\d+)", str(error))
        if run is None:
            raise
        seed = seeds[int(run.group(1))].spawn_key
        raise IntegrationError(f"{error} (the member with seed key {seed})") from error
    # The members' sensors read together: the stacked network gives each member's links their own laws, and the
    # members' chains share their sensors' links (one model, one length, one support).
    out = _read(Simulation(t=batch.t, x=batch.x, u=batch.u, dissipated=batch.dissipated, g=batch.g,
                           network=batch.network, chain=chains[0], impact_velocity=speed), traces)  # fmt: skip
    out["t"] = batch.t
    out["redrawn"] = np.array([draw.total_redrawn for draw in draws])
    out["spacing"] = np.stack([chain.profile("a") for chain in chains])
    return out


@dataclass(frozen=True, eq=False)
class Ensemble:
    """An ensemble of disordered chains struck alike, read at every ring (:func:`ensemble`).

    Attributes
    ----------
    ring : Ring
        The nominal ring.
    n_rings : int
    model : str
    m_eff_ratio : float
    spread : dict
        The spreads drawn (:func:`~ringchain.numerics.layouts.disorder.check_spread`).
    seed : numpy.random.SeedSequence
        The ensemble's seed; member i's is ``seeds[i]``, its i-th child.
    seeds : tuple of numpy.random.SeedSequence
    impact_velocity : float
        Speed of ring 0 at impact, m/s.
    drop_height : float or None
        m, for a drop.
    t_end : float
        Duration of every run, s.
    peak_force : ndarray, shape (count, n_rings)
        Peak of the leading pulse at each ring's sensor, N (static tension included); NaN where the
        reading failed.
    arrival : ndarray, shape (count, n_rings)
        Time of that peak after the impact, s.
    baseline : ndarray, shape (count, n_rings)
        The static tension each sensor reads before the wave arrives, N.
    spacing : ndarray, shape (count, n_rings - 1)
        Centre distance of each pair of neighbours of each member, m.
    redrawn : ndarray, shape (count,)
        Values of each member drawn again because they would have made a ring impossible
        (:mod:`~ringchain.numerics.layouts.disorder`, "Truncation").
    ordered_peak_force, ordered_arrival, ordered_baseline : ndarray, shape (n_rings,)
        The same readings on the ordered chain (every ring the nominal one), at the same impact.
    t : ndarray
        Sample times of the traces, s.
    trace_rings : tuple of int
        Rings whose sensor forces are kept.
    traces : ndarray, shape (count, len(trace_rings), len(t))
        Their sensor forces, N.
    ordered_traces : ndarray, shape (len(trace_rings), len(t))
    chain_options : dict
        Options of the chains (support, dashpots, striker).
    """

    ring: Ring
    n_rings: int
    model: str
    m_eff_ratio: float
    spread: dict
    seed: np.random.SeedSequence
    seeds: tuple
    impact_velocity: float
    drop_height: float | None
    t_end: float
    peak_force: np.ndarray
    arrival: np.ndarray
    baseline: np.ndarray
    spacing: np.ndarray
    redrawn: np.ndarray
    ordered_peak_force: np.ndarray
    ordered_arrival: np.ndarray
    ordered_baseline: np.ndarray
    t: np.ndarray = field(repr=False)
    trace_rings: tuple = ()
    traces: np.ndarray = field(default=None, repr=False)
    ordered_traces: np.ndarray = field(default=None, repr=False)
    chain_options: dict = field(default_factory=dict)

    @property
    def count(self) -> int:
        """Members of the ensemble."""
        return self.peak_force.shape[0]

    @property
    def failures(self) -> int:
        """Readings that failed (NaN in :attr:`peak_force`), all members and rings together."""
        return int(np.count_nonzero(~np.isfinite(self.peak_force)))

    def chain(self, i: int) -> Chain:
        """Member ``i``'s chain, drawn again from its seed (no warning: :attr:`redrawn` counts the truncation)."""
        i = range(self.count)[i]
        draw = draw_rings(self.ring, self.n_rings, self.spread, self.seeds[i], model=self.model,
                          support=self.chain_options.get("support", "fixed"))  # fmt: skip
        return draw.build(Chain, self.model, self.m_eff_ratio, **self.chain_options)

    def ordered_chain(self) -> Chain:
        """The chain without disorder: every ring the nominal one (:meth:`~ringchain.numerics.Chain.from_ring`)."""
        return Chain.from_ring(self.ring, self.n_rings, self.model, m_eff_ratio=self.m_eff_ratio, **self.chain_options)

    def summary(self, quantity: str = "peak_force", quantiles=DEFAULT_QUANTILES) -> Summary:
        """:func:`summarize` of ``quantity`` ("peak_force", "arrival" or "baseline") per ring."""
        names = ("peak_force", "arrival", "baseline")
        return summarize(getattr(self, v.choice("quantity", quantity, names)), quantiles)

    def wave_speed(self, near: int, far: int) -> np.ndarray:
        """Each member's wave speed between two rings, m/s: their centre distance over the time between the peaks."""
        near, far = (self.ordered_chain().ring_index(k) for k in (near, far))
        if not near < far:
            raise ValueError(f"the far ring must lie further from the impact than the near one, got {near}, {far}")
        return np.sum(self.spacing[:, near:far], axis=1) / (self.arrival[:, far] - self.arrival[:, near])

    def rows(self) -> list[dict]:
        """One row per member: its place, seed and values drawn again, then its peak force, arrival and static
        tension at each ring (units in the column names)."""
        entropy = self.seed.entropy
        out = []
        for i in range(self.count):
            row = {"member": i, "seed_entropy": entropy, "spawn_key": " ".join(map(str, self.seeds[i].spawn_key)),
                   "redrawn": int(self.redrawn[i])}  # fmt: skip
            for name, unit in (("peak_force", "N"), ("arrival", "s"), ("baseline", "N")):
                values = getattr(self, name)[i]
                row |= {f"{name}_{k}_{unit}": None if math.isnan(x) else float(x) for k, x in enumerate(values)}
            out.append(row)
        return out

    def summary_rows(self, quantiles=DEFAULT_QUANTILES) -> list[dict]:
        """One row per ring: the ordered chain's reading beside the members' mean, spread and quantiles."""
        peak, arrival = self.summary("peak_force", quantiles), self.summary("arrival", quantiles)
        out = []
        for k in range(self.n_rings):
            row = {"ring": k, "readings": int(peak.count[k]), "ordered_peak_force_N": float(self.ordered_peak_force[k]),
                   "peak_force_mean_N": peak.mean[k], "peak_force_std_N": peak.std[k],
                   "peak_force_sem_N": peak.sem[k]}  # fmt: skip
            row |= {f"peak_force_q{q:g}_N": peak.quantile_values[j, k] for j, q in enumerate(peak.quantiles)}
            row |= {"ordered_arrival_s": float(self.ordered_arrival[k]), "arrival_mean_s": arrival.mean[k],
                    "arrival_std_s": arrival.std[k], "arrival_sem_s": arrival.sem[k]}  # fmt: skip
            out.append({name: None if isinstance(x, float) and math.isnan(x) else x for name, x in row.items()})
        return out

    def write_csv(self, file=None, *, summary: bool = False) -> str | None:
        """Write :meth:`rows` (or, with ``summary``, :meth:`summary_rows`) as CSV to ``file`` (default: return it).

        Floats are written exactly (:func:`~ringchain.numerics.write_csv`); a failed reading is an empty cell.
        """
        return write_csv(self.summary_rows() if v.flag("summary", summary) else self.rows(), file)

    def describe(self) -> str:
        """The ensemble in one line: chain, spread, members, seed, impact and duration."""
        impact = (f"drop {self.drop_height:g} m (impact {self.impact_velocity:.4g} m/s)" if self.drop_height is not None
                  else f"impact {self.impact_velocity:.4g} m/s")  # fmt: skip
        return (f"{self.n_rings} rings, R/r = {self.ring.aspect_ratio:.4g}, {self.model} model, m_eff/m0 = "
                f"{self.m_eff_ratio:g}; spread {describe_spread(self.spread)}; {self.count} members (seed "
                f"{self.seed.entropy}); {impact}; {self.t_end * 1e3:.4g} ms")  # fmt: skip

    def plot(self, path, title: str | None = None) -> None:
        """Peak force against ring: the ordered chain, the members' mean with its standard error, and the band of
        :data:`DEFAULT_QUANTILES`' ends; written to ``path`` (the extension sets the format)."""
        s = self.summary()
        rings = np.arange(self.n_rings)
        fig = new_figure(figsize=(6.4, 3.8))
        ax = fig.add_subplot()
        low, high = s.quantile_values[0], s.quantile_values[-1]
        ax.fill_between(rings, low, high, color="0.85",
                        label=f"members, {100 * s.quantiles[0]:g}-{100 * s.quantiles[-1]:g} %")  # fmt: skip
        ax.errorbar(rings, s.mean, yerr=s.sem, fmt="o-", ms=3, color="C3", label="mean $\\pm$ standard error")
        ax.plot(rings, self.ordered_peak_force, "k--", label="ordered chain")
        ax.set(xlabel="ring", ylabel="peak force (N)", title=title or describe_spread(self.spread))
        ax.legend(fontsize=8)
        save_figure(fig, path, dpi=120)


def _impact(drop_height, impact_velocity, g):
    """(speed in m/s, dropped, drop height or None): one of the two, checked."""
    if (drop_height is None) == (impact_velocity is None):
        raise ValueError("give a drop height or an impact velocity, one of the two")
    speeds, dropped = impact_speeds(None if impact_velocity is None else float(impact_velocity),
                                    None if drop_height is None else float(drop_height), g)  # fmt: skip
    if not speeds[0] > 0:
        raise ValueError("the impact must be positive: give a drop height or an impact velocity above 0")
    return float(speeds[0]), dropped, None if drop_height is None else float(drop_height)


def ensemble(ring, n_rings, count, *, spread, seed, model="dual-spring", m_eff_ratio=1.0, drop_height=None,
             impact_velocity=None, t_end=None, traces=(), executor=None, batch_size=DEFAULT_BATCH_SIZE,
             max_workers=None, progress=False, n_samples=DEFAULT_SAMPLES, chain_options=None,
             **solver) -> Ensemble:  # fmt: skip
    """Strike ``count`` disordered chains alike and read the leading pulse at every ring (module notes).

    Parameters
    ----------
    ring : Ring
        The nominal ring (geometry, material, contact angle; R/r >= 3).
    n_rings : int
        Rings of each chain, >= 2.
    count : int
        Members, >= 2.
    spread : mapping
        ``"R"``, ``"r"``, ``"angle"`` (and for the power-law model ``"K"``, ``"m"``) to a relative
        standard deviation or a scipy.stats distribution of value/nominal
        (:mod:`~ringchain.numerics.layouts.disorder`).
    seed : int or numpy.random.SeedSequence
        The ensemble's seed; member i draws from its i-th child.  The same seed gives the same ensemble.
    model : {"dual-spring", "power-law"}, optional
    m_eff_ratio : float, optional
        Inertial over ring mass, m_eff/m0 in (0, 1] (Table I); gravity acts on m0.
    drop_height : float, optional
        Free-fall height of ring 0, m (the chain's drop protocol).
    impact_velocity : float, optional
        Speed of ring 0, m/s, instead of a drop.
    t_end : float, optional
        Duration of every run, s; default :func:`~ringchain.numerics.layouts.chain.default_t_end` of the
        ordered chain with the last ring as the far sensor.
    traces : sequence of int, optional
        Rings whose sensor forces are kept (:attr:`Ensemble.traces`).
    executor : concurrent.futures.Executor, optional
        Where the batches run, e.g. a Dask ``Client(...).get_executor()``; default local processes
        (``max_workers``, see :func:`~ringchain.numerics.sweep`: in a script, call under
        ``if __name__ == "__main__":``).
    batch_size : int, optional
        Members integrated together as one stacked network (default :data:`DEFAULT_BATCH_SIZE`).
    max_workers : int, optional
        Processes of the default pool (None: the CPUs; 0: this process).
    progress : bool, optional
        A tqdm progress bar on stderr.
    n_samples : int, optional
        Samples of each record (default :data:`~ringchain.numerics.engine.integrate.DEFAULT_SAMPLES`).
    chain_options : mapping, optional
        :data:`CHAIN_OPTIONS` passed to the chains (``support``, dashpots, ``striker_mass``).
    **solver
        Passed to :func:`~ringchain.numerics.simulate_batch`: ``method``, ``rtol``, ``atol``, ``gravity``,
        ``g``, ``max_energy_drift``... (default: its method and tolerances).

    Returns
    -------
    Ensemble
        Peak forces, arrivals and static tensions (count x n_rings), the ordered chain's, the seeds,
        :meth:`~Ensemble.summary`, :meth:`~Ensemble.write_csv`.

    Notes
    -----
    Beyond the paper (its last sentence asks for disorder); the theory of weak disorder to set
    beside an ensemble is :mod:`ringchain.theory.disorder` (the book's chapter "Disorder").

    Examples
    --------
    >>> ens = ensemble(Ring.from_aspect_ratio(9.0), 12, 4, spread={"R": 0.1}, seed=1, model="power-law",
    ...                drop_height=0.05, max_workers=0)
    >>> ens.peak_force.shape, ens.summary().count.tolist()[:3]
    ((4, 12), [4, 4, 4])
    """
    if not isinstance(ring, Ring):
        raise TypeError(f"ring must be a ringchain.theory.Ring, got {type(ring).__name__}")
    ring.check_chain()
    n_rings = v.count("n_rings", n_rings, 2)
    try:
        count = v.count("count", count, 2)
    except ValueError:
        raise ValueError(f"count must be an integer of at least 2 (an ensemble's spread needs two), got {count!r}"
                         ) from None  # fmt: skip
    model = v.choice("model", model, MODELS)
    spread = check_spread(spread, model)
    root = check_seed(seed)
    m_eff_ratio = float(v.in_range("m_eff_ratio", m_eff_ratio, 0.0, 1.0))
    batch_size = v.count("batch_size", batch_size, 1)
    progress = v.flag("progress", progress)
    n_samples = check_samples(n_samples)
    chain_options = dict(chain_options or {})
    if not isinstance(chain_options, Mapping) or set(chain_options) - set(CHAIN_OPTIONS):
        raise ValueError(f"chain_options takes {', '.join(CHAIN_OPTIONS)}, got {sorted(chain_options)}")
    g = float(v.positive("g", solver.pop("g", STANDARD_GRAVITY), "m/s^2"))
    gravity = v.flag("gravity", solver.pop("gravity", True))
    energy_limit = solver.pop("max_energy_drift", ENERGY_DRIFT_LIMIT)
    if energy_limit is not None:
        energy_limit = float(v.positive("max_energy_drift", energy_limit))
    speed, dropped, drop_height = _impact(drop_height, impact_velocity, g)
    ordered = Chain.from_ring(ring, n_rings, model, m_eff_ratio=m_eff_ratio, **chain_options)
    traces = tuple(ordered.ring_index(k) for k in ([traces] if np.ndim(traces) == 0 else traces))
    retries = MAX_DOUBLINGS if t_end is None else 0  # a default duration grows until the pulse has passed
    if t_end is None:
        t_end = default_t_end(ordered, [speed], (0, n_rings - 1))
    t_end = float(v.positive("t_end", t_end, "s"))
    seeds = member_seeds(root, count)
    run = dict(model=model, m_eff_ratio=m_eff_ratio, speed=speed, dropped=dropped, t_end=t_end, traces=traces,
               n_samples=n_samples, chain_options=chain_options, gravity=gravity, g=g,
               max_energy_drift=energy_limit, **solver)  # fmt: skip

    # The ordered chain first, in this process: it checks the solver's options before any worker starts.
    # Its time, per member, gives the members' work (timed again if it compiled the kernels): the job runs here
    # when a pool would save less than it costs to start (run_tasks).
    def timed_reference():
        for _ in range(2):
            before, start = compiled(), time.perf_counter()
            reference = run_members(ring, n_rings, {}, seeds[:1], **run)
            seconds = (time.perf_counter() - start) * count
            if compiled() == before:
                break
        return reference, seconds

    reference, seconds = timed_reference()
    # As run_experiment does: the default duration of a short chain (2 rings) may end before the leading pulse has
    # passed every ring of the ordered chain; double it (at most MAX_DOUBLINGS times) until it has.
    while retries and np.isnan(reference["peak_force"][0]).any():
        retries -= 1
        t_end = run["t_end"] = 2.0 * t_end
        reference, seconds = timed_reference()
    chunks = [seeds[k : k + batch_size] for k in range(0, count, batch_size)]
    results = run_tasks(run_members, [(ring, n_rings, spread, chunk) for chunk in chunks], executor, options=run,
                        max_workers=max_workers, progress=progress, sizes=[len(c) for c in chunks], name="ensemble",
                        unit="member", seconds=seconds)  # fmt: skip

    def joined(name):
        return np.concatenate([result[name] for result in results])

    return Ensemble(
        ring=ring, n_rings=n_rings, model=model, m_eff_ratio=m_eff_ratio, spread=spread, seed=root, seeds=seeds,
        impact_velocity=speed, drop_height=drop_height, t_end=t_end, peak_force=joined("peak_force"),
        arrival=joined("arrival"), baseline=joined("baseline"), spacing=joined("spacing"), redrawn=joined("redrawn"),
        ordered_peak_force=reference["peak_force"][0], ordered_arrival=reference["arrival"][0],
        ordered_baseline=reference["baseline"][0], t=reference["t"], trace_rings=traces, traces=joined("traces"),
        ordered_traces=reference["traces"][0], chain_options=chain_options,
    )  # fmt: skip
