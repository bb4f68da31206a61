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

import numpy as np

from . import _validate as v
from ._codegen import derived, sp

__all__ = [
    "symbols",
    "contact_extension",
    "bending_extension",
    "total_extension",
    "local_exponent_expr",
    "crossover_force_expr",
    "local_exponent_at_crossover",
    "series_displacement",
    "local_exponent",
    "crossover_force",
    "fit_power_law",
    "n_per_mm_to_si",
    "si_to_n_per_mm",
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


@derived
def _displacement():
    s = symbols()
    return (s["F"], s["K_c"], s["K_b"]), total_extension()


@derived
def _exponent():
    s = symbols()
    return (s["F"], s["K_c"], s["K_b"]), local_exponent_expr()


@derived
def _crossover():
    s = symbols()
    return (s["K_c"], s["K_b"]), crossover_force_expr()


def _stiffnesses(K_c, K_b):
    return v.positive("K_c", K_c, "N/m^1.5"), v.positive("K_b", K_b, "N/m")


def series_displacement(F, K_c, K_b):
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
    >>> float(series_displacement(8.0, 1.0, 4.0))  # 8^(2/3) + 8/4
    6.0
    """
    F = v.nonnegative("F", F, "N")
    K_c, K_b = _stiffnesses(K_c, K_b)
    return _displacement(F, K_c, K_b)


def local_exponent(F, K_c, K_b):
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
    Derivative of paper Eq. (3); with s = (F*/F)^(1/3), n = (s + 1)/(2 s/3 + 1).
    """
    F = v.positive("F", F, "N")
    K_c, K_b = _stiffnesses(K_c, K_b)
    return _exponent(F, K_c, K_b)


def crossover_force(K_c, K_b):
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
    return _crossover(K_c, K_b)


@functools.cache
def _gauss_legendre(order: int = 64):
    return np.polynomial.legendre.leggauss(order)


def fit_power_law(K_c, K_b, F_min=DEFAULT_FORCE_WINDOW[0], F_max=DEFAULT_FORCE_WINDOW[1]):
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
    if np.any(F_max <= F_min):
        raise ValueError(f"the force window needs F_min < F_max, got [{F_min}, {F_max}] N")
    nodes, weights = _gauss_legendre()
    lo, hi = np.log(F_min)[..., None], np.log(F_max)[..., None]
    log_F = 0.5 * (hi - lo) * nodes + 0.5 * (hi + lo)
    log_delta = np.log(_displacement(np.exp(log_F), K_c[..., None], K_b[..., None]))
    w = weights / weights.sum()
    mean_x = np.sum(w * log_delta, axis=-1)
    mean_y = np.sum(w * log_F, axis=-1)
    cov = np.sum(w * (log_delta - mean_x[..., None]) * (log_F - mean_y[..., None]), axis=-1)
    var = np.sum(w * (log_delta - mean_x[..., None]) ** 2, axis=-1)
    n = cov / var
    return np.exp(mean_y - n * mean_x), n


def n_per_mm_to_si(K, n):
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
    >>> float(n_per_mm_to_si(2.0, 1.5) / 1000**1.5)
    2.0
    """
    return v.as_float("K", K) * 1000.0 ** v.as_float("n", n)


def si_to_n_per_mm(K, n):
    """Inverse of :func:`n_per_mm_to_si`: K in N/m^n to N/mm^n."""
    return v.as_float("K", K) * 1000.0 ** (-v.as_float("n", n))
