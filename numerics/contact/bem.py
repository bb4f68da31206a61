r"""Numerical contact of two interlocked tori at every contact angle (boundary elements on the exact gap).

The Hertz theory of :mod:`ringchain.theory.contact` (paper Eq. 1, App. A) replaces the gap
between the tori by its quadratic part and holds above theta_min = arccos(1 - 2r/R) only.
Here the exact gap (:func:`ringchain.theory.gap.torus_gap` and the torus distance
:func:`~ringchain.theory.gap.torus_distance`) is loaded by a frictionless, non-adhesive
contact between elastic half-spaces, solved with FFT boundary elements on a non-periodic
grid (:mod:`.halfspace`: Polonsky and Keer's constrained conjugate gradients on Love's
pixel kernel, convolved by FFT on Hockney's padded grid).

Geometry (:func:`~ringchain.theory.gap.contact_patches`).  At and above theta_min the
tori touch at one point on the chain axis.  Below it they touch at two points, at +-c along
the bisector e of the ring planes, on the flanks of the tubes; the common normal n there
leans by the tilt phi from the chain axis about e (e is perpendicular to n, by the symmetry
of the two tori), and the tori at centre distance 2(R - r) already overlap by -gap.

- ``frame="tangent"`` (default): each contact is solved in its own tangent plane, spanned by
  e and e2 = n x e, with the gap measured along n (rays cast from the plane to both tori).
  A rigid approach delta along the chain axis is an approach delta cos(phi) along n (its
  component delta sin(phi) along e2 slides the frictionless surfaces and changes the gap by
  terms of order delta^2/r, neglected), and the axial force is the sum of the patches'
  normal forces times cos(phi).
- ``frame="axial"``: the naive model, every gap measured along the chain axis and solved
  in the plane normal to it (exactly the closed-form gap of the theory).  Below theta_min
  it overstates the stiffness, by about cos(phi)^(-3/2) for a Hertz-like patch.

The two patches push on the same two bodies; their elastic interaction is included.  If
they are far apart compared with their size, each is solved on its own window and sees the
other's load as the Boussinesq displacement P/(pi E* rho) of a point load at its centre
(rho the distance to it; the neglected multipoles are smaller by (size/rho)^2).  Otherwise
both are solved on one grid, the unfolded plane: its half x > 0 is the tangent plane of the
patch at +c and its half x < 0 the half-turned image, the tangent plane of the patch at -c,
so that the half-space kernel couples them directly.

The approach delta is measured from first contact: centre distance minus
2(R - r) + gap (the paper's a = 2(R - r) above theta_min).

Resolution.  The window holds the largest contact with a margin; the spacing puts
:data:`POINTS_ACROSS` pixels across the smallest contact along each axis (a pilot solve at
the smallest and largest force measures both).  On a sphere, 16 pixels across give the Hertz
force at a given approach to 0.2 % (8 pixels: 0.7 %).  The result is then checked: at the
smallest and largest force the approach found is imposed on a grid 1.5 times coarser, and
the relative change of the force is :attr:`ContactCurve.resolution_error`; above 1 % the
spacing is refined by 1.5 and the curve solved again.  As the error falls with refinement,
the production grid's error is below that figure.

Half-space limit.  The half-space treats the surface slopes within the contact as small and
the bodies as large compared with it; on a tube of radius r both assumptions are off by
terms of relative order (contact half-length)/r.  :data:`HALF_SPACE_LIMIT` = 0.1 r is
where we warn (:class:`HalfSpaceWarning`); the half-lengths are in
:attr:`ContactCurve.extent`.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass

import numpy as np
from ringchain.theory import DEFAULT_FORCE_WINDOW
from ringchain.theory import _validate as v

from .halfspace import ElasticHalfSpace

__all__ = [
    "ContactCurve",
    "PressureMaps",
    "contact_curve",
    "HalfSpaceWarning",
    "ResolutionWarning",
    "HALF_SPACE_LIMIT",
    "POINTS_ACROSS",
    "RESOLUTION_TOLERANCE",
    "FRAMES",
]

#: Largest contact half-length, as a fraction of the tube radius r, before :class:`HalfSpaceWarning`.
HALF_SPACE_LIMIT = 0.1

#: Pixels across the smallest contact of a curve along each axis of the grid (see the module notes).
POINTS_ACROSS = 16

#: Relative force change allowed between the production grid and one 1.5 times coarser.
RESOLUTION_TOLERANCE = 0.01

#: Frames in which the gap is measured: each contact's tangent plane, or the plane normal to the chain axis.
FRAMES = ("tangent", "axial")

_COARSENING = 1.5  # spacing ratio of the resolution check and of each refinement
_MAX_PASSES = 4  # window/spacing adjustments before giving up
_JOINT_SEPARATION = 2.0  # one grid for both patches if their windows are closer than this many window lengths
_GAP_ROUNDING = 16  # the gap's rounding, in units of eps (R - r) (measured: 7e-18 m rms, 3e-17 m at most, R = 22.5 mm)
_GAP_DIGITS = 100  # the smallest approach admitted, in units of the gap's rounding


class HalfSpaceWarning(UserWarning):
    """A contact larger than :data:`HALF_SPACE_LIMIT` times the tube radius: the half-space model is stretched."""


class ResolutionWarning(UserWarning):
    """The force did not converge to :data:`RESOLUTION_TOLERANCE` within the allowed refinements."""


class _OffTheTube(RuntimeError):
    """A ray from the plane of the maps misses a torus: the grid reaches round the side of the tube."""


@dataclass(frozen=True)
class PressureMaps:
    """Contact pressure of every load on the grid of the solution.

    Attributes
    ----------
    x : ndarray
        (nx,) pixel centres along the bisector of the ring planes, m, from the chain axis
        (in the tangent frame: the unfolded plane, see the module notes).
    y : ndarray
        (ny,) pixel centres across it, m (along e2 = n x e).
    p : ndarray
        (n_forces, nx, ny) pressure, Pa (normal to the plane of the map).
    mirrored : bool
        True if the map holds only the contact at x > 0; the other one is its mirror image
        (x -> -x), by the half-turn symmetry of the two tori.
    """

    x: np.ndarray
    y: np.ndarray
    p: np.ndarray
    mirrored: bool


@dataclass(frozen=True)
class ContactCurve:
    """Force against approach of two interlocked tori, from :func:`contact_curve`.

    Attributes
    ----------
    force : ndarray
        Force along the chain axis, N, increasing.
    delta : ndarray
        Approach along the chain axis from first contact, m (for a curve returned by
        :meth:`series`, the extension of contact and bending in series).
    area : ndarray
        Total contact area of all patches, m^2 (in the plane of the maps).
    n_patches : ndarray
        Number of separate contact regions at each force.
    extent : ndarray
        Largest half-length of a contact region (from its contact point), m.
    pressure : PressureMaps
        The pressure maps and their grid.
    R, r, E_star, angle : float
        Radii (m), effective modulus (Pa) and contact angle (rad) of the tori.
    frame : str
        ``"tangent"`` or ``"axial"`` (see the module notes).
    tilt : float
        Angle between the contact normal and the chain axis, rad (0 above theta_min).
    resolution_error : float
        Relative change of the force on a grid 1.5 times coarser (module notes).
    grid : tuple
        (nx, ny, hx, hy): pixels and spacing (m) of the grid.
    K_b : float or None
        Bending stiffness in series (N/m) if the curve comes from :meth:`series`.
    """

    force: np.ndarray
    delta: np.ndarray
    area: np.ndarray
    n_patches: np.ndarray
    extent: np.ndarray
    pressure: PressureMaps
    R: float
    r: float
    E_star: float
    angle: float
    frame: str
    tilt: float
    resolution_error: float
    grid: tuple
    K_b: float | None = None

    @property
    def local_exponent(self) -> np.ndarray:
        """d ln F / d ln delta at each force (second-order finite differences in ln delta)."""
        return np.gradient(np.log(self.force), np.log(self.delta))

    def fit(self, window=DEFAULT_FORCE_WINDOW, n=None) -> tuple[float, float]:
        """(K in N/m^n, n) of F = K delta^n fitted over the force ``window`` (N), paper Eq. (4).

        The least squares of :func:`ringchain.theory.fit_power_law` (equal weight per decade of
        force); ``n`` fixes the exponent (``n=1.5`` gives an effective Hertz constant K_c).
        The window must lie within the curve's forces.
        """
        from ringchain.theory.series import fit_power_law_to_curve

        F_min, F_max = window
        return fit_power_law_to_curve(self.force, self.delta, F_min, F_max, n=n)

    def series(self, K_b) -> ContactCurve:
        """This contact in series with a ring's bending spring K_b (N/m): paper Eq. (3).

        Returns a :class:`ContactCurve` whose ``delta`` is the extension delta_c + F/K_b
        (:func:`ringchain.theory.series_extension`); its :meth:`fit` gives Table II's K and n.
        """
        from ringchain.theory.series import series_extension

        if self.K_b is not None:
            raise ValueError("this curve already includes a bending spring")
        K_b = float(v.positive("K_b", K_b, "N/m"))
        return dataclasses.replace(self, delta=series_extension(self.force, delta_c=self.delta, K_b=K_b), K_b=K_b)


# -- geometry ------------------------------------------------------------------------------------------
def _half_turn(vector):
    """Image of a vector under the half turn about the chain axis (a symmetry of the two tori)."""
    return np.array([-vector[0], -vector[1], vector[2]])


class Tori:
    """The two tori at first contact and the frames in which their gap is measured."""

    def __init__(self, R, r, angle, frame):
        from ringchain.theory.gap import contact_patches

        self.R, self.r, self.angle, self.frame = R, r, angle, frame
        c, gap, tilt = (float(x) for x in contact_patches(R, r, angle))
        self.c, self.n_patches = c, (2 if c > 0 else 1)
        self.first_contact = 2 * (R - r) + gap  # centre distance at first contact
        self.z0 = R - r + gap / 2  # height of the contact points
        self.e = np.array([np.cos(angle / 2), np.sin(angle / 2), 0.0])
        if frame == "tangent":
            self.tilt = tilt
            self.normal = self._common_normal()
        else:
            self.tilt = 0.0
            self.normal = np.array([0.0, 0.0, 1.0])
        self.across = np.cross(self.normal, self.e)
        self.across /= np.linalg.norm(self.across)

    def _common_normal(self):
        """Unit normal at the contact point at +c, pointing from ring 2 into ring 1."""
        from ringchain.theory.gap import torus_distance

        point = self.c * self.e + np.array([0.0, 0.0, self.z0])
        _, gradient = torus_distance(*point, self.R, self.r)
        normal = -np.array([float(g) for g in gradient])
        normal -= np.dot(normal, self.e) * self.e  # zero by symmetry; removes rounding
        return normal / np.linalg.norm(normal)

    def _distance(self, ring, points):
        """Distance of ``points`` (3, ...) to ring 1 or 2 (first contact) and its gradient."""
        from ringchain.theory.gap import torus_distance

        x, y, z = points
        if ring == 1:
            D, (gx, gy, gz) = torus_distance(x, y, z, self.R, self.r)
            return D, np.stack([gx, gy, gz])
        cos, sin = np.cos(self.angle), np.sin(self.angle)
        D, (gs, gt, gz) = torus_distance(x * cos + y * sin, -x * sin + y * cos, z - self.first_contact, self.R, self.r)
        return D, np.stack([gs * cos - gt * sin, gs * sin + gt * cos, gz])

    def _cast(self, ring, origins, direction):
        """s with D(origin + s direction) = 0 for ring 1 or 2, by Newton's method from s = 0."""
        s = np.zeros(origins.shape[1:])
        step = direction.reshape(3, *([1] * s.ndim))
        tolerance = 1e-12 * self.r
        for _ in range(60):
            D, gradient = self._distance(ring, origins + s * step)
            slope = np.tensordot(direction, gradient, axes=1)
            update = D / slope
            s = s - update
            if np.all(np.abs(update) < tolerance):
                return s
        raise _OffTheTube("ray casting onto the torus did not converge: the window reaches too far round the tube")

    def gap(self, x, y):
        """Gap (m) along the contact normal at points (x, y) of the plane of the maps.

        ``x`` runs along the bisector from the chain axis and ``y`` across; points with x < 0
        belong to the half-turned frame of the contact at -c (module notes).
        """
        x, y = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float))
        gap = np.empty(x.shape)
        for side in (1, -1) if self.n_patches == 2 else (1,):
            mask = x >= 0 if side == 1 else x < 0
            mask = mask if self.n_patches == 2 else np.ones(x.shape, bool)
            if not np.any(mask):
                continue
            normal = self.normal if side == 1 else _half_turn(self.normal)
            across = self.across if side == 1 else _half_turn(self.across)
            xs, ys = x[mask], y[mask]
            origins = (
                np.array([0.0, 0.0, self.z0])[:, None] + self.e[:, None] * xs[None, :] + across[:, None] * ys[None, :]
            )
            gap[mask] = self._cast(1, origins, normal) - self._cast(2, origins, normal)
        return gap

    def normal_force_per_patch(self, force):
        """Normal force on each patch carrying the axial ``force`` (N)."""
        return force / (self.n_patches * np.cos(self.tilt))

    def axial_approach(self, normal_approach):
        return normal_approach / np.cos(self.tilt)


