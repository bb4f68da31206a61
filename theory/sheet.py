r"""Linear waves of a pretensioned sheet of interlinked rings: dispersion, long-wave speeds, anisotropy.

Beyond the paper, which closes by naming two-dimensional interlinked lattices as the next step (Sec. V).
The sheet is a planar network of point masses m (one per ring, moving in the sheet's plane) joined by
links, each the contact of two interlocked rings.  In the pretensioned state every link has the length a
(the distance between the two ring centres) and carries the tension T; small motions about that state
feel each link through two numbers only: its axial stiffness k = dF/d delta at T (the slope of the contact
law, :func:`.linear.contact_stiffness` for the power law) and its tension.  Step by step:

1. :func:`link_stiffness` -- the energy V(l) of one link, l = |b + d| its length when its ends move apart
   by d from the pretensioned bond vector b = a e, expanded to second order in d.  With V'(a) = T and
   V''(a) = k this gives the force T e the link pulls with and the 2 x 2 stiffness
   k e e^T + (T/a)(I - e e^T): the axial stiffness k along the link and the geometric stiffness T/a
   across it (a taut string resists being turned).
2. :func:`families` -- the two layouts.  ``"square"`` (4-in-1 chain mail): every site linked to 4
   neighbours at +-b_x = +-(a_x, 0) and +-b_y = +-(0, a_y).  ``"triangular"`` (6-in-1): 6 neighbours at
   +-b_1, +-b_2, +-b_3, bonds of one length a at 0, 60 and 120 degrees from the x axis.  A family is one
   lattice direction; its links share k, T and a, which may differ from family to family (a biaxial
   pretension).
3. :func:`equilibrium_force` -- the force on a site in the pretensioned state: the links of a family pull
   it equally both ways, so every set of family tensions is an equilibrium.
4. :func:`dynamical_matrix` -- the potential energy of the links meeting site 0, written with their exact
   lengths |b + u_j - u_0| and a law V_f per family, differentiated twice with respect to the
   displacements of site 0 and of each neighbour j at the pretensioned state (the second-order term of
   the network's energy); a Bloch wave u_j = U exp(i q.R_j - i omega t) turns m u_0'' = -sum_j H_0j u_j
   into D(q) U = omega^2 U with D = (1/m) sum_j H_0j exp(i q.R_j).  The sum over each +-b pair is
   real and comes out as D = (4/m) sum_f K_f sin^2(q.b_f/2), K_f the link stiffness of step 1 (checked
   in the tests, not assumed here).  The two eigenvalues of the real symmetric 2 x 2 matrix D are the
   squared frequencies of the two in-plane branches.
5. :func:`long_wave_tensor` -- lim_{q -> 0} D(q n)/q^2 along the direction n = (cos theta, sin theta):
   the acoustic (Christoffel) tensor over the mass, whose eigenvalues are the squared long-wave speeds
   in that direction.  Where its eigenvectors are n and the normal t (every direction of the uniform
   triangular sheet; the lattice directions of the square sheet, and its diagonals when its two
   families are alike), the waves are purely
   longitudinal and transverse (:func:`long_wave_speeds_squared`); elsewhere they are quasi-longitudinal
   and quasi-transverse.
6. :func:`branches_along_x` -- the textbook forms along the first lattice direction with one k, T and a
   for every family (:func:`uniform`): for the square sheet omega_L^2 = (4k/m) sin^2(q a/2) (the 1D chain)
   and omega_T^2 = (4T/(m a)) sin^2(q a/2) (the string); for the triangular sheet
   omega_L^2 = (4/m)[k sin^2(q a/2) + (k/2 + 3T/(2a)) sin^2(q a/4)] and
   omega_T^2 = (4/m)[(T/a) sin^2(q a/2) + (3k/2 + T/(2a)) sin^2(q a/4)].

What the long waves show.  The square sheet's long-wave modes are polarised along the lattice axes in
every direction, with c^2 = (k_x a_x^2 cos^2 theta + T_y a_y sin^2 theta)/m (along x) and
(T_x a_x cos^2 theta + k_y a_y^2 sin^2 theta)/m (along y): along a lattice direction the longitudinal
wave is the chain's, a sqrt(k/m), and the transverse one the string's, sqrt(T a/m); along the diagonal
the two are equal, sqrt((k a^2 + T a)/(2m)).  Without pretension the square net has no shear stiffness
(a mechanism).  The triangular sheet is isotropic at long wavelengths (six-fold symmetry makes the
acoustic tensor isotropic): c_L^2 = (9 k a^2 + 3 T a)/(8m), c_T^2 = (3 k a^2 + 9 T a)/(8m), so
c_L/c_T = sqrt(3) without pretension (central forces: Lame constants lambda = mu, Cauchy's relation) and
the tension brings the two speeds together.  For rings k a/T = n a/delta_0 >> 1 (F = K delta^n with the
static extension delta_0), so the square sheet's transverse waves along its rows are much slower than
its longitudinal ones, and the triangular sheet's speeds keep nearly the ratio sqrt(3).

Why one mass per ring.  The dual-spring chain of the paper gives each ring two half-masses joined by its
bending spring K_b, because in a chain a ring is squeezed between two contacts.  A ring of a sheet is
loaded at 4 or 6 contacts, and its body's response is a 4 x 4 or 6 x 6 compliance with modes of its own,
not one spring per link; the sheet here is the power-law model (one site per ring, Eq. (7)), whose link
stiffness k may be the tangent of any static law of the contact, the series law of Eq. (3) included.

Signatures follow the package's convention (:mod:`ringchain.theory`): the wavevector (qx, qy) or the
direction comes first; everything else is keyword-only.  The choice ``pattern=`` first, as ``model=`` in
:func:`~ringchain.theory.dispersion`; then T, k, m, a: the link tension T is the static force of the
contact and stands where F_0 stands in the package's order F_0, K, n, m, a, and the axial stiffness k, the
slope of the contact law at T, where K stands.  The long-wave speeds are computed from k a^2/m and T a/m
scaled by the largest of them (``_tensor_in_speeds``), and long waves of the dispersion as q times
those speeds, so that neither squares nor sin^2 of a tiny phase leave the doubles where omega does not.

7. :func:`dispersion_gradient` -- the derivatives of the entries of D(q) with respect to q_x and q_y.  The
   eigenvalue omega^2 of a symmetric D with unit eigenvector U changes as U^T (dD/dq) U (first-order
   perturbation), so the group velocity of a branch is v_g = grad_q omega = U^T (grad_q D) U/(2 omega): the
   direction energy travels in, which from a point source is not the wavevector's (the wave surface is the
   polar reciprocal of the slowness curve q/omega).

Numeric functions: :func:`sheet_dispersion`, :func:`sheet_group_velocity`, :func:`sheet_sound_speeds`.
"""

