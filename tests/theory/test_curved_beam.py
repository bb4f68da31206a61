"""The ring as a curved beam: kinematics, section constants, exact elements, classical limits."""

import mpmath
import numpy as np
import pytest
import sympy as sp
from ringchain.theory import curved_beam as cb
from ringchain.theory import ring

S = cb.symbols()
R, r, E, nu, rho, k, theta, y, z = (S[n] for n in ("R", "r", "E", "nu", "rho", "k", "theta", "y", "z"))
STEEL = dict(E=193e9, nu=0.29, rho=8000.0)


# --- kinematics -----------------------------------------------------------------------------------


def rigid_fields():
    """Rigid motions of the ring in the local frame: translations along x, y, z and rotations about x, y, z."""
    c, s = sp.cos(theta), sp.sin(theta)
    zero = sp.Integer(0)
    # (w, u, v, psi, phi_r, phi_t); a rotation Omega moves the centre line by Omega x R e_r and turns
    # the sections by Omega, written in the local frame e_r = (c, s, 0), e_t = (-s, c, 0).
    return [
        (c, -s, zero, zero, zero, zero),  # translation along x
        (s, c, zero, zero, zero, zero),  # translation along y
        (zero, zero, sp.Integer(1), zero, zero, zero),  # translation along z
        (zero, zero, R * s, zero, c, -s),  # rotation about x
        (zero, zero, -R * c, zero, s, c),  # rotation about y
        (zero, R, zero, sp.Integer(1), zero, zero),  # rotation about z
    ]


def substitute(expr, fields):
    (w, u, psi), (v, phi_r, phi_t) = cb.field_functions().values()
    values = dict(zip((w, u, v, psi, phi_r, phi_t), fields, strict=True))
    return sp.simplify(expr.subs(values).doit())


@pytest.mark.parametrize("motion", range(6))
def test_rigid_motions_do_not_strain(motion):
    for kind in cb.PLANES:
        strains = cb.generalised_strains(kind)
        assert all(substitute(e, rigid_fields()[motion]) == 0 for e in strains)
    assert substitute(cb.fibre_strain(), rigid_fields()[motion]) == 0


def test_in_plane_strains_are_the_curved_beam_ones():
    (w, u, psi), _ = cb.field_functions().values()
    eps, gamma, kappa = cb.generalised_strains("in-plane")
    # Extension (u' + w)/R, shear (w' - u)/R + psi, curvature change psi'/R (e.g. Boresi & Schmidt Ch. 9).
    assert sp.simplify(eps - (u.diff(theta) + w) / R) == 0
    assert sp.simplify(gamma - ((w.diff(theta) - u) / R + psi)) == 0
    assert sp.simplify(kappa - psi.diff(theta) / R) == 0


def test_fibre_strain_is_winklers():
    """The fibre at (y, z) strains by (eps + y kappa - z kappa_r)/(1 + y/R)."""
    eps, _, kappa = cb.generalised_strains("in-plane")
    kappa_r = cb.generalised_strains("out-of-plane")[0]
    assert sp.simplify(cb.fibre_strain() - (eps + y * kappa - z * kappa_r) / (1 + y / R)) == 0


# --- section constants ---------------------------------------------------------------------------------


def disc_quadrature(f):
    """integral(f(y, z) dA) over the unit disc by scipy's adaptive quadrature (error ~1e-11, absolute 1e-13:
    the inner integrals of odd powers vanish)."""
    from scipy.integrate import dblquad

    value, _ = dblquad(lambda t, s: f(s * np.cos(t), s * np.sin(t)) * s, 0, 1, 0, 2 * np.pi,
                       epsabs=1e-13, epsrel=1e-11)  # fmt: skip
    return value


