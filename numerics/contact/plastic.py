r"""The contact of two tori with its pressure capped at the first-yield pressure: a numerical check of Thornton.

:func:`capped_contact_curve` -- FFT boundary elements (:mod:`.halfspace`) on the exact gap of two tori (or on
Thornton's equivalent sphere) with the pressure capped at p_y, the first-yield pressure of the Hertz contact
(:func:`ringchain.theory.first_yield`), against Thornton's elastic-perfectly plastic loading curve
(:func:`ringchain.theory.thornton_loading_force`).  Thornton keeps the Hertz contact radius; the capped
half-space spreads its contact towards the truncated area, so the two part as delta/delta_y grows (the book's
chapter "Where the energy goes").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from ringchain.theory import _validate as v

from .bem import Tori, overlap_box
from .halfspace import ElasticHalfSpace

__all__ = ["CappedContactCurve", "capped_contact_curve", "CAPPED_SHAPES", "CAPPED_KKT_TOLERANCE"]


#: Geometries of :func:`capped_contact_curve`: the exact gap of the two tori, or Thornton's equivalent sphere.
CAPPED_SHAPES = ("torus", "sphere")

#: Largest violation of the contact conditions accepted in a capped solution, relative to the approach.
CAPPED_KKT_TOLERANCE = 1e-3

_CAPPED_WINDOW = 1.25  # window half-width over the half-width of the rigid overlap {gap < delta}
_CAPPED_MAXITER = 1000
_CAPPED_RETRIES = (0, 4, 8, -4, 12)  # pixels added to the requested count when a solution is refused


@dataclass(frozen=True)
class CappedContactCurve:
    """Loading curve of the contact with the pressure capped at p_y, from :func:`capped_contact_curve`.

    Attributes
    ----------
    delta : ndarray
        Approach, m.
    force : ndarray
        Contact force of the capped boundary-element solution, N.
    thornton : ndarray
        Thornton's loading force at the same approach, N
        (:func:`ringchain.theory.thornton_loading_force`).
    area, plastic_area : ndarray
        Contact area, and the part of it at the pressure cap, m^2.
    delta_y, F_y, p_y : float
        Approach (m) and force (N) at first yield, and the pressure cap (Pa).
    shape : str
        ``"torus"`` (the exact gap of the two tori) or ``"sphere"`` (the equivalent sphere of radius R_e).
    kkt_error : ndarray
        Largest violation of the contact conditions of each solution, relative to its approach.
    pixels : ndarray
        Pixels across the grid (along its shorter side) of each solution.
    """

    delta: np.ndarray
    force: np.ndarray
    thornton: np.ndarray
    area: np.ndarray
    plastic_area: np.ndarray
    delta_y: float
    F_y: float
    p_y: float
    shape: str
    kkt_error: np.ndarray
    pixels: np.ndarray

    @property
    def ratio(self) -> np.ndarray:
        """Capped boundary-element force over Thornton's at the same approach."""
        return self.force / self.thornton


def _capped_gap(shape, tori, R_e, delta, pixels):
    """(gap on the grid (m), pixel sizes (hx, hy), physical size) of a window holding {gap < delta}."""
    if shape == "sphere":
        x_lo, x_hi, y_half = -np.sqrt(2 * R_e * delta), np.sqrt(2 * R_e * delta), np.sqrt(2 * R_e * delta)
    else:
        x_lo, x_hi, y_half = overlap_box(tori, delta, limit=0.9 * tori.r)
    x_half = _CAPPED_WINDOW * max(abs(x_lo), abs(x_hi))
    y_half = _CAPPED_WINDOW * y_half
    short = min(x_half, y_half)
    nx = int(np.ceil(pixels * x_half / short))
    ny = int(np.ceil(pixels * y_half / short))
    hx, hy = 2 * x_half / nx, 2 * y_half / ny
    x = -x_half + (np.arange(nx) + 0.5) * hx
    y = -y_half + (np.arange(ny) + 0.5) * hy
    X, Y = np.meshgrid(x, y, indexing="ij")
    gap = (X**2 + Y**2) / (2 * R_e) if shape == "sphere" else tori.gap(X, Y)
    return gap, (hx, hy), (2 * x_half, 2 * y_half)