from __future__ import annotations

import functools
from typing import NamedTuple

import numpy as np

from . import _validate as v
from ._codegen import derived, sp

__all__ = [
    "PATTERNS",
    "FAMILY_NAMES",
    "symbols",
    "Family",
    "families",
    "link_stiffness",
    "equilibrium_force",
    "dynamical_matrix",
    "long_wave_tensor",
    "uniform",
    "branches_along_x",
    "long_wave_speeds_squared",
    "dispersion_gradient",
    "SheetSpeeds",
    "sheet_dispersion",
    "sheet_group_velocity",
    "sheet_sound_speeds",
]

#: The two layouts, by the names :func:`sheet_dispersion` takes.
PATTERNS = ("square", "triangular")

#: The link families of each layout, in the order of per-family parameters (tuples of k, T, a).
FAMILY_NAMES = {"square": ("x", "y"), "triangular": ("0 deg", "60 deg", "120 deg")}


@functools.cache
def symbols():
    """Symbols of the sheet: wavevector, direction, mass, and link parameters (uniform and per family).

    ``q_x``, ``q_y`` (rad/m) and ``theta`` (rad, from the x axis) are real; ``q`` (rad/m) the wavenumber
    along ``theta``; ``m`` (kg); ``a``, ``k``, ``T`` the uniform link length (m), axial stiffness (N/m)
    and tension (N); ``a_x``, ``a_y``, ``k_x``, ``k_y``, ``T_x``, ``T_y`` the square sheet's families;
    ``k_1``, ``k_2``, ``k_3``, ``T_1``, ``T_2``, ``T_3`` the triangular sheet's (0, 60, 120 degrees).
    """
    s = {name: sp.Symbol(name, real=True) for name in ("q_x", "q_y", "theta")}
    names = ["q", "m", "a", "k", "T", "a_x", "a_y", "k_x", "k_y", "T_x", "T_y"]
    names += ["k_1", "k_2", "k_3", "T_1", "T_2", "T_3"]
    s.update({name: sp.Symbol(name, positive=True) for name in names})
    return s


def _pattern(pattern):
    if pattern not in PATTERNS:
        raise ValueError(f"pattern must be one of {PATTERNS}, got {pattern!r}")
    return pattern


class Family(NamedTuple):
    """One family of links: the bond vector from a site to a neighbour, its length, stiffness and tension."""

    bond: object  #: sympy ImmutableMatrix (2 x 1), m
    length: object  #: a of the family, m
    k: object  #: axial stiffness, N/m
    T: object  #: tension, N


@functools.cache
def families(pattern):
    """The link families of a layout (step 2 of the module docstring), each a :class:`Family`.

    A site at R is linked to R + b and R - b for the bond vector b of every family: 2 families (4
    neighbours) for ``"square"``, 3 (6 neighbours) for ``"triangular"``.
    """
    s = symbols()
    if _pattern(pattern) == "square":
        return (
            Family(sp.ImmutableMatrix([s["a_x"], 0]), s["a_x"], s["k_x"], s["T_x"]),
            Family(sp.ImmutableMatrix([0, s["a_y"]]), s["a_y"], s["k_y"], s["T_y"]),
        )
    a = s["a"]
    angles = (0, sp.pi / 3, 2 * sp.pi / 3)
    return tuple(
        Family(sp.ImmutableMatrix([a * sp.cos(angle), a * sp.sin(angle)]), a, s[f"k_{i}"], s[f"T_{i}"])
        for i, angle in enumerate(angles, start=1)
    )


