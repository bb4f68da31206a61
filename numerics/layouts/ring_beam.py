r"""Rings that bend: each ring an elastic curved beam, and the ring as a chain sees it.

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
The chain of such rings is :class:`~ringchain.numerics.RingChain` (:mod:`.ring_chain`).

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
from ringchain.theory.curved_beam import element_matrices, element_shape_functions
from ringchain.theory.curved_beam import plane_kind as _kind

__all__ = [
    "RingModel",
    "ModeShape",
    "ReducedRing",
    "DEFAULT_ELEMENTS",
    "DEFAULT_MODES",
]

#: Elements round the ring: the frequencies of orders k <= 6 are converged to better than 1e-5
#: (tests/numerics/layouts/test_ring_beam.py); must be a multiple of 4 (nodes at the contacts and sides).
DEFAULT_ELEMENTS = 64

#: Fixed-interface modes kept per ring by default; chosen by the convergence study in
#: benchmarks/bench_ring_chain.py (sensor traces within a few per mille of the full model).
DEFAULT_MODES = 12


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
        self.elements = v.count("elements", elements, 4)
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
        from scipy.linalg import eigh

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
            count = v.count("count", count, 1)
            modes = self._elastic_modes(kind)
            if count > len(modes):
                raise ValueError(f"the model has {len(modes)} elastic modes of this kind, asked for {count}")
            return np.array([f for f, _, _ in modes[:count]])
        orders = np.atleast_1d(np.asarray(order))
        branch = v.count("branch", branch, 0)
        if branch > 2:
            raise ValueError(f"branch must be 0, 1 or 2, got {branch}")
        spectrum = self._spectrum(kind)
        out = []
        for k in orders:
            k = self._order(k, 2)
            out.append(np.sqrt(max(spectrum[k][0][branch], 0.0)) / (2.0 * np.pi))
        return np.array(out).reshape(np.shape(order))

    def _order(self, k, minimum) -> int:
        k = v.count("order", k, minimum)
        if k > self.elements // 2:
            raise ValueError(f"order {k} is above the {self.elements // 2} that {self.elements} elements resolve")
        return k

    def mode_orders(self, kind="in-plane", count=6) -> np.ndarray:
        """Circumferential orders k of the lowest ``count`` modes of :meth:`frequencies`."""
        count = v.count("count", count, 1)
        return np.array([k for _, k, _ in self._elastic_modes(_kind(kind))[:count]])

    def mode_shape(self, order, kind="in-plane", branch=0, points=8) -> ModeShape:
        """Shape of the mode of circumferential order ``order`` on ``branch`` (0: flexural).

        ``points`` per element along the ring, interpolated with the element's exact shape
        functions.  See :class:`ModeShape` for the normalisation.
        """
        kind = _kind(kind)
        k = self._order(order, 0)
        branch = v.count("branch", branch, 0)
        if branch > 2:
            raise ValueError(f"branch must be 0, 1 or 2, got {branch}")
        points = v.count("points", points, 1)
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
        from scipy.linalg import eigh

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
        modes = v.count("modes", modes, 0)
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
