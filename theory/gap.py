r"""The exact gap of two interlocked tori, beyond its quadratic (Hertz) part (beyond the paper; its Sec. IV.B).

Hertz's contact (:mod:`.contact`, paper Eq. (1) and App. A) keeps the gap between the tubes to
second order about the contact point; its curvatures A <= B are the eigenvalues of that quadratic
form.  Here the gap is derived exactly, for the BEM contact of :mod:`ringchain.numerics` and for
the two contact patches the paper reports below about 45 degrees.  Geometry: chain axis z; ring 1
is centred at the origin with its centre circle (radius R) in the xz-plane; ring 2 is the same
torus turned by theta about the chain axis and centred at (0, 0, d).  They touch on the inside of
both tubes, ring 1's tube above ring 2's; at the centre distance d = 2(R - r) (the paper's spacing
a) the contact points of the Hertz derivation coincide at (0, 0, R - r).  Step by step (each step
a function returning SymPy objects):

1. :func:`torus_distance_expr` -- the signed distance from a point to a torus, through the
   nearest point of its centre circle.
2. :func:`inner_surface_height` -- the height f(p, q) of the inner tube surface above its
   inner-equator point, solved from the distance on the branch through that point.
3. :func:`surface_gap` -- g(x, y) = f(x, y) + f(s, t), ring 2's own coordinates (s, t) turned by
   theta; :func:`surface_gap_quadratic` is its second-order Taylor polynomial, whose quadratic
   form has the eigenvalues A and B of :func:`.contact.relative_curvatures` (App. A,
   Eqs. (A1)-(A2); checked in the tests).
4. :func:`patch_geometry` -- below theta_min (:func:`.contact.minimum_angle`) the gap has two
   minima on the bisector of the ring planes: their distance from the axis, the overlap there
   and the slope of the tube, from the convex radicand of f in u = sqrt(r^2 - q^2).

Numeric functions: :func:`torus_distance`, :func:`torus_gap`, :func:`contact_patches`,
:func:`smallest_patch_angle`.
"""

from __future__ import annotations

import functools

import numpy as np

from . import _validate as v
from ._codegen import derived, sp
from .contact import minimum_angle, symbols

__all__ = [
    "gap_symbols",
    "torus_distance_expr",
    "inner_surface_height",
    "surface_gap",
    "surface_gap_quadratic",
    "patch_geometry",
    "fold_quartic",
    "torus_distance",
    "torus_gap",
    "contact_patches",
    "smallest_patch_angle",
]


# --- 1.-4. the exact gap ------------------------------------------------------------------


@functools.cache
def gap_symbols():
    """Symbols of the exact gap: x, y (position normal to the chain axis, m), X, Y, Z
    (a point in a torus's own frame, m), p, q (in-plane and out-of-plane offsets on one tube),
    L = R - r (the inner-equator radius), S, C = sin, cos of theta/2, u = sqrt(r^2 - q^2)."""
    x, y, X, Y, Z, p, q = sp.symbols("x y X Y Z p q", real=True)
    L = sp.Symbol("L", positive=True)
    S, C = sp.symbols("S C", positive=True)
    u = sp.Symbol("u", real=True)
    return dict(x=x, y=y, X=X, Y=Y, Z=Z, p=p, q=q, L=L, S=S, C=C, u=u)


def _with_inner_radius(expr):
    """``expr`` with R = L + r, L = R - r > 0, so that sqrt((R - r)^2) = R - r simplifies."""
    s, g = symbols(), gap_symbols()
    return expr.subs(s["R"], g["L"] + s["r"])


def torus_distance_expr():
    """Signed distance D(X, Y, Z) from a point to a torus (negative inside).

    The torus is the set of points at distance r from its centre circle, of radius R in the
    XZ-plane about the origin.  The nearest point of that circle to (X, Y, Z) is
    R (X, 0, Z)/sqrt(X^2 + Z^2); D is the distance to it, minus r.
    """
    s, g = symbols(), gap_symbols()
    R, r, X, Y, Z = s["R"], s["r"], g["X"], g["Y"], g["Z"]
    rho = sp.sqrt(X**2 + Z**2)
    offset = sp.Matrix([X, Y, Z]) - R * sp.Matrix([X / rho, 0, Z / rho])
    # |offset|^2 = (rho - R)^2 + Y^2, written so that the square root is visibly a distance.
    distance2 = (rho - R) ** 2 + Y**2
    if sp.simplify(distance2 - offset.dot(offset)) != 0:  # pragma: no cover - derivation check
        raise RuntimeError("distance to the centre circle")
    return sp.sqrt(distance2) - r