@pytest.mark.parametrize("aspect", [3.1, 9.0])
def test_section_stiffness_against_quadrature(aspect):
    """D from the reduced integrals equals the defining integrals E integral(R y^a z^b/(R + y) dA)."""
    values = {R: sp.Float(aspect, 30), r: 1, E: 1, nu: sp.Rational(3, 10)}
    D_in = cb.section_stiffness("in-plane").subs(values)
    D_out = cb.section_stiffness("out-of-plane").subs(values)
    weight = lambda f: lambda a, b: f(a, b) * aspect / (aspect + a)  # noqa: E731
    expected = {
        (D_in, 0, 0): disc_quadrature(weight(lambda a, b: 1.0)),
        (D_in, 0, 2): disc_quadrature(weight(lambda a, b: a)),
        (D_in, 2, 2): disc_quadrature(weight(lambda a, b: a * a)),
        (D_out, 0, 0): disc_quadrature(weight(lambda a, b: b * b)),
    }
    for (D, i, j), value in expected.items():
        # Quadrature to 1e-11 of the integral of |f|; D12 is smaller than that by ~r/R, hence 1e-8.
        assert float(D[i, j]) == pytest.approx(value, rel=1e-8)
    # Shear and torsion: the straight-bar constants G A/F (F = 10/9) and G J, J = pi r^4/2.
    G = values[E] / (2 * (1 + values[nu]))
    assert sp.simplify(D_in[1, 1] - G * sp.pi / sp.Rational(10, 9)) == 0
    assert sp.simplify(D_out[1, 1] - G * sp.pi / 2) == 0


def test_section_compliance_is_the_castigliano_energy_of_the_ring_module():
    """Inverting D (eps, kappa block) gives the complementary energy N^2/(2EA) + M^2/(2EJ) + MN/(EAR),
    the energy theory/ring.py integrates for K_b (there with M of opposite sign: -MN/(EAR))."""
    D = cb.section_stiffness("in-plane")
    block = sp.Matrix([[D[0, 0], D[0, 2]], [D[2, 0], D[2, 2]]])
    C = sp.simplify(block.inv())
    section = ring.section_properties()
    A, J = section["A"], section["J"]
    expected = sp.Matrix([[1 / (E * A), 1 / (E * A * R)], [1 / (E * A * R), 1 / (E * J)]])
    for aspect in (3, 9, 40):  # exact radicals at a few points
        values = {R: sp.Integer(aspect), r: 1, E: 1}
        assert all(sp.simplify((C - expected)[i].subs(values)) == 0 for i in range(4))


def test_section_stiffness_tends_to_thin():
    eps = sp.Symbol("epsilon", positive=True)
    thick, thin = cb.section_stiffness("in-plane"), cb.section_stiffness("in-plane", thick=False)
    for i, j in ((0, 0), (2, 2)):
        ratio = sp.series((thick[i, j] / thin[i, j]).subs(r, eps * R), eps, 0, 2).removeO()
        assert sp.simplify(ratio - 1) == 0  # thick = thin (1 + O((r/R)^2))
    expected = sp.diag(E * sp.pi * r**2, 9 * sp.pi * E * r**2 / (20 * (nu + 1)), E * sp.pi * r**4 / 4)
    assert sp.simplify(thin - expected) == sp.zeros(3, 3)


def test_section_inertia():
    I = sp.pi * r**4 / 4  # noqa: E741
    A = sp.pi * r**2
    # Rigid section: fibre velocities u + y psi (tangential), w (radial), weighted by the fibre length 1 + y/R.
    expected_in = sp.Matrix([[A, 0, 0], [0, A, I / R], [0, I / R, I]])
    assert sp.simplify(cb.section_inertia("in-plane") - expected_in) == sp.zeros(3, 3)
    expected_out = sp.Matrix([[A, 0, -I / R], [0, I, 0], [-I / R, 0, 2 * I]])
    assert sp.simplify(cb.section_inertia("out-of-plane") - expected_out) == sp.zeros(3, 3)
    assert cb.section_inertia("in-plane", thick=False) == sp.diag(A, A, I)


# --- the exact element ---------------------------------------------------------------------------------


