r"""Stresses below the Hertz contact of two tori, and the load at which the contact first yields.

Beyond the paper, which treats the contact as elastic (Eq. (1), App. A).  The half-space
z >= 0 (z into the body) carries the Hertz pressure p0 sqrt(1 - x^2/a^2 - y^2/b^2) on the
contact ellipse, semi-axes a >= b (a along the direction of the smaller relative
curvature A; a circle of radius a when the rings are perpendicular).  Step by step:

1. :func:`boussinesq_coefficients` -- a point load P at the origin.  Displacements of Love's
   form (Johnson 1985, Contact Mechanics, Sec. 3.2) built from H = P ln(rho + z),
   rho = |x|, and psi = dH/dz = P/rho::

       4 pi G u_x = alpha H_x + beta z psi_x,   4 pi G u_y = alpha H_y + beta z psi_y,
       4 pi G u_z = gamma psi + delta z psi_z,

   with four unknown numbers.  Navier's equations, the traction-free surface away from the
   load and the resultant P fix them: alpha = -(1 - 2 nu), beta = -1, gamma = 2 (1 - nu),
   delta = -1, Boussinesq's solution (Johnson Eq. (3.20)).
2. :func:`love_stresses` -- the operator of step 1 is linear and commutes with superposition
   over the loaded area, so H1 = integral of p ln(rho + z) dA gives the field of any normal
   pressure p.  Hooke's law gives the stresses in derivatives of H1; H1 is harmonic, which
   removes every second and higher z-derivative.  On the z axis of a pressure even in x and
   y the normal stresses need only H_xx, H_yy, psi_xx, psi_yy (psi = dH1/dz) and the shear
   stresses vanish, so sigma_x, sigma_y, sigma_z are the principal stresses there.
3. :func:`ellipsoidal_potential` -- for the Hertz pressure, psi = integral of p/rho dA is
   (pi a b p0/2) int_lambda^oo [1 - x^2/(a^2 + w) - y^2/(b^2 + w) - z^2/w] dw/sqrt((a^2 + w)(b^2 + w) w),
   lambda the positive root of x^2/(a^2 + lambda) + y^2/(b^2 + lambda) + z^2/lambda = 1
   (the potential of a flattened ellipsoid; Johnson Sec. 3.6, after Dyson and Ferrers).  It
   is stated, not derived; the tests check what makes it the potential of p: it is
   harmonic, it tends to P/rho far away, and -dpsi/dz = 2 pi p on the contact.
4. :func:`axis_integrals` -- on the axis (x = y = 0, lambda = z^2) Leibniz' rule gives
   psi_xx = int_{z^2}^oo f_xx dw (the boundary terms vanish there, checked), and
   H_xx = -int_z^oo psi_xx(z') dz' = -int_{z^2}^oo f_xx(w) (sqrt(w) - z) dw (order of
   integration swapped).  Likewise in y.
5. :func:`axis_stresses_circular` -- a = b: the integrals are elementary.  SymPy returns
   Johnson's Eq. (3.45), sigma_z = -p0/(1 + zeta^2) and
   sigma_r = p0 [-(1 + nu)(1 - zeta arctan(1/zeta)) + 1/(2 (1 + zeta^2))], zeta = z/a
   (the tests compare).
6. :func:`carlson_form`, :func:`axis_stresses_elliptical` -- a > b: each integral is
   Carlson's R_D (three factors, DLMF 19.16.5, after the shift w = z^2 + t) or elementary
   (two factors).  Exact, vectorised through SciPy's ``elliprd``, and well behaved as
   b/a -> 0 (no quadrature; the method of Thomas and Hoersch 1930 in Carlson's notation).
   The depth derivatives come from Leibniz' rule on the same integrals.
7. Von Mises: sigma_vm = sqrt(((sx - sy)^2 + (sy - sz)^2 + (sz - sx)^2)/2) on the axis; for
   the circle |sigma_r - sigma_z|.  Its largest value along the axis is found numerically
   (a scan in depth, then bisection on the closed-form derivative): first yield at
   p0 = Y/max(sigma_vm/p0).  For nu = 0.29 that is p0 = 1.601 Y at z = 0.478 a on the axis of
   the circular contact (Johnson Sec. 4.2(b): 1.60 Y at 0.48 a for nu = 0.3).
8. :func:`yield_relations` -- Johnson's elliptical Hertz relations (Sec. 4.2, as in
   :mod:`.contact`) at that pressure: b = a sqrt(1 - m), A = p0 b D(m)/(E* a^2) with
   D(m) = (K(m) - E(m))/m, P = 2/3 pi a b p0, delta = p0 b K(m)/E*.  Eliminating a and b gives
   F_y = 2/3 pi (1 - m)^(3/2) D(m)^2 p0^3/(A^2 E*^2); for the circle (m = 0, D = pi/4,
   A = 1/(2 R')) F_y = pi^3 R'^2 p0^3/(6 E*^2).

The maximum of von Mises stress on the axis is the maximum in the body for the Hertz
contact of metals (Johnson Sec. 3.4, 4.2; Thomas and Hoersch): the tests check it against
a search off the axis for nu = 0.29 at 90 and 60 degrees.

Signatures follow the package's convention (:mod:`ringchain.theory`): the geometry and material of the
contact R, r, E, nu, angle by position, as for :func:`~ringchain.theory.hertz_stiffness`, and the yield
strength Y keyword-only after them (Y and E are both positive pressures; with Y between nu and angle, as
it was, a copied ``hertz_stiffness(R, r, E, nu, angle)`` passed the angle as Y).  :func:`subsurface_stress`
is evaluated at the depth z (first) and takes the force F keyword-only, as
:func:`~ringchain.theory.contact_semi_axes` does.  The load and the semi-axes at a pressure are evaluated
through their logarithms (``_log_load_at_pressure``): A^2 E^2 leaves the doubles for tori far smaller
than any ring where the load does not.

Numeric functions: :func:`subsurface_stress`, :func:`first_yield` (:class:`FirstYield`),
:func:`yield_force`.
"""

