r"""The paper's measurement on any chain: a drop or an impact on ring 0, read by two embedded sensors.

:func:`run_experiment` runs what the paper's experiment does (Sec. III.A) on a
:class:`~ringchain.numerics.Chain`: ring 0 struck (dropped from a height, or hit at a speed),
the sensor forces of two rings recorded, and the leading pulse read at each -- peak force,
arrival time, the time of flight between them and the wave speed -- beside the compact
wave's speed of Eq. (8) at the near sensor's peak force.  ``ringchain simulate`` is this job
(it writes the traces with :func:`~ringchain.numerics.write_traces`);
:func:`~ringchain.numerics.paper_experiment` is it on the paper's own chain.

The duration that lets the pulse pass the far sensor is the chain's own
(:func:`~ringchain.numerics.layouts.chain.default_t_end`).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np
from ringchain.theory import STANDARD_GRAVITY, paper_data
from ringchain.theory import _validate as v

from ..engine import signals
from ..engine.integrate import simulate
from ..engine.plots import plot_sensor_traces
from ..engine.results import Simulation
from ..engine.traces import write_traces
from ..layouts.chain import Chain, default_t_end, sensor_pair

__all__ = ["Experiment", "run_experiment", "MAX_DOUBLINGS"]

#: Times a default duration (:func:`~ringchain.numerics.layouts.chain.default_t_end`) is doubled while the leading
#: pulse has not passed the far
#: sensor by the end (:func:`run_experiment`, :func:`ringchain.numerics.jobs.sweep.run_points`): the estimate is a
#: long-wave one, and a chain of two rings, or of rings metres across (R typed in mm), outruns it.
MAX_DOUBLINGS = 4


@dataclass(frozen=True, eq=False)
class Experiment:
    """A drop or an impact on a chain, read at two sensors (:func:`run_experiment`).

    Attributes
    ----------
    chain : Chain
    sensors : (int, int)
        Near and far sensor rings, counted from the impact.
    impact_velocity : float
        m/s.
    drop_height : float or None
        m.
    t_end : float
        Duration, s.
    simulation : Simulation
        The run (the sensors' rings and the support recorded).

    The readings are computed when asked for and raise a
    :class:`~ringchain.numerics.signals.PulseError` when a sensor reads no complete pulse:
    ``peak_forces`` (N, static tension included), ``arrival_times`` (s), ``time_of_flight``
    (s), ``wave_speed`` (m/s), ``theory_speed`` (Eq. (8) at the near peak, m/s; None for a
    chain that changes along its length), ``support_peak`` (N; None for a free end).
    """

    chain: Chain
    sensors: tuple
    impact_velocity: float
    drop_height: float | None
    t_end: float
    simulation: Simulation = field(repr=False)

    @functools.cached_property
    def peak_forces(self) -> tuple:
        return tuple(self.simulation.peak_force(k) for k in self.sensors)

    @functools.cached_property
    def arrival_times(self) -> tuple:
        return tuple(self.simulation.arrival_time(k) for k in self.sensors)

    @property
    def time_of_flight(self) -> float:
        return self.simulation.time_of_flight(*self.sensors)

    @property
    def wave_speed(self) -> float:
        return self.simulation.wave_speed(*self.sensors)

    @property
    def theory_speed(self) -> float | None:
        """V_s of Eq. (8) at the near sensor's peak force, with the chain's power law (or, for the dual-spring
        chain, the one fitted to its springs, Eq. 4), m/s; None if the chain changes along its length."""
        from ringchain.theory import fit_power_law, solitary_wave_speed

        chain = self.chain
        if not chain.uniform:
            return None
        K, n = (
            (chain.K, chain.n)
            if chain.model == "power-law"
            else (float(x) for x in fit_power_law(K_c=chain.K_c, K_b=chain.K_b))
        )
        return float(solitary_wave_speed(self.peak_forces[0], K=K, n=n, a=chain.a, m=chain.m))

    @property
    def support_peak(self) -> float | None:
        support = self.simulation.support_force
        return None if support is None else float(np.max(support))

    def summary(self, described: str) -> list[str]:
        """What ``ringchain simulate`` prints: the chain (``described``), the impact, each sensor's peak and
        arrival, the time of flight and speed beside Eq. (8), the support's largest force."""
        chain = self.chain
        near = self.sensors[0]
        lines = [f"{chain.n_rings} rings{described}, {chain.model} model, impact at {self.impact_velocity:.4g} m/s, "
                 f"{self.t_end * 1e3:.4g} ms"]  # fmt: skip
        for k, force, time in zip(self.sensors, self.peak_forces, self.arrival_times, strict=True):
            lines.append(f"  ring {k}: peak {force:.4g} N at {time * 1e3:.4g} ms")
        theory = self.theory_speed
        eq8 = "" if theory is None else f" (Eq. (8) at ring {near}'s peak: {theory:.4g} m/s)"
        lines.append(f"  time of flight {self.time_of_flight * 1e3:.4g} ms, speed {self.wave_speed:.4g} m/s{eq8}")
        if self.support_peak is not None:
            lines.append(f"  support: largest force {self.support_peak:.4g} N")
        return lines


def run_experiment(chain: Chain, *, drop_height=None, impact_velocity=None, sensors=paper_data.SENSOR_RINGS,
                   t_end=None, out=None, plot=None, **options) -> Experiment:  # fmt: skip
    """Strike ring 0 of ``chain`` and read two sensors, as the paper's experiment does (Sec. III.A).

    Parameters
    ----------
    chain : Chain
        Hanging from a fixed support (gravity acts), or free (then ``gravity=False``).
    drop_height : float, optional
        Free-fall height of ring 0, m (the chain's drop protocol).
    impact_velocity : float, optional
        Speed of ring 0, m/s, instead of a drop.
    sensors : (int, int), optional
        Near and far sensor rings (default the paper's 6 and 12).
    t_end : float, optional
        Duration, s; default :func:`default_t_end`, doubled (up to :data:`MAX_DOUBLINGS` times) while the
        leading pulse has not passed the far sensor by the end.
    out : str or path, optional
        Write the sensor traces there (:func:`~ringchain.numerics.write_traces`), before any reading.
    plot : str or path, optional
        Plot them there (the extension sets the format).
    **options
        Passed to :func:`~ringchain.numerics.simulate` (``method``, ``n_samples``, ``rtol``,
        ``gravity``...).  Only the sensors' rings and the top ring (the support's force) are
        recorded unless ``rings`` says otherwise (None: every ring).

    Returns
    -------
    Experiment

    Examples
    --------
    >>> from ringchain.theory import Ring
    >>> chain = Chain.from_ring(Ring.from_aspect_ratio(9.0), 8, "power-law")
    >>> run = run_experiment(chain, drop_height=0.05, sensors=(2, 5))
    >>> 0.0 < run.time_of_flight < 1e-3, run.support_peak > run.peak_forces[1] > 0.0  # s, N
    (True, True)
    """
    if not isinstance(chain, Chain):
        raise TypeError(f"chain must be a Chain, got {type(chain).__name__}")
    sensors = sensor_pair(sensors, chain.n_rings)
    if (drop_height is None) == (impact_velocity is None):
        raise ValueError("give a drop height or an impact velocity, one of the two")
    value, unit = (drop_height, "m") if drop_height is not None else (impact_velocity, "m/s")
    value = float(v.positive("drop_height" if drop_height is not None else "impact_velocity", value, unit))
    impact = {"drop_height": value} if drop_height is not None else {"impact_velocity": value}
    g = options.get("g", STANDARD_GRAVITY)
    speed = float(impact_speed_of(impact, g))
    retries = MAX_DOUBLINGS if t_end is None else 0
    if t_end is None:
        t_end = default_t_end(chain, [speed], sensors)
    rings = options.pop("rings", [*sensors, chain.n_rings - 1])
    while True:
        sim = simulate(chain, t_end, rings=rings, **impact, **options)
        if retries == 0 or _passed(sim, sensors[1]):
            break
        retries -= 1
        t_end *= 2.0
    if out is not None:
        write_traces(out, sim, sensors)
    if plot is not None:
        plot_sensor_traces(plot, sim, sensors, f"{chain.model}, {chain.n_rings} rings, impact {speed:.3g} m/s")
    return Experiment(chain=chain, sensors=sensors, impact_velocity=speed, drop_height=impact.get("drop_height"),
                      t_end=float(t_end), simulation=sim)  # fmt: skip


def _passed(sim: Simulation, ring: int) -> bool:
    """Whether the leading pulse has passed the sensor of ``ring`` (fallen to half its peak) within the run."""
    try:
        signals.leading_pulse(sim.t, sim.sensor(ring))
    except (signals.TruncatedPulseError, signals.NoPulseError):
        return False
    return True


def impact_speed_of(impact: dict, g: float) -> float:
    """The speed of ring 0 for ``{"drop_height": h}`` (sqrt(2 g h)) or ``{"impact_velocity": v}``, m/s."""
    from ringchain.theory import impact_speed

    return float(impact_speed(impact["drop_height"], g)) if "drop_height" in impact else impact["impact_velocity"]