# -- one grid ------------------------------------------------------------------------------------------
@dataclass
class _Grid:
    x0: float  # lower edge along x (from the axis), m
    y0: float
    nx: int
    ny: int
    hx: float
    hy: float
    joint: bool  # both patches on this grid

    @property
    def x(self):
        return self.x0 + (np.arange(self.nx) + 0.5) * self.hx

    @property
    def y(self):
        return self.y0 + (np.arange(self.ny) + 0.5) * self.hy

    def coarsened(self, factor):
        nx, ny = max(4, round(self.nx / factor)), max(4, round(self.ny / factor))
        return _Grid(self.x0, self.y0, nx, ny, self.nx * self.hx / nx, self.ny * self.hy / ny, self.joint)


def _fft_size(n):
    """Smallest integer >= n whose prime factors are 2, 3 and 5 (fast FFT lengths)."""
    n = max(int(np.ceil(n)), 4)
    while True:
        m = n
        for p in (2, 3, 5):
            while m % p == 0:
                m //= p
        if m == 1:
            return n
        n += 1


class _Solver:
    """Boundary elements on one grid; the elastic kernel is built once and reused for every load."""

    def __init__(self, tori, E_star, grid, curvatures):
        self.tori, self.E_star, self.grid, self.curvatures = tori, E_star, grid, curvatures
        X, Y = np.meshgrid(grid.x, grid.y, indexing="ij")
        self.X, self.Y = X, Y
        self.gap = tori.gap(X, Y)
        self.halfspace = ElasticHalfSpace((grid.nx, grid.ny), (grid.nx * grid.hx, grid.ny * grid.hy), E_star)
        separate = tori.n_patches == 2 and not grid.joint
        self.patches_on_grid = 2 if tori.n_patches == 2 and grid.joint else 1
        # The other patch (at -c) seen from this one's grid: Boussinesq's point-load displacement per newton.
        self.interaction = 1.0 / (np.pi * E_star * np.hypot(X + tori.c, Y)) if separate else 0.0

    def solve(self, load, approach, *, force_control=True):
        """One contact problem: the normal load per patch ``load`` (N) with ``approach`` (m) as the
        starting guess, or (``force_control=False``) the approach imposed, ``load`` setting the
        interaction and tolerances.  Returns the :class:`~.halfspace.HalfSpaceContact`."""
        total = load * self.patches_on_grid
        gap = self.gap + load * self.interaction
        # Start from Hertz's pressure shape on the gap: sqrt(delta/2 - gap) is exact for a quadratic gap.
        # Polonsky and Keer's iteration started from one pixel takes more steps to find the contact.
        guess = np.sqrt(np.maximum(0.0, approach / 2 - gap))
        if not guess.any():
            guess[np.unravel_index(np.argmin(gap), gap.shape)] = 1.0
        guess *= total / guess.sum()
        options = dict(initial_forces=guess, pentol=1e-6 * self._approach_scale(load), forcetol=1e-9 * total)
        if force_control:
            return self.halfspace.solve(gap, load=total, **options)
        return self.halfspace.solve(gap, approach=approach, **options)

    def _approach_scale(self, P):
        """Rough normal approach (m) of a load P, from the Hertz sphere of the local curvature (for tolerances)."""
        return _hertz_sphere_approach(P, self.E_star, self.curvatures)


