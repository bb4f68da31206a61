r"""Compiled kernels of rigid rings in space: the force and torques at one contact of two tori, and the pose
derivative of Hertz's stiffness there.

A contact is a row of :mod:`ringchain.numerics.engine.rings_kernels` (gap, angles, point, normal, the principal
curvatures of both tubes at the point and the cosine of the angle between their tangents).  The law
(:func:`contact_force`): the normal force [K delta^n + gamma delta_dot]_+ from the approach delta = -gap (zero for
an open contact), with K either given (the lumped power law of paper Eq. (4)) or the Hertz stiffness of the two
surfaces' curvatures (:func:`hertz_stiffness_curvatures`, App. A, n = 3/2), and a regularised Coulomb friction
mu F_n v_t/sqrt(|v_t|^2 + v_reg^2) opposing the slip v_t; the force acts at the contact point on ring 1 and its
opposite on ring 2.  Hertz's K follows the curvatures at the contact, which move with the pose: its derivative
(:func:`stiffness_slopes`) gives the loads that make the contact's force the gradient of its stored energy
(:func:`~ringchain.numerics.engine.rings_step.loads` adds them).  SI units throughout.

Near a fold.  Hertz's K_c = 4/3 E* (2A)^(-1/2) Gamma(B/A) grows without bound as the smaller sum of curvatures A
falls to zero, where a minimum of the distance of the centre circles is about to split in two (theta_min at a
crossing, a ring sliding past a fold); capped only at ln(B/A) = 690, the table's end, it reached some 1e150 times its
size, a cliff of the energy that the static solver's trial poses met (1e132-1e144 J).  There the gap along the flat
direction is quartic, h = A x^2 + C x^4 + B y^2, and the contact's length is set by C once A^2 < ~C delta.  The
rings' law (:func:`contact_stiffness`) keeps Hertz's form with an effective curvature A_eff(A, C delta): A itself
where A^2 >> C delta (to 28 (C delta/A^2)^3 relative: 2e-10 at the chapter's static pull at 60 degrees), bounded
below by a multiple of sqrt(C delta) at A = 0 and beyond; its stored energy is 2/5 K delta^(5/2) and its force the
derivative of that energy, so K's dependence on delta stays in the gradient.  C is that of the fold of two
interlocked tori at theta_min (:func:`fold_quartic`, derived in :func:`ringchain.theory.gap.fold_quartic`), one
number per pair.  Against the half-space solver (:class:`~ringchain.numerics.contact.halfspace.ElasticHalfSpace`, 32
pixels across the contact along each axis, a window 1.3 times it; 24 pixels change the force by 0.16 per cent at
most) on the gap A x^2 + C x^4 + B y^2, force at a given approach, law/solver - 1 (Hertz/solver - 1 beside it), for
B/sqrt(C delta) = 10, 100, 1000 (the rings' contacts near a fold: about 100-200), t = A/sqrt(C delta):

====== ======================== ========================
t      law                      Hertz
====== ======================== ========================
8      +0.001 +0.002 +0.002     +0.001 +0.002 +0.002
3      +0.003 +0.007 +0.009     +0.011 +0.016 +0.019
2      +0.003 +0.009 +0.014     +0.024 +0.034 +0.041
1      +0.007 +0.019 +0.027     +0.085 +0.110 +0.126
0.5    +0.006 +0.025 +0.036     +0.219 +0.273 +0.304
0      -0.012 +0.015 +0.030     (infinite)
-0.25  -0.035 -0.004 +0.014     (infinite)
-0.5   -0.070 -0.035 -0.015     (infinite)
-1     -0.173 -0.133 -0.108     (infinite)
-2     -0.437 -0.390 -0.362     (infinite)
====== ======================== ========================

(:data:`QUARTIC_WEIGHT` and :data:`QUARTIC_SCALE` fitted to these 54 forces, over t >= -0.5.) The table was measured
with B held; B now moves with A_eff (:func:`contact_stiffness`, for continuity through the circle B = A), which lowers
K by at most 1.0 per cent at B/sqrt(C delta) = 10 and 0.1 per cent from 100 on (t from 1 to -0.5). Below t = -0.5 the
law falls short: there the row's point is a maximum of the gap along x, the gap's two minima already overlap by
A^2/(4C) before the approach is counted, and the row no longer stands for the contact (the search would find two
minima; such rows are met only between searches, or where A of the curvatures at the tubes' surfaces and g'' of the
centre circles, equal at zero approach, differ by terms of order delta).

The disk cache: as every kernel module of the engine (:data:`ringchain.numerics.engine._compiled.KERNEL_MODULES`,
whose sources key the cache folder: a change here recompiles the kernels that call these).
"""

