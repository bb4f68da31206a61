r"""Linear waves of a chain under static tension: dispersion, band edges, sound speed, travel time under gravity.

Small motions about a static state in which every bond carries the same force F_0
(beyond the paper, which treats the strongly nonlinear pulse only).  Each contact
then acts as a linear spring of stiffness k_c = dF/d delta at F_0; the bending spring
of the dual-spring ring is linear anyway.  Step by step:

1. :func:`contact_stiffness` -- k_c(F_0) = n K^(1/n) F_0^((n-1)/n): the slope
   :func:`.longwave.linear_contact_stiffness` at the static extension
   :func:`.longwave.static_extension`.  It vanishes at F_0 = 0 for n > 1 (the sonic
   vacuum) and grows with the load: tension makes the chain stiffer.
2. :func:`power_law_dispersion` -- the power-law chain (Eq. (7)), one branch
   omega^2 = 4 k_c/m sin^2(q a/2).  Not derived again here: it is
   :func:`.longwave.lattice_dispersion` divided by its contact stiffness (a check that
   the stiffness is the only trace of the force law) times k_c.
3. :func:`dual_spring_matrix` -- the dual-spring chain (Eqs. (5)-(6)) linearised about
   the static state: two sites of mass m/2 per ring (lower and upper half, the site
   labelling of :mod:`ringchain.numerics.layouts.chain`), joined alternately by the ring's
   bending spring K_b and by the contact, whose force law enters only through its
   slope k_c.  A Bloch wave (amplitudes A, B on the two halves, phase exp(i q a) from
   one ring to the next) turns the equations of motion into the 2 x 2 Hermitian
   matrix D(q) with D (A, B) = omega^2 (A, B).
4. :func:`dual_spring_branches` -- the two eigenvalues of D(q) from its trace and
   determinant: omega^2 = [T -+ sqrt(T^2 - 4 Delta)]/2 with T = 4(k_c + K_b)/m and
   Delta = 16 k_c K_b sin^2(q a/2)/m^2.  The root that vanishes as q -> 0 is the
   acoustic branch, the other the optical one.  For the numbers the discriminant is
   written (k_c - K_b)^2 + 4 k_c K_b cos^2(q a/2), never negative, and the acoustic root
   Delta/omega_optical^2 (Vieta), which keeps its digits as q -> 0 where the
   difference form cancels.
5. :func:`band_edges_symbolic` -- the edges of the bands.  At q = pi/a (adjacent rings
   in antiphase) the two modes decouple: one stretches only the contacts, at
   2 sqrt(k_c/m), the other only the ring bodies, at 2 sqrt(K_b/m); the smaller is the
   top of the acoustic band, the larger the bottom of the optical band.  At q = 0 the
   optical mode (the two halves of every ring against each other, all rings in phase)
   has the top frequency 2 sqrt((k_c + K_b)/m).
6. :func:`dual_spring_sound_speed` -- lim omega_acoustic/q = a sqrt(k/m) with
   k = k_c K_b/(k_c + K_b), the tangent stiffness of contact and bending in series
   (Eq. (3)); the power-law chain's is :func:`.longwave.sound_speed_from_force`.
7. :func:`linear_travel_time` -- in the hanging chain contact k carries the weight of
   the k + 1 rings below it, so the sound speed grows up the chain; a small
   long-wave pulse crosses cell k in a/c(F_k), and the time between two rings is the
   sum over the cells between them (the WKB, or ray, approximation: the speed
   changes slowly on the scale of the pulse).

8. :func:`junction_symbolic` -- two chains joined end to end.  In the long-wave limit
   each chain is a string of mass m/a per length and axial stiffness k a, whose
   waves travel at the :func:`sound_speed` c = a sqrt(k/m); its impedance (force over
   velocity of a travelling wave) is Z = m c/a = sqrt(m k) (:func:`impedance`).  A wave
   arriving from chain 1 at the junction keeps the displacement and the force
   continuous there; solving these two conditions gives the reflected and transmitted
   force amplitudes R = (Z2 - Z1)/(Z1 + Z2) and T = 2 Z2/(Z1 + Z2)
   (:func:`junction_coefficients`), with R^2 + (Z1/Z2) T^2 = 1 (energy).  A pulse going
   into a stiffer or heavier chain (Z2 > Z1) is reflected with the same sign and
   transmitted stronger in force; into a softer one, reflected inverted (a drop of
   tension) and transmitted weaker.

Which frequency rings behind a pulse?  A disturbance at a fixed ring is left, long
after the front has passed, with the frequencies whose group velocity d omega/dq is
zero: the band edges.  The edge 2 sqrt(K_b/m) -- each ring's two halves swinging
against each other on its bending spring while the contacts hold still -- is the
same at every static force: it is the top of the acoustic band while the contacts are
stiffer than the ring bodies (k_c > K_b) and the bottom of the optical band when they
are softer, down to slack contacts (F_0 -> 0), where the optical band shrinks onto it
(every ring an isolated oscillator, group velocity zero for every q).  That is the
frequency of the trailing oscillations of the dual-spring chain behind a strong pulse,
after which the contacts are slack: in the paper's 20-ring chain the tail's strongest
line lies 0.2-1.4 % above it after drops of 0.2-0.5 m and 5 % above after 50 mm, lifted
by the contacts' brief re-engagements; after small drops (a few mm) the contacts stay
taut and the tail is not at an edge (tests/numerics/layouts/test_linear_waves.py; book chapter
"Linear waves and what the pulse carries").

Numeric functions: :func:`dispersion`, :func:`band_edges`, :func:`sound_speed`,
:func:`linear_travel_time`.
"""

