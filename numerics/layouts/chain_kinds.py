"""The chains built from others: graded, alternating and joined chains (:class:`~ringchain.numerics.Chain`'s
class methods ``graded``, ``alternating`` and ``joined``, written here as functions of the class).

Each takes the class as its first argument (they are bound to :class:`~ringchain.numerics.Chain` as
class methods) and builds through :meth:`~ringchain.numerics.Chain.from_rings` or the class itself, so
that this module does not import :mod:`.chain`.
"""

from __future__ import annotations

import numpy as np
from ringchain.theory import Ring
from ringchain.theory import _validate as v

__all__ = ["graded_chain", "alternating_chain", "joined_chain", "GRADING_PROFILES"]

#: How :meth:`Chain.graded <ringchain.numerics.Chain.graded>` spaces the values between its two ends.
GRADING_PROFILES = ("linear", "geometric")


def graded_chain(
    cls,
    ring: Ring,
    n_rings: int,
    *,
    aspect_ratio=None,
    angle=None,
    profile: str = "linear",
    model: str = "dual-spring",
    **options,
):
    """A chain whose R/r or contact angle changes steadily from the impact end to the far end.

    Parameters
    ----------
    ring : Ring
        The ring the others are made from: its tube radius r, material and (unless graded)
        angle.
    n_rings : int
    aspect_ratio : (float, float), optional
        R/r of ring 0 and of the last ring; R = aspect_ratio * r.
    angle : (float, float), optional
        Contact angle of the first and of the last contact, rad.
    profile : {"linear", "geometric"}, optional
        Values spaced evenly ("linear") or by a constant ratio ("geometric").
    model : {"dual-spring", "power-law"}
    **options
        Passed to :meth:`~ringchain.numerics.Chain.from_rings` (``m_eff_ratio``, dashpots, ``support``,
        ``striker_mass``).

    Examples
    --------
    >>> from ringchain.numerics import Chain
    >>> from ringchain.theory import Ring
    >>> chain = Chain.graded(Ring.from_aspect_ratio(9.0), 5, aspect_ratio=(9.0, 5.0))
    >>> bool(np.all(np.diff(chain.K_b) > 0))  # fatter rings bend less
    True
    """
    if not isinstance(ring, Ring):
        raise TypeError(f"ring must be a ringchain.theory.Ring, got {type(ring).__name__}")
    n_rings = v.count("n_rings", n_rings, 2)
    v.choice("profile", profile, GRADING_PROFILES)
    if (aspect_ratio is None) == (angle is None):
        raise ValueError("give one of aspect_ratio=(first, last) or angle=(first, last) to grade")
    name, ends = ("aspect_ratio", aspect_ratio) if angle is None else ("angle", angle)
    ends = v.positive(name, ends)
    if ends.shape != (2,):
        raise ValueError(f"{name} must be two values (first, last), got {ends.tolist()!r}")
    count = n_rings if name == "aspect_ratio" else n_rings - 1 + (options.get("support", "fixed") == "fixed")
    spaced = np.linspace if profile == "linear" else np.geomspace
    values = spaced(ends[0], ends[1], count)
    if name == "aspect_ratio":
        rings = [Ring(R=float(q) * ring.r, r=ring.r, material=ring.material, angle=ring.angle, thin=ring.thin)
                 for q in values]  # fmt: skip
        return cls.from_rings(rings, model=model, **options)
    return cls.from_rings([ring] * n_rings, angles=values, model=model, **options)


