"""Reading force-time traces: peaks, arrival times, time of flight, speed, pulse width, tail and spectrum.

Plain functions of NumPy arrays (a time vector ``t`` in s and a trace sampled on it),
used by :class:`ringchain.numerics.Simulation` for its sensor helpers and usable on
measured data.  The wave speed is measured as in the paper (Sec. III.A): the time of
flight between the peak-force arrivals at two sensors.

A sensor in a hanging chain reads the static tension (the weight of the rings below
it) before the wave arrives, and the pulse rides on it.  The pulse is therefore found
above the trace's *baseline*: the level before the wave arrives, given by the caller or
estimated from the start of the record (:func:`estimate_baseline`).  The leading pulse
is the first run of samples above the threshold, by default halfway between the
baseline and the trace's maximum.

A reading is refused, with a :class:`PulseError` (a :class:`ValueError`) that says why,
when the trace holds no pulse (:class:`NoPulseError`), when the pulse is cut off by the
start or the end of the record (:class:`TruncatedPulseError`), or when it is sampled
too coarsely to locate its peak (:class:`UnresolvedPulseError`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from ringchain.theory import _validate as v

__all__ = [
    "leading_pulse",
    "peak",
    "arrival_time",
    "time_of_flight",
    "wave_speed",
    "speed_over",
    "pulse_width",
    "estimate_baseline",
    "PulseError",
    "NoPulseError",
    "TruncatedPulseError",
    "UnresolvedPulseError",
    "LEADING_PULSE_THRESHOLD",
    "BASELINE_SAMPLES",
    "MIN_SAMPLES_PER_WIDTH",
    "tail",
    "spectrum",
    "dominant_frequency",
]

#: Default threshold of the leading pulse: this fraction of the way from the baseline to
#: the trace's maximum.
LEADING_PULSE_THRESHOLD = 0.5

#: Samples at the start of a record whose median is the estimated baseline
#: (:func:`estimate_baseline`); the median ignores one or two outliers among them.
BASELINE_SAMPLES = 5

#: Fewest samples per full width at half maximum of a pulse.  The parabola through the
#: sampled maximum and its neighbours then places a Gaussian or a compact cos^4 pulse
#: to 0.2% of its width and its height to 0.3% (worst over the sampling phase; at 4
#: samples 0.4% and 0.7%, at 3 samples 1% and 2%), tests/numerics/engine/test_signals.py.
MIN_SAMPLES_PER_WIDTH = 5

#: A trace whose largest rise above its baseline is below this fraction of its largest
#: magnitude holds no pulse: rounding and solver noise on a static trace are far below
#: it (a relative tolerance of 1e-9 at most gives a wobble of ~1e-9).
_NO_PULSE_LEVEL = 1e-6

#: Samples of the traces :func:`peak` reads together (a block of traces at a time: its work arrays stay small).
_BLOCK_SAMPLES = 1 << 20


class PulseError(ValueError):
    """A trace from which no leading pulse can be read (see the subclasses)."""


class NoPulseError(PulseError):
    """The trace never rises above its baseline: there is no pulse to read."""


class TruncatedPulseError(PulseError):
    """The leading pulse is cut off by the start or the end of the record."""


class UnresolvedPulseError(PulseError):
    """The leading pulse is sampled too coarsely to locate its peak."""


def _trace(t, y, rows=False):
    """``t`` (T,) and one trace ``y`` (T,); with ``rows``, traces on those times, ``y`` of shape (..., T)."""
    t = v.as_float("t", t)
    y = v.as_float("signal", y)
    if t.ndim != 1 or (y.shape[-1:] != t.shape if rows else y.shape != t.shape):
        what = "the signal (or the signals' last axis)" if rows else "the signal"
        raise ValueError(f"t and {what} must be 1-d of the same length, got shapes {t.shape} and {y.shape}")
    if t.size < 3 or np.any(np.diff(t) <= 0):
        raise ValueError("t must be increasing, with at least 3 samples")
    return t, y


def estimate_baseline(t, y):
    """The level of a trace before its pulse arrives: the median of its first samples.

    Parameters
    ----------
    t, y : array_like, shape (T,)
        Times (s, increasing) and trace, as in :func:`leading_pulse`; or traces on those times, ``y`` of
        shape (..., T), each read alone.

    Returns
    -------
    float, or ndarray of shape ``y.shape[:-1]``
        Median of the first :data:`BASELINE_SAMPLES` samples, in the units of ``y``.
        For a simulated sensor it is the static tension at the sensor; a record that
        starts after the wave has arrived needs its baseline given instead.

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> estimate_baseline(t, 2.0 + np.exp(-((t - 0.5) / 0.05) ** 2))
    2.0
    """
    t, y = _trace(t, y, rows=True)
    base = _baseline(y)
    return float(base) if y.ndim == 1 else base


def _baseline(y) -> np.ndarray:
    """:func:`estimate_baseline` of traces ``y`` (..., T)."""
    return np.median(y[..., :BASELINE_SAMPLES], axis=-1)


@dataclass(frozen=True)
class _Pulse:
    """The leading pulse of a trace: its run above threshold, sampled maximum and half-height crossings."""

    run: slice
    k: int  # index of the sampled maximum
    baseline: float
    t_left: float  # s, rising half-height crossing
    t_right: float  # s, falling half-height crossing


# Why a trace's leading pulse cannot be read (_Pulses.problem; 0: it can).
_FLAT, _UNREACHED, _EARLY, _UNFINISHED, _BEFORE, _COARSE = range(1, 7)


@dataclass(frozen=True)
class _Pulses:
    """The leading pulses of B traces on the same times (one a row), as :class:`_Pulse` each, in arrays of shape
    (B,); ``problem`` says why a trace's cannot be read (0: it can, see :meth:`error`)."""

    t: np.ndarray
    start: np.ndarray
    stop: np.ndarray
    k: np.ndarray
    baseline: np.ndarray
    top: np.ndarray
    level: np.ndarray
    height: np.ndarray  # the sampled maximum y[k]
    t_left: np.ndarray
    t_right: np.ndarray
    spacing: np.ndarray  # s, the largest sample spacing across the half-height crossings
    problem: np.ndarray

    def error(self, b: int, label: bool = False, index: int | None = None) -> PulseError:
        """The error of trace ``b`` (see :func:`leading_pulse`), naming it by its ``index`` (default b) if ``label``."""
        t, base, top, level = self.t, self.baseline[b], self.top[b], self.level[b]
        tk, yk, code = t[self.k[b]], self.height[b], self.problem[b]
        width = self.t_right[b] - self.t_left[b]
        spacing = self.spacing[b]
        if code == _FLAT:
            error = NoPulseError(f"no pulse: the trace never rises above its baseline {base:g} (its maximum is "
                                 f"{top:g})")  # fmt: skip
        elif code == _UNREACHED:
            error = NoPulseError(f"no pulse: the trace never reaches the threshold {level:g} (its maximum is {top:g})")
        elif code == _EARLY:
            error = TruncatedPulseError(
                f"the trace is above the pulse threshold {level:g} at the start of the record (t = {t[0]:g} s): "
                f"the pulse began before the record, or the baseline {base:g} is not the level before the wave "
                "(give it as baseline=)"
            )
        elif code == _UNFINISHED:
            error = TruncatedPulseError(
                f"the leading pulse (sampled peak {yk:g} at t = {tk:g} s) does not fall to half its height "
                f"within the record, which ends at t = {t[-1]:g} s: it is cut off; record for longer"
            )
        elif code == _BEFORE:
            error = TruncatedPulseError(
                f"the leading pulse (sampled peak {yk:g} at t = {tk:g} s) is above half its height from the "
                f"start of the record: it began before t = {t[0]:g} s"
            )
        else:
            error = UnresolvedPulseError(
                f"the leading pulse is sampled too coarsely to locate its peak: {width / spacing:.1f} samples "
                f"across its full width at half maximum ({width:.3g} s at a spacing of {spacing:.3g} s); sample at "
                f"least {MIN_SAMPLES_PER_WIDTH} per width (a spacing of {width / MIN_SAMPLES_PER_WIDTH:.3g} s or less)"
            )
        if label:
            error.args = (f"trace {b if index is None else index}: {error.args[0]}",)
        return error

    def check(self, label: bool = False) -> None:
        """Raise the error of the first trace whose pulse cannot be read (see :meth:`error`)."""
        failed = np.flatnonzero(self.problem)
        if failed.size:
            raise self.error(int(failed[0]), label)

    def one(self) -> _Pulse:
        """The pulse of the only trace (its error raised if it cannot be read)."""
        self.check()
        start, stop, k = int(self.start[0]), int(self.stop[0]), int(self.k[0])
        return _Pulse(slice(start, stop), k, float(self.baseline[0]), float(self.t_left[0]), float(self.t_right[0]))


