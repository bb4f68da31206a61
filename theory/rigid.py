r"""Rigid tori in space: their moments of inertia, and the Hertz stiffness of two surfaces at any contact.

The derivation, step by step (each step a function returning SymPy objects):

1. :func:`moments_of_inertia` -- a solid torus of mass m, uniform density, centre circle of radius R in the
   xy plane, tube radius r: integrate x^2 + y^2 (the axis) and y^2 + z^2 (a diameter) over its volume in
   tube coordinates (rho, psi, phi), point ((R + rho cos psi) cos phi, (R + rho cos psi) sin phi,
   rho sin psi), volume element rho (R + rho cos psi).  The volume is 2 pi^2 R r^2 (Pappus); the moments
   come out as m (R^2 + 3 r^2/4) about the axis and m (R^2/2 + 5 r^2/8) about a diameter (the tests compare
   with these known forms).
2. :func:`relative_curvature_matrix` -- the gap between two surfaces touching at a point, to second order:
   surface 1 has principal curvatures (k1a, k1b) along its axes (x, y), surface 2 (k2a, k2b) along axes
   turned by alpha; convex curvatures positive.  The gap is h = x^T H x with H = (K1 + Q K2 Q^T)/2, Q the
   rotation by alpha: Hertz's A and B are the eigenvalues of H.
3. :func:`curvature_sums_general` -- A + B = trace H and |B - A| = sqrt(trace^2 - 4 det H), reduced to the
   sum of squares (1/2) sqrt(g1^2 + g2^2 + 2 g1 g2 cos 2 alpha), g_i = k_ia - k_ib: the sums of App. A,
   Eqs. (A2a)-(A2b), here derived from the gap instead of quoted (the tests check that for two tori at their
   crossing they are :func:`ringchain.theory.contact.curvature_sums_pair`).
4. The stiffness: K_c = K_c(0, A) Gamma, with K_c(0, A) = 4/3 E* (2A)^(-1/2) the circular contact of
   curvature A (:func:`ringchain.theory.contact.circular_limit`) and Gamma the elliptical factor of the shape
   B/A (:func:`ringchain.theory.contact.elliptical_factor`, Johnson Sec. 4.2).
5. Numbers for an inner loop: :func:`elliptical_factor_grid` solves the shape equation once for Gamma at
   s = ln(1 + ln(B/A)) = j h, h = 1/256, j = 0 .. 1674 (ln(B/A) up to 690, as the table of
   :mod:`.contact`), by bisection on ln(1 - m) in the Carlson form of Johnson's equations
   (:func:`ringchain.theory.contact.carlson_form`).  Between the nodes Gamma is the cubic through the four
   nearest values: the error is about h^4 |Gamma''''|/24 < 1e-12 (the tests measure it against
   :func:`ringchain.theory.hertz_stiffness`, whose table is accurate to 1e-15).  The compiled kernels
   (:func:`ringchain.numerics.engine.rings_law.hertz_stiffness_curvatures`) take the same grid.

The curvatures at a contact of two tori in any pose (across a tube 1/r; along it cos(phi)/(R + r cos(phi)),
phi the angle round the tube from the outer equator, -1/(R - r) on the inner one) come from
:func:`ringchain.numerics.torus_contacts`.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from ._codegen import derived, sp
from .contact import effective_modulus_pair, pair_symbols, symbols
from .elliptical import TABLE_MAX_LOG_RATIO, carlson_form, circular_limit, ellipse_shape_ratio, elliptical_factor

__all__ = [
    "torus_symbols",
    "moments_of_inertia",
    "curvature_symbols",
    "relative_curvature_matrix",
    "curvature_sums_general",
    "torus_moments",
    "contact_modulus_pair",
    "hertz_stiffness_curvatures",
    "elliptical_factor_grid",
    "ELLIPTICAL_GRID_STEP",
]

#: Spacing h of :func:`elliptical_factor_grid` in s = ln(1 + ln(B/A)).
ELLIPTICAL_GRID_STEP = 1.0 / 256.0

#: Largest ln(B/A) of the grid (an ellipse with b/a about 1e-151): where the table of :mod:`.elliptical` stops.
_GRID_MAX_LOG_RATIO = TABLE_MAX_LOG_RATIO


@functools.cache
def torus_symbols():
    """Symbols of the torus: R, r, m (positive), tube coordinates rho, psi, phi."""
    R, r, m = sp.symbols("R r m", positive=True)
    rho = sp.Symbol("rho", nonnegative=True)
    psi, phi = sp.symbols("psi phi", real=True)
    return dict(R=R, r=r, m=m, rho=rho, psi=psi, phi=phi)


# --- 1. moments of inertia ------------------------------------------------------------------------------------
def moments_of_inertia():
    """(I_diameter, I_axis) of a solid torus of mass m, integrated over its volume (step 1 of the module notes)."""
    t = torus_symbols()
    R, r, m, rho, psi, phi = (t[k] for k in ("R", "r", "m", "rho", "psi", "phi"))
    reach = R + rho * sp.cos(psi)  # distance from the axis
    x, y, z = reach * sp.cos(phi), reach * sp.sin(phi), rho * sp.sin(psi)
    determinant = sp.simplify(sp.Matrix([x, y, z]).jacobian([rho, psi, phi]).det())
    volume_element = rho * reach  # |determinant|: positive for rho < r < R
    if sp.simplify(determinant**2 - volume_element**2) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the volume element of the tube coordinates is not rho (R + rho cos psi)")

    def integral(f):
        inner = sp.integrate(sp.expand(f * volume_element), (phi, 0, 2 * sp.pi))
        middle = sp.integrate(sp.expand(inner), (psi, 0, 2 * sp.pi))
        return sp.factor(sp.integrate(sp.expand(middle), (rho, 0, r)))

    volume = integral(sp.Integer(1))
    if sp.simplify(volume - 2 * sp.pi**2 * R * r**2) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the volume of the torus is not Pappus's 2 pi^2 R r^2")
    density = m / volume
    I_axis = sp.factor(sp.simplify(density * integral(x**2 + y**2)))
    I_diameter = sp.factor(sp.simplify(density * integral(y**2 + z**2)))
    return I_diameter, I_axis


# --- 2.-3. the curvature sums of two surfaces -----------------------------------------------------------------
@functools.cache
def curvature_symbols():
    """Symbols of two surfaces at a contact: principal curvatures k1a, k1b, k2a, k2b (real, 1/m), the angle alpha
    between the first principal directions, and the position (x, y) in the tangent plane."""
    k1a, k1b, k2a, k2b = sp.symbols("k_1a k_1b k_2a k_2b", real=True)
    alpha = sp.Symbol("alpha", real=True)
    x, y = sp.symbols("x y", real=True)
    return dict(k1a=k1a, k1b=k1b, k2a=k2a, k2b=k2b, alpha=alpha, x=x, y=y)


def relative_curvature_matrix():
    """H with gap h = x^T H x = (z1 - z2 of the two surfaces) to second order (step 2 of the module notes).

    Surface 1, z1 = (k1a x^2 + k1b y^2)/2 in its principal axes; surface 2, below it, z2 = -(k2a x'^2 + k2b y'^2)/2
    in axes (x', y') turned by alpha.  Returns H (2 x 2, symmetric).
    """
    c = curvature_symbols()
    x, y, alpha = c["x"], c["y"], c["alpha"]
    turn = sp.Matrix([[sp.cos(alpha), -sp.sin(alpha)], [sp.sin(alpha), sp.cos(alpha)]])
    xp, yp = turn.T * sp.Matrix([x, y])  # coordinates in surface 2's principal axes
    z1 = (c["k1a"] * x**2 + c["k1b"] * y**2) / 2
    z2 = -(c["k2a"] * xp**2 + c["k2b"] * yp**2) / 2
    gap = sp.expand(z1 - z2)
    H = sp.hessian(gap, (x, y)) / 2
    if sp.simplify(sp.expand((sp.Matrix([[x, y]]) * H * sp.Matrix([x, y]))[0] - gap)) != 0:  # pragma: no cover
        raise RuntimeError("the gap is not quadratic in the tangent plane")
    return sp.simplify(H)


def curvature_sums_general():
    """(A + B, |B - A|) of two surfaces: the trace of H and the difference of its eigenvalues (step 3).

    |B - A| = sqrt(trace^2 - 4 det) is returned as (1/2) sqrt(g1^2 + g2^2 + 2 g1 g2 cos 2 alpha),
    g_i = k_ia - k_ib, a form that is exact in floating point for equal rings at 90 degrees (checked equal).
    """
    c = curvature_symbols()
    H = relative_curvature_matrix()
    total = sp.simplify(H.trace())
    squared = sp.expand(sp.expand_trig(total**2 - 4 * H.det()))
    g1, g2 = c["k1a"] - c["k1b"], c["k2a"] - c["k2b"]
    sum_of_squares = (g1**2 + g2**2 + 2 * g1 * g2 * sp.cos(2 * c["alpha"])) / 4
    if sp.simplify(sp.expand(sp.expand_trig(sum_of_squares)) - squared) != 0:  # pragma: no cover
        raise RuntimeError("the eigenvalue difference is not Hertz's sum of squares")
    return total, sp.sqrt(sum_of_squares)


# --- 4.-5. numbers --------------------------------------------------------------------------------------------
@derived
def _moments():
    t = torus_symbols()
    return (t["R"], t["r"], t["m"]), moments_of_inertia()


@derived
def _modulus_pair():
    p = pair_symbols()
    return (p["E1"], p["nu1"], p["E2"], p["nu2"]), effective_modulus_pair()


@derived
def _circular_stiffness():
    """K_c(0, A)/E*: the circular contact of relative curvature A per unit effective modulus."""
    s = symbols()
    K_c, Es = circular_limit()
    return (s["A"],), sp.simplify(K_c / Es)


def _lambdify_floats(args, exprs):
    """A float evaluator of SymPy expressions that may call SciPy's Carlson integrals (derivation time only)."""
    import scipy.special

    return sp.lambdify(args, exprs, modules=[{"scipy": scipy}, "numpy"])


