r"""Hertz contact of two interlocked tori (paper Eq. 1 and App. A).

The derivation, step by step (each step a function returning SymPy objects):

1. :func:`principal_radii` -- at the contact point of two interlocked identical tori
   each body has principal radii r (around the tube, convex) and -(R - r) (along the
   inner equator, concave): App. A, below Eqs. (A2a)-(A2b).
2. :func:`curvature_sums` -- Hertz's sums A + B and |A - B| (App. A, Eqs. (A2a)-(A2b))
   with the angle between principal planes equal to the contact angle theta between
   the ring planes.  |A - B| collapses to (1/r + 1/(R - r)) |cos theta|.
3. :func:`relative_curvatures` -- A and B, with A <= B (Johnson's convention).
   A > 0 requires cos(theta) < 1 - 2 r/R: below that angle the gap between the
   tori closes along a line and the single-ellipse Hertz contact fails (the paper
   reports two contact patches below about 45 degrees, Sec. IV.B).
   :func:`minimum_angle` solves A = 0 for theta in the half-angle form
   theta_min = 2 asin(sqrt(r/R)), and :func:`half_angle_curvatures` writes A with
   cos(theta) = 1 - 2 sin^2(theta/2), A = (R sin^2(theta/2) - r)/(r (R - r)), whose sign
   is the sign of theta - theta_min even in floating point next to theta_min.
4. :func:`hertz_circular` -- theta = 90 degrees: A = B, R' = R'' = r(R - r)/(R - 2r),
   and Hertz's sphere relations a^3 = 3 P R_e/(4 E*), delta = a^2/R_e give
   P = K_c delta^(3/2) with K_c = 4/3 E* sqrt(R_e) (paper Eq. 1 and Eq. (A3)).
5. Any theta: Johnson's elliptical solution of two bodies with curvatures A <= B
   (:mod:`.elliptical`: K_c(m, A) with the squared eccentricity m of the ellipse, the shape
   equation B/A(m), the factor Gamma(m) = K_c(m, A)/K_c(0, A), and the tables that invert the
   shape equation for the numeric functions here).  For the tori B/A - 1 comes from
   :func:`half_angle_curvatures`; the perpendicular case (theta = pi/2 exactly) needs no table.
6. Two different tori (radii, materials), for chains that vary: :func:`principal_radii_pair`,
   :func:`curvature_sums_pair`, :func:`curvature_product_pair` (A without cancellation near the
   angle where it vanishes) and :func:`minimum_angle_pair`.

The effective modulus 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (App. A) is
:func:`effective_modulus`.  The exact gap of two tori, beyond its quadratic part, is in :mod:`.gap`.

Numeric functions: :func:`hertz_stiffness`, :func:`hertz_stiffness_pair`, :func:`contact_ellipse`,
:func:`contact_semi_axes`, :func:`minimum_contact_angle`, :func:`contact_modulus`.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from . import elliptical
from ._codegen import derived, sp
from ._forms import positive_differences, split_product
from .elliptical import (
    TABLE_MAX_EXCESS,
    TABLE_MAX_LOG_RATIO,
    circular_limit,
    elliptic_placeholders,
    from_table,
    hertz_semi_axes,
)
from .special import carlson_rd

__all__ = [
    "symbols",
    "effective_modulus",
    "principal_radii",
    "curvature_sums",
    "relative_curvatures",
    "equivalent_radius_perpendicular",
    "hertz_circular",
    "minimum_angle",
    "half_angle_curvatures",
    "hertz_stiffness",
    "hertz_stiffness_pair",
    "pair_symbols",
    "principal_radii_pair",
    "curvature_sums_pair",
    "curvature_product_pair",
    "effective_modulus_pair",
    "minimum_angle_pair",
    "contact_ellipse",
    "contact_semi_axes",
    "minimum_contact_angle",
    "contact_modulus",
]


@functools.cache
def symbols():
    """Symbols of this module: geometry R, r; material E, nu; angle theta; and the contact ellipse's
    (:func:`.elliptical.symbols`: m, A, B, P, delta, a, b, p0, m_1)."""
    R, r, E, nu = sp.symbols("R r E nu", positive=True)
    theta = sp.Symbol("theta", positive=True)  # angle between the ring planes, (0, pi/2]
    return dict(R=R, r=r, E=E, nu=nu, theta=theta, **elliptical.symbols())


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
    """(A + B, |A - B|) from Hertz's curvature sums (App. A, Eqs. (A2a)-(A2b)), alpha = theta.

    The square root is reduced with cos(2 theta) = 2 cos(theta)^2 - 1 and cos(theta) >= 0
    on the admissible range 0 < theta <= pi/2.
    """
    s = symbols()
    R, r = s["R"], s["r"]
    total, radicand, c = _hertz_sums(*principal_radii())
    difference = sp.sqrt(sp.factor(radicand)) / 2
    difference = sp.refine(difference, sp.Q.positive(R - r)).subs(c, sp.cos(s["theta"]))
    return sp.factor(sp.together(total)), difference


def _hertz_sums(R1p, R1pp, R2p, R2pp):
    """Hertz's A + B and (2 |A - B|)^2 of two bodies with principal radii (R1', R1''), (R2', R2'')
    whose principal planes meet at the angle theta (App. A, Eqs. (A2a)-(A2b)).

    Returns (A + B, (2 |A - B|)^2 in c = cos(theta), c), with cos(2 theta) = 2 c^2 - 1.
    """
    alpha = symbols()["theta"]
    total = sp.Rational(1, 2) * (1 / R1p + 1 / R1pp + 1 / R2p + 1 / R2pp)
    k1, k2 = 1 / R1p - 1 / R1pp, 1 / R2p - 1 / R2pp
    radicand = k1**2 + k2**2 + 2 * k1 * k2 * sp.cos(2 * alpha)
    c = sp.Symbol("c", nonnegative=True)  # cos(theta)
    return total, radicand.subs(sp.cos(2 * alpha), 2 * c**2 - 1), c


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
    K_c = sp.simplify(load / delta ** sp.Rational(3, 2))
    R_prime, _ = equivalent_radius_perpendicular()
    return sp.simplify(K_c.subs({Re: R_prime, Es: effective_modulus()}))


def minimum_angle():
    """theta_min = 2 asin(sqrt(r/R)): the angle at which A = 0 (step 3 of the module docstring).

    A is linear in cos(theta); A = 0 gives cos(theta_min) = 1 - 2r/R, solved in the half-angle
    form 1 - cos(theta) = 2 sin^2(theta/2), which keeps every digit for thin rings (r << R),
    where 1 - 2r/R rounds away most of r/R.
    """
    s = symbols()
    A, _ = relative_curvatures()
    c = sp.Symbol("c", real=True)
    (cos_min,) = sp.solve(A.subs(sp.cos(s["theta"]), c), c)
    h = sp.Symbol("h", positive=True)  # sin(theta_min/2)
    (half,) = sp.solve(sp.Eq(1 - 2 * h**2, cos_min), h)
    angle = 2 * sp.asin(half)
    if sp.simplify(sp.expand_trig(sp.cos(angle)) - cos_min) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("theta_min does not solve A = 0")
    return angle


def half_angle_curvatures():
    """(A, B/A - 1) in S = sin^2(theta/2): A = (R S - r)/(r (R - r)), B/A - 1 = R (1 - 2 S)/(R S - r).

    With cos(theta) = 1 - 2 S, R S - r changes sign exactly where theta crosses theta_min
    (:func:`minimum_angle`), with no cancellation of the size of 1 against r/R, and one sine
    serves both curvatures.  B/A - 1 = |A - B|/A is the shape datum of the ellipse.
    """
    s = symbols()
    theta = s["theta"]
    A, B = relative_curvatures()
    S = sp.Symbol("S", positive=True)
    half = {sp.cos(theta): 1 - 2 * S}
    A_half = sp.factor(A.subs(half))
    excess = sp.factor((B - A).subs(half) / A_half)
    if sp.simplify(A_half * (1 + excess) - B.subs(half)) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the half-angle curvatures do not give B")
    sine = sp.sin(theta / 2) ** 2
    return A_half.subs(S, sine), excess.subs(S, sine)


@functools.cache
def pair_symbols():
    """Symbols of two different rings: R1, r1, E1, nu1 and R2, r2, E2, nu2 (all positive)."""
    names = "R_1 r_1 E_1 nu_1 R_2 r_2 E_2 nu_2"
    return dict(zip(names.replace("_", "").split(), sp.symbols(names, positive=True), strict=True))


def principal_radii_pair():
    """(R1', R1'', R2', R2''): each torus's tube radius r_i and inner-equator radius -(R_i - r_i).

    Step 1 of the module docstring for two different tori; with R2 = R1, r2 = r1 it is
    :func:`principal_radii`.
    """
    p = pair_symbols()
    return p["r1"], -(p["R1"] - p["r1"]), p["r2"], -(p["R2"] - p["r2"])


def curvature_sums_pair():
    """(A + B, |A - B|) of two different interlocked tori at the contact angle theta (Eqs. (A2a)-(A2b)).

    The generalisation of :func:`curvature_sums` (the tests check that it reduces to it for
    equal rings): |A - B| = sqrt((k1 - k2)^2 + 4 k1 k2 cos^2 theta)/2 with k_i = 1/r_i + 1/(R_i - r_i).
    It is kept in that form, a sum of two squares: expanded over a common denominator, the radicand
    of two equal rings at 90 deg is a difference of large terms that rounds to a small negative
    number, and its square root to NaN.
    """
    R1p, R1pp, R2p, R2pp = principal_radii_pair()
    total, radicand, c = _hertz_sums(R1p, R1pp, R2p, R2pp)
    k1, k2 = 1 / R1p - 1 / R1pp, 1 / R2p - 1 / R2pp
    squares = (k1 - k2) ** 2 + 4 * k1 * k2 * c**2
    if sp.simplify(squares - radicand) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the sum of squares is not Hertz's (2 |A - B|)^2")
    difference = sp.sqrt(squares) / 2
    return sp.factor(sp.together(total)), difference.subs(c, sp.cos(symbols()["theta"]))


def curvature_product_pair():
    """A B = ((A + B)^2 - (A - B)^2)/4 of two different tori, factored.

    A = 2 A B/((A + B) + |A - B|) computes the smaller curvature without the cancellation of
    (A + B) - |A - B| as theta approaches the angle where A = 0; A B is a difference of two
    products, (1/r2 - 1/(R1 - r1))(1/r1 - 1/(R2 - r2)) - k1 k2 cos^2 theta, whose sign is that of A.
    """
    total, difference = curvature_sums_pair()
    theta = symbols()["theta"]
    S = sp.Symbol("S", positive=True)  # sin(theta)^2: cos^2 = 1 - S keeps the sign of A B exact
    product = sp.factor(sp.expand((total**2 - difference**2) / 4).subs(sp.cos(theta) ** 2, 1 - S))
    return product.subs(S, sp.sin(theta) ** 2)


def minimum_angle_pair():
    """Angle theta_min of two different tori at which A = 0: sin^2 theta_min = (r1 + r2)(R1 + R2 - r1 - r2)/(R1 R2).

    Solves A B = 0 (:func:`curvature_product_pair`) for sin^2 theta; for equal rings it is
    :func:`minimum_angle` (4 (r/R)(1 - r/R) = sin^2(2 asin(sqrt(r/R))), checked in the tests).
    """
    theta = symbols()["theta"]
    S = sp.Symbol("S", positive=True)
    (root,) = sp.solve(curvature_product_pair().subs(sp.sin(theta) ** 2, S), S)
    return sp.asin(sp.sqrt(sp.factor(root)))


def effective_modulus_pair():
    """E* of two different materials, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (App. A)."""
    p = pair_symbols()
    return effective_modulus(p["E1"], p["nu1"], p["E2"], p["nu2"])


# --- 3. numeric functions ---------------------------------------------------------------


@derived
def _curvatures():
    s = symbols()
    return (s["R"], s["r"], s["theta"]), tuple(positive_differences(half_angle_curvatures()))


@derived
def _minimum_angle():
    s = symbols()
    return (s["R"], s["r"]), minimum_angle()


def _material_and_shape(K_c, *shape):
    """K_c as (E*-dependent factor, geometric factor) in the material's E and nu."""
    return split_product(K_c.subs(sp.Symbol("E^*", positive=True), effective_modulus()), *shape)


@derived
def _effective_modulus():
    s = symbols()
    return (s["E"], s["nu"]), effective_modulus()


@derived
def _stiffness_circular():
    s = symbols()
    K_c, _ = circular_limit()
    A, _ = relative_curvatures()
    K_c = K_c.subs(s["A"], sp.factor(A.subs(s["theta"], sp.pi / 2)))
    return (s["R"], s["r"], s["E"], s["nu"]), _material_and_shape(K_c, s["R"], s["r"])


@derived
def _stiffness_of_curvature():
    s = symbols()
    K_c, _ = circular_limit()
    return (s["A"], s["E"], s["nu"]), _material_and_shape(K_c, s["A"])


@derived
def _curvatures_pair():
    """(A, |A - B|) of two different tori: A = 2 A B/((A + B) + |A - B|) (:func:`curvature_product_pair`)."""
    p, s = pair_symbols(), symbols()
    total, difference = curvature_sums_pair()
    A = 2 * curvature_product_pair() / (total + difference)
    return (p["R1"], p["r1"], p["R2"], p["r2"], s["theta"]), (A, difference)


@derived
def _minimum_angle_pair():
    p = pair_symbols()
    return (p["R1"], p["r1"], p["R2"], p["r2"]), minimum_angle_pair()


@derived
def _stiffness_of_curvature_pair():
    p, s = pair_symbols(), symbols()
    K_c, Es = circular_limit()
    return (s["A"], p["E1"], p["nu1"], p["E2"], p["nu2"]), K_c.subs(Es, effective_modulus_pair())


@derived
def _long_semi_axis():
    """a(P, A, m_1, E, nu) of :func:`hertz_semi_axes`, with D_m = R_D(0, m_1, 1)/3 (exact as m -> 0 and m -> 1)."""
    s = symbols()
    a, _, Es = hertz_semi_axes()
    _, D_m = elliptic_placeholders()
    a = a.subs({Es: effective_modulus(), D_m: carlson_rd(0, s["m_1"], 1) / 3})
    if s["m"] in a.free_symbols:  # pragma: no cover - derivation check
        raise RuntimeError("the long semi-axis depends on m other than through D_m")
    return (s["P"], s["A"], s["m_1"], s["E"], s["nu"]), a


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
        theta_min = arccos(1 - 2 r/R) = 2 arcsin(sqrt(r/R)) in rad (evaluated in the second
        form, accurate for thin rings too).

    Examples
    --------
    >>> round(float(minimum_contact_angle(20e-3, 2.5e-3)), 6)  # arccos(0.75)
    0.722734
    """
    R, r = v.torus_radii(R, r)
    with np.errstate(all="ignore"):
        return _minimum_angle(R, r)


def _check_material(E, nu):
    return v.positive("E", E, "Pa"), v.in_range("nu", nu, -1.0, 0.5, closed_high=False)


def _check_angle(angle):
    return v.in_range("angle", angle, 0.0, np.pi / 2)


def _ellipse(R, r, angle):
    """(A, B/A - 1) for checked R, r, angle; ValueError at or below theta_min or beyond the table.

    The angle pi/2 (the double nearest it) is the perpendicular contact, B = A exactly; elsewhere
    B/A - 1 is at least 0 (rounding next to pi/2 could make it -1e-16).
    """
    with np.errstate(all="ignore"):
        A, excess = _curvatures(R, r, angle)
        if isinstance(excess, np.ndarray) and excess.shape == np.broadcast_shapes(excess.shape, angle.shape):
            np.maximum(excess, 0.0, out=excess)
            if angle.max() == np.pi / 2:
                excess[np.broadcast_to(angle == np.pi / 2, excess.shape)] = 0.0
        else:
            excess = np.where(angle == np.pi / 2, 0.0, np.maximum(excess, 0.0))
    if not np.asarray(A).min() > 0:
        shape = np.broadcast_shapes(R.shape, r.shape, angle.shape)
        bad = ~(np.broadcast_to(A, shape) > 0)
        given = np.broadcast_to(angle, shape)[bad].min()
        limit = np.broadcast_to(minimum_contact_angle(R, r), shape)[bad].max()
        with np.errstate(over="ignore"):
            overflowed = not np.all(np.isfinite(r * (R - r)))
        if overflowed and given > limit:  # above theta_min, A vanished in rounding: r (R - r) overflowed
            v.finite_result(np.inf, "the relative curvature A", "radii (r (R - r) overflows)")
        raise ValueError(
            f"angle {v.show(given)} rad ({np.degrees(given):.6g} deg) is at or below theta_min = "
            f"{v.show(limit)} rad ({np.degrees(limit):.6g} deg) = arccos(1 - 2r/R), to double precision: "
            "the tori then touch along a line or at two patches, and the single elliptical Hertz contact "
            "does not apply"
        )
    if not np.asarray(excess).max() <= TABLE_MAX_EXCESS:
        raise ValueError(
            f"the contact ellipse is too elongated to represent (ln(B/A) > {TABLE_MAX_LOG_RATIO:g}, b/a < 1e-149): "
            "the angle lies within rounding of theta_min for these extreme proportions of the rings"
        )
    return A, excess


def _times(array, factor):
    """array * factor, in the array's memory when it is a full-shape array of its own."""
    if isinstance(array, np.ndarray) and array.shape == np.broadcast_shapes(array.shape, np.shape(factor)):
        array *= factor
        return array
    return array * factor


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
        Relative curvatures, 1/m, A <= B (App. A, Eq. (A1)).
    m : ndarray
        Squared eccentricity of the contact ellipse, 1 - (b/a)^2 (0 for a circle; it rounds to 1
        when b/a < 1e-8, at angles within about 1e-14 rad of theta_min).

    Notes
    -----
    App. A of the paper with Johnson's elliptical Hertz solution (Contact Mechanics,
    Sec. 4.2).  The aspect ratio of the ellipse is b/a = sqrt(1 - m).  m comes from the
    interpolated solution of the shape equation (:func:`.elliptical.elliptical_table`): relative error
    about 1e-15 for an elongated ellipse, absolute error about 1e-16 as m -> 0.

    Examples
    --------
    >>> A, B, m = contact_ellipse(22.5e-3, 2.5e-3)
    >>> bool(A == B), float(m)  # perpendicular rings: a circle
    (True, 0.0)
    >>> A, B, m = contact_ellipse(22.5e-3, 2.5e-3, np.radians(60))
    >>> round(float(B / A), 4), round(float(np.sqrt(1 - m)), 4)  # B/A and b/a
    (4.6, 0.3652)
    """
    R, r = v.torus_radii(R, r)
    angle = _check_angle(angle)
    v.broadcast_shape(R=R, r=r, angle=angle)
    A, excess = _ellipse(R, r, angle)
    with np.errstate(all="ignore"):
        B = A * (1 + excess)
        log_ratio = np.log1p(excess)
        m = np.minimum(log_ratio * from_table(1, np.log1p(log_ratio)), 1.0)  # 1 - m < 1e-16 rounds to 1
    reason = "radii (the curvatures 1/r overflow)"
    return v.finite_result(A, "A", reason), v.finite_result(B, "B", reason), m


def contact_semi_axes(R, r, E, nu, angle=np.pi / 2, *, F):
    """Semi-axes a >= b of the Hertz contact ellipse of two identical tori under the force F, m.

    Parameters
    ----------
    R, r, E, nu, angle : array_like
        As :func:`hertz_stiffness` (m, Pa, rad; angle in (theta_min, pi/2], default pi/2).
    F : array_like
        Force pressing the tori together, N, > 0 (keyword-only: it would pass silently for R).

    Returns
    -------
    a, b : ndarray
        Long and short semi-axis, m; a along the bisector of the ring planes (the direction of the
        smaller relative curvature A), b = a sqrt(1 - m) across it.

    Notes
    -----
    Johnson's elliptical solution (Contact Mechanics, Sec. 4.2; :func:`hertz_semi_axes`),
    a^3 = 3 F (K(m) - E(m))/(2 pi m A E*), with A and m from :func:`contact_ellipse`; at
    pi/2 the sphere of App. A, a^3 = 3 F R'/(4 E*).  The half-space solution, and with it the
    single-ellipse K_c of Eq. (1), needs a small against the tube radius r: as theta falls to
    theta_min the ellipse grows into a line at any force.  ``b`` rounds to 0 when b/a < 1e-8.

    Examples
    --------
    >>> a, b = contact_semi_axes(22.5e-3, 2.5e-3, 193e9, 0.29, F=100.0)
    >>> round(float(a) * 1e3, 4), bool(a == b)  # mm: a circle at 90 deg
    (0.1267, True)
    """
    R, r = v.torus_radii(R, r)
    E, nu = _check_material(E, nu)
    angle = _check_angle(angle)
    F = v.positive("F", F, "N")
    v.broadcast_shape(R=R, r=r, E=E, nu=nu, angle=angle, F=F)
    A, _, m = contact_ellipse(R, r, angle)
    with np.errstate(all="ignore"):
        m_1 = 1.0 - m
        a = np.asarray(_long_semi_axis(F, A, m_1, E, nu), dtype=float)
        b = a * np.sqrt(m_1)
    reason = "force, radii and elastic constants"
    return v.finite_result(a, "the semi-axis a", reason), v.finite_result(b, "the semi-axis b", reason)


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
        Contact angle theta between the ring planes, rad, in (theta_min, pi/2]
        (:func:`minimum_contact_angle`); default pi/2 (perpendicular).

    Returns
    -------
    ndarray
        K_c in N/m^1.5.

    Notes
    -----
    Paper Eq. (1) and App. A (Eq. (A3)) for theta = pi/2, where the contact is circular
    with R' = R'' = r(R - r)/(R - 2r) (the m -> 0 limit of the elliptical solution,
    :func:`circular_limit`); for other angles the exact elliptical Hertz solution
    (Johnson, Contact Mechanics, Sec. 4.2), K_c = K_c(0, A) Gamma(m), with the factor
    Gamma interpolated from its tabulated solution (:func:`.elliptical.elliptical_table`, relative
    error about 1e-15).  Raises ``ValueError`` for R <= 2 r, for angles at or below
    :func:`minimum_contact_angle`, and for inputs so extreme that K_c overflows.

    Examples
    --------
    >>> K_c = hertz_stiffness(22.5e-3, 2.5e-3, 193e9, 0.29)
    >>> round(float(K_c) / 1e9, 3)  # GN/m^1.5
    7.509
    """
    R, r = v.torus_radii(R, r)
    E, nu = _check_material(E, nu)
    angle = _check_angle(angle)
    v.broadcast_shape(R=R, r=r, E=E, nu=nu, angle=angle)
    if angle.size and angle.min() == np.pi / 2:  # validated <= pi/2: all perpendicular
        with np.errstate(all="ignore"):
            material, geometry = _stiffness_circular(R, r, E, nu)
            K_c = _times(geometry, material)
    else:
        A, excess = _ellipse(R, r, angle)
        with np.errstate(all="ignore"):
            s = np.log1p(np.log1p(excess, out=excess if isinstance(excess, np.ndarray) else None))
            material, curvature = _stiffness_of_curvature(A, E, nu)
            K_c = _times(_times(from_table(0, s, overwrite=True), curvature), material)
    return v.finite_result(K_c, "K_c", "radii and elastic constants")


