r"""Compiled kernels of rigid rings in space: their right-hand side, a splitting scheme for long runs, and their
contact forces, on the engine of :mod:`ringchain.numerics.engine.kernels`.

The model (:class:`~ringchain.numerics.Rings`, kind 2 of a :class:`~ringchain.numerics.engine.kernels.Packed` model).
Per ring seven coordinates x = [displacement of the centre from its reference (3, m: small numbers, whose
error the step control measures against small tolerances), unit quaternion (w, x, y, z) body -> space] and seven rates
u = [velocity (3, m/s, space), angular velocity (3, rad/s, body frame), 0] (the seventh rate pads the state so
that x and u have one length, as the engine's dopri5 loop wants; its derivative is zero).  The packed arrays
hold (:meth:`~ringchain.numerics.Rings.packed`):

- ``coupling`` (n, 9): per ring [R, r, m, I_1 (a diameter), I_3 (the axis), fixed, reference centre (3, m)];
- ``li``, ``lj``, ``kind`` (L,): the candidate pairs and their law (the kind of
  :func:`~ringchain.numerics.engine.rings_law.contact_force`: 0 Hertz of the curvatures, 1 F = K delta^n);
- ``par`` (1, L, 4): per pair [K (N/m^n), n, dashpot gamma (N s/m), friction coefficient mu];
- ``spans`` (L,): per pair the effective modulus E* (Pa) of the Hertz law;
- ``rest_vectors`` (L, 1 + MAX_CONTACTS): the warm start of each pair's contacts [count, the angles s_1 of
  its minima on ring i's centre circle], updated by every evaluation (one run at a time);
- ``floats`` [v_f, step]: the slip speed of the regularised Coulomb law (m/s) and the step of the table of
  the elliptical factor of the Hertz law, ``inv_top``;
- ``gravity`` (1, 7n): per unit g, the acceleration of each coordinate (-1 on the z of free rings);
- ``ints``: [2, 3, 7n, damped, n, L, search, 0, 0, 0]: ``search`` is 1 when the next evaluation of
  :func:`rings_derivative` is to search the contacts (the first after an accepted step), 0 in between.

The equations (Euler's in the body frame): dx/dt = v; dq/dt = q (x) (0, omega)/2; m dv/dt = F - m g e_z;
I domega/dt = tau_body - omega x (I omega), I = diag(I_1, I_1, I_3).  The rotation matrix is that of q/|q|,
so a quaternion whose norm drifts within a step still rotates rigidly; the dopri5 loop sets |q| = 1 after
each accepted step (:func:`normalise`).

Contacts.  The geometry and the law are those of :mod:`ringchain.numerics.engine.rings_kernels`: every local
minimum of the distance of the two centre circles (warm-started Newton, the cold scan as fallback), the tubes
overlapping by delta = r_1 + r_2 - d where it is below the sum of the tube radii; the normal force
[K delta^n + gamma d(delta)/dt]_+ (Hertz's K bounded near a fold by the gap's quartic, C of
:func:`~ringchain.numerics.engine.rings_law.fold_quartic` from the pair's radii, the force then the derivative of the
stored energy: :func:`~ringchain.numerics.engine.rings_law.contact_stiffness`) and the regularised Coulomb friction
at the contact point, forces and torques on both rings, and the loads of the pose derivatives of Hertz's K_c and
of the shares of twin contacts by a fold (:func:`~ringchain.numerics.engine.rings_law.stiffness_slopes`,
:func:`~ringchain.numerics.engine.rings_kernels.fold_weights`), so that the elastic loads are the gradient of the
stored energy (a rattle of four rings with Hertz's law holds its energy to 1.3e-11 of the impact's, 2e-7 without
them).  Their dissipated power (dashpot and friction) is the rate of the state's dissipated energy W.
The search (:func:`~ringchain.numerics.engine.rings_kernels.pair_contacts_warm`, with its checks for
minima that split or are born next to the ones it follows) runs once per accepted step of the Runge-Kutta
loop, at the first evaluation after it (:func:`normalise` raises the flag); the other stages follow the
minima from the angles of that search by one Newton step
(:func:`~ringchain.numerics.engine.rings_kernels.pair_contacts_follow`; the gap is stationary at a minimum, so
the angle's error enters the gap at second order), falling back on the search where a Newton step meets
g'' <= 0.  Measured on the struck chain of 1,000 rings (999 pairs, a loaded machine), the search costs 2.8 ms
an evaluation, the follow 1.9 ms; dopri5's run (benchmarks/bench_rings.py) 15 % less processor time.
The splitting scheme, :meth:`~ringchain.numerics.Rings.potential` and the contact records search at every
evaluation.

Velocity Verlet for rings (:func:`verlet_rings`).  A symmetric splitting (kick, drift, kick): half kicks of
the velocities and body angular momenta by the forces and torques, between which the positions drift and
each ring turns as the free symmetric rotor it is, exactly: with L the angular momentum in space,
q(t) = exp(t L / I_1) (x) q(0) (x) exp(t c e_3), c = L_3 (1/I_3 - 1/I_1) (both factors unit quaternions,
so |q| = 1 to round-off; renormalised each step).  Symplectic and time-reversible, second order.
"""