from __future__ import annotations

import math

import numpy as np
from ringchain.theory.elliptical import TABLE_MAX_LOG_RATIO

from ._compiled import jit
from .rings_kernels import rotation_matrix

__all__ = [
    "LAW_PARAMETERS",
    "QUARTIC_WEIGHT",
    "QUARTIC_SCALE",
    "fold_quartic",
    "hertz_stiffness_curvatures",
    "contact_stiffness",
    "elliptical_factor_at",
    "contact_force",
    "stiffness_slopes",
]

#: Parameters of a contact law (a row): kind (0 the Hertz stiffness of the curvatures, 1 a given K),
#: K (N/m^n, kind 1), n (kind 1), gamma (N s/m), mu, v_reg (m/s), E* (Pa, kind 0).  A row may carry an eighth
#: number, the quartic coefficient C (1/m^3) of the gap along the flat direction of a contact near a fold
#: (kind 0; :func:`contact_stiffness`, :func:`fold_quartic`); without it, or with C = 0, the law is Hertz's with
#: its ellipse capped at the table's end (:data:`ringchain.theory.elliptical.TABLE_MAX_LOG_RATIO`).
LAW_PARAMETERS = 8
#: The weight w_0 and the scale tau of the quartic term of the effective curvature of :func:`contact_stiffness`,
#: fitted to the half-space solver's force on the gaps A x^2 + C x^4 + B y^2 (the module notes).
QUARTIC_WEIGHT = 0.22
QUARTIC_SCALE = 3.35


@jit(inline="always")
def _quartic(law):
    """The quartic coefficient C (1/m^3) of a Hertz law row (:data:`LAW_PARAMETERS`): its eighth number, else 0."""
    return law[7] if law.size > 7 else 0.0


@jit()
def fold_quartic(R1, r1, R2, r2):
    """C (1/m^3): the quartic coefficient of the gap of two tori (radii R_i, r_i in m) along the flat direction at
    the fold of their contact, sum_i 1/(8 R_i r_i (R_i - r_i)).

    For two equal interlocked tori at theta_min (where A = 0) the exact gap along the bisector of the ring planes is
    A x^2 + C x^4 + O(x^6) with C = 1/(4 R r (R - r)), each tube's height adding 1/(8 R r (R - r))
    (:func:`ringchain.theory.gap.fold_quartic`, derived from :func:`ringchain.theory.gap.surface_gap`).
    For unequal tori and for folds of other kinds (a ring sliding over an unlinked neighbour) the true C differs by
    a factor of order one; K at A = 0 goes as C^(-1/4).
    """
    return 1.0 / (8.0 * R1 * r1 * (R1 - r1)) + 1.0 / (8.0 * R2 * r2 * (R2 - r2))


@jit()
def elliptical_factor_at(s, table, step):
    """Gamma at s = ln(1 + ln(B/A)) from its values on the uniform grid s_j = j ``step`` (``table``): the cubic
    through the four nearest values (clamped to the table's ends)."""
    n = table.size
    x = s / step
    j = int(x)
    if j < 1:
        j = 1
    if j > n - 3:
        j = n - 3
    t = x - j  # position from node j; the cubic through nodes j - 1 .. j + 2
    if x >= n - 1:
        return table[n - 1]
    a = table[j - 1]
    b = table[j]
    c = table[j + 1]
    d = table[j + 2]
    return (
        -a * t * (t - 1.0) * (t - 2.0) / 6.0
        + b * (t + 1.0) * (t - 1.0) * (t - 2.0) / 2.0
        - c * (t + 1.0) * t * (t - 2.0) / 2.0
        + d * (t + 1.0) * t * (t - 1.0) / 6.0
    )


