"""Contacts of two tori in any pose (numerics/rings_contact.py, numerics/rings_kernels.py), each against an
independent computation: dense sampling of both centre circles, the theory of the interlocked crossing
(:func:`ringchain.theory.contact_patches`), a count of piercings and the Gauss integral, Newton's third law."""

from __future__ import annotations

import numpy as np
import pytest
from ringchain.numerics.contact.tori import candidate_pairs, linking_number, torus_contacts
from ringchain.numerics.engine import rings_kernels as rk
from ringchain.numerics.engine import rings_law as rl
from ringchain.theory import (
    Ring,
    contact,
    contact_modulus,
    contact_patches,
    elliptical_factor_grid,
    hertz_stiffness,
    hertz_stiffness_curvatures,
    minimum_contact_angle,
)
from scipy.spatial.transform import Rotation

R, r = 22.5e-3, 2.5e-3  # the paper's rings (R/r = 9)
RING = Ring(R, r)
IDENTITY = np.array([1.0, 0.0, 0.0, 0.0])


def quaternion(rotation: Rotation) -> np.ndarray:
    """(w, x, y, z) of a SciPy rotation (which stores x, y, z, w)."""
    x, y, z, w = rotation.as_quat()
    return np.array([w, x, y, z])


def about(axis, angle) -> Rotation:
    return Rotation.from_rotvec(np.asarray(axis, float) / np.linalg.norm(axis) * angle)


class Torus:
    """Radii R and r (what torus_contacts reads from a ring)."""

    def __init__(self, R, r):
        self.R, self.r = R, r


def circle(centre, rotation: Rotation, radius, n):
    """n points of a centre circle in space, at s = 2 pi k/n (SciPy's rotation, not the kernels')."""
    s = 2 * np.pi * np.arange(n) / n
    body = radius * np.column_stack([np.cos(s), np.sin(s), np.zeros(n)])
    return np.asarray(centre) + rotation.apply(body)


def dense_profile(c1, rot1, R1, c2, rot2, R2, n=3000):
    """f(s_1) = min over n samples of circle 2 of the distance from circle 1's n samples."""
    p1, p2 = circle(c1, rot1, R1, n), circle(c2, rot2, R2, n)
    f = np.empty(n)
    for start in range(0, n, 500):
        block = p1[start : start + 500]
        f[start : start + 500] = np.sqrt(((block[:, None, :] - p2[None, :, :]) ** 2).sum(-1).min(axis=1))
    return f


# -- the gap against dense sampling of both circles ------------------------------------------------------------
def random_pairs(seed, count):
    """Random poses of two tori of varied radii: every other pair threaded (circle 2's disc pierced by circle 1
    at a random point, so usually linked), the others placed at random with overlapping bounding spheres."""
    rng = np.random.default_rng(seed)
    for k in range(count):
        R1, R2 = rng.uniform(10e-3, 30e-3, 2)
        r1, r2 = R1 / rng.uniform(3.0, 12.0), R2 / rng.uniform(3.0, 12.0)
        rot1, rot2 = Rotation.random(random_state=rng), Rotation.random(random_state=rng)
        if k % 2:
            point = circle(np.zeros(3), rot1, R1, 64)[rng.integers(64)]  # on circle 1
            in_plane = rot2.apply([np.cos(a := rng.uniform(0, 2 * np.pi)), np.sin(a), 0.0])
            c2 = point - rng.uniform(0.2, 0.9) * R2 * in_plane
        else:
            c2 = rng.normal(size=3)
            c2 *= rng.uniform(0.2, 1.2) * (R1 + R2) / np.linalg.norm(c2)
        yield (R1, r1, rot1), (R2, r2, rot2), c2


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_gap_of_random_pairs_matches_dense_sampling(seed):
    linked = unlinked = 0
    for (R1, r1, rot1), (R2, r2, rot2), c2 in random_pairs(seed, 12):
        c1 = np.zeros(3)
        contacts = torus_contacts(
            c1, quaternion(rot1), Torus(R1, r1), c2, quaternion(rot2), Torus(R2, r2), margin=np.inf
        )
        n = 3000
        f = dense_profile(c1, rot1, R1, c2, rot2, R2, n)
        # Resolution of the sampling: a sample of each circle lies within half a spacing (R pi/n of arc) of the
        # minimiser; the distance grows from its minimum at most by (1/R + 1/f) times the squared arcs (its second
        # derivative along each circle), and never faster than the arcs themselves (slope <= 1): the sampled
        # minimum exceeds the true one by at most the smaller of the two.
        arcs = np.array([R1 * np.pi / n, R2 * np.pi / n])
        tolerance = min((1 / min(R1, R2) + 1 / f.min()) * (arcs**2).sum(), arcs.sum())
        assert contacts.distance.min() <= f.min() + 1e-15  # the search finds the global minimum ...
        assert contacts.distance.min() >= f.min() - tolerance  # ... to the sampling's resolution
        assert np.allclose(contacts.gap, contacts.distance - r1 - r2, rtol=0, atol=1e-15)
        # every minimum found is a minimum of the sampled profile (to its resolution), and none is missed:
        # the sampled profile's minima deeper than the resolution are as many
        # the sampled profile's minima: the lowest sample of the 41 about it (minima of the scalloped sampled
        # profile closer than 20 samples, 2.4 deg, are one minimum spread by the sampling of circle 2)
        window = np.lib.stride_tricks.sliding_window_view(np.r_[f[-20:], f, f[:20]], 41)
        sampled_minima = np.flatnonzero((f == window.min(axis=1)) & (f < np.roll(f, 1)))
        for s1, d in zip(contacts.s_1, contacts.distance, strict=True):
            k = round(float(s1) / (2 * np.pi / n)) % n
            window = f[np.arange(k - 3, k + 4) % n]
            assert d <= window.min() + 1e-15 and d >= window.min() - tolerance
        assert len(contacts) == len(sampled_minima)
        if linking_number(c1, quaternion(rot1), R1, c2, quaternion(rot2), R2):
            linked += 1
        else:
            unlinked += 1
    assert linked >= 2 and unlinked >= 2  # both kinds were drawn


# -- the interlocked crossing against the theory of two equal tori ----------------------------------------------
def crossing(theta, distance=2 * (R - r)):
    """Ring 1 in the xz plane at the origin; ring 2 the same turned by theta about the chain axis z, at z = distance."""
    plane = about([1, 0, 0], -np.pi / 2)  # body z (the ring's axis) to -y: the ring in the xz plane
    return (np.zeros(3), quaternion(plane), np.array([0.0, 0.0, distance]), quaternion(about([0, 0, 1], theta) * plane))