def _link_energy(law, vector):
    """V(|vector|): the energy of a link whose end-to-end vector is ``vector`` (a 2 x 1 matrix)."""
    return law(sp.sqrt(vector.dot(vector)))


def _at_pretension(expr, law, length, k, T):
    """``expr`` (derivatives of V evaluated at the pretensioned length) with V'(a) = T and V''(a) = k.

    The lengths at which V and its derivatives are evaluated are square roots of sums of squares
    (a^2 cos^2 theta + a^2 sin^2 theta for a link at angle theta): simplified first, so that they read a.
    """
    expr = expr.replace(lambda e: e.is_Pow and e.exp == sp.S.Half, lambda e: sp.sqrt(sp.trigsimp(e.base))).doit()
    expr = expr.subs(sp.Derivative(law(length), (length, 2)), k).subs(sp.Derivative(law(length), length), T)
    if expr.has(law):  # pragma: no cover - derivation check
        raise RuntimeError("the expansion about the pretensioned state depends on the link law beyond V' and V''")
    return expr


@functools.cache
def link_stiffness():
    """(f, K): force and 2 x 2 stiffness of one link at angle ``theta``, from its energy to second order.

    The link joins two sites whose pretensioned separation is b = a (cos theta, sin theta); when its
    far end moves by d relative to the near one, its length is |b + d| and its energy
    V(|b + d|) = V(a) + f.d + d^T K d/2 + O(d^3), with V'(a) = T and V''(a) = k.  Returns the gradient
    f (a 2 x 1 matrix, the force T e with which the link pulls its near end) and the Hessian K.
    """
    s = symbols()
    a, k, T, theta = s["a"], s["k"], s["T"], s["theta"]
    law = sp.Function("V")
    d = sp.Matrix(sp.symbols("d_x d_y", real=True))
    bond = sp.Matrix([a * sp.cos(theta), a * sp.sin(theta)])
    energy = _link_energy(law, bond + d)
    at_rest = {d[0]: 0, d[1]: 0}

    def expanded(expr):
        # Over one denominator, then trigsimp: the same forms as simplify-then-trigsimp, in a third of the time.
        return sp.trigsimp(sp.together(_at_pretension(expr.subs(at_rest), law, a, k, T)))

    first = [sp.diff(energy, component) for component in d]
    gradient = sp.ImmutableMatrix([expanded(derivative) for derivative in first])
    # The Hessian is symmetric: each entry above the diagonal simplified once, from the gradient's derivatives.
    upper = {(i, j): expanded(sp.diff(first[i], d[j])) for i in range(2) for j in range(i, 2)}
    hessian = sp.ImmutableMatrix(2, 2, lambda i, j: upper[min(i, j), max(i, j)])
    return gradient, hessian


@functools.cache
def _site_energy(pattern):
    """The energy of the links meeting site 0 and the sites it involves.

    Returns (energy, u_0, neighbours, laws): u_0 the displacement of site 0 (2 x 1), neighbours a tuple of
    (u_j, R_j, family index, sign) with R_j = sign b_f the neighbour's pretensioned position, and laws a
    tuple of (V_f, a_f, k_f, T_f), one undefined function V_f per family.  The link from site 0 to
    R_j = +b_f has the end-to-end vector b_f + u_j - u_0, the one from R_j = -b_f to site 0 has
    b_f + u_0 - u_j: both are links of family f, stretched by the relative displacement along +b_f.
    """
    u0 = sp.Matrix(sp.symbols("u_0x u_0y", real=True))
    energy = sp.S.Zero
    neighbours, laws = [], []
    for index, family in enumerate(families(pattern), start=1):
        law = sp.Function(f"V_{index}")
        laws.append((law, family.length, family.k, family.T))
        bond = sp.Matrix(family.bond)
        for sign, tag in ((1, "p"), (-1, "m")):
            u = sp.Matrix(sp.symbols(f"u_{index}{tag}x u_{index}{tag}y", real=True))
            vector = bond + u - u0 if sign > 0 else bond + u0 - u
            energy += _link_energy(law, vector)
            neighbours.append((u, sign * bond, index - 1, sign))
    return energy, u0, tuple(neighbours), tuple(laws)


def _at_rest(pattern, expr):
    """``expr`` (a derivative of the site energy) at the pretensioned state: displacements 0, V' = T, V'' = k."""
    _, u0, neighbours, laws = _site_energy(pattern)
    rest = {c: 0 for c in u0}
    rest.update({c: 0 for u, *_ in neighbours for c in u})
    expr = expr.xreplace(rest)  # plain symbols replaced by 0: xreplace, without subs' pattern matching
    for law, length, k, T in laws:
        expr = _at_pretension(expr, law, length, k, T)
    return expr


def _site_derivative(pattern, expr):
    """:func:`_at_rest`, simplified."""
    return sp.simplify(_at_rest(pattern, expr))


