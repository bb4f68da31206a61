"""Linear waves of a pretensioned sheet of interlinked rings: derivation, dispersion, long-wave speeds.

The reference for the numbers is a periodic network assembled here, independently of theory/sheet.py:
sites on a small periodic lattice, links with a nonlinear force law (the ring contact's power law,
pretensioned), the network's forces in NumPy and their Jacobian by complex-step differentiation (exact to
rounding, no formula for a link's stiffness).
"""

import numpy as np
import pytest
import sympy as sp
from ringchain.theory import (
    Ring,
    SheetSpeeds,
    dispersion,
    linear,
    sheet,
    sheet_dispersion,
    sheet_group_velocity,
    sheet_sound_speeds,
)

S = sheet.symbols()
q, theta, m, a, k, T = (S[name] for name in ("q", "theta", "m", "a", "k", "T"))
q_x, q_y = S["q_x"], S["q_y"]


def assert_same(derived, expected):
    difference = sp.simplify(sp.Matrix([derived]) - sp.Matrix([expected]))
    assert difference == sp.zeros(*difference.shape)


def unit(angle):
    return sp.Matrix([sp.cos(angle), sp.sin(angle)])


def link_textbook(angle, stiffness, tension, length):
    """k e e^T + (T/a)(I - e e^T): the axial and geometric stiffness of a pretensioned bar (e.g. Bathe,
    Finite Element Procedures, Sec. 6.3, the 2D truss element's material and initial-stress matrices)."""
    e = unit(angle)
    return stiffness * e * e.T + tension / length * (sp.eye(2) - e * e.T)


# --- the derivation against the textbook forms -----------------------------------------------------------


def test_link_expansion_is_axial_plus_geometric_stiffness():
    force, stiffness = sheet.link_stiffness()
    assert (force - T * unit(theta)).applyfunc(sp.simplify) == sp.zeros(2, 1)
    assert (stiffness - link_textbook(theta, k, T, a)).applyfunc(sp.simplify) == sp.zeros(2, 2)


@pytest.mark.parametrize("pattern", sheet.PATTERNS)
def test_every_set_of_family_tensions_is_an_equilibrium(pattern):
    assert sheet.equilibrium_force(pattern) == sp.zeros(2, 1)


FAMILY_ANGLES = {"square": (0, sp.pi / 2), "triangular": (0, sp.pi / 3, 2 * sp.pi / 3)}


@pytest.mark.parametrize("pattern", sheet.PATTERNS)
def test_bloch_matrix_is_the_sum_of_the_link_stiffnesses(pattern):
    """Two routes: the site's energy differentiated whole (dynamical_matrix) and link by link (link_stiffness)."""
    _, stiffness = sheet.link_stiffness()
    wavevector = sp.Matrix([q_x, q_y])
    expected = sp.zeros(2, 2)
    for family, angle in zip(sheet.families(pattern), FAMILY_ANGLES[pattern], strict=True):
        assert_same(sp.Matrix(family.bond).norm(), family.length)
        assert (sp.Matrix(family.bond) / family.length - unit(angle)).applyfunc(sp.simplify) == sp.zeros(2, 1)
        K_f = stiffness.subs({theta: angle, k: family.k, T: family.T, a: family.length})
        expected += 4 / m * K_f * sp.sin(wavevector.dot(family.bond) / 2) ** 2
    assert (sheet.dynamical_matrix(pattern) - expected).applyfunc(sp.simplify) == sp.zeros(2, 2)


def test_square_matrix_textbook_form():
    k_x, k_y, T_x, T_y, a_x, a_y = (S[name] for name in ("k_x", "k_y", "T_x", "T_y", "a_x", "a_y"))
    sx, sy = sp.sin(q_x * a_x / 2) ** 2, sp.sin(q_y * a_y / 2) ** 2
    expected = sp.diag(4 / m * (k_x * sx + T_y / a_y * sy), 4 / m * (T_x / a_x * sx + k_y * sy))
    assert (sheet.dynamical_matrix("square") - expected).applyfunc(sp.simplify) == sp.zeros(2, 2)


