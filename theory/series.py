r"""Hertz contact and ring bending in series, and its power-law reduction (paper Eqs. 3-4).

One period of the chain is one contact (F = K_c delta_c^(3/2), Eq. 1) in series with
one ring's bending (F = K_b delta_b, Eq. 2).  Both carry the same force F, so the
extensions add (Eq. 3):

    delta(F) = (F/K_c)^(2/3) + F/K_b.

The local exponent n(F) = d ln F / d ln delta moves from the Hertz value 3/2 at small
force to 1 at large force; the two compliances are equal at the crossover force
F* = K_b^3/K_c^2, where n = 6/5 (:func:`local_exponent_at_crossover`).  The
power-law reduction F = K delta^n (Eq. 4) is a least-squares fit of ln F against
ln delta over a force window (:func:`fit_power_law`).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from . import _validate as v
from ._codegen import derived, sp
from ._forms import log_monomial
from .special import exp_of_log, gauss_legendre

__all__ = [
    "symbols",
    "contact_extension",
    "bending_extension",
    "total_extension",
    "local_exponent_expr",
    "crossover_force_expr",
    "local_exponent_at_crossover",
    "bending_share",
    "local_exponent_of_share",
    "series_displacement",
    "series_extension",
    "fit_power_law_to_curve",
    "local_exponent",
    "crossover_force",
    "fit_power_law",
    "n_per_mm_to_si",
    "si_to_n_per_mm",
    "series_stiffness_for_power_law",
    "DEFAULT_FORCE_WINDOW",
]

#: Default force window (N) of :func:`fit_power_law`: 1 N to 100 N, the range of peak
#: forces of the paper's drop experiments (its V_s(F_m) curves, Fig. 4, and the
#: forces printed by the main job), i.e. the forces at which the power law is used.
DEFAULT_FORCE_WINDOW = (1.0, 100.0)


@functools.cache
def symbols():
    """Symbols: force F, contact stiffness K_c, bending stiffness K_b, extensions."""
    F, K_c, K_b = sp.symbols("F K_c K_b", positive=True)
    delta_c, delta_b = sp.symbols("delta_c delta_b", positive=True)
    return dict(F=F, K_c=K_c, K_b=K_b, delta_c=delta_c, delta_b=delta_b)


def contact_extension():
    """delta_c(F), solving F = K_c delta_c^(3/2) (Eq. 1) for delta_c."""
    s = symbols()
    return sp.solve(sp.Eq(s["F"], s["K_c"] * s["delta_c"] ** sp.Rational(3, 2)), s["delta_c"])[0]


def bending_extension():
    """delta_b(F), solving F = K_b delta_b (Eq. 2) for delta_b."""
    s = symbols()
    return sp.solve(sp.Eq(s["F"], s["K_b"] * s["delta_b"]), s["delta_b"])[0]


def total_extension():
    """delta(F) = delta_c + delta_b, springs in series (Eq. 3)."""
    return contact_extension() + bending_extension()


def local_exponent_expr():
    """n(F) = d ln F / d ln delta = delta / (F d delta/dF)."""
    F = symbols()["F"]
    delta = total_extension()
    return sp.simplify(delta / (F * sp.diff(delta, F)))


def crossover_force_expr():
    """F* where the contact and bending extensions are equal."""
    s = symbols()
    return sp.solve(sp.Eq(contact_extension(), bending_extension()), s["F"])[0]


def local_exponent_at_crossover():
    """n(F*): equal compliances give n = 2/(2/3 + 1) = 6/5."""
    F = symbols()["F"]
    return sp.simplify(local_exponent_expr().subs(F, crossover_force_expr()))


def series_extension_expr():
    """delta = delta_c + delta_b(F) for any contact law: Eq. (3) with the contact's extension kept as a symbol."""
    s = symbols()
    return total_extension().subs(contact_extension(), s["delta_c"])


@derived
def _series_extension():
    s = symbols()
    return (s["delta_c"], s["F"], s["K_b"]), series_extension_expr()


def bending_share():
    """w = delta_b/(delta_c + delta_b): the share of the extension taken by ring bending (0 to 1)."""
    return sp.simplify(bending_extension() / total_extension())


