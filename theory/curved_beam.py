r"""A ring as a curved beam: kinematics, section constants, exact curved elements, free vibration.

The derivation, step by step (each step a function returning SymPy objects):

1. :func:`field_functions`, :func:`generalised_strains` -- a ring of centroidal radius R,
   angle theta measured in its plane.  Six centroid fields, in the local frame
   (e_r outward, e_t along increasing theta, e_z normal to the plane): translations
   w (radial), u (tangential), v (normal) and rotations psi (about e_z), phi_r (about e_r),
   phi_t (about e_t).  The linear strains of a Cosserat rod, Gamma = d' - Phi x e_t and
   K = Phi' with d/ds in the rotating frame (e_r' = e_t/R, e_t' = -e_r/R), split into the
   in-plane strains (extension eps, shear gamma, curvature change kappa) and the
   out-of-plane ones (bending kappa_r, twist kappa_t, shear gamma_z).
2. :func:`fibre_displacement`, :func:`fibre_strain` -- the cross-section (a disc of radius r)
   is rigid; the fibre at (y, z) of the section (y outward, z normal) has length
   (R + y) dtheta, so its strain is (eps + y kappa - z kappa_r)/(1 + y/R): Winkler's thick
   curved beam (Boresi & Schmidt, Ch. 9), the same theory as the package's Castigliano
   bending stiffness (:mod:`.ring`).
3. :func:`section_stiffness`, :func:`section_inertia` -- integrating the fibre energy
   E e^2/2 and the kinetic energy rho |d_dot|^2/2 over the section (weight (R + y)/R per unit
   centroidal length) gives the stiffness and inertia matrices of the section.  The
   1/(R + y) integrals reduce to Winkler's integral of dA/(R + y) (:func:`.ring.section_properties`).
   Transverse shear and torsion use the straight-bar constants G A/F (F = 10/9) and G J
   (J = pi r^4/2); their curved-bar corrections are O((r/R)^2) and not included.
4. :func:`homogeneous_solutions` -- the Euler-Lagrange equations of the static energy
   have, on any arc, a six-dimensional space of solutions (three rigid motions and three
   states of constant end loads), found exactly as combinations of 1, theta, cos, sin,
   theta cos, theta sin.  Interpolating the nodal values with them gives a two-node
   element whose static response is exact (no shear or membrane locking, rigid motions
   strain-free); its consistent mass follows from the same shape functions
   (:func:`element_matrices`).
5. :func:`mode_matrices` -- a free ring vibrating with circumferential order k
   (w ~ cos k theta, ...) reduces to 3x3 stiffness and mass matrices per order: the
   continuum frequencies the elements must converge to.
6. :func:`inextensional_frequency_expression` -- the classical thin-ring limits, derived
   from the same energies: inextensional, shear-rigid, without rotary inertia, thin
   section.  In plane (Hoppe 1871): omega_k^2 = E I k^2 (k^2 - 1)^2 / (rho A R^4 (k^2 + 1));
   out of plane (Michell 1890): omega_k^2 = E I k^2 (k^2 - 1)^2 / (rho A R^4 (k^2 + E I/(G J)))
   (Love, *Mathematical Theory of Elasticity*, Ch. XVIII; Rao, *Vibration of Continuous
   Systems*, Ch. 12).

The numeric functions evaluate lambdified forms of these expressions
(:func:`element_matrices`, :func:`ring_frequencies`, :func:`inextensional_frequency`).
"""

from __future__ import annotations

import functools
from typing import NamedTuple

import numpy as np

from . import _validate as v
from ._codegen import derived, sp
from .ring import SHEAR_FORM_FACTOR_CIRCLE, section_properties

__all__ = [
    "PLANES",
    "symbols",
    "field_functions",
    "fibre_displacement",
    "fibre_strain",
    "generalised_strains",
    "section_integral",
    "section_stiffness",
    "section_inertia",
    "energy_densities",
    "homogeneous_solutions",
    "mode_matrices",
    "inextensional_frequency_expression",
    "ElementMatrices",
    "element_matrices",
    "element_shape_functions",
    "ring_frequencies",
    "inextensional_frequency",
    "plane_kind",
]

#: The two decoupled families of motion of a plane ring.
PLANES = ("in-plane", "out-of-plane")

#: Gauss-Legendre points per element: the integrands (products of 1, theta, cos, sin, theta cos,
#: theta sin over at most a quarter turn) are entire; 16 points integrate them to rounding.
_GAUSS_POINTS = 16


def plane_kind(kind: str) -> str:
    """``kind`` if it is one of :data:`PLANES` (ValueError listing them)."""
    if kind not in PLANES:
        raise ValueError(f"kind must be one of {PLANES}, got {kind!r}")
    return kind


