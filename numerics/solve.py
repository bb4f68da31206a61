r"""Integrating a chain: initial conditions, solvers, and the recorded result.

Initial conditions (paper Sec. III.A).  With gravity the chain hangs from its fixed
support in static equilibrium (each contact carries the weight below it,
:meth:`Chain.static_extension`).  The impact is one of

- ``impact_velocity`` v: ring 0 starts moving away from the chain at speed v (along
  -axis) from the equilibrium of the whole chain;
- ``drop_height`` h: ring 0 was lifted and released, fell freely with its contacts
  slack, and the integration starts when its contact with ring 1 is just taut again,
  ring 0 moving away from the chain at sqrt(2 g h), unstretched (a freely falling ring
  carries no internal load), and the rest of the chain hanging at rest without ring
  0's weight.  h is the free-fall height, from release to the instant the slack is
  taken up: the lift above the hanging position is h plus the static extension of
  contact 0, a few micrometres.

Solvers.  ``method`` is "odeint" (the default: ODEPACK's LSODA driven by
:func:`scipy.integrate.odeint`, whose stepping loop runs in Fortran), a method of
:func:`scipy.integrate.solve_ivp` ("LSODA", the same integrator stepped from Python,
or "DOP853", "RK45", "RK23"), all on the vectorised right-hand side of
:class:`~ringchain.numerics.models.Lattice`, or "verlet": fixed-step velocity Verlet
(symplectic, second order) for long undamped chains.  "odeint" and "LSODA" take the
same steps (same right-hand-side count to a few per cent); "odeint" is 2-3x faster
on the paper's 20-ring chain because solve_ivp's per-step Python overhead is gone.
The absolute tolerances are ``rtol`` times each run's own scales (:func:`_scales`):
displacements of micrometres and velocities of metres per second cannot share one
absolute tolerance.  scipy's error norm is a root mean square over the
whole state, so in a very long chain, where the pulse occupies a few of many rings, the
control is looser per active ring than ``rtol`` suggests; Verlet has no such effect.
A batch of runs of one chain is integrated as one array problem (:func:`simulate_batch`).
"""

from __future__ import annotations

import csv
import functools
from dataclasses import dataclass, field

import numpy as np
from ringchain.theory import _validate as v
from ringchain.theory import paper_data
from scipy.integrate import odeint, solve_ivp

from . import signals
from .chain import Chain
from .models import STANDARD_GRAVITY

__all__ = [
    "simulate",
    "simulate_batch",
    "initial_state",
    "Simulation",
    "BatchSimulation",
    "EnergyBudget",
    "paper_experiment",
    "PaperExperiment",
    "ADAPTIVE_METHODS",
    "DEFAULT_METHOD",
    "DEFAULT_RTOL",
    "VERLET_STEPS_PER_PERIOD",
]

#: Default integrator (see benchmarks/bench_paper_recipe.py for the choice).
DEFAULT_METHOD = "odeint"

#: Default relative tolerance of the adaptive methods; the absolute tolerances are this
#: times the displacement, velocity and energy scales of the impact (:func:`_scales`).
#: Chosen by the convergence test in tests/numerics/test_solve.py.
DEFAULT_RTOL = 1e-9

#: Verlet steps per period of the fastest linearised lattice mode at four times the
#: estimated peak force; chosen by the convergence test in tests/numerics/test_solve.py.
VERLET_STEPS_PER_PERIOD = 60

#: The adaptive methods offered: "odeint" (LSODA stepped in Fortran, the default) and the
#: :func:`scipy.integrate.solve_ivp` methods.  LSODA (Adams, switching to BDF with a banded
#: Jacobian if the chain turns stiff) suits the chain; the explicit Runge-Kutta methods
#: lose their order at the kink of the contact law at delta = 0.
ADAPTIVE_METHODS = ("odeint", "LSODA", "DOP853", "RK45", "RK23")