def _grid_values():
    """Gamma at s_j = j h (step 5 of the module notes), solved by bisection on ln(1 - m)."""
    m_1 = symbols()["m_1"]
    evaluate = _lambdify_floats(
        (m_1,), (sp.log(carlson_form(ellipse_shape_ratio())), carlson_form(elliptical_factor()))
    )
    count = int(np.ceil(np.log1p(_GRID_MAX_LOG_RATIO) / ELLIPTICAL_GRID_STEP)) + 1
    target = np.expm1(np.arange(count) * ELLIPTICAL_GRID_STEP)  # ln(B/A) at the nodes
    lo = np.full(count, np.log(np.finfo(float).tiny))  # ln(m_1): B/A -> infinity
    hi = np.zeros(count)  # m_1 = 1: the circle
    with np.errstate(divide="ignore", invalid="ignore"):
        for _ in range(90):  # 708/2^90: far below the spacing of doubles near ln(m_1)
            middle = 0.5 * (lo + hi)
            above = evaluate(np.exp(middle))[0] > target
            lo, hi = np.where(above, middle, lo), np.where(above, hi, middle)
        gamma = evaluate(np.exp(0.5 * (lo + hi)))[1]
    gamma[0] = 1.0  # the circle (B = A) exactly
    if not (np.all(np.isfinite(gamma)) and np.all(np.diff(gamma) < 0)):  # pragma: no cover - derivation check
        raise RuntimeError("the elliptical factor is not finite and decreasing along the grid")
    return gamma


