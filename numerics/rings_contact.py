"""Least distance and linking number of pairs of circles, vectorised over the pairs (checks of layouts).

Provisional: the contact geometry of tori in any pose belongs to the torus-contact module; these two
functions serve :func:`ringchain.numerics.rings_layouts.check_links` until it lands.
"""

from __future__ import annotations

import numpy as np

__all__ = ["circle_gaps", "linking_numbers"]


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


def circle_gaps(c1, n1, R1, c2, n2, R2, samples: int = 96, iterations: int = 60) -> np.ndarray:
    """Least distance between circle 1 and circle 2 of each pair, m (sampling, then golden section)."""
    c1, c2 = np.atleast_2d(c1), np.atleast_2d(c2)
    n1, e1, f1 = _frames(np.atleast_2d(n1))
    n2 = _frames(np.atleast_2d(n2))[0]
    R1, R2 = np.broadcast_to(R1, len(c1)).astype(float), np.broadcast_to(R2, len(c1)).astype(float)

    def distance(s):
        points = c1[:, None, :] + R1[:, None, None] * (
            np.cos(s)[..., None] * e1[:, None] + np.sin(s)[..., None] * f1[:, None]
        )
        return _distance_to_circle(points, c2, n2, R2)

    step = 2 * np.pi / samples
    s = np.broadcast_to(np.arange(samples) * step, (len(c1), samples))
    best = np.argmin(distance(s), axis=1)
    lo, hi = (best - 1) * step, (best + 1) * step
    ratio = (np.sqrt(5) - 1) / 2
    for _ in range(iterations):
        a, b = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
        da, db = distance(np.stack([a, b], axis=1)).T
        hi, lo = np.where(da < db, b, hi), np.where(da < db, lo, a)
    return distance(0.5 * (lo + hi)[:, None])[:, 0]


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