from __future__ import annotations

import functools
from typing import NamedTuple

import numpy as np

from . import _validate as v
from . import longwave
from ._codegen import derived, sp
from .longwave import linear_sound_speed

__all__ = [
    "MODELS",
    "STANDARD_GRAVITY",
    "symbols",
    "contact_stiffness",
    "power_law_dispersion",
    "dual_spring_matrix",
    "dual_spring_branches",
    "band_edges_symbolic",
    "dual_spring_sound_speed",
    "BandEdges",
    "dispersion",
    "band_edges",
    "sound_speed",
    "linear_travel_time",
    "junction_symbolic",
    "impedance",
    "junction_coefficients",
    "free_fall_symbolic",
    "impact_speed",
]

#: The two lattice models of paper Sec. III.B, by the names :mod:`ringchain.numerics` uses.
MODELS = ("power-law", "dual-spring")

#: Standard acceleration of gravity, m/s^2 (CGPM 1901, exact by definition).
STANDARD_GRAVITY = 9.80665


@functools.cache
def symbols():
    """Symbols of :mod:`.longwave` plus K_b (bending stiffness, N/m) and k_c (contact stiffness at F_0, N/m)."""
    s = dict(longwave.symbols())
    s.update(K_b=sp.Symbol("K_b", positive=True), k_c=sp.Symbol("k_c", positive=True))
    return s


def _square_roots_simplified(expr):
    """expr with the argument of every square root expanded and factored (sqrt((x + y)^2) -> x + y, or |x - y|)."""
    return sp.simplify(
        expr.replace(lambda e: e.is_Pow and e.exp == sp.S.Half, lambda e: sp.sqrt(sp.factor(sp.expand(e.base))))
    )


def _merge_powers(expr):
    """Powers of positive bases merged (K^(1/n) F_0^(...) rather than nested powers)."""
    return sp.powsimp(sp.powdenest(sp.expand_power_base(expr, force=True), force=True), force=True)


# --- 1.-2. the contact spring and the power-law chain ----------------------------------------------


@functools.cache
def contact_stiffness():
    """k_c(F_0) = n K^(1/n) F_0^((n-1)/n), N/m: dF/d delta of F = K delta^n where F = F_0."""
    s = symbols()
    return _merge_powers(longwave.linear_contact_stiffness().subs(s["delta_0"], longwave.static_extension()))


@functools.cache
def power_law_dispersion():
    """omega^2(q) = 4 k_c/m sin^2(q a/2) of the power-law chain, in terms of its contact stiffness k_c.

    :func:`.longwave.lattice_dispersion` (derived there from the lattice, Eq. (7)) over
    :func:`.longwave.linear_contact_stiffness`; the ratio must be free of the static
    extension, so that the force law enters only through k_c.
    """
    s = symbols()
    per_stiffness = sp.simplify(longwave.lattice_dispersion() / longwave.linear_contact_stiffness())
    if per_stiffness.has(s["delta_0"]):  # pragma: no cover - derivation check
        raise RuntimeError("the power-law dispersion depends on more than the contact stiffness")
    return s["k_c"] * per_stiffness


