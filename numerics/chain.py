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
from ringchain.theory import Ring, linear, n_per_mm_to_si, paper_data
from ringchain.theory import _validate as v

from .models import STANDARD_GRAVITY, Lattice

__all__ = ["Chain", "MODELS", "SUPPORTS", "STIFFNESS_SOURCES"]

#: What each parameter of a :class:`Chain` is given per, when it varies along the chain.
_PROFILES = {"K": "contact", "n": "contact", "gamma": "contact", "m": "ring", "m_gravity": "ring", "K_b": "ring",
             "gamma_b": "ring", "a": "pair"}  # fmt: skip

#: The two lattice models of paper Sec. III.B (named once, in :mod:`ringchain.theory.linear`).
MODELS = linear.MODELS

#: Boundary at the far end from the impact: hanging from a fixed support, or free.
SUPPORTS = ("fixed", "free")

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
        K_si = float(n_per_mm_to_si(K_mm, n))
        if model == "power-law":
            return cls.from_ring(ring, n_rings, model, m_eff_ratio=ratio, K=K_si, n=n, **dashpots)
        from .paper import series_stiffness_for_power_law

        if "gamma" in dashpots:
            raise ValueError("K, n and gamma belong to the power-law model; use gamma_c and gamma_b")
        K_c, K_b = series_stiffness_for_power_law(K_si, n)
        m0 = ring.mass
        return cls.dual_spring(n_rings, K_c, K_b, ratio * m0, ring.spacing, m_gravity=m0, **dashpots)

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
