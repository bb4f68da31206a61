r"""Thornton's elastic-perfectly plastic contact of two tori, and the restitution of a colliding pair.

Beyond the paper (its dashpots stand for the losses; Sec. III.B).  Thornton (1997, J. Appl.
Mech. 64, 383) caps the Hertz pressure of two spheres at a limiting pressure p_y; here p_y is
the peak pressure at first yield (:mod:`.subsurface`, 1.60 Y for nu = 0.29), so that the
contact is elastic up to :func:`~ringchain.theory.yield_force` and plastic beyond.  Step by step:

1. :func:`hertz_sphere` -- the sphere of radius R_e on the elastic half-space (modulus E*):
   the Hertz pressure p0 sqrt(1 - s^2/a^2) integrated over the contact gives P = 2/3 pi a^2 p0;
   with Hertz's a^3 = 3 P R_e/(4 E*) and delta = a^2/R_e (as :func:`.contact.hertz_circular`)
   p0 = 2 E* a/(pi R_e) and P = 4/3 E* sqrt(R_e) delta^(3/2) = K_c delta^(3/2).
2. :func:`truncated_force` -- Thornton's loading: the contact radius stays Hertz's,
   a = sqrt(R_e delta), and the pressure is min(p0 sqrt(1 - s^2/a^2), p_y).  Integrated over
   the contact (flat top out to the radius where the Hertz pressure falls to p_y) it is
   F = pi p_y R_e (delta - delta_y/3) beyond the yield point delta_y = pi^2 p_y^2 R_e/(4 E*^2),
   where the Hertz peak pressure reaches p_y: a straight line of slope pi p_y R_e (the plastic
   stiffness), tangent to the Hertz curve at delta_y.
3. :func:`loading_force` -- the same in the contact's own constants K_c and delta_y
   (E* cancels): F = K_c delta_y^(3/2) (3 x - 1)/2, x = delta/delta_y >= 1; the slope is
   3/2 K_c sqrt(delta_y).
4. :func:`unloading_force` -- unloading from the largest approach delta_m = x_m delta_y is
   elastic, a Hertz contact of a larger radius R_p (the flattened tip): R_p follows from
   Hertz's a^3 = 3 F R_p/(4 E*) with Thornton's a_m = sqrt(R_e delta_m) and F_m the loading force at
   delta_m, and the unloading curve F = 4/3 E* sqrt(R_p) (delta - delta_p)^(3/2) passes through
   (delta_m, F_m): delta_m - delta_p = a_m^2/R_p = delta_y (3 x_m - 1)/(2 sqrt(x_m)).  The contact
   opens at the residual approach delta_p; reloading retraces the unloading curve up to delta_m.
   At x_m = 1 it is the Hertz curve, so one formula serves, with x_m = max(1, delta_m/delta_y).
5. :func:`energies` -- work of loading W_l(x_m), elastic energy returned on unloading
   W_u(x_m) = 2/5 F_m (delta_m - delta_p), the plastic work W_l - W_u, and the elastic energy
   stored at any point of an unloading curve.
6. :func:`impact` -- two bodies of reduced mass m meeting at relative speed V: W_l(x_m) = m V^2/2
   gives x_m, and the rebound energy W_u gives e^2 = W_u/W_l.  The contact just yields at
   V_y = sqrt(4 F_y delta_y/(5 m)) (the Hertz energy 2/5 F_y delta_y); in v = V/V_y,
   x_m = (1 + 2 sqrt((6 v^2 - 1)/5))/3 and e^2 = 6/5 (1 - 1/(6 v^2))/sqrt(x_m): Thornton's closed
   form (his Eq. (23); the tests compare), e ~ 1.2 v^(-1/4) at large v.

Equivalent radius of the torus contact.  Thornton's model is a sphere's; the tori touch on an
ellipse except at 90 degrees.  The law here has two constants, K_c (paper Eq. (1), the elliptical
Hertz constant of :func:`~ringchain.theory.hertz_stiffness`) and delta_y = (F_y/K_c)^(2/3) (F_y of
:func:`~ringchain.theory.yield_force`, from the elliptical subsurface stress); as a sphere it has the
radius R_e = (3 K_c/(4 E*))^2 and the cap p_y = 2 E* sqrt(delta_y/R_e)/pi.  This is not an
approximation of Thornton's construction applied to the ellipse itself, but the same law:
(i) the elastic branch is Eq. (1); (ii) it yields at the ellipse's F_y; (iii) the elliptical Hertz
pressure truncated at the ellipse's p0(F_y) on the Hertz ellipse (semi-axes a b proportional to delta)
gives a force linear in delta with slope pi p0(F_y) a b/delta = 3/2 K_c sqrt(delta_y), the sphere's
pi p_y R_e; (iv) the unloading stiffness at delta_m, that of the flat elliptical punch of the Hertz
ellipse, pi E* a/K(m), equals the sphere's 2 E* sqrt(R_e delta_m) (both are the Hertz tangent
stiffness 3/2 K_c sqrt(delta_m)).  The tests check (iii) and (iv) with independent elliptic
integrals.  The geometric mean of the principal relative radii, sqrt(R' R''), would not give
Eq. (1): R_e exceeds it by 10 % at 60 degrees and 42 % at 45 degrees (R/r = 9).  At 90 degrees
R_e = R' = r(R - r)/(R - 2r) and p_y is the first-yield peak pressure; at other angles the sphere's p_y
differs from the ellipse's p0(F_y) (p_y R_e = p0(F_y) a b/delta).

In the chain the ring's bending spring K_b (paper Eq. (2)) sits in series with the contact, and for the
paper's ring it is about as stiff as the plastic branch (K_b = 3.3 MN/m; pi p_y R_e = 3.1 MN/m for annealed
304): it takes part of the approach and returns the energy it stores, so the contact is driven less far
into its plastic branch.  Two free rings from a 5 cm drop rebound with e = 0.21 on the contact alone
(:func:`restitution_coefficient`) but 0.71 with the bending spring in series (0.54 and 0.95 for
cold-drawn wire; tests/theory/test_plastic.py).

What the model leaves out: work hardening (the flattened contact of a real ring yields at a
higher pressure the next time, and cold-worked wire hardly hardens), strain-rate effects, and
the growth of the contact beyond Hertz's radius (a numerical capped-pressure contact,
:func:`ringchain.numerics.contact.bem.capped_contact_curve`, carries 1.1-2 times Thornton's
force at the same approach, the ratio growing with delta/delta_y).  Read e as a lower bound
and the plastic loss as an upper bound.

Signatures follow the package's convention (:mod:`ringchain.theory`).  The force law is evaluated at the
approach delta (first, positional); its memory delta_max and its constants K_c and delta_y are keyword-only,
the state before the law as F_0 before K in the package's order, and delta_y after K_c (it is the law's
second constant, found from K_c and the yield force).  All are positive lengths or stiffnesses, so a
swapped positional call would answer silently.  The functions of two tori take their geometry and material
R, r, E, nu, angle by position, as :func:`~ringchain.theory.hertz_stiffness` does, and the yield strength Y
keyword-only after them: Y and E are both positive pressures, and with Y between nu and angle (as it was) a
copied ``hertz_stiffness(R, r, E, nu, angle)`` passed the angle as a yield strength of about 1 Pa.  The
reduced mass m of a colliding pair follows Y (a chain parameter, keyword-only).  The numbers are evaluated
in the approaches themselves, not in delta/delta_y, and V_y through its logarithm, so that they stay within
double precision wherever the result does (``_largest``, ``_yield_speed``, ``_restitution``).

Numeric functions: :func:`thornton_loading_force`, :func:`thornton_unloading_force`,
:func:`thornton_residual_indentation`, :func:`thornton_energy`, :func:`plastic_stiffness`,
:func:`equivalent_radius`, :func:`yield_velocity`, :func:`restitution_coefficient`.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate
from ._codegen import derived, sp
from ._forms import log_monomial
from .contact import contact_modulus, hertz_stiffness
from .subsurface import first_yield

__all__ = [
    "symbols",
    "hertz_sphere",
    "truncated_force",
    "loading_force",
    "unloading_force",
    "unloading_coefficient",
    "energies",
    "impact",
    "thornton_loading_force",
    "thornton_unloading_force",
    "thornton_residual_indentation",
    "thornton_energy",
    "plastic_stiffness",
    "equivalent_radius",
    "yield_velocity",
    "restitution_coefficient",
]


@functools.cache
def symbols():
    """Symbols: approach delta, radius R_e, modulus E*, limiting pressure p_y, contact radius a and peak
    pressure p0, radius s in the contact, K_c, delta_y, x = delta/delta_y, x_m = delta_m/delta_y, reduced
    mass m, impact speed V, v = V/V_y, and u = delta - delta_p, the elastic approach on an unloading curve."""
    names = "delta R_e E^* p_y a p_0 s K_c delta_y x x_m m V v u"
    keys = "delta R_e Es p_y a p0 s K_c delta_y x x_m m V v u".split()
    return dict(zip(keys, sp.symbols(names, positive=True), strict=True))


# --- 1.-3. loading ------------------------------------------------------------------------------------


@functools.cache
def hertz_sphere():
    """(P(delta), p0(delta), a(delta)) of the sphere R_e on the half-space E* (step 1)."""
    s = symbols()
    delta, R, Es, a, p0, r = (s[k] for k in ("delta", "R_e", "Es", "a", "p0", "s"))
    load = sp.integrate(p0 * sp.sqrt(1 - r**2 / a**2) * 2 * sp.pi * r, (r, 0, a))  # 2/3 pi a^2 p0
    radius = sp.sqrt(R * delta)  # delta = a^2/R_e
    P = sp.Symbol("P", positive=True)
    (force,) = sp.solve(sp.Eq(radius**3, 3 * P * R / (4 * Es)), P)  # a^3 = 3 P R_e/(4 E*)
    (peak,) = sp.solve(sp.Eq(load.subs(a, radius), force), p0)
    return sp.simplify(force), sp.simplify(peak), radius


@functools.cache
def truncated_force():
    """(F(delta), delta_y): Thornton's loading force on the truncated Hertz pressure, delta >= delta_y (step 2)."""
    s = symbols()
    delta, p_y, r = (s[k] for k in ("delta", "p_y", "s"))
    _, peak, radius = hertz_sphere()
    (delta_y,) = sp.solve(sp.Eq(peak, p_y), delta)
    # Radius a_p inside which the Hertz pressure exceeds p_y: p0 sqrt(1 - a_p^2/a^2) = p_y.
    inner = radius * sp.sqrt(1 - p_y**2 / peak**2)
    capped = sp.integrate(p_y * 2 * sp.pi * r, (r, 0, inner))
    t = sp.Symbol("t", positive=True)  # t = a^2 - s^2 in the elastic ring a_p < s < a
    elastic = sp.integrate(peak * sp.sqrt(t) / radius * sp.pi, (t, 0, radius**2 - inner**2))
    F = sp.expand(sp.simplify(capped + elastic))
    if sp.diff(F, delta, 2) != 0:  # pragma: no cover - derivation check
        raise RuntimeError(f"Thornton's loading force is not linear in delta: {F}")
    return F, delta_y