def _level(name, value) -> float:
    value = v.as_float(name, value)
    if value.ndim:
        raise ValueError(f"{name} must be one number, got an array of shape {value.shape}")
    return float(value)


def _levels(name, value, shape) -> np.ndarray:
    """A level (one number, or one per trace: ``shape``) as a flat array, one per trace."""
    if not shape:
        return np.array([_level(name, value)])
    value = v.as_float(name, value)
    if value.ndim and value.shape != shape:
        raise ValueError(f"{name} must be one number or one per trace (shape {shape}), got shape {value.shape}")
    return np.broadcast_to(value, shape).ravel()


def _leading_rows(t, y, threshold=None, baseline=None) -> _Pulses:
    """Find the leading pulse of each row of ``y`` (B, T), all at once, and mark those that cannot be read (see the
    module notes).  ``baseline``: None (each trace's own, :func:`estimate_baseline`) or one per trace (B,)."""
    B, T = y.shape
    rows, index = np.arange(B), np.arange(T)
    base = _baseline(y) if baseline is None else baseline
    top = y.max(axis=1)
    scale = np.maximum(np.abs(y).max(axis=1), np.abs(base))
    problem = np.where(top - base > _NO_PULSE_LEVEL * scale, 0, _FLAT)
    if threshold is None:
        level = base + LEADING_PULSE_THRESHOLD * (top - base)
    else:
        level = np.full(B, _level("threshold", threshold))
        low = np.flatnonzero((problem == 0) & ~(level > base))
        if low.size:
            which = f" (trace {low[0]})" if B > 1 else ""
            raise ValueError(f"the pulse threshold {level[0]:g} must lie above the trace's baseline "
                             f"{base[low[0]]:g}{which}")  # fmt: skip
        problem = np.where((problem == 0) & (level > top), _UNREACHED, problem)
    start = np.argmax(y >= level[:, None], axis=1)  # the first sample at or above the level
    problem = np.where((problem == 0) & (start == 0), _EARLY, problem)
    after = (y < level[:, None]) & (index > start[:, None])
    stop = np.where(after.any(axis=1), np.argmax(after, axis=1), T)
    k = np.argmax(np.where((index >= start[:, None]) & (index < stop[:, None]), y, -np.inf), axis=1)
    height = y[rows, k]
    half = base + 0.5 * (height - base)
    low = y < half[:, None]
    left, right = low & (index < k[:, None]), low & (index >= k[:, None])
    problem = np.where((problem == 0) & ~right.any(axis=1), _UNFINISHED, problem)
    problem = np.where((problem == 0) & ~left.any(axis=1), _BEFORE, problem)
    i = np.minimum(T - 1 - np.argmax(left[:, ::-1], axis=1), T - 2)  # y[i] < half <= y[i+1]
    j = np.maximum(np.argmax(right, axis=1), 1)  # y[j-1] >= half > y[j]
    with np.errstate(divide="ignore", invalid="ignore"):  # only at traces already marked (flat at a crossing)
        t_left = t[i] + (half - y[rows, i]) * (t[i + 1] - t[i]) / (y[rows, i + 1] - y[rows, i])
        t_right = t[j - 1] + (y[rows, j - 1] - half) * (t[j] - t[j - 1]) / (y[rows, j - 1] - y[rows, j])
    across = (index[:-1] >= i[:, None]) & (index[:-1] < j[:, None])
    spacing = np.where(across, np.diff(t), -np.inf).max(axis=1)
    problem = np.where((problem == 0) & (t_right - t_left < MIN_SAMPLES_PER_WIDTH * spacing), _COARSE, problem)
    return _Pulses(t, start, stop, k, base, top, level, height, t_left, t_right, spacing, problem)