def _odeint(rhs, y0, t_eval, rtol, atol, bandwidth):
    """LSODA through :func:`scipy.integrate.odeint`: (states of shape (len(y0), len(t)), nfev).

    The state y0 is at t = 0; odeint's first output time is its initial time, so 0 is
    put in front of ``t_eval`` when it starts later and its row dropped.  The Jacobian is
    banded, as for solve_ivp's LSODA.  A failure (too much work, tolerance too small) is
    an error.
    """
    lower, upper = bandwidth
    prepend = t_eval[0] > 0
    times = np.concatenate([[0.0], t_eval]) if prepend else t_eval
    y, info = odeint(
        rhs, y0, times, rtol=rtol, atol=atol, ml=lower, mu=upper, tfirst=True, full_output=True, mxstep=1_000_000
    )
    if info["message"] != "Integration successful.":
        raise RuntimeError(f"odeint failed: {info['message']}")
    return y[int(prepend) :].T, int(info["nfe"][-1])


# -- initial conditions ---------------------------------------------------------------------
def _impact_speeds(impact_velocities, drop_heights, g):
    if impact_velocities is not None and drop_heights is not None:
        raise ValueError("give an impact velocity or a drop height, not both")
    if drop_heights is not None:
        h = np.atleast_1d(v.nonnegative("drop_height", drop_heights, "m"))
        return np.sqrt(2.0 * g * h), True
    if impact_velocities is not None:
        return np.atleast_1d(v.nonnegative("impact_velocity", impact_velocities, "m/s")), False
    return np.zeros(1), False


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
    g = float(v.positive("g", g, "m/s^2"))
    speeds, dropped = _impact_speeds(impact_velocity, drop_height, g)
    g_static = g if gravity else 0.0
    if gravity and chain.support != "fixed":
        raise ValueError("gravity needs the chain to hang from a fixed support (support='fixed')")
    e = chain.static_extension(g_static, first_ring_hanging=not dropped)
    x = chain.displacement_from_extension(e)
    x = np.broadcast_to(x, (speeds.size, chain.n_sites)).copy()
    u = np.zeros_like(x)
    u[:, : chain.sites_per_ring] = -speeds[:, None]
    return x, u


def _scales(chain: Chain, x0, speeds, g):
    """Displacement (m), velocity (m/s) and energy (J) scales of each run, shape (B,) each.

    The velocity scale is the impact speed (floored at 1e-3 sqrt(g a) for a run without
    impact); the displacement scale adds the static pre-stretch to the extension at
    which the energy m V^2/4 of a two-ring collision is stored (contact and bending in
    series for the dual-spring model).  Each run of a batch gets its own scales, so that
    a small impact beside a large one keeps its own accuracy.
    """
    speed = np.maximum(speeds, max(1e-3 * np.sqrt(g * chain.a), 1e-9))
    energy = 0.25 * chain.m * speed**2
    X = ((chain.n + 1.0) * energy / chain.K) ** (1.0 / (chain.n + 1.0))
    if chain.K_b is not None:
        X = X + np.sqrt(2.0 * energy / chain.K_b)
    X = np.maximum(X, np.max(np.abs(chain.lattice.extension(x0)), axis=-1, initial=0.0))
    return X, speed, energy


def _verlet_step(chain: Chain, X, steps_per_period) -> float:
    """Time step: a fraction of the period of the fastest linearised mode (see module)."""
    lat = chain.lattice
    force = 4.0 * chain.K * X**chain.n  # generous bound on the peak bond force
    k_max = chain.n * chain.K ** (1.0 / chain.n) * force ** ((chain.n - 1.0) / chain.n)
    if chain.K_b is not None:
        k_max = max(k_max, chain.K_b)
    omega_max = 2.0 * np.sqrt(k_max / lat.mass.min())
    return 2.0 * np.pi / omega_max / steps_per_period


