r"""The static state of a network of rigid rings under gravity, its fixed rings held: energy minimisation.

:func:`equilibrium` minimises the potential energy -- gravity, sum m g z, plus the elastic energy of every
contact, K delta^(n+1) / (n + 1) for an approach delta = r_1 + r_2 - d (d the least distance between
the two centre circles) -- over the centres and orientations of the free rings, with L-BFGS
(:func:`scipy.optimize.minimize`). Each ring's orientation is the rotation vector theta of
q = exp(theta) q_0 about its pose q_0 at the start of a round; the gradient is the negative of the
forces and of the torques mapped through the left Jacobian of SO(3),
dU/dtheta = -J_l(theta)^T tau, exact at every theta (so the line search sees the true slope). Rounds
restart from the last pose with theta = 0 and a fresh list of candidate pairs (bounding spheres of
radius R + r, with a skin of r), until the largest residual force is below ``force_tol`` times the
heaviest weight and the largest torque below ``force_tol`` m g R.

Contacts: every pair whose centre circles come closer than r_1 + r_2, linked or not, one contact per
pair at the pair's least distance (:func:`~ringchain.numerics.rings_contact.closest_points`), acting
along the line of the two closest points of the centre circles. Law: the power law F = K delta^n of
paper Eq. (4) with one (K, n) for every contact; by default each pair's Hertz contact at 90 degrees,
K_c of Eq. (1) and n = 3/2 (the interlocked crossing of the chain and of the 4-in-1 weave).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from ringchain.theory import STANDARD_GRAVITY, Ring
from ringchain.theory import _validate as v

from .rings_circles import closest_points
from .rings_layouts import quaternion_about, quaternion_product, ring_radii, rotate

__all__ = ["equilibrium", "contact_state", "StaticState"]


@dataclass(frozen=True)
class StaticState:
    """The result of :func:`equilibrium`.

    Attributes
    ----------
    centres : ndarray (n, 3)
        m.
    orientations : ndarray (n, 4)
        Unit quaternions (w, x, y, z), body -> space.
    pairs : ndarray (n_contacts, 2)
        The pairs in contact at rest.
    approach : ndarray (n_contacts,)
        delta of each contact, m (positive: compressed).
    force : ndarray (n_contacts,)
        N.
    energy : float
        Potential energy, J (gravity from z = 0).
    residual_force, residual_torque : float
        Largest force (N) and torque (N m) left on a free ring.
    rounds, evaluations : int
        L-BFGS rounds and energy evaluations.
    """

    centres: np.ndarray
    orientations: np.ndarray
    pairs: np.ndarray
    approach: np.ndarray
    force: np.ndarray
    energy: float
    residual_force: float
    residual_torque: float
    rounds: int
    evaluations: int


def _masses(rings, n):
    if isinstance(rings, Ring):
        return np.full(n, rings.mass)
    return np.array([ring.mass for ring in rings])


def _default_law(rings):
    ring = rings if isinstance(rings, Ring) else rings[0]
    return ring.K_c if ring.angle == np.pi / 2 else Ring(ring.R, ring.r, ring.material).K_c, 1.5


def contact_state(centres, orientations, R, r, pairs, K, n):
    """Contacts of ``pairs`` in a pose: approach (m), force (N), energy (J), and forces and torques on the rings.

    Every local minimum of the distance between a pair's centre circles is a contact (two for parallel
    rings side by side, or linked rings at a small angle).  Returns ``(contact_pairs, delta, force, energy,
    forces (N, shape (n_rings, 3)), torques (N m, in space, (n_rings, 3)))``; a contact whose tubes are apart
    has delta < 0 and no force.
    """
    i, j = pairs[:, 0], pairs[:, 1]
    axes = rotate(orientations, np.array([0.0, 0.0, 1.0]))
    which, d, p1, p2 = closest_points(centres[i], axes[i], R[i], centres[j], axes[j], R[j], every=True)
    i, j = i[which], j[which]
    delta = r[i] + r[j] - d
    touching = delta > 0
    squeeze = np.where(touching, delta, 0.0)
    force = K * squeeze**n
    energy = float(np.sum(K * squeeze ** (n + 1) / (n + 1)))
    normal = (p2 - p1) / np.where(d > 0, d, 1.0)[:, None]  # from ring i towards ring j
    on_j = force[:, None] * normal
    forces, torques = np.zeros_like(centres), np.zeros_like(centres)
    np.add.at(forces, j, on_j)
    np.add.at(forces, i, -on_j)
    np.add.at(torques, j, np.cross(p2 - centres[j], on_j))
    np.add.at(torques, i, np.cross(p1 - centres[i], -on_j))
    return np.stack([i, j], axis=1), delta, force, energy, forces, torques


def _left_jacobian(theta):
    t = np.linalg.norm(theta, axis=1)[:, None, None]
    small = t < 1e-6
    t = np.where(small, 1.0, t)
    K = np.zeros((len(theta), 3, 3))
    K[:, 0, 1], K[:, 0, 2], K[:, 1, 2] = -theta[:, 2], theta[:, 1], -theta[:, 0]
    K[:, 1, 0], K[:, 2, 0], K[:, 2, 1] = theta[:, 2], -theta[:, 1], theta[:, 0]
    a = np.where(small, 0.5, (1 - np.cos(t)) / t**2)
    b = np.where(small, 1.0 / 6.0, (t - np.sin(t)) / t**3)
    return np.eye(3) + a * K + b * K @ K


def _exp(theta):
    t = np.linalg.norm(theta, axis=1)
    axis = np.where(t[:, None] > 0, theta, np.array([[0.0, 0.0, 1.0]]))
    return quaternion_about(axis, t)


def _lbfgs(gradient, x, *, tol, max_step, max_iterations, memory=20):
    """L-BFGS with a line search on the directional derivative alone: x where max |gradient| <= tol.

    The energy of stiff contacts under gravity changes by less than its own rounding near the minimum
    (a residual force F on a contact of stiffness k is worth F^2 / k), so the search brackets the zero
    of the slope along the direction (secant steps, expanding until it changes sign) and accepts a
    step once the slope has fallen to 0.9 of its first value (the curvature condition of Wolfe).
    Trial steps are capped at ``max_step`` in every variable (no ring jumps through another).
    Returns (x, gradient, iterations, evaluations).
    """
    g = gradient(x)
    evaluations, history = 1, []
    for iteration in range(max_iterations):
        if np.max(np.abs(g)) <= tol:
            return x, g, iteration, evaluations
        d = -g
        alphas = []
        for s_k, y_k, rho in reversed(history):
            alpha = rho * (s_k @ d)
            d -= alpha * y_k
            alphas.append(alpha)
        if history:
            s_k, y_k, _ = history[-1]
            d *= (s_k @ y_k) / (y_k @ y_k)
        for (s_k, y_k, rho), alpha in zip(history, reversed(alphas), strict=True):
            d += s_k * (alpha - rho * (y_k @ d))
        slope0 = d @ g
        if slope0 >= 0:  # not a descent direction: start again from steepest descent
            history.clear()
            d, slope0 = -g, -(g @ g)
        cap = max_step / max(np.max(np.abs(d)), 1e-300)
        lo, slope_lo, hi, slope_hi = 0.0, slope0, None, None
        step = min(1.0, cap)
        for _ in range(40):
            g_new = gradient(x + step * d)
            evaluations += 1
            slope = d @ g_new
            if abs(slope) <= 0.9 * abs(slope0):
                break
            if slope < 0:
                lo, slope_lo = step, slope
                if hi is None:
                    step = min(step * 4, lo + cap) if slope_lo == slope0 else lo + min(3 * (lo - 0.0), cap)
                    continue
            else:
                hi, slope_hi = step, slope
            # secant between the bracket's ends, kept inside it
            step = lo - slope_lo * (hi - lo) / (slope_hi - slope_lo)
            step = min(max(step, lo + 0.1 * (hi - lo)), hi - 0.1 * (hi - lo))
        s_new = step * d
        y_new = g_new - g
        if s_new @ y_new > 0:
            history.append((s_new, y_new, 1.0 / (s_new @ y_new)))
            if len(history) > memory:
                history.pop(0)
        x, g = x + s_new, g_new
    return x, g, max_iterations, evaluations


#: Softened contact stiffnesses, as fractions of the law's K, solved in turn before the law itself: the soft
#: contacts let the network move far at little cost (a drape), the stiff ones then only settle it.
_SOFTENING = (1e-6, 1e-4, 1e-2)


def _fire(gradient, x, *, tol, stiffness, max_iterations, max_move=0.5):
    """Damped dynamics (FIRE: Bitzek et al., Phys. Rev. Lett. 97, 170201 (2006)) to max |gradient| <= tol.

    The fallback of L-BFGS where the energy is not smooth enough for a line search (contacts that
    appear, merge or split as rings slide); unit masses in the scaled variables, the time step bounded
    by the contacts' stiffness and each step's move by ``max_move``.  Stops after ``max_iterations`` steps
    or when the variables have moved ``max_move`` from the start... (a new round then starts with fresh
    candidate pairs).  Returns (x, gradient, iterations, evaluations).
    """
    dt_max = 0.5 / np.sqrt(1e6 * stiffness)
    dt, a, positive = 0.1 * dt_max, 0.1, 0
    velocity = np.zeros_like(x)
    start = x.copy()
    g = gradient(x)
    for iteration in range(max_iterations):
        if np.max(np.abs(g)) <= tol or np.max(np.abs(x - start)) > 2 * max_move:
            return x, g, iteration, iteration + 1
        force = -g
        power = force @ velocity
        if power > 0:
            norm = np.linalg.norm(force)
            velocity = (1 - a) * velocity + a * np.linalg.norm(velocity) * force / max(norm, 1e-300)
            positive += 1
            if positive > 5:
                dt, a = min(dt * 1.1, dt_max), a * 0.99
        else:
            velocity[:] = 0.0
            dt, a, positive = dt * 0.5, 0.1, 0
        velocity += dt * force
        move = dt * velocity
        largest = np.max(np.abs(move))
        if largest > 0.1 * max_move:
            move *= 0.1 * max_move / largest
            velocity *= 0.1 * max_move / largest
        x = x + move
        g = gradient(x)
    return x, g, max_iterations, max_iterations + 1


def equilibrium(centres, orientations, rings, *, fixed=(), law=None, g=STANDARD_GRAVITY, force_tol=1e-8,
                max_rounds=50, max_iterations=2000) -> StaticState:  # fmt: skip
    """The static state of rigid rings under gravity (along -z), the ``fixed`` rings held where they are.

    Parameters
    ----------
    centres : array_like, shape (n, 3)
        Starting centres, m (a layout's rest pose).
    orientations : array_like, shape (n, 4)
        Starting orientations, unit quaternions (w, x, y, z), body -> space.
    rings : Ring or sequence of Ring
        Geometry and material (mass m0) of each ring.
    fixed : sequence of int
        Rings held in place (anchors).
    law : (float, float), optional
        (K in N/m^n, n) of the power law F = K delta^n (Eq. (4)) at every contact; default the Hertz
        contact of the (first) ring at 90 degrees, (K_c, 3/2) (Eq. (1)).
    g : float
        Gravity, m/s^2 (>= 0).
    force_tol : float
        Largest residual force on a free ring, as a fraction of the heaviest weight m g (torques:
        of m g R).
    max_rounds, max_iterations : int
        L-BFGS rounds (each with fresh candidate pairs) and iterations per round.

    Returns
    -------
    StaticState

    Raises
    ------
    RuntimeError
        If the residuals are still above ``force_tol`` after ``max_rounds`` rounds.
    """
    from scipy.spatial import cKDTree

    centres = v.as_float("centres", centres).reshape(-1, 3).copy()
    n = len(centres)
    orientations = v.as_float("orientations", orientations).reshape(n, 4).copy()
    R, r = ring_radii(rings, n)
    m = _masses(rings, n)
    g = float(v.nonnegative("g", g, "m/s^2"))
    K, exponent = _default_law(rings) if law is None else (float(law[0]), float(law[1]))
    v.positive("K", K, "N/m^n")
    v.positive("n", exponent)
    force_tol = float(v.positive("force_tol", force_tol))
    free = np.ones(n, dtype=bool)
    free[np.asarray(fixed, dtype=np.intp)] = False
    moving = np.flatnonzero(free)
    weight = max(float(np.max(m)) * g, 1e-300)
    length = float(np.max(r))  # variable scale: positions in tube radii, energy in m g r
    reach = float(np.max(R))
    torque_scale = weight * reach
    evaluations, rounds = 0, 0
    stages = [(scale, max(force_tol, 1e-3)) for scale in _SOFTENING] + [(1.0, force_tol)]
    for softening, tol in stages:
        for _ in range(max_rounds):
            rounds += 1
            skin = 2 * length
            pairs = cKDTree(centres).query_pairs(2 * float(np.max(R + r)) + skin, output_type="ndarray")
            pairs = pairs[free[pairs[:, 0]] | free[pairs[:, 1]]] if pairs.size else np.zeros((0, 2), dtype=np.intp)
            start_c, start_q = centres.copy(), orientations.copy()
            stiffness = softening * K

            def pose(x, start_c=start_c, start_q=start_q):
                x = x.reshape(-1, 6)
                c, q = start_c.copy(), start_q.copy()
                c[moving] += x[:, :3] * length
                theta = x[:, 3:] * (length / reach)  # rotations in units that move a rim by one tube radius
                q[moving] = quaternion_product(_exp(theta), start_q[moving])
                return c, q, theta

            def energy_gradient(x, pairs=pairs, pose=pose, stiffness=stiffness):
                c, q, theta = pose(x)
                elastic, forces, torques = contact_state(c, q, R, r, pairs, stiffness, exponent)[3:]
                # gravity from the round's start: small numbers, so the line search sees small changes
                U = elastic + g * length * float(np.sum(m[moving] * x.reshape(-1, 6)[:, 2]))
                forces[:, 2] -= m * g
                grad_c = -forces[moving] / weight
                grad_t = -np.einsum("nji,nj->ni", _left_jacobian(theta), torques[moving]) / torque_scale
                return U / (weight * length), np.concatenate([grad_c, grad_t], axis=1).ravel()

            x0 = np.zeros(6 * len(moving))
            x, _, _, count = _lbfgs(lambda x: energy_gradient(x)[1], x0, tol=tol, max_step=0.2,
                                    max_iterations=max_iterations) if softening == 1 else _fire(
                lambda x: energy_gradient(x)[1], x0, tol=tol, stiffness=softening, max_iterations=max_iterations)  # fmt: skip
            evaluations += count
            centres, orientations, _ = pose(x)
            orientations /= np.linalg.norm(orientations, axis=1, keepdims=True)
            contacts, delta, force, elastic, forces, torques = contact_state(
                centres, orientations, R, r, pairs, stiffness,
                                                                   exponent)  # fmt: skip
            forces[:, 2] -= m * g
            residual_force = float(np.max(np.abs(forces[moving]), initial=0.0))
            residual_torque = float(np.max(np.abs(torques[moving]), initial=0.0))
            moved = np.max(np.linalg.norm(centres - start_c, axis=1), initial=0.0)
            if residual_force <= tol * weight and residual_torque <= tol * torque_scale and moved < skin / 2:
                break
        else:
            raise RuntimeError(f"no static state within {max_rounds} rounds of L-BFGS at {softening:g} K: largest "
                               f"residual force {residual_force:.3g} N (goal {tol * weight:.3g} N), torque "
                               f"{residual_torque:.3g} N m")  # fmt: skip
    touching = delta > 0
    return StaticState(centres, orientations, contacts[touching], delta[touching], force[touching],
                       elastic + g * float(np.sum(m * centres[:, 2])), residual_force, residual_torque, rounds,
                       evaluations)  # fmt: skip
