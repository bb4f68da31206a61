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
of a pulse through a random chain (tests/theory/test_disorder.py, transfer matrices).
The compact wave is a few rings wide and strongly nonlinear; on the power-law lattice
(same tests: n = 1.2 and 1.5, sigma_m = 0.15 and sigma_K = 0.2 together) its travel time
over 200 rings is within 0.3 % of the harmonic-mean estimate (0.1 % and 0.2 %) and 0.7 %
shorter than the effective-medium one, the two estimates being sigma_Z^2/2 = 0.5-0.6 %
apart: it crosses each ring at its local speed.

**Scattering and the loss of the leading pulse.**

7. :func:`junction_reflection` -- from :func:`.linear.junction_symbolic`, the reflected
   force at the junction of cells with impedances Z_1, Z_2 is R = tanh((ln Z_2 - ln Z_1)/2).
   :func:`incoherent_loss` -- energy R^2 per junction, <R^2> = sigma_Z^2/2 for
   independent cells: the loss per ring of a pulse shorter than a ring, whose echoes do
   not overlap.
8. :func:`coherent_reflectance` -- a long wave sees the echoes of neighbouring junctions
   overlap: R_j = (eta_{j+1} - eta_j)/2 (eta = ln Z) telescope, and the reflected energy
   per ring at phase theta = q a per ring is sigma_Z^2 sin^2(theta), about theta^2 sigma_Z^2:
   smaller than <R^2> by 2 theta^2.  :func:`lattice_born_reflectance` derives the same
   from the lattice equations (Born approximation, Green's function of the mean chain):
   tan^2(theta/2) (sigma_m^2 + sigma_k^2 + 2 rho sigma_m sigma_k cos theta) per ring, whose
   long-wave limit is theta^2 sigma_Z^2 (checked).  :func:`localization_length_symbolic`:
   the transmitted energy of a harmonic wave falls as exp(-x/ell), ell = a/reflectance.
9. :func:`pulse_spread_symbolic` -- a linear pulse keeps its energy at each wavenumber q
   but for exp(-N theta^2 sigma_Z^2): its amplitude spectrum is multiplied by
   exp(-q^2 s^2/2), the pulse convolved with a Gaussian of rms width s = sigma_Z sqrt(a x)
   (the O'Doherty-Anstey formula of randomly layered media); it arrives at the
   effective-medium time of the cells it crossed.
10. :func:`profile_wavenumber_squared` -- the compact wave as the linear theory sees
    it: the mean square wavenumber of its strain (equivalently ring-velocity) profile,
    a^2 <q^2> = 24 (n-1)/(n (n+1) (5-n)) (finite for n < 5; its force profile gives
    24 n (n-1)/((3n+1)(n+1)), which the lattice does not follow).
    :func:`energy_force_exponent` -- E ~ F_m^((n+1)/n) (:func:`.pulse.energy`).
    :func:`attenuation_length_symbolic` -- energy lost per ring sigma_Z^2 a^2 <q^2>, so
    F_m ~ exp(-x/ell) with ell = a (n+1)^2 (5-n)/(24 (n-1) sigma_Z^2).
11. :func:`travel_time_symbolic` -- V_s ~ F_m^((n-1)/(2n)) (Eq. (8)), so the decaying
    wave slows: T(x) = ell (exp(beta x/ell) - 1)/(beta V_0), beta = (n-1)/(2n).

Orders and limits.  Steps 1-6: leading order in a/L (the pulse long beside a ring);
the expansions to second order in the spreads.  Steps 7-9: first Born order (energy
to second order in the spreads, the relative error O(sigma^2): 8 % at sigma_m = 0.2,
sigma_k = 0.15 against transfer matrices); the long-wave forms to leading order in
theta = q a; the Gaussian spread for pulses many rings wide.  Steps 10-11: a
quasi-linear estimate for the compact wave, of leading order in a^2 <q^2> (0.27 at
n = 1.1, 0.91 at n = 1.5); on the power-law lattice (tests, as above) the measured decay
length is 1.08 and 1.10 times the estimate for n = 1.2 and 1.5, where the force weighting
would be off by 1.3 and 1.6.  It describes a formed wave: near the impact, while the pulse
forms (its support spans 5 rings for n = 1.5, 19 for n = 1.1), the loss is larger -- in
those tests the peak at ring 10 is already 15 % below the ordered chain's, 3-5 times what
the formed wave's rate gives over 10 rings.  It needs weak disorder (sigma_Z^2 small:
strong disorder gives the power-law decay of Ponson et al., Phys. Rev. E 82, 021301
(2010)) and a decay slow on the scale of the wave (ell much longer than its support).

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
:func:`harmonic_mean_speed`, :func:`disorder_speed_shift`, :func:`impedance_spread`,
:func:`chain_impedance_spread`, :func:`disorder_attenuation_length`) take keywords only, like
:func:`~ringchain.theory.solitary_wave_width`.

Numeric functions: :func:`effective_medium_speed`, :func:`harmonic_mean_speed`,
:func:`disordered_solitary_wave_speed`, :func:`disorder_speed_shift`,
:func:`impedance_spread`, :func:`chain_impedance_spread`, :func:`localization_length`,
:func:`disorder_pulse_spread`, :func:`disorder_attenuation_length`,
:func:`attenuated_travel_time`; :func:`equations` collects the displayed forms.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from . import linear, longwave, pulse, solitary
from ._codegen import derived, sp
from ._forms import positive_differences

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
    "junction_reflection",
    "incoherent_loss",
    "coherent_reflectance",
    "lattice_born_reflectance",
    "localization_length_symbolic",
    "pulse_spread_symbolic",
    "profile_wavenumber_squared",
    "energy_force_exponent",
    "attenuation_length_symbolic",
    "travel_time_symbolic",
    "equations",
    "effective_medium_speed",
    "harmonic_mean_speed",
    "disordered_solitary_wave_speed",
    "disorder_speed_shift",
    "impedance_spread",
    "chain_impedance_spread",
    "localization_length",
    "disorder_pulse_spread",
    "disorder_attenuation_length",
    "attenuated_travel_time",
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


def _tidy(expr):
    """Powers of positive bases merged."""
    return sp.powsimp(sp.powdenest(sp.expand_power_base(expr, force=True), force=True), force=True)


