r"""Long-wave (continuum) limit of the power-law chain: Nesterenko's expansion (paper App. B).

The lattice is the power-law chain of the paper (Eq. (7) without dashpots) in the
tension convention of the project: the extension of contact i is u_{i+1} - u_i and

    m u_i'' = K (u_{i+1} - u_i)^n - K (u_i - u_{i-1})^n,        A = K/m.

The derivation, step by step (each step a function returning SymPy objects):

1. :func:`neighbour_displacements` -- Taylor series of u_{i+1}, u_{i-1} in the spacing
   a (App. B, Eqs. (B1)-(B3), from :func:`sympy.series` of u(x + h, t).
2. :func:`extension_parts` -- u_{i+1} - u_i = N + phi, u_i - u_{i-1} = N + psi with
   N = a u_x; :func:`binomial_expansion` -- (N + phi)^n to third order in phi/N.
3. :func:`power_difference` -- phi - psi, phi^2 - psi^2, phi^3 - psi^3 to the order
   the expansion needs.  With phi/N ~ psi/N ~ eps = a/L, the term N^(n-k)(phi^k - psi^k)
   is needed through a^(k+3) for u_tt to be exact to relative order eps^2
   (:data:`RELATIVE_ORDER`); phi^4 - psi^4 starts at a^9, beyond that order, which is why
   the binomial series stops at the cube.
4. :func:`displacement_equation` -- App. B Eq. (B15) for u_tt, assembled from steps 2-3;
   :func:`displacement_equation_direct` -- the same by expanding the lattice force
   directly in a (an independent route, used as a check).
5. :func:`flux` and :func:`displacement_equation_conservative` -- the conservative form
   u_tt = A a^(n+1) d/dx G.  G is derived, not guessed: the lattice force is the
   difference f(x + a/2) - f(x - a/2) of the contact force f = K (u(x + a/2) -
   u(x - a/2))^n at the contact points, and the central difference
   f(x + a/2) - f(x - a/2) = d/dx [a f + a^3/24 f_xx] + O(a^5) puts it in flux form.
6. :func:`strain_equation` -- App. B Eq. (B17) for the strain xi = u_x, with
   c_n^2 = A a^(n+1) (:func:`wave_speed_squared`).
7. Linear sound speed of a pre-stretched chain (static strain xi_0, static contact
   extension delta_0 = a xi_0, static force F_0 = K delta_0^n), derived twice: from the
   linearised lattice (:func:`lattice_dispersion`, :func:`sound_speed_lattice`) and from
   Eq. (B17) linearised about xi_0 (:func:`continuum_dispersion`,
   :func:`sound_speed_continuum`); both give c_0 = a sqrt(n K delta_0^(n-1)/m).

The expansion assumes u_x > 0 (every contact in tension), so powers of a u_x split into
a^p u_x^p.  The numeric function of this module is :func:`linear_sound_speed`.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from ._codegen import derived, sp
from ._forms import power_law, power_law_value

__all__ = [
    "RELATIVE_ORDER",
    "symbols",
    "lattice_acceleration",
    "neighbour_displacements",
    "extension_parts",
    "binomial_expansion",
    "power_difference",
    "orders_in_a",
    "displacement_equation",
    "displacement_equation_direct",
    "contact_force_at_midpoint",
    "central_difference",
    "flux",
    "displacement_equation_conservative",
    "wave_speed_squared",
    "strain_flux",
    "strain_equation",
    "linear_contact_stiffness",
    "lattice_dispersion",
    "sound_speed_lattice",
    "continuum_dispersion",
    "sound_speed_continuum",
    "static_extension",
    "sound_speed_from_force",
    "linear_sound_speed",
]

#: Relative order in eps = a/L to which the long-wave equations are kept (App. B: eps^2).
RELATIVE_ORDER = 2

#: Number of Taylor terms (powers a^0 ... a^5) kept in the neighbour displacements: enough
#: for every coefficient through relative order eps^2 (phi^2 - psi^2 needs a^4 terms).
_TAYLOR_TERMS = 6


@functools.cache
def symbols():
    """Symbols: x, t; spacing a, exponent n, stiffness K, mass m; A = K/m; c_n; fields u, xi.

    Also ``h`` (a generic shift), ``N``/``e`` (placeholders of the binomial series), the
    static strain ``xi_0``, the static extension ``delta_0``, the static force ``F_0`` and
    the wavenumber ``q``/frequency ``omega`` of the linear analysis.
    """
    x, t, h = sp.symbols("x t h", real=True)
    a, n, K, m = sp.symbols("a n K m", positive=True)
    A, c_n = sp.symbols("A c_n", positive=True)
    N, e = sp.symbols("N e", positive=True)
    xi_0, delta_0, F_0 = sp.symbols("xi_0 delta_0 F_0", positive=True)
    q, omega = sp.symbols("q omega", positive=True)
    u = sp.Function("u")(x, t)
    xi = sp.Function("xi")(x, t)
    return dict(
        x=x,
        t=t,
        h=h,
        a=a,
        n=n,
        K=K,
        m=m,
        A=A,
        c_n=c_n,
        N=N,
        e=e,
        xi_0=xi_0,
        delta_0=delta_0,
        F_0=F_0,
        q=q,
        omega=omega,
        u=u,
        xi=xi,
    )


def lattice_acceleration(u_prev, u_here, u_next):
    """u_i'' = A [(u_{i+1} - u_i)^n - (u_i - u_{i-1})^n], the lattice in tension (A = K/m)."""
    s = symbols()
    return s["A"] * ((u_next - u_here) ** s["n"] - (u_here - u_prev) ** s["n"])


# --- 1.-3. the expansion -------------------------------------------------------------------


def _taylor(shift):
    """Taylor polynomial of u(x + shift, t) through shift^5, from sympy.series."""
    s = symbols()
    h = s["h"]
    series = sp.series(sp.Function("u")(s["x"] + h, s["t"]), h, 0, _TAYLOR_TERMS).removeO().doit()
    return series.subs(h, shift)


@functools.cache
def neighbour_displacements():
    """(u_{i-1}, u_{i+1}): Taylor polynomials in a through a^5 (App. B, Eqs. (B1)-(B3)."""
    a = symbols()["a"]
    return _taylor(-a), _taylor(a)


@functools.cache
def extension_parts():
    """(N, phi, psi) with u_{i+1} - u_i = N + phi, u_i - u_{i-1} = N + psi and N = a u_x."""
    s = symbols()
    u, a, x = s["u"], s["a"], s["x"]
    u_prev, u_next = neighbour_displacements()
    N = a * sp.diff(u, x)
    return N, sp.expand(u_next - u - N), sp.expand(u - u_prev - N)


def binomial_expansion(N=None, e=None, terms=4):
    """(N + e)^n to ``terms`` terms in e/N (the binomial series of App. B, Eqs. (B6)-(B7)).

    With the default symbols ``N`` and ``e`` it returns
    N^n + n N^(n-1) e + n(n-1)/2 N^(n-2) e^2 + n(n-1)(n-2)/6 N^(n-3) e^3.
    """
    s = symbols()
    series = sp.series((s["N"] + s["e"]) ** s["n"], s["e"], 0, terms).removeO()
    series = sp.expand(sp.powsimp(sp.expand(series)))
    return series.subs({s["N"]: s["N"] if N is None else N, s["e"]: s["e"] if e is None else e}, simultaneous=True)


def orders_in_a(expr, leading=0):
    """{k: c_k} with expr = sum_k c_k a^(leading + k) (k integer), after splitting powers.

    Powers (a u_x)^p are split into a^p u_x^p, valid for u_x > 0 (contacts in tension).
    """
    a = symbols()["a"]
    expr = sp.expand(sp.expand_power_base(sp.expand(expr), force=True))
    out: dict = {}
    for term in sp.Add.make_args(expr):
        coeff, k = sp.powsimp(term / a**leading, force=True).as_coeff_exponent(a)
        if not k.is_integer:
            raise ValueError(f"term {term} is not a^({leading}) times an integer power of a")
        out[int(k)] = out.get(int(k), 0) + coeff
    return {k: c for k, c in sorted(out.items()) if sp.expand(c) != 0}


def _truncate(expr, through, leading=0, divide=False):
    """expr with only the powers a^(leading + k), k <= through, kept (divided by a^leading if asked)."""
    a = symbols()["a"]
    keep = {k: c for k, c in orders_in_a(expr, leading).items() if k <= through}
    return sp.Add(*[c * a ** (k if divide else leading + k) for k, c in keep.items()])


def power_difference(k, through=None):
    """phi^k - psi^k through a^through (default k + 1 + RELATIVE_ORDER, what Eq. (B15) needs).

    N^(n-k) (phi^k - psi^k) is a^(n-k) (phi^k - psi^k); the leading term of u_tt is a^(n+1),
    so relative order eps^2 needs phi^k - psi^k through a^(k + 3).
    """
    _, phi, psi = extension_parts()
    through = k + 1 + RELATIVE_ORDER if through is None else through
    return _truncate(phi**k - psi**k, through)


@functools.cache
def displacement_equation():
    """Right-hand side of u_tt, App. B Eq. (B15), assembled from the binomial series.

    u_tt = A sum_k C_k N^(n-k) (phi^k - psi^k), k = 1..3, with C_k the binomial
    coefficients of :func:`binomial_expansion` and the power differences of
    :func:`power_difference`; kept through a^(n+3), relative order eps^2.
    """
    s = symbols()
    a, n, A = s["a"], s["n"], s["A"]
    N_sym, e = s["N"], s["e"]
    N, _, _ = extension_parts()
    series = binomial_expansion()
    rhs = 0
    for k in range(1, 4):
        coefficient = series.coeff(e, k).subs(N_sym, N)
        rhs += coefficient * power_difference(k)
    return sp.collect(_truncate(A * rhs, RELATIVE_ORDER, leading=n + 1), a)


@functools.cache
def displacement_equation_direct():
    """u_tt from the lattice force expanded directly in a (a check of Eq. (B15) by another route).

    A [(N + phi)^n - (N + psi)^n] = A N^n [(1 + phi/N)^n - (1 + psi/N)^n], the bracket
    expanded with :func:`sympy.series` in a, through relative order eps^2.
    """
    s = symbols()
    a, n, A = s["a"], s["n"], s["A"]
    N, phi, psi = extension_parts()
    bracket = (1 + sp.expand(phi / N)) ** n - (1 + sp.expand(psi / N)) ** n
    bracket = sp.series(bracket, a, 0, 2 + RELATIVE_ORDER).removeO()
    return sp.collect(_truncate(A * N**n * bracket, RELATIVE_ORDER, leading=n + 1), a)


# --- 5. conservative form -------------------------------------------------------------------


@functools.cache
def contact_force_at_midpoint():
    """f/K = (u(x + a/2) - u(x - a/2))^n, the contact force at x, through relative order eps^2."""
    s = symbols()
    a, n, u, x = s["a"], s["n"], s["u"], s["x"]
    extension = sp.expand(_taylor(a / 2) - _taylor(-a / 2))  # a u_x + a^3/24 u_xxx + ...
    N = a * sp.diff(u, x)
    series = binomial_expansion(N, extension - N)
    return _truncate(series, RELATIVE_ORDER, leading=n)


def central_difference(order=4):
    """F(x + a/2) - F(x - a/2) of a generic F(x), through a^(order - 1).

    Returns ``(expr, F)``: a F' + a^3/24 F''' for the default order.
    """
    s = symbols()
    a, x, h = s["a"], s["x"], s["h"]
    F = sp.Function("F")
    series = sp.series(F(x + h) - F(x - h), h, 0, order).removeO().doit()
    return sp.expand(series.subs(h, a / 2)), F


@functools.cache
def flux():
    """G with u_tt = A a^(n+1) d/dx G (the conservative form of App. B, below Eq. (B15)).

    The central difference a F' + a^3/24 F''' = d/dx (a F + a^3/24 F'') of the contact
    force F = f (:func:`contact_force_at_midpoint`) gives the flux a f + a^3/24 f_xx;
    divided by a^(n+1) and kept through relative order eps^2:
    G = u_x^n + n a^2/24 [(n - 1) u_x^(n-2) u_xx^2 + 2 u_x^(n-1) u_xxx].
    """
    s = symbols()
    a, n, x = s["a"], s["n"], s["x"]
    difference, F = central_difference()
    # The difference is d/dx of the same series with one derivative fewer on each term.
    antiderivative = difference.replace(
        lambda e: isinstance(e, sp.Derivative) and e.expr == F(x),
        lambda e: sp.Derivative(F(x), (x, e.derivative_count - 1)).doit(),
    )
    if sp.expand(sp.diff(antiderivative, x) - difference) != 0:  # pragma: no cover - a derivation check
        raise RuntimeError("the central difference is not in flux form")
    f = contact_force_at_midpoint()
    total = antiderivative.subs(F(x), f).doit()
    return sp.collect(_truncate(total, RELATIVE_ORDER, leading=n + 1, divide=True), a)


@functools.cache
def displacement_equation_conservative():
    """A a^(n+1) d/dx G, evaluated: must equal Eq. (B15) (:func:`displacement_equation`)."""
    s = symbols()
    a, n = s["a"], s["n"]
    return sp.collect(_truncate(s["A"] * a ** (n + 1) * sp.diff(flux(), s["x"]), RELATIVE_ORDER, leading=n + 1), a)


def wave_speed_squared():
    """c_n^2 = A a^(n+1) = K a^(n+1)/m (App. B, below Eq. (B17))."""
    s = symbols()
    return s["K"] / s["m"] * s["a"] ** (s["n"] + 1)


@functools.cache
def strain_flux():
    """G of the strain equation: :func:`flux` with u_x replaced by xi."""
    s = symbols()
    return flux().subs(sp.Derivative(s["u"], s["x"]), s["xi"])


@functools.cache
def strain_equation():
    """App. B Eq. (B17): xi_tt = c_n^2 d^2/dx^2 {xi^n + n a^2/24 [...]} as a SymPy ``Eq``.

    Differentiating u_tt = c_n^2 d/dx G in x and writing xi = u_x.  The right-hand side
    is returned unevaluated (``Derivative`` of the strain flux), as printed in the paper.
    """
    s = symbols()
    u, x, t, xi = s["u"], s["x"], s["t"], s["xi"]
    lhs = sp.diff(u, t, 2, x).subs(sp.Derivative(u, x), xi)
    rhs = s["c_n"] ** 2 * sp.Derivative(strain_flux(), (x, 2))
    return sp.Eq(lhs.doit(), rhs)


# --- 7. linear sound speed of the pre-stretched chain ------------------------------------------


def linear_contact_stiffness():
    """k_0 = dF/d delta at delta_0: n K delta_0^(n-1), the stiffness of the linearised contact."""
    s = symbols()
    delta = sp.Symbol("delta", positive=True)
    return sp.diff(s["K"] * delta ** s["n"], delta).subs(delta, s["delta_0"])


@functools.cache
def lattice_dispersion():
    """omega^2(q) of the lattice linearised about a uniform extension delta_0.

    u_j = delta_0 j + epsilon eta_j: the acceleration of :func:`lattice_acceleration` to
    first order in epsilon, for the plane wave eta_{j+k} = exp(i k q a) eta_j with
    eta_j'' = -omega^2 eta_j, gives omega^2 = 4 k_0/m sin^2(q a/2).
    """
    s = symbols()
    a, q, omega, delta_0 = s["a"], s["q"], s["omega"], s["delta_0"]
    eps = sp.Symbol("epsilon", positive=True)
    eta = sp.Symbol("eta", positive=True)
    shifted = [sp.exp(sp.I * k * q * a) * eta for k in (-1, 0, 1)]
    positions = [delta_0 * k + eps * shift for k, shift in zip((-1, 0, 1), shifted, strict=True)]
    acceleration = lattice_acceleration(*positions).subs(s["A"], s["K"] / s["m"])
    linear = sp.diff(acceleration, eps).subs(eps, 0)
    omega2 = sp.expand(sp.expand(sp.solve(sp.Eq(-(omega**2) * eta, linear), omega**2)[0]).rewrite(sp.cos))
    return sp.factor(sp.expand(omega2.subs(sp.cos(a * q), 1 - 2 * sp.sin(a * q / 2) ** 2)))


@functools.cache
def sound_speed_lattice():
    """c_0 = lim_{q -> 0} omega/q of :func:`lattice_dispersion`: a sqrt(n K delta_0^(n-1)/m)."""
    s = symbols()
    return sp.simplify(sp.limit(sp.sqrt(lattice_dispersion()) / s["q"], s["q"], 0))


@functools.cache
def continuum_dispersion():
    """omega^2(q) of Eq. (B17) linearised about the static strain xi_0.

    xi = xi_0 + epsilon eta with eta = exp(i(q x - omega t)); to first order in epsilon,
    omega^2 = c_n^2 n xi_0^(n-1) (q^2 - a^2 q^4/12): the long-wave expansion of
    :func:`lattice_dispersion` (a test checks the two agree through q^4).
    """
    s = symbols()
    x, t, q, omega, xi = s["x"], s["t"], s["q"], s["omega"], s["xi"]
    eps = sp.Symbol("epsilon", positive=True)
    wave = sp.exp(sp.I * (q * x - omega * t))
    equation = strain_equation()
    residual = (equation.lhs - equation.rhs).subs(xi, s["xi_0"] + eps * wave).doit()
    linear = sp.expand(sp.diff(residual, eps).subs(eps, 0) / wave)
    return sp.expand(sp.powsimp(sp.solve(linear, omega**2)[0]))


@functools.cache
def sound_speed_continuum():
    """c_0 = lim_{q -> 0} omega/q of :func:`continuum_dispersion`: c_n sqrt(n xi_0^(n-1))."""
    s = symbols()
    return sp.simplify(sp.limit(sp.sqrt(continuum_dispersion()) / s["q"], s["q"], 0))


@functools.cache
def static_extension():
    """delta_0(F_0) = (F_0/K)^(1/n): the contact extension that carries the static force F_0 = K delta_0^n."""
    s = symbols()
    return sp.solve(sp.Eq(s["F_0"], s["K"] * s["delta_0"] ** s["n"]), s["delta_0"])[0]


@functools.cache
def sound_speed_from_force():
    """c_0(F_0) = a sqrt(n K^(1/n) F_0^((n-1)/n)/m): :func:`sound_speed_lattice` with F_0 = K delta_0^n."""
    s = symbols()
    return sp.powsimp(sp.simplify(sound_speed_lattice().subs(s["delta_0"], static_extension())), force=True)


@derived
def _sound_speed():
    """(log C, p) of the power law c_0 = C F_0^p (:func:`sound_speed_from_force`)."""
    s = symbols()
    return (s["K"], s["n"], s["a"], s["m"]), power_law(sound_speed_from_force(), s["F_0"])


def linear_sound_speed(F_0, *, K, n, m, a):
    """Speed of small-amplitude long waves in a chain pre-stretched by a static force F_0.

    Parameters
    ----------
    F_0 : array_like
        Static contact force, N, >= 0 (0 gives 0 for n > 1: the "sonic vacuum").
    K : array_like
        Power-law prefactor, N/m^n (F = K delta^n, paper Eq. 4).
    n : array_like
        Power-law exponent, > 0.
    m : array_like
        Ring mass (or effective mass), kg.
    a : array_like
        Distance between adjacent ring centres, m (a = 2(R - r)).

    Returns
    -------
    ndarray
        c_0 = a sqrt(n K delta_0^(n-1)/m) with delta_0 = (F_0/K)^(1/n), in m/s.

    Notes
    -----
    Long-wave limit of the dispersion relation of the lattice linearised about the
    static extension delta_0 (:func:`lattice_dispersion`); the same speed follows from
    App. B Eq. (B17) linearised about xi_0 = delta_0/a (:func:`sound_speed_continuum`).
    It is the limit F_m -> F_0 of
    :func:`~ringchain.theory.solitary_wave_speed_prestressed`.

    Examples
    --------
    >>> float(linear_sound_speed(1.0, K=4.0, n=1.0, m=1.0, a=2.0))  # linear spring: a sqrt(K/m)
    4.0
    """
    F_0 = v.nonnegative("F_0", F_0, "N")
    K = v.positive("K", K, "N/m^n")
    n = v.positive("n", n)
    a = v.positive("a", a, "m")
    m = v.positive("m", m, "kg")
    v.broadcast_shape(F_0=F_0, K=K, n=n, a=a, m=m)
    if np.any((F_0 == 0) & (n < 1)):
        raise ValueError("F_0 = 0 with n < 1 gives an infinite sound speed; give F_0 > 0")
    with np.errstate(all="ignore"):
        log_coefficient, exponent = _sound_speed(K, n, a, m)
        # exp(log C + p log F_0) where F_0 > 0; C 0^p at F_0 = 0: 0 for n > 1, C for the linear chain.
        stretched = power_law_value(log_coefficient, exponent, np.where(F_0 > 0, F_0, 1.0))
        unstretched = np.where(exponent == 0, np.exp(log_coefficient), 0.0)
        speed = np.where(F_0 > 0, stretched, unstretched)
    return v.finite_result(speed, "c_0", "static force and chain parameters (K, n, m, a)")
