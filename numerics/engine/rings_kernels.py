r"""Compiled kernels of rigid rings in space: the contacts of two tori in any pose.

Plain Numba functions on float arrays, for the inner loop of a simulation of rigid tori
(:func:`ringchain.numerics.torus_contacts` is the Python face of the geometry, with the conventions).
Everything here is in SI units; a ring's pose is its centre (3,) and a unit quaternion (w, x, y, z)
taking its body frame to space, its axis being body z and its centre circle of radius R in the body
xy plane, at the angle s from body x.

The contact geometry.  Two tubes touch where the distance between their centre circles has a local
minimum.  For the point of circle 1 at the angle s, written in the frame of ring 2 as (X, Y, Z)(s)
(each a constant plus R_1 times a combination of cos s and sin s), the nearest point of circle 2 is
R_2 (X, Y, 0)/rho with rho = sqrt(X^2 + Y^2), at the distance f(s) = sqrt((rho - R_2)^2 + Z^2).
Every local minimum of the distance of the two circles is a local minimum of f (the distance from a
point to a circle has one minimum on the circle), so the search is one-dimensional.  The kernels work
with g = f^2/2, smooth wherever rho > 0 (also where the circles cross, f = 0), with its derivatives
g' and g'' in closed form (:func:`_profile`).  Where circle 1 crosses the axis of circle 2 (rho = 0)
g has a cusp that is a local maximum, never a minimum.

- The cold search (:func:`pair_contacts`) samples g' at ``n_scan`` equally spaced angles; a minimum
  lies where g' changes from negative to positive between two samples (a maximum, the cusp included,
  only changes it the other way, and a sample within rounding of a zero cannot make a spurious pair of
  changes).  Each bracket is refined by Newton's method safeguarded by bisection (``rtsafe``).  Where
  g'' <= 0 at one of the points h/32 .. h/2 on either side of a minimum found (h = 2 pi/n_scan; an
  inflection: a maximum close by, beyond which a twin may hide; :func:`_inflection_near`), the search
  samples 2 h on both sides again at h/32, so that twins down to about h/32 from their maximum are found too
  (the default n_scan = 64 is justified in :mod:`ringchain.numerics.contact.tori`).  A minimum and a
  maximum between the same two samples leave g' of one sign at both, and no bracket: where the mean slope
  (g(b) - g(a))/h falls well below the mean of the two end slopes, the cubic Hermite model of g' from g' and
  g'' at both ends is formed, and where its interior extremum comes within 0.05 of the interval's scale of
  zero (:func:`_dip_hidden`, :func:`_dip_between`) the interval is sampled again at h/32.  These looks run
  after the brackets are refined, so a minimum bracketed keeps the angle of its own refinement (the rows are
  those of the scan without them wherever it found every minimum).  A 30 x 30 sheet of chain mail, in the
  pose where its static solver once stopped (a twin 0.88 h past its maximum, the maximum and the twin between
  two samples): of the intervals of its 3,807 pairs whose bounding spheres overlap, 1.3 per cent pass the
  first test and 79 the second; on its 3,863 pairs within 2 mm the search finds all 5,970 minima of a profile
  sampled at 2^13 points (13 were missed without the test).
- A pose where f is constant to rounding (g varies by less than 1e-12 of its scale over the scan:
  coaxial rings, concentric or stacked) has a circle of contact, not isolated minima.  It is
  returned as ``LINE_POINTS`` contacts at s = 0, pi/2, pi, 3 pi/2, flagged (field ``line`` = 1).
- The warm-started search (:func:`pair_contacts_warm`) takes the angles s of the minima of the last
  call and runs a few Newton iterations from each.  It falls back on the cold search when an iteration
  fails to converge, meets g'' <= 0 (the minimum merged with a maximum, or split in two: theta_min
  crossed), finds an inflection close by as the cold search does (the minimum is about to split, or a new
  one is being born next to it), finds a maximum within 2 h of a minimum with no other minimum followed
  within 4 h beyond it, or a dip of g' between s and s +- 2 h by the test of the cold search
  (:func:`_twin_near`: a twin that the cold search would find), or two minima converge to one.  It cannot see a
  minimum born away from the ones it tracks (a fold of f far from them; such a minimum is born shallower
  than the tracked minimum downhill of it): callers run the cold search every few steps (see
  :mod:`ringchain.numerics.contact.tori`).
- Between searches (the stages of a Runge-Kutta step), :func:`pair_contacts_follow` evaluates the rows at
  the last angles after a fixed number of Newton steps (zero or one), with no check: the gap is stationary
  at a minimum, so an angle off by ds errs by g'' ds^2/2.

One row of ``FIELDS`` numbers per minimum (named in ``CONTACT_FIELDS`` of the Python module):
gap (m), s_1, s_2 (rad), the contact point (3, m: midway between the two tube surfaces along the
normal), the unit normal (3, from ring 2 towards ring 1), the principal curvatures of tube 1 at the
point (along the tube, signed, and across it, 1/r_1; 1/m, convex positive), the same for tube 2, the
cosine of the angle between the two tube tangents (in [0, 1]), the distance f of the centre circles
(m) and the line flag.

The contact law at a row is :mod:`ringchain.numerics.engine.rings_law`'s
(:func:`~ringchain.numerics.engine.rings_law.contact_force`). Where a maximum of the distance between two minima is
itself in overlap (tubes lying nearly parallel over an arc), each minimum carries a share of its force
(:func:`fold_weights`) that vanishes as it meets the maximum and disappears (a fold), so that the loads stay
continuous in the pose; elsewhere the share is one. Without it the force of a contact jumps as the scan finds or
misses a minimum a rounding error from a fold (met in a 4 x 4 sheet of chain mail under gravity: a minimum 1e-8 r
below the maximum next to it, both 1e-3 r deep, 2.7 N of force that came and went as the pose changed by 1e-18 m),
and no static solver can converge. The loads of a pair are the gradient of its stored energy sum_a w_a K_a
delta_a^(n+1)/(n+1): the shares w_a are functions of the approaches of the minima and of the maxima in overlap,
whose derivatives over the pose are unit forces along their normals (:func:`fold_weights` returns the shares' slopes
and the maxima's rows), and Hertz's K_a follows the curvatures at its contact
(:func:`~ringchain.numerics.engine.rings_law.stiffness_slopes`); :func:`~ringchain.numerics.engine.rings_step.loads`
adds both.

The module's constants that the kernels read (``MAX_CONTACTS``, ``LINE_POINTS``, the modes of
:func:`pairs_contacts`) are compiled in as constants, as Numba does with globals.

The disk cache.  As :mod:`ringchain.numerics.engine.kernels` (its folder, ``CACHE``): Numba keys a cached kernel
on its own file, so the kernels that call one another all live in this module; a kernel of another
module that calls these is not recompiled when they change (clear the cache after editing them).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from ._compiled import CACHE

__all__ = [
    "FIELDS",
    "MAX_CONTACTS",
    "LINE_POINTS",
    "N_SCAN",
    "rotation_matrix",
    "pair_contacts",
    "pair_contacts_warm",
    "pair_contacts_follow",
    "pairs_contacts",
    "fold_weights",
    "COLD",
    "WARM",
    "FOLLOW",
]

#: Numbers per contact row (see the module notes).
FIELDS = 16
#: Most minima returned for one pair: 20,000 random poses of two circles had at most two local minima of
#: their distance (a linked pair below theta_min, a ring lying across another); eight leave room, and a
#: circle of contact is returned as ``LINE_POINTS`` rows.
MAX_CONTACTS = 8
#: Rows that stand for a circle of contact (coaxial rings).
LINE_POINTS = 4
#: Default number of samples of the cold search.
N_SCAN = 64

_previous_cache_dir = numba.config.CACHE_DIR
if CACHE is not None:
    numba.config.CACHE_DIR = CACHE  # read when each kernel below is decorated; restored at the end of the module


def _jit(**options):
    return numba.njit(cache=CACHE is not None, error_model="numpy", **options)


# -- poses ---------------------------------------------------------------------------------------------------
@_jit()
def rotation_matrix(q, out):
    """Write into ``out`` (3, 3) the rotation of the quaternion q = (w, x, y, z) (body to space; columns are
    the body axes in space).  q need not be exactly unit: the formula divides by |q|^2."""
    w, x, y, z = q[0], q[1], q[2], q[3]
    s = 2.0 / (w * w + x * x + y * y + z * z)
    out[0, 0] = 1.0 - s * (y * y + z * z)
    out[0, 1] = s * (x * y - w * z)
    out[0, 2] = s * (x * z + w * y)
    out[1, 0] = s * (x * y + w * z)
    out[1, 1] = 1.0 - s * (x * x + z * z)
    out[1, 2] = s * (y * z - w * x)
    out[2, 0] = s * (x * z - w * y)
    out[2, 1] = s * (y * z + w * x)
    out[2, 2] = 1.0 - s * (x * x + y * y)


@_jit()
def _coefficients(c1, M1, c2, M2, k):
    """k = [D, A, B] (9,): circle 1's centre, body x and body y in the frame of ring 2 (D relative to c2)."""
    for i in range(3):
        d = 0.0
        a = 0.0
        b = 0.0
        for j in range(3):
            d += M2[j, i] * (c1[j] - c2[j])
            a += M2[j, i] * M1[j, 0]
            b += M2[j, i] * M1[j, 1]
        k[i] = d
        k[3 + i] = a
        k[6 + i] = b