def _powers(expr, base):
    """{exponent: coefficient} with expr = sum coefficient * base**exponent (base a positive symbol)."""
    out: dict = {}
    for term in sp.Add.make_args(sp.expand(expr)):
        term = sp.powsimp(sp.expand_power_base(sp.factor(term), force=True), force=True, combine="exp")
        coefficient, power = term.as_independent(base, as_Add=False)
        found, exponent = sp.powsimp(power, force=True, combine="exp").as_base_exp()
        if found != base and power != 1:  # pragma: no cover - derivation check
            raise RuntimeError(f"{term} is not a power of {base}")
        exponent = sp.factor(exponent) if power != 1 else sp.S.Zero
        out[exponent] = out.get(exponent, 0) + coefficient
    return {exponent: sp.factor(c) for exponent, c in out.items() if sp.simplify(c) != 0}


def _reduce_gammas(expr):
    """expr with Gamma functions whose arguments differ by integers written through one of them (rising factorials).

    Gamma(z + k) = Gamma(z) (z)_k, so ratios such as Gamma(z + 1)/Gamma(z) become rational.
    """
    expr = expr.replace(lambda e: isinstance(e, sp.gamma), lambda e: sp.gamma(sp.factor(sp.together(e.args[0]))))
    representatives: list = []
    values = {}
    for argument in sorted({g.args[0] for g in expr.atoms(sp.gamma)}, key=sp.default_sort_key):
        for representative in representatives:
            shift = sp.simplify(argument - representative)
            if shift.is_integer:
                values[sp.gamma(argument)] = sp.gamma(representative) * sp.rf(representative, shift)
                break
        else:
            representatives.append(argument)
    return sp.factor(sp.simplify(sp.expand_func(expr.subs(values))))


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
        return sp.factor_terms(sp.Sum(_tidy(expr), (j, 1, s["N"])))

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
    value = _as_means(_tidy(value), {total(K[j] ** (-1 / n)): s["mean_K_compliance"]})
    return _tidy(value)


def _homogenised_chain(expr):
    """expr of a uniform chain (K, a, m) evaluated on the homogenised one (K_eff, <a>, <m>)."""
    s = symbols()
    values = {s["K"]: effective_contact_law(), s["a"]: s["mean_a"], s["m"]: s["mean_m"]}
    return _tidy(expr.subs(values, simultaneous=True))


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
    if sp.simplify(_tidy(prestretched / linear_limit)) != 1:  # pragma: no cover - derivation check
        raise RuntimeError("the homogenised power-law chain does not linearise to the effective medium")
    return _homogenised_chain(solitary.speed_from_force())


def _cell_time(speed, per_cell):
    """(rest, part): a/speed split into the factor of the per-cell quantities ``per_cell`` and the rest."""
    s = symbols()
    time = _tidy(sp.simplify(s["a"] / speed))
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
    return _tidy(s["mean_a"] / (rest * s["mean_ray"]))


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
    return expectation(_tidy(per_cell.subs(_disordered_values(), simultaneous=True)))


def _relative_shift(speed, means):
    """speed(means)/speed(uniform) - 1 to second order: each mean symbol -> E[its per-cell expression]."""
    s = symbols()
    eps = _epsilon()
    uniform = speed.subs({mean: per_cell for mean, per_cell in means.items()})
    disordered = speed.subs({mean: _mean_of(per_cell) for mean, per_cell in means.items()})
    ratio = _tidy(sp.simplify(disordered / uniform))
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
    ratio = _tidy(sp.simplify(impedance.subs({s["K"]: K2, s["m"]: m2}, simultaneous=True) / impedance))
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
    log_ratio = sp.expand_log(sp.log(_tidy(deviating)), force=True)
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


# --- 7.-9. scattering: junctions, the lattice, pulses -----------------------------------------------------


@functools.cache
def junction_reflection():
    """(R, Delta): the reflected force over the incident one at a junction with ln(Z_2/Z_1) = Delta: tanh(Delta/2).

    :func:`.linear.junction_symbolic` with Z_2 = Z_1 exp(Delta).
    """
    Z1, Z2 = sp.symbols("Z_1 Z_2", positive=True)
    Delta = sp.Symbol("Delta", real=True)
    reflected, _ = linear.junction_symbolic()
    value = sp.simplify(reflected.subs(Z2, Z1 * sp.exp(Delta)))
    if sp.simplify((value - sp.tanh(Delta / 2)).rewrite(sp.exp)) != 0:  # pragma: no cover - derivation check
        raise RuntimeError(f"the junction reflects {value}")
    return sp.tanh(Delta / 2), Delta


@functools.cache
def incoherent_loss():
    """<R^2> per junction to second order, for independent cells: sigma_Z^2/2.

    R^2 of :func:`junction_reflection` expanded, Delta = eta_2 - eta_1 with eta = ln Z
    independent across cells, each of variance sigma_Z^2.
    """
    s = symbols()
    R, Delta = junction_reflection()
    eta1, eta2 = sp.symbols("eta_1 eta_2", real=True)
    square = sp.expand(sp.series(R**2, Delta, 0, 3).removeO().subs(Delta, eta2 - eta1))
    moments = {eta1**2: s["sigma_Z"] ** 2, eta2**2: s["sigma_Z"] ** 2, eta1 * eta2: 0}
    return sp.expand(square.subs(moments))


@functools.cache
def coherent_reflectance():
    """Energy reflected per ring by a long wave of phase theta per ring, independent cells: sigma_Z^2 sin^2(theta).

    The echoes add with their phases, r = sum_j R_j exp(2 i theta j), R_j = (eta_{j+1} - eta_j)/2
    (:func:`junction_reflection` to first order).  Cell l enters R_{l-1} and R_l, so
    r = sum_l eta_l c_l with |c_l|^2 = |exp(-2 i theta) - 1|^2/4, and <|r|^2> = N sigma_Z^2 |c|^2.
    """
    s = symbols()
    theta = s["theta"]
    R, Delta = junction_reflection()
    slope = sp.diff(R, Delta).subs(Delta, 0)  # R_j = slope (eta_{j+1} - eta_j)
    site = sp.Symbol("l", integer=True)
    # eta_l enters R_{l-1} (with +) and R_l (with -): phase exp(2 i theta (l - 1)) - exp(2 i theta l).
    phase = sp.exp(2 * sp.I * theta * (site - 1)) - sp.exp(2 * sp.I * theta * site)
    unit = sp.exp(2 * sp.I * theta * site)  # modulus 1
    reduced = sp.simplify(phase / unit)
    if reduced.has(site):  # pragma: no cover - derivation check
        raise RuntimeError("the phase of a cell's echo does not factor")
    size = sp.expand_complex(slope * reduced * sp.conjugate(slope * reduced))
    return sp.factor(s["sigma_Z"] ** 2 * sp.trigsimp(sp.simplify(size)))


