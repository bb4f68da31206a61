"""A chain's numbers from its rings, once per distinct ring or contact: the helpers of
:meth:`~ringchain.numerics.Chain.from_rings` (Eqs. (1), (2) and (4) of the paper through :mod:`ringchain.theory`).

A uniform chain gets its single ring's numbers exactly (one scalar call each); a chain of rings that differ (a
disordered chain) gets the numbers of all its distinct rings and contacts in one call of the theory's functions,
which take arrays.
"""

from __future__ import annotations

import numpy as np
from ringchain.theory import bending_stiffness, fit_power_law, hertz_stiffness_pair

__all__ = ["per_distinct", "columns", "rings_K_b", "pair_K_c", "contacts_K_c", "power_law_fits"]


def per_distinct(evaluate, keys, what: str, many=None) -> np.ndarray:
    """``evaluate(*key)`` for each key, once per distinct key (scalar calls: a uniform chain gets its single ring's
    numbers exactly); an error names the first ``what`` (formatted with i, j).  ``many(distinct keys)``, given,
    evaluates several distinct keys in one call, one row each (a disordered chain's rings cost one call, not one
    each; only where it gives each key's scalar numbers, to the last bit at most, as the tests of disordered chains
    check); an error there is looked for key by key."""
    ids: dict = {}  # each key hashed once (a key of rings hashes each ring's fields)
    index = [ids.setdefault(key, len(ids)) for key in keys]
    distinct = list(ids)
    if many is not None and len(distinct) > 1:
        try:
            rows = np.asarray(many(distinct), dtype=float)
            if rows.shape[0] != len(distinct):
                raise ValueError(f"{len(rows)} rows for {len(distinct)} keys")
            return rows[index]
        except ValueError:
            pass  # found and named below
    values = [None] * len(distinct)
    for i, k in enumerate(index):
        if values[k] is None:
            try:
                values[k] = evaluate(*distinct[k])
            except ValueError as error:
                raise ValueError(f"{what.format(i=i, j=i + 1)}: {error}") from None
    return np.array([values[k] for k in index], dtype=float)


def columns(rings) -> list:
    """R, r (m), E (Pa) and nu of each of ``rings`` (Ring), as arrays."""
    return [np.array([read(q) for q in rings]) for read in (lambda q: q.R, lambda q: q.r, lambda q: q.material.E,
                                                              lambda q: q.material.nu)]  # fmt: skip


def rings_K_b(distinct) -> np.ndarray:
    """K_b (Eq. 2, :attr:`Ring.K_b`: elementwise arithmetic) of distinct (ring,) keys, in one call."""
    rings = [ring for (ring,) in distinct]
    (thin,) = {ring.thin for ring in rings}  # both settings: a ValueError, and a call per ring instead
    return bending_stiffness(*columns(rings), thin=thin)


def pair_K_c(below, above, angle) -> float:
    """K_c of two rings (Ring) in contact at ``angle`` (rad), N/m^1.5 (Eq. 1, App. A): one scalar call."""
    m, n = below.material, above.material
    return float(hertz_stiffness_pair(below.R, below.r, m.E, m.nu, above.R, above.r, n.E, n.nu, angle))


def contacts_K_c(distinct) -> np.ndarray:
    """K_c of distinct (below, above, angle) keys: the contacts of two different rings in one call (the theory takes
    arrays), that of a ring with its like (the support's) alone, as a uniform chain's (hertz_stiffness evaluates it,
    whose scalar and array evaluations may differ in the last bit)."""
    alike = np.array([below is above or below == above for below, above, _ in distinct])
    out = np.array([pair_K_c(*key) if same else np.nan for key, same in zip(distinct, alike, strict=True)])
    pairs = [key for key, same in zip(distinct, alike, strict=True) if not same]
    if pairs:
        sides = [columns([key[side] for key in pairs]) for side in (0, 1)]
        out[~alike] = hertz_stiffness_pair(*sides[0], *sides[1], np.array([key[2] for key in pairs]))
    return out


def power_law_fits(distinct) -> np.ndarray:
    """The power laws (K, n) fitted to distinct (K_c, K_b) pairs (Eq. 4), in one call, one row each."""
    K_c, K_b = (np.array(column) for column in zip(*distinct, strict=True))
    return np.stack(fit_power_law(K_c=K_c, K_b=K_b), axis=-1)