def _hertz_sphere_approach(P, E_star, curvatures):
    """Approach (m) of a sphere of radius 1/(2 sqrt(A B)) under the normal load P: a scale, not a result."""
    A, B = curvatures
    R_e = 1.0 / (2 * np.sqrt(A * B))
    return (3 * P / (4 * E_star * np.sqrt(R_e))) ** (2 / 3)


def _curvatures(tori, step):
    """Quadratic coefficients (A along x, B along y, 1/m) of the gap at the contact point at +c."""
    x = tori.c + step * np.array([-1.0, 0.0, 1.0])
    along = tori.gap(x, 0.0 * x)
    across = tori.gap(np.full(3, tori.c), step * np.array([-1.0, 0.0, 1.0]))
    A = (along[0] - 2 * along[1] + along[2]) / (2 * step**2)
    B = (across[0] - 2 * across[1] + across[2]) / (2 * step**2)
    return max(A, 1e-3 * B), B


def overlap_box(tori, depth, *, limit):
    """Extent of {gap < depth} along the lines through the contact point at +c: (x_lo, x_hi, y_half), m.

    Marches outward in steps that grow geometrically from 1e-9 limit to ``limit`` (2.6 % each: a
    contact of any size, down to nanometres on a millimetre tube, is found to that precision) and
    stops at the first point past ``depth`` (or at ``limit``, or, for two patches, at the chain axis).
    """

    def reach(direction, start):
        steps = np.geomspace(1e-9 * limit, limit, 800)
        for chunk in np.split(steps, 16):
            points = start[:, None] + direction[:, None] * chunk[None, :]
            if tori.n_patches == 2 and direction[0] < 0:
                points = points[:, points[0] > 0]
                if not points.size:
                    return 0.0
            g = tori.gap(points[0], points[1])
            outside = np.nonzero(g > depth)[0]
            if outside.size:
                return points[int(direction[1] != 0)][outside[0]]
        return points[int(direction[1] != 0)][-1]

    centre = np.array([tori.c, 0.0])
    x_lo = reach(np.array([-1.0, 0.0]), centre)
    x_hi = reach(np.array([1.0, 0.0]), centre)
    y_half = reach(np.array([0.0, 1.0]), centre)
    return x_lo, x_hi, y_half


