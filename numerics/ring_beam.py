r"""Rings that bend: each ring an elastic curved beam, the chain of such rings, and its integration.

The paper's lattices (Eqs. (5)-(7)) treat a ring as one or two point masses and fit an
effective mass m_eff/m0 (Table I).  Here each ring is resolved:

- :class:`RingModel` -- one free ring of centroidal radius R and solid section of radius r,
  discretised into exact curved-beam elements with consistent mass
  (:mod:`ringchain.theory.curved_beam`: Winkler's thick curved beam in plane, extension,
  shear and rotary inertia; bending, torsion and shear out of plane).  It gives the
  natural frequencies and mode shapes of both families, the diametral stiffness (two
  opposite point loads, the K_b of paper Eq. (2)) and the reduced rings below.
- :class:`ReducedRing` -- a ring as the chain sees it: its two contact points (bottom and
  top, displacements along the chain axis) and a few internal coordinates.  The contact
  forces of a straight chain act along its axis at points on the ring's axis of symmetry,
  in the ring's plane, so only in-plane motion symmetric about that axis is excited; the
  ring is restricted to that subspace exactly and then reduced by Craig-Bampton: static
  constraint modes for the two contact points (which hold the rigid translation and the
  static stretch, so the diametral stiffness is kept exactly) plus the lowest
  fixed-interface modes (:meth:`RingModel.reduce`).  ``modes=None`` keeps the full finite
  element ring (on the symmetric subspace), to check the reduction against.
- :class:`RingChain`, :func:`simulate_rings` -- rings joined at their contact points by the
  unilateral Hertz law F = K_c delta_+^(3/2) (Eq. (1)), hanging under gravity from a fixed
  support through one more contact, struck at the bottom as the lattices are
  (:mod:`ringchain.numerics.solve`): a drop starts when the slack is taken up, ring 0
  undeformed and moving at sqrt(2 g h), the rest hanging at equilibrium without ring 0's
  weight.  Inertia and weight are the ring's own mass m0: nothing is fitted.
- :class:`RingSimulation` -- a :class:`~ringchain.numerics.Simulation` of the ring-resolved
  chain: contact, support and sensor forces, energy, and the signal helpers and CSV
  writer of the lattice runs.  The sensor of a ring reads the force carried across the
  middle of its body: the sum of the normal forces in the two side sections (theta = 0 and
  pi, halfway between the contacts), the continuum counterpart of the dual-spring model's
  bending-spring force.

Coordinates: the axis points up the chain, away from the impact (ARCHITECTURE.md); each
ring's coordinates are [y_bottom, y_top, q_1, ...] with y the displacements of its contact
points along the axis (m) and q the internal coordinates (m: modal coordinates scaled to a
modal mass m0; in the full model the in-plane nodal displacements and R times the rotations).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np
from ringchain.theory import Material, Ring, get_material
from ringchain.theory import _validate as v
from ringchain.theory.curved_beam import _plane as _kind
from ringchain.theory.curved_beam import element_matrices, element_shape_functions
from scipy.linalg import eigh

from .chain import _count
from .models import STANDARD_GRAVITY
from .solve import (
    DEFAULT_RTOL,
    VERLET_STEPS_PER_PERIOD,
    EnergyBudget,
    IntegrationError,
    Simulation,
    _check_t_eval,
    _impact_speeds,
    _odeint,
    _verlet,
)

__all__ = [
    "RingModel",
    "ModeShape",
    "ReducedRing",
    "RingChain",
    "RingSimulation",
    "simulate_rings",
    "DEFAULT_ELEMENTS",
    "DEFAULT_MODES",
    "RING_METHODS",
    "DEFAULT_RING_METHOD",
]

#: Elements round the ring: the frequencies of orders k <= 6 are converged to better than 1e-5
#: (tests/numerics/test_ring_beam.py); must be a multiple of 4 (nodes at the contacts and sides).
DEFAULT_ELEMENTS = 64

#: Fixed-interface modes kept per ring by default; chosen by the convergence study in
#: benchmarks/bench_ring_chain.py (sensor traces within a few per mille of the full model).
DEFAULT_MODES = 12

#: Integrators of :func:`simulate_rings`, the default first (see its notes).
RING_METHODS = ("verlet", "odeint")
DEFAULT_RING_METHOD = "verlet"


class ModeShape(NamedTuple):
    """A natural mode of the free ring.

    Attributes
    ----------
    frequency : float
        Hz.
    order : int
        Circumferential order k (waves round the ring).
    theta : ndarray
        Angles along the ring, rad (theta = pi/2 is the top contact, 3 pi/2 the bottom one).
    displacement : ndarray, shape (3, len(theta))
        The fields in the local frame: (w, u, R psi) in plane (radial, tangential, and the
        section rotation times R), (v, R phi_r, R phi_t) out of plane; dimensionless,
        scaled to a largest translation of 1, oriented symmetric about the chain axis
        (the line through both contacts) with the top moving outward.
    """

    frequency: float
    order: int
    theta: np.ndarray
    displacement: np.ndarray


class RingModel:
    """One free ring as a curved beam, discretised into exact curved elements.

    Parameters
    ----------
    R : float
        Centroidal radius, m.
    r : float
        Radius of the solid circular section, m; r < R.
    material : Material or str, optional
        A :class:`~ringchain.theory.Material` or a preset name (default "stainless").
    elements : int, optional
        Number of equal elements round the ring, a multiple of 4 (default
        :data:`DEFAULT_ELEMENTS`).

    Notes
    -----
    The elements interpolate with the exact static solutions of the curved beam
    (:func:`ringchain.theory.curved_beam.element_matrices`), so the static stiffness is
    exact for any number of elements and only the mass is discretised; frequencies
    converge as the square of the element angle (the tangential motion is interpolated as
    in a bar: 64 elements hold orders k <= 6 of the R/r = 9 ring to 3e-3, k = 2 to 2e-5).
    The assembled ring is invariant under rotation by one element, so its modes are
    Fourier modes of order k: each order's 3x3 problem is solved separately
    (:meth:`frequencies`), which is the same spectrum as the assembled matrices
    (:meth:`matrices`) with every k >= 1 mode a degenerate pair.

    Examples
    --------
    >>> ring = RingModel(22.5e-3, 2.5e-3)
    >>> ring.frequencies(order=[2, 3]).round(-1)  # Hz, in plane
    array([ 5100., 14040.])
    >>> round(ring.diametral_stiffness() / 1e6, 3)  # MN/m, = ringchain.theory.bending_stiffness
    3.316
    """

    def __init__(self, R, r, material="stainless", elements=DEFAULT_ELEMENTS):
        self.R = float(v.positive("R", R, "m"))
        self.r = float(v.positive("r", r, "m"))
        if self.r >= self.R:
            raise ValueError(f"r must be smaller than R for a ring (got R/r = {self.R / self.r:g})")
        if not isinstance(material, Material):
            material = get_material(material)
        self.material = material
        self.elements = _count("elements", elements, 4)
        if self.elements % 4:
            raise ValueError(f"elements must be a multiple of 4 (nodes at the contacts and sides), got {elements}")

    def __repr__(self) -> str:
        return f"RingModel(R={self.R!r}, r={self.r!r}, material={self.material.name!r}, elements={self.elements})"

    @classmethod
    def from_ring(cls, ring: Ring, elements=DEFAULT_ELEMENTS) -> RingModel:
        """The curved-beam model of a :class:`~ringchain.theory.Ring` (its R, r and material)."""
        if not isinstance(ring, Ring):
            raise TypeError(f"ring must be a ringchain.theory.Ring, got {type(ring).__name__}")
        return cls(ring.R, ring.r, ring.material, elements)

    # -- geometry and matrices ------------------------------------------------------------
    @property
    def element_angle(self) -> float:
        """Angle of one element, rad."""
        return 2.0 * np.pi / self.elements

    @property
    def node_angles(self) -> np.ndarray:
        """Angles of the nodes, rad: node j at j 2 pi/elements (theta = 0 is a side of the ring)."""
        return np.arange(self.elements) * self.element_angle

    @property
    def mass(self) -> float:
        """Ring mass m0 = rho 2 pi^2 R r^2, kg."""
        return self.material.rho * 2.0 * np.pi**2 * self.R * self.r**2

    def _cached(self, key, build):
        """``build()``, computed once per model and key."""
        cache = self.__dict__.setdefault("_cache", {})
        if key not in cache:
            cache[key] = build()
        return cache[key]

    def element(self, kind="in-plane"):
        """:class:`~ringchain.theory.curved_beam.ElementMatrices` of one element."""
        m = self.material
        kind = _kind(kind)
        return self._cached(
            ("element", kind),
            lambda: element_matrices(self.R, self.r, m.E, m.nu, rho=m.rho, angle=self.element_angle, kind=kind),
        )

    def matrices(self, kind="in-plane") -> tuple[np.ndarray, np.ndarray]:
        """Assembled stiffness and mass of the free ring, shape (3 n, 3 n) each.

        DOFs of node j at 3j, 3j+1, 3j+2: (w, u, psi) in plane, (v, phi_r, phi_t) out of
        plane, in the node's local frame (m and rad).
        """
        return self._cached(("matrices", _kind(kind)), lambda: self._assemble(kind))

    def _assemble(self, kind):
        el = self.element(kind)
        n = self.elements
        K = np.zeros((3 * n, 3 * n))
        M = np.zeros((3 * n, 3 * n))
        for j in range(n):
            dofs = np.r_[3 * j : 3 * j + 3, 3 * ((j + 1) % n) : 3 * ((j + 1) % n) + 3]
            K[np.ix_(dofs, dofs)] += el.stiffness
            M[np.ix_(dofs, dofs)] += el.mass
        return K, M

    # -- free vibration -------------------------------------------------------------------------
    def _spectrum(self, kind):
        """Order k = 0..n/2 -> (omega^2 (3,), eigenvectors (3, 3) complex) of the assembled ring."""
        return self._cached(("spectrum", kind), lambda: self._fourier_spectrum(kind))

    def _fourier_spectrum(self, kind):
        el = self.element(kind)
        K, M = el.stiffness, el.mass
        beta = self.element_angle
        spectrum = {}
        for k in range(self.elements // 2 + 1):
            phase = np.exp(1j * k * beta)

            def fourier(X, phase=phase):
                return X[:3, :3] + X[3:, 3:] + X[:3, 3:] * phase + X[3:, :3] / phase

            Kk, Mk = fourier(K), fourier(M)
            spectrum[k] = eigh(0.5 * (Kk + Kk.conj().T), 0.5 * (Mk + Mk.conj().T))
        return spectrum

    def _elastic_modes(self, kind):
        """Sorted (frequency Hz, order, branch) of the elastic modes, each degenerate pair once."""
        return self._cached(("modes", kind), lambda: self._sorted_modes(kind))

    def _sorted_modes(self, kind):
        modes = []
        for k, (omega2, _) in self._spectrum(kind).items():
            for branch, value in enumerate(omega2):
                if k <= 1 and branch == 0:  # k = 0: rotation (in plane) / translation (out); k = 1: the pairs
                    continue
                modes.append((np.sqrt(max(value, 0.0)) / (2.0 * np.pi), k, branch))
        return sorted(modes)

    def frequencies(self, kind="in-plane", count=6, order=None, branch=0) -> np.ndarray:
        """Natural frequencies of the free ring, Hz, rigid-body modes excluded.

        Parameters
        ----------
        kind : {"in-plane", "out-of-plane"}
        count : int, optional
            Number of frequencies, lowest first; each degenerate pair of the circular ring
            (the same mode turned by a quarter wave) is counted once.
        order : int or array_like of int, optional
            Instead of the lowest ``count``: the frequency of circumferential order k (waves
            round the ring), k >= 2, on branch ``branch`` (0: flexural, the lowest; 1 and 2:
            the extensional and shear branches in plane, torsional and shear out of plane).
        branch : int, optional

        Returns
        -------
        ndarray
            Hz.
        """
        kind = _kind(kind)
        if order is None:
            count = _count("count", count, 1)
            modes = self._elastic_modes(kind)
            if count > len(modes):
                raise ValueError(f"the model has {len(modes)} elastic modes of this kind, asked for {count}")
            return np.array([f for f, _, _ in modes[:count]])
        orders = np.atleast_1d(np.asarray(order))
        branch = _count("branch", branch, 0)
        if branch > 2:
            raise ValueError(f"branch must be 0, 1 or 2, got {branch}")
        spectrum = self._spectrum(kind)
        out = []
        for k in orders:
            k = self._order(k, 2)
            out.append(np.sqrt(max(spectrum[k][0][branch], 0.0)) / (2.0 * np.pi))
        return np.array(out).reshape(np.shape(order))

    def _order(self, k, minimum) -> int:
        k = _count("order", k, minimum)
        if k > self.elements // 2:
            raise ValueError(f"order {k} is above the {self.elements // 2} that {self.elements} elements resolve")
        return k

    def mode_orders(self, kind="in-plane", count=6) -> np.ndarray:
        """Circumferential orders k of the lowest ``count`` modes of :meth:`frequencies`."""
        count = _count("count", count, 1)
        return np.array([k for _, k, _ in self._elastic_modes(_kind(kind))[:count]])

    def mode_shape(self, order, kind="in-plane", branch=0, points=8) -> ModeShape:
        """Shape of the mode of circumferential order ``order`` on ``branch`` (0: flexural).

        ``points`` per element along the ring, interpolated with the element's exact shape
        functions.  See :class:`ModeShape` for the normalisation.
        """
        kind = _kind(kind)
        k = self._order(order, 0)
        branch = _count("branch", branch, 0)
        if branch > 2:
            raise ValueError(f"branch must be 0, 1 or 2, got {branch}")
        points = _count("points", points, 1)
        omega2, vectors = self._spectrum(kind)[k]
        vec = vectors[:, branch]
        # Phase: the first field (w or v) real and positive, so that it goes as cos k(theta - pi/2).
        vec = vec * np.exp(-1j * np.angle(vec[0])) if abs(vec[0]) > 1e-12 * np.abs(vec).max() else vec
        theta_nodes = self.node_angles
        nodal = np.real(vec[:, None] * np.exp(1j * k * (theta_nodes[None, :] - np.pi / 2)))  # (3, n)
        m = self.material
        local = np.linspace(0.0, self.element_angle, points, endpoint=False)
        N = element_shape_functions(self.R, self.r, m.E, m.nu, self.element_angle, local, kind)  # (P, 3, 6)
        n = self.elements
        q = np.concatenate([nodal, np.roll(nodal, -1, axis=1)], axis=0)  # (6, n): element e's two nodes
        fields = np.einsum("pia,ae->iep", N, q).reshape(3, n * points)
        theta = (theta_nodes[:, None] + local[None, :]).ravel()
        rotation = [2] if kind == "in-plane" else [1, 2]
        fields[rotation] *= self.R
        translation = [0, 1] if kind == "in-plane" else [0]
        fields /= np.abs(fields[translation]).max()
        return ModeShape(float(np.sqrt(max(omega2[branch], 0.0)) / (2.0 * np.pi)), k, theta, fields)

    # -- the ring as the chain loads it ---------------------------------------------------------
    @functools.cached_property
    def _symmetric(self):
        """(P, K_s, M_s, sensor_s): the in-plane ring restricted to motion symmetric about the chain axis.

        Coordinates: [y_bottom, y_top, then for each node with -pi/2 < theta < pi/2: w, u, R psi];
        P maps them to the assembled DOFs (the mirror node pi - theta has w equal, u and psi
        opposite).  sensor_s is the normal force summed over the two side sections (theta = 0, pi).
        """
        n = self.elements
        K, M = self.matrices("in-plane")
        top, bottom = n // 4, 3 * n // 4
        columns = []
        column = np.zeros(3 * n)
        column[3 * bottom] = -1.0  # the bottom contact moves down when the ring moves outward there
        columns.append(column)
        column = np.zeros(3 * n)
        column[3 * top] = 1.0
        columns.append(column)
        for j in [*range(bottom + 1, n), *range(0, top)]:
            mirror = (n // 2 - j) % n
            for dof, sign, scale in ((0, 1.0, 1.0), (1, -1.0, 1.0), (2, -1.0, 1.0 / self.R)):
                column = np.zeros(3 * n)
                column[3 * j + dof] = scale
                column[3 * mirror + dof] = sign * scale
                columns.append(column)
        P = np.array(columns).T
        # Normal force at the side node theta = 0, from both elements that meet there, times 2 sides.
        res = self.element("in-plane").resultants
        row = np.zeros(3 * n)
        row[np.r_[3 * (n - 1) : 3 * n, 0:3]] += 0.5 * res[1, 0]  # element n-1 ends at node 0
        row[0:6] += 0.5 * res[0, 0]  # element 0 starts at node 0
        return P, P.T @ K @ P, P.T @ M @ P, 2.0 * row @ P

    def diametral_stiffness(self) -> float:
        """Stiffness of the ring pulled by two opposite point loads at its contacts, N/m.

        The force over the increase of the distance between the two load points; the
        finite-element counterpart of K_b (paper Eq. (2), :func:`ringchain.theory.bending_stiffness`),
        equal to its curved-beam (``thin=False``) value for any number of elements.
        """
        return _condensed_stiffness(*self._symmetric[1:2])

    def reduce(self, modes=DEFAULT_MODES) -> ReducedRing:
        """The ring as the chain sees it, reduced by Craig-Bampton (see the module notes).

        Parameters
        ----------
        modes : int or None, optional
            Fixed-interface modes kept (contact points held along the axis); 0 keeps only the
            static shapes (Guyan: the rigid translation and the static stretch), None keeps the
            full finite-element ring on its symmetric subspace.

        Returns
        -------
        ReducedRing
        """
        _, K, M, sensor = self._symmetric
        n_s = K.shape[0]
        rigid = np.zeros(n_s)
        rigid[:2] = 1.0
        theta = self.node_angles[[*range(3 * self.elements // 4 + 1, self.elements), *range(0, self.elements // 4)]]
        rigid[2::3], rigid[3::3] = np.sin(theta), np.cos(theta)  # y-translation: w = sin, u = cos
        if modes is None:
            fixed = eigh(K[2:, 2:], M[2:, 2:], eigvals_only=True)
            return ReducedRing(mass=M, stiffness=K, sensor=sensor, rigid=rigid,
                               mode_frequencies=np.sqrt(fixed) / (2.0 * np.pi), description="full")  # fmt: skip
        modes = _count("modes", modes, 0)
        if modes > n_s - 2:
            raise ValueError(f"the ring has {n_s - 2} internal coordinates, asked for {modes} modes")
        K_ii, K_ib, M_ii = K[2:, 2:], K[2:, :2], M[2:, 2:]
        constraint = -np.linalg.solve(K_ii, K_ib)  # interior response to unit contact displacements
        if modes:
            omega2, phi = eigh(K_ii, M_ii, subset_by_index=[0, modes - 1])
        else:
            omega2, phi = np.zeros(0), np.zeros((n_s - 2, 0))
        phi = phi * np.sqrt(self.mass)  # modal mass m0: modal coordinates in metres
        T = np.zeros((n_s, 2 + modes))
        T[:2, :2] = np.eye(2)
        T[2:, :2] = constraint
        T[2:, 2:] = phi
        k_b = _condensed_stiffness(K)
        stiffness = np.zeros((2 + modes, 2 + modes))
        stiffness[:2, :2] = k_b * np.array([[1.0, -1.0], [-1.0, 1.0]])  # exactly singular on the rigid translation
        stiffness[2:, 2:] = np.diag(omega2 * self.mass)
        mass = T.T @ M @ T
        reduced_rigid = np.zeros(2 + modes)
        reduced_rigid[:2] = 1.0
        return ReducedRing(mass=0.5 * (mass + mass.T), stiffness=stiffness, sensor=sensor @ T, rigid=reduced_rigid,
                           mode_frequencies=np.sqrt(omega2) / (2.0 * np.pi),
                           description=f"Craig-Bampton, {modes} modes")  # fmt: skip


def _condensed_stiffness(K) -> float:
    """Stiffness between the two contact coordinates (0, 1) with the rest condensed out, N/m."""
    K_bb = K[:2, :2] - K[:2, 2:] @ np.linalg.solve(K[2:, 2:], K[2:, :2])
    return float(0.5 * (K_bb[1, 1] - K_bb[0, 1]))


@dataclass(frozen=True, eq=False)
class ReducedRing:
    """A ring as the chain sees it: coordinates [y_bottom, y_top, internal...] with mass and stiffness.

    Build it with :meth:`RingModel.reduce` or :meth:`two_masses`.

    Attributes
    ----------
    mass, stiffness : ndarray, shape (n, n)
        kg and N/m; the kinetic and strain energies are u^T M u/2 and x^T K x/2.
    sensor : ndarray, shape (n,)
        The sensor force (the force across the middle of the ring body) is ``sensor @ x``, N.
    rigid : ndarray, shape (n,)
        The coordinates of a rigid translation by 1 m along the chain axis (K rigid = 0).
    mode_frequencies : ndarray
        Frequencies of the kept internal modes with the contact points held, Hz.
    description : str
    """

    mass: np.ndarray
    stiffness: np.ndarray
    sensor: np.ndarray
    rigid: np.ndarray
    mode_frequencies: np.ndarray = field(default_factory=lambda: np.zeros(0))
    description: str = ""

    def __post_init__(self):
        n = np.shape(self.rigid)[0]
        for name in ("mass", "stiffness"):
            if np.shape(getattr(self, name)) != (n, n):
                raise ValueError(f"{name} must be {n} x {n}, got shape {np.shape(getattr(self, name))}")
        if n < 2:
            raise ValueError("a reduced ring has at least its two contact coordinates")

    @classmethod
    def two_masses(cls, m, K_b) -> ReducedRing:
        """The ring of the dual-spring model (paper Eqs. (5)-(6)): two lumped halves m/2 joined by K_b.

        Its sensor reads the spring force K_b (y_top - y_bottom), as the dual-spring chain's does.
        """
        m = float(v.positive("m", m, "kg"))
        K_b = float(v.positive("K_b", K_b, "N/m"))
        return cls(mass=np.diag([m / 2, m / 2]), stiffness=K_b * np.array([[1.0, -1.0], [-1.0, 1.0]]),
                   sensor=np.array([-K_b, K_b]), rigid=np.ones(2), description="two masses")  # fmt: skip

    @property
    def n_dof(self) -> int:
        return self.rigid.size

    @property
    def m(self) -> float:
        """Total mass (the rigid translation's), kg."""
        return float(self.rigid @ self.mass @ self.rigid)

    @property
    def K_b(self) -> float:
        """Diametral stiffness between the two contact points, N/m."""
        return _condensed_stiffness(self.stiffness)

    @functools.cached_property
    def inverse_mass(self) -> np.ndarray:
        return np.linalg.inv(self.mass)


@dataclass(frozen=True, eq=False)
class RingChain:
    """A chain of ``n_rings`` identical resolved rings joined by Hertz contacts, ring 0 at the impact end.

    Attributes
    ----------
    n_rings : int
    ring : ReducedRing
    K_c : float
        Contact stiffness, N/m^n (Eq. (1)).
    a : float
        Distance between the centres of adjacent rings, m (2(R - r); only the wave speed uses it).
    n : float
        Contact exponent (3/2, Hertz).
    support : {"fixed", "free"}
        The top ring hangs from a fixed support through one more contact, or its top is free.
    """

    n_rings: int
    ring: ReducedRing
    K_c: float
    a: float
    n: float = 1.5
    support: str = "fixed"

    def __post_init__(self):
        set_ = functools.partial(object.__setattr__, self)
        set_("n_rings", _count("n_rings", self.n_rings, 2))
        if not isinstance(self.ring, ReducedRing):
            raise TypeError(f"ring must be a ReducedRing, got {type(self.ring).__name__}")
        set_("K_c", float(v.positive("K_c", self.K_c, "N/m^n")))
        set_("a", float(v.positive("a", self.a, "m")))
        set_("n", float(v.in_range("n", self.n, 1.0, np.inf, closed_low=True, closed_high=False)))
        if self.support not in ("fixed", "free"):
            raise ValueError(f"support must be 'fixed' or 'free', got {self.support!r}")

    @classmethod
    def from_ring(cls, ring: Ring, n_rings: int, *, modes=DEFAULT_MODES, elements=DEFAULT_ELEMENTS,
                  support="fixed") -> RingChain:  # fmt: skip
        """A chain of identical :class:`~ringchain.theory.Ring` s, each resolved as a curved beam.

        The contact stiffness is the ring's K_c (Eq. (1), elliptical at oblique angles); the
        ring body is :meth:`RingModel.reduce` with ``modes`` (None: the full model).

        Examples
        --------
        >>> chain = RingChain.from_ring(Ring.from_aspect_ratio(9.0), 20, modes=4)
        >>> chain.ring.n_dof, round(chain.ring.m * 1e3, 2)  # coordinates per ring, mass in g
        (6, 22.21)
        """
        if not isinstance(ring, Ring):
            raise TypeError(f"ring must be a ringchain.theory.Ring, got {type(ring).__name__}")
        ring.check_chain()
        body = RingModel.from_ring(ring, elements).reduce(modes)
        return cls(n_rings, body, ring.K_c, ring.spacing, support=support)

    @property
    def m(self) -> float:
        """Mass of a ring, kg."""
        return self.ring.m

    @property
    def n_dof(self) -> int:
        return self.n_rings * self.ring.n_dof

    def contact_extension(self, x) -> np.ndarray:
        """Extensions of the contacts (and of the support contact last, if fixed), m; x shape (..., n_rings, n)."""
        e = x[..., 1:, 0] - x[..., :-1, 1]
        if self.support == "fixed":
            e = np.concatenate([e, -x[..., -1:, 1]], axis=-1)
        return e

    def contact_forces(self, e) -> np.ndarray:
        """Hertz forces of extensions ``e``, N: K_c e_+^n."""
        return self.K_c * np.maximum(e, 0.0) ** self.n

    def linear_dispersion(self, wavenumber, tension) -> np.ndarray:
        """Frequencies of the infinite chain of these rings linearised about a uniform tension, Hz.

        Parameters
        ----------
        wavenumber : array_like
            Phase advance per ring q, rad, in [0, pi].
        tension : float
            Static tension of every contact, N; the contacts act as springs of stiffness
            dF/ddelta = n K_c^(1/n) T^((n-1)/n).

        Returns
        -------
        ndarray, shape (len(q), n_dof)
            The branches, lowest (acoustic) first.  At long waves the acoustic branch is
            omega = q sqrt(k_s/m) with 1/k_s = 1/k_contact + 1/K_b, whatever the ring's inner
            structure: the series law of paper Eq. (3) with the whole ring mass.
        """
        q = np.atleast_1d(v.as_float("wavenumber", wavenumber))
        tension = float(v.positive("tension", tension, "N"))
        k = self.n * self.K_c ** (1.0 / self.n) * tension ** ((self.n - 1.0) / self.n)
        ring = self.ring
        out = np.empty((q.size, ring.n_dof))
        for i, phase in enumerate(np.exp(1j * q)):
            D = ring.stiffness.astype(complex)
            D[0, 0] += k
            D[1, 1] += k
            D[1, 0] -= k * phase  # contact with the ring above: its bottom against this top
            D[0, 1] -= k * np.conj(phase)
            omega2 = eigh(D, ring.mass, eigvals_only=True)
            out[i] = np.sqrt(np.maximum(omega2, 0.0)) / (2.0 * np.pi)
        return out

    def static_state(self, g=STANDARD_GRAVITY, *, first_ring_hanging=True) -> np.ndarray:
        """Coordinates of the chain hanging at rest from its support, shape (n_rings, n).

        Contact i (between rings i and i+1) carries the weight of rings 0..i (1..i if ring 0 is
        held up: then ring 0 is undeformed, its top just touching ring 1).  Each ring is solved
        with its bottom point fixed, then the rings are stacked from the support down so that
        each contact has its Hertz extension (T/K_c)^(1/n).
        """
        if self.support != "fixed":
            raise ValueError("a chain with a free far end has no static equilibrium under gravity")
        ring, N = self.ring, self.n_rings
        weight = g * ring.m
        weights = np.full(N, weight)
        if not first_ring_hanging:
            weights[0] = 0.0
        tension = np.cumsum(weights)  # contact i carries rings 0..i; tension[N-1] is the support
        gravity = -g * ring.mass @ ring.rigid
        x = np.zeros((N, ring.n_dof))
        for i in range(N):
            if i == 0 and not first_ring_hanging:
                continue  # undeformed
            load = gravity.copy()
            load[1] += tension[i]
            load[0] -= tension[i - 1] if i > 0 else 0.0
            x[i, 1:] = np.linalg.solve(ring.stiffness[1:, 1:], load[1:])  # bottom point held at 0
        stretch = (tension / self.K_c) ** (1.0 / self.n)
        top = 0.0 - stretch[N - 1]
        for i in range(N - 1, -1, -1):
            x[i] += (top - x[i, 1]) * ring.rigid
            if i:
                top = x[i, 0] - stretch[i - 1]  # contact 0 is just taut when ring 0 is held (no tension)
        return x

    def initial_state(self, *, impact_velocity=None, drop_height=None, gravity=True, g=STANDARD_GRAVITY):
        """Coordinates and velocities at t = 0, shape (n_rings, n) each (see :func:`simulate_rings`)."""
        g = float(v.positive("g", g, "m/s^2"))
        speeds, dropped = _impact_speeds(impact_velocity, drop_height, g)
        if speeds.size != 1:
            raise ValueError("simulate_rings takes one impact")
        if gravity:
            x = self.static_state(g, first_ring_hanging=not dropped)
        else:
            x = np.zeros((self.n_rings, self.ring.n_dof))
        u = np.zeros_like(x)
        u[0] = -float(speeds[0]) * self.ring.rigid
        return x, u

    def stepper(self, batch_shape, g):
        """A function ``(x, u, out)`` writing the accelerations of flat coordinates x into ``out``.

        The interface :func:`ringchain.numerics.solve` integrators call (``u`` is not read:
        the chain is undamped).
        """
        if tuple(batch_shape) not in ((), (1,)):
            raise ValueError("the ring-resolved chain integrates one run at a time")
        if tuple(batch_shape) == (1,):  # one run with a batch axis, as the Verlet integrator passes it
            single = self.stepper((), g)
            return lambda x, u, out: single(x[0], None, out[0])
        ring, N, n = self.ring, self.n_rings, self.ring.n_dof
        coupling = -(ring.inverse_mass @ ring.stiffness).T  # a = x @ coupling + f @ M^-T - g rigid
        inv_bottom, inv_top = ring.inverse_mass[:, 0], ring.inverse_mass[:, 1]
        gravity = g * ring.rigid
        K_c, power, fixed = self.K_c, self.n, self.support == "fixed"
        F = np.empty(N if fixed else N - 1)

        def accelerations_into(x, u, out):
            X = x.reshape(N, n)
            A = out.reshape(N, n)
            np.subtract(X[1:, 0], X[:-1, 1], out=F[: N - 1])
            if fixed:
                F[N - 1] = -X[N - 1, 1]
            np.maximum(F, 0.0, out=F)
            np.power(F, power, out=F)
            np.multiply(F, K_c, out=F)
            np.matmul(X, coupling, out=A)
            A += np.outer(F[:N] if fixed else np.append(F, 0.0), inv_top)  # pulled up at the top
            A[1:] -= np.outer(F[: N - 1], inv_bottom)  # pulled down at the bottom
            A -= gravity

        return accelerations_into

    def first_order_rhs(self, g):
        """f(t, y) for y = [x_0, u_0, x_1, u_1, ...] (ring by ring), and its Jacobian bandwidth."""
        N, n = self.n_rings, self.ring.n_dof
        accelerations_into = self.stepper((), g)
        x = np.empty(N * n)
        a = np.empty(N * n)

        def rhs(t, y):
            Y = y.reshape(N, 2, n)
            dy = np.empty_like(Y)
            dy[:, 0] = Y[:, 1]
            x.reshape(N, n)[...] = Y[:, 0]
            accelerations_into(x, None, a)
            dy[:, 1] = a.reshape(N, n)
            return dy.ravel()

        return rhs, (4 * n - 2, n)


def simulate_rings(chain: RingChain, t_end, *, impact_velocity=None, drop_height=None, gravity=True, t_eval=None,
                   n_samples=2001, method=DEFAULT_RING_METHOD, rtol=DEFAULT_RTOL, atol=None, dt=None,
                   steps_per_period=VERLET_STEPS_PER_PERIOD, g=STANDARD_GRAVITY) -> RingSimulation:  # fmt: skip
    """Integrate the ring-resolved chain after an impact on ring 0: the sibling of :func:`~ringchain.numerics.simulate`.

    Parameters
    ----------
    chain : RingChain
    t_end : float
        Duration, s; t = 0 is the impact (for a drop: the instant the slack is taken up).
    impact_velocity : float, optional
        Speed of ring 0 moving away from the chain at t = 0, m/s (from the equilibrium of
        the whole chain under gravity).
    drop_height : float, optional
        Free-fall height of ring 0, m: ring 0 undeformed at sqrt(2 g h), its contact with
        ring 1 just taut, the rest hanging at equilibrium without its weight.
    gravity : bool, optional
        Hang the chain under gravity (default), or start unstretched without gravity.
    t_eval : array_like, optional
        Sample times in [0, t_end], s; default ``n_samples`` evenly spaced.
    n_samples : int, optional
    method : {"verlet", "odeint"}, optional
        Velocity Verlet with step ``dt`` (the default, :data:`DEFAULT_RING_METHOD`), or LSODA
        through :func:`scipy.integrate.odeint` (tolerances ``rtol``, and ``atol`` relative to
        the run's displacement and velocity scales).  The default step is 1/``steps_per_period``
        of the period of the fastest mode of a ring with both contacts stiffened to twice their
        stiffness at four times the estimated peak force, an upper bound on the chain's fastest
        mode.  The chain is undamped and its rings' fast modes make LSODA turn stiff (ten times
        slower with 8 or more modes); symplectic Verlet keeps the energy to ~1e-5 of the impact's
        at the default step and is second order (tests/numerics/test_ring_beam.py).
    rtol, atol, dt, steps_per_period, g
        As in :func:`~ringchain.numerics.simulate`.

    Returns
    -------
    RingSimulation

    Examples
    --------
    >>> chain = RingChain.from_ring(Ring.from_aspect_ratio(9.0), 4, modes=2)
    >>> sim = simulate_rings(chain, 2e-4, drop_height=0.01, n_samples=201)
    >>> sim.contact_force.shape, bool(sim.contact_force.min() >= 0.0)
    ((201, 3), True)
    """
    if not isinstance(chain, RingChain):
        raise TypeError(f"chain must be a RingChain, got {type(chain).__name__}")
    if np.ndim(impact_velocity) or np.ndim(drop_height):
        raise ValueError("simulate_rings takes one impact")
    t_end = float(v.positive("t_end", t_end, "s"))
    t_eval = _check_t_eval(t_eval, t_end, n_samples)
    g = float(v.positive("g", g, "m/s^2"))
    if gravity and chain.support != "fixed":
        raise ValueError("gravity needs the chain to hang from a fixed support (support='fixed')")
    x0, u0 = chain.initial_state(impact_velocity=impact_velocity, drop_height=drop_height, gravity=gravity, g=g)
    speed = -float(u0[0, 0])
    g_dyn = g if gravity else 0.0
    X, V = _scales(chain, x0, speed, g)
    N, n = x0.shape
    if method == "verlet":
        if dt is None:
            dt = _verlet_step(chain, X, float(v.positive("steps_per_period", steps_per_period)))
        dt = float(v.positive("dt", dt, "s"))
        xs, us, stats = _verlet(chain, x0.reshape(1, -1), u0.reshape(1, -1), t_eval, t_end, dt, g_dyn, None,
                                _finite_watch)  # fmt: skip
        xs, us = xs[0], us[0]
    elif method == "odeint":
        rtol = float(v.positive("rtol", rtol))
        atol_rel = rtol if atol is None else float(v.positive("atol", atol))
        rhs, bandwidth = chain.first_order_rhs(g_dyn)
        y0 = np.stack([x0, u0], axis=1).ravel()
        atol = atol_rel * np.broadcast_to(np.array([X, V])[None, :, None], (N, 2, n)).ravel()
        y, nfev = _odeint(rhs, y0, 0.0, t_eval, rtol, atol, bandwidth)
        states = y.reshape(N, 2, n, -1)
        xs = states[:, 0].transpose(2, 0, 1).reshape(-1, N * n)
        us = states[:, 1].transpose(2, 0, 1).reshape(-1, N * n)
        stats = {"method": method, "rtol": rtol, "nfev": nfev}
    else:
        raise ValueError(f"method must be one of {RING_METHODS}, got {method!r}")
    return RingSimulation(
        chain=chain, t=t_eval, x=np.ascontiguousarray(xs), u=np.ascontiguousarray(us),
        dissipated=np.zeros(t_eval.size), g=g_dyn, impact_velocity=speed,
        drop_height=None if drop_height is None else float(drop_height), stats=stats,
    )  # fmt: skip


def _finite_watch(t, x, u, dissipated=0.0):
    """Stop a run whose state turns non-finite (the Verlet step above its stability limit)."""
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(u))):
        raise IntegrationError(f"the state became non-finite by t = {t:g} s: the integration is unstable; "
                               "take a smaller dt or more steps_per_period")  # fmt: skip