def alternating_chain(cls, ring_a: Ring, ring_b: Ring, n_rings: int, angles=None, model="dual-spring", **options):
    """A chain of two kinds of ring in turn, ``ring_a`` at the impact end.

    Parameters
    ----------
    ring_a, ring_b : Ring
    n_rings : int
    angles : float or array_like, optional
        As in :meth:`~ringchain.numerics.Chain.from_rings`; e.g. ``[pi/2, pi/3] * k`` for alternating angles.
    model : {"dual-spring", "power-law"}
    **options
        Passed to :meth:`~ringchain.numerics.Chain.from_rings` (``m_eff_ratio``, dashpots, ``support``,
        ``striker_mass``).

    Examples
    --------
    >>> from ringchain.numerics import Chain
    >>> from ringchain.theory import Ring
    >>> chain = Chain.alternating(Ring.from_aspect_ratio(9.0), Ring.from_aspect_ratio(5.5), 6)
    >>> len(set(np.round(chain.m, 6)))  # two ring masses
    2
    """
    n_rings = v.count("n_rings", n_rings, 2)
    return cls.from_rings([ring_a, ring_b] * (n_rings // 2) + [ring_a] * (n_rings % 2), angles, model, **options)


def joined_chain(cls, chain_a, chain_b, *, junction=None):
    """``chain_a`` (at the impact end) hung from ``chain_b``: one chain of both chains' rings.

    Parameters
    ----------
    chain_a, chain_b : Chain
        Chains of the same model.  The joined chain takes ``chain_b``'s support and
        ``chain_a``'s striker (its ring 0 is struck); ``chain_b``'s ring 0, inside the
        joined chain, has the inertia ``m`` of its ring whatever ``chain_b``'s striker.
    junction : dict, optional
        The contact between the last ring of ``chain_a`` and the first of ``chain_b``: K (and
        for the power-law model n), gamma and the centre distance a, SI units.  Default:
        ``chain_a``'s support contact (its last contact if its far end is free), as if
        ``chain_a`` hung from ``chain_b`` as from its support, and a the mean of the two
        chains' spacings at the junction ((R1 - r1) + (R2 - r2) for chains of rings).

    Examples
    --------
    >>> from ringchain.numerics import Chain
    >>> stiff = Chain.power_law(4, K=2e7, n=1.5, m=0.01, a=0.04)
    >>> soft = Chain.power_law(4, K=2e6, n=1.5, m=0.01, a=0.04)
    >>> Chain.joined(stiff, soft).K.tolist()  # contacts: 3 of a, the junction, 3 of b, b's support
    [20000000.0, 20000000.0, 20000000.0, 20000000.0, 2000000.0, 2000000.0, 2000000.0, 2000000.0]
    """
    for name, chain in (("chain_a", chain_a), ("chain_b", chain_b)):
        if not isinstance(chain, cls):
            raise TypeError(f"{name} must be a {cls.__name__}, got {type(chain).__name__}")
    if chain_a.model != chain_b.model:
        raise ValueError(f"both chains must be of one model, got {chain_a.model!r} and {chain_b.model!r}")
    junction = dict(junction or {})
    unknown = set(junction) - {"K", "n", "gamma", "a"}
    if unknown:
        raise ValueError(f"junction takes K, n, gamma and a, got {sorted(unknown)}")
    joint = {name: float(chain_a.profile(name)[-1]) for name in ("K", "n", "gamma")}
    joint["a"] = 0.5 * (float(chain_a.profile("a")[-1]) + float(chain_b.profile("a")[0]))
    joint |= {name: float(value) for name, value in junction.items()}

    def contacts(name):
        a_part = chain_a.profile(name)[: chain_a.n_rings - 1]
        return np.concatenate([a_part, [joint[name]], chain_b.profile(name)])

    def per_ring(name):
        return np.concatenate([chain_a.profile(name), chain_b.profile(name)])

    dual = chain_a.model == "dual-spring"
    return cls(
        chain_a.model, chain_a.n_rings + chain_b.n_rings, contacts("K"), contacts("n"), per_ring("m"),
        np.concatenate([chain_a.profile("a"), [joint["a"]], chain_b.profile("a")]), gamma=contacts("gamma"),
        K_b=per_ring("K_b") if dual else None, gamma_b=per_ring("gamma_b") if dual else 0.0,
        m_gravity=per_ring("m_gravity"), support=chain_b.support, striker_mass=chain_a.striker_mass,
    )  # fmt: skip