def _grid_for(tori, x_lo, x_hi, y_half, hx, hy):
    """A grid covering [x_lo, x_hi] x [-y_half, y_half], the joint grid if the patches' windows come close."""
    joint = tori.n_patches == 1
    if tori.n_patches == 2 and x_lo < _JOINT_SEPARATION * (x_hi - x_lo):
        joint, x_lo = True, -x_hi
    if joint and tori.n_patches == 1:
        half = max(abs(x_lo), abs(x_hi))
        x_lo, x_hi = -half, half  # symmetric about the axis (the gap is even in x there)
    nx = _fft_size((x_hi - x_lo) / hx)
    if joint:
        nx += nx % 2  # an even count puts the axis between two pixels, so both halves match
    ny = _fft_size(2 * y_half / hy)
    ny += ny % 2
    hx, hy = (x_hi - x_lo) / nx, 2 * y_half / ny
    return _Grid(x_lo, -y_half, nx, ny, hx, hy, joint)


def _contact_box(grid, pressure, tori):
    """Bounding box (x_lo, x_hi, y_half) of the contact at +c, and whether any contact touches the grid's edge."""
    inside = pressure > 0
    touches = bool(inside[0].any() or inside[-1].any() or inside[:, 0].any() or inside[:, -1].any())
    if tori.n_patches == 2 and grid.joint:
        inside = inside & (grid.x[:, None] > 0)
    ix = np.nonzero(inside.any(axis=1))[0]
    iy = np.nonzero(inside.any(axis=0))[0]
    x_lo = grid.x0 + ix[0] * grid.hx
    x_hi = grid.x0 + (ix[-1] + 1) * grid.hx
    y_half = max(abs(grid.y0 + iy[0] * grid.hy), abs(grid.y0 + (iy[-1] + 1) * grid.hy))
    return x_lo, x_hi, y_half, touches