@_jit(inline="always")
def _profile(k, R1, R2, C, S):
    """(g, g', g'') of g(s) = f(s)^2/2 at cos s = C, sin s = S; on the axis of circle 2 (rho = 0), g' = 0 and
    g'' = -inf (the cusp is a maximum)."""
    X = k[0] + R1 * (k[3] * C + k[6] * S)
    Y = k[1] + R1 * (k[4] * C + k[7] * S)
    Z = k[2] + R1 * (k[5] * C + k[8] * S)
    Xp = R1 * (k[6] * C - k[3] * S)
    Yp = R1 * (k[7] * C - k[4] * S)
    Zp = R1 * (k[8] * C - k[5] * S)
    Xpp = k[0] - X
    Ypp = k[1] - Y
    Zpp = k[2] - Z
    rho = math.sqrt(X * X + Y * Y)
    e = rho - R2
    g = 0.5 * (e * e + Z * Z)
    if rho == 0.0:
        return g, 0.0, -math.inf
    rp = (X * Xp + Y * Yp) / rho
    rpp = (Xp * Xp + Yp * Yp + X * Xpp + Y * Ypp - rp * rp) / rho
    return g, e * rp + Z * Zp, rp * rp + e * rpp + Zp * Zp + Z * Zpp


@_jit()
def _refine(k, R1, R2, a, b, gp_a, gp_b):
    """The zero of g' in [a, b] (g'(a) = gp_a < 0 <= g'(b) = gp_b) by Newton's method safeguarded by bisection,
    started from the secant's zero; (s, iterations)."""
    s = a + (b - a) * gp_a / (gp_a - gp_b)
    step_old = b - a
    step = step_old
    for it in range(1, 101):
        _, gp, gpp = _profile(k, R1, R2, math.cos(s), math.sin(s))
        if gp == 0.0:
            return s, it
        if gp < 0.0:
            a = s
        else:
            b = s
        newton = False
        if gpp > 0.0:
            trial = -gp / gpp
            if abs(trial) <= 1e-13:  # converged: the next step is below 1e-13 rad (R 1e-13 on the circle)
                return s + trial, it
            newton = a < s + trial < b and abs(2.0 * gp) <= abs(step_old * gpp)
        step_old = step
        if newton:
            step = -gp / gpp
            s += step
        else:
            step = 0.5 * (b - a)
            s = a + step
        if b - a <= 1e-13:
            return s, it
    return s, 100