@jit()
def _factor_slope(s, table, step):
    """dGamma/ds of :func:`elliptical_factor_at` (the derivative of the same cubic; 0 past the table's end)."""
    n = table.size
    x = s / step
    if x >= n - 1:
        return 0.0
    j = int(x)
    if j < 1:
        j = 1
    if j > n - 3:
        j = n - 3
    t = x - j
    a = table[j - 1]
    b = table[j]
    c = table[j + 1]
    d = table[j + 2]
    slope = (
        -a * (3.0 * t * t - 6.0 * t + 2.0) / 6.0
        + b * (3.0 * t * t - 4.0 * t - 1.0) / 2.0
        - c * (3.0 * t * t - 2.0 * t - 2.0) / 2.0
        + d * (3.0 * t * t - 1.0) / 6.0
    )
    return slope / step


@jit()
def _curvature_sums(k1a, k1b, k2a, k2b, cos_angle):
    """Hertz's A <= B (1/m) of two surfaces' principal curvatures (App. A, Eqs. (A2a)-(A2b))."""
    d1 = k1a - k1b
    d2 = k2a - k2b
    total = 0.5 * (k1a + k1b + k2a + k2b)
    cos2 = 2.0 * cos_angle * cos_angle - 1.0
    radicand = d1 * d1 + d2 * d2 + 2.0 * d1 * d2 * cos2
    difference = 0.5 * math.sqrt(radicand) if radicand > 0.0 else 0.0
    A = 0.5 * (total - difference)
    return A, A + difference


@jit()
def _hertz(A, B, E_star, max_log_ratio, table, step):
    """(K_c (N/m^1.5), dK_c/dA at fixed B - A (N m^-0.5)) of the sums A, B: 4/3 E* (2A)^(-1/2) Gamma(B/A), the
    ellipse capped at ln(B/A) = ``max_log_ratio`` and at the table's end (a smaller A, zero or negative included, is
    raised to B exp(-cap), where the slope is 0); B < A is taken as the circle.  The slope holds the excess B - A
    (not B): it is continuous as the excess goes to 0 (the circle), where one at fixed B jumps by K Gamma'/(A Gamma)."""
    cap = math.log1p(max_log_ratio) if max_log_ratio > 0.0 else 0.0
    top = (table.size - 1) * step
    if not cap < top:
        cap = top
    excess = B - A if B > A else 0.0
    capped = True
    if A > 0.0 and math.log1p(excess / A) < max_log_ratio:
        s = math.log1p(math.log1p(excess / A))
        capped = s > cap
        if capped:
            s = cap
    else:
        s = cap
    if capped:
        A = B * math.exp(-math.expm1(s))
    gamma = elliptical_factor_at(s, table, step)
    K = 4.0 / 3.0 * E_star / math.sqrt(2.0 * A) * gamma
    if capped:
        return K, 0.0
    # d ln K/dA = -1/(2A) + Gamma'/Gamma ds/dA; at fixed excess e = B - A, s = ln(1 + ln(1 + e/A)) and
    # ds/dA = -e / (A^2 (1 + e/A) (1 + ln(1 + e/A))), which goes to 0 with e (the circle's, B <= A)
    ratio = excess / A
    ds = -ratio / (A * (1.0 + ratio) * (1.0 + math.log1p(ratio)))
    return K, K * (-0.5 / A + _factor_slope(s, table, step) / gamma * ds)


@jit()
def hertz_stiffness_curvatures(k1a, k1b, k2a, k2b, cos_angle, E_star, max_log_ratio, table, step):
    """K_c (N/m^1.5) of two surfaces with principal curvatures (k1a, k1b), (k2a, k2b) (1/m, convex positive)
    whose first principal directions make the angle with cosine ``cos_angle``; E* in Pa.

    Hertz's sums (App. A, Eqs. (A2a)-(A2b)), K_c = 4/3 E* (2A)^(-1/2) Gamma(B/A) with Gamma from ``table``
    (:func:`ringchain.theory.elliptical_factor_grid`), as :func:`ringchain.theory.hertz_stiffness_curvatures`.
    K_c grows without bound as A -> 0 (a minimum about to split: theta_min at a crossing); the ellipse is
    capped at ln(B/A) = ``max_log_ratio`` (and at the table's end, 690): a smaller A, zero or negative
    included, is raised to B exp(-max_log_ratio), which keeps K_c finite and continuous.  The contacts of rigid
    rings bound it by the quartic term of the gap instead (:func:`contact_stiffness`).
    """
    A, B = _curvature_sums(k1a, k1b, k2a, k2b, cos_angle)
    K, _ = _hertz(A, B, E_star, max_log_ratio, table, step)
    return K


