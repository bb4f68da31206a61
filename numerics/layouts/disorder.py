r"""Rings that differ from one another: random draws about a nominal ring (issue 23; beyond the paper).

The paper's last sentence asks for the effects of disorder.  Real rings differ in their radii,
in the angle at which neighbours meet and, in the measured power law, in the contact itself.
:func:`draw_rings` draws the rings of one chain at random about a nominal
:class:`~ringchain.theory.Ring`; :meth:`~ringchain.numerics.Chain.disordered` builds the chain
from the draw (through :meth:`~ringchain.numerics.Chain.from_rings`, so that every contact is
the unequal-torus contact of its two rings, :func:`~ringchain.theory.hertz_stiffness_pair`);
:func:`~ringchain.numerics.jobs.ensemble` runs many such chains.

What is drawn
-------------
``spread`` maps each quantity to its relative spread: a number s >= 0 (the value is the nominal
one times 1 + s z, z standard normal: s is the relative standard deviation), or a frozen
:mod:`scipy.stats` distribution of the factor value/nominal (``scipy.stats.uniform(0.9, 0.2)``:
within 10 % either side; mean 1 leaves the mean where it was).

- ``"R"``, ``"r"`` -- major and tube radius of each ring (per ring): mass, spacing, bending
  stiffness and contacts follow from the geometry;
- ``"angle"`` -- contact angle of each contact (per contact, the support's last when fixed),
  about the ring's own; an angle drawn above pi/2 is folded back to pi minus it (the angle
  between two ring planes is at most 90 degrees);
- ``"K"``, ``"m"`` (power-law model only) -- the prefactor of each contact's fitted power law
  (per contact) and each ring's mass (per ring, through the density: inertia and weight alike),
  the setting of :mod:`ringchain.theory.disorder`, whose exponent n is common to every contact.

Truncation
----------
A draw that would make a ring or a contact impossible is drawn again from the same stream
until it is possible: the distribution is truncated there.  Impossible are a factor <= 0, a
ring that cannot hold its neighbours -- R/r < 3 (:attr:`~ringchain.theory.Ring.can_form_chain`),
or a hole 2(R_j - r_j) too small for the wires of both neighbours, 2(r_{j-1} + r_{j+1}) (the same
condition for equal rings) -- and a contact without a single Hertz contact
(:func:`~ringchain.theory.hertz_stiffness_pair` refuses its angle); an impossible contact draws
its angle again if the angle is spread, else its two rings.  :class:`RingDraw` records how many
values were drawn again; :meth:`~ringchain.numerics.Chain.disordered` warns with a
:class:`DisorderWarning`, :func:`~ringchain.numerics.jobs.ensemble` records the count per member.

Seeds
-----
Every draw comes from :class:`numpy.random.Generator` s seeded by a
:class:`numpy.random.SeedSequence`: ``seed`` (an integer or a SeedSequence) gives each
quantity its own stream, the child with key :data:`SPREAD_NAMES`.index(name) (so adding a spread
in r leaves the draws of R as they were), and :func:`member_seeds` gives the members of an
ensemble theirs, SeedSequence(seed).spawn(count).  The same seed gives the same chain, on any
machine and in any process.
"""

from __future__ import annotations

import dataclasses
import numbers
import warnings
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from ringchain.theory import MIN_CHAIN_ASPECT_RATIO, Ring, bending_stiffness, hertz_stiffness, hertz_stiffness_pair
from ringchain.theory import _validate as v

__all__ = [
    "SPREAD_NAMES",
    "GEOMETRY_SPREADS",
    "POWER_LAW_SPREADS",
    "MAX_REDRAW_ROUNDS",
    "DisorderWarning",
    "RingDraw",
    "draw_rings",
    "disordered_chain",
    "check_spread",
    "check_seed",
    "member_seeds",
    "describe_spread",
]

#: Quantities a disordered chain may spread, in the order that keys their random streams.
SPREAD_NAMES = ("R", "r", "angle", "K", "m")