def _in_contact_constants(expr):
    """``expr`` with R_e = (3 K_c/(4 E*))^2 and p_y from delta_y = pi^2 p_y^2 R_e/(4 E*^2); E* must cancel."""
    s = symbols()
    force, _, _ = hertz_sphere()
    _, delta_y = truncated_force()
    (R_e,) = sp.solve(sp.Eq(force / s["delta"] ** sp.Rational(3, 2), s["K_c"]), s["R_e"])
    (p_y,) = sp.solve(sp.Eq(delta_y.subs(s["R_e"], R_e), s["delta_y"]), s["p_y"])
    out = sp.simplify(expr.subs(s["p_y"], p_y.subs(s["R_e"], R_e)).subs(s["R_e"], R_e))
    if out.has(s["Es"]):  # pragma: no cover - derivation check
        raise RuntimeError(f"E* does not cancel from {out}")
    return out


@functools.cache
def loading_force():
    """(F, slope): Thornton's loading force F(x) = K_c delta_y^(3/2) (3 x - 1)/2 (x = delta/delta_y >= 1) and
    its slope dF/ddelta = pi p_y R_e, both in K_c and delta_y (step 3)."""
    s = symbols()
    F, _ = truncated_force()
    F = _in_contact_constants(F).subs(s["delta"], s["x"] * s["delta_y"])
    slope = _in_contact_constants(sp.diff(truncated_force()[0], s["delta"]))
    return sp.factor(F), sp.factor(slope)


