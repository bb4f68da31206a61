r"""A chain of interlocked rings as a lattice: masses, springs, dashpots, gravity, support.

:class:`Chain` holds the parameters of one of the paper's two models (Sec. III.B) and
builds the :class:`~ringchain.numerics.models.Lattice` that is integrated.

Site labelling of the dual-spring model
---------------------------------------
The paper (Eqs. (5)-(6)) gives unit cell i two sites of mass m/2, u_i and w_i,
joined by the unilateral Hertz contact F_c(u_i - w_i), while the bidirectional bending
spring F_b joins w_{i-1} to u_i.  A Hertz contact acts *between* two rings and bending
acts *inside* one ring, so the paper's cell is not a ring: ring j is the pair
(w_{j-1}, u_j) held together by its bending spring, and the paper's cell i straddles
the contact between ring i (upper half u_i) and ring i+1 (lower half w_i).  Here the
sites are numbered along the chain from the impact end: site 2j is the lower half of
ring j (the paper's w_{j-1}), site 2j+1 its upper half (the paper's u_j); bond 2j is
the bending spring of ring j and bond 2j+1 the contact between rings j and j+1.  One
period is then one contact in series with one ring body, the two springs in series
of Fig. 1(b) and of the static law Eq. (3); each ring keeps its mass m (two halves of
m/2), so the two models have the same ring masses.

Sign convention
---------------
The paper writes the contact terms as F(u_{i-1} - u_i) and F(u_i - w_i), the form of a
chain in compression.  Interlocked rings load in tension, so the paper's displacements
are measured along the axis pointing *towards* the impact.  Here (ARCHITECTURE.md) the
axis points away from the impact (up the hanging chain) and the extension of contact i
is delta_i = u_{i+1} - u_i, positive in tension: the paper's u is minus ours, and the
equations are otherwise identical.

Effective mass
--------------
The paper fits an inertial mass m_eff < m0 (Table I) to the wave speed.  ``m`` here is
the inertial mass (the paper's m_eff) and ``m_gravity`` the mass gravity acts on
(default ``m``; the real ring mass m0 for the experiment).  The mixed choice keeps the
static pre-stretch of the hanging chain right (each contact carries the true weight
below it) but means the model rings do not fall like real ones: a ring with slack
contacts accelerates at g m_gravity/m (about 2.7 g for m/m0 = 0.37), and an impact
speed v carries momentum m v, not m0 v.  This is why a drop is started at the instant
the slack is taken up, with the free-fall speed sqrt(2 g h) of the real ring
(:func:`ringchain.numerics.simulate`), rather than integrated through the fall.
"""

from __future__ import annotations

import functools
import math
import numbers
from dataclasses import dataclass

import numpy as np
from ringchain.theory import Ring, fit_power_law, hertz_stiffness_pair, linear, n_per_mm_to_si, paper_data
from ringchain.theory import _validate as v

from .models import STANDARD_GRAVITY, Lattice

__all__ = ["Chain", "MODELS", "SUPPORTS", "STIFFNESS_SOURCES", "GRADING_PROFILES"]

#: What each parameter of a :class:`Chain` is given per, when it varies along the chain.
_PROFILES = {"K": "contact", "n": "contact", "gamma": "contact", "m": "ring", "m_gravity": "ring", "K_b": "ring",
             "gamma_b": "ring", "a": "pair"}  # fmt: skip

#: The two lattice models of paper Sec. III.B (named once, in :mod:`ringchain.theory.linear`).
MODELS = linear.MODELS

#: Boundary at the far end from the impact: hanging from a fixed support, or free.
SUPPORTS = ("fixed", "free")

#: How :meth:`Chain.graded` spaces the values between its two ends.
GRADING_PROFILES = ("linear", "geometric")

#: Sources of the stiffness of :meth:`Chain.from_paper`: the paper's measured power law
#: (Table I) or the ring's theory (Eqs. 1-4).
STIFFNESS_SOURCES = ("table", "theory")


def _integer(name: str, value) -> int:
    """``value`` as an int: a whole number (2 or 2.0), not a bool, a string or 2.7 (ValueError naming it)."""
    if isinstance(value, bool | np.bool_) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be an integer, got {value!r}")
    if not math.isfinite(value) or int(value) != value:
        raise ValueError(f"{name} must be an integer, got {value!r}")
    return int(value)


