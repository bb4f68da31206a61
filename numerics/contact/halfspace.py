r"""Frictionless contact of elastic half-spaces on a regular grid: FFT boundary elements, Polonsky and Keer's solver.

The surfaces meet over a rectangular window of ``nx x ny`` pixels.  Each pixel carries a uniform pressure
(its force over its area), and the normal displacement of both surfaces together at a pixel centre is the
sum over the loaded pixels of Love's solution for a uniformly loaded rectangle (Johnson, *Contact
Mechanics*, Eq. (3.25)), with the contact modulus E* of both bodies: far from the load it is
Boussinesq's P/(pi E* rho) of a point load.

Convolution.  The influence of pixel j on pixel i depends on their offset alone, so the displacements
are a discrete convolution.  It is computed by FFT on a grid padded to twice each side (Hockney 1970):
the forces fill one quarter of the ``2 nx x 2 ny`` grid, the rest is zero, and the kernel holds every
offset from -(n - 1) to n - 1 along each axis, so the circular convolution of the padded arrays equals
the non-periodic one on the window.  The kernel's transform is computed once per grid
(:class:`ElasticHalfSpace`) and reused for every load.

Contact.  With the rigid gap g (m) between the undeformed surfaces, the approach delta (m) and the pixel
forces f (N), the deformed gap is h = g + u(f) - delta.  The solution has f >= 0, h >= 0 and f h = 0:
the surfaces touch where they press and press nowhere else.  It is the minimum of the convex
quadratic 1/2 f.u(f) + f.(g - delta) over f >= 0 (its gradient is h), found by Polonsky and Keer's
(1999) constrained conjugate gradients: conjugate-gradient steps on the pixels in contact, each to the
exact minimum along its direction; pixels whose force would turn tensile leave the contact (their force
is set to zero), and pixels that overlap without force join the next step's set.  Any change of the set
restarts the gradients (a steepest-descent step); Polonsky and Keer give the joining pixels the previous
step's length instead, which can overshoot when many join at once.

- Force control (``load`` given): the total force is held, and the approach is the mean of g + u over
  the contact (the multiplier of the force constraint); the search directions have zero sum.
- Displacement control (``approach`` given): the total force follows.
- A hardness (``hardness``: the largest force per pixel, N) caps the pressure, as in Almqvist et al.
  (2007): a pixel at the cap "flows" (it may overlap, h <= 0), leaves the conjugate-gradient set, and
  returns to it when its gap opens.  The capped problem is the same quadratic with the bounds
  0 <= f <= hardness; displacement control only.

Stopping test.  The solution is accepted when the contact conditions hold to ``pentol`` (m): |h| inside
the contact, the overlap -h outside it and the opening h of flowing pixels, all measured on
displacements computed afresh from the forces; and when no pixel's force had to be clipped by more than
``forcetol`` (N) in the last step (set to zero from tensile, or to the hardness from above it), so that
the contact has settled, and no displacement moved by more than ``pentol`` in it.  The same tests in
spirit as ContactMechanics' ``pentol`` and ``forcetol``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from ringchain.theory import _validate as v

__all__ = ["ElasticHalfSpace", "HalfSpaceContact", "rectangle_displacement"]


def _corner(s, t):
    """The primitive of 1/sqrt(s^2 + t^2) in s and t, zero on both axes: s asinh(t/|s|) + t asinh(s/|t|)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        first = np.where(s == 0, 0.0, s * np.arcsinh(t / np.abs(s)))
        second = np.where(t == 0, 0.0, t * np.arcsinh(s / np.abs(t)))
    return first + second


