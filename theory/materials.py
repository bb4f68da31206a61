"""Material presets, each with its source (SI units).

The symbolic derivations stay parameterised in E and nu; numbers enter only here,
through named constructors.
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass

from . import _validate as v
from .contact import contact_modulus

__all__ = [
    "Material",
    "STAINLESS_STEEL_304",
    "STAINLESS_STEEL_304_ANNEALED",
    "STAINLESS_STEEL_304_COLD_WORKED",
    "MATERIALS",
    "get_material",
]


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
    yield_strength : float or None
        Yield strength in uniaxial tension (0.2 % offset), Pa; None for a material treated as
        elastic (the paper's model).  It sets where the contact first yields
        (:func:`~ringchain.theory.yield_force`).
    """

    name: str
    _: KW_ONLY
    E: float
    nu: float
    rho: float
    source: str
    yield_strength: float | None = None

    def __post_init__(self):
        checked = {
            "E": v.positive("E", self.E, "Pa"),
            "nu": v.in_range("nu", self.nu, -1.0, 0.5, closed_high=False),
            "rho": v.positive("rho", self.rho, "kg/m^3"),
        }
        if self.yield_strength is not None:
            checked["yield_strength"] = v.positive("yield_strength", self.yield_strength, "Pa")
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

#: AISI 304 annealed, with its yield strength: the elastic constants of :data:`STAINLESS_STEEL_304`.
STAINLESS_STEEL_304_ANNEALED = Material(
    name="stainless-annealed",
    E=193e9,
    nu=0.29,
    rho=8000.0,
    yield_strength=215e6,
    source="ASM Aerospace Specification Metals data sheet for AISI 304 (annealed): tensile yield strength "
    "(0.2 % offset) 215 MPa, ultimate 505 MPa; E = 193 GPa, nu = 0.29, rho = 8.00 g/cm^3",
)

#: AISI 304 cold-drawn wire (the rings are bent from wire; the paper does not state the temper).
STAINLESS_STEEL_304_COLD_WORKED = Material(
    name="stainless-cold-worked",
    E=193e9,
    nu=0.29,
    rho=8000.0,
    yield_strength=1.0e9,
    source="AISI 304 cold-drawn (spring-temper) wire, ASTM A313: tensile strength about 1.3-1.6 GPa at "
    "2-6 mm diameter; 0.2 % yield taken as 1.0 GPa, a round value about 70 % of it (an assumption for "
    "heavily drawn austenitic wire, not a specified minimum); elastic constants as annealed",
)

#: Presets by key.
MATERIALS = {
    material.name: material
    for material in (STAINLESS_STEEL_304, STAINLESS_STEEL_304_ANNEALED, STAINLESS_STEEL_304_COLD_WORKED)
}


def get_material(name_or_material) -> Material:
    """A :class:`Material` from a preset key (``"stainless"``) or a Material itself."""
    if isinstance(name_or_material, Material):
        return name_or_material
    try:
        return MATERIALS[str(name_or_material).lower()]
    except KeyError:
        raise ValueError(f"unknown material {name_or_material!r}; presets: {sorted(MATERIALS)}") from None
