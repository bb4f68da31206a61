r"""The lattice against the linear theory and the pulse invariants (:mod:`ringchain.theory.linear`, ``.pulse``).

1. Dispersion.  A chain hanging from its top support, without gravity, every bond
   pre-stretched to the same force F_0: the free lower end unloads, and that unloading
   travels up at the sound speed, so the middle of a long chain stays uniform for a
   while.  A small standing packet with carrier q sits there; the Bloch amplitude
   Z(t) = sum_j x_j(t) exp(-i q a j) over the packet's rings obeys, for the linear lattice,
   Z'' = -omega(q)^2 Z exactly (one branch), or for the two sites of a dual-spring ring
   with only the lower halves displaced, Z(t)/Z(0) = [cos(omega_a t) + cos(omega_o t)]/2.
   Fitting these to the lattice's Z(t) measures omega(q).  Measured agreement with
   :func:`~ringchain.theory.dispersion`: better than 1e-7 (paper chains, F_0 = 2 N,
   q a = 0.5, 1.5, 2.5, both models, both branches).
2. Trailing oscillations.  The paper's 20-ring dual-spring chain after a drop: behind the
   leading pulse the contacts are slack (median force 0), where the chain's bands are
   the acoustic band collapsed to 0 and the optical band flattened onto the ring's own
   bending mode 2 sqrt(K_b/m) (6.39 kHz); the dominant frequency of ring 6 between the
   pulse and its reflection from the support sits just above that edge, lifted by the
   brief re-engagements of the contacts: +5.0 % after a 50 mm drop (contacts slack 68 %
   of the time), +1.4 % after 0.2 m (83 %).  After a 2 mm drop the contacts stay taut and
   the tail is weak and not at any one edge: there the prediction does not apply.
3. Invariants and impact law.  Power-law chains (K = m = a = 1) struck at ring 0; the
   formed wave is measured around contact 110 of 200.  Energy and momentum inside it
   (rings within two support lengths of its peak) against
   :func:`~ringchain.theory.solitary_wave_energy` and ``solitary_wave_momentum`` at
   its measured peak force; the long-wave error, measured (eps = a/L):

       n          1.5      1.4      1.3      1.2
       eps        0.201    0.170    0.135    0.096
       energy     +1.39%   +1.09%   +0.80%   +0.52%   = +0.054..0.069 eps
       momentum   -0.84%   -0.86%   -0.82%   -0.67%   = -0.042..0.070 eps

   (n = 1.1, eps = 0.051, on 460 rings: +0.25 % and -0.42 %.)  Tolerances: 0.09 eps for
   the energy, 0.1 eps for the momentum.  The energy fraction of the impact in the wave
   is 99.4 % (n = 1.5) to 97.6 % (n = 1.1); its momentum is 1.14 to 1.53 times the
   striker's.  Impact law (energy conservation) over three decades of v0: exponent
   2n/(n+1) to 1.4e-5 (the lattice is exactly scale invariant: x -> lambda^(2/(n+1)) x,
   t -> lambda^(-(n-1)/(n+1)) t maps the run at v0 onto the run at lambda v0, so this
   checks the scaling and the solver), and peak force 1.1-1.4 % below
   :func:`~ringchain.theory.impact_amplitude` for n = 1.1-1.5 (tolerance 2 %).
4. Travel time.  A smooth force pulse (rms width 8 rings) launched up the hanging chain
   (the paper's chains, 140 rings): its peak goes from ring 55 to ring 100 in the time
   :func:`~ringchain.theory.linear_travel_time` sums over the graded chain to 0.1-0.17 %
   (+0.17 % power law n = 1.11, -0.16 % dual spring, +0.10 % n = 1.5; the pulse's
   dispersion, about a^2/(16 sigma^2) = 0.1 %, is of that size); a uniform speed taken at
   ring 55 misses by 1.2-5 %.
"""

import numpy as np
import pytest
from ringchain.numerics import STANDARD_GRAVITY, Chain, paper_chain, signals, simulate, simulate_batch
from ringchain.theory import (
    band_edges,
    dispersion,
    impact_amplitude,
    linear_travel_time,
    solitary_wave_energy,
    solitary_wave_momentum,
    solitary_wave_speed,
    solitary_wave_width,
    sound_speed,
)
from scipy.optimize import least_squares

F_0 = 2.0  # N: the static force of the dispersion test, about that of contact 8 of the hanging paper chain


def paper_parameters(model):
    chain = paper_chain(model)
    return dict(model=model, K=chain.K, n=chain.n, m=chain.m, a=chain.a, K_b=chain.K_b)