def rectangle_displacement(x, y, a, b, E_star):
    """Surface displacement per unit pressure of a uniformly loaded rectangle, m/Pa (Love's solution).

    Parameters
    ----------
    x, y : array_like
        Point of the surface, m, from the centre of the rectangle (along its sides 2a and 2b).
    a, b : float
        Half-sides of the rectangle, m, > 0.
    E_star : float
        Contact modulus of the two bodies, Pa, > 0 (the displacement is that of both surfaces together).

    Returns
    -------
    ndarray
        The displacement at (x, y) under a pressure of 1 Pa on |x| < a, |y| < b, m/Pa: the integral of
        Boussinesq's 1/(pi E* rho) over the rectangle.

    Notes
    -----
    Johnson, *Contact Mechanics* (1985), Eq. (3.25), written with the primitive
    F(s, t) = s asinh(t/|s|) + t asinh(s/|t|) of 1/sqrt(s^2 + t^2): the integral over the rectangle is
    F(x+a, y+b) - F(x-a, y+b) - F(x+a, y-b) + F(x-a, y-b).  This form has no difference of nearly equal
    logarithms far from the rectangle, where Johnson's quotients of logarithms lose digits.

    Examples
    --------
    >>> centre = float(rectangle_displacement(0.0, 0.0, 1e-3, 1e-3, 1e11))
    >>> side = 2e-3  # the centre of a square: 4 side ln(1 + sqrt 2)/(pi E*) per pascal
    >>> round(centre / (4 * side * float(np.log(1 + np.sqrt(2))) / (np.pi * 1e11)), 12)
    1.0
    """
    a = float(v.positive("a", a, "m"))
    b = float(v.positive("b", b, "m"))
    E_star = float(v.positive("E_star", E_star, "Pa"))
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    integral = _corner(x + a, y + b) - _corner(x - a, y + b) - _corner(x + a, y - b) + _corner(x - a, y - b)
    return integral / (np.pi * E_star)


@dataclass(frozen=True)
class HalfSpaceContact:
    """A solution of :meth:`ElasticHalfSpace.solve`.

    Attributes
    ----------
    forces : ndarray
        (nx, ny) force on each pixel, N, >= 0.
    displacement : ndarray
        (nx, ny) displacement of both surfaces together at the pixel centres, m.
    approach : float
        Approach of the bodies, m (the one imposed, or the one found under force control).
    separation : ndarray
        (nx, ny) deformed gap h = gap + displacement - approach, m (<= 0 only where the pixel flows).
    flowing : ndarray
        (nx, ny) bool, pixels at the hardness (none without one).
    iterations : int
        Conjugate-gradient iterations taken.
    """

    forces: np.ndarray
    displacement: np.ndarray
    approach: float
    separation: np.ndarray
    flowing: np.ndarray
    iterations: int

    @property
    def force(self) -> float:
        """Total contact force, N."""
        return float(self.forces.sum())


