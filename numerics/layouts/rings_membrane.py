r"""What the point model says of a network of rigid rings held in tension: its links' forces and its membrane.

The lattices of the earlier layouts (chains, sheets) put each ring at a point; a link in tension T of length
l then resists a turn of its line by the geometric stiffness T/l across it (the second term of the link's
stiffness matrix, :func:`ringchain.theory.sheet.link_stiffness`, a taut string's).  Loaded across its
links, a pretensioned network of points is a membrane (a string for a chain):

    sum_j (T_ij / l_ij) (w_i - w_j) = f_i  on every free point i,  w = 0 on the fixed ones,

with w the deflection along the load and f the load of each point.  :func:`membrane_deflection` solves it;
:func:`link_forces_at_rest` reads the tensions T_ij of a :class:`~ringchain.numerics.Rings` at rest (its
static state from :meth:`~ringchain.numerics.Rings.equilibrium`), so that the rigid rings' own deflection
can be set beside the point model's with the same tensions.  Beyond the paper.
"""

from __future__ import annotations

import numpy as np
from ringchain.theory import _validate as v
from ringchain.theory import hertz_stiffness

__all__ = ["link_forces_at_rest", "membrane_deflection", "taut_chain"]


def link_forces_at_rest(rings) -> np.ndarray:
    """Normal force each linked pair of ``rings`` carries in its rest pose, N, tension positive.

    Parameters
    ----------
    rings : Rings
        The network, e.g. at its static state (:meth:`~ringchain.numerics.Rings.equilibrium`).

    Returns
    -------
    ndarray, shape (n_links,)
        The force of each pair of :attr:`~ringchain.numerics.Rings.links` (summed over its contacts), the
        ``link_force`` of a run at its first instant.
    """
    from .rings import Rings, RingsSimulation

    if not isinstance(rings, Rings):
        raise ValueError(f"rings must be a ringchain.numerics.Rings, got {type(rings).__name__}")
    x, u = rings.initial_motion()
    frame = RingsSimulation(t=np.zeros(1), x=x, u=u, dissipated=np.zeros(1), g=0.0, model=rings, stats={})
    return frame.link_force[0]


