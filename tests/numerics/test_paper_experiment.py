"""The paper's drop experiment (Sec. III): 20 rings, R/r = 9, sensors in rings 6 and 12.

Both models (Table I: K = 2284 N/mm^n, n = 1.11, m_eff/m0 = 0.37; the dual-spring chain
with K_c, K_b of the ring), hanging under gravity, struck by the lowest ring dropped
from millimetres to tens of centimetres.
"""

import numpy as np
import pytest
from ringchain.numerics import Chain, paper_experiment, simulate_batch
from ringchain.theory import paper_data
from scipy.signal import find_peaks

HEIGHTS = [0.001, 0.01, 0.1, 0.5]  # m
NEAR, FAR = paper_data.SENSOR_RINGS
T_END = 2e-3  # s


@pytest.fixture(scope="module", params=["power-law", "dual-spring"])
def runs(request):
    return simulate_batch(Chain.from_paper(request.param), T_END, drop_heights=HEIGHTS)


def test_a_leading_pulse_reaches_both_sensors(runs):
    for run in runs:
        t_near, t_far = run.arrival_time(NEAR), run.arrival_time(FAR)
        assert 0 < t_near < t_far < T_END
        # The pulse keeps its strength from ring 6 to ring 12 (a solitary wave, not a spreading
        # linear one): measured within 11%, the hanging pre-load growing up the chain.
        assert run.peak_force(FAR) == pytest.approx(run.peak_force(NEAR), rel=0.15)


def test_higher_drops_give_stronger_and_faster_pulses(runs):
    peaks = [run.peak_force(NEAR) for run in runs]
    flights = [run.time_of_flight(NEAR, FAR) for run in runs]
    assert peaks == sorted(peaks)
    assert flights == sorted(flights, reverse=True)  # amplitude-dependent speed


def trailing_maxima(run, ring):
    """Local maxima standing out by 1% of the peak after the leading pulse: from one width
    after its peak, over 0.4 ms (before the reflection from the support comes back)."""
    t_peak, width = run.arrival_time(ring), run.pulse_width(ring)
    window = (run.t > t_peak + width) & (run.t < t_peak + width + 4e-4)
    trace = run.sensor(ring)
    peaks, _ = find_peaks(trace[window], prominence=0.01 * trace.max())
    return peaks.size


def test_only_the_dual_spring_chain_rings_after_the_pulse(runs):
    counts = [trailing_maxima(run, ring) for run in runs for ring in (NEAR, FAR)]
    if runs.chain.model == "dual-spring":
        # The rings' bending modes ring on, a maximum every ~0.16 ms standing out by 2-22% of
        # the peak: measured 2-3 maxima in 0.4 ms.
        assert min(counts) >= 2
    else:
        assert max(counts) == 0  # one compact pulse, then the contacts relax


def test_times_of_flight_are_fractions_of_a_millisecond(runs):
    flights = np.array([run.time_of_flight(NEAR, FAR) for run in runs])
    # Measured: 0.49-0.43 ms (power law), 0.35-0.33 ms (dual spring).  The paper's
    # "0.426 s" and "0.348 s" are three orders of magnitude away: they must be ms.
    assert np.all((1e-4 < flights) & (flights < 1e-3))
    quoted = paper_data.ARRIVAL_TIMES_AS_PRINTED
    assert quoted["low amplitude"] > 100 * flights.max()


def test_neither_model_spans_both_quoted_times(runs):
    """The paper's low/high-amplitude times differ by 22%; over 1 mm to 50 cm of drop height
    the power-law chain's time of flight changes by 14% and the dual-spring chain's by 7%:
    no one drop range of one model reaches both (the speed grows only as F_m^((n-1)/2n),
    F_m^0.05 for n = 1.11)."""
    flights = [run.time_of_flight(NEAR, FAR) for run in runs]
    quoted = paper_data.ARRIVAL_TIMES_AS_PRINTED
    assert max(flights) / min(flights) < quoted["low amplitude"] / quoted["high amplitude"]


def test_paper_experiment_reads_the_two_sensors():
    result = paper_experiment(0.01, "dual-spring")
    sim = result.simulation
    assert result.sensors == (NEAR, FAR)
    assert result.impact_velocity == pytest.approx(np.sqrt(2 * 9.80665 * 0.01), rel=1e-15)
    assert result.peak_forces == (sim.peak_force(NEAR), sim.peak_force(FAR))
    assert result.time_of_flight == result.arrival_times[1] - result.arrival_times[0]
    assert result.wave_speed == pytest.approx((FAR - NEAR) * sim.chain.a / result.time_of_flight, rel=1e-14)
