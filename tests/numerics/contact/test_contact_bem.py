"""Numerical contact of two tori (numerics/contact_bem.py) against Hertz, and below theta_min."""

import numpy as np
import pytest
from ringchain.numerics.contact import angle as contact_angle
from ringchain.numerics.contact import bem as contact_bem
from ringchain.numerics.contact.bem import HalfSpaceWarning, contact_curve
from ringchain.theory import (
    bending_stiffness,
    contact_ellipse,
    contact_modulus,
    contact_patches,
    fit_power_law,
    hertz_stiffness,
    minimum_contact_angle,
)
from scipy.special import ellipe, ellipk

R, r, E, nu = 22.5e-3, 2.5e-3, 193e9, 0.29  # the paper's R/r = 9 stainless ring
SMALL = [0.05, 0.5]  # N: contacts of 0.01-0.05 r, where the quartic terms of the gap are below 1e-3


class _Sphere:
    """A sphere of radius R_s on a flat: the gap x^2/(2 R_s) + y^2/(2 R_s), as the solver's own check."""

    n_patches, c, tilt, r = 1, 0.0, 0.0, 1.0

    def __init__(self, R_s):
        self.R_s = R_s

    def gap(self, x, y):
        return (np.asarray(x) ** 2 + np.asarray(y) ** 2) / (2 * self.R_s)


@pytest.mark.parametrize("points", [8, 16])
def test_sphere_on_flat_gives_hertz(points):
    R_s, E_star, P = 1e-2, 1e11, 2.0
    a = (3 * P * R_s / (4 * E_star)) ** (1 / 3)  # Hertz, Johnson Sec. 4.2, typed independently
    delta_hertz = a**2 / R_s
    h = 2 * a / points
    grid = contact_bem._grid_for(_Sphere(R_s), -1.5 * a, 1.5 * a, 1.5 * a, h, h)
    solver = contact_bem._Solver(_Sphere(R_s), E_star, grid, (1 / (2 * R_s), 1 / (2 * R_s)))
    result = solver.solve(P, 0.5 * delta_hertz)
    # 8 pixels across the contact: 0.7 % in force at given approach, 16: 0.2 % (module notes); the approach
    # error is 2/3 of that.
    assert result.approach == pytest.approx(delta_hertz, rel=0.005 if points == 8 else 0.0015)
    area = np.count_nonzero(result.forces > 0) * grid.hx * grid.hy
    assert area == pytest.approx(np.pi * a**2, rel=4 / points)  # pixel count: edge error ~ perimeter x h/2


@pytest.mark.parametrize("angle_deg", [90.0, 60.0, 45.0])
def test_force_and_ellipse_agree_with_hertz_at_small_load(angle_deg):
    angle = np.radians(angle_deg)
    curve = contact_curve(R, r, E, nu, angle, SMALL)
    K_c = float(hertz_stiffness(R, r, E, nu, angle))
    # The solver resolves the force to 0.2 % (16 pixels across); the gap's quartic terms add < 0.1 % here.
    assert curve.force == pytest.approx(K_c * curve.delta**1.5, rel=0.01)
    assert curve.force == pytest.approx(K_c * curve.delta**1.5, rel=0.003)
    A, _B, m = (float(v) for v in contact_ellipse(R, r, angle))
    X, Y = np.meshgrid(curve.pressure.x, curve.pressure.y, indexing="ij")
    for p, delta in zip(curve.pressure.p, curve.delta, strict=True):
        w = p / p.sum()
        # Hertz's pressure sqrt(1 - x^2/a^2 - y^2/b^2) has <x^2> = a^2/5, <y^2> = b^2/5.
        a_num, b_num = np.sqrt(5 * np.sum(w * X**2)), np.sqrt(5 * np.sum(w * Y**2))
        if m < 1e-12:  # circle: a^2 = R' delta, R' = 1/(2A)
            a = np.sqrt(delta / (2 * A))
        else:  # Johnson Sec. 4.2: delta/A = a^2 K/((K - E)/m), the major axis along A (the bisector)
            a = np.sqrt(delta * (ellipk(m) - ellipe(m)) / (m * A * ellipk(m)))
        b = a * np.sqrt(1 - m)
        # Second moments on the grid: error ~ (h/a)^2 ~ 0.4 %, measured 0.2 % or less.
        assert (a_num, b_num) == (pytest.approx(a, rel=0.01), pytest.approx(b, rel=0.01))
    assert np.all(curve.n_patches == 1)
    assert curve.resolution_error < contact_bem.RESOLUTION_TOLERANCE