# -- the curve -----------------------------------------------------------------------------------------
def contact_curve(R, r, E, nu, angle, forces, *, frame="tangent", points_across=POINTS_ACROSS) -> ContactCurve:
    """Force against approach of two interlocked identical tori, at any contact angle, by boundary elements.

    Parameters
    ----------
    R, r : float
        Major and tube radius of both tori, m (R > 2 r).
    E : float
        Young's modulus, Pa.
    nu : float
        Poisson's ratio, in (-1, 0.5).
    angle : float
        Contact angle theta between the ring planes, rad, in (2 arcsin(r/R), pi/2]; below
        theta_min = arccos(1 - 2r/R) the tori touch at two patches.
    forces : array_like
        Forces along the chain axis, N, > 0 (sorted; duplicates removed).
    frame : {"tangent", "axial"}, optional
        Measure the gap along each contact's normal (default) or along the chain axis (the
        naive model, for comparison); see the module notes.
    points_across : int, optional
        Pixels across the smallest contact along each axis (default :data:`POINTS_ACROSS`).

    Returns
    -------
    ContactCurve
        Force, approach from first contact, area, patches, pressure maps; ``fit`` gives
        F = K delta^n (Eq. (4)) and ``series(K_b)`` the contact in series with the ring's
        bending (Eq. (3)).

    Warns
    -----
    HalfSpaceWarning
        If a contact's half-length exceeds :data:`HALF_SPACE_LIMIT` r.
    ResolutionWarning
        If the force did not converge to :data:`RESOLUTION_TOLERANCE`.

    Notes
    -----
    Frictionless, non-adhesive contact of elastic half-spaces with the exact torus gap; at
    and above theta_min it reproduces :func:`ringchain.theory.hertz_stiffness` (Eq. (1),
    App. A) at small load.  See the module notes for the frames, the two patches'
    interaction, the resolution and the half-space limit.

    Examples
    --------
    >>> curve = contact_curve(22.5e-3, 2.5e-3, 193e9, 0.29, np.pi / 2, [0.1, 1.0])
    >>> [int(k) for k in curve.n_patches], curve.frame
    ([1, 1], 'tangent')
    """
    from ringchain.theory.contact import contact_modulus
    from ringchain.theory.gap import contact_patches

    R = float(v.positive("R", R, "m"))
    r = float(v.positive("r", r, "m"))
    angle = float(v.as_float("angle", angle))
    contact_patches(R, r, angle)  # validates R > 2 r and the angle, with errors that say why
    E_star = float(contact_modulus(E, nu))
    forces = np.unique(v.positive("forces", forces, "N").ravel())
    if not forces.size:
        raise ValueError("forces must hold at least one force (N), got none")
    if frame not in FRAMES:
        raise ValueError(f"frame must be one of {FRAMES}, got {frame!r}")
    points_across = int(points_across)
    if points_across < 4:
        raise ValueError(f"points_across must be at least 4, got {points_across}")
    tori = Tori(R, r, angle, frame)
    loads = tori.normal_force_per_patch(forces)
    A, B = _curvatures(tori, 1e-3 * r)
    _check_isolated(tori, B)
    _check_resolvable(tori, E_star, (A, B), forces, loads)
    with np.errstate(over="ignore"):  # a force so large that the estimate overflows is round the tube too
        estimate = np.sqrt(_hertz_sphere_approach(loads[-1], E_star, (A, B)) / (2 * np.sqrt(A * B)))
    if not estimate < r:  # the contact radius of the Hertz sphere of the local curvatures
        raise _round_the_tube(forces[-1])
    try:
        return _curve(tori, E_star, forces, loads, (A, B), points_across)
    except _OffTheTube:
        raise _round_the_tube(forces[-1]) from None