def local_exponent_of_share():
    """(n(w), w): the local exponent as a function of the bending share w alone, n = 3/(2 + w).

    Solves w = delta_b/delta for F and substitutes into :func:`local_exponent_expr`; the
    stiffnesses cancel (checked).  From w = 0 (all contact, n = 3/2) to w = 1 (all bending,
    n = 1); at the crossover w = 1/2 and n = 6/5.
    """
    s = symbols()
    w = sp.Symbol("w", positive=True)
    ratio = sp.Symbol("phi", positive=True)  # delta_b/delta_c = w/(1 - w)
    (force,) = sp.solve(sp.Eq(bending_extension() / contact_extension(), ratio), s["F"])
    exponent = sp.simplify(local_exponent_expr().subs(s["F"], force).subs(ratio, w / (1 - w)))
    if exponent.has(s["K_c"], s["K_b"]):  # pragma: no cover - derivation check
        raise RuntimeError("the local exponent depends on more than the bending share")
    return exponent, w


@derived
def _displacement():
    s = symbols()
    return (s["F"], s["K_c"], s["K_b"]), total_extension()


@derived
def _exponent():
    """n(w) with w = 1/(1 + delta_c/delta_b) and delta_c/delta_b = exp(log of the monomial): no
    intermediate overflow for any positive F, K_c, K_b (exp overflowing gives w = 0, n = 3/2)."""
    s = symbols()
    exponent, w = local_exponent_of_share()
    share = 1 / (1 + exp_of_log(log_monomial(contact_extension() / bending_extension())))
    return (s["F"], s["K_c"], s["K_b"]), exponent.subs(w, share)


@derived
def _log_displacement_terms():
    """ln delta_c and ln delta_b (the two terms of Eq. (3), each a monomial), for ln delta = logaddexp."""
    s = symbols()
    terms = sp.Add.make_args(total_extension())
    return (s["F"], s["K_c"], s["K_b"]), tuple(log_monomial(term) for term in terms)


@derived
def _crossover():
    """F* = exp(log of the monomial K_b^3/K_c^2): representable whenever F* is."""
    s = symbols()
    return (s["K_c"], s["K_b"]), exp_of_log(log_monomial(crossover_force_expr()))


def _stiffnesses(K_c, K_b):
    return v.positive("K_c", K_c, "N/m^1.5"), v.positive("K_b", K_b, "N/m")


def series_displacement(F, *, K_c, K_b):
    """Extension delta of one contact in series with one ring's bending (paper Eq. 3).

    Parameters
    ----------
    F : array_like
        Tensile force, N, >= 0.
    K_c : array_like
        Hertz contact stiffness, N/m^1.5 (:func:`~ringchain.theory.hertz_stiffness`).
    K_b : array_like
        Bending stiffness of the ring, N/m (:func:`~ringchain.theory.bending_stiffness`).

    Returns
    -------
    ndarray
        delta = (F/K_c)^(2/3) + F/K_b in m.

    Examples
    --------
    >>> float(series_displacement(8.0, K_c=1.0, K_b=4.0))  # 8^(2/3) + 8/4
    6.0
    """
    F = v.nonnegative("F", F, "N")
    K_c, K_b = _stiffnesses(K_c, K_b)
    v.broadcast_shape(F=F, K_c=K_c, K_b=K_b)
    with np.errstate(all="ignore"):
        delta = _displacement(F, K_c, K_b)
    return v.finite_result(delta, "delta", "force and stiffnesses")


def series_extension(F, *, delta_c, K_b):
    """Extension of a contact of any law in series with one ring's bending (paper Eq. 3).

    Parameters
    ----------
    F : array_like
        Force, N, >= 0.
    delta_c : array_like
        Extension (approach) of the contact at force F, m, >= 0 -- e.g. from a numerical
        contact curve (:func:`ringchain.numerics.contact_curve`).
    K_b : array_like
        Bending stiffness of the ring, N/m.

    Returns
    -------
    ndarray
        delta = delta_c + F/K_b in m.

    Examples
    --------
    >>> float(series_extension(2.0, delta_c=1e-6, K_b=1e6))  # 1 um + 2 N / (1 N/um)
    3e-06
    """
    F = v.nonnegative("F", F, "N")
    delta_c = v.nonnegative("delta_c", delta_c, "m")
    K_b = v.positive("K_b", K_b, "N/m")
    with np.errstate(all="ignore"):  # overflow is reported by value
        delta = _series_extension(delta_c, F, K_b)
    return v.finite_result(delta, "the extension", "extensions, forces and bending stiffnesses")


