r"""The chain of rings that bend: :class:`RingChain`, a layout of the engine, and its runs.

- :class:`RingChain`, :func:`simulate_rings` -- rings resolved as curved beams
  (:class:`~ringchain.numerics.layouts.ring_beam.ReducedRing`) joined at their contact points by the
  unilateral Hertz law F = K_c delta_+^(3/2) (Eq. (1)), hanging under gravity from a fixed
  support through one more contact, struck at the bottom as the lattices are
  (:class:`~ringchain.numerics.Chain`): a drop starts when the slack is taken up, ring 0
  undeformed and moving at sqrt(2 g h), the rest hanging at equilibrium without ring 0's
  weight.  Inertia and weight are the ring's own mass m0: nothing is fitted.  The chain
  implements the engine's model and dynamics contracts itself (its rings' dense mass and
  stiffness matrices are not pairwise links), so :func:`~ringchain.numerics.simulate`
  integrates it with any of its methods.
- :class:`RingSimulation` -- a :class:`~ringchain.numerics.Simulation` of the ring-resolved
  chain: contact, support and sensor forces, energy, and the signal helpers and CSV
  writer of the lattice runs.  The sensor of a ring reads the force carried across the
  middle of its body: the sum of the normal forces in the two side sections (theta = 0 and
  pi, halfway between the contacts), the continuum counterpart of the dual-spring model's
  bending-spring force.

Coordinates: the axis points up the chain, away from the impact (ARCHITECTURE.md); each
ring's coordinates are [y_bottom, y_top, q_1, ...] (:mod:`.ring_beam`).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from ringchain.theory import STANDARD_GRAVITY, Ring
from ringchain.theory import _validate as v

from ..engine.integrate import impact_speeds, simulate
from ..engine.results import BatchSimulation, EnergyBudget, Simulation
from .chain import ring_index
from .ring_beam import DEFAULT_ELEMENTS, DEFAULT_MODES, ReducedRing, RingModel

__all__ = ["RingChain", "RingSimulation", "RingBatch", "simulate_rings", "RING_METHODS", "DEFAULT_RING_METHOD"]

#: Integrators of :func:`simulate_rings`, the default first (see its notes; any method of
#: :func:`~ringchain.numerics.simulate` runs, these two are the ones the tests compare).
RING_METHODS = ("verlet", "odeint")
DEFAULT_RING_METHOD = "verlet"


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
        set_("n_rings", v.count("n_rings", self.n_rings, 2))
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
        from scipy.linalg import eigh

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
        speeds, dropped = impact_speeds(impact_velocity, drop_height, g)
        if speeds.size != 1:
            raise ValueError("simulate_rings takes one impact")
        x, u = self.impact_state(speeds, dropped, v.flag("gravity", gravity), g)
        return x.reshape(self.n_rings, -1), u.reshape(self.n_rings, -1)

    def ring_index(self, ring) -> int:
        """``ring`` as a ring index of this chain (ValueError naming it otherwise)."""
        return ring_index(ring, self.n_rings)

    # -- the model contract (ringchain.numerics.engine.integrate) -------------------------------------------
    def dynamics(self) -> RingChain:
        """What the engine integrates: the chain itself (it implements the dynamics contract)."""
        return self

    def impact_state(self, speeds, dropped, gravity, g):
        """Flat coordinates and velocities of the runs at t = 0, shape (B, n_dof); ``speeds`` in m/s."""
        if gravity and self.support != "fixed":
            raise ValueError("gravity needs the chain to hang from a fixed support (support='fixed')")
        if gravity:
            x = self.static_state(g, first_ring_hanging=not dropped)
        else:
            x = np.zeros((self.n_rings, self.ring.n_dof))
        x = np.broadcast_to(x.ravel(), (speeds.size, self.n_dof)).copy()
        u = np.zeros_like(x)
        u[:, : self.ring.n_dof] = -speeds[:, None] * self.ring.rigid
        return x, u

    def recorded(self, rings):
        """Every ring is recorded (the ring-resolved chain is short)."""
        if rings is not None:
            raise ValueError("the ring-resolved chain records every ring (rings=None)")
        return None, None

    def result(self, **record) -> RingBatch:
        return RingBatch(chain=self, network=None, **record)

    # -- the dynamics contract (ringchain.numerics.engine.network) -------------------------------------------
    damped = False

    @property
    def n_coords(self) -> int:
        return self.n_dof

    @property
    def bandwidth(self) -> tuple[int, int]:
        """Bands of the Jacobian of :meth:`first_order_rhs` (state ring by ring: x, then u, of each ring)."""
        n = self.ring.n_dof
        return 4 * n - 2, n

    def stepper(self, batch_shape, g):
        """A function ``(x, u, out)`` writing the accelerations of flat coordinates x into ``out``.

        ``u`` is not read: the chain is undamped.  One run at a time (``batch_shape`` () or (1,)).
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

    def first_order_rhs(self, n_runs, g):
        """f(t, y) for y = [x_0, u_0, x_1, u_1, ...] (ring by ring) of one run."""
        if n_runs != 1:
            raise ValueError("the ring-resolved chain integrates one run at a time")
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

        return rhs

    def pack(self, x, u, dissipated=None) -> np.ndarray:
        N, n = self.n_rings, self.ring.n_dof
        return np.stack([x.reshape(-1, N, n), u.reshape(-1, N, n)], axis=2).ravel()

    def unpack(self, y, n_runs):
        N, n = self.n_rings, self.ring.n_dof
        states = y.reshape(n_runs, N, 2, n, -1)
        return states[:, :, 0].reshape(n_runs, N * n, -1), states[:, :, 1].reshape(n_runs, N * n, -1), None

    def state_scales(self, X, V, E) -> np.ndarray:
        N, n = self.n_rings, self.ring.n_dof
        return np.broadcast_to(np.stack([X, V], axis=-1)[:, None, :, None], (X.size, N, 2, n)).ravel()

    def energy(self, x, u, x_start, g, dissipated) -> EnergyBudget:
        """Kinetic, contact, ring strain ("bending") and gravity energy, J, of states (..., n_dof)."""
        ring = self.ring
        X = x.reshape(*x.shape[:-1], self.n_rings, -1)
        U = u.reshape(X.shape)
        X0 = np.asarray(x_start).reshape(*np.shape(x_start)[:-1], self.n_rings, -1)
        e = np.maximum(self.contact_extension(X), 0.0)
        centre = (ring.mass @ ring.rigid) / ring.m
        return EnergyBudget(
            kinetic=0.5 * np.einsum("...ia,ab,...ib->...", U, ring.mass, U),
            contact=self.K_c * np.sum(e ** (self.n + 1.0), axis=-1) / (self.n + 1.0),
            bending=0.5 * np.einsum("...ia,ab,...ib->...", X, ring.stiffness, X),
            gravity=g * ring.m * np.sum((X - X0) @ centre, axis=-1),
            dissipated=dissipated,
        )

    def scales(self, x0, u0, g):
        """Displacement (m), velocity (m/s) and energy (J) scales of each run (as a network's).

        The velocity scale is the impact speed (floored at 1e-3 sqrt(g a)); the displacement
        scale the extension at which the energy m V^2/4 of a two-ring collision is stored in a
        contact and a ring body in series, or the largest static extension if larger.
        """
        speed = np.maximum(np.max(np.abs(u0), axis=-1), max(1e-3 * np.sqrt(g * self.a), 1e-9))
        energy = 0.25 * self.m * speed**2
        X = ((self.n + 1.0) * energy / self.K_c) ** (1.0 / (self.n + 1.0)) + np.sqrt(2.0 * energy / self.ring.K_b)
        static = np.abs(self.contact_extension(x0.reshape(x0.shape[0], self.n_rings, -1))).max(axis=-1, initial=0.0)
        return np.maximum(X, static), speed, energy

    def max_frequency(self, X) -> float:
        """The fastest mode of a ring held at both contacts by twice the contact stiffness at four
        times the force of extension X (a bound for the chain), rad/s."""
        from scipy.linalg import eigh

        force = 4.0 * self.K_c * X**self.n
        k_contact = self.n * self.K_c ** (1.0 / self.n) * force ** ((self.n - 1.0) / self.n)
        ring = self.ring
        K = ring.stiffness.copy()
        K[0, 0] += 2.0 * k_contact
        K[1, 1] += 2.0 * k_contact
        return float(np.sqrt(eigh(K, ring.mass, eigvals_only=True)[-1]))