# --- 4. unloading -----------------------------------------------------------------------------------


@functools.cache
def unloading_force():
    """(F(delta; x_m), delta_p(x_m)): elastic unloading from delta_m = x_m delta_y (step 4), in K_c and delta_y."""
    s = symbols()
    delta, R, Es, x_m = (s[k] for k in ("delta", "R_e", "Es", "x_m"))
    F_load, yield_point = truncated_force()
    D = sp.Symbol("delta_m", positive=True)  # the largest approach, in R_e, E*, p_y first
    a_m = sp.sqrt(R * D)  # Thornton keeps Hertz's contact radius
    F_m = F_load.subs(delta, D)
    R_p = sp.Symbol("R_p", positive=True)
    (radius,) = sp.solve(sp.Eq(a_m**3, 3 * F_m * R_p / (4 * Es)), R_p)
    delta_p = D - a_m**2 / radius
    F = 4 * Es / 3 * sp.sqrt(radius) * (delta - delta_p) ** sp.Rational(3, 2)
    # F_m > 0 beyond the yield point, so the powers of a_m^2/R_p may be merged.
    if sp.simplify(sp.powdenest(F.subs(delta, D), force=True) - F_m) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the unloading curve does not start at the largest load")
    # In the contact's constants, with delta_m = x_m delta_y (delta_y of the sphere, then renamed).
    at = {D: x_m * yield_point}
    F = _in_contact_constants(F.subs(at))
    delta_p = _in_contact_constants(delta_p.subs(at))
    F = sp.powsimp(sp.powdenest(F, force=True), force=True)
    return F, sp.factor(delta_p)