@functools.cache
def symbols():
    """Symbols: angle theta, ring radius R, tube radius r, E, nu, rho, section coordinates y, z,
    circumferential order k, strain symbols and the generic section constants of step 4."""
    theta = sp.Symbol("theta", real=True)
    R, r, E, rho = sp.symbols("R r E rho", positive=True)
    nu = sp.Symbol("nu", positive=True)
    y, z = sp.symbols("y z", real=True)
    k = sp.Symbol("k", integer=True, positive=True)
    strains = {
        "in-plane": sp.symbols("epsilon gamma kappa", real=True),
        "out-of-plane": sp.symbols("kappa_r kappa_t gamma_z", real=True),
    }
    # Generic section constants (step 4): the sparsity of the derived matrices, numbers later.
    D11, Ds, D22, Db, Dt, Dz = sp.symbols("D_11 D_s D_22 D_b D_t D_z", positive=True)
    D12 = sp.Symbol("D_12", real=True)
    m11, m22, m33 = sp.symbols("m_11 m_22 m_33", positive=True)
    m23 = sp.Symbol("m_23", real=True)
    return dict(
        theta=theta, R=R, r=r, E=E, nu=nu, rho=rho, y=y, z=z, k=k, strains=strains,
        D={
            "in-plane": sp.Matrix([[D11, 0, D12], [0, Ds, 0], [D12, 0, D22]]),
            "out-of-plane": sp.diag(Db, Dt, Dz),
        },
        # In plane (w, u, psi): u and psi couple (I/R); out of plane (v, phi_r, phi_t): v and phi_t.
        m={
            "in-plane": sp.Matrix([[m11, 0, 0], [0, m11, m23], [0, m23, m33]]),
            "out-of-plane": sp.Matrix([[m11, 0, m23], [0, m22, 0], [m23, 0, m33]]),
        },
    )  # fmt: skip


@functools.cache
def field_functions():
    """The six centroid fields of theta: {'in-plane': (w, u, psi), 'out-of-plane': (v, phi_r, phi_t)}."""
    theta = symbols()["theta"]
    make = lambda *names: tuple(sp.Function(n)(theta) for n in names)  # noqa: E731
    return {"in-plane": make("w", "u", "psi"), "out-of-plane": make("v", "phi_r", "phi_t")}


def _frame_derivative(vector):
    """d/ds of a vector given by its (r, t, z) components in the frame rotating along the ring."""
    s = symbols()
    a_r, a_t, a_z = vector
    R, theta = s["R"], s["theta"]
    return sp.Matrix([a_r.diff(theta) / R - a_t / R, a_t.diff(theta) / R + a_r / R, a_z.diff(theta) / R])


def _displacement_and_rotation():
    (w, u, psi), (v, phi_r, phi_t) = field_functions().values()
    return sp.Matrix([w, u, v]), sp.Matrix([phi_r, phi_t, psi])


def generalised_strains(kind="in-plane"):
    """Strains of the centroid line (linear Cosserat rod), as a Matrix of expressions.

    In plane: (eps, gamma, kappa) = (Gamma_t, Gamma_r, K_z); out of plane:
    (kappa_r, kappa_t, gamma_z) = (K_r, K_t, Gamma_z), where Gamma = d' - Phi x e_t and K = Phi'.
    """
    d, phi = _displacement_and_rotation()
    tangent = sp.Matrix([0, 1, 0])
    Gamma = _frame_derivative(d) - phi.cross(tangent)
    K = _frame_derivative(phi)
    if plane_kind(kind) == "in-plane":
        return sp.Matrix([Gamma[1], Gamma[0], K[2]])
    return sp.Matrix([K[0], K[1], Gamma[2]])


def fibre_displacement():
    """(radial, tangential, normal) displacement of the fibre (y, z) of a rigid section: d + Phi x (y e_r + z e_z)."""
    s = symbols()
    d, phi = _displacement_and_rotation()
    return d + phi.cross(sp.Matrix([s["y"], 0, s["z"]]))


def fibre_strain():
    """Circumferential strain of the fibre at (y, z): (d u_t/d theta + u_r)/(R + y) of its displacement."""
    s = symbols()
    radial, tangential, _ = fibre_displacement()
    return (tangential.diff(s["theta"]) + radial) / (s["R"] + s["y"])


@functools.cache
def _disc_moment(a: int, b: int):
    """integral(y^a z^b dA) over the disc of radius r, in polar coordinates y = s cos t, z = s sin t."""
    s = symbols()
    t, radius = sp.Symbol("t", real=True), s["r"]
    angular = sp.integrate(sp.cos(t) ** a * sp.sin(t) ** b, (t, 0, 2 * sp.pi))
    return angular * radius ** (a + b + 2) / (a + b + 2)


def _polynomial_section_integral(poly):
    """integral(P dA) over the disc for a polynomial P in y, z (monomial by monomial)."""
    s = symbols()
    P = sp.Poly(sp.expand(poly), s["y"], s["z"])
    return sum((coeff * _disc_moment(a, b) for (a, b), coeff in P.terms()), sp.Integer(0))