# --- 3.-6. the dual-spring chain ----------------------------------------------------------------------


@functools.cache
def dual_spring_matrix():
    """D(q): the dual-spring chain linearised about a uniform static force, D (A, B) = omega^2 (A, B).

    Sites: lower half L_j and upper half U_j of ring j, mass m/2 each; the bending spring
    K_b joins L_j to U_j, the contact F_c joins U_j to L_{j+1} (tension positive).  With
    static extensions e_b, e_c and the Bloch wave L_j = j (e_b + e_c) + epsilon A
    exp(i q a j), U_j = L_j + e_b + epsilon (B - A) exp(i q a j), the accelerations of
    L_0 and U_0 to first order in epsilon are -D (A, B); F_c'(e_c) is written k_c.
    """
    s = symbols()
    q, a, m, K_b, k_c = s["q"], s["a"], s["m"], s["K_b"], s["k_c"]
    eps = sp.Symbol("epsilon", positive=True)
    e_c, e_b = sp.symbols("e_c e_b", positive=True)
    A, B = sp.symbols("A B")
    F_c = sp.Function("F_c")  # the contact law, any; only its slope at e_c survives

    def lower(j):
        return j * (e_b + e_c) + eps * A * sp.exp(sp.I * q * a * j)

    def upper(j):
        return j * (e_b + e_c) + e_b + eps * B * sp.exp(sp.I * q * a * j)

    def bending(extension):
        return K_b * extension

    acceleration_lower = (bending(upper(0) - lower(0)) - F_c(lower(0) - upper(-1))) / (m / 2)
    acceleration_upper = (F_c(lower(1) - upper(0)) - bending(upper(0) - lower(0))) / (m / 2)
    linear = [sp.diff(acc, eps).subs(eps, 0).doit() for acc in (acceleration_lower, acceleration_upper)]
    linear = [expr.subs(sp.Derivative(F_c(e_c), e_c), k_c) for expr in linear]
    matrix = -sp.Matrix(linear).jacobian([A, B])
    if matrix.has(eps, e_b) or matrix.has(F_c):  # pragma: no cover - derivation check
        raise RuntimeError("the linearised dual-spring chain depends on its static state beyond k_c")
    return matrix.applyfunc(sp.expand)


def _to_half_angle(expr):
    """cos(q a) -> 1 - 2 sin^2(q a/2) after rewriting exponentials as cosines."""
    s = symbols()
    qa = s["q"] * s["a"]
    return sp.expand(sp.expand(expr.rewrite(sp.cos)).subs(sp.cos(qa), 1 - 2 * sp.sin(qa / 2) ** 2))


@functools.cache
def dual_spring_branches():
    """(omega_acoustic^2, omega_optical^2) of the dual-spring chain, in terms of k_c and K_b.

    The eigenvalues of :func:`dual_spring_matrix`, roots of W^2 - T W + Delta = 0 with
    T = trace, Delta = determinant.  The acoustic root (the one that vanishes at q = 0)
    is returned as Delta/omega_optical^2, the optical root with its discriminant
    written as (k_c - K_b)^2 + 4 k_c K_b cos^2(q a/2) (see the module docstring).
    """
    s = symbols()
    q, k_c, K_b = s["q"], s["k_c"], s["K_b"]
    matrix = dual_spring_matrix()
    trace = sp.simplify(matrix.trace())
    determinant = sp.factor(_to_half_angle(matrix.det()))
    if determinant.has(sp.I) or trace.has(q):  # pragma: no cover - derivation check
        raise RuntimeError("the dual-spring matrix is not Hermitian with a q-free trace")
    W, T, Delta = sp.symbols("W T Delta", positive=True)
    roots = sp.solve(W**2 - T * W + Delta, W)
    # Delta = 0 exactly at q = 0 (Delta ~ sin^2(q a/2)): the acoustic root is the one that vanishes there.
    acoustic = next(root for root in roots if sp.simplify(root.subs(Delta, 0)) == 0)
    optical = next(root for root in roots if root != acoustic)
    values = {T: trace, Delta: determinant}
    # The discriminant T^2 - 4 Delta as scale^2 [(k_c - K_b)^2 + rest], rest a square of a cosine.
    discriminant = sp.expand(trace**2 - 4 * determinant)
    scale = trace / (k_c + K_b)  # 4/m
    rest = sp.factor(sp.trigsimp(sp.expand(discriminant / scale**2 - (k_c - K_b) ** 2)))
    stable = scale**2 * sp.Add((k_c - K_b) ** 2, rest, evaluate=False)
    if sp.simplify(stable - discriminant) != 0 or not rest.has(sp.cos):  # pragma: no cover - derivation check
        raise RuntimeError("the discriminant is not (k_c - K_b)^2 + 4 k_c K_b cos^2(q a/2)")
    optical_value = (trace + scale * sp.sqrt(stable / scale**2)) / 2
    if sp.simplify(optical_value - optical.subs(values)) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the optical root was rewritten wrongly")
    acoustic_value = determinant / optical_value
    if sp.simplify(acoustic.subs(values) * optical.subs(values) - determinant) != 0:  # pragma: no cover
        raise RuntimeError("the product of the roots is not the determinant")
    return acoustic_value, optical_value