@functools.cache
def equilibrium_force(pattern):
    """-dE/du_0 at the pretensioned state: the net force on a site (2 x 1), zero for any family tensions."""
    energy, u0, _, _ = _site_energy(pattern)
    return sp.ImmutableMatrix([-_site_derivative(pattern, sp.diff(energy, c)) for c in u0])


@functools.cache
def dynamical_matrix(pattern):
    """D(q_x, q_y): the Bloch matrix of the sheet, D U = omega^2 U (step 4 of the module docstring).

    Per-family parameters (``k_x``, ``T_x``, ``a_x``, ... or ``k_1``, ``T_1``, ...); the 2 x 2 matrix
    acts on the (x, y) amplitudes of the in-plane displacement.  Written as sum_f M_f sin^2(q.b_f/2).
    """
    s = symbols()
    energy, u0, neighbours, _ = _site_energy(pattern)
    fams = families(pattern)
    # A phase symbol per family: exp(i q.R_j) = exp(i sign phase_f) for the neighbours at R_j = sign b_f.
    phases = sp.symbols(f"phi_1:{len(fams) + 1}", real=True)
    halves = sp.symbols(f"s_1:{len(fams) + 1}", real=True)  # sin(phase_f/2)

    first = [sp.diff(energy, c) for c in u0]  # dE/du_0, once: each block differentiates it again

    def block(u):  # not simplified: half_angle expands each entry and factors its coefficients (1 s less)
        return sp.Matrix(2, 2, lambda i, j: _at_rest(pattern, sp.diff(first[i], u[j])))

    bloch = block(u0)
    for u, _, index, sign in neighbours:
        bloch += block(u) * sp.exp(sp.I * sign * phases[index])
    bloch = bloch / s["m"]

    def half_angle(entry):
        half_angles = {sp.cos(p): 1 - 2 * h**2 for p, h in zip(phases, halves, strict=True)}
        entry = sp.expand(sp.expand(entry.rewrite(sp.cos)).subs(half_angles))
        if entry.has(sp.I) or entry.has(*phases):  # pragma: no cover - derivation check
            raise RuntimeError("the Bloch matrix is not real: the +-b neighbours do not pair up")
        if sp.simplify(entry.subs({h: 0 for h in halves})) != 0:  # pragma: no cover - derivation check
            raise RuntimeError("the Bloch matrix does not vanish at q = 0: a rigid translation costs energy")
        q = sp.Matrix([s["q_x"], s["q_y"]])
        terms = [
            sp.factor(entry.coeff(h, 2)) * sp.sin(sp.expand(q.dot(f.bond) / 2)) ** 2
            for h, f in zip(halves, fams, strict=True)
        ]
        if sp.expand(entry - sum(entry.coeff(h, 2) * h**2 for h in halves)) != 0:  # pragma: no cover
            raise RuntimeError("the Bloch matrix is not a sum of sin^2(q.b/2) terms")
        return sp.Add(*terms)

    return sp.ImmutableMatrix(bloch.applyfunc(half_angle))


@functools.cache
def long_wave_tensor(pattern):
    """lim_{q -> 0} D(q n)/q^2 for n = (cos theta, sin theta), m^2/s^2: its eigenvalues are c^2 along n."""
    s = symbols()
    q, theta = s["q"], s["theta"]
    along = {s["q_x"]: q * sp.cos(theta), s["q_y"]: q * sp.sin(theta)}
    matrix = dynamical_matrix(pattern).subs(along)

    def limit(entry):  # term by term: each M_f sin^2(q n.b_f/2)/q^2 -> M_f (n.b_f)^2/4
        return sp.Add(*(sp.factor(sp.limit(term / q**2, q, 0)) for term in sp.Add.make_args(entry)))

    return sp.ImmutableMatrix(matrix.applyfunc(limit))


def uniform(expr, pattern):
    """``expr`` with one k, T and a for every family of the layout (the symbols ``k``, ``T``, ``a``)."""
    s = symbols()
    values = {}
    for family in families(pattern):
        values.update({family.k: s["k"], family.T: s["T"], family.length: s["a"]})
    return expr.subs(values)


@functools.cache
def branches_along_x(pattern):
    """(omega_L^2, omega_T^2) of a wave along x (q_x = q, q_y = 0), uniform links (step 6 of the docstring).

    Along x, D is diagonal (checked): the wave polarised along x is longitudinal, the one along y
    transverse, at every q.
    """
    s = symbols()
    matrix = uniform(dynamical_matrix(pattern), pattern).subs({s["q_x"]: s["q"], s["q_y"]: 0})
    if sp.simplify(matrix[0, 1]) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("a wave along x mixes the two polarisations")
    return sp.factor(matrix[0, 0]), sp.factor(matrix[1, 1])


