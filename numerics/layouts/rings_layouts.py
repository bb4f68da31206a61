r"""Networks of rigid rings in 3D: a chain, 4-in-1 chain mail and a polycatenated block (their rest poses).

Every layout returns ``(centres, orientations, links)``: ring centres, shape (n, 3) in m; orientations,
shape (n, 4), unit quaternions (w, x, y, z) taking a ring's body frame to space, the ring's axis (the
normal to its plane) being body z and its centre circle, of radius R, lying in the body xy plane; and the
interlocked pairs, shape (n_links, 2), each once with i < j.  :func:`check_links` verifies a rest pose:
every listed pair linked (Gauss linking number +-1), every other pair within reach unlinked, and no two
tubes overlapping (tube gap >= 0); it raises naming the first pair that fails.

Layouts
-------
:func:`chain_layout`
    The paper's chain in 3D: centres on the z axis, ring 0 at the bottom (the struck end), a = 2(R - r)
    apart (neighbours just touching, Eq. (8)'s spacing), each ring's plane turned 90 degrees about z from
    its neighbour's (the paper's contact angle).
:func:`tilted_chain_layout`
    The same chain with each ring tilted and shifted a little at random (seeded), neighbours just touching.
:func:`mail_layout`
    European 4-in-1 chain mail in the vertical xz plane (geometry in :func:`mail_geometry`).
:func:`pam_layout`
    A 3D polycatenated block: rings on the sites of the NbO net (each ring catenated with four
    neighbours in its own plane; see the function).

The interlocked pairs of a layout are what it intends; :func:`check_links` measures them.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from ringchain.theory import Ring
from ringchain.theory import _validate as v

__all__ = [
    "chain_layout",
    "tilted_chain_layout",
    "mail_layout",
    "mail_geometry",
    "pam_layout",
    "check_links",
    "ring_radii",
    "quaternion_about",
    "quaternion_product",
    "rotate",
    "MAIL_PATTERNS",
]

#: Weaves :func:`mail_layout` builds.
MAIL_PATTERNS = ("4-in-1",)

#: A tube gap down to this fraction of the tube radius below zero counts as touching (the rounding of
#: the contact search on rings built exactly touching, as the chain's neighbours are).
GAP_TOLERANCE = 1e-9


# -- quaternions (w, x, y, z), body -> space ---------------------------------------------------------
def quaternion_about(axis, angle) -> np.ndarray:
    """Unit quaternion (w, x, y, z) of a rotation by ``angle`` (rad) about ``axis`` (any length > 0)."""
    axis = np.asarray(axis, dtype=float)
    axis = axis / np.linalg.norm(axis, axis=-1, keepdims=True)
    half = 0.5 * np.asarray(angle, dtype=float)[..., None]
    return np.concatenate([np.cos(half), np.sin(half) * axis], axis=-1)


def quaternion_product(p, q) -> np.ndarray:
    """Hamilton product p q (apply q, then p), broadcast over leading axes."""
    p, q = np.asarray(p, dtype=float), np.asarray(q, dtype=float)
    w1, v1 = p[..., :1], p[..., 1:]
    w2, v2 = q[..., :1], q[..., 1:]
    w = w1 * w2 - np.sum(v1 * v2, axis=-1, keepdims=True)
    return np.concatenate([w, w1 * v2 + w2 * v1 + np.cross(v1, v2)], axis=-1)


def rotate(q, vectors) -> np.ndarray:
    """Vectors (..., 3) taken from the body frame to space by unit quaternions q (..., 4)."""
    q, vectors = np.asarray(q, dtype=float), np.asarray(vectors, dtype=float)
    w, u = q[..., :1], q[..., 1:]
    t = 2.0 * np.cross(u, vectors)
    return vectors + w * t + np.cross(u, t)


def ring_radii(rings, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(R, r) per ring, m, arrays of shape (n,), from one :class:`~ringchain.theory.Ring` or n of them."""
    if isinstance(rings, Ring):
        return np.full(n, rings.R), np.full(n, rings.r)
    if not isinstance(rings, Sequence) or not all(isinstance(ring, Ring) for ring in rings):
        raise TypeError(f"rings must be a Ring or a sequence of Ring, got {type(rings).__name__}")
    if len(rings) != n:
        raise ValueError(f"rings: one Ring or one per ring ({n}), got {len(rings)}")
    return np.array([ring.R for ring in rings]), np.array([ring.r for ring in rings])


def _check_ring(ring) -> Ring:
    if not isinstance(ring, Ring):
        raise TypeError(f"ring must be a ringchain.theory.Ring, got {type(ring).__name__}")
    return ring