@functools.cache
def lattice_born_reflectance():
    """Energy reflected per ring, Born approximation on the lattice.

    tan^2(theta/2) (sigma_m^2 + sigma_k^2 + 2 rho sigma_m sigma_k cos theta) at phase theta per ring.

    The mean chain (m, k) carries u_j = exp(i theta j) with m omega^2 = 2 k (1 - cos theta).
    A cell's deviations (mu, kappa) add the source S_0 = mu m omega^2 u_0 + kappa k (u_1 - u_0)
    at ring 0 and S_1 = -kappa k (u_1 - u_0) at ring 1; the Green's function of the mean
    chain, G_j = exp(i theta |j|)/(2 i k sin theta) (solved from its equation at j = 0),
    sends back r = -sum_j G exp(i theta j) S_j.  Cells at j carry exp(2 i theta j), so for
    independent cells <|r|^2> per ring is the variance of the cell's r.  Symbols theta,
    sigma_m, sigma_k and rho (the correlation of mu and kappa in one cell).
    """
    s = symbols()
    theta, m, k, omega = s["theta"], s["m"], s["k"], s["omega"]
    mu, kappa = s["mu"], s["kappa"]
    j = sp.Symbol("j", integer=True)
    g = sp.Symbol("g")
    green = g * sp.exp(sp.I * theta * sp.Abs(j))
    dispersion = {omega**2: 2 * k * (1 - sp.cos(theta)) / m}
    at_source = m * omega**2 * green.subs(j, 0) + k * (green.subs(j, 1) - 2 * green.subs(j, 0) + green.subs(j, -1))
    g_value = sp.solve(sp.Eq(at_source.subs(dispersion), 1), g)[0]

    def u(site):
        return sp.exp(sp.I * theta * site)

    sources = {0: mu * m * omega**2 * u(0) + kappa * k * (u(1) - u(0)), 1: -kappa * k * (u(1) - u(0))}
    amplitude = -g_value * sum(sp.exp(sp.I * theta * site) * source for site, source in sources.items())
    amplitude = sp.expand(amplitude.subs(dispersion))
    c_mu, c_kappa = (sp.simplify(amplitude.coeff(d)) for d in (mu, kappa))

    def modulus_squared(z):
        return sp.simplify(sp.trigsimp(sp.expand_complex(z * sp.conjugate(z))))

    cross = sp.simplify(sp.trigsimp(sp.expand_complex(c_mu * sp.conjugate(c_kappa) + c_kappa * sp.conjugate(c_mu))))
    sigma_m, sigma_k, rho = s["sigma_m"], s["sigma_k"], s["rho"]
    reflectance = (
        modulus_squared(c_mu) * sigma_m**2 + modulus_squared(c_kappa) * sigma_k**2 + cross * rho * sigma_m * sigma_k
    )
    factor = sp.tan(theta / 2) ** 2
    closed = factor * (sigma_m**2 + sigma_k**2 + 2 * rho * sigma_m * sigma_k * sp.cos(theta))
    if sp.simplify(sp.expand_trig(((reflectance - closed) / factor).rewrite(sp.cos))) != 0:  # pragma: no cover
        raise RuntimeError(f"the Born reflectance is {reflectance}")
    # Long waves: theta^2 sigma_Z^2 with sigma_Z^2 = Var(ln Z) = (sigma_m^2 + sigma_k^2 + 2 rho sigma_m sigma_k)/4.
    long_wave = sp.series(closed, theta, 0, 3).removeO()
    variance = impedance_variance().subs({s["sigma_K"]: sigma_k, s["rho_mK"]: rho, s["n"]: 1})
    coherent = sp.series(coherent_reflectance().subs(s["sigma_Z"] ** 2, variance), theta, 0, 3).removeO()
    if sp.simplify(long_wave - coherent) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the lattice and the junctions disagree at long waves")
    return closed


@functools.cache
def localization_length_symbolic():
    """ell(omega) = a/reflectance: the transmitted energy of a harmonic wave falls as exp(-x/ell).

    :func:`lattice_born_reflectance` at the phase per ring of the mean chain,
    sin^2(theta/2) = m omega^2/(4 k) (:func:`.linear.power_law_dispersion` with k_c = k);
    written with S = sin^2(theta/2): tan^2(theta/2) = S/(1 - S), cos theta = 1 - 2 S.
    The energy reflectance adds up ring after ring (random phases), <ln T> = -N reflectance.
    """
    s = symbols()
    theta, k, omega, a = s["theta"], s["k"], s["omega"], s["a"]
    S = sp.Symbol("S", positive=True)
    dispersion = linear.power_law_dispersion().subs({linear.symbols()["k_c"]: k, s["q"]: theta / a})
    half_angle = sp.solve(sp.Eq(omega**2, dispersion.subs(sp.sin(theta / 2), sp.sqrt(S))), S)[0]
    reflectance = lattice_born_reflectance()
    in_S = reflectance.subs(sp.tan(theta / 2) ** 2, S / (1 - S)).subs(sp.cos(theta), 1 - 2 * S)
    check = (in_S - reflectance).subs(S, sp.sin(theta / 2) ** 2)
    if sp.simplify(sp.expand_trig(check.rewrite(sp.cos))) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the half-angle form of the reflectance is wrong")
    return sp.simplify(a / in_S.subs(S, half_angle))