@functools.cache
def long_wave_speeds_squared(pattern, angle=None):
    """(c_L^2, c_T^2), m^2/s^2, of long waves along ``angle`` (default the symbol theta), uniform links.

    The :func:`long_wave_tensor` in the frame of n = (cos angle, sin angle) and its normal t: c_L^2 = n.C n,
    c_T^2 = t.C t.  A ValueError if n.C t does not vanish there (quasi-longitudinal waves: the
    polarisations are not along n and t), as for the square sheet off its axes and diagonals.
    """
    s = symbols()
    theta = s["theta"]
    tensor = uniform(long_wave_tensor(pattern), pattern)
    angle = theta if angle is None else sp.sympify(angle)
    n = sp.Matrix([sp.cos(angle), sp.sin(angle)])
    t = sp.Matrix([-sp.sin(angle), sp.cos(angle)])
    tensor = tensor.subs(theta, angle)

    def project(left, right):
        # Expanded in sin(theta), cos(theta) first (the triangular tensor holds cos(theta + pi/3) and the like):
        # simplify then needs 0.8 s instead of 5 s, to the same result.
        product = sp.expand(sp.expand_trig((left.T * tensor * right)[0, 0]))
        return sp.factor(sp.trigsimp(sp.simplify(product)))

    if project(n, t) != 0:
        raise ValueError(f"long waves of the {pattern} sheet along {angle} are not purely longitudinal and transverse")
    return project(n, n), project(t, t)


@functools.cache
def dispersion_gradient(pattern):
    """(dD/dq_x, dD/dq_y): the derivatives of the Bloch matrix (step 7 of the module docstring), m^2/s^2 per rad/m."""
    s = symbols()
    D = dynamical_matrix(pattern)
    return tuple(sp.ImmutableMatrix(D.applyfunc(lambda entry, q=q: sp.diff(entry, q))) for q in (s["q_x"], s["q_y"]))


# --- numeric functions ----------------------------------------------------------------------------------------


def _family_arguments(pattern):
    s = symbols()
    fams = families(pattern)
    lengths = [s["a_x"], s["a_y"]] if pattern == "square" else [s["a"]]
    return [f.k for f in fams] + [f.T for f in fams] + lengths


@derived
def _square_matrix():
    s = symbols()
    D = dynamical_matrix("square")
    return (s["q_x"], s["q_y"], s["m"], *_family_arguments("square")), sp.Tuple(D[0, 0], D[1, 1], D[0, 1])


@derived
def _triangular_matrix():
    s = symbols()
    D = dynamical_matrix("triangular")
    return (s["q_x"], s["q_y"], s["m"], *_family_arguments("triangular")), sp.Tuple(D[0, 0], D[1, 1], D[0, 1])


def _gradient_entries(pattern):
    s = symbols()
    dx, dy = dispersion_gradient(pattern)
    entries = sp.Tuple(dx[0, 0], dx[1, 1], dx[0, 1], dy[0, 0], dy[1, 1], dy[0, 1])
    return (s["q_x"], s["q_y"], s["m"], *_family_arguments(pattern)), entries


@derived
def _square_gradient():
    return _gradient_entries("square")


@derived
def _triangular_gradient():
    return _gradient_entries("triangular")


def _tensor_in_speeds(pattern):
    """The long-wave tensor in theta and, per family, kappa_f = k_f a_f^2/m and tau_f = T_f a_f/m (m^2/s^2).

    The mass and the lengths cancel (checked): every entry is a sum of the kappa_f and tau_f times functions
    of theta, so the numbers may scale them all by one factor.  In k, T, m and a its entries overflowed
    (k a^2 beyond 1e308 for a above 1e154 m) where the speeds, their square roots, did not.
    """
    s = symbols()
    C = long_wave_tensor(pattern)
    fams = families(pattern)
    kappas = [sp.Symbol(f"kappa_{i}", nonnegative=True) for i in range(len(fams))]
    taus = [sp.Symbol(f"tau_{i}", nonnegative=True) for i in range(len(fams))]
    speeds = {}
    for f, kappa, tau in zip(fams, kappas, taus, strict=True):
        speeds.update({f.k: kappa * s["m"] / f.length**2, f.T: tau * s["m"] / f.length})
    C = C.subs(speeds).applyfunc(sp.simplify)
    if C.has(s["m"], *(f.length for f in fams)):  # pragma: no cover - derivation check
        raise RuntimeError(f"the long-wave tensor of the {pattern} sheet is not a function of k a^2/m and T a/m")
    return (s["theta"], *kappas, *taus), sp.Tuple(C[0, 0], C[1, 1], C[0, 1])


@derived
def _square_tensor():
    return _tensor_in_speeds("square")


@derived
def _triangular_tensor():
    return _tensor_in_speeds("triangular")


_MATRIX = {"square": _square_matrix, "triangular": _triangular_matrix}
_GRADIENT = {"square": _square_gradient, "triangular": _triangular_gradient}
_TENSOR = {"square": _square_tensor, "triangular": _triangular_tensor}
_SHEET = "wavevectors and sheet parameters (k, T, m, a)"


def _per_family(name, value, pattern, unit, check):
    """One validated array per link family: a tuple gives one value per family, anything else is shared."""
    names = FAMILY_NAMES[pattern]
    if isinstance(value, tuple):
        if len(value) != len(names):
            raise ValueError(
                f"{name} for the {pattern} pattern is one value or a tuple of {len(names)} (one per link family: "
                f"{', '.join(names)}), got a tuple of {len(value)}"
            )
        return [check(f"{name}[{i}]", item, unit) for i, item in enumerate(value)]
    value = check(name, value, unit)
    return [value] * len(names)