def section_integral(expr, thick=True):
    """Integral over the disc y^2 + z^2 <= r^2 of a polynomial in y, z, divided by (R + y) if ``thick``.

    Polynomials integrate monomial by monomial (:func:`_disc_moment`).  For the thick
    case the z integral over the chord |z| <= h = sqrt(r^2 - y^2) is done first: the even
    powers give h times a polynomial P(y), and dividing P by (R + y), P = Q (R + y) + c,
    leaves integral(h Q dy) = integral(Q dA)/2 and Winkler's integral(dA/(R + y)) = A/R_n
    (:func:`.ring.section_properties`), so integral(expr dA) = integral(Q dA)/2 + c A/(2 R_n).
    """
    s = symbols()
    y, z, r, R = s["y"], s["z"], s["r"], s["R"]
    if not thick:
        return sp.simplify(_polynomial_section_integral(expr))
    chord = sp.Integer(0)  # integral(expr dz) / h, a polynomial in y
    for (power,), coeff in sp.Poly(sp.expand(expr), z).terms():
        if power % 2 == 0:  # odd powers of z integrate to zero
            chord += coeff * 2 * (r**2 - y**2) ** sp.Rational(power, 2) / (power + 1)
    quotient, remainder = sp.div(sp.Poly(sp.expand(chord), y), sp.Poly(R + y, y))
    section = section_properties()
    winkler = section["A"] / (R - section["e"])  # integral(dA/(R + y)) = A/R_n
    return sp.simplify(_polynomial_section_integral(quotient.as_expr()) / 2 + remainder.as_expr() * winkler / 2)


def _strain_symbols_of_fibre():
    """The fibre strain written with the strain symbols: (eps + y kappa - z kappa_r)/(1 + y/R)."""
    s = symbols()
    eps, _, kappa = s["strains"]["in-plane"]
    kappa_r = s["strains"]["out-of-plane"][0]
    return (eps + s["y"] * kappa - s["z"] * kappa_r) / (1 + s["y"] / s["R"])


@functools.cache
def section_stiffness(kind="in-plane", thick=True):
    """Section stiffness matrix D: strain energy per unit centroidal length = s^T D s / 2.

    In plane s = (eps, gamma, kappa); out of plane s = (kappa_r, kappa_t, gamma_z).
    ``thick=False`` drops the curvature of the section (fibre strain eps + y kappa - z kappa_r):
    D = diag(E A, G A/F, E I) and diag(E I, G J, G A/F), the thin-ring constants.
    """
    s = symbols()
    R, E, nu, y = s["R"], s["E"], s["nu"], s["y"]
    strain = _strain_symbols_of_fibre()
    if thick:
        # E e^2/2 over a fibre volume (R + y)/R per unit centroidal length: E R (...)^2/(R + y)/2.
        density = E * R * sp.expand(sp.numer(sp.together(strain)) ** 2) / 2 / R**2
        normal_energy = section_integral(density, thick=True)
    else:
        normal_energy = section_integral(E * sp.expand((strain * (1 + y / R)) ** 2) / 2, thick=False)
    G = E / (2 * (1 + nu))
    F = sp.Rational(*SHEAR_FORM_FACTOR_CIRCLE)
    area = section_integral(sp.Integer(1), thick=False)
    polar = section_integral(s["y"] ** 2 + s["z"] ** 2, thick=False)  # J of a solid circle
    gamma, (_, kappa_t, gamma_z) = s["strains"]["in-plane"][1], s["strains"]["out-of-plane"]
    energy = normal_energy + G * area / F * (gamma**2 + gamma_z**2) / 2 + G * polar * kappa_t**2 / 2
    names = s["strains"][plane_kind(kind)]
    return sp.simplify(sp.hessian(energy, names))


@functools.cache
def section_inertia(kind="in-plane", thick=True):
    """Section inertia matrix m: kinetic energy per unit centroidal length = rho q_dot^T m q_dot / 2.

    q = (w, u, psi) in plane, (v, phi_r, phi_t) out of plane; from the fibre velocities of
    :func:`fibre_displacement` weighted by the fibre length (1 + y/R) (``thick=False``: weight 1).
    """
    s = symbols()
    fields = field_functions()[plane_kind(kind)]
    rates = sp.symbols("q_1:4", real=True)
    fibre = fibre_displacement()
    others = [f for plane in PLANES for f in field_functions()[plane] if f not in fields]
    fibre = fibre.subs({f: 0 for f in others}).subs(dict(zip(fields, rates, strict=True)))
    weight = (1 + s["y"] / s["R"]) if thick else 1
    density = sp.expand(sum(c**2 for c in fibre) * weight / 2)
    energy = section_integral(density, thick=False)
    return sp.simplify(sp.hessian(energy, rates))


