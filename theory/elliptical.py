r"""Hertz's elliptical contact of two bodies of relative curvatures A <= B, and the tables that invert it.

Johnson (Contact Mechanics, Sec. 4.2, Eqs. 4.39-4.41) solves the contact of any two bodies whose
gap is quadratic with principal relative curvatures A <= B; :mod:`.contact` supplies the A and B
of two tori (App. A of the paper, Eqs. (A2a)-(A2b)) and its numeric functions evaluate what is
derived here.  Step by step (each step a function returning SymPy objects):

1. :func:`hertz_elliptical_monomial`, :func:`hertz_elliptical` -- the load
   P = 2/3 pi a b p0, the approach delta = p0 b K(m)/E* and the curvature
   A = p0 b (K(m) - E(m))/(E* a^2 m), with the complete elliptic integrals K(m), E(m) of the
   ellipse's eccentricity e^2 = m (kept as the placeholders of :func:`elliptic_placeholders`
   while eliminating), give P = K_c(m, A) delta^(3/2); :func:`hertz_semi_axes` solves the same
   relations for the semi-axes a >= b under a load.
2. :func:`ellipse_shape_ratio` -- the shape equation B/A = (E/(1 - m) - K)/(K - E);
   :func:`circular_limit` is K_c as m -> 0 (Hertz's sphere, paper Eq. (1) and Eq. (A3) by a
   second route), and :func:`elliptical_factor` the ratio Gamma(m) = K_c(m, A)/K_c(0, A), a
   function of the shape alone.
3. Numbers.  Carlson's forms (:mod:`.special`, :func:`carlson_form`), K(m) = R_F(0, 1-m, 1) and
   (K - E)/m = R_D(0, 1-m, 1)/3, keep the circular limit m -> 0 exact in floating point, and
   with the complementary parameter m_1 = 1 - m as the variable they stay exact as m -> 1 too.
   The shape equation has no closed-form inverse, and evaluating R_F and R_D is slow (R_D costs
   as much as a few hundred NumPy operations per point), so the numeric code does not solve it
   point by point.  Gamma and m are smooth functions of s = ln(1 + ln(B/A)) (s = 0 for the
   circle; s -> infinity as the tori's angle approaches theta_min); :func:`elliptical_table`
   solves the shape equation once, at the Chebyshev points of short intervals of s, and stores
   the interpolating polynomials (accurate to a few units of 1e-16; the derivation checks the
   error at the midpoints).  The table is generated code like every derivation, so the disk
   cache of :mod:`._codegen` keeps it between processes; :func:`from_table` evaluates it: a
   table look-up and a polynomial per point.
"""

from __future__ import annotations

import functools

import numpy as np

from ._codegen import derived, sp
from .special import carlson_rd, carlson_rf

__all__ = [
    "symbols",
    "elliptic_placeholders",
    "hertz_elliptical_monomial",
    "hertz_elliptical",
    "hertz_semi_axes",
    "ellipse_shape_ratio",
    "circular_limit",
    "elliptical_factor",
    "carlson_form",
    "elliptical_table",
    "from_table",
    "TABLE_MAX_LOG_RATIO",
    "TABLE_MAX_EXCESS",
]


@functools.cache
def symbols():
    """Symbols of the contact ellipse: m, curvatures A <= B, load P and approach delta, semi-axes, p0, m_1."""
    m = sp.Symbol("m", nonnegative=True)  # squared eccentricity of the contact ellipse
    A, B = sp.symbols("A B", positive=True)  # relative curvatures, A <= B
    P, delta = sp.symbols("P delta", positive=True)  # load and normal approach
    a, b, p0 = sp.symbols("a b p_0", positive=True)  # semi-axes (a >= b) and peak pressure
    m_1 = sp.Symbol("m_1", positive=True)  # complementary parameter 1 - m = (b/a)^2
    return dict(m=m, A=A, B=B, P=P, delta=delta, a=a, b=b, p0=p0, m_1=m_1)


# --- 1.-2. Johnson's elliptical solution ------------------------------------------------


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


def circular_limit():
    """K_c(A, E*) of the circular contact: :func:`hertz_elliptical` as m -> 0 (R' = R'' = 1/(2A)).

    A second route to step 4 of :mod:`.contact`: with A = 1/(2 R_e) it is 4/3 E* sqrt(R_e) (the tests check
    it against :func:`.contact.hertz_circular` and the paper's Eq. (1)).  Returns (K_c, E*).
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


# --- 3. Carlson forms and the table ---------------------------------------------------


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
_TABLE_STEP = 0.025
_TABLE_DEGREE = 5
#: The largest ln(B/A) the table covers (an ellipse with b/a about 1e-151).
TABLE_MAX_LOG_RATIO = 690.0
#: The largest B/A - 1 the table covers.
TABLE_MAX_EXCESS = float(np.expm1(TABLE_MAX_LOG_RATIO))


def _table_intervals():
    top = float(np.log1p(TABLE_MAX_LOG_RATIO))
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


def from_table(which: int, s, overwrite=False):
    """Gamma (which = 0) or m/ln(B/A) (which = 1) at s = ln(1 + ln(B/A)), from :func:`elliptical_table`.

    Parameters
    ----------
    which : {0, 1}
        0: the elliptical factor Gamma (:func:`elliptical_factor`); 1: m/ln(B/A), m the squared
        eccentricity that solves the shape equation (:func:`ellipse_shape_ratio`).
    s : ndarray or float
        ln(1 + ln(B/A)) of the relative curvatures (dimensionless), 0 <= s < ln(1 + TABLE_MAX_LOG_RATIO);
        not checked (the callers in :mod:`.contact` check B/A).
    overwrite : bool, optional
        Let the evaluation use the memory of the array ``s``.

    Returns
    -------
    ndarray or float
        The value, by Horner's scheme in t on the interval of each point, in place (few
        temporaries: on 10^5 points a fresh array costs as much as the arithmetic).
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