@pytest.mark.parametrize("degrees", [90.0, 60.0, 45.0])
def test_one_contact_above_theta_min_at_the_inner_equators(degrees):
    theta = np.radians(degrees)
    c1, q1, c2, q2 = crossing(theta)
    contacts = torus_contacts(c1, q1, RING, c2, q2, RING, margin=np.inf)
    assert len(contacts) == 1
    # App. A: touching at the spacing 2(R - r), at (0, 0, R - r), normal along the chain axis; both tubes
    # convex across (1/r), concave along (-1/(R - r)), their tangents at the contact angle theta
    assert abs(contacts.gap[0]) < 1e-17  # rounding of R - r and 2(R - r), a few 1e-18 m
    # s converges to 1e-13 rad (the refinement's stopping step): the point to R 1e-13, a few 1e-15 m
    assert np.allclose(contacts.point[0], [0, 0, R - r], rtol=0, atol=1e-14)
    # from ring 2 to ring 1: ring 2's lower tube, through ring 1's hole, lies under ring 1's upper tube
    assert np.allclose(contacts.normal[0], [0, 0, 1], rtol=0, atol=1e-9)
    for curvatures in (contacts.curvatures_1[0], contacts.curvatures_2[0]):
        assert np.allclose(curvatures, [-1 / (R - r), 1 / r], rtol=1e-9)
    assert contacts.angle[0] == pytest.approx(theta, abs=1e-9)


@pytest.mark.parametrize("below", [2.0, 5.0, 10.0])
def test_two_contacts_below_theta_min_where_the_theory_puts_them(below):
    theta = float(minimum_contact_angle(R, r)) - np.radians(below)
    contacts = torus_contacts(*crossing(theta)[:2], RING, *crossing(theta)[2:], RING, margin=0.0)
    assert len(contacts) == 2
    # contact_patches: the tori overlap at the spacing 2(R - r) and first touch at 2(R - r) + gap (gap < 0), at
    # +-c from the axis, their normal tilted from it by ``tilt``
    c, gap, tilt = (float(x) for x in contact_patches(R, r, theta))
    c1, q1, c2, q2 = crossing(theta, 2 * (R - r) + gap)
    touching = torus_contacts(c1, q1, RING, c2, q2, RING, margin=np.inf)
    assert len(touching) == 2
    # the theory's gap is exact to its own rounding (1e-18 m of a 1e-4 m gap); the touching contacts have
    # zero gap to the rounding of the centres, well below 1e-15 m
    assert np.allclose(touching.gap, 0.0, rtol=0, atol=1e-15)
    assert np.allclose(np.hypot(touching.point[:, 0], touching.point[:, 1]), c, rtol=1e-9)
    assert np.allclose(np.arccos(np.abs(touching.normal[:, 2])), tilt, rtol=1e-9)


@pytest.mark.parametrize("below", [0.001, 0.01, 0.3, 0.5, 1.2])
def test_both_contacts_are_found_close_to_theta_min(below):
    # module notes of rings_contact: the coarse scan (64 samples) separates the two minima from about 1 deg below
    # theta_min; closer, the inflection next to the minimum found triggers a finer look that finds its twin
    theta = float(minimum_contact_angle(R, r)) - np.radians(below)
    contacts = torus_contacts(*crossing(theta)[:2], RING, *crossing(theta)[2:], RING, margin=np.inf)
    assert len(contacts) == 2
    # the two are images of each other under the half turn about the chain axis z, which maps both rings onto
    # themselves: equal gaps, points (x, y, z) and (-x, -y, z).  The gaps to their rounding (a few 1e-18 m); the
    # points to where the flat minima put s_1: g'' -> 0 near theta_min, and the rounding of g' (1e-16 R^2) over
    # g'' moves the root, by 2e-13 m at 0.001 deg (measured), within 1e-6 of the points' distance from the axis
    assert contacts.gap[0] == pytest.approx(contacts.gap[1], rel=0, abs=1e-17)
    off_axis = np.hypot(*contacts.point[0, :2])
    assert off_axis > 1e-5  # two points, not one found twice
    assert np.allclose(contacts.point[0, :2], -contacts.point[1, :2], rtol=0, atol=1e-6 * off_axis)
    assert contacts.point[0, 2] == pytest.approx(contacts.point[1, 2], abs=1e-14)


# -- twin minima that the coarse scan's samples straddle --------------------------------------------------------------
#: Two neighbours of a 30 x 30 sheet of chain mail (R/r = 9) where its static solver once stopped: the distance of
#: their centre circles has twin minima 0.043 r and 0.040 r deep on either side of a maximum 0.039 r deep, the second
#: 0.88 of the scan's spacing beyond the maximum (centres in m; quaternions (w, x, y, z)).
TWIN_POSE = (
    np.array([0.08070779461969348, 0.00328759901605863, 0.5876193261228208]),
    np.array([0.6655839647893028, -0.7312985065081204, -0.11201527343726425, 0.09824998071816356]),
    np.array([0.06478191591641538, 0.00336219282038628, 0.6243902440075156]),
    np.array([0.70895128706511, -0.6693207891535885, 0.01868054284744149, -0.22146961663954376]),
)


def sampled_minima(c1, rot1, R1, c2, rot2, R2, n=2**16):
    """The local minima (s_1, distance) of the distance from circle 1 to circle 2: 2^16 samples of circle 1 (the
    nearest point of circle 2 in closed form, the point's projection on its plane scaled to R2), each sampled minimum
    refined by SciPy's ``brentq`` on the distance's derivative within a sample each side."""
    from scipy.optimize import brentq

    def point(s):  # circle 1 in ring 2's frame, and its derivative in s
        s = np.atleast_1d(s)
        body = R1 * np.column_stack([np.cos(s), np.sin(s), np.zeros_like(s)])
        tangent = R1 * np.column_stack([-np.sin(s), np.cos(s), np.zeros_like(s)])
        return rot2.inv().apply(np.asarray(c1) + rot1.apply(body) - c2), rot2.inv().apply(rot1.apply(tangent))

    def distance(s):
        p, _ = point(s)
        return np.hypot(np.hypot(p[:, 0], p[:, 1]) - R2, p[:, 2])

    def slope(s):  # d(distance^2/2)/ds
        p, dp = point(s)
        rho = np.hypot(p[:, 0], p[:, 1])
        return ((rho - R2) * (p[:, 0] * dp[:, 0] + p[:, 1] * dp[:, 1]) / rho + p[:, 2] * dp[:, 2])[0]

    s = 2 * np.pi * np.arange(n) / n
    f = distance(s)
    step = 2 * np.pi / n
    found = []
    for i in np.flatnonzero((f < np.roll(f, 1)) & (f <= np.roll(f, -1))):
        root = brentq(slope, s[i] - step, s[i] + step, xtol=1e-15, rtol=1e-15)
        found.append((root % (2 * np.pi), distance(root)[0]))
    return np.array(sorted(found))


