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
5. :func:`hertz_elliptical` -- any theta: Johnson's elliptical solution (Contact
   Mechanics, Sec. 4.2, Eqs. 4.39-4.41) with complete elliptic integrals K(m), E(m)
   of the ellipse's eccentricity e^2 = m, eliminated to P = K_c(m, A) delta^(3/2) and
   the shape equation B/A = (E/(1 - m) - K)/(K - E).  :func:`circular_limit` is its
   m -> 0 limit (the same K_c as step 4, by a second route), and :func:`elliptical_factor`
   the ratio Gamma(m) = K_c(m, A)/K_c(0, A), a function of the shape alone.
6. Numbers.  Carlson's forms (:mod:`.special`), K(m) = R_F(0, 1-m, 1) and (K - E)/m =
   R_D(0, 1-m, 1)/3, keep the circular limit m -> 0 exact in floating point, and with the
   complementary parameter m_1 = 1 - m as the variable they stay exact as m -> 1 too.
   The shape equation has no closed-form inverse, and evaluating R_F and R_D is slow
   (R_D costs as much as a few hundred NumPy operations per point), so the numeric code does not solve it
   point by point.  Gamma and m are smooth functions of s = ln(1 + ln(B/A)) (s = 0 for the
   circle; s -> infinity as theta -> theta_min); :func:`elliptical_table` solves the
   shape equation once, at the Chebyshev points of short intervals of s, and stores the
   interpolating polynomials (accurate to a few units of 1e-16; the derivation checks
   the error at the midpoints).  A call then costs a table look-up and a polynomial
   per point, and the perpendicular case (theta = pi/2 exactly) skips it altogether.

The effective modulus 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (App. A) is
:func:`effective_modulus`.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from ._codegen import derived, sp
from ._forms import positive_differences, split_product
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
    "hertz_semi_axes",
    "elliptic_placeholders",
    "ellipse_shape_ratio",
    "minimum_angle",
    "half_angle_curvatures",
    "circular_limit",
    "elliptical_factor",
    "carlson_form",
    "elliptical_table",
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
    "gap_symbols",
    "torus_distance_expr",
    "inner_surface_height",
    "surface_gap",
    "surface_gap_quadratic",
    "patch_geometry",
    "torus_distance",
    "torus_gap",
    "contact_patches",
    "smallest_patch_angle",
    "contact_modulus",
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
    m_1 = sp.Symbol("m_1", positive=True)  # complementary parameter 1 - m = (b/a)^2
    return dict(R=R, r=r, E=E, nu=nu, theta=theta, m=m, A=A, B=B, P=P, delta=delta, a=a, b=b, p0=p0, m_1=m_1)


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


def elliptic_placeholders():
    """Positive symbols K_m = K(m) and D_m = (K(m) - E(m))/m used inside the derivation.

    Working with them keeps the algebra to monomials (fast, no ``simplify``); they are
    replaced by the elliptic integrals at the end (:func:`hertz_elliptical`), or by
    Carlson's forms R_F(0, 1-m, 1) and R_D(0, 1-m, 1)/3 for numerics (:mod:`.special`).
    """
    return sp.Symbol("K_m", positive=True), sp.Symbol("D_m", positive=True)