@functools.cache
def pulse_spread_symbolic():
    """(filter, s): the amplitude filter exp(-N theta^2 sigma_Z^2/2) over N = x/a rings and its Gaussian's width s.

    The long-wave reflectance theta^2 sigma_Z^2 (:func:`coherent_reflectance`) at theta = q a;
    the energy at wavenumber q falls as exp(-N theta^2 sigma_Z^2), the amplitude as its
    square root; exp(-q^2 s^2/2) is the Fourier transform of a Gaussian of rms width s,
    solved for s: s = sigma_Z sqrt(a x).
    """
    s = symbols()
    q, a, x = s["q"], s["a"], s["distance"]
    theta = s["theta"]
    per_ring = sp.series(coherent_reflectance(), theta, 0, 3).removeO().subs(theta, q * a)
    amplitude = sp.exp(-(x / a) * per_ring / 2)
    width, y = sp.Symbol("s", positive=True), sp.Symbol("y", real=True)
    kernel = sp.exp(-(y**2) / (2 * width**2)) / (sp.sqrt(2 * sp.pi) * width)
    transform = sp.simplify(sp.integrate(kernel * sp.exp(-sp.I * q * y), (y, -sp.oo, sp.oo), conds="none"))
    exponents = [sp.expand_log(sp.log(f), force=True) for f in (transform, amplitude)]
    solved = [w for w in sp.solve(sp.Eq(*exponents), width) if w.is_nonnegative]
    if len(solved) != 1:  # pragma: no cover - derivation check
        raise RuntimeError(f"the spread is {solved}")
    return amplitude, solved[0]


# --- 10.-11. the compact wave ----------------------------------------------------------------------------


@functools.cache
def profile_wavenumber_squared(weight="strain"):
    """a^2 <q^2> = a^2 int f_tau^2 dtau/int f^2 dtau of the compact wave, f its strain (default) or force profile.

    ``weight="strain"``: f = xi, the strain, proportional to the ring velocity v = -V_s xi
    (:func:`.solitary.velocity_profile`): 24 (n-1)/(n (n+1) (5-n)), finite for n < 5.
    ``weight="force"``: f = F = K (a xi)^n: 24 n (n-1)/((3n+1)(n+1)).  On the hump
    xi = xi_max S^p, S = sin(omega tau), so xi_tau^2 = xi_max^2 p^2 omega^2 S^(2p-2) (1 - S^2),
    a sum of powers of xi; each power is integrated by :func:`.pulse.profile_integral`.
    """
    s = symbols()
    X, tau, n, a, K = s["X"], s["tau"], s["n"], s["a"], s["K"]
    if weight not in ("strain", "force"):
        raise ValueError(f"weight must be 'strain' or 'force', got {weight!r}")
    solution = solitary.compact_solution()
    omega, p = solution["omega"], solution["p"]
    xi_max = sp.Symbol("xi_max", positive=True)
    S = sp.Symbol("S", positive=True)
    hump = solitary.strain_profile().subs(sp.Abs(sp.sin(omega * tau)), sp.sin(omega * tau))
    hump = hump.subs(solution["xi_max"], xi_max)
    slope = sp.diff(hump, tau).subs({sp.cos(omega * tau): sp.sqrt(1 - S**2), sp.sin(omega * tau): S})
    slope_squared = sp.expand(slope**2).subs(S, (X / xi_max) ** (1 / p))
    profile = X if weight == "strain" else K * (a * X) ** n
    density = sp.expand(_tidy(sp.diff(profile, X) ** 2) * slope_squared)

    def integral(expr):
        return sum(
            coefficient * pulse.profile_integral(power).subs(pulse.symbols()["xi_max"], xi_max)
            for power, coefficient in _powers(expr, X).items()
        )

    ratio = integral(density) / integral(_tidy(profile**2))
    ratio = sp.powsimp(sp.expand(sp.powsimp(sp.expand_power_base(ratio, force=True), force=True, combine="exp")))
    ratio = ratio.replace(lambda e: e.is_Pow and bool(e.exp.free_symbols), lambda e: sp.Pow(e.base, sp.cancel(e.exp)))
    ratio = _reduce_gammas(sp.expand_func(sp.simplify(ratio)).rewrite(sp.gamma))
    if ratio.has(xi_max) or ratio.has(K):  # pragma: no cover - derivation check
        raise RuntimeError(f"the mean square wavenumber depends on the amplitude: {ratio}")
    return positive_differences(sp.factor(sp.simplify(ratio * a**2)))


@functools.cache
def energy_force_exponent():
    """d ln E/d ln F_m of the compact wave's energy (:func:`.pulse.energy`): (n+1)/n."""
    s = symbols()
    energy = pulse.energy()
    return sp.simplify(s["F_m"] * sp.diff(energy, s["F_m"]) / energy)


@functools.cache
def attenuation_length_symbolic():
    """ell = a (n+1)^2 (5-n)/(24 (n-1) sigma_Z^2): the distance over which the compact wave's peak force falls by e.

    The wave loses the fraction sigma_Z^2 a^2 <q^2> of its energy per ring
    (:func:`coherent_reflectance` at long waves, weighted by :func:`profile_wavenumber_squared`),
    d ln E/dx = -sigma_Z^2 a <q^2>; with F_m ~ E^(n/(n+1)) (:func:`energy_force_exponent`)
    d ln F_m/dx = -1/ell.
    """
    s = symbols()
    theta, a = s["theta"], s["a"]
    per_ring = sp.series(coherent_reflectance(), theta, 0, 3).removeO()
    per_ring = per_ring.subs(theta**2, profile_wavenumber_squared())  # theta^2 = (q a)^2 -> a^2 <q^2>
    energy_rate = -per_ring / a  # d ln E/dx
    force_rate = energy_rate / energy_force_exponent()
    return positive_differences(sp.factor(sp.simplify(-1 / force_rate)))


@functools.cache
def travel_time_symbolic():
    """(T, beta): the time to cross a distance x while F_m = F_0 exp(-x/ell): ell (exp(beta x/ell) - 1)/(beta V_0).

    V_s ~ F_m^beta with beta = d ln V_s/d ln F_m = (n-1)/(2n) (:func:`.solitary.speed_from_force`),
    so V(x) = V_0 exp(-beta x/ell) and T = int_0^x dx'/V(x').
    """
    s = symbols()
    F, x, ell, V_0 = s["F_m"], s["distance"], s["ell"], s["V_0"]
    speed = solitary.speed_from_force()
    beta = sp.simplify(F * sp.diff(speed, F) / speed)
    y, b = sp.Symbol("y", positive=True), sp.Symbol("b", positive=True)  # b stands for beta > 0 (n > 1)
    time = sp.integrate(sp.exp(b * y / ell) / V_0, (y, 0, x)).subs(b, beta)
    return sp.simplify(time), beta