def _verlet(lat, x0, u0, t_eval, t_end, dt, g):
    """Velocity Verlet (leapfrog form), sampled at ``t_eval`` by cubic Hermite interpolation."""
    n_steps = max(1, int(np.ceil(t_end / dt)))
    dt = t_end / n_steps
    accelerations_into = lat.stepper(x0.shape[:-1], g)
    x, u = x0.copy(), u0.copy()
    a = np.empty_like(x)
    accelerations_into(x, None, a)
    T = t_eval.size
    xs = np.empty((T, *x.shape))
    us = np.empty((T, *x.shape))
    # Sample j lies in step k(j): t_k < t_j <= t_{k+1} (t_j = 0 is step "-1": the start).
    step_of = np.ceil(t_eval / dt - 1e-9).astype(int) - 1
    theta = t_eval / dt - step_of
    j = 0
    while j < T and step_of[j] < 0:
        xs[j], us[j] = x, u
        j += 1
    half = 0.5 * dt
    u_half = u + half * a  # u at t + dt/2
    kick = np.empty_like(x)
    for k in range(n_steps):
        x_prev, u_prev = (x.copy(), u_half - half * a) if j < T and step_of[j] == k else (None, None)
        np.multiply(u_half, dt, out=kick)
        x += kick
        accelerations_into(x, None, a)
        if x_prev is not None:
            u_now = u_half + half * a
            while j < T and step_of[j] == k:
                s = theta[j]
                h00, h10, h01, h11 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s, -2 * s**3 + 3 * s**2, s**3 - s**2
                d00, d10, d01, d11 = 6 * s**2 - 6 * s, 3 * s**2 - 4 * s + 1, -6 * s**2 + 6 * s, 3 * s**2 - 2 * s
                xs[j] = h00 * x_prev + h10 * dt * u_prev + h01 * x + h11 * dt * u_now
                us[j] = (d00 * x_prev + d01 * x) / dt + d10 * u_prev + d11 * u_now
                j += 1
        np.multiply(a, dt, out=kick)
        u_half += kick
    return xs, us, {"method": "verlet", "dt": dt, "nfev": n_steps + 1}


def _check_t_eval(t_eval, t_end, n_samples):
    if t_eval is None:
        return np.linspace(0.0, t_end, _count_samples(n_samples))
    t_eval = v.as_float("t_eval", t_eval)
    if t_eval.ndim != 1 or t_eval.size < 1:
        raise ValueError("t_eval must be a 1-d array of times")
    if np.any(np.diff(t_eval) <= 0) or t_eval[0] < 0 or t_eval[-1] > t_end:
        raise ValueError("t_eval must be increasing and lie within [0, t_end]")
    return t_eval


def _count_samples(n):
    if int(n) != n or n < 3:
        raise ValueError(f"n_samples must be an integer >= 3, got {n!r}")
    return int(n)


