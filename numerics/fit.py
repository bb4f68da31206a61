r"""From measurements to parameters: the paper's fitting workflow (Sec. III.B, IV, Tables I-II).

The paper takes K and n "from quasi-static tests" and m_eff/m0 and the dashpots "from
dynamic fitting".  This module does both, with lmfit (bounded least squares, standard
errors, correlations) on SciPy:

- reading data: :func:`read_traces` (the CSV of ``ringchain simulate --out``: ``t_s`` and
  one ``sensor_ring<k>_N`` column per sensor ring), :func:`read_static`
  (``displacement_m``, ``force_N``) and :func:`read_speed_amplitude` (``peak_force_N``,
  ``speed_m_s``, or a sweep's ``peak_force_near_N``, ``wave_speed_m_s``); a file that
  cannot be used raises :class:`DataError`, which says what is wrong and where;
- quasi-static: :func:`fit_static`, F = K delta^n (Eq. 4) or Hertz in series with bending
  (Eq. 3), each with an optional displacement offset;
- speed against amplitude: :func:`fit_speed_amplitude`, m_eff/m0 (and n) through Eq. (8);
- sensor traces: :func:`fit_traces`, any of the chain's m, gamma, K, n, K_b, gamma_b, a
  trigger offset t0 and an impact speed v0 per record (or one offset h0 of all the drop
  heights), from one or several records.

Every fit returns a :class:`FitResult` (values, standard errors, 95% intervals,
correlations, information criteria) or raises :class:`FitError`; it never returns an
unconverged answer.

Trace fits: the forward model
-----------------------------
The residual is the simulated sensor force at each measured sample minus the measured
one, plus a DC offset per channel (fitted; a piezoelectric sensor does not read the static
tension).  The measured time t maps to the model's t - t0 (t0: the measured time of the
impact); before the impact the model reads the chain at rest.  The chain is simulated on a
uniform grid over the measured window and read at t - t0 by a cubic spline, whose
derivative gives the Jacobian column of t0 without a run.  The Jacobian columns of the
chain's parameters (and of h0) are forward differences, one run per parameter (all impact
speeds v0 share one run: each record depends only on its own), and all the runs of one
Jacobian --
the base point and its perturbations -- are integrated as one batch by
:func:`_simulate_parameter_sets`, so that they share their steps (the differences are then
smooth in the parameters) and the per-step cost of NumPy is paid once.
"""

from __future__ import annotations

import csv
import dataclasses
import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from ringchain.theory import _validate as v

from .chain import Chain
from .models import STANDARD_GRAVITY, Lattice
from .solve import Simulation, _adaptive, _scales, initial_state, simulate

__all__ = [
    "read_traces",
    "read_static",
    "read_speed_amplitude",
    "fit_static",
    "fit_speed_amplitude",
    "fit_traces",
    "FitResult",
    "TraceRecord",
    "FitError",
    "DataError",
    "CHAIN_PARAMETERS",
    "MIN_SAMPLES",
    "FIT_RTOL",
]

#: Chain fields a trace fit may free (besides "t0", "v0" and "h0").
CHAIN_PARAMETERS = ("m", "gamma", "K", "n", "K_b", "gamma_b")

#: Fewest samples a data file or trace may have.
MIN_SAMPLES = 10

#: Relative tolerance of the forward runs of a trace fit.  The sensor forces of the paper's
#: chain differ from converged ones by about 1e-6 of their peak (tests/numerics/test_fit.py),
#: far below any measured noise, at half the cost of the package's default 1e-9; at 1e-7 the
#: forward differences of the Jacobian are off by up to 15 % where contacts open.
FIT_RTOL = 1e-8

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

#: The same for the static and speed fits, whose models are closed forms differentiated by
#: lmfit at steps of sqrt(machine epsilon) (Jacobian accurate to ~1e-7).
ANALYTIC_RESOLUTION = 1e-5

#: A pulse must stand this many noise levels above its baseline (read_traces).
PULSE_NOISE_RATIO = 8.0

_UNITS = {
    "m": "kg", "gamma": "N s/m", "K": "N/m^n", "n": "", "K_b": "N/m", "gamma_b": "N s/m", "t0": "s", "v0": "m/s",
    "h0": "m", "offset": "N", "delta0": "m", "K_c": "N/m^1.5", "m_eff_ratio": "", "m_gravity": "kg", "a": "m",
    "m0": "kg",
}  # fmt: skip


class DataError(ValueError):
    """A data file or array that cannot be used; the message says what is wrong and where.

    Attributes
    ----------
    path : str or None
        File.
    line : int or None
        Line of the file (1-based), where known.
    column : str or None
        Column name, where known.
    """

    def __init__(self, message, *, path=None, line=None, column=None, column_number=None):
        parts = [] if path is None else [str(path)]
        if line is not None:
            parts.append(f"line {line}")
        if column is not None:
            parts.append(f"column {column!r}" if column_number is None else f"column {column_number} ({column})")
        where = ", ".join(parts)
        super().__init__(f"{where}: {message}" if where else message)
        self.path, self.line, self.column = path, line, column


class FitError(RuntimeError):
    """A fit that did not converge (or cannot be trusted); never a silent wrong answer."""