@functools.cache
def band_edges_symbolic():
    """dict of omega^2 at the band edges: acoustic_top, optical_bottom (q = pi/a) and optical_top (q = 0).

    Dual-spring chain, from :func:`dual_spring_branches`; with real k_c and K_b the
    square root of (k_c - K_b)^2 is |k_c - K_b|, so the two q = pi/a values are
    4 min(k_c, K_b)/m and 4 max(k_c, K_b)/m.
    """
    s = symbols()
    q, a = s["q"], s["a"]
    acoustic, optical = dual_spring_branches()
    return dict(
        acoustic_top=_square_roots_simplified(acoustic.subs(q, sp.pi / a)),
        optical_bottom=_square_roots_simplified(optical.subs(q, sp.pi / a)),
        optical_top=_square_roots_simplified(optical.subs(q, 0)),
    )


@functools.cache
def dual_spring_sound_speed():
    """c = lim_{q -> 0} omega_acoustic/q = a sqrt(k_c K_b/(m (k_c + K_b))), m/s."""
    s = symbols()
    acoustic, _ = dual_spring_branches()
    return _square_roots_simplified(sp.limit(sp.sqrt(acoustic) / s["q"], s["q"], 0))


@functools.cache
def junction_symbolic():
    """(R, T): reflected and transmitted force over incident force at the junction of two chains.

    Step 8 of the module docstring.  Chain i is, at long wavelengths, a string with wave
    speed c_i and impedance Z_i (axial stiffness per length Z_i c_i).  With the junction at
    x = 0, a harmonic incident wave exp(i w (t - x/c1)), the reflected one
    r exp(i w (t + x/c1)) and the transmitted one t exp(i w (t - x/c2)) of displacement,
    continuity of displacement and of force (Z c du/dx) fixes r and t; the force amplitudes
    are -i w Z1, i w Z1 r and -i w Z2 t.  Returns expressions in ``Z_1``, ``Z_2``.
    """
    Z1, Z2, c1, c2, w = sp.symbols("Z_1 Z_2 c_1 c_2 omega", positive=True)
    r, t, x, time = sp.symbols("r t x time")
    u1 = sp.exp(sp.I * w * (time - x / c1)) + r * sp.exp(sp.I * w * (time + x / c1))
    u2 = t * sp.exp(sp.I * w * (time - x / c2))
    force1, force2 = Z1 * c1 * sp.diff(u1, x), Z2 * c2 * sp.diff(u2, x)
    conditions = [(u1 - u2).subs(x, 0), (force1 - force2).subs(x, 0)]
    solution = sp.solve(conditions, [r, t], dict=True)[0]
    incident = -sp.I * w * Z1
    reflected = sp.I * w * Z1 * solution[r]
    transmitted = -sp.I * w * Z2 * solution[t]
    return sp.factor(sp.simplify(reflected / incident)), sp.factor(sp.simplify(transmitted / incident))


