"""A small pulse across the junction of two chains: the lattice's reflection and transmission.

The experiment behind :func:`ringchain.theory.junction_coefficients`: two chains of one model
joined end to end (contact stiffness and ring mass changing at one contact), held at a static
force F_0 in every contact, and a long Gaussian pulse of small force travelling from the first
into the second.  The sensors read the incident, reflected and transmitted pulses.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from ringchain.theory import STANDARD_GRAVITY, impedance, junction_coefficients, sound_speed
from ringchain.theory import _validate as v
from scipy.special import erf

from ..engine.integrate import simulate
from ..layouts.chain import MODELS, Chain, initial_state

__all__ = ["JunctionReading", "junction_pulse"]


@dataclass(frozen=True)
class JunctionReading:
    """Forces of the reflected and transmitted pulses over the incident one, lattice and theory.

    Attributes
    ----------
    R, T : float
        Read from the lattice: the largest excursion of the force at a contact 15 rings
        before the junction after the incident pulse has passed, and at a contact 15 rings
        after it, each over the incident pulse's.
    R_theory, T_theory : float
        :func:`ringchain.theory.junction_coefficients` of the two chains' impedances.
    Z1, Z2 : float
        :func:`ringchain.theory.impedance` of the two chains, N s/m.
    """

    R: float
    T: float
    R_theory: float
    T_theory: float
    Z1: float
    Z2: float


def junction_pulse(model, *, K, m, n=1.5, K_b=3.3e6, a=0.04, F_0=5.0, amplitude=0.02, rings=(50, 40), width=4.0,
                   rtol=1e-10) -> JunctionReading:  # fmt: skip
    """Send a small long pulse from one chain into another and read its reflection and transmission.

    Parameters
    ----------
    model : {"power-law", "dual-spring"}
    K : (float, float)
        Contact stiffness of the first and the second chain, N/m^n (K_c for the dual-spring model).
    m : (float, float)
        Inertial ring mass of each chain, kg.
    n : float, optional
        Contact exponent (3/2 for the dual-spring model).
    K_b : float, optional
        Bending stiffness of every ring, N/m (dual-spring model).
    a : float, optional
        Distance between ring centres, m.
    F_0 : float, optional
        Static force in every contact, N: the weight of ring 0 alone (the other rings weigh
        1e-9 kg), so that the chain is uniformly stretched.
    amplitude : float, optional
        Peak force of the pulse over F_0.
    rings : (int, int), optional
        Rings of each chain; the pulse starts centred on ring 20 of the first.  The second is
        lengthened if need be, so that nothing the support reflects comes back during the run.
    width : float, optional
        Standard deviation of the Gaussian pulse, in spacings a.
    rtol : float, optional
        Tolerance of the integration (odeint).

    Returns
    -------
    JunctionReading

    Notes
    -----
    The pulse is a travelling wave of the long-wave theory: displacement U(X - c1 t) with
    strain dF/(Z1 c1) under a Gaussian of force, and velocity -c1 U'.  The contact between the
    last ring of the first chain and the first of the second is the junction and has the first
    chain's stiffness.
    """
    v.choice("model", model, MODELS)
    (K1, K2), (m1, m2) = (tuple(float(x) for x in v.positive(name, pair)) for name, pair in (("K", K), ("m", m)))
    N1, N2 = (int(x) for x in rings)
    if N1 < 36 or N2 < 16:
        raise ValueError(f"rings must be at least (36, 16) for the pulse and the sensors to fit, got {rings!r}")
    if model == "dual-spring":
        n = 1.5
    else:
        K_b = None
    sides = [dict(model=model, F_0=F_0, K=k, n=n, m=mass, a=a, K_b=K_b) for k, mass in ((K1, m1), (K2, m2))]
    c1, c2 = (float(sound_speed(**side)) for side in sides)
    Z1, Z2 = (float(impedance(**side)) for side in sides)
    X0, w, dF = 20 * a, width * a, amplitude * F_0
    near, far = N1 - 15, N1 + 15  # contacts in chain 1 and in chain 2
    t_end = ((N1 - 20) + 15) * a / c1 + 15 * a / c2 + 6 * w / min(c1, c2)
    # Chain 2 long enough that nothing reflected by the support comes back within t_end.
    ahead = c2 * (t_end - ((N1 - 20) * a - 4 * w) / c1) + 4 * w
    N2 = max(N2, int(np.ceil(ahead / a)) + 2)
    n_rings = N1 + N2
    # Contact N1 - 1, between the last ring of chain 1 and the first of chain 2, is the junction.
    K_contacts, masses = np.r_[np.full(N1, K1), np.full(N2, K2)], np.r_[np.full(N1, m1), np.full(N2, m2)]
    m_gravity = np.full(n_rings, 1e-9)
    m_gravity[0] = F_0 / STANDARD_GRAVITY
    if model == "power-law":
        chain = Chain.power_law(n_rings, K=K_contacts, n=n, m=masses, a=a, m_gravity=m_gravity)
    else:
        chain = Chain.dual_spring(n_rings, K_c=K_contacts, K_b=K_b, m=masses, a=a, m_gravity=m_gravity)
    k = chain.sites_per_ring
    X = (np.arange(chain.n_sites) // k + 0.5 * (np.arange(chain.n_sites) % k)) * a  # half-rings half a spacing up
    strain = dF / (Z1 * c1)
    U = strain * w * np.sqrt(np.pi / 2) * (1 + erf((X - X0) / (np.sqrt(2) * w)))
    x0, _ = initial_state(chain)
    x = x0[0] + U - U[-1]
    u = -c1 * strain * np.exp(-((X - X0) ** 2) / (2 * w**2))
    sim = simulate(chain, t_end, initial=(x, u), n_samples=3001, rtol=rtol)
    f = sim.contact_force - (F_0 + STANDARD_GRAVITY * 1e-9 * np.arange(n_rings - 1))
    passed = sim.t > ((near - 20) * a + 4 * w) / c1  # the incident pulse has gone by the near sensor

    def extreme(values):
        return float(values[np.argmax(np.abs(values))])

    incident = extreme(f[~passed, near])
    R_theory, T_theory = junction_coefficients(Z1, Z2)
    return JunctionReading(extreme(f[passed, near]) / incident, extreme(f[:, far]) / incident, float(R_theory),
                           float(T_theory), Z1, Z2)  # fmt: skip