def hertz_elliptical_monomial():
    """K_c of an elliptical contact as a monomial in A, E*, K_m = K(m), D_m = (K - E)/m.

    Johnson Sec. 4.2 (semi-axes a >= b, b = a sqrt(1 - m), peak pressure p0)::

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


def hertz_semi_axes():
    """(a, b, E*): the semi-axes a >= b of the contact ellipse under the load P (Johnson Sec. 4.2).

    From the same relations as :func:`hertz_elliptical_monomial` (P = 2/3 pi a b p0,
    A = p0 b D_m/(E* a^2), b = a sqrt(1 - m)), solved for a instead of the approach:
    a^3 = 3 P D_m/(2 pi A E*) with D_m = (K(m) - E(m))/m (:func:`elliptic_placeholders`); at
    m = 0 (D_m = pi/4, A = 1/(2 R_e)) Hertz's sphere a^3 = 3 P R_e/(4 E*).  The half-space
    model holds while a is small against the tube (:data:`ringchain.numerics.HALF_SPACE_LIMIT`).
    """
    s = symbols()
    P, A, m, a, p0 = (s[k] for k in ("P", "A", "m", "a", "p0"))
    Es = sp.Symbol("E^*", positive=True)
    _, D_m = elliptic_placeholders()
    b_of_a = a * sp.sqrt(1 - m)
    _, p0_of_a = sp.solve_linear(A - p0 * b_of_a * D_m / (Es * a**2), symbols=[p0])
    per_cube = sp.cancel(sp.Rational(2, 3) * sp.pi * a * b_of_a * p0_of_a / a**3)
    if a in per_cube.free_symbols:  # pragma: no cover - derivation check
        raise RuntimeError("Johnson's load is not proportional to a^3")
    a_of_P = (P / per_cube) ** sp.Rational(1, 3)
    return a_of_P, a_of_P * sp.sqrt(1 - m), Es


def ellipse_shape_ratio():
    """B/A as a function of m, from Johnson's two curvature equations (Sec. 4.2)."""
    s = symbols()
    m = s["m"]
    K, E = sp.elliptic_k(m), sp.elliptic_e(m)
    A_rel = (K - E) / m  # common factor p0 b/(E* a^2) dropped
    B_rel = (E / (1 - m) - K) / m
    return sp.simplify(B_rel / A_rel)


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


def circular_limit():
    """K_c(A, E*) of the circular contact: :func:`hertz_elliptical` as m -> 0 (R' = R'' = 1/(2A)).

    A second route to step 4: with A = 1/(2 R_e) it is 4/3 E* sqrt(R_e) (the tests check
    it against :func:`hertz_circular` and the paper's Eq. (1)).  Returns (K_c, E*).
    """
    K_c, Es = hertz_elliptical()
    return sp.limit(K_c, symbols()["m"], 0), Es


def elliptical_factor():
    """Gamma(m) = K_c(m, A)/K_c(0, A): how much stiffer the elliptical contact is than the circular
    one of the same curvature A.  A function of m alone (A and E* cancel, checked)."""
    s = symbols()
    K_c, Es = hertz_elliptical()
    circular, _ = circular_limit()
    factor = sp.simplify(K_c / circular)
    if factor.has(s["A"], Es):  # pragma: no cover - derivation check
        raise RuntimeError("the elliptical factor depends on more than the shape")
    return factor


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


def carlson_form(expr):
    """``expr`` in terms of the complementary parameter m_1 = 1 - m, with K(m) -> R_F(0, m_1, 1)
    and E(m) -> R_F - m R_D(0, m_1, 1)/3 (DLMF 19.25.1), by way of the placeholders K_m and
    D_m = (K - E)/m so that m cancels exactly.  Exact in floating point as m -> 0 and,
    with m_1 as the variable, as m -> 1."""
    s = symbols()
    m, m_1 = s["m"], s["m_1"]
    K_m, D_m = elliptic_placeholders()
    placeholders = sp.cancel(expr.subs({sp.elliptic_e(m): K_m - m * D_m}).subs({sp.elliptic_k(m): K_m}))
    carlson = placeholders.subs({K_m: carlson_rf(0, 1 - m, 1), D_m: carlson_rd(0, 1 - m, 1) / 3})
    return sp.factor(carlson.subs(m, 1 - m_1))


#: Intervals of s = ln(1 + ln(B/A)) of the elliptical table, their polynomial degree, and the
#: largest ln(B/A) covered: 690, an ellipse with b/a about 1e-151, beyond any use (the single
#: Hertz ellipse needs theta well above theta_min); the last interval ends where m_1 = 1 - m
#: reaches the smallest normal double.
#: Beyond this length (m) its square overflows a double.
_SQUARE_LIMIT = float(np.sqrt(np.finfo(float).max))