def _tension(name, value, unit):
    array = v.as_array(name, value)
    if array.size and array.min() < 0:  # NaN compares False: refused below as non-finite
        raise ValueError(
            f"{name} must be non-negative (in {unit}): a link of interlocked rings carries tension only (it goes "
            f"slack under compression), got {v.show(array)}"
        )
    return v.nonnegative(name, array, unit)


def _sheet(pattern, k, T, m, a):
    """Validated per-family k, T, lengths and m, as the generated functions take them (after the wavevector)."""
    _pattern(pattern)
    ks = _per_family("k", k, pattern, "N/m", v.nonnegative)
    Ts = _per_family("T", T, pattern, "N", _tension)
    if pattern == "triangular" and isinstance(a, tuple):
        raise ValueError(
            "a for the triangular pattern is one link length (the bonds form equilateral triangles; per-family "
            "lengths would make the lattice oblique, which is not modelled): give one value; a biaxial pretension "
            "is a tension T per family at that length"
        )
    lengths = _per_family("a", a, pattern, "m", v.positive)
    if pattern == "triangular":
        lengths = lengths[:1]
    m = v.positive("m", m, "kg")
    return m, [*ks, *Ts, *lengths]


def _speeds_squared(pattern, angle, m, params):
    """(xx, yy, xy, log_scale): the long-wave tensor along ``angle`` divided by exp(log_scale), entries at most 3.

    kappa_f = k_f a_f^2/m and tau_f = T_f a_f/m (:func:`_tensor_in_speeds`) are formed from logarithms and divided
    by the largest of them, so that neither they nor the entries leave the doubles; no stiffness and no tension
    leave a zero tensor.
    """
    count = len(FAMILY_NAMES[pattern])
    ks, Ts, lengths = params[:count], params[count : 2 * count], params[2 * count :]
    lengths = lengths * count if len(lengths) == 1 else lengths
    log_m = np.log(m)
    logs = [np.log(k) + 2 * np.log(a) - log_m for k, a in zip(ks, lengths, strict=True)]
    logs += [np.log(T) + np.log(a) - log_m for T, a in zip(Ts, lengths, strict=True)]
    log_scale = functools.reduce(np.maximum, logs)
    log_scale = np.where(log_scale > -np.inf, log_scale, 0.0)
    scaled = [np.exp(x - log_scale) for x in logs]
    xx, yy, xy = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in _TENSOR[pattern](angle, *scaled)))
    return xx, yy, xy, log_scale


#: Below this phase q a/2 per bond sin^2 equals its argument's square to double precision (relative 3e-17), and
#: the dispersion is the long-wave tensor times q^2 (:func:`sheet_dispersion`).
_LONG_WAVE_PHASE = 1e-8


def _named(pattern, values):
    """The per-family arrays with their parameter names, for shape messages."""
    names = FAMILY_NAMES[pattern]
    labels = [f"k[{i}]" for i in range(len(names))] + [f"T[{i}]" for i in range(len(names))]
    labels += [f"a[{i}]" for i in range(len(values) - len(labels))]
    return dict(zip(labels, values, strict=True))


def _ascending(xx, yy, xy):
    """Ascending eigenvalues of the symmetric positive semi-definite [[xx, xy], [xy, yy]], no overflow.

    The larger is (xx + yy)/2 + hypot((xx - yy)/2, xy), a sum of non-negative terms; the smaller is the
    determinant over it, written (xx/upper) yy - (xy/upper) xy so that no product overflows (both ratios
    are at most 1).  Rounding can leave the smaller a few ulp of the larger below zero where the matrix is
    singular (a mechanism of the network); it is set to zero there.
    """
    xx, yy, xy = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (xx, yy, xy)))
    upper = 0.5 * xx + 0.5 * yy + np.hypot(0.5 * xx - 0.5 * yy, xy)
    safe = np.where(upper > 0, upper, 1.0)
    lower = np.where(upper > 0, (xx / safe) * yy - (xy / safe) * xy, 0.0)
    return np.maximum(lower, 0.0), upper