#: Quantities of the ring's geometry (either model).
GEOMETRY_SPREADS = ("R", "r", "angle")

#: Quantities only the power-law model spreads (its contact prefactor and ring mass).
POWER_LAW_SPREADS = ("K", "m")

#: Rounds of redrawing before a spread is refused as making rings impossible too often.
MAX_REDRAW_ROUNDS = 1000

#: Relative rounding allowed at the chain limit R >= 3 r (as :attr:`ringchain.theory.Ring.can_form_chain`).
_ROUNDING = 4 * np.finfo(float).eps


class DisorderWarning(UserWarning):
    """Values of a disordered chain were drawn again: the distribution was truncated where rings are impossible."""


def check_spread(spread, model: str = "dual-spring") -> dict:
    """``spread`` checked: {name: relative standard deviation (float) or frozen distribution}, in SPREAD_NAMES order.

    Parameters
    ----------
    spread : mapping
        Names of :data:`SPREAD_NAMES` to a number >= 0 (relative standard deviation) or an
        object with an ``rvs(size=, random_state=)`` method (a frozen :mod:`scipy.stats`
        distribution of value/nominal).  ``"K"`` and ``"m"`` only for the power-law model.
    model : {"dual-spring", "power-law"}

    Returns
    -------
    dict
        The spreads with a non-zero number or a distribution (zeros dropped), keyed in the order of
        :data:`SPREAD_NAMES`.

    Examples
    --------
    >>> check_spread({"r": 0.05, "R": 0.1, "angle": 0.0})
    {'R': 0.1, 'r': 0.05}
    """
    if not isinstance(spread, Mapping):
        raise TypeError(f"spread must be a mapping of names ({', '.join(SPREAD_NAMES)}) to spreads, got {spread!r}")
    unknown = [name for name in spread if name not in SPREAD_NAMES]
    if unknown:
        raise ValueError(f"spread: unknown quantity {unknown[0]!r}; spread one of {', '.join(SPREAD_NAMES)}")
    if model != "power-law" and any(name in spread for name in POWER_LAW_SPREADS):
        raise ValueError(
            "spread: K and m spread the power-law model's contact prefactor and ring mass; the dual-spring chain "
            "takes its springs and masses from the rings' geometry (spread R, r or angle)"
        )
    checked = {}
    for name in SPREAD_NAMES:
        if name not in spread:
            continue
        value = spread[name]
        if callable(getattr(value, "rvs", None)):
            checked[name] = value
            continue
        if isinstance(value, bool) or not isinstance(value, numbers.Real):
            raise TypeError(
                f"spread[{name!r}] must be a relative standard deviation (a number >= 0) or a scipy.stats "
                f"distribution of value/nominal, got {value!r}"
            )
        value = float(v.nonnegative(f"spread[{name!r}] (a relative standard deviation)", value))
        if value > 0:
            checked[name] = value
    return checked


def describe_spread(spread) -> str:
    """The spreads in a few words: ``"R 10 %, r 5 %"`` (a distribution by its name), or ``"none"``."""
    words = []
    for name, value in spread.items():
        if isinstance(value, float):
            words.append(f"{name} {100 * value:.3g} %")
        else:
            dist = getattr(value, "dist", None)
            words.append(f"{name} {getattr(dist, 'name', type(value).__name__)}")
    return ", ".join(words) or "none"


def check_seed(seed) -> np.random.SeedSequence:
    """``seed`` as a SeedSequence: a non-negative integer (or a sequence of them), or a SeedSequence as it is.

    None and a :class:`numpy.random.Generator` are refused: a draw must be repeatable from its seed.
    """
    if isinstance(seed, np.random.SeedSequence):
        return seed
    if seed is None or isinstance(seed, np.random.Generator | np.random.BitGenerator | bool | float | str):
        raise TypeError(
            f"seed must be a non-negative integer or a numpy.random.SeedSequence (so that the draw can be repeated), "
            f"got {seed!r}"
        )
    try:
        return np.random.SeedSequence(seed)
    except (TypeError, ValueError) as error:
        raise ValueError(f"seed must be a non-negative integer or a numpy.random.SeedSequence: {error}") from None