from __future__ import annotations

import math

import numpy as np

from . import rings_kernels, rings_law
from ._compiled import CACHE, Packed, jit
from ._kernel_calls import announce_compile, kernel_array, verlet_arrays

__all__ = [
    "rings_derivative",
    "loads",
    "normalise",
    "contact_state",
    "derivative",
    "verlet_rings",
    "CONTACTS",
]

#: Contacts per pair of rings (two where linked rings cross below theta_min).
CONTACTS = 2


@jit(inline="always")
def _rotation(q0, q1, q2, q3, R):
    """The rotation matrix of the quaternion (q0, q1, q2, q3) (normalised here) into R (3, 3)."""
    s = 1.0 / (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    R[0, 0] = 1.0 - 2.0 * s * (q2 * q2 + q3 * q3)
    R[0, 1] = 2.0 * s * (q1 * q2 - q0 * q3)
    R[0, 2] = 2.0 * s * (q1 * q3 + q0 * q2)
    R[1, 0] = 2.0 * s * (q1 * q2 + q0 * q3)
    R[1, 1] = 1.0 - 2.0 * s * (q1 * q1 + q3 * q3)
    R[1, 2] = 2.0 * s * (q2 * q3 - q0 * q1)
    R[2, 0] = 2.0 * s * (q1 * q3 - q0 * q2)
    R[2, 1] = 2.0 * s * (q2 * q3 + q0 * q1)
    R[2, 2] = 1.0 - 2.0 * s * (q1 * q1 + q2 * q2)


@jit()
def _pair(m, k, x, u, R, warm, load, rec, rows, vec, law, search, fold):
    """Forces and torques of the contacts of pair ``k`` at state (x, u), added to ``load`` (n, 6: force and torque
    about the ring's centre, in space); returns (dissipated power, elastic energy).  The pair's contacts are
    found by :func:`~ringchain.numerics.engine.rings_kernels.pair_contacts_warm` from ``warm[k]`` ([count, angles s_1
    of the last minima]; updated) and loaded by :func:`~ringchain.numerics.engine.rings_law.contact_force`; the
    CONTACTS deepest of them are described in ``rec`` (see :func:`contact_state`).  ``rows`` (MAX_CONTACTS,
    FIELDS), ``vec`` (9, 3) and ``law`` (LAW_PARAMETERS,) are work arrays (allocated once per evaluation).  Without
    ``search`` the contacts are followed from ``warm[k]`` by one Newton step
    (:func:`~ringchain.numerics.engine.rings_kernels.pair_contacts_follow`; ``warm`` left as it is), searched where
    that step fails."""
    i, j = m.li[k], m.lj[k]
    c1, c2, v1, v2, w1, w2, force, t1, t2 = vec[0], vec[1], vec[2], vec[3], vec[4], vec[5], vec[6], vec[7], vec[8]
    for c in range(3):
        c1[c] = m.coupling[i, 6 + c] + x[7 * i + c]
        c2[c] = m.coupling[j, 6 + c] + x[7 * j + c]
        v1[c], v2[c] = u[7 * i + c], u[7 * j + c]
        w1[c] = R[i, c, 0] * u[7 * i + 3] + R[i, c, 1] * u[7 * i + 4] + R[i, c, 2] * u[7 * i + 5]
        w2[c] = R[j, c, 0] * u[7 * j + 3] + R[j, c, 1] * u[7 * j + 4] + R[j, c, 2] * u[7 * j + 5]
    count = int(warm[k, 0])
    # The ints passed on are typed int64 (np.int64), not as literals: a literal (a module constant, a number) is a
    # Numba type of its own, and the search (with its scan) would compile again for the batch query's int64 calls.
    if search or count == 0 or rings_kernels.pair_contacts_follow(
        c1, x[7 * i + 3 : 7 * i + 7], m.coupling[i, 0], m.coupling[i, 1], c2, x[7 * j + 3 : 7 * j + 7],
        m.coupling[j, 0], m.coupling[j, 1], warm[k, 1:], count, np.int64(1), rows,
    ) == 0:  # fmt: skip
        count, _, _ = rings_kernels.pair_contacts_warm(
            c1, x[7 * i + 3 : 7 * i + 7], m.coupling[i, 0], m.coupling[i, 1], c2, x[7 * j + 3 : 7 * j + 7],
            m.coupling[j, 0], m.coupling[j, 1], np.int64(rings_kernels.N_SCAN), warm[k, 1:], int(warm[k, 0]),
            np.int64(8), rows,
        )  # fmt: skip
        warm[k, 0] = count
        for c in range(count):
            warm[k, 1 + c] = rows[c, 1]
    weights, slopes, tops, stored_energy, slopes_K = fold
    rings_kernels.fold_weights(c1, x[7 * i + 3 : 7 * i + 7], m.coupling[i, 0], m.coupling[i, 1], c2,
                               x[7 * j + 3 : 7 * j + 7], m.coupling[j, 0], m.coupling[j, 1], rows, count,
                               weights, slopes, tops)  # fmt: skip
    law[0], law[2], law[3] = m.kind[k], m.par[0, k, 1], m.par[0, k, 2]
    law[4], law[5] = m.par[0, k, 3], m.floats[0]
    law[7] = rings_law.fold_quartic(m.coupling[i, 0], m.coupling[i, 1], m.coupling[j, 0], m.coupling[j, 1])
    power, energy = 0.0, 0.0
    for slot in range(rec.shape[0]):
        rec[slot, 0] = -np.inf
    for c in range(count):
        law[1], law[6] = m.par[0, k, 0] * weights[c], m.spans[k] * weights[c]  # the share of a contact by a fold
        normal, stored, dashpot, friction = rings_law.contact_force(
            rows[c], c1, v1, w1, c2, v2, w2, law, m.inv_top, m.floats[1], force, t1, t2)  # fmt: skip
        power += dashpot + friction
        energy += stored
        stored_energy[c] = stored
        if law[0] == 0.0 and stored > 0.0:  # Hertz's K_c changes with the pose: the loads of its change too
            rings_law.stiffness_slopes(rows[c], c1, x[7 * i + 3 : 7 * i + 7], m.coupling[i, 0], c2,
                                           x[7 * j + 3 : 7 * j + 7], m.coupling[j, 0], law, m.inv_top, m.floats[1],
                                           slopes_K)  # fmt: skip
            for a in range(3):  # ring 2: the opposite force, and minus ring 1's torque minus (c_1 - c_2) x its force
                b, d = (a + 1) % 3, (a + 2) % 3
                load[i, a] -= stored * slopes_K[a]
                load[j, a] += stored * slopes_K[a]
                load[i, 3 + a] -= stored * slopes_K[3 + a]
                load[j, 3 + a] += stored * (
                    slopes_K[3 + a] + (c1[b] - c2[b]) * slopes_K[d] - (c1[d] - c2[d]) * slopes_K[b]
                )
        for a in range(3):
            load[i, a] += force[a]
            load[j, a] -= force[a]
            load[i, 3 + a] += t1[a]
            load[j, 3 + a] += t2[a]
        slot = rec.shape[0] - 1  # the record keeps the deepest contacts
        if -rows[c, 0] <= rec[slot, 0]:
            continue
        while slot > 0 and rec[slot - 1, 0] < -rows[c, 0]:
            for a in range(12):
                rec[slot, a] = rec[slot - 1, a]
            slot -= 1
        rec[slot, 0], rec[slot, 7], rec[slot, 11] = -rows[c, 0], normal, stored
        for a in range(3):
            rec[slot, 1 + a], rec[slot, 4 + a] = rows[c, 3 + a], rows[c, 6 + a]
            rec[slot, 8 + a] = force[a] - normal * rows[c, 6 + a]
    if count > 1:
        _fold_loads(count, weights, slopes, stored_energy, rows, tops, c1, c2, i, j, load, force)
    return power, energy


@jit()
def _fold_loads(count, weights, slopes, stored, rows, tops, c1, c2, i, j, load, force):
    """Add to ``load`` the loads of the derivatives of the shares of a pair's contacts by a fold
    (:func:`~ringchain.numerics.engine.rings_kernels.fold_weights`): the elastic energy of the pair is
    sum_a w_a phi_a, phi_a = stored[a] / w_a, and each minimum or maximum c in overlap carries the normal force
    dE/d(delta_c) = sum_a phi_a dw_a/d(delta_c) along its row's normal through its point (the approaches are
    stationary in the angles on both circles), so that the loads are minus the gradient of that energy.  ``force``
    (3,) is a work array."""
    M = rings_kernels.MAX_CONTACTS
    for c in range(2 * M):
        push = 0.0
        for a in range(count):
            if weights[a] > 0.0:
                push += stored[a] / weights[a] * slopes[a, c]
        if push == 0.0:
            continue
        row = rows[c] if c < M else tops[c - M]
        for a in range(3):
            force[a] = push * row[6 + a]
            load[i, a] += force[a]
            load[j, a] -= force[a]
        for a in range(3):  # torques about the centres, the force acting on the line of the normal through the point
            b, d = (a + 1) % 3, (a + 2) % 3
            load[i, 3 + a] += (row[3 + b] - c1[b]) * force[d] - (row[3 + d] - c1[d]) * force[b]
            load[j, 3 + a] -= (row[3 + b] - c2[b]) * force[d] - (row[3 + d] - c2[d]) * force[b]


@jit()
def _fold_work():
    """The work arrays of :func:`_pair` for the shares of contacts by a fold: weights, their slopes, the rows of the
    maxima in overlap (:func:`~ringchain.numerics.engine.rings_kernels.fold_weights`), the stored energies."""
    M = rings_kernels.MAX_CONTACTS
    return np.empty(M), np.empty((M, 2 * M)), np.empty((M, rings_kernels.FIELDS)), np.empty(M), np.empty(6)


@jit()
def loads(m, x, u, R, out, search=True):
    """Rotation matrices of every ring into R (n, 3, 3) and the contact forces and torques (space) into
    ``out`` (n, 6); returns (dissipated power, elastic energy).  ``search``: search every pair's contacts (else
    follow them from the last search: the module notes)."""
    n = m.ints[4]
    for r in range(n):
        o = 7 * r
        _rotation(x[o + 3], x[o + 4], x[o + 5], x[o + 6], R[r])
        for c in range(6):
            out[r, c] = 0.0
    power, energy = 0.0, 0.0
    rec, vec = np.empty((CONTACTS, 12)), np.empty((9, 3))
    rows, law = np.empty((rings_kernels.MAX_CONTACTS, rings_kernels.FIELDS)), np.empty(rings_law.LAW_PARAMETERS)
    fold = _fold_work()
    for k in range(m.li.size):
        pk, ek = _pair(m, k, x, u, R, m.rest_vectors, out, rec, rows, vec, law, search, fold)
        power += pk
        energy += ek
    return power, energy


@jit()
def rings_derivative(m, b, g, y, dy, N):
    """dy/dt of the rings' state y = [x (N), u (N), W if damped] (the module notes)."""
    n = m.ints[4]
    R = np.empty((n, 3, 3))
    load = np.empty((n, 6))
    x, u = y[:N], y[N : 2 * N]
    search = m.ints[6] != 0  # the first evaluation after an accepted step searches, the stages follow
    m.ints[6] = 0
    power, _ = loads(m, x, u, R, load, search)
    for r in range(n):
        o = 7 * r
        if m.coupling[r, 5] != 0.0:  # fixed
            for c in range(7):
                dy[o + c] = 0.0
                dy[N + o + c] = 0.0
            continue
        mass, I1, I3 = m.coupling[r, 2], m.coupling[r, 3], m.coupling[r, 4]
        q0, q1, q2, q3 = x[o + 3], x[o + 4], x[o + 5], x[o + 6]
        w1, w2, w3 = u[o + 3], u[o + 4], u[o + 5]
        for c in range(3):
            dy[o + c] = u[o + c]
            dy[N + o + c] = load[r, c] / mass - g * m.gravity[0, o + c]
        dy[o + 3] = -0.5 * (q1 * w1 + q2 * w2 + q3 * w3)
        dy[o + 4] = 0.5 * (q0 * w1 + q2 * w3 - q3 * w2)
        dy[o + 5] = 0.5 * (q0 * w2 + q3 * w1 - q1 * w3)
        dy[o + 6] = 0.5 * (q0 * w3 + q1 * w2 - q2 * w1)
        t1 = R[r, 0, 0] * load[r, 3] + R[r, 1, 0] * load[r, 4] + R[r, 2, 0] * load[r, 5]  # the torque in the body
        t2 = R[r, 0, 1] * load[r, 3] + R[r, 1, 1] * load[r, 4] + R[r, 2, 1] * load[r, 5]
        t3 = R[r, 0, 2] * load[r, 3] + R[r, 1, 2] * load[r, 4] + R[r, 2, 2] * load[r, 5]
        dy[N + o + 3] = (t1 + (I1 - I3) * w2 * w3) / I1
        dy[N + o + 4] = (t2 + (I3 - I1) * w3 * w1) / I1
        dy[N + o + 5] = t3 / I3
        dy[N + o + 6] = 0.0
    if y.size > 2 * N:
        dy[2 * N] = power


@jit()
def normalise(m, y, G, n):
    """|q| = 1 for every ring of the G states of length n one after the other in ``y`` (after accepted steps); the
    next evaluation searches the contacts."""
    N = m.ints[2]
    m.ints[6] = 1
    for q in range(G):
        for r in range(m.ints[4]):
            o = q * n + 7 * r + 3
            s = 1.0 / math.sqrt(y[o] ** 2 + y[o + 1] ** 2 + y[o + 2] ** 2 + y[o + 3] ** 2)
            for c in range(4):
                y[o + c] *= s
    return N


@jit()
def derivative(m, g, y, dy):
    """dy/dt of one state (the NumPy face of :func:`rings_derivative`, for SciPy's methods and tests: every
    evaluation searches the contacts)."""
    m.ints[6] = 1
    rings_derivative(m, 0, g, y, dy, m.ints[2])


@jit()
def contact_state(m, xs, us, warm, out):
    """The contacts of states ``xs``, ``us`` (T, 7n) into ``out`` (T, L, CONTACTS, 12): per pair (i, j) its
    CONTACTS deepest minima of the distance of the centre circles, each [approach delta (m: > 0 in contact,
    else minus the gap), point (3, m), normal (3, from ring j to ring i), normal force (N), friction force on
    ring i (3, N), elastic energy (J)], warm-started from ``warm`` (L, 1 + MAX_CONTACTS; updated); a slot not
    in use has delta = -inf."""
    n = m.ints[4]
    R = np.empty((n, 3, 3))
    load = np.zeros((n, 6))
    vec = np.empty((9, 3))
    rows, law = np.empty((rings_kernels.MAX_CONTACTS, rings_kernels.FIELDS)), np.empty(rings_law.LAW_PARAMETERS)
    fold = _fold_work()
    # Search every time: n >= 0 is True typed as a plain bool, as the dopri5 loop's flag, so that _pair compiles
    # once for every caller (a literal True is a type of its own: a second compile of _pair, ~6 s of CPU).
    search = n >= 0
    for k_t in range(xs.shape[0]):
        x, u = xs[k_t], us[k_t]
        for r in range(n):
            o = 7 * r
            _rotation(x[o + 3], x[o + 4], x[o + 5], x[o + 6], R[r])
        for k in range(m.li.size):
            for slot in range(CONTACTS):
                for c in range(12):
                    out[k_t, k, slot, c] = 0.0
            _pair(m, k, x, u, R, warm, load, out[k_t, k], rows, vec, law, search, fold)


# -- velocity Verlet with the free rotor -------------------------------------------------------------------------
@jit(inline="always")
def _qmul(a0, a1, a2, a3, b0, b1, b2, b3):
    return (a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3, a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
            a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1, a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0)  # fmt: skip


@jit(inline="always")
def _qexp(v0, v1, v2):
    """The unit quaternion of the rotation vector (v0, v1, v2), rad."""
    angle = math.sqrt(v0 * v0 + v1 * v1 + v2 * v2)
    if angle < 1e-300:
        return 1.0, 0.0, 0.0, 0.0
    s = math.sin(0.5 * angle) / angle
    return math.cos(0.5 * angle), s * v0, s * v1, s * v2


@jit()
def _kick(m, x, u, R, load, h, g):
    """Velocities and body angular velocities kicked by the load over ``h`` (s)."""
    for r in range(m.ints[4]):
        o = 7 * r
        if m.coupling[r, 5] != 0.0:
            continue
        mass, I1, I3 = m.coupling[r, 2], m.coupling[r, 3], m.coupling[r, 4]
        for c in range(3):
            u[o + c] += h * (load[r, c] / mass - g * m.gravity[0, o + c])
        for c in range(3):  # L_body += h tau_body
            tau = R[r, 0, c] * load[r, 3] + R[r, 1, c] * load[r, 4] + R[r, 2, c] * load[r, 5]
            u[o + 3 + c] += h * tau / (I3 if c == 2 else I1)


@jit()
def _drift(m, x, u, R, h):
    """Positions drift and every ring turns as a free symmetric rotor for ``h`` (s), exactly."""
    for r in range(m.ints[4]):
        o = 7 * r
        if m.coupling[r, 5] != 0.0:
            continue
        I1, I3 = m.coupling[r, 3], m.coupling[r, 4]
        for c in range(3):
            x[o + c] += h * u[o + c]
        w1, w2, w3 = u[o + 3], u[o + 4], u[o + 5]
        L0, L1, L2 = I1 * w1, I1 * w2, I3 * w3  # body
        S0 = R[r, 0, 0] * L0 + R[r, 0, 1] * L1 + R[r, 0, 2] * L2  # space
        S1 = R[r, 1, 0] * L0 + R[r, 1, 1] * L1 + R[r, 1, 2] * L2
        S2 = R[r, 2, 0] * L0 + R[r, 2, 1] * L1 + R[r, 2, 2] * L2
        a = _qexp(h * S0 / I1, h * S1 / I1, h * S2 / I1)
        c3 = h * L2 * (1.0 / I3 - 1.0 / I1)
        bq = (math.cos(0.5 * c3), 0.0, 0.0, math.sin(0.5 * c3))
        q = _qmul(a[0], a[1], a[2], a[3], x[o + 3], x[o + 4], x[o + 5], x[o + 6])
        q = _qmul(q[0], q[1], q[2], q[3], bq[0], bq[1], bq[2], bq[3])
        s = 1.0 / math.sqrt(q[0] ** 2 + q[1] ** 2 + q[2] ** 2 + q[3] ** 2)
        x[o + 3], x[o + 4], x[o + 5], x[o + 6] = q[0] * s, q[1] * s, q[2] * s, q[3] * s
        _rotation(x[o + 3], x[o + 4], x[o + 5], x[o + 6], R[r])
        for c in range(3):  # the body angular momentum of the turned ring: R^T L_space / I
            Lb = R[r, 0, c] * S0 + R[r, 1, c] * S1 + R[r, 2, c] * S2
            u[o + 3 + c] = Lb / (I3 if c == 2 else I1)


@jit()
def _verlet_rings_run(m, g, x0, u0, t_eval, n_steps, dt, keep, out_x, out_u):
    N = x0.size
    n = m.ints[4]
    x, u = x0.copy(), u0.copy()
    R = np.empty((n, 3, 3))
    load = np.empty((n, 6))
    x_prev, u_prev = np.empty(N), np.empty(N)
    search = n >= 0  # True, a plain bool: no compile of loads and _pair of their own (see contact_state)
    loads(m, x, u, R, load, search)
    T = t_eval.size
    j = 0
    while j < T and t_eval[j] / dt - 1e-9 <= 0.0:
        for c in range(keep.size):
            out_x[j, c], out_u[j, c] = x[keep[c]], u[keep[c]]
        j += 1
    for k in range(n_steps):
        for c in range(N):
            x_prev[c], u_prev[c] = x[c], u[c]
        _kick(m, x, u, R, load, 0.5 * dt, g)
        _drift(m, x, u, R, dt)
        loads(m, x, u, R, load, search)
        _kick(m, x, u, R, load, 0.5 * dt, g)
        while j < T and math.ceil(t_eval[j] / dt - 1e-9) - 1 == k:  # linear between the step's ends (second order)
            s = t_eval[j] / dt - k
            for c in range(keep.size):
                q = keep[c]
                out_x[j, c] = (1.0 - s) * x_prev[q] + s * x[q]
                out_u[j, c] = (1.0 - s) * u_prev[q] + s * u[q]
            j += 1
        if not math.isfinite(x[0] + u[0]):
            return 2, x, u
    for c in range(N):
        if not (math.isfinite(x[c]) and math.isfinite(u[c])):
            return 2, x, u
    return 0, x, u


def verlet_rings(packed: Packed, x0, u0, t_eval, t_end, dt, keep, g):
    """The splitting scheme of the module notes over ``t_eval`` for one or more runs (rows of x0, u0): the same
    returns as :func:`ringchain.numerics.engine.kernels.verlet` (x and u of ``keep`` (B, T, K), final x and u, status,
    the step, the number of steps)."""
    x0, u0, n_steps, dt, out_x, out_u, status, final_x, final_u = verlet_arrays(x0, u0, t_eval, t_end, dt, keep)
    t_eval, keep = kernel_array(t_eval), kernel_array(keep, dtype=np.int64)
    for b in range(x0.shape[0]):
        args = (packed, float(g), x0[b], u0[b], t_eval, int(n_steps), float(dt), keep, out_x[b], out_u[b])
        if b == 0:
            announce_compile(_verlet_rings_run, "verlet", CACHE, args)
        code, x, u = _verlet_rings_run(*args)
        status[b], final_x[b], final_u[b] = code, x, u
    return out_x, out_u, final_x, final_u, status, dt, n_steps