def sheet_dispersion(qx, qy, *, pattern, T, k, m, a):
    """Angular frequencies of the in-plane waves of a pretensioned sheet of interlinked rings, rad/s.

    Parameters
    ----------
    qx, qy : array_like
        Wavevector components, rad/m, along x (the first lattice direction) and y.
    pattern : {"square", "triangular"}
        ``"square"``: each ring linked to 4 neighbours along x and y (4-in-1 chain mail), bond vectors
        (a_x, 0) and (0, a_y).  ``"triangular"``: 6 neighbours at 0, 60 and 120 degrees from x (6-in-1),
        bonds of one length a.
    T : array_like or tuple
        Static tension of a link, N, >= 0 (links carry tension only).  A tuple gives one value per
        link family, (T_x, T_y) for the square sheet and (T_0, T_60, T_120) for the triangular one;
        any other array_like (a number, a list, an ndarray) is the same for every family and broadcasts.
    k : array_like or tuple
        Axial stiffness of a link at its static tension, N/m, >= 0: k = dF/d delta of the contact law
        (for the power law F = K delta^n, k = n K^(1/n) T^((n-1)/n)); per family as ``T``.
    m : array_like
        Inertial mass of a ring (one site per ring), kg.
    a : array_like or tuple
        Length of a link in the pretensioned state (distance between the two ring centres), m; a tuple
        (a_x, a_y) for the square sheet.  The triangular sheet takes one length (equilateral bonds).

    Returns
    -------
    ndarray
        omega, rad/s, of shape broadcast(qx, qy, T, k, m, a) + (2,): the two in-plane branches on the
        last axis, ascending (so a branch is not one polarisation: where they cross the labels swap).
        Along a lattice direction of the square sheet the branches are the longitudinal wave (the 1D
        chain's) and the transverse wave (the string's, with the geometric stiffness T/a); for rings
        k a >> T, so the transverse one is the lower.

    Notes
    -----
    The eigenvalues of the Bloch matrix D(q) = (4/m) sum_f [k_f e_f e_f^T + (T_f/a_f)(I - e_f e_f^T)]
    sin^2(q.b_f/2) (:func:`dynamical_matrix`, derived from the network's potential energy to second
    order about the pretensioned state).  omega is periodic on the reciprocal lattice.  Every set of
    family tensions is an equilibrium (:func:`equilibrium_force`); the square sheet then carries the
    membrane tensions (force per length of a cut) T_x/a_y along x and T_y/a_x along y.  The square sheet without
    pretension (T = 0) has zero-frequency branches (it shears freely).  Beyond the paper (Sec. V names
    2D interlinked lattices as the next step).

    Examples
    --------
    >>> sheet_dispersion(np.pi, 0.0, pattern="square", T=0.25, k=1.0, m=1.0, a=1.0).tolist()  # T/a, k
    [1.0, 2.0]
    >>> sheet_dispersion([0.1, 0.2], 0.0, pattern="triangular", T=0.0, k=1.0, m=1.0, a=1.0).shape
    (2, 2)
    """
    m, params = _sheet(pattern, k, T, m, a)
    qx, qy = v.as_float("qx", qx), v.as_float("qy", qy)
    v.broadcast_shape(qx=qx, qy=qy, m=m, **_named(pattern, params))
    with np.errstate(all="ignore"):  # overflow is reported below, by value
        lower, upper = _ascending(*_MATRIX[pattern](qx, qy, m, *params))
        omega = np.stack([np.sqrt(lower), np.sqrt(upper)], axis=-1)
        # Long waves as q^2 times the long-wave tensor: sin^2(q a/2) underflows for q a below 1e-154, and with it
        # omega, where the geometric stiffness T/a is large enough to keep omega far above the smallest double.
        q = np.hypot(qx, qy)
        long = q * functools.reduce(np.maximum, params[2 * len(FAMILY_NAMES[pattern]) :]) / 2 < _LONG_WAVE_PHASE
        if np.any(long):
            xx, yy, xy, log_scale = _speeds_squared(pattern, np.arctan2(qy, qx), m, params)
            speeds = np.stack([np.sqrt(c) for c in _ascending(xx, yy, xy)], axis=-1)
            speeds = speeds * np.exp(0.5 * log_scale)[..., None]
            omega = np.where(long[..., None], q[..., None] * speeds, omega)
    return v.finite_result(omega, "omega", _SHEET)


def sheet_group_velocity(qx, qy, *, pattern, T, k, m, a):
    """Group velocities of the two in-plane branches of a pretensioned sheet, m/s.

    Parameters
    ----------
    qx, qy : array_like
        Wavevector components, rad/m, as in :func:`sheet_dispersion`; not both zero.
    pattern, T, k, m, a
        As in :func:`sheet_dispersion`.

    Returns
    -------
    ndarray
        v_g = grad_q omega, m/s, of shape broadcast(qx, qy, T, k, m, a) + (2, 2): the branches on the
        second-last axis in the order of :func:`sheet_dispersion` (ascending omega), the (x, y) components
        on the last.  Where the two branches meet (the square sheet's diagonal for long waves) omega is not
        differentiable and the value is that of one of the two polarisations.

    Notes
    -----
    v_g = U^T (grad_q D) U/(2 omega) for the unit eigenvector U of the Bloch matrix D(q) of the branch
    (:func:`dispersion_gradient`, step 7 of the module docstring).  For long waves the branches are
    non-dispersive and v_g along a ray direction traces the wave surface, the front of a point source:
    for the square sheet's branch polarised along x it is the ellipse (x/c_L)^2 + (y/c_T)^2 = t^2, so that
    off a lattice direction the front of that branch travels at 1/sqrt(cos^2/c_L^2 + sin^2/c_T^2), close
    to c_T/|sin| where c_T << c_L.  Beyond the paper.

    Examples
    --------
    >>> v = sheet_group_velocity(1e-6, 0.0, pattern="square", T=0.25, k=1.0, m=1.0, a=1.0)  # long wave along x
    >>> [round(float(x), 9) for x in v[:, 0]]  # the string's sqrt(T a/m), then the chain's a sqrt(k/m)
    [0.5, 1.0]
    """
    m, params = _sheet(pattern, k, T, m, a)
    qx, qy = v.as_float("qx", qx), v.as_float("qy", qy)
    v.broadcast_shape(qx=qx, qy=qy, m=m, **_named(pattern, params))
    if np.any((qx == 0) & (qy == 0)):
        raise ValueError(
            "the wavevector (qx, qy) in rad/m must not be zero: the group velocity of a long wave is "
            "taken at a small q (sheet_sound_speeds gives the long-wave phase speeds)"
        )
    with np.errstate(all="ignore"):  # overflow is reported below, by value
        xx, yy, xy = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in _MATRIX[pattern](qx, qy, m, *params)))
        lower, upper = _ascending(xx, yy, xy)
        # The upper eigenvector makes the angle psi with x, tan(2 psi) = 2 xy/(xx - yy); the lower is normal to it.
        psi = 0.5 * np.arctan2(2 * xy, xx - yy)
        c, s = np.cos(psi), np.sin(psi)
        gradient = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in _GRADIENT[pattern](qx, qy, m, *params)))
        velocity = []
        for omega2, (ux, uy) in ((lower, (-s, c)), (upper, (c, s))):
            omega = np.sqrt(omega2)
            components = [
                (ux * ux * dxx + uy * uy * dyy + 2 * ux * uy * dxy) / (2 * omega)
                for dxx, dyy, dxy in (gradient[:3], gradient[3:])
            ]
            velocity.append(np.stack(components, axis=-1))
        velocity = np.stack(velocity, axis=-2)
    return v.finite_result(velocity, "the group velocity", _SHEET)


