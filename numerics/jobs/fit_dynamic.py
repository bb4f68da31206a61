r"""Sensor traces to parameters: the paper's "dynamic fitting" (Sec. III.B), :func:`fit_traces`.

Any of the chain's m, gamma, K, n, K_b, gamma_b, a trigger offset t0 and an impact speed v0
per record (or one offset h0 of all the drop heights), from one or several records.

The forward model
-----------------
The residual is the simulated sensor force at each measured sample minus the measured
one, plus a DC offset per channel (fitted; a piezoelectric sensor does not read the static
tension).  The measured time t maps to the model's t - t0 (t0: the measured time of the
impact); before the impact the model reads the chain at rest.  The chain is simulated on a
uniform grid over the measured window and read at t - t0 by a cubic spline, whose
derivative gives the Jacobian column of t0 without a run.  The Jacobian columns of the
chain's parameters (and of h0) are forward differences, one run per parameter (all impact
speeds v0 share one run: each record depends only on its own), and all the runs of one
Jacobian -- the base point and its perturbations -- are integrated as one batch
(:func:`simulate_parameter_sets`: the chains' networks stacked,
:meth:`~ringchain.numerics.Network.stack`), so that they share their steps (the differences
are then smooth in the parameters) and the per-step cost of NumPy is paid once.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from ringchain.theory import STANDARD_GRAVITY, impact_speed
from ringchain.theory import _validate as v

from ..engine.integrate import simulate, simulate_batch
from ..engine.network import Network
from ..engine.results import Simulation
from ..engine.traces import noise_level, pulse_problem, starting_level
from ..layouts.chain import Chain
from .fit import FitError, FitResult, as_data, check_converged, dominated, minimize, result_from_lmfit, weak_directions

__all__ = [
    "fit_traces",
    "TraceRecord",
    "simulate_parameter_sets",
    "CHAIN_PARAMETERS",
    "FIT_RTOL",
    "JACOBIAN_STEP",
    "MODEL_RESOLUTION",
    "JACOBIAN_RESOLUTION",
]

#: Chain fields a trace fit may free (besides "t0", "v0" and "h0").
CHAIN_PARAMETERS = ("m", "gamma", "K", "n", "K_b", "gamma_b")

#: Relative tolerance of the forward runs of a trace fit (the compiled pair, the runs of one Jacobian
#: stepped together).  The sensor forces of the paper's chain differ from converged ones by about 5e-7
#: of their peak (4e-6 at 1e-8; tests/numerics/jobs/test_fit.py), far below any measured noise, at a third
#: of the cost of the pair's default 3e-10; looser, the forward differences of the Jacobian go wrong
#: where contacts open (by up to 15 % with LSODA at 1e-7).
FIT_RTOL = 1e-9

#: Relative step of the forward differences of the Jacobian.  Truncation error ~ step (1e-4
#: of a column); the runs of one Jacobian share their integration steps, so their
#: difference carries far less than the solver's own tolerance.
JACOBIAN_STEP = 1e-4

#: Relative accuracy of the forward model at the measured samples (integration at FIT_RTOL and
#: spline interpolation; largest where contacts open): 1e-4 of the peak force on the paper's chain.
MODEL_RESOLUTION = 1e-4

#: Singular value (relative to the largest) of a trace fit's Jacobian with unit columns below which
#: a direction is checked by a profile (:func:`_profile_check`).  The forward
#: differences are accurate to about 1e-3 of a column where the traces are smooth, but a
#: dashpot makes the force jump where a contact closes, and the samples the jump crosses put
#: spikes into the columns: exactly degenerate fits (the symmetry of fit_traces' Notes) came out
#: between 5e-4 and 7e-3, as did directions a held dashpot determines weakly (7e-3, 1.4e-2);
#: well-determined ones at 0.04 and above.
JACOBIAN_RESOLUTION = 3e-2

#: Profile check: a parameter is held this many linearised standard errors off, but at most
#: PROBE_CAP of its value (a valley followed much further bends away from the solution); if the
#: sum of squares rises by less than one sigma^2 (its standard error is then larger than the
#: shift; along a symmetry the rise is the solver's noise), it is taken as undetermined.
PROBE_SIGMAS, PROBE_CAP = 10.0, 0.3


@dataclass(frozen=True, eq=False)
class TraceRecord:
    """One measured record of a trace fit and the fitted model on its samples.

    Attributes
    ----------
    t : ndarray
        Measured times, s.
    measured, fitted : dict
        {ring: force (N)}: the data, and the model at the fitted parameters (DC offset included).
    t0 : float
        Fitted (or fixed) measured time of the impact, s.
    v0 : float
        Impact speed, m/s.
    drop_height : float or None
        The record's drop height, m, if it was given as one.
    """

    t: np.ndarray
    measured: dict
    fitted: dict
    t0: float
    v0: float
    drop_height: float | None

    @property
    def residual(self) -> dict:
        """{ring: fitted - measured}, N."""
        return {k: self.fitted[k] - self.measured[k] for k in self.measured}


# -- trace fits: the forward model --------------------------------------------------------------------
def simulate_parameter_sets(chains, speeds, dropped, t_grid, rings, *, rtol=FIT_RTOL, gravity=True,
                            g=STANDARD_GRAVITY, batched=True):  # fmt: skip
    """(parameter sets) -> simulated sensor forces: the forward model of :func:`fit_traces`.

    Parameters
    ----------
    chains : sequence of Chain, length P
        One chain per parameter set (same model and number of rings).
    speeds : ndarray, shape (P, R)
        Impact speed of each record under each parameter set, m/s.
    dropped : sequence of bool, length R
        Whether record r is a drop (the chain's drop protocol) or an impact on the hanging chain.
    t_grid : ndarray
        Times after the impact, s, from 0.
    rings : sequence of sequences
        Sensor rings of each record.
    rtol : float, optional
        Tolerance of the runs (absolute tolerance the same, relative to each run's scales).
    batched : bool
        Integrate all P x R runs as one array problem (default), or one
        :func:`~ringchain.numerics.simulate` call per run.

    Returns
    -------
    list of ndarray
        Per record, the sensor forces of shape (P, n_rings of the record, len(t_grid)), N.

    Notes
    -----
    The batch is the chains' networks stacked (:meth:`~ringchain.numerics.Network.stack`, run b
    on chain b) and integrated by :func:`~ringchain.numerics.simulate_batch` as a batch of runs
    of one chain is (the same driver and tolerances).
    """
    P, R = speeds.shape
    out = [np.empty((P, len(ks), t_grid.size)) for ks in rings]
    options = dict(t_eval=t_grid, rtol=rtol, atol=rtol, gravity=gravity, g=g, max_energy_drift=None)
    if not batched or P * R == 1:
        for p, chain in enumerate(chains):
            for r in range(R):
                x, u = chain.impact_state(np.array([speeds[p, r]]), dropped[r], gravity, g)
                sim = simulate(chain, t_grid[-1], initial=(x, u), rings=rings[r], **options)
                out[r][p] = [sim.sensor(k) for k in rings[r]]
        return out
    runs = [(chain, r) for chain in chains for r in range(R)]
    states = [chain.impact_state(np.array([speed]), dropped[r], gravity, g)
              for (chain, r), speed in zip(runs, speeds.ravel(), strict=True)]  # fmt: skip
    x0 = np.concatenate([x for x, _ in states])
    u0 = np.concatenate([u for _, u in states])
    # Only the sites the sensors read are recorded, and every run's sensors are read in one pass over the batch:
    # the stacked network gives each run its own laws, and the chains share their sensors' links (one layout).
    sensors = sorted({int(k) for ks in rings for k in ks})
    layout = chains[0]
    network = Network.stack([chain.network() for chain, _ in runs])
    recorded = sorted({int(k) for k in network.rings[layout.recorded_sites(sensors)]})
    batch = simulate_batch(network, t_grid[-1], initial=(x0, u0), shared_steps=True, rings=recorded, **options)
    sim = Simulation(t=t_grid, x=batch.x, u=batch.u, dissipated=batch.dissipated, g=batch.g, network=batch.network,
                     sites=batch.sites, chain=layout, rings=tuple(sensors))  # fmt: skip
    forces = {k: sim.sensor(k) for k in sensors}  # (P x R, T) each, run b = p R + r
    for r, ks in enumerate(rings):
        out[r][:] = np.stack([forces[k][r::R] for k in ks], axis=1)
    return out


@dataclass
class _Record:
    t: np.ndarray
    rings: tuple
    force: np.ndarray  # (C, T)
    speed: float
    dropped: bool
    drop_height: float | None


def _records(t, traces, chain, drop_height, impact_velocity):
    """Normalise the two call forms of fit_traces into a list of _Record."""
    if isinstance(traces, Mapping):
        items = [(t, traces, drop_height, impact_velocity)]
    elif isinstance(traces, Sequence) and not isinstance(traces, str | bytes):
        if t is not None:
            raise ValueError("with a list of (t, traces, drop height) records, pass t=None")
        if drop_height is not None:
            raise ValueError("give each record's drop height in its (t, traces, drop height) tuple")
        speeds = [None] * len(traces) if impact_velocity is None else list(np.atleast_1d(impact_velocity))
        if len(speeds) != len(traces):
            raise ValueError(f"impact_velocity has {len(speeds)} values for {len(traces)} records")
        items = []
        for i, record in enumerate(traces):
            if len(record) != 3:
                raise ValueError(f"record {i} must be a (t, traces, drop height) tuple, got {len(record)} items")
            items.append((*record, speeds[i]))
    else:
        raise TypeError(f"traces must be a {{ring: force}} mapping or a list of records, got {type(traces).__name__}")
    if not items:
        raise ValueError("no records to fit")
    records = []
    for i, (t_r, traces_r, h, speed) in enumerate(items):
        where = "" if len(items) == 1 else f" (record {i})"
        t_r = as_data(f"t{where}", t_r, "s")
        if np.any(np.diff(t_r) <= 0):
            k = int(np.flatnonzero(np.diff(t_r) <= 0)[0]) + 1
            raise ValueError(f"t{where} must increase; sample {k} ({t_r[k]:g} s) follows {t_r[k - 1]:g} s")
        if not isinstance(traces_r, Mapping) or not traces_r:
            raise ValueError(f"traces{where} must be a non-empty {{ring: force}} mapping")
        rings = tuple(int(k) for k in traces_r)
        for k in rings:
            if not 0 <= k < chain.n_rings:
                raise ValueError(f"sensor ring {k}{where} is not in a chain of {chain.n_rings} rings")
        force = np.array([v.as_float(f"traces[{k}]{where}", traces_r[k]) for k in traces_r])
        if force.shape[1:] != t_r.shape:
            raise ValueError(f"each trace{where} must have the {t_r.size} samples of t, got shape {force.shape}")
        for k, y in zip(rings, force, strict=True):
            problem = pulse_problem(y)
            if problem:
                raise ValueError(f"traces[{k}]{where}: {problem}")
        if (h is None) == (speed is None):
            raise ValueError(f"give a drop height or an impact velocity{where}, one of the two")
        if h is not None:
            h = float(v.positive(f"drop_height{where}", h, "m"))
            speed = float(impact_speed(h))
        speed = float(v.positive(f"impact_velocity{where}", speed, "m/s"))
        records.append(_Record(t_r, rings, force, speed, h is not None, h))
    return records


class _TraceProblem:
    """Parameters, forward runs, residual and Jacobian of a trace fit."""

    def __init__(self, records, chain, free, *, t0, offsets, rtol, gravity, batched, g=STANDARD_GRAVITY):
        self.records, self.chain, self.rtol, self.gravity, self.batched, self.g = (
            records, chain, rtol, gravity, batched, g)  # fmt: skip
        self.chain_free = [name for name in CHAIN_PARAMETERS if name in free]
        self.free_t0, self.free_v0, self.free_h0, self.offsets = "t0" in free, "v0" in free, "h0" in free, offsets
        # Parameters that move every record, one forward run each in a Jacobian.
        self.shared_free = [*self.chain_free, *(["h0"] if self.free_h0 else [])]
        self.fixed_t0 = t0
        self.n_runs = 0
        self.n_batches = 0
        self._last = None
        self._run = None  # (what a forward run depends on, its splines): the last single run
        self._chains = {}  # {values of the free chain parameters: Chain}
        self.suffix = [""] if len(records) == 1 else [f"_{i}" for i in range(len(records))]
        # Grid of the forward runs: the finest measured sampling (median step).
        self.dt_grid = min(float(np.median(np.diff(rec.t))) for rec in records)
        self.force_scale = max(float(np.max(y) - starting_level(y)) for rec in records for y in rec.force)
        # A field that changes along the chain (a chain file's) is fitted as its profile times one factor: the
        # parameter is the value at ring 0 (contact 0), the profile's ratios stay as given.
        self.profiles = {}
        for name in self.chain_free:
            value = np.asarray(getattr(chain, name), dtype=float)
            if value.ndim and np.ptp(value) > 0:
                if value[0] == 0:
                    raise ValueError(f"{name} changes along the chain from 0 at ring 0: it cannot be fitted as one "
                                     "factor of its profile; hold it")  # fmt: skip
                self.profiles[name] = value / value[0]

    def scales(self, records):
        """Scale of each parameter for :func:`~.fit.minimize`: a record's span for t0, the measured peak for the
        offsets, the smallest drop height for h0 (the others: their starting values)."""
        scales = {"h0": min((rec.drop_height for rec in records if rec.drop_height), default=1.0)}
        for r, rec in enumerate(records):
            scales[self.name("t0", r)] = float(rec.t[-1] - rec.t[0])
            scales.update(dict.fromkeys((self.offset_name(r, k) for k in rec.rings), self.force_scale))
        return scales

    # -- names and values ----------------------------------------------------------------------------
    def name(self, kind, r):
        """Name of record r's "t0" or "v0"."""
        return f"{kind}{self.suffix[r]}"

    def offset_name(self, r, ring):
        return f"offset_ring{ring}{self.suffix[r]}"

    def offset_names(self):
        return [self.offset_name(r, k) for r, rec in enumerate(self.records) for k in rec.rings]

    def damping_scale(self, chain):
        """gamma* = sqrt(m k), N s/m: critical damping of one ring on the contact's tangent stiffness at
        the largest measured force (the bending stiffness if lower); the scale of a dashpot near 0 (ring 0's)."""
        F = self.force_scale
        n, K, m = first(chain.n), first(chain.K), first(chain.m)
        k = n * K ** (1.0 / n) * F ** ((n - 1.0) / n)
        if chain.K_b is not None:
            k = min(k, first(chain.K_b))
        return math.sqrt(m * k)

    def chain_at(self, values):
        """The chain at ``values``, made once per set of values (a Jacobian's base point is the residual's last one,
        and a chain builds its network once)."""
        key = tuple(values[k] for k in self.chain_free)
        if key not in self._chains:
            fields = {k: values[k] * self.profiles[k] if k in self.profiles else values[k] for k in self.chain_free}
            self._chains[key] = dataclasses.replace(self.chain, **fields)
        return self._chains[key]

    def speeds_at(self, values):
        """Impact speed of each record, m/s: its free v0, sqrt(2 g (h + h0)), or as given."""
        if self.free_v0:
            return np.array([values[self.name("v0", r)] for r in range(len(self.records))])
        if self.free_h0:
            return np.array([math.sqrt(2.0 * self.g * (rec.drop_height + values["h0"])) for rec in self.records])
        return np.array([rec.speed for rec in self.records])

    def t0s(self, values):
        return [values[self.name("t0", r)] if self.free_t0 else self.fixed_t0[r] for r in range(len(self.records))]

    # -- forward runs ----------------------------------------------------------------------------------
    def simulate(self, value_sets, t0s):
        """Cubic splines (over the time after the impact) of each record's sensor forces, shape
        (P, C) per record for the P parameter sets, on a grid covering every measured sample."""
        from scipy.interpolate import CubicSpline

        t_end = max(rec.t[-1] - t0 for rec, t0 in zip(self.records, t0s, strict=True))
        if not t_end > 0:
            raise FitError("every record ends before the impact (t0 beyond the last sample)")
        n = int(min(max(math.ceil(t_end / self.dt_grid), 200), 20000)) + 1
        t_grid = np.linspace(0.0, t_end * (1.0 + 2.0 / n), n)
        chains = [self.chain_at(values) for values in value_sets]
        speeds = np.array([self.speeds_at(values) for values in value_sets])
        forces = simulate_parameter_sets(
            chains, speeds, [rec.dropped for rec in self.records], t_grid, [rec.rings for rec in self.records],
            rtol=self.rtol, gravity=self.gravity, g=self.g, batched=self.batched,
        )  # fmt: skip
        self.n_runs += len(value_sets)
        self.n_batches += 1 if self.batched else len(value_sets) * len(self.records)
        return [CubicSpline(t_grid, f, axis=-1) for f in forces]

    def model(self, splines, values, t0s, *, slope=False):
        """Per record, the model (P, C, T) at the measured samples, DC offsets added; or, with
        ``slope``, its time derivative (zero before the impact)."""
        out = []
        for r, (rec, spline, t0) in enumerate(zip(self.records, splines, t0s, strict=True)):
            tau = rec.t - t0
            if slope:
                out.append(np.where(tau > 0, spline(np.maximum(tau, 0.0), 1), 0.0))
                continue
            y = spline(np.maximum(tau, 0.0))  # before the impact: the chain at rest
            if self.offsets:
                y = y + np.array([values[self.offset_name(r, k)] for k in rec.rings])[:, None]
            out.append(y)
        return out

    def fitted(self, values):
        """Model of each record (C, T) at ``values`` (one forward run; the last one is cached, and its run serves
        values that differ in the DC offsets only, which do not enter it: the start after :func:`_align`)."""
        key = tuple(sorted(values.items()))
        if self._last is None or self._last[0] != key:
            t0s = self.t0s(values)
            run = (tuple(values[name] for name in self.chain_free), tuple(self.speeds_at(values).tolist()),
                   tuple(t0s))  # fmt: skip
            if self._run is None or self._run[0] != run:
                self._run = run, self.simulate([values], t0s)
            self._last = key, [m[0] for m in self.model(self._run[1], values, t0s)]
        return self._last[1]

    # -- lmfit callbacks -------------------------------------------------------------------------------
    def residual_of(self, values):
        """Model minus data at every sample, N, records and channels in turn."""
        model = self.fitted(values)
        return np.concatenate([(m - rec.force).ravel() for m, rec in zip(model, self.records, strict=True)])

    def residual(self, params):
        return self.residual_of(params.valuesdict())

    def jacobian(self, params):
        """d residual / d parameter, columns in the order of the free parameters: one batch of runs
        (the base point, one per chain parameter, one for all the v0), t0 from the spline's slope,
        offsets exactly."""
        values = params.valuesdict()
        steps = {}
        for name in self.shared_free:
            if name.startswith("gamma"):
                scale = self.damping_scale(self.chain_at(values))
            elif name == "h0":
                scale = min(rec.drop_height for rec in self.records)
            else:
                scale = 0.0
            steps[name] = JACOBIAN_STEP * max(abs(values[name]), scale)
        sets = [values] + [{**values, name: values[name] + h} for name, h in steps.items()]
        v0_names = [self.name("v0", r) for r in range(len(self.records))] if self.free_v0 else []
        for name in v0_names:
            steps[name] = JACOBIAN_STEP * values[name]
        if v0_names:  # each record depends on its own v0 only: one run perturbs them all
            sets.append({**values, **{name: values[name] + steps[name] for name in v0_names}})
        t0s = self.t0s(values)
        splines = self.simulate(sets, t0s)
        model = self.model(splines, values, t0s)
        slopes = self.model(splines, values, t0s, slope=True)
        blocks = []
        for r, rec in enumerate(self.records):
            base = model[r][0]
            columns = dict.fromkeys(params, None)
            for i, name in enumerate(self.shared_free, start=1):
                columns[name] = (model[r][i] - base) / steps[name]
            if v0_names:
                columns[v0_names[r]] = (model[r][-1] - base) / steps[v0_names[r]]
            if self.free_t0:
                columns[self.name("t0", r)] = -slopes[r][0]
            for c, k in enumerate(rec.rings if self.offsets else ()):
                column = np.zeros_like(base)
                column[c] = 1.0
                columns[self.offset_name(r, k)] = column
            zero = np.zeros(base.size)
            blocks.append(np.column_stack([zero if col is None else col.ravel()
                                           for name, col in columns.items() if params[name].vary]))  # fmt: skip
        return np.vstack(blocks)


def _profile_check(problem, out, residual, **options):
    """Covariance of a trace fit with its weak directions measured by profiles, and the free
    parameters the data do not determine: (covariance or None if unchanged, [names]).

    Only where the Jacobian (unit columns) has singular directions below JACOBIAN_RESOLUTION.
    The forward differences cannot measure the curvature of such a direction: where a dashpot
    makes the force jump as a contact closes, the samples the jump crosses put spikes into the
    columns as large as the direction's singular value.  So for each, the parameter with the
    largest share in it is held PROBE_SIGMAS linearised standard errors off (at most PROBE_CAP of
    its value) and the others are fitted again from the solution (a profile).  If the sum of
    squares rises by less than one sigma^2 (sigma^2 = chi-square / degrees of freedom), the
    valley is flat (a refit that fails counts as flat: no error bars rather than wrong ones):
    the held parameter, those that slid along with it (by more than two standard errors) and
    those whose variance the direction dominates (:func:`dominated`) are undetermined.
    Otherwise the rise gives the held parameter's variance, shift^2 sigma^2 / rise, and the
    direction's singular value is set to reproduce it.
    """
    params = out.params
    names = [name for name, p in params.items() if p.vary]
    weak = weak_directions(out, names, JACOBIAN_RESOLUTION)
    if weak is None or len(weak[3]) == 0 or any(params[k].stderr is None for k in names):
        return None, []
    sv, vt, norms, indices = weak
    ssr = float(np.sum(np.square(residual)))
    sigma2 = ssr / max(residual.size - len(names), 1)
    values = params.valuesdict()
    stderr = {k: float(params[k].stderr) for k in names}
    inverse_square = 1.0 / np.square(sv)
    undetermined = set()
    for i in indices:
        j = int(np.argmax(np.abs(vt[i])))
        held = names[j]
        shift = PROBE_SIGMAS * stderr[held]
        if values[held] != 0:  # stay where the valley is followed from the solution
            shift = min(shift, PROBE_CAP * abs(values[held]))
        for sign in (1.0, -1.0):
            value = values[held] + sign * shift
            if not params[held].min < value < params[held].max:
                continue
            trial = params.copy()
            trial[held].set(value=value, vary=False)
            refit = minimize(problem.residual, trial, jac=problem.jacobian, **options)
            rise = (float(np.sum(np.square(problem.residual(refit.params)))) - ssr) / sigma2
            if not refit.success:  # cannot tell: no error bars rather than wrong ones
                rise = 0.0
            if rise < 1.0:
                moved = [k for k in names if k != held and abs(refit.params[k].value - values[k]) > 2 * stderr[k]]
                undetermined.update([held, *moved, *dominated(names, sv, vt, [i])])
                inverse_square[i] = 0.0
            else:  # sum over directions of (component / singular value)^2 = variance (norm^2 / sigma^2)
                target = shift**2 / rise * norms[j] ** 2 / sigma2
                others = float(np.sum(np.square(vt[:, j]) * inverse_square)) - vt[i, j] ** 2 * inverse_square[i]
                if target > others:
                    inverse_square[i] = (target - others) / vt[i, j] ** 2
            break
    covariance = sigma2 * (vt.T * inverse_square) @ vt / np.outer(norms, norms)
    return covariance, [k for k in names if k in undetermined]


def first(value) -> float:
    """A chain field's value at ring 0 (contact 0): the field itself for a uniform chain."""
    return float(np.ravel(value)[0])


#: A record longer than this many times the time the pulse takes to pass its farthest sensor, or shorter than
#: 1/SPAN_RATIO of the time it takes to pass one ring, is refused (:func:`_check_spans`): the first holds
#: little but the chain ringing and makes every forward run that much longer (minutes, for times in ms read
#: as s); the second cannot hold a pulse of that chain.
SPAN_RATIO = 100.0


def _check_spans(records, chain):
    """Refuse a record whose span is far from the time the pulse needs to reach its sensors (SPAN_RATIO), with the
    likely cause: times in other units than s, or another chain than the one measured."""
    from ..layouts.chain import default_t_end

    speeds = [rec.speed for rec in records]
    for r, rec in enumerate(records):
        span = float(rec.t[-1] - rec.t[0])
        where = "" if len(records) == 1 else f" of record {r}"
        far = max(1, *rec.rings)
        passing = default_t_end(chain, speeds, (0, far))
        if span > SPAN_RATIO * passing:
            raise ValueError(f"the times{where} span {span:.4g} s, {span / passing:.3g} times the {passing:.3g} s the "
                             f"pulse needs to pass ring {far}: are they in s (not ms)? Cut the record to the pulse, or "
                             "give the chain measured")  # fmt: skip
        one_ring = default_t_end(chain, speeds, (0, 1))
        if span < one_ring / SPAN_RATIO:
            raise ValueError(f"the times{where} span {span:.4g} s, 1/{one_ring / span:.3g} of the {one_ring:.3g} s the "
                             "pulse needs to pass one ring: are they in s, and is the chain (R, r, material) the one "
                             "measured?")  # fmt: skip


def _noisy_peak(t, y):
    """Time (s) and height of the leading peak of a noisy trace (above its starting level).

    :func:`signals.peak` takes the first run of samples above half the maximum, which noise
    breaks into pieces on the rising edge.  Here the pulse runs from the first sample above
    half the maximum until the trace falls below a quarter of it (noise of a few per cent
    cannot cross that gap), and its peak is the vertex of the parabola fitted to the
    samples of the pulse above 80 % of its largest one.
    """
    y = y - starting_level(y)
    top = float(np.max(y))
    start = int(np.argmax(y >= 0.5 * top))
    below = np.flatnonzero(y[start:] < 0.25 * top)
    stop = start + int(below[0]) if below.size else y.size
    k = start + int(np.argmax(y[start:stop]))
    near = np.flatnonzero(y[start:stop] >= 0.8 * y[k]) + start
    if near.size >= 3:
        c2, c1, c0 = np.polyfit(t[near] - t[k], y[near], 2)
        if c2 < 0:
            shift = float(np.clip(-c1 / (2.0 * c2), t[near[0]] - t[k], t[near[-1]] - t[k]))
            return t[k] + shift, c0 + c1 * shift + c2 * shift**2
    return float(t[k]), float(y[k])


def _peak_times(t, force):
    """Time (s) and height (N, above the starting level) of the leading peak of each channel, (C, 2)."""
    return np.array([_noisy_peak(t, y) for y in force])


def _check_amplitudes(record, model, measured, where):
    """Refuse a start whose pulse at a sensor is more than 20 times below or above the measured one (N, above the
    starting levels): the least squares cannot get there, and the likely cause is a unit or the chain."""
    for ring, simulated, peak in zip(record.rings, model, measured, strict=True):
        if not simulated > 0:
            raise FitError(f"the starting chain gives no pulse at ring {ring}{where} within the measured window "
                           f"({record.t[0]:.4g} to {record.t[-1]:.4g} s): are the times in s, and the chain (its "
                           "rings, m) and the impact those measured? Give better starting values")  # fmt: skip
        ratio = peak / simulated
        if not 1 / 20 <= ratio <= 20:
            side = "below" if ratio > 1 else "above"
            raise FitError(f"the starting chain's pulse at ring {ring}{where} peaks at {simulated:.3g} N, "
                           f"{max(ratio, 1 / ratio):.3g} times {side} the measured {peak:.3g} N: are the forces in "
                           "N? Otherwise the chain (its rings, m) or the impact is far off: give better starting "
                           "values")  # fmt: skip


def _align(problem, values, *, iterations=4):
    """Starting values from the pulses: t0 from the arrival at the first sensor, the speed
    parameter (m, else K) from the time of flight, v0 from the peak height.

    With the scaling of the power-law chain at a fixed impact speed (time ~ (m/K)^(1/(n+1)),
    force ~ K^(1/(n+1)) m^(n/(n+1)) v0^(2n/(n+1))), each update is a power of the measured
    over the simulated ratio; a few forward runs bring a start 30 % off within the reach of
    the least squares.
    """
    measured = [_peak_times(rec.t, rec.force) for rec in problem.records]
    n = first(problem.chain.n)
    speed_name = next((k for k in ("m", "K") if k in problem.chain_free), None)
    R = len(problem.records)
    for it in range(iterations):
        splines = problem.simulate([values], [min(0.0, rec.t[0]) for rec in problem.records])
        ratios, amplitudes = [], []
        for r, (spline, meas) in enumerate(zip(splines, measured, strict=True)):
            model = _peak_times(spline.x, spline(spline.x)[0])
            _check_amplitudes(problem.records[r], model[:, 1], meas[:, 1], "" if R == 1 else f" of record {r}")
            if problem.free_t0:
                values[problem.name("t0", r)] = float(meas[0, 0] - model[0, 0])
            if len(meas) >= 2:
                ratios.append((meas[-1, 0] - meas[0, 0]) / (model[-1, 0] - model[0, 0]))
            amplitudes.append(meas[0, 1] / model[0, 1])
        if it == iterations - 1:
            break
        ratio = float(np.exp(np.mean(np.log(ratios)))) if ratios and min(ratios) > 0 else 1.0
        moved = False
        if speed_name and abs(ratio - 1.0) > 0.01:
            values[speed_name] *= ratio ** ((n + 1.0) * (1.0 if speed_name == "m" else -1.0))
            moved = True
        if problem.free_v0 and max(abs(x - 1.0) for x in amplitudes) > 0.01:
            for r in range(R):
                values[problem.name("v0", r)] *= amplitudes[r] ** ((n + 1.0) / (2.0 * n))
            moved = True
        if not moved:
            break
    if problem.offsets:
        zero = {**values, **dict.fromkeys(problem.offset_names(), 0.0)}
        for r, (rec, model) in enumerate(zip(problem.records, problem.fitted(zero), strict=True)):
            for c, k in enumerate(rec.rings):
                values[problem.offset_name(r, k)] = float(np.median(rec.force[c] - model[c]))
    return values


def fit_traces(
    t, traces, chain, *, drop_height=None, impact_velocity=None, free=("m", "gamma"), t0=0.0, offsets=True,
    align=True, gravity=True, rtol=FIT_RTOL, max_nfev=60, batched=True,
) -> FitResult:  # fmt: skip
    """Fit a chain to measured sensor traces (the paper's "dynamic fitting", Sec. III.B).

    Parameters
    ----------
    t : array_like or None
        Measured times, s (the trigger's clock: t0 below maps it to the impact).
    traces : mapping or list
        {ring: force (N)} measured on ``t`` (rings counted from the impact), or a list of
        ``(t, traces, drop_height)`` records fitted jointly (then ``t=None``): one chain
        shared by all, one impact and one trigger offset per record.
    chain : Chain
        The model (power-law or dual-spring), with the starting values of the free
        parameters and the values of the fixed ones; gravity acts on ``chain.m_gravity``.
        Its striker (``striker_mass``) follows the fitted m in the paper's convention, and
        keeps its mass when given in kg (``"m0"``: a rigid ring of known mass).
    drop_height : float, optional
        Free-fall height of ring 0, m (impact speed sqrt(2 g h)).
    impact_velocity : float or sequence, optional
        Impact speed, m/s, instead of a drop height (one per record for a list).
    free : iterable of str
        Free parameters: any of the chain's "m" (kg), "gamma" (contact dashpot, N s/m; the
        dual-spring model's gamma_c), "K" (N/m^n; K_c of the dual-spring model), "n"
        (power-law only), "K_b" (N/m) and "gamma_b" (N s/m) (both dual-spring); "t0" (the
        measured time of the impact, s) and "v0" (the impact speed, m/s: a drop height is
        never exact), one per record; or, instead of "v0", "h0" (m): one offset added to
        every drop height (the zero of the height scale, where the slack is taken up, is
        uncertain), so that the free fall of record i is h_i + h0.
    t0 : float or sequence, optional
        Measured time of the impact, s, when "t0" is not free (default 0, as in the files of
        ``ringchain simulate``); one per record for a list.
    offsets : bool, optional
        Fit a DC offset (N) per channel (default; a piezoelectric sensor does not read the
        chain's static tension).
    align : bool, optional
        First move t0, the speed parameter and v0 to match the measured arrival times, time
        of flight and peak heights (a few forward runs); default True.
    gravity : bool, optional
        The chain hangs under gravity (default).
    rtol : float, optional
        Relative tolerance of the forward runs (default :data:`FIT_RTOL`).
    max_nfev : int, optional
        Most residual evaluations of the least squares.
    batched : bool, optional
        Integrate the runs of each Jacobian as one batch (default) or one by one.

    Returns
    -------
    FitResult
        ``values`` and ``stderr`` by name (SI; per-record names get a suffix _0, _1, ...
        when there are several records; DC offsets are "offset_ring<k>"), ``correlation``,
        ``chain`` (the fitted Chain), ``residual``, ``records`` (data and fitted model),
        ``n_forward_runs``.

    Raises
    ------
    FitError
        If the least squares do not converge, or the starting chain gives no pulse.

    Notes
    -----
    Which parameters the traces determine.  Eq. (8) depends on K^(1/n)/m only.  The
    traces say more when the impact speed is known: the power-law chain (Eq. 7) with
    m/alpha, K/alpha^n, gamma/alpha hit at alpha v0 moves as alpha times the original
    chain, with the same forces (gravity included: the weights are unchanged), so the
    sensors cannot tell the two apart.  Hence:

    - v0 known (the drop heights exact): the impulse m v0 fixes m, and K follows; one drop
      is enough;
    - "v0" free, one per record: m and K are never separated, however many drops: with
      "gamma" free too the fit reports them as not identifiable (infinite standard errors
      and a note); with the dashpot held, which breaks the symmetry a little, their
      correlation stays near 1, along K^(1/n)/m = const (Eq. (8));
    - "h0" free, one offset of all the heights: one drop cannot separate m and K, but
      several drops from different heights can (sqrt(h_i + h0) cannot follow one common
      factor alpha).

    The symmetry scales the striker with the rings, as the paper's convention does (the
    striker is a ring of mass m).  A striker of known mass (``striker_mass`` in kg, "m0")
    does not scale, so it breaks the symmetry too; and the values a known impact gives are
    those of the striker assumed: the impact's energy m_s v0^2/2 sets the amplitude.

    The book's chapter "From measurements to parameters" shows the three cases.
    """
    import lmfit

    if not isinstance(chain, Chain):
        raise TypeError(f"chain must be a Chain, got {type(chain).__name__}")
    free = tuple(free)
    allowed = (*CHAIN_PARAMETERS, "t0", "v0", "h0")
    for name in free:
        if name not in allowed:
            raise ValueError(f"free parameters are {', '.join(allowed)}; got {name!r}")
    if "v0" in free and "h0" in free:
        raise ValueError("free 'v0' (a speed per record) or 'h0' (one offset of all drop heights), not both")
    if chain.model == "dual-spring" and "n" in free:
        raise ValueError("the dual-spring contact is Hertzian (n = 3/2): 'n' can be free in the power-law model only")
    if chain.model == "power-law" and {"K_b", "gamma_b"} & set(free):
        raise ValueError("K_b and gamma_b belong to the dual-spring model")
    records = _records(t, traces, chain, drop_height, impact_velocity)
    R = len(records)
    if "h0" in free and any(rec.drop_height is None for rec in records):
        raise ValueError("a free drop-height offset 'h0' needs every record's drop height")
    t0_fixed = v.as_float("t0", t0)
    if t0_fixed.ndim == 0:
        t0_fixed = np.full(R, float(t0_fixed))
    if t0_fixed.shape != (R,):
        raise ValueError(f"t0 must be one value or one per record ({R}), got {np.size(t0)}")
    problem = _TraceProblem(records, chain, free, t0=[float(x) for x in t0_fixed], offsets=offsets,
                            rtol=float(v.positive("rtol", rtol)), gravity=gravity, batched=batched)  # fmt: skip
    _check_spans(records, chain)

    values = {name: first(getattr(chain, name)) for name in problem.chain_free}
    for name in ("gamma", "gamma_b"):
        if name in values and values[name] == 0.0:  # a start at 0 (the bound): 1e-4 of critical damping
            values[name] = 1e-4 * problem.damping_scale(chain)
    for r, rec in enumerate(records):
        if problem.free_t0:
            values[problem.name("t0", r)] = problem.fixed_t0[r]
        if problem.free_v0:
            values[problem.name("v0", r)] = rec.speed
    if problem.free_h0:
        values["h0"] = 0.0
    values.update(dict.fromkeys(problem.offset_names() if offsets else (), 0.0))
    if align:
        values = _align(problem, values)

    params = lmfit.Parameters()
    bounds = {"m": (0.0, np.inf), "K": (0.0, np.inf), "n": (1.0, 4.0), "K_b": (0.0, np.inf), "gamma": (0.0, np.inf),
              "gamma_b": (0.0, np.inf)}  # fmt: skip
    for name, value in values.items():
        if name in bounds:
            low, high = bounds[name]
        elif name.startswith("v0"):
            low, high = 0.0, np.inf
        elif name == "h0":  # every free fall stays positive
            low, high = -0.999 * min(rec.drop_height for rec in records), np.inf
        elif name.startswith("t0"):
            rec = records[problem.suffix.index(name[2:])]
            span = rec.t[-1] - rec.t[0]
            low, high = rec.t[0] - span, rec.t[-1] - 0.05 * span
        else:
            low, high = -np.inf, np.inf
        params.add(name, value=value, min=low, max=high)
    least_squares = {"max_nfev": max_nfev, "ftol": 1e-7, "xtol": 1e-5, "gtol": 1e-10}
    least_squares |= {"scales": problem.scales(records), "residual_scale": problem.force_scale}
    out = minimize(problem.residual, params, jac=problem.jacobian, **least_squares)
    names = list(params)
    check_converged("traces", out, names)
    final = out.params.valuesdict()
    model = problem.fitted(final)  # lmfit's last evaluation, from the cache
    residual = problem.residual_of(final)
    covariance, unresolved = _profile_check(problem, out, residual, **least_squares)
    speeds, t0s = problem.speeds_at(final), problem.t0s(final)
    out_records = tuple(
        TraceRecord(t=rec.t, measured=dict(zip(rec.rings, rec.force, strict=True)),
                    fitted=dict(zip(rec.rings, m, strict=True)), t0=float(t0s[r]), v0=float(speeds[r]),
                    drop_height=rec.drop_height)
        for r, (rec, m) in enumerate(zip(records, model, strict=True))
    )  # fmt: skip
    noise = math.sqrt(np.mean([noise_level(y) ** 2 for rec in records for y in rec.force]))
    rms = float(np.sqrt(np.mean(residual**2)))
    notes = []
    # Below MODEL_RESOLUTION of the peak, a misfit is the forward model's own (spline, solver).
    floor = max(noise, MODEL_RESOLUTION * problem.force_scale)
    if rms > 3.0 * floor:
        notes.append(f"the residual ({rms:.3g} N rms) is {rms / floor:.1f} times the noise of the traces "
                     f"({floor:.3g} N): the model misses features of the data, or this is a local minimum")  # fmt: skip
    model_fields = CHAIN_PARAMETERS if chain.model == "dual-spring" else ("m", "gamma", "K", "n")
    fixed = {k: first(getattr(chain, k)) for k in model_fields if k not in problem.chain_free}
    fixed["m_gravity"] = first(chain.m_gravity)
    if not chain.uniform:
        notes.append("the chain changes along its length: each chain parameter (free or fixed) is given at ring 0 "
                     "(contact 0); a free one scales its whole profile")  # fmt: skip
    if chain.striker_mass is not None:  # a striker given in kg (a rigid ring) keeps its mass while m is fitted
        fixed["striker_mass"] = chain.striker_mass
    for r in range(R):
        if not problem.free_t0:
            fixed[problem.name("t0", r)] = problem.fixed_t0[r]
        if not (problem.free_v0 or problem.free_h0):
            fixed[problem.name("v0", r)] = records[r].speed
    spread = sum(float(np.sum(np.square(y - y.mean()))) for rec in records for y in rec.force)
    return result_from_lmfit(
        "traces", out, names, residual, spread=spread, unresolved=unresolved, covariance=covariance, fixed=fixed,
        n_forward_runs=problem.n_runs,
        n_batches=problem.n_batches, chain=problem.chain_at(final), records=out_records, notes=notes,
        extra={"rms_residual_N": rms, "noise_N": noise},
    )  # fmt: skip