def _round_the_tube(force):
    return ValueError(
        f"the contact reaches round the tube at {force:.3g} N: the window that holds it takes in the sides of the "
        f"tubes, where no half-space describes the surfaces (limit {HALF_SPACE_LIMIT:g} r); ask for smaller forces"
    )


def _curve(tori, E_star, forces, loads, curvatures, points_across):
    """:func:`contact_curve` of checked inputs."""
    R, r, angle, frame = tori.R, tori.r, tori.angle, tori.frame
    A, B = curvatures

    # Pilot: window from the rigid overlap at twice a Hertz-sphere estimate of the approach, coarse grid.
    x_lo, x_hi, y_half = overlap_box(tori, 2 * _hertz_sphere_approach(loads[-1], E_star, (A, B)), limit=0.9 * r)
    small = overlap_box(tori, 2 * _hertz_sphere_approach(loads[0], E_star, (A, B)), limit=0.9 * r)
    hx = (small[1] - small[0]) / (points_across / 2)
    hy = 2 * small[2] / (points_across / 2)
    spacing_factor = 1.0
    for _ in range(_MAX_PASSES * 3):
        grid = _grid_for(tori, x_lo, x_hi, y_half, hx * spacing_factor, hy * spacing_factor)
        solver = _Solver(tori, E_star, grid, (A, B))
        first = solver.solve(loads[0], solver._approach_scale(loads[0]))
        last = solver.solve(loads[-1], solver._approach_scale(loads[-1]))
        box_small = _contact_box(grid, first.forces, tori)
        box_large = _contact_box(grid, last.forces, tori)
        if box_large[3]:  # the largest contact reaches the edge: enlarge the window and try again
            x_lo, x_hi, y_half = _enlarged(tori, x_lo, x_hi, y_half, 1.5)
            continue
        break
    else:  # pragma: no cover - defensive
        raise RuntimeError("could not find a window holding the largest contact")
    # Production grid: the largest contact with a margin, the smallest one resolved by points_across pixels.
    margin = 0.25
    width = box_large[1] - box_large[0]
    x_lo, x_hi = box_large[0] - margin * width, box_large[1] + margin * width
    y_half = box_large[2] * (1 + 2 * margin)
    if tori.n_patches == 2:
        x_lo = max(x_lo, 0.0)
    hx = (box_small[1] - box_small[0]) / points_across
    hy = 2 * box_small[2] / points_across
    for _ in range(_MAX_PASSES):
        grid = _grid_for(tori, x_lo, x_hi, y_half, hx, hy)
        solution = _solve_curve(tori, E_star, grid, loads, (A, B))
        if solution["touches"]:
            x_lo, x_hi, y_half = _enlarged(tori, x_lo, x_hi, y_half, 1.3)
            continue
        error = _resolution_error(tori, E_star, grid, loads, solution, (A, B))
        if error <= RESOLUTION_TOLERANCE:
            break
        hx, hy = hx / _COARSENING, hy / _COARSENING
    else:
        warnings.warn(
            f"the contact force changed by {error:.2%} between grids after {_MAX_PASSES} refinements "
            f"(tolerance {RESOLUTION_TOLERANCE:.0%})",
            ResolutionWarning,
            stacklevel=3,
        )
    extent = solution["extent"]
    if np.any(extent > HALF_SPACE_LIMIT * r):
        k = int(np.argmax(extent > HALF_SPACE_LIMIT * r))
        warnings.warn(
            f"at {forces[k]:.3g} N and above the contact reaches {extent[k] / r:.2f} r from its centre "
            f"(up to {extent.max() / r:.2f} r at {forces[-1]:.3g} N); the half-space model assumes it small "
            f"compared with the tube radius r (limit {HALF_SPACE_LIMIT:g} r)",
            HalfSpaceWarning,
            stacklevel=3,
        )
    mirrored = tori.n_patches == 2 and not grid.joint
    return ContactCurve(
        force=forces,
        delta=tori.axial_approach(solution["approach"]),
        area=solution["area"] * (2 if mirrored else 1),
        n_patches=solution["n_patches"] * (2 if mirrored else 1),
        extent=extent,
        pressure=PressureMaps(grid.x, grid.y, solution["pressure"], mirrored),
        R=R,
        r=r,
        E_star=E_star,
        angle=angle,
        frame=frame,
        tilt=tori.tilt,
        resolution_error=error,
        grid=(grid.nx, grid.ny, grid.hx, grid.hy),
    )


