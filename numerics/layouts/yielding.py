r"""Chains whose contacts yield: the constants of Thornton's law for the rings of a chain (beyond the paper).

:meth:`~ringchain.numerics.Chain.from_ring` and :meth:`~ringchain.numerics.Chain.from_rings` take a
``yield_strength`` (Pa; one per ring for ``from_rings``) and hand the chain here:
:func:`yielding_chain` gives each contact of the dual-spring chain Thornton's elastic-perfectly plastic law
(:class:`~ringchain.numerics.laws.Thornton`) on its Hertz constant K_c (paper Eq. (1)), with the approach at
first yield delta_y of :func:`ringchain.theory.first_yield`, and starts each contact from the largest
approach it had when the chain was hung: the plastic static equilibrium under gravity.

For annealed AISI 304 (Y = 215 MPa) the paper's ring (R/r = 9, r = 2.5 mm) yields at F_y = 0.15 N, less
than the weight of one ring (0.22 N): every contact of the hanging chain is already flattened, the top
one (about 4 N) far into its plastic branch.  The memory is set at standard gravity with every ring
hanging, as the chain was hung before ring 0 was lifted for a drop; a chain run under another g keeps
that memory (a chain hung under a stronger gravity would flatten further on its first loading).

The contact of two unequal rings yields where the first of its two tori does: delta_y is the smaller of
the two rings' own delta_y (each ring against a ring like itself, of its own yield strength) -- exact for
equal rings, an estimate for unequal ones (the subsurface stress of two unequal tori is not derived).
"""

from __future__ import annotations

import dataclasses

import numpy as np
from ringchain.theory import STANDARD_GRAVITY, first_yield
from ringchain.theory import _validate as v

__all__ = ["yielding_chain", "contact_yield_approach", "hanging_memory"]


def contact_yield_approach(rings, yield_strength, angles, support_fixed) -> np.ndarray:
    """Approach at first yield of each contact of a chain of ``rings``, m (module notes).

    Parameters
    ----------
    rings : sequence of Ring
        The rings from the impact end.
    yield_strength : float or array_like
        Yield strength of each ring (von Mises), Pa: one number or one per ring.
    angles : array_like
        Contact angle of each contact, rad (the support's last when the support is fixed).
    support_fixed : bool
        Whether the top ring hangs from a fixed support (its contact counted like a ring with itself).

    Returns
    -------
    ndarray
        delta_y per contact, m.
    """
    Y = np.broadcast_to(np.asarray(v.positive("yield_strength", yield_strength, "Pa"), dtype=float), (len(rings),))
    pairs = [(k, k + 1) for k in range(len(rings) - 1)] + ([(len(rings) - 1,) * 2] if support_fixed else [])
    angles = np.broadcast_to(np.asarray(angles, dtype=float), (len(pairs),))
    out = np.empty(len(pairs))
    cache = {}
    for c, ((i, j), angle) in enumerate(zip(pairs, angles, strict=True)):
        values = []
        for k in (i, j):
            ring = rings[k]
            key = (ring.R, ring.r, ring.material.E, ring.material.nu, float(angle), float(Y[k]))
            if key not in cache:
                cache[key] = float(first_yield(ring.R, ring.r, ring.material.E, ring.material.nu, float(angle),
                                               Y=float(Y[k])).indentation)  # fmt: skip
            values.append(cache[key])
        out[c] = min(values)
    return out


def hanging_memory(chain, g=STANDARD_GRAVITY) -> np.ndarray:
    """Largest approach of each contact of a yielding ``chain`` hung at rest under gravity ``g``, m.

    The contacts load from their present memory (the chain's ``delta_max``) to the static tension
    they carry, on Thornton's loading curve where it exceeds the loading force at the memory.
    """
    e = chain.static_extension(g)
    contacts = chain.sites_per_ring * np.arange(chain.n_contacts) + chain.sites_per_ring - 1
    return np.maximum(e[contacts], chain.profile("delta_max"))


def yielding_chain(chain, rings, yield_strength, angles):
    """The dual-spring ``chain`` of ``rings`` with Thornton contacts, hung in its plastic static equilibrium.

    Parameters
    ----------
    chain : Chain
        The elastic dual-spring chain of these rings (from :meth:`~ringchain.numerics.Chain.from_ring` or
        :meth:`~ringchain.numerics.Chain.from_rings`).
    rings : sequence of Ring
        Its rings, from the impact end.
    yield_strength : float or array_like
        Pa, one number or one per ring.
    angles : float or array_like
        Contact angle of each contact, rad (the support's last when fixed).

    Returns
    -------
    Chain
        The chain with ``delta_y`` (m per contact) and ``delta_max`` (m per contact: the hanging chain's
        approaches under standard gravity, each contact's memory at the start of a run).
    """
    if chain.model != "dual-spring":
        raise ValueError("contacts that yield are Hertz contacts (Thornton's law on K_c, Eq. (1)): use the "
                         "dual-spring model; the power-law model's contact lumps the ring's bending")  # fmt: skip
    delta_y = contact_yield_approach(rings, yield_strength, angles, chain.support == "fixed")
    virgin = dataclasses.replace(chain, delta_y=delta_y, delta_max=0.0)
    if chain.support != "fixed":
        return virgin
    return dataclasses.replace(virgin, delta_max=hanging_memory(virgin))