from __future__ import annotations

import functools
from typing import NamedTuple

import numpy as np

from . import _validate as v
from ._codegen import derived, sp
from .contact import (
    contact_ellipse,
    contact_modulus,
    effective_modulus,
    hertz_stiffness,
)
from .contact import symbols as contact_symbols
from .elliptical import elliptic_placeholders
from .special import carlson_rd, carlson_rf

__all__ = [
    "symbols",
    "boussinesq_coefficients",
    "love_stresses",
    "ellipsoidal_potential",
    "axis_integrals",
    "axis_stresses_circular",
    "carlson_form",
    "axis_stresses_elliptical",
    "yield_relations",
    "FirstYield",
    "subsurface_stress",
    "first_yield",
    "yield_force",
]


@functools.cache
def symbols():
    """Symbols: position x, y (real), depth z > 0, the ellipsoidal variable w, semi-axes a, b, peak
    pressure p0, Poisson's ratio nu, shear modulus G, point load P, distance rho, the potential H(x, y, z),
    the relative depth zeta = z/b and m_1 = 1 - m = (b/a)^2."""
    x, y = sp.symbols("x y", real=True)
    z, w, a, b, p0, G, P, rho = sp.symbols("z w a b p_0 G P rho", positive=True)
    nu = sp.Symbol("nu", real=True)
    zeta, m_1 = sp.symbols("zeta m_1", positive=True)
    H = sp.Function("H")(x, y, z)
    return dict(x=x, y=y, z=z, w=w, a=a, b=b, p0=p0, G=G, P=P, rho=rho, nu=nu, H=H, zeta=zeta, m_1=m_1)


# --- 1. the point load ----------------------------------------------------------------------------


def _d(expr, variable):
    """d/d(variable) of an expression in x, y, z and the symbol rho = sqrt(x^2 + y^2 + z^2)."""
    s = symbols()
    return sp.diff(expr, variable) + sp.diff(expr, s["rho"]) * variable / s["rho"]


#: Points (x, y, z, rho) with rho = sqrt(x^2 + y^2 + z^2) rational, where identities in x, y, z, rho
#: are evaluated exactly: two give the equations, the other three check the solution.
_POINTS = ((1, 2, 2, 3), (2, 3, 6, 7), (1, 4, 8, 9), (2, 6, 9, 11), (4, 4, 7, 9))


def _ansatz_field(coefficients):
    """(u, stresses) of the point-load ansatz of step 1 in x, y, z, rho (H = ln(rho + z), P = 1)."""
    s = symbols()
    x, y, z, rho, G, nu = (s[k] for k in ("x", "y", "z", "rho", "G", "nu"))
    alpha, beta, gamma, delta = coefficients
    H = sp.log(rho + z)
    psi = _d(H, z)
    c = 1 / (4 * sp.pi * G)
    u = [
        c * (alpha * _d(H, x) + beta * z * _d(psi, x)),
        c * (alpha * _d(H, y) + beta * z * _d(psi, y)),
        c * (gamma * psi + delta * z * _d(psi, z)),
    ]
    u = [sp.cancel(component) for component in u]  # rational in x, y, z, rho: small before differentiating
    X = (x, y, z)
    divergence = sp.cancel(sum(_d(u[i], X[i]) for i in range(3)))
    lame = 2 * G * nu / (1 - 2 * nu)
    stress = [
        [(lame * divergence if i == j else 0) + G * (_d(u[i], X[j]) + _d(u[j], X[i])) for j in range(3)]
        for i in range(3)
    ]
    navier = [G * sum(_d(_d(u[i], q), q) for q in X) + (lame + G) * _d(divergence, X[i]) for i in range(3)]
    return u, stress, navier


def _at(expr, point):
    s = symbols()
    values = {k: sp.Integer(value) for k, value in zip((s["x"], s["y"], s["z"], s["rho"]), point, strict=True)}
    return sp.cancel(expr.xreplace(values))


