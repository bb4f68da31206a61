r"""From measurements to parameters: the quasi-static and speed fits, and what every fit returns.

The paper takes K and n "from quasi-static tests" and m_eff/m0 and the dashpots "from
dynamic fitting" (Sec. III.B, IV, Tables I-II).  This module and :mod:`.fit_dynamic` do both,
with lmfit (bounded least squares, standard errors, correlations) on SciPy:

- quasi-static: :func:`fit_static`, F = K delta^n (Eq. 4) or Hertz in series with bending
  (Eq. 3), each with an optional displacement offset;
- speed against amplitude: :func:`fit_speed_amplitude`, m_eff/m0 (and n) through Eq. (8);
- sensor traces: :func:`ringchain.numerics.fit_traces` (module :mod:`.fit_dynamic`);
- the data files: :mod:`.traces`.

Every fit returns a :class:`FitResult` (values, standard errors, 95% intervals,
correlations, information criteria) or raises :class:`FitError`; it never returns an
unconverged answer.  The least-squares helpers below (:func:`minimize`,
:func:`result_from_lmfit`, ...) are shared with the trace fits.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np
from ringchain.theory import _validate as v

from ..engine.traces import MIN_SAMPLES

__all__ = [
    "fit_static",
    "fit_speed_amplitude",
    "fit_speed_rings",
    "FitResult",
    "FitError",
    "STATIC_MODELS",
    "ANALYTIC_RESOLUTION",
    "MINIMUM_STEP",
]

#: The same for the static and speed fits, whose models are closed forms differentiated by
#: lmfit at steps of sqrt(machine epsilon) (Jacobian accurate to ~1e-7).
ANALYTIC_RESOLUTION = 1e-5

#: A static or speed fit has converged when one more Gauss-Newton step would move no free
#: parameter by more than this many standard errors (:func:`check_minimum`).  A stop within
#: ftol = 1e-8 of the least sum of squares leaves about sqrt(1e-8 dof) of them (7e-4 for 50
#: samples, 3e-3 for 1000); one stopped early by an absolute threshold (forces in uN, before
#: minimize scaled the problem: 2.75 times the least chi-square) left 3.8.
MINIMUM_STEP = 0.05

_UNITS = {
    "m": "kg", "gamma": "N s/m", "K": "N/m^n", "n": "", "K_b": "N/m", "gamma_b": "N s/m", "t0": "s", "v0": "m/s",
    "h0": "m", "offset": "N", "delta0": "m", "K_c": "N/m^1.5", "m_eff_ratio": "", "m_gravity": "kg", "a": "m",
    "m0": "kg", "striker_mass": "kg",
}  # fmt: skip


class FitError(RuntimeError):
    """A fit that did not converge (or cannot be trusted); never a silent wrong answer."""


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
    chain: object = None
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
                         unit_of(name)))  # fmt: skip
        widths = [max(len(r[j]) for r in rows) for j in range(5)]
        lines += ["  " + "  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip() for r in rows]
        if self.fixed:
            fixed = ", ".join(
                f"{k} = {x:.6g}" + (f" {unit_of(k)}" if unit_of(k) else "") for k, x in self.fixed.items()
            )
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


def unit_of(name: str) -> str:
    base = name.split("_")[0] if name.startswith(("t0_", "v0_", "offset_")) else name
    return _UNITS.get(base, "")


def check_converged(kind, out, names):
    """Raise FitError unless the least squares converged."""
    if not out.success or getattr(out, "aborted", False):
        message = getattr(out, "message", "") or "no message"
        values = ", ".join(f"{k} = {out.params[k].value:.6g}" for k in names)
        raise FitError(f"the {kind} fit did not converge after {out.nfev} evaluations ({message}); last values: "
                       f"{values}; give better starting values, fix a parameter or allow more evaluations")  # fmt: skip


def weak_directions(out, names, threshold):
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


def dominated(names, sv, vt, unresolved):
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


def unresolved_parameters(out, names, resolution):
    """Free parameters the data do not determine, or []: the singular directions of the Jacobian
    with unit columns below ``resolution`` times the largest (the Jacobian's own relative error,
    with a margin), an exact symmetry computed as noise (:func:`dominated`)."""
    weak = weak_directions(out, names, resolution)
    if weak is None:
        return []
    sv, vt, _, indices = weak
    return dominated(names, sv, vt, indices)


def result_from_lmfit(kind, out, names, residual, *, spread, resolution=None, unresolved=None, covariance=None,
                       fixed=None, data_scale=None, **more) -> FitResult:  # fmt: skip
    """A FitResult from an lmfit MinimizerResult.

    Raises FitError unless it converged to a point that explains some of the data: a
    residual sum of squares below ``spread``, that of the data about their mean (a start so
    far off that the gradient vanishes can stop the least squares "successfully" anywhere);
    and, given the ``data_scale`` of an exact Jacobian's fit, at the minimum (:func:`check_minimum`).
    Parameters the data do not determine (``unresolved``, or :func:`unresolved_parameters` at
    ``resolution``) get an infinite standard error and a note; ``covariance`` replaces lmfit's.
    """
    from scipy import stats

    check_converged(kind, out, names)
    chisqr = float(np.sum(np.square(residual)))
    if not chisqr < spread:
        values = ", ".join(f"{k} = {out.params[k].value:.6g}" for k in names)
        raise FitError(f"the {kind} fit stopped ({out.message}) at a point that explains none of the data (sum of "
                       f"squared residuals {chisqr:.4g} >= {spread:.4g} about the mean): {values}; give better "
                       "starting values")  # fmt: skip
    if data_scale is not None:
        check_minimum(kind, out, names, data_scale)
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
        unresolved = unresolved_parameters(out, names, resolution)
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


def minimize(residual, params, jac=None, *, scales=None, residual_scale=1.0, **options):
    """lmfit least squares (trust-region reflective, Jacobian-scaled variables), solved in units of order one.

    Each free parameter is divided by its scale (``scales[name]``; default its starting
    magnitude, else the width of its bounds, else 1) and the residual by ``residual_scale``
    (the data's), so that the solver's absolute thresholds mean the same in any units: its
    gradient tolerance (forces in uN stopped it early), and the 1e-10 that SciPy keeps a
    start away from a bound (it moved a mass of 8e-12 kg, bounded below by 0, to 1e-10).
    The result is returned in the caller's units: values, standard errors, covariance,
    Jacobian, residual and chi-square.
    """
    from lmfit import Minimizer, Parameters

    free = [name for name, p in params.items() if p.vary]
    scale = {name: _scale_of(params[name], (scales or {}).get(name)) for name in free}
    inner = Parameters()
    for name in free:
        p, s = params[name], scale[name]
        inner.add(name, value=p.value / s, min=p.min / s, max=p.max / s)
    current = params.copy()  # the caller's parameters, set to each trial point in turn

    def physical(q):
        for name in free:
            current[name].value = q[name].value * scale[name]
        return current

    S = np.array([scale[name] for name in free])
    kws = {"x_scale": "jac", **options}
    if jac is not None:
        kws["jac"] = lambda q: np.asarray(jac(physical(q))) * (S / residual_scale)
    # Exact data fitted exactly: lmfit divides zero covariances by zero standard errors for its correlations.
    with np.errstate(invalid="ignore", divide="ignore"):
        out = Minimizer(lambda q: np.asarray(residual(physical(q))) / residual_scale, inner, scale_covar=True).minimize(
            method="least_squares", **kws
        )
    found = params.copy()
    for name in free:
        q = out.params[name]
        found[name].value = q.value * scale[name]
        found[name].stderr = None if q.stderr is None else q.stderr * scale[name]
        found[name].correl = q.correl
    out.params = found
    if out.covar is not None:
        out.covar = out.covar * np.outer(S, S)
    if getattr(out, "jac", None) is not None:
        out.jac = np.asarray(out.jac) * (residual_scale / S)
    out.residual = np.asarray(out.residual) * residual_scale
    out.chisqr, out.redchi = out.chisqr * residual_scale**2, out.redchi * residual_scale**2
    return out


def _scale_of(param, given) -> float:
    """The scale of a free parameter in :func:`minimize`."""
    for scale in (given, abs(param.value), param.max - param.min):
        if scale is not None and math.isfinite(scale) and scale > 0:
            return float(scale)
    return 1.0


def check_minimum(kind, out, names, data_scale):
    """Raise FitError if the least squares stopped short of the minimum: one Gauss-Newton step from the
    result (the solve of J dx = -r) would move a free parameter that is not at a bound by more than
    :data:`MINIMUM_STEP` of its standard error.  Skipped when the data are fitted to within
    1e-6 of ``data_scale`` rms, better than any measurement: noise-free data, whose standard errors
    are the solver's own tolerance (xtol, 1e-8 relative)."""
    jac, residual, covar = getattr(out, "jac", None), np.asarray(out.residual), out.covar
    if jac is None or covar is None or np.sqrt(np.mean(residual**2)) < 1e-6 * data_scale:
        return
    step = np.linalg.lstsq(np.asarray(jac), -residual, rcond=None)[0]
    sd = np.sqrt(np.clip(np.diag(covar), 0.0, None))
    for name, dx, sigma in zip(names, step, sd, strict=True):
        p = out.params[name]
        at_bound = any(math.isfinite(b) and abs(p.value - b) <= 1e-9 * max(abs(b), abs(p.value))
                       for b in (p.min, p.max))  # fmt: skip
        if not at_bound and sigma > 0 and abs(dx) > MINIMUM_STEP * sigma:
            raise FitError(f"the {kind} fit stopped short of the minimum ({out.message}): one more step moves {name} "
                           f"by {abs(dx) / sigma:.3g} standard errors, from {p.value:.6g}; give better starting values "
                           "or allow more evaluations")  # fmt: skip


def as_data(name, value, unit, minimum=MIN_SAMPLES):
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
    delta = as_data("displacement", displacement, "m")
    F = as_data("force", force, "N")
    if delta.shape != F.shape:
        raise ValueError(f"displacement and force must have the same length, got {delta.size} and {F.size}")
    for name, array, unit in (("displacement", delta, "m"), ("force", F, "N")):
        if np.ptp(array) == 0:
            raise ValueError(f"{name} takes one value, {array[0]:g} {unit}, at every sample: a static test needs a "
                             "range of loads")  # fmt: skip
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

    scale = float(np.max(np.abs(F)))  # the fit is solved in units of the data (minimize)
    scales = {"delta0": float(np.ptp(delta))}
    out = minimize(lambda p: model_force(p) - F, params, scales=scales, residual_scale=scale, max_nfev=max_nfev)
    names = list(params)
    spread = float(np.sum(np.square(F - F.mean())))
    return result_from_lmfit(f"static {model}", out, names, model_force(out.params) - F, spread=spread,
                              resolution=ANALYTIC_RESOLUTION, data_scale=scale)  # fmt: skip


# -- speed against amplitude -------------------------------------------------------------------------
def fit_speed_amplitude(F_m, V_s, *, K, n, a, m0, free_n=False, start=None, max_nfev=None) -> FitResult:
    """Fit m_eff/m0 (and n) of Eq. (8) to measured (peak force, wave speed) pairs.

    V_s = a sqrt(2/(n+1)) (K^(1/n)/m_eff)^(1/2) F_m^((n-1)/(2n)), m_eff = (m_eff/m0) m0
    (:func:`ringchain.theory.solitary_wave_speed`), fitted to the speeds (m/s).

    Parameters
    ----------
    F_m : array_like
        Peak forces, N (at the near sensor, as the paper reads its Fig. 4); at least 2
        pairs (3 with ``free_n``, and then forces that differ).
    V_s : array_like
        Wave speeds, m/s (time of flight between the sensors).
    K : float or array_like
        Power-law stiffness, N/m^n (e.g. from :func:`fit_static`); held fixed in N/m^n.  One
        value, or one per pair (pairs measured on different rings; also ``n``, ``a``, ``m0``).
    n : float or array_like
        Exponent (> 1); the starting value if ``free_n`` (then one value).
    a : float or array_like
        Ring spacing, m (a = 2(R - r)).
    m0 : float or array_like
        Ring mass, kg.
    free_n : bool, optional
        Fit n too.
    start : float, optional
        Starting m_eff/m0; default the least-squares value at the starting n (V_s is
        proportional to (m_eff/m0)^(-1/2), a linear least squares in that power).
    max_nfev : int, optional
        Most residual evaluations (default lmfit's).

    Returns
    -------
    FitResult
        "m_eff_ratio" (and "n").  Eq. (8) depends on K^(1/n)/m_eff only: the fitted ratio
        is as good as the K it is given.  ``fixed`` holds K, n, a and m0 where every pair
        shares them.

    Raises
    ------
    FitError
        If the least squares do not converge, or the ratio comes out above 1 (its whole 95 %
        interval): the speeds are then slower than rings of their own mass allow, which
        points to speeds or forces in other units (km/s, kN) or the wrong rings.

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
    F_m = v.positive("F_m", as_data("F_m", F_m, "N", least), "N")
    V_s = v.positive("V_s", as_data("V_s", V_s, "m/s", least), "m/s")
    if F_m.shape != V_s.shape:
        raise ValueError(f"F_m and V_s must have the same length, got {F_m.size} and {V_s.size}")
    chain = {"K": v.positive("K", K, "N/m^n"), "n": v.in_range("n", n, 1.0, np.inf, closed_high=False),
             "a": v.positive("a", a, "m"), "m0": v.positive("m0", m0, "kg")}  # fmt: skip
    for name, value in chain.items():
        if value.ndim > 1 or value.size not in (1, F_m.size):
            raise ValueError(f"{name} must be one value or one per pair ({F_m.size}), got shape {value.shape}")
    K, n, a, m0 = (value if value.size > 1 else float(value) for value in chain.values())
    if free_n and np.ndim(n):
        if np.ptp(n) > 0:
            raise ValueError(f"free_n fits one exponent, but the pairs' exponents differ ({np.min(n):.6g} to "
                             f"{np.max(n):.6g}): fit the pairs of one ring at a time")  # fmt: skip
        n = float(n[0])
    if free_n and np.ptp(F_m) == 0:
        raise ValueError(f"free_n needs peak forces that differ: every F_m is {F_m[0]:g} N, and n shapes V_s(F_m)")
    if start is None:  # V_s = c g(F_m) with c = (m_eff/m0)^(-1/2) and g the speeds at m_eff = m0
        g = solitary_wave_speed(F_m, K=K, n=float(np.ravel(n)[0]) if free_n else n, m=m0, a=a)
        start = (float(np.sum(g * g)) / float(np.sum(g * V_s))) ** 2
    start = float(v.positive("start", start))
    params = lmfit.Parameters()
    params.add("m_eff_ratio", value=start, min=0.0)
    params.add("n", value=float(np.ravel(n)[0]), min=1.0 + 1e-9, vary=bool(free_n))

    def speeds(p):
        exponent = p["n"].value if free_n else n
        return solitary_wave_speed(F_m, K=K, n=exponent, m=p["m_eff_ratio"].value * m0, a=a)

    scale = float(np.max(V_s))  # solved in units of the data (minimize)
    out = minimize(lambda p: speeds(p) - V_s, params, residual_scale=scale, max_nfev=max_nfev)
    names = ["m_eff_ratio", "n"] if free_n else ["m_eff_ratio"]
    fixed = {name: float(value) for name, value in (("K", K), ("a", a), ("m0", m0), ("n", n))
             if np.ndim(value) == 0 and not (free_n and name == "n")}  # fmt: skip
    # Equal forces: Eq. (8) is one number for every pair, and the best fit is the mean; a zero speed explains none.
    spread = float(np.sum(np.square(V_s - (V_s.mean() if np.ptp(F_m) > 0 else 0.0))))
    result = result_from_lmfit("speed-amplitude", out, names, speeds(out.params) - V_s, spread=spread,
                               resolution=ANALYTIC_RESOLUTION, fixed=fixed, data_scale=scale)  # fmt: skip
    ratio, (low, _) = result.values["m_eff_ratio"], result.intervals["m_eff_ratio"]
    if low > 1.0:
        slower = math.sqrt(ratio)  # V_s ~ m_eff^(-1/2) at a given force
        raise FitError(f"m_eff/m0 = {ratio:.4g} (95 % interval from {low:.4g}) lies above 1: the speeds are "
                       f"{slower:.3g} times slower than Eq. (8) allows for rings of their own mass; are they in m/s "
                       "and the forces in N, and are the rings (K, n, a, m0) those measured?")  # fmt: skip
    return result


def fit_speed_rings(F_m, V_s, rings, *, K=None, n=None, free_n=False, start=None, max_nfev=None) -> FitResult:
    """:func:`fit_speed_amplitude` with each pair's chain taken from the ring it was measured on.

    Parameters
    ----------
    F_m, V_s : array_like
        Peak forces (N) and wave speeds (m/s).
    rings : Ring or sequence of Ring
        The ring of every pair (one for all, or one per pair, as a sweep file names them):
        its spacing a, mass m0 and, unless ``K`` and ``n`` are given, its power law (Eq. 4,
        :meth:`ringchain.theory.Ring.power_law`), evaluated once per distinct ring.
    K, n : float, optional
        One power law for every pair (N/m^n, exponent), instead of the rings' own.
    free_n, start, max_nfev
        As in :func:`fit_speed_amplitude`.

    Returns
    -------
    FitResult
        As :func:`fit_speed_amplitude`'s; pairs from several rings are fitted with one
        m_eff/m0, and a note names the rings.
    """
    from ringchain.theory import Ring

    F_m = np.atleast_1d(np.asarray(F_m, dtype=float))
    rings = [rings] * F_m.size if isinstance(rings, Ring) else list(rings)
    if len(rings) != F_m.size:
        raise ValueError(f"rings must be one Ring or one per pair ({F_m.size}), got {len(rings)}")
    for i, ring in enumerate(rings):
        if not isinstance(ring, Ring):
            raise TypeError(f"rings[{i}] must be a ringchain.theory.Ring, got {type(ring).__name__}")
    if (K is None) != (n is None):
        raise ValueError("give both K and n, or neither (then each ring's power law, Eq. 4)")

    def key(ring):
        return ring.R, ring.r, ring.angle, ring.material.name

    distinct = {}
    for ring in rings:
        if key(ring) not in distinct:
            distinct[key(ring)] = (ring, *(ring.power_law() if K is None else (K, n)))
    laws = [distinct[key(ring)] for ring in rings]
    per_pair = {"K": [law[1] for law in laws], "n": [law[2] for law in laws], "a": [law[0].spacing for law in laws],
                "m0": [law[0].mass for law in laws]}  # fmt: skip
    chain = {name: values[0] if len(distinct) == 1 else np.array(values, dtype=float)
             for name, values in per_pair.items()}  # fmt: skip
    result = fit_speed_amplitude(F_m, V_s, **chain, free_n=free_n, start=start, max_nfev=max_nfev)
    if len(distinct) == 1:
        return result
    count = {k: sum(1 for ring in rings if key(ring) == k) for k in distinct}
    names = "; ".join(f"R = {R:.6g} m, r = {r:.6g} m, {math.degrees(angle):.6g} deg, {material} ({count[k]} pairs)"
                      for k in distinct for R, r, angle, material in [k])  # fmt: skip
    note = f"one m_eff/m0 fitted to pairs from {len(distinct)} rings, each with its own K, n (Eq. 4), a and m0: {names}"
    return dataclasses.replace(result, notes=(*result.notes, note))