@derived
def _elliptical_grid():
    values = _grid_values()
    exact = [sp.Float(float(value), 17) for value in values]  # 17 digits: every double round-trips
    return (), sp.ImmutableDenseMatrix(1, len(exact), exact)


@functools.cache
def _grid() -> np.ndarray:
    grid = np.asarray(_elliptical_grid(), dtype=float).ravel()
    grid.setflags(write=False)
    return grid


def elliptical_factor_grid():
    """Gamma = K_c/K_c(0, A) of the elliptical Hertz contact on the grid s_j = j h of s = ln(1 + ln(B/A)).

    Returns
    -------
    values : ndarray (1675,)
        Gamma at the nodes (read-only); Gamma(0) = 1 (the circle), decreasing.
    step : float
        h = :data:`ELLIPTICAL_GRID_STEP` = 1/256.

    Notes
    -----
    Step 5 of the module notes: the shape equation of Johnson's elliptical solution (Contact Mechanics,
    Sec. 4.2) solved at every node; what :func:`ringchain.numerics.engine.rings_law.hertz_stiffness_curvatures`
    interpolates (cubic through four nodes, error below 1e-12).

    Examples
    --------
    >>> values, step = elliptical_factor_grid()
    >>> float(values[0]), step
    (1.0, 0.00390625)
    """
    return _grid(), ELLIPTICAL_GRID_STEP