@pytest.mark.parametrize("kind", cb.PLANES)
def test_homogeneous_solutions_solve_the_static_equations(kind):
    from sympy.calculus.euler import euler_equations

    fields = cb.field_functions()[kind]
    energy, _ = cb.energy_densities(kind)
    equations = euler_equations(energy, list(fields), theta)
    B = cb.homogeneous_solutions(kind)
    # Exact check at generic rational section constants (the solutions are rational in them).
    constants = sorted(B.free_symbols - {theta}, key=str)
    generic = {s: sp.Rational(p, 7) for s, p in zip(constants, range(3, 3 + len(constants)), strict=True)}
    for j in range(6):
        values = dict(zip(fields, B[:, j].subs(generic), strict=True))
        assert all(sp.simplify(eq.lhs.subs(generic).subs(values).doit()) == 0 for eq in equations)
    # Six independent solutions: the Wronskian-like matrix of values and derivatives is regular.
    stacked = sp.Matrix.vstack(B, B.diff(theta)).subs(generic).subs(theta, sp.Rational(1, 3))
    assert stacked.rank() == 6


@pytest.mark.parametrize("kind", cb.PLANES)
def test_element_matrices(kind):
    R_, r_, beta = 22.5e-3, 2.5e-3, np.pi / 8
    el = cb.element_matrices(R_, r_, STEEL["E"], STEEL["nu"], rho=STEEL["rho"], angle=beta, kind=kind)
    K, M = el.stiffness, el.mass
    assert np.allclose(K, K.T, rtol=0, atol=1e-12 * np.abs(K).max())
    eigenvalues = np.linalg.eigvalsh(K)
    # Three rigid motions strain-free, to rounding (the basis contains them exactly).
    assert np.all(np.abs(eigenvalues[:3]) < 1e-12 * eigenvalues[-1]) and eigenvalues[3] > 1e-9 * eigenvalues[-1]
    assert np.all(np.linalg.eigvalsh(M) > 0)
    # The rigid translation across the element's chord carries the arc's mass rho A R beta.
    nodes = np.array([0.0, beta])
    if kind == "in-plane":  # translation along y: w = sin, u = cos at each node
        translation = np.ravel([[np.sin(t), np.cos(t), 0.0] for t in nodes])
    else:  # translation along z
        translation = np.ravel([[1.0, 0.0, 0.0] for _ in nodes])
    assert np.allclose(K @ translation, 0.0, atol=1e-12 * np.abs(K).max())
    arc_mass = STEEL["rho"] * np.pi * r_**2 * R_ * beta
    assert translation @ M @ translation == pytest.approx(arc_mass, rel=1e-12)


def test_mass_is_the_integral_of_the_shape_functions():
    """M = integral(N^T m N R dtheta), recomputed on a fine trapezoid grid from the shape functions."""
    R_, r_, beta = 22.5e-3, 2.5e-3, np.pi / 8
    el = cb.element_matrices(R_, r_, STEEL["E"], STEEL["nu"], rho=STEEL["rho"], angle=beta)
    grid = np.linspace(0.0, beta, 801)
    N = cb.element_shape_functions(R_, r_, STEEL["E"], STEEL["nu"], beta, grid)
    I = np.pi * r_**4 / 4  # noqa: E741
    A = np.pi * r_**2
    m = STEEL["rho"] * np.array([[A, 0, 0], [0, A, I / R_], [0, I / R_, I]])
    integrand = np.einsum("pia,ij,pjb->pab", N, m, N) * R_
    M = np.trapezoid(integrand, grid, axis=0)
    # Trapezoid rule on 800 intervals of a smooth integrand: relative error ~ (beta/800)^2/12 ~ 4e-8.
    assert np.allclose(M, el.mass, rtol=0, atol=1e-6 * np.abs(el.mass).max())


def test_shape_functions_interpolate_the_nodes():
    beta = np.pi / 12
    N = cb.element_shape_functions(22.5e-3, 2.5e-3, 193e9, 0.29, beta, [0.0, beta], "out-of-plane")
    # Through the inverse of the nodal matrix (condition number ~1e4 at this angle): errors ~1e-12.
    assert np.allclose(N[0], np.eye(3, 6), atol=1e-10) and np.allclose(N[1], np.eye(3, 6, 3), atol=1e-10)