def _leading(t, y, threshold=None, baseline=None) -> _Pulse:
    """Find the leading pulse of one trace and check that it can be read (see the module notes)."""
    t, y = _trace(t, y)
    base = None if baseline is None else _levels("baseline", baseline, ())
    return _leading_rows(t, y[None], threshold, base).one()


def leading_pulse(t, y, threshold=None, *, baseline=None) -> slice:
    """Samples of the first pulse of ``y``: the first run of samples above ``threshold``.

    Parameters
    ----------
    t : array_like, shape (T,)
        Times, s, increasing.
    y : array_like, shape (T,)
        Trace (e.g. a force, N).
    threshold : float, optional
        Level that defines the pulse, in the units of ``y``; default halfway between the
        baseline and the trace's maximum.  The first pulse, not the largest one, is the
        wave's arrival: a reflection from the far end can be larger than the incident
        pulse near it.
    baseline : float, optional
        Level of the trace before the wave arrives (e.g. the static tension at a sensor
        of a hanging chain); default :func:`estimate_baseline`.

    Returns
    -------
    slice
        Indices of the first run of samples with y >= threshold.

    Raises
    ------
    NoPulseError
        If the trace never rises above its baseline (or never reaches ``threshold``).
    TruncatedPulseError
        If the pulse is cut off by the start or the end of the record.
    UnresolvedPulseError
        If fewer than :data:`MIN_SAMPLES_PER_WIDTH` samples span its width at half height.
    """
    return _leading(t, y, threshold, baseline).run