# -- the chain ----------------------------------------------------------------------------------------
def chain_layout(n_rings: int, ring: Ring, *, spacing: float | None = None):
    """A straight chain along z: ring 0 at the origin (the bottom, struck end), ring k at z = k a.

    Parameters
    ----------
    n_rings : int
        Number of rings, at least 2.
    ring : ringchain.theory.Ring
        The rings' geometry (R, r in m); R >= 3 r (each ring holds two neighbours).
    spacing : float, optional
        Distance a between adjacent centres, m; default 2(R - r), neighbours just touching (the
        paper's spacing, Eq. (8)); a smaller one leaves slack, at least R + 2r + ... so that
        second neighbours stay apart (checked by :func:`check_links`).

    Returns
    -------
    centres : ndarray, shape (n, 3)
        m.
    orientations : ndarray, shape (n, 4)
        Ring k's axis (body z) along space x for even k, along space y for odd k: planes at 90
        degrees, each turned by 90 degrees about z from its neighbour.
    links : ndarray, shape (n - 1, 2)
        (k, k + 1).

    Examples
    --------
    >>> from ringchain.theory import Ring
    >>> centres, orientations, links = chain_layout(3, Ring(0.0225, 0.0025))
    >>> centres[:, 2].round(4).tolist(), links.tolist()
    ([0.0, 0.04, 0.08], [[0, 1], [1, 2]])
    """
    n = v.count("n_rings", n_rings, 2)
    ring = _check_ring(ring)
    ring.check_chain()
    a = ring.spacing if spacing is None else float(v.positive("spacing", spacing, "m"))
    if a > ring.spacing * (1 + 1e-12):
        raise ValueError(f"spacing {a:g} m exceeds 2(R - r) = {ring.spacing:g} m: neighbours would not be linked "
                         "without overlapping")  # fmt: skip
    centres = np.zeros((n, 3))
    centres[:, 2] = a * np.arange(n)
    # Axis along x (a quarter turn about y), then a quarter turn about z for every other ring.
    even = quaternion_about([0.0, 1.0, 0.0], np.pi / 2)
    odd = quaternion_product(quaternion_about([0.0, 0.0, 1.0], np.pi / 2), even)
    orientations = np.where((np.arange(n) % 2 == 0)[:, None], even, odd)
    links = np.stack([np.arange(n - 1), np.arange(1, n)], axis=1)
    return centres, orientations, links


def tilted_chain_layout(n_rings: int, ring: Ring, *, tilt: float, offset: float, seed: int):
    """The chain of :func:`chain_layout` with each ring tilted and shifted a little at random, neighbours just touching.

    Each ring turns by an angle drawn uniformly from [-tilt, tilt] about an axis drawn uniformly on the
    sphere, and its centre moves across the chain (x and y) by amounts drawn uniformly from [-offset,
    offset]; then, from ring 1 up, each ring moves along z until its tube just touches the ring below (the
    tube gap of the pair, the least distance of their centre circles less 2r, is zero to 1e-13 m), so that a
    chain struck along its axis starts with no force and no slack, as the straight chain does.

    Parameters
    ----------
    n_rings : int
        Number of rings, at least 2.
    ring : ringchain.theory.Ring
        The rings' geometry (R, r in m).
    tilt : float
        Largest tilt, rad, in [0, 0.2] (the rings stay linked with their neighbours only).
    offset : float
        Largest sideways offset of a centre, m, in [0, r].
    seed : int
        Seed of :func:`numpy.random.default_rng`.

    Returns
    -------
    centres, orientations, links
        As :func:`chain_layout`; with ``tilt = offset = 0`` its straight chain.
    """
    from scipy.optimize import brentq

    from ..contact.tori import torus_contacts

    ring = _check_ring(ring)
    tilt, offset = float(v.as_float("tilt", tilt)), float(v.as_float("offset", offset))
    if not 0.0 <= tilt <= 0.2:
        raise ValueError(f"tilt must lie in [0, 0.2] rad, got {tilt:g} rad")
    if not 0.0 <= offset <= ring.r:
        raise ValueError(f"offset must lie in [0, r] = [0, {ring.r:g}] m, got {offset:g} m")
    centres, orientations, links = chain_layout(n_rings, ring)
    rng = np.random.default_rng(v.integer("seed", seed))
    n = len(centres)
    axes = rng.standard_normal((n, 3))
    orientations = quaternion_product(quaternion_about(axes, tilt * rng.uniform(-1.0, 1.0, n)), orientations)
    centres[:, :2] += offset * rng.uniform(-1.0, 1.0, (n, 2))
    for k in range(1, n):

        def gap(z, k=k):
            centre = np.array([centres[k, 0], centres[k, 1], z])
            return torus_contacts(centres[k - 1], orientations[k - 1], ring, centre, orientations[k], ring,
                                  margin=np.inf).gap.min()  # fmt: skip

        below = centres[k - 1, 2]
        centres[k, 2] = brentq(gap, below + 0.8 * ring.spacing, below + 1.2 * ring.spacing, xtol=1e-13)
    check_links(centres, orientations, ring, links)
    return centres, orientations, links