@pytest.mark.parametrize("turn", [0.0, 0.25, 0.5, 0.75, 1.0 - 1e-3])
def test_twin_minima_between_two_samples_are_both_found(turn):
    # the stuck pair, ring 1 turned about its own axis by a fraction of the scan's spacing h: the samples fall at
    # every phase of the profile (turn 0: the maximum and the second minimum between two samples, g' > 0 at both)
    c1, q1, c2, q2 = TWIN_POSE
    h = 2 * np.pi / rk.N_SCAN
    rot1 = Rotation.from_quat(np.r_[q1[1:], q1[0]]) * about([0, 0, 1], turn * h)
    rot2 = Rotation.from_quat(np.r_[q2[1:], q2[0]])
    contacts = torus_contacts(c1, quaternion(rot1), RING, c2, q2, RING, margin=np.inf)
    expected = sampled_minima(c1, rot1, R, c2, rot2, R)
    assert len(expected) == 2  # the twins (the independent count)
    assert len(contacts) == len(expected)
    order = np.argsort(contacts.s_1)
    # the angles: the kernel's refinement stops at steps below 1e-13 rad, brentq at 1e-15 (8e-15 rad apart, measured);
    # the distances to the rounding of the centres, 0.6 m from the origin (1.1e-16 m a unit in the last place)
    assert np.allclose(contacts.s_1[order], expected[:, 0], rtol=0, atol=1e-12)
    assert np.allclose(contacts.distance[order], expected[:, 1], rtol=0, atol=1e-15)


#: Two more pairs of that sheet, in another pose, where a minimum and the maximum after it fall between two samples
#: (g' < 0 at both, the cubic model of g' there with a negative leading coefficient): in the first the hidden minimum
#: lies 0.013 r apart and the other 0.005 r in overlap; in the second both lie 4.4 r apart.
MIN_THEN_MAX_POSES = [
    (
        np.array([0.49130025165660457, -0.00018933500037956208, -0.14872626410184117]),
        np.array([0.6996013068889742, -0.6934750031665781, -0.12414826766771271, 0.1193215781720151]),
        np.array([0.47826633569255067, -0.00011757263842218032, -0.11132213105439388]),
        np.array([0.6938059932423045, -0.6980608422135318, 0.12307003592982618, -0.12727164085304085]),
    ),
    (
        np.array([0.623626867169433, -0.0011670125413987256, 0.18316533793120965]),
        np.array([0.6829132329589671, -0.7083482918764797, 0.1281378436131849, -0.1243097207758428]),
        np.array([0.6704880531709142, -0.0014860846230293678, 0.17979810987347283]),
        np.array([0.6801261155784489, -0.7119099296296991, 0.11926817027840073, -0.12801493100904213]),
    ),
]


@pytest.mark.parametrize("pose", MIN_THEN_MAX_POSES, ids=["touching", "apart"])
def test_a_minimum_and_the_maximum_after_it_between_two_samples_are_found(pose):
    c1, q1, c2, q2 = pose
    contacts = torus_contacts(c1, q1, RING, c2, q2, RING, margin=np.inf)
    rot1, rot2 = (Rotation.from_quat(np.r_[q[1:], q[0]]) for q in (q1, q2))
    expected = sampled_minima(c1, rot1, R, c2, rot2, R)
    assert len(expected) == 2  # the independent count
    assert len(contacts) == len(expected)
    order = np.argsort(contacts.s_1)
    # as for the twins above: the refinement's and brentq's tolerances; the rounding of the centres
    assert np.allclose(contacts.s_1[order], expected[:, 0], rtol=0, atol=1e-12)
    assert np.allclose(contacts.distance[order], expected[:, 1], rtol=0, atol=1e-15)


def test_warm_start_hands_the_straddled_twin_to_the_cold_search():
    c1, q1, c2, q2 = TWIN_POSE
    cold = np.empty((rk.MAX_CONTACTS, rk.FIELDS))
    rows, _ = rk.pair_contacts(c1, q1, R, r, c2, q2, R, r, rk.N_SCAN, cold)
    assert rows == 2
    first = np.argmin(cold[:rows, 1])  # the minimum that the scan brackets; its twin lies between two samples
    warm = np.empty_like(cold)
    # following only the first: a maximum 1.35 h from it with no minimum followed beyond, so the cold search runs
    rows_warm, _, fell_back = rk.pair_contacts_warm(c1, q1, R, r, c2, q2, R, r, rk.N_SCAN, cold[[first], 1].copy(), 1,
                                                    6, warm)  # fmt: skip
    assert (rows_warm, fell_back) == (2, 1)
    assert np.array_equal(warm[:2], cold[:2])  # the same search
    # following both (the second lies 0.88 h from the maximum, an inflection within h/2 of it: the cold search runs
    # again, as before), the same two minima to the refinement's tolerance (s to 1e-12 rad; the gap stationary there)
    rows_warm, _, _ = rk.pair_contacts_warm(c1, q1, R, r, c2, q2, R, r, rk.N_SCAN, cold[:2, 1].copy(), 2, 6, warm)
    assert rows_warm == 2
    assert np.allclose(warm[:2, :15], cold[:2, :15], rtol=0, atol=1e-9)


# -- rings resting on one another; symmetric poses ----------------------------------------------------------------
def test_ring_resting_across_an_unlinked_one():
    # ring 2 upright in the xz plane, standing on the top of ring 1's tube (ring 1 flat in the xy plane)
    R2, r2 = 15e-3, 2e-3
    upright = quaternion(about([1, 0, 0], np.pi / 2))
    c2 = np.array([R, 0.0, R2 + r + r2])
    contacts = torus_contacts(np.zeros(3), IDENTITY, RING, c2, upright, Torus(R2, r2), margin=1e-12)
    assert len(contacts) == 1
    assert abs(contacts.gap[0]) < 1e-17  # rounding of the height, a few 1e-18 m
    assert np.allclose(contacts.point[0], [R, 0, r], rtol=0, atol=1e-15)
    assert np.allclose(contacts.normal[0], [0, 0, -1], rtol=0, atol=1e-12)  # from ring 2 (above) to ring 1
    # top of tube 1 (flat along the tube), bottom of ring 2's outer equator (convex, 1/(R2 + r2))
    assert np.allclose(contacts.curvatures_1[0], [0.0, 1 / r], rtol=1e-12, atol=1e-9)
    assert np.allclose(contacts.curvatures_2[0], [1 / (R2 + r2), 1 / r2], rtol=1e-12)
    assert contacts.angle[0] == pytest.approx(np.pi / 2, abs=1e-12)