@functools.cache
def boussinesq_coefficients():
    """(alpha, beta, gamma, delta) of step 1: Boussinesq's point load from Love's form of the displacements.

    Navier's equations at exact points (x, y, z, rho) give two linear conditions; the surface
    tractions sigma_xz, sigma_zz at a point of z = 0 off the load a third; the resultant of
    sigma_zz over a plane z = const equal to -P (compression) the fourth.
    """
    s = symbols()
    unknowns = sp.symbols("alpha beta gamma delta")
    _, stress, navier = _ansatz_field(unknowns)
    equations = [sp.numer(_at(component, point)) for point in _POINTS[:2] for component in navier]
    (solution,) = sp.solve(equations, unknowns[:2], dict=True)
    x, y, z, rho = (s[k] for k in ("x", "y", "z", "rho"))
    surface = {x: 3, y: 4, rho: 5}
    tractions = [sp.simplify(stress[i][2].subs(solution).subs(surface).subs(z, 0)) for i in (0, 2)]
    (more,) = sp.solve([t for t in tractions if t != 0], unknowns[2], dict=True)
    solution = {k: sp.simplify(val.subs(more)) for k, val in solution.items()} | more
    # Resultant over the plane at depth z: sigma_zz is even in x; on y = 0, x^2 = rho^2 - z^2.
    szz = sp.expand(sp.together(stress[2][2].subs(solution).subs(y, 0))).subs(x**2, rho**2 - z**2)
    # Elementary (a rational function of rho): meijerg=False skips the Meijer-G route, which fails first.
    resultant = sp.integrate(sp.simplify(szz) * 2 * sp.pi * rho, (rho, z, sp.oo), meijerg=False)
    (last,) = sp.solve(sp.Eq(resultant, -1), unknowns[3], dict=True)
    coefficients = tuple(sp.simplify(sp.sympify(c).subs(solution).subs(last)) for c in unknowns)
    _, _, navier = _ansatz_field(coefficients)
    for point in _POINTS[2:5]:  # pragma: no branch - derivation check at points not used above
        if any(_at(component, point) != 0 for component in navier):  # pragma: no cover
            raise RuntimeError("the point-load field does not satisfy Navier's equations")
    return coefficients


def point_load_stresses():
    """Boussinesq's stresses of a unit point load (3 x 3 nested lists) in x, y, z, rho = sqrt(x^2 + y^2 + z^2)."""
    _, stress, _ = _ansatz_field(boussinesq_coefficients())
    return [[sp.factor(sp.together(component)) for component in row] for row in stress]


# --- 2. Love's stresses of any normal pressure ------------------------------------------------------


def _harmonic(expr):
    """``expr`` with every derivative of H of z-order >= 2 reduced by Laplace's equation, H_zz = -H_xx - H_yy."""
    s = symbols()
    H, x, y, z = s["H"], s["x"], s["y"], s["z"]

    def counts(d):
        order = dict(d.variable_count)
        return order.get(x, 0), order.get(y, 0), order.get(z, 0)

    def is_reducible(e):
        return isinstance(e, sp.Derivative) and e.expr == H and counts(e)[2] >= 2

    def reduce(d):
        i, j, k = counts(d)
        terms = [((x, i + 2), (y, j), (z, k - 2)), ((x, i), (y, j + 2), (z, k - 2))]
        return -sum(sp.Derivative(H, *[(q, n) for q, n in term if n]) for term in terms)

    while expr.has(sp.Derivative) and any(is_reducible(d) for d in expr.atoms(sp.Derivative)):
        expr = expr.replace(is_reducible, reduce)
    return sp.expand(expr)


@functools.cache
def love_stresses():
    """sigma_ij (3 x 3 nested lists) of the normal pressure whose potential is H(x, y, z), harmonic.

    Step 2: the displacements of step 1 with P ln(rho + z) replaced by H, Hooke's law
    sigma = lambda tr(eps) I + 2 G eps, then :func:`_harmonic`.  G cancels.
    """
    s = symbols()
    H, x, y, z, G, nu = (s[k] for k in ("H", "x", "y", "z", "G", "nu"))
    alpha, beta, gamma, delta = boussinesq_coefficients()
    c = 1 / (4 * sp.pi * G)
    u = [
        c * (alpha * H.diff(x) + beta * z * H.diff(x, z)),
        c * (alpha * H.diff(y) + beta * z * H.diff(y, z)),
        c * (gamma * H.diff(z) + delta * z * H.diff(z, 2)),
    ]
    X = (x, y, z)
    divergence = sum(u[i].diff(X[i]) for i in range(3))
    lame = 2 * G * nu / (1 - 2 * nu)
    stress = [
        [_harmonic(sp.cancel((lame * divergence if i == j else 0) + G * (u[i].diff(X[j]) + u[j].diff(X[i]))))
         for j in range(3)]
        for i in range(3)
    ]  # fmt: skip
    if any(component.has(G) for row in stress for component in row):  # pragma: no cover - derivation check
        raise RuntimeError("the stresses depend on the shear modulus")
    return stress


# --- 3.-4. the Hertz pressure and its potential on the axis ---------------------------------------


def ellipsoidal_potential():
    """(f, Phi): psi = int_lambda^oo f dw (step 3), lambda the root of Phi(lambda) = 0.

    f(w; x, y, z) = (pi a b p0/2) [1 - x^2/(a^2 + w) - y^2/(b^2 + w) - z^2/w]/sqrt((a^2 + w)(b^2 + w) w)
    and Phi(L) = x^2/(a^2 + L) + y^2/(b^2 + L) + z^2/L - 1, with L a Symbol named ``lambda``.
    """
    s = symbols()
    x, y, z, w, a, b, p0 = (s[k] for k in ("x", "y", "z", "w", "a", "b", "p0"))
    L = sp.Symbol("lambda", positive=True)
    shape = 1 - x**2 / (a**2 + w) - y**2 / (b**2 + w) - z**2 / w
    f = sp.pi * a * b * p0 / 2 * shape / sp.sqrt((a**2 + w) * (b**2 + w) * w)
    Phi = x**2 / (a**2 + L) + y**2 / (b**2 + L) + z**2 / L - 1
    return f, Phi