def test_branches_along_x_textbook_forms():
    longitudinal, transverse = sheet.branches_along_x("square")
    assert_same(longitudinal, 4 * k / m * sp.sin(q * a / 2) ** 2)  # the 1D chain
    assert_same(transverse, 4 * T / (m * a) * sp.sin(q * a / 2) ** 2)  # a beaded string
    longitudinal, transverse = sheet.branches_along_x("triangular")
    s1, s2 = sp.sin(q * a / 2) ** 2, sp.sin(q * a / 4) ** 2
    assert_same(longitudinal, 4 / m * (k * s1 + (k / 2 + 3 * T / (2 * a)) * s2))
    assert_same(transverse, 4 / m * (T / a * s1 + (3 * k / 2 + T / (2 * a)) * s2))


def test_square_long_wave_speeds():
    assert_same(sp.Matrix(sheet.long_wave_speeds_squared("square", 0)), sp.Matrix([k * a**2 / m, T * a / m]))
    assert_same(sp.Matrix(sheet.long_wave_speeds_squared("square", sp.pi / 2)), sp.Matrix([k * a**2 / m, T * a / m]))
    diagonal = (k * a**2 + T * a) / (2 * m)
    assert_same(sp.Matrix(sheet.long_wave_speeds_squared("square", sp.pi / 4)), sp.Matrix([diagonal, diagonal]))
    with pytest.raises(ValueError, match="not purely longitudinal"):
        sheet.long_wave_speeds_squared("square", sp.pi / 6)  # polarised along the axes, not along n


def test_triangular_long_wave_speeds_are_isotropic_and_obey_cauchy():
    longitudinal, transverse = sheet.long_wave_speeds_squared("triangular")
    assert not longitudinal.has(theta) and not transverse.has(theta)
    assert_same(longitudinal, (9 * k * a**2 + 3 * T * a) / (8 * m))
    assert_same(transverse, (3 * k * a**2 + 9 * T * a) / (8 * m))
    # Without pretension, the triangular spring network: Lame constants lambda = mu = sqrt(3) k/4 (2D, N/m),
    # E = 2k/sqrt(3), Poisson's ratio 1/3 (Cauchy's relation for central forces; e.g. Ostoja-Starzewski,
    # Appl. Mech. Rev. 55, 35 (2002)), areal density 2m/(sqrt(3) a^2).
    lame = sp.sqrt(3) * k / 4
    density = 2 * m / (sp.sqrt(3) * a**2)
    assert_same(longitudinal.subs(T, 0), 3 * lame / density)
    assert_same(transverse.subs(T, 0), lame / density)


@pytest.mark.parametrize("pattern", sheet.PATTERNS)
def test_long_wave_tensor_is_the_q_squared_term_of_the_bloch_matrix(pattern):
    """An independent route to the limit: the Taylor series of D(q n) in q, its q^2 coefficient."""
    along = {q_x: q * sp.cos(theta), q_y: q * sp.sin(theta)}
    # The series of a sum is the sum of the series: term by term (each M_f sin^2(q n.b_f/2)), 2.7 s -> 1.2 s.
    series = (
        sheet.dynamical_matrix(pattern)
        .subs(along)
        .applyfunc(lambda e: sp.Add(*(sp.series(term, q, 0, 3).removeO() for term in sp.Add.make_args(e))))
    )
    coefficient = series.applyfunc(lambda e: sp.expand(e).coeff(q, 2))
    assert (sheet.long_wave_tensor(pattern) - coefficient).applyfunc(sp.simplify) == sp.zeros(2, 2)


def test_square_with_slack_cross_links_is_the_1d_chain_symbolically():
    """D_xx with T_y = 0 is linear.power_law_dispersion (the chain's Eq. (7)) at k_c = k_x."""
    D = sheet.dynamical_matrix("square").subs({S["T_y"]: 0})
    chain = linear.power_law_dispersion()
    L = linear.symbols()
    assert_same(D[0, 0], chain.subs({L["k_c"]: S["k_x"], L["q"]: q_x, L["a"]: S["a_x"], L["m"]: m}))


# --- the generated code ----------------------------------------------------------------------------------

DERIVED = [
    sheet._square_matrix,
    sheet._triangular_matrix,
    sheet._square_tensor,
    sheet._triangular_tensor,
    sheet._square_gradient,
    sheet._triangular_gradient,
]
SAMPLE = {"q_x": 31.0, "q_y": -17.0, "theta": 0.7, "m": 0.008, "a": 0.04, "a_x": 0.04, "a_y": 0.05}
SAMPLE |= {"k_x": 2.1e4, "k_y": 3.3e4, "T_x": 2.0, "T_y": 5.0, "k_1": 2.1e4, "k_2": 1.7e4, "k_3": 3.3e4}
SAMPLE |= {"T_1": 2.0, "T_2": 5.0, "T_3": 0.5}
# The long-wave tensors take k a^2/m and T a/m per family (m^2/s^2).
SAMPLE |= {"kappa_0": 4.2, "kappa_1": 6.6, "kappa_2": 5.1, "tau_0": 1.0e-2, "tau_1": 3.1e-2, "tau_2": 2.5e-3}