def test_ring_lying_across_another_touches_at_both_crossings():
    c2 = np.array([R, 0.0, 2 * r * (1 - 1e-6)])  # flat on ring 1, its circle crossing ring 1's twice
    contacts = torus_contacts(np.zeros(3), IDENTITY, RING, c2, IDENTITY, RING, margin=0.0)
    assert len(contacts) == 2
    # the circles cross, seen from above, where both are at distance R from their centres: x = R/2
    assert np.allclose(contacts.point[:, 0], R / 2, rtol=1e-9)
    assert np.allclose(np.sort(contacts.point[:, 1]), [-R * np.sqrt(3) / 2, R * np.sqrt(3) / 2], rtol=1e-9)
    assert np.allclose(contacts.gap, -2e-6 * r, rtol=1e-6)


@pytest.mark.parametrize(
    "c2, R2",
    [([0.0, 0.0, 2 * r * (1 - 1e-6)], R), ([0.0, 0.0, 0.0], R + 2 * r * (1 - 1e-6))],
    ids=["stacked", "concentric"],
)
def test_coaxial_rings_touch_along_a_circle(c2, R2):
    contacts = torus_contacts(np.zeros(3), IDENTITY, RING, c2, about_z(0.3), Torus(R2, r), margin=0.0)
    assert contacts.line and len(contacts) == rk.LINE_POINTS
    assert np.allclose(contacts.gap, -2e-6 * r, rtol=1e-6)


def about_z(angle):
    return quaternion(about([0, 0, 1], angle))


def test_coaxial_rings_apart_have_no_contact():
    assert len(torus_contacts(np.zeros(3), IDENTITY, RING, [0, 0, 3 * r], IDENTITY, RING)) == 0


def test_coplanar_rings_side_by_side():
    c2 = np.array([2 * (R + r) * (1 - 1e-9), 0.0, 0.0])  # outer equators touching
    contacts = torus_contacts(np.zeros(3), IDENTITY, RING, c2, about_z(1.0), RING, margin=0.0)
    assert len(contacts) == 1
    assert np.allclose(contacts.normal[0], [-1, 0, 0], rtol=0, atol=1e-12)
    assert contacts.angle[0] == pytest.approx(0.0, abs=1e-6)  # parallel tangents (arccos near 1: sqrt of rounding)
    assert np.allclose(contacts.curvatures_1[0], [1 / (R + r), 1 / r], rtol=1e-12)


def test_no_spurious_contact_where_circle_1_crosses_the_axis_of_circle_2():
    # circle 1 (upright, xz plane, centre (R1, 0, 0)) passes through the centre of ring 2 (flat, at the origin):
    # there the nearest point of circle 2 is undefined and the distance has a cusp (a maximum); the sample
    # s_1 = pi falls exactly on it
    R1 = 12e-3
    q1 = quaternion(about([1, 0, 0], np.pi / 2))
    c1 = np.array([R1, 0.0, 0.0])
    contacts = torus_contacts(c1, q1, Torus(R1, 1e-3), np.zeros(3), IDENTITY, RING, margin=np.inf)
    f = dense_profile(c1, Rotation.from_quat(np.r_[q1[1:], q1[0]]), R1, np.zeros(3), Rotation.identity(), R)
    is_min = (f < np.roll(f, 1)) & (f <= np.roll(f, -1))
    assert len(contacts) == is_min.sum()
    assert np.all(np.abs(contacts.s_1 - np.pi) > 0.1)  # none at the cusp


# -- warm start ------------------------------------------------------------------------------------------------------
def test_warm_start_follows_the_minima_and_agrees_with_the_cold_search():
    theta = np.radians(70)
    c1, q1, c2, q2 = crossing(theta)
    out = np.empty((rk.MAX_CONTACTS, rk.FIELDS))
    rows, _ = rk.pair_contacts(c1, q1, R, r, c2, q2, R, r, rk.N_SCAN, out)
    previous = out[:rows, 1].copy()
    turned = quaternion(about([0.3, 1.0, 0.2], 2e-3) * Rotation.from_quat(np.r_[q2[1:], q2[0]]))
    warm = np.empty_like(out)
    rows_warm, iterations, fell_back = rk.pair_contacts_warm(c1, q1, R, r, c2 + 1e-6, turned, R, r, rk.N_SCAN,
                                                             previous, rows, 6, warm)  # fmt: skip
    cold = np.empty_like(out)
    rows_cold, _ = rk.pair_contacts(c1, q1, R, r, c2 + 1e-6, turned, R, r, rk.N_SCAN, cold)
    assert (rows_warm, fell_back) == (rows_cold, 0)
    assert iterations <= 4
    # both converge to the same minimum: s to 1e-12 rad moves the gap by less than R s^2
    assert np.allclose(warm[:rows_warm, :15], cold[:rows_cold, :15], rtol=0, atol=1e-9)
    assert abs(warm[0, 0] - cold[0, 0]) < 1e-17


def test_following_a_minimum_between_searches_errs_to_second_order():
    c1, q1, c2, q2 = crossing(np.radians(70), 2 * (R - r) + 1e-6)
    out = np.empty((rk.MAX_CONTACTS, rk.FIELDS))
    rows, _ = rk.pair_contacts(c1, q1, R, r, c2, q2, R, r, rk.N_SCAN, out)
    previous = out[:rows, 1].copy()
    turned = quaternion(about([0.3, 1.0, 0.2], 1e-3) * Rotation.from_quat(np.r_[q2[1:], q2[0]]))
    converged = np.empty_like(out)
    rk.pair_contacts(c1, q1, R, r, c2, turned, R, r, rk.N_SCAN, converged)
    moved = abs(converged[0, 1] - previous[0])
    followed = np.empty_like(out)
    assert rk.pair_contacts_follow(c1, q1, R, r, c2, turned, R, r, previous, rows, 0, followed) == 1
    # at the old angle: the distance of the circles is stationary at its minimum, so the gap is larger by about
    # f'' ds^2/2, f'' = R^2 g''/f at most of the order R^2/f (1/m), ds the minimum's move
    excess = followed[0, 0] - converged[0, 0]
    assert 0 <= excess <= R**2 / converged[0, 14] * moved**2
    # one Newton step: quadratic convergence leaves ds^2 of angle, its square of gap: rounding
    assert rk.pair_contacts_follow(c1, q1, R, r, c2, turned, R, r, previous, rows, 1, followed) == 1
    assert abs(followed[0, 0] - converged[0, 0]) < 1e-17