@functools.cache
def unloading_coefficient():
    """C(x_m) with F = C u^(3/2) on the unloading curve, u = delta - delta_p: the form the numbers use (u is
    computed as a difference of the approach and delta_p, exact where delta_p = 0; the expanded form of
    :func:`unloading_force` cancels for delta << delta_y)."""
    s = symbols()
    F, delta_p = unloading_force()
    u = s["u"]
    C = sp.simplify(sp.powdenest(F.subs(s["delta"], u + delta_p), force=True) / u ** sp.Rational(3, 2))
    if C.has(u, s["delta_y"]) or sp.simplify(C.subs(s["x_m"], 1) - s["K_c"]) != 0:  # pragma: no cover
        raise RuntimeError(f"the unloading curve is not C(x_m) u^(3/2) with C(1) = K_c: {C}")
    return C


# --- 5.-6. energies and the impact -------------------------------------------------------------------


@functools.cache
def energies():
    """(W_load(x_m), W_unload(x_m), stored(u; x_m)): work to reach delta_m, elastic energy returned
    from there to delta_p, and elastic energy stored at u = delta - delta_p on the unloading curve (step 5)."""
    s = symbols()
    delta, x, x_m, K_c, delta_y = (s[k] for k in ("delta", "x", "x_m", "K_c", "delta_y"))
    F_load, _ = loading_force()
    _, delta_p = unloading_force()
    elastic = sp.integrate(K_c * delta ** sp.Rational(3, 2), (delta, 0, delta_y))
    plastic = sp.integrate(F_load * delta_y, (x, 1, x_m))  # d delta = delta_y dx
    W_load = sp.factor(sp.simplify(elastic + plastic))
    u, t = s["u"], sp.Symbol("t", positive=True)
    stored = sp.integrate(unloading_coefficient() * t ** sp.Rational(3, 2), (t, 0, u))
    W_unload = sp.factor(sp.simplify(sp.powdenest(stored.subs(u, x_m * delta_y - delta_p), force=True)))
    return W_load, W_unload, sp.simplify(stored)


@functools.cache
def impact():
    """(V_y, x_m(v), e(v)): the yield speed and, for v = V/V_y >= 1, the largest approach and the
    coefficient of restitution of two bodies of reduced mass m (step 6)."""
    s = symbols()
    m, V, v, x_m = (s[k] for k in ("m", "V", "v", "x_m"))
    W_load, W_unload, _ = energies()
    (V_y,) = sp.solve(sp.Eq(m * V**2 / 2, W_load.subs(x_m, 1)), V)
    roots = sp.solve(sp.Eq(W_load, m * (v * V_y) ** 2 / 2), x_m)
    (largest,) = [root for root in roots if sp.simplify(root.subs(v, 1) - 1) == 0]  # the branch through x_m = 1
    e = sp.sqrt(sp.simplify(W_unload / W_load).subs(x_m, largest))
    return sp.simplify(V_y), sp.simplify(largest), sp.simplify(e)


# --- numeric functions ---------------------------------------------------------------------------------


@derived
def _loading():
    """(F, slope) beyond the yield point in the approach itself, F = K_c sqrt(delta_y) (3 delta - delta_y)/2:
    through x = delta/delta_y it needed delta_y^(3/2), which underflows for delta_y below 1e-205 m."""
    s = symbols()
    F, slope = loading_force()
    return (s["delta"], s["K_c"], s["delta_y"]), (sp.factor(F.subs(s["x"], s["delta"] / s["delta_y"])), slope)