def test_end_resultants_of_a_pure_bending_state():
    """A uniform moment M0 bends the arc into kappa = M0 C22 with N = 0: the resultants read it back."""
    R_, r_, beta = 22.5e-3, 2.5e-3, np.pi / 8
    el = cb.element_matrices(R_, r_, STEEL["E"], STEEL["nu"], rho=STEEL["rho"], angle=beta)
    D = np.asarray(cb._sections(R_, r_, STEEL["E"], STEEL["nu"])["D"]["in-plane"])
    strains = np.linalg.solve(D[np.ix_([0, 2], [0, 2])], [0.0, 1.0])  # (eps, kappa) of N = 0, M = 1 N m
    eps, kappa = strains
    # Fields with constant eps and kappa, gamma = 0 (check: u' + w = R eps, w' - u = -R psi, psi' = R kappa):
    # psi = R kappa theta, u = R^2 kappa theta, w = R eps - R^2 kappa.
    nodal = np.ravel([[R_ * eps - R_**2 * kappa, R_**2 * kappa * t, R_ * kappa * t] for t in (0.0, beta)])
    for end in range(2):
        N, V, M = el.resultants[end] @ nodal
        assert N == pytest.approx(0.0, abs=1e-8) and V == pytest.approx(0.0, abs=1e-8)  # rounding of E R^2 terms
        assert M == pytest.approx(1.0, rel=1e-9)


# --- vibration of the ring ------------------------------------------------------------------------------


def test_in_plane_classical_limit_is_hoppes():
    """Derived: omega_k^2 = E I k^2 (k^2 - 1)^2/(rho A R^4 (k^2 + 1)) (Hoppe 1871; Love, Ch. XVIII)."""
    I, A = sp.pi * r**4 / 4, sp.pi * r**2  # noqa: E741
    expected = sp.sqrt(E * I / (rho * A * R**4)) * k * (k**2 - 1) / sp.sqrt(k**2 + 1)
    assert sp.simplify(cb.inextensional_frequency_expression("in-plane") - expected) == 0


def test_out_of_plane_classical_limit_is_michells():
    """Derived: omega_k^2 = E I k^2 (k^2 - 1)^2/(rho A R^4 (k^2 + E I/(G J))), E I/(G J) = 1 + nu for a disc."""
    I, A, J = sp.pi * r**4 / 4, sp.pi * r**2, sp.pi * r**4 / 2  # noqa: E741
    G = E / (2 * (1 + nu))
    expected = sp.sqrt(E * I / (rho * A * R**4)) * k * (k**2 - 1) / sp.sqrt(k**2 + E * I / (G * J))
    assert sp.simplify(cb.inextensional_frequency_expression("out-of-plane") - expected) == 0


def test_nafems_ring_frequencies():
    """NAFEMS FV6 (Selected benchmarks for natural frequency analysis, test 6): R = 1 m, r = 0.05 m,
    E = 200 GPa, nu = 0.3, rho = 8000 kg/m^3; the reference values (the classical formulas), Hz,
    are printed to 5 significant digits."""
    in_plane = cb.inextensional_frequency(1.0, 0.05, 2e11, 0.3, rho=8000.0, k=[2, 3, 4])
    out_of_plane = cb.inextensional_frequency(1.0, 0.05, 2e11, 0.3, rho=8000.0, k=[2, 3, 4], kind="out-of-plane")
    assert np.allclose(in_plane, [53.382, 150.99, 289.51], rtol=1e-4)
    assert np.allclose(out_of_plane, [51.849, 148.77, 286.98], rtol=1e-4)