def test_warm_start_falls_back_when_the_contact_splits():
    theta_min = float(minimum_contact_angle(R, r))
    c1, q1, c2, q2 = crossing(theta_min + np.radians(1))
    out = np.empty((rk.MAX_CONTACTS, rk.FIELDS))
    rows, _ = rk.pair_contacts(c1, q1, R, r, c2, q2, R, r, rk.N_SCAN, out)
    _, _, c2, q2 = crossing(theta_min - np.radians(5))
    rows_warm, _, fell_back = rk.pair_contacts_warm(c1, q1, R, r, c2, q2, R, r, rk.N_SCAN, out[:rows, 1].copy(),
                                                    rows, 6, out)  # fmt: skip
    assert (rows, rows_warm, fell_back) == (1, 2, 1)


# -- broad phase and linking --------------------------------------------------------------------------------------
def test_candidate_pairs_against_all_pairs():
    rng = np.random.default_rng(5)
    centres = rng.uniform(0, 0.3, (200, 3))
    radii = rng.uniform(0.01, 0.03, 200)
    skin = 0.004
    pairs = candidate_pairs(centres, radii, skin=skin)
    i, j = np.triu_indices(200, 1)
    near = np.linalg.norm(centres[i] - centres[j], axis=1) <= radii[i] + radii[j] + skin
    assert np.array_equal(pairs, np.column_stack([i[near], j[near]]))


def piercings(c1, rot1, R1, c2, rot2, R2, n=20000):
    """Signed count of the segments of a 20000-gon of circle 2 crossing the disc of circle 1."""
    p = rot1.inv().apply(circle(c2, rot2, R2, n) - c1)  # in ring 1's frame
    q = np.roll(p, -1, axis=0)
    cross = np.sign(p[:, 2]) != np.sign(q[:, 2])
    t = p[cross, 2] / (p[cross, 2] - q[cross, 2])
    at = p[cross, :2] + t[:, None] * (q[cross, :2] - p[cross, :2])
    inside = np.hypot(at[:, 0], at[:, 1]) < R1
    return int(np.sum(np.sign(q[cross, 2] - p[cross, 2])[inside]))


def gauss_integral(c1, rot1, R1, c2, rot2, R2, n=400):
    """(1/4 pi) double integral of (x1 - x2) . (dx1 x dx2)/|x1 - x2|^3 by the trapezoid rule."""
    s = 2 * np.pi * np.arange(n) / n
    x1, x2 = circle(c1, rot1, R1, n), circle(c2, rot2, R2, n)
    d1 = rot1.apply(R1 * np.column_stack([-np.sin(s), np.cos(s), 0 * s]))
    d2 = rot2.apply(R2 * np.column_stack([-np.sin(s), np.cos(s), 0 * s]))
    diff = x1[:, None] - x2[None]
    integrand = np.einsum("ijk,ijk->ij", diff, np.cross(d1[:, None], d2[None])) / np.linalg.norm(diff, axis=-1) ** 3
    return integrand.sum() * (2 * np.pi / n) ** 2 / (4 * np.pi)


def test_linking_number_against_piercings_and_the_gauss_integral():
    rng = np.random.default_rng(11)
    seen = set()
    for _ in range(40):
        R1, R2 = rng.uniform(10e-3, 30e-3, 2)
        rot1, rot2 = Rotation.random(random_state=rng), Rotation.random(random_state=rng)
        c1, c2 = rng.normal(size=3) * 0.01, rng.normal(size=3) * 0.015
        number = linking_number(c1, quaternion(rot1), R1, c2, quaternion(rot2), Torus(R2, 1e-3))
        assert number == piercings(c1, rot1, R1, c2, rot2, R2)
        # the Gauss integral converges exponentially for circles apart; 0.05 is far from rounding to the wrong integer
        gauss = gauss_integral(c1, rot1, R1, c2, rot2, R2)
        assert abs(gauss - number) < 0.05 or dense_profile(c1, rot1, R1, c2, rot2, R2, 400).min() < 2e-3
        seen.add(number)
    assert seen == {-1, 0, 1}


def test_linking_number_of_the_crossing_and_of_rings_apart():
    c1, q1, c2, q2 = crossing(np.pi / 2)
    assert abs(linking_number(c1, q1, RING, c2, q2, RING)) == 1
    assert linking_number(c1, q1, RING, c2 + np.array([0, 0, 2 * R]), q2, RING) == 0


# -- validation -------------------------------------------------------------------------------------------------------
def test_bad_inputs_are_refused_with_their_units():
    with pytest.raises(ValueError, match="quaternion"):
        torus_contacts(np.zeros(3), [0, 0, 0, 0], RING, [0, 0, 1], IDENTITY, RING)
    with pytest.raises(ValueError, match="in m"):
        torus_contacts([0, 0], IDENTITY, RING, [0, 0, 1], IDENTITY, RING)
    with pytest.raises(ValueError, match=r"r must lie in \(0, R\)"):
        torus_contacts(np.zeros(3), IDENTITY, Torus(1e-3, 2e-3), [0, 0, 1], IDENTITY, RING)
    with pytest.raises(ValueError, match="n_scan"):
        torus_contacts(np.zeros(3), IDENTITY, RING, [0, 0, 1], IDENTITY, RING, n_scan=4)
    with pytest.raises(ValueError, match="skin"):
        candidate_pairs(np.zeros((2, 3)), 1.0, skin=-1.0)


# -- the contact law -------------------------------------------------------------------------------------------------
STEEL = (193e9, 0.29)
#: The table as the rings' packing hands it to the kernels: a writable copy (a read-only one compiles them again).
GRID = (np.array(elliptical_factor_grid()[0]), elliptical_factor_grid()[1])
#: The grid's cubic interpolation (tests/theory/test_rigid.py): 5e-12 of K_c.
GRID_TOLERANCE = 5e-12


def test_compiled_stiffness_equals_the_theory_function():
    rng = np.random.default_rng(8)
    E_star = float(contact_modulus(*STEEL))
    for _ in range(200):
        k1a, k2a = rng.uniform(-60, 200, 2)
        k1b, k2b = rng.uniform(100, 600, 2)
        angle = rng.uniform(0, np.pi / 2)
        try:
            expected = float(hertz_stiffness_curvatures(k1a, k1b, k2a, k2b, angle, *STEEL, *STEEL))
        except ValueError:  # A <= 0: no single Hertz ellipse
            continue
        K_c = rl.hertz_stiffness_curvatures(k1a, k1b, k2a, k2b, np.cos(angle), E_star, 690.0, *GRID)
        assert K_c == pytest.approx(expected, rel=1e-13)  # the same arithmetic in another order: rounding