def simulate_rings(chain: RingChain, t_end, *, impact_velocity=None, drop_height=None, gravity=True, t_eval=None,
                   method=DEFAULT_RING_METHOD, **options) -> RingSimulation:  # fmt: skip
    """Integrate the ring-resolved chain after an impact on ring 0 (:func:`~ringchain.numerics.simulate`, Verlet).

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
    method : {"verlet", "odeint"}, optional
        Velocity Verlet with step ``dt`` (the default, :data:`DEFAULT_RING_METHOD`), or LSODA
        through :func:`scipy.integrate.odeint` (tolerances ``rtol``, and ``atol`` relative to
        the run's displacement and velocity scales).  The default step is 1/``steps_per_period``
        of the period of the fastest mode of a ring with both contacts stiffened to twice their
        stiffness at four times the estimated peak force, an upper bound on the chain's fastest
        mode (:meth:`RingChain.max_frequency`).  The chain is undamped and its rings' fast modes
        make LSODA turn stiff (ten times slower with 8 or more modes); symplectic Verlet keeps
        the energy to ~1e-5 of the impact's at the default step and is second order
        (tests/numerics/layouts/test_ring_beam.py).
    **options
        As in :func:`~ringchain.numerics.simulate` (``n_samples``, ``rtol``, ``atol``, ``dt``,
        ``steps_per_period``, ``g``...).

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
    if method not in RING_METHODS:
        raise ValueError(f"method must be one of {RING_METHODS}, got {method!r}")
    return simulate(chain, t_end, impact_velocity=impact_velocity, drop_height=drop_height, gravity=gravity,
                    t_eval=t_eval, method=method, **options)  # fmt: skip


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
    def link_force(self) -> np.ndarray:
        """Force of every contact, then of the support contact if fixed, N (the ring-resolved chain's links)."""
        return self.bond_force

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
        return self.chain.energy(self.x, self.u, self.x[:1], self.g, self.dissipated)


@dataclass(frozen=True, eq=False)
class RingBatch(BatchSimulation):
    """Runs of the ring-resolved chain; ``result[0]`` is a :class:`RingSimulation`."""

    def __getitem__(self, i) -> RingSimulation:
        i = range(len(self))[i]
        return RingSimulation(
            t=self.t, x=np.ascontiguousarray(self.x[i]), u=np.ascontiguousarray(self.u[i]),
            dissipated=self.dissipated[i], g=self.g, stats=self.stats, chain=self.chain,
            impact_velocity=float(self.impact_velocity[i]),
            drop_height=None if self.drop_height is None else float(self.drop_height[i]),
        )  # fmt: skip
