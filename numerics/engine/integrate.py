r"""The engine: one integrator layer for every lattice, after the model of :mod:`scipy.integrate`.

:func:`simulate` and :func:`simulate_batch` integrate any *model*: a layout that builds a
network (a :class:`~ringchain.numerics.Chain`: the paper's chains, uniform or varying), a
:class:`~ringchain.numerics.Network` itself, or the ring-resolved
:class:`~ringchain.numerics.RingChain`.  A chain's run is its network's run.

The model contract (what :func:`simulate_batch` calls):

- ``model.dynamics()`` -- the object integrated, implementing the dynamics contract of
  :mod:`ringchain.numerics.engine.network` (stepper, first-order right-hand side and its
  bandwidth, packing of the flat state, energies, tolerance scales, fastest frequency);
- ``model.impact_state(speeds, dropped, gravity, g)`` -- the initial displacements and
  velocities of B runs (shape (B, n_coords) each) after an impact at ``speeds`` (m/s,
  validated here, once), ``dropped`` telling a drop (the chain's protocol: see
  :class:`~ringchain.numerics.Chain`) from an impact on the hanging chain;
- ``model.recorded(rings)`` -- the rings to record (validated) and the coordinates they
  need (None: all);
- ``model.result(**record)`` -- the result record (a :class:`~ringchain.numerics.BatchSimulation`
  for a chain, a :class:`~ringchain.numerics.NetworkBatch` for a network).

Any other initial state (a wave packet on a pre-stretched chain, say) is given as
``initial=(x0, u0)``.

Methods.  The compiled ones (:mod:`ringchain.numerics.engine.kernels`, their whole time loop in
Numba): "dopri5" (the default: Dormand and Prince's 5(4) pair with its continuous extension,
the error measured in the max norm over the components, so that components at rest or runs
repeated in a batch never change the steps a run takes; each run of a batch with its own
steps) and "verlet" (fixed-step velocity Verlet, symplectic, second order, for long undamped
chains).  The SciPy ones, the independent reference the tests compare against, on the model's
vectorised NumPy right-hand side: "odeint" (ODEPACK's LSODA driven by
:func:`scipy.integrate.odeint`, whose stepping loop runs in Fortran) and the methods of
:func:`scipy.integrate.solve_ivp` ("LSODA", the same integrator stepped from Python, "DOP853",
"RK45", "RK23").  The absolute tolerances are ``atol`` (default ``rtol``) times each run's own
scales (``dynamics.scales``): displacements of micrometres and velocities of metres per second
cannot share one absolute tolerance.  SciPy's error norm is a root mean square over the whole
state, so in a very long chain, where the pulse occupies a few of many rings, the control is
looser per active ring than ``rtol`` suggests; the compiled pair's max norm has no such effect.
A batch of runs (of one model, or of a :meth:`~ringchain.numerics.Network.stack` of models, one
run each) is one call; for SciPy a record longer than :data:`CHUNK_BYTES` of states is
integrated in consecutive chunks of samples.

Checks.  The settings are validated before any work: ``dt`` must lie below the stability
limit 2/omega_max of velocity Verlet (``dynamics.max_frequency``), ``steps_per_period``
above pi, and the tolerances within :data:`TOLERANCE_RANGE`.  The memory the run keeps
and, for Verlet, its work (steps x coordinates x runs) are estimated first
(:func:`estimate_run`); a run that would not fit in the memory available, or would take
hours, is refused with a message saying how to make it smaller (``rings``: record only the
rings read; ``n_samples``).  During the run the energy budget is watched: a state that
turns non-finite, or a total energy (dissipated energy included) that drifts from its
initial value by more than ``max_energy_drift`` times the impact energy, stops the run
with an :class:`IntegrationError` rather than returning an unstable result.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np
from ringchain.theory import STANDARD_GRAVITY, impact_speed
from ringchain.theory import _validate as v

from .resources import available_memory as _available_memory  # one name, patched by tests
from .resources import fields_cost, format_bytes, format_duration

__all__ = [
    "simulate",
    "simulate_batch",
    "estimate_run",
    "RunEstimate",
    "IntegrationError",
    "RunTooLargeError",
    "ADAPTIVE_METHODS",
    "METHODS",
    "COMPILED_METHODS",
    "DEFAULT_METHOD",
    "DEFAULT_RTOL",
    "DEFAULT_TOLERANCES",
    "VERLET_STEPS_PER_PERIOD",
    "TOLERANCE_RANGE",
    "ENERGY_DRIFT_LIMIT",
    "DEFAULT_MAX_SECONDS",
    "DEFAULT_SAMPLES",
    "CHUNK_BYTES",
    "format_bytes",
    "format_duration",
    "check_samples",
    "check_model_size",
    "impact_speeds",
    "verlet_step",
    "EnergyWatch",
]

#: Default integrator: the compiled Dormand-Prince 5(4) pair, its steps ending where contacts open or close:
#: sensor forces of the paper's chain within 2.8e-7 of their peak against an event-located tight reference
#: (8.8e-6 for odeint at rtol 1e-9, 18x slower in the same run; benchmarks/bench_paper_recipe.py).
DEFAULT_METHOD = "dopri5"

#: Default relative tolerance of each adaptive method; the absolute tolerances are this times the
#: displacement, velocity and energy scales of the impact (``dynamics.scales``).  The pair's 3e-10 gives
#: the accuracy LSODA gives at 1e-9 (its error control in the max norm over components and its
#: continuous extension differ from LSODA's RMS norm and interpolation): measured on the paper's chains,
#: both models, both stiffness sources (tests/numerics/engine/test_kernels.py).
DEFAULT_TOLERANCES = {"dopri5": 3e-10, "odeint": 1e-9, "LSODA": 1e-9, "DOP853": 1e-9, "RK45": 1e-9, "RK23": 1e-9}

#: The default relative tolerance of :data:`DEFAULT_METHOD`.
DEFAULT_RTOL = DEFAULT_TOLERANCES[DEFAULT_METHOD]

#: Verlet steps per period of the fastest linearised lattice mode at four times the
#: estimated peak force; chosen by the convergence test in tests/numerics/engine/test_integrate.py.
VERLET_STEPS_PER_PERIOD = 60

#: The adaptive methods: "dopri5" (Dormand-Prince 5(4), compiled, max-norm error control, each run of a
#: batch with its own steps: :mod:`ringchain.numerics.engine.kernels`), "odeint" (LSODA stepped in Fortran) and
#: the :func:`scipy.integrate.solve_ivp` methods, the independent reference.  LSODA (Adams, switching to BDF
#: with a banded Jacobian if the chain turns stiff) suits the chain; SciPy's explicit Runge-Kutta methods lose
#: their order at the kink of the contact law at delta = 0, which costs the higher orders most ("dopri5" ends
#: its steps there and keeps its order: :mod:`ringchain.numerics.engine.kernels`).
ADAPTIVE_METHODS = ("dopri5", "odeint", "LSODA", "DOP853", "RK45", "RK23")

#: The compiled methods (:mod:`ringchain.numerics.engine.kernels`): their whole time loop runs in Numba.
COMPILED_METHODS = ("dopri5", "verlet")

#: Every method :func:`simulate` takes.
METHODS = (*ADAPTIVE_METHODS, "verlet")

#: Range of ``rtol`` of the adaptive methods (``atol``, relative to the run's scales, may
#: not exceed its top).  Below 1e-13 LSODA refuses the tolerance as beyond double
#: precision ("illegal input" at 1e-14) and scipy's Runge-Kutta methods raise it to
#: 2.2e-14; above 1e-3 the error control no longer controls: over 2 ms of the paper's
#: chain, rtol = 1e-3 leaves sensor errors of 3-8% of the peak and 1e-2 of 15-28%
#: (measured against rtol = 1e-12; tests/numerics/engine/test_integrate.py checks the range's ends).
TOLERANCE_RANGE = (1e-13, 1e-3)

#: Largest drift of the total energy (dissipated energy included) from its initial
#: value, as a fraction of the impact energy m v^2/2, before a run is stopped as unstable
#: or inaccurate.  The default settings drift by ~1e-8 (LSODA) and ~1e-4 (Verlet, 60 steps
#: per period); an unstable Verlet step grows without bound; rtol = 1e-2 drifts by 7-19%.
ENERGY_DRIFT_LIMIT = 1e-2

#: Estimated duration (s) above which a run is refused unless ``max_seconds`` is raised
#: (:func:`estimate_run`).
DEFAULT_MAX_SECONDS = 3600.0

#: Samples of a record when ``t_eval`` is not given.
DEFAULT_SAMPLES = 2001

#: Most bytes of full states one adaptive solver call returns; longer records are
#: integrated in consecutive chunks of samples (the solver restarts at each chunk).
CHUNK_BYTES = 256 * 2**20

# Rough cost of one step of the compiled methods: a fixed overhead plus a cost per coordinate and
# run (a dopri5 step is seven evaluations and their Runge-Kutta sums), measured on the paper's
# chain on a busy 2-core machine (benchmarks/bench_kernels.py gives this machine's numbers); only
# used to turn a number of steps into an order of magnitude of seconds.
_SECONDS_PER_STEP = 2e-7
_SECONDS_PER_SITE_STEP = {"verlet": 3e-8, "dopri5": 2e-7}

# Steps dopri5 takes per period of the fastest linearised mode (as Verlet's steps_per_period) at
# rtol = 1e-7, growing as rtol^(-1/5) (a fifth-order pair): measured 4.9-6.4 on the paper's chain
# (drops of 1-30 cm) against 60 for Verlet, 22 at rtol = 3e-10.  An estimate, not a bound: the
# contacts' openings and closings cost rejected steps the linearised modes do not show.
_DOPRI5_STEPS_PER_PERIOD = 7.0

# A sheet (2-3D network): its stepper costs this many times a chain's per coordinate; what follows the run (link_force,
# energy(), the file: one compiled pass, engine/fields) is resources.fields_cost (tracemalloc:
# tests/numerics/layouts/test_sheet_estimate.py; processor time: benchmarks/bench_sheet_estimate.py).
_PLANAR_STEP_COST = 6.5  # dopri5 takes 2.4x the steps the linearised modes suggest, each 2.7x a chain's per coordinate
# Bytes per site of a chain's network, dynamics and initial state, built before a run can be estimated (measured:
# 153 per site for a dual-spring chain of 1e6 rings); a chain that needs more than the memory available is refused
# before they are built (issue 24, item 11: 1e8 rings took 15.7 GB and 34 s before the estimate refused them).
_SETUP_BYTES_PER_SITE = 160

# Most LSODA steps between two samples (odeint's mxstep); a run that needs more fails.
_MAX_STEPS_PER_SAMPLE = 1_000_000
#: Steps the compiled dopri5 may take per run before it stops with "too many steps".
_MAX_DOPRI5_STEPS = 10_000_000


class IntegrationError(ValueError):
    """The integrator failed, or its result is unstable (non-finite, or the energy drifted)."""


class RunTooLargeError(ValueError):
    """A run that would need more memory or time than allowed; the message says how to shrink it.

    Attributes: ``needed`` and ``limit`` (bytes needed, and available or allowed; None for a duration),
    ``estimate`` (the :class:`RunEstimate`, where one was made), ``seconds`` (the longest duration allowed, s).
    """

    def __init__(self, message, *, needed=None, limit=None, estimate=None, seconds=None):
        super().__init__(message)
        self.needed, self.limit, self.estimate, self.seconds = needed, limit, estimate, seconds


# -- the methods --------------------------------------------------------------------------------------
def _odeint(rhs, y0, t0, times, rtol, atol, bandwidth):
    """LSODA through :func:`scipy.integrate.odeint` from state ``y0`` at ``t0``: (states at ``times``, nfev).

    odeint's first output time is its initial time, so ``t0`` is put in front of ``times``
    when they start later and its row dropped.  The Jacobian is banded, as for solve_ivp's
    LSODA.  A failure raises :class:`IntegrationError` with ODEPACK's reason.
    """
    from scipy.integrate import ODEintWarning, odeint

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


def _solve_ivp(rhs, method, y0, t0, times, rtol, atol, bandwidth):
    """A :func:`scipy.integrate.solve_ivp` method from ``y0`` at ``t0``: (states at ``times``, nfev)."""
    from scipy.integrate import solve_ivp

    band = dict(zip(("lband", "uband"), bandwidth, strict=True)) if method == "LSODA" else {}
    sol = solve_ivp(rhs, (t0, times[-1]), y0, method=method, t_eval=times, rtol=rtol, atol=atol, **band)
    if not sol.success:
        raise IntegrationError(
            f"solve_ivp ({method}) stopped before t = {times[-1]:g} s: {sol.message} (rtol = {rtol:g}); "
            "try method='odeint' or 'verlet', or other tolerances"
        )
    return sol.y, sol.nfev


def _adaptive(method, dyn, x0, u0, scales, t_eval, rtol, atol, g, keep, watch):
    """An adaptive method over ``t_eval``, in chunks of samples of at most :data:`CHUNK_BYTES` of states.

    ``x0``, ``u0`` (shape (B, n_coords)) start the B runs of ``dyn`` (of one model, or of a
    stack, one run each); ``scales`` = (X, V, E) of each run times ``atol`` are the absolute
    tolerances of its displacements, velocities and dissipated energy.  Returns x and u of
    the coordinates ``keep`` (all if None), shape (B, T, K), the dissipated energy (B, T) and stats.
    """
    B, N = x0.shape
    T = t_eval.size
    y0 = dyn.pack(x0, u0)
    atol = atol * dyn.state_scales(*scales)
    rhs = dyn.first_order_rhs(B, g)
    sel = slice(None) if keep is None else keep
    K = N if keep is None else keep.size
    xs, us = np.empty((B, T, K)), np.empty((B, T, K))
    dissipated = np.zeros((B, T))
    chunk = max(1, CHUNK_BYTES // (8 * y0.size))
    t_prev, y_prev, nfev = 0.0, y0, 0
    for j0 in range(0, T, chunk):
        times = t_eval[j0 : j0 + chunk]
        if times[-1] <= t_prev:  # only the initial state is asked for
            y, calls = y_prev[:, None], 0
        elif method == "odeint":
            y, calls = _odeint(rhs, y_prev, t_prev, times, rtol, atol, dyn.bandwidth)
        else:
            y, calls = _solve_ivp(rhs, method, y_prev, t_prev, times, rtol, atol, dyn.bandwidth)
        nfev += calls
        x, u, w = dyn.unpack(y, B)
        xs[:, j0 : j0 + times.size] = x[:, sel, :].transpose(0, 2, 1)
        us[:, j0 : j0 + times.size] = u[:, sel, :].transpose(0, 2, 1)
        if w is not None:
            dissipated[:, j0 : j0 + times.size] = w
        y_prev, t_prev = y[:, -1].copy(), float(times[-1])
        watch(t_prev, x[..., -1], u[..., -1], 0.0 if w is None else w[:, -1])
    return xs, us, dissipated, {"method": method, "rtol": rtol, "nfev": nfev}


def _compiled(method, dyn, x0, u0, scales, t_eval, t_end, rtol, atol, dt, g, keep, watch, shared=False):
    """A compiled method (:mod:`ringchain.numerics.engine.kernels`): x and u of ``keep`` (B, T, K), W (B, T) and stats.

    The kernels check that the state stays finite; the energy watch reads the final state.
    """
    from ._kernel_calls import collector_paused

    with collector_paused():  # the first import starts Numba and decorates the kernels
        from . import kernels

    packed = kernels.pack(dyn)
    B, N = x0.shape
    keep = np.arange(N) if keep is None else keep
    memory = dyn.initial_memory() if getattr(dyn, "stateful", False) else None  # (B or 1, links)
    if memory is not None:
        memory = np.broadcast_to(memory, (B, memory.shape[-1]))
    if method == "verlet":
        out = kernels.verlet(packed, x0, u0, t_eval, t_end, dt, keep, g, memory=memory)
        xs, us, x_end, u_end, status, dt, steps = out[:7]
        ms, m_end = out[7:] if memory is not None else (None, None)
        _check_status(method, status, t_end)
        watch(t_end, x_end, u_end, 0.0, m_end)
        return xs, us, np.zeros((B, t_eval.size)), {"method": method, "dt": dt, "nfev": steps + 1}, ms
    X, V, E = scales
    columns = [np.repeat(X[:, None], N, axis=1), np.repeat(V[:, None], N, axis=1)]
    state = [x0, u0]
    if dyn.damped:
        columns.append(E[:, None])
        state.append(np.zeros((B, 1)))
    if hasattr(dyn, "tolerance_scales"):  # a model whose coordinates have several units (rigid rings)
        columns = [dyn.tolerance_scales(X, V, E)]
    if memory is not None:  # the memory's derivative is zero: its tolerance never enters the error
        columns.append(np.repeat(X[:, None], memory.shape[1], axis=1))
        state.append(memory)
    xs, us, w, ms, final, status, counts = kernels.dopri5(
        packed, np.hstack(state), t_eval, rtol, atol * np.hstack(columns), keep, g, shared=shared,
        max_steps=_MAX_DOPRI5_STEPS)  # fmt: skip
    _check_status(method, status, t_end, rtol)
    first = 2 * N + int(dyn.damped)
    watch(t_end, final[:, :N], final[:, N : 2 * N], final[:, 2 * N] if dyn.damped else 0.0,
          final[:, first:] if memory is not None else None)  # fmt: skip
    return xs, us, w, {"method": method, "rtol": rtol, "nfev": int(counts[:, 0].sum()),
                       "steps": counts[:, 1].tolist(), "rejected": counts[:, 2].tolist(),
                       "cut": counts[:, 3].tolist()}, \
        (ms if memory is not None else None)  # fmt: skip


def _check_status(method, status, t_end, rtol=None):
    """Raise IntegrationError with the kernel's reason if a run did not finish."""
    from .kernels import STATUS

    failed = np.flatnonzero(status)
    if failed.size:
        b = int(failed[0])
        tolerances = "" if rtol is None else f" (rtol = {rtol:g})"
        advice = ("take a smaller dt or more steps_per_period" if method == "verlet" else
                  "try a larger rtol or atol, or method='odeint'")  # fmt: skip
        raise IntegrationError(f"{method} stopped before t = {t_end:g} s in run {b}: {STATUS[int(status[b])]}"
                               f"{tolerances}; {advice}")  # fmt: skip