def _at_force(expr):
    """expr with k_c = :func:`contact_stiffness` (the static force F_0 as the variable)."""
    s = symbols()
    return expr.subs(s["k_c"], contact_stiffness())


# --- numeric functions --------------------------------------------------------------------------------


def _arguments(with_q=True, with_a=True, with_K_b=True):
    s = symbols()
    names = ["q"] * with_q + ["F_0", "K", "n", "m"] + ["a"] * with_a + ["K_b"] * with_K_b
    return tuple(s[name] for name in names)


@derived
def _power_law_branch():
    return _arguments(with_K_b=False), sp.sqrt(_at_force(power_law_dispersion()))


@derived
def _acoustic_branch():
    return _arguments(), sp.sqrt(_at_force(dual_spring_branches()[0]))


@derived
def _optical_branch():
    return _arguments(), sp.sqrt(_at_force(dual_spring_branches()[1]))


@derived
def _dual_spring_edges():
    edges = band_edges_symbolic()
    values = [sp.sqrt(_at_force(edges[key])) for key in ("acoustic_top", "optical_bottom", "optical_top")]
    return _arguments(with_q=False, with_a=False), sp.Tuple(*values)


@derived
def _power_law_top():
    s = symbols()
    top = power_law_dispersion().subs(s["q"], sp.pi / s["a"])
    return _arguments(with_q=False, with_a=False, with_K_b=False), sp.sqrt(_at_force(top))


@derived
def _dual_spring_speed():
    return _arguments(with_q=False), _at_force(dual_spring_sound_speed())


_CHAIN = "static force and chain parameters (F_0, K, n, m, a, K_b)"


def _model(model, K_b):
    if model not in MODELS:
        raise ValueError(f"model must be one of {MODELS}, got {model!r}")
    if model == "dual-spring":
        if K_b is None:
            raise ValueError("the dual-spring model needs the bending stiffness K_b (N/m)")
        return v.positive("K_b", K_b, "N/m")
    if K_b is not None:
        raise ValueError("K_b belongs to the dual-spring model, not the power-law one")
    return None


def _static_chain(F_0, K, n, m):
    F_0 = v.nonnegative("F_0", F_0, "N")
    K = v.positive("K", K, "N/m^n")
    n = v.positive("n", n)
    m = v.positive("m", m, "kg")
    if np.any((F_0 == 0) & (n < 1)):
        raise ValueError("F_0 = 0 with n < 1 gives an infinitely stiff contact; give F_0 > 0 (N)")
    return F_0, K, n, m


class BandEdges(NamedTuple):
    """Angular frequencies at the edges of the pass bands, rad/s (see :func:`band_edges`)."""

    acoustic_top: np.ndarray
    optical_bottom: np.ndarray
    optical_top: np.ndarray