@jit()
def _effective_curvature(A, quartic, delta):
    """(A_eff (1/m), dA_eff/d(delta) (1/m^2)) of :func:`contact_stiffness`: A_eff = a_0 phi(A/a_0),
    a_0 = sqrt(C delta), phi(t) = (t + sqrt(t^2 + 4 w(t)))/2, w = w_0 for t <= 0, w_0/(1 + (t/tau)^4) above."""
    a0 = math.sqrt(quartic * delta)
    t = A / a0
    u = (t / QUARTIC_SCALE) ** 4 if t > 0.0 else 0.0
    w = QUARTIC_WEIGHT / (1.0 + u)
    root = math.sqrt(t * t + 4.0 * w)
    # d A_eff/d delta = a_0/(2 delta) (phi - t phi') = a_0/(2 delta) (2 w - t w')/root, t w' = -4 w u/(1 + u)
    slope = a0 / (2.0 * delta) * (2.0 * w + 4.0 * w * u / (1.0 + u)) / root
    # the larger root of phi^2 - t phi - w = 0, without cancellation on either side of t = 0 (A itself, to
    # rounding, where w/t^2 is below rounding)
    if t >= 0.0:
        return A + a0 * (2.0 * w / (root + t)), slope
    return a0 * (2.0 * w / (root - t)), slope


@jit()
def contact_stiffness(k1a, k1b, k2a, k2b, cos_angle, E_star, quartic, delta, table, step):
    """(K (N/m^1.5), dK/d(delta) (N/m^2.5)) of a contact whose gap is A x^2 + C x^4 + B y^2 about its point:
    Hertz's K_c of the curvatures (:func:`hertz_stiffness_curvatures`, App. A) where A^2 >> C delta, bounded
    where A -> 0 and below.

    Parameters: principal curvatures (1/m), the cosine of the angle between the first principal directions, E*
    (Pa) as :func:`hertz_stiffness_curvatures`; ``quartic`` C (1/m^3, :func:`fold_quartic`; 0: Hertz's K_c with
    its ellipse capped at the table's end); ``delta`` the approach (m, > 0).

    The contact's stored energy is 2/5 K delta^(5/2) and its force d/d(delta) of it, K delta^(3/2) +
    2/5 delta^(5/2) dK/d(delta) (:func:`contact_force`).  K is Hertz's with A replaced by A_eff = a_0 phi(A/a_0)
    (and B by B + A_eff - A), a_0 = sqrt(C delta), phi(t) = (t + sqrt(t^2 + 4 w(t)))/2: the curvature delta/a^2
    of a gap A x^2 + w C x^4 that reaches delta at the half-length a (the larger root), with w = QUARTIC_WEIGHT for
    t <= 0 and w_0/(1 + (t/QUARTIC_SCALE)^4) above, so that A_eff = A (1 + O(t^-6)) where the quartic is negligible
    (t = A/sqrt(C delta) >> 1), sqrt(w_0 C delta) at A = 0, and C delta w_0/|A| for A << -sqrt(C delta).  w_0 and
    tau are fitted to the half-space solver on such gaps; the force is within 4 per cent of it for t >= -0.25 and
    1e1 <= B/sqrt(C delta) <= 1e3, 7 per cent at t = -0.5 (the module notes).  At fixed C, A_eff is smooth (C^3 at
    t = 0) in A and delta, and K finite for every A.
    """
    A, B = _curvature_sums(k1a, k1b, k2a, k2b, cos_angle)
    if not (quartic > 0.0 and delta > 0.0):
        K, _ = _hertz(A, B, E_star, TABLE_MAX_LOG_RATIO, table, step)
        return K, 0.0
    A_eff, slope = _effective_curvature(A, quartic, delta)
    # B moves with A_eff (its excess over A kept): near the circle (B - A small against A_eff - A) the ellipse then
    # stays on its side of B = A_eff, and K and dK/d(delta) stay continuous through B = A (a crossing of equal rings
    # at 90 degrees, which a swing of the chain crosses); where B >> A (a fold) B moves by A_eff - A << B
    K, dK = _hertz(A_eff, B + (A_eff - A), E_star, TABLE_MAX_LOG_RATIO, table, step)
    return K, dK * slope


