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

import math
from dataclasses import dataclass, field

import numpy as np
from ringchain.theory import _validate as v

from .traces import MIN_SAMPLES

__all__ = [
    "fit_static",
    "fit_speed_amplitude",
    "FitResult",
    "FitError",
    "STATIC_MODELS",
    "ANALYTIC_RESOLUTION",
]

#: The same for the static and speed fits, whose models are closed forms differentiated by
#: lmfit at steps of sqrt(machine epsilon) (Jacobian accurate to ~1e-7).
ANALYTIC_RESOLUTION = 1e-5

_UNITS = {
    "m": "kg", "gamma": "N s/m", "K": "N/m^n", "n": "", "K_b": "N/m", "gamma_b": "N s/m", "t0": "s", "v0": "m/s",
    "h0": "m", "offset": "N", "delta0": "m", "K_c": "N/m^1.5", "m_eff_ratio": "", "m_gravity": "kg", "a": "m",
    "m0": "kg",
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
                       fixed=None, **more) -> FitResult:  # fmt: skip
    """A FitResult from an lmfit MinimizerResult.

    Raises FitError unless it converged to a point that explains some of the data: a
    residual sum of squares below ``spread``, that of the data about their mean (a start so
    far off that the gradient vanishes can stop the least squares "successfully" anywhere).
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


def minimize(residual, params, jac=None, **options):
    """lmfit least squares (trust-region reflective, Jacobian-scaled variables)."""
    from lmfit import Minimizer

    kws = {"x_scale": "jac", **options}
    if jac is not None:
        kws["jac"] = jac
    return Minimizer(residual, params, scale_covar=True).minimize(method="least_squares", **kws)


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

    out = minimize(lambda p: model_force(p) - F, params, max_nfev=max_nfev)
    names = list(params)
    spread = float(np.sum(np.square(F - F.mean())))
    return result_from_lmfit(f"static {model}", out, names, model_force(out.params) - F, spread=spread,
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
    F_m = v.positive("F_m", as_data("F_m", F_m, "N", least), "N")
    V_s = v.positive("V_s", as_data("V_s", V_s, "m/s", least), "m/s")
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

    out = minimize(lambda p: speeds(p) - V_s, params, max_nfev=max_nfev)
    names = ["m_eff_ratio", "n"] if free_n else ["m_eff_ratio"]
    fixed = {"K": K, "a": a, "m0": m0, **({} if free_n else {"n": n})}
    spread = float(np.sum(np.square(V_s - V_s.mean())))
    return result_from_lmfit("speed-amplitude", out, names, speeds(out.params) - V_s, spread=spread,
                              resolution=ANALYTIC_RESOLUTION, fixed=fixed)  # fmt: skip