def _factor_at(s):
    """The cubic through the four nodes nearest s (clamped to the grid), as the compiled kernel evaluates it."""
    values = _grid()
    n = values.size
    x = np.asarray(s, dtype=float) / ELLIPTICAL_GRID_STEP
    j = np.clip(x.astype(np.intp), 1, n - 3)
    t = x - j
    a, b, c, d = (values[j + k] for k in (-1, 0, 1, 2))
    cubic = (
        -a * t * (t - 1) * (t - 2) / 6
        + b * (t + 1) * (t - 1) * (t - 2) / 2
        - c * (t + 1) * t * (t - 2) / 2
        + d * (t + 1) * t * (t - 1) / 6
    )
    return np.where(x >= n - 1, values[-1], cubic)


def torus_moments(R, r, *, m):
    """Principal moments of inertia of a solid torus (uniform density) about its centre.

    Parameters
    ----------
    R : array_like
        Radius of the centre circle, m.
    r : array_like
        Tube radius, m; 0 < r < R.
    m : array_like
        Mass, kg, > 0 (keyword-only, as every chain parameter of the package).

    Returns
    -------
    I_diameter, I_axis : ndarray
        Moments about a diameter and about the axis (normal to the ring's plane), kg m^2:
        m (R^2/2 + 5 r^2/8) and m (R^2 + 3 r^2/4).

    Notes
    -----
    Integrated over the torus's volume in SymPy (:func:`moments_of_inertia`); beyond the paper, for the rigid
    rings of :mod:`ringchain.numerics`.  A thin ring (r -> 0) has m R^2/2 and m R^2.

    Examples
    --------
    >>> I_d, I_a = torus_moments(0.02, 0.0025, m=0.01)
    >>> float(I_d), float(I_a)  # kg m^2
    (2.0390625e-06, 4.046875e-06)
    """
    R = v.positive("R", R, "m")
    r = v.positive("r", r, "m")
    m = v.positive("m", m, "kg")
    v.broadcast_shape(R=R, r=r, m=m)
    if not np.all(r < R):
        raise ValueError(f"r must be smaller than R (a torus with a hole), in m; got r/R = {v.show(np.max(r / R))}")
    with np.errstate(all="ignore"):
        I_diameter, I_axis = (np.asarray(x, dtype=float) for x in _moments(R, r, m))
    reason = "radii and mass"
    return (v.finite_result(I_diameter, "I_diameter", reason), v.finite_result(I_axis, "I_axis", reason))


def contact_modulus_pair(E1, nu1, E2, nu2):
    """Effective modulus E* of two bodies of different materials, Pa: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.

    Parameters
    ----------
    E1, E2 : array_like
        Young's moduli, Pa.
    nu1, nu2 : array_like
        Poisson's ratios, in (-1, 0.5).

    Returns
    -------
    ndarray
        E*, Pa (App. A; :func:`ringchain.theory.contact.effective_modulus_pair`); for equal materials
        :func:`ringchain.theory.contact_modulus`.

    Examples
    --------
    >>> round(float(contact_modulus_pair(193e9, 0.29, 193e9, 0.29)) / 1e9, 2)  # GPa
    105.36
    """
    E1, nu1, E2, nu2 = _check_materials(E1, nu1, E2, nu2)
    with np.errstate(all="ignore"):
        modulus = np.asarray(_modulus_pair(E1, nu1, E2, nu2), dtype=float)
    return v.finite_result(modulus, "E*", "elastic constants")


def _check_materials(E1, nu1, E2, nu2):
    E1, E2 = v.positive("E1", E1, "Pa"), v.positive("E2", E2, "Pa")
    nu1 = v.in_range("nu1", nu1, -1.0, 0.5, closed_high=False)
    nu2 = v.in_range("nu2", nu2, -1.0, 0.5, closed_high=False)
    v.broadcast_shape(E1=E1, nu1=nu1, E2=E2, nu2=nu2)
    return E1, nu1, E2, nu2