class ElasticHalfSpace:
    """The non-periodic elastic half-space on a regular grid of pixels, its kernel transformed once.

    Parameters
    ----------
    shape : tuple of int
        (nx, ny) pixels, each >= 1.
    size : tuple of float
        (Lx, Ly) physical size of the window, m, > 0 (pixel spacing Lx/nx, Ly/ny).
    E_star : float
        Contact modulus of the two bodies, Pa, > 0 (1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2).

    Attributes
    ----------
    shape, size, E_star
        As given (size in m, E_star in Pa).
    spacing : tuple of float
        (hx, hy) pixel sides, m.
    pixel_area : float
        hx hy, m^2.
    self_influence : float
        Displacement of a pixel's centre per newton on that pixel, m/N (the largest of the kernel).

    Notes
    -----
    The displacement of pixel forces is their convolution with :func:`rectangle_displacement`, by FFT on
    the grid padded to (2 nx, 2 ny) (Hockney 1970; see the module notes).

    Examples
    --------
    >>> space = ElasticHalfSpace((64, 64), (2e-3, 2e-3), 1e11)
    >>> X, Y = space.coordinates()
    >>> gap = (X**2 + Y**2) / (2 * 0.01)  # a sphere of radius 1 cm on a flat
    >>> solution = space.solve(gap, load=1.0, pentol=1e-12, forcetol=1e-9)
    >>> round(solution.force, 12), bool(solution.approach > 0)
    (1.0, True)
    """

    def __init__(self, shape, size, E_star):
        from scipy import fft

        nx, ny = (int(n) for n in shape)
        if nx < 1 or ny < 1:
            raise ValueError(f"shape must hold two pixel counts >= 1, got {tuple(shape)}")
        Lx = float(v.positive("size[0]", size[0], "m"))
        Ly = float(v.positive("size[1]", size[1], "m"))
        self.E_star = float(v.positive("E_star", E_star, "Pa"))
        self.shape, self.size = (nx, ny), (Lx, Ly)
        self.spacing = (Lx / nx, Ly / ny)
        self.pixel_area = self.spacing[0] * self.spacing[1]
        self._padded = (2 * nx, 2 * ny)
        # Offsets 0, 1, ..., n - 1, then (unused) n, then -(n - 1), ..., -1: the circular order of the FFT.
        ix, iy = np.fft.fftfreq(2 * nx, 1 / (2 * nx)), np.fft.fftfreq(2 * ny, 1 / (2 * ny))
        hx, hy = self.spacing
        kernel = rectangle_displacement((ix * hx)[:, None], (iy * hy)[None, :], hx / 2, hy / 2, self.E_star)
        self.self_influence = float(kernel[0, 0]) / self.pixel_area  # m/N: a pixel's force on its own centre
        self._kernel_hat = fft.rfft2(kernel / self.pixel_area)  # displacement per newton, transformed
        self._fft = fft

    def coordinates(self):
        """(X, Y): pixel centres, m, (nx, ny) arrays, from the centre of the window."""
        (nx, ny), (hx, hy) = self.shape, self.spacing
        x = (np.arange(nx) + 0.5 - nx / 2) * hx
        y = (np.arange(ny) + 0.5 - ny / 2) * hy
        return np.meshgrid(x, y, indexing="ij")

    def displacement(self, forces):
        """Displacement at the pixel centres, m, of the (nx, ny) pixel forces ``forces`` (N)."""
        forces = np.asarray(forces, dtype=float)
        if forces.shape != self.shape:
            raise ValueError(f"forces must have the grid's shape {self.shape}, got {forces.shape}")
        nx, ny = self.shape
        transformed = self._fft.rfft2(forces, s=self._padded)
        return self._fft.irfft2(transformed * self._kernel_hat, s=self._padded)[:nx, :ny]

    def solve(
        self,
        gap,
        *,
        load=None,
        approach=None,
        hardness=None,
        initial_forces=None,
        pentol,
        forcetol,
        maxiter=5000,
    ) -> HalfSpaceContact:
        """Contact of the two surfaces across ``gap``, by Polonsky and Keer's constrained conjugate gradients.

        Parameters
        ----------
        gap : array_like
            (nx, ny) gap between the undeformed surfaces at the pixel centres, m (its smallest value is
            where they touch first, at zero approach if it is zero).
        load : float, optional
            Total force, N, > 0 (force control: the approach is found).  Exactly one of ``load`` and
            ``approach``.
        approach : float, optional
            Approach of the bodies, m (displacement control: the force follows).
        hardness : float, optional
            Largest force on a pixel, N, > 0 (the pressure cap times the pixel area); displacement control
            only.
        initial_forces : array_like, optional
            (nx, ny) starting pixel forces, N, >= 0 (default: the load on the pixel of the smallest gap,
            or for displacement control the hardness or a pixel's force of the overlap there).
        pentol : float
            Tolerance of the contact conditions on the deformed gap, and of the last step's largest change
            of a displacement, m, > 0.
        forcetol : float
            Largest force by which a pixel may have been clipped in the last step (a tensile force set to
            zero, or a force above the hardness set to it), N, > 0.
        maxiter : int, optional
            Largest number of iterations.

        Returns
        -------
        HalfSpaceContact
            Pixel forces, displacements, approach, deformed gap and flowing pixels.

        Raises
        ------
        RuntimeError
            If the contact conditions are not met within ``maxiter`` iterations.

        Notes
        -----
        Polonsky and Keer (1999), Wear 231, 206, with displacement control and a hardness cap
        (Almqvist et al. 2007); see the module notes for the stopping test.
        """
        gap = np.asarray(gap, dtype=float)
        if gap.shape != self.shape:
            raise ValueError(f"gap must have the grid's shape {self.shape}, got {gap.shape}")
        if not np.all(np.isfinite(gap)):
            raise ValueError("gap (m) must be finite everywhere")
        if (load is None) == (approach is None):
            raise ValueError("give exactly one of load (N, force control) and approach (m, displacement control)")
        if load is not None:
            load = float(v.positive("load", load, "N"))
            if hardness is not None:
                raise ValueError("a hardness (N per pixel) needs displacement control: give approach (m), not load")
        else:
            approach = float(v.as_float("approach", approach))
        if hardness is not None:
            hardness = float(v.positive("hardness", hardness, "N"))
        pentol = float(v.positive("pentol", pentol, "m"))
        forcetol = float(v.positive("forcetol", forcetol, "N"))
        maxiter = int(maxiter)
        cap = np.inf if hardness is None else hardness
        if initial_forces is None:
            forces = np.zeros(self.shape)
            first = np.unravel_index(np.argmin(gap), gap.shape)
            if load is not None:
                forces[first] = load
            elif approach > gap[first]:
                forces[first] = min(cap, (approach - gap[first]) / self.self_influence)
        else:
            forces = np.array(initial_forces, dtype=float)
            if forces.shape != self.shape or np.any(forces < 0) or not np.all(np.isfinite(forces)):
                raise ValueError(f"initial_forces must be finite forces >= 0 (N) of shape {self.shape}")
            forces = np.minimum(forces, cap)
            if load is not None:
                if not forces.any():
                    raise ValueError("initial_forces must not all be zero under force control (load given)")
                forces *= load / forces.sum()
        return self._iterate(gap, forces, load, approach, cap, pentol, forcetol, maxiter)

    def _iterate(self, gap, forces, load, approach, cap, pentol, forcetol, maxiter):
        """The constrained conjugate gradients from checked inputs (see :meth:`solve`)."""
        u = self.displacement(forces)
        direction = np.zeros(self.shape)
        G_old, restart, clipped_force, moved, fresh = 1.0, True, np.inf, np.inf, True
        for it in range(1, maxiter + 1):
            free = (forces > 0) & (forces < cap)  # in contact and not flowing
            h = gap + u
            if load is not None:  # the approach that makes the mean gap over the contact zero
                approach = float(h[free].mean())
            h -= approach
            # Converged?  The contact conditions on fresh displacements, and a settled last step.
            residual = _violation(h, forces, cap)
            if residual <= pentol and moved <= pentol and clipped_force <= forcetol:
                if fresh:
                    return HalfSpaceContact(forces, u, approach, h, forces >= cap, it - 1)
                u, fresh = self.displacement(forces), True  # check again without the accumulated rounding
                continue
            # Pixels that overlap without force, or flowing pixels whose gap opened, join the set of the
            # step; the gradients restart (Polonsky and Keer) as they do after any change of the set.
            wrong = ((forces == 0) & (h < 0)) | ((forces >= cap) & (h > 0))
            active = free | wrong
            if not active.any():  # nothing to move: no pixel in contact, none violating
                clipped_force = moved = 0.0
                continue
            restart = restart or bool(wrong.any())
            G = float(np.sum(h[active] ** 2))
            if restart:
                direction = np.where(active, h, 0.0)
            else:
                direction = np.where(active, h + (G / G_old) * direction, 0.0)
            G_old = G
            if load is not None:
                direction[active] -= direction[active].mean()  # keeps the total force
            step = self.displacement(direction)
            curvature = float(np.sum(step * direction))  # > 0: the kernel is positive definite
            if not curvature > 0:  # no move left (the gap is exactly zero on the set): settled, or stuck
                if residual <= pentol:
                    clipped_force, moved, restart = 0.0, 0.0, True
                    continue
                break
            tau = float(np.sum(h * direction)) / curvature  # the exact minimum along the direction
            forces = forces - tau * direction
            excess = np.maximum(-forces, forces - cap)  # > 0 where a force turned tensile or passed the cap
            clipped = excess > 0
            clipped_force = float(excess.max())
            forces = np.clip(forces, 0.0, cap)
            scale = 1.0
            if load is not None:
                if not forces.sum() > 0:
                    break
                scale = load / forces.sum()
                forces *= scale
            restart = bool(clipped.any())
            if restart:
                new, fresh = self.displacement(forces), True
            else:  # linear in the forces: the step's displacement, scaled like them
                new, fresh = (u - tau * step) * scale, False
            moved, u = float(np.abs(new - u).max()), new
        raise RuntimeError(
            f"the contact solver did not converge ({it} of at most {maxiter} iterations): contact conditions met "
            f"to {residual:.3g} m (tolerance {pentol:.3g} m), largest force clipped in the last step "
            f"{clipped_force:.3g} N (tolerance {forcetol:.3g} N)"
        )


def _violation(h, forces, cap):
    """Largest violation of the contact conditions, m: the gap inside the contact, the overlap outside it,
    the opening of flowing pixels."""
    inside = (forces > 0) & (forces < cap)
    return max(
        np.max(np.abs(h[inside]), initial=0.0),
        np.max(-h[forces == 0], initial=0.0),
        np.max(h[forces >= cap], initial=0.0),
    )
