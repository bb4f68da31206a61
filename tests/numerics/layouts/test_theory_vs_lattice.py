r"""The lattice against Nesterenko's long-wave solitary wave (paper Eq. (8), App. B).

A power-law chain, undamped, without gravity and free at both ends, is struck at ring 0
(``impact_velocity``).  A solitary wave forms within a few widths and then travels
unchanged; between contacts 100 and 200 of a 300-ring chain we measure its peak force
F_m, its speed (time of flight between the force peaks) and its full width at half
maximum, and compare them with ``solitary_wave_speed(F_m, K=K, n=n, m=m, a=a)`` and the FWHM of
``solitary_wave_profile`` (the compact force profile, of support
``solitary_wave_width(n=n, a=a)``).

The long-wave theory is an expansion in eps = a/L, L the support length of the wave;
the lattice differs from it by its long-wave error, which we measured (velocity Verlet,
converged to 1e-4) as

    n          1.5      1.4      1.3      1.2      1.1
    a/L        0.201    0.170    0.135    0.096    0.051
    speed      +1.24%   +0.85%   +0.52%   +0.25%   +0.07%    = +0.27..0.31 (a/L)^2
    FWHM       -5.3%    -4.3%    -3.2%    -2.2%    -1.1%     = -0.22..0.26 (a/L)

The speed error scales as (a/L)^2, the width error roughly as a/L; both shrink as
n -> 1, where the wave widens (L ~ a/(n - 1)).  The tolerances are these measured errors
with margins of 13-30%: |V/V_s - 1| < 0.4 (a/L)^2 and |FWHM/FWHM_theory - 1| < 0.3 a/L.
"""

import numpy as np
import pytest
from ringchain.numerics import Chain, paper_chain, signals, simulate
from ringchain.theory import (
    Ring,
    impact_amplitude,
    impact_speed,
    n_per_mm_to_si,
    paper_data,
    solitary_wave_profile,
    solitary_wave_speed,
    solitary_wave_width,
)
from scipy.optimize import brentq

N_RINGS = 300
NEAR, FAR = 100, 200  # contacts between which the formed wave is measured


def theory_fwhm(F_m, K, n, a):
    """Full width at half maximum of the compact force profile (App. B), m: the profile
    is even and falls monotonically from its centre, so it is twice the root of F = F_m/2
    on the half support."""
    half_support = 0.5 * float(solitary_wave_width(n=n, a=a))

    def excess(x):
        return float(solitary_wave_profile(x, F_m=F_m, K=K, n=n, a=a)) - 0.5 * F_m

    return 2.0 * brentq(excess, 0.0, half_support, xtol=1e-14 * a)


def measure(K, n, m, a, impact_velocity):
    chain = Chain.power_law(N_RINGS, K, n, m, a, support="free")
    # Long enough for the wave to pass contact FAR, not to reach the far end (it travels
    # 250 rings at 0.8 times the theory speed at a rough force scale; measured ~1.0 times).
    t_end = 250 * a / (0.8 * float(solitary_wave_speed(_force_scale(K, n, m, impact_velocity), K=K, n=n, m=m, a=a)))
    # 200 Verlet steps per period: 4 times more change F_m, speed and width by < 1e-4.
    sim = simulate(chain, t_end, impact_velocity=impact_velocity, gravity=False, method="verlet",
                   steps_per_period=200, n_samples=6001)  # fmt: skip
    near, far = sim.contact_force[:, NEAR], sim.contact_force[:, FAR]
    (t_near, F_near), (t_far, F_far) = signals.peak(sim.t, near), signals.peak(sim.t, far)
    speed = (FAR - NEAR) * a / (t_far - t_near)
    width = signals.pulse_width(sim.t, far) * speed
    return F_near, F_far, speed, width


def _force_scale(K, n, m, v):
    """A rough peak force for choosing the duration: a contact absorbing m v^2/2."""
    delta = ((n + 1) * 0.5 * m * v**2 / K) ** (1.0 / (n + 1))
    return K * delta**n


def errors(K, n, m, a, impact_velocity):
    """Peak forces at the two contacts, and the relative speed and width errors against Eq. (8) and
    the FWHM of the compact profile at their mean peak force, with eps = a/L."""
    F_near, F_far, speed, width = measure(K, n, m, a, impact_velocity)
    F_m = 0.5 * (F_near + F_far)
    eps = a / float(solitary_wave_width(n=n, a=a))
    speed_error = speed / float(solitary_wave_speed(F_m, K=K, n=n, m=m, a=a)) - 1.0
    width_error = width / theory_fwhm(F_m, K, n, a) - 1.0
    return F_near, F_far, speed_error, width_error, eps


def check(K, n, m, a, impact_velocity):
    F_near, F_far, speed_error, width_error, eps = errors(K, n, m, a, impact_velocity)
    # The wave is formed: it carries the same peak force at both contacts (measured to 1e-4).
    assert F_far == pytest.approx(F_near, rel=1e-3)
    assert abs(speed_error) < 0.4 * eps**2  # long-wave error, measured 0.27-0.31 eps^2 (module docstring)
    assert abs(width_error) < 0.3 * eps  # long-wave error, measured 0.22-0.26 eps (module docstring)