def energy_densities(kind="in-plane", D=None, m=None):
    """(strain energy, kinetic energy / rho) per unit angle, in terms of the fields (and their rates).

    ``D`` and ``m`` default to the generic section constants of :func:`symbols` (step 4);
    the kinetic density is written with the fields standing for their rates.
    """
    s = symbols()
    D = s["D"][plane_kind(kind)] if D is None else D
    m = s["m"][kind] if m is None else m
    strains = generalised_strains(kind)
    q = sp.Matrix(field_functions()[kind])
    R = s["R"]
    return (R * (strains.T * D * strains)[0] / 2, R * (q.T * m * q)[0] / 2)


#: Trial functions of the homogeneous solutions (step 4).
def _trial_functions():
    theta = symbols()["theta"]
    c, si = sp.cos(theta), sp.sin(theta)
    return [sp.Integer(1), theta, theta**2, c, si, theta * c, theta * si]


@functools.cache
def homogeneous_solutions(kind="in-plane"):
    """The six independent static solutions on an arc, as a 3x6 Matrix (fields x solutions).

    Solves the Euler-Lagrange equations of the static energy (generic section constants)
    in the span of :func:`_trial_functions` for each field; the solution space is
    six-dimensional (checked), three rigid motions and three constant-load states.
    """
    s = symbols()
    theta = s["theta"]
    from sympy.calculus.euler import euler_equations

    fields = field_functions()[plane_kind(kind)]
    energy, _ = energy_densities(kind)
    equations = euler_equations(energy, list(fields), theta)
    trial = _trial_functions()
    coefficients = [sp.symbols(f"c_{j}_0:{len(trial)}") for j in range(3)]
    ansatz = {f: sum(c * t for c, t in zip(cs, trial, strict=True)) for f, cs in zip(fields, coefficients, strict=True)}
    conditions = []
    for eq in equations:
        residual = sp.expand(eq.lhs.subs(ansatz).doit())
        basis = [theta * sp.cos(theta), theta * sp.sin(theta), sp.cos(theta), sp.sin(theta), theta**2, theta]
        conditions += list(sp.collect(residual, basis, evaluate=False).values())
    unknowns = [c for cs in coefficients for c in cs]
    matrix, _ = sp.linear_eq_to_matrix(conditions, unknowns)
    # Exact linear algebra over the field of rational functions of the section constants.
    from sympy.polys.matrices import DomainMatrix

    null = DomainMatrix.from_Matrix(matrix).to_field().nullspace().to_Matrix()
    if null.rows != 6:  # pragma: no cover - a wrong trial space would show here
        raise RuntimeError(f"expected 6 homogeneous solutions, found {null.rows}")
    n = len(trial)
    columns = []
    for row in range(6):
        vector = null.row(row)
        pivot = next(x for x in vector if x != 0)  # scale each solution to a unit leading coefficient
        coefficients_ = [sp.factor(sp.cancel(x / pivot)) for x in vector]
        columns.append([sum(coefficients_[j * n + i] * trial[i] for i in range(n)) for j in range(3)])
    return sp.Matrix(columns).T


def _element_basis(kind):
    """(args, [B; S]): the six solutions (3x6) and their strains (3x6), for lambdify."""
    s = symbols()
    B = homogeneous_solutions(kind)
    fields = field_functions()[kind]
    strains = generalised_strains(kind)
    columns = []
    for j in range(6):
        values = dict(zip(fields, B[:, j], strict=True))
        columns.append(strains.subs(values).doit())
    S = sp.Matrix.hstack(*columns)
    D = s["D"][kind]
    constants = sorted(D.free_symbols, key=lambda x: x.name)
    return (s["theta"], s["R"], *constants), sp.Matrix.vstack(B, sp.simplify(S))


@derived
def _element_basis_in_plane():
    return _element_basis("in-plane")


@derived
def _element_basis_out_of_plane():
    return _element_basis("out-of-plane")


@derived
def _section_matrices():
    """(R, r, E, nu) -> [D_in; D_out; m_in; m_out; thin D_in; thin D_out; thin m_in; thin m_out] (24x3)."""
    s = symbols()
    blocks = [section_stiffness(k, thick) for thick in (True, False) for k in PLANES]
    blocks += [section_inertia(k, thick) for thick in (True, False) for k in PLANES]
    order = [0, 1, 4, 5, 2, 3, 6, 7]  # thick D, thick m, thin D, thin m
    return (s["R"], s["r"], s["E"], s["nu"]), sp.Matrix.vstack(*[blocks[i] for i in order])


def _sections(R, r, E, nu, thick=True):
    """Numeric {'D': {plane: 3x3}, 'm': {plane: 3x3}} (m per unit rho)."""
    values = np.asarray(_section_matrices(float(R), float(r), float(E), float(nu)), dtype=float).reshape(8, 3, 3)
    offset = 0 if thick else 4
    return {
        "D": dict(zip(PLANES, values[offset : offset + 2], strict=True)),
        "m": dict(zip(PLANES, values[offset + 2 : offset + 4], strict=True)),
    }