@derived
def _largest():
    """(delta_p, w, W_load) at the largest approach delta_m > delta_y, in delta_m and delta_y themselves.

    delta_p = (sqrt(delta_m) - sqrt(delta_y))^2 (1 + sqrt(delta_y/delta_m)/2) the residual approach,
    w = delta_m - delta_p = sqrt(delta_y) (3 delta_m - delta_y)/(2 sqrt(delta_m)) and W_load the work of loading,
    each checked against steps 4-5.  In x_m = delta_m/delta_y they needed x_m^(3/2) and x_m^2 (overflowing for
    x_m beyond 1e205 and 1e154), and w came as the difference of two nearly equal approaches (all digits lost
    for x_m beyond 1e32).  The numbers use, besides, that with F_m the loading force at delta_m (:func:`_loading`)
    the unloading curve is F = F_m (u/w)^(3/2) (it passes through (delta_m, F_m), checked) and returns
    W_unload = 2/5 F_m w (checked).
    """
    s = symbols()
    D, dy, K_c = sp.Symbol("delta_m", positive=True), s["delta_y"], s["K_c"]
    at = {s["x_m"]: D / dy}
    F_m = sp.factor(loading_force()[0].subs(s["x"], D / dy))
    _, delta_p = unloading_force()
    W_load, W_unload, _ = energies()
    root_m, root_y = sp.sqrt(D), sp.sqrt(dy)
    residual = (root_m - root_y) ** 2 * (1 + root_y / (2 * root_m))
    span = root_y * (3 * D - dy) / (2 * root_m)
    checks = [
        (residual, delta_p.subs(at)),
        (span, D - delta_p.subs(at)),
        (unloading_coefficient().subs(at) * span ** sp.Rational(3, 2), F_m),
        (sp.Rational(2, 5) * F_m * span, W_unload.subs(at)),
    ]
    for stable, exact in checks:
        if sp.simplify(sp.powdenest(stable - exact, force=True)) != 0:  # pragma: no cover - derivation check
            raise RuntimeError(f"{stable} is not {exact}")
    return (D, K_c, dy), (residual, span, sp.factor(W_load.subs(at)))


@derived
def _yield_speed():
    """ln V_y: V_y is a monomial in K_c, delta_y and m, evaluated as the exponential of its logarithm (its
    delta_y^(5/4) underflows where V_y does not)."""
    s = symbols()
    V_y, _, _ = impact()
    logs = {name: sp.Symbol(f"log_{name}", real=True) for name in ("K_c", "delta_y", "m")}
    logarithm = log_monomial(V_y).subs({sp.log(s[name]): log for name, log in logs.items()})
    if logarithm.has(*(s[name] for name in logs)):  # pragma: no cover - derivation check
        raise RuntimeError(f"V_y = {V_y} is not a monomial of K_c, delta_y and m")
    return tuple(logs.values()), logarithm


@derived
def _restitution():
    """e(v) for v = V/V_y >= 1 written without v^2: e = sqrt(6/5 (1 - 1/(6 v^2))) x_m^(-1/4),
    x_m = (1 + 2 v sqrt((6 - 1/v^2)/5))/3 (checked against step 6); 6 v^2 - 1 overflowed for v beyond 1e154."""
    s = symbols()
    v = s["v"]
    _, _, e = impact()
    x_m = (1 + 2 * v * sp.sqrt((6 - 1 / v**2) / 5)) / 3
    stable = sp.sqrt(sp.Rational(6, 5) * (1 - 1 / (6 * v**2))) / x_m ** sp.Rational(1, 4)
    if sp.simplify(stable**4 - e**4) != 0:  # both positive: equal fourth powers  # pragma: no cover
        raise RuntimeError(f"{stable} is not Thornton's e = {e}")
    return (v,), stable


def _law(K_c, delta_y, **arrays):
    K_c = _validate.positive("K_c", K_c, "N/m^1.5")
    delta_y = _validate.positive("delta_y", delta_y, "m")
    _validate.broadcast_shape(K_c=K_c, delta_y=delta_y, **arrays)
    return K_c, delta_y


def _hertz(K_c, delta):
    """K_c delta^(3/2), zero for delta <= 0."""
    return K_c * np.maximum(delta, 0.0) ** 1.5


def _memory(delta, delta_max, K_c, delta_y):
    """Thornton's law with memory at the approach delta: (F, u, plastic, F_m, span, W_load).

    delta_m = max(delta_y, delta, delta_max) (the memory, with the current approach counted); ``plastic`` where
    delta_m > delta_y; u = delta - delta_p the elastic approach on the current curve (w exactly at delta_m, delta
    on the Hertz curve); F = F_m (u/w)^(3/2) there, K_c delta^(3/2) on the Hertz curve, zero where u <= 0.
    """
    delta_m = np.maximum(np.maximum(delta, delta_max), delta_y)
    plastic = delta_m > delta_y
    F_m, _ = _loading(delta_m, K_c, delta_y)
    delta_p, span, W_load = (np.asarray(x, dtype=float) for x in _largest(delta_m, K_c, delta_y))
    u = np.where(plastic, np.where(delta >= delta_m, span, delta - delta_p), delta)
    ratio = np.maximum(u, 0.0) / span
    F = np.where(plastic, F_m * ratio**1.5, _hertz(K_c, delta))
    return F, u, plastic, F_m, span, W_load


