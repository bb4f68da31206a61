r"""Weak disorder: rings that differ from one another (issue 23; beyond the paper, whose last sentence asks for it).

A chain whose spacing a_j, mass m_j and contact (stiffness k_j, or power-law prefactor
K_j at a common exponent n) vary from ring to ring.  Cell j is ring j and the contact
from ring j to ring j + 1 (the side away from the impact).  Relative spreads are about
the arithmetic means: K_j = <K> (1 + kappa_j), m_j = <m> (1 + mu_j), a_j = <a> (1 + alpha_j),
sigma_K^2 = <kappa^2> and so on.  Step by step (each step a function returning SymPy objects):

**Speed of long waves.**

1. :func:`cell_transfer_matrix` -- a harmonic motion exp(-i omega t) of ring j and
   contact j maps (u_j, F_{j-1}) to (u_{j+1}, F_j): T_j = [[1 - m_j omega^2/k_j, 1/k_j],
   [-m_j omega^2, 1]], det T_j = 1.
2. :func:`long_wave_transfer` -- by induction over the cells, the product of any number
   of them is, to first order in omega^2, [[1 + omega^2 alpha, C + omega^2 beta],
   [-omega^2 M, 1 + omega^2 gamma]] with alpha + gamma = -M C, M = sum m_j, C = sum 1/k_j:
   its trace is 2 - omega^2 M C whatever the order of the cells.
3. :func:`bloch_long_wave_speed` -- a chain repeating any such sequence (period
   Lambda = sum a_j) carries Bloch waves with cos(q Lambda) = trace/2; on the acoustic
   branch omega/q -> Lambda/sqrt(M C).
4. :func:`homogenised_constants`, :func:`homogenised_wave_equation` -- the homogenised
   medium: a window of many cells, short beside the wavelength, carries one force F
   (its inertia is of relative order (a/L)^2), so its extension is the sum of the
   contacts' extensions F/k_j; its mass per length is sum m/sum a and its stiffness
   per length sum a/sum(1/k).  The plane waves of rho u_tt = E u_xx travel at
   :func:`effective_medium_speed_symbolic` c = <a>/sqrt(<m> <1/k>), the same as step 3
   (checked).  For the power-law contact (:func:`effective_contact_law`) the window's
   extension is F^(1/n) sum K_j^(-1/n): the homogenised chain is the uniform chain with
   spacing <a>, mass <m> and K_eff = <K^(-1/n)>^(-n), whose compact wave (Eq. (8))
   travels at :func:`effective_solitary_speed`.
5. :func:`harmonic_mean_speed_symbolic`, :func:`harmonic_solitary_speed` -- the other
   estimate: each cell crossed at its own local speed, a_j/c_j = sqrt(m_j/k_j) (the
   spacing cancels), mean speed <a>/<sqrt(m/k)>: the length-weighted harmonic mean of
   the local speeds, the ray (WKB) time of flight of :func:`.linear.linear_travel_time`.
   For the compact wave a_j/V_j = sqrt((n+1)/2) sqrt(m_j) K_j^(-1/(2n)) F^(-(n-1)/(2n)).
6. :func:`effective_medium_shift`, :func:`harmonic_mean_shift`, :func:`speed_contrast`
   -- both to second order in the spreads, at a given force and about the uniform chain
   with the arithmetic means: V_EM/V - 1 = -(n+1)/(4 n^2) sigma_K^2 (mass and spacing
   spreads do not enter at any order: only their means do), V_H/V - 1 = sigma_m^2/8
   - (2n+1)/(8 n^2) sigma_K^2 + rho sigma_m sigma_K/(4n), and V_H/V_EM - 1 = sigma_Z^2/2,
   sigma_Z^2 the variance of ln Z, Z = sqrt(m k) the impedance (:func:`impedance_variance`;
   Z_{j+1}/Z_j does not depend on the force, :func:`impedance_ratio`).  So the harmonic
   mean is the larger unless the impedance is the same in every cell (m proportional to
   1/k, not to k: with m proportional to k every local speed is the same, yet the
   effective medium is slower by the factor 1/sqrt(<k><1/k>)).  The linear chain is n = 1
   with K -> k: V_EM/V - 1 = -sigma_k^2/2.  The errors are of third order in the spreads
   (fourth for symmetric distributions).

Which one holds?  A linear long pulse (many rings wide) runs at the effective-medium
speed of the cells it has crossed: the Bloch limit for periodic chains, and the arrival
of a pulse through a random chain (tests/theory/test_scattering.py, transfer matrices).
The compact wave is a few rings wide and strongly nonlinear; on the power-law lattice
(tests/theory/test_attenuation.py: n = 1.2 and 1.5, sigma_m = 0.15 and sigma_K = 0.2 together) its travel time
over 200 rings is within 0.3 % of the harmonic-mean estimate (0.1 % and 0.2 %) and 0.7 %
shorter than the effective-medium one, the two estimates being sigma_Z^2/2 = 0.5-0.6 %
apart: it crosses each ring at its local speed.

**Scattering and the loss of the leading pulse** continue in :mod:`.scattering` (steps 7-9:
reflections at the junctions of cells, the localization length of harmonic waves, the spreading of
a long pulse) and :mod:`.attenuation` (steps 10-11: the compact wave's loss of peak force and its
slowing).

Orders and limits: leading order in a/L (the pulse long beside a ring); the expansions to
second order in the spreads.

Signatures follow the package's convention (:mod:`ringchain.theory`): what a function is evaluated at
comes first and may be positional (the force F_m, the frequency omega, the distance); everything else is
keyword-only.  The chain's parameters come in the package's one order K, n, m, a, with k (the stiffness of
a linear contact, the prefactor of the n = 1 law) where K stands; the choice ``estimate=`` first, as
``model=`` in :func:`~ringchain.theory.dispersion`; the wave's own speed V0 before the chain's parameters,
as F_m before K in :func:`~ringchain.theory.solitary_wave_profile`.  What describes the disorder comes last:
the spreads sigma_K (or sigma_k), sigma_m in the order of K and m, the correlation, sigma_Z, and
attenuation_length.  These are not in the package's list of chain parameters, and are keyword-only for the
same reason: two relative spreads (or a spread and a spacing) have the same sign and range, so a swapped
positional call would answer silently.  Functions of the chain alone (:func:`effective_medium_speed`,
:func:`harmonic_mean_speed`, :func:`disorder_speed_shift`, :func:`.scattering.impedance_spread`,
:func:`.scattering.chain_impedance_spread`, :func:`.attenuation.disorder_attenuation_length`) take keywords only, like
:func:`~ringchain.theory.solitary_wave_width`.

Numeric functions: :func:`effective_medium_speed`, :func:`harmonic_mean_speed`,
:func:`disordered_solitary_wave_speed`, :func:`disorder_speed_shift`; :func:`equations` collects the
displayed forms.  The impedance spread sigma_Z of a chain is in :mod:`.scattering`.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from . import linear, longwave, pulse, solitary
from ._codegen import derived, sp
from ._forms import merge_powers

__all__ = [
    "ESTIMATES",
    "symbols",
    "cell_transfer_matrix",
    "long_wave_transfer",
    "bloch_long_wave_speed",
    "homogenised_constants",
    "homogenised_wave_equation",
    "effective_medium_speed_symbolic",
    "effective_contact_law",
    "effective_solitary_speed",
    "harmonic_mean_speed_symbolic",
    "harmonic_solitary_speed",
    "expectation",
    "effective_medium_shift",
    "harmonic_mean_shift",
    "impedance_ratio",
    "impedance_variance",
    "speed_contrast",
    "equations",
    "effective_medium_speed",
    "harmonic_mean_speed",
    "disordered_solitary_wave_speed",
    "disorder_speed_shift",
]

#: The two estimates of the mean speed over a disordered chain (step 6 of the module docstring).
ESTIMATES = ("effective-medium", "harmonic-mean")


@functools.cache
def symbols():
    """Symbols of :mod:`.pulse` plus those of the disordered chain.

    ``k`` (contact stiffness, N/m); the means ``mean_a``, ``mean_m``, ``mean_compliance``
    (<1/k>), ``mean_K_compliance`` (<K^(-1/n)>), ``mean_transit`` (<sqrt(m/k)>), ``mean_ray``
    (<sqrt(m) K^(-1/(2n))>); the relative deviations ``kappa``, ``mu``, ``alpha`` of K (or k),
    m and a; their spreads ``sigma_K``, ``sigma_m``, ``sigma_a`` and correlations ``rho_mK``,
    ``rho_aK``, ``rho_am``; ``sigma_Z`` (spread of ln Z), ``theta`` (phase per ring), ``N``
    (rings), ``distance``, ``ell`` (a decay length) and ``V_0``.
    """
    s = dict(pulse.symbols())

    def positive(name):
        return sp.Symbol(name, positive=True)

    def nonnegative(name):
        return sp.Symbol(name, nonnegative=True)

    s.update(
        k=positive("k"),
        mean_a=positive(r"\langle a\rangle"),
        mean_m=positive(r"\langle m\rangle"),
        mean_compliance=positive(r"\langle k^{-1}\rangle"),
        mean_K_compliance=positive(r"\langle K^{-1/n}\rangle"),
        mean_transit=positive(r"\langle\sqrt{m/k}\rangle"),
        mean_ray=positive(r"\langle\sqrt{m}\,K^{-1/(2n)}\rangle"),
        kappa=sp.Symbol("kappa", real=True),
        mu=sp.Symbol("mu", real=True),
        alpha=sp.Symbol("alpha", real=True),
        sigma_K=nonnegative("sigma_K"),
        sigma_m=nonnegative("sigma_m"),
        sigma_a=nonnegative("sigma_a"),
        rho_mK=sp.Symbol("rho_mK", real=True),
        rho_aK=sp.Symbol("rho_aK", real=True),
        rho_am=sp.Symbol("rho_am", real=True),
        sigma_Z=nonnegative("sigma_Z"),
        sigma_k=nonnegative("sigma_k"),
        rho=sp.Symbol("rho", real=True),
        theta=positive("theta"),
        N=sp.Symbol("N", positive=True, integer=True),
        distance=positive("x"),
        ell=positive(r"\ell"),
        V_0=positive("V_0"),
    )
    return s


# --- 1.-3. transfer matrices and the Bloch limit --------------------------------------------------------


@functools.cache
def cell_transfer_matrix():
    """T_j: (u_{j+1}, F_j) = T_j (u_j, F_{j-1}) for ring j (mass m) and contact j (stiffness k), symbols m, k, omega.

    From the equation of motion of ring j in harmonic motion, -m omega^2 u_j = F_j - F_{j-1}
    (F_j the tension of contact j), and the contact law F_j = k (u_{j+1} - u_j), solved for
    (u_{j+1}, F_j).
    """
    s = symbols()
    m, k, omega = s["m"], s["k"], s["omega"]
    u, F_before, F_after, u_after = sp.symbols("u_j F_before F_after u_after")
    equations = [sp.Eq(-m * omega**2 * u, F_after - F_before), sp.Eq(F_after, k * (u_after - u))]
    solution = sp.solve(equations, [F_after, u_after], dict=True)[0]
    matrix = sp.Matrix([solution[u_after], solution[F_after]]).jacobian([u, F_before])
    if sp.simplify(matrix.det() - 1) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the transfer matrix of a cell does not have determinant 1")
    return matrix.applyfunc(sp.expand)


@functools.cache
def long_wave_transfer():
    """(M, C, trace): any product of cells has trace 2 - omega^2 M C + O(omega^4), M = sum m, C = sum 1/k.

    Induction on the number of cells, with W = omega^2.  Hypothesis: the product P of the
    first cells is [[1 + W alpha, C + W beta], [-W M, 1 + W gamma]] + O(W^2) with
    alpha + gamma = -M C.  Base: one cell (:func:`cell_transfer_matrix`), M = m, C = 1/k.
    Step: T P, T the next cell, has the same form with M + m and C + 1/k.  Both are checked
    here; the returned trace is in terms of the symbols M, C and omega.
    """
    s = symbols()
    m, k, omega = s["m"], s["k"], s["omega"]
    W = sp.Symbol("W", positive=True)
    M, C = sp.symbols("M C", positive=True)
    alpha, beta = sp.symbols("alpha_P beta_P")
    cell = cell_transfer_matrix().subs(omega, sp.sqrt(W))

    def first_order(matrix):
        expanded = matrix.applyfunc(sp.expand)
        return expanded.applyfunc(lambda e: e.coeff(W, 0)), expanded.applyfunc(lambda e: e.coeff(W, 1))

    def has_form(matrix, M_value, C_value):
        zeroth, first = first_order(matrix)
        return (
            zeroth == sp.Matrix([[1, C_value], [0, 1]])
            and sp.simplify(first[1, 0] + M_value) == 0
            and sp.simplify(first[0, 0] + first[1, 1] + M_value * C_value) == 0
        )

    hypothesis = sp.Matrix([[1 + W * alpha, C + W * beta], [-W * M, 1 + W * (-M * C - alpha)]])
    if not has_form(cell, m, 1 / k):  # pragma: no cover - derivation check
        raise RuntimeError("one cell is not of the induction's form")
    if not has_form(cell * hypothesis, M + m, C + 1 / k):  # pragma: no cover - derivation check
        raise RuntimeError("the induction step fails")
    trace = sp.expand(hypothesis.trace()).subs(W, omega**2)  # alpha cancels: 2 - omega^2 M C
    if trace.has(alpha):  # pragma: no cover - derivation check
        raise RuntimeError("the trace depends on the order of the cells")
    return M, C, trace


@functools.cache
def bloch_long_wave_speed():
    """(Lambda, M, C, c): the long-wave speed c = Lambda/sqrt(M C) of a chain repeating any sequence of cells.

    Bloch's theorem for a period of transfer matrix P (det P = 1): cos(q Lambda) = tr P/2,
    Lambda the period's length; with :func:`long_wave_transfer` and omega = c q on the
    acoustic branch, the q^2 terms fix c.
    """
    s = symbols()
    q, omega = s["q"], s["omega"]
    M, C, trace = long_wave_transfer()
    Lambda, c = sp.Symbol("Lambda", positive=True), sp.Symbol("c", positive=True)
    bloch = sp.series(sp.cos(q * Lambda), q, 0, 3).removeO() - (trace / 2).subs(omega, c * q)
    speed = [root for root in sp.solve(sp.expand(bloch).coeff(q, 2), c) if root.is_positive]
    if len(speed) != 1:  # pragma: no cover - derivation check
        raise RuntimeError(f"the long-wave limit gave {speed}")
    return Lambda, M, C, speed[0]


# --- 4. the homogenised medium ----------------------------------------------------------------------------


def _window():
    """(j, a_j, m_j, total): the index, indexed spacing and mass of cell j, and the sum over a window of N cells."""
    s = symbols()
    j = sp.Symbol("j", integer=True, positive=True)
    a, m = sp.IndexedBase("a", positive=True), sp.IndexedBase("m", positive=True)

    def total(expr):
        return sp.factor_terms(sp.Sum(merge_powers(expr), (j, 1, s["N"])))

    return j, a[j], m[j], total


def _as_means(expr, values):
    """expr with every window sum replaced by N times the mean it stands for ({sum: mean symbol})."""
    N = symbols()["N"]
    return sp.simplify(expr.subs({total: N * mean for total, mean in values.items()}))


@functools.cache
def homogenised_constants():
    """(rho, E): mass per length and axial stiffness of the homogenised linear chain, in terms of the means.

    A window of N cells carries one force F (step 4 of the module docstring); contact j
    stretches by the delta_j that solves F = k_j delta_j, the window by their sum, so its
    strain is sum(delta_j)/sum(a_j) and E = F/strain; rho = sum(m_j)/sum(a_j).
    """
    s = symbols()
    j, a_j, m_j, total = _window()
    k = sp.IndexedBase("k", positive=True)
    F, delta, E = sp.symbols("F delta E", positive=True)
    extension = total(sp.solve(sp.Eq(F, k[j] * delta), delta)[0])
    strain = extension / total(a_j)
    stiffness = sp.solve(sp.Eq(F, E * strain), E)[0]
    means = {total(a_j): s["mean_a"], total(m_j): s["mean_m"], total(1 / k[j]): s["mean_compliance"]}
    return _as_means(total(m_j) / total(a_j), means), _as_means(stiffness, means)


@functools.cache
def homogenised_wave_equation():
    """(equation, c): rho u_tt = E u_xx of :func:`homogenised_constants` and the speed of its plane waves."""
    s = symbols()
    x, t, q, omega = s["x"], s["t"], s["q"], s["omega"]
    rho, E = homogenised_constants()
    u = sp.Function("u")(x, t)
    equation = sp.Eq(rho * sp.diff(u, t, 2), E * sp.diff(u, x, 2))
    wave = sp.exp(sp.I * (q * x - omega * t))
    residual = sp.simplify((equation.lhs - equation.rhs).subs(u, wave).doit() / wave)
    speed = [root / q for root in sp.solve(residual, omega) if (root / q).is_positive]
    if len(speed) != 1:  # pragma: no cover - derivation check
        raise RuntimeError(f"the homogenised wave equation gave {speed}")
    return equation, sp.simplify(speed[0])


@functools.cache
def effective_medium_speed_symbolic():
    """c = <a>/sqrt(<m> <1/k>) of the homogenised chain; equal to :func:`bloch_long_wave_speed` (checked)."""
    s = symbols()
    _, c = homogenised_wave_equation()
    Lambda, M, C, bloch = bloch_long_wave_speed()
    N = s["N"]
    periodic = bloch.subs({Lambda: N * s["mean_a"], M: N * s["mean_m"], C: N * s["mean_compliance"]})
    if sp.simplify(periodic - c) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the homogenised speed is not the Bloch long-wave limit")
    return c


@functools.cache
def effective_contact_law():
    """K_eff = <K^(-1/n)>^(-n): the contact of the uniform chain that stretches like a window of power-law contacts.

    The window carries F; contact j stretches by (F/K_j)^(1/n), the window by
    F^(1/n) sum K_j^(-1/n); N equal contacts K_eff stretch alike when F = K_eff (extension/N)^n.
    """
    s = symbols()
    n = s["n"]
    j, _, _, total = _window()
    K = sp.IndexedBase("K", positive=True)
    F, delta, K_eff = sp.symbols("F delta K_eff", positive=True)
    extension = total(sp.solve(sp.Eq(F, K[j] * delta**n), delta)[0])
    value = sp.solve(sp.Eq(F, K_eff * (extension / s["N"]) ** n), K_eff)[0]
    value = _as_means(merge_powers(value), {total(K[j] ** (-1 / n)): s["mean_K_compliance"]})
    return merge_powers(value)


def _homogenised_chain(expr):
    """expr of a uniform chain (K, a, m) evaluated on the homogenised one (K_eff, <a>, <m>)."""
    s = symbols()
    values = {s["K"]: effective_contact_law(), s["a"]: s["mean_a"], s["m"]: s["mean_m"]}
    return merge_powers(expr.subs(values, simultaneous=True))


@functools.cache
def effective_solitary_speed():
    """V_EM(F_m): Eq. (8) (:func:`.solitary.speed_from_force`) on the homogenised chain.

    Checked: its linear limit on a chain pre-stretched by F (:func:`.longwave.sound_speed_from_force`
    on the homogenised chain) is :func:`effective_medium_speed_symbolic` with k_j the contact
    stiffness n K_j^(1/n) F^((n-1)/n), so that <1/k> = <K^(-1/n)> F^((1-n)/n)/n.
    """
    s = symbols()
    prestretched = _homogenised_chain(longwave.sound_speed_from_force()).subs(s["F_0"], s["F_m"])
    scale = 1 / linear.contact_stiffness().subs(s["F_0"], s["F_m"]) * s["K"] ** (1 / s["n"])
    linear_limit = effective_medium_speed_symbolic().subs(s["mean_compliance"], scale * s["mean_K_compliance"])
    if sp.simplify(merge_powers(prestretched / linear_limit)) != 1:  # pragma: no cover - derivation check
        raise RuntimeError("the homogenised power-law chain does not linearise to the effective medium")
    return _homogenised_chain(solitary.speed_from_force())


def _cell_time(speed, per_cell):
    """(rest, part): a/speed split into the factor of the per-cell quantities ``per_cell`` and the rest."""
    s = symbols()
    time = merge_powers(sp.simplify(s["a"] / speed))
    rest, part = time.as_independent(*per_cell, as_Add=False)
    if rest.has(*per_cell) or time.has(s["a"]):  # pragma: no cover - derivation check
        raise RuntimeError(f"the time per cell {time} does not separate")
    return rest, part


@functools.cache
def harmonic_mean_speed_symbolic():
    """c_H = <a>/<sqrt(m/k)>: the length-weighted harmonic mean of the local speeds a sqrt(k/m) of the cells.

    The local speed is :func:`.longwave.sound_speed_from_force` of a linear contact (n = 1,
    K = k); the time to cross cell j, a_j/c_j, is sqrt(m_j/k_j) (the spacing cancels).
    """
    s = symbols()
    local = longwave.sound_speed_from_force().subs({s["n"]: 1, s["K"]: s["k"]})
    rest, part = _cell_time(local, (s["m"], s["k"]))
    if sp.simplify(part - sp.sqrt(s["m"] / s["k"])) != 0:  # pragma: no cover - derivation check
        raise RuntimeError(f"the crossing time of a cell is {part}")
    return s["mean_a"] / (rest * s["mean_transit"])


@functools.cache
def harmonic_solitary_speed():
    """V_H(F_m) = <a>/<a/V_s>: the harmonic mean of the local Eq. (8) speeds at one force F_m.

    a_j/V_s(F_m; K_j, a_j, m_j) = sqrt((n+1)/2) sqrt(m_j) K_j^(-1/(2n)) F_m^(-(n-1)/(2n)).
    """
    s = symbols()
    rest, part = _cell_time(solitary.speed_from_force(), (s["m"], s["K"]))
    if sp.simplify(part - sp.sqrt(s["m"]) * s["K"] ** (-1 / (2 * s["n"]))) != 0:  # pragma: no cover
        raise RuntimeError(f"the crossing time of a cell is {part}")
    return merge_powers(s["mean_a"] / (rest * s["mean_ray"]))


# --- 6. expansions in the spreads -------------------------------------------------------------------------


def _epsilon():
    return sp.Symbol("epsilon", positive=True)


def expectation(expr, order=2):
    """E[expr] to ``order`` in the relative deviations kappa, mu, alpha (zero means), with a bookkeeping epsilon.

    Each deviation is scaled by epsilon, ``expr`` expanded in epsilon through ``order``, and
    the monomials replaced by their moments: <kappa^2> = sigma_K^2, <mu kappa> =
    rho_mK sigma_m sigma_K, ...; third and higher moments are beyond second order.  The
    result keeps epsilon (epsilon^2 marks the second-order terms).
    """
    s = symbols()
    if order > 2:
        raise ValueError("moments beyond the second are not defined here")
    eps = _epsilon()
    deviations = (s["kappa"], s["mu"], s["alpha"])
    scaled = expr.subs({d: eps * d for d in deviations}, simultaneous=True)
    series = sp.expand(sp.series(scaled, eps, 0, order + 1).removeO())
    spread = {s["kappa"]: s["sigma_K"], s["mu"]: s["sigma_m"], s["alpha"]: s["sigma_a"]}
    correlation = {
        frozenset((s["mu"], s["kappa"])): s["rho_mK"],
        frozenset((s["alpha"], s["kappa"])): s["rho_aK"],
        frozenset((s["alpha"], s["mu"])): s["rho_am"],
    }
    total = 0
    for term in sp.Add.make_args(series):
        powers = term.as_powers_dict()
        present = [d for d in deviations if powers.get(d, 0)]
        coefficient = term / sp.Mul(*(d ** powers[d] for d in present))
        degree = sum(powers[d] for d in present)
        if degree == 0:
            total += coefficient
        elif degree == 2 and len(present) == 1:
            total += coefficient * spread[present[0]] ** 2
        elif degree == 2:
            first, second = present
            total += coefficient * correlation[frozenset(present)] * spread[first] * spread[second]
        elif degree != 1:  # pragma: no cover - derivation check (epsilon keeps degrees <= order)
            raise RuntimeError(f"unexpected term {term}")
    return total


def _disordered_values():
    """Per-cell values K_bar (1 + kappa), m_bar (1 + mu), a_bar (1 + alpha), the bars written K, m, a."""
    s = symbols()
    return {s["K"]: s["K"] * (1 + s["kappa"]), s["m"]: s["m"] * (1 + s["mu"]), s["a"]: s["a"] * (1 + s["alpha"])}


def _mean_of(per_cell):
    """E[per_cell] of a per-cell expression in K, m, a, to second order in the spreads (epsilon kept)."""
    return expectation(merge_powers(per_cell.subs(_disordered_values(), simultaneous=True)))


def _relative_shift(speed, means):
    """speed(means)/speed(uniform) - 1 to second order: each mean symbol -> E[its per-cell expression]."""
    s = symbols()
    eps = _epsilon()
    uniform = speed.subs({mean: per_cell for mean, per_cell in means.items()})
    disordered = speed.subs({mean: _mean_of(per_cell) for mean, per_cell in means.items()})
    ratio = merge_powers(sp.simplify(disordered / uniform))
    shift = sp.series(ratio, eps, 0, 3).removeO().subs(eps, 1) - 1
    if shift.has(s["K"], s["m"], s["a"], s["F_m"]):  # pragma: no cover - derivation check
        raise RuntimeError(f"the relative shift {shift} depends on the means")
    return sp.expand(sp.simplify(shift))


@functools.cache
def effective_medium_shift():
    """V_EM/V - 1 at given force, to second order in the spreads: -(n+1)/(4 n^2) sigma_K^2.

    :func:`effective_solitary_speed` with <a>, <m>, <K^(-1/n)> the expectations of the
    per-cell a, m, K^(-1/n) over the uniform chain with the means (K, m, a).
    """
    s = symbols()
    n = s["n"]
    means = {s["mean_a"]: s["a"], s["mean_m"]: s["m"], s["mean_K_compliance"]: s["K"] ** (-1 / n)}
    return _relative_shift(effective_solitary_speed(), means)


@functools.cache
def harmonic_mean_shift():
    """V_H/V - 1 at given force, to second order.

    sigma_m^2/8 - (2n+1)/(8 n^2) sigma_K^2 + rho_mK sigma_m sigma_K/(4n): :func:`harmonic_solitary_speed` with
    <sqrt(m) K^(-1/(2n))> the expectation over the cells.
    """
    s = symbols()
    n = s["n"]
    means = {s["mean_a"]: s["a"], s["mean_ray"]: sp.sqrt(s["m"]) * s["K"] ** (-1 / (2 * n))}
    return _relative_shift(harmonic_solitary_speed(), means)


@functools.cache
def impedance_ratio():
    """Z_{j+1}/Z_j of neighbouring cells at one force: sqrt(m_{j+1}/m_j) (K_{j+1}/K_j)^(1/(2n)), free of the force.

    Z = sqrt(m k) (:func:`.linear.impedance`) with the contact stiffness k = n K^(1/n) F^((n-1)/n)
    (:func:`.linear.contact_stiffness`) at the force F that both cells carry.
    """
    s = symbols()
    K2, m2 = sp.symbols("K_2 m_2", positive=True)
    impedance = sp.sqrt(s["m"] * linear.contact_stiffness())
    ratio = merge_powers(sp.simplify(impedance.subs({s["K"]: K2, s["m"]: m2}, simultaneous=True) / impedance))
    if ratio.has(s["F_0"]):  # pragma: no cover - derivation check
        raise RuntimeError("the impedance ratio depends on the force")
    return ratio, K2, m2


@functools.cache
def impedance_variance():
    """sigma_Z^2 = Var(ln Z) to second order: sigma_m^2/4 + sigma_K^2/(4 n^2) + rho_mK sigma_m sigma_K/(2n).

    ln(Z_j/Z_bar) from :func:`impedance_ratio` (Z_bar the uniform chain's), expanded to first
    order in the deviations; its mean vanishes at that order, so the variance is E[(ln Z/Z_bar)^2].
    """
    s = symbols()
    ratio, K2, m2 = impedance_ratio()
    # Cell j (K (1 + kappa), m (1 + mu)) against the uniform chain's cell (K, m).
    deviating = ratio.subs({K2: s["K"] * (1 + s["kappa"]), m2: s["m"] * (1 + s["mu"])})
    log_ratio = sp.expand_log(sp.log(merge_powers(deviating)), force=True)
    eps = _epsilon()
    linear_part = sp.series(log_ratio.subs({d: eps * d for d in (s["kappa"], s["mu"])}), eps, 0, 2).removeO()
    return sp.expand(expectation(linear_part.subs(eps, 1) ** 2).subs(eps, 1))


@functools.cache
def speed_contrast():
    """V_H/V_EM - 1 to second order; equal to sigma_Z^2/2 (:func:`impedance_variance`, checked)."""
    eps = _epsilon()
    contrast = sp.expand(sp.series((1 + harmonic_mean_shift() * eps) / (1 + effective_medium_shift() * eps), eps, 0, 2))
    contrast = sp.expand(contrast.removeO().subs(eps, 1) - 1)
    if sp.simplify(contrast - impedance_variance() / 2) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the two estimates do not differ by half the variance of ln Z")
    return contrast


# --- the displayed equations -----------------------------------------------------------------------------


@functools.cache
def equations():
    """The forms a book page displays, each a SymPy ``Eq`` from the derivations above (dict by name).

    The scattering's and the attenuation's are in :func:`.scattering.equations` and
    :func:`.attenuation.equations`.
    """
    V_EM, V_H, V = sp.symbols(r"V_{EM} V_H V", positive=True)
    c_EM, c_H = sp.symbols(r"c_{EM} c_H", positive=True)
    sigma_Z2 = sp.Symbol(r"\sigma_Z^2", nonnegative=True)
    return {
        "transfer_matrix": sp.Eq(
            sp.MatrixSymbol("T_j", 2, 2), sp.ImmutableMatrix(cell_transfer_matrix()), evaluate=False
        ),
        "long_wave_trace": sp.Eq(sp.Symbol(r"\mathrm{tr}\,P"), long_wave_transfer()[2]),
        "effective_medium_speed": sp.Eq(c_EM, effective_medium_speed_symbolic()),
        "harmonic_mean_speed": sp.Eq(c_H, harmonic_mean_speed_symbolic()),
        "effective_contact": sp.Eq(sp.Symbol(r"K_{\mathrm{eff}}"), effective_contact_law()),
        "effective_solitary_speed": sp.Eq(V_EM, effective_solitary_speed()),
        "harmonic_solitary_speed": sp.Eq(V_H, harmonic_solitary_speed()),
        "effective_medium_shift": sp.Eq(V_EM / V - 1, effective_medium_shift()),
        "harmonic_mean_shift": sp.Eq(V_H / V - 1, harmonic_mean_shift()),
        "impedance_variance": sp.Eq(sigma_Z2, impedance_variance()),
        "speed_contrast": sp.Eq(V_H / V_EM - 1, speed_contrast()),
    }


# --- numeric functions ------------------------------------------------------------------------------------


def _logs(expr, names):
    """(log symbols, log(expr) in them): log(expr) expanded, log(symbol) -> a new symbol, for positive symbols."""
    logarithm = sp.expand(sp.expand_log(sp.log(expr), force=True))
    logs = tuple(sp.Symbol(f"log_{name}", real=True) for name in names)
    s = symbols()
    logarithm = logarithm.subs({sp.log(s[name]): log for name, log in zip(names, logs, strict=True)})
    if logarithm.has(*(s[name] for name in names)):  # pragma: no cover - derivation check
        raise RuntimeError(f"{expr} is not a monomial of {names}")
    return logs, logarithm


@derived
def _effective_speed():
    names = ("mean_a", "mean_m", "mean_compliance")
    return _logs(effective_medium_speed_symbolic(), names)


@derived
def _harmonic_speed():
    names = ("mean_a", "mean_transit")
    return _logs(harmonic_mean_speed_symbolic(), names)


@derived
def _solitary_effective():
    s = symbols()
    logs, logarithm = _logs(effective_solitary_speed(), ("F_m", "mean_a", "mean_m", "mean_K_compliance"))
    return (s["n"], *logs), logarithm


@derived
def _solitary_harmonic():
    s = symbols()
    logs, logarithm = _logs(harmonic_solitary_speed(), ("F_m", "mean_a", "mean_ray"))
    return (s["n"], *logs), logarithm


@derived
def _shift_effective():
    s = symbols()
    return (s["n"], s["sigma_K"]), effective_medium_shift()


@derived
def _shift_harmonic():
    s = symbols()
    return (s["n"], s["sigma_K"], s["sigma_m"], s["rho_mK"]), harmonic_mean_shift()


# --- validation helpers ------------------------------------------------------------------------------------


def _log_mean(logs):
    """log of the mean of exp(logs) over the last axis, without overflow (logs finite)."""
    top = np.max(logs, axis=-1, keepdims=True)
    return np.log(np.mean(np.exp(logs - top), axis=-1)) + top[..., 0]


def _estimate(estimate):
    if estimate not in ESTIMATES:
        raise ValueError(f"estimate must be one of {ESTIMATES}, got {estimate!r}")
    return estimate


_CELLS = "per-ring spacings, masses and contacts"


def effective_medium_speed(*, k, m, a):
    """Speed of long linear waves in a chain whose rings differ: the effective (homogenised) medium, m/s.

    Parameters
    ----------
    k : array_like
        Stiffness of each contact, N/m, > 0.  The last axis runs over the contacts; leading axes
        are separate chains and broadcast.  For a power-law chain under a static force F_0 the
        slope n K_j^(1/n) F_0^((n-1)/n) (:func:`~ringchain.theory.linear.contact_stiffness`).
    m : array_like
        Mass of each ring, kg, > 0 (last axis: rings).
    a : array_like
        Spacing of each ring from the next (centre to centre), m, > 0 (last axis: rings).

    Returns
    -------
    ndarray
        c = <a>/sqrt(<m> <1/k>), the means over the last axes (which may differ in length:
        N rings have N - 1 contacts), with the shape of the leading axes.

    Notes
    -----
    :func:`effective_medium_speed_symbolic`: the plane waves of the homogenised medium,
    equal to the long-wave limit of the Bloch waves of any periodic chain
    (:func:`bloch_long_wave_speed`).  Exact at leading order in a/L for a pulse many rings
    wide; a long linear pulse in a random chain arrives at the effective-medium time of
    the rings it crossed.  Smaller than :func:`harmonic_mean_speed` unless the impedance
    sqrt(m k) is the same in every cell.  Beyond the paper.

    Examples
    --------
    >>> round(float(effective_medium_speed(k=[1.0, 0.25], m=[1.0, 1.0], a=[1.0, 1.0])), 12)  # <1/k> = 5/2: sqrt(2/5)
    0.632455532034
    """
    a, m, k = v.rings("a", a, "m"), v.rings("m", m, "kg"), v.rings("k", k, "N/m")
    logs = (_log_mean(np.log(a)), _log_mean(np.log(m)), _log_mean(-np.log(k)))
    v.broadcast_shape(a=logs[0], m=logs[1], k=logs[2])
    with np.errstate(all="ignore"):
        speed = np.exp(_effective_speed(*logs))
    return v.finite_array_result(speed, "the effective-medium speed", _CELLS)


def harmonic_mean_speed(*, k, m, a):
    """Speed of long linear waves crossing each ring at its own local speed: <a>/<sqrt(m/k)>, m/s.

    Parameters
    ----------
    k, m, a : array_like
        As in :func:`effective_medium_speed`; here m and k pair up cell by cell (ring j and
        the contact from it to ring j + 1), so their last axes must match.

    Returns
    -------
    ndarray
        The length-weighted harmonic mean of the local speeds a_j sqrt(k_j/m_j): the ray
        (WKB) time of flight sum sqrt(m_j/k_j) turned into a speed.

    Notes
    -----
    :func:`harmonic_mean_speed_symbolic`.  Larger than :func:`effective_medium_speed` by the
    factor 1 + sigma_Z^2/2 (sigma_Z^2 the variance of ln sqrt(m k), :func:`speed_contrast`)
    unless the impedance is the same in every cell; a long linear pulse does not travel at
    this speed, the compact wave nearly does (:func:`disordered_solitary_wave_speed`).

    Examples
    --------
    >>> round(float(harmonic_mean_speed(k=[1.0, 0.25], m=[1.0, 1.0], a=[1.0, 1.0])), 12)  # times 1 and 2: 2/3
    0.666666666667
    """
    a, m, k = v.rings("a", a, "m"), v.rings("m", m, "kg"), v.rings("k", k, "N/m")
    v.broadcast_shape(m=m, k=k)
    with np.errstate(all="ignore"):
        transit = _log_mean(0.5 * (np.log(m) - np.log(k)))
    logs = (_log_mean(np.log(a)), transit)
    v.broadcast_shape(a=logs[0], m_and_k=logs[1])
    with np.errstate(all="ignore"):
        speed = np.exp(_harmonic_speed(*logs))
    return v.finite_array_result(speed, "the harmonic-mean speed", _CELLS)


def disordered_solitary_wave_speed(F_m, *, estimate, K, n, m, a):
    """Mean speed of the compact solitary wave of peak force F_m over a chain whose rings differ, m/s.

    Parameters
    ----------
    F_m : array_like
        Peak contact force of the wave, N, > 0; broadcast over the leading axes.
    estimate : {"effective-medium", "harmonic-mean"}
        ``"effective-medium"``: Eq. (8) on the homogenised chain, <a> sqrt(2/(n+1))
        F_m^((n-1)/(2n))/sqrt(<m> <K^(-1/n)>) (:func:`effective_solitary_speed`).
        ``"harmonic-mean"``: <a>/<a/V_s>, each cell crossed at its own Eq. (8) speed,
        <a> sqrt(2/(n+1)) F_m^((n-1)/(2n))/<sqrt(m) K^(-1/(2n))> (:func:`harmonic_solitary_speed`).
    K : array_like
        Power-law prefactor of each contact, N/m^n (last axis: contacts).
    n : array_like
        The common exponent, > 1 (one per chain: broadcast over the leading axes, not per ring).
    m : array_like
        Mass of each ring, kg (last axis: rings; it pairs with K cell by cell for the
        harmonic mean, so its last axis must match K's there).
    a : array_like
        Spacing of each ring, m (last axis: rings).

    Returns
    -------
    ndarray
        The speed, with the shape of the leading axes.

    Notes
    -----
    Which to use: on the power-law lattice (tests/theory/test_attenuation.py; n = 1.2 and 1.5,
    sigma_m = 0.15 and sigma_K = 0.2) the compact wave crosses 200 rings within 0.3 % of the
    harmonic-mean time and 0.7 % faster than the effective medium: it is a few rings wide
    and crosses each ring at its local speed; the homogenised speed is the limit of a pulse
    many rings wide (and of linear waves).  Compare a measured speed with
    the ordered chain's at the same force (Eq. (8) itself is off by about 1 % on the
    lattice for n = 1.5), and mind that the force falls along the chain
    (:func:`.attenuation.attenuated_travel_time`).  Beyond the paper.

    Examples
    --------
    >>> K = [1.0, 4.0]  # K^(-1/2) = 1, 1/2
    >>> round(float(disordered_solitary_wave_speed(1.0, estimate="effective-medium", K=K, n=2.0, m=1.0, a=1.0)), 6)
    0.942809
    >>> round(float(disordered_solitary_wave_speed(1.0, estimate="harmonic-mean", K=K, n=2.0, m=1.0, a=1.0)), 6)
    0.956585
    """
    estimate = _estimate(estimate)
    F_m = v.positive("F_m", F_m, "N")
    n = v.exponent_between(n)
    K, a, m = v.rings("K", K, "N/m^n"), v.rings("a", a, "m"), v.rings("m", m, "kg")
    with np.errstate(all="ignore"):
        log_a = _log_mean(np.log(a))
        if estimate == "effective-medium":
            log_K = _log_mean(-np.log(K) / n[..., None])
            log_m = _log_mean(np.log(m))
            v.broadcast_shape(F_m=F_m, K=log_K, n=n, a=log_a, m=log_m)
            speed = np.exp(_solitary_effective(n, np.log(F_m), log_a, log_m, log_K))
        else:
            v.broadcast_shape(K=K, m=m)
            log_ray = _log_mean(0.5 * np.log(m) - np.log(K) / (2 * n[..., None]))
            v.broadcast_shape(F_m=F_m, K_and_m=log_ray, n=n, a=log_a)
            speed = np.exp(_solitary_harmonic(n, np.log(F_m), log_a, log_ray))
    return v.finite_array_result(speed, "the mean speed", "force and per-ring chain parameters")


def disorder_speed_shift(*, estimate, n, sigma_K, sigma_m=0.0, correlation=0.0):
    """Relative change of the mean wave speed that weak disorder brings, at a given force (second order).

    Parameters
    ----------
    estimate : {"effective-medium", "harmonic-mean"}
        As in :func:`disordered_solitary_wave_speed`.
    n : array_like
        Contact exponent, > 0: the compact wave (n > 1) or the linear waves of a power-law
        chain pre-stretched by a static force (any n; both shift alike); a chain of linear
        springs k is n = 1 with sigma_K the spread of k.
    sigma_K : array_like
        Relative standard deviation of the contacts' prefactor K about its mean, >= 0.
    sigma_m : array_like, optional
        Relative standard deviation of the ring masses about their mean, >= 0.
    correlation : array_like, optional
        Correlation of a ring's mass with the prefactor of its contact (the one towards the
        next ring), in [-1, 1].

    Returns
    -------
    ndarray
        V/V_0 - 1 with V_0 the speed of the uniform chain with the arithmetic means
        <K>, <m>, <a>: -(n+1)/(4 n^2) sigma_K^2 for the effective medium
        (:func:`effective_medium_shift`; the spreads of m and a do not enter),
        sigma_m^2/8 - (2n+1)/(8 n^2) sigma_K^2 + correlation sigma_m sigma_K/(4n) for the
        harmonic mean (:func:`harmonic_mean_shift`).

    Notes
    -----
    Second order in the spreads, for independent or correlated cells alike (only one-cell
    moments enter); the error is of third order (fourth for symmetric distributions).  The
    two estimates differ by sigma_Z^2/2 (:func:`.scattering.impedance_spread`).  The linear chain
    (n = 1): -sigma_k^2/2 for the effective medium.  Beyond the paper.

    Examples
    --------
    >>> round(float(disorder_speed_shift(estimate="effective-medium", n=1.0, sigma_K=0.1)), 12)
    -0.005
    >>> round(float(disorder_speed_shift(estimate="harmonic-mean", n=1.0, sigma_K=0.1, sigma_m=0.1)), 12)  # (-3+1)/800
    -0.0025
    """
    estimate = _estimate(estimate)
    n = v.exponent_between(n, low=0.0)
    sigma_K, sigma_m, correlation = v.spreads(sigma_K, sigma_m, correlation)
    v.broadcast_shape(n=n, sigma_K=sigma_K, sigma_m=sigma_m, correlation=correlation)
    with np.errstate(all="ignore"):
        if estimate == "effective-medium":
            shape = np.broadcast_shapes(*(np.shape(x) for x in (n, sigma_K, sigma_m, correlation)))
            shift = np.broadcast_to(_shift_effective(n, sigma_K), shape)
        else:
            shift = _shift_harmonic(n, sigma_K, sigma_m, correlation)
    return v.finite_array_result(shift, "the speed shift", "exponent and spreads")