def simulate_batch(
    chain: Chain,
    t_end,
    *,
    impact_velocities=None,
    drop_heights=None,
    gravity=True,
    t_eval=None,
    n_samples=2001,
    method=DEFAULT_METHOD,
    rtol=DEFAULT_RTOL,
    atol=None,
    dt=None,
    steps_per_period=VERLET_STEPS_PER_PERIOD,
    g=STANDARD_GRAVITY,
) -> BatchSimulation:
    """Integrate B runs of one chain together, as one vectorised array problem.

    The B states are stacked into one array of shape (B, n_sites) and advanced by one
    integrator, so the cost per step is that of one right-hand side over B x n_sites
    sites.  With an adaptive method the runs share their steps, chosen for the error
    norm of the whole batch, so each run is at least as accurate as its own tolerance
    asks (scipy's RMS error norm over the batch can only be dominated by the most
    demanding run); the numbers agree with separate :func:`simulate` runs to the
    solver tolerance.

    Parameters
    ----------
    chain : Chain
    t_end : float
        Duration, s.
    impact_velocities, drop_heights : array_like, optional
        One run per value (see :func:`initial_state`).
    gravity, t_eval, n_samples, method, rtol, atol, dt, steps_per_period, g
        As in :func:`simulate` (its "Other Parameters").

    Returns
    -------
    BatchSimulation
        ``contact_force`` of shape (B, len(t), n_rings - 1); ``result[i]`` is run i.
    """
    if not isinstance(chain, Chain):
        raise TypeError(f"chain must be a Chain, got {type(chain).__name__}")
    t_end = float(v.positive("t_end", t_end, "s"))
    t_eval = _check_t_eval(t_eval, t_end, n_samples)
    g = float(v.positive("g", g, "m/s^2"))
    x0, u0 = initial_state(
        chain, impact_velocity=impact_velocities, drop_height=drop_heights, gravity=gravity, g=g
    )
    speeds = -u0[:, 0]
    g_dyn = g if gravity else 0.0
    lat = chain.lattice
    B, S = x0.shape
    X, V, E = _scales(chain, x0, speeds, g)
    if method == "verlet":
        if chain.damped:
            raise ValueError("Verlet integrates undamped chains only (the dashpots make forces depend on velocity)")
        if dt is None:
            dt = _verlet_step(chain, float(X.max()), float(v.positive("steps_per_period", steps_per_period)))
        dt = float(v.positive("dt", dt, "s"))
        xs, us, stats = _verlet(lat, x0, u0, t_eval, t_end, dt, g_dyn)
        xs, us = np.moveaxis(xs, 0, 1), np.moveaxis(us, 0, 1)
        dissipated = np.zeros((B, t_eval.size))
    elif method in ADAPTIVE_METHODS:
        rtol = float(v.positive("rtol", rtol))
        atol_rel = rtol if atol is None else float(v.positive("atol", atol))
        n_w = B if lat.damped else 0
        y0 = np.concatenate([np.stack([x0, u0], axis=-1).ravel(), np.zeros(n_w)])
        per_site = np.repeat(np.stack([X, V], axis=-1), S, axis=0).ravel()  # x, u interleaved, run by run
        atol = atol_rel * np.concatenate([per_site, E[:n_w]])
        rhs = lat.first_order_rhs(B, g_dyn)
        if method == "odeint":
            y, nfev = _odeint(rhs, y0, t_eval, rtol, atol, lat.BANDWIDTH)
        else:
            band = dict(zip(("lband", "uband"), lat.BANDWIDTH, strict=True)) if method == "LSODA" else {}
            sol = solve_ivp(rhs, (0.0, t_end), y0, method=method, t_eval=t_eval, rtol=rtol, atol=atol, **band)
            if not sol.success:
                raise RuntimeError(f"solve_ivp failed: {sol.message}")
            y, nfev = sol.y, sol.nfev
        states = y[: 2 * B * S].reshape(B, S, 2, -1)
        xs = states[:, :, 0, :].transpose(0, 2, 1)
        us = states[:, :, 1, :].transpose(0, 2, 1)
        dissipated = y[2 * B * S :] if lat.damped else np.zeros((B, t_eval.size))
        stats = {"method": method, "rtol": rtol, "nfev": nfev}
    else:
        raise ValueError(f"method must be one of {(*ADAPTIVE_METHODS, 'verlet')}, got {method!r}")
    heights = None if drop_heights is None else np.atleast_1d(np.asarray(drop_heights, dtype=float))
    return BatchSimulation(
        chain=chain, t=t_eval, x=np.ascontiguousarray(xs), u=np.ascontiguousarray(us),
        dissipated=np.ascontiguousarray(dissipated), g=g_dyn, impact_velocity=speeds, drop_height=heights,
        stats=stats,
    )  # fmt: skip