@pytest.mark.parametrize("kind", cb.PLANES)
@pytest.mark.parametrize("order", [2, 4, 6])
def test_ring_frequencies_reduce_to_the_classical_ones(kind, order):
    args = dict(R=22.5e-3, r=2.5e-3, E=STEEL["E"], nu=STEEL["nu"], rho=STEEL["rho"], k=order, kind=kind)
    classical = cb.inextensional_frequency(**args)
    limit = cb.ring_frequencies(**args, extension=False, shear=False, rotary_inertia=False, thick=False)
    with mpmath.workdps(20):
        I, A = mpmath.pi * 2.5e-3**4 / 4, mpmath.pi * 2.5e-3**2  # noqa: E741
        extra = 1 if kind == "in-plane" else 1 + STEEL["nu"]
        mp = mpmath.sqrt(STEEL["E"] * I / (STEEL["rho"] * A * 22.5e-3**4)) * order * (order**2 - 1)
        mp = mp / mpmath.sqrt(order**2 + extra) / (2 * mpmath.pi)
    assert limit.size == 1 and limit[0] == pytest.approx(classical, rel=1e-12)  # same formula, two routes
    assert float(classical) == pytest.approx(float(mp), rel=1e-13)  # against mpmath
    # Each effect switched on lowers the flexural frequency of a thick ring (R/r = 9).
    full = cb.ring_frequencies(**args)[0]
    assert full < classical


@pytest.mark.parametrize("kind", cb.PLANES)
def test_mode_matrices_against_quadrature(kind):
    """A^T K A/2 is the strain energy of the order-k fields, summed numerically round the ring."""
    K, _, _ = cb.mode_matrices(kind)
    amplitudes, fields = cb._fourier_ansatz(kind)
    energy, _ = cb.energy_densities(kind)
    constants = sorted(energy.free_symbols - {theta, R}, key=str)
    values = {k: 3, R: sp.Rational(1), **{s: sp.Rational(p, 5) for s, p in zip(constants, range(2, 2 + len(constants)),
                                                                               strict=True)}}  # fmt: skip
    A = dict(zip(amplitudes, (sp.Rational(1, 2), sp.Rational(-1, 3), sp.Rational(1, 7)), strict=True))
    density = sp.lambdify(theta, energy.subs(fields).doit().subs(values).subs(A), "mpmath")
    with mpmath.workdps(25):
        numeric = mpmath.quad(density, [0, 2 * mpmath.pi])
    a = sp.Matrix(list(A.values()))
    exact = ((a.T * K.subs(values) * a)[0] / 2).evalf(25)
    assert abs(numeric - exact) < 1e-18 * abs(exact)


def test_thick_rings_depart_from_the_classical_frequencies_as_k_r_over_R_squared():
    """Shear, rotary inertia and extension lower omega_k by O((k r/R)^2): ratios tend to 1 as R/r grows."""
    aspects = np.array([40.0, 80.0, 160.0])
    for order in (2, 6):
        departures = []
        for aspect in aspects:
            args = dict(R=aspect * 2.5e-3, r=2.5e-3, E=STEEL["E"], nu=STEEL["nu"], rho=STEEL["rho"], k=order)
            departures.append(1 - cb.ring_frequencies(**args)[0] / cb.inextensional_frequency(**args))
        ratios = np.array(departures[:-1]) / np.array(departures[1:])
        # Doubling R/r divides the departure by 4, up to the next order, a relative O((k r/R)^2).
        assert np.all(np.abs(ratios - 4) < 4 * (order / aspects[:-1]) ** 2)


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: cb.element_matrices(2.5e-3, 2.5e-3, 193e9, 0.29, rho=8000.0, angle=0.1), "r must be smaller than R"),
        (lambda: cb.element_matrices(22.5e-3, 2.5e-3, 193e9, 0.29, rho=8000.0, angle=2.0), "angle must lie in"),
        (
            lambda: cb.element_matrices(22.5e-3, 2.5e-3, 193e9, 0.29, rho=8000.0, angle=0.1, kind="sideways"),
            "kind must be one of",
        ),
        (lambda: cb.inextensional_frequency(22.5e-3, 2.5e-3, 193e9, 0.29, rho=8000.0, k=1), "k must be an integer"),
        (lambda: cb.ring_frequencies(22.5e-3, 2.5e-3, 193e9, 0.29, rho=-1.0, k=2), "rho must be positive"),
        (lambda: cb.element_shape_functions(22.5e-3, 2.5e-3, 193e9, 0.29, 0.1, [0.2]), "theta must lie within"),
    ],
)
def test_bad_inputs(call, message):
    with pytest.raises(ValueError, match=message):
        call()
