r"""Weak disorder, scattering: the reflections that take energy from a wave (beyond the paper; issue 23).

Continues :mod:`.disorder` (a chain whose cells, ring j and the contact from it to ring j + 1,
differ: relative spreads sigma_m, sigma_K or sigma_k about the means, a correlation rho of a cell's
mass with its contact, sigma_Z the spread of ln Z, Z = sqrt(m k) the impedance of a cell, from
:func:`.disorder.impedance_variance`).  Step by step (each step a function returning SymPy objects;
the numbering continues :mod:`.disorder`'s):

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

Orders and limits: first Born order (energy to second order in the spreads, the relative error
O(sigma^2): 8 % at sigma_m = 0.2, sigma_k = 0.15 against transfer matrices); the long-wave forms to
leading order in theta = q a; the Gaussian spread for pulses many rings wide.  What the compact
wave loses to the same reflections is in :mod:`.attenuation`.

Signatures follow :mod:`.disorder`'s: what a function is evaluated at (the frequency omega, the
distance) first and positional, everything else keyword-only, the spreads last.

Numeric functions: :func:`impedance_spread` (sigma_Z from the spreads, first order,
:func:`.disorder.impedance_variance`) and :func:`chain_impedance_spread` (sigma_Z of a given chain,
neighbour correlations included), :func:`localization_length`, :func:`disorder_pulse_spread`;
:func:`equations` collects the displayed forms.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from . import linear
from ._codegen import derived, sp
from ._forms import sum_of_squares
from .disorder import impedance_variance, symbols

__all__ = [
    "junction_reflection",
    "incoherent_loss",
    "coherent_reflectance",
    "lattice_born_reflectance",
    "localization_length_symbolic",
    "pulse_spread_symbolic",
    "equations",
    "localization_length",
    "disorder_pulse_spread",
    "impedance_spread",
    "chain_impedance_spread",
]


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


# --- the displayed equations -----------------------------------------------------------------------------


@functools.cache
def equations():
    """The forms a book page displays, each a SymPy ``Eq`` from the derivations above (dict by name)."""
    R = sp.Symbol("R")
    return {
        "junction_reflection": sp.Eq(R, junction_reflection()[0]),
        "incoherent_loss": sp.Eq(sp.Symbol(r"\langle R^2\rangle"), incoherent_loss()),
        "coherent_reflectance": sp.Eq(sp.Symbol(r"\rho(\theta)"), coherent_reflectance()),
        "lattice_born_reflectance": sp.Eq(sp.Symbol(r"\rho(\theta)"), lattice_born_reflectance()),
        "localization_length": sp.Eq(sp.Symbol(r"\ell(\omega)"), localization_length_symbolic()),
        "pulse_spread": sp.Eq(sp.Symbol("s"), pulse_spread_symbolic()[1]),
    }


# --- numeric functions ------------------------------------------------------------------------------------


@derived
def _localization_length():
    """(ell, bracket): ell = a (1 - S)/(S bracket), S = m omega^2/(4 k), the bracket in sum-of-squares form."""
    s = symbols()
    sigma_m, sigma_k, rho, theta, a = s["sigma_m"], s["sigma_k"], s["rho"], s["theta"], s["a"]
    S = sp.Symbol("S", positive=True)
    ell = localization_length_symbolic()
    half_angle = s["m"] * s["omega"] ** 2 / (4 * s["k"])  # sin^2(theta/2) of the mean chain
    bracket = sp.expand(lattice_born_reflectance() / sp.tan(theta / 2) ** 2)
    stable = sum_of_squares(bracket, sigma_m, sigma_k, rho * sp.cos(theta)).subs(sp.cos(theta), 1 - 2 * S)
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
    sigma_k, sigma_m, correlation = v.spreads(sigma_k, sigma_m, correlation)
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
    return v.finite_array_result(spread, "the spread", "distance, spacing and sigma_Z")


# --- the impedance spread that scatters -------------------------------------------------------------------


@derived
def _impedance_spread():
    s = symbols()
    n, sigma_K, sigma_m, rho = s["n"], s["sigma_K"], s["sigma_m"], s["rho_mK"]
    stable = sum_of_squares(sp.expand(4 * impedance_variance()), sigma_m, sigma_K / n, rho)
    return (n, sigma_K, sigma_m, rho), sp.sqrt(stable) / 2


def impedance_spread(*, n, sigma_K, sigma_m=0.0, correlation=0.0):
    """Standard deviation sigma_Z of ln Z, Z = sqrt(m k) the impedance of a cell, for independent cells.

    Parameters
    ----------
    n, sigma_K, sigma_m, correlation : array_like
        As in :func:`.disorder.disorder_speed_shift`.

    Returns
    -------
    ndarray
        sigma_Z = sqrt(sigma_m^2 + (sigma_K/n)^2 + 2 correlation sigma_m sigma_K/n)/2 (first
        order in the spreads; :func:`impedance_variance`).  The impedance ratio of
        neighbours does not depend on the force (:func:`.disorder.impedance_ratio`), so one sigma_Z
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
    n = v.exponent_between(n, low=0.0)
    sigma_K, sigma_m, correlation = v.spreads(sigma_K, sigma_m, correlation)
    v.broadcast_shape(n=n, sigma_K=sigma_K, sigma_m=sigma_m, correlation=correlation)
    with np.errstate(all="ignore"):
        spread = _impedance_spread(n, sigma_K, sigma_m, correlation)
    return v.finite_array_result(spread, "sigma_Z", "exponent and spreads")


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
    m, K = v.rings("m", m, "kg"), v.rings("K", K, "N/m^n")
    n = v.exponent_between(n, low=0.0)
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
    return v.finite_array_result(spread, "sigma_Z", "per-ring masses and contacts")