def verlet_step(dyn, X, steps_per_period) -> float:
    """Verlet time step, s: 1/``steps_per_period`` of the period of the fastest linearised mode
    (``dyn.max_frequency(X)``, links at up to four times the force of extension ``X``)."""
    return 2.0 * np.pi / dyn.max_frequency(X) / steps_per_period


class EnergyWatch:
    """Stops a run whose state turns non-finite or whose total energy drifts (module notes).

    Called as ``watch(t, x, u, dissipated)`` with states of shape (B, n_coords).
    """

    def __init__(self, dyn, x0, u0, g, scale, limit, advice):
        self.dyn, self.x0, self.g, self.scale, self.limit, self.advice = dyn, x0, g, scale, limit, advice
        self.initial = self._total(x0, u0, 0.0, dyn.initial_memory() if getattr(dyn, "stateful", False) else None)

    def _total(self, x, u, dissipated, memory):
        """Total energy, J; with the plastic work of laws with memory (``memory`` per link) when given."""
        extra = {} if memory is None else {"memory": memory}
        return self.dyn.energy(x, u, self.x0, self.g, dissipated, **extra).total

    def __call__(self, t, x, u, dissipated=0.0, memory=None):
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(u))):
            raise IntegrationError(f"the state became non-finite by t = {t:g} s: the integration is unstable; "
                                   f"{self.advice}")  # fmt: skip
        if self.limit is None:
            return
        total = self._total(x, u, dissipated, memory)
        drifts = np.atleast_1d(np.abs(total - self.initial) / self.scale)
        worst = int(np.argmax(np.where(np.isnan(drifts), np.inf, drifts)))
        drift = float(drifts[worst])
        if not drift <= self.limit:
            where = f" in run {worst}" if drifts.size > 1 else ""
            raise IntegrationError(
                f"the total energy drifted by {drift:.3g} times the impact energy by t = {t:g} s{where} "
                f"(max_energy_drift = {self.limit:g}): the integration is unstable or inaccurate; {self.advice}"
            )


