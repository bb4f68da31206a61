"""The formed compact wave's loss in a disordered power-law chain follows the small-phase law at the paper's n.

The law of :func:`ringchain.theory.disorder_attenuation_length` takes the loss per ring as sigma_Z^2 theta^2
averaged over the wave's strain spectrum (a^2 <q^2>); the junction model's sin^2(theta) averaged the same way
gives a decay length a^2 <q^2>/<sin^2> times longer (1.31 at n = 1.11, 2.13 at n = 1.5). The engine's chains
decide between the two (book chapter "Disorder", section "Mechanism or coincidence?").
"""

import numpy as np
import pytest
from ringchain.numerics import Chain, signals, simulate
from ringchain.theory import (
    chain_impedance_spread,
    disorder_attenuation_length,
    impact_amplitude,
    solitary_wave_profile,
    solitary_wave_speed,
    solitary_wave_width,
)

A, M, K, RINGS = 0.04, 0.01, 1.0e9, 300  # a chain chosen for the test (the lattice is scale free)


def sin_squared_factor(n):
    """a^2 <q^2> / <sin^2(q a)> over the power spectrum of the compact wave's strain profile (a = 1)."""
    x = np.linspace(-200.0, 200.0, 2**16)
    strain = solitary_wave_profile(x, F_m=1.0, K=1.0, n=n, a=1.0) ** (1 / n)
    power = np.abs(np.fft.rfft(strain)) ** 2
    phase = 2 * np.pi * np.fft.rfftfreq(x.size, d=x[1] - x[0])
    return np.sum(phase**2 * power) / np.sum(np.sin(phase) ** 2 * power)


def measured_over_law(n, members=8, seed=5):
    """The measured decay length over the law's, its standard error, and the law's sin^2 factor."""
    first, last = int(np.ceil(3 * float(solitary_wave_width(n=n, a=1.0)))), RINGS - 40
    V0 = float(solitary_wave_speed(impact_amplitude(1.0, K=K, n=n, m=M, a=A), K=K, n=n, m=M, a=A))
    t_end = (last + 10) * A / (0.75 * V0)

    def peaks(chain):
        run = simulate(chain, t_end, impact_velocity=1.0, gravity=False, method="verlet", n_samples=4001)
        return signals.peak(run.t, run.contact_force[:, first:last].T)[1]  # every contact's trace, read at once

    ordered = peaks(Chain.power_law(RINGS, K, n, M, A, support="free"))
    rng = np.random.default_rng(seed)
    slopes, sigmas = [], []
    for _ in range(members):
        m_, K_ = np.exp(0.15 * rng.standard_normal(RINGS)), np.exp(0.2 * rng.standard_normal(RINGS - 1))
        m_, K_ = M * m_ / m_.mean(), K * K_ / K_.mean()
        ratio = np.log(peaks(Chain.power_law(RINGS, K_, n, m_, A, support="free")) / ordered)
        slopes.append(np.polyfit(np.arange(first, last), ratio, 1)[0])
        sigmas.append(float(chain_impedance_spread(K=K_, n=n, m=m_, lags=0)))
    slopes = np.array(slopes)
    law = float(disorder_attenuation_length(n=n, a=1.0, sigma_Z=np.sqrt(np.mean(np.square(sigmas)))))
    error = slopes.std(ddof=1) / np.sqrt(members) / slopes.mean() ** 2 / law
    return -1 / slopes.mean() / law, error, sin_squared_factor(n)


@pytest.mark.slow
@pytest.mark.parametrize("n", [1.11, 1.5])
def test_the_decay_length_follows_the_small_phase_law(n):
    ratio, error, factor = measured_over_law(n)
    # Measured 1.2 (n = 1.11) and 1.1 (n = 1.5) with 12 members (the book); the law is a leading-order estimate
    # (the theory module's notes: 1.08-1.10 at n = 1.2 and 1.5). 0.9-1.35 with three standard errors.
    assert 0.9 - 3 * error < ratio < 1.35 + 3 * error
    # At n = 1.5 the sin^2 form's length is 2.1 times the law's: the measurement must lie well below it.
    if n == 1.5:
        assert ratio + 3 * error < 0.7 * factor