def _leibniz(term, variable):
    """d/d(variable) of (integrand, rest): psi-like = Integral(integrand, (w, lambda, oo)) + rest.

    The lower limit lambda depends on x, y, z through Phi(lambda) = 0 (implicit differentiation).
    """
    s = symbols()
    integrand, rest = term
    _, Phi = ellipsoidal_potential()
    L = sp.Symbol("lambda", positive=True)
    L_v = -sp.diff(Phi, variable) / sp.diff(Phi, L)

    def d(expr):
        return sp.diff(expr, variable) + sp.diff(expr, L) * L_v

    return sp.diff(integrand, variable), d(rest) - integrand.subs(s["w"], L) * L_v


@functools.cache
def axis_integrals():
    """psi_xx, psi_yy, H_xx, H_yy on the z axis as unevaluated integrals over w from z^2 (step 4).

    The boundary terms of Leibniz' rule, which carry dlambda/dx, vanish on the axis (checked).
    """
    s = symbols()
    x, y, z, w = (s[k] for k in ("x", "y", "z", "w"))
    f, _ = ellipsoidal_potential()
    L = sp.Symbol("lambda", positive=True)
    axis = {x: 0, y: 0}
    results = []
    for variable in (x, y):
        integrand, rest = _leibniz(_leibniz((f, sp.Integer(0)), variable), variable)
        rest = sp.simplify(rest.subs(axis).subs(L, z**2))
        if rest != 0:  # pragma: no cover - derivation check
            raise RuntimeError(f"a boundary term survives on the axis: {rest}")
        results.append(sp.simplify(integrand.subs(axis)))
    f_xx, f_yy = results
    psi = [sp.Integral(g, (w, z**2, sp.oo)) for g in (f_xx, f_yy)]
    # H_xx(z) = -int_z^oo psi_xx(t) dt = -int_z^oo int_{t^2}^oo g(w) dw dt = -int_{z^2}^oo g(w) (sqrt(w) - z) dw.
    H = [sp.Integral(-g * (sp.sqrt(w) - z), (w, z**2, sp.oo)) for g in (f_xx, f_yy)]
    return dict(psi_xx=psi[0], psi_yy=psi[1], H_xx=H[0], H_yy=H[1])


def _axis_stresses(values):
    """(sigma_x, sigma_y, sigma_z) on the axis from H_xx, H_yy, psi_xx, psi_yy (a dict of expressions)."""
    s = symbols()
    H, x, y, z = (s[k] for k in ("H", "x", "y", "z"))
    derivatives = {
        sp.Derivative(H, (x, 2)): values["H_xx"],
        sp.Derivative(H, (y, 2)): values["H_yy"],
        sp.Derivative(H, (x, 2), z): values["psi_xx"],
        sp.Derivative(H, (y, 2), z): values["psi_yy"],
    }
    stress = love_stresses()
    out = []
    for i in range(3):
        component = stress[i][i]
        if set(component.atoms(sp.Derivative)) - set(derivatives):  # pragma: no cover - derivation check
            raise RuntimeError(f"sigma_{i}{i} needs more than H_xx, H_yy, psi_xx, psi_yy on the axis")
        out.append(component.subs(derivatives))
    return tuple(out)


# --- 5. the circle -------------------------------------------------------------------------------


@functools.cache
def axis_stresses_circular():
    """(sigma_r/p0, sigma_z/p0) on the axis of the circular Hertz contact, functions of zeta = z/a and nu.

    The integrals of step 4 with b = a, evaluated by SymPy (elementary); sigma_x = sigma_y = sigma_r.
    """
    s = symbols()
    a, b, z, p0, zeta = (s[k] for k in ("a", "b", "z", "p0", "zeta"))
    t = sp.Symbol("t", positive=True)  # w = t^2: rational integrands, integrated fast and exactly
    # Rational integrands: meijerg=False skips the Meijer-G attempt SymPy makes first (2.5 s of 6 s, same values).
    values = {
        k: sp.simplify(integral.subs(b, a).transform(s["w"], t**2).doit(meijerg=False))
        for k, integral in axis_integrals().items()
    }
    sx, sy, sz = (sp.simplify((component / p0).subs(z, zeta * a)) for component in _axis_stresses(values))
    if sp.simplify(sx - sy) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the circular contact is not axisymmetric on its axis")
    return sx, sz


# --- 6. the ellipse in Carlson's form ---------------------------------------------------------------