def hertz_stiffness_pair(R1, r1, E1, nu1, R2, r2, E2, nu2, angle=np.pi / 2):
    """Hertz contact stiffness K_c of two different interlocked tori, F = K_c delta^(3/2).

    Parameters
    ----------
    R1, r1 : array_like
        Major and tube radius of the first torus, m (R1 > 2 r1).
    E1, nu1 : array_like
        Its Young's modulus (Pa) and Poisson's ratio (in (-1, 0.5)).
    R2, r2, E2, nu2 : array_like
        The same for the second torus.
    angle : array_like, optional
        Contact angle theta between the ring planes, rad, in (0, pi/2]; default pi/2.  The
        single elliptical contact needs A > 0 (below, the tori touch along a line or at two
        patches, as for equal rings: :func:`minimum_contact_angle`).

    Returns
    -------
    ndarray
        K_c in N/m^1.5; symmetric in the two rings, and equal to :func:`hertz_stiffness`
        (to its last digit: that evaluation is used) when the rings are the same.

    Notes
    -----
    App. A of the paper (Eqs. (A2a)-(A2b)) with the principal radii of two different tori
    (:func:`curvature_sums_pair`), the effective modulus of two materials
    (:func:`effective_modulus_pair`), and the exact elliptical Hertz solution of
    :func:`hertz_stiffness`: K_c = K_c(0, A) Gamma(m), Gamma from the same table
    (:func:`.elliptical.elliptical_table`) at the shape B/A of this pair.  For perpendicular rings of
    equal proportions it is Eq. (1).  The centre distance of the two rings is
    (R1 - r1) + (R2 - r2).

    Examples
    --------
    >>> K_c = hertz_stiffness_pair(22.5e-3, 2.5e-3, 193e9, 0.29, 15e-3, 2.5e-3, 193e9, 0.29)
    >>> round(float(K_c) / 1e9, 3)  # GN/m^1.5: between the two rings' own 7.509 and 7.853
    7.68
    """
    R1, r1 = v.torus_radii(R1, r1)
    R2, r2 = v.torus_radii(R2, r2)
    E1, nu1 = _check_material(E1, nu1)
    E2, nu2 = _check_material(E2, nu2)
    angle = _check_angle(angle)
    v.broadcast_shape(R1=R1, r1=r1, E1=E1, nu1=nu1, R2=R2, r2=r2, E2=E2, nu2=nu2, angle=angle)
    if np.array_equal(R1, R2) and np.array_equal(r1, r2) and np.array_equal(E1, E2) and np.array_equal(nu1, nu2):
        return hertz_stiffness(R1, r1, E1, nu1, angle)  # the pair of identical tori
    K_c = _pair_stiffness(R1, r1, E1, nu1, R2, r2, E2, nu2, angle)
    same = (R1 == R2) & (r1 == r2) & (E1 == E2) & (nu1 == nu2)
    if np.any(same):  # identical pairs among different ones: the single-torus number, as for equal arrays
        shape = np.broadcast_shapes(np.shape(K_c), same.shape, angle.shape)
        K_c = np.array(np.broadcast_to(K_c, shape), dtype=float)
        picked = np.broadcast_to(same, shape)
        K_c[picked] = hertz_stiffness(*(np.broadcast_to(x, shape)[picked] for x in (R1, r1, E1, nu1, angle)))
    return K_c