def local_exponent(F, *, K_c, K_b):
    """Local exponent n(F) = d ln F / d ln delta of the series law.

    Parameters
    ----------
    F : array_like
        Force, N, > 0.
    K_c, K_b : array_like
        Contact (N/m^1.5) and bending (N/m) stiffness.

    Returns
    -------
    ndarray
        n(F), between 1 (bending, F >> F*) and 3/2 (Hertz, F << F*).

    Notes
    -----
    Derivative of paper Eq. (3); with the bending share w = delta_b/delta of the extension,
    n = 3/(2 + w) (:func:`local_exponent_of_share`), evaluated so that no force or
    stiffness, however large or small, overflows it.

    Examples
    --------
    >>> round(float(local_exponent(8.0, K_c=1.0, K_b=4.0)), 12)  # delta_c = 4, delta_b = 2: w = 1/3, n = 9/7
    1.285714285714
    """
    F = v.positive("F", F, "N")
    K_c, K_b = _stiffnesses(K_c, K_b)
    v.broadcast_shape(F=F, K_c=K_c, K_b=K_b)
    with np.errstate(all="ignore"):
        return _exponent(F, K_c, K_b)


def crossover_force(*, K_c, K_b):
    """Force F* = K_b^3/K_c^2 (N) at which contact and bending extensions are equal.

    Parameters
    ----------
    K_c, K_b : array_like
        Contact (N/m^1.5) and bending (N/m) stiffness.

    Returns
    -------
    ndarray
        F* in N.  Below F* the contact dominates (n -> 3/2), above it bending (n -> 1).
    """
    K_c, K_b = _stiffnesses(K_c, K_b)
    v.broadcast_shape(K_c=K_c, K_b=K_b)
    with np.errstate(all="ignore"):
        force = _crossover(K_c, K_b)
    return v.finite_result(force, "F*", "stiffnesses")


def fit_power_law(*, K_c, K_b, F_min=DEFAULT_FORCE_WINDOW[0], F_max=DEFAULT_FORCE_WINDOW[1]):
    """Least-squares power law F = K delta^n to the series law over [F_min, F_max] (Eq. 4).

    Parameters
    ----------
    K_c, K_b : array_like
        Contact (N/m^1.5) and bending (N/m) stiffness; broadcast together.
    F_min, F_max : float, optional
        Force window, N, 0 < F_min < F_max.  Default 1 N to 100 N
        (:data:`DEFAULT_FORCE_WINDOW`): the peak forces of the paper's drop experiments,
        where the power law stands in for the series law.

    Returns
    -------
    K : ndarray
        Prefactor in N/m^n (convert with :func:`si_to_n_per_mm` for the paper's N/mm^n).
    n : ndarray
        Exponent.

    Notes
    -----
    Minimises the integral over ln F in [ln F_min, ln F_max] of
    (ln F - ln K - n ln delta(F))^2, i.e. equal weight per decade of force, like
    force-controlled data sampled logarithmically.  The integrals are evaluated by
    64-point Gauss-Legendre quadrature (exact to machine precision for this smooth
    integrand).  The fitted n lies between the local exponents at the window's ends.
    """
    K_c, K_b = _stiffnesses(K_c, K_b)
    F_min = v.positive("F_min", F_min, "N")
    F_max = v.positive("F_max", F_max, "N")
    v.broadcast_shape(K_c=K_c, K_b=K_b, F_min=F_min, F_max=F_max)
    if np.any(F_max <= F_min):
        raise ValueError(
            f"the force window needs F_min < F_max, got F_min = {v.show(F_min)} N and F_max = {v.show(F_max)} N"
        )
    nodes, weights = gauss_legendre()
    lo, hi = np.log(F_min)[..., None], np.log(F_max)[..., None]
    log_F = 0.5 * (hi - lo) * nodes + 0.5 * (hi + lo)
    with np.errstate(all="ignore"):
        # ln delta = ln(delta_c + delta_b) from the logarithms of the two terms: no overflow.
        log_delta = np.logaddexp(*_log_displacement_terms(np.exp(log_F), K_c[..., None], K_b[..., None]))
    K, n = _log_least_squares(log_F, log_delta, weights)
    reason = "stiffnesses and force window (a window narrower than rounding has no slope)"
    return v.finite_result(K, "the fitted K", reason), v.finite_result(n, "the fitted n", reason)


