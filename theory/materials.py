"""Material presets, each with its source (SI units).

The symbolic derivations stay parameterised in E and nu; numbers enter only here,
through named constructors.
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass

from . import _validate as v
from .contact import contact_modulus

__all__ = ["Material", "STAINLESS_STEEL_304", "MATERIALS", "get_material"]


@dataclass(frozen=True)
class Material:
    """An isotropic elastic material.

    The name may be given by position; the constants only by keyword (``E=``, ``nu=``, ``rho=``,
    ``source=``): E and rho are both positive numbers, and a swap would pass silently.

    Attributes
    ----------
    name : str
        Short key, e.g. ``"stainless"``.
    E : float
        Young's modulus, Pa.
    nu : float
        Poisson's ratio.
    rho : float
        Density, kg/m^3.
    source : str
        Where the numbers come from.
    """

    name: str
    _: KW_ONLY
    E: float
    nu: float
    rho: float
    source: str

    def __post_init__(self):
        checked = {
            "E": v.positive("E", self.E, "Pa"),
            "nu": v.in_range("nu", self.nu, -1.0, 0.5, closed_high=False),
            "rho": v.positive("rho", self.rho, "kg/m^3"),
        }
        for name, value in checked.items():
            if value.size != 1:
                raise ValueError(f"{name} of a material must be one number, got an array of shape {value.shape}")
            object.__setattr__(self, name, float(value.reshape(())))

    @property
    def G(self) -> float:
        """Shear modulus E/(2(1 + nu)), Pa."""
        return self.E / (2.0 * (1.0 + self.nu))

    @property
    def E_star(self) -> float:
        """Contact modulus of two bodies of this material, Pa (App. A).

        1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 with both bodies of this material, from the
        derivation (:func:`ringchain.theory.contact.effective_modulus`): E/(2(1 - nu^2)).
        """
        return float(contact_modulus(self.E, self.nu))


#: AISI 304 austenitic stainless steel, annealed (the paper's rings are "stainless steel";
#: the grade is not stated, 304 is the common one).
STAINLESS_STEEL_304 = Material(
    name="stainless",
    E=193e9,
    nu=0.29,
    rho=8000.0,
    source="ASM Handbook Vol. 1 / ASM Aerospace Specification Metals data sheet for AISI 304: "
    "E = 193 GPa, nu = 0.29, rho = 8.00 g/cm^3",
)

#: Presets by key.
MATERIALS = {STAINLESS_STEEL_304.name: STAINLESS_STEEL_304}


def get_material(name_or_material) -> Material:
    """A :class:`Material` from a preset key (``"stainless"``) or a Material itself."""
    if isinstance(name_or_material, Material):
        return name_or_material
    try:
        return MATERIALS[str(name_or_material).lower()]
    except KeyError:
        raise ValueError(f"unknown material {name_or_material!r}; presets: {sorted(MATERIALS)}") from None
