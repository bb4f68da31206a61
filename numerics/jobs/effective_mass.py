r"""The effective mass the ring-resolved chain predicts, and the trailing oscillations it rings with.

The paper fits an effective mass m_eff/m0 = 0.33-0.37 (Tables I and II) so that its power-law
lattice (Eq. (7)) moves as fast as the measured pulses, and explains it by the inertia "localized
in transverse ovalization and bending".  Here the ring-resolved chain
(:mod:`ringchain.numerics.layouts.ring_beam`), whose rings bend and carry their full mass, plays the
experiment: the paper's 20-ring chain is dropped from several heights, and the power-law
lattice's inertial mass is fitted to its sensor traces, untuned.

The lattice takes K and n from the quasi-static law of the same rings (the series law of
Hertz contact and ring bending, Eq. (3), fitted by Eq. (4) over 1-100 N: what a quasi-static
test of these rings would measure), and m0 for gravity; only its inertial mass is free.  The
dual-spring lattice (Eqs. (5)-(6)) with the rings' K_c and K_b is fitted the same way: its
static law is exactly the rings', so its m_eff measures inertia alone, free of the power law's
error outside 1-100 N.  The
fit (:func:`fit_effective_mass`) is least squares on the arrival times of the leading pulse
at the sensors (the peak of the pulse, as the paper measures the wave speed, Sec. III.A), in
log(m/m0) with :func:`scipy.optimize.least_squares`; the residual is a function argument, so
a fit of whole traces can replace it.  Both the ring-resolved and the lattice traces are
low-passed alike (:func:`lowpass`) before the peaks are read: the rings' own modes ride on the
pulse of the ring-resolved chain as a ripple of 20-30 kHz that would otherwise decide which
sample is the peak.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np
from ringchain.theory import Ring, paper_data
from ringchain.theory import _validate as v

from ..engine import signals
from ..engine.integrate import simulate_batch
from ..engine.results import Simulation
from ..layouts.chain import Chain
from ..layouts.ring_beam import DEFAULT_ELEMENTS, DEFAULT_MODES
from ..layouts.ring_chain import RingChain, RingSimulation, simulate_rings

__all__ = [
    "DEFAULT_CUTOFF",
    "DROP_HEIGHTS",
    "lowpass",
    "arrival_times",
    "arrival_time_residuals",
    "EffectiveMassFit",
    "fit_effective_mass",
    "EffectiveMassPrediction",
    "predict_effective_mass",
    "trailing_spectrum",
    "spectral_peaks",
]

#: Cut-off of the low-pass applied to sensor traces before their peaks are read, Hz: twice the
#: bandwidth of the leading pulse (full width at half maximum ~0.2 ms, spectrum below ~5 kHz),
#: under the ripple of the rings' modes (benchmarks/bench_ring_chain.py shows the fit's
#: sensitivity to it).
DEFAULT_CUTOFF = 10e3

#: Drop heights of the prediction, m: the paper's range, 1 cm to 50 cm (Fig. 4).
DROP_HEIGHTS = (0.01, 0.02, 0.05, 0.1, 0.2, 0.5)


def lowpass(t, y, cutoff=DEFAULT_CUTOFF, order=4) -> np.ndarray:
    """Zero-phase Butterworth low-pass of traces sampled evenly on ``t``, along the last axis.

    Parameters
    ----------
    t : array_like, shape (T,)
        Evenly spaced times, s.
    y : array_like, shape (..., T)
        Traces (e.g. forces, N).
    cutoff : float, optional
        -3 dB frequency of each pass, Hz; below the Nyquist frequency.
    order : int, optional
        Butterworth order of each pass (forward and backward: no phase shift, so peak times
        are not delayed).

    Returns
    -------
    ndarray
        The filtered traces, same shape as ``y``.

    Examples
    --------
    >>> t = np.linspace(0.0, 1e-3, 1001)
    >>> y = np.sin(2 * np.pi * 2e3 * t) + 0.5 * np.sin(2 * np.pi * 50e3 * t)
    >>> float(np.abs(lowpass(t, y) - np.sin(2 * np.pi * 2e3 * t))[200:800].max()) < 0.01
    True
    """
    from scipy.signal import butter, sosfiltfilt

    t = v.as_float("t", t)
    y = v.as_float("y", y)
    step = np.diff(t)
    if t.ndim != 1 or t.size < 16 or np.ptp(step) > 1e-6 * step.mean():
        raise ValueError("t must be 1-d, evenly spaced, with at least 16 samples")
    rate = 1.0 / step.mean()
    cutoff = float(v.positive("cutoff", cutoff, "Hz"))
    if cutoff >= rate / 2:
        raise ValueError(f"cutoff must be below the Nyquist frequency {rate / 2:g} Hz, got {cutoff:g} Hz")
    sos = butter(int(order), cutoff, fs=rate, output="sos")
    return sosfiltfilt(sos, y, axis=-1)


def arrival_times(sim: Simulation, sensors=paper_data.SENSOR_RINGS, cutoff=DEFAULT_CUTOFF) -> np.ndarray:
    """Arrival times (s) of the leading pulse at the ``sensors``: the peaks of the low-passed sensor traces.

    ``cutoff=None`` reads the raw traces.  Works on a lattice :class:`~ringchain.numerics.Simulation`
    and on a :class:`~ringchain.numerics.RingSimulation` alike.
    """
    traces = np.array([sim.sensor(i) for i in sensors])
    if cutoff is not None:
        traces = lowpass(sim.t, traces, cutoff)
    return np.array([signals.arrival_time(sim.t, trace) for trace in traces])


def arrival_time_residuals(reference: Sequence[Simulation], sensors, cutoff) -> Callable:
    """The default residual of :func:`fit_effective_mass`: relative differences of the arrival times.

    Returns a function of the lattice runs (one per reference run) giving
    (lattice - reference)/reference run by run and sensor by sensor; the reference's arrival
    times are read once.
    """
    target = np.array([arrival_times(sim, sensors, cutoff) for sim in reference])

    def residuals(model: Sequence[Simulation]) -> np.ndarray:
        times = np.array([arrival_times(sim, sensors, cutoff) for sim in model])
        return ((times - target) / target).ravel()

    return residuals


@dataclass(frozen=True)
class EffectiveMassFit:
    """A power-law lattice fitted to reference runs through its inertial mass.

    Attributes
    ----------
    ratio : float
        Fitted inertial mass over ring mass, m_eff/m0.
    standard_error : float
        Standard error of ``ratio`` from the residuals and the Jacobian of the fit
        (nan with a single residual).
    K : float
        Lattice stiffness, N/m^n.
    n : float
        Lattice exponent.
    residuals : ndarray
        Relative residuals at the optimum (see ``residual`` of :func:`fit_effective_mass`).
    lattice : list of Simulation
        The fitted lattice's runs, one per reference run.
    """

    ratio: float
    standard_error: float
    K: float
    n: float
    residuals: np.ndarray
    lattice: list = field(repr=False)


def fit_effective_mass(
    reference: Sequence[Simulation],
    ring: Ring,
    *,
    model="power-law",
    sensors=paper_data.SENSOR_RINGS,
    K=None,
    n=None,
    cutoff=DEFAULT_CUTOFF,
    residual: Callable = arrival_time_residuals,
    bounds=(0.05, 3.0),
    initial=0.5,
) -> EffectiveMassFit:
    """Fit the inertial mass of a lattice of the paper (Eq. (7), or Eqs. (5)-(6)) to reference drop runs.

    Parameters
    ----------
    reference : sequence of Simulation
        Drop runs (``drop_height`` set) of one chain, on one time grid, from the impact on:
        ring-resolved runs, or any runs with sensors.
    ring : Ring
        The rings: mass m0 (gravity acts on it), spacing a, and by default K and n.
    model : {"power-law", "dual-spring"}, optional
        The power-law lattice (default; the paper's m_eff of Table I is fitted to it), or the
        dual-spring lattice with the ring's K_c and K_b (Eqs. (1)-(2)): the same static law as
        ring-resolved rings, without the power-law fit of Eq. (4).
    sensors : tuple of int, optional
        Rings whose sensor traces are compared.
    K, n : float, optional
        Power-law stiffness (N/m^n) and exponent; default the ring's quasi-static power law
        (:meth:`~ringchain.theory.Ring.power_law`, Eq. (4)).  For the dual-spring lattice the
        fit reports K_c and 3/2.
    cutoff : float or None, optional
        Low-pass of the traces before the arrival times are read, Hz (None: raw).
    residual : callable, optional
        ``residual(reference, sensors, cutoff)`` returning a function of the lattice runs (one
        per reference run) that gives a 1-d array of dimensionless residuals; default
        :func:`arrival_time_residuals` (a fit of whole traces takes its place here).
    bounds : (float, float), optional
        Range of m_eff/m0 searched.
    initial : float, optional
        Starting m_eff/m0.

    Returns
    -------
    EffectiveMassFit

    Notes
    -----
    The lattice has the reference's number of rings and fixed support, is hung under gravity
    with the ring mass m0 and integrated over the reference's time grid for all drop
    heights at once (:func:`~ringchain.numerics.simulate_batch`).  Least squares in
    log(m_eff/m0) (:func:`scipy.optimize.least_squares`, bounded).
    """
    from scipy.optimize import least_squares

    reference = list(reference)
    if not reference:
        raise ValueError("reference must hold at least one run")
    heights = np.array([run.drop_height if run.drop_height is not None else np.nan for run in reference])
    if np.any(np.isnan(heights)):
        raise ValueError("every reference run must be a drop (drop_height set)")
    t = reference[0].t
    if any(run.t.shape != t.shape or np.any(run.t != t) for run in reference):
        raise ValueError("the reference runs must share one time grid")
    n_rings = reference[0].chain.n_rings
    if model == "dual-spring":
        if K is not None or n is not None:
            raise ValueError("K and n belong to the power-law lattice; the dual-spring one takes the ring's K_c, K_b")
        K, n = ring.K_c, 1.5
    elif model == "power-law":
        if (K is None) != (n is None):
            raise ValueError("give both K and n, or neither (then the ring's power law is used)")
        if K is None:
            K, n = ring.power_law()
    else:
        raise ValueError(f"model must be 'power-law' or 'dual-spring', got {model!r}")
    lo, hi = (float(b) for b in bounds)
    if not 0 < lo < float(initial) < hi:
        raise ValueError(f"need 0 < bounds[0] < initial < bounds[1], got {bounds} and {initial}")
    m0 = ring.mass

    runs = {}  # log ratio -> lattice runs (the optimum's are reused)

    def lattice(log_ratio):
        if log_ratio not in runs:
            m = m0 * float(np.exp(log_ratio))
            if model == "dual-spring":
                chain = Chain.dual_spring(n_rings, K, ring.K_b, m, ring.spacing, m_gravity=m0)
            else:
                chain = Chain.power_law(n_rings, K, n, m, ring.spacing, m_gravity=m0)
            # rtol 1e-7: arrival times to ~1e-9 s, a thousandth of the sampling step.
            runs[log_ratio] = list(simulate_batch(chain, t[-1], drop_heights=heights, t_eval=t, rtol=1e-7))
        return runs[log_ratio]

    residuals = residual(reference, sensors, cutoff)

    def fun(p):
        return residuals(lattice(float(p[0])))

    # Steps of 1 % in log(m): arrival times read by parabola from samples are smooth on that scale;
    # stop when log(m) moves by less than 1e-4 (the ratio to 1e-4 relative).
    result = least_squares(fun, [np.log(initial)], bounds=([np.log(lo)], [np.log(hi)]), diff_step=1e-2,
                           xtol=1e-4)  # fmt: skip
    ratio = float(np.exp(result.x[0]))
    dof = result.fun.size - 1
    if dof > 0 and np.any(result.jac):
        variance = 2.0 * result.cost / dof / float(result.jac[:, 0] @ result.jac[:, 0])
        error = ratio * float(np.sqrt(variance))  # d(ratio) = ratio d(log ratio)
    else:
        error = float("nan")
    return EffectiveMassFit(ratio=ratio, standard_error=error, K=float(K), n=float(n), residuals=result.fun,
                            lattice=lattice(float(result.x[0])))  # fmt: skip


@dataclass(frozen=True)
class EffectiveMassPrediction:
    """The ring-resolved chain dropped from several heights and the paper's lattices fitted to it.

    Attributes
    ----------
    aspect_ratio : float
        R/r of the rings (r = 2.5 mm, stainless, as the paper's).
    drop_heights : ndarray
        m.
    runs : list of RingSimulation
        The ring-resolved runs, one per drop height.
    fits : dict
        Lattice model ("power-law", "dual-spring") -> :class:`EffectiveMassFit` to all heights.
    per_height : dict or None
        Lattice model -> m_eff/m0 fitted to each height alone, ndarray (``per_height=True``).
    paper_ratio : float or None
        The paper's fitted m_eff/m0 for this aspect ratio (Table I), if it has one.
    """

    aspect_ratio: float
    drop_heights: np.ndarray
    runs: list = field(repr=False)
    fits: dict = field(repr=False)
    per_height: dict | None = None
    paper_ratio: float | None = None

    @property
    def fit(self) -> EffectiveMassFit:
        """The power-law lattice's fit (the lattice of the paper's Table I)."""
        return self.fits["power-law"]

    @property
    def ratio(self) -> float:
        """The predicted m_eff/m0 of the power-law lattice (all heights)."""
        return self.fit.ratio


def predict_effective_mass(
    aspect_ratio,
    drop_heights=DROP_HEIGHTS,
    *,
    n_rings=paper_data.CHAIN_RINGS,
    sensors=paper_data.SENSOR_RINGS,
    modes=DEFAULT_MODES,
    elements=DEFAULT_ELEMENTS,
    t_end=3e-3,
    n_samples=3001,
    cutoff=DEFAULT_CUTOFF,
    models=("power-law", "dual-spring"),
    per_height=False,
    **options,
) -> EffectiveMassPrediction:
    """Run the paper's drop experiment on the ring-resolved chain and fit the lattices' m_eff/m0 to it.

    Parameters
    ----------
    aspect_ratio : float
        R/r of the rings; r = 2.5 mm (the paper's), AISI 304 stainless.
    drop_heights : sequence of float, optional
        m; default :data:`DROP_HEIGHTS` (1 cm to 50 cm).
    n_rings, sensors : optional
        The paper's 20 rings and sensors in rings 6 and 12.
    modes, elements : optional
        Resolution of each ring (:meth:`~ringchain.numerics.layouts.ring_beam.RingModel.reduce`).
    t_end, n_samples : optional
        Duration (s) and samples of each run; 3 ms holds the leading pulse at ring 12 for
        drops from 1 cm up.
    cutoff : float or None, optional
        Low-pass before reading arrival times, Hz.
    models : tuple of str, optional
        Lattices fitted (:func:`fit_effective_mass`): the power-law one (the paper's Table I
        m_eff) and the dual-spring one, whose static law is exactly the rings'.
    per_height : bool, optional
        Also fit each height alone (shows whether m_eff depends on the amplitude).
    **options
        Passed to :func:`~ringchain.numerics.simulate_rings`.

    Returns
    -------
    EffectiveMassPrediction
    """
    ring = Ring.from_aspect_ratio(float(v.positive("aspect_ratio", aspect_ratio)), r=paper_data.TUBE_RADIUS)
    heights = np.atleast_1d(v.positive("drop_heights", drop_heights, "m")).astype(float)
    if "power-law" not in models:
        raise ValueError(f"models must include 'power-law' (the paper's Table I lattice), got {models!r}")
    chain = RingChain.from_ring(ring, n_rings, modes=modes, elements=elements)
    runs: list[RingSimulation] = [
        simulate_rings(chain, t_end, drop_height=float(h), n_samples=n_samples, **options) for h in heights
    ]
    fits = {model: fit_effective_mass(runs, ring, model=model, sensors=sensors, cutoff=cutoff) for model in models}
    single = None
    if per_height:
        single = {
            model: np.array([fit_effective_mass([run], ring, model=model, sensors=sensors, cutoff=cutoff).ratio
                             for run in runs])
            for model in models
        }  # fmt: skip
    table = paper_data.TABLE_I.get(float(aspect_ratio))
    return EffectiveMassPrediction(
        aspect_ratio=float(aspect_ratio), drop_heights=heights, runs=runs, fits=fits, per_height=single,
        paper_ratio=None if table is None else table[2],
    )  # fmt: skip


# -- trailing oscillations -----------------------------------------------------------------------


def trailing_spectrum(t, y, start, stop=None) -> tuple[np.ndarray, np.ndarray]:
    """Amplitude spectrum of a trace between ``start`` and ``stop`` (s), linear trend removed, Hann window.

    Returns (frequencies in Hz, amplitudes in the trace's unit); the frequency resolution is
    1/(stop - start).
    """
    t = v.as_float("t", t)
    y = v.as_float("y", y)
    stop = t[-1] if stop is None else float(stop)
    window = (t >= float(start)) & (t <= stop)
    if window.sum() < 16:
        raise ValueError(f"the window [{start:g}, {stop:g}] s holds fewer than 16 samples")
    tw, yw = t[window], y[window]
    yw = yw - np.polyval(np.polyfit(tw, yw, 1), tw)
    spectrum = np.abs(np.fft.rfft(yw * np.hanning(yw.size))) * 2.0 / np.hanning(yw.size).sum()
    return np.fft.rfftfreq(yw.size, tw[1] - tw[0]), spectrum


def spectral_peaks(frequencies, amplitudes, count=3, floor=0.05) -> np.ndarray:
    """Frequencies (Hz) of the ``count`` strongest local maxima of a spectrum, strongest first.

    Maxima below ``floor`` times the strongest, and at zero frequency, are ignored.
    """
    f = v.as_float("frequencies", frequencies)
    a = v.as_float("amplitudes", amplitudes)
    inner = np.flatnonzero((a[1:-1] > a[:-2]) & (a[1:-1] >= a[2:])) + 1
    inner = inner[(f[inner] > 0) & (a[inner] >= floor * a[inner].max(initial=0.0))]
    strongest = inner[np.argsort(a[inner])[::-1]][: int(count)]
    return f[strongest]