def member_seeds(seed, count: int) -> tuple:
    """The seeds of the ``count`` members of an ensemble: the children of ``seed``, as SeedSequence(seed).spawn(count).

    Member i's seed depends on ``seed`` and i only (not on how many members there are, nor on
    what the SeedSequence spawned before), so that an ensemble is the same however it is split.

    Examples
    --------
    >>> [s.spawn_key for s in member_seeds(7, 3)]
    [(0,), (1,), (2,)]
    >>> member_seeds(7, 3)[2].generate_state(1) == np.random.SeedSequence(7).spawn(3)[2].generate_state(1)
    array([ True])
    """
    root = check_seed(seed)
    count = v.count("count", count, 1)
    return tuple(
        np.random.SeedSequence(root.entropy, spawn_key=(*root.spawn_key, i), pool_size=root.pool_size)
        for i in range(count)
    )


def _stream(seed: np.random.SeedSequence, name: str) -> np.random.Generator:
    """The generator of quantity ``name`` under ``seed``: its child keyed by the name's place in SPREAD_NAMES."""
    child = np.random.SeedSequence(seed.entropy, spawn_key=(*seed.spawn_key, SPREAD_NAMES.index(name)),
                                   pool_size=seed.pool_size)  # fmt: skip
    return np.random.default_rng(child)


@dataclass(frozen=True, eq=False)
class RingDraw:
    """The random draw of one disordered chain (:func:`draw_rings`).

    Attributes
    ----------
    rings : tuple of Ring
        The rings from the impact end; a mass spread enters through each ring's density.
    angles : ndarray or None
        Contact angle of each contact, rad (None: every ring's own angle, not spread).
    K_factor : ndarray or None
        Factor on each contact's power-law prefactor (power-law model; None: not spread).
    redrawn : dict
        {name: values drawn again} for the spread quantities (module notes, "Truncation").
    seed : numpy.random.SeedSequence
        The seed of the draw.
    """

    rings: tuple
    angles: np.ndarray | None
    K_factor: np.ndarray | None
    redrawn: dict
    seed: np.random.SeedSequence

    @property
    def total_redrawn(self) -> int:
        """Values drawn again, all quantities together."""
        return int(sum(self.redrawn.values()))

    def build(self, cls, model: str = "dual-spring", m_eff_ratio: float = 1.0, **options):
        """The chain of these rings: ``cls.from_rings`` (each contact that of its two rings), then the K factors.

        ``cls`` is :class:`~ringchain.numerics.Chain` (this module sits below it and does not import it);
        ``model``, ``m_eff_ratio`` and ``options`` as in :meth:`~ringchain.numerics.Chain.from_rings`.
        """
        chain = cls.from_rings(self.rings, self.angles, model, m_eff_ratio=m_eff_ratio, **options)
        if self.K_factor is None:
            return chain
        return dataclasses.replace(chain, K=chain.profile("K") * self.K_factor)

    def warn(self, stacklevel: int = 3) -> None:
        """Warn with a :class:`DisorderWarning` if any value was drawn again, saying how many."""
        if self.total_redrawn:
            counts = ", ".join(f"{count} of {name}" for name, count in self.redrawn.items() if count)
            warnings.warn(
                f"{self.total_redrawn} drawn values would have made a ring or a contact impossible and were drawn "
                f"again ({counts}): the distribution is truncated there", DisorderWarning, stacklevel=stacklevel,
            )  # fmt: skip


