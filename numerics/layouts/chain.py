r"""A chain of interlocked rings as a network: masses, springs, dashpots, gravity, support.

:class:`Chain` holds the parameters of one of the paper's two models (Sec. III.B) and
builds the :class:`~ringchain.numerics.Network` that is integrated (:meth:`Chain.network`):
a layout of the engine.  Simulating a chain is simulating its network from the chain's
initial state, and reading the result as the paper reads its chain.

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
speed v carries momentum m v, not m0 v (unless the striker is given its own mass, below).
This is why a drop is started at the instant the slack is taken up, with the free-fall
speed sqrt(2 g h) of the real ring (:func:`ringchain.numerics.simulate`), rather than
integrated through the fall.

Initial conditions (paper Sec. III.A)
-------------------------------------
With gravity the chain hangs from its fixed support in static equilibrium (each contact
carries the weight below it, :meth:`Chain.static_extension`).  The impact is one of

- ``impact_velocity`` v: ring 0 starts moving away from the chain at speed v (along
  -axis) from the equilibrium of the whole chain;
- ``drop_height`` h: ring 0 was lifted and released, fell freely with its contacts
  slack, and the integration starts when its contact with ring 1 is just taut again,
  ring 0 moving away from the chain at sqrt(2 g h) (:func:`ringchain.theory.impact_speed`),
  unstretched (a freely falling ring carries no internal load), and the rest of the chain
  hanging at rest without ring 0's weight.  h is the free-fall height, from release to the
  instant the slack is taken up: the lift above the hanging position is h plus the static
  extension of contact 0, a few micrometres.

The striker
-----------
Ring 0, the struck ring, has the inertial mass of every lattice ring (the paper's
convention, the default) or its own ``striker_mass``: a ring in free fall moves as a rigid
body, so a rigid striker brings the momentum m0 v0 and the energy m0 v0^2/2 of the real ring
(``striker_mass="m0"``), however the inertia is shared inside the wave that follows.  With
m_eff = 0.37 m0 the paper's convention brings 37 % of both, and by the impact law
(:func:`ringchain.theory.impact_amplitude`) a wave (m0/m_eff)^(n/(n+1)) times weaker.
``striker_mass`` is stored in kg (None for the paper's convention); ring 0's sites get that
inertia (halves of striker_mass/2 in the dual-spring model), gravity still acts on
``m_gravity``.  A copy with other parameters (``dataclasses.replace``, the trace fits) keeps
a striker given in kg, a rigid ring of known mass; the paper's convention follows ``m``.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from ringchain.theory import STANDARD_GRAVITY, Ring, fit_power_law, linear
from ringchain.theory import _validate as v

from ..engine.integrate import impact_speeds
from ..engine.laws import LinearSpring, PowerLaw, Thornton
from ..engine.network import ANCHOR, Links, Network
from ..engine.results import BatchSimulation
from ._ring_numbers import contacts_K_c, pair_K_c, per_distinct, power_law_fits, rings_K_b
from .chain_kinds import GRADING_PROFILES, alternating_chain, graded_chain, joined_chain
from .disorder import disordered_chain
from .yielding import yielding_chain

__all__ = ["Chain", "MODELS", "SUPPORTS", "GRADING_PROFILES", "STRIKERS", "initial_state", "sensor_pair", "ring_index",
           "default_t_end", "striker_convention"]  # fmt: skip

#: What each parameter of a :class:`Chain` is given per, when it varies along the chain.
_PROFILES = {"K": "contact", "n": "contact", "gamma": "contact", "m": "ring", "m_gravity": "ring", "K_b": "ring",
             "gamma_b": "ring", "a": "pair", "delta_y": "contact", "delta_max": "contact"}  # fmt: skip

#: The two lattice models of paper Sec. III.B (named once, in :mod:`ringchain.theory.linear`).
MODELS = linear.MODELS

#: Boundary at the far end from the impact: hanging from a fixed support, or free.
SUPPORTS = ("fixed", "free")

#: The struck ring's inertia: the lattice's (``"m_eff"``, the paper's convention) or the real
#: ring's mass m0 (``"m0"``, a rigid ring in free fall); a number in kg is taken as it is.
STRIKERS = ("m_eff", "m0")


def striker_convention(value) -> str | float:
    """``value`` as a striker: ``"m_eff"`` (also for None), ``"m0"`` or a mass in kg (ValueError otherwise)."""
    if value is None:
        return "m_eff"
    if isinstance(value, str):
        return v.choice("striker_mass", value, STRIKERS)
    if isinstance(value, bool | np.bool_) or np.ndim(value) != 0:
        raise ValueError(f"striker_mass must be one mass (in kg) or one of {STRIKERS}, got {value!r}")
    return float(v.positive("striker_mass", value, "kg"))


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


@dataclass(frozen=True, eq=False)
class Chain:
    r"""A chain of ``n_rings`` interlocked rings, ring 0 at the impact end.

    Build it with :meth:`power_law`, :meth:`dual_spring` or :meth:`from_ring` (the paper's
    own chain: :func:`ringchain.numerics.jobs.paper.paper_chain`); a chain that changes along its
    length with :meth:`from_rings`, :meth:`graded`, :meth:`alternating` or :meth:`joined`; rings that
    differ at random with :meth:`disordered`.
    The contact law of both models is [K delta^n + gamma delta_dot]_+
    (:class:`~ringchain.numerics.laws.PowerLaw`);
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
    striker_mass : float or None
        Inertial mass of the struck ring 0, kg, or None: ``m``, the paper's convention (also
        ``"m_eff"``; ``"m0"``: ``m_gravity`` of ring 0, a rigid striker; :attr:`striker_inertia`).
    delta_y, delta_max : float, ndarray or None
        Yielding contacts (:mod:`.yielding`): Thornton's approach at first yield and the largest
        approach before the run, m (per contact); ``delta_y`` None: elastic Hertz contacts.
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
    striker_mass: float | str | None = None
    delta_y: float | None = None
    delta_max: float = 0.0

    def __post_init__(self):
        v.choice("model", self.model, MODELS)
        v.choice("support", self.support, SUPPORTS)
        set_ = functools.partial(object.__setattr__, self)
        set_("n_rings", v.count("n_rings", self.n_rings, 2))
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
        if self.delta_y is not None:  # Thornton contacts: Hertz's exponent only
            if np.any(np.asarray(self.n) != 1.5):
                raise ValueError("contacts that yield follow Hertz's law (n = 3/2): use the dual-spring model")
            set_("delta_y", _parameter("delta_y", self.delta_y, contacts, v.positive, "m", "contact"))
        set_("delta_max", _parameter("delta_max", self.delta_max, contacts, v.nonnegative, "m", "contact"))
        striker = striker_convention(self.striker_mass)
        set_("striker_mass", {"m_eff": None, "m0": float(self.profile("m_gravity")[0])}.get(striker, striker))

    def _key(self) -> tuple:
        return tuple(
            (value.shape, value.tobytes()) if isinstance(value, np.ndarray) else value
            for value in (self.model, self.n_rings, self.K, self.n, self.m, self.a, self.gamma, self.K_b,
                          self.gamma_b, self.m_gravity, self.support, self.striker_mass, self.delta_y, self.delta_max)
        )  # fmt: skip

    def __eq__(self, other):
        if not isinstance(other, Chain):
            return NotImplemented
        return self._key() == other._key()

    def __hash__(self):
        return hash(self._key())

    # -- constructors ------------------------------------------------------------------
    @classmethod
    def power_law(cls, n_rings, K, n, m, a, gamma=0.0, m_gravity=None, *, support="fixed", striker_mass=None) -> Chain:
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
        striker_mass : float or {"m_eff", "m0"}, optional
            Inertial mass of ring 0, kg; default ``m`` (the paper's convention); "m0": ``m_gravity``.

        Examples
        --------
        >>> chain = Chain.power_law(20, K=4.9e6, n=1.11, m=8.2e-3, a=0.04)
        >>> chain.n_sites, chain.network().n_links  # 19 contacts and the support
        (20, 20)
        """
        return cls("power-law", n_rings, K, n, m, a, gamma=gamma, m_gravity=m_gravity, support=support,
                   striker_mass=striker_mass)  # fmt: skip

    @classmethod
    def dual_spring(
        cls, n_rings, K_c, K_b, m, a, gamma_c=0.0, gamma_b=0.0, m_gravity=None, *, support="fixed", striker_mass=None
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
        striker_mass : float or {"m_eff", "m0"}, optional
            Inertial mass of ring 0 (both halves), kg; default ``m``; "m0": ``m_gravity``.

        Examples
        --------
        >>> chain = Chain.dual_spring(20, K_c=7.5e9, K_b=3.3e6, m=8.2e-3, a=0.04)
        >>> chain.n_sites, chain.contact_links[:3].tolist(), chain.bending_links[:3].tolist()
        (40, [1, 3, 5], [0, 2, 4])
        """
        return cls(
            "dual-spring", n_rings, K_c, 1.5, m, a, gamma=gamma_c, K_b=K_b, gamma_b=gamma_b,
            m_gravity=m_gravity, support=support, striker_mass=striker_mass,
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
        striker_mass=None,
        yield_strength=None,
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
        striker_mass : float or {"m_eff", "m0"}, optional
            Inertial mass of ring 0, kg: default m_eff (the paper's); "m0" the ring's (module notes).
        yield_strength : float, optional
            Pa: contacts that yield, from the hanging chain's plastic equilibrium (dual-spring; :mod:`.yielding`).

        Examples
        --------
        >>> chain = Chain.from_ring(Ring.from_aspect_ratio(9.0), 20, m_eff_ratio=0.37)
        >>> round(chain.m / chain.m_gravity, 2), round(chain.a * 1e3, 1)
        (0.37, 40.0)
        """
        if not isinstance(ring, Ring):
            raise TypeError(f"ring must be a ringchain.theory.Ring, got {type(ring).__name__}")
        ring.check_chain()
        v.choice("model", model, MODELS)
        ratio = float(v.in_range("m_eff_ratio", m_eff_ratio, 0.0, 1.0))
        m0 = ring.mass
        if model == "dual-spring":
            if K is not None or n is not None or gamma:
                raise ValueError("K, n and gamma belong to the power-law model; use gamma_c and gamma_b")
            chain = cls.dual_spring(
                n_rings, ring.K_c, ring.K_b, ratio * m0, ring.spacing, gamma_c, gamma_b, m0, support=support,
                striker_mass=striker_mass,
            )  # fmt: skip
            return chain if yield_strength is None else yielding_chain(chain, [ring] * n_rings, yield_strength,
                                                                       ring.angle)  # fmt: skip
        if gamma_c or gamma_b or yield_strength is not None:
            raise ValueError("gamma_c, gamma_b and yield_strength belong to the dual-spring model")
        if (K is None) != (n is None):
            raise ValueError("give both K and n, or neither (then the series law is fitted, Eq. 4)")
        if K is None:
            K, n = ring.power_law()
        return cls.power_law(n_rings, K, n, ratio * m0, ring.spacing, gamma, m0, support=support,
                             striker_mass=striker_mass)  # fmt: skip

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
        striker_mass=None,
        yield_strength=None,
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
        striker_mass : float or {"m_eff", "m0"}, optional
            Inertial mass of ring 0, kg (see :meth:`from_ring`).
        yield_strength : float or array_like, optional
            Pa, one number or one per ring: contacts that yield (see :meth:`from_ring`).

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
        v.choice("model", model, MODELS)
        v.choice("support", support, SUPPORTS)
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
        K_c = per_distinct(pair_K_c, [(below, above, float(angle)) for (below, above), angle in
                                        zip(pairs, angles, strict=True)], "contact of rings {i} and {j}",
                            contacts_K_c)  # fmt: skip
        K_b = per_distinct(lambda ring: ring.K_b, [(ring,) for ring in rings], "ring {i}", rings_K_b)
        m0 = np.array([ring.mass for ring in rings])
        a = np.array([(below.R - below.r) + (above.R - above.r) for below, above in pairs[: n_rings - 1]])
        if model == "dual-spring":
            if gamma is not None and np.any(gamma):
                raise ValueError("gamma belongs to the power-law model; use gamma_c and gamma_b")
            chain = cls.dual_spring(n_rings, K_c, K_b[:n_rings], ratio * m0, a, gamma_c, gamma_b, m0, support=support,
                                    striker_mass=striker_mass)  # fmt: skip
            return chain if yield_strength is None else yielding_chain(chain, rings, yield_strength, angles)
        if np.any(gamma_c) or np.any(gamma_b) or yield_strength is not None:
            raise ValueError("gamma_c and gamma_b belong to the dual-spring model; use gamma")
        # Each period of the chain is a contact in series with the body of the ring below it (Eq. 3).
        below_K_b = np.append(K_b, K_b[-1])[: len(pairs)]
        fits = per_distinct(lambda kc, kb: tuple(float(x) for x in fit_power_law(K_c=kc, K_b=kb)),
                             list(zip(K_c.tolist(), below_K_b.tolist(), strict=True)), "contact {i}",
                             power_law_fits)  # fmt: skip
        return cls.power_law(n_rings, fits[:, 0], fits[:, 1], ratio * m0, a, gamma, m0, support=support,
                             striker_mass=striker_mass)  # fmt: skip

    # A chain of rings drawn at random about a nominal ring (issue 23): disorder.disordered_chain's docstring.
    disordered = classmethod(disordered_chain)

    # Chains built from others (their docstrings in :mod:`.chain_kinds`).
    graded = classmethod(graded_chain)
    alternating = classmethod(alternating_chain)
    joined = classmethod(joined_chain)

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
    def striker_inertia(self) -> float:
        """Inertial mass of ring 0, the striker, kg: ``striker_mass``, or ``m`` of ring 0 (the paper's convention)."""
        return float(self.profile("m")[0]) if self.striker_mass is None else self.striker_mass

    def striker_reduced_mass(self, m) -> float:
        """Reduced mass of the striker (ring 0, :attr:`striker_inertia`) and a ring of mass ``m`` (kg), kg."""
        return self.striker_inertia * m / (self.striker_inertia + m)

    @property
    def damped(self) -> bool:
        return bool(np.any(self.gamma > 0) or np.any(self.gamma_b > 0))

    # -- the network --------------------------------------------------------------------------
    @property
    def contact_links(self) -> np.ndarray:
        """Network link index of the contact between ring i and ring i+1, i = 0..n_rings-2."""
        return self.sites_per_ring * np.arange(self.n_rings - 1) + (self.sites_per_ring - 1)

    @property
    def bending_links(self) -> np.ndarray | None:
        """Network link index of the bending spring of ring i (dual-spring), else None."""
        return 2 * np.arange(self.n_rings) if self.model == "dual-spring" else None

    @property
    def support_link(self) -> int | None:
        """Network link index of the contact with the fixed support, or None if free."""
        return self.n_sites - 1 if self.support == "fixed" else None

    def network(self) -> Network:
        """The sites and links the engine integrates (one site per ring, or two halves of m/2 for the
        dual-spring model; :attr:`contact_links`, :attr:`bending_links`, :attr:`support_link` say
        which link is which).  Built once per chain.

        Examples
        --------
        >>> chain = Chain.dual_spring(3, K_c=7.5e9, K_b=3.3e6, m=8.2e-3, a=0.04)
        >>> net = chain.network()
        >>> net.n_sites, net.n_links, net.i.tolist(), net.j.tolist()  # spring, contact, spring, ..., the support
        (6, 6, [0, 1, 2, 3, 4, 5], [1, 2, 3, 4, 5, -1])
        """
        return self._network

    @functools.cached_property
    def _network(self) -> Network:
        k, N = self.sites_per_ring, self.n_rings

        def per_site(value):
            return np.full(self.n_sites, value / k) if np.ndim(value) == 0 else np.repeat(value / k, k)

        mass = per_site(self.m)
        if self.striker_mass is not None:
            mass = mass.copy() if np.ndim(self.m) else mass
            mass[:k] = self.striker_mass / k
        # Rest positions along the axis (only the length scale of the tolerances reads them): the
        # ring centres a apart, the halves of a dual-spring ring a quarter spacing either side.
        a = self.profile("a")
        centres = np.concatenate([[0.0], np.cumsum(a)])
        if k == 2:
            below, above = np.concatenate([[a[0]], a]), np.concatenate([a, [a[-1]]])
            positions = np.stack([centres - below / 4, centres + above / 4], axis=-1).ravel()
        else:
            positions = centres
        # Contact c joins ring c (its upper half) to ring c + 1 (its lower half); the support's, the top ring to
        # the anchor.
        i = k * np.arange(self.n_contacts) + (k - 1)
        j = i + 1
        if self.support == "fixed":
            j[-1] = ANCHOR
        law = PowerLaw(self.K, self.n, self.gamma)
        if self.delta_y is not None:  # contacts that yield (:mod:`.yielding`)
            law = Thornton(self.K, self.delta_y, self.gamma, self.delta_max)
        links = [Links(i, j, law, index=i)]
        if self.model == "dual-spring":
            springs = k * np.arange(N)
            links.insert(0, Links(springs, springs + 1, LinearSpring(self.K_b, self.gamma_b), index=springs))
        return Network(mass, links, weight_mass=per_site(self.m_gravity), positions=positions,
                       rings=np.repeat(np.arange(N), k))  # fmt: skip

    def ring_sites(self, i) -> np.ndarray:
        """Site indices of ring i (one site, or lower and upper half); ``i`` an index or an array of them."""
        i = np.asarray(i)
        if i.dtype.kind not in "iu" or np.any((i < 0) | (i >= self.n_rings)):
            raise ValueError(f"ring indices must be integers in 0..{self.n_rings - 1}, got {i.tolist()!r}")
        return self.sites_per_ring * i[..., None] + np.arange(self.sites_per_ring)

    def ring_index(self, ring) -> int:
        """``ring`` as a ring index of this chain (ValueError naming it otherwise)."""
        return ring_index(ring, self.n_rings)

    def sensor_links(self, rings) -> tuple[np.ndarray, np.ndarray]:
        """Links read by the sensors of ``rings`` and their weights, each of shape (len(rings), 2).

        The dual-spring sensor is ring j's bending link; the power-law sensor is the mean of
        the contacts below (j - 1) and above (j) ring j (see
        :attr:`~ringchain.numerics.Simulation.sensor_force`).  A link that does not exist (below
        ring 0, above a free top ring) has weight 0.
        """
        rings = np.asarray(rings, dtype=int)
        if self.model == "dual-spring":
            links = np.stack([2 * rings, 2 * rings], axis=-1)
            return links, np.broadcast_to([1.0, 0.0], links.shape)
        below, above = rings - 1, rings
        has_below, has_above = below >= 0, above < self.n_contacts
        links = np.stack([np.where(has_below, below, above), np.where(has_above, above, below)], axis=-1)
        return links, 0.5 * np.stack([has_below, has_above], axis=-1)

    def recorded_sites(self, rings) -> np.ndarray:
        """Sites whose states the sensors of ``rings`` need (sorted)."""
        links, weights = self.sensor_links(np.array(rings))
        used = links[weights > 0]
        net = self.network()
        sites = np.concatenate([net.i[used], net.j[used]])
        return np.unique(sites[sites != ANCHOR])

    # -- statics ---------------------------------------------------------------------------------
    def static_extension(self, g=STANDARD_GRAVITY, *, first_ring_hanging=True) -> np.ndarray:
        """Link extensions, m, of the chain hanging at rest from its support.

        Link k carries the weight of every site below it; its extension inverts its law:
        (T/K)^(1/n) for a contact, T/K_b for a bending spring.

        Parameters
        ----------
        g : float
            Gravity, m/s^2.
        first_ring_hanging : bool, optional
            False when ring 0 is held up (lifted for a drop): its weight is then not on
            the chain and its own links are unloaded.
        """
        first_ring_hanging = v.flag("first_ring_hanging", first_ring_hanging)
        if self.support != "fixed" and g > 0:
            raise ValueError("a chain with a free far end has no static equilibrium under gravity")
        net = self.network()
        weights = g * net.weight_mass
        if not first_ring_hanging:
            weights = weights.copy()
            weights[: self.sites_per_ring] = 0.0
        return net.extension_at(np.cumsum(weights)[: net.n_links])  # link k carries sites 0..k

    def displacement_from_extension(self, e) -> np.ndarray:
        """Site displacements, m, with link extensions ``e``: the support is the fixed
        reference when present, else site 0 is at 0."""
        e = np.asarray(e, dtype=float)
        if self.support == "fixed":
            return 0.0 - np.cumsum(e[..., ::-1], axis=-1)[..., ::-1]  # 0.0 - : no -0.0
        return np.concatenate([np.zeros((*e.shape[:-1], 1)), np.cumsum(e, axis=-1)], axis=-1)

    # -- the model contract (ringchain.numerics.engine.integrate) -------------------------------------------
    def dynamics(self) -> Network:
        """What the engine integrates: :meth:`network`."""
        return self.network()

    def impact_state(self, speeds, dropped, gravity, g):
        """Displacements and velocities of B runs at t = 0 (module notes); ``speeds`` validated (m/s)."""
        if gravity and self.support != "fixed":
            raise ValueError("gravity needs the chain to hang from a fixed support (support='fixed')")
        e = self.static_extension(g if gravity else 0.0, first_ring_hanging=not dropped)
        x = np.broadcast_to(self.displacement_from_extension(e), (speeds.size, self.n_sites)).copy()
        u = np.zeros_like(x)
        u[:, : self.sites_per_ring] = -speeds[:, None]
        return x, u

    def recorded(self, rings):
        """The rings to record (sorted, validated) and the sites their sensors need; (None, None) for all."""
        if rings is None:
            return None, None
        values = [rings] if np.ndim(rings) == 0 else list(rings)
        if not values:
            raise ValueError("rings must name at least one ring (or be None for every ring)")
        rings = tuple(sorted({self.ring_index(r) for r in values}))
        return rings, self.recorded_sites(rings)

    def result(self, **record) -> BatchSimulation:
        """The record of a batch of runs of this chain."""
        return BatchSimulation(chain=self, network=self.network(), **record)


def initial_state(chain: Chain, *, impact_velocity=None, drop_height=None, gravity=True, g=STANDARD_GRAVITY):
    """Site displacements and velocities at t = 0, shape (B, n_sites) each.

    Parameters
    ----------
    chain : Chain
    impact_velocity : float or array_like, optional
        Speed of ring 0 moving away from the chain, m/s (one run per value).
    drop_height : float or array_like, optional
        Free-fall height of ring 0, m; the impact speed is sqrt(2 g h) (see module notes).
    gravity : bool, optional
        Start from the hanging equilibrium (needs a fixed support) or, if False, from the
        unstretched chain with every contact just taut.
    g : float, optional
        Gravity, m/s^2; also sets sqrt(2 g h) when gravity is off.

    Returns
    -------
    x, u : ndarray, shape (B, n_sites)
        Displacements (m) and velocities (m/s) along the axis pointing away from the impact.

    Examples
    --------
    >>> chain = Chain.power_law(3, K=1e6, n=1.5, m=0.01, a=0.04)
    >>> x, u = initial_state(chain, impact_velocity=[0.5, 1.0], gravity=False)
    >>> x.tolist(), u.tolist()
    ([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]], [[-0.5, 0.0, 0.0], [-1.0, 0.0, 0.0]])
    """
    if not isinstance(chain, Chain):
        raise TypeError(f"chain must be a Chain, got {type(chain).__name__}")
    g = float(v.positive("g", g, "m/s^2"))
    speeds, dropped = impact_speeds(impact_velocity, drop_height, g)
    return chain.impact_state(speeds, dropped, v.flag("gravity", gravity), g)


def ring_index(ring, n_rings: int) -> int:
    """``ring`` as the index of a ring of a chain of ``n_rings`` (ValueError naming it otherwise)."""
    i = v.integer("ring", ring)
    if not 0 <= i < n_rings:
        raise ValueError(f"ring {i} is not in a chain of {n_rings} rings (0..{n_rings - 1})")
    return i


def default_t_end(chain: Chain, speeds, sensors) -> float:
    """Duration that lets the leading pulse pass the far sensor, s.

    The time the long-wave solitary wave of the chain's power law (Eq. (8)) needs to
    carry its front 1.5 times the distance to ring ``sensors[1]`` plus half a wave width
    (:func:`ringchain.theory.solitary_wave_width`), at a force estimate below the actual
    peak (so the estimated speed is low and the duration long): a quarter of the peak
    force of the striker's collision with ring 1 at the smallest impact speed (the striker of
    :class:`~ringchain.numerics.Chain`, of mass ``striker_inertia``), and at least the weight
    of one ring (the gravity prestress keeps weak waves fast).  For the dual-spring
    chain the power law is the one fitted to its contact and bending springs in series
    (Eq. 4).  :func:`run_points` doubles the duration if a pulse is still passing the far
    sensor at the end.

    The half width is capped at the chain's length: as n -> 1 the long-wave width grows
    without bound (~ a/(n - 1)), but no pulse wider than the chain passes the sensor before
    its reflection from the support comes back, and the capped duration stays finite
    (without the cap, 79 s of simulated time at R/r = 100, 2.5e3 s at R/r = 200).
    """
    from ringchain.theory import fit_power_law, solitary_wave_speed, solitary_wave_width

    if not isinstance(chain, Chain):
        raise TypeError(f"chain must be a Chain, got {type(chain).__name__}")
    speeds = np.atleast_1d(v.positive("speeds", speeds, "m/s"))
    if speeds.size == 0:
        raise ValueError("speeds must hold at least one impact speed (m/s)")
    far = sensor_pair(sensors, chain.n_rings)[1]
    if not chain.uniform:
        return _varying_t_end(chain, speeds, far)
    if chain.model == "dual-spring":
        K, n = (float(x) for x in fit_power_law(K_c=chain.K_c, K_b=chain.K_b))
    else:
        K, n = chain.K, chain.n
    speed = float(np.min(speeds))
    # The striker m_s hitting ring 1 (m) at v stores mu v^2/2 at the peak of K delta^n, mu = m_s m/(m_s + m).
    delta = ((n + 1.0) * 0.5 * chain.striker_reduced_mass(chain.m) * speed**2 / K) ** (1.0 / (n + 1.0))
    force = max(0.25 * K * delta**n, chain.m_gravity * STANDARD_GRAVITY)
    V = float(solitary_wave_speed(force, K=K, n=n, a=chain.a, m=chain.m))
    width = min(float(solitary_wave_width(n=n, a=chain.a)), chain.n_rings * chain.a)
    return (1.5 * far * chain.a + 0.5 * width) / V


def _varying_t_end(chain: Chain, speeds, far: int) -> float:
    """:func:`default_t_end` of a chain that changes along its length: the same estimate contact by
    contact (each contact's power law, the heaviest ring), the pulse's time summed over the
    contacts up to the far sensor."""
    from ringchain.theory import fit_power_law, solitary_wave_speed, solitary_wave_width

    pairs = slice(0, chain.n_rings - 1)
    if chain.model == "dual-spring":
        K, n = fit_power_law(K_c=chain.profile("K")[pairs], K_b=chain.profile("K_b")[: chain.n_rings - 1])
    else:
        K, n = chain.profile("K")[pairs], chain.profile("n")[pairs]
    m, a, speed = float(np.max(chain.m)), chain.profile("a"), float(np.min(speeds))
    delta = ((n + 1.0) * 0.5 * chain.striker_reduced_mass(m) * speed**2 / K) ** (1.0 / (n + 1.0))
    force = np.maximum(0.25 * K * delta**n, float(np.min(chain.m_gravity)) * STANDARD_GRAVITY)
    V = solitary_wave_speed(force, K=K, n=n, a=a, m=m)
    width = min(float(np.max(solitary_wave_width(n=n, a=a))), float(np.sum(a)))
    return float(1.5 * np.sum(a[:far] / V[:far]) + 0.5 * width / np.min(V))


def sensor_pair(sensors, n_rings=None) -> tuple[int, int]:
    """Two sensor rings, near then far from the impact, within ``n_rings`` if given (ValueError saying why)."""
    if isinstance(sensors, str) or np.ndim(sensors) != 1 or len(sensors) != 2:
        raise ValueError(f"sensors must be two rings, near then far from the impact, got {sensors!r}")
    near, far = (v.integer("sensor ring", s) for s in sensors)
    if not 0 <= near < far:
        raise ValueError(f"sensors must be two rings, near then far, counted from 0, got {tuple(sensors)!r}")
    if n_rings is not None and far >= n_rings:
        raise ValueError(f"sensor ring {far} is not in a chain of {n_rings} rings (0..{n_rings - 1})")
    return near, far
