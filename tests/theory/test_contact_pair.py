"""Hertz contact of two different interlocked tori: reduction to equal rings, symmetry, mpmath check."""

import mpmath
import numpy as np
import pytest
from ringchain.theory import contact, hertz_stiffness, hertz_stiffness_pair
from ringchain.theory._codegen import sp
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

STEEL = (193e9, 0.29)
BRASS = (100e9, 0.34)


def _independent_stiffness(R1, r1, E1, nu1, R2, r2, E2, nu2, angle):
    """K_c by another route, in mpmath at 30 digits.

    Curvatures: the eigenvalues of half the sum of the two bodies' curvature tensors (ring 2's
    turned by ``angle``), not Hertz's sum formulas.  Shape: Johnson's equation
    B/A = (E/(1 - m) - K)/(K - E) solved for m with mpmath's root finder.  Load: from
    Johnson's P = 2/3 pi a b p0, delta = p0 b K/E*, A = p0 b (K - E)/(E* a^2 m), which give
    K_c = P/delta^1.5 = 2/3 pi E* (A m/(K - E))^(-1/2) K^(-3/2) (a cancels).
    """
    mpmath.mp.dps = 30
    mp = mpmath.mpf
    c1 = mpmath.matrix([[1 / mp(r1), 0], [0, -1 / (mp(R1) - mp(r1))]])
    c2 = mpmath.matrix([[1 / mp(r2), 0], [0, -1 / (mp(R2) - mp(r2))]])
    cos, sin = mpmath.cos(mp(angle)), mpmath.sin(mp(angle))
    turn = mpmath.matrix([[cos, -sin], [sin, cos]])
    A, B = sorted(mpmath.eigsy((c1 + turn * c2 * turn.T) / 2)[0])
    E_star = 1 / ((1 - mp(nu1) ** 2) / mp(E1) + (1 - mp(nu2) ** 2) / mp(E2))
    if B / A - 1 < mp(10) ** -25:
        m = mp(0)
        K, D = mpmath.pi / 2, mpmath.pi / 4  # K(0) and lim (K - E)/m
    else:

        def shape(m):
            K, E = mpmath.ellipk(m), mpmath.ellipe(m)
            return (E / (1 - m) - K) / (K - E) - B / A

        m = mpmath.findroot(shape, (mp(10) ** -12, 1 - mp(10) ** -12), solver="anderson")
        K, D = mpmath.ellipk(m), (mpmath.ellipk(m) - mpmath.ellipe(m)) / m
    return float(2 * mpmath.pi / 3 * E_star * mpmath.sqrt(D / A) * K**-1.5)


def test_curvature_sums_reduce_to_those_of_equal_rings():
    p, s = contact.pair_symbols(), contact.symbols()
    equal = {p["R1"]: s["R"], p["R2"]: s["R"], p["r1"]: s["r"], p["r2"]: s["r"]}
    L = sp.Symbol("L", positive=True)  # R - r > 0: lets sqrt((R - r)^2) = R - r
    c = sp.Symbol("c", nonnegative=True)  # cos(theta) >= 0 on (0, pi/2]
    for pair, single in zip(contact.curvature_sums_pair(), contact.curvature_sums(), strict=True):
        difference = (pair.subs(equal) - single).subs({s["R"]: s["r"] + L, sp.cos(s["theta"]): c})
        assert sp.simplify(difference) == 0
    A, B = contact.relative_curvatures()
    assert sp.simplify(contact.curvature_product_pair().subs(equal) - sp.expand_trig(A * B)) == 0
    sine = sp.sin(contact.minimum_angle_pair().subs(equal)) ** 2
    assert sp.simplify(sine - sp.expand_trig(sp.sin(contact.minimum_angle()) ** 2)) == 0
    E, nu = sp.symbols("E nu", positive=True)
    same = {p["E1"]: E, p["E2"]: E, p["nu1"]: nu, p["nu2"]: nu}
    assert sp.simplify(contact.effective_modulus_pair().subs(same) - contact.effective_modulus()) == 0