@_jit()
def _fields(k, c1, M1, r1, R1, c2, M2, R2, r2, s, line, row):
    """Write the contact row (module notes) of the minimum of circle 1 at the angle s."""
    C = math.cos(s)
    S = math.sin(s)
    X = k[0] + R1 * (k[3] * C + k[6] * S)
    Y = k[1] + R1 * (k[4] * C + k[7] * S)
    Z = k[2] + R1 * (k[5] * C + k[8] * S)
    rho = math.sqrt(X * X + Y * Y)
    if rho > 0.0:
        ux2, uy2 = X / rho, Y / rho
    else:  # on the axis (a coaxial pose of zero radius cannot occur for R1 > 0): any direction
        ux2, uy2 = 1.0, 0.0
    e = rho - R2
    f = math.sqrt(e * e + Z * Z)
    # radial (u) and tangent (t) of both circles in space; the normal n from circle 2 to circle 1 (tuples: no
    # allocation in the inner loop)
    u1 = (C * M1[0, 0] + S * M1[0, 1], C * M1[1, 0] + S * M1[1, 1], C * M1[2, 0] + S * M1[2, 1])
    t1 = (C * M1[0, 1] - S * M1[0, 0], C * M1[1, 1] - S * M1[1, 0], C * M1[2, 1] - S * M1[2, 0])
    u2 = (ux2 * M2[0, 0] + uy2 * M2[0, 1], ux2 * M2[1, 0] + uy2 * M2[1, 1], ux2 * M2[2, 0] + uy2 * M2[2, 1])
    t2 = (ux2 * M2[0, 1] - uy2 * M2[0, 0], ux2 * M2[1, 1] - uy2 * M2[1, 0], ux2 * M2[2, 1] - uy2 * M2[2, 0])
    if f > 0.0:  # (q1 - q2)/f
        n = ((e * u2[0] + Z * M2[0, 2]) / f, (e * u2[1] + Z * M2[1, 2]) / f, (e * u2[2] + Z * M2[2, 2]) / f)
    else:  # the centre circles cross: the normal of both tangents (any sign), or the radial of circle 2
        n = (t1[1] * t2[2] - t1[2] * t2[1], t1[2] * t2[0] - t1[0] * t2[2], t1[0] * t2[1] - t1[1] * t2[0])
        norm = math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
        n = (n[0] / norm, n[1] / norm, n[2] / norm) if norm > 0.0 else u2
    row[0] = f - r1 - r2
    row[1] = s % (2.0 * math.pi)
    row[2] = math.atan2(uy2, ux2) % (2.0 * math.pi)
    for i in range(3):
        q1 = c1[i] + R1 * u1[i]
        q2 = c2[i] + R2 * u2[i]
        row[3 + i] = 0.5 * ((q1 - r1 * n[i]) + (q2 + r2 * n[i]))
        row[6 + i] = n[i]
    cos1 = -(n[0] * u1[0] + n[1] * u1[1] + n[2] * u1[2])  # outward normal of tube 1 is -n
    cos2 = n[0] * u2[0] + n[1] * u2[1] + n[2] * u2[2]
    row[9] = cos1 / (R1 + r1 * cos1)
    row[10] = 1.0 / r1
    row[11] = cos2 / (R2 + r2 * cos2)
    row[12] = 1.0 / r2
    row[13] = min(1.0, abs(t1[0] * t2[0] + t1[1] * t2[1] + t1[2] * t2[2]))
    row[14] = f
    row[15] = line


@_jit()
def _pose(c1, q1, c2, q2, M1, M2, k):
    rotation_matrix(q1, M1)
    rotation_matrix(q2, M2)
    _coefficients(c1, M1, c2, M2, k)


