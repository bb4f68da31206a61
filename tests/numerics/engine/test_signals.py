"""Peak, arrival, time of flight, speed and width on traces with known answers."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from ringchain.numerics import signals

T = np.linspace(0.0, 1e-3, 1001)  # 1 us samples


def bump(t0, height=10.0, sigma=2e-5):
    return height * np.exp(-0.5 * ((T - t0) / sigma) ** 2)


def test_peak_is_refined_between_samples():
    t_peak, height = signals.peak(T, bump(3.3e-4 + 0.37e-6))
    # Parabolic refinement of a Gaussian sampled at sigma/20: error O((dt/sigma)^2 dt) ~ 1e-9 s.
    assert t_peak == pytest.approx(3.3037e-4, abs=5e-9)
    assert height == pytest.approx(10.0, rel=1e-3)  # ~ (dt/sigma)^2 / 8


def test_first_pulse_not_the_largest():
    y = bump(2e-4, 5.0) + bump(7e-4, 9.0)
    # A reflection twice as high would hide the leading pulse at the default threshold ...
    assert signals.arrival_time(T, y) == pytest.approx(2e-4, abs=1e-8)
    # ... which is why the threshold can be set.
    assert signals.arrival_time(T, y, threshold=6.0) == pytest.approx(7e-4, abs=1e-8)


def test_time_of_flight_and_speed():
    near, far = bump(2e-4), bump(6.5e-4)
    assert signals.time_of_flight(T, near, far) == pytest.approx(4.5e-4, abs=2e-9)  # both peaks refined ~1e-9 s
    assert signals.wave_speed(T, near, far, 0.24) == pytest.approx(0.24 / 4.5e-4, rel=1e-5)
    with pytest.raises(ValueError, match="far trace peaks first"):
        signals.wave_speed(T, far, near, 0.24)


def test_pulse_width_of_a_gaussian():
    # FWHM = 2 sqrt(2 ln 2) sigma; linear interpolation of the crossings, error ~ dt^2/sigma.
    assert signals.pulse_width(T, bump(5e-4)) == pytest.approx(2 * np.sqrt(2 * np.log(2)) * 2e-5, rel=1e-3)


def test_pulse_width_needs_the_whole_pulse():
    with pytest.raises(signals.TruncatedPulseError, match="does not fall to half its height"):
        signals.pulse_width(T, bump(0.999e-3))


@pytest.mark.parametrize(
    ("t", "y", "message"),
    [(T, np.zeros(1001), "no pulse"), (T[::-1], bump(5e-4), "t must be increasing"),
     (T, bump(5e-4)[:10], "same length"), (T, bump(5e-4), "threshold must be finite")],
)  # fmt: skip
def test_bad_traces_are_refused(t, y, message):
    with pytest.raises(ValueError, match=message):
        signals.peak(t, y, threshold=np.nan if "threshold" in message else None)


# -- the static baseline ---------------------------------------------------------------------------
# A sensor in the hanging chain reads the weight of the rings below it (2.5 N at ring 12 of the
# paper's chain) before the wave comes; a 10 um drop adds a pulse of 1.6 N, and the reflection
# from the support later adds 2 N.


def test_the_pulse_is_read_above_the_static_baseline():
    static, reflection = 2.5, bump(8e-4, 2.0)
    y = static + bump(3e-4, 1.6) + reflection
    # Half the trace's maximum (2.25 N) lies below the static force: measured from zero, the
    # "leading pulse" would start at t = 0 and its maximum would be the reflection.
    assert signals.arrival_time(T, y) == pytest.approx(3e-4, abs=1e-8)  # refined peak of a known bump
    assert signals.peak(T, y, baseline=static)[1] == pytest.approx(static + 1.6, rel=1e-3)  # (dt/sigma)^2/8
    assert signals.estimate_baseline(T, y) == static
    # Two sensors with their own static forces.
    near = 1.2 + bump(2e-4, 1.8)
    assert signals.time_of_flight(T, near, y) == pytest.approx(1e-4, abs=2e-8)
    assert signals.time_of_flight(T, near, y, baseline=(1.2, static)) == pytest.approx(1e-4, abs=2e-8)


def test_a_static_trace_has_no_pulse():
    with pytest.raises(signals.NoPulseError, match=r"no pulse: the trace never rises above its baseline 2\.5"):
        signals.arrival_time(T, np.full(T.size, 2.5))
    with pytest.raises(signals.NoPulseError, match="never reaches the threshold"):
        signals.peak(T, 2.5 + bump(5e-4, 1.0), threshold=4.0)
    with pytest.raises(ValueError, match="must lie above the trace's baseline"):
        signals.peak(T, 2.5 + bump(5e-4, 1.0), threshold=2.0)


# -- truncation and sampling -----------------------------------------------------------------------------
@pytest.mark.parametrize("centre", [1.02e-3, 0.985e-3], ids=["rising-at-the-end", "peak-inside-tail-cut"])
def test_a_pulse_cut_off_by_the_end_of_the_record_is_refused(centre):
    # At 0.985 ms the peak is inside the record but the trace is still at exp(-0.28) = 0.75 of
    # it at the end: the pulse has not passed.
    with pytest.raises(signals.TruncatedPulseError, match="cut off; record for longer"):
        signals.arrival_time(T, bump(centre))


def test_a_pulse_that_began_before_the_record_is_refused():
    with pytest.raises(signals.TruncatedPulseError, match="at the start of the record"):
        signals.arrival_time(T, bump(0.0))
    with pytest.raises(signals.TruncatedPulseError, match="at the start of the record"):
        signals.arrival_time(T, bump(3e-4), baseline=-30.0)  # a wrong baseline puts the start above threshold


def test_a_coarsely_sampled_pulse_is_refused():
    t = np.linspace(0.0, 1e-3, 34)  # 30 us samples: 1.6 per full width at half maximum of sigma = 20 us
    with pytest.raises(signals.UnresolvedPulseError, match=r"1\.\d samples across its full width"):
        signals.peak(t, 10.0 * np.exp(-0.5 * ((t - 3.3e-4) / 2e-5) ** 2))


def profiles(width):
    """A Gaussian and the compact cos^4 pulse (n = 3/2 solitary wave shape) of unit height and
    full width at half maximum ``width``, as functions of time."""
    sigma = width / (2 * np.sqrt(2 * np.log(2)))
    scale = width / (2 * np.arccos(0.5**0.25))  # cos(t/scale)^4 = 1/2 at t = width/2
    return {
        "gaussian": lambda t: np.exp(-0.5 * (t / sigma) ** 2),
        "cos4": lambda t: np.where(np.abs(t / scale) < np.pi / 2, np.cos(t / scale) ** 4, 0.0),
    }


@pytest.mark.parametrize("shape", ["gaussian", "cos4"])
def test_the_resolution_limit_bounds_the_peak_error(shape):
    """At MIN_SAMPLES_PER_WIDTH samples per width the refined peak is within 0.25% of the width in
    time and 0.35% in height, whatever the sampling phase (the constant's comment: 0.21% and
    0.30% at worst, measured over 20 phases)."""
    width = 1.0
    pulse = profiles(width)[shape]
    dt = width / signals.MIN_SAMPLES_PER_WIDTH
    for phase in np.linspace(0.0, 1.0, 20, endpoint=False):
        t = np.arange(-10.0, 10.0, dt) + phase * dt
        t_peak, height = signals.peak(t, pulse(t))
        assert abs(t_peak) < 2.5e-3 * width
        assert abs(height - 1.0) < 3.5e-3


@settings(max_examples=60, deadline=None, derandomize=True)
@given(
    base=st.floats(-1e3, 1e3), height=st.floats(1e-3, 1e3), centre=st.floats(0.2, 0.8),
    samples_per_width=st.floats(5.0, 50.0), shape=st.sampled_from(["gaussian", "cos4"]),
)  # fmt: skip
def test_a_resolved_complete_pulse_is_found_on_any_baseline(base, height, centre, samples_per_width, shape):
    # A rise below signals._NO_PULSE_LEVEL (1e-6) of the trace's magnitude is read as solver noise,
    # not a pulse (test_a_static_trace_has_no_pulse); the sampled peak of a resolved pulse can sit
    # a few per cent below its height, so ten times that level keeps clear of the boundary.
    assume(height > 1e-5 * max(abs(base), abs(base + height)))
    width = 0.05
    t = np.arange(0.0, 1.0, width / samples_per_width)
    y = base + height * profiles(width)[shape](t - centre)
    t_peak, y_peak = signals.peak(t, y)
    # The resolution bound of the test above (0.25% of the width, 0.35% of the height), plus the
    # rounding of a height 1e6 times smaller than the baseline.
    assert abs(t_peak - centre) < 2.5e-3 * width
    assert abs(y_peak - (base + height)) < 3.5e-3 * height + 1e-12 * abs(base)
    assert signals.pulse_width(t, y) == pytest.approx(width, rel=0.05)  # linear crossings, >= 5 samples/width


@settings(max_examples=200, deadline=None)
@given(st.lists(st.floats(-1e6, 1e6), min_size=3, max_size=60), st.sampled_from(["peak", "pulse_width"]))
def test_any_trace_gives_a_finite_reading_or_a_value_error(values, name):
    y = np.array(values)
    t = np.arange(y.size) * 1e-3
    try:
        result = getattr(signals, name)(t, y)
    except ValueError as exc:  # PulseError and its kinds are ValueErrors, each with its reason
        assert str(exc)
        return
    assert np.all(np.isfinite(result))


# --- tail and spectrum ---------------------------------------------------------------------------


def test_spectrum_finds_a_line_under_a_trend():
    t = np.linspace(0.0, 0.02, 4001)
    y = 5.0 + 300.0 * t + 0.8 * np.sin(2 * np.pi * 6395.0 * t + 0.3)
    frequency, amplitude = signals.spectrum(t, y)
    # Zero padding 16x: the line is located to 1/16 of 1/(20 ms) = 3 Hz; a Hann-windowed sine of
    # amplitude A peaks at A/2 (within the scalloping of the padded grid, < 0.1 %).
    assert frequency[np.argmax(amplitude)] == pytest.approx(6395.0, abs=3.2)
    assert amplitude.max() == pytest.approx(0.4, rel=2e-3)
    assert signals.dominant_frequency(t, y) == frequency[np.argmax(amplitude)]


def test_spectrum_needs_even_times_and_a_positive_padding():
    t = np.linspace(0.0, 1.0, 101) ** 2
    with pytest.raises(ValueError, match="evenly spaced"):
        signals.spectrum(t, np.sin(t))
    with pytest.raises(ValueError, match="pad must be a positive integer"):
        signals.spectrum(np.linspace(0.0, 1.0, 11), np.zeros(11), pad=0)


def test_tail_lies_between_the_leading_pulse_and_the_next():
    t = np.linspace(0.0, 1.0, 10001)
    pulse = np.exp(-(((t - 0.1) / 0.02) ** 2))
    ringing = 0.01 * np.sin(300 * t) * (t > 0.15)
    echo = 0.6 * np.exp(-(((t - 0.8) / 0.02) ** 2))
    part = signals.tail(t, pulse + ringing + echo)
    # The pulse falls to 2 % of its height at 0.1 + 0.02 sqrt(ln 50) s; the echo passes 40 % at 0.8 - 0.02 sqrt(ln 1.5).
    assert t[part.start] == pytest.approx(0.1 + 0.02 * np.sqrt(np.log(50.0)), abs=2e-3)  # the ringing shifts it
    assert t[part.stop] == pytest.approx(0.8 - 0.02 * np.sqrt(np.log(1.5)), abs=2e-3)
    assert signals.tail(t, pulse).stop == t.size  # no second pulse: to the end
    with pytest.raises(signals.TruncatedPulseError):  # never falls after its peak: no complete pulse, no tail
        signals.tail(t, t)


# -- many traces at once -------------------------------------------------------------------------------
def reference_peak(t, y, baseline=None):
    """The leading pulse read as the module notes define it, sample by sample in plain Python (an independent
    reader): the exception class a reading raises, or (time, height) of the parabola through the sampled maximum."""
    y = [float(value) for value in y]
    base = float(np.median(y[:5])) if baseline is None else float(baseline)
    top = max(y)
    if not top - base > 1e-6 * max(max(abs(value) for value in y), abs(base)):
        return signals.NoPulseError
    level = base + 0.5 * (top - base)
    start = next(i for i, value in enumerate(y) if value >= level)
    if start == 0:
        return signals.TruncatedPulseError
    stop = next((i for i in range(start, len(y)) if y[i] < level), len(y))
    k = max(range(start, stop), key=lambda i: (y[i], -i))  # the first sampled maximum of the run
    half = base + 0.5 * (y[k] - base)
    right = next((i for i in range(k, len(y)) if y[i] < half), None)
    left = next((i for i in range(k - 1, -1, -1) if y[i] < half), None)
    if right is None or left is None:
        return signals.TruncatedPulseError
    t_left = t[left] + (half - y[left]) * (t[left + 1] - t[left]) / (y[left + 1] - y[left])
    t_right = t[right - 1] + (y[right - 1] - half) * (t[right] - t[right - 1]) / (y[right - 1] - y[right])
    if t_right - t_left < signals.MIN_SAMPLES_PER_WIDTH * max(np.diff(t[left : right + 1])):
        return signals.UnresolvedPulseError
    (t0, t1, t2), (y0, y1, y2) = t[k - 1 : k + 2], y[k - 1 : k + 2]
    a = ((y2 - y1) / (t2 - t1) - (y0 - y1) / (t0 - t1)) / (t2 - t0)  # y = y1 + b (t - t1) + a (t - t1)^2
    if a >= 0:
        return t1, y1
    b = (y0 - y1) / (t0 - t1) - a * (t0 - t1)
    return t1 - b / (2 * a), y1 - b * b / (4 * a)


def random_traces(rng, count):
    """Traces like a batch of sensors': a static level, one to three pulses of random heights, widths and
    places (some cut off by the ends, some too narrow to read), noise; a few flat ones."""
    traces = np.empty((count, T.size))
    for row in traces:
        row[:] = rng.uniform(-5.0, 5.0)
        if rng.random() < 0.05:
            continue  # static: no pulse
        row += 1e-3 * rng.standard_normal(T.size)
        for _ in range(rng.integers(1, 4)):
            row += bump(rng.uniform(-5e-5, 1.05e-3), rng.uniform(0.1, 10.0), rng.uniform(1e-6, 4e-5))
    return traces


def test_many_traces_are_read_as_the_independent_reader_reads_each():
    rng = np.random.default_rng(30)
    traces = random_traces(rng, 300)
    times, heights = signals.peak(T, traces, errors="nan")
    expected = [reference_peak(T, y) for y in traces]
    kinds = {type(e) if isinstance(e, tuple) else e for e in expected}
    assert {tuple, signals.NoPulseError, signals.TruncatedPulseError, signals.UnresolvedPulseError} <= kinds
    for b, (y, reading) in enumerate(zip(traces, expected, strict=True)):
        if isinstance(reading, tuple):
            # The same rule and the same formulas in another order of operations: rounding only (a few ulps of
            # the time's size, which the parabola's vertex can amplify by its conditioning).
            assert (times[b], heights[b]) == pytest.approx(reading, rel=1e-9, abs=0.0), b
            assert signals.peak(T, y) == (times[b], heights[b])  # one trace alone: the same numbers exactly
        else:
            assert np.isnan(times[b]) and np.isnan(heights[b]), b
            with pytest.raises(reading):
                signals.peak(T, y)


def test_many_traces_raise_the_first_failure_naming_it_and_keep_their_shape():
    rng = np.random.default_rng(7)
    good = 2.0 + np.stack([bump(c) for c in rng.uniform(2e-4, 8e-4, 6)])
    times, heights = signals.peak(T, good.reshape(2, 3, T.size))
    assert times.shape == heights.shape == (2, 3)
    assert np.array_equal(times.ravel(), [signals.peak(T, y)[0] for y in good])
    broken = good.copy()
    broken[4] = bump(0.999e-3)  # cut off by the end of the record
    with pytest.raises(signals.TruncatedPulseError, match=r"^trace 4: the leading pulse .* cut off"):
        signals.peak(T, broken)


def test_many_traces_take_a_baseline_each():
    static = np.array([0.5, 2.5, -1.0])
    traces = static[:, None] + np.stack([bump(3e-4, 1.6), bump(5e-4, 0.4), bump(6e-4, 3.0)])
    assert np.array_equal(signals.estimate_baseline(T, traces), [signals.estimate_baseline(T, y) for y in traces])
    times, heights = signals.peak(T, traces, baseline=static)
    for b, y in enumerate(traces):
        assert (times[b], heights[b]) == signals.peak(T, y, baseline=static[b])
    with pytest.raises(ValueError, match=r"baseline must be one number or one per trace \(shape \(3,\)\)"):
        signals.peak(T, traces, baseline=[1.0, 2.0])


def test_many_traces_on_a_small_block_are_read_alike(monkeypatch):
    # Traces are read a block at a time (memory); the blocks must not change a reading or the failure named.
    traces = random_traces(np.random.default_rng(3), 40)
    whole = signals.peak(T, traces, errors="nan")
    monkeypatch.setattr(signals, "_BLOCK_SAMPLES", 7 * T.size)
    assert all(
        np.array_equal(a, b, equal_nan=True) for a, b in zip(whole, signals.peak(T, traces, errors="nan"), strict=True)
    )
    first = int(np.flatnonzero(np.isnan(whole[0]))[0])
    with pytest.raises(signals.PulseError, match=rf"^trace {first}: "):
        signals.peak(T, traces)