_TABLE_STEP = 0.025
_TABLE_DEGREE = 5
_TABLE_MAX_LOG_RATIO = 690.0
_TABLE_MAX_EXCESS = float(np.expm1(_TABLE_MAX_LOG_RATIO))  # B/A - 1


def _table_intervals():
    top = float(np.log1p(_TABLE_MAX_LOG_RATIO))
    return int(top / _TABLE_STEP) + 1, top


def _lambdify_floats(args, exprs):
    """A float evaluator of SymPy expressions that may call SciPy's Carlson integrals (derivation time only)."""
    import scipy.special

    return sp.lambdify(args, exprs, modules=[{"scipy": scipy}, "numpy"])


def elliptical_table():
    """Coefficients of the piecewise polynomials of Gamma and m/ln(B/A) in s = ln(1 + ln(B/A)).

    On each interval [j h, (j + 1) h] (h = ``_TABLE_STEP``) both functions are interpolated at
    the Chebyshev points by polynomials of degree ``_TABLE_DEGREE`` in t = 2 (s/h - j) - 1.
    The values at the points come from the shape equation (:func:`ellipse_shape_ratio`)
    solved for m_1 = 1 - m in :func:`carlson_form` by bisection in ln(m_1) (B/A increases
    monotonically as m_1 falls from 1 to 0), and from :func:`elliptical_factor`.  The
    interpolation error is checked at every interval's midpoint (below 1e-14 relative).

    Returns an array of shape (2, degree + 1, intervals): [0] Gamma, [1] m/ln(B/A); row k
    holds the coefficients of t^k.
    """
    s = symbols()
    m_1 = s["m_1"]
    log_ratio = sp.log(carlson_form(ellipse_shape_ratio()))
    factor = carlson_form(elliptical_factor())
    evaluate = _lambdify_floats((m_1,), (log_ratio, factor))
    intervals, _ = _table_intervals()
    k = np.arange(_TABLE_DEGREE + 1)
    points = np.cos(np.pi * (k + 0.5) / (_TABLE_DEGREE + 1))  # Chebyshev points in [-1, 1]
    start = np.arange(intervals)[:, None]
    s_points = (start + 0.5 * (1 + points)) * _TABLE_STEP
    s_middle = (np.arange(intervals) + 0.5) * _TABLE_STEP

    def values(s_value):
        target = np.expm1(s_value)  # ln(B/A)
        lo = np.full_like(target, np.log(np.finfo(float).tiny))  # ln(m_1): B/A -> infinity
        hi = np.zeros_like(target)  # m_1 = 1: the circle, ln(B/A) = 0
        for _ in range(90):  # 708 / 2^90 is far below the spacing of doubles near ln(m_1)
            middle = 0.5 * (lo + hi)
            above = evaluate(np.exp(middle))[0] > target
            lo = np.where(above, middle, lo)
            hi = np.where(above, hi, middle)
        log_m_1 = 0.5 * (lo + hi)
        gamma = evaluate(np.exp(log_m_1))[1]
        m = -np.expm1(log_m_1)
        # m/ln(B/A) -> 4/3 at the circle (B/A = 1 + 3m/4 + ...); the first point has s > 0.
        return np.stack([gamma, m / target])

    with np.errstate(divide="ignore", invalid="ignore"):
        at_points = values(s_points.ravel()).reshape(2, intervals, -1)
        at_middle = values(s_middle)
    vandermonde = np.vander(points, _TABLE_DEGREE + 1, increasing=True)
    coefficients = np.linalg.solve(vandermonde, at_points.transpose(2, 0, 1).reshape(_TABLE_DEGREE + 1, -1))
    coefficients = coefficients.reshape(_TABLE_DEGREE + 1, 2, intervals).transpose(1, 0, 2)
    error = np.max(np.abs(coefficients[:, 0, :] / at_middle - 1), axis=1)  # t = 0 at the midpoints
    # Gamma to 1e-14; m/ln(B/A) to 1e-13, since m (found to about 1e-16 absolute) is divided by
    # ln(B/A) ~ 1e-3 in the first interval.
    if not (error[0] < 1e-14 and error[1] < 1e-13):  # pragma: no cover - derivation check
        raise RuntimeError(f"the elliptical table interpolates to {error[0]:.1e} and {error[1]:.1e} only")
    return coefficients


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