# -- what a run will cost ----------------------------------------------------------------------
@dataclass(frozen=True)
class RunEstimate:
    """What a run will take, estimated before it starts (:func:`estimate_run`).

    Attributes
    ----------
    method : str
    runs, sites, samples : int
        Runs of the batch, coordinates of one run (``sites``: one per lattice site of a chain, two per ring of
        a sheet), samples of the record.
    recorded_sites : int
        Coordinates whose x and u are kept (all, or those the sensors of ``rings`` need).
    steps : int or None
        Verlet steps; for "dopri5", the steps it is expected to take (from the fastest linearised
        mode and rtol); None for SciPy's adaptive methods.
    dt : float or None
        Verlet step, s (None for the adaptive methods).
    memory : int
        Bytes: the record (x, u and the dissipated energy), the forces derived from it,
        and the solver's own arrays; for a network in two or three dimensions (a sheet), the peak of
        its link forces and energies computed from the record.
    post_seconds : float
        Rough duration of what a sheet's run does after the integration (link forces, energies,
        writing its file), s; 0 for a chain.
    planar : bool
        A network in two or three dimensions (its general stepper costs more per site than a chain's).
    """

    method: str
    runs: int
    sites: int
    samples: int
    recorded_sites: int
    steps: int | None
    dt: float | None
    memory: int
    post_seconds: float = 0.0
    planar: bool = False

    @property
    def work(self) -> int | None:
        """Steps x coordinates x runs (the compiled methods), or None."""
        return None if self.steps is None else self.steps * self.sites * self.runs

    @property
    def seconds(self) -> float | None:
        """Rough duration of a compiled run, s, at the per-step costs measured on a 2-core machine."""
        if self.steps is None:
            return None
        per_site = _SECONDS_PER_SITE_STEP[self.method] * (_PLANAR_STEP_COST if self.planar else 1.0)
        return self.steps * (_SECONDS_PER_STEP + per_site * self.sites * self.runs) + self.post_seconds

    def describe(self, memory=True) -> str:
        """One line: the run's size, work, rough duration and (unless ``memory`` is False) memory."""
        size = f"{self.runs} run(s) x {self.sites} coordinates x {self.samples} samples"
        steps = f"Verlet steps of {self.dt:.3g} s" if self.dt is not None else f"{self.method} steps (expected)"
        work = (
            ""
            if self.steps is None
            else (
                f", {self.steps:.3g} {steps} = {self.work:.3g} coordinate-steps (roughly "
                f"{format_duration(self.seconds)})"
            )
        )
        return f"{size}{work}" + (f", {format_bytes(self.memory)} of memory" if memory else "")