def series_stiffness_for_power_law(*, K, n, F_min=DEFAULT_FORCE_WINDOW[0], F_max=DEFAULT_FORCE_WINDOW[1]):
    """Contact and bending stiffness whose series law reduces to the power law K delta^n (Eqs. 3-4).

    The series law delta(F) = (F/K_c)^(2/3) + F/K_b (Eq. 3) can be written
    (F/K_b) (1 + (F*/F)^(1/3)) with the crossover force F* = K_b^3/K_c^2, so the exponent of
    its least-squares power law over a force window (Eq. 4, :func:`fit_power_law`) depends on
    F* alone, rising from 1 (F* -> 0, bending only) to 3/2 (F* -> infinity, Hertz only), and
    K_b then scales K as K_b^n.  One root finding gives F*, a power gives K_b: the fit of the
    result is (K, n) to the root finder's tolerance.

    Parameters
    ----------
    K : float
        Power-law stiffness, N/m^n (e.g. Table I's, through :func:`n_per_mm_to_si`).
    n : float
        Exponent, strictly between 1 and 3/2.
    F_min, F_max : float, optional
        Force window, N; default :data:`DEFAULT_FORCE_WINDOW`.

    Returns
    -------
    K_c : float
        Contact stiffness, N/m^1.5.
    K_b : float
        Bending stiffness, N/m.

    Notes
    -----
    The inverse of :func:`fit_power_law`: two springs for two measured numbers.  Beyond the
    paper, which runs its dual-spring chain on the theory's springs (Sec. III.B); the package
    uses it to give that chain the stiffness of Table I.

    Examples
    --------
    >>> K_c, K_b = series_stiffness_for_power_law(K=4.9e6, n=1.11)
    >>> K, n = fit_power_law(K_c=K_c, K_b=K_b)
    >>> round(float(K) / 4.9e6, 9), round(float(n), 9)
    (1.0, 1.11)
    """
    from scipy.optimize import brentq

    K = float(v.positive("K", K, "N/m^n"))
    n = float(v.in_range("n", n, 1.0, 1.5, closed_high=False))
    F_min = float(v.positive("F_min", F_min, "N"))
    F_max = float(v.positive("F_max", F_max, "N"))
    if not F_max > F_min:
        raise ValueError(f"the force window needs F_min < F_max, got [{F_min:g}, {F_max:g}] N")

    def fitted(log_crossover):  # the fit with K_b = 1 N/m, K_c = F*^(-1/2)
        return fit_power_law(K_c=np.exp(-0.5 * log_crossover), K_b=1.0, F_min=F_min, F_max=F_max)

    # F* from 1e-12 to 1e12 times the window's geometric mean: n from ~1 to ~1.5.
    centre = 0.5 * (math.log(F_min) + math.log(F_max))
    low, high = centre - 12 * math.log(10), centre + 12 * math.log(10)
    if not float(fitted(low)[1]) < n < float(fitted(high)[1]):
        raise ValueError(f"no Hertz contact in series with a linear spring fits n = {n:g} over "
                         f"[{F_min:g}, {F_max:g}] N")  # fmt: skip
    log_crossover = brentq(lambda x: float(fitted(x)[1]) - n, low, high, xtol=1e-13, rtol=1e-15)
    K_unit = float(fitted(log_crossover)[0])
    # In logarithms: K_b^3 overflows for K beyond about 1e100 N/m^n where K_c itself does not.
    log_K_b = (math.log(K) - math.log(K_unit)) / n
    with np.errstate(over="ignore"):
        K_b = float(np.exp(log_K_b))
        K_c = float(np.exp(1.5 * log_K_b - 0.5 * log_crossover))
    if not (0.0 < K_c < math.inf and 0.0 < K_b < math.inf):  # beyond the largest double, or below the smallest
        raise ValueError(f"the springs of K = {K:g} N/m^n, n = {n:g} are not representable in double precision")
    return K_c, K_b