# -- chain mail ---------------------------------------------------------------------------------------
#: Clearances of the 4-in-1 construction, in tube radii: between rings two rows apart (coplanar), and the
#: share of the linked pair's room kept free (see :func:`mail_geometry`).
_MAIL_ROW_CLEARANCE = 0.1
_MAIL_LINK_ROOM = 0.95


def mail_geometry(ring: Ring) -> tuple[float, float, float]:
    r"""Tilt, pitch and row spacing of 4-in-1 chain mail of ``ring``: (alpha rad, p m, w m).

    The weave.  Rows run along x, w apart in z; ring j of row i sits at (j p + (i mod 2) p/2, 0, i w),
    its axis n = (+-sin alpha, cos alpha, 0): tilted by alpha from the sheet's normal y towards x, the
    sign alternating from row to row.  Each ring is linked with the two nearest rings of the row above
    and the two of the row below, none in its own row.

    Derivation.  Two rings of neighbouring rows, offset (k p/2, 0, w) with k odd, have planes that
    meet in a line parallel to z, at distance d_k = k p / (4 cos alpha) from both centres; each
    circle crosses it at +-s_k = +-sqrt(R^2 - d_k^2) about its own height, so the pair is linked iff
    the two crossings interleave, w < 2 s_k.  The construction asks:

    - rings two rows apart (coplanar, 2w apart) clear: w = R + r + 0.1 r;
    - the nearest pair linked (w < 2 s_1) and its wires apart: the crossing of one circle through
      the other's plane, at distance sqrt(d_1^2 + (w - s_1)^2) from that ring's centre, within
      0.95 (R - 2r) of it;
    - the next pair (k = 3) unlinked with a tube's width to spare: w - 2 s_3 >= 2 r;
    - neighbours in a row (parallel planes p sin alpha apart) clear: p sin alpha = 2 d_1 > 2 r at
      alpha = 45 degrees, the tilt that minimises d_1 for a given plane separation.

    d_1 is the middle of the interval these leave; :func:`check_links` then verifies the whole sheet
    (the conditions above are about crossings, the check about the tubes themselves).

    Raises
    ------
    ValueError
        If R/r leaves no such interval (thick rings, R below about 4 r; at R = 4 r the interval exists but
        :func:`check_links` finds the unlinked diagonal pair overlapping: about 5 r is needed).
    """
    ring = _check_ring(ring)
    R, r = ring.R, ring.r
    alpha = math.pi / 4
    w = R + r + _MAIL_ROW_CLEARANCE * r
    lower = max(1.1 * r, math.sqrt(max(R * R - (w - 2 * r) ** 2 / 4, 0.0)) / 3)
    upper_link = math.sqrt(max(R * R - w * w / 4, 0.0))
    room = (_MAIL_LINK_ROOM * (R - 2 * r)) ** 2

    def crowding(d):  # squared distance of the crossing from the centre, less the room
        return d * d + (w - math.sqrt(R * R - d * d)) ** 2 - room

    upper = upper_link
    if crowding(min(upper_link, R) * (1 - 1e-12)) > 0:
        from scipy.optimize import brentq

        upper = brentq(crowding, 0.0, min(upper_link, R) * (1 - 1e-12)) if crowding(0.0) < 0 else 0.0
    if not lower < upper:
        raise ValueError(f"R/r = {R / r:.4g} is too small for 4-in-1 chain mail of this construction: the rings "
                         "cannot link two neighbours above and two below without their tubes overlapping "
                         "(R/r of about 5 or more is needed)")  # fmt: skip
    d1 = 0.5 * (lower + upper)
    p = 4 * d1 * math.cos(alpha)
    return alpha, p, w