def dispersion(q, *, model, F_0, K, n, m, a, K_b=None):
    """Angular frequency of each branch of the chain linearised about a static force F_0.

    Parameters
    ----------
    q : array_like
        Wavenumber, rad/m (a phase q a from one ring to the next); omega is even and
        2 pi/a-periodic in q.
    model : {"power-law", "dual-spring"}
        Power-law chain (Eq. (7)): one mass m per ring.  Dual-spring chain (Eqs. (5)-(6)):
        two masses m/2 per ring, contact and bending spring K_b alternating.
    F_0 : array_like
        Static force in every contact and ring body, N, >= 0.
    K : array_like
        Contact law F = K delta^n: prefactor, N/m^n (K_c, N/m^1.5, for the dual-spring chain).
    n : array_like
        Contact exponent, > 0 (3/2 for the Hertz contact of the dual-spring chain).
    m : array_like
        Inertial mass of a ring, kg.
    a : array_like
        Distance between adjacent ring centres, m.
    K_b : array_like, optional
        Bending stiffness of a ring, N/m (dual-spring model only).

    Returns
    -------
    ndarray
        omega, rad/s, of shape broadcast(q, F_0, ...) + (branches,): one branch for the
        power-law chain, two (acoustic first, then optical) for the dual-spring chain.

    Notes
    -----
    The contact acts as a spring of stiffness k_c = n K^(1/n) F_0^((n-1)/n)
    (:func:`contact_stiffness`).  Power law: omega = 2 sqrt(k_c/m) |sin(q a/2)|
    (:func:`power_law_dispersion`, from :func:`.longwave.lattice_dispersion`).
    Dual spring: omega^2 = 2/m [k_c + K_b -+ sqrt(k_c^2 + K_b^2 + 2 k_c K_b cos(q a))]
    (:func:`dual_spring_branches`), evaluated in a form that keeps its digits at small q.
    Beyond the paper, which treats the nonlinear pulse only.

    Examples
    --------
    >>> dispersion([0.0, np.pi], model="power-law", F_0=1.0, K=1.0, n=1.0, m=1.0, a=1.0).ravel().tolist()
    [0.0, 2.0]
    >>> dispersion(np.pi, model="dual-spring", F_0=1.0, K=1.0, n=1.0, m=4.0, a=1.0, K_b=4.0).tolist()
    [1.0, 2.0]
    """
    K_b = _model(model, K_b)
    q = v.as_float("q", q)
    F_0, K, n, m = _static_chain(F_0, K, n, m)
    a = v.positive("a", a, "m")
    with np.errstate(all="ignore"):  # overflow is reported below, by value
        if model == "power-law":
            omega = np.asarray(_power_law_branch(q, F_0, K, n, m, a), dtype=float)[..., None]
        else:
            branches = (_acoustic_branch(q, F_0, K, n, m, a, K_b), _optical_branch(q, F_0, K, n, m, a, K_b))
            omega = np.stack(np.broadcast_arrays(*branches), axis=-1).astype(float)
    return v.finite_result(omega, "omega", _CHAIN)


def band_edges(F_0, *, model, K, n, m, K_b=None):
    """Angular frequencies at the band edges of the chain linearised about a static force F_0.

    Parameters
    ----------
    model, F_0, K, n, m, K_b
        As in :func:`dispersion` (the edges do not depend on the spacing a).

    Returns
    -------
    BandEdges
        ``acoustic_top``, ``optical_bottom``, ``optical_top`` in rad/s.  Dual spring:
        2 sqrt(min(k_c, K_b)/m), 2 sqrt(max(k_c, K_b)/m) (both at q = pi/a) and
        2 sqrt((k_c + K_b)/m) (q = 0).  Power law: the top of its single band,
        2 sqrt(k_c/m), and NaN for the optical edges (it has no optical band).

    Notes
    -----
    The group velocity vanishes at every edge, so these are the frequencies that stay
    behind at a ring after a disturbance has passed.  One dual-spring edge, 2 sqrt(K_b/m),
    does not depend on F_0 (module docstring): the frequency of the trailing oscillations
    behind a pulse strong enough to leave the contacts slack.

    Examples
    --------
    >>> [round(float(e), 6) for e in band_edges(model="dual-spring", F_0=1.0, K=1.0, n=1.0, m=4.0, K_b=4.0)]
    [1.0, 2.0, 2.236068]
    """
    K_b = _model(model, K_b)
    F_0, K, n, m = _static_chain(F_0, K, n, m)
    with np.errstate(all="ignore"):  # overflow is reported below, by value
        if model == "power-law":
            top = v.finite_result(np.asarray(_power_law_top(F_0, K, n, m), dtype=float), "omega", _CHAIN)
            nan = np.full_like(top, np.nan)
            return BandEdges(top, nan, nan.copy())
        edges = np.broadcast_arrays(*_dual_spring_edges(F_0, K, n, m, K_b))
    return BandEdges(*(v.finite_result(np.asarray(e, dtype=float), "omega", _CHAIN) for e in edges))


def sound_speed(F_0, *, model, K, n, m, a, K_b=None):
    """Speed of long linear waves in a chain under static force F_0, m/s.

    Parameters
    ----------
    model, F_0, K, n, m, a, K_b
        As in :func:`dispersion`.

    Returns
    -------
    ndarray
        lim_{q -> 0} omega/q of the acoustic branch: a sqrt(k/m), with k = k_c for the
        power-law chain (:func:`~ringchain.theory.linear_sound_speed`) and
        k = k_c K_b/(k_c + K_b), contact and ring body in series, for the dual-spring one.

    Examples
    --------
    >>> round(float(sound_speed(model="dual-spring", F_0=1.0, K=2.0, n=1.0, m=1.0, a=1.0, K_b=2.0)), 12)  # k = 1
    1.0
    """
    K_b = _model(model, K_b)
    F_0, K, n, m = _static_chain(F_0, K, n, m)
    a = v.positive("a", a, "m")
    if model == "power-law":
        return linear_sound_speed(F_0, K=K, n=n, m=m, a=a)
    with np.errstate(all="ignore"):  # overflow is reported below, by value
        speed = np.asarray(_dual_spring_speed(F_0, K, n, m, a, K_b), dtype=float)
    return v.finite_result(speed, "the sound speed", _CHAIN)