@pytest.mark.parametrize("derived", DERIVED, ids=lambda d: d.name)
def test_generated_code_equals_evalf(derived):
    args, expr = derived.expression()
    values = [SAMPLE[str(arg)] for arg in args]
    got = np.asarray(derived(*values), dtype=float)
    expected = np.asarray(sp.N(sp.Matrix([expr]), 20, subs=dict(zip(args, values, strict=True))), dtype=float)
    # The generated code evaluates the same expression in double precision: 1e-12 of the largest entry
    # (an off-diagonal entry is a difference of family terms, so it carries their absolute rounding).
    assert np.allclose(got.ravel(), expected.ravel(), rtol=0, atol=1e-12 * np.abs(expected).max())


# --- an independent network -----------------------------------------------------------------------------

LATTICE = {  # primitive vectors (columns) and the families: (index offset, bond vector) per family
    "square": lambda ax, ay: (np.array([[ax, 0.0], [0.0, ay]]), [((1, 0), (ax, 0.0)), ((0, 1), (0.0, ay))]),
    "triangular": lambda a_, _: (
        np.array([[a_, a_ / 2], [0.0, a_ * np.sqrt(3) / 2]]),
        [((1, 0), (a_, 0.0)), ((0, 1), (a_ / 2, a_ * np.sqrt(3) / 2)), ((-1, 1), (-a_ / 2, a_ * np.sqrt(3) / 2))],
    ),
}