def inner_surface_height():
    """Height f(p, q) of a torus's inner tube surface above its inner-equator point.

    Solving D(p, q, Z) = 0 (:func:`torus_distance_expr`) for Z on the branch through the
    inner equator (p, q) = (0, 0), Z = R - r: sqrt(p^2 + Z^2) = R - sqrt(r^2 - q^2), then
    Z = sqrt((R - sqrt(r^2 - q^2))^2 - p^2).  p runs along the ring (in its plane), q
    across it (around the tube).  Returns f = Z - (R - r).
    """
    s, g = symbols(), gap_symbols()
    R, r, p, q = s["R"], s["r"], g["p"], g["q"]
    w = sp.Symbol("w", positive=True)  # sqrt(p^2 + Z^2), the distance from the ring's axis
    on_surface = torus_distance_expr().subs(sp.sqrt(g["X"] ** 2 + g["Z"] ** 2), w).subs(g["Y"], q)
    radii = sp.solve(on_surface, w)  # the outer and the inner side of the tube
    L = gap_symbols()["L"]
    inner = [root for root in radii if sp.simplify(_with_inner_radius(root.subs(q, 0)) - L) == 0]
    if len(inner) != 1:  # pragma: no cover - derivation check
        raise RuntimeError(f"inner branch of the tube not found among {radii}")
    # p^2 + Z^2 = w^2 on the inner side; ring 1's top (where ring 2 hangs) is the root Z > 0.
    height = sp.sqrt(inner[0] ** 2 - p**2)
    if sp.simplify(_with_inner_radius(height.subs({p: 0, q: 0})) - L) != 0:  # pragma: no cover
        raise RuntimeError("the upper root does not pass through the inner equator")
    return height - (R - r)


def surface_gap():
    """Exact gap g(x, y) between the two tubes along the chain axis at centre distance 2(R - r).

    Ring 1's tube surface is z_1 = (R - r) + f(x, y); ring 2, turned by theta and upside
    down, has z_2 = (R - r) - f(s, t) with s = x cos(theta) + y sin(theta) and
    t = -x sin(theta) + y cos(theta) its own in-plane and out-of-plane coordinates, so
    g = z_1 - z_2 = f(x, y) + f(s, t).  At centre distance 2(R - r) + delta the gap is
    g - delta; wherever g < 0 the undeformed tori overlap (below theta_min).
    """
    s, g = symbols(), gap_symbols()
    x, y, theta, p, q = g["x"], g["y"], s["theta"], g["p"], g["q"]
    f = inner_surface_height()
    along = x * sp.cos(theta) + y * sp.sin(theta)
    across = -x * sp.sin(theta) + y * sp.cos(theta)
    return f.subs({p: x, q: y}) + f.subs({p: along, q: across}, simultaneous=True)


def surface_gap_quadratic():
    """Second-order Taylor polynomial of :func:`surface_gap` about the axis, with L = R - r.

    Its quadratic form has the eigenvalues A and B of :func:`.contact.relative_curvatures`
    (App. A, Eqs. (A1)-(A2)); the tests check trace A + B and determinant A B.
    """
    g = gap_symbols()
    eps = sp.Symbol("epsilon", positive=True)
    scaled = _with_inner_radius(surface_gap()).subs({g["x"]: eps * g["x"], g["y"]: eps * g["y"]})
    # The eps^2 Taylor coefficient as d^2/d eps^2 at eps = 0 over 2!: the same polynomial as
    # sp.series(scaled, eps, 0, 3), which spends 8 s in trigsimp where the derivative takes 0.3 s.
    return sp.expand(sp.diff(scaled, eps, 2).subs(eps, 0) / 2)