def _log_least_squares(log_F, log_delta, weights, n=None):
    """(K, n) minimising sum w (ln F - ln K - n ln delta)^2 along the last axis (n fixed if given)."""
    with np.errstate(all="ignore"):
        w = weights / weights.sum()
        mean_x = np.sum(w * log_delta, axis=-1)
        mean_y = np.sum(w * log_F, axis=-1)
        if n is None:
            cov = np.sum(w * (log_delta - mean_x[..., None]) * (log_F - mean_y[..., None]), axis=-1)
            var = np.sum(w * (log_delta - mean_x[..., None]) ** 2, axis=-1)
            n = cov / var
        return np.exp(mean_y - n * mean_x), n


def fit_power_law_to_curve(F, delta, F_min=DEFAULT_FORCE_WINDOW[0], F_max=DEFAULT_FORCE_WINDOW[1], *, n=None):
    """Power law F = K delta^n fitted to a tabulated force-extension curve over [F_min, F_max] (Eq. 4).

    Parameters
    ----------
    F : array_like
        Forces of the curve, N, > 0, strictly increasing; the window must lie within them.
    delta : array_like
        Extensions at those forces, m, > 0, increasing.
    F_min, F_max : float, optional
        Force window, N (default :data:`DEFAULT_FORCE_WINDOW`, 1 N to 100 N).
    n : float, optional
        Fix the exponent (e.g. 1.5 for an effective Hertz constant) and fit K alone.

    Returns
    -------
    K : float
        Prefactor in N/m^n.
    n : float
        Exponent.

    Notes
    -----
    The same least squares as :func:`fit_power_law`: equal weight per decade of force, by
    64-point Gauss-Legendre quadrature in ln F, with ln delta interpolated linearly in ln F
    between the curve's points (an error of second order in their spacing).

    Examples
    --------
    >>> F = np.geomspace(0.5, 200.0, 9)
    >>> K, n = fit_power_law_to_curve(F, (F / 3.0) ** (1 / 1.25))
    >>> round(float(K), 6), round(float(n), 6)
    (3.0, 1.25)
    """
    F = v.positive("F", F, "N")
    delta = v.positive("delta", delta, "m")
    if F.ndim != 1 or F.shape != delta.shape or F.size < 2 or np.any(np.diff(F) <= 0) or np.any(np.diff(delta) <= 0):
        raise ValueError(
            "F and delta must be 1-D arrays of the same length (>= 2), both strictly increasing (a contact "
            "extends as it is loaded)"
        )
    F_min, F_max = float(F_min), float(F_max)
    if not 0 < F_min < F_max:
        raise ValueError(f"the force window needs 0 < F_min < F_max, got [{F_min:g}, {F_max:g}] N")
    if F_min < F[0] * (1 - 1e-12) or F_max > F[-1] * (1 + 1e-12):
        raise ValueError(
            f"the force window [{F_min:g}, {F_max:g}] N must lie within the curve's [{F[0]:g}, {F[-1]:g}] N"
        )
    nodes, weights = gauss_legendre()
    lo, hi = np.log(F_min), np.log(F_max)
    log_F = 0.5 * (hi - lo) * nodes + 0.5 * (hi + lo)
    log_delta = np.interp(log_F, np.log(F), np.log(delta))
    K, n = _log_least_squares(log_F, log_delta, weights, n)
    v.finite_result(K, "the fitted K", "forces and extensions")
    return float(K), float(n)


def n_per_mm_to_si(K, *, n):
    """Convert a power-law prefactor from N/mm^n (the paper's tables) to N/m^n.

    Parameters
    ----------
    K : array_like
        Prefactor in N/mm^n.
    n : array_like
        Exponent (dimensionless).

    Returns
    -------
    ndarray
        K * 1000^n, in N/m^n.

    Examples
    --------
    >>> float(n_per_mm_to_si(2.0, n=1.5) / 1000**1.5)
    2.0
    """
    return _convert(K, n, 1.0)


def si_to_n_per_mm(K, *, n):
    """Inverse of :func:`n_per_mm_to_si`: K in N/m^n to N/mm^n.

    Examples
    --------
    >>> float(si_to_n_per_mm(2.0 * 1000**1.5, n=1.5))
    2.0
    """
    return _convert(K, n, -1.0)


def _convert(K, n, direction):
    K, n = v.as_float("K", K), v.as_float("n", n)
    v.broadcast_shape(K=K, n=n)
    with np.errstate(all="ignore"):
        converted = K * 1000.0 ** (direction * n)
    return v.finite_result(converted, "the converted K", "prefactor and exponent")
