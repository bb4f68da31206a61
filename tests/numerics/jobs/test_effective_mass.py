"""Fitting the power-law lattice's effective mass, low-pass, trailing spectra."""

import numpy as np
import pytest
from ringchain.numerics import Chain, simulate_batch
from ringchain.numerics.jobs.effective_mass import (
    arrival_times,
    fit_effective_mass,
    lowpass,
    predict_effective_mass,
    spectral_peaks,
    trailing_spectrum,
)
from ringchain.theory import Ring, paper_data

RING = Ring.from_aspect_ratio(9.0)
SENSORS = (2, 5)


def test_fit_recovers_a_known_effective_mass():
    """Reference: the power-law lattice itself at m = 0.6 m0; the fit must find 0.6."""
    K, n = RING.power_law()
    truth = Chain.power_law(8, K, n, 0.6 * RING.mass, RING.spacing, m_gravity=RING.mass)
    reference = list(simulate_batch(truth, 8e-4, drop_heights=[0.02, 0.2], n_samples=801))
    fit = fit_effective_mass(reference, RING, sensors=SENSORS)
    # Zero residual at the truth; least squares stops within its tolerances of it (arrival times
    # move by ~0.5 % per % of mass, read from 1 us samples by parabola: ~1e-4).
    assert fit.ratio == pytest.approx(0.6, rel=1e-3)
    assert np.abs(fit.residuals).max() < 1e-4
    assert fit.K == K and fit.n == n and len(fit.lattice) == 2


def test_fit_uses_the_given_power_law():
    K, n = 4.9e6, 1.11  # the paper's Table I values for R/r = 9, in SI
    truth = Chain.power_law(8, K, n, 0.37 * RING.mass, RING.spacing, m_gravity=RING.mass)
    reference = list(simulate_batch(truth, 8e-4, drop_heights=[0.05], n_samples=801))
    fit = fit_effective_mass(reference, RING, sensors=SENSORS, K=K, n=n, cutoff=None)
    assert fit.ratio == pytest.approx(0.37, rel=1e-3)  # as above, raw traces
    assert fit.standard_error < 1e-3  # two residuals, one parameter: from their (tiny) scatter


def test_fit_of_the_dual_spring_lattice():
    truth = Chain.dual_spring(8, RING.K_c, RING.K_b, 0.7 * RING.mass, RING.spacing, m_gravity=RING.mass)
    reference = list(simulate_batch(truth, 8e-4, drop_heights=[0.02, 0.2], n_samples=801))
    fit = fit_effective_mass(reference, RING, model="dual-spring", sensors=SENSORS)
    assert fit.ratio == pytest.approx(0.7, rel=1e-3)  # as for the power-law lattice
    assert fit.K == RING.K_c and fit.n == 1.5
    with pytest.raises(ValueError, match="belong to the power-law lattice"):
        fit_effective_mass(reference, RING, model="dual-spring", K=1.0, n=1.5)
    with pytest.raises(ValueError, match="model must be"):
        fit_effective_mass(reference, RING, model="granular")


def test_lowpass_keeps_slow_signals_in_phase_and_removes_fast_ones():
    t = np.linspace(0.0, 2e-3, 2001)
    pulse = np.exp(-(((t - 1e-3) / 1e-4) ** 2))  # a 0.1 ms pulse: spectrum below ~5 kHz
    ripple = 0.3 * np.sin(2 * np.pi * 25e3 * t)
    filtered = lowpass(t, pulse + ripple, 10e3)
    # Butterworth order 4, twice: 25 kHz falls by (25/10)^8 ~ 1500; the pulse keeps its peak time.
    assert np.abs(filtered - pulse)[200:-200].max() < 0.01
    assert t[np.argmax(filtered)] == pytest.approx(1e-3, abs=1e-6)
    with pytest.raises(ValueError, match="Nyquist"):
        lowpass(t, pulse, 1e6)


def test_trailing_spectrum_finds_the_lines():
    t = np.linspace(0.0, 4e-3, 4001)
    y = 2.0 * np.sin(2 * np.pi * 7e3 * t) + 1.0 * np.sin(2 * np.pi * 18e3 * t) + 5.0 * t  # plus a trend
    f, a = trailing_spectrum(t, y, 1e-3, 4e-3)
    peaks = spectral_peaks(f, a, count=2)
    resolution = 1 / 3e-3  # Hz: the window's length
    assert np.allclose(peaks, [7e3, 18e3], atol=resolution)
    assert a[np.argmin(np.abs(f - 7e3))] == pytest.approx(2.0, rel=0.2)  # Hann window, line between bins


def test_arrival_times_read_the_leading_pulse():
    K, n = RING.power_law()
    chain = Chain.power_law(8, K, n, RING.mass, RING.spacing, m_gravity=RING.mass)
    sim = simulate_batch(chain, 8e-4, drop_heights=[0.05], n_samples=801)[0]
    raw = arrival_times(sim, SENSORS, cutoff=None)
    assert np.allclose(raw, [sim.arrival_time(i) for i in SENSORS])
    # A smooth lattice pulse: the 10 kHz low-pass moves its peak by less than a sample.
    assert np.allclose(arrival_times(sim, SENSORS), raw, atol=1e-6)


@pytest.mark.slow
def test_prediction_on_a_short_chain():
    prediction = predict_effective_mass(9.0, [0.05], n_rings=8, sensors=SENSORS, modes=4, elements=16,
                                        t_end=8e-4, n_samples=801)  # fmt: skip
    assert prediction.paper_ratio == paper_data.TABLE_I[9.0][2]
    assert len(prediction.runs) == 1 and prediction.runs[0].drop_height == 0.05
    # The resolved rings carry their whole mass; the fitted lattice mass lies between the stretch
    # inertia alone and the ring's (0.1-1.5 m0 is the search range's interior).
    assert 0.1 < prediction.ratio < 1.5
    assert np.abs(prediction.fit.residuals).max() < 0.1
    assert set(prediction.fits) == {"power-law", "dual-spring"}