def _capped_solve(gap, pixel, size, E_star, p_y, delta, R_e):
    """One capped solution at imposed approach delta: (forces per pixel, flowing pixels, relative KKT violation).

    Raises RuntimeError if the solver does not converge on this grid.
    """
    hardness = p_y * pixel[0] * pixel[1]  # the cap on the force per pixel
    halfspace = ElasticHalfSpace(gap.shape, size, E_star)
    # Start from the Hertz pressure of the sphere R_e, capped: p = (2 E*/pi) sqrt(2 (delta/2 - gap)/R_e).
    guess = 2 * E_star / np.pi * np.sqrt(2 * np.maximum(0.0, delta / 2 - gap) / R_e) * pixel[0] * pixel[1]
    guess = np.minimum(guess, hardness)
    if not guess.any():
        guess[np.unravel_index(np.argmin(gap), gap.shape)] = hardness
    # The contact conditions to 1e-6 delta (the force to about as much; the check below asks 1e-3 delta).
    result = halfspace.solve(
        gap, approach=delta, hardness=hardness, initial_forces=guess,
        pentol=1e-6 * delta, forcetol=1e-9 * hardness, maxiter=_CAPPED_MAXITER,
    )  # fmt: skip
    forces = result.forces
    # The contact conditions of the capped problem, checked here on the solution's own deformed gap
    # (< 0 where it flows), independently of the solver's stopping test.
    deformed = result.displacement + gap - delta
    tiny = 1e-9 * hardness
    free, flowing = forces <= tiny, forces >= hardness - tiny
    elastic = ~free & ~flowing
    violation = max(
        np.max(np.abs(deformed[elastic]), initial=0.0),
        np.max(-deformed[free], initial=0.0),
        np.max(deformed[flowing], initial=0.0),
    )
    return forces, flowing, violation / delta