def simulate(chain: Chain, t_end, *, impact_velocity=None, drop_height=None, gravity=True, t_eval=None,
             **options) -> Simulation:  # fmt: skip
    """Integrate a chain after an impact on ring 0 (paper Eqs. power law and dual-spring).

    Parameters
    ----------
    chain : Chain
    t_end : float
        Duration, s; t = 0 is the impact (for a drop: the instant the slack is taken up).
    impact_velocity : float, optional
        Speed of ring 0 moving away from the chain at t = 0, m/s.
    drop_height : float, optional
        Free-fall height of ring 0, m: impact speed sqrt(2 g h) (see the module notes).
    gravity : bool, optional
        Hang the chain from its support under gravity (default) or integrate a chain
        without gravity, starting unstretched.
    t_eval : array_like, optional
        Sample times in [0, t_end], s; default ``n_samples`` evenly spaced.

    Other Parameters
    ----------------
    n_samples : int, optional
        Number of samples when ``t_eval`` is not given; default 2001.
    method : {"odeint", "LSODA", "DOP853", "RK45", "RK23", "verlet"}, optional
        Adaptive integrator: "odeint" (default, :data:`DEFAULT_METHOD`: LSODA stepped in
        Fortran) or a :func:`scipy.integrate.solve_ivp` method; or fixed-step velocity
        Verlet (undamped chains only).
    rtol : float, optional
        Relative tolerance of the adaptive methods; default :data:`DEFAULT_RTOL`.
    atol : float, optional
        Absolute tolerance relative to the run's displacement, velocity and energy
        scales (default ``rtol``).
    dt : float, optional
        Verlet step, s; default a fraction 1/``steps_per_period`` of the period of the
        fastest linearised mode at four times the estimated peak force.  The error of a
        fixed step grows with the distance the wave travels: for hundreds of rings, use
        more steps per period (tests/numerics/test_theory_vs_lattice.py uses 200).
    steps_per_period : float, optional
        See ``dt``; default :data:`VERLET_STEPS_PER_PERIOD`.
    g : float, optional
        Gravity, m/s^2; default :data:`STANDARD_GRAVITY`.

    Returns
    -------
    Simulation
        Times ``t`` (s), ``contact_force`` (len(t), n_rings - 1) in N, sensors, energy.

    Examples
    --------
    >>> chain = Chain.power_law(10, K=1e9, n=1.5, m=0.01, a=0.02, support="free")
    >>> sim = simulate(chain, 2e-4, impact_velocity=0.1, gravity=False)
    >>> sim.contact_force.shape
    (2001, 9)
    >>> bool(sim.contact_force.min() >= 0.0)  # contacts never push
    True
    """
    if np.ndim(impact_velocity) or np.ndim(drop_height):
        raise ValueError("simulate takes one impact; use simulate_batch for several")
    batch = simulate_batch(
        chain, t_end,
        impact_velocities=None if impact_velocity is None else [impact_velocity],
        drop_heights=None if drop_height is None else [drop_height],
        gravity=gravity, t_eval=t_eval, **options,
    )  # fmt: skip
    return batch[0]


# -- results ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class EnergyBudget:
    """Energies of a run, J, each of shape (..., len(t)).

    ``gravity`` is measured from the initial configuration.  Without dashpots,
    ``dissipated`` is zero and ``total`` is conserved; with them, ``total`` (which
    includes the dissipated energy) is conserved and the mechanical energy
    ``total - dissipated`` only decreases.
    """

    kinetic: np.ndarray
    contact: np.ndarray
    bending: np.ndarray
    gravity: np.ndarray
    dissipated: np.ndarray

    @property
    def mechanical(self) -> np.ndarray:
        return self.kinetic + self.contact + self.bending + self.gravity

    @property
    def total(self) -> np.ndarray:
        return self.mechanical + self.dissipated


