r"""Rigid rings in space: :class:`Rings`, solid tori in three dimensions, a model of the engine.

Every other lattice of the package puts a ring at a point.  Here each ring is a rigid torus (major radius R,
tube radius r, its material) with a position, an orientation, a velocity and an angular velocity; rings
touch where their tubes overlap, anywhere on them, and push each other apart along the normal of the
contact; a friction force acts against the slip.  The model implements the engine's model and dynamics
contracts (:mod:`ringchain.numerics.engine.integrate`), so :func:`~ringchain.numerics.simulate` integrates it with
the compiled Dormand-Prince pair (max-norm error control) or with velocity Verlet (a splitting with the exact
free rotor, for long undamped runs), and SciPy's methods as the reference.

State and conventions (what users rely on):

- centres (n, 3), m; orientations (n, 4), unit quaternions (w, x, y, z) taking the ring's body frame to
  space, the ring's axis (normal to its plane) being body z; velocities (n, 3) in space, m/s; angular
  velocities (n, 3) in the body frame, rad/s;
- mass m0 of each ring (:attr:`~ringchain.theory.Ring.mass`) and its principal moments about a diameter and
  about the axis, (I_1, I_3) = (m (R^2/2 + 5 r^2/8), m (R^2 + 3 r^2/4)) (the solid torus,
  :func:`~ringchain.theory.torus_moments`);
- fixed rings (anchors) do not move; gravity acts along -z.

Equations (Euler's, in the body frame): dx/dt = v; dq/dt = q (x) (0, omega)/2; m dv/dt = F + m g;
I domega/dt = tau_body - omega x (I omega).  The compiled kernels (:mod:`ringchain.numerics.engine.rings_step`)
keep |q| = 1 to round-off: dopri5 renormalises each accepted step (the rotation matrix is that of q/|q| in
between), Verlet composes unit quaternions.  The state the engine integrates stores each centre as its
displacement from the reference centre, so that the step control measures the approach of contacts
(micrometres) against tolerances of the same size.

Contacts.  Candidate pairs are the pairs whose bounding spheres (radius R + r) come within ``skin`` of each
other in the rest configuration (:func:`~ringchain.numerics.candidate_pairs`), fixed for a run; the linked
pairs (:attr:`Rings.links`) are those whose centre circles have Gauss linking number +-1
(:func:`~ringchain.numerics.linking_number`).  The contacts of each pair are every local minimum of the
distance of their centre circles (:mod:`ringchain.numerics.engine.rings_kernels`), warm-started from the last
evaluation.  The contact law is Hertz's, F = K_c delta^(3/2), with K_c from the principal curvatures of
both tubes at each contact and the angle between their principal directions (App. A, the general form behind
Eq. (1): :func:`~ringchain.theory.hertz_stiffness_curvatures`; at the crossing of interlocked rings it is
:func:`~ringchain.theory.hertz_stiffness` at their angle), or the lumped power law F = K delta^n of Eq. (4)
(:meth:`~ringchain.theory.Ring.power_law`); optional dashpots (gamma, N s/m) and regularised Coulomb
friction (coefficient mu, slip speed ``slip_speed``).  ``link_force`` is the normal force a linked pair
carries (tension positive: the pair is pulled apart).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from ringchain.theory import STANDARD_GRAVITY, Ring, torus_moments
from ringchain.theory import _validate as v

from ..contact.tori import candidate_pairs, linking_number
from ..engine._kernel_calls import kernel_array

__all__ = ["Rings", "RingsSimulation", "RingsBatch", "RingsEnergy", "LAWS"]

#: The contact laws of :meth:`Rings.from_rings`.
LAWS = ("hertz", "power-law")

#: Default slip speed of the regularised Coulomb friction, m/s: below it the friction force grows linearly.
SLIP_SPEED = 1e-4


def rotation_matrices(q) -> np.ndarray:
    """Rotation matrices (..., 3, 3) of quaternions (..., 4) (w, x, y, z), normalised here."""
    q = np.asarray(q, dtype=float)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = np.moveaxis(q, -1, 0)
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], axis=-1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], axis=-1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], axis=-1),
    ], axis=-2)  # fmt: skip


@dataclass(frozen=True, eq=False)
class Rings:
    """Rigid tori in three dimensions: a network of rings (build it with :meth:`from_rings`).

    Attributes
    ----------
    centres : ndarray, shape (n, 3)
        Centres at rest, m.
    orientations : ndarray, shape (n, 4)
        Unit quaternions (w, x, y, z), body to space; the ring's axis is body z.
    rings : tuple of Ring
        Each ring's geometry and material.
    fixed : ndarray of bool, shape (n,)
        Anchors: rings that do not move.
    law : {"hertz", "power-law"}
    friction : float
        Coulomb coefficient mu of every contact.
    dashpot : float
        Normal dashpot gamma of every contact, N s/m.
    pairs : ndarray, shape (n_pairs, 2)
        Candidate pairs of the contact search (i < j).
    linked : ndarray of bool, shape (n_pairs,)
        Which candidates are interlocked.
    stiffness, exponent : ndarray, shape (n_pairs,)
        The law F = K delta^n of each candidate pair (N/m^n): Eq. (4)'s, or for Hertz K_c at the pair's
        crossing angle at rest (pi/2 if not linked), the scale of the run's steps (the kernels take K_c at
        every contact from the curvatures there).
    slip_speed : float
        Slip speed of the regularised Coulomb law, m/s.
    """

    centres: np.ndarray
    orientations: np.ndarray
    rings: tuple
    fixed: np.ndarray
    law: str
    friction: float
    dashpot: float
    pairs: np.ndarray
    linked: np.ndarray
    stiffness: np.ndarray
    exponent: np.ndarray
    slip_speed: float = SLIP_SPEED

    @classmethod
    def from_rings(cls, centres, orientations, rings, *, fixed=(), law="hertz", friction=0.0, dashpot=0.0,
                   skin=None, slip_speed=SLIP_SPEED) -> Rings:  # fmt: skip
        """Any network of rigid rings.

        Parameters
        ----------
        centres : array_like, shape (n, 3)
            Ring centres, m.
        orientations : array_like, shape (n, 4)
            Unit quaternions (w, x, y, z) taking each ring's body frame to space (the ring's axis is body z).
        rings : Ring or sequence of Ring
            One :class:`~ringchain.theory.Ring` for all, or one per ring.
        fixed : sequence of int, optional
            Indices of the anchors (rings that do not move).
        law : {"hertz", "power-law"}, optional
            Hertz contact at each pair's crossing angle (Eq. (1); default) or the lumped power law of
            Eq. (4) fitted to each ring (:meth:`~ringchain.theory.Ring.power_law`).
        friction : float, optional
            Coulomb friction coefficient mu (default 0: frictionless).
        dashpot : float, optional
            Normal dashpot of every contact, N s/m (default 0).
        skin : float, optional
            Margin of the contact search, m: pairs whose bounding spheres (radius R + r) come closer than
            this at rest are candidates; default half the largest R.
        slip_speed : float, optional
            Slip speed below which friction grows linearly (regularised Coulomb law), m/s.

        Examples
        --------
        >>> ring = Ring.from_aspect_ratio(9.0)
        >>> a = ring.spacing
        >>> turn = [np.cos(np.pi / 4), 0.0, 0.0, np.sin(np.pi / 4)]  # the second ring turned about z
        >>> up = [np.cos(np.pi / 4), np.sin(np.pi / 4), 0.0, 0.0]  # axis along -y: the ring stands in xz
        >>> pair = Rings.from_rings([[0, 0, 0], [0, 0, a]], [up, [0.5, 0.5, 0.5, 0.5]], ring)
        >>> pair.links.tolist()
        [[0, 1]]
        """
        centres = v.as_float("centres", centres)
        if centres.ndim != 2 or centres.shape[1] != 3 or centres.shape[0] < 1:
            raise ValueError(f"centres must have shape (n, 3) in m, got {centres.shape}")
        n = centres.shape[0]
        q = v.as_float("orientations", orientations)
        if q.shape != (n, 4):
            raise ValueError(f"orientations must have shape (n, 4) = ({n}, 4) (unit quaternions w, x, y, z), "
                             f"got {q.shape}")  # fmt: skip
        norm = np.linalg.norm(q, axis=1)
        if np.any(np.abs(norm - 1.0) > 1e-6):
            bad = int(np.argmax(np.abs(norm - 1.0)))
            raise ValueError(f"orientations must be unit quaternions: ring {bad} has norm {norm[bad]:.9g}")
        q = q / norm[:, None]
        if isinstance(rings, Ring):
            rings = (rings,) * n
        rings = tuple(rings)
        if len(rings) != n or not all(isinstance(ring, Ring) for ring in rings):
            raise ValueError(f"rings must be one ringchain.theory.Ring or a sequence of {n} of them")
        flags = np.zeros(n, dtype=bool)
        index = np.asarray(fixed, dtype=np.int64).reshape(-1) if np.size(fixed) else np.zeros(0, dtype=np.int64)
        if index.size and (index.min() < -n or index.max() >= n):
            raise ValueError(f"fixed must list ring indices in [0, {n}), got {index.tolist()}")
        flags[index] = True
        if law not in LAWS:
            raise ValueError(f"law must be one of {LAWS}, got {law!r}")
        friction = float(v.nonnegative("friction", friction))
        dashpot = float(v.nonnegative("dashpot", dashpot, "N s/m"))
        slip_speed = float(v.positive("slip_speed", slip_speed, "m/s"))
        R = np.array([ring.R for ring in rings])
        r = np.array([ring.r for ring in rings])
        skin = 0.5 * R.max() if skin is None else float(v.nonnegative("skin", skin, "m"))
        pairs = candidate_pairs(centres, R + r, skin=skin).astype(np.int64).reshape(-1, 2)
        linked = np.array([linking_number(centres[i], q[i], rings[i], centres[j], q[j], rings[j]) != 0
                           for i, j in pairs], dtype=bool).reshape(-1)  # fmt: skip
        rot = rotation_matrices(q)
        stiffness, exponent = _pair_laws(rings, rot[..., 2], pairs, linked, law)
        return cls(centres, q, rings, flags, law, friction, dashpot, pairs, linked, stiffness, exponent, slip_speed)

    @classmethod
    def chain(cls, n_rings, ring, *, fixed_top=True, spacing=None, **options) -> Rings:
        """The paper's chain in 3D (:func:`~ringchain.numerics.layouts.rings_layouts.chain_layout`): along z, ring 0 at
        the bottom (the struck end), neighbours just touching, planes at 90 degrees; the top ring fixed unless
        ``fixed_top=False`` (a free chain).  ``options`` go to :meth:`from_rings` (law, friction, dashpot)."""
        from .rings_layouts import chain_layout

        centres, orientations, _ = chain_layout(n_rings, ring, spacing=spacing)
        fixed = [len(centres) - 1] if v.boolean("fixed_top", fixed_top) else []
        return cls.from_rings(centres, orientations, ring, fixed=fixed, **options)

    @classmethod
    def mail(cls, rows, cols, ring, *, pattern="4-in-1", fixed_top=True, **options) -> Rings:
        """A sheet of chain mail in the vertical xz plane (:func:`.rings_layouts.mail_layout`),
        its rest pose checked; the top row fixed unless ``fixed_top=False``."""
        from .rings_layouts import mail_layout

        centres, orientations, _ = mail_layout(rows, cols, ring, pattern=pattern)
        fixed = np.arange((rows - 1) * cols, rows * cols) if v.boolean("fixed_top", fixed_top) else []
        return cls.from_rings(centres, orientations, ring, fixed=fixed, **options)

    @classmethod
    def pam(cls, nx, ny, nz, ring, *, fixed_top=True, spacing=None, **options) -> Rings:
        """A polycatenated block on the NbO net (:func:`~ringchain.numerics.layouts.rings_layouts.pam_layout`), its
        rest pose checked; the rings of the top layer fixed unless ``fixed_top=False``."""
        from .rings_layouts import pam_layout

        centres, orientations, _ = pam_layout(nx, ny, nz, ring, spacing=spacing)
        top = np.flatnonzero(np.isclose(centres[:, 2], centres[:, 2].max()))
        fixed = top if v.boolean("fixed_top", fixed_top) else []
        return cls.from_rings(centres, orientations, ring, fixed=fixed, **options)

    # -- what users read -------------------------------------------------------------------------------------------
    @property
    def n_rings(self) -> int:
        return self.centres.shape[0]

    @property
    def masses(self) -> np.ndarray:
        """Ring masses m0, kg, shape (n,)."""
        return np.array([ring.mass for ring in self.rings])

    @property
    def moments(self) -> np.ndarray:
        """Principal moments (I_diameter, I_axis) of each ring, kg m^2, shape (n, 2)."""
        R = np.array([ring.R for ring in self.rings])
        r = np.array([ring.r for ring in self.rings])
        return np.stack(torus_moments(R, r, m=self.masses), axis=-1)

    @property
    def links(self) -> np.ndarray:
        """The interlocked pairs (n_links, 2), i < j: Gauss linking number +-1 of their centre circles."""
        return self.pairs[self.linked]

    def equilibrium(self, **options):
        """The network at its static state under gravity (a :class:`Rings` at rest there).

        The solver (in stages of softened contacts, an L-BFGS descent on the energy then Newton's method on the
        loads with pseudo-time steps, over positions and rotation vectors) is the layouts' module ``rings_static``
        (its ``static_state`` also returns the record of the phases), built on
        :meth:`RingsDynamics.contact_loads`; ``options`` are its ``g``, ``force_tol`` and ``max_iterations``.
        """
        try:
            from .rings_static import equilibrium
        except ImportError:
            raise NotImplementedError(
                "the static solver of rigid rings (numerics/rings_static.py) is not in this build; minimise the "
                "energy of Rings.potential (its forces and torques are minus its gradient)"
            ) from None
        return equilibrium(self, **options)

    def moved(self, centres, orientations) -> Rings:
        """The same network with other rest centres (n, 3, m) and orientations (n, 4), its laws kept."""
        q = np.asarray(orientations, dtype=float)
        return Rings(np.array(centres, dtype=float), q / np.linalg.norm(q, axis=1, keepdims=True), self.rings,
                     self.fixed, self.law, self.friction, self.dashpot, self.pairs, self.linked, self.stiffness,
                     self.exponent, self.slip_speed)  # fmt: skip

    def potential(self, centres, orientations, g=STANDARD_GRAVITY):
        """Potential energy (J: contacts and gravity), forces (n, 3, N) and torques (n, 3, N m, in space) of a
        configuration: minus the gradient of the energy over positions and rotation vectors (applied on the
        left, in space).  Fixed rings get their loads too (the solver ignores them).  Each call searches the
        contacts from scratch; :meth:`RingsDynamics.contact_loads` keeps the warm start between calls."""
        elastic, loads = self.dynamics().contact_loads(centres, orientations)
        free = ~self.fixed
        gravity = g * float(np.sum(self.masses[free] * np.asarray(centres)[free, 2]))
        forces = loads[:, :3].copy()
        forces[free, 2] -= g * self.masses[free]
        return elastic + gravity, forces, loads[:, 3:]

    # -- the model contract (engine.integrate) ---------------------------------------------------------------------
    def dynamics(self, stiffness_scale=1.0) -> RingsDynamics:
        """What the engine integrates (a fresh one per run: it carries the warm start of the contacts); the static
        solver's softened stages scale every contact's stiffness by ``stiffness_scale``."""
        return RingsDynamics(self, stiffness_scale)

    def initial_motion(self, velocity=None, angular_velocity=None):
        """Initial state (x0, u0), each of shape (1, 7n), from velocities (n, 3, m/s, space) and angular
        velocities (n, 3, rad/s, body frame) of the rings at rest (None: zero); fixed rings must not move."""
        n = self.n_rings
        values = []
        for name, value, unit in (("velocity", velocity, "m/s"), ("angular_velocity", angular_velocity, "rad/s")):
            value = np.zeros((n, 3)) if value is None else v.as_float(name, value)
            if value.shape != (n, 3):
                raise ValueError(f"{name} must have shape (n, 3) = ({n}, 3) in {unit}, got {value.shape}")
            if np.any(value[self.fixed] != 0.0):
                raise ValueError(f"{name} of the fixed rings {np.flatnonzero(self.fixed).tolist()} must be zero")
            values.append(value)
        x = self.dynamics().state(self.centres, self.orientations)
        u = np.zeros((n, 7))
        u[:, :3], u[:, 3:6] = values
        return x[None], u.reshape(1, -1)

    def impact_state(self, speeds, dropped, gravity, g):
        """Ring 0 moving along -z at each of ``speeds`` (m/s), the rest at rest: the struck end of a chain."""
        if dropped:
            raise ValueError("rigid rings take an impact velocity (or velocity=...), not a drop height")
        if speeds.size != 1:
            raise ValueError("rigid rings integrate one run at a time")
        velocity = np.zeros((self.n_rings, 3))
        velocity[0, 2] = -float(speeds[0])
        if self.fixed[0] and speeds[0] != 0.0:
            raise ValueError("ring 0 is fixed: it cannot be struck")
        return self.initial_motion(velocity)

    def recorded(self, rings):
        """Every ring is recorded."""
        if rings is not None:
            raise ValueError("rigid rings record every ring (rings=None)")
        return None, None

    def result(self, **record) -> RingsBatch:
        """The record of the runs; the quaternions read from the continuous extension set to norm 1."""
        x = record["x"].reshape(*record["x"].shape[:-1], self.n_rings, 7).copy()
        x[..., 3:] /= np.linalg.norm(x[..., 3:], axis=-1, keepdims=True)
        record["x"] = x.reshape(record["x"].shape)
        record.pop("rings", None)
        record.pop("drop_height", None)
        record.pop("memory", None)
        return RingsBatch(model=self, **record)


def _pair_laws(rings, axes, pairs, linked, law):
    """(K, n) of each candidate pair: Hertz at the crossing angle (linked; pi/2 otherwise), or Eq. (4)."""
    from ringchain.theory import hertz_stiffness_pair

    L = len(pairs)
    if law == "power-law":
        K, n = np.empty(L), np.empty(L)
        for k, (i, j) in enumerate(pairs):
            (K_a, n_a), (K_b, n_b) = _power_law(rings[i]), _power_law(rings[j])
            K[k], n[k] = (K_a, n_a) if (K_a, n_a) == (K_b, n_b) else (np.sqrt(K_a * K_b), 0.5 * (n_a + n_b))
        return K, n
    if not L:
        return np.zeros(0), np.zeros(0)
    i, j = pairs.T
    cosine = np.minimum(1.0, np.abs(np.einsum("kc,kc->k", axes[i], axes[j])))
    angle = np.where(linked, np.maximum(np.arccos(cosine), 1e-3), np.pi / 2)
    R, r = np.array([ring.R for ring in rings]), np.array([ring.r for ring in rings])
    E, nu = np.array([ring.material.E for ring in rings]), np.array([ring.material.nu for ring in rings])
    K = np.asarray(hertz_stiffness_pair(R[i], r[i], E[i], nu[i], R[j], r[j], E[j], nu[j], angle), dtype=float)
    return np.broadcast_to(K, (L,)).copy(), np.full(L, 1.5)


@functools.cache
def _power_law(ring):
    return ring.power_law()


class RingsDynamics:
    """The dynamics contract of :mod:`ringchain.numerics.engine.network` for :class:`Rings` (state of one run:
    [x (7n), u (7n), W if damped]; the module notes of :mod:`ringchain.numerics.engine.rings_step`)."""

    stateful = False

    def __init__(self, model: Rings, stiffness_scale: float = 1.0):
        self.model = model
        #: Factor on every contact's stiffness (K of the power law, E* of Hertz's): below 1, the softened contacts
        #: of the static solver's first stages (:mod:`ringchain.numerics.layouts.rings_static`).
        self.stiffness_scale = float(v.positive("stiffness_scale", stiffness_scale))
        self.n_rings = model.n_rings
        self.n_coords = 7 * model.n_rings
        self.damped = bool(model.dashpot > 0.0 or model.friction > 0.0)
        self.n_links = len(model.links)

    @functools.cached_property
    def _packed(self):
        from ringchain.theory import contact_modulus_pair, elliptical_factor_grid

        from ..engine.kernels import PARAMETERS, PackedRings
        from ..engine.rings_kernels import MAX_CONTACTS

        model = self.model
        n, L = self.n_rings, len(model.pairs)
        R = np.array([ring.R for ring in model.rings])
        r = np.array([ring.r for ring in model.rings])
        I1, I3 = torus_moments(R, r, m=model.masses)
        bodies = np.column_stack([R, r, model.masses, I1, I3, model.fixed.astype(float), model.centres])
        warm = np.zeros((L, 1 + MAX_CONTACTS))  # no minima known: the first evaluation searches cold
        par = np.zeros((1, L, PARAMETERS))
        par[0, :, 0], par[0, :, 1], par[0, :, 2], par[0, :, 3] = model.stiffness * self.stiffness_scale, \
            model.exponent, model.dashpot, model.friction  # fmt: skip
        gravity = np.zeros((n, 7))
        gravity[~model.fixed, 2] = 1.0
        ints = np.array([2, 3, 7 * n, int(self.damped), n, L, 1, 0, 0, 0], dtype=np.int64)  # 1: search first
        # The kind of rings_law.contact_force: 0 Hertz of the curvatures at each contact (E* per pair, the
        # elliptical factor's table), 1 the given law F = K delta^n (Rings.stiffness, exponent).
        hertz = model.law == "hertz"
        kind = np.full(L, 0 if hertz else 1, dtype=np.int64)
        table, step = elliptical_factor_grid() if hertz else (np.ones(4), 1.0)
        table = kernel_array(table, dtype=float)
        moduli = np.zeros(L)
        if hertz and L:
            E = np.array([ring.material.E for ring in model.rings])
            nu = np.array([ring.material.nu for ring in model.rings])
            i, j = model.pairs.T
            moduli = np.asarray(contact_modulus_pair(E[i], nu[i], E[j], nu[j]), dtype=float) * self.stiffness_scale
        return PackedRings(ints, np.array([model.slip_speed, step]), np.zeros((1, 7 * n)), gravity.reshape(1, -1),
                      model.pairs[:, 0].copy(), model.pairs[:, 1].copy(), kind, par, warm, moduli, np.zeros(L),
                      kernel_array(bodies), table, np.zeros(n))  # fmt: skip

    def packed(self):
        """The :class:`~ringchain.numerics.engine.kernels.PackedRings` form (kind 2) of the rings, made once per run."""
        return self._packed

    def state(self, centres, orientations) -> np.ndarray:
        """The coordinates x (7n,) of a configuration: displacements from the rest centres, quaternions."""
        x = np.empty((self.n_rings, 7))
        x[:, :3] = np.asarray(centres, dtype=float) - self.model.centres
        x[:, 3:] = orientations
        return x.ravel()

    def contact_loads(self, centres, orientations):
        """Elastic energy of the contacts (J) and the contact loads (n, 6: force, N, and torque about the centre,
        N m, in space) of a configuration at rest, warm-started from this object's last call (the first searches
        every pair from scratch)."""
        from ..engine.rings_step import loads

        x = self.state(centres, orientations)
        out = np.zeros((self.n_rings, 6))
        _, elastic = loads(self.packed(), x, np.zeros_like(x), np.empty((self.n_rings, 3, 3)), out, True)
        return elastic, out

    # -- the dynamics contract ----------------------------------------------------------------------------------
    @property
    def bandwidth(self) -> tuple[int, int]:
        size = 2 * self.n_coords + int(self.damped)
        return size, size

    def first_order_rhs(self, n_runs, g):
        """f(t, y) of one run's state [x, u, W if damped] (the compiled right-hand side)."""
        from ..engine.rings_step import derivative

        if n_runs != 1:
            raise ValueError("rigid rings integrate one run at a time")
        m = self.packed()

        def rhs(t, y):
            dy = np.empty_like(y)
            derivative(m, float(g), kernel_array(y), dy)
            return dy

        return rhs

    def pack(self, x, u, dissipated=None) -> np.ndarray:
        parts = [np.atleast_2d(x), np.atleast_2d(u)]
        if self.damped:
            parts.append(np.zeros((parts[0].shape[0], 1)) if dissipated is None else np.reshape(dissipated, (-1, 1)))
        return np.hstack(parts).ravel()

    def unpack(self, y, n_runs):
        N = self.n_coords
        states = y.reshape(n_runs, 2 * N + int(self.damped), -1)
        return states[:, :N], states[:, N : 2 * N], (states[:, 2 * N] if self.damped else None)

    def tolerance_scales(self, X, V, E) -> np.ndarray:
        """Absolute tolerance per unit atol of each component of the compiled state, shape (B, 7n [+ 7n, 1])."""
        R = np.array([ring.R for ring in self.model.rings])
        per_x = np.column_stack([np.ones((self.n_rings, 3)), np.ones((self.n_rings, 4)) / R[:, None]])
        per_u = np.column_stack([np.ones((self.n_rings, 3)), np.ones((self.n_rings, 4)) / R[:, None]])
        rows = [X[:, None] * per_x.ravel(), V[:, None] * per_u.ravel()]
        if self.damped:
            rows.append(E[:, None])
        return np.hstack(rows)

    def state_scales(self, X, V, E) -> np.ndarray:
        return self.tolerance_scales(X, V, E).ravel()

    def energy(self, x, u, x_start, g, dissipated) -> RingsEnergy:
        """Energies of states x, u (..., 7n) (the module notes): translational and rotational kinetic, contact,
        gravity from ``x_start``, and the dissipated energy."""
        from ..engine.rings_step import contact_state

        model = self.model
        shape = np.shape(x)[:-1]
        X = np.reshape(x, (-1, self.n_rings, 7))
        U = np.reshape(u, (-1, self.n_rings, 7))
        X0 = np.broadcast_to(np.reshape(x_start, (-1, self.n_rings, 7)), X.shape)
        mass = model.masses
        I1, I3 = self.moments
        translational = 0.5 * np.einsum("i,kic->k", mass, U[..., :3] ** 2)
        rotational = 0.5 * np.einsum("i,kic->k", I1, U[..., 3:5] ** 2) + 0.5 * np.einsum("i,ki->k", I3, U[..., 5] ** 2)
        free = ~model.fixed
        gravity = g * np.einsum("i,ki->k", mass * free, X[..., 2] - X0[..., 2])
        m = self.packed()
        record = np.zeros((X.shape[0], len(model.pairs), 2, 12))
        contact_state(m, kernel_array(X.reshape(X.shape[0], -1)), kernel_array(U.reshape(
            U.shape[0], -1)), np.zeros_like(m.rest_vectors), record)  # fmt: skip
        contact = record[..., 11].sum(axis=(1, 2))
        return RingsEnergy(translational.reshape(shape), rotational.reshape(shape), contact.reshape(shape),
                           gravity.reshape(shape), np.broadcast_to(dissipated, shape).astype(float))  # fmt: skip

    @functools.cached_property
    def moments(self):
        return tuple(self.model.moments.T)

    def scales(self, x0, u0, g):
        """Displacement (m), velocity (m/s) and energy (J) scales of each run.

        The velocity scale is the largest speed of a ring (its rim's for spins), floored at
        1e-3 sqrt(g R); the energy scale m V^2/4; the displacement scale the approach storing that energy in
        the stiffest contact, or the largest approach at rest if larger, floored at 1e-6 R.
        """
        model = self.model
        R = np.array([ring.R for ring in model.rings])
        U = np.reshape(u0, (u0.shape[0], self.n_rings, 7))
        speed = np.maximum(np.linalg.norm(U[..., :3], axis=-1), np.linalg.norm(U[..., 3:6], axis=-1) * R).max(axis=1)
        speed = np.maximum(speed, 1e-3 * np.sqrt(g * R.min()))
        energy = 0.25 * model.masses.min() * speed**2
        X = np.full(speed.shape, 1e-6 * R.min())
        if len(model.pairs):
            K, n = model.stiffness.max(), model.exponent.min()
            X = np.maximum(X, ((n + 1.0) * energy / K) ** (1.0 / (n + 1.0)))
            m = self.packed()
            record = np.zeros((x0.shape[0], len(model.pairs), 2, 12))
            from ..engine.rings_step import contact_state

            contact_state(m, kernel_array(x0), kernel_array(u0), np.zeros_like(m.rest_vectors), record)
            X = np.maximum(X, np.max(record[..., 0], axis=(1, 2), initial=0.0))
        return X, speed, energy

    def max_frequency(self, X) -> float:
        """A bound of the fastest linearised mode, rad/s: a ring between two contacts of the stiffest law at four
        times the force of approach X, translating and turning (the contact at R + r from its centre)."""
        model = self.model
        R = np.array([ring.R + ring.r for ring in model.rings])
        I1, _ = self.moments
        if not len(model.pairs):
            return 1.0
        K, n = model.stiffness.max(), model.exponent.min()
        force = 4.0 * K * X**n
        k = n * K ** (1.0 / n) * force ** ((n - 1.0) / n)
        return float(np.sqrt(2.0 * k * np.max(1.0 / model.masses + R**2 / I1)))