class Network:
    """A periodic N x N network of point masses joined by pretensioned power-law links.

    Each link pulls with F = K (l - l_0)^n, chosen so that at its length a it carries the tension T with
    slope k: the static extension is delta_0 = n T/k and K = T/delta_0^n (a ring contact of exponent n).
    """

    def __init__(self, pattern, N, k, T, a, m, n=1.5):
        families = 2 if pattern == "square" else 3
        per = [x if isinstance(x, tuple) else (x,) * families for x in (k, T)]
        lengths = a if isinstance(a, tuple) else (a, a)
        self.primitive, layout = LATTICE[pattern](*lengths)
        self.N, self.m = N, m
        self.links = []  # (site, neighbour, bond vector, K, l_0, n)
        for (offset, bond), k_f, T_f in zip(layout, *per, strict=True):
            bond = np.array(bond)
            length = np.hypot(*bond)
            delta_0 = n * T_f / k_f
            assert delta_0 < length  # a link that exists at its rest length
            for i in range(N):
                for j in range(N):
                    here = i * N + j
                    there = ((i + offset[0]) % N) * N + (j + offset[1]) % N
                    self.links.append((here, there, bond, T_f / delta_0**n, length - delta_0, n))

    def forces(self, u):
        """Forces on every site (N^2 x 2) for displacements u (N^2 x 2, real or complex)."""
        f = np.zeros_like(u)
        for here, there, bond, K, rest, n in self.links:
            vector = bond + u[there] - u[here]
            length = np.sqrt(vector @ vector)  # analytic in u (no abs): complex steps pass through
            pull = K * (length - rest) ** n * vector / length
            f[here] += pull
            f[there] -= pull
        return f

    def hessian(self):
        """d^2 E/du du (2 N^2 square) by complex-step differentiation of the forces (exact to rounding)."""
        size = 2 * self.N**2
        H = np.empty((size, size))
        step = 1e-30
        for c in range(size):
            u = np.zeros(size, dtype=complex)
            u[c] = 1j * step
            H[:, c] = -self.forces(u.reshape(-1, 2)).imag.ravel() / step
        return H

    def allowed_wavevectors(self):
        """q with q.a_i = 2 pi n_i/N: the Bloch waves that fit the periodic network (N^2 x 2, rad/m)."""
        n = np.stack(np.meshgrid(np.arange(self.N), np.arange(self.N), indexing="ij"), -1).reshape(-1, 2)
        return 2 * np.pi / self.N * np.linalg.solve(self.primitive.T, n.T).T

    def bloch_matrix(self, H, wavevector):
        """(1/m) sum_j H_0j exp(i q.R_j) over site 0 and its neighbours (R_j unwrapped to the nearest image)."""
        D = np.zeros((2, 2), dtype=complex)
        for j in range(self.N**2):
            block = H[0:2, 2 * j : 2 * j + 2]
            if not np.any(block):
                continue
            index = np.array([j // self.N, j % self.N])
            index = np.where(index > self.N // 2, index - self.N, index)
            D += block * np.exp(1j * wavevector @ (self.primitive @ index))
        return D / self.m

    def long_wave_tensor(self, H, direction):
        """lim D(q n)/q^2 = -(1/2m) sum_j H_0j (n.R_j)^2: the q^2 term of the Bloch sum (its q^0 term is the
        sum of the row, zero for a network that translates freely, and its q^1 term cancels between +-R_j)."""
        C = np.zeros((2, 2))
        for j in range(self.N**2):
            block = H[0:2, 2 * j : 2 * j + 2]
            index = np.array([j // self.N, j % self.N])
            index = np.where(index > self.N // 2, index - self.N, index)
            C -= block * (direction @ (self.primitive @ index)) ** 2 / 2
        return C / self.m


CASES = {  # ring-like links (k a/T large) and links whose geometric stiffness matters (T/(k a) = 0.2)
    "square ring-like": ("square", dict(k=2.1e4, T=2.0, a=0.04, m=0.008)),
    "square biaxial": ("square", dict(k=(2.1e4, 3.3e4), T=(2.0e2, 5.0e2), a=(0.04, 0.05), m=0.008)),
    "triangular ring-like": ("triangular", dict(k=2.1e4, T=2.0, a=0.04, m=0.008)),
    "triangular per family": ("triangular", dict(k=(2.1e4, 1.7e4, 3.3e4), T=(1.7e2, 3.0e2, 0.5e2), a=0.04, m=0.008)),
}


@pytest.fixture(scope="module", params=list(CASES))
def network(request):
    pattern, parameters = CASES[request.param]
    net = Network(pattern, 5, **parameters)
    return pattern, parameters, net, net.hessian()


def test_network_is_in_equilibrium(network):
    _, parameters, net, _ = network
    forces = net.forces(np.zeros((net.N**2, 2)))
    # Every site feels its links' tensions cancel: zero to the rounding of sums of T (1e-13 of T).
    assert np.abs(forces).max() < 1e-13 * np.max(parameters["T"])


def test_dispersion_equals_the_finite_network_eigenfrequencies(network):
    pattern, parameters, net, H = network
    assert np.allclose(H, H.T, rtol=0, atol=1e-12 * np.abs(H).max())  # a potential: symmetric to rounding
    network_omega2 = np.sort(np.linalg.eigvalsh(H / net.m))
    wavevectors = net.allowed_wavevectors()
    theory_omega2 = np.sort((sheet_dispersion(*wavevectors.T, pattern=pattern, **parameters) ** 2).ravel())
    # eigvalsh is backward stable: each eigenvalue within a few eps of the largest (1e-9 leaves room).
    scale = network_omega2.max()
    assert np.allclose(network_omega2, theory_omega2, rtol=0, atol=1e-9 * scale)


def test_dispersion_equals_the_bloch_reduced_network(network):
    """At wavevectors the small network does not hold, through its Hessian's translation invariance."""
    pattern, parameters, net, H = network
    rng = np.random.default_rng(21)
    span = 2 * np.pi / np.min(np.linalg.norm(net.primitive, axis=0))
    wavevectors = rng.uniform(-span, span, size=(40, 2))
    omega = sheet_dispersion(*wavevectors.T, pattern=pattern, **parameters)
    reference = np.array([np.sqrt(np.linalg.eigvalsh(net.bloch_matrix(H, wv))) for wv in wavevectors])
    # Branch by branch, relative: the Hessian and the 2 x 2 eigenproblem carry a few eps of the largest
    # entry, and the lower omega^2 is at least 2e-3 of the upper here (found 1e-13 at most): 1e-9.
    assert np.allclose(omega, reference, rtol=1e-9, atol=0)


def test_long_wave_speeds_and_polarisations_equal_the_network(network):
    """The longitudinal branch is the one whose polarisation lies nearer the direction of travel."""
    pattern, parameters, net, H = network
    angles = np.linspace(0.0, np.pi, 13) + 0.01
    speeds = sheet_sound_speeds(angles, pattern=pattern, **parameters)
    for angle, longitudinal, transverse in zip(angles, *speeds, strict=True):
        direction = np.array([np.cos(angle), np.sin(angle)])
        values, vectors = np.linalg.eigh(net.long_wave_tensor(H, direction))
        nearer = np.argmax(np.abs(vectors.T @ direction))
        # Sums of Hessian blocks, each exact to rounding; the smaller eigenvalue is at least 1e-3 of the
        # larger here, so it keeps 12 digits: 1e-10.
        assert np.allclose([longitudinal, transverse], np.sqrt(values[[nearer, 1 - nearer]]), rtol=1e-10)


# --- long waves as the limit of the dispersion ------------------------------------------------------------


@pytest.mark.parametrize("case", list(CASES))
def test_speeds_are_the_small_q_limit_of_the_dispersion(case):
    pattern, parameters = CASES[case]
    angles = np.linspace(0.0, 2 * np.pi, 25)
    qa = 1e-5
    wavenumber = qa / np.max(parameters["a"])
    omega = sheet_dispersion(wavenumber * np.cos(angles), wavenumber * np.sin(angles), pattern=pattern, **parameters)
    speeds = np.sort(np.stack(sheet_sound_speeds(angles, pattern=pattern, **parameters), axis=-1), axis=-1)
    # omega/q = c (1 - O((q a)^2/24)): 1e-11 here, 1e-9 leaves room for rounding in sin^2 of (q a) ~ 1e-5
    assert np.allclose(omega / wavenumber, speeds, rtol=1e-9, atol=0)


# --- group velocity --------------------------------------------------------------------------------------


@pytest.mark.parametrize("case", list(CASES))
def test_group_velocity_is_the_gradient_of_the_dispersion(case):
    pattern, parameters = CASES[case]
    rng = np.random.default_rng(7)
    a_max = np.max(parameters["a"])
    qx, qy = rng.uniform(-3.0, 3.0, (2, 40)) / a_max
    velocity = sheet_group_velocity(qx, qy, pattern=pattern, **parameters)
    h = 1e-6 / a_max
    # Central differences of omega (an independent route: sheet_dispersion alone); their error is
    # O((h a)^2) ~ 1e-12 of omega's scale plus rounding of omega over h, ~1e-16/1e-6: 1e-7 of the largest speed.
    for axis, (dx, dy) in enumerate(((h, 0.0), (0.0, h))):
        forward = sheet_dispersion(qx + dx, qy + dy, pattern=pattern, **parameters)
        backward = sheet_dispersion(qx - dx, qy - dy, pattern=pattern, **parameters)
        numeric = (forward - backward) / (2 * h)
        # Points where the branches nearly meet have a kink there: keep those whose gap is wide.
        omega = sheet_dispersion(qx, qy, pattern=pattern, **parameters)
        apart = (omega[:, 1] - omega[:, 0]) > 1e-3 * omega[:, 1]
        scale = np.abs(numeric).max()
        assert np.allclose(velocity[apart, :, axis], numeric[apart], rtol=0, atol=1e-7 * scale)


def test_group_velocity_of_long_square_waves_traces_the_wave_ellipse():
    k, T, m, a = 2.1e4, 2.0, 0.008, 0.04
    c_L, c_T = a * np.sqrt(k / m), np.sqrt(T * a / m)
    psi = np.linspace(0.05, 0.7, 12)  # wavevector directions below the diagonal, where the branches meet
    q = 1e-6 / a
    velocity = sheet_group_velocity(q * np.cos(psi), q * np.sin(psi), pattern="square", k=k, T=T, m=m, a=a)
    # The branch polarised along x has omega^2 = c_L^2 q_x^2 + c_T^2 q_y^2: its group velocity is
    # (c_L^2 q_x, c_T^2 q_y)/omega, on the ellipse (v_x/c_L)^2 + (v_y/c_T)^2 = 1 (its wave surface).
    # Below the diagonal it is the upper branch. Long-wave error (q a)^2 ~ 1e-12; rounding: 1e-9.
    x_branch = velocity[:, 1]
    assert np.allclose((x_branch[:, 0] / c_L) ** 2 + (x_branch[:, 1] / c_T) ** 2, 1.0, rtol=1e-9)
    omega = np.hypot(c_L * np.cos(psi), c_T * np.sin(psi))
    assert np.allclose(x_branch[:, 0], c_L**2 * np.cos(psi) / omega, rtol=1e-9)


def test_group_velocity_refuses_a_zero_wavevector():
    with pytest.raises(ValueError, match="must not be zero"):
        sheet_group_velocity(0.0, 0.0, pattern="square", k=1.0, T=1.0, m=1.0, a=1.0)


def test_square_speeds_along_axes_and_diagonal():
    kx, ky, Tx, Ty, ax, ay, mass = 2.1e4, 3.3e4, 2.0e2, 5.0e2, 0.04, 0.05, 0.008
    biaxial = dict(pattern="square", k=(kx, ky), T=(Tx, Ty), m=mass, a=(ax, ay))
    along_x, along_y = sheet_sound_speeds(0.0, **biaxial), sheet_sound_speeds(np.pi / 2, **biaxial)
    # chain and string along each lattice direction, to rounding (1e-14)
    assert np.allclose(along_x, [ax * np.sqrt(kx / mass), np.sqrt(Tx * ax / mass)], rtol=1e-14)
    assert np.allclose(along_y, [ay * np.sqrt(ky / mass), np.sqrt(Ty * ay / mass)], rtol=1e-14)
    # Labels follow the polarisation, not the speed: a tension above k a makes the longitudinal wave the slower.
    taut = sheet_sound_speeds(0.0, pattern="square", k=1.0, T=4.0, m=1.0, a=1.0)
    assert np.allclose(taut, [1.0, 2.0], rtol=1e-14)
    diagonal = sheet_sound_speeds(np.pi / 4, pattern="square", k=1.0, T=0.5, m=2.0, a=1.0)
    assert np.allclose(diagonal, np.sqrt((1.0 + 0.5) / 4), rtol=1e-14)  # (k a^2 + T a)/(2m), to rounding


@pytest.mark.parametrize("pattern", ["square", "triangular"])
def test_long_waves_of_huge_and_tiny_sheets_stay_within_double_precision(pattern):
    """The long-wave tensor's k a^2/m overflowed for links above 1e154 m (speeds refused, naming the transverse one)
    and sin^2(q a/2) underflowed for q a below 1e-154, making omega zero where it is 1e-148 rad/s.  Now: with
    a -> s a, k -> k/s^2, T -> T/s the speeds do not change; and long waves are omega = q c to the last digit."""
    links = dict(pattern=pattern, T=2.0, k=3.0e4, m=0.008)
    reference = sheet_sound_speeds(0.3, a=0.04, **links)
    for s_ in (1e156, 1e-150):  # a = 4e154 m: a^2 is beyond the doubles
        scaled = sheet_sound_speeds(0.3, pattern=pattern, T=2.0 / s_, k=3.0e4 / s_ / s_, m=0.008, a=0.04 * s_)
        np.testing.assert_allclose(scaled, reference, rtol=1e-12)
    q, angle = 1e-170, 0.3  # q a/2 = 2e-172: sin^2 underflows, omega = q c = 1e-168 rad/s does not
    omega = sheet_dispersion(q * np.cos(angle), q * np.sin(angle), a=0.04, **links)
    np.testing.assert_allclose(omega, q * np.sort(reference), rtol=1e-14)
    tiny = sheet_dispersion(10.0, 5.0, a=1e-300, **links)  # the string's omega^2 = T a q^2/m, with T/a = 2e300
    assert np.all(tiny > 0) and np.all(tiny < 1e-147)


# --- symmetries -------------------------------------------------------------------------------------------

RNG = np.random.default_rng(2021)
Q = RNG.uniform(-200.0, 200.0, size=(64, 2))  # rad/m, over several Brillouin zones of a = 0.04 m


def rotate(wavevectors, angle):
    c, s = np.cos(angle), np.sin(angle)
    return wavevectors @ np.array([[c, s], [-s, c]])  # each row rotated by +angle


def test_square_sheet_has_the_symmetry_of_the_square():
    parameters = dict(pattern="square", k=2.1e4, T=2.0e2, m=0.008, a=0.04)
    omega = sheet_dispersion(*Q.T, **parameters)
    # Rotations by 90 degrees and the mirror x <-> y permute the same sin^2 terms: a few ulp (1e-13).
    for image in (rotate(Q, np.pi / 2), Q[:, ::-1], -Q):
        assert np.allclose(sheet_dispersion(*image.T, **parameters), omega, rtol=1e-13)
    # A biaxial sheet turned by 90 degrees is the sheet with its families exchanged.
    biaxial = dict(k=(2.1e4, 3.3e4), T=(2.0e2, 5.0e2), a=(0.04, 0.05), m=0.008)
    turned = {name: value[::-1] if isinstance(value, tuple) else value for name, value in biaxial.items()}
    assert np.allclose(
        sheet_dispersion(*rotate(Q, np.pi / 2).T, pattern="square", **turned),
        sheet_dispersion(*Q.T, pattern="square", **biaxial),
        rtol=1e-13,
    )


def test_triangular_sheet_has_the_symmetry_of_the_hexagon():
    parameters = dict(pattern="triangular", k=2.1e4, T=2.0e2, m=0.008, a=0.04)
    omega = sheet_dispersion(*Q.T, **parameters)
    # Rotations by 60 degrees and the mirror y -> -y: equal to the rounding of q.b after the rotation (1e-12).
    for image in (rotate(Q, np.pi / 3), rotate(Q, -np.pi / 3), Q * [1, -1]):
        assert np.allclose(sheet_dispersion(*image.T, **parameters), omega, rtol=1e-12)
    # Per family: the sheet turned by 60 degrees has the 0-degree family's links at 60 degrees, and so on.
    per_family = dict(k=(2.1e4, 1.7e4, 3.3e4), T=(1.7e2, 3.0e2, 0.5e2), a=0.04, m=0.008)
    turned = dict(per_family, k=(3.3e4, 2.1e4, 1.7e4), T=(0.5e2, 1.7e2, 3.0e2))
    assert np.allclose(
        sheet_dispersion(*rotate(Q, np.pi / 3).T, pattern="triangular", **turned),
        sheet_dispersion(*Q.T, pattern="triangular", **per_family),
        rtol=1e-12,
    )


@pytest.mark.parametrize("pattern", sheet.PATTERNS)
def test_dispersion_is_periodic_on_the_reciprocal_lattice(pattern):
    a_ = 0.04
    primitive, _ = LATTICE[pattern](a_, a_)
    reciprocal = 2 * np.pi * np.linalg.inv(primitive).T  # columns b_i with a_i.b_j = 2 pi delta_ij
    parameters = dict(pattern=pattern, k=2.1e4, T=2.0e2, m=0.008, a=a_)
    omega = sheet_dispersion(*Q.T, **parameters)
    for shift in (reciprocal[:, 0], reciprocal[:, 1], reciprocal[:, 0] - 2 * reciprocal[:, 1]):
        # sin^2 of arguments a few times larger: rounding of q.b grows with |q| (1e-12)
        assert np.allclose(sheet_dispersion(*(Q + shift).T, **parameters), omega, rtol=1e-12)


def test_triangular_long_waves_are_isotropic():
    angles = np.linspace(-np.pi, np.pi, 37)
    speeds = sheet_sound_speeds(angles, pattern="triangular", k=2.1e4, T=2.0e2, m=0.008, a=0.04)
    c_L2, c_T2 = (9 * 2.1e4 * 0.04**2 + 3 * 2.0e2 * 0.04) / 0.064, (3 * 2.1e4 * 0.04**2 + 9 * 2.0e2 * 0.04) / 0.064
    # the same at every angle, to rounding of the angle's cosines and sines (1e-13)
    assert np.allclose(speeds.longitudinal, np.sqrt(c_L2), rtol=1e-13)
    assert np.allclose(speeds.transverse, np.sqrt(c_T2), rtol=1e-13)
    central = sheet_sound_speeds(angles, pattern="triangular", k=2.1e4, T=0.0, m=0.008, a=0.04)
    assert np.allclose(central.longitudinal / central.transverse, np.sqrt(3), rtol=1e-13)  # Cauchy: lambda = mu


def test_square_long_waves_are_anisotropic_with_fourfold_symmetry():
    angles = np.linspace(0.0, np.pi / 2, 19)
    parameters = dict(pattern="square", k=2.1e4, T=2.0, m=0.008, a=0.04)
    speeds = np.stack(sheet_sound_speeds(angles, **parameters))
    turned = np.stack(sheet_sound_speeds(angles + np.pi / 2, **parameters))
    mirrored = np.stack(sheet_sound_speeds(np.pi / 2 - angles, **parameters))
    assert np.allclose(turned, speeds, rtol=1e-13) and np.allclose(mirrored, speeds, rtol=1e-13)  # rounding
    # The longitudinal speed falls from the axis to the diagonal, where both speeds meet.
    assert np.all(np.diff(speeds[0, :10]) < 0)
    assert np.isclose(speeds[0, 9], speeds[1, 9], rtol=1e-13)


# --- the 1D limit ---------------------------------------------------------------------------------------


def test_square_sheet_without_cross_links_is_the_power_law_chain():
    ring = Ring.from_aspect_ratio(9.0)
    K, n = ring.power_law()
    F0, mass, spacing = 5.0, 0.37 * ring.mass, ring.spacing
    L = linear.symbols()
    k_c = float(linear.contact_stiffness().subs({L["K"]: K, L["n"]: n, L["F_0"]: F0}))  # the same slope
    qx = np.linspace(-np.pi / spacing, 2 * np.pi / spacing, 31)
    qy = np.linspace(-50.0, 80.0, 31)
    omega = sheet_dispersion(qx, qy, pattern="square", k=(k_c, 0.0), T=(F0, 0.0), m=mass, a=(spacing, 0.03))
    chain = dispersion(qx, model="power-law", F_0=F0, K=K, n=n, m=mass, a=spacing)[:, 0]
    string = 2 * np.sqrt(F0 / (mass * spacing)) * np.abs(np.sin(qx * spacing / 2))
    # the same closed forms evaluated in double, k_c rounded once more on its way through float(): 1e-12
    assert np.allclose(omega[:, 1], chain, rtol=1e-12, atol=0)
    assert np.allclose(omega[:, 0], string, rtol=1e-12, atol=0)


# --- inputs ---------------------------------------------------------------------------------------------


def test_shapes_broadcast_with_branches_last():
    qx = np.linspace(0.0, 50.0, 4)[:, None]
    k = np.array([1e4, 2e4, 3e4])
    omega = sheet_dispersion(qx, 0.0, pattern="triangular", k=k, T=1.0, m=0.01, a=0.04)
    assert omega.shape == (4, 3, 2) and np.all(np.diff(omega, axis=-1) >= 0)
    omega = sheet_dispersion(qx, 1.0, pattern="square", k=(k, 1e4), T=1.0, m=0.01, a=0.04)
    assert omega.shape == (4, 3, 2)
    speeds = sheet_sound_speeds(qx, pattern="square", k=k, T=1.0, m=0.01, a=0.04)
    assert isinstance(speeds, SheetSpeeds) and speeds.longitudinal.shape == speeds.transverse.shape == (4, 3)


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (dict(pattern="hexagonal"), "pattern must be one of"),
        (dict(k=(1.0, 2.0, 3.0)), r"tuple of 2 \(one per link family: x, y\), got a tuple of 3"),
        (dict(T=-1.0), "tension only"),
        (dict(T=(1.0, -1.0)), r"T\[1\] must be non-negative"),
        (dict(k=-1.0), "k must be non-negative"),
        (dict(m=0.0), "m must be positive"),
        (dict(a=(0.04, 0.0)), r"a\[1\] must be positive"),
        (dict(k=np.nan), "k must be finite"),
        (dict(k=(np.ones(3), np.ones(4))), r"k\[0\] \(shape \(3,\)\) and k\[1\] \(shape \(4,\)\)"),
    ],
)
def test_bad_inputs_are_refused_with_a_reason(change, message):
    parameters = dict(pattern="square", k=1e4, T=1.0, m=0.01, a=0.04) | change
    with pytest.raises(ValueError, match=message):
        sheet_dispersion(1.0, 2.0, **parameters)
    with pytest.raises(ValueError, match=message):
        sheet_sound_speeds(0.3, **parameters)


def test_triangular_refuses_per_family_lengths_and_bad_wavevectors():
    with pytest.raises(ValueError, match="equilateral"):
        sheet_dispersion(1.0, 2.0, pattern="triangular", k=1e4, T=1.0, m=0.01, a=(0.04, 0.04, 0.04))
    with pytest.raises(ValueError, match="qx must be finite"):
        sheet_dispersion(np.inf, 2.0, pattern="triangular", k=1e4, T=1.0, m=0.01, a=0.04)
    with pytest.raises(ValueError, match="not representable"):
        sheet_dispersion(1.0, 2.0, pattern="triangular", k=1e308, T=1.0, m=1e-300, a=0.04)
