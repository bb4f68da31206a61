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

Any other state (a wave packet on a pre-stretched chain, say) is given as
``initial=(x0, u0)``, the site displacements and velocities.

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
A batch of runs of one chain is integrated as one array problem (:func:`simulate_batch`); so are
several chains of one layout, one run each, their lattices stacked
(:meth:`~ringchain.numerics.models.Lattice.stack`; the trace fits of :mod:`~ringchain.numerics.fit`).

Checks.  The settings are validated before any work: ``dt`` must lie below the stability
limit 2/omega_max of velocity Verlet (omega_max, the fastest linearised mode at four
times the estimated peak force, :func:`_verlet_step`), ``steps_per_period`` above pi, and
the tolerances within :data:`TOLERANCE_RANGE`.  The memory the run keeps and, for
Verlet, its work (steps x sites x runs) are estimated first (:func:`estimate_run`); a
run that would not fit in the memory available, or would take hours, is refused with a
message saying how to make it smaller (``rings``: record only the rings read;
``n_samples``).  During the run the energy budget is watched: a state that turns
non-finite, or a total energy (dissipated energy included) that drifts from its
initial value by more than ``max_energy_drift`` times the impact energy, stops the run
with an :class:`IntegrationError` rather than returning an unstable result.
"""

from __future__ import annotations

import csv
import functools
import math
import os
import warnings
from dataclasses import dataclass, field

import numpy as np
from ringchain.theory import _validate as v
from scipy.integrate import ODEintWarning, odeint, solve_ivp

from . import signals
from .chain import Chain, _flag, _integer
from .models import STANDARD_GRAVITY

__all__ = [
    "simulate",
    "simulate_batch",
    "initial_state",
    "Simulation",
    "BatchSimulation",
    "EnergyBudget",
    "RunEstimate",
    "estimate_run",
    "IntegrationError",
    "RunTooLargeError",
    "ADAPTIVE_METHODS",
    "DEFAULT_METHOD",
    "DEFAULT_RTOL",
    "VERLET_STEPS_PER_PERIOD",
    "TOLERANCE_RANGE",
    "ENERGY_DRIFT_LIMIT",
    "DEFAULT_MAX_SECONDS",
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


#: Range of ``rtol`` of the adaptive methods (``atol``, relative to the run's scales, may
#: not exceed its top).  Below 1e-13 LSODA refuses the tolerance as beyond double
#: precision ("illegal input" at 1e-14) and scipy's Runge-Kutta methods raise it to
#: 2.2e-14; above 1e-3 the error control no longer controls: over 2 ms of the paper's
#: chain, rtol = 1e-3 leaves sensor errors of 3-8% of the peak and 1e-2 of 15-28%
#: (measured against rtol = 1e-12; tests/numerics/test_solve.py checks the range's ends).
TOLERANCE_RANGE = (1e-13, 1e-3)

#: Largest drift of the total energy (dissipated energy included) from its initial
#: value, as a fraction of the impact energy m v^2/2, before a run is stopped as unstable
#: or inaccurate.  The default settings drift by ~1e-8 (LSODA) and ~1e-4 (Verlet, 60 steps
#: per period); an unstable Verlet step grows without bound; rtol = 1e-2 drifts by 7-19%.
ENERGY_DRIFT_LIMIT = 1e-2

#: Estimated duration (s) above which a run is refused unless ``max_seconds`` is raised
#: (:func:`estimate_run`).
DEFAULT_MAX_SECONDS = 3600.0

# Rough cost of one Verlet step: a fixed overhead plus a cost per site and run, measured on
# a 2-core machine (benchmarks/bench_batch.py gives this machine's numbers); only used to
# turn a number of steps into an order of magnitude of seconds.
_SECONDS_PER_STEP = 1.5e-5
_SECONDS_PER_SITE_STEP = 2e-8

# Most LSODA steps between two samples (odeint's mxstep); a run that needs more fails.
_MAX_STEPS_PER_SAMPLE = 1_000_000

# Most bytes of full states one adaptive solver call returns; longer records are
# integrated in consecutive chunks of samples (the solver restarts at each chunk).
_CHUNK_BYTES = 256 * 2**20


class IntegrationError(ValueError):
    """The integrator failed, or its result is unstable (non-finite, or the energy drifted)."""


class RunTooLargeError(ValueError):
    """A run that would need more memory or time than allowed; the message says how to shrink it."""


def _odeint(rhs, y0, t0, times, rtol, atol, bandwidth):
    """LSODA through :func:`scipy.integrate.odeint` from state ``y0`` at ``t0``.

    Returns the states at ``times`` (shape (len(y0), len(times))) and the number of
    right-hand-side calls.  odeint's first output time is its initial time, so ``t0`` is
    put in front of ``times`` when they start later and its row dropped.  The Jacobian is
    banded, as for solve_ivp's LSODA.  A failure raises :class:`IntegrationError` with
    ODEPACK's reason.
    """
    lower, upper = bandwidth
    prepend = times[0] > t0
    grid = np.concatenate([[t0], times]) if prepend else times
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ODEintWarning)  # its message is in the error below
        y, info = odeint(
            rhs, y0, grid, rtol=rtol, atol=atol, ml=lower, mu=upper, tfirst=True, full_output=True,
            mxstep=_MAX_STEPS_PER_SAMPLE,
        )  # fmt: skip
    if info["message"] != "Integration successful.":
        raise IntegrationError(
            f"odeint (LSODA) failed between t = {t0:g} s and {grid[-1]:g} s: {info['message']} "
            f"(rtol = {rtol:g}); the chain may be too stiff for these tolerances: try method='verlet', "
            "a larger rtol or atol, or more samples"
        )
    return y[int(prepend) :].T, int(info["nfe"][-1])


# -- initial conditions ---------------------------------------------------------------------
def _impact_speeds(impact_velocities, drop_heights, g):
    if impact_velocities is not None and drop_heights is not None:
        raise ValueError("give an impact velocity or a drop height, not both")
    for name, values, unit in (("drop_height", drop_heights, "m"), ("impact_velocity", impact_velocities, "m/s")):
        if values is None:
            continue
        values = np.atleast_1d(v.nonnegative(name, values, unit))
        if values.ndim != 1 or values.size == 0:
            raise ValueError(f"{name} must be one value or a 1-d array of values (one per run), got shape "
                             f"{values.shape}")  # fmt: skip
        return (np.sqrt(2.0 * g * values), True) if name == "drop_height" else (values, False)
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
    gravity = _flag("gravity", gravity)
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
    speed = np.maximum(speeds, max(1e-3 * np.sqrt(g * np.min(chain.a)), 1e-9))
    energy = 0.25 * np.max(chain.m) * speed**2

    # Along a chain that changes, the largest scale over its contacts and rings (the uniform
    # chain's numbers are used as they are: the same arithmetic as before arrays existed).
    def largest(values):
        return values if chain.uniform else np.max(values, axis=-1)

    along = energy if chain.uniform else energy[..., None]
    X = largest(((chain.n + 1.0) * along / chain.K) ** (1.0 / (chain.n + 1.0)))
    if chain.K_b is not None:
        X = X + largest(np.sqrt(2.0 * along / chain.K_b))
    X = np.maximum(X, np.max(np.abs(chain.lattice.extension(x0)), axis=-1, initial=0.0))
    return X, speed, energy


def _verlet_step(chain: Chain, X, steps_per_period) -> float:
    """Time step: a fraction of the period of the fastest linearised mode (see module)."""
    lat = chain.lattice
    force = 4.0 * chain.K * X**chain.n  # generous bound on the peak bond force
    k_max = np.max(chain.n * chain.K ** (1.0 / chain.n) * force ** ((chain.n - 1.0) / chain.n))
    if chain.K_b is not None:
        k_max = max(k_max, np.max(chain.K_b))
    omega_max = 2.0 * np.sqrt(k_max / lat.mass.min())
    return 2.0 * np.pi / omega_max / steps_per_period


def _energy_budget(lat, x, u, x_start, g, dissipated) -> EnergyBudget:
    """Energies of states x, u (shape (..., n_sites)), gravity measured from ``x_start``."""
    e = lat.extension(x)
    return EnergyBudget(
        kinetic=lat.kinetic_energy(u),
        contact=lat.contact_energy(e),
        bending=lat.spring_energy(e),
        gravity=lat.gravity_energy(x - x_start, g),
        dissipated=dissipated,
    )


class _EnergyWatch:
    """Stops a run whose state turns non-finite or whose total energy drifts (module notes)."""

    def __init__(self, lat, x0, u0, g, scale, limit, advice):
        self.lat, self.x0, self.g, self.scale, self.limit, self.advice = lat, x0, g, scale, limit, advice
        self.initial = _energy_budget(lat, x0, u0, x0, g, 0.0).total

    def __call__(self, t, x, u, dissipated=0.0):
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(u))):
            raise IntegrationError(f"the state became non-finite by t = {t:g} s: the integration is unstable; "
                                   f"{self.advice}")  # fmt: skip
        if self.limit is None:
            return
        total = _energy_budget(self.lat, x, u, self.x0, self.g, dissipated).total
        drift = float(np.max(np.abs(total - self.initial) / self.scale))
        if not drift <= self.limit:
            raise IntegrationError(
                f"the total energy drifted by {drift:.3g} times the impact energy by t = {t:g} s "
                f"(max_energy_drift = {self.limit:g}): the integration is unstable or inaccurate; {self.advice}"
            )


#: Energy checks per Verlet run (each costs about one step).
_WATCHES = 16


def _verlet(lat, x0, u0, t_eval, t_end, dt, g, keep, watch):
    """Velocity Verlet (leapfrog form), sampled at ``t_eval`` by cubic Hermite interpolation.

    Returns x and u of the sites ``keep`` (all if None), shape (B, len(t_eval), K), and stats.
    """
    n_steps = max(1, math.ceil(t_end / dt))
    dt = t_end / n_steps
    accelerations_into = lat.stepper(x0.shape[:-1], g)
    x, u = x0.copy(), u0.copy()
    a = np.empty_like(x)
    accelerations_into(x, None, a)
    sel = slice(None) if keep is None else keep
    T = t_eval.size
    xs = np.empty((x.shape[0], T, x[:, sel].shape[-1]))
    us = np.empty_like(xs)
    # Sample j lies in step k(j): t_k < t_j <= t_{k+1} (t_j = 0 is step "-1": the start).
    step_of = np.ceil(t_eval / dt - 1e-9).astype(int) - 1
    theta = t_eval / dt - step_of
    j = 0
    while j < T and step_of[j] < 0:
        xs[:, j], us[:, j] = x[:, sel], u[:, sel]
        j += 1
    half = 0.5 * dt
    u_half = u + half * a  # u at t + dt/2
    kick = np.empty_like(x)
    check_every = max(1, n_steps // _WATCHES)
    for k in range(n_steps):
        sampling = j < T and step_of[j] == k
        if sampling:
            x_prev, u_prev = x[:, sel].copy(), u_half[:, sel] - half * a[:, sel]
        np.multiply(u_half, dt, out=kick)
        x += kick
        accelerations_into(x, None, a)
        if sampling:
            x_now, u_now = x[:, sel], u_half[:, sel] + half * a[:, sel]
            while j < T and step_of[j] == k:
                s = theta[j]
                h00, h10, h01, h11 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s, -2 * s**3 + 3 * s**2, s**3 - s**2
                d00, d10, d01, d11 = 6 * s**2 - 6 * s, 3 * s**2 - 4 * s + 1, -6 * s**2 + 6 * s, 3 * s**2 - 2 * s
                xs[:, j] = h00 * x_prev + h10 * dt * u_prev + h01 * x_now + h11 * dt * u_now
                us[:, j] = (d00 * x_prev + d01 * x_now) / dt + d10 * u_prev + d11 * u_now
                j += 1
        if (k + 1) % check_every == 0 or k == n_steps - 1:
            watch((k + 1) * dt, x, u_half + half * a)
        np.multiply(a, dt, out=kick)
        u_half += kick
    return xs, us, {"method": "verlet", "dt": dt, "nfev": n_steps + 1}


def _solve_ivp(rhs, method, y0, t0, times, rtol, atol, bandwidth):
    """A :func:`scipy.integrate.solve_ivp` method from ``y0`` at ``t0``: (states at ``times``, nfev)."""
    band = dict(zip(("lband", "uband"), bandwidth, strict=True)) if method == "LSODA" else {}
    sol = solve_ivp(rhs, (t0, times[-1]), y0, method=method, t_eval=times, rtol=rtol, atol=atol, **band)
    if not sol.success:
        raise IntegrationError(
            f"solve_ivp ({method}) stopped before t = {times[-1]:g} s: {sol.message} (rtol = {rtol:g}); "
            "try method='odeint' or 'verlet', or other tolerances"
        )
    return sol.y, sol.nfev


def _adaptive(method, lat, x0, u0, scales, t_eval, rtol, atol, g, keep, watch):
    """An adaptive method over ``t_eval``, in chunks of samples of at most :data:`_CHUNK_BYTES` of states.

    ``x0``, ``u0`` (shape (B, n_sites)) start the B runs of ``lat`` (of one chain, or of a
    :meth:`~ringchain.numerics.models.Lattice.stack` of B chains, one run each);
    ``scales`` = (X, V, E) of each run (:func:`_scales`) times ``atol`` are the absolute
    tolerances of its displacements, velocities and dissipated energy.  Returns x and u of
    the sites ``keep`` (all if None), shape (B, T, K), the dissipated energy (B, T) and stats.
    """
    B, S, T = *x0.shape, t_eval.size
    X, V, E = scales
    n_w = B if lat.damped else 0
    y0 = np.concatenate([np.stack([x0, u0], axis=-1).ravel(), np.zeros(n_w)])
    per_site = np.repeat(np.stack([X, V], axis=-1), S, axis=0).ravel()  # x, u interleaved, run by run
    atol = atol * np.concatenate([per_site, E[:n_w]])
    rhs = lat.first_order_rhs(B, g)
    n_xu = 2 * B * S
    sel = slice(None) if keep is None else keep
    K = S if keep is None else keep.size
    xs, us = np.empty((B, T, K)), np.empty((B, T, K))
    dissipated = np.zeros((B, T))
    chunk = max(1, _CHUNK_BYTES // (8 * y0.size))
    t_prev, y_prev, nfev = 0.0, y0, 0
    for j0 in range(0, T, chunk):
        times = t_eval[j0 : j0 + chunk]
        if times[-1] <= t_prev:  # only the initial state is asked for
            y, calls = y_prev[:, None], 0
        elif method == "odeint":
            y, calls = _odeint(rhs, y_prev, t_prev, times, rtol, atol, lat.BANDWIDTH)
        else:
            y, calls = _solve_ivp(rhs, method, y_prev, t_prev, times, rtol, atol, lat.BANDWIDTH)
        nfev += calls
        states = y[:n_xu].reshape(B, S, 2, -1)
        xs[:, j0 : j0 + times.size] = states[:, sel, 0, :].transpose(0, 2, 1)
        us[:, j0 : j0 + times.size] = states[:, sel, 1, :].transpose(0, 2, 1)
        if y.shape[0] > n_xu:
            dissipated[:, j0 : j0 + times.size] = y[n_xu:]
        y_prev, t_prev = y[:, -1].copy(), float(times[-1])
        watch(t_prev, states[:, :, 0, -1], states[:, :, 1, -1], y[n_xu:, -1] if y.shape[0] > n_xu else 0.0)
    return xs, us, dissipated, {"method": method, "rtol": rtol, "nfev": nfev}


def _check_t_eval(t_eval, t_end, n_samples):
    if t_eval is None:
        return np.linspace(0.0, t_end, _count_samples(n_samples))
    t_eval = v.as_float("t_eval", t_eval)
    if t_eval.ndim != 1 or t_eval.size < 1:
        raise ValueError(f"t_eval must be a 1-d array of times, got shape {t_eval.shape}")
    if np.any(np.diff(t_eval) <= 0) or t_eval[0] < 0 or t_eval[-1] > t_end:
        raise ValueError(f"t_eval must be increasing and lie within [0, t_end] = [0, {t_end:g}] s")
    return t_eval


def _count_samples(n):
    n = _integer("n_samples", n)
    if n < 3:
        raise ValueError(f"n_samples must be at least 3, got {n}")
    return n


def _rtol(value) -> float:
    value = float(v.as_float("rtol", value))
    low, high = TOLERANCE_RANGE
    if not low <= value <= high:
        raise ValueError(
            f"rtol must lie in [{low:g}, {high:g}], got {value:g}: below, the tolerance is beyond double precision; "
            "above, the error control no longer controls (TOLERANCE_RANGE)"
        )
    return value


# -- what a run will cost ----------------------------------------------------------------------
@dataclass(frozen=True)
class RunEstimate:
    """What a run will take, estimated before it starts (:func:`estimate_run`).

    Attributes
    ----------
    method : str
    runs, sites, samples : int
        Runs of the batch, lattice sites of the chain, samples of the record.
    recorded_sites : int
        Sites whose x and u are kept (all, or those the sensors of ``rings`` need).
    steps : int or None
        Verlet steps (None for an adaptive method, which chooses them as it goes).
    dt : float or None
        Verlet step, s.
    memory : int
        Bytes: the record (x, u and the dissipated energy), the forces derived from it,
        and the solver's own arrays.
    """

    method: str
    runs: int
    sites: int
    samples: int
    recorded_sites: int
    steps: int | None
    dt: float | None
    memory: int

    @property
    def work(self) -> int | None:
        """Steps x sites x runs (Verlet), or None."""
        return None if self.steps is None else self.steps * self.sites * self.runs

    @property
    def seconds(self) -> float | None:
        """Rough duration of a Verlet run, s, at the per-step costs measured on a 2-core machine."""
        if self.steps is None:
            return None
        return self.steps * (_SECONDS_PER_STEP + _SECONDS_PER_SITE_STEP * self.sites * self.runs)

    def describe(self, memory=True) -> str:
        """One line: the run's size, work, rough duration and (unless ``memory`` is False) memory."""
        size = f"{self.runs} run(s) x {self.sites} sites x {self.samples} samples"
        work = "" if self.steps is None else (
            f", {self.steps:.3g} Verlet steps of {self.dt:.3g} s = {self.work:.3g} site-steps (roughly "
            f"{_duration(self.seconds)})")  # fmt: skip
        return f"{size}{work}" + (f", {_bytes(self.memory)} of memory" if memory else "")