@dataclass(frozen=True, eq=False)
class _Record:
    """Arrays of one run (shape (T, ...)) or a batch (shape (B, T, ...)) and what they give."""

    chain: Chain
    t: np.ndarray
    x: np.ndarray
    u: np.ndarray
    dissipated: np.ndarray
    g: float
    impact_velocity: np.ndarray | float
    drop_height: np.ndarray | float | None
    stats: dict = field(default_factory=dict, repr=False)

    @functools.cached_property
    def bond_force(self) -> np.ndarray:
        """Force in every lattice bond, N, positive in tension."""
        lat = self.chain.lattice
        e = lat.extension(self.x)
        return lat.bond_forces(e, lat.extension(self.u) if lat.damped else None)

    @property
    def contact_force(self) -> np.ndarray:
        """Force between ring i and ring i+1, N, positive in tension; shape (..., T, n_rings - 1)."""
        return self.bond_force[..., self.chain.contact_bonds]

    @property
    def bending_force(self) -> np.ndarray | None:
        """Force through the body of ring i (dual-spring bending spring and dashpot), N."""
        bonds = self.chain.bending_bonds
        return None if bonds is None else self.bond_force[..., bonds]

    @property
    def support_force(self) -> np.ndarray | None:
        """Force between the top ring and the fixed support, N (None for a free end)."""
        k = self.chain.support_bond
        return None if k is None else self.bond_force[..., k]

    @functools.cached_property
    def sensor_force(self) -> np.ndarray:
        """Force read by a sensor embedded in each ring, N; shape (..., T, n_rings).

        The force carried across the middle of the ring body.  In the dual-spring model
        it is the force of the ring's bending spring (with its dashpot), which joins the
        ring's two halves.  In the power-law model a ring is rigid, and Newton's law for
        its lower half (half the mass and half the weight, the ring being symmetric)
        gives exactly the mean of the forces on its two sides: with F_below, F_above the
        contact forces and T the force at mid-ring, (m/2) a = T - F_below - m_g g/2 and
        m a = F_above - F_below - m_g g, so T = (F_below + F_above)/2.  Ring 0 has no
        force below it; the top ring has the support (or nothing) above it.
        """
        if self.chain.model == "dual-spring":
            return self.bending_force
        f = self.bond_force
        pad = [(0, 0)] * (f.ndim - 1) + [(1, 0 if self.chain.support == "fixed" else 1)]
        padded = np.pad(f, pad)
        return 0.5 * (padded[..., :-1] + padded[..., 1:])

    @property
    def ring_displacement(self) -> np.ndarray:
        """Displacement of the centre of mass of each ring, m; shape (..., T, n_rings)."""
        k = self.chain.sites_per_ring
        return self.x.reshape(*self.x.shape[:-1], -1, k).mean(axis=-1)

    @property
    def ring_velocity(self) -> np.ndarray:
        """Velocity of the centre of mass of each ring, m/s; shape (..., T, n_rings)."""
        k = self.chain.sites_per_ring
        return self.u.reshape(*self.u.shape[:-1], -1, k).mean(axis=-1)

    def energy(self) -> EnergyBudget:
        """Kinetic, contact, bending, gravity and dissipated energy, J (see :class:`EnergyBudget`)."""
        lat = self.chain.lattice
        e = lat.extension(self.x)
        x_start = self.x[..., :1, :]
        return EnergyBudget(
            kinetic=lat.kinetic_energy(self.u),
            contact=lat.contact_energy(e),
            bending=lat.spring_energy(e),
            gravity=lat.gravity_energy(self.x - x_start, self.g),
            dissipated=self.dissipated,
        )


@dataclass(frozen=True, eq=False)
class Simulation(_Record):
    """One run: times ``t`` (s), site displacements ``x`` and velocities ``u`` (T, n_sites).

    Forces are derived on demand: ``contact_force`` (T, n_rings - 1), ``sensor_force``
    (T, n_rings), ``bending_force`` and ``support_force``; the sensor helpers read the
    leading pulse of the sensor force of a ring (:mod:`ringchain.numerics.signals`).
    """

    def sensor(self, ring: int) -> np.ndarray:
        """Sensor force of ring ``ring`` (index from the impact end), N, shape (T,)."""
        return self.sensor_force[:, self._ring(ring)]

    def _ring(self, i) -> int:
        i = int(i)
        if not 0 <= i < self.chain.n_rings:
            raise IndexError(f"ring {i} is not in a chain of {self.chain.n_rings} rings")
        return i

    def peak_force(self, ring: int, threshold=None) -> float:
        """Peak of the leading pulse read by the sensor in ``ring``, N."""
        return signals.peak(self.t, self.sensor(ring), threshold)[1]

    def arrival_time(self, ring: int, threshold=None) -> float:
        """Time of the leading peak at the sensor in ``ring``, s, from the impact."""
        return signals.arrival_time(self.t, self.sensor(ring), threshold)

    def time_of_flight(self, near: int, far: int, threshold=None) -> float:
        """Time between the leading peaks at two sensors, s."""
        return signals.time_of_flight(self.t, self.sensor(near), self.sensor(far), threshold)

    def wave_speed(self, near: int, far: int, threshold=None) -> float:
        """(far - near) a over the time of flight, m/s (as measured in the paper)."""
        distance = (self._ring(far) - self._ring(near)) * self.chain.a
        return signals.wave_speed(self.t, self.sensor(near), self.sensor(far), distance, threshold)

    def pulse_width(self, ring: int, threshold=None) -> float:
        """Full width at half maximum of the leading pulse at the sensor in ``ring``, s."""
        return signals.pulse_width(self.t, self.sensor(ring), threshold)

    def to_csv(self, path) -> None:
        """Write t (s), the contact forces and the support force (N) as CSV columns."""
        columns = {"t_s": self.t}
        for i in range(self.chain.n_rings - 1):
            columns[f"contact_{i}_{i + 1}_N"] = self.contact_force[:, i]
        if self.support_force is not None:
            columns["support_N"] = self.support_force
        with open(path, "w", newline="") as handle:
            writer = csv.writer(handle)
            writer.writerow(columns)
            writer.writerows(np.column_stack(list(columns.values())).tolist())