@pytest.mark.parametrize("degrees", [90.0, 60.0])
def test_stiffness_at_a_found_crossing_is_hertz_stiffness(degrees):
    theta = np.radians(degrees)
    c1, q1, c2, q2 = crossing(theta)
    contacts = torus_contacts(c1, q1, RING, c2, q2, RING, margin=np.inf)
    row = contacts.rows[0]
    K_c = rl.hertz_stiffness_curvatures(*row[9:14], float(contact_modulus(*STEEL)), 690.0, *GRID)
    # the table's resolution, and the curvatures of the found minimum: s to 1e-13 rad changes cos(phi) by its
    # square, and the tangents' angle by 1e-13 rad
    assert K_c == pytest.approx(float(hertz_stiffness(R, r, *STEEL, theta)), rel=GRID_TOLERANCE + 1e-12)


def reference_force(row, c1, v1, w1, c2, v2, w2, K, n, gamma, mu, v_reg):
    """The law of rings_law.contact_force in NumPy, written from its documentation."""
    delta = -row[0]
    point, normal = row[3:6], row[6:9]
    if delta <= 0:
        return np.zeros(3), np.zeros(3), np.zeros(3), 0.0, 0.0, 0.0, 0.0
    slip_velocity = (v1 + np.cross(w1, point - c1)) - (v2 + np.cross(w2, point - c2))
    approach_rate = -slip_velocity @ normal
    elastic = K * delta**n
    F_n = max(elastic + gamma * approach_rate, 0.0)
    slip = slip_velocity - (slip_velocity @ normal) * normal
    friction = -mu * F_n * slip / np.sqrt(slip @ slip + v_reg**2)
    F = F_n * normal + friction
    return (F, np.cross(point - c1, F), np.cross(point - c2, -F), F_n, K * delta ** (n + 1) / (n + 1),
            (F_n - elastic) * approach_rate, -friction @ slip)  # fmt: skip


@pytest.mark.parametrize("mu", [0.0, 0.3])
def test_contact_force_against_the_numpy_reference_and_its_invariants(mu):
    rng = np.random.default_rng(21)
    law = np.array([1.0, 3e9, 1.3, 40.0, mu, 1e-3, 0.0])  # the power law of Eq. (4), dashpot, friction
    c1, q1, c2, q2 = crossing(np.radians(70), 2 * (R - r) + 3e-6)  # rings pulled 3 um apart: overlap
    contacts = torus_contacts(c1, q1, RING, c2, q2, RING)
    (row,) = contacts.rows
    force, torque_1, torque_2 = np.empty(3), np.empty(3), np.empty(3)
    for _ in range(20):
        v1, w1, v2, w2 = rng.normal(size=(4, 3)) * [[0.1], [5.0], [0.1], [5.0]]
        out = rl.contact_force(row, c1, v1, w1, c2, v2, w2, law, *GRID, force, torque_1, torque_2)
        F, T1, T2, F_n, energy, dashpot, friction = reference_force(
            row, c1, v1, w1, c2, v2, w2, 3e9, 1.3, 40.0, mu, 1e-3
        )
        scale = np.abs(F).max()
        assert np.allclose(force, F, rtol=0, atol=1e-13 * scale)  # rounding
        assert np.allclose(torque_1, T1, rtol=0, atol=1e-13 * scale * R)
        assert np.allclose(torque_2, T2, rtol=0, atol=1e-13 * scale * R)
        assert out == pytest.approx((F_n, energy, dashpot, friction), rel=1e-12, abs=1e-18)
        # invariants: ring 2 gets -F at the same point, so the torques about the origin cancel
        total = torque_1 + np.cross(c1, force) + torque_2 + np.cross(c2, -force)
        assert np.allclose(total, 0.0, rtol=0, atol=1e-13 * scale * R)
        # the friction power is minus the tangential force times the slip velocity, and >= 0
        tangential = force - (force @ row[6:9]) * row[6:9]
        slip_velocity = (v1 + np.cross(w1, row[3:6] - c1)) - (v2 + np.cross(w2, row[3:6] - c2))
        assert out[3] == pytest.approx(-tangential @ slip_velocity, rel=1e-12, abs=1e-18) and out[3] >= 0


@pytest.mark.parametrize("quartic", [None, 1.0 / (4 * R * r * (R - r))], ids=["row of 7", "row with a quartic"])
def test_contact_force_is_central_without_friction_and_zero_when_open(quartic):
    c1, q1, c2, q2 = crossing(np.pi / 2, 2 * (R - r) + 1e-6)
    (row,) = torus_contacts(c1, q1, RING, c2, q2, RING).rows
    law = [0.0, 0.0, 1.5, 0.0, 0.0, 1e-3, float(contact_modulus(*STEEL))]  # Hertz of the curvatures
    # the quartic of the fold (rings_law.fold_quartic) changes nothing here: A/sqrt(C delta) = 2e3 at a circle
    law = np.array(law if quartic is None else [*law, quartic])
    force, torque_1, torque_2 = np.empty(3), np.empty(3), np.empty(3)
    zero = np.zeros(3)
    F_n, energy, _, _ = rl.contact_force(row, c1, zero, zero, c2, zero, zero, law, *GRID, force, torque_1, torque_2)
    # Eq. (1): K_c delta^(3/2) with delta = 1 um, along the chain axis (the contact point on it: no torque)
    K_c = float(hertz_stiffness(R, r, *STEEL))
    assert F_n == pytest.approx(K_c * 1e-9, rel=1e-9)  # delta from the gap: rounding of 1e-6 m against R
    assert energy == pytest.approx(0.4 * K_c * 1e-15, rel=1e-9)
    assert np.allclose(force, [0, 0, F_n], rtol=0, atol=1e-9 * F_n)
    assert np.allclose(torque_1, 0.0, atol=1e-9 * F_n * R) and np.allclose(torque_2, 0.0, atol=1e-9 * F_n * R)
    row = row.copy()
    row[0] = 1e-9  # open
    assert rl.contact_force(row, c1, zero, zero, c2, zero, zero, law, *GRID, force, torque_1, torque_2) == (0, 0, 0, 0)
    assert not force.any()