@_jit()
def _posed(c1, q1, c2, q2, extra):
    """The rotation matrices M1, M2 and the coefficients k of a pose (:func:`_pose`) in a new work array, with
    ``extra`` numbers more: (M1, M2, k, the extra numbers).  Every caller passes MAX_CONTACTS (whether it uses the
    extra numbers or not): a literal is a Numba type of its own, and two of them would compile it twice."""
    work = np.empty(27 + extra)
    M1 = work[:9].reshape((3, 3))
    M2 = work[9:18].reshape((3, 3))
    k = work[18:27]
    _pose(c1, q1, c2, q2, M1, M2, k)
    return M1, M2, k, work[27:]


@_jit()
def _scan(k, c1, M1, R1, r1, c2, M2, R2, r2, n_scan, out):
    """The cold search of a pose whose coefficients k are computed; returns (rows written, iterations)."""
    h = 2.0 * math.pi / n_scan
    ch = math.cos(h)
    sh = math.sin(h)
    C = 1.0
    S = 0.0
    g_min = math.inf
    g_max = -math.inf
    brackets = np.empty((2 * MAX_CONTACTS, 3))  # sample index, g' at both ends
    found = 0
    dips = np.empty(2 * MAX_CONTACTS)  # sample index of intervals where a minimum may hide between the samples
    hidden = 0
    g_first = 0.0
    gp_first = 0.0
    g_prev = 0.0
    gp_prev = 0.0
    C_prev = 1.0
    S_prev = 0.0
    for j in range(n_scan + 1):
        if j < n_scan:
            g, gp, _ = _profile(k, R1, R2, C, S)
            g_min = min(g_min, g)
            g_max = max(g_max, g)
        else:  # the first sample again: the interval that closes the circle
            g, gp, C, S = g_first, gp_first, 1.0, 0.0
        if j == 0:
            g_first = g
            gp_first = gp
        elif gp_prev < 0.0 <= gp:
            if found < brackets.shape[0]:
                brackets[found, 0] = j - 1
                brackets[found, 1] = gp_prev
                brackets[found, 2] = gp
                found += 1
        elif hidden < dips.size and _dip_hidden(k, R1, R2, C_prev, S_prev, g_prev, gp_prev, C, S, g, gp, h):
            dips[hidden] = j - 1
            hidden += 1
        g_prev = g
        gp_prev = gp
        C_prev = C
        S_prev = S
        C, S = C * ch - S * sh, S * ch + C * sh
    scale = k[0] * k[0] + k[1] * k[1] + k[2] * k[2] + R1 * R1 + R2 * R2
    if g_max - g_min <= 1e-12 * scale:  # a circle of contact: LINE_POINTS rows
        for j in range(LINE_POINTS):
            _fields(k, c1, M1, r1, R1, c2, M2, R2, r2, 2.0 * math.pi * j / LINE_POINTS, 1.0, out[j])
        return LINE_POINTS, 0
    iterations = 0
    minima = np.empty(out.shape[0])
    # Ints typed int64, not literals (each literal is a Numba type of its own: _keep and _fine_look would compile
    # once per literal they are called with).
    rows = np.int64(0)
    fine = h / 32.0
    for i in range(found):
        a = brackets[i, 0] * h
        s, it = _refine(k, R1, R2, a, a + h, brackets[i, 1], brackets[i, 2])
        iterations += it
        rows = _keep(minima, rows, s)
        if _inflection_near(k, R1, R2, s, h):  # a twin may hide next to this minimum: 2 h each side again at h/32
            rows, it = _fine_look(k, R1, R2, s - 2.0 * h, np.int64(128), fine, minima, rows)
            iterations += it
    for i in range(hidden):  # after the brackets' minima, so that those keep the angles of their own refinement
        rows, it = _fine_look(k, R1, R2, dips[i] * h, np.int64(32), fine, minima, rows)
        iterations += it
    for i in range(rows):
        _fields(k, c1, M1, r1, R1, c2, M2, R2, r2, minima[i], 0.0, out[i])
    return rows, iterations


#: How close to zero (in parts of the interval's scale of g') the cubic model of g' between two samples may come
#: before the samples between them are looked at (:func:`_dip_between`).
_DIP_MARGIN = 0.05


