r"""The static state of a network of rigid rings under gravity, its fixed rings held: :meth:`Rings.equilibrium`.

:func:`equilibrium` minimises the potential energy of a :class:`~ringchain.numerics.Rings` -- gravity,
sum m g z, plus the elastic energy of every contact (:meth:`Rings.potential`: the network's own contact
law, every local minimum of the distance of two centre circles a contact) -- over the centres and
orientations of the free rings.  Each ring's orientation is the rotation vector theta of
q = exp(theta) q_0 about its starting pose q_0; the gradient is the negative of the forces and of the
torques mapped through the left Jacobian of SO(3), dU/dtheta = -J_l(theta)^T tau, exact at every theta.

Two solvers, because the contacts are stiff.  Near the minimum a residual force F on a contact of
stiffness k is worth F^2 / k of energy, below the rounding of the energy itself, so a line search on
the energy stalls; :func:`_lbfgs` searches on the slope alone.  Far from it (a sheet that drapes, its
rings sliding by centimetres), the contacts appear and vanish as rings slide and L-BFGS's model of the
energy is poor; damped dynamics (FIRE, :func:`_fire`) first settles the network on contacts softened to
1e-6, 1e-4 and 1e-2 of their stiffness, then L-BFGS finishes on the law itself.  Converged when the largest
residual force on a free ring is below ``force_tol`` times the heaviest weight m g, and the largest
torque below ``force_tol`` m g R.
"""

from __future__ import annotations

import dataclasses

import numpy as np
from ringchain.theory import STANDARD_GRAVITY
from ringchain.theory import _validate as v

from .rings_layouts import quaternion_about, quaternion_product

__all__ = ["equilibrium"]


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


def _fire(gradient, x, *, tol, stiffness, max_iterations, max_move=0.5):
    """Damped dynamics (FIRE: Bitzek et al., Phys. Rev. Lett. 97, 170201 (2006)) to max |gradient| <= tol.

    The fallback of L-BFGS where the energy is not smooth enough for a line search (contacts that
    appear, merge or split as rings slide); unit masses in the scaled variables, the time step bounded
    by the contacts' stiffness and each step's move by ``max_move``.  Stops after ``max_iterations`` steps.
    Returns (x, gradient, iterations, evaluations).
    """
    dt_max = 0.5 / np.sqrt(1e6 * stiffness)
    dt, a, positive = 0.1 * dt_max, 0.1, 0
    velocity = np.zeros_like(x)
    g = gradient(x)
    for iteration in range(max_iterations):
        if np.max(np.abs(g)) <= tol:
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


#: Softened contact stiffnesses, as fractions of the law's K, settled in turn by damped dynamics before the law
#: itself: the soft contacts let the network move far at little cost (a drape), the stiff ones then only settle it.
SOFTENING = (1e-6, 1e-4, 1e-2)


def equilibrium(network, *, g=STANDARD_GRAVITY, force_tol=1e-8, soften=True, max_iterations=2000):
    """The network at its static state under gravity (along -z), its fixed rings held where they are.

    Parameters
    ----------
    network : Rings
        The rings, their law and anchors; its rest pose is the start.
    g : float
        Gravity, m/s^2 (> 0).
    force_tol : float
        Largest residual force on a free ring, as a fraction of the heaviest weight m g (torques: of
        m g R with R the largest major radius).
    soften : bool
        Settle on softened contacts first (:data:`SOFTENING`; needed when the rings move far, as in a drape;
        a chain that only stretches needs none).
    max_iterations : int
        Steps of each stage (damped dynamics) or iterations of L-BFGS.

    Returns
    -------
    Rings
        The same network (laws, anchors) at rest in its static state (:meth:`Rings.moved`).

    Raises
    ------
    RuntimeError
        If the residuals are still above ``force_tol`` at the end.
    """
    g = float(v.positive("g", g, "m/s^2"))
    force_tol = float(v.positive("force_tol", force_tol))
    max_iterations = v.count("max_iterations", max_iterations, 1)
    masses = network.masses
    moving = np.flatnonzero(~network.fixed)
    weight = float(np.max(masses)) * g
    length = float(max(ring.r for ring in network.rings))  # variable scale: positions in tube radii
    reach = float(max(ring.R for ring in network.rings))
    torque_scale = weight * reach
    centres, orientations = network.centres.copy(), network.orientations.copy()
    stages = [(scale, max(force_tol, 1e-3)) for scale in (SOFTENING if v.boolean("soften", soften) else ())]
    for softening, tol in [*stages, (1.0, force_tol)]:
        model = dataclasses.replace(network, stiffness=network.stiffness * softening)
        start_c, start_q = centres.copy(), orientations.copy()

        def pose(x, start_c=start_c, start_q=start_q):
            x = x.reshape(-1, 6)
            c, q = start_c.copy(), start_q.copy()
            c[moving] += x[:, :3] * length
            theta = x[:, 3:] * (length / reach)  # rotations in units that move a rim by one tube radius
            q[moving] = quaternion_product(_exp(theta), start_q[moving])
            return c, q, theta

        def gradient(x, pose=pose, model=model):
            c, q, theta = pose(x)
            _, forces, torques = model.potential(c, q, g)
            grad_c = -forces[moving] / weight
            grad_t = -np.einsum("nji,nj->ni", _left_jacobian(theta), torques[moving]) / torque_scale
            return np.concatenate([grad_c, grad_t], axis=1).ravel()

        x0 = np.zeros(6 * len(moving))
        if softening < 1:
            x = _fire(gradient, x0, tol=tol, stiffness=softening, max_iterations=max_iterations)[0]
        else:
            x = _lbfgs(gradient, x0, tol=tol, max_step=0.2, max_iterations=max_iterations)[0]
        centres, orientations, _ = pose(x)
        orientations /= np.linalg.norm(orientations, axis=1, keepdims=True)
    _, forces, torques = network.potential(centres, orientations, g)
    residual_force = float(np.max(np.abs(forces[moving]), initial=0.0))
    residual_torque = float(np.max(np.abs(torques[moving]), initial=0.0))
    if residual_force > force_tol * weight or residual_torque > force_tol * torque_scale:
        raise RuntimeError(f"no static state within {max_iterations} iterations: largest residual force "
                           f"{residual_force:.3g} N (goal {force_tol * weight:.3g} N), torque {residual_torque:.3g} "
                           f"N m (goal {force_tol * torque_scale:.3g} N m)")  # fmt: skip
    return network.moved(centres, orientations)