def _generic_values(kind, D):
    """The entries of a numeric D in the order of the generic symbols (sorted by name)."""
    generic = symbols()["D"][kind]
    positions = {sym: divmod(i, 3) for i, sym in enumerate(generic) if sym != 0}
    return [D[positions[sym]] for sym in sorted(positions, key=lambda x: x.name)]


class ElementMatrices(NamedTuple):
    """Stiffness and consistent mass of one curved element, and its end resultants.

    DOFs: node 1 then node 2, each (w, u, psi) in plane or (v, phi_r, phi_t) out of plane,
    in the local frame of the node (translations in m, rotations in rad).

    Attributes
    ----------
    stiffness, mass : ndarray, shape (6, 6)
        N/m (and N, N m for the rotation entries); kg (and kg m, kg m^2).
    resultants : ndarray, shape (2, 3, 6)
        Section resultants at node 1 and node 2 from the nodal DOFs: D times the strains,
        (N, V, M) in plane (normal force, shear force along e_r, moment about e_z; N and N m),
        (M_r, T, V_z) out of plane.
    """

    stiffness: np.ndarray
    mass: np.ndarray
    resultants: np.ndarray


def _ring_and_material(R, r, E, nu):
    """Checked arrays R, r (r < R), E, nu, as :func:`.ring.bending_stiffness` checks them."""
    R = v.positive("R", R, "m")
    r = v.positive("r", r, "m")
    if np.any(r >= R):
        raise ValueError(f"r must be smaller than R for a ring (got R/r = {np.min(R / r):g})")
    return R, r, v.positive("E", E, "Pa"), v.in_range("nu", nu, -1.0, 0.5, closed_high=False)


def _element_inputs(R, r, E, nu, angle, kind):
    R, r, E, nu = (float(x) for x in _ring_and_material(R, r, E, nu))
    beta = float(v.in_range("angle", angle, 0.0, np.pi / 2))
    return R, r, E, nu, beta, plane_kind(kind)


def _unit_element(r_over_R, nu, beta, kind):
    """On a ring of unit radius and modulus: (basis at theta, D, m, inverse of the nodal matrix).

    ``basis(theta)`` is the 6x6 [B; S] of :func:`_element_basis`; the shape functions are
    B(theta) @ inverse.
    """
    section = _sections(1.0, r_over_R, 1.0, nu)
    D, m = section["D"][kind], section["m"][kind]
    func = _element_basis_in_plane if kind == "in-plane" else _element_basis_out_of_plane
    constants = _generic_values(kind, D)

    def basis(theta):
        return np.asarray(func(float(theta), 1.0, *constants), dtype=float)

    inverse = np.linalg.inv(np.vstack([basis(0.0)[:3], basis(beta)[:3]]))
    return basis, D, m, inverse


def _dof_scale(R, kind):
    """Length scale of each nodal DOF (translations R, rotations 1), node 1 then node 2."""
    dof = np.array([R, R, 1.0] if kind == "in-plane" else [R, 1.0, 1.0])
    return np.concatenate([dof, dof])


def element_matrices(R, r, E, nu, *, rho, angle, kind="in-plane") -> ElementMatrices:
    """Stiffness, consistent mass and resultants of one exact curved element (step 4).

    Parameters
    ----------
    R : float
        Centroidal radius of the ring, m.
    r : float
        Radius of the solid circular section, m; r < R.
    E : float
        Young's modulus, Pa.
    nu : float
        Poisson's ratio.
    rho : float
        Density, kg/m^3.
    angle : float
        Angle spanned by the element, rad, in (0, pi/2].
    kind : {"in-plane", "out-of-plane"}

    Returns
    -------
    ElementMatrices

    Notes
    -----
    The shape functions interpolate the nodal values with the six exact static solutions
    (:func:`homogeneous_solutions`), so a ring of any number of these elements has the
    exact static stiffness of the curved-beam theory (its diametral stiffness is the
    Castigliano K_b of paper Eq. (2), :func:`~ringchain.theory.bending_stiffness`), and
    rigid motions are exactly strain-free.  The integrals are computed on a ring of unit
    radius and modulus (well-conditioned) by Gauss-Legendre quadrature and scaled to SI.

    Examples
    --------
    >>> el = element_matrices(22.5e-3, 2.5e-3, 193e9, 0.29, rho=8000.0, angle=np.pi / 16)
    >>> el.stiffness.shape, bool(np.allclose(el.stiffness, el.stiffness.T))
    ((6, 6), True)
    """
    R, r, E, nu, beta, kind = _element_inputs(R, r, E, nu, angle, kind)
    rho = float(v.positive("rho", rho, "kg/m^3"))
    basis, D, m, inverse = _unit_element(r / R, nu, beta, kind)
    x, weights = np.polynomial.legendre.leggauss(_GAUSS_POINTS)
    values = np.array([basis(t) for t in (x + 1.0) * beta / 2.0])
    weights = weights * beta / 2.0
    B, S = values[:, :3, :], values[:, 3:, :]
    K_hat = inverse.T @ np.einsum("q,qia,ij,qjb->ab", weights, S, D, S) @ inverse
    M_hat = inverse.T @ np.einsum("q,qia,ij,qjb->ab", weights, B, m, B) @ inverse
    resultants_hat = np.array([D @ basis(t)[3:] @ inverse for t in (0.0, beta)])
    # Back to SI: lengths scale with R, strain energy with E R^3, kinetic energy with rho R^5 omega^2.
    dof = _dof_scale(R, kind)
    scale = np.outer(1.0 / dof, 1.0 / dof)
    K = 0.5 * (K_hat + K_hat.T) * scale * E * R**3
    M = 0.5 * (M_hat + M_hat.T) * scale * rho * R**5
    # Resultants: forces scale with E R^2, moments with E R^3.
    force = np.array([E * R**2, E * R**2, E * R**3] if kind == "in-plane" else [E * R**3, E * R**3, E * R**2])
    resultants = resultants_hat * force[None, :, None] / dof[None, None, :]
    return ElementMatrices(stiffness=K, mass=M, resultants=resultants)