def _count(name: str, value, minimum: int) -> int:
    value = _integer(name, value)
    if value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {value}")
    return value


def _flag(name: str, value) -> bool:
    """``value`` as a bool: True or False only (a string such as "no" is refused, not read as true)."""
    if isinstance(value, bool | np.bool_):
        return bool(value)
    raise ValueError(f"{name} must be True or False, got {value!r}")


def _parameter(name: str, value, length: int, check, unit: str, what: str):
    """A chain parameter: a float (uniform) or a read-only array of ``length`` values (one per ``what``).

    An array whose values are all equal becomes that float, so that a uniform chain has one
    representation however it was built (and compares equal to the scalar-built chain).
    """
    if np.ndim(value) == 0:
        return float(check(name, value, unit))
    array = np.array(check(name, value, unit), dtype=float)
    if array.shape != (length,):
        raise ValueError(f"{name} must be one number or {length} values (one per {what}), got shape {array.shape}")
    if np.ptp(array) == 0:
        return float(array[0])
    array.flags.writeable = False
    return array


def _per_distinct(evaluate, keys, what: str) -> np.ndarray:
    """``evaluate(*key)`` for each key, once per distinct key (scalar calls: a uniform chain gets
    its single ring's numbers exactly); an error names the first ``what`` (formatted with i, j)."""
    values, results = {}, []
    for i, key in enumerate(keys):
        if key not in values:
            try:
                values[key] = evaluate(*key)
            except ValueError as error:
                raise ValueError(f"{what.format(i=i, j=i + 1)}: {error}") from None
        results.append(values[key])
    return np.array(results, dtype=float)


def _choice(name: str, value: str, options) -> str:
    if value not in options:
        raise ValueError(f"{name} must be one of {options}, got {value!r}")
    return value