def _check_isolated(tori, B):
    """Refuse angles at which the gap curves away from the contact points across the bisector (B <= 0).

    Just above 2 arcsin(r/R) the two contact points sit on the flanks of the tubes, and the gap across
    them falls away instead of rising: the tori touch along lines, not at two points, and no
    half-space contact of a point describes them.  The message names the angle where B = 0.
    """
    if B > 0:
        return
    from ringchain.theory import minimum_contact_angle, smallest_patch_angle
    from scipy.optimize import brentq

    def across(angle):
        return _curvatures(Tori(tori.R, tori.r, angle, tori.frame), 1e-3 * tori.r)[1]

    lo, hi = tori.angle, float(minimum_contact_angle(tori.R, tori.r))
    floor = float(smallest_patch_angle(tori.R, tori.r))
    lowest = brentq(across, max(lo, floor), hi, xtol=1e-9) if across(hi) > 0 else hi
    raise ValueError(
        f"at {math.degrees(tori.angle):.6g} deg the gap between the tubes curves away from the contact points "
        f"across the bisector (curvature {B:.3g} 1/m): the tori touch along lines there, not at two points, and "
        f"the numerical contact does not apply; for R/r = {tori.R / tori.r:.6g} it needs the contact angle above "
        f"about {math.degrees(lowest):.4g} deg"
    )


