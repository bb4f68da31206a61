"""The static state of rigid rings under gravity (:meth:`Rings.equilibrium`): residuals and the balance of weights."""

import numpy as np
import pytest
from ringchain.numerics import Rings
from ringchain.theory import STANDARD_GRAVITY, Ring

RING = Ring.from_aspect_ratio(9.0)


def assert_static(rest, tol):
    """Residuals of ``rest`` within ``tol`` m g (torques m g R), and its fixed rings carrying the free ones' weight."""
    _, forces, torques = rest.potential(rest.centres, rest.orientations)
    weight = RING.mass * STANDARD_GRAVITY
    free = ~rest.fixed
    # The solver's own bound, checked here from a search of every contact from scratch.
    assert np.abs(forces[free]).max() <= tol * weight
    assert np.abs(torques[free]).max() <= tol * weight * RING.R
    # Invariant (independent of the solver): the contacts push the fixed rings down by the weight of the free rings
    # (their own weight is not a contact force), to the residual force on each free ring, tol m g each.
    np.testing.assert_allclose(-forces[rest.fixed, 2].sum(), free.sum() * weight, atol=free.sum() * tol * weight)


@pytest.mark.parametrize("law", ["hertz", "power-law"])
def test_the_anchor_carries_the_weight_of_the_hanging_chain(law):
    tol = 1e-9
    assert_static(Rings.chain(6, RING, law=law).equilibrium(force_tol=tol), tol)


def test_a_small_sheet_of_chain_mail_hangs_from_its_top_row():
    sheet = Rings.mail(2, 3, RING)  # three free rings, each hung on two of the fixed row (one at the edges)
    tol = 1e-8
    rest = sheet.equilibrium(force_tol=tol)
    assert_static(rest, tol)
    # The rings hang: every free ring is lower than it was built (they rest on the row above, not on the layout).
    free = ~sheet.fixed
    assert np.all(rest.centres[free, 2] < sheet.centres[free, 2])


def test_equilibrium_names_a_bad_tolerance():
    with pytest.raises(ValueError, match="force_tol"):
        Rings.chain(3, RING).equilibrium(force_tol=-1.0)


@pytest.mark.parametrize("precondition", [True, False], ids=["preconditioned", "plain"])
@pytest.mark.parametrize("build", [lambda: Rings.chain(6, RING), lambda: Rings.mail(2, 3, RING)], ids=["chain", "mail"])
def test_the_first_order_phase_alone_reaches_the_static_state(build, precondition, monkeypatch):
    from ringchain.numerics.layouts import rings_static

    # The first phase (L-BFGS on the energy, its initial inverse Hessian the stiffness matrix or s.y / y.y) handing
    # over only at the tolerance itself: Newton's method runs only if it stops short, so the phases must all be
    # descents and the state found theirs.
    monkeypatch.setattr(rings_static, "HANDOVER", 0.0)
    monkeypatch.setattr(rings_static, "PRECONDITION", precondition)
    network, tol = build(), 1e-8
    centres, orientations, phases = rings_static.static_state(network, force_tol=tol)
    assert [phase["phase"] for phase in phases] == ["descent"] * len(rings_static.SOFTENING)
    assert phases[-1]["residual"] <= tol
    # Independent of the solver: a search of every contact from scratch, and the weight carried by the fixed rings.
    assert_static(network.moved(centres, orientations), tol)


def test_the_phases_are_recorded():
    from ringchain.numerics.layouts.rings_static import static_state

    chain, tol = Rings.chain(3, RING), 1e-8
    centres, orientations, phases = static_state(chain, force_tol=tol)
    assert phases[0]["phase"] == "descent" and phases[0]["softening"] == 1e-3
    for phase in phases:
        assert phase["evaluations"] >= phase["iterations"] >= 0 and phase["wall"] >= 0.0
        assert phase["memory"] is None  # tracemalloc is not tracing
    assert phases[-1]["softening"] == 1.0 and phases[-1]["residual"] <= tol
    assert_static(chain.moved(centres, orientations), tol)


def _quaternion(rotation):
    """(w, x, y, z) of a SciPy rotation (which stores x, y, z, w)."""
    x, y, z, w = rotation.as_quat()
    return np.array([w, x, y, z])