def patch_geometry():
    """The two contact points below theta_min: distance from the axis, gap there, slope.

    By the symmetries of the two tori (a half turn about the chain axis; the reflection in
    the vertical plane through the bisector of the ring planes, which swaps them), g is
    even along the bisector direction (cos(theta/2), sin(theta/2)).  On it ring 1 has
    (p, q) = c (C, S) with C, S = cos, sin of theta/2, ring 2 (c C, -c S), so g = 2 f(c C, c S).
    With u = sqrt(r^2 - q^2) the radicand of f is W(u) = (R - u)^2 - C^2 (r^2 - u^2)/S^2,
    convex in u; dW/du = 0 gives u* = R S^2, which lies on the tube (u* < r) exactly
    when cos(theta) > 1 - 2 r/R, i.e. below theta_min.  Returns a dict of expressions in
    R, r, theta: ``c`` (distance of each point from the axis along the bisector), ``gap``
    (g there, negative: the overlap at centre distance 2(R - r)) and ``slope2`` (squared
    slope |grad f|^2 of the tube there, so the common normal leans by
    arctan(sqrt(slope2)) from the chain axis).  These hold while R sin(theta/2) > r; at
    R sin(theta/2) = r the points reach the sides of the tubes and the slope is infinite.
    """
    s, g = symbols(), gap_symbols()
    R, r, theta = s["R"], s["r"], s["theta"]
    S, C, u, L, p, q = g["S"], g["C"], g["u"], g["L"], g["p"], g["q"]
    W = (R - u) ** 2 - C**2 * (r**2 - u**2) / S**2
    (u_star,) = sp.solve(sp.diff(W, u), u)
    u_star = sp.simplify(u_star.subs(C**2, 1 - S**2))
    c = sp.sqrt((r**2 - u_star**2) / S**2)
    f = inner_surface_height()
    # W(u*) = C^2 (R^2 S^2 - r^2)/S^2: positive while R sin(theta/2) > r (the point is on
    # the upper half of the tube; at R sin(theta/2) = r it reaches the tube's side).
    per_C2 = sp.factor(sp.simplify(W.subs(u, u_star).subs(C**2, 1 - S**2) / (1 - S**2)))
    gap = 2 * (C * sp.sqrt(per_C2) - (R - r))
    slope2 = sum(sp.diff(f, v) ** 2 for v in (p, q))
    slope2 = slope2.subs({p: c * C, q: c * S}, simultaneous=True)
    slope2 = sp.factor(sp.simplify(_with_inner_radius(slope2).subs(C, sp.sqrt(1 - S**2)).subs(L, R - r)))
    half = {S: sp.sin(theta / 2), C: sp.cos(theta / 2)}
    return dict(c=sp.simplify(c.subs(half)), gap=gap.subs(half), slope2=slope2.subs(half))


def fold_quartic():
    """C (1/m^3): the quartic coefficient of the gap along the flat direction where the contact splits.

    At theta_min (:func:`.contact.minimum_angle`) the quadratic coefficient A of the gap along the bisector of the
    ring planes vanishes, and g = C c^4 + O(c^6) there (g is even along it: :func:`patch_geometry`), c the distance
    from the axis along the bisector.  The fourth derivative of :func:`surface_gap` on the bisector at c = 0 over
    4!, at theta_min, in R and r: 1/(4 R r (R - r)), each tube adding half.  The law of rigid rings near a fold
    (:func:`ringchain.numerics.engine.rings_law.contact_stiffness`) bounds Hertz's stiffness with it.
    """
    s, g = symbols(), gap_symbols()
    theta, c = s["theta"], sp.Symbol("c", real=True)
    along = surface_gap().subs({g["x"]: c * sp.cos(theta / 2), g["y"]: c * sp.sin(theta / 2)}, simultaneous=True)
    at_fold = {theta: minimum_angle()}
    quadratic = sp.simplify(_with_inner_radius(sp.diff(along, c, 2).subs(c, 0).subs(at_fold)))
    if quadratic != 0:  # pragma: no cover - derivation check
        raise RuntimeError(f"the gap's quadratic coefficient on the bisector does not vanish at theta_min: {quadratic}")
    quartic = sp.simplify(_with_inner_radius(sp.diff(along, c, 4).subs(c, 0).subs(at_fold) / 24))
    return sp.factor(sp.simplify(quartic.subs(g["L"], s["R"] - s["r"])))


# --- numeric functions ---------------------------------------------------------------------


#: Beyond this length (m) its square overflows a double.
_SQUARE_LIMIT = float(np.sqrt(np.finfo(float).max))


@derived
def _distance():
    s, g = symbols(), gap_symbols()
    D = torus_distance_expr()
    point = (g["X"], g["Y"], g["Z"])
    return (*point, s["R"], s["r"]), (D, *(sp.diff(D, v) for v in point))


@derived
def _gap():
    s, g = symbols(), gap_symbols()
    return (g["x"], g["y"], s["R"], s["r"], s["theta"]), surface_gap()


@derived
def _patches():
    s = symbols()
    geometry = patch_geometry()
    return (s["R"], s["r"], s["theta"]), (geometry["c"], geometry["gap"], sp.atan(sp.sqrt(geometry["slope2"])))