@jit()
def stiffness_slopes(row, c1, q1, R1, c2, q2, R2, law, table, step, out):
    """The Hertz stiffness K_c of a contact row (law kind 0, as :func:`contact_force`) and its logarithmic derivative
    over the pose of ring 1: ``out`` (6,) receives d(ln K_c)/d(c_1) (1/m) and d(ln K_c)/d(theta_1) (rotation vector
    of ring 1 about its centre, in space; 1/rad), ring 2 held.  Returns K_c (N/m^1.5).

    K_c depends on the pose through the curvature of each tube along its centre circle at the contact,
    cos_i / (R_i + r_i cos_i) (cos_1 = -n.u_1, cos_2 = n.u_2: u_i the radial of circle i at the contact, n the
    normal), and the cosine of the angle between the tangents t_1, t_2; these follow the contact angles s_1, s_2,
    which move with the pose: s_2 as the nearest point of circle 2 to the point p_1 of circle 1
    (ds_2 = t_2.dp_1 / rho, rho the distance of p_1 from the axis of ring 2), s_1 as the minimum of the distance
    (the total differential of g'(s_1) = R_1 (p_1 - p_2).t_1 vanishes; its coefficient of ds_1 is g''/R_1).  The
    derivatives of K_c over its three arguments are central differences of :func:`contact_stiffness` at the row's
    approach and the law's quartic C (both held: the approach's own derivative is the normal force of
    :func:`contact_force`) (relative steps of 1e-6: their error about 1e-10 of the derivative).  A contact energy
    K_c phi(delta) then has the loads of :func:`contact_force` plus -phi dK_c/dpose; ring 2's follow from the
    invariance of K_c under a rigid motion of both rings (its force the opposite, its torque about its centre minus
    ring 1's minus (c_1 - c_2) x that force).
    """
    M1 = np.empty((3, 3))
    M2 = np.empty((3, 3))
    rotation_matrix(q1, M1)
    rotation_matrix(q2, M2)
    quartic, delta = _quartic(law), -row[0]
    k1a, k1b, k2a, k2b, cosine = row[9], row[10], row[11], row[12], row[13]
    K, _ = contact_stiffness(k1a, k1b, k2a, k2b, cosine, law[6], quartic, delta, table, step)
    partials = np.empty(3)  # d ln K over k1a, k2a, the cosine
    for a in range(3):
        h = 1e-6 * ((abs(k1a) + k1b) if a == 0 else (abs(k2a) + k2b) if a == 1 else 1.0)
        up, _ = contact_stiffness(k1a + h * (a == 0), k1b, k2a + h * (a == 1), k2b, cosine + h * (a == 2), law[6],
                                  quartic, delta, table, step)  # fmt: skip
        down, _ = contact_stiffness(k1a - h * (a == 0), k1b, k2a - h * (a == 1), k2b, cosine - h * (a == 2), law[6],
                                    quartic, delta, table, step)  # fmt: skip
        partials[a] = (up - down) / (2.0 * h * K)
    C1, S1, C2, S2 = math.cos(row[1]), math.sin(row[1]), math.cos(row[2]), math.sin(row[2])
    u1, t1, u2, t2, n, lever = np.empty(3), np.empty(3), np.empty(3), np.empty(3), np.empty(3), np.empty(3)
    for i in range(3):
        u1[i] = C1 * M1[i, 0] + S1 * M1[i, 1]
        t1[i] = C1 * M1[i, 1] - S1 * M1[i, 0]
        u2[i] = C2 * M2[i, 0] + S2 * M2[i, 1]
        t2[i] = C2 * M2[i, 1] - S2 * M2[i, 0]
        n[i] = row[6 + i]
        lever[i] = R1 * u1[i]  # p_1 - c_1
    f = row[14]
    d = np.empty(3)  # p_1 - p_2
    for i in range(3):
        d[i] = f * n[i]
    rho = R2 + f * (n[0] * u2[0] + n[1] * u2[1] + n[2] * u2[2])
    cos1 = -(n[0] * u1[0] + n[1] * u1[1] + n[2] * u1[2])
    cos2 = n[0] * u2[0] + n[1] * u2[1] + n[2] * u2[2]
    tt = t1[0] * t2[0] + t1[1] * t2[1] + t1[2] * t2[2]
    sign = 1.0 if tt >= 0.0 else -1.0
    r1, r2 = 1.0 / k1b, 1.0 / k2b
    dk1 = R1 / (R1 + r1 * cos1) ** 2  # d(k1a)/d(cos_1)
    dk2 = R2 / (R2 + r2 * cos2) ** 2
    # g''/R_1 = R_1 t_1.P t_1 - d.u_1 with P = I - (R_2/rho) t_2 t_2^T (dp_2 = (R_2/rho) t_2 t_2.dp_1)
    t1t2 = tt
    curvature = R1 * (1.0 - (R2 / rho) * t1t2 * t1t2) - (d[0] * u1[0] + d[1] * u1[1] + d[2] * u1[2])
    a, w, dp1, dd, dn = np.empty(3), np.empty(3), np.empty(3), np.empty(3), np.empty(3)
    wt1, wu1 = np.empty(3), np.empty(3)  # w x t_1, w x u_1
    for e in range(6):
        for i in range(3):
            w[i] = 1.0 if e == 3 + i else 0.0
        for i in range(3):  # the move of p_1 at fixed s_1: dc + w x (p_1 - c_1)
            a[i] = (1.0 if e == i else 0.0) + w[(i + 1) % 3] * lever[(i + 2) % 3] - w[(i + 2) % 3] * lever[(i + 1) % 3]
        for i in range(3):
            wt1[i] = w[(i + 1) % 3] * t1[(i + 2) % 3] - w[(i + 2) % 3] * t1[(i + 1) % 3]
            wu1[i] = w[(i + 1) % 3] * u1[(i + 2) % 3] - w[(i + 2) % 3] * u1[(i + 1) % 3]
        t2a = t2[0] * a[0] + t2[1] * a[1] + t2[2] * a[2]
        t1Pa = (t1[0] * a[0] + t1[1] * a[1] + t1[2] * a[2]) - (R2 / rho) * t1t2 * t2a
        ds1 = -(t1Pa + (d[0] * wt1[0] + d[1] * wt1[1] + d[2] * wt1[2])) / curvature
        for i in range(3):
            dp1[i] = a[i] + R1 * t1[i] * ds1
        ds2 = (t2[0] * dp1[0] + t2[1] * dp1[1] + t2[2] * dp1[2]) / rho
        for i in range(3):
            dd[i] = dp1[i] - R2 * t2[i] * ds2
        nd = n[0] * dd[0] + n[1] * dd[1] + n[2] * dd[2]
        for i in range(3):
            dn[i] = (dd[i] - n[i] * nd) / f
        du1n, dt1t2, du2n = 0.0, 0.0, 0.0
        for i in range(3):
            du1 = wu1[i] + t1[i] * ds1
            dt1 = wt1[i] - u1[i] * ds1
            du1n += dn[i] * u1[i] + n[i] * du1
            du2n += dn[i] * u2[i] + n[i] * t2[i] * ds2
            dt1t2 += dt1 * t2[i] - t1[i] * u2[i] * ds2
        out[e] = partials[0] * dk1 * (-du1n) + partials[1] * dk2 * du2n + partials[2] * sign * dt1t2
    return K