@pytest.mark.parametrize(
    "law, below, pull",
    [("power-law", 2.0, 1e-5), ("power-law", 2.0, 3e-5), ("hertz", 2.0, 3e-5), ("hertz", -10.0, 3e-5),
     ("hertz", 0.0, 3e-5)],
)  # fmt: skip
def test_the_loads_are_the_gradient_of_the_energy(law, below, pull):
    """Central differences of the energy of Rings.potential against its forces and torques: at twin contacts whose
    maximum between them is in overlap (``below`` theta_min by 2 degrees; the shares of rings_kernels.fold_weights
    depend on the pose) with the power law (a constant K: the shares are the only stiffness that changes with the
    pose) and with Hertz's law (K_c of the curvatures at each contact changes with the pose too), and with Hertz's
    law at one contact 10 degrees above theta_min, and at theta_min itself (one contact whose A/sqrt(C delta) is 1.2:
    Hertz's K bounded by the gap's quartic, rings_law.contact_stiffness, K depending on the approach)."""
    from ringchain.numerics.contact.tori import torus_contacts
    from ringchain.theory import minimum_contact_angle
    from scipy.spatial.transform import Rotation

    R, r = RING.R, RING.r
    upright = Rotation.from_rotvec([-np.pi / 2, 0.0, 0.0])  # the ring's axis along y: it stands in the xz plane
    theta = float(minimum_contact_angle(R, r)) - np.radians(below)
    turn = Rotation.from_rotvec([0.0, 0.0, theta])
    tilt = Rotation.from_rotvec(0.002 * np.array([0.2, 0.1, 1.0]) / np.linalg.norm([0.2, 0.1, 1.0]))
    rotation = tilt * upright  # ring 0 off the symmetric pose, ring 1 crossing it at theta, pulled apart by `pull`
    centres = np.array([[1e-5, -2e-5, 0.0], [0.0, 0.0, 2 * (R - r) + pull]])
    orientations = np.array([_quaternion(rotation), _quaternion(turn * upright)])
    right = np.array([_quaternion(upright), _quaternion(Rotation.from_rotvec([0.0, 0.0, np.pi / 2]) * upright)])
    pair = Rings.from_rings(centres, right, RING, law=law, fixed=[1])  # built at 90 degrees, posed at theta
    contacts = torus_contacts(centres[0], orientations[0], RING, centres[1], orientations[1], RING)
    assert len(contacts) == (2 if below > 0.0 else 1)
    energy, forces, torques = pair.potential(centres, orientations)
    if law == "power-law":  # the shares are at work: the energy is below the full energy of both contacts by 1 %
        K, n = pair.stiffness[0], pair.exponent[0]
        assert energy < 0.99 * np.sum(K * (-contacts.gap) ** (n + 1) / (n + 1))

    def potential(centre, turned):
        moved_c, moved_q = centres.copy(), orientations.copy()
        moved_c[0], moved_q[0] = centre, _quaternion(turned)
        return pair.potential(moved_c, moved_q)[0]

    # Steps (m, rad): truncation (step / approach)^2 ~ 1e-9 (approaches of 1e-5 m), rounding of the energy (1e-18 J
    # of some 1e-3 J) over the step ~ 1e-9 N against forces of 1e2-1e4 N.
    step, angle = 1e-9, 1e-7
    scale = np.abs(forces[0]).max()
    for axis in np.eye(3):
        push = (potential(centres[0] + step * axis, rotation) - potential(centres[0] - step * axis, rotation)) / step
        twist = potential(centres[0], Rotation.from_rotvec(angle * axis) * rotation)
        twist = (twist - potential(centres[0], Rotation.from_rotvec(-angle * axis) * rotation)) / angle
        # 1e-6 of the largest force (torques of it times R): a thousand times the differences' error; without the
        # derivatives of the shares and of K_c the loads missed them by 6-30 per cent at the twin contacts, and by
        # 1e-3 of the largest torque (the twist about z) at the single Hertz contact.
        assert -0.5 * push == pytest.approx(forces[0] @ axis, rel=0, abs=1e-6 * scale)
        assert -0.5 * twist == pytest.approx(torques[0] @ axis, rel=0, abs=1e-6 * scale * R)


def _positive_definite(size, seed):
    """A sparse symmetric positive definite matrix B B^T + I (eigenvalues at least 1), seeded."""
    from scipy import sparse

    rng = np.random.default_rng(seed)
    b = sparse.random(size, size, density=0.05, random_state=rng)
    return (b @ b.T + sparse.identity(size)).tocsc()