def test_grid_refinement_converges():
    angle = np.radians(60.0)
    deltas = {k: contact_curve(R, r, E, nu, angle, [1.0], points_across=k).delta[0] for k in (8, 16, 32)}
    coarse, medium = abs(deltas[8] / deltas[32] - 1), abs(deltas[16] / deltas[32] - 1)
    assert medium < coarse
    assert medium < 2e-3  # 16 pixels across: 0.2 % in force, 2/3 of that in approach


def test_series_curve_gives_the_papers_power_law_at_90_degrees():
    K_b = float(bending_stiffness(R, r, E, nu))
    curve = contact_curve(R, r, E, nu, np.pi / 2, np.geomspace(1.0, 100.0, 9))
    K, n = curve.series(K_b).fit()
    K_ref, n_ref = fit_power_law(K_c=hertz_stiffness(R, r, E, nu), K_b=K_b)
    # Hertz to 0.2 % in force; 9 points over two decades interpolate ln delta to ~1e-4.
    assert n == pytest.approx(float(n_ref), rel=2e-3)
    assert K == pytest.approx(float(K_ref), rel=2e-2)  # K = F/delta^n: n's error times ln(delta) ~ 12
    assert np.all(np.diff(curve.delta) > 0)
    # The contact alone: local exponent 3/2 (Hertz) to the solver's accuracy.
    assert curve.local_exponent == pytest.approx(1.5, abs=0.01)
    with pytest.raises(ValueError, match="already includes"):
        curve.series(K_b).series(K_b)


def test_two_symmetric_patches_below_theta_min(monkeypatch):
    angle = np.radians(37.0)
    separate = contact_curve(R, r, E, nu, angle, SMALL)
    assert separate.pressure.mirrored and np.all(separate.n_patches == 2)
    monkeypatch.setattr(contact_bem, "_JOINT_SEPARATION", np.inf)  # both patches on one grid
    joint = contact_curve(R, r, E, nu, angle, SMALL)
    assert not joint.pressure.mirrored and np.all(joint.n_patches == 2)
    x = joint.pressure.x
    for p in joint.pressure.p:
        left, right = p[x < 0].sum(), p[x > 0].sum()
        # Each half's gap is cast onto the tori on its own; they agree by the half turn to rounding.
        assert left == pytest.approx(right, rel=1e-6)
        assert np.allclose(p, p[::-1], rtol=0, atol=1e-6 * p.max())
    # The joint grid couples the patches through the half-space kernel, the separate windows by a point
    # load; the neglected multipoles are ~(size/distance)^2 of an interaction that is itself < 1e-3 here.
    assert joint.delta == pytest.approx(separate.delta, rel=1e-3)
    c, _, tilt = (float(v) for v in contact_patches(R, r, angle))
    right_half = joint.pressure.p[0] * (x[:, None] > 0)
    centre = np.sum(right_half * x[:, None]) / np.sum(right_half)
    assert centre == pytest.approx(c, rel=0.02)  # the pressure is centred on the contact point
    assert joint.tilt == pytest.approx(tilt)


