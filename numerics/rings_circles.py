"""Least distance and linking number of pairs of circles, vectorised over the pairs (checks of layouts).

Provisional: the contact geometry of tori in any pose belongs to the torus-contact module; these two
functions serve :func:`ringchain.numerics.rings_layouts.check_links` until it lands.
"""

from __future__ import annotations

import numpy as np

__all__ = ["circle_gaps", "closest_points", "linking_numbers"]


def _frames(axes):
    axes = axes / np.linalg.norm(axes, axis=-1, keepdims=True)
    helper = np.where(np.abs(axes[:, :1]) < 0.9, np.array([[1.0, 0.0, 0.0]]), np.array([[0.0, 1.0, 0.0]]))
    e1 = np.cross(axes, helper)
    e1 /= np.linalg.norm(e1, axis=-1, keepdims=True)
    return axes, e1, np.cross(axes, e1)


def _distance_to_circle(points, centre, axis, R):
    """Distance of points (P, N, 3) from circles (P,) of centre, unit axis and radius R."""
    d = points - centre[:, None, :]
    h = np.einsum("pnk,pk->pn", d, axis)
    rho = np.sqrt(np.maximum(np.einsum("pnk,pnk->pn", d, d) - h * h, 0.0))
    return np.hypot(h, rho - R[:, None])


def _circle_points(c, e, f, R, s):
    """Points of circles (P,) at angles s (P, N): shape (P, N, 3)."""
    return c[:, None, :] + R[:, None, None] * (np.cos(s)[..., None] * e[:, None] + np.sin(s)[..., None] * f[:, None])


def closest_points(c1, n1, R1, c2, n2, R2, samples: int = 32, newton: int = 6, every: bool = False):
    """Least distance between circle 1 and circle 2 of each pair, with the two closest points.

    Circle 1 is sampled at ``samples`` angles, the distance of each sample from circle 2 being exact
    (the point's height over the plane of circle 2 and its radial offset from it); each local minimum of
    the samples (``every=True``) or the least one is refined by ``newton`` Newton steps on that distance
    as a function of the angle (central differences).  Returns ``(pair, distance, point_1, point_2)``:
    the pair index of each minimum (P',), its distance (P',), m, and the closest points (P', 3).
    """
    c1, c2 = np.atleast_2d(np.asarray(c1, dtype=float)), np.atleast_2d(np.asarray(c2, dtype=float))
    n1, e1, f1 = _frames(np.atleast_2d(np.asarray(n1, dtype=float)))
    n2 = _frames(np.atleast_2d(np.asarray(n2, dtype=float)))[0]
    R1 = np.broadcast_to(np.asarray(R1, dtype=float), len(c1))
    R2 = np.broadcast_to(np.asarray(R2, dtype=float), len(c1))
    step = 2 * np.pi / samples
    f = _distance_to_circle(_circle_points(c1, e1, f1, R1, np.broadcast_to(np.arange(samples) * step,
                            (len(c1), samples))), c2, n2, R2)  # fmt: skip
    if every:
        minimum = (f <= np.roll(f, 1, axis=1)) & (f < np.roll(f, -1, axis=1))
        pair, k = np.nonzero(minimum)
    else:
        pair, k = np.arange(len(c1)), np.argmin(f, axis=1)
    c1, e1, f1, R1, c2, n2, R2 = c1[pair], e1[pair], f1[pair], R1[pair], c2[pair], n2[pair], R2[pair]

    def distance(s):
        return _distance_to_circle(_circle_points(c1, e1, f1, R1, s), c2, n2, R2)

    s = k * step
    h = 1e-4
    for _ in range(newton):
        lo, mid, hi = distance(np.stack([s - h, s, s + h], axis=1)).T
        curvature = (hi - 2 * mid + lo) / (h * h)
        move = np.where(curvature > 0, -(hi - lo) / (2 * h) / np.where(curvature > 0, curvature, 1.0), 0.0)
        s = s + np.clip(move, -step, step)
    if every and len(s) > 1:  # two samples of one pair that refined to the same minimum count once
        same = (pair[1:] == pair[:-1]) & (np.abs(np.angle(np.exp(1j * (s[1:] - s[:-1])))) < 1e-6)
        keep = np.concatenate([[True], ~same])
        pair, s, c1, e1, f1, R1, c2, n2, R2 = (x[keep] for x in (pair, s, c1, e1, f1, R1, c2, n2, R2))
    point_1 = _circle_points(c1, e1, f1, R1, s[:, None])[:, 0]
    d = point_1 - c2
    radial = d - np.einsum("pk,pk->p", d, n2)[:, None] * n2
    radial /= np.linalg.norm(radial, axis=1, keepdims=True)
    point_2 = c2 + R2[:, None] * radial
    return pair, np.linalg.norm(point_2 - point_1, axis=1), point_1, point_2


def circle_gaps(c1, n1, R1, c2, n2, R2) -> np.ndarray:
    """Least distance between circle 1 and circle 2 of each pair, m (:func:`closest_points`)."""
    return closest_points(c1, n1, R1, c2, n2, R2, samples=96)[1]


def linking_numbers(c1, n1, R1, c2, n2, R2, samples: int = 720) -> np.ndarray:
    """Linking number of each pair of circles: signed crossings of circle 2 through the disc of circle 1."""
    c1, c2 = np.atleast_2d(c1), np.atleast_2d(c2)
    n1 = _frames(np.atleast_2d(n1))[0]
    n2, e2, f2 = _frames(np.atleast_2d(n2))
    R1, R2 = np.broadcast_to(R1, len(c1)).astype(float), np.broadcast_to(R2, len(c1)).astype(float)
    s = np.linspace(0.0, 2 * np.pi, samples + 1)
    points = c2[:, None, :] + R2[:, None, None] * (
        np.cos(s)[None, :, None] * e2[:, None] + np.sin(s)[None, :, None] * f2[:, None]
    )
    h = np.einsum("pnk,pk->pn", points - c1[:, None, :], n1)
    cross = (h[:, :-1] >= 0) != (h[:, 1:] >= 0)  # a sample exactly in the plane counts once
    t = np.where(cross, h[:, :-1] / np.where(cross, h[:, :-1] - h[:, 1:], 1.0), 0.0)
    where = points[:, :-1] + t[..., None] * (points[:, 1:] - points[:, :-1])
    inside = np.linalg.norm(where - c1[:, None, :], axis=-1) < R1[:, None]
    return np.sum(np.where(cross & inside, np.sign(h[:, 1:] - h[:, :-1]), 0.0), axis=1).astype(int)