def _factors(source, size: int, rng: np.random.Generator) -> np.ndarray:
    """``size`` factors value/nominal: 1 + s z for a relative standard deviation s, or the distribution's draws."""
    if isinstance(source, float):
        return 1.0 + source * rng.standard_normal(size)
    values = np.asarray(source.rvs(size=size, random_state=rng), dtype=float)
    if values.shape != (size,):
        raise ValueError(f"a spread's distribution gave values of shape {values.shape} for size={size}")
    return values


def _folded(angle: np.ndarray) -> np.ndarray:
    """Angles between ring planes: an angle above pi/2 is pi minus it."""
    return np.where(angle > np.pi / 2, np.pi - angle, angle)


def _bad_rings(R, r, support: str) -> np.ndarray:
    """Rings that cannot be links of the chain: R < 3 r, or a hole 2(R - r) too small for both neighbours' wires."""
    with np.errstate(all="ignore"):
        bad = ~(np.isfinite(R) & np.isfinite(r) & (r > 0) & (R >= MIN_CHAIN_ASPECT_RATIO * r * (1.0 - _ROUNDING)))
        below = np.concatenate([[0.0], r[:-1]])  # ring 0 has no neighbour below
        above = np.concatenate([r[1:], [r[-1] if support == "fixed" else 0.0]])  # the support: a ring like the top
        bad |= ~(R - r >= (below + above) * (1.0 - _ROUNDING))
    return bad


def _bad_contacts(R, r, angles, material, support: str) -> np.ndarray:
    """Contacts whose angle has no single Hertz contact for their two rings (checked together, then one by one)."""
    upper = np.arange(1, R.size + (support == "fixed"))
    upper[-1] = min(upper[-1], R.size - 1)  # the support's contact: the top ring with a ring like itself
    lower = np.arange(upper.size)
    args = (R[lower], r[lower], material.E, material.nu, R[upper], r[upper], material.E, material.nu)
    try:
        hertz_stiffness_pair(*args, angles)
        return np.zeros(upper.size, dtype=bool)
    except ValueError:
        pass
    bad = np.zeros(upper.size, dtype=bool)
    for c in range(upper.size):
        try:
            hertz_stiffness_pair(*(a[c] if np.ndim(a) else a for a in args), angles[c])
        except ValueError:
            bad[c] = True
    return bad


def _drawn_rings(ring, R, r, density) -> tuple:
    """The drawn rings: ``Ring(R_j, r_j)`` of the nominal ring's material (its density times ``density_j``), angle
    and bending setting, checked together.

    A Ring checks itself when made (Hertz contact with a ring like itself at its angle, Eq. (1); its bending
    stiffness, Eq. (2); a finite mass), which costs a tenth of a millisecond a ring, most of a disordered chain's
    making.  Here :func:`~ringchain.theory.hertz_stiffness` and :func:`~ringchain.theory.bending_stiffness` check
    all the rings in one call each (they check elementwise), then each ring is the nominal one with its radii and
    material replaced: the same fields as made one by one (tests/numerics/jobs/test_ensemble.py compares them).
    Where the arrays fail a check, the rings are made one by one, which raises the first one's error as before.
    """
    material = ring.material
    materials = [material if m_j == 1.0 else dataclasses.replace(material, rho=material.rho * float(m_j))
                 for m_j in density]  # fmt: skip

    def made(R_j, r_j, material_j):
        return Ring(float(R_j), float(r_j), material=material_j, angle=ring.angle, thin=ring.thin)

    try:
        hertz_stiffness(R, r, material.E, material.nu, ring.angle)
        bending_stiffness(R, r, material.E, material.nu, thin=ring.thin)
    except ValueError:
        return tuple(map(made, R, r, materials))
    nominal = {field.name: getattr(ring, field.name) for field in dataclasses.fields(Ring)}
    rings = []
    for R_j, r_j, material_j in zip(R, r, materials, strict=True):
        drawn = object.__new__(Ring)
        drawn.__dict__.update(nominal, R=float(R_j), r=float(r_j), material=material_j)
        rings.append(drawn if np.isfinite(drawn.mass) else made(R_j, r_j, material_j))
    return tuple(rings)