@functools.cache
def _two_factor_integral():
    """(X, Z, int_0^oo (t + X)^(-1/2) (t + Z)^(-3/2) dt) by SymPy, in a form free of cancellation."""
    X, Z, t = sp.symbols("X Z t", positive=True)
    value = sp.simplify(sp.integrate((t + X) ** sp.Rational(-1, 2) * (t + Z) ** sp.Rational(-3, 2), (t, 0, sp.oo)))
    stable = 2 / (sp.sqrt(Z) * (sp.sqrt(X) + sp.sqrt(Z)))  # the same, rationalised: no difference of roots
    if sp.simplify(value - stable) != 0:  # pragma: no cover - derivation check
        raise RuntimeError(f"two-factor integral {value}")
    return X, Z, stable


def carlson_form(integral):
    """An integral int_{z^2}^oo c (a^2 + w)^(-p) (b^2 + w)^(-q) w^(-s) dw (sums of such terms) in closed form.

    After w = z^2 + t the three-factor terms with exponents {1/2, 1/2, 3/2} are (2/3) c R_D(X, Y, Z),
    Z the argument of exponent 3/2 (DLMF 19.16.5); two-factor terms with exponents {1/2, 3/2}
    are elementary (:func:`_two_factor_integral`).
    """
    s = symbols()
    w, z = s["w"], s["z"]
    integrand, (variable, low, high) = integral.function, integral.limits[0]
    if variable != w or low != z**2 or high != sp.oo:  # pragma: no cover - misuse
        raise ValueError(f"not an integral over w from z^2 to oo: {integral}")
    half, three_halves = sp.Rational(1, 2), sp.Rational(3, 2)
    total = sp.Integer(0)
    X2, Z2, two_factor = _two_factor_integral()
    numerator, denominator = sp.fraction(sp.together(integrand))
    for top in sp.Add.make_args(sp.expand(numerator)):
        coefficient, part = (top / denominator).as_independent(w, as_Add=False)
        powers = sp.powsimp(part, force=True).as_powers_dict()
        exponents = {base: -e for base, e in powers.items() if base.has(w)}
        if any(base.has(w) for base in coefficient.free_symbols) or not exponents:  # pragma: no cover
            raise ValueError(f"term {top / denominator} is not a product of powers of linear factors in w")
        args = {base: base.subs(w, z**2) for base in exponents}
        heavy = [base for base, e in exponents.items() if e == three_halves]
        light = [base for base, e in exponents.items() if e == half]
        if len(heavy) != 1 or len(heavy) + len(light) != len(exponents):  # pragma: no cover - derivation check
            raise ValueError(f"exponents {exponents} are not of R_D's or the elementary form")
        if len(light) == 2:
            total += coefficient * sp.Rational(2, 3) * carlson_rd(args[light[0]], args[light[1]], args[heavy[0]])
        elif len(light) == 1:
            total += coefficient * two_factor.subs({X2: args[light[0]], Z2: args[heavy[0]]})
        else:  # pragma: no cover - derivation check
            raise ValueError(f"exponents {exponents} are not of R_D's or the elementary form")
    return total


def _depth_derivative(integral):
    """d/dz of Integral(g(w, z), (w, z^2, oo)) by Leibniz' rule: the integral of dg/dz minus 2 z g(z^2, z)."""
    s = symbols()
    w, z = s["w"], s["z"]
    g = integral.function
    inside = sp.expand(sp.diff(g, z))
    boundary = sp.simplify(2 * z * g.subs(w, z**2))
    return (sp.Integral(inside, (w, z**2, sp.oo)) if inside != 0 else 0) - boundary


def _carlson_everywhere(expr):
    return expr.replace(lambda e: isinstance(e, sp.Integral), carlson_form)


@functools.cache
def axis_stresses_elliptical():
    """(sigma_x, sigma_y, sigma_z)/p0 on the axis and their zeta-derivatives, functions of zeta = z/b, m_1, nu.

    Step 6: the integrals of step 4 in Carlson's form with a = 1, b = sqrt(m_1), z = zeta b (the
    stresses over p0 depend on the shape and the relative depth only).  The derivatives are taken
    before the integrals are evaluated (Leibniz' rule in the lower limit z^2).  Returns a 6-tuple.
    """
    s = symbols()
    a, b, z, p0, zeta, m_1 = (s[k] for k in ("a", "b", "z", "p0", "zeta", "m_1"))
    integrals = axis_integrals()
    # The stresses are linear in the four integrals V with coefficients in z: d sigma/dz is the sum of
    # (d sigma/dV) (dV/dz) and the explicit z-derivative at fixed V.
    held = {k: sp.Symbol(f"V_{k}") for k in integrals}
    in_held = _axis_stresses(held)
    substitute = {held[k]: integral for k, integral in integrals.items()}
    stresses = [component.subs(substitute) for component in in_held]
    slopes = [
        (sp.diff(component, z) + sum(sp.diff(component, held[k]) * _depth_derivative(integral)
                                     for k, integral in integrals.items())).subs(substitute)
        for component in in_held
    ]  # fmt: skip
    scale = {a: 1, b: sp.sqrt(m_1)}
    out = []
    for k, expr in enumerate((*stresses, *slopes)):
        expr = _carlson_everywhere(expr).subs(scale)
        expr = expr.subs(z, zeta * sp.sqrt(m_1)) / p0
        if k >= 3:
            expr *= sp.sqrt(m_1)  # d/dzeta = b d/dz
        out.append(sp.expand(expr))
    return tuple(out)


# --- 8. the load at first yield -----------------------------------------------------------------------