def element_shape_functions(R, r, E, nu, angle, theta, kind="in-plane") -> np.ndarray:
    """Shape functions of the exact curved element at angles ``theta`` within it, shape (len(theta), 3, 6).

    Row i gives field i (w, u, psi or v, phi_r, phi_t; m and rad) at theta from the six nodal
    DOFs of :class:`ElementMatrices`.  Parameters as :func:`element_matrices` (no density: the
    static solutions do not depend on it); ``theta`` in rad, within [0, angle].

    Examples
    --------
    >>> N = element_shape_functions(22.5e-3, 2.5e-3, 193e9, 0.29, np.pi / 16, [0.0, np.pi / 16])
    >>> bool(np.allclose(N[0], np.eye(3, 6)) and np.allclose(N[1], np.eye(3, 6, 3)))
    True
    """
    R, r, E, nu, beta, kind = _element_inputs(R, r, E, nu, angle, kind)
    theta = np.atleast_1d(v.as_float("theta", theta))
    if np.any(theta < 0) or np.any(theta > beta):
        raise ValueError(f"theta must lie within the element, [0, {beta:g}] rad")
    basis, _, _, inverse = _unit_element(r / R, nu, beta, kind)
    dof = _dof_scale(R, kind)
    values = np.array([basis(t)[:3] @ inverse for t in theta])
    return values * dof[None, :3, None] / dof[None, None, :]


# --- 5. free vibration of the continuous ring ----------------------------------------------------


def _fourier_ansatz(kind):
    """Amplitudes and the order-k fields: w, v, phi_t ~ cos k theta; u, psi, phi_r ~ sin k theta."""
    s = symbols()
    k, theta = s["k"], s["theta"]
    amplitudes = sp.symbols("A_1:4", real=True)
    c, si = sp.cos(k * theta), sp.sin(k * theta)
    trig = (c, si, si) if kind == "in-plane" else (c, si, c)
    fields = field_functions()[kind]
    return amplitudes, {f: a * t for f, a, t in zip(fields, amplitudes, trig, strict=True)}


@functools.cache
def mode_matrices(kind="in-plane"):
    """(K, M, C): 3x3 stiffness and mass of order-k motion, and the strain amplitudes C.

    With the order-k fields of amplitudes A (:func:`_fourier_ansatz`), the strain energy
    over the ring is A^T K A / 2 and the kinetic energy omega^2 A^T M A / 2 (generic section
    constants, rho in M); the strains are C A times cos or sin k theta.  Frequencies:
    det(K - omega^2 M) = 0.
    """
    s = symbols()
    kind = plane_kind(kind)
    theta = s["theta"]
    amplitudes, fields = _fourier_ansatz(kind)
    U, T = energy_densities(kind)
    U_total = sp.integrate(sp.expand(sp.expand_trig(U.subs(fields).doit())), (theta, 0, 2 * sp.pi))
    T_total = sp.integrate(sp.expand(T.subs(fields)), (theta, 0, 2 * sp.pi))
    K = sp.simplify(sp.hessian(U_total, amplitudes))
    M = sp.simplify(s["rho"] * sp.hessian(T_total, amplitudes))
    strains = generalised_strains(kind).subs(fields).doit()
    # Each strain is (amplitude combination) x cos or sin k theta: divide the trig factor out.
    C = sp.Matrix([[sp.simplify(sp.diff(e, a).subs(theta, sp.pi / (4 * s["k"])) * sp.sqrt(2)) for a in amplitudes]
                   for e in strains])  # fmt: skip
    return K, M, C