class SheetSpeeds(NamedTuple):
    """Long-wave speeds of a sheet along a direction, m/s (see :func:`sheet_sound_speeds`)."""

    longitudinal: np.ndarray
    transverse: np.ndarray


def sheet_sound_speeds(angle, *, pattern, T, k, m, a):
    """Speeds of long in-plane waves of a pretensioned sheet along a direction, m/s.

    Parameters
    ----------
    angle : array_like
        Direction of propagation, rad, from the x axis (the first lattice direction).
    pattern, T, k, m, a
        As in :func:`sheet_dispersion`.

    Returns
    -------
    SheetSpeeds
        ``longitudinal`` and ``transverse``: lim_{q -> 0} omega/q of the two branches along
        n = (cos angle, sin angle), the square roots of the eigenvalues of the :func:`long_wave_tensor`.
        Where its polarisations are not along n and its normal (the square sheet off its axes and
        diagonals, or a biaxially pretensioned triangular one) the waves are quasi-longitudinal and
        quasi-transverse: ``longitudinal`` is the branch polarised nearer n; where both are 45 degrees
        from n it is the faster.  Arrays of shape broadcast(angle, T, k, m, a).

    Notes
    -----
    Square sheet along x: c_L = a_x sqrt(k_x/m) (the chain's sound speed), c_T = sqrt(T_x a_x/m) (a
    string of tension T_x and mass m/a_x per length); along the diagonal, with one k, T, a, both are
    sqrt((k a^2 + T a)/(2m)).  Triangular sheet with one k, T, a: isotropic, c_L^2 = (9 k a^2 + 3 T a)/(8m),
    c_T^2 = (3 k a^2 + 9 T a)/(8m) (:func:`long_wave_speeds_squared`).  Beyond the paper.

    Examples
    --------
    >>> c = sheet_sound_speeds(0.0, pattern="triangular", T=0.0, k=8.0, m=9.0, a=1.0)
    >>> round(float(c.longitudinal), 12), round(float(c.transverse) ** 2, 12)
    (1.0, 0.333333333333)
    """
    m, params = _sheet(pattern, k, T, m, a)
    angle = v.as_float("angle", angle)
    v.broadcast_shape(angle=angle, m=m, **_named(pattern, params))
    with np.errstate(all="ignore"):  # overflow is reported below, by value
        xx, yy, xy, log_scale = _speeds_squared(pattern, angle, m, params)
        lower, upper = _ascending(xx, yy, xy)
        # n.C n - t.C t: positive when the faster branch is polarised nearer n (the polarisation of the
        # larger eigenvalue makes the angle psi with tan(2 psi) = 2 xy/(xx - yy)).  Zero when both are 45
        # degrees from n; within the rounding of cos(2 angle) and sin(2 angle) (a few ulp of the larger
        # term: cos(pi/2) is 6e-17 in double) that counts as zero, and the faster branch is longitudinal.
        nearer_n = (xx - yy) * np.cos(2 * angle) + 2 * xy * np.sin(2 * angle)
        nearer = nearer_n >= -8 * np.finfo(float).eps * (np.abs(xx - yy) + 2 * np.abs(xy))
        scale = np.exp(0.5 * log_scale)
        longitudinal = np.sqrt(np.where(nearer, upper, lower)) * scale
        transverse = np.sqrt(np.where(nearer, lower, upper)) * scale
    return SheetSpeeds(
        v.finite_result(longitudinal, "the longitudinal speed", _SHEET),
        v.finite_result(transverse, "the transverse speed", _SHEET),
    )