def check_samples(n) -> int:
    """A number of samples: an integer of at least 3 (ValueError saying why)."""
    n = v.integer("n_samples", n)
    if n < 3:
        raise ValueError(f"n_samples must be at least 3, got {n}")
    return n


def _check_t_eval(t_eval, t_end, n_samples):
    if t_eval is None:
        return np.linspace(0.0, t_end, check_samples(n_samples))
    t_eval = v.as_float("t_eval", t_eval)
    if t_eval.ndim != 1 or t_eval.size < 1:
        raise ValueError(f"t_eval must be a 1-d array of times, got shape {t_eval.shape}")
    if np.any(np.diff(t_eval) <= 0) or t_eval[0] < 0 or t_eval[-1] > t_end:
        raise ValueError(f"t_eval must be increasing and lie within [0, t_end] = [0, {t_end:g}] s")
    return t_eval


def _rtol(value) -> float:
    value = float(v.as_float("rtol", value))
    low, high = TOLERANCE_RANGE
    if not low <= value <= high:
        raise ValueError(
            f"rtol must lie in [{low:g}, {high:g}], got {value:g}: below, the tolerance is beyond double precision; "
            "above, the error control no longer controls (TOLERANCE_RANGE)"
        )
    return value


def impact_speeds(impact_velocities, drop_heights, g):
    """The impact speeds (m/s, shape (B,)) and whether they are drops, validated once, here."""
    if impact_velocities is not None and drop_heights is not None:
        raise ValueError("give an impact velocity or a drop height, not both")
    for name, values, unit in (("drop_height", drop_heights, "m"), ("impact_velocity", impact_velocities, "m/s")):
        if values is None:
            continue
        values = np.atleast_1d(v.nonnegative(name, values, unit))
        if values.ndim != 1 or values.size == 0:
            raise ValueError(f"{name} must be one value or a 1-d array of values (one per run), got shape "
                             f"{values.shape}")  # fmt: skip
        return (impact_speed(values, g), True) if name == "drop_height" else (values, False)
    return np.zeros(1), False