# --- 1. dispersion ------------------------------------------------------------------------------------------


def uniform_state(chain, force):
    """Site displacements with every bond carrying ``force`` (fixed top support)."""
    return chain.displacement_from_extension(chain.network().extension_at(force))


def bloch_amplitude(chain, params, qa, sigma=10.0, periods=4.0):
    """t and Z(t)/Z(0) of a standing packet on the lower half of each ring (module docstring, 1.)."""
    c = float(sound_speed(F_0=F_0, **params))
    slowest = c * 2 * np.sin(qa / 2) / chain.a  # below the acoustic frequency at q, for the duration only
    t_end = periods * 2 * np.pi / slowest
    reach = int(np.ceil(c * t_end / chain.a)) + 2  # rings crossed at the sound speed, the fastest signal
    half = int(4 * sigma) + reach  # the packet spreads at most this far
    centre = half + int(1.25 * reach) + 20  # the unloading from the free end must not reach the window
    n_rings = centre + half + 5
    if chain.model == "power-law":
        long_chain = Chain.power_law(n_rings, chain.K, chain.n, chain.m, chain.a)
    else:
        long_chain = Chain.dual_spring(n_rings, chain.K, chain.K_b, chain.m, chain.a)
    x_eq = uniform_state(long_chain, F_0)
    j = np.arange(n_rings)
    e0 = (F_0 / chain.K) ** (1 / chain.n)
    packet = 1e-3 * e0 / qa * np.exp(-((j - centre) ** 2) / (2 * sigma**2)) * np.cos(qa * j)  # strain ~ 1e-3
    dx = np.zeros(long_chain.n_sites)
    dx[:: long_chain.sites_per_ring] = packet
    sim = simulate(long_chain, t_end, initial=(x_eq + dx, np.zeros_like(dx)), gravity=False, n_samples=4001)
    k = long_chain.sites_per_ring
    window = slice(centre - half, centre + half + 1)
    lower = sim.x[:, ::k][:, window] - x_eq[::k][window]
    Z = lower @ np.exp(-1j * qa * j[window])
    return sim.t, Z / Z[0]


def spectral_peaks(t, y, count, pad=16):
    """Angular frequencies of the ``count`` strongest lines of y (:func:`~ringchain.numerics.signals.spectrum`)."""
    frequency, amplitude = signals.spectrum(t, y, pad=pad)
    lobe = int(2.5 * frequency.size * 2 / (pad * y.size)) + 1  # the Hann main lobe: 2 unpadded bins either side
    peaks = []
    for _ in range(count):
        i = int(np.argmax(amplitude))
        peaks.append(2 * np.pi * frequency[i])
        amplitude[max(i - lobe, 0) : i + lobe] = 0.0
    return sorted(peaks)


@pytest.mark.parametrize("model", ["power-law", "dual-spring"])
@pytest.mark.parametrize("qa", [0.5, 1.5, 2.5])
def test_small_packet_follows_the_dispersion_relation(model, qa):
    params = paper_parameters(model)
    chain = paper_chain(model)
    t, z = bloch_amplitude(chain, params, qa)
    y = z.real
    # Z stays real: no travelling component, and nothing else enters the window (measured |imag| < 3e-7).
    assert np.abs(z.imag).max() < 1e-5
    guesses = spectral_peaks(t, y, 1 if model == "power-law" else 2)  # the lattice's own lines, no theory
    if model == "power-law":
        fit = least_squares(lambda p: p[0] * np.cos(p[1] * t) - y, [1.0, guesses[0]])
        measured = fit.x[1:2]
    else:
        two_lines = lambda p: p[0] * np.cos(p[1] * t) + p[2] * np.cos(p[3] * t) - y  # noqa: E731
        fit = least_squares(two_lines, [0.5, guesses[0], 0.5, guesses[1]])
        measured = fit.x[[1, 3]]
        np.testing.assert_allclose(fit.x[[0, 2]], 0.5, atol=1e-3)  # both branches weigh 1/2 (equal half masses)
    predicted = dispersion(qa / chain.a, F_0=F_0, **params)
    # The issue asks 1 %; measured < 1e-5: the strain of 1e-3 of the static one shifts the
    # frequency by ~1e-6 (second order), the rest is the solver (rtol 1e-9) and the window.
    np.testing.assert_allclose(measured, predicted, rtol=1e-4)


# --- 2. trailing oscillations ------------------------------------------------------------------------------