def draw_rings(ring, n_rings, spread, seed, *, model: str = "dual-spring", support: str = "fixed") -> RingDraw:
    """Draw the rings of one disordered chain about ``ring`` (module notes).

    Parameters
    ----------
    ring : Ring
        The nominal ring (its geometry, material, contact angle); must form a chain (R/r >= 3).
    n_rings : int
        Rings of the chain, >= 2.
    spread : mapping
        Quantity (``"R"``, ``"r"``, ``"angle"``; ``"K"``, ``"m"`` for the power-law model) to a
        relative standard deviation or a scipy.stats distribution of value/nominal (:func:`check_spread`).
    seed : int or numpy.random.SeedSequence
        Seed of the draw (:func:`check_seed`); each quantity draws from its own child stream.
    model : {"dual-spring", "power-law"}
    support : {"fixed", "free"}
        Whether the chain hangs from a support (one more contact, the top ring with a ring like itself).

    Returns
    -------
    RingDraw
        The rings, the contact angles and prefactor factors (if spread), how many values were drawn
        again, the seed.  With no spread every ring is ``ring`` itself.

    Raises
    ------
    ValueError
        If the spread makes rings impossible so often that :data:`MAX_REDRAW_ROUNDS` rounds of
        redrawing leave some impossible.

    Examples
    --------
    >>> draw = draw_rings(Ring.from_aspect_ratio(9.0), 4, {"R": 0.1}, seed=3)
    >>> [round(ring.R * 1e3, 2) for ring in draw.rings], draw.total_redrawn  # mm
    ([23.68, 22.61, 21.63, 25.88], 0)
    """
    if not isinstance(ring, Ring):
        raise TypeError(f"ring must be a ringchain.theory.Ring, got {type(ring).__name__}")
    ring.check_chain()
    n_rings = v.count("n_rings", n_rings, 2)
    model = v.choice("model", model, ("dual-spring", "power-law"))
    support = v.choice("support", support, ("fixed", "free"))
    spread = check_spread(spread, model)
    seed = check_seed(seed)
    n_contacts = n_rings - 1 + (support == "fixed")
    sizes = {"R": n_rings, "r": n_rings, "angle": n_contacts, "K": n_contacts, "m": n_rings}
    streams = {name: _stream(seed, name) for name in spread}
    factors = {name: np.ones(size) for name, size in sizes.items()}
    redrawn = dict.fromkeys(spread, 0)

    def draw(name, where=None):
        """Draw ``name`` (again, where ``where``): the positions drawn again are counted."""
        if name not in spread:
            return
        if where is None:
            factors[name] = _factors(spread[name], sizes[name], streams[name])
            return
        count = int(np.count_nonzero(where))
        if count:
            factors[name][where] = _factors(spread[name], count, streams[name])
            redrawn[name] += count

    for name in spread:
        draw(name)
    nominal_angle = ring.angle
    for _ in range(MAX_REDRAW_ROUNDS):
        with np.errstate(all="ignore"):
            angles = _folded(nominal_angle * factors["angle"])
        positive = {name: ~(np.isfinite(f) & (f > 0)) for name, f in factors.items()}
        positive["angle"] |= ~(angles > 0)
        if any(np.any(bad) for bad in positive.values()):
            for name, bad in positive.items():
                draw(name, bad)
            continue
        R, r = ring.R * factors["R"], ring.r * factors["r"]
        rings_bad = _bad_rings(R, r, support)
        if np.any(rings_bad):
            draw("R", rings_bad)
            draw("r", rings_bad)
            continue
        contacts_bad = _bad_contacts(R, r, angles, ring.material, support)
        if not np.any(contacts_bad):
            break
        if "angle" in spread:
            draw("angle", contacts_bad)
        else:  # the contact's two rings (the support's: the top ring alone)
            pair = np.zeros(n_rings, dtype=bool)
            index = np.flatnonzero(contacts_bad)
            pair[index] = True
            pair[np.minimum(index + 1, n_rings - 1)] = True
            draw("R", pair)
            draw("r", pair)
    else:
        raise ValueError(
            f"the spread ({describe_spread(spread)}) makes rings or contacts impossible so often that "
            f"{MAX_REDRAW_ROUNDS} rounds of drawing again left some impossible; give a smaller spread"
        )
    rings = (ring,) * n_rings if not spread else _drawn_rings(ring, R, r, factors["m"])
    return RingDraw(
        rings=rings,
        angles=angles if "angle" in spread else None,
        K_factor=factors["K"] if "K" in spread else None,
        redrawn=redrawn,
        seed=seed,
    )