def _mode_matrices(kind):
    s = symbols()
    K, M, C = mode_matrices(kind)
    D, m = s["D"][kind], s["m"][kind]
    constants = sorted(D.free_symbols | m.free_symbols, key=lambda x: x.name)
    return (s["k"], s["R"], s["rho"], *constants), sp.Matrix.vstack(K, M, C)


@derived
def _mode_matrices_in_plane():
    return _mode_matrices("in-plane")


@derived
def _mode_matrices_out_of_plane():
    return _mode_matrices("out-of-plane")


# --- 6. the classical thin-ring limits -------------------------------------------------------------


@functools.cache
def inextensional_frequency_expression(kind="in-plane"):
    """omega_k of the classical thin ring, derived from the order-k energies (Rayleigh quotient).

    Thin section (D = diag(E A, G A/F, E I) or diag(E I, G J, G A/F)), no rotary inertia,
    shear-rigid, and in plane inextensional.  The constraints (eps = 0, gamma = 0 in plane;
    gamma_z = 0 out of plane) fix all amplitudes but one up to the twist amplitude out of
    plane, which carries no inertia and is condensed out (minimum of the strain energy).
    Returns omega (rad/s) in terms of k, R, r, E, nu, rho.
    """
    s = symbols()
    kind = plane_kind(kind)
    K, M, C = mode_matrices(kind)
    D_thin = section_stiffness(kind, thick=False)
    m_thin = section_inertia(kind, thick=False)
    D, m = s["D"][kind], s["m"][kind]
    values = {D[i, j]: D_thin[i, j] for i in range(3) for j in range(3) if D[i, j] != 0}
    translational = {m[0, 0]: m_thin[0, 0]}  # rotary inertia and its couplings dropped
    values.update({sym: 0 for sym in m.free_symbols if sym not in translational})
    values.update(translational)
    K, M, C = (X.subs(values) for X in (K, M, C))
    amplitudes = sp.symbols("A_1:4", real=True)
    constrained = [1, 0] if kind == "in-plane" else [2]  # gamma and eps; gamma_z
    solved = sp.solve([(C[i, :] * sp.Matrix(amplitudes))[0] for i in constrained],
                      [amplitudes[i] for i in ((1, 2) if kind == "in-plane" else (1,))], dict=True)[0]  # fmt: skip
    A = sp.Matrix(amplitudes).subs(solved)
    stiffness = sp.expand((A.T * K * A)[0])
    mass = sp.expand((A.T * M * A)[0])
    if kind == "out-of-plane":  # condense the twist amplitude A_3 (no inertia): minimum of the strain energy
        twist = sp.solve(sp.diff(stiffness, amplitudes[2]), amplitudes[2])[0]
        stiffness = stiffness.subs(amplitudes[2], twist)
    omega_squared = sp.factor(sp.simplify(stiffness / mass))
    return sp.sqrt(omega_squared)


@derived
def _inextensional_in_plane():
    s = symbols()
    return (s["k"], s["R"], s["r"], s["E"], s["nu"], s["rho"]), inextensional_frequency_expression("in-plane")


@derived
def _inextensional_out_of_plane():
    s = symbols()
    return (s["k"], s["R"], s["r"], s["E"], s["nu"], s["rho"]), inextensional_frequency_expression("out-of-plane")


def _ring_inputs(R, r, E, nu, rho, k):
    R, r, E, nu = _ring_and_material(R, r, E, nu)
    rho = v.positive("rho", rho, "kg/m^3")
    k = v.as_float("k", k)
    bad = (k != np.round(k)) | (k < 2)
    if np.any(bad):
        raise ValueError(f"k must be an integer circumferential order >= 2, got {v.show(k[bad] if k.ndim else k)}")
    return R, r, E, nu, rho, k


#: What is beyond double precision in the frequencies of a ring.
_EXTREME = "radii, elastic constants, density and order"


def inextensional_frequency(R, r, E, nu, *, rho, k, kind="in-plane"):
    """Classical flexural frequency of a free thin ring of order k, Hz.

    Parameters
    ----------
    R, r : array_like
        Centroidal and section radius, m.
    E, nu, rho : array_like
        Young's modulus (Pa), Poisson's ratio, density (kg/m^3).
    k : array_like of int
        Circumferential order (number of waves round the ring), >= 2.
    kind : {"in-plane", "out-of-plane"}

    Returns
    -------
    ndarray
        f_k = omega_k/(2 pi), Hz: in plane omega_k = sqrt(E I/(rho A R^4)) k (k^2 - 1)/sqrt(k^2 + 1)
        (Hoppe), out of plane the same with k^2 + E I/(G J) = k^2 + 1 + nu under the root
        (Michell), both derived by :func:`inextensional_frequency_expression`.

    Examples
    --------
    >>> round(float(inextensional_frequency(1.0, 0.05, 2e11, 0.3, rho=8000.0, k=2)), 2)  # NAFEMS FV6 ring, Hz
    53.38
    """
    R, r, E, nu, rho, k = _ring_inputs(R, r, E, nu, rho, k)
    func = _inextensional_in_plane if plane_kind(kind) == "in-plane" else _inextensional_out_of_plane
    with np.errstate(all="ignore"):  # overflow is reported by value
        frequency = np.asarray(func(k, R, r, E, nu, rho), dtype=float) / (2.0 * np.pi)
    return v.finite_result(frequency, "the frequency", _EXTREME)