def trailing_tail(sim, ring):
    """Dominant frequency (Hz) of the sensor of ``ring`` between the leading pulse and the reflected one,
    the median force of its two contacts there (N) and the fraction of that time they are slack."""
    force = sim.sensor(ring)
    part = signals.tail(sim.t, force)  # from 2 % above the static force to the pulse reflected by the support
    assert part.stop < sim.t.size  # the reflection came back within the record
    frequency = signals.dominant_frequency(sim.t[part], force[part])  # located to 0.6 % of the edge frequency
    contacts = sim.contact_force[part, ring - 1 : ring + 1]
    return frequency, float(np.median(contacts)), float(np.mean(contacts <= 0.0))


@pytest.mark.parametrize(("drop_height", "bound"), [(0.05, 0.06), (0.2, 0.02)])
def test_trailing_oscillation_sits_at_the_ring_bending_edge(drop_height, bound):
    chain = paper_chain("dual-spring")
    sim = simulate(chain, 2.5e-3, drop_height=drop_height, n_samples=25001)
    frequency, residual, slack = trailing_tail(sim, 6)
    assert residual == 0.0 and slack > 0.5  # behind the pulse the contacts are slack
    edges = band_edges(model="dual-spring", F_0=residual, K=chain.K, n=chain.n, m=chain.m, K_b=chain.K_b)
    # At F_0 = 0 the optical band is flat: both its edges are the ring's bending mode.
    predicted = float(edges.optical_bottom) / (2 * np.pi)
    assert float(edges.optical_top) == pytest.approx(float(edges.optical_bottom), rel=1e-12)
    # Measured +5.0 % (50 mm) and +1.4 % (0.2 m): the contacts re-engage 32 % and 17 % of the
    # time, which lifts the frequency above the edge; the FFT grid is 0.6 % of it.
    assert -0.006 < frequency / predicted - 1 < bound


# --- 3. invariants and the impact law --------------------------------------------------------------------

N_RINGS, NEAR, MID, FAR = 200, 100, 110, 120
SPEEDS = np.array([0.01, 0.1, 1.0, 10.0])  # three decades of impact speed (units K = m = a = 1)


def formed_wave(n):
    """The formed wave in a power-law chain struck at each of SPEEDS: (support length, rows of peak force,
    energy and momentum)."""
    chain = Chain.power_law(N_RINGS, 1.0, n, 1.0, 1.0, support="free")
    slowest = float(impact_amplitude(SPEEDS.min(), K=1.0, n=n, m=1.0, a=1.0))
    # Until the slowest wave passes contact FAR + 10 (its speed from Eq. (8), within 2 %).
    t_end = (FAR + 10) / (0.98 * float(solitary_wave_speed(slowest, K=1.0, n=n, m=1.0, a=1.0)))
    # Verlet at 200 steps per period: F_m, E and P change by < 1e-5 with 400 (the error grows with the
    # distance travelled; see tests/numerics/layouts/test_theory_vs_lattice.py).
    batch = simulate_batch(chain, t_end, impact_velocities=SPEEDS, gravity=False, method="verlet",
                           steps_per_period=200, n_samples=3001)  # fmt: skip
    support = float(solitary_wave_width(n=n, a=1.0))
    rows = []
    for run in batch:
        F_near, F_far = (signals.peak(run.t, run.contact_force[:, c])[1] for c in (NEAR, FAR))
        k = int(np.argmin(np.abs(np.argmax(run.contact_force, axis=1) - MID)))  # the peak at contact MID
        peak = int(np.argmax(run.contact_force[k]))
        window = slice(peak - int(2 * support), peak + int(2 * support) + 1)
        e = chain.network().extension(run.x[k])
        kinetic = 0.5 * run.u[k, window] ** 2
        contact = np.maximum(e[window], 0.0) ** (n + 1) / (n + 1)
        rows.append(dict(F_near=F_near, F_far=F_far, F_m=0.5 * (F_near + F_far),
                         energy=kinetic.sum() + contact[:-1].sum(), momentum=-run.u[k, window].sum()))  # fmt: skip
    return support, rows


@pytest.fixture(scope="module", params=[1.5, 1.2])
def struck(request):
    return request.param, *formed_wave(request.param)


def test_the_wave_is_formed(struck):
    _, _, rows = struck
    for row in rows:
        assert row["F_far"] == pytest.approx(row["F_near"], rel=1e-3)  # the same peak 20 rings apart