def thornton_loading_force(delta, *, K_c, delta_y):
    """Force of Thornton's elastic-perfectly plastic contact on first loading, N.

    Parameters
    ----------
    delta : array_like
        Approach (extension of the interlocked contact), m; no force for delta <= 0.
    K_c : array_like
        Hertz constant of the contact, N/m^1.5 (paper Eq. (1); :func:`~ringchain.theory.hertz_stiffness`).
    delta_y : array_like
        Approach at first yield, m (:attr:`~ringchain.theory.FirstYield.indentation`).

    Returns
    -------
    ndarray
        K_c delta^(3/2) up to delta_y; beyond it K_c delta_y^(3/2) (3 delta/delta_y - 1)/2, a straight line of
        slope pi p_y R_e = 3/2 K_c sqrt(delta_y) (:func:`plastic_stiffness`).

    Notes
    -----
    Steps 2-3 of the module docstring (Thornton 1997): the Hertz pressure capped at p_y, on Hertz's
    contact radius.

    Examples
    --------
    >>> [float(f) for f in thornton_loading_force([0.5, 1.0, 2.0], K_c=1.0, delta_y=1.0)]
    [0.3535533905932738, 1.0, 2.5]
    """
    delta = _validate.as_float("delta", delta)
    K_c, delta_y = _law(K_c, delta_y, delta=delta)
    with np.errstate(all="ignore"):
        F_plastic, _ = _loading(np.maximum(delta, delta_y), K_c, delta_y)
        F = np.where(delta > delta_y, F_plastic, _hertz(K_c, delta))
    return _validate.finite_result(F, "the contact force", "approach and contact constants")


def thornton_unloading_force(delta, *, delta_max, K_c, delta_y):
    """Force of Thornton's contact with memory: unloading and reloading below the largest approach delta_max, N.

    Parameters
    ----------
    delta : array_like
        Approach, m.
    delta_max : array_like
        Largest approach the contact has reached so far, m, >= 0.
    K_c, delta_y : array_like
        As :func:`thornton_loading_force` (N/m^1.5, m).

    Returns
    -------
    ndarray
        For x_m = max(1, delta/delta_y, delta_max/delta_y): the Hertz curve of the flattened tip,
        F_m ((delta - delta_p)/(delta_m - delta_p))^(3/2) with delta_m = x_m delta_y, F_m the loading force
        there and delta_p :func:`thornton_residual_indentation`; zero for delta <= delta_p.  At and beyond
        delta_max it is the loading force, and while delta_max <= delta_y the Hertz force: this is the
        whole law, with delta_max its one internal variable.

    Notes
    -----
    Step 4 of the module docstring.  The current approach counts in the memory (x_m uses
    max(delta, delta_max)), so a trial step beyond delta_max is already on the loading curve; the
    caller updates delta_max = max(delta_max, delta) on accepted steps only.

    Examples
    --------
    >>> [round(float(f), 4) for f in thornton_unloading_force([0.5, 1.0, 3.0], delta_max=3.0, K_c=1.0, delta_y=1.0)]
    [0.0, 0.1962, 4.0]
    """
    delta = _validate.as_float("delta", delta)
    delta_max = _validate.nonnegative("delta_max", delta_max, "m")
    K_c, delta_y = _law(K_c, delta_y, delta=delta, delta_max=delta_max)
    with np.errstate(all="ignore"):
        F, *_ = _memory(delta, delta_max, K_c, delta_y)
    return _validate.finite_result(F, "the contact force", "approach and contact constants")


def thornton_residual_indentation(delta_max, *, delta_y):
    """Approach delta_p at which a contact unloaded from delta_max opens (the permanent flattening), m.

    Parameters
    ----------
    delta_max : array_like
        Largest approach reached, m, >= 0.
    delta_y : array_like
        Approach at first yield, m.

    Returns
    -------
    ndarray
        delta_p = delta_max - delta_y (3 x_m - 1)/(2 sqrt(x_m)), x_m = delta_max/delta_y; 0 while
        delta_max <= delta_y (step 4 of the module docstring).

    Examples
    --------
    >>> float(thornton_residual_indentation(4.0, delta_y=1.0))  # 4 - 11/4
    1.25
    """
    delta_max = _validate.nonnegative("delta_max", delta_max, "m")
    delta_y = _validate.positive("delta_y", delta_y, "m")
    _validate.broadcast_shape(delta_max=delta_max, delta_y=delta_y)
    with np.errstate(all="ignore"):
        delta_m = np.maximum(delta_max, delta_y)
        delta_p, _, _ = _largest(delta_m, 1.0, delta_y)
        delta_p = np.where(delta_m > delta_y, delta_p, 0.0)
    return _validate.finite_result(delta_p, "the residual approach", "approaches")