@dataclass(frozen=True)
class RingsEnergy:
    """Energies of a run of rigid rings, J, each of shape (..., len(t)): kinetic (translational and
    rotational), elastic energy of the contacts, gravity from the initial configuration, and the energy the
    dashpots and friction took out since t = 0.  ``total`` is conserved."""

    translational: np.ndarray
    rotational: np.ndarray
    contact: np.ndarray
    gravity: np.ndarray
    dissipated: np.ndarray

    @property
    def kinetic(self) -> np.ndarray:
        return self.translational + self.rotational

    @property
    def mechanical(self) -> np.ndarray:
        return self.kinetic + self.contact + self.gravity

    @property
    def total(self) -> np.ndarray:
        return self.mechanical + self.dissipated


@dataclass(frozen=True, eq=False)
class RingsSimulation:
    """One run of rigid rings.

    Attributes
    ----------
    t : ndarray, shape (T,)
        Times, s.
    x, u : ndarray, shape (T, 7n)
        The integrated state (the module notes of :mod:`ringchain.numerics.engine.rings_step`).
    dissipated : ndarray, shape (T,)
        Energy the dashpots and friction took out since t = 0, J.
    g : float
        Gravity of the run, m/s^2 (0 without).
    model : Rings
    stats : dict
    """

    t: np.ndarray
    x: np.ndarray
    u: np.ndarray
    dissipated: np.ndarray
    g: float
    model: Rings
    stats: dict
    impact_velocity: float = 0.0

    @property
    def _state(self):
        return self.x.reshape(self.t.size, -1, 7), self.u.reshape(self.t.size, -1, 7)

    @property
    def centres(self) -> np.ndarray:
        """Ring centres, m, shape (T, n, 3)."""
        return self.model.centres + self._state[0][..., :3]

    @property
    def orientations(self) -> np.ndarray:
        """Unit quaternions (w, x, y, z), shape (T, n, 4)."""
        q = self._state[0][..., 3:]
        return q / np.linalg.norm(q, axis=-1, keepdims=True)

    @property
    def velocities(self) -> np.ndarray:
        """Velocities of the centres, m/s, space, shape (T, n, 3)."""
        return self._state[1][..., :3]

    @property
    def angular_velocities(self) -> np.ndarray:
        """Angular velocities, rad/s, body frame, shape (T, n, 3)."""
        return self._state[1][..., 3:6]

    @functools.cached_property
    def contacts(self) -> np.ndarray:
        """Every contact slot of every candidate pair (:attr:`Rings.pairs`), shape (T, n_pairs, 2, 12): [approach
        (m; -inf for an unused slot), point (3, m), normal (3, from the pair's second ring to its first), normal
        force (N), friction force on the first ring (3, N), elastic energy (J)]: the two deepest minima of the
        distance of the centre circles of each pair."""
        from ..engine.rings_step import contact_state

        dyn = self.model.dynamics()
        m = dyn.packed()
        out = np.zeros((self.t.size, len(self.model.pairs), 2, 12))
        contact_state(m, kernel_array(self.x), kernel_array(self.u), np.zeros_like(m.rest_vectors), out)
        return out

    @property
    def contact_force(self) -> np.ndarray:
        """Normal force of each candidate pair (summed over its contacts), N, shape (T, n_pairs)."""
        return self.contacts[..., 7].sum(axis=-1)

    @property
    def link_force(self) -> np.ndarray:
        """Normal force each linked pair carries (:attr:`Rings.links`), N, tension positive, shape (T, n_links)."""
        return self.contact_force[:, self.model.linked]

    def energy(self) -> RingsEnergy:
        """The energy budget of the run (:class:`RingsEnergy`)."""
        dyn = self.model.dynamics()
        return dyn.energy(self.x, self.u, self.x[0], self.g, self.dissipated)

    def linear_momentum(self) -> np.ndarray:
        """Total momentum of the rings, kg m/s, shape (T, 3)."""
        return np.einsum("i,tic->tc", self.model.masses, self.velocities)

    def angular_momentum(self, origin=(0.0, 0.0, 0.0)) -> np.ndarray:
        """Total angular momentum about ``origin`` (m), kg m^2/s, space, shape (T, 3)."""
        moments = self.model.moments
        body = self.angular_velocities * np.stack([moments[:, 0], moments[:, 0], moments[:, 1]], axis=-1)
        spin = np.einsum("tiab,tib->tia", rotation_matrices(self.orientations), body)
        orbital = np.cross(self.centres - np.asarray(origin, dtype=float), self.velocities) * self.model.masses[:, None]
        return (spin + orbital).sum(axis=1)


@dataclass(frozen=True, eq=False)
class RingsBatch(RingsSimulation):
    """Runs of rigid rings (one, for now): arrays of shape (B, T, ...); ``batch[0]`` is a :class:`RingsSimulation`
    (``impact_velocity`` has one value per run)."""

    def __len__(self) -> int:
        return self.x.shape[0]

    def __getitem__(self, b) -> RingsSimulation:
        b = range(len(self))[b]
        return RingsSimulation(t=self.t, x=self.x[b], u=self.u[b], dissipated=self.dissipated[b], g=self.g,
                               model=self.model, stats=self.stats,
                               impact_velocity=float(self.impact_velocity[b]))  # fmt: skip
