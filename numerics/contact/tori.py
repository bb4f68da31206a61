r"""Contacts of rigid tori in space: the narrow phase of two rings in any pose, the broad phase, linking.

Conventions (shared with the rigid rings that use them).  A ring's centre is a (3,) array in m; its
orientation a unit quaternion (w, x, y, z) taking the ring's body frame to space; the ring's axis (the
normal to its plane) is body z and its centre circle, of radius R, lies in the body xy plane, the
point at the angle s being R (cos s, sin s, 0) in the body frame.  Circles are oriented by increasing s
(counterclockwise about body z), which fixes the sign of :func:`linking_number`.

The narrow phase (:func:`torus_contacts`).  The tube surfaces touch where the distance between the
centre circles has a local minimum; each minimum with gap = distance - r_1 - r_2 below ``margin`` is a
contact.  The search and its degenerate poses are described in :mod:`ringchain.numerics.engine.rings_kernels`;
the compiled functions there (:func:`~ringchain.numerics.engine.rings_kernels.pair_contacts`, its warm-started
variant and :func:`~ringchain.numerics.engine.rings_law.contact_force`) are what a time loop calls.

How many samples.  The coarse scan brackets a minimum where g' (the slope of the squared distance) turns from
negative to positive between two samples, h = 2 pi/n_scan apart; a minimum and the maximum beside it that fall
between the same two samples leave g' of one sign at both, and the scan looks between those two again at spacing
h/32 where the cubic model of g' from its values and slopes there dips close to zero (see
:mod:`ringchain.numerics.engine.rings_kernels`).  Before that look, a pair of a 30 x 30 sheet of chain mail whose
second minimum lay 0.88 h past the maximum had only its first found; on the 3,863 close pairs of that sheet's pose
the search now finds all 5,970 minima of a profile sampled at 2^13 points (without the look it missed 13).  Two
linked rings at the angle theta below theta_min touch at two points, on circle 1 at the angles +-Delta from the
crossing, Delta growing from zero at theta_min as sqrt(theta_min - theta); for the paper's proportions (R/r = 9)
Delta reaches h = 5.6 deg (n_scan = 64) about 1 deg below theta_min, where the two minima lie 6.7 um of gap below
the maximum between them (benchmarks/bench_rings_contact.py prints Delta and that depth against theta).  Closer to
theta_min the minimum found has an inflection next to it, and a second look at 2 h on both sides with spacing h/32
finds its twin: both contacts are found down to 0.001 deg below theta_min (Delta = 0.2 deg, a depth of 7e-12 m).  A
ring resting across an unlinked one, or two rings side by side, has minima a quarter turn or more apart; two rings
crossing twice have minima as far apart as their crossings.  64 samples keep the scan cheap (its samples cost no
trigonometric function) while every pair of minima more than h/32 = 0.18 deg from the maximum between them is found.

The warm start.  :func:`~ringchain.numerics.engine.rings_kernels.pair_contacts_warm` follows the minima of the last
step with Newton's method, three iterations per minimum for a step that turns a ring by 1e-3 rad (the last confirms
convergence; benchmarks/bench_rings_contact.py), and falls back on the cold search when a minimum is lost, an
inflection comes close to it (8 pairs in 8,000 for steps of 1e-2 rad), or a maximum lies within 2 h of it with no
minimum followed beyond (the twin the cold search would find there).  It cannot see a minimum born away from those
it follows (such a minimum starts shallower than the followed minimum downhill of it), so a caller runs the cold
search every few steps, and whenever a pair has turned by more than about h/4 since its last one.  Within a step
(the stages of a Runge-Kutta method) :func:`~ringchain.numerics.engine.rings_kernels.pair_contacts_follow` takes one
Newton step from the step's angles with no check: the gap is stationary at its minimum, so what is left is of second
order.  Measured processor time per pair (1.5 minima each, R/r = 9, benchmarks/bench_rings_contact.py on a loaded
machine, with the look between samples of :mod:`~ringchain.numerics.engine.rings_kernels`): cold 2.8 us, warm 1.5 us,
followed 0.9 us (before that look: 2.0, 1.1 and 0.6 us).

The broad phase (:func:`candidate_pairs`): pairs of rings whose bounding spheres (radius R + r about the
centre) come within ``skin`` of each other, linked or not, from a k-d tree; rebuilt when a ring has moved
by more than half the skin.

Linking (:func:`linking_number`): the Gauss linking number of two circles, +-1 for interlocked rings and
0 otherwise, as the signed count of the crossings of circle 2 through the disc of circle 1.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..engine import rings_kernels as rk

__all__ = [
    "CONTACT_FIELDS",
    "TorusContacts",
    "torus_contacts",
    "candidate_pairs",
    "linking_number",
    "pose_arrays",
]

#: Names of the numbers of one contact row of the compiled kernels (:mod:`ringchain.numerics.engine.rings_kernels`).
CONTACT_FIELDS = (
    "gap", "s_1", "s_2", "point_x", "point_y", "point_z", "normal_x", "normal_y", "normal_z",
    "curvature_along_1", "curvature_across_1", "curvature_along_2", "curvature_across_2",
    "cos_angle", "distance", "line",
)  # fmt: skip


@dataclass(frozen=True)
class TorusContacts:
    """The contacts of two tori (one entry per contact, k of them; arrays of length k).

    Attributes
    ----------
    gap : ndarray (k,)
        Distance between the centre circles minus r_1 + r_2, m; negative where the tubes overlap (the
        approach delta = -gap of the contact law).
    point : ndarray (k, 3)
        The contact point, m: midway between the two tube surfaces along the normal.
    normal : ndarray (k, 3)
        Unit normal, pointing from ring 2 towards ring 1 (the direction of the force on ring 1).
    s_1, s_2 : ndarray (k,)
        Angles of the contact on each centre circle, rad, in [0, 2 pi) (the warm start's state is s_1).
    curvatures_1, curvatures_2 : ndarray (k, 2)
        Principal curvatures of each tube surface at the contact, 1/m, convex positive: along the tube
        (cos phi/(R + r cos phi), phi the angle around the tube from its outer equator: -1/(R - r) on the
        inner equator) and across it (1/r).
    angle : ndarray (k,)
        Angle between the two tubes' tangents at the contact, rad, in [0, pi/2] (the angle between the
        principal directions of the Hertz contact; the contact angle theta at an interlocked crossing).
    distance : ndarray (k,)
        Distance between the centre circles, m.
    line : bool
        True when the distance of the circles is constant (coaxial rings): a circle of contact, given as
        four contacts at s_1 = 0, pi/2, pi, 3 pi/2.
    rows : ndarray (k, FIELDS)
        The same as the compiled kernels give it (:data:`CONTACT_FIELDS`).
    """

    rows: np.ndarray

    def __len__(self) -> int:
        return self.rows.shape[0]

    def _column(self, name):
        return self.rows[:, CONTACT_FIELDS.index(name)]

    @property
    def gap(self) -> np.ndarray:
        return self._column("gap")

    @property
    def point(self) -> np.ndarray:
        return self.rows[:, 3:6]

    @property
    def normal(self) -> np.ndarray:
        return self.rows[:, 6:9]

    @property
    def s_1(self) -> np.ndarray:
        return self._column("s_1")

    @property
    def s_2(self) -> np.ndarray:
        return self._column("s_2")

    @property
    def curvatures_1(self) -> np.ndarray:
        return self.rows[:, 9:11]

    @property
    def curvatures_2(self) -> np.ndarray:
        return self.rows[:, 11:13]

    @property
    def angle(self) -> np.ndarray:
        return np.arccos(self._column("cos_angle"))

    @property
    def distance(self) -> np.ndarray:
        return self._column("distance")

    @property
    def line(self) -> bool:
        return bool(len(self) and self.rows[0, CONTACT_FIELDS.index("line")] == 1.0)


def _radii(ring, name, tube=True):
    """(R, r) of a ring (or anything with R and r; a number is R alone where ``tube`` is False), validated."""
    if hasattr(ring, "R"):
        R, r = ring.R, (ring.r if tube or hasattr(ring, "r") else 0.0)
    elif not tube:
        R, r = ring, 0.0
    else:
        raise TypeError(f"{name} must be a ringchain.theory.Ring or have R and r (m), got {ring!r}")
    R = float(np.asarray(R, dtype=float))
    r = float(np.asarray(r, dtype=float))
    if not (np.isfinite(R) and R > 0):
        raise ValueError(f"{name}.R must be positive and finite, in m (got {R!r})")
    if tube and not (np.isfinite(r) and 0 < r < R):
        raise ValueError(f"{name}.r must lie in (0, R), in m (got r = {r!r} with R = {R!r})")
    return R, r


def pose_arrays(centre, orientation, name="ring"):
    """(centre (3,), unit quaternion (4,)) as contiguous float arrays, validated; the quaternion is normalised.

    Raises ``ValueError`` for a centre that is not three finite numbers (m) or a quaternion that is not four
    finite numbers of nonzero norm (w, x, y, z).
    """
    c = np.ascontiguousarray(centre, dtype=float)
    q = np.ascontiguousarray(orientation, dtype=float)
    if c.shape != (3,) or not np.all(np.isfinite(c)):
        raise ValueError(f"the centre of {name} must be three finite coordinates in m, got {centre!r}")
    norm = np.linalg.norm(q) if q.shape == (4,) else np.nan
    if not (np.isfinite(norm) and norm > 0):
        raise ValueError(
            f"the orientation of {name} must be a quaternion (w, x, y, z) of nonzero norm, got {orientation!r}"
        )
    return c, q / norm


def torus_contacts(centre_1, orientation_1, ring_1, centre_2, orientation_2, ring_2, *, margin=0.0, n_scan=rk.N_SCAN):
    """Every contact of two tori in any pose.

    Parameters
    ----------
    centre_1, centre_2 : array_like (3,)
        Centres of the rings, m.
    orientation_1, orientation_2 : array_like (4,)
        Unit quaternions (w, x, y, z) taking each ring's body frame to space (axis = body z); normalised here.
    ring_1, ring_2 : Ring or object with R and r
        Major and tube radius of each ring, m (:class:`ringchain.theory.Ring`; 0 < r < R).
    margin : float, optional
        Minima of the distance of the centre circles with gap <= ``margin`` (m) are returned: 0 gives the
        touching and overlapping contacts; a positive margin the near ones too (``np.inf``: every minimum).
    n_scan : int, optional
        Samples of the cold search (module notes: two minima closer than about 2 pi/n_scan to the maximum
        between them are returned as one), >= 8.

    Returns
    -------
    TorusContacts
        The contacts, with ``gap`` (m), ``point``, ``normal`` (from ring 2 to ring 1), ``s_1``, ``s_2``, the
        principal curvatures of both tubes and the angle between their tangents.

    Notes
    -----
    The minima of the distance between the centre circles (:mod:`ringchain.numerics.engine.rings_kernels`); at the
    interlocked crossing of two equal rings at the contact angle theta above theta_min there is one, with
    the curvatures of App. A of the paper (across the tube 1/r, along it -1/(R - r)).

    Examples
    --------
    >>> from ringchain.theory import Ring
    >>> ring = Ring(20e-3, 2.5e-3)
    >>> upright = [np.cos(np.pi / 4), np.sin(np.pi / 4), 0.0, 0.0]  # a quarter turn about x: the ring in the xz plane
    >>> # ring 2 upright through the hole of ring 1 (flat), their centres 2(R - r) = 35 mm apart: touching
    >>> contacts = torus_contacts([0, 0, 0], [1, 0, 0, 0], ring, [35e-3, 0, 0], upright, ring, margin=1e-9)
    >>> len(contacts), abs(round(float(contacts.gap[0]), 12))
    (1, 0.0)
    >>> np.round(contacts.point[0] * 1e3, 9) + 0.0, np.round(contacts.normal[0], 9) + 0.0  # mm; from ring 2 to 1
    (array([17.5,  0. ,  0. ]), array([1., 0., 0.]))
    """
    R1, r1 = _radii(ring_1, "ring_1")
    R2, r2 = _radii(ring_2, "ring_2")
    c1, q1 = pose_arrays(centre_1, orientation_1, "ring 1")
    c2, q2 = pose_arrays(centre_2, orientation_2, "ring 2")
    margin = float(margin)
    if np.isnan(margin):
        raise ValueError("margin must be a number of m (or inf), got nan")
    if isinstance(n_scan, bool) or not isinstance(n_scan, (int, np.integer)) or n_scan < 8:
        raise ValueError(f"n_scan must be an integer >= 8 (samples of the search), got {n_scan!r}")
    out = np.empty((rk.MAX_CONTACTS, rk.FIELDS))
    rows, _ = rk.pair_contacts(c1, q1, R1, r1, c2, q2, R2, r2, int(n_scan), out)
    rows = out[:rows]
    return TorusContacts(np.array(rows[rows[:, 0] <= margin]))


def candidate_pairs(centres, radii, *, skin=0.0):
    """Pairs of rings whose bounding spheres come within ``skin`` of each other (the broad phase).

    Parameters
    ----------
    centres : array_like (n, 3)
        Ring centres, m.
    radii : array_like (n,) or float
        Bounding radius of each ring about its centre, m: R + r for a torus.
    skin : float, optional
        Extra distance, m, >= 0: a list built with a skin stays valid until some ring has moved by
        more than skin/2.

    Returns
    -------
    ndarray (m, 2) of int
        Pairs (i, j), i < j, with |c_i - c_j| <= radii_i + radii_j + skin, sorted; linked and unlinked alike.

    Examples
    --------
    >>> candidate_pairs([[0, 0, 0], [0, 0, 0.03], [0, 0, 0.2]], 0.0225)
    array([[0, 1]])
    """
    from scipy.spatial import cKDTree

    centres = np.asarray(centres, dtype=float)
    if centres.ndim != 2 or centres.shape[1] != 3 or not np.all(np.isfinite(centres)):
        raise ValueError(f"centres must be an (n, 3) array of finite coordinates in m, got shape {centres.shape}")
    radii = np.broadcast_to(np.asarray(radii, dtype=float), centres.shape[:1])
    if not np.all(np.isfinite(radii) & (radii >= 0)):
        raise ValueError("radii must be finite and >= 0, in m")
    skin = float(skin)
    if not (np.isfinite(skin) and skin >= 0):
        raise ValueError(f"skin must be finite and >= 0, in m, got {skin!r}")
    if centres.shape[0] < 2:
        return np.zeros((0, 2), dtype=np.intp)
    reach = 2.0 * radii.max() + skin
    pairs = cKDTree(centres).query_pairs(reach, output_type="ndarray").astype(np.intp)
    if pairs.size == 0:
        return np.zeros((0, 2), dtype=np.intp)
    pairs.sort(axis=1)
    distance = np.linalg.norm(centres[pairs[:, 0]] - centres[pairs[:, 1]], axis=1)
    pairs = pairs[distance <= radii[pairs[:, 0]] + radii[pairs[:, 1]] + skin]
    return pairs[np.lexsort((pairs[:, 1], pairs[:, 0]))]


def linking_number(centre_1, orientation_1, ring_1, centre_2, orientation_2, ring_2):
    """The Gauss linking number of the centre circles of two rings: +-1 interlocked, 0 not.

    Parameters
    ----------
    centre_1, orientation_1, centre_2, orientation_2 : array_like
        Poses as in :func:`torus_contacts` (m; quaternions (w, x, y, z), body to space).
    ring_1, ring_2 : Ring, object with R, or float
        The rings, or the radii R of their centre circles, m.

    Returns
    -------
    int
        The signed number of times circle 2 crosses the disc of circle 1, counted +1 along circle 1's axis
        (body z; both circles oriented by increasing s).  Where the centre circles meet (tubes overlapping by
        more than a tube's radius) the linking number is undefined, and the count is that of the crossings
        strictly inside the disc.

    Examples
    --------
    >>> turn = [np.cos(np.pi / 4), np.sin(np.pi / 4), 0.0, 0.0]  # ring plane xz
    >>> linking_number([0, 0, 0], [1, 0, 0, 0], 0.02, [0.02, 0, 0], turn, 0.02)
    -1
    >>> linking_number([0, 0, 0], [1, 0, 0, 0], 0.02, [0.05, 0, 0], turn, 0.02)
    0
    """
    R1, _ = _radii(ring_1, "ring_1", tube=False)
    R2, _ = _radii(ring_2, "ring_2", tube=False)
    c1, q1 = pose_arrays(centre_1, orientation_1, "ring 1")
    c2, q2 = pose_arrays(centre_2, orientation_2, "ring 2")
    M1, M2 = np.empty((3, 3)), np.empty((3, 3))
    rk.rotation_matrix(q1, M1)
    rk.rotation_matrix(q2, M2)
    # circle 2 in the frame of ring 1: D + R2 (cos s a + sin s b)
    D, a, b = M1.T @ (c2 - c1), M1.T @ M2[:, 0], M1.T @ M2[:, 1]
    amplitude = np.hypot(a[2], b[2])
    if amplitude == 0.0 or abs(D[2]) >= R2 * amplitude:  # parallel planes, or circle 2 misses the plane
        return 0
    phase = np.arctan2(b[2], a[2])
    half = np.arccos(-D[2] / (R2 * amplitude))
    count = 0
    for s in (phase + half, phase - half):  # a cos s + b sin s = -D_z/R2
        x = D[:2] + R2 * (np.cos(s) * a[:2] + np.sin(s) * b[:2])
        crossing = R2 * (b[2] * np.cos(s) - a[2] * np.sin(s))  # dz/ds
        if x @ x < R1 * R1:
            count += int(np.sign(crossing))
    return count