# --- the displayed equations -----------------------------------------------------------------------------


@functools.cache
def equations():
    """The forms a book page displays, each a SymPy ``Eq`` from the derivations above (dict by name)."""
    s = symbols()
    V_EM, V_H, V = sp.symbols(r"V_{EM} V_H V", positive=True)
    c_EM, c_H = sp.symbols(r"c_{EM} c_H", positive=True)
    R, T = sp.symbols("R T")
    rate, ell = sp.symbols(r"\Gamma \ell", positive=True)
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
        "junction_reflection": sp.Eq(R, junction_reflection()[0]),
        "incoherent_loss": sp.Eq(sp.Symbol(r"\langle R^2\rangle"), incoherent_loss()),
        "coherent_reflectance": sp.Eq(sp.Symbol(r"\rho(\theta)"), coherent_reflectance()),
        "lattice_born_reflectance": sp.Eq(sp.Symbol(r"\rho(\theta)"), lattice_born_reflectance()),
        "localization_length": sp.Eq(sp.Symbol(r"\ell(\omega)"), localization_length_symbolic()),
        "pulse_spread": sp.Eq(sp.Symbol("s"), pulse_spread_symbolic()[1]),
        "profile_wavenumber": sp.Eq(s["a"] ** 2 * sp.Symbol(r"\langle q^2\rangle"), profile_wavenumber_squared()),
        "energy_force_exponent": sp.Eq(sp.Symbol(r"d\ln E/d\ln F_m"), energy_force_exponent()),
        "energy_loss_per_ring": sp.Eq(rate, s["sigma_Z"] ** 2 * profile_wavenumber_squared()),
        "attenuation_length": sp.Eq(ell, attenuation_length_symbolic()),
        "travel_time": sp.Eq(T, travel_time_symbolic()[0]),
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


def _sum_of_squares(variance, first, second, correlation):
    """``variance`` = first^2 + second^2 + 2 c first second (checked) in a form that stays non-negative.

    (1+c)/2 (first+second)^2 + (1-c)/2 (first-second)^2.

    Both terms are non-negative for |c| <= 1, so rounding never makes the value negative.
    """
    if sp.simplify(variance - (first**2 + second**2 + 2 * correlation * first * second)) != 0:  # pragma: no cover
        raise RuntimeError(f"{variance} is not the variance of two correlated terms")
    return (1 + correlation) / 2 * (first + second) ** 2 + (1 - correlation) / 2 * (first - second) ** 2


@derived
def _impedance_spread():
    s = symbols()
    n, sigma_K, sigma_m, rho = s["n"], s["sigma_K"], s["sigma_m"], s["rho_mK"]
    stable = _sum_of_squares(sp.expand(4 * impedance_variance()), sigma_m, sigma_K / n, rho)
    return (n, sigma_K, sigma_m, rho), sp.sqrt(stable) / 2


@derived
def _localization_length():
    """(ell, bracket): ell = a (1 - S)/(S bracket), S = m omega^2/(4 k), the bracket in sum-of-squares form."""
    s = symbols()
    sigma_m, sigma_k, rho, theta, a = s["sigma_m"], s["sigma_k"], s["rho"], s["theta"], s["a"]
    S = sp.Symbol("S", positive=True)
    ell = localization_length_symbolic()
    half_angle = s["m"] * s["omega"] ** 2 / (4 * s["k"])  # sin^2(theta/2) of the mean chain
    bracket = sp.expand(lattice_born_reflectance() / sp.tan(theta / 2) ** 2)
    stable = _sum_of_squares(bracket, sigma_m, sigma_k, rho * sp.cos(theta)).subs(sp.cos(theta), 1 - 2 * S)
    form = a * (1 - S) / (S * stable)
    if sp.simplify(form.subs(S, half_angle) - ell) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the localization length is not a (1 - S)/(S bracket)")
    args = (s["omega"], s["m"], s["k"], a, sigma_m, sigma_k, rho)
    return args, sp.Tuple(form.subs(S, half_angle), stable.subs(S, half_angle))


@derived
def _pulse_spread():
    s = symbols()
    _, spread = pulse_spread_symbolic()
    return (s["distance"], s["a"], s["sigma_Z"]), spread


@derived
def _attenuation_length():
    s = symbols()
    return (s["n"], s["a"], s["sigma_Z"]), attenuation_length_symbolic()


@derived
def _travel_time():
    """(T, its limit beta x/ell -> 0): T written with expm1 (accurate for small beta x/ell)."""
    from sympy.codegen.cfunctions import expm1

    s = symbols()
    time, beta = travel_time_symbolic()
    z = beta * s["distance"] / s["ell"]
    stable = s["distance"] / s["V_0"] * expm1(z) / z
    if sp.simplify(stable.rewrite(sp.exp) - time) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("the expm1 form of the travel time is wrong")
    limit = sp.limit(time, s["ell"], sp.oo)
    return (s["distance"], s["V_0"], s["n"], s["ell"]), sp.Tuple(stable, limit)


# --- validation helpers ------------------------------------------------------------------------------------


def _rings(name, value, unit):
    """Per-ring values: positive, finite, at least one ring on the last axis (a number is one ring)."""
    array = v.positive(name, value, unit)
    if array.ndim == 0:
        array = array[None]
    if array.shape[-1] == 0:
        raise ValueError(f"{name} must hold at least one ring: its last axis (the rings) is empty")
    return array


def _log_mean(logs):
    """log of the mean of exp(logs) over the last axis, without overflow (logs finite)."""
    top = np.max(logs, axis=-1, keepdims=True)
    return np.log(np.mean(np.exp(logs - top), axis=-1)) + top[..., 0]


def _estimate(estimate):
    if estimate not in ESTIMATES:
        raise ValueError(f"estimate must be one of {ESTIMATES}, got {estimate!r}")
    return estimate