def membrane_deflection(centres, links, tensions, loads, fixed) -> np.ndarray:
    """Deflection of a network of points joined by taut links under loads across them (the point model), m.

    Parameters
    ----------
    centres : array_like, shape (n, 3)
        Positions of the points (ring centres), m: each link's length l_ij is the distance of its ends.
    links : array_like of int, shape (n_links, 2)
        The linked pairs.
    tensions : array_like, shape (n_links,)
        Tension T_ij of each link, N (> 0 for a link that holds: a slack link gives no stiffness).
    loads : array_like, shape (n,)
        Load f_i on each point along the deflection, N (the loads of fixed points are ignored).
    fixed : array_like of int or of bool
        The fixed points (indices, or a mask of shape (n,)); at least one, so that the membrane is held.

    Returns
    -------
    ndarray, shape (n,)
        w, m, along the loads; zero at the fixed points.

    Raises
    ------
    ValueError
        On a negative tension (N), a shape mismatch, no fixed point, or a free point that no taut link
        holds to the fixed ones (the membrane's matrix is then singular).

    Notes
    -----
    The geometric stiffness T/l of each link (:func:`ringchain.theory.sheet.link_stiffness`, the membrane term of
    a pretensioned sheet's waves, c_T^2 = T a / m along a row of the square sheet) assembled over the network:
    for a string of N + 1 links of length a and tension T carrying P at each of its N points,
    w_k = P a k (N + 1 - k) / (2 T).  Small deflections (w much less than the span, so that T and l stay as given).

    Examples
    --------
    >>> centres = np.column_stack([np.arange(5) * 0.04, np.zeros(5), np.zeros(5)])  # a string, 4 links
    >>> links = [[0, 1], [1, 2], [2, 3], [3, 4]]
    >>> w = membrane_deflection(centres, links, [10.0] * 4, [0.0, 0.0, 1.0, 0.0, 0.0], fixed=[0, 4])
    >>> round(float(w[2]) * 1e3, 9)  # P L / (4 T) = 1 N x 0.16 m / 40 N, in mm
    4.0
    """
    centres = v.as_float("centres", centres)
    if centres.ndim != 2 or centres.shape[1] != 3:
        raise ValueError(f"centres must have shape (n, 3) in m, got {centres.shape}")
    n = centres.shape[0]
    links = np.asarray(links, dtype=np.int64).reshape(-1, 2)
    if links.size and (links.min() < 0 or links.max() >= n):
        raise ValueError(f"links must hold point indices in [0, {n}), got {links.min()}..{links.max()}")
    tensions = v.nonnegative("tensions", tensions, "N")
    if tensions.shape != (len(links),):
        raise ValueError(f"tensions must have shape (n_links,) = ({len(links)},) in N, got {tensions.shape}")
    loads = v.as_float("loads", loads)
    if loads.shape != (n,):
        raise ValueError(f"loads must have shape (n,) = ({n},) in N, got {loads.shape}")
    mask = np.zeros(n, dtype=bool)
    fixed = np.asarray(fixed)
    if fixed.dtype == bool:
        if fixed.shape != (n,):
            raise ValueError(f"fixed as a mask must have shape ({n},), got {fixed.shape}")
        mask = fixed.copy()
    else:
        mask[fixed.astype(np.int64).reshape(-1)] = True
    if not mask.any():
        raise ValueError("fixed must name at least one point: a free membrane has no static deflection")
    i, j = links.T
    length = np.linalg.norm(centres[j] - centres[i], axis=1)
    k = tensions / length  # geometric stiffness of each link, N/m
    stiffness = np.zeros((n, n))
    np.add.at(stiffness, (i, i), k)
    np.add.at(stiffness, (j, j), k)
    np.add.at(stiffness, (i, j), -k)
    np.add.at(stiffness, (j, i), -k)
    free = np.flatnonzero(~mask)
    w = np.zeros(n)
    if free.size:
        block = stiffness[np.ix_(free, free)]
        if np.linalg.matrix_rank(block) < free.size:
            raise ValueError("a free point is not held to the fixed ones by taut links (the membrane is singular)")
        w[free] = np.linalg.solve(block, loads[free])
    return w


def taut_chain(n_rings, ring, tension, **options):
    """The paper's chain laid along x between two fixed end rings, stretched so that every contact carries ``tension``.

    Parameters
    ----------
    n_rings : int
        Number of rings, the two fixed ends included, at least 3.
    ring : ringchain.theory.Ring
        The rings' geometry and material.
    tension : float
        Pretension of every contact, N (> 0).
    **options
        To :meth:`~ringchain.numerics.Rings.from_rings` (law, friction, dashpot); the law must be Hertz's (the
        default).

    Returns
    -------
    Rings
        The rings of :func:`~ringchain.numerics.layouts.rings_layouts.chain_layout` turned to lie along x (ring 0
        and ring n - 1 fixed), their centres a + delta apart: delta = (T / K_c)^(2/3), the approach of the Hertz
        contact of Eq. (1) at 90 degrees (:func:`ringchain.theory.hertz_stiffness`), so that without gravity
        the chain is at rest with tension T in every contact.
    """
    from .rings import Rings
    from .rings_layouts import chain_layout, quaternion_about, quaternion_product

    n = v.count("n_rings", n_rings, 3)
    tension = float(v.positive("tension", tension, "N"))
    if options.get("law", "hertz") != "hertz":
        raise ValueError(f"taut_chain pretensions the Hertz law only, got law={options['law']!r}")
    _, orientations, _ = chain_layout(n, ring)
    along_x = quaternion_about([0.0, 1.0, 0.0], np.pi / 2)  # the chain's axis z turned onto x
    orientations = quaternion_product(np.broadcast_to(along_x, orientations.shape), orientations)
    K_c = float(hertz_stiffness(ring.R, ring.r, ring.material.E, ring.material.nu))
    centres = np.zeros((n, 3))
    centres[:, 0] = np.arange(n) * (ring.spacing + (tension / K_c) ** (2.0 / 3.0))
    return Rings.from_rings(centres, orientations, ring, fixed=[0, n - 1], **options)