# -- reading data ------------------------------------------------------------------------------------
def _read_table(path, required, *, optional_pattern=None, minimum=MIN_SAMPLES):
    """Columns of a CSV file: ({name: array}, [line number of each row], {name: column number}).

    Lines starting with ``#`` and blank lines are skipped; the first other line is the
    header.  Every cell of a required column (and of columns matching ``optional_pattern``)
    must be a finite number.
    """
    path = Path(path)
    try:
        text = path.read_text()
    except OSError as exc:
        raise DataError(f"cannot read the file ({exc.strerror or exc})", path=path) from None
    header, rows, lines = None, [], []
    for number, row in enumerate(csv.reader(text.splitlines()), start=1):
        if not row or not "".join(row).strip() or row[0].lstrip().startswith("#"):
            continue
        if header is None:
            header = [cell.strip() for cell in row]
            header_line = number
            continue
        rows.append(row)
        lines.append(number)
    if header is None:
        raise DataError("no header line (the file is empty or all comments)", path=path)
    alternatives = [required] if isinstance(required[0], str) else list(required)
    for names in alternatives:
        if all(name in header for name in names):
            break
    else:
        wanted = " or ".join(", ".join(names) for names in alternatives)
        raise DataError(f"missing column(s): need {wanted}; the header has {', '.join(header)}",
                        path=path, line=header_line)  # fmt: skip
    wanted = list(names)
    if optional_pattern is not None:
        wanted += [name for name in header if re.fullmatch(optional_pattern, name) and name not in wanted]
    index = {name: header.index(name) for name in wanted}
    columns = {name: np.empty(len(rows)) for name in wanted}
    for i, (row, number) in enumerate(zip(rows, lines, strict=True)):
        for name, j in index.items():
            if j >= len(row):
                raise DataError(f"no value: the row has {len(row)} cells, the header {len(header)}", path=path,
                                line=number, column=name, column_number=j + 1)  # fmt: skip
            cell = row[j].strip()
            try:
                value = float(cell)
            except ValueError:
                value = math.nan
            if not math.isfinite(value):
                raise DataError(f"not a finite number: {cell!r}", path=path, line=number, column=name,
                                column_number=j + 1)  # fmt: skip
            columns[name][i] = value
    if len(rows) < minimum:
        raise DataError(f"{len(rows)} samples; at least {minimum} are needed", path=path)
    return columns, lines, {name: j + 1 for name, j in index.items()}


def _check_increasing(t, path, lines, name, number):
    bad = np.flatnonzero(np.diff(t) <= 0)
    if bad.size:
        i = int(bad[0]) + 1
        raise DataError(f"time does not increase: {t[i]:.9g} s after {t[i - 1]:.9g} s on line {lines[i - 1]}",
                        path=path, line=lines[i], column=name, column_number=number)  # fmt: skip