def test_force_approach_is_continuous_across_theta_min():
    lowest = float(minimum_contact_angle(R, r))
    with pytest.warns(HalfSpaceWarning):  # near theta_min the contact is a long line even at 0.1 N
        below = contact_curve(R, r, E, nu, lowest - 1e-7, [0.1], points_across=12)
    with pytest.warns(HalfSpaceWarning):
        above = contact_curve(R, r, E, nu, lowest + 1e-7, [0.1], points_across=12)
    assert below.tilt > 0 and above.tilt == 0  # two contact points (merged into one patch) against one
    assert below.n_patches[0] == 1
    # delta varies steeply here (~17 % per 0.01 deg), which over 2e-7 rad is 0.02 %; the rest is the two
    # grids' resolution, each better than 1 %.
    assert below.delta[0] == pytest.approx(above.delta[0], rel=0.02)


def test_axial_gap_overstates_the_stiffness_of_tilted_patches():
    angle = np.radians(30.0)
    forces = [1.0, 10.0]
    tangent = contact_curve(R, r, E, nu, angle, forces)
    axial = contact_curve(R, r, E, nu, angle, forces, frame="axial")
    tilt = tangent.tilt
    assert axial.tilt == 0 and tangent.tilt == pytest.approx(float(contact_patches(R, r, angle)[2]))
    ratio = tangent.fit((1.0, 10.0), n=1.5)[0] / axial.fit((1.0, 10.0), n=1.5)[0]
    # A Hertz patch seen along the axis: approach / cos(tilt), curvatures / cos^3 and / cos, force x cos:
    # the axial stiffness is larger by ~cos(tilt)^(-3/2), up to the change of the ellipse's shape (~10 %).
    assert ratio == pytest.approx(np.cos(tilt) ** 1.5, rel=0.15)


def _hertz_normal_approach(P, A, B, E_star):
    """Approach (m) of the Hertz contact of a gap A x^2 + B y^2 (1/m, A <= B) under the normal load P (N).

    Johnson (Contact Mechanics, Sec. 4.2), typed here: the ellipse's m = e^2 from
    B/A = (E(m)/(1 - m) - K(m))/(K(m) - E(m)); P = 2/3 pi a b p0 with A = p0 b (K - E)/(E* a^2 m), b = a sqrt(1 - m),
    so a^3 = 3 P (K - E)/(2 pi A E* m); the approach p0 b K/E* = A a^2 m K/(K - E).
    """
    from scipy.optimize import brentq

    m = brentq(lambda m: (ellipe(m) / (1 - m) - ellipk(m)) / (ellipk(m) - ellipe(m)) - B / A, 1e-12, 1 - 1e-15)
    K, E = ellipk(m), ellipe(m)
    a = (3 * P * (K - E) / (2 * np.pi * A * E_star * m)) ** (1 / 3)
    return A * a**2 * m * K / (K - E)


@pytest.mark.parametrize("angle_deg", [30.0, 20.0])
def test_tilted_patches_are_hertz_contacts_in_their_own_planes(angle_deg):
    """Issue 24, item 16: a second check of the tilted patches' approach (one test alone caught a change of it).

    Below theta_min each of the two patches, at small load, is a Hertz contact of the gap's curvatures in its
    tangent plane, under the normal load F/(2 cos(tilt)), pushed in further by the other patch's load, a point
    load 2c away (Boussinesq: P/(pi E* 2c)); the approach along the chain axis is the normal one over cos(tilt).
    Tilts of 56 and 78 deg here: cos(tilt) = 0.56 and 0.21.
    """
    angle = np.radians(angle_deg)
    forces = np.array([0.05, 0.2, 1.0])
    curve = contact_curve(R, r, E, nu, angle, forces)
    tori = contact_bem.Tori(R, r, angle, "tangent")
    assert tori.n_patches == 2 and curve.tilt == pytest.approx(tori.tilt)
    step = 1e-3 * r  # second differences of the gap at its contact point: (step/r)^2 = 1e-6 of its quartic terms
    along = tori.gap(tori.c + step * np.array([-1.0, 0.0, 1.0]), np.zeros(3))
    across = tori.gap(np.full(3, tori.c), step * np.array([-1.0, 0.0, 1.0]))
    A, B = sorted(float(g[0] - 2 * g[1] + g[2]) / (2 * step**2) for g in (along, across))
    E_star = float(contact_modulus(E, nu))  # of the pair: E / (2 (1 - nu^2))
    normal = forces / (2 * np.cos(curve.tilt))
    approach = [_hertz_normal_approach(P, A, B, E_star) + P / (np.pi * E_star * 2 * tori.c) for P in normal]
    # The grid resolves the force to 0.2 % (16 pixels across, module notes), the approach to 2/3 of it; the
    # quartic terms of the gap at 0.01-0.05 r add < 0.1 %: measured 0.01-0.06 %.
    np.testing.assert_allclose(curve.delta, np.array(approach) / np.cos(curve.tilt), rtol=3e-3)