@pytest.mark.parametrize("angle", [np.pi / 2, 1.3, 1.0, 0.8])
def test_the_two_torus_route_reproduces_hertz_stiffness_for_equal_rings(angle):
    R, r = 22.5e-3, 2.5e-3
    general = contact._pair_stiffness(*map(np.asarray, (R, r, *STEEL, R, r, *STEEL, angle)))
    # Two derivations of the same number (Hertz sums of two tori vs the half-angle form of one):
    # rounding of a few operations and the same table, measured 8e-16.
    assert general == pytest.approx(float(hertz_stiffness(R, r, *STEEL, angle)), rel=1e-14)
    # The public function gives the single-torus number itself for equal rings (a uniform chain
    # built ring by ring is then exactly the uniform chain).
    assert hertz_stiffness_pair(R, r, *STEEL, R, r, *STEEL, angle) == hertz_stiffness(R, r, *STEEL, angle)


PAIRS = [
    ((22.5e-3, 2.5e-3, *STEEL), (15e-3, 2.5e-3, *STEEL)),
    ((22.5e-3, 2.5e-3, *STEEL), (30e-3, 4e-3, *BRASS)),
    ((12e-3, 1.5e-3, *BRASS), (40e-3, 3e-3, *STEEL)),
]


@pytest.mark.parametrize("angle", [np.pi / 2, 1.3, 1.1, 0.95])
@pytest.mark.parametrize(("ring1", "ring2"), PAIRS)
def test_unequal_rings_against_mpmath_elliptic_integrals(ring1, ring2, angle):
    expected = _independent_stiffness(*ring1, *ring2, angle)
    # The table of Gamma is accurate to ~1e-15 and the curvature formulas lose a few digits
    # near theta_min; 1e-12 leaves room for both (measured 1.2e-15 at most).
    assert float(hertz_stiffness_pair(*ring1, *ring2, angle)) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(("ring1", "ring2"), PAIRS)
def test_symmetric_in_the_two_rings(ring1, ring2):
    angles = np.linspace(1.0, np.pi / 2, 7)
    # Same formulas with the roles swapped: sums in another order, rounding only (measured 2.2e-16).
    forward, backward = hertz_stiffness_pair(*ring1, *ring2, angles), hertz_stiffness_pair(*ring2, *ring1, angles)
    np.testing.assert_allclose(forward, backward, rtol=1e-14)


def test_broadcasts_over_arrays():
    R2 = np.linspace(12e-3, 30e-3, 5)
    K = hertz_stiffness_pair(22.5e-3, 2.5e-3, *STEEL, R2, 2.5e-3, *STEEL)
    assert K.shape == (5,)
    expected = [_independent_stiffness(22.5e-3, 2.5e-3, *STEEL, R, 2.5e-3, *STEEL, np.pi / 2) for R in R2]
    np.testing.assert_allclose(K, expected, rtol=1e-12)  # as in the mpmath test above


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (dict(angle=0.5), r"angle 0.5 rad \(28.6479 deg\) is at or below the smallest angle of a single contact"),
        (dict(R1=4e-3), "R must exceed 2 r"),
        (dict(R1=12e-3, r1=5.5e-3, R2=15e-3, r2=7e-3), "the tubes are too thick for the holes"),
        (dict(nu2=0.6), "nu must lie in"),
        (dict(angle=2.0), "angle must lie in"),
    ],
)
def test_refuses_what_has_no_single_hertz_contact(args, message):
    values = dict(R1=22.5e-3, r1=2.5e-3, E1=193e9, nu1=0.29, R2=15e-3, r2=2.5e-3, E2=193e9, nu2=0.29) | args
    with pytest.raises(ValueError, match=message):
        hertz_stiffness_pair(**values)


