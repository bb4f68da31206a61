"""Reading force-time traces: peaks, arrival times, time of flight, speed, pulse width.

Plain functions of NumPy arrays (a time vector ``t`` in s and a trace sampled on it),
used by :class:`ringchain.numerics.Simulation` for its sensor helpers and usable on
measured data.  The wave speed is measured as in the paper (Sec. III.A): the time of
flight between the peak-force arrivals at two sensors.
"""

from __future__ import annotations

import numpy as np
from ringchain.theory import _validate as v

__all__ = ["leading_pulse", "peak", "arrival_time", "time_of_flight", "wave_speed", "pulse_width"]

#: Default threshold of :func:`leading_pulse`, as a fraction of the trace's maximum.
LEADING_PULSE_THRESHOLD = 0.5


def _trace(t, y):
    t = v.as_float("t", t)
    y = v.as_float("signal", y)
    if t.ndim != 1 or y.shape != t.shape:
        raise ValueError(f"t and the signal must be 1-d of the same length, got shapes {t.shape} and {y.shape}")
    if t.size < 3 or np.any(np.diff(t) <= 0):
        raise ValueError("t must be increasing, with at least 3 samples")
    return t, y


def leading_pulse(t, y, threshold=None) -> slice:
    """Samples of the first pulse of ``y``: the first run of samples above ``threshold``.

    Parameters
    ----------
    t : array_like, shape (T,)
        Times, s, increasing.
    y : array_like, shape (T,)
        Trace (e.g. a force, N).
    threshold : float, optional
        Level that defines the pulse; default half the trace's maximum.  The first
        pulse, not the largest one, is the wave's arrival: a reflection from the far end
        can be larger than the incident pulse near it.

    Returns
    -------
    slice
        Indices of the first run of samples with y >= threshold.
    """
    t, y = _trace(t, y)
    if threshold is None:
        threshold = LEADING_PULSE_THRESHOLD * y.max()
    if not threshold > 0:
        raise ValueError(f"the pulse threshold must be positive, got {threshold:g} (is the trace all <= 0?)")
    above = np.flatnonzero(y >= threshold)
    if above.size == 0:
        raise ValueError(f"the trace never reaches the threshold {threshold:g}")
    start = above[0]
    below = np.flatnonzero(y[start:] < threshold)
    stop = start + below[0] if below.size else y.size
    return slice(start, stop)


def peak(t, y, threshold=None) -> tuple[float, float]:
    """Time (s) and height of the maximum of the leading pulse of ``y``.

    The sampled maximum is refined by the parabola through it and its two neighbours
    (error O(dt^3) in time for a smooth peak).

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 11)
    >>> tp, yp = peak(t, 1.0 - (t - 0.33) ** 2)
    >>> round(tp, 12), round(yp, 12)
    (0.33, 1.0)
    """
    t, y = _trace(t, y)
    pulse = leading_pulse(t, y, threshold)
    k = pulse.start + int(np.argmax(y[pulse]))
    if k == 0 or k == y.size - 1:
        return float(t[k]), float(y[k])
    t0, t1, t2 = t[k - 1 : k + 2]
    y0, y1, y2 = y[k - 1 : k + 2]
    # Vertex of the parabola through three (possibly unevenly spaced) points.
    d0, d2 = t0 - t1, t2 - t1
    s0, s2 = (y0 - y1) / d0, (y2 - y1) / d2
    curvature = (s2 - s0) / (d2 - d0)
    if curvature >= 0:
        return float(t1), float(y1)
    slope = s0 - curvature * d0
    shift = -slope / (2.0 * curvature)
    return float(t1 + shift), float(y1 + slope * shift + curvature * shift**2)


def arrival_time(t, y, threshold=None) -> float:
    """Arrival time of the leading pulse: the time of its peak, s (see :func:`peak`)."""
    return peak(t, y, threshold)[0]


def time_of_flight(t, y_near, y_far, threshold=None) -> float:
    """Time between the leading-pulse peaks of two traces, s (paper Sec. III.A)."""
    return arrival_time(t, y_far, threshold) - arrival_time(t, y_near, threshold)


def wave_speed(t, y_near, y_far, distance, threshold=None) -> float:
    """Wave speed, m/s: ``distance`` (m) over the time of flight between two traces."""
    distance = float(v.positive("distance", distance, "m"))
    tof = time_of_flight(t, y_near, y_far, threshold)
    if tof <= 0:
        raise ValueError(f"the far trace peaks first (time of flight {tof:g} s): no wave from near to far")
    return distance / tof


def pulse_width(t, y, threshold=None) -> float:
    """Full width at half maximum of the leading pulse, s.

    The half-maximum crossings on either side of the leading peak are found by linear
    interpolation between samples; the trace must fall below half its peak on both
    sides within the record.

    Examples
    --------
    >>> t = np.linspace(-1.0, 1.0, 2001)
    >>> round(pulse_width(t, np.exp(-t**2 / 0.08)), 6)  # Gaussian, sigma = 0.2: 2 sqrt(2 ln 2) sigma
    0.470964
    """
    t, y = _trace(t, y)
    pulse = leading_pulse(t, y, threshold)
    k = pulse.start + int(np.argmax(y[pulse]))
    half = 0.5 * y[k]
    left = np.flatnonzero(y[:k] < half)
    right = np.flatnonzero(y[k:] < half)
    if left.size == 0 or right.size == 0:
        raise ValueError("the leading pulse does not fall to half its peak within the record")
    i = left[-1]  # y[i] < half <= y[i+1]
    j = k + right[0]  # y[j-1] >= half > y[j]
    t_left = t[i] + (half - y[i]) * (t[i + 1] - t[i]) / (y[i + 1] - y[i])
    t_right = t[j - 1] + (y[j - 1] - half) * (t[j] - t[j - 1]) / (y[j - 1] - y[j])
    return float(t_right - t_left)