def _pair_stiffness(R1, r1, E1, nu1, R2, r2, E2, nu2, angle):
    """:func:`hertz_stiffness_pair` of checked arrays, by the two-torus derivation (also for equal rings)."""
    with np.errstate(all="ignore"):
        A, difference = _curvatures_pair(R1, r1, R2, r2, angle)
        excess = difference / A
    if not np.asarray(A).min() > 0:
        with np.errstate(all="ignore"):
            limit = _minimum_angle_pair(R1, r1, R2, r2)
        shape = np.broadcast_shapes(*(np.shape(x) for x in (A, angle, limit)))
        bad = ~(np.broadcast_to(A, shape) > 0)
        given, at = np.broadcast_to(angle, shape)[bad].min(), np.broadcast_to(limit, shape)[bad].max()
        reason = (
            f"at or below the smallest angle of a single contact of this pair, {v.show(at)} rad "
            f"({np.degrees(at):.6g} deg)" if np.isfinite(at) else
            "impossible for this pair: the tubes are too thick for the holes, (r1 + r2)(R1 + R2 - r1 - r2) > R1 R2"
        )  # fmt: skip
        raise ValueError(
            f"angle {v.show(given)} rad ({np.degrees(given):.6g} deg) is {reason}: the elliptical Hertz contact "
            "of the two tori does not apply"
        )
    if not np.asarray(excess).max() <= TABLE_MAX_EXCESS:
        raise ValueError(
            f"the contact ellipse is too elongated to represent (ln(B/A) > {TABLE_MAX_LOG_RATIO:g}): the angle "
            "lies within rounding of the smallest angle of a single contact of this pair"
        )
    with np.errstate(all="ignore"):
        s = np.log1p(np.log1p(np.maximum(excess, 0.0)))
        K_c = from_table(0, s) * _stiffness_of_curvature_pair(A, E1, nu1, E2, nu2)
    return v.finite_result(K_c, "K_c", "radii and elastic constants")


def contact_modulus(E, nu):
    """Effective modulus E* of two identical bodies, Pa: 1/E* = 2 (1 - nu^2)/E (App. A).

    Parameters
    ----------
    E : array_like
        Young's modulus, Pa.
    nu : array_like
        Poisson's ratio, in (-1, 0.5).

    Returns
    -------
    ndarray
        E* = E/(2 (1 - nu^2)), Pa (:func:`effective_modulus`).

    Examples
    --------
    >>> round(float(contact_modulus(193e9, 0.29)) / 1e9, 2)  # GPa
    105.36
    """
    E, nu = _check_material(E, nu)
    v.broadcast_shape(E=E, nu=nu)
    with np.errstate(all="ignore"):
        modulus = _effective_modulus(E, nu)
    return v.finite_result(modulus, "E*", "elastic constants")
