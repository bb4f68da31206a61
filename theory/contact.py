r"""Hertz contact of two interlocked tori (paper Eq. 1 and App. A).

The derivation, step by step (each step a function returning SymPy objects):

1. :func:`principal_radii` -- at the contact point of two interlocked identical tori
   each body has principal radii r (around the tube, convex) and -(R - r) (along the
   inner equator, concave): App. A, below Eq. (whole).
2. :func:`curvature_sums` -- Hertz's sums A + B and |A - B| (App. A, Eq. whole a/b)
   with the angle between principal planes equal to the contact angle theta between
   the ring planes.  |A - B| collapses to (1/r + 1/(R - r)) |cos theta|.
3. :func:`relative_curvatures` -- A and B, with A <= B (Johnson's convention).
   A > 0 requires cos(theta) < 1 - 2 r/R: below that angle the gap between the
   tori closes along a line and the single-ellipse Hertz contact fails (the paper
   reports two contact patches below about 45 degrees, Sec. IV.B).
4. :func:`hertz_circular` -- theta = 90 degrees: A = B, R' = R'' = r(R - r)/(R - 2r),
   and Hertz's sphere relations a^3 = 3 P R_e/(4 E*), delta = a^2/R_e give
   P = K_c delta^(3/2) with K_c = 4/3 E* sqrt(R_e) (paper Eq. 1 and Eq. three).
5. :func:`hertz_elliptical` -- any theta: Johnson's elliptical solution (Contact
   Mechanics, Sec. 4.2, Eqs. 4.39-4.41) with complete elliptic integrals K(m), E(m)
   of the ellipse's eccentricity e^2 = m, eliminated to P = K_c(m, A) delta^(3/2) and
   the shape equation B/A = (E/(1 - m) - K)/(K - E).
6. The numeric code evaluates step 5 in Carlson's form (:mod:`.special`): K(m) =
   R_F(0, 1-m, 1) and (K - E)/m = R_D(0, 1-m, 1)/3, so the circular limit m -> 0 is
   exact in floating point too.

The effective modulus 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (App. A) is
:func:`effective_modulus`.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from ._codegen import derived, sp
from .special import carlson_rd, carlson_rf

__all__ = [
    "symbols",
    "effective_modulus",
    "principal_radii",
    "curvature_sums",
    "relative_curvatures",
    "equivalent_radius_perpendicular",
    "hertz_circular",
    "hertz_elliptical",
    "hertz_elliptical_monomial",
    "elliptic_placeholders",
    "ellipse_shape_ratio",
    "hertz_stiffness",
    "contact_ellipse",
    "minimum_contact_angle",
]


@functools.cache
def symbols():
    """Symbols of this module: geometry R, r; material E, nu; angle theta; Hertz quantities."""
    R, r, E, nu = sp.symbols("R r E nu", positive=True)
    theta = sp.Symbol("theta", positive=True)  # angle between the ring planes, (0, pi/2]
    m = sp.Symbol("m", nonnegative=True)  # squared eccentricity of the contact ellipse
    A, B = sp.symbols("A B", positive=True)  # relative curvatures, A <= B
    P, delta = sp.symbols("P delta", positive=True)  # load and normal approach
    a, b, p0 = sp.symbols("a b p_0", positive=True)  # semi-axes (a >= b) and peak pressure
    return dict(R=R, r=r, E=E, nu=nu, theta=theta, m=m, A=A, B=B, P=P, delta=delta, a=a, b=b, p0=p0)


# --- 1. geometry ------------------------------------------------------------------------


def effective_modulus(E1=None, nu1=None, E2=None, nu2=None):
    """E* from 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (App. A); identical bodies by default."""
    s = symbols()
    E1 = s["E"] if E1 is None else E1
    nu1 = s["nu"] if nu1 is None else nu1
    E2 = E1 if E2 is None else E2
    nu2 = nu1 if nu2 is None else nu2
    return sp.factor(sp.cancel(1 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)))


def principal_radii():
    """(R1', R1'', R2', R2''): tube radius r and inner-equator radius -(R - r), both tori."""
    s = symbols()
    tube, equator = s["r"], -(s["R"] - s["r"])
    return tube, equator, tube, equator


def curvature_sums():
    """(A + B, |A - B|) from Hertz's curvature sums (App. A, Eq. whole), alpha = theta.

    The square root is reduced with cos(2 theta) = 2 cos(theta)^2 - 1 and cos(theta) >= 0
    on the admissible range 0 < theta <= pi/2.
    """
    s = symbols()
    R, r = s["R"], s["r"]
    R1p, R1pp, R2p, R2pp = principal_radii()
    alpha = s["theta"]
    total = sp.Rational(1, 2) * (1 / R1p + 1 / R1pp + 1 / R2p + 1 / R2pp)
    k1, k2 = 1 / R1p - 1 / R1pp, 1 / R2p - 1 / R2pp
    radicand = k1**2 + k2**2 + 2 * k1 * k2 * sp.cos(2 * alpha)
    c = sp.Symbol("c", nonnegative=True)  # cos(theta)
    difference = sp.sqrt(sp.factor(radicand.subs(sp.cos(2 * alpha), 2 * c**2 - 1))) / 2
    difference = sp.refine(difference, sp.Q.positive(R - r)).subs(c, sp.cos(alpha))
    return sp.factor(sp.together(total)), difference


def relative_curvatures():
    """(A, B) = ((A+B) -/+ |A-B|)/2, so that A <= B."""
    total, difference = curvature_sums()
    A = sp.factor(sp.together((total - difference) / 2))
    B = sp.factor(sp.together((total + difference) / 2))
    return A, B


def equivalent_radius_perpendicular():
    """(R', R'') = (1/2A, 1/2B) at theta = pi/2: both equal r(R - r)/(R - 2r)."""
    s = symbols()
    A, B = relative_curvatures()
    at = {s["theta"]: sp.pi / 2}
    return sp.factor(1 / (2 * A.subs(at))), sp.factor(1 / (2 * B.subs(at)))


# --- 2. Hertz solutions -----------------------------------------------------------------


def hertz_circular():
    """K_c for the circular contact (theta = pi/2), derived from Hertz's sphere relations.

    Johnson Sec. 4.2: a^3 = 3 P R_e/(4 E*) and delta = a^2/R_e; eliminating the contact
    radius a gives P = K_c delta^(3/2).  Returns K_c(R, r, E, nu) (paper Eq. 1).
    """
    s = symbols()
    P, delta, a = s["P"], s["delta"], s["a"]
    Re = sp.Symbol("R_e", positive=True)
    Es = sp.Symbol("E^*", positive=True)
    a_of_delta = sp.solve(sp.Eq(delta, a**2 / Re), a)[0]
    load = sp.solve(sp.Eq(a_of_delta**3, 3 * P * Re / (4 * Es)), P)[0]
    K_c = sp.simplify(load / delta**sp.Rational(3, 2))
    R_prime, _ = equivalent_radius_perpendicular()
    return sp.simplify(K_c.subs({Re: R_prime, Es: effective_modulus()}))


def elliptic_placeholders():
    """Positive symbols K_m = K(m) and D_m = (K(m) - E(m))/m used inside the derivation.

    Working with them keeps the algebra to monomials (fast, no ``simplify``); they are
    replaced by the elliptic integrals at the end (:func:`hertz_elliptical`), or by
    Carlson's forms R_F(0, 1-m, 1) and R_D(0, 1-m, 1)/3 for numerics (:mod:`.special`).
    """
    return sp.Symbol("K_m", positive=True), sp.Symbol("D_m", positive=True)


def hertz_elliptical_monomial():
    """K_c of an elliptical contact as a monomial in A, E*, K_m = K(m), D_m = (K - E)/m.

    Johnson Sec. 4.2 (semi-axes a >= b, b = a sqrt(1 - m), peak pressure p0):
        P = 2/3 pi a b p0,
        delta = p0 b K(m)/E*,
        A = p0 b (K(m) - E(m))/(E* a^2 m) = p0 b D_m/(E* a^2).
    Eliminating a, b and p0 leaves P = K_c delta^(3/2).  Returns (K_c, E*) with E* a
    Symbol named ``E^*``.
    """
    s = symbols()
    P, A, m, a, p0 = (s[k] for k in ("P", "A", "m", "a", "p0"))
    Es = sp.Symbol("E^*", positive=True)
    K_m, D_m = elliptic_placeholders()
    b_of_a = a * sp.sqrt(1 - m)
    _, p0_of_a = sp.solve_linear(A - p0 * b_of_a * D_m / (Es * a**2), symbols=[p0])
    # The load is a^3 times a factor free of a: solve for a^3, take the real cube root.
    per_cube = sp.cancel(sp.Rational(2, 3) * sp.pi * a * b_of_a * p0_of_a / a**3)
    if a in per_cube.free_symbols:  # pragma: no cover - derivation check
        raise RuntimeError("Johnson's load is not proportional to a^3")
    a_of_P = (P / per_cube) ** sp.Rational(1, 3)
    delta_of_P = (p0_of_a * b_of_a * K_m / Es).subs(a, a_of_P)
    # Every factor is positive, so powers may be merged freely.
    K_c = sp.powsimp(sp.powdenest(P / delta_of_P ** sp.Rational(3, 2), force=True), force=True)
    return K_c, Es


def hertz_elliptical():
    """K_c of an elliptical contact in terms of m = e^2, the curvature A and E*.

    :func:`hertz_elliptical_monomial` with K_m = K(m) and D_m = (K(m) - E(m))/m: the
    complete elliptic integrals of Johnson's solution.  Returns (K_c, E*).
    """
    m = symbols()["m"]
    K_c, Es = hertz_elliptical_monomial()
    K_m, D_m = elliptic_placeholders()
    K, E = sp.elliptic_k(m), sp.elliptic_e(m)
    return K_c.subs({K_m: K, D_m: (K - E) / m}), Es


def ellipse_shape_ratio():
    """B/A as a function of m, from Johnson's two curvature equations (Sec. 4.2)."""
    s = symbols()
    m = s["m"]
    K, E = sp.elliptic_k(m), sp.elliptic_e(m)
    A_rel = (K - E) / m  # common factor p0 b/(E* a^2) dropped
    B_rel = (E / (1 - m) - K) / m
    return sp.simplify(B_rel / A_rel)


# --- 3. numeric functions ---------------------------------------------------------------


@derived
def _curvatures():
    s = symbols()
    A, B = relative_curvatures()
    return (s["R"], s["r"], s["theta"]), (A, B)


def _carlson(expr):
    """expr with K(m) -> R_F(0, 1-m, 1) and E(m) -> R_F - m R_D(0, 1-m, 1)/3 (DLMF 19.25.1),
    by way of the placeholders K_m and D_m = (K - E)/m, so that m cancels exactly."""
    m = symbols()["m"]
    K_m, D_m = elliptic_placeholders()
    placeholders = sp.cancel(expr.subs({sp.elliptic_e(m): K_m - m * D_m}).subs({sp.elliptic_k(m): K_m}))
    return placeholders.subs({K_m: carlson_rf(0, 1 - m, 1), D_m: carlson_rd(0, 1 - m, 1) / 3})


@derived
def _shape_ratio():
    return (symbols()["m"],), _carlson(ellipse_shape_ratio())


@derived
def _stiffness_elliptical():
    s = symbols()
    K_c, Es = hertz_elliptical()
    return (s["m"], s["A"], s["E"], s["nu"]), _carlson(K_c).subs(Es, effective_modulus())


def minimum_contact_angle(R, r):
    """Smallest contact angle (rad) for which one elliptical Hertz contact exists.

    A > 0 requires cos(theta) < 1 - 2 r/R (step 3 of the module docstring).

    Parameters
    ----------
    R, r : array_like
        Major and minor (tube) radius of the torus, m; R > 2 r.

    Returns
    -------
    ndarray
        arccos(1 - 2 r/R) in rad.
    """
    R, r = _check_geometry(R, r)
    return np.arccos(1 - 2 * r / R)


def _check_geometry(R, r):
    R = v.positive("R", R, "m")
    r = v.positive("r", r, "m")
    if np.any(R <= 2 * r):
        raise ValueError(
            "R must exceed 2 r: for R <= 2 r the relative curvature of two interlocked tori is not "
            f"positive and Hertz contact does not apply (got R/r = {np.min(R / r):g})"
        )
    return R, r


def _check_angle(R, r, angle):
    angle = v.in_range("angle", angle, 0.0, np.pi / 2)
    limit = np.arccos(1 - 2 * r / R)
    if np.any(angle <= limit):
        bad = np.broadcast_to(angle <= limit, np.broadcast_shapes(angle.shape, limit.shape))
        lim = np.broadcast_to(limit, bad.shape)[bad].max()
        raise ValueError(
            f"contact angle {np.degrees(np.broadcast_to(angle, bad.shape)[bad].min()):.4g} deg is at or below "
            f"{np.degrees(lim):.4g} deg = arccos(1 - 2r/R): the tori then touch along a line or at two "
            "patches, and the single elliptical Hertz contact does not apply"
        )
    return angle


def _solve_eccentricity(ratio):
    """m in [0, 1) with B/A(m) = ratio >= 1, by bisection (B/A increases monotonically in m)."""
    ratio = np.asarray(ratio, dtype=float)
    lo = np.zeros_like(ratio)
    hi = np.ones_like(ratio)
    for _ in range(60):  # 2^-60 < 1e-18: below double precision of m
        mid = 0.5 * (lo + hi)
        above = _shape_ratio(mid) > ratio
        hi = np.where(above, mid, hi)
        lo = np.where(above, lo, mid)
    return 0.5 * (lo + hi)


def contact_ellipse(R, r, angle=np.pi / 2):
    """Relative curvatures and shape of the Hertz contact ellipse of two identical tori.

    Parameters
    ----------
    R, r : array_like
        Major and tube radius of each torus, m (R > 2 r).
    angle : array_like, optional
        Contact angle theta between the two ring planes, rad, in (theta_min, pi/2];
        pi/2 (perpendicular rings) is the paper's case.

    Returns
    -------
    A, B : ndarray
        Relative curvatures, 1/m, A <= B (App. A, Eq. one).
    m : ndarray
        Squared eccentricity of the contact ellipse, 1 - (b/a)^2 (0 for a circle).

    Notes
    -----
    App. A of the paper with Johnson's elliptical Hertz solution (Contact Mechanics,
    Sec. 4.2).  The aspect ratio of the ellipse is b/a = sqrt(1 - m).
    """
    R, r = _check_geometry(R, r)
    angle = _check_angle(R, r, angle)
    A, B = _curvatures(R, r, angle)
    A, B = np.asarray(A, dtype=float), np.asarray(B, dtype=float)
    return A, B, _solve_eccentricity(B / A)


def hertz_stiffness(R, r, E, nu, angle=np.pi / 2):
    """Hertz contact stiffness K_c of two identical interlocked tori, F = K_c delta^(3/2).

    Parameters
    ----------
    R, r : array_like
        Major and tube (cross-section) radius of the torus, m.  R > 2 r is required.
    E : array_like
        Young's modulus, Pa.
    nu : array_like
        Poisson's ratio, in (-1, 0.5).
    angle : array_like, optional
        Contact angle theta between the ring planes, rad; default pi/2 (perpendicular).

    Returns
    -------
    ndarray
        K_c in N/m^1.5.

    Notes
    -----
    Paper Eq. (1) and App. A (Eq. three) for theta = pi/2, where the contact is circular
    with R' = R'' = r(R - r)/(R - 2r); for other angles the exact elliptical Hertz
    solution (Johnson, Contact Mechanics, Sec. 4.2) with complete elliptic integrals,
    evaluated in Carlson's form.  Raises ``ValueError`` for R <= 2 r and for angles at or
    below :func:`minimum_contact_angle`.

    Examples
    --------
    >>> K_c = hertz_stiffness(22.5e-3, 2.5e-3, 193e9, 0.29)
    >>> round(float(K_c) / 1e9, 3)  # GN/m^1.5
    7.509
    """
    R, r = _check_geometry(R, r)
    E = v.positive("E", E, "Pa")
    nu = v.in_range("nu", nu, -1.0, 0.5, closed_high=False)
    A, _, m = contact_ellipse(R, r, angle)
    return _stiffness_elliptical(m, A, E, nu)