@_jit(inline="always")
def _dip_between(gp_a, gpp_a, gp_b, gpp_b, h):
    """Whether g' may change sign twice between two samples h apart where it has one sign at both (g'(a) = gp_a,
    g''(a) = gpp_a, the same at b): a maximum and a minimum hidden between them.

    The cubic Hermite model of g' on the interval (from g' and g'' at both ends) has an interior minimum (both ends
    >= 0) or maximum (both < 0) that comes within ``_DIP_MARGIN`` times the interval's scale max(|g'(a)|, |g'(b)|,
    h |g''(a)|, h |g''(b)|) of zero.  The model errs by at most h^4 max|g'''''|/384, about (h/l)^3/384 of that scale
    for a profile varying over the angle l: 0.0026 for l = h; 0.05 covers features down to l = h/2.7 (measured on
    the 3,807 pairs of a 30 x 30 sheet of chain mail whose bounding spheres overlap, in the pose where its static
    solver once stopped: the model's minimum of g' within 0.0018 of the scale of the one sampled at h/64; 79
    intervals of 243,648 flagged, 57 of them hiding a minimum).  Twins closer than that lie within
    h/5 of their maximum, and the inflection next to the one found catches them (:func:`_inflection_near`)."""
    if gp_a >= 0.0:
        if not (gpp_a < 0.0 or gpp_b > 0.0):  # g' rises from a or falls into b: no interior minimum of the model
            return False
        sign = 1.0
    else:
        if not (gpp_a > 0.0 or gpp_b < 0.0):
            return False
        sign = -1.0
    # the model p(t) = sign g'(a + t h) on [0, 1]; p'(t) = A t^2 + B t + D
    u0, u1 = sign * gp_a, sign * gp_b
    v0, v1 = sign * h * gpp_a, sign * h * gpp_b
    scale = max(u0, u1, abs(v0), abs(v1))
    A = 6.0 * (u0 - u1) + 3.0 * (v0 + v1)
    B = -6.0 * (u0 - u1) - 4.0 * v0 - 2.0 * v1
    D = v0
    disc = B * B - 4.0 * A * D
    if not disc >= 0.0:
        return False
    # the root of p' where p'' = 2 A t + B = +sqrt(disc) > 0, t = (-B + sqrt(disc)) / (2 A), or, without the
    # cancellation where B > 0, 2 D / (-B - sqrt(disc)) (the product of the roots is D / A; also where A = 0)
    root = math.sqrt(disc)
    if B > 0.0:
        t = 2.0 * D / (-B - root)
    elif A != 0.0:
        t = (-B + root) / (2.0 * A)
    else:  # p' = B t + D with B <= 0: no interior minimum
        return False
    if not 0.0 < t < 1.0:
        return False
    t2 = t * t
    t3 = t2 * t
    p = u0 * (2.0 * t3 - 3.0 * t2 + 1.0) + v0 * (t3 - 2.0 * t2 + t) + u1 * (3.0 * t2 - 2.0 * t3) + v1 * (t3 - t2)
    return p < _DIP_MARGIN * scale


@_jit(inline="always")
def _dip_hidden(k, R1, R2, C_a, S_a, g_a, gp_a, C_b, S_b, g_b, gp_b, h):
    """Whether a maximum and a minimum may hide between two samples h apart (cos and sin of their angles, g and g'
    at each) where g' has one sign at both: first from the mean slope (g(b) - g(a))/h, which a dip of g' between
    them pulls below the mean of the end slopes (the quadratic through the end slopes with that mean curves by
    kappa = 6 (mean - (g'(a) + g'(b))/2); the intervals that :func:`_dip_between` flagged on the 30 x 30 sheet its
    notes name had kappa below -0.73 max|g'| of the two ends, and kappa below -0.25 max|g'| lets through 1.3 per cent
    of all intervals), then where it is, from g'' at both ends (:func:`_dip_between`).  The scan itself needs no
    g''."""
    if (gp_a < 0.0) != (gp_b < 0.0):
        return False
    sign = 1.0 if gp_a >= 0.0 else -1.0
    u0 = sign * gp_a
    u1 = sign * gp_b
    kappa = 6.0 * (sign * (g_b - g_a) / h - 0.5 * (u0 + u1))
    if not kappa < -0.25 * max(u0, u1):
        return False
    _, _, gpp_a = _profile(k, R1, R2, C_a, S_a)
    _, _, gpp_b = _profile(k, R1, R2, C_b, S_b)
    return _dip_between(gp_a, gpp_a, gp_b, gpp_b, h)


@_jit()
def _fine_look(k, R1, R2, start, count, fine, minima, rows):
    """Sample g' at ``count`` + 1 points ``fine`` apart from ``start`` and refine every change of sign from - to +
    into ``minima[:rows]`` (:func:`_keep`); returns (rows, Newton iterations)."""
    iterations = 0
    a = start
    _, gp_a, _ = _profile(k, R1, R2, math.cos(a), math.sin(a))
    for _ in range(count):
        b = a + fine
        _, gp_b, _ = _profile(k, R1, R2, math.cos(b), math.sin(b))
        if gp_a < 0.0 <= gp_b:
            s, it = _refine(k, R1, R2, a, b, gp_a, gp_b)
            iterations += it
            rows = _keep(minima, rows, s)
        a = b
        gp_a = gp_b
    return rows, iterations


@_jit()
def _inflection_near(k, R1, R2, s, h):
    """Whether g'' <= 0 at s +- h/32, h/16, h/8, h/4 or h/2: an inflection next to the minimum at s, so a maximum
    within about 1.2 h of it, beyond which a twin minimum may lie (for g ~ (x^2 - D^2)^2 the inflections lie
    0.42 D from each minimum, D half their distance; these points see D from h/50 to 1.2 h)."""
    C = math.cos(s)
    S = math.sin(s)
    cp = math.cos(h / 32.0)
    sp = math.sin(h / 32.0)
    for _ in range(5):
        for sign in (-1.0, 1.0):
            _, _, gpp = _profile(k, R1, R2, C * cp - sign * S * sp, S * cp + sign * C * sp)
            if not gpp > 0.0:
                return True
        cp, sp = 2.0 * cp * cp - 1.0, 2.0 * sp * cp  # double the offset
    return False