def _scales(chain: RingChain, x0, speed, g):
    """Displacement (m) and velocity (m/s) scales of a run (as :func:`ringchain.numerics.solve._scales`).

    The velocity scale is the impact speed (floored at 1e-3 sqrt(g a)); the displacement
    scale the extension at which the energy m V^2/4 of a two-ring collision is stored in a
    contact and a ring body in series, or the largest static extension if larger.
    """
    speed = max(speed, 1e-3 * np.sqrt(g * chain.a), 1e-9)
    energy = 0.25 * chain.m * speed**2
    X = ((chain.n + 1.0) * energy / chain.K_c) ** (1.0 / (chain.n + 1.0)) + np.sqrt(2.0 * energy / chain.ring.K_b)
    static = np.abs(chain.contact_extension(x0)).max(initial=0.0)
    return max(X, static), speed


def _verlet_step(chain: RingChain, X, steps_per_period) -> float:
    """A fraction 1/steps_per_period of the period of the fastest mode of a ring held at both contacts
    by twice the contact stiffness at four times the estimated peak force (a bound for the chain)."""
    force = 4.0 * chain.K_c * X**chain.n
    k_contact = chain.n * chain.K_c ** (1.0 / chain.n) * force ** ((chain.n - 1.0) / chain.n)
    ring = chain.ring
    K = ring.stiffness.copy()
    K[0, 0] += 2.0 * k_contact
    K[1, 1] += 2.0 * k_contact
    omega_max = np.sqrt(eigh(K, ring.mass, eigvals_only=True)[-1])
    return 2.0 * np.pi / omega_max / steps_per_period


