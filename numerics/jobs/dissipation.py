r"""Where the energy of an impact goes: the jobs of a chain whose contacts yield (beyond the paper).

- :func:`energy_shares` -- the energy budget of a run as shares of the impact energy: kinetic, stored
  (contacts and ring bodies), gravity, plastic work and viscous loss, closing to the impact energy;
- :func:`second_impact` -- the chain after a run, its contacts flattened by it and hanging again at rest
  (a contact reloaded below its largest approach is elastic; past it, Thornton's law, without work
  hardening, yields again on the same line: no shakedown);
- :func:`equivalent_contact_dashpot` -- the constant contact dashpot gamma_c of the elastic chain whose pulse
  at a sensor ring is as high as the yielding chain's: what the paper's fitted dashpot (Sec. III.B, Eqs. (5)-(6))
  stands for when the loss is plastic.
"""

from __future__ import annotations

import dataclasses

import numpy as np
from ringchain.theory import _validate as v

from ..engine.integrate import simulate
from ..layouts.chain import Chain
from ..layouts.yielding import hanging_memory

__all__ = ["energy_shares", "second_impact", "equivalent_contact_dashpot"]


def energy_shares(sim) -> dict:
    """Energies of a chain's run as fractions of the energy brought in, each of shape (T,).

    Parameters
    ----------
    sim : Simulation
        A run that recorded every ring.

    Returns
    -------
    dict
        "kinetic", "stored" (contacts and bending), "gravity" (from the start), "plastic" (work done on the
        contacts since the start) and "viscous" (dashpots), each divided by the energy at the start (the impact's
        kinetic energy plus nothing else: the chain hangs at rest), and "closure", the sum minus 1 (the
        integration's error, in units of the impact energy).
    """
    budget = sim.energy()
    impact = float(budget.kinetic[0])
    if not impact > 0:
        raise ValueError("the run has no kinetic energy at its start: it is not an impact")
    plastic = np.broadcast_to(np.asarray(budget.plastic, dtype=float), budget.kinetic.shape)
    shares = {
        "kinetic": budget.kinetic / impact,
        "stored": (budget.contact + budget.bending - budget.contact[0] - budget.bending[0]) / impact,
        "gravity": budget.gravity / impact,
        "plastic": (plastic - plastic[0]) / impact,
        "viscous": np.asarray(budget.dissipated) / impact,
    }
    shares["closure"] = sum(shares.values()) - 1.0
    return shares


def second_impact(chain: Chain, sim) -> Chain:
    """``chain`` after the run ``sim``: each contact's memory the largest approach of the run, hanging at rest.

    Parameters
    ----------
    chain : Chain
        A chain with yielding contacts (``yield_strength``).
    sim : Simulation
        A run of it.

    Returns
    -------
    Chain
        The same chain whose contacts start from the memory the run left (and from the static tension, if
        that loads them further), to be struck again.
    """
    if chain.delta_y is None or sim.memory is None:
        raise ValueError("a second impact needs a chain with yielding contacts (yield_strength) and a run of it")
    contacts = chain.sites_per_ring * np.arange(chain.n_contacts) + chain.sites_per_ring - 1
    flattened = dataclasses.replace(chain, delta_max=np.max(sim.memory[..., contacts], axis=-2))
    return dataclasses.replace(flattened, delta_max=hanging_memory(flattened))


def equivalent_contact_dashpot(target_peak, chain: Chain, drop_height, ring=12, *, t_end=1.5e-3, bracket=(0.0, 50.0),
                               rtol=1e-3) -> float:  # fmt: skip
    """The contact dashpot gamma_c (N s/m) that brings the elastic ``chain``'s pulse at ``ring`` to ``target_peak``.

    Parameters
    ----------
    target_peak : float
        Peak of the leading pulse at the sensor of ``ring``, N (the yielding chain's).
    chain : Chain
        The elastic dual-spring chain (its own gamma_b kept).
    drop_height : float
        m.
    ring : int
        Sensor ring.
    t_end : float
        Duration of each run, s.
    bracket : (float, float)
        gamma_c range searched, N s/m.
    rtol : float
        Relative accuracy of gamma_c.

    Returns
    -------
    float
        gamma_c, N s/m (bisection: the peak falls as gamma_c grows).
    """
    target_peak = float(v.positive("target_peak", target_peak, "N"))

    def peak(gamma):
        return simulate(dataclasses.replace(chain, gamma=gamma), t_end, drop_height=drop_height).peak_force(ring)

    low, high = (float(g) for g in bracket)
    if not peak(high) < target_peak < peak(low):
        raise ValueError(f"the peak {target_peak:.4g} N is not reached for gamma_c in {bracket} N s/m")
    while high - low > rtol * high:
        middle = 0.5 * (low + high)
        low, high = (middle, high) if peak(middle) > target_peak else (low, middle)
    return 0.5 * (low + high)