def mail_layout(rows: int, cols: int, ring: Ring, *, pattern: str = "4-in-1", check: bool = True):
    """A sheet of 4-in-1 chain mail in the vertical xz plane, row 0 at the bottom (z = 0).

    Parameters
    ----------
    rows, cols : int
        Rows (stacked along z) and rings per row (along x), each at least 2.
    ring : ringchain.theory.Ring
        The rings' geometry (R, r in m).
    pattern : str
        ``"4-in-1"`` (the European weave; :func:`mail_geometry` gives its tilt, pitch and spacing).
    check : bool
        Verify the rest pose with :func:`check_links` (default; a 30 x 30 sheet takes a few seconds).

    Returns
    -------
    centres, orientations, links
        Ring (i, j) is number ``i * cols + j``; links (i, j)-(i + 1, j') for the two rings j' of the
        row above nearest to it.
    """
    rows, cols = v.count("rows", rows, 2), v.count("cols", cols, 2)
    v.choice("pattern", pattern, MAIL_PATTERNS)
    alpha, p, w = mail_geometry(ring)
    i, j = np.divmod(np.arange(rows * cols), cols)
    centres = np.stack([j * p + (i % 2) * p / 2, np.zeros(i.size), i * w], axis=1)
    # Axis along y (a quarter turn about x), then tilted by -+alpha about z (towards +-x).
    to_y = quaternion_about([1.0, 0.0, 0.0], -np.pi / 2)
    tilt = np.where(i % 2 == 0, -alpha, alpha)
    orientations = quaternion_product(quaternion_about(np.array([[0.0, 0.0, 1.0]]), tilt), to_y)
    links = []
    for row in range(rows - 1):
        shift = -1 if row % 2 == 0 else 0  # even rows reach j - 1 and j above, odd rows j and j + 1
        for col in range(cols):
            for above in (col + shift, col + shift + 1):
                if 0 <= above < cols:
                    links.append((row * cols + col, (row + 1) * cols + above))
    links = np.array(links, dtype=np.intp)
    if v.boolean("check", check):
        check_links(centres, orientations, ring, links)
    return centres, orientations, links


# -- a polycatenated block ----------------------------------------------------------------------------
#: Axis of the ring on each parity class (i mod 2, j mod 2, k mod 2) of the cubic grid; None: no ring.
_NBO_AXES = {(0, 0, 0): 2, (1, 1, 1): 2, (1, 0, 0): 1, (0, 1, 1): 1, (0, 1, 0): 0, (1, 0, 1): 0,
             (0, 0, 1): None, (1, 1, 0): None}  # fmt: skip


def pam_layout(nx: int, ny: int, nz: int, ring: Ring, *, spacing: float | None = None, check: bool = True):
    r"""A 3D polycatenated block: rings on the NbO net, each catenated with four neighbours.

    Construction (the design route of Zhou et al., Science 387, 269 (2025), "3D polycatenated
    architected materials": a crystalline net's nodes become particles and its edges catenations).
    Take the simple cubic grid of spacing a and colour its sites by parity (i, j, k) mod 2. The
    classes (0, 0, 1) and (1, 1, 0) are empty; the others carry a ring whose axis is z on (0, 0, 0)
    and (1, 1, 1), y on (1, 0, 0) and (0, 1, 1), x on (0, 1, 0) and (1, 0, 1). The remaining sites
    form the NbO net (RCSR symbol nbo), every node square-planar and 4-connected: a ring's four grid
    neighbours in its own plane are occupied by rings whose planes contain the bond and are
    perpendicular to its own -- the chain's interlocked pair, a = 2(R - r) apart by default (just
    touching) -- and its two neighbours along its axis are empty sites.

    Parameters
    ----------
    nx, ny, nz : int
        Grid sites along x, y and z (each at least 2); about 3/4 of them hold a ring.
    ring : ringchain.theory.Ring
        The rings' geometry, m; R/r above about 3.5 keeps diagonal neighbours, sqrt(2)(R - 2r)
        apart, clear of each other.
    spacing : float, optional
        Grid spacing a, m (default 2(R - r)).
    check : bool
        Verify the rest pose with :func:`check_links` (default).

    Returns
    -------
    centres, orientations, links
        Rings in the order of the grid (x fastest); links between grid neighbours.
    """
    nx, ny, nz = (v.count(name, n, 2) for name, n in (("nx", nx), ("ny", ny), ("nz", nz)))
    ring = _check_ring(ring)
    a = ring.spacing if spacing is None else float(v.positive("spacing", spacing, "m"))
    if a > ring.spacing * (1 + 1e-12):
        raise ValueError(f"spacing {a:g} m exceeds 2(R - r) = {ring.spacing:g} m: neighbours would not be linked "
                         "without overlapping")  # fmt: skip
    k, j, i = np.meshgrid(np.arange(nz), np.arange(ny), np.arange(nx), indexing="ij")
    grid = np.stack([i.ravel(), j.ravel(), k.ravel()], axis=1)
    axes = np.array([_NBO_AXES[tuple(site)] if _NBO_AXES[tuple(site)] is not None else -1 for site in grid % 2])
    keep = axes >= 0
    grid, axes = grid[keep], axes[keep]
    turns = {2: np.array([1.0, 0.0, 0.0, 0.0]), 0: quaternion_about([0.0, 1.0, 0.0], np.pi / 2),
             1: quaternion_about([1.0, 0.0, 0.0], -np.pi / 2)}  # fmt: skip
    orientations = np.array([turns[axis] for axis in axes])
    index = {tuple(site): n for n, site in enumerate(grid)}
    links = []
    for n, site in enumerate(grid):
        for direction in range(3):
            if direction == axes[n]:
                continue
            step = np.zeros(3, dtype=int)
            step[direction] = 1
            other = index.get(tuple(site + step))
            if other is not None:
                links.append((n, other))
    centres, links = grid * a, np.array(links, dtype=np.intp).reshape(-1, 2)
    if v.boolean("check", check):
        check_links(centres, orientations, ring, links)
    return centres, orientations, links