@dataclass(frozen=True, eq=False)
class BatchSimulation(_Record):
    """B runs of one chain: arrays of shape (B, T, ...); ``result[i]`` is run i as a :class:`Simulation`."""

    def __len__(self) -> int:
        return self.x.shape[0]

    def __getitem__(self, i) -> Simulation:
        i = range(len(self))[i]
        return Simulation(
            chain=self.chain, t=self.t, x=self.x[i], u=self.u[i], dissipated=self.dissipated[i], g=self.g,
            impact_velocity=float(self.impact_velocity[i]),
            drop_height=None if self.drop_height is None else float(self.drop_height[i]), stats=self.stats,
        )  # fmt: skip

    def __iter__(self):
        return (self[i] for i in range(len(self)))


# -- the paper's experiment -------------------------------------------------------------------
@dataclass(frozen=True)
class PaperExperiment:
    """What the paper measured on its 20-ring chain, for one drop and one model.

    Attributes
    ----------
    model : str
    drop_height : float
        m.
    impact_velocity : float
        sqrt(2 g h), m/s.
    sensors : tuple of int
        Rings holding the sensors, counted from the impact (ring 0 is the dropped ring).
    peak_forces : tuple of float
        Leading-pulse peak at each sensor, N.
    arrival_times : tuple of float
        Leading-pulse peak times, s after the impact.
    time_of_flight : float
        Between the two sensors, s.
    wave_speed : float
        Sensor distance over time of flight, m/s.
    simulation : Simulation
    """

    model: str
    drop_height: float
    impact_velocity: float
    sensors: tuple
    peak_forces: tuple
    arrival_times: tuple
    time_of_flight: float
    wave_speed: float
    simulation: Simulation = field(repr=False)


def paper_experiment(
    drop_height, model="power-law", *, t_end=2e-3, sensors=paper_data.SENSOR_RINGS, **options
) -> PaperExperiment:
    """Simulate the paper's drop experiment (Sec. III) and read its two sensors.

    The chain is :meth:`Chain.from_paper` for R/r = 9 (Table I: K = 2284 N/mm^n,
    n = 1.11, m_eff/m0 = 0.37; the dual-spring model takes K_c and K_b of that ring),
    20 rings hanging under gravity from a fixed support, sensors in rings 6 and 12.

    Parameters
    ----------
    drop_height : float
        Free-fall height of the lowest ring, m.
    model : {"power-law", "dual-spring"}
    t_end : float, optional
        Duration, s (default 2 ms: the leading pulse passes ring 12 within about 1 ms for
        drops of 1 mm and more).
    sensors : tuple of int, optional
        Two rings, from the impact.
    **options
        Passed to :func:`simulate` (e.g. ``method``, ``rtol``); ``gamma``/``gamma_c``/
        ``gamma_b`` are passed to :meth:`Chain.from_paper`.

    Returns
    -------
    PaperExperiment

    Examples
    --------
    >>> run = paper_experiment(0.05, "power-law")
    >>> 10 < run.peak_forces[0] < 1000, 1e-4 < run.time_of_flight < 1e-3  # N, s
    (True, True)
    """
    dashpots = {k: options.pop(k) for k in ("gamma", "gamma_c", "gamma_b") if k in options}
    chain = Chain.from_paper(model, **dashpots)
    sim = simulate(chain, t_end, drop_height=drop_height, gravity=True, **options)
    near, far = sensors
    return PaperExperiment(
        model=model, drop_height=float(drop_height), impact_velocity=float(sim.impact_velocity),
        sensors=(near, far), peak_forces=(sim.peak_force(near), sim.peak_force(far)),
        arrival_times=(sim.arrival_time(near), sim.arrival_time(far)), time_of_flight=sim.time_of_flight(near, far),
        wave_speed=sim.wave_speed(near, far), simulation=sim,
    )  # fmt: skip