@pytest.mark.parametrize("positive", [True, False], ids=["positive", "pivoting"])
def test_the_factors_solve_as_a_dense_solve(positive):
    from ringchain.numerics.layouts import rings_static

    matrix = _positive_definite(60, seed=1)
    b = np.random.default_rng(2).standard_normal(60)
    factor = rings_static._factor(matrix, positive=positive)
    expected = np.linalg.solve(matrix.toarray(), b)  # an independent (dense, LAPACK) solve
    # Both solves are backward stable: each is within cond(A) times a small multiple of the machine's epsilon of the
    # exact solution (1e3 eps covers that multiple for 60 unknowns).
    bound = 1e3 * np.finfo(float).eps * np.linalg.cond(matrix.toarray()) * np.abs(expected).max()
    np.testing.assert_allclose(factor.solve(b), expected, rtol=0, atol=bound)


@pytest.mark.parametrize("entry", [(3, 3), (3, 7)], ids=["diagonal", "off-diagonal"])
@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize("positive", [True, False], ids=["positive", "pivoting"])
def test_a_matrix_with_an_entry_not_finite_is_refused(entry, value, positive):
    from ringchain.numerics.layouts import rings_static

    matrix = _positive_definite(30, seed=3).tolil()
    i, j = entry
    matrix[i, j] = matrix[j, i] = value  # symmetric, as the solver's matrices are
    assert rings_static._factor(matrix.tocsc(), positive=positive) is None


def test_an_indefinite_matrix_is_refused_without_pivoting_and_solved_with_it():
    from ringchain.numerics.layouts import rings_static

    matrix = _positive_definite(40, seed=4).tolil()
    matrix[5, 5] = -1.0  # a negative diagonal entry: e_5^T A e_5 < 0, so A is not positive definite
    matrix = matrix.tocsc()
    assert rings_static._factor(matrix) is None
    b = np.random.default_rng(5).standard_normal(40)
    expected = np.linalg.solve(matrix.toarray(), b)  # independent: dense LAPACK
    # As in the test above: both within cond(A) times a small multiple of eps of the exact solution.
    bound = 1e3 * np.finfo(float).eps * np.linalg.cond(matrix.toarray()) * np.abs(expected).max()
    np.testing.assert_allclose(rings_static._factor(matrix, positive=False).solve(b), expected, rtol=0, atol=bound)


@pytest.mark.parametrize("spoilt", [lambda b: np.full_like(b, np.nan), lambda b: 0.5 * b[::-1]], ids=["nan", "garbage"])
def test_factors_whose_solve_is_spoilt_are_refused(spoilt, monkeypatch):
    """SuperLU's factors of some matrices solve to garbage (its BLAS told an illegal leading dimension, which it
    reports and ignores); no small matrix was found that does so, so the factors here are stand-ins whose solve
    returns NaN or a wrong vector."""
    import scipy.sparse.linalg
    from ringchain.numerics.layouts import rings_static

    class Spoilt:
        def __init__(self, factor):
            self.factor, self.U = factor, factor.U

        def solve(self, b):
            return spoilt(b)

    splu = scipy.sparse.linalg.splu
    monkeypatch.setattr(scipy.sparse.linalg, "splu", lambda *args, **kwargs: Spoilt(splu(*args, **kwargs)))
    matrix = _positive_definite(30, seed=6)
    assert rings_static._factor(matrix) is None
    assert rings_static._factor(matrix, positive=False) is None


class _Matrix:
    """A stand-in for the solver's problem whose stiffness matrix is given."""

    def __init__(self, matrix):
        self.matrix = matrix

    def stiffness(self, grad):
        return self.matrix