def ring_frequencies(R, r, E, nu, *, rho, k, kind="in-plane", extension=True, shear=True, rotary_inertia=True,
                     thick=True) -> np.ndarray:  # fmt: skip
    """The three frequencies of order-k motion of the continuous ring, Hz, lowest first.

    Parameters
    ----------
    R, r, E, nu, rho : float
        Ring radius (m), section radius (m), Young's modulus (Pa), Poisson's ratio, density (kg/m^3).
    k : int
        Circumferential order, >= 2.
    kind : {"in-plane", "out-of-plane"}
    extension, shear, rotary_inertia, thick : bool, optional
        Switch off, one at a time, what the classical ring leaves out: the extension of the
        centre line (in plane only: eps = 0), transverse shear (gamma = 0), the rotary inertia
        of the section, and the curvature of the section (thin constants, step 3).  With
        all four off the lowest frequency is :func:`inextensional_frequency`.

    Returns
    -------
    ndarray
        Flexural (lowest) and higher branches, Hz; fewer than three when constraints remove
        amplitudes or massless ones are condensed out.

    Examples
    --------
    >>> f = ring_frequencies(22.5e-3, 2.5e-3, 193e9, 0.29, rho=8000.0, k=2)
    >>> round(float(f[0] / inextensional_frequency(22.5e-3, 2.5e-3, 193e9, 0.29, rho=8000.0, k=2)), 3)
    0.984
    """
    R, r, E, nu, rho, k = (float(x) for x in _ring_inputs(R, r, E, nu, rho, k))
    kind = plane_kind(kind)
    try:
        with np.errstate(all="ignore"):  # overflow is reported by value
            frequencies = _ring_frequencies(R, r, E, nu, rho, k, kind, extension, shear, rotary_inertia, thick)
    except (OverflowError, ZeroDivisionError, np.linalg.LinAlgError, ValueError):  # infinities met on the way
        frequencies = np.array([np.inf])
    return v.finite_result(frequencies, "a frequency", _EXTREME)


def _ring_frequencies(R, r, E, nu, rho, k, kind, extension, shear, rotary_inertia, thick):
    """:func:`ring_frequencies` of checked numbers."""
    from scipy.linalg import eigh, null_space

    section = _sections(R, r, E, nu, thick=thick)
    D, m = section["D"][kind], section["m"][kind]
    s = symbols()
    generic = {**{sym: D[divmod(i, 3)] for i, sym in enumerate(s["D"][kind]) if sym != 0},
               **{sym: m[divmod(i, 3)] for i, sym in enumerate(s["m"][kind]) if sym != 0}}  # fmt: skip
    if not rotary_inertia:
        translational = s["m"][kind][0, 0]
        generic = {sym: (val if sym == translational or sym in s["D"][kind].free_symbols else 0.0)
                   for sym, val in generic.items()}  # fmt: skip
    constants = [generic[sym] for sym in sorted(generic, key=lambda x: x.name)]
    func = _mode_matrices_in_plane if kind == "in-plane" else _mode_matrices_out_of_plane
    K, M, C = np.asarray(func(k, R, rho, *constants), dtype=float).reshape(3, 3, 3)
    rows = []
    if not shear:
        rows.append(C[1] if kind == "in-plane" else C[2])
    if not extension and kind == "in-plane":
        rows.append(C[0])
    T = null_space(np.array(rows)) if rows else np.eye(3)
    K, M = T.T @ K @ T, T.T @ M @ T
    # Amplitudes without inertia (rotary inertia off) are condensed out statically.
    mass_values, mass_vectors = np.linalg.eigh(M)
    massless = mass_values <= 1e-12 * max(mass_values.max(), 1e-300)
    if massless.any():
        Q0, Q1 = mass_vectors[:, massless], mass_vectors[:, ~massless]
        K00, K01, K11 = Q0.T @ K @ Q0, Q0.T @ K @ Q1, Q1.T @ K @ Q1
        K = K11 - K01.T @ np.linalg.solve(K00, K01)
        M = Q1.T @ M @ Q1
    omega_squared = eigh(0.5 * (K + K.T), 0.5 * (M + M.T), eigvals_only=True)
    return np.sqrt(np.maximum(omega_squared, 0.0)) / (2.0 * np.pi)