def capped_contact_curve(R, r, E, nu, Y, delta_over_delta_y, *, angle=np.pi / 2, shape="torus", pixels=48):
    """Loading curve of the two tori's contact with the pressure capped at the first-yield pressure.

    Parameters
    ----------
    R, r : float
        Major and tube radius of both tori, m (R > 2 r).
    E, nu : float
        Young's modulus (Pa) and Poisson's ratio.
    Y : float
        Yield strength, Pa (:func:`ringchain.theory.first_yield`).
    delta_over_delta_y : array_like
        Approaches in units of the approach at first yield, > 0.
    angle : float, optional
        Contact angle between the ring planes, rad, above theta_min (one elliptical contact); default pi/2.
    shape : {"torus", "sphere"}, optional
        Solve on the exact gap of the tori (:func:`ringchain.theory.torus_gap`, capped at the first-yield
        peak pressure of their elliptical contact) or on Thornton's equivalent sphere (radius R_e of
        :func:`ringchain.theory.equivalent_radius`, capped at its p_y, which gives the same K_c and delta_y).
    pixels : int, optional
        Pixels across the shorter side of each window (default 48; the window is 1.25 times the rigid
        overlap {gap < delta}).

    Returns
    -------
    CappedContactCurve
        Force against approach, Thornton's force at the same approach, areas, the check of each solution.

    Raises
    ------
    RuntimeError
        If no grid of the retries (:data:`_CAPPED_RETRIES`) gives a solution within
        :data:`CAPPED_KKT_TOLERANCE`.

    Notes
    -----
    Elastic half-spaces in frictionless contact whose pressure may not exceed p_y: where it would, the
    surfaces interpenetrate (the material flows).  Polonsky and Keer's constrained conjugate gradients with
    a hardness (Almqvist et al. 2007; Weber et al. 2018) on FFT boundary elements,
    :meth:`~.halfspace.ElasticHalfSpace.solve` with ``approach=delta, hardness=p_y * pixel area``.  Each
    solution is accepted only if the contact conditions hold to :data:`CAPPED_KKT_TOLERANCE` delta (gap zero
    where 0 < p < p_y, open where p = 0, closed or penetrating where p = p_y); otherwise, or if the solver
    does not converge, the grid is changed by a few pixels and the problem solved again.  Resolution,
    measured on the paper's ring with 32, 48 and 96 pixels: the ratio to Thornton's force changes by 0.1 %
    at 2 delta_y and by up to 2 % at 10-300 delta_y, where the few pixels at the edge of the flowing region
    set it.

    The capped half-space carries more force than Thornton's model at the same approach, 1.09 times at
    2 delta_y, 1.44 at 10 and 1.8-1.9 at a few hundred: Thornton keeps Hertz's contact radius
    a^2 = R_e delta, and so a plastic slope pi p_y R_e, while the capped contact spreads towards the
    rigid truncation radius a^2 = 2 R_e delta (slope 2 pi p_y R_e) as the plastic zone takes over.
    """
    from ringchain.theory import contact_modulus, equivalent_radius, first_yield, hertz_stiffness
    from ringchain.theory import thornton_loading_force as thornton

    if shape not in CAPPED_SHAPES:
        raise ValueError(f"shape must be one of {CAPPED_SHAPES}, got {shape!r}")
    R = float(v.positive("R", R, "m"))
    r = float(v.positive("r", r, "m"))
    angle = float(v.as_float("angle", angle))
    pixels = int(pixels)
    if pixels < 8:
        raise ValueError(f"pixels must be at least 8, got {pixels}")
    ratios = np.atleast_1d(v.positive("delta_over_delta_y", delta_over_delta_y)).astype(float).ravel()
    yielding = first_yield(R, r, E, nu, angle, Y=Y)  # validates the rest, with errors that say why
    K_c = float(hertz_stiffness(R, r, E, nu, angle))
    E_star = float(contact_modulus(E, nu))
    R_e = float(equivalent_radius(R, r, angle))
    delta_y, F_y = float(yielding.indentation), float(yielding.force)
    if shape == "sphere":
        # The sphere that yields at F_y: F_y = pi^3 R_e^2 p_y^3/(6 E*^2) (the circular case of first_yield).
        p_y = float(np.cbrt(6 * E_star**2 * F_y / (np.pi**3 * R_e**2)))
        tori = None
    else:
        p_y = float(yielding.pressure)
        tori = Tori(R, r, angle, "axial")
        if tori.n_patches != 1:
            raise ValueError("the capped contact is computed for one elliptical contact (angle above theta_min)")
    deltas = ratios * delta_y
    force, area, plastic, errors, used = (np.empty(ratios.size) for _ in range(5))
    for k, delta in enumerate(deltas):
        for extra in _CAPPED_RETRIES:
            gap, pixel, size = _capped_gap(shape, tori, R_e, delta, pixels + extra)
            try:
                forces, flowing, error = _capped_solve(gap, pixel, size, E_star, p_y, delta, R_e)
            except RuntimeError:  # not converged on this grid: the next one
                error = np.inf
                continue
            if error <= CAPPED_KKT_TOLERANCE:
                break
        else:
            raise RuntimeError(
                f"the capped contact at delta = {ratios[k]:g} delta_y did not satisfy the contact conditions "
                f"to {CAPPED_KKT_TOLERANCE:g} delta on any grid (last: {error:.2g})"
            )
        cell = pixel[0] * pixel[1]
        force[k], area[k] = forces.sum(), np.count_nonzero(forces > 0) * cell
        plastic[k], errors[k], used[k] = np.count_nonzero(flowing) * cell, error, pixels + extra
    return CappedContactCurve(
        delta=deltas,
        force=force,
        thornton=np.asarray(thornton(deltas, K_c=K_c, delta_y=delta_y), dtype=float),
        area=area,
        plastic_area=plastic,
        delta_y=delta_y,
        F_y=F_y,
        p_y=p_y,
        shape=shape,
        kkt_error=errors,
        pixels=used.astype(int),
    )