@dataclass(frozen=True, eq=False)
class RingSimulation(Simulation):
    """One run of the ring-resolved chain: times ``t`` (s), coordinates ``x`` and velocities ``u``, shape (T, n_dof).

    The same public interface as :class:`~ringchain.numerics.Simulation`: ``contact_force``
    (T, n_rings - 1), ``support_force``, ``sensor_force`` (T, n_rings), ``sensor(i)``,
    ``peak_force``, ``arrival_time``, ``time_of_flight``, ``wave_speed``, ``pulse_width``,
    ``energy`` and ``to_csv``.  There is no bending spring (``bending_force`` is None): the
    sensor reads the normal force across the middle of each ring body.
    """

    @property
    def coordinates(self) -> np.ndarray:
        """Coordinates per ring, m, shape (T, n_rings, n)."""
        return self.x.reshape(self.t.size, self.chain.n_rings, -1)

    @functools.cached_property
    def bond_force(self) -> np.ndarray:
        """Force of every contact, then of the support contact if fixed, N; shape (T, n_rings - 1 (+1))."""
        return self.chain.contact_forces(self.chain.contact_extension(self.coordinates))

    @property
    def contact_force(self) -> np.ndarray:
        return self.bond_force[:, : self.chain.n_rings - 1]

    @property
    def support_force(self) -> np.ndarray | None:
        return self.bond_force[:, -1] if self.chain.support == "fixed" else None

    @property
    def bending_force(self) -> None:
        return None

    @functools.cached_property
    def sensor_force(self) -> np.ndarray:
        """Normal force across the middle of each ring (both side sections), N; shape (T, n_rings)."""
        return self.coordinates @ self.chain.ring.sensor

    def _sensor(self, rings) -> np.ndarray:
        """Sensor forces of ``rings`` (1-d array), N, shape (T, len(rings)) (what :meth:`sensor` reads)."""
        return self.sensor_force[..., rings]

    @property
    def ring_displacement(self) -> np.ndarray:
        """Displacement of each ring's centre of mass, m; shape (T, n_rings)."""
        ring = self.chain.ring
        return self.coordinates @ (ring.mass @ ring.rigid) / ring.m

    @property
    def ring_velocity(self) -> np.ndarray:
        """Velocity of each ring's centre of mass, m/s; shape (T, n_rings)."""
        ring = self.chain.ring
        return self.u.reshape(self.t.size, self.chain.n_rings, -1) @ (ring.mass @ ring.rigid) / ring.m

    def energy(self) -> EnergyBudget:
        """Kinetic, contact, ring strain ("bending") and gravity energy, J; gravity from t = 0."""
        ring, chain = self.chain.ring, self.chain
        X = self.coordinates
        U = self.u.reshape(X.shape)
        e = np.maximum(chain.contact_extension(X), 0.0)
        return EnergyBudget(
            kinetic=0.5 * np.einsum("tia,ab,tib->t", U, ring.mass, U),
            contact=chain.K_c * np.sum(e ** (chain.n + 1.0), axis=-1) / (chain.n + 1.0),
            bending=0.5 * np.einsum("tia,ab,tib->t", X, ring.stiffness, X),
            gravity=self.g * ring.m * np.sum(self.ring_displacement - self.ring_displacement[:1], axis=-1),
            dissipated=self.dissipated,
        )
