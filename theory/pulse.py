r"""What the compact solitary wave carries: its energy and momentum, and the impact that launches it.

Continues :mod:`.solitary` (App. B) from the compact solution
xi(tau) = xi_max |sin(omega tau)|^p, p = 2/(n-1), on one hump 0 < omega tau < pi.
Beyond the paper, which gives V_s(F_m) (Eq. (8)) but not how F_m follows from the
impact.  Step by step:

1. :func:`euler_beta_integral` -- Euler's integral int_0^1 s^(alpha-1) (1-s)^(beta-1) ds,
   evaluated by SymPy (a hypergeometric function at 1, then Gauss's theorem by
   ``hyperexpand``) to Gamma(alpha) Gamma(beta)/Gamma(alpha + beta) = B(alpha, beta).
2. :func:`profile_integral` -- int xi^k dtau over the hump: theta = omega tau, the hump's
   symmetry about theta = pi/2, and s = sin^2 theta turn it into Euler's integral, so
   int xi^k dtau = xi_max^k B(1/2, (k p + 1)/2)/omega.
3. :func:`energy_densities` -- per unit length of chain (one ring per spacing a): the
   kinetic energy m v^2/(2 a), with the ring velocity v = -V_s xi of
   :func:`.solitary.velocity_profile`, and the contact energy U(a xi)/a with
   U(delta) = int_0^delta K e^n de (delta ~ a xi, as for Eq. (8)); the momentum density
   m v/a.
4. :func:`energy_parts`, :func:`energy`, :func:`momentum` -- the densities integrated with
   step 2, V_s from :func:`.solitary.speed_from_strain` and xi_max from F_m = K (a xi_max)^n.
   The kinetic and contact parts are in the ratio 2(n+1)/(n+3) (10/9 for Hertz): not
   equipartition.  The energy depends on F_m, K and n only (the wave spans a fixed
   number of rings, whatever a), E = F_m delta_m C(n) with delta_m = (F_m/K)^(1/n); the
   momentum is sqrt(m) times a function of F_m, K and n, directed towards the impact.
5. :func:`impact_law` -- a striker of mass m_s hitting the end of the chain at v_0 puts
   its kinetic energy into the leading wave: E(F_m) = m_s v_0^2/2, solved for F_m.
   E ~ F_m^((n+1)/n) gives F_m ~ v_0^(2n/(n+1)) whatever the prefactor (scaling); the
   prefactor comes from the energy of step 4.

Why energy and not momentum: on the lattice (tests/numerics/layouts/test_linear_waves.py) a
striker of the chain's own mass gives the leading wave 97.6-99.4 % of its energy for
n = 1.1-1.5, but 1.14-1.53 times its momentum (the striker and the first rings recoil
towards the chain and carry the difference).  The energy law puts the amplitude of the
formed wave 1.1-1.4 % too high (the measured error: the energy left behind, 0.6-2.4 %,
and the long-wave error of the wave's energy, +1.39 to +0.25 %, both make it high and
add); the momentum law would be 14-36 % too low.

Numeric functions: :func:`solitary_wave_energy`, :func:`solitary_wave_momentum`,
:func:`impact_amplitude`.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from . import longwave, solitary
from ._codegen import derived, sp
from ._forms import power_law, power_law_value, power_root
from .special import beta

__all__ = [
    "symbols",
    "euler_beta_integral",
    "profile_integral",
    "energy_densities",
    "energy_parts",
    "energy",
    "momentum",
    "impact_law",
    "solitary_wave_energy",
    "solitary_wave_momentum",
    "impact_amplitude",
]


@functools.cache
def symbols():
    """Symbols of :mod:`.solitary` plus the striker mass m_s, the impact speed v_0 and a power k."""
    s = dict(solitary.symbols())
    s.update(
        m_s=sp.Symbol("m_s", positive=True),
        v_0=sp.Symbol("v_0", positive=True),
        k=sp.Symbol("k", positive=True),
    )
    return s


def _tidy(expr):
    """Powers of positive bases merged (every base here is positive)."""
    return sp.powsimp(sp.powdenest(sp.expand_power_base(expr, force=True), force=True), force=True)


# --- 1.-2. integrals of the profile --------------------------------------------------------------


@functools.cache
def euler_beta_integral():
    """(alpha, beta, value): int_0^1 s^(alpha-1) (1-s)^(beta-1) ds by SymPy, and the check that it is B(alpha, beta).

    The integral is a Mellin transform, done by SymPy's Meijer G-function algorithm, which gives
    Gamma(alpha) Gamma(beta)/Gamma(alpha + beta) (``hyperexpand`` and ``gammasimp`` bring any 2F1 at 1
    it leaves to that form by Gauss's theorem).
    """
    from sympy.integrals.meijerint import meijerint_definite

    alpha, beta_ = sp.symbols("alpha beta", positive=True)
    s = sp.Symbol("s", positive=True)
    # The definite Meijer G-function integral called directly: ``sp.integrate(..., meijerg=True)`` takes 2 s
    # for it (its front end tries antiderivatives first), this 0.4 s; SymPy's default risch takes 8 s.
    result = meijerint_definite(s ** (alpha - 1) * (1 - s) ** (beta_ - 1), s, 0, 1)
    if result is None or result[1] is sp.false:  # pragma: no cover - derivation check
        raise RuntimeError(f"SymPy's Meijer G-function integration gave {result}")
    value = sp.gammasimp(sp.hyperexpand(result[0]))
    if sp.simplify(value - beta(alpha, beta_).rewrite(sp.gamma)) != 0:  # pragma: no cover - derivation check
        raise RuntimeError(f"Euler's integral gave {value}, not B(alpha, beta)")
    return alpha, beta_, value


@functools.cache
def _euler_substitution():
    """(e, int_0^1 ... ds): int_0^(pi/2) sin(theta)^e dtheta under theta = asin(sqrt(s)), for a symbol e.

    ``Integral.transform`` solves for the inverse of the substitution, which costs about 0.3 s
    whatever the exponent: done once here, and the exponent k p of :func:`profile_integral`
    substituted into the result.
    """
    theta = sp.Symbol("theta", positive=True)
    if sp.sin(sp.pi - theta) != sp.sin(theta):  # pragma: no cover - derivation check
        raise RuntimeError("the hump is not symmetric")
    power = sp.Dummy("e", positive=True)
    half = sp.Integral(sp.sin(theta) ** power, (theta, 0, sp.pi / 2))
    return power, half.transform(theta, sp.asin(sp.sqrt(sp.Symbol("s", positive=True))))


@functools.cache
def profile_integral(k=None):
    """int xi^k dtau over the support of the compact wave: xi_max^k B(1/2, (k p + 1)/2)/omega.

    ``k`` is a SymPy expression (default: the symbol k); xi_max stays a symbol.  With
    theta = omega tau the hump is 0 < theta < pi, symmetric about pi/2, so the integral is
    2/omega int_0^(pi/2) sin(theta)^(k p) dtheta; theta = asin(sqrt(s)) makes that
    1/omega int_0^1 s^((k p - 1)/2) (1 - s)^(-1/2) ds, Euler's integral
    (:func:`euler_beta_integral`) with alpha = (k p + 1)/2 and beta = 1/2.
    """
    s = symbols()
    k = s["k"] if k is None else k
    solution = solitary.compact_solution()
    p, omega = solution["p"], solution["omega"]
    power, half = _euler_substitution()
    euler = half.subs(power, k * p)
    integrand = sp.powsimp(euler.function, force=True)
    (variable, low, high) = euler.limits[0]
    if (low, high) != (0, 1):  # pragma: no cover - derivation check
        raise RuntimeError(f"the substitution gave limits {low}, {high}")
    A, B, C = sp.Wild("A", exclude=[variable]), sp.Wild("B", exclude=[variable]), sp.Wild("C", exclude=[variable])
    match = integrand.match(C * variable**A * (1 - variable) ** B)
    if match is None:  # pragma: no cover - derivation check
        raise RuntimeError(f"{integrand} is not of Euler's form")
    alpha, beta_, _ = euler_beta_integral()
    exponents = {alpha: sp.simplify(match[A] + 1), beta_: sp.simplify(match[B] + 1)}
    half_value = match[C] * beta(exponents[alpha], exponents[beta_])
    return s["xi_max"] ** k * 2 * half_value / omega


# --- 3.-4. energy and momentum ----------------------------------------------------------------------


@functools.cache
def energy_densities():
    """(kinetic, contact, momentum) per unit length, as functions of the strain (symbol ``xi``).

    Kinetic m v^2/(2 a) and momentum m v/a with v = -V_s xi (:func:`.solitary.velocity_profile`);
    contact energy U(a xi)/a with U(delta) = int_0^delta K e^n de.
    """
    s = symbols()
    X, K, n, m, a = s["X"], s["K"], s["n"], s["m"], s["a"]
    velocity_per_strain = sp.simplify(solitary.velocity_profile() / solitary.strain_profile())  # -V_s
    e, delta = sp.symbols("e delta", positive=True)
    stored = sp.integrate(K * e**n, (e, 0, delta), conds="none")
    kinetic = m * (velocity_per_strain * X) ** 2 / (2 * a)
    contact = _tidy(stored.subs(delta, a * X) / a)
    return kinetic, contact, m * velocity_per_strain * X / a


def _integrate_density(density):
    """int density dtau over the hump, density = c xi^k (from :func:`profile_integral`)."""
    s = symbols()
    coefficient, power = _tidy(density).as_coeff_exponent(s["X"])
    if coefficient.has(s["X"]):  # pragma: no cover - derivation check
        raise RuntimeError(f"{density} is not a power of xi")
    return coefficient * profile_integral(power)


def _in_force(expr):
    """expr with V_s(xi_max), c_n^2 = K a^(n+1)/m and xi_max = (F_m/K)^(1/n)/a substituted."""
    s = symbols()
    xi_peak = sp.solve(sp.Eq(s["F_m"], s["K"] * (s["a"] * s["xi_max"]) ** s["n"]), s["xi_max"], check=False)[0]
    expr = expr.subs(s["V_s"], solitary.speed_from_strain())
    expr = expr.subs(s["c_n"], sp.sqrt(longwave.wave_speed_squared()))
    return _tidy(sp.simplify(_tidy(expr.subs(s["xi_max"], xi_peak))))


@functools.cache
def energy_parts():
    """(kinetic, contact) energy of the compact solitary wave of peak force F_m, J."""
    kinetic, contact, _ = energy_densities()
    return _in_force(_integrate_density(kinetic)), _in_force(_integrate_density(contact))


@functools.cache
def energy():
    """E(F_m) = kinetic + contact energy of the compact solitary wave, J (a and m cancel)."""
    kinetic, contact = energy_parts()
    return _tidy(sp.simplify(kinetic + contact))


@functools.cache
def momentum():
    """|P|(F_m), kg m/s: the momentum of the wave, m V_s int xi dtau/a, directed towards the impact."""
    _, _, density = energy_densities()
    return _in_force(-_integrate_density(density))


@functools.cache
def impact_law():
    """F_m(v_0, m_s): E(F_m) = m_s v_0^2/2 (:func:`energy`) solved for F_m, N."""
    s = symbols()
    # E = C F_m^((n+1)/n): one positive root (``solve`` takes 0.5 s to find it).
    return _tidy(power_root(sp.Eq(energy(), s["m_s"] * s["v_0"] ** 2 / 2), s["F_m"]))


# --- numeric functions --------------------------------------------------------------------------


# Each is a power of its force or speed, C x^p: evaluated as exp(log C + p log x) (:func:`power_law_value`), so
# that no intermediate power overflows where the result does not (v0^2 overflows from 1.3e154 m/s on).
@derived
def _energy():
    s = symbols()
    return (s["K"], s["n"]), power_law(energy(), s["F_m"])


@derived
def _momentum():
    s = symbols()
    return (s["K"], s["n"], s["m"]), power_law(momentum(), s["F_m"])


@derived
def _amplitude():
    s = symbols()
    return (s["K"], s["n"], s["m_s"]), power_law(sp.expand_power_base(impact_law(), force=True), s["v_0"])


def _power_of(function, variable, *parameters, what):
    """exp(log C + p log variable) of a derived power law, refused by value beyond double precision."""
    with np.errstate(all="ignore"):
        log_coefficient, exponent = function(*parameters)
        value = power_law_value(log_coefficient, exponent, variable)
    return v.finite_result(value, what, "force or speed and chain parameters (K, n, m)")


def solitary_wave_energy(F_m, *, K, n, m, a):
    """Energy carried by the compact solitary wave of peak contact force F_m, J (App. B).

    Parameters
    ----------
    F_m : array_like
        Peak contact force of the wave, N, > 0.
    K : array_like
        Power-law prefactor, N/m^n (F = K delta^n, paper Eq. (4)).
    n : array_like
        Power-law exponent, > 1.
    m : array_like
        Ring mass, kg (validated; it cancels).
    a : array_like
        Distance between adjacent ring centres, m (validated; it cancels).

    Returns
    -------
    ndarray
        E = sqrt(n/(6(n+1))) F_m delta_m [B(1/2, (n+3)/(2(n-1))) + B(1/2, (3n+1)/(2(n-1)))]/(n-1)
        with delta_m = (F_m/K)^(1/n), in J; the first Beta term is the kinetic energy,
        the second the contact energy.

    Notes
    -----
    The kinetic and contact energy densities of the compact solution of App. B
    (Eq. (B21) and below) integrated over its support (:func:`energy`); m and a cancel
    because the wave spans a fixed number of rings.  Beyond the paper.  On the lattice
    the formed wave carries 0.05-0.07 (a/L) more than this at its measured amplitude,
    L = :func:`~ringchain.theory.solitary_wave_width` (the long-wave error; measured in
    tests/numerics/layouts/test_linear_waves.py).

    Examples
    --------
    >>> round(float(solitary_wave_energy(1.0, K=1.0, n=1.5, m=1.0, a=1.0)), 6)  # Hertz, in units K = F_m = 1
    1.032266
    """
    F_m = v.positive("F_m", F_m, "N")
    K, n, _, _ = v.compact_wave_chain(K, n, a, m)
    return _power_of(_energy, F_m, K, n, what="the energy")


def solitary_wave_momentum(F_m, *, K, n, m, a):
    """Momentum carried by the compact solitary wave of peak contact force F_m, kg m/s (App. B).

    Parameters
    ----------
    F_m, K, n, m, a : array_like
        As in :func:`solitary_wave_energy` (here m counts; a cancels).

    Returns
    -------
    ndarray
        |P| = m V_s int xi dtau/a = sqrt(m n/3) sqrt(F_m delta_m) B(1/2, (n+1)/(2(n-1)))/(n-1)
        with delta_m = (F_m/K)^(1/n), in kg m/s.  The rings move towards the impact
        (u_t = -V_s xi in the tension convention), so the momentum points there; its
        size is returned.

    Notes
    -----
    :func:`momentum`.  E and P^2 scale alike with F_m, so the wave moves like a particle
    of fixed mass P^2/(2E): 1.34 m for n = 3/2, growing as n -> 1 (the wave widens).
    Beyond the paper.

    Examples
    --------
    >>> round(float(solitary_wave_momentum(1.0, K=1.0, n=1.5, m=1.0, a=1.0)), 6)
    1.666081
    """
    F_m = v.positive("F_m", F_m, "N")
    K, n, _, m = v.compact_wave_chain(K, n, a, m)
    return _power_of(_momentum, F_m, K, n, m, what="the momentum")


def impact_amplitude(v0, *, K, n, m, a, m_striker=None):
    """Peak force of the leading solitary wave launched by a striker hitting the chain end at v0, N.

    Parameters
    ----------
    v0 : array_like
        Impact speed, m/s, > 0 (for a drop from height h, sqrt(2 g h)).
    K, n, m, a : array_like
        Chain: prefactor (N/m^n), exponent (> 1), ring mass (kg), spacing (m; it cancels).
    m_striker : array_like, optional
        Mass of the striker, kg; default ``m``: the paper's convention, a dropped ring of the
        chain's inertial mass m_eff.  A ring in free fall strikes as a rigid body, with its
        full mass m0 (``striker_mass="m0"`` of :class:`ringchain.numerics.Chain`).

    Returns
    -------
    ndarray
        F_m with :func:`solitary_wave_energy` (F_m) = m_striker v0^2/2: the striker's
        kinetic energy in the leading wave, F_m ~ v0^(2n/(n+1)) (:func:`impact_law`).

    Notes
    -----
    Energy, not momentum, is the conserved quantity that fixes the amplitude: the leading
    wave takes nearly all the striker's energy but more than its momentum (module
    docstring).  Measured on long undamped power-law chains with m_striker = m, the
    formed wave's peak force is 1.1-1.4 % below this prediction for n = 1.1-1.5.  A
    striker heavier than a ring launches a train of waves, and the leading one carries
    less than all of the energy: with m_striker = 2.70 m (Table I's m0/m_eff) the formed
    wave is 2.3 % below the prediction for n = 1.11 (tests/numerics/layouts/test_striker.py) and
    6.9 % for n = 3/2 (the book's chapter on linear waves).  In a short chain with n near 1
    the wave has no room to form (its width L/a grows as 1/(n - 1)).  Beyond the paper.

    Examples
    --------
    >>> round(float(impact_amplitude(1.0, K=1.0, n=1.5, m=1.0, a=1.0)), 6)
    0.647302
    """
    v0 = v.positive("v0", v0, "m/s")
    K, n, _, m = v.compact_wave_chain(K, n, a, m)
    m_striker = m if m_striker is None else v.positive("m_striker", m_striker, "kg")
    return _power_of(_amplitude, v0, K, n, m_striker, what="F_m")