# -- the check ----------------------------------------------------------------------------------------
def check_links(centres, orientations, rings, links) -> None:
    """Raise ``ValueError`` unless ``links`` are exactly the interlocked pairs and no two tubes overlap.

    Every pair of rings whose bounding spheres (radius R + r) meet is measured: its Gauss linking
    number must be +-1 for a listed pair and 0 otherwise, and its tube gap (the least distance of the
    centre circles less r_1 + r_2) must be >= 0 (down to ``GAP_TOLERANCE`` r of rounding). The
    message names the first pair that fails, by its ring indices.

    Parameters
    ----------
    centres : array_like, shape (n, 3)
        m.
    orientations : array_like, shape (n, 4)
        Unit quaternions (w, x, y, z), body -> space.
    rings : Ring or sequence of Ring
        One ring for all or one per ring.
    links : array_like, shape (n_links, 2)
        The intended interlocked pairs.
    """
    from ..contact.tori import candidate_pairs, linking_number, torus_contacts

    centres = np.asarray(centres, dtype=float)
    orientations = np.asarray(orientations, dtype=float)
    n_rings = len(centres)
    R, r = ring_radii(rings, n_rings)
    per_ring = [rings] * n_rings if isinstance(rings, Ring) else list(rings)
    intended = {tuple(sorted(map(int, pair))) for pair in np.asarray(links, dtype=int).reshape(-1, 2)}
    pairs = np.asarray(candidate_pairs(centres, R + r), dtype=np.intp).reshape(-1, 2)
    pairs = np.sort(pairs, axis=1)
    candidates = {tuple(pair) for pair in pairs.tolist()}
    missing = intended - candidates
    if missing:
        i, j = min(missing)
        distance = np.linalg.norm(centres[i] - centres[j])
        raise ValueError(f"rings {i} and {j} are listed as linked but are {distance:g} m apart: too far to interlock")
    if pairs.size == 0:
        return
    i, j = pairs[:, 0], pairs[:, 1]
    lk = np.array([linking_number(centres[a], orientations[a], per_ring[a], centres[b], orientations[b], per_ring[b])
                   for a, b in pairs])  # fmt: skip
    gaps = np.array([np.min(torus_contacts(centres[a], orientations[a], per_ring[a], centres[b], orientations[b],
                                           per_ring[b], margin=np.inf).gap, initial=np.inf)
                     for a, b in pairs])  # fmt: skip
    for n in np.lexsort((pairs[:, 1], pairs[:, 0])):
        pair = (int(i[n]), int(j[n]))
        linked = pair in intended
        if linked and abs(lk[n]) != 1:
            raise ValueError(f"rings {pair[0]} and {pair[1]} should be interlocked but their linking number is "
                             f"{lk[n]}")  # fmt: skip
        if not linked and lk[n] != 0:
            raise ValueError(f"rings {pair[0]} and {pair[1]} are interlocked (linking number {lk[n]}) but not "
                             "listed as linked")  # fmt: skip
        if gaps[n] < -GAP_TOLERANCE * min(r[i[n]], r[j[n]]):
            raise ValueError(f"the tubes of rings {pair[0]} and {pair[1]} overlap by {-gaps[n]:.3g} m")