def yield_relations():
    """(P, a, delta) of the elliptical Hertz contact with peak pressure p0, relative curvature A and shape m_1.

    Johnson Sec. 4.2 (the relations :func:`.elliptical.hertz_elliptical_monomial` starts from):
    b = a sqrt(m_1), A = p0 b D_m/(E* a^2), P = 2/3 pi a b p0, delta = p0 b K_m/E*, with
    K_m = K(m) and D_m = (K(m) - E(m))/m the placeholders of :func:`.elliptical.elliptic_placeholders`
    and E* a Symbol named ``E^*``.
    """
    s, c = symbols(), contact_symbols()
    a, p0, m_1 = s["a"], s["p0"], s["m_1"]
    A = c["A"]
    Es = sp.Symbol("E^*", positive=True)
    K_m, D_m = elliptic_placeholders()
    b = a * sp.sqrt(m_1)
    (a_of_p0,) = sp.solve(sp.Eq(A, p0 * b * D_m / (Es * a**2)), a)
    P = sp.factor(sp.Rational(2, 3) * sp.pi * a * b * p0).subs(a, a_of_p0)
    delta = (p0 * b * K_m / Es).subs(a, a_of_p0)
    return sp.factor(P), a_of_p0, sp.factor(delta)


def _with_carlson(expr, m_1):
    """K_m -> R_F(0, m_1, 1), D_m -> R_D(0, m_1, 1)/3 (DLMF 19.25.1, as :func:`.elliptical.carlson_form`)."""
    K_m, D_m = elliptic_placeholders()
    return expr.subs({K_m: carlson_rf(0, m_1, 1), D_m: carlson_rd(0, m_1, 1) / 3})


# --- numeric functions ---------------------------------------------------------------------------------


@derived
def _circular_axis():
    s = symbols()
    sr, sz = axis_stresses_circular()
    g = sr - sz
    return (s["zeta"], s["nu"]), (sr, sz, sp.diff(g, s["zeta"]))


@derived
def _elliptical_axis():
    s = symbols()
    return (s["zeta"], s["m_1"], s["nu"]), axis_stresses_elliptical()


@derived
def _log_load_at_pressure():
    """(ln P, ln a) of the elliptical contact at peak pressure p0, in ln p0, ln A, ln E, nu and m_1 (Carlson's forms).

    P = P_1 p0^3/(A^2 E^2) and a = a_1 p0/(A E) with P_1, a_1 functions of nu and m_1 alone (checked): in
    logarithms no power of p0, A or E leaves the doubles on the way (A^2 E^2 overflowed for r below 1e-140 m,
    and the yield force came out as zero).  The circle is m_1 = 1, A = 1/(2 R').
    """
    s, c = symbols(), contact_symbols()
    p0, A, E, nu, m_1 = s["p0"], c["A"], c["E"], c["nu"], s["m_1"]
    P, a, _ = yield_relations()
    material = {sp.Symbol("E^*", positive=True): effective_modulus()}
    P, a = (_with_carlson(e.subs(material), m_1) for e in (P, a))
    unit = {p0: 1, A: 1, E: 1}
    P_1, a_1 = P.subs(unit), a.subs(unit)
    if sp.simplify(P - P_1 * p0**3 / (A * E) ** 2) != 0 or sp.simplify(a - a_1 * p0 / (A * E)) != 0:  # pragma: no cover
        raise RuntimeError("the load and the semi-axis are not P_1 p0^3/(A E)^2 and a_1 p0/(A E)")
    logs = sp.symbols("log_p0 log_A log_E", real=True)
    log_P = 3 * logs[0] - 2 * logs[1] - 2 * logs[2] + sp.log(P_1)
    log_a = logs[0] - logs[1] - logs[2] + sp.log(a_1)
    return (*logs, nu, m_1), (log_P, log_a)


#: Depths (zeta = z/b) scanned for the largest von Mises stress before the bisection: the maximum lies
#: at 0.38-0.55 b for the circle with nu in [0, 0.5) and moves to 0 as nu -> -1 and towards 0.8 b as b/a -> 0.
_SCAN = np.linspace(0.0, 3.0, 61)
_BISECTIONS = 60  # the bracket of width 0.1 shrinks below the spacing of doubles near the maximum


def _von_mises(sx, sy, sz):
    return np.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2))


def _circle_values(zeta, nu):
    sr, sz, _ = _circular_axis(zeta, nu)
    return np.abs(sr - sz)


def _circle_slope(zeta, nu):
    sr, sz, slope = _circular_axis(zeta, nu)
    return np.sign(sr - sz) * slope


def _ellipse_values(zeta, m_1, nu):
    sx, sy, sz, *_ = _elliptical_axis(zeta, m_1, nu)
    return _von_mises(sx, sy, sz)


def _ellipse_slope(zeta, m_1, nu):
    sx, sy, sz, dx, dy, dz = _elliptical_axis(zeta, m_1, nu)
    return (sx - sy) * (dx - dy) + (sy - sz) * (dy - dz) + (sz - sx) * (dz - dx)  # d(sigma_vm^2)/dzeta / 2