def hertz_stiffness_curvatures(k1_a, k1_b, k2_a, k2_b, angle, E1, nu1, E2, nu2):
    """Hertz contact stiffness K_c of two surfaces from their principal curvatures, F = K_c delta^(3/2).

    Parameters
    ----------
    k1_a, k1_b : array_like
        Principal curvatures of surface 1 at the contact, 1/m, convex positive (a tube: 1/r across it; along it
        cos(phi)/(R + r cos(phi)), -1/(R - r) on the inner equator).
    k2_a, k2_b : array_like
        The same for surface 2.
    angle : array_like
        Angle between the directions of k1_a and k2_a, rad (any real: only cos(2 angle) enters).
    E1, nu1, E2, nu2 : array_like
        Young's moduli (Pa) and Poisson's ratios (in (-1, 0.5)) of the two bodies.

    Returns
    -------
    ndarray
        K_c in N/m^1.5.

    Notes
    -----
    App. A of the paper, Eqs. (A2a)-(A2b), for any two surfaces (:func:`curvature_sums_general`), with the
    elliptical Hertz solution: K_c = 4/3 E* (2A)^(-1/2) Gamma(B/A) (:func:`ringchain.theory.contact.circular_limit`,
    Gamma from :func:`elliptical_factor_grid`).  At the crossing of two interlocked tori (k_a = -1/(R - r),
    k_b = 1/r for both, angle = the contact angle) it is :func:`ringchain.theory.hertz_stiffness` (Eq. (1) at
    90 degrees) and :func:`ringchain.theory.hertz_stiffness_pair`, to 1e-12.  Raises ``ValueError`` where
    A <= 0: the surfaces do not close to a point contact (a line, or two patches).

    Examples
    --------
    >>> R, r = 22.5e-3, 2.5e-3
    >>> K_c = hertz_stiffness_curvatures(-1 / (R - r), 1 / r, -1 / (R - r), 1 / r, np.pi / 2, 193e9, 0.29, 193e9, 0.29)
    >>> round(float(K_c) / 1e9, 3)  # GN/m^1.5, Eq. (1)
    7.509
    """
    k1_a, k1_b, k2_a, k2_b = (
        v.as_float(n, x) for n, x in zip(("k1_a", "k1_b", "k2_a", "k2_b"), (k1_a, k1_b, k2_a, k2_b), strict=True)
    )
    angle = v.as_float("angle", angle)
    E1, nu1, E2, nu2 = _check_materials(E1, nu1, E2, nu2)
    v.broadcast_shape(k1_a=k1_a, k1_b=k1_b, k2_a=k2_a, k2_b=k2_b, angle=angle, E1=E1, nu1=nu1, E2=E2, nu2=nu2)
    with np.errstate(all="ignore"):
        total = 0.5 * (k1_a + k1_b + k2_a + k2_b)
        g1, g2 = k1_a - k1_b, k2_a - k2_b
        difference = 0.5 * np.sqrt(np.maximum(g1 * g1 + g2 * g2 + 2 * g1 * g2 * np.cos(2 * angle), 0.0))
        A = 0.5 * (total - difference)
    if not np.all(A > 0):
        raise ValueError(
            "the relative curvature A of the two surfaces must be positive (1/m): where A <= 0 the surfaces touch "
            f"along a line or at two patches and no single Hertz ellipse exists (smallest A: {v.show(np.min(A))} 1/m)"
        )
    with np.errstate(all="ignore"):
        s = np.log1p(np.log1p(difference / A))
    if not np.all(s <= np.log1p(_GRID_MAX_LOG_RATIO)):
        raise ValueError(f"the contact ellipse is too elongated to represent (ln(B/A) > {_GRID_MAX_LOG_RATIO:g})")
    E_star = contact_modulus_pair(E1, nu1, E2, nu2)
    with np.errstate(all="ignore"):
        K_c = np.asarray(_circular_stiffness(A), dtype=float) * E_star * _factor_at(s)
    return v.finite_result(K_c, "K_c", "curvatures and elastic constants")