def _check_resolvable(tori, E_star, curvatures, forces, loads):
    """Refuse forces whose approach comes near the rounding of the gap, where no grid resolves the contact.

    The gap is a difference of two distances of order R - r, so it is known to a few units of
    eps (R - r), about 1e-17 m on the paper's rings (measured: 7e-18 rms at 90 deg).  The
    smallest approach admitted is :data:`_GAP_DIGITS` times that rounding (the force is then
    within 0.3 % of Hertz's; at the rounding itself the "contact" is rounding noise).
    """
    rounding = _GAP_ROUNDING * np.finfo(float).eps * (tori.R - tori.r)
    smallest = _GAP_DIGITS * rounding
    if _hertz_sphere_approach(loads[0], E_star, curvatures) >= smallest:
        return
    A, B = curvatures
    R_e = 1.0 / (2 * np.sqrt(A * B))
    floor = 4 / 3 * E_star * np.sqrt(R_e) * smallest**1.5 * forces[0] / loads[0]  # the sphere's load, axial
    raise ValueError(
        f"forces must be at least {floor:.2g} N for these rings, got {forces[0]:.3g} N: below, the approach is "
        f"within {_GAP_DIGITS:g} times the rounding of the gap between the tori ({rounding:.1g} m) and the boundary "
        "elements cannot resolve the contact (at such loads each patch is a Hertz contact of the gap's curvatures)"
    )


def _enlarged(tori, x_lo, x_hi, y_half, factor):
    centre = tori.c
    x_lo = centre - factor * (centre - x_lo)
    x_hi = centre + factor * (x_hi - centre)
    if tori.n_patches == 2:
        x_lo = max(x_lo, 0.0)
    return x_lo, x_hi, factor * y_half


def _solve_curve(tori, E_star, grid, loads, curvatures):
    """Every load on one grid (one elastic kernel), each solve started from the previous displacements."""
    from scipy import ndimage

    solver = _Solver(tori, E_star, grid, curvatures)
    pixel = grid.hx * grid.hy
    approach, area, patches, extent, pressure = [], [], [], [], []
    touches = False
    guess = solver._approach_scale(loads[0])
    for k, P in enumerate(loads):
        if k:  # Hertz's scaling from the previous load
            guess = approach[-1] * (P / loads[k - 1]) ** (2 / 3)
        result = solver.solve(P, guess)
        forces = result.forces
        p = forces / pixel
        inside = forces > 0
        approach.append(result.approach)
        area.append(inside.sum() * pixel)
        patches.append(ndimage.label(inside)[1])
        centre = np.where(solver.X > 0, tori.c, -tori.c) if tori.n_patches == 2 else 0.0
        half = np.maximum(np.abs(solver.X - centre) + grid.hx / 2, np.abs(solver.Y) + grid.hy / 2)
        extent.append(half[inside].max())
        pressure.append(p)
        touches |= _contact_box(grid, forces, tori)[3]
    return dict(
        approach=np.array(approach),
        area=np.array(area),
        n_patches=np.array(patches),
        extent=np.array(extent),
        pressure=np.array(pressure),
        touches=touches,
        solver=solver,
    )


def _resolution_error(tori, E_star, grid, loads, solution, curvatures):
    """Largest relative force change at the smallest and largest load when the grid is 1.5 times coarser."""
    coarse = _Solver(tori, E_star, grid.coarsened(_COARSENING), curvatures)
    errors = []
    for k in (0, len(loads) - 1):
        result = coarse.solve(loads[k], solution["approach"][k], force_control=False)
        errors.append(abs(result.force / (loads[k] * coarse.patches_on_grid) - 1))
    return float(max(errors))