def test_the_preconditioner_shifts_an_indefinite_matrix_until_it_is_positive_definite():
    from ringchain.numerics.layouts import rings_static
    from scipy import sparse

    matrix = _positive_definite(40, seed=7)
    largest = np.abs(matrix.diagonal()).max()
    lowest = np.linalg.eigvalsh(matrix.toarray())[0]
    # Shifted down by s so that its lowest eigenvalue, lowest - s, is -5e-3 of its largest diagonal, largest - s (2.7,
    # above 1: the shifts are fractions of it): the shifts 1e-8, 1e-6 and 1e-4 of it leave it indefinite, 1e-2 makes
    # it positive definite.
    s = (lowest + 5e-3 * largest) / (1.0 + 5e-3)
    matrix = (matrix - s * sparse.identity(40)).tocsc()
    largest = np.abs(matrix.diagonal()).max()
    assert largest > 1.0 and np.linalg.eigvalsh(matrix.toarray())[0] == pytest.approx(-5e-3 * largest, rel=1e-9)
    solve = rings_static._preconditioner(_Matrix(matrix), None)
    b = np.random.default_rng(8).standard_normal(40)
    shifted = matrix.toarray() + 1e-2 * largest * np.eye(40)
    expected = np.linalg.solve(shifted, b)  # independent: dense LAPACK
    # As in the tests above: both within cond times a small multiple of eps of the exact solution.
    bound = 1e3 * np.finfo(float).eps * np.linalg.cond(shifted) * np.abs(expected).max()
    np.testing.assert_allclose(solve(b), expected, rtol=0, atol=bound)


def test_the_preconditioner_of_a_matrix_not_finite_is_none():
    from ringchain.numerics.layouts import rings_static

    # No shift makes it finite: none is tried forever (the solver then steps along the gradient and its pairs).
    matrix = _positive_definite(20, seed=9).tolil()
    matrix[4, 4] = np.nan
    assert rings_static._preconditioner(_Matrix(matrix.tocsc()), None) is None


def _cliff(problem, dof, sides):
    """Wrap the loads of ``problem`` with a cliff of the energy (1e100 J, its gradient 1e110) where the move of ``dof``
    passes half the finite-difference step, on the given sides (+1, -1): a stand-in for Hertz's stiffness of the
    curvatures capped at ln(B/A) = 690, which jumps by some 1e140 where a contact's sum A of curvatures turns
    negative."""
    from ringchain.numerics.layouts import rings_static

    evaluate = problem.evaluate

    def cliffed(x, cold=True):
        energy, grad = evaluate(x, cold)
        if any(side * x[dof] > 0.5 * rings_static.DIFFERENCE for side in sides):
            grad = grad.copy()
            grad[dof] += 1e110
            energy += 1e100
        return energy, grad

    problem.evaluate = cliffed


@pytest.fixture(scope="module")
def hanging():
    """A chain of four rings hanging at rest, its contacts closed under the weights (the rest pose of a chain
    just touches them: a difference there is one-sided by nature, Hertz's force growing from zero)."""
    return Rings.chain(4, RING).equilibrium(force_tol=1e-6)


@pytest.mark.parametrize("dof", [0, 2, 4, 7])
def test_the_stiffness_matrix_takes_no_difference_across_a_cliff(dof, hanging):
    from ringchain.numerics.layouts import rings_static

    chain = hanging
    plain = rings_static._Problem(chain, STANDARD_GRAVITY)
    size = 6 * plain.moving.size
    expected = plain.stiffness(plain.evaluate(np.zeros(size))[1]).toarray()
    cliffed = rings_static._Problem(chain, STANDARD_GRAVITY)
    _cliff(cliffed, dof, sides=(1.0,))
    matrix = cliffed.stiffness(cliffed.evaluate(np.zeros(size))[1]).toarray()
    assert cliffed.dropped == 0
    # The forward and backward differences of a smooth gradient agree to DIFFERENCE over the length on which the
    # stiffness changes (the approach of a contact, some 1e-3 r): 1e-4 of the largest entry, bounded at ten times that;
    # the difference across the cliff would put 1e117 in the matrix.
    np.testing.assert_allclose(matrix, expected, rtol=0, atol=1e-3 * np.abs(expected).max())


def test_the_stiffness_matrix_leaves_out_a_column_with_a_cliff_either_side(hanging):
    from ringchain.numerics.layouts import rings_static

    chain = hanging
    problem = rings_static._Problem(chain, STANDARD_GRAVITY)
    size = 6 * problem.moving.size
    plain = problem.stiffness(problem.evaluate(np.zeros(size))[1]).toarray()
    _cliff(problem, 2, sides=(1.0, -1.0))  # a translation (along z) of the lowest ring
    matrix = problem.stiffness(problem.evaluate(np.zeros(size))[1]).toarray()
    assert problem.dropped == 1
    assert np.all(matrix[:, 2] == 0.0)  # left out, not the difference across the cliff
    assert np.any(plain[:, 2] != 0.0)  # (where the plain matrix has a column: the ring rests on its neighbour)
