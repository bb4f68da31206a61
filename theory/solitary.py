r"""Compact solitary wave of the power-law chain and its speed (paper Sec. IV.C, App. B Eqs. (B18)-(B21)).

Continues :mod:`.longwave` from the strain equation (Eq. (B17)).  Step by step:

1. :func:`travelling_wave_ode` -- xi(x, t) = xi(tau), tau = x - V_s t turns Eq. (B17)
   into d^2/dtau^2 [V_s^2 xi - c_n^2 G(xi)] = 0 (:func:`travelling_wave_potential`);
   :func:`twice_integrated` integrates twice (``dsolve``) to Eq. (B19) with constants
   C_1, C_0; :func:`integration_constants` evaluates Eq. (B19) on a uniform state
   xi -> xi_inf: boundedness for all tau forces C_1 = 0, and C_0 = (V_s/c_n)^2 xi_inf -
   xi_inf^n, which vanishes on an unstretched chain (xi_inf = 0).
2. :func:`change_of_variables` -- xi = (y/sigma)^q, tau = mu/kappa.  The exponent
   q = 2/(n+1) is derived as the one that removes xi_tau^2 from the equation, kappa and
   sigma as the scales that make the coefficients of y and of y^((3-n)/(n+1)) equal to
   -1 and 1; :func:`oscillator_equation` and :func:`oscillator_potential` give
   y_mumu = -W'(y) with W = y^2/2 - (n+1)/4 y^(4/(n+1)) + C (n+1)/2 y^(2/(n+1)) (Eq. (B21);
   the last term, from C_0, is the pre-stretched chain's).
3. :func:`compact_solution` -- the ansatz xi = A |sin(omega tau)|^p in Eq. (B19): its
   residual is a sum of powers |sin|^p, |sin|^(n p) and |sin|^(n p - 2); a nontrivial
   balance needs n p - 2 = p, so p = 2/(n-1), and the two remaining coefficients fix
   omega and A.  :func:`profile_residual` substitutes the result back: the residual
   simplifies to 0 for symbolic n > 1 (SymPy proves it; the tests repeat the check
   with mpmath at 40 digits for irrational n, independently of the SymPy
   manipulations).  Every term of Eq. (B19) is a multiple of |sin|^p, so all vanish at
   the edges of a hump, and one hump glued to xi = 0 outside (the compact solitary
   wave) satisfies Eq. (B19) at every tau.
4. Speeds and profiles: :func:`speed_from_strain` (V_s(xi_max)),
   :func:`velocity_profile` (v = u_t = -V_s xi, so xi_max = -v_max/V_s),
   :func:`speed_from_velocity`, :func:`force_profile` (F = K (a xi)^n, delta ~ a xi),
   :func:`speed_from_force` (paper Eq. (8)), :func:`support_width` (pi/omega),
   :func:`centred_force_profile`.
5. The pre-stretched chain (a static strain xi_0 > 0 far from the wave, beyond the paper)
   continues from Eq. (B19) in :mod:`.prestressed`.

Numeric functions: :func:`solitary_wave_speed`, :func:`solitary_wave_speed_from_velocity`,
:func:`solitary_wave_width`, :func:`solitary_wave_profile`.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from . import longwave
from ._codegen import derived, sp
from ._forms import power_law, power_law_value, power_root, tidy_powers

__all__ = [
    "symbols",
    "travelling_wave_ode",
    "travelling_wave_potential",
    "twice_integrated",
    "eq19_residual",
    "integration_constants",
    "change_of_variables",
    "oscillator_equation",
    "oscillator_potential",
    "compact_solution",
    "strain_profile",
    "profile_residual",
    "speed_from_strain",
    "velocity_profile",
    "speed_from_velocity",
    "force_profile",
    "speed_from_force",
    "support_width",
    "centred_force_profile",
    "stable_profile",
    "solitary_wave_speed",
    "solitary_wave_speed_from_velocity",
    "solitary_wave_width",
    "solitary_wave_profile",
]


@functools.cache
def symbols():
    """Symbols of :mod:`.longwave` plus tau, V_s, the travelling-wave unknowns and amplitudes.

    ``X``, ``X_tau``, ``X_tautau`` stand for xi, xi_tau, xi_tautau in Eq. (B19); ``s`` is
    (V_s/c_n)^2; ``v_max`` is negative (the signed peak ring velocity of a tension wave
    running towards +x).
    """
    s = dict(longwave.symbols())
    tau = sp.Symbol("tau", real=True)
    V_s = sp.Symbol("V_s", positive=True)
    X = sp.Symbol("xi", positive=True)
    X_tau, X_tautau = sp.symbols("xi_tau xi_tautau", real=True)
    C_0, C_1 = sp.symbols("C_0 C_1", real=True)
    xi_max, xi_inf = sp.symbols("xi_max xi_inf", positive=True)
    v_max = sp.Symbol("v_max", negative=True)
    F_m = sp.Symbol("F_m", positive=True)
    y, mu = sp.symbols("y mu", positive=True)
    ratio = sp.Symbol("s", positive=True)
    s.update(
        tau=tau,
        V_s=V_s,
        X=X,
        X_tau=X_tau,
        X_tautau=X_tautau,
        C_0=C_0,
        C_1=C_1,
        s=ratio,
        xi_max=xi_max,
        xi_inf=xi_inf,
        v_max=v_max,
        F_m=F_m,
        y=y,
        mu=mu,
        f=sp.Function("f"),
    )
    return s


def _speed_ratio_squared():
    s = symbols()
    return s["V_s"] ** 2 / s["c_n"] ** 2


def _to_ratio(expr):
    """V_s -> c_n sqrt(s): express (V_s/c_n)^2 by the positive symbol s."""
    s = symbols()
    return expr.subs(s["V_s"], s["c_n"] * sp.sqrt(s["s"]))


def _from_ratio(expr):
    """s -> (V_s/c_n)^2, powers merged (all bases positive)."""
    s = symbols()
    return sp.powsimp(sp.powdenest(expr.subs(s["s"], _speed_ratio_squared()), force=True), force=True)


# --- 1. travelling wave and Eq. (B19) ----------------------------------------------------------


def _travelling(expr):
    """expr with xi(x, t) -> f(tau), tau = x - V_s t (chain rule of Eq. (B18))."""
    s = symbols()
    x, t, tau, V_s, f = s["x"], s["t"], s["tau"], s["V_s"], s["f"]
    return expr.subs(s["xi"], f(x - V_s * t)).doit().subs(x, tau + V_s * t).doit()


@functools.cache
def travelling_wave_ode():
    """Eq. (B17) for xi = f(tau), as an expression equal to zero."""
    equation = longwave.strain_equation()
    return sp.expand(_travelling(equation.lhs - equation.rhs))


@functools.cache
def travelling_wave_potential():
    """H(tau) = V_s^2 f - c_n^2 G(f), with :func:`travelling_wave_ode` = H''(tau) (checked)."""
    s = symbols()
    H = _travelling(s["V_s"] ** 2 * s["xi"] - s["c_n"] ** 2 * longwave.strain_flux())
    if sp.expand(sp.diff(H, s["tau"], 2) - travelling_wave_ode()) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the travelling-wave equation is not a second derivative")
    return H


@functools.cache
def twice_integrated():
    """Eq. (B19): (V_s/c_n)^2 xi = G(xi) + C_1 tau + C_0, as a SymPy ``Eq`` in f(tau).

    H'' = 0 is solved by ``dsolve``: H = c_n^2 (C_0 + C_1 tau) (constants renamed and
    scaled by c_n^2); dividing by c_n^2 gives the paper's form.
    """
    s = symbols()
    tau, c_n, f = s["tau"], s["c_n"], s["f"]
    h = sp.Function("h")
    general = sp.dsolve(sp.Derivative(h(tau), (tau, 2)), h(tau)).rhs
    constant, slope = general.coeff(tau, 0), general.coeff(tau, 1)
    general = general.subs({constant: c_n**2 * s["C_0"], slope: c_n**2 * s["C_1"]}, simultaneous=True)
    H = travelling_wave_potential()
    G = sp.expand((s["V_s"] ** 2 * f(tau) - H) / c_n**2)
    return sp.Eq(_speed_ratio_squared() * f(tau), G + sp.expand(general / c_n**2))


def eq19_residual(X=None, X_tau=None, X_tautau=None, C_0=None, C_1=None):
    """lhs - rhs of Eq. (B19) with xi, xi_tau, xi_tautau, C_0, C_1 replaced (symbols by default)."""
    s = symbols()
    tau, f = s["tau"], s["f"]
    equation = twice_integrated()
    residual = equation.lhs - equation.rhs
    values = {
        sp.Derivative(f(tau), (tau, 2)): s["X_tautau"] if X_tautau is None else X_tautau,
        sp.Derivative(f(tau), tau): s["X_tau"] if X_tau is None else X_tau,
    }
    residual = residual.subs(values).subs(f(tau), s["X"] if X is None else X)
    return residual.subs({s["C_0"]: s["C_0"] if C_0 is None else C_0, s["C_1"]: s["C_1"] if C_1 is None else C_1})


@functools.cache
def integration_constants(xi_inf=None):
    """{C_1: 0, C_0: (V_s/c_n)^2 xi_inf - xi_inf^n}: Eq. (B19) on a uniform state xi -> xi_inf.

    The residual must vanish for every tau, so its coefficients of tau^1 and tau^0 do.
    ``xi_inf = 0`` (unstretched chain) gives C_0 = 0; the default is the symbol xi_inf.
    """
    s = symbols()
    xi_inf = s["xi_inf"] if xi_inf is None else xi_inf
    residual = sp.expand(eq19_residual(X=xi_inf, X_tau=0, X_tautau=0))
    equations = [residual.coeff(s["tau"], 1), residual.coeff(s["tau"], 0)]
    return sp.solve(equations, [s["C_1"], s["C_0"]], dict=True)[0]


# --- 2. nonlinear oscillator (Eq. (B21)) ------------------------------------------------------------


def _power_coefficients(expr, base):
    """{exponent: coefficient} of expr as a sum of coefficient * base**exponent (base > 0)."""
    out: dict = {}
    for term in sp.Add.make_args(sp.expand(expr)):
        exponent = 0
        rest = []
        for factor in sp.Mul.make_args(tidy_powers(sp.factor(term))):
            b, e = factor.as_base_exp()
            if b == base:
                exponent += e
            else:
                rest.append(factor)
        exponent = sp.factor(sp.cancel(exponent))
        out[exponent] = out.get(exponent, 0) + sp.Mul(*rest)
    factored = {e: sp.factor(c) for e, c in out.items()}
    return {e: tidy_powers(c) for e, c in factored.items() if c != 0}


def _coefficient(coefficients, exponent):
    """The coefficient of base**exponent in the output of :func:`_power_coefficients`."""
    # The exponents are rational functions of n, whose difference cancel reduces to 0 exactly when they are equal.
    return next(c for e, c in coefficients.items() if sp.cancel(e - exponent) == 0)


def _roots_of_factors(product, x):
    """The roots in x of a product whose factors are linear in x or powers of positive bases (checked).

    The powers of positive bases (y, sigma) never vanish, so the product does exactly where a linear
    factor does; its root is read from the two coefficients (``solve`` takes 0.25 s).
    """
    roots = []
    for factor in sp.Mul.make_args(product):
        base, _ = factor.as_base_exp()
        if not base.has(x) or base.is_positive:
            continue
        if not (base.is_polynomial(x) and sp.degree(base, x) == 1):  # pragma: no cover - derivation check
            raise RuntimeError(f"the factor {factor} is not linear in {x}")
        roots.append(-base.coeff(x, 0) / base.coeff(x, 1))
    return roots


@functools.cache
def _change_of_variables_ratio():
    """:func:`change_of_variables` with (V_s/c_n)^2 written as the symbol s."""
    s = symbols()
    n, y = s["n"], s["y"]
    q, kappa, sigma = sp.symbols("q kappa sigma", positive=True)
    y_mu, y_mumu = sp.symbols("y_mu y_mumu", real=True)
    xi_of_y = (y / sigma) ** q
    xi_tau = sp.diff(xi_of_y, y) * y_mu * kappa
    xi_tautau = (sp.diff(xi_of_y, y, 2) * y_mu**2 + sp.diff(xi_of_y, y) * y_mumu) * kappa**2
    residual = _to_ratio(eq19_residual(xi_of_y, xi_tau, xi_tautau, C_1=0))
    residual = sp.expand(sp.powsimp(sp.expand(residual)))
    q_value = next(value for value in _roots_of_factors(sp.factor(residual.coeff(y_mu, 2)), q) if value != 0)
    # The residual is linear in y_mumu (it enters through xi_tautau alone): its root read from the two
    # coefficients, which ``solve`` takes 1 s to find.
    with_q = sp.expand(residual.subs(q, q_value))
    if sp.diff(with_q, y_mumu, 2) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the residual is not linear in y_mumu")
    y_mumu_value = -with_q.coeff(y_mumu, 0) / with_q.coeff(y_mumu, 1)
    coefficients = _power_coefficients(y_mumu_value, y)
    linear = _coefficient(coefficients, 1)
    kappa_value = next(k for k in sp.solve(sp.Eq(linear, -1), kappa, check=False) if k.is_positive)
    nonlinear = tidy_powers(sp.simplify(-_coefficient(coefficients, (3 - n) / (n + 1)) / linear))  # kappa cancels
    # nonlinear = c sigma^e (a monomial, checked): sigma = c^(-1/e), without ``solve`` (0.15 s).
    coefficient, exponent = nonlinear.as_coeff_exponent(sigma)
    if coefficient.has(sigma) or not exponent.has(n):  # pragma: no cover - derivation check
        raise RuntimeError(f"{nonlinear} is not a power of sigma")
    sigma_value = tidy_powers((1 / coefficient) ** (1 / exponent))
    # The scales substituted term by term into the coefficients already read (substituting them into the whole
    # quotient y_mumu_value and expanding gives a sum of 30 large fractions, 0.9 s to reduce again).
    values = {q: q_value, kappa: kappa_value, sigma: sigma_value}
    forcing = sp.Add(*(c.subs(values) * y**e for e, c in coefficients.items()))
    return dict(
        q=q_value,
        kappa=kappa_value,
        sigma=sigma_value,
        y=sp.powsimp(sp.expand_power_base(s["X"] ** (1 / q_value) * sigma_value, force=True), force=True),
        mu=kappa_value * s["tau"],
        y_mumu=sum(c * y**e for e, c in _power_coefficients(forcing, y).items()),
    )


@functools.cache
def change_of_variables():
    """The substitution of App. B: dict with q, kappa, sigma, y(xi), mu(tau) and y_mumu(y).

    xi = (y/sigma)^q and mu = kappa tau.  q is solved from the vanishing of the
    y_mu^2 coefficient (q = 2/(n+1)); kappa (= sqrt(6(n+1)/n)/a) from the coefficient of
    y in y_mumu being -1; sigma (= (c_n/V_s)^((n+1)/(n-1))) from the coefficient of
    y^((3-n)/(n+1)) being 1.  C_1 = 0 and C_0 is kept.
    """
    return {key: _from_ratio(value) for key, value in _change_of_variables_ratio().items()}


def oscillator_equation():
    """y_mumu(y) of Eq. (B21), C_0 kept: -y + y^((3-n)/(n+1)) - C_0 s^(-n/(n-1)) y^((1-n)/(n+1)).

    Written with s = (V_s/c_n)^2 (symbol ``s``).
    """
    return _change_of_variables_ratio()["y_mumu"]


@functools.cache
def oscillator_potential(prestressed=False):
    """W(y) with y_mumu = -W'(y) and W(0) = 0, s = (V_s/c_n)^2 (symbol ``s``).

    ``prestressed=False``: C_0 = 0, W = y^2/2 - (n+1)/4 y^(4/(n+1)) (App. B).
    ``prestressed=True``: C_0 kept, which adds C (n+1)/2 y^(2/(n+1)) with
    C = C_0 s^(-n/(n-1)) = C_0 (c_n/V_s)^(2n/(n-1)).
    """
    s = symbols()
    force = oscillator_equation()
    if not prestressed:
        force = force.subs(s["C_0"], 0)
    W = -sum(sp.integrate(c * s["y"] ** e, s["y"]) for e, c in _power_coefficients(force, s["y"]).items())
    return sum(sp.factor(c) * s["y"] ** e for e, c in _power_coefficients(W, s["y"]).items())


# --- 3. compact solution ------------------------------------------------------------------------


def _positive_square_root(expr, x):
    """The root x > 0 of expr = c_2 x^2 + c_0 (checked) when n > 1, without ``solve`` (0.35 s with the choice of root).

    x^2 = -c_0/c_2, factored; its square root is taken with n = 1 + nu, nu > 0, so that a factor
    (n - 1)^2 of x^2 gives the factor n - 1 of the positive root.
    """
    n = symbols()["n"]
    square = sp.Symbol("square", positive=True)
    quadratic = sp.expand(expr.subs(x, sp.sqrt(square)))
    if quadratic.has(x) or sp.diff(quadratic, square, 2) != 0:  # pragma: no cover - derivation check
        raise RuntimeError(f"{expr} is not c_2 {x}^2 + c_0")
    nu = sp.Symbol("nu", positive=True)
    value = sp.factor(-quadratic.coeff(square, 0) / quadratic.coeff(square, 1)).subs(n, 1 + nu)
    if not value.is_positive:  # pragma: no cover - derivation check
        raise RuntimeError(f"{x}^2 = {value} is not positive for n > 1")
    return sp.sqrt(value).subs(nu, n - 1)


def _root_of_two_powers(expr, x):
    """The root x > 0 of expr = c_1 x^(e + 1) + c_0 x^e (checked): x = -c_0/c_1, factored (``solve`` takes 0.25 s)."""
    terms: dict = {}
    for term in sp.Add.make_args(expr):
        coefficient, power = term.as_independent(x, as_Add=False)
        base, exponent = power.as_base_exp()
        if base != x:  # pragma: no cover - derivation check
            raise RuntimeError(f"{term} is not a power of {x}")
        exponent = sp.cancel(exponent)
        terms[exponent] = terms.get(exponent, 0) + coefficient
    if len(terms) != 2:  # pragma: no cover - derivation check
        raise RuntimeError(f"{expr} is not a sum of two powers of {x}")
    (first, c_first), (second, c_second) = terms.items()
    if sp.cancel(first - second) == 1:
        (first, c_first), (second, c_second) = (second, c_second), (first, c_first)
    if sp.cancel(second - first) != 1:  # pragma: no cover - derivation check
        raise RuntimeError(f"the powers of {x} in {expr} do not differ by one")
    return sp.factor(-c_first / c_second)


@functools.cache
def _compact_solution_ratio():
    s = symbols()
    n, tau = s["n"], s["tau"]
    amplitude, omega, p = sp.symbols("A omega p", positive=True)
    S = sp.Symbol("S", positive=True)  # sin(omega tau) on the hump 0 < omega tau < pi
    xi = amplitude * sp.sin(omega * tau) ** p
    residual = _to_ratio(eq19_residual(xi, sp.diff(xi, tau), sp.diff(xi, tau, 2), C_0=0, C_1=0))
    residual = residual.subs(sp.cos(omega * tau), sp.sqrt(1 - S**2)).subs(sp.sin(omega * tau), S)
    exponents = list(_power_coefficients(residual, S))
    # The linear term s A S^p can only be balanced by the dispersive term S^(n p - 2).
    if not any(sp.cancel(e - (n * p - 2)) == 0 for e in exponents):  # pragma: no cover - derivation check
        raise RuntimeError("no dispersive term S^(n p - 2) in the residual")
    # n p - 2 = p is linear in p: its root read from the two coefficients (``solve`` takes 0.3 s).
    balance = sp.expand(n * p - 2 - p)
    if sp.diff(balance, p, 2) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the balance of exponents is not linear in p")
    p_value = -balance.coeff(p, 0) / balance.coeff(p, 1)
    balanced = _power_coefficients(residual.subs(p, p_value), S)
    equations = [sp.expand(c) for c in balanced.values()]
    no_ratio = next(e for e in equations if not e.has(s["s"]))
    omega_value = _positive_square_root(no_ratio, omega)
    with_ratio = next(e for e in equations if e.has(s["s"])).subs(omega, omega_value)
    Z = sp.Symbol("Z", positive=True)  # A^(n-1)
    power = _root_of_two_powers(sp.powsimp(sp.powdenest(with_ratio.subs(amplitude, Z ** (1 / (n - 1))), force=True)), Z)
    return dict(p=p_value, omega=sp.factor(omega_value), xi_max=power ** (1 / (n - 1)), xi_max_power=power)


@functools.cache
def compact_solution():
    """Exponent p, wavenumber omega and amplitude xi_max of xi = xi_max |sin(omega tau)|^p.

    Returns a dict with p = 2/(n-1), omega = (n-1)/(n+1) sqrt(6(n+1)/n)/a and
    xi_max = ((n+1)/2 (V_s/c_n)^2)^(1/(n-1)), each solved from Eq. (B19) with C_0 = C_1 = 0
    (see the module docstring, step 3).
    """
    return {key: _from_ratio(value) for key, value in _compact_solution_ratio().items() if key != "xi_max_power"}


def strain_profile():
    """xi(tau) = xi_max |sin(omega tau)|^(2/(n-1)) (App. B, below Eq. (B21)), one hump compact."""
    s = symbols()
    sol = compact_solution()
    return sol["xi_max"] * sp.Abs(sp.sin(sol["omega"] * s["tau"])) ** sol["p"]


@functools.cache
def profile_residual():
    """Residual of Eq. (B19) (C_0 = C_1 = 0) for :func:`strain_profile` on the hump: 0 for symbolic n.

    On 0 < omega tau < pi, |sin| = sin; the residual, reduced with cos^2 = 1 - sin^2, is
    collected in powers of sin and each coefficient simplified.
    """
    s = symbols()
    tau = s["tau"]
    S = sp.Symbol("S", positive=True)
    sol = _compact_solution_ratio()
    xi = sol["xi_max"] * sp.sin(sol["omega"] * tau) ** sol["p"]
    residual = _to_ratio(eq19_residual(xi, sp.diff(xi, tau), sp.diff(xi, tau, 2), C_0=0, C_1=0))
    residual = residual.subs(sp.cos(sol["omega"] * tau), sp.sqrt(1 - S**2)).subs(sp.sin(sol["omega"] * tau), S)
    n = s["n"]
    total = 0
    for coefficient in _power_coefficients(residual, S).values():
        # Split exponents such as n/(n-1) = 1 + 1/(n-1) so that equal powers cancel.
        coefficient = tidy_powers(coefficient).replace(
            lambda e: e.is_Pow and e.exp.has(n), lambda e: sp.Pow(e.base, sp.apart(e.exp, n))
        )
        total += sp.simplify(sp.expand(sp.expand_power_exp(coefficient)))
    return total


@functools.cache
def speed_from_strain():
    """V_s(xi_max) = sqrt(2 c_n^2/(n+1) xi_max^(n-1)), solved from the amplitude of the solution."""
    s = symbols()
    ratio = sp.solve(
        sp.Eq(s["xi_max"] ** (s["n"] - 1), _compact_solution_ratio()["xi_max_power"]), s["s"], check=False
    )[0]
    return s["c_n"] * sp.sqrt(ratio)


def velocity_profile():
    """v = u_t = -V_s xi: the ring velocity of the travelling wave u(x - V_s t) (chain rule, Eq. (B18))."""
    s = symbols()
    U = sp.Function("U")
    u = U(s["x"] - s["V_s"] * s["t"])
    ratio = sp.simplify(sp.diff(u, s["t"]) / sp.diff(u, s["x"]))  # u_t / u_x = -V_s
    return ratio * strain_profile()


@functools.cache
def speed_from_velocity():
    """V_s(v_max) = (2 c_n^2/(n+1))^(1/(n+1)) (-v_max)^((n-1)/(n+1)), v_max < 0 the signed peak velocity.

    At the peak (|sin| = 1) :func:`velocity_profile` gives v_max = -V_s xi_max, so
    xi_max = -v_max/V_s; with :func:`speed_from_strain`, solved for V_s.
    """
    s = symbols()
    V_s = s["V_s"]
    peak = velocity_profile().subs(sp.Abs(sp.sin(compact_solution()["omega"] * s["tau"])), 1)
    peak = peak.subs(compact_solution()["xi_max"], s["xi_max"])
    xi_peak = sp.solve(sp.Eq(s["v_max"], peak), s["xi_max"])[0]
    equation = sp.Eq(V_s**2, speed_from_strain().subs(s["xi_max"], xi_peak) ** 2)
    return sp.powsimp(power_root(equation, V_s), force=True)


def force_profile():
    """F(tau) = K (a xi)^n, the contact force of the wave (delta ~ a xi, Sec. IV.C)."""
    s = symbols()
    return s["K"] * (s["a"] * strain_profile()) ** s["n"]


@functools.cache
def speed_from_force():
    """V_s(F_m): paper Eq. (8), from F_m = K (a xi_max)^n and :func:`speed_from_strain`."""
    s = symbols()
    xi_peak = sp.solve(sp.Eq(s["F_m"], s["K"] * (s["a"] * s["xi_max"]) ** s["n"]), s["xi_max"], check=False)[0]
    speed = speed_from_strain().subs(s["xi_max"], xi_peak).subs(s["c_n"], sp.sqrt(longwave.wave_speed_squared()))
    return tidy_powers(speed)


def support_width():
    """pi/omega: the length of one hump, the support of the compact wave (m)."""
    return sp.pi / compact_solution()["omega"]


@functools.cache
def centred_force_profile():
    """F(x)/F_m with x from the wave's centre: cos(omega x)^(2n/(n-1)) for |x| < pi/(2 omega), else 0.

    :func:`force_profile` divided by its peak value (|sin| = 1) and shifted by
    tau = x + pi/(2 omega), i.e. x = 0 at the peak.
    """
    s = symbols()
    omega = compact_solution()["omega"]
    S = sp.Symbol("S", positive=True)
    hump = force_profile().subs(sp.Abs(sp.sin(omega * s["tau"])), S)
    shape = tidy_powers(hump / hump.subs(S, 1))
    centred = tidy_powers(shape.subs(S, sp.sin(omega * s["x"] + sp.pi / 2)))
    return sp.Piecewise((centred, sp.Abs(omega * s["x"]) < sp.pi / 2), (0, True))


# --- numeric functions ----------------------------------------------------------------------------


def _in_si(expr):
    """expr with c_n^2 = K a^(n+1)/m (:func:`.longwave.wave_speed_squared`)."""
    s = symbols()
    return tidy_powers(expr.subs(s["c_n"], sp.sqrt(longwave.wave_speed_squared())))


@derived
def _speed():
    s = symbols()
    return (s["K"], s["n"], s["a"], s["m"]), power_law(speed_from_force(), s["F_m"])


@derived
def _speed_from_velocity():
    s = symbols()
    speed = sp.Symbol("v_speed", positive=True)  # |v_max| = -v_max
    return (s["K"], s["n"], s["a"], s["m"]), power_law(_in_si(speed_from_velocity().subs(s["v_max"], -speed)), speed)


@derived
def _width():
    s = symbols()
    return (s["n"], s["a"]), support_width()


def stable_profile():
    """:func:`centred_force_profile` times F_m, in the form the numeric code evaluates.

    cos(theta)^e with e = 2n/(n-1) is written exp(e log cos(theta_c)), where theta_c is
    theta on the hump and 0 outside.  NumPy evaluates both branches of a Piecewise, so
    the hump branch must stay finite everywhere: it never forms a negative base or
    log(0), and as n -> 1 (e -> infinity) exp(e log cos) underflows quietly to 0 away
    from the centre; its relative rounding error is about e times that of cos.
    """
    s = symbols()
    (hump, condition), _ = centred_force_profile().args
    if not (hump.is_Pow and isinstance(hump.base, sp.cos)):  # pragma: no cover - derivation check
        raise RuntimeError(f"unexpected profile {hump}")
    clipped = sp.Piecewise((hump.base.args[0], condition), (0, True))
    stable = sp.exp(hump.exp * sp.log(sp.cos(clipped)))
    return sp.Piecewise((s["F_m"] * stable, condition), (0, True))


@derived
def _profile():
    s = symbols()
    return (s["x"], s["F_m"], s["K"], s["n"], s["a"]), stable_profile()


def _chain_speed(function, variable, K, n, a, m):
    """exp(log C + p log variable) for a derived power law (log C, p) of the chain (K, n, a, m)."""
    with np.errstate(all="ignore"):
        log_coefficient, exponent = function(K, n, a, m)
        return power_law_value(log_coefficient, exponent, variable)


_CHAIN = "force, velocity and chain parameters (K, n, m, a)"


def solitary_wave_speed(F_m, *, K, n, m, a):
    """Speed of the compact solitary wave of peak contact force F_m (paper Eq. (8)).

    Parameters
    ----------
    F_m : array_like
        Peak contact force of the wave, N, > 0.
    K : array_like
        Power-law prefactor, N/m^n (F = K delta^n, paper Eq. 4).
    n : array_like
        Power-law exponent, > 1.
    m : array_like
        Ring mass (the paper uses the effective mass m_eff), kg.
    a : array_like
        Distance between adjacent ring centres, m (a = 2(R - r)).

    Returns
    -------
    ndarray
        V_s = a sqrt(2/(n+1)) (K^(1/n)/m)^(1/2) F_m^((n-1)/(2n)), m/s.

    Notes
    -----
    Derived from the lattice (App. B Eqs. (B15)-(B21); :func:`speed_from_force`), with the
    long-wave estimate delta_max = a xi_max of the peak contact extension.  As n -> 1
    it tends to the linear sound speed a sqrt(K/m).  Evaluated as exp(log C + p log F_m)
    from the derived power law V_s = C F_m^p, so no intermediate product overflows;
    raises ``ValueError`` if V_s itself is beyond double precision.

    Examples
    --------
    >>> round(float(solitary_wave_speed(8.0, K=1.0, n=3.0, m=1.0, a=1.0)), 6)  # sqrt(1/2) 8^(1/3)
    1.414214
    """
    F_m = v.positive("F_m", F_m, "N")
    chain = v.compact_wave_chain(K, n, a, m)
    v.broadcast_shape(F_m=F_m, K=chain[0], n=chain[1], a=chain[2], m=chain[3])
    return v.finite_result(_chain_speed(_speed, F_m, *chain), "V_s", _CHAIN)


def solitary_wave_speed_from_velocity(v_max, *, K, n, m, a):
    """Speed of the compact solitary wave from its peak ring velocity v_max (App. B).

    Parameters
    ----------
    v_max : array_like
        Peak ring velocity, m/s, nonzero.  Only its magnitude enters: the sign says which way
        the wave runs.  In the paper's convention (App. B, tension positive, the axis pointing
        away from the impact) the rings of a wave running towards +x move towards -x,
        u_t = -V_s xi, so the signed v_max of App. B is negative; a measured peak speed
        |v_max| > 0 gives the same V_s, and so does a wave running towards -x (v_max > 0).
    K, n, m, a : array_like
        Chain: prefactor (N/m^n), exponent (> 1), mass (kg), spacing (m), as in
        :func:`solitary_wave_speed`.

    Returns
    -------
    ndarray
        V_s = (2 c_n^2/(n+1))^(1/(n+1)) |v_max|^((n-1)/(n+1)) with c_n^2 = K a^(n+1)/m, m/s.

    Notes
    -----
    From xi_max = -v_max/V_s (Eq. (B18)) and V_s^2 = 2 c_n^2 xi_max^(n-1)/(n+1)
    (:func:`speed_from_velocity`).  Accepting the magnitude is the choice that cannot
    mislead: V_s depends only on |v_max|, a measured peak speed is positive, and the
    signed value of App. B is negative; ``v_max = 0`` (no wave) raises ``ValueError``.

    Examples
    --------
    >>> round(float(solitary_wave_speed_from_velocity(-1.0, K=1.0, n=3.0, m=1.0, a=1.0)), 6)  # (1/2)^(1/4)
    0.840896
    >>> round(float(solitary_wave_speed_from_velocity(1.0, K=1.0, n=3.0, m=1.0, a=1.0)), 6)  # the magnitude: same speed
    0.840896
    """
    v_max = v.as_float("v_max", v_max)
    speed = np.abs(v_max)
    if speed.size and not speed.min() > 0:
        raise ValueError(
            "v_max must be nonzero (m/s), got 0: it is the peak ring velocity of the wave (either sign; "
            "App. B's signed value is negative for a wave running away from the impact)"
        )
    chain = v.compact_wave_chain(K, n, a, m)
    v.broadcast_shape(v_max=v_max, K=chain[0], n=chain[1], a=chain[2], m=chain[3])
    return v.finite_result(_chain_speed(_speed_from_velocity, speed, *chain), "V_s", _CHAIN)


def solitary_wave_width(*, n, a):
    """Length of the support of the compact solitary wave, pi/omega (App. B).

    Parameters
    ----------
    n : array_like
        Power-law exponent, > 1.
    a : array_like
        Distance between adjacent ring centres, m.

    Returns
    -------
    ndarray
        pi/omega = pi a (n+1)/((n-1) sqrt(6(n+1)/n)), m: one hump of the sine profile.
        It grows without bound as n -> 1.

    Examples
    --------
    >>> round(float(solitary_wave_width(n=1.5, a=1.0)), 4)  # Hertz: 5 pi/sqrt(10), about five spacings
    4.9673
    """
    n = v.compact_wave_exponent(n)
    a = v.positive("a", a, "m")
    v.broadcast_shape(n=n, a=a)
    with np.errstate(all="ignore"):
        width = _width(n, a)
    return v.finite_result(width, "the width", "exponent and spacing")


def solitary_wave_profile(x, *, F_m, K, n, a):
    """Contact-force profile of the compact solitary wave, zero outside its support.

    Parameters
    ----------
    x : array_like
        Position along the chain measured from the wave's centre (its peak), m; the
        profile is even in x.
    F_m : array_like
        Peak contact force, N, > 0.
    K : array_like
        Power-law prefactor, N/m^n (validated; it cancels from the profile at given F_m).
    n : array_like
        Power-law exponent, > 1.
    a : array_like
        Distance between adjacent ring centres, m.

    Returns
    -------
    ndarray
        F(x) = F_m cos(omega x)^(2n/(n-1)) for |x| < pi/(2 omega), else 0, in N, with
        omega = (n-1)/(n+1) sqrt(6(n+1)/n)/a.

    Notes
    -----
    F = K (a xi)^n with the strain profile xi = xi_max |sin(omega tau)|^(2/(n-1)) of
    App. B (:func:`centred_force_profile`), evaluated in the stable form of
    :func:`stable_profile` (finite and warning-free as n -> 1).

    Examples
    --------
    >>> [round(float(F), 6) for F in solitary_wave_profile([0.0, 1.0, 3.0], F_m=2.0, K=1.0, n=1.5, a=1.0)]
    [2.0, 0.550693, 0.0]
    """
    x = v.as_float("x", x)
    F_m = v.positive("F_m", F_m, "N")
    K, n, a = v.compact_wave_chain(K, n, a)
    v.broadcast_shape(x=x, F_m=F_m, K=K, n=n, a=a)
    with np.errstate(all="ignore"):
        profile = _profile(x, F_m, K, n, a)
    return v.finite_result(profile, "the profile", "positions, force and chain parameters")