@pytest.fixture(scope="module")
def errors_by_exponent():
    # Units with K = m = a = 1: the comparison is dimensionless.
    return {n: errors(1.0, n, 1.0, 1.0, 1.0) for n in (1.5, 1.4, 1.3, 1.2, 1.1)}


@pytest.mark.parametrize("n", [1.5, 1.4, 1.3, 1.2, 1.1])
def test_speed_and_width_match_the_long_wave_theory(errors_by_exponent, n):
    F_near, F_far, speed_error, width_error, eps = errors_by_exponent[n]
    assert F_far == pytest.approx(F_near, rel=1e-3)  # a formed wave (measured to 1e-4)
    assert abs(speed_error) < 0.4 * eps**2  # long-wave error, measured 0.27-0.31 eps^2 (module docstring)
    assert abs(width_error) < 0.3 * eps  # long-wave error, measured 0.22-0.26 eps (module docstring)


def test_long_wave_error_shrinks_as_n_tends_to_one(errors_by_exponent):
    speed_errors = [abs(errors_by_exponent[n][2]) for n in (1.5, 1.4, 1.3, 1.2, 1.1)]
    width_errors = [abs(errors_by_exponent[n][3]) for n in (1.5, 1.4, 1.3, 1.2, 1.1)]
    assert speed_errors == sorted(speed_errors, reverse=True)
    assert width_errors == sorted(width_errors, reverse=True)
    # The discrete wave is faster and narrower than the continuum one.
    assert all(errors_by_exponent[n][2] > 0 and errors_by_exponent[n][3] < 0 for n in errors_by_exponent)


@pytest.mark.slow
@pytest.mark.parametrize("aspect_ratio", sorted(paper_data.TABLE_I))
def test_paper_chains_in_si_units(aspect_ratio):
    """Table I chains (SI units, m_eff, a = 2(R - r)), free and without gravity, struck at 1 m/s."""
    chain = paper_chain("power-law", aspect_ratio=aspect_ratio)
    K_mm, n, _ = paper_data.TABLE_I[aspect_ratio]
    assert chain.K == float(n_per_mm_to_si(K_mm, n=n))
    check(chain.K, chain.n, chain.m, chain.a, 1.0)


@pytest.mark.parametrize("law", ["hertz", "ring"])
def test_a_simulated_drop_launches_the_wave_the_impact_law_predicts(law):
    """Issue 24, item 16: :func:`ringchain.theory.impact_amplitude` against drops on the R/r = 9 ring's chain.

    The drop protocol (ring 0 falls h and strikes the chain at sqrt(2 g h)) on a chain at rest, without gravity
    (a hanging chain's tension grows along it and reshapes the wave; the law is that of a chain at rest), in SI:
    the Hertz contact alone (n = 3/2, K_c) and the ring's series law (n = 1.107, Eq. 4).  The formed wave, read at
    contacts 80 and 100 of 160, against the amplitude whose solitary-wave energy is the striker's m v0^2/2.
    """
    ring = Ring.from_aspect_ratio(9.0)
    K, n = (float(ring.K_c), 1.5) if law == "hertz" else ring.power_law()
    chain = Chain.power_law(160, K, n, ring.mass, ring.spacing)
    heights = [0.1, 0.5]
    predicted = impact_amplitude(impact_speed(np.array(heights)), K=K, n=n, m=ring.mass, a=ring.spacing)
    speed = float(solitary_wave_speed(predicted.min(), K=K, n=n, m=ring.mass, a=ring.spacing))
    t_end = 110 * ring.spacing / (0.9 * speed)  # past contact 100 at the slower wave (Eq. (8) within 10 %)
    for h, F_law in zip(heights, predicted, strict=True):
        # Verlet at 200 steps per period, as the strike of the module (F_m changes by < 1e-4 with 400).
        sim = simulate(chain, t_end, drop_height=h, gravity=False, method="verlet", steps_per_period=200,
                       n_samples=4001)  # fmt: skip
        F_80, F_100 = (signals.peak(sim.t, sim.contact_force[:, c])[1] for c in (80, 100))
        assert F_100 == pytest.approx(F_80, rel=1e-3)  # formed: measured 3e-4 (n = 1.107), 2e-7 (n = 3/2)
        # The energy the wave leaves behind: measured 1.19 % (n = 3/2) and 1.36 % (n = 1.107) below the law at
        # both heights, as on the strikes of tests/numerics/layouts/test_linear_waves.py (1.1-1.4 %); the band is that
        # with 0.6 % to either side.  A kinetic-energy density 53 % too large puts the lattice 12-15 % above the
        # law (measured).
        assert 0.98 < F_100 / F_law < 0.995, (h, F_100 / F_law)