@_jit()
def _twin_near(k, R1, R2, s, h, gpp_s, followed, count, index):
    """Whether the minimum at s (g'' = ``gpp_s`` there; ``followed[index]`` of the ``count`` minima followed, rad)
    may have an unfollowed twin next to it: a maximum within 2 h of it with no other followed minimum within 4 h on
    that side, or a maximum and a minimum hidden between s and s + h or s + h and s + 2 h (the same on the other
    side; :func:`_dip_between`).

    The warm start's check that the cold search would find no twin beyond a maximum next to the minimum it follows
    (the cold search brackets such a twin, or finds it between two samples by :func:`_dip_between`); without samples,
    it looks two scan spacings each side, four evaluations of the profile."""
    C = math.cos(s)
    S = math.sin(s)
    ch = math.cos(h)
    sh = math.sin(h)
    for sign in (-1.0, 1.0):
        # outwards from the minimum: sign g'(s + sign x) and g''(s + sign x) are the slope and curvature of the
        # slope in x, and g' = 0 at the minimum itself
        gp_a, gpp_a = 0.0, gpp_s
        Cj, Sj = C, S
        for _ in range(2):
            Cj, Sj = Cj * ch - sign * Sj * sh, Sj * ch + sign * Cj * sh
            _, gp, gpp = _profile(k, R1, R2, Cj, Sj)
            if not sign * gp > 0.0:  # g' has turned: a maximum (or the cusp) between, and a minimum beyond it
                followed_beyond = False
                for j in range(count):
                    ahead = (sign * (followed[j] - s)) % (2.0 * math.pi)
                    if j != index and 0.0 < ahead <= 4.0 * h:
                        followed_beyond = True
                if not followed_beyond:
                    return True
                break  # the maximum between two minima followed
            if _dip_between(gp_a, gpp_a, sign * gp, gpp, h):
                return True
            gp_a, gpp_a = sign * gp, gpp
    return False


@_jit()
def _keep(minima, count, s):
    """Append the angle s to ``minima[:count]`` unless it is within 1e-9 rad of one of them or the array is full."""
    s = s % (2.0 * math.pi)
    for i in range(count):
        separation = abs(minima[i] - s)
        if min(separation, 2.0 * math.pi - separation) < 1e-9:
            return count
    if count < minima.size:
        minima[count] = s
        count += 1
    return count


@_jit()
def pair_contacts(c1, q1, R1, r1, c2, q2, R2, r2, n_scan, out):
    """Every local minimum of the distance of two centre circles, found from scratch (the cold search).

    Parameters: centres c1, c2 (3,) m; quaternions q1, q2 (4,) (w, x, y, z), body to space; radii R1, r1,
    R2, r2 (m); n_scan samples of the scan; ``out`` (MAX_CONTACTS, FIELDS) receives one row per minimum
    (module notes).  Returns (number of rows, Newton iterations spent in the refinement).
    """
    M1, M2, k, _ = _posed(c1, q1, c2, q2, MAX_CONTACTS)
    return _scan(k, c1, M1, R1, r1, c2, M2, R2, r2, n_scan, out)


@_jit()
def pair_contacts_warm(c1, q1, R1, r1, c2, q2, R2, r2, n_scan, s_previous, n_previous, max_iterations, out):
    """:func:`pair_contacts` started from the angles ``s_previous[:n_previous]`` (rad, on circle 1) of the
    last call's minima (usually ``out[:, 1]`` of that call).

    Returns (number of rows, Newton iterations, 1 if it fell back on the cold search else 0).  Each minimum
    gets at most ``max_iterations`` Newton steps (each at most a quarter of the scan spacing); the cold
    search takes over when one does not converge to 1e-12 rad, meets g'' <= 0, has an inflection nearby
    (:func:`_inflection_near`: the minimum may be splitting, or one being born next to it), or two meet
    (module notes).
    """
    M1, M2, k, found = _posed(c1, q1, c2, q2, MAX_CONTACTS)
    h = 2.0 * math.pi / n_scan
    iterations = 0
    ok = 0 < n_previous <= out.shape[0]
    for i in range(n_previous if ok else 0):
        s = s_previous[i]
        converged = False
        for _ in range(max_iterations):
            _, gp, gpp = _profile(k, R1, R2, math.cos(s), math.sin(s))
            iterations += 1
            if not gpp > 0.0:
                break
            step = -gp / gpp
            if step > 0.25 * h:
                step = 0.25 * h
            elif step < -0.25 * h:
                step = -0.25 * h
            s += step
            if abs(step) <= 1e-12:
                converged = True
                break
        if not converged:
            ok = False
            break
        if _inflection_near(k, R1, R2, s, h):  # a maximum close by: a twin, or one being born, may be missed
            ok = False
            break
        if _twin_near(k, R1, R2, s, h, gpp, s_previous, n_previous, i):  # a maximum within 2 h, no minimum followed
            # beyond it (gpp: g'' of the last Newton step, 1e-12 rad from s)
            ok = False
            break
        s = s % (2.0 * math.pi)
        for j in range(i):
            separation = abs(found[j] - s)
            if min(separation, 2.0 * math.pi - separation) < 0.25 * h:
                ok = False
        found[i] = s
        if not ok:
            break
    if ok:
        for i in range(n_previous):
            _fields(k, c1, M1, r1, R1, c2, M2, R2, r2, found[i], 0.0, out[i])
        return n_previous, iterations, 0
    rows, more = _scan(k, c1, M1, R1, r1, c2, M2, R2, r2, n_scan, out)
    return rows, iterations + more, 1