def _bytes(n) -> str:
    for unit, size in (("GB", 2**30), ("MB", 2**20), ("kB", 2**10)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n:.0f} B"


def _duration(seconds) -> str:
    for unit, size in (("days", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= size:
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.3g} s"


def _available_memory() -> int | None:
    """Bytes of memory this process can still take: MemAvailable, capped by ulimit -v and a cgroup limit.

    None if none of them can be read.
    """
    available = None
    try:
        with open("/proc/meminfo") as handle:
            for line in handle:
                if line.startswith("MemAvailable:"):
                    available = int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        try:
            available = os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
        except (OSError, ValueError, AttributeError):
            pass
    try:  # an address-space limit (ulimit -v) less what the process already maps
        import resource

        soft, _ = resource.getrlimit(resource.RLIMIT_AS)
        if soft != resource.RLIM_INFINITY:
            with open("/proc/self/statm") as handle:
                mapped = int(handle.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
            available = soft - mapped if available is None else min(available, soft - mapped)
    except (ImportError, OSError, ValueError):
        pass
    try:
        with open("/sys/fs/cgroup/memory.max") as handle:
            limit = handle.read().strip()
        with open("/sys/fs/cgroup/memory.current") as handle:
            used = int(handle.read().strip())
        if limit != "max":
            free = int(limit) - used
            available = free if available is None else min(available, free)
    except (OSError, ValueError):
        pass
    return available


def _sensor_bonds(chain: Chain, rings: np.ndarray):
    """Bonds read by the sensors of ``rings`` and their weights, each of shape (len(rings), 2).

    The dual-spring sensor is ring j's bending bond 2j; the power-law sensor is the mean
    of the bonds below (j - 1) and above (j) ring j (see :attr:`Simulation.sensor_force`).
    A bond that does not exist (below ring 0, above a free top ring) has weight 0.
    """
    rings = np.asarray(rings, dtype=int)
    if chain.model == "dual-spring":
        bonds = np.stack([2 * rings, 2 * rings], axis=-1)
        weights = np.broadcast_to([1.0, 0.0], bonds.shape)
        return bonds, weights
    n_bonds = chain.lattice.n_bonds
    below, above = rings - 1, rings
    has_below, has_above = below >= 0, above < n_bonds
    bonds = np.stack([np.where(has_below, below, above), np.where(has_above, above, below)], axis=-1)
    weights = 0.5 * np.stack([has_below, has_above], axis=-1)
    return bonds, weights


def _ring_index(chain: Chain, ring) -> int:
    i = _integer("ring", ring)
    if not 0 <= i < chain.n_rings:
        raise ValueError(f"ring {i} is not in a chain of {chain.n_rings} rings (0..{chain.n_rings - 1})")
    return i


def _sensor_pair(sensors, n_rings=None) -> tuple[int, int]:
    """Two sensor rings, near then far from the impact, within ``n_rings`` if given (ValueError saying why)."""
    if isinstance(sensors, str) or np.ndim(sensors) != 1 or len(sensors) != 2:
        raise ValueError(f"sensors must be two rings, near then far from the impact, got {sensors!r}")
    near, far = (_integer("sensor ring", s) for s in sensors)
    if not 0 <= near < far:
        raise ValueError(f"sensors must be two rings, near then far, counted from 0, got {tuple(sensors)!r}")
    if n_rings is not None and far >= n_rings:
        raise ValueError(f"sensor ring {far} is not in a chain of {n_rings} rings (0..{n_rings - 1})")
    return near, far


def _rings(chain: Chain, rings) -> tuple | None:
    """The rings to record, sorted, or None for all."""
    if rings is None:
        return None
    values = [rings] if np.ndim(rings) == 0 else list(rings)
    if not values:
        raise ValueError("rings must name at least one ring (or be None for every ring)")
    return tuple(sorted({_ring_index(chain, r) for r in values}))


def _recorded_sites(chain: Chain, rings) -> np.ndarray | None:
    """Sites whose x and u the sensors of ``rings`` need (sorted), or None for every site."""
    if rings is None:
        return None
    bonds, weights = _sensor_bonds(chain, np.array(rings))
    used = bonds[weights > 0]
    sites = np.concatenate([used, used + 1])
    return np.unique(sites[sites < chain.n_sites])


def _initial_arrays(chain: Chain, initial):
    """``initial = (x0, u0)`` validated and stacked into two arrays of shape (B, n_sites)."""
    try:
        x0, u0 = initial
    except (TypeError, ValueError):
        raise TypeError("initial must be a pair (x0, u0): site displacements (m) and velocities (m/s)") from None
    arrays = []
    for name, value in (("displacements x0", x0), ("velocities u0", u0)):
        array = v.as_float(f"initial {name}", value)
        if array.ndim not in (1, 2) or array.shape[-1] != chain.n_sites:
            raise ValueError(
                f"initial {name} must have shape (n_sites,) or (B, n_sites) with n_sites = {chain.n_sites}, "
                f"got {array.shape}"
            )
        arrays.append(np.atleast_2d(array))
    try:
        x0, u0 = np.broadcast_arrays(*arrays)
    except ValueError:
        raise ValueError(
            f"initial displacements and velocities give different numbers of runs: {arrays[0].shape[0]} and "
            f"{arrays[1].shape[0]}"
        ) from None
    return np.array(x0, dtype=float), np.array(u0, dtype=float)


def _prepare(chain, t_end, impact_velocities, drop_heights, gravity, t_eval, n_samples, method, rtol, atol, dt,
             steps_per_period, g, rings, initial=None):  # fmt: skip
    """Validate a run's inputs and estimate its cost; returns (RunEstimate, everything the run needs)."""
    if not isinstance(chain, Chain):
        raise TypeError(f"chain must be a Chain, got {type(chain).__name__}")
    t_end = float(v.positive("t_end", t_end, "s"))
    t_eval = _check_t_eval(t_eval, t_end, n_samples)
    g = float(v.positive("g", g, "m/s^2"))
    gravity = _flag("gravity", gravity)
    if not isinstance(method, str) or method not in (*ADAPTIVE_METHODS, "verlet"):
        raise ValueError(f"method must be one of {(*ADAPTIVE_METHODS, 'verlet')}, got {method!r}")
    if initial is None:
        x0, u0 = initial_state(chain, impact_velocity=impact_velocities, drop_height=drop_heights, gravity=gravity, g=g)
    elif impact_velocities is not None or drop_heights is not None:
        raise ValueError("give an initial state or an impact (impact_velocities, drop_heights), not both")
    else:
        x0, u0 = _initial_arrays(chain, initial)
    B, S = x0.shape
    scales = _scales(chain, x0, np.max(np.abs(u0), axis=-1), g)  # = the impact speeds for an impact
    rings = _rings(chain, rings)
    keep = _recorded_sites(chain, rings)
    K = S if keep is None else keep.size
    T = t_eval.size
    steps = None
    if method == "verlet":
        if chain.damped:
            raise ValueError("Verlet integrates undamped chains only (the dashpots make forces depend on velocity)")
        X = float(scales[0].max())
        limit = _verlet_step(chain, X, np.pi)  # 2/omega_max: the stability limit of velocity Verlet
        if dt is None:
            sp = float(v.as_float("steps_per_period", steps_per_period))
            if not sp > np.pi:
                raise ValueError(
                    f"steps_per_period must exceed pi, the stability limit of velocity Verlet (omega dt < 2), "
                    f"got {sp:g} (default {VERLET_STEPS_PER_PERIOD})"
                )
            dt = _verlet_step(chain, X, sp)
        else:
            dt = float(v.positive("dt", dt, "s"))
            if dt >= limit:
                raise ValueError(
                    f"dt = {dt:g} s is above the stability limit of velocity Verlet on this chain, 2/omega_max = "
                    f"{limit:.3g} s (omega_max: the fastest linearised mode at four times the estimated peak force); "
                    f"the default step is {_verlet_step(chain, X, VERLET_STEPS_PER_PERIOD):.3g} s"
                )
        steps = max(1, math.ceil(t_end / dt))
        solver = 8 * 12 * B * S  # state, accelerations, work arrays of the stepper
    else:
        rtol = _rtol(rtol)
        atol = rtol if atol is None else float(v.in_range("atol", atol, 0.0, TOLERANCE_RANGE[1]))
        n_state = 2 * B * S + (B if chain.lattice.damped else 0)
        solver = 8 * n_state * (2 * min(T, max(1, _CHUNK_BYTES // (8 * n_state))) + 30)  # output, copies, LSODA
    derived = (chain.lattice.n_bonds if rings is None else 2 * len(rings)) * 8 * B * T  # forces derived later
    memory = 8 * B * T * (2 * K + 1) + derived + solver
    estimate = RunEstimate(method, B, S, T, K, steps, dt, int(memory))
    prepared = dict(t_end=t_end, t_eval=t_eval, g=g, gravity=gravity, x0=x0, u0=u0, scales=scales, rings=rings,
                    keep=keep, dt=dt, rtol=rtol, atol=atol)  # fmt: skip
    return estimate, prepared


def estimate_run(chain: Chain, t_end, *, impact_velocities=None, drop_heights=None, gravity=True, t_eval=None,
                 n_samples=2001, method=DEFAULT_METHOD, rtol=DEFAULT_RTOL, atol=None, dt=None,
                 steps_per_period=VERLET_STEPS_PER_PERIOD, g=STANDARD_GRAVITY, rings=None,
                 initial=None) -> RunEstimate:  # fmt: skip
    """Size, memory and (for Verlet) work and rough duration of a run, before running it.

    Takes the arguments of :func:`simulate_batch` and validates them as it does.

    Returns
    -------
    RunEstimate
        ``memory`` in bytes; ``steps``, ``work`` (steps x sites x runs) and a rough
        ``seconds`` for Verlet; ``describe()`` puts them in one line.

    Examples
    --------
    >>> chain = Chain.dual_spring(100_000, K_c=7.5e9, K_b=3.3e6, m=8.2e-3, a=0.04)
    >>> full = estimate_run(chain, 2e-3, drop_heights=0.05, method="verlet")
    >>> sensors = estimate_run(chain, 2e-3, drop_heights=0.05, method="verlet", rings=[6, 12])
    >>> round(full.memory / 2**30, 1), round(sensors.memory / 2**20, 1)  # GB, MB
    (9.0, 18.5)
    """
    return _prepare(chain, t_end, impact_velocities, drop_heights, gravity, t_eval, n_samples, method, rtol, atol,
                    dt, steps_per_period, g, rings, initial)[0]  # fmt: skip


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
    rings=None,
    max_memory=None,
    max_seconds=DEFAULT_MAX_SECONDS,
    max_energy_drift=ENERGY_DRIFT_LIMIT,
    initial=None,
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
    gravity, t_eval, n_samples, method, rtol, atol, dt, steps_per_period, g, rings, max_memory, max_seconds, \
max_energy_drift
        As in :func:`simulate` (its "Other Parameters").
    initial : (array_like, array_like), optional
        Any initial state instead of an impact: site displacements x0 (m) and velocities
        u0 (m/s), each of shape (n_sites,) or (B, n_sites) (one run per row; a single row
        is shared), as in :func:`initial_state`; ``gravity`` then only says whether
        gravity acts.  Not together with ``impact_velocities`` or ``drop_heights``.

    Returns
    -------
    BatchSimulation
        ``contact_force`` of shape (B, len(t), n_rings - 1); ``result[i]`` is run i.

    Raises
    ------
    RunTooLargeError
        If the run would need more memory than ``max_memory`` or longer than ``max_seconds``.
    IntegrationError
        If the integrator fails, or the run turns unstable (see the module notes).
    """
    estimate, run = _prepare(chain, t_end, impact_velocities, drop_heights, gravity, t_eval, n_samples, method, rtol,
                             atol, dt, steps_per_period, g, rings, initial)  # fmt: skip
    _check_size(estimate, run["rings"], max_memory, max_seconds)
    if max_energy_drift is not None:
        max_energy_drift = float(v.positive("max_energy_drift", max_energy_drift))
    lat = chain.lattice
    x0, u0, t_eval = run["x0"], run["u0"], run["t_eval"]
    B = x0.shape[0]
    E = run["scales"][2]
    g_dyn = run["g"] if run["gravity"] else 0.0
    advice = ("take a smaller dt or more steps_per_period" if method == "verlet" else
              "take a smaller rtol (and atol), or method='verlet'")  # fmt: skip
    watch = _EnergyWatch(lat, x0, u0, g_dyn, 2.0 * E, max_energy_drift, advice)  # 2 E = m v^2 / 2
    with np.errstate(over="ignore", invalid="ignore"):  # an unstable run is reported by the watch
        if method == "verlet":
            xs, us, stats = _verlet(lat, x0, u0, t_eval, run["t_end"], run["dt"], g_dyn, run["keep"], watch)
            dissipated = np.zeros((B, t_eval.size))
        else:
            xs, us, dissipated, stats = _adaptive(method, lat, x0, u0, run["scales"], t_eval, run["rtol"], run["atol"],
                                                  g_dyn, run["keep"], watch)  # fmt: skip
    heights = None if drop_heights is None else np.atleast_1d(np.asarray(drop_heights, dtype=float))
    return BatchSimulation(
        chain=chain, t=t_eval, x=xs, u=us, dissipated=dissipated, g=g_dyn, impact_velocity=-u0[:, 0],
        drop_height=heights, stats=stats, rings=run["rings"],
    )  # fmt: skip


def _check_size(estimate: RunEstimate, rings, max_memory, max_seconds):
    """Refuse a run larger than the memory available or longer than ``max_seconds`` (RunTooLargeError)."""
    limit = _available_memory() if max_memory is None else int(v.positive("max_memory", max_memory, "bytes"))
    if limit is not None and estimate.memory > limit:
        smaller = "" if rings is not None else (
            "; record only the rings you read (rings=[...]: the sensors need 1-3 rings' sites each)")  # fmt: skip
        raise RunTooLargeError(
            f"this run needs about {_bytes(estimate.memory)} of memory ({estimate.describe(memory=False)}), more "
            f"than the {_bytes(limit)} {'available' if max_memory is None else 'allowed (max_memory)'}{smaller}; "
            "or take fewer samples (n_samples or t_eval) or fewer runs per batch"
        )
    if max_seconds is not None:
        max_seconds = float(v.positive("max_seconds", max_seconds, "s"))
        if estimate.seconds is not None and estimate.seconds > max_seconds:
            raise RunTooLargeError(
                f"this run would take roughly {_duration(estimate.seconds)} ({estimate.describe()}), more than "
                f"max_seconds = {max_seconds:g} s; shorten t_end, take a larger dt (below the stability limit) "
                "or fewer runs, or raise max_seconds"
            )


def simulate(chain: Chain, t_end, *, impact_velocity=None, drop_height=None, gravity=True, t_eval=None,
             initial=None, **options) -> Simulation:  # fmt: skip
    """Integrate a chain after an impact on ring 0 (paper Eqs. (5)-(7)).

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
    initial : (array_like, array_like), optional
        Any initial state instead of an impact: site displacements x0 (m, from the
        configuration with every bond just taut) and velocities u0 (m/s), shape
        (n_sites,) each; ``gravity`` then only says whether gravity acts.  E.g. a wave
        packet on a pre-stretched chain.

    Other Parameters
    ----------------
    n_samples : int, optional
        Number of samples when ``t_eval`` is not given; default 2001.
    method : {"odeint", "LSODA", "DOP853", "RK45", "RK23", "verlet"}, optional
        Adaptive integrator: "odeint" (default, :data:`DEFAULT_METHOD`: LSODA stepped in
        Fortran) or a :func:`scipy.integrate.solve_ivp` method; or fixed-step velocity
        Verlet (undamped chains only).
    rtol : float, optional
        Relative tolerance of the adaptive methods, in :data:`TOLERANCE_RANGE`; default
        :data:`DEFAULT_RTOL`.
    atol : float, optional
        Absolute tolerance relative to the run's displacement, velocity and energy
        scales, at most 1e-3 (default ``rtol``).
    dt : float, optional
        Verlet step, s; default a fraction 1/``steps_per_period`` of the period of the
        fastest linearised mode at four times the estimated peak force.  The error of a
        fixed step grows with the distance the wave travels: for hundreds of rings, use
        more steps per period (tests/numerics/test_theory_vs_lattice.py uses 200).  Must lie
        below the stability limit 2/omega_max.
    steps_per_period : float, optional
        See ``dt``; default :data:`VERLET_STEPS_PER_PERIOD`; must exceed pi (stability).
    g : float, optional
        Gravity, m/s^2; default :data:`STANDARD_GRAVITY`.
    rings : sequence of int, optional
        Record only what the sensors of these rings need (the ring's sites, and for the
        power-law model its neighbours'), not every ring: for long chains, whose full
        record (2 x samples x sites doubles) does not fit in memory.  The sensor helpers
        then work for these rings only.  Default: every ring.
    max_memory : int, optional
        Bytes the run may take (record, forces derived from it, solver arrays); default
        the memory available.  A larger run is refused with :class:`RunTooLargeError`.
    max_seconds : float, optional
        Longest rough duration of a Verlet run (:attr:`RunEstimate.seconds`), s; default
        :data:`DEFAULT_MAX_SECONDS`; None for no limit.
    max_energy_drift : float, optional
        Largest drift of the total energy, as a fraction of the impact energy, before the
        run is stopped with :class:`IntegrationError`; default :data:`ENERGY_DRIFT_LIMIT`;
        None to check only that the state stays finite.

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
    if initial is not None and len(_initial_arrays(chain, initial)[0]) != 1:
        raise ValueError("simulate takes one initial state of shape (n_sites,); use simulate_batch for several")
    batch = simulate_batch(
        chain, t_end,
        impact_velocities=None if impact_velocity is None else [impact_velocity],
        drop_heights=None if drop_height is None else [drop_height],
        gravity=gravity, t_eval=t_eval, initial=initial, **options,
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
    """Arrays of one run (shape (T, ...)) or a batch (shape (B, T, ...)) and what they give.

    ``x`` and ``u`` hold every site, or, if the run recorded only some ``rings``, the sites
    their sensors need (:attr:`sites`, in order).
    """

    chain: Chain
    t: np.ndarray
    x: np.ndarray
    u: np.ndarray
    dissipated: np.ndarray
    g: float
    impact_velocity: np.ndarray | float
    drop_height: np.ndarray | float | None
    stats: dict = field(default_factory=dict, repr=False)
    rings: tuple | None = None

    @functools.cached_property
    def sites(self) -> np.ndarray:
        """Lattice sites held by ``x`` and ``u``, in order."""
        keep = _recorded_sites(self.chain, self.rings)
        return np.arange(self.chain.n_sites) if keep is None else keep

    def _require_all(self, what: str) -> None:
        if self.rings is not None:
            raise ValueError(
                f"{what} needs every ring, but this run recorded rings {list(self.rings)} only "
                "(simulate with rings=None to keep them all)"
            )

    def _columns(self, sites) -> np.ndarray:
        """Columns of ``x`` holding the lattice ``sites`` (all recorded: see :meth:`_sensor`)."""
        return sites if self.rings is None else np.searchsorted(self.sites, sites)

    def _bond_force_of(self, bonds) -> np.ndarray:
        """Forces of the lattice ``bonds`` (1-d array), N, shape (..., T, len(bonds)), from the recorded sites."""
        lat = self.chain.lattice
        upper = bonds + 1
        anchor = upper >= lat.n_sites  # the support's bond: its upper end does not move
        lower_cols, upper_cols = self._columns(bonds), self._columns(np.where(anchor, bonds, upper))

        def extension(x):
            return np.where(anchor, 0.0, x[..., upper_cols]) - x[..., lower_cols]

        return lat.bond_forces(extension(self.x), extension(self.u) if lat.damped else None, bonds=bonds)

    def _sensor(self, rings) -> np.ndarray:
        """Sensor forces of ``rings`` (1-d array), N, shape (..., T, len(rings)); see :attr:`sensor_force`."""
        bonds, weights = _sensor_bonds(self.chain, rings)
        unique, index = np.unique(bonds, return_inverse=True)
        forces = self._bond_force_of(unique)[..., index.reshape(bonds.shape)]
        return np.sum(forces * weights, axis=-1)

    @functools.cached_property
    def bond_force(self) -> np.ndarray:
        """Force in every lattice bond, N, positive in tension."""
        self._require_all("bond_force")
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
        self._require_all("sensor_force")
        return self._sensor(np.arange(self.chain.n_rings))

    @property
    def ring_displacement(self) -> np.ndarray:
        """Displacement of the centre of mass of each ring, m; shape (..., T, n_rings)."""
        self._require_all("ring_displacement")
        k = self.chain.sites_per_ring
        return self.x.reshape(*self.x.shape[:-1], -1, k).mean(axis=-1)

    @property
    def ring_velocity(self) -> np.ndarray:
        """Velocity of the centre of mass of each ring, m/s; shape (..., T, n_rings)."""
        self._require_all("ring_velocity")
        k = self.chain.sites_per_ring
        return self.u.reshape(*self.u.shape[:-1], -1, k).mean(axis=-1)

    def energy(self) -> EnergyBudget:
        """Kinetic, contact, bending, gravity and dissipated energy, J (see :class:`EnergyBudget`)."""
        self._require_all("energy")
        return _energy_budget(self.chain.lattice, self.x, self.u, self.x[..., :1, :], self.g, self.dissipated)


@dataclass(frozen=True, eq=False)
class Simulation(_Record):
    """One run: times ``t`` (s), site displacements ``x`` and velocities ``u`` (T, n_sites).

    Forces are derived on demand: ``contact_force`` (T, n_rings - 1), ``sensor_force``
    (T, n_rings), ``bending_force`` and ``support_force``; the sensor helpers read the
    leading pulse of the sensor force of a ring (:mod:`ringchain.numerics.signals`,
    which raises a :class:`~ringchain.numerics.signals.PulseError` when there is no
    complete, resolved pulse to read).  A run that recorded only some ``rings`` has the
    sensor helpers for those rings only.
    """

    def sensor(self, ring: int) -> np.ndarray:
        """Sensor force of ring ``ring`` (index from the impact end), N, shape (T,)."""
        return self._sensor(np.array([self._ring(ring)]))[..., 0]

    def _ring(self, ring) -> int:
        i = _ring_index(self.chain, ring)
        if self.rings is not None and i not in self.rings:
            raise ValueError(f"ring {i} was not recorded: this run kept rings {list(self.rings)} only (rings=...)")
        return i

    def peak_force(self, ring: int, threshold=None) -> float:
        """Peak of the leading pulse read by the sensor in ``ring``, N (static tension included)."""
        return signals.peak(self.t, self.sensor(ring), threshold)[1]

    def arrival_time(self, ring: int, threshold=None) -> float:
        """Time of the leading peak at the sensor in ``ring``, s, from the impact."""
        return signals.arrival_time(self.t, self.sensor(ring), threshold)

    def _pair(self, near, far) -> tuple[int, int]:
        near, far = self._ring(near), self._ring(far)
        if not near < far:
            raise ValueError(f"the far ring must lie further from the impact than the near one, got near = {near}, "
                             f"far = {far}")  # fmt: skip
        return near, far

    def time_of_flight(self, near: int, far: int, threshold=None) -> float:
        """Time between the leading peaks at two sensors, s (``near`` < ``far``, counted from the impact)."""
        near, far = self._pair(near, far)
        return signals.time_of_flight(self.t, self.sensor(near), self.sensor(far), threshold)

    def wave_speed(self, near: int, far: int, threshold=None) -> float:
        """(far - near) a over the time of flight, m/s (as measured in the paper)."""
        near, far = self._pair(near, far)
        a = self.chain.a
        distance = (far - near) * a if np.ndim(a) == 0 else float(np.sum(a[near:far]))  # centre to centre
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
            rings=self.rings,
        )  # fmt: skip

    def __iter__(self):
        return (self[i] for i in range(len(self)))


def __getattr__(name):
    # The paper's experiment lives in ringchain.numerics.paper; kept importable from here.
    if name in ("paper_experiment", "PaperExperiment"):
        from . import paper

        return getattr(paper, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