def disordered_chain(cls, ring, n_rings, *, spread, seed, model: str = "dual-spring", m_eff_ratio: float = 1.0,
                     **options):  # fmt: skip
    """A chain of rings that differ at random about ``ring``; called as ``Chain.disordered(ring, n_rings, ...)``.

    :func:`draw_rings`, then :meth:`~ringchain.numerics.Chain.from_rings` on the drawn rings, so
    that each contact is that of its two rings (:func:`~ringchain.theory.hertz_stiffness_pair`) and
    each spacing (R1 - r1) + (R2 - r2); a spread of ``"K"`` then multiplies each contact's prefactor.
    (The body of the class method :meth:`ringchain.numerics.Chain.disordered`; ``cls`` is the class.)

    Parameters
    ----------
    ring : Ring
        The nominal ring: geometry, material, contact angle; R/r >= 3.
    n_rings : int
        Rings of the chain, >= 2.
    spread : mapping
        ``"R"``, ``"r"``, ``"angle"`` (and for the power-law model ``"K"``, ``"m"``) to a relative
        standard deviation (a number >= 0) or a frozen scipy.stats distribution of value/nominal
        (module notes).  An empty mapping, or zeros, give :meth:`~ringchain.numerics.Chain.from_ring`'s
        chain exactly.
    seed : int or numpy.random.SeedSequence
        Seed of the draw: the same seed gives the same chain.
    model : {"dual-spring", "power-law"}, optional
        As in :meth:`~ringchain.numerics.Chain.from_rings`: the dual-spring chain's contacts are
        Hertz contacts of the two rings and its bending springs each ring's own (Eqs. 1-2); the
        power-law chain fits K and n to each contact in series with the ring below (Eq. 4).
    m_eff_ratio : float, optional
        Inertial over ring mass, m_eff/m0 in (0, 1] (Table I); gravity acts on m0.
    **options
        Passed to :meth:`~ringchain.numerics.Chain.from_rings`: ``support``, ``gamma``, ``gamma_c``,
        ``gamma_b``, ``striker_mass``.

    Returns
    -------
    Chain

    Warns
    -----
    DisorderWarning
        If values were drawn again because they would have made a ring or a contact impossible
        (module notes, "Truncation"), saying how many.

    Notes
    -----
    Beyond the paper (its last sentence asks for disorder); the theory of weak disorder is
    :mod:`ringchain.theory.disorder`.

    Examples
    --------
    >>> from ringchain.numerics import Chain
    >>> ring = Ring.from_aspect_ratio(9.0)
    >>> chain = Chain.disordered(ring, 20, spread={"R": 0.1, "r": 0.05}, seed=1)
    >>> chain == Chain.disordered(ring, 20, spread={"R": 0.1, "r": 0.05}, seed=1)  # the same seed, the same chain
    True
    >>> Chain.disordered(ring, 20, spread={}, seed=1) == Chain.from_ring(ring, 20)  # no spread: the ordered chain
    True
    """
    draw = draw_rings(ring, n_rings, spread, seed, model=model, support=options.get("support", "fixed"))
    draw.warn(stacklevel=3)
    return draw.build(cls, model, m_eff_ratio, **options)