@_jit()
def pair_contacts_follow(c1, q1, R1, r1, c2, q2, R2, r2, s_previous, n_previous, newton_steps, out):
    """The rows of the minima followed from ``s_previous[:n_previous]`` by exactly ``newton_steps`` Newton steps
    (0: evaluated at those angles), with no check and no fallback: for the stages of a Runge-Kutta step between
    two searches.  The distance is stationary at a minimum, so an angle off by ds changes the gap by only
    g'' ds^2/2 (second order).  Returns 0 if a Newton step met g'' <= 0 (that minimum is no longer near: search
    again), else 1 (with no Newton step, always 1).
    """
    M1, M2, k, _ = _posed(c1, q1, c2, q2, MAX_CONTACTS)
    ok = 1
    for i in range(n_previous):
        s = s_previous[i]
        for _ in range(newton_steps):
            _, gp, gpp = _profile(k, R1, R2, math.cos(s), math.sin(s))
            if not gpp > 0.0:
                ok = 0
                break
            s -= gp / gpp
        _fields(k, c1, M1, r1, R1, c2, M2, R2, r2, s, 0.0, out[i])
    return ok


#: Modes of :func:`pairs_contacts`.
COLD, WARM, FOLLOW = 0, 1, 2


@_jit()
def pairs_contacts(centres, orientations, R, r, pairs, n_scan, mode, iterations, state, counts, out, stats):
    """The contacts of many pairs of rings in one call (the narrow phase of a step, or of a stage).

    Parameters: ``centres`` (n, 3) m, ``orientations`` (n, 4) quaternions (w, x, y, z), ``R``, ``r`` (n,) m;
    ``pairs`` (m, 2) int; ``mode``: ``COLD`` searches every pair from scratch (:func:`pair_contacts`), ``WARM``
    starts each pair from ``state[p, :counts[p]]``, the angles s_1 of its last minima, with at most
    ``iterations`` Newton steps each (:func:`pair_contacts_warm`; a pair with counts[p] == 0 is searched cold),
    ``FOLLOW`` takes exactly ``iterations`` Newton steps from them with no check (:func:`pair_contacts_follow`;
    a pair that meets g'' <= 0 is searched cold).  ``out`` (m, MAX_CONTACTS, FIELDS) receives each pair's rows;
    ``counts`` (m,) their number and ``state`` their angles s_1 (both updated in place for the next call, except
    by a follow, which leaves them for the step's search; a follow that fell back on the cold search updates
    them).  ``stats`` (3,) int receives the Newton
    iterations, the cold searches and the warm starts or follows that fell back on one.  Every minimum is
    returned, touching or not: a contact carries force where its gap (field 0) is negative.
    """
    stats[0] = 0
    stats[1] = 0
    stats[2] = 0
    for p in range(pairs.shape[0]):
        i = pairs[p, 0]
        j = pairs[p, 1]
        c1, q1, R1, r1 = centres[i], orientations[i], R[i], r[i]
        c2, q2, R2, r2 = centres[j], orientations[j], R[j], r[j]
        if mode == FOLLOW and counts[p] > 0:
            if pair_contacts_follow(c1, q1, R1, r1, c2, q2, R2, r2, state[p], counts[p], iterations, out[p]) == 1:
                stats[0] += iterations * counts[p]
                continue
            stats[2] += 1
        if mode == WARM and counts[p] > 0:
            rows, spent, fell_back = pair_contacts_warm(c1, q1, R1, r1, c2, q2, R2, r2, n_scan, state[p], counts[p],
                                                        iterations, out[p])  # fmt: skip
            stats[1] += fell_back
            stats[2] += fell_back
        else:
            rows, spent = pair_contacts(c1, q1, R1, r1, c2, q2, R2, r2, n_scan, out[p])
            stats[1] += 1
        stats[0] += spent
        counts[p] = rows
        for c in range(rows):
            state[p, c] = out[p, c, 1]


# -- minima next to a maximum in overlap ---------------------------------------------------------------------------
@_jit(inline="always")
def _share(P_a, P_b, D):
    """(x, dx/dP_a, dx/dP_b, dx/dD) of the share x = 1 - D / (D + P_a) * P_b / (P_a + P_b) of :func:`fold_weights`
    (P_a + P_b > 0)."""
    total = P_a + P_b
    f = D * P_b / ((D + P_a) * total)
    d_a = -f / (D + P_a) - f / total
    d_b = D / ((D + P_a) * total) - f / total
    d_D = P_b / ((D + P_a) * total) - f / (D + P_a)
    return 1.0 - f, -d_a, -d_b, -d_D