def peak(t, y, threshold=None, *, baseline=None, errors="raise"):
    """Time (s) and height of the maximum of the leading pulse of ``y``, or of each of many traces at once.

    The sampled maximum is refined by the parabola through it and its two neighbours
    (error O(dt^3) in time for a smooth peak).  ``threshold`` and ``baseline`` are as in
    :func:`leading_pulse`, which also lists the errors raised.  The height is the
    trace's value at the peak (baseline included).

    Parameters
    ----------
    t : array_like, shape (T,)
        Times, s, increasing.
    y : array_like, shape (T,) or (..., T)
        One trace, or traces sampled at ``t`` (one per row: the sensors of a batch of runs), read at once;
        each trace is read exactly as it would be alone.
    threshold : float, optional
        As in :func:`leading_pulse` (one level for every trace).
    baseline : float or array_like of shape ``y.shape[:-1]``, optional
        As in :func:`leading_pulse`: one level, or one per trace.
    errors : {"raise", "nan"}, optional
        A trace whose leading pulse cannot be read raises its :class:`PulseError` (of several traces the first,
        named by its flat index), or with "nan" reads NaN.

    Returns
    -------
    time, height : float, or ndarray of shape ``y.shape[:-1]``
        s, and the units of ``y``.

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> tp, yp = peak(t, np.clip(1.0 - ((t - 0.33) / 0.1) ** 2, 0.0, None))  # a parabolic bump
    >>> round(tp, 12), round(yp, 12)
    (0.33, 1.0)
    >>> times, heights = peak(t, [np.exp(-(((t - c) / 0.05) ** 2)) for c in (0.2, 0.5)])
    >>> np.round(times, 12).tolist()
    [0.2, 0.5]
    """
    if errors not in ("raise", "nan"):
        raise ValueError(f'errors must be "raise" or "nan", got {errors!r}')
    t, y = _trace(t, y, rows=True)
    shape, T = y.shape[:-1], t.size
    traces = y.reshape(-1, T)
    levels = None if baseline is None else _levels("baseline", baseline, shape)
    block = max(1, _BLOCK_SAMPLES // T)  # traces read together: a few arrays of block x T samples at a time
    found = [_leading_rows(t, traces[a : a + block], threshold, None if levels is None else levels[a : a + block])
             for a in range(0, traces.shape[0], block)]  # fmt: skip
    problem, k = (np.concatenate([getattr(p, name) for p in found]) for name in ("problem", "k"))
    if errors == "raise" and np.any(problem):
        first = int(np.flatnonzero(problem)[0])
        raise found[first // block].error(first % block, label=bool(shape), index=first)
    rows, k = np.arange(traces.shape[0]), np.clip(k, 1, T - 2)  # (a trace marked may peak at an end)
    t0, t1, t2 = t[k - 1], t[k], t[k + 1]
    y0, y1, y2 = traces[rows, k - 1], traces[rows, k], traces[rows, k + 1]
    # Vertex of the parabola through three (possibly unevenly spaced) points.
    d0, d2 = t0 - t1, t2 - t1
    s0, s2 = (y0 - y1) / d0, (y2 - y1) / d2
    curvature = (s2 - s0) / (d2 - d0)
    with np.errstate(divide="ignore", invalid="ignore"):  # a flat top (curvature 0) is read at its sample
        slope = s0 - curvature * d0
        shift = -slope / (2.0 * curvature)
        bent = curvature < 0
        time = np.where(bent, t1 + shift, t1)
        height = np.where(bent, y1 + slope * shift + curvature * shift**2, y1)
    failed = problem != 0
    time[failed], height[failed] = np.nan, np.nan
    if not shape:
        return float(time[0]), float(height[0])
    return time.reshape(shape), height.reshape(shape)


def arrival_time(t, y, threshold=None, *, baseline=None) -> float:
    """Arrival time of the leading pulse: the time of its peak, s (see :func:`peak`)."""
    return peak(t, y, threshold, baseline=baseline)[0]


def _pair(baseline):
    """Baselines of a (near, far) pair of traces: None (each estimated), one level, or two."""
    if baseline is None:
        return None, None
    levels = v.as_float("baseline", baseline)
    if levels.ndim == 0:
        return float(levels), float(levels)
    if levels.shape == (2,):
        return float(levels[0]), float(levels[1])
    raise ValueError(f"baseline must be one level or a (near, far) pair, got shape {levels.shape}")


def time_of_flight(t, y_near, y_far, threshold=None, *, baseline=None) -> float:
    """Time between the leading-pulse peaks of two traces, s (paper Sec. III.A).

    ``baseline`` is one level for both traces or a (near, far) pair; by default each
    trace's own (:func:`estimate_baseline`).  See :func:`leading_pulse` for the errors.
    """
    near, far = _pair(baseline)
    return arrival_time(t, y_far, threshold, baseline=far) - arrival_time(t, y_near, threshold, baseline=near)


def wave_speed(t, y_near, y_far, distance, threshold=None, *, baseline=None) -> float:
    """Wave speed, m/s: ``distance`` (m) over the time of flight between two traces.

    Examples
    --------
    >>> t = np.linspace(0.0, 1e-3, 1001)
    >>> near, far = (np.exp(-(((t - t0) / 2e-5) ** 2)) for t0 in (2e-4, 6e-4))
    >>> round(wave_speed(t, near, far, 0.24), 6)  # 0.24 m in 0.4 ms
    600.0
    """
    distance = float(v.positive("distance", distance, "m"))
    return speed_over(distance, time_of_flight(t, y_near, y_far, threshold, baseline=baseline))


def speed_over(distance, time_of_flight):
    """``distance`` (m) over a time of flight (s), m/s (floats, or arrays of flights); a flight that is not
    positive is refused (no wave from the near sensor to the far one)."""
    flights = np.asarray(time_of_flight)
    bad = np.flatnonzero((flights <= 0).ravel()) if flights.ndim else ([0] if flights <= 0 else [])
    if len(bad):
        first = float(flights.ravel()[bad[0]])
        where = f" (run {bad[0]})" if flights.ndim else ""
        raise ValueError(f"the far trace peaks first (time of flight {first:g} s){where}: no wave from near to far")
    return distance / time_of_flight


def pulse_width(t, y, threshold=None, *, baseline=None) -> float:
    """Full width at half maximum of the leading pulse above its baseline, s.

    The half-height level is halfway between the baseline and the leading peak; its
    crossings on either side of the peak are found by linear interpolation between
    samples.  ``threshold`` and ``baseline`` are as in :func:`leading_pulse`, which
    also lists the errors raised (a pulse must fall below half its height on both sides
    within the record).

    Examples
    --------
    >>> t = np.linspace(-1.5, 1.5, 3001)
    >>> round(pulse_width(t, np.exp(-t**2 / 0.08)), 6)  # Gaussian, sigma = 0.2: 2 sqrt(2 ln 2) sigma
    0.470964
    """
    pulse = _leading(t, y, threshold, baseline)
    return pulse.t_right - pulse.t_left


def tail(t, y, threshold=None, *, baseline=None, settled=0.02, next_pulse=0.4) -> slice:
    """Samples of the trailing oscillation: after the leading pulse, before the next pulse.

    Parameters
    ----------
    t, y : array_like, shape (T,)
        Times (s) and trace.
    threshold, baseline : float, optional
        Define the leading pulse (see :func:`leading_pulse`).
    settled : float, optional
        The tail starts when the trace, after its leading peak, first falls below
        ``baseline + settled (peak - baseline)`` (default 2 % of the pulse above its baseline).
    next_pulse : float, optional
        It ends when the trace next exceeds ``next_pulse`` times the leading peak (a second
        pulse, e.g. the one reflected by the far end), or at the end of the record.

    Returns
    -------
    slice
        Indices of the tail; empty if the trace never settles after its leading pulse.

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 1001)
    >>> y = np.exp(-((t - 0.1) / 0.02) ** 2) + 0.01 * np.sin(200 * t) + np.exp(-((t - 0.8) / 0.02) ** 2)
    >>> part = tail(t, y)
    >>> round(float(t[part.start]), 2), round(float(t[part.stop]), 2)
    (0.14, 0.78)
    """
    t, y = _trace(t, y)
    pulse = _leading(t, y, threshold, baseline)
    k = pulse.k
    level = pulse.baseline + settled * (y[k] - pulse.baseline)
    below = np.flatnonzero(y[k:] < level)
    if below.size == 0:
        return slice(y.size, y.size)
    start = k + int(below[0])
    again = np.flatnonzero(y[start:] > next_pulse * y[k])
    return slice(start, start + int(again[0]) if again.size else y.size)


def spectrum(t, y, *, pad=16) -> tuple[np.ndarray, np.ndarray]:
    """Amplitude spectrum of a trace on evenly spaced times: linear trend removed, Hann window, zero padding.

    Parameters
    ----------
    t, y : array_like, shape (T,)
        Times (s), evenly spaced, and trace.
    pad : int, optional
        Zero padding: the transform has the next power of two >= ``pad`` T points, so a
        line is located to a fraction 1/``pad`` of the record's resolution 1/(t[-1] - t[0]).

    Returns
    -------
    frequency : ndarray
        Hz.
    amplitude : ndarray
        Amplitude of the windowed transform divided by the window's sum (a pure
        sine of amplitude A shows a line of height A/2), in the units of y.

    Examples
    --------
    >>> t = np.linspace(0.0, 0.1, 2001)
    >>> f, amplitude = spectrum(t, 3.0 + 2.0 * np.sin(2 * np.pi * 440.0 * t))
    >>> round(float(f[np.argmax(amplitude)])), round(float(amplitude.max()), 2)
    (440, 1.0)
    """
    t, y = _trace(t, y)
    step = np.diff(t)
    if np.ptp(step) > 1e-6 * step.mean():
        raise ValueError("the spectrum needs evenly spaced times")
    if int(pad) != pad or pad < 1:
        raise ValueError(f"pad must be a positive integer, got {pad!r}")
    detrended = y - np.polyval(np.polyfit(t - t[0], y, 1), t - t[0])
    window = np.hanning(y.size)
    size = 1 << int(np.ceil(np.log2(pad * y.size)))
    amplitude = np.abs(np.fft.rfft(detrended * window, size)) / window.sum()
    return np.fft.rfftfreq(size, step.mean()), amplitude


def dominant_frequency(t, y, *, pad=16) -> float:
    """Frequency of the strongest line of :func:`spectrum` (Hz); the trend is removed first.

    Examples
    --------
    >>> t = np.linspace(0.0, 0.1, 2001)
    >>> round(dominant_frequency(t, np.sin(2 * np.pi * 440.0 * t) + 0.3 * np.sin(2 * np.pi * 1000.0 * t)))
    440
    """
    frequency, amplitude = spectrum(t, y, pad=pad)
    return float(frequency[np.argmax(amplitude)])