@pytest.mark.parametrize("aspect", [2.2, 3.0, 4.5, 6.0, 9.0, 40.0])
@pytest.mark.parametrize("angle", [np.pi / 2, 1.3, 1.0])
def test_identical_pairs_inside_an_array(aspect, angle):
    # Issue 24, item 13: an exactly identical pair among different ones goes the two-torus route, where
    # |A - B| = sqrt((k1 - k2)^2 + 4 k1 k2 cos^2 theta)/2 must not lose its zero to cancellation (it gave
    # sqrt of a rounding-negative radicand, NaN curvatures, and 90 deg refused as below theta_min).
    r = 2.5e-3
    if angle <= float(contact.minimum_contact_angle(aspect * r, r)):
        pytest.skip("no single contact of equal rings at this angle")
    single = float(hertz_stiffness(aspect * r, r, *STEEL, angle))
    R1 = np.array([22.5e-3, aspect * r])
    two_torus = contact._pair_stiffness(*map(np.asarray, (R1, r, *STEEL, aspect * r, r, *STEEL, angle)))
    # The identical pair by the two-torus route against the one-torus route: rounding of a few operations
    # and the same table (1e-14, as in the test of equal rings above; measured below 1e-15).
    assert two_torus[1] == pytest.approx(single, rel=1e-14)
    # The public function gives the one-torus number itself for each identical pair, as for equal arrays.
    K = hertz_stiffness_pair(R1, r, *STEEL, aspect * r, r, *STEEL, angle)
    assert K[1] == single
    assert K[0] == hertz_stiffness_pair(22.5e-3, r, *STEEL, aspect * r, r, *STEEL, angle)


def test_the_issue_case_of_an_identical_pair_in_an_array():
    K = hertz_stiffness_pair(np.array([22.5e-3, 15e-3]), 2.5e-3, *STEEL, 15e-3, 2.5e-3, *STEEL)
    assert K[1] == hertz_stiffness(15e-3, 2.5e-3, *STEEL)


def _stiffness_from_the_surfaces(R1, r1, E1, nu1, R2, r2, E2, nu2, angle):
    """K_c from the two tori's own surfaces: a second route for unequal rings (issue 24, item 16).

    Ring 1's plane is xz, its centre the origin; ring 2 hangs through it, centre at z = (R1 - r1) + (R2 - r2),
    its plane turned by ``angle`` about z.  Near the contact point (0, 0, R1 - r1) the inner surfaces are
    z1 = sqrt((R1 - sqrt(r1^2 - y^2))^2 - x^2) and z2 = d - sqrt((R2 - sqrt(r2^2 - y'^2))^2 - x'^2) (x', y'
    in ring 2's turned frame): the gap z1 - z2, whose Hessian by second differences gives the curvature sums
    (no principal radius assumed), and Hertz's ellipse (Johnson Sec. 4.2, as in _independent_stiffness).
    """
    d = (R1 - r1) + (R2 - r2)
    cos, sin = np.cos(angle), np.sin(angle)

    def gap(x, y):
        xt, yt = x * cos + y * sin, -x * sin + y * cos
        z1 = np.sqrt((R1 - np.sqrt(r1**2 - y**2)) ** 2 - x**2)
        z2 = d - np.sqrt((R2 - np.sqrt(r2**2 - yt**2)) ** 2 - xt**2)
        return z1 - z2

    h = 1e-3 * min(r1, r2)
    hessian = np.array([
        [gap(h, 0) - 2 * gap(0, 0) + gap(-h, 0), (gap(h, h) - gap(h, -h) - gap(-h, h) + gap(-h, -h)) / 4],
        [0.0, gap(0, h) - 2 * gap(0, 0) + gap(0, -h)],
    ]) / h**2  # fmt: skip
    hessian[1, 0] = hessian[0, 1]
    A, B = np.linalg.eigvalsh(hessian / 2)  # gap = A x'^2 + B y'^2 in the principal axes, A <= B
    E_star = 1 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)
    m = brentq(lambda m: (ellipe(m) / (1 - m) - ellipk(m)) / (ellipk(m) - ellipe(m)) - B / A, 1e-14, 1 - 1e-15)
    K, E = ellipk(m), ellipe(m)
    return 2 * np.pi / 3 * E_star * np.sqrt((K - E) / (A * m)) * K**-1.5


@pytest.mark.parametrize("angle", [1.3, 1.1])
@pytest.mark.parametrize(("ring1", "ring2"), PAIRS)
def test_unequal_rings_against_the_curvature_of_their_own_surfaces(ring1, ring2, angle):
    expected = _stiffness_from_the_surfaces(*ring1, *ring2, angle)
    # Second differences at h = 1e-3 r: truncation (h/r)^2 = 1e-6 of the curvatures and rounding
    # eps R/h^2 ~ 1e-6 of them; K_c follows them to first order: 1e-5 leaves a margin (measured below 1e-6).
    assert float(hertz_stiffness_pair(*ring1, *ring2, angle)) == pytest.approx(expected, rel=1e-5)