@derived
def _junction():
    Z1, Z2 = sp.symbols("Z_1 Z_2", positive=True)
    return (Z1, Z2), sp.Tuple(*junction_symbolic())


def impedance(F_0, *, model, K, n, m, a, K_b=None):
    """Impedance of a chain to long linear waves under static force F_0, N s/m.

    Parameters
    ----------
    model, F_0, K, n, m, a, K_b
        As in :func:`dispersion`.

    Returns
    -------
    ndarray
        Z = m c/a = sqrt(m k): the force carried by a long travelling wave over the
        velocity of its rings, with c the :func:`sound_speed` and k the chain's tangent
        stiffness per ring (the contact's, or contact and ring body in series, Eq. (3)).

    Notes
    -----
    Step 8 of the module docstring.  Beyond the paper.

    Examples
    --------
    >>> float(impedance(model="power-law", F_0=1.0, K=4.0, n=1.0, m=1.0, a=2.0))  # sqrt(m K)
    2.0
    """
    c = sound_speed(F_0, model=model, K=K, n=n, m=m, a=a, K_b=K_b)
    with np.errstate(all="ignore"):  # m (c/a) = sqrt(m k): m c alone can overflow where Z does not
        Z = np.asarray(v.positive("m", m, "kg") * (c / v.positive("a", a, "m")), dtype=float)
    return v.finite_result(Z, "the impedance", _CHAIN)


def junction_coefficients(Z1, Z2):
    """Reflection and transmission of a long linear wave's force at the junction of two chains.

    Parameters
    ----------
    Z1 : array_like
        :func:`impedance` of the chain the wave comes from, N s/m.
    Z2 : array_like
        Impedance of the chain it goes into, N s/m.

    Returns
    -------
    R, T : ndarray
        Reflected and transmitted force over incident force: (Z2 - Z1)/(Z1 + Z2) and
        2 Z2/(Z1 + Z2) (:func:`junction_symbolic`).  The energy fluxes F^2/Z balance:
        R^2 + (Z1/Z2) T^2 = 1.

    Notes
    -----
    Long-wave limit (the pulse spans many rings): the junction is then a point, whatever
    the contact that makes it.  Small amplitudes about a pre-stretched state; a pulse
    in a chain without static force is nonlinear at any amplitude (the sonic vacuum).
    Beyond the paper.

    Examples
    --------
    >>> [float(x) for x in junction_coefficients(1.0, 3.0)]
    [0.5, 1.5]
    """
    Z1, Z2 = v.positive("Z1", Z1, "N s/m"), v.positive("Z2", Z2, "N s/m")
    v.broadcast_shape(Z1=Z1, Z2=Z2)
    R, T = _junction(Z1, Z2)
    return np.asarray(R, dtype=float), np.asarray(T, dtype=float)


def _ring_index(name, value):
    number = value.item() if isinstance(value, np.generic) else value  # 2.5, not np.float64(2.5), in the message
    if isinstance(number, bool) or not isinstance(number, (int, float)) or not float(number).is_integer():
        raise TypeError(f"{name} must be an integer ring index, got {number!r}")
    return int(number)