def test_energy_and_momentum_of_the_formed_wave(struck):
    n, support, rows = struck
    eps = 1.0 / support  # a/L
    for row, v0 in zip(rows, SPEEDS, strict=True):
        energy = float(solitary_wave_energy(row["F_m"], K=1.0, n=n, m=1.0, a=1.0))
        momentum = float(solitary_wave_momentum(row["F_m"], K=1.0, n=n, m=1.0, a=1.0))
        assert abs(row["energy"] / energy - 1) < 0.09 * eps  # long-wave error, measured 0.054-0.069 eps
        assert abs(row["momentum"] / momentum - 1) < 0.10 * eps  # measured 0.042-0.070 eps
        # The wave takes nearly all the striker's energy (98-99.4 %) but more than its momentum.
        assert 0.97 < row["energy"] / (0.5 * v0**2) < 1.0
        assert row["momentum"] / v0 > 1.1


def test_impact_law_over_three_decades(struck):
    n, _, rows = struck
    F_m = np.array([row["F_m"] for row in rows])
    slope = np.polyfit(np.log(SPEEDS), np.log(F_m), 1)[0]
    # Exact for the lattice equations (module docstring); one Verlet step for all four runs and the
    # sampled peaks leave 1.4e-5.
    assert slope == pytest.approx(2 * n / (n + 1), rel=1e-4)
    predicted = impact_amplitude(SPEEDS, K=1.0, n=n, m=1.0, a=1.0)
    # Energy conservation; measured 1.1-1.4 % low for n = 1.1-1.5, the same at every v0 (the energy
    # the wave leaves behind, 0.6-2.4 %, and the long-wave error of its energy, +1.39 to +0.25 %, add).
    np.testing.assert_allclose(F_m / predicted, 1.0, atol=0.02)
    assert np.all(F_m < predicted)


# --- 4. travel time in the hanging chain ------------------------------------------------------------------


def upgoing_pulse(chain, centre, sigma, relative=1e-3):
    """(x0, u0): the hanging equilibrium plus a small force pulse travelling up (WKB-matched velocity)."""
    lat = chain.network()
    e_static = chain.static_extension()
    tension = lat.forces(e_static)
    k = chain.sites_per_ring
    bond_position = (np.arange(lat.n_links) + 1) / k - 0.5  # in rings: contact j-(j+1) at j + 1/2
    pulse = relative * tension * np.exp(-((bond_position - centre) ** 2) / (2 * sigma**2))
    stiffness = lat.stiffness(e_static)
    x0 = chain.displacement_from_extension(e_static + pulse / stiffness)
    site_position = (np.arange(chain.n_sites) + 0.5) / k - 0.5
    force = np.interp(site_position, bond_position, tension)
    c = sound_speed(model=chain.model, F_0=force, K=chain.K, n=chain.n, m=chain.m, a=chain.a, K_b=chain.K_b)
    # A wave f(x - c t) moving up: u_t = -c u_x = -c (strain) = -c dF/(k_eff a) = -dF a/(m c).
    u0 = -np.interp(site_position, bond_position, pulse) * chain.a / (chain.m * c)
    return x0, u0


@pytest.mark.parametrize(
    "chain",
    [
        paper_chain("power-law", n_rings=140),
        paper_chain("dual-spring", n_rings=140),
        Chain.power_law(140, 1e9, 1.5, 0.01, 0.04, m_gravity=0.02),  # Hertz-like: a steeper grading
    ],
    ids=["power-law", "dual-spring", "power-law-n1.5"],
)
def test_travel_time_of_a_small_pulse_up_the_hanging_chain(chain):
    low, high = 55, 100
    x0, u0 = upgoing_pulse(chain, centre=30, sigma=8.0)
    params = dict(model=chain.model, K=chain.K, n=chain.n, m=chain.m, a=chain.a, K_b=chain.K_b)
    t_end = float(linear_travel_time(0, high + 8, m_gravity=chain.m_gravity, **params))
    sim = simulate(chain, t_end, initial=(x0, u0), gravity=True, n_samples=8001)
    dynamic = sim.sensor_force - sim.sensor_force[0]
    flight = signals.time_of_flight(sim.t, dynamic[:, low], dynamic[:, high])
    wkb = float(linear_travel_time(low, high, m_gravity=chain.m_gravity, **params))
    # WKB and dispersion (about a^2/(16 sigma^2) = 0.1 % for the peak); measured 0.10-0.17 %.
    assert flight / wkb - 1 == pytest.approx(0.0, abs=0.004)
    # The grading matters: one speed, that at the lower ring, misses by 1.2-5 %.
    uniform = (high - low) * chain.a / float(sound_speed(F_0=(low + 1) * chain.m_gravity * STANDARD_GRAVITY, **params))
    assert abs(flight / uniform - 1) > 0.01