@derived
def _stiffness_elliptical():
    """:func:`elliptical_table` as generated code (a constant array: no arguments)."""
    table = elliptical_table()
    exact = [sp.Float(float(value), 17) for value in table.ravel()]  # 17 digits: every double round-trips
    if any(float(e) != value for e, value in zip(exact, table.ravel(), strict=True)):  # pragma: no cover
        raise RuntimeError("the table does not round-trip through its printed digits")
    return (), sp.ImmutableDenseMatrix(table.shape[0] * table.shape[1], table.shape[2], exact)


@functools.cache
def _table() -> np.ndarray:
    table = np.asarray(_stiffness_elliptical(), dtype=float)
    return table.reshape(2, _TABLE_DEGREE + 1, -1)


def _from_table(which: int, s, overwrite=False):
    """Gamma (which = 0) or m/ln(B/A) (which = 1) at s = ln(1 + ln(B/A)), 0 <= s < top.

    Horner's scheme in t on the interval of each point, in place (few temporaries: on 10^5
    points a fresh array costs as much as the arithmetic); ``overwrite`` lets it use s's memory.
    """
    coefficients = _table()[which]
    t = np.multiply(s, 1.0 / _TABLE_STEP, out=s if overwrite and isinstance(s, np.ndarray) else None)
    index = t.astype(np.intp)
    t -= index
    t *= 2.0
    t -= 1.0
    value = coefficients[_TABLE_DEGREE].take(index)
    for row in coefficients[_TABLE_DEGREE - 1 :: -1]:
        value *= t
        value += row.take(index)
    return value


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
    R, r = _check_geometry(R, r)
    with np.errstate(all="ignore"):
        return _minimum_angle(R, r)