@dataclass(frozen=True, eq=False)
class Chain:
    r"""A chain of ``n_rings`` interlocked rings, ring 0 at the impact end.

    Build it with :meth:`power_law`, :meth:`dual_spring`, :meth:`from_ring` or
    :meth:`from_paper`; a chain that changes along its length with :meth:`from_rings`,
    :meth:`graded`, :meth:`alternating` or :meth:`joined`.  The contact law of both models
    is [K delta^n + gamma delta_dot]_+ (:func:`~ringchain.numerics.models.power_law_force`);
    the dual-spring model uses K = K_c, n = 3/2, gamma = gamma_c and adds the bending
    spring K_b, gamma_b inside each ring.

    Every parameter is one number (a uniform chain) or an array along the chain: per ring
    (``m``, ``m_gravity``, ``K_b``, ``gamma_b``: ``n_rings`` values, ring 0 at the impact
    end), per contact (``K``, ``n``, ``gamma``: :attr:`n_contacts` values, contact i
    between ring i and ring i+1, the last one the support's contact when the support is
    fixed) or per pair of neighbours (``a``: ``n_rings - 1`` values).  An array of equal
    values is stored as its number, so a uniform chain is the same object however it was
    built; the uniform chain is the case of the arrays with one value, run by the same code.

    Attributes
    ----------
    model : {"power-law", "dual-spring"}
    n_rings : int
    K : float or ndarray
        Contact stiffness, N/m^n (per contact).
    n : float or ndarray
        Contact exponent (per contact).
    m : float or ndarray
        Inertial mass of a ring (the paper's m_eff), kg (per ring).
    a : float or ndarray
        Distance between the centres of adjacent rings, m (a = 2(R - r); for unequal
        rings (R1 - r1) + (R2 - r2); per pair of neighbours).
    gamma : float or ndarray
        Contact dashpot, N s/m (per contact).
    K_b : float, ndarray or None
        Bending stiffness, N/m (dual-spring only; per ring).
    gamma_b : float or ndarray
        Bending dashpot, N s/m (dual-spring only; per ring).
    m_gravity : float or ndarray
        Mass of a ring that gravity acts on, kg (default ``m``; per ring); see the module notes.
    support : {"fixed", "free"}
        "fixed": the top ring (the far end) hangs from a fixed support through one more
        contact of the chain's contact law; "free": the far end is free.
    """

    model: str
    n_rings: int
    K: float
    n: float
    m: float
    a: float
    gamma: float = 0.0
    K_b: float | None = None
    gamma_b: float = 0.0
    m_gravity: float | None = None
    support: str = "fixed"

    def __post_init__(self):
        _choice("model", self.model, MODELS)
        _choice("support", self.support, SUPPORTS)
        set_ = functools.partial(object.__setattr__, self)
        set_("n_rings", _count("n_rings", self.n_rings, 2))
        rings, contacts, pairs = self.n_rings, self.n_contacts, self.n_rings - 1
        exponent = functools.partial(v.in_range, low=1.0, high=np.inf, closed_low=True, closed_high=False)
        set_("K", _parameter("K", self.K, contacts, v.positive, "N/m^n", "contact"))
        set_("n", _parameter("n", self.n, contacts, lambda name, value, unit: exponent(name, value), "", "contact"))
        set_("m", _parameter("m", self.m, rings, v.positive, "kg", "ring"))
        set_("a", _parameter("a", self.a, pairs, v.positive, "m", "pair of neighbouring rings"))
        set_("gamma", _parameter("gamma", self.gamma, contacts, v.nonnegative, "N s/m", "contact"))
        m_gravity = self.m if self.m_gravity is None else self.m_gravity
        set_("m_gravity", _parameter("m_gravity", m_gravity, rings, v.positive, "kg", "ring"))
        if self.model == "dual-spring":
            if np.any(np.asarray(self.n) != 1.5):
                raise ValueError(
                    f"the dual-spring model's contact is Hertz contact, n = 3/2 (Eq. 1); got n = {v.show(self.n)} "
                    "(a fitted exponent belongs to the power-law model)"
                )
            if self.K_b is None:
                raise ValueError("the dual-spring model needs the bending stiffness K_b")
            set_("K_b", _parameter("K_b", self.K_b, rings, v.positive, "N/m", "ring"))
            set_("gamma_b", _parameter("gamma_b", self.gamma_b, rings, v.nonnegative, "N s/m", "ring"))
        elif self.K_b is not None or np.any(self.gamma_b):
            raise ValueError("K_b and gamma_b belong to the dual-spring model, not the power-law one")

    def _key(self) -> tuple:
        return tuple(
            (value.shape, value.tobytes()) if isinstance(value, np.ndarray) else value
            for value in (self.model, self.n_rings, self.K, self.n, self.m, self.a, self.gamma, self.K_b,
                          self.gamma_b, self.m_gravity, self.support)
        )  # fmt: skip

    def __eq__(self, other):
        if not isinstance(other, Chain):
            return NotImplemented
        return self._key() == other._key()

    def __hash__(self):
        return hash(self._key())

    # -- constructors ------------------------------------------------------------------
    @classmethod
    def power_law(cls, n_rings, K, n, m, a, gamma=0.0, m_gravity=None, *, support="fixed") -> Chain:
        """Power-law chain, paper Eq. (7): one mass m per ring, contacts K delta^n.

        Parameters
        ----------
        n_rings : int
            Number of rings, >= 2.
        K : float
            Contact stiffness, N/m^n (the paper's N/mm^n through
            :func:`ringchain.theory.n_per_mm_to_si`).
        n : float
            Exponent of Eq. (4), >= 1.
        m : float
            Inertial mass of a ring, kg (the paper's m_eff).
        a : float
            Distance between ring centres, m.
        gamma : float, optional
            Dashpot inside each contact's bracket, N s/m.
        m_gravity : float, optional
            Mass gravity acts on, kg; default ``m``.
        support : {"fixed", "free"}, optional
            Far end hanging from a fixed support (default) or free.

        Examples
        --------
        >>> chain = Chain.power_law(20, K=4.9e6, n=1.11, m=8.2e-3, a=0.04)
        >>> chain.n_sites, chain.lattice.n_bonds  # 19 contacts and the support
        (20, 20)
        """
        return cls("power-law", n_rings, K, n, m, a, gamma=gamma, m_gravity=m_gravity, support=support)

    @classmethod
    def dual_spring(
        cls, n_rings, K_c, K_b, m, a, gamma_c=0.0, gamma_b=0.0, m_gravity=None, *, support="fixed"
    ) -> Chain:
        """Dual-spring chain, paper Eqs. (5)-(6): two masses m/2 per ring.

        Parameters
        ----------
        n_rings : int
            Number of rings, >= 2.
        K_c : float
            Hertz contact stiffness, N/m^1.5 (Eq. 1).
        K_b : float
            Bending stiffness of a ring, N/m (Eq. 2).
        m : float
            Inertial mass of a ring, kg; each half is m/2.
        a : float
            Distance between ring centres, m.
        gamma_c, gamma_b : float, optional
            Contact and bending dashpots, N s/m, each in parallel with its spring.
        m_gravity : float, optional
            Mass gravity acts on, kg; default ``m``.
        support : {"fixed", "free"}, optional
            Far end hanging from a fixed support (through one more Hertz contact) or free.

        Examples
        --------
        >>> chain = Chain.dual_spring(20, K_c=7.5e9, K_b=3.3e6, m=8.2e-3, a=0.04)
        >>> chain.n_sites, chain.contact_bonds[:3].tolist(), chain.bending_bonds[:3].tolist()
        (40, [1, 3, 5], [0, 2, 4])
        """
        return cls(
            "dual-spring", n_rings, K_c, 1.5, m, a, gamma=gamma_c, K_b=K_b, gamma_b=gamma_b,
            m_gravity=m_gravity, support=support,
        )  # fmt: skip

    @classmethod
    def from_ring(
        cls,
        ring: Ring,
        n_rings: int,
        model: str = "dual-spring",
        *,
        m_eff_ratio: float = 1.0,
        K=None,
        n=None,
        gamma: float = 0.0,
        gamma_c: float = 0.0,
        gamma_b: float = 0.0,
        support: str = "fixed",
    ) -> Chain:
        """A chain of identical :class:`~ringchain.theory.Ring` s.

        Parameters
        ----------
        ring : Ring
            Geometry and material; must be able to form a chain (R/r >= 3).
        n_rings : int
            Number of rings.
        model : {"dual-spring", "power-law"}
            Dual-spring: K_c and K_b of the ring (Eqs. 1-2).  Power-law: K and n fitted to
            the series law (Eq. 4, :meth:`Ring.power_law`) unless ``K`` and ``n`` are given.
        m_eff_ratio : float, optional
            Inertial mass over ring mass, m_eff/m0 in (0, 1] (Table I); gravity acts on m0.
        K, n : float, optional
            Power-law stiffness (N/m^n) and exponent, e.g. measured ones (Table I).
        gamma : float, optional
            Power-law contact dashpot, N s/m.
        gamma_c, gamma_b : float, optional
            Dual-spring contact and bending dashpots, N s/m.
        support : {"fixed", "free"}, optional

        Examples
        --------
        >>> chain = Chain.from_ring(Ring.from_aspect_ratio(9.0), 20, m_eff_ratio=0.37)
        >>> round(chain.m / chain.m_gravity, 2), round(chain.a * 1e3, 1)
        (0.37, 40.0)
        """
        if not isinstance(ring, Ring):
            raise TypeError(f"ring must be a ringchain.theory.Ring, got {type(ring).__name__}")
        ring.check_chain()
        _choice("model", model, MODELS)
        ratio = float(v.in_range("m_eff_ratio", m_eff_ratio, 0.0, 1.0))
        m0 = ring.mass
        if model == "dual-spring":
            if K is not None or n is not None or gamma:
                raise ValueError("K, n and gamma belong to the power-law model; use gamma_c and gamma_b")
            return cls.dual_spring(
                n_rings, ring.K_c, ring.K_b, ratio * m0, ring.spacing, gamma_c, gamma_b, m0, support=support
            )
        if gamma_c or gamma_b:
            raise ValueError("gamma_c and gamma_b belong to the dual-spring model; use gamma")
        if (K is None) != (n is None):
            raise ValueError("give both K and n, or neither (then the series law is fitted, Eq. 4)")
        if K is None:
            K, n = ring.power_law()
        return cls.power_law(n_rings, K, n, ratio * m0, ring.spacing, gamma, m0, support=support)

    @classmethod
    def from_paper(
        cls,
        model: str = "power-law",
        aspect_ratio: float = 9.0,
        n_rings: int = paper_data.CHAIN_RINGS,
        *,
        stiffness: str | None = None,
        **dashpots,
    ) -> Chain:
        """The paper's experimental chain: Table I parameters for ``aspect_ratio``.

        Both models use the fitted m_eff/m0 as inertial mass and m0 for gravity; the rings
        are the paper's, r = 2.5 mm, stainless steel.  ``dashpots`` are passed on (default
        undamped: the paper does not report its fitted gamma values).

        Parameters
        ----------
        model : {"power-law", "dual-spring"}
        aspect_ratio : float
            A row of Table I (9, 6 or 5.5).
        n_rings : int
        stiffness : {"table", "theory"}, optional
            "table": the power-law chain takes the measured K (N/mm^n, converted to SI)
            and n; the dual-spring chain the K_c and K_b whose series law reduces to that
            power law over 1-100 N
            (:func:`ringchain.numerics.paper.series_stiffness_for_power_law`).  "theory":
            the ring's K_c and K_b (Eqs. 1-2), and for the power-law chain the power law
            fitted to them (Eq. 4).  Default: as the paper did (Sec. III.B), "table" for
            the power-law chain and "theory" for the dual-spring chain.

        Examples
        --------
        >>> chain = Chain.from_paper("power-law")
        >>> chain.n_rings, chain.n, round(chain.m / chain.m_gravity, 2)
        (20, 1.11, 0.37)
        """
        if aspect_ratio not in paper_data.TABLE_I:
            raise ValueError(f"Table I has aspect ratios {sorted(paper_data.TABLE_I)}, got {aspect_ratio!r}")
        _choice("model", model, MODELS)
        if stiffness is None:
            stiffness = "table" if model == "power-law" else "theory"
        _choice("stiffness", stiffness, STIFFNESS_SOURCES)
        K_mm, n, ratio = paper_data.TABLE_I[aspect_ratio]
        ring = Ring.from_aspect_ratio(aspect_ratio, r=paper_data.TUBE_RADIUS)
        if stiffness == "theory":
            return cls.from_ring(ring, n_rings, model, m_eff_ratio=ratio, **dashpots)
        K_si = float(n_per_mm_to_si(K_mm, n=n))
        if model == "power-law":
            return cls.from_ring(ring, n_rings, model, m_eff_ratio=ratio, K=K_si, n=n, **dashpots)
        from .paper import series_stiffness_for_power_law

        if "gamma" in dashpots:
            raise ValueError("K, n and gamma belong to the power-law model; use gamma_c and gamma_b")
        K_c, K_b = series_stiffness_for_power_law(K_si, n)
        m0 = ring.mass
        return cls.dual_spring(n_rings, K_c, K_b, ratio * m0, ring.spacing, m_gravity=m0, **dashpots)

    @classmethod
    def from_rings(
        cls,
        rings,
        angles=None,
        model: str = "dual-spring",
        *,
        m_eff_ratio: float = 1.0,
        gamma: float = 0.0,
        gamma_c: float = 0.0,
        gamma_b: float = 0.0,
        support: str = "fixed",
    ) -> Chain:
        """A chain of given rings, ring 0 at the impact end: each contact from the two rings it joins.

        Parameters
        ----------
        rings : sequence of Ring
            The rings in order along the chain (at least two), each able to form a chain (R/r >= 3).
        angles : float or array_like, optional
            Contact angle of each contact, rad: one number, or :attr:`n_contacts` values (the
            last the support's contact when fixed).  Default: each ring's own ``angle``,
            read as the angle it makes with the ring above it (the top ring's for the support).
        model : {"dual-spring", "power-law"}
            Dual-spring: each contact's K_c from its two rings
            (:func:`~ringchain.theory.hertz_stiffness_pair`, Eq. 1 for equal rings), each
            ring's K_b from its own geometry (Eq. 2).  Power-law: each contact's K and n
            fitted to the series law of that contact and the ring below it (Eq. 4).
        m_eff_ratio : float, optional
            Inertial mass over ring mass, m_eff/m0 in (0, 1]; gravity acts on m0.
        gamma : float or array_like, optional
            Power-law contact dashpots, N s/m.
        gamma_c, gamma_b : float or array_like, optional
            Dual-spring contact and bending dashpots, N s/m.
        support : {"fixed", "free"}, optional
            The support's contact is that of the top ring with a ring like itself.

        Notes
        -----
        The centre distance of two interlocked rings is (R1 - r1) + (R2 - r2), 2(R - r) for
        equal rings.  Rings that are all the same give exactly :meth:`from_ring`'s chain.

        Examples
        --------
        >>> big, small = Ring.from_aspect_ratio(9.0), Ring.from_aspect_ratio(6.0)
        >>> chain = Chain.from_rings([big, big, small, small])
        >>> (chain.a * 1e3).round(2).tolist()  # mm: 2(R - r), then (R1 - r1) + (R2 - r2)
        [40.0, 32.5, 25.0]
        """
        rings = list(rings) if not isinstance(rings, Ring) else [rings]
        if len(rings) < 2:
            raise ValueError(f"rings must hold at least two rings, got {len(rings)}")
        for i, ring in enumerate(rings):
            if not isinstance(ring, Ring):
                raise TypeError(f"rings[{i}] must be a ringchain.theory.Ring, got {type(ring).__name__}")
            try:
                ring.check_chain()
            except ValueError as error:
                raise ValueError(f"rings[{i}]: {error}") from None
        _choice("model", model, MODELS)
        _choice("support", support, SUPPORTS)
        ratio = float(v.in_range("m_eff_ratio", m_eff_ratio, 0.0, 1.0))
        n_rings = len(rings)
        pairs = [(rings[i], rings[i + 1]) for i in range(n_rings - 1)]
        if support == "fixed":
            pairs.append((rings[-1], rings[-1]))
        if angles is None:
            angles = [below.angle for below, _ in pairs]
        angles = v.in_range("angles", angles, 0.0, np.pi / 2)
        if angles.ndim > 1 or angles.size not in (1, len(pairs)):
            raise ValueError(f"angles must be one angle or {len(pairs)} (one per contact), got shape {angles.shape}")
        angles = np.broadcast_to(angles, (len(pairs),))
        # One evaluation per distinct contact (a uniform chain's numbers are then the ring's own).
        K_c = _per_distinct(
            lambda below, above, angle: float(hertz_stiffness_pair(
                below.R, below.r, below.material.E, below.material.nu,
                above.R, above.r, above.material.E, above.material.nu, angle)),
            [(below, above, float(angle)) for (below, above), angle in zip(pairs, angles, strict=True)],
            "contact of rings {i} and {j}",
        )  # fmt: skip
        K_b = _per_distinct(lambda ring: ring.K_b, [(ring,) for ring in rings], "ring {i}")
        m0 = np.array([ring.mass for ring in rings])
        a = np.array([(below.R - below.r) + (above.R - above.r) for below, above in pairs[: n_rings - 1]])
        if model == "dual-spring":
            if gamma is not None and np.any(gamma):
                raise ValueError("gamma belongs to the power-law model; use gamma_c and gamma_b")
            return cls.dual_spring(n_rings, K_c, K_b[:n_rings], ratio * m0, a, gamma_c, gamma_b, m0, support=support)
        if np.any(gamma_c) or np.any(gamma_b):
            raise ValueError("gamma_c and gamma_b belong to the dual-spring model; use gamma")
        # Each period of the chain is a contact in series with the body of the ring below it (Eq. 3).
        below_K_b = np.append(K_b, K_b[-1])[: len(pairs)]
        fits = _per_distinct(lambda kc, kb: tuple(float(x) for x in fit_power_law(K_c=kc, K_b=kb)),
                             list(zip(K_c.tolist(), below_K_b.tolist(), strict=True)), "contact {i}")  # fmt: skip
        return cls.power_law(n_rings, fits[:, 0], fits[:, 1], ratio * m0, a, gamma, m0, support=support)

    @classmethod
    def graded(
        cls,
        ring: Ring,
        n_rings: int,
        *,
        aspect_ratio=None,
        angle=None,
        profile: str = "linear",
        model: str = "dual-spring",
        **options,
    ) -> Chain:
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
            Passed to :meth:`from_rings` (``m_eff_ratio``, dashpots, ``support``).

        Examples
        --------
        >>> chain = Chain.graded(Ring.from_aspect_ratio(9.0), 5, aspect_ratio=(9.0, 5.0))
        >>> bool(np.all(np.diff(chain.K_b) > 0))  # fatter rings bend less
        True
        """
        if not isinstance(ring, Ring):
            raise TypeError(f"ring must be a ringchain.theory.Ring, got {type(ring).__name__}")
        n_rings = _count("n_rings", n_rings, 2)
        _choice("profile", profile, GRADING_PROFILES)
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

    @classmethod
    def alternating(cls, ring_a: Ring, ring_b: Ring, n_rings: int, angles=None, model="dual-spring", **options):
        """A chain of two kinds of ring in turn, ``ring_a`` at the impact end.

        Parameters
        ----------
        ring_a, ring_b : Ring
        n_rings : int
        angles : float or array_like, optional
            As in :meth:`from_rings`; e.g. ``[pi/2, pi/3] * k`` for alternating angles.
        model : {"dual-spring", "power-law"}
        **options
            Passed to :meth:`from_rings`.

        Examples
        --------
        >>> chain = Chain.alternating(Ring.from_aspect_ratio(9.0), Ring.from_aspect_ratio(5.5), 6)
        >>> len(set(np.round(chain.m, 6)))  # two ring masses
        2
        """
        n_rings = _count("n_rings", n_rings, 2)
        return cls.from_rings([ring_a, ring_b] * (n_rings // 2) + [ring_a] * (n_rings % 2), angles, model, **options)

    @classmethod
    def joined(cls, chain_a: Chain, chain_b: Chain, *, junction=None) -> Chain:
        """``chain_a`` (at the impact end) hung from ``chain_b``: one chain of both chains' rings.

        Parameters
        ----------
        chain_a, chain_b : Chain
            Chains of the same model.  The joined chain takes ``chain_b``'s support.
        junction : dict, optional
            The contact between the last ring of ``chain_a`` and the first of ``chain_b``: K (and
            for the power-law model n), gamma and the centre distance a, SI units.  Default:
            ``chain_a``'s support contact (its last contact if its far end is free), as if
            ``chain_a`` hung from ``chain_b`` as from its support, and a the mean of the two
            chains' spacings at the junction ((R1 - r1) + (R2 - r2) for chains of rings).

        Examples
        --------
        >>> stiff = Chain.power_law(4, K=2e7, n=1.5, m=0.01, a=0.04)
        >>> soft = Chain.power_law(4, K=2e6, n=1.5, m=0.01, a=0.04)
        >>> Chain.joined(stiff, soft).K.tolist()  # contacts: 3 of a, the junction, 3 of b, b's support
        [20000000.0, 20000000.0, 20000000.0, 20000000.0, 2000000.0, 2000000.0, 2000000.0, 2000000.0]
        """
        for name, chain in (("chain_a", chain_a), ("chain_b", chain_b)):
            if not isinstance(chain, Chain):
                raise TypeError(f"{name} must be a Chain, got {type(chain).__name__}")
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
            m_gravity=per_ring("m_gravity"), support=chain_b.support,
        )  # fmt: skip

    # -- derived quantities -----------------------------------------------------------------
    @property
    def K_c(self) -> float:
        """Hertz contact stiffness of the dual-spring model (= K), N/m^1.5."""
        return self.K

    @property
    def gamma_c(self) -> float:
        """Contact dashpot (= gamma), N s/m."""
        return self.gamma

    @property
    def sites_per_ring(self) -> int:
        return 2 if self.model == "dual-spring" else 1

    @property
    def n_sites(self) -> int:
        return self.n_rings * self.sites_per_ring

    @property
    def n_contacts(self) -> int:
        """Contacts of the chain: n_rings - 1 between rings, and one more with a fixed support."""
        return self.n_rings - 1 + (self.support == "fixed")

    @property
    def uniform(self) -> bool:
        """Whether every parameter is one number (the chain does not change along its length)."""
        return not any(isinstance(getattr(self, name), np.ndarray) for name in _PROFILES)

    def profile(self, name: str) -> np.ndarray:
        """Parameter ``name`` as an array along the chain, whether stored as one number or not.

        Per ring for m, m_gravity, K_b, gamma_b; per contact for K, n, gamma (the support's
        last when fixed); per pair of neighbours for a.  Units as the attribute's.

        Examples
        --------
        >>> Chain.power_law(3, K=1e6, n=1.5, m=0.01, a=0.04).profile("K").tolist()  # two contacts and the support
        [1000000.0, 1000000.0, 1000000.0]
        """
        if name not in _PROFILES:
            raise ValueError(f"name must be one of {tuple(_PROFILES)}, got {name!r}")
        value = getattr(self, name)
        if value is None:
            raise ValueError(f"the {self.model} chain has no {name}")
        length = {"ring": self.n_rings, "contact": self.n_contacts, "pair": self.n_rings - 1}[_PROFILES[name]]
        return np.broadcast_to(np.asarray(value, dtype=float), (length,))

    @property
    def damped(self) -> bool:
        return bool(np.any(self.gamma > 0) or np.any(self.gamma_b > 0))

    @property
    def contact_bonds(self) -> np.ndarray:
        """Lattice bond index of the contact between ring i and ring i+1, i = 0..n_rings-2."""
        return self.sites_per_ring * np.arange(self.n_rings - 1) + (self.sites_per_ring - 1)

    @property
    def bending_bonds(self) -> np.ndarray | None:
        """Lattice bond index of the bending spring of ring i (dual-spring), else None."""
        return 2 * np.arange(self.n_rings) if self.model == "dual-spring" else None

    @property
    def support_bond(self) -> int | None:
        """Lattice bond index of the contact with the fixed support, or None if free."""
        return self.n_sites - 1 if self.support == "fixed" else None

    @property
    def _contact_bond_indices(self) -> np.ndarray:
        """Lattice bond of each contact (the support's last when fixed): per-contact arrays go there."""
        bonds = self.contact_bonds
        return np.append(bonds, self.support_bond) if self.support == "fixed" else bonds

    @functools.cached_property
    def lattice(self) -> Lattice:
        """The sites and bonds integrated by the solver."""
        k = self.sites_per_ring
        n_bonds = self.n_sites if self.support == "fixed" else self.n_sites - 1
        contact = np.zeros(n_bonds, dtype=bool)
        contact[self._contact_bond_indices] = True
        spring = ~contact

        def on(bonds, value):
            """Per-bond array: ``value`` (a number or one per bond of ``bonds``) on those bonds, 0 elsewhere."""
            if np.ndim(value) == 0:
                return np.where(bonds, value, 0.0)
            out = np.zeros(n_bonds)
            out[bonds] = value
            return out

        def per_site(value):
            return np.full(self.n_sites, value / k) if np.ndim(value) == 0 else np.repeat(value / k, k)

        # A spring bond has no contact force (K_contact = 0); its exponent is a placeholder 1.
        n = self.n if np.ndim(self.n) == 0 else on(contact, self.n) + spring
        return Lattice(
            mass=per_site(self.m),
            weight_mass=per_site(self.m_gravity),
            K_contact=on(contact, self.K),
            n=n,
            K_spring=on(spring, 0.0 if self.K_b is None else self.K_b),
            gamma_contact=on(contact, self.gamma),
            gamma_spring=on(spring, self.gamma_b),
        )

    def ring_sites(self, i) -> np.ndarray:
        """Site indices of ring i (one site, or lower and upper half); ``i`` an index or an array of them."""
        i = np.asarray(i)
        if i.dtype.kind not in "iu" or np.any((i < 0) | (i >= self.n_rings)):
            raise ValueError(f"ring indices must be integers in 0..{self.n_rings - 1}, got {i.tolist()!r}")
        return self.sites_per_ring * i[..., None] + np.arange(self.sites_per_ring)

    def static_extension(self, g=STANDARD_GRAVITY, *, first_ring_hanging=True) -> np.ndarray:
        """Bond extensions, m, of the chain hanging at rest from its support.

        Bond k carries the weight of every site below it (the sites 0..k); its extension
        inverts its force law: (T/K)^(1/n) for a contact, T/K_b for a bending spring.

        Parameters
        ----------
        g : float
            Gravity, m/s^2.
        first_ring_hanging : bool, optional
            False when ring 0 is held up (lifted for a drop): its weight is then not on
            the chain and its own bonds are unloaded.
        """
        first_ring_hanging = _flag("first_ring_hanging", first_ring_hanging)
        if self.support != "fixed" and g > 0:
            raise ValueError("a chain with a free far end has no static equilibrium under gravity")
        weights = g * self.lattice.weight_mass
        if not first_ring_hanging:
            weights = weights.copy()
            weights[: self.sites_per_ring] = 0.0
        tension = np.cumsum(weights)[: self.lattice.n_bonds]
        if self.model == "power-law":  # every bond a contact: K and n per bond
            return (tension / self.K) ** (1.0 / self.n)
        e = np.empty_like(tension)
        contacts = self._contact_bond_indices
        e[contacts] = (tension[contacts] / self.K) ** (1.0 / self.n)
        e[0::2] = tension[0::2] / self.K_b
        return e

    def displacement_from_extension(self, e) -> np.ndarray:
        """Site displacements, m, with bond extensions ``e``: the support is the fixed
        reference when present, else site 0 is at 0."""
        e = np.asarray(e, dtype=float)
        if self.support == "fixed":
            return 0.0 - np.cumsum(e[..., ::-1], axis=-1)[..., ::-1]  # 0.0 - : no -0.0
        return np.concatenate([np.zeros((*e.shape[:-1], 1)), np.cumsum(e, axis=-1)], axis=-1)