@jit()
def contact_force(row, c1, v1, w1, c2, v2, w2, law, table, step, force, torque_1, torque_2):
    """Force and torques of one contact row (module notes) between ring 1 and ring 2.

    Parameters: ``row`` (FIELDS,); centres c (3,) m, velocities v (3,) m/s and angular velocities w (3,) rad/s,
    all in space; ``law`` (LAW_PARAMETERS - 1,) or (LAW_PARAMETERS,): kind (0 Hertz of the curvatures, 1 the
    power law K delta^n), K, n, gamma, mu, v_reg, E*[, the gap's quartic coefficient C, 1/m^3, of
    :func:`contact_stiffness`]; ``table``, ``step``: the elliptical
    factor (kind 0; :func:`ringchain.theory.elliptical_factor_grid`).
    Writes the force on ring 1 (N; ring 2 gets its opposite) and the torques on rings 1 and 2 about their
    centres (N m), all in space.  Returns (normal force N, stored energy J, dashpot power W, friction power W):
    the powers are dissipated (>= 0).

    With a constant K (the power law) the elastic force and torques are exactly the gradient of the stored
    energy K delta^(n+1)/(n+1) (the gap is stationary in s_1 and s_2 at the minimum, and the contact point lies
    on the common normal of the centre circles).  The Hertz stiffness of the curvatures changes with the pose
    (the angle between the tubes, the place round each tube): the force here leaves out the pose derivative of
    K, which :func:`stiffness_slopes` gives (the loads of :func:`~ringchain.numerics.engine.rings_step.loads` add
    it, and are then the gradient of the stored energy).  v_reg = 0 is Coulomb's law itself (the friction
    force jumps where the slip reverses).
    """
    for i in range(3):
        force[i] = 0.0
        torque_1[i] = 0.0
        torque_2[i] = 0.0
    delta = -row[0]
    if not delta > 0.0:
        return 0.0, 0.0, 0.0, 0.0
    if law[0] == 0.0:  # energy 2/5 K delta^(5/2), K = K(delta) near a fold: the force is its derivative
        K, dK = contact_stiffness(row[9], row[10], row[11], row[12], row[13], law[6], _quartic(law), delta, table,
                                  step)  # fmt: skip
        energy = 0.4 * K * delta * delta * math.sqrt(delta)
        elastic = K * delta * math.sqrt(delta) + 0.4 * dK * delta * delta * math.sqrt(delta)
    else:
        K = law[1]
        n = law[2]
        elastic = K * delta**n
        energy = elastic * delta / (n + 1.0)
    # lever arms from the centres, and the velocity of ring 1's material point at the contact relative to ring 2's
    a1 = (row[3] - c1[0], row[4] - c1[1], row[5] - c1[2])
    a2 = (row[3] - c2[0], row[4] - c2[1], row[5] - c2[2])
    rel = (
        (v1[0] + w1[1] * a1[2] - w1[2] * a1[1]) - (v2[0] + w2[1] * a2[2] - w2[2] * a2[1]),
        (v1[1] + w1[2] * a1[0] - w1[0] * a1[2]) - (v2[1] + w2[2] * a2[0] - w2[0] * a2[2]),
        (v1[2] + w1[0] * a1[1] - w1[1] * a1[0]) - (v2[2] + w2[0] * a2[1] - w2[1] * a2[0]),
    )
    normal_speed = rel[0] * row[6] + rel[1] * row[7] + rel[2] * row[8]
    delta_rate = -normal_speed
    normal = elastic + law[3] * delta_rate
    if normal < 0.0:
        normal = 0.0
    # the dashpot's share of the normal force (with the bracket: normal - elastic) and the power it takes
    dashpot_power = (normal - elastic) * delta_rate
    slip = (rel[0] - normal_speed * row[6], rel[1] - normal_speed * row[7], rel[2] - normal_speed * row[8])
    slip2 = slip[0] * slip[0] + slip[1] * slip[1] + slip[2] * slip[2]
    mu = law[4]
    factor = 0.0
    if mu > 0.0 and slip2 > 0.0:
        factor = mu * normal / math.sqrt(slip2 + law[5] * law[5])
    for i in range(3):
        force[i] = normal * row[6 + i] - factor * slip[i]
    friction_power = factor * slip2
    torque_1[0] = a1[1] * force[2] - a1[2] * force[1]
    torque_1[1] = a1[2] * force[0] - a1[0] * force[2]
    torque_1[2] = a1[0] * force[1] - a1[1] * force[0]
    torque_2[0] = -(a2[1] * force[2] - a2[2] * force[1])
    torque_2[1] = -(a2[2] * force[0] - a2[0] * force[2])
    torque_2[2] = -(a2[0] * force[1] - a2[1] * force[0])
    return normal, energy, dashpot_power, friction_power