def _noise_level(y) -> float:
    """Robust standard deviation of white noise on a smooth trace, from its first differences.

    The smaller of the estimates over the whole trace (the pulse is a small part of it) and
    over its quiet start (its first 5 %, before the wave arrives): ringing of the chain
    after the pulse raises the first, a record that starts late the second.
    """

    def robust(d):
        return float(1.4826 * np.median(np.abs(d - np.median(d))) / math.sqrt(2.0))

    return min(robust(np.diff(y)), robust(np.diff(y[: max(4, y.size // 20)])))


def _baseline(y) -> float:
    """The trace's level before anything happens: median of its first 5 % of samples (at least 3)."""
    return float(np.median(y[: max(3, y.size // 20)]))


def _pulse_problem(y) -> str | None:
    """Why ``y`` has no usable pulse (None if it has one): it must rise PULSE_NOISE_RATIO noise levels."""
    excursion = float(np.max(y) - _baseline(y))
    noise = _noise_level(y)
    if excursion > PULSE_NOISE_RATIO * noise and excursion > 0:
        return None
    return (f"no pulse: the trace rises at most {excursion:.4g} N above its starting level, within "
            f"{PULSE_NOISE_RATIO:g} noise levels ({noise:.3g} N each); negate an inverted channel")  # fmt: skip


def read_traces(path):
    """Read sensor force traces: the CSV that ``ringchain simulate --out`` writes.

    Parameters
    ----------
    path : str or path
        CSV file with a header line: ``t_s`` (time, s) and one column
        ``sensor_ring<k>_N`` (force, N, tension positive) per sensor ring k, counted from the
        impact as the package counts rings (ring 0 is the one struck).  Lines starting with
        ``#`` are comments; other columns are ignored.  The sampling need not be uniform, the
        time need not start at the impact (a trigger offset is fitted) and a channel may
        carry a DC offset (fitted too).

    Returns
    -------
    t : ndarray
        Times, s, increasing.
    traces : dict
        {k: force (N) of the sensor in ring k}, ring order of the file.

    Raises
    ------
    DataError
        A missing column, a time that does not increase, a cell that is not a finite number
        (NaN), fewer than :data:`MIN_SAMPLES` samples, or a trace without a pulse; the
        message names the file, line and column.

    Examples
    --------
    >>> import tempfile
    >>> t = np.linspace(0.0, 1e-3, 50)
    >>> rows = "".join(f"{x},{np.exp(-((x - 5e-4) / 1e-4) ** 2)}\\n" for x in t)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = Path(folder) / "run.csv"
    ...     _ = path.write_text("t_s,sensor_ring6_N\\n" + rows)
    ...     t_read, traces = read_traces(path)
    >>> t_read.size, list(traces)
    (50, [6])
    """
    columns, lines, numbers = _read_table(path, ["t_s"], optional_pattern=r"sensor_ring\d+_N")
    sensors = [name for name in columns if name != "t_s"]
    if not sensors:
        raise DataError("missing column(s): need at least one sensor_ring<k>_N column (force in N of the sensor "
                        "in ring k)", path=path)  # fmt: skip
    t = columns["t_s"]
    _check_increasing(t, path, lines, "t_s", numbers["t_s"])
    traces = {}
    for name in sensors:
        problem = _pulse_problem(columns[name])
        if problem:
            raise DataError(problem, path=path, column=name, column_number=numbers[name])
        traces[int(re.fullmatch(r"sensor_ring(\d+)_N", name).group(1))] = columns[name]
    return t, traces


def read_static(path):
    """Read a quasi-static force-displacement test.

    Parameters
    ----------
    path : str or path
        CSV file with the columns ``displacement_m`` (m) and ``force_N`` (N, tension
        positive); ``#`` lines are comments, other columns are ignored.

    Returns
    -------
    displacement, force : ndarray

    Raises
    ------
    DataError
        A missing column, a cell that is not a finite number, or fewer than
        :data:`MIN_SAMPLES` rows (file, line, column in the message).
    """
    columns, _, _ = _read_table(path, ["displacement_m", "force_N"])
    return columns["displacement_m"], columns["force_N"]


def read_speed_amplitude(path):
    """Read measured (peak force, wave speed) pairs for :func:`fit_speed_amplitude`.

    Parameters
    ----------
    path : str or path
        CSV file with ``peak_force_N`` and ``speed_m_s``, or the columns of a
        ``ringchain sweep`` file, ``peak_force_near_N`` and ``wave_speed_m_s``; at least 3 rows.

    Returns
    -------
    F_m, V_s : ndarray
        N and m/s.
    """
    columns, _, _ = _read_table(path, [("peak_force_N", "speed_m_s"), ("peak_force_near_N", "wave_speed_m_s")],
                                minimum=3)  # fmt: skip
    if "peak_force_N" in columns:
        return columns["peak_force_N"], columns["speed_m_s"]
    return columns["peak_force_near_N"], columns["wave_speed_m_s"]


# -- results -------------------------------------------------------------------------------------------
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


@dataclass(frozen=True, eq=False)
class FitResult:
    """What a fit found.

    Attributes
    ----------
    kind : str
        "traces", "static power-law", "static series" or "speed-amplitude".
    names : tuple of str
        The free parameters, in the order of :attr:`correlation`.
    values, stderr : dict
        {name: value}, SI units ("m" in kg, "t0" in s, "v0" in m/s, "offset_*" in N); the
        standard errors are scaled by the reduced chi-square (the noise is estimated from
        the residual).
    intervals : dict
        {name: (low, high)}, 95 % confidence intervals: value -/+ t_{0.975, dof} stderr.
    correlation : ndarray
        Correlation matrix of the free parameters (k, k); :meth:`corr` reads one entry.
    fixed : dict
        Parameters held at their given values.
    residual : ndarray
        Model minus data at every sample (N, or m/s for speeds).
    chisqr, aic, bic : float
        Sum of squared residuals and the Akaike and Bayesian information criteria,
        n ln(chisqr/n) + 2k and n ln(chisqr/n) + k ln n: the lower, the better the data support
        the model (compare models fitted to the same data).
    n_data : int
    n_forward_runs : int
        Parameter sets simulated (each over every record); 0 for fits without a simulation.
    n_batches : int
        Integrator calls that ran them (a batch holds several parameter sets).
    chain : Chain or None
        The fitted chain (trace fits).
    records : tuple of TraceRecord
        Data and fitted model per record (trace fits).
    notes : tuple of str
        Anything the user should know (non-identifiable parameters, misfit above the noise).
    message : str
        The least squares' reason for stopping.
    extra : dict
        More numbers by name (trace fits: "rms_residual_N" and the traces' "noise_N").
    """

    kind: str
    names: tuple
    values: dict
    stderr: dict
    intervals: dict
    correlation: np.ndarray
    fixed: dict
    residual: np.ndarray
    chisqr: float
    aic: float
    bic: float
    n_data: int
    n_forward_runs: int = 0
    n_batches: int = 0
    chain: Chain | None = None
    records: tuple = ()
    notes: tuple = ()
    message: str = ""
    extra: dict = field(default_factory=dict)

    def corr(self, a: str, b: str) -> float:
        """Correlation coefficient of the free parameters ``a`` and ``b``."""
        for name in (a, b):
            if name not in self.names:
                raise KeyError(f"{name!r} is not a free parameter of this fit; free: {', '.join(self.names)}")
        return float(self.correlation[self.names.index(a), self.names.index(b)])

    def to_dict(self) -> dict:
        """Plain-Python summary (for JSON): values, stderr, intervals, correlation, criteria."""
        finite = lambda x: None if x is None or not math.isfinite(x) else float(x)  # noqa: E731
        return {
            "kind": self.kind,
            "values": {k: float(x) for k, x in self.values.items()},
            "stderr": {k: finite(x) for k, x in self.stderr.items()},
            "intervals_95": {k: [finite(lo), finite(hi)] for k, (lo, hi) in self.intervals.items()},
            "correlation": {
                a: {b: finite(self.correlation[i, j]) for j, b in enumerate(self.names)}
                for i, a in enumerate(self.names)
            },
            "fixed": {k: float(x) for k, x in self.fixed.items()},
            "chisqr": float(self.chisqr),
            "aic": float(self.aic),
            "bic": float(self.bic),
            "n_data": int(self.n_data),
            "n_forward_runs": int(self.n_forward_runs),
            "notes": list(self.notes),
            **{k: finite(x) for k, x in self.extra.items()},
        }

    def report(self) -> str:
        """A readable table of the fit."""
        lines = [f"{self.kind} fit: {self.n_data} data, {len(self.names)} free parameters"]
        rows = [("parameter", "value", "std. error", "95 % interval", "unit")]
        for name in self.names:
            lo, hi = self.intervals[name]
            rows.append((name, f"{self.values[name]:.6g}", f"{self.stderr[name]:.3g}", f"[{lo:.6g}, {hi:.6g}]",
                         _unit(name)))  # fmt: skip
        widths = [max(len(r[j]) for r in rows) for j in range(5)]
        lines += ["  " + "  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows]
        if self.fixed:
            fixed = ", ".join(f"{k} = {x:.6g}" + (f" {_unit(k)}" if _unit(k) else "") for k, x in self.fixed.items())
            lines.append(f"  fixed: {fixed}")
        strong = [(a, b, self.correlation[i, j]) for i, a in enumerate(self.names)
                  for j, b in enumerate(self.names) if j > i and abs(self.correlation[i, j]) > 0.5]  # fmt: skip
        if strong:
            lines.append("  correlations above 0.5: " + ", ".join(f"{a}-{b} {r:+.3f}" for a, b, r in strong))
        lines.append(f"  chi-square {self.chisqr:.6g}, AIC {self.aic:.6g}, BIC {self.bic:.6g}")
        if self.n_forward_runs:
            lines.append(f"  forward runs {self.n_forward_runs} in {self.n_batches} integrator calls")
        lines += [f"  note: {note}" for note in self.notes]
        return "\n".join(lines)


def _unit(name: str) -> str:
    base = name.split("_")[0] if name.startswith(("t0_", "v0_", "offset_")) else name
    return _UNITS.get(base, "")


def _check_converged(kind, out, names):
    """Raise FitError unless the least squares converged."""
    if not out.success or getattr(out, "aborted", False):
        message = getattr(out, "message", "") or "no message"
        values = ", ".join(f"{k} = {out.params[k].value:.6g}" for k in names)
        raise FitError(f"the {kind} fit did not converge after {out.nfev} evaluations ({message}); last values: "
                       f"{values}; give better starting values, fix a parameter or allow more evaluations")  # fmt: skip


def _weak_directions(out, names, threshold):
    """(singular values, right singular vectors, column norms, indices of the weak ones) of the
    Jacobian with unit columns: weak means below ``threshold`` times the largest; None if the
    result carries no Jacobian."""
    jac = getattr(out, "jac", None)
    if jac is None or np.ndim(jac) != 2 or jac.shape[1] != len(names):
        return None
    norms = np.linalg.norm(jac, axis=0)
    norms = np.where(norms > 0, norms, 1.0)
    _, sv, vt = np.linalg.svd(jac / norms, full_matrices=False)
    return sv, vt, norms, np.flatnonzero(sv < threshold * sv[0])


def _dominated(names, sv, vt, unresolved):
    """Parameters whose variance comes mostly from the ``unresolved`` singular directions.

    A parameter's variance is the sum over the directions of (component / singular value)^2;
    where the unresolved directions give more than half of it, its standard error measures
    only how flat the valley is computed to be.
    """
    if len(unresolved) == 0:
        return []
    share = np.square(vt / np.maximum(sv, 1e-300)[:, None])
    rest = np.setdiff1d(np.arange(sv.size), unresolved)
    null, other = share[unresolved].sum(axis=0), share[rest].sum(axis=0)
    return [name for name, a, b in zip(names, null, other, strict=True) if a > b]


def _unresolved(out, names, resolution):
    """Free parameters the data do not determine, or []: the singular directions of the Jacobian
    with unit columns below ``resolution`` times the largest (the Jacobian's own relative error,
    with a margin), an exact symmetry computed as noise (:func:`_dominated`)."""
    weak = _weak_directions(out, names, resolution)
    if weak is None:
        return []
    sv, vt, _, indices = weak
    return _dominated(names, sv, vt, indices)


def _result_from_lmfit(kind, out, names, residual, *, spread, resolution=None, unresolved=None, covariance=None,
                       fixed=None, **more) -> FitResult:  # fmt: skip
    """A FitResult from an lmfit MinimizerResult.

    Raises FitError unless it converged to a point that explains some of the data: a
    residual sum of squares below ``spread``, that of the data about their mean (a start so
    far off that the gradient vanishes can stop the least squares "successfully" anywhere).
    Parameters the data do not determine (``unresolved``, or :func:`_unresolved` at
    ``resolution``) get an infinite standard error and a note; ``covariance`` replaces lmfit's.
    """
    from scipy import stats

    _check_converged(kind, out, names)
    chisqr = float(np.sum(np.square(residual)))
    if not chisqr < spread:
        values = ", ".join(f"{k} = {out.params[k].value:.6g}" for k in names)
        raise FitError(f"the {kind} fit stopped ({out.message}) at a point that explains none of the data (sum of "
                       f"squared residuals {chisqr:.4g} >= {spread:.4g} about the mean): {values}; give better "
                       "starting values")  # fmt: skip
    k = len(names)
    n = int(np.size(residual))
    dof = max(n - k, 1)
    quantile = float(stats.t.ppf(0.975, dof))
    values = {name: float(out.params[name].value) for name in names}
    notes = list(more.pop("notes", ()))
    covar = out.covar if covariance is None else covariance
    if covar is None or not np.all(np.isfinite(covar)):
        stderr = dict.fromkeys(names, math.inf)
        correlation = np.full((k, k), np.nan)
        np.fill_diagonal(correlation, 1.0)
        notes.append("the parameters are not identifiable from these data (singular Jacobian): no error estimate")
    else:
        covar = np.asarray(covar, dtype=float)
        sd = np.sqrt(np.clip(np.diag(covar), 0.0, None))
        stderr = dict(zip(names, (float(s) for s in sd), strict=True))
        with np.errstate(invalid="ignore", divide="ignore"):
            correlation = covar / np.outer(sd, sd)
    if unresolved is None:
        unresolved = _unresolved(out, names, resolution)
    if unresolved:
        stderr.update(dict.fromkeys(unresolved, math.inf))
        for name in unresolved:  # no correlation either: a valley has no shape to measure
            i = names.index(name)
            correlation[i, :] = correlation[:, i] = np.nan
            correlation[i, i] = 1.0
        notes.append(f"not identifiable from these data: {', '.join(unresolved)} (a combination of them leaves the "
                     "residuals unchanged); their values are one point of a valley of equally good fits")  # fmt: skip
    intervals = {name: (values[name] - quantile * stderr[name], values[name] + quantile * stderr[name])
                 for name in names}  # fmt: skip
    log_likelihood_term = n * math.log(chisqr / n) if chisqr > 0 else -math.inf
    return FitResult(
        kind=kind, names=tuple(names), values=values, stderr=stderr, intervals=intervals, correlation=correlation,
        fixed=dict(fixed or {}), residual=np.asarray(residual, dtype=float), chisqr=chisqr,
        aic=log_likelihood_term + 2 * k, bic=log_likelihood_term + k * math.log(n), n_data=n, notes=tuple(notes),
        message=str(getattr(out, "message", "")), **more,
    )  # fmt: skip


def _minimize(residual, params, jac=None, **options):
    """lmfit least squares (trust-region reflective, Jacobian-scaled variables)."""
    from lmfit import Minimizer

    kws = {"x_scale": "jac", **options}
    if jac is not None:
        kws["jac"] = jac
    return Minimizer(residual, params, scale_covar=True).minimize(method="least_squares", **kws)


def _as_data(name, value, unit, minimum=MIN_SAMPLES):
    array = v.as_float(name, value)
    if array.ndim != 1:
        raise ValueError(f"{name} must be a 1-d array ({unit}), got shape {array.shape}")
    if array.size < minimum:
        raise ValueError(f"{name} has {array.size} samples; at least {minimum} are needed")
    return array


# -- quasi-static fits ---------------------------------------------------------------------------------
STATIC_MODELS = ("power-law", "series")


def _series_force(delta, K_c, K_b):
    """Force F(delta) of the series law (Eq. 3), inverting delta(F) of ringchain.theory by Newton.

    delta(F) = series_displacement is increasing and concave, so Newton's iteration from
    the lower bound F = min(K_c (delta/2)^(3/2), K_b delta/2) (each spring takes at most
    all of delta, at least half for one of them) rises monotonically to the root; the
    slope is d delta/dF = delta/(F n(F)) with the local exponent n(F).
    """
    from ringchain.theory import local_exponent, series_displacement

    delta = np.asarray(delta, dtype=float)
    positive = delta > 0
    d = delta[positive]
    F = np.minimum(K_c * (0.5 * d) ** 1.5, 0.5 * K_b * d)
    for _ in range(60):
        dd = series_displacement(F, K_c=K_c, K_b=K_b)
        step = (d - dd) * F * local_exponent(F, K_c=K_c, K_b=K_b) / dd
        F = F + step
        if np.all(np.abs(step) <= 1e-13 * F):
            break
    out = np.zeros_like(delta)
    out[positive] = F
    return out


def _power_force(delta, K, n):
    return K * np.maximum(delta, 0.0) ** n


def _static_start(delta, force, model):
    """Starting values by linear regressions: log-log (power law) or delta on (F^(2/3), F) (series)."""
    use = (delta > 0) & (force > 0)
    if np.count_nonzero(use) < 3:
        raise ValueError("fit_static needs at least 3 samples with positive displacement and force")
    d, F = delta[use], force[use]
    if model == "power-law":
        n, log_K = np.polyfit(np.log(d), np.log(F), 1)
        return {"K": float(np.exp(log_K)), "n": float(n)}
    from scipy.optimize import nnls

    (c, b), _ = nnls(np.column_stack([F ** (2.0 / 3.0), F]), d)  # delta = c F^(2/3) + b F
    scale_c, scale_b = float(np.sum(d) / np.sum(F ** (2.0 / 3.0))), float(np.sum(d) / np.sum(F))
    c, b = max(c, 1e-3 * scale_c), max(b, 1e-3 * scale_b)
    return {"K_c": float(c**-1.5), "K_b": float(1.0 / b)}


def fit_static(displacement, force, model="power-law", *, offset=False, start=None, max_nfev=None) -> FitResult:
    """Fit a quasi-static force-displacement test: F = K delta^n (Eq. 4) or the series law (Eq. 3).

    Parameters
    ----------
    displacement : array_like
        Extension of the contact (or of the pair of rings), m.
    force : array_like
        Tensile force, N; same length, at least :data:`MIN_SAMPLES` samples.
    model : {"power-law", "series"}
        "power-law": F = K (delta - delta0)_+^n, free K (N/m^n) and n.  "series": Hertz
        contact K_c (n = 3/2, Eq. 1) in series with linear bending K_b (Eq. 2),
        delta - delta0 = (F/K_c)^(2/3) + F/K_b (Eq. 3,
        :func:`ringchain.theory.series_displacement`), free K_c (N/m^1.5) and K_b (N/m).
    offset : bool, optional
        Also fit the displacement offset delta0 (m): the zero of a tensile test is uncertain.
    start : dict, optional
        Starting values by name (default: from linear regressions of the data).
    max_nfev : int, optional
        Most residual evaluations (default lmfit's).

    Returns
    -------
    FitResult
        Values, standard errors, 95 % intervals, correlation matrix, AIC and BIC.  The
        residuals are in force (the force is the noisy reading), so the criteria of the two
        models fitted to the same data compare directly: the lower AIC is the law the data
        support.

    Raises
    ------
    FitError
        If the least squares do not converge.

    Examples
    --------
    >>> delta = np.linspace(2e-6, 4e-5, 30)
    >>> fit = fit_static(delta, 4.9e6 * delta**1.11, "power-law")
    >>> round(fit.values["n"], 6), round(fit.values["K"] / 4.9e6, 6)
    (1.11, 1.0)
    """
    import lmfit

    if model not in STATIC_MODELS:
        raise ValueError(f"model must be one of {STATIC_MODELS}, got {model!r}")
    delta = _as_data("displacement", displacement, "m")
    F = _as_data("force", force, "N")
    if delta.shape != F.shape:
        raise ValueError(f"displacement and force must have the same length, got {delta.size} and {F.size}")
    guess = _static_start(delta, F, model)
    guess.update(start or {})
    params = lmfit.Parameters()
    if model == "power-law":
        params.add("K", value=guess["K"], min=0.0)
        params.add("n", value=guess["n"], min=0.1, max=10.0)
    else:
        params.add("K_c", value=guess["K_c"], min=0.0)
        params.add("K_b", value=guess["K_b"], min=0.0)
    if offset:
        span = float(np.ptp(delta))
        params.add("delta0", value=float(guess.get("delta0", 0.0)), min=float(delta.min()) - span,
                   max=float(delta.max()))  # fmt: skip

    def model_force(p):
        shift = delta - (p["delta0"].value if offset else 0.0)
        if model == "power-law":
            return _power_force(shift, p["K"].value, p["n"].value)
        return _series_force(shift, p["K_c"].value, p["K_b"].value)

    out = _minimize(lambda p: model_force(p) - F, params, max_nfev=max_nfev)
    names = list(params)
    spread = float(np.sum(np.square(F - F.mean())))
    return _result_from_lmfit(f"static {model}", out, names, model_force(out.params) - F, spread=spread,
                              resolution=ANALYTIC_RESOLUTION)  # fmt: skip


# -- speed against amplitude -------------------------------------------------------------------------
def fit_speed_amplitude(F_m, V_s, *, K, n, a, m0, free_n=False, start=1.0, max_nfev=None) -> FitResult:
    """Fit m_eff/m0 (and n) of Eq. (8) to measured (peak force, wave speed) pairs.

    V_s = a sqrt(2/(n+1)) (K^(1/n)/m_eff)^(1/2) F_m^((n-1)/(2n)), m_eff = (m_eff/m0) m0
    (:func:`ringchain.theory.solitary_wave_speed`), fitted to the speeds (m/s).

    Parameters
    ----------
    F_m : array_like
        Peak forces, N (at the near sensor, as the paper reads its Fig. 4); at least 2
        pairs (3 with ``free_n``).
    V_s : array_like
        Wave speeds, m/s (time of flight between the sensors).
    K : float
        Power-law stiffness, N/m^n (e.g. from :func:`fit_static`); held fixed in N/m^n.
    n : float
        Exponent (> 1); the starting value if ``free_n``.
    a : float
        Ring spacing, m (a = 2(R - r)).
    m0 : float
        Ring mass, kg.
    free_n : bool, optional
        Fit n too.
    start : float, optional
        Starting m_eff/m0 (default 1).
    max_nfev : int, optional
        Most residual evaluations (default lmfit's).

    Returns
    -------
    FitResult
        "m_eff_ratio" (and "n").  Eq. (8) depends on K^(1/n)/m_eff only: the fitted ratio
        is as good as the K it is given.

    Examples
    --------
    >>> from ringchain.theory import solitary_wave_speed
    >>> F = np.geomspace(2.0, 80.0, 12)
    >>> V = solitary_wave_speed(F, K=4.9e6, n=1.11, m=0.37 * 8.2e-3, a=0.04)
    >>> fit = fit_speed_amplitude(F, V, K=4.9e6, n=1.11, a=0.04, m0=8.2e-3, start=0.5)
    >>> round(fit.values["m_eff_ratio"], 6)
    0.37
    """
    import lmfit
    from ringchain.theory import solitary_wave_speed

    least = 3 if free_n else 2  # one more pair than free parameters, for an error estimate
    F_m = v.positive("F_m", _as_data("F_m", F_m, "N", least), "N")
    V_s = v.positive("V_s", _as_data("V_s", V_s, "m/s", least), "m/s")
    if F_m.shape != V_s.shape:
        raise ValueError(f"F_m and V_s must have the same length, got {F_m.size} and {V_s.size}")
    K = float(v.positive("K", K, "N/m^n"))
    n = float(v.in_range("n", n, 1.0, np.inf, closed_high=False))
    a = float(v.positive("a", a, "m"))
    m0 = float(v.positive("m0", m0, "kg"))
    start = float(v.positive("start", start))
    params = lmfit.Parameters()
    params.add("m_eff_ratio", value=start, min=0.0)
    params.add("n", value=n, min=1.0 + 1e-9, vary=bool(free_n))

    def speeds(p):
        return solitary_wave_speed(F_m, K=K, n=p["n"].value, m=p["m_eff_ratio"].value * m0, a=a)

    out = _minimize(lambda p: speeds(p) - V_s, params, max_nfev=max_nfev)
    names = ["m_eff_ratio", "n"] if free_n else ["m_eff_ratio"]
    fixed = {"K": K, "a": a, "m0": m0, **({} if free_n else {"n": n})}
    spread = float(np.sum(np.square(V_s - V_s.mean())))
    return _result_from_lmfit("speed-amplitude", out, names, speeds(out.params) - V_s, spread=spread,
                              resolution=ANALYTIC_RESOLUTION, fixed=fixed)  # fmt: skip


# -- trace fits: the forward model --------------------------------------------------------------------
def _simulate_parameter_sets(chains, speeds, dropped, t_grid, rings, *, rtol=FIT_RTOL, gravity=True,
                             g=STANDARD_GRAVITY, batched=True):  # fmt: skip
    """(parameter sets) -> simulated sensor forces: the forward model of :func:`fit_traces`.

    Parameters
    ----------
    chains : sequence of Chain, length P
        One chain per parameter set (same model and number of rings).
    speeds : ndarray, shape (P, R)
        Impact speed of each record under each parameter set, m/s.
    dropped : sequence of bool, length R
        Whether record r is a drop (initial state of :func:`initial_state` with a drop height).
    t_grid : ndarray
        Times after the impact, s, from 0.
    rings : sequence of sequences
        Sensor rings of each record.
    batched : bool
        Integrate all P x R runs as one array problem (default), or one
        :func:`~ringchain.numerics.simulate` call per run.

    Returns
    -------
    list of ndarray
        Per record, the sensor forces of shape (P, n_rings of the record, len(t_grid)), N.

    Notes
    -----
    The batch is the chains' lattices stacked (:meth:`Lattice.stack`, run b on chain b)
    and integrated as :func:`simulate_batch` integrates a batch of runs of one chain
    (the same driver, :func:`ringchain.numerics.solve._adaptive`, and tolerances).
    """
    P, R = speeds.shape
    if not batched or P * R == 1:
        out = [np.empty((P, len(ks), t_grid.size)) for ks in rings]
        for p, chain in enumerate(chains):
            for r in range(R):
                impact = _impact(speeds[p, r], dropped[r], g)
                sim = simulate(chain, t_grid[-1], t_eval=t_grid, rtol=rtol, gravity=gravity, g=g, **impact)
                out[r][p] = sim.sensor_force[:, list(rings[r])].T
        return out
    runs = [(chain, r) for chain in chains for r in range(R)]
    x0, u0, scales = [], [], []
    for (chain, r), speed in zip(runs, speeds.ravel(), strict=True):
        x, u = initial_state(chain, gravity=gravity, g=g, **_impact(speed, dropped[r], g))
        x0.append(x[0])
        u0.append(u[0])
        scales.append(np.concatenate(_scales(chain, x, -u[:, 0], g)))
    x0, u0, scales = np.array(x0), np.array(u0), np.array(scales)
    lat = Lattice.stack([chain.lattice for chain, _ in runs])
    xs, us, _, _ = _adaptive("odeint", lat, x0, u0, scales.T, t_grid, rtol, rtol, g if gravity else 0.0, None,
                             watch=lambda *state: None)  # fmt: skip
    out = [np.empty((P, len(ks), t_grid.size)) for ks in rings]
    for b, (chain, r) in enumerate(runs):
        sim = Simulation(chain=chain, t=t_grid, x=xs[b], u=us[b],
                         dissipated=np.zeros(t_grid.size), g=g, impact_velocity=float(speeds.flat[b]),
                         drop_height=None)  # fmt: skip
        out[r][b // R] = sim.sensor_force[:, list(rings[r])].T
    return out


def _impact(speed, dropped, g):
    return {"drop_height": speed**2 / (2.0 * g)} if dropped else {"impact_velocity": speed}


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
        t_r = _as_data(f"t{where}", t_r, "s")
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
            problem = _pulse_problem(y)
            if problem:
                raise ValueError(f"traces[{k}]{where}: {problem}")
        if (h is None) == (speed is None):
            raise ValueError(f"give a drop height or an impact velocity{where}, one of the two")
        if h is not None:
            h = float(v.positive(f"drop_height{where}", h, "m"))
            speed = math.sqrt(2.0 * STANDARD_GRAVITY * h)
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
        self.suffix = [""] if len(records) == 1 else [f"_{i}" for i in range(len(records))]
        # Grid of the forward runs: the finest measured sampling (median step).
        self.dt_grid = min(float(np.median(np.diff(rec.t))) for rec in records)
        self.force_scale = max(float(np.max(y) - _baseline(y)) for rec in records for y in rec.force)

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
        the largest measured force (the bending stiffness if lower); the scale of a dashpot near 0."""
        F = self.force_scale
        k = chain.n * chain.K ** (1.0 / chain.n) * F ** ((chain.n - 1.0) / chain.n)
        if chain.K_b is not None:
            k = min(k, chain.K_b)
        return math.sqrt(chain.m * k)

    def chain_at(self, values):
        return dataclasses.replace(self.chain, **{k: values[k] for k in self.chain_free})

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
        forces = _simulate_parameter_sets(
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
        """Model of each record (C, T) at ``values`` (one forward run; the last one is cached)."""
        key = tuple(sorted(values.items()))
        if self._last is None or self._last[0] != key:
            t0s = self.t0s(values)
            self._last = key, [m[0] for m in self.model(self.simulate([values], t0s), values, t0s)]
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
    those whose variance the direction dominates (:func:`_dominated`) are undetermined.
    Otherwise the rise gives the held parameter's variance, shift^2 sigma^2 / rise, and the
    direction's singular value is set to reproduce it.
    """
    params = out.params
    names = [name for name, p in params.items() if p.vary]
    weak = _weak_directions(out, names, JACOBIAN_RESOLUTION)
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
            refit = _minimize(problem.residual, trial, jac=problem.jacobian, **options)
            rise = (float(np.sum(np.square(problem.residual(refit.params)))) - ssr) / sigma2
            if not refit.success:  # cannot tell: no error bars rather than wrong ones
                rise = 0.0
            if rise < 1.0:
                moved = [k for k in names if k != held and abs(refit.params[k].value - values[k]) > 2 * stderr[k]]
                undetermined.update([held, *moved, *_dominated(names, sv, vt, [i])])
                inverse_square[i] = 0.0
            else:  # sum over directions of (component / singular value)^2 = variance (norm^2 / sigma^2)
                target = shift**2 / rise * norms[j] ** 2 / sigma2
                others = float(np.sum(np.square(vt[:, j]) * inverse_square)) - vt[i, j] ** 2 * inverse_square[i]
                if target > others:
                    inverse_square[i] = (target - others) / vt[i, j] ** 2
            break
    covariance = sigma2 * (vt.T * inverse_square) @ vt / np.outer(norms, norms)
    return covariance, [k for k in names if k in undetermined]


def _noisy_peak(t, y):
    """Time (s) and height of the leading peak of a noisy trace (above its starting level).

    :func:`signals.peak` takes the first run of samples above half the maximum, which noise
    breaks into pieces on the rising edge.  Here the pulse runs from the first sample above
    half the maximum until the trace falls below a quarter of it (noise of a few per cent
    cannot cross that gap), and its peak is the vertex of the parabola fitted to the
    samples of the pulse above 80 % of its largest one.
    """
    y = y - _baseline(y)
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


def _align(problem, values, *, iterations=4):
    """Starting values from the pulses: t0 from the arrival at the first sensor, the speed
    parameter (m, else K) from the time of flight, v0 from the peak height.

    With the scaling of the power-law chain at a fixed impact speed (time ~ (m/K)^(1/(n+1)),
    force ~ K^(1/(n+1)) m^(n/(n+1)) v0^(2n/(n+1))), each update is a power of the measured
    over the simulated ratio; a few forward runs bring a start 30 % off within the reach of
    the least squares.
    """
    measured = [_peak_times(rec.t, rec.force) for rec in problem.records]
    n = problem.chain.n
    speed_name = next((k for k in ("m", "K") if k in problem.chain_free), None)
    R = len(problem.records)
    for it in range(iterations):
        splines = problem.simulate([values], [min(0.0, rec.t[0]) for rec in problem.records])
        ratios, amplitudes = [], []
        for r, (spline, meas) in enumerate(zip(splines, measured, strict=True)):
            model = _peak_times(spline.x, spline(spline.x)[0])
            if np.any(model[:, 1] < 0.05 * meas[:, 1]):  # a pulse 20 times smaller is no pulse
                raise FitError(f"the starting chain gives no pulse at the sensors of record {r} within the "
                               "measured window; give better starting values")  # fmt: skip
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

    values = {name: float(getattr(chain, name)) for name in problem.chain_free}
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
    out = _minimize(problem.residual, params, jac=problem.jacobian, **least_squares)
    names = list(params)
    _check_converged("traces", out, names)
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
    noise = math.sqrt(np.mean([_noise_level(y) ** 2 for rec in records for y in rec.force]))
    rms = float(np.sqrt(np.mean(residual**2)))
    notes = []
    # Below MODEL_RESOLUTION of the peak, a misfit is the forward model's own (spline, solver).
    floor = max(noise, MODEL_RESOLUTION * problem.force_scale)
    if rms > 3.0 * floor:
        notes.append(f"the residual ({rms:.3g} N rms) is {rms / floor:.1f} times the noise of the traces "
                     f"({floor:.3g} N): the model misses features of the data, or this is a local minimum")  # fmt: skip
    model_fields = CHAIN_PARAMETERS if chain.model == "dual-spring" else ("m", "gamma", "K", "n")
    fixed = {k: float(getattr(chain, k)) for k in model_fields if k not in problem.chain_free}
    fixed["m_gravity"] = chain.m_gravity
    for r in range(R):
        if not problem.free_t0:
            fixed[problem.name("t0", r)] = problem.fixed_t0[r]
        if not (problem.free_v0 or problem.free_h0):
            fixed[problem.name("v0", r)] = records[r].speed
    spread = sum(float(np.sum(np.square(y - y.mean()))) for rec in records for y in rec.force)
    return _result_from_lmfit(
        "traces", out, names, residual, spread=spread, unresolved=unresolved, covariance=covariance, fixed=fixed,
        n_forward_runs=problem.n_runs,
        n_batches=problem.n_batches, chain=problem.chain_at(final), records=out_records, notes=notes,
        extra={"rms_residual_N": rms, "noise_N": noise},
    )  # fmt: skip
