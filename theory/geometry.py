"""A ring of the chain and everything the static theory derives from it.

A :class:`Ring` is a solid torus of major radius R and tube radius r, of some
material, interlocked with its neighbours at a contact angle theta between ring
planes.  It gives the mass m0, the spacing a = 2(R - r) of adjacent centres
(paper Eq. (8)), the contact and bending stiffnesses (Eqs. 1-2), the crossover
force and the power-law fit (Eqs. 3-4).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import _validate as v
from .contact import hertz_stiffness
from .materials import STAINLESS_STEEL_304, Material, get_material
from .ring import bending_stiffness
from .series import DEFAULT_FORCE_WINDOW, crossover_force, fit_power_law, local_exponent

__all__ = ["Ring", "MIN_CHAIN_ASPECT_RATIO", "PAPER_TUBE_RADIUS"]

#: Smallest R/r of a chain: the hole, of diameter 2(R - r), must pass the wire of both
#: neighbours, 2 x 2r, so R >= 3 r.  (Two rings alone interlock for R > 2 r.)
MIN_CHAIN_ASPECT_RATIO = 3.0

#: Tube radius of the paper's rings, m (Fig. 2 caption).
PAPER_TUBE_RADIUS = 2.5e-3

#: Relative tolerance of the chain limit R >= 3 r: a few units of double-precision rounding, so
#: that radii given as decimals (0.3 and 0.1) at the limit are not refused for their last bit.
_ROUNDING = 4 * np.finfo(float).eps


@dataclass(frozen=True)
class Ring:
    """One solid torus of the chain.

    Parameters
    ----------
    R : float
        Major (centroidal) radius, m.
    r : float
        Tube radius, m; R > 2 r is required for Hertz contact.
    material : Material or str, optional
        Default AISI 304 stainless steel (:data:`~ringchain.theory.materials.STAINLESS_STEEL_304`).
    angle : float, optional
        Contact angle theta between adjacent ring planes, rad; pi/2 is the paper's case.
    thin : bool, optional
        Use the thin-ring bending stiffness instead of the curved-beam one (``True`` or
        ``False``; anything else raises ``TypeError``).

    Examples
    --------
    >>> ring = Ring.from_aspect_ratio(9.0)
    >>> round(ring.R * 1e3, 2), round(ring.spacing * 1e3, 2)  # mm
    (22.5, 40.0)
    """

    R: float
    r: float
    material: Material = field(default=STAINLESS_STEEL_304)
    angle: float = np.pi / 2
    thin: bool = False

    def __post_init__(self):
        object.__setattr__(self, "material", get_material(self.material))
        for name in ("R", "r", "angle"):
            value = v.as_float(name, getattr(self, name))
            if value.size != 1:
                raise ValueError(f"{name} of a Ring must be one number, got an array of shape {value.shape}")
            object.__setattr__(self, name, float(value.reshape(())))
        object.__setattr__(self, "thin", v.boolean("thin", self.thin))
        # Validates R > 2 r and the angle, with errors that say why.
        hertz_stiffness(self.R, self.r, self.material.E, self.material.nu, self.angle)
        bending_stiffness(self.R, self.r, self.material.E, self.material.nu, thin=self.thin)
        v.finite_result(self.mass, "the ring's mass", "radii and density")

    @classmethod
    def from_aspect_ratio(cls, aspect_ratio, r=PAPER_TUBE_RADIUS, **kwargs) -> Ring:
        """A ring with R = aspect_ratio * r (default r = 2.5 mm, the paper's tube radius)."""
        aspect_ratio, r = v.positive("aspect_ratio", aspect_ratio), v.positive("r", r, "m")
        with np.errstate(all="ignore"):
            R = aspect_ratio * r
        v.finite_result(R, "R = aspect_ratio * r", "aspect ratio and tube radius")
        return cls(R=R, r=r, **kwargs)

    @property
    def aspect_ratio(self) -> float:
        """R/r."""
        return self.R / self.r

    @property
    def can_form_chain(self) -> bool:
        """Whether R >= 3 r, so that each ring can hold both neighbours.

        Equality within the rounding of the inputs counts as equality: ``Ring(0.3, 0.1)``, whose
        R/r is 2.9999999999999996 in floating point, is the limiting ring R = 3 r.
        """
        return bool(self.R >= MIN_CHAIN_ASPECT_RATIO * self.r * (1.0 - _ROUNDING))

    def check_chain(self) -> None:
        """Raise ``ValueError`` if this ring cannot be a link of an interlocked chain."""
        if not self.can_form_chain:
            raise ValueError(
                f"R/r = {v.show(self.aspect_ratio)} is below {MIN_CHAIN_ASPECT_RATIO:g}: the hole of a ring, "
                "2(R - r) across, cannot pass the wires of two neighbours (4 r), so these rings cannot form a chain"
            )

    @property
    def volume(self) -> float:
        """Torus volume 2 pi^2 R r^2 (Pappus), m^3."""
        with np.errstate(all="ignore"):
            return float(2.0 * np.pi**2 * np.float64(self.R) * self.r * self.r)

    @property
    def mass(self) -> float:
        """Ring mass m0, kg."""
        return self.material.rho * self.volume

    @property
    def spacing(self) -> float:
        """Distance a = 2(R - r) between the centres of adjacent rings in contact, m."""
        return 2.0 * (self.R - self.r)

    @property
    def K_c(self) -> float:
        """Hertz contact stiffness, N/m^1.5 (Eq. 1; elliptical contact if angle != pi/2)."""
        m = self.material
        return float(hertz_stiffness(self.R, self.r, m.E, m.nu, self.angle))

    @property
    def K_b(self) -> float:
        """Bending stiffness of the ring, N/m (Eq. 2)."""
        m = self.material
        return float(bending_stiffness(self.R, self.r, m.E, m.nu, thin=self.thin))

    @property
    def crossover_force(self) -> float:
        """Force F* = K_b^3/K_c^2 at which contact and bending compliances are equal, N."""
        return float(crossover_force(K_c=self.K_c, K_b=self.K_b))

    def local_exponent(self, F):
        """Local exponent n(F) of the series law at force F (N)."""
        return local_exponent(F, K_c=self.K_c, K_b=self.K_b)

    def power_law(self, F_min=DEFAULT_FORCE_WINDOW[0], F_max=DEFAULT_FORCE_WINDOW[1]) -> tuple[float, float]:
        """Fitted (K in N/m^n, n) of F = K delta^n over [F_min, F_max] N (Eq. 4)."""
        K, n = fit_power_law(K_c=self.K_c, K_b=self.K_b, F_min=F_min, F_max=F_max)
        return float(K), float(n)