def torus_distance(X, Y, Z, R, r):
    """Signed distance from points to a torus, and its gradient (the outward unit normal).

    Parameters
    ----------
    X, Y, Z : array_like
        Points in the torus's own frame, m: centre at the origin, centre circle of radius
        R in the XZ-plane (so Y is along the torus's axis of symmetry).
    R, r : array_like
        Major and tube radius, m.

    Returns
    -------
    D : ndarray
        Distance to the surface, m; negative inside the solid torus.
    gradient : tuple of ndarray
        (dD/dX, dD/dY, dD/dZ), a unit vector away from the centre circle.

    Notes
    -----
    :func:`torus_distance_expr`.  Undefined on the axis X = Z = 0.
    """
    R, r = v.torus_radii(R, r)
    points = (v.as_float(name, w) for name, w in zip("XYZ", (X, Y, Z), strict=True))
    with np.errstate(all="ignore"):  # overflow is reported by value
        D, *gradient = _distance(*points, R, r)
    reason = "points and radii (or points on the axis X = Z = 0)"
    return v.finite_result(D, "the distance", reason), tuple(v.finite_result(g, "the normal", reason) for g in gradient)


def smallest_patch_angle(R, r):
    """Angle 2 arcsin(r/R) (rad) below which the two contact points reach the sides of the tubes.

    Below theta_min (:func:`.contact.minimum_contact_angle`) the tori touch at two points on the
    flanks of the tubes (:func:`contact_patches`); as theta falls they move round the tubes
    and reach the sides, where the common normal is perpendicular to the chain axis, at
    R sin(theta/2) = r (:func:`patch_geometry`).
    """
    R, r = v.torus_radii(R, r)
    return 2 * np.arcsin(r / R)


def torus_gap(x, y, R, r, angle):
    """Exact gap along the chain axis between two interlocked tori at centre distance 2(R - r).

    Parameters
    ----------
    x, y : array_like
        Position in the plane normal to the chain axis, m, from the axis; x lies in ring 1's
        plane, ring 2's plane is turned by ``angle`` from it.
    R, r : array_like
        Major and tube radius of both tori, m (R > 2 r).
    angle : array_like
        Contact angle theta between the ring planes, rad, in (0, pi/2].

    Returns
    -------
    ndarray
        g(x, y) in m (:func:`surface_gap`): the distance along the chain axis from ring 2's
        tube up to ring 1's; negative where the undeformed tori overlap.  Its quadratic part is
        A x'^2 + B y'^2 of App. A, Eq. (A1).

    Raises
    ------
    ValueError
        If a point does not lie over both tubes (|y| or the corresponding offset of ring 2
        exceeds r, or a point is past the inner equator's circle).
    """
    R, r = v.torus_radii(R, r)
    angle = v.in_range("angle", angle, 0.0, np.pi / 2)
    x, y = v.as_float("x", x), v.as_float("y", y)
    with np.errstate(all="ignore"):
        g = np.asarray(_gap(x, y, R, r, angle), dtype=float)
    if np.any(np.isnan(g)):
        if R.max() > _SQUARE_LIMIT:  # R^2 overflows: the gap is lost to rounding, whatever the point
            v.finite_result(g, "the gap", "radii")
        raise ValueError("x, y must lie over both tubes (|offset across each tube| < r); some points do not")
    return v.finite_result(g, "the gap", "positions and radii")


def contact_patches(R, r, angle):
    """Where the undeformed tori first touch: distance from the axis, overlap and tilt.

    Parameters
    ----------
    R, r : array_like
        Major and tube radius, m (R > 2 r).
    angle : array_like
        Contact angle theta between the ring planes, rad, in (2 arcsin(r/R), pi/2]
        (:func:`smallest_patch_angle`).

    Returns
    -------
    c : ndarray
        Distance of each contact point from the chain axis, m, along the bisector of the ring
        planes: 0 at and above theta_min (one contact), positive below it (two contacts at
        +-c).
    gap : ndarray
        :func:`torus_gap` at those points, m: 0 above theta_min; negative below it, where the
        tori at centre distance 2(R - r) overlap and first touch at 2(R - r) + gap.
    tilt : ndarray
        Angle between the common normal at the contact points and the chain axis, rad.

    Notes
    -----
    :func:`patch_geometry`; theta_min = arccos(1 - 2r/R) (:func:`.contact.minimum_contact_angle`).
    """
    R, r = v.torus_radii(R, r)
    angle = v.in_range("angle", angle, 0.0, np.pi / 2)
    lowest = smallest_patch_angle(R, r)
    if np.any(angle <= lowest):
        raise ValueError(
            f"angle must exceed 2 arcsin(r/R) = {np.degrees(np.max(lowest)):.4g} deg, where the contact points reach "
            f"the sides of the tubes (got {np.degrees(np.min(angle)):.4g} deg)"
        )
    R, r, angle = np.broadcast_arrays(R, r, angle)
    two = angle < np.arccos(1 - 2 * r / R)
    c, gap, tilt = (np.zeros(angle.shape) for _ in range(3))
    if np.any(two):
        c[two], gap[two], tilt[two] = _patches(R[two], r[two], angle[two])
    return c, gap, tilt