def test_compiled_stiffness_is_capped_continuously_where_a_vanishes():
    B, cap = 400.0, 10.0
    E_star = float(contact_modulus(*STEEL))
    # at the cap: the theory's K_c of the ellipse with ln(B/A) = 10 (surface 1 with curvatures 2A, 2B on a plane)
    at_cap = float(hertz_stiffness_curvatures(2 * B * np.exp(-cap), 2 * B, 0.0, 0.0, 0.0, *STEEL, *STEEL))
    for A in (0.0, -1.0, B * np.exp(-cap) * (1 - 1e-9)):  # degenerate, beyond, and just beyond the cap
        K_c = rl.hertz_stiffness_curvatures(2 * A, 2 * B, 0.0, 0.0, 1.0, E_star, cap, *GRID)
        assert K_c == pytest.approx(at_cap, rel=GRID_TOLERANCE + 1e-9)  # the last: K_c moves by 1e-9 / 2 of A
    below = rl.hertz_stiffness_curvatures(2 * B * np.exp(-cap) * (1 + 1e-9), 2 * B, 0.0, 0.0, 1.0, E_star, cap, *GRID)
    assert below == pytest.approx(at_cap, rel=1e-8)  # continuous through the cap


# -- the law near a fold: Hertz's K of an effective curvature (rings_law.contact_stiffness) ----------------------------
def gap_law(t, B, quartic=1.0, delta=1.0, E_star=1.0):
    """(K, dK/d(delta), force, energy) of rings_law.contact_stiffness for the gap A x^2 + C x^4 + B y^2 with
    A = t sqrt(C delta): surface 1 of curvatures 2A, 2B on a plane (Hertz's sums A, B)."""
    A = t * np.sqrt(quartic * delta)
    K, dK = rl.contact_stiffness(2 * A, 2 * B, 0.0, 0.0, 1.0, E_star, quartic, delta, *GRID)
    return K, dK, K * delta**1.5 + 0.4 * dK * delta**2.5, 0.4 * K * delta**2.5


def test_fold_quartic_is_the_derivation_of_the_gap():
    from ringchain.theory.gap import fold_quartic

    expression = fold_quartic()
    R_, r_ = contact.symbols()["R"], contact.symbols()["r"]
    at = lambda R0, r0: float(expression.subs({R_: R0, r_: r0}))  # noqa: E731
    assert rl.fold_quartic(R, r, R, r) == pytest.approx(at(R, r), rel=1e-14)  # rounding
    # unequal rings: each tube's half (the stated approximation of the kernel)
    assert rl.fold_quartic(R, r, 2 * R, 3 * r) == pytest.approx((at(R, r) + at(2 * R, 3 * r)) / 2, rel=1e-14)


@pytest.mark.parametrize("degrees", [90.0, 60.0])
@pytest.mark.parametrize("approach", [1e-9, 1e-7, 1e-5])
def test_contact_stiffness_is_hertz_where_the_quartic_is_negligible(degrees, approach):
    c1, q1, c2, q2 = crossing(np.radians(degrees))
    (row,) = torus_contacts(c1, q1, RING, c2, q2, RING, margin=np.inf).rows
    E_star, quartic = float(contact_modulus(*STEEL)), rl.fold_quartic(R, r, R, r)
    hertz = rl.hertz_stiffness_curvatures(*row[9:14], E_star, 690.0, *GRID)
    K, dK = rl.contact_stiffness(*row[9:14], E_star, quartic, approach, *GRID)
    # A_eff = A (1 + w/t^2), w/t^2 ~ 28 t^-6: t = A/sqrt(C delta) >= 42 here (60 degrees, 1e-5 m = 4e-3 r), so
    # 5e-9 at most; the chapter's static pulls (50 N, 3.5e-6 m: t = 71) 2e-10
    assert K == pytest.approx(hertz, rel=1e-8)
    assert abs(dK) * approach < 1e-8 * K


def test_contact_law_is_finite_and_smooth_through_the_fold():
    ts = np.linspace(-4.0, 6.0, 4001)
    forces = np.array([gap_law(t, 100.0)[2] for t in ts])
    assert np.all(np.isfinite(forces)) and np.all(forces > 0)
    assert np.all(np.diff(forces) < 0)  # stiffer as the fold opens (A up), softer on its other side
    # continuous force and slope: the second differences of a smooth F(t) on a step of 2.5e-3 are F'' 6e-6, here
    # 9.7e-7 of F(0) at most (6.7e-7 at t = 0, where w(t) turns: C^3); a jump of the slope would stand out
    second = np.abs(np.diff(forces, 2)) / forces[np.searchsorted(ts, 0.0)]
    assert second.max() < 1e-5
    # bounded where Hertz's K_c grows without bound: F(0) of order F(t = 3), not 1e150 times it
    assert forces[np.searchsorted(ts, 0.0)] < 3 * forces[np.searchsorted(ts, 3.0)]


def test_contact_law_is_continuous_through_the_circle():
    # Two equal rings crossing at 90 degrees touch in a circle (B = A): a hanging chain's contacts sit there and a
    # sideways swing turns them through it.  The law's K and dK/d(delta) must not jump at B = A (with B held while
    # A_eff > A they did: K's second differences here 3.4e-7 of K, dK by a factor 2, and the swing's dopri5 steps
    # were rejected half the time: 1,746 of 5,039 over 0.4 s, against 3 of 616 now).
    k = np.array([-1 / (R - r), 1 / r, -1 / (R - r), 1 / r])  # along and across each tube at the inner rim
    E_star, quartic, delta = 1e7, rl.fold_quartic(R, r, R, r), 4e-4  # a soft ring's approach: t = 18
    cosines = np.linspace(-1e-3, 1e-3, 201)  # through cos = 0, the circle
    K, dK = np.array([rl.contact_stiffness(*k, c, E_star, quartic, delta, *GRID) for c in cosines]).T
    # K is even in the cosine and smooth: its second differences on this step measured 1.1e-10 of K, dK's steps
    # 6.5e-5 of it; the bounds are ten times those (the jumps above are 3,000 and 8,000 times them)
    assert np.abs(np.diff(K, 2)).max() < 1e-9 * K[100]
    assert np.abs(np.diff(dK)).max() < 1e-3 * abs(dK[100])


@pytest.mark.parametrize("t", [5.0, 1.0, 0.0, -1.0, -3.0])
def test_contact_force_is_the_derivative_of_its_energy(t):
    B, quartic, delta = 400.0, 2.2e5, 1e-6  # the paper's ring: B ~ 1/r, C of its fold
    A = t * np.sqrt(quartic * delta)

    def energy(d):
        K, _ = rl.contact_stiffness(2 * A, 2 * B, 0.0, 0.0, 1.0, 1e11, quartic, d, *GRID)
        return 0.4 * K * d**2.5

    h = 1e-5 * delta
    K, dK = rl.contact_stiffness(2 * A, 2 * B, 0.0, 0.0, 1.0, 1e11, quartic, delta, *GRID)
    force = K * delta**1.5 + 0.4 * dK * delta**2.5
    # central difference: truncation (h/delta)^2 ~ 1e-10, rounding 1e-16/1e-5 of the energy
    assert (energy(delta + h) - energy(delta - h)) / (2 * h) == pytest.approx(force, rel=1e-9)


