r"""Solitary wave on a pre-stretched power-law chain and its speed (beyond the paper; App. B, Eq. (B19)).

Continues :mod:`.solitary` (the compact wave on an unstretched chain) for a static strain
xi_0 > 0 far from the wave, as in a hanging chain below its top.  Step by step:

1. :func:`first_integral` -- with w(xi) = xi_tau^2, Eq. (B19) (:func:`.solitary.eq19_residual`)
   is linear in w and xi^(n-1) is its integrating factor: n a^2/24 xi^(n-1) xi_tau^2 = P(xi) + E.
2. :func:`prestressed_speed_squared` -- C_0 from the uniform state xi_0
   (:func:`.solitary.integration_constants`) and xi_tau = 0 at xi_0 and at the peak xi_max give
   V_s^2 = 2 c_n^2 [(xi_max^(n+1) - xi_0^(n+1))/(n+1) - xi_0^n (xi_max - xi_0)]/(xi_max - xi_0)^2.
3. :func:`prestressed_speed_hypergeometric` -- the same as
   V_s^2 = n c_n^2 xi_max^(n-1) 2F1(1 - n, 2; 3; 1 - xi_0/xi_max), finite and accurate for
   every 0 <= xi_0 <= xi_max; :func:`prestressed_speed_from_force` writes it in forces.
   For n = 3/2 this is Nesterenko's weakly compressed chain.
4. Numbers: the speed over the compact wave's (:func:`.solitary.speed_from_strain`) is
   G^2 = n (n+1)/2 2F1 (:func:`prestress_factor`), a function of n and xi_0/xi_max alone,
   evaluated from its elementary form (:func:`prestress_factor_elementary`) where that keeps
   its digits and from Euler's integral (:func:`prestress_factor_integral`) by Gauss-Legendre
   quadrature where it does not.

Numeric function: :func:`solitary_wave_speed_prestressed`.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from . import longwave
from ._codegen import derived, sp
from ._forms import tidy_powers
from .solitary import eq19_residual, integration_constants, solitary_wave_speed, speed_from_strain, symbols
from .special import gauss_legendre, hyp2f1

__all__ = [
    "first_integral",
    "prestressed_speed_squared",
    "prestressed_speed_hypergeometric",
    "prestressed_speed_from_force",
    "prestress_factor",
    "prestress_factor_elementary",
    "prestress_factor_integral",
    "solitary_wave_speed_prestressed",
]


# --- 1.-3. the first integral and the speed ------------------------------------------------------


@functools.cache
def first_integral():
    """(lhs, rhs) of n a^2/24 xi^(n-1) xi_tau^2 = P(xi) + E, C_1 = 0 and C_0 kept; E a symbol.

    With w(xi) = xi_tau^2, xi_tautau = w'(xi)/2 and Eq. (B19) becomes
    b [(n-1) xi^(n-2) w + xi^(n-1) w'] = (V_s/c_n)^2 xi - xi^n - C_0, b = n a^2/24;
    the integrating factor exp(int (n-1)/xi) = xi^(n-1) makes the left side
    b d/dxi (xi^(n-1) w), and the right side integrates to P(xi).
    """
    s = symbols()
    X, n = s["X"], s["n"]
    w = sp.Function("w")
    residual = eq19_residual(X, sp.sqrt(w(X)), sp.diff(w(X), X) / 2, C_1=0)  # lhs - rhs of Eq. (B19)
    dispersive = sp.expand(-(residual - residual.subs(w(X), 0).doit()).doit())  # b[...] part
    source = sp.expand(residual.subs(w(X), 0).doit())  # (V/c)^2 xi - xi^n - C_0
    w_coefficient, w_prime_coefficient = dispersive.coeff(w(X)), dispersive.coeff(sp.diff(w(X), X))
    factor = sp.simplify(sp.exp(sp.integrate(sp.expand(w_coefficient / w_prime_coefficient), X)))
    b = sp.simplify(w_prime_coefficient / X ** (n - 1))
    if sp.simplify(b * sp.diff(factor * w(X), X) - dispersive) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("xi^(n-1) is not an integrating factor")
    E = sp.Symbol("E", real=True)
    return b * factor * s["X_tau"] ** 2, sp.integrate(source, X) + E


@functools.cache
def prestressed_speed_squared():
    """V_s^2(xi_max, xi_0) of the solitary wave on a chain with static strain xi_0 (elementary form).

    :func:`first_integral` with C_0 from :func:`integration_constants` (xi -> xi_0) and
    xi_tau = 0 at xi_0 (far field) and at the peak xi_max; solved for V_s^2.
    """
    s = symbols()
    X, xi_0, xi_max = s["X"], s["xi_0"], s["xi_max"]
    _, rhs = first_integral()
    E = sp.Symbol("E", real=True)
    rhs = rhs.subs(s["C_0"], integration_constants(xi_0)[s["C_0"]])
    energy = sp.solve(rhs.subs(X, xi_0), E, check=False)[0]
    ratio = sp.solve(rhs.subs(E, energy).subs(X, xi_max), s["V_s"] ** 2, check=False)
    return sp.factor(sp.simplify(ratio[0]))


@functools.cache
def prestressed_speed_hypergeometric():
    """V_s^2 = n c_n^2 xi_max^(n-1) 2F1(1 - n, 2; 3; 1 - xi_0/xi_max) (as ``hyp2f1``).

    Writing xi = xi_max (1 - z u) turns the bracket of :func:`prestressed_speed_squared`
    into the integral of the contact stiffness along the wave,
    V_s^2 = 2 n c_n^2 xi_max^(n-1) int_0^1 u (1 - z u)^(n-1) du with z = 1 - xi_0/xi_max,
    and Euler's integral (DLMF 15.6.1) makes that n c_n^2 xi_max^(n-1) 2F1(1-n, 2; 3; z).
    The identity with the elementary form is proved symbolically in the tests
    (:func:`sympy.hyperexpand`); here it is checked at a few points (a guard against an
    inconsistent edit).  At z = 0 (no wave) 2F1 = 1: the sound speed; at z = 1 (no
    pre-stretch) 2F1 = 2/(n(n+1)): the compact wave.  Unlike the elementary form, which is
    0/0 as xi_max -> xi_0, it evaluates accurately for every 0 <= xi_0 <= xi_max.
    """
    s = symbols()
    n, xi_0, xi_max = s["n"], s["xi_0"], s["xi_max"]
    form = n * s["c_n"] ** 2 * xi_max ** (n - 1) * hyp2f1(1 - n, 2, 3, 1 - xi_0 / xi_max)
    R = sp.Rational
    for point in ({n: R(13, 10), xi_0: R(1, 5)}, {n: R(5, 2), xi_0: R(7, 10)}, {n: R(21, 20), xi_0: R(1, 100)}):
        point = {**point, xi_max: R(11, 10), s["c_n"]: 2}
        elementary, hypergeometric = (sp.N(e.subs(point), 30) for e in (prestressed_speed_squared(), form))
        if abs(elementary / hypergeometric - 1) > 1e-20:  # pragma: no cover - derivation check
            raise RuntimeError("the pre-stretched speed is not the hypergeometric form")
    return form


@functools.cache
def prestressed_speed_from_force():
    """V_s(F_m, F_0): :func:`prestressed_speed_hypergeometric` with F = K (a xi)^n for the peak and the static force."""
    s = symbols()
    K, a, n = s["K"], s["a"], s["n"]
    xi_peak = sp.solve(sp.Eq(s["F_m"], K * (a * s["xi_max"]) ** n), s["xi_max"], check=False)[0]
    xi_static = sp.solve(sp.Eq(s["F_0"], K * (a * s["xi_0"]) ** n), s["xi_0"], check=False)[0]
    speed2 = prestressed_speed_hypergeometric().subs({s["xi_max"]: xi_peak, s["xi_0"]: xi_static}, simultaneous=True)
    speed2 = speed2.subs(s["c_n"] ** 2, longwave.wave_speed_squared())
    return tidy_powers(sp.sqrt(speed2))


@functools.cache
def prestress_factor():
    """G^2 = V_s^2(xi_max, xi_0)/V_s^2(xi_max, 0) = n (n+1)/2 2F1(1 - n, 2; 3; 1 - w), w = xi_0/xi_max.

    :func:`prestressed_speed_hypergeometric` over the compact wave's :func:`speed_from_strain`
    squared; a function of n and w alone (checked).  Returns (G^2, w) with w a Symbol.
    """
    s = symbols()
    w = sp.Symbol("w", positive=True)
    ratio = prestressed_speed_hypergeometric().subs(s["xi_0"], w * s["xi_max"]) / speed_from_strain() ** 2
    ratio = sp.powsimp(sp.expand_power_base(sp.simplify(ratio), force=True), force=True)
    if ratio.has(s["xi_max"], s["c_n"]):  # pragma: no cover - derivation check
        raise RuntimeError("the pre-stretch factor depends on more than n and xi_0/xi_max")
    return ratio, w


@functools.cache
def prestress_factor_elementary():
    """G^2 = (1 - q (1 + n Z))/Z^2 with q = F_0/F_m = w^n and Z = 1 - w: the elementary form.

    From :func:`prestressed_speed_squared` over the compact wave's speed squared, with
    w^n = q (F = K (a xi)^n) and w = 1 - Z.  Accurate where the numerator is not small:
    its terms are at most 1, so its relative rounding error is a few 1e-16 divided by its
    value; as F_0 -> F_m (Z -> 0) it is 0/0.  Returns (G^2, q, Z) with q, Z Symbols.
    """
    s = symbols()
    n = s["n"]
    w, q, Z = (sp.Symbol(name, positive=True) for name in ("w", "q", "Z"))
    ratio = prestressed_speed_squared().subs(s["xi_0"], w * s["xi_max"]) / speed_from_strain() ** 2
    ratio = sp.expand_power_exp(sp.expand(sp.powsimp(sp.expand_power_base(sp.simplify(ratio), force=True))))
    closed = sp.factor(sp.simplify(ratio.subs(w**n, q).subs(w, 1 - Z)))
    if closed.has(w, s["xi_max"], s["c_n"]):  # pragma: no cover - derivation check
        raise RuntimeError(f"the elementary pre-stretch factor is not a function of q and Z: {closed}")
    return closed, q, Z


@functools.cache
def prestress_factor_integral():
    """(integrand, t): G^2 = int_0^1 integrand dt, from Euler's integral of 2F1 (DLMF 15.6.1).

    2F1(a, b; c; z) = Gamma(c)/(Gamma(b) Gamma(c - b)) int_0^1 t^(b-1) (1 - t)^(c-b-1) (1 - z t)^(-a) dt
    with a = 1 - n, b = 2, c = 3, times n (n+1)/2 (:func:`prestress_factor`): the integrand
    n (n+1) t (1 - Z t)^(n-1), Z = 1 - w.  Smooth on [0, 1] wherever the elementary form
    loses digits (Z small), so Gauss-Legendre quadrature evaluates it there.
    """
    factor, w = prestress_factor()
    hypergeometric = next(iter(factor.atoms(sp.Function)))
    a, b, c, argument = hypergeometric.args
    t, Z = sp.Symbol("t", positive=True), sp.Symbol("Z", positive=True)
    weight = sp.gamma(c) / (sp.gamma(b) * sp.gamma(c - b)) * t ** (b - 1) * (1 - t) ** (c - b - 1)
    euler = weight * (1 - argument * t) ** (-a)
    integrand = sp.simplify((factor / hypergeometric * euler).subs(w, 1 - Z))
    if argument.subs(w, 1 - Z) != Z or integrand.has(w):  # pragma: no cover - derivation check
        raise RuntimeError("the pre-stretch factor is not 2F1 of 1 - w")
    return integrand, t, Z


# --- 4. numeric functions -------------------------------------------------------------------------


def _prestress_in_forces(expr, q, Z):
    """expr(q, Z) with q = F_0/F_m and Z = 1 - q^(1/n) = -expm1(log(q)/n) (accurate for q -> 1)."""
    from sympy.codegen.cfunctions import expm1

    s = symbols()
    ratio = s["F_0"] / s["F_m"]
    values = {Z: -expm1(sp.log(ratio) / s["n"])}
    if q is not None:
        values[q] = ratio
    return expr.subs(values)


@derived
def _prestress_elementary():
    s = symbols()
    closed, q, Z = prestress_factor_elementary()
    numerator, denominator = sp.fraction(sp.factor(closed))
    return (s["F_m"], s["F_0"], s["n"]), tuple(_prestress_in_forces(e, q, Z) for e in (numerator, denominator))


@derived
def _prestress_integrand():
    """The integrand at t = x in [0, 1], with (1 - Z t)^(n-1) = exp((n - 1) log1p(-Z t))."""
    from sympy.codegen.cfunctions import log1p

    s = symbols()
    integrand, t, Z = prestress_factor_integral()
    base = 1 - Z * t
    power = next(p for p in integrand.atoms(sp.Pow) if p.base in (base, sp.expand(base)))
    stable = integrand.subs(power, sp.exp(power.exp * log1p(-Z * t)))
    if stable.has(power):  # pragma: no cover - derivation check
        raise RuntimeError("the integrand's power was not rewritten")
    return (s["x"], s["F_m"], s["F_0"], s["n"]), _prestress_in_forces(stable.subs(t, s["x"]), None, Z)


#: The elementary pre-stretch factor is used where its numerator is at least this: its
#: relative rounding error is then below about 12 x 1e-16; below it, quadrature.
_ELEMENTARY_FROM = 0.25


#: Gauss-Legendre points for the pre-stretch factor: where the numerator is below
#: _ELEMENTARY_FROM the integrand is analytic well beyond [0, 1] (its singularity, at
#: t = 1/Z >= 2, or its exponent (n - 1) Z <= 1 keep it smooth), and 12 points integrate
#: it to below 1e-16.
_QUADRATURE_POINTS = 12


def _prestress(F_m, F_0, n):
    """sqrt(G^2): the pre-stretched speed over the compact wave's, broadcast over the arguments."""
    with np.errstate(all="ignore"):
        numerator, denominator = _prestress_elementary(F_m, F_0, n)
        shape = np.broadcast_shapes(np.shape(numerator), np.shape(denominator))
        factor = np.array(np.broadcast_to(numerator / denominator, shape), dtype=float)
        near = np.broadcast_to(~(numerator >= _ELEMENTARY_FROM), shape)
        if np.any(near):
            F_m_, F_0_, n_ = (np.broadcast_to(value, shape)[near] for value in (F_m, F_0, n))
            points, weights = gauss_legendre(_QUADRATURE_POINTS)
            total = 0.0
            for point, weight in zip(0.5 * (points + 1.0), 0.5 * weights, strict=True):
                total = total + weight * _prestress_integrand(point, F_m_, F_0_, n_)
            factor[near] = total
        return np.sqrt(factor)


def solitary_wave_speed_prestressed(F_m, *, F_0, K, n, m, a):
    """Speed of the solitary wave on a chain pre-stretched by a static contact force F_0.

    Parameters
    ----------
    F_m : array_like
        Peak contact force of the wave, static part included, N; F_m >= F_0 and F_m > 0.
    F_0 : array_like
        Static contact force far from the wave, N, >= 0 (in a hanging chain, the weight
        of the rings below the contact).
    K, n, m, a : array_like
        Chain: prefactor (N/m^n), exponent (> 1), mass (kg), spacing (m), as in
        :func:`solitary_wave_speed`.

    Returns
    -------
    ndarray
        V_s = a sqrt(n K^(1/n) F_m^((n-1)/n)/m 2F1(1-n, 2; 3; 1 - (F_0/F_m)^(1/n))), m/s.

    Notes
    -----
    Eq. (B19) with C_0 set by the static strain xi_0 = (F_0/K)^(1/n)/a and its first
    integral (:func:`prestressed_speed_squared`,
    :func:`prestressed_speed_hypergeometric`); the generalisation to any n of
    Nesterenko's weakly compressed chain (n = 3/2).  F_0 = 0 gives
    :func:`solitary_wave_speed`; F_0 -> F_m gives the linear sound speed
    :func:`~ringchain.theory.linear_sound_speed` at F_0.  Evaluated as the compact wave's
    speed times G = sqrt(n (n+1)/2 2F1): G from its elementary form
    (:func:`prestress_factor_elementary`) where that keeps its digits, else from Euler's
    integral (:func:`prestress_factor_integral`) by 12-point Gauss-Legendre quadrature;
    both accurate to about 1e-15 for every n > 1 and 0 <= F_0 <= F_m (SciPy's hyp2f1
    loses digits, or returns NaN, for large n).

    Examples
    --------
    >>> round(float(solitary_wave_speed_prestressed(8.0, F_0=0.0, K=1.0, n=3.0, m=1.0, a=1.0)), 6)
    1.414214
    >>> round(float(solitary_wave_speed_prestressed(8.0, F_0=8.0, K=1.0, n=3.0, m=1.0, a=1.0)), 6)  # sqrt(3) 8^(1/3)
    3.464102
    """
    F_m = v.positive("F_m", F_m, "N")
    F_0 = v.nonnegative("F_0", F_0, "N")
    chain = v.compact_wave_chain(K, n, a, m)
    v.broadcast_shape(F_m=F_m, F_0=F_0, K=chain[0], n=chain[1], a=chain[2], m=chain[3])
    if np.any(F_0 > F_m):
        excess = np.broadcast_to(F_0, np.broadcast_shapes(F_0.shape, F_m.shape))[F_0 > F_m]
        raise ValueError(
            f"F_0 must not exceed F_m (got F_0 = {v.show(excess.max())} N above F_m): F_m is the peak contact "
            "force of the wave with the static force F_0 included, so F_m >= F_0"
        )
    factor = _prestress(F_m, F_0, chain[1])
    with np.errstate(all="ignore"):
        speed = solitary_wave_speed(F_m, K=chain[0], n=chain[1], m=chain[3], a=chain[2]) * factor
    return v.finite_result(speed, "V_s", "force, velocity and chain parameters (K, n, m, a)")