@_jit()
def fold_weights(c1, q1, R1, r1, c2, q2, R2, r2, rows, count, weights, slopes, tops):
    """Weights (count,) in [0, 1] of the contacts ``rows[:count]`` of a pair (minima of the distance of the centre
    circles), continuous in the pose where a maximum between two minima is itself in overlap; their derivatives
    over the approaches of the minima and of those maxima; the rows of those maxima.

    Where two tubes lie nearly parallel over an arc, the distance can have a minimum next to a maximum, both below
    r_1 + r_2; as the pose changes the two meet and vanish (a fold), and a contact counted with its full force
    would vanish with a finite force.  For each maximum in overlap, by delta_M, between minima a and b lying P_a and
    P_b below it, minimum a keeps the share S(x), x = 1 - delta_M / (delta_M + P_a) * P_b / (P_a + P_b), of its
    force (and b likewise), S(x) = 3 x^2 - 2 x^3: none at a fold (P_a -> 0), all of it as its neighbour vanishes
    (P_b -> 0) or the maximum leaves the overlap (delta_M -> 0), half each where twins merge (P_a = P_b -> 0).
    The shares of its two sides multiply.

    Each weight is a function of the approaches delta = -gap of the minima and of the maxima in overlap, and each of
    these is stationary in the angles on both circles, so its derivative over the pose is that of the distance at
    fixed angles (a unit force along the row's normal, through its point): a contact energy sum w_a phi_a(delta_a)
    has the loads of its contacts (weighted) plus dE/d(delta_c) = sum_a phi_a dw_a/d(delta_c) at every minimum and
    maximum c (:func:`~ringchain.numerics.engine.rings_step.loads`).  ``slopes`` (MAX_CONTACTS, 2 MAX_CONTACTS)
    receives dw_a/d(delta_c), column c < MAX_CONTACTS for minimum c, MAX_CONTACTS + m for the maximum m after the
    m-th minimum by angle; ``tops`` (MAX_CONTACTS, FIELDS) the row of that maximum (module notes; its column of
    ``slopes`` is zero where it is out of overlap, and its row then unwritten).  Where twins merge exactly
    (P_a = P_b = 0) the derivative depends on the direction (the weights on the ratio P_a / P_b) and is set to zero.
    """
    for i in range(count):
        weights[i] = 1.0
        for c in range(2 * MAX_CONTACTS):
            slopes[i, c] = 0.0
    if count < 2:
        return
    M1, M2, k, order = _posed(c1, q1, c2, q2, MAX_CONTACTS)
    for i in range(count):
        order[i] = i
    for i in range(1, count):  # by angle (count <= MAX_CONTACTS: insertion sort)
        j = i
        while j > 0 and rows[int(order[j - 1]), 1] > rows[int(order[j]), 1]:
            order[j - 1], order[j] = order[j], order[j - 1]
            j -= 1
    rim = r1 + r2
    for i in range(count):  # the maximum after each minimum (two minima: one each way round the circle)
        a, b = int(order[i]), int(order[(i + 1) % count])
        if not (rows[a, 0] < 0.0 and rows[b, 0] < 0.0):
            continue  # a maximum above a minimum out of contact is out of contact too
        lo, hi = rows[a, 1], rows[b, 1]
        if hi <= lo:
            hi += 2.0 * math.pi
        for _ in range(60):  # the zero of g' from + to - between the two minima, by bisection
            s = 0.5 * (lo + hi)
            _, gp, _ = _profile(k, R1, R2, math.cos(s), math.sin(s))
            if gp > 0.0:
                lo = s
            else:
                hi = s
        g, _, _ = _profile(k, R1, R2, math.cos(lo), math.sin(lo))
        top = math.sqrt(2.0 * g) - rim  # the gap at the maximum
        if top >= 0.0:
            continue
        _fields(k, c1, M1, r1, R1, c2, M2, R2, r2, lo, 0.0, tops[i])
        D = -top
        P_a, P_b = top - rows[a, 0], top - rows[b, 0]
        open_a, open_b = P_a > 0.0, P_b > 0.0  # a minimum above its maximum (rounding): P = 0, no derivative
        P_a, P_b = max(P_a, 0.0), max(P_b, 0.0)
        share_a, share_b = 0.5, 0.5
        da, db = (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)  # d share / d(delta_a, delta_b, delta_M)
        if P_a + P_b > 0.0:
            share_a, x_Pa, x_Pb, x_D = _share(P_a, P_b, D)  # P_a = delta_a - delta_M, P_b = delta_b - delta_M
            da = (x_Pa * open_a, x_Pb * open_b, x_D - x_Pa * open_a - x_Pb * open_b)
            share_b, x_Pb, x_Pa, x_D = _share(P_b, P_a, D)
            db = (x_Pa * open_a, x_Pb * open_b, x_D - x_Pa * open_a - x_Pb * open_b)
        # smoothed (3 x^2 - 2 x^3: a half stays a half), so that a minimum that the scan finds or misses a rounding
        # error from its fold carries a share of order (P / delta_M)^2, not P / delta_M
        for m, share, d in ((a, share_a, da), (b, share_b, db)):
            factor = share * share * (3.0 - 2.0 * share)
            slope = 6.0 * share * (1.0 - share)  # dS/dx
            for c in range(2 * MAX_CONTACTS):  # the product rule: w_m := w_m S
                slopes[m, c] *= factor
            slopes[m, a] += weights[m] * slope * d[0]
            slopes[m, b] += weights[m] * slope * d[1]
            slopes[m, MAX_CONTACTS + i] += weights[m] * slope * d[2]
            weights[m] *= factor


numba.config.CACHE_DIR = _previous_cache_dir