def _initial_arrays(n_coords, initial):
    """``initial = (x0, u0)`` validated and stacked into two arrays of shape (B, n_coords)."""
    try:
        x0, u0 = initial
    except (TypeError, ValueError):
        raise TypeError("initial must be a pair (x0, u0): displacements (m) and velocities (m/s)") from None
    arrays = []
    for name, value in (("displacements x0", x0), ("velocities u0", u0)):
        array = v.as_float(f"initial {name}", value)
        if array.ndim not in (1, 2) or array.shape[-1] != n_coords:
            raise ValueError(
                f"initial {name} must have shape (n_sites,) or (B, n_sites) with n_sites = {n_coords}, "
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


def _prepare(model, t_end, impact_velocities, drop_heights, gravity, t_eval, n_samples, method, rtol, atol, dt,
             steps_per_period, g, rings, initial=None):  # fmt: skip
    """Validate a run's inputs and estimate its cost; returns (RunEstimate, everything the run needs)."""
    if not callable(getattr(model, "dynamics", None)):
        raise TypeError(f"a model must be a Chain, a Network or a RingChain, got {type(model).__name__}")
    t_end = float(v.positive("t_end", t_end, "s"))
    t_eval = _check_t_eval(t_eval, t_end, n_samples)
    g = float(v.positive("g", g, "m/s^2"))
    gravity = v.flag("gravity", gravity)
    if not isinstance(method, str) or method not in METHODS:
        raise ValueError(f"method must be one of {METHODS}, got {method!r}")
    # A layout (a Chain) builds its network only now: refuse one that cannot fit before building it.
    sites = getattr(model, "n_sites", None) if callable(getattr(model, "network", None)) else None
    if sites is not None:
        check_model_size(sites, _SETUP_BYTES_PER_SITE, "its network and initial state")
    dyn = model.dynamics()
    if getattr(dyn, "stateful", False) and method not in COMPILED_METHODS:
        raise ValueError(
            f"this model has laws with memory ({', '.join(dyn.stateful)}: the largest approach of each contact), "
            f"which only the compiled methods {COMPILED_METHODS} update, on accepted steps; method={method!r} cannot "
            "integrate it: use method='dopri5' (the default) or 'verlet'"
        )
    if initial is None:
        speeds, dropped = impact_speeds(impact_velocities, drop_heights, g)
        x0, u0 = model.impact_state(speeds, dropped, gravity, g)
    elif impact_velocities is not None or drop_heights is not None:
        raise ValueError("give an initial state or an impact (impact_velocities, drop_heights), not both")
    else:
        x0, u0 = _initial_arrays(dyn.n_coords, initial)
    B, N = x0.shape
    scales = dyn.scales(x0, u0, g)
    rings, keep = model.recorded(rings)
    K = N if keep is None else keep.size
    T = t_eval.size
    steps = None
    if method == "verlet":
        if dyn.damped:
            raise ValueError("Verlet integrates undamped chains only (the dashpots make forces depend on velocity)")
        X = float(scales[0].max())
        limit = verlet_step(dyn, X, np.pi)  # 2/omega_max: the stability limit of velocity Verlet
        if dt is None:
            sp = float(v.as_float("steps_per_period", steps_per_period))
            if not sp > np.pi:
                raise ValueError(
                    f"steps_per_period must exceed pi, the stability limit of velocity Verlet (omega dt < 2), "
                    f"got {sp:g} (default {VERLET_STEPS_PER_PERIOD})"
                )
            dt = verlet_step(dyn, X, sp)
        else:
            dt = float(v.positive("dt", dt, "s"))
            if dt >= limit:
                raise ValueError(
                    f"dt = {dt:g} s is above the stability limit of velocity Verlet on this chain, 2/omega_max = "
                    f"{limit:.3g} s (omega_max: the fastest linearised mode at four times the estimated peak force); "
                    f"the default step is {verlet_step(dyn, X, VERLET_STEPS_PER_PERIOD):.3g} s"
                )
        steps = max(1, math.ceil(t_end / dt))
        solver = 8 * 12 * B * N  # state, accelerations, work arrays of the stepper
    else:
        rtol = _rtol(DEFAULT_TOLERANCES[method] if rtol is None else rtol)
        atol = rtol if atol is None else float(v.in_range("atol", atol, 0.0, TOLERANCE_RANGE[1]))
        if method == "dopri5":
            per_period = _DOPRI5_STEPS_PER_PERIOD * (1e-7 / rtol) ** 0.2
            steps = max(1, math.ceil(t_end / verlet_step(dyn, float(scales[0].max()), per_period)))
        n_state = 2 * B * N + (B if dyn.damped else 0)
        solver = 8 * n_state * (2 * min(T, max(1, CHUNK_BYTES // (8 * n_state))) + 30)  # output, copies, LSODA
    links = getattr(dyn, "n_links", N) if rings is None else 2 * len(rings)
    planar = getattr(dyn, "dim", 1) > 1
    # The forces derived later (link_force, kept): in two or three dimensions in one compiled pass with the
    # energies (engine/fields), after the solver's arrays are freed.
    if planar:
        post, derived = fields_cost(links, K, T, B)
        if method in COMPILED_METHODS:
            solver = 8 * 12 * B * N  # a compiled method writes the record itself
        memory = 8 * B * T * (2 * K + 1) + max(derived, solver)
    else:
        post, derived = 0.0, links * 8 * B * T
        memory = 8 * B * T * (2 * K + 1) + derived + solver
    estimate = RunEstimate(method, B, N, T, K, steps, dt, int(memory), post, planar)
    prepared = dict(t_end=t_end, t_eval=t_eval, g=g, gravity=gravity, x0=x0, u0=u0, scales=scales, rings=rings,
                    keep=keep, dt=dt, rtol=rtol, atol=atol, dynamics=dyn)  # fmt: skip
    return estimate, prepared


def estimate_run(model, t_end, *, impact_velocities=None, drop_heights=None, gravity=True, t_eval=None,
                 n_samples=DEFAULT_SAMPLES, method=DEFAULT_METHOD, rtol=None, atol=None, dt=None,
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
    >>> from ringchain.numerics import Chain
    >>> chain = Chain.dual_spring(100_000, K_c=7.5e9, K_b=3.3e6, m=8.2e-3, a=0.04)
    >>> full = estimate_run(chain, 2e-3, drop_heights=0.05, method="verlet")
    >>> sensors = estimate_run(chain, 2e-3, drop_heights=0.05, method="verlet", rings=[6, 12])
    >>> round(full.memory / 2**30, 1), round(sensors.memory / 2**20, 1)  # GB, MB
    (9.0, 18.5)
    """
    return _prepare(model, t_end, impact_velocities, drop_heights, gravity, t_eval, n_samples, method, rtol, atol,
                    dt, steps_per_period, g, rings, initial)[0]  # fmt: skip


def _check_size(estimate: RunEstimate, rings, max_memory, max_seconds):
    """Refuse a run larger than the memory available or longer than ``max_seconds`` (RunTooLargeError)."""
    limit = _available_memory() if max_memory is None else int(v.positive("max_memory", max_memory, "bytes"))
    if limit is not None and estimate.memory > limit:
        smaller = "" if rings is not None else (
            "; record only the rings you read (rings=[...]: the sensors need 1-3 rings' sites each)")  # fmt: skip
        raise RunTooLargeError(
            f"this run needs about {format_bytes(estimate.memory)} of memory ({estimate.describe(memory=False)}), "
            f"more than the {format_bytes(limit)} {'available' if max_memory is None else 'allowed (max_memory)'}"
            f"{smaller}; or take fewer samples (n_samples or t_eval) or fewer runs per batch",
            needed=estimate.memory, limit=limit, estimate=estimate,
        )  # fmt: skip
    if max_seconds is not None:
        max_seconds = float(v.positive("max_seconds", max_seconds, "s"))
        if estimate.seconds is not None and estimate.seconds > max_seconds:
            raise RunTooLargeError(
                f"this run would take roughly {format_duration(estimate.seconds)} ({estimate.describe()}), more "
                f"than max_seconds = {max_seconds:g} s; shorten t_end, take a larger dt (below the stability "
                "limit) or fewer runs, or raise max_seconds", estimate=estimate, seconds=max_seconds,
            )  # fmt: skip


def check_model_size(sites: int, bytes_per_site: int, what: str) -> None:
    """Refuse (:class:`RunTooLargeError`), before anything is allocated, a model whose ``what`` needs more than
    the memory available at ``bytes_per_site`` bytes per site."""
    available = _available_memory()
    needed = int(bytes_per_site) * int(sites)
    if available is not None and needed > available:
        raise RunTooLargeError(
            f"a model of {sites} sites needs about {format_bytes(needed)} for {what} alone, more than the "
            f"{format_bytes(available)} available; take fewer rings",
            needed=needed, limit=available,
        )  # fmt: skip


def simulate_batch(
    model,
    t_end,
    *,
    impact_velocities=None,
    drop_heights=None,
    gravity=True,
    t_eval=None,
    n_samples=DEFAULT_SAMPLES,
    method=DEFAULT_METHOD,
    rtol=None,
    atol=None,
    dt=None,
    steps_per_period=VERLET_STEPS_PER_PERIOD,
    g=STANDARD_GRAVITY,
    rings=None,
    max_memory=None,
    max_seconds=DEFAULT_MAX_SECONDS,
    max_energy_drift=ENERGY_DRIFT_LIMIT,
    initial=None,
    shared_steps=False,
):
    """Integrate B runs of one model together, as one array problem.

    The compiled methods advance each run with its own steps (each run of the pair "dopri5" chooses
    its step sizes for its own error; the runs share Numba's threads), so a run's result does not
    depend on the batch it is in; ``shared_steps=True`` makes "dopri5" step the batch together, one
    step size for the error of all (forward differences between the runs then share their steps, as
    the trace fit's Jacobian needs).  The SciPy methods integrate the B x n_coords states as one
    system, whose steps are shared (the RMS error norm over the batch can only be dominated by the
    most demanding run).  Either way the numbers agree with separate :func:`simulate` runs to the
    solver tolerance.

    Parameters
    ----------
    model : Chain, Network or RingChain
        What to integrate (see the module notes); a :meth:`~ringchain.numerics.Network.stack`
        of B networks takes B initial states, one run each.
    t_end : float
        Duration, s.
    impact_velocities, drop_heights : array_like, optional
        One run per value (see :func:`~ringchain.numerics.initial_state`).
    gravity, t_eval, n_samples, method, rtol, atol, dt, steps_per_period, g, rings, max_memory, max_seconds, \
max_energy_drift
        As in :func:`simulate` (its "Other Parameters").
    initial : (array_like, array_like), optional
        Any initial state instead of an impact: displacements x0 (m) and velocities u0 (m/s),
        each of shape (n_coords,) or (B, n_coords) (one run per row; a single row is shared);
        ``gravity`` then only says whether gravity acts.  Not together with
        ``impact_velocities`` or ``drop_heights``.
    shared_steps : bool, optional
        "dopri5" only: one step size for the whole batch (see above).  Default False.

    Returns
    -------
    BatchSimulation or NetworkBatch
        ``contact_force`` of shape (B, len(t), n_rings - 1) for a chain, ``link_force`` for a
        network; ``result[i]`` is run i.

    Raises
    ------
    RunTooLargeError
        If the run would need more memory than ``max_memory`` or longer than ``max_seconds``.
    IntegrationError
        If the integrator fails, or the run turns unstable (see the module notes).
    """
    estimate, run = _prepare(model, t_end, impact_velocities, drop_heights, gravity, t_eval, n_samples, method, rtol,
                             atol, dt, steps_per_period, g, rings, initial)  # fmt: skip
    _check_size(estimate, run["rings"], max_memory, max_seconds)
    if max_energy_drift is not None:
        max_energy_drift = float(v.positive("max_energy_drift", max_energy_drift))
    dyn = run["dynamics"]
    x0, u0, t_eval = run["x0"], run["u0"], run["t_eval"]
    E = run["scales"][2]
    g_dyn = run["g"] if run["gravity"] else 0.0
    advice = ("take a smaller dt or more steps_per_period" if method == "verlet" else
              "take a smaller rtol (and atol), or method='verlet'")  # fmt: skip
    watch = EnergyWatch(dyn, x0, u0, g_dyn, 2.0 * E, max_energy_drift, advice)  # 2 E = m v^2 / 2
    with np.errstate(over="ignore", invalid="ignore"):  # an unstable run is reported by the watch
        if method in COMPILED_METHODS:
            xs, us, dissipated, stats, memory = _compiled(
                method, dyn, x0, u0, run["scales"], t_eval, run["t_end"], run["rtol"], run["atol"], run["dt"], g_dyn,
                run["keep"], watch, shared=v.flag("shared_steps", shared_steps))  # fmt: skip
        else:
            xs, us, dissipated, stats = _adaptive(method, dyn, x0, u0, run["scales"], t_eval, run["rtol"],
                                                  run["atol"], g_dyn, run["keep"], watch)  # fmt: skip
            memory = None
    heights = None if drop_heights is None else np.atleast_1d(np.asarray(drop_heights, dtype=float))
    extra = {} if memory is None else {"memory": memory}  # laws with memory: the largest approach per link
    return model.result(t=t_eval, x=xs, u=us, dissipated=dissipated, g=g_dyn, stats=stats, rings=run["rings"],
                        impact_velocity=np.max(np.abs(u0), axis=-1), drop_height=heights, **extra)  # fmt: skip


def simulate(model, t_end, *, impact_velocity=None, drop_height=None, gravity=True, t_eval=None, initial=None,
             velocity=None, angular_velocity=None, **options):  # fmt: skip
    """Integrate a chain after an impact on ring 0 (paper Eqs. (5)-(7)), or any model of the engine.

    Parameters
    ----------
    model : Chain, Network or RingChain
        The chain (or its :meth:`~ringchain.numerics.Chain.network`, or any network, or the
        ring-resolved chain).  A network has no struck ring: give it ``initial``.
    t_end : float
        Duration, s; t = 0 is the impact (for a drop: the instant the slack is taken up).
    impact_velocity : float, optional
        Speed of ring 0 moving away from the chain at t = 0, m/s.
    drop_height : float, optional
        Free-fall height of ring 0, m: impact speed sqrt(2 g h)
        (:func:`ringchain.theory.impact_speed`; the protocol in :class:`~ringchain.numerics.Chain`).
    gravity : bool, optional
        Hang the chain from its support under gravity (default) or integrate a chain
        without gravity, starting unstretched.
    t_eval : array_like, optional
        Sample times in [0, t_end], s; default ``n_samples`` evenly spaced.
    initial : (array_like, array_like), optional
        Any initial state instead of an impact: displacements x0 (m, from the configuration
        with every link just taut) and velocities u0 (m/s), shape (n_coords,) each;
        ``gravity`` then only says whether gravity acts.  E.g. a wave packet on a
        pre-stretched chain.
    velocity, angular_velocity : array_like, optional
        Rigid rings (:class:`~ringchain.numerics.Rings`) only: the initial velocities of the
        rings, shape (n, 3), m/s in space, and angular velocities, shape (n, 3), rad/s in the
        body frame, from their rest configuration (default zero).

    Other Parameters
    ----------------
    n_samples : int, optional
        Number of samples when ``t_eval`` is not given; default :data:`DEFAULT_SAMPLES`.
    method : {"dopri5", "odeint", "LSODA", "DOP853", "RK45", "RK23", "verlet"}, optional
        Adaptive integrator: "dopri5" (default, :data:`DEFAULT_METHOD`: Dormand-Prince 5(4),
        compiled, error in the max norm over the components), "odeint" (LSODA stepped in
        Fortran) or a :func:`scipy.integrate.solve_ivp` method, the independent reference; or
        fixed-step velocity Verlet (compiled; undamped chains only).
    rtol : float, optional
        Relative tolerance of the adaptive methods, in :data:`TOLERANCE_RANGE`; default the
        method's (:data:`DEFAULT_TOLERANCES`).
    atol : float, optional
        Absolute tolerance relative to the run's displacement, velocity and energy
        scales, at most 1e-3 (default ``rtol``).
    dt : float, optional
        Verlet step, s; default a fraction 1/``steps_per_period`` of the period of the
        fastest linearised mode at four times the estimated peak force.  The error of a
        fixed step grows with the distance the wave travels: for hundreds of rings, use
        more steps per period (tests/numerics/layouts/test_theory_vs_lattice.py uses 200).  Must lie
        below the stability limit 2/omega_max.
    steps_per_period : float, optional
        See ``dt``; default :data:`VERLET_STEPS_PER_PERIOD`; must exceed pi (stability).
    g : float, optional
        Gravity, m/s^2; default :data:`~ringchain.numerics.STANDARD_GRAVITY`.
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
    Simulation or NetworkSimulation
        Times ``t`` (s); for a chain ``contact_force`` (len(t), n_rings - 1) in N, sensors,
        energy; for a network ``link_force`` (len(t), n_links).

    Examples
    --------
    >>> from ringchain.numerics import Chain
    >>> chain = Chain.power_law(10, K=1e9, n=1.5, m=0.01, a=0.02, support="free")
    >>> sim = simulate(chain, 2e-4, impact_velocity=0.1, gravity=False)
    >>> sim.contact_force.shape
    (2001, 9)
    >>> bool(sim.contact_force.min() >= 0.0)  # contacts never push
    True
    """
    if np.ndim(impact_velocity) or np.ndim(drop_height):
        raise ValueError("simulate takes one impact; use simulate_batch for several")
    motion = getattr(model, "initial_motion", None)
    if velocity is not None or angular_velocity is not None:
        if motion is None:
            raise ValueError(
                f"velocity and angular_velocity set the motion of rigid rings (Rings); a {type(model).__name__} "
                "takes impact_velocity, drop_height or initial=(x0, u0)"
            )
        if initial is not None or impact_velocity is not None or drop_height is not None:
            raise ValueError("give velocity/angular_velocity, an impact or an initial state, not several")
        initial = motion(velocity, angular_velocity)
    elif motion is not None and initial is None and impact_velocity is None and drop_height is None:
        initial = motion()  # rigid rings released at rest
    if initial is not None:
        try:
            x0 = np.asarray(initial[0])
        except (TypeError, IndexError, KeyError):
            x0 = None
        if x0 is not None and x0.ndim > 1 and x0.shape[0] != 1:
            raise ValueError("simulate takes one initial state of shape (n_sites,); use simulate_batch for several")
    batch = simulate_batch(
        model, t_end,
        impact_velocities=None if impact_velocity is None else [impact_velocity],
        drop_heights=None if drop_height is None else [drop_height],
        gravity=gravity, t_eval=t_eval, initial=initial, **options,
    )  # fmt: skip
    return batch[0]
