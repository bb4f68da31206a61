"""Peak, arrival, time of flight, speed and width on traces with known answers."""

import numpy as np
import pytest
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
    with pytest.raises(ValueError, match="does not fall to half its peak"):
        signals.pulse_width(T, bump(0.999e-3))


@pytest.mark.parametrize(
    ("t", "y", "message"),
    [(T, np.zeros(1001), "threshold must be positive"), (T[::-1], bump(5e-4), "t must be increasing"),
     (T, bump(5e-4)[:10], "same length")],
)  # fmt: skip
def test_bad_traces_are_refused(t, y, message):
    with pytest.raises(ValueError, match=message):
        signals.peak(t, y)