def linear_travel_time(ring_from, ring_to, *, model, K, n, m, a, K_b=None, m_gravity=None, g=STANDARD_GRAVITY):
    """Time a small long-wave pulse takes between two rings of a chain hanging under gravity, s.

    Parameters
    ----------
    ring_from, ring_to : int
        Rings counted from the lower (free, impact) end, ring 0 the lowest;
        0 <= ring_from < ring_to.
    model, K, n, m, a, K_b
        As in :func:`dispersion`; ``m`` is the inertial mass of a ring.
    m_gravity : array_like, optional
        Mass of a ring that gravity acts on, kg (default ``m``; the paper's rings have
        inertial mass m_eff and weight m0 g).
    g : array_like, optional
        Gravity, m/s^2.

    Returns
    -------
    ndarray
        sum over the contacts k = ring_from, ..., ring_to - 1 of a/c(F_k), with
        F_k = (k + 1) m_gravity g the weight of the rings below contact k and c the
        :func:`sound_speed` at that force.

    Notes
    -----
    The WKB (ray) approximation: the pulse is long compared with a, so that it travels
    at the long-wave speed, and short compared with the distance over which that speed
    changes (about k rings at contact k).  The static force grades the sound speed as
    F^((n-1)/(2n)) in the power-law chain; in the dual-spring chain the contact
    stiffens with the load while the ring bodies do not, so the speed saturates at
    a sqrt(K_b/m) high up a long chain.  Beyond the paper.

    Examples
    --------
    >>> float(linear_travel_time(0, 3, model="power-law", K=4.0, n=1.0, m=1.0, a=2.0, m_gravity=1.0))
    1.5
    """
    i, j = _ring_index("ring_from", ring_from), _ring_index("ring_to", ring_to)
    if not 0 <= i < j:
        raise ValueError(f"need 0 <= ring_from < ring_to, got ring_from = {i}, ring_to = {j}")
    m_gravity = v.positive("m_gravity", m if m_gravity is None else m_gravity, "kg")
    g = v.positive("g", g, "m/s^2")
    with np.errstate(all="ignore"):  # overflow is reported by value
        force = np.arange(i + 1, j + 1) * np.asarray(m_gravity * g)[..., None]
    force = v.finite_result(force, "the static force", "masses and gravity")
    expand = [None if value is None else np.asarray(value, dtype=float)[..., None] for value in (K, n, m, a, K_b)]
    K, n, m, a, K_b = expand
    speed = sound_speed(model=model, F_0=force, K=K, n=n, m=m, a=a, K_b=K_b)
    with np.errstate(all="ignore"):
        time = np.sum(a / speed, axis=-1)
    if np.any(speed == 0):
        raise ValueError("the sound speed vanishes at an unloaded contact (F_0 = 0 with n > 1): no linear travel time")
    return v.finite_result(time, "the travel time", _CHAIN)


# --- the drop: free fall to the impact -------------------------------------------------------------------


def free_fall_symbolic():
    """Impact speed v of a ring released from rest that falls freely through the height h.

    Energy conservation, m g h = m v^2/2, solved for v > 0: the ring's mass drops out (any
    ring, lumped or resolved, falls as a rigid body while its contacts are slack).
    """
    m, g, h, v0 = sp.symbols("m g h v", positive=True)
    (speed,) = sp.solve(sp.Eq(m * g * h, m * v0**2 / 2), v0)
    return speed


@derived
def _impact_speed():
    g, h = sp.symbols("g h", positive=True)
    return (h, g), free_fall_symbolic()


def impact_speed(drop_height, g=STANDARD_GRAVITY):
    """Speed of a ring dropped from ``drop_height`` when its slack is taken up, m/s: sqrt(2 g h).

    Parameters
    ----------
    drop_height : array_like
        Free-fall height, m, >= 0 (from release to the instant the contact with the ring
        above is taut again; see :class:`ringchain.numerics.Chain`).
    g : float, optional
        Acceleration of gravity, m/s^2, > 0; default :data:`STANDARD_GRAVITY`.

    Returns
    -------
    ndarray
        m/s (:func:`free_fall_symbolic`).

    Notes
    -----
    The one place where a drop height becomes an impact speed (the lattice, the command
    line and the book call it).  Beyond the paper, which gives no heights.

    Examples
    --------
    >>> round(float(impact_speed(0.05)), 6)  # the book's 5 cm drop
    0.990285
    """
    h = v.nonnegative("drop_height", drop_height, "m")
    g = v.positive("g", g, "m/s^2")
    v.broadcast_shape(drop_height=h, g=g)
    with np.errstate(all="ignore"):  # overflow is reported below, by value
        speed = np.asarray(_impact_speed(h, g), dtype=float)
    return v.finite_result(speed, "the impact speed", "drop height and gravity")