def _check_geometry(R, r):
    """R, r as float arrays with 0 < 2 r < R, finite; a ValueError naming the problem otherwise.

    The usual case (r one number) costs two reductions over R.
    """
    r = v.positive("r", r, "m")
    R = v.as_array("R", R)
    v.broadcast_shape(R=R, r=r)
    if R.size and r.size == 1:
        lo, hi = R.min(), R.max()
        fine = bool(hi < np.inf and 0.5 * lo > r.reshape(()))  # False for NaN too; 0.5 R is exact
    else:
        fine = False
    if not fine:
        R = v.positive("R", R, "m")
        if not np.all(0.5 * R > r):
            with np.errstate(all="ignore"):
                ratio = np.min(R / r)
            raise ValueError(
                "R must exceed 2 r: for R <= 2 r the relative curvature of two interlocked tori is not "
                f"positive and Hertz contact does not apply (got R/r = {v.show(ratio)})"
            )
    return R, r


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
    if not np.asarray(excess).max() <= _TABLE_MAX_EXCESS:
        raise ValueError(
            f"the contact ellipse is too elongated to represent (ln(B/A) > {_TABLE_MAX_LOG_RATIO:g}, b/a < 1e-149): "
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
    interpolated solution of the shape equation (:func:`elliptical_table`): relative error
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
    R, r = _check_geometry(R, r)
    angle = _check_angle(angle)
    v.broadcast_shape(R=R, r=r, angle=angle)
    A, excess = _ellipse(R, r, angle)
    with np.errstate(all="ignore"):
        B = A * (1 + excess)
        log_ratio = np.log1p(excess)
        m = np.minimum(log_ratio * _from_table(1, np.log1p(log_ratio)), 1.0)  # 1 - m < 1e-16 rounds to 1
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
    R, r = _check_geometry(R, r)
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
    Gamma interpolated from its tabulated solution (:func:`elliptical_table`, relative
    error about 1e-15).  Raises ``ValueError`` for R <= 2 r, for angles at or below
    :func:`minimum_contact_angle`, and for inputs so extreme that K_c overflows.

    Examples
    --------
    >>> K_c = hertz_stiffness(22.5e-3, 2.5e-3, 193e9, 0.29)
    >>> round(float(K_c) / 1e9, 3)  # GN/m^1.5
    7.509
    """
    R, r = _check_geometry(R, r)
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
            K_c = _times(_times(_from_table(0, s, overwrite=True), curvature), material)
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
    (:func:`elliptical_table`) at the shape B/A of this pair.  For perpendicular rings of
    equal proportions it is Eq. (1).  The centre distance of the two rings is
    (R1 - r1) + (R2 - r2).

    Examples
    --------
    >>> K_c = hertz_stiffness_pair(22.5e-3, 2.5e-3, 193e9, 0.29, 15e-3, 2.5e-3, 193e9, 0.29)
    >>> round(float(K_c) / 1e9, 3)  # GN/m^1.5: between the two rings' own 7.509 and 7.853
    7.68
    """
    R1, r1 = _check_geometry(R1, r1)
    R2, r2 = _check_geometry(R2, r2)
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
    if not np.asarray(excess).max() <= _TABLE_MAX_EXCESS:
        raise ValueError(
            f"the contact ellipse is too elongated to represent (ln(B/A) > {_TABLE_MAX_LOG_RATIO:g}): the angle "
            "lies within rounding of the smallest angle of a single contact of this pair"
        )
    with np.errstate(all="ignore"):
        s = np.log1p(np.log1p(np.maximum(excess, 0.0)))
        K_c = _from_table(0, s) * _stiffness_of_curvature_pair(A, E1, nu1, E2, nu2)
    return v.finite_result(K_c, "K_c", "radii and elastic constants")


# --- 4. the exact gap of two tori (beyond the quadratic Hertz gap) ----------------------
#
# Chain axis z.  Ring 1 is centred at the origin with its centre circle (radius R) in the
# xz-plane; ring 2 is the same torus turned by theta about the chain axis and centred at
# (0, 0, d).  They touch on the inside of both tubes, ring 1's tube above ring 2's; at the
# centre distance d = 2(R - r) (the paper's spacing a) the contact points of the Hertz
# derivation coincide at (0, 0, R - r).


@functools.cache
def gap_symbols():
    """Symbols of the exact-gap section: x, y (position normal to the chain axis, m), X, Y, Z
    (a point in a torus's own frame, m), p, q (in-plane and out-of-plane offsets on one tube),
    L = R - r (the inner-equator radius), S, C = sin, cos of theta/2, u = sqrt(r^2 - q^2)."""
    x, y, X, Y, Z, p, q = sp.symbols("x y X Y Z p q", real=True)
    L = sp.Symbol("L", positive=True)
    S, C = sp.symbols("S C", positive=True)
    u = sp.Symbol("u", real=True)
    return dict(x=x, y=y, X=X, Y=Y, Z=Z, p=p, q=q, L=L, S=S, C=C, u=u)


def _with_inner_radius(expr):
    """``expr`` with R = L + r, L = R - r > 0, so that sqrt((R - r)^2) = R - r simplifies."""
    s, g = symbols(), gap_symbols()
    return expr.subs(s["R"], g["L"] + s["r"])


def torus_distance_expr():
    """Signed distance D(X, Y, Z) from a point to a torus (negative inside).

    The torus is the set of points at distance r from its centre circle, of radius R in the
    XZ-plane about the origin.  The nearest point of that circle to (X, Y, Z) is
    R (X, 0, Z)/sqrt(X^2 + Z^2); D is the distance to it, minus r.
    """
    s, g = symbols(), gap_symbols()
    R, r, X, Y, Z = s["R"], s["r"], g["X"], g["Y"], g["Z"]
    rho = sp.sqrt(X**2 + Z**2)
    offset = sp.Matrix([X, Y, Z]) - R * sp.Matrix([X / rho, 0, Z / rho])
    # |offset|^2 = (rho - R)^2 + Y^2, written so that the square root is visibly a distance.
    distance2 = (rho - R) ** 2 + Y**2
    if sp.simplify(distance2 - offset.dot(offset)) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("distance to the centre circle")
    return sp.sqrt(distance2) - r


def inner_surface_height():
    """Height f(p, q) of a torus's inner tube surface above its inner-equator point.

    Solving D(p, q, Z) = 0 (:func:`torus_distance_expr`) for Z on the branch through the
    inner equator (p, q) = (0, 0), Z = R - r: sqrt(p^2 + Z^2) = R - sqrt(r^2 - q^2), then
    Z = sqrt((R - sqrt(r^2 - q^2))^2 - p^2).  p runs along the ring (in its plane), q
    across it (around the tube).  Returns f = Z - (R - r).
    """
    s, g = symbols(), gap_symbols()
    R, r, p, q = s["R"], s["r"], g["p"], g["q"]
    w = sp.Symbol("w", positive=True)  # sqrt(p^2 + Z^2), the distance from the ring's axis
    on_surface = torus_distance_expr().subs(sp.sqrt(g["X"] ** 2 + g["Z"] ** 2), w).subs(g["Y"], q)
    radii = sp.solve(on_surface, w)  # the outer and the inner side of the tube
    L = gap_symbols()["L"]
    inner = [root for root in radii if sp.simplify(_with_inner_radius(root.subs(q, 0)) - L) == 0]
    if len(inner) != 1:  # pragma: no cover - derivation check
        raise RuntimeError(f"inner branch of the tube not found among {radii}")
    # p^2 + Z^2 = w^2 on the inner side; ring 1's top (where ring 2 hangs) is the root Z > 0.
    height = sp.sqrt(inner[0] ** 2 - p**2)
    if sp.simplify(_with_inner_radius(height.subs({p: 0, q: 0})) - L) != 0:  # pragma: no cover
        raise RuntimeError("the upper root does not pass through the inner equator")
    return height - (R - r)


def surface_gap():
    """Exact gap g(x, y) between the two tubes along the chain axis at centre distance 2(R - r).

    Ring 1's tube surface is z_1 = (R - r) + f(x, y); ring 2, turned by theta and upside
    down, has z_2 = (R - r) - f(s, t) with s = x cos(theta) + y sin(theta) and
    t = -x sin(theta) + y cos(theta) its own in-plane and out-of-plane coordinates, so
    g = z_1 - z_2 = f(x, y) + f(s, t).  At centre distance 2(R - r) + delta the gap is
    g - delta; wherever g < 0 the undeformed tori overlap (below theta_min).
    """
    s, g = symbols(), gap_symbols()
    x, y, theta, p, q = g["x"], g["y"], s["theta"], g["p"], g["q"]
    f = inner_surface_height()
    along = x * sp.cos(theta) + y * sp.sin(theta)
    across = -x * sp.sin(theta) + y * sp.cos(theta)
    return f.subs({p: x, q: y}) + f.subs({p: along, q: across}, simultaneous=True)


def surface_gap_quadratic():
    """Second-order Taylor polynomial of :func:`surface_gap` about the axis, with L = R - r.

    Its quadratic form has the eigenvalues A and B of :func:`relative_curvatures`
    (App. A, Eqs. (A1)-(A2)); the tests check trace A + B and determinant A B.
    """
    g = gap_symbols()
    eps = sp.Symbol("epsilon", positive=True)
    scaled = _with_inner_radius(surface_gap()).subs({g["x"]: eps * g["x"], g["y"]: eps * g["y"]})
    return sp.expand(sp.series(scaled, eps, 0, 3).removeO().coeff(eps, 2))


def patch_geometry():
    """The two contact points below theta_min: distance from the axis, gap there, slope.

    By the symmetries of the two tori (a half turn about the chain axis; the reflection in
    the vertical plane through the bisector of the ring planes, which swaps them), g is
    even along the bisector direction (cos(theta/2), sin(theta/2)).  On it ring 1 has
    (p, q) = c (C, S) with C, S = cos, sin of theta/2, ring 2 (c C, -c S), so g = 2 f(c C, c S).
    With u = sqrt(r^2 - q^2) the radicand of f is W(u) = (R - u)^2 - C^2 (r^2 - u^2)/S^2,
    convex in u; dW/du = 0 gives u* = R S^2, which lies on the tube (u* < r) exactly
    when cos(theta) > 1 - 2 r/R, i.e. below theta_min.  Returns a dict of expressions in
    R, r, theta: ``c`` (distance of each point from the axis along the bisector), ``gap``
    (g there, negative: the overlap at centre distance 2(R - r)) and ``slope2`` (squared
    slope |grad f|^2 of the tube there, so the common normal leans by
    arctan(sqrt(slope2)) from the chain axis).  These hold while R sin(theta/2) > r; at
    R sin(theta/2) = r the points reach the sides of the tubes and the slope is infinite.
    """
    s, g = symbols(), gap_symbols()
    R, r, theta = s["R"], s["r"], s["theta"]
    S, C, u, L, p, q = g["S"], g["C"], g["u"], g["L"], g["p"], g["q"]
    W = (R - u) ** 2 - C**2 * (r**2 - u**2) / S**2
    (u_star,) = sp.solve(sp.diff(W, u), u)
    u_star = sp.simplify(u_star.subs(C**2, 1 - S**2))
    c = sp.sqrt((r**2 - u_star**2) / S**2)
    f = inner_surface_height()
    # W(u*) = C^2 (R^2 S^2 - r^2)/S^2: positive while R sin(theta/2) > r (the point is on
    # the upper half of the tube; at R sin(theta/2) = r it reaches the tube's side).
    per_C2 = sp.factor(sp.simplify(W.subs(u, u_star).subs(C**2, 1 - S**2) / (1 - S**2)))
    gap = 2 * (C * sp.sqrt(per_C2) - (R - r))
    slope2 = sum(sp.diff(f, v) ** 2 for v in (p, q))
    slope2 = slope2.subs({p: c * C, q: c * S}, simultaneous=True)
    slope2 = sp.factor(sp.simplify(_with_inner_radius(slope2).subs(C, sp.sqrt(1 - S**2)).subs(L, R - r)))
    half = {S: sp.sin(theta / 2), C: sp.cos(theta / 2)}
    return dict(c=sp.simplify(c.subs(half)), gap=gap.subs(half), slope2=slope2.subs(half))


# --- 5. numeric functions of the exact gap ------------------------------------------------


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


@derived
def _distance():
    s, g = symbols(), gap_symbols()
    D = torus_distance_expr()
    point = (g["X"], g["Y"], g["Z"])
    return (*point, s["R"], s["r"]), (D, *(sp.diff(D, v) for v in point))


@derived
def _gap():
    s, g = symbols(), gap_symbols()
    return (g["x"], g["y"], s["R"], s["r"], s["theta"]), surface_gap()


@derived
def _patches():
    s = symbols()
    geometry = patch_geometry()
    return (s["R"], s["r"], s["theta"]), (geometry["c"], geometry["gap"], sp.atan(sp.sqrt(geometry["slope2"])))


def torus_distance(X, Y, Z, R, r):
    """Signed distance from points to a torus, and its gradient (the outward unit normal).

    Parameters
    ----------
    X, Y, Z : array_like
        Points in the torus's own frame, m: centre at the origin, centre circle of radius
        R in the XZ-plane (so Y is along the torus's axis of symmetry).
    R, r : array_like
        Major and tube radius, m.

    Returns
    -------
    D : ndarray
        Distance to the surface, m; negative inside the solid torus.
    gradient : tuple of ndarray
        (dD/dX, dD/dY, dD/dZ), a unit vector away from the centre circle.

    Notes
    -----
    :func:`torus_distance_expr`.  Undefined on the axis X = Z = 0.
    """
    R, r = _check_geometry(R, r)
    points = (v.as_float(name, w) for name, w in zip("XYZ", (X, Y, Z), strict=True))
    with np.errstate(all="ignore"):  # overflow is reported by value
        D, *gradient = _distance(*points, R, r)
    reason = "points and radii (or points on the axis X = Z = 0)"
    return v.finite_result(D, "the distance", reason), tuple(v.finite_result(g, "the normal", reason) for g in gradient)


def smallest_patch_angle(R, r):
    """Angle 2 arcsin(r/R) (rad) below which the two contact points reach the sides of the tubes.

    Below theta_min (:func:`minimum_contact_angle`) the tori touch at two points on the
    flanks of the tubes (:func:`contact_patches`); as theta falls they move round the tubes
    and reach the sides, where the common normal is perpendicular to the chain axis, at
    R sin(theta/2) = r (:func:`patch_geometry`).
    """
    R, r = _check_geometry(R, r)
    return 2 * np.arcsin(r / R)


def torus_gap(x, y, R, r, angle):
    """Exact gap along the chain axis between two interlocked tori at centre distance 2(R - r).

    Parameters
    ----------
    x, y : array_like
        Position in the plane normal to the chain axis, m, from the axis; x lies in ring 1's
        plane, ring 2's plane is turned by ``angle`` from it.
    R, r : array_like
        Major and tube radius of both tori, m (R > 2 r).
    angle : array_like
        Contact angle theta between the ring planes, rad, in (0, pi/2].

    Returns
    -------
    ndarray
        g(x, y) in m (:func:`surface_gap`): the distance along the chain axis from ring 2's
        tube up to ring 1's; negative where the undeformed tori overlap.  Its quadratic part is
        A x'^2 + B y'^2 of App. A, Eq. (A1).

    Raises
    ------
    ValueError
        If a point does not lie over both tubes (|y| or the corresponding offset of ring 2
        exceeds r, or a point is past the inner equator's circle).
    """
    R, r = _check_geometry(R, r)
    angle = v.in_range("angle", angle, 0.0, np.pi / 2)
    x, y = v.as_float("x", x), v.as_float("y", y)
    with np.errstate(all="ignore"):
        g = np.asarray(_gap(x, y, R, r, angle), dtype=float)
    if np.any(np.isnan(g)):
        if R.max() > _SQUARE_LIMIT:  # R^2 overflows: the gap is lost to rounding, whatever the point
            v.finite_result(g, "the gap", "radii")
        raise ValueError("x, y must lie over both tubes (|offset across each tube| < r); some points do not")
    return v.finite_result(g, "the gap", "positions and radii")


def contact_patches(R, r, angle):
    """Where the undeformed tori first touch: distance from the axis, overlap and tilt.

    Parameters
    ----------
    R, r : array_like
        Major and tube radius, m (R > 2 r).
    angle : array_like
        Contact angle theta between the ring planes, rad, in (2 arcsin(r/R), pi/2]
        (:func:`smallest_patch_angle`).

    Returns
    -------
    c : ndarray
        Distance of each contact point from the chain axis, m, along the bisector of the ring
        planes: 0 at and above theta_min (one contact), positive below it (two contacts at
        +-c).
    gap : ndarray
        :func:`torus_gap` at those points, m: 0 above theta_min; negative below it, where the
        tori at centre distance 2(R - r) overlap and first touch at 2(R - r) + gap.
    tilt : ndarray
        Angle between the common normal at the contact points and the chain axis, rad.

    Notes
    -----
    :func:`patch_geometry`; theta_min = arccos(1 - 2r/R) (:func:`minimum_contact_angle`).
    """
    R, r = _check_geometry(R, r)
    angle = v.in_range("angle", angle, 0.0, np.pi / 2)
    lowest = smallest_patch_angle(R, r)
    if np.any(angle <= lowest):
        raise ValueError(
            f"angle must exceed 2 arcsin(r/R) = {np.degrees(np.max(lowest)):.4g} deg, where the contact points reach "
            f"the sides of the tubes (got {np.degrees(np.min(angle)):.4g} deg)"
        )
    R, r, angle = np.broadcast_arrays(R, r, angle)
    two = angle < np.arccos(1 - 2 * r / R)
    c, gap, tilt = (np.zeros(angle.shape) for _ in range(3))
    if np.any(two):
        c[two], gap[two], tilt[two] = _patches(R[two], r[two], angle[two])
    return c, gap, tilt