def thornton_energy(delta, *, delta_max, K_c, delta_y):
    """Elastic energy stored in Thornton's contact and the plastic work done on it so far, J.

    Parameters
    ----------
    delta, delta_max, K_c, delta_y : array_like
        As :func:`thornton_unloading_force` (m, m, N/m^1.5, m).

    Returns
    -------
    stored : ndarray
        Elastic energy at delta on the current (unloading or loading) curve: the integral of the force
        from delta_p to delta, J; zero when the contact is open.
    dissipated : ndarray
        Plastic work W_load(x_m) - W_unload(x_m) for x_m = max(1, delta/delta_y, delta_max/delta_y), J:
        zero until the contact first yields.

    Notes
    -----
    Step 5 of the module docstring.  The force is -d(stored)/d(separation) on every curve, and along
    any history stored + dissipated is the work done on the contact, so a chain's energy budget
    closes with kinetic + stored + dissipated.

    Examples
    --------
    >>> [round(float(w), 4) for w in thornton_energy(3.0, delta_max=3.0, K_c=1.0, delta_y=1.0)]
    [3.695, 1.705]
    """
    delta = _validate.as_float("delta", delta)
    delta_max = _validate.nonnegative("delta_max", delta_max, "m")
    K_c, delta_y = _law(K_c, delta_y, delta=delta, delta_max=delta_max)
    with np.errstate(all="ignore"):
        F, u, plastic, F_m, span, W_load = _memory(delta, delta_max, K_c, delta_y)
        stored = 0.4 * F * np.maximum(u, 0.0)  # the integral of C t^(3/2) from 0 to u: 2/5 F u
        dissipated = np.where(plastic, W_load - 0.4 * F_m * span, 0.0)  # W_load - W_unload
    what = "the contact energy", "approach and contact constants"
    return _validate.finite_result(stored, *what), _validate.finite_result(dissipated, *what)


def _contact(R, r, E, nu, Y, angle):
    """(K_c, delta_y) of the torus contact (validated), delta_y refused below the normal doubles.

    A subnormal delta_y keeps a few digits or none (it is 0 below 5e-324), and every quantity built on it would
    carry that error silently: zero, or an infinite v/V_y.
    """
    y = first_yield(R, r, E, nu, angle, Y=Y)
    delta_y = np.asarray(y.indentation, dtype=float)
    if delta_y.size and not np.min(delta_y) >= np.finfo(float).tiny:
        raise ValueError(
            f"the approach at first yield, delta_y = {_validate.show(np.min(delta_y))} m, lies below the normal range "
            "of double precision for these radii, elastic constants and yield strength; they lie far outside any "
            "physical range"
        )
    return hertz_stiffness(R, r, E, nu, angle), delta_y


def plastic_stiffness(R, r, E, nu, angle=np.pi / 2, *, Y):
    """Slope of Thornton's loading line, pi p_y R_e = 3/2 K_c sqrt(delta_y), N/m.

    Parameters
    ----------
    R, r : array_like
        Major and tube radius of the tori, m (R > 2 r).
    E, nu : array_like
        Young's modulus (Pa) and Poisson's ratio.
    angle : array_like, optional
        Contact angle between the ring planes, rad; default pi/2.
    Y : array_like
        Yield strength, Pa.

    Returns
    -------
    ndarray
        dF/ddelta of the plastic contact, N/m: to be compared with the ring's bending stiffness K_b
        (paper Eq. (2)), in series with it.

    Examples
    --------
    >>> round(float(plastic_stiffness(22.5e-3, 2.5e-3, 193e9, 0.29, Y=215e6)) / 1e6, 3)  # MN/m
    3.089
    """
    K_c, delta_y = _contact(R, r, E, nu, Y, angle)
    with np.errstate(all="ignore"):
        _, slope = _loading(delta_y, K_c, delta_y)
    return _validate.finite_result(slope, "the plastic stiffness", "radii, elastic constants and yield strength")


def equivalent_radius(R, r, angle=np.pi / 2):
    """Radius R_e of the sphere whose Hertz law is the tori's, R_e = (3 K_c/(4 E*))^2, m.

    Parameters
    ----------
    R, r : array_like
        Major and tube radius of the tori, m (R > 2 r).
    angle : array_like, optional
        Contact angle between the ring planes, rad; default pi/2.

    Returns
    -------
    ndarray
        R_e in m: r(R - r)/(R - 2r) at 90 degrees (App. A), larger than the geometric mean
        sqrt(R' R'') of the principal relative radii at other angles (module docstring).

    Examples
    --------
    >>> round(float(equivalent_radius(22.5e-3, 2.5e-3)) * 1e3, 4)  # mm: 2.5 x 20/17.5
    2.8571
    """
    with np.errstate(all="ignore"):
        ratio = hertz_stiffness(R, r, 1.0, 0.0, angle) / contact_modulus(1.0, 0.0)  # K_c/E*: geometry only
        R_e = (0.75 * ratio) ** 2
    return _validate.finite_result(R_e, "the equivalent radius", "radii")