def half_space_force(t, B, points_across=32):
    """Force (E* = 1, C = 1, delta = 1) of the half-space solver on the gap t x^2 + x^4 + B y^2: a window 1.3
    times the contact's extent (the larger root of t x^2 + x^4 = 1 along x, 1/sqrt(B) across), ``points_across``
    pixels across it along each axis."""
    from ringchain.numerics.contact.halfspace import ElasticHalfSpace

    a, b = np.sqrt((-t + np.sqrt(t * t + 4.0)) / 2.0), np.sqrt(1.0 / B)
    hx, hy = 2 * a / points_across, 2 * b / points_across
    nx, ny = 2 * int(np.ceil(1.3 * a / hx)), 2 * int(np.ceil(1.3 * b / hy))
    space = ElasticHalfSpace((nx, ny), (nx * hx, ny * hy), 1.0)
    X, Y = space.coordinates()
    return space.solve(t * X**2 + X**4 + B * Y**2, approach=1.0, pentol=1e-9, forcetol=1e-12, maxiter=20000).force


@pytest.mark.parametrize("t", [3.0, 1.0, 0.0, -0.5])
def test_contact_law_against_the_half_space_solver(t):
    # Independent: the half-space solver (boundary elements) on the quartic gap, at B/sqrt(C delta) = 300 (between
    # the values 10, 100, 1000 to which w_0 and tau were fitted).  5 per cent: the law's largest misfit over
    # t >= -0.5 in the fit, 3.6 per cent, and the solver's resolution (32 against 24 pixels: 0.3 per cent).
    assert gap_law(t, 300.0)[2] == pytest.approx(half_space_force(t, 300.0), rel=0.05)


def test_batch_of_pairs_equals_single_calls_cold_and_warm():
    rng = np.random.default_rng(4)
    centres = rng.normal(size=(6, 3)) * 0.01
    orientations = np.array([quaternion(Rotation.random(random_state=rng)) for _ in range(6)])
    radii, tubes = rng.uniform(15e-3, 25e-3, 6), np.full(6, 2e-3)
    pairs = np.array([[0, 1], [1, 2], [3, 5], [2, 4]])
    out = np.empty((4, rk.MAX_CONTACTS, rk.FIELDS))
    counts, state, stats = np.zeros(4, np.int64), np.zeros((4, rk.MAX_CONTACTS)), np.zeros(3, np.int64)
    rk.pairs_contacts(centres, orientations, radii, tubes, pairs, rk.N_SCAN, rk.COLD, 6, state, counts, out, stats)
    assert stats[1] == 4 and stats[2] == 0  # four cold searches
    for p, (i, j) in enumerate(pairs):
        single = np.empty((rk.MAX_CONTACTS, rk.FIELDS))
        rows, _ = rk.pair_contacts(centres[i], orientations[i], radii[i], tubes[i], centres[j], orientations[j],
                                   radii[j], tubes[j], rk.N_SCAN, single)  # fmt: skip
        assert counts[p] == rows and np.array_equal(out[p, :rows], single[:rows])
        assert np.array_equal(state[p, :rows], single[:rows, 1])
    # warm, from the same poses: each minimum confirmed in one Newton iteration or two
    cold = out.copy()
    rk.pairs_contacts(centres, orientations, radii, tubes, pairs, rk.N_SCAN, rk.WARM, 6, state, counts, out, stats)
    assert stats[1] == 0 and stats[0] <= 2 * counts.sum()
    for p in range(4):
        # the same minima to the refinement's tolerance (s to 1e-13 rad): every field to 1e-12 of itself
        assert np.allclose(out[p, : counts[p]], cold[p, : counts[p]], rtol=1e-12, atol=1e-12)
    # followed with one Newton step: the same again, no search
    rk.pairs_contacts(centres, orientations, radii, tubes, pairs, rk.N_SCAN, rk.FOLLOW, 1, state, counts, out, stats)
    assert stats[1] == 0 and stats[0] == counts.sum()
    for p in range(4):
        assert np.allclose(out[p, : counts[p]], cold[p, : counts[p]], rtol=1e-12, atol=1e-12)


def test_power_law_force_and_torques_are_the_gradient_of_its_energy():
    """Central differences of K delta^(n+1)/(n+1) (delta from torus_contacts) against the force and torques."""
    K, n = 3e9, 1.3
    law = np.array([1.0, K, n, 0.0, 0.0, 1e-3, 0.0])
    c1, q1, c2, q2 = crossing(np.radians(65), 2 * (R - r) + 3e-6)
    rot1 = Rotation.from_quat(np.r_[q1[1:], q1[0]]) * about([0.2, 0.1, 1.0], 0.05)  # a generic pose
    rot2 = Rotation.from_quat(np.r_[q2[1:], q2[0]])
    c1 = c1 + np.array([0.4e-3, -0.2e-3, 0.0])

    def energy(centre, rotation):
        gap = torus_contacts(centre, quaternion(rotation), RING, c2, quaternion(rot2), RING).gap
        return sum(K * (-g) ** (n + 1) / (n + 1) for g in gap)

    (row,) = torus_contacts(c1, quaternion(rot1), RING, c2, quaternion(rot2), RING).rows
    force, torque_1, torque_2 = np.empty(3), np.empty(3), np.empty(3)
    zero = np.zeros(3)
    rl.contact_force(row, c1, zero, zero, c2, zero, zero, law, *GRID, force, torque_1, torque_2)
    step, turn = 1e-9, 1e-7  # m, rad: truncation (step/delta)^2 ~ 1e-7 against rounding of the gap (1e-18/1e-15)
    for axis in np.eye(3):
        push = (energy(c1 + step * axis, rot1) - energy(c1 - step * axis, rot1)) / (2 * step)
        twist = (energy(c1, about(axis, turn) * rot1) - energy(c1, about(axis, -turn) * rot1)) / (2 * turn)
        assert -push == pytest.approx(force @ axis, rel=1e-5, abs=1e-6 * np.abs(force).max())
        assert -twist == pytest.approx(torque_1 @ axis, rel=1e-5, abs=1e-6 * np.abs(force).max() * R)