def _maximum(values, slope, *params):
    """(max over zeta of values(zeta, *params), its zeta): a scan over :data:`_SCAN`, then bisection on slope."""
    shape = np.broadcast_shapes(*(np.shape(p) for p in params))
    params = [np.broadcast_to(p, shape) for p in params]
    with np.errstate(all="ignore"):
        scanned = np.stack([values(zeta, *params) for zeta in _SCAN])
        best = np.argmax(scanned, axis=0)
        lo = _SCAN[np.maximum(best - 1, 0)]
        hi = _SCAN[np.minimum(best + 1, _SCAN.size - 1)]
        for _ in range(_BISECTIONS):
            middle = 0.5 * (lo + hi)
            rising = slope(middle, *params) > 0
            lo = np.where(rising, middle, lo)
            hi = np.where(rising, hi, middle)
        zeta = 0.5 * (lo + hi)
        peak = values(zeta, *params)
    return peak, zeta


#: Smallest yield strength taken, Pa: softer than any metal or polymer of a ring (lead yields at about 5 MPa); a
#: smaller Y is a strength in MPa given as Pa (215 for 215e6), which would give forces 1e18 times too small.
MIN_YIELD_STRENGTH = 1e6


def _check_yield_inputs(R, r, E, nu, Y, angle):
    Y = v.positive("Y", Y, "Pa")
    if Y.size and np.min(Y) < MIN_YIELD_STRENGTH:
        raise ValueError(f"Y = {float(np.min(Y)):g} Pa is below 1 MPa, softer than any ring's material: Y is in Pa "
                         f"(215 MPa is 215e6)")  # fmt: skip
    A, _, m = contact_ellipse(R, r, angle)  # validates R > 2 r and the angle, with errors that say why
    K_c = hertz_stiffness(R, r, E, nu, angle)  # validates E and nu
    v.broadcast_shape(R=R, r=r, E=E, nu=nu, Y=Y, angle=angle)
    return Y, A, m, K_c


def _shape(m):
    """m_1 = 1 - m, refusing an ellipse whose b/a rounds to zero."""
    m_1 = 1.0 - np.asarray(m, dtype=float)
    if np.asarray(m_1).size and not np.min(m_1) > 0:
        raise ValueError(
            "the contact ellipse is too elongated to resolve (b/a below 1e-8): the angle lies within about "
            "1e-14 rad of the smallest angle of a single contact"
        )
    return m_1


class FirstYield(NamedTuple):
    """The contact of two tori at first yield (:func:`first_yield`).

    Attributes
    ----------
    force : ndarray
        Contact force F_y at which the largest von Mises stress reaches Y, N.
    indentation : ndarray
        Approach delta_y = (F_y/K_c)^(2/3) at that force, m (K_c of :func:`~ringchain.theory.hertz_stiffness`).
    pressure : ndarray
        Peak Hertz pressure p0 at first yield, Pa.
    depth : ndarray
        Depth below the surface, on the contact's axis, where yield starts, m.
    pressure_ratio : ndarray
        p0/Y (1.601 for the circular contact at nu = 0.29).
    depth_ratio : ndarray
        Depth over the contact's semi-minor axis b (its radius for the circle; 0.478 at nu = 0.29).
    """

    force: np.ndarray
    indentation: np.ndarray
    pressure: np.ndarray
    depth: np.ndarray
    pressure_ratio: np.ndarray
    depth_ratio: np.ndarray


def first_yield(R, r, E, nu, angle=np.pi / 2, *, Y) -> FirstYield:
    """Force, approach, pressure and depth at which the contact of two identical tori first yields.

    Parameters
    ----------
    R, r : array_like
        Major and tube radius of the tori, m (R > 2 r).
    E : array_like
        Young's modulus, Pa.
    nu : array_like
        Poisson's ratio, in (-1, 0.5).
    angle : array_like, optional
        Contact angle theta between the ring planes, rad, in (theta_min, pi/2]; default pi/2.
    Y : array_like
        Yield strength in uniaxial tension (von Mises), Pa.

    Returns
    -------
    FirstYield
        F_y (N), delta_y (m), p0 (Pa), depth (m), p0/Y and depth/b.

    Notes
    -----
    Steps 1-8 of the module docstring: the largest von Mises stress on the axis of the Hertz
    contact (circular at pi/2, Johnson Eq. (3.45); elliptical otherwise, in Carlson's closed
    form) reaches Y at p0 = Y/max(sigma_vm/p0); the load follows from the elliptical Hertz
    relations, F_y = 2/3 pi (1 - m)^(3/2) D(m)^2 p0^3/(A^2 E*^2), which for perpendicular
    rings (App. A, R' = r(R - r)/(R - 2r)) is pi^3 R'^2 p0^3/(6 E*^2).  F_y scales as Y^3.
    The maximum along the depth is found to about 1e-15 relative.  The ratio p0/Y depends
    on nu and the shape of the ellipse only.

    Examples
    --------
    >>> y = first_yield(22.5e-3, 2.5e-3, 193e9, 0.29, Y=215e6)  # the paper's ring, annealed AISI 304
    >>> round(float(y.pressure_ratio), 3), round(float(y.depth_ratio), 3), round(float(y.force), 3)
    (1.601, 0.478, 0.155)
    """
    Y, A, m, K_c = _check_yield_inputs(R, r, E, nu, Y, angle)
    E, nu, angle = (v.as_float(name, value) for name, value in (("E", E), ("nu", nu), ("angle", angle)))
    m_1 = _shape(m)  # 1 for the circle
    with np.errstate(all="ignore"):
        if angle.size and angle.min() == np.pi / 2:  # all perpendicular: the circle's stresses in closed form
            peak, zeta = _maximum(_circle_values, _circle_slope, nu)
        else:
            peak, zeta = _maximum(_ellipse_values, _ellipse_slope, m_1, nu)
        p0 = Y / peak
        log_force, log_a = _log_load_at_pressure(np.log(p0), np.log(A), np.log(E), nu, m_1)
        force = v.finite_result(np.exp(log_force), "the yield force", "radii, elastic constants and yield strength")
        indentation = np.exp(2.0 / 3.0 * (log_force - np.log(K_c)))  # (F_y/K_c)^(2/3), which may underflow
        depth = zeta * np.exp(log_a) * np.sqrt(m_1)
    v.finite_result((indentation, depth), "the approach at first yield", "radii and elastic constants")
    return FirstYield(force, indentation, p0, depth, 1.0 / peak, zeta)