def yield_velocity(R, r, E, nu, angle=np.pi / 2, *, Y, m):
    """Relative impact speed at which the contact of two colliding rings just yields, m/s.

    Parameters
    ----------
    R, r : array_like
        Major and tube radius of the tori, m (R > 2 r).
    E, nu : array_like
        Young's modulus (Pa) and Poisson's ratio.
    angle : array_like, optional
        Contact angle between the ring planes, rad; default pi/2.
    Y : array_like
        Yield strength, Pa.
    m : array_like
        Reduced mass of the pair, kg (m0/2 for two equal free rings of mass m0).

    Returns
    -------
    ndarray
        V_y = sqrt(4 F_y delta_y/(5 m)): the kinetic energy m V_y^2/2 equals the elastic Hertz energy
        2/5 F_y delta_y stored up to the yield force (step 6 of the module docstring).

    Examples
    --------
    >>> m = 8000.0 * 2 * np.pi**2 * 22.5e-3 * 2.5e-3**2 / 2  # two of the paper's rings
    >>> round(float(yield_velocity(22.5e-3, 2.5e-3, 193e9, 0.29, Y=215e6, m=m)) * 1e3, 3)  # mm/s
    0.916
    """
    m = _validate.positive("m", m, "kg")
    K_c, delta_y = _contact(R, r, E, nu, Y, angle)
    _validate.broadcast_shape(m=m, K_c=K_c)
    with np.errstate(all="ignore"):
        V_y = np.exp(_yield_speed(np.log(K_c), np.log(delta_y), np.log(m)))
    return _validate.finite_result(V_y, "the yield speed", "radii, elastic constants, yield strength and mass")


def restitution_coefficient(v, R, r, E, nu, angle=np.pi / 2, *, Y, m):
    """Coefficient of restitution of two rings colliding at relative speed v with Thornton's contact.

    Parameters
    ----------
    v : array_like
        Relative speed of approach, m/s, >= 0.
    R, r : array_like
        Major and tube radius of the tori, m (R > 2 r).
    E, nu : array_like
        Young's modulus (Pa) and Poisson's ratio.
    angle : array_like, optional
        Contact angle between the ring planes, rad; default pi/2.
    Y : array_like
        Yield strength, Pa.
    m : array_like
        Reduced mass of the pair, kg.

    Returns
    -------
    ndarray
        e = separation speed over approach speed: 1 up to :func:`yield_velocity`, then Thornton's
        e(V/V_y) (step 6 of the module docstring), about 1.2 (V/V_y)^(-1/4) at high speed.

    Notes
    -----
    The rings are rigid bodies here: the contact alone absorbs the energy.  A lower bound of e
    (an upper bound of the plastic loss): no work hardening, Hertz's contact radius.

    Examples
    --------
    >>> m = 8000.0 * 2 * np.pi**2 * 22.5e-3 * 2.5e-3**2 / 2
    >>> v0 = np.sqrt(2 * 9.80665 * 0.05)  # a 5 cm drop
    >>> round(float(restitution_coefficient(v0, 22.5e-3, 2.5e-3, 193e9, 0.29, Y=215e6, m=m)), 3)
    0.207
    """
    speed = _validate.nonnegative("v", v, "m/s")
    m = _validate.positive("m", m, "kg")
    K_c, delta_y = _contact(R, r, E, nu, Y, angle)
    _validate.broadcast_shape(v=speed, m=m, K_c=K_c)
    with np.errstate(all="ignore"):
        V_y = np.exp(_yield_speed(np.log(K_c), np.log(delta_y), np.log(m)))
        ratio = np.where(speed > 0, speed / V_y, 0.0)
    if not np.all(ratio < np.inf):
        raise ValueError(
            "the speed in units of the yield speed V_y (v/V_y) is beyond double precision for these speed, radii, "
            f"elastic constants, yield strength and mass (V_y = {_validate.show(np.min(V_y))} m/s); they lie far "
            "outside any physical range"
        )
    with np.errstate(all="ignore"):
        e = np.where(ratio > 1.0, _restitution(np.maximum(ratio, 1.0)), 1.0)
    return _validate.finite_result(e, "the coefficient of restitution", "speed, radii, elastic constants and mass")