def test_half_space_warning_and_extent():
    with pytest.warns(HalfSpaceWarning, match="tube radius"):
        curve = contact_curve(R, r, E, nu, np.radians(45.0), [1.0, 100.0])
    assert curve.extent[-1] > contact_bem.HALF_SPACE_LIMIT * r > curve.extent[0]


def test_angle_power_law_row():
    K_b = float(bending_stiffness(R, r, E, nu))
    row = contact_angle.angle_power_law(R, r, E, nu, np.radians(60.0), K_b, window=(1.0, 100.0), n_forces=5)
    _K_ref, n_ref = fit_power_law(K_c=hertz_stiffness(R, r, E, nu, np.radians(60.0)), K_b=K_b)
    assert row.n == pytest.approx(float(n_ref), rel=5e-3)  # 5 forces over two decades: interpolation ~1e-3
    assert row.K_c == pytest.approx(float(hertz_stiffness(R, r, E, nu, np.radians(60.0))), rel=5e-3)
    assert row.n_patches == 1 and row.max_extent_over_r > 0


def test_bad_arguments():
    with pytest.raises(ValueError, match="frame"):
        contact_curve(R, r, E, nu, 1.0, [1.0], frame="normal")
    with pytest.raises(ValueError, match="forces"):
        contact_curve(R, r, E, nu, 1.0, [0.0, 1.0])
    with pytest.raises(ValueError, match="sides of the tubes"):
        contact_curve(R, r, E, nu, np.radians(10.0), [1.0])
    with pytest.raises(ValueError, match="R must exceed 2 r"):
        contact_curve(2 * r, r, E, nu, 1.0, [1.0])
    assert contact_modulus(E, nu) > 0


# -- issue 24, item 14: no forces, tiny forces ------------------------------------------------------


def test_no_forces_is_refused_by_name():
    with pytest.raises(ValueError, match=r"forces must hold at least one force \(N\), got none"):
        contact_curve(R, r, E, nu, np.pi / 2, [])


@pytest.mark.parametrize("force", [1e-8, 1e-10])
def test_tiny_forces_agree_with_hertz(force):
    # Contacts of 60 nm and less: the window search once marched in steps of 0.9 r/400 (5.6 um), sized the
    # grid coarser than the contact, and the solver reached its iteration limit.
    curve = contact_curve(R, r, E, nu, np.pi / 2, [force])
    K_c = float(hertz_stiffness(R, r, E, nu))
    # As at small load above: 0.2 % from the grid (16 pixels across), 0.3 % allowed (measured 0.16 %).
    assert curve.force == pytest.approx(K_c * curve.delta**1.5, rel=0.003)


def test_forces_below_the_gap_resolution_are_refused():
    # At 1e-16 N the approach (2.5e-17 m) is the rounding of the gap (about 1e-17 m at R - r = 20 mm): the
    # "contact" found is rounding noise (9 patches, 140 % off Hertz). Refused, naming the smallest force.
    with pytest.raises(ValueError, match=r"forces must be at least [0-9.e-]+ N for these rings"):
        contact_curve(R, r, E, nu, np.pi / 2, [1e-16, 1.0])