def yield_force(R, r, E, nu, angle=np.pi / 2, *, Y):
    """Contact force at which the Hertz contact of two identical tori first yields, N.

    Parameters
    ----------
    R, r : array_like
        Major and tube radius of the tori, m (R > 2 r).
    E : array_like
        Young's modulus, Pa.
    nu : array_like
        Poisson's ratio, in (-1, 0.5).
    angle : array_like, optional
        Contact angle theta between the ring planes, rad, in (theta_min, pi/2]; default pi/2.
    Y : array_like
        Yield strength (von Mises), Pa.

    Returns
    -------
    ndarray
        F_y in N: :attr:`FirstYield.force` of :func:`first_yield` (its Notes give the method).

    Examples
    --------
    >>> round(float(yield_force(22.5e-3, 2.5e-3, 193e9, 0.29, Y=1e9)), 2)  # cold-drawn AISI 304 wire
    15.59
    """
    return first_yield(R, r, E, nu, angle, Y=Y).force


def subsurface_stress(z, R, r, E, nu, angle=np.pi / 2, *, F):
    """Stresses on the axis of the elastic Hertz contact of two tori, at depth z under the contact force F.

    Parameters
    ----------
    z : array_like
        Depth below the contact's centre, m, >= 0.
    R, r : array_like
        Major and tube radius of the tori, m (R > 2 r).
    E : array_like
        Young's modulus, Pa.
    nu : array_like
        Poisson's ratio, in (-1, 0.5).
    angle : array_like, optional
        Contact angle theta between the ring planes, rad, in (theta_min, pi/2]; default pi/2.
    F : array_like
        Contact force, N, > 0 (keyword-only, as in :func:`~ringchain.theory.contact_semi_axes`).

    Returns
    -------
    sigma_x, sigma_y, sigma_z, von_mises : ndarray
        Normal stresses (Pa, compression negative) along the major axis of the contact ellipse,
        along its minor axis and along the depth, and the von Mises stress (Pa).  On the axis
        these are the principal stresses.

    Notes
    -----
    Steps 1-6 of the module docstring: Boussinesq's point load superposed over the Hertz
    pressure through Love's potentials, in Carlson's closed form (for the circle, b/a = 1, it
    equals Johnson's Eq. (3.45); the tests compare).  The contact is that of
    :func:`~ringchain.theory.hertz_stiffness`
    (semi-axes a^3 = 3 F D(m)/(2 pi A E*), b = a sqrt(1 - m)).  Elastic: beyond
    :func:`yield_force` the stresses are those the elastic contact would carry.

    Examples
    --------
    >>> sx, sy, sz, vm = subsurface_stress(0.0, 22.5e-3, 2.5e-3, 193e9, 0.29, F=10.0)
    >>> round(float(-sz / 1e9), 3)  # GPa: the peak pressure p0 at the surface
    1.381
    """
    z = v.nonnegative("z", z, "m")
    F = v.positive("F", F, "N")
    A, _, m = contact_ellipse(R, r, angle)
    contact_modulus(E, nu)  # validates E and nu
    v.broadcast_shape(z=z, F=F, R=R, r=r, E=E, nu=nu, angle=angle)
    E, nu, angle = (v.as_float(name, value) for name, value in (("E", E), ("nu", nu), ("angle", angle)))
    m_1 = _shape(m)
    with np.errstate(all="ignore"):
        # p0 from the load: P is p0^3 times a factor free of p0 (yield_relations), so scale a unit pressure.
        log_unit_load, log_unit_a = _log_load_at_pressure(0.0, np.log(A), np.log(E), nu, m_1)
        log_p0 = (np.log(F) - log_unit_load) / 3
        p0 = np.exp(log_p0)
        b = np.exp(log_unit_a + log_p0) * np.sqrt(m_1)
        sx, sy, sz, *_ = _elliptical_axis(z / b, m_1, nu)
        stresses = tuple(p0 * component for component in (sx, sy, sz))
        stresses = (*stresses, _von_mises(*stresses))
    return tuple(v.finite_result(s, "the stress", "force, radii and elastic constants") for s in stresses)