def _spreads(sigma_K, sigma_m, correlation):
    sigma_K = v.nonnegative("sigma_K", sigma_K)
    sigma_m = v.nonnegative("sigma_m", sigma_m)
    correlation = v.in_range("correlation", correlation, -1.0, 1.0, closed_low=True, closed_high=True)
    return sigma_K, sigma_m, correlation


def _exponent(n, low=1.0, high=np.inf):
    """n in (low, high), with what the bounds mean."""
    try:
        return v.in_range("n", n, low, high, closed_high=False)
    except ValueError as error:
        reason = {
            1.0: "the compact solitary wave exists only for n > 1 (n = 1 is the linear chain)",
            0.0: "the contact law F = K delta^n needs n > 0",
        }[low]
        if high < np.inf:
            reason += f"; its strain profile has an infinite mean square wavenumber (a cusp) for n >= {high:g}"
        raise ValueError(f"{error}: {reason}") from None


def _result(value, what, inputs):
    with np.errstate(all="ignore"):
        array = np.asarray(value, dtype=float)
    return v.finite_result(array, what, inputs)


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
    a, m, k = _rings("a", a, "m"), _rings("m", m, "kg"), _rings("k", k, "N/m")
    logs = (_log_mean(np.log(a)), _log_mean(np.log(m)), _log_mean(-np.log(k)))
    v.broadcast_shape(a=logs[0], m=logs[1], k=logs[2])
    with np.errstate(all="ignore"):
        speed = np.exp(_effective_speed(*logs))
    return _result(speed, "the effective-medium speed", _CELLS)


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
    a, m, k = _rings("a", a, "m"), _rings("m", m, "kg"), _rings("k", k, "N/m")
    v.broadcast_shape(m=m, k=k)
    with np.errstate(all="ignore"):
        transit = _log_mean(0.5 * (np.log(m) - np.log(k)))
    logs = (_log_mean(np.log(a)), transit)
    v.broadcast_shape(a=logs[0], m_and_k=logs[1])
    with np.errstate(all="ignore"):
        speed = np.exp(_harmonic_speed(*logs))
    return _result(speed, "the harmonic-mean speed", _CELLS)


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
    Which to use: on the power-law lattice (tests/theory/test_disorder.py; n = 1.2 and 1.5,
    sigma_m = 0.15 and sigma_K = 0.2) the compact wave crosses 200 rings within 0.3 % of the
    harmonic-mean time and 0.7 % faster than the effective medium: it is a few rings wide
    and crosses each ring at its local speed; the homogenised speed is the limit of a pulse
    many rings wide (and of linear waves).  Compare a measured speed with
    the ordered chain's at the same force (Eq. (8) itself is off by about 1 % on the
    lattice for n = 1.5), and mind that the force falls along the chain
    (:func:`attenuated_travel_time`).  Beyond the paper.

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
    n = _exponent(n)
    K, a, m = _rings("K", K, "N/m^n"), _rings("a", a, "m"), _rings("m", m, "kg")
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
    return _result(speed, "the mean speed", "force and per-ring chain parameters")


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
    two estimates differ by sigma_Z^2/2 (:func:`impedance_spread`).  The linear chain
    (n = 1): -sigma_k^2/2 for the effective medium.  Beyond the paper.

    Examples
    --------
    >>> round(float(disorder_speed_shift(estimate="effective-medium", n=1.0, sigma_K=0.1)), 12)
    -0.005
    >>> round(float(disorder_speed_shift(estimate="harmonic-mean", n=1.0, sigma_K=0.1, sigma_m=0.1)), 12)  # (-3+1)/800
    -0.0025
    """
    estimate = _estimate(estimate)
    n = _exponent(n, low=0.0)
    sigma_K, sigma_m, correlation = _spreads(sigma_K, sigma_m, correlation)
    v.broadcast_shape(n=n, sigma_K=sigma_K, sigma_m=sigma_m, correlation=correlation)
    with np.errstate(all="ignore"):
        if estimate == "effective-medium":
            shape = np.broadcast_shapes(*(np.shape(x) for x in (n, sigma_K, sigma_m, correlation)))
            shift = np.broadcast_to(_shift_effective(n, sigma_K), shape)
        else:
            shift = _shift_harmonic(n, sigma_K, sigma_m, correlation)
    return _result(shift, "the speed shift", "exponent and spreads")


def impedance_spread(*, n, sigma_K, sigma_m=0.0, correlation=0.0):
    """Standard deviation sigma_Z of ln Z, Z = sqrt(m k) the impedance of a cell, for independent cells.

    Parameters
    ----------
    n, sigma_K, sigma_m, correlation : array_like
        As in :func:`disorder_speed_shift`.

    Returns
    -------
    ndarray
        sigma_Z = sqrt(sigma_m^2 + (sigma_K/n)^2 + 2 correlation sigma_m sigma_K/n)/2 (first
        order in the spreads; :func:`impedance_variance`).  The impedance ratio of
        neighbours does not depend on the force (:func:`impedance_ratio`), so one sigma_Z
        serves every amplitude.

    Notes
    -----
    For cells that are not independent (a contact shares its two rings with its
    neighbours), what scattering needs is the long-wave variance Var(sum ln Z_j)/N
    (:func:`chain_impedance_spread` estimates it from a chain).  Beyond the paper.

    Examples
    --------
    >>> round(float(impedance_spread(n=1.0, sigma_K=0.2, sigma_m=0.2)), 12)  # sqrt(0.04 + 0.04)/2
    0.141421356237
    """
    n = _exponent(n, low=0.0)
    sigma_K, sigma_m, correlation = _spreads(sigma_K, sigma_m, correlation)
    v.broadcast_shape(n=n, sigma_K=sigma_K, sigma_m=sigma_m, correlation=correlation)
    with np.errstate(all="ignore"):
        spread = _impedance_spread(n, sigma_K, sigma_m, correlation)
    return _result(spread, "sigma_Z", "exponent and spreads")


def chain_impedance_spread(*, K, n, m, lags=1):
    """sigma_Z of a given chain: the long-wave spread of ln Z estimated from its rings, neighbour correlations included.

    Parameters
    ----------
    K : array_like
        Prefactor of each contact, N/m^n (last axis: N - 1 contacts, or N); contact j
        pairs with ring j.
    n : array_like
        The common exponent, > 0 (1 for linear springs K = k), one per chain.
    m : array_like
        Mass of each ring, kg (last axis: N rings).
    lags : int, optional
        Neighbour correlations kept: a contact that depends on its two rings correlates
        cells one apart (lags=1); independent cells need lags=0.

    Returns
    -------
    ndarray
        sqrt(c_0 + 2 sum_{l=1}^{lags} c_l), c_l the sample autocovariances (divided by the
        number of cells) of ln Z_j = ln m_j/2 + ln K_j/(2n), clipped at zero.  The expected
        value of the square falls short of sigma_Z^2 by about (2 lags + 1)/N of it; pool
        members by averaging the squares.

    Examples
    --------
    >>> m = [1.0, 4.0, 1.0, 4.0]
    >>> round(float(chain_impedance_spread(K=[1.0, 1.0, 1.0, 1.0], n=1.0, m=m, lags=0)), 12)  # ln(2)/2
    0.34657359028
    """
    if isinstance(lags, bool) or not isinstance(lags, (int, np.integer)) or lags < 0:
        raise ValueError(f"lags must be a non-negative integer, got {lags!r}")
    m, K = _rings("m", m, "kg"), _rings("K", K, "N/m^n")
    n = _exponent(n, low=0.0)
    cells = K.shape[-1]
    if m.shape[-1] not in (cells, cells + 1):
        raise ValueError(
            f"m has {m.shape[-1]} rings and K {cells} contacts: give N rings and N - 1 (or N) contacts, "
            "contact j between ring j and ring j + 1"
        )
    if lags >= cells:
        raise ValueError(f"lags must be smaller than the number of cells ({cells}), got {lags}")
    with np.errstate(all="ignore"):
        logs = 0.5 * np.log(m[..., :cells]) + np.log(K) / (2 * n[..., None])
        deviation = logs - logs.mean(axis=-1, keepdims=True)
        # In units of the largest deviation, so that no square overflows (ln K/(2n) is huge for n -> 0).
        scale = np.max(np.abs(deviation), axis=-1, keepdims=True)
        deviation = deviation / np.where(scale > 0, scale, 1.0)
        variance = np.mean(deviation**2, axis=-1)
        for lag in range(1, lags + 1):
            variance = variance + 2 * np.sum(deviation[..., lag:] * deviation[..., :-lag], axis=-1) / cells
        spread = scale[..., 0] * np.sqrt(np.maximum(variance, 0.0))
    return _result(spread, "sigma_Z", "per-ring masses and contacts")


def localization_length(omega, *, k, m, a, sigma_k, sigma_m, correlation=0.0):
    """Localization length of harmonic linear waves in a weakly disordered chain: the energy falls by e over ell, m.

    Parameters
    ----------
    omega : array_like
        Angular frequency, rad/s, inside the band of the mean chain: 0 < omega < 2 sqrt(k/m).
    k, m, a : array_like
        Mean contact stiffness (N/m), mean ring mass (kg) and mean spacing (m).
    sigma_k, sigma_m : array_like
        Relative standard deviations of the stiffnesses and masses, >= 0 (independent cells).
    correlation : array_like, optional
        Correlation of a ring's mass with the stiffness of its contact, in [-1, 1].

    Returns
    -------
    ndarray
        ell = a/rho with rho = tan^2(theta/2) (sigma_m^2 + sigma_k^2 + 2 correlation sigma_m
        sigma_k cos theta), sin^2(theta/2) = m omega^2/(4 k) (:func:`localization_length_symbolic`):
        the transmitted energy falls as exp(-x/ell) (<ln T> = -x/ell), the force amplitude
        as exp(-x/(2 ell)).  Infinite where there is no disorder.

    Notes
    -----
    First Born order (:func:`lattice_born_reflectance`): relative error O(sigma^2), 8 % at
    sigma_m = 0.2, sigma_k = 0.15 against transfer matrices; it needs rho small, so it fails
    near the band edge, where tan(theta/2) grows without bound.  At long waves
    rho -> theta^2 sigma_Z^2: the Rayleigh-like omega^2 law behind :func:`disorder_pulse_spread`.
    Beyond the paper.

    Examples
    --------
    >>> round(float(localization_length(np.sqrt(2.0), k=1.0, m=1.0, a=1.0, sigma_k=0.0, sigma_m=0.1)), 6)  # theta: pi/2
    100.0
    """
    omega = v.positive("omega", omega, "rad/s")
    m, k, a = v.positive("m", m, "kg"), v.positive("k", k, "N/m"), v.positive("a", a, "m")
    sigma_k, sigma_m, correlation = _spreads(sigma_k, sigma_m, correlation)
    v.broadcast_shape(omega=omega, m=m, k=k, a=a, sigma_m=sigma_m, sigma_k=sigma_k, correlation=correlation)
    with np.errstate(all="ignore"):
        top = 2 * np.sqrt(k / m)
    if np.any(~(omega < top)):
        raise ValueError(
            "omega must lie inside the band of the mean chain, below 2 sqrt(k/m): "
            f"got omega/(2 sqrt(k/m)) up to {v.show(np.max(omega / top))}"
        )
    with np.errstate(all="ignore"):
        ell, bracket = np.broadcast_arrays(*_localization_length(omega, m, k, a, sigma_m, sigma_k, correlation))
    none = bracket == 0  # no disorder: nothing scatters
    finite = v.finite_result(np.where(none, 0.0, ell), "ell", "frequency, chain and spreads")
    return np.where(none, np.inf, finite)


def disorder_pulse_spread(distance, *, a, sigma_Z):
    """Rms width of the Gaussian that weak disorder convolves a long linear pulse with after a distance, m.

    Parameters
    ----------
    distance : array_like
        Distance travelled, m, >= 0.
    a : array_like
        Mean spacing of the rings, m.
    sigma_Z : array_like
        Spread of ln Z (:func:`impedance_spread`, or :func:`chain_impedance_spread` for a
        given chain), >= 0.

    Returns
    -------
    ndarray
        s = sigma_Z sqrt(a x) (:func:`pulse_spread_symbolic`): the pulse, seen from its
        (random) arrival at the effective-medium time, is the ordered chain's convolved with
        a Gaussian of rms width s (in time s/c).  A Gaussian pulse of rms width w keeps
        w/sqrt(w^2 + s^2) of its peak and of its energy.

    Notes
    -----
    The O'Doherty-Anstey formula of randomly layered media, here from the lattice: energy
    exp(-N q^2 a^2 sigma_Z^2) at wavenumber q after N rings.  Leading order in q a and in
    sigma_Z^2; the pulse must be many rings wide (a pulse shorter than a ring loses the
    incoherent <R^2> = sigma_Z^2/2 per ring instead, :func:`incoherent_loss`).  Beyond the
    paper.

    Examples
    --------
    >>> round(float(disorder_pulse_spread(100.0, a=1.0, sigma_Z=0.1)), 12)  # 0.1 sqrt(100)
    1.0
    """
    distance = v.nonnegative("distance", distance, "m")
    a = v.positive("a", a, "m")
    sigma_Z = v.nonnegative("sigma_Z", sigma_Z)
    v.broadcast_shape(distance=distance, a=a, sigma_Z=sigma_Z)
    with np.errstate(all="ignore"):
        spread = _pulse_spread(distance, a, sigma_Z)
    return _result(spread, "the spread", "distance, spacing and sigma_Z")


#: Exponent range of :func:`disorder_attenuation_length`: the compact wave needs n > 1, its
#: strain profile's mean square wavenumber n < 5.
_ATTENUATION_EXPONENTS = (1.0, 5.0)


def disorder_attenuation_length(*, n, a, sigma_Z):
    """Distance over which weak disorder makes the compact wave's peak force fall by e, m.

    Parameters
    ----------
    n : array_like
        Contact exponent, 1 < n < 5.
    a : array_like
        Mean spacing of the rings, m.
    sigma_Z : array_like
        Spread of ln Z, Z = sqrt(m k) (:func:`impedance_spread`, :func:`chain_impedance_spread`), >= 0.

    Returns
    -------
    ndarray
        ell = a (n+1)^2 (5-n)/(24 (n-1) sigma_Z^2) (:func:`attenuation_length_symbolic`):
        F_m ~ exp(-x/ell); infinite without disorder.

    Notes
    -----
    A quasi-linear estimate: the wave loses per ring the energy a linear pulse with its
    strain (ring-velocity) profile would scatter, sigma_Z^2 a^2 <q^2>
    (:func:`profile_wavenumber_squared`), and keeps the shape of a compact wave, so
    F_m ~ E^(n/(n+1)).  Leading order in a^2 <q^2> (0.27 at n = 1.1, 0.91 at n = 1.5) and in
    sigma_Z^2.  On the power-law lattice (tests/theory/test_disorder.py; sigma_m = 0.15 and
    sigma_K = 0.2) the measured decay length is 1.08 and 1.10 times this for n = 1.2 and 1.5.
    It holds for a formed wave: near the impact, while the pulse forms (about its support,
    5 rings for n = 1.5 and 19 for n = 1.1), the loss is larger (15 % by ring 10 in those
    tests, 3-5 times the formed wave's rate); strong disorder gives a power-law decay
    instead (Ponson et al., Phys. Rev. E 82, 021301 (2010)).  Compare with the ordered
    chain's peak ring by ring.  Beyond the paper.

    Examples
    --------
    >>> round(float(disorder_attenuation_length(n=1.5, a=1.0, sigma_Z=0.1)), 3)  # about 180 rings
    182.292
    """
    n = _exponent(n, *_ATTENUATION_EXPONENTS)
    a = v.positive("a", a, "m")
    sigma_Z = v.nonnegative("sigma_Z", sigma_Z)
    v.broadcast_shape(n=n, a=a, sigma_Z=sigma_Z)
    with np.errstate(all="ignore"):
        ell = np.asarray(_attenuation_length(n, a, sigma_Z), dtype=float)
    none = np.broadcast_to(sigma_Z == 0, ell.shape)
    finite = v.finite_result(np.where(none, 0.0, ell), "the attenuation length", "exponent, spacing and sigma_Z")
    return np.where(none, np.inf, finite)


def attenuated_travel_time(distance, *, V0, n, attenuation_length):
    """Time the compact wave takes to cross a distance while its peak force decays, s.

    Parameters
    ----------
    distance : array_like
        Distance, m, >= 0.
    V0 : array_like
        Speed of the wave where the distance starts, m/s, > 0 (e.g.
        :func:`disordered_solitary_wave_speed` at the force there).
    n : array_like
        Contact exponent, > 1.
    attenuation_length : array_like
        ell of F_m ~ exp(-x/ell), m, > 0; ``np.inf`` for no decay
        (:func:`disorder_attenuation_length`).

    Returns
    -------
    ndarray
        T = ell (exp(beta x/ell) - 1)/(beta V0), beta = (n-1)/(2n) (:func:`travel_time_symbolic`),
        evaluated with expm1 (x/V0 where beta x/ell -> 0).  The mean speed over the distance is x/T.

    Notes
    -----
    V_s ~ F_m^((n-1)/(2n)) (Eq. (8)): the slowing that comes with the loss of amplitude.
    Beyond the paper.

    Examples
    --------
    >>> float(attenuated_travel_time(0.0, V0=1.0, n=1.5, attenuation_length=10.0))
    0.0
    >>> float(attenuated_travel_time(2.0, V0=1.0, n=1.5, attenuation_length=np.inf))
    2.0
    """
    distance = v.nonnegative("distance", distance, "m")
    V0 = v.positive("V0", V0, "m/s")
    n = _exponent(n)
    ell = v.as_array("attenuation_length", attenuation_length)
    if ell.size and not (np.min(ell) > 0):  # also NaN
        raise ValueError(
            f"attenuation_length must be positive (m; np.inf for no decay), got {v.show(ell[~(ell > 0)].ravel()[0])}"
        )
    v.broadcast_shape(distance=distance, V0=V0, n=n, attenuation_length=ell)
    with np.errstate(all="ignore"):
        full, limit = _travel_time(distance, V0, n, np.where(np.isinf(ell), 1.0, ell))
        z = (n - 1) / (2 * n) * distance / ell
        time = np.where(z == 0, limit, full)
    return _result(time, "the travel time", "distance, speed, exponent and attenuation length")
